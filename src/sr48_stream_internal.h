/* SPDX-License-Identifier: MIT */
/* Streaming semi-regular 4-8 refinement, private interface between its files (paper:
 * semi-regular-4-8-refinement-box-splines.txt, sections 4 and 6; the method, the exactness
 * argument and the bit-identity with subd_sr48_build are in sr48_window.c's header):
 *   sr48_level0.c      the base mesh's adjacency and checks, the fan walk, level 0's window;
 *   sr48_window.c      the per-level window: the refinement of a window as a whole (with
 *                      smoothing), the crop to the rings of a set of triangles (also in one
 *                      pass with the refinement);
 *   sr48_descent.c     the descents to the finest level (a vertex's finest position, L of
 *                      level 0, the adaptation box);
 *   sr48_census.c      the base's census of its level-0 windows (stream_valence);
 *   sr48_tile.c        the breadth-first uniform tile of the last SUBD_SR48_STREAM_TILE_LEVELS
 *                      levels (its last level smoothed without a window) and the emission of
 *                      a window triangle;
 *   sr48_chord_walk.c  CHORD's walk over the deeper windows, its decisions and memos (the
 *                      criterion and its proof: sr48_chord.c);
 *   sr48_chord_tile.c  CHORD's breadth-first tiles: the walk's and the memo's;
 *   sr48_chord_region.c  CHORD's counting region F(D), the forcing diamonds (its calls:
 *                      sr48_chord_internal.h);
 *   sr48_stream.c      the driver: capacities and layout, plan, begin, the depth-first step.
 * One window layout and one state block (s48_state) serve them all. The window's accessors
 * are static inline here: they are on the hot path of every refinement and walk. Names
 * shared across the files are subd_s48_*_ (unique in src/: the library is also one
 * translation unit, make amalgamate). */
#ifndef SUBD_SR48_STREAM_INTERNAL_H
#define SUBD_SR48_STREAM_INTERNAL_H
#include "subd.h"
#include "real_avg.h"
#include "stream_internal.h"
#include "sr48_internal.h"

#define S48_OUT 0xffffu /* neighbour outside the window                                  */
#define S48_BND 0xfffeu /* the mesh boundary                                             */
#define S48_EXACT 0x1u  /* vertex flag: position final and bit-exact                     */
#define S48_INC 0x2u    /* smoothing scratch: some input missing                          */
#define S48_FAR 0xffu   /* crop: vertex not reached                                       */
/* s48_state's l0ok (sr48_level0.c sets it with every level-0 window of a uniform stream; the
 * windows the walk and the tile derive from that window inherit it: sr48_window.c's header) */
#define S48_L0_RANGE 0x1u  /* every position finite, |coordinate| < 2^64: no check can fire  */
#define S48_L0_CLOSED 0x2u /* no mesh boundary (S48_BND) in the window                      */
#define S48_RINGS SUBD_SR48_STREAM_RINGS_
#define S48C_M SUBD_SR48_STREAM_CHORD_EXACT_ /* CHORD: levels of exact descendants (sr48_chord.c) */
#define S48C_ND SUBD_SR48_STREAM_CHORD_DESC_  /* CHORD: their capacity, triangles              */
#define S48C_NC SUBD_SR48_STREAM_CHORD_CACHE_ /* CHORD: cached finest positions (a power of 2) */
#define S48C_T SUBD_SR48_STREAM_CHORD_TILE_  /* CHORD: levels refined breadth first (a tile) */
#define S48C_ND2 SUBD_SR48_STREAM_CHORD_DECIDED_ /* CHORD: decided diamonds kept (a power of 2) */
#define S48C_NB SUBD_SR48_STREAM_CHORD_MASKS_ /* CHORD: tiles' deviation masks kept (a power of 2) */

