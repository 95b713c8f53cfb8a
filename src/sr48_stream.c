/* SPDX-License-Identifier: MIT */
/* Streaming semi-regular 4-8 refinement (paper: semi-regular-4-8-refinement-box-splines.txt,
 * sections 4 and 6).
 * Length (~1 220 lines): three pieces share one window layout and state - the window
 * (refine, smooth, crop, descent to the finest level), the CHORD walk over the deeper windows
 * (its test and proof are in sr48_chord.c) and the stream driver (plan, begin, step,
 * adaptive decisions); the split into sr48_window.c, the chord walk and sr48_stream.c behind
 * a private window header is open work (issue 19, item 7; issue 20).
 * What it streams: the triangles of subd_sr48_extract's uniform cut of
 * subd_sr48_build's hierarchy, handed out one at a time through the common stream
 * interface (include/subd.h "Streams", src/stream.c), in memory that depends on the level
 * count and the base mesh's largest valence only.
 *
 * Method. Every level-0 triangle T0 of the base mesh (subd_sr48_base) is refined depth
 * first, child 0 before child 1, so triangles come out in the hierarchy's index order at
 * the last level. Level k keeps a window: the level-k triangles within S48_RINGS vertex
 * rings of the current triangle's children (a triangle is in ring r when it shares a
 * vertex with ring r-1), each with its three vertices, its base, leg-0 and leg-1
 * neighbours as window indices (or OUT of the window, or BND: the mesh boundary) and its
 * global key (T0 * 2^k + the child path = its index within level k of the hierarchy). The
 * window of level k+1 is the window of level k refined as a whole (every diamond split,
 * subd_sr48_step's rule, the children's neighbours by the local form of its rule:
 * for t = (c; a, b) with base neighbour N, leg neighbours L0 (c-a) and L1 (b-c), child 0
 * = (m; c, a) has base child 1 of L0, leg 0 child 1 of t, leg 1 child 1 of N; child 1 =
 * (m; b, c) has base child 0 of L1, leg 0 child 0 of N, leg 1 child 0 of t), smoothed
 * after an even level (subd_sr48_smooth's rule), then cropped to the rings of the next
 * current triangle. The last level is not stored: the two children of the current level
 * L-1 triangle are emitted from the refined (uncropped) window: one internal batch.
 *
 * Exactness. A vertex's position is exact when every input of its rule was: a new vertex
 * needs its diamond's two apexes (both triangles in the window; a boundary half-diamond
 * its base ends), an older vertex smoothed after an even level needs its whole fan in the
 * window (no window triangle at it has an OUT neighbour across an edge at it) and every
 * new neighbour exact. Each window vertex carries that flag; an emitted corner that is not
 * exact would be a bug of the ring count (the window too small for the dependency cone),
 * reported as SUBD_ERR_TOO_BIG rather than emitted (test_sr48_stream checks it never
 * happens, by comparing every position with subd_sr48_build's).
 *
 * Bit-identity with subd_sr48_build: a new vertex is the same subd_mid of the same two
 * positions (the apex of the diamond's lower-index triangle first); a smoothed vertex sums
 * its new neighbours in the order of the diamonds' lower triangle index, which is the
 * window's order (windows are kept sorted by key: children of sorted parents are sorted,
 * and cropping filters in order). Q16.16 sums are exact anyway.
 *
 * Ids (closed form): a level-0 vertex keeps its index; the vertex created at level k >= 1
 * by splitting the diamond whose lower-key triangle has key K at level k-1 gets
 * V0 + T0n (2^(k-1) - 1) + K (V0, T0n: the base's vertex and triangle counts).
 *
 * Adaptive cuts (POINT, RAMP, PLANE, CALLBACK; sr48_extract.c's nested region): every window
 * vertex also carries L, the level-0 mesh's piecewise-linear interpolant at the finest
 * positions of the level-0 vertices (a new vertex: subd_mid of L at its base ends, as
 * sr48_extract.c computes it, so the bits agree). L of the level-0 window is found by one
 * descent per vertex (s48_finest: refine and crop towards the vertex down to max_level,
 * where its position is exact by the ring rule). At its first visit the current triangle's
 * diamond is decided on L's box over the window triangles that touch it (the diamond lies
 * within one ring of the current triangle, its star within two: in the window); a diamond
 * that does not split makes the current triangle a leaf, emitted with its corners' finest
 * positions by three descents (blocks above the current level are free then). Since the
 * region is nested, a diamond that splits has split parents, so the top-down walk cuts
 * exactly subd_sr48_extract's (least conforming) cut, with no lookahead. RAMP's range and
 * POINT's default radius come from the adaptation box A (the finest positions of the base
 * triangles' corners, subd_sr48_adapt_mode), found before the first triangle by one descent per
 * base vertex (s48_adapt_box); CALLBACK asks fn on the same box as POINT/RAMP/PLANE.
 *
 * Chordal cuts (CHORD; the criterion, why it nests and why it is conservative: sr48_chord.c):
 * the current triangle's diamond splits iff a triangle of its star (as above: in the window)
 * has W > eps, W its subtree's largest chordal deviation of subd_sr48_extract's kind. W of
 * a star triangle is found by walking its subtree to max_level with the windows of the
 * levels below (s48_chord_walk: free at the decision); the current triangle is walked in
 * place, another one after rebuilding the windows 0..k along its path (s48c_path: the same
 * calls, so the same bits), and the current path is rebuilt afterwards. A direct-mapped
 * cache keeps verdicts by key (a "within" covers the descendants).
 *
 * Memory: the fixed state block, the overflow ring (2 triangles), L + 1 window blocks
 * (level L uses only its header), the refined window (twice the triangles), the smoothing
 * sums and the crop's maps (CHORD: the walk's per-level state, the star's keys, the verdict
 * cache); all sized by the window capacities of SUBD_SR48_STREAM_BYTES,
 * which depend on the largest valence only.
 */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "entry.h"
#include "layout.h"
#include "mesh_internal.h"
#include "real_avg.h"
#include "stream_internal.h"
#include "sr48_internal.h"

#define S48_OUT 0xffffu /* neighbour outside the window                                  */
#define S48_BND 0xfffeu /* the mesh boundary                                             */
#define S48_EXACT 0x1u  /* vertex flag: position final and bit-exact                     */
#define S48_INC 0x2u    /* smoothing scratch: some input missing                          */
#define S48_FAR 0xffu   /* crop: vertex not reached                                       */
#define S48_RINGS SUBD_SR48_STREAM_RINGS_
#define S48C_NC SUBD_SR48_STREAM_CHORD_CACHE_ /* CHORD: cached W verdicts (s48c_cached)      */

/* One window's arrays (level k, or the refined window X). hd: nt, nv, cur, ch0, ch1, nxt. */
typedef struct s48_win {
    uint32_t *hd;
    uint16_t *tv, *tn;
    uint32_t *key; /* lo, hi per triangle */
    subd_real *vp;
    uint32_t *vid; /* lo, hi per vertex   */
    uint8_t *vf;
    subd_real *vl; /* adaptive modes: L (the level-0 interpolant) per vertex, else NULL */
} s48_win;

/* Window vertex sv of src as vertex dv of dst: position, id, flags and (adaptive) L. */
static void s48_vcopy(const s48_win *dst, uint32_t dv, const s48_win *src, uint32_t sv)
{
    uint32_t j;
    for (j = 0; j < 3u; j++) dst->vp[3u * dv + j] = src->vp[3u * sv + j];
    dst->vid[2u * dv] = src->vid[2u * sv];
    dst->vid[2u * dv + 1u] = src->vid[2u * sv + 1u];
    dst->vf[dv] = src->vf[sv];
    if (dst->vl)
        for (j = 0; j < 3u; j++) dst->vl[3u * dv + j] = src->vl[3u * sv + j];
}

