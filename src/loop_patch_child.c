/* SPDX-License-Identifier: MIT */
/* The patches of streaming Loop (loop_patch.h): a child's 1-ring extracted from its parent's
 * patch (subd_lp_extract_child), the window of all four children's 1-rings
 * (subd_lp_extract_window), with their twins and ring starts mapped so that every ring is
 * walked in subd_loop's order in the child as in loop.c's level (the argument: loop_stream.c's
 * header). Paper: loop-progressive-interpolation.txt, section 1 (the 1-ring of a refined
 * face). Apart from loop_patch.c (the control patch, the cache of refined values, limit
 * mode's view, the ids): extraction reads a level and writes the next, it computes no point. */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "loop_internal.h"
#include "loop_patch.h"
#include "layout.h"
#include "mesh_internal.h"

/* ------------------------------------------------------------------------------------ */
/* A child's 1-ring                                                                       */

/* The six points of local face pf as cached values (loop.c's points 0..5: corners 0..2,
 * then the new vertices of edges 0..2): a corner that is not a centre corner has none
 * (LP_NO_SLOT: a vertex this level cannot compute; no child that touches the centre's
 * children uses it). Corner j of child k is point TOPO_LOOP_CHILD_POINTS[k][j]. */
static void face_points(const sp_level *p, uint32_t pf, uint32_t pt[6])
{
    uint32_t h = 3u * pf, j;
    for (j = 0; j < 3u; j++) {
        uint32_t u = p->cv[h + j];
        pt[j] = u < 3u ? u : LP_NO_SLOT;
        pt[3u + j] = p->slot[h + j];
    }
}

/* Which children of local face pf (bit k: child k) touch a corner of the centre's child c,
 * whose corners are the cached values s[0..2]: child i of a face holds its corner i, and the
 * new vertex of its edge j lies in children j, j+1 and 3. Every face of the child's 1-ring
 * descends from a face at the child's old corner or at one of its two edges. */
static uint32_t child_mask(const sp_level *p, uint32_t pf, uint32_t c, const uint32_t s[3])
{
    uint32_t j, m = 0, h = 3u * pf;
    for (j = 0; j < 3u; j++) {
        uint32_t sl = p->slot[h + j];
        if (c < 3u && p->cv[h + j] == c) m |= 1u << j;
        if (sl != LP_NO_SLOT && ((c == 3u && sl == s[0]) || sl == s[1] || sl == s[2]))
            m |= (1u << j) | (1u << ((j + 1u) % 3u)) | 8u;
    }
    return m;
}

/* Child corner (f, k, j) of the parent numbering -> child-local half-edge or LP_TW_BORDER. */
static uint16_t map_cc(const uint16_t *fmap, uint32_t f, uint32_t k, uint32_t j)
{
    uint16_t q = fmap[4u * f + k];
    return q == LP_NO_SLOT ? (uint16_t)LP_TW_BORDER : (uint16_t)(3u * q + j);
}

/* Twin of an outer child half-edge: child kk, corner jj of the parent twin t's face. */
static uint16_t outer_twin(const uint16_t *fmap, uint32_t t, int second)
{
    uint32_t c;
    if (t == LP_TW_NONE) return (uint16_t)LP_TW_NONE;
    if (t == LP_TW_BORDER) return (uint16_t)LP_TW_BORDER;
    /* v_i -> m_i pairs with the twin's second half, m_i -> v_i+1 with its first */
    c = second ? topo_loop_second_half(t % 3u) : topo_loop_first_half(t % 3u);
    return map_cc(fmap, t / 3u, c / 3u, c % 3u);
}

/* vert_out of the child's corner that descends from slot s of the centre (loop.c: half_first
 * for an old vertex, new_vout for a new one). */
static uint16_t child_vout(const sp_level *p, const uint16_t *fmap, uint32_t s, uint32_t h)
{
    uint32_t hl, f, c;
    if (s < 3u) {
        uint32_t hv = p->vout[s];
        return map_cc(fmap, hv / 3u, hv % 3u, 0u);
    }
    hl = lower_of(p, h);
    f = hl / 3u;
    c = topo_loop_new_vout(hl % 3u, p->tw[hl] == LP_TW_NONE);
    return map_cc(fmap, f, c / 3u, c % 3u);
}

/* The parent faces whose children can touch child c, ascending: c < 3, the faces around
 * corner c (every face of the child's 1-ring descends from a face at the child's old corner
 * or at one of its two edges, and both lie at corner c); c = 3, the centre and its edge
 * neighbours. Returns their number. */
