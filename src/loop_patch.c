/* SPDX-License-Identifier: MIT */
/* The patches of streaming Loop (loop_patch.h): a control face's 1-ring, its refined values
 * and its children's 1-rings, bit-identical to subd_loop because every rule is loop_rules.h's
 * and every ring and stencil is summed in loop.c's order (see loop_stream.c's header for the
 * argument). Paper: loop-progressive-interpolation.txt, sections 1 and 4.
 * A child's 1-ring and the window of all four (their twin and ring-start mapping) are
 * extracted by loop_patch_child.c; the ring walk they share is loop_patch.h's. */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "loop_internal.h"
#include "loop_patch.h"
#include "layout.h"
#include "mesh_internal.h"

/* A block of nv vertices, nf faces and nc cached values (offsets into it; returns its
 * bytes); `cache`: with the refined values; `control`: with the input face and vertex of each
 * local element. */
static uint32_t block_layout(uint32_t nv, uint32_t nf, uint32_t nc, int cache, int control, uint32_t off[A_N])
{
    uint32_t t = 0;
    off[A_POS] = t;   subd_size_add(&t, nv, 3u * (uint32_t)sizeof(subd_real));
    off[A_VFLAG] = t; subd_size_add(&t, nv, 1u);
    off[A_VOUT] = t;  subd_size_add(&t, nv, 2u);
    off[A_CV] = t;    subd_size_add(&t, nf, 6u);
    off[A_TW] = t;    subd_size_add(&t, nf, 6u);
    off[A_SLOT] = t;  subd_size_add(&t, nf, 6u);
    off[A_SH] = t;    subd_size_add(&t, nf, 3u);
    off[A_CPOS] = t;  if (cache) subd_size_add(&t, nc, 3u * (uint32_t)sizeof(subd_real));
    off[A_CFLAG] = t; if (cache) subd_size_add(&t, nc, 1u);
    off[A_CFACE] = t; if (control) subd_size_add(&t, nf, 4u);
    off[A_CVERT] = t; if (control) subd_size_add(&t, nv, 4u);
    return t;
}

/* A level's arrays for corner valence sum s. SUBD_LOOP_SLEV_ is the same sum. */
uint32_t subd_lp_level_layout(uint32_t s, int cache, int control, uint32_t off[A_N])
{
    return block_layout(cap_v(s), cap_f(s), s, cache, control, off);
}

/* The window of a patch whose corner valences sum to s: its vertices are cached values of the
 * patch (at most s); its faces the children at the patch's corners (one per face around a
 * corner: at most s) and the middle children of the centre and its three edge neighbours; its
 * cached values the six region vertices' points and the edges at them (the corners' children
 * keep the corners' valences, the new vertices have valence 6 at most: s + 18). SUBD_LOOP_SWIN_
 * is the same sum. */
uint32_t subd_lp_window_layout(uint32_t s, uint32_t off[A_N])
{
    return block_layout(s, s + 4u, s + 24u, 1, 0, off);
}

/* ------------------------------------------------------------------------------------ */
/* Level 0: the control face's 1-ring                                                     */

/* Position of input face f in the sorted local face list, or nf. */
static uint32_t find_face(const sp_level *p, uint32_t nf, uint32_t f)
{
    uint32_t lo = 0, hi = nf;
    while (lo < hi) {
        uint32_t mid = (lo + hi) / 2u;
        if (p->cface[mid] < f) lo = mid + 1u;
        else hi = mid;
    }
    return (lo < nf && p->cface[lo] == f) ? lo : nf;
}

/* Inserts input face f into the sorted list (no duplicates). */
static void add_face(const sp_level *p, uint32_t *nf, uint32_t f)
{
    uint32_t i = find_face(p, *nf, f), j;
    if (i < *nf) return;
    for (i = *nf; i > 0u && p->cface[i - 1u] > f; i--) {}
    for (j = *nf; j > i; j--) p->cface[j] = p->cface[j - 1u];
    p->cface[i] = f;
    (*nf)++;
}

