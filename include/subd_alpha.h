/* SPDX-License-Identifier: MIT */
/* Semi-stationary alpha-subdivision (Zhang Hongxin and Wang Guojin,
 * "Semi-stationary subdivision operators in geometric modeling", Progress in Natural Science
 * 12(10), 2002). Each call's comment: a summary, Memory, Errors (every status), Cost, Notes.
 *
 * Curves: the second order bisect operator S_2(f; n) of formula (2) and the higher orders of
 * definition 3 (S_{2k} = B C S_{2k-1}, S_{2k+1} = C S_{2k}; C averages consecutive points,
 * B shifts the indices by one). Surfaces: the Doo-Sabin type operator of formula (3).
 *
 * Kernel and parameter. The level-n weights use f_n = f(alpha; n) = s * g(2^-(n+1) alpha),
 * where s is the stiffness (s = f(0), table 1) and g is the kernel:
 *   SUBD_ALPHA_BSPLINE  g = 1                (f == s; s = 1: uniform B-splines, Chaikin)
 *   SUBD_ALPHA_COS      g(x) = cos x         (C-curves: exact circles and ellipses)
 *   SUBD_ALPHA_POLY     g(x) = 1 - x^2 / 2   (the paper's "1 - alpha^2/2")
 *   SUBD_ALPHA_COSH     g(x) = cosh x        (the paper's "(e^alpha + e^-alpha) / 2")
 * The paper writes the cos kernel as cos(2^-(n+1) alpha) and the other two without the
 * level argument; we evaluate all three at the same argument 2^-(n+1) alpha, so that POLY is
 * the second order Taylor polynomial of COS and COSH is COS at an imaginary angle (it
 * reproduces hyperbolas as COS reproduces circles).
 *
 * alpha is an exact rational number of turns: alpha = 2 pi * alpha_num / alpha_den radians
 * (a regular N-gon's edge angle is 1/N). The kernel values are computed with integer
 * arithmetic only (cos from subd_cos_turns_q62, cosh from an own Q62 exponential series),
 * the weights in Q32.32 integers, then rounded once to subd_real: identical bits on every
 * target, no libm, no float in the fixed-point build.
 *
 * Stiffness. The paper is inconsistent: its table 1 lists s in (-inf, -1] as "diverge" and
 * (-1, 0) as "fractal", but theorem 1 proves convergence only for s in (-1/2, inf) (and for
 * s in (-1, -1/2] the output does diverge: edge lengths grow level by level). We follow
 * theorem 1: s <= -1/2 is rejected with SUBD_ERR_DIVERGENT; s in (-1/2, 0] is accepted and
 * reported as not smooth (continuity = -1); s in (0, 1/2] gives GC0 (continuity 0); s > 1/2
 * gives GC^(k-1) for curves (theorem 1) and GC1 for the Doo-Sabin type surface (theorem 2).
 * A stiffness outside the internal Q32.32 range (|s| >= 2^31, float build) or not finite is
 * SUBD_ERR_PARAM. A level whose own f_n <= -1 (possible when s > 1 and the kernel is
 * negative at a large alpha) would divide by 1 + f_n <= 0 and is rejected with
 * SUBD_ERR_PARAM; a level with f_n in (-1, -1/2] is accepted (finitely many such levels do
 * not change convergence, which depends on s = lim f_n) but amplifies the points.
 *
 * Memory: every call has a plan that is exactly the arena peak of the run. On any failure
 * the arena is rewound to where it was and the outputs are not touched.
 */
#ifndef SUBD_ALPHA_H
#define SUBD_ALPHA_H

#include <stdint.h>
#include "subd.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum subd_alpha_kernel {
    SUBD_ALPHA_BSPLINE = 0,
    SUBD_ALPHA_COS = 1,
    SUBD_ALPHA_POLY = 2,
    SUBD_ALPHA_COSH = 3
} subd_alpha_kernel;

/* Highest operator order accepted (S_2 .. S_8). */
#define SUBD_ALPHA_MAX_ORDER 8u
/* |alpha_num| and every |tag| must be <= this; alpha_den must be in 1..(INT32_MAX >>
 * (levels + 1)) so that every level's angle is an exact int32 fraction of a turn. */
