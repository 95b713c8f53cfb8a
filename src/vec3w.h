/* SPDX-License-Identifier: MIT */
/* Wide 3-vectors: differences, dot and cross products of subd_reals that must not lose
 * bits (face normals, tangents, point-triangle distances), written once for both
 * arithmetics. Used by crease.c, sr48_adapt.c and loop_limit.c (limit tangents and
 * normals: subd_w3_normalize + subd_w3_cross + subd_w3_unit).
 *
 * subd_wide is int64_t in the Q16.16 build (values in units of 2^-16, exact) and float in
 * the float32 build.
 *
 * Scaling and overflow contract (CMSIS-DSP style):
 *  - subd_wide_diff / subd_w3_diff: Q16.16 exact (|p - q| < 2^32). float32: one rounding.
 *  - subd_w3_dot, subd_w3_cross: Q16.16 exact int64 arithmetic; the CALLER keeps every
 *    component below 2^30 in magnitude (then |dot| < 3 * 2^60, |cross| < 2^61), usually
 *    with subd_w3_normalize / subd_w3_fit first. float32: products rounded one at a time
 *    into named temporaries and summed left to right, so the bits do not depend on the
 *    compiler contracting a*b+c (DESIGN.md); no overflow guard: scale first if needed.
 *  - subd_w3_normalize(t, o, bits): a direction-preserving rescale, for when only the
 *    direction matters. float32: o = t / max|t_k| (so max|o_k| = 1). Q16.16: o = t * 2^-s
 *    with s = bitlen(max|t_k|) - bits, so max|o_k| is in [2^(bits-1), 2^bits); shrinking
 *    truncates toward zero, growing is exact. t = 0 gives o = 0. bits in 1..62.
 *    subd_w3_normalize_shr: the same values, Q16.16 by shifts instead of 64-bit divisions.
 *  - subd_w3_fit(t, o, bits): as subd_w3_normalize but Q16.16 only shrinks (s >= 0), so
 *    small vectors keep their size: max|o_k| < 2^bits. float32: the same as normalize.
 *  - subd_w3_unit(c, out) (vec3w.c): c / |c| as subd_reals, (0, 0, 0) for c = 0; c is first
 *    rescaled by subd_w3_normalize(c, ., 30), so any c is accepted. Q16.16: rounded to
 *    nearest (ties away from zero) in units of 2^-16; float32: n / sqrt(n . n).
 *  - subd_wide_madd(acc, w, d) = acc + w * d for a subd_real weight: Q16.16 exact in int64
 *    (acc in units of 2^-32) while the caller keeps |w d| and the sum below 2^63; float32
 *    the product rounded into a temporary, then the sum.
 *  - subd_wide_mulu(n, x) = n * x: Q16.16 exact while |x| < 2^31 and n < 2^32; float32 one
 *    rounding. subd_wide_of(x): x widened (exact in both).
 *  - subd_w3_dist2(p, q, ovf) (vec3w.c): |p - q|^2 of saturated differences (subd_sub),
 *    Q16.16 exact in 64 bits (vec3w's exact differences would need 33 bits and its dot
 *    product 30-bit components), float32 rounded per product and summed left to right, an
 *    infinite sum flagged in *ovf; subd_w3_dist_root(s, ovf): its square root as a subd_real
 *    (Q16.16: the integer root rounded to nearest, saturated to INT32_MAX with *ovf set).
 *    PIA's error measure (pia.c, pia_fast.c).
 *  - subd_w3_span_*, subd_w3_side, subd_w3_add_ratio: see their comments below.
 * All but subd_w3_unit are static inline; none has side effects but subd_w3_add_ratio's on
 * p and *ovf; o may alias t. */
#ifndef SUBD_VEC3W_H
#define SUBD_VEC3W_H
#include "subd.h"
#include "real_avg.h" /* subd_div_round */

