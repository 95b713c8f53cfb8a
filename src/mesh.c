/* Index mesh: validation and adjacency from a plain face list.
 *
 * Adjacency is built the meshoptimizer way, by counting and prefix sums: the corners of
 * each vertex are bucketed (count, prefix sum, scatter in corner order), and the twin of
 * half-edge a->b is looked up in b's bucket. Buckets keep corner order, so every result
 * is independent of memory addresses and of the platform; there is no hashing and no sort.
 * Cost: O(C + sum of valence^2), no recursion, constant stack.
 *
 * Conventions (see subd.h): corner c is also the half-edge from corner_vert[c] to the next
 * corner's vertex in the same face; vert_out[v] is v's boundary half-edge when v is on a
 * boundary, so one walk from it visits v's whole fan in order.
 */
#include "mesh_internal.h"
#include "layout.h"
#include "entry.h"

#define TAG_VISITED 0x80u /* temporary edge_tag bit while walking boundary loops */

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
            if (!d) return SUBD_ERR_FACE_SIZE;
            d->face = f;
            return subd_fail(d, SUBD_ERR_FACE_SIZE);
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

/* The builder's scratch (layout.h): per-vertex bucket starts and the bucketed corners. */
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

/* Twins: for half-edge a->b, the half-edges b->a are in b's bucket and any duplicate a->b
 * in a's. More than two half-edges on one edge is a non-manifold edge; two in the same
 * direction (and none opposite) means one of the faces is flipped. */
static int build_twins(subd_mesh *m, const uint32_t *vstart, const uint32_t *vcorner, subd_diag *d)
{
    uint32_t h, k;
    for (h = 0; h < m->num_corners; h++) m->twin[h] = SUBD_NONE;
    for (h = 0; h < m->num_corners; h++) {
        uint32_t a = m->corner_vert[h], b = subd_he_dest(m, h);
        uint32_t same = 0, rev = 0, other = SUBD_NONE, last_face = m->corner_face[h];
        for (k = vstart[a]; k < vstart[a + 1u]; k++) {
            uint32_t g = vcorner[k];
            if (subd_he_dest(m, g) == b) {
                same++;
                if (m->corner_face[g] > last_face) last_face = m->corner_face[g];
            }
        }
        for (k = vstart[b]; k < vstart[b + 1u]; k++) {
            uint32_t g = vcorner[k];
            if (subd_he_dest(m, g) == a) {
                rev++;
                other = g;
                if (m->corner_face[g] > last_face) last_face = m->corner_face[g];
            }
        }
        if (same + rev > 2u) {
            d->face = last_face;
            return subd_fail(d, SUBD_ERR_NONMANIFOLD_EDGE);
        }
        if (same == 2u) {
            d->face = last_face;
            return subd_fail(d, SUBD_ERR_ORIENTATION);
        }
        if (rev == 1u) m->twin[h] = other;
    }
    return SUBD_OK;
}

/* Fans: a manifold vertex has at most one boundary half-edge going out, and one walk
 * around it from there (or from any half-edge if interior) reaches all of its corners. */
static int build_fans(subd_mesh *m, const uint32_t *vstart, const uint32_t *vcorner, subd_diag *d)
{
    uint32_t v, k;
    for (v = 0; v < m->num_verts; v++) {
        uint32_t deg = vstart[v + 1u] - vstart[v], start = SUBD_NONE, nb = 0, steps, h;
        m->vert_tag[v] = 0;
        m->vert_out[v] = SUBD_NONE;
        if (deg == 0) {
            m->vert_tag[v] = SUBD_VTAG_ISOLATED;
            m->num_isolated++;
            continue;
        }
        for (k = vstart[v]; k < vstart[v + 1u]; k++) {
            if (m->twin[vcorner[k]] == SUBD_NONE) {
                nb++;
                start = vcorner[k];
            }
        }
        if (nb > 1u) {
            d->vertex = v;
            return subd_fail(d, SUBD_ERR_NONMANIFOLD_VERTEX);
        }
        if (nb == 0) start = vcorner[vstart[v]];
        steps = 1;
        for (h = subd_ring_next(m, start, start); h != SUBD_NONE && steps <= deg; h = subd_ring_next(m, start, h))
            steps++;
        if (steps != deg) {
            d->vertex = v;
            return subd_fail(d, SUBD_ERR_NONMANIFOLD_VERTEX);
        }
        m->vert_out[v] = start;
        if (nb) m->vert_tag[v] = SUBD_VTAG_BOUNDARY;
    }
    return SUBD_OK;
}

/* Boundary loops: from a boundary half-edge a->b the next one along the loop is b's
 * outgoing boundary half-edge, vert_out[b]. Each loop is walked once. */
