/* SPDX-License-Identifier: MIT */
/* The base mesh's census of its level-0 windows (subd_sr48's stream_valence, filled by
 * subd_sr48_base: src/sr48_census.c) and the 4-8 stream on a base whose extraordinary
 * vertices are close together (test/data/dense_ico.obj: three valence-9 input vertices in
 * one triangle), where windows sized by the largest valence alone are too small (the stream
 * stopped with SUBD_ERR_TOO_BIG before the census, as on nefertiti and fandisk).
 *  - stream_valence is at least max(8, the largest valence) and, on every shape of the
 *    other 4-8 tests, equal to it (their plans do not change); on the dense mesh larger;
 *  - every level-0 window (a hybrid pair's and each triangle's two vertex rings, counted
 *    here by a brute-force distance search over tri_vert, not the fan walks) fits the
 *    capacities of stream_valence: 6 N + 16 triangles, 4 N + 16 vertices;
 *  - the stream on the dense mesh equals subd_sr48_build + subd_sr48_extract: UNIFORM triangle
 *    j is face j (same corners, same bits), POINT the same triangles (sorted), levels 0..3
 *    (the device 0..1), smoothing on and off, plan = peak = the macro of stream_valence;
 *  - subd_sr48_build's hierarchy has stream_valence 0; subd_sr48_base's plan = its peak. */
#include <stdlib.h>
#include <string.h>
#include "harness.h"
#include "corpus.h"
#include "fixtures.h"

#if H_HOST
#include <stdio.h>
#define CE_NOTE(...) printf(__VA_ARGS__)
#else
#define CE_NOTE(...) ((void)0)
#endif

#define CE_ST_ARENA (64u * 1024u)
#define CE_MAT_ARENA (H_ARENA_BYTES - CE_ST_ARENA)
#define CE_MAXT (H_HOST ? 8192u : 1024u) /* triangles compared */
#define CE_MAXB 1024u                    /* base vertices and triangles searched */

static int ce_dense(subd_arena *a, subd_mesh *m)
{
    const corpus_file *f = corpus_find("test/data/dense_ico.obj");
    subd_diag d;
    if (!CHECK(f != 0)) return 0;
    return CHECK_EQ(subd_obj_read(a, f->data, f->len, m, &d), SUBD_OK);
}

/* Brute force: the largest level-0 window (triangles, vertices) over the pairs and single
 * triangles: vertices at distance <= 2 from the seeds by repeated passes over tri_vert
 * (a triangle links its three vertices), triangles with a vertex at distance <= 1. */
static uint8_t g_dist[CE_MAXB];
static void ce_window(const subd_sr48 *b, uint32_t p0, uint32_t p1, uint32_t *nt, uint32_t *nv)
{
    uint32_t t, j, pass, n0 = b->level_tri[1];
    for (t = 0; t < b->num_verts; t++) g_dist[t] = 9;
    for (t = p0; t <= p1; t++)
        for (j = 0; j < 3u; j++) g_dist[b->tri_vert[3u * t + j]] = 0;
    for (pass = 1; pass <= 2u; pass++)
        for (t = 0; t < n0; t++) {
            uint32_t lo = 9;
            for (j = 0; j < 3u; j++)
                if (g_dist[b->tri_vert[3u * t + j]] < lo) lo = g_dist[b->tri_vert[3u * t + j]];
            if (lo + 1u != pass) continue;
            for (j = 0; j < 3u; j++)
                if (g_dist[b->tri_vert[3u * t + j]] > pass) g_dist[b->tri_vert[3u * t + j]] = (uint8_t)pass;
        }
    *nt = 0;
    *nv = 0;
    for (t = 0; t < n0; t++) {
        uint32_t lo = 9;
        for (j = 0; j < 3u; j++)
            if (g_dist[b->tri_vert[3u * t + j]] < lo) lo = g_dist[b->tri_vert[3u * t + j]];
        if (lo <= 1u) ++*nt;
    }
    for (t = 0; t < b->num_verts; t++)
        if (g_dist[t] <= 2u) ++*nv;
}

