/* SPDX-License-Identifier: MIT */
/* Test fixtures shared by several test files (issue 19 item 7: one home for each): the
 * brute-force point-to-triangle distance of the chordal checks (test_sr48_chord.c,
 * test_sr48_stream_shapes.c), the 4-8 test shapes (test_sr48_chord.c,
 * test_sr48_stream_shapes.c, test_sr48_stream.c) and the mesh lookups of several suites.
 * Tested by suite_fixtures (test/test_fixtures.c) against closed forms. */
#ifndef TEST_FIXTURES_H
#define TEST_FIXTURES_H
#include "harness.h"

/* Squared distance from p to the triangle (a, b, c), in double: the closest point found by
 * the Voronoi regions of the vertices, edges and face (Ericson, Real-Time Collision
 * Detection, 5.1.5). */
double fx_tri_dist2(const double *p, const double *a, const double *b, const double *c);

/* The chordal guarantee by brute force: for each of the points pts[0..np) (3 subd_reals
 * each), whether some triangle of tris[0..nt) (9 subd_reals each: three corners) lies within
 * squared distance bound2. Returns a value <= bound2 when every point has one, and otherwise
 * the largest squared distance from a point that has none to its nearest triangle (> bound2).
 * A point's search stops at the first triangle within bound2, and a triangle whose bounding
 * box is farther than bound2 is not measured (the box's distance is a lower bound), so the
 * answer to "every point within the bound?" is the one of measuring every pair. */
double fx_worst_dist2(const subd_real *pts, uint32_t np, const subd_real *tris, uint32_t nt, double bound2);

/* The first half-edge of m (in corner order) from vertex a to vertex b, or SUBD_NONE;
 * fx_find_edge: the first from a to b or from b to a. Linear search. */
uint32_t fx_find_he(const subd_mesh *m, uint32_t a, uint32_t b);
uint32_t fx_find_edge(const subd_mesh *m, uint32_t a, uint32_t b);

#endif
