/* SPDX-License-Identifier: MIT */
/* Doo-Sabin type alpha-subdivision surface S_2(f; n) (Zhang & Wang 2002, section 2.1,
 * formula (3), theorem 2) and the higher orders S_k = C^(k-2) S_2 (section 2.2, figure 3;
 * C is the dual averaging step dual_step below, see subd_alpha.h for its boundary rule).
 *
 * Geometry: for corner i of an N-gon with centroid c and d_j = p_j - c,
 *   p_i' = c + f/(1+f) d_i + f/(2(1+f)^2) (d_{i-1} + d_{i+1}),
 * which is formula (3) rewritten with its weights' sum 1 (f/(1+f) + f/(1+f)^2 + 1/(1+f)^2 = 1):
 * the centroid is formed once per face, so the face's centroid is kept up to rounding
 * (theorem 2) and a translation moves every output point by the same amount. The two
 * weights come from the kernel in Q32.32 (alpha_kernel.c); Q16.16 products are formed in
 * 128 bits and rounded once per point.
 *
 * Topology (Doo-Sabin, the paper's figure 1): output vertex j is input corner j; faces are
 * the input faces (corner order kept), a quad [next(h), h, next(t), t] per interior edge
 * (h < t = twin(h)), and per interior vertex the face of its corners in ring order. The
 * arrays go through subd_mesh_finish, the builder's own validator.
 *
 * Valence 2 (the paper is silent): an interior vertex with two faces would give a digon
 * [h1, h2] whose two edges are also edges of the two neighbouring edge quads (a
 * non-manifold edge). We collapse the digon to an edge: the vertex makes no face, and the
 * two edge quads share the edge h1 h2 (opposite orientations), so h1 and h2 are interior
 * output vertices of valence 3. Only the input can have such vertices (every interior
 * vertex of an S_2 or C output has valence >= 3); the counts below subtract D2 of them.
 *
 * Boundary (the paper is silent): boundary edges and vertices make no face; boundary faces
 * use formula (3) unchanged. The surface therefore recedes from the boundary polygon, as
 * Doo-Sabin without boundary rules does; it stays a valid manifold with boundary and keeps
 * its Euler characteristic.
 *
 * Counts (exact plan without doing the work): with E_i interior edges, V_i interior
 * vertices and S the corners at interior vertices, one step gives
 *   V' = C, F' = F + E_i + V_i, C' = C + 4 E_i + S, E_i' = 2 E_i + S, V_i' = S, S' = 4 S
 * (an output vertex is interior iff its input vertex is, and then has valence 4; boundary
 * vertices and boundary edges of the output are equal in number, C - S).
 *
 * Dual step C counts (B = boundary vertices = boundary edges, a manifold boundary: every
 * mesh C sees is a Doo-Sabin or C output, whose boundary vertices have one fan each):
 *   V' = F + 2B, F' = V, C' = C + 3B, E_i' = E_i + B, V_i' = F, S' = C, B' = 2B.
 * A face of C has as many corners as its vertex has faces, plus 3 on the boundary: an
 * interior vertex of an S_2 output has 4 faces and one of a C output as many as a face of
 * the mesh before (<= SUBD_MAX_FACE_SIZE); boundary vertices have at most 3 faces (S_2) or
 * 2 (C). So the input's valence check is the only face size check needed.
 *
 * Memory: the first step (S_2 of level 1) builds its mesh above the caller's mark; each
 * later step (S_2 or C) builds above the previous one and is then moved down over it (a
 * forward byte copy to a lower address; the arrays hold indices, never pointers), so the
 * peak is two consecutive steps plus the validator's scratch, and after success only the
 * last step's arrays remain. C keeps its index maps in the new mesh's twin and corner_face
 * arrays before the validator fills them, so it needs no scratch of its own.
 */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "alpha_internal.h"
#include "entry.h"
#include "real_avg.h"
#include "topo.h"

