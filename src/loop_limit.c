/* SPDX-License-Identifier: MIT */
/* Loop limit positions and normals.
 * This file: the classification's use, the position masks (interior, curve, dart, corner)
 * and their caches, and the public calls; the normals (tangent masks) are
 * loop_limit_normal.c, the pieces both use loop_limit_internal.h.
 *
 * Paper: loop-progressive-interpolation.txt, formula (3) (interior limit points) and
 * section 4 (boundary rules; "six different configurations" of boundary limit points,
 * Fig. 1 (e)-(j), whose pictures the text does not carry: derived in doc/loop_limit.md).
 * Rules and vertex classes are those of loop.c (Hoppe et al. 1994 by sharp-edge count).
 *
 * Positions: each vertex class's limit mask (interior: the paper's (3); boundary and crease
 * vertices: the six configurations of section 4 as l S0, the stationary left eigenvector
 * times the first level's matrix; B-spline rule (1/6, 2/3, 1/6); darts in closed form in Q62
 * integers; corners stay), applied as v + sum w_i (p_i - v), rounded once (Q16.16: Q28
 * weights, exact 64-bit sums, <= 0.5 LSB). Normals (loop_limit_normal.c): the cross product
 * of the two dominant non-unit left eigenvectors' tangents (interior cos/sin masks; boundary
 * and crease along/across masks, equal to Hoppe et al.'s for the paper's rule; darts,
 * corners), scaled before the cross product, unit length by subd_sqrt. The derivations of
 * every mask, and where they differ from Hoppe's/pbrt's, are in doc/loop_limit.md.
 *
 * Memory and work: subd_loop_limit_apply uses no arena memory; subd_loop_limit allocates
 * exactly its outputs (3 * num_verts subd_reals each). Work O(sum of valences) for
 * positions; a dart with the B-spline rule costs O(n^3) (power iteration, n <= 48, above
 * which the interior cos mask is used). The interior tangent weights of valences 4..8 are
 * tabulated once per call in subd_loop_limit's frame (lim_trig), so the integer trig runs
 * O(1) times per call for them instead of twice per neighbour. No recursion; the largest
 * frame (subd_loop_limit with the normal code inlined) is below 1 KB on Cortex-M.
 */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "entry.h"
#include "layout.h"
#include "loop_internal.h"
#include "loop_rules.h"
#include "mesh_internal.h"
#include "vec3w.h"
#include "wide.h"
#include "loop_limit_internal.h"

/* Vertex classes: loop_rules.h (the one classification of loop.c, this file and pia.c);
 * lim_vert and lim_regular: loop_limit_internal.h. */
#define lim_classify subd_loop_classify

/* ------------------------------------------------------------------------------------ */
/* Interior weights in 64-bit integer arithmetic.                                         */

/* round(a * b / 2^62) for a, b < 2^63 (wide.h's 128-bit product), rounded half up. */
static uint64_t lim_mul_q62(uint64_t a, uint64_t b)
{
    return subd_u128_shr_round(subd_u128_mul(a, b), 62u);
}

/* round(num * 2^62 / den), half up, for num < 2 den and 0 < den < 2^63 (wide.h's division). */
static uint64_t lim_div_q62(uint64_t num, uint64_t den)
{
    uint64_t rem, q;
    subd_u128 n;
    n.hi = num >> 2;
    n.lo = num << 62;
    q = subd_u128_div(n, den, &rem);
    return q + (rem >= den - rem ? 1u : 0u);
}