/* A control patch's look-up hints (on the stack while it is built): LP_HINT entries keyed
 * by the low bits of an input index. Vertices: a chained hash, exact: the entry holds the
 * last local vertex of its key + 1 (0: none) and vout, unused until the patch is done, links
 * each local vertex to the one before it with the same key (+ 1), so a new vertex is known
 * new without a search. Faces: the local face + 1 of the last face with the key, checked
 * against cface (a collision costs the binary search the hint would have saved). */
#define LP_HINT 64u

/* Local index of input vertex v (appended when new); hint: the vertices' chains. */
static uint16_t local_vertex(const subd_mesh *in, const sp_level *p, uint32_t v, uint16_t *hint)
{
    uint32_t nv = p->h->nv, k = hint[v % LP_HINT];
    while (k != 0u) {
        if (p->cvert[k - 1u] == v) return (uint16_t)(k - 1u);
        k = p->vout[k - 1u];
    }
    p->vout[nv] = hint[v % LP_HINT]; /* the chain (build_control resets vout) */
    hint[v % LP_HINT] = (uint16_t)(nv + 1u);
    p->cvert[nv] = v;
    p->pos[3u * nv] = in->pos[3u * v];
    p->pos[3u * nv + 1u] = in->pos[3u * v + 1u];
    p->pos[3u * nv + 2u] = in->pos[3u * v + 2u];
    /* the regular bit is set by subd_lp_build_control where a sharp edge reads it */
    p->vflag[nv] = (uint8_t)((in->vert_tag[v] & SUBD_VTAG_CORNER) ? TOPO_PF_CORNER : 0u);
    p->h->nv = nv + 1u;
    return (uint16_t)nv;
}

/* Sharpness of input half-edge h at level 0 and of its children: topo_edge_sharp. */
static uint8_t input_sharp(const subd_mesh *in, uint32_t h)
{
    return topo_edge_sharp(in->twin, in->edge_tag, h) ? (uint8_t)(LP_SH_RULE | LP_SH_CHILD) : (uint8_t)0u;
}

/* Builds level 0 for input face f: every face around its corners (walked both ways from
 * vert_out, so an unusual vert_out loses no face), sorted; corners 0..2 are f's. */
void subd_lp_build_control(const subd_mesh *in, uint32_t f, const sp_level *p, uint32_t levels)
{
    uint32_t j, nf = 0, lf, n1 = (uint32_t)1 << levels;
    uint16_t vh[LP_HINT], fh[LP_HINT]; /* hints: vertices, faces (LP_HINT) */
    for (j = 0; j < LP_HINT; j++) vh[j] = fh[j] = 0;
    p->h->nv = 0;
    for (j = 0; j < 3u; j++) {
        uint32_t u = in->corner_vert[3u * f + j], h0 = in->vert_out[u], h = h0, steps = 0, t;
        (void)local_vertex(in, p, u, vh);
        for (;;) { /* counter-clockwise: twin(prev(h)) */
            add_face(p, &nf, h / 3u);
            t = in->twin[tri_prev(h)];
            if (t == SUBD_NONE || t == h0 || ++steps > in->num_corners) break;
            h = t;
        }
        if (t == SUBD_NONE) /* clockwise from vert_out: next(twin(h)) */
            for (h = h0; in->twin[h] != SUBD_NONE && steps++ <= in->num_corners;) {
                h = tri_next(in->twin[h]);
                add_face(p, &nf, h / 3u);
            }
    }
    for (lf = 0; lf < nf; lf++) fh[p->cface[lf] % LP_HINT] = (uint16_t)(lf + 1u);
    for (lf = 0; lf < nf; lf++)
        for (j = 0; j < 3u; j++) {
            uint32_t h = 3u * p->cface[lf] + j, t = in->twin[h], l = 3u * lf + j;
            p->cv[l] = local_vertex(in, p, in->corner_vert[h], vh);
            p->sh[l] = input_sharp(in, h);
            if (t == SUBD_NONE) {
                p->tw[l] = LP_TW_NONE;
            } else {
                uint32_t tf = fh[(t / 3u) % LP_HINT];
                tf = (tf != 0u && p->cface[tf - 1u] == t / 3u) ? tf - 1u : find_face(p, nf, t / 3u);
                p->tw[l] = tf < nf ? (uint16_t)(3u * tf + t % 3u) : (uint16_t)LP_TW_BORDER;
            }
        }
    /* A vertex's regular bit (its whole ring, subd_loop_classify on the input) is read only
     * by the sharp-edge rule of an edge at it, and a regular vertex has sharp edges: so only
     * the ends of the patch's sharp edges are classified (the walk is most of a control
     * patch's cost on a mesh without creases). */
    for (lf = 0; lf < 3u * nf; lf++)
        if (p->sh[lf] != 0u)
            for (j = 0; j < 2u; j++) {
                uint32_t u = p->cv[j ? tri_next(lf) : lf];
                loop_vinfo c;
                subd_loop_classify(in, p->cvert[u], &c);
                if (c.regular) p->vflag[u] = (uint8_t)(p->vflag[u] | TOPO_PF_REGULAR);
            }
    for (lf = 3; lf < p->h->nv; lf++) p->vout[lf] = LP_TW_NONE; /* the chains' links, done */
    for (j = 0; j < 3u; j++) { /* the input's vert_out, as loop.c's first level walks it */
        uint32_t h = in->vert_out[in->corner_vert[3u * f + j]];
        p->vout[j] = (uint16_t)(3u * find_face(p, nf, h / 3u) + h % 3u);
    }
    p->h->nf = nf;
    p->h->cf = find_face(p, nf, f);
    p->h->child = 0;
    p->h->nr = 3;
    p->h->ca[0] = 0; p->h->cb[0] = 0;
    p->h->ca[1] = n1; p->h->cb[1] = 0;
    p->h->ca[2] = 0; p->h->cb[2] = n1;
}

