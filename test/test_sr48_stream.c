/* SPDX-License-Identifier: MIT */
/* Streaming semi-regular 4-8 (subd_sr48_stream, src/sr48_stream.c) against the materialising
 * calls: subd_sr48_build(steps = L) then subd_sr48_extract(UNIFORM, L). On closed and open
 * shapes (tetrahedron: valence 3 input vertices; cube of triangles; icosahedron; a hexagon
 * fan; an open 8x8 grid; two triangles with an isolated-triangle pre-processing; the torus),
 * levels 0..7 (uniform tiles alone up to SUBD_SR48_STREAM_TILE_LEVELS, below depth-first
 * levels beyond), smoothing on and off, both arithmetics:
 *  - the j-th streamed triangle is the extraction's face j: same corners (apex, b0, b1) with
 *    the same position bits;
 *  - ids: one id per extraction vertex and one vertex per id (a bijection), level-0 ids =
 *    base indices; welding by id gives the extraction's mesh, so a closed input gives a
 *    closed 2-manifold (the validator's boundary edge count is 0);
 *  - the pull form in batches of 1, 7 and 100 gives the same triangles as the push form;
 *  - the plan equals the peak, every smaller arena fails with SUBD_ERR_NOMEM (bytes_needed =
 *    the plan, nothing emitted, arena unchanged); bad parameters; a sink's stop value. */
#include <string.h>
#include "harness.h"
#include "corpus.h"
#include "fixtures.h"
#if H_HOST
#include <stdio.h>
#define T_NOTE(...) printf(__VA_ARGS__)
#else
#define T_NOTE(...) ((void)0)
#endif

/* The shapes: fx_sr48_shape (test/fixtures.c); g_bn sets the bipyramid's apex valence (3..16). */
static uint32_t g_bn = 5;

#define ST_ARENA (64u * 1024u)       /* the stream's arena: the top of h_arena_buf         */
#define MAT_ARENA (H_ARENA_BYTES - ST_ARENA)
#if H_HOST
#define MAXV 65536u /* sr48s_checkpoints: the tetrahedron at 11 binary steps */
#else
#define MAXV 2048u
#endif

/* The sink: compares triangle j with the extraction's face j. */
typedef struct cmp_ctx {
    const subd_mesh *m;
    uint32_t j, bad, stop_after;
    uint64_t id[MAXV];
    uint8_t have[MAXV];
    uint32_t hash;
} cmp_ctx;

static cmp_ctx g_cc;

static uint32_t tri_hash(uint32_t h, const subd_tri *t)
{
    uint32_t i, j;
    for (i = 0; i < 3u; i++) {
        for (j = 0; j < 3u; j++) {
            uint32_t b = subd_real_bits(t->pos[i][j]);
            h = h_fnv(h, &b, 4);
        }
        h = h_fnv(h, &t->id[i], 8);
    }
    h = h_fnv(h, &t->face, 4);
    return h_fnv(h, &t->level, 4);
}

static int cmp_tri(void *ctx, const subd_tri *t)
{
    cmp_ctx *c = (cmp_ctx *)ctx;
    const subd_mesh *m = c->m;
    uint32_t i, q;
    c->hash = tri_hash(c->hash, t);
    if (c->j >= m->num_faces) {
        c->bad++;
        return 0;
    }
    for (i = 0; i < 3u; i++) {
        uint32_t v = m->corner_vert[3u * c->j + i];
        for (q = 0; q < 3u; q++)
            if (!h_same(t->pos[i][q], m->pos[3u * v + q])) c->bad++;
        if (v < MAXV) {
            if (c->have[v] && c->id[v] != t->id[i]) c->bad++;
            c->have[v] = 1;
            c->id[v] = t->id[i];
        }
    }
    c->j++;
    if (c->stop_after && c->j == c->stop_after) return 77;
    return 0;
}

