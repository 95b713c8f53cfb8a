/* SPDX-License-Identifier: MIT */
/* tinysubd — subdivision surfaces and curves for devices without a heap.
 *
 * Everything the library needs comes from a caller-owned arena (a byte buffer, usually a
 * static array). Every operation has a planning call that returns the exact number of arena
 * bytes it will use, so the buffer can be sized before any work is done. Every call either
 * succeeds or returns a negative status with the arena and all inputs exactly as they were.
 *
 * Arena contents are 32-bit indices, subd_reals and tag bytes only: the bytes an operation
 * needs are the same on a 64-bit PC and a 32-bit device, and for float32 and Q16.16.
 */
#ifndef SUBD_H
#define SUBD_H

#include <stdint.h>
#include "subd_config.h"
#include "subd_real.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Version (semantic versioning; CHANGELOG.md). Before 1.0 a minor release may change the API
 * and the arena layout (plans may grow or shrink) and golden output only where the changelog
 * says so; a patch release changes neither API, plans nor output bits. From 1.0 on, output
 * bits and plans change only in a major release. */
#define SUBD_VERSION_MAJOR 0
#define SUBD_VERSION_MINOR 5
#define SUBD_VERSION_PATCH 0
#define SUBD_VERSION_NUMBER (SUBD_VERSION_MAJOR * 10000 + SUBD_VERSION_MINOR * 100 + SUBD_VERSION_PATCH)
#define SUBD_VERSION "0.5.0"

/* subd_version: SUBD_VERSION_NUMBER of the library linked (compare with the header's to
 * catch a mismatch). Memory: none. Errors: none. Cost: O(1). */
uint32_t subd_version(void);

/* ------------------------------------------------------------------------------------ */
/* Status codes. 0 is success; every error is negative and specific.                     */

typedef enum subd_status {
    SUBD_OK = 0,
    SUBD_ERR_NOMEM = -1,          /* arena too small: diag.bytes_needed says how much     */
    SUBD_ERR_PARAM = -2,          /* invalid argument (NULL pointer, bad option value)    */
    SUBD_ERR_PARSE = -3,          /* text is not in the format (diag.line)                */
    SUBD_ERR_NAN = -4,            /* a coordinate is NaN or infinite                      */
    SUBD_ERR_RANGE = -5,          /* a value does not fit subd_real (or overflowed)       */
    SUBD_ERR_INDEX = -6,          /* a vertex index is out of range (or 0 in OBJ)         */
    SUBD_ERR_FACE_SIZE = -7,      /* a face has < 3 or > SUBD_MAX_FACE_SIZE corners       */
    SUBD_ERR_DEGENERATE = -8,     /* a face uses the same vertex twice                    */
    SUBD_ERR_NONMANIFOLD_EDGE = -9,   /* an edge is shared by more than two faces         */
    SUBD_ERR_ORIENTATION = -10,   /* two faces traverse a shared edge in the same direction */
    SUBD_ERR_NONMANIFOLD_VERTEX = -11, /* a vertex's faces form more than one fan (bow-tie) */
    SUBD_ERR_TOO_BIG = -12,       /* counts whose sizes do not fit 32-bit arithmetic       */
    SUBD_ERR_EMPTY = -13,         /* the input has no vertices or no faces where needed   */
    SUBD_ERR_NOT_TRIANGLES = -14, /* a triangle-only scheme got a polygon (diag.face: the first) */
    SUBD_ERR_ARITH = -15,         /* subd_selfcheck: float arithmetic is not the reference's  */
    SUBD_ERR_DIVERGENT = -16      /* a parameter for which the scheme diverges (alpha: a
                                   * stiffness s <= -1/2, theorem 1)                       */
} subd_status;
/* The most negative status (every status is in SUBD_STATUS_LOWEST..0); moves with the enum. */
#define SUBD_STATUS_LOWEST SUBD_ERR_DIVERGENT

/* subd_status_str: a short, constant English description of a status ("non-manifold
 * edge"); "unknown status" for a value outside SUBD_STATUS_LOWEST..0 and positive values.
 * Memory: none (static strings). Errors: none. Cost: O(1). */
const char *subd_status_str(int status);