#define SUBD_ALPHA_MAX_NUM ((1 << 30) - 1)

typedef struct subd_alpha_opts {
    uint32_t order;       /* k in 2..SUBD_ALPHA_MAX_ORDER                                 */
    uint32_t levels;      /* 0..SUBD_MAX_LEVELS (surfaces: >= 1)                          */
    uint32_t kernel;      /* subd_alpha_kernel                                            */
    int32_t alpha_num;    /* alpha = 2 pi alpha_num / alpha_den radians                   */
    int32_t alpha_den;    /* > 0                                                          */
    subd_real stiffness;  /* s = f(0); must be > -1/2 (theorem 1)                         */
    /* Optional alpha tags (section 3): numerators over the shared alpha_den, each within
     * +-SUBD_ALPHA_MAX_NUM; NULL = alpha_num everywhere. Curves: one per input point.
     * Surfaces: one per input vertex for odd k, one per input face for even k. See the
     * curve and surface sections for how they travel. */
    const int32_t *tag_num;
} subd_alpha_opts;

/* subd_alpha_opts_default: order 2, levels 1, B-spline kernel, alpha = 0 (den 1),
 * stiffness 1, no tags.
 * Memory: none. Errors: none (o must not be NULL). Cost: O(1). */
void subd_alpha_opts_default(subd_alpha_opts *o);

/* subd_alpha_kernel_value: the kernel value f(alpha; n) = s g(2^-(n+1) alpha) for
 * alpha = 2 pi num / den, rounded to subd_real, into *f. Any int32 num.
 * Memory: no arena; stack < 200 bytes.
 * Errors: SUBD_ERR_PARAM (f NULL, bad kernel, den <= 0, den << (n + 1) not an int32,
 *   s <= -1, |s| >= 2^31 or not finite; the kernel itself accepts s in (-1, -1/2], only the
 *   operators refuse it with SUBD_ERR_DIVERGENT), SUBD_ERR_RANGE (the value does not fit:
 *   cosh (or poly) of a large angle, e.g. num = SUBD_ALPHA_MAX_NUM at level 0). *f is
 *   untouched on failure.
 * Cost: O(1) (the deterministic cos/sin or a short series in 64-bit integers). */
int subd_alpha_kernel_value(uint32_t kernel, int32_t num, int32_t den, uint32_t level, subd_real s,
                            subd_real *f);

/* ------------------------------------------------------------------------------------ */
/* Curves                                                                                 */
/*                                                                                        */
/* Closed polygon of m >= 3 points (the edge p[m-1] p[0] is implied; do not repeat p[0]):  */
/* every level maps m points to 2m (S_2 doubles, C keeps the count); for even k the B      */
/* shifts of definition 3 rotate the start by (k - 2) / 2 points per level.                 */
/*                                                                                        */
/* Open polyline of m >= 2 points, end condition "odd reflection": the polyline is         */
/* continued beyond each end point e by the point reflection through e (p[-j] = 2 e -      */
/* p[j]). Both operators map such point-symmetric sequences to point-symmetric ones, so the */
/* end points never move and every level's end tangent points along its end edge. For     */
/* S_2 the first and last input points are the midpoints of virtual end edges (whose far   */
/* vertices are those reflections); a control polyline that circumscribes a circular arc  */
/* and starts and ends at its tangent points therefore gives that arc exactly with the cos */
/* kernel. Point counts: S_2 maps m to 2m - 2 (m >= 3; a segment stays a segment); C maps  */
/* m to m - 1 after S_2 and to m + 1 after another C; B is not applied to open curves.     */
/*                                                                                        */
/* Per-vertex alpha (tag_num, section 3): an edge (a, b) of S_2 uses alpha = (tag_a +      */
/* tag_b) / 2 (exact: num tag_a + tag_b over 2 alpha_den); the two new points of an edge   */
/* inherit the tag of their nearer end, C's midpoint of (a, b) gets floor((tag_a +         */
/* tag_b) / 2); a reflected point has its mirror image's tag. Equal tags give exactly the  */
/* uniform result.                                                                        */

