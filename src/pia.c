/* SPDX-License-Identifier: MIT */
/* Progressive interpolation with Loop subdivision surfaces.
 *
 * Paper: F. Cheng, F. Fan, S. Lai, C. Huang, J. Wang, J. Yong, "Loop subdivision surface
 * based progressive interpolation" (../shared/papers/loop-progressive-interpolation.txt),
 * sections 2-4.
 *
 * Given the vertices P of a triangle mesh, find control points V with the same topology
 * whose Loop limit positions L V are P. L is the limit-position operator
 * (subd_loop_limit_apply, loop_limit.c): formula (3) at smooth vertices (and darts), the
 * six boundary masks of section 4 (or the B-spline mask 1/6, 2/3, 1/6) on boundaries and
 * creases, identity at corners and isolated vertices.
 *
 * SUBD_PIA_PAPER: the paper's method (section 2, formulas (1) and (2)):
 *     V^0 = P,   D^k = P - L V^k,   V^{k+1} = V^k + D^k          (pia_step_paper)
 * Section 3: D^{k+1} = (I - B) D^k with B = D S (D diagonal positive, S symmetric positive
 * definite), so B's eigenvalues are in (0, 1] (theorem 2) and the error shrinks by
 * max |1 - lambda| per iteration. Section 4, open meshes: a boundary vertex's limit depends
 * only on boundary vertices, so the boundary is interpolated first (phase 1: only vertices
 * tagged SUBD_VTAG_BOUNDARY move, until their error is <= tol), then the interior with the
 * boundary fixed (phase 2: the other vertices move, until their error is <= tol). A closed
 * mesh has only phase 2.
 *
 * Choices where the paper is silent (also in include/subd_loop.h):
 *   - The error of a vertex is the Euclidean distance |P_i - (L V)_i| in input units;
 *     max_err and mean_err are over all vertices (corners and isolated vertices, whose
 *     limit is the control point itself, have error 0).
 *   - One iteration is one update of V. `iterations` counts the updates of all phases and
 *     max_iter bounds that total (a later phase gets what the earlier ones leave). One tol
 *     ends every phase, as in the paper's section 5.
 *   - Crease vertices (curve rules) and interior corners are "interior" for the paper's
 *     sequencing and move in phase 2. Without darts their limits depend only on crease and
 *     corner vertices, so phase 2's matrix is block triangular (corners, crease curves,
 *     smooth vertices) and its eigenvalues, those of the blocks, are in (0, 1].
 *   - Phase 2 runs even if phase 1 stopped above tol (stall guard below): the interior is
 *     still interpolated as well as it can be, and converged = 0.
 *   - Stall guard: a phase stops (not converged) when its max error has not reached a new
 *     minimum for PIA_STALL consecutive iterations. In exact arithmetic the error decreases
 *     geometrically, so this ends only runs that sit at the rounding floor (or whose
 *     assumptions fail); max_iter still bounds everything.
 *
 * SUBD_PIA_FAST, beyond the paper: conjugate gradients phase by phase, preconditioned by
 * symmetric Gauss-Seidel, or Chebyshev semi-iteration when darts couple the phases, with
 * safeguards that hand a phase back to the paper's step: src/pia_fast.c, whose header has
 * the convergence argument. This file holds what both methods share (validation, the one
 * layout, errors, the paper's step, the result) and the driver.
 *
 * Arithmetic. Q16.16: L rounds each coordinate of each limit point once (1/2 LSB), P - L V
 * is an exact integer, and FAST's updates round again, so the floor an iteration can reach is
 * about 1 LSB per coordinate: sqrt(3) = 1.73 LSB in the Euclidean norm. The smallest tol
 * accepted is therefore PIA_TOL_MIN_LSB = 2 LSB (2^-15, > sqrt(3)); anything below is
 * SUBD_ERR_PARAM, not an endless loop. 2 LSB was reached by both methods on every test and
 * bench mesh, coordinates up to 8000 included; should a run sit at the floor above tol, the
 * stall guard ends it (converged = 0). The CG dot products are summed exactly in 128 bits
 * from components scaled to 21 bits and weights in 8.8 fixed point, and their ratios come
 * from an integer division, so the fixed build uses no float. Any saturation sets the
 * overflow flag and the call fails with SUBD_ERR_RANGE. Float32: tol must be positive and
 * finite; the floor is a few ulps of the coordinates (the stall guard ends runs below it),
 * and squared distances must stay finite (coordinates below about 1e18, else RANGE).
 *
 * Memory (exact plan): V (the output, 3 subd_reals per vertex) and L V (same); FAST adds
 * the search direction p, q = L p, pt = K' p and the sweep vector z (same), two weights per
 * vertex (the CG weight w and chi, subd_reals) and one class byte per vertex. On success
 * only V stays in the arena. Stack (-fstack-usage, -O2):
 * under 850 bytes on the deepest path (Cortex-M3, Q16.16: subd_pia 232, subd_pia_fast 8,
 * pia_phase_sym 216 with the inlined CG and SGS phases, pia_sweep_fwd 96, pia_half_row 136:
 * 688), and subd_pia, subd_pia_fast, pia_phase_sym plus subd_loop_limit_apply's
 * (pia_classify and pia_phase_cheb are kept out of line, off that path). Work per iteration: one application of L, O(corners), plus
 * O(vertices); an SGS step does 1.5 applications' worth (three half-row passes).
 */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "entry.h"