/* Local keys and ids (one word each; s48_key and s48_vid give the global 64-bit ones). A
 * level-k triangle's local key is i0 * 2^k + its child path below its level-0 ancestor, i0
 * that ancestor's index in the level-0 window (s48_state's gt: the window's base triangles,
 * sorted, so local keys sort as global ones: T0 * 2^k + path, T0 = gt[i0]). A vertex's local
 * id: j * 2^S48_IDS + q, j = 0 for a level-0 vertex (q its index in the level-0 window, gv),
 * else j - 1 = the level of the triangle whose diamond created it and q that triangle's
 * local key. Bounds: i0 < SUBD_SR48_STREAM_WT_(SUBD_SR48_STREAM_MAX_VALENCE) <= 2^9 and
 * k < SUBD_SR48_MAX_STEPS <= 16, so q < 2^(9 + 15) < 2^S48_IDS, and j <= 16 < 2^(32 - S48_IDS)
 * (checked at compile time in sr48_stream.c). */
#define S48_IDS 27u
#define S48_IDQ ((1u << S48_IDS) - 1u)

struct s48_state;
/* One window's arrays (level k, or the refined window X). hd: nt, nv, cur, ch0, ch1, nxt,
 * the window's level; hd[7]: of level 0's window 1 when it is cropped smaller
 * (subd_s48_build0_small_), of the uniform tile's blocks X and A how many tiles were made,
 * and how many of them with the two rings of the exactness argument (sr48_tile.c: the
 * smaller crops first; counted for the tests, which force the two rings with
 * S48_TILE_FULL in A's; S48_TILE_TINY: the tests' too small first crops, so that the
 * exactness checks must send tiles to the two rings). */
#define S48_TILE_FULL 0x80000000u
#define S48_TILE_TINY 0x40000000u
typedef struct s48_win {
    uint32_t *hd;
    uint16_t *tv, *tn;
    uint32_t *key; /* local key per triangle (above) */
    subd_real *vp;
    uint32_t *vid; /* local id per vertex (above)    */
    uint8_t *vf;
    subd_real *vl; /* adaptive modes: L (the level-0 interpolant) per vertex, else NULL */
    const struct s48_state *st; /* the level-0 window's gt, gv; nv0, n0 (global keys, ids) */
} s48_win;

/* Window vertex sv of src as vertex dv of dst: position, id, flags and (adaptive) L. */
static inline void s48_vcopy(const s48_win *dst, uint32_t dv, const s48_win *src, uint32_t sv)
{
    dst->vp[3u * dv] = src->vp[3u * sv];
    dst->vp[3u * dv + 1u] = src->vp[3u * sv + 1u];
    dst->vp[3u * dv + 2u] = src->vp[3u * sv + 2u];
    dst->vid[dv] = src->vid[sv];
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
    uint32_t t0, k, err;
    uint8_t built;
    uint8_t l0ok;      /* the last level-0 window's S48_L0_RANGE, S48_L0_CLOSED (uniform; else 0) */
    uint16_t two_rings; /* tests (test_sr48_chord.c): CHORD's tiles and the descents take the
                         * two rings alone, not the smaller crops first (0 after begin) */
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
    int16_t *sumhi;    /* smoothing: 3 per parent vertex, Q16.16 sums' high parts (the low
                        * parts and float sums live in X's positions: sr48_window.c)     */
    uint32_t *cnt;
    uint8_t *dist;
    uint16_t *mtab, *tmap, *vmap;
    uint32_t *gt, *gv, *gvt; /* level-0 window: triangles, vertices, a triangle at each     */
    /* CHORD (sr48_chord.c's criterion, subd_s48_chord_wants_): per walk level the triangle, the
     * child state, the corners' sources (0..2 the walked triangle's corners, 3 + j the vertex
     * level j's node creates), whether it counts; the star's keys; the decided diamond's
     * descendants per level (count, then packed window triangle + path, key lo, key hi) */
    uint32_t *ccur, *cch, *csrc, *cfl, *ckey, *cdn, *cdesc;
    subd_real *cpos; /* finest positions: the walked triangle's corners, then one per level */
    /* (the cache of finest positions, sr48_chord_walk.c: S48C_NC ids after cdesc's 3 S48C_ND
     * words, their positions after cpos's 3 (levels + 4) subd_reals; then the tile's
     * interpolant stack, node corners and flags, sr48_chord_walk.c's s48c_lin) */
    /* Checkpoints of the uniform walk and (max_level > c) of POINT, RAMP, PLANE, CALLBACK's
     * (sr48_stream.c, s48_ensure; NULL: one window per level, CHORD): levels
     * c, 2c, .. (c = SUBD_SR48_STREAM_CKPT_) above the tile keep a window each, the levels
     * between and level 0 share c - 1 slots (s48_slot) and are rebuilt from their checkpoint
     * (level 0: from the base mesh) when the walk returns. Per level its walk state (cur,
     * nxt) while its slot holds another level, then per slot the level it holds plus 1 (0:
     * none). */
    uint32_t *ckw;
} s48_state;