/* Ids distinct across vertices (an insertion sort of c->id in place: the last use). */
static int ids_distinct(cmp_ctx *c, uint32_t nv)
{
    uint64_t *ids = c->id;
    uint32_t i, j;
    for (i = 0; i < nv; i++) {
        uint64_t x = c->id[i];
        j = i;
        while (j > 0u && ids[j - 1u] > x) {
            ids[j] = ids[j - 1u];
            j--;
        }
        ids[j] = x;
    }
    for (i = 1; i < nv; i++)
        if (ids[i] == ids[i - 1u]) return 0;
    return 1;
}

static subd_tri g_buf[100];

/* The base's largest valence counted directly: triangles per vertex. */
static uint16_t g_cnt[MAXV];
static uint32_t base_valence(const subd_sr48 *b)
{
    uint32_t t, best = 0;
    if (b->num_verts > MAXV) return 0;
    for (t = 0; t < b->num_verts; t++) g_cnt[t] = 0;
    for (t = 0; t < 3u * b->level_tri[1]; t++)
        if (++g_cnt[b->tri_vert[t]] > best) best = g_cnt[b->tri_vert[t]];
    return best;
}

/* Pull in batches of `batch`: the hash of everything. */
static int pull_hash(subd_arena *a, const subd_sr48 *base, const subd_sr48_stream_opts *o, uint32_t batch,
                     uint32_t *hash, uint32_t *count)
{
    subd_stream s;
    subd_diag d;
    uint32_t h = 2166136261u, n = 0, mark = subd_arena_mark(a);
    int got, i;
    if (!CHECK_EQ(subd_sr48_stream_begin(a, base, o, &s, &d), SUBD_OK)) return 0;
    while ((got = subd_stream_next_tris(&s, g_buf, batch)) > 0) {
        CHECK(got <= (int)batch);
        for (i = 0; i < got; i++) h = tri_hash(h, &g_buf[i]);
        n += (uint32_t)got;
    }
    CHECK_EQ(got, 0);
    CHECK_EQ(subd_arena_mark(a), mark);
    *hash = h;
    *count = n;
    return 1;
}

/* The materialised side's buffer (NULL: h_arena_buf below the stream's arena). */
static uint8_t *g_mat;
static uint32_t g_mat_bytes;

