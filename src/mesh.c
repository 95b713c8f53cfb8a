/* SPDX-License-Identifier: MIT */
/* Index mesh: validation and adjacency from a plain face list.
 *
 * Adjacency is built the meshoptimizer way, by counting and prefix sums: the half-edges are
 * sorted by undirected edge (smaller end vertex, then larger) with two stable counting-sort
 * passes over the vertex indices (LSD radix sort with one digit per vertex index), so the
 * half-edges of one edge are adjacent and twins, non-manifold edges and flipped faces show in
 * one scan; per-vertex fans come from one more pass over the corners. Every pass keeps
 * corner order among equal keys, so every result is independent of memory addresses and of
 * the platform; there is no hashing and no comparison sort. Cost: O(V + C) whatever the
 * valences (one vertex of valence 65 536 builds as fast as a grid with as many corners; the
 * bucket-scan builder before it was O(C + sum of valence^2)), no recursion, constant stack.
 * (edge_sort.c's radix sort is not reused: it sorts 64-bit keys descending and would need
 * two 64-bit key arrays, three times this scratch.)
 *
 * Conventions (see subd.h): corner c is also the half-edge from corner_vert[c] to the next
 * corner's vertex in the same face; vert_out[v] is v's boundary half-edge when v is on a
 * boundary, so one walk from it visits v's whole fan in order.
 */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "mesh_internal.h"
#include "layout.h"
#include "entry.h"
#include "topo.h"


void subd_diag_clear(subd_diag *d)
{
    d->status = SUBD_OK;
    d->line = 0;
    d->face = SUBD_NONE;
    d->vertex = SUBD_NONE;
    d->polyline = SUBD_NONE;
    d->bytes_needed = 0;
}

int subd_fail(subd_diag *d, int status)
{
    d->status = status;
    return status;
}

int subd_require_triangles(const subd_mesh *m, subd_diag *d)
{
    uint32_t f;
    for (f = 0; f < m->num_faces; f++) {
        if (subd_face_size(m, f) != 3u) {
            if (!d) return SUBD_ERR_NOT_TRIANGLES;
            d->face = f;
            return subd_fail(d, SUBD_ERR_NOT_TRIANGLES);
        }
    }
    return SUBD_OK;
}

void subd_mesh_move_down(subd_mesh *m, uint8_t *dst, uint32_t bytes)
{
    uint8_t *src = (uint8_t *)m->pos;
    uint32_t i, delta = (uint32_t)(src - dst);
    for (i = 0; i < bytes; i++) dst[i] = src[i]; /* ascending: safe for dst <= src */
#define MOVE(p) (m->p = (void *)((uint8_t *)(void *)m->p - delta))
    MOVE(pos);
    MOVE(face_start);
    MOVE(corner_vert);
    MOVE(corner_face);
    MOVE(twin);
    MOVE(vert_out);
    MOVE(vert_tag);
    MOVE(edge_tag);
    MOVE(line_start);
    MOVE(line_vert);
#undef MOVE
}

/* The one layout of the mesh arrays (layout.h): counts with a == NULL, carves otherwise;
 * *bytes is the arrays plus the builder's scratch, UINT32_MAX when too big. */
static int mesh_layout(subd_arena *a, const mesh_counts *c, subd_mesh *m, uint32_t *bytes)
{
    subd_layout l;
    subd_mesh tmp;
    subd_mesh *p = m ? m : &tmp;
    uint32_t total;
    int st;
    subd_layout_begin(&l, a);
    p->pos = subd_layout_take(&l, c->nv, 3u * (uint32_t)sizeof(subd_real));
    p->face_start = subd_layout_take(&l, c->nf + 1u, 4u);
    p->corner_vert = subd_layout_take(&l, c->nc, 4u);
    p->corner_face = subd_layout_take(&l, c->nc, 4u);
    p->twin = subd_layout_take(&l, c->nc, 4u);
    p->vert_out = subd_layout_take(&l, c->nv, 4u);
    p->vert_tag = subd_layout_take(&l, c->nv, 1u);
    p->edge_tag = subd_layout_take(&l, c->nc, 1u);
    p->line_start = subd_layout_take(&l, c->nl + 1u, 4u);
    p->line_vert = subd_layout_take(&l, c->nlv, 4u);
    st = subd_layout_end(&l, &total);
    subd_bytes_add(&total, subd_mesh_scratch_bytes(c));
    if (c->nv == UINT32_MAX || c->nf == UINT32_MAX || c->nl == UINT32_MAX) total = UINT32_MAX;
    *bytes = total;
    if (!a) return SUBD_OK;
    return st;
}

