/* SPDX-License-Identifier: MIT */
/* Loop limit normals (subd_loop_limit_normal): the tangent masks of every vertex class and
 * their unit cross product, for subd_loop_limit and subd_loop_limit_vertex (loop_limit.c,
 * which holds the positions and the public calls). Paper and derivations: loop_limit.c's
 * header ("NORMALS"); the classification is loop_rules.h's, shared with the positions.
 */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "loop_internal.h"
#include "loop_rules.h"
#include "mesh_internal.h"
#include "topo.h"
#include "vec3w.h"
#include "wide.h"
#include "loop_limit_internal.h"

/* ------------------------------------------------------------------------------------ */
/* Limit normals                                                                          */

/* Unit vectors by vec3w.h: subd_w3_unit(c) is c / |c|, or (0, 0, 0) for c = 0.
 * lim_unit_cross: the unit vector along t1 x t2 (loop_limit_internal.h's
 * subd_loop_limit_unit_cross, out of line here); lim_dot_sign: the sign of a . b. Both
 * first rescale their operands with subd_w3_normalize to 30 bits (float32: largest
 * component 1), so the cross and dot products cannot overflow (Q16.16: below 2^61 and
 * 3 * 2^60) or underflow; only the directions matter. */
static void lim_unit_cross(const subd_wide *t1, const subd_wide *t2, subd_real *out)
{
    subd_loop_limit_unit_cross(t1, t2, out);
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

void subd_loop_limit_reg6_trig(lim_reg6 *k)
{
    lim_trig tab;
    uint32_t j;
    tab.filled = 0;
    for (j = 0; j < 6u; j++) lim_sincos(&tab, j, 6u, &k->c[j], &k->s[j]);
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

void subd_loop_limit_normal(const subd_mesh *m, subd_loop_boundary b, const subd_real *ctrl, uint32_t v,
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
