/* SPDX-License-Identifier: MIT */
/* The census of the base mesh's level-0 windows (subd_sr48_base fills subd_sr48's
 * stream_valence with it; the stream sizes its windows by it: src/sr48_stream.c). Paper:
 * semi-regular-4-8-refinement-box-splines.txt, section 5 (the base mesh); the windows are
 * beyond the paper (src/sr48_window.c's header).
 *
 * Why. The stream's windows have capacities that are functions of one number N, the valence
 * (SUBD_SR48_STREAM_WT_(N) = 6 N + 16 triangles, SUBD_SR48_STREAM_WV_(N) = 4 N + 16 vertices
 * at level 0, the deeper windows and the tile from the same N). Taken as the base's largest
 * valence, they were measured on meshes whose extraordinary vertices lie apart; a decimated
 * scan (nefertiti: several valence-9..16 vertices within two rings of each other) has level-0
 * neighbourhoods above 6 N + 16 and the stream stopped with SUBD_ERR_TOO_BIG. So the base
 * counts, for every level-0 triangle and every hybrid pair (the uniform window holds both
 * children of a hybrid triangle), exactly what subd_s48_build0_ will need - the largest
 * nt + (fan size) while it gathers (a fan is read into the window's free tail before it is
 * merged) and the final vertex count - and takes the smallest N whose capacities hold the
 * largest of them, or the largest valence if that is more (at least 8, the capacities'
 * floor). The deeper windows follow the same N, so they grow with it; that they then fit is
 * measured, as before (the stream still checks every capacity and every vertex's exactness,
 * and reports SUBD_ERR_TOO_BIG rather than emit a wrong position).
 *
 * Cost (0.6.0): the pair's gathering is made for every pair, a triangle's own only where the
 * pair's triangle count plus its largest fan exceeds the capacities of the N found so far
 * (subd_s48_census_run_ says why that bounds it; a base with a vertex of two fans, which
 * subd_sr48_base never makes, makes every one): on spot's base about one gathering per pair
 * instead of three, the same N (the tests compare it with every gathering made).
 *
 * Cost (0.6.0, later): a fan triangle after the first is entered by an edge of the one before,
 * whose corners are stamped already: only its third corner is tested (the same queue); the
 * gathering stops at the first vertex of the last ring (breadth first); and two consecutive
 * pairs (2H .. 2H + 3, H even) are first bounded by one gathering from their four triangles
 * (the same bound, subd_s48_census_run_), made alone only where it does not fit: on spot's
 * base it fits for about three pairs in four: about 0.75 gatherings per pair, each a little
 * larger.
 *
 * Memory (subd_s48_census_bytes_): a stamp per base vertex (the run that reached it and its
 * ring distance), a stamp per base triangle and the gathering's queue (a vertex and the
 * triangle it was found in): 12 bytes per base vertex and 4 per base triangle, taken by
 * subd_sr48_base above its output and released. Cost: O(triangles * window). (It also took
 * one fan, nt0 + 1 words no longer read once each fan was merged as it is walked; dropped
 * before 0.6.0's release, which lowers subd_sr48_base_plan by 4 (nt0 + 1) bytes where the
 * census is its peak.) */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "sr48_stream_internal.h"
#include "layout.h"

/* The gathering's rings: the stream's (S48_RINGS). */
#define S48N_RINGS SUBD_SR48_STREAM_RINGS_

typedef struct s48n_work {
    const subd_sr48 *b;
    uint32_t *vs, *ts, *qv, *qt; /* stamps; queue */
    uint32_t run;
} s48n_work;

/* The census's scratch (layout.h: counted when a is NULL, carved otherwise). */
static int s48n_layout(subd_arena *a, uint32_t nv0, uint32_t nt0, s48n_work *w, uint32_t *bytes)
{
    subd_layout l;
    subd_layout_begin(&l, a);
    w->vs = (uint32_t *)subd_layout_take(&l, nv0, 4u);
    w->ts = (uint32_t *)subd_layout_take(&l, nt0, 4u);
    w->qv = (uint32_t *)subd_layout_take(&l, nv0, 4u);
    w->qt = (uint32_t *)subd_layout_take(&l, nv0, 4u);
    return subd_layout_end(&l, bytes);
}