/* ------------------------------------------------------------------------------------ */
/* Refined values of a level (the cache)                                                  */

/* One-ring iterator of a complete vertex of a patch: topo_ring's walk specialised to the
 * patch's 16-bit arrays, whose twin may also say "outside the patch" (LP_TW_BORDER, which
 * cannot occur at a centre corner; the walk stops there). From vout counter-clockwise (twin
 * of prev); on a boundary the last neighbour is the origin of the incoming boundary
 * half-edge. Bounded by the patch's half-edges whatever the patch holds. test_topo's
 * topo_patch_ring holds it equal to topo_ring on the input (subd_lp_ring). */
uint32_t subd_lp_ring(const sp_level *p, uint32_t v, uint32_t *nbr, uint32_t *he, uint32_t max)
{
    uint32_t n = 0, nb, h = 0;
    sp_ring it;
    sp_ring_begin(p, v, &it);
    while ((nb = sp_ring_step(p, &it, &h)) != SUBD_NONE) {
        if (n < max) {
            nbr[n] = nb;
            he[n] = h;
        }
        n++;
    }
    return n;
}

/* Neighbours a vertex point keeps from its one walk (LP_VP_KEEP: more than the valences a
 * real mesh has, few enough for the stack; a larger ring is walked a second time). */
#define LP_VP_KEEP 12u

/* One neighbour of lp_ring_x: kept (the first LP_VP_KEEP) and, on a sharp half-edge,
 * counted (the first two kept in snb). */
TOPO_INLINE void lp_ring_put(uint32_t xi, int sharp, uint32_t n, uint32_t *x, uint32_t *ns, uint32_t *snb)
{
    if (sharp) {
        if (*ns < 2u) snb[*ns] = xi;
        (*ns)++;
    }
    if (n < LP_VP_KEEP) x[n] = xi;
}

/* sp_ring_step's walk from vert_out, inlined for the vertex points (its most frequent
 * use): the value index of each neighbour (next = 0: its vertex; next = 1: the cached edge
 * point of its half-edge, slot), the first LP_VP_KEEP into x, the sharp ones (sharp_bit)
 * counted into *ns and the first two into snb. Returns the number of neighbours. The same
 * half-edges as sp_ring_step in the same order, the same tail and the same guard. */