typedef struct s48_state {
    subd_stream_impl impl; /* first: stream.c's view */
    subd_stream_ring ring;
    const subd_sr48 *base;
    uint32_t levels, smooth, wt, wv, xv, nv0, n0;
    uint32_t t0, k, built, err;
    uint8_t *lev;      /* levels 0..L-1 blocks of lev_size, then X                         */
    uint32_t lev_size;
    uint32_t off[8], xoff[8];
    subd_sr48_adapt ad;
    uint32_t adapt;    /* POINT, RAMP, PLANE, CALLBACK: the nested-region cut (subd_sr48_adapt_mode) */
    uint32_t boxed;    /* RAMP, POINT's default radius: 0 until the adaptation box is found */
    subd_real blo[3], bhi[3], radius; /* the adaptation box A; POINT's radius (resolved)  */
    subd_real *l0;     /* L of the level-0 window's vertices (3 per vertex)                */
    uint32_t *lgv, *lgvt; /* the level-0 window's vertices and a triangle at each, kept     */
    uint8_t *xblk;
    subd_sum *sum;     /* 3 per vertex (reserved as 8 bytes each in both arithmetics)     */
    uint32_t *cnt;
    uint8_t *dist;
    uint16_t *mtab, *tmap, *vmap;
    uint32_t *gt, *gv, *gvt; /* level-0 window: triangles, vertices, a triangle at each     */
    /* CHORD (sr48_chord.c's criterion, s48_chord_wants): per walk level the triangle, the
     * child state, the corners' sources (0..2 the walked triangle's corners, 3 + j the vertex
     * level j's node creates); the star's keys; the verdict cache */
    uint32_t chord;
    uint32_t *ccur, *cch, *csrc, *ckey, *cache;
    subd_real *cpos; /* finest positions: the walked triangle's corners, then one per level */
} s48_state;
SUBD_STREAM_STATE_FITS(s48_state);

/* ------------------------------------------------------------------------------------ */
/* Capacities and layout                                                                  */

static uint32_t s48_cap_t(uint32_t n) { return SUBD_SR48_STREAM_WT_(n); }
static uint32_t s48_cap_v(uint32_t n) { return SUBD_SR48_STREAM_WV_(n); }

/* A window's arrays for ct triangles and cv vertices: offsets inside its block, its size. */
static uint32_t s48_win_layout(uint32_t ct, uint32_t cv, uint32_t nl, uint32_t *off)
{
    subd_layout y;
    uint32_t b, i;
    const uint32_t cnt[7] = {8u, 3u * ct, 3u * ct, 2u * ct, 3u * cv, 2u * cv, cv};
    const uint32_t el[7] = {4u, 2u, 2u, 4u, 4u, 4u, 1u};
    subd_layout_begin(&y, 0);
    for (i = 0; i < 7u; i++) {
        off[i] = y.bytes;
        (void)subd_layout_take(&y, cnt[i], el[i]);
    }
    off[7] = nl ? y.bytes : 0u; /* 0: no L (the header is at 0) */
    if (nl) (void)subd_layout_take(&y, 3u * cv, (uint32_t)sizeof(subd_real));
    (void)subd_layout_end(&y, &b);
    return b;
}

static void s48_win_at(uint8_t *blk, const uint32_t *off, s48_win *w)
{
    w->hd = (uint32_t *)(void *)(blk + off[0]);
    w->tv = (uint16_t *)(void *)(blk + off[1]);
    w->tn = (uint16_t *)(void *)(blk + off[2]);
    w->key = (uint32_t *)(void *)(blk + off[3]);
    w->vp = (subd_real *)(void *)(blk + off[4]);
    w->vid = (uint32_t *)(void *)(blk + off[5]);
    w->vf = blk + off[6];
    w->vl = off[7] != 0u ? (subd_real *)(void *)(blk + off[7]) : 0;
}

/* The one layout of plan and begin (layout.h's walk). */
static int s48_layout(subd_arena *a, uint32_t levels, uint32_t valence, uint32_t nl, uint32_t chord, s48_state **ps,
                      uint8_t **ring, uint32_t *bytes)
{
    subd_layout y;
    uint32_t ct = s48_cap_t(valence), cv = s48_cap_v(valence), xv = cv + ct, off[8];
    uint32_t lsz = s48_win_layout(ct, cv, nl, off), xsz = s48_win_layout(2u * ct, xv, nl, off);
    s48_state *s;
    subd_layout_begin(&y, a);
    s = subd_layout_take(&y, 1u, SUBD_STREAM_STATE_BYTES);
    *ring = subd_layout_take(&y, 2u, (uint32_t)sizeof(subd_tri));
    if (s) {
        s->wt = ct;
        s->wv = cv;
        s->xv = xv;
        s->lev_size = lsz;
        (void)s48_win_layout(ct, cv, nl, s->off);
        (void)s48_win_layout(2u * ct, xv, nl, s->xoff);
    }
    {
        uint8_t *lev = subd_layout_take(&y, levels > 0u ? levels : 1u, lsz);
        uint8_t *x = subd_layout_take(&y, 1u, xsz);
        subd_sum *sum = subd_layout_take(&y, 3u * xv, 8u);
        uint32_t *cnt = subd_layout_take(&y, xv, 4u);
        uint8_t *dist = subd_layout_take(&y, xv, 1u);
        uint16_t *mtab = subd_layout_take(&y, ct, 2u);
        uint16_t *tmap = subd_layout_take(&y, 2u * ct, 2u);
        uint16_t *vmap = subd_layout_take(&y, xv, 2u);
        uint32_t *gt = subd_layout_take(&y, ct, 4u);
        uint32_t *gv = subd_layout_take(&y, cv, 4u);
        uint32_t *gvt = subd_layout_take(&y, cv, 4u);
        subd_real *l0 = nl ? subd_layout_take(&y, 3u * cv, (uint32_t)sizeof(subd_real)) : 0;
        uint32_t *lgv = nl ? subd_layout_take(&y, cv, 4u) : 0;
        uint32_t *lgvt = nl ? subd_layout_take(&y, cv, 4u) : 0;
        uint32_t *ci = chord ? subd_layout_take(&y, 5u * (levels + 1u) + 2u * ct + 3u * S48C_NC, 4u) : 0;
        subd_real *cp = chord ? subd_layout_take(&y, 3u * (levels + 4u), (uint32_t)sizeof(subd_real)) : 0;
        if (s) {
            s->l0 = l0;
            s->lgv = lgv;
            s->lgvt = lgvt;
            s->lev = lev;
            s->xblk = x;
            s->sum = sum;
            s->cnt = cnt;
            s->dist = dist;
            s->mtab = mtab;
            s->tmap = tmap;
            s->vmap = vmap;
            s->gt = gt;
            s->gv = gv;
            s->gvt = gvt;
            s->cpos = cp;
            s->ccur = ci;
            s->cch = ci ? ci + (levels + 1u) : 0;
            s->csrc = ci ? ci + 2u * (levels + 1u) : 0;
            s->ckey = ci ? ci + 5u * (levels + 1u) : 0;
            s->cache = ci ? ci + 5u * (levels + 1u) + 2u * ct : 0;
        }
    }
    *ps = s;
    return subd_layout_end(&y, bytes);
}

/* ------------------------------------------------------------------------------------ */
/* The base mesh                                                                          */

