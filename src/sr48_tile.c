/* SPDX-License-Identifier: MIT */
/* Streaming semi-regular 4-8 refinement: the breadth-first uniform tile and the emission of
 * a window triangle (paper: semi-regular-4-8-refinement-box-splines.txt, sections 4 and 6;
 * the window and its exactness argument: sr48_window.c; the private interface:
 * sr48_stream_internal.h).
 *
 * Uniform tiles: the last tw levels are not walked one triangle at a time (tw =
 * s48_tile_walk: m + 1 when L > m, m = SUBD_SR48_STREAM_TILE_LEVELS, else L): the current
 * level L-tw triangle's window is refined tw - 1 times breadth first, each time cropped in
 * the same pass (subd_s48_refine_crop_) to the rings of the set of its descendants at that
 * level (contiguous, the windows being sorted by key), alternately into the two tile blocks
 * A and X so that the last, level L-1, lands in X; X then holds the descendants D, and the
 * 2^tw triangles of level L, D's children, are emitted in key order without a level-L
 * window: a child's new vertex is its diamond's midpoint, as subd_s48_refine_ makes it,
 * computed once per diamond when emitted, and (L even, smoothing) its old corners are
 * smoothed once per tile by subd_s48_last_ with refine's sums restricted to D's corners
 * (into A, free by then). The last window needs less than two rings: with L even and
 * smoothing, the fan of every corner of D and each fan triangle's diamond partner (ring 1
 * of D and the partners of its triangles: subd_s48_last_'s sums and flags read nothing
 * else, and ring 1 holds the whole fan of a corner wherever the refined window does), else
 * D and their partners (the emitted new vertices' diamonds); a kept vertex's position and
 * flags do not depend on the crop. When L <= m the tile starts at level 0 and covers both
 * base triangles 2H, 2H + 1 of a hybrid pair (adjacent in the level-0 window; 2H's
 * descendants come first in key order). The tile windows contain every window the
 * depth-first walk would crop for one of the descendants (rings of a union are the union of
 * the rings), so the exactness argument of sr48_window.c carries over, and the triangles and
 * their order are unchanged. The level-0 window of a uniform stream holds the rings of both
 * children of a hybrid triangle and serves both.
 *
 * Smaller crops (0.6.0): the windows before the last are first cropped to ring 1 of the
 * descendants and the partners of its triangles too (about half of two rings: 1.5 refined
 * parent triangles per output triangle instead of 2.8 on the icosahedron at 8 steps),
 * without a proof that this always suffices; instead every position the tile hands out
 * (the corners of D, smoothed or not, and the two apexes or base ends of each emitted
 * midpoint) is checked exact before the first triangle leaves (s48_tile_exact: the flags of
 * sr48_window.c, computed for the kept triangles exactly as with two rings), and a tile
 * where one is not is made again with the two rings. Exact flags mean the same bits
 * whatever the crop (a kept vertex's position and flags are refine's), so the stream's
 * output is unchanged; on every tile of the test shapes (valences 3..64, boundaries,
 * isolated triangles, both parities, smoothing on and off) the smaller crops were enough
 * (test_sr48_tiles counts it). Emission then reads no flag, and the corners' 64-bit ids are
 * computed once per tile vertex (s48_tile_ids) rather than once per corner.
 *
 * Exactness checks while summing (Unreleased): when level L is smoothed, subd_s48_last_
 * makes s48_tile_exact's tests itself (a corner's flag, each D diamond's midpoint inputs and
 * inside base neighbour) and returns 2 when one fails, so the tile is not walked again to
 * check; the ids are made for the emitted corners only (A's vertices). test_sr48_tiles
 * forces too small first crops (S48_TILE_TINY) to see the checks send tiles to the two
 * rings with the same bits.
 *
 * (Unreleased) The finiteness checks are skipped where the level-0 window is in range
 * (sr48_window.c's header), and subd_s48_last_'s pass for the boundary flags where it has no
 * boundary (s48_state's l0ok); the same bits. Tried and dropped: keeping the emitted
 * diamonds' midpoints from subd_s48_last_ for the emission (in A's free triangle corners)
 * saved about 8 instructions per face in the emission and cost more in subd_s48_last_
 * (register pressure in its loop) on the M4F.
 *
 * A and X are blocks of the stream's state of the same capacities (SUBD_SR48_STREAM_TT_,
 * _TV_ of m: a tile of m + 1 levels keeps at most the descendants m levels below its root
 * in a window); the level windows below the tile's root are unused while a tile is handed
 * out. A tile's triangles leave in batches as large as the caller's buffer
 * (subd_s48_tile_emit_), the rest at the next step.
 */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "sr48_stream_internal.h"