/* Position weights and the affine combinations v + sum w_i (p_i - v) they weight.
 * Float32: the difference form keeps a constant mesh exactly constant and the error relative
 * to the local spread; weights are subd_reals, so lim_madd_w is vec3w.h's subd_wide_madd.
 * Q16.16 (why the #if: the algorithm's own precision, not a scalar twin): the weights are
 * Q28 in an int64 (16 bits finer than subd_real, so the weight rounding costs at most
 * |p_i - v| * 2^-29 instead of 2^-17 - several LSB at high valence - while w * (p_i - v) <
 * 2^28 * 2^32 and any sum of them with sum |w_i| <= 1 stay below 2^61); the differences
 * and products are exact in 64 bits and lim_finish rounds once at 2^-28, which equals
 * rounding (1 - sum w_i) v + sum w_i p_i exactly. The type lim_w: loop_limit_internal.h. */
#if SUBD_FIXED
#define LIM_W_FRAC(num, den) ((lim_w)((((int64_t)(num) << 29) + (den)) / (2 * (int64_t)(den)))) /* num >= 0 */
static lim_w lim_w_from_q62(uint64_t q) { return (lim_w)((q + ((uint64_t)1 << 33)) >> 34); }
static subd_wide lim_madd_w(subd_wide acc, lim_w w, subd_wide d) { return acc + w * d; }
/* v + acc / 2^28, rounded to nearest (ties up, as subd_round16) */
static subd_real lim_finish(subd_real v, subd_wide acc, uint32_t *ovf)
{
    return subd_real_sat((int64_t)v + ((acc + ((int64_t)1 << 27)) >> 28), ovf);
}
#else
#define LIM_W_FRAC(num, den) SUBD_REAL_FRAC(num, den)
static lim_w lim_w_from_q62(uint64_t q) { return subd_real_from_q62((int64_t)q); }
#define lim_madd_w subd_wide_madd
static subd_real lim_finish(subd_real v, subd_wide acc, uint32_t *ovf) { return subd_chk(v + acc, ovf); }
#endif

/* chi(n) = 1 / (n + 3 / (8 beta)) with Loop's beta = (5/8 - (3/8 + 1/4 cos(2 pi/n))^2) / n.
 * With B = n beta:  chi = 8B / (n (8B + 3)),  centre 1 - n chi = 3 / (8B + 3),
 * the paper's beta_n of formula (3). Computed in Q62 and rounded once. */
static lim_w lim_chi(uint32_t n)
{
    uint64_t bq = subd_loop_nbeta_q62(n) >> 3;           /* B/8 in Q62 = B in Q59 */
    uint64_t r = lim_div_q62(bq, bq + ((uint64_t)3 << 56)); /* 8B / (8B + 3) < 1 */
    return lim_w_from_q62((r + n / 2u) / n);
}

/* LIM_CACHE (valences 2..17 cached per call, on the stack): loop_limit_internal.h */

static lim_w lim_chi_cached(lim_w *cache, uint32_t n)
{
    if (n >= 2u && n < 2u + LIM_CACHE) {
        if (cache[n - 2u] == (lim_w)0) cache[n - 2u] = lim_chi(n);
        return cache[n - 2u];
    }
    return lim_chi(n);
}

/* ------------------------------------------------------------------------------------ */
/* Dart weights (one sharp edge, to ring neighbour k).                                    */

#define LIM_ONE_Q62 ((uint64_t)1 << 62)
#define LIM_ONE_Q60 ((uint64_t)1 << 60)
#define LIM_R_Q62 UINT64_C(0x0d5b8a37570bd666) /* r = (5 - sqrt(21))/2, rounded (Python decimal) */

static uint64_t lim_pow_q62(uint64_t x, uint32_t e)
{
    uint64_t r = LIM_ONE_Q62;
    while (e != 0u && x != 0u) {
        if (e & 1u) r = lim_mul_q62(r, x);
        x = lim_mul_q62(x, x);
        e >>= 1;
    }
    return e != 0u ? 0u : r;
}

typedef struct lim_dart {
    uint32_t n;
    uint64_t c83;   /* 8 beta / 3, Q60                        */
    uint64_t t;     /* normaliser T, Q60                      */
    uint64_t rn;    /* r^n, Q62                               */
    uint64_t wk;    /* weight of the sharp neighbour, Q62     */
} lim_dart;