/* Window access (hot: every level of every walk), shared by the four files. */
static inline void s48_win_at(const s48_state *s, uint8_t *blk, const uint32_t *off, s48_win *w)
{
    w->st = s;
    w->hd = (uint32_t *)(void *)(blk + off[0]);
    w->tv = (uint16_t *)(void *)(blk + off[1]);
    w->tn = (uint16_t *)(void *)(blk + off[2]);
    w->key = (uint32_t *)(void *)(blk + off[3]);
    w->vp = (subd_real *)(void *)(blk + off[4]);
    w->vid = (uint32_t *)(void *)(blk + off[5]);
    w->vf = blk + off[6];
    w->vl = off[7] != 0u ? (subd_real *)(void *)(blk + off[7]) : 0;
}
/* The levels the uniform walk's tile covers (1: no tile): m + 1 when max_level > m, the tile
 * window A being sized for m levels with a window at the last one, which the walk does not
 * make (sr48_tile.c), else m. */
static inline uint32_t s48_tile_walk(const s48_state *s)
{
    return s->tm > 1u && s->levels > s->tm ? s->tm + 1u : s->tm;
}

/* The slot of level k's window (uniform checkpoints: see s48_state's ckw). */
static inline uint32_t s48_slot(const s48_state *s, uint32_t k)
{
    const uint32_t c = SUBD_SR48_STREAM_CKPT_, tw = s48_tile_walk(s);
    uint32_t nc;
    if (!s->ckw) return k;
    /* slots 0 .. nc - 1: the checkpoints c, 2c, .. nc c (nc = D / c, D = levels - tw, the
     * deepest level window the walk makes); then c - 1 slots, one per k mod c; level 0
     * (rebuilt from the base mesh, no checkpoint) shares the slot of k mod c = c - 1 */
    nc = (s->levels > tw ? s->levels - tw : 0u) / c;
    if (k % c == 0u && k > 0u) return k / c - 1u;
    return nc - 1u + (k == 0u ? c - 1u : k % c);
}
static inline void s48_lev(const s48_state *s, uint32_t k, s48_win *w)
{
    s48_win_at(s, s->lev + s48_slot(s, k) * s->lev_size, s->off, w);
}
static inline void s48_x(const s48_state *s, s48_win *w) { s48_win_at(s, s->xblk, s->xoff, w); }

/* The global key (T0 * 2^k + path, its index within level k of the hierarchy) of a level-k
 * triangle with local key q. */
static inline uint64_t s48_gkey(const s48_state *s, uint32_t q, uint32_t k)
{
    return ((uint64_t)s->gt[q >> k] << k) | (q & ((1u << k) - 1u));
}
/* Window w's triangle t's global key. */
static inline uint64_t s48_key(const s48_win *w, uint32_t t) { return s48_gkey(w->st, w->key[t], w->hd[6]); }
/* Window w's vertex v's global id (the closed form of sr48_window.c's header). */
static inline uint64_t s48_vid(const s48_win *w, uint32_t v)
{
    const s48_state *s = w->st;
    const uint32_t r = w->vid[v], j = r >> S48_IDS;
    if (j == 0u) return s->gv[r];
    return (uint64_t)s->nv0 + (uint64_t)s->n0 * (((uint64_t)1 << (j - 1u)) - 1u) + s48_gkey(s, r & S48_IDQ, j - 1u);
}
/* Is window neighbour n a window triangle (not OUT, not BND)? */
static inline int s48_local(uint16_t n) { return n < S48_BND; }
/* The new vertex of window x's triangle i's diamond at the next level, as subd_s48_refine_
 * makes it: the midpoint (subd_mid) of *e0 and *e1, read from the diamond's lower triangle
 * *lt (the lower index of i and its base neighbour): its base ends, or with smoothing and
 * the partner in the window the two apexes. Returns *lt's base neighbour (S48_OUT: an input
 * is outside the window). One rule for the tiles that make the last level without its
 * window (sr48_tile.c, sr48_chord_walk.c). */
