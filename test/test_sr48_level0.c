/* SPDX-License-Identifier: MIT */
/* The 4-8 stream's level 0 and the base's census (src/sr48_level0.c, src/sr48_census.c):
 *  - the valence walk (each fan whole once, from its lowest triangle) gives the largest
 *    number of triangles at a vertex, counted here from tri_vert (fx_sr48_valence), on every
 *    shape without a vertex of two fans;
 *  - the census with its bounded gatherings skipped gives the N of the census with every
 *    gathering made (subd_s48_census_run_ exact), which is the base's stream_valence, on the
 *    4-8 test shapes, bipyramids of valence 3..16, the dense icosahedron (a census above the
 *    valence), the nefertiti patch, the 64-fan, the triangulated torus, and a base with a
 *    vertex of two fans (made by hand: two triangles apart, joined at a vertex), where
 *    nothing is skipped; over the shapes gatherings are skipped (the bounded path is
 *    reached);
 *  - the stream's plan on a base made by hand (stream_valence cleared, or too large) follows
 *    the valence walk, or refuses the base with the same status;
 *  - the stream against subd_sr48_build + subd_sr48_extract on five shapes through the
 *    level-0 windows, and a base damaged between plan and begin (sr48l0_stream,
 *    sr48l0_between, below). */
#include <stdlib.h>
#include <string.h>
#include "harness.h"
#include "corpus.h"
#include "fixtures.h"
#include "../src/sr48_stream_internal.h"

/* Two triangles apart (x < 1 and x > 3); l0_bowtie joins them at a vertex, by hand (the
 * mesh builder refuses a vertex of two fans, so subd_sr48_base never makes one). */
static const char l0_two_obj[] = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 3 0 0\nv 4 0 0\nv 3 1 0\nf 1 2 3\nf 4 5 6\n";
static uint32_t g_l0_tv[3u * 64u];

/* base with a corner of a triangle right of x = 2 renamed to a vertex left of it (its
 * tri_vert copied to g_l0_tv): a vertex of two fans. 0 when the base is not as expected. */
static int l0_bowtie(subd_sr48 *base)
{
    uint32_t t, j, va = SUBD_NONE, vb = SUBD_NONE;
    if (!CHECK(3u * base->level_tri[1] <= 3u * 64u)) return 0;
    for (t = 0; t < base->num_verts; t++) {
        const subd_real x = base->pos[3u * t];
        if (x < fx_real(1.5) && va == SUBD_NONE) va = t;
        if (x > fx_real(2.5) && vb == SUBD_NONE) vb = t;
    }
    if (!CHECK(va != SUBD_NONE && vb != SUBD_NONE)) return 0;
    for (t = 0; t < 3u * base->level_tri[1]; t++) g_l0_tv[t] = base->tri_vert[t] == vb ? va : base->tri_vert[t];
    base->tri_vert = g_l0_tv;
    for (j = 0, t = 0; t < 3u * base->level_tri[1]; t++) j += g_l0_tv[t] == va;
    return CHECK(j >= 2u);
}

static int l0_obj(subd_arena *a, const char *text, uint32_t len, subd_mesh *m)
{
    subd_diag d;
    return CHECK_EQ(subd_obj_read(a, text, len, m, &d), SUBD_OK);
}

/* Mesh number i of the census shapes (0 when past the last). */
static int l0_shape(uint32_t i, subd_arena *a, subd_mesh *m, int *two)
{
    static const uint32_t bipyr[5] = {3u, 5u, 9u, 12u, 16u};
    static const char *const files[3] = {"test/data/nefertiti_patch.obj", "test/data/fan64.obj",
                                         "test/data/torus_tri.obj"};
    *two = 0;
    if (i < FX48_COUNT) return fx_sr48_shape((int)i, 12u, a, m);
    i -= FX48_COUNT;
    if (i < 5u) return fx_sr48_shape(FX48_BIPYR, bipyr[i], a, m);
    i -= 5u;
    if (i == 0u) return fx_sr48_shape(FX48_DENSE, 12u, a, m);
    i -= 1u;
    if (i < 3u) {
        const corpus_file *f = corpus_find(files[i]);
        if (!CHECK(f != 0)) return 0;
        return l0_obj(a, (const char *)f->data, f->len, m);
    }
    i -= 3u;
    if (i == 0u) {
        *two = 1;
        return l0_obj(a, l0_two_obj, (uint32_t)sizeof l0_two_obj - 1u, m);
    }
    return -1;
}

