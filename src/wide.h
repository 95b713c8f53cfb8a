/* SPDX-License-Identifier: MIT */
/* Wide integer arithmetic with one home (part of the scalar layer, beside subd_real.h,
 * real_avg.h and vec3w.h): the 64x64 -> 128-bit product, the 128/64-bit long division, the
 * correctly rounded conversion of a scaled integer to subd_real and back, and one gcd.
 * Written once for trig.c (its Q63 Taylor series), alpha_kernel.c (Q32.32 kernel values),
 * loop_rules.c / loop_limit.c (Q62 limit and smooth-rule weights), pia_fast.c (the ratio
 * of its exact CG dot products) and tags.c (reduced alpha fractions).
 *
 * Why by hand: 32-bit ARM has no __int128, and the library must give the same bits on the
 * host and on a Cortex-M, so every step is 32x32 -> 64-bit products and 64-bit shifts.
 *
 * Contracts (all exact unless a rounding is named; no function has side effects):
 *  - subd_u128_mul(a, b): the full product a * b of two uint64 (any values).
 *  - subd_u128_add64(n, c): n + c with the carry into hi (wraps only above 2^128).
 *  - subd_u128_shr(n, s): floor(n / 2^s), s in 1..127, the low 64 bits of it (callers keep
 *    the quotient below 2^64: that is their range argument, not checked here).
 *  - subd_u128_shr_round(n, s): round(n / 2^s), half up, as subd_u128_shr of n + 2^(s-1).
 *  - subd_u128_div(n, d, &rem) (wide.c): floor(n / d) and n mod d for n.hi < d (so the
 *    quotient fits 64 bits), d any nonzero uint64. Restoring long division, 64 steps;
 *    two 64/32-bit digit steps when d < 2^32. The quotient is the exact floor whatever the
 *    path, so callers round as they like from the remainder (2 rem >= d: half up).
 *  - subd_f32_bits_from_scaled(q, frac) (wide.c): the IEEE-754 binary32 bit pattern of
 *    q * 2^-frac rounded to nearest, ties to even, frac in 0..62 (every nonzero result is
 *    then a normal float: 2^-62 <= |value| <= 2^63). Integer code, so it exists (and is
 *    tested) in both builds; the float build reads the pattern as its subd_real.
 *  - subd_real_from_scaled_away / _up(q, frac, ovf): q * 2^-frac as a subd_real, frac in
 *    17..62. float32: subd_f32_bits_from_scaled (never sets *ovf). Q16.16: the two tie rules
 *    of the library, kept apart because they are observable (see test_wide.c):
 *      _away: half away from zero (trig.c's subd_real_from_q62, symmetric: -x rounds to
 *             -(x rounded));
 *      _up:   half up, towards +infinity (the alpha kernel's Q32.32 values,
 *             subd_alpha_kernel_value: e.g. -2^-17 rounds to 0, not to -2^-16);
 *    both saturate to the Q16.16 range with *ovf set.
 *  - subd_real_to_q32(x, ovf): x * 2^32 as int64. Q16.16 exact. float32: rounded to nearest
 *    (ties up in magnitude; tiny values give 0); *ovf when |x| >= 2^30 or x is not finite.
 *  - subd_gcd64(a, b) (wide.c): gcd(|a|, |b|) for any int64 a, b, gcd(a, 0) = |a| (Euclid;
 *    at most ~92 steps).
 */
#ifndef SUBD_WIDE_H
#define SUBD_WIDE_H
#include "subd.h"

/* An unsigned 128-bit integer hi * 2^64 + lo. */
typedef struct subd_u128 {
    uint64_t hi, lo;
} subd_u128;

/* a * b from four 32x32 -> 64-bit products. */
static inline subd_u128 subd_u128_mul(uint64_t a, uint64_t b)
{
    uint64_t a0 = (uint32_t)a, a1 = a >> 32, b0 = (uint32_t)b, b1 = b >> 32;
    uint64_t p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
    uint64_t mid = (p00 >> 32) + (uint32_t)p01 + (uint32_t)p10;
    subd_u128 r;
    r.hi = p11 + (p01 >> 32) + (p10 >> 32) + (mid >> 32);
    r.lo = (mid << 32) | (uint32_t)p00;
    return r;
}

