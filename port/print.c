/* SPDX-License-Identifier: MIT */
/* Integer and string output over port_write (see print.h). */
#include "print.h"

void print_str(const char *s)
{
    uint32_t n = 0;
    while (s[n]) n++;
    port_write(s, n);
}

uint32_t print_fmt_u64(char *b, uint64_t v)
{
    char r[20];
    uint32_t n = 0, i;
    do { r[n++] = (char)('0' + (uint32_t)(v % 10u)); v /= 10u; } while (v);
    for (i = 0; i < n; i++) b[i] = r[n - 1u - i];
    return n;
}

void print_u64(uint64_t v)
{
    char b[20];
    port_write(b, print_fmt_u64(b, v));
}

void print_i64(int64_t v)
{
    if (v < 0) { print_str("-"); print_u64(0u - (uint64_t)v); } else print_u64((uint64_t)v);
}

void print_u32(uint32_t v) { print_u64(v); }
void print_i32(int32_t v) { print_i64(v); }

void print_hex32(uint32_t v)
{
    static const char d[] = "0123456789abcdef";
    char b[10];
    int i;
    b[0] = '0'; b[1] = 'x';
    for (i = 0; i < 8; i++) b[2 + i] = d[(v >> (28 - 4 * i)) & 15u];
    port_write(b, 10);
}

void print_nl(void) { port_write("\n", 1); }
