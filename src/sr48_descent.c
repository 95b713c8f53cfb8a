/* SPDX-License-Identifier: MIT */
/* Streaming semi-regular 4-8 refinement: descents to the finest level (paper:
 * semi-regular-4-8-refinement-box-splines.txt, sections 4 and 6; the window they refine and
 * crop, its exactness argument: sr48_window.c; the private interface:
 * sr48_stream_internal.h). The finest position of a vertex is found by refining and
 * cropping towards it down to max_level, where it is exact by the ring rule
 * (subd_s48_finest_); L of the level-0 window (subd_s48_level0_lin_, CHORD's and the
 * adaptive cuts' interpolants) and the adaptation box (subd_s48_adapt_box_: RAMP, POINT's
 * default radius) are descents of the level-0 vertices. Moved out of sr48_window.c (its
 * length). Where a descent keeps its windows: the level blocks below its start (CHORD, few
 * levels), or with the adaptive walk's checkpoints (whose slots hold the walk's path) two
 * windows in the refined window's block, the last level also cropped (s48_dwin).
 */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "sr48_stream_internal.h"

/* The window of level j of a descent from level k (j > k): with the checkpoints of the
 * adaptive walk (s->ckw) the level slots hold the walk's path and its checkpoints, so the
 * descent's windows alternate between two level windows without L (a descent reads
 * positions only; L is a level window's last array, at off[7]) inside X's block, free during
 * a descent (it holds two: a compile-time check in sr48_stream.c); otherwise (CHORD, fewer
 * levels than a checkpoint's spacing) the blocks of the levels below k, free then. */
static void s48_dwin(const s48_state *s, uint32_t k, uint32_t j, s48_win *w)
{
    uint32_t off[8], i;
    if (j == k || !s->ckw) {
        s48_lev(s, j, w);
        return;
    }
    for (i = 0; i < 7u; i++) off[i] = s->off[i];
    off[7] = 0;
    s48_win_at(s, s->xblk + ((j - k) & 1u) * s->off[7], off, w);
}

/* One descent of subd_s48_finest_, each level cropped by subd_s48_refine_crop_'s fin (0: two
 * rings, 1: ring 1 of the children and the partners of its triangles). 1 done, 0 failure,
 * 2 not found exact (fin 1: made again with two rings). The last level: the refined window
 * X (no checkpoints), or (checkpoints: X's block holds the descent's windows) one more
 * refinement and crop: a kept vertex's position and flags are refine's, the same bits. */
static int s48_descend(s48_state *s, uint32_t k, uint32_t t, uint64_t id, subd_real *out, uint32_t fin)
{
    s48_win w, x, c;
    uint32_t j, cur = t, q, ch, v;
    for (j = k;; j++) {
        s48_dwin(s, k, j, &w);
        /* child 0 = (m; apex, b0) keeps apex and b0, child 1 = (m; b1, apex) keeps b1 */
        ch = (s48_vid(&w, w.tv[3u * cur + 2u]) == id) ? 1u : 0u;
        if (j + 1u == s->levels && !s->ckw) break;
        s48_dwin(s, k, j + 1u, &c); /* refined and cropped to cur's children in one pass */
        if (!subd_s48_refine_crop_(s, &w, j, cur, 1u, &c, s->wt, s->wv, fin)) return fin && !s->err ? 2 : 0;
        cur = c.hd[3u + ch];
        if (cur == S48_OUT) return fin ? 2 : 0;
        if (j + 1u == s->levels) break; /* checkpoints: c holds the vertex at max_level */
    }
    if (!s->ckw) {
        s48_x(s, &x);
        if (!subd_s48_refine_(s, &w, j, &x)) return 0;
        c = x;
        cur = 2u * cur + ch;
    }
    for (q = 0; q < 3u; q++) {
        v = c.tv[3u * cur + q];
        if (s48_vid(&c, v) != id) continue;
        if (!(c.vf[v] & S48_EXACT)) return fin ? 2 : 0;
        for (j = 0; j < 3u; j++) out[j] = c.vp[3u * v + j];
        return 1;
    }
    return 0;
}

/* The finest (max_level) position of the vertex with id `id`, a corner of triangle t of the
 * level-k window (k < levels): the windows k+1.. are refined and cropped along children
 * that keep the vertex as a corner (a corner of a triangle is a corner of one of its
 * children), and its position is read from the last refined window, where it is exact by
 * the ring rule (checked). Uses the blocks of levels > k (no checkpoints) and X only. 0 on failure. Each
 * level but the last is refined and cropped in one pass (subd_s48_refine_crop_); first to
 * ring 1 of the children and the partners of its triangles, as the uniform tile's windows
 * (sr48_tile.c; about half the triangles), and when the vertex is then not exact, again with
 * the two rings of the exactness argument: a kept vertex's position and flags do not
 * depend on the crop, so the bits are the same (s->two_rings, a test hook: the two rings
 * alone). */
int subd_s48_finest_(s48_state *s, uint32_t k, uint32_t t, uint64_t id, subd_real *out)
{
    const int r = s->two_rings ? 2 : s48_descend(s, k, t, id, out, 1u);
    return r == 2 ? s48_descend(s, k, t, id, out, 0u) : r;
}

/* L of the level-0 window of t0 (s->l0): each vertex's finest position, by a descent from
 * a base triangle at it. Rebuilds level 0 for every vertex; the caller rebuilds t0's. */
int subd_s48_level0_lin_(s48_state *s, uint32_t t0)
{
    s48_win w;
    uint32_t nv, i, j;
    for (i = 0; i < 3u * s->wv; i++) s->l0[i] = 0; /* the descents' L: defined, unused */
    if (!subd_s48_build0_(s, t0)) return 0;
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
        if (!subd_s48_build0_(s, s->lgvt[i])) return 0;
        if (!subd_s48_finest_(s, 0, w.hd[2], s->lgv[i], s->l0 + 3u * i)) return 0;
    }
    return 1;
}

/* The adaptation box A (RAMP, POINT's default radius; subd_sr48_adapt_mode): the finest
 * positions of the level-0 triangles' corners, each vertex by one descent from the
 * lowest-index triangle of its fan (so once); then POINT's radius. levels > 0. */
int subd_s48_adapt_box_(s48_state *s)
{
    const subd_sr48 *b = s->base;
    uint32_t t, j, i, zero = 0;
    s48_win w;
    for (i = 0; i < 3u * s->wv; i++) s->l0[i] = 0; /* the descents' L: defined, unused */
    subd_sr48_box_grow_(b->pos, &zero, 0, s->blo, s->bhi, 1);
    for (t = 0; t < s->n0; t++)
        for (j = 0; j < 3u; j++) {
            uint32_t v = b->tri_vert[3u * t + j], nf = subd_s48_fan_(b, v, t, s->gt, s->wt), low = 1;
            subd_real p[3];
            if (nf == UINT32_MAX) return 0;
            for (i = 0; i < nf; i++)
                if (s->gt[i] < t) low = 0;
            if (!low) continue;
            if (!subd_s48_build0_(s, t)) return 0;
            s48_lev(s, 0, &w);
            if (!subd_s48_finest_(s, 0, w.hd[2], v, p)) return 0;
            subd_sr48_box_grow_(p, &zero, 1, s->blo, s->bhi, 0);
        }
    if (s->ad.mode == SUBD_SR48_ADAPT_POINT && s->radius == 0)
        s->radius = subd_sr48_default_radius_(s->blo, s->bhi, s->levels);
    return 1;
}