/* b_m = (8 beta/3) (1 - (r^m + r^(n-m)) / (1 + r^n)), Q60. */
static uint64_t lim_dart_b(const lim_dart *s, uint32_t m)
{
    uint64_t q = lim_div_q62(lim_pow_q62(LIM_R_Q62, m) + lim_pow_q62(LIM_R_Q62, s->n - m), LIM_ONE_Q62 + s->rn);
    return lim_mul_q62(s->c83, LIM_ONE_Q62 - q);
}

/* w8 = 8 w: the stationary weight of the dart on its sharp edge's new vertex (4: midpoint,
 * 3: the paper's 3/8 for an extraordinary end). first = 1 when the paper's rule takes the
 * midpoint on the first level (the sharp neighbour is not regular). */
static void lim_dart_setup(lim_dart *s, uint32_t n, uint32_t w8, int first_mid)
{
    uint64_t b60 = subd_loop_nbeta_q62(n) >> 2, beta = (b60 + n / 2u) / n, sq, sumb, bk;
    s->n = n;
    s->c83 = (8u * b60 + (3u * n) / 2u) / (3u * n);
    s->rn = lim_pow_q62(LIM_R_Q62, n);
    /* sum_{m=1}^{n-1} (r^m + r^(n-m)) / (1 + r^n) = 2 (r - r^n) / ((1 - r)(1 + r^n)) */
    sq = lim_div_q62(2u * (LIM_R_Q62 - s->rn), lim_mul_q62(LIM_ONE_Q62 - LIM_R_Q62, LIM_ONE_Q62 + s->rn));
    sumb = (uint64_t)(n - 1u) * s->c83 - lim_mul_q62(s->c83, sq);
    bk = (beta + lim_dart_b(s, 1u) / 4u) * 8u / w8;
    s->t = LIM_ONE_Q60 + bk + sumb;
    s->wk = lim_div_q62(bk, s->t);
    if (first_mid) s->wk -= s->wk / 8u; /* level 0 uses v/2 + p_k/2 instead of 3/8, 5/8 */
}

/* Weight of ring neighbour at distance m (1..n-1) from the sharp one, Q62 -> subd_real. */
static lim_w lim_dart_weight(const lim_dart *s, uint32_t m)
{
    if (m == 0u) return lim_w_from_q62(s->wk);
    return lim_w_from_q62(lim_div_q62(lim_dart_b(s, m), s->t));
}

/* ------------------------------------------------------------------------------------ */
/* Boundary-curve limit weights (see the derivation at the top).                          */

void subd_loop_limit_curve_frac(subd_loop_boundary b, int rv, int ru, int32_t *num, int32_t *den)
{
    /* [v regular][u regular]: (R; . E) 7/48, (R; . R) 1/6, (E; . E) 7/40, (E; . R) 1/5 */
    static const int32_t tab[2][2][2] = {{{7, 40}, {1, 5}}, {{7, 48}, {1, 6}}};
    if (b == SUBD_LOOP_BOUNDARY_BSPLINE) {
        *num = 1;
        *den = 6;
        return;
    }
    *num = tab[rv != 0][ru != 0][0];
    *den = tab[rv != 0][ru != 0][1];
}

static void lim_curve_weights(const subd_mesh *m, subd_loop_boundary b, const lim_vert *c,
                              lim_w *w0, lim_w *w1)
{
    int32_t n0, d0, n1, d1;
    int rv = 0, r0 = 0, r1 = 0;
    if (b != SUBD_LOOP_BOUNDARY_BSPLINE) { /* the B-spline rule needs no classes */
        rv = (int)c->regular;
        r0 = lim_regular(m, c->c0);
        r1 = lim_regular(m, c->c1);
    }
    subd_loop_limit_curve_frac(b, rv, r0, &n0, &d0);
    subd_loop_limit_curve_frac(b, rv, r1, &n1, &d1);
    *w0 = LIM_W_FRAC(n0, d0);
    *w1 = LIM_W_FRAC(n1, d1);
}

