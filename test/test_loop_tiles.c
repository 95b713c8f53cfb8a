/* SPDX-License-Identifier: MIT */
/* Streaming Loop's regular tiles (src/loop_tile.c: the last levels of a regular patch
 * refined breadth first on a lattice) against subd_loop / subd_loop_limit bit for bit (the
 * comparison of loop_cmp.c): grids with a flipped quad (valence 5 and 7 next to regular
 * regions), creases crossing regular regions, a boundary; tile counts against an
 * independent brute-force regularity test; huge coordinates (the general path); level 6;
 * partial tiles next to irregular vertices; limit mode's 5-level tiles made by sixteenths,
 * pulled in batches against the push form. */
#include "loop_cmp.h"
#include "../src/loop_tile.h"

/* An n x n grid of quads split along one diagonal (interior valence 6, a boundary), with
 * heights that vary (exact in both arithmetics); `flip`: the middle quad split along the
 * other diagonal (two valence-5 and two valence-7 vertices next to regular regions);
 * `crease`: the horizontal edges of row n/2 tagged crease (a crease across a regular
 * region, ending at the boundary). */
static int make_grid(subd_arena *a, uint32_t n, int flip, int crease, subd_mesh *m)
{
    static uint32_t idx[6u * 8u * 8u];
    static subd_real pos[3u * 9u * 9u];
    subd_face_list fl = {0, 0, 0, 0, idx, 0, 0, 0};
    uint32_t i, j, k = 0, h;
    for (j = 0; j <= n; j++)
        for (i = 0; i <= n; i++) {
            uint32_t v = j * (n + 1u) + i;
            pos[3u * v] = SUBD_REAL_FRAC((int32_t)i, 1);
            pos[3u * v + 1u] = SUBD_REAL_FRAC((int32_t)j, 1);
            pos[3u * v + 2u] = SUBD_REAL_FRAC((int32_t)((i * 7u + j * 3u) % 5u), 4);
        }
    for (j = 0; j < n; j++)
        for (i = 0; i < n; i++) {
            uint32_t va = j * (n + 1u) + i, vb = va + 1u, vc = va + n + 2u, vd = va + n + 1u;
            if (flip && i == n / 2u && j == n / 2u) {
                idx[k++] = va; idx[k++] = vb; idx[k++] = vd;
                idx[k++] = vb; idx[k++] = vc; idx[k++] = vd;
            } else {
                idx[k++] = va; idx[k++] = vb; idx[k++] = vc;
                idx[k++] = va; idx[k++] = vc; idx[k++] = vd;
            }
        }
    fl.num_verts = (n + 1u) * (n + 1u);
    fl.pos = pos;
    fl.num_faces = 2u * n * n;
    if (!h_build(a, &fl, m)) return 0;
    if (crease)
        for (h = 0; h < m->num_corners; h++) {
            uint32_t u = m->corner_vert[h], w = m->corner_vert[h % 3u == 2u ? h - 2u : h + 1u];
            if (u / (n + 1u) == n / 2u && w / (n + 1u) == n / 2u) subd_edge_tag_set(m, h, SUBD_ETAG_CREASE);
        }
    return 1;
}

/* Brute force: control face f can start a tile (loop_tile.c's "regular"): each corner in
 * exactly six faces, every half-edge from it with a twin and no crease on either half, no
 * CORNER tag; and the faces that touch f are 13 with 12 vertices in all. */
static int brute_regular(const subd_mesh *m, uint32_t f)
{
    uint32_t c, g, h, k, nf = 0, nv = 0, vs[64];
    for (c = 0; c < 3u; c++) {
        uint32_t v = m->corner_vert[3u * f + c], deg = 0;
        if (m->vert_tag[v] & SUBD_VTAG_CORNER) return 0;
        for (h = 0; h < m->num_corners; h++) {
            if (m->corner_vert[h] != v) continue;
            deg++;
            if (m->twin[h] == SUBD_NONE || m->twin[h % 3u == 0u ? h + 2u : h - 1u] == SUBD_NONE) return 0;
            if ((m->edge_tag[h] | m->edge_tag[m->twin[h]]) & SUBD_ETAG_CREASE) return 0;
        }
        if (deg != 6u) return 0;
    }
    for (g = 0; g < m->num_faces; g++) {
        int touch = 0;
        for (c = 0; c < 3u; c++)
            for (k = 0; k < 3u; k++)
                if (m->corner_vert[3u * g + c] == m->corner_vert[3u * f + k]) touch = 1;
        if (!touch) continue;
        nf++;
        for (c = 0; c < 3u; c++) {
            uint32_t v = m->corner_vert[3u * g + c], seen = 0;
            for (k = 0; k < nv; k++)
                if (vs[k] == v) seen = 1;
            if (!seen && nv < 64u) vs[nv++] = v;
        }
    }
    return nf == 13u && nv == 12u;
}