typedef struct ds_stats {
    uint32_t v, f, c, ei, vi, s;
    uint32_t d2; /* interior vertices of valence 2 (their digons collapse; input only)  */
    uint32_t b; /* boundary vertices = boundary edges (after a step; not used for the input) */
} ds_stats;

static int input_stats(const subd_mesh *m, ds_stats *st, uint32_t *bad_vertex)
{
    uint32_t h, v;
    st->v = m->num_verts;
    st->f = m->num_faces;
    st->c = m->num_corners;
    st->ei = st->vi = st->s = st->b = st->d2 = 0;
    *bad_vertex = SUBD_NONE;
    for (h = 0; h < m->num_corners; h++)
        if (m->twin[h] != SUBD_NONE && h < m->twin[h]) st->ei++;
    for (v = 0; v < m->num_verts; v++) {
        uint32_t first = m->vert_out[v], h2, k = 0;
        if (first == SUBD_NONE || (m->vert_tag[v] & SUBD_VTAG_BOUNDARY)) continue;
        for (h2 = first; h2 != SUBD_NONE && k <= m->num_corners; h2 = subd_ring_next(m, first, h2)) k++;
        if (k > SUBD_MAX_FACE_SIZE) {
            *bad_vertex = v;
            return SUBD_ERR_FACE_SIZE;
        }
        st->vi++;
        st->s += k;
        if (k == 2u) st->d2++;
    }
    return SUBD_OK;
}

/* One step's counts (dual = 0: Doo-Sabin type S_2; dual = 1: the dual averaging C), or 0
 * when they do not fit 32 bits. */
static int next_stats(const ds_stats *a, int dual, ds_stats *b)
{
    uint64_t v, f, c, ei, vi, s, nb;
    if (!dual) {
        /* a valence-2 vertex makes no face (its digon collapses to an edge): one face, two
         * corners and one interior edge fewer, and its two corners get valence 3 */
        v = a->c;
        f = (uint64_t)a->f + a->ei + a->vi - a->d2;
        c = (uint64_t)a->c + 4u * (uint64_t)a->ei + a->s - 2u * (uint64_t)a->d2;
        ei = 2u * (uint64_t)a->ei + a->s - a->d2;
        vi = a->s;
        s = 4u * (uint64_t)a->s - 2u * (uint64_t)a->d2;
        nb = a->c - a->s;
    } else {
        v = (uint64_t)a->f + 2u * (uint64_t)a->b;
        f = (uint64_t)a->vi + a->b;
        c = (uint64_t)a->c + 3u * (uint64_t)a->b;
        ei = (uint64_t)a->ei + a->b;
        vi = a->f;
        s = a->c;
        nb = 2u * (uint64_t)a->b;
    }
    if (v >= (1u << 28) || f >= (1u << 28) || c >= (1u << 28) || ei >= (1u << 28) || s >= (1u << 28) ||
        nb >= (1u << 28))
        return 0;
    b->v = (uint32_t)v;
    b->f = (uint32_t)f;
    b->c = (uint32_t)c;
    b->ei = (uint32_t)ei;
    b->vi = (uint32_t)vi;
    b->s = (uint32_t)s;
    b->b = (uint32_t)nb;
    b->d2 = 0; /* every interior vertex of an S_2 or C output has valence >= 3 */
    return 1;
}

static void to_counts(const ds_stats *s, mesh_counts *c)
{
    c->nv = s->v;
    c->nf = s->f;
    c->nc = s->c;
    c->nl = 0;
    c->nlv = 0;
}

/* Which kind of element carries the tags after step j of a level (j = 0: S_2, j >= 1: the
 * j-th C): S_2 leaves face tags and each C swaps the kind (alpha_tags.c). */
static int step_vertex_tags(uint32_t j) { return (j & 1u) != 0u; }

/* The kind tagged at the start of a level: vertices for odd k, faces for even k. */
static int level_vertex_tags(const subd_alpha_opts *o) { return (o->order & 1u) != 0u; }

/* Bytes of one step's output tags (0 without tags): one int32 per tagged element. */
static uint32_t tag_bytes(const subd_alpha_opts *o, const ds_stats *s, uint32_t j)
{
    if (!o->tag_num) return 0;
    return SUBD_ALIGN_UP(4u * (step_vertex_tags(j) ? s->v : s->f));
}