/* Neighbour of level-0 triangle t across slot 0 (base), 1 (leg 0: c-a), 2 (leg 1: b-c). */
static uint32_t s48_base_nbr(const subd_sr48 *b, uint32_t t, uint32_t slot)
{
    uint32_t g;
    if (slot == 0u) return b->tri_base_nb[t];
    if ((t & 1u) == 0u && slot == 1u) return t + 1u;
    if ((t & 1u) == 1u && slot == 2u) return t - 1u;
    g = b->hyb_base_nb[t >> 1];
    if (g == SUBD_NONE) return SUBD_NONE;
    return (t & 1u) == 0u ? 2u * g + 1u : 2u * g;
}

/* The two ends of slot s of a triangle with vertices v = (c, a, b). */
static void s48_slot_ends(const uint32_t *v, uint32_t s, uint32_t *p, uint32_t *q)
{
    *p = s == 0u ? v[1] : s == 1u ? v[0] : v[2];
    *q = s == 0u ? v[2] : s == 1u ? v[1] : v[0];
}

static void s48_tri_verts(const subd_sr48 *b, uint32_t t, uint32_t *v)
{
    v[0] = b->tri_vert[3u * t];
    v[1] = b->tri_vert[3u * t + 1u];
    v[2] = b->tri_vert[3u * t + 2u];
}

/* The base mesh's rules (checked once, before any walk): level 0 only, vertices in range
 * and distinct, every neighbour in range, pointing back across the same edge reversed. */
static int s48_base_check(const subd_sr48 *b)
{
    uint32_t n0, t, s, v[3], u[3];
    if (!b || b->steps != 0u || !b->pos || !b->tri_vert || !b->tri_base_nb || !b->hyb_base_nb) return SUBD_ERR_PARAM;
    if ((b->flags & ~SUBD_SR48_NO_SMOOTH) != 0u) return SUBD_ERR_PARAM;
    n0 = b->level_tri[1];
    if (b->level_tri[0] != 0u || n0 != b->num_tris || (n0 & 1u) != 0u || b->num_verts != b->level_verts[0])
        return SUBD_ERR_PARAM;
    if (n0 == 0u) return SUBD_ERR_EMPTY;
    if (n0 >= 0x0fffffffu || b->num_verts >= 0x0fffffffu) return SUBD_ERR_TOO_BIG;
    for (t = 0; t < n0 / 2u; t++)
        if (b->hyb_base_nb[t] != SUBD_NONE && b->hyb_base_nb[t] >= n0 / 2u) return SUBD_ERR_PARAM;
    for (t = 0; t < n0; t++) {
        s48_tri_verts(b, t, v);
        if (v[0] >= b->num_verts || v[1] >= b->num_verts || v[2] >= b->num_verts || v[0] == v[1] || v[1] == v[2] ||
            v[0] == v[2])
            return SUBD_ERR_PARAM;
        if (b->tri_base_nb[t] != SUBD_NONE && b->tri_base_nb[t] >= n0) return SUBD_ERR_PARAM;
    }
    for (t = 0; t < n0; t++) {
        s48_tri_verts(b, t, v);
        for (s = 0; s < 3u; s++) {
            uint32_t n = s48_base_nbr(b, t, s), p, q, r, ok = 0;
            if (n == SUBD_NONE) continue;
            s48_slot_ends(v, s, &p, &q);
            s48_tri_verts(b, n, u);
            for (r = 0; r < 3u; r++) {
                uint32_t p2, q2;
                s48_slot_ends(u, r, &p2, &q2);
                if (p2 == q && q2 == p && s48_base_nbr(b, n, r) == t) ok = 1;
            }
            if (!ok) return SUBD_ERR_PARAM;
        }
    }
    return SUBD_OK;
}

static uint32_t s48_pos_of(const uint32_t *v, uint32_t x) { return v[0] == x ? 0u : v[1] == x ? 1u : 2u; }

/* The two slots at corner position p: (c: 1, 2), (a: 1, 0), (b: 0, 2). */
static uint32_t s48_slot_at(uint32_t p, uint32_t j)
{
    static const uint8_t tab[3][2] = {{1u, 2u}, {1u, 0u}, {0u, 2u}};
    return tab[p][j];
}

/* Walks the fan of vertex x of the base from triangle t (which holds x): every triangle
 * around x, each once, into out (when not NULL, at most cap); returns the count, or
 * UINT32_MAX beyond cap. Around an interior vertex it comes back to t; at a boundary vertex
 * it walks the other way from t too. */
static uint32_t s48_fan(const subd_sr48 *b, uint32_t x, uint32_t t, uint32_t *out, uint32_t cap)
{
    uint32_t n = 0, dir, lim = b->level_tri[1] + 1u;
    if (out && cap) out[n] = t;
    n++;
    for (dir = 0; dir < 2u; dir++) {
        uint32_t cur = t, v[3], p, q, slot, i;
        s48_tri_verts(b, cur, v);
        slot = s48_slot_at(s48_pos_of(v, x), dir);
        for (i = 0; i < lim; i++) {
            uint32_t nx = s48_base_nbr(b, cur, slot), w;
            s48_slot_ends(v, slot, &p, &q);
            w = p == x ? q : p; /* the edge's other end */
            if (nx == SUBD_NONE) break;
            if (nx == t) return n; /* around: interior vertex */
            if (n >= cap) return UINT32_MAX;
            if (out) out[n] = nx;
            n++;
            cur = nx;
            s48_tri_verts(b, cur, v);
            {
                uint32_t px = s48_pos_of(v, x), s0 = s48_slot_at(px, 0), s1 = s48_slot_at(px, 1), e0, e1;
                s48_slot_ends(v, s0, &e0, &e1);
                slot = (e0 == w || e1 == w) ? s1 : s0; /* leave by the other edge at x */
            }
        }
        if (i == lim) return UINT32_MAX;
    }
    return n;
}

/* Largest number of triangles around a base vertex. */
static uint32_t s48_valence(const subd_sr48 *b)
{
    uint32_t t, j, best = 0;
    for (t = 0; t < b->level_tri[1]; t++)
        for (j = 0; j < 3u; j++) {
            uint32_t n = s48_fan(b, b->tri_vert[3u * t + j], t, 0, 0xffffu);
            if (n > best) best = n;
        }
    return best;
}

/* ------------------------------------------------------------------------------------ */
/* Checks and plan                                                                        */

/* Does the mode keep L (the level-0 interpolant) per window vertex? (CHORD does not.) */
static uint32_t s48_has_l(const subd_sr48_stream_opts *o)
{
    return o->adapt.mode != SUBD_SR48_ADAPT_UNIFORM && o->adapt.mode != SUBD_SR48_ADAPT_CHORD;
}

static int s48_check(const subd_sr48 *b, const subd_sr48_stream_opts *o, uint32_t *valence)
{
    int st;
    if (!o) return SUBD_ERR_PARAM;
    /* every mode streams: the nested region (POINT, RAMP, PLANE, CALLBACK; subd_sr48_adapt_mode) or
     * the nested chordal criterion (CHORD, sr48_chord.c); the parameters as subd_sr48_extract
     * checks them (CHORD: eps > 0 and finite) */
    switch (o->adapt.mode) {
    case SUBD_SR48_ADAPT_UNIFORM: break;
    case SUBD_SR48_ADAPT_POINT:
    case SUBD_SR48_ADAPT_RAMP:
    case SUBD_SR48_ADAPT_PLANE:
    case SUBD_SR48_ADAPT_CALLBACK:
    case SUBD_SR48_ADAPT_CHORD:
        if (subd_sr48_adapt_check_(&o->adapt) != SUBD_OK) return SUBD_ERR_PARAM;
        break;
    default: return SUBD_ERR_PARAM;
    }
    if (o->adapt.max_level > SUBD_SR48_MAX_STEPS) return SUBD_ERR_PARAM;
    if ((st = s48_base_check(b)) != SUBD_OK) return st;
    *valence = s48_valence(b);
    if (*valence > SUBD_SR48_STREAM_MAX_VALENCE) return SUBD_ERR_TOO_BIG;
    if (*valence < 8u) *valence = 8u;
    return SUBD_OK;
}