/* subd_lt_start on every control face's patch agrees with brute_regular; returns the number
 * of regular faces. */
static uint32_t count_tiles(subd_arena *a, const subd_mesh *m)
{
    uint32_t off[A_N], bytes = subd_lp_level_layout(3u * 16u, 0, 1, off), f, n = 0, mark = subd_arena_mark(a);
    uint8_t *blk = (uint8_t *)subd_arena_alloc(a, bytes), *tb = (uint8_t *)subd_arena_alloc(a, subd_lt_layout(4u, 0, 0));
    sp_head head;
    sp_level p;
    lt_tile tl;
    loop_wcache wc;
    subd_real org[3];
    uint32_t ovf = 0;
    if (!CHECK(blk != 0 && tb != 0)) return 0;
    wc.have = 0;
    p.h = &head;
    subd_lp_level_bind(blk, off, &p); /* the library's carve (loop_patch.c) */
    p.cpos = 0; /* a control patch without the cache */
    p.cflag = 0;
    subd_lt_carve(&tl, tb, 0, 4u, 0); /* subd_lt_start needs no table */
    for (f = 0; f < m->num_faces; f++) {
        int r;
        subd_lp_build_control(m, f, &p, 4u);
        r = subd_lt_start(&tl, &p, &wc, &ovf, org);
        CHECK_EQ(r, brute_regular(m, f));
        n += (uint32_t)r;
    }
    CHECK_EQ(ovf, 0);
    subd_arena_rewind(a, mark);
    return n;
}

/* Tiles next to a valence-5 and a valence-7 vertex, across a crease, along a boundary, and
 * (host) at level 6: the stream equals subd_loop bit for bit, both rules; the tile test
 * agrees with the brute-force one and finds both kinds of patch. Levels 2-3 (tiles of 2 and
 * 3 levels at level 0) also on the device, with a hash; 4-5 (tiles of 4 and 5 levels at
 * level 0) and the icosahedron at level 6 (tiles at level 1, next to its valence-5
 * vertices) on the host; the grids at level 6: stream_level6; the torus is regular
 * everywhere (every control face starts a tile at level 0). */
static void stream_tiles(void)
{
    uint32_t hash = 2166136261u, id, levels, nreg;
    lc_streams = lc_skipped = 0;
    for (id = 0; id < 2u; id++) {
        subd_arena a;
        subd_mesh in;
        subd_arena_init(&a, CMP_BUF, CMP_BYTES);
        if (!make_grid(&a, 6u, id == 0u, id == 1u, &in)) return;
        nreg = count_tiles(&a, &in);
        CHECK(nreg > 0u && nreg < in.num_faces);
        for (levels = 2; levels <= 3u; levels++) {
            lc_compare_one(&a, &in, levels, SUBD_LOOP_BOUNDARY_PAPER, 0, &hash);
            lc_compare_one(&a, &in, levels, SUBD_LOOP_BOUNDARY_BSPLINE, 0, &hash);
        }
    }
    h_hash("stream_tiles", hash);
#if H_HOST
    for (id = 0; id < 2u; id++) {
        subd_arena a;
        subd_mesh in;
        subd_arena_init(&a, CMP_BUF, CMP_BYTES);
        if (!make_grid(&a, 6u, id == 0u, id == 1u, &in)) return;
        for (levels = 4; levels <= 5u; levels++) {
            lc_compare_one(&a, &in, levels, SUBD_LOOP_BOUNDARY_PAPER, 0, &hash);
            lc_compare_one(&a, &in, levels, SUBD_LOOP_BOUNDARY_BSPLINE, 0, &hash);
        }
    }
    {
        subd_arena a;
        subd_mesh in;
        subd_arena_init(&a, CMP_BUF, CMP_BYTES);
        if (!lc_make_shape(S_ICO, &a, &in)) return;
        lc_compare_one(&a, &in, 6, SUBD_LOOP_BOUNDARY_PAPER, 0, &hash);
        subd_arena_init(&a, CMP_BUF, CMP_BYTES);
        if (!lc_make_shape(S_TORUS, &a, &in)) return;
        CHECK_EQ(count_tiles(&a, &in), in.num_faces); /* valence 6 everywhere */
        lc_compare_one(&a, &in, 4, SUBD_LOOP_BOUNDARY_PAPER, 0, &hash);
    }
    CHECK_EQ(lc_skipped, 0);
    CHECK_EQ(lc_streams, 8u + 2u * 4u + 2u); /* level 6 of the grids: stream_level6 */
#else
    CHECK_EQ(lc_streams + lc_skipped, 8u);
#endif
    h_str("  tile streams compared ");
    h_u32(lc_streams);
    h_str(", skipped ");
    h_u32(lc_skipped);
    h_nl();
}

