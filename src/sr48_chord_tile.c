/* SPDX-License-Identifier: MIT */
/* Streaming semi-regular 4-8 refinement, CHORD: the tiles (paper:
 * semi-regular-4-8-refinement-box-splines.txt, sections 4 and 6; the criterion and its proof:
 * sr48_chord.c; the walk and the decisions that call these: sr48_chord_walk.c; the windows:
 * sr48_window.c; the private interfaces: sr48_stream_internal.h, sr48_chord_internal.h).
 *
 * A tile refines the last levels of a subtree breadth first, as the uniform stream's tile
 * (sr48_tile.c): one refinement and crop per level instead of one per node, every node's
 * corners and new vertex read at max_level from the last level. The windows are first
 * cropped to ring 1 of the descendants and the partners of their triangles and the last
 * level is made without its window (s48c_small); where a position would then not be exact,
 * the tile is made again with the two rings of the exactness argument (sr48_window.c), which
 * s48_state.two_rings forces for the tests. A kept vertex's position and flags do not depend
 * on the crop, so the deviations, and with them the cut, are the same either way.
 *  - the walk's tile (subd_s48_chord_tile_): a node of the depth-first walk and its subtree,
 *    with the counting flags of its nodes (s48c_flags) and the walk's ancestors above it;
 *  - the memo's tile (subd_s48_chord_bits_): a level-tl root's node deviations (E > eps per
 *    node), kept in the memo (subd_s48_chord_mk_) for every decision of levels tl ..
 *    max_level - 1 that meets it;
 *  - the interpolants (s48c_sub): each tested node's interpolant is carried down its subtree
 *    one midpoint step per level (the steps of subd_sr48_chord_beyond_, so the same bits).
 * Memo entries are functions of the root, never of the decision being taken.
 */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "sr48_chord_internal.h"

/* A tile's node masks are 64 bits (two words of a memo entry): its internal nodes
 * 1 .. 2^S48C_T - 1 (subd_s48_chord_tile_). */
typedef char s48c_masks_fit[S48C_T >= 1u && S48C_T <= 6u ? 1 : -1];

/* CHORD's tile arrays after the finest positions and their cache (sr48_stream.c's layout,
 * one block): the interpolant stack (9 subd_sr48_lin per level, 8 bytes each reserved),
 * then 3 corners per node of a tile of SUBD_SR48_STREAM_CTM_(levels) levels (heap order),
 * then a flag per node. */
static subd_sr48_lin *s48c_lin(const s48_state *s)
{
    return (subd_sr48_lin *)(void *)((uint8_t *)s->cpos + SUBD_SR48_SA_(12u * (s->levels + 4u + S48C_NC)));
}
static uint16_t *s48c_tn(const s48_state *s)
{
    return (uint16_t *)(void *)((uint8_t *)s48c_lin(s) + 72u * (SUBD_SR48_STREAM_CTM_(s->levels) + 1u));
}
static uint8_t *s48c_tf(const s48_state *s) { return (uint8_t *)s48c_tn(s) + (12u << SUBD_SR48_STREAM_CTM_(s->levels)); }
static uint8_t *s48c_vm(const s48_state *s) { return s48c_tf(s) + (2u << SUBD_SR48_STREAM_CTM_(s->levels)); }

/* One step of subd_sr48_chord_beyond_'s interpolant: the triangle l (apex, b0, b1) to its
 * child `bit` (0: (m; apex, b0), 1: (m; b1, apex)), m the midpoint of its base: the same
 * operations in the same order, so the same bits. */
static void s48c_lin_child(const subd_sr48_lin *l, uint32_t bit, subd_sr48_lin *c)
{
    uint32_t i;
    for (i = 0; i < 3u; i++) {
        c[i] = subd_sr48_lin_mid_(l[3u + i], l[6u + i]);
        c[3u + i] = bit ? l[6u + i] : l[i];
        c[6u + i] = bit ? l[i] : l[3u + i];
    }
}

/* The tile's subtree of node h0 (heap order in ctn, the internal nodes below n) against one
 * interpolant, given at h0 in clin[0..8]: the vertex each internal node creates (the apex
 * of its child 0), pre-order, the interpolant carried down one step per level in clin (as
 * subd_sr48_chord_beyond_ computes it along the path, so the same bits). 1 beyond, 0 within. */
