/* SPDX-License-Identifier: MIT */
/* Quasi 4-8 subdivision.
 *
 * Paper: L. Velho, "Quasi 4-8 Subdivision" (quasi-4-8-subdivision.txt): section 3.1,
 * Algorithm 1 (refinement: sort_edges, split, mark_cluster, subdiv), section 3.2,
 * Algorithm 2 (two-pass smoothing), section 4.3 (tagged features, boundaries).
 *
 * Choices where the paper is silent:
 *  - "sorts edges by decreasing length and radially around each vertex": edges are first
 *    numbered radially (vertices in index order; around each vertex its not yet numbered
 *    edges in one-ring order from vert_out), then stably sorted by decreasing squared
 *    length, so equal lengths are processed in that radial order. Around a vertex of
 *    valence n whose edges are all equal and longest, the first edge splits, its cluster
 *    marks both neighbours, the third splits, ... - alternate edges split, which is what
 *    figures 5(d) (hexagon: centre keeps valence 6) and 8(a) (12-gon: radial decomposition,
 *    centre keeps 12) show; for odd n (9-gon) the last face is left over and its rim edge
 *    splits (centre valence 10, figure 8(c)). The figures come out when the centre vertex
 *    is numbered first (it is vertex 0 in every fan we build and in hexfan.obj).
 *  - Lengths are compared after rounding the squared length to opts.len_bits significant
 *    bits (default 12, round to nearest; integer/bit arithmetic only). The regular
 *    polygons' equal edges are equal in exact arithmetic but not after rounding their
 *    vertices to float32 or Q16.16 (Q16.16: the hexagon's spokes at 60 degrees come out
 *    4e-6 longer than those at 0 degrees); the paper's figures depend on those ties, so
 *    without this the fixed build would give the perturbed-hexagon topology (centre 8).
 *  - Squared lengths, their keys and the stable radix sort: src/edge_sort.c (shared with
 *    the semi-regular 4-8 pre-processing).
 *  - New vertices are edge midpoints (refinement is purely topological plus midpoints);
 *    Algorithm 2 then moves them.
 *  - Section 4.3, "a tagged vertex or edge is not affected by smoothing": vertices tagged
 *    CORNER or FIXED and both ends of a CREASE edge keep their position; a new vertex on a
 *    crease stays at the edge's midpoint, and both halves keep the crease tag, so a tagged
 *    polyline keeps its shape at every step.
 *  - Section 4.3, "boundary vertices are constrained to move along the surface normal
 *    direction": SUBD_QUASI48_BOUNDARY_NORMAL. The paper names neither the normal nor the
 *    displacement: the displacement is the interior rule's (every new neighbour counts),
 *    the normal the area-weighted one of the vertex's faces in the step's input (read-only
 *    during pass 2, so the visiting order does not matter), and only the normal component
 *    is applied (q48_smooth_normal); a zero normal leaves the vertex. New boundary vertices
 *    stay at edge midpoints (their interior-rule displacement lies in their face's plane).
 *    The other modes: fixed, as in its planar figures, or smoothed as curves.
 *  - Smoothing of an old vertex uses exact weights: Q16.16 forms (k p + sum) / (2k) in 64
 *    bits with one rounding, so planar input stays exactly planar in z and weights sum to 1.
 *
 * Memory: two mesh buffers sized by the per-step bounds (ping-pong, the last step writes
 * the lower one, which becomes the output) and one set of per-step arrays sized for the
 * largest step, all planned by q48_layout.
 *
 * Adjacency: the general builder (subd_mesh_finish) would cost a validation and a bucket
 * pass with random access per step, most of a step's time on large meshes. A split only
 * cuts faces along edges of a valid manifold mesh, so the child's twins follow from the
 * parent's (q48_link_twins) and its fans from its corners (subd_mesh_fans, the builder's own
 * convention in mesh.c); both give exactly the arrays, tags and counts the builder would
 * give, in O(C).
 */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "mesh_internal.h"