int subd_sr48_stream_plan(const subd_sr48 *base, const subd_sr48_stream_opts *o, uint32_t *bytes, subd_diag *diag)
{
    subd_diag own;
    subd_diag *d = diag ? diag : &own;
    uint32_t val, b;
    s48_state *s;
    uint8_t *ring;
    int st;
    subd_diag_clear(d);
    if (!bytes) return subd_fail(d, SUBD_ERR_PARAM);
    if ((st = s48_check(base, o, &val)) != SUBD_OK) return subd_fail(d, st);
    st = s48_layout(0, o->adapt.max_level, val, s48_has_l(o), o->adapt.mode == SUBD_SR48_ADAPT_CHORD, &s, &ring, &b);
    if (st != SUBD_OK) return subd_fail(d, st);
    *bytes = b;
    return SUBD_OK;
}

/* ------------------------------------------------------------------------------------ */
/* Windows                                                                                */

static void s48_lev(const s48_state *s, uint32_t k, s48_win *w) { s48_win_at(s->lev + k * s->lev_size, s->off, w); }
static void s48_x(const s48_state *s, s48_win *w) { s48_win_at(s->xblk, s->xoff, w); }

static uint64_t s48_key(const s48_win *w, uint32_t t)
{
    return ((uint64_t)w->key[2u * t + 1u] << 32) | w->key[2u * t];
}
static void s48_set_key(s48_win *w, uint32_t t, uint64_t k)
{
    w->key[2u * t] = (uint32_t)k;
    w->key[2u * t + 1u] = (uint32_t)(k >> 32);
}
static void s48_set_id(s48_win *w, uint32_t v, uint64_t id)
{
    w->vid[2u * v] = (uint32_t)id;
    w->vid[2u * v + 1u] = (uint32_t)(id >> 32);
}

/* Level 0's window around base triangle t0: every base triangle within S48_RINGS vertex
 * rings, found by fan walks from the vertices at distance < S48_RINGS (BFS order), sorted
 * by index; local vertices and neighbours. 0 when a capacity is exceeded. */
static int s48_build0(s48_state *s, uint32_t t0)
{
    const subd_sr48 *b = s->base;
    uint32_t nt = 0, nv = 0, i, j, q;
    s48_win w;
    s48_lev(s, 0, &w);
    for (j = 0; j < 3u; j++) {
        s->gv[nv] = b->tri_vert[3u * t0 + j];
        s->gvt[nv] = t0;
        s->dist[nv++] = 0;
    }
    for (q = 0; q < nv; q++) {
        uint32_t x = s->gv[q], nf, f;
        if (s->dist[q] >= S48_RINGS) continue;
        nf = s48_fan(b, x, s->gvt[q], 0, 0xffffu);
        if (nf == UINT32_MAX) return 0;
        /* the whole fan into the free tail of gt, then merged (deduplicated) */
        /* the fan at gt's tail: a triangle appended at nt can only overwrite fan entries
         * already read (nt grows by at most one per entry read, and nt + nf <= wt) */
        if (nt + nf > s->wt) return 0;
        (void)s48_fan(b, x, s->gvt[q], s->gt + (s->wt - nf), nf);
        for (f = 0; f < nf; f++) {
            uint32_t tt = s->gt[s->wt - nf + f], dup = 0, u;
            for (i = 0; i < nt; i++)
                if (s->gt[i] == tt) dup = 1;
            if (dup) continue;
            for (j = 0; j < 3u; j++) {
                uint32_t vx = b->tri_vert[3u * tt + j], seen = 0;
                for (u = 0; u < nv; u++)
                    if (s->gv[u] == vx) seen = 1;
                if (seen) continue;
                if (nv >= s->wv) return 0;
                s->gv[nv] = vx;
                s->gvt[nv] = tt;
                s->dist[nv++] = (uint8_t)(s->dist[q] + 1u);
            }
            s->gt[nt++] = tt;
        }
    }
    /* sort the triangles (insertion sort: at most wt of them) */
    for (i = 1; i < nt; i++) {
        uint32_t x = s->gt[i];
        j = i;
        while (j > 0u && s->gt[j - 1u] > x) {
            s->gt[j] = s->gt[j - 1u];
            j--;
        }
        s->gt[j] = x;
    }
    for (i = 0; i < nt; i++) {
        uint32_t tt = s->gt[i];
        for (j = 0; j < 3u; j++) {
            uint32_t vx = b->tri_vert[3u * tt + j], u = 0, nb, lo, hi;
            while (s->gv[u] != vx) u++; /* present: added with the triangle */
            w.tv[3u * i + j] = (uint16_t)u;
            nb = s48_base_nbr(b, tt, j);
            if (nb == SUBD_NONE) {
                w.tn[3u * i + j] = S48_BND;
                continue;
            }
            lo = 0;
            hi = nt;
            while (lo < hi) {
                uint32_t mid = (lo + hi) / 2u;
                if (s->gt[mid] < nb) lo = mid + 1u;
                else hi = mid;
            }
            w.tn[3u * i + j] = (lo < nt && s->gt[lo] == nb) ? (uint16_t)lo : S48_OUT;
        }
        s48_set_key(&w, i, tt);
        if (tt == t0) w.hd[2] = i;
    }
    for (i = 0; i < nv; i++) {
        for (j = 0; j < 3u; j++) w.vp[3u * i + j] = b->pos[3u * s->gv[i] + j];
        s48_set_id(&w, i, s->gv[i]);
        w.vf[i] = S48_EXACT;
        if (w.vl)
            for (j = 0; j < 3u; j++) w.vl[3u * i + j] = s->l0[3u * i + j];
    }
    w.hd[0] = nt;
    w.hd[1] = nv;
    return 1;
}

static int s48_local(uint16_t n) { return n < S48_BND; }

static void s48_scatter(const s48_state *s, const s48_win *x, uint32_t v, uint32_t m, int boundary_ok)
{
    uint32_t q;
    if ((s->cnt[v] & 0x80000000u) && !boundary_ok) return;
    for (q = 0; q < 3u; q++) s->sum[3u * v + q] = subd_sum_add(s->sum[3u * v + q], x->vp[3u * m + q]);
    s->cnt[v]++;
    if (!(x->vf[m] & S48_EXACT)) s->dist[v] |= S48_INC;
}

/* Refines window p (level k) as a whole into X (level k+1), smoothing after an even level.
 * 0 on a capacity or range failure (s->err says which). */