/* The arena of every step t > 0: [previous mesh arrays][previous tags][this step's arrays]
 * [this step's tags][the validator's scratch]; then this step's arrays and tags move down to
 * the caller's mark. The peak is the largest such sum. */
static int surface_plan(const subd_mesh *in, const subd_alpha_opts *o, uint32_t *bytes, subd_diag *d)
{
    ds_stats cur, nxt;
    mesh_counts c;
    uint32_t t, peak = 0, prev = 0, bad;
    int st = input_stats(in, &cur, &bad);
    if (st != SUBD_OK) {
        d->vertex = bad;
        return st;
    }
    for (t = 0; t < o->levels * (o->order - 1u); t++) {
        uint32_t total, tags;
        uint64_t here;
        if (!next_stats(&cur, t % (o->order - 1u) != 0u, &nxt)) return SUBD_ERR_TOO_BIG;
        to_counts(&nxt, &c);
        total = subd_mesh_counts_bytes(&c);
        tags = tag_bytes(o, &nxt, t % (o->order - 1u)); /* counts < 2^28: no wrap */
        here = (uint64_t)total + prev + tags;
        if (total == UINT32_MAX || here >= UINT32_MAX) return SUBD_ERR_TOO_BIG;
        if (here > peak) peak = (uint32_t)here;
        prev = subd_mesh_arrays_bytes(&c) + tags;
        cur = nxt;
    }
    *bytes = peak;
    return SUBD_OK;
}

/* The arrays the steps read; a mesh without adjacency (e.g. subd_loop output without
 * SUBD_LOOP_ADJACENCY: twin and vert_out NULL) is refused. */
#define ALPHA_SURFACE_NEEDS                                                                                   \
    (TOPO_FACE_START | TOPO_POS | TOPO_VERT_OUT | TOPO_VERT_TAG | TOPO_CORNER_VERT | TOPO_CORNER_FACE | TOPO_TWIN)

static int check_args(const subd_mesh *in, const subd_alpha_opts *o, int64_t *s_q32)
{
    int st;
    if (!subd_topo_has(in, ALPHA_SURFACE_NEEDS)) return SUBD_ERR_PARAM;
    if ((st = subd_alpha_check_opts(o, SUBD_ALPHA_MAX_ORDER, s_q32)) != SUBD_OK) return st;
    if (o->levels < 1u) return SUBD_ERR_PARAM;
    if (in->num_faces == 0) return SUBD_ERR_EMPTY;
    return SUBD_OK;
}

int subd_alpha_surface_plan(const subd_mesh *in, const subd_alpha_opts *o, uint32_t *bytes, subd_diag *diag)
{
    subd_diag own, *d = subd_plan_begin(&own, diag);
    int64_t s;
    int st;
    if (!bytes) return subd_plan_end(d, SUBD_ERR_PARAM);
    if ((st = check_args(in, o, &s)) != SUBD_OK) return subd_plan_end(d, st);
    return subd_plan_end(d, surface_plan(in, o, bytes, d));
}

/* Face centroid, rounded once (Q16.16: exact sum, one rounded division). */
static subd_real centroid(const subd_mesh *m, uint32_t s, uint32_t e, uint32_t k, uint32_t *ovf)
{
    subd_sum sum = 0;
    uint32_t i;
    for (i = s; i < e; i++) sum = subd_sum_add(sum, m->pos[3u * m->corner_vert[i] + k]);
    return subd_avg(sum, e - s, ovf);
}

/* The two weights of formula (3) for one alpha numerator at one level, cached: with no
 * tags (or equal ones) the kernel runs once per level, as without tags. */
typedef struct ds_weights {
    const subd_alpha_opts *o;
    int64_t s_q32;
    uint32_t level;
    subd_alpha_kcache kc; /* the kernel value of the last face's alpha */
    subd_alpha_wt wa, wb;
} ds_weights;

