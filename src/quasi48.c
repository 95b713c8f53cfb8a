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
 *    polyline keeps its shape at every step. (The paper's remark that boundary vertices
 *    "move along the surface normal direction" is not implemented: boundaries are either
 *    fixed, as in its planar figures, or smoothed as curves; see subd_q48_boundary.)
 *  - Smoothing of an old vertex uses exact weights: Q16.16 forms (k p + sum) / (2k) in 64
 *    bits with one rounding, so planar input stays exactly planar in z and weights sum to 1.
 *
 * Memory: two mesh buffers sized by the per-step bounds (ping-pong, the last step writes
 * the lower one, which becomes the output) and one set of per-step arrays sized for the
 * largest step, all planned by q48_layout.
 */
#include "mesh_internal.h"
#include "subd_quasi48.h"
#include "edge_sort.h"

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
    uint8_t *ekeep;     /* per output half-edge: crease tag to restore after the builder */
} q48_work;

static uint32_t builder_scratch(const mesh_counts *c)
{
    uint32_t b = 0;
    subd_size_add(&b, c->nv + 1u, 4u);
    subd_size_add(&b, c->nc, 4u);
    return b;
}

/* Bytes of the mesh arrays alone (the builder's scratch is counted separately). */
static uint32_t arrays_bytes(const mesh_counts *c)
{
    uint32_t b = subd_mesh_counts_bytes(c);
    return b == UINT32_MAX ? b : b - builder_scratch(c);
}

static void add_bytes(uint32_t *total, uint32_t b)
{
    if (b == UINT32_MAX || *total > UINT32_MAX - b) *total = UINT32_MAX;
    else *total += b;
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

/* The one layout: plan and run both call it, so they cannot drift apart. With w == NULL
 * it only counts; otherwise it allocates the per-step arrays in the same order. */
static int q48_layout_work(subd_arena *a, const q48_layout *L, q48_work *w, uint32_t *bytes)
{
    struct { void **slot; uint32_t count, elem; } arr[11];
    void *dummy[11];
    uint32_t i, n = 0, total = 0;
#define ARR(ptr, cnt, sz) do { arr[n].slot = w ? (void **)(void *)&(ptr) : &dummy[n]; \
                               arr[n].count = (cnt); arr[n].elem = (sz); n++; } while (0)
    q48_work tmp;
    q48_work *p = w ? w : &tmp;
    ARR(p->es.key[0], L->cs, 8u);
    ARR(p->es.key[1], L->cs, 8u);
    ARR(p->es.edge_of, L->cs, 4u);
    ARR(p->es.edge_he, L->cs, 4u);
    ARR(p->es.ord[0], L->cs, 4u);
    ARR(p->es.ord[1], L->cs, 4u);
    ARR(p->split, L->cs, 4u);
    ARR(p->es.mark, L->cs, 1u);
    ARR(p->es.cnt, 256u, 4u);
    ARR(p->vkeep, L->out.nv, 1u);
    ARR(p->ekeep, L->out.nc, 1u);
#undef ARR
    for (i = 0; i < n; i++) subd_size_add(&total, arr[i].count, arr[i].elem);
    *bytes = total;
    if (!a) return SUBD_OK;
    for (i = 0; i < n; i++) {
        void *q = subd_arena_alloc(a, arr[i].count * arr[i].elem);
        if (!q) return SUBD_ERR_NOMEM;
        *arr[i].slot = q;
    }
    return SUBD_OK;
}

static int q48_check(const subd_mesh *in, const subd_q48_opts *o, subd_diag *d)
{
    if (!in || !o || o->steps < 1u || o->steps > SUBD_Q48_MAX_STEPS || o->len_bits > SUBD_Q48_LEN_BITS_EXACT ||
        (o->boundary != SUBD_Q48_BOUNDARY_FIXED && o->boundary != SUBD_Q48_BOUNDARY_SMOOTH))
        return subd_fail(d, SUBD_ERR_PARAM);
    if (in->num_faces && (!in->twin || !in->vert_out || !in->corner_face || !in->edge_tag))
        return subd_fail(d, SUBD_ERR_PARAM);
    if (subd_require_triangles(in, d) != SUBD_OK) return SUBD_ERR_FACE_SIZE;
    if (in->num_faces == 0) return subd_fail(d, SUBD_ERR_EMPTY);
    return SUBD_OK;
}

