/* SPDX-License-Identifier: MIT */
/* Tests of subd_real_format (src/real_format.c) against the exact bignum formatter it replaced,
 * kept in test/ref_format.h as an independent reference: byte for byte (length, text, and no
 * byte written past the returned length), and every text read back by subd_real_parse to the
 * same bits.
 *
 * Float32: every power of two (normal and subnormal), the first and last subnormals and random
 * ones, the floats around every decade 10^k (-45 <= k <= 38, +-8 ulps: the points where the
 * digit count and the positional/exponent layout change), the binade bottoms (asymmetric
 * gaps), +-0, +-inf, NaNs, and random bit patterns (10^6 on the host, fewer on QEMU where the
 * reference is slow). Q16.16: the values with integer part 0 and 32767 (every fraction),
 * every 4099th value of the 2^32 (host) and random ones, both signs, in both builds (the
 * Q16.16 formatter is int32 code; the round trip through the parser only in the Q16.16 build). The exhaustive checks
 * over all 2^32 patterns are `make check-format-exhaustive` (test/tools/format_exhaustive.c). */
#include "harness.h"
#include "ref_format.h"
#include "../src/text.h" /* subd_q16_format */

#define FMT_RANDOM (H_HOST ? 1000000u : 1500u)

typedef struct fmt_stats {
    uint32_t cases, fails;
} fmt_stats;

static void report(uint32_t bits, const char *got, uint32_t gn, const char *want, uint32_t wn)
{
    char b[48];
    uint32_t i;
    h_str("    bits ");
    h_hex32(bits);
    h_str(" got \"");
    for (i = 0; i < gn && i < 40u; i++) b[i] = got[i];
    b[i] = 0;
    h_str(b);
    h_str("\" want \"");
    for (i = 0; i < wn && i < 40u; i++) b[i] = want[i];
    b[i] = 0;
    h_str(b);
    h_str("\"");
    h_nl();
}

/* One case: fast == reference byte for byte, nothing written past the length, and the text
 * parses back to the same bits (finite values of the build's own arithmetic). q16 selects
 * the Q16.16 formatter (subd_q16_format, in both builds; subd_real_format of the Q16.16
 * build) instead of the float one. */
static void one_kind(fmt_stats *s, uint32_t bits, int q16)
{
    char got[40], want[40];
    uint32_t gn, wn, k, ok = 1;
    int parse = q16 == SUBD_FIXED;
    for (k = 0; k < sizeof got; k++) got[k] = '#';
    if (q16) {
        gn = subd_q16_format((int32_t)bits, got);
        wn = ref_format_fixed((int32_t)bits, want);
#if SUBD_FIXED
        {
            char same[40];
            uint32_t sn = subd_real_format((subd_real)bits, same);
            if (sn != gn) ok = 0;
            for (k = 0; ok && k < sn; k++)
                if (same[k] != got[k]) ok = 0;
        }
#endif
    } else {
#if SUBD_FIXED
        gn = wn = 0;
#else
        union { uint32_t u; float f; } c;
        c.u = bits;
        gn = subd_real_format(c.f, got);
        wn = ref_format_float(c.f, want);
        if ((bits & 0x7f800000u) == 0x7f800000u) parse = 0;
#endif
    }
    if (gn != wn || gn > 24u) ok = 0;
    for (k = 0; ok && k < gn; k++)
        if (got[k] != want[k]) ok = 0;
    for (k = gn; ok && k < sizeof got; k++)
        if (got[k] != '#') ok = 0;
    if (ok && parse) {
        const char *p = got;
        subd_real y = 0;
        if (subd_real_parse(&p, got + gn, &y) != SUBD_OK || p != got + gn || subd_real_bits(y) != bits) ok = 0;
    }
    s->cases++;
    if (!ok && s->fails++ < 8u) report(bits, got, gn < 40u ? gn : 40u, want, wn < 40u ? wn : 40u);
}

#if !SUBD_FIXED
static void one(fmt_stats *s, uint32_t bits) { one_kind(s, bits, 0); }

/* Both signs. */
static void pm(fmt_stats *s, uint32_t bits)
{
    one(s, bits);
    one(s, bits ^ 0x80000000u);
}
#endif

static void pm16(fmt_stats *s, uint32_t bits)
{
    one_kind(s, bits, 1);
    one_kind(s, bits ^ 0x80000000u, 1);
}