static int s48c_sub(const s48_state *s, const s48_win *x, uint32_t h0, uint32_t n)
{
    subd_sr48_lin *st = s48c_lin(s), mid[3];
    const uint16_t *tn = s48c_tn(s);
    uint32_t h = h0, d = 0, i, e;
    for (e = 0; e < n; e++) { /* at most n - 1 nodes, each tested once */
        const subd_sr48_lin *l = st + 9u * d;
        for (i = 0; i < 3u; i++) mid[i] = subd_sr48_lin_mid_(l[3u + i], l[6u + i]);
        if (subd_sr48_beyond_(x->vp + 3u * tn[6u * h], mid, s->ad.eps)) return 1;
        if (2u * h < n) { /* an internal child 0 */
            s48c_lin_child(l, 0u, st + 9u * (d + 1u));
            h *= 2u;
            d++;
            continue;
        }
        while (d > 0u && (h & 1u)) { /* up past the children 1 */
            h >>= 1;
            d--;
        }
        if (d == 0u) return 0;
        h++; /* child 0's sibling */
        s48c_lin_child(st + 9u * (d - 1u), 1u, st + 9u * d);
    }
    return 0;
}

/* A cheap upper bound first (s48c_devs): for the vertex m that node h creates and a vertex v
 * of the subtree of h's child c, |P(v) - L_h(v)| <= |P(v) - L_c(v)| + |L_c(v) - L_h(v)|, and
 * L_c - L_h is affine on c with the values 0, 0 and P(m) - L_h(m) at c's corners (L_c's
 * corners are finest positions, so are h's), so E(h) <= |P(m) - L_h(m)| + max E(c) over
 * h's two children, E = 0 at max_level (any norm; here the sum of the axes' absolute values,
 * which bounds the Euclidean one). U(h), the bound carried up the tile, needs one midpoint
 * per node where s48c_sub walks every subtree. A node whose U is below the limits here is
 * within eps whatever the rounding of the exact test, which still decides every other node,
 * so the answers are the same bits:
 *  - Q16.16: U is exact in Q32.32, rounded up to units; the test's interpolant is exact (16
 *    halvings of Q32.32) and each axis rounded by half a unit, so the sum of its rounded
 *    axes is at most U + 3/2 and both its per-axis and its sum-of-squares comparisons say
 *    within when U <= eps - 2 units.
 *  - float: with M the largest |coordinate| of the tile's points (every L is a mean of
 *    them), the test's 7 midpoints per path err by at most 7 2^-24 M per axis and U's own
 *    rounding by at most 2^-20 U + 54 2^-24 M (6 terms of 3 axes), so with M <= 2^14 eps
 *    (and eps >= 1e-20, away from subnormals; else no filter) U <= 7 eps / 8 gives a
 *    Euclidean test value of at most (0.875 (1 + 2^-20) + 0.067) eps < eps (1 - 2^-21).
 * Measured (callgrind, `subd sr48 --stream --chord`, x86 instructions of the whole run): the
 * icosahedron at 9 steps, eps 0.01, 270.5 M -> 247.3 M (Q16.16 312.0 M -> 273.1 M); spot at 6
 * steps, eps 0.002, 10.25 G -> 8.58 G; on test_sr48_chord's shapes (float) 61 % of the nodes
 * are cleared by U, and the cuts there are compared with the exhaustive criterion. */
#if SUBD_FIXED
typedef uint32_t s48c_ub; /* Q16.16 units, rounded up, saturating */
static void s48c_mx(const subd_real *p, subd_real *mx) { (void)p, (void)mx; } /* M: not needed */
static s48c_ub s48c_ub_of(const subd_real *pm, const subd_real *b0, const subd_real *b1, subd_real *mx)
{
    uint64_t e = 0;
    uint32_t i;
    (void)mx;
    for (i = 0; i < 3u; i++) {
        const int64_t d = (int64_t)pm[i] * 65536 -
                          subd_sr48_lin_mid_(subd_sr48_lin_of_(b0[i]), subd_sr48_lin_of_(b1[i]));
        e += (uint64_t)(d < 0 ? -d : d);
    }
    e = (e + 65535u) >> 16;
    return e > 0xFFFFFFFFu ? 0xFFFFFFFFu : (s48c_ub)e;
}
static s48c_ub s48c_ub_add(s48c_ub a, s48c_ub b) { return a > 0xFFFFFFFFu - b ? 0xFFFFFFFFu : a + b; }
static s48c_ub s48c_ub_max(s48c_ub a, s48c_ub b) { return a > b ? a : b; }
static int s48c_ub_filters(subd_real eps, subd_real mx) { return (void)mx, eps >= 2; }
static int s48c_ub_within(s48c_ub u, subd_real eps) { return (uint64_t)u + 2u <= (uint64_t)(uint32_t)eps; }
#else
typedef float s48c_ub;
static float s48c_absf(float x) { return x < 0.0f ? -x : x; }
/* M: the largest |coordinate| of p's so far; a NaN stays (then no filter) */
static void s48c_mx(const subd_real *p, subd_real *mx)
{
    uint32_t i;
    for (i = 0; i < 3u; i++) {
        const float a = s48c_absf(p[i]);
        if (!(a <= *mx) && *mx == *mx) *mx = a;
    }
}
static s48c_ub s48c_ub_of(const subd_real *pm, const subd_real *b0, const subd_real *b1, subd_real *mx)
{
    float e = 0.0f;
    uint32_t i;
    for (i = 0; i < 3u; i++) e += s48c_absf(pm[i] - subd_sr48_lin_mid_(b0[i], b1[i]));
    s48c_mx(pm, mx);
    return e;
}
static s48c_ub s48c_ub_add(s48c_ub a, s48c_ub b) { return a + b; }
static s48c_ub s48c_ub_max(s48c_ub a, s48c_ub b) { return (a > b || a != a) ? a : b; } /* NaN wins */
static int s48c_ub_filters(subd_real eps, subd_real mx) { return mx <= eps * 16384.0f && eps >= 1e-20f; }
static int s48c_ub_within(s48c_ub u, subd_real eps) { return u <= eps * 0.875f; }
#endif