static int q48_plan(const subd_mesh *in, const subd_q48_opts *o, q48_layout *L, subd_diag *d)
{
    uint32_t b = 0, wb;
    int st;
    if ((st = q48_check(in, o, d)) != SUBD_OK) return st;
    if ((st = counts_for(in, o->steps, &L->out)) != SUBD_OK) return subd_fail(d, st);
    if ((st = counts_for(in, o->steps - 1u, &L->mid)) != SUBD_OK) return subd_fail(d, st);
    L->cs = L->mid.nc; /* input of the last step: the output bound of step steps-1 */
    add_bytes(&b, arrays_bytes(&L->out));
    if (o->steps >= 2u) add_bytes(&b, arrays_bytes(&L->mid));
    q48_layout_work(0, L, 0, &wb);
    add_bytes(&b, wb);
    add_bytes(&b, builder_scratch(&L->out));
    L->bytes = b;
    if (b == UINT32_MAX) return subd_fail(d, SUBD_ERR_TOO_BIG);
    return SUBD_OK;
}

int subd_quasi48_plan(const subd_mesh *in, const subd_q48_opts *o, uint32_t *bytes)
{
    q48_layout L;
    subd_diag d;
    int st;
    subd_diag_clear(&d);
    if (!bytes) return SUBD_ERR_PARAM;
    st = q48_plan(in, o, &L, &d);
    if (st == SUBD_OK) *bytes = L.bytes;
    return st;
}

/* ------------------------------------------------------------------------------------ */
/* Arithmetic helpers: averages with exact weights in both arithmetics.                   */

#if SUBD_FIXED
typedef int64_t q48_sum;
static q48_sum q48_sum_add(q48_sum s, subd_real v) { return s + v; }
/* n / k rounded to nearest, ties away from zero (symmetric under negation). */
static subd_real q48_div_round(int64_t n, int64_t k)
{
    int64_t q = (n >= 0) ? (n + k / 2) / k : -((-n + k / 2) / k);
    return (subd_real)q; /* a convex combination of in-range values is in range */
}
static subd_real q48_avg(q48_sum s, uint32_t k, uint32_t *ovf)
{
    (void)ovf;
    return q48_div_round(s, (int64_t)k);
}
static subd_real q48_mid(subd_real a, subd_real b, uint32_t *ovf)
{
    (void)ovf;
    return q48_div_round((int64_t)a + b, 2);
}
/* 1/2 p + 1/2 (s / k) = (k p + s) / (2k), one rounding. */
static subd_real q48_blend(subd_real p, q48_sum s, uint32_t k, uint32_t *ovf)
{
    (void)ovf;
    return q48_div_round((int64_t)k * p + s, 2 * (int64_t)k);
}
#else
typedef float q48_sum;
static q48_sum q48_sum_add(q48_sum s, subd_real v) { return s + v; }
static subd_real q48_avg(q48_sum s, uint32_t k, uint32_t *ovf)
{
    return subd_chk(s / (float)k, ovf);
}
static subd_real q48_mid(subd_real a, subd_real b, uint32_t *ovf)
{
    subd_real ha = 0.5f * a, hb = 0.5f * b; /* no overflow of a + b near FLT_MAX */
    return subd_chk(ha + hb, ovf);
}
static subd_real q48_blend(subd_real p, q48_sum s, uint32_t k, uint32_t *ovf)
{
    subd_real avg = s / (float)k, hp = 0.5f * p, ha = 0.5f * avg;
    return subd_chk(hp + ha, ovf);
}
#endif