/* subd_selfcheck: run-time check that this build, on this machine, computes the arithmetic
 * every other build computes, so its output is bit-identical to the host's; for firmware to
 * call at start-up (src/selfcheck.c).
 * Memory: no arena, no state; a few words of stack.
 * Errors: SUBD_ERR_ARITH (the arithmetic differs; the library's output would not be the
 *   host's bits). Otherwise SUBD_OK.
 * Cost: a few dozen arithmetic operations.
 * Notes: float32: every product rounded before it is added (no fused multiply-add
 * from contraction, which the library's sources turn off whatever the compiler flags, see
 * src/fp_contract.h; no excess precision), round to nearest with ties to even (the FPU's
 * rounding mode), subnormals kept (no flush-to-zero, e.g. FPSCR.FZ on Cortex-M). Q16.16:
 * products round ties towards +infinity, >> on negative values is arithmetic. */
int subd_selfcheck(void);

/* Diagnostics filled by every call that can fail. Fields that do not apply are 0 or
 * SUBD_NONE. line is 1-based and set by the text readers; face/vertex name the offending
 * element (0-based) for validation errors; bytes_needed is set on SUBD_ERR_NOMEM. */
typedef struct subd_diag {
    int32_t status;
    uint32_t line;
    uint32_t face;
    uint32_t vertex;
    uint32_t polyline;
    uint32_t bytes_needed;
} subd_diag;

/* subd_diag_clear: sets every field to "not applicable" (status SUBD_OK, elements
 * SUBD_NONE, line 0). Every call that takes a diag clears it itself first.
 * Memory: none. Errors: none (d must not be NULL). Cost: O(1). */
void subd_diag_clear(subd_diag *d);

#define SUBD_NONE 0xffffffffu

/* ------------------------------------------------------------------------------------ */
/* Arena: a bump allocator over a caller buffer.                                          */

typedef struct subd_arena {
    uint8_t *base;
    uint32_t size;
    uint32_t used;
    uint32_t peak;
} subd_arena;

/* subd_arena_init: uses buf[0..size) as the arena (used = peak = 0). If buf is not aligned
 * to SUBD_ARENA_ALIGN the first bytes are skipped (declare the buffer with that alignment to
 * use all of it).
 * Memory: the caller's buffer; the library never allocates otherwise.
 * Errors: none (a NULL buf or a size below the alignment gives an empty arena).
 * Cost: O(1). */
void subd_arena_init(subd_arena *a, void *buf, uint32_t size);
/* subd_arena_alloc: `bytes` bytes (rounded up to SUBD_ARENA_ALIGN) aligned to
 * SUBD_ARENA_ALIGN, not cleared.
 * Memory: the rounded bytes of the arena; the peak follows.
 * Errors: NULL when the arena is too small (a failed call changes nothing).
 * Cost: O(1). */
void *subd_arena_alloc(subd_arena *a, uint32_t bytes);
/* subd_arena_mark, subd_arena_rewind: the current position; rewinding to a mark frees
 * everything allocated after it (a mark beyond the current position is ignored).
 * Memory: none. Errors: none. Cost: O(1). */
uint32_t subd_arena_mark(const subd_arena *a);
void subd_arena_rewind(subd_arena *a, uint32_t mark);
/* subd_arena_free_bytes: bytes still free.
 * Memory: none. Errors: none. Cost: O(1). */
uint32_t subd_arena_free_bytes(const subd_arena *a);
/* subd_arena_reset_peak: starts a new peak measurement at the current position (peak =
 * used), so the peak of the next call can be compared with its plan.
 * Memory: none. Errors: none. Cost: O(1). */
void subd_arena_reset_peak(subd_arena *a);

/* subd_size_add: size arithmetic that cannot wrap: count * elem_bytes rounded up to
 * SUBD_ARENA_ALIGN, added to *total. Any overflow of 32 bits sets *total to UINT32_MAX and
 * it stays there (sticky), which the plans report as SUBD_ERR_TOO_BIG.
 * Memory: none. Errors: none (overflow is the sticky UINT32_MAX). Cost: O(1). */
void subd_size_add(uint32_t *total, uint32_t count, uint32_t elem_bytes);

/* ------------------------------------------------------------------------------------ */
/* Mesh: index-based, arrays in the arena, descriptor owned by the caller.                */
/*                                                                                        */
/* Faces are polygons of 3..SUBD_MAX_FACE_SIZE corners. Corner c of face f is one of        */
/* face_start[f] .. face_start[f+1]-1 and also names the half-edge from corner_vert[c] to  */
/* the vertex of the next corner of the same face. twin[c] is the opposite half-edge in   */
/* the neighbouring face or SUBD_NONE on a boundary. vert_out[v] is an outgoing half-edge */
/* of v: for a boundary vertex the one whose twin is SUBD_NONE, so a one-ring walk that   */
/* starts there sees every face in order; SUBD_NONE for a vertex no face uses.             */

