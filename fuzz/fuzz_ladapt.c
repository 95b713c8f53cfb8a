/* SPDX-License-Identifier: MIT */
/* libFuzzer target: the adaptive Loop limit stream (subd_loop_adapt_stream) on a small mesh
 * decoded from the input bytes.
 *
 * The bytes choose a closed template (tetrahedron, octahedron) or an open one (a 3x3 grid of
 * triangles), perturbed positions (sometimes huge, or NaN/inf in float32), crease tags and a
 * corner tag, the max level 0..4 (0: refused), the boundary rule (or an unknown one), the mode
 * (CHORD, CALLBACK or an unknown value), the tolerance (sometimes <= 0) and the callback's
 * levels (from the bytes, some above the max level). Each stream runs with an arena of
 * exactly its plan and of plan - 1; fuzz_check.c's checks apply (known status; the arena back
 * at its mark; peak <= plan; guard bytes intact), and: plan - 1 gives SUBD_ERR_NOMEM with
 * bytes_needed = plan and nothing emitted; on success every id has one set of bits, no
 * triangle repeats an id, no directed edge repeats, and a closed template's output is closed
 * (every directed edge's reverse is there); a pull in batches of 3 gives the same triangles. */
#include "fuzz_check.h"

#include <stdlib.h>
#include <string.h>

typedef struct la_cur {
    const uint8_t *p;
    size_t n, i;
} la_cur;
static uint8_t la_u8(la_cur *c) { return c->i < c->n ? c->p[c->i++] : 0u; }

static subd_real la_coord(int base, uint8_t b)
{
#if SUBD_FIXED
    if (b == 0x7fu) return (subd_real)(30000 * 65536);
    return (subd_real)(base * 65536 + (int32_t)(int8_t)b * 1024);
#else
    if (b == 0x7fu) {
        float z = 0.0f;
        return z / z;
    }
    if (b == 0x7eu) return 3e38f;
    return (float)base + (float)(int8_t)b / 64.0f;
#endif
}

