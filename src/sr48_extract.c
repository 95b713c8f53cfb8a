/* SPDX-License-Identifier: MIT */
/* Variable-resolution extraction from the semi-regular 4-8 hierarchy of right triangles.
 * Length (~870 lines): two concepts that should be two files, the adaptation geometry (the
 * nested star box, POINT/RAMP/PLANE/CALLBACK tests, the chordal walk; its test is in
 * sr48_chord.c) and the cut (marks,
 * forced splits, output); the split is open work (issue 19, item 7), kept together this
 * release because the stream shares the box test through sr48_internal.h.
 *
 * Paper: L. Velho, "Semi-regular 4-8 refinement and box spline surfaces"
 * (semi-regular-4-8-refinement-box-splines.txt), section 3 (adaptive tilings: a basic block
 * - a diamond - is split as a whole, and splitting an external edge of a block forces the
 * neighbouring block to split: the restricted hierarchy) and section 7 (figure 20:
 * tessellations extracted by point location, a linear ramp and a step across a plane).
 * Beyond the paper: a chordal tolerance (CHORD) and a caller callback.
 *
 * How the cut is computed (the least conforming refinement that honours every request):
 *  - a triangle is "active" when it belongs to the current cut (level 0, or its parent is
 *    split). Splitting a diamond needs both of its triangles active, so force_split first
 *    splits the diamonds of their parents, coarser and coarser, with an explicit stack in
 *    the arena (each entry is one level coarser than the one below it, so its depth is at
 *    most max_level);
 *  - a FIFO worklist holds every triangle of level < max_level that becomes active (each
 *    exactly once: a triangle becomes active when its parent's diamond splits), including
 *    the ones activated by forced splits; each is evaluated against the adaptation function
 *    once and, when it asks for a split, force_split splits it. The result is the least
 *    fixpoint, so it does not depend on the processing order.
 *  - one mark byte per triangle of level < max_level: SPLIT, WANT (the adaptation
 *    function asked for the split), so forced_splits counts the diamonds neither of whose
 *    triangles wanted the split, and OK (its index rules were checked);
 *  - the output faces are the cut's leaves, found by a stackless depth-first walk of the
 *    split triangles from level 0 (ex_next_leaf); it yields each level's leaves in index
 *    order, so each face is written straight to its place "by level, then by index".
 *
 * Cost: the adaptive modes touch only the triangles they visit (level 0, the active ones,
 * the coarser ones forced splits reach, CHORD's walked subtrees, the output faces), and
 * validate each the first time it is touched, before any of its indices is read (ex_ok),
 * instead of checking the whole hierarchy up front. What remains proportional to the
 * hierarchy is streaming: clearing the mark bytes, the per-vertex used flags and
 * renumbering, and, for RAMP and POINT's default radius only, the bounding box. UNIFORM
 * outputs all of level max, so it checks levels 0..max up front.
 *
 * Adaptation functions. POINT, RAMP and PLANE are evaluated on a nested region, so that
 * a top-down decision without lookahead (subd_sr48_stream) gives the same cut:
 *  - L is the piecewise-linear interpolant of the level-0 mesh at its vertices' finest
 *    positions: L at a level-0 vertex is its position, L at a vertex created by splitting a
 *    diamond is the midpoint (subd_mid) of L at its base ends (the parameter midpoint;
 *    commutative, so every triangle that has the vertex computes the same L);
 *  - the region of a diamond D of level k is B(D), the bounding box of L over the corners
 *    of every level-k triangle that shares a vertex with D (its "star", walked fan by fan;
 *    a leg neighbour is the parent of the base neighbour of the child whose base is that
 *    leg, so no adjacency is stored);
 *  - nesting: a child diamond D' = {c, c'} of level k+1 (c a child of p, c' of p', p and
 *    p' sharing the leg that is c's base) touches only m, m' (the new vertices of D(p),
 *    D(p')) and the ends of that leg, so its star lies in the children of the stars of
 *    D(p) and of D(p'); corners of children are corners or base midpoints of their
 *    parents and a midpoint lies between its ends in both arithmetics, so
 *    B(D') is inside B(D(p)) and B(D(p')). Each predicate below is monotone in the box
 *    and in the level (a coarser level asks for no less), so a diamond that asks for a
 *    split has parent diamonds that ask too: the least conforming cut has no forced
 *    split, it is exactly {D : pred(B(D), level of D)}, evaluable top-down;
 *  - POINT: split a level-k diamond iff dist(point, B) < (max_level - k) * radius
 *    (compared as squares; Q16.16 floors the per-axis distances and the limit by one
 *    common shift to below 2^30 so the squares sum in int64);
 *  - RAMP: split iff (k + 1)(hi - lo) <= max_level (x - lo), x = B's maximum on the axis;
 *    Q16.16 exact;
 *  - PLANE: split iff the corner of B furthest along the normal has (q - point).normal
 *    >= 0; Q16.16: exact sign (the three 64-bit products are summed as high and low 32-bit
 *    halves, vec3w.h).
 *  The star costs O(4 valence) triangles of O(k) each (L down the child path) per
 *  evaluation. CALLBACK and CHORD are not nested (forced splits may occur):
 *  - CALLBACK: fn(ctx, the triangle's apex, b0, b1 finest positions) > k;
 *  - CHORD: the chordal deviation of t is the largest |P(v) - L_t(v)| over the vertices v
 *    of t's subtree down to level max_level (the "finest level" of this extraction; deeper
 *    vertices cannot be honoured, max_level triangles are never split), L_t the linear
 *    interpolation of t's corners at v's dyadic parameter. The subtree is walked depth
 *    first with an explicit arena stack carrying L at the three corners of each node: the
 *    parameter of a split vertex is the midpoint of its node's base, so L there is the
 *    average of L at the base ends (Q16.16: L is kept in Q32.32, so 16 halvings are exact).
 *    The walk stops at the first vertex beyond eps; only active triangles are walked, so
 *    the work is O(faces of level max_level * levels) at most.
 *  The bounding box (RAMP, POINT's default radius) is that of the vertices of levels
 *  0..max_level.
 *
 * Memory (one layout function for plan and run): phase 1 allocates the marks, the worklist
 * (reused afterwards as per-vertex "used" flags to count the output vertices), the
 * force-split stack and, for CHORD, the deviation stack. Phase 2 keeps the marks, puts the
 * output mesh arrays (exact counts) above them and a vertex renumbering map above those,
 * fills the mesh, gives the map back and moves the arrays down over the marks, so the
 * result occupies exactly its own bytes; then subd_mesh_finish validates it and builds the
 * adjacency in scratch above the arrays. The bytes needed are
 *   max(phase 1, marks + mesh arrays + max(map, builder scratch)),
 * which the plan bounds with the uniform max_level counts (and which is exact for UNIFORM,
 * where there are no marks, whenever every input vertex is used by a face).
 */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "mesh_internal.h"
