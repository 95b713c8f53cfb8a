/* SPDX-License-Identifier: MIT */
/* Semi-regular 4-8 refinement with four-direction (Zwart-Powell) box-spline smoothing and
 * variable-resolution extraction (L. Velho, "Semi-regular 4-8 refinement and box spline
 * surfaces", SIBGRAPI 2000). Included by subd.h. Each call's comment follows one template:
 * a summary, then Memory, Errors (every status), Cost and Notes.
 *
 * Three stages:
 *  1. Pre-processing (section 5): find_clusters picks an independent set of two-face
 *     clusters (interior edges only, by decreasing length, radially around each vertex, the
 *     same sort_edges / mark_cluster as quasi 4-8's Algorithm 1); hybrid subdivision splits
 *     each cluster's diagonal (new vertex: the cluster's face point) and each remaining
 *     isolated triangle barycentrically; one regular binary step then splits every original
 *     edge (new vertex: its edge point). The result, level 0 of the hierarchy, is a
 *     triangulated quadrangulation: every triangle is right-angled in the 4-8 sense and
 *     knows its base edge (the edge opposite its newest vertex).
 *  2. Regular 4-8 refinement (section 4) as `steps` binary steps, each splitting every base
 *     edge; two binary steps are one 4-8 refinement (faces x4). All levels are kept as an
 *     index-based hierarchy of right triangles (below), so variable-resolution meshes can be
 *     extracted without recomputing anything.
 *  3. Smoothing (section 6, unless SUBD_SR48_NO_SMOOTH): the factored ZP rule, see
 *     subd_sr48_build.
 *
 * Then subd_sr48_extract cuts a crack-free mesh out of the hierarchy: uniform at one level,
 * or with a resolution that follows an adaptation function (section 7), or the coarsest
 * mesh within a chordal tolerance of the finest level. */
#ifndef SUBD_SR48_H
#define SUBD_SR48_H

#include "subd.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Binary levels above level 0 one hierarchy can hold (two per 4-8 refinement). */
#define SUBD_SR48_MAX_STEPS (2u * SUBD_MAX_LEVELS)

/* subd_sr48_opts.flags */
#define SUBD_SR48_NO_SMOOTH 0x1u /* refinement only: new vertices are base-edge midpoints */

typedef struct subd_sr48_opts {
    uint32_t steps; /* binary steps after pre-processing, 0..SUBD_SR48_MAX_STEPS */
    uint32_t flags;
} subd_sr48_opts;

/* The hierarchy of right triangles. All arrays live in the arena.
 *
 * Triangles are stored level by level: level k (0..steps) holds the triangles
 * [level_tri[k], level_tri[k+1]). Parent and children are implicit in the index, so the
 * hierarchy costs 16 bytes per triangle:
 *   the i-th triangle of level k (t = level_tri[k] + i), k < steps, has the children
 *   level_tri[k+1] + 2i and level_tri[k+1] + 2i + 1; the parent of a level-k triangle t
 *   (k > 0) is level_tri[k-1] + (t - level_tri[k]) / 2.
 * tri_vert[3t..3t+2] = (apex, b0, b1), counter-clockwise in the input's orientation; the
 * base edge is b0 -> b1, the apex is the triangle's newest vertex. Splitting t = (c; a, b)
 * at the new vertex m on its base gives child 2i = (m; c, a) and child 2i+1 = (m; b, c):
 * a child's base is one of its parent's legs.
 * tri_base_nb[t] is the triangle across t's base edge: it is on the same level and has the
 * same base edge (t and it form a diamond and are always split together), or SUBD_NONE
 * when the base edge is on the boundary (a half-diamond).
 *
 * Vertices are never renumbered: the vertices existing at level k are [0, level_verts[k]);
 * the input's vertices come first (0..num_input_verts-1), then the pre-processing face
 * points, then its edge points, then each binary step's new vertices. Positions are those
 * of the finest level (`steps`): extraction at any level uses them, so every extracted
 * mesh interpolates the finest surface at its vertices. */
typedef struct subd_sr48 {
    uint32_t steps;
    uint32_t flags;
    uint32_t num_input_verts;
    uint32_t num_verts; /* = level_verts[steps]                                       */
    uint32_t num_tris;  /* = level_tri[steps + 1], all levels                        */
    subd_real *pos;     /* 3 * num_verts                                             */
    uint32_t *tri_vert; /* 3 * num_tris                                              */
    uint32_t *tri_base_nb;
    uint32_t level_verts[SUBD_SR48_MAX_STEPS + 1];
    uint32_t level_tri[SUBD_SR48_MAX_STEPS + 2];
    /* pre-processing report (section 5) */
    uint32_t num_clusters;     /* two-face clusters                                   */
    uint32_t num_isolated;     /* triangles split barycentrically                     */
    /* the base mesh only (subd_sr48_base; NULL from subd_sr48_build): per hybrid triangle H
     * (level -1, the parent of level-0 triangles 2H and 2H+1, level_tri[1] / 2 of them) the
     * hybrid triangle across its base edge (an input edge), or SUBD_NONE on the boundary.
     * It gives level 0's leg neighbours: triangle 2H has the sibling 2H+1 across leg 0 and
     * child 1 of hyb_base_nb[H] across leg 1; 2H+1 has child 0 of hyb_base_nb[H] across
     * leg 0 and the sibling across leg 1 (the rule of every later level). */
    uint32_t *hyb_base_nb;
    /* the base mesh only (0 from subd_sr48_build): the valence subd_sr48_stream sizes its
     * windows with - the largest valence (at least 8), or more where level-0 neighbourhoods
     * are denser than the windows of that valence hold (several extraordinary vertices
     * within two rings of each other, as in decimated scans). Pass it to
     * SUBD_SR48_STREAM_BYTES and its siblings for a static buffer. */
    uint32_t stream_valence;
} subd_sr48;

/* Cluster count argument of subd_sr48_plan when it is not known. */
#define SUBD_SR48_CLUSTERS_UNKNOWN 0xFFFFFFFFu

