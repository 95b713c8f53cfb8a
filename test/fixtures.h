/* SPDX-License-Identifier: MIT */
/* Test fixtures shared by several test files (issue 19 item 7: one home for each): the
 * brute-force point-to-triangle distance of the chordal checks (test_sr48_chord.c,
 * test_sr48_stream_shapes.c), the mesh lookups of several suites (test_loop.c,
 * test_loop_rules.c), the planar triangle grid (test_mesh.c, test_quasi48.c, test_sr48.c),
 * the 4-8 tests' shapes and their base-mesh valences (test_sr48_stream.c,
 * test_sr48_stream_shapes.c, test_sr48_chord.c) and the decimal-to-subd_real conversion.
 * Each is checked by the suites that use it (a wrong fixture fails their closed forms). */
#ifndef TEST_FIXTURES_H
#define TEST_FIXTURES_H
#include "harness.h"
#include "subd_sr48.h"

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

/* The planar (n+1) x (m+1) grid of unit squares, vertex (i, j) = i (m + 1) + j at (j, i, z),
 * each square (a, b, c, d) = (v, v + 1, v + m + 2, v + m + 1) cut into two triangles by
 * the diagonal a-c ((a, b, c), (a, c, d)), or with alternate set by b-d where i + j is even
 * ((a, b, d), (b, c, d)): an open disk. Writes idx (6 n m) and, when pos is not NULL, pos
 * (z from z[v], or 0 when z is NULL); returns the triangle count 2 n m. */
uint32_t fx_grid(uint32_t n, uint32_t m, int alternate, const subd_real *z, subd_real *pos, uint32_t *idx);

/* The 4-8 stream's closed-form vertex ids recomputed from a hierarchy h of `levels` steps
 * (include/subd_sr48.h: level-0 vertex i keeps i; the vertex created at level k >= 1 by the
 * diamond whose lower triangle is i of level k - 1 is V0 + T0n (2^(k-1) - 1) + i): map[id] =
 * the hierarchy's vertex, SUBD_NONE for an id no vertex has. Returns the id count, or 0 when
 * it exceeds cap (a failed CHECK). Used to match streamed corners with the hierarchy's. */
uint32_t fx_sr48_id_map(const subd_sr48 *h, uint32_t levels, uint32_t *map, uint32_t cap);

/* x as the nearest subd_real (Q16.16: rounded half away from zero; float32: the C cast).
 * For test inputs written as decimals. */
subd_real fx_real(double x);

/* The shapes of the 4-8 stream tests, by id: a tetrahedron (valence 3), a cube of
 * triangles, the icosahedron, a hexagon fan (open), an open 8x8 grid, two triangles and an
 * isolated one (open; pre-processing keeps a triangle alone), the 6x4 torus, and a closed
 * bipyramid: bipyr_n (3..16) equator vertices on the unit circle (z alternating 0, 1/8),
 * apexes at z = +-1 of valence bipyr_n. Builds the mesh with adjacency in a; 1 on success
 * (a failed CHECK otherwise). */
enum { FX48_TET, FX48_CUBE, FX48_ICO, FX48_HEXFAN, FX48_GRID, FX48_TWO, FX48_TORUS, FX48_BIPYR, FX48_COUNT,
       FX48_DENSE = FX48_COUNT /* test/data/dense_ico.obj, after the count: in no shape loop */ };
int fx_sr48_shape(int id, uint32_t bipyr_n, subd_arena *a, subd_mesh *m);

/* The largest (and in *lowest, when not NULL, the smallest non-zero) vertex valence of a
 * 4-8 base mesh's level-0 triangles (what the stream's plan takes); 0 (a failed CHECK)
 * when the base has more than FX_SR48_MAXV vertices (the count table is static). */
#define FX_SR48_MAXV (H_HOST ? 32768u : 2048u)
uint32_t fx_sr48_valence(const subd_sr48 *base, uint32_t *lowest);

/* Triangle keys for comparing two triangle sets in any order: the 9 position bits of the
 * triangle p[0..8] rotated to start at its smallest corner, into row[0..8]; fx_tri_key_cmp
 * orders such rows (qsort). */
void fx_tri_key(uint32_t *row, const subd_real *p);
int fx_tri_key_cmp(const void *a, const void *b);

/* A triangle sink that counts: ++*(uint32_t *)ctx per triangle, nothing read, returns 0. */
int fx_count_tri(void *ctx, const subd_tri *t);

/* subd_sr48_stream(base, so) into fx_count_tri with every arena size from 0 to plan at buf
 * (in steps of `step` until within `near` of the plan, then of 1): below the plan
 * SUBD_ERR_NOMEM with bytes_needed = plan, nothing emitted, the arena untouched (mark and
 * peak 0); at the plan SUBD_OK, peak = plan. Returns the triangles streamed at the plan (0
 * after a failed check). */
uint32_t fx_sr48_plan_sweep(const subd_sr48 *base, const subd_sr48_stream_opts *so, uint8_t *buf, uint32_t plan,
                            uint32_t step, uint32_t near);

#endif
