/* SPDX-License-Identifier: MIT */
/* The uniform 4-8 stream's tiles (src/sr48_tile.c): every tile is made first with its
 * windows before the last cropped to ring 1 of the descendants and the partners of its
 * triangles, checked exact before its first triangle leaves, and made again with the two
 * rings of the exactness argument where a position would not be exact. Compared against the
 * materialising calls (subd_sr48_build(steps = L) then subd_sr48_extract(UNIFORM, L)):
 *  - both crops (the smaller ones first, and the two rings alone: S48_TILE_FULL set in the
 *    tile block's counter after the begin call) give the extraction's j-th face as the j-th
 *    triangle, same corners, same position bits, one id per extraction vertex;
 *  - the tiles are counted (the counters of sr48_stream_internal.h): as many as the walk's
 *    closed form (L <= SUBD_SR48_STREAM_TILE_LEVELS: one per hybrid pair, else
 *    n0 2^(L - m - 1) with n0 base triangles), and none made again with the two rings: the
 *    smaller crops were exact on every tile of these shapes - closed and open, extraordinary
 *    vertices of valence 3..16 after pre-processing (bipyramids), a mesh with isolated
 *    triangles, the icosahedron, the torus -, smoothed and not, both arithmetics;
 *  - too small first crops (S48_TILE_TINY: the descendants and their partners) give the same
 *    triangles and bits, and some smoothed tiles are made again: the exactness checks
 *    (subd_s48_last_'s when max_level is even and smoothed, else s48_tile_exact's) fire
 *    where a position would not be exact, rather than let it out;
 *  - shapes scaled to the Q16.16 limit (sr48t_big): the smoothing sums carry;
 *  - float32 shapes scaled to 2^62 and 2^80 (sr48t_range): the windows skip their
 *    finiteness checks below 2^64 (s48_state's l0ok: S48_L0_RANGE, sr48_window.c's header)
 *    and keep them above, the same bits either way; a base moved near 2^127 fails the
 *    stream with SUBD_ERR_RANGE (its sums overflow). Q16.16: every
 *    level-0 window is in range. */
#include "harness.h"
#include "corpus.h"
#include "fixtures.h"
#include "../src/sr48_stream_internal.h"
#if H_HOST
#include <stdio.h>
#define T_NOTE(...) printf(__VA_ARGS__)
#else
#define T_NOTE(...) ((void)0)
#endif

#if H_HOST
#define TL_MAXV 300000u
static uint8_t g_tl_big[48u << 20] __attribute__((aligned(8))); /* hierarchies up to 9 steps */
#define TL_MAT g_tl_big
#define TL_MAT_BYTES ((uint32_t)sizeof g_tl_big)
#define TL_ST (h_arena_buf)
#define TL_ST_BYTES H_ARENA_BYTES
#else
#define TL_MAXV 2048u
#define TL_ST_BYTES (64u * 1024u) /* the stream: the top of h_arena_buf */
#define TL_MAT (h_arena_buf)
#define TL_MAT_BYTES (H_ARENA_BYTES - TL_ST_BYTES)
#define TL_ST (h_arena_buf + TL_MAT_BYTES)
#endif

static uint64_t g_tl_id[TL_MAXV];
static uint32_t g_tl_l0ok; /* s48_state's l0ok, ANDed over the batches of the last stream */
static uint32_t g_tl_tiny; /* tiles made again after too small first crops (S48_TILE_TINY) */
static uint8_t g_tl_have[TL_MAXV];
static subd_tri g_tl_buf[64];

/* The stream of base with max_level L against the extraction out, pulled in batches of 64;
 * full: 1 the two rings alone, 2 too small first crops (S48_TILE_TINY: the exactness checks
 * must send tiles to the two rings). *tiles, *twice: the tile counters after the last
 * triangle. */
