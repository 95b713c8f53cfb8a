/* SPDX-License-Identifier: MIT */
/* Streaming semi-regular 4-8 refinement: the CHORD criterion's walk (paper:
 * semi-regular-4-8-refinement-box-splines.txt, sections 4 and 6; the criterion, why it nests
 * and why it is conservative: sr48_chord.c, whose test this file calls; the windows it
 * walks: sr48_window.c; the counting region F(D) it asks: sr48_chord_region.c; the private
 * interfaces: sr48_stream_internal.h, sr48_chord_internal.h). Kept apart from sr48_chord.c,
 * which subd_sr48_extract shares: this file needs the stream's windows.
 *
 * Chordal cuts (CHORD; the criterion, why it nests and why it is conservative: sr48_chord.c):
 * the current triangle's diamond D splits iff a triangle of S(D) (the diamonds whose split
 * forces D's, S48C_M levels down, then the stars of the deepest of them) has a chordal
 * deviation of subd_sr48_extract's kind above eps. F(D)'s first levels come from the
 * level-k window's adjacency (subd_s48_chord_desc_, sr48_chord_region.c); S(D) lies under
 * D's star (in the window), whose triangles' subtrees are searched to max_level (a triangle
 * whose subtree cannot hold a member is skipped, subd_s48_chord_may_). The answer is exactly
 * the one of walking every counting node and testing every vertex below it (same cut, bits
 * and order); what makes it cheaper:
 *  - tiles (subd_s48_chord_tile_): the last S48C_T levels of a subtree are refined breadth first, as
 *    the uniform stream's tile (sr48_tile.c), one refinement and crop per level instead of
 *    one per node (first cropped to ring 1 of the descendants and their partners, the last
 *    level made without its window, sr48_chord_tile.c; two rings where a position would not be
 *    exact), and every node's corners and new vertex are read at max_level from the
 *    last refined window (no descents); a decision of level k >= max_level - S48C_T tiles
 *    each star triangle from the current window when it holds what the tile needs (every
 *    corner exact, the full star at the star test's level: checked), else after rebuilding
 *    the windows along that triangle's path (s48c_path); a coarser decision walks depth
 *    first (s48_chord_walk) down to level max_level - S48C_T and tiles there;
 *  - the interpolants (sr48_chord_tile.c's s48c_sub): each tested node's interpolant is carried down its subtree
 *    one midpoint step per level (the steps of subd_sr48_chord_beyond_, so the same bits)
 *    instead of being rebuilt from the node for every vertex;
 *  - the memo's tiles (s48c_fast, subd_s48_chord_bits_): a decision of level k >= tl = max_level -
 *    S48C_T reads E > eps of the nodes under each star triangle from the memo entry of its
 *    level-tl ancestor's tile (made from the level-tl window when missing, in three level
 *    windows kept for it after max_level - 1's), so a tile of the last S48C_T levels is
 *    refined about once for all the decisions of levels tl .. max_level - 1 that meet it;
 *    only a deviating node S48C_M or more levels below the decision (its star test needs
 *    that level's window) sends the star triangle to its own tile as before;
 *  - the answers before F(D) (s48c_pre, s48c_coarse): every node under D's own triangles is in
 *    S(D) (sr48_chord.c), so one of them deviating splits D, and a decision none of whose star
 *    subtrees deviates is a leaf, both read from the memo's bits without F(D)
 *    (subd_s48_chord_desc_) or a walk; a coarser decision (k < tl) reads only the tiles the
 *    memo already holds. Measured on the icosahedron at 9 steps, eps 0.01 (x86, whole run):
 *    F(D) made 1 849 -> 654 times, the depth-first walk entered 587 -> 251 times;
 *    with the memo's victim rule (subd_s48_chord_mk_) and its tiles' cached corners
 *    (subd_s48_chord_bits_), 233.3 M -> 162.6 M; spot at 6 steps, eps 0.002, 7.83 G -> 6.36 G;
 *  - memos, all exact (functions of a key, never of the decision being taken): a tile root's
 *    deviations (E > eps of each of its nodes, and of each walk ancestor over its subtree:
 *    whether a node counts depends on the decision, its deviation does not), the answer
 *    per diamond (asked by both its triangles), finest positions per vertex id.
 *
 * The walk's per-level state, the star's keys, F(D)'s first levels and the memos are blocks
 * of the stream's state (s48_state's c* members, sized by sr48_stream.c's layout; a tile's
 * window A lives in three level windows below the tile's root, free during a decision).
 *
 * The tiles, their smaller crops and the memo's tiles are sr48_chord_tile.c's (one file per
 * concept: the walk and the decisions here, the breadth-first tiles there; their calls:
 * sr48_chord_internal.h).
 */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "sr48_chord_internal.h"


