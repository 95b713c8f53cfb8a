/* SPDX-License-Identifier: MIT */
/* Loop limit positions and normals.
 * Length (~830 lines): positions and normals share the classification, the masks and
 * their caches; the split into two files is open work (issue 19, item 7).
 *
 * Paper: loop-progressive-interpolation.txt, formula (3) (interior limit points) and
 * section 4 (boundary rules; "six different configurations" of boundary limit points,
 * Fig. 1 (e)-(j), whose pictures the text does not carry: they are derived below).
 * Rules and vertex classes are those of loop.c (Hoppe et al. 1994 by sharp-edge count).
 *
 * POSITIONS. A limit mask is the left eigenvector, eigenvalue 1, of the subdivision matrix of
 * the smallest vertex neighbourhood that maps to itself. If the first level's matrix S0
 * differs from the stationary one S (rules that depend on "regular" can change after one
 * level, because new vertices are always regular), the mask is l S0 with l from S.
 *
 *  - Interior (smooth), valence n: the paper's (3), v_inf = (1 - n chi) v + chi sum p_i,
 *    chi = 1 / (n + 3/(8 beta)), Loop's beta = (5/8 - (3/8 + 1/4 cos(2 pi/n))^2) / n; with
 *    B = n beta: chi = 8B / (n (8B + 3)) and the centre weight 3 / (8B + 3) is the paper's
 *    beta_n. Regular n = 6: 1/2 and 1/12. chi comes from subd_cos_turns_q62 in 64-bit
 *    integers and is rounded once.
 *
 *  - Boundary and crease vertices, paper's rule. The curve rules involve only the curve:
 *    vertex 1/8 c0 + 3/4 v + 1/8 c1; edge midpoint when both ends are regular or both
 *    extraordinary, else 5/8 regular + 3/8 extraordinary. The triple (c0, v, c1) maps to
 *    (e0, v', e1); the new e0, e1 are regular, v keeps its class, so from level 1 on the
 *    configuration is (R, X, R) with X the class of v:
 *      X regular:        e_i = 1/2 v + 1/2 c_i   S = [1/2 1/2 0; 1/8 3/4 1/8; 0 1/2 1/2]
 *                        left eigenvector (1/6, 2/3, 1/6)            (Fig. 1(e))
 *      X extraordinary:  e_i = 3/8 v + 5/8 c_i   S = [5/8 3/8 0; 1/8 3/4 1/8; 0 3/8 5/8]
 *                        (a, b, a) S = (a, b, a): 5a/8 + b/8 = a, so b = 3a: (1/5, 3/5, 1/5)
 *                                                                     (Fig. 1(f))
 *    The first level's edge rule depends on the neighbours' classes; l S0 gives, with
 *    R = regular, E = extraordinary, (weight c0, v, c1):
 *      (R; R R)  1/6   2/3    1/6          (E; R R)  1/5   3/5    1/5
 *      (R; R E)  1/6   11/16  7/48         (E; R E)  1/5   5/8    7/40
 *      (R; E E)  7/48  17/24  7/48         (E; E E)  7/40  13/20  7/40
 *    e.g. (R; R E): 1/6 (c0 + v)/2 + 2/3 (c0 + 6v + c1)/8 + 1/6 (5/8 v + 3/8 c1). A
 *    neighbour of the same class as v weighs 1/6 (v regular) or 7/40 (v extraordinary), one
 *    of the other class 7/48 or 1/5. The paper states that (e) and (f) need regular
 *    neighbours and that the others come from combining the rules with them: this is that
 *    combination. The test checks all six against 60 levels of subdivision. "Regular" (as
 *    in loop.c): valence 4 on a boundary (the paper); inside, a crease vertex of valence 6
 *    with its sharp edges opposite (three faces per side), which is what refinement
 *    creates. Corners, darts and all other crease vertices are extraordinary.
 *  - B-spline rule (midpoints everywhere): (1/6, 2/3, 1/6).
 *  - Dart (one sharp edge, to ring neighbour k; smooth vertex rule): not the interior
 *    mask, because the sharp edge's new vertex is (w v + (1-w) p_k) instead of Loop's edge
 *    rule (w = 1/2 midpoint; 3/8 for the paper's rule from level 1 on, the dart being
 *    extraordinary and the new crease vertex regular). With weight 1 on v, the eigenvector
 *    has b_m (m = 1..n-1 steps from k) from  b_(m-1) + b_(m+1) - 5 b_m = -8 beta  with the
 *    p_k terms absent at both ends:
 *      b_m = (8 beta/3) (1 - (r^m + r^(n-m)) / (1 + r^n)),  r = (5 - sqrt 21)/2,
 *      b_k = (beta + b_1/4) / w,  then divided by T = 1 + b_k + sum b_m
 *    (sum of the r-terms in closed form: 2 (r - r^n) / ((1 - r)(1 + r^n))). With the paper's
 *    rule and an extraordinary p_k the first level uses the midpoint: l S0 moves b_k/8 from
 *    p_k to v. Q62 integer arithmetic, rounded once per weight.
 *  - Corners (tagged, or three or more sharp edges) and isolated vertices stay.
 *
 * Every combination is v + sum w_i (p_i - v): in Q16.16 the weights are Q28 (lim_w), the
 * differences and products exact in 64 bits and the sum rounded once, which is exactly
 * round((1 - sum w_i) v + sum w_i p_i) (the weights sum to one by construction, a constant
 * mesh and any translation are reproduced exactly; measured error <= 0.5 LSB); in
 * float32 the difference form keeps constants exact and the error relative to the local
 * spread. Positions are convex combinations, so Q16.16 cannot overflow (SUBD_ERR_RANGE only
 * in float32, when differences of coordinates near FLT_MAX overflow).
 *
 * NORMALS. The tangent plane is spanned by the two dominant non-unit left eigenvectors of the
 * one-ring's matrix (the limit of the one-ring's fan); normal = unit(t_a x t_b), oriented
 * outwards for counter-clockwise faces (the ring walk is counter-clockwise seen from the
 * front: face (v, p_i, p_i+1)). Checked against the fan normal after 60-240 levels.
 *  - Interior: t1 = sum cos(2 pi i/n) p_i, t2 = sum sin(2 pi i/n) p_i, normal t1 x t2.
 *  - Boundary or crease side with k neighbours p_0..p_(k-1) (p_0, p_(k-1) on sharp edges),
 *    w_v the stationary weight of v on its sharp edges' new vertices (1/2; the paper's rule
 *    with v extraordinary: 3/8), w_0, w_(k-1) the level-0 weights:
 *      along  = (1 - w_(k-1)) (p_(k-1) - v) - (1 - w_0) (p_0 - v)   (l = p_(k-1) - p_0, l S0)
 *      across, k = 2: (3/4 - w_0)(p_0 - v) + (3/4 - w_1)(p_1 - v)   (curve mode (1,-2,1))
 *      across, k >= 3, theta = pi/(k-1), eigenvalue lambda = 3/8 + 1/4 cos theta:
 *        b_i = sin(i theta) inside (the recurrence b_(i-1) + b_(i+1) = (8 lambda - 3) b_i with
 *        the ends absent), b_end from column p_0, b_end (lambda - 1 + w_v) = (a + b_1)/8, and
 *        translation invariance a + 2 b_end + sum b_i = 0:
 *          b_end = -cos theta (1 + cos theta) / (sin theta (2 cos theta - 3 + 8 w_v))
 *        (0 for k = 3, where p_1 - v is itself an eigenvector); level 0 adds
 *        -b_end (w_end - w_v)/lambda per end. normal = across x along.
 *    For the paper's rule with w_v = 3/8 this is exactly Hoppe et al.'s mask (as in pbrt):
 *    -(1 + cos)/(2 sin) : sin(i theta) = -sin theta : (2 - 2 cos theta) sin(i theta). For the
 *    B-spline rule (w_v = 1/2) it differs from Hoppe's at k >= 5, which has no weight on v
 *    (the test measures Hoppe's masks up to 10 degrees off there): pbrt pairs Hoppe's
 *    masks with midpoint boundary edges, the inconsistency REFERENCE.md warns of. With midpoints and k >= 8 the second interior mode
 *    (3/8 + 1/4 cos 2 theta > 1/2) outgrows the boundary direction: the surface is not
 *    tangent-plane continuous there and the fan converges to the plane of the two interior
 *    modes, whose normal is returned (mask sin(2 i theta), ends +-sin 2theta/(2 cos 2theta - 1)).
 *    At k = 7 the two share 1/2 in a Jordan block; the returned across x along is the fan's
 *    limit, reached only like 1/L. The paper's rule has no such case (along: 5/8).
 *    An interior crease vertex: the two sides' unit normals, summed and normalised.
 *  - Dart: the mirror-antisymmetric mode sum sin(2 pi m/n) p_m is unchanged; the
 *    symmetric one is, for the paper's rule, b_m = sin(m pi/n), b_k = -cot(pi/(2n)) with no
 *    weight on v (eigenvalue 3/8 + 1/4 cos(pi/n)), and for midpoints the result of a power
 *    iteration (see lim_dart_sym_power).
 *  - Corner: see lim_corner_normal (exact for sectors of up to two faces, and for the
 *    paper's rule, whose 5/8 curve rule dominates; otherwise approximate).
 *  - Vanishing tangents give (0, 0, 0). Tangents are scaled before the cross product
 *    (float: by the largest component; Q16.16: to 30 bits in int64), so nothing overflows.
 *    Unit length needs a square root: subd_sqrt / subd_isqrt64 (sqrt.c), no libm.
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

/* Vertex classes: loop_rules.h (the one classification of loop.c, this file and pia.c). */
typedef loop_vinfo lim_vert;
#define lim_classify subd_loop_classify