#include "subd_sr48.h"
#include "layout.h"
#include "entry.h"
#include "vec3w.h"
#include "sr48_internal.h"

#define EX_SPLIT 0x1u
#define EX_WANT 0x2u
#define EX_OK 0x4u /* ex_check_tri passed (lazy validation, see ex_ok) */

/* A node of the chordal-deviation walk: the triangle, its level and the linear
 * interpolant of the walk's root at its three corners (apex, b0, b1). The arena reserves
 * EX_CNODE_BYTES per node in both arithmetics so the plan does not depend on the build. */
typedef subd_sr48_lin ex_lin; /* sr48_internal.h: Q32.32 in Q16.16 */
typedef struct ex_cnode {
    uint32_t tri, level;
    ex_lin l[9];
} ex_cnode;
#define EX_CNODE_BYTES 80u
typedef char ex_cnode_fits[(sizeof(ex_cnode) <= EX_CNODE_BYTES) ? 1 : -1];

typedef struct ex_layout {
    uint32_t max;          /* max_level                                                 */
    uint32_t uniform;      /* mode UNIFORM: no marks, no worklist                        */
    uint32_t ntri;         /* triangles of levels < max (marks, worklist)               */
    uint32_t nvert;        /* vertices of levels <= max                                 */
    uint32_t marks;        /* aligned bytes of the marks (kept during phase 2)          */
    uint32_t phase1;       /* bytes of phase 1                                          */
    uint32_t vmap;         /* aligned bytes of the renumbering map                      */
} ex_layout;

typedef struct ex_ctx {
    const subd_sr48 *h;
    const subd_sr48_adapt *ad;
    uint32_t max, uniform;
    uint8_t *mark;
    uint32_t *work;    /* worklist, then per-vertex used flags                          */
    uint32_t *fstack;  /* force_split stack, max + 1 entries                            */
    ex_cnode *cstack;  /* CHORD walk stack, max + 1 entries                             */
    uint32_t qtail;
    uint32_t forced;
    int bad;           /* a visited triangle broke the index rules: stop, SUBD_ERR_PARAM */
    subd_real lo[3], hi[3];
    subd_real radius;
} ex_ctx;

/* ------------------------------------------------------------------------------------ */
/* Parameters and the hierarchy's shape.                                                  */

static int real_ok(subd_real x) { return subd_real_is_finite(x); }

/* The mode's own parameters (sr48_internal.h: the stream checks them here too). */
int subd_sr48_adapt_check_(const subd_sr48_adapt *ad)
{
    uint32_t i;
    switch (ad->mode) {
    case SUBD_SR48_ADAPT_UNIFORM: break;
    case SUBD_SR48_ADAPT_POINT:
        for (i = 0; i < 3u; i++) if (!real_ok(ad->point[i])) return SUBD_ERR_PARAM;
        if (!real_ok(ad->radius) || ad->radius < 0) return SUBD_ERR_PARAM;
        break;
    case SUBD_SR48_ADAPT_RAMP:
        if (ad->axis > 2u) return SUBD_ERR_PARAM;
        break;
    case SUBD_SR48_ADAPT_PLANE:
        for (i = 0; i < 3u; i++)
            if (!real_ok(ad->point[i]) || !real_ok(ad->normal[i])) return SUBD_ERR_PARAM;
        if (ad->normal[0] == 0 && ad->normal[1] == 0 && ad->normal[2] == 0) return SUBD_ERR_PARAM;
        break;
    case SUBD_SR48_ADAPT_CALLBACK:
        if (!ad->fn) return SUBD_ERR_PARAM;
        break;
    case SUBD_SR48_ADAPT_CHORD:
        if (!real_ok(ad->eps) || !(ad->eps > 0)) return SUBD_ERR_PARAM;
        break;
    default: return SUBD_ERR_PARAM;
    }
    return SUBD_OK;
}

static int ex_check_params(const subd_sr48 *h, const subd_sr48_adapt *ad)
{
    uint32_t k;
    if (!h || !ad) return SUBD_ERR_PARAM;
    if (h->steps > SUBD_SR48_MAX_STEPS || ad->max_level > h->steps) return SUBD_ERR_PARAM;
    if (subd_sr48_adapt_check_(ad) != SUBD_OK) return SUBD_ERR_PARAM;
    /* level structure: level 0 from 0, every later level twice the one before */
    if (h->level_tri[0] != 0u) return SUBD_ERR_PARAM;
    for (k = 1; k <= h->steps + 1u; k++) {
        uint32_t n = h->level_tri[k] - h->level_tri[k - 1u];
        if (h->level_tri[k] < h->level_tri[k - 1u]) return SUBD_ERR_PARAM;
        if (k >= 2u && n != 2u * (h->level_tri[k - 1u] - h->level_tri[k - 2u])) return SUBD_ERR_PARAM;
    }
    for (k = 1; k <= h->steps; k++)
        if (h->level_verts[k] < h->level_verts[k - 1u]) return SUBD_ERR_PARAM;
    if (h->num_tris != h->level_tri[h->steps + 1u] || h->num_verts != h->level_verts[h->steps])
        return SUBD_ERR_PARAM;
    if (h->level_tri[1] == 0u) return SUBD_ERR_EMPTY;
    if (!h->pos || !h->tri_vert || !h->tri_base_nb) return SUBD_ERR_PARAM;
    return SUBD_OK;
}

