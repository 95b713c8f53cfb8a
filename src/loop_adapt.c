/* SPDX-License-Identifier: MIT */
/* Adaptive Loop limit stream (include/subd_loop_adapt.h): each control face emitted at its own
 * level 0..L with watertight transitions, every vertex a level-L limit point (the uniform limit
 * stream's bits and ids), to a chord tolerance or at levels a callback chooses.
 * Length (~910 lines): the level choice (edge and face chord tests with the nearby-triangle
 * search and the uniform fallback's counting pass, callback) and the emission (uniform
 * interior, transition rings) share the per-face lattice walk and its state; splitting the
 * level choice into its own file behind a private header is open work (issue 22).
 *
 * Paper: loop-progressive-interpolation.txt, sections 1 and 4 (the rules, through
 * loop_patch.c's patches and loop_limit.c's masks; nothing here computes a new rule). The
 * paper says nothing about adaptive tessellation; the choices:
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
 * Levels. Each control edge gets a level e, each face a level l >= its edges'.
 *   CALLBACK: l = min(callback(face), L); an edge's e = the smaller of its two faces' levels
 *     (the callback is a function of the face index, so both faces compute the same).
 *   CHORD: an edge's e is the larger of (a) the smallest level whose chord polyline (the
 *     level-e lattice points of the edge, as limit points) holds every level-L limit point of
 *     the edge within eps, walked from the end with the smaller control vertex on the same
 *     bits from both faces, and (b) the smaller of its two faces' "own" levels (the smallest
 *     level at which the face's uniform triangles hold its level-L points within eps; a
 *     function of that face alone), so both faces decide the same e and no edge is coarser
 *     than both its faces would take uniformly. A face's l is the smallest level >= its
 *     edges' at which every level-L limit point of the face lies within eps of the triangle
 *     (of this face's triangulation at l) that contains it in the parameter domain; at l = L
 *     this holds by construction (every level-L point is a vertex or lies on a chord its
 *     edge's e was chosen for), so l = L needs no check. A point farther than eps from its
 *     own triangle may still be near another emitted triangle of the face (the limit
 *     parametrisation is not the chord's: near extraordinary vertices a point lies over the
 *     neighbouring triangle): the check tries the face's triangles in the 3 x 3 level-l
 *     cells around it and the ring triangles beside it (la_near_holds; any emitted triangle
 *     is a sound witness), which took the icosahedron (eps 0.001) and the cube (eps 0.003)
 *     from 4x the uniform count to 1x. The neighbouring FACES' triangles are not tried (their
 *     levels are decided from this face's: a cycle), so a level that only they make
 *     sufficient is missed (open work). "Within eps": float32, the Euclidean
 *     distance to that triangle (segment, for an edge) plus a rounding margin of 2^-18 of the
 *     coordinates' magnitude; Q16.16, whose resolution cannot hold the squared distances of
 *     fine levels, the bound |x - p|_1 + 8 LSB, p the triangle's point at x's barycentric
 *     coordinates (>= the Euclidean distance, so Q16.16 refines more). Either way the
 *     distance to the emitted mesh is within eps: an exact check on the points the guarantee
 *     is about, not an estimate; its cost is about one uniform level-L pass per level tried
 *     (the output is what is adaptive, not the work).
 *   CHORD fallback (la_prepass): the level choice runs once over the whole mesh before the
 *     first triangle, counting the adaptive cut's triangles A and taking U = the largest
 *     own level; if A > 4^U F and every face passes the check at U (checked again: a face's
 *     own level is only the first that passes), every face is emitted at U, uniformly: the
 *     stream never emits more than that uniform level, at the price of a second pass.
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
#include "loop_internal.h"
#include "loop_patch.h"
#include "mesh_internal.h"
#include "stream_internal.h"

/* The blocks (NULL when counting), the uniform limit stream's layout. */
typedef struct la_layout {
    uint32_t n;
    uint32_t off0[A_N], off1[A_N];
    sp_head *head;
    uint8_t *lev0, *lev1; /* levels 1..L: blocks of size1 bytes (level L without its cache) */
    subd_mesh view;
    uint16_t *smap, *fmap;
    loop_wcache *wc; /* the smooth rule's weights, cached (subd_reals and a word: arena data) */
    subd_real *pc;   /* CHORD, L <= SUBD_LOOP_ADAPT_PC_LEVELS_: one face's level-L limit points (else NULL) */
    uint32_t *pbits; /* which of them are filled                                            */
    uint32_t *memo;  /* with pc: SUBD_LOOP_ADAPT_MEMO_ (face, own level) pairs, by face mod the count */
    uint32_t size1, total;
} la_layout;

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

