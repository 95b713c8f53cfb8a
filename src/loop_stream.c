/* SPDX-License-Identifier: MIT */
/* Streaming Loop subdivision: subd_loop's level-L triangles handed to a sink one at a time,
 * in memory that depends on the level count and the largest valence only.
 * Length (~850 lines): one concept, the depth-first patch walk with its pull-form driver,
 * limit mode and the tile hand-off (layout shared with the idle levels, tile_push to the
 * sink), which all read the one level layout; the tiles themselves are loop_tile.c, the patch
 * views loop_patch.c.
 *
 * Paper: loop-progressive-interpolation.txt, section 1 (Loop's scheme) and section 4 (the
 * boundary rules); the rules are loop_rules.h's, the same code subd_loop runs.
 *
 * Method. The level-(k+1) positions of a triangle's 1-ring (every face that shares a vertex
 * with it) follow from the level-k positions of its parent's 1-ring: the even vertices that
 * occur are the parent's three corners, whose rings the parent 1-ring holds, and the odd ones
 * lie on edges at those corners, whose two faces it holds. So one control face is refined
 * depth first: level k keeps the 1-ring patch of its current face ("centre"), the refined
 * values of that patch (the three corners' vertex points and the edge points of every edge
 * at them: the "cache", shared by the four children) and which child comes next. An explicit
 * stack of such levels replaces recursion. The last two levels are emitted at once from level
 * L-2's cache (emit_grandchildren: the centre's 16 grandchildren, whose level L-1 rings and
 * stencils are read off L-2's topology without building the four level L-1 patches); one
 * level in all emits from level 0 (emit_children); limit mode goes down to level L and moves
 * the centre's corners to the limit with loop_limit.c's masks (emit_limit).
 * Regular tiles (loop_tile.c): at level L - t (t = SUBD_LOOP_TILE_LEVELS, limit mode
 * SUBD_LOOP_TILE_LEVELS_LIMIT, at most L) a patch
 * whose centre has three smooth valence-6 corners is not refined depth first: its last t
 * levels are made breadth first on a triangular grid, each vertex once, and its 4^t
 * triangles go out quarter by quarter in the same order (tile_emit, resumable when the
 * caller's buffer is full; the push form hands them to the sink straight from the quarter's
 * arrays: tile_push). In limit mode each quarter's vertices are moved to the limit on
 * the grid too, with the valence-6 masks computed once per stream (loop_limit.c's
 * subd_loop_limit_reg6, the same sums as subd_loop_limit's). A patch refused at level L - t
 * (an irregular corner) is refined depth first, and its regular descendants below it are
 * tiles of one level fewer per level (partial tiles, down to 3 levels, limit mode 2: sp_enter),
 * so only the faces at the irregular vertex itself go down the general path. Other patches
 * take the general path below (limit mode: loop_limit.c's masks on a view of level L's patch, chi and the trig
 * table cached in the run state, so once per valence and stream).
 *
 * Bit-identity with subd_loop. A rule gives the same bits only if it adds the same products
 * in the same order. loop.c sums a vertex's ring from vert_out (the boundary half-edge, else
 * the smallest corner of the level, preserved by refinement), and an edge's stencil from its
 * lower half-edge (the one with the smaller index). A patch keeps its faces sorted by their
 * index in subd_loop's level (children of face f are 4f..4f+3, so sorted parents give sorted
 * children) and each face's corners in that level's order, so comparing local half-edge
 * indices compares global ones; vert_out is derived exactly as loop.c derives it (half_first
 * for old vertices, the fixed corner of new_vout for new ones; at level 0 the input's
 * vert_out). Classes: a control vertex's "regular" bit comes from subd_loop_classify on the input
 * (its whole ring), a new vertex is regular exactly when it lies on a sharp edge.
 * Assumed, as the builder, the readers and subd_loop guarantee: vert_out of a boundary
 * vertex is its boundary half-edge, and SUBD_ETAG_BOUNDARY is set only on boundary edges.
 *
 * Emission order: control face by control face; inside a face depth first with children
 * 0..3, so the j-th triangle of face f is subd_loop's face 4^L f + j, corners in its order.
 * The push form hands a batch to the sink from the one item, without the queue between
 * (emit_tris for the general path's grandchildren, tile_push for the tiles).
 *
 * The patches (the 1-ring of one face per level, its cache, its children's 1-rings) are
 * loop_patch.c's; this file lays the levels out, walks them and emits.
 *
 * Memory (the one layout of plan and run: stream_layout, layout.h's walk): L + 1 level
 * headers, level 0's patch (corner valences up to N each: at most 3N - 2 faces, 3N - 3
 * vertices, 3N cached values), levels 1..L-2 (limit mode: 1..L-1; at most one corner above
 * valence 6: N + 12 in place of 3N), the limit mode's level L and its mesh view, one
 * extraction's scratch (a slot map and a child-face map), the tiles' emission tables (one
 * per depth); a tile's own block shares memory with its level k >= tk = L - t and the
 * levels below it, which are idle while a tile is made and emitted (stream_layout), so the
 * plan holds the larger of the two.
 * Local indices are 16-bit (SUBD_LOOP_STREAM_MAX_VALENCE keeps every count below 2^16 - 2).
 */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "entry.h"