/* The builder's scratch (layout.h): per-vertex counts (nv + 1 slots, nv used; the +1 keeps
 * the plan and SUBD_MESH_BYTES as they were) and the half-edges sorted by edge. */
static int scratch_layout(subd_arena *a, uint32_t nv, uint32_t nc, uint32_t **vstart, uint32_t **vcorner,
                          uint32_t *bytes)
{
    subd_layout l;
    uint32_t *vs, *vc;
    subd_layout_begin(&l, a);
    vs = subd_layout_take(&l, nv + 1u, 4u);
    vc = subd_layout_take(&l, nc, 4u);
    if (vstart) *vstart = vs;
    if (vcorner) *vcorner = vc;
    return subd_layout_end(&l, bytes);
}

uint32_t subd_mesh_scratch_bytes(const mesh_counts *c)
{
    uint32_t b;
    scratch_layout(0, c->nv, c->nc, 0, 0, &b);
    return b;
}

uint32_t subd_mesh_arrays_bytes(const mesh_counts *c)
{
    uint32_t b = subd_mesh_counts_bytes(c);
    return b == UINT32_MAX ? b : b - subd_mesh_scratch_bytes(c);
}

uint32_t subd_mesh_counts_bytes(const mesh_counts *c)
{
    uint32_t bytes;
    mesh_layout(0, c, 0, &bytes);
    return bytes;
}

int subd_mesh_alloc_arrays(subd_arena *a, const mesh_counts *c, subd_mesh *m)
{
    uint32_t bytes;
    int st;
    /* The whole plan (scratch included) must fit before anything is handed out. */
    mesh_layout(0, c, 0, &bytes);
    if (bytes == UINT32_MAX) return SUBD_ERR_TOO_BIG;
    if (bytes > subd_arena_free_bytes(a)) return SUBD_ERR_NOMEM;
    st = mesh_layout(a, c, m, &bytes);
    if (st) return st;
    m->num_verts = c->nv;
    m->num_faces = c->nf;
    m->num_corners = c->nc;
    m->num_lines = c->nl;
    m->num_line_verts = c->nlv;
    m->num_edges = m->num_boundary_edges = m->num_boundary_loops = m->num_isolated = 0;
    return SUBD_OK;
}

/* Per-face checks that need no adjacency: index range and repeated vertices. */
static int check_faces(const subd_mesh *m, subd_diag *d)
{
    uint32_t f, i, j;
    for (f = 0; f < m->num_faces; f++) {
        uint32_t s = m->face_start[f], e = m->face_start[f + 1u];
        d->face = f;
        for (i = s; i < e; i++)
            if (m->corner_vert[i] >= m->num_verts) return subd_fail(d, SUBD_ERR_INDEX);
        for (i = s; i < e; i++)
            for (j = i + 1u; j < e; j++)
                if (m->corner_vert[i] == m->corner_vert[j]) return subd_fail(d, SUBD_ERR_DEGENERATE);
    }
    d->face = SUBD_NONE;
    for (f = 0; f < m->num_lines; f++) {
        for (i = m->line_start[f]; i < m->line_start[f + 1u]; i++) {
            if (m->line_vert[i] >= m->num_verts) {
                d->polyline = f;
                return subd_fail(d, SUBD_ERR_INDEX);
            }
        }
    }
    return SUBD_OK;
}

