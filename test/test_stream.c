/* SPDX-License-Identifier: MIT */
/* The one stream interface (subd.h "Streams", src/stream.c) on the Loop stream: the pull form
 * (subd_loop_stream_begin + subd_stream_next_tris) in batches of 1, 7 and a large size hands
 * out exactly the push form's triangles, in the same order, byte for byte (positions, normals,
 * ids, face, level), closed and open meshes, creases, limit mode, one and several levels;
 * then the end of the stream, the handle's errors, a failed begin leaving arena and handle
 * untouched, subd_stream_end giving the arena back at any time, two streams in one arena,
 * and the push form's sink stop with the item's face. The push form itself is compared with
 * subd_loop bit for bit in test_loop_stream.c. */
#include "harness.h"
#include "corpus.h"

#define PULL_BIG (H_HOST ? 4096u : 256u) /* the device's RAM holds a smaller batch buffer */
static subd_tri pull_buf[PULL_BIG];

static int load(subd_arena *a, const char *name, subd_mesh *m)
{
    const corpus_file *f = corpus_find(name);
    subd_diag d;
    if (!CHECK(f != 0)) return 0;
    return CHECK_EQ(subd_obj_read(a, f->data, f->len, m, &d), SUBD_OK);
}

static int same_tri(const subd_tri *x, const subd_tri *y)
{
    const uint8_t *p = (const uint8_t *)x, *q = (const uint8_t *)y;
    uint32_t i;
    for (i = 0; i < (uint32_t)sizeof(subd_tri); i++)
        if (p[i] != q[i]) return 0;
    return 1;
}

/* The push form's sink: each triangle against the pull stream's next one. */
typedef struct pull_cmp {
    subd_stream *s;
    uint32_t batch, have, next, seen, bad, bad_count;
} pull_cmp;

static int cmp_pulled(void *ctx, const subd_tri *t)
{
    pull_cmp *c = (pull_cmp *)ctx;
    if (c->next == c->have) {
        int n = subd_stream_next_tris(c->s, pull_buf, c->batch);
        if (n <= 0 || (uint32_t)n > c->batch) {
            c->bad_count++;
            return 9;
        }
        c->have = (uint32_t)n;
        c->next = 0;
    }
    if (!same_tri(t, &pull_buf[c->next])) c->bad++;
    c->next++;
    c->seen++;
    return 0;
}

static void pull_equals_push(void)
{
    static const char *const names[] = {"test/data/icosahedron.obj", "test/data/grid_tri_8x8.obj"};
    const uint32_t batches[3] = {1u, 7u, PULL_BIG};
    subd_arena a;
    uint32_t mi, lv, fl, b;
    for (mi = 0; mi < 2u; mi++)
        for (lv = 1; lv <= 3u; lv++)
            for (fl = 0; fl < 2u; fl++)
                for (b = 0; b < 3u; b++) {
                    subd_mesh in;
                    subd_loop_opts o;
                    subd_stream s;
                    subd_tri_sink sink;
                    subd_diag d;
                    pull_cmp c;
                    uint32_t mark;
                    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
                    if (!load(&a, names[mi], &in)) return;
                    if (mi == 1u) subd_edge_tag_set(&in, in.num_corners / 2u, SUBD_ETAG_CREASE);
                    o.levels = lv;
                    o.boundary = SUBD_LOOP_BOUNDARY_PAPER;
                    o.flags = fl ? SUBD_LOOP_STREAM_LIMIT : 0u;
                    mark = subd_arena_mark(&a);
                    if (!CHECK_OK(subd_loop_stream_begin(&a, &in, &o, &s, &d), &d)) return;
                    c.s = &s;
                    c.batch = batches[b];
                    c.have = c.next = c.seen = c.bad = c.bad_count = 0;
                    sink.tri = cmp_pulled;
                    sink.ctx = &c;
                    CHECK_OK(subd_loop_stream(&a, &in, &o, &sink, &d), &d); /* above the pull stream */
                    CHECK_EQ(c.bad, 0);
                    CHECK_EQ(c.bad_count, 0);
                    CHECK_EQ(c.next, c.have);                 /* nothing pulled beyond */
                    CHECK_EQ(c.seen, in.num_faces << (2u * lv)); /* 4^L per control face */
                    CHECK_EQ(subd_stream_next_tris(&s, pull_buf, c.batch), 0); /* the end ... */
                    CHECK_EQ(subd_arena_mark(&a), mark);                       /* ... gave it back */
                    CHECK_EQ(subd_stream_next_tris(&s, pull_buf, c.batch), 0); /* and stays ended */
                    CHECK_EQ(s.items_, c.seen);
                }
}