static void sr48l0_census(void)
{
    uint32_t i, skipped_all = 0;
    for (i = 0;; i++) {
        subd_arena a;
        subd_mesh in;
        subd_sr48 base;
        subd_diag d;
        uint32_t skipped = 1, exact_skipped = 1, ne, ns, mark, low;
        int two, got;
        subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
        got = l0_shape(i, &a, &in, &two);
        if (got < 0) break;
        if (!got) continue;
        if (!CHECK_EQ(subd_sr48_base(&a, &in, 0u, &base, &d), SUBD_OK)) continue;
        if (two && !l0_bowtie(&base)) continue;
        mark = subd_arena_mark(&a);
        ne = subd_s48_census_run_(&a, &base, 1u, &exact_skipped);
        subd_arena_rewind(&a, mark);
        ns = subd_s48_census_run_(&a, &base, 0u, &skipped);
        subd_arena_rewind(&a, mark);
        CHECK(ne >= 8u);
        CHECK_EQ(ns, ne);
        if (!two) CHECK_EQ(base.stream_valence, ne);
        CHECK_EQ(exact_skipped, 0u);
        if (two) {
            CHECK_EQ(skipped, 0u); /* a vertex of two fans: every gathering made */
            CHECK(subd_s48_valence_(&base) <= fx_sr48_valence(&base, &low));
        } else {
            CHECK_EQ(subd_s48_valence_(&base), fx_sr48_valence(&base, &low));
        }
        skipped_all += skipped;
    }
    CHECK(skipped_all > 0u);
}

/* The stream's plan takes max(8, the valence walk, stream_valence): with stream_valence
 * cleared (a base made by hand) the plan is the macro of the corner count's valence, with it
 * above SUBD_SR48_STREAM_MAX_VALENCE the stream refuses the base (SUBD_ERR_TOO_BIG), on
 * bipyramids of valence 3..16 and the 64-fan (the largest valence the stream takes). */
static void sr48l0_valence(void)
{
    static const uint32_t bipyr[4] = {3u, 7u, 12u, 16u};
    uint32_t i;
    for (i = 0; i < 5u; i++) {
        subd_arena a;
        subd_mesh in;
        subd_sr48 base, bad;
        subd_sr48_stream_opts so;
        subd_diag d;
        uint32_t plan = 0, v, low, l;
        int got;
        subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
        if (i < 4u) {
            got = fx_sr48_shape(FX48_BIPYR, bipyr[i], &a, &in);
        } else {
            const corpus_file *f = corpus_find("test/data/fan64.obj");
            got = CHECK(f != 0) && l0_obj(&a, f->data, f->len, &in);
        }
        if (!got || !CHECK_EQ(subd_sr48_base(&a, &in, 0u, &base, &d), SUBD_OK)) continue;
        v = fx_sr48_valence(&base, &low);
        if (v < 8u) v = 8u;
        so.adapt.mode = SUBD_SR48_ADAPT_UNIFORM;
        for (l = 2u; l <= 8u; l += 6u) {
            so.adapt.max_level = l;
            bad = base;
            bad.stream_valence = 0;
            if (v > SUBD_SR48_STREAM_MAX_VALENCE) {
                CHECK_FAIL(subd_sr48_stream_plan(&bad, &so, &plan, &d), &d, SUBD_ERR_TOO_BIG);
                continue;
            }
            if (CHECK_EQ(subd_sr48_stream_plan(&bad, &so, &plan, &d), SUBD_OK))
                CHECK_EQ(plan, SUBD_SR48_STREAM_BYTES(l, v));
            bad.stream_valence = SUBD_SR48_STREAM_MAX_VALENCE + 1u;
            CHECK_FAIL(subd_sr48_stream_plan(&bad, &so, &plan, &d), &d, SUBD_ERR_TOO_BIG);
        }
    }
}

