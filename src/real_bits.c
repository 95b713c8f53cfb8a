/* SPDX-License-Identifier: MIT */
/* IEEE binary32 / binary64 bit patterns <-> subd_real, in integer arithmetic only.
 *
 * The binary mesh formats (STL, PLY) store coordinates as IEEE float32 or float64; these
 * conversions turn their bits into subd_reals with the rounding subd_real_parse gives the same
 * value written as text (src/real_text.c): float32 correctly rounded to nearest, ties to even,
 * subnormals kept; Q16.16 the nearest multiple of 2^-16, ties away from zero. Both are
 * computed from the bits alone (value = sig * 2^exp2 with an integer sig), so the fixed-point
 * build never touches float and a Cortex-M4F (single precision only) needs no double
 * arithmetic. The reverse, subd_real -> float32 bits, serves the binary STL writer: exact in
 * float32, and for Q16.16 the nearest float32 (ties to even) of x / 65536, which is what
 * (float)(x / 65536.0) gives on a host.
 */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "vec3w.h" /* subd_bitlen64 */
#include "real_bits.h"

/* |sig * 2^exp2| (sig < 2^63) rounded to float32 bits without sign (nearest, ties to even).
 * Returns SUBD_ERR_RANGE when the rounded value is 2^128 or more. */
static int rbits_to_f32(uint64_t sig, int32_t exp2, uint32_t *bits)
{
    int32_t e, q, s;
    uint64_t m;
    if (sig == 0u) { *bits = 0; return SUBD_OK; }
    e = (int32_t)subd_bitlen64(sig) - 1 + exp2; /* value in [2^e, 2^(e+1)) */
    if (e >= 128) return SUBD_ERR_RANGE;
    q = (e < -126 ? -126 : e) - 23;          /* exponent of the result's last bit */
    s = q - exp2;                            /* sig >> s is the result's significand */
    if (s <= 0) {
        m = sig << (uint32_t)(-s);           /* exact: at most 24 bits */
    } else if (s >= 64) {
        m = 0;                               /* below a quarter of the smallest subnormal */
    } else {
        uint64_t rem = sig & (((uint64_t)1 << (uint32_t)s) - 1u), half = (uint64_t)1 << (uint32_t)(s - 1);
        m = sig >> (uint32_t)s;
        if (rem > half || (rem == half && (m & 1u))) m++;
    }
    /* normal: m in [2^23, 2^24], the hidden bit (or a carry to 2^24) adds to the exponent;
     * subnormal: m <= 2^23, where 2^23 is the smallest normal, as it should be */
    *bits = e < -126 ? (uint32_t)m : ((uint32_t)(e + 126) << 23) + (uint32_t)m;
    return *bits >= 0x7f800000u ? SUBD_ERR_RANGE : SUBD_OK;
}

#if SUBD_FIXED /* the two arithmetics round differently (see subd_real.h) */
/* sig * 2^exp2 with the sign neg, rounded to Q16.16 (ties away from zero). */
static int rbits_to_real(uint32_t neg, uint64_t sig, int32_t exp2, subd_real *out)
{
    int32_t k = exp2 + 16; /* the value in units of 2^-16 is sig * 2^k */
    uint64_t mag;
    if (sig == 0u) {
        mag = 0;
    } else if (k >= 0) {
        if ((int32_t)subd_bitlen64(sig) + k > 32) return SUBD_ERR_RANGE;
        mag = sig << (uint32_t)k;
    } else if (k <= -63) {
        mag = 0; /* sig < 2^53 here: below half a unit */
    } else {
        mag = (sig + ((uint64_t)1 << (uint32_t)(-k - 1))) >> (uint32_t)(-k);
    }
    return subd_real_from_mag(neg, mag, out);
}
#else
static int rbits_to_real(uint32_t neg, uint64_t sig, int32_t exp2, subd_real *out)
{
    uint32_t bits;
    int st = rbits_to_f32(sig, exp2, &bits);
    if (st != SUBD_OK) return st;
    *out = subd_f32_of_bits(bits | (neg ? 0x80000000u : 0u));
    return SUBD_OK;
}
#endif

int subd_real_from_f32_bits(uint32_t bits, subd_real *out)
{
    uint32_t e = (bits >> 23) & 0xffu, f = bits & 0x7fffffu;
    if (!out) return SUBD_ERR_PARAM;
    if (e == 0xffu) return SUBD_ERR_NAN;
    return rbits_to_real(bits >> 31, e ? f | 0x800000u : f, (int32_t)(e ? e : 1u) - 150, out);
}

int subd_real_from_f64_bits(uint64_t bits, subd_real *out)
{
    uint32_t e = (uint32_t)(bits >> 52) & 0x7ffu;
    uint64_t f = bits & 0xfffffffffffffu;
    if (!out) return SUBD_ERR_PARAM;
    if (e == 0x7ffu) return SUBD_ERR_NAN;
    return rbits_to_real((uint32_t)(bits >> 63), e ? f | 0x10000000000000u : f, (int32_t)(e ? e : 1u) - 1075, out);
}

uint32_t subd_real_to_f32_bits(subd_real x)
{
    uint32_t bits = subd_real_bits(x);
    if (SUBD_FIXED) {
        /* x / 65536 with |x| <= 2^31: at most 32 significant bits, rounded to 24 */
        uint32_t neg = bits >> 31, mag = neg ? 0u - bits : bits, r = 0;
        (void)rbits_to_f32(mag, -16, &r); /* cannot fail: < 2^16 */
        return r | (neg << 31);
    }
    return bits;
}