/* The handle's errors, the end at any time, a failed begin. */
static void pull_errors(void)
{
    subd_arena a, small;
    subd_mesh in, quad;
    subd_loop_opts o = {2, SUBD_LOOP_BOUNDARY_PAPER, 0};
    subd_stream s, zero, sentinel;
    subd_point pt;
    subd_diag d;
    uint32_t mark, plan, i;
    uint8_t *buf;
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    if (!load(&a, "test/data/icosahedron.obj", &in) || !load(&a, "test/data/cube_quad.obj", &quad)) return;
    mark = subd_arena_mark(&a);
    for (i = 0; i < (uint32_t)sizeof zero; i++) ((uint8_t *)&zero)[i] = 0;
    CHECK_EQ(subd_stream_next_tris(0, pull_buf, 1), SUBD_ERR_PARAM);
    CHECK_EQ(subd_stream_next_tris(&zero, pull_buf, 1), SUBD_ERR_PARAM); /* never begun */
    subd_stream_end(0);
    subd_stream_end(&zero);
    if (!CHECK_OK(subd_loop_stream_begin(&a, &in, &o, &s, &d), &d)) return;
    CHECK(subd_arena_mark(&a) > mark);
    CHECK_EQ(subd_stream_next_tris(&s, 0, 1), SUBD_ERR_PARAM);
    CHECK_EQ(subd_stream_next_tris(&s, pull_buf, 0), SUBD_ERR_PARAM);
    CHECK_EQ(subd_stream_next_points(&s, &pt, 1), SUBD_ERR_PARAM); /* a triangle stream */
    CHECK_EQ(subd_stream_next_tris(&s, pull_buf, 5), 5);           /* still running */
    subd_stream_end(&s);                                            /* stop early */
    CHECK_EQ(subd_arena_mark(&a), mark);
    subd_stream_end(&s); /* idempotent */
    CHECK_EQ(subd_arena_mark(&a), mark);
    CHECK_EQ(subd_stream_next_tris(&s, pull_buf, 5), 0);
    /* begin's own errors: arena and handle untouched */
    for (i = 0; i < (uint32_t)sizeof sentinel; i++) ((uint8_t *)&sentinel)[i] = 0xA5u;
    s = sentinel;
    CHECK_FAIL(subd_loop_stream_begin(&a, &quad, &o, &s, &d), &d, SUBD_ERR_NOT_TRIANGLES);
    CHECK_EQ(d.face, 0);
    CHECK_FAIL(subd_loop_stream_begin(0, &in, &o, &s, &d), &d, SUBD_ERR_PARAM);
    CHECK_FAIL(subd_loop_stream_begin(&a, &in, &o, 0, &d), &d, SUBD_ERR_PARAM);
    o.levels = 0;
    CHECK_FAIL(subd_loop_stream_begin(&a, &in, &o, &s, &d), &d, SUBD_ERR_PARAM);
    o.levels = 2;
    CHECK_EQ(d.bytes_needed, 0);
    if (!CHECK_OK(subd_loop_stream_plan(&in, &o, &plan, 0), &d)) return;
    CHECK_EQ(plan, SUBD_LOOP_STREAM_BYTES(2, 5));
    buf = (uint8_t *)subd_arena_alloc(&a, plan);
    if (!CHECK(buf != 0)) return;
    for (i = 0; i < plan; i += (i < 64u || plan - i < 64u) ? 1u : 61u) {
        subd_arena_init(&small, buf, i);
        if (!CHECK_FAIL(subd_loop_stream_begin(&small, &in, &o, &s, &d), &d, SUBD_ERR_NOMEM)) break;
        if (!CHECK_EQ(d.bytes_needed, plan) || !CHECK_EQ(small.used, 0)) break;
    }
    for (i = 0; i < (uint32_t)sizeof s; i++)
        if (!CHECK_EQ(((uint8_t *)&s)[i], 0xA5u)) break;
    subd_arena_init(&small, buf, plan);
    CHECK_OK(subd_loop_stream_begin(&small, &in, &o, &s, &d), &d);
    CHECK_EQ(small.used, plan);
    while (subd_stream_next_tris(&s, pull_buf, 3) > 0) {}
    CHECK_EQ(small.used, 0);
    CHECK_EQ(small.peak, plan);
}

/* The push form's sink stop, over the pull handle: the value back, diag.face = the face of
 * the triangle the sink stopped at, the arena given back. */
static int stop_at(void *ctx, const subd_tri *t)
{
    uint32_t *n = (uint32_t *)ctx;
    (void)t;
    return --*n == 0u ? 42 : 0;
}

static void push_stop(void)
{
    subd_arena a;
    subd_mesh in;
    subd_loop_opts o = {2, SUBD_LOOP_BOUNDARY_PAPER, 0};
    subd_stream s;
    subd_tri_sink sink;
    subd_diag d;
    uint32_t mark, n = 40;
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    if (!load(&a, "test/data/icosahedron.obj", &in)) return;
    mark = subd_arena_mark(&a);
    sink.tri = stop_at;
    sink.ctx = &n;
    if (!CHECK_OK(subd_loop_stream_begin(&a, &in, &o, &s, &d), &d)) return;
    CHECK_EQ(subd_stream_run_tris(&s, &sink, &d), 42);
    CHECK_EQ(d.status, 42);
    CHECK_EQ(d.face, 39u / 16u); /* 16 triangles per control face at two levels */
    CHECK_EQ(subd_arena_mark(&a), mark);
    CHECK_EQ(subd_stream_next_tris(&s, pull_buf, 1), 0);
    CHECK_FAIL(subd_stream_run_tris(&s, 0, &d), &d, SUBD_ERR_PARAM);
    CHECK_EQ(d.bytes_needed, 0);
}

const test_case suite_stream[] = {
    {"pull_equals_push", pull_equals_push},
    {"pull_errors", pull_errors},
    {"push_stop", push_stop},
    {0, 0},
};