static void lim_position(const subd_mesh *m, subd_loop_boundary b, const subd_real *ctrl, uint32_t v,
                         const lim_vert *c, lim_w *cache, subd_real *out, uint32_t *ovf)
{
    const subd_real *pv = &ctrl[3u * v];
    uint32_t k;
    if (c->cls == LOOP_SMOOTH) {
        uint32_t n = 0;
        subd_wide s[3];
        lim_w w = lim_chi_cached(cache, c->valence);
        topo_ring r; /* smooth: interior, no tail */
        for (k = 0; k < 3u; k++) s[k] = (subd_wide)0;
        topo_ring_begin(&r, m, v);
        for (; n < c->valence && topo_ring_step(&r); n++) {
            const subd_real *p = &ctrl[3u * r.nb];
            for (k = 0; k < 3u; k++) s[k] += subd_wide_diff(p[k], pv[k]);
        }
        /* Q16.16: n chi <= 1, so w s < 2^61; float32: the product rounded once */
        for (k = 0; k < 3u; k++) out[k] = lim_finish(pv[k], w * s[k], ovf);
    } else if (c->cls == LOOP_DART) {
        uint32_t i = 0, n = c->valence;
        subd_wide acc[3];
        lim_dart ds;
        topo_ring r; /* a dart is interior: no tail */
        int paper = b == SUBD_LOOP_BOUNDARY_PAPER;
        lim_dart_setup(&ds, n, paper ? 3u : 4u, paper && !lim_regular(m, c->c0));
        for (k = 0; k < 3u; k++) acc[k] = (subd_wide)0;
        topo_ring_begin(&r, m, v);
        for (; i < n && topo_ring_step(&r); i++) {
            const subd_real *p = &ctrl[3u * r.nb];
            lim_w w = lim_dart_weight(&ds, (i + n - c->i0) % n);
            for (k = 0; k < 3u; k++) acc[k] = lim_madd_w(acc[k], w, subd_wide_diff(p[k], pv[k]));
        }
        for (k = 0; k < 3u; k++) out[k] = lim_finish(pv[k], acc[k], ovf);
    } else if (c->cls == LOOP_CREASE) {
        const subd_real *p0 = &ctrl[3u * c->c0], *p1 = &ctrl[3u * c->c1];
        lim_w w0, w1;
        lim_curve_weights(m, b, c, &w0, &w1);
        for (k = 0; k < 3u; k++) {
            subd_wide acc = lim_madd_w((subd_wide)0, w0, subd_wide_diff(p0[k], pv[k]));
            acc = lim_madd_w(acc, w1, subd_wide_diff(p1[k], pv[k]));
            out[k] = lim_finish(pv[k], acc, ovf);
        }
    } else {
        for (k = 0; k < 3u; k++) out[k] = pv[k];
    }
}

void subd_loop_limit_apply(const subd_mesh *m, subd_loop_boundary b, const subd_real *ctrl,
                           subd_real *lim, uint32_t *ovf)
{
    lim_w cache[LIM_CACHE];
    uint32_t v, k;
    lim_vert c;
    for (k = 0; k < LIM_CACHE; k++) cache[k] = (lim_w)0;
    for (v = 0; v < m->num_verts; v++) {
        lim_classify(m, v, &c);
        lim_position(m, b, ctrl, v, &c, cache, &lim[3u * v], ovf);
    }
}

/* ------------------------------------------------------------------------------------ */
/* Public calls                                                                           */