#include "topo.h"
#include "subd_quasi48.h"
#include "edge_sort.h"
#include "real_avg.h"
#include "layout.h"
#include "entry.h"
#include "vec3w.h"

typedef struct q48_layout {
    mesh_counts out;  /* bound for the last step's output                                */
    mesh_counts mid;  /* bound for the output of step steps-1 (second buffer)            */
    uint32_t cs;      /* corners of the largest step input (bound for its edge count)    */
    uint32_t bytes;
} q48_layout;

typedef struct q48_work {
    subd_edge_work es;  /* edge numbering, sort and cluster marks (edge_sort.c)          */
    uint32_t *split;    /* per edge: the new vertex, or SUBD_NONE                        */
    uint8_t *vkeep;     /* per output vertex: caller tags, then "pinned" during smoothing */
} q48_work;

/* Bytes from the start of mesh buffer c when `above` bytes are allocated after it.
 * subd_mesh_alloc_arrays hands out a buffer only when the builder's scratch would fit above
 * it as well; quasi 4-8 never runs the builder, but the plan must leave that room at each
 * allocation (it exceeds `above` only for inputs with many isolated vertices). */
static uint32_t buffer_then(const mesh_counts *c, uint32_t above)
{
    uint32_t b = subd_mesh_arrays_bytes(c), s = subd_mesh_scratch_bytes(c);
    subd_bytes_add(&b, subd_bytes_max(above, s));
    return b;
}

static int counts_for(const subd_mesh *in, uint32_t s, mesh_counts *c)
{
    uint64_t f = (uint64_t)in->num_faces << s;
    uint64_t v = (uint64_t)in->num_verts + f - in->num_faces;
    if (3u * f >= UINT32_MAX || v >= UINT32_MAX) return SUBD_ERR_TOO_BIG;
    c->nv = (uint32_t)v;
    c->nf = (uint32_t)f;
    c->nc = (uint32_t)(3u * f);
    c->nl = in->num_lines;
    c->nlv = in->num_line_verts;
    return SUBD_OK;
}

/* The one layout of the per-step arrays (layout.h): plan and run both call it, so they
 * cannot drift apart. With a == NULL it only counts (w may be NULL). */
static int q48_layout_work(subd_arena *a, const q48_layout *L, q48_work *w, uint32_t *bytes)
{
    subd_layout l;
    q48_work tmp;
    q48_work *p = w ? w : &tmp;
    subd_layout_begin(&l, a);
    p->es.key[0] = subd_layout_take(&l, L->cs, 8u);
    p->es.key[1] = subd_layout_take(&l, L->cs, 8u);
    p->es.edge_of = subd_layout_take(&l, L->cs, 4u);
    p->es.edge_he = subd_layout_take(&l, L->cs, 4u);
    p->es.ord[0] = subd_layout_take(&l, L->cs, 4u);
    p->es.ord[1] = subd_layout_take(&l, L->cs, 4u);
    p->split = subd_layout_take(&l, L->cs, 4u);
    p->es.mark = subd_layout_take(&l, L->cs, 1u);
    p->es.cnt = subd_layout_take(&l, 256u, 4u);
    p->vkeep = subd_layout_take(&l, L->out.nv, 1u);
    return subd_layout_end(&l, bytes);
}

static int q48_check(const subd_mesh *in, const subd_quasi48_opts *o, subd_diag *d)
{
    int st;
    if (!in || !o || o->steps < 1u || o->steps > SUBD_QUASI48_MAX_STEPS || o->len_bits > SUBD_QUASI48_LEN_BITS_EXACT ||
        (o->boundary != SUBD_QUASI48_BOUNDARY_FIXED && o->boundary != SUBD_QUASI48_BOUNDARY_SMOOTH &&
         o->boundary != SUBD_QUASI48_BOUNDARY_NORMAL))
        return subd_fail(d, SUBD_ERR_PARAM);
    if (!subd_topo_has(in, TOPO_IF_FACES | TOPO_TWIN | TOPO_VERT_OUT | TOPO_CORNER_FACE | TOPO_EDGE_TAG))
        return subd_fail(d, SUBD_ERR_PARAM);
    if ((st = subd_require_triangles(in, d)) != SUBD_OK) return st;
    if (in->num_faces == 0) return subd_fail(d, SUBD_ERR_EMPTY);
    return SUBD_OK;
}