static int check_positions(const subd_mesh *m, subd_diag *d)
{
    uint32_t i;
    for (i = 0; i < 3u * m->num_verts; i++) {
        if (!subd_real_is_finite(m->pos[i])) {
            d->vertex = i / 3u;
            return subd_fail(d, SUBD_ERR_NAN);
        }
    }
    return SUBD_OK;
}

/* The arrays the adjacency passes read, copied to locals: the passes store into uint32_t
 * arrays, which the compiler must otherwise assume may alias the mesh's pointers and counts. */
typedef struct mesh_view {
    const uint32_t *cv, *cf, *fs;
    uint32_t nv, nf, nc;
} mesh_view;

static mesh_view view_of(const subd_mesh *m)
{
    mesh_view w;
    w.cv = m->corner_vert;
    w.cf = m->corner_face;
    w.fs = m->face_start;
    w.nv = m->num_verts;
    w.nf = m->num_faces;
    w.nc = m->num_corners;
    return w;
}

/* The two end vertices of half-edge h, smaller first: its undirected edge. */
static inline void edge_ends(const mesh_view *w, uint32_t h, uint32_t *lo, uint32_t *hi)
{
    uint32_t f = w->cf[h], a = w->cv[h], b = w->cv[(h + 1u == w->fs[f + 1u]) ? w->fs[f] : h + 1u];
    *lo = a < b ? a : b;
    *hi = a < b ? b : a;
}

/* Prefix sum over cnt[0..n): each slot becomes the first index of its key. */
static void counts_to_starts(uint32_t *cnt, uint32_t n)
{
    uint32_t v, sum = 0;
    for (v = 0; v < n; v++) {
        uint32_t c = cnt[v];
        cnt[v] = sum;
        sum += c;
    }
}

/* The half-edges sorted by undirected edge, smaller end then larger end, equal edges in
 * corner order: an LSD radix sort with one digit per end vertex, two stable counting passes
 * (cnt: num_verts slots). The first pass runs face by face in corner order, so its end
 * vertices come without the face lookups of subd_he_dest, into tmp; the second into out. */
static void sort_by_edge(const mesh_view *w, uint32_t *cnt, uint32_t *tmp, uint32_t *out)
{
    const uint32_t *cv = w->cv, *fs = w->fs;
    const uint32_t nv = w->nv, nf = w->nf, nc = w->nc;
    uint32_t v, f, c, i, lo, hi;
    for (v = 0; v < nv; v++) cnt[v] = 0;
    for (f = 0; f < nf; f++) {
        uint32_t s = fs[f], e = fs[f + 1u];
        for (c = s; c < e; c++) {
            uint32_t a = cv[c], b = cv[c + 1u < e ? c + 1u : s];
            cnt[a < b ? b : a]++;
        }
    }
    counts_to_starts(cnt, nv);
    for (f = 0; f < nf; f++) {
        uint32_t s = fs[f], e = fs[f + 1u];
        for (c = s; c < e; c++) {
            uint32_t a = cv[c], b = cv[c + 1u < e ? c + 1u : s];
            tmp[cnt[a < b ? b : a]++] = c;
        }
    }
    for (v = 0; v < nv; v++) cnt[v] = 0;
    for (i = 0; i < nc; i++) {
        edge_ends(w, tmp[i], &lo, &hi);
        cnt[lo]++;
    }
    counts_to_starts(cnt, nv);
    for (i = 0; i < nc; i++) {
        edge_ends(w, tmp[i], &lo, &hi);
        out[cnt[lo]++] = tmp[i];
    }
}

/* Twins: the half-edges are sorted by undirected edge (sort_by_edge, with twin[] as its
 * temporary), so the half-edges of one edge form a run whose first entry is its smallest
 * corner. More than two half-edges on one edge is a non-manifold edge; two in the same
 * direction means one of the faces is flipped. The error reported is that of the bad edge
 * with the smallest corner (the first one a scan of the corners in order meets), naming the
 * largest face on that edge. */