/* The index rules of subd_sr48 for triangle t of level k <= max: its vertices exist at
 * level k and are distinct; its base neighbour is on the same level, points back and has
 * the same base edge; below max, its children follow the split pattern around one new
 * vertex of level k + 1, which is also the apex of the partner's first child. Every index
 * it reads is bounds-checked first, so this is safe on any hierarchy that passed
 * ex_check_params, and afterwards t's vertices, neighbour and children may be used freely
 * (the extraction can then never read outside the arrays or build a broken mesh from a
 * hand-made hierarchy). */
static int ex_check_tri(const subd_sr48 *h, uint32_t t, uint32_t k, uint32_t max)
{
    uint32_t t0 = h->level_tri[k], t1 = h->level_tri[k + 1u], nv = h->level_verts[k];
    const uint32_t *v = h->tri_vert + 3u * t;
    uint32_t nb = h->tri_base_nb[t];
    if (v[0] >= nv || v[1] >= nv || v[2] >= nv || v[0] == v[1] || v[1] == v[2] || v[0] == v[2])
        return SUBD_ERR_PARAM;
    if (nb != SUBD_NONE) {
        if (nb < t0 || nb >= t1 || nb == t || h->tri_base_nb[nb] != t) return SUBD_ERR_PARAM;
        if (h->tri_vert[3u * nb + 1u] != v[2] || h->tri_vert[3u * nb + 2u] != v[1]) return SUBD_ERR_PARAM;
    }
    if (k < max) {
        uint32_t c0 = t1 + 2u * (t - t0);
        const uint32_t *a = h->tri_vert + 3u * c0, *b = a + 3;
        uint32_t m = a[0];
        if (m < nv || m >= h->level_verts[k + 1u]) return SUBD_ERR_PARAM;
        if (a[1] != v[0] || a[2] != v[1] || b[0] != m || b[1] != v[2] || b[2] != v[0]) return SUBD_ERR_PARAM;
        if (nb != SUBD_NONE && h->tri_vert[3u * (t1 + 2u * (nb - t0))] != m) return SUBD_ERR_PARAM;
    }
    return SUBD_OK;
}

/* Every triangle of levels 0..max (UNIFORM, whose output is all of level max anyway; the
 * adaptive modes check lazily, see ex_ok). */
static int ex_check_hierarchy(const subd_sr48 *h, uint32_t max)
{
    uint32_t k, t;
    for (k = 0; k <= max; k++)
        for (t = h->level_tri[k]; t < h->level_tri[k + 1u]; t++)
            if (ex_check_tri(h, t, k, max) != SUBD_OK) return SUBD_ERR_PARAM;
    return SUBD_OK;
}

/* Phase 2's renumbering map, one entry per vertex of levels <= max (layout.h). */
static int ex_layout_vmap(subd_arena *a, const ex_layout *L, uint32_t **vmap, uint32_t *bytes)
{
    subd_layout l;
    uint32_t *v;
    subd_layout_begin(&l, a);
    v = subd_layout_take(&l, L->nvert, 4u);
    if (vmap) *vmap = v;
    return subd_layout_end(&l, bytes);
}

/* The one layout of phase 1 (layout.h). With a == NULL it only counts (c may be NULL). */
static int ex_layout_phase1(subd_arena *a, ex_layout *L, ex_ctx *c, const subd_sr48_adapt *ad)
{
    uint32_t nwork = (L->uniform || L->nvert > L->ntri) ? L->nvert : L->ntri;
    uint32_t nf = L->uniform ? 0u : L->max + 1u;
    uint32_t ncs = (!L->uniform && ad->mode == SUBD_SR48_ADAPT_CHORD) ? L->max + 1u : 0u;
    subd_layout l;
    ex_ctx tmp;
    ex_ctx *p = c ? c : &tmp;
    int st;
    subd_layout_begin(&l, a);
    p->mark = subd_layout_take(&l, L->uniform ? 0u : L->ntri, 1u);
    L->marks = l.bytes;
    p->work = subd_layout_take(&l, nwork, 4u);
    p->fstack = subd_layout_take(&l, nf, 4u);
    p->cstack = subd_layout_take(&l, ncs, EX_CNODE_BYTES);
    st = subd_layout_end(&l, &L->phase1);
    ex_layout_vmap(0, L, 0, &L->vmap);
    return st;
}

/* Bytes needed once the output counts are known (see the file comment). */
static uint32_t ex_need(const ex_layout *L, uint32_t nv, uint32_t nf)
{
    mesh_counts mc;
    uint32_t arrays, scratch, b = L->marks;
    if (nf > (UINT32_MAX - 1u) / 3u) return UINT32_MAX;
    mc.nv = nv; mc.nf = nf; mc.nc = 3u * nf; mc.nl = 0; mc.nlv = 0;
    arrays = subd_mesh_counts_bytes(&mc);
    if (arrays == UINT32_MAX) return UINT32_MAX;
    scratch = subd_mesh_scratch_bytes(&mc);
    arrays -= scratch;
    subd_bytes_add(&b, arrays);
    subd_bytes_add(&b, subd_bytes_max(scratch, L->vmap));
    return subd_bytes_max(b, L->phase1);
}

