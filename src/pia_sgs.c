/* SPDX-License-Identifier: MIT */
/* Progressive interpolation, SUBD_PIA_FAST's preconditioned phase (beyond the paper,
 * loop-progressive-interpolation.txt; pia_fast.c holds the rest of the method and its
 * overview, (1) to (2) and the safeguards): the symmetric Gauss-Seidel sweeps over the
 * strictly lower / upper neighbours of each row of the phase's block of L, SGS-preconditioned
 * CG with Eisenstat's trick (subd_pia_phase_sgs), and the row-shape test that keeps plain CG
 * on a uniform phase (subd_pia_uniform). The W inner products and the end of an iteration
 * are pia_fast.c's (subd_pia_dot, subd_pia_ratio, subd_pia_cg_advance).
 *
 * Symmetric Gauss-Seidel preconditioning (subd_pia_phase_sgs). With the phase's block
 * A = D + Lo + Up split by vertex index (D its diagonal: beta_n, or 1 minus the two curve
 * weights), M = K D^-1 K', K = D + Lo, K' = D + Up, satisfies W M = (D_W + E) D_W^-1
 * (D_W + E^T) with D_W = W D, E = W Lo, W Up = E^T (W A symmetric): M is W-symmetric and
 * positive definite, so PCG in the W inner product converges, |e_k| <= 2 q^k |e_0| in the
 * energy norm with q from kappa(M^-1 A) instead of kappa(A). Its Krylov space is not the
 * paper's, so (1)'s "never behind the paper" does not carry over: that is measured (every
 * test and bench mesh, pia_fast in test/test_pia.c). SGS shrinks kappa on irregular
 * meshes (measured in float64 on L at 1e-4 x diagonal: spot 4 -> 2 iterations, the open
 * bunny 8 -> 4). Eisenstat's trick keeps pt = K' p by recurrence, so A p = pt + Lo p: an
 * iteration is a forward sweep y = K^-1 r, a backward sweep z = K'^-1 D y and Lo p, each half
 * an application of L (the strictly lower or upper neighbours of every row), and counts as
 * 1.5 iterations (`iterations` is the work in applications of L, rounded up; max_iter bounds
 * it). The sweeps use loop_limit.c's curve masks themselves (subd_loop_limit_curve_frac, by
 * the regularity pia_classify records) and chi_n = 1 / w_v recomputed here in subd_real
 * (loop_limit.c's own Q62 chi would round differently and change the iterates), equal to
 * L's up to rounding; a difference only perturbs the L V
 * recurrence, which the true error at convergence checks (safeguards below). A uniform phase,
 * where every row has the same diagonal and CG weight (the icosahedron, torus_tri, the
 * hexfan's boundary), keeps plain CG: the data's symmetry that CG exploits there (1
 * iteration on the icosahedron, 3 on torus_tri) is lost to the sweep order (measured: 5 and
 * 4 SGS iterations, 7.5 and 6 in work), and Jacobi scaling, the symmetric alternative, is
 * the identity there.
 */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "loop_rules.h"
#include "mesh_internal.h"
#include "pia_internal.h"
#include "topo.h"

/* ------------------------------------------------------------------------------------ */
/* Symmetric Gauss-Seidel preconditioned CG with Eisenstat's trick (FAST)                 */

/* The two sharp-edge neighbours of curve vertex v, in ring order (as loop_limit.c). */
static void pia_curve_nbrs(const subd_mesh *m, uint32_t v, uint32_t *c)
{
    uint32_t ns = 0;
    topo_ring r;
    c[0] = c[1] = v;
    topo_ring_begin(&r, m, v);
    while (topo_ring_step(&r))
        if (topo_ring_sharp(&r, m->edge_tag)) { /* topo.h's rule, as subd_loop_classify */
            if (ns < 2u) c[ns] = r.nb;
            ns++;
        }
}

/* Weight of curve neighbour u in curve vertex v's row of L: loop_limit.c's mask, by the
 * regularity pia_classify recorded (a regular vertex is always a curve vertex). */