/* The class of neighbour v (regular or not, for the paper's curve rules): from its ring, or
 * given by LOOP_VTAG_KNOWN (loop_stream.c's patch views, where v's ring may be cut). */
static int lim_regular(const subd_mesh *m, uint32_t v)
{
    lim_vert c;
    if (m->vert_tag[v] & LOOP_VTAG_KNOWN) return (m->vert_tag[v] & LOOP_VTAG_REGULAR) != 0u;
    lim_classify(m, v, &c);
    return (int)c.regular;
}

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
 * rounding (1 - sum w_i) v + sum w_i p_i exactly. */
#if SUBD_FIXED
typedef int64_t lim_w;
#define LIM_W_FRAC(num, den) ((lim_w)((((int64_t)(num) << 29) + (den)) / (2 * (int64_t)(den)))) /* num >= 0 */
static lim_w lim_w_from_q62(uint64_t q) { return (lim_w)((q + ((uint64_t)1 << 33)) >> 34); }
static subd_wide lim_madd_w(subd_wide acc, lim_w w, subd_wide d) { return acc + w * d; }
/* v + acc / 2^28, rounded to nearest (ties up, as subd_round16) */
static subd_real lim_finish(subd_real v, subd_wide acc, uint32_t *ovf)
{
    return subd_real_sat((int64_t)v + ((acc + ((int64_t)1 << 27)) >> 28), ovf);
}
#else
typedef float lim_w;
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