static int ex_plan(const subd_sr48 *h, const subd_sr48_adapt *ad, ex_layout *L, uint32_t *bound)
{
    int st = ex_check_params(h, ad);
    if (st != SUBD_OK) return st;
    L->max = ad->max_level;
    L->uniform = (ad->mode == SUBD_SR48_ADAPT_UNIFORM) || ad->max_level == 0u;
    L->ntri = h->level_tri[L->max];
    L->nvert = h->level_verts[L->max];
    if ((st = ex_layout_phase1(0, L, 0, ad)) != SUBD_OK) return st;
    *bound = ex_need(L, L->nvert, h->level_tri[L->max + 1u] - h->level_tri[L->max]);
    return *bound == UINT32_MAX ? SUBD_ERR_TOO_BIG : SUBD_OK;
}

int subd_sr48_extract_plan(const subd_sr48 *h, const subd_sr48_adapt *ad, uint32_t *bytes, subd_diag *diag)
{
    subd_diag own, *d = subd_plan_begin(&own, diag);
    ex_layout L;
    uint32_t b;
    int st;
    if (!bytes) return subd_plan_end(d, SUBD_ERR_PARAM);
    st = ex_plan(h, ad, &L, &b);
    if (st == SUBD_OK) *bytes = b;
    return subd_plan_end(d, st);
}

/* Lazy validation (adaptive modes): a triangle's index rules are checked the first time
 * the extraction touches it - dequeued as active, on top of the forced-split stack, walked
 * by CHORD, or emitted at level max - and before any of its indices is used, so the work
 * follows the triangles visited instead of the whole hierarchy. EX_OK remembers the
 * result for triangles below max (they have a mark byte); level-max triangles are touched
 * once, when they are emitted. On failure c->bad is set and phase 1 stops. */
static int ex_ok(ex_ctx *c, uint32_t t, uint32_t k)
{
    if (k < c->max && (c->mark[t] & EX_OK)) return 1;
    if (ex_check_tri(c->h, t, k, c->max) != SUBD_OK) {
        c->bad = 1;
        return 0;
    }
    if (k < c->max) c->mark[t] = (uint8_t)(c->mark[t] | EX_OK);
    return 1;
}

/* ------------------------------------------------------------------------------------ */
/* Adaptation functions.                                                                  */

static const subd_real *ex_pos(const ex_ctx *c, uint32_t v) { return c->h->pos + 3u * v; }

/* The nested region of POINT, RAMP and PLANE (see the file comment): the box of the
 * level-0 interpolant L over the star of t's diamond at level k. */

/* L at the corners of triangle x of level k (apex, b0, b1): from its level-0 ancestor's
 * corners (finest positions), one base midpoint per level along the child path in x's
 * index (child 0 = (m; apex, b0), child 1 = (m; b1, apex)). The level-0 ancestor is checked
 * before its vertices are read; no other index is read. */
static int ex_tri_lin(ex_ctx *c, uint32_t x, uint32_t k, subd_real *l)
{
    const subd_sr48 *h = c->h;
    uint32_t i = x - h->level_tri[k], a = i >> k, j, q, ovf = 0;
    if (!ex_ok(c, a, 0)) return 0;
    for (j = 0; j < 9u; j++) l[j] = ex_pos(c, h->tri_vert[3u * a + j / 3u])[j % 3u];
    for (j = k; j > 0u; j--) {
        subd_real m[3], o[6];
        for (q = 0; q < 3u; q++) m[q] = subd_mid(l[3u + q], l[6u + q], &ovf);
        if ((i >> (j - 1u)) & 1u) {
            for (q = 0; q < 3u; q++) { o[q] = l[6u + q]; o[3u + q] = l[q]; }
        } else {
            for (q = 0; q < 3u; q++) { o[q] = l[q]; o[3u + q] = l[3u + q]; }
        }
        for (q = 0; q < 3u; q++) { l[q] = m[q]; l[3u + q] = o[q]; l[6u + q] = o[3u + q]; }
    }
    return 1;
}

/* The neighbour of x (level k < max, checked) across slot 0 (base), 1 (leg 0: apex-b0) or
 * 2 (leg 1: b1-apex): a leg of x is the base of one of its children, whose base neighbour's
 * parent is x's leg neighbour. SUBD_NONE on the boundary or when a child breaks the index
 * rules (c->bad set). */
static uint32_t ex_nbr(ex_ctx *c, uint32_t x, uint32_t k, uint32_t slot)
{
    const subd_sr48 *h = c->h;
    uint32_t ch, nb;
    if (slot == 0u) return h->tri_base_nb[x];
    ch = h->level_tri[k + 1u] + 2u * (x - h->level_tri[k]) + (slot - 1u);
    if (!ex_ok(c, ch, k + 1u)) return SUBD_NONE;
    nb = h->tri_base_nb[ch];
    return nb == SUBD_NONE ? SUBD_NONE : h->level_tri[k] + (nb - h->level_tri[k + 1u]) / 2u;
}

/* Grows box (lo, hi) by L over the level-k triangles around vertex v, starting at x0 (which
 * has v as a corner): the fan is walked in one direction until it closes or meets the
 * boundary, then in the other; duplicates do not change a box. 0 on a broken hierarchy. */
static int ex_fan_box(ex_ctx *c, uint32_t x0, uint32_t k, uint32_t v, subd_real *lo, subd_real *hi)
{
    const subd_sr48 *h = c->h;
    uint32_t dir, steps, cap = h->level_tri[k + 1u] - h->level_tri[k];
    for (dir = 0; dir < 2u; dir++) {
        uint32_t x = x0, prev = SUBD_NONE;
        for (steps = 0; steps <= cap; steps++) {
            const uint32_t *tv;
            subd_real l[9];
            uint32_t j, s0, s1, nx;
            if (!ex_ok(c, x, k) || !ex_tri_lin(c, x, k, l)) return 0;
            for (j = 0; j < 9u; j++) {
                if (l[j] < lo[j % 3u]) lo[j % 3u] = l[j];
                if (l[j] > hi[j % 3u]) hi[j % 3u] = l[j];
            }
            tv = h->tri_vert + 3u * x;
            /* the two slots at v: corner 0 (apex) -> legs (slots 1, 2); b0 -> 1, 0; b1 -> 2, 0 */
            if (tv[0] == v) { s0 = 1u; s1 = 2u; }
            else if (tv[1] == v) { s0 = 1u; s1 = 0u; }
            else if (tv[2] == v) { s0 = 2u; s1 = 0u; }
            else return 0;
            if (dir) { j = s0; s0 = s1; s1 = j; }
            nx = ex_nbr(c, x, k, s0);
            if (c->bad) return 0;
            if (nx == prev && prev != SUBD_NONE) nx = ex_nbr(c, x, k, s1);
            if (c->bad) return 0;
            if (nx == SUBD_NONE || nx == x0) break;
            if (nx < h->level_tri[k] || nx >= h->level_tri[k + 1u]) return 0;
            prev = x;
            x = nx;
        }
    }
    return 1;
}