#include "layout.h"
#include "loop_internal.h"
#include "loop_patch.h"
#include "loop_tile.h"
#include "mesh_internal.h"
#include "stream_internal.h"

/* The blocks stream_layout takes (NULL when it only counts). A level's own arrays are an
 * offset table inside its block (off0, off1 from level_layout) rather than carved: the
 * same table addresses every level block of its size, and level_at re-addresses a level
 * at each visit of the depth-first walk (several times per emitted batch), so the offsets
 * are computed once. It is the same idea as a carving walk: one function (level_layout)
 * computes every offset, and plan and run both get them from stream_layout. */
/* The arrays of limit mode's subd_mesh view of level L (the rest of the mesh is filled at
 * each use; only the arrays live in the run state). */
typedef struct sp_view {
    uint32_t *face_start, *corner_vert, *corner_face, *twin, *vert_out;
    uint8_t *vert_tag, *edge_tag;
} sp_view;

/* Limit mode's masks, kept for the whole stream: loop_limit.c's caches (chi and the trig
 * table once per valence, not per vertex) and the tiles' valence-6 masks. A block of
 * SUBD_LOOP_SMASK_ bytes in the arena (a fixed size: the plan is the same for both
 * arithmetics, whose lim_w differ). */
typedef struct sp_masks {
    lim_cache lc;
    lim_reg6 lk;
} sp_masks;
typedef char sp_masks_fit[sizeof(sp_masks) <= SUBD_LOOP_SMASK_ ? 1 : -1];

typedef struct sp_layout {
    uint32_t n;         /* the largest valence, at least 6                                */
    uint32_t off0[A_N]; /* level 0's arrays, inside lev0                                   */
    uint32_t off1[A_N]; /* a later level's arrays, inside its block of size1               */
    sp_head *head;      /* L + 1 level headers                                             */
    uint8_t *lev0;      /* level 0's block                                                 */
    uint8_t *lev1;      /* levels 1, 2, ...: blocks of size1 bytes, one after the other     */
    sp_view view;       /* limit mode: level L's patch as a subd_mesh (arrays only) for
                         * loop_limit.c's masks                                             */
    uint16_t *smap, *fmap; /* one extraction's slot map and child-face map                */
    uint8_t *tile;         /* the region of the regular tiles' blocks (loop_tile.h), when
                            * tdepth >= 2: it shares memory with the levels from tk on    */
    uint8_t *tab;          /* the tiles' emission tables (depths 2..lt_table_depth)        */
    sp_masks *mk;          /* limit mode: the limit masks' caches                          */
    uint32_t tdepth;       /* levels a tile at level tk refines (tile_depth); 0: none      */
    uint32_t tk;           /* the first level with tiles: L - tdepth                       */
    uint32_t size1, total;
} sp_layout;

/* Levels of a tile: SUBD_LOOP_TILE_LEVELS (limit mode: _LIMIT), at most L; none below 2. */
static uint32_t tile_depth(uint32_t levels, int limit)
{
    uint32_t c = limit ? (uint32_t)SUBD_LOOP_TILE_LEVELS_LIMIT : (uint32_t)SUBD_LOOP_TILE_LEVELS;
    uint32_t t = levels < c ? levels : c;
    return t < 2u ? 0u : t;
}