/* Per-vertex tag bits. */
#define SUBD_VTAG_BOUNDARY 0x01u /* on a boundary loop (set by the builder)               */
#define SUBD_VTAG_ISOLATED 0x02u /* used by no face (set by the builder)                  */
#define SUBD_VTAG_CORNER   0x04u /* caller: keep fixed (Hoppe et al. corner)              */
#define SUBD_VTAG_FIXED    0x08u /* caller: do not move (schemes that honour tags)        */
/* Bits 0x40 and 0x80 are reserved for the library: keep them 0 (subd_loop_limit and
 * subd_pia return SUBD_ERR_PARAM, diag.vertex, when an input vertex has them). */
/* Per-half-edge tag bits (edge tags are kept equal on both half-edges of an edge). */
#define SUBD_ETAG_BOUNDARY 0x01u /* no twin (set by the builder)                          */
#define SUBD_ETAG_CREASE   0x02u /* caller: sharp feature edge                            */

typedef struct subd_mesh {
    uint32_t num_verts;
    uint32_t num_faces;
    uint32_t num_corners;   /* sum of face sizes = number of half-edges                   */
    subd_real *pos;         /* 3 * num_verts: x, y, z                                     */
    uint32_t *face_start;   /* num_faces + 1                                              */
    uint32_t *corner_vert;  /* num_corners                                                */
    uint32_t *corner_face;  /* num_corners                                                */
    uint32_t *twin;         /* num_corners                                                */
    uint32_t *vert_out;     /* num_verts                                                  */
    uint8_t *vert_tag;      /* num_verts                                                  */
    uint8_t *edge_tag;      /* num_corners (per half-edge)                                */
    /* polylines (OBJ `l` records); not part of the surface topology                      */
    uint32_t num_lines;
    uint32_t num_line_verts;
    uint32_t *line_start;   /* num_lines + 1                                              */
    uint32_t *line_vert;    /* num_line_verts                                             */
    /* summary filled by the builder                                                      */
    uint32_t num_edges;
    uint32_t num_boundary_edges;
    uint32_t num_boundary_loops;
    uint32_t num_isolated;  /* vertices used by no face (accepted, tagged ISOLATED)       */
} subd_mesh;

/* A plain face list: the input of the mesh builder. face_size may be NULL (all triangles).
 * Indices are 0-based. Lines are optional (num_lines = 0, pointers NULL). */
typedef struct subd_face_list {
    uint32_t num_verts;
    const subd_real *pos;        /* 3 * num_verts */
    uint32_t num_faces;
    const uint32_t *face_size;   /* num_faces, or NULL for triangles */
    const uint32_t *index;       /* sum of face sizes */
    uint32_t num_lines;
    const uint32_t *line_size;   /* num_lines */
    const uint32_t *line_index;  /* sum of line sizes */
} subd_face_list;

/* subd_mesh_plan: the exact arena bytes subd_mesh_build needs for this face list (arrays
 * plus temporary working memory), in *bytes.
 * Memory: no arena use.
 * Errors: SUBD_ERR_PARAM (NULL pointers), SUBD_ERR_FACE_SIZE (a size outside
 *   3..SUBD_MAX_FACE_SIZE, so the corner count is unknown), SUBD_ERR_TOO_BIG.
 * Cost: O(faces). */
int subd_mesh_plan(const subd_face_list *fl, uint32_t *bytes);

/* Closed-form plan for compile-time buffer sizing: bytes for a mesh with at most V vertices,
 * F faces, C corners (C = 3F for triangles), L lines and LV line vertices. Always >= the
 * exact plan. */
#define SUBD_ALIGN_UP(x) (((x) + (SUBD_ARENA_ALIGN - 1u)) & ~(SUBD_ARENA_ALIGN - 1u))
#define SUBD_MESH_BYTES(V, F, C, L, LV)                                                       \
    (SUBD_ALIGN_UP(3u * (V) * (uint32_t)sizeof(subd_real)) /* pos */                          \
     + SUBD_ALIGN_UP(((F) + 1u) * 4u)                      /* face_start */                   \
     + 3u * SUBD_ALIGN_UP((C) * 4u)                        /* corner_vert, corner_face, twin */ \
     + SUBD_ALIGN_UP((V) * 4u) + SUBD_ALIGN_UP(V)          /* vert_out, vert_tag */           \
     + SUBD_ALIGN_UP(C)                                    /* edge_tag */                     \
     + SUBD_ALIGN_UP(((L) + 1u) * 4u) + SUBD_ALIGN_UP((LV) * 4u) /* polylines */              \
     + SUBD_ALIGN_UP(((V) + 1u) * 4u) + SUBD_ALIGN_UP((C) * 4u)) /* build scratch */