/* ------------------------------------------------------------------------------------ */
/* The level-0 windows against the materialised calls, and a base damaged between plan and
 * begin (src/sr48_level0.c's window gathers each fan as it walks it and finds neighbours
 * through one table; s48_check runs in plan and in begin, each on the base it is given).
 *  - the stream equals subd_sr48_build + subd_sr48_extract on the torus, the open grid,
 *    the two triangles and an isolated one, the hexagon fan and the valence-12 bipyramid,
 *    levels 1..3 (the device 1..2), with and without smoothing: UNIFORM (a tile from level 0
 *    over each hybrid pair's smaller window) triangle j is face j, same corner bits, and the
 *    ids a bijection onto the extraction's corners; POINT (a window per triangle, its two
 *    rings) the same triangles, sorted;
 *  - a base damaged after a successful plan (a neighbour that does not point back, a vertex
 *    out of range, no hyb_base_nb, steps != 0, no triangles, stream_valence above the
 *    largest) is refused by begin and by the push form with plan's status on it, the arena
 *    unchanged and no triangle emitted. */
#define L0_ST_ARENA (64u * 1024u)

/* The stream's triangles checked as they come: UNIFORM against face n of the extraction
 * (same corner bits, each extraction vertex always with one id), POINT kept as sorted keys.
 * Arrays from the materialised arena's free space (no static buffers: device RAM). */
typedef struct l0_sink {
    const subd_mesh *out;
    uint64_t *idv; /* UNIFORM: the id of each extraction vertex (UINT64_MAX: not met yet) */
    uint32_t *kb;  /* POINT: the triangles' keys */
    uint32_t n, bad;
} l0_sink;

static int l0_cmp64(const void *a, const void *b)
{
    const uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return x < y ? -1 : x > y;
}

static int l0_tri(void *ctx, const subd_tri *t)
{
    l0_sink *s = (l0_sink *)ctx;
    const subd_mesh *out = s->out;
    uint32_t c, j;
    if (s->n >= out->num_faces) { /* more triangles than the extraction */
        s->bad++;
        return 0;
    }
    if (s->kb) {
        subd_real p[9];
        for (c = 0; c < 3u; c++)
            for (j = 0; j < 3u; j++) p[3u * c + j] = t->pos[c][j];
        fx_tri_key(s->kb + 9u * s->n, p);
    } else {
        for (c = 0; c < 3u; c++) {
            const uint32_t v = out->corner_vert[3u * s->n + c];
            for (j = 0; j < 3u; j++)
                if (!h_same(out->pos[3u * v + j], t->pos[c][j])) s->bad++;
            if (s->idv[v] == UINT64_MAX) s->idv[v] = t->id[c];
            if (s->idv[v] != t->id[c]) s->bad++;
        }
    }
    s->n++;
    return 0;
}

#if H_HOST
static uint8_t g_l0mat[4u << 20] __attribute__((aligned(8))); /* the hierarchy at level 3 */
#endif

/* One shape at one level, UNIFORM or POINT, smoothing on or off; at level 1 (the host's and
 * the device's) the triangles' bits into *hv. */