/* E > eps of every internal node 1 .. n - 1 of the tile (n = 2^m, m <= 6; nodes in tn,
 * corners filled): bit h set when node h deviates. U bottom up, level by level in place
 * (slot i of a level reads slots 2i, 2i + 1 of the level below before it is written), then
 * the exact test (s48c_sub) on the nodes U does not clear. */
static uint64_t s48c_devs(const s48_state *s, const s48_win *x, uint32_t n)
{
    subd_sr48_lin *st = s48c_lin(s);
    const uint16_t *tn = s48c_tn(s);
    s48c_ub u[32];
    uint64_t bad = 0, ok = 0;
    subd_real mx = 0;
    uint32_t h, q, lo, i;
    for (i = 0; i < 3u; i++) s48c_mx(x->vp + 3u * tn[3u + i], &mx); /* the root's corners: tile points too */
    for (lo = n >> 1; lo >= 1u; lo >>= 1)
        for (h = lo; h < 2u * lo; h++) {
            const uint16_t *c = tn + 3u * h;
            s48c_ub e = s48c_ub_of(x->vp + 3u * tn[6u * h], x->vp + 3u * c[1], x->vp + 3u * c[2], &mx);
            if (2u * h < n) {
                e = s48c_ub_add(e, s48c_ub_max(u[2u * (h - lo)], u[2u * (h - lo) + 1u]));
            }
            u[h - lo] = e;
            if (s48c_ub_within(e, s->ad.eps)) ok |= (uint64_t)1 << h;
        }
    if (!s48c_ub_filters(s->ad.eps, mx)) ok = 0;
    for (h = 1; h < n; h++) {
        if ((ok >> h) & 1u) continue;
        for (q = 0; q < 9u; q++) st[q] = subd_sr48_lin_of_(x->vp[3u * tn[3u * h + q / 3u] + q % 3u]);
        if (s48c_sub(s, x, h, n)) bad |= (uint64_t)1 << h;
    }
    return bad;
}

/* The memo entry of the tile root with key `key` at level j: S48C_NB entries of 5 words after
 * the decided diamonds (subd_s48_chord_tile_ has their words), in sets of S48C_NW (by key and
 * level), each set kept in order of use (move to front). The entry that holds the root, else
 * a victim: the least recently used entry that is empty, or whose root lies in a level-0
 * triangle before the current one (s->t0; the stream walks them in index order) or more than
 * 2 S48C_NB / 2^j triangles after it, else the set's least recently used; moved to the set's
 * front either way and returned there (valid until the next call). Why: many tiles are first
 * made for a decision of an earlier level-0 triangle near the shared edge or vertex (on the
 * icosahedron at 9 steps, eps 0.01: 900 of 1 141 under 2-way LRU), so a tile of a triangle
 * soon to come is asked again when that triangle is walked, while one of an earlier triangle
 * only by the decisions left near it; one far ahead would be evicted before (the memo holds
 * about S48C_NB / 2^j level-0 triangles' tiles). Measured (tiles made, icosahedron 9 steps eps
 * 0.01 / spot 6 steps eps 0.002): 2-way LRU 1 222 / 60 575; 16-way LRU 1 162 / 56 184;
 * 16-way keeping every later triangle 944 / 63 603; this (horizon 2 S48C_NB / 2^j) 939 /
 * 54 180, horizon S48C_NB / 2^j 997 / 54 654 (every tile kept: 673 / 23 776). Which entry
 * holds a root changes nothing but the hits: entries are functions of their roots. */