/* subd_mesh_build: builds and validates a mesh into *out. Copies positions and indices
 * into the arena, builds adjacency by counting sorts and prefix sums, tags boundary vertices
 * and edges, counts boundary loops and isolated vertices.
 * Memory: exactly subd_mesh_plan's bytes at the peak; the scratch is given back, *out's
 *   arrays stay. Stack a few dozen bytes; no recursion.
 * Errors: checks, in this order, and returns the first failure found:
 *   SUBD_ERR_PARAM (NULL pointers), SUBD_ERR_EMPTY (no vertices), SUBD_ERR_FACE_SIZE
 *   (diag.face), SUBD_ERR_TOO_BIG, SUBD_ERR_NOMEM (diag.bytes_needed = the plan),
 *   then per face in order SUBD_ERR_INDEX and SUBD_ERR_DEGENERATE (diag.face), per polyline
 *   SUBD_ERR_INDEX (diag.polyline), per vertex SUBD_ERR_NAN (diag.vertex; float build),
 *   then SUBD_ERR_NONMANIFOLD_EDGE and SUBD_ERR_ORIENTATION (diag.face: the latest face
 *   using the edge) and SUBD_ERR_NONMANIFOLD_VERTEX (diag.vertex).
 *   On failure the arena is rewound to where it was and *out is not touched.
 * Cost: O(V + C), independent of the valences.
 * Notes: vertices used by no face are accepted (a scanned mesh often has them, and rejecting them
 * would force every user to clean files first): they are counted in num_isolated, tagged
 * SUBD_VTAG_ISOLATED, have vert_out = SUBD_NONE, and schemes leave them where they are.
 * A mesh with vertices but no faces (points or polylines only) is valid. */
int subd_mesh_build(subd_arena *arena, const subd_face_list *fl, subd_mesh *out, subd_diag *diag);

/* Half-edge navigation (all O(1) except prev, which is O(1) as well via face_start). */
static inline uint32_t subd_he_next(const subd_mesh *m, uint32_t h)
{
    uint32_t f = m->corner_face[h];
    return (h + 1u == m->face_start[f + 1u]) ? m->face_start[f] : h + 1u;
}
static inline uint32_t subd_he_prev(const subd_mesh *m, uint32_t h)
{
    uint32_t f = m->corner_face[h];
    return (h == m->face_start[f]) ? m->face_start[f + 1u] - 1u : h - 1u;
}
static inline uint32_t subd_he_origin(const subd_mesh *m, uint32_t h) { return m->corner_vert[h]; }
static inline uint32_t subd_he_dest(const subd_mesh *m, uint32_t h) { return m->corner_vert[subd_he_next(m, h)]; }
static inline uint32_t subd_face_size(const subd_mesh *m, uint32_t f)
{
    return m->face_start[f + 1u] - m->face_start[f];
}

/* Ordered one-ring traversal. subd_ring_first gives vert_out[v]; subd_ring_next gives the
 * next outgoing half-edge of the same vertex (rotating towards the previous corner of the
 * face, i.e. counter-clockwise seen from the front for counter-clockwise faces) or
 * SUBD_NONE after the last one. On an interior vertex the walk stops before returning to
 * the first half-edge. */
static inline uint32_t subd_ring_first(const subd_mesh *m, uint32_t v) { return m->vert_out[v]; }
static inline uint32_t subd_ring_next(const subd_mesh *m, uint32_t first, uint32_t h)
{
    uint32_t t = m->twin[subd_he_prev(m, h)];
    return (t == first) ? SUBD_NONE : t;
}

/* subd_vertex_ring: writes the one-ring neighbours of v in order into nbr[0..max) and
 * returns their number (the valence).
 * Memory: none. Errors: none; 0 for the cases below. Cost: O(valence).
 * Notes: For a boundary vertex the first and last are its boundary neighbours and
 * the count is faces + 1. Returns 0 for an isolated vertex, and (writing nothing) for a NULL
 * mesh, v >= num_verts or a mesh without adjacency (twin, vert_out or corner_face NULL, e.g.
 * subd_loop output without SUBD_LOOP_ADJACENCY). If the valence exceeds max only max are
 * written, but the full valence is returned. */
uint32_t subd_vertex_ring(const subd_mesh *m, uint32_t v, uint32_t *nbr, uint32_t max);

/* subd_vertex_valence: the valence (number of edges at v); 0 where subd_vertex_ring
 * returns 0.
 * Memory: none. Errors: none (0 as subd_vertex_ring). Cost: O(valence). */
uint32_t subd_vertex_valence(const subd_mesh *m, uint32_t v);