/* Block index of level k in the level blocks (level 0 has its own block, lev0; a tile at
 * level 0 starts where level 1's block does). */
static uint32_t tile_bi(uint32_t k) { return k ? k - 1u : 0u; }

/* The block of a tile at level k >= tk (depth L - k): level k's own block, which the tile
 * may overwrite (subd_lt_start reads the patch first) with the deeper levels', idle while it
 * is made and emitted; levels tk..k-1 above it are live (their next children). */
static uint32_t tile_off(const sp_layout *l, uint32_t k) { return (tile_bi(k) - tile_bi(l->tk)) * l->size1; }

/* The limit mode's mesh view of a level with corner valence sum s: loop_patch.c's layout of
 * it (SUBD_LOOP_SVIEW_ is the same sum); only the arrays are kept in the run state (a whole
 * subd_mesh would not fit SUBD_STREAM_STATE_BYTES). */
static void view_layout(subd_layout *y, uint32_t s, sp_view *w)
{
    subd_mesh v;
    subd_lp_view_take(y, s, &v);
    w->face_start = v.face_start;
    w->corner_vert = v.corner_vert;
    w->corner_face = v.corner_face;
    w->twin = v.twin;
    w->vert_out = v.vert_out;
    w->vert_tag = v.vert_tag;
    w->edge_tag = v.edge_tag;
}

/* The one layout (layout.h's walk: counts with a == NULL, carves otherwise;
 * SUBD_LOOP_STREAM_BYTES_ is the same sum). Levels 1..tk-1 (tk: the tile's level) come
 * first; level tk, the deeper levels and limit mode's level L with its view share one
 * region with the tile's block: while a tile is made and emitted the walk is at level tk,
 * the deeper levels are idle and level tk's patch is not read again (subd_lt_start reads
 * all of it before it writes the tile, and writes nothing when it refuses the patch; the
 * walk rebuilds level tk before its next use); a level below tk is built only after the
 * tile is done or refused. Level 0 (tk = 0) stays outside. */
static int stream_layout(subd_arena *a, uint32_t levels, uint32_t valence, int limit, sp_layout *l)
{
    subd_layout y;
    uint32_t s0, s1, cached, above, r0, tb, j;
    uint8_t *region;
    l->n = valence < 6u ? 6u : valence;
    s0 = 3u * l->n;
    s1 = l->n + 12u;
    subd_layout_begin(&y, a);
    l->head = subd_layout_take(&y, levels + 1u, (uint32_t)sizeof(sp_head));
    l->lev0 = subd_layout_take(&y, 1u, subd_lp_level_layout(s0, 1, 1, l->off0));
    l->size1 = subd_lp_level_layout(s1, 1, 0, l->off1);
    /* levels with a cache: 1..L-2 (the last two levels are emitted from L-2's), limit mode
     * 1..L-1; then limit mode's level L and its mesh view */
    cached = limit ? levels - 1u : levels >= 2u ? levels - 2u : 0u;
    l->tdepth = tile_depth(levels, limit);
    /* levels above the region: 1..tk-1, tk = L - tdepth <= cached */
    above = l->tdepth ? (levels > l->tdepth ? levels - l->tdepth - 1u : 0u) : cached;
    l->lev1 = subd_layout_take(&y, above, l->size1);
    region = subd_layout_take(&y, 0u, 1u); /* where the next array starts (carving) */
    r0 = y.bytes;
    (void)subd_layout_take(&y, cached - above, l->size1);
    if (limit) {
        (void)subd_layout_take(&y, 1u, subd_lp_level_layout(s1, 0, 0, l->off1)); /* at lev1 + cached * size1 */
        view_layout(&y, s1, &l->view);
    }
    (void)subd_lp_level_layout(s1, 1, 0, l->off1); /* the cache arrays follow the patch: same offsets */
    /* the tiles: at level tk + j (j = 0..tdepth - 2) one of depth tdepth - j, at its level's
     * block (tile_off) */
    l->tk = levels - l->tdepth;
    tb = 0;
    if (l->tdepth)
        for (j = 0; j + 2u <= l->tdepth; j++) {
            uint32_t b = tile_off(l, l->tk + j);
            subd_bytes_add(&b, subd_lt_layout(l->tdepth - j, limit, 0));
            tb = subd_bytes_max(tb, b);
        }
    if (y.bytes != UINT32_MAX && tb > y.bytes - r0) (void)subd_layout_take(&y, tb - (y.bytes - r0), 1u);
    l->tile = l->tdepth ? region : 0;
    l->tab = l->tdepth ? subd_layout_take(&y, 1u, subd_lt_tab_bytes(lt_table_depth(l->tdepth, limit))) : 0;
    l->smap = subd_layout_take(&y, s0, 2u);
    l->fmap = subd_layout_take(&y, 4u * cap_f(s0), 2u);
    l->mk = limit ? (sp_masks *)(void *)subd_layout_take(&y, 1u, SUBD_LOOP_SMASK_) : 0;
    return subd_layout_end(&y, &l->total);
}

