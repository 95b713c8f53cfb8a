/* SPDX-License-Identifier: MIT */
/* The Loop stream's emitters: a batch of level-L triangles handed to the sink (push form) or
 * put in the caller's buffer (pull form), from the depth-first walk of loop_stream.c, whose
 * header comment gives the method, the bit-identity argument and the memory.
 * General path: the last two levels at once from level L-2's cache (emit_grandchildren: the
 * centre's 16 grandchildren, whose level L-1 rings and stencils are read off L-2's topology
 * without building the four level L-1 patches); one level in all from level 0
 * (emit_children); limit mode the centre of level L moved to the limit (emit_limit).
 * The tile hand-off: a regular tile's (loop_tile.c) 4^t triangles quarter by quarter in
 * subd_loop's order (tile_emit, resumable when the caller's buffer is full); the push form
 * hands them to the sink straight from the quarter's arrays (tile_push).
 * Emission order: the j-th triangle of control face f is subd_loop's face 4^L f + j, corners
 * in its order; the push form hands a batch to the sink from the one item, without the queue
 * between. */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "loop_stream_internal.h"
#include "mesh_internal.h"

typedef struct tile_p3 { subd_real v[3]; } tile_p3; /* one point: copied as a whole (ldm/stm) */

/* The next output slot: the caller's buffer, else the overflow ring, which holds a whole
 * batch (loop_stream.c's ring_cap), so it is never full here. */
static subd_tri *out_tri(const sp_run *r)
{
    subd_tri *t = (subd_tri *)subd_stream_q_put(r->q);
    t->face = r->f;
    t->level = r->o->levels;
    return t;
}

/* One emitted triangle from three level-L values and their ids. */
static int emit_tri(const sp_run *r, const subd_real *const x[3], const uint64_t id[3])
{
    subd_tri *t = out_tri(r);
    uint32_t j, k;
    for (j = 0; j < 3u; j++) {
        for (k = 0; k < 3u; k++) {
            t->pos[j][k] = x[j][k];
            t->normal[j][k] = 0;
        }
        t->id[j] = id[j];
    }
    return subd_stream_q_commit(r->q);
}

/* n triangles of points pt and ids id, corners ix (3 per triangle): the push form hands them
 * to the sink straight from the one item (face, level and zero normals written once, as
 * tile_emit does), the pull form puts each in the caller's buffer or the ring. Returns 0 or
 * the sink's value (kept in q->stop, as subd_stream_q_commit leaves it). */
static int emit_tris(const sp_run *r, const subd_real *const *pt, const uint64_t *id, const uint8_t *ix, uint32_t n)
{
    subd_stream_q *q = r->q;
    subd_tri *t = (subd_tri *)(void *)q->one;
    uint32_t i, j, k;
    int (*fn)(void *, const subd_tri *);
    void *ctx;
    if (!t || !q->ts) {
        for (i = 0; i < n; i++, ix += 3) {
            const subd_real *x[3];
            uint64_t xi[3];
            int st;
            for (j = 0; j < 3u; j++) {
                x[j] = pt[ix[j]];
                xi[j] = id[ix[j]];
            }
            if ((st = emit_tri(r, x, xi)) != 0) return st;
        }
        return 0;
    }
    fn = q->ts->tri;
    ctx = q->ts->ctx;
    t->face = r->f;
    t->level = r->o->levels;
    for (j = 0; j < 3u; j++)
        for (k = 0; k < 3u; k++) t->normal[j][k] = 0;
    for (i = 0; i < n; i++, ix += 3) {
        int st;
        /* each point copied as a whole (tile_push's tile_p3), the sink read once */
        for (j = 0; j < 3u; j++) {
            *(tile_p3 *)(void *)t->pos[j] = *(const tile_p3 *)(const void *)pt[ix[j]];
            t->id[j] = id[ix[j]];
        }
        if ((st = fn(ctx, t)) != 0) {
            q->stop = st;
            return st;
        }
    }
    return 0;
}

/* The corners of child k of a triangle whose corners are points 0..2 and whose edge j -> j+1
 * has point 3 + j: child k < 3 is (v_k, m_k, m_k-1), child 3 is (m0, m1, m2) (loop.c's order,
 * topo.h's table). */