static int q48_refine(subd_arena *a, const subd_mesh *m, subd_mesh *o, const mesh_counts *cap, uint32_t bits,
                      q48_work *w, subd_diag *d)
{
    const uint32_t nv = m->num_verts, nf = m->num_faces;
    uint32_t ne, i, e, f, ns, nsf = 0, k, ovf = 0;
    int st;

    /* sort_edges, then split unmarked edges and mark their clusters (edge_sort.c) */
    ne = subd_edge_number(m, &w->es, m->num_corners);
    if (ne == SUBD_NONE) return subd_fail(d, SUBD_ERR_PARAM); /* cannot happen: E <= corners */
    ns = subd_edge_clusters(m, &w->es, ne, bits, 0, nv, w->split);
    for (f = 0; f < nf; f++) {
        uint32_t s = m->face_start[f];
        if (w->split[w->es.edge_of[s]] != SUBD_NONE || w->split[w->es.edge_of[s + 1u]] != SUBD_NONE ||
            w->split[w->es.edge_of[s + 2u]] != SUBD_NONE)
            nsf++;
    }
    /* ns <= nsf <= nf by the marking, so the bounds hold; checked anyway */
    if (nv + ns > cap->nv || nf + nsf > cap->nf) return subd_fail(d, SUBD_ERR_NOMEM);

    o->num_verts = nv + ns;
    o->num_faces = nf + nsf;
    o->num_corners = 3u * (nf + nsf);
    o->num_lines = m->num_lines;
    o->num_line_verts = m->num_line_verts;

    /* positions: old vertices copied, new ones at the midpoints */
    for (i = 0; i < 3u * nv; i++) o->pos[i] = m->pos[i];
    for (e = 0; e < ne; e++) {
        uint32_t v = w->split[e], h = w->es.edge_he[e];
        const subd_real *p, *q;
        if (v == SUBD_NONE) continue;
        p = m->pos + 3u * subd_he_origin(m, h);
        q = m->pos + 3u * subd_he_dest(m, h);
        for (k = 0; k < 3u; k++) o->pos[3u * v + k] = q48_mid(p[k], q[k], &ovf);
    }
    if (ovf) return subd_fail(d, SUBD_ERR_RANGE);
    for (i = 0; i < nv; i++) w->vkeep[i] = (uint8_t)(m->vert_tag[i] & (SUBD_VTAG_CORNER | SUBD_VTAG_FIXED));
    for (; i < nv + ns; i++) w->vkeep[i] = 0;

    /* subdiv: faces */
    o->face_start[0] = 0;
    for (f = 0; f <= nf + nsf; f++) o->face_start[f] = 3u * f;
    k = nf; /* next appended face */
    for (f = 0; f < nf; f++) {
        uint32_t s = m->face_start[f], j, at = 3u * f;
        for (j = 0; j < 3u; j++) {
            uint32_t h = s + j, v = w->split[w->es.edge_of[h]];
            if (v == SUBD_NONE) continue;
            {
                uint32_t h1 = s + (j + 1u) % 3u, h2 = s + (j + 2u) % 3u, bt = 3u * k;
                uint8_t cr = (uint8_t)(m->edge_tag[h] & SUBD_ETAG_CREASE);
                /* (a, m, c) at the face's index, (m, b, c) appended */
                o->corner_vert[at] = m->corner_vert[h];
                o->corner_vert[at + 1u] = v;
                o->corner_vert[at + 2u] = m->corner_vert[h2];
                w->ekeep[at] = cr;
                w->ekeep[at + 1u] = 0;
                w->ekeep[at + 2u] = (uint8_t)(m->edge_tag[h2] & SUBD_ETAG_CREASE);
                o->corner_vert[bt] = v;
                o->corner_vert[bt + 1u] = m->corner_vert[h1];
                o->corner_vert[bt + 2u] = m->corner_vert[h2];
                w->ekeep[bt] = cr;
                w->ekeep[bt + 1u] = (uint8_t)(m->edge_tag[h1] & SUBD_ETAG_CREASE);
                w->ekeep[bt + 2u] = 0;
                k++;
            }
            break;
        }
        if (j == 3u) {
            for (j = 0; j < 3u; j++) {
                o->corner_vert[at + j] = m->corner_vert[s + j];
                w->ekeep[at + j] = (uint8_t)(m->edge_tag[s + j] & SUBD_ETAG_CREASE);
            }
        }
    }
    o->line_start[0] = 0;
    for (i = 0; i < m->num_lines; i++) o->line_start[i + 1u] = m->line_start[i + 1u];
    for (i = 0; i < m->num_line_verts; i++) o->line_vert[i] = m->line_vert[i];

    st = subd_mesh_finish(a, o, d);
    if (st != SUBD_OK) return st;
    for (i = 0; i < o->num_verts; i++) o->vert_tag[i] = (uint8_t)(o->vert_tag[i] | w->vkeep[i]);
    for (i = 0; i < o->num_corners; i++) o->edge_tag[i] = (uint8_t)(o->edge_tag[i] | w->ekeep[i]);
    return SUBD_OK;
}

/* ------------------------------------------------------------------------------------ */
/* Algorithm 2: smoothing in place; vertices >= nv_old are the step's new vertices.       */

