/* SPDX-License-Identifier: MIT */
/* The 4-8 stream's level 0 (paper: semi-regular-4-8-refinement-box-splines.txt, sections 4
 * and 5): the base mesh's adjacency read from subd_sr48_base's arrays (a level-0 triangle's
 * base neighbour, its legs' neighbours through the hybrid triangles), the base's checks,
 * the fan walk around a base vertex (the stream's valence, the census of sr48_census.c, the
 * adaptation box) and the level-0 window: the base triangles within two vertex rings of the
 * current base triangle (or hybrid pair), gathered by fan walks. The method, the exactness
 * argument and the window layout are in sr48_window.c's header; the deeper levels' windows
 * (refine, crop, descents) are there too.
 * Cost (0.6.0; at 2 steps the level-0 window, the census and the valence were most of a
 * uniform stream's instructions): a fan step searches one corner (s48_fan_lo); the valence
 * walks every fan whole once, from its lowest triangle; the window records its triangles'
 * corners while gathering and reads them back through the sort's permutation instead of a
 * second lookup. */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "sr48_stream_internal.h"

/* ------------------------------------------------------------------------------------ */
/* The base mesh                                                                          */

/* Neighbour of level-0 triangle t across slot 0 (base), 1 (leg 0: c-a), 2 (leg 1: b-c):
 * the fan walk's (sr48_stream_internal.h). */
static uint32_t s48_base_nbr(const subd_sr48 *b, uint32_t t, uint32_t slot) { return subd_s48_base_nbr_(b, t, slot); }

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
int subd_s48_base_check_(const subd_sr48 *b)
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
    /* reciprocity: the slot of n with the ends (q, p) - the one starting at q's position i
     * (slot 1 starts at corner 0, 0 at 1, 2 at 2; the corners are distinct, so it is the
     * only candidate) - must point back to t */
    for (t = 0; t < n0; t++) {
        static const uint8_t from[3] = {1u, 0u, 2u};
        s48_tri_verts(b, t, v);
        for (s = 0; s < 3u; s++) {
            uint32_t n = s48_base_nbr(b, t, s), p, q, i;
            if (n == SUBD_NONE) continue;
            s48_slot_ends(v, s, &p, &q);
            s48_tri_verts(b, n, u);
            i = u[0] == q ? 0u : u[1] == q ? 1u : u[2] == q ? 2u : 3u;
            if (i == 3u || u[i == 2u ? 0u : i + 1u] != p || s48_base_nbr(b, n, from[i]) != t) return SUBD_ERR_PARAM;
        }
    }
    return SUBD_OK;
}

/* The two slots at corner position p: (c: 1, 2), (a: 1, 0), (b: 0, 2). */
static uint32_t s48_slot_at(uint32_t p, uint32_t j)
{
    static const uint8_t tab[3][2] = {{1u, 2u}, {1u, 0u}, {0u, 2u}};
    return tab[p][j];
}

/* Walks the fan of vertex x of the base from triangle t (which holds x): every triangle
 * around x, each once, into out (when not NULL, at most cap); returns the count, or
 * UINT32_MAX beyond cap. Around an interior vertex it comes back to t; at a boundary vertex
 * it walks the other way from t too. lo: returns 0 as soon as a triangle below lo is met
 * (subd_s48_valence_ walks each fan whole only from its lowest triangle; 0: never).
 * The steps (one corner search per triangle) are sr48_stream_internal.h's, shared with the
 * census's walk (sr48_census.c), which visits the same triangles in the same order. */
static uint32_t s48_fan_lo(const subd_sr48 *b, uint32_t x, uint32_t t, uint32_t *out, uint32_t cap, uint32_t lo)
{
    uint32_t n = 0, dir, lim = b->level_tri[1] + 1u;
    if (out && cap) out[n] = t;
    n++;
    for (dir = 0; dir < 2u; dir++) {
        uint32_t cur = t, slot, i, w;
        slot = subd_s48_fan_first_(b, x, t, dir, &w);
        for (i = 0; i < lim; i++) {
            const uint32_t nx = subd_s48_base_nbr_(b, cur, slot);
            if (nx == SUBD_NONE) break;
            if (nx == t) return n; /* around: interior vertex */
            if (nx < lo) return 0;
            if (n >= cap) return UINT32_MAX;
            if (out) out[n] = nx;
            n++;
            cur = nx;
            slot = subd_s48_fan_enter_(b, x, nx, &w); /* leave by the other edge at x */
        }
        if (i == lim) return UINT32_MAX;
    }
    return n;
}
static uint32_t s48_fan(const subd_sr48 *b, uint32_t x, uint32_t t, uint32_t *out, uint32_t cap)
{
    return s48_fan_lo(b, x, t, out, cap, 0u);
}

