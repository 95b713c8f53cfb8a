/* SPDX-License-Identifier: MIT */
/* Streaming Loop (subd_loop_stream) against the materialising call, subd_loop: on every corpus
 * shape (closed, open, creases, corners, valence 3 and >= 12, isolated vertices), levels 1..4,
 * both boundary rules, the j-th streamed triangle must be subd_loop's face j with the same
 * corners, bit-identical positions, and ids that map one-to-one onto subd_loop's vertices
 * (checked both ways: one id per vertex, one vertex per id) and follow the documented closed
 * form for control vertices. Plus: the plan depends on levels and valence only and equals
 * SUBD_LOOP_STREAM_BYTES; every smaller arena fails with SUBD_ERR_NOMEM before anything is
 * emitted; a sink that stops after k triangles gets k and its status back; the windows (the
 * last three levels of the patches the tiles refuse) are made where the tile counts leave
 * them, and their triangles pulled in odd batches equal subd_loop's. The regular tiles
 * (lattice refinement next to the general path) are test_loop_tiles.c's; the comparison both
 * use is loop_cmp.c's. */
#include "harness.h"
#include "loop_cmp.h"
#include "../src/loop_stream_internal.h"

static void stream_equals_loop(void)
{
    int id;
    uint32_t hash = 2166136261u, lim;
    lc_streams = lc_skipped = 0;
    for (id = 0; id < (H_HOST ? S_COUNT : S_DEVICE); id++) {
        subd_arena a;
        subd_mesh in;
        uint32_t levels;
        subd_arena_init(&a, CMP_BUF, CMP_BYTES);
        if (!lc_make_shape(id, &a, &in)) return;
        for (lim = 0; lim < 2u; lim++)
            for (levels = 1; levels <= (lim ? 3u : 4u); levels++) {
                lc_compare_one(&a, &in, levels, SUBD_LOOP_BOUNDARY_PAPER, lim ? SUBD_LOOP_STREAM_LIMIT : 0u, &hash);
                lc_compare_one(&a, &in, levels, SUBD_LOOP_BOUNDARY_BSPLINE, lim ? SUBD_LOOP_STREAM_LIMIT : 0u, &hash);
            }
    }
    CHECK(lc_streams >= (H_HOST ? 126u : 60u)); /* the host runs every case; say how many */
    h_str("  streams compared ");
    h_u32(lc_streams);
    h_str(", skipped (subd_loop's output too big for the test arena) ");
    h_u32(lc_skipped);
    h_nl();
}

/* Streamed positions are hashed per arithmetic; host and QEMU must print the same. */
static void stream_hashes(void)
{
    int id;
    for (id = 0; id < S_DEVICE; id++) {
        subd_arena a;
        subd_mesh in;
        uint32_t hash = 2166136261u;
        static const char *const names[] = {"stream_tet", "stream_cube_crease", "stream_ico", "stream_hexfan",
                                            "stream_fan64", "stream_grid_crease", "stream_iso"};
        subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
        if (!lc_make_shape(id, &a, &in)) return;
        lc_compare_one(&a, &in, 2, SUBD_LOOP_BOUNDARY_PAPER, 0, &hash);
        lc_compare_one(&a, &in, 3, SUBD_LOOP_BOUNDARY_BSPLINE, 0, &hash);
        lc_compare_one(&a, &in, 2, SUBD_LOOP_BOUNDARY_PAPER, SUBD_LOOP_STREAM_LIMIT, &hash);
        h_hash(names[id], hash);
    }
}

/* The plan is a function of levels and valence: equal for two meshes with the same largest
 * valence, equal to the macro, growing with both, and under 16 KiB at 8 levels, valence 16. */
