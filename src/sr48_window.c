/* SPDX-License-Identifier: MIT */
/* Streaming semi-regular 4-8 refinement: the per-level window (paper:
 * semi-regular-4-8-refinement-box-splines.txt, sections 4 and 6; the private interface and
 * the other files of the stream: sr48_stream_internal.h). What it keeps: the local control
 * net of one level around the current triangle, refined, smoothed and cropped level by
 * level, so that every position it hands out is subd_sr48_build's, bit for bit.
 *
 * Method. Every level-0 triangle T0 of the base mesh (subd_sr48_base) is refined depth
 * first, child 0 before child 1, so triangles come out in the hierarchy's index order at
 * the last level. Level k keeps a window: the level-k triangles within S48_RINGS vertex
 * rings of the current triangle's children (a triangle is in ring r when it shares a
 * vertex with ring r-1), each with its three vertices, its base, leg-0 and leg-1
 * neighbours as window indices (or OUT of the window, or BND: the mesh boundary) and its
 * key (T0 * 2^k + the child path = its index within level k of the hierarchy; stored in a
 * local one-word form, T0 replaced by its index in the level-0 window, as are the vertex
 * ids: sr48_stream_internal.h). The
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
 * Descents (adaptive cuts, CHORD): sr48_descent.c. The last level of a uniform tile, smoothed
 * without a window: sr48_tile.c. The in-place smoothing sums: sr48_stream_internal.h.
 *
 * Cost (0.7.0): a crop numbers its kept triangles in a first pass and writes their corners
 * and neighbours (mapped at once) in a second, so no neighbour is renumbered afterwards; the
 * three coordinates are handled unrolled (s48_mid3 and the sums' helpers); the same bits.
 * (Unreleased) refine_crop's passes are split where one loop held more live values than the
 * Cortex-M's registers (the flags, the keep test per crop kind, the corners then the
 * neighbours, the new vertices of an unsmoothed level), and it reads the windows' array
 * pointers from local copies (a store to a byte array may alias anything): the same passes
 * in the same order, the same bits; on the M4F the uniform 8-step stream's refine_crop went
 * from about 413 to 310 instructions per output face.
 *
 * Finiteness checks (Unreleased). float32: every midpoint and smoothed average goes through
 * subd_chk (SUBD_ERR_RANGE when not finite). A uniform stream's level-0 window records
 * whether all its positions are finite with every coordinate below 2^64 in magnitude
 * (s48_state's l0ok, S48_L0_RANGE: sr48_level0.c); the windows and the tile derived from it
 * (the walk's levels, its checkpoints, the tile windows A and X) then skip the checks
 * (s48_mid3k, s48_avg3k: the same operations, so the same bits), because none could fire:
 * a midpoint 0.5 a + 0.5 b of finite a, b is at most max(|a|, |b|) in magnitude (halving is
 * exact or shrinks, and rounding to nearest cannot pass a representable bound of the exact
 * sum), so midpoints never grow; a smoothed vertex is s / k of a float sum of k < 2^16
 * terms (one per diamond at the vertex, fewer than a window's triangles, which are indexed by
 * 16 bits), each partial sum at most (1 + 2^-24) times the exact one in magnitude, so |s / k|
 * <= M (1 + 2^-24)^(k + 1) for inputs of magnitude <= M. Over at most 16 levels the largest
 * magnitude M grows by less than (1 + 2^-24)^(16 (2^16 + 1)) < 1.1, so every position stays
 * below 1.1 2^64 and every partial sum below 2^16 1.2 2^64 < 2^81, far from FLT_MAX
 * (about 2^128): no overflow, and no NaN (it needs a non-finite input or inf - inf). A
 * window whose level-0 window fails the test (or an adaptive mode's: their descents and
 * CHORD refine windows of other level-0 windows) keeps every check, so the error and the
 * triangles emitted before it are unchanged. Q16.16 has no checks to skip (its midpoints
 * and averages are exact convex combinations in 64 bits: sr48_stream_internal.h). Also (same
 * bits): an old vertex's sum takes no more terms once it is known incomplete (its position
 * will be the parent's, s48_rc_scatter).
 */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "layout.h"