static int ds_weights_for(ds_weights *w, int32_t num, uint32_t *ovf)
{
    int64_t f, u, a, b;
    int st, fresh;
    st = subd_alpha_kcache_get(&w->kc, w->o, num, w->o->alpha_den, w->level, w->s_q32, &f, &fresh);
    if (st != SUBD_OK || !fresh) return st;
    u = SUBD_Q32_ONE + f;
    a = subd_alpha_divq(f, u, 32, ovf);     /* f / (1 + f)        */
    b = subd_alpha_divq(a, 2 * u, 32, ovf); /* f / (2 (1 + f)^2)  */
    w->wa = subd_alpha_wt_from_q32(a, ovf);
    w->wb = subd_alpha_wt_from_q32(b, ovf);
    return SUBD_OK;
}

/* Formula (3) for every corner of every face of m, into pos (3 per corner); each face with
 * the alpha its tags give (t NULL: the options' alpha everywhere). */
static int ds_positions(const subd_mesh *m, ds_weights *w, int vertex_tags, const int32_t *t, subd_real *pos,
                        uint32_t *ovf)
{
    uint32_t f, k;
    for (f = 0; f < m->num_faces; f++) {
        uint32_t s = m->face_start[f], e = m->face_start[f + 1u], i;
        int32_t num = t ? subd_alpha_face_num(m, vertex_tags, t, f) : w->o->alpha_num;
        subd_alpha_wt wa, wb;
        int st = ds_weights_for(w, num, ovf);
        if (st != SUBD_OK) return st;
        wa = w->wa;
        wb = w->wb;
        for (k = 0; k < 3u; k++) {
            subd_real c = centroid(m, s, e, k, ovf);
            for (i = s; i < e; i++) {
                uint32_t ip = (i == s) ? e - 1u : i - 1u, in = (i + 1u == e) ? s : i + 1u;
                subd_alpha_diff di = subd_alpha_sub(m->pos[3u * m->corner_vert[i] + k], c, ovf);
                subd_alpha_diff dp = subd_alpha_sub(m->pos[3u * m->corner_vert[ip] + k], c, ovf);
                subd_alpha_diff dn = subd_alpha_sub(m->pos[3u * m->corner_vert[in] + k], c, ovf);
                pos[3u * i + k] = subd_alpha_comb(c, wa, di, wb, subd_alpha_dadd(dp, dn, ovf), ovf);
            }
        }
    }
    return SUBD_OK;
}

/* Doo-Sabin faces of m into out's face_start / corner_vert (counts already set). */
static void ds_faces(const subd_mesh *m, subd_mesh *out)
{
    uint32_t f, h, v, nf = 0, nc = 0;
    out->face_start[0] = 0;
    for (f = 0; f < m->num_faces; f++) {
        for (h = m->face_start[f]; h < m->face_start[f + 1u]; h++) out->corner_vert[nc++] = h;
        out->face_start[++nf] = nc;
    }
    for (h = 0; h < m->num_corners; h++) {
        uint32_t t = m->twin[h];
        if (t == SUBD_NONE || t < h) continue;
        out->corner_vert[nc++] = subd_he_next(m, h);
        out->corner_vert[nc++] = h;
        out->corner_vert[nc++] = subd_he_next(m, t);
        out->corner_vert[nc++] = t;
        out->face_start[++nf] = nc;
    }
    for (v = 0; v < m->num_verts; v++) {
        uint32_t first = m->vert_out[v], second;
        if (first == SUBD_NONE || (m->vert_tag[v] & SUBD_VTAG_BOUNDARY)) continue;
        second = subd_ring_next(m, first, first);
        if (second == SUBD_NONE || subd_ring_next(m, first, second) == SUBD_NONE) continue; /* digon */
        for (h = first; h != SUBD_NONE; h = subd_ring_next(m, first, h)) out->corner_vert[nc++] = h;
        out->face_start[++nf] = nc;
    }
    out->line_start[0] = 0;
}