static void stream_plan(void)
{
    subd_arena a;
    subd_mesh ico, tet, cube, fan;
    subd_loop_opts o;
    subd_diag d0;
    uint32_t l, n, p1, p2;
    subd_diag_clear(&d0);
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    if (!lc_make_shape(S_ICO, &a, &ico) || !lc_make_shape(S_TET, &a, &tet) || !lc_make_shape(S_CUBE_CREASE, &a, &cube) ||
        !lc_make_shape(S_FAN64, &a, &fan))
        return;
    o.boundary = SUBD_LOOP_BOUNDARY_PAPER;
    o.flags = 0;
    for (l = 1; l <= SUBD_MAX_LEVELS; l++) {
        o.levels = l;
        /* icosahedron (valence 5), tetrahedron (3) and the cube (4, 5, 6): all below 6 or at 6 */
        CHECK_OK(subd_loop_stream_plan(&ico, &o, &p1, 0), &d0);
        CHECK_OK(subd_loop_stream_plan(&tet, &o, &p2, 0), &d0);
        CHECK_EQ(p1, p2);
        CHECK_EQ(p1, SUBD_LOOP_STREAM_BYTES(l, 6));
        o.flags = SUBD_LOOP_STREAM_LIMIT;
        CHECK_OK(subd_loop_stream_plan(&tet, &o, &p2, 0), &d0);
        CHECK_EQ(p2, SUBD_LOOP_STREAM_BYTES_LIMIT(l, 6));
        /* limit mode keeps level L-1 and L, a mesh view and the masks' caches; its tile
         * (SUBD_LOOP_TILE_LEVELS_LIMIT) may be smaller, so the plans compare only without
         * tiles (one level) */
        if (l == 1u) CHECK(p2 > p1);
        o.flags = 0;
        CHECK_OK(subd_loop_stream_plan(&cube, &o, &p2, 0), &d0);
        CHECK_EQ(p2, p1);
        CHECK_OK(subd_loop_stream_plan(&fan, &o, &p2, 0), &d0); /* centre valence 64 */
        CHECK_EQ(p2, SUBD_LOOP_STREAM_BYTES(l, 64));
        CHECK(p2 > p1);
    }
    for (n = 6; n <= 64u; n++) CHECK(SUBD_LOOP_STREAM_BYTES(4, n) < SUBD_LOOP_STREAM_BYTES(4, n + 1u));
    CHECK(SUBD_LOOP_STREAM_BYTES(8, 16) <= 16u * 1024u);
    CHECK(SUBD_LOOP_STREAM_BYTES_LIMIT(8, 16) <= 16u * 1024u); /* the tile shares the idle levels' memory */
    h_str("  plan bytes, 8 levels: valence 6 ");
    h_u32(SUBD_LOOP_STREAM_BYTES(8, 6));
    h_str(", 16 ");
    h_u32(SUBD_LOOP_STREAM_BYTES(8, 16));
    h_str(", 32 ");
    h_u32(SUBD_LOOP_STREAM_BYTES(8, 32));
    h_nl();
}


/* Every arena below the plan: SUBD_ERR_NOMEM, diag.bytes_needed = plan, nothing emitted, the
 * arena as before; the plan itself succeeds. */
static void stream_small_arenas(void)
{
    subd_arena a, small;
    subd_mesh in;
    subd_loop_opts o;
    subd_loop_sink sink;
    subd_diag d;
    uint32_t plan, size, count = 0;
    uint8_t *buf;
    subd_diag_clear(&d);
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    if (!lc_make_shape(S_CUBE_CREASE, &a, &in)) return;
    o.levels = 3;
    o.boundary = SUBD_LOOP_BOUNDARY_PAPER;
    o.flags = 0;
    if (!CHECK_OK(subd_loop_stream_plan(&in, &o, &plan, 0), &d)) return;
    buf = (uint8_t *)subd_arena_alloc(&a, plan);
    if (!CHECK(buf != 0)) return;
    sink.tri = lc_count_tri;
    sink.ctx = &count;
    for (size = 0; size < plan; size++) {
        subd_arena_init(&small, buf, size);
        if (!CHECK_FAIL(subd_loop_stream(&small, &in, &o, &sink, &d), &d, SUBD_ERR_NOMEM)) break;
        if (!CHECK_EQ(d.bytes_needed, plan) || !CHECK_EQ(small.used, 0) || !CHECK_EQ(count, 0)) break;
    }
    subd_arena_init(&small, buf, plan);
    CHECK_OK(subd_loop_stream(&small, &in, &o, &sink, &d), &d);
    CHECK_EQ(count, 12u * 64u);
    CHECK_EQ(small.used, 0);
    CHECK_EQ(small.peak, plan);
}