static void tl_stream(const subd_sr48 *base, const subd_mesh *out, uint32_t L, int full, uint32_t *tiles,
                      uint32_t *twice)
{
    subd_arena sa;
    subd_stream st;
    subd_diag d;
    subd_sr48_stream_opts so;
    uint32_t j = 0, bad = 0, i, q;
    int got;
    subd_arena_init(&sa, TL_ST, TL_ST_BYTES);
    so.adapt.mode = SUBD_SR48_ADAPT_UNIFORM;
    so.adapt.max_level = L;
    *tiles = 0;
    *twice = 0;
    if (!CHECK_EQ(subd_sr48_stream_begin(&sa, base, &so, &st, &d), SUBD_OK)) return;
    {
        s48_state *s = (s48_state *)st.state_;
        s48_win a;
        if (s->tm > 1u && full) {
            s48_win_at(s, s->ablk, s->aoff, &a);
            a.hd[7] |= full == 1 ? S48_TILE_FULL : S48_TILE_TINY;
        }
    }
    for (i = 0; i < out->num_verts; i++) g_tl_have[i] = 0;
    g_tl_l0ok = 0xffu;
    while ((got = subd_stream_next_tris(&st, g_tl_buf, 64u)) > 0) {
        int k;
        const s48_state *s = (const s48_state *)st.state_;
        g_tl_l0ok &= s->l0ok;
        for (k = 0; k < got; k++, j++) {
            const subd_tri *t = &g_tl_buf[k];
            if (j >= out->num_faces) {
                bad++;
                continue;
            }
            for (i = 0; i < 3u; i++) {
                const uint32_t v = out->corner_vert[3u * j + i];
                for (q = 0; q < 3u; q++)
                    if (!h_same(t->pos[i][q], out->pos[3u * v + q])) bad++;
                if (g_tl_have[v] && g_tl_id[v] != t->id[i]) bad++;
                g_tl_have[v] = 1;
                g_tl_id[v] = t->id[i];
            }
        }
        if (s->tm > 1u) { /* the counters (the state stays in place until the end call) */
            s48_win x, a;
            s48_x(s, &x);
            s48_win_at(s, s->ablk, s->aoff, &a);
            *tiles = x.hd[7];
            *twice = a.hd[7] & ~(S48_TILE_FULL | S48_TILE_TINY);
        }
    }
    CHECK_EQ(got, 0);
    CHECK_EQ(j, out->num_faces);
    CHECK_EQ(bad, 0u);
    for (i = 0; i < out->num_verts; i++) CHECK(g_tl_have[i]);
}

/* The shape's positions scaled so that the largest magnitude is 2^e (float32 only), or
 * (e = 0) near the Q16.16 limit (raw |x| >= 2^30; float: the same numbers), so that
 * smoothing sums of four or more terms leave 32 bits and carry into their high parts
 * (sr48_stream_internal.h's s48_sadd1), upwards and, where the shape has negative
 * coordinates (the icosahedron, the bipyramid), downwards. 0 when the shape has no extent. */
static int tl_scale(subd_mesh *in, uint32_t e)
{
    subd_real mx = 0;
    uint32_t i;
    for (i = 0; i < 3u * in->num_verts; i++) {
        const subd_real v = in->pos[i] < 0 ? -in->pos[i] : in->pos[i];
        if (v > mx) mx = v;
    }
    if (!CHECK(mx > 0)) return 0;
    for (i = 0; i < 3u * in->num_verts; i++) {
#if SUBD_FIXED /* raw * (2^31 - 2^16) / max: |raw| <= 2^31 - 2^16, the largest >= 2^30 */
        (void)e;
        in->pos[i] = (subd_real)(((int64_t)in->pos[i] * 2147418112) / mx);
#else
        subd_real p = 32767.0f;
        if (e) {
            uint32_t j;
            for (p = 1.0f, j = 0; j < e; j++) p *= 2.0f;
        }
        in->pos[i] = in->pos[i] / mx * p;
#endif
    }
    return 1;
}