#include "layout.h"
#include "mesh_internal.h"
#include "real_avg.h"
#include "loop_rules.h"
#include "pia_internal.h"

/* ------------------------------------------------------------------------------------ */
/* Validation and layout                                                                  */

static int pia_tol_ok(subd_real tol)
{
#if SUBD_FIXED /* why: Q16.16 has a floor of about 1.73 LSB, below which tol cannot be met */
    return tol >= PIA_TOL_MIN_LSB;
#else
    return subd_real_is_finite(tol) && tol > 0.0f;
#endif
}

/* PARAM (pointers, options, a mesh without adjacency), then NOT_TRIANGLES (diag.face). */
static int pia_check(const subd_mesh *in, const subd_pia_opts *o, subd_diag *d)
{
    if (!o || !subd_topo_has(in, TOPO_ALWAYS | TOPO_POS | TOPO_FACE_START | TOPO_CORNER_VERT | TOPO_CORNER_FACE |
                                     TOPO_TWIN | TOPO_VERT_OUT | TOPO_VERT_TAG | TOPO_EDGE_TAG) ||
        in->num_verts == 0u)
        return subd_fail(d, SUBD_ERR_PARAM);
    if ((o->boundary != SUBD_LOOP_BOUNDARY_PAPER && o->boundary != SUBD_LOOP_BOUNDARY_BSPLINE) ||
        (o->method != SUBD_PIA_PAPER && o->method != SUBD_PIA_FAST) || o->max_iter == 0u ||
        !pia_tol_ok(o->tol))
        return subd_fail(d, SUBD_ERR_PARAM);
    if (subd_loop_tags_public(in, d) != SUBD_OK) return subd_fail(d, SUBD_ERR_PARAM);
    return subd_require_triangles(in, d);
}

/* The one layout (layout.h's walk: counts with a == NULL, carves otherwise): V, L V, and
 * for FAST p, q, pt, z, w, od, cls. *keep = the bytes of V, the part that stays. */
