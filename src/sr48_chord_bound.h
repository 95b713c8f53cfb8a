/* SPDX-License-Identifier: MIT */
/* CHORD's pruning bound (sr48_chord_bound.c: the bound, why it is sound, the margin), the
 * private interface of sr48_chord_walk.c to it. Names subd_s48b_*_ (unique in src/). */
#ifndef SUBD_SR48_CHORD_BOUND_H
#define SUBD_SR48_CHORD_BOUND_H
#include "sr48_stream_internal.h"

/* Test switch (test_sr48_chord_prune.c): nonzero turns the pruning off, so that a test
 * can compare the cut with and without it. The library only reads it. */
extern int subd_s48b_off_;

/* One pruning test: window p of level l = max_level - rem, its nodes lo .. lo + n - 1 (n a
 * power of two: the heap nodes n .. 2n - 1 of a tile whose node 1 is their level l - log2 n
 * ancestor; n = 1: one node), and what the tests below them compare against. */
typedef struct s48b_ctx {
    const s48_win *p;
    uint32_t lo, n, rem;
    int strict;     /* every vertex of V2(q) must be exact (a window of unknown origin)  */
    subd_real mag;  /* largest |coordinate| of the window's positions            */
    subd_sr48_lin dsum; /* largest sum of per-axis ranges of a node's region (>= D(q)) */
} s48b_ctx;

/* The chart of p and every node's own bound D(q) (q and every triangle below it): 1 when all
 * of them are within the limit, 0 when not (or the region is not regular: then no pruning).
 * strict 0: p is a proper window (the walk's, or a tile's started from one), where a vertex
 * of V2(q) that is not exact is not in q's dependency cone (sr48_chord_bound.c). */
int subd_s48b_begin_(s48_state *s, s48b_ctx *c, const s48_win *p, uint32_t lo, uint32_t n, uint32_t rem, int strict);
/* Is every vertex of V2(q) in window p exact, and V1(q)'s fans closed in it? Then a tile of q
 * started from p is as good as one started from q's own window (sr48_chord_bound.c). */
int subd_s48b_proper_(s48_state *s, const s48_win *p, uint32_t q);
/* The tile's nodes 1 .. n - 1 above level l (corners hc: 3 window vertices of p per heap
 * node, their level-l positions; finest corners unknown): 1 when none can deviate. */
int subd_s48b_inner_(s48_state *s, const s48b_ctx *c, const uint16_t *hc);
/* One interpolant with known corners, given at node 1's corners (9 values, carried there by
 * `steps` midpoint steps; mag: the largest |coordinate| of the triangle it interpolates): 1
 * when no vertex below the nodes can deviate from it. */
int subd_s48b_known_(s48_state *s, const s48b_ctx *c, const subd_sr48_lin *l, subd_real mag, uint32_t steps);

/* sr48_chord_walk.c's interpolant step (subd_sr48_chord_beyond_'s): triangle l (apex, b0, b1)
 * to its child `bit`. */
void subd_s48c_lin_child_(const subd_sr48_lin *l, uint32_t bit, subd_sr48_lin *c);

#endif
