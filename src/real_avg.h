/* SPDX-License-Identifier: MIT */
/* Rounding averages of subd_reals: sums, means, midpoints and the half-and-half blend that
 * quasi 4-8 and semi-regular 4-8 smoothing use, written once for both arithmetics.
 *
 * Why a header of its own: the Q16.16 forms are exact (a 64-bit sum of the values, one
 * division rounded to nearest, ties away from zero, so the result is symmetric under
 * negation and a planar input stays exactly planar); the float32 forms are the plain
 * expressions, with the midpoint halving first so that a + b cannot overflow near FLT_MAX.
 *
 * Two midpoints exist because two roundings are in use and the outputs must keep their bits:
 * subd_mid halves first (float32), subd_mid_of_sum rounds the sum and halves it (float32:
 * overflow of a + b is reported), subd_mid_of_sum_even is the same with Q16.16 ties to even
 * (the alpha curve operator's unbiased rounding). In float32 the two sum-first forms agree;
 * in Q16.16 subd_mid and subd_mid_of_sum agree.
 *
 * Scaling and overflow contract (CMSIS-DSP style):
 *  - Q16.16: subd_sum is int64_t. A sum of at most 2^31 subd_reals is exact. subd_avg,
 *    subd_mid and subd_blend return a convex combination of in-range values, which is in
 *    range, so they never saturate and never set *ovf. k must be >= 1.
 *    subd_mid_of_sum_even's h + (s & h & 1) is round-half-to-even of s / 2.
 *  - float32: subd_sum is float, summed in the caller's order (float sums depend on it).
 *    Each result goes through subd_chk, which sets *ovf when it is not finite.
 * All functions are static inline: callers in the scheme files get the same code as the
 * copies they replace, so results are bit-identical to before. */
#ifndef SUBD_REAL_AVG_H
#define SUBD_REAL_AVG_H
#include "subd.h"

#if SUBD_FIXED
typedef int64_t subd_sum; /* exact sums of Q16.16 values */

/* n / k rounded to nearest, ties away from zero; k >= 1. */
static inline subd_real subd_div_round(int64_t n, int64_t k)
{
    int64_t q = (n >= 0) ? (n + k / 2) / k : -((-n + k / 2) / k);
    return (subd_real)q; /* callers divide a convex combination: in range */
}
static inline subd_sum subd_sum_add(subd_sum s, subd_real v) { return s + v; }
/* s / k, one rounding. */
static inline subd_real subd_avg(subd_sum s, uint32_t k, uint32_t *ovf)
{
    (void)ovf;
    return subd_div_round(s, (int64_t)k);
}
/* (a + b) / 2, one rounding. */
static inline subd_real subd_mid(subd_real a, subd_real b, uint32_t *ovf)
{
    (void)ovf;
    return subd_div_round((int64_t)a + b, 2);
}
/* 1/2 p + 1/2 (s / k) = (k p + s) / (2k), one rounding. */
static inline subd_real subd_blend(subd_real p, subd_sum s, uint32_t k, uint32_t *ovf)
{
    (void)ovf;
    return subd_div_round((int64_t)k * p + s, 2 * (int64_t)k);
}
static inline subd_real subd_mid_of_sum(subd_real a, subd_real b, uint32_t *ovf) { return subd_mid(a, b, ovf); }
/* (a + b) / 2, ties to even. */
static inline subd_real subd_mid_of_sum_even(subd_real a, subd_real b, uint32_t *ovf)
{
    int64_t s = (int64_t)a + b, h = s >> 1;
    (void)ovf;
    return (subd_real)(h + (s & h & 1));
}
#else
typedef float subd_sum;

static inline subd_sum subd_sum_add(subd_sum s, subd_real v) { return s + v; }
static inline subd_real subd_avg(subd_sum s, uint32_t k, uint32_t *ovf) { return subd_chk(s / (float)k, ovf); }
static inline subd_real subd_mid(subd_real a, subd_real b, uint32_t *ovf)
{
    subd_real ha = 0.5f * a, hb = 0.5f * b; /* no overflow of a + b near FLT_MAX */
    return subd_chk(ha + hb, ovf);
}
static inline subd_real subd_blend(subd_real p, subd_sum s, uint32_t k, uint32_t *ovf)
{
    subd_real avg = s / (float)k, hp = 0.5f * p, ha = 0.5f * avg;
    return subd_chk(hp + ha, ovf);
}
/* (a + b) * 1/2: the sum rounded (and checked), then halved exactly. */
static inline subd_real subd_mid_of_sum(subd_real a, subd_real b, uint32_t *ovf)
{
    return subd_mul(subd_add(a, b, ovf), 0.5f, ovf);
}
static inline subd_real subd_mid_of_sum_even(subd_real a, subd_real b, uint32_t *ovf)
{
    return subd_mid_of_sum(a, b, ovf);
}
#endif

#endif