/* subd_edge_tag_set, subd_edge_tag_clear: set or clear tag bits on an edge (both
 * half-edges).
 * Memory: none. Errors: none (a NULL mesh, h >= num_corners or a mesh without edge tags is
 *   left alone). Cost: O(1). */
void subd_edge_tag_set(subd_mesh *m, uint32_t h, uint8_t bits);
void subd_edge_tag_clear(subd_mesh *m, uint32_t h, uint8_t bits);

/* subd_mesh_tag_crease_angle: tags as SUBD_ETAG_CREASE every interior edge whose dihedral
 * angle (the angle between the normals of its two faces) is larger than the angle whose
 * cosine is cos_limit; e.g. subd_cos_turns(30, 360) for 30 degrees. Returns the number of
 * edges tagged.
 * Memory: none.
 * Errors: none (no status: the cases below return 0 and change nothing).
 * Cost: O(corners * face size).
 * Notes: Q16.16 resolves the angle to about 0.06 degrees. Any cos_limit: above 1
 * every interior edge is tagged, below -1 none. A NULL mesh or one without adjacency (twin
 * or corner_face NULL, e.g. subd_loop output without SUBD_LOOP_ADJACENCY) is not touched
 * and 0 is returned. */
uint32_t subd_mesh_tag_crease_angle(subd_mesh *m, subd_real cos_limit);

/* subd_mesh_euler: the Euler characteristic V - E + F (isolated vertices included), from
 * the builder's summary counts.
 * Memory: none. Errors: none (0 for a NULL mesh). Cost: O(1). */
int32_t subd_mesh_euler(const subd_mesh *m);

/* ------------------------------------------------------------------------------------ */
/* OBJ and OFF on memory buffers.                                                         */
/*                                                                                        */
/* Readers take the whole file in memory (any line endings), parse numbers with           */
/* subd_real_parse (same bits on every target) and build the mesh with subd_mesh_build,   */
/* so every validation error applies; diag.line names the offending line (for validation  */
/* errors: the face's `f` line or the vertex's `v` line).                                  */

/* subd_obj_plan, subd_off_plan: the exact arena bytes subd_obj_read / subd_off_read need
 * for this buffer, in *bytes. subd_obj_read, subd_off_read: parse the buffer and build the
 * mesh into *out.
 * Memory: the plans use no arena; the readers use exactly the plan at the peak and leave
 *   *out's arrays (subd_mesh_build's) in the arena.
 * Errors: SUBD_ERR_PARAM (NULL pointers other than the empty (NULL, 0) buffer),
 *   SUBD_ERR_PARSE (diag.line: a record that is not in the format), SUBD_ERR_NAN and
 *   SUBD_ERR_RANGE (diag.line: a coordinate that is nan/inf text or does not fit subd_real),
 *   SUBD_ERR_INDEX (diag.line: an index out of range, or 0 in OBJ), SUBD_ERR_FACE_SIZE,
 *   SUBD_ERR_EMPTY (no vertices), SUBD_ERR_TOO_BIG (counts beyond 32 bits); the readers also
 *   SUBD_ERR_NOMEM (diag.bytes_needed) and every error of subd_mesh_build, with diag.line the
 *   line of the element it names. On failure the arena is back where it was and *out
 *   untouched.
 * Cost: O(length of the buffer) (two passes: count, then fill), then subd_mesh_build. */
int subd_obj_plan(const char *buf, uint32_t len, uint32_t *bytes, subd_diag *diag);
int subd_obj_read(subd_arena *arena, const char *buf, uint32_t len, subd_mesh *out, subd_diag *diag);
int subd_off_plan(const char *buf, uint32_t len, uint32_t *bytes, subd_diag *diag);
int subd_off_read(subd_arena *arena, const char *buf, uint32_t len, subd_mesh *out, subd_diag *diag);

/* subd_obj_line_of, subd_off_line_of: the 1-based line, in the buffer a mesh was read
 * from, of the input element a later call names in diag (diag.face, else diag.polyline
 * (OBJ), else diag.vertex, numbered as the reader numbers them), e.g. the face of a
 * SUBD_ERR_NOT_TRIANGLES from a triangle scheme.
 * Memory: no arena. Errors: none: 0 when the diag names no element, the buffer has no such
 *   element or does not parse. Cost: one scan of the buffer (two for OFF). */
uint32_t subd_obj_line_of(const char *buf, uint32_t len, const subd_diag *diag);
uint32_t subd_off_line_of(const char *buf, uint32_t len, const subd_diag *diag);