/* Three coordinates stored, or zeroed (unrolled: the emission's hot path). */
static inline void s48_put3(subd_real *o, const subd_real *p)
{
    o[0] = p[0];
    o[1] = p[1];
    o[2] = p[2];
}
static inline void s48_zero3(subd_real *o)
{
    o[0] = 0;
    o[1] = 0;
    o[2] = 0;
}

/* A tile triangle (m; p1, p2) with its ids, level-0 ancestor and level (no normal). */
static inline void s48_tile_tri(subd_tri *o, const subd_real *m, const subd_real *p1, const subd_real *p2,
                                uint64_t i0, uint64_t i1, uint64_t i2, uint32_t face, uint32_t L)
{
    s48_put3(o->pos[0], m);
    s48_put3(o->pos[1], p1);
    s48_put3(o->pos[2], p2);
    s48_zero3(o->normal[0]);
    s48_zero3(o->normal[1]);
    s48_zero3(o->normal[2]);
    o->id[0] = i0;
    o->id[1] = i1;
    o->id[2] = i2;
    o->face = face;
    o->level = L;
}

/* Window w's triangle t as a stream triangle; 0 when a corner is not exact. *stop: the push
 * form's sink value (non-zero: stop the stream with it). */
int subd_s48_emit_(const s48_state *s, const s48_win *w, uint32_t t, subd_stream_q *q, int *stop)
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
        o->id[j] = s48_vid(w, v);
    }
    o->face = s->t0;
    o->level = s->levels;
    *stop = subd_stream_q_commit(q);
    return 1;
}

/* The last level of a uniform tile without its window: X (level L-1 = max_level - 1) is
 * not refined into level L; only the corners of level L's triangles that the tile emits
 * (the children of X's triangles c0 .. c0 + n - 1) are computed. Their new vertices are
 * single midpoints, made when emitted (sr48_tile.c); this computes the old ones, the
 * corners of c0 .. c0 + n - 1, when level L is smoothed (L even): the same sums as
 * subd_s48_refine_'s over the same diamonds in the same order (X's triangle order), but
 * only into those corners, each mapped by s->vmap to a vertex of a (the tile window, free
 * once X is refined from it: a's vid keeps X's index, a's position and flag the result;
 * a's hd[1] their count). The exactness rules are refine's, restricted to the same
 * vertices. 0 on failure; 1 when every position the tile hands out is exact (each corner,
 * and the midpoint inputs of the diamond of each of c0 .. c0 + n - 1, whose base neighbour
 * is inside: s48_tile_exact's tests, made here while summing), else 2. */
