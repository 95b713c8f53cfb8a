/* SPDX-License-Identifier: MIT */
/* Exhaustive check of subd_real_format (src/real_format.c) against the bignum reference
 * (test/ref_format.h), for `make check-format-exhaustive`: every bit pattern in
 * [first, first + count) (default: all 2^32), byte for byte, plus subd_real_parse reading the
 * text back to the same bits. Float32 goes through the non-negative patterns only and derives
 * the negative text as "-" + the positive one, checked directly on every 4096th pattern (the
 * sign is one byte in front; both formatters handle it before any digit work). Q16.16 checks
 * every pattern (subd_q16_format; read back by the parser in the Q16.16 build). Host only.
 * Usage: format_exhaustive float|q16 [FIRST COUNT]   (hex or decimal; float needs the float
 * build). Prints progress every 2^28 patterns and a final line "... N checked, M mismatches". */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "subd.h"
#include "ref_format.h"
#include "../../src/text.h" /* subd_q16_format */

static int check(uint32_t bits, int q16, unsigned long long *bad)
{
    char a[40], b[40];
    uint32_t an, bn;
    subd_real y = 0;
    const char *p;
    int parse = q16 == SUBD_FIXED;
    if (q16) {
        an = subd_q16_format((int32_t)bits, a);
        bn = ref_format_fixed((int32_t)bits, b);
    } else {
#if SUBD_FIXED
        return 0;
#else
        union { uint32_t u; float f; } c;
        c.u = bits;
        an = subd_real_format(c.f, a);
        bn = ref_format_float(c.f, b);
        if ((bits & 0x7f800000u) == 0x7f800000u) parse = 0;
#endif
    }
    if (an != bn || memcmp(a, b, an) != 0) goto fail;
    if (!parse) return 0;
    p = a;
    if (subd_real_parse(&p, a + an, &y) != SUBD_OK || p != a + an || subd_real_bits(y) != bits) goto fail;
    return 0;
fail:
    if ((*bad)++ < 20u) {
        a[an < 39u ? an : 39u] = 0;
        b[bn < 39u ? bn : 39u] = 0;
        printf("MISMATCH %08lx: \"%s\" vs reference \"%s\"\n", (unsigned long)bits, a, b);
    }
    return 1;
}

int main(int argc, char **argv)
{
    unsigned long long first = 0, count = 1ull << 32, i, checked = 0, bad = 0;
    int q16;
    if ((argc != 2 && argc != 4) || (strcmp(argv[1], "float") != 0 && strcmp(argv[1], "q16") != 0) ||
        (SUBD_FIXED && strcmp(argv[1], "float") == 0)) {
        fprintf(stderr, "usage: %s float|q16 [FIRST COUNT]   (float only in the float build)\n", argv[0]);
        return 2;
    }
    q16 = strcmp(argv[1], "q16") == 0;
    if (argc == 4) {
        first = strtoull(argv[2], 0, 0);
        count = strtoull(argv[3], 0, 0);
    }
    if (first > 0xffffffffull) return 2;
    if (count > (1ull << 32) - first) count = (1ull << 32) - first;
    for (i = first; i < first + count; i++) {
        uint32_t bits = (uint32_t)i;
        if ((i & 0xfffffffull) == 0 && i != first) {
            printf("  at %08lx: %llu checked, %llu mismatches\n", (unsigned long)bits, checked, bad);
            fflush(stdout);
        }
        /* negative floats: only every 4096th directly (see the header) */
        if (!q16 && (bits >> 31) && (bits & 0xfffu) != 0u) continue;
        check(bits, q16, &bad);
        checked++;
    }
    printf("format exhaustive %s (%s build): %llu checked, %llu mismatches\n", q16 ? "q16.16" : "float32",
           SUBD_FIXED ? "Q16.16" : "float", checked, bad);
    return bad ? 1 : 0;
}