/* The box of L over every level-k triangle sharing a vertex with t's diamond. */
static int ex_star_box(ex_ctx *c, uint32_t t, uint32_t k, subd_real *lo, subd_real *hi)
{
    const subd_sr48 *h = c->h;
    uint32_t j, nb = h->tri_base_nb[t];
    for (j = 0; j < 3u; j++) {
        lo[j] = SUBD_REAL_MAX;
        hi[j] = -SUBD_REAL_MAX;
    }
    for (j = 0; j < 3u; j++)
        if (!ex_fan_box(c, t, k, h->tri_vert[3u * t + j], lo, hi)) return 0;
    if (nb != SUBD_NONE && !ex_fan_box(c, nb, k, h->tri_vert[3u * nb], lo, hi)) return 0;
    return 1;
}

/* POINT: dist(point, box) < n * radius (n = max_level - k levels to go). Every step is
 * monotone in the box and in n, which is all the nesting needs. */
static int ex_point_wants(const subd_sr48_adapt *ad, subd_real radius, const subd_real *lo, const subd_real *hi, uint32_t n)
{
    subd_wide d[3], lim = subd_wide_mulu(n, subd_wide_of(radius));
    uint32_t i;
    for (i = 0; i < 3u; i++) {
        subd_real p = ad->point[i];
        d[i] = p < lo[i] ? subd_wide_diff(lo[i], p) : p > hi[i] ? subd_wide_diff(p, hi[i]) : 0;
        if (d[i] >= lim) return 0;
    }
#if SUBD_FIXED /* the algorithm differs: one common floor shift keeps the squares in int64 */
    {
        int32_t s = (int32_t)subd_bitlen64((uint64_t)lim) - 30;
        uint64_t sum = 0, l2;
        if (s < 0) s = 0;
        for (i = 0; i < 3u; i++) sum += ((uint64_t)d[i] >> s) * ((uint64_t)d[i] >> s);
        l2 = ((uint64_t)lim >> s) * ((uint64_t)lim >> s);
        return sum < l2;
    }
#else
    {
        float s0 = d[0] * d[0], s1 = d[1] * d[1], s2 = d[2] * d[2];
        return s0 + s1 + s2 < lim * lim;
    }
#endif
}

/* RAMP: (k + 1)(hi - lo) <= max (x - lo), x the box's largest coordinate on the axis. */
static int ex_ramp_wants(const subd_sr48_adapt *ad, const subd_real *rlo, const subd_real *rhi, const subd_real *hi,
                         uint32_t k)
{
    uint32_t ax = ad->axis;
    subd_real lo = rlo[ax], top = rhi[ax];
    return subd_wide_mulu(k + 1u, subd_wide_diff(top, lo)) <= subd_wide_mulu(ad->max_level, subd_wide_diff(hi[ax], lo));
}

/* PLANE: the box's corner furthest along the normal is on the side (x - point).normal >= 0
 * (exact in Q16.16, vec3w.h). */
static int ex_plane_wants(const subd_sr48_adapt *ad, const subd_real *lo, const subd_real *hi)
{
    subd_real q[3];
    uint32_t i;
    for (i = 0; i < 3u; i++) q[i] = ad->normal[i] >= 0 ? hi[i] : lo[i];
    return subd_w3_side(q, ad->point, ad->normal);
}

/* POINT, RAMP or PLANE on a diamond of level k < max_level with region box (lo, hi)
 * (sr48_internal.h: the stream takes its decisions here too). radius: POINT's (resolved);
 * rlo, rhi: RAMP's bounding box. */
int subd_sr48_box_wants_(const subd_sr48_adapt *ad, subd_real radius, const subd_real *rlo, const subd_real *rhi,
                         const subd_real *lo, const subd_real *hi, uint32_t k)
{
    if (ad->mode == SUBD_SR48_ADAPT_POINT) return ex_point_wants(ad, radius, lo, hi, ad->max_level - k);
    if (ad->mode == SUBD_SR48_ADAPT_RAMP) return ex_ramp_wants(ad, rlo, rhi, hi, k);
    if (ad->mode == SUBD_SR48_ADAPT_CALLBACK) return ad->fn(ad->ctx, lo, hi) > k;
    return ex_plane_wants(ad, lo, hi);
}

/* Chordal deviation of t (level k < max, checked) beyond eps: depth-first walk of t's
 * subtree down to level max, stopping at the first vertex that deviates. Stack: pop one
 * node, push its two children, so at most (max - k) + 1 <= max + 1 entries. Each node is
 * checked before its child is read (a failure sets c->bad and answers 0). */