static int s48_refine(s48_state *s, const s48_win *p, uint32_t k, s48_win *x)
{
    const uint32_t nt = p->hd[0], nvp = p->hd[1];
    const uint64_t off = (uint64_t)s->nv0 + (uint64_t)s->n0 * (((uint64_t)1 << k) - 1u);
    uint32_t i, j, nv = nvp, ovf = 0;
    for (i = 0; i < nvp; i++) s48_vcopy(x, i, p, i);
    for (i = 0; i < nt; i++) {
        const uint16_t *tv = p->tv + 3u * i;
        uint16_t nb = p->tn[3u * i], m;
        uint64_t key = s48_key(p, i);
        if (s48_local(nb) && nb < i) {
            m = s->mtab[nb];
        } else {
            uint32_t e0 = tv[1], e1 = tv[2], exact;
            if (nv >= s->xv) return 0;
            m = (uint16_t)nv++;
            if (s48_local(nb) && s->smooth) {
                e0 = tv[0];
                e1 = p->tv[3u * nb];
            }
            exact = (nb != S48_OUT) && (p->vf[e0] & p->vf[e1] & S48_EXACT);
            for (j = 0; j < 3u; j++) x->vp[3u * m + j] = subd_mid(p->vp[3u * e0 + j], p->vp[3u * e1 + j], &ovf);
            x->vf[m] = (uint8_t)(exact ? S48_EXACT : 0u);
            if (x->vl) /* L: the base midpoint, whatever the smoothing */
                for (j = 0; j < 3u; j++) x->vl[3u * m + j] = subd_mid(p->vl[3u * tv[1] + j], p->vl[3u * tv[2] + j], &ovf);
            s48_set_id(x, m, off + key);
        }
        s->mtab[i] = m;
        x->tv[6u * i] = m;
        x->tv[6u * i + 1u] = tv[0];
        x->tv[6u * i + 2u] = tv[1];
        x->tv[6u * i + 3u] = m;
        x->tv[6u * i + 4u] = tv[2];
        x->tv[6u * i + 5u] = tv[0];
        s48_set_key(x, 2u * i, 2u * key);
        s48_set_key(x, 2u * i + 1u, 2u * key + 1u);
    }
    if (ovf) {
        s->err = (uint32_t)(-SUBD_ERR_RANGE);
        return 0;
    }
    for (i = 0; i < nt; i++) {
        uint16_t nb = p->tn[3u * i], l0 = p->tn[3u * i + 1u], l1 = p->tn[3u * i + 2u];
        uint16_t *c0 = x->tn + 6u * i, *c1 = c0 + 3;
        c0[0] = s48_local(l0) ? (uint16_t)(2u * l0 + 1u) : l0;
        c0[1] = (uint16_t)(2u * i + 1u);
        c0[2] = s48_local(nb) ? (uint16_t)(2u * nb + 1u) : nb;
        c1[0] = s48_local(l1) ? (uint16_t)(2u * l1) : l1;
        c1[1] = s48_local(nb) ? (uint16_t)(2u * nb) : nb;
        c1[2] = (uint16_t)(2u * i);
    }
    x->hd[0] = 2u * nt;
    x->hd[1] = nv;
    if (s->smooth && ((k + 1u) & 1u) == 0u) {
        for (i = 0; i < nvp; i++) {
            s->cnt[i] = 0;
            s->dist[i] = 0;
            for (j = 0; j < 3u; j++) s->sum[3u * i + j] = 0;
        }
        for (i = 0; i < nt; i++) {
            const uint16_t *tv = p->tv + 3u * i;
            uint32_t sl;
            if (p->tn[3u * i] == S48_BND) {
                s->cnt[tv[1]] = 0x80000000u;
                s->cnt[tv[2]] = 0x80000000u;
            }
            for (sl = 0; sl < 3u; sl++)
                if (p->tn[3u * i + sl] == S48_OUT) { /* the edge's ends miss part of their fan */
                    s->dist[sl == 0u ? tv[1] : sl == 1u ? tv[0] : tv[2]] |= S48_INC;
                    s->dist[sl == 0u ? tv[2] : sl == 1u ? tv[1] : tv[0]] |= S48_INC;
                }
        }
        for (i = 0; i < nt; i++) {
            const uint16_t *tv = p->tv + 3u * i;
            uint16_t nb = p->tn[3u * i];
            uint32_t m = s->mtab[i];
            if (nb == S48_BND) {
                s48_scatter(s, x, tv[1], m, 1);
                s48_scatter(s, x, tv[2], m, 1);
                s48_scatter(s, x, tv[0], m, 0);
            } else if (nb == S48_OUT) {
                s->dist[tv[0]] |= S48_INC;
            } else if (i < nb) {
                s48_scatter(s, x, tv[1], m, 0);
                s48_scatter(s, x, tv[2], m, 0);
                s48_scatter(s, x, tv[0], m, 0);
                s48_scatter(s, x, p->tv[3u * nb], m, 0);
            }
        }
        for (i = 0; i < nvp; i++) {
            uint32_t n = s->cnt[i] & ~0x80000000u;
            if (n == 0u || (s->dist[i] & S48_INC)) {
                x->vf[i] = 0;
                continue;
            }
            for (j = 0; j < 3u; j++) x->vp[3u * i + j] = subd_avg(s->sum[3u * i + j], n, &ovf);
            x->vf[i] = S48_EXACT;
        }
        if (ovf) {
            s->err = (uint32_t)(-SUBD_ERR_RANGE);
            return 0;
        }
    }
    return 1;
}

/* Crops X to the triangles within S48_RINGS vertex rings of X's triangles c0 and c0 + 1
 * (the current triangle's children) into window w, in order. */
static int s48_crop(s48_state *s, const s48_win *x, uint32_t c0, s48_win *w)
{
    const uint32_t nt = x->hd[0], nv = x->hd[1];
    uint32_t i, j, r, kt = 0, kv = 0;
    for (i = 0; i < nv; i++) s->dist[i] = S48_FAR;
    for (j = 0; j < 6u; j++) s->dist[x->tv[3u * c0 + j]] = 0;
    for (r = 1; r < S48_RINGS; r++)
        for (i = 0; i < nt; i++) {
            const uint16_t *tv = x->tv + 3u * i;
            uint32_t md = s->dist[tv[0]];
            if (s->dist[tv[1]] < md) md = s->dist[tv[1]];
            if (s->dist[tv[2]] < md) md = s->dist[tv[2]];
            if (md + 1u > r) continue;
            for (j = 0; j < 3u; j++)
                if (s->dist[tv[j]] > r) s->dist[tv[j]] = (uint8_t)r;
        }
    for (i = 0; i < nv; i++) s->vmap[i] = S48_OUT;
    for (i = 0; i < nt; i++) {
        const uint16_t *tv = x->tv + 3u * i;
        uint32_t md = s->dist[tv[0]];
        if (s->dist[tv[1]] < md) md = s->dist[tv[1]];
        if (s->dist[tv[2]] < md) md = s->dist[tv[2]];
        if (md + 1u > S48_RINGS) {
            s->tmap[i] = S48_OUT;
            continue;
        }
        if (kt >= s->wt) return 0;
        s->tmap[i] = (uint16_t)kt++;
        for (j = 0; j < 3u; j++)
            if (s->vmap[tv[j]] == S48_OUT) {
                if (kv >= s->wv) return 0;
                s->vmap[tv[j]] = (uint16_t)kv++;
            }
    }
    for (i = 0; i < nv; i++) {
        uint16_t v = s->vmap[i];
        if (v == S48_OUT) continue;
        s48_vcopy(w, v, x, i);
    }
    for (i = 0; i < nt; i++) {
        uint16_t t = s->tmap[i];
        if (t == S48_OUT) continue;
        for (j = 0; j < 3u; j++) {
            uint16_t n = x->tn[3u * i + j];
            w->tv[3u * t + j] = s->vmap[x->tv[3u * i + j]];
            w->tn[3u * t + j] = s48_local(n) ? s->tmap[n] : n;
        }
        w->key[2u * t] = x->key[2u * i];
        w->key[2u * t + 1u] = x->key[2u * i + 1u];
    }
    w->hd[0] = kt;
    w->hd[1] = kv;
    w->hd[3] = s->tmap[c0];
    w->hd[4] = s->tmap[c0 + 1u];
    return 1;
}

/* Window w's triangle t as a stream triangle; 0 when a corner is not exact. *stop: the push
 * form's sink value (non-zero: stop the stream with it). */