#define LIM_CACHE 16u /* valences 2..17 cached per call, on the stack */

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
/* Limit normals                                                                          */

/* Unit vectors by vec3w.h: subd_w3_unit(c) is c / |c|, or (0, 0, 0) for c = 0.
 * lim_unit_cross: the unit vector along t1 x t2; lim_dot_sign: the sign of a . b. Both
 * first rescale their operands with subd_w3_normalize to 30 bits (float32: largest
 * component 1), so the cross and dot products cannot overflow (Q16.16: below 2^61 and
 * 3 * 2^60) or underflow; only the directions matter. */
static void lim_unit_cross(const subd_wide *t1, const subd_wide *t2, subd_real *out)
{
    subd_wide a[3], b[3], c[3];
    subd_w3_normalize(t1, a, 30u);
    subd_w3_normalize(t2, b, 30u);
    subd_w3_cross(a, b, c);
    subd_w3_unit(c, out);
}

static subd_wide lim_dot_sign(const subd_wide *a, const subd_wide *b)
{
    subd_wide x[3], y[3];
    subd_w3_normalize(a, x, 30u);
    subd_w3_normalize(b, y, 30u);
    return subd_w3_dot(x, y);
}

/* acc += u for a unit vector u (in subd_real). */
static void lim_add_unit(subd_wide *acc, const subd_real *u)
{
    uint32_t k;
    for (k = 0; k < 3u; k++) acc[k] += subd_wide_of(u[k]);
}