static int pia_layout(subd_arena *a, const subd_mesh *in, const subd_pia_opts *o, pia_state *s, uint32_t *keep,
                      uint32_t *bytes)
{
    subd_layout l;
    uint32_t nv = in->num_verts, vb = 3u * (uint32_t)sizeof(subd_real);
    int fast = o->method == SUBD_PIA_FAST;
    subd_layout_begin(&l, a);
    s->v = subd_layout_take(&l, nv, vb);
    (void)subd_layout_end(&l, keep);
    s->lv = subd_layout_take(&l, nv, vb);
    s->p = fast ? subd_layout_take(&l, nv, vb) : 0;
    s->q = fast ? subd_layout_take(&l, nv, vb) : 0;
    s->pt = fast ? subd_layout_take(&l, nv, vb) : 0;
    s->z = fast ? subd_layout_take(&l, nv, vb) : 0;
    s->w = fast ? subd_layout_take(&l, nv, (uint32_t)sizeof(subd_real)) : 0;
    s->od = fast ? subd_layout_take(&l, nv, (uint32_t)sizeof(subd_real)) : 0;
    s->cls = fast ? subd_layout_take(&l, nv, 1u) : 0;
    return subd_layout_end(&l, bytes);
}

int subd_pia_plan(const subd_mesh *in, const subd_pia_opts *o, uint32_t *bytes, subd_diag *diag)
{
    subd_diag own, *d = subd_plan_begin(&own, diag);
    pia_state s;
    uint32_t keep;
    int st;
    if (!bytes) return subd_plan_end(d, SUBD_ERR_PARAM);
    if ((st = pia_check(in, o, d)) != SUBD_OK) return subd_plan_end(d, st);
    return subd_plan_end(d, pia_layout(0, in, o, &s, &keep, bytes));
}

/* ------------------------------------------------------------------------------------ */
/* Sets, errors, L                                                                        */

/* Max over the set of |P - L V| (with the current lv). */
subd_real subd_pia_max_err(pia_state *s, uint32_t set)
{
    const subd_mesh *m = s->m;
    pia_sq best = 0, e;
    uint32_t i;
    for (i = 0; i < m->num_verts; i++) {
        if (!pia_in_set(s, i, set)) continue;
        e = subd_w3_dist2(&m->pos[3u * i], &s->lv[3u * i], &s->ovf);
        if (e > best) best = e;
    }
    return subd_w3_dist_root(best, &s->ovf);
}

/* ------------------------------------------------------------------------------------ */
/* The paper's iteration                                                                  */

/* Update (2) on the set: V += P - L V. */
static void pia_step_paper(pia_state *s, uint32_t set)
{
    const subd_mesh *m = s->m;
    uint32_t i, k;
    for (i = 0; i < m->num_verts; i++) {
        if (!pia_in_set(s, i, set)) continue;
        for (k = 3u * i; k < 3u * i + 3u; k++)
            s->v[k] = subd_add(s->v[k], subd_sub(m->pos[k], s->lv[k], &s->ovf), &s->ovf);
    }
}

/* Tracks a phase's progress: records err of iteration k and returns 1 once the error has
 * not reached a new minimum for PIA_STALL iterations (the rounding floor: not converged). */
int subd_pia_stalled(subd_real err, uint32_t k, subd_real *best, uint32_t *stall)
{
    if (k == 0u || err < *best) {
        *best = err;
        *stall = 0;
        return 0;
    }
    return ++*stall >= PIA_STALL;
}

/* Runs the paper's iteration on the set until its max error is <= tol, it stalls, or the
 * budget is spent. Needs an exact lv on entry and leaves one. */
void subd_pia_phase_paper(pia_state *s, uint32_t set)
{
    subd_real err, best = 0;
    uint32_t stall = 0, k;
    for (k = 0;; k++) {
        err = subd_pia_max_err(s, set);
        if (s->ovf || err <= s->o->tol || subd_pia_stalled(err, k, &best, &stall)) return;
        if (!pia_budget(s, 2u)) return;
        pia_step_paper(s, set);
        s->half += 2u;
        pia_limit(s);
        if (s->ovf) return;
    }
}

/* ------------------------------------------------------------------------------------ */