/* A sink that stops after k triangles gets exactly k, and its value comes back. */
static void stream_sink_stop(void)
{
    subd_arena a;
    subd_mesh in, ref;
    subd_loop_opts o;
    subd_loop_sink sink;
    subd_diag d;
    cmp_sink s;
    uint64_t ids[1];
    uint32_t k;
    static const uint32_t stops[] = {1, 2, 5, 16, 17, 63, 64, 65, 300};
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    if (!lc_make_shape(S_ICO, &a, &in)) return;
    o.levels = 2;
    o.boundary = SUBD_LOOP_BOUNDARY_PAPER;
    o.flags = 0;
    if (!CHECK_OK(subd_loop(&a, &in, &o, &ref, &d), &d)) return;
    (void)ids;
    for (k = 0; k < sizeof stops / sizeof stops[0]; k++) {
        uint64_t *v2id = (uint64_t *)subd_arena_alloc(&a, ref.num_verts * 8u);
        uint32_t mark;
        if (!CHECK(v2id != 0)) return;
        lc_sink_init(&s, &sink, &ref, v2id, stops[k], 0);
        mark = subd_arena_mark(&a);
        CHECK_EQ(subd_loop_stream(&a, &in, &o, &sink, &d), 7);
        CHECK_EQ(d.face, (stops[k] - 1u) / 16u); /* 16 triangles per control face */
        CHECK_EQ(s.j, stops[k]);
        CHECK_EQ(s.bad_pos, 0);
        CHECK_EQ(subd_arena_mark(&a), mark);
        subd_arena_rewind(&a, mark - ((ref.num_verts * 8u + SUBD_ARENA_ALIGN - 1u) & ~(SUBD_ARENA_ALIGN - 1u)));
    }
}

/* Bad arguments and inputs: the specific status, nothing emitted, arena unchanged. */
static void stream_errors(void)
{
    subd_arena a;
    subd_mesh in, quad, noadj;
    subd_loop_opts o;
    subd_loop_sink sink, nosink;
    subd_diag d;
    uint32_t count = 0, mark, plan;
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    if (!lc_make_shape(S_ICO, &a, &in) || !lc_load_file(&a, "test/data/cube_quad.obj", &quad)) return;
    o.levels = 2;
    o.boundary = SUBD_LOOP_BOUNDARY_PAPER;
    o.flags = 0;
    sink.tri = lc_count_tri;
    sink.ctx = &count;
    nosink.tri = 0;
    nosink.ctx = 0;
    mark = subd_arena_mark(&a);
    CHECK_FAIL(subd_loop_stream(0, &in, &o, &sink, &d), &d, SUBD_ERR_PARAM);
    CHECK_FAIL(subd_loop_stream(&a, 0, &o, &sink, &d), &d, SUBD_ERR_PARAM);
    CHECK_FAIL(subd_loop_stream(&a, &in, 0, &sink, &d), &d, SUBD_ERR_PARAM);
    CHECK_FAIL(subd_loop_stream(&a, &in, &o, 0, &d), &d, SUBD_ERR_PARAM);
    CHECK_FAIL(subd_loop_stream(&a, &in, &o, &nosink, &d), &d, SUBD_ERR_PARAM);
    CHECK_EQ(subd_loop_stream_plan(&in, &o, 0, 0), SUBD_ERR_PARAM);
    o.levels = 0;
    CHECK_FAIL(subd_loop_stream(&a, &in, &o, &sink, &d), &d, SUBD_ERR_PARAM);
    CHECK_EQ(subd_loop_stream_plan(&in, &o, &plan, 0), SUBD_ERR_PARAM);
    o.levels = SUBD_MAX_LEVELS + 1u;
    CHECK_FAIL(subd_loop_stream(&a, &in, &o, &sink, &d), &d, SUBD_ERR_PARAM);
    o.levels = 2;
    o.boundary = (subd_loop_boundary)7;
    CHECK_FAIL(subd_loop_stream(&a, &in, &o, &sink, &d), &d, SUBD_ERR_PARAM);
    o.boundary = SUBD_LOOP_BOUNDARY_PAPER;
    o.flags = SUBD_LOOP_ADJACENCY;
    CHECK_FAIL(subd_loop_stream(&a, &in, &o, &sink, &d), &d, SUBD_ERR_PARAM);
    o.flags = 0;
    CHECK_FAIL(subd_loop_stream(&a, &quad, &o, &sink, &d), &d, SUBD_ERR_NOT_TRIANGLES);
    CHECK_EQ(d.face, 0);
    noadj = in;
    noadj.twin = 0;
    CHECK_FAIL(subd_loop_stream(&a, &noadj, &o, &sink, &d), &d, SUBD_ERR_PARAM);
    CHECK_EQ(count, 0);
    CHECK_EQ(subd_arena_mark(&a), mark);
}

/* A sum that rounds above the float range: a closed bipyramid (apex valence 7) with every
 * coordinate at SUBD_REAL_MAX. The stream must fail where subd_loop fails (float32:
 * SUBD_ERR_RANGE, diag.face set; Q16.16: both succeed, the weights sum to one exactly), with
 * the arena mark unchanged. */