typedef struct subd_alpha_curve_out {
    uint32_t num_points;
    subd_real *pos;       /* 3 * num_points, in the arena                                  */
    int32_t continuity;   /* -1 not smooth (s <= 0), 0 GC0, else k - 1 (theorem 1)         */
} subd_alpha_curve_out;

/* subd_alpha_curve_plan: the exact arena bytes (*bytes) and output point count
 * (*out_points) of subd_alpha_curve for m input points.
 * Memory: no arena use.
 * Errors: SUBD_ERR_PARAM (NULL, bad order / levels / kernel / alpha, |s| >= 2^31 or s not
 *   finite), SUBD_ERR_DIVERGENT (s <= -1/2), SUBD_ERR_EMPTY (m < 2 open, m < 3 closed),
 *   SUBD_ERR_TOO_BIG (m or a level's count > 2^26).
 * Cost: O(levels * k). */
int subd_alpha_curve_plan(uint32_t m, int closed, const subd_alpha_opts *o, uint32_t *bytes,
                          uint32_t *out_points);

/* subd_alpha_curve: refines one curve by opts->levels applications of S_k(f; n),
 * n = 0 .. levels - 1, into *out.
 * Memory: exactly the plan: one arena buffer of the largest intermediate size (each
 *   operator runs in place) plus, with tags, one int32 tag per point that is given back at
 *   the end: after success the arena holds only out->pos. Stack about 200 bytes.
 * Cost: O(points of the last level * k).
 * Errors: in this order, SUBD_ERR_PARAM (NULL, options,
 * |s| >= 2^31 or not finite), SUBD_ERR_DIVERGENT (s <= -1/2), SUBD_ERR_EMPTY,
 * SUBD_ERR_TOO_BIG (m or a level's count > 2^26; checked before any point is read),
 * SUBD_ERR_NAN (a non-finite input point, diag.vertex), SUBD_ERR_NOMEM (diag.bytes_needed =
 * the plan), SUBD_ERR_PARAM (a tag outside +-SUBD_ALPHA_MAX_NUM, diag.vertex; a level with
 * f_n <= -1), SUBD_ERR_RANGE (overflow: a kernel value or a point outside the range). On
 * failure the arena is back where it was and *out is untouched. */
int subd_alpha_curve(subd_arena *arena, const subd_real *pos, uint32_t m, int closed,
                     const subd_alpha_opts *o, subd_alpha_curve_out *out, subd_diag *diag);

/* ------------------------------------------------------------------------------------ */
/* Streamed curves (src/alpha_stream.c): the points of subd_alpha_curve one at a time, to  */
/* the common point stream of subd.h ("Streams"), in memory that depends on the level     */
/* count and the order only; optionally only the points a chord tolerance needs.          */
/*                                                                                        */
/* Points (subd_point): pos; tangent (0, 0, 0); id = the point's index in subd_alpha_curve's */
/* output (0 .. num_points - 1, a closed form: the stream walks that output in order);     */
/* curve 0; level = opts->levels.                                                         */
/* Uniform (chord = 0): every point of subd_alpha_curve's output, in its order, with its  */
/* bits (both arithmetics, closed and open, every kernel, stiffness and tags).            */
/* Adaptive (chord > 0): a subsequence of those points (same ids, same bits) whose        */
/* polyline (closed: with the edge back to the first point) has every point of the        */
/* uniform output within chord of it: the output is cut into blocks of 256 segments, and  */
/* inside a block a span of indices [a, b] is one segment when every point between a and  */
/* b lies within chord of the segment (measured, with a margin for rounding), else it is  */
/* halved (top-down). The first point (and for an open curve the last) is always emitted, */
/* as is every 256th (at least one point in 256 is kept).                                 */
/* Run-time failures are excluded at the begin call: without tags, with every f_n >= 0    */
/* and an input extent inside the range a run cannot fail (convex combinations); otherwise */
/* the begin call runs the stream once without output and fails as subd_alpha_curve would, */
/* so a refused input emits nothing and a begun stream never fails.                       */