static int lim_check(const subd_mesh *in, subd_loop_boundary b, subd_diag *d)
{
    int st;
    if (!in || (b != SUBD_LOOP_BOUNDARY_PAPER && b != SUBD_LOOP_BOUNDARY_BSPLINE)) return SUBD_ERR_PARAM;
    if (!subd_topo_has(in, TOPO_POS | TOPO_VERT_OUT | TOPO_VERT_TAG) ||
        !subd_topo_has(in, TOPO_IF_FACES | TOPO_FACE_START | TOPO_CORNER_VERT | TOPO_CORNER_FACE | TOPO_TWIN |
                               TOPO_EDGE_TAG))
        return SUBD_ERR_PARAM;
    if ((st = subd_loop_tags_public(in, d)) != SUBD_OK) return st;
    return subd_require_triangles(in, d);
}

void subd_loop_limit_vertex(const subd_mesh *m, subd_loop_boundary b, const subd_real *ctrl, uint32_t v,
                            subd_real *pos, subd_real *normal, uint32_t *ovf)
{
    lim_w cache[LIM_CACHE];
    lim_trig tab;
    lim_vert c;
    uint32_t k;
    for (k = 0; k < LIM_CACHE; k++) cache[k] = (lim_w)0;
    tab.filled = 0;
    lim_classify(m, v, &c);
    lim_position(m, b, ctrl, v, &c, cache, pos, ovf);
    if (normal) lim_normal(m, b, ctrl, v, &c, &tab, normal);
}

void subd_loop_limit_vertex_cached(const subd_mesh *m, subd_loop_boundary b, const subd_real *ctrl, uint32_t v,
                                   lim_cache *lc, subd_real *pos, subd_real *normal, uint32_t *ovf)
{
    lim_vert c;
    lim_classify(m, v, &c);
    lim_position(m, b, ctrl, v, &c, lc->chi, pos, ovf);
    if (normal) lim_normal(m, b, ctrl, v, &c, &lc->tab, normal);
}

void subd_loop_limit_cache_init(lim_cache *lc)
{
    uint32_t k;
    for (k = 0; k < LIM_CACHE; k++) lc->chi[k] = (lim_w)0;
    lc->tab.filled = 0;
}

/* The valence-6 masks as subd_loop_limit's tables give them: cos 2 pi j/6 = 1, 1/2, -1/2, -1,
 * -1/2, 1/2 and sin = 0, r, r, 0, -r, -r (r = sin 60 degrees rounded) in both arithmetics
 * (trig.c's exact range reduction; float32 0.5 and 1 are exact, Q16.16 32768 and 65536).
 * fast records that they are, which is what lim_reg6_fast assumes; the general loop below it
 * stays for any other table (and the tests run both). */
void subd_loop_limit_reg6_init(lim_reg6 *k)
{
    static const int8_t c2[6] = {2, 1, -1, -2, -1, 1}, sg[6] = {0, 1, 1, 0, -1, -1}; /* 2 cos, sign of sin */
    subd_real one = SUBD_REAL_ONE, half = SUBD_REAL_FRAC(1, 2), r;
    uint32_t j;
    k->chi = lim_chi(6u);
    subd_loop_limit_reg6_trig(k);
    r = k->s[1];
    k->fast = r > (subd_real)0;
    for (j = 0; j < 6u; j++) {
        subd_real c = c2[j] == 2 ? one : c2[j] == 1 ? half : c2[j] == -1 ? -half : -one;
        subd_real sj = sg[j] > 0 ? r : sg[j] < 0 ? -r : (subd_real)0;
        if (subd_real_bits(k->c[j]) != subd_real_bits(c) || subd_real_bits(k->s[j]) != subd_real_bits(sj)) k->fast = 0;
    }
}