#if !SUBD_FIXED

static uint32_t parse_bits(const char *t)
{
    const char *p = t, *e = t;
    subd_real v = 0;
    while (*e) e++;
    if (subd_real_parse(&p, e, &v) != SUBD_OK) return 0;
    return subd_real_bits(v);
}

static void format_float_edges(void)
{
    fmt_stats s = {0, 0};
    uint32_t i, st = 7u;
    int32_t k, d;
    /* specials: zeros, infinities, NaNs (quiet, signalling, payloads) */
    pm(&s, 0u);
    pm(&s, 0x7f800000u);
    pm(&s, 0x7fc00000u);
    pm(&s, 0x7f800001u);
    pm(&s, 0x7fffffffu);
    /* every power of two: subnormal 2^-149..2^-127, normal 2^-126..2^127; and the float
     * just below and above each (binade bottoms have a gap below half the gap above) */
    for (i = 0; i < 23u; i++) pm(&s, 1u << i);
    for (i = 1; i < 255u; i++) {
        pm(&s, i << 23);
        pm(&s, (i << 23) - 1u);
        pm(&s, (i << 23) + 1u);
    }
    /* subnormals: the first and last ones, random ones */
    for (i = 1; i < (H_HOST ? 4096u : 256u); i++) {
        pm(&s, i);
        pm(&s, 0x00800000u - i);
    }
    for (i = 0; i < (H_HOST ? 20000u : 200u); i++) one(&s, h_rand(&st) & 0x807fffffu);
    /* decades: the float nearest 10^k and its neighbours, where the digit count and the
     * positional / exponent layout change (1e-5 | 0.0001, 100000000 | 1e+09) */
    for (k = -45; k <= 38; k++) {
        char t[8];
        uint32_t n = 0, a = (uint32_t)(k < 0 ? -k : k), b;
        t[n++] = '1';
        t[n++] = 'e';
        if (k < 0) t[n++] = '-';
        if (a >= 10u) t[n++] = (char)('0' + a / 10u);
        t[n++] = (char)('0' + a % 10u);
        t[n] = 0;
        b = parse_bits(t);
        for (d = -8; d <= 8; d++) {
            uint32_t c = (uint32_t)((int32_t)b + d);
            if (c == 0u || c >= 0x7f800000u) continue;
            pm(&s, c);
        }
    }
    if (!CHECK_EQ(s.fails, 0)) { h_str("    of "); h_u32(s.cases); h_nl(); }
}

static void format_float_random(void)
{
    fmt_stats s = {0, 0};
    uint32_t i, st = 20261201u;
    for (i = 0; i < FMT_RANDOM; i++) one(&s, h_rand(&st));
    if (!CHECK_EQ(s.fails, 0)) { h_str("    of "); h_u32(s.cases); h_nl(); }
}

#endif

static void format_fixed_edges(void)
{
    fmt_stats s = {0, 0};
    uint32_t i;
    /* every fraction with integer part 0, 1 and 32767 (the longest texts), both signs */
    for (i = 0; i < 65536u; i += H_HOST ? 1u : 61u) {
        pm16(&s, i);
        pm16(&s, 0x10000u + i);
        pm16(&s, 0x7fff0000u + i);
    }
    one_kind(&s, 0x80000000u, 1); /* -32768 */
    /* a stride over the 2^32 values (every integer part, varied fractions) */
    for (i = 0; i < (H_HOST ? 1047824u : 1000u); i++) one_kind(&s, i * (H_HOST ? 4099u : 4294967u), 1);
    if (!CHECK_EQ(s.fails, 0)) { h_str("    of "); h_u32(s.cases); h_nl(); }
}

static void format_fixed_random(void)
{
    fmt_stats s = {0, 0};
    uint32_t i, st = 20261201u;
    for (i = 0; i < FMT_RANDOM; i++) one_kind(&s, h_rand(&st), 1);
    if (!CHECK_EQ(s.fails, 0)) { h_str("    of "); h_u32(s.cases); h_nl(); }
}


const test_case suite_format[] = {
#if !SUBD_FIXED
    {"format_float_edges", format_float_edges},
    {"format_float_random", format_float_random},
#endif
    {"format_fixed_edges", format_fixed_edges},
    {"format_fixed_random", format_fixed_random},
    {0, 0}
};