/* subd_sr48_plan: the arena bytes subd_sr48_build uses, in *bytes: exact with the cluster
 * count of subd_sr48_count_clusters (the build's peak equals it), an upper bound with
 * clusters = SUBD_SR48_CLUSTERS_UNKNOWN (no clusters: the largest level 0).
 * Memory: no arena use.
 * Errors: SUBD_ERR_PARAM (NULL, steps out of range, unknown flag bits, input without
 *   adjacency, clusters more than half the faces), SUBD_ERR_NOT_TRIANGLES (diag.face: a
 *   non-triangle), SUBD_ERR_EMPTY (no faces), SUBD_ERR_TOO_BIG. diag (may be NULL) gets the
 *   status (and face) as subd_sr48_build would; bytes_needed stays 0.
 * Cost: O(corners).
 * Notes: the pre-processed size depends on how many two-face clusters find_clusters picks
 * (level 0 has 8 triangles per cluster and 6 per isolated triangle), which needs the edge
 * sort. The bytes are: the output arrays (pos, tri_vert, tri_base_nb), plus the largest of find_clusters' edge
 * sort (33 bytes per edge + 12 per face + 1 KiB), the pre-processing arrays with the level-0
 * smoothing sums, and the smoothing sums of the largest later even level (per vertex 3 sums
 * and a count: 28 bytes in Q16.16, whose sums are exact 64-bit integers, 16 in float32; so
 * the two arithmetics have different plans). */
int subd_sr48_plan(const subd_mesh *in, const subd_sr48_opts *o, uint32_t clusters, uint32_t *bytes,
                   subd_diag *diag);

/* subd_sr48_count_clusters: the number of two-face clusters find_clusters picks for `in`
 * (section 5), in *clusters, for an exact subd_sr48_plan.
 * Memory: the edge sort (33 bytes per edge + 12 per face + 1 KiB) in the arena's free
 *   space, given back: the arena is unchanged afterwards.
 * Errors: SUBD_ERR_PARAM, SUBD_ERR_NOT_TRIANGLES, SUBD_ERR_EMPTY, SUBD_ERR_TOO_BIG (as
 *   subd_sr48_plan), SUBD_ERR_NOMEM (diag->bytes_needed: what the sort needs).
 * Cost: O(edges) (a radix sort of the edge lengths, then one pass). */
int subd_sr48_count_clusters(subd_arena *a, const subd_mesh *in, uint32_t *clusters, subd_diag *diag);

/* subd_sr48_build: pre-processes `in` and refines it `o->steps` binary steps into the
 * hierarchy *out.
 * Memory: exactly subd_sr48_plan(in, o, subd_sr48_count_clusters(in)) at the peak; *out's
 *   arrays stay in the arena.
 * Errors: those of subd_sr48_plan, SUBD_ERR_PARAM also when the input's summary counts
 *   (num_edges, num_boundary_edges) do not match its faces; SUBD_ERR_NOMEM (bytes_needed =
 *   the exact plan when the arena holds the cluster count's sort, otherwise the
 *   SUBD_SR48_CLUSTERS_UNKNOWN bound), SUBD_ERR_RANGE (float32: a position overflowed;
 *   Q16.16 averages cannot leave the range). On failure the arena is rewound and *out
 *   untouched.
 * Cost: O(corners * 2^steps) (each binary step doubles the triangles).
 * Notes: smoothing (the factored Zwart-Powell rule of section 6). The paper's "the values at new
 * grid points are the average of their two neighbours" is ambiguous on a 4-8 mesh (a new
 * vertex has four neighbours); the choice made here reproduces the ZP dual quad scheme
 * exactly on regular grids (test_sr48 checks it against an independent ZP):
 *  - pre-processing: a cluster's face point is the centroid of its four vertices, an
 *    isolated triangle's the barycentre, an edge point the edge's midpoint; then every
 *    interior input vertex and every face point moves to the average of its adjacent edge
 *    points, every boundary input vertex to the average of its two boundary edge points;
 *  - each binary step: the new vertex of a diamond is the average of the diamond's two
 *    apexes (the vertices opposite the split base edge); of a boundary half-diamond, the
 *    midpoint of the base edge;
 *  - after every second binary step, every older interior vertex moves to the average of
 *    its neighbours created by that step (the centroid of its new quad blocks), every older
 *    boundary vertex to the average of its two new boundary neighbours (the boundary
 *    converges to the quadratic B-spline, as the interior does to the ZP box spline).
 * On a regular grid the ZP control points are the valence-4 vertices after each double
 * step. With SUBD_SR48_NO_SMOOTH, face points are the midpoint of the cluster diagonal
 * (barycentre for isolated triangles), every new vertex is its base edge's midpoint and
 * nothing moves: the surface is the input polyhedron.
 * Q16.16: each average is one exact integer sum divided once, rounded to nearest.
 *
 * The build first counts the clusters in the free arena (as subd_sr48_count_clusters), then
 * allocates the output and runs find_clusters again above it. */
int subd_sr48_build(subd_arena *a, const subd_mesh *in, const subd_sr48_opts *o, subd_sr48 *out,
                    subd_diag *diag);

/* subd_sr48_base_plan: the arena bytes subd_sr48_base uses, in *bytes: subd_sr48_plan of
 * steps = 0 plus 4 bytes per hybrid triangle (level_tri[1] / 2) for hyb_base_nb, unless the
 * census of the level-0 windows (stream_valence: 12 bytes per base vertex and 4 per base
 * triangle, above the output) needs more; exact with subd_sr48_count_clusters' count, a
 * bound with SUBD_SR48_CLUSTERS_UNKNOWN.
 * Memory: no arena use.
 * Errors: as subd_sr48_plan (flags: SUBD_SR48_NO_SMOOTH or 0).
 * Cost: O(corners). */
int subd_sr48_base_plan(const subd_mesh *in, uint32_t flags, uint32_t clusters, uint32_t *bytes);

/* subd_sr48_base: the pre-processing alone (section 5): the level-0 hierarchy (as
 * subd_sr48_build with steps = 0, the level-0 smoothing applied unless
 * SUBD_SR48_NO_SMOOTH) with hyb_base_nb kept, the base mesh subd_sr48_stream refines. A
 * device can build it once (or load it) and keep only it: it is the size of the control
 * mesh (about 4 triangles per input triangle).
 * Memory: exactly subd_sr48_base_plan with the cluster count at the peak; *out's arrays stay
 *   in the arena.
 * Errors: those of subd_sr48_build.
 * Cost: O(corners) plus the edge sort, plus the census: O(triangles * window).
 * Notes: every field is as subd_sr48_build's with steps = 0; hyb_base_nb follows the arrays;
 * stream_valence is the census's (src/sr48_census.c). */
