/* SPDX-License-Identifier: MIT */
/* Streaming semi-regular 4-8 refinement (paper: semi-regular-4-8-refinement-box-splines.txt,
 * sections 4 and 6).
 * Length (~1 490 lines): four pieces share one window layout and state - the window
 * (refine, smooth, crop, descent to the finest level), the uniform tile (s48_tile), the CHORD
 * walk over the deeper windows and the forcing diamonds (its test and proof are in
 * sr48_chord.c) and the stream driver (plan, begin, step, adaptive decisions); the split into sr48_window.c, the chord walk and sr48_stream.c behind
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
 * Uniform tiles: the last m = SUBD_SR48_STREAM_TILE_LEVELS levels (all when L <= m) are not
 * walked one triangle at a time: the current level L-m triangle's window is refined m times
 * breadth first, each time cropped to the rings of the set of its descendants at that level
 * (contiguous in the refined window, which is sorted by key), and its 2^m descendants are
 * emitted from the last refined window in key order (s48_tile). The tile window contains
 * every window the depth-first walk would crop for one of the descendants (rings of a union
 * are the union of the rings), so the exactness argument below carries over, and the
 * triangles and their order are unchanged. The level-0 window of a uniform stream holds the
 * rings of both children of a hybrid triangle (base triangles 2H, 2H + 1) and serves both.
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
 * the current triangle's diamond D splits iff a triangle of S(D) (the diamonds whose split
 * forces D's, S48C_M levels down, then the stars of the deepest of them) has a chordal
 * deviation of subd_sr48_extract's kind above eps. F(D)'s first levels come from the
 * level-k window's adjacency (s48c_desc); S(D) lies under D's star (in the window), whose
 * triangles are walked to max_level with the windows of the levels below (s48_chord_walk:
 * free at the decision; a triangle whose subtree cannot hold a member is skipped,
 * s48c_may); the current triangle is walked in place, another one after rebuilding the
 * windows 0..k along its path (s48c_path: the same calls, so the same bits), and the
 * current path is rebuilt afterwards.
 *
 * Memory: the fixed state block, the overflow ring (2 triangles), L window blocks (uniform:
 * L - m + 1, then the tile window), the refined window (twice the triangles of the larger of
 * the two), the smoothing sums and the crop's maps (CHORD: the walk's per-level state, the
 * star's keys, F(D)'s first levels); all sized by the window capacities of
 * SUBD_SR48_STREAM_BYTES, which depend on the largest valence (and the tile's m) only.
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
#define S48C_M SUBD_SR48_STREAM_CHORD_EXACT_ /* CHORD: levels of exact descendants (sr48_chord.c) */
#define S48C_ND SUBD_SR48_STREAM_CHORD_DESC_  /* CHORD: their capacity, triangles              */

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
static inline void s48_vcopy(const s48_win *dst, uint32_t dv, const s48_win *src, uint32_t sv)
{
    dst->vp[3u * dv] = src->vp[3u * sv];
    dst->vp[3u * dv + 1u] = src->vp[3u * sv + 1u];
    dst->vp[3u * dv + 2u] = src->vp[3u * sv + 2u];
    dst->vid[2u * dv] = src->vid[2u * sv];
    dst->vid[2u * dv + 1u] = src->vid[2u * sv + 1u];
    dst->vf[dv] = src->vf[sv];
    if (dst->vl) {
        dst->vl[3u * dv] = src->vl[3u * sv];
        dst->vl[3u * dv + 1u] = src->vl[3u * sv + 1u];
        dst->vl[3u * dv + 2u] = src->vl[3u * sv + 2u];
    }
}