/* One coordinate of the three valence-6 sums of lim_reg6_fast: *s = sum d_j, *t1 = sum
 * cos_j d_j, *t2 = sum sin_j d_j over the ring's differences d_j = p_j - v, j = 0..5 from the
 * ring start, as lim_position's smooth branch and lim_smooth_tangents (i0 = 0) make them.
 *
 * Q16.16: those sums are exact int64 sums of exact products (no rounding, no overflow:
 * |d_j| < 2^32, weights <= 2^16), so any grouping gives their bits: t1 = 2^15 (2 (d0 - d3) +
 * (d1 - d2) - (d4 - d5)), t2 = r ((d1 + d2) - (d4 + d5)), one multiplication per sum.
 *
 * float32: the same roundings in the same order. The reference adds w_j * d_j to an
 * accumulator that starts at +0, left to right. (1) w d for w = 1 is d, for w = -1 and
 * -1/2 it is -(|w| d) (rounding is symmetric), and a + (-x) is a - x (IEEE 754 defines the
 * subtraction so), so the products by 1 and -1 are dropped and the negative weights
 * subtract. (2) A sum that starts at +0 is never -0 (round to nearest: x + y = -0 only when
 * x = y = -0), so adding a zero product (sin 0 d0, sin 180 d3, both +-0 for finite d: a
 * tile's points are finite) leaves it unchanged: those terms are dropped. (3) Starting
 * instead from the first term and adding +0 at the end gives the same bits: if the
 * shortened sum is never -0 the two run equal; once it is -0 (every term so far -0) the
 * reference holds +0, and -0 + x = x = +0 + x for every x but x = -0, where the reference
 * stays +0; the final + 0.0f maps that -0 to +0 and changes nothing else. (4) The position
 * sum s skips that + 0.0f: it is -0 only when every d_j is -0, i.e. every p_j is -0 and v
 * is +0 (p - v = -0 only so), and then v + chi s is +0 for either sign of s. */
#if SUBD_FIXED
static inline void lim_reg6_axis(subd_real r, subd_real v, subd_real p0, subd_real p1, subd_real p2, subd_real p3,
                                 subd_real p4, subd_real p5, subd_wide *s, subd_wide *t1, subd_wide *t2)
{
    subd_wide d0 = subd_wide_diff(p0, v), d1 = subd_wide_diff(p1, v), d2 = subd_wide_diff(p2, v);
    subd_wide d3 = subd_wide_diff(p3, v), d4 = subd_wide_diff(p4, v), d5 = subd_wide_diff(p5, v);
    *s = d0 + d1 + d2 + d3 + d4 + d5;
    *t1 = (2 * (d0 - d3) + (d1 - d2) - (d4 - d5)) * 32768;
    *t2 = ((d1 + d2) - (d4 + d5)) * (subd_wide)r;
}
#else
static inline void lim_reg6_axis(subd_real r, subd_real v, subd_real p0, subd_real p1, subd_real p2, subd_real p3,
                                 subd_real p4, subd_real p5, subd_wide *s, subd_wide *t1, subd_wide *t2)
{
    subd_wide d0 = subd_wide_diff(p0, v), d1 = subd_wide_diff(p1, v), d2 = subd_wide_diff(p2, v);
    subd_wide d3 = subd_wide_diff(p3, v), d4 = subd_wide_diff(p4, v), d5 = subd_wide_diff(p5, v);
    subd_wide h1 = 0.5f * d1, h2 = 0.5f * d2, h4 = 0.5f * d4, h5 = 0.5f * d5;
    subd_wide r1 = r * d1, r2 = r * d2, r4 = r * d4, r5 = r * d5, a, b, x;
    x = d0 + d1;
    x = x + d2;
    x = x + d3;
    x = x + d4;
    *s = x + d5;
    a = d0 + h1; /* 1 d0 + 1/2 d1 */
    a = a - h2;  /* + (-1/2) d2 */
    a = a - d3;  /* + (-1) d3 */
    a = a - h4;  /* + (-1/2) d4 */
    a = a + h5;  /* + 1/2 d5 */
    *t1 = a + 0.0f;
    b = r1 + r2; /* 0 d0 + r d1 + r d2 */
    b = b - r4;  /* + 0 d3 + (-r) d4 */
    b = b - r5;  /* + (-r) d5 */
    *t2 = b + 0.0f;
}
#endif