#if SUBD_FIXED
typedef int64_t subd_wide;
typedef uint64_t subd_dist_sq; /* a squared distance in LSB^2, exact: 3 * (2^31)^2 < 2^64 */
#else
typedef float subd_wide;
typedef float subd_dist_sq; /* a squared distance, a plain left-to-right sum */
#endif

static inline subd_wide subd_wide_of(subd_real x) { return (subd_wide)x; }
static inline subd_wide subd_wide_diff(subd_real p, subd_real q) { return (subd_wide)p - (subd_wide)q; }
static inline subd_wide subd_wide_mulu(uint32_t n, subd_wide x) { return (subd_wide)n * x; }

static inline subd_wide subd_wide_madd(subd_wide acc, subd_real w, subd_wide d)
{
    subd_wide t = (subd_wide)w * d;
    return acc + t;
}

/* r = p - q */
static inline void subd_w3_diff(const subd_real *p, const subd_real *q, subd_wide *r)
{
    r[0] = subd_wide_diff(p[0], q[0]);
    r[1] = subd_wide_diff(p[1], q[1]);
    r[2] = subd_wide_diff(p[2], q[2]);
}

/* r = a - b */
static inline void subd_w3_sub(const subd_wide *a, const subd_wide *b, subd_wide *r)
{
    r[0] = a[0] - b[0];
    r[1] = a[1] - b[1];
    r[2] = a[2] - b[2];
}

static inline subd_wide subd_w3_dot(const subd_wide *a, const subd_wide *b)
{
    subd_wide p0 = a[0] * b[0], p1 = a[1] * b[1], p2 = a[2] * b[2];
    return p0 + p1 + p2;
}

/* r = a x b; r must not alias a or b. */
static inline void subd_w3_cross(const subd_wide *a, const subd_wide *b, subd_wide *r)
{
    subd_wide p0, p1;
    p0 = a[1] * b[2];
    p1 = a[2] * b[1];
    r[0] = p0 - p1;
    p0 = a[2] * b[0];
    p1 = a[0] * b[2];
    r[1] = p0 - p1;
    p0 = a[0] * b[1];
    p1 = a[1] * b[0];
    r[2] = p0 - p1;
}

/* Number of significant bits of v (0 for 0), by halving instead of a loop over 64 bits.
 * Integer only: available in both builds (edge_sort.c's length keys use it too). */
static inline uint32_t subd_bitlen64(uint64_t v)
{
    uint32_t n = 0;
    if (v >> 32) { n += 32u; v >>= 32; }
    if (v >> 16) { n += 16u; v >>= 16; }
    if (v >> 8) { n += 8u; v >>= 8; }
    if (v >> 4) { n += 4u; v >>= 4; }
    if (v >> 2) { n += 2u; v >>= 2; }
    if (v >> 1) { n += 1u; v >>= 1; }
    return n + (uint32_t)v;
}

#if SUBD_FIXED
static inline uint64_t subd_w3_maxabs(const subd_wide *t)
{
    uint64_t big = 0;
    uint32_t k;
    for (k = 0; k < 3u; k++) {
        uint64_t a = (uint64_t)(t[k] < 0 ? -t[k] : t[k]);
        if (a > big) big = a;
    }
    return big;
}

/* x / 2^s truncated toward zero (C's division) for s in 1..63, as a shift of the magnitude:
 * a 64-bit division is a library call on Cortex-M (__aeabi_ldivmod, about a hundred
 * instructions; the limit normals made nine per vertex). |x| >> s < 2^63, so the negation
 * back is defined. */
static inline int64_t subd_wide_shr_trunc(int64_t x, uint32_t s)
{
    uint64_t m = x < 0 ? 0u - (uint64_t)x : (uint64_t)x;
    m >>= s;
    return x < 0 ? -(int64_t)m : (int64_t)m;
}

/* o = t * 2^-s: truncating division for s > 0, exact product for s <= 0. */
static inline void subd_w3_shift(const subd_wide *t, subd_wide *o, int32_t s)
{
    uint32_t k;
    if (s > 0)
        for (k = 0; k < 3u; k++) o[k] = t[k] / ((int64_t)1 << s);
    else
        for (k = 0; k < 3u; k++) o[k] = t[k] * ((int64_t)1 << -s);
}

