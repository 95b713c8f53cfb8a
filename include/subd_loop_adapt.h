/* SPDX-License-Identifier: MIT */
/* Adaptive Loop limit stream (src/loop_adapt.c): the limit surface of a triangle mesh as
 * triangles on the common triangle stream (subd.h "Streams"), each control face at its own
 * level up to a max level L, watertight. Included by subd.h. */
#ifndef SUBD_LOOP_ADAPT_H
#define SUBD_LOOP_ADAPT_H

#include "subd.h"

#ifdef __cplusplus
extern "C" {
#endif

#define SUBD_LOOP_ADAPT_CHORD 0u    /* levels from a chord tolerance (opts.chord)          */
#define SUBD_LOOP_ADAPT_CALLBACK 1u /* a level per control face from opts.face_level       */

/* The level of control face `face` (values above the max level mean the max level); must
 * return the same value for the same face every time it is called during one stream. */
typedef uint32_t (*subd_loop_face_level_fn)(void *user, uint32_t face);

typedef struct subd_loop_adapt_opts {
    subd_loop_opts loop;  /* levels: the max level L (1..SUBD_MAX_LEVELS); boundary rule;
                           * flags 0 or SUBD_LOOP_STREAM_LIMIT (limit positions always)     */
    uint32_t mode;        /* SUBD_LOOP_ADAPT_CHORD or SUBD_LOOP_ADAPT_CALLBACK              */
    subd_real chord;      /* CHORD: the tolerance eps (> 0, finite), input units            */
    subd_loop_face_level_fn face_level; /* CALLBACK: the level of each control face         */
    void *user;           /* handed to face_level                                          */
} subd_loop_adapt_opts;

/* subd_loop_adapt_stream_plan: the exact arena bytes of the adaptive stream (*bytes) =
 * SUBD_LOOP_ADAPT_STREAM_BYTES(L, N) for max level L and largest valence N of the input
 * (the uniform limit stream's: one control face's 1-ring per level 0..L, level L's mesh
 * view, one extraction's scratch, the run state and a one-triangle ring; at L <= 4 also
 * CHORD's point cache: one face's level-L limit points, a bit each, and 64 remembered own
 * levels, 1 856 + 512 bytes at L = 4, none above).
 * Memory: no arena use.
 * Errors: as subd_loop_stream_plan with SUBD_LOOP_STREAM_LIMIT (SUBD_ERR_PARAM,
 *   SUBD_ERR_NOT_TRIANGLES with diag.face, SUBD_ERR_TOO_BIG), and SUBD_ERR_PARAM for a NULL
 *   opts, an unknown mode, CHORD with chord <= 0 or not finite, CALLBACK without face_level.
 * Cost: O(corners). */
int subd_loop_adapt_stream_plan(const subd_mesh *in, const subd_loop_adapt_opts *o, uint32_t *bytes,
                                subd_diag *diag);

/* subd_loop_adapt_stream: the limit surface of `in`, each control face f at a level l(f) in
 * 0..L with each edge at a level e <= both its faces' levels, handed to sink->tri one
 * triangle at a time (subd_tri: limit positions, unit limit normals, ids; face: f; level:
 * l(f)).
 * Memory: exactly the plan's bytes at the peak, independent of the mesh and the output;
 *   nothing stays in the arena after the call (= subd_loop_adapt_stream_begin +
 *   subd_stream_run_tris).
 * Errors: as the plan, and SUBD_ERR_NOMEM (diag.bytes_needed = the plan) before anything is
 *   emitted; SUBD_ERR_RANGE (a position overflowed; diag.face); or the sink's non-zero value
 *   unchanged. The arena is always back where it was.
 * Cost: CALLBACK: per emitted triangle O(L) patch extractions at most (descents share their
 *   upper levels). CHORD: per control face, per edge about L 2^L limit evaluations and, per
 *   level tried for the face, one distance test of every level-L lattice point of the face,
 *   for the face and for each neighbour's own level (the output is adaptive, the check is
 *   exhaustive); the points themselves: at L <= 4 computed once per face visit into the
 *   point cache (about one uniform level-L pass of the face), above that once per level
 *   tried; all of it twice
 *   (a pass before the first triangle decides between the adaptive cut and the uniform
 *   fallback, see CHORD below).
 * Notes: every vertex is the limit point of a lattice point (a, b) of its control face (units
 *   1/2^L), bit-identical to the uniform limit stream at level L (subd_loop_stream with
 *   SUBD_LOOP_STREAM_LIMIT) and with its id (subd_loop.h's formula at level L), so a vertex
 *   used by several triangles or faces has one id and one value. A face whose edges are all
 *   at its level is emitted as the uniform stream emits it at that level (order and corners);
 *   a face with a coarser edge as its uniform triangles inside the triangle shrunk by one
 *   level-l step, plus a ring zipped between the face boundary (each edge's own level-e
 *   points) and that inner triangle (level 1: a fan), so there are no T-junctions: a closed
 *   input gives a closed, consistently oriented output when welded by id.
 *   CALLBACK: l(f) = min(face_level(f), L); e = the smaller of its faces' levels.
 *   CHORD: e is the larger of the smallest level whose chord polyline holds every level-L
 *   limit point of the edge within eps (computed on the same bits by both faces) and the
 *   smaller of its faces' own uniform levels; l(f) the smallest level >= its edges' at which
 *   every level-L limit point of the face lies within eps of the emitted triangle containing
 *   it or of one of the face's emitted triangles near it (the 3 x 3 lattice cells around
 *   it, the ring triangles beside it) (float32: Euclidean distance plus a rounding margin;
 *   Q16.16: |x - p|_1 plus 8 LSB, p a point of the triangle: x's barycentric coordinates,
 *   negative ones set to 0; a larger bound), else L. Fallback: before the first triangle the
 *   stream counts the adaptive cut's triangles; when they exceed the 4^U F of the uniform
 *   level U = the largest over the faces of the smallest level whose uniform triangles (the
 *   face's own, or its edge neighbours' beside the shared edge: at a uniform level all are
 *   emitted) hold the face's level-L points by the same check, and every face passes that
 *   check at U, every face is emitted at U instead (same guarantee, fewer triangles).
 *   Guarantee: every vertex of the uniform limit stream at level L lies within eps
 *   (Euclidean) of the emitted mesh.
 *   An eps below every deviation (and below the margin: 8 LSB in Q16.16, about 2^-18 of the
 *   coordinates in float32) gives the uniform limit stream bit for bit, as does CALLBACK
 *   with every face at L. */
int subd_loop_adapt_stream(subd_arena *a, const subd_mesh *in, const subd_loop_adapt_opts *o,
                           const subd_tri_sink *sink, subd_diag *diag);

/* subd_loop_adapt_stream_begin: the pull form (subd.h "Streams"): checks what the push form
 * checks, puts the state in the arena and fills *s; subd_stream_next_tris hands out the same
 * triangles in the same order with the same bits, subd_stream_end gives the arena back.
 * Memory: the plan's bytes, kept until the end.
 * Errors: those the push form reports before it emits anything; on failure the arena and *s
 *   are untouched. Later, subd_stream_next_tris returns SUBD_ERR_RANGE (s->diag.face).
 * Cost: O(corners) here; each next call: one triangle's batch (CHORD: a new control face
 *   first chooses its levels, the cost above). */
int subd_loop_adapt_stream_begin(subd_arena *a, const subd_mesh *in, const subd_loop_adapt_opts *o,
                                 subd_stream *s, subd_diag *diag);

/* The plan at compile time (L in 1..SUBD_MAX_LEVELS, N the largest valence): a uint32_t
 * constant expression equal to subd_loop_adapt_stream_plan. L = 8, N = 16: see the test
 * (loop_adapt_plan_16k). */
#define SUBD_LOOP_ADAPT_STREAM_BYTES(L, N) \
    (SUBD_STREAM_STATE_BYTES + SUBD_LOOP_SA_((uint32_t)sizeof(subd_tri)) + SUBD_LOOP_SA_(4u * 12u * ((L) + 1u)) + \
     SUBD_LOOP_SLEV_(3u * SUBD_LOOP_SN_(N), 1u, 1u) + ((L) - 1u) * SUBD_LOOP_SLEV_(SUBD_LOOP_SN_(N) + 12u, 1u, 0u) + \
     SUBD_LOOP_SLEV_(SUBD_LOOP_SN_(N) + 12u, 0u, 0u) + SUBD_LOOP_SVIEW_(SUBD_LOOP_SN_(N) + 12u) + \
     SUBD_LOOP_SSCR_(3u * SUBD_LOOP_SN_(N)) + SUBD_LOOP_SA_(SUBD_LOOP_ADAPT_WCACHE_) + SUBD_LOOP_ADAPT_PC_BYTES_(L))
#define SUBD_LOOP_ADAPT_WCACHE_ 132u /* the smooth rule's weight cache (16 pairs and a word) */
/* The point cache (L <= 4): one face's level-L limit points (3 subd_reals each, 4 bytes in both
 * arithmetics), a bit per point and 64 remembered (face, own level) pairs; none above level 4,
 * so the plan at 8 levels is unchanged. */
#define SUBD_LOOP_ADAPT_PC_LEVELS_ 4u
#define SUBD_LOOP_ADAPT_PC_POINTS_(L) ((((uint32_t)1 << (L)) + 1u) * (((uint32_t)1 << (L)) + 2u) / 2u)
#define SUBD_LOOP_ADAPT_PC_BYTES_(L) \
    ((L) <= SUBD_LOOP_ADAPT_PC_LEVELS_ ? SUBD_LOOP_SA_(12u * SUBD_LOOP_ADAPT_PC_POINTS_(L)) + \
     SUBD_LOOP_SA_(4u * ((SUBD_LOOP_ADAPT_PC_POINTS_(L) + 31u) / 32u)) + 8u * SUBD_LOOP_ADAPT_MEMO_ : 0u)
#define SUBD_LOOP_ADAPT_MEMO_ 64u /* with the point cache: faces' own levels remembered */

#ifdef __cplusplus
}
#endif

#endif
