/* SPDX-License-Identifier: MIT */
/* The chord test of the streaming alpha curve's adaptive mode (alpha_stream.c, which decides
 * its spans top down with it): is every point strictly between a and b within eps of the
 * segment from point a to point b? Zhang & Wang 2002 define the curves only; the chordal
 * tolerance is beyond the paper (the choices: alpha_stream.c's header, "Adaptive mode").
 *
 * Each distance is bounded from above, never rounded down: a point Q of the segment is
 * computed (the projection's parameter clamped to [0, 1]: where Q lies on the segment
 * changes the distance, not the bound's validity) and |P - Q| is compared with eps less a
 * margin for Q's own rounding. Q16.16: exact int64 differences, the parameter in Q32.32 from
 * vectors scaled below 2^30, Q rounded to units (within 0.87 units of the segment: one unit
 * of margin). float: differences in the wide type of vec3w.h, a margin of 2^-20 of the
 * magnitudes involved (a few ulps of each rounding) and 0.1 % more; inf or NaN splits.
 * Moved out of alpha_stream.c (its length); same code, same bits.
 */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "alpha_internal.h"
#include "vec3w.h"

#if SUBD_FIXED /* the distance bound differs: exact int64/128-bit arithmetic on Q16.16 units */
static int alpha_near(subd_real eps, const subd_real *A, const subd_real *B, const subd_real *P)
{
    int64_t u[3], d[3], us[3], ds[3], num, den, t, e;
    const int64_t eps_raw = (int64_t)eps - 1; /* one unit of margin for rounding Q, below */
    uint64_t sum = 0, big = 0, lim;
    uint32_t k, ovf = 0;
    int32_t sh;
    for (k = 0; k < 3u; k++) {
        u[k] = (int64_t)B[k] - A[k];
        d[k] = (int64_t)P[k] - A[k];
        if ((uint64_t)(u[k] < 0 ? -u[k] : u[k]) > big) big = (uint64_t)(u[k] < 0 ? -u[k] : u[k]);
        if ((uint64_t)(d[k] < 0 ? -d[k] : d[k]) > big) big = (uint64_t)(d[k] < 0 ? -d[k] : d[k]);
    }
    /* the projection parameter from vectors scaled below 2^30 (only where Q lies on the
     * segment depends on it, not the bound's validity) */
    sh = (int32_t)subd_bitlen64(big) - 30;
    if (sh < 0) sh = 0;
    for (k = 0; k < 3u; k++) {
        us[k] = u[k] / ((int64_t)1 << sh);
        ds[k] = d[k] / ((int64_t)1 << sh);
    }
    num = us[0] * ds[0] + us[1] * ds[1] + us[2] * ds[2];
    den = us[0] * us[0] + us[1] * us[1] + us[2] * us[2];
    if (den <= 0 || num <= 0) t = 0;
    else if (num >= den) t = SUBD_Q32_ONE;
    else t = subd_alpha_divq(num, den, 32, &ovf);
    if (ovf || eps_raw <= 0) return 0;
    /* Q = A + t u, rounded to units: within 0.87 units of the segment; eps_raw has that margin */
    for (k = 0; k < 3u; k++) {
        e = d[k] - subd_alpha_mulq(u[k], t, 32, &ovf);
        if (e < 0) e = -e;
        if (e > eps_raw) return 0;
        sum += (uint64_t)e * (uint64_t)e;
    }
    lim = (uint64_t)eps_raw * (uint64_t)eps_raw;
    return !ovf && sum <= lim;
}
#else
static float alpha_absf(float x) { return x < 0.0f ? -x : x; }
static int alpha_near(subd_real eps, const subd_real *A, const subd_real *B, const subd_real *P)
{
    subd_wide u[3], d[3], e[3];
    float num, den, t, big = 0.0f, tol, lim, ee;
    uint32_t k;
    subd_w3_diff(B, A, u);
    subd_w3_diff(P, A, d);
    num = subd_w3_dot(u, d);
    den = subd_w3_dot(u, u);
    if (!(den > 0.0f) || !(num > 0.0f)) t = 0.0f;
    else if (num >= den) t = 1.0f;
    else t = num / den;
    for (k = 0; k < 3u; k++) {
        float q = t * u[k];
        e[k] = d[k] - q;
        big = big + alpha_absf(A[k]) + alpha_absf(u[k]) + alpha_absf(P[k]);
    }
    /* rounding of u, d, t u and the difference: a few ulps of the magnitudes involved */
    tol = big * 0x1p-20f;
    if (!(eps > tol)) return 0;
    lim = (eps - tol) * (eps - tol) * 0.999f;
    ee = subd_w3_dot(e, e);
    return ee <= lim; /* false for inf / nan: split */
}
#endif

int subd_alpha_span_near(subd_real eps, const subd_real *pts, uint32_t a, uint32_t b)
{
    uint32_t i;
    for (i = a + 1u; i < b; i++)
        if (!alpha_near(eps, pts + 3u * a, pts + 3u * b, pts + 3u * i)) return 0;
    return 1;
}