static inline void subd_w3_normalize(const subd_wide *t, subd_wide *o, uint32_t bits)
{
    subd_w3_shift(t, o, (int32_t)subd_bitlen64(subd_w3_maxabs(t)) - (int32_t)bits);
}

/* subd_w3_normalize's values, the division as subd_wide_shr_trunc: the limit normals
 * (loop_limit_internal.h, subd_w3_unit) rescale three vectors per vertex (Cortex-M3 limit
 * stream: about 100 instructions fewer per triangle); quasi48.c measured 1% slower with the
 * shifts (its fan's code around them), so the other callers keep the division. */
static inline void subd_w3_normalize_shr(const subd_wide *t, subd_wide *o, uint32_t bits)
{
    int32_t s = (int32_t)subd_bitlen64(subd_w3_maxabs(t)) - (int32_t)bits;
    uint32_t k;
    if (s > 0)
        for (k = 0; k < 3u; k++) o[k] = subd_wide_shr_trunc(t[k], (uint32_t)s);
    else
        subd_w3_shift(t, o, s);
}

static inline void subd_w3_fit(const subd_wide *t, subd_wide *o, uint32_t bits)
{
    int32_t s = (int32_t)subd_bitlen64(subd_w3_maxabs(t)) - (int32_t)bits;
    subd_w3_shift(t, o, s > 0 ? s : 0);
}
#else
/* Written out for the three components (the loops cost Loop limit normals a third of their
 * instructions on a Cortex-M4F); the same operations as the loops they replace. The
 * magnitude is the compiler's fabs where it has one (one instruction): it differs from
 * t < 0 ? -t : t only for -0 (+0) and in a NaN's sign, and neither can pass a > big with
 * big >= +0, so big is the same. */
#if defined(__GNUC__)
#define SUBD_W3_ABS(x) __builtin_fabsf(x)
#else
#define SUBD_W3_ABS(x) ((x) < 0.0f ? -(x) : (x))
#endif
static inline void subd_w3_normalize(const subd_wide *t, subd_wide *o, uint32_t bits)
{
    float t0 = t[0], t1 = t[1], t2 = t[2], big = 0.0f, a;
    (void)bits;
    a = SUBD_W3_ABS(t0);
    if (a > big) big = a;
    a = SUBD_W3_ABS(t1);
    if (a > big) big = a;
    a = SUBD_W3_ABS(t2);
    if (a > big) big = a;
    if (big > 0.0f) {
        o[0] = t0 / big;
        o[1] = t1 / big;
        o[2] = t2 / big;
    } else {
        o[0] = o[1] = o[2] = 0.0f;
    }
}

static inline void subd_w3_fit(const subd_wide *t, subd_wide *o, uint32_t bits) { subd_w3_normalize(t, o, bits); }
static inline void subd_w3_normalize_shr(const subd_wide *t, subd_wide *o, uint32_t bits) { subd_w3_normalize(t, o, bits); }
#endif

/* A common shift for a set of wide 3-vectors whose cross products are summed (a face's
 * Newell fan in crease.c, a vertex's fan of faces): Q16.16 shifts every vector by one s so
 * that its components are below 2^bits, so the products and their sum stay in int64 and the
 * terms add up exactly; float32 has the range and leaves the vectors alone.
 *  - subd_w3_span_add(big, t): max(big, max |t_k|) (Q16.16; float32: big unchanged);
 *  - subd_w3_span_shift(big, bits): s = max(0, bitlen(big) - bits) (float32: 0);
 *  - subd_w3_span_apply(t, o, s): o = t * 2^-s, truncating toward zero (subd_w3_shift),
 *    so a sign change commutes with it (float32: o = t). */