static void la_level_at(const la_layout *l, uint32_t k, sp_level *lv)
{
    const uint32_t *off = k == 0u ? l->off0 : l->off1;
    uint8_t *b = k == 0u ? l->lev0 : l->lev1 + (k - 1u) * l->size1;
    lv->h = l->head + k;
    subd_lp_level_bind(b, off, lv);
}

/* ------------------------------------------------------------------------------------ */
/* Lattice geometry (integers, units 1/2^L of the control face (0,0), (N,0), (0,N))        */

typedef struct la_pt {
    int32_t a, b;
} la_pt;

/* A triangle of a face's triangulation: its corners and, for a uniform level-l triangle, its
 * index among the face's 4^l (digits: the children from the top), else LA_NO_SUB. */
#define LA_NO_SUB 0xffffffffu
typedef struct la_tri {
    la_pt p[3];
    uint32_t sub;
} la_tri;

static int64_t la_cross(la_pt o, la_pt u, la_pt v)
{
    return (int64_t)(u.a - o.a) * (v.b - o.b) - (int64_t)(u.b - o.b) * (v.a - o.a);
}

static la_pt la_mid(la_pt u, la_pt v)
{
    la_pt m;
    m.a = (u.a + v.a) / 2;
    m.b = (u.b + v.b) / 2;
    return m;
}

/* Child c of triangle t (topo.h's table: child i = (v_i, m_i, m_i-1), child 3 = (m0, m1, m2)). */
static void la_child(la_pt t[3], uint32_t c)
{
    la_pt m0 = la_mid(t[0], t[1]), m1 = la_mid(t[1], t[2]), m2 = la_mid(t[2], t[0]);
    if (c == 3u) {
        t[0] = m0; t[1] = m1; t[2] = m2;
    } else {
        la_pt v = t[c], mc = c == 0u ? m0 : c == 1u ? m1 : m2, mp = c == 0u ? m2 : c == 1u ? m0 : m1;
        t[0] = v; t[1] = mc; t[2] = mp;
    }
}

static void la_root(la_pt t[3], int32_t n)
{
    t[0].a = 0; t[0].b = 0;
    t[1].a = n; t[1].b = 0;
    t[2].a = 0; t[2].b = n;
}

/* Corners of uniform level-l triangle `sub`. */
static void la_sub_corners(uint32_t sub, uint32_t l, int32_t n, la_pt t[3])
{
    uint32_t k;
    la_root(t, n);
    for (k = 0; k < l; k++) la_child(t, (sub >> (2u * (l - 1u - k))) & 3u);
}

/* ------------------------------------------------------------------------------------ */
/* State                                                                                  */

typedef struct la_face {
    uint32_t l, e[3]; /* face and edge levels                                        */
    uint32_t trans;   /* some edge coarser than l                                    */
    uint32_t no, ni;  /* ring: outer and inner loop vertex counts                    */
    uint32_t own;     /* CHORD: the face's own uniform level (la_face_own)          */
} la_face;

typedef struct la_iter {
    uint32_t phase; /* 0 uniform triangles, 1 the ring, 2 done                        */
    uint32_t j;     /* phase 0: next level-l triangle; phase 1 (fan): next step        */
    uint32_t io, ii;
} la_iter;

typedef struct la_state {
    subd_stream_impl impl; /* first: stream.c's view of the state */
    subd_stream_ring ring;
    la_layout lay;
    const subd_mesh *in;
    subd_loop_adapt_opts o;
    uint32_t f, started, ovf;
    uint32_t gf; /* the control face whose hierarchy la_goto descends (f, or a neighbour) */
    uint32_t pathf, depth, view_ok; /* the stack holds face pathf's levels 0..depth  */
    uint8_t path[SUBD_MAX_LEVELS + 1u];
    la_face fc;
    la_iter it;
    uint32_t pre; /* CHORD: the pre-pass (la_prepass) has run                        */
    uint32_t uni; /* CHORD: every face at this uniform level, or SUBD_NONE: adaptive */
    uint32_t pcf; /* the control face whose level-L points lay.pc holds, or SUBD_NONE  */
} la_state;
SUBD_STREAM_STATE_FITS(la_state);

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
 * corner (see Values above), so the cache holds la_eval_point's bits. */
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
static void la_eval_point(la_state *s, la_pt x, subd_real *pos, subd_real *nrm)
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
 * child 0 down to level L: the corner stays corner 0), else by la_eval_point. */