static int q48_plan(const subd_mesh *in, const subd_quasi48_opts *o, q48_layout *L, subd_diag *d)
{
    uint32_t b, wb;
    int st;
    if ((st = q48_check(in, o, d)) != SUBD_OK) return st;
    if ((st = counts_for(in, o->steps, &L->out)) != SUBD_OK) return subd_fail(d, st);
    if ((st = counts_for(in, o->steps - 1u, &L->mid)) != SUBD_OK) return subd_fail(d, st);
    L->cs = L->mid.nc; /* input of the last step: the output bound of step steps-1 */
    /* allocation order: buf[0] (out), buf[1] (mid, steps >= 2), the per-step arrays */
    q48_layout_work(0, L, 0, &wb);
    b = (o->steps >= 2u) ? buffer_then(&L->mid, wb) : wb;
    b = buffer_then(&L->out, b);
    L->bytes = b;
    if (b == UINT32_MAX) return subd_fail(d, SUBD_ERR_TOO_BIG);
    return SUBD_OK;
}

int subd_quasi48_plan(const subd_mesh *in, const subd_quasi48_opts *o, uint32_t *bytes, subd_diag *diag)
{
    subd_diag own, *d = subd_plan_begin(&own, diag);
    q48_layout L;
    int st;
    if (!bytes) return subd_plan_end(d, SUBD_ERR_PARAM);
    st = q48_plan(in, o, &L, d);
    if (st == SUBD_OK) *bytes = L.bytes;
    return subd_plan_end(d, st);
}

/* ------------------------------------------------------------------------------------ */
/* Navigation in the child meshes, whose face f is corners 3f..3f+2 (q48_split_faces writes
 * them so): the same half-edges as subd_he_next/prev, without loading corner_face and
 * face_start (tri_next, tri_prev: mesh_internal.h; rings: topo_ring_begin_tri). */

static uint32_t tri_dest(const subd_mesh *m, uint32_t h) { return m->corner_vert[tri_next(h)]; }

/* ------------------------------------------------------------------------------------ */
/* Algorithm 1: refinement.                                                               */

/* The side (0..2) of parent face f whose edge is split, or 3 when none is. The marking
 * leaves at most one split edge per face. */
static uint32_t split_side(const subd_mesh *m, const q48_work *w, uint32_t f)
{
    uint32_t s = m->face_start[f], j;
    for (j = 0; j < 3u; j++)
        if (w->split[w->es.edge_of[s + j]] != SUBD_NONE) return j;
    return 3u;
}

/* subdiv: a face with split edge (a, b) -> v and opposite vertex c becomes (a, v, c) at its
 * index and (v, b, c) appended in face order; other faces are copied. Crease tags pass to
 * both halves of a split edge and stay on unsplit sides. map[p] records where parent
 * half-edge p went: its child half-edge, or for a split half-edge its second half (v, b);
 * the first half (a, v) is always corner 0 of the face's kept child. side[f] keeps f's
 * split_side for q48_link_twins. */