/* Limit mode on regular tiles (loop_tile.c's lt_limit_quarter): limit positions and normals
 * equal subd_loop_limit of subd_loop's output bit for bit where tiles meet a valence-5 and a
 * valence-7 vertex, a crease across a regular region and a boundary, both rules: level 2
 * (tiles of 2 levels at level 0) on the device too, with a hash; on the host levels 3-5
 * (tiles of 3 and 4 levels at level 0, 4 at level 1), the icosahedron at level 6 (tiles at
 * level 2, next to its valence-5 vertices), and the torus at level 4 (tiles everywhere); the
 * grids at level 6: stream_level6. */
static void stream_tiles_limit(void)
{
    uint32_t hash = 2166136261u, id;
    lc_streams = lc_skipped = 0;
    for (id = 0; id < 2u; id++) {
        subd_arena a;
        subd_mesh in;
        subd_arena_init(&a, CMP_BUF, CMP_BYTES);
        if (!make_grid(&a, 6u, id == 0u, id == 1u, &in)) return;
        lc_compare_one(&a, &in, 2, SUBD_LOOP_BOUNDARY_PAPER, SUBD_LOOP_STREAM_LIMIT, &hash);
        lc_compare_one(&a, &in, 2, SUBD_LOOP_BOUNDARY_BSPLINE, SUBD_LOOP_STREAM_LIMIT, &hash);
    }
    h_hash("stream_tiles_limit", hash);
#if H_HOST
    for (id = 0; id < 2u; id++) {
        subd_arena a;
        subd_mesh in;
        uint32_t levels;
        subd_arena_init(&a, CMP_BUF, CMP_BYTES);
        if (!make_grid(&a, 6u, id == 0u, id == 1u, &in)) return;
        for (levels = 3; levels <= 5u; levels++) {
            lc_compare_one(&a, &in, levels, SUBD_LOOP_BOUNDARY_PAPER, SUBD_LOOP_STREAM_LIMIT, &hash);
            lc_compare_one(&a, &in, levels, SUBD_LOOP_BOUNDARY_BSPLINE, SUBD_LOOP_STREAM_LIMIT, &hash);
        }
    }
    {
        subd_arena a;
        subd_mesh in;
        subd_arena_init(&a, CMP_BUF, CMP_BYTES);
        if (!lc_make_shape(S_ICO, &a, &in)) return;
        lc_compare_one(&a, &in, 6, SUBD_LOOP_BOUNDARY_PAPER, SUBD_LOOP_STREAM_LIMIT, &hash);
        subd_arena_init(&a, CMP_BUF, CMP_BYTES);
        if (!lc_make_shape(S_TORUS, &a, &in)) return;
        lc_compare_one(&a, &in, 4, SUBD_LOOP_BOUNDARY_BSPLINE, SUBD_LOOP_STREAM_LIMIT, &hash);
    }
    CHECK_EQ(lc_skipped, 0);
    CHECK_EQ(lc_streams, 4u + 2u * 6u + 2u); /* level 6 of the grids: stream_level6 */
#else
    CHECK_EQ(lc_skipped, 0);
    CHECK_EQ(lc_streams, 4u);
#endif
    h_str("  limit tile streams compared ");
    h_u32(lc_streams);
    h_str(", skipped ");
    h_u32(lc_skipped);
    h_nl();
}

/* The position hash of lc_cmp_tri (each corner's three coordinates in emission order) without
 * a reference: the device's side of stream_level6. */
/* Tiles near the top of the range (src/loop_tile.c, LT_HUGE): the tile's rules are not
 * checked for overflow (convex combinations of the patch's level-0 points), so a patch with
 * a coordinate beyond SUBD_REAL_MAX / 2 must take the checked general path. The flipped grid
 * moved to coordinates 0.375..0.45 SUBD_REAL_MAX (every regular patch tiled, unchecked) and
 * 0.925..1.0 SUBD_REAL_MAX (every patch refused, the general path): the stream's status is
 * subd_loop's, and
 * when both succeed the bits are (lc_compare_one), levels 2 and 3, plain and limit. Q16.16's
 * bound is its own (stream_tiles_fixed_range): the grids scaled by 4 check it too. */