static void stream_range(void)
{
    static uint32_t idx[6u * 7u];
    subd_real pos[3u * 9u];
    subd_face_list fl = {9, 0, 14, 0, idx, 0, 0, 0};
    subd_arena a;
    subd_mesh in, out;
    subd_loop_opts o = {1, SUBD_LOOP_BOUNDARY_PAPER, 0};
    subd_loop_sink sink;
    subd_diag d;
    uint32_t k, count = 0, mark;
    int want;
    for (k = 0; k < 7u; k++) {
        uint32_t e = 2u + k, e1 = 2u + (k + 1u) % 7u;
        idx[6u * k] = 0; idx[6u * k + 1u] = e; idx[6u * k + 2u] = e1;
        idx[6u * k + 3u] = 1; idx[6u * k + 4u] = e1; idx[6u * k + 5u] = e;
    }
    for (k = 0; k < 27u; k++) pos[k] = SUBD_REAL_MAX;
    fl.pos = pos;
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    if (!h_build(&a, &fl, &in)) return;
    mark = subd_arena_mark(&a);
    want = subd_loop(&a, &in, &o, &out, &d);
    CHECK_EQ(want, SUBD_FIXED ? SUBD_OK : SUBD_ERR_RANGE);
    subd_arena_rewind(&a, mark);
    sink.tri = lc_count_tri;
    sink.ctx = &count;
    CHECK_EQ(subd_loop_stream(&a, &in, &o, &sink, &d), want);
    CHECK_EQ(subd_arena_mark(&a), mark);
    if (want != SUBD_OK) CHECK(d.face < in.num_faces);
    else CHECK_EQ(count, 4u * in.num_faces);
}

/* ------------------------------------------------------------------------------------ */
/* Regular tiles (src/loop_tile.c) meeting irregular patches                              */

/* A disk cut from the nefertiti scan (test/data/nefertiti_patch.obj: 115 vertices, interior
 * valences 4..10, a boundary of 38): almost every patch takes the general path (the ring
 * walks of the vertex points, the control patch's look-up hints, whose 64 entries the
 * vertex and face indices overflow, the grandchildren pushed to the sink), next to regular
 * children tiled one level down. The stream equals subd_loop bit for bit, ids included
 * (levels 1..4, levels 1..3 with the B-spline boundary rule; the device compares what its
 * test arena holds), and a sink that stops inside the grandchildren gets exactly its
 * triangles (level 3, the device level 2). */
static void stream_irregular(void)
{
    uint32_t hash = 2166136261u, levels, k, g0 = lc_streams;
    subd_arena a;
    subd_mesh in;
    subd_diag d;
    static const uint32_t stops[] = {1, 15, 16, 17, 250};
    subd_diag_clear(&d);
    subd_arena_init(&a, CMP_BUF, CMP_BYTES);
    if (!lc_load_file(&a, "test/data/nefertiti_patch.obj", &in)) return;
    CHECK_EQ(in.num_verts, 115u);
    for (levels = 1; levels <= 4u; levels++) {
        lc_compare_one(&a, &in, levels, SUBD_LOOP_BOUNDARY_PAPER, 0u, &hash);
        if (levels <= 3u) lc_compare_one(&a, &in, levels, SUBD_LOOP_BOUNDARY_BSPLINE, 0u, &hash);
    }
    for (k = 0; k < sizeof stops / sizeof stops[0]; k++) {
        subd_loop_opts o;
        subd_loop_sink sink;
        uint32_t mark = subd_arena_mark(&a);
        cmp_sink s;
        subd_mesh ref;
        uint64_t *v2id;
        o.levels = H_HOST ? 3u : 2u; /* the device's test arena holds subd_loop's level 2 */
        o.boundary = SUBD_LOOP_BOUNDARY_PAPER;
        o.flags = 0;
        if (!CHECK_OK(subd_loop(&a, &in, &o, &ref, &d), &d)) return;
        v2id = (uint64_t *)subd_arena_alloc(&a, ref.num_verts * 8u);
        if (!CHECK(v2id != 0)) return;
        lc_sink_init(&s, &sink, &ref, v2id, stops[k], 0);
        CHECK_EQ(subd_loop_stream(&a, &in, &o, &sink, &d), 7);
        CHECK_EQ(d.face, (stops[k] - 1u) >> (2u * o.levels)); /* 4^L triangles per control face */
        CHECK_EQ(s.j, stops[k]);
        CHECK_EQ(s.bad_pos, 0);
        CHECK_EQ(s.bad_id, 0);
        subd_arena_rewind(&a, mark);
    }
    h_str("  irregular disk: streams compared ");
    h_u32(lc_streams - g0);
    h_nl();
    (void)hash;
}