static void q48_split_faces(const subd_mesh *m, subd_mesh *o, const q48_work *w, uint32_t *map,
                            uint8_t *side)
{
    const uint8_t cr = SUBD_ETAG_CREASE;
    uint32_t f, j, k = m->num_faces; /* k: next appended face */
    for (f = 0; f <= o->num_faces; f++) o->face_start[f] = 3u * f;
    for (f = 0; f < m->num_faces; f++) {
        uint32_t s = m->face_start[f], at = 3u * f;
        o->corner_face[at] = o->corner_face[at + 1u] = o->corner_face[at + 2u] = f;
        j = split_side(m, w, f);
        side[f] = (uint8_t)j;
        if (j == 3u) {
            for (j = 0; j < 3u; j++) {
                o->corner_vert[at + j] = m->corner_vert[s + j];
                o->edge_tag[at + j] = (uint8_t)(m->edge_tag[s + j] & cr);
                map[s + j] = at + j;
            }
        } else {
            uint32_t h = s + j, h1 = s + (j + 1u) % 3u, h2 = s + (j + 2u) % 3u, bt = 3u * k;
            uint32_t v = w->split[w->es.edge_of[h]];
            uint8_t hc = (uint8_t)(m->edge_tag[h] & cr);
            o->corner_vert[at] = m->corner_vert[h];
            o->corner_vert[at + 1u] = v;
            o->corner_vert[at + 2u] = m->corner_vert[h2];
            o->edge_tag[at] = hc;
            o->edge_tag[at + 1u] = 0;
            o->edge_tag[at + 2u] = (uint8_t)(m->edge_tag[h2] & cr);
            o->corner_vert[bt] = v;
            o->corner_vert[bt + 1u] = m->corner_vert[h1];
            o->corner_vert[bt + 2u] = m->corner_vert[h2];
            o->edge_tag[bt] = hc;
            o->edge_tag[bt + 1u] = (uint8_t)(m->edge_tag[h1] & cr);
            o->edge_tag[bt + 2u] = 0;
            o->corner_face[bt] = o->corner_face[bt + 1u] = o->corner_face[bt + 2u] = k;
            map[h] = bt;
            map[h1] = bt + 1u;
            map[h2] = at + 2u;
            k++;
        }
    }
}

/* Twin of the child of an unsplit parent half-edge p: the child of p's twin. */
static uint32_t child_twin(const subd_mesh *m, const uint32_t *map, uint32_t p)
{
    uint32_t t = m->twin[p];
    return (t == SUBD_NONE) ? SUBD_NONE : map[t];
}

/* Twins of the child from the parent's: unsplit sides pair as their parents did; the halves
 * of a split edge (a, v), (v, b) pair with the halves (v, a), (b, v) of its twin, which was
 * split at the same vertex (both faces of a split edge are cut by it); the cut (v, c) pairs
 * with (c, v). */
static void q48_link_twins(const subd_mesh *m, subd_mesh *o, const uint32_t *map, const uint8_t *side)
{
    uint32_t f, j;
    for (f = 0; f < m->num_faces; f++) {
        uint32_t s = m->face_start[f], at = 3u * f;
        j = side[f];
        if (j == 3u) {
            for (j = 0; j < 3u; j++) o->twin[at + j] = child_twin(m, map, s + j);
        } else {
            uint32_t h = s + j, h1 = s + (j + 1u) % 3u, h2 = s + (j + 2u) % 3u, bt = map[h], t = m->twin[h];
            o->twin[at] = (t == SUBD_NONE) ? SUBD_NONE : map[t];                    /* (v, a) */
            o->twin[bt] = (t == SUBD_NONE) ? SUBD_NONE : 3u * m->corner_face[t];    /* (b, v) */
            o->twin[at + 1u] = bt + 2u;
            o->twin[bt + 2u] = at + 1u;
            o->twin[at + 2u] = child_twin(m, map, h2);
            o->twin[bt + 1u] = child_twin(m, map, h1);
        }
    }
}

/* Position of the new vertex on parent half-edge h (a->b): the midpoint (Algorithm 1); with
 * smoothing, unless the vertex is pinned (a boundary or crease edge: section 4.3), Algorithm
 * 2's pass 1 replaces it by the average of its four neighbours, all old vertices, so it is
 * computed here from the parent without a walk in the child. Float sums depend on their
 * order, so the neighbours are added in the order of the child's ring walk from vert_out:
 * vert_out is v's lowest corner, the cut (v, c) of the lower-numbered of the edge's two
 * faces, and the walk from there visits c, a, d, b for that face's half-edge a->b, its
 * opposite vertex c and the other face's opposite vertex d. */