#include "mesh_internal.h"
#include "real_avg.h"
#include "sr48_stream_internal.h"

/* Refines window p (level k) as a whole into X (level k+1), smoothing after an even level.
 * 0 on a capacity or range failure (s->err says which). */
int subd_s48_refine_(s48_state *s, const s48_win *p, uint32_t k, s48_win *x)
{
    const uint32_t nt = p->hd[0], nvp = p->hd[1];
    const uint32_t idj = (k + 1u) << S48_IDS; /* local ids of the vertices made here */
    const int sm = s->smooth && ((k + 1u) & 1u) == 0u;
    uint32_t i, nv = nvp, ovf = 0;
#ifdef S48_DBG
    s48_dbg[30] += nt; s48_dbg[31]++;
#endif
    /* the old vertices: ids, flags, L; positions, or (smoothed level) zero sums */
    for (i = 0; i < nvp; i++) {
        x->vid[i] = p->vid[i];
        x->vf[i] = p->vf[i];
    }
    if (x->vl)
        for (i = 0; i < 3u * nvp; i++) x->vl[i] = p->vl[i];
    if (sm) {
        for (i = 0; i < nvp; i++) {
            s->cnt[i] = 0;
            s->dist[i] = 0;
            s48_szero3(s, x, 3u * i);
        }
    } else {
        for (i = 0; i < 3u * nvp; i++) x->vp[i] = p->vp[i];
    }
    for (i = 0; i < nt; i++) {
        const uint16_t *tv = p->tv + 3u * i;
        const uint16_t nb = p->tn[3u * i], l0 = p->tn[3u * i + 1u], l1 = p->tn[3u * i + 2u];
        const uint32_t key = p->key[i]; /* local: children 2 key, 2 key + 1 */
        uint16_t m, *c0 = x->tn + 6u * i, *c1 = c0 + 3;
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
            s48_mid3(x->vp + 3u * m, p->vp + 3u * e0, p->vp + 3u * e1, &ovf);
            x->vf[m] = (uint8_t)(exact ? S48_EXACT : 0u);
            if (x->vl) /* L: the base midpoint, whatever the smoothing */
                s48_mid3(x->vl + 3u * m, p->vl + 3u * tv[1], p->vl + 3u * tv[2], &ovf);
            x->vid[m] = idj | key;
        }
        s->mtab[i] = m;
        x->tv[6u * i] = m;
        x->tv[6u * i + 1u] = tv[0];
        x->tv[6u * i + 2u] = tv[1];
        x->tv[6u * i + 3u] = m;
        x->tv[6u * i + 4u] = tv[2];
        x->tv[6u * i + 5u] = tv[0];
        x->key[2u * i] = 2u * key;
        x->key[2u * i + 1u] = 2u * key + 1u;
        c0[0] = s48_local(l0) ? (uint16_t)(2u * l0 + 1u) : l0;
        c0[1] = (uint16_t)(2u * i + 1u);
        c0[2] = s48_local(nb) ? (uint16_t)(2u * nb + 1u) : nb;
        c1[0] = s48_local(l1) ? (uint16_t)(2u * l1) : l1;
        c1[1] = s48_local(nb) ? (uint16_t)(2u * nb) : nb;
        c1[2] = (uint16_t)(2u * i);
        if (sm) {
            if (nb == S48_BND) {
                s->cnt[tv[1]] = 0x80000000u;
                s->cnt[tv[2]] = 0x80000000u;
            }
            /* an edge to outside: its ends miss part of their fan (slots (b, a), (c, a), (b, c)) */
            if (nb == S48_OUT || l0 == S48_OUT) s->dist[tv[1]] |= S48_INC;
            if (nb == S48_OUT || l1 == S48_OUT) s->dist[tv[2]] |= S48_INC;
            if (l0 == S48_OUT || l1 == S48_OUT) s->dist[tv[0]] |= S48_INC;
        }
    }
    if (ovf) {
        s->err = (uint32_t)(-SUBD_ERR_RANGE);
        return 0;
    }
    x->hd[0] = 2u * nt;
    x->hd[1] = nv;
    x->hd[6] = k + 1u;
    if (sm) {
        for (i = 0; i < nt; i++) {
            const uint16_t *tv = p->tv + 3u * i;
            uint16_t nb = p->tn[3u * i];
            uint32_t m = s->mtab[i];
            const subd_real *mp = x->vp + 3u * m;
            const uint32_t mf = x->vf[m];
            if (nb == S48_BND) {
                s48_scatter(s, x, tv[1], mp, mf, 1);
                s48_scatter(s, x, tv[2], mp, mf, 1);
                s48_scatter(s, x, tv[0], mp, mf, 0);
            } else if (nb == S48_OUT) {
                s->dist[tv[0]] |= S48_INC;
            } else if (i < nb) {
                s48_scatter(s, x, tv[1], mp, mf, 0);
                s48_scatter(s, x, tv[2], mp, mf, 0);
                s48_scatter(s, x, tv[0], mp, mf, 0);
                s48_scatter(s, x, p->tv[3u * nb], mp, mf, 0);
            }
        }
        for (i = 0; i < nvp; i++) {
            uint32_t n = s->cnt[i] & ~0x80000000u;
            if (n == 0u || (s->dist[i] & S48_INC)) {
                s48_cp3(x->vp + 3u * i, p->vp + 3u * i); /* not a sum */
                x->vf[i] = 0;
                continue;
            }
            s48_avg3(s, x, 3u * i, n, &ovf);
            x->vf[i] = S48_EXACT;
        }
        if (ovf) {
            s->err = (uint32_t)(-SUBD_ERR_RANGE);
            return 0;
        }
    }
    return 1;
}