/* big: 1 the shape scaled to near the Q16.16 limit (tl_scale), 2 + e (float32) to 2^e. */
static void tl_case_s(int shape, uint32_t bn, uint32_t L, uint32_t flags, int big)
{
    subd_arena a;
    subd_mesh in, out;
    subd_sr48 h, base;
    subd_sr48_opts o;
    subd_sr48_adapt ad;
    subd_sr48_adapt_report rep;
    subd_diag d;
    uint32_t tiles, twice, n0, want, m = SUBD_SR48_STREAM_TILE_LEVELS;
    subd_arena_init(&a, TL_MAT, TL_MAT_BYTES);
    if (!fx_sr48_shape(shape, bn, &a, &in)) return;
    if (big && !tl_scale(&in, big >= 2 ? (uint32_t)big - 2u : 0u)) return;
    o.steps = L;
    o.flags = flags;
    if (!CHECK_EQ(subd_sr48_build(&a, &in, &o, &h, &d), SUBD_OK)) return;
    ad.mode = SUBD_SR48_ADAPT_UNIFORM;
    ad.max_level = L;
    if (!CHECK_EQ(subd_sr48_extract(&a, &h, &ad, &out, &rep, &d), SUBD_OK)) return;
    if (!CHECK_EQ(subd_sr48_base(&a, &in, flags, &base, &d), SUBD_OK)) return;
    if (!CHECK(out.num_verts <= TL_MAXV)) return;
    n0 = base.level_tri[1];
    want = L <= 1u ? 0u : L <= m ? n0 / 2u : n0 << (L - m - 1u);
    tl_stream(&base, &out, L, 0, &tiles, &twice);
    CHECK_EQ(tiles, want);
    if (!CHECK_EQ(twice, 0u))
        T_NOTE("shape %d (%u) L %u flags %u: %u of %u tiles made again\n", shape, bn, L, flags, twice, tiles);
    tl_stream(&base, &out, L, 1, &tiles, &twice);
    CHECK_EQ(tiles, want);
    CHECK_EQ(twice, want);
    tl_stream(&base, &out, L, 2, &tiles, &twice);
    CHECK_EQ(tiles, want);
    CHECK(twice <= want);
    g_tl_tiny += twice;
}
static void tl_case(int shape, uint32_t bn, uint32_t L, uint32_t flags) { tl_case_s(shape, bn, L, flags, 0); }

/* Tiles from level 0 over a hybrid pair (L <= m), from level 0 per base triangle (L = m + 1)
 * and below depth-first levels (L = m + 2), where the materialised hierarchy fits. */
static void sr48t_tiles(void)
{
    uint32_t f;
    g_tl_tiny = 0;
    for (f = 0; f < 2u; f++) {
        const uint32_t fl = f ? SUBD_SR48_NO_SMOOTH : 0u;
        uint32_t bn, L;
        for (L = 2; L <= 6u; L++) tl_case(FX48_TWO, 5, L, fl);
        tl_case(FX48_TET, 5, 5, fl);
        tl_case(FX48_HEXFAN, 5, 6, fl);
#if H_HOST
        for (L = 7; L <= 9u; L++) tl_case(FX48_TWO, 5, L, fl);
        tl_case(FX48_ICO, 5, 8, fl);
        tl_case(FX48_GRID, 5, 8, fl);
        tl_case(FX48_TORUS, 5, 7, fl);
        tl_case(FX48_CUBE, 5, 9, fl);
        for (bn = 3; bn <= 16u; bn++) tl_case(FX48_BIPYR, bn, 8, fl);
#else
        (void)bn;
#endif
    }
    /* the checks fired: smoothed tiles from too small crops were made again (and gave the
     * extraction's bits above) */
    CHECK(g_tl_tiny > 0u);
}

/* Coordinates near the Q16.16 limit: the smoothing sums carry into their high parts (every
 * level, the tile's last one included), against the materialised hierarchy's 64-bit sums. */
