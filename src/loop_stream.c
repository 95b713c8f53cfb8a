/* SPDX-License-Identifier: MIT */
/* Streaming Loop subdivision: subd_loop's level-L triangles handed to a sink one at a time,
 * in memory that depends on the level count and the largest valence only.
 * This file lays the levels out (the plan) and walks them (the pull-form driver); the
 * emitters and the tiles' hand-off to the sink are loop_stream_emit.c (the types both read:
 * loop_stream_internal.h), the tiles themselves loop_tile.c, the patch views loop_patch.c.
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
 * Windows (plain mode, from 3 levels on): a level L-3 patch is not extracted child by child;
 * the union of its four children's 1-rings is one patch (loop_patch.c's window, at level
 * L-2's block), whose cache holds each level L-2 point once (the four 1-rings share most of
 * them), and emit_grandchildren runs on each of its four children in turn; the push form
 * makes the four in one step and shares the 15 of their 60 level-L points that two of them
 * hold (measured: nefertiti level 3, 96 % irregular control faces, 982 -> 657 x86
 * instructions per triangle with a counting sink).
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
 * loop_patch.c's; this file lays the levels out and walks them, loop_stream_emit.c emits.
 *
 * Memory (the one layout of plan and run: stream_layout, layout.h's walk): L + 1 level
 * headers, level 0's patch (corner valences up to N each: at most 3N - 2 faces, 3N - 3
 * vertices, 3N cached values), levels 1..L-2 (limit mode: 1..L-1; at most one corner above
 * valence 6: N + 12 in place of 3N; plain mode from 3 levels: level L-2's block holds the
 * window, larger by a few faces and edges), the limit mode's level L and its mesh view, one
 * extraction's scratch (a slot map and a child-face map), the tiles' emission tables (one
 * per depth); a tile's own block shares memory with its level k >= tk = L - t and the
 * levels below it, which are idle while a tile is made and emitted (stream_layout), so the
 * plan holds the larger of the two.
 * Local indices are 16-bit (SUBD_LOOP_STREAM_MAX_VALENCE keeps every count below 2^16 - 2).
 */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "entry.h"
#include "layout.h"
#include "loop_stream_internal.h"
#include "mesh_internal.h"

/* Levels of a tile: SUBD_LOOP_TILE_LEVELS (limit mode: _LIMIT), at most L; none below 2. */
static uint32_t tile_depth(uint32_t levels, int limit)
{
    uint32_t c = limit ? (uint32_t)SUBD_LOOP_TILE_LEVELS_LIMIT : (uint32_t)SUBD_LOOP_TILE_LEVELS;
    uint32_t t = levels < c ? levels : c;
    return t < 2u ? 0u : t;
}

/* Plain mode from 3 levels on makes the last three levels of a patch the tiles refuse from a
 * window (loop_patch.h): the four children of level L-3's centre in one patch at level L-2's
 * block, each vertex once, then each child's 16 grandchildren by the two-level emitter. */
static int window_on(uint32_t levels, int limit) { return !limit && levels >= 3u; }

/* The window's block (its offsets into l->m.offw): for a patch of level L-3, whose corner
 * valences sum to at most 3N at level 0 and N + 12 below. */
static uint32_t window_layout(sp_layout *l, uint32_t levels)
{
    return subd_lp_window_layout(levels == 3u ? 3u * l->n : l->n + 12u, l->m.offw);
}

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
    if (window_on(levels, limit)) { /* the window, at level L-2's block: larger than a level */
        uint32_t wb = window_layout(l, levels);
        if (wb > l->size1) (void)subd_layout_take(&y, 1u, wb - l->size1);
    }
    if (limit) {
        (void)subd_layout_take(&y, 1u, subd_lp_level_layout(s1, 0, 0, l->off1)); /* at lev1 + cached * size1 */
        view_layout(&y, s1, &l->m.view);
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
/* The pull form (subd.h "Streams"): the depth-first walk as a resumable step              */

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
    /* a regular patch has 12 vertices and 13 faces (subd_lt_start): the others are refused
     * before the tile is carved */
    if (s->lay.tdepth && s->k >= s->lay.tk && (s->k == s->lay.tk || s->k + LT_PARTIAL_MIN(s->limit) <= o->levels) &&
        p->h->nv == 12u && p->h->nf == 13u) {
        lt_tile tl;
        subd_lt_carve(&tl, s->lay.tile + tile_off(&s->lay, s->k), s->lay.tab, o->levels - s->k, (int)s->limit);
        if (subd_lt_start(&tl, p, &s->wc, &s->ovf, LS_TMOVE(s))) {
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
            if ((st = subd_ls_tile_emit(s, q)) != 0) {
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
        if (s->k == s->depth && window_on(o->levels, (int)s->limit)) {
            if (p.h->child < 4u) { /* the centre's children from the window: the push form all
                                    * four at once (sharing their points; from the first: a
                                    * stream pulled before may be pushed on), else one per batch */
                uint32_t c = p.h->child, push = q->one && q->ts && c == 0u, cend = push ? 4u : c + 1u;
                sp_gcshare sh;
                qv.h = s->lay.head + s->k + 1u;
                subd_lp_level_bind(s->lay.lev1 + s->k * s->lay.size1, s->lay.m.offw, &qv);
                if (c == 0u) {
                    subd_lp_extract_window(&p, &qv, s->lay.smap, s->lay.fmap);
                    subd_lp_fill_cache(&qv, o->boundary, 1, &s->wc, &s->ovf);
                    s->nwin++;
                }
                sh.have = 0;
                for (; c < cend; c++) {
                    p.h->child = c + 1u;
                    qv.h->cf = qv.h->child + c;
                    subd_lp_child_lattice(p.h, c, qv.h->ca, qv.h->cb);
                    if ((st = subd_ls_emit_grandchildren(&s->run, &qv, push ? &sh : 0, c, &s->wc, &s->ovf)) != 0) {
                        d->face = s->run.f;
                        return st;
                    }
                }
                if (c == 4u) sp_up(s);
                return SUBD_OK;
            }
        } else if (s->k == s->depth) {
            st = s->limit ? subd_ls_emit_limit(&s->run, &p, &s->lay, &s->lay.mk->lc, &s->ovf)
                 : o->levels >= 2u ? subd_ls_emit_grandchildren(&s->run, &p, 0, 0, &s->wc, &s->ovf) : subd_ls_emit_children(&s->run, &p);
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
    s->depth = limit ? o->levels : window_on(o->levels, limit) ? o->levels - 3u : o->levels >= 2u ? o->levels - 2u : 0u;
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
    s->nwin = 0;
    { /* every id is below V + C (N - 1) + F (N - 1)(N - 2) / 2, N = 2^L (subd_loop.h) */
        uint64_t nm1 = ((uint64_t)1 << o->levels) - 1u;
        s->idwide = (uint64_t)in->num_verts + (uint64_t)in->num_corners * nm1 +
                    (uint64_t)in->num_faces * (nm1 * (nm1 - 1u) / 2u) > ((uint64_t)1 << 32) ? 1u : 0u;
    }
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

uint32_t subd_ls_stream_windows(const subd_stream *h) { return ((const sp_state *)h->state_)->nwin; }

void subd_ls_stream_wide_ids(subd_stream *h) { ((sp_state *)h->state_)->idwide = 1; }

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