static void run_case(int shape, uint32_t levels, uint32_t flags)
{
    subd_arena a, sa;
    subd_mesh in, out;
    subd_sr48 h, base;
    subd_sr48_opts o;
    subd_sr48_stream_opts so;
    subd_sr48_adapt_report rep;
    subd_diag d;
    subd_tri_sink sink;
    uint32_t plan = 0, i, ph, pn, b;
    subd_arena_init(&a, g_mat ? g_mat : h_arena_buf, g_mat ? g_mat_bytes : MAT_ARENA);
    if (!fx_sr48_shape(shape, g_bn, &a, &in)) return;
    o.steps = levels;
    o.flags = flags;
    if (!CHECK_EQ(subd_sr48_build(&a, &in, &o, &h, &d), SUBD_OK)) return;
    so.adapt.mode = SUBD_SR48_ADAPT_UNIFORM;
    so.adapt.max_level = levels;
    if (!CHECK_EQ(subd_sr48_extract(&a, &h, &so.adapt, &out, &rep, &d), SUBD_OK)) {
        T_NOTE("shape %d levels %u: extract needs %u\n", shape, levels, d.bytes_needed);
        return;
    }
    if (!CHECK_EQ(subd_sr48_base(&a, &in, flags, &base, &d), SUBD_OK)) return;
    /* the base is level 0 of the hierarchy */
    CHECK_EQ(base.level_tri[1], h.level_tri[1]);
    CHECK_EQ(base.num_verts, h.level_verts[0]);
    if (!CHECK(out.num_verts <= MAXV)) return;
    if (!CHECK_EQ(subd_sr48_stream_plan(&base, &so, &plan, &d), SUBD_OK)) return;
    subd_arena_init(&sa, h_arena_buf + MAT_ARENA, ST_ARENA);
    if (!CHECK(plan <= ST_ARENA)) {
        T_NOTE("plan %u\n", plan);
        return;
    }
    g_cc.m = &out;
    g_cc.j = 0;
    g_cc.bad = 0;
    g_cc.stop_after = 0;
    g_cc.hash = 2166136261u;
    for (i = 0; i < out.num_verts; i++) g_cc.have[i] = 0;
    sink.tri = cmp_tri;
    sink.ctx = &g_cc;
    subd_arena_reset_peak(&sa);
    if (!CHECK_EQ(subd_sr48_stream(&sa, &base, &so, &sink, &d), SUBD_OK)) {
        T_NOTE("shape %d levels %u flags %u: status %d face %u\n", shape, levels, flags, d.status, d.face);
        return;
    }
    CHECK_EQ(sa.peak, plan);
    CHECK_EQ(plan, SUBD_SR48_STREAM_BYTES(levels, base_valence(&base)));
    CHECK_EQ(subd_arena_mark(&sa), 0u);
    CHECK_EQ(g_cc.j, out.num_faces);
    if (!CHECK_EQ(g_cc.bad, 0u)) T_NOTE("shape %d levels %u flags %u\n", shape, levels, flags);
    for (i = 0; i < out.num_verts; i++) CHECK(g_cc.have[i]);
    CHECK(ids_distinct(&g_cc, out.num_verts));
    /* level-0 vertices keep their base index */
    for (i = 0; i < out.num_verts && levels == 0u; i++) CHECK(g_cc.id[i] < base.num_verts);
    /* welded by id the stream is the extraction's mesh; closed input -> closed output */
    CHECK_EQ(out.num_boundary_edges == 0u, in.num_boundary_edges == 0u);
    if (levels == 3u && shape != FX48_BIPYR) {
        static const char *const names[FX48_COUNT] = {"sr48s_tet", "sr48s_cube", "sr48s_ico", "sr48s_hexfan",
                                                   "sr48s_grid", "sr48s_two", "sr48s_torus", "sr48s_bipyr"};
        h_hash(names[shape], g_cc.hash ^ flags);
    }
    /* pull form, several batch sizes: the push form's triangles */
    for (b = 0; b < 3u; b++) {
        static const uint32_t sizes[3] = {1u, 7u, 100u};
        if (pull_hash(&sa, &base, &so, sizes[b], &ph, &pn)) {
            CHECK_EQ(pn, out.num_faces);
            CHECK_EQ(ph, g_cc.hash);
        }
    }
}

static void sr48s_uniform(void)
{
    /* up to 7 = SUBD_SR48_STREAM_TILE_LEVELS (7 levels only where the materialised hierarchy
     * fits the test arena: the two-triangle shape); more levels: sr48s_tiles, sr48s_checkpoints */
    static const uint32_t maxl[FX48_COUNT] = {6, 4, 3, 5, 1, 7, 3, 4};
    int s;
    uint32_t l, f;
    for (s = 0; s < FX48_COUNT; s++)
        for (f = 0; f < 2u; f++)
            for (l = 0; l <= maxl[s]; l++) run_case(s, l, f ? SUBD_SR48_NO_SMOOTH : 0u);
}

/* Uniform checkpoints (host): from 11 binary steps the levels more than
 * SUBD_SR48_STREAM_CKPT_ above the tile share window slots and are rebuilt from their
 * checkpoint when the walk returns (sr48_stream.c); the stream must still give the
 * extraction's triangles, bits and order, with plan = peak = the macro. */