/* Largest number of triangles around a base vertex: every fan once, whole from its lowest
 * triangle (a fan's count is the same from any of its triangles; the walks from the others
 * stop at the first lower one). corners (not NULL): the triangles at each vertex; *two = 1
 * when a whole fan has fewer (a vertex of two fans: sr48_census.c). */
uint32_t subd_s48_valence_cnt_(const subd_sr48 *b, const uint32_t *corners, uint32_t *two)
{
    uint32_t t, j, best = 0;
    for (t = 0; t < b->level_tri[1]; t++)
        for (j = 0; j < 3u; j++) {
            /* t's neighbours across its two edges at corner j (s48_slot_at): one below t
             * (SUBD_NONE is above every index), and the walk from t would stop there */
            const uint32_t x = b->tri_vert[3u * t + j], n0 = s48_base_nbr(b, t, s48_slot_at(j, 0u)),
                           n1 = s48_base_nbr(b, t, s48_slot_at(j, 1u));
            uint32_t n;
            if (n0 < t || n1 < t) continue;
            n = s48_fan_lo(b, x, t, 0, 0xffffu, t);
            if (n > best) best = n;
            if (corners && n != 0u && n != corners[x]) *two = 1;
        }
    return best;
}
uint32_t subd_s48_valence_(const subd_sr48 *b) { return subd_s48_valence_cnt_(b, 0, 0); }

/* ------------------------------------------------------------------------------------ */
/* Windows                                                                                */

/* Level 0's window's gathering looks base triangles and vertices up in two hash tables
 * (open addressing, linear probing) over the crop's maps, which are free between crops: a
 * slot holds a local index + 1 (0: empty), the key is read back from gt or gv. A table has
 * a power of 2 of slots above the window's capacity, so it never fills. */
static uint32_t s48_h0_size(uint32_t cap)
{
    uint32_t h = 1;
    while (2u * h <= cap && h < 0x8000u) h *= 2u;
    return h;
}
/* The slot of key x in table tab (size hm + 1) over keys keys[]: x's, or the empty one
 * where it goes. */
static uint32_t s48_h0_find(const uint16_t *tab, uint32_t hm, const uint32_t *keys, uint32_t x)
{
    uint32_t h = ((x * 2654435761u) >> 12) & hm, i;
    for (i = 0; i <= hm; i++) {
        if (tab[h] == 0u || keys[tab[h] - 1u] == x) break;
        h = (h + 1u) & hm;
    }
    return h;
}

/* Adds base triangle tt to the level-0 window being gathered (ht[h]: its empty slot) with
 * those of its corners not in it yet, at distance d; its corners' local indices into
 * lv[3 nt ..] (read back once the triangles are sorted). x, qx: a corner already in the
 * window and its local index (a fan's vertex: no lookup; SUBD_NONE: none). 0 when the
 * vertex capacity is exceeded. */
static inline int s48_h0_add(s48_state *s, uint16_t *ht, uint32_t h, uint16_t *hv, uint32_t vm, uint32_t tt, uint32_t *nt,
                             uint32_t *nv, uint32_t d, uint16_t *lv, uint32_t x, uint32_t qx)
{
    const uint32_t *tv = s->base->tri_vert + 3u * tt;
    uint16_t *o = lv + 3u * *nt;
    uint32_t j;
    for (j = 0; j < 3u; j++) {
        const uint32_t vx = tv[j];
        uint32_t g;
        if (vx == x) {
            o[j] = (uint16_t)qx;
            continue;
        }
        g = s48_h0_find(hv, vm, s->gv, vx);
        if (hv[g] == 0u) {
            if (*nv >= s->wv) return 0;
            hv[g] = (uint16_t)(*nv + 1u);
            s->gv[*nv] = vx;
            s->gvt[*nv] = tt;
            s->dist[*nv] = (uint8_t)d;
            ++*nv;
        }
        o[j] = (uint16_t)(hv[g] - 1u);
    }
    ht[h] = (uint16_t)(*nt + 1u);
    s->gt[(*nt)++] = tt;
    return 1;
}

/* Merges the fan of window vertex q (base vertex x, found in triangle t) into the window
 * being gathered, as s48_fan walks it (the same triangles in the same order): the fan's
 * triangles not in the window yet, each with its corners. The capacities as when the whole
 * fan was read into the free tail of gt before the merge: 0 when nt (before the fan) plus
 * the fan's size exceeds wt, or a walk does not close (s48_fan's UINT32_MAX), or the vertex
 * capacity is exceeded. */