/* The cache of finest positions (S48C_NC entries, direct mapped by id: the ids after cdesc,
 * the positions after cpos, sr48_stream_internal.h): a
 * vertex's finest position is a function of its id (subd_s48_finest_ finds subd_sr48_build's
 * bits, whatever window it starts from), so a hit gives the same bits as the descent it saves.
 * The walked triangles' corners and the nodes' new vertices are asked again and again: by
 * every star triangle at a corner, by the decisions of the sibling and of the children. */
void subd_s48_chord_begin_(s48_state *s)
{
    uint32_t i;
    uint32_t *cid = s->cdesc + 3u * S48C_ND;
    for (i = 0; i < 2u * (S48C_NC + S48C_ND2) + 5u * S48C_NB; i++) cid[i] = 0xffffffffu;
}

static uint32_t s48c_slot(uint64_t id)
{
    return (uint32_t)(((uint32_t)id ^ (uint32_t)(id >> 32)) * 2654435761u) >> 16 & (S48C_NC - 1u);
}

/* Keeps the finest position p of vertex id in the cache. */
void subd_s48_chord_put_(s48_state *s, uint64_t id, const subd_real *p)
{
    uint32_t e = s48c_slot(id), q, *cid = s->cdesc + 3u * S48C_ND;
    subd_real *cp = s->cpos + 3u * (s->levels + 4u);
    cid[2u * e] = (uint32_t)id;
    cid[2u * e + 1u] = (uint32_t)(id >> 32);
    for (q = 0; q < 3u; q++) cp[3u * e + q] = p[q];
}

/* subd_s48_finest_ through the cache (the same contract; blocks > k and X are clobbered on a
 * miss only, which the callers allow). Also the CHORD stream's leaves' corners (sr48_stream.c:
 * the walk's and the tiles' roots' corners were cached when their diamonds were decided; the
 * others, usually one or two of a leaf's three, by a descent each: measured cheaper than a
 * tile of the leaf's level-tl ancestor, which 0.6.0 made for them at first). */
int subd_s48_chord_finest_(s48_state *s, uint32_t k, uint32_t t, uint64_t id, subd_real *out)
{
    uint32_t e = s48c_slot(id), q, *cid = s->cdesc + 3u * S48C_ND;
    const subd_real *cp = s->cpos + 3u * (s->levels + 4u);
    if (cid[2u * e] == (uint32_t)id && cid[2u * e + 1u] == (uint32_t)(id >> 32)) {
        for (q = 0; q < 3u; q++) out[q] = cp[3u * e + q];
        return 1;
    }
    if (!subd_s48_finest_(s, k, t, id, out)) return 0;
    subd_s48_chord_put_(s, id, out);
    return 1;
}

/* CHORD (the criterion and its proof: sr48_chord.c). Rebuilds the windows of levels 0..k
 * along the path of the level-k triangle with key `key` (T0 * 2^k + its child bits), as
 * the walk leaves them when that triangle is current (hd[2], hd[5]): the same calls on the
 * same input, so the same bits. `have` is the key whose path the windows 0..k hold now
 * (the walk leaves them alone): window j + 1 is a function of window j and its current
 * triangle (level j's ancestor) only, window 0 of T0 only, so the windows up to one level
 * below the deepest common ancestor are kept and only the child choices there are redone.
 * 0 on failure. */