static void stream_tiles_huge(void)
{
    uint32_t s, v, k, hash = 2166136261u, levels, lim;
    for (s = 0; s < 2u; s++)
        for (lim = 0; lim < 2u; lim++)
            for (levels = 2; levels <= 3u; levels++) {
                subd_arena a;
                subd_mesh in, ref;
                subd_loop_opts o = {levels, SUBD_LOOP_BOUNDARY_PAPER, 0};
                subd_loop_sink sink;
                subd_diag d;
                uint32_t count = 0, mark;
                int want;
                subd_arena_init(&a, CMP_BUF, CMP_BYTES);
                if (!make_grid(&a, 6u, 1, 0, &in)) return;
                for (v = 0; v < in.num_verts; v++)
                    for (k = 0; k < 3u; k++) /* grid coordinates 0..6 -> (0.45 or 1 - c / 80) x the range */
                        in.pos[3u * v + k] = SUBD_FIXED ? in.pos[3u * v + k] * 4
                                                        : ((s ? 1.0f : 0.45f) - in.pos[3u * v + k] * 0.0125f) * SUBD_REAL_MAX;
                mark = subd_arena_mark(&a);
                want = subd_loop(&a, &in, &o, &ref, &d);
                subd_arena_rewind(&a, mark);
                o.flags = lim ? SUBD_LOOP_STREAM_LIMIT : 0u;
                sink.tri = lc_count_tri;
                sink.ctx = &count;
                if (lim && want == SUBD_OK) { /* the limit reference may overflow where the levels do not */
                    if (lc_compare_one(&a, &in, levels, SUBD_LOOP_BOUNDARY_PAPER, SUBD_LOOP_STREAM_LIMIT, &hash)) continue;
                    CHECK_EQ(subd_arena_mark(&a), mark);
                    continue;
                }
                CHECK_EQ(subd_loop_stream(&a, &in, &o, &sink, &d), want);
                CHECK_EQ(subd_arena_mark(&a), mark);
                if (want == SUBD_OK && !lim) CHECK(lc_compare_one(&a, &in, levels, SUBD_LOOP_BOUNDARY_PAPER, 0, &hash));
                if (!SUBD_FIXED && s == 0u) CHECK_EQ(want, SUBD_OK); /* 0.45: in range everywhere */
            }
}

/* Q16.16 tiles sum in 32 bits (src/loop_tile.c's lt_vpt, lt_ept: (3 (a + b) + v + e + 4) >> 3
 * and (10 v + p_0 + ... + p_5 + 8) >> 4 for subd_loop's exact 64-bit sums), which needs the
 * valence-6 weights to be 1/16 and 5/8 exactly (checked here in both arithmetics) and the
 * tile's coordinates below 2^27 in magnitude (a patch beyond is moved by whole units first:
 * loop_tile.c's lt_move). The flipped grid moved to the edge of that range, x near +2^27 - 1
 * and y near -(2^27 - 1) (raw), where a sum is within 16 of overflowing 32 bits (s = 0),
 * just beyond it (s = 1: every regular patch moved), and spread over -3 2^28 .. 3 2^28 (s =
 * 2: every patch wider than the move allows): the stream against subd_loop bit for bit,
 * levels 2 and 3, plain and limit mode, and the tile counts of the pull form (tiles, tiles,
 * then none). */