#if H_HOST
static uint8_t g_big[32u << 20] __attribute__((aligned(8))); /* the hierarchy at 11-12 steps */
#endif
static void sr48s_checkpoints(void)
{
#if H_HOST
    uint32_t f;
    g_mat = g_big;
    g_mat_bytes = (uint32_t)sizeof g_big;
    for (f = 0; f < 2u; f++) {
        run_case(FX48_TWO, 11, f ? SUBD_SR48_NO_SMOOTH : 0u);
        run_case(FX48_TWO, 12, f ? SUBD_SR48_NO_SMOOTH : 0u);
        run_case(FX48_TET, 11, f ? SUBD_SR48_NO_SMOOTH : 0u);
    }
    g_mat = 0;
#endif
}

/* The uniform tile's last window is cropped tighter than the others (sr48_window.c,
 * subd_s48_refine_crop_: ring 1 of the descendants and the partners of its triangles when
 * max_level is even and smoothed, the descendants and their partners otherwise) and the
 * tile's windows alternate between two blocks: every max_level from 1 to 10 (tiles from
 * level 0 over a hybrid pair up to SUBD_SR48_STREAM_TILE_LEVELS, from level 0 per base
 * triangle one above, depth-first levels above the tile beyond), open (the grid, the two
 * triangles) and closed, and around extraordinary vertices of valence 3..16 at both
 * parities, against the extraction (host: the hierarchies need the big arena). */
static void sr48s_tiles(void)
{
#if H_HOST
    uint32_t f, l;
    g_mat = g_big;
    g_mat_bytes = (uint32_t)sizeof g_big;
    for (f = 0; f < 2u; f++) {
        for (l = 1; l <= 10u; l++)
            if (l != 3u) run_case(FX48_TWO, l, f ? SUBD_SR48_NO_SMOOTH : 0u); /* 3: sr48s_uniform (its HASH) */
        run_case(FX48_GRID, 7, f ? SUBD_SR48_NO_SMOOTH : 0u);
        run_case(FX48_ICO, 8, f ? SUBD_SR48_NO_SMOOTH : 0u);
        run_case(FX48_TORUS, 7, f ? SUBD_SR48_NO_SMOOTH : 0u);
        for (g_bn = 3; g_bn <= 16u; g_bn++)
            for (l = 4; l <= 5u; l++) run_case(FX48_BIPYR, l, f ? SUBD_SR48_NO_SMOOTH : 0u);
    }
    g_bn = 5;
    g_mat = 0;
#endif
}

/* Extraordinary valences: bipyramids with apexes of valence 3..16. */
static void sr48s_valence(void)
{
    for (g_bn = 3; g_bn <= 16u; g_bn++) {
        run_case(FX48_BIPYR, 3, 0);
        run_case(FX48_BIPYR, 3, SUBD_SR48_NO_SMOOTH);
    }
    g_bn = 5;
}

/* A shape's base in the low arena (the caller's), as subd_sr48_base builds it. */
static int make_base(int shape, subd_arena *a, uint32_t flags, subd_sr48 *base, subd_mesh *in)
{
    subd_diag d;
    subd_arena_init(a, h_arena_buf, MAT_ARENA);
    if (!fx_sr48_shape(shape, g_bn, a, in)) return 0;
    return CHECK_EQ(subd_sr48_base(a, in, flags, base, &d), SUBD_OK);
}

/* Every arena below the plan: SUBD_ERR_NOMEM, bytes_needed = the plan, arena unchanged,
 * nothing emitted; the plan itself works and is the peak. */
static void sr48s_plan_exhaustive(void)
{
    subd_arena a;
    subd_mesh in;
    subd_sr48 base;
    subd_sr48_stream_opts so;
    subd_diag d;
    uint32_t plan;
    if (!make_base(FX48_TET, &a, 0, &base, &in)) return;
    so.adapt.mode = SUBD_SR48_ADAPT_UNIFORM;
    so.adapt.max_level = 3;
    if (!CHECK_EQ(subd_sr48_stream_plan(&base, &so, &plan, &d), SUBD_OK)) return;
    /* 16 level-0 triangles, 2^3 each */
    CHECK_EQ(fx_sr48_plan_sweep(&base, &so, h_arena_buf + MAT_ARENA, plan, 7u, 64u), 16u << 3);
}

