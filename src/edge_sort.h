/* SPDX-License-Identifier: MIT */
/* Edge sort and cluster marking shared by quasi 4-8 subdivision (quasi48.c, Algorithm 1:
 * sort_edges, mark_cluster) and semi-regular 4-8 pre-processing (sr48_pre.c, section 5,
 * find_clusters). One implementation, so both schemes number, sort and mark edges the same
 * way (see src/edge_sort.c for the choices). Private to the library. */
#ifndef SUBD_EDGE_SORT_H
#define SUBD_EDGE_SORT_H
#include "subd.h"

/* Working arrays, allocated by the caller: edge_of per half-edge; edge_he, key[0..1],
 * ord[0..1], mark per edge (at most the number of half-edges; a triangle mesh has no more
 * faces than edges, and mark holds one flag per face); cnt 256 radix counters. After
 * subd_edge_clusters only edge_of and edge_he hold results; ord and mark are scratch. */
typedef struct subd_edge_work {
    uint32_t *edge_of; /* per half-edge: its edge number (radial order)                   */
    uint32_t *edge_he; /* per edge: one of its half-edges (the first one numbered)         */
    uint64_t *key[2];  /* sort keys (with bits <= 24: key << 32 | half-edge), ping-pong     */
    uint32_t *ord[2];  /* half-edges alongside the keys when bits > 24, ping-pong          */
    uint8_t *mark;     /* per face: holds an edge selected by a cluster                    */
    uint32_t *cnt;     /* 256 radix counters                                               */
} subd_edge_work;

/* Numbers the edges of a triangle mesh radially around each vertex (vertices in index order;
 * around each vertex its not yet numbered edges in one-ring order from vert_out, a boundary
 * vertex's incoming boundary edge last). Fills edge_of and edge_he. Returns the number of
 * edges, or SUBD_NONE when there are more than cap (edge_he has room for cap). */
uint32_t subd_edge_number(const subd_mesh *m, const subd_edge_work *w, uint32_t cap);

/* Algorithm 1's marking pass over the numbered edges 0..ne-1: sorts them by decreasing
 * squared length rounded to `bits` significant bits (1..53; stable, so equal lengths keep
 * the radial numbering), then goes down the list: an edge that is not marked (and, with
 * interior_only, is not a boundary edge) is selected, sel[e] = base + its rank among the
 * selected, and its cluster (the edge and every edge of the faces containing it) is
 * marked; every other edge gets sel[e] = SUBD_NONE. Returns the number selected. The mesh
 * must be all triangles. */
uint32_t subd_edge_clusters(const subd_mesh *m, subd_edge_work *w, uint32_t ne, uint32_t bits, int interior_only,
                            uint32_t base, uint32_t *sel);

#endif