/* subd_obj_write, subd_off_write, subd_obj_write_normals: write the mesh as text into
 * buf[0..cap), numbers by subd_real_format (the same bytes on every target); *len receives
 * the number of bytes written. subd_obj_write_normals adds one normal per vertex
 * (3 * num_verts; `vn` records, faces as `f a//a ...`).
 * Memory: no arena; the caller's buffer only.
 * Errors: SUBD_ERR_PARAM (NULL mesh, len or normals), SUBD_ERR_NOMEM (cap too small: nothing
 *   is written and *len receives the exact size needed). With buf == NULL nothing is written,
 *   *len receives the exact size and SUBD_OK is returned, so a caller can size its buffer;
 *   SUBD_ERR_TOO_BIG (the text would exceed 4 GB).
 * Cost: O(vertices + corners) (every number formatted once per call; sizing calls format
 *   too). */
int subd_obj_write(const subd_mesh *m, char *buf, uint32_t cap, uint32_t *len);
int subd_off_write(const subd_mesh *m, char *buf, uint32_t cap, uint32_t *len);
int subd_obj_write_normals(const subd_mesh *m, const subd_real *normals, char *buf, uint32_t cap, uint32_t *len);

/* ------------------------------------------------------------------------------------ */
/* STL and PLY on memory buffers.                                                         */
/*                                                                                        */
/* Readers take the whole file in memory and build the mesh with subd_mesh_build's         */
/* validation, so every error of subd_mesh_build applies. Binary coordinates (float32,     */
/* PLY also float64) become subd_reals by subd_real_from_f32_bits / _f64_bits, text ones    */
/* by subd_real_parse: the same value gives the same bits from every format and target.   */

/* subd_stl_plan: the exact arena bytes subd_stl_read needs for this buffer, in *bytes.
 * subd_stl_read: reads binary or ASCII STL and welds the facets' corners into shared
 * vertices (equal coordinate bits, -0 = +0; vertices numbered by first use, faces in file
 * order, each facet one triangle), so the mesh has its adjacency.
 * Memory: the plans use no arena. The plan is the bytes of the unwelded mesh (3 vertices
 * per facet) with subd_mesh_build's scratch, about 40 bytes per corner: the read takes all of
 * it at the peak (the weld works inside it) for every file, and leaves *out's arrays, for
 * the welded vertex count, in the arena.
 * Errors: SUBD_ERR_PARAM (NULL pointers other than the empty (NULL, 0) buffer),
 *   SUBD_ERR_EMPTY (an empty buffer, no facets), SUBD_ERR_TOO_BIG (counts beyond 32-bit
 *   sizes). Binary (diag.face: the 0-based facet): SUBD_ERR_PARSE for a buffer shorter than
 *   the 84-byte header (no facet named), a truncated file (the first incomplete facet) or
 *   one longer than its count says (diag.face = the count, the first facet beyond it: also
 *   a binary file with a "solid" header whose count the size contradicts), SUBD_ERR_NAN
 *   (NaN or infinity), SUBD_ERR_RANGE (outside Q16.16). ASCII (diag.line): SUBD_ERR_PARSE,
 *   SUBD_ERR_NAN, SUBD_ERR_RANGE, SUBD_ERR_FACE_SIZE (a loop of other than 3 vertices). The
 *   read also: SUBD_ERR_NOMEM (diag.bytes_needed) and subd_mesh_build's errors for the welded
 *   mesh (e.g. SUBD_ERR_NONMANIFOLD_EDGE when three facets weld onto one edge), with
 *   diag.face the facet (for a vertex error, diag.vertex the welded vertex and diag.face the
 *   first facet using it) and, for ASCII, diag.line its `facet` line. On failure the arena
 *   is back where it was and *out untouched.
 * Cost: O(length) to scan (plan and read each), then O(F) for the weld (at most 12 counting
 *   passes over the 3F corners) and subd_mesh_build.
 * Notes: normals and attribute bytes are ignored. A buffer of 84 + 50 n bytes with count n
 * at byte 80 is binary even if its header starts with "solid". Q16.16: corners whose float32
 * values round to the same Q16.16 value weld. */
int subd_stl_plan(const char *buf, uint32_t len, uint32_t *bytes, subd_diag *diag);
int subd_stl_read(subd_arena *arena, const char *buf, uint32_t len, subd_mesh *out, subd_diag *diag);