int subd_s48_last_(s48_state *s, const s48_win *x0, uint32_t c0, uint32_t n, s48_win *a0)
{
    /* the windows' array pointers in locals (why: a store to a byte array, a flag, may alias
     * anything, and the pointers would be read again after each) */
    const s48_win xl = *x0, al = *a0;
    const s48_win *x = &xl, *a = &al;
    const uint32_t nt = x->hd[0], nv = x->hd[1];
    const uint16_t *xtv = x->tv, *xtn = x->tn;
    const subd_real *xvp = x->vp;
    const uint8_t *xvf = x->vf;
    uint16_t *vm = s->vmap;
    const uint32_t chk = !(s->l0ok & S48_L0_RANGE); /* the finiteness checks (sr48_window.c) */
    uint32_t i, j, nn = 0, ovf = 0, bad = 0;
    for (i = 0; i < nv; i++) vm[i] = S48_OUT;
    for (j = 0; j < 3u * n; j++) {
        const uint16_t v = xtv[3u * c0 + j];
        if (vm[v] != S48_OUT) continue;
        if (nn >= s->av) return 0;
        vm[v] = (uint16_t)nn;
        a->vid[nn] = v;
        s->cnt[nn] = 0;
        s->dist[nn] = 0;
        s48_szero3(s, a, 3u * nn);
        nn++;
    }
    /* the boundary flags first (a boundary vertex sums its boundary diamonds only; none
     * when the level-0 window had no boundary) */
    for (i = 0; i < nt && !(s->l0ok & S48_L0_CLOSED); i++) {
        const uint16_t *tv = xtv + 3u * i;
        uint16_t u;
        if (xtn[3u * i] != S48_BND) continue;
        if ((u = vm[tv[1]]) != S48_OUT) s->cnt[u] = 0x80000000u;
        if ((u = vm[tv[2]]) != S48_OUT) s->cnt[u] = 0x80000000u;
    }
    for (i = 0; i < nt; i++) {
        const uint16_t *tv = xtv + 3u * i, *tn = xtn + 3u * i;
        const uint16_t nb = tn[0], u0 = vm[tv[0]], u1 = vm[tv[1]], u2 = vm[tv[2]];
        const uint32_t o0 = nb == S48_OUT, o1 = tn[1] == S48_OUT, o2 = tn[2] == S48_OUT;
        uint16_t u3;
        uint32_t e0, e1, mf;
        subd_real mp[3];
        if (u0 == S48_OUT && u1 == S48_OUT && u2 == S48_OUT) {
            if (nb == S48_BND || !s48_local(nb) || nb < i || vm[xtv[3u * nb]] == S48_OUT) continue;
        } else if (o0 | o1 | o2) {
            /* an edge to outside: its ends miss part of their fan (slots (b, a), (c, a), (b, c)) */
            if ((o0 | o1) && u1 != S48_OUT) s->dist[u1] |= S48_INC;
            if ((o0 | o2) && u2 != S48_OUT) s->dist[u2] |= S48_INC;
            if ((o1 | o2) && u0 != S48_OUT) s->dist[u0] |= S48_INC;
        }
        if (o0) {
            if (u0 != S48_OUT) s->dist[u0] |= S48_INC;
            bad |= i - c0 < n; /* a triangle of D without its diamond */
            continue;
        }
        if (nb == S48_BND) {
            e0 = tv[1];
            e1 = tv[2];
            u3 = S48_OUT;
        } else {
            if (nb < i) continue; /* the diamond's lower triangle made it */
            e0 = tv[0];
            e1 = xtv[3u * nb];
            u3 = vm[e1];
        }
        s48_mid3k(mp, xvp + 3u * e0, xvp + 3u * e1, &ovf, chk);
        mf = xvf[e0] & xvf[e1] & S48_EXACT;
        if (!mf && (i - c0 < n || (s48_local(nb) && nb - c0 < n))) bad = 1; /* a midpoint emitted */
        {
            const int bnd = nb == S48_BND;
            if (u1 != S48_OUT) s48_scatter(s, a, u1, mp, mf, bnd);
            if (u2 != S48_OUT) s48_scatter(s, a, u2, mp, mf, bnd);
            if (u0 != S48_OUT) s48_scatter(s, a, u0, mp, mf, 0);
            if (u3 != S48_OUT) s48_scatter(s, a, u3, mp, mf, 0);
        }
    }
    for (i = 0; i < nn; i++) {
        const uint32_t v = a->vid[i], k = s->cnt[i] & ~0x80000000u;
        if (k == 0u || (s->dist[i] & S48_INC)) {
            s48_cp3(a->vp + 3u * i, x->vp + 3u * v); /* not a sum */
            a->vf[i] = 0;
            bad = 1; /* a corner of D */
            continue;
        }
        s48_avg3k(s, a, 3u * i, k, &ovf, chk);
        a->vf[i] = S48_EXACT;
    }
    if (ovf) {
        s->err = (uint32_t)(-SUBD_ERR_RANGE);
        return 0;
    }
    a->hd[1] = nn; /* the corners */
    return bad ? 2 : 1;
}