static const uint8_t child_corner[4][3] = TOPO_LOOP_CHILD_POINTS;

/* The centre's four children at the last level (one level in all), from the cache: points
 * 0..2 the corners' vertex points, 3..5 the edges' new vertices. */
int subd_ls_emit_children(const sp_run *r, const sp_level *p)
{
    const sp_head *ph = p->h;
    const subd_real *pt[6];
    uint64_t id[6];
    uint32_t c, j;
    for (j = 0; j < 3u; j++) {
        uint32_t j1 = (j + 1u) % 3u;
        pt[j] = p->cpos + 3u * j;
        pt[3u + j] = p->cpos + 3u * p->slot[3u * ph->cf + j];
        id[j] = subd_lp_vertex_id(r->in, r->f, ph->ca[j], ph->cb[j], r->o->levels);
        id[3u + j] = subd_lp_vertex_id(r->in, r->f, (ph->ca[j] + ph->ca[j1]) / 2u, (ph->cb[j] + ph->cb[j1]) / 2u,
                               r->o->levels);
    }
    for (c = 0; c < 4u; c++) {
        const subd_real *x[3];
        uint64_t xi[3];
        int st;
        for (j = 0; j < 3u; j++) {
            x[j] = pt[child_corner[c][j]];
            xi[j] = id[child_corner[c][j]];
        }
        if ((st = emit_tri(r, x, xi)) != 0) return st;
    }
    return 0;
}

/* The 16 grandchildren's corners as emit_grandchildren's points (0..2 corners, 3..5 m,
 * 6..8 h1, 9..11 h2, 12..14 in): child c < 3 of the centre has the six points (v_c, m_c,
 * m_c-1, h1_c, in_c, h2_c-1), child 3 (m0, m1, m2, in_1, in_2, in_0) (its corners, then
 * the new points on its edges j -> j+1: GC_SIX(c, q)), and its grandchild g has corner j at
 * point GC_SIX(c, TOPO_LOOP_CP(g, j)): subd_loop's order, a constant table. */
#define GC_SIX(c, q)                                                                                         \
    ((c) < 3u ? ((q) == 0u ? (c) : (q) == 1u ? 3u + (c) : (q) == 2u ? 3u + ((c) + 2u) % 3u                   \
                 : (q) == 3u ? 6u + (c) : (q) == 4u ? 12u + (c) : 9u + ((c) + 2u) % 3u)                      \
              : ((q) < 3u ? 3u + (q) : (q) == 3u ? 13u : (q) == 4u ? 14u : 12u))
#define GC_T(c, g) GC_SIX(c, TOPO_LOOP_CP(g, 0u)), GC_SIX(c, TOPO_LOOP_CP(g, 1u)), GC_SIX(c, TOPO_LOOP_CP(g, 2u))
#define GC_C(c) GC_T(c, 0u), GC_T(c, 1u), GC_T(c, 2u), GC_T(c, 3u)
static const uint8_t gc_corner[48] = {GC_C(0u), GC_C(1u), GC_C(2u), GC_C(3u)};
#undef GC_C
#undef GC_T
#undef GC_SIX

/* The last two levels at once: the 16 level-L triangles of the centre of level L-2 (p), from
 * its cache (the level L-1 values of its children's 1-rings) and its topology, without
 * building the four level L-1 patches. Level L-1 seen from here, centre edge j = a -> b
 * (half-edge h in the centre face, twin t in face (b, a, d), third corner c):
 *   - the child of corner i has corner i's ring shape (vertex_point, next = 1);
 *   - the new vertex m of edge j has the ring b, m(b,c), m(c,a), a, m(a,d), m(d,b)
 *     (counter-clockwise; a boundary edge has the first four), starting as loop.c's
 *     new_vout starts it: at m(c,a) when h is the lower half-edge and not corner 2, at b
 *     when it is corner 2; at m(d,b) or a likewise for t; at b on a boundary;
 *   - the halves a -> m and m -> b keep the edge's lower side; the inner edge
 *     m_j -> m_j-1 is lower in child j (opposite corner v_j) than in child 3 (m_j+1).
 * Values: ve[i] corner i's child, vm[j] edge j's new vertex, h1[j] / h2[j] the points on the
 * halves a - m / m - b, in[j] the point on the inner edge m_j - m_j-1.
 * The centre's corners are p's local vertices vc (0..2; in a window, one of its four children:
 * three of 0..5), whose level L-1 vertex points are at the same cache slots. */
