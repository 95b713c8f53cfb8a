/* SPDX-License-Identifier: MIT */
/* subd tool: option values and descriptions (tool_parse.c), a leaf of the tool's files. */
#ifndef TOOL_PARSE_H
#define TOOL_PARSE_H
#include <stddef.h>
#include <stdint.h>

/* Value parsers for the option rows: 0, or -1 when s is not one. */
int tool_parse_u32(const char *s, uint32_t max, uint32_t *out);
int tool_parse_double(const char *s, double lo, double hi, double *out);
/* n comma-separated numbers (coordinates within +-1e6). */
int tool_parse_doubles(const char *s, int n, double *out);
/* Appends printf text to buf[k..n) (truncating), returns the new k: for command.describe. */
size_t tool_describe_add(char *buf, size_t k, size_t n, const char *fmt, ...);
#endif