/* The next neighbour of topo.h's walk (the tail included); the callers take exactly the
 * valence of subd_loop_classify's walk, which is the same walk. */
static uint32_t lim_ring_step(topo_ring *r)
{
    (void)topo_ring_step(r);
    return r->nb;
}

/* Per-call table of the interior tangent weights subd_cos_turns(j, n), subd_sin_turns(j, n)
 * for the common valences LIM_TRIG_LO..LIM_TRIG_HI, j = 0..n/2, each valence filled on its
 * first use (the integer trig was most of the normals' time). The other half of the ring
 * follows bit for bit from the exact range reduction of trig.c: cos((n-j)/n) == cos(j/n),
 * sin((n-j)/n) == -sin(j/n) in Q62, and subd_real_from_q62 rounds the magnitude, so the
 * negation commutes with it (sin is 0 only at j = 0 and n/2, which are stored). Lives in
 * subd_loop_limit's frame: no global state, no arena memory. */
#define LIM_TRIG_LO 4u
#define LIM_TRIG_HI 8u
#define LIM_TRIG_SLOTS 19u /* sum of (n/2 + 1) for n = LIM_TRIG_LO..LIM_TRIG_HI */

typedef struct lim_trig {
    uint32_t filled; /* bit n: valence n present */
    subd_real c[LIM_TRIG_SLOTS], s[LIM_TRIG_SLOTS];
} lim_trig;

/* cos(2 pi j/n) and sin(2 pi j/n), 0 <= j < n, as subd_cos_turns / subd_sin_turns. */
static void lim_sincos(lim_trig *t, uint32_t j, uint32_t n, subd_real *wc, subd_real *ws)
{
    uint32_t off = 0, m, jj;
    if (!t || n < LIM_TRIG_LO || n > LIM_TRIG_HI) {
        *wc = subd_cos_turns((int32_t)j, (int32_t)n);
        *ws = subd_sin_turns((int32_t)j, (int32_t)n);
        return;
    }
    for (m = LIM_TRIG_LO; m < n; m++) off += m / 2u + 1u;
    if (!(t->filled & ((uint32_t)1 << n))) {
        for (jj = 0; jj <= n / 2u; jj++) {
            t->c[off + jj] = subd_cos_turns((int32_t)jj, (int32_t)n);
            t->s[off + jj] = subd_sin_turns((int32_t)jj, (int32_t)n);
        }
        t->filled |= (uint32_t)1 << n;
    }
    if (j <= n / 2u) {
        *wc = t->c[off + j];
        *ws = t->s[off + j];
    } else {
        *wc = t->c[off + n - j];
        *ws = (subd_real)0 - t->s[off + n - j];
    }
}

/* Interior tangents t1 = sum cos(2 pi i/n) (p_i - v), t2 = sum sin(2 pi i/n) (p_i - v),
 * with i counted from ring position i0. */
static void lim_smooth_tangents(const subd_mesh *m, const subd_real *ctrl, uint32_t v, uint32_t n,
                                uint32_t i0, lim_trig *tab, subd_wide *t1, subd_wide *t2)
{
    const subd_real *pv = &ctrl[3u * v];
    uint32_t i, k;
    topo_ring r;
    topo_ring_begin(&r, m, v);
    for (k = 0; k < 3u; k++) t1[k] = t2[k] = (subd_wide)0;
    for (i = 0; i < n; i++) {
        const subd_real *p = &ctrl[3u * lim_ring_step(&r)];
        uint32_t j = (i + n - i0) % n;
        subd_real wc, ws;
        lim_sincos(tab, j, n, &wc, &ws);
        for (k = 0; k < 3u; k++) {
            subd_wide d = subd_wide_diff(p[k], pv[k]);
            t1[k] = subd_wide_madd(t1[k], wc, d);
            t2[k] = subd_wide_madd(t2[k], ws, d);
        }
    }
}

/* The unit normal of one side of a boundary or crease vertex: ring positions s .. s+k-1
 * (mod n), whose first and last are the sharp neighbours. w8v: 8 times the stationary
 * weight of v on its sharp edges' new vertices; w8a, w8b: 8 times the level-0 weights at
 * the first and last sharp edge. See the derivation at the top of the file. */