typedef struct s48_state {
    subd_stream_impl impl; /* first: stream.c's view */
    subd_stream_ring ring;
    const subd_sr48 *base;
    uint32_t levels, smooth, wt, wv, xv, nv0, n0;
    uint32_t at, av;   /* the tile window's capacities (uniform)                           */
    uint32_t tm;       /* the tile's levels m (uniform; 1: no tile, s48_tile_levels)       */
    uint32_t tcur, tend; /* uniform: X's triangles still to emit (tcur < tend: a tile is out) */
    uint32_t t0, k, built, err;
    uint8_t *lev;      /* level windows 0..L-1 (uniform: 0..L-m), blocks of lev_size       */
    uint8_t *ablk, *xblk; /* the tile window A (uniform), the refined window X          */
    uint32_t lev_size;
    uint32_t off[8], aoff[8], xoff[8];
    subd_sr48_adapt ad;
    uint32_t adapt;    /* POINT, RAMP, PLANE, CALLBACK: the nested-region cut (subd_sr48_adapt_mode) */
    uint32_t boxed;    /* RAMP, POINT's default radius: 0 until the adaptation box is found */
    subd_real blo[3], bhi[3], radius; /* the adaptation box A; POINT's radius (resolved)  */
    subd_real *l0;     /* L of the level-0 window's vertices (3 per vertex)                */
    uint32_t *lgv, *lgvt; /* the level-0 window's vertices and a triangle at each, kept     */
    subd_sum *sum;     /* 3 per vertex (reserved as 8 bytes each in both arithmetics)     */
    uint32_t *cnt;
    uint8_t *dist;
    uint16_t *mtab, *tmap, *vmap;
    uint32_t *gt, *gv, *gvt; /* level-0 window: triangles, vertices, a triangle at each     */
    /* CHORD (sr48_chord.c's criterion, s48_chord_wants): per walk level the triangle, the
     * child state, the corners' sources (0..2 the walked triangle's corners, 3 + j the vertex
     * level j's node creates), whether it counts; the star's keys; the decided diamond's
     * descendants per level (count, then packed window triangle + path, key lo, key hi) */
    uint32_t *ccur, *cch, *csrc, *cfl, *ckey, *cdn, *cdesc;
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

/* The tile's depth m (uniform mode): the last m levels are refined breadth first. */
static uint32_t s48_tile_levels(uint32_t levels, uint32_t uniform)
{
    if (!uniform) return 1u;
    return levels < SUBD_SR48_STREAM_TILE_LEVELS ? (levels > 0u ? levels : 1u) : SUBD_SR48_STREAM_TILE_LEVELS;
}

/* The one layout of plan and begin (layout.h's walk). Uniform: levels 0..L-m in level
 * windows, the tile window A (the current level L-m triangle's descendants at one level
 * below max_level, with their rings) and X of twice A; otherwise levels 0..L-1 and X. */
static int s48_layout(subd_arena *a, uint32_t levels, uint32_t valence, uint32_t nl, uint32_t chord, s48_state **ps,
                      uint8_t **ring, uint32_t *bytes)
{
    subd_layout y;
    const uint32_t m = s48_tile_levels(levels, !nl && !chord), tile = m > 1u;
    const uint32_t nlev = levels >= m ? levels - m + 1u : 1u;
    uint32_t ct = s48_cap_t(valence), cv = s48_cap_v(valence), off[8];
    uint32_t at = tile ? SUBD_SR48_STREAM_TT_(valence, m) : ct, av = tile ? SUBD_SR48_STREAM_TV_(valence, m) : cv;
    uint32_t mt = at > ct ? at : ct, xv = (av > cv ? av : cv) + mt;
    uint32_t lsz = s48_win_layout(ct, cv, nl, off), asz = tile ? s48_win_layout(at, av, nl, off) : 0u;
    uint32_t xsz = s48_win_layout(2u * mt, xv, nl, off);
    s48_state *s;
    subd_layout_begin(&y, a);
    s = subd_layout_take(&y, 1u, SUBD_STREAM_STATE_BYTES);
    *ring = subd_layout_take(&y, 2u, (uint32_t)sizeof(subd_tri));
    if (s) {
        s->wt = ct;
        s->wv = cv;
        s->at = at;
        s->av = av;
        s->xv = xv;
        s->tm = m;
        s->lev_size = lsz;
        (void)s48_win_layout(ct, cv, nl, s->off);
        (void)s48_win_layout(at, av, nl, s->aoff);
        (void)s48_win_layout(2u * mt, xv, nl, s->xoff);
    }
    {
        uint8_t *lev = subd_layout_take(&y, nlev, lsz);
        uint8_t *ab = tile ? subd_layout_take(&y, 1u, asz) : 0;
        uint8_t *x = subd_layout_take(&y, 1u, xsz);
        subd_sum *sum = subd_layout_take(&y, 3u * xv, 8u);
        uint32_t *cnt = subd_layout_take(&y, xv, 4u);
        uint8_t *dist = subd_layout_take(&y, xv, 1u);
        uint16_t *mtab = subd_layout_take(&y, mt, 2u);
        uint16_t *tmap = subd_layout_take(&y, 2u * mt, 2u);
        uint16_t *vmap = subd_layout_take(&y, xv, 2u);
        uint32_t *gt = subd_layout_take(&y, ct, 4u);
        uint32_t *gv = subd_layout_take(&y, cv, 4u);
        uint32_t *gvt = subd_layout_take(&y, cv, 4u);
        subd_real *l0 = nl ? subd_layout_take(&y, 3u * cv, (uint32_t)sizeof(subd_real)) : 0;
        uint32_t *lgv = nl ? subd_layout_take(&y, cv, 4u) : 0;
        uint32_t *lgvt = nl ? subd_layout_take(&y, cv, 4u) : 0;
        uint32_t *ci = chord ? subd_layout_take(&y, 6u * (levels + 1u) + 2u * ct + S48C_M + 1u + 3u * S48C_ND, 4u) : 0;
        subd_real *cp = chord ? subd_layout_take(&y, 3u * (levels + 4u), (uint32_t)sizeof(subd_real)) : 0;
        if (s) {
            s->l0 = l0;
            s->lgv = lgv;
            s->lgvt = lgvt;
            s->lev = lev;
            s->ablk = ab;
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
            s->cfl = ci ? ci + 5u * (levels + 1u) : 0;
            s->ckey = ci ? ci + 6u * (levels + 1u) : 0;
            s->cdn = ci ? ci + 6u * (levels + 1u) + 2u * ct : 0;
            s->cdesc = ci ? ci + 6u * (levels + 1u) + 2u * ct + S48C_M + 1u : 0;
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
    uint32_t nt = 0, nv = 0, i, j, q, u, p;
    s48_win w;
    s48_lev(s, 0, &w);
    /* uniform: the rings of both children of t0's hybrid triangle (t0 even and odd), so
     * that one window serves both (s48_step) */
    for (p = s->adapt ? t0 : (t0 & ~1u); p <= (s->adapt ? t0 : (t0 | 1u)); p++)
        for (j = 0; j < 3u; j++) {
            uint32_t vx = b->tri_vert[3u * p + j], seen = 0;
            for (u = 0; u < nv; u++)
                if (s->gv[u] == vx) seen = 1;
            if (seen) continue;
            s->gv[nv] = vx;
            s->gvt[nv] = p;
            s->dist[nv++] = 0;
        }
    for (q = 0; q < nv; q++) {
        uint32_t x = s->gv[q], nf, f;
        if (s->dist[q] >= S48_RINGS) continue;
        /* the whole fan at the free tail of gt, then merged (deduplicated): a triangle
         * appended at nt can only overwrite fan entries already read (nt grows by at most
         * one per entry read, and nt + nf <= wt) */
        nf = s48_fan(b, x, s->gvt[q], s->gt + nt, s->wt - nt);
        if (nf == UINT32_MAX) return 0;
        for (i = 0; i < nf; i++) s->gt[s->wt - 1u - i] = s->gt[nt + nf - 1u - i];
        for (f = 0; f < nf; f++) {
            uint32_t tt = s->gt[s->wt - nf + f], dup = 0;
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
            uint32_t vx = b->tri_vert[3u * tt + j], nb, lo, hi;
            u = 0;
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
        if (tt == (t0 | 1u)) w.hd[4] = i;
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

#ifdef S48_DBG
uint32_t s48_dbg[40];
#endif
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
#ifdef S48_DBG
    s48_dbg[30] += nt; s48_dbg[31]++;
#endif
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

/* Crops X to the triangles within S48_RINGS vertex rings of X's triangles c0 .. c0 + n - 1
 * (the current triangle's descendants: contiguous, X being sorted by key) into window w of
 * capacity ct triangles, cv vertices, in order; w's hd[3] is c0's index in w, hd[4] c0 + 1's. */
static int s48_crop_n(s48_state *s, const s48_win *x, uint32_t c0, uint32_t n, s48_win *w, uint32_t ct, uint32_t cv)
{
    const uint32_t nt = x->hd[0], nv = x->hd[1];
    uint32_t i, j, r, kt = 0, kv = 0;
#ifdef S48_DBG
    s48_dbg[32] += nt; s48_dbg[33]++;
#endif
    for (i = 0; i < nv; i++) s->dist[i] = S48_FAR;
    for (j = 0; j < 3u * n; j++) s->dist[x->tv[3u * c0 + j]] = 0;
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
        if (kt >= ct) return 0;
        s->tmap[i] = (uint16_t)kt++;
        for (j = 0; j < 3u; j++)
            if (s->vmap[tv[j]] == S48_OUT) {
                if (kv >= cv) return 0;
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
            uint16_t nb = x->tn[3u * i + j];
            w->tv[3u * t + j] = s->vmap[x->tv[3u * i + j]];
            w->tn[3u * t + j] = s48_local(nb) ? s->tmap[nb] : nb;
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

/* s48_crop_n to the current triangle's two children c0, c0 + 1, into a level window. */
static int s48_crop(s48_state *s, const s48_win *x, uint32_t c0, s48_win *w)
{
    return s48_crop_n(s, x, c0, 2u, w, s->wt, s->wv);
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

/* Uniform tiles: the current triangle t of the level-k window w (k = L - m) refined
 * breadth first down to max_level: m - 1 times refined into X and cropped into the tile
 * window A to the rings of t's descendants (contiguous in X: X is sorted by key), then
 * refined once more into X, whose t's 2^m descendants s->tcur .. s->tend - 1 are emitted
 * in key order by s48_tile_emit. A contains every window the depth-first walk would crop
 * for one descendant (a union of rings), so every emitted corner is exact (checked). */
static int s48_tile(s48_state *s, const s48_win *w, uint32_t t)
{
    s48_win x, a;
    const s48_win *p = w;
    uint32_t j, lo = t, n = 1;
    s48_x(s, &x);
    s48_win_at(s->ablk, s->aoff, &a);
    for (j = 0; j < s->tm; j++) {
        if (!s48_refine(s, p, s->k + j, &x)) return 0;
        lo *= 2u;
        n *= 2u;
        if (j + 1u == s->tm) break;
        if (!s48_crop_n(s, &x, lo, n, &a, s->at, s->av)) return 0;
#ifdef S48_DBG
        if (a.hd[0] > s48_dbg[2u * j]) s48_dbg[2u * j] = a.hd[0];
        if (a.hd[1] > s48_dbg[2u * j + 1u]) s48_dbg[2u * j + 1u] = a.hd[1];
#endif
        lo = a.hd[3];
        p = &a;
    }
    s->tcur = lo;
    s->tend = lo + n;
    return 1;
}

/* The tile's triangles not handed out yet, until the caller's buffer is full or the sink
 * stops. 0 when a corner is not exact. */
static int s48_tile_emit(s48_state *s, subd_stream_q *q, int *stop)
{
    s48_win x;
    s48_x(s, &x);
    while (s->tcur < s->tend && !subd_stream_q_full(q)) {
        if (!s48_emit(s, &x, s->tcur, q, stop)) return 0;
        s->tcur++;
        if (*stop) return 1;
    }
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

/* CHORD's counting region (the criterion and its proof: sr48_chord.c). The level-(k + d)
 * triangle (i, p), d <= S48C_M, is window-k triangle i's descendant along the d child bits
 * of p (the first step the highest bit); its key is key(i) * 2^d + p. Packed: i << 8 | p. */

/* Its neighbour across slot `slot` (0 base, 1 leg 0, 2 leg 1) by the local form of the
 * refinement's rule (s48_refine): child 0 has base child 1 of the parent's leg-0
 * neighbour, leg 0 its sibling, leg 1 child 1 of the parent's base neighbour; child 1 has
 * base child 0 of the parent's leg-1 neighbour, leg 0 child 0 of the parent's base
 * neighbour, leg 1 its sibling. 1 found (*oi, *op), 0 the mesh boundary, -1 outside
 * window k. */
static int s48c_nbr(const s48_win *w, uint32_t i, uint32_t p, uint32_t d, uint32_t slot, uint32_t *oi,
                    uint32_t *op)
{
    uint32_t push = 0, np = 0, q;
    for (q = 0; q <= S48C_M; q++) { /* at most d + 1 <= S48C_M + 1 rounds */
        uint32_t b = p & 1u;
        if (d == 0u) {
            uint16_t n = w->tn[3u * i + slot];
            if (n == S48_BND) return 0;
            if (n == S48_OUT) return -1;
            i = n;
            p = 0;
            break;
        }
        if (b == 0u && slot == 1u) {
            p |= 1u;
            break;
        }
        if (b == 1u && slot == 2u) {
            p &= ~1u;
            break;
        }
        push |= (1u - b) << np; /* the answer is that child of the parent's neighbour */
        np++;
        slot = b == 0u ? (slot == 0u ? 1u : 0u) : (slot == 0u ? 2u : 0u);
        p >>= 1;
        d--;
    }
    while (np > 0u) { /* the last parent-level step is the first child bit */
        np--;
        p = (p << 1) | ((push >> np) & 1u);
    }
    *oi = i;
    *op = p;
    return 1;
}

/* The first entry of level d's descendants (3 words each; at most 2 * 4^d of them). */
static uint32_t s48c_off(uint32_t d) { return 2u * ((1u << (2u * d)) - 1u) / 3u; }

/* Is `v` (word `w` of the entries: 0 packed, 1 key) in level d's sorted descendants? */
static int s48c_has(const s48_state *s, uint32_t d, uint64_t v, uint32_t wd)
{
    const uint32_t *e = s->cdesc + 3u * s48c_off(d);
    uint32_t lo = 0, hi = s->cdn[d];
    while (lo < hi) {
        uint32_t mid = (lo + hi) / 2u;
        uint64_t m = wd == 0u ? e[3u * mid] : (((uint64_t)e[3u * mid + 2u] << 32) | e[3u * mid + 1u]);
        if (m == v) return 1;
        if (m < v) lo = mid + 1u;
        else hi = mid;
    }
    return 0;
}

/* The diamonds whose split forces the split of the current triangle t's diamond (t in the
 * level-k window), level by level down to k + min(S48C_M, levels - 1 - k): level k is t and
 * its base neighbour; level d + 1 is the children of level d and their base neighbours
 * (the other triangle of each child's diamond: a diamond of level d + 1 forces both
 * diamonds its triangles' parents belong to). Each level sorted (by packed form, which is
 * key order: the window is sorted by key). All of them lie in the subtrees of t's star,
 * so every neighbour asked for is in the window (sr48_chord.c); 0 if not. */
static int s48c_desc(s48_state *s, uint32_t k, uint32_t t)
{
    s48_win w;
    uint32_t m = s->levels - 1u - k, d, n, x, b, q;
    uint16_t nb;
    s48_lev(s, k, &w);
    if (m > S48C_M) m = S48C_M;
    nb = w.tn[3u * t];
    if (nb == S48_OUT) return 0;
    for (d = 0; d <= S48C_M; d++) s->cdn[d] = 0;
    for (d = 0; d <= m; d++) {
        uint32_t *e = s->cdesc + 3u * s48c_off(d);
        n = 0;
        if (d == 0u) {
            e[0] = t << 8;
            n = 1;
            if (s48_local(nb)) e[3u * n++] = (uint32_t)nb << 8;
        } else {
            const uint32_t *pe = s->cdesc + 3u * s48c_off(d - 1u);
            for (x = 0; x < s->cdn[d - 1u]; x++)
                for (b = 0; b < 2u; b++) {
                    uint32_t i = pe[3u * x] >> 8, p = ((pe[3u * x] & 0xffu) << 1) | b, oi, op;
                    int r;
                    e[3u * n++] = (i << 8) | p;
                    r = s48c_nbr(&w, i, p, d, 0, &oi, &op);
                    if (r < 0) return 0;
                    /* a base neighbour whose parent is of level d - 1's set is a child above;
                     * base neighbours are a bijection, so no other duplicate */
                    if (r == 0 || s48c_has(s, d - 1u, (oi << 8) | (op >> 1), 0)) continue;
                    e[3u * n++] = (oi << 8) | op;
                }
        }
        for (x = 1; x < n; x++) { /* insertion sort by packed form */
            uint32_t v = e[3u * x];
            q = x;
            while (q > 0u && e[3u * (q - 1u)] > v) {
                e[3u * q] = e[3u * (q - 1u)];
                q--;
            }
            e[3u * q] = v;
        }
        for (x = 0; x < n; x++) {
            uint64_t key = (s48_key(&w, e[3u * x] >> 8) << d) | (e[3u * x] & 0xffu);
            e[3u * x + 1u] = (uint32_t)key;
            e[3u * x + 2u] = (uint32_t)(key >> 32);
        }
        s->cdn[d] = n;
    }
    return 1;
}

/* Does the walk's node cur (window w of level j >= k) count for the diamond decided at
 * level k: levels k .. k + S48C_M - 1 the descendant diamonds, level k + S48C_M the star
 * of the descendant diamonds of that level (a triangle sharing a vertex with one; its
 * star is in the window), deeper levels through their level k + S48C_M ancestor (the walk
 * does not enter a subtree that does not count there). */
static uint32_t s48c_counts(const s48_state *s, uint32_t k, uint32_t j, const s48_win *w, uint32_t cur)
{
    uint32_t d = j - k, i, a, b;
    if (d < S48C_M) return (uint32_t)s48c_has(s, d, s48_key(w, cur), 1u);
    if (d > S48C_M) return 1u;
    for (i = 0; i < w->hd[0]; i++) {
        int touch = 0;
        for (a = 0; a < 3u; a++)
            for (b = 0; b < 3u; b++)
                if (w->tv[3u * i + a] == w->tv[3u * cur + b]) touch = 1;
        if (touch && s48c_has(s, d, s48_key(w, i), 1u)) return 1u;
    }
    return 0u;
}

/* May the subtree of triangle i of the level-k window (k < levels, after s48c_desc) hold a
 * counting node? Yes if i is an ancestor of a descendant of the deepest level kept (they
 * cover the shallower ones) or, when that level is k + S48C_M, shares a vertex with one (a
 * triangle sharing a vertex with a level k + S48C_M descendant has its level-k ancestor
 * equal to or sharing a vertex with the descendant's: a shared vertex inside a level-k
 * edge makes the two ancestors the triangles of that edge). */
static int s48c_may(const s48_state *s, const s48_win *w, uint32_t k, uint32_t i)
{
    uint32_t m = s->levels - 1u - k, x, a, b, q, prev = 0xffffffffu;
    const uint32_t *e;
    if (m > S48C_M) m = S48C_M;
    e = s->cdesc + 3u * s48c_off(m);
    for (x = 0; x < s->cdn[m]; x++) {
        q = e[3u * x] >> 8; /* sorted: equal ancestors are consecutive */
        if (q == prev) continue;
        prev = q;
        if (q == i) return 1;
        if (m < S48C_M) continue;
        for (a = 0; a < 3u; a++)
            for (b = 0; b < 3u; b++)
                if (w->tv[3u * q + a] == w->tv[3u * i + b]) return 1;
    }
    return 0;
}

/* The vertex created by the walk's node at level i (its finest position known) against
 * the interpolant of every node from the walked triangle (level k) down to it that counts
 * (s48c_counts). */
static int s48c_test(const s48_state *s, uint32_t k, uint32_t i)
{
    const subd_real *p = s->cpos + 3u * (3u + i);
    uint32_t a, l, q;
    for (a = k; a <= i; a++) {
        subd_real c[9];
        uint32_t path = 0;
        if (!s->cfl[a]) continue;
        for (q = 0; q < 9u; q++) c[q] = s->cpos[3u * s->csrc[3u * a + q / 3u] + q % 3u];
        for (l = a; l < i; l++) path |= (s->cch[l] - 1u) << (l - a);
        if (subd_sr48_chord_beyond_(c, path, i - a, p, s->ad.eps)) return 1;
    }
    return 0;
}

/* Is some counting node of triangle ts's subtree (ts of the level-k window, k < levels)
 * beyond eps? Walks the subtree depth first (pre-order, child 0 first) with the windows of
 * levels k+1.. and X (free while level k decides): each node's window is refined, then
 * cropped to its children as the stream does, so every position is the stream's (exact
 * by the ring rule, checked); a node of level k + S48C_M that does not count is not
 * entered. The walked triangle's corners get their finest positions by descents
 * (s48_finest), so does a node's new vertex (from the cropped window of its children,
 * where it is their apex; at level max_level - 1 it is read from the refined window, the
 * finest level); each is then tested against the interpolants of the counting nodes on
 * its path from ts, whose corners are all known by then. 1 beyond, 0 within, -1 failure. */
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
        s->cfl[j] = s48c_counts(s, k, j, &w, cur);
        if (j - k != S48C_M || s->cfl[j]) {
            s48_x(s, &x);
            if (!s48_refine(s, &w, j, &x)) return -1;
            v = x.tv[6u * cur]; /* the node's new vertex */
            if (j < last) {
                uint64_t id = s48_vid(&x, v);
                s48_lev(s, j + 1u, &c);
                if (!s48_crop(s, &x, 2u * cur, &c) || c.hd[3] == S48_OUT) return -1;
                /* its finest position: a descent from child 0 (blocks > j + 1 and X; child
                 * 0's walk rebuilds them from block j + 1) */
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
        }
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

/* CHORD's decision for the current triangle t of the level-k window: is some counting node
 * (s48c_counts) beyond eps? The counting region lies in the subtrees of the star of t's
 * diamond (the window triangles that share a vertex with it; all of them are in the
 * window, see s48_wants), so those are walked: t in place, another one after rebuilding
 * the windows 0..k along its path, and the current path is rebuilt after. 1 split, 0
 * leaf, -1 failure. */
static int s48_chord_wants(s48_state *s, uint32_t k, uint32_t t)
{
    s48_win w;
    uint32_t vs[4], nv = 3, i, j, q, ns = 1, moved = 0;
    uint64_t cur;
    int r = 0;
    uint16_t nb;
    if (!s48c_desc(s, k, t)) return -1;
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
        if (!touch || !s48c_may(s, &w, k, i)) continue;
        s->ckey[2u * ns] = w.key[2u * i];
        s->ckey[2u * ns + 1u] = w.key[2u * i + 1u];
        ns++;
    }
    for (i = 0; i < ns && r == 0; i++) {
        uint64_t key = ((uint64_t)s->ckey[2u * i + 1u] << 32) | s->ckey[2u * i];
        if (i == 0u) {
            r = s48_chord_walk(s, k, t);
        } else {
            moved = 1;
            if (!s48c_path(s, key, k)) return -1;
            s48_lev(s, k, &w);
            r = s48_chord_walk(s, k, w.hd[2]);
        }
        if (r < 0) return -1;
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
    if (s->ad.mode == SUBD_SR48_ADAPT_CHORD) return s48_chord_wants(s, k, t); /* 1, 0, or -1: a failed walk */
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
        if (s->tcur < s->tend) { /* a tile being handed out */
            if (!s48_tile_emit(s, q, &stop)) goto fail;
            if (stop || s->tcur < s->tend) return stop;
            s48_up(s);
            return SUBD_OK;
        }
        if (s->t0 >= s->n0) {
            q->ended = 1;
            return SUBD_OK;
        }
        if (!s->boxed) {
            if (!s48_adapt_box(s)) goto fail;
            s->boxed = 1;
        }
        if (!s->built && !s->adapt && (s->t0 & 1u) && s->levels > 0u) {
            /* the sibling of the last base triangle: the same level-0 window */
            s48_lev(s, 0, &w);
            w.hd[2] = w.hd[4];
            w.hd[5] = 0;
            s->k = 0;
            s->built = 1;
        }
        if (!s->built) {
            if (s->adapt && s->ad.mode != SUBD_SR48_ADAPT_CHORD && !s48_level0_lin(s, s->t0)) goto fail;
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
        if (s->tm > 1u && s->k + s->tm == s->levels) {
            if (!s48_tile(s, &w, w.hd[2])) goto fail;
            continue;
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
    s->tcur = 0;
    s->tend = 0;
    s->built = 0;
    s->err = 0;
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