/* subd_alpha_curve_stream_plan: the exact arena bytes of the stream (*bytes) =
 * SUBD_ALPHA_CURVE_STREAM_BYTES(opts->levels, opts->order), for every m, closed, chord and
 * tags.
 * Memory: no arena use.
 * Errors: as subd_alpha_curve_plan (SUBD_ERR_PARAM, SUBD_ERR_DIVERGENT, SUBD_ERR_EMPTY,
 *   SUBD_ERR_TOO_BIG), and SUBD_ERR_PARAM for a chord < 0 or not finite.
 * Cost: O(levels * k). */
int subd_alpha_curve_stream_plan(uint32_t m, int closed, const subd_alpha_opts *o, subd_real chord,
                                 uint32_t *bytes);

/* subd_alpha_curve_stream_begin: starts the pull stream *s of the curve pos[0 .. 3m) (the
 * caller keeps pos and o->tag_num alive and unchanged until the stream ends); then
 * subd_stream_next_points / subd_stream_end (subd.h).
 * Memory: exactly the plan, in the arena until the stream ends (the end, a failure or
 *   subd_stream_end rewinds it). Stack (Cortex-M4, gcc -O2, -fstack-usage): about 0.7 KB on
 *   the deepest path (push form, stream layer, a stage step, the kernel); a pull walks the
 *   stages in a loop, not by recursion.
 * Errors: in subd_alpha_curve's order: SUBD_ERR_PARAM (NULL arena, pos or s, options, a
 *   chord < 0 or not finite), SUBD_ERR_DIVERGENT, SUBD_ERR_EMPTY, SUBD_ERR_TOO_BIG,
 *   SUBD_ERR_NAN (diag.vertex), SUBD_ERR_NOMEM (diag.bytes_needed = the plan), SUBD_ERR_PARAM
 *   (a tag outside +-SUBD_ALPHA_MAX_NUM, diag.vertex), then what the run would report:
 *   SUBD_ERR_PARAM (a level with f_n <= -1) or SUBD_ERR_RANGE (a kernel value or a point
 *   overflows); the lowest failing level's kernel status first, as subd_alpha_curve. On
 *   failure the arena is where it was and *s untouched. A begun stream's next calls fail
 *   only for a bad handle or buffer.
 * Cost: O(m) (the extent and the tag checks); with tags, a negative f_n or a wide input
 *   O(subd_alpha_curve) for the run without output. Each next call: its points plus one
 *   batch (uniform: one point, about (k - 1) L stage steps; adaptive: one block of 256
 *   segments, its points and their distance tests). */
int subd_alpha_curve_stream_begin(subd_arena *arena, const subd_real *pos, uint32_t m, int closed,
                                  const subd_alpha_opts *o, subd_real chord, subd_stream *s, subd_diag *diag);

/* subd_alpha_curve_stream: the push form: begin, every point to sink->point, end.
 * Memory: as subd_alpha_curve_stream_begin; nothing stays in the arena.
 * Errors: SUBD_ERR_PARAM (NULL sink or sink->point, before anything else), the begin call's
 *   (nothing is emitted), or the sink's non-zero value unchanged (the stream stops at once).
 * Cost: O(subd_alpha_curve) (the uniform cost in both modes) plus the sink's. */
int subd_alpha_curve_stream(subd_arena *arena, const subd_real *pos, uint32_t m, int closed,
                            const subd_alpha_opts *o, subd_real chord, const subd_point_sink *sink, subd_diag *diag);

/* The plan at compile time (levels L in 0..SUBD_MAX_LEVELS, order K in 2..8), for a static
 * buffer: the state block, a one-point ring, per stage (L K of them: S_2, K - 2 averages and
 * the shift per level) 8 words, 9 window points and their tags, and the adaptive block of 258
 * points. 9 280 bytes at L = 8, K = 4; 14 912 at L = 8, K = 8. */
