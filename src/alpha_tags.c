/* SPDX-License-Identifier: MIT */
/* Parameter tags of alpha-subdivision surfaces (Zhang & Wang 2002, section 3: "tag every
 * point a parameter when k is odd and every face a parameter when k is even", updated "as
 * Ref. [9]", Sederberg et al.'s non-uniform recursive subdivision). The paper gives no
 * rule for elements with no single parent; the one used here is the table in
 * include/subd_alpha.h, and this file is its only home.
 *
 * The principle (issue 15): an element that descends from one tagged element inherits its
 * alpha; an element that descends from several takes their arithmetic mean. It is applied
 * to the kind of element that is tagged at that point of the level, which alternates: S_2
 * always leaves face tags; each dual step C turns face tags into vertex tags and back
 * (C is a duality: a new vertex per old face, a new face per old vertex). So for even k
 * (an even number of C per level) the level ends face-tagged, for odd k vertex-tagged,
 * as the paper asks, and C itself never averages except where its boundary rule makes a
 * vertex that no single face owns.
 *
 * Why not track face alphas throughout (the first suggestion, "under C, the faces
 * that meet"): with odd k the input tags are on vertices, and a vertex tag would only ever
 * enter as a share of its faces' means; in figure 4(d) (S_3, one vertex with alpha = 9) no
 * weight would ever see 9 (a cube corner's faces get 9/4). With the rule here the V-face
 * of a tagged vertex, whose centroid becomes that vertex's new point, carries its alpha
 * at every level, and a face tag (S_4, S_6, ...) likewise reaches its own output face
 * unchanged through the two C steps instead of being averaged with its neighbours twice.
 *
 * Tags are numerators over the one alpha_den of the options, so a mean is an integer
 * operation: the same bits in the float and the Q16.16 build. The mean is floor(sum / n)
 * of the exact int64 sum (the curve's (a + b) >> 1 is the case n = 2); equal tags give
 * their value exactly, so uniform tags reproduce the untagged run bit for bit. Sums are
 * taken in a fixed order (corner order, ring order), although integer sums do not depend
 * on it.
 */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "alpha_internal.h"

int32_t subd_alpha_tag_mean(int64_t sum, uint32_t n)
{
    int64_t q = sum / (int64_t)n;
    if (sum % (int64_t)n != 0 && sum < 0) q--; /* floor, not truncation */
    return (int32_t)q;
}

/* Mean of the tags of the faces around vertex v (ring order from vert_out). */
static int32_t ring_face_mean(const subd_mesh *m, uint32_t v, const int32_t *ft)
{
    uint32_t first = m->vert_out[v], h, n = 0;
    int64_t sum = 0;
    for (h = first; h != SUBD_NONE; h = subd_ring_next(m, first, h)) {
        sum += ft[m->corner_face[h]];
        n++;
    }
    return subd_alpha_tag_mean(sum, n);
}

int32_t subd_alpha_face_num(const subd_mesh *m, int vertex_tags, const int32_t *t, uint32_t f)
{
    uint32_t s = m->face_start[f], e = m->face_start[f + 1u], i;
    int64_t sum = 0;
    if (!vertex_tags) return t[f];
    for (i = s; i < e; i++) sum += t[m->corner_vert[i]];
    return subd_alpha_tag_mean(sum, e - s);
}

void subd_alpha_tags_s2(const subd_mesh *m, int vertex_tags, const int32_t *t, int32_t *out)
{
    uint32_t f, h, v, n = 0;
    for (f = 0; f < m->num_faces; f++) out[n++] = subd_alpha_face_num(m, vertex_tags, t, f);
    for (h = 0; h < m->num_corners; h++) {
        uint32_t tw = m->twin[h];
        if (tw == SUBD_NONE || tw < h) continue;
        if (vertex_tags) out[n++] = subd_alpha_tag_mean((int64_t)t[m->corner_vert[h]] + t[subd_he_dest(m, h)], 2u);
        else out[n++] = subd_alpha_tag_mean((int64_t)t[m->corner_face[h]] + t[m->corner_face[tw]], 2u);
    }
    /* the V-faces, with the same skips as the Doo-Sabin faces (boundary, digon) */
    for (v = 0; v < m->num_verts; v++) {
        uint32_t first = m->vert_out[v], second;
        if (first == SUBD_NONE || (m->vert_tag[v] & SUBD_VTAG_BOUNDARY)) continue;
        second = subd_ring_next(m, first, first);
        if (second == SUBD_NONE || subd_ring_next(m, first, second) == SUBD_NONE) continue;
        out[n++] = vertex_tags ? t[v] : ring_face_mean(m, v, t);
    }
}

void subd_alpha_tags_dual(const subd_mesh *m, int vertex_tags, const int32_t *t, int32_t *out)
{
    uint32_t f, h, v, n = 0;
    if (vertex_tags) {
        /* one face per vertex (vertex order): the face of v inherits v's alpha */
        for (v = 0; v < m->num_verts; v++)
            if (m->vert_out[v] != SUBD_NONE) out[n++] = t[v];
        return;
    }
    for (f = 0; f < m->num_faces; f++) out[n++] = t[f]; /* a centroid inherits its face's */
    for (h = 0; h < m->num_corners; h++)                /* a boundary edge's midpoint: its one face */
        if (m->twin[h] == SUBD_NONE) out[n++] = t[m->corner_face[h]];
    for (v = 0; v < m->num_verts; v++) /* a kept boundary vertex: the faces that meet there */
        if (m->vert_out[v] != SUBD_NONE && (m->vert_tag[v] & SUBD_VTAG_BOUNDARY)) out[n++] = ring_face_mean(m, v, t);
}