/* Refine and crop in one pass (the uniform and adaptive walks, the uniform tile): window p
 * (level k) refined and cropped to the rings of the children of p's triangles c0 .. c0 + n - 1
 * into window w (capacity ct, cv; w is not p), without the refined window X: the same
 * triangles in the same order, the same vertex numbering, positions, flags, keys and ids as
 * subd_s48_refine_ (p into X) then subd_s48_crop_n_ (X's 2 c0 .. 2 (c0 + n) - 1 into w).
 * The children are numbered as X numbers them (child j of p's triangle i is X's 2 i + j, a
 * new vertex gets refine's index), the ring distances are found on the children as refine
 * would make them, and only the kept children are written. A new vertex is computed when it
 * is kept or (smoothed level) when a kept old vertex sums it: an old vertex's sum takes the
 * same diamonds in the same order as refine's (the sums of other vertices are not made), so
 * the same bits, and its flags come from the same tests over the same parent triangles. The
 * smoothing scratch: counts, the boundary flag and the incomplete flag (S48_RC_INC) in
 * s->cnt per parent vertex, the sums in w's positions of the kept vertex. A position that
 * overflows is reported only when computed (each is, in the window where it is kept).
 * fin: 0 the crop of subd_s48_crop_n_ (S48_RINGS rings); the last window of a uniform tile
 * (sr48_tile.c) needs less, and keeps a subset of those rings: 1 (level L even, smoothed:
 * subd_s48_last_ sums the whole fan of every corner of the children D and each fan
 * triangle's diamond) ring 1 of D and the partners (base neighbours) of its triangles,
 * 2 (L odd or no smoothing) D and its partners (the emitted new vertices' diamonds); a kept
 * vertex's position and flags do not depend on the crop, so they are refine's (the uniform
 * tile also crops its other windows with 1 first, and checks the flags: sr48_tile.c). 0 on
 * failure (s->err: SUBD_ERR_RANGE; else a capacity). */
#define S48_RC_BND 0x80000000u
#define S48_RC_INC 0x40000000u
#define S48_RC_N 0x3fffffffu
/* Adds a new vertex (position mp, flags mf) to parent vertex v's sum (in w's vertex u).
 * Nothing once v is incomplete (S48_RC_INC: its position will be the parent's, not the sum,
 * whatever else is added; the sum is not read). */