static int stop_at(void *ctx, const subd_tri *t)
{
    uint32_t *n = (uint32_t *)ctx;
    (void)t;
    return ++*n == 5u ? 42 : 0;
}

static void sr48s_errors(void)
{
    subd_arena a, sa;
    subd_mesh in, noadj;
    subd_sr48 base, bad, h;
    subd_sr48_opts o;
    subd_sr48_stream_opts so;
    subd_diag d;
    subd_tri_sink sink;
    subd_stream s;
    uint32_t plan, n = 0, flags = 0, m;
    static uint32_t nb[1024];
    if (!make_base(FX48_ICO, &a, 0, &base, &in)) return;
    subd_arena_init(&sa, h_arena_buf + MAT_ARENA, ST_ARENA);
    so.adapt.mode = SUBD_SR48_ADAPT_UNIFORM;
    so.adapt.max_level = 2;
    sink.tri = stop_at;
    sink.ctx = &n;
    /* a sink's stop value comes back unchanged, the arena is given back */
    CHECK_EQ(subd_sr48_stream(&sa, &base, &so, &sink, &d), 42);
    CHECK_EQ(n, 5u);
    CHECK_EQ(subd_arena_mark(&sa), 0u);
    /* parameters */
    CHECK_FAIL(subd_sr48_stream_plan(0, &so, &plan, &d), &d, SUBD_ERR_PARAM);
    CHECK_FAIL(subd_sr48_stream_plan(&base, 0, &plan, &d), &d, SUBD_ERR_PARAM);
    CHECK_FAIL(subd_sr48_stream_plan(&base, &so, 0, &d), &d, SUBD_ERR_PARAM);
    CHECK_FAIL(subd_sr48_stream(&sa, &base, &so, 0, &d), &d, SUBD_ERR_PARAM);
    CHECK_EQ(d.status, SUBD_ERR_PARAM);
    CHECK_FAIL(subd_sr48_stream(0, &base, &so, &sink, &d), &d, SUBD_ERR_PARAM);
    CHECK_FAIL(subd_sr48_stream_begin(&sa, &base, &so, 0, &d), &d, SUBD_ERR_PARAM);
    so.adapt.max_level = SUBD_SR48_MAX_STEPS + 1u;
    CHECK_FAIL(subd_sr48_stream_plan(&base, &so, &plan, &d), &d, SUBD_ERR_PARAM);
    so.adapt.max_level = 2;
    so.adapt.mode = (subd_sr48_adapt_mode)77;
    CHECK_FAIL(subd_sr48_stream_plan(&base, &so, &plan, &d), &d, SUBD_ERR_PARAM);
    so.adapt.mode = SUBD_SR48_ADAPT_UNIFORM;
    /* a base that is not subd_sr48_base's: a hierarchy (no hyb_base_nb), steps > 0, broken
     * neighbours or vertices; each refused before anything is emitted */
    o.steps = 1;
    o.flags = 0;
    if (CHECK_EQ(subd_sr48_build(&a, &in, &o, &h, &d), SUBD_OK)) {
        CHECK(h.hyb_base_nb == 0);
        CHECK_FAIL(subd_sr48_stream_plan(&h, &so, &plan, &d), &d, SUBD_ERR_PARAM);
    }
    bad = base;
    bad.steps = 1;
    CHECK_FAIL(subd_sr48_stream_plan(&bad, &so, &plan, &d), &d, SUBD_ERR_PARAM);
    bad = base;
    bad.flags = 8;
    CHECK_FAIL(subd_sr48_stream_plan(&bad, &so, &plan, &d), &d, SUBD_ERR_PARAM);
    if (CHECK(base.level_tri[1] <= 1024u)) {
        for (m = 0; m < base.level_tri[1]; m++) nb[m] = base.tri_base_nb[m];
        bad = base;
        bad.tri_base_nb = nb;
        nb[3] = nb[5]; /* points at a triangle that does not point back */
        CHECK_FAIL(subd_sr48_stream_plan(&bad, &so, &plan, &d), &d, SUBD_ERR_PARAM);
        n = 0;
        CHECK_FAIL(subd_sr48_stream(&sa, &bad, &so, &sink, &d), &d, SUBD_ERR_PARAM);
        CHECK_EQ(n, 0u);
        nb[3] = base.level_tri[1];
        CHECK_FAIL(subd_sr48_stream_plan(&bad, &so, &plan, &d), &d, SUBD_ERR_PARAM);
    }
    bad = base;
    bad.hyb_base_nb = nb;
    for (m = 0; m < base.level_tri[1] / 2u; m++) nb[m] = base.hyb_base_nb[m];
    nb[0] = SUBD_NONE; /* one side says boundary, the other does not */
    CHECK_FAIL(subd_sr48_stream_plan(&bad, &so, &plan, &d), &d, SUBD_ERR_PARAM);
    CHECK_EQ(subd_arena_mark(&sa), 0u);
    /* the pull handle: bad calls, and a stale handle */
    CHECK_EQ(subd_stream_next_tris(0, g_buf, 1), SUBD_ERR_PARAM);
    if (CHECK_EQ(subd_sr48_stream_begin(&sa, &base, &so, &s, &d), SUBD_OK)) {
        CHECK_EQ(subd_stream_next_tris(&s, 0, 1), SUBD_ERR_PARAM);
        CHECK_EQ(subd_stream_next_tris(&s, g_buf, 0), SUBD_ERR_PARAM);
        CHECK_EQ(subd_stream_next_points(&s, (subd_point *)(void *)g_buf, 1), SUBD_ERR_PARAM);
        CHECK_EQ(subd_stream_next_tris(&s, g_buf, 3), 3);
        subd_stream_end(&s);
        CHECK_EQ(subd_arena_mark(&sa), 0u);
        CHECK_EQ(subd_stream_next_tris(&s, g_buf, 3), 0);
    }
    /* the base call refuses what subd_sr48_build refuses */
    CHECK_FAIL(subd_sr48_base(&a, 0, 0, &base, &d), &d, SUBD_ERR_PARAM);
    CHECK_FAIL(subd_sr48_base(&a, &in, 4u, &base, &d), &d, SUBD_ERR_PARAM);
    CHECK_EQ(subd_sr48_base_plan(&in, 0, SUBD_SR48_CLUSTERS_UNKNOWN, 0), SUBD_ERR_PARAM);
    if (h_tetra_no_adjacency(&a, &in, &noadj)) CHECK_FAIL(subd_sr48_base(&a, &noadj, 0, &base, &d), &d, SUBD_ERR_PARAM);
    (void)flags;
}