static void l0_stream_case(int shape, uint32_t levels, uint32_t flags, int point, uint32_t *hv)
{
    subd_arena a, sa;
    subd_mesh in, out;
    subd_sr48 h, base;
    subd_sr48_opts o;
    subd_sr48_stream_opts so;
    subd_sr48_adapt_report rep;
    subd_diag d;
    subd_tri_sink sink;
    l0_sink k;
    uint32_t plan = 0, i, c, n = 0, *ka = 0;
    uint64_t *ids = 0;
#if H_HOST
    subd_arena_init(&a, g_l0mat, (uint32_t)sizeof g_l0mat);
#else
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES - L0_ST_ARENA);
#endif
    if (!fx_sr48_shape(shape, 12u, &a, &in)) return;
    o.steps = levels;
    o.flags = flags;
    if (!CHECK_OK(subd_sr48_build(&a, &in, &o, &h, &d), &d)) return;
    memset(&so, 0, sizeof so);
    so.adapt.mode = point ? SUBD_SR48_ADAPT_POINT : SUBD_SR48_ADAPT_UNIFORM;
    so.adapt.max_level = levels;
    so.adapt.radius = fx_real(0.25);
    if (!CHECK_OK(subd_sr48_extract(&a, &h, &so.adapt, &out, &rep, &d), &d)) return;
    if (!CHECK_OK(subd_sr48_base(&a, &in, flags, &base, &d), &d)) return;
    memset(&k, 0, sizeof k);
    k.out = &out;
    if (point) {
        ka = (uint32_t *)subd_arena_alloc(&a, 36u * out.num_faces);
        k.kb = (uint32_t *)subd_arena_alloc(&a, 36u * out.num_faces);
        if (!CHECK(ka != 0 && k.kb != 0)) return;
    } else {
        k.idv = (uint64_t *)subd_arena_alloc(&a, 8u * out.num_verts);
        ids = (uint64_t *)subd_arena_alloc(&a, 8u * out.num_verts);
        if (!CHECK(k.idv != 0 && ids != 0)) return;
        for (i = 0; i < out.num_verts; i++) k.idv[i] = UINT64_MAX;
    }
    if (!CHECK_OK(subd_sr48_stream_plan(&base, &so, &plan, &d), &d) || !CHECK(plan <= L0_ST_ARENA)) return;
    subd_arena_init(&sa, h_arena_buf + H_ARENA_BYTES - L0_ST_ARENA, L0_ST_ARENA);
    sink.tri = l0_tri;
    sink.ctx = &k;
    if (!CHECK_OK(subd_sr48_stream(&sa, &base, &so, &sink, &d), &d)) return;
    CHECK_EQ(sa.peak, plan);
    if (!CHECK_EQ(k.n, out.num_faces)) return;
    if (point) {
        for (i = 0; i < out.num_faces; i++) {
            subd_real q[9];
            uint32_t j;
            for (c = 0; c < 3u; c++)
                for (j = 0; j < 3u; j++) q[3u * c + j] = out.pos[3u * out.corner_vert[3u * i + c] + j];
            fx_tri_key(ka + 9u * i, q);
        }
        qsort(ka, out.num_faces, 36, fx_tri_key_cmp);
        qsort(k.kb, out.num_faces, 36, fx_tri_key_cmp);
        k.bad += memcmp(ka, k.kb, 36u * out.num_faces) != 0;
        if (levels == 1u) *hv = h_fnv(*hv, k.kb, 36u * out.num_faces);
    } else { /* no two extraction vertices with one id: the ids a bijection onto them */
        for (i = 0; i < out.num_verts; i++)
            if (k.idv[i] != UINT64_MAX) ids[n++] = k.idv[i];
        CHECK_EQ(n, out.num_verts);
        qsort(ids, n, sizeof ids[0], l0_cmp64);
        for (i = 1; i < n; i++) k.bad += ids[i] == ids[i - 1u];
        if (levels == 1u) *hv = h_fnv(*hv, out.pos, (uint32_t)sizeof(subd_real) * 3u * out.num_verts);
    }
    CHECK_EQ(k.bad, 0u);
}

static void sr48l0_stream(void)
{
    static const int shapes[5] = {FX48_TORUS, FX48_GRID, FX48_TWO, FX48_HEXFAN, FX48_BIPYR};
    static const char *const names[5] = {"sr48l0_stream_torus", "sr48l0_stream_grid", "sr48l0_stream_two",
                                         "sr48l0_stream_hexfan", "sr48l0_stream_bipyr12"};
    uint32_t s, l, f, p;
    for (s = 0; s < 5u; s++) {
        uint32_t hv = 2166136261u;
        for (f = 0; f < 2u; f++)
            for (l = 1; l <= (H_HOST ? 3u : 1u); l++)
                for (p = 0; p < 2u; p++) l0_stream_case(shapes[s], l, f ? SUBD_SR48_NO_SMOOTH : 0u, (int)p, &hv);
        h_hash(names[s], hv);
    }
}

/* Counts the triangles a refused stream would emit (none). */
static uint32_t g_l0calls;
static int l0_count(void *ctx, const subd_tri *t)
{
    (void)ctx;
    (void)t;
    g_l0calls++;
    return 0;
}

/* Damage k (0..6) to a copy of base (nb, tv: room for its tri_base_nb and tri_vert), or 0
 * when there is no such damage here. */