int subd_sr48_base(subd_arena *a, const subd_mesh *in, uint32_t flags, subd_sr48 *out, subd_diag *diag);

/* --------------------------------------------------------------------------------------
 * Variable-resolution extraction (section 7).
 * The extracted mesh is conforming: a diamond is split as a whole, and splitting a diamond
 * first splits the (at most two) coarser diamonds its triangles come from ("forced
 * splits", the restricted hierarchy), with an explicit stack in the arena. So edge
 * neighbours differ by at most one level and there are no T-junctions. */
typedef enum subd_sr48_adapt_mode {
    SUBD_SR48_ADAPT_UNIFORM = 0, /* every triangle at max_level                                  */
    /* POINT, RAMP, PLANE and CALLBACK are evaluated per diamond D of level k on its nested
       region B(D): the bounding box, over every level-k triangle sharing a vertex with D,
       of the level-0 mesh's piecewise-linear interpolant L (level-0 vertices at their
       finest positions, each later vertex at the midpoint of L at its base ends). A split
       child diamond's box lies in both parent diamonds' boxes and the predicates are
       monotone, so the cut needs no forced split and a top-down stream takes the same
       decisions. The adaptation box A (RAMP's range, POINT's default radius) is the box
       of the finest positions of the level-0 triangles' corners (= the box of L over the
       whole mesh): known before any refinement, so the stream has it too. */
    SUBD_SR48_ADAPT_POINT,       /* finest at `point`: split iff dist(point, B) < (max_level - k)
                               radius, i.e. level max_level - floor(d / radius)              */
    SUBD_SR48_ADAPT_RAMP,        /* level rising linearly along `axis` (0, 1, 2) from 0 at A's
                               minimum lo to max_level at A's maximum hi, evaluated at B's
                               largest coordinate x on that axis: level
                               floor(max_level (x - lo) / (hi - lo)), max_level if hi = lo   */
    SUBD_SR48_ADAPT_PLANE,       /* max_level where B touches the side (x - point).normal >= 0,
                               level 0 elsewhere (a step function)                            */
    SUBD_SR48_ADAPT_CALLBACK,    /* split iff fn(ctx, B's lo, B's hi) > k: fn returns the level it
                               wants for the region (see subd_sr48_adapt_fn)                      */
    SUBD_SR48_ADAPT_CHORD        /* split exactly the triangles whose chordal deviation exceeds eps */
} subd_sr48_adapt_mode;

/* CALLBACK's adaptation function: the level (0..max_level; more counts as max_level) wanted
 * for the region whose bounding box is lo[0..2] .. hi[0..2] (a diamond's nested region B, in
 * input units). Required: monotone (a box inside another never gets a higher level) and
 * pure (the same box, the same answer: both calls ask once per evaluated triangle, so twice
 * for a diamond of two triangles, in orders that differ). Then the cut has no forced split and
 * subd_sr48_extract and subd_sr48_stream give the same triangles. A callback that is not
 * monotone still gives a conforming cut from each call (extract: forced splits; stream: a
 * diamond is asked only once its parents split), but the two may differ.
 * Example (detail near a viewer at v, one level per r of distance): d = the distance from v
 * to the box (0 inside), return d < max_level r ? max_level - floor(d / r) : 0. */
typedef uint32_t (*subd_sr48_adapt_fn)(void *ctx, const subd_real *lo, const subd_real *hi);

typedef struct subd_sr48_adapt {
    subd_sr48_adapt_mode mode;
    uint32_t max_level;  /* 0..hierarchy steps                                             */
    subd_real point[3];  /* POINT, PLANE                                                   */
    subd_real normal[3]; /* PLANE (need not be unit length)                                */
    subd_real radius;    /* POINT: distance per level; 0 = A's diagonal / (2 max_level)   */
    uint32_t axis;       /* RAMP                                                           */
    subd_real eps;       /* CHORD: > 0, in input units                                     */
    subd_sr48_adapt_fn fn;    /* CALLBACK                                                       */
    void *ctx;
} subd_sr48_adapt;

/* What an extraction produced. */
typedef struct subd_sr48_adapt_report {
    uint32_t faces;         /* output triangles                                             */
    uint32_t uniform_faces; /* triangles of uniform level max_level (saved = the difference)  */
    uint32_t forced_splits; /* diamonds split only to keep the mesh conforming              */
    uint32_t level_faces[SUBD_SR48_MAX_STEPS + 1]; /* output triangles per level            */
} subd_sr48_adapt_report;

/* subd_sr48_extract_plan: the arena bytes subd_sr48_extract may use, in *bytes.
 * Memory: no arena use.
 * Errors: the parameter errors of subd_sr48_extract (SUBD_ERR_PARAM, SUBD_ERR_EMPTY,
 *   SUBD_ERR_TOO_BIG); diag (may be NULL) gets the status, bytes_needed stays 0.
 * Cost: O(levels).
 * Notes: exact for SUBD_SR48_ADAPT_UNIFORM (when every input
 * vertex is used by a face; unused input vertices are dropped, so the mesh is then smaller);
 * for the other modes the bound of the uniform max_level mesh (an adaptive mesh never has
 * more triangles or vertices) plus the marking memory (1 byte and 4 bytes per triangle of
 * levels < max_level, 80 bytes per level for CHORD). An adaptive extraction needs only the
 * bytes it uses: it fails with SUBD_ERR_NOMEM only when they are not free, and then
 * diag->bytes_needed is the exact need when the marking memory fit (else the plan). */
int subd_sr48_extract_plan(const subd_sr48 *h, const subd_sr48_adapt *ad, uint32_t *bytes, subd_diag *diag);