static int ex_chord_wants(ex_ctx *c, uint32_t t, uint32_t k)
{
    const subd_sr48 *h = c->h;
    ex_cnode *st = c->cstack;
    uint32_t sp = 1, i;
    st[0].tri = t;
    st[0].level = k;
    for (i = 0; i < 9u; i++) st[0].l[i] = subd_sr48_lin_of_(ex_pos(c, h->tri_vert[3u * t + i / 3u])[i % 3u]);
    while (sp > 0u) {
        ex_cnode nd = st[--sp];
        uint32_t kk = nd.level, c0, m;
        ex_lin lm[3];
        if (!ex_ok(c, nd.tri, kk)) return 0; /* before reading its child's apex */
        c0 = h->level_tri[kk + 1u] + 2u * (nd.tri - h->level_tri[kk]);
        m = h->tri_vert[3u * c0];
        for (i = 0; i < 3u; i++) lm[i] = subd_sr48_lin_mid_(nd.l[3u + i], nd.l[6u + i]);
        if (subd_sr48_beyond_(ex_pos(c, m), lm, c->ad->eps)) return 1;
        if (kk + 1u >= c->max) continue;
        if (sp + 2u > c->max + 1u) return 1; /* cannot happen (see above); stay in bounds */
        /* child 2i = (m; apex, b0), child 2i+1 = (m; b1, apex) */
        st[sp].tri = c0;
        st[sp + 1u].tri = c0 + 1u;
        st[sp].level = st[sp + 1u].level = kk + 1u;
        for (i = 0; i < 3u; i++) {
            st[sp].l[i] = lm[i];
            st[sp].l[3u + i] = nd.l[i];
            st[sp].l[6u + i] = nd.l[3u + i];
            st[sp + 1u].l[i] = lm[i];
            st[sp + 1u].l[3u + i] = nd.l[6u + i];
            st[sp + 1u].l[6u + i] = nd.l[i];
        }
        sp += 2u;
    }
    return 0;
}

/* Does triangle t of level k < max (checked) ask for a split? */
static int ex_wants(ex_ctx *c, uint32_t t, uint32_t k)
{
    subd_real lo[3], hi[3];
    switch (c->ad->mode) {
    case SUBD_SR48_ADAPT_POINT:
    case SUBD_SR48_ADAPT_RAMP:
    case SUBD_SR48_ADAPT_PLANE:
    case SUBD_SR48_ADAPT_CALLBACK:
        if (!ex_star_box(c, t, k, lo, hi)) {
            c->bad = 1;
            return 0;
        }
        return subd_sr48_box_wants_(c->ad, c->radius, c->lo, c->hi, lo, hi, k);
    case SUBD_SR48_ADAPT_CHORD: return ex_chord_wants(c, t, k);
    default: return 1;
    }
}

/* ------------------------------------------------------------------------------------ */
/* The restricted hierarchy: marking.                                                     */

static uint32_t ex_level(const subd_sr48 *h, uint32_t t, uint32_t max)
{
    uint32_t k = max;
    while (k > 0u && t < h->level_tri[k]) k--;
    return k;
}

static uint32_t ex_parent(const subd_sr48 *h, uint32_t t, uint32_t k)
{
    return h->level_tri[k - 1u] + (t - h->level_tri[k]) / 2u;
}

/* Marks t's diamond split and queues the new active triangles that may split again. */
static void ex_split_one(ex_ctx *c, uint32_t t, uint32_t k)
{
    const subd_sr48 *h = c->h;
    uint32_t c0 = h->level_tri[k + 1u] + 2u * (t - h->level_tri[k]);
    c->mark[t] = (uint8_t)(c->mark[t] | EX_SPLIT);
    if (k + 1u < c->max) {
        c->work[c->qtail++] = c0;
        c->work[c->qtail++] = c0 + 1u;
    }
}

/* Splits t's diamond after the diamonds of the parents of t and of its partner. Each entry
 * pushed is the parent of the entry below it or of that entry's partner, so it is one level
 * coarser: at most max entries (levels max-1 .. 0). An entry is checked before its partner
 * is read (a failure sets c->bad and stops). */
static void ex_force_split(ex_ctx *c, uint32_t t0)
{
    const subd_sr48 *h = c->h;
    uint32_t sp = 0;
    c->fstack[sp++] = t0;
    while (sp > 0u) {
        uint32_t t = c->fstack[sp - 1u], k = ex_level(h, t, c->max), nb;
        if (c->mark[t] & EX_SPLIT) { sp--; continue; }
        if (!ex_ok(c, t, k)) return;
        nb = h->tri_base_nb[t];
        if (k > 0u && sp <= c->max) {
            uint32_t p = ex_parent(h, t, k);
            if (!(c->mark[p] & EX_SPLIT)) { c->fstack[sp++] = p; continue; }
            if (nb != SUBD_NONE) {
                p = ex_parent(h, nb, k);
                if (!(c->mark[p] & EX_SPLIT)) { c->fstack[sp++] = p; continue; }
            }
        }
        ex_split_one(c, t, k);
        if (nb != SUBD_NONE) ex_split_one(c, nb, k);
        sp--;
    }
}

/* The cut: marks and forced_splits; 0 when a visited triangle broke the index rules.
 * The marks of all triangles below max are cleared first: one byte each, written in one
 * streaming pass (the arena holds garbage, and the forced-split walk reads the marks of
 * parents that are not known to be active, so they cannot be cleared lazily as triangles
 * become active). Everything else follows the triangles visited: the worklist ends up
 * holding every active triangle below max exactly once, and every split triangle is one
 * of them, so forced_splits is counted over it. */
static int ex_mark(ex_ctx *c)
{
    const subd_sr48 *h = c->h;
    uint32_t head = 0, t, i, n0 = h->level_tri[1], ntri = h->level_tri[c->max];
    uint8_t *mark = c->mark; /* locals: stores through a byte pointer may alias anything */
    c->qtail = 0;
    c->forced = 0;
    c->bad = 0;
    for (t = 0; t < ntri; t++) mark[t] = 0;
    for (t = 0; t < n0; t++) c->work[c->qtail++] = t;
    /* every triangle enters the queue once, when it becomes active, so the queue never
     * holds more than the triangles of levels < max */
    while (head < c->qtail) {
        uint32_t k;
        t = c->work[head++];
        k = ex_level(h, t, c->max);
        if (!ex_ok(c, t, k)) return 0;
        if (!ex_wants(c, t, k)) {
            if (c->bad) return 0;
            continue;
        }
        c->mark[t] = (uint8_t)(c->mark[t] | EX_WANT);
        if (!(c->mark[t] & EX_SPLIT)) ex_force_split(c, t);
        if (c->bad) return 0;
    }
    /* all of them were dequeued, hence checked */
    for (i = 0; i < c->qtail; i++) {
        uint32_t nb;
        uint8_t w;
        t = c->work[i];
        nb = h->tri_base_nb[t];
        if (!(c->mark[t] & EX_SPLIT) || (nb != SUBD_NONE && nb < t)) continue;
        w = (uint8_t)(c->mark[t] | (nb != SUBD_NONE ? c->mark[nb] : 0u));
        if (!(w & EX_WANT)) c->forced++;
    }
    return 1;
}