/* lim_position's smooth branch and lim_smooth_tangents (i0 = 0) for valence 6 with the ring
 * given: the same sums (lim_reg6_axis), the three coordinates written out so that the sums
 * stay in registers, then lim_finish's rounding and check and the unit normal. */
static void lim_reg6_fast(const lim_reg6 *k, const subd_real *pv, const int32_t *ring, subd_real *pos, subd_real *nrm,
                          uint32_t *ovf)
{
    const subd_real *p0 = pv + ring[0], *p1 = pv + ring[1], *p2 = pv + ring[2];
    const subd_real *p3 = pv + ring[3], *p4 = pv + ring[4], *p5 = pv + ring[5];
    subd_real r = k->s[1], v0 = pv[0], v1 = pv[1], v2 = pv[2];
    lim_w chi = k->chi;
    subd_wide s0, s1, s2, t1[3], t2[3];
    lim_reg6_axis(r, v0, p0[0], p1[0], p2[0], p3[0], p4[0], p5[0], &s0, &t1[0], &t2[0]);
    lim_reg6_axis(r, v1, p0[1], p1[1], p2[1], p3[1], p4[1], p5[1], &s1, &t1[1], &t2[1]);
    lim_reg6_axis(r, v2, p0[2], p1[2], p2[2], p3[2], p4[2], p5[2], &s2, &t1[2], &t2[2]);
    /* Q16.16: n chi <= 1, so w s < 2^61; float32: the product rounded once */
    pos[0] = lim_finish(v0, chi * s0, ovf);
    pos[1] = lim_finish(v1, chi * s1, ovf);
    pos[2] = lim_finish(v2, chi * s2, ovf);
    subd_loop_limit_unit_cross(t1, t2, nrm);
}

/* The general form: lim_position's smooth branch and lim_smooth_tangents (i0 = 0) for
 * valence 6 with the ring given, the same sums in the same order in one pass over the ring
 * (each difference p - v computed once for the three sums it enters). */
void subd_loop_limit_reg6(const lim_reg6 *k, const subd_real *pv, const int32_t *ring, subd_real *pos, subd_real *nrm,
                          uint32_t *ovf)
{
    subd_wide s0 = (subd_wide)0, s1 = (subd_wide)0, s2 = (subd_wide)0, t1[3], t2[3];
    subd_wide a0 = (subd_wide)0, a1 = (subd_wide)0, a2 = (subd_wide)0;
    subd_wide b0 = (subd_wide)0, b1 = (subd_wide)0, b2 = (subd_wide)0;
    uint32_t i;
    if (k->fast) {
        lim_reg6_fast(k, pv, ring, pos, nrm, ovf);
        return;
    }
    for (i = 0; i < 6u; i++) {
        const subd_real *p = pv + ring[i];
        subd_real wc = k->c[i], ws = k->s[i];
        subd_wide d0 = subd_wide_diff(p[0], pv[0]), d1 = subd_wide_diff(p[1], pv[1]);
        subd_wide d2 = subd_wide_diff(p[2], pv[2]);
        s0 += d0;
        s1 += d1;
        s2 += d2;
        a0 = subd_wide_madd(a0, wc, d0);
        a1 = subd_wide_madd(a1, wc, d1);
        a2 = subd_wide_madd(a2, wc, d2);
        b0 = subd_wide_madd(b0, ws, d0);
        b1 = subd_wide_madd(b1, ws, d1);
        b2 = subd_wide_madd(b2, ws, d2);
    }
    pos[0] = lim_finish(pv[0], k->chi * s0, ovf);
    pos[1] = lim_finish(pv[1], k->chi * s1, ovf);
    pos[2] = lim_finish(pv[2], k->chi * s2, ovf);
    t1[0] = a0;
    t1[1] = a1;
    t1[2] = a2;
    t2[0] = b0;
    t2[1] = b1;
    t2[2] = b2;
    subd_loop_limit_unit_cross(t1, t2, nrm);
}