int subd_ls_emit_grandchildren(const sp_run *r, const sp_level *p, sp_gcshare *sh, uint32_t c, loop_wcache *wc,
                               uint32_t *ovf)
{
    const sp_head *ph = p->h;
    const subd_real *cp = p->cpos;
    subd_loop_boundary rule = r->o->boundary;
    uint32_t cf = ph->cf, i, j, sm[3], vc[3];
    subd_real ve[3][3], vm[3][3], h1[3][3], h2[3][3], in[3][3];
    subd_real *pv[3], *pm[3], *p1[3], *p2[3]; /* where each point is made: the locals or sh */
    const subd_real *pt[15];
    uint64_t id[15], ib;
    uint32_t known_v = 0, known_e = 0; /* points the window's earlier children made */
    for (i = 0; i < 3u; i++) {
        vc[i] = p->cv[3u * cf + i]; /* 0..2, in a window 0..5 */
        sm[i] = p->slot[3u * cf + i];
        pv[i] = ve[i];
        pm[i] = vm[i];
        p1[i] = h1[i];
        p2[i] = h2[i];
    }
    if (sh) { /* corner child c: (v_c, m_c, m_c-1); middle child: (m0, m1, m2) */
        for (i = 0; i < 3u; i++) {
            uint32_t mi = c == 3u ? i : i == 1u ? c : i == 2u ? (c + 2u) % 3u : 3u;
            if (mi == 3u) continue;
            pv[i] = sh->mve[mi];
            if (sh->have & (1u << mi)) known_v |= 1u << i;
            sh->have |= 1u << mi;
        }
        if (c == 3u) {
            known_e = 7u;
            for (j = 0; j < 3u; j++) {
                pm[j] = sh->evm[j];
                p1[j] = sh->eh1[j];
                p2[j] = sh->eh2[j];
            }
        } else { /* its inner edge m_c -> m_c-1: the middle child's edge c - 1, reversed */
            pm[1] = sh->evm[(c + 2u) % 3u];
            p1[1] = sh->eh2[(c + 2u) % 3u];
            p2[1] = sh->eh1[(c + 2u) % 3u];
        }
    }
    for (i = 0; i < 3u; i++)
        if (!(known_v & (1u << i))) subd_lp_vertex_point(p, vc[i], 1, wc, ovf, pv[i], 0);
    for (j = 0; j < 3u; j++) {
        uint32_t h = 3u * cf + j, t = p->tw[h], j1 = (j + 1u) % 3u;
        uint32_t ring[6], nr, start, k, lower_t = (t < LP_TW_BORDER && t < h);
        const subd_real *xm = cp + 3u * sm[j], *xa = cp + 3u * vc[j], *xb = cp + 3u * vc[j1];
        const subd_real *xca = cp + 3u * sm[(j + 2u) % 3u], *xbc = cp + 3u * sm[j1];
        int sharp = (p->sh[h] & LP_SH_CHILD) != 0u;
        subd_real *om = pm[j], *o1 = p1[j], *o2 = p2[j];
        uint32_t rm = sharp ? TOPO_PF_REGULAR : 0u, ra = p->cflag[vc[j]] & TOPO_PF_REGULAR;
        uint32_t rb = p->cflag[vc[j1]] & TOPO_PF_REGULAR;
        if (known_e & (1u << j)) continue;
        ring[0] = vc[j1]; ring[1] = sm[j1]; ring[2] = sm[(j + 2u) % 3u]; ring[3] = vc[j];
        nr = 4;
        if (t < LP_TW_BORDER) {
            ring[4] = p->slot[tri_next(t)]; /* m(a, d) */
            ring[5] = p->slot[tri_prev(t)]; /* m(d, b) */
            nr = 6;
        }
        if (t >= LP_TW_BORDER) start = 0;
        else if (!lower_t) start = (j == 2u) ? 0u : 2u;
        else start = (t % 3u == 2u) ? 3u : 5u;
        if (sharp) { /* crease or boundary: its two sharp neighbours b and a, in ring order */
            int a_first = start == 2u || start == 3u;
            loop_rule_crease(om, xm, a_first ? xa : xb, a_first ? xb : xa, ovf);
        } else {
            loop_weights w = subd_loop_weights_of(wc, 6u, ovf);
            subd_acc acc[3];
            loop_smooth_begin(acc, w, xm);
            for (k = 0; k < nr; k++) loop_smooth_add(acc, w, cp + 3u * ring[(start + k) % nr]);
            loop_smooth_end(om, acc, ovf);
        }
        /* the halves a - m and m - b */
        if (sharp || t >= LP_TW_BORDER) {
            if (lower_t) {
                loop_rule_sharp_edge(o1, xm, xa, rule, rm, ra, ovf);
                loop_rule_sharp_edge(o2, xb, xm, rule, rb, rm, ovf);
            } else {
                loop_rule_sharp_edge(o1, xa, xm, rule, ra, rm, ovf);
                loop_rule_sharp_edge(o2, xm, xb, rule, rm, rb, ovf);
            }
        } else {
            const subd_real *xad = cp + 3u * ring[4], *xdb = cp + 3u * ring[5];
            if (lower_t) {
                loop_rule_edge(o1, xm, xa, xad, xca, ovf);
                loop_rule_edge(o2, xb, xm, xdb, xbc, ovf);
            } else {
                loop_rule_edge(o1, xa, xm, xca, xad, ovf);
                loop_rule_edge(o2, xm, xb, xbc, xdb, ovf);
            }
        }
    }
    for (j = 0; j < 3u; j++) /* inner edge m_j -> m_j-1 of child j, opposite v_j; child 3: m_j+1 */
        loop_rule_edge(in[j], cp + 3u * sm[j], cp + 3u * sm[(j + 2u) % 3u], cp + 3u * vc[j],
                       cp + 3u * sm[(j + 1u) % 3u], ovf);
    if (*ovf) return SUBD_ERR_RANGE;
    /* the 15 points and their ids, once: 0..2 corners, 3..5 m, 6..8 h1, 9..11 h2, 12..14 in */
    ib = subd_lp_id_base(r->in, r->f, r->o->levels);
    for (i = 0; i < 3u; i++) {
        uint32_t i1 = (i + 1u) % 3u, ip = (i + 2u) % 3u, lv = r->o->levels;
        uint32_t mai = (ph->ca[i] + ph->ca[i1]) / 2u, mbi = (ph->cb[i] + ph->cb[i1]) / 2u;
        uint32_t map = (ph->ca[ip] + ph->ca[i]) / 2u, mbp = (ph->cb[ip] + ph->cb[i]) / 2u;
        pt[i] = pv[i];
        pt[3u + i] = pm[i];
        pt[6u + i] = p1[i];
        pt[9u + i] = p2[i];
        pt[12u + i] = in[i];
        id[i] = subd_lp_vertex_id_b(r->in, r->f, ph->ca[i], ph->cb[i], lv, ib);
        id[3u + i] = subd_lp_vertex_id_b(r->in, r->f, mai, mbi, lv, ib);
        id[6u + i] = subd_lp_vertex_id_b(r->in, r->f, (ph->ca[i] + mai) / 2u, (ph->cb[i] + mbi) / 2u, lv, ib);
        id[9u + i] = subd_lp_vertex_id_b(r->in, r->f, (mai + ph->ca[i1]) / 2u, (mbi + ph->cb[i1]) / 2u, lv, ib);
        id[12u + i] = subd_lp_vertex_id_b(r->in, r->f, (mai + map) / 2u, (mbi + mbp) / 2u, lv, ib);
    }
    /* the 16 grandchildren in subd_loop's order (gc_corner) */
    return emit_tris(r, pt, id, gc_corner, 16u);
}

