/* SPDX-License-Identifier: MIT */
/* Streaming semi-regular 4-8 refinement (paper: semi-regular-4-8-refinement-box-splines.txt,
 * sections 4 and 6).
 * What it streams: the triangles of subd_sr48_extract's uniform cut of
 * subd_sr48_build's hierarchy, handed out one at a time through the common stream
 * interface (include/subd.h "Streams", src/stream.c), in memory that depends on the level
 * count and the base mesh's largest valence only.
 *
 * Files: this driver (capacities and layout, plan, begin, the depth-first step and the
 * adaptive decisions); the per-level window and why its positions are exact and
 * bit-identical with subd_sr48_build's (sr48_window.c); the breadth-first uniform tile of the
 * last SUBD_SR48_STREAM_TILE_LEVELS levels (sr48_tile.c); CHORD's walk (sr48_chord_walk.c);
 * their private interface (sr48_stream_internal.h).
 *
 * Order. Every level-0 triangle T0 of the base mesh (subd_sr48_base) is refined depth
 * first, child 0 before child 1, so triangles come out in the hierarchy's index order at
 * the last level; level k keeps a window around the current triangle (sr48_window.c). The
 * two children of the current level L-1 triangle are emitted from the refined (uncropped)
 * window: one internal batch; a uniform stream's last m levels are a tile (sr48_tile.c).
 *
 * Adaptive cuts (POINT, RAMP, PLANE, CALLBACK; sr48_adapt.c's nested region): every window
 * vertex also carries L, the level-0 mesh's piecewise-linear interpolant at the finest
 * positions of the level-0 vertices (a new vertex: subd_mid of L at its base ends, as
 * sr48_adapt.c computes it, so the bits agree). L of the level-0 window is found by one
 * descent per vertex (subd_s48_finest_, sr48_descent.c: refine and crop towards the vertex down to max_level,
 * where its position is exact by the ring rule). At its first visit the current triangle's
 * diamond is decided on L's box over the window triangles that touch it (the diamond lies
 * within one ring of the current triangle, its star within two: in the window); a diamond
 * that does not split makes the current triangle a leaf, emitted with its corners' finest
 * positions by three descents (blocks above the current level are free then). Since the
 * region is nested, a diamond that splits has split parents, so the top-down walk cuts
 * exactly subd_sr48_extract's (least conforming) cut, with no lookahead. RAMP's range and
 * POINT's default radius come from the adaptation box A (the finest positions of the base
 * triangles' corners, subd_sr48_adapt_mode), found before the first triangle by one descent per
 * base vertex (subd_s48_adapt_box_); CALLBACK asks fn on the same box as POINT/RAMP/PLANE.
 *
 * Chordal cuts (CHORD): s48_wants asks subd_s48_chord_wants_ (sr48_chord_walk.c).
 *
 * Memory: the fixed state block, the overflow ring (2 triangles), L window blocks (uniform:
 * the levels 0..L - tw above the tile, or the checkpoints' slots, then the two tile windows
 * A and X of the same size), the refined window X otherwise (twice the triangles of a level
 * window, without L; POINT, RAMP, PLANE, CALLBACK with max_level > SUBD_SR48_STREAM_CKPT_: the
 * levels 0..L - 1 in the checkpoints' slots as the uniform walk's, rebuilt by the same calls
 * (s48_ensure: L of a rebuilt window is refine's midpoint rule again, the decisions' state is
 * the walk state kept per level), their descents' two windows in X's block, sr48_descent.c),
 * the smoothing sums and the crop's maps (CHORD: the walk's per-level state, the star's keys,
 * F(D)'s first levels); all sized by the window capacities of
 * SUBD_SR48_STREAM_BYTES, which depend on the largest valence (and the tile's m) only.
 */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "entry.h"
#include "layout.h"
#include "mesh_internal.h"
#include "real_avg.h"
#include "stream_internal.h"
#include "sr48_stream_internal.h"

SUBD_STREAM_STATE_FITS(s48_state);
/* Local keys and ids fit their words (sr48_stream_internal.h): a level-0 window's triangle
 * and vertex indices below 2^9, levels below 2^4 + 1. */
