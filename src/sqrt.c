/* SPDX-License-Identifier: MIT */
/* Deterministic square roots in integer arithmetic (no libm: sqrtf would pull libm into the
 * device image, and the link proofs forbid it).
 *
 * subd_isqrt64: the integer square root of a uint64, digit by digit (two bits of the
 * argument per result bit, 32 steps of shift/compare/subtract), rounded to nearest. No
 * division, no multiplication wider than the operands, so it runs the same on every
 * target (the result saturates at 2^32 - 1 above (2^32 - 1/2)^2). Round to nearest: with r = floor(sqrt(x)) and rem = x - r^2, sqrt(x) >= r + 1/2
 * exactly when x >= r^2 + r + 1/4, i.e. (integers) rem > r; an exact half cannot occur.
 *
 * subd_sqrt, float32: correctly rounded (round to nearest, ties to even; a tie cannot occur
 * for a square root of a float) and therefore bit-identical to IEEE sqrt for every
 * non-negative input, +0, -0 (gives -0), subnormals and +inf. The argument is taken apart
 * as m * 2^e with an integer m < 2^24 (subnormals normalised), m is shifted left so that
 * M = m * 2^s has 47 or 48 bits and e - s is even; then floor(sqrt(M)) has exactly 24 bits
 * and the remainder decides the rounding as above (a carry into bit 24 is absorbed by the
 * exponent field when the pattern is assembled by addition). Negative inputs (not -0) and
 * -inf give the quiet NaN 0x7fc00000 (the ARM default NaN; x86's sqrtss gives 0xffc00000,
 * so NaN bits are the one place a host libm differs); a NaN input is returned quieted.
 *
 * subd_sqrt, Q16.16: the nearest Q16.16 value to sqrt(x / 2^16), i.e. the rounded integer
 * square root of x * 2^16 (< 2^47, result < 2^24); negative inputs give 0.
 */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "subd.h"

/* floor(sqrt(x)) and the remainder x - floor(sqrt(x))^2. */
static uint32_t isqrt_floor(uint64_t x, uint64_t *rem_out)
{
    uint64_t rem = x, res = 0, bit = (uint64_t)1 << 62;
    while (bit > rem) bit >>= 2;
    while (bit != 0u) {
        if (rem >= res + bit) {
            rem -= res + bit;
            res = (res >> 1) + bit;
        } else {
            res >>= 1;
        }
        bit >>= 2;
    }
    *rem_out = rem;
    return (uint32_t)res;
}

uint32_t subd_isqrt64(uint64_t x)
{
    uint64_t rem;
    uint32_t r = isqrt_floor(x, &rem);
    /* sqrt(x) >= r + 1/2 exactly when rem > r; saturate at 2^32 - 1 for x >= (2^32 - 1/2)^2 */
    return (rem > r && r != UINT32_MAX) ? r + 1u : r;
}

#if SUBD_FIXED

subd_real subd_sqrt(subd_real x)
{
    if (x <= 0) return 0;
    return (subd_real)subd_isqrt64((uint64_t)x << 16);
}

#else

subd_real subd_sqrt(subd_real x)
{
    union { float f; uint32_t u; } c;
    uint32_t bits, expf, r;
    uint64_t m, rem;
    int32_t e;
    c.f = x;
    bits = c.u;
    if ((bits & 0x7fffffffu) == 0u) return x;               /* +0 -> +0, -0 -> -0 */
    if ((bits & 0x7f800000u) == 0x7f800000u && (bits & 0x007fffffu) != 0u) {
        c.u = bits | 0x00400000u;                              /* NaN: quiet it */
        return c.f;
    }
    if (bits & 0x80000000u) {                                  /* negative, -inf */
        c.u = 0x7fc00000u;
        return c.f;
    }
    if (bits == 0x7f800000u) return x;                         /* +inf */
    expf = bits >> 23;
    m = bits & 0x007fffffu;
    if (expf == 0u) {
        e = -149;                                              /* subnormal: m * 2^-149 */
    } else {
        m |= 0x00800000u;
        e = (int32_t)expf - 150;                               /* normal: m * 2^(E-150) */
    }
    /* shift m to 47 or 48 bits with an even exponent: x = M * 2^e, e even */
    while (m < ((uint64_t)1 << 46)) {
        m <<= 1;
        e--;
    }
    if (e & 1) {
        m <<= 1;
        e--;
    }
    /* M in [2^46, 2^48): r = floor(sqrt(M)) in [2^23, 2^24) */
    r = isqrt_floor(m, &rem);
    if (rem > r) r++;                                          /* nearest (no ties) */
    /* result = r * 2^(e/2), r a 24-bit significand (or 2^24 after rounding up) */
    c.u = ((uint32_t)(e / 2 + 149) << 23) + r; /* biased exponent e/2 + 150, hidden bit in r */
    return c.f;
}

#endif