#ifndef S48C_NW
#define S48C_NW 16u
#endif
#ifndef S48C_PD
#define S48C_PD 2u /* subd_s48_chord_bits_: levels of a memo tile whose corners are cached */
#endif
typedef char s48c_ways_fit[S48C_NW >= 1u && S48C_NB % S48C_NW == 0u ? 1 : -1];
/* The memo's set for the tile root (key, level j) in *set, and the root's way in it
 * (S48C_NW when the set does not hold it): the one lookup of subd_s48_chord_mk_ and
 * subd_s48_chord_mk_find_. */
static uint32_t s48c_mk_way(const s48_state *s, uint64_t key, uint32_t j, uint32_t **set)
{
    const uint32_t tag = (uint32_t)(key >> 32) | j << 20;
    uint32_t *e = s->cdesc + 3u * S48C_ND + 2u * (S48C_NC + S48C_ND2) +
                  5u * S48C_NW * ((((uint32_t)key ^ tag) * 2654435761u) >> 16 & (S48C_NB / S48C_NW - 1u));
    uint32_t f = 0;
    while (f < S48C_NW && !(e[5u * f] == (uint32_t)key && e[5u * f + 1u] == tag)) f++;
    *set = e;
    return f;
}

uint32_t *subd_s48_chord_mk_(const s48_state *s, uint64_t key, uint32_t j)
{
    uint32_t *e, q, h[5], f = s48c_mk_way(s, key, j, &e);
    if (f == 0u) return e;
    if (f == S48C_NW) { /* a miss: the victim (above) */
        for (f = S48C_NW - 1u; f > 0u; f--) {
            const uint32_t lv = e[5u * f + 1u] >> 20;
            uint32_t r0;
            if (e[5u * f + 1u] == 0xffffffffu) break; /* empty */
            r0 = (uint32_t)((((uint64_t)(e[5u * f + 1u] & 0xfffffu) << 32) | e[5u * f]) >> lv);
            if (r0 < s->t0 || r0 - s->t0 > ((2u * S48C_NB) >> lv)) break;
        }
        if (f == 0u) f = S48C_NW - 1u;
    }
    for (q = 0; q < 5u; q++) h[q] = e[5u * f + q];
    for (; f > 0u; f--)
        for (q = 0; q < 5u; q++) e[5u * f + q] = e[5u * (f - 1u) + q];
    for (q = 0; q < 5u; q++) e[q] = h[q];
    return e;
}

/* The memo entry of the tile root with key `key` at level j if it holds it, else NULL; no
 * change of the order of use (a look that may well miss: s48c_coarse). */
const uint32_t *subd_s48_chord_mk_find_(const s48_state *s, uint64_t key, uint32_t j)
{
    uint32_t *e, f = s48c_mk_way(s, key, j, &e);
    return f < S48C_NW ? e + 5u * f : 0;
}

/* One level of a tile (subd_s48_chord_tile_, subd_s48_chord_bits_: the same refinements and crops, so the same
 * positions): at the first level of a tile of 2 or more levels the root r's window w is
 * cropped to r and its two rings (the window's invariant); the window *p of level `level` is
 * refined into x; unless it was the tile's last level, x is cropped into a to the rings of
 * the descendants (*lo, *n: their first index and count, doubled by the refinement).
 * -1 failure, 1 the last level refined (in x), 0 go on. */
static int s48c_level(s48_state *s, const s48_win *w, uint32_t r, uint32_t level, int first, int last,
                      const s48_win **p, s48_win *a, s48_win *x, uint32_t *lo, uint32_t *n, uint32_t ct, uint32_t cv)
{
    if (first && !last) {
        if (!subd_s48_crop_n_(s, w, r, 1u, a, ct, cv)) return -1;
        *lo = a->hd[3];
        *p = a;
    }
    if (!subd_s48_refine_(s, *p, level, x)) return -1;
    *lo *= 2u;
    *n *= 2u;
    if (last) return 1;
    if (!subd_s48_crop_n_(s, x, *lo, *n, a, ct, cv)) return -1;
    *lo = a->hd[3];
    *p = a;
    return 0;
}

/* subd_s48_chord_tile_'s counting flags of the tile's nodes at one level (the descendants lo .. lo + n - 1
 * of window p, level j + step, `step` levels below the root, which is f->up levels below the
 * decision's level f->k): tf[n + q]. They read the keys of the nodes and the fans of their
 * corners only, which every crop of the tile holds (ring 1 of the descendants holds each
 * corner's fan wherever two rings do), so they do not depend on the crop. 0, or -2 when a
 * loose tile's window misses part of a star. */
