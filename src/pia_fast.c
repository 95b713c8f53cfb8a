/* SPDX-License-Identifier: MIT */
/* Progressive interpolation, the accelerated method SUBD_PIA_FAST (beyond the paper:
 * loop-progressive-interpolation.txt, sections 2-4, which pia.c follows; pia.c also holds
 * the validation, layout, errors and the driver shared with it).
 * This file: the vertex classes and CG weights, the W inner products, plain CG, the end of a
 * CG or PCG iteration shared with pia_sgs.c, Chebyshev and the driver; the preconditioner
 * (SGS sweeps, row shapes) is pia_sgs.c.
 *
 * SUBD_PIA_FAST, beyond the paper. Two accelerations, chosen by the mesh's structure:
 *
 * (1) Conjugate gradients, phase by phase (pia_phase_sym), when no dart couples the phases:
 * plain CG (pia_phase_cg) on a uniform phase, preconditioned CG (pia_phase_sgs, (1b) below)
 * on any other.
 * The phases are the paper's, split by limit rule rather than by the boundary tag: first
 * the curve vertices (boundary and crease vertices, two sharp edges), then the smooth ones;
 * corners and isolated vertices never move (V = P is exact there). Vertices outside the
 * phase are fixed, so the phase solves A x = b with A its block of L, and CG runs in the
 * inner product <x, y>_W = sum_v w_v x_v . y_v, where W makes W A symmetric:
 *   - smooth block: row v of L is beta_n on v and chi_n = (1 - beta_n) / n on each
 *     neighbour; w_v = 1 / chi_{n_v} = n / (1 - beta_n) gives (W A)_{uv} = 1 for every edge:
 *     W A is the minor S_I of the paper's S (section 4), positive definite by theorem 1;
 *   - curve block: the weight of neighbour u in row v is c_v g_u with c_v = 1/48 (regular
 *     v) or 1/40 (extraordinary), g_u = 8 (regular u) or 7 (the six masks 1/6, 7/48, 1/5,
 *     7/40); w_v = 48 or 35 gives (W A)_{uv} = g_u g_v / 8, symmetric, and as the two
 *     neighbour weights of a row sum to at most 2/5, W A is strictly diagonally dominant
 *     with a positive diagonal, hence positive definite. B-spline rule: w_v = 1.
 * CG's k-th iterate minimises the energy norm |e|_{WA} over V^0 + K_k(A, r_0). The paper's
 * k-th iterate V^0 + sum_{j<k} (I - A)^j r_0 lies in the same affine Krylov space, so in
 * exact arithmetic CG is never behind the paper's method after the same number of
 * iterations (in that norm), and |e_k| <= 2 q^k |e_0| with q = (sqrt(kappa) - 1) /
 * (sqrt(kappa) + 1), kappa <= 1 / lambda_min. A lower bound for lambda_min from theorem 1's
 * proof, x^T S x >= sum_i n_i (beta_i/(1-beta_i) - 1/2) x_i^2, gives lambda_min >=
 * min_i (3 beta_i - 1) / 2 = 1/10, 17/110, 0.207, 1/4 for smallest valence 3, 4, 5, >= 6
 * (tight on the regular lattice, spectrum [1/4, 1]): q = 1/3 there against the paper's
 * 3/4. In practice CG does far better (superlinear; exact after as many steps as the data
 * has distinct eigenvalues: 1 on the bundled icosahedron, whose coordinates are one
 * eigenvector). Per iteration: one application of L (to the search direction; L V follows
 * by the same recurrence) and two weighted dot products.
 *
 * (1b) Symmetric Gauss-Seidel preconditioned CG on a non-uniform phase: pia_sgs.c (its
 * derivation in that file's header).
 *
 * (2) Chebyshev semi-iteration on all movable vertices at once (pia_phase_cheb) when the
 * mesh has darts. A dart (one sharp edge) uses formula (3), yet the crease vertex next to it
 * depends on it, so the curve and smooth blocks are coupled both ways, L is no longer
 * symmetrisable and CG does not apply; alternating CG phases (block Gauss-Seidel) measured
 * no faster than the paper's step. Chebyshev needs only an interval [l, 1] holding the
 * spectrum: l = the smallest of the bounds above over the movable vertices, with 1/5
 * (paper rule) or 1/3 (B-spline rule) for curve vertices by Gershgorin on their rows and
 * both bounds for a dart. Its residual after k steps is p_k(L) r_0 with p_k the scaled
 * Chebyshev polynomial, |p_k| <= 2 q^k / (1 + q^2k) on [l, 1], q = (1 - sqrt l) /
 * (1 + sqrt l); the first step is the optimally weighted paper step V += 2/(1 + l) r.
 * With darts there is no proof that the spectrum is real; eigenvalues in (0, l) or
 * (1, 1 + l) would still decay (|p_k| < 1 there), only more slowly. Chebyshev is not the
 * choice without darts because it is tuned to the worst case: on smooth data (error near
 * eigenvalue 1) it lost to the paper's plain step (6 against 5 iterations on the
 * icosahedron), where CG takes 1.
 *
 * Safeguards (FAST). W is computed here from the valence and loop_limit.c's regularity rule
 * while L's weights are rounded (and valences above PIA_MAX_VALENCE get a capped weight), so
 * W A is symmetric only to that accuracy: perturbed CG, slower at worst. The recurrence for
 * L V drifts from the true L V by rounding, so when it says "converged" L V is recomputed
 * and the true error decides; if that fails the phase is at the rounding floor and the
 * paper's step finishes it (its integer floor is lower than CG's). A curvature
 * <p, A p>_W <= 0, a step or ratio that does not fit subd_real, or an error above twice the
 * phase's starting error also hand the phase to the paper's step (which converges for any
 * spectrum in (0, 2)). Whatever is left above tol after the accelerated phases (a stalled
 * phase) gets the paper's step on every movable vertex; the stall guard ends each phase.
 *
 */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "loop_rules.h"
