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
 *    the valence walk, or refuses the base with the same status. */
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

const test_case suite_sr48_level0[] = {
    {"sr48l0_census", sr48l0_census},
    {"sr48l0_valence", sr48l0_valence},
    {0, 0},
};