/* Uniform tiles: the current triangle t of the level-k window w (k = L - tw, tw = s48_tile_walk)
 * refined breadth first: tw - 2 times refined into X and cropped into the tile window A to
 * the rings of t's descendants (contiguous in X: X is sorted by key), then refined once
 * more into X, level L - 1, whose descendants of t (lo .. lo + n - 1) have as children the
 * tile's 2^tw triangles of level L, emitted in key order by subd_s48_tile_emit_ without a
 * level-L window (subd_s48_last_ smooths their old corners). A contains every window the
 * depth-first walk would crop for one descendant (a union of rings), so every emitted
 * corner is exact. small = 1: the windows before the last cropped smaller (fin 1 of
 * subd_s48_refine_crop_: ring 1 of the descendants and the partners of its triangles, see
 * subd_s48_tile_), 0: to their two rings. 0 on failure; else 1, or (level L smoothed)
 * subd_s48_last_'s 1 or 2 (a position handed out not exact). */
static int s48_tile_build(s48_state *s, const s48_win *w, uint32_t t, uint32_t n0, uint32_t small)
{
    s48_win x, a;
    const s48_win *p = w;
    const uint32_t tw = s48_tile_walk(s);
    uint32_t j, lo = t, n = n0, tiny;
    s48_x(s, &x);
    s48_win_at(s, s->ablk, s->aoff, &a);
    /* the smaller crops: 1, or the tests' too small 2 (S48_TILE_TINY) */
    tiny = (a.hd[7] & S48_TILE_TINY) ? 2u : 1u;
    /* tw - 1 refinements, each cropped to the rings of t's descendants (subd_s48_refine_crop_),
     * alternately into A and X so that the last one (level L - 1, twice the descendants of
     * the one before: X's capacities) lands in X */
    for (j = 0; j + 1u < tw; j++) {
        const uint32_t last = j + 2u == tw;
        s48_win *o = ((tw - 2u - j) & 1u) ? &a : &x;
        const uint32_t fin = last ? (s->smooth && (s->levels & 1u) == 0u ? 1u : 2u) : small ? tiny : 0u;
        if (!subd_s48_refine_crop_(s, p, s->k + j, lo, n, o, s->at, s->av, fin)) return 0;
#ifdef S48_DBG
        if (o->hd[0] > s48_dbg[2u * j]) s48_dbg[2u * j] = o->hd[0];
        if (o->hd[1] > s48_dbg[2u * j + 1u]) s48_dbg[2u * j + 1u] = o->hd[1];
#endif
        lo = o->hd[3];
        n *= 2u;
        p = o;
    }
    s->tcur = 2u * lo;
    s->tend = 2u * (lo + n);
    if (s->smooth && (s->levels & 1u) == 0u) return subd_s48_last_(s, &x, lo, n, &a);
    return 1;
}

/* Is every position the tile emits exact (the tests of subd_s48_tile_emit_, made before the
 * first triangle leaves)? X's triangles s->tcur / 2 .. s->tend / 2 - 1: their diamonds'
 * midpoint sources, and their corners: the corners of both children. When level L is
 * smoothed, subd_s48_last_ made the same tests while it summed (r: its 1, all exact, or 2),
 * and the corners are its smoothed ones in A; else r = 1 and X is read. */
static int s48_tile_exact(const s48_state *s, int r)
{
    s48_win x;
    uint32_t i, j;
    if (s->smooth && (s->levels & 1u) == 0u) return r == 1;
    s48_x(s, &x);
    for (i = s->tcur >> 1; i < s->tend >> 1; i++) {
        const uint16_t *tv = x.tv + 3u * i;
        uint32_t lt, e0, e1;
        const uint16_t lnb = subd_s48_mid_ends_(s, &x, i, &lt, &e0, &e1);
        if (lnb == S48_OUT || !(x.vf[e0] & x.vf[e1] & S48_EXACT)) return 0;
        for (j = 0; j < 3u; j++)
            if (!(x.vf[tv[j]] & S48_EXACT)) return 0;
    }
    return 1;
}

/* The global ids of X's vertices, once per tile (an emitted corner is a corner of about
 * three triangles): 8 bytes per vertex over A's neighbours and keys, which the tile no
 * longer reads (A holds the smoothed corners only): 10 bytes per triangle of A's capacity,
 * more than 8 per vertex of X's (SUBD_SR48_STREAM_TT_, _TV_: 60 N + 320 + 15 2^m against
 * 32 N + 256 + 6 2^m). Only the emitted corners' entries are made (X's vertices of D's
 * triangles; when level L is smoothed, A's vertices are those, by X index in A's vid), the
 * rest of X's (ring and partners) not being read. 0 if not (cannot happen). */
