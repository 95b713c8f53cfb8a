/* SPDX-License-Identifier: MIT */
/* Adaptive Loop limit stream (include/subd_loop_adapt.h): each control face emitted at its own
 * level 0..L with watertight transitions, every vertex a level-L limit point (the uniform limit
 * stream's bits and ids), to a chord tolerance or at levels a callback chooses.
 * This file: the lattice walk to a point's level-L patch, the limit points (and CHORD's point
 * cache), a face's triangulation as an iterator, the stream and its entry points; the levels
 * (CHORD's chord tests, CALLBACK) are loop_adapt_chord.c's, the shared types
 * loop_adapt_internal.h's.
 *
 * Paper: loop-progressive-interpolation.txt, sections 1 and 4 (the rules, through
 * loop_patch.c's patches and loop_limit.c's masks; nothing here computes a new rule). The
 * paper says nothing about adaptive tessellation; the choices (the levels: loop_adapt_chord.c):
 *
 * Values. A vertex is a lattice point (A, B) of its control face in units of 1/2^L (L the max
 * level) and its position is ALWAYS the limit of that point computed at level L, from the
 * level-L 1-ring patch that has it as a corner, exactly as the uniform limit stream computes
 * it (loop_patch.c's patches are bit-identical to subd_loop's level L whatever path reached
 * them, and subd_loop_limit_vertex walks the corner's ring from loop.c's vert_out). So a vertex
 * has one value whichever face, level or triangle asks for it: shared vertices agree bit for bit
 * and a face at level L is the uniform limit stream's face. A point is reached by descending
 * the control face's hierarchy (la_goto): a stack of levels 0..L like the uniform stream's,
 * re-extracting only the levels below the first child that differs from the last descent.
 *
 * Triangulation of a face at level l (n = 2^l):
 *   - every edge at l: the uniform level-l triangles, depth first, children 0..3 (the uniform
 *     stream's order and corner order);
 *   - some edge coarser, l >= 2: the uniform triangles whose corners all lie in the inner
 *     triangle (1,1), (n-2,1), (1,n-2) (level-l units; the outer triangle shrunk about its
 *     centroid), in the same order, then the ring between the face's boundary (each edge's
 *     level-e points) and the inner triangle's boundary (its level-l points), zipped by the
 *     perimeter parameter (edge j covers [j, j+1) on both loops; both loops are homothetic about
 *     the centroid, so equal parameters lie on one ray and the zipped triangles do not fold;
 *     a tie advances the outer loop);
 *   - some edge coarser, l = 1: a fan of the boundary polygon from the midpoint of the first
 *     edge at level 1 (no such edge: the control triangle itself).
 * No vertex of one face lies inside an edge of the other (both use the edge's level-e points
 * only), so there are no T-junctions.
 *
 * Memory: the uniform limit stream's layout (levels 0..L-1 with caches, level L and its mesh
 * view, one extraction's scratch), the run state and a one-triangle ring; nothing else. */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "entry.h"
#include "layout.h"
#include "loop_adapt_internal.h"
#include "mesh_internal.h"

/* The weight cache's bytes, as SUBD_LOOP_ADAPT_STREAM_BYTES counts them. */
typedef char la_wcache_bytes[sizeof(loop_wcache) == SUBD_LOOP_ADAPT_WCACHE_ ? 1 : -1];

