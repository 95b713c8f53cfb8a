/* SPDX-License-Identifier: MIT */
/* The regular tiles' push loop (src/loop_stream_emit.c's tile_push) in both of its id forms:
 * a stream whose ids all lie below 2^32 hands out each tile vertex's id from its record's low
 * word alone (the high word known to be zero), any other stream reads the high words too
 * (src/loop_tile.h's qhi). A stream large enough to reach 2^32 does not fit a test, so the
 * second form is forced on small streams (subd_ls_stream_wide_ids) and must hand out the
 * same triangles, bits and ids as the first, and (host) as subd_loop. */
#include "loop_cmp.h"
#include "../src/loop_stream_internal.h"

/* FNV-1a of every triangle's positions, normals and ids in emission order, and a count. */
typedef struct emit_hash {
    uint32_t h, n;
} emit_hash;

static int emit_hash_tri(void *ctx, const subd_loop_tri *t)
{
    emit_hash *e = (emit_hash *)ctx;
    uint32_t c, k;
    for (c = 0; c < 3u; c++) {
        for (k = 0; k < 3u; k++) {
            uint32_t p = subd_real_bits(t->pos[c][k]), q = subd_real_bits(t->normal[c][k]);
            e->h = h_fnv(e->h, &p, 4);
            e->h = h_fnv(e->h, &q, 4);
        }
        e->h = h_fnv(e->h, &t->id[c], 8);
    }
    e->n++;
    return 0;
}

/* Tiles of every depth the stream makes (the pull form, read before its last batch ends it). */
static uint32_t tiles_made(subd_arena *a, const subd_mesh *in, const subd_loop_opts *o)
{
    static subd_tri buf[16]; /* static: off the device's stack */
    subd_stream h;
    uint32_t n = 0, t, made = 0;
    int r;
    if (!CHECK_OK(subd_loop_stream_begin(a, in, o, &h, 0), 0)) return 0;
    while ((r = subd_stream_next_tris(&h, buf, 16u)) > 0) {
        n += (uint32_t)r;
        if (n == in->num_faces << (2u * o->levels))
            for (t = 2; t <= 5u; t++) made += subd_lt_stream_count(&h, t);
    }
    CHECK_EQ(r, 0);
    subd_stream_end(&h);
    return made;
}

/* The grid with a crease across it and the icosahedron (tiles next to irregular vertices),
 * levels 3-5 (the device 3-4), plain and limit mode: the push form with the high words read equals the one
 * without, triangle for triangle (positions, normals, ids); the host compares the plain
 * stream with the high words read against subd_loop too (loop_cmp.c's sink). */
static void stream_wide_ids(void)
{
    static const int shapes[2] = {S_GRID_CREASE, S_ICO};
    uint32_t si, lim, levels, made = 0;
    for (si = 0; si < 2u; si++)
        for (lim = 0; lim < 2u; lim++)
            for (levels = 3; levels <= (H_HOST ? 5u : 4u); levels++) { /* the device: its time */
                subd_arena a;
                subd_mesh in;
                subd_loop_opts o;
                subd_loop_sink sink;
                subd_stream h;
                subd_diag d;
                emit_hash e0 = {2166136261u, 0}, e1 = {2166136261u, 0};
                uint32_t mark;
                subd_arena_init(&a, CMP_BUF, CMP_BYTES);
                if (!lc_make_shape(shapes[si], &a, &in)) return;
                o.levels = levels;
                o.boundary = SUBD_LOOP_BOUNDARY_PAPER;
                o.flags = lim ? SUBD_LOOP_STREAM_LIMIT : 0u;
                mark = subd_arena_mark(&a);
                made += tiles_made(&a, &in, &o);
                sink.tri = emit_hash_tri;
                sink.ctx = &e0;
                if (!CHECK_OK(subd_loop_stream(&a, &in, &o, &sink, &d), &d)) return;
                sink.ctx = &e1;
                if (!CHECK_OK(subd_loop_stream_begin(&a, &in, &o, &h, &d), &d)) return;
                subd_ls_stream_wide_ids(&h);
                if (!CHECK_OK(subd_stream_run_tris(&h, &sink, &d), &d)) return;
                CHECK_EQ(subd_arena_mark(&a), mark);
                CHECK_EQ(e0.n, in.num_faces << (2u * levels));
                CHECK_EQ(e1.n, e0.n);
                CHECK_EQ(e1.h, e0.h);
#if H_HOST
                if (!lim) {
                    subd_mesh ref;
                    subd_loop_opts ro = o;
                    cmp_sink cs;
                    uint64_t *ids;
                    ro.flags = 0;
                    if (!CHECK_OK(subd_loop(&a, &in, &ro, &ref, &d), &d)) return;
                    ids = (uint64_t *)subd_arena_alloc(&a, ref.num_verts * 8u);
                    if (!CHECK(ids != 0)) return;
                    lc_sink_init(&cs, &sink, &ref, ids, 0, 2166136261u);
                    if (!CHECK_OK(subd_loop_stream_begin(&a, &in, &o, &h, &d), &d)) return;
                    subd_ls_stream_wide_ids(&h);
                    if (!CHECK_OK(subd_stream_run_tris(&h, &sink, &d), &d)) return;
                    CHECK_EQ(cs.j, ref.num_faces);
                    CHECK_EQ(cs.bad_pos, 0);
                    CHECK_EQ(cs.bad_id, 0);
                    subd_arena_rewind(&a, mark);
                }
#endif
            }
    CHECK(made > 0u); /* the tiles' push loop ran */
}

const test_case suite_loop_tile_emit[] = {
    {"stream_wide_ids", stream_wide_ids},
    {0, 0},
};