static void ce_capacity(const subd_sr48 *b, const char *what)
{
    uint32_t t, nt, nv, mt = 0, mv = 0, n = b->stream_valence, low;
    (void)what; /* named in the host's note */
    if (!CHECK(b->num_verts <= CE_MAXB && b->level_tri[1] <= CE_MAXB)) return;
    for (t = 0; t + 1u < b->level_tri[1]; t += 2u) {
        ce_window(b, t, t + 1u, &nt, &nv);
        if (nt > mt) mt = nt;
        if (nv > mv) mv = nv;
        ce_window(b, t, t, &nt, &nv);
        if (nt > mt) mt = nt;
        if (nv > mv) mv = nv;
    }
    if (!CHECK(mt <= 6u * n + 16u && mv <= 4u * n + 16u))
        CE_NOTE("%s: a window of %u triangles, %u vertices; N = %u\n", what, mt, mv, n);
    CHECK(n >= 8u && n >= fx_sr48_valence(b, &low));
}

/* stream_valence = max(8, valence) on the shapes of the other tests; windows fit. */
static void sr48ce_shapes(void)
{
    static const int shapes[] = {FX48_TET, FX48_CUBE, FX48_ICO, FX48_HEXFAN, FX48_GRID, FX48_TWO, FX48_TORUS, FX48_BIPYR};
    uint32_t i, low, v;
    for (i = 0; i < sizeof shapes / sizeof shapes[0]; i++) {
        subd_arena a;
        subd_mesh in;
        subd_sr48 base, h;
        subd_sr48_opts o;
        subd_diag d;
        uint32_t plan = 0;
        subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
        if (!fx_sr48_shape(shapes[i], 12u, &a, &in)) continue;
        if (!CHECK_EQ(subd_sr48_base_plan(&in, 0u, SUBD_SR48_CLUSTERS_UNKNOWN, &plan), SUBD_OK)) continue;
        subd_arena_reset_peak(&a);
        {
            uint32_t mark = subd_arena_mark(&a);
            if (!CHECK_EQ(subd_sr48_base(&a, &in, 0u, &base, &d), SUBD_OK)) continue;
            CHECK(a.peak - mark <= plan); /* the census's scratch is in the plan */
        }
        v = fx_sr48_valence(&base, &low);
        CHECK_EQ(base.stream_valence, v < 8u ? 8u : v);
        ce_capacity(&base, "sr48ce_capacity_shape");
        o.steps = 1;
        o.flags = 0;
        if (CHECK_EQ(subd_sr48_build(&a, &in, &o, &h, &d), SUBD_OK)) CHECK_EQ(h.stream_valence, 0u);
    }
}

/* The stream's triangles, kept. */
typedef struct ce_sink {
    uint32_t n, over;
    subd_real pos[9u * CE_MAXT];
} ce_sink;
static ce_sink g_ce;
static int ce_tri(void *ctx, const subd_tri *t)
{
    ce_sink *s = (ce_sink *)ctx;
    uint32_t i, j;
    if (s->n >= CE_MAXT) {
        s->over = 1;
        return 0;
    }
    for (i = 0; i < 3u; i++)
        for (j = 0; j < 3u; j++) s->pos[9u * s->n + 3u * i + j] = t->pos[i][j];
    s->n++;
    return 0;
}

/* Triangle keys for the sorted comparison: the 9 position bits of a triangle rotated to
 * start at its smallest corner, in a uint32_t[9] row. */
static uint32_t g_ka[9u * CE_MAXT], g_kb[9u * CE_MAXT];

#if H_HOST
static uint8_t g_mat[4u << 20] __attribute__((aligned(8))); /* the hierarchy at level 3 */
#endif