/* The cut's leaves (the output faces), one per call: the leaf after (*t, *k), or the first
 * one when *t == SUBD_NONE; 0 after the last. UNIFORM: level max in index order. Otherwise
 * a depth-first walk of the split triangles from the level-0 ones, children in index order;
 * a child's index order is its parent's, so each level's leaves come in increasing index
 * order, which is all the face order needs (by level, then index: the caller places each
 * leaf after the earlier leaves of its level). No stack: a triangle's parent and its place
 * among its siblings follow from its index, so the work is O(triangles of the cut and
 * their split ancestors), not O(hierarchy). Reads the marks of active triangles only,
 * which ex_mark checked. */
static int ex_next_leaf(const ex_ctx *c, uint32_t *pt, uint32_t *pk)
{
    const subd_sr48 *h = c->h;
    uint32_t t = *pt, k = *pk;
    if (c->uniform) {
        t = t == SUBD_NONE ? h->level_tri[c->max] : t + 1u;
        *pt = t;
        *pk = c->max;
        return t < h->level_tri[c->max + 1u];
    }
    if (t == SUBD_NONE) {
        t = 0;
        k = 0;
    } else {
        /* up while t is its parent's second child, then on to the next sibling or root */
        while (k > 0u && ((t - h->level_tri[k]) & 1u)) {
            t = ex_parent(h, t, k);
            k--;
        }
        t++;
        if (k == 0u && t >= h->level_tri[1]) return 0;
    }
    /* down to the first leaf under t */
    while (k < c->max && (c->mark[t] & EX_SPLIT)) {
        t = h->level_tri[k + 1u] + 2u * (t - h->level_tri[k]);
        k++;
    }
    *pt = t;
    *pk = k;
    return 1;
}

/* The adaptation box (RAMP's range, POINT's default radius; subd_sr48_adapt_mode): the box of
 * the finest positions of the corners of the level-0 triangles, i.e. of L over the whole
 * mesh. 0 when a level-0 corner is out of range. */
static int ex_bbox(ex_ctx *c)
{
    const subd_sr48 *h = c->h;
    uint32_t t, n = 3u * h->level_tri[1];
    for (t = 0; t < n; t++)
        if (h->tri_vert[t] >= h->level_verts[0]) return 0;
    subd_sr48_box_grow_(h->pos, h->tri_vert, n, c->lo, c->hi, 1);
    return 1;
}

/* Grows (lo, hi) by the n points pos + 3 idx[i] (reset first when `init`); sr48_internal.h. */
void subd_sr48_box_grow_(const subd_real *pos, const uint32_t *idx, uint32_t n, subd_real *blo, subd_real *bhi,
                         int init)
{
    subd_real lo[3], hi[3]; /* locals, so the compiler keeps them in registers */
    uint32_t v, i;
    for (i = 0; i < 3u; i++) {
        lo[i] = init ? SUBD_REAL_MAX : blo[i];
        hi[i] = init ? -SUBD_REAL_MAX : bhi[i];
    }
    for (v = 0; v < n; v++) {
        const subd_real *p = pos + 3u * idx[v];
        for (i = 0; i < 3u; i++) {
            if (p[i] < lo[i]) lo[i] = p[i];
            if (p[i] > hi[i]) hi[i] = p[i];
        }
    }
    for (i = 0; i < 3u; i++) {
        blo[i] = lo[i];
        bhi[i] = hi[i];
    }
}

/* POINT's default radius (sr48_internal.h): the adaptation box's diagonal / (2 max_level),
 * at least one unit of the last place so the level function stays defined; max > 0. */
subd_real subd_sr48_default_radius_(const subd_real *blo, const subd_real *bhi, uint32_t max)
{
#if SUBD_FIXED /* the algorithm differs: integer square root, pre-shift keeps the squares in 64 bits */
    uint64_t d[3], sum = 0, diag;
    uint32_t i, sh = 0;
    for (i = 0; i < 3u; i++) {
        d[i] = (uint64_t)((int64_t)bhi[i] - blo[i]);
        if (d[i] >> 31) sh = 1u; /* keep each square below 2^62 */
    }
    for (i = 0; i < 3u; i++) sum += (d[i] >> sh) * (d[i] >> sh);
    diag = (uint64_t)subd_isqrt64(sum) << sh;
    diag /= 2u * max;
    if (diag == 0u) diag = 1u;
    return diag > (uint64_t)INT32_MAX ? SUBD_REAL_MAX : (subd_real)diag;
#else
    float dx = bhi[0] - blo[0], dy = bhi[1] - blo[1], dz = bhi[2] - blo[2];
    float sx = dx * dx, sy = dy * dy, sz = dz * dz;
    float r = subd_sqrt(sx + sy + sz) / (float)(2u * max);
    return r > 0.0f ? r : 1.0f;
#endif
}

/* ------------------------------------------------------------------------------------ */

