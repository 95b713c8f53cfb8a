/* SPDX-License-Identifier: MIT */
/* Quasi 4-8 subdivision (L. Velho, "Quasi 4-8 subdivision", Computer Aided Geometric
 * Design 18(4), 2001): geometry-sensitive
 * longest-edge binary refinement with edge-cluster marking (Algorithm 1) followed by the
 * two-pass convolution smoothing (Algorithm 2), with the section 4.3 feature control
 * (tagged vertices and edges are not affected by smoothing) and three boundary modes.
 * Included by subd.h. Each call's comment: a summary, Memory, Errors (every status), Cost,
 * Notes. */
#ifndef SUBD_QUASI48_H
#define SUBD_QUASI48_H

#include "subd.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Largest number of binary steps one call accepts. Two binary steps make one 4-8
 * refinement (face count x4, like one Loop level), hence twice SUBD_MAX_LEVELS. */
#define SUBD_QUASI48_MAX_STEPS (2u * SUBD_MAX_LEVELS)

/* What smoothing does with boundary vertices (refinement is the same in every mode). */
typedef enum subd_quasi48_boundary {
    /* Boundary vertices never move; new boundary vertices are edge midpoints, so the
     * boundary polygon keeps its shape (the paper's planar examples, figures 5-8). */
    SUBD_QUASI48_BOUNDARY_FIXED = 0,
    /* The 1-D analogue of Algorithm 2 along each boundary curve: new boundary vertices are
     * the midpoints of their two boundary neighbours (pass 1), an old boundary vertex becomes
     * 1/2 own + 1/2 the average of its new boundary neighbours (pass 2; with both neighbours
     * new that is the cubic B-spline vertex rule 3/4, 1/8, 1/8). */
    SUBD_QUASI48_BOUNDARY_SMOOTH = 1,
    /* Section 4.3: "boundary vertices are constrained to move along the surface normal
     * direction". An old boundary vertex p takes the interior rule's target t (1/2 p + 1/2
     * the average of all its new neighbours, both boundary ones included) and moves by the
     * normal component of t - p only: p + ((t - p) . n / n . n) n, with n the area-weighted
     * normal of p in the step's input (the sum over p's faces (p, b, c) of (b - p) x (c - p),
     * in the deterministic arithmetic: Q16.16 exact int64 products after a common shift).
     * n = 0 (the faces cancel or are degenerate) leaves p where it is. New boundary vertices
     * stay at the edge midpoint: the interior rule's displacement of a vertex on a boundary
     * edge lies in the plane of its one face, so its normal component is 0. A planar open
     * mesh in z = 0 therefore gives bit for bit the FIXED result; a rotation by 90 degrees
     * about z (x, y) -> (-y, x) maps the output bit for bit (Q16.16: any rotation that
     * permutes and negates axes). */
    SUBD_QUASI48_BOUNDARY_NORMAL = 2
} subd_quasi48_boundary;

/* subd_quasi48_opts.flags */
#define SUBD_QUASI48_NO_SMOOTH 0x1u /* refinement only (Algorithm 1 without Algorithm 2)      */

typedef struct subd_quasi48_opts {
    uint32_t steps;              /* binary steps, 1..SUBD_QUASI48_MAX_STEPS                    */
    subd_quasi48_boundary boundary;
    uint32_t flags;
    /* Length resolution of the edge sort: squared edge lengths are rounded to this many
     * significant bits (round to nearest) before they are compared, so edges whose lengths
     * differ only by the rounding of the arithmetic count as equal and go by the radial
     * tie-break (see subd_quasi48). 0 = SUBD_QUASI48_LEN_BITS_DEFAULT; 1..53 accepted; 53
     * (SUBD_QUASI48_LEN_BITS_EXACT) compares the squared lengths as computed (float32: the
     * float32 sum of the float32 squares of the coordinate differences, 24 bits; Q16.16:
     * the exact integer sum, exact for edges shorter than 1448 units, 53 bits beyond). */
    uint32_t len_bits;
} subd_quasi48_opts;

#define SUBD_QUASI48_LEN_BITS_DEFAULT 12u
#define SUBD_QUASI48_LEN_BITS_EXACT 53u

/* Upper bounds after `steps` binary steps of a triangle mesh with V vertices and F faces
 * (every split needs a face of its own, so one step adds at most F vertices and F faces):
 *   F_s <= 2^s F,   V_s <= V + (2^s - 1) F,   corners = 3 F_s. */
#define SUBD_QUASI48_MAX_FACES(F, s) ((F) << (s))
#define SUBD_QUASI48_MAX_VERTS(V, F, s) ((V) + (((F) << (s)) - (F)))

/* subd_quasi48_opts_default: 2 binary steps, SUBD_QUASI48_BOUNDARY_FIXED, smoothing on,
 * len_bits SUBD_QUASI48_LEN_BITS_DEFAULT.
 * Memory: none. Errors: none (NULL is ignored). Cost: O(1). */
void subd_quasi48_opts_default(subd_quasi48_opts *o);