TOPO_INLINE uint32_t lp_ring_x(const sp_level *p, uint32_t v, int next, uint8_t sharp_bit, uint32_t *x, uint32_t *ns,
                               uint32_t *snb)
{
    const uint16_t *cv = p->cv, *tw = p->tw, *sl = p->slot;
    const uint8_t *sh = p->sh;
    uint32_t h0 = p->vout[v], h = h0, n = 0, bound = 3u * p->h->nf;
    for (;;) {
        uint32_t r = h % 3u, pr = r == 0u ? h + 2u : h - 1u, t; /* tri_prev, tri_next: one modulo */
        lp_ring_put(next ? sl[h] : cv[r == 2u ? h - 2u : h + 1u], (sh[h] & sharp_bit) != 0u, n, x, ns, snb);
        n++;
        t = tw[pr];
        if (t == LP_TW_NONE) { /* the tail: the origin of the incoming boundary half-edge */
            lp_ring_put(next ? sl[pr] : cv[pr], (sh[pr] & sharp_bit) != 0u, n, x, ns, snb);
            return n + 1u;
        }
        if (t == h0 || t == LP_TW_BORDER || n >= bound) return n;
        h = t;
    }
}

/* Vertex point of centre corner v (0..2): one walk (lp_ring_x) gives the class and the
 * ring, then the class's rule; a vertex known to be smooth of valence 6 takes loop.c's
 * smooth_fast weights without classifying.
 * next = 0: of the patch's level, from its positions; *child gets the flags of v's child
 * (the class is kept by refinement). next = 1: of the level below, from the cache (v's child
 * has v's ring shape: its neighbours are the edge points of v's edges, in the same order
 * from the same start), for the last two levels emitted at once. */
void subd_lp_vertex_point(const sp_level *p, uint32_t v, int next, loop_wcache *wc, uint32_t *ovf, subd_real *out,
                         uint8_t *child)
{
    uint32_t n, wn, ns = 0, snb[2] = {0, 0}, cls = LOOP_SMOOTH, x[LP_VP_KEEP], i;
    const subd_real *base = next ? p->cpos : p->pos, *pv = base + 3u * v;
    uint8_t f = next ? p->cflag[v] : p->vflag[v], sharp_bit = next ? (uint8_t)LP_SH_CHILD : (uint8_t)LP_SH_RULE;
    /* two copies of the walk, each of one kind */
    if (next) n = wn = lp_ring_x(p, v, 1, sharp_bit, x, &ns, snb);
    else n = wn = lp_ring_x(p, v, 0, sharp_bit, x, &ns, snb);
    if (f & TOPO_PF_SMOOTH6) n = 6; /* its class is known: the ring walked is summed with n = 6 */
    else cls = loop_class_of(ns, (f & TOPO_PF_CORNER) != 0u);
    if (cls == LOOP_CORNER) {
        out[0] = pv[0];
        out[1] = pv[1];
        out[2] = pv[2];
    } else if (cls == LOOP_CREASE) {
        loop_rule_crease(out, pv, base + 3u * snb[0], base + 3u * snb[1], ovf);
    } else {
        loop_weights w = subd_loop_weights_of(wc, n, ovf);
        subd_acc acc[3];
        loop_smooth_begin(acc, w, pv);
        if (wn <= LP_VP_KEEP) {
            for (i = 0; i < wn; i++) loop_smooth_add(acc, w, base + 3u * x[i]);
        } else { /* a ring longer than kept: the walk again */
            uint32_t he = 0, nb;
            sp_ring it;
            sp_ring_begin(p, v, &it);
            while ((nb = sp_ring_step(p, &it, &he)) != SUBD_NONE)
                loop_smooth_add(acc, w, next ? p->cpos + 3u * p->slot[he] : p->pos + 3u * nb);
        }
        loop_smooth_end(out, acc, ovf);
        if (n == 6u) f |= TOPO_PF_SMOOTH6;
    }
    if (child) *child = f;
}

/* Edge point of the edge of lower half-edge hl. */
static void edge_point(const sp_level *p, uint32_t hl, subd_loop_boundary rule, uint32_t *ovf, subd_real *out)
{
    uint32_t a = p->cv[hl], b = p->cv[tri_next(hl)], t = p->tw[hl];
    if (!(p->sh[hl] & LP_SH_RULE) && t < LP_TW_BORDER)
        loop_rule_edge(out, p->pos + 3u * a, p->pos + 3u * b, p->pos + 3u * p->cv[tri_prev(hl)],
                       p->pos + 3u * p->cv[tri_prev(t)], ovf);
    else
        loop_rule_sharp_edge(out, p->pos + 3u * a, p->pos + 3u * b, rule, p->vflag[a] & TOPO_PF_REGULAR,
                             p->vflag[b] & TOPO_PF_REGULAR, ovf);
}