S48_INLINE void s48_rc_scatter(const s48_state *s, const s48_win *w, uint32_t v, uint32_t u,
                                  const subd_real *mp, uint32_t mf, int boundary_ok)
{
    const uint32_t c = s->cnt[v];
    if (c & (boundary_ok ? S48_RC_INC : S48_RC_INC | S48_RC_BND)) return;
    s48_sadd3(s, w, 3u * u, mp);
    s->cnt[v] = (c + 1u) | ((mf & S48_EXACT) ? 0u : S48_RC_INC);
}
/* Window vertex number of X's vertex v in the window being cropped, numbered as met. */
static inline uint16_t s48_rc_num(uint16_t *vm, uint16_t v, uint32_t *kv)
{
    uint16_t u = vm[v];
    if (u == S48_OUT) {
        u = (uint16_t)*kv;
        vm[v] = u;
        *kv += 1u;
    }
    return u;
}
int subd_s48_refine_crop_(s48_state *s, const s48_win *p0, uint32_t k, uint32_t c0, uint32_t n, s48_win *w0,
                          uint32_t ct, uint32_t cv, uint32_t fin)
{
    /* the two windows' array pointers in locals (why: a store to a byte array, a flag or a
     * distance, may alias anything, and the pointers would be read again after each) */
    const s48_win pl = *p0;
    s48_win wl = *w0;
    const s48_win *p = &pl, *w = &wl;
    const uint32_t nt = p->hd[0], nvp = p->hd[1];
    const uint32_t idj = (k + 1u) << S48_IDS; /* local ids of the vertices made here */
    const int sm = s->smooth && ((k + 1u) & 1u) == 0u;
    const uint32_t chk = !(s->l0ok & S48_L0_RANGE); /* the finiteness checks (the header) */
    uint16_t *mt = s->mtab, *vm = s->vmap, *tm = s->tmap;
    uint8_t *d = s->dist;
    uint32_t *cnt = s->cnt;
    uint32_t i, nv = nvp, kt = 0, kv = 0, ovf = 0;
#ifdef S48_DBG
    s48_dbg[30] += nt; s48_dbg[31]++;
#endif
    /* X's new vertices as refine numbers them; the smoothing flags (refine's tests), in
     * their own loop (why: fewer live values per loop) */
    {
        const uint16_t *ptv = p->tv, *ptn = p->tn;
        const uint32_t xv = s->xv;
        for (i = 0; i < nt; i++) {
            const uint16_t nb = ptn[3u * i];
            if (s48_local(nb) && nb < i) {
                mt[i] = mt[nb];
            } else {
                if (nv >= xv) return 0;
                mt[i] = (uint16_t)nv++;
            }
        }
        if (sm) {
            for (i = 0; i < nvp; i++) cnt[i] = 0;
            for (i = 0; i < nt; i++) {
                const uint16_t *tv = ptv + 3u * i;
                const uint16_t nb = ptn[3u * i], l0 = ptn[3u * i + 1u], l1 = ptn[3u * i + 2u];
                if (nb == S48_BND) {
                    cnt[tv[1]] |= S48_RC_BND;
                    cnt[tv[2]] |= S48_RC_BND;
                }
                if (nb == S48_OUT || l0 == S48_OUT) cnt[tv[1]] |= S48_RC_INC;
                if (nb == S48_OUT || l1 == S48_OUT) cnt[tv[2]] |= S48_RC_INC;
                if (nb == S48_OUT || l0 == S48_OUT || l1 == S48_OUT) cnt[tv[0]] |= S48_RC_INC;
            }
        }
    }
    /* ring distances on the children (m; c, a), (m; b, c) of every parent (c; a, b) */
    for (i = 0; i < nv; i++) {
        d[i] = S48_FAR;
        vm[i] = S48_OUT;
    }
    for (i = c0; i < c0 + n; i++) {
        d[p->tv[3u * i]] = 0;
        d[p->tv[3u * i + 1u]] = 0;
        d[p->tv[3u * i + 2u]] = 0;
        d[mt[i]] = 0;
    }
    if (fin == 0u) {
        uint32_t r;
        for (r = 1; r < S48_RINGS; r++)
            for (i = 0; i < nt; i++) {
                const uint16_t *tv = p->tv + 3u * i;
                const uint32_t m = mt[i];
                uint32_t dm = d[m], dc = d[tv[0]], da = d[tv[1]], db = d[tv[2]], md;
                md = dm < dc ? dm : dc;
                if (da < md) md = da;
                if (md + 1u <= r) { /* child 0: (m; c, a) */
                    if (dm > r) d[m] = (uint8_t)r;
                    if (dc > r) d[tv[0]] = (uint8_t)r;
                    if (da > r) d[tv[1]] = (uint8_t)r;
                }
                dm = d[m];
                dc = d[tv[0]];
                md = dm < dc ? dm : dc;
                if (db < md) md = db;
                if (md + 1u <= r) { /* child 1: (m; b, c) */
                    if (dm > r) d[m] = (uint8_t)r;
                    if (db > r) d[tv[2]] = (uint8_t)r;
                    if (dc > r) d[tv[0]] = (uint8_t)r;
                }
            }
    }
    /* which children are kept, numbered in X's order (tm: X's index -> w's, or OUT);
     * then their corners (vertices numbered as met), neighbours (X's, mapped by tm at
     * once) and keys: two passes, so that no neighbour is renumbered afterwards */
    {
        /* one loop per crop (why: fin tested once, and fewer live values per loop) */
        const uint16_t *ptv = p->tv, *ptn = p->tn;
        if (fin == 1u) {
            /* ring 1 and the partners of its triangles: a corner at distance 0 (d is 0 or
             * S48_FAR here), or the partner's (the child of the base neighbour ln across the
             * base ends; its apex is ln's new vertex) */
            for (i = 0; i < nt; i++) {
                const uint16_t *tv = ptv + 3u * i, l0 = ptn[3u * i + 1u], l1 = ptn[3u * i + 2u];
                const uint32_t dmc = (uint32_t)d[mt[i]] & d[tv[0]];
                const uint32_t k0 = (dmc & d[tv[1]]) == 0u || (s48_local(l0) && d[mt[l0]] == 0u);
                const uint32_t k1 = (dmc & d[tv[2]]) == 0u || (s48_local(l1) && d[mt[l1]] == 0u);
                tm[2u * i] = k0 ? (uint16_t)kt : (uint16_t)S48_OUT;
                kt += k0;
                tm[2u * i + 1u] = k1 ? (uint16_t)kt : (uint16_t)S48_OUT;
                kt += k1;
            }
        } else if (fin == 2u) { /* the descendants and their partners */
            for (i = 0; i < nt; i++) {
                const uint16_t l0 = ptn[3u * i + 1u], l1 = ptn[3u * i + 2u];
                const uint32_t in = i - c0 < n;
                const uint32_t k0 = in || (s48_local(l0) && l0 - c0 < n);
                const uint32_t k1 = in || (s48_local(l1) && l1 - c0 < n);
                tm[2u * i] = k0 ? (uint16_t)kt : (uint16_t)S48_OUT;
                kt += k0;
                tm[2u * i + 1u] = k1 ? (uint16_t)kt : (uint16_t)S48_OUT;
                kt += k1;
            }
        } else { /* within S48_RINGS rings: a corner nearer than S48_RINGS */
            for (i = 0; i < nt; i++) {
                const uint16_t *tv = ptv + 3u * i;
                const uint32_t dm = d[mt[i]], dc = d[tv[0]], da = d[tv[1]], db = d[tv[2]];
                const uint32_t mc = dm < dc ? dm : dc;
                const uint32_t k0 = (da < mc ? da : mc) < S48_RINGS;
                const uint32_t k1 = (db < mc ? db : mc) < S48_RINGS;
                tm[2u * i] = k0 ? (uint16_t)kt : (uint16_t)S48_OUT;
                kt += k0;
                tm[2u * i + 1u] = k1 ? (uint16_t)kt : (uint16_t)S48_OUT;
                kt += k1;
            }
        }
    }
    if (kt > ct) return 0;
    /* two passes over the kept children (why: one pass holds more live values than the
     * Cortex-M's registers, and its spills cost more than the second loop): their corners,
     * the vertices numbered as met (in the same order as one pass), then their neighbours
     * and keys */
    {
        const uint16_t *ptv = p->tv;
        uint16_t *wtv = w->tv;
        for (i = 0; i < nt; i++) {
            const uint32_t t0 = tm[2u * i], t1 = tm[2u * i + 1u];
            const uint16_t *tv = ptv + 3u * i;
            const uint16_t m = mt[i];
            uint16_t *ov;
            if ((t0 & t1) == S48_OUT) continue; /* neither kept */
            if (t0 != S48_OUT && t1 != S48_OUT) { /* both: m, c, a, then b (as met) */
                const uint16_t um = s48_rc_num(vm, m, &kv), uc = s48_rc_num(vm, tv[0], &kv);
                ov = wtv + 3u * t0; /* child 0: (m; c, a) */
                ov[0] = um;
                ov[1] = uc;
                ov[2] = s48_rc_num(vm, tv[1], &kv);
                ov = wtv + 3u * t1; /* child 1: (m; b, c) */
                ov[0] = um;
                ov[1] = s48_rc_num(vm, tv[2], &kv);
                ov[2] = uc;
            } else if (t0 != S48_OUT) {
                ov = wtv + 3u * t0;
                ov[0] = s48_rc_num(vm, m, &kv);
                ov[1] = s48_rc_num(vm, tv[0], &kv);
                ov[2] = s48_rc_num(vm, tv[1], &kv);
            } else {
                ov = wtv + 3u * t1;
                ov[0] = s48_rc_num(vm, m, &kv);
                ov[1] = s48_rc_num(vm, tv[2], &kv);
                ov[2] = s48_rc_num(vm, tv[0], &kv);
            }
        }
    }
    {
        const uint16_t *ptn = p->tn;
        const uint32_t *pkey = p->key;
        uint16_t *wtn = w->tn;
        uint32_t *wkey = w->key;
        for (i = 0; i < nt; i++) {
            const uint32_t t0 = tm[2u * i], t1 = tm[2u * i + 1u];
            const uint16_t *tn = ptn + 3u * i;
            uint16_t nb;
            uint16_t *on;
            uint32_t key2;
            if ((t0 & t1) == S48_OUT) continue;
            nb = tn[0];
            key2 = 2u * pkey[i];
            if (t0 != S48_OUT) { /* child 0: base neighbour child 1 of L0 */
                const uint16_t l0 = tn[1];
                on = wtn + 3u * t0;
                on[0] = s48_local(l0) ? tm[2u * l0 + 1u] : l0;
                on[1] = (uint16_t)t1;
                on[2] = s48_local(nb) ? tm[2u * nb + 1u] : nb;
                wkey[t0] = key2;
            }
            if (t1 != S48_OUT) { /* child 1: base neighbour child 0 of L1 */
                const uint16_t l1 = tn[2];
                on = wtn + 3u * t1;
                on[0] = s48_local(l1) ? tm[2u * l1] : l1;
                on[1] = s48_local(nb) ? tm[2u * nb] : nb;
                on[2] = (uint16_t)t0;
                wkey[t1] = key2 + 1u;
            }
        }
    }
    if (kv > cv) return 0;
    /* the kept old vertices: ids, L; positions and flags, or (smoothed level) zero sums
     * (one loop per case: why, the tests once) */
    {
        const uint32_t *pvid = p->vid;
        uint32_t *wvid = w->vid;
        if (sm) {
            for (i = 0; i < nvp; i++) {
                const uint32_t u = vm[i];
                if (u == S48_OUT) continue;
                wvid[u] = pvid[i];
                s48_szero3(s, w, 3u * u);
            }
        } else {
            subd_real *wvp = w->vp;
            const subd_real *pvp = p->vp;
            uint8_t *wvf = w->vf;
            const uint8_t *pvf = p->vf;
            for (i = 0; i < nvp; i++) {
                const uint32_t u = vm[i];
                if (u == S48_OUT) continue;
                wvid[u] = pvid[i];
                s48_cp3(wvp + 3u * u, pvp + 3u * i);
                wvf[u] = pvf[i];
            }
        }
        if (w->vl)
            for (i = 0; i < nvp; i++)
                if (vm[i] != S48_OUT) s48_cp3(w->vl + 3u * vm[i], p->vl + 3u * i);
    }
    /* the new vertices, each from the diamond's lower triangle (refine's rule), when kept
     * or summed; the sums in refine's order. Not smoothed: the kept ones only, their own
     * loop (why: no sums to test per triangle, fewer live values) */
    if (!sm) {
        const uint16_t *ptv = p->tv, *ptn = p->tn;
        const uint32_t smooth = s->smooth;
        for (i = 0; i < nt; i++) {
            const uint16_t *tv = ptv + 3u * i;
            const uint16_t nb = ptn[3u * i];
            const uint32_t um = vm[mt[i]];
            uint32_t e0 = tv[1], e1 = tv[2], mf;
            if ((s48_local(nb) && nb < i) || um == S48_OUT) continue; /* the lower one's, or not kept */
            if (s48_local(nb) && smooth) {
                e0 = tv[0];
                e1 = ptv[3u * nb];
            }
            mf = (nb != S48_OUT) && (p->vf[e0] & p->vf[e1] & S48_EXACT) ? S48_EXACT : 0u;
            s48_mid3k(w->vp + 3u * um, p->vp + 3u * e0, p->vp + 3u * e1, &ovf, chk);
            w->vf[um] = (uint8_t)mf;
            if (w->vl) /* L: the base midpoint, whatever the smoothing */
                s48_mid3(w->vl + 3u * um, p->vl + 3u * tv[1], p->vl + 3u * tv[2], &ovf);
            w->vid[um] = idj | p->key[i];
        }
    } else {
        const uint16_t *ptv = p->tv, *ptn = p->tn;
        const uint8_t *pvf = p->vf;
        const subd_real *pvp = p->vp;
        for (i = 0; i < nt; i++) {
            const uint16_t *tv = ptv + 3u * i;
            const uint16_t nb = ptn[3u * i];
            const uint32_t um = vm[mt[i]];
            uint32_t e0 = tv[1], e1 = tv[2], mf, u0, u1, u2, u3 = S48_OUT, v3 = 0;
            subd_real mp[3];
            if (s48_local(nb) && nb < i) continue; /* made by the lower triangle */
            if (um == S48_OUT && nb == S48_OUT) continue; /* neither kept nor summed */
            u0 = vm[tv[0]];
            u1 = vm[tv[1]];
            u2 = vm[tv[2]];
            if (s48_local(nb)) {
                v3 = ptv[3u * nb];
                u3 = vm[v3];
                e0 = tv[0]; /* smoothed: the apexes */
                e1 = v3;
            }
            if (um == S48_OUT && u0 == S48_OUT && u1 == S48_OUT && u2 == S48_OUT && u3 == S48_OUT) continue;
            mf = (nb != S48_OUT) && (pvf[e0] & pvf[e1] & S48_EXACT) ? S48_EXACT : 0u;
            s48_mid3k(mp, pvp + 3u * e0, pvp + 3u * e1, &ovf, chk);
            if (um != S48_OUT) {
                s48_cp3(w->vp + 3u * um, mp);
                w->vf[um] = (uint8_t)mf;
                if (w->vl) /* L: the base midpoint, whatever the smoothing */
                    s48_mid3(w->vl + 3u * um, p->vl + 3u * tv[1], p->vl + 3u * tv[2], &ovf);
                w->vid[um] = idj | p->key[i];
            }
            if (nb == S48_OUT) continue;
            {
                const int bnd = nb == S48_BND;
                if (u1 != S48_OUT) s48_rc_scatter(s, w, tv[1], u1, mp, mf, bnd);
                if (u2 != S48_OUT) s48_rc_scatter(s, w, tv[2], u2, mp, mf, bnd);
                if (u0 != S48_OUT) s48_rc_scatter(s, w, tv[0], u0, mp, mf, 0);
                if (u3 != S48_OUT) s48_rc_scatter(s, w, v3, u3, mp, mf, 0);
            }
        }
    }
    if (sm)
        for (i = 0; i < nvp; i++) {
            const uint32_t u = vm[i], c = cnt[i], q = c & S48_RC_N;
            if (u == S48_OUT) continue;
            if (q == 0u || (c & S48_RC_INC)) {
                s48_cp3(w->vp + 3u * u, p->vp + 3u * i); /* not a sum */
                w->vf[u] = 0;
                continue;
            }
            s48_avg3k(s, w, 3u * u, q, &ovf, chk);
            w->vf[u] = S48_EXACT;
        }
    if (ovf) {
        s->err = (uint32_t)(-SUBD_ERR_RANGE);
        return 0;
    }
    w->hd[0] = kt;
    w->hd[1] = kv;
    w->hd[6] = k + 1u;
    w->hd[3] = tm[2u * c0];
    w->hd[4] = tm[2u * c0 + 1u];
    return 1;
}