static void lim_side_normal(const subd_mesh *m, const subd_real *ctrl, uint32_t v, uint32_t n, uint32_t s,
                            uint32_t k, int32_t w8v, int32_t w8a, int32_t w8b, subd_real *out)
{
    const subd_real *pv = &ctrl[3u * v];
    uint32_t i, c, ovf = 0;
    topo_ring r;
    subd_wide along[3], across[3];
    subd_real bend = 0, wa_a, wa_b, wc_a, wc_b, sn = 0;
    int32_t den = 2 * (int32_t)(k - 1u);
    int two = 0;
    for (c = 0; c < 3u; c++) along[c] = across[c] = (subd_wide)0;
    /* along: (1 - w_b) (p_last - v) - (1 - w_a) (p_first - v) */
    wa_a = SUBD_REAL_FRAC(w8a - 8, 8);
    wa_b = SUBD_REAL_FRAC(8 - w8b, 8);
    if (k == 2u) {
        /* across: (3/4 - w_a) (p_first - v) + (3/4 - w_b) (p_last - v) */
        wc_a = SUBD_REAL_FRAC(6 - w8a, 8);
        wc_b = SUBD_REAL_FRAC(6 - w8b, 8);
    } else {
        /* theta = pi/(k-1); b_end = -cos(1 + cos) / (sin (2 cos - 3 + 8 w_v)), 0 for k = 3;
         * then corrected for the level-0 rule at that end */
        subd_real cs = subd_cos_turns(1, den);
        sn = subd_sin_turns(1, den);
        if (k > 3u) {
            subd_real num = subd_neg(subd_mul(cs, subd_add(SUBD_REAL_ONE, cs, &ovf), &ovf), &ovf);
            subd_real dd = subd_add(subd_add(cs, cs, &ovf), SUBD_REAL_FRAC(w8v - 3, 1), &ovf);
            bend = subd_div(num, subd_mul(sn, dd, &ovf), &ovf);
        }
        /* level 0: t = lambda (mask . P) - b_end (w_end - w_v)(p_end - v), 8 lambda = 3 + 2 cos */
        {
            subd_real l8 = subd_add(SUBD_REAL_FRAC(3, 1), subd_add(cs, cs, &ovf), &ovf);
            wc_a = subd_sub(bend, subd_div(subd_mul(bend, SUBD_REAL_FRAC(w8a - w8v, 1), &ovf), l8, &ovf), &ovf);
            wc_b = subd_sub(bend, subd_div(subd_mul(bend, SUBD_REAL_FRAC(w8b - w8v, 1), &ovf), l8, &ovf), &ovf);
        }
    }
    /* With a midpoint rule and k >= 8 the second interior mode, eigenvalue
     * 3/8 + 1/4 cos(2 theta) > 1/2, outgrows the boundary direction (eigenvalue 1/2): the
     * fan converges to the plane of the two interior modes. Its mask: sin(2 i theta) inside,
     * +-sin(2 theta) / (2 cos(2 theta) - 1) at the ends (no level-0 correction: midpoints). */
    if (w8v == 4 && k >= 8u) {
        subd_real c2 = subd_cos_turns(2, den), s2 = subd_sin_turns(2, den);
        wa_a = subd_div(s2, subd_sub(subd_add(c2, c2, &ovf), SUBD_REAL_ONE, &ovf), &ovf);
        wa_b = subd_neg(wa_a, &ovf);
        two = 1;
    }
    topo_ring_begin(&r, m, v);
    for (i = 0; i < n; i++) {
        const subd_real *p = &ctrl[3u * lim_ring_step(&r)];
        uint32_t j = (i + n - s) % n;
        subd_real wl = 0, wx;
        if (j >= k) continue;
        if (j == 0u) {
            wl = wa_a;
            wx = wc_a;
        } else if (j == k - 1u) {
            wl = wa_b;
            wx = wc_b;
        } else {
            wx = subd_sin_turns((int32_t)j, den);
            if (two) wl = subd_sin_turns(2 * (int32_t)j, den);
        }
        for (c = 0; c < 3u; c++) {
            subd_wide d = subd_wide_diff(p[c], pv[c]);
            along[c] = subd_wide_madd(along[c], wl, d);
            across[c] = subd_wide_madd(across[c], wx, d);
        }
    }
    if (two) lim_unit_cross(along, across, out);
    else lim_unit_cross(across, along, out);
}