/* subd_sr48_base: plan exact with the cluster count, every smaller arena fails cleanly, and
 * it is subd_sr48_build's level 0 (same arrays) plus the hybrid neighbours. */
static void sr48s_base(void)
{
    subd_arena a;
    subd_mesh in;
    subd_sr48 base, h;
    subd_sr48_opts o;
    subd_diag d;
    uint32_t cl, plan, plan0, i, mark, size;
    subd_arena_init(&a, h_arena_buf, MAT_ARENA);
    if (!fx_sr48_shape(FX48_ICO, g_bn, &a, &in)) return;
    if (!CHECK_EQ(subd_sr48_count_clusters(&a, &in, &cl, &d), SUBD_OK)) return;
    if (!CHECK_EQ(subd_sr48_base_plan(&in, 0, cl, &plan), SUBD_OK)) return;
    o.steps = 0;
    o.flags = 0;
    if (!CHECK_EQ(subd_sr48_plan(&in, &o, cl, &plan0, &d), SUBD_OK)) return;
    mark = subd_arena_mark(&a);
    if (!CHECK_EQ(subd_sr48_build(&a, &in, &o, &h, &d), SUBD_OK)) return;
    CHECK_EQ(plan - plan0, (h.level_tri[1] / 2u * 4u + 7u) & ~7u);
    for (size = plan - 40u; size <= plan; size++) {
        subd_arena b;
        subd_arena_init(&b, h_arena_buf + MAT_ARENA, size);
        if (size < plan) {
            CHECK_FAIL(subd_sr48_base(&b, &in, 0, &base, &d), &d, SUBD_ERR_NOMEM);
            CHECK_EQ(d.bytes_needed, plan);
            CHECK_EQ(subd_arena_mark(&b), 0u);
        } else {
            subd_arena_reset_peak(&b);
            if (!CHECK_EQ(subd_sr48_base(&b, &in, 0, &base, &d), SUBD_OK)) return;
            CHECK_EQ(b.peak, plan);
        }
    }
    CHECK_EQ(base.num_tris, h.num_tris);
    for (i = 0; i < 3u * h.num_tris; i++) CHECK_EQ(base.tri_vert[i], h.tri_vert[i]);
    for (i = 0; i < h.num_tris; i++) CHECK_EQ(base.tri_base_nb[i], h.tri_base_nb[i]);
    for (i = 0; i < 3u * h.num_verts; i++) CHECK(h_same(base.pos[i], h.pos[i]));
    (void)mark;
}