static int s48c_path(s48_state *s, uint64_t key, uint64_t have, uint32_t k)
{
    s48_win w, x, c;
    uint32_t j, a = 0, fresh = 0;
    if ((key >> k) != (have >> k)) {
        fresh = 1;
        if (!subd_s48_build0_(s, (uint32_t)(key >> k))) return 0;
    } else {
        /* a: the levels whose ancestors agree (ancestor at level j: key >> (k - j)), at
         * least level 0's; windows 0..a are kept (a <= k - 1: the keys differ at level k) */
        while (a + 1u < k && (key >> (k - a - 1u)) == (have >> (k - a - 1u))) a++;
        if (key == have) a = k;
    }
    for (j = a; j < k; j++) {
        uint32_t bit = (uint32_t)(key >> (k - 1u - j)) & 1u;
        s48_lev(s, j, &w);
        s48_lev(s, j + 1u, &c);
        w.hd[5] = bit + 1u;
        if (j > a || fresh) { /* kept: window a + 1, the crop around the common ancestor's children */
            s48_x(s, &x);
            if (!subd_s48_refine_(s, &w, j, &x) || !subd_s48_crop_(s, &x, 2u * w.hd[2], &c)) return 0;
        }
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
 * the interpolant of every node from the walked triangle (level k) down to it that counts
 * (subd_s48_chord_counts_). */
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
 * (subd_s48_finest_), so does a node's new vertex (from the cropped window of its children,
 * where it is their apex; at level max_level - 1 it is read from the refined window, the
 * finest level); each is then tested against the interpolants of the counting nodes on
 * its path from ts, whose corners are all known by then. 1 beyond, 0 within, -1 failure. */
static int s48_chord_walk(s48_state *s, uint32_t k, uint32_t ts)
{
    const uint32_t tl = s->levels > S48C_T ? s->levels - S48C_T : 0u; /* the tiles' level */
    s48_win w, x, c;
    uint32_t j = k, q;
    if (k >= tl) return subd_s48_chord_tile_(s, k, k, ts, 0);
    s48_lev(s, k, &w);
    for (q = 0; q < 3u; q++)
        if (!subd_s48_chord_finest_(s, k, ts, s48_vid(&w, w.tv[3u * ts + q]), s->cpos + 3u * q)) return -1;
    s->ccur[k] = ts;
    s->cch[k] = 0;
    for (q = 0; q < 3u; q++) s->csrc[3u * k + q] = q;
    for (;;) {
        uint32_t cur = s->ccur[j], v;
        subd_real *pm = s->cpos + 3u * (3u + j);
        s48_lev(s, j, &w);
        s->cfl[j] = subd_s48_chord_counts_(s, k, j, &w, cur);
        if (!s->cfl[j] && j - k <= S48C_M && (j - k == S48C_M || !subd_s48_chord_may_at_(s, &w, k, j, cur))) {
            /* not entered */
        } else if (j == tl) { /* its subtree breadth first (j > k) */
            const int r = subd_s48_chord_tile_(s, k, j, cur, 0);
            if (r != 0) return r;
        } else {
            uint64_t id;
            s48_x(s, &x);
            if (!subd_s48_refine_(s, &w, j, &x)) return -1;
            v = x.tv[6u * cur]; /* the node's new vertex */
            id = s48_vid(&x, v);
            s48_lev(s, j + 1u, &c);
            if (!subd_s48_crop_(s, &x, 2u * cur, &c) || c.hd[3] == S48_OUT) return -1;
            /* its finest position: a descent from child 0 (blocks > j + 1 and X; child 0's
             * walk rebuilds them from block j + 1) */
            if (!subd_s48_chord_finest_(s, j + 1u, c.hd[3], id, pm)) return -1;
            s->cch[j] = 1u; /* in child 0 while its new vertex is tested */
            if (s48c_test(s, k, j)) return 1;
            j++;
            s->ccur[j] = c.hd[3];
            s->cch[j] = 0;
            s48c_child(s, j, 0);
            continue;
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

/* The memo entry of the level-tl ancestor of star triangle ki (level k >= tl = max_level -
 * S48C_T) with its tile's deviations, made when missing (from the level-tl window of whatever
 * path the windows hold); NULL with *rb = 0 when the ancestor is not in that window or its
 * tile is not exact (the caller takes the other ways), -1 failure. */
static uint32_t *s48c_entry(s48_state *s, uint64_t ki, uint32_t k, int *rb)
{
    const uint32_t tl = s->levels > S48C_T ? s->levels - S48C_T : 0u;
    const uint64_t ak = ki >> (k - tl);
    uint32_t *mk = subd_s48_chord_mk_(s, ak, tl);
    *rb = 0;
    if (mk[0] != (uint32_t)ak || mk[1] != ((uint32_t)(ak >> 32) | tl << 20)) {
        s48_win w;
        uint32_t lo = 0, hi;
        s48_lev(s, tl, &w);
        hi = w.hd[0];
        while (lo < hi) { /* the ancestor in the window (sorted by key) */
            const uint32_t mid = (lo + hi) / 2u;
            if (s48_key(&w, mid) < ak) lo = mid + 1u;
            else hi = mid;
        }
        if (lo >= w.hd[0] || s48_key(&w, lo) != ak) return 0;
        *rb = subd_s48_chord_bits_(s, tl, lo, mk);
        if (*rb <= 0) return 0;
    }
    return mk;
}

/* The deviating nodes e levels under star triangle ki (level k >= tl), e = 0 .. max_level -
 * 1 - k, from its memo entry mk: bit q set when i's descendant along the e child bits q (the
 * first step the highest bit) deviates, E > eps. Node base << e | q of the tile, base = i's
 * node (1 << (k - tl) | ki's last k - tl bits): a run of 2^e <= 32 bits. */
static uint32_t s48c_row(const uint32_t *mk, uint32_t base, uint32_t e)
{
    const uint64_t bits = mk[2] | (uint64_t)mk[4] << 32;
    return (uint32_t)((bits >> (base << e)) & (((uint64_t)1 << (1u << e)) - 1u)); /* base << e < 64 */
}

/* Does any node of star triangle ki's subtree (i itself included) deviate? From its memo entry
 * (s48c_entry): 1 yes, 0 no, 2 unknown (no entry), -1 failure. Needs no F(D) (s48c_pre). */
static int s48c_any(s48_state *s, uint32_t k, uint64_t ki)
{
    const uint32_t tl = s->levels > S48C_T ? s->levels - S48C_T : 0u, dl = k - tl, m = s->levels - tl;
    const uint32_t base = (1u << dl) | (uint32_t)(ki & ((1u << dl) - 1u));
    int rb;
    uint32_t e, *mk = s48c_entry(s, ki, k, &rb);
    if (!mk) return rb < 0 ? -1 : 2;
    for (e = 0; (base << e) < (1u << m); e++)
        if (s48c_row(mk, base, e)) return 1;
    return 0;
}

/* The decision's part under star triangle i (key ki, level k >= tl) from the memo's tile of its
 * level-tl ancestor (made when missing): every node under i that deviates (a bit of the entry)
 * and counts (subd_s48_chord_counts_: for a node d levels below k < S48C_M, a descendant diamond
 * of D) answers 1. A deviating node d >= S48C_M levels below counts when its level k + S48C_M
 * ancestor is in a star of F(D)'s, a test on that level's window: then 2 (the caller tiles i as
 * before), also when the ancestor is not in the window or its tile not exact. 0: no counting node
 * under i deviates. -1 failure. The same pairs (node, vertex) as subd_s48_chord_tile_'s, read from a
 * function of the triangle: the same answer. */
static int s48c_fast(s48_state *s, uint32_t k, uint64_t ki)
{
    const uint32_t tl = s->levels > S48C_T ? s->levels - S48C_T : 0u, dl = k - tl, m = s->levels - tl;
    const uint32_t base = (1u << dl) | (uint32_t)(ki & ((1u << dl) - 1u)); /* i's node in the tile */
    uint32_t e, q, deep = 0, row, *mk;
    int rb;
    if (!(mk = s48c_entry(s, ki, k, &rb))) return rb < 0 ? -1 : 2;
    for (e = 0; (base << e) < (1u << m); e++) {
        row = s48c_row(mk, base, e);
        if (!row) continue;
        if (e >= S48C_M) {
            deep = 1;
            continue;
        }
        for (q = 0; row; q++, row >>= 1)
            if ((row & 1u) && subd_s48_chord_has_(s, e, (ki << e) | q, 1u)) return 1;
    }
    return deep ? 2 : 0;
}

/* Does triangle i of window w share a vertex with the diamond whose vertices are vs[0..nv)? */
static int s48c_touch(const s48_win *w, uint32_t i, const uint32_t *vs, uint32_t nv)
{
    uint32_t j, q;
    for (j = 0; j < 3u; j++)
        for (q = 0; q < nv; q++)
            if (w->tv[3u * i + j] == vs[q]) return 1;
    return 0;
}

/* A decision of level k >= tl before F(D) (subd_s48_chord_desc_, about a tenth of the stream's
 * work when made for every decision), from bits of memo entries only (functions of the tile
 * roots, so the answer is the full decision's):
 *  - 1 when a node of the subtree of t or of its base neighbour deviates: every such node is in
 *    S(D) (sr48_chord.c: the children of D's triangles are triangles of F(D)'s diamonds one level
 *    down, and so on down to level k + S48C_M, where each is in the star of its own diamond G,
 *    so its subtree is in S(D) too), so the full decision would find it (s48c_fast: a node d < S48C_M
 *    levels down is in F(D)'s level d; deeper ones count through the star test of their level
 *    k + S48C_M ancestor, subd_s48_chord_tile_);
 *  - 0 when no node under any star triangle deviates (s48c_fast would answer 0 for each,
 *    whatever F(D));
 *  - 2 otherwise (the full decision), -1 failure. */
static int s48c_pre(s48_state *s, const s48_win *w, uint32_t k, uint32_t t, const uint32_t *vs, uint32_t nv)
{
    const uint16_t nb = w->tn[3u * t];
    uint32_t i, need;
    int a = s48c_any(s, k, s48_key(w, t));
    if (a == 1 || a < 0) return a;
    need = a != 0;
    if (s48_local(nb)) {
        a = s48c_any(s, k, s48_key(w, nb));
        if (a == 1 || a < 0) return a;
        need |= a != 0;
    }
    for (i = 0; i < w->hd[0] && !need; i++) {
        if (i == t || i == nb || !s48c_touch(w, i, vs, nv)) continue;
        if ((a = s48c_any(s, k, s48_key(w, i))) < 0) return -1;
        need = a != 0;
    }
    return need ? 2 : 0;
}

/* A decision of level k < tl before its walk: 1 when the memo already holds the tile of a
 * level-tl descendant of t or of its base neighbour with a deviating node (every node under
 * D's triangles is in S(D), s48c_pre), else 2 (the full decision). Kept tiles only: the
 * level-tl window need not hold the path of t's descendants while level k decides, so none
 * is made here. A tile node deviates or not whatever the decision: the answer is the walk's. */
static int s48c_coarse(const s48_state *s, const s48_win *w, uint32_t k, uint32_t t)
{
    const uint32_t tl = s->levels - S48C_T, dl = tl - k; /* k < tl: levels > S48C_T */
    const uint16_t nb = w->tn[3u * t];
    uint32_t c, q;
    for (c = 0; c < (s48_local(nb) ? 2u : 1u); c++) {
        const uint64_t key = s48_key(w, c ? nb : t) << dl;
        for (q = 0; q < (1u << dl); q++) {
            const uint32_t *mk = subd_s48_chord_mk_find_(s, key | q, tl);
            if (mk && (mk[2] | mk[4])) return 1;
        }
    }
    return 2;
}

/* The full decision (subd_s48_chord_wants_): F(D), then every star triangle that may hold a
 * counting node. 1 split, 0 leaf, -1 failure. */
static int s48c_full(s48_state *s, uint32_t k, uint32_t t, const uint32_t *vs, uint32_t nv)
{
    const uint32_t tiled = k + S48C_T >= s->levels; /* every star triangle is one tile */
    s48_win w;
    uint32_t i, ns = 1, moved = 0;
    uint64_t cur, have;
    int r = 0;
    s48_lev(s, k, &w);
    cur = s48_key(&w, t);
    if (!subd_s48_chord_desc_(s, k, t)) return -1;
    have = cur;
    s->ckey[0] = (uint32_t)cur;
    s->ckey[1] = (uint32_t)(cur >> 32);
    if (tiled) { /* t in place: from the memo's tile, else its own */
        if ((r = s48c_fast(s, k, cur)) < 0) return -1;
        if (r == 2 && (r = subd_s48_chord_tile_(s, k, k, t, 0)) < 0) return -1;
    }
    for (i = 0; i < w.hd[0] && r == 0; i++) {
        if (i == t) continue;
        if (!s48c_touch(&w, i, vs, nv) || !subd_s48_chord_may_(s, &w, k, i)) continue;
        if (tiled) {
            /* from the memo's tile; else from t's window, as it is (subd_s48_chord_tile_ checks that
             * it holds what the tile needs); else after rebuilding the windows along i's
             * path, below */
            int ri = s48c_fast(s, k, s48_key(&w, i));
            if (ri == 2) ri = subd_s48_chord_tile_(s, k, k, i, 1);
            if (ri == -1) return -1;
            if (ri >= 0) {
                r = ri;
                continue;
            }
        }
        {
            const uint64_t ki = s48_key(&w, i);
            s->ckey[2u * ns] = (uint32_t)ki;
            s->ckey[2u * ns + 1u] = (uint32_t)(ki >> 32);
        }
        ns++;
    }
    for (i = tiled ? 1u : 0u; i < ns && r == 0; i++) {
        uint64_t key = ((uint64_t)s->ckey[2u * i + 1u] << 32) | s->ckey[2u * i];
        if (i == 0u) {
            r = s48_chord_walk(s, k, t);
        } else {
            if (!s48c_path(s, key, have, k)) return -1;
            have = key;
            moved = 1;
            s48_lev(s, k, &w);
            r = s48_chord_walk(s, k, w.hd[2]);
        }
        if (r < 0) return -1;
    }
    if (moved && !s48c_path(s, cur, have, k)) return -1;
    return r;
}

/* CHORD's decision for the current triangle t of the level-k window: is some counting node
 * (subd_s48_chord_counts_) beyond eps? The counting region lies in the subtrees of the star of
 * t's diamond (the window triangles that share a vertex with it; all of them are in the window,
 * see s48_wants), so those are walked: t in place, another one after rebuilding the windows 0..k
 * along its path, and the current path is rebuilt after. 1 split, 0 leaf, -1 failure. */
int subd_s48_chord_wants_(s48_state *s, uint32_t k, uint32_t t)
{
    const uint32_t tiled = k + S48C_T >= s->levels; /* every star triangle is one tile */
    s48_win w;
    uint32_t vs[4], nv = 3, j, *dc, tag;
    uint64_t cur, dk;
    int r;
    uint16_t nb;
    s48_lev(s, k, &w);
    nb = w.tn[3u * t];
    cur = s48_key(&w, t);
    /* the decided diamonds (S48C_ND2 entries after the finest positions' ids, direct mapped
     * by the diamond's lower key and level: key low word, then key high word | level << 20
     * | the answer << 31; global keys are below 2^44): the answer is a function of the
     * diamond, S(D), whichever of its triangles asks, so a hit gives the walk's answer */
    dk = s48_local(nb) && s48_key(&w, nb) < cur ? s48_key(&w, nb) : cur;
    tag = (uint32_t)(dk >> 32) | k << 20;
    dc = s->cdesc + 3u * S48C_ND + 2u * S48C_NC +
         2u * ((((uint32_t)dk ^ tag) * 2654435761u) >> 16 & (S48C_ND2 - 1u));
    if (dc[0] == (uint32_t)dk && (dc[1] & 0x7fffffffu) == tag) {
        r = (int)(dc[1] >> 31);
        return r;
    }
    for (j = 0; j < 3u; j++) vs[j] = w.tv[3u * t + j];
    if (s48_local(nb)) vs[nv++] = w.tv[3u * nb];
    r = tiled ? s48c_pre(s, &w, k, t, vs, nv) : s48c_coarse(s, &w, k, t);
    if (r == 2) r = s48c_full(s, k, t, vs, nv);
    if (r < 0) return -1;
    dc[0] = (uint32_t)dk;
    dc[1] = tag | (uint32_t)r << 31;
    return r;
}
