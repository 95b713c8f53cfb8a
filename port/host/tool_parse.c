/* SPDX-License-Identifier: MIT */
/* subd tool: the option values' parsers (whole unsigned numbers, numbers in a range, comma
 * lists) and the builder of a command's description, shared by the parser (subd_options.c)
 * and the scheme modules (cmd_*.c). A leaf: it calls no other tool file, so the modules
 * depend on it and not on the parser, which depends on them through the command table.
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "tool_parse.h"

int tool_parse_u32(const char *s, uint32_t max, uint32_t *out)
{
    unsigned long long v = 0;
    if (!*s) return -1;
    for (; *s >= '0' && *s <= '9'; s++) {
        v = v * 10u + (unsigned)(*s - '0');
        if (v > max) return -1;
    }
    if (*s) return -1;
    *out = (uint32_t)v;
    return 0;
}

int tool_parse_double(const char *s, double lo, double hi, double *out)
{
    char *end;
    double v;
    errno = 0;
    v = strtod(s, &end);
    if (end == s || *end || errno || !(v >= lo && v <= hi)) return -1;
    *out = v;
    return 0;
}

int tool_parse_doubles(const char *s, int n, double *out)
{
    char buf[64];
    int i;
    for (i = 0; i < n; i++) {
        const char *c = strchr(s, ',');
        size_t len = (i + 1 < n) ? (c ? (size_t)(c - s) : sizeof buf) : strlen(s);
        if (len >= sizeof buf) return -1;
        memcpy(buf, s, len);
        buf[len] = '\0';
        if (tool_parse_double(buf, -1e6, 1e6, &out[i])) return -1;
        s += len + (i + 1 < n ? 1u : 0u);
    }
    return 0;
}

size_t tool_describe_add(char *buf, size_t k, size_t n, const char *fmt, ...)
{
    va_list ap;
    int w;
    if (k >= n) return n;
    va_start(ap, fmt);
    w = vsnprintf(buf + k, n - k, fmt, ap);
    va_end(ap);
    if (w < 0) return k;
    k += (size_t)w;
    return k < n ? k : n;
}