/* Dart tangents. The sharp edge breaks the ring's rotational symmetry but not its mirror
 * symmetry about the sharp edge, so the antisymmetric interior mode stays exact:
 * t_a = sum sin(2 pi m/n) (p_m - v), m counted from the sharp neighbour. The symmetric
 * dominant mode changes:
 *   paper's rule (stationary 3/8 at the dart): a left eigenvector with no weight on v,
 *     b_m = sin(m pi/n), b_sharp = -cot(pi/(2n)), eigenvalue 3/8 + 1/4 cos(pi/n) (check:
 *     column p_sharp: b_s (lambda - 5/8) = b_1/4, column v: 3/8 sum b_m + 3/8 b_s = 0, both
 *     hold with these values); when the sharp neighbour is not regular, level 0 uses the
 *     midpoint: b_s becomes b_s (1 - 1/(8 lambda)).
 *   midpoints: the eigenvector has weight on v and its eigenvalue solves a transcendental
 *     equation; it is found by power iteration on the mirror-symmetric half of the ring
 *     (DART_ITER(n) steps, valence <= DART_MAXN; above that the interior cos mask is used). */
#define DART_MAXN 48u
#define DART_ITER(n) (64u + (n) * (n) / 2u) /* ratio of the next symmetric eigenvalue ~ 1 - 30/n^2 */

static void lim_dart_sym_power(uint32_t n, int64_t *bv)
{
    /* bv[0] = weight of v, bv[1 + m] = b_m for m = 0..n/2 (b_0: the sharp neighbour); the
     * full ring has b_m = b_(n-m). One step bv <- bv S is done in place, keeping the old
     * b_(j-1) in prev. */
    uint64_t bq = subd_loop_nbeta_q62(n), beta30 = ((bq >> 32) + n / 2u) / n; /* beta in Q30 */
    int64_t beta = (int64_t)beta30, cbeta = ((int64_t)1 << 30) - (int64_t)n * beta, big;
    uint32_t h = n / 2u, it, j;
    for (j = 0; j <= h; j++) /* start: the cos mask, in Q30 */
        bv[1u + j] = subd_cos_turns_q62((int32_t)j, (int32_t)n) / ((int64_t)1 << 32);
    bv[0] = 0;
    for (it = 0; it < DART_ITER(n); it++) {
        int64_t sum = 0, a = bv[0], bs = bv[1], prev = 0, ab;
        for (j = 1; j < n; j++) sum += bv[1u + (j <= h ? j : n - j)];
        ab = a * beta / ((int64_t)1 << 30);
        bv[0] = a * cbeta / ((int64_t)1 << 30) + 3 * sum / 8 + bs / 2; /* column v */
        bv[1] = ab + bs / 2 + bv[2] / 4;                               /* column p_sharp: b_1 = b_(n-1) */
        for (j = 1; j <= h; j++) {                                     /* columns p_m */
            int64_t cur = bv[1u + j], next = 0, t;
            if (j + 1u < n) next = j + 1u <= h ? bv[2u + j] : (n - j - 1u == j ? cur : prev);
            t = ab + 3 * cur / 8 + next / 8;
            if (j > 1u) t += prev / 8;
            prev = cur;
            bv[1u + j] = t;
        }
        /* keep the sum zero (no component along the limit mask), then rescale so the
         * largest entry lies in [2^30, 2^31): products with Q30 weights stay below 2^62 */
        sum = bv[1];
        for (j = 1; j < n; j++) sum += bv[1u + (j <= h ? j : n - j)];
        bv[0] = -sum;
        big = 0;
        for (j = 0; j <= h + 1u; j++) big = bv[j] > big ? bv[j] : (-bv[j] > big ? -bv[j] : big);
        if (big == 0) break;
        while (big >= ((int64_t)1 << 31)) {
            big /= 2;
            for (j = 0; j <= h + 1u; j++) bv[j] /= 2;
        }
        while (big < ((int64_t)1 << 30)) {
            big *= 2;
            for (j = 0; j <= h + 1u; j++) bv[j] *= 2;
        }
    }
}