static int s48_emit(const s48_state *s, const s48_win *w, uint32_t t, subd_stream_q *q, int *stop)
{
    subd_tri *o;
    uint32_t j, i;
    for (j = 0; j < 3u; j++)
        if (!(w->vf[w->tv[3u * t + j]] & S48_EXACT)) return 0;
    o = (subd_tri *)subd_stream_q_put(q);
    if (!o) return 0;
    for (j = 0; j < 3u; j++) {
        uint32_t v = w->tv[3u * t + j];
        for (i = 0; i < 3u; i++) {
            o->pos[j][i] = w->vp[3u * v + i];
            o->normal[j][i] = 0;
        }
        o->id[j] = ((uint64_t)w->vid[2u * v + 1u] << 32) | w->vid[2u * v];
    }
    o->face = s->t0;
    o->level = s->levels;
    *stop = subd_stream_q_commit(q);
    return 1;
}

/* ------------------------------------------------------------------------------------ */
/* Adaptive cuts (POINT, RAMP, PLANE, CALLBACK): sr48_extract.c's nested region, top down. */

static uint64_t s48_vid(const s48_win *w, uint32_t v)
{
    return ((uint64_t)w->vid[2u * v + 1u] << 32) | w->vid[2u * v];
}

/* The finest (max_level) position of the vertex with id `id`, a corner of triangle t of the
 * level-k window (k < levels): the windows k+1.. are refined and cropped along children
 * that keep the vertex as a corner (a corner of a triangle is a corner of one of its
 * children), and its position is read from the last refined window, where it is exact by
 * the ring rule (checked). Uses the blocks of levels > k and X only. 0 on failure. */
static int s48_finest(s48_state *s, uint32_t k, uint32_t t, uint64_t id, subd_real *out)
{
    s48_win w, x, c;
    uint32_t j, cur = t, q;
    for (j = k; j < s->levels; j++) {
        uint32_t ch;
        s48_lev(s, j, &w);
        s48_x(s, &x);
        /* child 0 = (m; apex, b0) keeps apex and b0, child 1 = (m; b1, apex) keeps b1 */
        ch = (s48_vid(&w, w.tv[3u * cur + 2u]) == id) ? 1u : 0u;
        if (!s48_refine(s, &w, j, &x)) return 0;
        if (j + 1u == s->levels) {
            for (q = 0; q < 3u; q++) {
                uint32_t v = x.tv[3u * (2u * cur + ch) + q];
                if (s48_vid(&x, v) != id) continue;
                if (!(x.vf[v] & S48_EXACT)) return 0;
                for (j = 0; j < 3u; j++) out[j] = x.vp[3u * v + j];
                return 1;
            }
            return 0;
        }
        s48_lev(s, j + 1u, &c);
        if (!s48_crop(s, &x, 2u * cur, &c)) return 0;
        cur = c.hd[3u + ch];
        if (cur == S48_OUT) return 0;
    }
    return 0;
}

/* L of the level-0 window of t0 (s->l0): each vertex's finest position, by a descent from
 * a base triangle at it. Rebuilds level 0 for every vertex; the caller rebuilds t0's. */
static int s48_level0_lin(s48_state *s, uint32_t t0)
{
    s48_win w;
    uint32_t nv, i, j;
    for (i = 0; i < 3u * s->wv; i++) s->l0[i] = 0; /* the descents' L: defined, unused */
    if (!s48_build0(s, t0)) return 0;
    s48_lev(s, 0, &w);
    nv = w.hd[1];
    for (i = 0; i < nv; i++) {
        s->lgv[i] = s->gv[i];
        s->lgvt[i] = s->gvt[i];
    }
    for (i = 0; i < nv; i++) {
        if (s->levels == 0u) {
            for (j = 0; j < 3u; j++) s->l0[3u * i + j] = s->base->pos[3u * s->lgv[i] + j];
            continue;
        }
        if (!s48_build0(s, s->lgvt[i])) return 0;
        if (!s48_finest(s, 0, w.hd[2], s->lgv[i], s->l0 + 3u * i)) return 0;
    }
    return 1;
}

/* The adaptation box A (RAMP, POINT's default radius; subd_sr48_adapt_mode): the finest
 * positions of the level-0 triangles' corners, each vertex by one descent from the
 * lowest-index triangle of its fan (so once); then POINT's radius. levels > 0. */
static int s48_adapt_box(s48_state *s)
{
    const subd_sr48 *b = s->base;
    uint32_t t, j, i, zero = 0;
    s48_win w;
    for (i = 0; i < 3u * s->wv; i++) s->l0[i] = 0; /* the descents' L: defined, unused */
    subd_sr48_box_grow_(b->pos, &zero, 0, s->blo, s->bhi, 1);
    for (t = 0; t < s->n0; t++)
        for (j = 0; j < 3u; j++) {
            uint32_t v = b->tri_vert[3u * t + j], nf = s48_fan(b, v, t, s->gt, s->wt), low = 1;
            subd_real p[3];
            if (nf == UINT32_MAX) return 0;
            for (i = 0; i < nf; i++)
                if (s->gt[i] < t) low = 0;
            if (!low) continue;
            if (!s48_build0(s, t)) return 0;
            s48_lev(s, 0, &w);
            if (!s48_finest(s, 0, w.hd[2], v, p)) return 0;
            subd_sr48_box_grow_(p, &zero, 1, s->blo, s->bhi, 0);
        }
    if (s->ad.mode == SUBD_SR48_ADAPT_POINT && s->radius == 0)
        s->radius = subd_sr48_default_radius_(s->blo, s->bhi, s->levels);
    return 1;
}

/* CHORD (the criterion and its proof: sr48_chord.c). Rebuilds the windows of levels 0..k
 * along the path of the level-k triangle with key `key` (T0 * 2^k + its child bits), as
 * the walk leaves them when that triangle is current (hd[2], hd[5]): the same calls on the
 * same input, so the same bits. 0 on failure. */
static int s48c_path(s48_state *s, uint64_t key, uint32_t k)
{
    s48_win w, x, c;
    uint32_t j;
    if (!s48_build0(s, (uint32_t)(key >> k))) return 0;
    for (j = 0; j < k; j++) {
        uint32_t bit = (uint32_t)(key >> (k - 1u - j)) & 1u;
        s48_lev(s, j, &w);
        s48_x(s, &x);
        s48_lev(s, j + 1u, &c);
        w.hd[5] = bit + 1u;
        if (!s48_refine(s, &w, j, &x) || !s48_crop(s, &x, 2u * w.hd[2], &c)) return 0;
        c.hd[2] = c.hd[3u + bit];
        if (c.hd[2] == S48_OUT) return 0;
    }
    s48_lev(s, k, &w);
    w.hd[5] = 0;
    return 1;
}

/* The corners' sources of the walk's node at level j, child `bit` of the node at j - 1
 * (apex, b0, b1) with new vertex M = 3 + (j - 1): child 0 = (M; apex, b0), 1 = (M; b1, apex). */
static void s48c_child(s48_state *s, uint32_t j, uint32_t bit)
{
    const uint32_t *p = s->csrc + 3u * (j - 1u);
    uint32_t *c = s->csrc + 3u * j;
    c[0] = 3u + (j - 1u);
    c[1] = bit ? p[2] : p[0];
    c[2] = bit ? p[0] : p[1];
}

/* The vertex created by the walk's node at level i (its finest position known) against
 * the interpolant of every node from the walked triangle (level k) down to it. */
static int s48c_test(const s48_state *s, uint32_t k, uint32_t i)
{
    const subd_real *p = s->cpos + 3u * (3u + i);
    uint32_t a, l, q;
    for (a = k; a <= i; a++) {
        subd_real c[9];
        uint32_t path = 0;
        for (q = 0; q < 9u; q++) c[q] = s->cpos[3u * s->csrc[3u * a + q / 3u] + q % 3u];
        for (l = a; l < i; l++) path |= (s->cch[l] - 1u) << (l - a);
        if (subd_sr48_chord_beyond_(c, path, i - a, p, s->ad.eps)) return 1;
    }
    return 0;
}