/* subd_sr48_extract: a conforming triangle mesh (validated, with adjacency) cut out of the
 * hierarchy, into *out; what was cut into *rep.
 * Memory: at most subd_sr48_extract_plan's bytes (UNIFORM: exactly); *out's arrays stay in
 *   the arena, the marking memory is given back.
 * Errors: SUBD_ERR_PARAM (see below), SUBD_ERR_EMPTY (no level-0 triangle),
 *   SUBD_ERR_TOO_BIG, SUBD_ERR_NOMEM (see subd_sr48_extract_plan). rep and diag may be NULL.
 *   On failure the arena is rewound and *out and *rep untouched.
 * Cost: see Work below.
 * Notes: a triangle t of level k is split when k < max_level and the adaptation function asks for
 * a level above k (CHORD: when its chordal deviation exceeds eps), or when a finer
 * neighbour needs it (forced). The result is the least such cut, so it does not depend on
 * evaluation order; each triangle that becomes part of the cut below max_level is
 * evaluated once (CALLBACK: one call each). forced_splits counts the split diamonds
 * neither of whose triangles asked for the split. Chordal deviation of t: the largest
 * distance between a vertex of level <= max_level (the finest level of this extraction:
 * max_level triangles are never split) inside t (or on its edges) and the point of t with
 * the same hierarchy (dyadic barycentric) parameter: an upper bound of the distance to t,
 * so every vertex of level <= max_level is within eps of the extracted mesh (Q16.16: the
 * deviation is rounded to Q16.16 before the comparison, so within eps + 2^-16). RAMP's
 * range and POINT's default radius use the adaptation box A (subd_sr48_adapt_mode: the level-0
 * triangles' corners). POINT, RAMP, PLANE and a monotone CALLBACK never force a split
 * (their regions are nested, see subd_sr48_adapt_mode), so their cut is exactly the diamonds
 * that ask; each evaluation walks the diamond's star at its level (about 4 valence
 * triangles, O(level) each).
 * Output vertices are the used hierarchy vertices in increasing index order; output faces
 * are the cut's triangles by level, then by hierarchy index, as (apex, b0, b1).
 * Work: UNIFORM O(triangles of levels <= max_level). The other modes: O(triangles visited:
 * level 0, the cut's triangles and their split ancestors, the coarser triangles forced
 * splits reach) plus, for CHORD, a walk of each evaluated triangle's subtree (stopping at
 * the first vertex beyond eps): at most O(faces of level max_level * max_level); plus
 * streaming passes of 1 byte per triangle of levels < max_level (clearing the marks) and a
 * few words per vertex of levels <= max_level (used flags, renumbering); RAMP and POINT's
 * default radius: O(level-0 triangles) for the adaptation box.
 * SUBD_ERR_PARAM: a NULL pointer; mode out of range; max_level > h->steps; RAMP
 * axis > 2; CHORD eps not > 0; CALLBACK fn NULL; POINT radius < 0; PLANE normal zero;
 * float: a non-finite point, normal, radius or eps; a hierarchy that breaks the index rules
 * above: UNIFORM on any triangle of levels 0..max_level, the other modes on a triangle the
 * extraction visits - each is checked before its indices are used, a damaged part the cut
 * never reaches goes unnoticed, and an arena too small for the marks gives SUBD_ERR_NOMEM
 * first. */
int subd_sr48_extract(subd_arena *a, const subd_sr48 *h, const subd_sr48_adapt *ad, subd_mesh *out,
                      subd_sr48_adapt_report *rep, subd_diag *diag);

/* --------------------------------------------------------------------------------------
 * Streaming (the common stream interface of subd.h, "Streams"). */

typedef struct subd_sr48_stream_opts {
    subd_sr48_adapt adapt; /* the cut; adapt.max_level is the finest level: binary steps above
                         level 0, whose positions every emitted vertex has                */
} subd_sr48_stream_opts;

/* Largest valence (triangles around a base vertex) the stream takes. */
#define SUBD_SR48_STREAM_MAX_VALENCE 64u

/* subd_sr48_stream_plan: the exact arena bytes subd_sr48_stream needs, in *bytes: a function
 * of adapt.max_level and the base's stream_valence only (SUBD_SR48_STREAM_BYTES: its largest
 * valence, at least 8, or more where the census of subd_sr48_base found denser level-0
 * neighbourhoods).
 * Memory: no arena use.
 * Errors: SUBD_ERR_PARAM (NULL, a base that is not subd_sr48_base's - steps != 0, no
 *   hyb_base_nb, broken indices -, max_level > SUBD_SR48_MAX_STEPS, the mode's parameters
 *   as subd_sr48_extract: CHORD's eps not > 0 or not finite), SUBD_ERR_EMPTY,
 *   SUBD_ERR_TOO_BIG (a valence or stream_valence above SUBD_SR48_STREAM_MAX_VALENCE).
 * Cost: O(corners * valence) (the base's rules are checked, its fans walked). */
int subd_sr48_stream_plan(const subd_sr48 *base, const subd_sr48_stream_opts *o, uint32_t *bytes, subd_diag *diag);