#include "mesh_internal.h"
#include "pia_internal.h"
#include "wide.h"

/* ------------------------------------------------------------------------------------ */
/* Conjugate gradients (FAST)                                                             */

/* CG weight of a smooth vertex of valence n: n / (1 - beta_n) = n (1 - x^2) / (5/8 - x^2)
 * with x = 3/8 + cos(2 pi / n) / 4 (see loop_limit.c); 5/8 - x^2 >= 15/64. */
static subd_real pia_weight_smooth(uint32_t n, uint32_t *ovf)
{
    subd_real x, x2;
    if (n > PIA_MAX_VALENCE) n = PIA_MAX_VALENCE;
    x = subd_add(SUBD_REAL_FRAC(3, 8), subd_mul(subd_cos_turns(1, (int32_t)n), SUBD_REAL_FRAC(1, 4), ovf), ovf);
    x2 = subd_mul(x, x, ovf);
    return subd_mul(subd_from_int((int32_t)n, ovf),
                    subd_div(subd_sub(SUBD_REAL_ONE, x2, ovf), subd_sub(SUBD_REAL_FRAC(5, 8), x2, ovf), ovf), ovf);
}

/* Class and CG weight of every vertex, by subd_loop_classify (loop_rules.h, the classification of
 * loop.c and loop_limit.c): a corner (tagged, or three or more sharp edges) or isolated
 * vertex is fixed; two sharp edges make a curve vertex (regular as loop_rules.h defines it:
 * valence 4 on a boundary, valence 6 with opposite sharp edges inside); fewer make a smooth
 * vertex (one: a dart, formula (3) as well). */