static uint64_t *s48_tile_idv(const s48_state *s)
{
    return (uint64_t *)(void *)(s->ablk + s->aoff[2]);
}
static int s48_tile_ids(const s48_state *s)
{
    s48_win x, a;
    uint64_t *id = s48_tile_idv(s);
    uint32_t v;
    s48_x(s, &x);
    if (8u * x.hd[1] > s->aoff[4] - s->aoff[2]) return 0;
    if (s->smooth && (s->levels & 1u) == 0u) { /* A's vertices: D's corners (subd_s48_last_) */
        s48_win_at(s, s->ablk, s->aoff, &a);
        for (v = 0; v < a.hd[1]; v++) id[a.vid[v]] = s48_vid(&x, a.vid[v]);
    } else {
        for (v = 0; v < x.hd[1]; v++) id[v] = s48_vid(&x, v);
    }
    return 1;
}

/* The tile of the current triangle t of the level-k window w (n = 2: t and t + 1, the two
 * base triangles of a hybrid pair, at level 0): first with every window before the last
 * cropped to ring 1 of the descendants and the partners of its triangles (fin 1 of
 * subd_s48_refine_crop_, as the last window when L is even; a tile from level 0 also reads
 * level 0's window cropped so, subd_s48_build0_small_), about half the triangles of two
 * rings, then checked by s48_tile_exact; where a position would not be exact, the tile is
 * made again with the two rings of the exactness argument (sr48_window.c; level 0's window
 * built again with its two rings: w is that block, t0's index read again). A kept
 * vertex's position and flags do not depend on the crop (refine_crop's), so the tile's bits
 * are the same either way, and every position handed out is checked exact before the first
 * triangle leaves. Measured: the smaller crops were enough on every tile of the test shapes
 * (valences 3..64, boundaries, isolated triangles; test_sr48_tiles counts them). The
 * counters: hd[7] of X (tiles) and of A (tiles made again; with S48_TILE_FULL set, which
 * the tests set after the begin call, every tile is made with the two rings alone, so that
 * they compare both crops; with S48_TILE_TINY, the windows before the last are first cropped
 * to the descendants and their partners (fin 2), too small for smoothing, so that the tests
 * see the checks send tiles to the two rings). 0 on failure. */
int subd_s48_tile_(s48_state *s, const s48_win *w, uint32_t t, uint32_t n0)
{
    s48_win x, a;
    s48_x(s, &x);
    s48_win_at(s, s->ablk, s->aoff, &a);
    x.hd[7]++;
    if (!(a.hd[7] & S48_TILE_FULL)) {
        const int r = s48_tile_build(s, w, t, n0, 1u);
        if (!r) return 0;
        if (s48_tile_exact(s, r)) return s48_tile_ids(s);
    }
    a.hd[7]++; /* below S48_TILE_TINY: at most one per tile */
    if (w->hd[6] == 0u && w->hd[7] == 1u) { /* level 0's smaller window: its two rings */
        if (!subd_s48_build0_(s, s->t0)) return 0;
        t = w->hd[2]; /* t0's index in it (the pair's: t0 even, t0 + 1 next) */
    }
    {
        const int r = s48_tile_build(s, w, t, n0, 0u);
        if (!r) return 0;
        return s48_tile_exact(s, r) && s48_tile_ids(s);
    }
}

/* One child triangle into the queue (s48_tile_tri), *stop the sink's answer: 1, or 0 when
 * the queue had no slot. Inline: the emission's two children stay straight-line code. */
static inline int s48_tile_put(subd_stream_q *q, const subd_real *m, const subd_real *p1, const subd_real *p2,
                               uint64_t idm, uint64_t i1, uint64_t i2, uint32_t face, uint32_t L, int *stop)
{
    subd_tri *o = (subd_tri *)subd_stream_q_put(q);
    if (!o) return 0;
    s48_tile_tri(o, m, p1, p2, idm, i1, i2, face, L);
    *stop = subd_stream_q_commit(q);
    return 1;
}

/* The tile's triangles not handed out yet (level L: child s->tcur & 1 of X's triangle
 * s->tcur / 2), until the caller's buffer is full or the sink stops. A child's new vertex
 * is the midpoint subd_s48_refine_ makes for the diamond (from its lower triangle, id by
 * that triangle's key); its old corners are X's vertices, smoothed by subd_s48_last_ when
 * level L is even. Every position is exact (s48_tile_exact checked them). 0 on failure. */