/* subd_sr48_stream_begin: the pull form (subd.h "Streams"): the stream's state into the
 * arena, then subd_stream_next_tris hands out the triangles of subd_sr48_extract(UNIFORM,
 * max_level) of subd_sr48_build(steps = max_level, the base's flags), in the same order,
 * corners (apex, b0, b1), positions bit for bit (both arithmetics, with and without
 * smoothing, open and closed meshes).
 * Memory: exactly subd_sr48_stream_plan's bytes, until the end (subd_stream_end). Stack
 *   (Cortex-M4F, gcc -O2 -fstack-usage): begin about 300 bytes; subd_stream_next_tris about
 *   640 (next 56 + step 248 + tile 40 + tile build 136 + refine and crop 160), uniform with
 *   checkpoints (max_level >= 11) about 680 (step + rebuild 136 + level 0's window 184 +
 *   fan walk 56), plus the caller's; the push form subd_sr48_stream about 820 (stream 120 +
 *   run 120 + step + tile + tile build + refine and crop; with checkpoints about 860) plus
 *   the sink's.
 * Errors: those of subd_sr48_stream_plan, SUBD_ERR_NOMEM (bytes_needed = the plan; nothing
 *   taken). Later, from subd_stream_next_tris: SUBD_ERR_RANGE (float32: a position
 *   overflowed, diag.face the level-0 triangle), SUBD_ERR_TOO_BIG (the window of a level
 *   overflowed: cannot happen within the valence the plan was made for).
 * Cost: uniform: per tile of 2^(m+1) triangles (m = SUBD_SR48_STREAM_TILE_LEVELS, default 7)
 *   m breadth-first refinements of its descendants plus a margin, each refined and cropped
 *   in one pass: the descendants' first ring and its partners, checked exact before the
 *   tile leaves, else the tile made again with two rings (never on the test shapes; on the
 *   icosahedron at 8 steps 1.5 refined parent triangles per output face, two rings 2.8,
 *   0.5.0: 4.2), the last level emitted without a window; adaptive modes: O(window) per
 *   internal batch of 2 triangles (one refinement of the level max_level-1 window, about
 *   60 triangles);
 *   O(window * valence) per level-0 triangle more (its window is gathered by fan walks).
 *   Measured (uniform, base + plan + stream): on spot 1.5-3.9 / 3.4-7.5 / 8.7-14.7 M faces/s
 *   at 2 / 4 / 6 steps, 1.2-1.5x / 1.9-3.1x / 6.0-7.1x the faces/s of a first
 *   subd_sr48_build + subd_sr48_extract in the same run, 0.29-0.34x / 0.5-0.7x / 1.8-2.0x of
 *   them run again in their touched arena (bench -s sr48stream); 585 instructions per
 *   triangle on the Cortex-M4F at 8 steps into a counting sink (897 with the demo's
 *   checksum sink), M3 Q16.16: 706 (1 021; before the window changes of 0.6.0 1 315 / 1 435
 *   with the checksum sink, before the smaller crops 1 914 / 2 167; 0.5.0: 2 526 / 2 868;
 *   make demo).
 * Adaptive modes (POINT, RAMP, PLANE, CALLBACK): the triangles of subd_sr48_extract(mode,
 *   max_level) of the same hierarchy, as a set (depth first per level-0 triangle, not the
 *   extraction's order), positions bit for bit and the same ids rule. Each diamond is
 *   decided once, top down, on the nested region of subd_sr48_adapt_mode (L's box over its star,
 *   which the window holds); L of the level-0 window comes from one descent per window
 *   vertex (refining and cropping towards it down to max_level), and a leaf of level
 *   k < max_level gets its corners' max_level positions by three such descents, so a cut
 *   costs O(window * max_level) per leaf and per level-0 window vertex on top of the
 *   uniform work of its split triangles. With max_level > SUBD_SR48_STREAM_CKPT_ the walk
 *   keeps the uniform walk's checkpoints (SUBD_SR48_STREAM_SLOTS_(max_level - 1) level
 *   windows) and rebuilds the levels between when it returns to them. RAMP and POINT's default radius first find the
 *   adaptation box A (subd_sr48_adapt_mode): the first subd_stream_next_tris call descends from
 *   one level-0 triangle at each base vertex (the lowest-index one of its fan), O(base
 *   vertices * window * max_level) once. CALLBACK: fn is called once per triangle of
 *   level < max_level that is in the cut or split (as subd_sr48_extract: level 0 and the
 *   children of split triangles). Plan: SUBD_SR48_STREAM_ADAPT_BYTES.
 * Chordal cuts (CHORD; src/sr48_chord.c has the criterion and its proof): a level-k diamond
 *   D splits iff a triangle d of S(D) has subd_sr48_extract's chordal deviation E(d) > eps;
 *   S(D) is D and the diamonds whose split forces D's (the way subd_sr48_extract's forced
 *   splits propagate) for SUBD_SR48_STREAM_CHORD_EXACT_ levels below D, then every
 *   triangle under the stars of the deepest of those diamonds. The criterion nests (a
 *   diamond that splits has parents that split), so it is decided top down with no forced
 *   split, and every vertex of level <= max_level lies within eps of the streamed mesh
 *   (Q16.16: eps + 2^-16, as subd_sr48_extract). It is not subd_sr48_extract(CHORD)'s cut
 *   but contains it: measured 1.000x its faces on the test shapes, 1.15x (eps 0.002) and
 *   1.08x (eps 5e-4) on spot at 6 steps. Each decision searches the subtrees under D's
 *   star that may hold a triangle of S(D) down to max_level: the last
 *   SUBD_SR48_STREAM_CHORD_TILE_ levels of each breadth first (a tile: one refinement of
 *   the root's descendants and their rings per level), coarser levels depth first with the
 *   windows of the deeper levels; each tile root's deviations (E > eps per node) and each
 *   diamond's answer are kept (exact: functions of the triangle), so a tile is mostly
 *   computed once for the decisions of its neighbours; a decision of level >= max_level -
 *   SUBD_SR48_STREAM_CHORD_TILE_ reads its star triangles' deviations from the tiles of
 *   their ancestors at that level (one tile per root for all the levels below it).
 *   The tiles and the descents crop each level to ring 1 of the descendants and the
 *   partners of their triangles (as the uniform tile), checked exact, else again with two
 *   rings. O(window * 2^SUBD_SR48_STREAM_CHORD_TILE_) per tile; measured: the icosahedron
 *   at 9 steps, eps 0.01, about 0.12 M Cortex-M4F instructions per output face (M3 Q16.16:
 *   0.144 M; make demo), and on the host 0.44-0.47x / 0.35-0.37x the output faces/s of
 *   subd_sr48_build + subd_sr48_extract(CHORD) on spot at 6 steps, eps 0.002 / 5e-4 (bench
 *   -s sr48chord, a same-run ratio under load): every finest vertex is computed about 1.4
 *   (icosahedron) to 2.3 (spot) times (a tile root's tile is remade when the memo of
 *   SUBD_SR48_STREAM_CHORD_MASKS_ roots lost it), and exactly (no a-priori bound), so the stream cannot be faster than the uniform
 *   stream of max_level (about 28 k M4F instructions per output face in this case).
 *   Plan: SUBD_SR48_STREAM_CHORD_BYTES.
 * Notes: triangle face = the level-0 triangle it lies in, level = max_level (adaptive: the
 * leaf's level). Ids: a level-0
 * vertex keeps its base index; the vertex created at level k >= 1 by the diamond whose
 * lower-index triangle is the i-th of level k-1 (i = its index minus level_tri[k-1]) gets
 * num_verts + level_tri[1] (2^(k-1) - 1) + i (num_verts, level_tri of the base): equal ids
 * have equal bits, and the ids are a bijection onto the extraction's vertices. */
int subd_sr48_stream_begin(subd_arena *a, const subd_sr48 *base, const subd_sr48_stream_opts *o, subd_stream *s,
                           subd_diag *diag);

/* subd_sr48_stream: the push form: subd_sr48_stream_begin, then every triangle to sink->tri
 * (subd_stream_run_tris).
 * Memory: as subd_sr48_stream_begin; the arena is back where it was afterwards.
 * Errors: those of subd_sr48_stream_begin, SUBD_ERR_PARAM (NULL sink), or the sink's
 *   non-zero value unchanged.
 * Cost: as subd_sr48_stream_begin. */