#define SUBD_ALPHA_SA_(x) (((uint32_t)(x) + (SUBD_ARENA_ALIGN - 1u)) & ~(uint32_t)(SUBD_ARENA_ALIGN - 1u))
#define SUBD_ALPHA_CURVE_STREAM_BYTES(L, K) \
    (SUBD_ALPHA_SA_(SUBD_STREAM_STATE_BYTES) + SUBD_ALPHA_SA_(40u) + SUBD_ALPHA_SA_(32u * (uint32_t)(L) * (uint32_t)(K)) + \
     SUBD_ALPHA_SA_(108u * (uint32_t)(L) * (uint32_t)(K)) + SUBD_ALPHA_SA_(36u * (uint32_t)(L) * (uint32_t)(K)) + \
     SUBD_ALPHA_SA_(12u * 258u))

/* Path formats of subd_path_write. */
#define SUBD_PATH_XYZ 1u
#define SUBD_PATH_GCODE 2u

/* subd_path_write: the points p[0..n) of a path as text into buf[0..cap), numbers by
 * subd_real_format (the same bytes on every target); *len receives the bytes written.
 * SUBD_PATH_XYZ: one "x y z" line per point. SUBD_PATH_GCODE: a plain tool path: for the
 * path's first point (first_index == 0) "G21" (millimetres), "G90" (absolute) and
 * "G0 X.. Y.. Z.." (rapid move to the start); every later point "G1 X.. Y.. Z..", the one at
 * index 1 with " F<feed>" when feed > 0 (F is modal). first_index is the index of p[0] in
 * the path, so a stream can be written in pieces with the same bytes as in one.
 * Memory: no arena; the caller's buffer only.
 * Errors: SUBD_ERR_PARAM (NULL len, NULL p with n > 0, an unknown format, feed < 0 or not
 *   finite), SUBD_ERR_NOMEM (cap too small: nothing is written, *len = the size needed);
 *   with buf == NULL nothing is written, *len receives the size and SUBD_OK is returned;
 *   SUBD_ERR_TOO_BIG (the text would exceed 4 GB).
 * Cost: O(n) (two passes: count, then write). */
int subd_path_write(const subd_point *p, uint32_t n, uint32_t first_index, uint32_t format, subd_real feed,
                    char *buf, uint32_t cap, uint32_t *len);