static void q48_new_position(const subd_mesh *m, uint32_t h, int smooth, subd_real *out, uint32_t *ovf)
{
    const subd_real *p = m->pos + 3u * subd_he_origin(m, h), *q = m->pos + 3u * subd_he_dest(m, h);
    uint32_t t = m->twin[h], k;
    for (k = 0; k < 3u; k++) out[k] = subd_mid(p[k], q[k], ovf);
    if (!smooth || topo_mesh_edge_sharp(m, h)) return; /* pinned: a boundary or crease edge */
    if (m->corner_face[t] < m->corner_face[h]) {
        uint32_t x = h;
        h = t;
        t = x;
    }
    {
        const subd_real *r[4];
        r[0] = m->pos + 3u * m->corner_vert[subd_he_prev(m, h)];
        r[1] = m->pos + 3u * subd_he_origin(m, h);
        r[2] = m->pos + 3u * m->corner_vert[subd_he_prev(m, t)];
        r[3] = m->pos + 3u * subd_he_dest(m, h);
        for (k = 0; k < 3u; k++) {
            subd_sum s = 0;
            s = subd_sum_add(s, r[0][k]);
            s = subd_sum_add(s, r[1][k]);
            s = subd_sum_add(s, r[2][k]);
            s = subd_sum_add(s, r[3][k]);
            out[k] = subd_avg(s, 4u, ovf);
        }
    }
}

static int q48_refine(const subd_mesh *m, subd_mesh *o, const mesh_counts *cap, uint32_t bits, int smooth,
                      q48_work *w, subd_diag *d)
{
    const uint32_t nv = m->num_verts, nf = m->num_faces;
    uint32_t ne, i, e, ns, nsf = 0, ovf = 0;

    /* sort_edges, then split unmarked edges and mark their clusters (edge_sort.c) */
    ne = subd_edge_number(m, &w->es, m->num_corners);
    if (ne == SUBD_NONE) return subd_fail(d, SUBD_ERR_PARAM); /* cannot happen: E <= corners */
    ns = subd_edge_clusters(m, &w->es, ne, bits, 0, nv, w->split);
    /* faces cut: one per split boundary edge, two per split interior edge (a face has at
     * most one split edge) */
    for (e = 0; e < ne; e++)
        if (w->split[e] != SUBD_NONE) nsf += (m->twin[w->es.edge_he[e]] == SUBD_NONE) ? 1u : 2u;
    /* ns <= nsf <= nf by the marking, so the bounds hold; checked anyway */
    if (nv + ns > cap->nv || nf + nsf > cap->nf) return subd_fail(d, SUBD_ERR_NOMEM);

    o->num_verts = nv + ns;
    o->num_faces = nf + nsf;
    o->num_corners = 3u * (nf + nsf);
    o->num_lines = m->num_lines;
    o->num_line_verts = m->num_line_verts;

    /* positions: old vertices copied (q48_smooth moves them later), new ones placed */
    for (i = 0; i < 3u * nv; i++) o->pos[i] = m->pos[i];
    for (e = 0; e < ne; e++) {
        if (w->split[e] == SUBD_NONE) continue;
        q48_new_position(m, w->es.edge_he[e], smooth, o->pos + 3u * w->split[e], &ovf);
    }
    if (ovf) return subd_fail(d, SUBD_ERR_RANGE);
    for (i = 0; i < nv; i++) w->vkeep[i] = (uint8_t)(m->vert_tag[i] & (SUBD_VTAG_CORNER | SUBD_VTAG_FIXED));
    for (; i < nv + ns; i++) w->vkeep[i] = 0;

    /* the sort's order array and the cluster marks are free once the clusters are marked:
     * they hold the half-edge map (one entry per parent corner) and the split side per
     * parent face; both have an entry per corner of the largest step's input */
    q48_split_faces(m, o, w, w->es.ord[0], w->es.mark);
    q48_link_twins(m, o, w->es.ord[0], w->es.mark);
    subd_mesh_fans(o, w->vkeep); /* the builder's fans, tags and counts (mesh.c) */
    o->line_start[0] = 0;
    for (i = 0; i < m->num_lines; i++) o->line_start[i + 1u] = m->line_start[i + 1u];
    for (i = 0; i < m->num_line_verts; i++) o->line_vert[i] = m->line_vert[i];
    return SUBD_OK;
}