/* W(t) > eps for triangle ts of the level-k window (k < levels)? Walks ts's subtree depth
 * first (pre-order, child 0 first) with the windows of levels k+1.. and X (free while
 * level k decides): each node's window is refined, then cropped to its children as the
 * stream does, so every position is the stream's (exact by the ring rule, checked). The
 * walked triangle's corners get their finest positions by descents (s48_finest), so does a
 * node's new vertex (from the cropped window of its children, where it is their apex; at
 * level max_level - 1 it is read from the refined window, the finest level); each is then
 * tested against the interpolants of the node and its ancestors down from ts, whose
 * corners are all known by then. 1 beyond, 0 within, -1 failure. */
static int s48_chord_walk(s48_state *s, uint32_t k, uint32_t ts)
{
    const uint32_t last = s->levels - 1u;
    s48_win w, x, c;
    uint32_t j = k, q;
    s48_lev(s, k, &w);
    for (q = 0; q < 3u; q++)
        if (!s48_finest(s, k, ts, s48_vid(&w, w.tv[3u * ts + q]), s->cpos + 3u * q)) return -1;
    s->ccur[k] = ts;
    s->cch[k] = 0;
    for (q = 0; q < 3u; q++) s->csrc[3u * k + q] = q;
    for (;;) {
        uint32_t cur = s->ccur[j], v;
        subd_real *pm = s->cpos + 3u * (3u + j);
        s48_lev(s, j, &w);
        s48_x(s, &x);
        if (!s48_refine(s, &w, j, &x)) return -1;
        v = x.tv[6u * cur]; /* the node's new vertex */
        if (j < last) {
            uint64_t id = s48_vid(&x, v);
            s48_lev(s, j + 1u, &c);
            if (!s48_crop(s, &x, 2u * cur, &c) || c.hd[3] == S48_OUT) return -1;
            /* its finest position: a descent from child 0 (blocks > j + 1 and X; child 0's
             * walk rebuilds them from block j + 1) */
            if (!s48_finest(s, j + 1u, c.hd[3], id, pm)) return -1;
            s->cch[j] = 1u; /* in child 0 while its new vertex is tested */
            if (s48c_test(s, k, j)) return 1;
            j++;
            s->ccur[j] = c.hd[3];
            s->cch[j] = 0;
            s48c_child(s, j, 0);
            continue;
        }
        /* a leaf node: its new vertex is at the finest level in X */
        if (!(x.vf[v] & S48_EXACT)) return -1;
        for (q = 0; q < 3u; q++) pm[q] = x.vp[3u * v + q];
        if (s48c_test(s, k, j)) return 1;
        /* up to the deepest node whose child 1 is not walked yet */
        for (;;) {
            if (j == k) return 0;
            j--;
            if (s->cch[j] == 1u) break;
        }
        s->cch[j] = 2u;
        s48_lev(s, j + 1u, &c); /* cropped to both children of node j, untouched below */
        j++;
        s->ccur[j] = c.hd[4];
        s->cch[j] = 0;
        s48c_child(s, j, 1u);
        if (s->ccur[j] == S48_OUT) return -1;
    }
}

/* The verdict cache, direct mapped (S48C_NC slots, a power of two) by key and level: -1
 * unknown, 0 within (the triangle or one of its ancestors is: W does not grow down the
 * hierarchy), 1 beyond. Entries: key lo, key hi, level | verdict << 8 | 1 << 9 (valid). */
static uint32_t s48c_slot(uint64_t key, uint32_t k)
{
    uint64_t h = (key ^ ((uint64_t)k << 58)) * 0x9e3779b97f4a7c15u;
    return (uint32_t)(h >> 40) & (S48C_NC - 1u);
}

static int s48c_cached(const s48_state *s, uint64_t key, uint32_t k)
{
    uint32_t d;
    for (d = 0; d <= k; d++) {
        const uint32_t *e = s->cache + 3u * s48c_slot(key >> d, k - d);
        if (e[0] != (uint32_t)(key >> d) || e[1] != (uint32_t)(key >> (d + 32u)) || (e[2] & 0x2ffu) != 0x200u + k - d)
            continue;
        if (d == 0u) return (int)((e[2] >> 8) & 1u);
        if (((e[2] >> 8) & 1u) == 0u) return 0;
    }
    return -1;
}

static void s48c_remember(s48_state *s, uint64_t key, uint32_t k, int dirty)
{
    uint32_t *e = s->cache + 3u * s48c_slot(key, k);
    e[0] = (uint32_t)key;
    e[1] = (uint32_t)(key >> 32);
    e[2] = k | ((uint32_t)dirty << 8) | 0x200u;
}

/* CHORD's decision for the current triangle t of the level-k window: W(s) > eps for some
 * s in the star of t's diamond (the window triangles that share a vertex with it; all of
 * them are in the window, see s48_wants)? t is walked in place; another star triangle
 * after rebuilding the windows 0..k along its path, and the current path is rebuilt after.
 * 1 split, 0 leaf, -1 failure. */
static int s48_chord_wants(s48_state *s, uint32_t k, uint32_t t)
{
    s48_win w;
    uint32_t vs[4], nv = 3, i, j, q, ns = 1, moved = 0;
    uint64_t cur;
    int r = 0;
    uint16_t nb;
    s48_lev(s, k, &w);
    nb = w.tn[3u * t];
    cur = s48_key(&w, t);
    for (j = 0; j < 3u; j++) vs[j] = w.tv[3u * t + j];
    if (s48_local(nb)) vs[nv++] = w.tv[3u * nb];
    s->ckey[0] = (uint32_t)cur;
    s->ckey[1] = (uint32_t)(cur >> 32);
    for (i = 0; i < w.hd[0]; i++) {
        int touch = 0;
        if (i == t) continue;
        for (j = 0; j < 3u; j++)
            for (q = 0; q < nv; q++)
                if (w.tv[3u * i + j] == vs[q]) touch = 1;
        if (!touch) continue;
        s->ckey[2u * ns] = w.key[2u * i];
        s->ckey[2u * ns + 1u] = w.key[2u * i + 1u];
        ns++;
    }
    for (i = 0; i < ns && r == 0; i++) {
        uint64_t key = ((uint64_t)s->ckey[2u * i + 1u] << 32) | s->ckey[2u * i];
        r = s48c_cached(s, key, k);
        if (r >= 0) continue;
        if (i == 0u) {
            r = s48_chord_walk(s, k, t);
        } else {
            moved = 1;
            if (!s48c_path(s, key, k)) return -1;
            s48_lev(s, k, &w);
            r = s48_chord_walk(s, k, w.hd[2]);
        }
        if (r < 0) return -1;
        s48c_remember(s, key, k, r);
    }
    if (moved && !s48c_path(s, cur, k)) return -1;
    return r;
}

/* Does the current triangle t of the level-k window (k < levels) split its diamond? The
 * region: L's box over the window's triangles that share a vertex with the diamond (all of
 * them are in the window: the diamond is within one ring of t). */
static int s48_wants(s48_state *s, const s48_win *w, uint32_t t, uint32_t k)
{
    uint32_t vs[4], nv = 3, i, j, q;
    subd_real lo[3], hi[3];
    uint16_t nb = w->tn[3u * t];
    if (s->chord) return s48_chord_wants(s, k, t); /* 1, 0, or -1: a failed walk */
    for (j = 0; j < 3u; j++) vs[j] = w->tv[3u * t + j];
    if (s48_local(nb)) vs[nv++] = w->tv[3u * nb];
    for (j = 0; j < 3u; j++) {
        lo[j] = SUBD_REAL_MAX;
        hi[j] = -SUBD_REAL_MAX;
    }
    for (i = 0; i < w->hd[0]; i++) {
        int touch = 0;
        for (j = 0; j < 3u; j++)
            for (q = 0; q < nv; q++)
                if (w->tv[3u * i + j] == vs[q]) touch = 1;
        if (!touch) continue;
        for (j = 0; j < 3u; j++) {
            const subd_real *l = w->vl + 3u * w->tv[3u * i + j];
            for (q = 0; q < 3u; q++) {
                if (l[q] < lo[q]) lo[q] = l[q];
                if (l[q] > hi[q]) hi[q] = l[q];
            }
        }
    }
    return subd_sr48_box_wants_(&s->ad, s->radius, s->blo, s->bhi, lo, hi, k);
}