static const int la_tet_p[4][3] = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
static const uint32_t la_tet_f[4][3] = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
static const int la_oct_p[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
static const uint32_t la_oct_f[8][3] = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                        {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};

typedef struct la_out {
    subd_tri *t;
    uint32_t n, cap;
} la_out;

static int la_sink(void *ctx, const subd_tri *t)
{
    la_out *o = (la_out *)ctx;
    if (o->n < o->cap) o->t[o->n] = *t;
    o->n++;
    return 0;
}

static uint32_t g_levels[16];
static uint32_t la_level(void *user, uint32_t face)
{
    (void)user;
    return g_levels[face % 16u];
}

typedef struct la_e {
    uint64_t u, v;
} la_e;
static int la_e_cmp(const void *x, const void *y)
{
    const la_e *a = (const la_e *)x, *b = (const la_e *)y;
    if (a->u != b->u) return a->u < b->u ? -1 : 1;
    return a->v < b->v ? -1 : a->v > b->v;
}
typedef struct la_v {
    uint64_t id;
    uint32_t bits[6];
} la_v;
static int la_v_cmp(const void *x, const void *y)
{
    const la_v *a = (const la_v *)x, *b = (const la_v *)y;
    return a->id < b->id ? -1 : a->id > b->id;
}

static void la_weld_check(const la_out *o, int closed)
{
    uint32_t n = o->n, i, j, k;
    la_e *e = (la_e *)malloc(3u * n * sizeof *e + 1u);
    la_v *v = (la_v *)malloc(3u * n * sizeof *v + 1u);
    if (!e || !v) abort();
    for (i = 0; i < n; i++)
        for (j = 0; j < 3u; j++) {
            const subd_tri *t = &o->t[i];
            e[3u * i + j].u = t->id[j];
            e[3u * i + j].v = t->id[(j + 1u) % 3u];
            FZ_CHECK(t->id[j] != t->id[(j + 1u) % 3u], "a triangle repeats an id", i, j);
            v[3u * i + j].id = t->id[j];
            for (k = 0; k < 3u; k++) {
                v[3u * i + j].bits[k] = subd_real_bits(t->pos[j][k]);
                v[3u * i + j].bits[3u + k] = subd_real_bits(t->normal[j][k]);
            }
        }
    qsort(e, 3u * n, sizeof *e, la_e_cmp);
    qsort(v, 3u * n, sizeof *v, la_v_cmp);
    for (i = 1; i < 3u * n; i++) {
        if (v[i].id == v[i - 1u].id)
            FZ_CHECK(memcmp(v[i].bits, v[i - 1u].bits, sizeof v[i].bits) == 0, "one id, one set of bits", i, 0);
        FZ_CHECK(la_e_cmp(&e[i], &e[i - 1u]) != 0, "a directed edge repeats", i, 0);
    }
    if (closed)
        for (i = 0; i < 3u * n; i++) {
            la_e r;
            r.u = e[i].v;
            r.v = e[i].u;
            FZ_CHECK(bsearch(&r, e, 3u * n, sizeof *e, la_e_cmp) != NULL, "closed input, closed output", i, 0);
        }
    free(e);
    free(v);
}

int FUZZ_ENTRY(const uint8_t *data, size_t size)
{
    la_cur c = {data, size, 0};
    uint8_t tmpl = la_u8(&c) % 3u, fl;
    subd_real pos[3 * 16];
    uint32_t idx[3 * 18], nv, nf, i, j, plan = 0;
    subd_face_list f;
    fz_arena ma;
    subd_mesh m;
    subd_diag d;
    subd_loop_adapt_opts o;
    fz_snap snap;
    int st, closed = tmpl < 2u;
    memset(&f, 0, sizeof f);
    if (tmpl == 0u) {
        nv = 4; nf = 4;
        for (i = 0; i < nv; i++)
            for (j = 0; j < 3u; j++) pos[3u * i + j] = la_coord(la_tet_p[i][j], la_u8(&c));
        for (i = 0; i < nf; i++)
            for (j = 0; j < 3u; j++) idx[3u * i + j] = la_tet_f[i][j];
    } else if (tmpl == 1u) {
        nv = 6; nf = 8;
        for (i = 0; i < nv; i++)
            for (j = 0; j < 3u; j++) pos[3u * i + j] = la_coord(la_oct_p[i][j], la_u8(&c));
        for (i = 0; i < nf; i++)
            for (j = 0; j < 3u; j++) idx[3u * i + j] = la_oct_f[i][j];
    } else { /* 3x3 vertices, 8 triangles */
        nv = 9; nf = 8;
        for (i = 0; i < nv; i++) {
            pos[3u * i] = la_coord((int)(i % 3u), la_u8(&c));
            pos[3u * i + 1u] = la_coord((int)(i / 3u), la_u8(&c));
            pos[3u * i + 2u] = la_coord(0, la_u8(&c));
        }
        for (i = 0; i < 4u; i++) {
            uint32_t x = i % 2u, y = i / 2u, v0 = 3u * y + x;
            idx[6u * i] = v0; idx[6u * i + 1u] = v0 + 1u; idx[6u * i + 2u] = v0 + 4u;
            idx[6u * i + 3u] = v0; idx[6u * i + 4u] = v0 + 4u; idx[6u * i + 5u] = v0 + 3u;
        }
    }
    f.num_verts = nv;
    f.pos = pos;
    f.num_faces = nf;
    f.index = idx;
    fz_arena_open(&ma, 1u << 16);
    if (subd_mesh_build(&ma.a, &f, &m, &d) != SUBD_OK) {
        fz_arena_close(&ma);
        return 0;
    }
    fl = la_u8(&c);
    for (i = 0; i < m.num_corners; i++)
        if (m.twin[i] != SUBD_NONE && ((fl >> (i % 8u)) & 1u) && (la_u8(&c) & 3u) == 0u)
            subd_edge_tag_set(&m, i, SUBD_ETAG_CREASE);
    if (fl & 1u) m.vert_tag[0] = (uint8_t)(m.vert_tag[0] | SUBD_VTAG_CORNER);
    memset(&o, 0, sizeof o);
    o.loop.levels = la_u8(&c) % 5u;
    o.loop.boundary = (subd_loop_boundary)(la_u8(&c) % 3u);
    o.loop.flags = (la_u8(&c) & 1u) ? SUBD_LOOP_STREAM_LIMIT : 0u;
    o.mode = la_u8(&c) % 3u;
    {
        uint8_t eb = la_u8(&c);
#if SUBD_FIXED
        o.chord = (subd_real)((int32_t)(int8_t)eb * 64);
#else
        o.chord = (float)(int8_t)eb / 512.0f;
#endif
    }
    o.face_level = (la_u8(&c) & 7u) ? la_level : NULL;
    for (i = 0; i < 16u; i++) g_levels[i] = la_u8(&c) % 7u;
    fz_snap_take(&snap, ma.block, ma.a.used);
    st = subd_loop_adapt_stream_plan(&m, &o, &plan, &d);
    fz_status_known(st, 0, "subd_loop_adapt_stream_plan");
    if (st == SUBD_OK && plan <= FZ_MAX_ARENA) {
        uint32_t cap = nf << (2u * o.loop.levels);
        la_out out = {(subd_tri *)malloc(cap * sizeof(subd_tri)), 0, cap};
        subd_tri_sink sink = {la_sink, &out};
        fz_arena sa;
        if (!out.t) abort();
        /* plan - 1: NOMEM, nothing emitted */
        fz_arena_open(&sa, plan - 1u);
        st = subd_loop_adapt_stream(&sa.a, &m, &o, &sink, &d);
        FZ_CHECK(st == SUBD_ERR_NOMEM && d.bytes_needed == plan && out.n == 0u, "plan - 1: NOMEM", st, out.n);
        fz_arena_after(&sa, st, 0, plan, "subd_loop_adapt_stream (plan - 1)");
        fz_arena_close(&sa);
        /* exactly the plan */
        fz_arena_open(&sa, plan);
        st = subd_loop_adapt_stream(&sa.a, &m, &o, &sink, &d);
        fz_status_known(st, 0, "subd_loop_adapt_stream");
        FZ_CHECK(sa.a.used == 0u, "nothing stays in the arena", sa.a.used, st);
        fz_arena_after(&sa, st, 0, plan, "subd_loop_adapt_stream");
        FZ_CHECK(st == SUBD_OK || st == SUBD_ERR_RANGE, "a planned stream fails only by overflow", st, 0);
        FZ_CHECK(out.n <= cap, "at most the uniform count", out.n, cap);
        if (st == SUBD_OK) {
            subd_stream h;
            subd_tri buf[3];
            uint32_t k = 0;
            int got;
            la_weld_check(&out, closed);
            FZ_CHECK(subd_loop_adapt_stream_begin(&sa.a, &m, &o, &h, &d) == SUBD_OK, "begin", 0, 0);
            while ((got = subd_stream_next_tris(&h, buf, 3u)) > 0)
                for (i = 0; i < (uint32_t)got; i++, k++)
                    FZ_CHECK(k < out.n && memcmp(&buf[i], &out.t[k], sizeof buf[i]) == 0, "pull = push", k, out.n);
            FZ_CHECK(got == 0 && k == out.n, "pull count", got, k);
            FZ_CHECK(sa.a.used == 0u, "pull: nothing stays in the arena", sa.a.used, 0);
        }
        fz_arena_close(&sa);
        free(out.t);
    }
    fz_snap_check(&snap, "subd_loop_adapt_stream (input mesh)");
    fz_snap_free(&snap);
    fz_arena_close(&ma);
    return 0;
}