static int la_layout_walk(subd_arena *a, uint32_t levels, uint32_t valence, la_layout *l)
{
    subd_layout y;
    uint32_t s0, s1;
    l->n = valence < 6u ? 6u : valence;
    s0 = 3u * l->n;
    s1 = l->n + 12u;
    subd_layout_begin(&y, a);
    l->head = subd_layout_take(&y, levels + 1u, (uint32_t)sizeof(sp_head));
    l->lev0 = subd_layout_take(&y, 1u, subd_lp_level_layout(s0, 1, 1, l->off0));
    l->size1 = subd_lp_level_layout(s1, 1, 0, l->off1);
    l->lev1 = subd_layout_take(&y, levels - 1u, l->size1);
    (void)subd_layout_take(&y, 1u, subd_lp_level_layout(s1, 0, 0, l->off1)); /* level L */
    subd_lp_view_take(&y, s1, &l->view);
    (void)subd_lp_level_layout(s1, 1, 0, l->off1);
    l->smap = subd_layout_take(&y, s0, 2u);
    l->fmap = subd_layout_take(&y, 4u * cap_f(s0), 2u);
    l->wc = subd_layout_take(&y, 1u, (uint32_t)sizeof(loop_wcache));
    l->pc = 0;
    l->pbits = 0;
    l->memo = 0;
    if (levels <= SUBD_LOOP_ADAPT_PC_LEVELS_) {
        uint32_t np = SUBD_LOOP_ADAPT_PC_POINTS_(levels);
        l->pc = subd_layout_take(&y, np, 3u * (uint32_t)sizeof(subd_real));
        l->pbits = subd_layout_take(&y, (np + 31u) / 32u, 4u);
        l->memo = subd_layout_take(&y, 2u * SUBD_LOOP_ADAPT_MEMO_, 4u);
    }
    return subd_layout_end(&y, &l->total);
}

SUBD_STREAM_STATE_FITS(la_state);

/* Level k's arrays (loop_patch.h's subd_lp_level_at, the Loop streams' layout). */
static void la_level_at(const la_layout *l, uint32_t k, sp_level *lv)
{
    subd_lp_level_at(l->head, l->lev0, l->lev1, l->size1, l->off0, l->off1, k, lv);
}

/* Level L's patch is the descent d[1..L] of the current face (re-extracting below the first
 * child that differs from the last descent). */
static void la_goto(la_state *s, const uint8_t *d)
{
    uint32_t L = s->o.loop.levels, k;
    sp_level p, q;
    if (s->pathf != s->gf) {
        la_level_at(&s->lay, 0, &p);
        subd_lp_build_control(s->in, s->gf, &p, L);
        subd_lp_fill_cache(&p, s->o.loop.boundary, 1, s->lay.wc, &s->ovf);
        s->pathf = s->gf;
        s->depth = 0;
        s->view_ok = 0;
    }
    for (k = 1; k <= s->depth && s->path[k] == d[k]; k++) {}
    for (; k <= L; k++) {
        la_level_at(&s->lay, k - 1u, &p);
        la_level_at(&s->lay, k, &q);
        subd_lp_extract_child(&p, &q, d[k], s->lay.smap, s->lay.fmap);
        if (k < L) subd_lp_fill_cache(&q, s->o.loop.boundary, 1, s->lay.wc, &s->ovf);
        s->path[k] = d[k];
        s->depth = k;
        s->view_ok = 0;
    }
}

/* Limit position (and normal, if nrm) of corner j of level L's patch. */
static void la_limit_corner(la_state *s, uint32_t j, subd_real *pos, subd_real *nrm)
{
    sp_level p;
    la_level_at(&s->lay, s->o.loop.levels, &p);
    if (!s->view_ok) {
        subd_lp_view_fill(&p, &s->lay.view);
        s->view_ok = 1;
    }
    subd_loop_limit_vertex(&s->lay.view, s->o.loop.boundary, p.pos, j, pos, nrm, &s->ovf);
}

/* Index of lattice point x (a + b <= n) in the point cache: row b holds n + 1 - b points. */
static uint32_t la_pc_index(la_pt x, int32_t n)
{
    return (uint32_t)(x.b * (n + 1) - x.b * (x.b - 1) / 2 + x.a);
}

/* Fills the point cache with face gf's level-L limit points: the level-L triangles depth
 * first (la_goto re-extracts only below the first differing child, as the uniform stream
 * does), each corner once. A point's value does not depend on the patch that has it as a
 * corner (see Values above), so the cache holds subd_la_eval_point's bits. */