/* Not inlined (nor pia_phase_cheb): their frames stay off the CG path's stack. */
static SUBD_NOINLINE void pia_classify(pia_state *s)
{
    const subd_mesh *m = s->m;
    const subd_real curve = (s->o->boundary == SUBD_LOOP_BOUNDARY_BSPLINE) ? SUBD_REAL_FRAC(1, 3) : SUBD_REAL_FRAC(1, 5);
    subd_real lo, cache[PIA_WCACHE];
    uint32_t v, n, ns;
    loop_vinfo c;
    for (v = 0; v < PIA_WCACHE; v++) cache[v] = 0;
    s->ell = SUBD_REAL_FRAC(1, 3);
    s->darts = 0;
    for (v = 0; v < m->num_verts; v++) {
        s->cls[v] = PIA_CLS_FIXED;
        s->w[v] = 0;
        s->od[v] = 0;
        subd_loop_classify(m, v, &c);
        if (c.cls == LOOP_ISOLATED || c.cls == LOOP_CORNER) continue;
        n = c.valence;
        ns = c.nsharp;
        if (ns == 2u) {
            s->cls[v] = (uint8_t)(PIA_CLS_CURVE | (c.regular ? PIA_CLS_REGULAR : 0));
            if (s->o->boundary == SUBD_LOOP_BOUNDARY_BSPLINE) s->w[v] = SUBD_REAL_ONE;
            else s->w[v] = subd_from_int(c.regular ? 48 : 35, &s->ovf);
            lo = curve;
        } else {
            s->cls[v] = PIA_CLS_SMOOTH;
            if (n < PIA_WCACHE) {
                if (cache[n] == 0) cache[n] = pia_weight_smooth(n, &s->ovf);
                s->w[v] = cache[n];
            } else {
                s->w[v] = pia_weight_smooth(n, &s->ovf);
            }
            s->od[v] = subd_div(SUBD_REAL_ONE, s->w[v], &s->ovf); /* chi_n = 1 / w_v */
            /* (3 beta_n - 1) / 2, increasing in n */
            if (n <= 2u) lo = SUBD_REAL_FRAC(1, 14);
            else if (n == 3u) lo = SUBD_REAL_FRAC(1, 10);
            else if (n == 4u) lo = SUBD_REAL_FRAC(17, 110);
            else if (n == 5u) lo = SUBD_REAL_FRAC(2071, 10000); /* 0.2071326 rounded down */
            else lo = SUBD_REAL_FRAC(1, 4);
            if (ns == 1u) {
                s->darts = 1;
                if (curve < lo) lo = curve;
            }
        }
        if (lo < s->ell) s->ell = lo;
    }
}

/* Why the #if: the fixed build's CG dot products are exact 128-bit integer sums and their
 * ratio an integer division (the algorithm of the fixed build, not a scalar twin). */
#if SUBD_FIXED

/* Component k of a - as (as may be NULL), exactly. */
static int64_t pia_comp(const subd_real *a, const subd_real *as, uint32_t k)
{
    return (int64_t)a[k] - (as ? as[k] : 0);
}

/* c / 2^sh truncated towards zero (symmetric, so tiny values of either sign vanish), for
 * |c| < 2^(21 + sh): the result fits 22 bits. */
static int32_t pia_shr(int64_t c, uint32_t sh)
{
    return (int32_t)(c < 0 ? -(int64_t)((uint64_t)-c >> sh) : (int64_t)((uint64_t)c >> sh));
}

/* sum over the set of w_v (a_v - as_v) . (b_v - bs_v), summed exactly in 128 bits after
 * scaling the components to |c| < 2^21 (one shift for the whole sum, from the largest
 * component) and the weights to 8.8 fixed point (< 2^16): each vertex term is below
 * 3 * 2^42 * 2^16 < 2^60. The products are 32 x 32 -> 64 bits (one instruction on a
 * Cortex-M3). */
pia_dotv subd_pia_dot(const pia_state *s, uint32_t set, const subd_real *a, const subd_real *as,
                        const subd_real *b, const subd_real *bs)
{
    pia_dotv r;
    uint64_t bits = 0, old;
    uint32_t i, k, sh = 0;
    r.lo = 0;
    r.hi = 0;
    for (i = 0; i < s->m->num_verts; i++) {
        if (!pia_in_set(s, i, set)) continue;
        for (k = 3u * i; k < 3u * i + 3u; k++) {
            int64_t ca = pia_comp(a, as, k), cb = pia_comp(b, bs, k);
            bits |= (uint64_t)(ca < 0 ? -ca : ca) | (uint64_t)(cb < 0 ? -cb : cb);
        }
    }
    while ((bits >> sh) >= ((uint64_t)1 << 21)) sh++;
    for (i = 0; i < s->m->num_verts; i++) {
        int64_t t = 0, wq;
        if (!pia_in_set(s, i, set)) continue;
        for (k = 3u * i; k < 3u * i + 3u; k++)
            t += (int64_t)pia_shr(pia_comp(a, as, k), sh) * pia_shr(pia_comp(b, bs, k), sh);
        wq = ((int64_t)s->w[i] + 128) / 256;
        if (wq > 65535) wq = 65535;
        t *= wq;
        old = r.lo;
        r.lo += (uint64_t)t;
        r.hi += (t < 0 ? -1 : 0) + (r.lo < old ? 1 : 0);
    }
    r.e = (int32_t)(2u * sh) - 8;
    return r;
}

