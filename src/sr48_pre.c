/* SPDX-License-Identifier: MIT */
/* Semi-regular 4-8 refinement: pre-processing (paper: semi-regular-4-8-refinement-box-splines.txt,
 * section 5): find_clusters (Algorithm 1), the hybrid binary subdivision (cluster diagonals
 * split, isolated triangles split barycentrically) and the first regular binary step that
 * splits every original edge; the result is level 0 of the hierarchy, a triangulated
 * quadrangulation whose triangles know their base edges.
 *
 * Choices where the paper is silent:
 *  - find_clusters uses quasi 4-8's sort_edges and mark_cluster (src/edge_sort.c) with the
 *    default length resolution SUBD_QUASI48_LEN_BITS_DEFAULT (12 significant bits of the squared
 *    length, so lengths equal in exact arithmetic tie in both arithmetics and go by the
 *    radial numbering). Only interior edges can be a cluster diagonal: a boundary edge is
 *    skipped (not selected, nothing marked).
 *  - Numbering: face points in order of the lower face index of their cluster (isolated
 *    triangles: their own index), then one edge point per non-diagonal edge in the radial
 *    edge numbering order. Hybrid triangles of face f (fstart[f]...): a cluster face
 *    (x; u, w) with diagonal u -> w gives (p; x, u), (p; w, x); an isolated face (a, b, c)
 *    gives (g; a, b), (g; b, c), (g; c, a) (p, g the face point; the apex first, the base
 *    an original edge). Level 0 triangles 2H, 2H+1 are the children of hybrid triangle H.
 *  - Positions: cluster face point = centroid of the four vertices (NO_SMOOTH: midpoint of
 *    the diagonal), isolated face point = barycentre, edge point = edge midpoint; the
 *    smoothing of input vertices and face points is done by sr48_refine.c.
 */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "sr48_internal.h"

int subd_sr48_pre_alloc_a(subd_arena *a, const subd_mesh *in, sr48_pre *w, uint32_t *bytes, uint32_t *keep)
{
    const uint32_t ne = in->num_edges;
    subd_layout l;
    sr48_pre tmp;
    sr48_pre *p = w ? w : &tmp;
    subd_layout_begin(&l, a);
    p->es.edge_of = subd_layout_take(&l, in->num_corners, 4u);
    p->es.edge_he = subd_layout_take(&l, ne, 4u);
    p->sel = subd_layout_take(&l, ne, 4u);
    *keep = l.bytes;
    p->es.key[0] = subd_layout_take(&l, ne, 8u);
    p->es.key[1] = subd_layout_take(&l, ne, 8u);
    p->es.ord[0] = subd_layout_take(&l, ne, 4u);
    p->es.ord[1] = subd_layout_take(&l, ne, 4u);
    p->es.mark = subd_layout_take(&l, ne, 1u);
    p->es.cnt = subd_layout_take(&l, 256u, 4u);
    return subd_layout_end(&l, bytes);
}

int subd_sr48_pre_alloc_b(subd_arena *a, const sr48_layout *L, sr48_pre *w, uint32_t *bytes)
{
    subd_layout l;
    sr48_pre tmp;
    sr48_pre *p = w ? w : &tmp;
    subd_layout_begin(&l, a);
    p->fstart = subd_layout_take(&l, L->nf, 4u);
    p->fpt = subd_layout_take(&l, L->nf, 4u);
    p->hnb = subd_layout_take(&l, L->nhyb, 4u);
    return subd_layout_end(&l, bytes);
}

int subd_sr48_find_clusters(const subd_mesh *in, sr48_pre *w, uint32_t *clusters)
{
    uint32_t ne = subd_edge_number(in, &w->es, in->num_edges);
    if (ne != in->num_edges) return SUBD_ERR_PARAM; /* the mesh's summary does not match */
    *clusters = subd_edge_clusters(in, &w->es, ne, SUBD_QUASI48_LEN_BITS_DEFAULT, 1, 0, w->sel);
    return SUBD_OK;
}

/* Corner (0..2) of the face's cluster diagonal, or 3 for an isolated triangle. */
static uint32_t diag_corner(const sr48_pre *w, uint32_t s)
{
    uint32_t j;
    for (j = 0; j < 3u; j++)
        if (w->sel[w->es.edge_of[s + j]] == SR48_DIAG) return j;
    return 3u;
}

/* Hybrid triangle whose base is input half-edge h (not a diagonal). */
static uint32_t hyb_of(const subd_mesh *in, const sr48_pre *w, uint32_t h)
{
    uint32_t f = in->corner_face[h], s = in->face_start[f], j = diag_corner(w, s);
    if (j == 3u) return w->fstart[f] + (h - s);
    return w->fstart[f] + 2u - (h - s + 3u - j) % 3u;
}

static void put_tri(subd_sr48 *h, uint32_t t, uint32_t apex, uint32_t b0, uint32_t b1)
{
    h->tri_vert[3u * t] = apex;
    h->tri_vert[3u * t + 1u] = b0;
    h->tri_vert[3u * t + 2u] = b1;
}