static void stream_tiles_fixed_range(void)
{
    loop_wcache wc;
    uint32_t ovf = 0, s, v, k, lim, levels, hash = 2166136261u;
    loop_weights w;
    wc.have = 0;
    w = subd_loop_weights_of(&wc, 6u, &ovf);
    CHECK(w.b == SUBD_REAL_FRAC(1, 16));
    CHECK(w.wc == SUBD_REAL_FRAC(5, 8));
    CHECK_EQ(ovf, 0);
#if SUBD_FIXED
    for (s = 0; s < 3u; s++)
        for (lim = 0; lim < 2u; lim++)
            for (levels = 2; levels <= 3u; levels++) {
                subd_arena a;
                subd_mesh in;
                subd_loop_opts o = {levels, SUBD_LOOP_BOUNDARY_PAPER, 0};
                subd_stream h;
                static subd_tri buf[16]; /* static: off the device's stack */
                uint32_t mark, n = 0, tiles = 0;
                int r;
                subd_arena_init(&a, CMP_BUF, CMP_BYTES);
                if (!make_grid(&a, 6u, 1, 0, &in)) return;
                for (v = 0; v < in.num_verts; v++)
                    for (k = 0; k < 3u; k++) { /* raw 0 .. 6 * 2^16 -> the range's edge, inward */
                        int32_t edge = s ? (1 << 27) + (1 << 20) : (1 << 27) - 1, c = in.pos[3u * v + k] / 4;
                        in.pos[3u * v + k] = k == 1u ? -(edge - c) : edge - c;
                        if (s == 2u) /* raw 0 .. 6 * 2^16 -> -3 2^28 .. 3 2^28 */
                            in.pos[3u * v + k] = (int32_t)((int64_t)c * 16384 - 3 * ((int64_t)1 << 28));
                    }
                (void)lc_compare_one(&a, &in, levels, SUBD_LOOP_BOUNDARY_PAPER, lim ? SUBD_LOOP_STREAM_LIMIT : 0u, &hash);
                o.flags = lim ? SUBD_LOOP_STREAM_LIMIT : 0u;
                mark = subd_arena_mark(&a);
                if (!CHECK_OK(subd_loop_stream_begin(&a, &in, &o, &h, 0), 0)) return;
                while ((r = subd_stream_next_tris(&h, buf, 16u)) > 0) {
                    n += (uint32_t)r;
                    if (n == in.num_faces << (2u * levels)) tiles = subd_lt_stream_count(&h, levels);
                }
                CHECK_EQ(r, 0);
                CHECK_EQ(n, in.num_faces << (2u * levels));
                subd_stream_end(&h);
                CHECK_EQ(subd_arena_mark(&a), mark);
                if (s == 2u) CHECK_EQ(tiles, 0); /* too wide: the general path */
                else CHECK(tiles > 0u);
            }
#else
    (void)s; (void)v; (void)k; (void)lim; (void)levels; (void)hash;
#endif
}

static int hash_tri(void *ctx, const subd_loop_tri *t)
{
    uint32_t *h = (uint32_t *)ctx, c, k;
    for (c = 0; c < 3u; c++)
        for (k = 0; k < 3u; k++) {
            uint32_t b = subd_real_bits(t->pos[c][k]);
            *h = h_fnv(*h, &b, 4);
        }
    return 0;
}

/* Level 6 on two shapes where tiles meet irregular patches (the 6 x 6 grid with a flipped
 * quad: valence-5 and valence-7 vertices next to regular regions and a boundary; the grid
 * with a crease across it), plain and limit mode, one rule each: the host compares the
 * stream with subd_loop (limit mode: subd_loop_limit of it) bit for bit and prints the
 * position hash; the device, where subd_loop's level 6 does not fit, streams the same into
 * the same hash, so make test's host = QEMU hash comparison carries the check over to the
 * device (plain mode: tiles of SUBD_LOOP_TILE_LEVELS levels at level 1, limit mode of
 * SUBD_LOOP_TILE_LEVELS_LIMIT at level 2). */
static void stream_level6(void)
{
    static const char *const names[4] = {"stream_l6_flip", "stream_l6_flip_limit", "stream_l6_crease",
                                         "stream_l6_crease_limit"};
    uint32_t id, lim;
    lc_streams = lc_skipped = 0;
    for (id = 0; id < 2u; id++)
        for (lim = 0; lim < 2u; lim++) {
            subd_arena a;
            subd_mesh in;
            uint32_t hash = 2166136261u, fl = lim ? SUBD_LOOP_STREAM_LIMIT : 0u;
            subd_loop_boundary b = id ? SUBD_LOOP_BOUNDARY_BSPLINE : SUBD_LOOP_BOUNDARY_PAPER;
            subd_arena_init(&a, CMP_BUF, CMP_BYTES);
            if (!make_grid(&a, 6u, id == 0u, id == 1u, &in)) return;
            {
                subd_loop_opts o;
                subd_loop_sink sink;
                subd_diag d;
                uint32_t own = 2166136261u;
                o.levels = 6;
                o.boundary = b;
                o.flags = fl;
                sink.tri = hash_tri;
                sink.ctx = &own;
                subd_diag_clear(&d);
                CHECK_OK(subd_loop_stream(&a, &in, &o, &sink, &d), &d);
#if H_HOST
                CHECK(lc_compare_one(&a, &in, 6, b, fl, &hash));
                CHECK_EQ(own, hash); /* the device's hash is the checked one */
#endif
                hash = own;
            }
            h_hash(names[2u * id + lim], hash);
        }
#if H_HOST
    CHECK_EQ(lc_streams, 4u);
    CHECK_EQ(lc_skipped, 0);
#endif
}