/* ------------------------------------------------------------------------------------ */
/* Adaptive cuts: that the stream's triangles are subd_sr48_extract's, every mode on every
 * shape, is test_sr48_stream_shapes.c's (faces matched by hierarchy vertex numbers, so cuts
 * with coincident faces too; the callback's call count, no forced splits); here their
 * error paths. */
/* CALLBACK: a viewer at g_view, one level per g_vr of distance from the region's box (0
 * inside it): monotone (a box inside another is no nearer), so nested. */
static double g_view[3], g_vr;
static uint32_t g_vmax;
static uint32_t view_level(void *ctx, const subd_real *lo, const subd_real *hi)
{
    double d2 = 0, lim;
    uint32_t i, n;
    (void)ctx;
    for (i = 0; i < 3u; i++) {
        double l = h_dbl(lo[i]), h = h_dbl(hi[i]), e = g_view[i] < l ? l - g_view[i] : g_view[i] > h ? g_view[i] - h : 0;
        d2 += e * e;
    }
    /* level max - floor(d / r), 0 beyond max r: the largest n <= max with (max - n) r <= d */
    for (n = 0; n <= g_vmax; n++) {
        lim = (double)(g_vmax - n) * g_vr;
        if (lim * lim <= d2) return n;
    }
    return g_vmax;
}

/* The error paths of the modes that need the adaptation box or a callback (RAMP, POINT's
 * default radius, CALLBACK): every arena below the plan gives SUBD_ERR_NOMEM (bytes_needed =
 * the plan, nothing emitted, arena unchanged), the plan works; bad parameters give the
 * status subd_sr48_extract gives on the same cut of the built hierarchy, nothing emitted; a
 * sink's stop value comes back. */