uint32_t subd_s48_census_bytes_(uint32_t nv0, uint32_t nt0)
{
    s48n_work w;
    uint32_t bytes = 0;
    (void)s48n_layout(0, nv0, nt0, &w, &bytes);
    return bytes;
}

/* Triangle tt into the gathering tagged tag (once), its corners not reached yet into the
 * queue at distance dist + 1, found in tt. */
static inline void s48n_merge(s48n_work *w, uint32_t tt, uint32_t tag, uint32_t dist, uint32_t *nt, uint32_t *nv)
{
    const uint32_t *v = w->b->tri_vert + 3u * tt;
    uint32_t j;
    if (w->ts[tt] == tag) return;
    w->ts[tt] = tag;
    ++*nt;
    for (j = 0; j < 3u; j++) {
        const uint32_t vx = v[j];
        if ((w->vs[vx] & ~3u) == tag) continue;
        w->vs[vx] = tag + dist + 1u;
        w->qv[*nv] = vx;
        w->qt[(*nv)++] = tt;
    }
}

/* One gathering as subd_s48_build0_ does it, from the triangles p0..p1 of the base: the
 * largest nt + fan size and the vertex count, into *need_t, *need_v (maxima); its triangle
 * count and largest fan into *nt_out, *nf_out (the bound of subd_s48_census_run_). Each fan
 * is walked as subd_s48_fan_ walks it (sr48_stream_internal.h's steps, the same triangles in
 * the same order) and merged as it is walked: nt + fan size is taken with nt before the fan,
 * as the window reads a whole fan before merging it. */
static void s48n_gather(s48n_work *w, uint32_t p0, uint32_t p1, uint32_t *need_t, uint32_t *need_v, uint32_t *nt_out,
                        uint32_t *nf_out)
{
    const subd_sr48 *b = w->b;
    const uint32_t cap = b->level_tri[1] + 1u;
    uint32_t nt = 0, nv = 0, p, j, q, mf = 0;
    const uint32_t tag = 4u * ++w->run; /* stamp = tag + distance (< 4) */
    for (p = p0; p <= p1; p++)
        for (j = 0; j < 3u; j++) {
            const uint32_t vx = b->tri_vert[3u * p + j];
            if ((w->vs[vx] & ~3u) == tag) continue;
            w->vs[vx] = tag;
            w->qv[nv] = vx;
            w->qt[nv++] = p;
        }
    for (q = 0; q < nv; q++) {
        const uint32_t x = w->qv[q], dist = w->vs[x] & 3u, t = w->qt[q], nt0 = nt, vtag = tag + dist + 1u;
        uint32_t nf = 1, dir;
        if (dist >= S48N_RINGS) break; /* breadth first: the rest of the queue is as far */
        s48n_merge(w, t, tag, dist, &nt, &nv);
        for (dir = 0; dir < 2u; dir++) {
            uint32_t e, cur = t, i, around = 0, slot = subd_s48_fan_first_(b, x, t, dir, &e);
            for (i = 0; i < cap; i++) {
                const uint32_t nx = subd_s48_base_nbr_(b, cur, slot);
                if (nx == SUBD_NONE) break;
                if (nx == t) { /* around: interior vertex */
                    around = 1;
                    break;
                }
                /* nx entered by the edge (x, e) of cur, merged already: only its third
                 * corner (the next e) can be new (s48n_merge's order: the same queue) */
                slot = subd_s48_fan_enter_(b, x, nx, &e);
                if (w->ts[nx] != tag) {
                    w->ts[nx] = tag;
                    nt++;
                    if ((w->vs[e] & ~3u) != tag) {
                        w->vs[e] = vtag;
                        w->qv[nv] = e;
                        w->qt[nv++] = nx;
                    }
                }
                nf++;
                cur = nx;
            }
            if (i == cap) nf = cap; /* a broken fan: the stream's check refuses the base */
            if (around || i == cap) break;
        }
        if (nt0 + nf > *need_t) *need_t = nt0 + nf;
        if (nf > mf) mf = nf;
    }
    if (nv > *need_v) *need_v = nv;
    *nt_out = nt;
    *nf_out = mf;
}