typedef struct s48c_fl {
    uint32_t k, up, loose;
} s48c_fl;
static int s48c_flags(const s48_state *s, const s48c_fl *f, uint32_t j, uint32_t step, const s48_win *p, uint32_t lo,
                      uint32_t n)
{
    const uint32_t d = f->up + step;
    uint8_t *tf = s48c_tf(s), *vm = s48c_vm(s);
    uint32_t i, q, u, h;
    if (d == S48C_M) {
        /* subd_s48_chord_counts_' star test for all of them at once: per vertex of p, 1 when
         * it is a corner of one of F(D)'s triangles of this level, 2 when a triangle at it
         * has an outside neighbour across an edge at it (its fan is not all in p: a loose
         * tile's window may miss part of a star) */
        for (i = 0; i < p->hd[1]; i++) vm[i] = 0;
        for (i = 0; i < p->hd[0]; i++) {
            const uint16_t *tv = p->tv + 3u * i;
            if (subd_s48_chord_has_(s, S48C_M, s48_key(p, i), 1u)) {
                vm[tv[0]] |= 1u;
                vm[tv[1]] |= 1u;
                vm[tv[2]] |= 1u;
            }
            for (u = 0; u < 3u; u++) /* slot u's ends: (a, b), (c, a), (b, c) */
                if (p->tn[3u * i + u] == S48_OUT) {
                    vm[tv[u == 0u ? 1u : u == 1u ? 0u : 2u]] |= 2u;
                    vm[tv[u == 0u ? 2u : u == 1u ? 1u : 0u]] |= 2u;
                }
        }
    }
    for (q = 0; q < n; q++) {
        h = n + q;
        if (d == S48C_M) {
            const uint16_t *tv = p->tv + 3u * (lo + q);
            const uint32_t mv = (uint32_t)vm[tv[0]] | vm[tv[1]] | vm[tv[2]];
            if (f->loose && (mv & 2u)) return -2;
            tf[h] = (uint8_t)(mv & 1u);
        } else if (d < S48C_M) {
            tf[h] = (uint8_t)subd_s48_chord_counts_(s, f->k, j + step, p, lo + q);
        } else {
            tf[h] = step == 0u ? 1u : tf[h >> 1];
        }
    }
    return 0;
}

/* The level max_level triangles of the tile of triangle r of the level-j window w (m = max_level - j
 * >= 2 levels) with the uniform tile's smaller crops (sr48_tile.c, s48_tile_build): m - 1
 * refinements, each cropped in the same pass to ring 1 of r's descendants and the partners of
 * their triangles (subd_s48_refine_crop_'s fin 1; the last as the uniform tile's last, fin 1
 * or 2, except that a flagged tile keeps fin 1 there: its star test may fall on the last level
 * and needs every triangle at the descendants' corners, which fin 2 drops), alternately into the tile window A and x so that the last, level
 * max_level - 1 (its descendants D), lands in x; then level max_level without its window, as
 * subd_s48_tile_emit_ makes it: D's corners (smoothed by subd_s48_last_ when max_level is even
 * and smoothed) and each D triangle's diamond's new vertex (the midpoint of the same two
 * vertices, subd_mid; into x's vertex nv + q for D's triangle q, nv = x's vertex count, after
 * the ones D's corners have). Every position is checked exact first (s48_tile_exact's
 * tests): a kept vertex's position and flags do not depend on the crop, so the positions are
 * those of the two rings' tile below. tn gets the corners of the 2 |D| triangles of level
 * max_level (nodes 2 |D| .. 4 |D| - 1), *nl their count. 1 done, 0 not exact, a capacity or
 * an overflow (the caller makes the tile with the two rings, which reports the overflow),
 * -1 failure. fl (subd_s48_chord_tile_'s tiles): each level's counting flags first (s48c_flags; -2 as
 * there). A (*ap) holds capacities s->at, s->av. Measured: about half the refined triangles of
 * the two rings' tile. */