/* ------------------------------------------------------------------------------------ */
/* Algorithm 2, pass 2, in place: vertices >= nv_old are the step's new vertices, already
 * smoothed by pass 1 (q48_new_position).                                                 */

/* Pass 2 for old vertex v: 1/2 its position + 1/2 the average of its new neighbours (in
 * ring order from vert_out; none: unchanged), written to t[0..2]. On a boundary, `curve`
 * (smooth mode) counts only the two boundary neighbours; otherwise (normal mode) every
 * neighbour counts, the last boundary one after the ring walk. Returns 0 when v has no new
 * neighbour (t untouched). */
static uint32_t q48_pass2(const subd_mesh *o, uint32_t v, uint32_t nv_old, int curve, subd_real *t, uint32_t *ovf)
{
    uint32_t first = o->vert_out[v], n = 0, k;
    subd_sum s[3] = {0, 0, 0};
    int bnd = o->twin[first] == SUBD_NONE;
    topo_ring r; /* topo.h's walk; on a boundary its tail, the incoming boundary edge's origin,
                  * closes the fan and counts in both modes */
    topo_ring_begin_tri(&r, o->corner_vert, o->twin, o->num_corners, first);
    while (topo_ring_step(&r)) {
        uint32_t u = r.nb;
        if (u < nv_old || (bnd && curve && !r.tail && r.he != first)) continue;
        for (k = 0; k < 3u; k++) s[k] = subd_sum_add(s[k], o->pos[3u * u + k]);
        n++;
    }
    if (n == 0) return 0;
    for (k = 0; k < 3u; k++) t[k] = subd_blend(o->pos[3u * v + k], s[k], n, ovf);
    return n;
}

/* Area-weighted normal of vertex v of the step's input m (section 4.3, normal mode): the
 * sum over v's faces (v, b, c) of (b - v) x (c - v), twice the area times the unit normal,
 * from the positions before the step, so it does not depend on the order in which pass 2
 * moves vertices. Q16.16: exact int64 arithmetic after one common shift of every edge
 * vector of the fan (truncating toward zero, so sign changes commute with it) chosen so
 * that no sum overflows: components below 2^b with 2b + 1 + bitlen(faces) <= 62. float32:
 * the subd_w3 products in their fixed order; non-finite only for coordinates near 1e19.
 * Why the two #ifs: the Q16.16 algorithm needs that shift, found by a first walk of the
 * fan, which float32 does not need (vec3w.h's subd_w3_span_* would express both builds in
 * one text, as in crease.c's face_shift; left for after the ring-walk rework of this file). */