/* subd_stl_write: writes the mesh as binary STL into buf[0..cap): an 80-byte header (not
 * starting with "solid"), the triangle count, and per triangle (a polygon as a fan from its
 * first corner) the unit normal and the corners as float32 (subd_real_to_f32_bits), attribute
 * 0; *len receives the number of bytes, 84 + 50 T. Polylines and isolated vertices are not
 * written.
 * Memory: no arena; the caller's buffer only.
 * Errors: SUBD_ERR_PARAM (NULL mesh or len), SUBD_ERR_NOMEM (cap too small: nothing is
 *   written and *len receives the exact size needed). With buf == NULL nothing is written,
 *   *len receives the exact size and SUBD_OK is returned; SUBD_ERR_TOO_BIG (over 4 GB).
 * Cost: O(corners).
 * Notes: float32 reads back bit for bit through subd_stl_read. Q16.16 coordinates of magnitude
 * below 256 are exact in float32 and read back bit for bit; larger ones are rounded to 24
 * significant bits (off by at most half a float32 ulp, < 2^-9). */
int subd_stl_write(const subd_mesh *m, char *buf, uint32_t cap, uint32_t *len);

/* subd_ply_plan: the exact arena bytes subd_ply_read needs for this buffer, in *bytes.
 * subd_ply_read: reads PLY, `format ascii 1.0` or `format binary_little_endian 1.0`: the
 * element `vertex` (properties x, y, z of type float/float32 or double/float64) and the
 * element `face` (a list property vertex_indices or vertex_index, any integer count and
 * index types), in any order; every other element and property is skipped by its declared
 * type (lists included). Faces keep their sizes (3..SUBD_MAX_FACE_SIZE).
 * Memory: the plans use no arena; the reader uses exactly the plan at the peak and leaves
 *   *out's arrays (subd_mesh_build's) in the arena.
 * Errors: SUBD_ERR_PARAM (NULL pointers other than the empty (NULL, 0) buffer),
 *   SUBD_ERR_PARSE (header: diag.line of the offending line, e.g. a format other than the two
 *   above, so big-endian PLY is refused at its `format` line, an unknown type, x/y/z not
 *   float or double or missing; body: a value that is not a number or an integer, a missing
 *   or extra value or record, a file shorter or longer than the header says),
 *   SUBD_ERR_NAN, SUBD_ERR_RANGE (a coordinate), SUBD_ERR_INDEX (an index out of range or
 *   negative), SUBD_ERR_FACE_SIZE, SUBD_ERR_EMPTY (no vertices), SUBD_ERR_TOO_BIG; the
 *   reader also SUBD_ERR_NOMEM (diag.bytes_needed) and every error of subd_mesh_build. Body
 *   errors name the record: ASCII the line (diag.line); binary diag.vertex or diag.face
 *   (0-based), or for another element and for trailing bytes the line of its `element`
 *   line / of `end_header`. On failure the arena is back where it was and *out untouched.
 * Cost: O(length of the buffer) (two passes: count, then fill), then subd_mesh_build. */
int subd_ply_plan(const char *buf, uint32_t len, uint32_t *bytes, subd_diag *diag);
int subd_ply_read(subd_arena *arena, const char *buf, uint32_t len, subd_mesh *out, subd_diag *diag);

/* subd_ply_line_of: the 1-based line of face diag.face (else vertex diag.vertex) in an ASCII
 * PLY buffer a mesh was read from, as subd_obj_line_of.
 * Memory: no arena. Errors: none: 0 when the diag names no element, the buffer is binary,
 *   has no such element or does not parse. Cost: one scan of the buffer (two passes). */
uint32_t subd_ply_line_of(const char *buf, uint32_t len, const subd_diag *diag);

/* ------------------------------------------------------------------------------------ */
/* Streams: one interface for every scheme.                                               */
/*                                                                                        */
/* A stream hands a scheme's output to the caller piece by piece instead of storing it, in */
/* an arena whose size depends on the level count, the largest valence and the mode only,  */
/* never on the mesh or the output. Surfaces stream triangles (subd_tri), curves points    */
/* (subd_point). Every stream has two forms:                                              */
/*  - pull: subd_X_stream_begin(arena, in, opts, &s, diag) puts the stream's state in the  */
/*    arena (its plan, subd_X_stream_plan, includes it), then subd_stream_next_tris /      */
/*    subd_stream_next_points fill a caller buffer with up to `max` items per call, with   */
/*    bounded work per call (a controller's main loop interleaves them with its real-time */
/*    work), and subd_stream_end gives the arena back. Pulling in batches of any size gives */
/*    the same items in the same order with the same bits as one push call.               */
/*  - push: subd_X_stream(arena, in, opts, sink, diag) = begin, next until the end with    */
/*    every item handed to the sink, end (subd_stream_run_tris / _points).                */
/* Ids are closed-form 64-bit global vertex ids: every item that uses a vertex gives it    */
/* the same id and the same bits (no cracks); each scheme's header gives its formula.     */