static int build_twins(subd_mesh *m, uint32_t *cnt, uint32_t *sorted, subd_diag *d)
{
    const mesh_view w = view_of(m);
    const uint32_t nc = w.nc, *cv = w.cv, *cf = w.cf;
    uint32_t *twin = m->twin;
    uint32_t i, j, h, bad_head = SUBD_NONE, bad_face = 0;
    int bad_st = SUBD_OK;
    sort_by_edge(&w, cnt, twin, sorted);
    for (h = 0; h < nc; h++) twin[h] = SUBD_NONE;
    for (i = 0; i < nc; i = j) {
        uint32_t head = sorted[i], lo, hi, glo, ghi, last_face = cf[head];
        edge_ends(&w, head, &lo, &hi);
        for (j = i + 1u; j < nc; j++) {
            uint32_t g = sorted[j];
            edge_ends(&w, g, &glo, &ghi);
            if (glo != lo || ghi != hi) break;
            if (cf[g] > last_face) last_face = cf[g];
        }
        if (j - i == 2u && cv[sorted[i + 1u]] != cv[head]) {
            twin[head] = sorted[i + 1u];
            twin[sorted[i + 1u]] = head;
        } else if (j - i >= 2u && head < bad_head) {
            bad_head = head;
            bad_face = last_face;
            bad_st = (j - i > 2u) ? SUBD_ERR_NONMANIFOLD_EDGE : SUBD_ERR_ORIENTATION;
        }
    }
    if (bad_st == SUBD_OK) return SUBD_OK;
    d->face = bad_face;
    return subd_fail(d, bad_st);
}

/* Boundary loops: from a boundary half-edge a->b the next one along the loop is b's
 * outgoing boundary half-edge, vert_out[b]. Each loop is walked once (a pass-long
 * TOPO_ETAG_VISITED bit marks the walked half-edges). */
static uint32_t mesh_boundary_loops(subd_mesh *m, uint32_t nbe)
{
    uint32_t h, loops = 0;
    if (nbe == 0) return 0;
    for (h = 0; h < m->num_corners; h++) {
        uint32_t g = h, steps = 0;
        if ((m->edge_tag[h] & (SUBD_ETAG_BOUNDARY | TOPO_ETAG_VISITED)) != SUBD_ETAG_BOUNDARY) continue;
        loops++;
        do {
            m->edge_tag[g] = (uint8_t)(m->edge_tag[g] | TOPO_ETAG_VISITED);
            g = m->vert_out[subd_he_dest(m, g)];
            steps++;
        } while (g != h && steps <= nbe);
    }
    for (h = 0; h < m->num_corners; h++) m->edge_tag[h] = (uint8_t)(m->edge_tag[h] & ~TOPO_ETAG_VISITED);
    return loops;
}

void subd_mesh_fans(subd_mesh *m, const uint8_t *keep)
{
    uint32_t v, c, nbe = 0, niso = 0;
    for (v = 0; v < m->num_verts; v++) m->vert_out[v] = SUBD_NONE;
    for (c = m->num_corners; c-- > 0;) m->vert_out[m->corner_vert[c]] = c; /* lowest corner last */
    for (v = 0; v < m->num_verts; v++) {
        uint8_t t = keep ? keep[v] : (uint8_t)0u;
        if (m->vert_out[v] == SUBD_NONE) {
            t = (uint8_t)(t | SUBD_VTAG_ISOLATED);
            niso++;
        }
        m->vert_tag[v] = t;
    }
    for (c = 0; c < m->num_corners; c++) {
        if (m->twin[c] == SUBD_NONE) {
            v = m->corner_vert[c];
            m->vert_out[v] = c;
            m->vert_tag[v] = (uint8_t)(m->vert_tag[v] | SUBD_VTAG_BOUNDARY);
            m->edge_tag[c] = (uint8_t)(m->edge_tag[c] | SUBD_ETAG_BOUNDARY);
            nbe++;
        }
    }
    m->num_isolated = niso;
    m->num_boundary_edges = nbe;
    m->num_edges = (m->num_corners + nbe) / 2u;
    m->num_boundary_loops = mesh_boundary_loops(m, nbe);
}