/* The dual averaging operator C on m into out (counts already set): output vertices are
 * m's face centroids (face order), then the midpoints of m's boundary edges (half-edge
 * order), then m's boundary vertices (vertex order); one face per vertex of m (vertex
 * order): an interior vertex gives the centroids of its faces in ring order, a boundary
 * vertex v gives [v, mid(first boundary edge), centroids in ring order, mid(last boundary
 * edge)]. out->twin (>= m's corners) and out->corner_face (>= m's vertices) hold the index
 * maps until subd_mesh_finish overwrites them. */
static void dual_step(const subd_mesh *m, subd_mesh *out, uint32_t *ovf)
{
    uint32_t *emap = out->twin, *vmap = out->corner_face;
    uint32_t f, h, v, k, n = m->num_faces, nf = 0, nc = 0;
    for (f = 0; f < m->num_faces; f++)
        for (k = 0; k < 3u; k++) out->pos[3u * f + k] = centroid(m, m->face_start[f], m->face_start[f + 1u], k, ovf);
    for (h = 0; h < m->num_corners; h++) {
        uint32_t a, b;
        if (m->twin[h] != SUBD_NONE) continue;
        a = m->corner_vert[h];
        b = subd_he_dest(m, h);
        for (k = 0; k < 3u; k++) out->pos[3u * n + k] = subd_mid_of_sum(m->pos[3u * a + k], m->pos[3u * b + k], ovf);
        emap[h] = n++;
    }
    for (v = 0; v < m->num_verts; v++) {
        if (m->vert_out[v] == SUBD_NONE || !(m->vert_tag[v] & SUBD_VTAG_BOUNDARY)) continue;
        for (k = 0; k < 3u; k++) out->pos[3u * n + k] = m->pos[3u * v + k];
        vmap[v] = n++;
    }
    out->face_start[0] = 0;
    for (v = 0; v < m->num_verts; v++) {
        uint32_t first = m->vert_out[v];
        topo_ring r;
        if (first == SUBD_NONE) continue;
        if (m->vert_tag[v] & SUBD_VTAG_BOUNDARY) {
            out->corner_vert[nc++] = vmap[v];
            out->corner_vert[nc++] = emap[first];
        }
        /* the faces around v in ring order; on a boundary topo.h's tail is the incoming
         * boundary edge, whose midpoint closes the face */
        topo_ring_begin(&r, m, v);
        while (topo_ring_step(&r)) out->corner_vert[nc++] = r.tail ? emap[r.he] : m->corner_face[r.he];
        out->face_start[++nf] = nc;
    }
    out->line_start[0] = 0;
}

/* SUBD_OK when every input tag is within +-SUBD_ALPHA_MAX_NUM; else SUBD_ERR_PARAM with
 * diag.vertex (odd k: vertex tags) or diag.face (even k: face tags). */
static int check_tags(const subd_mesh *in, const subd_alpha_opts *o, subd_diag *d)
{
    int vt = level_vertex_tags(o);
    uint32_t n = vt ? in->num_verts : in->num_faces, i;
    for (i = 0; o->tag_num && i < n; i++)
        if (o->tag_num[i] > SUBD_ALPHA_MAX_NUM || o->tag_num[i] < -SUBD_ALPHA_MAX_NUM) {
            if (vt) d->vertex = i;
            else d->face = i;
            return SUBD_ERR_PARAM;
        }
    return SUBD_OK;
}