/* subd_quasi48_plan: the arena bytes subd_quasi48 uses for this input and options, in
 * *bytes (a bound: see Notes; the run never exceeds it).
 * Memory: no arena use.
 * Errors: SUBD_ERR_PARAM (NULL, steps or len_bits out of range, unknown boundary mode or
 *   flag, input without adjacency), SUBD_ERR_NOT_TRIANGLES (diag.face: a non-triangle),
 *   SUBD_ERR_EMPTY (no faces), SUBD_ERR_TOO_BIG (the bound does not fit 32-bit sizes).
 * Cost: O(corners).
 * Notes: the number of splits of a step is only known after its marking pass, so the plan
 * is computed from the bounds above: the
 * output mesh arrays sized for step `steps`, one more set for step steps-1 (ping-pong
 * between steps; none when steps == 1) and the per-step working memory for the largest step
 * input (edge numbering, sort keys, marks, split vertices: 37 bytes per corner of step
 * steps-1, 1 KiB of radix counters, one tag byte per output vertex; the sort's order array
 * doubles as the map from parent to child half-edges). The child's adjacency is derived
 * from the parent's, so no builder scratch is needed; but the mesh allocator hands out a
 * mesh buffer only when the builder's scratch for it (4 bytes per vertex and per corner)
 * would fit above it, and the plan keeps that room when what follows the buffer is smaller
 * (only for inputs with many isolated vertices). Everything is allocated before the first
 * step, so the measured peak equals the plan except in that case. subd_quasi48 refuses to
 * start unless that many bytes are free, so the run can never exceed the plan. */
int subd_quasi48_plan(const subd_mesh *in, const subd_quasi48_opts *o, uint32_t *bytes, subd_diag *diag);

/* subd_quasi48: `steps` binary steps of quasi 4-8 subdivision of an all-triangle mesh,
 * into *out.
 * Memory: at most subd_quasi48_plan's bytes (all of it allocated before the first step);
 *   *out's arrays stay in the arena. Stack under 800 bytes, no recursion (see the end).
 * Cost: per step at most 8 radix passes over the edges and O(C) for the adjacency and the
 *   smoothing.
 * Notes: each step:
 *  1. Algorithm 1 (refinement). Edges are numbered "radially around each vertex": vertices
 *     in index order, and around each vertex its not yet numbered edges in one-ring order
 *     (starting at vert_out[v], the order of subd_ring_next; a boundary vertex's incoming
 *     boundary edge last). The edges are then sorted by decreasing squared length (rounded
 *     to opts.len_bits significant bits) with a stable radix sort, so equal lengths keep the
 *     radial numbering. Going down the sorted list, an edge that is not marked is split at
 *     its midpoint and its cluster (the edge and every edge of the faces containing it) is
 *     marked; so every face has at most one split edge. Every face with a split edge (a, b)
 *     and opposite vertex c becomes (a, m, c), kept at the face's index, and (m, b, c),
 *     appended in face order; faces without a split edge are copied unchanged.
 *  2. Algorithm 2 (smoothing, unless SUBD_QUASI48_NO_SMOOTH), in place: every new interior
 *     vertex becomes the average of its (four) neighbours; then every old vertex becomes 1/2
 *     its position + 1/2 the average of its k new neighbours (k = 0: unchanged). Section 4.3:
 *     vertices tagged SUBD_VTAG_CORNER or SUBD_VTAG_FIXED, both ends of every
 *     SUBD_ETAG_CREASE edge and (SUBD_QUASI48_BOUNDARY_FIXED) boundary vertices do not move; new
 *     vertices on crease and boundary edges stay at the edge midpoint; see
 *     subd_quasi48_boundary for the smoothing mode.
 * Vertex i of the input is vertex i of the output; a step's new vertices follow, in
 * split order (longest edge first). Crease tags pass to both halves of a split crease
 * edge; CORNER/FIXED tags stay with their vertices; polylines are copied. The output has
 * full adjacency (each step derives it from its input's; arrays, tags and counts are those
 * subd_mesh_build would build for the same faces) and its arrays lie in the arena.
 * The input is not modified.
 * Errors: those of subd_quasi48_plan, SUBD_ERR_NOMEM (diag.bytes_needed = the plan),
 * SUBD_ERR_RANGE (float32 overflow to infinity, in normal mode also of a normal's
 * products, coordinates beyond about 1e19; Q16.16 cannot overflow in the fixed and smooth
 * modes, every new position being a convex combination, but a normal projection can leave
 * the range: a component may move further than the displacement's). On failure the arena is back where it was and *out untouched.
 * Work per step: at most 8 radix passes over the edges, O(C) for the adjacency; no
 * recursion; stack under 800 bytes (subd_quasi48's own frame, with every step inlined:
 * 464 / 656 bytes on Cortex-M4F / M3 (the normal mode's 64-bit projection is inlined), plus
 * at most 88 in pass 2 or 72 in the edge sort). */
int subd_quasi48(subd_arena *a, const subd_mesh *in, const subd_quasi48_opts *o, subd_mesh *out,
                 subd_diag *d);

/* The 0.3 names (subd_q48_*, SUBD_Q48_*), kept as aliases (deprecated, until 1.0): one
 * name per scheme, quasi48, across its header, types, calls, file and tool command. */
#define subd_q48_opts subd_quasi48_opts
#define subd_q48_boundary subd_quasi48_boundary
#define SUBD_Q48_BOUNDARY_FIXED SUBD_QUASI48_BOUNDARY_FIXED
#define SUBD_Q48_BOUNDARY_NORMAL SUBD_QUASI48_BOUNDARY_NORMAL
#define SUBD_Q48_BOUNDARY_SMOOTH SUBD_QUASI48_BOUNDARY_SMOOTH
#define SUBD_Q48_NO_SMOOTH SUBD_QUASI48_NO_SMOOTH
#define SUBD_Q48_LEN_BITS_DEFAULT SUBD_QUASI48_LEN_BITS_DEFAULT
#define SUBD_Q48_LEN_BITS_EXACT SUBD_QUASI48_LEN_BITS_EXACT
#define SUBD_Q48_MAX_STEPS SUBD_QUASI48_MAX_STEPS
#define SUBD_Q48_MAX_FACES SUBD_QUASI48_MAX_FACES
#define SUBD_Q48_MAX_VERTS SUBD_QUASI48_MAX_VERTS

#ifdef __cplusplus
}
#endif

#endif