static void sr48t_big(void)
{
    uint32_t f;
    for (f = 0; f < 2u; f++) {
        const uint32_t fl = f ? SUBD_SR48_NO_SMOOTH : 0u;
        tl_case_s(FX48_TWO, 5, 4, fl, 1);
        tl_case_s(FX48_HEXFAN, 5, 6, fl, 1);
#if H_HOST
        tl_case_s(FX48_ICO, 5, 8, fl, 1);
        tl_case_s(FX48_BIPYR, 7, 8, fl, 1);
        tl_case_s(FX48_TORUS, 5, 7, fl, 1);
#endif
    }
}

/* The finiteness checks (sr48_window.c's header): skipped where the level-0 window is in
 * range, the same bits as the materialised hierarchy's either way; and an overflow still
 * fails the stream with SUBD_ERR_RANGE. */
static void sr48t_range(void)
{
#if SUBD_FIXED /* no checks: every level-0 window in range */
    tl_case_s(FX48_TWO, 5, 4, 0u, 1);
    CHECK(g_tl_l0ok & S48_L0_RANGE);
#else
    uint32_t f;
    for (f = 0; f < 2u; f++) {
        const uint32_t fl = f ? SUBD_SR48_NO_SMOOTH : 0u;
        tl_case_s(FX48_HEXFAN, 5, 6, fl, 2 + 62); /* below 2^64: no checks */
        CHECK(g_tl_l0ok & S48_L0_RANGE);
        tl_case_s(FX48_HEXFAN, 5, 6, fl, 2 + 80); /* above: checked, nothing fires */
        CHECK(!(g_tl_l0ok & S48_L0_RANGE));
#if H_HOST
        tl_case_s(FX48_ICO, 5, 8, fl, 2 + 62);
        CHECK_EQ(g_tl_l0ok, S48_L0_RANGE | S48_L0_CLOSED);
        tl_case_s(FX48_ICO, 5, 8, fl, 2 + 80);
        CHECK_EQ(g_tl_l0ok, S48_L0_CLOSED);
#endif
    }
    { /* the base's positions moved to 1.5 2^126 (1 + x 2^-6), x the shape's in [-1, 1]
       * (after subd_sr48_base, whose own pre-processing would overflow): every smoothing
       * sum overflows, and the stream fails with SUBD_ERR_RANGE (the checks are kept) */
        subd_arena a, sa;
        subd_mesh in;
        subd_sr48 base;
        subd_sr48_stream_opts so;
        subd_stream st;
        subd_diag d;
        subd_real p = 1.5f, *bp;
        uint32_t i;
        int got;
        subd_arena_init(&a, TL_MAT, TL_MAT_BYTES);
        if (!fx_sr48_shape(FX48_HEXFAN, 5, &a, &in) || !tl_scale(&in, 0u)) return;
        if (!CHECK_EQ(subd_sr48_base(&a, &in, 0u, &base, &d), SUBD_OK)) return;
        for (i = 0; i < 126u; i++) p *= 2.0f;
        bp = base.pos;
        for (i = 0; i < 3u * base.num_verts; i++) bp[i] = p + bp[i] / 32767.0f * (p / 64.0f);
        subd_arena_init(&sa, TL_ST, TL_ST_BYTES);
        so.adapt.mode = SUBD_SR48_ADAPT_UNIFORM;
        so.adapt.max_level = 4;
        if (!CHECK_EQ(subd_sr48_stream_begin(&sa, &base, &so, &st, &d), SUBD_OK)) return;
        while ((got = subd_stream_next_tris(&st, g_tl_buf, 64u)) > 0) continue;
        subd_stream_end(&st);
        CHECK_EQ(got, SUBD_ERR_RANGE);
    }
#endif
}

const test_case suite_sr48_tiles[] = {
    {"sr48t_tiles", sr48t_tiles},
    {"sr48t_big", sr48t_big},
    {"sr48t_range", sr48t_range},
    {0, 0},
};