/* x as mant * 2^e with mant in [2^61, 2^62) (x > 0, hi >= 0). */
static uint64_t pia_norm(pia_dotv x, int32_t *e)
{
    uint64_t hi = (uint64_t)x.hi, lo = x.lo;
    int32_t ex = x.e;
    while (hi != 0u || lo >= ((uint64_t)1 << 62)) {
        lo = (lo >> 1) | (hi << 63);
        hi >>= 1;
        ex++;
    }
    while (lo < ((uint64_t)1 << 61)) {
        lo <<= 1;
        ex--;
    }
    *e = ex;
    return lo;
}

/* x / y as a subd_real (truncated); *ok = 0 when x < 0, y <= 0 or the ratio does not fit. */
subd_real subd_pia_ratio(pia_dotv x, pia_dotv y, int *ok)
{
    uint64_t mx, my, q, rem;
    int32_t ex, ey, sh;
    subd_u128 n;
    if (x.hi < 0 || y.hi < 0 || (y.hi == 0 && y.lo == 0u)) {
        *ok = 0;
        return 0;
    }
    if (x.hi == 0 && x.lo == 0u) return 0;
    mx = pia_norm(x, &ex);
    my = pia_norm(y, &ey);
    /* q = floor(mx / my * 2^30) < 2^31 (mx / my in (1/2, 2)), by wide.h's long division */
    n.hi = mx >> 34;
    n.lo = mx << 30;
    q = subd_u128_div(n, my, &rem);
    /* value = q * 2^(ex - ey - 30); Q16.16 raw = q * 2^(ex - ey - 14) */
    sh = ex - ey - 14;
    if (sh >= 0) {
        if (sh > 31 || q > ((uint64_t)INT32_MAX >> sh)) {
            *ok = 0;
            return 0;
        }
        return (subd_real)(q << sh);
    }
    if (sh <= -63) return 0;
    return (subd_real)(q >> -sh);
}

#else

pia_dotv subd_pia_dot(const pia_state *s, uint32_t set, const subd_real *a, const subd_real *as,
                        const subd_real *b, const subd_real *bs)
{
    float acc = 0.0f;
    uint32_t i, k;
    for (i = 0; i < s->m->num_verts; i++) {
        float t = 0.0f, wt;
        if (!pia_in_set(s, i, set)) continue;
        for (k = 3u * i; k < 3u * i + 3u; k++) {
            float ca = as ? a[k] - as[k] : a[k], cb = bs ? b[k] - bs[k] : b[k];
            float pr = ca * cb;
            t = t + pr;
        }
        wt = s->w[i] * t;
        acc = acc + wt;
    }
    return acc;
}

subd_real subd_pia_ratio(pia_dotv x, pia_dotv y, int *ok)
{
    float r;
    if (!(x >= 0.0f) || !(y > 0.0f) || !subd_real_is_finite(x) || !subd_real_is_finite(y)) {
        *ok = 0;
        return 0.0f;
    }
    r = x / y;
    if (!subd_real_is_finite(r)) *ok = 0;
    return r;
}

#endif

/* The end of a CG or PCG iteration (pia_internal.h's PIA_GO_ON, PIA_DONE, PIA_SAFEGUARD),
 * shared by both: V += alpha p and L V += alpha q on the
 * set with the new max error in one pass (the recurrence; `halves` half-applications of L
 * are charged), then the verdict. DONE: the true error (residual replacement) is <= tol,
 * or no new minimum for PIA_STALL iterations (the rounding floor: not converged); lv is
 * exact then. SAFEGUARD: the recurrence drifted at the rounding floor, or the error grew
 * beyond twice its start; the caller polishes with the paper's step. */