/* Partial tiles (loop_stream.c's sp_enter): a patch refused at the tiles' level tk, next to an
 * irregular vertex, has its regular children tiled one level down with a tile of one level
 * fewer, down to tiles of three levels (limit mode: two). The icosahedron (every control vertex of
 * valence 5) counts them exactly: a face with c irregular corners has c corner children with
 * one irregular corner and 4 - c regular ones; a regular face at level tk is a tile, below it
 * one at level k when L - k is at least that least depth. The pull form's tile counts (subd_lt_stream_count) must be these,
 * plain and limit mode, levels 2..6; the host compares the streams with subd_loop (limit mode:
 * subd_loop_limit of it) bit for bit at levels 3..5 (level 6: stream_tiles,
 * stream_tiles_limit), both rules. */
static void stream_tiles_partial(void)
{
    uint32_t hash = 2166136261u, lim, levels, t, k, fails = 0, made = 0;
    subd_arena a;
    subd_mesh in;
    subd_arena_init(&a, CMP_BUF, CMP_BYTES);
    if (!lc_make_shape(S_ICO, &a, &in)) return;
    for (lim = 0; lim < 2u; lim++)
        for (levels = 2; levels <= 6u; levels++) {
            uint32_t cfg = lim ? (uint32_t)SUBD_LOOP_TILE_LEVELS_LIMIT : (uint32_t)SUBD_LOOP_TILE_LEVELS;
            uint32_t td = levels < cfg ? levels : cfg, tk, want[6], reg = 0, irr3 = in.num_faces, irr1 = 0, got;
            uint32_t n = 0, mark = subd_arena_mark(&a);
            subd_loop_opts o;
            subd_stream h;
            static subd_tri buf[40]; /* static: off the device's stack */
            int r;
            if (td < 2u) continue;
            tk = levels - td;
            for (t = 0; t < 6u; t++) want[t] = 0;
            for (k = 0; k + 2u <= levels; k++) {
                if (k == tk || (k > tk && levels - k >= (lim ? 2u : 3u))) {
                    want[levels - k] += reg; /* a regular face at level tk, or below it with a
                                              * tile of at least 3 levels (limit mode: 2) */
                    reg = 0;
                }
                reg = 4u * reg + irr3 + 3u * irr1;
                irr1 = 3u * irr3 + irr1;
                irr3 = 0;
            }
            o.levels = levels;
            o.boundary = SUBD_LOOP_BOUNDARY_PAPER;
            o.flags = lim ? SUBD_LOOP_STREAM_LIMIT : 0u;
            if (!CHECK_OK(subd_loop_stream_begin(&a, &in, &o, &h, 0), 0)) return;
            while ((r = subd_stream_next_tris(&h, buf, 40u)) > 0) {
                n += (uint32_t)r;
                if (n == in.num_faces << (2u * levels)) /* the last triangles: every tile made */
                    for (t = 2; t <= 5u; t++) {
                        got = subd_lt_stream_count(&h, t);
                        if (got != want[t]) fails++;
                        if (t < td) made += got;
                    }
            }
            CHECK_EQ(r, 0);
            CHECK_EQ(n, in.num_faces << (2u * levels));
            subd_stream_end(&h);
            CHECK_EQ(subd_arena_mark(&a), mark);
            if (levels >= 4u) CHECK(want[lim ? 2u : 3u] > 0u); /* partial tiles down to their least depth */
        }
    CHECK_EQ(fails, 0);
    CHECK(made > 0u);
#if H_HOST
    for (lim = 0; lim < 2u; lim++)
        for (levels = 3; levels <= 5u; levels++) {
            uint32_t fl = lim ? SUBD_LOOP_STREAM_LIMIT : 0u;
            lc_compare_one(&a, &in, levels, SUBD_LOOP_BOUNDARY_PAPER, fl, &hash);
            lc_compare_one(&a, &in, levels, SUBD_LOOP_BOUNDARY_BSPLINE, fl, &hash);
        }
    CHECK_EQ(lc_skipped, 0);
#endif
    (void)hash;
}

/* Limit mode's depth-5 tiles (loop_tile.h's lt_split: a quarter's last level with margin
 * made at its first sixteenth, kept for the other three): the pull form, stopped at every
 * 7th triangle (inside a sixteenth's 64; 1024 triangles per tile) and at every 1000th,
 * resumes with exactly the push form's triangles (positions, normals, ids, face, level), and
 * depth-5 tiles are made: the flipped grid at level 5 (tiles at level 0, partial ones next
 * to its valence-5 and valence-7 vertices), both rules. The push form equals
 * subd_loop_limit's bits (stream_tiles_limit, stream_level6). */
