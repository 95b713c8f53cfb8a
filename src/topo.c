/* SPDX-License-Identifier: MIT */
/* Topology helpers (topo.h): the part that is not inline, the adjacency check. */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "topo.h"

/* 1 when pointer p is present or not needed: `need` names its bit and the guard says the
 * array is needed (count: the count the array is sized by). */
static int topo_array_ok(const void *p, uint32_t need, uint32_t bit, uint32_t count, uint32_t faces)
{
    uint32_t needed;
    if (!(need & bit)) return 1;
    if (need & TOPO_ALWAYS) needed = 1u;
    else if (need & TOPO_IF_FACES) needed = faces != 0u;
    else needed = count != 0u;
    return !needed || p != 0;
}

int subd_topo_has(const subd_mesh *m, uint32_t need)
{
    uint32_t nv, nc, nf;
    if (!m) return 0;
    nv = m->num_verts;
    nc = m->num_corners;
    nf = m->num_faces;
    return topo_array_ok(m->pos, need, TOPO_POS, nv, nf) && topo_array_ok(m->vert_out, need, TOPO_VERT_OUT, nv, nf) &&
           topo_array_ok(m->vert_tag, need, TOPO_VERT_TAG, nv, nf) &&
           topo_array_ok(m->face_start, need, TOPO_FACE_START, 1u, nf) &&
           topo_array_ok(m->corner_vert, need, TOPO_CORNER_VERT, nc, nf) &&
           topo_array_ok(m->corner_face, need, TOPO_CORNER_FACE, nc, nf) &&
           topo_array_ok(m->twin, need, TOPO_TWIN, nc, nf) && topo_array_ok(m->edge_tag, need, TOPO_EDGE_TAG, nc, nf);
}