static void lim_dart_normal(const subd_mesh *m, subd_loop_boundary b, const subd_real *ctrl, uint32_t v,
                            const lim_vert *c, subd_real *out)
{
    const subd_real *pv = &ctrl[3u * v];
    uint32_t n = c->valence, i, k, ovf = 0;
    topo_ring r;
    subd_wide ta[3], ts[3];
    int64_t bv[DART_MAXN / 2u + 2u];
    subd_real bs = 0;
    int power = 0;
    if (b == SUBD_LOOP_BOUNDARY_PAPER) {
        /* cot(pi/(2n)) = (1 + cos(pi/n)) / sin(pi/n) */
        subd_real cs = subd_cos_turns(1, 2 * (int32_t)n), sn = subd_sin_turns(1, 2 * (int32_t)n);
        bs = subd_neg(subd_div(subd_add(SUBD_REAL_ONE, cs, &ovf), sn, &ovf), &ovf);
        if (!lim_regular(m, c->c0)) {
            subd_real l8 = subd_add(SUBD_REAL_FRAC(3, 1), subd_add(cs, cs, &ovf), &ovf);
            bs = subd_sub(bs, subd_div(bs, l8, &ovf), &ovf);
        }
    } else if (n <= DART_MAXN) {
        lim_dart_sym_power(n, bv);
        power = 1;
    }
    for (k = 0; k < 3u; k++) ta[k] = ts[k] = (subd_wide)0;
    topo_ring_begin(&r, m, v);
    for (i = 0; i < n; i++) {
        const subd_real *p = &ctrl[3u * lim_ring_step(&r)];
        uint32_t j = (i + n - c->i0) % n;
        subd_real wa = subd_sin_turns((int32_t)j, (int32_t)n), ws;
        if (power) {
            int64_t q = bv[1u + (j <= n / 2u ? j : n - j)]; /* |q| < 2^31 */
            ws = subd_real_from_q62(q * ((int64_t)1 << 31));
        } else if (b == SUBD_LOOP_BOUNDARY_PAPER) {
            ws = j == 0u ? bs : subd_sin_turns((int32_t)j, 2 * (int32_t)n);
        } else {
            ws = subd_cos_turns((int32_t)j, (int32_t)n);
        }
        for (k = 0; k < 3u; k++) {
            subd_wide d = subd_wide_diff(p[k], pv[k]);
            ta[k] = subd_wide_madd(ta[k], wa, d);
            ts[k] = subd_wide_madd(ts[k], ws, d);
        }
    }
    if (b == SUBD_LOOP_BOUNDARY_PAPER) lim_unit_cross(ta, ts, out);
    else lim_unit_cross(ts, ta, out);
}

/* Corner: per sector between sharp edges, the unit normal of (p_first - v) x (p_last - v)
 * (the directions in which the two sharp curves leave the fixed corner, exact tangents of
 * those curves), turned to agree with the sector's fan; the unit normals are summed and
 * normalised. This is the tangent plane when the sector has at most two faces; with more
 * faces an interior mode of the sector can decay more slowly than the curves and Loop's
 * corner has no tangent plane in general (Biermann et al. 2000), so it is an approximation
 * there. A tagged corner without sharp edges uses the interior tangents, which stay exact
 * for a fixed centre (its modes with weight 0 on v are those of the smooth ring); with one
 * sharp edge, the same (an approximation). */
