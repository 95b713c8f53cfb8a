/* SPDX-License-Identifier: MIT */
/* Semi-regular 4-8 refinement: regular 4-8 binary steps as a hierarchy of right triangles
 * (paper: semi-regular-4-8-refinement-box-splines.txt, section 4), the factored
 * four-direction (Zwart-Powell) box-spline smoothing (section 6), planning and the build
 * driver. The pre-processing (section 5) is in sr48_pre.c; the layout is documented in
 * include/subd_sr48.h.
 *
 * Choices where the paper is silent:
 *  - Base neighbours need no adjacency and no scratch: a triangle's leg neighbours are its
 *    sibling and a child of its parent's base neighbour, so level k+1's base neighbours
 *    follow from level k-1's (see subd_sr48_step). Level 0's leg neighbours come from the
 *    hybrid triangles' base neighbours (hnb, pre-processing scratch).
 *  - Smoothing, see subd_sr48_build: a new vertex is the average of the two apexes of its
 *    diamond (a boundary half-diamond: the base midpoint); after every even level (level 0
 *    included), every older vertex moves to the average of the neighbours that level's step
 *    created, a boundary vertex to the average of its two new boundary neighbours. The
 *    older vertices' neighbours are gathered by scattering each new vertex into its
 *    diamond's four vertices (per-vertex sums, Q16.16 exactly in 64 bits). The boundary
 *    vertices of a step are the base ends of its half-diamonds (every boundary edge is a
 *    base at odd levels and of the hybrid level).
 *  - Why this is the ZP scheme (checked by test_sr48): after a double step the step's
 *    valence-4 vertices are 1/2 e + 1/4 e' + 1/4 e'' of the previous valence-4 vertices (the
 *    control net), the corner rule of the ZP dual quad scheme; older vertices never enter
 *    an interior new vertex, so their update only places them on the surface (the
 *    centroid of their new quad block). They do enter the boundary half-diamonds' base
 *    midpoints: with the boundary update that makes the boundary new vertices 3/4 e + 1/4 e'
 *    of the boundary control points (Chaikin, the quadratic B-spline).
 *
 * Memory (sr48_layout): the output arrays, then the largest of: find_clusters' edge
 * numbering and sort (phase A); the hybrid subdivision's per-face and per-hybrid-triangle
 * arrays plus the level-0 smoothing sums (phase B, on top of phase A's edge numbering);
 * the smoothing sums of the largest later even level. The build runs find_clusters twice:
 * once to count the clusters (the output sizes depend on them; same memory as
 * subd_sr48_count_clusters), once above the allocated output.
 */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "sr48_internal.h"
#include "mesh_internal.h"
#include "topo.h"
#include "entry.h"

/* ------------------------------------------------------------------------------------ */
/* Layout and plan                                                                        */

static int sr48_check(const subd_mesh *in, const subd_sr48_opts *o, subd_diag *d)
{
    int st;
    if (!in || !o || o->steps > SUBD_SR48_MAX_STEPS || (o->flags & ~SUBD_SR48_NO_SMOOTH) != 0u)
        return subd_fail(d, SUBD_ERR_PARAM);
    if (!subd_topo_has(in, TOPO_IF_FACES | TOPO_TWIN | TOPO_VERT_OUT | TOPO_CORNER_FACE | TOPO_FACE_START |
                               TOPO_CORNER_VERT | TOPO_POS))
        return subd_fail(d, SUBD_ERR_PARAM);
    if ((st = subd_require_triangles(in, d)) != SUBD_OK) return st;
    if (in->num_faces == 0) return subd_fail(d, SUBD_ERR_EMPTY);
    return SUBD_OK;
}

/* Layouts (layout.h): the smoothing sums of n vertices, and the output arrays. */
static int sums_layout(subd_arena *a, uint32_t n, sr48_sums *s, uint32_t *bytes)
{
    subd_layout l;
    sr48_sums tmp;
    sr48_sums *p = s ? s : &tmp;
    subd_layout_begin(&l, a);
    p->s = subd_layout_take(&l, 3u * n, (uint32_t)sizeof(subd_sum)); /* n < 2^28, checked by the caller */
    p->cnt = subd_layout_take(&l, n, 4u);
    return subd_layout_end(&l, bytes);
}