/* Fills the cache: slots 0..nr-1 the region vertices' vertex points (the centre's corners, or
 * a window's six), then one slot per edge at a region vertex (`all`), or only the centre's
 * three edges (the last level, which emits the centre's children and refines nothing
 * further). */
void subd_lp_fill_cache(const sp_level *p, subd_loop_boundary rule, int all, loop_wcache *wc, uint32_t *ovf)
{
    uint32_t h, v, nr = p->h->nr, nc = nr, n3 = 3u * p->h->nf;
    for (h = 0; h < n3; h++) p->slot[h] = LP_NO_SLOT;
    for (v = 0; v < nr; v++) subd_lp_vertex_point(p, v, 0, wc, ovf, p->cpos + 3u * v, &p->cflag[v]);
    if (!all) {
        for (v = 0; v < 3u; v++) {
            h = 3u * p->h->cf + v;
            p->slot[h] = (uint16_t)(3u + v);
            edge_point(p, lower_of(p, h), rule, ovf, p->cpos + 3u * (3u + v));
        }
        p->h->nc = 6;
        return;
    }
    /* face by face (its corners read once, no modulo), each edge at a corner once: at its
     * first half-edge, which is its lower one (a twin below it has the same ends and took
     * the slot already) */
    for (h = 0; h < n3; h += 3u) {
        const uint16_t *fc = p->cv + h;
        uint32_t j;
        if (fc[0] >= nr && fc[1] >= nr && fc[2] >= nr) continue; /* no edge at a region vertex */
        for (j = 0; j < 3u; j++) {
            uint32_t j1 = j == 2u ? 0u : j + 1u, hj = h + j, t, hl;
            if (p->slot[hj] != LP_NO_SLOT || (fc[j] >= nr && fc[j1] >= nr)) continue;
            t = p->tw[hj];
            hl = lower_of(p, hj);
            p->slot[hj] = (uint16_t)nc;
            if (t < LP_TW_BORDER) p->slot[t] = (uint16_t)nc;
            if (hl == hj && !(p->sh[hj] & LP_SH_RULE) && t < LP_TW_BORDER) /* edge_point's smooth rule */
                loop_rule_edge(p->cpos + 3u * nc, p->pos + 3u * fc[j], p->pos + 3u * fc[j1],
                               p->pos + 3u * fc[j1 == 2u ? 0u : j1 + 1u], p->pos + 3u * p->cv[tri_prev(t)], ovf);
            else
                edge_point(p, hl, rule, ovf, p->cpos + 3u * nc);
            p->cflag[nc] = (p->sh[hl] & LP_SH_CHILD) ? (uint8_t)TOPO_PF_REGULAR : (uint8_t)TOPO_PF_SMOOTH6;
            nc++;
        }
    }
    p->h->nc = nc;
}

/* ------------------------------------------------------------------------------------ */
/* Limit mode's pieces (loop_patch.h: shared with the adaptive stream)                    */

void subd_lp_view_take(struct subd_layout *y, uint32_t s, subd_mesh *w)
{
    uint32_t nv = cap_v(s), nf = cap_f(s);
    w->face_start = subd_layout_take(y, nf + 1u, 4u);
    w->corner_vert = subd_layout_take(y, nf, 12u);
    w->corner_face = subd_layout_take(y, nf, 12u);
    w->twin = subd_layout_take(y, nf, 12u);
    w->vert_out = subd_layout_take(y, nv, 4u);
    w->vert_tag = subd_layout_take(y, nv, 1u);
    w->edge_tag = subd_layout_take(y, nf, 3u);
}