int subd_pia_cg_advance(pia_state *s, uint32_t set, subd_real alpha, uint32_t halves, subd_real start,
                          subd_real *best, uint32_t *stall)
{
    const subd_real *P = s->m->pos;
    subd_real err;
    pia_sq e2 = 0;
    uint32_t i, k;
    for (i = 0; i < s->m->num_verts; i++) {
        pia_sq d2;
        if (!pia_in_set(s, i, set)) continue;
        for (k = 3u * i; k < 3u * i + 3u; k++) {
            s->v[k] = subd_add(s->v[k], subd_mul(alpha, s->p[k], &s->ovf), &s->ovf);
            s->lv[k] = subd_add(s->lv[k], subd_mul(alpha, s->q[k], &s->ovf), &s->ovf);
        }
        d2 = subd_w3_dist2(&P[3u * i], &s->lv[3u * i], &s->ovf);
        if (d2 > e2) e2 = d2;
    }
    s->lv_true = 0;
    s->half += halves;
    err = subd_w3_dist_root(e2, &s->ovf);
    if (!s->ovf && err <= s->o->tol) {
        pia_limit(s);
        err = subd_pia_max_err(s, set);
        return s->ovf || err <= s->o->tol ? PIA_DONE : PIA_SAFEGUARD;
    }
    if (err < *best) {
        *best = err;
        *stall = 0;
    } else if (++*stall >= PIA_STALL) {
        if (!s->lv_true) pia_limit(s);
        return PIA_DONE;
    }
    if (err > start && subd_sub(err, start, &s->ovf) > start) return PIA_SAFEGUARD;
    return PIA_GO_ON;
}

/* CG on the set (all other vertices fixed) until its max error is <= tol, it stalls, the
 * budget is spent, or a safeguard hands the phase to the paper's step. Needs an exact lv on
 * entry and leaves one. */
static void pia_phase_cg(pia_state *s, uint32_t set)
{
    const subd_mesh *m = s->m;
    const subd_real *P = m->pos;
    subd_real err, start, best, alpha, beta;
    pia_dotv rho, rho_new, sigma;
    uint32_t i, k, stall = 0;
    int ok = 1, st;

    err = subd_pia_max_err(s, set);
    if (s->ovf || err <= s->o->tol) return;
    start = best = err;
    for (i = 0; i < m->num_verts; i++) {
        int in = pia_in_set(s, i, set);
        for (k = 3u * i; k < 3u * i + 3u; k++) s->p[k] = in ? subd_sub(P[k], s->lv[k], &s->ovf) : 0;
    }
    rho = subd_pia_dot(s, set, P, s->lv, P, s->lv);
    while (!s->ovf && pia_budget(s, 2u)) {
        subd_loop_limit_apply(m, s->o->boundary, s->p, s->q, &s->ovf);
        sigma = subd_pia_dot(s, set, s->p, 0, s->q, 0);
        alpha = subd_pia_ratio(rho, sigma, &ok);
        if (!ok || s->ovf) break;
        st = subd_pia_cg_advance(s, set, alpha, 2u, start, &best, &stall);
        if (st == PIA_DONE) return;
        if (st == PIA_SAFEGUARD) {
            ok = 0;
            break;
        }
        rho_new = subd_pia_dot(s, set, P, s->lv, P, s->lv);
        beta = subd_pia_ratio(rho_new, rho, &ok);
        if (!ok) break;
        rho = rho_new;
        for (i = 0; i < m->num_verts; i++) {
            if (!pia_in_set(s, i, set)) continue;
            for (k = 3u * i; k < 3u * i + 3u; k++) {
                subd_acc acc = subd_acc_add(subd_acc_zero(), SUBD_REAL_ONE, subd_sub(P[k], s->lv[k], &s->ovf));
                acc = subd_acc_add(acc, beta, s->p[k]);
                s->p[k] = subd_acc_real(acc, &s->ovf);
            }
        }
    }
    if (s->ovf) return;
    if (!s->lv_true) pia_limit(s);
    if (!ok) subd_pia_phase_paper(s, set); /* safeguard: the paper's step from here on */
}

/* A phase of the symmetrisable system: plain CG when the set is uniform, else SGS-PCG. */
static void pia_phase_sym(pia_state *s, uint32_t set)
{
    if (subd_pia_uniform(s, set)) pia_phase_cg(s, set);
    else if (!s->ovf) subd_pia_phase_sgs(s, set); /* pia_sgs.c */
}