typedef struct pull_cmp5 {
    subd_stream *s;
    subd_tri buf[1000];
    uint32_t batch, have, next, bad;
} pull_cmp5;

static int pull_tri5(void *ctx, const subd_tri *t)
{
    pull_cmp5 *c = (pull_cmp5 *)ctx;
    const subd_tri *u;
    uint32_t j, k;
    if (c->next == c->have) {
        int r = subd_stream_next_tris(c->s, c->buf, c->batch);
        c->have = r > 0 ? (uint32_t)r : 0u;
        c->next = 0;
        if (!c->have) {
            c->bad++;
            return 0;
        }
    }
    u = &c->buf[c->next++];
    for (j = 0; j < 3u; j++) {
        for (k = 0; k < 3u; k++)
            if (!h_same(t->pos[j][k], u->pos[j][k]) || !h_same(t->normal[j][k], u->normal[j][k])) c->bad++;
        if (t->id[j] != u->id[j]) c->bad++;
    }
    if (t->face != u->face || t->level != u->level) c->bad++;
    return 0;
}

static void stream_tiles_limit5(void)
{
    static pull_cmp5 c; /* static: off the device's stack */
    const uint32_t batches[2] = {7u, 1000u};
    uint32_t b, rule;
    for (rule = 0; rule < 2u; rule++)
        for (b = 0; b < 2u; b++) {
            subd_arena a;
            subd_mesh in;
            subd_loop_opts o;
            subd_stream h;
            subd_tri_sink sink;
            subd_diag d;
            uint32_t mark;
            subd_diag_clear(&d);
            subd_arena_init(&a, CMP_BUF, CMP_BYTES);
            if (!make_grid(&a, 6u, 1, 0, &in)) return;
            o.levels = 5;
            o.boundary = rule ? SUBD_LOOP_BOUNDARY_BSPLINE : SUBD_LOOP_BOUNDARY_PAPER;
            o.flags = SUBD_LOOP_STREAM_LIMIT;
            mark = subd_arena_mark(&a);
            if (!CHECK_OK(subd_loop_stream_begin(&a, &in, &o, &h, &d), &d)) return;
            c.s = &h;
            c.batch = batches[b];
            c.have = c.next = c.bad = 0;
            sink.tri = pull_tri5;
            sink.ctx = &c;
            CHECK_OK(subd_loop_stream(&a, &in, &o, &sink, &d), &d); /* above the pull stream */
            CHECK_EQ(c.bad, 0);
            CHECK_EQ(c.next, c.have);
#if SUBD_LOOP_TILE_LEVELS_LIMIT == 5
            CHECK(subd_lt_stream_count(&h, 5u) > 0u); /* depth-5 tiles were made */
#endif
            CHECK_EQ(subd_stream_next_tris(&h, c.buf, c.batch), 0); /* the end */
            CHECK_EQ(subd_arena_mark(&a), mark);
        }
}

/* The ids subd_lt_ids gives piece (org, e1, e2) of side m of the tile face with corners
 * (ca, cb) (side h) in control face f at level lv, against subd_lp_vertex_id at each piece
 * vertex's lattice point; *inner += 1 when every one lies inside the control face. Returns
 * the number of wrong ids. */
static uint32_t piece_ids_bad(lt_tile *tl, const subd_mesh *in, uint32_t f, uint32_t lv, const uint32_t ca[3],
                              const uint32_t cb[3], int32_t h, int32_t m, const int32_t org[2], const int32_t e1[2],
                              const int32_t e2[2], uint32_t *inner)
{
    int32_t ea = ((int32_t)ca[1] - (int32_t)ca[0]) / h, eb = ((int32_t)cb[1] - (int32_t)cb[0]) / h;
    int32_t fa = ((int32_t)ca[2] - (int32_t)ca[0]) / h, fb = ((int32_t)cb[2] - (int32_t)cb[0]) / h;
    int32_t n1 = (int32_t)1 << lv, x, y;
    uint32_t q = 0, bad = 0, all = 1;
    subd_lt_ids(tl, in, f, lv, ca, cb, org, e1, e2);
    for (y = 0; y <= m; y++)
        for (x = 0; x + y <= m; x++, q++) {
            int32_t gx = org[0] + x * e1[0] + y * e2[0], gy = org[1] + x * e1[1] + y * e2[1];
            int32_t pa = (int32_t)ca[0] + gx * ea + gy * fa, pb = (int32_t)cb[0] + gx * eb + gy * fb;
            uint64_t want = subd_lp_vertex_id(in, f, (uint32_t)pa, (uint32_t)pb, lv);
            if (((uint64_t)tl->q[q].id | ((uint64_t)tl->qhi[q] << 32)) != want) bad++;
            if (pa < 1 || pb < 1 || pa + pb > n1 - 1) all = 0;
        }
    *inner += all;
    return bad;
}