/* ------------------------------------------------------------------------------------ */
/* Surfaces: the Doo-Sabin type operator S_2(f; n), formula (3), and the higher orders     */
/* S_k = C^(k-2) S_2 of section 2.2 (S_3 = C S_2 is the paper's Catmull-Clark variant).    */
/*                                                                                        */
/* Each corner i of an N-gon gets p_i' = f/(1+f) p_i + f/(2(1+f)^2) (p_{i-1} + p_{i+1})   */
/* + 1/(N(1+f)^2) sum p, computed as c + f/(1+f) d_i + f/(2(1+f)^2)(d_{i-1} + d_{i+1}),   */
/* d = p - c, c the face centroid (the weights sum to 1). The output is the Doo-Sabin mesh: */
/* vertex j of the output is corner j of the input; faces, in this order: one per input    */
/* face (same corner order), one quad per interior edge, one face per interior vertex (its */
/* corners in ring order). Boundary rule: boundary edges and boundary vertices make no      */
/* face, so the boundary recedes by half a face per level (the classical Doo-Sabin         */
/* behaviour without boundary rules); faces on the boundary use formula (3) unchanged.     */
/* Isolated vertices and polylines are dropped. An interior vertex of valence 2 (two faces  */
/* sharing two consecutive edges, e.g. a split edge) would make a digon: it makes no face;  */
/* the digon is collapsed to the edge the two neighbouring edge quads share, so each of its */
/* two corners becomes an interior output vertex of valence 3 (with D2 such vertices:      */
/* F' -= D2, C' -= 2 D2, E_int' -= D2, S' -= 2 D2; only the input can have them). So every  */
/* manifold input works at every order; an error never names an intermediate mesh's element.*/
/* The output is built with the library's                                                 */
/* validator (subd_mesh_finish), so every adjacency array and tag is set.                  */
/* Counts per S_2 step: V' = C, F' = F + E_int + V_int, C' = C + 4 E_int + S (S = the sum  */
/* of the valences of the interior vertices); then E_int' = 2 E_int + S, V_int' = S,       */
/* S' = 4 S and B' = C - S boundary vertices (= boundary edges).                          */
/*                                                                                        */
/* Dual averaging C (figure 3), applied k - 2 times after each S_2 step (no parameter):    */
/* output vertices are the face centroids (face order), then the midpoints of the boundary */
/* edges (half-edge order), then the boundary vertices themselves (vertex order); one face */
/* per vertex of the mesh (vertex order): an interior vertex gives the centroids of its    */
/* faces in ring order; a boundary vertex v gives [v, midpoint of its outgoing boundary    */
/* edge, the centroids of its faces in ring order, midpoint of its incoming boundary edge] */
/* (boundary rule: the dual of the mesh with its boundary polygon kept, split at the edge  */
/* midpoints; so C keeps the boundary polygon and only S_2 makes it recede). C keeps the   */
/* Euler characteristic and the boundary loops. Counts per C step (B boundary vertices =   */
/* boundary edges): V' = F + 2B, F' = V, C' = C + 3B, E_int' = E_int + B, V_int' = F,      */
/* S' = C, B' = 2B. On a regular quad grid with f = 1, S_3 is the tensor-product cubic     */
/* B-spline refinement (the face, edge and vertex points of Catmull-Clark).                */
/*                                                                                        */
/* Tags (section 3: "tag every point a parameter when k is odd and every face a parameter  */
/* when k is even"). tag_num holds one alpha numerator (over alpha_den) per input vertex   */
/* (odd k) or per input face (even k). Formula (3) on a face uses that face's alpha: its   */
/* tag (face tags) or the mean of its corners' tags (vertex tags). The kind of element      */
/* that carries tags alternates within a level: S_2 leaves face tags, each C swaps faces    */
/* and vertices (C is a duality), so a level ends with the kind it started with. Rule      */
/* (src/alpha_tags.c): an element descending from one tagged element inherits its alpha,  */
/* one descending from several takes their mean:                                           */
/*                                                                                        */
/*   step  tagged before  new element                 its alpha                           */
/*   ----  -------------  --------------------------  ----------------------------------- */
/*   S_2   faces          face-face of F              alpha(F)                            */
/*   S_2   faces          edge-face of edge (F1|F2)   mean(alpha(F1), alpha(F2))          */
/*   S_2   faces          vertex-face of v            mean over the faces around v        */
/*   S_2   vertices       face-face of F              mean over F's corners (= F's alpha) */
/*   S_2   vertices       edge-face of edge (a, b)    mean(alpha(a), alpha(b))            */
/*   S_2   vertices       vertex-face of v            alpha(v)                            */
/*   C     faces          vertex at F's centroid      alpha(F)                            */
/*   C     faces          midpoint of boundary edge   alpha(the edge's face)              */
/*   C     faces          kept boundary vertex v      mean over the faces around v        */
/*   C     vertices       face of v                   alpha(v)                            */
/*                                                                                        */
/* The mean of n tags is floor(sum / n) in whole units of 1/alpha_den turn (exact int64   */
/* sum; the curve rule's floor((a + b) / 2) is n = 2): integer arithmetic, so both builds  */
/* carry the same tags, and equal tags reproduce the untagged result bit for bit. Sums run */
/* in corner order and ring order. Why the tagged kind alternates instead of tracking face */
/* alphas throughout: a vertex tag (odd k) then reaches its vertex-face, whose centroid is */
/* that vertex's new point, unchanged at every level (figure 4(d)), and a face tag (even k */
/* >= 4) its own output face, instead of being averaged with its neighbours at every C.    */
/* Why numerators over the shared alpha_den and not a subd_real angle: the kernel takes    */
/* exact turns (a radian angle would be rounded by the division by 2 pi), and integer     */
/* means are the same on every target and arithmetic. A mean loses less than 1/alpha_den  */
/* turn: choose a fine den (e.g. 3600000, degrees with 4 decimals) for smooth gradations.  */
/* Locality: a tag changes only the points within the operator's support of its element.  */