static int l0_damage(const subd_sr48 *base, uint32_t k, subd_sr48 *bad, uint32_t *nb, uint32_t *tv, int *want)
{
    const uint32_t n0 = base->level_tri[1];
    uint32_t t;
    *bad = *base;
    for (t = 0; t < n0; t++) nb[t] = base->tri_base_nb[t];
    for (t = 0; t < 3u * n0; t++) tv[t] = base->tri_vert[t];
    *want = SUBD_ERR_PARAM;
    switch (k) {
    case 0: /* a base neighbour that does not point back: itself */
        nb[0] = 0;
        bad->tri_base_nb = nb;
        return 1;
    case 1: /* a base neighbour pointing back across another edge: t's pair partner's */
        for (t = 0; t < n0; t++)
            if (nb[t] != SUBD_NONE && nb[t ^ 1u] != SUBD_NONE && nb[t ^ 1u] != nb[t]) {
                nb[t] = nb[t ^ 1u];
                bad->tri_base_nb = nb;
                return 1;
            }
        return 0;
    case 2: /* a vertex out of range */
        tv[3u * (n0 - 1u) + 2u] = base->num_verts;
        bad->tri_vert = tv;
        return 1;
    case 3: bad->hyb_base_nb = 0; return 1;
    case 4: bad->steps = 1; return 1;
    case 5: /* no triangles */
        bad->num_tris = 0;
        bad->level_tri[1] = 0;
        *want = SUBD_ERR_EMPTY;
        return 1;
    default: /* a census above the largest valence the stream takes */
        bad->stream_valence = SUBD_SR48_STREAM_MAX_VALENCE + 1u;
        *want = SUBD_ERR_TOO_BIG;
        return 1;
    }
}

static void sr48l0_between(void)
{
    static const int shapes[3] = {FX48_TORUS, FX48_GRID, FX48_TWO};
    uint32_t s, k, l;
    for (s = 0; s < 3u; s++)
        for (l = 1; l <= (H_HOST ? 9u : 1u); l += 8u) {
            subd_arena a, sa;
            subd_mesh in;
            subd_sr48 base, bad;
            subd_sr48_stream_opts so;
            subd_diag d;
            subd_tri_sink sink;
            subd_stream str;
            uint32_t plan = 0, p2 = 0, *nb, *tv;
            subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES - L0_ST_ARENA);
            if (!fx_sr48_shape(shapes[s], 12u, &a, &in) || !CHECK_OK(subd_sr48_base(&a, &in, 0u, &base, &d), &d))
                continue;
            nb = (uint32_t *)subd_arena_alloc(&a, 4u * base.level_tri[1]);
            tv = (uint32_t *)subd_arena_alloc(&a, 12u * base.level_tri[1]);
            if (!CHECK(nb != 0 && tv != 0)) continue;
            memset(&so, 0, sizeof so);
            so.adapt.mode = SUBD_SR48_ADAPT_UNIFORM;
            so.adapt.max_level = l;
            if (!CHECK_OK(subd_sr48_stream_plan(&base, &so, &plan, &d), &d) || !CHECK(plan <= L0_ST_ARENA)) continue;
            sink.tri = l0_count;
            sink.ctx = 0;
            for (k = 0; k < 7u; k++) {
                int want, st;
                if (!l0_damage(&base, k, &bad, nb, tv, &want)) continue;
                /* plan on the good base succeeded; the caller damages it, then begins */
                CHECK_FAIL(subd_sr48_stream_plan(&bad, &so, &p2, &d), &d, want);
                subd_arena_init(&sa, h_arena_buf + H_ARENA_BYTES - L0_ST_ARENA, L0_ST_ARENA);
                CHECK_FAIL(subd_sr48_stream_begin(&sa, &bad, &so, &str, &d), &d, want);
                CHECK_EQ(sa.used, 0u);
                g_l0calls = 0;
                st = subd_sr48_stream(&sa, &bad, &so, &sink, &d);
                CHECK_EQ(st, want);
                CHECK_EQ(sa.used, 0u);
                CHECK_EQ(g_l0calls, 0u);
            }
            /* and the good base streams after all that, in its plan */
            subd_arena_init(&sa, h_arena_buf + H_ARENA_BYTES - L0_ST_ARENA, L0_ST_ARENA);
            g_l0calls = 0;
            if (CHECK_OK(subd_sr48_stream(&sa, &base, &so, &sink, &d), &d)) {
                CHECK_EQ(sa.peak, plan);
                CHECK_EQ(g_l0calls, (uint64_t)base.level_tri[1] << l);
            }
        }
}

const test_case suite_sr48_level0[] = {
    {"sr48l0_census", sr48l0_census},
    {"sr48l0_valence", sr48l0_valence},
    {"sr48l0_stream", sr48l0_stream},
    {"sr48l0_between", sr48l0_between},
    {0, 0},
};