static int s48_h0_fan(s48_state *s, uint16_t *ht, uint32_t tm, uint16_t *hv, uint32_t vm, uint32_t q, uint32_t *nt,
                      uint32_t *nv, uint16_t *lv)
{
    const subd_sr48 *b = s->base;
    const uint32_t x = s->gv[q], t = s->gvt[q], d = s->dist[q] + 1u, lim = b->level_tri[1] + 1u;
    const uint32_t cap = s->wt - *nt; /* the fan's room, as s48_fan's cap */
    uint32_t n = 1, dir, h;
    if (cap == 0u) return 0;
    h = s48_h0_find(ht, tm, s->gt, t);
    if (ht[h] == 0u && !s48_h0_add(s, ht, h, hv, vm, t, nt, nv, d, lv, x, q)) return 0;
    for (dir = 0; dir < 2u; dir++) {
        uint32_t cur = t, slot, i, w;
        slot = subd_s48_fan_first_(b, x, t, dir, &w);
        for (i = 0; i < lim; i++) {
            const uint32_t nx = subd_s48_base_nbr_(b, cur, slot);
            if (nx == SUBD_NONE) break;
            if (nx == t) return 1; /* around: interior vertex */
            if (n >= cap) return 0;
            n++;
            h = s48_h0_find(ht, tm, s->gt, nx);
            if (ht[h] == 0u && !s48_h0_add(s, ht, h, hv, vm, nx, nt, nv, d, lv, x, q)) return 0;
            cur = nx;
            slot = subd_s48_fan_enter_(b, x, nx, &w); /* leave by the other edge at x */
        }
        if (i == lim) return 0;
    }
    return 1;
}

/* Level 0's window around base triangle t0: every base triangle within S48_RINGS vertex
 * rings, found by fan walks from the vertices at distance < S48_RINGS (BFS order), sorted
 * by index; local vertices and neighbours. small: ring 1 (the fans of t0's corners) and the
 * base neighbours of its triangles only, the uniform tile's smaller crop at level 0
 * (sr48_tile.c; hd[7] = 1 says so). 0 when a capacity is exceeded.
 * Cost (0.6.0, later): each fan is merged as it is walked (s48_h0_fan), its vertex x not
 * looked up; the walk stops at the first vertex of the last ring (breadth first: the queue
 * is sorted by distance); the sort moves gathering indices only (perm; the sorted triangles
 * into w.key), so the triangle table keeps its gathering indices and the neighbours are
 * looked up in it through the inverse permutation (in vmap, the vertex table, free once
 * gathered) instead of a second table; a leg's neighbour inside the hybrid pair (2H, 2H + 1)
 * is the next or previous sorted triangle. (Unreleased) The two tables are sized above the
 * level-0 window's capacities (wt, wv), not the tile windows' (4x fewer entries cleared per
 * window; probing is not observable: the gathering order is the fans'); the window records
 * s->l0ok (positions finite and below 2^64, no boundary: sr48_window.c's header). */