int subd_s48_tile_emit_(s48_state *s, subd_stream_q *q, int *stop)
{
    s48_win x, a;
    const uint32_t sm = s->smooth && (s->levels & 1u) == 0u, L = s->levels, tend = s->tend;
    const uint32_t k = L - 1u, low = (1u << k) - 1u; /* X's level; a local key's path bits */
    const uint64_t id0 = (uint64_t)s->nv0 + (uint64_t)s->n0 * (((uint64_t)1 << k) - 1u);
    const uint64_t *idv = s48_tile_idv(s);
    /* why locals: the windows' arrays and the walk's position are not reloaded after every
     * sink call (s->tcur is written back on every way out) */
    const uint16_t *xtv, *vm = s->vmap;
    const uint32_t *xkey, *gt = s->gt;
    const subd_real *xvp, *cvp;
    const uint32_t chk = !(s->l0ok & S48_L0_RANGE); /* the finiteness checks (sr48_window.c) */
    uint32_t ovf = 0, tc = s->tcur, ci0 = 0xffffffffu;
    uint64_t cid = 0; /* id0 + the global key's high part of level-0 window triangle ci0 */
    s48_win_at(s, s->xblk, s->xoff, &x);
    s48_win_at(s, s->ablk, s->aoff, &a);
    xtv = x.tv;
    xkey = x.key;
    xvp = x.vp;
    cvp = sm ? a.vp : x.vp; /* the corners: smoothed into A by subd_s48_last_ (by vmap), or X's */
    while (tc < tend && !subd_stream_q_full(q)) {
        /* X's triangle i: its diamond's new vertex (from the lower triangle), its id, the
         * level-0 ancestor and the corners once for both children */
        const uint32_t i = tc >> 1;
        const uint16_t *tv = xtv + 3u * i;
        uint32_t lt, e0, e1, face, ql; /* lt: the diamond's lower triangle */
        uint64_t idm;
        subd_real mp[3];
        const subd_real *cp[3]; /* c, a, b: child 0 = (m; c, a), child 1 = (m; b, c) */
        (void)subd_s48_mid_ends_(s, &x, i, &lt, &e0, &e1);
        s48_mid3k(mp, xvp + 3u * e0, xvp + 3u * e1, &ovf, chk);
        if (ovf) {
            s->tcur = tc;
            s->err = (uint32_t)(-SUBD_ERR_RANGE);
            return 0;
        }
        /* the new vertex's id: id0 + s48_gkey(lt's key) (sr48_window.c's closed form), the
         * ancestor's part kept while the ancestor repeats (a tile's one or two, and the
         * partners' across its border) */
        ql = xkey[lt];
        if ((ql >> k) != ci0) {
            ci0 = ql >> k;
            cid = id0 + ((uint64_t)gt[ci0] << k);
        }
        idm = cid + (ql & low);
        face = gt[xkey[i] >> k]; /* the level-0 ancestor (local key: sr48_stream_internal.h) */
        if (sm) { /* exact: s48_tile_exact */
            cp[0] = cvp + 3u * vm[tv[0]];
            cp[1] = cvp + 3u * vm[tv[1]];
            cp[2] = cvp + 3u * vm[tv[2]];
        } else {
            cp[0] = cvp + 3u * tv[0];
            cp[1] = cvp + 3u * tv[1];
            cp[2] = cvp + 3u * tv[2];
        }
        if ((tc & 1u) == 0u) { /* child 0 = (m; c, a) */
            if (!s48_tile_put(q, mp, cp[0], cp[1], idm, idv[tv[0]], idv[tv[1]], face, L, stop)) {
                s->tcur = tc;
                return 0;
            }
            tc++;
            if (*stop || tc >= tend || subd_stream_q_full(q)) break;
        }
        /* child 1 = (m; b, c) */
        if (!s48_tile_put(q, mp, cp[2], cp[0], idm, idv[tv[2]], idv[tv[0]], face, L, stop)) {
            s->tcur = tc;
            return 0;
        }
        tc++;
        if (*stop) break;
    }
    s->tcur = tc;
    return 1;
}