static int s48c_small(s48_state *s, const s48_win *w, uint32_t j, uint32_t r, uint32_t m, s48_win *ap, s48_win *x,
                      uint32_t *nl, const s48c_fl *fl)
{
    const uint32_t sm = s->smooth && (s->levels & 1u) == 0u;
    const s48_win a = *ap;
    const s48_win *p = w;
    uint16_t *tn = s48c_tn(s);
    uint32_t step, lo = r, n = 1, q, i, nv, ovf = 0;
    for (step = 0; step + 1u < m; step++) {
        const uint32_t last = step + 2u == m;
        s48_win *o = ((m - 2u - step) & 1u) ? ap : x;
        if (fl && s48c_flags(s, fl, j, step, p, lo, n) < 0) return -2;
        if (!subd_s48_refine_crop_(s, p, j + step, lo, n, o, s->at, s->av, last && !sm && !fl ? 2u : 1u))
            return s->err ? -1 : 0;
        lo = o->hd[3];
        n *= 2u;
        p = o;
    }
    if (fl && s48c_flags(s, fl, j, m - 1u, x, lo, n) < 0) return -2;
    if (sm && !subd_s48_last_(s, x, lo, n, ap)) return s->err ? -1 : 0;
    nv = x->hd[1];
    if (nv + n > s->xv) return 0;
    for (q = 0; q < n; q++) {
        const uint16_t *tv = x->tv + 3u * (lo + q);
        uint32_t e0, e1, lt;
        const uint16_t lnb = subd_s48_mid_ends_(s, x, lo + q, &lt, &e0, &e1);
        if (lnb == S48_OUT || !(x->vf[e0] & x->vf[e1] & S48_EXACT)) return 0;
        for (i = 0; i < 3u; i++)
            if (!((sm ? a.vf[s->vmap[tv[i]]] : x->vf[tv[i]]) & S48_EXACT)) return 0;
        for (i = 0; i < 3u; i++) x->vp[3u * (nv + q) + i] = subd_mid(x->vp[3u * e0 + i], x->vp[3u * e1 + i], &ovf);
        /* child 0 = (m; c, a), child 1 = (m; b, c) of (c; a, b) */
        tn[6u * (n + q)] = (uint16_t)(nv + q);
        tn[6u * (n + q) + 1u] = tv[0];
        tn[6u * (n + q) + 2u] = tv[1];
        tn[6u * (n + q) + 3u] = (uint16_t)(nv + q);
        tn[6u * (n + q) + 4u] = tv[2];
        tn[6u * (n + q) + 5u] = tv[0];
    }
    if (ovf) return 0;
    if (sm) /* D's corners at max_level, after every new vertex read them at max_level - 1 */
        for (q = 0; q < 3u * n; q++) {
            const uint16_t v = x->tv[3u * lo + q];
            for (i = 0; i < 3u; i++) x->vp[3u * v + i] = a.vp[3u * s->vmap[v] + i];
        }
    *nl = 2u * n;
    return 1;
}

/* CHORD's tile: the subtree of the walk's node r (level j >= k, current in the level-j window,
 * entered; its ancestors' nodes k .. j - 1 on the walk's path, with their counting flags and
 * their corners' finest positions) refined breadth first down to max_level as the uniform
 * stream's tile (sr48_tile.c: each level cropped to the rings of r's descendants, a union of the
 * windows the depth-first walk would crop, so every position is exact and the stream's, checked),
 * in the tile window A and X. Its nodes' counting flags are the walk's (subd_s48_chord_counts_ on
 * the level's window, which holds each descendant's rings; below level k + S48C_M a node counts
 * iff its ancestor there does); the corners of every node come bottom up from the level max_level
 * triangles (child 0 = (m; c, a), child 1 = (m; b, c) of (c; a, b)). Then every vertex the
 * subtree creates is tested against every counting node above it: the walk's counting ancestors
 * (their interpolant brought down to r) and the tile's counting nodes: the same pairs as the
 * depth-first walk tests, so the same answer. 1 beyond, 0 within, -1 failure; loose (r is not its
 * window's current triangle): -2 when the window misses part of a depth-S48C_M node's star or a
 * corner is not exact (the caller then rebuilds r's own windows). */