static subd_real pia_curve_w(const pia_state *s, uint32_t v, uint32_t u)
{
    int32_t num, den;
    subd_loop_limit_curve_frac(s->o->boundary, (s->cls[v] & PIA_CLS_REGULAR) != 0u, (s->cls[u] & PIA_CLS_REGULAR) != 0u,
                               &num, &den);
    return SUBD_REAL_FRAC(num, den);
}

/* Vertex v's row of A (L restricted to the set PIA_SET_CURVE or PIA_SET_SMOOTH, v in it): the diagonal, returned, and in
 * sum the off-diagonal part applied to x over the neighbours u in the set with u < v
 * (upper = 0: the strictly lower triangle Lo) or u > v (upper = 1: Up); rows of L with
 * neighbours outside the set lose those columns (fixed vertices). x = NULL: the diagonal
 * only. */
static subd_real pia_half_row(pia_state *s, uint32_t set, uint32_t v, int upper, const subd_real *x,
                              subd_real *sum)
{
    const subd_mesh *m = s->m;
    subd_acc acc[3];
    subd_real d;
    uint32_t k, i, n = 0;
    const uint8_t want = set == PIA_SET_CURVE ? PIA_CLS_CURVE : PIA_CLS_SMOOTH; /* the set's class */
    for (k = 0; k < 3u; k++) acc[k] = subd_acc_zero();
    if (pia_cls(s, v) == PIA_CLS_CURVE) {
        uint32_t c[2];
        pia_curve_nbrs(m, v, c);
        d = SUBD_REAL_ONE;
        for (i = 0; i < 2u; i++) {
            subd_real wu = pia_curve_w(s, v, c[i]);
            d = subd_sub(d, wu, &s->ovf);
            if (!x || (upper ? c[i] <= v : c[i] >= v) || pia_cls(s, c[i]) != want) continue;
            for (k = 0; k < 3u; k++) acc[k] = subd_acc_add(acc[k], wu, x[3u * c[i] + k]);
        }
    } else {
        topo_ring r; /* a smooth vertex is interior: no tail */
        topo_ring_begin(&r, m, v);
        for (; topo_ring_step(&r); n++) {
            uint32_t u = r.nb;
            if (!x || (upper ? u <= v : u >= v) || s->cls[u] != want) continue;
            for (k = 0; k < 3u; k++) acc[k] = subd_acc_add(acc[k], s->od[v], x[3u * u + k]);
        }
        d = subd_sub(SUBD_REAL_ONE, subd_mul(subd_from_int((int32_t)n, &s->ovf), s->od[v], &s->ovf), &s->ovf);
    }
    for (k = 0; k < 3u; k++) sum[k] = subd_acc_real(acc[k], &s->ovf);
    return d;
}

/* Forward sweep: z = K^-1 (P - L V) on the set, K = D + Lo (0 elsewhere). */
static void pia_sweep_fwd(pia_state *s, uint32_t set)
{
    const subd_mesh *m = s->m;
    subd_real sum[3], d;
    uint32_t v, k;
    for (v = 0; v < m->num_verts; v++) {
        if (!pia_in_set(s, v, set)) {
            for (k = 3u * v; k < 3u * v + 3u; k++) s->z[k] = 0;
            continue;
        }
        d = pia_half_row(s, set, v, 0, s->z, sum);
        for (k = 0; k < 3u; k++) {
            subd_real r = subd_sub(m->pos[3u * v + k], s->lv[3u * v + k], &s->ovf);
            s->z[3u * v + k] = subd_div(subd_sub(r, sum[k], &s->ovf), d, &s->ovf);
        }
    }
}

/* Backward sweep: q = K'^-1 D z on the set, K' = D + Up (0 elsewhere). */
static void pia_sweep_bwd(pia_state *s, uint32_t set)
{
    const subd_mesh *m = s->m;
    subd_real sum[3], d;
    uint32_t v, k;
    for (v = m->num_verts; v-- > 0u;) {
        if (!pia_in_set(s, v, set)) {
            for (k = 3u * v; k < 3u * v + 3u; k++) s->q[k] = 0;
            continue;
        }
        d = pia_half_row(s, set, v, 1, s->q, sum);
        for (k = 0; k < 3u; k++)
            s->q[3u * v + k] = subd_sub(s->z[3u * v + k], subd_div(sum[k], d, &s->ovf), &s->ovf);
    }
}