static uint32_t sums_bytes(uint32_t n)
{
    uint32_t b;
    sums_layout(0, n, 0, &b);
    return b;
}

static int sr48_out_layout(subd_arena *a, const sr48_layout *L, subd_sr48 *h, uint32_t *bytes)
{
    const uint32_t nv = L->level_verts[L->steps], nt = L->level_tri[L->steps + 1u];
    subd_layout l;
    subd_sr48 tmp;
    subd_sr48 *p = h ? h : &tmp;
    subd_layout_begin(&l, a);
    p->pos = subd_layout_take(&l, 3u * nv, (uint32_t)sizeof(subd_real));
    p->tri_vert = subd_layout_take(&l, 3u * nt, 4u);
    p->tri_base_nb = subd_layout_take(&l, nt, 4u);
    p->hyb_base_nb = L->keep ? (uint32_t *)subd_layout_take(&l, L->nhyb, 4u) : 0;
    return subd_layout_end(&l, bytes);
}

/* Counts and bytes; clusters may be SUBD_SR48_CLUSTERS_UNKNOWN (bound: no clusters). */
static int sr48_layout_calc(const subd_mesh *in, const subd_sr48_opts *o, uint32_t clusters, uint32_t keep_hnb,
                            sr48_layout *L, subd_diag *d)
{
    const uint64_t lim = 0x0fffffffu; /* counts below 2^28: 3 * 4 * count fits 32 bits */
    uint64_t c, F, E, B, T, V, tt = 0;
    uint32_t k, b;
    int st;
    if ((st = sr48_check(in, o, d)) != SUBD_OK) return st;
    F = in->num_faces;
    E = in->num_edges;
    B = in->num_boundary_edges;
    c = (clusters == SUBD_SR48_CLUSTERS_UNKNOWN) ? 0u : clusters;
    if (2u * c > F || c > E) return subd_fail(d, SUBD_ERR_PARAM);
    L->steps = o->steps;
    L->keep = keep_hnb;
    L->smooth = (o->flags & SUBD_SR48_NO_SMOOTH) ? 0u : 1u;
    L->nf = (uint32_t)F;
    L->ne = (uint32_t)E;
    L->clusters = (uint32_t)c;
    L->isolated = (uint32_t)(F - 2u * c);
    if (3u * F + E + in->num_verts >= lim) return subd_fail(d, SUBD_ERR_TOO_BIG);
    L->nhyb = (uint32_t)(3u * F - 2u * c);
    L->nv_hyb = (uint32_t)(in->num_verts + F - c);
    T = 2u * (uint64_t)L->nhyb;
    V = (uint64_t)L->nv_hyb + E - c;
    for (k = 0; k <= o->steps; k++) {
        uint64_t db = (k & 1u) ? (2u * B) << (k >> 1) : 0u;
        if (T >= lim || V >= lim || tt + T >= lim || db > T) return subd_fail(d, SUBD_ERR_TOO_BIG);
        L->level_tri[k] = (uint32_t)tt;
        L->level_verts[k] = (uint32_t)V;
        tt += T;
        V += (T - db) / 2u + db;
        T *= 2u;
    }
    L->level_tri[o->steps + 1u] = (uint32_t)tt;
    for (k = o->steps + 1u; k <= SUBD_SR48_MAX_STEPS; k++) L->level_verts[k] = L->level_verts[o->steps];
    for (k = o->steps + 2u; k <= SUBD_SR48_MAX_STEPS + 1u; k++) L->level_tri[k] = (uint32_t)tt;

    sr48_out_layout(0, L, 0, &L->out_bytes);
    {
        uint32_t keep; /* phase A's edge_of, edge_he, sel stay in phase B */
        subd_sr48_pre_alloc_a(0, in, 0, &L->a_bytes, &keep);
        subd_sr48_pre_alloc_b(0, L, 0, &b);
        L->b_bytes = keep;
        subd_bytes_add(&L->b_bytes, b);
        if (L->smooth) subd_bytes_add(&L->b_bytes, sums_bytes(L->nv_hyb));
    }
    L->s_bytes = 0;
    if (L->smooth)
        for (k = 2; k <= o->steps; k += 2u) {
            uint32_t sb = sums_bytes(L->level_verts[k - 1u]);
            if (sb > L->s_bytes) L->s_bytes = sb;
        }
    L->c_bytes = keep_hnb ? subd_s48_census_bytes_(L->level_verts[0], L->level_tri[1]) : 0u;
    L->bytes = L->out_bytes;
    subd_bytes_add(&L->bytes, subd_bytes_max(subd_bytes_max(L->a_bytes, L->c_bytes), subd_bytes_max(L->b_bytes, L->s_bytes)));
    if (L->bytes == UINT32_MAX) return subd_fail(d, SUBD_ERR_TOO_BIG);
    return SUBD_OK;
}