int subd_s48_chord_tile_(s48_state *s, uint32_t k, uint32_t j, uint32_t r, uint32_t loose)
{
    const uint32_t m = s->levels - j, up = j - k; /* up: the walk's nodes above r */
    s48_win w, x, a;
    const s48_win *p = &w;
    uint32_t step, lo = r, n = 1, q, h, i, u, dd, deep = 0, above, *mk, tag;
    uint64_t bad;
    int lv;
    uint16_t *tn = s48c_tn(s);
    uint8_t *tf = s48c_tf(s);
    subd_sr48_lin *st = s48c_lin(s);
    const s48c_fl fl = {k, up, loose};
    /* A: the level window j + 1 (m = 2: two children, a level window's crop) or j + 1 ..
     * j + 3 (m >= 3: the tile window's layout, which fits three level windows:
     * sr48_stream.c), free below the walk's node (j + 3 <= max_level: for m = 3 the third
     * is the first window of the memo's tiles, s48c_mwin, scratch between their calls) */
    const uint32_t ct = m >= 3u ? s->at : s->wt, cv = m >= 3u ? s->av : s->wv;
    uint64_t key;
    s48_lev(s, j, &w);
    key = s48_key(&w, r);
    tag = (uint32_t)(key >> 32) | j << 20;
    /* r's deviations kept (S48C_NB entries of 5 words after the decided diamonds, sets of S48C_NW by
     * key and level, subd_s48_chord_mk_: key low word; key high word | level << 20; words 2 and 4 the
     * low and high halves of a 64-bit mask, bit h set when the tile's node h deviates by
     * more than eps, E(h) > eps; word 3 bit u set when the vertices r's subtree creates
     * deviate from the interpolant of r's ancestor u levels up, for u <= the value in bits
     * 24..28). All are functions of r, whatever the decision: a hit answers unless a
     * deviating node's counting flag needs the star test (level k + S48C_M), which needs
     * the tile's windows. */
    mk = subd_s48_chord_mk_(s, key, j);
    if (mk[0] == (uint32_t)key && mk[1] == tag && (mk[3] >> 24 & 0x1fu) >= up) {
        for (u = 1; u <= up; u++)
            if (((mk[3] >> u) & 1u) && s->cfl[j - u]) return 1;
        for (h = 1, dd = 0; h < (1u << m); h++) {
            if (h == 2u << dd) dd++; /* h's depth below r */
            if (!(((mk[2] | (uint64_t)mk[4] << 32) >> h) & 1u)) continue;
            if (up + dd < S48C_M) {
                if (subd_s48_chord_has_(s, up + dd, (key << dd) | (h - (1u << dd)), 1u)) return 1;
            } else if (up > S48C_M) {
                return 1; /* below level k + S48C_M every node of an entered subtree counts */
            } else {
                deep = 1;
            }
        }
        if (!deep) return 0;
    }
    s48_x(s, &x);
    if (m >= 3u) s48_win_at(s, s->lev + (j + 1u) * s->lev_size, s->aoff, &a);
    else if (m == 2u) s48_lev(s, j + 1u, &a);
    /* with the smaller crops where A has the tile window's capacities (m >= 3), else or when
     * they miss a position, each level cropped to the two rings */
    lv = m >= 3u && !s->two_rings ? s48c_small(s, &w, j, r, m, &a, &x, &n, &fl) : 0;
    if (lv < 0) return lv;
    if (lv == 0) {
        n = 1;
        for (step = 0; step < m; step++) {
            if (s48c_flags(s, &fl, j, step, p, lo, n) < 0) return -2;
            lv = s48c_level(s, &w, r, j + step, step == 0u, step + 1u == m, &p, &a, &x, &lo, &n, ct, cv);
            if (lv < 0) return -1;
            if (lv > 0) break;
        }
        for (q = 0; q < n; q++) /* the level max_level descendants: nodes n .. 2n - 1 */
            for (i = 0; i < 3u; i++) {
                const uint16_t v = x.tv[3u * (lo + q) + i];
                if (!(x.vf[v] & S48_EXACT)) return loose ? -2 : -1;
                tn[3u * (n + q) + i] = v;
            }
    }
    for (h = n - 1u; h >= 1u; h--) {
        tn[3u * h] = tn[6u * h + 1u];
        tn[3u * h + 1u] = tn[6u * h + 2u];
        tn[3u * h + 2u] = tn[6u * h + 4u];
    }
    if (up == 0u) /* the root's corners: the leaf's, if its diamond does not split */
        for (i = 0; i < 3u; i++) subd_s48_chord_put_(s, s48_vid(&x, tn[3u + i]), x.vp + 3u * tn[3u + i]);
    bad = s48c_devs(s, &x, n); /* every node's deviation */
    for (u = 1, above = 0; u <= up; u++) { /* the walk's nodes above, their interpolant brought down to r */
        const uint32_t l = j - u;
        for (q = 0; q < 9u; q++) st[q] = subd_sr48_lin_of_(s->cpos[3u * s->csrc[3u * l + q / 3u] + q % 3u]);
        for (i = l; i < j; i++) {
            s48c_lin_child(st, s->cch[i] - 1u, st + 9);
            for (q = 0; q < 9u; q++) st[q] = st[9u + q];
        }
        if (s48c_sub(s, &x, 1u, n)) above |= 1u << u;
    }
    mk[0] = (uint32_t)key;
    mk[1] = tag;
    mk[2] = (uint32_t)bad;
    mk[4] = (uint32_t)(bad >> 32);
    mk[3] = above | up << 24;
    for (u = 1; u <= up; u++)
        if (((above >> u) & 1u) && s->cfl[j - u]) return 1;
    for (h = 1; h < n; h++)
        if (((bad >> h) & 1u) && tf[h]) return 1;
    return 0;
}