/* ------------------------------------------------------------------------------------ */
/* Chebyshev semi-iteration (FAST on meshes with darts)                                   */

/* Chebyshev iteration for L V = P on the set, for a spectrum in [ell, 1], until the max
 * error is <= tol, it stalls, or the budget is spent; an error above twice the starting
 * one hands the set to the paper's step. p holds the step d_k. Exact lv on entry and exit. */
static SUBD_NOINLINE void pia_phase_cheb(pia_state *s, uint32_t set)
{
    const subd_mesh *m = s->m;
    subd_real one = SUBD_REAL_ONE, two = subd_add(one, one, &s->ovf);
    subd_real opl = subd_add(one, s->ell, &s->ovf), oml = subd_sub(one, s->ell, &s->ovf);
    subd_real c0 = subd_div(two, opl, &s->ovf);                                /* 1 / theta  */
    subd_real two_sigma = subd_div(subd_add(opl, opl, &s->ovf), oml, &s->ovf); /* 2 sigma    */
    subd_real four_over = subd_div(subd_add(two, two, &s->ovf), oml, &s->ovf); /* 2 / delta  */
    subd_real err, best = 0, start = 0, rho = 0, rho_new, a, c;
    uint32_t stall = 0, k, i;
    for (k = 0;; k++) {
        err = subd_pia_max_err(s, set);
        if (s->ovf || err <= s->o->tol || subd_pia_stalled(err, k, &best, &stall)) return;
        if (!pia_budget(s, 2u)) return;
        if (k == 0u) {
            start = err;
            a = 0;
            c = c0;
            rho = subd_div(oml, opl, &s->ovf); /* rho_0 = 1 / sigma */
            for (i = 0; i < 3u * m->num_verts; i++) s->p[i] = 0;
        } else if (err > start && subd_sub(err, start, &s->ovf) > start) {
            subd_pia_phase_paper(s, set); /* safeguard: the error grew beyond twice its start */
            return;
        } else {
            rho_new = subd_div(one, subd_sub(two_sigma, rho, &s->ovf), &s->ovf);
            a = subd_mul(rho_new, rho, &s->ovf);
            c = subd_mul(rho_new, four_over, &s->ovf);
            rho = rho_new;
        }
        /* d = a d + c (P - L V), V += d */
        for (i = 0; i < m->num_verts; i++) {
            uint32_t j;
            if (!pia_in_set(s, i, set)) continue;
            for (j = 3u * i; j < 3u * i + 3u; j++) {
                subd_acc acc = subd_acc_add(subd_acc_zero(), a, s->p[j]);
                acc = subd_acc_add(acc, c, subd_sub(m->pos[j], s->lv[j], &s->ovf));
                s->p[j] = subd_acc_real(acc, &s->ovf);
                s->v[j] = subd_add(s->v[j], s->p[j], &s->ovf);
            }
        }
        s->half += 2u;
        pia_limit(s);
        if (s->ovf) return;
    }
}

/* ------------------------------------------------------------------------------------ */

/* SUBD_PIA_FAST from V = P (exact lv): the curve phase, then the smooth phase, or one
 * Chebyshev phase when darts couple them; then the paper's step on whatever a stalled or
 * abandoned phase left above tol. The curve phase of an open mesh is its boundary phase in
 * the report (half_bnd): it moves the boundary vertices (and any crease vertices) first,
 * as the paper's phase 1 does; on a closed mesh, or with darts, the boundary phase is
 * empty and every iteration counts as interior. */
void subd_pia_fast(pia_state *s)
{
    pia_classify(s);
    if (!s->ovf && s->darts) pia_phase_cheb(s, PIA_SET_MOVABLE);
    if (!s->ovf && !s->darts) pia_phase_sym(s, PIA_SET_CURVE);
    if (!s->darts && s->m->num_boundary_edges > 0u) s->half_bnd = s->half;
    if (!s->ovf && !s->darts) pia_phase_sym(s, PIA_SET_SMOOTH);
    /* a phase that stalled or gave up: the paper's step polishes what is left */
    if (!s->ovf && subd_pia_max_err(s, PIA_SET_ALL) > s->o->tol) subd_pia_phase_paper(s, PIA_SET_MOVABLE);
}