/* subd_lt_ids against subd_lp_vertex_id, the general id of a point of a control face
 * (piece_ids_bad), for every piece frame a tile can take (each pair of consecutive lattice
 * directions, origins on the piece's own lattice, the piece inside the tile's face), tile
 * faces of both kinds and every corner order at the control face's corners, along its edges
 * and inside, levels 3-7, depths 2-5, quarters and sixteenths: pieces inside the control
 * face (subd_lt_ids' whole-piece run) and touching its boundary (runs found per row,
 * subd_lp_vertex_id around them). */
static void tile_ids_direct(void)
{
    static lt_rec rec[153]; /* a piece of side 16 at most */
    static uint32_t rechi[153];
    static const int8_t dx[6] = {1, 0, -1, -1, 0, 1}, dy[6] = {0, 1, 1, 0, -1, -1};
    subd_arena a;
    subd_mesh in;
    lt_tile tl;
    uint32_t lv, t, split, f, bad = 0, pieces = 0, inner = 0, kind, rot, k, e;
    subd_arena_init(&a, CMP_BUF, CMP_BYTES);
    if (!make_grid(&a, 2u, 0, 0, &in)) return;
    tl.q = rec;
    tl.qhi = rechi;
    for (lv = 3; lv <= 7u; lv++)
        for (t = 2; t <= 5u && t <= lv; t++)
            for (split = 1; split <= 2u && split < t; split++)
                for (f = 0; f < in.num_faces; f += 3u) {
                    int32_t n1 = (int32_t)1 << lv, h = (int32_t)1 << t, m = h >> split, A, B;
                    tl.depth = t;
                    tl.split = split;
                    for (B = 0; B + h <= n1; B += h)
                        for (A = 0; A + B + h <= n1; A += h)
                            for (kind = 0; kind < 2u; kind++) {
                                /* up (A, B) (A + h, B) (A, B + h), down (A + h, B) (A + h, B + h)
                                 * (A, B + h); at the control face's boundary and a few inside */
                                int32_t pa[3] = {kind ? A + h : A, A + h, A}, pb[3] = {B, kind ? B + h : B, B + h};
                                if ((kind && A + B + 2 * h > n1) || (A && B && A + B + 2 * h < n1 && A != h)) continue;
                                for (rot = 0; rot < 3u; rot++)
                                    for (e = 0; e < 6u; e++) {
                                        uint32_t ca[3], cb[3];
                                        int32_t e1[2] = {dx[e], dy[e]}, o[2];
                                        int32_t e2[2] = {dx[(e + 1u) % 6u], dy[(e + 1u) % 6u]};
                                        for (k = 0; k < 3u; k++) {
                                            ca[k] = (uint32_t)pa[(k + rot) % 3u];
                                            cb[k] = (uint32_t)pb[(k + rot) % 3u];
                                        }
                                        for (o[1] = 0; o[1] <= h; o[1] += m)
                                            for (o[0] = 0; o[0] + o[1] <= h; o[0] += m) {
                                                int32_t x1 = o[0] + m * e1[0], y1 = o[1] + m * e1[1];
                                                int32_t x2 = o[0] + m * e2[0], y2 = o[1] + m * e2[1];
                                                if (x1 < 0 || y1 < 0 || x1 + y1 > h || x2 < 0 || y2 < 0 || x2 + y2 > h)
                                                    continue; /* the piece leaves the tile's face */
                                                bad += piece_ids_bad(&tl, &in, f, lv, ca, cb, h, m, o, e1, e2, &inner);
                                                pieces++;
                                            }
                                    }
                            }
                }
    CHECK_EQ(bad, 0);
    CHECK(inner > 0u && inner < pieces); /* both of subd_lt_ids' paths */
}

const test_case suite_loop_tiles[] = {
    {"stream_tiles", stream_tiles},
    {"stream_tiles_limit", stream_tiles_limit},
    {"stream_tiles_huge", stream_tiles_huge},
    {"stream_tiles_fixed_range", stream_tiles_fixed_range},
    {"stream_level6", stream_level6},
    {"stream_tiles_partial", stream_tiles_partial},
    {"stream_tiles_limit5", stream_tiles_limit5},
    {"tile_ids_direct", tile_ids_direct},
    {0, 0},
};