/* Crops X to the triangles within S48_RINGS vertex rings of X's triangles c0 .. c0 + n - 1
 * (the current triangle's descendants: contiguous, X being sorted by key) into window w of
 * capacity ct triangles, cv vertices, in order; w's hd[3] is c0's index in w, hd[4] c0 + 1's. */
int subd_s48_crop_n_(s48_state *s, const s48_win *x, uint32_t c0, uint32_t n, s48_win *w, uint32_t ct, uint32_t cv)
{
    const uint32_t nt = x->hd[0], nv = x->hd[1];
    uint8_t *d = s->dist;
    uint16_t *vm = s->vmap, *tm = s->tmap;
    uint32_t i, j, r, kt = 0, kv = 0;
#ifdef S48_DBG
    s48_dbg[32] += nt; s48_dbg[33]++;
#endif
    for (i = 0; i < nv; i++) {
        d[i] = S48_FAR;
        vm[i] = S48_OUT;
    }
    for (j = 0; j < 3u * n; j++) d[x->tv[3u * c0 + j]] = 0;
    for (r = 1; r < S48_RINGS; r++)
        for (i = 0; i < nt; i++) {
            const uint16_t *tv = x->tv + 3u * i;
            const uint32_t d0 = d[tv[0]], d1 = d[tv[1]], d2 = d[tv[2]];
            uint32_t md = d0 < d1 ? d0 : d1;
            if (d2 < md) md = d2;
            if (md + 1u > r) continue;
            if (d0 > r) d[tv[0]] = (uint8_t)r;
            if (d1 > r) d[tv[1]] = (uint8_t)r;
            if (d2 > r) d[tv[2]] = (uint8_t)r;
        }
    /* the kept triangles numbered in order (tm: X's index -> w's, or OUT), then their
     * corners (vertices numbered as met), neighbours (mapped by tm at once) and keys */
    for (i = 0; i < nt; i++) {
        const uint16_t *tv = x->tv + 3u * i;
        const uint32_t d0 = d[tv[0]], d1 = d[tv[1]], d2 = d[tv[2]];
        uint32_t md = d0 < d1 ? d0 : d1;
        if (d2 < md) md = d2;
        tm[i] = md < S48_RINGS ? (uint16_t)kt++ : (uint16_t)S48_OUT;
    }
    if (kt > ct) return 0;
    for (i = 0; i < nt; i++) {
        const uint32_t t = tm[i];
        const uint16_t *tv = x->tv + 3u * i, *tn = x->tn + 3u * i;
        uint16_t *ov, *on;
        if (t == S48_OUT) continue;
        ov = w->tv + 3u * t;
        on = w->tn + 3u * t;
        w->key[t] = x->key[i];
        ov[0] = s48_rc_num(vm, tv[0], &kv);
        ov[1] = s48_rc_num(vm, tv[1], &kv);
        ov[2] = s48_rc_num(vm, tv[2], &kv);
        on[0] = s48_local(tn[0]) ? tm[tn[0]] : tn[0];
        on[1] = s48_local(tn[1]) ? tm[tn[1]] : tn[1];
        on[2] = s48_local(tn[2]) ? tm[tn[2]] : tn[2];
    }
    if (kv > cv) return 0;
    for (i = 0; i < nv; i++) {
        uint16_t v = vm[i];
        if (v == S48_OUT) continue;
        s48_vcopy(w, v, x, i);
    }
    w->hd[0] = kt;
    w->hd[1] = kv;
    w->hd[6] = x->hd[6];
    w->hd[3] = tm[c0];
    w->hd[4] = tm[c0 + 1u];
    return 1;
}

/* subd_s48_crop_n_ to the current triangle's two children c0, c0 + 1, into a level window. */
int subd_s48_crop_(s48_state *s, const s48_win *x, uint32_t c0, s48_win *w)
{
    return subd_s48_crop_n_(s, x, c0, 2u, w, s->wt, s->wv);
}