int subd_sr48_stream(subd_arena *a, const subd_sr48 *base, const subd_sr48_stream_opts *o, const subd_tri_sink *sink,
                     subd_diag *diag);

/* The plan at compile time, for a static buffer: L = adapt.max_level (0..SUBD_SR48_MAX_STEPS),
 * N = the base's stream_valence (subd_sr48_base; `subd sr48 --stream --stats` prints it: the
 * largest valence, triangles around a vertex, values below 8 counting as 8, or more on bases
 * whose extraordinary vertices lie within two rings of each other). A
 * uint32_t constant expression equal to subd_sr48_stream_plan. Example:
 *     static uint8_t buf[SUBD_SR48_STREAM_BYTES(8, 12)] __attribute__((aligned(8)));
 * The window of a level holds the triangles within SUBD_SR48_STREAM_RINGS_ vertex rings of the
 * current triangle's children: at most SUBD_SR48_STREAM_WT_(N) triangles and
 * SUBD_SR48_STREAM_WV_(N) vertices (measured: 56 and 40 on regular regions, 4N + 24 and
 * 3N + 16 around a vertex of valence N >= 8; the capacities add a margin, and a window that
 * would overflow stops the stream with SUBD_ERR_TOO_BIG). Blocks: the run state, the
 * overflow ring (2 triangles), the level windows (16 bytes per triangle, 17 per vertex;
 * uniform: SUBD_SR48_STREAM_SLOTS_(D) of them - checkpoints, below - and two tile windows,
 * see SUBD_SR48_STREAM_TILE_LEVELS; the adaptive modes: SUBD_SR48_STREAM_ADAPT_NW_(L), the
 * same checkpoints; CHORD: max(L, 1) and three more) and the refined window: twice the
 * triangles, WT + WV vertices), the smoothing sums (6 bytes per vertex of the larger parent
 * window, level or tile, in both arithmetics), counts (4) and the crop's and level 0's maps. */
#define SUBD_SR48_STREAM_RINGS_ 2u
#define SUBD_SR48_STREAM_N_(n) ((uint32_t)(n) < 8u ? 8u : (uint32_t)(n))
#define SUBD_SR48_STREAM_WT_(n) (6u * SUBD_SR48_STREAM_N_(n) + 16u)
#define SUBD_SR48_STREAM_WV_(n) (4u * SUBD_SR48_STREAM_N_(n) + 16u)
#define SUBD_SR48_SA_(x) (((uint32_t)(x) + (SUBD_ARENA_ALIGN - 1u)) & ~(uint32_t)(SUBD_ARENA_ALIGN - 1u))
#define SUBD_SR48_WIN_(t, v) \
    (SUBD_SR48_SA_(32u) + 2u * SUBD_SR48_SA_(6u * (t)) + SUBD_SR48_SA_(4u * (t)) + SUBD_SR48_SA_(12u * (v)) + \
     SUBD_SR48_SA_(4u * (v)) + SUBD_SR48_SA_(v))
#define SUBD_SR48_MAX_(a, b) ((uint32_t)(a) > (uint32_t)(b) ? (uint32_t)(a) : (uint32_t)(b))
/* Uniform tiles: the last SUBD_SR48_STREAM_TILE_LEVELS levels (fewer when max_level is
 * smaller) are refined breadth first: the tile windows hold the current triangle's
 * descendants with their rings, at most SUBD_SR48_STREAM_TT_(N, m) triangles and
 * SUBD_SR48_STREAM_TV_(N, m) vertices (m the tile's levels); the tile's windows alternate
 * between two such blocks (A and X), each refined and cropped in one pass. 7 levels (0.5.0:
 * 6 with X twice A): 0.76x the host instructions of 6 on the icosahedron at 8 steps
 * (callgrind), in less memory at every (L, N); 8 would be 0.61x but take about 12 KB more
 * (L = 8 or 16, every N). */
#ifndef SUBD_SR48_STREAM_TILE_LEVELS
#define SUBD_SR48_STREAM_TILE_LEVELS 7u
#endif
#define SUBD_SR48_STREAM_TM_(L) \
    ((uint32_t)(L) < SUBD_SR48_STREAM_TILE_LEVELS ? SUBD_SR48_MAX_(L, 1u) : SUBD_SR48_STREAM_TILE_LEVELS)
#define SUBD_SR48_STREAM_TT_(n, m) (SUBD_SR48_STREAM_WT_(n) + (1u << (m)) + (1u << ((m) - 1u)) + 16u)
#define SUBD_SR48_STREAM_TV_(n, m) (SUBD_SR48_STREAM_WV_(n) + (1u << ((m) - 1u)) + (1u << ((m) - 2u)) + 16u)
/* The plan of nl level windows of t triangles and v vertices, a tile window of at, av when
 * tile is 1, the refined window of twice max(t, at) triangles and its working arrays. */
#define SUBD_SR48_STREAM_G_(nl, t, v, tile, at, av) \
    (SUBD_SR48_SA_(SUBD_STREAM_STATE_BYTES) + SUBD_SR48_SA_(2u * (uint32_t)sizeof(subd_tri)) + \
     (uint32_t)(nl) * SUBD_SR48_WIN_(t, v) + (uint32_t)(tile) * SUBD_SR48_WIN_(at, av) + \
     SUBD_SR48_STREAM_X_(t, v, SUBD_SR48_MAX_(at, t), SUBD_SR48_MAX_(av, v) + SUBD_SR48_MAX_(at, t), \
                         SUBD_SR48_MAX_(av, v)))
#define SUBD_SR48_STREAM_X_(t, v, mt, xv, pv) (SUBD_SR48_WIN_(2u * (mt), xv) + SUBD_SR48_STREAM_S_(t, v, mt, xv, pv))
/* The working arrays: smoothing sums' high parts and counts (pv), the crop's distances,
 * maps (mt, xv) and level 0's window (t, v). */
#define SUBD_SR48_STREAM_S_(t, v, mt, xv, pv) \
    (SUBD_SR48_SA_(6u * (pv)) + SUBD_SR48_SA_(4u * (pv)) + SUBD_SR48_SA_(xv) + SUBD_SR48_SA_(2u * (mt)) + \
     SUBD_SR48_SA_(4u * (mt)) + SUBD_SR48_SA_(2u * (xv)) + SUBD_SR48_SA_(4u * (t)) + 2u * SUBD_SR48_SA_(4u * (v)))