static uint32_t parent_faces(const sp_level *p, uint32_t c, uint16_t *cand)
{
    uint32_t n = 0, i, j, cf = p->h->cf;
    if (c == 3u) {
        cand[n++] = (uint16_t)cf;
        for (j = 0; j < 3u; j++)
            if (p->tw[3u * cf + j] < LP_TW_BORDER) cand[n++] = (uint16_t)(p->tw[3u * cf + j] / 3u);
    } else { /* sp_ring_step's walk, inlined: the face of each outgoing half-edge (the tail's
              * incoming half-edge lies in the last face already) */
        uint32_t h0 = p->vout[c], h = h0, bound = 3u * p->h->nf;
        for (;;) {
            uint32_t t = p->tw[h % 3u == 0u ? h + 2u : h - 1u];
            cand[n++] = (uint16_t)(h / 3u);
            if (t == LP_TW_NONE || t == h0 || t == LP_TW_BORDER || n >= bound) break;
            h = t;
        }
    }
    for (i = 1; i < n; i++) { /* insertion sort: a few entries */
        uint16_t f = cand[i];
        for (j = i; j > 0u && cand[j - 1u] > f; j--) cand[j] = cand[j - 1u];
        cand[j] = f;
    }
    return n;
}

static const uint8_t child_pts[4][3] = TOPO_LOOP_CHILD_POINTS; /* 0..2 corners, 3 + i: m_i */

/* Twins and sharp bits of the nf children taken (taken[i] = 4 * parent face + child, their
 * local faces in fmap): loop.c's refine_level, mapped to the child level's faces. */
static void child_twins(const sp_level *p, const sp_level *q, const uint16_t *fmap, const uint16_t *taken, uint32_t nf)
{
    uint32_t ci, pf, k, j;
    for (ci = 0; ci < nf; ci++) {
            uint32_t l = 3u * ci;
            pf = taken[ci] / 4u;
            k = taken[ci] % 4u;
            if (k == 3u) {
                for (j = 0; j < 3u; j++) {
                    q->tw[l + j] = map_cc(fmap, pf, (j + 1u) % 3u, 1u);
                    q->sh[l + j] = 0;
                }
            } else {
                uint32_t h0 = 3u * pf + k, h2 = 3u * pf + (k + 2u) % 3u;
                q->tw[l] = outer_twin(fmap, p->tw[h0], 1);
                q->tw[l + 1u] = map_cc(fmap, pf, 3u, (k + 2u) % 3u);
                q->tw[l + 2u] = outer_twin(fmap, p->tw[h2], 0);
                q->sh[l] = (p->sh[h0] & LP_SH_CHILD) ? (uint8_t)(LP_SH_RULE | LP_SH_CHILD) : (uint8_t)0u;
                q->sh[l + 1u] = 0;
                q->sh[l + 2u] = (p->sh[h2] & LP_SH_CHILD) ? (uint8_t)(LP_SH_RULE | LP_SH_CHILD) : (uint8_t)0u;
            }
    }
}

/* Lattice coordinates of child c's corners: a corner stays, a new vertex is the midpoint of
 * edge i. */
void subd_lp_child_lattice(const sp_head *ph, uint32_t c, uint32_t ca[3], uint32_t cb[3])
{
    uint32_t j;
    for (j = 0; j < 3u; j++) {
        uint32_t i = (c == 3u) ? j : (j == 1u) ? c : (c + 2u) % 3u, i1 = (i + 1u) % 3u;
        if (c < 3u && j == 0u) {
            ca[0] = ph->ca[c];
            cb[0] = ph->cb[c];
        } else {
            ca[j] = (ph->ca[i] + ph->ca[i1]) / 2u;
            cb[j] = (ph->cb[i] + ph->cb[i1]) / 2u;
        }
    }
}

/* Cached value sl of p as vertex v of q (position and flags). */
static inline void take_vertex(const sp_level *p, const sp_level *q, uint32_t sl, uint32_t v)
{
    q->pos[3u * v] = p->cpos[3u * sl];
    q->pos[3u * v + 1u] = p->cpos[3u * sl + 1u];
    q->pos[3u * v + 2u] = p->cpos[3u * sl + 2u];
    q->vflag[v] = p->cflag[sl];
}

/* The children k of p's face pf with bit k of mask into q as faces *nf, *nf + 1, ..; their
 * corners (fp: face_points of pf) numbered as met (smap: p's cached value -> q's vertex,
 * *nv the next), fmap and taken recording which child each face is. One home for a
 * child's 1-ring and the window. */
static inline void take_children(const sp_level *p, const sp_level *q, uint32_t pf, uint32_t mask,
                                 const uint32_t fp[6], uint16_t *smap, uint16_t *fmap, uint16_t *taken,
                                 uint32_t *nv, uint32_t *nf)
{
    uint32_t k, j;
    for (k = 0; mask != 0u; k++, mask >>= 1) {
        if (!(mask & 1u)) continue;
        fmap[4u * pf + k] = (uint16_t)*nf;
        taken[*nf] = (uint16_t)(4u * pf + k);
        for (j = 0; j < 3u; j++) {
            uint32_t sl = fp[child_pts[k][j]];
            if (smap[sl] == LP_NO_SLOT) { /* sl is a valid slot: see face_points */
                smap[sl] = (uint16_t)*nv;
                take_vertex(p, q, sl, *nv);
                (*nv)++;
            }
            q->cv[3u * *nf + j] = smap[sl];
        }
        (*nf)++;
    }
}