static inline subd_u128 subd_u128_add64(subd_u128 n, uint64_t c)
{
    n.lo += c;
    if (n.lo < c) n.hi++;
    return n;
}

/* floor(n / 2^s), low 64 bits; s in 1..127. */
static inline uint64_t subd_u128_shr(subd_u128 n, uint32_t s)
{
    if (s < 64u) return (n.hi << (64u - s)) | (n.lo >> s);
    return s == 64u ? n.hi : n.hi >> (s - 64u);
}

/* round(n / 2^s) half up, low 64 bits; s in 1..127. */
static inline uint64_t subd_u128_shr_round(subd_u128 n, uint32_t s)
{
    subd_u128 h;
    h.hi = s > 64u ? (uint64_t)1 << (s - 65u) : 0u;
    h.lo = s > 64u ? 0u : (uint64_t)1 << (s - 1u);
    n.lo += h.lo;
    n.hi += h.hi + (n.lo < h.lo ? 1u : 0u);
    return subd_u128_shr(n, s);
}

uint64_t subd_u128_div(subd_u128 n, uint64_t d, uint64_t *rem);
uint32_t subd_f32_bits_from_scaled(int64_t q, uint32_t frac);
uint64_t subd_gcd64(int64_t a, int64_t b);

/* Why the #if (scalar layer): the two arithmetics round a scaled integer differently. */
#if SUBD_FIXED
/* |q| * 2^-(frac-16) rounded, the sign applied afterwards (half away from zero). */
static inline subd_real subd_real_from_scaled_away(int64_t q, uint32_t frac, uint32_t *ovf)
{
    uint32_t sh = frac - 16u;
    uint64_t u = q < 0 ? 0u - (uint64_t)q : (uint64_t)q;
    uint64_t m = (u >> sh) + ((u >> (sh - 1u)) & 1u); /* u + 2^(sh-1) could wrap at u = 2^64 - 1 */
    if (m > (uint64_t)INT32_MAX) {
        *ovf |= 1u;
        return q < 0 ? INT32_MIN : INT32_MAX;
    }
    return (subd_real)(q < 0 ? -(int64_t)m : (int64_t)m);
}

/* floor(q * 2^-(frac-16) + 1/2) (half up). */
static inline subd_real subd_real_from_scaled_up(int64_t q, uint32_t frac, uint32_t *ovf)
{
    uint32_t sh = frac - 16u;
    int64_t half = (int64_t)1 << (sh - 1u);
    if (q > INT64_MAX - half) {
        *ovf |= 1u;
        return INT32_MAX;
    }
    return subd_real_sat((q + half) >> sh, ovf);
}

static inline int64_t subd_real_to_q32(subd_real x, uint32_t *ovf)
{
    (void)ovf;
    return (int64_t)x * 65536;
}
#else
static inline subd_real subd_real_of_bits(uint32_t b)
{
    union { float f; uint32_t u; } c;
    c.u = b;
    return c.f;
}

static inline subd_real subd_real_from_scaled_away(int64_t q, uint32_t frac, uint32_t *ovf)
{
    (void)ovf;
    return subd_real_of_bits(subd_f32_bits_from_scaled(q, frac));
}

static inline subd_real subd_real_from_scaled_up(int64_t q, uint32_t frac, uint32_t *ovf)
{
    (void)ovf;
    return subd_real_of_bits(subd_f32_bits_from_scaled(q, frac));
}

static inline int64_t subd_real_to_q32(subd_real x, uint32_t *ovf)
{
    uint32_t b = subd_real_bits(x), e = (b >> 23) & 0xffu;
    uint64_t m = (b & 0x7fffffu) | 0x800000u, v;
    int neg = (b >> 31) != 0;
    if (e == 0xffu) {
        *ovf |= 1u;
        return 0;
    }
    if (e == 0) return 0; /* zero or subnormal: far below 2^-32 */
    /* x = m 2^(e - 150); Q32 = m 2^(e - 118) */
    if (e >= 118u) {
        if (e - 118u > 38u) {
            *ovf |= 1u;
            return 0;
        }
        v = m << (e - 118u);
    } else {
        uint32_t sh = 118u - e;
        if (sh > 40u) return 0;
        v = (m + ((uint64_t)1 << (sh - 1u))) >> sh;
    }
    return neg ? -(int64_t)v : (int64_t)v;
}
#endif

#endif
