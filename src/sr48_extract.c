/* SPDX-License-Identifier: MIT */
/* Variable-resolution extraction from the semi-regular 4-8 hierarchy of right triangles.
 * This file is the cut (parameters, lazy validation, marks, forced splits, output); the
 * adaptation geometry (the nested star box, the POINT/RAMP/PLANE/CALLBACK predicates, the
 * CHORD walk) is sr48_adapt.c, their private interface sr48_extract_internal.h.
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
 * Adaptation functions (POINT, RAMP, PLANE on a nested region, CALLBACK, CHORD): their
 * definitions, why the region nests and what each predicate costs are in sr48_adapt.c; this
 * file asks subd_sr48_ex_wants_ once per active triangle of level < max_level.
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
#include "sr48_internal.h"
#include "sr48_extract_internal.h"

typedef struct ex_layout {
    uint32_t max;          /* max_level                                                 */
    uint32_t uniform;      /* mode UNIFORM: no marks, no worklist                        */
    uint32_t ntri;         /* triangles of levels < max (marks, worklist)               */
    uint32_t nvert;        /* vertices of levels <= max                                 */
    uint32_t marks;        /* aligned bytes of the marks (kept during phase 2)          */
    uint32_t phase1;       /* bytes of phase 1                                          */
    uint32_t vmap;         /* aligned bytes of the renumbering map                      */
} ex_layout;

/* ------------------------------------------------------------------------------------ */
/* Parameters and the hierarchy's shape.                                                  */

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
int subd_sr48_ex_check_tri_(const subd_sr48 *h, uint32_t t, uint32_t k, uint32_t max)
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
            if (subd_sr48_ex_check_tri_(h, t, k, max) != SUBD_OK) return SUBD_ERR_PARAM;
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
        if (!subd_sr48_ex_wants_(c, t, k)) {
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
            if (!subd_sr48_ex_bbox_(&c)) { st = SUBD_ERR_PARAM; goto fail; }
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