int subd_sr48_plan(const subd_mesh *in, const subd_sr48_opts *o, uint32_t clusters, uint32_t *bytes,
                   subd_diag *diag)
{
    subd_diag own, *d = subd_plan_begin(&own, diag);
    sr48_layout L;
    int st;
    if (!bytes) return subd_plan_end(d, SUBD_ERR_PARAM);
    st = sr48_layout_calc(in, o, clusters, 0, &L, d);
    if (st == SUBD_OK) *bytes = L.bytes;
    return subd_plan_end(d, st);
}

/* Runs find_clusters in the free space and gives it back. */
static int count_in_place(subd_arena *a, const subd_mesh *in, uint32_t *clusters, subd_diag *d)
{
    uint32_t mark = subd_arena_mark(a), need, keep;
    sr48_pre w;
    int st;
    subd_sr48_pre_alloc_a(0, in, 0, &need, &keep);
    if (need > subd_arena_free_bytes(a)) {
        d->bytes_needed = need;
        return subd_fail(d, SUBD_ERR_NOMEM);
    }
    st = subd_sr48_pre_alloc_a(a, in, &w, &need, &keep);
    if (st == SUBD_OK) st = subd_sr48_find_clusters(in, &w, clusters);
    subd_arena_rewind(a, mark);
    if (st != SUBD_OK) return subd_fail(d, st);
    return SUBD_OK;
}

/* The exact layout of a build. The output sizes depend on the cluster count, which only
 * find_clusters gives, so find_clusters runs first in the free arena space (given back)
 * and the layout is then computed with its count. On SUBD_ERR_NOMEM d->bytes_needed is the
 * plan (the bound without clusters when not even find_clusters fits). */
static int sr48_layout_exact(subd_arena *a, const subd_mesh *in, const subd_sr48_opts *o, uint32_t keep_hnb,
                             sr48_layout *L, subd_diag *d)
{
    uint32_t clusters;
    int st;
    if ((st = sr48_layout_calc(in, o, SUBD_SR48_CLUSTERS_UNKNOWN, keep_hnb, L, d)) != SUBD_OK) return st;
    if (L->a_bytes > subd_arena_free_bytes(a)) {
        d->bytes_needed = L->bytes; /* the bound: not even the cluster count fits */
        return subd_fail(d, SUBD_ERR_NOMEM);
    }
    if ((st = count_in_place(a, in, &clusters, d)) != SUBD_OK) return st;
    if ((st = sr48_layout_calc(in, o, clusters, keep_hnb, L, d)) != SUBD_OK) return st;
    d->bytes_needed = L->bytes;
    if (L->bytes > subd_arena_free_bytes(a)) return subd_fail(d, SUBD_ERR_NOMEM);
    return SUBD_OK;
}