/* The smallest N >= n whose capacities hold need_t triangles and need_v vertices. */
static uint32_t s48n_fit(uint32_t n, uint32_t need_t, uint32_t need_v)
{
    while (6u * n + 16u < need_t || 4u * n + 16u < need_v) n++;
    return n;
}

/* The census (subd_s48_census_), exact = 1: every gathering made; 0: a triangle's own
 * gathering is skipped where its pair's bounds it below the capacities of the N found so
 * far, *skipped counts them (the tests compare both). Why the bound holds: a triangle's
 * seeds are among its pair's, so (breadth first, every fan whole: no vertex has two fans)
 * every vertex it walks the pair walks, and its triangles T and vertices are the pair's or
 * fewer; its nt + fan size at any vertex is at most |T| + that fan <= the pair's triangle
 * count + the pair's largest fan, its vertex count at most the pair's. A skipped gathering
 * then cannot raise N, as N only grows. A base with a vertex of two fans (corners counted
 * against the whole walks, subd_s48_valence_cnt_) makes every gathering. Two consecutive pairs
 * are bounded the same way by one gathering from their four triangles (seeds a superset of
 * each pair's), tried first for H even; where it fits, both pairs and their triangles are
 * skipped (6 in *skipped). */
uint32_t subd_s48_census_run_(subd_arena *a, const subd_sr48 *b, uint32_t exact, uint32_t *skipped)
{
    const uint32_t nv0 = b->level_verts[0], nt0 = b->level_tri[1];
    uint32_t need_t = 0, need_v = 0, t, n, v, bytes, two = 0, ntp, nfp, nt1, nf1;
    s48n_work w;
    if (s48n_layout(a, nv0, nt0, &w, &bytes) != SUBD_OK) return 0; /* the plan holds it */
    w.b = b;
    w.run = 0;
    *skipped = 0;
    /* the corners per vertex (in the queue, free until the first gathering) */
    for (v = 0; v < nv0; v++) w.qv[v] = 0;
    for (t = 0; t < 3u * nt0; t++) w.qv[b->tri_vert[t]]++;
    v = subd_s48_valence_cnt_(b, w.qv, &two);
    n = v < 8u ? 8u : v;
    for (v = 0; v < nv0; v++) w.vs[v] = 0;
    for (t = 0; t < nt0; t++) w.ts[t] = 0;
    for (t = 0; t + 1u < nt0; t += 2u) {
        if (!exact && !two && (t & 2u) == 0u && t + 3u < nt0) {
            /* two pairs at once (2H, 2H + 1 and the next two: H even): their seeds are
             * among the four triangles', so the same bound holds for both pairs and their
             * triangles (below); made alone where it does not fit */
            uint32_t gt = 0, gv = 0, ntg, nfg;
            s48n_gather(&w, t, t + 3u, &gt, &gv, &ntg, &nfg);
            if (ntg + nfg <= 6u * n + 16u && gv <= 4u * n + 16u) {
                *skipped += 6u; /* two pairs and their four triangles */
                t += 2u;
                continue;
            }
        }
        s48n_gather(&w, t, t + 1u, &need_t, &need_v, &ntp, &nfp); /* uniform: the hybrid pair */
        n = s48n_fit(n, need_t, need_v);
        if (!exact && !two && ntp + nfp <= 6u * n + 16u) {
            *skipped += 2u; /* adaptive: one triangle, bounded by the pair */
            continue;
        }
        s48n_gather(&w, t, t, &need_t, &need_v, &nt1, &nf1); /* adaptive: one triangle   */
        s48n_gather(&w, t + 1u, t + 1u, &need_t, &need_v, &nt1, &nf1);
        n = s48n_fit(n, need_t, need_v);
    }
    return n;
}

/* The valence the stream sizes its windows with (above); 0 when the arena does not hold
 * the scratch (subd_sr48_base's plan does). */
uint32_t subd_s48_census_(subd_arena *a, const subd_sr48 *b)
{
    uint32_t skipped;
    return subd_s48_census_run_(a, b, 0u, &skipped);
}
