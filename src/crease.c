/* SPDX-License-Identifier: MIT */
/* Feature tagging: mark as creases the edges whose dihedral angle exceeds a limit.
 *
 * The schemes treat SUBD_ETAG_CREASE edges like boundaries (Hoppe et al. 1994); this is how
 * a CAD or scan mesh gets its tags without a tag file. The test is on face normals (Newell's
 * method, so polygons work too): an interior edge is a crease when the angle between the
 * normals of its two faces is larger than the limit, i.e. when n1.n2 < c |n1| |n2| with
 * c = cos(limit). Both sides are compared squared, so no square root is needed.
 *
 * Float32: normals are scaled by their largest component before the comparison, so no
 * product can overflow. Q16.16: the normal of each face is formed exactly in 64-bit integers
 * from coordinate differences shifted down to 28 bits, then rounded to 10 significant bits
 * per component; with that the squared comparison fits in 64 bits. The angle is then
 * resolved to about 1e-3 radians (0.06 degrees), which is ample for a feature threshold.
 *
 * Range: cos_limit is clamped to [-1, 1] in meaning: above 1 every interior edge is tagged
 * (even one next to a degenerate face), below -1 none (and the Q16.16 squares never see a
 * value outside [-1, 1], which keeps them inside int64). A mesh without adjacency (twin or
 * corner_face NULL) is left alone and 0 returned.
 */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "subd.h"
#include "vec3w.h"
#include "topo.h"

#define N_BITS 10 /* Q16.16: significant bits kept per normal component */

/* The shift that brings the differences of the face's corners [s, e) to p0 below 2^28
 * (Q16.16; float32: none, vec3w.h's span), so their cross products and the fan's sum stay in
 * int64. One shift for the whole face, so the fan's terms add up exactly. */
static int32_t face_shift(const subd_mesh *m, uint32_t s, uint32_t e, const subd_real *p0)
{
    uint64_t big = 0;
    uint32_t c;
    for (c = s; c < e; c++) {
        subd_wide d[3];
        subd_w3_diff(&m->pos[3u * m->corner_vert[c]], p0, d);
        big = subd_w3_span_add(big, d);
    }
    return subd_w3_span_shift(big, 28u);
}

/* r = (p - p0) * 2^-sh */
static void corner_diff(const subd_real *p, const subd_real *p0, int32_t sh, subd_wide *r)
{
    subd_w3_diff(p, p0, r);
    subd_w3_span_apply(r, r, sh);
}

/* Normal of face f by Newell's method over the fan from its first corner, rescaled by
 * subd_w3_fit (float32: largest component 1; Q16.16: at most N_BITS bits per component, so
 * the squared comparison below fits 64 bits). */
static void face_normal(const subd_mesh *m, uint32_t f, subd_wide n[3])
{
    uint32_t s = m->face_start[f], e = m->face_start[f + 1u], c, k;
    const subd_real *p0 = &m->pos[3u * m->corner_vert[s]];
    subd_wide acc[3] = {0, 0, 0}, a[3], b[3], x[3];
    int32_t sh = face_shift(m, s, e, p0);
    for (c = s + 1u; c + 1u < e; c++) {
        corner_diff(&m->pos[3u * m->corner_vert[c]], p0, sh, a);
        corner_diff(&m->pos[3u * m->corner_vert[c + 1u]], p0, sh, b);
        subd_w3_cross(a, b, x);
        for (k = 0; k < 3u; k++) acc[k] += x[k];
    }
    subd_w3_fit(acc, n, N_BITS);
}

/* True when the angle between a and b exceeds the angle whose cosine is c. A zero normal
 * (degenerate face) never makes a crease. */
static int angle_exceeds(const subd_wide a[3], const subd_wide b[3], subd_real c)
{
    subd_wide dot = subd_w3_dot(a, b), aa = subd_w3_dot(a, a), bb = subd_w3_dot(b, b);
#if SUBD_FIXED /* the algorithm differs: c^2 aa bb in fixed point, rescaled to stay in int64 */
    /* dot^2 and aa*bb < 2^44; with c^2 in Q30 the product below stays under 2^60 */
    int64_t c2 = ((int64_t)c * c) >> 2, lhs, rhs;
    if (aa == 0 || bb == 0) return 0;
    lhs = dot * dot;
    rhs = (((aa * bb) >> 14) * c2) >> 16; /* = c^2 aa bb */
    if (c >= 0) return dot < 0 || lhs < rhs;
    return dot < 0 && lhs > rhs;
#else
    float rhs;
    if (aa == 0.0f || bb == 0.0f) return 0;
    rhs = c * c * aa * bb;
    if (c >= 0.0f) return dot < 0.0f || dot * dot < rhs;
    return dot < 0.0f && dot * dot > rhs;
#endif
}

uint32_t subd_mesh_tag_crease_angle(subd_mesh *m, subd_real cos_limit)
{
    uint32_t h, tagged = 0;
    int all;
    subd_wide a[3], b[3];
    if (!m || !m->num_corners ||
        !subd_topo_has(m, TOPO_ALWAYS | TOPO_TWIN | TOPO_CORNER_FACE | TOPO_FACE_START | TOPO_CORNER_VERT | TOPO_POS |
                              TOPO_EDGE_TAG))
        return 0; /* no mesh or no adjacency: nothing tagged */
    if (cos_limit < -SUBD_REAL_ONE) return 0; /* < -1: no angle exceeds it */
    all = cos_limit > SUBD_REAL_ONE;          /* > 1: every angle does     */
    for (h = 0; h < m->num_corners; h++) {
        uint32_t t = m->twin[h];
        if (t == SUBD_NONE || t < h) continue; /* each interior edge once */
        face_normal(m, m->corner_face[h], a);
        face_normal(m, m->corner_face[t], b);
        if (all || angle_exceeds(a, b, cos_limit)) {
            subd_edge_tag_set(m, h, SUBD_ETAG_CREASE);
            tagged++;
        }
    }
    return tagged;
}