static void sr48s_adapt_errors(void)
{
    subd_arena a, sa;
    subd_mesh in;
    subd_sr48 base, h;
    subd_sr48_opts o;
    subd_sr48_stream_opts so;
    subd_diag d;
    subd_tri_sink sink;
    subd_mesh out;
    uint32_t plan, size, n, m, full = 0;
    int st, xs;
    if (!make_base(FX48_CUBE, &a, 0, &base, &in)) return;
    o.steps = 3;
    o.flags = 0;
    if (!CHECK_EQ(subd_sr48_build(&a, &in, &o, &h, &d), SUBD_OK)) return;
    sink.tri = fx_count_tri;
    sink.ctx = &n;
    g_view[0] = 0.6; g_view[1] = 0.2; g_view[2] = 0.9;
    g_vr = 0.25;
    g_vmax = 3;
    for (m = 0; m < 3u; m++) {
        memset(&so, 0, sizeof so);
        so.adapt.max_level = 3;
        so.adapt.mode = m == 0u ? SUBD_SR48_ADAPT_RAMP : m == 1u ? SUBD_SR48_ADAPT_POINT : SUBD_SR48_ADAPT_CALLBACK;
        so.adapt.axis = 2;
        so.adapt.fn = view_level;
        if (!CHECK_EQ(subd_sr48_stream_plan(&base, &so, &plan, &d), SUBD_OK)) return;
        for (size = 0; size <= plan; size += (size + 16u < plan) ? 61u : 1u) {
            n = 0;
            subd_arena_init(&sa, h_arena_buf + MAT_ARENA, size);
            st = subd_sr48_stream(&sa, &base, &so, &sink, &d);
            if (size < plan) {
                if (!CHECK_EQ(st, SUBD_ERR_NOMEM) || !CHECK_EQ(d.bytes_needed, plan) || !CHECK_EQ(n, 0u) ||
                    !CHECK_EQ(subd_arena_mark(&sa), 0u) || !CHECK_EQ(sa.peak, 0u))
                    return;
            } else {
                CHECK_EQ(st, SUBD_OK);
                CHECK(n > 0u);
                CHECK_EQ(sa.peak, plan);
                CHECK_EQ(d.bytes_needed, 0u);
                full = n;
            }
        }
        /* a sink's stop value, mid-stream */
        n = 0;
        sink.tri = stop_at;
        subd_arena_init(&sa, h_arena_buf + MAT_ARENA, ST_ARENA);
        if (full > 5u) {
            CHECK_EQ(subd_sr48_stream(&sa, &base, &so, &sink, &d), 42);
            CHECK_EQ(n, 5u);
        }
        CHECK_EQ(subd_arena_mark(&sa), 0u);
        sink.tri = fx_count_tri;
        /* bad parameters of this mode: extract's status, nothing emitted */
        if (m == 0u) so.adapt.axis = 3;
        if (m == 1u) so.adapt.radius = fx_real(-1);
        if (m == 2u) so.adapt.fn = 0;
        xs = subd_sr48_extract(&a, &h, &so.adapt, &out, 0, &d);
        CHECK_EQ(xs, SUBD_ERR_PARAM);
        n = 0;
        CHECK_FAIL(subd_sr48_stream(&sa, &base, &so, &sink, &d), &d, xs);
        CHECK_FAIL(subd_sr48_stream_plan(&base, &so, &plan, &d), &d, xs);
        CHECK_EQ(n, 0u);
        CHECK_EQ(subd_arena_mark(&sa), 0u);
#if !SUBD_FIXED
        if (m == 1u) { /* a non-finite point */
            union { uint32_t u; float f; } nan;
            nan.u = 0x7fc00000u;
            so.adapt.radius = 0;
            so.adapt.point[1] = nan.f;
            xs = subd_sr48_extract(&a, &h, &so.adapt, &out, 0, &d);
            CHECK_EQ(xs, SUBD_ERR_PARAM);
            CHECK_FAIL(subd_sr48_stream(&sa, &base, &so, &sink, &d), &d, xs);
            CHECK_EQ(n, 0u);
        }
#endif
    }
}

const test_case suite_sr48_stream[] = {
    {"sr48s_base", sr48s_base},
    {"sr48s_plan_exhaustive", sr48s_plan_exhaustive},
    {"sr48s_errors", sr48s_errors},
    {"sr48s_uniform", sr48s_uniform},
    {"sr48s_valence", sr48s_valence},
    {"sr48s_checkpoints", sr48s_checkpoints},
    {"sr48s_tiles", sr48s_tiles},
    {"sr48s_adapt_errors", sr48s_adapt_errors},
    {0, 0},
};