static void ce_case(uint32_t levels, uint32_t flags, int point)
{
    subd_arena a, sa;
    subd_mesh in, out;
    subd_sr48 h, base;
    subd_sr48_opts o;
    subd_sr48_stream_opts so;
    subd_sr48_adapt_report rep;
    subd_diag d;
    subd_tri_sink sink;
    uint32_t plan = 0, i, j, low, bad = 0;
#if H_HOST
    subd_arena_init(&a, g_mat, (uint32_t)sizeof g_mat);
#else
    subd_arena_init(&a, h_arena_buf, CE_MAT_ARENA);
#endif
    if (!ce_dense(&a, &in)) return;
    o.steps = levels;
    o.flags = flags;
    if (!CHECK_EQ(subd_sr48_build(&a, &in, &o, &h, &d), SUBD_OK)) return;
    memset(&so, 0, sizeof so);
    so.adapt.mode = point ? SUBD_SR48_ADAPT_POINT : SUBD_SR48_ADAPT_UNIFORM;
    so.adapt.max_level = levels;
    so.adapt.point[0] = fx_real(1.9);
    so.adapt.radius = fx_real(0.5);
    if (!CHECK_EQ(subd_sr48_extract(&a, &h, &so.adapt, &out, &rep, &d), SUBD_OK)) {
        CE_NOTE("levels %u flags %u point %d: extract status %d needs %u\n", levels, flags, point, d.status,
                d.bytes_needed);
        return;
    }
    if (!CHECK_EQ(subd_sr48_base(&a, &in, flags, &base, &d), SUBD_OK)) return;
    if (levels == 0u && !flags && !point) { /* once: the census matters on this mesh */
        CHECK(base.stream_valence > fx_sr48_valence(&base, &low));
        ce_capacity(&base, "sr48ce_capacity_dense");
    }
    if (!CHECK(out.num_faces <= CE_MAXT)) return;
    if (!CHECK_EQ(subd_sr48_stream_plan(&base, &so, &plan, &d), SUBD_OK)) return;
    CHECK_EQ(plan, point ? SUBD_SR48_STREAM_ADAPT_BYTES(levels, base.stream_valence)
                         : SUBD_SR48_STREAM_BYTES(levels, base.stream_valence));
    if (!CHECK(plan <= CE_ST_ARENA)) return;
    subd_arena_init(&sa, h_arena_buf + CE_MAT_ARENA, CE_ST_ARENA);
    subd_arena_reset_peak(&sa);
    g_ce.n = 0;
    g_ce.over = 0;
    sink.tri = ce_tri;
    sink.ctx = &g_ce;
    if (!CHECK_EQ(subd_sr48_stream(&sa, &base, &so, &sink, &d), SUBD_OK)) return;
    CHECK_EQ(sa.peak, plan);
    CHECK_EQ(g_ce.over, 0u);
    if (!CHECK_EQ(g_ce.n, out.num_faces)) return;
    for (i = 0; i < out.num_faces; i++) {
        subd_real q[9];
        uint32_t c;
        for (c = 0; c < 3u; c++)
            for (j = 0; j < 3u; j++) q[3u * c + j] = out.pos[3u * out.corner_vert[3u * i + c] + j];
        if (!point) {
            for (j = 0; j < 9u; j++)
                if (!h_same(q[j], g_ce.pos[9u * i + j])) bad++;
            continue;
        }
        fx_tri_key(&g_ka[9u * i], q);
        fx_tri_key(&g_kb[9u * i], &g_ce.pos[9u * i]);
    }
    if (point) {
        qsort(g_ka, out.num_faces, 36, fx_tri_key_cmp);
        qsort(g_kb, out.num_faces, 36, fx_tri_key_cmp);
        bad += memcmp(g_ka, g_kb, 36u * out.num_faces) != 0;
        if (levels == 1u && !flags) CHECK(out.num_faces < 2u * base.level_tri[1]); /* a real cut */
    }
    CHECK_EQ(bad, 0u);
    if (levels == 1u && !point) {
        uint32_t hv = 2166136261u;
        for (i = 0; i < 9u * g_ce.n; i++) {
            uint32_t bits = subd_real_bits(g_ce.pos[i]);
            hv = h_fnv(hv, &bits, 4);
        }
        h_hash(flags ? "sr48ce_dense_l1_nosmooth" : "sr48ce_dense_l1", hv);
    }
}

static void sr48ce_dense(void)
{
    uint32_t l, f;
    for (f = 0; f < 2u; f++)
        for (l = 0; l <= (H_HOST ? 3u : 1u); l++) {
            ce_case(l, f ? SUBD_SR48_NO_SMOOTH : 0u, 0);
            ce_case(l, f ? SUBD_SR48_NO_SMOOTH : 0u, 1);
        }
}

const test_case suite_sr48_census[] = {
    {"sr48ce_shapes", sr48ce_shapes},
    {"sr48ce_dense", sr48ce_dense},
    {0, 0},
};