static void lim_corner_normal(const subd_mesh *m, const subd_real *ctrl, uint32_t v, uint32_t n,
                              int boundary, subd_real *out)
{
    const subd_real *pv = &ctrl[3u * v];
    uint32_t i, k, s0 = 0;
    uint32_t nfaces = boundary ? n - 1u : n;
    subd_wide acc[3], fan[3], d0[3], dp[3];
    topo_ring r;
    for (k = 0; k < 3u; k++) acc[k] = fan[k] = d0[k] = dp[k] = (subd_wide)0;
    /* an interior corner: start the walk at its first sharp edge (a boundary one starts
     * at its boundary edge already) */
    if (!boundary) {
        topo_ring_begin(&r, m, v);
        while (s0 < n && topo_ring_step(&r) && !topo_ring_sharp(&r, m->edge_tag)) s0++;
    }
    topo_ring_begin(&r, m, v);
    for (i = 0; i < s0; i++) (void)lim_ring_step(&r);
    /* faces (v, p_j, p_j+1) for j = s0 .. s0 + nfaces - 1; sector ends at sharp edges */
    for (i = 0; i <= nfaces; i++) {
        uint32_t he, u;
        subd_wide d[3];
        if (s0 + i == n) topo_ring_begin(&r, m, v); /* wrap around an interior corner */
        he = r.next; /* the outgoing half-edge of this step; SUBD_NONE for the tail */
        u = lim_ring_step(&r);
        for (k = 0; k < 3u; k++) d[k] = subd_wide_diff(ctrl[3u * u + k], pv[k]);
        if (i > 0u) {
            subd_real fn[3];
            lim_unit_cross(dp, d, fn);
            lim_add_unit(fan, fn);
            if (he == SUBD_NONE || topo_mesh_edge_sharp(m, he) || i == nfaces) {
                subd_real sn[3];
                subd_wide sw[3];
                lim_unit_cross(d0, d, sn);
                for (k = 0; k < 3u; k++) sw[k] = (subd_wide)sn[k];
                if (lim_dot_sign(fan, sw) < 0)
                    for (k = 0; k < 3u; k++) sn[k] = -sn[k];
                lim_add_unit(acc, sn);
                for (k = 0; k < 3u; k++) {
                    fan[k] = (subd_wide)0;
                    d0[k] = d[k];
                }
            }
        } else {
            for (k = 0; k < 3u; k++) d0[k] = d[k];
        }
        for (k = 0; k < 3u; k++) dp[k] = d[k];
    }
    subd_w3_unit(acc, out);
}

/* 8 w for the paper's rule on sharp edge (v, c): 4 when both are regular or both are not,
 * else 5 (v regular) or 3 (v extraordinary). */
static int32_t lim_w8(subd_loop_boundary b, int rv, int rc)
{
    if (b == SUBD_LOOP_BOUNDARY_BSPLINE || rv == rc) return 4;
    return rv ? 5 : 3;
}

static void lim_normal(const subd_mesh *m, subd_loop_boundary b, const subd_real *ctrl, uint32_t v,
                       const lim_vert *c, lim_trig *tab, subd_real *out)
{
    subd_wide t1[3], t2[3];
    uint32_t k, n = c->valence;
    for (k = 0; k < 3u; k++) out[k] = (subd_real)0;
    if (c->cls == LOOP_SMOOTH || (c->cls == LOOP_CORNER && c->nsharp <= 1u)) {
        lim_smooth_tangents(m, ctrl, v, n, 0u, tab, t1, t2);
        lim_unit_cross(t1, t2, out);
    } else if (c->cls == LOOP_DART) {
        lim_dart_normal(m, b, ctrl, v, c, out);
    } else if (c->cls == LOOP_CORNER) {
        lim_corner_normal(m, ctrl, v, n, c->boundary != 0u, out);
    } else if (c->cls == LOOP_CREASE) {
        int rv = b == SUBD_LOOP_BOUNDARY_PAPER && (int)c->regular;
        int r0 = b == SUBD_LOOP_BOUNDARY_PAPER && lim_regular(m, c->c0);
        int r1 = b == SUBD_LOOP_BOUNDARY_PAPER && lim_regular(m, c->c1);
        int32_t w8v = (b == SUBD_LOOP_BOUNDARY_BSPLINE || rv) ? 4 : 3;
        int32_t w80 = lim_w8(b, rv, r0), w81 = lim_w8(b, rv, r1);
        if (c->boundary) {
            lim_side_normal(m, ctrl, v, n, 0u, n, w8v, w80, w81, out);
        } else {
            subd_real u0[3], u1[3];
            subd_wide acc[3];
            lim_side_normal(m, ctrl, v, n, c->i0, c->i1 - c->i0 + 1u, w8v, w80, w81, u0);
            lim_side_normal(m, ctrl, v, n, c->i1, n - (c->i1 - c->i0) + 1u, w8v, w81, w80, u1);
            for (k = 0; k < 3u; k++) acc[k] = (subd_wide)0;
            lim_add_unit(acc, u0);
            lim_add_unit(acc, u1);
            subd_w3_unit(acc, out);
        }
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