static void la_eval_corner(la_state *s, const la_tri *t, uint32_t c, subd_real *pos, subd_real *nrm)
{
    uint32_t L = s->o.loop.levels, l = s->fc.l, k;
    uint8_t d[SUBD_MAX_LEVELS + 1u];
    if (t->sub == LA_NO_SUB || (!nrm && s->lay.pc)) {
        la_eval_point(s, t->p[c], pos, nrm);
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

static void la_face_setup_ring(la_face *fc)
{
    fc->trans = fc->e[0] < fc->l || fc->e[1] < fc->l || fc->e[2] < fc->l;
    fc->no = ((uint32_t)1 << fc->e[0]) + ((uint32_t)1 << fc->e[1]) + ((uint32_t)1 << fc->e[2]);
    fc->ni = fc->l >= 2u ? 3u * (((uint32_t)1 << fc->l) - 3u) : 0u;
}

/* The next triangle of the face (corners counter-clockwise); 0 after the last. */
static int la_next(const la_face *fc, uint32_t L, la_iter *it, la_tri *t)
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
/* The chord check                                                                        */

static subd_real la_abs(subd_real x, uint32_t *ovf) { return x < 0 ? subd_neg(x, ovf) : x; }

#if !SUBD_FIXED
/* Float32: the Euclidean distance from x to the triangle (c0, c1, c2), or to the segment
 * (c0, c1) when c2 is NULL (Ericson, Real-Time Collision Detection, 5.1.2 and 5.1.5: the
 * closest point q by Voronoi regions); returns |x - q|^2. A rounding that misjudges a region
 * gives a farther q: the bound only grows. */
static subd_real la_dot(const subd_real *a, const subd_real *b, uint32_t *ovf)
{
    subd_real r = subd_mul(a[0], b[0], ovf);
    r = subd_add(r, subd_mul(a[1], b[1], ovf), ovf);
    return subd_add(r, subd_mul(a[2], b[2], ovf), ovf);
}

static subd_real la_dist2(const subd_real *x, const subd_real *c0, const subd_real *c1, const subd_real *c2,
                          uint32_t *ovf)
{
    subd_real ab[3], ac[3], ap[3], bp[3], cp[3], q[3], e[3], d1, d2, d3, d4, d5, d6, va, vb, vc, v, w;
    const subd_real *base = c0, *dir2 = ac;
    uint32_t k;
    for (k = 0; k < 3u; k++) {
        ab[k] = subd_sub(c1[k], c0[k], ovf);
        ap[k] = subd_sub(x[k], c0[k], ovf);
        bp[k] = subd_sub(x[k], c1[k], ovf);
        ac[k] = c2 ? subd_sub(c2[k], c0[k], ovf) : 0;
        cp[k] = c2 ? subd_sub(x[k], c2[k], ovf) : 0;
    }
    v = w = 0;
    d1 = la_dot(ab, ap, ovf);
    if (!c2) { /* the segment: t = clamp(ab.ap / ab.ab, 0, 1) */
        d3 = la_dot(ab, ab, ovf);
        if (d1 > 0) v = d1 >= d3 ? SUBD_REAL_ONE : subd_div(d1, d3, ovf);
    } else {
        d2 = la_dot(ac, ap, ovf);
        d3 = la_dot(ab, bp, ovf);
        d4 = la_dot(ac, bp, ovf);
        d5 = la_dot(ab, cp, ovf);
        d6 = la_dot(ac, cp, ovf);
        vc = subd_sub(subd_mul(d1, d4, ovf), subd_mul(d3, d2, ovf), ovf);
        vb = subd_sub(subd_mul(d5, d2, ovf), subd_mul(d1, d6, ovf), ovf);
        va = subd_sub(subd_mul(d3, d6, ovf), subd_mul(d5, d4, ovf), ovf);
        if (d1 <= 0 && d2 <= 0) {
        } else if (d3 >= 0 && d4 <= d3) {
            v = SUBD_REAL_ONE;
        } else if (vc <= 0 && d1 >= 0 && d3 <= 0) {
            v = subd_div(d1, subd_sub(d1, d3, ovf), ovf);
        } else if (d6 >= 0 && d5 <= d6) {
            w = SUBD_REAL_ONE;
        } else if (vb <= 0 && d2 >= 0 && d6 <= 0) {
            w = subd_div(d2, subd_sub(d2, d6, ovf), ovf);
        } else if (va <= 0 && subd_sub(d4, d3, ovf) >= 0 && subd_sub(d5, d6, ovf) >= 0) {
            subd_real n = subd_sub(d4, d3, ovf);
            w = subd_div(n, subd_add(n, subd_sub(d5, d6, ovf), ovf), ovf);
            base = c1; /* q = c1 + w (c2 - c1) */
            for (k = 0; k < 3u; k++) e[k] = subd_sub(c2[k], c1[k], ovf);
            dir2 = e;
        } else {
            subd_real den = subd_add(subd_add(va, vb, ovf), vc, ovf);
            v = subd_div(vb, den, ovf);
            w = subd_div(vc, den, ovf);
        }
    }
    for (k = 0; k < 3u; k++) {
        q[k] = subd_add(base[k], subd_mul(base == c0 ? v : 0, ab[k], ovf), ovf);
        q[k] = subd_add(q[k], subd_mul(w, dir2[k], ovf), ovf);
        q[k] = subd_sub(x[k], q[k], ovf);
    }
    return la_dot(q, q, ovf);
}
#endif

/* 1 when x lies within eps of the triangle (c0, c1, c2) (the segment (c0, c1) when c2 is
 * NULL), with a margin for rounding. Float32: the Euclidean distance (la_dist2) plus 2^-18 of
 * the coordinates' magnitude. Q16.16: |x - p|_1 + 8 LSB, p the point of the triangle at x's
 * barycentric coordinates (r1, r2) in the parameter domain (|.|_2 <= |.|_1; a bound, larger
 * than the distance: squared distances of fine levels are below Q16.16's resolution). */
static int la_within(la_state *s, const subd_real *x, const subd_real *c0, const subd_real *c1, const subd_real *c2,
                     subd_real r1, subd_real r2)
{
    uint32_t k, ovf = 0;
    subd_real dev = 0, mag = 0, margin;
#if SUBD_FIXED /* why: see above; Q16.16 resolves no squared distance of a fine level */
    for (k = 0; k < 3u; k++) {
        subd_real p = subd_add(c0[k], subd_mul(r1, subd_sub(c1[k], c0[k], &ovf), &ovf), &ovf);
        if (c2) p = subd_add(p, subd_mul(r2, subd_sub(c2[k], c0[k], &ovf), &ovf), &ovf);
        dev = subd_add(dev, la_abs(subd_sub(x[k], p, &ovf), &ovf), &ovf);
    }
    (void)mag;
    margin = (subd_real)8;
    dev = subd_add(dev, margin, &ovf);
    return !ovf && dev <= s->o.chord;
#else
    (void)r1;
    (void)r2;
    for (k = 0; k < 3u; k++) {
        mag = subd_add(mag, la_abs(x[k], &ovf), &ovf);
        mag = subd_add(mag, la_abs(c0[k], &ovf), &ovf);
        mag = subd_add(mag, la_abs(c1[k], &ovf), &ovf);
        if (c2) mag = subd_add(mag, la_abs(c2[k], &ovf), &ovf);
    }
    margin = subd_mul(mag, SUBD_REAL_FRAC(1, 262144), &ovf);
    if (margin >= s->o.chord) return 0;
    dev = subd_sub(s->o.chord, margin, &ovf);
    dev = subd_mul(dev, dev, &ovf);
    return la_dist2(x, c0, c1, c2, &ovf) <= dev && !ovf;
#endif
}

/* CHORD: the level of edge j of the current face. The edge is walked from its end with the
 * smaller control vertex, so the other face takes the same steps on the same bits. */
static uint32_t la_edge_chord(la_state *s, uint32_t j)
{
    const subd_mesh *in = s->in;
    uint32_t L = s->o.loop.levels, e, k;
    int32_t n = (int32_t)1 << L, m, m0, seg;
    la_pt t[3], u, w, x;
    subd_real c0[3], c1[3], y[3];
    la_root(t, n);
    u = t[j];
    w = t[(j + 1u) % 3u];
    if (in->corner_vert[3u * s->f + j] > in->corner_vert[3u * s->f + (j + 1u) % 3u]) {
        u = t[(j + 1u) % 3u];
        w = t[j];
    }
    for (e = 0; e < L; e++) {
        int ok = 1;
        seg = n >> e;
        for (k = 0; ok && k < ((uint32_t)1 << e); k++) {
            m0 = (int32_t)k * seg;
            x.a = u.a + (w.a - u.a) / n * m0;
            x.b = u.b + (w.b - u.b) / n * m0;
            la_eval_point(s, x, c0, 0);
            x.a = u.a + (w.a - u.a) / n * (m0 + seg);
            x.b = u.b + (w.b - u.b) / n * (m0 + seg);
            la_eval_point(s, x, c1, 0);
            for (m = 1; ok && m < seg; m++) {
                x.a = u.a + (w.a - u.a) / n * (m0 + m);
                x.b = u.b + (w.b - u.b) / n * (m0 + m);
                la_eval_point(s, x, y, 0);
                ok = la_within(s, y, c0, c1, 0, SUBD_REAL_FRAC(m, seg), 0);
            }
        }
        if (ok) return e;
    }
    return L;
}

/* Barycentric weights (w0, w1, w2) of x in triangle t (sum: its doubled area > 0), negative
 * ones set to 0: the weights of a point OF the triangle (x's own point when t contains x). */
static int64_t la_bary(const la_tri *t, la_pt x, int64_t *w1, int64_t *w2)
{
    int64_t area = la_cross(t->p[0], t->p[1], t->p[2]), a1 = la_cross(t->p[2], t->p[0], x);
    int64_t a2 = la_cross(t->p[0], t->p[1], x), a0 = area - a1 - a2;
    if (a0 < 0) a0 = 0;
    if (a1 < 0) a1 = 0;
    if (a2 < 0) a2 = 0;
    *w1 = a1;
    *w2 = a2;
    return a0 + a1 + a2;
}

/* 1 when y (the limit point of lattice point x) lies within eps of emitted triangle t. */
static int la_tri_holds(la_state *s, const la_tri *t, la_pt x, const subd_real *y)
{
    subd_real c[3][3];
    int64_t w1, w2, sum = la_bary(t, x, &w1, &w2);
    uint32_t k;
    for (k = 0; k < 3u; k++) la_eval_point(s, t->p[k], c[k], 0);
    return sum > 0 && la_within(s, y, c[0], c[1], c[2], SUBD_REAL_FRAC(w1, sum), SUBD_REAL_FRAC(w2, sum));
}

/* CHORD, when y is farther than eps from the triangle containing x: 1 when another triangle
 * of the face's triangulation (s->fc) near x holds it (all of them are emitted, so any is a
 * sound witness): the uniform level-l triangles of the 3 x 3 lattice cells around x that the
 * triangulation keeps, then the ring triangles whose lattice box, one level-l step wider,
 * holds x. A subset (the nearest in the parameter domain), to bound the work: each
 * candidate costs three limit evaluations. */
static int la_near_holds(la_state *s, la_pt x, const subd_real *y)
{
    const la_face *fc = &s->fc;
    uint32_t L = s->o.loop.levels, l = fc->l, up, k;
    int32_t n = (int32_t)1 << L, step = n >> l, m = (int32_t)1 << l, ci = x.a / step, cj = x.b / step, i, j;
    la_tri t;
    la_iter it;
    t.sub = LA_NO_SUB;
    for (j = cj - 1; j <= cj + 1; j++)
        for (i = ci - 1; i <= ci + 1; i++)
            for (up = 0; up < 2u; up++) {
                uint32_t keep = 1;
                if (i < 0 || j < 0 || i + j + (up ? 2 : 1) > m) continue;
                /* cell (i, j): (i, j) (i+1, j) (i, j+1), and (i+1, j) (i+1, j+1) (i, j+1) */
                t.p[0].a = up ? (i + 1) * step : i * step;
                t.p[0].b = j * step;
                t.p[1].a = (i + 1) * step;
                t.p[1].b = up ? (j + 1) * step : j * step;
                t.p[2].a = i * step;
                t.p[2].b = (j + 1) * step;
                if (fc->trans)
                    for (k = 0; k < 3u; k++)
                        if (l < 2u || t.p[k].a < step || t.p[k].b < step || t.p[k].a + t.p[k].b > n - step) keep = 0;
                if (keep && la_tri_holds(s, &t, x, y)) return 1;
            }
    if (!fc->trans) return 0;
    it.phase = 1;
    it.j = it.io = it.ii = 0;
    while (la_next(fc, L, &it, &t)) {
        la_pt lo = t.p[0], hi = t.p[0];
        for (k = 1; k < 3u; k++) {
            if (t.p[k].a < lo.a) lo.a = t.p[k].a;
            if (t.p[k].b < lo.b) lo.b = t.p[k].b;
            if (t.p[k].a > hi.a) hi.a = t.p[k].a;
            if (t.p[k].b > hi.b) hi.b = t.p[k].b;
        }
        if (x.a < lo.a - step || x.a > hi.a + step || x.b < lo.b - step || x.b > hi.b + step) continue;
        if (la_tri_holds(s, &t, x, y)) return 1;
    }
    return 0;
}

/* CHORD: 1 when every level-L lattice point of the face lies within eps of the face's
 * triangulation (s->fc): of the triangle that contains it, else of one near it
 * (la_near_holds). */
static int la_face_ok(la_state *s)
{
    uint32_t L = s->o.loop.levels, k;
    int32_t n = (int32_t)1 << L;
    la_iter it;
    la_tri t;
    it.phase = it.j = it.io = it.ii = 0;
    while (la_next(&s->fc, L, &it, &t)) {
        subd_real c[3][3], y[3];
        la_pt x, lo = t.p[0], hi = t.p[0];
        int64_t area = la_cross(t.p[0], t.p[1], t.p[2]);
        for (k = 0; k < 3u; k++) {
            la_eval_corner(s, &t, k, c[k], 0);
            if (t.p[k].a < lo.a) lo.a = t.p[k].a;
            if (t.p[k].b < lo.b) lo.b = t.p[k].b;
            if (t.p[k].a > hi.a) hi.a = t.p[k].a;
            if (t.p[k].b > hi.b) hi.b = t.p[k].b;
        }
        if (area <= 0) return 0; /* never: the triangulation does not fold */
        for (x.b = lo.b; x.b <= hi.b; x.b++)
            for (x.a = lo.a; x.a <= hi.a && x.a + x.b <= n; x.a++) {
                int64_t w1 = la_cross(t.p[2], t.p[0], x), w2 = la_cross(t.p[0], t.p[1], x);
                int64_t w0 = area - w1 - w2;
                if (w0 < 0 || w1 < 0 || w2 < 0 || w0 == area || w1 == area || w2 == area) continue;
                la_eval_point(s, x, y, 0);
                if (!la_within(s, y, c[0], c[1], c[2], SUBD_REAL_FRAC(w1, area), SUBD_REAL_FRAC(w2, area)) &&
                    !la_near_holds(s, x, y))
                    return 0;
            }
        if (s->ovf) return 0;
    }
    return 1;
}

/* CHORD: the smallest level at which face g's uniform triangles (every edge at that level)
 * hold its level-L limit points within eps (L: always). A function of g alone, asked by g
 * and by its three neighbours in each pass: remembered in lay.memo when there is one. */
static uint32_t la_face_own(la_state *s, uint32_t g)
{
    uint32_t L = s->o.loop.levels, l, j, *mm = s->lay.memo ? s->lay.memo + 2u * (g % SUBD_LOOP_ADAPT_MEMO_) : 0;
    la_face keep = s->fc;
    if (mm && mm[0] == g) return mm[1];
    s->gf = g;
    for (l = 0; l < L; l++) {
        s->fc.l = l;
        for (j = 0; j < 3u; j++) s->fc.e[j] = l;
        la_face_setup_ring(&s->fc);
        if (la_face_ok(s)) break;
    }
    s->fc = keep;
    s->gf = s->f;
    if (mm && !s->ovf) {
        mm[0] = g;
        mm[1] = l;
    }
    return l;
}

/* The levels of the current face and its edges. */
static void la_face_levels(la_state *s)
{
    const subd_mesh *in = s->in;
    uint32_t L = s->o.loop.levels, j, f = s->f, l, own, og[3];
    la_face *fc = &s->fc;
    if (s->o.mode == SUBD_LOOP_ADAPT_CALLBACK) {
        uint32_t lf = s->o.face_level(s->o.user, f);
        fc->l = lf < L ? lf : L;
        for (j = 0; j < 3u; j++) {
            uint32_t tw = in->twin[3u * f + j], lg;
            fc->e[j] = fc->l;
            if (tw == SUBD_NONE) continue;
            lg = s->o.face_level(s->o.user, tw / 3u);
            if (lg < fc->e[j]) fc->e[j] = lg;
        }
        la_face_setup_ring(fc);
        return;
    }
    l = 0;
    for (j = 0; j < 3u; j++) { /* the neighbours first: face f's points stay in the cache after */
        uint32_t tw = in->twin[3u * f + j];
        og[j] = tw == SUBD_NONE ? SUBD_NONE : la_face_own(s, tw / 3u);
    }
    own = la_face_own(s, f);
    for (j = 0; j < 3u; j++) {
        uint32_t o1 = own, o2;
        fc->e[j] = la_edge_chord(s, j);
        /* not below the level both faces would take uniformly (la_face_own: a function of
         * the face alone, so both faces compute the same): a coarser edge would force its
         * faces into transitions finer than they need */
        o2 = og[j] == SUBD_NONE ? o1 : og[j];
        if (o2 < o1) o1 = o2;
        if (o1 > fc->e[j]) fc->e[j] = o1;
        if (fc->e[j] > l) l = fc->e[j];
    }
    s->gf = f;
    fc->own = own;
    for (; l < L; l++) {
        fc->l = l;
        la_face_setup_ring(fc);
        if (la_face_ok(s)) return;
    }
    fc->l = L;
    la_face_setup_ring(fc);
}

/* Every face at uniform level u (CHORD's fallback). */
static void la_face_uniform(la_face *fc, uint32_t u)
{
    fc->l = fc->e[0] = fc->e[1] = fc->e[2] = u;
    la_face_setup_ring(fc);
}

/* CHORD, before the first triangle: the adaptive cut's triangle count A and the uniform
 * level U = the largest own level (la_face_own) over the faces; when A exceeds the 4^U F
 * triangles of level U and every face passes the chord check at U (la_face_ok: a face's own
 * level is the first that passes, a higher one is checked again), the stream emits level U
 * instead (s->uni), a cut with the same guarantee and fewer triangles. One pass of the level
 * choice over the mesh (the emission pass repeats it): about twice the work, no memory. */
static int la_prepass(la_state *s, subd_diag *d)
{
    uint32_t L = s->o.loop.levels, F = s->in->num_faces, f, u = 0, ok = 1;
    uint64_t adapt = 0;
    la_iter it;
    la_tri t;
    for (f = 0; f < F; f++) {
        s->f = s->gf = f;
        la_face_levels(s);
        if (s->ovf) break;
        it.phase = it.j = it.io = it.ii = 0;
        while (la_next(&s->fc, L, &it, &t)) adapt++;
        if (s->fc.own > u) u = s->fc.own;
    }
    if (!s->ovf && adapt > ((uint64_t)F << (2u * u)) && u < L)
        for (f = 0; ok && f < F; f++) {
            s->f = s->gf = f;
            la_face_uniform(&s->fc, u);
            ok = la_face_ok(s) && !s->ovf;
        }
    if (s->ovf) {
        d->face = s->f;
        return SUBD_ERR_RANGE;
    }
    s->uni = adapt > ((uint64_t)F << (2u * u)) && ok ? u : SUBD_NONE;
    s->f = s->gf = 0;
    s->pre = 1;
    return SUBD_OK;
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
                int st = la_prepass(s, d);
                if (st != SUBD_OK) return st;
            }
            if (s->f >= s->in->num_faces) {
                q->ended = 1;
                return SUBD_OK;
            }
            s->gf = s->f;
            if (s->o.mode == SUBD_LOOP_ADAPT_CHORD && s->uni != SUBD_NONE) la_face_uniform(&s->fc, s->uni);
            else la_face_levels(s);
            s->it.phase = s->it.j = s->it.io = s->it.ii = 0;
            s->started = 1;
        }
        if (s->ovf) {
            d->face = s->f;
            return SUBD_ERR_RANGE;
        }
        if (la_next(&s->fc, L, &s->it, &t)) {
            subd_tri *o = (subd_tri *)subd_stream_q_put(q); /* the ring holds one: never NULL */
            for (k = 0; k < 3u; k++) {
                la_eval_corner(s, &t, k, o->pos[k], o->normal[k]);
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