typedef char s48_local_fits[SUBD_SR48_STREAM_WT_(SUBD_SR48_STREAM_MAX_VALENCE) <= 512u &&
                                    SUBD_SR48_STREAM_WV_(SUBD_SR48_STREAM_MAX_VALENCE) <= 512u &&
                                    SUBD_SR48_MAX_STEPS <= 16u && 9u + SUBD_SR48_MAX_STEPS - 1u <= S48_IDS
                                ? 1
                                : -1];
/* CHORD's tile window (sr48_chord_walk.c, s48c_tile) lives in three free level windows: its
 * capacities exceed a level window's by amounts that do not depend on the valence, so the
 * least valence counted (8) is the tightest case. */
typedef char s48c_tile_fits[SUBD_SR48_WIN_(SUBD_SR48_STREAM_TT_(8u, SUBD_SR48_STREAM_CHORD_TILE_),
                                           SUBD_SR48_STREAM_TV_(8u, SUBD_SR48_STREAM_CHORD_TILE_)) <=
                                    3u * SUBD_SR48_WIN_(SUBD_SR48_STREAM_WT_(8u), SUBD_SR48_STREAM_WV_(8u))
                                ? 1
                                : -1];

/* The adaptive walk's descents with checkpoints (sr48_descent.c, s48_dwin) keep two level
 * windows without L in X's block (which has no L either: the children emitted from it need
 * positions only): twice a level window fits the refined window (its margin grows with the
 * valence, so the least valence counted is the tightest case). */
typedef char s48_dwin_fits[2u * SUBD_SR48_WIN_(SUBD_SR48_STREAM_WT_(8u), SUBD_SR48_STREAM_WV_(8u)) <=
                                   SUBD_SR48_WIN_(2u * SUBD_SR48_STREAM_WT_(8u),
                                                  SUBD_SR48_STREAM_WV_(8u) + SUBD_SR48_STREAM_WT_(8u))
                               ? 1
                               : -1];

/* ------------------------------------------------------------------------------------ */
/* Capacities and layout                                                                  */

static uint32_t s48_cap_t(uint32_t n) { return SUBD_SR48_STREAM_WT_(n); }
static uint32_t s48_cap_v(uint32_t n) { return SUBD_SR48_STREAM_WV_(n); }