/* The windows (loop_stream.c: from 3 levels on, a patch of level L-3 the tiles refuse makes
 * its last three levels from the union of its children's 1-rings): each control face is a
 * tile of depth L or refined, each level-k patch below it (k <= L-3) a tile of depth L - k or
 * refined, and each refined level L-3 patch one window, so the pull form's window count must
 * be what the tile counts leave (and not zero: every shape here has irregular vertices). On
 * the host the pulled triangles (batches of 7, so a batch ends inside a window's children)
 * are compared with subd_loop's output, which the device's test arena cannot hold. Shapes:
 * the irregular disk (boundary, valences 4-8), the creased cube (creases, corners), the
 * creased grid (boundary with creases) and the valence-64 fan (a level-0 window with a large
 * corner). */
static void stream_windows(void)
{
    int sh;
    uint32_t levels, made = 0, fails = 0;
    static const int shapes[] = {-1, S_CUBE_CREASE, S_GRID_CREASE, S_FAN64};
    for (sh = 0; sh < 4; sh++)
        for (levels = 3; levels <= (H_HOST ? 5u : 3u); levels++) {
            subd_arena a;
            subd_mesh in;
            subd_loop_opts o;
            subd_stream h;
            subd_diag d;
            static subd_tri buf[7]; /* static: off the device's stack */
            uint32_t n = 0, rem, k, w = 0, cmp = 0;
            int r;
#if H_HOST
            subd_mesh ref;
            subd_loop_sink sink;
            cmp_sink cs;
            uint64_t *v2id = 0;
#endif
            subd_diag_clear(&d);
            subd_arena_init(&a, CMP_BUF, CMP_BYTES);
            if (shapes[sh] < 0 ? !lc_load_file(&a, "test/data/nefertiti_patch.obj", &in) : !lc_make_shape(shapes[sh], &a, &in))
                return;
            o.levels = levels;
            o.boundary = (levels & 1u) ? SUBD_LOOP_BOUNDARY_PAPER : SUBD_LOOP_BOUNDARY_BSPLINE;
            o.flags = 0;
#if H_HOST
            if (levels <= 4u) { /* subd_loop's level 5 of the fan is more than the comparison needs */
                if (!CHECK_OK(subd_loop(&a, &in, &o, &ref, &d), &d)) return;
                v2id = (uint64_t *)subd_arena_alloc(&a, ref.num_verts * 8u);
                if (!CHECK(v2id != 0)) return;
                lc_sink_init(&cs, &sink, &ref, v2id, 0, 0);
                cmp = 1;
            }
#endif
            if (!CHECK_OK(subd_loop_stream_begin(&a, &in, &o, &h, &d), &d)) return;
            while ((r = subd_stream_next_tris(&h, buf, 7u)) > 0) {
#if H_HOST
                if (cmp)
                    for (k = 0; k < (uint32_t)r; k++) (void)lc_cmp_tri(&cs, &buf[k]);
#endif
                n += (uint32_t)r;
                if (n == in.num_faces << (2u * levels)) w = subd_ls_stream_windows(&h); /* before the end */
            }
            CHECK_EQ(r, 0);
            CHECK_EQ(n, in.num_faces << (2u * levels));
            /* the patches the tiles leave at level L-3 (tiles of depth L - k at level k) */
            rem = in.num_faces;
            for (k = 0; k + 3u <= levels; k++) {
                rem -= subd_lt_stream_count(&h, levels - k);
                if (k + 3u < levels) rem *= 4u;
            }
            subd_stream_end(&h);
            if (w != rem) fails++;
            if (w == 0u) fails++;
            made += w;
#if H_HOST
            if (cmp) {
                CHECK_EQ(cs.j, ref.num_faces);
                CHECK_EQ(cs.bad_pos, 0);
                CHECK_EQ(cs.bad_id, 0);
            }
#else
            (void)cmp;
#endif
        }
    CHECK_EQ(fails, 0);
    h_str("  windows made ");
    h_u32(made);
    h_nl();
}

const test_case suite_loop_stream[] = {
    {"stream_equals_loop", stream_equals_loop},
    {"stream_hashes", stream_hashes},
    {"stream_plan", stream_plan},
    {"stream_small_arenas", stream_small_arenas},
    {"stream_sink_stop", stream_sink_stop},
    {"stream_errors", stream_errors},
    {"stream_range", stream_range},
    {"stream_irregular", stream_irregular},
    {"stream_windows", stream_windows},
    {0, 0},
};