/* Limit mode: the centre of level L's patch, each corner moved to its limit position with its
 * unit limit normal by loop_limit.c's masks on a subd_mesh view of the patch (the corners'
 * rings are whole; an outer vertex's class is given by LOOP_VTAG_KNOWN). */
int subd_ls_emit_limit(const sp_run *r, const sp_level *p, const sp_layout *lay, lim_cache *lc,
                                    uint32_t *ovf)
{
    const sp_head *ph = p->h;
    uint32_t j;
    subd_mesh m;
    subd_tri t;
    m.face_start = lay->m.view.face_start;
    m.corner_vert = lay->m.view.corner_vert;
    m.corner_face = lay->m.view.corner_face;
    m.twin = lay->m.view.twin;
    m.vert_out = lay->m.view.vert_out;
    m.vert_tag = lay->m.view.vert_tag;
    m.edge_tag = lay->m.view.edge_tag;
    subd_lp_view_fill(p, &m);
    for (j = 0; j < 3u; j++) {
        subd_loop_limit_vertex_cached(&m, r->o->boundary, p->pos, j, lc, t.pos[j], t.normal[j], ovf);
        t.id[j] = subd_lp_vertex_id(r->in, r->f, ph->ca[j], ph->cb[j], r->o->levels);
    }
    if (*ovf) return SUBD_ERR_RANGE;
    t.face = r->f;
    t.level = r->o->levels;
    *(subd_tri *)subd_stream_q_put(r->q) = t; /* the ring holds one: never NULL */
    return subd_stream_q_commit(r->q);
}