/* 1 when (q - p) . n >= 0 for subd_real points q, p and a direction n (a plane side test).
 * Q16.16: exact: each product is below 2^63 in magnitude and the sum of three is kept as
 * hi 2^32 + lo with 0 <= lo < 2^32, so its sign is the sign of hi. float32: differences and
 * products rounded one at a time, summed left to right. */
/* subd_w3_add_ratio(p, num, den, u, ovf): p += (num / den) u for den > 0 (the projection of
 * a displacement on u, with num = d . u and den = u . u). Q16.16: num, den and u_k as from
 * subd_w3_normalize(., ., 20) and an exact difference (|num| < 2^54, den < 2^42,
 * |u_k| < 2^20); (num / den) u_k is formed as q u_k + round(r u_k / den) from the truncating
 * quotient q and remainder r, exact but for that one rounding; a result outside the Q16.16
 * range sets *ovf and leaves that and the later components of p as they were. float32:
 * s = num / den once, then p_k + s u_k, each rounded (subd_chk sets *ovf when not finite). */
#if SUBD_FIXED
static inline uint64_t subd_w3_span_add(uint64_t big, const subd_wide *t)
{
    uint64_t x = subd_w3_maxabs(t);
    return x > big ? x : big;
}

static inline int32_t subd_w3_span_shift(uint64_t big, uint32_t bits)
{
    int32_t s = (int32_t)subd_bitlen64(big) - (int32_t)bits;
    return s > 0 ? s : 0;
}

static inline void subd_w3_span_apply(const subd_wide *t, subd_wide *o, int32_t s) { subd_w3_shift(t, o, s); }

static inline int subd_w3_side(const subd_real *q, const subd_real *p, const subd_real *n)
{
    int64_t hi = 0, lo = 0;
    uint32_t i;
    for (i = 0; i < 3u; i++) {
        int64_t prod = ((int64_t)q[i] - p[i]) * (int64_t)n[i];
        hi += prod >> 32;
        lo += prod & (int64_t)0xffffffff;
    }
    hi += lo >> 32;
    return hi >= 0;
}

static inline void subd_w3_add_ratio(subd_real *p, subd_wide num, subd_wide den, const subd_wide *u, uint32_t *ovf)
{
    int64_t q = num / den, r = num % den;
    uint32_t k;
    for (k = 0; k < 3u; k++) {
        int64_t x = (int64_t)p[k] + q * u[k] + subd_div_round(r * u[k], den);
        if (x > INT32_MAX || x < INT32_MIN) {
            *ovf |= 1u;
            return;
        }
        p[k] = (subd_real)x;
    }
}
#else
static inline uint64_t subd_w3_span_add(uint64_t big, const subd_wide *t)
{
    (void)t;
    return big;
}

static inline int32_t subd_w3_span_shift(uint64_t big, uint32_t bits)
{
    (void)big;
    (void)bits;
    return 0;
}

static inline void subd_w3_span_apply(const subd_wide *t, subd_wide *o, int32_t s)
{
    (void)s;
    o[0] = t[0];
    o[1] = t[1];
    o[2] = t[2];
}

static inline int subd_w3_side(const subd_real *q, const subd_real *p, const subd_real *n)
{
    float s0 = (q[0] - p[0]) * n[0], s1 = (q[1] - p[1]) * n[1], s2 = (q[2] - p[2]) * n[2];
    return s0 + s1 + s2 >= 0.0f;
}

static inline void subd_w3_add_ratio(subd_real *p, subd_wide num, subd_wide den, const subd_wide *u, uint32_t *ovf)
{
    float s = num / den;
    uint32_t k;
    for (k = 0; k < 3u; k++) {
        float m = s * u[k];
        p[k] = subd_chk(p[k] + m, ovf);
    }
}
#endif

void subd_w3_unit(const subd_wide *c, subd_real *out);
subd_dist_sq subd_w3_dist2(const subd_real *p, const subd_real *q, uint32_t *ovf);
subd_real subd_w3_dist_root(subd_dist_sq s, uint32_t *ovf);

#endif