static void la_pc_fill(la_state *s)
{
    uint32_t L = s->o.loop.levels, np = SUBD_LOOP_ADAPT_PC_POINTS_(L), cnt = (uint32_t)1 << (2u * L), sub, k, i;
    int32_t n = (int32_t)1 << L;
    uint8_t d[SUBD_MAX_LEVELS + 1u];
    la_pt t[3];
    for (i = 0; i < (np + 31u) / 32u; i++) s->lay.pbits[i] = 0;
    d[0] = 0;
    for (sub = 0; sub < cnt; sub++) {
        int moved = 0;
        la_sub_corners(sub, L, n, t);
        for (k = 0; k < 3u; k++) {
            uint32_t x = la_pc_index(t[k], n);
            if (s->lay.pbits[x / 32u] & (1u << (x % 32u))) continue;
            if (!moved) {
                for (i = 1; i <= L; i++) d[i] = (uint8_t)((sub >> (2u * (L - i))) & 3u);
                la_goto(s, d);
                moved = 1;
            }
            la_limit_corner(s, k, s->lay.pc + 3u * x, 0);
            s->lay.pbits[x / 32u] |= 1u << (x % 32u);
        }
    }
    s->pcf = s->gf;
}

/* The limit point of lattice point x: descends into the first child that contains it (or,
 * without a normal, from the point cache when there is one). */
void subd_la_eval_point(la_state *s, la_pt x, subd_real *pos, subd_real *nrm)
{
    uint32_t L = s->o.loop.levels, k, c, j = 0;
    uint8_t d[SUBD_MAX_LEVELS + 1u];
    la_pt t[3];
    if (!nrm && s->lay.pc) {
        const subd_real *p;
        if (s->pcf != s->gf) la_pc_fill(s);
        p = s->lay.pc + 3u * la_pc_index(x, (int32_t)1 << L);
        pos[0] = p[0];
        pos[1] = p[1];
        pos[2] = p[2];
        return;
    }
    la_root(t, (int32_t)1 << L);
    d[0] = 0;
    for (k = 1; k <= L; k++) {
        for (c = 0; c < 3u; c++) {
            la_pt u[3];
            u[0] = t[0]; u[1] = t[1]; u[2] = t[2];
            la_child(u, c);
            if (la_cross(u[0], u[1], x) >= 0 && la_cross(u[1], u[2], x) >= 0 && la_cross(u[2], u[0], x) >= 0) break;
        }
        la_child(t, c); /* c == 3: the middle child, the only one left */
        d[k] = (uint8_t)c;
    }
    for (k = 0; k < 3u; k++)
        if (t[k].a == x.a && t[k].b == x.b) j = k;
    la_goto(s, d);
    la_limit_corner(s, j, pos, nrm);
}

/* Corner c of triangle t: a uniform triangle's corner by its own descent (corner c, then
 * child 0 down to level L: the corner stays corner 0), else by subd_la_eval_point. */
void subd_la_eval_corner(la_state *s, const la_tri *t, uint32_t c, subd_real *pos, subd_real *nrm)
{
    uint32_t L = s->o.loop.levels, l = s->fc.l, k;
    uint8_t d[SUBD_MAX_LEVELS + 1u];
    if (t->sub == LA_NO_SUB || (!nrm && s->lay.pc)) {
        subd_la_eval_point(s, t->p[c], pos, nrm);
        return;
    }
    d[0] = 0;
    for (k = 1; k <= l; k++) d[k] = (uint8_t)((t->sub >> (2u * (l - k))) & 3u);
    for (k = l + 1u; k <= L; k++) d[k] = (uint8_t)(k == l + 1u ? c : 0u);
    la_goto(s, d);
    la_limit_corner(s, l < L ? 0u : c, pos, nrm);
}

/* ------------------------------------------------------------------------------------ */
/* A face's triangulation as an iterator                                                  */

/* Outer loop vertex k: edge j's i-th level-e point; its parameter j + i / 2^e. */
static la_pt la_outer(const la_face *fc, int32_t n, uint32_t k, uint32_t *pj, uint32_t *pi, uint32_t *pd)
{
    la_pt t[3], x;
    uint32_t j = 0, i = k, cnt;
    int32_t step;
    for (;;) {
        cnt = (uint32_t)1 << fc->e[j];
        if (i < cnt || j == 2u) break;
        i -= cnt;
        j++;
    }
    la_root(t, n);
    step = n >> fc->e[j];
    x.a = t[j].a + (t[(j + 1u) % 3u].a - t[j].a) / n * step * (int32_t)i;
    x.b = t[j].b + (t[(j + 1u) % 3u].b - t[j].b) / n * step * (int32_t)i;
    *pj = j; *pi = i; *pd = cnt;
    return x;
}