int subd_sr48_count_clusters(subd_arena *a, const subd_mesh *in, uint32_t *clusters, subd_diag *diag)
{
    subd_entry e;
    subd_diag *d = subd_entry_begin(&e, a, diag);
    subd_sr48_opts o;
    sr48_layout L;
    uint32_t n;
    int st;
    if (!a || !clusters) return subd_entry_fail(&e, SUBD_ERR_PARAM);
    o.steps = 0;
    o.flags = 0;
    if ((st = sr48_layout_calc(in, &o, SUBD_SR48_CLUSTERS_UNKNOWN, 0, &L, d)) != SUBD_OK) return subd_entry_fail(&e, st);
    if ((st = count_in_place(a, in, &n, d)) != SUBD_OK) return subd_entry_fail(&e, st);
    *clusters = n;
    return subd_entry_ok(&e);
}

/* ------------------------------------------------------------------------------------ */
/* Section 4: one binary step                                                             */

/* Level k -> k+1. Triangle t = (c; a, b), the i-th of level k, is child j = i & 1 of the
 * i/2-th triangle P of level k-1, whose base neighbour is N (pnb). t's children are
 * (m; c, a) and (m; b, c), m the new vertex of t's diamond. t's legs are c-a (leg 0) and
 * b-c (leg 1). Since P = (c'; a', b') has children (c; c', a') and (c; b', c'):
 *   j = 0: across leg 0 (c-c') is the sibling t+1, across leg 1 (a'-c) child 1 of N;
 *   j = 1: across leg 0 (c-b') child 0 of N, across leg 1 (c'-c) the sibling t-1.
 * A leg of t is a leg of the neighbour L across it too, the other one (both have the newest
 * vertex c as apex), and each child's base is one of t's legs, so
 *   base_nb(child 0 of t) = child 1 of L0, base_nb(child 1 of t) = child 0 of L1,
 * SUBD_NONE across the boundary (N == SUBD_NONE). */
int subd_sr48_step(subd_sr48 *h, uint32_t k, const uint32_t *pnb, uint32_t pbase, int smooth)
{
    const uint32_t t0 = h->level_tri[k], n = h->level_tri[k + 1u] - t0, cb = h->level_tri[k + 1u];
    const uint32_t cap = h->level_verts[k + 1u];
    uint32_t i, next = h->level_verts[k], q, ovf = 0;
    uint32_t *tv = h->tri_vert, *base_nb = h->tri_base_nb;
    subd_real *pos = h->pos;
    for (i = 0; i < n; i++) {
        const uint32_t t = t0 + i, c = tv[3u * t], a = tv[3u * t + 1u], b = tv[3u * t + 2u], nb = base_nb[t];
        const uint32_t ch = cb + 2u * i, pn = pnb[i >> 1];
        uint32_t m, nrel;
        if (nb == SUBD_NONE || nb > t) {
            if (next >= cap) return SUBD_ERR_PARAM; /* inconsistent input summary */
            m = next++;
            if (nb != SUBD_NONE && smooth) {
                const uint32_t c2 = tv[3u * nb];
                for (q = 0; q < 3u; q++) pos[3u * m + q] = subd_mid(pos[3u * c + q], pos[3u * c2 + q], &ovf);
            } else {
                for (q = 0; q < 3u; q++) pos[3u * m + q] = subd_mid(pos[3u * a + q], pos[3u * b + q], &ovf);
            }
        } else {
            m = tv[3u * (cb + 2u * (nb - t0))];
        }
        tv[3u * ch] = m;
        tv[3u * ch + 1u] = c;
        tv[3u * ch + 2u] = a;
        tv[3u * ch + 3u] = m;
        tv[3u * ch + 4u] = b;
        tv[3u * ch + 5u] = c;
        nrel = (pn == SUBD_NONE) ? SUBD_NONE : pn - pbase; /* N, index within level k-1 */
        if ((i & 1u) == 0u) {
            base_nb[ch] = cb + 2u * (i + 1u) + 1u;
            base_nb[ch + 1u] = (nrel == SUBD_NONE) ? SUBD_NONE : cb + 2u * (2u * nrel + 1u);
        } else {
            base_nb[ch] = (nrel == SUBD_NONE) ? SUBD_NONE : cb + 2u * (2u * nrel) + 1u;
            base_nb[ch + 1u] = cb + 2u * (i - 1u);
        }
    }
    if (next != cap) return SUBD_ERR_PARAM;
    return ovf ? SUBD_ERR_RANGE : SUBD_OK;
}