static void level_at(const sp_layout *l, uint32_t k, sp_level *lv)
{
    subd_lp_level_at(l->head, l->lev0, l->lev1, l->size1, l->off0, l->off1, k, lv);
}

/* ------------------------------------------------------------------------------------ */
/* Input                                                                                  */


static int stream_check(const subd_mesh *in, const subd_loop_opts *o, sp_layout *l, subd_diag *d)
{
    uint32_t n;
    int st = subd_loop_check(in, o, SUBD_LOOP_STREAM_LIMIT, d);
    if (st != SUBD_OK) return st;
    n = subd_lp_max_valence(in);
    if (n > SUBD_LOOP_STREAM_MAX_VALENCE) return subd_fail(d, SUBD_ERR_TOO_BIG);
    return stream_layout(0, o->levels, n, (o->flags & SUBD_LOOP_STREAM_LIMIT) != 0u, l);
}

static uint32_t stream_total(const sp_layout *l, uint32_t levels, int limit);

int subd_loop_stream_plan(const subd_mesh *in, const subd_loop_opts *o, uint32_t *bytes, subd_diag *diag)
{
    subd_diag own, *d = subd_plan_begin(&own, diag);
    sp_layout l;
    int st;
    if (!bytes) return subd_plan_end(d, SUBD_ERR_PARAM);
    if ((st = stream_check(in, o, &l, d)) == SUBD_OK)
        *bytes = stream_total(&l, o->levels, (o->flags & SUBD_LOOP_STREAM_LIMIT) != 0u);
    return subd_plan_end(d, st);
}

/* ------------------------------------------------------------------------------------ */
/* Ids and emission                                                                       */

typedef struct sp_run {
    const subd_mesh *in;
    const subd_loop_opts *o;
    subd_stream_q *q; /* where this batch's triangles go (stream_internal.h) */
    uint32_t f;
} sp_run;

