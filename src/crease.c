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
 */
#include "subd.h"

#if SUBD_FIXED
typedef int64_t crease_n; /* components of a normal, |x| < 2^10 after face_normal */
#define N_BITS 10
#else
typedef float crease_n;
#endif

/* Normal of face f by Newell's method over the fan from its first corner. */
static void face_normal(const subd_mesh *m, uint32_t f, crease_n n[3])
{
    uint32_t s = m->face_start[f], e = m->face_start[f + 1u], c, k;
    const subd_real *p0 = &m->pos[3u * m->corner_vert[s]];
#if SUBD_FIXED
    int64_t acc[3] = {0, 0, 0}, big = 0, a[3], b[3];
    uint32_t shift = 0;
    for (c = s; c < e; c++)
        for (k = 0; k < 3u; k++) {
            int64_t x = (int64_t)m->pos[3u * m->corner_vert[c] + k] - p0[k];
            if (x > big) big = x;
            if (-x > big) big = -x;
        }
    while ((big >> shift) >= ((int64_t)1 << 28)) shift++;
    for (c = s + 1u; c + 1u < e; c++) {
        for (k = 0; k < 3u; k++) {
            a[k] = ((int64_t)m->pos[3u * m->corner_vert[c] + k] - p0[k]) / ((int64_t)1 << shift);
            b[k] = ((int64_t)m->pos[3u * m->corner_vert[c + 1u] + k] - p0[k]) / ((int64_t)1 << shift);
        }
        acc[0] += a[1] * b[2] - a[2] * b[1];
        acc[1] += a[2] * b[0] - a[0] * b[2];
        acc[2] += a[0] * b[1] - a[1] * b[0];
    }
    big = 0;
    for (k = 0; k < 3u; k++) {
        if (acc[k] > big) big = acc[k];
        if (-acc[k] > big) big = -acc[k];
    }
    shift = 0;
    while ((big >> shift) >= ((int64_t)1 << N_BITS)) shift++;
    for (k = 0; k < 3u; k++) n[k] = acc[k] / ((int64_t)1 << shift);
#else
    float acc[3] = {0.0f, 0.0f, 0.0f}, big = 0.0f;
    for (c = s + 1u; c + 1u < e; c++) {
        const subd_real *p1 = &m->pos[3u * m->corner_vert[c]], *p2 = &m->pos[3u * m->corner_vert[c + 1u]];
        float a[3], b[3];
        for (k = 0; k < 3u; k++) {
            a[k] = p1[k] - p0[k];
            b[k] = p2[k] - p0[k];
        }
        acc[0] += a[1] * b[2] - a[2] * b[1];
        acc[1] += a[2] * b[0] - a[0] * b[2];
        acc[2] += a[0] * b[1] - a[1] * b[0];
    }
    for (k = 0; k < 3u; k++) {
        float x = acc[k] < 0.0f ? -acc[k] : acc[k];
        if (x > big) big = x;
    }
    for (k = 0; k < 3u; k++) n[k] = big > 0.0f ? acc[k] / big : 0.0f;
#endif
}

/* True when the angle between a and b exceeds the angle whose cosine is c. A zero normal
 * (degenerate face) never makes a crease. */
static int angle_exceeds(const crease_n a[3], const crease_n b[3], subd_real c)
{
    crease_n dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    crease_n aa = a[0] * a[0] + a[1] * a[1] + a[2] * a[2];
    crease_n bb = b[0] * b[0] + b[1] * b[1] + b[2] * b[2];
#if SUBD_FIXED
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
    crease_n a[3], b[3];
    for (h = 0; h < m->num_corners; h++) {
        uint32_t t = m->twin[h];
        if (t == SUBD_NONE || t < h) continue; /* each interior edge once */
        face_normal(m, m->corner_face[h], a);
        face_normal(m, m->corner_face[t], b);
        if (angle_exceeds(a, b, cos_limit)) {
            subd_edge_tag_set(m, h, SUBD_ETAG_CREASE);
            tagged++;
        }
    }
    return tagged;
}