static int q48_smooth(subd_mesh *o, uint32_t nv_old, subd_q48_boundary bmode, const q48_work *w, subd_diag *d)
{
    uint8_t *pin = w->vkeep;
    uint32_t v, h, k, ovf = 0;
    const uint8_t fixed_bits = (uint8_t)(SUBD_VTAG_CORNER | SUBD_VTAG_FIXED | SUBD_VTAG_ISOLATED);

    for (v = 0; v < o->num_verts; v++) {
        uint8_t t = o->vert_tag[v];
        pin[v] = (uint8_t)((t & fixed_bits) != 0 ||
                           ((t & SUBD_VTAG_BOUNDARY) && (bmode == SUBD_Q48_BOUNDARY_FIXED || v >= nv_old)));
    }
    for (h = 0; h < o->num_corners; h++) {
        if (o->edge_tag[h] & SUBD_ETAG_CREASE) {
            pin[subd_he_origin(o, h)] = 1;
            pin[subd_he_dest(o, h)] = 1;
        }
    }
    /* pass 1: new interior vertices = average of their neighbours (all old) */
    for (v = nv_old; v < o->num_verts; v++) {
        uint32_t first = o->vert_out[v], n = 0;
        q48_sum s[3] = {0, 0, 0};
        if (pin[v]) continue;
        for (h = first; h != SUBD_NONE && n < o->num_corners; h = subd_ring_next(o, first, h)) {
            const subd_real *q = o->pos + 3u * subd_he_dest(o, h);
            for (k = 0; k < 3u; k++) s[k] = q48_sum_add(s[k], q[k]);
            n++;
        }
        for (k = 0; k < 3u; k++) o->pos[3u * v + k] = q48_avg(s[k], n, &ovf);
    }
    /* pass 2: old vertices = 1/2 own + 1/2 average of the new neighbours */
    for (v = 0; v < nv_old; v++) {
        uint32_t first = o->vert_out[v], n = 0, last = SUBD_NONE, steps = 0;
        q48_sum s[3] = {0, 0, 0};
        if (pin[v]) continue;
        if (o->twin[first] == SUBD_NONE) {
            /* boundary curve (smooth mode): only the two boundary neighbours count */
            uint32_t ends[2], j;
            for (h = first; h != SUBD_NONE && steps < o->num_corners; h = subd_ring_next(o, first, h), steps++)
                last = h;
            ends[0] = subd_he_dest(o, first);
            ends[1] = subd_he_origin(o, subd_he_prev(o, last));
            for (j = 0; j < 2u; j++) {
                if (ends[j] < nv_old) continue;
                for (k = 0; k < 3u; k++) s[k] = q48_sum_add(s[k], o->pos[3u * ends[j] + k]);
                n++;
            }
        } else {
            for (h = first; h != SUBD_NONE && steps < o->num_corners; h = subd_ring_next(o, first, h), steps++) {
                uint32_t u = subd_he_dest(o, h);
                if (u < nv_old) continue;
                for (k = 0; k < 3u; k++) s[k] = q48_sum_add(s[k], o->pos[3u * u + k]);
                n++;
            }
        }
        if (n == 0) continue;
        for (k = 0; k < 3u; k++) o->pos[3u * v + k] = q48_blend(o->pos[3u * v + k], s[k], n, &ovf);
    }
    if (ovf) return subd_fail(d, SUBD_ERR_RANGE);
    return SUBD_OK;
}

/* ------------------------------------------------------------------------------------ */

int subd_quasi48(subd_arena *a, const subd_mesh *in, const subd_q48_opts *o, subd_mesh *out, subd_diag *diag)
{
    subd_diag dummy;
    subd_diag *d = diag ? diag : &dummy;
    q48_layout L;
    q48_work w;
    subd_mesh buf[2];
    const subd_mesh *src = in;
    uint32_t mark, keep, s, wb, bits;
    int st;

    subd_diag_clear(d);
    if (!a || !out) return subd_fail(d, SUBD_ERR_PARAM);
    if ((st = q48_plan(in, o, &L, d)) != SUBD_OK) return st;
    d->bytes_needed = L.bytes;
    if (L.bytes > subd_arena_free_bytes(a)) return subd_fail(d, SUBD_ERR_NOMEM);
    bits = o->len_bits ? o->len_bits : SUBD_Q48_LEN_BITS_DEFAULT;

    mark = subd_arena_mark(a);
    st = subd_mesh_alloc_arrays(a, &L.out, &buf[0]);
    keep = subd_arena_mark(a);
    if (st == SUBD_OK && o->steps >= 2u) st = subd_mesh_alloc_arrays(a, &L.mid, &buf[1]);
    if (st == SUBD_OK) st = q48_layout_work(a, &L, &w, &wb);
    if (st != SUBD_OK) goto fail;

    for (s = 1; s <= o->steps; s++) {
        /* the last step writes buf[0]; earlier steps alternate, never onto their input */
        subd_mesh *dst = &buf[(o->steps - s) & 1u];
        const mesh_counts *cap = ((o->steps - s) & 1u) ? &L.mid : &L.out;
        st = q48_refine(a, src, dst, cap, bits, &w, d);
        if (st == SUBD_OK && !(o->flags & SUBD_Q48_NO_SMOOTH)) st = q48_smooth(dst, src->num_verts, o->boundary, &w, d);
        if (st != SUBD_OK) goto fail;
        src = dst;
    }
    subd_arena_rewind(a, keep);
    d->bytes_needed = 0;
    *out = buf[0];
    return SUBD_OK;
fail:
    subd_arena_rewind(a, mark);
    return subd_fail(d, st);
}