/* ------------------------------------------------------------------------------------ */
/* Section 6: the double-step update of older vertices                                    */

static void scatter(const sr48_sums *s, uint32_t v, const subd_real *p, int boundary_ok)
{
    uint32_t q;
    if ((s->cnt[v] & SR48_BFLAG) && !boundary_ok) return;
    for (q = 0; q < 3u; q++) s->s[3u * v + q] = subd_sum_add(s->s[3u * v + q], p[q]);
    s->cnt[v]++;
}

int subd_sr48_smooth(subd_sr48 *h, uint32_t k, const uint32_t *pnb, uint32_t pbase, uint32_t nold, const sr48_sums *s)
{
    const uint32_t cb = h->level_tri[k], np = (h->level_tri[k + 1u] - cb) / 2u;
    const uint32_t *tv = h->tri_vert;
    uint32_t i, v, q, ovf = 0;
    subd_real *pos = h->pos;
    for (v = 0; v < nold; v++) {
        s->cnt[v] = 0;
        for (q = 0; q < 3u; q++) s->s[3u * v + q] = 0;
    }
    /* parent i of level k-1 = (c; a, b): child 0 = (m; c, a), child 1 = (m; b, c) */
    for (i = 0; i < np; i++) {
        if (pnb[i] != SUBD_NONE) continue;
        s->cnt[tv[3u * (cb + 2u * i) + 2u]] = SR48_BFLAG;
        s->cnt[tv[3u * (cb + 2u * i + 1u) + 1u]] = SR48_BFLAG;
    }
    for (i = 0; i < np; i++) {
        const uint32_t *c0 = tv + 3u * (cb + 2u * i), *c1 = c0 + 3u;
        const subd_real *pm = pos + 3u * c0[0];
        uint32_t nrel = (pnb[i] == SUBD_NONE) ? SUBD_NONE : pnb[i] - pbase;
        if (nrel == SUBD_NONE) {
            scatter(s, c0[2], pm, 1);
            scatter(s, c1[1], pm, 1);
            scatter(s, c0[1], pm, 0);
        } else if (i < nrel) {
            scatter(s, c0[2], pm, 0);
            scatter(s, c1[1], pm, 0);
            scatter(s, c0[1], pm, 0);
            scatter(s, tv[3u * (cb + 2u * nrel) + 1u], pm, 0);
        }
    }
    for (v = 0; v < nold; v++) {
        uint32_t n = s->cnt[v] & ~SR48_BFLAG;
        if (n == 0) continue;
        for (q = 0; q < 3u; q++) pos[3u * v + q] = subd_avg(s->s[3u * v + q], n, &ovf);
    }
    return ovf ? SUBD_ERR_RANGE : SUBD_OK;
}

/* ------------------------------------------------------------------------------------ */