static inline uint16_t subd_s48_mid_ends_(const s48_state *s, const s48_win *x, uint32_t i, uint32_t *lt,
                                          uint32_t *e0, uint32_t *e1)
{
    const uint16_t nb = x->tn[3u * i];
    const uint32_t l = (s48_local(nb) && nb < i) ? nb : i;
    const uint16_t *lv = x->tv + 3u * l, lnb = x->tn[3u * l];
    *lt = l;
    *e0 = lv[1];
    *e1 = lv[2];
    if (s48_local(lnb) && s->smooth) {
        *e0 = lv[0];
        *e1 = x->tv[3u * lnb];
    }
    return lnb;
}

/* Smoothing sums in place (sr48_window.c's refinements, sr48_tile.c's last level; static
 * inline here, like the window accessors: the innermost loops): while X is smoothed, the
 * running sum of an old vertex's new neighbours lives in its own X position (its old
 * position is not read again: the new vertices come from the parent's positions, and an
 * old vertex left unsmoothed gets the parent's back). Element e = 3 v + axis. */
#if SUBD_FIXED /* why: a Q16.16 subd_sum is 64 bits: the low part, signed in [-2^31, 2^31),
                * in the X position, the high part in s->sumhi. A sum has at most as many
                * terms as the parent has triangles (one per diamond at the vertex), fewer than
                * 2^10 (SUBD_SR48_STREAM_TT_ at the largest valence), each below 2^31 in
                * magnitude, so |high part| < 2^9: an int16 */
#define S48_W32 ((subd_sum)4294967296)
static inline subd_sum s48_sget(const s48_state *s, const s48_win *x, uint32_t e)
{
    return (subd_sum)s->sumhi[e] * S48_W32 + (subd_sum)x->vp[e];
}
static inline void s48_sput(const s48_state *s, const s48_win *x, uint32_t e, subd_sum v)
{
    const subd_sum q = v + S48_W32 / 2, hi = q >= 0 ? q / S48_W32 : -((S48_W32 - 1 - q) / S48_W32);
    s->sumhi[e] = (int16_t)hi;
    x->vp[e] = (subd_real)(v - hi * S48_W32);
}
#else /* float: subd_sum is subd_real: the same additions in the same order, in place */
static inline subd_sum s48_sget(const s48_state *s, const s48_win *x, uint32_t e)
{
    (void)s;
    return x->vp[e];
}
static inline void s48_sput(const s48_state *s, const s48_win *x, uint32_t e, subd_sum v)
{
    (void)s;
    x->vp[e] = v;
}
#endif

/* The three coordinates at once (unrolled: the hot paths of every window). */
static inline void s48_mid3(subd_real *o, const subd_real *a, const subd_real *b, uint32_t *ovf)
{
    o[0] = subd_mid(a[0], b[0], ovf);
    o[1] = subd_mid(a[1], b[1], ovf);
    o[2] = subd_mid(a[2], b[2], ovf);
}
/* s48_mid3, without the finiteness checks when chk is 0 (the window's level-0 window was in
 * S48_L0_RANGE: then no check could fire, sr48_window.c's header): the same bits. Q16.16
 * has no checks to skip. */