/* PCG on the set (all other vertices fixed) with the symmetric Gauss-Seidel preconditioner
 * M = K D^-1 K' (K = D + Lo, K' = D + Up, A = K + K' - D the set's block of L in vertex
 * order), until its max error is <= tol, it stalls, the budget is spent, or a safeguard
 * hands the phase to the paper's step. With pt = K' p, A p = pt + Lo p (Eisenstat), so an
 * iteration costs a forward sweep (Lo), a backward sweep (Up) and Lo p: three halves of an
 * application of L, counted as 1.5 iterations. Exact lv on entry and exit. */
void subd_pia_phase_sgs(pia_state *s, uint32_t set)
{
    const subd_mesh *m = s->m;
    const subd_real *P = m->pos;
    subd_real err, start, best, alpha, beta, sum[3], d;
    pia_dotv rho, rho_new, sigma;
    uint32_t i, k, stall = 0;
    int ok = 1, st;

    err = subd_pia_max_err(s, set);
    if (s->ovf || err <= s->o->tol || !pia_budget(s, 3u)) return;
    start = best = err;
    beta = 0;
    for (i = 0; i < 3u * m->num_verts; i++) s->p[i] = s->pt[i] = 0;
    pia_sweep_fwd(s, set);
    pia_sweep_bwd(s, set);
    rho = subd_pia_dot(s, set, P, s->lv, s->q, 0);
    while (!s->ovf && pia_budget(s, 3u)) {
        /* one ascending pass: p = z + beta p, pt = D y + beta pt (= K' p), q = pt + Lo p
         * (= A p); Lo p at v reads only the p_u, u < v, already updated (q held z) */
        for (i = 0; i < m->num_verts; i++) {
            if (!pia_in_set(s, i, set)) continue;
            d = pia_half_row(s, set, i, 0, s->p, sum);
            for (k = 0; k < 3u; k++) {
                uint32_t j = 3u * i + k;
                subd_acc acc = subd_acc_add(subd_acc_zero(), SUBD_REAL_ONE, s->q[j]);
                s->p[j] = subd_acc_real(subd_acc_add(acc, beta, s->p[j]), &s->ovf);
                acc = subd_acc_add(subd_acc_zero(), d, s->z[j]);
                s->pt[j] = subd_acc_real(subd_acc_add(acc, beta, s->pt[j]), &s->ovf);
                s->q[j] = subd_add(s->pt[j], sum[k], &s->ovf);
            }
        }
        sigma = subd_pia_dot(s, set, s->p, 0, s->q, 0);
        alpha = subd_pia_ratio(rho, sigma, &ok);
        if (!ok || s->ovf) break;
        st = subd_pia_cg_advance(s, set, alpha, 3u, start, &best, &stall);
        if (st == PIA_DONE) return;
        if (st == PIA_SAFEGUARD) {
            ok = 0;
            break;
        }
        pia_sweep_fwd(s, set);
        pia_sweep_bwd(s, set);
        rho_new = subd_pia_dot(s, set, P, s->lv, s->q, 0);
        beta = subd_pia_ratio(rho_new, rho, &ok);
        if (!ok) break;
        rho = rho_new;
    }
    if (s->ovf) return;
    if (!s->lv_true) pia_limit(s);
    if (!ok) subd_pia_phase_paper(s, set);
}

/* 1 when every vertex of the set has the same row shape (CG weight and diagonal of L). */
int subd_pia_uniform(pia_state *s, uint32_t set)
{
    subd_real w0 = 0, d0 = 0, d, sum[3];
    uint32_t v;
    int first = 1;
    for (v = 0; v < s->m->num_verts; v++) {
        if (!pia_in_set(s, v, set)) continue;
        d = pia_half_row(s, set, v, 0, 0, sum);
        if (first) {
            w0 = s->w[v];
            d0 = d;
            first = 0;
        } else if (s->w[v] != w0 || d != d0) {
            return 0;
        }
    }
    return 1;
}
