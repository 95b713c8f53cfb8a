/* SPDX-License-Identifier: MIT */
/* Loop subdivision (C. Loop, "Smooth subdivision surfaces based on triangles", M.S. thesis,
 * University of Utah, 1987), materialised and streamed; Loop limit positions and normals; and
 * progressive interpolation (F. Cheng, F. Fan, S. Lai, C. Huang, J. Wang, J. Yong, "Loop
 * subdivision surface based progressive interpolation", Journal of Computer Science and
 * Technology 24(1), 2009). Included by subd.h.
 * Each call's comment follows one template: a summary, then Memory (arena and stack),
 * Errors (every status the call can return), Cost, and Notes. */
#ifndef SUBD_LOOP_H
#define SUBD_LOOP_H

#ifdef __cplusplus
extern "C" {
#endif

/* Boundary (and crease) rules, named after where they come from. */
typedef enum subd_loop_boundary {
    /* Paper, section 4: boundary vertex 3/4 v + 1/8 (c0 + c1); boundary edge midpoint when
     * both ends are regular or both extraordinary, else 5/8 regular + 3/8 extraordinary. */
    SUBD_LOOP_BOUNDARY_PAPER = 0,
    /* Midpoint on every boundary edge (a cubic B-spline boundary curve), as OpenSubdiv
     * and CGAL do. */
    SUBD_LOOP_BOUNDARY_BSPLINE = 1
} subd_loop_boundary;

/* subd_loop_opts.flags */
#define SUBD_LOOP_ADJACENCY 0x1u /* give the final level full adjacency (twin, vert_out, tags) */

typedef struct subd_loop_opts {
    uint32_t levels;             /* 1..SUBD_MAX_LEVELS                                   */
    subd_loop_boundary boundary;
    uint32_t flags;
} subd_loop_opts;

/* subd_loop_opts_default: one level, SUBD_LOOP_BOUNDARY_PAPER, no flags.
 * Memory: none. Errors: none (NULL is ignored). Cost: O(1). */
void subd_loop_opts_default(subd_loop_opts *o);

/* subd_loop_plan: the exact arena bytes subd_loop needs for this input and options, in
 * *bytes (subd_loop's peak arena use equals it).
 * Memory: no arena use; SUBD_LOOP_BYTES below gives the same number at compile time.
 * Errors: SUBD_ERR_PARAM (NULL pointer, levels outside 1..SUBD_MAX_LEVELS, unknown boundary
 *   rule or flag, a mesh without adjacency: twin and vert_out are needed, as the builder, the
 *   readers and subd_loop with SUBD_LOOP_ADJACENCY make them; a face_start that does not
 *   run from 0 to num_corners),
 *   SUBD_ERR_NOT_TRIANGLES (diag.face: the first face that is not a triangle),
 *   SUBD_ERR_TOO_BIG (the output does not fit 32-bit counts or the plan exceeds UINT32_MAX).
 * Cost: O(corners).
 * Notes: the intermediate levels live inside the output block (level L-1 where face_start
 *   and corner_face go, which are written last), so the plan is the output arrays alone
 *   unless isolated vertices dominate the mesh. */
int subd_loop_plan(const subd_mesh *in, const subd_loop_opts *o, uint32_t *bytes, subd_diag *diag);

/* The plan as a compile-time constant, for sizing a static buffer: subd_loop_plan of an
 * all-triangle mesh with V vertices (isolated ones included), F faces and E edges
 * (E = (3 F + boundary edges) / 2), L levels, flags 0 (SUBD_LOOP_BYTES) or
 * SUBD_LOOP_ADJACENCY (SUBD_LOOP_BYTES_ADJ); the boundary rule does not matter. A uint64_t
 * constant expression: equal to subd_loop_plan whenever that succeeds (values of
 * UINT32_MAX and more mean SUBD_ERR_TOO_BIG). Level k has F 4^k faces,
 * E 2^k + 3 F 2^k (2^k - 1) / 2 edges and V + E (2^k - 1) + F (2^k - 1)(2^k - 2) / 2
 * vertices; each array is rounded up to SUBD_ARENA_ALIGN. Example:
 *     static uint8_t buf[SUBD_LOOP_BYTES(12, 20, 30, 3)]; // icosahedron, 3 levels */
#define SUBD_LOOP_BYTES(V, F, E, L) SUBD_LOOP_BYTES_(V, F, E, L, 0u)
#define SUBD_LOOP_BYTES_ADJ(V, F, E, L) SUBD_LOOP_BYTES_(V, F, E, L, 1u)

/* helpers of SUBD_LOOP_BYTES (not API): the layout of src/loop.c, level by level */
#define SUBD_LOOP_AL_(x) (((uint64_t)(x) + (SUBD_ARENA_ALIGN - 1u)) & ~(uint64_t)(SUBD_ARENA_ALIGN - 1u))
#define SUBD_LOOP_MAX_(a, b) ((a) > (b) ? (a) : (b))
#define SUBD_LOOP_P2_(k) ((uint64_t)1 << (k))
#define SUBD_LOOP_NF_(F, k) ((uint64_t)(F) << (2u * (k)))
#define SUBD_LOOP_NE_(F, E, k) \
    (((uint64_t)(E) << (k)) + 3u * (uint64_t)(F) * (SUBD_LOOP_P2_(k) * (SUBD_LOOP_P2_(k) - 1u) / 2u))
#define SUBD_LOOP_NV_(V, F, E, k) \
    ((uint64_t)(V) + (uint64_t)(E) * (SUBD_LOOP_P2_(k) - 1u) + \
     (uint64_t)(F) * ((SUBD_LOOP_P2_(k) - 1u) * (SUBD_LOOP_P2_(k) - 2u) / 2u))
/* an intermediate level: pos, corners, twins, vert_out, vertex tags, valences, edge tags */
#define SUBD_LOOP_LEVEL_(nv, nf) \
    (SUBD_LOOP_AL_(12u * (nv)) + 2u * SUBD_LOOP_AL_(12u * (nf)) + SUBD_LOOP_AL_(4u * (nv)) + \
     2u * SUBD_LOOP_AL_(nv) + SUBD_LOOP_AL_(3u * (nf)))
#define SUBD_LOOP_LV_(V, F, E, k) SUBD_LOOP_LEVEL_(SUBD_LOOP_NV_(V, F, E, k), SUBD_LOOP_NF_(F, k))
/* output arrays written while level L is refined: pos, corners, tags (twins, vert_out) */
#define SUBD_LOOP_FRONT_(nv, nf, adj) \
    (SUBD_LOOP_AL_(12u * (nv)) + SUBD_LOOP_AL_(12u * (nf)) + SUBD_LOOP_AL_(nv) + SUBD_LOOP_AL_(3u * (nf)) + \
     ((adj) ? SUBD_LOOP_AL_(12u * (nf)) + SUBD_LOOP_AL_(4u * (nv)) : 0u))
/* ... then face_start and corner_face */
#define SUBD_LOOP_OUT_(nv, nf, adj) \
    (SUBD_LOOP_FRONT_(nv, nf, adj) + SUBD_LOOP_AL_(4u * ((nf) + 1u)) + SUBD_LOOP_AL_(12u * (nf)))
#define SUBD_LOOP_BYTES_(V, F, E, L, adj) \
    SUBD_LOOP_MAX_(SUBD_LOOP_OUT_(SUBD_LOOP_NV_(V, F, E, L), SUBD_LOOP_NF_(F, L), adj), \
                   (L) < 2u ? 0u : \
                   SUBD_LOOP_MAX_(SUBD_LOOP_FRONT_(SUBD_LOOP_NV_(V, F, E, L), SUBD_LOOP_NF_(F, L), adj), \
                                  (L) < 3u ? 0u : SUBD_LOOP_LV_(V, F, E, (L) < 3u ? 0u : (L) - 2u)) + \
                   SUBD_LOOP_LV_(V, F, E, (L) < 2u ? 0u : (L) - 1u))

/* subd_loop: `levels` steps of Loop subdivision (Loop's original weights) of an
 * all-triangle mesh, into *out.
 * Memory: exactly subd_loop_plan's bytes at the peak; after the call the arena holds only
 *   *out's arrays. Stack about 650 bytes (Cortex-M4, gcc -O2).
 * Errors: as subd_loop_plan (SUBD_ERR_PARAM, SUBD_ERR_NOT_TRIANGLES, SUBD_ERR_TOO_BIG), and
 *   SUBD_ERR_NOMEM (diag.bytes_needed = the plan), SUBD_ERR_RANGE (float32 only: a sum
 *   rounded to infinity near FLT_MAX; every rule is a convex combination whose Q16.16
 *   weights sum to exactly 1, so it cannot occur in Q16.16). On failure the arena is back
 *   where it was and *out is untouched.
 * Cost: O(4^levels * corners).
 * Notes: edges tagged SUBD_ETAG_CREASE follow the boundary rules; vertices tagged
 * SUBD_VTAG_CORNER (and vertices with three or more sharp edges, Hoppe et al. 1994) stay
 * where they are; isolated vertices are copied. Vertices keep their indices (vertex i of the
 * input is vertex i of the output), new vertices follow, one per edge in the order of the
 * edge's lower half-edge index. Face f's children are faces 4f..4f+3: (v_i, m_i, m_{i-1})
 * for i = 0, 1, 2 and (m0, m1, m2), with v_i face f's corners and m_i the new vertex on
 * edge v_i -> v_{i+1}. Child edges of crease/boundary edges keep their tags; CORNER and
 * FIXED vertex tags are kept (FIXED changes no rule); polylines are not carried over
 * (num_lines = 0). The input is not modified; *out's arrays are in the arena, and after the
 * call the arena holds only them. Without SUBD_LOOP_ADJACENCY the output has pos,
 * face_start, corner_vert, corner_face, vert_tag and edge_tag, and twin/vert_out are NULL;
 * with it the output equals subd_mesh_build of its own face list (plus the crease and
 * corner tags). Rules and classification: src/loop_rules.c; memory layout: src/loop.c. */
int subd_loop(subd_arena *a, const subd_mesh *in, const subd_loop_opts *o, subd_mesh *out, subd_diag *d);

/* ------------------------------------------------------------------------------------ */
/* Streaming Loop: any level in memory independent of the mesh and the output             */

/* The stream's triangles and sink are the common ones of subd.h ("Streams"): subd_tri
 * (for each corner, in subd_loop's corner order, its position, its global vertex id and,
 * with SUBD_LOOP_STREAM_LIMIT, its unit limit normal, else zeros; face: the control face;
 * level: o->levels) and subd_tri_sink. The names below are the 0.3 ones, kept as aliases
 * (deprecated, until 1.0). */
typedef subd_tri subd_loop_tri;
typedef subd_tri_sink subd_loop_sink;

/* subd_loop_opts.flags for the stream (SUBD_LOOP_ADJACENCY does not apply) */
#define SUBD_LOOP_STREAM_LIMIT 0x2u /* emit limit positions and unit limit normals */

/* subd_loop_stream_plan: the exact arena bytes subd_loop_stream and subd_loop_stream_begin
 * need, in *bytes: a function of the level count, the largest valence of the input (neighbours per vertex, at
 * least 6 is assumed) and the LIMIT flag only, never of the number of faces.
 * Memory: no arena use; SUBD_LOOP_STREAM_BYTES(_LIMIT) gives the same number at compile time.
 * Errors: SUBD_ERR_PARAM (as subd_loop_plan, and SUBD_LOOP_ADJACENCY, which does not apply
 *   to a stream), SUBD_ERR_NOT_TRIANGLES (diag.face), SUBD_ERR_TOO_BIG (a valence above
 *   SUBD_LOOP_STREAM_MAX_VALENCE).
 * Cost: O(corners). */
int subd_loop_stream_plan(const subd_mesh *in, const subd_loop_opts *o, uint32_t *bytes, subd_diag *diag);

/* Largest valence the stream takes (local indices are 16-bit). */
#define SUBD_LOOP_STREAM_MAX_VALENCE 2000u

/* subd_loop_stream: `levels` steps of Loop subdivision of `in`, exactly as subd_loop
 * computes them, handed to sink->tri one triangle at a time instead of stored.
 * Memory: exactly subd_loop_stream_plan's bytes at the peak, independent of the mesh: the
 *   run state (SUBD_STREAM_STATE_BYTES), the overflow ring of one batch (16 triangles; one
 *   level: 4; limit mode: 1; 104 bytes each), one control face's 1-ring per level,
 *   refined depth first (an explicit stack, no recursion), and from 2 levels on one regular
 *   tile of min(L, SUBD_LOOP_TILE_LEVELS) levels (limit mode: SUBD_LOOP_TILE_LEVELS_LIMIT;
 *   6.3 KB at 5; limit mode 7.2 KB at 5, its last level made by sixteenths, 3.6 KB at 4),
 *   sharing memory with the levels below the tile's, idle while it runs; next to an irregular vertex smaller tiles one level down, in the same
 *   memory), where regular patches are refined breadth first; nothing stays in it after the
 *   call. It is subd_loop_stream_begin + subd_stream_run_tris (subd.h "Streams"). Stack (Cortex-M, -fstack-usage,
 *   gcc -O2): about 1.3 KB on the deepest path (subd_loop_stream 504 bytes + the two-level
 *   emitter 704), 1.7 KB in limit mode (the limit masks), plus the sink's.
 * Errors: as subd_loop_stream_plan (SUBD_ERR_PARAM, SUBD_ERR_NOT_TRIANGLES,
 *   SUBD_ERR_TOO_BIG), and SUBD_ERR_NOMEM (diag.bytes_needed) before anything is emitted;
 *   SUBD_ERR_RANGE (float32: a position overflowed; diag.face the control face) before the
 *   triangle that holds it is emitted; or the sink's non-zero value unchanged (diag.face:
 *   the control face being streamed). The arena is always back where it was.
 * Cost: O(4^levels * faces), about a constant times subd_loop's.
 * Notes: emission order: control face by
 * control face; inside face f its 4^L triangles in subd_loop's order, so the j-th triangle
 * emitted is subd_loop's output face j, with the same corners in the same order.
 * Same surface: every position is bit-identical to the same vertex of subd_loop's level-L
 * mesh (both boundary rules, creases, corners, both arithmetics), so a vertex shared by
 * several triangles gets the same bits from each (no cracks).
 * Global vertex ids, closed form (N = 2^L, V, C = the input's vertex and corner counts):
 *   control vertex v:                              v
 *   inside the edge of lower half-edge h, at lattice position s = 1..N-1 counted from the
 *   end with the smaller vertex id:                V + h (N - 1) + s - 1
 *   inside face f at lattice point a v1 + b v2 (a, b >= 1, a + b <= N - 1, in units of
 *   1/N from corner v0 along the face's edges v0->v1 and v0->v2):
 *                                                  V + C (N - 1) + f (N - 1)(N - 2)/2
 *                                                    + (a - 1)(N - 1) - (a - 1) a / 2 + b - 1
 * Equal ids have equal bits. The ids are a bijection onto subd_loop's vertices that some face
 * uses, but not dense: an interior edge's upper half-edge h names no vertices, so
 * (C - E)(N - 1) ids are unused (a host that wants dense indices numbers edges itself).
 * With SUBD_LOOP_STREAM_LIMIT each corner is moved to its limit position and gets its unit
 * limit normal, as subd_loop_limit of subd_loop's level-L output. */
int subd_loop_stream(subd_arena *a, const subd_mesh *in, const subd_loop_opts *o, const subd_tri_sink *sink,
                     subd_diag *d);

/* subd_loop_stream_begin: the pull form of subd_loop_stream (subd.h "Streams"): checks
 * everything subd_loop_stream checks, puts the stream's state in the arena and fills *s;
 * then subd_stream_next_tris(s, buf, max) hands out the same triangles in the same order
 * with the same bits as the push form, in batches of the caller's size, and
 * subd_stream_end(s) (or the end of the stream, or a failure) gives the arena back.
 * Memory: subd_loop_stream_plan's bytes, taken here and kept until the end; the arena must
 *   not be used for anything else meanwhile.
 * Errors: those subd_loop_stream reports before it emits anything (SUBD_ERR_PARAM,
 *   SUBD_ERR_NOT_TRIANGLES, SUBD_ERR_TOO_BIG, SUBD_ERR_NOMEM with diag.bytes_needed); on
 *   failure the arena and *s are untouched. Later, subd_stream_next_tris returns
 *   SUBD_ERR_RANGE (s->diag.face: the control face) as subd_loop_stream would.
 * Cost: O(corners) here (the valence scan); each next call: its triangles plus at most one
 *   batch (one control face's walk down to the next emitting level: O(levels) patch
 *   extractions). */
int subd_loop_stream_begin(subd_arena *a, const subd_mesh *in, const subd_loop_opts *o, subd_stream *s,
                           subd_diag *diag);

/* The plan at compile time, for a static buffer: levels L (1..SUBD_MAX_LEVELS), largest
 * valence N; SUBD_LOOP_STREAM_BYTES_LIMIT for SUBD_LOOP_STREAM_LIMIT. A uint32_t constant
 * expression equal to subd_loop_stream_plan. Example:
 *     static uint8_t buf[SUBD_LOOP_STREAM_BYTES(6, 8)] __attribute__((aligned(8)));
 * Per level k <= L-2 (limit mode: k <= L-1; k = 0: the control face's 1-ring, corners of
 * valence up to N; k >= 1: at most one corner above valence 6): positions, flags, ring
 * starts, corners, twins, sharp bits and the refined values of the level (the last two
 * levels are emitted from level L-2's; plain mode from 3 levels: level L-2's block holds
 * level L-3's window, the four children's 1-rings in one patch, SUBD_LOOP_SWX_ more); limit
 * mode adds level L, a subd_mesh view of it and the limit masks' caches;
 * then the scratch of one extraction and (L >= 2) the regular tiles
 * (SUBD_LOOP_TILE_BYTES_, their tables SUBD_LOOP_TTAB_; SUBD_LOOP_TILE_LEVELS and _LIMIT in
 * subd_config.h): a tile of t levels at level L-t and, next to irregular vertices, smaller
 * ones at the levels below it down to L-2, each in its level's block and the deeper levels'
 * (SUBD_LOOP_TREG_): the larger of the two counts. */
#define SUBD_LOOP_STREAM_BYTES(L, N) SUBD_LOOP_STREAM_BYTES_(L, N, 0u)
#define SUBD_LOOP_STREAM_BYTES_LIMIT(L, N) SUBD_LOOP_STREAM_BYTES_(L, N, 1u)
#define SUBD_LOOP_SN_(N) ((uint32_t)(N) < 6u ? 6u : (uint32_t)(N))
#define SUBD_LOOP_SA_(x) (((uint32_t)(x) + (SUBD_ARENA_ALIGN - 1u)) & ~(uint32_t)(SUBD_ARENA_ALIGN - 1u))
/* faces, vertices, cached values of a level whose corner valences sum to at most S */
#define SUBD_LOOP_SF_(S) ((S) - 2u)
#define SUBD_LOOP_SV_(S) ((S) - 3u)
#define SUBD_LOOP_SC_(S) (S)
#define SUBD_LOOP_SLEV_(S, cache, ctl) \
    (SUBD_LOOP_SA_(3u * 4u * SUBD_LOOP_SV_(S)) + SUBD_LOOP_SA_(SUBD_LOOP_SV_(S)) + \
     SUBD_LOOP_SA_(2u * SUBD_LOOP_SV_(S)) + 3u * SUBD_LOOP_SA_(2u * 3u * SUBD_LOOP_SF_(S)) + \
     SUBD_LOOP_SA_(3u * SUBD_LOOP_SF_(S)) + \
     ((cache) ? SUBD_LOOP_SA_(3u * 4u * SUBD_LOOP_SC_(S)) + SUBD_LOOP_SA_(SUBD_LOOP_SC_(S)) : 0u) + \
     ((ctl) ? SUBD_LOOP_SA_(4u * SUBD_LOOP_SF_(S)) + SUBD_LOOP_SA_(4u * SUBD_LOOP_SV_(S)) : 0u))
#define SUBD_LOOP_SVIEW_(S) \
    (SUBD_LOOP_SA_(4u * (SUBD_LOOP_SF_(S) + 1u)) + 3u * SUBD_LOOP_SA_(12u * SUBD_LOOP_SF_(S)) + \
     SUBD_LOOP_SA_(4u * SUBD_LOOP_SV_(S)) + SUBD_LOOP_SA_(SUBD_LOOP_SV_(S)) + SUBD_LOOP_SA_(3u * SUBD_LOOP_SF_(S)))
#define SUBD_LOOP_SSCR_(S) (SUBD_LOOP_SA_(2u * SUBD_LOOP_SC_(S)) + SUBD_LOOP_SA_(2u * 4u * SUBD_LOOP_SF_(S)))
#define SUBD_LOOP_STREAM_BYTES_(L, N, lim) \
    (SUBD_STREAM_STATE_BYTES + SUBD_LOOP_SA_(((lim) ? 1u : (L) >= 2u ? 16u : 4u) * (uint32_t)sizeof(subd_tri)) + \
     SUBD_LOOP_SA_(4u * 12u * ((L) + 1u)) + SUBD_LOOP_SLEV_(3u * SUBD_LOOP_SN_(N), 1u, 1u) + \
     SUBD_LOOP_STK_(L, lim) * SUBD_LOOP_SLEV_(SUBD_LOOP_SN_(N) + 12u, 1u, 0u) + \
     (SUBD_LOOP_SDEEP_(L, N, lim) > SUBD_LOOP_TREG_(L, N, lim) ? SUBD_LOOP_SDEEP_(L, N, lim) : SUBD_LOOP_TREG_(L, N, lim)) + \
     SUBD_LOOP_TTAB_(SUBD_LOOP_TPD_(SUBD_LOOP_TD_(L, lim), lim)) + SUBD_LOOP_SSCR_(3u * SUBD_LOOP_SN_(N)) + ((lim) ? SUBD_LOOP_SMASK_ : 0u))
/* levels with a cache (1..L-2, limit mode 1..L-1); of them, those above the tile's level
 * tk = L-t (1..tk-1); the region from level max(tk, 1) on, which the tile's block shares: the
 * other cached levels and limit mode's level L with its mesh view */
#define SUBD_LOOP_SCACHED_(L, lim) ((lim) ? (L) - 1u : (L) >= 2u ? (L) - 2u : 0u)
#define SUBD_LOOP_STK_(L, lim) \
    (SUBD_LOOP_TD_(L, lim) ? ((L) > SUBD_LOOP_TD_(L, lim) ? (L) - SUBD_LOOP_TD_(L, lim) - 1u : 0u) : SUBD_LOOP_SCACHED_(L, lim))
#define SUBD_LOOP_SDEEP_(L, N, lim) \
    ((SUBD_LOOP_SCACHED_(L, lim) - SUBD_LOOP_STK_(L, lim)) * SUBD_LOOP_SLEV_(SUBD_LOOP_SN_(N) + 12u, 1u, 0u) + \
     ((lim) ? SUBD_LOOP_SLEV_(SUBD_LOOP_SN_(N) + 12u, 0u, 0u) + SUBD_LOOP_SVIEW_(SUBD_LOOP_SN_(N) + 12u) : 0u) + \
     SUBD_LOOP_SWX_(L, N, lim))
/* plain mode from 3 levels on: the window of level L-3's patch (corner valences up to 3N at
 * level 0, N + 12 below) at level L-2's block, by what it exceeds the block */
#define SUBD_LOOP_SWIN_(S) \
    (SUBD_LOOP_SA_(12u * (S)) + SUBD_LOOP_SA_(S) + SUBD_LOOP_SA_(2u * (S)) + 3u * SUBD_LOOP_SA_(6u * ((S) + 4u)) + \
     SUBD_LOOP_SA_(3u * ((S) + 4u)) + SUBD_LOOP_SA_(12u * ((S) + 24u)) + SUBD_LOOP_SA_((S) + 24u))
#define SUBD_LOOP_SWS_(L, N) ((uint32_t)(L) == 3u ? 3u * SUBD_LOOP_SN_(N) : SUBD_LOOP_SN_(N) + 12u)
#define SUBD_LOOP_SWX_(L, N, lim) \
    (!(lim) && (uint32_t)(L) >= 3u && SUBD_LOOP_SWIN_(SUBD_LOOP_SWS_(L, N)) > SUBD_LOOP_SLEV_(SUBD_LOOP_SN_(N) + 12u, 1u, 0u) \
         ? SUBD_LOOP_SWIN_(SUBD_LOOP_SWS_(L, N)) - SUBD_LOOP_SLEV_(SUBD_LOOP_SN_(N) + 12u, 1u, 0u) \
         : 0u)
/* limit mode's masks: the limit masks' per-valence caches and the valence-6 masks */
#define SUBD_LOOP_SMASK_ 352u
/* The regular tile (src/loop_tile.h) of t = SUBD_LOOP_TD_ levels (0: none): two grids of
 * sides 2^(t-1) + 3 and 2^(t-2) + 3 (positions, ring starts, rotations, lower sides; the
 * second's memory also holds a quarter of the last level, side 2^(t-1), as records of
 * position and id, 20 bytes each: a 16-byte record of the position and the id's low word,
 * the high words in an array after the records (src/loop_tile.h); limit mode: its positions with a one-vertex margin, side
 * 2^(t-1) + 3, and the records and normals of its limit points after it) and its emission
 * table. */
#define SUBD_LOOP_TCFG_(lim) ((lim) ? (uint32_t)SUBD_LOOP_TILE_LEVELS_LIMIT : (uint32_t)SUBD_LOOP_TILE_LEVELS)
#define SUBD_LOOP_TMIN_(L, lim) ((uint32_t)(L) < SUBD_LOOP_TCFG_(lim) ? (uint32_t)(L) : SUBD_LOOP_TCFG_(lim))
#define SUBD_LOOP_TD_(L, lim) (SUBD_LOOP_TMIN_(L, lim) < 2u ? 0u : SUBD_LOOP_TMIN_(L, lim))
#define SUBD_LOOP_TCNT_(s) (((s) + 1u) * ((s) + 2u) / 2u)
#define SUBD_LOOP_TC_(t) ((t) < 2u ? 2u : (t))
#define SUBD_LOOP_TNA_(t) SUBD_LOOP_TCNT_((1u << (SUBD_LOOP_TC_(t) - 1u)) + 3u)
#define SUBD_LOOP_TNB_(t) SUBD_LOOP_TCNT_((1u << (SUBD_LOOP_TC_(t) - 2u)) + 3u)
#define SUBD_LOOP_TQN_(t) SUBD_LOOP_TCNT_(1u << (SUBD_LOOP_TC_(t) - 1u))
#define SUBD_LOOP_TGB_(t) \
    (SUBD_LOOP_SA_(12u * SUBD_LOOP_TNB_(t)) + 2u * SUBD_LOOP_SA_(SUBD_LOOP_TNB_(t)) + SUBD_LOOP_SA_(2u * SUBD_LOOP_TNB_(t)))
#define SUBD_LOOP_TQU_(t, lim) ((lim) ? SUBD_LOOP_SA_(12u * SUBD_LOOP_TNA_(t)) : SUBD_LOOP_SA_(20u * SUBD_LOOP_TQN_(t)))
/* the depth whose quarter is a piece of the last level (loop_tile.h's lt_table_depth): the
 * tile's own, but limit mode's depth 5 makes its last level by the quarters' children */
#define SUBD_LOOP_TPD_(t, lim) ((lim) && (t) >= 5u ? (t) - 1u : (t))
#define SUBD_LOOP_TILE_BYTES_(t, lim) \
    ((t) ? SUBD_LOOP_SA_(12u * SUBD_LOOP_TNA_(t)) + 2u * SUBD_LOOP_SA_(SUBD_LOOP_TNA_(t)) + \
               SUBD_LOOP_SA_(2u * SUBD_LOOP_TNA_(t)) + \
               (SUBD_LOOP_TGB_(t) > SUBD_LOOP_TQU_(t, lim) ? SUBD_LOOP_TGB_(t) : SUBD_LOOP_TQU_(t, lim)) + \
               ((lim) ? SUBD_LOOP_SA_(20u * SUBD_LOOP_TQN_(SUBD_LOOP_TPD_(t, lim))) + \
                            SUBD_LOOP_SA_(12u * SUBD_LOOP_TQN_(SUBD_LOOP_TPD_(t, lim))) \
                      : 0u) \
         : 0u)
/* the tiles' emission tables, depths 2..t (their own block, filled once per stream; t:
 * SUBD_LOOP_TPD_ of the largest tile) */
#define SUBD_LOOP_TT1_(t, u) ((t) >= (u) ? SUBD_LOOP_SA_(3u << (2u * ((u) - 1u))) : 0u)
#define SUBD_LOOP_TTAB_(t) (SUBD_LOOP_TT1_(t, 2u) + SUBD_LOOP_TT1_(t, 3u) + SUBD_LOOP_TT1_(t, 4u) + SUBD_LOOP_TT1_(t, 5u))
/* The tiles' region: at level tk + j (tk = L - t, j = 0..t-2) a tile of depth t - j at
 * level tk + j's block, j level blocks (one fewer when tk = 0: level 0 has its own block)
 * after the region's start; the largest of them. */
#define SUBD_LOOP_TOFF_(L, lim, j) ((uint32_t)(L) > SUBD_LOOP_TD_(L, lim) ? (j) : (j) ? (j) - 1u : 0u)
#define SUBD_LOOP_TJ_(L, N, lim, j) \
    (SUBD_LOOP_TD_(L, lim) >= (j) + 2u \
         ? SUBD_LOOP_TOFF_(L, lim, j) * SUBD_LOOP_SLEV_(SUBD_LOOP_SN_(N) + 12u, 1u, 0u) + \
               SUBD_LOOP_TILE_BYTES_(SUBD_LOOP_TD_(L, lim) >= (j) + 2u ? SUBD_LOOP_TD_(L, lim) - (j) : 2u, lim) \
         : 0u)
#define SUBD_LOOP_TMAX_(a, b) ((a) > (b) ? (a) : (b))
#define SUBD_LOOP_TREG_(L, N, lim) \
    SUBD_LOOP_TMAX_(SUBD_LOOP_TMAX_(SUBD_LOOP_TJ_(L, N, lim, 0u), SUBD_LOOP_TJ_(L, N, lim, 1u)), \
                    SUBD_LOOP_TMAX_(SUBD_LOOP_TJ_(L, N, lim, 2u), SUBD_LOOP_TJ_(L, N, lim, 3u)))

/* ------------------------------------------------------------------------------------ */
/* Limit positions and normals                                                            */

/* Options of subd_loop_limit: the boundary rule set and SUBD_LOOP_LIMIT_NORMALS (unit limit
 * normals too). */
#define SUBD_LOOP_LIMIT_NORMALS 0x1u
typedef struct subd_loop_limit_opts {
    subd_loop_boundary boundary;
    uint32_t flags;
} subd_loop_limit_opts;

/* subd_loop_limit_opts_default: SUBD_LOOP_BOUNDARY_PAPER with normals.
 * Memory: none. Errors: none (NULL is ignored). Cost: O(1). */
void subd_loop_limit_opts_default(subd_loop_limit_opts *o);

/* subd_loop_limit_plan: the exact arena bytes of subd_loop_limit, in *bytes: 3 * num_verts
 * subd_reals for the positions and, with SUBD_LOOP_LIMIT_NORMALS, as many again for the
 * normals, each rounded up to SUBD_ARENA_ALIGN (no working memory); diag as the call fills it.
 * Memory: no arena use.
 * Errors: SUBD_ERR_PARAM (NULL pointer, unknown boundary rule or flag, a mesh without adjacency,
 *   vertex tag bits 0x40/0x80 set, which are reserved: diag.vertex), SUBD_ERR_NOT_TRIANGLES
 *   (diag.face), SUBD_ERR_TOO_BIG.
 * Cost: O(corners). */
int subd_loop_limit_plan(const subd_mesh *in, const subd_loop_limit_opts *o, uint32_t *bytes, subd_diag *diag);

/* subd_loop_limit: limit-surface positions of every control vertex (*pos, 3 * num_verts,
 * in the arena) and, with SUBD_LOOP_LIMIT_NORMALS, unit limit normals (*normals, 3 *
 * num_verts; a vertex where the tangents vanish gets (0, 0, 0); normals may be NULL without
 * the flag, SUBD_ERR_PARAM with it).
 * Memory: exactly subd_loop_limit_plan's bytes, which stay in the arena; stack about
 *   0.9 KB on Cortex-M4 (376 bytes + the normal's 480: masks of valences 2..17 are cached
 *   per call).
 * Errors: as subd_loop_limit_plan (SUBD_ERR_PARAM, SUBD_ERR_NOT_TRIANGLES, SUBD_ERR_TOO_BIG),
 *   and SUBD_ERR_NOMEM (diag.bytes_needed), SUBD_ERR_RANGE (float32: a position rounded to
 *   infinity). On failure the arena is back where it was and *pos, *normals are untouched.
 * Cost: O(corners).
 * Notes: interior vertices use the progressive-interpolation paper's formula (3); boundary
 *   vertices the rule set b; creases follow the boundary rules; corners and isolated vertices
 *   stay. */
int subd_loop_limit(subd_arena *a, const subd_mesh *in, const subd_loop_limit_opts *o, subd_real **pos,
                    subd_real **normals, subd_diag *d);

/* ------------------------------------------------------------------------------------ */
/* Progressive interpolation (paper, sections 2-4)                                        */

typedef enum subd_pia_method {
    SUBD_PIA_PAPER = 0, /* V <- V + (P - L V), boundary first then interior (the paper)   */
    SUBD_PIA_FAST = 1   /* an accelerated iteration; see src/pia_fast.c for why it converges */
} subd_pia_method;

typedef struct subd_pia_opts {
    subd_loop_boundary boundary;
    subd_real tol;       /* stop when max |P - L V| <= tol (input units)                  */
    uint32_t max_iter;   /* stop after this many iterations (>= 1)                        */
    subd_pia_method method;
} subd_pia_opts;

/* One phase of the paper's sequencing (section 4): the boundary vertices (tagged
 * SUBD_VTAG_BOUNDARY) first, then the interior (every other vertex) with the boundary fixed.
 * iterations: the iterations spent in the phase (PAPER: phase 1 and phase 2; FAST: the curve
 * phase, boundary and crease vertices, counts as the boundary phase of an open mesh, the
 * smooth phase and the final polish as interior; with darts FAST runs one phase over all
 * vertices, counted as interior). boundary.iterations + interior.iterations = iterations
 * (interior is the difference, so a preconditioned half iteration is counted once). A
 * closed mesh has an empty boundary phase: 0 iterations, 0 vertices, errors 0. verts: the
 * vertices of the set; max_err and mean_err: over the set, at the end of the call (a
 * boundary vertex's limit depends only on boundary vertices, so PAPER's boundary errors are
 * those phase 1 ended with). */
typedef struct subd_pia_phase {
    uint32_t iterations;
    uint32_t verts;
    subd_real max_err;
    subd_real mean_err;
} subd_pia_phase;

typedef struct subd_pia_result {
    uint32_t iterations;
    subd_real max_err;   /* max over vertices of |P - L V| (Euclidean) at the end         */
    subd_real mean_err;  /* mean of the same                                              */
    int converged;       /* 1 when max_err <= tol                                        */
    subd_pia_phase boundary, interior; /* the paper's two phases (subd_pia_phase)        */
} subd_pia_result;

/* subd_pia_opts_default: SUBD_LOOP_BOUNDARY_PAPER, tol two Q16.16 LSB (2^-15, the
 * smallest tolerance both arithmetics resolve), at most 100 iterations, SUBD_PIA_PAPER.
 * Memory: none. Errors: none (NULL is ignored). Cost: O(1). */
void subd_pia_opts_default(subd_pia_opts *o);

/* subd_pia_plan: the exact arena bytes of subd_pia for this input and options, in *bytes:
 * PAPER 2 arrays of 3 * num_verts subd_reals (V, L V); FAST 6 such arrays (V, L V, search
 * direction, L of it, two for the preconditioner) plus two subd_reals and one byte per
 * vertex, each rounded up to SUBD_ARENA_ALIGN.
 * Memory: no arena use.
 * Errors: validates like subd_pia: SUBD_ERR_PARAM, SUBD_ERR_NOT_TRIANGLES, SUBD_ERR_TOO_BIG.
 * Cost: O(corners). */
int subd_pia_plan(const subd_mesh *in, const subd_pia_opts *o, uint32_t *bytes, subd_diag *diag);

/* subd_pia: control positions V (*pos, 3 * num_verts, in the arena) whose Loop limit
 * surface passes through the input mesh's vertices P within tol, and how it went (*result).
 * Memory: exactly subd_pia_plan's bytes at the peak; on success only V stays in the arena.
 *   Stack under 700 bytes on Cortex-M (688 on the deepest path, M3).
 * Cost: per iteration one application of L, O(corners); the number of iterations depends
 *   on the mesh and tol (PAPER 10 / 18 on spot / the open bunny at 1e-4 of the diagonal,
 *   FAST 3 / 6: `make bench`).
 * Notes: within tol means max over vertices of the Euclidean distance |P_i - (L V)_i| <= tol,
 * L being subd_loop_limit's operator with rule o->boundary (creases and corners of the input
 * honoured). The input needs full adjacency (twin, vert_out) and
 * triangles only. PAPER starts from V = P and repeats V += P - L V, on the boundary vertices
 * until they are within tol, then on the rest with the boundary fixed (paper, sections 2
 * and 4). FAST (conjugate gradients, symmetric Gauss-Seidel preconditioned unless every
 * vertex of a phase has the same valence and rule, or Chebyshev iteration when a crease ends
 * inside the surface; see src/pia_fast.c for the convergence argument) reaches the same tol in
 * fewer iterations. An iteration is one update of V costing one application of L (a
 * preconditioned FAST step costs and counts 1.5; the total is rounded up);
 * result->iterations counts them over all phases and never exceeds max_iter; max_err and mean_err are over
 * all vertices (corners and isolated vertices stay where they are, error 0). A phase whose
 * error stops decreasing for 10 iterations (the arithmetic's rounding floor) ends early.
 * Not converging within max_iter is not an error: result->converged says so.
 * tol: float32 any positive finite value; Q16.16 at least 2 LSB (2^-15): L's rounding floor
 * is about 1 LSB per coordinate, sqrt(3) LSB in norm.
 * Errors: SUBD_ERR_PARAM (NULL pointer, mesh without adjacency, bad boundary or method,
 * max_iter == 0, tol not positive, NaN/inf or below the Q16.16 minimum), SUBD_ERR_NOT_TRIANGLES
 * (diag.face: the first non-triangle), SUBD_ERR_TOO_BIG, SUBD_ERR_NOMEM (diag.bytes_needed),
 * SUBD_ERR_RANGE (a control point or error leaves the Q16.16 range, or is not finite in
 * float32). On failure the arena is back where it was and *pos and *result are untouched;
 * on success only V stays in the arena. */
int subd_pia(subd_arena *a, const subd_mesh *in, const subd_pia_opts *o, subd_real **pos,
             subd_pia_result *result, subd_diag *d);

#ifdef __cplusplus
}
#endif

#endif