int subd_pia(subd_arena *a, const subd_mesh *in, const subd_pia_opts *o, subd_real **pos,
             subd_pia_result *result, subd_diag *diag)
{
    subd_entry e;
    subd_diag *d = subd_entry_begin(&e, a, diag);
    pia_state s;
    subd_pia_result res;
    uint32_t keep, bytes, i;
    int st;

    if (!a || !pos || !result) return subd_entry_fail(&e, SUBD_ERR_PARAM);
    if ((st = pia_check(in, o, d)) != SUBD_OK) return subd_entry_fail(&e, st);
    if ((st = pia_layout(0, in, o, &s, &keep, &bytes)) != SUBD_OK) return subd_entry_fail(&e, st);
    if (bytes > subd_arena_free_bytes(a)) { /* checked first: nothing is taken on failure */
        d->bytes_needed = bytes;
        return subd_entry_fail(&e, SUBD_ERR_NOMEM);
    }
    (void)pia_layout(a, in, o, &s, &keep, 0); /* cannot fail: it fits */
    s.m = in;
    s.o = o;
    s.half = 0;
    s.ovf = 0;
    s.lv_true = 0;

    for (i = 0; i < 3u * in->num_verts; i++) s.v[i] = in->pos[i]; /* V^0 = P */
    pia_limit(&s);
    s.half_bnd = 0;
    if (o->method == SUBD_PIA_FAST) {
        subd_pia_fast(&s);
    } else {
        if (in->num_boundary_edges > 0u) subd_pia_phase_paper(&s, PIA_SET_BOUNDARY);
        s.half_bnd = s.half;
        if (!s.ovf) subd_pia_phase_paper(&s, PIA_SET_INTERIOR);
    }

    /* final statistics over all vertices and per phase set, from the exact L V of the
     * returned V */
    if (!s.ovf) {
        subd_sum sum = 0, part[2] = {0, 0};
        uint32_t cnt[2] = {0, 0};
        res.max_err = subd_pia_max_err(&s, PIA_SET_ALL);
        res.boundary.max_err = subd_pia_max_err(&s, PIA_SET_BOUNDARY);
        res.interior.max_err = subd_pia_max_err(&s, PIA_SET_INTERIOR);
        for (i = 0; i < in->num_verts; i++) {
            subd_real ei = subd_w3_dist_root(subd_w3_dist2(&in->pos[3u * i], &s.lv[3u * i], &s.ovf), &s.ovf);
            uint32_t j = (in->vert_tag[i] & SUBD_VTAG_BOUNDARY) ? 0u : 1u;
            sum = subd_sum_add(sum, ei);
            part[j] = subd_sum_add(part[j], ei);
            cnt[j]++;
        }
        res.mean_err = subd_avg(sum, in->num_verts, &s.ovf); /* num_verts >= 1 (pia_check) */
        res.boundary.verts = cnt[0];
        res.interior.verts = cnt[1];
        res.boundary.mean_err = cnt[0] ? subd_avg(part[0], cnt[0], &s.ovf) : 0;
        res.interior.mean_err = cnt[1] ? subd_avg(part[1], cnt[1], &s.ovf) : 0;
        res.iterations = (uint32_t)((s.half + 1u) / 2u); /* <= max_iter (pia_budget) */
        res.boundary.iterations = (uint32_t)((s.half_bnd + 1u) / 2u);
        res.interior.iterations = res.iterations - res.boundary.iterations;
        res.converged = res.max_err <= o->tol;
    }
    if (s.ovf) return subd_entry_fail(&e, SUBD_ERR_RANGE);
    subd_arena_rewind(a, e.mark + keep); /* give back everything but V */
    *pos = s.v;
    *result = res;
    return subd_entry_ok(&e);
}

void subd_pia_opts_default(subd_pia_opts *o)
{
    if (!o) return;
    o->boundary = SUBD_LOOP_BOUNDARY_PAPER;
    o->tol = SUBD_REAL_FRAC(2, 65536); /* 2^-15: the smallest tolerance Q16.16 resolves */
    o->max_iter = 100;
    o->method = SUBD_PIA_PAPER;
}