/* The ids of the current quarter's vertices (loop_tile.c's subd_lt_ids), from the tile
 * face's corners (the tile's level's header). */
static void tile_ids(sp_state *s, const lt_tile *tl, const int32_t org[2], const int32_t e1[2], const int32_t e2[2])
{
    sp_level p;
    level_at(&s->lay, s->k, &p);
    subd_lt_ids(tl, s->run.in, s->run.f, s->o.levels, p.h->ca, p.h->cb, org, e1, e2);
}

/* Push form: quarter triangles j0..n-1 of the table straight to the sink through the one
 * item t (face and level already written; plain mode: zero normals too, limit mode: the
 * quarter's normals tl->qnrm are copied); *at: the triangle the sink stopped at (its value
 * returned), else n. The hot loop of the stream: the fewest loads and stores per triangle,
 * the sink called without the queue between. */
TOPO_INLINE int tile_push_n(const lt_tile *tl, uint32_t j0, uint32_t n, subd_tri *t, const subd_tri_sink *ts,
                              uint32_t *at, const tile_p3 *N, const uint32_t *H)
{
    int (*fn)(void *, const subd_tri *) = ts->tri;
    void *ctx = ts->ctx;
    const uint8_t *ix = tl->tab + 3u * j0;
    const lt_rec *Q = tl->q;
    tile_p3 *tp = (tile_p3 *)(void *)t->pos, *tn = (tile_p3 *)(void *)t->normal;
    uint32_t j;
    for (j = j0; j < n; j++, ix += 3) {
        int st;
        uint32_t a;
        const lt_rec *r;
        /* corner by corner (few live registers), unrolled; position and id's low word from
         * one record, the high word from H (NULL: every id below 2^32) */
#define TILE_PUSH_CORNER(k)                                                          \
        a = ix[k];                                                                   \
        r = Q + a;                                                                   \
        tp[k] = *(const tile_p3 *)(const void *)r->p;                                \
        t->id[k] = H ? (uint64_t)r->id | ((uint64_t)H[a] << 32) : (uint64_t)r->id;   \
        if (N) tn[k] = N[a];
        TILE_PUSH_CORNER(0)
        TILE_PUSH_CORNER(1)
        TILE_PUSH_CORNER(2)
#undef TILE_PUSH_CORNER
        if ((st = fn(ctx, t)) != 0) {
            *at = j;
            return st;
        }
    }
    *at = n;
    return 0;
}

/* The plain and the limit loop apart (no normals to test for per triangle), and those of
 * streams whose ids all lie below 2^32 (`wide` = 0: the high words are zero, unread) apart
 * from the others'. */
static int tile_push(const lt_tile *tl, uint32_t j0, uint32_t n, subd_tri *t, const subd_tri_sink *ts, uint32_t *at,
                     uint32_t wide)
{
    const tile_p3 *N = (const tile_p3 *)(const void *)tl->qnrm;
    if (wide) return N ? tile_push_n(tl, j0, n, t, ts, at, N, tl->qhi) : tile_push_n(tl, j0, n, t, ts, at, 0, tl->qhi);
    return N ? tile_push_n(tl, j0, n, t, ts, at, N, 0) : tile_push_n(tl, j0, n, t, ts, at, 0, 0);
}