int subd_alpha_surface(subd_arena *arena, const subd_mesh *in, const subd_alpha_opts *o, subd_mesh *out,
                       subd_alpha_surface_info *info, subd_diag *diag)
{
    subd_entry e;
    subd_diag *d = subd_entry_begin(&e, arena, diag);
    int64_t s_q32;
    uint32_t mark = e.mark, bytes, t, i, ovf = 0, keep = 0;
    subd_mesh prev, cur;
    ds_stats st_in, st_cur;
    ds_weights w;
    const int32_t *prev_tags;
    int32_t *cur_tags = 0;
    int prev_vt, st;

    if (!arena || !out) return subd_entry_fail(&e, SUBD_ERR_PARAM);
    if ((st = check_args(in, o, &s_q32)) != SUBD_OK) return subd_entry_fail(&e, st);
    for (i = 0; i < 3u * in->num_verts; i++)
        if (!subd_real_is_finite(in->pos[i])) {
            d->vertex = i / 3u;
            return subd_entry_fail(&e, SUBD_ERR_NAN);
        }
    if ((st = check_tags(in, o, d)) != SUBD_OK) return subd_entry_fail(&e, st);
    if ((st = surface_plan(in, o, &bytes, d)) != SUBD_OK) return subd_entry_fail(&e, st);
    if (bytes > subd_arena_free_bytes(arena)) {
        d->bytes_needed = bytes;
        return subd_entry_fail(&e, SUBD_ERR_NOMEM);
    }
    input_stats(in, &st_in, &i);
    st_cur = st_in;
    prev = *in;
    prev_tags = o->tag_num; /* the caller's: read in place */
    prev_vt = level_vertex_tags(o);
    w.o = o;
    w.s_q32 = s_q32;
    w.level = 0;
    subd_alpha_kcache_reset(&w.kc);
    w.wa = w.wb = 0;
    for (t = 0; t < o->levels * (o->order - 1u); t++) {
        ds_stats nx;
        mesh_counts c;
        uint32_t j = t % (o->order - 1u), tb, arrays;
        next_stats(&st_cur, j != 0u, &nx);
        to_counts(&nx, &c);
        arrays = subd_mesh_arrays_bytes(&c);
        tb = tag_bytes(o, &nx, j);
        if ((st = subd_mesh_alloc_arrays(arena, &c, &cur)) != SUBD_OK) break;
        if (tb) {
            /* right after the arrays, so the two move down as one block */
            cur_tags = (int32_t *)subd_arena_alloc(arena, tb);
            if (!cur_tags) { /* not expected: the plan counted it */
                st = SUBD_ERR_NOMEM;
                break;
            }
        }
        if (j == 0u) {
            w.level = t / (o->order - 1u);
            subd_alpha_kcache_reset(&w.kc);
            st = ds_positions(&prev, &w, prev_vt, prev_tags, cur.pos, &ovf);
            if (st != SUBD_OK) break;
            if (!ovf) ds_faces(&prev, &cur);
            if (cur_tags) subd_alpha_tags_s2(&prev, prev_vt, prev_tags, cur_tags);
        } else {
            dual_step(&prev, &cur, &ovf);
            if (cur_tags) subd_alpha_tags_dual(&prev, prev_vt, prev_tags, cur_tags);
        }
        if (ovf) {
            st = SUBD_ERR_RANGE;
            break;
        }
        st = subd_mesh_finish(arena, &cur, d);
        if (st != SUBD_OK) {
            /* (not expected: every step of a valid input is valid) an intermediate mesh's
             * element means nothing to the caller: name none */
            d->face = d->vertex = d->polyline = SUBD_NONE;
            d->line = 0;
            break;
        }
        if (t > 0u) {
            /* drop the previous mesh (and its tags): move this one down to where it started */
            uint32_t delta = (uint32_t)((uint8_t *)cur.pos - (arena->base + mark));
            subd_arena_rewind(arena, mark);
            subd_mesh_move_down(&cur, arena->base + mark, arrays + tb);
            subd_arena_alloc(arena, arrays + tb);
            if (cur_tags) cur_tags = (int32_t *)(void *)((uint8_t *)cur_tags - delta);
        }
        prev = cur;
        prev_tags = cur_tags;
        prev_vt = step_vertex_tags(j);
        st_cur = nx;
        keep = arrays;
    }
    if (st != SUBD_OK) return subd_entry_fail(&e, st); /* d->bytes_needed is still 0 here */
    if (o->tag_num) subd_arena_rewind(arena, mark + keep); /* the last tags were scratch */
    *out = cur;
    if (info) info->continuity = subd_alpha_continuity(s_q32, 1);
    return subd_entry_ok(&e);
}