/* Inner loop vertex k (l >= 2): side j's i-th point of the inner triangle; parameter
 * j + i / (2^l - 3). */
static la_pt la_inner(uint32_t l, int32_t n, uint32_t k, uint32_t *pj, uint32_t *pi, uint32_t *pd)
{
    int32_t sc = n >> l, m = ((int32_t)1 << l) - 3;
    uint32_t j = k / (uint32_t)m, i = k % (uint32_t)m;
    la_pt c[3], t[3], x;
    la_root(t, n);
    c[0].a = sc; c[0].b = sc;
    c[1].a = n - 2 * sc; c[1].b = sc;
    c[2].a = sc; c[2].b = n - 2 * sc;
    x.a = c[j].a + (t[(j + 1u) % 3u].a - t[j].a) / n * sc * (int32_t)i;
    x.b = c[j].b + (t[(j + 1u) % 3u].b - t[j].b) / n * sc * (int32_t)i;
    *pj = j; *pi = i; *pd = (uint32_t)m;
    return x;
}

/* p1 <= p2 for parameters j + i / d. */
static int la_param_le(uint32_t j1, uint32_t i1, uint32_t d1, uint32_t j2, uint32_t i2, uint32_t d2)
{
    return ((uint64_t)j1 * d1 + i1) * d2 <= ((uint64_t)j2 * d2 + i2) * d1;
}

void subd_la_face_setup_ring(la_face *fc)
{
    fc->trans = fc->e[0] < fc->l || fc->e[1] < fc->l || fc->e[2] < fc->l;
    fc->no = ((uint32_t)1 << fc->e[0]) + ((uint32_t)1 << fc->e[1]) + ((uint32_t)1 << fc->e[2]);
    fc->ni = fc->l >= 2u ? 3u * (((uint32_t)1 << fc->l) - 3u) : 0u;
}

/* The next triangle of the face (corners counter-clockwise); 0 after the last. */
int subd_la_next(const la_face *fc, uint32_t L, la_iter *it, la_tri *t)
{
    int32_t n = (int32_t)1 << L;
    uint32_t j1, i1, d1, j2, i2, d2;
    if (it->phase == 0u) {
        uint32_t cnt = (uint32_t)1 << (2u * fc->l);
        int32_t sc = n >> fc->l;
        while (it->j < cnt) {
            uint32_t k, inside = 1;
            t->sub = it->j++;
            la_sub_corners(t->sub, fc->l, n, t->p);
            if (!fc->trans) return 1;
            for (k = 0; k < 3u; k++)
                if (t->p[k].a < sc || t->p[k].b < sc || t->p[k].a + t->p[k].b > n - sc) inside = 0;
            if (inside && fc->l >= 2u) return 1;
        }
        it->phase = fc->trans ? 1u : 2u;
        it->j = it->io = it->ii = 0;
    }
    if (it->phase != 1u) return 0;
    t->sub = LA_NO_SUB;
    if (fc->l < 2u) { /* l = 1: a fan of the boundary polygon */
        uint32_t k0 = 0, k;
        for (k = 0; k < fc->no; k++) {
            (void)la_outer(fc, n, k, &j1, &i1, &d1);
            if (i1 == 1u && d1 == 2u) break;
        }
        if (k == fc->no) { /* every edge at 0: the control triangle */
            if (it->j++ > 0u) {
                it->phase = 2u;
                return 0;
            }
            la_root(t->p, n);
            return 1;
        }
        k0 = k;
        if (it->j + 2u >= fc->no) {
            it->phase = 2u;
            return 0;
        }
        it->j++;
        t->p[0] = la_outer(fc, n, k0, &j1, &i1, &d1);
        t->p[1] = la_outer(fc, n, (k0 + it->j) % fc->no, &j1, &i1, &d1);
        t->p[2] = la_outer(fc, n, (k0 + it->j + 1u) % fc->no, &j1, &i1, &d1);
        return 1;
    }
    if (it->io >= fc->no && it->ii >= fc->ni) {
        it->phase = 2u;
        return 0;
    }
    if (it->io + 1u >= fc->no) { j1 = 3; i1 = 0; d1 = 1; }
    else (void)la_outer(fc, n, it->io + 1u, &j1, &i1, &d1);
    if (it->ii + 1u >= fc->ni) { j2 = 3; i2 = 0; d2 = 1; }
    else (void)la_inner(fc->l, n, it->ii + 1u, &j2, &i2, &d2);
    if (it->io < fc->no && (it->ii >= fc->ni || la_param_le(j1, i1, d1, j2, i2, d2))) {
        t->p[0] = la_outer(fc, n, it->io, &j1, &i1, &d1);
        t->p[1] = la_outer(fc, n, (it->io + 1u) % fc->no, &j1, &i1, &d1);
        t->p[2] = la_inner(fc->l, n, it->ii % fc->ni, &j1, &i1, &d1);
        it->io++;
    } else {
        t->p[0] = la_outer(fc, n, it->io % fc->no, &j1, &i1, &d1);
        t->p[1] = la_inner(fc->l, n, (it->ii + 1u) % fc->ni, &j1, &i1, &d1);
        t->p[2] = la_inner(fc->l, n, it->ii, &j1, &i1, &d1);
        it->ii++;
    }
    return 1;
}