/* One triangle of a surface stream. */
typedef struct subd_tri {
    subd_real pos[3][3];    /* corner positions, counter-clockwise as the input's faces   */
    subd_real normal[3][3]; /* unit normals where the stream gives them, else zeros        */
    uint64_t id[3];         /* global vertex ids (see the scheme's header)                 */
    uint32_t face;          /* the control (base mesh) face it comes from                  */
    uint32_t level;         /* its refinement level, in the scheme's steps                 */
} subd_tri;

/* One point of a curve stream. */
typedef struct subd_point {
    subd_real pos[3];
    subd_real tangent[3]; /* unit tangent where the stream gives it, else zeros            */
    uint64_t id;          /* global point id (see the scheme's header)                      */
    uint32_t curve;       /* the control polygon it comes from                              */
    uint32_t level;       /* its refinement level                                           */
} subd_point;

/* Sinks: the caller's consumers of the push form. The item is valid only during the call.
 * A non-zero return stops the stream at once and the push call returns that value
 * unchanged (use positive values to tell them from the library's negative statuses). */
typedef struct subd_tri_sink {
    int (*tri)(void *ctx, const subd_tri *t);
    void *ctx;
} subd_tri_sink;
typedef struct subd_point_sink {
    int (*point)(void *ctx, const subd_point *p);
    void *ctx;
} subd_point_sink;

/* Every stream's state starts with a fixed block of this many arena bytes (the run state:
 * where the walk is, the scheme's options, the overflow ring's bookkeeping), the same on
 * every target; the plans and SUBD_X_STREAM_BYTES macros include it. */
#define SUBD_STREAM_STATE_BYTES 512u

/* A pull stream's handle, owned by the caller (its state lives in the arena). Fields ending
 * in _ are private; diag holds the details of the last failure (status, face, ...). */
#define SUBD_STREAM_TRIS 1u
#define SUBD_STREAM_POINTS 2u
typedef struct subd_stream {
    uint32_t magic_;  /* set by a begin call                                           */
    void *state_;
    subd_arena *arena_;
    uint32_t mark_;
    int32_t status_;  /* SUBD_OK while running, 1 after the end, < 0 after a failure */
    uint32_t kind_;   /* SUBD_STREAM_TRIS or SUBD_STREAM_POINTS                       */
    uint32_t items_;  /* items handed out so far (saturates at UINT32_MAX)             */
    subd_diag diag;
} subd_stream;

/* subd_stream_next_tris, subd_stream_next_points: the next up to `max` items of a stream
 * into buf[0..max); returns how many (1..max), 0 at the end of the stream, or a negative
 * status (then s->diag has the details, and every later call returns the same status).
 * At the end or on a failure the stream's arena is given back (as subd_stream_end).
 * Memory: none beyond the stream's own (already in the arena). Stack: the scheme's step.
 * Errors: SUBD_ERR_PARAM (NULL s or buf, max = 0, a stream of the other kind, a handle no
 *   begin call filled), SUBD_ERR_RANGE (a position overflowed), the scheme's own.
 * Cost: bounded per call: `max` items plus at most one internal batch of the scheme (its
 *   header says how many items a batch holds). */
int subd_stream_next_tris(subd_stream *s, subd_tri *buf, uint32_t max);
int subd_stream_next_points(subd_stream *s, subd_point *buf, uint32_t max);

/* subd_stream_end: stops the stream (any time) and rewinds its arena to where it was
 * before the begin call. Idempotent.
 * Memory: gives the stream's bytes back. Errors: none (NULL is ignored). Cost: O(1). */
void subd_stream_end(subd_stream *s);

/* subd_stream_run_tris, subd_stream_run_points: the push form over a begun stream: every
 * remaining item to the sink, then subd_stream_end. Returns SUBD_OK, a negative status
 * (diag: its details) or the sink's non-zero value unchanged.
 * Memory: none beyond the stream's. Errors: SUBD_ERR_PARAM (NULL s, sink or its
 *   function), the stream's own. Cost: the stream's. */
int subd_stream_run_tris(subd_stream *s, const subd_tri_sink *sink, subd_diag *diag);
int subd_stream_run_points(subd_stream *s, const subd_point_sink *sink, subd_diag *diag);

#ifdef __cplusplus
}
#endif

#include "subd_loop.h"
#include "subd_quasi48.h"
#include "subd_alpha.h"
#include "subd_sr48.h"
#include "subd_tags.h"
#include "subd_loop_adapt.h"

#endif