/* A window's arrays for ct triangles and cv vertices: offsets inside its block, its size. */
static uint32_t s48_win_layout(uint32_t ct, uint32_t cv, uint32_t nl, uint32_t *off)
{
    subd_layout y;
    uint32_t b, i;
    const uint32_t cnt[7] = {8u, 3u * ct, 3u * ct, ct, 3u * cv, cv, cv};
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


/* The tile's depth m (uniform mode): the last m levels are refined breadth first. */
static uint32_t s48_tile_levels(uint32_t levels, uint32_t uniform)
{
    if (!uniform) return 1u;
    return levels < SUBD_SR48_STREAM_TILE_LEVELS ? (levels > 0u ? levels : 1u) : SUBD_SR48_STREAM_TILE_LEVELS;
}

/* Uniform, max_level <= m: one tile from level 0 serves both base triangles 2H, 2H + 1 of
 * a hybrid pair (adjacent in the level-0 window, which holds the rings of both; 2H's
 * descendants come first in key order, so the order is unchanged): the first refinement,
 * of the largest window, is made once per pair, and the tile's last window holds
 * 2^(max_level - 1) triangles as the walk's tiles of m levels do. */
static int s48_tile_pair(const s48_state *s)
{
    return s->tm > 1u && s->tm == s->levels;
}

/* Checkpoints (uniform and adaptive walks): the window slots of levels 0..d (d >= c), a window per c-th level
 * above 0 and c - 1 shared by the levels between and level 0 (SUBD_SR48_STREAM_SLOTS_). */
static uint32_t s48_slots(uint32_t d, uint32_t c)
{
    return d / c + c - 1u;
}

/* The one layout of plan and begin (layout.h's walk). Uniform: levels 0..L-tw in level
 * windows (or the checkpoints' slots), the tile windows A and X (the current level L-tw
 * triangle's descendants, at most m levels below it, with their rings; sr48_tile.c);
 * otherwise levels 0..L-1 and X of twice a level window. */
static int s48_layout(subd_arena *a, uint32_t levels, uint32_t valence, uint32_t nl, uint32_t chord, s48_state **ps,
                      uint8_t **ring, uint32_t *bytes)
{
    subd_layout y;
    /* CHORD: its tiles (sr48_chord_walk.c, up to mc levels breadth first) keep their tile
     * window A in the free level windows below the tile's root, X is sized for them */
    const uint32_t m = s48_tile_levels(levels, !nl && !chord), mc = chord ? SUBD_SR48_STREAM_CTM_(levels) : 0u;
    const uint32_t tile = m > 1u, tw = tile && levels > m ? m + 1u : m; /* s48_tile_walk */
    /* the deepest level window: L - tw (uniform), L - 1 (otherwise) */
    const uint32_t dl = levels >= tw ? levels - tw : 0u, ckc =
        !chord && dl >= SUBD_SR48_STREAM_CKPT_ ? SUBD_SR48_STREAM_CKPT_ : 0u; /* fewer slots than levels */
    /* CHORD: three more level windows after levels 0..L-1, the tile window of the memo's tiles
     * (sr48_chord_walk.c, s48c_bits: taken while a decision holds levels up to max_level - 1) */
    const uint32_t nlev = (ckc ? s48_slots(dl, ckc) : dl + 1u) + (chord ? 3u : 0u);
    uint32_t ct = s48_cap_t(valence), cv = s48_cap_v(valence), off[8];
    uint32_t at = m > 1u ? SUBD_SR48_STREAM_TT_(valence, m) : chord ? SUBD_SR48_STREAM_TT_(valence, mc) : ct;
    uint32_t av = m > 1u ? SUBD_SR48_STREAM_TV_(valence, m) : chord ? SUBD_SR48_STREAM_TV_(valence, mc) : cv;
    /* X: twice the larger parent's triangles; its vertices: the parent's (pv) and at most one
     * new one per parent triangle (a diamond's vertex is made once, by its lower triangle) */
    uint32_t mt = at > ct ? at : ct, pv = av > cv ? av : cv, xv = pv + mt;
    uint32_t lsz = s48_win_layout(ct, cv, nl, off), asz = tile ? s48_win_layout(at, av, nl, off) : 0u;
    /* X: a uniform tile's windows alternate between A and X, each refined and cropped in one
     * pass (subd_s48_refine_crop_), so X is A's size; otherwise a whole refined window */
    uint32_t xsz = tile ? asz : s48_win_layout(2u * mt, xv, 0u, off); /* no L: never read */
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
        if (tile)
            (void)s48_win_layout(at, av, nl, s->xoff);
        else
            (void)s48_win_layout(2u * mt, xv, 0u, s->xoff);
    }
    {
        uint8_t *lev = subd_layout_take(&y, nlev, lsz);
        uint8_t *ab = tile ? subd_layout_take(&y, 1u, asz) : 0;
        uint8_t *x = subd_layout_take(&y, 1u, xsz);
        /* the smoothing sums' high parts and counts: the parent's vertices only
         * (subd_s48_refine_; reserved in both arithmetics) */
        int16_t *sumhi = subd_layout_take(&y, 3u * pv, 2u);
        uint32_t *cnt = subd_layout_take(&y, pv, 4u);
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
        uint32_t *ci =
            chord ? subd_layout_take(&y, 6u * (levels + 1u) + 2u * ct + S48C_M + 1u + 3u * S48C_ND + 2u * S48C_NC + 2u * S48C_ND2 +
                                           5u * S48C_NB,
                                       4u)
                  : 0;
        /* then CHORD's tile: its interpolant stack (9 subd_sr48_lin per level, 8 bytes each
         * reserved in both arithmetics), 3 corners and a flag per node of a tile of mc levels
         * (heap order), a byte per vertex of a parent window; carved by sr48_chord_walk.c
         * (s48c_lin) */
        subd_real *cp = chord ? subd_layout_take(&y, 1u,
                                                 SUBD_SR48_SA_(12u * (levels + 4u + S48C_NC)) + 72u * (mc + 1u) +
                                                     (12u << mc) + (2u << mc) + pv)
                              : 0;
        uint32_t *ckw = ckc ? subd_layout_take(&y, 2u * (levels + 1u) + nlev, 4u) : 0;
        if (s) {
            s->l0 = l0;
            s->lgv = lgv;
            s->lgvt = lgvt;
            s->lev = lev;
            s->ablk = ab;
            s->xblk = x;
            s->sumhi = sumhi;
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
            s->ckw = ckw;
            if (ckw) {
                uint32_t i;
                for (i = 0; i < 2u * (levels + 1u) + nlev; i++) ckw[i] = 0; /* no slot held */
            }
        }
    }
    *ps = s;
    return subd_layout_end(&y, bytes);
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
    if ((st = subd_s48_base_check_(b)) != SUBD_OK) return st;
    *valence = subd_s48_valence_(b);
    if (b->stream_valence > *valence) *valence = b->stream_valence; /* the base's census (sr48_census.c) */
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
/* The walk                                                                               */

/* Does the current triangle t of the level-k window (k < levels) split its diamond? The
 * region: L's box over the window's triangles that share a vertex with the diamond (all of
 * them are in the window: the diamond is within one ring of t). */
static int s48_wants(s48_state *s, const s48_win *w, uint32_t t, uint32_t k)
{
    uint32_t vs[4], nv = 3, i, j, q;
    subd_real lo[3], hi[3];
    uint16_t nb = w->tn[3u * t];
    if (s->ad.mode == SUBD_SR48_ADAPT_CHORD) return subd_s48_chord_wants_(s, k, t); /* 1, 0, or -1: a failed walk */
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
        if (!(s->ad.mode == SUBD_SR48_ADAPT_CHORD ? subd_s48_chord_finest_ : subd_s48_finest_)(s, k, t, id[j], p[j]))
            return 0;
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

/* Checkpoints: level k's window is about to be written into its slot: the walk
 * state (cur, nxt) of the level the slot holds is kept in ckw until that level is rebuilt. */
static void s48_take_slot(s48_state *s, uint32_t k)
{
    uint32_t *own = s->ckw + 2u * (s->levels + 1u) + s48_slot(s, k);
    if (*own != 0u && *own != k + 1u) {
        const uint32_t j = *own - 1u;
        s48_win o;
        s48_lev(s, j, &o); /* the same slot */
        s->ckw[2u * j] = o.hd[2];
        s->ckw[2u * j + 1u] = o.hd[5];
    }
    *own = k + 1u;
}

/* Checkpoints: makes level k's slot hold level k's window of the current path,
 * rebuilding it (and the levels between) from the deepest level below it whose slot still
 * holds it (a checkpoint at the latest; level 0 from the base mesh): the calls of the first
 * descent (build level 0's window, refine the level below, crop to its current triangle's
 * children), so the same bits; then its walk state back. 0 on failure (s->err). */
static int s48_ensure(s48_state *s, uint32_t k)
{
    const uint32_t *own = s->ckw + 2u * (s->levels + 1u);
    uint32_t j = k;
    s48_win p, c;
    while (j > 0u && own[s48_slot(s, j)] != j + 1u) j--;
    if (j == 0u && own[s48_slot(s, 0)] != 1u) {
        /* uniform: the window of t0's hybrid pair, whichever of the two t0 is; adaptive: with L
         * from s->l0, kept since t0's subd_s48_level0_lin_ */
        s48_take_slot(s, 0);
        if (!subd_s48_build0_(s, s->t0)) return 0;
        s48_lev(s, 0, &p);
        p.hd[2] = s->ckw[0];
        p.hd[5] = s->ckw[1];
    }
    for (; j < k; j++) {
        s48_lev(s, j, &p);
        s48_take_slot(s, j + 1u); /* level j + 1's slot is not level j's */
        s48_lev(s, j + 1u, &c);
        if (!subd_s48_refine_crop_(s, &p, j, p.hd[2], 1u, &c, s->wt, s->wv, 0u)) return 0;
        c.hd[2] = s->ckw[2u * (j + 1u)];
        c.hd[5] = s->ckw[2u * (j + 1u) + 1u];
    }
    return 1;
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
            if (!subd_s48_tile_emit_(s, q, &stop)) goto fail;
            if (stop || s->tcur < s->tend) return stop;
            if (s48_tile_pair(s)) s->t0++; /* the tile was both of the pair's */
            s48_up(s);
            return SUBD_OK;
        }
        if (s->t0 >= s->n0) {
            q->ended = 1;
            return SUBD_OK;
        }
        if (!s->boxed) {
            if (!subd_s48_adapt_box_(s)) goto fail;
            s->boxed = 1;
        }
        if (!s->built && !s->adapt && (s->t0 & 1u) && s->levels > 0u &&
            (!s->ckw || s->ckw[2u * (s->levels + 1u) + s48_slot(s, 0)] == 1u)) {
            /* the sibling of the last base triangle: the same level-0 window */
            s48_lev(s, 0, &w);
            w.hd[2] = w.hd[4];
            w.hd[5] = 0;
            s->k = 0;
            s->built = 1;
        }
        if (!s->built) {
            if (s->adapt && s->ad.mode != SUBD_SR48_ADAPT_CHORD && !subd_s48_level0_lin_(s, s->t0)) goto fail;
            if (s->ckw) s48_take_slot(s, 0);
            /* a uniform tile from level 0 reads level 0's smaller window first (sr48_tile.c) */
            if (!(!s->adapt && s->tm > 1u && s48_tile_walk(s) == s->levels ? subd_s48_build0_small_
                                                                             : subd_s48_build0_)(s, s->t0))
                goto fail;
            s->k = 0;
            s->built = 1;
            s48_lev(s, 0, &w);
            w.hd[5] = 0;
            if (s->levels == 0u) {
                if (!subd_s48_emit_(s, &w, w.hd[2], q, &stop)) goto fail;
                s->t0++;
                s->built = 0;
                return stop;
            }
        }
        if (s->ckw && s->ckw[2u * (s->levels + 1u) + s48_slot(s, s->k)] != s->k + 1u) {
            /* the walk is back at a level whose slot a deeper level took */
            if (s->ckw[2u * s->k + 1u] >= 2u) {
                s48_up(s);
                continue;
            }
            if (!s48_ensure(s, s->k)) goto fail;
        }
        s48_lev(s, s->k, &w);
        if (s->adapt && w.hd[5] == 0u && (wants = s48_wants(s, &w, w.hd[2], s->k)) <= 0) {
            /* a leaf below max_level (or a failed CHORD walk) */
            if (wants < 0) goto fail;
            if (!s48_emit_leaf(s, s->k, w.hd[2], q, &stop)) goto fail;
            s48_up(s);
            return stop;
        }
        if (s->tm > 1u && s->k + s48_tile_walk(s) == s->levels) {
            if (!subd_s48_tile_(s, &w, w.hd[2], s48_tile_pair(s) ? 2u : 1u)) goto fail;
            continue;
        }
        if (s->k + 1u == s->levels) {
            s48_x(s, &x);
            if (!subd_s48_refine_(s, &w, s->k, &x)) goto fail;
            if (!subd_s48_emit_(s, &x, 2u * w.hd[2], q, &stop)) goto fail;
            if (stop) return stop;
            if (!subd_s48_emit_(s, &x, 2u * w.hd[2] + 1u, q, &stop)) goto fail;
            s48_up(s);
            return stop;
        }
        if (w.hd[5] == 0u) {
            if (s->ckw) s48_take_slot(s, s->k + 1u); /* level k + 1's slot is not level k's */
            s48_lev(s, s->k + 1u, &c);
            if (!subd_s48_refine_crop_(s, &w, s->k, w.hd[2], 1u, &c, s->wt, s->wv, 0u)) goto fail;
        } else if (w.hd[5] == 1u && s->ckw && !s48_ensure(s, s->k + 1u)) {
            goto fail;
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
    s->two_rings = 0;
    if (s->tm > 1u) { /* the tile counters (sr48_stream_internal.h) */
        s48_win x, ta;
        s48_x(s, &x);
        s48_win_at(s, s->ablk, s->aoff, &ta);
        x.hd[7] = 0;
        ta.hd[7] = 0;
    }
    if (o->adapt.mode == SUBD_SR48_ADAPT_CHORD) subd_s48_chord_begin_(s);
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
