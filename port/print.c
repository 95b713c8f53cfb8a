/* Integer and string output over port_write (see print.h). */
#include "print.h"

void print_str(const char *s)
{
    uint32_t n = 0;
    while (s[n]) n++;
    port_write(s, n);
}

void print_u32(uint32_t v)
{
    char b[10];
    uint32_t n = 0;
    do { b[9 - n] = (char)('0' + v % 10u); v /= 10u; n++; } while (v);
    port_write(b + 10 - n, n);
}

void print_i32(int32_t v)
{
    if (v < 0) { print_str("-"); print_u32(0u - (uint32_t)v); } else print_u32((uint32_t)v);
}

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