/* ------------------------------------------------------------------------------------ */
/* The stream                                                                             */

static int la_step(void *state, subd_stream_q *q, subd_diag *d)
{
    la_state *s = (la_state *)state;
    uint32_t L = s->o.loop.levels, k;
    la_tri t;
    for (;;) {
        if (!s->started) {
            if (s->o.mode == SUBD_LOOP_ADAPT_CHORD && !s->pre) {
                int st = subd_la_prepass(s, d);
                if (st != SUBD_OK) return st;
            }
            if (s->f >= s->in->num_faces) {
                q->ended = 1;
                return SUBD_OK;
            }
            s->gf = s->f;
            if (s->o.mode == SUBD_LOOP_ADAPT_CHORD && s->uni != SUBD_NONE) subd_la_face_uniform(&s->fc, s->uni);
            else subd_la_face_levels(s);
            s->it.phase = s->it.j = s->it.io = s->it.ii = 0;
            s->started = 1;
        }
        if (s->ovf) {
            d->face = s->f;
            return SUBD_ERR_RANGE;
        }
        if (subd_la_next(&s->fc, L, &s->it, &t)) {
            subd_tri *o = (subd_tri *)subd_stream_q_put(q); /* the ring holds one: never NULL */
            for (k = 0; k < 3u; k++) {
                subd_la_eval_corner(s, &t, k, o->pos[k], o->normal[k]);
                o->id[k] = subd_lp_vertex_id(s->in, s->f, (uint32_t)t.p[k].a, (uint32_t)t.p[k].b, L);
            }
            if (s->ovf) {
                d->face = s->f;
                return SUBD_ERR_RANGE;
            }
            o->face = s->f;
            o->level = s->fc.l;
            return subd_stream_q_commit(q);
        }
        s->started = 0;
        s->f++;
    }
}

static int la_check(const subd_mesh *in, const subd_loop_adapt_opts *o, la_layout *l, subd_diag *d)
{
    uint32_t n;
    int st;
    if (!o) return subd_fail(d, SUBD_ERR_PARAM);
    if (o->mode == SUBD_LOOP_ADAPT_CHORD) {
        if (!subd_real_is_finite(o->chord) || !(o->chord > 0)) return subd_fail(d, SUBD_ERR_PARAM);
    } else if (o->mode != SUBD_LOOP_ADAPT_CALLBACK || !o->face_level) {
        return subd_fail(d, SUBD_ERR_PARAM);
    }
    if ((st = subd_loop_check(in, &o->loop, SUBD_LOOP_STREAM_LIMIT, d)) != SUBD_OK) return st;
    n = subd_lp_max_valence(in);
    if (n > SUBD_LOOP_STREAM_MAX_VALENCE) return subd_fail(d, SUBD_ERR_TOO_BIG);
    return la_layout_walk(0, o->loop.levels, n, l);
}