void subd_lp_view_fill(const sp_level *p, subd_mesh *m)
{
    uint32_t nf = p->h->nf, nv = p->h->nv, c, v;
    m->num_verts = nv;
    m->num_faces = nf;
    m->num_corners = 3u * nf;
    m->pos = p->pos;
    m->num_lines = m->num_line_verts = 0;
    m->line_start = m->line_vert = 0;
    m->num_edges = m->num_boundary_edges = m->num_boundary_loops = m->num_isolated = 0;
    for (c = 0; c <= nf; c++) m->face_start[c] = 3u * c;
    for (c = 0; c < 3u * nf; c++) {
        uint32_t tw = p->tw[c];
        m->corner_vert[c] = p->cv[c];
        m->corner_face[c] = c / 3u;
        m->twin[c] = tw < LP_TW_BORDER ? tw : SUBD_NONE;
        m->edge_tag[c] = (uint8_t)((tw == LP_TW_NONE ? SUBD_ETAG_BOUNDARY : 0u) |
                                   ((tw != LP_TW_NONE && (p->sh[c] & LP_SH_RULE)) ? SUBD_ETAG_CREASE : 0u));
    }
    for (v = 0; v < nv; v++) {
        uint8_t f = p->vflag[v];
        m->vert_out[v] = v < 3u ? p->vout[v] : SUBD_NONE;
        m->vert_tag[v] = (uint8_t)(LOOP_VTAG_KNOWN | ((f & TOPO_PF_REGULAR) ? LOOP_VTAG_REGULAR : 0u) |
                                   ((f & TOPO_PF_CORNER) ? SUBD_VTAG_CORNER : 0u) |
                                   ((v < 3u && p->tw[p->vout[v]] == LP_TW_NONE) ? SUBD_VTAG_BOUNDARY : 0u));
    }
}

uint64_t subd_lp_vertex_id(const subd_mesh *in, uint32_t f, uint32_t a, uint32_t b, uint32_t levels)
{
    uint64_t n1 = (uint64_t)1 << levels, nm1 = n1 - 1u;
    uint32_t h, t, u, w, tw;
    uint64_t pos;
    if (a == 0u && b == 0u) return in->corner_vert[3u * f];
    if (a == n1 && b == 0u) return in->corner_vert[3u * f + 1u];
    if (a == 0u && b == n1) return in->corner_vert[3u * f + 2u];
    if (b == 0u) { h = 3u * f; t = a; }
    else if ((uint64_t)a + b == n1) { h = 3u * f + 1u; t = b; }
    else if (a == 0u) { h = 3u * f + 2u; t = (uint32_t)(n1 - b); }
    else {
        uint64_t am = a - 1u;
        return subd_lp_id_base(in, f, levels) + am * nm1 - am * (am + 1u) / 2u + (b - 1u);
    }
    u = in->corner_vert[h];
    w = in->corner_vert[tri_next(h)];
    tw = in->twin[h];
    pos = (u < w) ? t : n1 - t;
    if (tw != SUBD_NONE && tw < h) h = tw;
    return (uint64_t)in->num_verts + (uint64_t)h * nm1 + pos - 1u;
}

/* Largest number of neighbours of a vertex of the input (a triangle mesh with adjacency):
 * outgoing half-edges, plus one on a boundary. O(corners). */
uint32_t subd_lp_max_valence(const subd_mesh *in)
{
    uint32_t v, best = 0;
    for (v = 0; v < in->num_verts; v++) {
        uint32_t h0 = in->vert_out[v], h = h0, n = 0;
        if (h0 == SUBD_NONE || h0 >= in->num_corners) continue;
        for (;;) {
            uint32_t t = in->twin[tri_prev(h)];
            n++;
            if (t == SUBD_NONE) {
                n++;
                break;
            }
            if (t == h0 || n > in->num_corners) break;
            h = t;
        }
        if (n > best) best = n;
    }
    return best;
}

void subd_lp_level_bind(uint8_t *b, const uint32_t *off, sp_level *lv)
{
    lv->pos = (subd_real *)(void *)(b + off[A_POS]);
    lv->vflag = b + off[A_VFLAG];
    lv->vout = (uint16_t *)(void *)(b + off[A_VOUT]);
    lv->cv = (uint16_t *)(void *)(b + off[A_CV]);
    lv->tw = (uint16_t *)(void *)(b + off[A_TW]);
    lv->slot = (uint16_t *)(void *)(b + off[A_SLOT]);
    lv->sh = b + off[A_SH];
    lv->cpos = (subd_real *)(void *)(b + off[A_CPOS]);
    lv->cflag = b + off[A_CFLAG];
    lv->cface = (uint32_t *)(void *)(b + off[A_CFACE]);
    lv->cvert = (uint32_t *)(void *)(b + off[A_CVERT]);
}