/* The memo's tiles (the decisions of levels k >= tl = max_level - S48C_T, or 0 when
 * max_level <= S48C_T): a star triangle i of level k is a node of the tile of its level-tl
 * ancestor, so E > eps of i's nodes are bits of that tile's memo entry, which one tile
 * computes for the 2^(k - tl) triangles of every level k below it and for every decision
 * that meets them (before: one tile per star triangle per decision level, from its own
 * level). The root is taken from the level-tl window of whatever path the windows hold
 * (any window triangle: positions are exact where flagged, and every corner at max_level
 * is checked), refined in the tile window after level max_level - 1's (three level
 * windows, free: a decision of level k <= max_level - 1 holds windows 0..k) and X. */
static s48_win s48c_mwin(const s48_state *s)
{
    s48_win a;
    s48_win_at(s, s->lev + (s->levels > 1u ? s->levels : 1u) * s->lev_size, s->aoff, &a);
    return a;
}

/* The memo's tile of triangle r of the level-j window (j the tiles' level): E > eps of each
 * of its nodes into r's memo entry mk (subd_s48_chord_tile_'s words, no walk ancestors: up = 0). The level
 * max_level triangles come from s48c_small, else from subd_s48_chord_tile_'s refinements and crops
 * (so the same positions either way); then the same bottom-up node corners and tests
 * (s48c_sub). 1 done, 0 a corner at max_level is not exact (the window misses part of r's
 * dependency cone), -1 failure. */
int subd_s48_chord_bits_(s48_state *s, uint32_t j, uint32_t r, uint32_t *mk)
{
    const uint32_t m = s->levels - j;
    s48_win w, x, a = s48c_mwin(s);
    const s48_win *p = &w;
    uint32_t step, lo = r, n = 1, q, h, i;
    uint64_t bad;
    int lv;
    uint16_t *tn = s48c_tn(s);
    uint64_t key;
    s48_lev(s, j, &w);
    key = s48_key(&w, r);
    s48_x(s, &x);
    lv = m >= 2u && !s->two_rings ? s48c_small(s, &w, j, r, m, &a, &x, &n, 0) : 0;
    if (lv < 0) return -1;
    if (lv == 0) {
        n = 1;
        for (step = 0; step < m; step++) {
            lv = s48c_level(s, &w, r, j + step, step == 0u, step + 1u == m, &p, &a, &x, &lo, &n, s->at, s->av);
            if (lv < 0) return -1;
            if (lv > 0) break;
        }
        for (q = 0; q < n; q++) /* the level max_level descendants: nodes n .. 2n - 1 */
            for (i = 0; i < 3u; i++) {
                const uint16_t v = x.tv[3u * (lo + q) + i];
                if (!(x.vf[v] & S48_EXACT)) return 0;
                tn[3u * (n + q) + i] = v;
            }
    }
    for (h = n - 1u; h >= 1u; h--) {
        tn[3u * h] = tn[6u * h + 1u];
        tn[3u * h + 1u] = tn[6u * h + 2u];
        tn[3u * h + 2u] = tn[6u * h + 4u];
    }
    bad = s48c_devs(s, &x, n); /* every node's deviation */
    /* the finest positions of the corners of its nodes of the first S48C_PD levels into the
     * cache (the root's corners and the new vertices of nodes 1 .. 2^(S48C_PD - 1) - 1; not
     * the ones made at max_level past x's vertices): the corners of the leaves of the cut
     * there, asked when they are emitted (subd_s48_chord_finest_). Exact (checked above) and
     * a function of the id: the same bits as a descent. Measured on the icosahedron at 9
     * steps, eps 0.01 (x86, whole run; the cache is direct mapped, more puts evict more):
     * none 173.7 M (774 descents), S48C_PD 1 164.6 M (500), 2 162.8 M (425), 3 164.9 M (477),
     * 4 168.2 M (552). */
    for (i = 0; i < 3u; i++) subd_s48_chord_put_(s, s48_vid(&x, tn[3u + i]), x.vp + 3u * tn[3u + i]);
    for (h = 1; h < (1u << (S48C_PD - 1u)) && 2u * h < n; h++)
        if (tn[6u * h] < x.hd[1]) subd_s48_chord_put_(s, s48_vid(&x, tn[6u * h]), x.vp + 3u * tn[6u * h]);
    mk[0] = (uint32_t)key;
    mk[1] = (uint32_t)(key >> 32) | j << 20;
    mk[2] = (uint32_t)bad;
    mk[4] = (uint32_t)(bad >> 32);
    mk[3] = 0;
    return 1;
}