static int s48_build0(s48_state *s, uint32_t t0, uint32_t small)
{
    const subd_sr48 *b = s->base;
    /* the tables above the level-0 window's capacities wt, wv (every gathering checks them),
     * not the larger tile windows' (why: cleared per window, and a uniform tile's level-0
     * window is small) */
    const uint32_t tm = s48_h0_size(2u * s->wt) - 1u, vm = s48_h0_size(2u * s->wv) - 1u;
    uint16_t *ht = s->tmap, *hv = s->vmap; /* 2 max(at, wt) and xv > wt + wv entries */
    uint16_t *perm = s->mtab;                /* the sort's permutation: mt >= wt entries */
    uint16_t *rank = s->vmap;                /* its inverse: xv > wt entries, after gathering */
    uint32_t nt = 0, nv = 0, i, j, q, p, ok = S48_L0_RANGE | S48_L0_CLOSED;
    s48_win w;
    s48_lev(s, 0, &w);
    /* (i < tm + 1: a bounded loop, which compilers clear in one go) */
    for (i = 0; i < tm + 1u; i++) ht[i] = 0;
    for (i = 0; i < vm + 1u; i++) hv[i] = 0;
    /* uniform: the rings of both children of t0's hybrid triangle (t0 even and odd), so
     * that one window serves both (s48_step) */
    for (p = s->adapt ? t0 : (t0 & ~1u); p <= (s->adapt ? t0 : (t0 | 1u)); p++)
        for (j = 0; j < 3u; j++) {
            const uint32_t vx = b->tri_vert[3u * p + j], h = s48_h0_find(hv, vm, s->gv, vx);
            if (hv[h] != 0u) continue;
            hv[h] = (uint16_t)(nv + 1u);
            s->gv[nv] = vx;
            s->gvt[nv] = p;
            s->dist[nv++] = 0;
        }
    for (q = 0; q < nv; q++) {
        if (s->dist[q] >= (small ? 1u : S48_RINGS)) break; /* breadth first: the rest is as far */
        if (!s48_h0_fan(s, ht, tm, hv, vm, q, &nt, &nv, w.tn)) return 0;
    }
    if (small) { /* the base neighbours of ring 1 (dist: unused from here) */
        const uint32_t n1 = nt;
        for (q = 0; q < n1; q++) {
            const uint32_t tt = s48_base_nbr(b, s->gt[q], 0u);
            uint32_t h;
            if (tt == SUBD_NONE) continue;
            h = s48_h0_find(ht, tm, s->gt, tt);
            if (ht[h] != 0u) continue;
            if (nt >= s->wt) return 0;
            if (!s48_h0_add(s, ht, h, hv, vm, tt, &nt, &nv, 2u, w.tn, SUBD_NONE, 0u)) return 0;
        }
    }
    /* sort the triangles' gathering indices by triangle (perm; Shell sort, gaps 57 23 10 4
     * 1: at most wt of them, distinct), the sorted triangles into w.key; gt keeps the
     * gathering order (the table's keys) until the neighbours are found */
    for (i = 0; i < nt; i++) perm[i] = (uint16_t)i;
    for (p = 0; p < 5u; p++) {
        static const uint8_t gap[5] = {57u, 23u, 10u, 4u, 1u};
        const uint32_t g = gap[p];
        for (i = g; i < nt; i++) {
            const uint16_t o = perm[i];
            const uint32_t x = s->gt[o];
            j = i;
            while (j >= g && s->gt[perm[j - g]] > x) {
                perm[j] = perm[j - g];
                j -= g;
            }
            perm[j] = o;
        }
    }
    for (i = 0; i < nt; i++) w.key[i] = s->gt[perm[i]];
    /* the corners' local indices, recorded by s48_h0_add in tn's place in gathering order;
     * the inverse permutation */
    for (i = 0; i < nt; i++) {
        const uint16_t *lv = w.tn + 3u * perm[i];
        w.tv[3u * i] = lv[0];
        w.tv[3u * i + 1u] = lv[1];
        w.tv[3u * i + 2u] = lv[2];
        rank[perm[i]] = (uint16_t)i;
    }
    for (i = 0; i < nt; i++) {
        const uint32_t tt = w.key[i];
        for (j = 0; j < 3u; j++) {
            uint32_t nb;
            if (j == 1u + (tt & 1u)) { /* the leg inside the pair: tt ^ 1, adjacent when in */
                const uint32_t k = (tt & 1u) ? i - 1u : i + 1u;
                w.tn[3u * i + j] = (k < nt && w.key[k] == (tt ^ 1u)) ? (uint16_t)k : S48_OUT;
                continue;
            }
            nb = s48_base_nbr(b, tt, j);
            if (nb == SUBD_NONE) {
                w.tn[3u * i + j] = S48_BND;
                ok &= ~S48_L0_CLOSED;
                continue;
            }
            nb = ht[s48_h0_find(ht, tm, s->gt, nb)];
            w.tn[3u * i + j] = nb != 0u ? rank[nb - 1u] : S48_OUT;
        }
        if (tt == t0) w.hd[2] = i;
        if (tt == (t0 | 1u)) w.hd[4] = i;
    }
    for (i = 0; i < nt; i++) {
        s->gt[i] = w.key[i];
        w.key[i] = i; /* local: gt[i] */
    }
    for (i = 0; i < nv; i++) {
        const subd_real *ps = b->pos + 3u * s->gv[i];
        w.vp[3u * i] = ps[0];
        w.vp[3u * i + 1u] = ps[1];
        w.vp[3u * i + 2u] = ps[2];
#if !SUBD_FIXED /* |x| < 2^64, finite: the magnitude bits below 2^64's */
        for (j = 0; j < 3u; j++)
            if ((subd_real_bits(ps[j]) & 0x7fffffffu) >= 0x5f800000u) ok &= ~S48_L0_RANGE;
#endif
        w.vid[i] = i; /* local: gv[i] */
        w.vf[i] = S48_EXACT;
        if (w.vl)
            for (j = 0; j < 3u; j++) w.vl[3u * i + j] = s->l0[3u * i + j];
    }
    w.hd[0] = nt;
    w.hd[1] = nv;
    w.hd[6] = 0;
    w.hd[7] = small;
    /* uniform only: the adaptive modes' descents and CHORD also refine windows of other
     * level-0 windows than the last one built */
    s->l0ok = (uint8_t)(s->adapt ? 0u : ok);
    return 1;
}
int subd_s48_build0_(s48_state *s, uint32_t t0) { return s48_build0(s, t0, 0u); }
int subd_s48_build0_small_(s48_state *s, uint32_t t0) { return s48_build0(s, t0, 1u); }

#ifdef S48_DBG
uint32_t s48_dbg[40];
#endif

/* The fan walk for the base's census (sr48_census.c): one walk, s48_fan. */
uint32_t subd_s48_fan_(const subd_sr48 *b, uint32_t x, uint32_t t, uint32_t *out, uint32_t cap)
{
    return s48_fan(b, x, t, out, cap);
}