static void q48_vertex_normal(const subd_mesh *m, uint32_t v, subd_wide *n)
{
    const subd_real *pv = m->pos + 3u * v;
    uint32_t k;
    int32_t sh = 0;
    subd_wide e0[3], e1[3], c[3];
    topo_ring r; /* v's faces (v, b, c): the outgoing half-edges v -> b, c = prev's origin */
#if SUBD_FIXED
    uint64_t big = 0;
    uint32_t nf = 0, bits;
    topo_ring_begin(&r, m, v);
    while (topo_ring_step(&r) && !r.tail) {
        subd_w3_diff(m->pos + 3u * r.nb, pv, e0);
        subd_w3_diff(m->pos + 3u * m->corner_vert[topo_ring_prev_he(&r, r.he)], pv, e1);
        if (subd_w3_maxabs(e0) > big) big = subd_w3_maxabs(e0);
        if (subd_w3_maxabs(e1) > big) big = subd_w3_maxabs(e1);
        nf++;
    }
    bits = (61u - subd_bitlen64(nf)) / 2u;
    sh = (int32_t)subd_bitlen64(big) - (int32_t)bits;
    if (sh < 0) sh = 0;
#endif
    n[0] = n[1] = n[2] = 0;
    topo_ring_begin(&r, m, v);
    while (topo_ring_step(&r) && !r.tail) {
        subd_w3_diff(m->pos + 3u * r.nb, pv, e0);
        subd_w3_diff(m->pos + 3u * m->corner_vert[topo_ring_prev_he(&r, r.he)], pv, e1);
#if SUBD_FIXED
        subd_w3_shift(e0, e0, sh);
        subd_w3_shift(e1, e1, sh);
#endif
        subd_w3_cross(e0, e1, c);
        for (k = 0; k < 3u; k++) n[k] += c[k];
    }
    (void)sh;
}

/* p += ((t - p) . n / n . n) n: only the normal component of the displacement t - p; n = 0
 * leaves p. Both forms are symmetric under negating any axis and exchanging x and y (a
 * rotation by 90 degrees about z maps the output bit for bit; Q16.16: any axis
 * permutation, its sums being exact). Q16.16: the displacement is exact (|d| < 2^32); n is
 * rescaled to 20 bits, direction kept to 2^-19 (subd_w3_normalize), so d . n < 2^54 and
 * n . n < 2^42; (d . n) n_j / (n . n) is formed as q n_j + round(r n_j / n . n) from the
 * truncating quotient q and remainder r, exact but for that one rounding; a result outside
 * the Q16.16 range sets *ovf (a component can move further than the displacement's);
 * vec3w.h's subd_w3_add_ratio. float32: n is scaled to max |n_k| = 1 first, so n . n is
 * in [1, 3]. */
static void q48_project_normal(subd_real *p, const subd_real *t, const subd_wide *n, uint32_t *ovf)
{
    subd_wide u[3], d[3], dn, nn;
    subd_w3_normalize(n, u, 20u);
    nn = subd_w3_dot(u, u);
    if (!(nn > 0)) return; /* zero normal (faces cancel or are degenerate): v stays */
    subd_w3_diff(t, p, d);
    dn = subd_w3_dot(d, u);
    subd_w3_add_ratio(p, dn, nn, u, ovf);
}

/* Normal mode for old boundary vertex v: the interior rule's target (every new neighbour),
 * of which only the displacement along v's normal in the step's input m is taken. */
static void q48_smooth_normal(subd_mesh *o, const subd_mesh *m, uint32_t v, uint32_t nv_old, uint32_t *ovf)
{
    subd_real t[3];
    subd_wide n[3];
    uint32_t k;
    if (!q48_pass2(o, v, nv_old, 0, t, ovf)) return;
    q48_vertex_normal(m, v, n);
#if !SUBD_FIXED /* why: float32 products can overflow to infinity (Q16.16's cannot, by the
                 * shift in q48_vertex_normal) */
    for (k = 0; k < 3u; k++) (void)subd_chk(n[k], ovf);
    if (*ovf) return;
#endif
    (void)k;
    q48_project_normal(o->pos + 3u * v, t, n, ovf);
}