/* Uniform with a tile: nl level windows and two tile windows (A, X) of at, av. */
#define SUBD_SR48_STREAM_UT_(nl, t, v, at, av) \
    (SUBD_SR48_SA_(SUBD_STREAM_STATE_BYTES) + SUBD_SR48_SA_(2u * (uint32_t)sizeof(subd_tri)) + \
     (uint32_t)(nl) * SUBD_SR48_WIN_(t, v) + 2u * SUBD_SR48_WIN_(at, av) + \
     SUBD_SR48_STREAM_S_(t, v, SUBD_SR48_MAX_(at, t), SUBD_SR48_MAX_(av, v) + SUBD_SR48_MAX_(at, t), \
                         SUBD_SR48_MAX_(av, v)))
/* Without tiles (the adaptive modes): SUBD_SR48_STREAM_ADAPT_NW_(L) level windows. */
#define SUBD_SR48_STREAM_DFS_BYTES_(L, N) \
    SUBD_SR48_STREAM_G_(SUBD_SR48_STREAM_ADAPT_NW_(L), SUBD_SR48_STREAM_WT_(N), SUBD_SR48_STREAM_WV_(N), 0u, \
                        SUBD_SR48_STREAM_WT_(N), SUBD_SR48_STREAM_WV_(N))
/* The levels the uniform walk's tile covers: m + 1 when L > m > 1 (the last level has no
 * window, sr48_tile.c), else m; the walk's level windows are those of levels 0..D,
 * D = L - that (the tile's root). */
#define SUBD_SR48_STREAM_TW_(L) \
    (SUBD_SR48_STREAM_TM_(L) > 1u && (uint32_t)(L) > SUBD_SR48_STREAM_TM_(L) ? SUBD_SR48_STREAM_TM_(L) + 1u \
                                                                          : SUBD_SR48_STREAM_TM_(L))
/* Uniform checkpoints: when SUBD_SR48_STREAM_CKPT_ levels or more lie above the tile's
 * root (levels 0..D), every CKPT_-th above 0 keeps its window and the ones between
 * and level 0 share CKPT_ - 1 windows, rebuilt from their checkpoint (level 0: from the base
 * mesh) when the walk returns to them: SUBD_SR48_STREAM_SLOTS_(D) level windows, plus 2
 * words per level and one per slot of walk state; otherwise one window per level. */
#define SUBD_SR48_STREAM_CKPT_ 3u
#define SUBD_SR48_STREAM_D_(L) ((uint32_t)(L) > SUBD_SR48_STREAM_TW_(L) ? (uint32_t)(L) - SUBD_SR48_STREAM_TW_(L) : 0u)
#define SUBD_SR48_STREAM_SLOTS_(d) \
    ((uint32_t)(d) >= SUBD_SR48_STREAM_CKPT_ ? (uint32_t)(d) / SUBD_SR48_STREAM_CKPT_ + SUBD_SR48_STREAM_CKPT_ - 1u \
                                          : (uint32_t)(d) + 1u)
#define SUBD_SR48_STREAM_BYTES(L, N) \
    ((SUBD_SR48_STREAM_D_(L) >= SUBD_SR48_STREAM_CKPT_ \
          ? SUBD_SR48_SA_(4u * (2u * ((uint32_t)(L) + 1u) + SUBD_SR48_STREAM_SLOTS_(SUBD_SR48_STREAM_D_(L)))) \
          : 0u) + \
     (SUBD_SR48_STREAM_TM_(L) > 1u \
          ? SUBD_SR48_STREAM_UT_(SUBD_SR48_STREAM_SLOTS_(SUBD_SR48_STREAM_D_(L)), SUBD_SR48_STREAM_WT_(N), \
                                 SUBD_SR48_STREAM_WV_(N), SUBD_SR48_STREAM_TT_(N, SUBD_SR48_STREAM_TM_(L)), \
                                 SUBD_SR48_STREAM_TV_(N, SUBD_SR48_STREAM_TM_(L))) \
          : SUBD_SR48_STREAM_G_(SUBD_SR48_STREAM_SLOTS_(SUBD_SR48_STREAM_D_(L)), SUBD_SR48_STREAM_WT_(N), \
                                SUBD_SR48_STREAM_WV_(N), 0u, SUBD_SR48_STREAM_WT_(N), SUBD_SR48_STREAM_WV_(N))))
/* The plan of the adaptive modes (POINT, RAMP, PLANE, CALLBACK): the walk's level windows
 * are those of levels 0..L - 1 (the children of a level L - 1 triangle come from the refined
 * window); with SUBD_SR48_STREAM_CKPT_ or more below level 0 (L > CKPT_), the uniform
 * checkpoints: SUBD_SR48_STREAM_SLOTS_(L - 1) windows and the walk state (2 words per level,
 * one per slot), the levels between rebuilt with their L and their decisions' state when the
 * walk returns (the descents to the finest level then keep their two windows in the refined
 * window's block); otherwise max(L, 1) windows. Plus L (3 subd_reals) per level window
 * vertex (not in the refined window: its triangles are emitted, positions only), and the
 * level-0 window's L, vertices, triangles (the adaptation box lives in the run state). */
#define SUBD_SR48_STREAM_ADAPT_NW_(L) \
    ((uint32_t)(L) > 0u ? SUBD_SR48_STREAM_SLOTS_((uint32_t)(L) - 1u) : 1u)
#define SUBD_SR48_STREAM_ADAPT_CKW_(L) \
    ((uint32_t)(L) > SUBD_SR48_STREAM_CKPT_ \
         ? SUBD_SR48_SA_(4u * (2u * ((uint32_t)(L) + 1u) + SUBD_SR48_STREAM_ADAPT_NW_(L))) \
         : 0u)
#define SUBD_SR48_STREAM_ADAPT_EXTRA_(L, t, v) \
    (SUBD_SR48_STREAM_ADAPT_NW_(L) * SUBD_SR48_SA_(12u * (v)) + SUBD_SR48_SA_(12u * (v)) + \
     2u * SUBD_SR48_SA_(4u * (v)))
#define SUBD_SR48_STREAM_ADAPT_BYTES(L, N) \
    (SUBD_SR48_STREAM_DFS_BYTES_(L, N) + \
     SUBD_SR48_STREAM_ADAPT_EXTRA_(L, SUBD_SR48_STREAM_WT_(N), SUBD_SR48_STREAM_WV_(N)) + \
     SUBD_SR48_STREAM_ADAPT_CKW_(L))