static inline void s48_mid3k(subd_real *o, const subd_real *a, const subd_real *b, uint32_t *ovf, uint32_t chk)
{
#if SUBD_FIXED
    (void)chk;
    s48_mid3(o, a, b, ovf);
#else
    if (chk) {
        s48_mid3(o, a, b, ovf);
    } else { /* subd_mid's operations */
        const subd_real a0 = 0.5f * a[0], b0 = 0.5f * b[0], a1 = 0.5f * a[1], b1 = 0.5f * b[1];
        const subd_real a2 = 0.5f * a[2], b2 = 0.5f * b[2];
        o[0] = a0 + b0;
        o[1] = a1 + b1;
        o[2] = a2 + b2;
    }
#endif
}
static inline void s48_cp3(subd_real *o, const subd_real *p)
{
    o[0] = p[0];
    o[1] = p[1];
    o[2] = p[2];
}
static inline void s48_szero3(const s48_state *s, const s48_win *x, uint32_t e)
{
    s48_sput(s, x, e, 0);
    s48_sput(s, x, e + 1u, 0);
    s48_sput(s, x, e + 2u, 0);
}
#if SUBD_FIXED /* why: one term added to the (high, low) pair directly, the low part kept in
                * [-2^31, 2^31) (s48_sput's form) by a carry into the high part, without
                * forming and splitting the 64-bit sum (the hot path of every smoothing) */
static inline void s48_sadd1(const s48_state *s, const s48_win *x, uint32_t e, subd_real v)
{
    int64_t t = (int64_t)x->vp[e] + v;
    if (t >= (int64_t)2147483647 + 1) {
        t -= S48_W32;
        s->sumhi[e] = (int16_t)(s->sumhi[e] + 1);
    } else if (t < -(int64_t)2147483647 - 1) {
        t += S48_W32;
        s->sumhi[e] = (int16_t)(s->sumhi[e] - 1);
    }
    x->vp[e] = (subd_real)t;
}
#else
static inline void s48_sadd1(const s48_state *s, const s48_win *x, uint32_t e, subd_real v)
{
    s48_sput(s, x, e, subd_sum_add(s48_sget(s, x, e), v));
}
#endif
static inline void s48_sadd3(const s48_state *s, const s48_win *x, uint32_t e, const subd_real *mp)
{
    s48_sadd1(s, x, e, mp[0]);
    s48_sadd1(s, x, e + 1u, mp[1]);
    s48_sadd1(s, x, e + 2u, mp[2]);
}

/* subd_avg(s, n): the same call, with the usual n = 4 (a regular vertex: four diamonds)
 * as a constant, so that Q16.16 divides by shifts instead of a 64-bit division (a library
 * call on the Cortex-M3); the same bits. */
static inline subd_real s48_avg(subd_sum s, uint32_t n, uint32_t *ovf)
{
#if SUBD_FIXED
    return n == 4u ? subd_avg(s, 4u, ovf) : subd_avg(s, n, ovf);
#else /* float: one division either way */
    return subd_avg(s, n, ovf);
#endif
}

/* A smoothed position: the three sums at e .. e + 2 (in x's positions) averaged in place. */
static inline void s48_avg3(const s48_state *s, const s48_win *x, uint32_t e, uint32_t n, uint32_t *ovf)
{
    x->vp[e] = s48_avg(s48_sget(s, x, e), n, ovf);
    x->vp[e + 1u] = s48_avg(s48_sget(s, x, e + 1u), n, ovf);
    x->vp[e + 2u] = s48_avg(s48_sget(s, x, e + 2u), n, ovf);
}

/* s48_avg3, without the finiteness checks when chk is 0 (as s48_mid3k). */
static inline void s48_avg3k(const s48_state *s, const s48_win *x, uint32_t e, uint32_t n, uint32_t *ovf, uint32_t chk)
{
#if SUBD_FIXED
    (void)chk;
    s48_avg3(s, x, e, n, ovf);
#else
    if (chk) {
        s48_avg3(s, x, e, n, ovf);
    } else { /* subd_avg's operations */
        const float k = (float)n;
        x->vp[e] = x->vp[e] / k;
        x->vp[e + 1u] = x->vp[e + 1u] / k;
        x->vp[e + 2u] = x->vp[e + 2u] / k;
    }
#endif
}

/* The smoothing's scatters are forced inline (GCC, clang): gcc -O2 for the Cortex-M3 keeps
 * them out of line (the Q16.16 carries make them larger), a call per sum term, about 2% of
 * the M3's uniform stream; the M4F's were inline already. */
#if defined(__GNUC__)
#define S48_INLINE static inline __attribute__((always_inline))
#else
#define S48_INLINE static inline
#endif

/* Adds a new vertex (position mp, flags mf) to the sum of vertex v (sums in x's positions,
 * counts and flags in s->cnt, s->dist at v). */
S48_INLINE void s48_scatter(const s48_state *s, const s48_win *x, uint32_t v, const subd_real *mp,
                               uint32_t mf, int boundary_ok)
{
    if ((s->cnt[v] & 0x80000000u) && !boundary_ok) return;
    s48_sadd3(s, x, 3u * v, mp);
    s->cnt[v]++;
    if (!(mf & S48_EXACT)) s->dist[v] |= S48_INC;
}

#ifdef S48_DBG /* capacity statistics of a debug build (defined in sr48_level0.c) */
extern uint32_t s48_dbg[40];
#endif

/* The base's fan walk (sr48_level0.c's walks and the census's, sr48_census.c; static inline:
 * the innermost loop of every level-0 window and of the census): the neighbour of level-0
 * triangle t across slot 0 (base), 1 (leg 0: c-a), 2 (leg 1: b-c); the first step from t
 * (which holds x) around x in direction dir: the slot left by, *w the edge's other end (x's
 * slots in walk order: c 1, 2; a 1, 0; b 0, 2); the step into triangle nx, entered by the
 * edge (x, *w): nx is left by the edge at x opposite w (slot 0 opposite c, 2 opposite a, 1
 * opposite b), its other end (the third corner) the next *w. */
static inline uint32_t subd_s48_base_nbr_(const subd_sr48 *b, uint32_t t, uint32_t slot)
{
    uint32_t g;
    if (slot == 0u) return b->tri_base_nb[t];
    if ((t & 1u) == 0u && slot == 1u) return t + 1u;
    if ((t & 1u) == 1u && slot == 2u) return t - 1u;
    g = b->hyb_base_nb[t >> 1];
    if (g == SUBD_NONE) return SUBD_NONE;
    return (t & 1u) == 0u ? 2u * g + 1u : 2u * g;
}
static inline uint32_t subd_s48_fan_first_(const subd_sr48 *b, uint32_t x, uint32_t t, uint32_t dir, uint32_t *w)
{
    static const uint8_t sl[3][2] = {{1u, 2u}, {1u, 0u}, {0u, 2u}}, oe[3][2] = {{1u, 2u}, {0u, 2u}, {1u, 0u}};
    const uint32_t *v = b->tri_vert + 3u * t, p = v[0] == x ? 0u : v[1] == x ? 1u : 2u;
    *w = v[oe[p][dir]];
    return sl[p][dir];
}
static inline uint32_t subd_s48_fan_enter_(const subd_sr48 *b, uint32_t x, uint32_t nx, uint32_t *w)
{
    static const uint8_t opp[3] = {0u, 2u, 1u};
    const uint32_t *v = b->tri_vert + 3u * nx, u0 = v[0], u1 = v[1], u2 = v[2];
    const uint32_t slot = opp[u0 == *w ? 0u : u1 == *w ? 1u : 2u];
    *w = u0 + u1 + u2 - x - *w; /* unsigned: wraps back exactly */
    return slot;
}

/* The base mesh (sr48_window.c): SUBD_OK when b is a usable subd_sr48_base, and the largest
 * number of triangles around a base vertex. */
int subd_s48_base_check_(const subd_sr48 *b);
uint32_t subd_s48_valence_(const subd_sr48 *b);
/* The same, and with corners (the triangles at each vertex) *two = 1 when a vertex has two
 * fans (sr48_level0.c); the census with every gathering made (exact) or the bounded ones
 * skipped (counted in *skipped; sr48_census.c, compared by the tests). */
uint32_t subd_s48_valence_cnt_(const subd_sr48 *b, const uint32_t *corners, uint32_t *two);
uint32_t subd_s48_census_run_(subd_arena *a, const subd_sr48 *b, uint32_t exact, uint32_t *skipped);

/* Windows (sr48_window.c): level 0's window around base triangle t0; window p of level k
 * refined into X; X cropped to the rings of its triangles c0 .. c0 + n - 1 into w (capacity
 * ct, cv), or to the current triangle's two children into a level window. 0 on failure. */
int subd_s48_build0_(s48_state *s, uint32_t t0);
/* Level 0's window cropped smaller, for a uniform tile from level 0 (sr48_level0.c,
 * sr48_tile.c): ring 1 of t0's hybrid pair and the base neighbours of its triangles;
 * hd[7] = 1 (subd_s48_build0_: 0). 0 on failure. */
int subd_s48_build0_small_(s48_state *s, uint32_t t0);
int subd_s48_refine_(s48_state *s, const s48_win *p, uint32_t k, s48_win *x);
int subd_s48_crop_n_(s48_state *s, const s48_win *x, uint32_t c0, uint32_t n, s48_win *w, uint32_t ct, uint32_t cv);
int subd_s48_crop_(s48_state *s, const s48_win *x, uint32_t c0, s48_win *w);
/* subd_s48_refine_ of window p (level k) then subd_s48_crop_n_ of the children of p's
 * triangles c0 .. c0 + n - 1, in one pass without X (the same window w, bit for bit); w is
 * not p. fin 1, 2: the smaller crops of a tile's last window (sr48_window.c). 0 on failure. */
int subd_s48_refine_crop_(s48_state *s, const s48_win *p, uint32_t k, uint32_t c0, uint32_t n, s48_win *w,
                          uint32_t ct, uint32_t cv, uint32_t fin);
/* The last level of a uniform tile without its window (sr48_tile.c): the smoothed
 * positions at max_level of the corners of x's triangles c0 .. c0 + n - 1 (x: level
 * max_level - 1), into a's vertices by s->vmap. 0 on failure (s->err); else 1, or 2 when
 * a corner or a midpoint input of those triangles' diamonds is not exact. */
int subd_s48_last_(s48_state *s, const s48_win *x, uint32_t c0, uint32_t n, s48_win *a);

/* Descents (sr48_window.c): the finest position of vertex `id`, a corner of triangle t of
 * the level-k window; L of the level-0 window of t0; the adaptation box. 0 on failure. */
int subd_s48_finest_(s48_state *s, uint32_t k, uint32_t t, uint64_t id, subd_real *out);
int subd_s48_level0_lin_(s48_state *s, uint32_t t0);
int subd_s48_adapt_box_(s48_state *s);

/* Emission and the uniform tile (sr48_tile.c): window w's triangle t as a stream triangle;
 * the tile of the current triangle t of the level-k window w (n = 2: t and t + 1, the two
 * base triangles of a hybrid pair, at level 0); its triangles not handed out yet. 0 on
 * failure (a corner not exact). */
int subd_s48_emit_(const s48_state *s, const s48_win *w, uint32_t t, subd_stream_q *q, int *stop);
int subd_s48_tile_(s48_state *s, const s48_win *w, uint32_t t, uint32_t n);
int subd_s48_tile_emit_(s48_state *s, subd_stream_q *q, int *stop);

/* CHORD's decision for the current triangle t of the level-k window (sr48_chord_walk.c):
 * 1 split, 0 leaf, -1 failure. */
int subd_s48_chord_wants_(s48_state *s, uint32_t k, uint32_t t);
/* Empties CHORD's cache of finest positions (sr48_chord_walk.c); at the stream's begin. */
void subd_s48_chord_begin_(s48_state *s);
/* subd_s48_finest_ through CHORD's cache of finest positions (sr48_chord_walk.c). */
int subd_s48_chord_finest_(s48_state *s, uint32_t k, uint32_t t, uint64_t id, subd_real *out);

#endif