/* Fans (subd_mesh_fans, the convention), then their check: a manifold vertex has at most one
 * boundary half-edge going out, and one walk around it from there (or from its smallest
 * corner if interior) reaches all of its corners, deg of them. A vertex with two outgoing
 * boundary half-edges fails the same count (a walk from one never reaches the other, whose
 * twin is none). */
static int build_fans(subd_mesh *m, uint32_t *deg, subd_diag *d)
{
    uint32_t v, h;
    for (h = 0; h < m->num_corners; h++) m->edge_tag[h] = 0;
    subd_mesh_fans(m, 0);
    for (v = 0; v < m->num_verts; v++) deg[v] = 0;
    for (h = 0; h < m->num_corners; h++) deg[m->corner_vert[h]]++;
    for (v = 0; v < m->num_verts; v++) {
        uint32_t start = m->vert_out[v], steps;
        if (deg[v] == 0) continue;
        steps = 1;
        for (h = subd_ring_next(m, start, start); h != SUBD_NONE && steps <= deg[v]; h = subd_ring_next(m, start, h))
            steps++;
        if (steps != deg[v]) {
            d->vertex = v;
            return subd_fail(d, SUBD_ERR_NONMANIFOLD_VERTEX);
        }
    }
    return SUBD_OK;
}

int subd_mesh_finish(subd_arena *a, subd_mesh *m, subd_diag *d)
{
    uint32_t mark = subd_arena_mark(a);
    uint32_t *vstart, *vcorner, f, c;
    int st;

    if ((st = check_faces(m, d)) != SUBD_OK) return st;
    if ((st = check_positions(m, d)) != SUBD_OK) return st;

    for (f = 0; f < m->num_faces; f++)
        for (c = m->face_start[f]; c < m->face_start[f + 1u]; c++) m->corner_face[c] = f;

    if (scratch_layout(a, m->num_verts, m->num_corners, &vstart, &vcorner, 0) != SUBD_OK) {
        subd_arena_rewind(a, mark);
        return subd_fail(d, SUBD_ERR_NOMEM);
    }
    st = build_twins(m, vstart, vcorner, d);
    if (st == SUBD_OK) st = build_fans(m, vstart, d);
    subd_arena_rewind(a, mark);
    return st;
}

static int face_list_counts(const subd_face_list *fl, mesh_counts *c, subd_diag *d)
{
    uint64_t nc = 0, nlv = 0;
    uint32_t f;
    for (f = 0; f < fl->num_faces; f++) {
        uint32_t k = fl->face_size ? fl->face_size[f] : 3u;
        if (k < 3u || k > SUBD_MAX_FACE_SIZE) {
            d->face = f;
            return subd_fail(d, SUBD_ERR_FACE_SIZE);
        }
        nc += k;
    }
    for (f = 0; f < fl->num_lines; f++) nlv += fl->line_size[f];
    if (nc >= UINT32_MAX || nlv >= UINT32_MAX) return subd_fail(d, SUBD_ERR_TOO_BIG);
    c->nv = fl->num_verts;
    c->nf = fl->num_faces;
    c->nc = (uint32_t)nc;
    c->nl = fl->num_lines;
    c->nlv = (uint32_t)nlv;
    return SUBD_OK;
}

static int face_list_ok(const subd_face_list *fl)
{
    if (!fl) return 0;
    if (fl->num_verts && !fl->pos) return 0;
    if (fl->num_faces && !fl->index) return 0;
    if (fl->num_lines && (!fl->line_size || !fl->line_index)) return 0;
    return 1;
}

int subd_mesh_plan(const subd_face_list *fl, uint32_t *bytes)
{
    mesh_counts c;
    subd_diag d;
    int st;
    if (!face_list_ok(fl) || !bytes) return SUBD_ERR_PARAM;
    subd_diag_clear(&d);
    if ((st = face_list_counts(fl, &c, &d)) != SUBD_OK) return st;
    *bytes = subd_mesh_counts_bytes(&c);
    return (*bytes == UINT32_MAX) ? SUBD_ERR_TOO_BIG : SUBD_OK;
}