int subd_sr48_extract(subd_arena *a, const subd_sr48 *h, const subd_sr48_adapt *ad, subd_mesh *out,
                      subd_sr48_adapt_report *rep, subd_diag *diag)
{
    subd_entry e;
    subd_diag *d = subd_entry_begin(&e, a, diag);
    ex_layout L;
    ex_ctx c;
    mesh_counts mc;
    subd_mesh m;
    subd_sr48_adapt_report r;
    uint32_t next[SUBD_SR48_MAX_STEPS + 1u];
    uint32_t bound = 0, need, mark0, arr0, arr1, nv, nf, v, k, t, f, nvert;
    uint32_t *vmap, *used;
    int st;

    if (!a || !out) return subd_entry_fail(&e, SUBD_ERR_PARAM);
    if ((st = ex_plan(h, ad, &L, &bound)) != SUBD_OK) return subd_entry_fail(&e, st);
    /* UNIFORM emits all of level max: validate levels 0..max up front (the adaptive modes
     * validate what they visit, ex_ok) */
    if (L.uniform && (st = ex_check_hierarchy(h, L.max)) != SUBD_OK) return subd_entry_fail(&e, st);
    if (L.phase1 > subd_arena_free_bytes(a)) {
        d->bytes_needed = bound;
        return subd_entry_fail(&e, SUBD_ERR_NOMEM);
    }
    c.h = h;
    c.ad = ad;
    c.max = L.max;
    c.uniform = L.uniform;
    c.forced = 0;
    c.bad = 0;
    c.radius = ad->radius;
    mark0 = e.mark;
    if ((st = ex_layout_phase1(a, &L, &c, ad)) != SUBD_OK) goto fail;

    /* phase 1: the cut and its counts */
    if (!c.uniform) {
        /* the adaptation box: a pass over the level-0 corners, only when used */
        if (ad->mode == SUBD_SR48_ADAPT_RAMP || (ad->mode == SUBD_SR48_ADAPT_POINT && c.radius == 0))
            if (!ex_bbox(&c)) { st = SUBD_ERR_PARAM; goto fail; }
        if (ad->mode == SUBD_SR48_ADAPT_POINT && c.radius == 0) c.radius = subd_sr48_default_radius_(c.lo, c.hi, c.max);
        if (!ex_mark(&c)) { st = SUBD_ERR_PARAM; goto fail; }
    }
    /* the leaves: per-level counts, and the used vertices flagged in the worklist's memory
     * (level-max leaves are checked here, the first time they are touched) */
    for (k = 0; k < SUBD_SR48_MAX_STEPS + 1u; k++) r.level_faces[k] = 0;
    nvert = L.nvert;
    used = c.work;
    for (v = 0; v < nvert; v++) used[v] = 0;
    nf = 0;
    t = SUBD_NONE;
    k = 0;
    while (ex_next_leaf(&c, &t, &k)) {
        const uint32_t *tv = h->tri_vert + 3u * t;
        if (!c.uniform && k == c.max && !ex_ok(&c, t, k)) { st = SUBD_ERR_PARAM; goto fail; }
        used[tv[0]] = used[tv[1]] = used[tv[2]] = 1u;
        r.level_faces[k]++;
        nf++;
    }
    for (nv = 0, v = 0; v < nvert; v++) nv += used[v];
    need = ex_need(&L, nv, nf);
    if (need == UINT32_MAX) { st = SUBD_ERR_TOO_BIG; goto fail; }
    if (need > a->size - mark0) {
        d->bytes_needed = need;
        return subd_entry_fail(&e, SUBD_ERR_NOMEM);
    }

    /* phase 2: arrays above the marks, the renumbering map above the arrays */
    subd_arena_rewind(a, mark0 + L.marks);
    mc.nv = nv; mc.nf = nf; mc.nc = 3u * nf; mc.nl = 0; mc.nlv = 0;
    arr0 = subd_arena_mark(a);
    if ((st = subd_mesh_alloc_arrays(a, &mc, &m)) != SUBD_OK) goto fail;
    arr1 = subd_arena_mark(a);
    if ((st = ex_layout_vmap(a, &L, &vmap, 0)) != SUBD_OK) goto fail;
    /* faces by level, then index: a leaf goes after the earlier leaves of its level; the
     * corners get hierarchy vertex numbers first, renumbered once vmap is known */
    for (f = 0, k = 0; k < SUBD_SR48_MAX_STEPS + 1u; k++) {
        next[k] = f;
        f += r.level_faces[k];
    }
    for (v = 0; v < nvert; v++) vmap[v] = 0;
    t = SUBD_NONE;
    k = 0;
    while (ex_next_leaf(&c, &t, &k)) {
        const uint32_t *tv = h->tri_vert + 3u * t;
        uint32_t *cv = m.corner_vert + 3u * next[k]++;
        cv[0] = tv[0];
        cv[1] = tv[1];
        cv[2] = tv[2];
        vmap[tv[0]] = vmap[tv[1]] = vmap[tv[2]] = 1u;
    }
    for (nv = 0, v = 0; v < nvert; v++) {
        if (!vmap[v]) { vmap[v] = SUBD_NONE; continue; }
        for (k = 0; k < 3u; k++) m.pos[3u * nv + k] = h->pos[3u * v + k];
        vmap[v] = nv++;
    }
    for (f = 0; f < 3u * nf; f++) m.corner_vert[f] = vmap[m.corner_vert[f]];
    for (f = 0; f <= nf; f++) m.face_start[f] = 3u * f;
    m.line_start[0] = 0;
    r.faces = nf;
    r.uniform_faces = h->level_tri[c.max + 1u] - h->level_tri[c.max];
    r.forced_splits = c.forced;

    /* give the map and the marks back: the mesh arrays move down to mark0 */
    subd_arena_rewind(a, arr1);
    if (arr0 != mark0) {
        subd_mesh_move_down(&m, a->base + mark0, arr1 - arr0); /* m.pos is at arr0 */
        subd_arena_rewind(a, mark0 + (arr1 - arr0));
    }
    if ((st = subd_mesh_finish(a, &m, d)) != SUBD_OK) return subd_entry_fail(&e, st);
    *out = m;
    if (rep) *rep = r;
    return subd_entry_ok(&e);
fail:
    if (st == SUBD_ERR_NOMEM) d->bytes_needed = bound;
    return subd_entry_fail(&e, st);
}