/* The tile's triangles, piece by piece (quarters, or their children: lt_split), each
 * piece's in subd_loop's order (its table);
 * stops when the caller's buffer is full (ton stays set: the next step goes on here).
 * Push form: the sink gets the one item each time (const), so the fields that do not change
 * within the call (face, level, zero normals) are written once and each triangle writes its
 * positions and ids. Returns 0, SUBD_ERR_RANGE or the sink's value. */
int subd_ls_tile_emit(sp_state *s, subd_stream_q *q)
{
    lt_tile tl;
    uint32_t n, tj, j, k;
    int st;
    const subd_real *nr;
    subd_tri *one = (subd_tri *)(void *)q->one;
    subd_lt_carve(&tl, s->lay.tile + tile_off(&s->lay, s->k), s->lay.tab, s->tdep, (int)s->limit);
    tl.lk = s->limit ? &s->lay.mk->lk : 0;
    nr = tl.qnrm;
    n = 1u << (2u * (tl.depth - tl.split)); /* a piece's triangles (loop_tile.h's lt_split) */
    if (s->ovf) return SUBD_ERR_RANGE;
    if (one) {
        one->face = s->run.f;
        one->level = s->o.levels;
        for (j = 0; j < 3u; j++)
            for (k = 0; k < 3u; k++) one->normal[j][k] = 0;
    }
    while (s->tq < (1u << (2u * tl.split))) {
        if (!s->tready) {
            int32_t org[2], e1[2], e2[2];
            subd_lt_quarter(&tl, s->tq, &s->wc, &s->ovf, LS_TMOVE(s), org, e1, e2);
            if (s->ovf) return SUBD_ERR_RANGE;
            tile_ids(s, &tl, org, e1, e2);
            s->tready = 1;
            s->tj = 0;
        }
        if (one && q->ts) { /* push: the hot loop */
            if (q->stop) return 0;
            if ((st = tile_push(&tl, s->tj, n, one, q->ts, &tj, s->idwide)) != 0) {
                q->stop = st; /* as subd_stream_q_commit leaves it */
                s->tj = tj + 1u;
                return st;
            }
        } else
        for (tj = s->tj; tj < n; tj++) {
            const uint8_t *ix = tl.tab + 3u * tj;
            const lt_rec *r0 = tl.q + ix[0], *r1 = tl.q + ix[1], *r2 = tl.q + ix[2];
            const subd_real *x0 = r0->p, *x1 = r1->p, *x2 = r2->p;
            subd_real p00 = x0[0], p01 = x0[1], p02 = x0[2], p10 = x1[0], p11 = x1[1], p12 = x1[2];
            subd_real p20 = x2[0], p21 = x2[1], p22 = x2[2];
            uint64_t d0 = (uint64_t)r0->id | ((uint64_t)tl.qhi[ix[0]] << 32);
            uint64_t d1 = (uint64_t)r1->id | ((uint64_t)tl.qhi[ix[1]] << 32);
            uint64_t d2 = (uint64_t)r2->id | ((uint64_t)tl.qhi[ix[2]] << 32);
            subd_tri *t;
            if (one) {
                if (q->stop) break;
                t = one;
            } else {
                if (q->n >= q->max) break; /* the caller's buffer is full */
                t = out_tri(&s->run);
                if (!nr)
                    for (j = 0; j < 3u; j++)
                        for (k = 0; k < 3u; k++) t->normal[j][k] = 0;
            }
            if (nr) /* limit mode: the unit limit normals */
                for (j = 0; j < 3u; j++)
                    for (k = 0; k < 3u; k++) t->normal[j][k] = nr[3u * ix[j] + k];
            t->pos[0][0] = p00; t->pos[0][1] = p01; t->pos[0][2] = p02;
            t->pos[1][0] = p10; t->pos[1][1] = p11; t->pos[1][2] = p12;
            t->pos[2][0] = p20; t->pos[2][1] = p21; t->pos[2][2] = p22;
            t->id[0] = d0;
            t->id[1] = d1;
            t->id[2] = d2;
            if ((st = subd_stream_q_commit(q)) != 0) {
                s->tj = tj + 1u;
                return st;
            }
        }
        s->tj = tj;
        if (tj < n) return 0;
        s->tq++;
        s->tready = 0;
    }
    s->ton = 0;
    return 0;
}