int subd_mesh_build(subd_arena *arena, const subd_face_list *fl, subd_mesh *out, subd_diag *diag)
{
    subd_entry e;
    subd_diag *d = subd_entry_begin(&e, arena, diag);
    subd_mesh m;
    mesh_counts c;
    uint32_t i, f;
    int st;

    if (!arena || !out || !face_list_ok(fl)) return subd_entry_fail(&e, SUBD_ERR_PARAM);
    if (fl->num_verts == 0) return subd_entry_fail(&e, SUBD_ERR_EMPTY);
    if ((st = face_list_counts(fl, &c, d)) != SUBD_OK) return subd_entry_fail(&e, st);
    d->bytes_needed = subd_mesh_counts_bytes(&c);
    if ((st = subd_mesh_alloc_arrays(arena, &c, &m)) != SUBD_OK) return subd_entry_fail(&e, st);
    for (i = 0; i < 3u * c.nv; i++) m.pos[i] = fl->pos[i];
    m.face_start[0] = 0;
    for (f = 0; f < c.nf; f++) m.face_start[f + 1u] = m.face_start[f] + (fl->face_size ? fl->face_size[f] : 3u);
    for (i = 0; i < c.nc; i++) m.corner_vert[i] = fl->index[i];
    m.line_start[0] = 0;
    for (f = 0; f < c.nl; f++) m.line_start[f + 1u] = m.line_start[f] + fl->line_size[f];
    for (i = 0; i < c.nlv; i++) m.line_vert[i] = fl->line_index[i];
    if ((st = subd_mesh_finish(arena, &m, d)) != SUBD_OK) return subd_entry_fail(&e, st);
    *out = m;
    return subd_entry_ok(&e);
}

uint32_t subd_vertex_ring(const subd_mesh *m, uint32_t v, uint32_t *nbr, uint32_t max)
{
    uint32_t n = 0;
    topo_ring r;
    if (!subd_topo_has(m, TOPO_ALWAYS | TOPO_VERT_OUT | TOPO_TWIN | TOPO_CORNER_FACE | TOPO_VERT_TAG) ||
        v >= m->num_verts)
        return 0;
    /* topo.h's walk: on a boundary its tail, the origin of the incoming boundary edge, is
     * the last neighbour */
    topo_ring_begin(&r, m, v);
    while (topo_ring_step(&r)) {
        if (n < max) nbr[n] = r.nb;
        n++;
    }
    return n;
}

uint32_t subd_vertex_valence(const subd_mesh *m, uint32_t v)
{
    return subd_vertex_ring(m, v, 0, 0);
}

/* Guarded so that no input crashes: a NULL mesh, an out-of-range half-edge or a mesh without
 * edge tags is left alone; without twins (subd_loop output without SUBD_LOOP_ADJACENCY) only h
 * itself changes, as there is no other half-edge to keep equal. */
static void edge_tag_update(subd_mesh *m, uint32_t h, uint8_t set, uint8_t keep)
{
    uint32_t t;
    if (!m || !m->edge_tag || h >= m->num_corners) return;
    m->edge_tag[h] = (uint8_t)((m->edge_tag[h] & keep) | set);
    t = m->twin ? m->twin[h] : SUBD_NONE;
    if (t < m->num_corners) m->edge_tag[t] = (uint8_t)((m->edge_tag[t] & keep) | set);
}

void subd_edge_tag_set(subd_mesh *m, uint32_t h, uint8_t bits) { edge_tag_update(m, h, bits, 0xffu); }

void subd_edge_tag_clear(subd_mesh *m, uint32_t h, uint8_t bits) { edge_tag_update(m, h, 0u, (uint8_t)~bits); }

int32_t subd_mesh_euler(const subd_mesh *m)
{
    if (!m) return 0;
    return (int32_t)m->num_verts - (int32_t)m->num_edges + (int32_t)m->num_faces;
}
