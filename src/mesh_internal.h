/* SPDX-License-Identifier: MIT */
/* Private mesh construction interface shared by the builder (mesh.c) and the readers
 * (obj.c, off.c): the readers parse straight into the mesh arrays and then run the same
 * validation and adjacency pass, so there is one layout and one validator. Also the corner
 * steps of an all-triangle mesh that the schemes walk with (tri_next, tri_prev). */
#ifndef SUBD_MESH_INTERNAL_H
#define SUBD_MESH_INTERNAL_H
#include "subd.h"

/* Next and previous corner in a mesh whose face f is corners 3f..3f+2 (every face a triangle,
 * as each scheme level is): subd_he_next/prev without loading corner_face and face_start. */
static inline uint32_t tri_next(uint32_t h) { return (h % 3u == 2u) ? h - 2u : h + 1u; }
static inline uint32_t tri_prev(uint32_t h) { return (h % 3u == 0u) ? h + 2u : h - 1u; }

typedef struct mesh_counts {
    uint32_t nv, nf, nc, nl, nlv;
} mesh_counts;

/* Exact bytes of the mesh arrays plus the builder's temporary memory; UINT32_MAX when the
 * counts are too large for 32-bit sizes. */
uint32_t subd_mesh_counts_bytes(const mesh_counts *c);
/* Its two parts: the builder's scratch (subd_mesh_finish) and the mesh arrays alone. */
uint32_t subd_mesh_scratch_bytes(const mesh_counts *c);
uint32_t subd_mesh_arrays_bytes(const mesh_counts *c);

/* Allocates the mesh arrays (not the scratch) by the layout function (layout.h) that
 * subd_mesh_counts_bytes counts with, and sets every pointer and count of *m. Returns SUBD_OK or SUBD_ERR_NOMEM; on failure the
 * arena may have advanced (callers rewind to their own mark). */
int subd_mesh_alloc_arrays(subd_arena *a, const mesh_counts *c, subd_mesh *m);

/* Validates the filled arrays (pos, face_start, corner_vert, line_start, line_vert) and
 * builds corner_face, twin, vert_out, tags and the summary counts. Uses scratch memory
 * above the arrays and gives it back. Returns SUBD_OK or a validation error (with diag). */
int subd_mesh_finish(subd_arena *a, subd_mesh *m, subd_diag *d);

/* A text format for the two-pass reader driver (reader.c). scan() parses the whole buffer:
 * with m == NULL it only counts elements into *c; otherwise *c holds the counts of the
 * counting pass on entry and scan() fills m's arrays. line_of() turns the element a
 * validation error names (d->face, d->vertex or d->polyline) back into its line. */
typedef struct subd_reader {
    int (*scan)(const char *buf, uint32_t len, mesh_counts *c, subd_mesh *m, subd_diag *d);
    uint32_t (*line_of)(const char *buf, uint32_t len, const mesh_counts *c, const subd_diag *d);
} subd_reader;

/* Plan and read for any format: count, allocate exactly, fill, validate, map errors to
 * lines; on failure the arena is rewound and *out untouched. */
int subd_reader_plan(const subd_reader *r, const char *buf, uint32_t len, uint32_t *bytes, subd_diag *diag);
int subd_reader_read(const subd_reader *r, subd_arena *a, const char *buf, uint32_t len, subd_mesh *out,
                     subd_diag *diag);
/* The line of the element d names (counting scan, then line_of); 0 when none or unparsable. */
uint32_t subd_reader_line_of(const subd_reader *r, const char *buf, uint32_t len, const subd_diag *d);

/* The builder's fans, tags and counts, for a mesh whose corner_vert, face_start, corner_face
 * and twin are set and whose edge_tag holds no BOUNDARY bit yet (the builder clears it; a
 * scheme that makes its own twins keeps its crease bits there). Every scheme that makes a
 * mesh without the builder calls this, so its output equals the builder's:
 *   vert_out[v]: v's outgoing boundary half-edge when it has one (a manifold vertex has at
 *     most one), else its lowest corner; SUBD_NONE for a vertex without corners;
 *   vert_tag[v] = keep[v] (keep NULL: 0) | SUBD_VTAG_BOUNDARY | SUBD_VTAG_ISOLATED as they
 *     apply; edge_tag |= SUBD_ETAG_BOUNDARY where there is no twin;
 *   num_isolated, num_boundary_edges, num_edges, and num_boundary_loops (from a boundary
 *     half-edge a->b the next along its loop is vert_out[b]).
 * O(V + C). Does not check manifoldness (the builder walks each fan afterwards). */
void subd_mesh_fans(subd_mesh *m, const uint8_t *keep);

/* Sets diag fields for an error and returns the status (for one-line error returns inside
 * a call). Public entry points end through subd_entry_fail (entry.h), which also rewinds. */
int subd_fail(subd_diag *d, int status);

/* SUBD_OK when every face of m is a triangle; else SUBD_ERR_NOT_TRIANGLES with d->face (when
 * d != NULL) set to the first other face. For the schemes defined on triangles only. */
int subd_require_triangles(const subd_mesh *m, subd_diag *d);

/* Moves mesh *m, whose arrays lie contiguous from m->pos (`bytes` long, as the mesh layout
 * allocates them), down to dst <= m->pos, and rebases its pointers. Used to drop working
 * memory from below a finished output. */
void subd_mesh_move_down(subd_mesh *m, uint8_t *dst, uint32_t bytes);
#endif