/* Emits triangle t of the level-k window as a leaf of the cut (k < levels): its corners'
 * finest positions by descents. */
static int s48_emit_leaf(s48_state *s, uint32_t k, uint32_t t, subd_stream_q *q, int *stop)
{
    subd_tri *o;
    subd_real p[3][3];
    uint64_t id[3];
    uint32_t j, i;
    s48_win w;
    s48_lev(s, k, &w);
    for (j = 0; j < 3u; j++) id[j] = s48_vid(&w, w.tv[3u * t + j]);
    for (j = 0; j < 3u; j++)
        if (!s48_finest(s, k, t, id[j], p[j])) return 0;
    o = (subd_tri *)subd_stream_q_put(q);
    if (!o) return 0;
    for (j = 0; j < 3u; j++) {
        for (i = 0; i < 3u; i++) {
            o->pos[j][i] = p[j][i];
            o->normal[j][i] = 0;
        }
        o->id[j] = id[j];
    }
    o->face = s->t0;
    o->level = k;
    *stop = subd_stream_q_commit(q);
    return 1;
}

/* Back up one level after a triangle's subtree is done: to the parent, or at level 0 to the
 * next base triangle (whose window is built on the next step). */
static void s48_up(s48_state *s)
{
    if (s->k == 0u) {
        s->t0++;
        s->built = 0;
    } else {
        s->k--;
    }
}

/* One batch: the next one or two triangles of the depth-first walk; q->ended after the last
 * level-0 triangle. */
static int s48_step(void *state, subd_stream_q *q, subd_diag *d)
{
    s48_state *s = (s48_state *)state;
    s48_win w, x, c;
    int stop = 0, wants;
    for (;;) {
        if (s->t0 >= s->n0) {
            q->ended = 1;
            return SUBD_OK;
        }
        if (!s->boxed) {
            if (!s48_adapt_box(s)) goto fail;
            s->boxed = 1;
        }
        if (!s->built) {
            if (s->adapt && !s->chord && !s48_level0_lin(s, s->t0)) goto fail;
            if (!s48_build0(s, s->t0)) goto fail;
            s->k = 0;
            s->built = 1;
            s48_lev(s, 0, &w);
            w.hd[5] = 0;
            if (s->levels == 0u) {
                if (!s48_emit(s, &w, w.hd[2], q, &stop)) goto fail;
                s->t0++;
                s->built = 0;
                return stop;
            }
        }
        s48_lev(s, s->k, &w);
        if (s->adapt && w.hd[5] == 0u && (wants = s48_wants(s, &w, w.hd[2], s->k)) <= 0) {
            /* a leaf below max_level (or a failed CHORD walk) */
            if (wants < 0) goto fail;
            if (!s48_emit_leaf(s, s->k, w.hd[2], q, &stop)) goto fail;
            s48_up(s);
            return stop;
        }
        if (s->k + 1u == s->levels) {
            s48_x(s, &x);
            if (!s48_refine(s, &w, s->k, &x)) goto fail;
            if (!s48_emit(s, &x, 2u * w.hd[2], q, &stop)) goto fail;
            if (stop) return stop;
            if (!s48_emit(s, &x, 2u * w.hd[2] + 1u, q, &stop)) goto fail;
            s48_up(s);
            return stop;
        }
        if (w.hd[5] == 0u) {
            s48_x(s, &x);
            s48_lev(s, s->k + 1u, &c);
            if (!s48_refine(s, &w, s->k, &x)) goto fail;
            if (!s48_crop(s, &x, 2u * w.hd[2], &c)) goto fail;
        }
        if (w.hd[5] < 2u) {
            s48_lev(s, s->k + 1u, &c);
            c.hd[2] = c.hd[3u + w.hd[5]];
            c.hd[5] = 0;
            w.hd[5]++;
            s->k++;
            continue;
        }
        if (s->k == 0u) {
            s->t0++;
            s->built = 0;
        } else {
            s->k--;
        }
    }
fail:
    d->face = s->t0;
    return s->err ? -(int)s->err : SUBD_ERR_TOO_BIG;
}

int subd_sr48_stream_begin(subd_arena *a, const subd_sr48 *base, const subd_sr48_stream_opts *o, subd_stream *str,
                           subd_diag *diag)
{
    subd_entry e;
    subd_diag *d = subd_entry_begin(&e, a, diag);
    uint32_t val, bytes;
    s48_state *s;
    uint8_t *ring;
    int st;
    if (!a || !str) return subd_entry_fail(&e, SUBD_ERR_PARAM);
    if ((st = s48_check(base, o, &val)) != SUBD_OK) return subd_entry_fail(&e, st);
    if ((st = s48_layout(0, o->adapt.max_level, val, s48_has_l(o), o->adapt.mode == SUBD_SR48_ADAPT_CHORD, &s, &ring,
                         &bytes)) != SUBD_OK)
        return subd_entry_fail(&e, st);
    if (bytes > subd_arena_free_bytes(a)) {
        d->bytes_needed = bytes;
        return subd_entry_fail(&e, SUBD_ERR_NOMEM);
    }
    (void)s48_layout(a, o->adapt.max_level, val, s48_has_l(o), o->adapt.mode == SUBD_SR48_ADAPT_CHORD, &s, &ring,
                     &bytes); /* fits */
    s->impl.step = s48_step;
    s->impl.ring = &s->ring;
    s->impl.ring_items = ring;
    s->base = base;
    s->levels = o->adapt.max_level;
    s->adapt = o->adapt.mode != SUBD_SR48_ADAPT_UNIFORM ? 1u : 0u;
    s->ad = o->adapt;
    s->radius = o->adapt.radius;
    s->boxed = (s->levels > 0u && (o->adapt.mode == SUBD_SR48_ADAPT_RAMP ||
                                   (o->adapt.mode == SUBD_SR48_ADAPT_POINT && o->adapt.radius == 0)))
                   ? 0u
                   : 1u;
    s->smooth = (base->flags & SUBD_SR48_NO_SMOOTH) ? 0u : 1u;
    s->nv0 = base->num_verts;
    s->n0 = base->level_tri[1];
    s->t0 = 0;
    s->k = 0;
    s->built = 0;
    s->err = 0;
    s->chord = o->adapt.mode == SUBD_SR48_ADAPT_CHORD ? 1u : 0u;
    if (s->chord) {
        uint32_t i;
        for (i = 0; i < 3u * S48C_NC; i++) s->cache[i] = 0; /* no valid entry */
    }
    subd_stream_start(str, a, e.mark, SUBD_STREAM_TRIS, &s->impl, 2u);
    return subd_entry_ok(&e);
}

int subd_sr48_stream(subd_arena *a, const subd_sr48 *base, const subd_sr48_stream_opts *o, const subd_tri_sink *sink,
                     subd_diag *diag)
{
    subd_entry e;
    subd_stream s;
    int st;
    (void)subd_entry_begin(&e, a, diag);
    if (!sink || !sink->tri) return subd_entry_fail(&e, SUBD_ERR_PARAM);
    st = subd_sr48_stream_begin(a, base, o, &s, diag);
    if (st != SUBD_OK) return st;
    return subd_stream_run_tris(&s, sink, diag);
}