/* Level k+1 (q) = the 1-ring of child c of level k's (p) centre. fmap holds LP_NO_SLOT on entry
 * and on return (only the entries set here are reset); q's slot array, which fill_cache
 * rewrites afterwards, holds the parent faces and the list of children taken meanwhile. */
void subd_lp_extract_child(const sp_level *p, const sp_level *q, uint32_t c, uint16_t *smap, uint16_t *fmap)
{
    const sp_head *ph = p->h;
    uint32_t cf = ph->cf, s[3], e[3], pf, j, nv = 0, nf = 0, ncand, ci;
    uint16_t *cand = q->slot, *taken;
    for (j = 0; j < ph->nc; j++) smap[j] = LP_NO_SLOT;
    /* the child's corners, in its corner order: (v_c, m_c, m_c-1) or (m0, m1, m2) */
    if (c < 3u) {
        s[0] = c;
        s[1] = p->slot[3u * cf + c];
        s[2] = p->slot[3u * cf + (c + 2u) % 3u];
        e[0] = 0;
        e[1] = 3u * cf + c;
        e[2] = 3u * cf + (c + 2u) % 3u;
    } else {
        for (j = 0; j < 3u; j++) {
            s[j] = p->slot[3u * cf + j];
            e[j] = 3u * cf + j;
        }
    }
    for (j = 0; j < 3u; j++) {
        smap[s[j]] = (uint16_t)j;
        take_vertex(p, q, s[j], j);
    }
    nv = 3;
    ncand = parent_faces(p, c, cand);
    taken = cand + ncand;
    for (ci = 0; ci < ncand; ci++) {
        uint32_t mask, fp[6];
        pf = cand[ci];
        mask = child_mask(p, pf, c, s);
        if (mask == 0u) continue;
        face_points(p, pf, fp);
        take_children(p, q, pf, mask, fp, smap, fmap, taken, &nv, &nf);
    }
    child_twins(p, q, fmap, taken, nf);
    for (j = 0; j < 3u; j++) q->vout[j] = child_vout(p, fmap, s[j], e[j]);
    q->h->nv = nv;
    q->h->nf = nf;
    q->h->cf = fmap[4u * cf + c];
    for (ci = 0; ci < nf; ci++) fmap[taken[ci]] = LP_NO_SLOT;
    q->h->child = 0;
    q->h->nr = 3;
    subd_lp_child_lattice(ph, c, q->h->ca, q->h->cb);
}

/* The window (loop_patch.h): the children of p's faces that have a corner among the region
 * vertices (the centre's corners' children and its edges' new vertices), in face order, so
 * sorted as subd_loop's level is. A child k < 3 of a face holds the face's corner k and the
 * new vertices of the two edges at it, so it is taken exactly when that corner is a centre
 * corner (a centre edge's new vertex lies on an edge at a centre corner); the middle child
 * when one of the face's edges is a centre edge. Every face around a region vertex is taken,
 * so each region vertex's ring is whole; every vertex taken is a cached value of p. */
void subd_lp_extract_window(const sp_level *p, const sp_level *q, uint16_t *smap, uint16_t *fmap)
{
    const sp_head *ph = p->h;
    uint32_t cf = ph->cf, pf, j, nv, nf = 0, ci, nfp = ph->nf;
    uint16_t *taken = q->slot; /* the children taken (fill_cache rewrites the slots) */
    for (j = 0; j < ph->nc; j++) smap[j] = LP_NO_SLOT;
    /* the region vertices 0..5: the corners' children, then the centre edges' new vertices */
    for (j = 0; j < 6u; j++) {
        uint32_t sl = j < 3u ? j : p->slot[3u * cf + j - 3u];
        smap[sl] = (uint16_t)j;
        take_vertex(p, q, sl, j);
    }
    nv = 6;
    for (pf = 0; pf < nfp; pf++) {
        const uint16_t *fc = p->cv + 3u * pf;
        uint32_t fp[6], mask = 0;
        if (fc[0] >= 3u && fc[1] >= 3u && fc[2] >= 3u) continue; /* no corner of the centre */
        face_points(p, pf, fp);
        for (j = 0; j < 3u; j++) {
            if (fc[j] < 3u) mask |= 1u << j;
            if (fp[3u + j] != LP_NO_SLOT && smap[fp[3u + j]] < 6u) mask |= 8u; /* a centre edge */
        }
        take_children(p, q, pf, mask, fp, smap, fmap, taken, &nv, &nf);
    }
    child_twins(p, q, fmap, taken, nf);
    for (j = 0; j < 3u; j++) {
        q->vout[j] = child_vout(p, fmap, j, 0u);
        q->vout[3u + j] = child_vout(p, fmap, p->slot[3u * cf + j], 3u * cf + j);
    }
    q->h->nv = nv;
    q->h->nf = nf;
    q->h->nr = 6;
    q->h->child = q->h->cf = fmap[4u * cf]; /* the centre's four children follow it */
    for (ci = 0; ci < nf; ci++) fmap[taken[ci]] = LP_NO_SLOT;
}