typedef struct subd_alpha_surface_info {
    int32_t continuity;   /* -1 not smooth (s <= 0), 0 GC0 (s in (0, 1/2]), 1 GC1 (any k)  */
} subd_alpha_surface_info;

/* Note on theorem 2: the eigenvalues of a face's circulant matrix (lemma 1 on the paper's
 * Cir_N row, which is formula (3)) are 1 and f/(1+f) + f/(1+f)^2 cos(2 pi (j-1)/N); the
 * closed form printed in the paper's proof has 2f/(1+f)^2, a factor 2 too large (at f = 1,
 * N = 4 it would give 0 instead of Doo-Sabin's 1/4). The code follows formula (3).       */

/* subd_alpha_surface_plan: the exact arena bytes of subd_alpha_surface, in *bytes (the
 * peak: after the first step two consecutive steps' meshes, and with tags their tag
 * arrays, coexist while one is built).
 * Memory: no arena use.
 * Errors: SUBD_ERR_PARAM (NULL, options, |s| >= 2^31, a mesh without adjacency: twin,
 *   vert_out or corner_face NULL, e.g. subd_loop output without SUBD_LOOP_ADJACENCY),
 *   SUBD_ERR_DIVERGENT (s <= -1/2), SUBD_ERR_EMPTY (no faces), SUBD_ERR_FACE_SIZE (an
 *   interior vertex of valence > SUBD_MAX_FACE_SIZE would make a face that large),
 *   SUBD_ERR_TOO_BIG.
 * Cost: O(levels * k) after one O(corners) pass (the counts per step are closed forms). */
int subd_alpha_surface_plan(const subd_mesh *in, const subd_alpha_opts *o, uint32_t *bytes, subd_diag *diag);

/* subd_alpha_surface: opts->levels (1..SUBD_MAX_LEVELS) levels of S_k, k = opts->order in
 * 2..SUBD_ALPHA_MAX_ORDER, into *out.
 * Memory: exactly subd_alpha_surface_plan's bytes at the peak; after success the arena
 *   holds only *out's arrays. Stack about 450 bytes.
 * Cost: O(output corners) per level (with tags: plus one kernel evaluation per face whose
 *   alpha differs from the previous face's).
 * Notes: level n is a Doo-Sabin type step with f_n = f(alpha; n) followed by
 * k - 2 dual averaging steps. With tag_num, each face's alpha comes from the tags (above);
 * the tags of each step are one int32 per tagged element in the arena (the plan counts them,
 * two steps' at a time) and are given back at the end.
 * The input is not modified; the result's arrays are in the arena (the only memory left
 * in use after success). info (may be NULL) receives the continuity class (the S_2 class
 * for every order: the paper proves GC^(k-1) only away from extraordinary points).
 * Errors: in this order, SUBD_ERR_PARAM (NULL, options, |s| >= 2^31, a mesh without
 * adjacency), SUBD_ERR_DIVERGENT (s <= -1/2), SUBD_ERR_EMPTY, SUBD_ERR_NAN (diag.vertex),
 * SUBD_ERR_PARAM (a tag outside +-SUBD_ALPHA_MAX_NUM: diag.vertex for odd k, diag.face for
 * even k; the first one), SUBD_ERR_FACE_SIZE (diag.vertex), SUBD_ERR_TOO_BIG,
 * SUBD_ERR_NOMEM, then while running SUBD_ERR_PARAM (a level with f_n <= -1 on some
 * face; no element named) and SUBD_ERR_RANGE (a kernel value or a position overflows).
 * SUBD_ERR_NOMEM sets diag.bytes_needed = the plan. On every failure the arena is back at
 * its mark and *out is untouched. */
int subd_alpha_surface(subd_arena *arena, const subd_mesh *in, const subd_alpha_opts *o, subd_mesh *out,
                       subd_alpha_surface_info *info, subd_diag *diag);

#ifdef __cplusplus
}
#endif

#endif