/* The plan of CHORD: the adaptive modes' level windows, three more for the tile window of the
 * memo's tiles (rooted max(L - SUBD_SR48_STREAM_CHORD_TILE_, 0) levels down, made while a
 * decision holds the windows of its path), and a refined window sized for the
 * tiles of SUBD_SR48_STREAM_CTM_(L) levels (twice SUBD_SR48_STREAM_TT_ triangles; the walk's
 * tile window lives in three level windows, free below the tile's root), plus the subtree
 * walk's state (per level: the node, its child state, its corners' sources and whether it
 * counts, 6 words; the star's keys, 2 words per window triangle), the decided diamond's
 * descendant diamonds of its first SUBD_SR48_STREAM_CHORD_EXACT_ levels below (at most
 * 2 * 4^j triangles j levels down, 3 words each, and a count per level; src/sr48_chord.c),
 * a cache of finest positions (SUBD_SR48_STREAM_CHORD_CACHE_ entries: an id, 2 words, and 3
 * subd_reals), the answers of SUBD_SR48_STREAM_CHORD_DECIDED_ diamonds (2 words each), the
 * deviation masks of SUBD_SR48_STREAM_CHORD_MASKS_ tile roots (5 words each, in sets of 16
 * kept in order of use, evicting roots of level-0 triangles already walked or far ahead
 * first: src/sr48_chord_tile.c; with 6-level tiles and sets of 2, 512 measured 0.83x the x86
 * instructions of the default 256 on the icosahedron at 9 steps, 226 M against 273 M, for
 * 5 120 bytes more), the walk's
 * finest positions (3 subd_reals per level + 4) and the tile's nodes (3 corners, 6 bytes,
 * and a flag per node of a tile of m levels: 2^(m + 1) nodes), interpolants (9 per level,
 * 8 bytes each) and a byte per vertex of its window; src/sr48_chord_walk.c. SUBD_SR48_STREAM_CHORD_TILE_ (1..6, default
 * 6: a tile's node masks are 64 bits): on the icosahedron at 9 steps (M4F instructions per
 * output face, plan at (9, 10)) 5 with 4-word masks and a 512-entry memo measured 1.96x the
 * instructions of 6 (994 712 against 506 766) for 3 176 bytes less (54 576 against 57 752;
 * 6 needs the third level window for its tile window); 4 measured 1.4x the instructions
 * of 5. */
#define SUBD_SR48_STREAM_CHORD_EXACT_ 3u
#define SUBD_SR48_STREAM_CHORD_DESC_ (2u * ((1u << (2u * (SUBD_SR48_STREAM_CHORD_EXACT_ + 1u))) - 1u) / 3u)
#ifndef SUBD_SR48_STREAM_CHORD_CACHE_
#define SUBD_SR48_STREAM_CHORD_CACHE_ 256u
#endif
#ifndef SUBD_SR48_STREAM_CHORD_DECIDED_
#define SUBD_SR48_STREAM_CHORD_DECIDED_ 64u
#endif
#ifndef SUBD_SR48_STREAM_CHORD_MASKS_
#define SUBD_SR48_STREAM_CHORD_MASKS_ 256u
#endif
#ifndef SUBD_SR48_STREAM_CHORD_TILE_
#define SUBD_SR48_STREAM_CHORD_TILE_ 6u
#endif
#define SUBD_SR48_STREAM_CTM_(L) \
    ((uint32_t)(L) < SUBD_SR48_STREAM_CHORD_TILE_ ? SUBD_SR48_MAX_(L, 2u) : SUBD_SR48_STREAM_CHORD_TILE_)
#define SUBD_SR48_STREAM_CHORD_BYTES(L, N) \
    (SUBD_SR48_STREAM_G_(SUBD_SR48_MAX_(L, 1u) + 3u, SUBD_SR48_STREAM_WT_(N), SUBD_SR48_STREAM_WV_(N), 0u, \
                         SUBD_SR48_STREAM_TT_(N, SUBD_SR48_STREAM_CTM_(L)), \
                         SUBD_SR48_STREAM_TV_(N, SUBD_SR48_STREAM_CTM_(L))) + \
     SUBD_SR48_SA_((12u << SUBD_SR48_STREAM_CTM_(L)) + (2u << SUBD_SR48_STREAM_CTM_(L)) + \
                   72u * (SUBD_SR48_STREAM_CTM_(L) + 1u) + \
                   SUBD_SR48_MAX_(SUBD_SR48_STREAM_TV_(N, SUBD_SR48_STREAM_CTM_(L)), SUBD_SR48_STREAM_WV_(N))) + \
     SUBD_SR48_SA_(4u * (6u * ((uint32_t)(L) + 1u) + 2u * SUBD_SR48_STREAM_WT_(N) + SUBD_SR48_STREAM_CHORD_EXACT_ + \
                         1u + 3u * SUBD_SR48_STREAM_CHORD_DESC_ + 2u * SUBD_SR48_STREAM_CHORD_CACHE_ + \
                         2u * SUBD_SR48_STREAM_CHORD_DECIDED_ + 5u * SUBD_SR48_STREAM_CHORD_MASKS_)) + \
     SUBD_SR48_SA_(12u * ((uint32_t)(L) + 4u + SUBD_SR48_STREAM_CHORD_CACHE_)))

/* The 0.3 names (subd_adapt*, SUBD_ADAPT_*; header subd_semireg48.h), kept as aliases
 * (deprecated, until 1.0): one name per scheme, sr48, across its header, types, calls, files
 * and tool command. */
#define subd_adapt subd_sr48_adapt
#define subd_adapt_fn subd_sr48_adapt_fn
#define subd_adapt_mode subd_sr48_adapt_mode
#define subd_adapt_report subd_sr48_adapt_report
#define SUBD_ADAPT_UNIFORM SUBD_SR48_ADAPT_UNIFORM
#define SUBD_ADAPT_POINT SUBD_SR48_ADAPT_POINT
#define SUBD_ADAPT_RAMP SUBD_SR48_ADAPT_RAMP
#define SUBD_ADAPT_PLANE SUBD_SR48_ADAPT_PLANE
#define SUBD_ADAPT_CALLBACK SUBD_SR48_ADAPT_CALLBACK
#define SUBD_ADAPT_CHORD SUBD_SR48_ADAPT_CHORD

#ifdef __cplusplus
}
#endif

#endif