/* The one layout (layout.h's walk: counts with a == NULL, carves otherwise): positions,
 * then normals when asked for; no working memory. */
static int lim_layout(subd_arena *a, const subd_mesh *in, int normals, subd_real **pos, subd_real **nrm,
                      uint32_t *bytes)
{
    subd_layout l;
    subd_layout_begin(&l, a);
    *pos = subd_layout_take(&l, in->num_verts, 3u * (uint32_t)sizeof(subd_real));
    *nrm = normals ? subd_layout_take(&l, in->num_verts, 3u * (uint32_t)sizeof(subd_real)) : 0;
    return subd_layout_end(&l, bytes);
}

void subd_loop_limit_opts_default(subd_loop_limit_opts *o)
{
    if (!o) return;
    o->boundary = SUBD_LOOP_BOUNDARY_PAPER;
    o->flags = SUBD_LOOP_LIMIT_NORMALS;
}

int subd_loop_limit_plan(const subd_mesh *in, const subd_loop_limit_opts *o, uint32_t *bytes, subd_diag *diag)
{
    subd_diag own, *d = subd_plan_begin(&own, diag);
    subd_real *p, *nrm;
    int st;
    if (!bytes || !o || (o->flags & ~SUBD_LOOP_LIMIT_NORMALS) != 0u) return subd_plan_end(d, SUBD_ERR_PARAM);
    if ((st = lim_check(in, o->boundary, d)) != SUBD_OK) return subd_plan_end(d, st);
    return subd_plan_end(d, lim_layout(0, in, (o->flags & SUBD_LOOP_LIMIT_NORMALS) != 0u, &p, &nrm, bytes));
}

int subd_loop_limit(subd_arena *a, const subd_mesh *in, const subd_loop_limit_opts *o, subd_real **pos,
                    subd_real **normals_out, subd_diag *diag)
{
    subd_entry e;
    subd_diag *d = subd_entry_begin(&e, a, diag);
    subd_real *p, *nrm;
    lim_w cache[LIM_CACHE];
    lim_trig tab;
    uint32_t bytes, v, k, ovf = 0;
    lim_vert c;
    int st;

    subd_real **normals;
    subd_loop_boundary b;
    if (!a || !pos || !o || (o->flags & ~SUBD_LOOP_LIMIT_NORMALS) != 0u) return subd_entry_fail(&e, SUBD_ERR_PARAM);
    b = o->boundary;
    normals = (o->flags & SUBD_LOOP_LIMIT_NORMALS) ? normals_out : 0;
    if ((o->flags & SUBD_LOOP_LIMIT_NORMALS) && !normals_out) return subd_entry_fail(&e, SUBD_ERR_PARAM);
    if ((st = lim_check(in, b, d)) != SUBD_OK) return subd_entry_fail(&e, st);
    if ((st = lim_layout(0, in, normals != 0, &p, &nrm, &bytes)) != SUBD_OK) return subd_entry_fail(&e, st);
    if (bytes > subd_arena_free_bytes(a)) { /* checked first: a failed call leaves the peak */
        d->bytes_needed = bytes;
        return subd_entry_fail(&e, SUBD_ERR_NOMEM);
    }
    (void)lim_layout(a, in, normals != 0, &p, &nrm, 0); /* cannot fail: it fits */
    for (k = 0; k < LIM_CACHE; k++) cache[k] = (lim_w)0;
    tab.filled = 0;
    for (v = 0; v < in->num_verts; v++) {
        lim_classify(in, v, &c);
        lim_position(in, b, in->pos, v, &c, cache, &p[3u * v], &ovf);
        if (nrm) lim_normal(in, b, in->pos, v, &c, &tab, &nrm[3u * v]);
    }
    if (ovf) {
        d->vertex = SUBD_NONE;
        return subd_entry_fail(&e, SUBD_ERR_RANGE);
    }
    *pos = p;
    if (normals) *normals = nrm;
    return subd_entry_ok(&e);
}