/* The next output slot: the caller's buffer, else the overflow ring, which holds a whole
 * batch (ring_cap below), so it is never full here. */
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
    t->face = r->f;
    t->level = r->o->levels;
    for (j = 0; j < 3u; j++)
        for (k = 0; k < 3u; k++) t->normal[j][k] = 0;
    for (i = 0; i < n; i++, ix += 3) {
        int st;
        for (j = 0; j < 3u; j++) {
            const subd_real *x = pt[ix[j]];
            t->pos[j][0] = x[0];
            t->pos[j][1] = x[1];
            t->pos[j][2] = x[2];
            t->id[j] = id[ix[j]];
        }
        if ((st = q->ts->tri(q->ts->ctx, t)) != 0) {
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
SUBD_NOINLINE static int emit_children(const sp_run *r, const sp_level *p)
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
 * halves a - m / m - b, in[j] the point on the inner edge m_j - m_j-1. */
SUBD_NOINLINE static int emit_grandchildren(const sp_run *r, const sp_level *p, loop_wcache *wc, uint32_t *ovf)
{
    const sp_head *ph = p->h;
    const subd_real *cp = p->cpos;
    subd_loop_boundary rule = r->o->boundary;
    uint32_t cf = ph->cf, i, j, sm[3];
    subd_real ve[3][3], vm[3][3], h1[3][3], h2[3][3], in[3][3];
    const subd_real *pt[15];
    uint64_t id[15], ib;
    for (i = 0; i < 3u; i++) {
        subd_lp_vertex_point(p, i, 1, wc, ovf, ve[i], 0);
        sm[i] = p->slot[3u * cf + i];
    }
    for (j = 0; j < 3u; j++) {
        uint32_t h = 3u * cf + j, t = p->tw[h], j1 = (j + 1u) % 3u;
        uint32_t ring[6], nr, start, k, lower_t = (t < LP_TW_BORDER && t < h);
        const subd_real *xm = cp + 3u * sm[j], *xa = cp + 3u * j, *xb = cp + 3u * j1;
        const subd_real *xca = cp + 3u * sm[(j + 2u) % 3u], *xbc = cp + 3u * sm[j1];
        int sharp = (p->sh[h] & LP_SH_CHILD) != 0u;
        uint32_t rm = sharp ? TOPO_PF_REGULAR : 0u, ra = p->cflag[j] & TOPO_PF_REGULAR, rb = p->cflag[j1] & TOPO_PF_REGULAR;
        ring[0] = j1; ring[1] = sm[j1]; ring[2] = sm[(j + 2u) % 3u]; ring[3] = j;
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
            loop_rule_crease(vm[j], xm, a_first ? xa : xb, a_first ? xb : xa, ovf);
        } else {
            loop_weights w = subd_loop_weights_of(wc, 6u, ovf);
            subd_acc acc[3];
            loop_smooth_begin(acc, w, xm);
            for (k = 0; k < nr; k++) loop_smooth_add(acc, w, cp + 3u * ring[(start + k) % nr]);
            loop_smooth_end(vm[j], acc, ovf);
        }
        /* the halves a - m and m - b */
        if (sharp || t >= LP_TW_BORDER) {
            if (lower_t) {
                loop_rule_sharp_edge(h1[j], xm, xa, rule, rm, ra, ovf);
                loop_rule_sharp_edge(h2[j], xb, xm, rule, rb, rm, ovf);
            } else {
                loop_rule_sharp_edge(h1[j], xa, xm, rule, ra, rm, ovf);
                loop_rule_sharp_edge(h2[j], xm, xb, rule, rm, rb, ovf);
            }
        } else {
            const subd_real *xad = cp + 3u * ring[4], *xdb = cp + 3u * ring[5];
            if (lower_t) {
                loop_rule_edge(h1[j], xm, xa, xad, xca, ovf);
                loop_rule_edge(h2[j], xb, xm, xdb, xbc, ovf);
            } else {
                loop_rule_edge(h1[j], xa, xm, xca, xad, ovf);
                loop_rule_edge(h2[j], xm, xb, xbc, xdb, ovf);
            }
        }
    }
    for (j = 0; j < 3u; j++) /* inner edge m_j -> m_j-1 of child j, opposite v_j; child 3: m_j+1 */
        loop_rule_edge(in[j], cp + 3u * sm[j], cp + 3u * sm[(j + 2u) % 3u], cp + 3u * j, cp + 3u * sm[(j + 1u) % 3u],
                       ovf);
    if (*ovf) return SUBD_ERR_RANGE;
    /* the 15 points and their ids, once: 0..2 corners, 3..5 m, 6..8 h1, 9..11 h2, 12..14 in */
    ib = subd_lp_id_base(r->in, r->f, r->o->levels);
    for (i = 0; i < 3u; i++) {
        uint32_t i1 = (i + 1u) % 3u, ip = (i + 2u) % 3u, lv = r->o->levels;
        uint32_t mai = (ph->ca[i] + ph->ca[i1]) / 2u, mbi = (ph->cb[i] + ph->cb[i1]) / 2u;
        uint32_t map = (ph->ca[ip] + ph->ca[i]) / 2u, mbp = (ph->cb[ip] + ph->cb[i]) / 2u;
        pt[i] = ve[i];
        pt[3u + i] = vm[i];
        pt[6u + i] = h1[i];
        pt[9u + i] = h2[i];
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
SUBD_NOINLINE static int emit_limit(const sp_run *r, const sp_level *p, const sp_layout *lay, lim_cache *lc,
                                    uint32_t *ovf)
{
    const sp_head *ph = p->h;
    uint32_t j;
    subd_mesh m;
    subd_tri t;
    m.face_start = lay->view.face_start;
    m.corner_vert = lay->view.corner_vert;
    m.corner_face = lay->view.corner_face;
    m.twin = lay->view.twin;
    m.vert_out = lay->view.vert_out;
    m.vert_tag = lay->view.vert_tag;
    m.edge_tag = lay->view.edge_tag;
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

/* ------------------------------------------------------------------------------------ */
/* The pull form (subd.h "Streams"): the depth-first walk as a resumable step              */

/* The run state, in the arena's fixed SUBD_STREAM_STATE_BYTES block. The walk's position is
 * (run.f, k, started) plus each level header's `child`, which are in the arena already. */
typedef struct sp_state {
    subd_stream_impl impl; /* first: stream.c's view of the state */
    subd_stream_ring ring;
    sp_layout lay;
    sp_run run;
    subd_loop_opts o;
    loop_wcache wc;
    uint32_t k, depth, ovf, started, limit;
    /* the regular tile: at level k >= lay.tk, of depth tdep = L - k; ton while its triangles
     * go out: piece tq (a quarter, or limit mode's depth 5 a quarter's child: lt_split), its
     * triangle tj, tready once the piece's positions and ids are made */
    uint32_t tdep, ton, tq, tj, tready;
    uint32_t ntile[4]; /* tiles made so far, by depth 2..5 (subd_lt_stream_count) */
} sp_state;
SUBD_STREAM_STATE_FITS(sp_state);

/* Triangles one batch can make (the overflow ring holds them): limit mode 1 (one per
 * centre), one level 4 (the centre's children), else 16 (its grandchildren). */
static uint32_t ring_cap(uint32_t levels, int limit) { return limit ? 1u : levels >= 2u ? 16u : 4u; }

static uint32_t ring_bytes(uint32_t levels, int limit)
{
    uint32_t b = 0;
    subd_size_add(&b, ring_cap(levels, limit), (uint32_t)sizeof(subd_tri));
    return b;
}

/* The whole plan: the run state, the ring, the levels (stream_layout). */
static uint32_t stream_total(const sp_layout *l, uint32_t levels, int limit)
{
    uint32_t b = SUBD_STREAM_STATE_BYTES;
    subd_bytes_add(&b, ring_bytes(levels, limit));
    subd_bytes_add(&b, l->total);
    return b;
}

/* Up one level from the current one, or on to the next control face. */
static void sp_up(sp_state *s)
{
    if (s->k == 0u) {
        s->started = 0;
        s->run.f++;
    } else {
        s->k--;
    }
}

/* Smallest partial tile (below level tk): plain mode 3 levels, since the general path's last
 * two levels from level L-2 (emit_grandchildren) take fewer instructions than a tile of two
 * (measured: nefertiti level 3, whose control faces are mostly irregular, 17% more with
 * them); limit mode 2, since its general path moves every corner to the limit alone. */
#define LT_PARTIAL_MIN(limit) ((limit) ? 2u : 3u)

/* Level s->k (p) was just built: a regular tile from here when this is a tile's level (level
 * tk, and below it partial tiles down to LT_PARTIAL_MIN levels: a patch refused at level tk,
 * next to an irregular vertex, has its regular children tiled one level down, with a tile of
 * one level fewer) and p is regular; else its cache (a level above the emitting one caches everything its
 * children's 1-rings need; the emitting level only its centre's six values; limit mode's
 * level L none). */
static void sp_enter(sp_state *s, const sp_level *p)
{
    const subd_loop_opts *o = &s->o;
    if (s->lay.tdepth && s->k >= s->lay.tk && (s->k == s->lay.tk || s->k + LT_PARTIAL_MIN(s->limit) <= o->levels)) {
        lt_tile tl;
        subd_lt_carve(&tl, s->lay.tile + tile_off(&s->lay, s->k), s->lay.tab, o->levels - s->k, (int)s->limit);
        if (subd_lt_start(&tl, p, &s->wc, &s->ovf)) {
            s->tdep = o->levels - s->k;
            s->ntile[s->tdep - 2u]++;
            s->ton = 1;
            s->tq = s->tj = s->tready = 0;
            return;
        }
    }
    if (s->k < s->depth || !s->limit)
        subd_lp_fill_cache(p, o->boundary, s->k < s->depth || o->levels >= 2u, &s->wc, &s->ovf);
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
typedef struct tile_p3 { subd_real v[3]; } tile_p3; /* one point: copied as a whole (ldm/stm) */
static inline int tile_push_n(const lt_tile *tl, uint32_t j0, uint32_t n, subd_tri *t, const subd_tri_sink *ts,
                              uint32_t *at, const tile_p3 *N)
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
        /* corner by corner (few live registers), unrolled; position and id from one record */
#define TILE_PUSH_CORNER(k)                                                          \
        a = ix[k];                                                                   \
        r = Q + a;                                                                   \
        tp[k] = *(const tile_p3 *)(const void *)r->p;                                \
        t->id[k] = (uint64_t)r->id[0] | ((uint64_t)r->id[1] << 32);                  \
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

/* The plain and the limit loop apart (no normals to test for per triangle). */
static int tile_push(const lt_tile *tl, uint32_t j0, uint32_t n, subd_tri *t, const subd_tri_sink *ts, uint32_t *at)
{
    if (tl->qnrm) return tile_push_n(tl, j0, n, t, ts, at, (const tile_p3 *)(const void *)tl->qnrm);
    return tile_push_n(tl, j0, n, t, ts, at, 0);
}

/* The tile's triangles, piece by piece (quarters, or their children: lt_split), each
 * piece's in subd_loop's order (its table);
 * stops when the caller's buffer is full (ton stays set: the next step goes on here).
 * Push form: the sink gets the one item each time (const), so the fields that do not change
 * within the call (face, level, zero normals) are written once and each triangle writes its
 * positions and ids. Returns 0, SUBD_ERR_RANGE or the sink's value. */
SUBD_NOINLINE static int tile_emit(sp_state *s, subd_stream_q *q)
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
            subd_lt_quarter(&tl, s->tq, &s->wc, &s->ovf, org, e1, e2);
            if (s->ovf) return SUBD_ERR_RANGE;
            tile_ids(s, &tl, org, e1, e2);
            s->tready = 1;
            s->tj = 0;
        }
        if (one && q->ts) { /* push: the hot loop */
            if (q->stop) return 0;
            if ((st = tile_push(&tl, s->tj, n, one, q->ts, &tj)) != 0) {
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
            uint64_t d0 = (uint64_t)r0->id[0] | ((uint64_t)r0->id[1] << 32);
            uint64_t d1 = (uint64_t)r1->id[0] | ((uint64_t)r1->id[1] << 32);
            uint64_t d2 = (uint64_t)r2->id[0] | ((uint64_t)r2->id[1] << 32);
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

/* One batch: walks on from where the last step stopped to the next emitting visit and emits
 * there (a tile: as much of it as the caller takes); q->ended after the last face. */
static int sp_step(void *state, subd_stream_q *q, subd_diag *d)
{
    sp_state *s = (sp_state *)state;
    const subd_mesh *in = s->run.in;
    const subd_loop_opts *o = &s->o;
    sp_level p, qv;
    int st;
    s->run.q = q;
    for (;;) {
        if (s->ton) {
            if ((st = tile_emit(s, q)) != 0) {
                d->face = s->run.f;
                return st;
            }
            if (s->ton) return SUBD_OK; /* the caller's buffer is full */
            sp_up(s);
            return SUBD_OK;
        }
        if (!s->started) {
            if (s->run.f >= in->num_faces) {
                q->ended = 1;
                return SUBD_OK;
            }
            level_at(&s->lay, 0, &p);
            subd_lp_build_control(in, s->run.f, &p, o->levels);
            s->k = 0;
            s->started = 1;
            sp_enter(s, &p);
            continue;
        }
        if (s->ovf) {
            d->face = s->run.f;
            return SUBD_ERR_RANGE;
        }
        level_at(&s->lay, s->k, &p);
        st = 0;
        if (s->k == s->depth) {
            st = s->limit ? emit_limit(&s->run, &p, &s->lay, &s->lay.mk->lc, &s->ovf)
                 : o->levels >= 2u ? emit_grandchildren(&s->run, &p, &s->wc, &s->ovf) : emit_children(&s->run, &p);
            if (st != 0) {
                d->face = s->run.f;
                return st;
            }
            st = 1; /* a batch went out: return after leaving this level */
        } else if (p.h->child < 4u) {
            uint32_t c = p.h->child++;
            level_at(&s->lay, s->k + 1u, &qv);
            subd_lp_extract_child(&p, &qv, c, s->lay.smap, s->lay.fmap);
            s->k++;
            sp_enter(s, &qv);
            continue;
        }
        /* this level is done: up one, or on to the next control face */
        sp_up(s);
        if (st) return SUBD_OK;
    }
}

int subd_loop_stream_begin(subd_arena *a, const subd_mesh *in, const subd_loop_opts *o, subd_stream *h,
                           subd_diag *diag)
{
    subd_entry e;
    subd_diag *d = subd_entry_begin(&e, a, diag);
    sp_layout lay;
    sp_state *s;
    uint8_t *ring;
    uint32_t f, total;
    int st, limit;

    if (!a || !h) return subd_entry_fail(&e, SUBD_ERR_PARAM);
    if ((st = stream_check(in, o, &lay, d)) != SUBD_OK) return subd_entry_fail(&e, st);
    limit = (o->flags & SUBD_LOOP_STREAM_LIMIT) != 0u;
    total = stream_total(&lay, o->levels, limit);
    if (total > subd_arena_free_bytes(a)) { /* checked first: nothing is taken on failure */
        d->bytes_needed = total;
        return subd_entry_fail(&e, SUBD_ERR_NOMEM);
    }
    s = (sp_state *)subd_arena_alloc(a, SUBD_STREAM_STATE_BYTES); /* fits: checked above */
    ring = (uint8_t *)subd_arena_alloc(a, ring_bytes(o->levels, limit));
    (void)stream_layout(a, o->levels, lay.n, limit, &lay);
    s->lay = lay;
    for (f = 0; f < 4u * cap_f(3u * lay.n); f++) lay.fmap[f] = LP_NO_SLOT; /* extract_child keeps it so */
    s->wc.have = 0;
    s->o = *o;
    s->limit = (uint32_t)limit;
    /* the level that emits: level L (limit mode), L-2 (its centre's 16 grandchildren), or 0
     * for one level (its centre's 4 children) */
    s->depth = limit ? o->levels : o->levels >= 2u ? o->levels - 2u : 0u;
    s->run.in = in;
    s->run.o = &s->o;
    s->run.q = 0;
    s->run.f = 0;
    s->k = 0;
    s->ovf = 0;
    s->started = 0;
    s->ton = 0;
    s->tdep = 0;
    for (f = 0; f < 4u; f++) s->ntile[f] = 0;
    /* the tiles' emission tables (depths 2..lt_table_depth: loop_tile.h), once */
    for (f = 2; lay.tdepth && f <= lt_table_depth(lay.tdepth, limit); f++) {
        lt_tile tl;
        subd_lt_carve(&tl, lay.tile, lay.tab, f, limit);
        subd_lt_table(&tl);
    }
    if (limit) {
        subd_loop_limit_cache_init(&lay.mk->lc);
        if (lay.tdepth) subd_loop_limit_reg6_init(&lay.mk->lk);
    }
    s->impl.step = sp_step;
    s->impl.ring = &s->ring;
    s->impl.ring_items = ring;
    subd_stream_start(h, a, e.mark, SUBD_STREAM_TRIS, &s->impl, ring_cap(o->levels, limit));
    return subd_entry_ok(&e);
}

uint32_t subd_lt_stream_count(const subd_stream *h, uint32_t t)
{
    const sp_state *s = (const sp_state *)h->state_;
    return t >= 2u && t <= 5u ? s->ntile[t - 2u] : 0u;
}

int subd_loop_stream(subd_arena *a, const subd_mesh *in, const subd_loop_opts *o, const subd_tri_sink *sink,
                     subd_diag *diag)
{
    subd_stream h;
    int st;
    if (!sink || !sink->tri) {
        subd_entry e;
        (void)subd_entry_begin(&e, a, diag);
        return subd_entry_fail(&e, SUBD_ERR_PARAM);
    }
    if ((st = subd_loop_stream_begin(a, in, o, &h, diag)) != SUBD_OK) return st;
    return subd_stream_run_tris(&h, sink, diag);
}