/* Hybrid triangle H = (p; b0, b1) on base half-edge he: its two level-0 children, and the
 * base-neighbour pair of child 0 with child 1 of `prev` (the hybrid triangle before H around
 * p, whose b1 is H's b0). */
static void hybrid(const subd_mesh *in, sr48_pre *w, subd_sr48 *h, uint32_t H, uint32_t prev, uint32_t p, uint32_t he)
{
    uint32_t b0 = in->corner_vert[he], b1 = subd_he_dest(in, he), e = w->sel[w->es.edge_of[he]];
    put_tri(h, 2u * H, e, p, b0);
    put_tri(h, 2u * H + 1u, e, b1, p);
    h->tri_base_nb[2u * H] = 2u * prev + 1u;
    h->tri_base_nb[2u * prev + 1u] = 2u * H;
    w->hnb[H] = in->twin[he] == SUBD_NONE ? SUBD_NONE : hyb_of(in, w, in->twin[he]);
}

int subd_sr48_level0(const subd_mesh *in, const sr48_layout *L, sr48_pre *w, subd_sr48 *h)
{
    const uint32_t nv = in->num_verts, nf = in->num_faces;
    uint32_t e, f, k, i, hs = 0, fp = nv, ep = L->nv_hyb, ovf = 0;
    subd_real *pos = h->pos;

    /* sel: diagonals and edge points */
    for (e = 0; e < L->ne; e++) w->sel[e] = (w->sel[e] != SUBD_NONE) ? SR48_DIAG : ep++;
    if (ep != L->level_verts[0]) return SUBD_ERR_PARAM;
    /* faces: first hybrid triangle, face point */
    for (f = 0; f < nf; f++) {
        uint32_t s = in->face_start[f], j = diag_corner(w, s);
        w->fstart[f] = hs;
        if (j == 3u) {
            hs += 3u;
            w->fpt[f] = fp++;
        } else {
            uint32_t g = in->corner_face[in->twin[s + j]];
            hs += 2u;
            w->fpt[f] = (g > f) ? fp++ : w->fpt[g];
        }
    }
    if (hs != L->nhyb || fp != L->nv_hyb) return SUBD_ERR_PARAM;

    /* positions: input vertices, face points, edge points */
    for (i = 0; i < 3u * nv; i++) pos[i] = in->pos[i];
    for (f = 0; f < nf; f++) {
        uint32_t s = in->face_start[f], j = diag_corner(w, s), v[4], n = 3, q = w->fpt[f];
        subd_sum sum[3] = {0, 0, 0};
        if (j == 3u) {
            v[0] = in->corner_vert[s]; v[1] = in->corner_vert[s + 1u]; v[2] = in->corner_vert[s + 2u];
        } else {
            uint32_t tw = in->twin[s + j];
            if (in->corner_face[tw] < f) continue; /* the cluster's lower face did it */
            v[0] = in->corner_vert[s + j];                  /* u */
            v[1] = in->corner_vert[s + (j + 1u) % 3u];      /* w */
            v[2] = in->corner_vert[s + (j + 2u) % 3u];      /* x */
            v[3] = in->corner_vert[subd_he_prev(in, tw)];   /* y */
            n = L->smooth ? 4u : 2u;
        }
        for (k = 0; k < 3u; k++) {
            uint32_t c;
            for (c = 0; c < n; c++) sum[k] = subd_sum_add(sum[k], pos[3u * v[c] + k]);
            pos[3u * q + k] = subd_avg(sum[k], n, &ovf);
        }
    }
    for (e = 0; e < L->ne; e++) {
        uint32_t he = w->es.edge_he[e], q = w->sel[e], a = in->corner_vert[he], b = subd_he_dest(in, he);
        if (q == SR48_DIAG) continue;
        for (k = 0; k < 3u; k++) pos[3u * q + k] = subd_mid(pos[3u * a + k], pos[3u * b + k], &ovf);
    }
    if (ovf) return SUBD_ERR_RANGE;

    /* hybrid triangles and level 0 */
    for (f = 0; f < nf; f++) {
        uint32_t s = in->face_start[f], j = diag_corner(w, s), H = w->fstart[f], p = w->fpt[f];
        if (j == 3u) {
            for (k = 0; k < 3u; k++) hybrid(in, w, h, H + k, H + (k + 2u) % 3u, p, s + k);
        } else {
            /* (p; x, u) on x -> u, its predecessor (p; w, x) = H + 1; (p; w, x) on w -> x, its
             * predecessor the partner face's first hybrid triangle (p; y, w) */
            uint32_t g = in->corner_face[in->twin[s + j]];
            hybrid(in, w, h, H, H + 1u, p, s + (j + 2u) % 3u);
            hybrid(in, w, h, H + 1u, w->fstart[g], p, s + (j + 1u) % 3u);
        }
    }
    return SUBD_OK;
}