static void count_boundary_loops(subd_mesh *m)
{
    uint32_t h, nbe = 0, loops = 0;
    for (h = 0; h < m->num_corners; h++) {
        m->edge_tag[h] = (m->twin[h] == SUBD_NONE) ? SUBD_ETAG_BOUNDARY : 0u;
        if (m->twin[h] == SUBD_NONE) nbe++;
    }
    for (h = 0; h < m->num_corners; h++) {
        uint32_t g = h, steps = 0;
        if (m->edge_tag[h] != SUBD_ETAG_BOUNDARY) continue; /* interior or visited */
        loops++;
        do {
            m->edge_tag[g] |= TAG_VISITED;
            g = m->vert_out[subd_he_dest(m, g)];
            steps++;
        } while (g != h && steps <= nbe);
    }
    for (h = 0; h < m->num_corners; h++) m->edge_tag[h] &= (uint8_t)~TAG_VISITED;
    m->num_boundary_edges = nbe;
    m->num_boundary_loops = loops;
    m->num_edges = (m->num_corners + nbe) / 2u;
}

int subd_mesh_finish(subd_arena *a, subd_mesh *m, subd_diag *d)
{
    uint32_t mark = subd_arena_mark(a);
    uint32_t *vstart, *vcorner, v, f, c;
    int st;

    if ((st = check_faces(m, d)) != SUBD_OK) return st;
    if ((st = check_positions(m, d)) != SUBD_OK) return st;

    for (f = 0; f < m->num_faces; f++)
        for (c = m->face_start[f]; c < m->face_start[f + 1u]; c++) m->corner_face[c] = f;

    if (scratch_layout(a, m->num_verts, m->num_corners, &vstart, &vcorner, 0) != SUBD_OK) {
        subd_arena_rewind(a, mark);
        return subd_fail(d, SUBD_ERR_NOMEM);
    }
    /* count -> prefix sum -> scatter; vstart[v] ends as the first bucket slot of v */
    for (v = 0; v <= m->num_verts; v++) vstart[v] = 0;
    for (c = 0; c < m->num_corners; c++) vstart[m->corner_vert[c] + 1u]++;
    for (v = 0; v < m->num_verts; v++) vstart[v + 1u] += vstart[v];
    for (c = 0; c < m->num_corners; c++) vcorner[vstart[m->corner_vert[c]]++] = c;
    for (v = m->num_verts; v > 0; v--) vstart[v] = vstart[v - 1u];
    vstart[0] = 0;

    m->num_isolated = 0;
    st = build_twins(m, vstart, vcorner, d);
    if (st == SUBD_OK) st = build_fans(m, vstart, vcorner, d);
    subd_arena_rewind(a, mark);
    if (st != SUBD_OK) return st;
    count_boundary_loops(m);
    return SUBD_OK;
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
    uint32_t first, h, last = SUBD_NONE, n = 0;
    if (!m || v >= m->num_verts || !m->vert_out || !m->twin || !m->corner_face || !m->vert_tag) return 0;
    first = m->vert_out[v];
    if (first == SUBD_NONE) return 0;
    for (h = first; h != SUBD_NONE; h = subd_ring_next(m, first, h)) {
        if (n < max) nbr[n] = subd_he_dest(m, h);
        n++;
        last = h;
    }
    /* On a boundary the walk ends at the face whose incoming edge is the other boundary
     * edge; its origin is the last neighbour. */
    if (m->vert_tag[v] & SUBD_VTAG_BOUNDARY) {
        if (n < max) nbr[n] = m->corner_vert[subd_he_prev(m, last)];
        n++;
    }
    return n;
}

uint32_t subd_vertex_valence(const subd_mesh *m, uint32_t v)
{
    return subd_vertex_ring(m, v, 0, 0);
}

void subd_edge_tag_set(subd_mesh *m, uint32_t h, uint8_t bits)
{
    m->edge_tag[h] = (uint8_t)(m->edge_tag[h] | bits);
    if (m->twin[h] != SUBD_NONE) m->edge_tag[m->twin[h]] = (uint8_t)(m->edge_tag[m->twin[h]] | bits);
}

void subd_edge_tag_clear(subd_mesh *m, uint32_t h, uint8_t bits)
{
    m->edge_tag[h] = (uint8_t)(m->edge_tag[h] & ~bits);
    if (m->twin[h] != SUBD_NONE) m->edge_tag[m->twin[h]] = (uint8_t)(m->edge_tag[m->twin[h]] & ~bits);
}

int32_t subd_mesh_euler(const subd_mesh *m)
{
    return (int32_t)m->num_verts - (int32_t)m->num_edges + (int32_t)m->num_faces;
}