static int sr48_build_impl(subd_arena *a, const subd_mesh *in, const subd_sr48_opts *o, uint32_t keep_hnb, subd_sr48 *out,
                           subd_diag *diag)
{
    subd_entry e;
    subd_diag *d = subd_entry_begin(&e, a, diag);
    sr48_layout L;
    sr48_pre w;
    sr48_sums sums;
    subd_sr48 h;
    uint32_t bytes, k, cl2, base, keep, tmp;
    int st;

    if (!a || !out) return subd_entry_fail(&e, SUBD_ERR_PARAM);
    if ((st = sr48_layout_exact(a, in, o, keep_hnb, &L, d)) != SUBD_OK) return subd_entry_fail(&e, st);

    h.steps = o->steps;
    h.flags = o->flags;
    h.num_input_verts = in->num_verts;
    h.num_verts = L.level_verts[o->steps];
    h.num_tris = L.level_tri[o->steps + 1u];
    for (k = 0; k <= SUBD_SR48_MAX_STEPS; k++) h.level_verts[k] = L.level_verts[k];
    for (k = 0; k <= SUBD_SR48_MAX_STEPS + 1u; k++) h.level_tri[k] = L.level_tri[k];
    h.num_clusters = L.clusters;
    h.num_isolated = L.isolated;
    h.stream_valence = 0;
    if ((st = sr48_out_layout(a, &L, &h, &bytes)) != SUBD_OK) return subd_entry_fail(&e, st);

    /* pre-processing: phase A (find_clusters again, above the output), phase B */
    base = subd_arena_mark(a);
    st = subd_sr48_pre_alloc_a(a, in, &w, &tmp, &keep);
    if (st == SUBD_OK) st = subd_sr48_find_clusters(in, &w, &cl2);
    if (st == SUBD_OK && cl2 != L.clusters) st = SUBD_ERR_PARAM;
    if (st != SUBD_OK) return subd_entry_fail(&e, st);
    subd_arena_rewind(a, base + keep);
    st = subd_sr48_pre_alloc_b(a, &L, &w, &tmp);
    if (st == SUBD_OK && L.smooth) st = sums_layout(a, L.nv_hyb, &sums, &tmp);
    if (st == SUBD_OK) st = subd_sr48_level0(in, &L, &w, &h);
    if (st == SUBD_OK && L.smooth) st = subd_sr48_smooth(&h, 0, w.hnb, 0, L.nv_hyb, &sums);
    if (st == SUBD_OK && keep_hnb)
        for (k = 0; k < L.nhyb; k++) h.hyb_base_nb[k] = w.hnb[k]; /* the base keeps level -1's neighbours */
    if (st == SUBD_OK && o->steps >= 1u) st = subd_sr48_step(&h, 0, w.hnb, 0, (int)L.smooth);
    if (st != SUBD_OK) return subd_entry_fail(&e, st);
    subd_arena_rewind(a, base);
    if (keep_hnb) { /* the base mesh: the census of its level-0 windows, for the stream */
        h.stream_valence = subd_s48_census_(a, &h);
        subd_arena_rewind(a, base);
    }

    /* binary steps 1 .. steps-1 (step k makes level k+1), smoothing after even levels */
    for (k = 1; k < o->steps; k++) {
        const uint32_t p0 = L.level_tri[k - 1u], p1 = L.level_tri[k];
        st = subd_sr48_step(&h, k, h.tri_base_nb + p0, p0, (int)L.smooth);
        if (st == SUBD_OK && L.smooth && ((k + 1u) & 1u) == 0u) {
            st = sums_layout(a, L.level_verts[k], &sums, &tmp);
            if (st == SUBD_OK) st = subd_sr48_smooth(&h, k + 1u, h.tri_base_nb + p1, p1, L.level_verts[k], &sums);
            subd_arena_rewind(a, base);
        }
        if (st != SUBD_OK) return subd_entry_fail(&e, st);
    }
    *out = h;
    return subd_entry_ok(&e);
}

int subd_sr48_build(subd_arena *a, const subd_mesh *in, const subd_sr48_opts *o, subd_sr48 *out, subd_diag *diag)
{
    return sr48_build_impl(a, in, o, 0, out, diag);
}

/* The base mesh: a build with steps = 0 that keeps the hybrid level's base neighbours. */
static int sr48_base_opts(const uint32_t *flags, subd_sr48_opts *o)
{
    if (!flags) return SUBD_ERR_PARAM;
    o->steps = 0;
    o->flags = *flags;
    return SUBD_OK;
}

int subd_sr48_base_plan(const subd_mesh *in, uint32_t flags, uint32_t clusters, uint32_t *bytes)
{
    sr48_layout L;
    subd_sr48_opts o;
    subd_diag d;
    int st;
    subd_diag_clear(&d);
    if (!bytes) return SUBD_ERR_PARAM;
    (void)sr48_base_opts(&flags, &o);
    st = sr48_layout_calc(in, &o, clusters, 1u, &L, &d);
    if (st == SUBD_OK) *bytes = L.bytes;
    return st;
}

int subd_sr48_base(subd_arena *a, const subd_mesh *in, uint32_t flags, subd_sr48 *out, subd_diag *diag)
{
    subd_sr48_opts o;
    (void)sr48_base_opts(&flags, &o);
    return sr48_build_impl(a, in, &o, 1u, out, diag);
}