static uint32_t la_total(const la_layout *l)
{
    uint32_t b = SUBD_STREAM_STATE_BYTES, r = 0;
    subd_size_add(&r, 1u, (uint32_t)sizeof(subd_tri));
    subd_bytes_add(&b, r);
    subd_bytes_add(&b, l->total);
    return b;
}

int subd_loop_adapt_stream_plan(const subd_mesh *in, const subd_loop_adapt_opts *o, uint32_t *bytes,
                                subd_diag *diag)
{
    subd_diag own, *d = subd_plan_begin(&own, diag);
    la_layout l;
    int st;
    if (!bytes) return subd_plan_end(d, SUBD_ERR_PARAM);
    if ((st = la_check(in, o, &l, d)) == SUBD_OK) *bytes = la_total(&l);
    return subd_plan_end(d, st);
}

int subd_loop_adapt_stream_begin(subd_arena *a, const subd_mesh *in, const subd_loop_adapt_opts *o,
                                 subd_stream *h, subd_diag *diag)
{
    subd_entry e;
    subd_diag *d = subd_entry_begin(&e, a, diag);
    la_layout lay;
    la_state *s;
    uint8_t *ring;
    uint32_t f, total, r = 0;
    int st;
    if (!a || !h) return subd_entry_fail(&e, SUBD_ERR_PARAM);
    if ((st = la_check(in, o, &lay, d)) != SUBD_OK) return subd_entry_fail(&e, st);
    total = la_total(&lay);
    if (total > subd_arena_free_bytes(a)) { /* checked first: nothing is taken on failure */
        d->bytes_needed = total;
        return subd_entry_fail(&e, SUBD_ERR_NOMEM);
    }
    s = (la_state *)subd_arena_alloc(a, SUBD_STREAM_STATE_BYTES); /* fits: checked above */
    subd_size_add(&r, 1u, (uint32_t)sizeof(subd_tri));
    ring = (uint8_t *)subd_arena_alloc(a, r);
    (void)la_layout_walk(a, o->loop.levels, lay.n, &lay);
    s->lay = lay;
    for (f = 0; f < 4u * cap_f(3u * lay.n); f++) lay.fmap[f] = LP_NO_SLOT; /* extract_child keeps it so */
    lay.wc->have = 0;
    s->o = *o;
    s->in = in;
    s->f = 0;
    s->started = 0;
    s->ovf = 0;
    s->pathf = SUBD_NONE;
    s->gf = 0;
    s->depth = 0;
    s->view_ok = 0;
    s->pre = 0;
    s->uni = SUBD_NONE;
    s->pcf = SUBD_NONE;
    s->nb = 0;
    if (lay.memo)
        for (f = 0; f < SUBD_LOOP_ADAPT_MEMO_; f++) lay.memo[2u * f] = SUBD_NONE;
    s->impl.step = la_step;
    s->impl.ring = &s->ring;
    s->impl.ring_items = ring;
    subd_stream_start(h, a, e.mark, SUBD_STREAM_TRIS, &s->impl, 1u);
    return subd_entry_ok(&e);
}

int subd_loop_adapt_stream(subd_arena *a, const subd_mesh *in, const subd_loop_adapt_opts *o,
                           const subd_tri_sink *sink, subd_diag *diag)
{
    subd_stream h;
    int st;
    if (!sink || !sink->tri) {
        subd_entry e;
        (void)subd_entry_begin(&e, a, diag);
        return subd_entry_fail(&e, SUBD_ERR_PARAM);
    }
    if ((st = subd_loop_adapt_stream_begin(a, in, o, &h, diag)) != SUBD_OK) return st;
    return subd_stream_run_tris(&h, sink, diag);
}