static int q48_smooth(subd_mesh *o, const subd_mesh *m, subd_quasi48_boundary bmode, const q48_work *w,
                      subd_diag *d)
{
    uint8_t *pin = w->vkeep;
    const uint32_t nv_old = m->num_verts;
    uint32_t v, h, c, ovf = 0;
    const uint8_t fixed_bits = (uint8_t)(SUBD_VTAG_CORNER | SUBD_VTAG_FIXED | SUBD_VTAG_ISOLATED);

    for (v = 0; v < nv_old; v++) {
        uint8_t t = o->vert_tag[v];
        pin[v] = (uint8_t)((t & fixed_bits) != 0 ||
                           ((t & SUBD_VTAG_BOUNDARY) && bmode == SUBD_QUASI48_BOUNDARY_FIXED));
    }
    for (h = 0; h < o->num_corners; h++) {
        if (o->edge_tag[h] & SUBD_ETAG_CREASE) { /* only old vertices are read below */
            pin[o->corner_vert[h]] = 1;
            pin[tri_dest(o, h)] = 1;
        }
    }
    /* pass 1 (new vertices = average of their neighbours) was done by q48_new_position */
    /* pass 2 (q48_pass2). A vertex reads only new vertices (and, in normal mode, the step's
     * input m) and writes only itself, so the order of visits is free: each is visited at
     * its vert_out corner, in corner order, so that consecutive walks stay in neighbouring
     * faces (vertex order is split order, longest edge first, which scatters consecutive
     * vertices over the mesh). */
    for (c = 0; c < o->num_corners; c++) {
        v = o->corner_vert[c];
        if (v >= nv_old || pin[v] || o->vert_out[v] != c) continue;
        if (bmode == SUBD_QUASI48_BOUNDARY_NORMAL && o->twin[c] == SUBD_NONE)
            q48_smooth_normal(o, m, v, nv_old, &ovf);
        else
            (void)q48_pass2(o, v, nv_old, 1, o->pos + 3u * v, &ovf);
    }
    if (ovf) return subd_fail(d, SUBD_ERR_RANGE);
    return SUBD_OK;
}

/* ------------------------------------------------------------------------------------ */

int subd_quasi48(subd_arena *a, const subd_mesh *in, const subd_quasi48_opts *o, subd_mesh *out, subd_diag *diag)
{
    subd_entry e;
    subd_diag *d = subd_entry_begin(&e, a, diag);
    q48_layout L;
    q48_work w;
    subd_mesh buf[2];
    const subd_mesh *src = in;
    uint32_t keep, s, wb, bits;
    int st, smooth;

    if (!a || !out) return subd_entry_fail(&e, SUBD_ERR_PARAM);
    if ((st = q48_plan(in, o, &L, d)) != SUBD_OK) return subd_entry_fail(&e, st);
    d->bytes_needed = L.bytes;
    if (L.bytes > subd_arena_free_bytes(a)) return subd_entry_fail(&e, SUBD_ERR_NOMEM);
    bits = o->len_bits ? o->len_bits : SUBD_QUASI48_LEN_BITS_DEFAULT;
    smooth = !(o->flags & SUBD_QUASI48_NO_SMOOTH);

    st = subd_mesh_alloc_arrays(a, &L.out, &buf[0]);
    keep = subd_arena_mark(a);
    if (st == SUBD_OK && o->steps >= 2u) st = subd_mesh_alloc_arrays(a, &L.mid, &buf[1]);
    if (st == SUBD_OK) st = q48_layout_work(a, &L, &w, &wb);
    if (st != SUBD_OK) return subd_entry_fail(&e, st);

    for (s = 1; s <= o->steps; s++) {
        /* the last step writes buf[0]; earlier steps alternate, never onto their input */
        subd_mesh *dst = &buf[(o->steps - s) & 1u];
        const mesh_counts *cap = ((o->steps - s) & 1u) ? &L.mid : &L.out;
        st = q48_refine(src, dst, cap, bits, smooth, &w, d);
        if (st == SUBD_OK && smooth) st = q48_smooth(dst, src, o->boundary, &w, d);
        if (st != SUBD_OK) return subd_entry_fail(&e, st);
        src = dst;
    }
    subd_arena_rewind(a, keep);
    *out = buf[0];
    return subd_entry_ok(&e);
}

void subd_quasi48_opts_default(subd_quasi48_opts *o)
{
    if (!o) return;
    o->steps = 2;
    o->boundary = SUBD_QUASI48_BOUNDARY_FIXED;
    o->flags = 0;
    o->len_bits = SUBD_QUASI48_LEN_BITS_DEFAULT;
}
