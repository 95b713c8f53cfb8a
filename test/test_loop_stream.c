/* SPDX-License-Identifier: MIT */
/* Streaming Loop (subd_loop_stream) against the materialising call, subd_loop: on every corpus
 * shape (closed, open, creases, corners, valence 3 and >= 12, isolated vertices), levels 1..4,
 * both boundary rules, the j-th streamed triangle must be subd_loop's face j with the same
 * corners, bit-identical positions, and ids that map one-to-one onto subd_loop's vertices
 * (checked both ways: one id per vertex, one vertex per id) and follow the documented closed
 * form for control vertices. Plus: the plan depends on levels and valence only and equals
 * SUBD_LOOP_STREAM_BYTES; every smaller arena fails with SUBD_ERR_NOMEM before anything is
 * emitted; a sink that stops after k triangles gets k and its status back. */
#include "harness.h"
#include "corpus.h"
#include "../src/loop_tile.h"

/* A tetrahedron (valence 3) and a cube of triangles (valence 4 and 5) as OBJ text. */
static const char tet_obj[] = "v 1 1 1\nv 1 -1 -1\nv -1 1 -1\nv -1 -1 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n";
static const char cube_obj[] =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
    "f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 2 3 7\nf 2 7 6\nf 3 4 8\nf 3 8 7\n"
    "f 4 1 5\nf 4 5 8\n";
/* Two triangles and an isolated vertex between them. */
static const char iso_obj[] = "v 0 0 0\nv 1 0 0\nv 9 9 9\nv 1 1 0\nv 0 1 0.5\nf 1 2 4\nf 1 4 5\n";

enum { S_TET, S_CUBE_CREASE, S_ICO, S_HEXFAN, S_FAN64, S_GRID_CREASE, S_ISO, S_TORUS, S_TORUS_CREASE, S_COUNT };
#define S_DEVICE S_TORUS /* shapes 0..S_DEVICE-1 run on the device too, the rest on the host */

static int load_text(subd_arena *a, const char *txt, subd_mesh *m)
{
    subd_diag d;
    uint32_t n = 0;
    while (txt[n]) n++;
    return CHECK_EQ(subd_obj_read(a, txt, n, m, &d), SUBD_OK);
}

static int load_file(subd_arena *a, const char *name, subd_mesh *m)
{
    const corpus_file *f = corpus_find(name);
    subd_diag d;
    if (!CHECK(f != 0)) return 0;
    return CHECK_EQ(subd_obj_read(a, f->data, f->len, m, &d), SUBD_OK);
}

/* Creases on every `every`-th interior edge (both halves) and two corner tags. */
static void tag_features(subd_mesh *m, uint32_t every)
{
    uint32_t h, k = 0;
    for (h = 0; h < m->num_corners; h++)
        if (m->twin[h] != SUBD_NONE && h < m->twin[h] && k++ % every == 0u) subd_edge_tag_set(m, h, SUBD_ETAG_CREASE);
    m->vert_tag[0] = (uint8_t)(m->vert_tag[0] | SUBD_VTAG_CORNER);
    m->vert_tag[m->num_verts - 1u] = (uint8_t)(m->vert_tag[m->num_verts - 1u] | SUBD_VTAG_CORNER);
}

static int make_shape(int id, subd_arena *a, subd_mesh *m)
{
    int ok;
    switch (id) {
    case S_TET: return load_text(a, tet_obj, m);
    case S_CUBE_CREASE:
        if (!(ok = load_text(a, cube_obj, m))) return 0;
        tag_features(m, 2);
        return 1;
    case S_ICO: return load_file(a, "test/data/icosahedron.obj", m);
    case S_HEXFAN: return load_file(a, "test/data/hexfan.obj", m);
    case S_FAN64: return load_file(a, "test/data/fan64.obj", m);
    case S_GRID_CREASE:
        if (!(ok = load_file(a, "test/data/grid_tri_8x8.obj", m))) return 0;
        tag_features(m, 5);
        return 1;
    case S_ISO: return load_text(a, iso_obj, m);
    case S_TORUS: return load_file(a, "test/data/torus_tri.obj", m);
    default:
        if (!(ok = load_file(a, "test/data/torus_tri.obj", m))) return 0;
        tag_features(m, 3);
        return 1;
    }
}

/* The sink of the comparison: triangle j against face j of subd_loop's output. */
typedef struct cmp_sink {
    const subd_mesh *ref;
    const subd_real *lpos, *lnrm; /* limit mode: subd_loop_limit of ref (else NULL)     */
    uint64_t *v2id;   /* ref vertex -> id seen for it, UINT64_MAX before */
    uint32_t j, bad_pos, bad_id, stop_after;
    uint32_t hash;
} cmp_sink;

static int cmp_tri(void *ctx, const subd_loop_tri *t)
{
    cmp_sink *s = (cmp_sink *)ctx;
    uint32_t c, k;
    if (s->j >= s->ref->num_faces) {
        s->bad_pos++;
        return 0;
    }
    for (c = 0; c < 3u; c++) {
        uint32_t v = s->ref->corner_vert[3u * s->j + c];
        for (k = 0; k < 3u; k++) {
            uint32_t b = subd_real_bits(t->pos[c][k]);
            const subd_real *want = s->lpos ? s->lpos : s->ref->pos;
            if (!h_same(t->pos[c][k], want[3u * v + k])) s->bad_pos++;
            if (s->lnrm && !h_same(t->normal[c][k], s->lnrm[3u * v + k])) s->bad_pos++;
            if (!s->lnrm && !h_same(t->normal[c][k], 0)) s->bad_pos++;
            s->hash = h_fnv(s->hash, &b, 4);
        }
        if (s->v2id[v] == UINT64_MAX) s->v2id[v] = t->id[c];
        else if (s->v2id[v] != t->id[c]) s->bad_id++;
    }
    s->j++;
    return (s->stop_after && s->j == s->stop_after) ? 7 : 0;
}

/* In-place ascending sort of n ids (shell sort; the test's own, no qsort). */
static void sort_ids(uint64_t *x, uint32_t n)
{
    uint32_t gap, i, j;
    for (gap = n / 2u; gap > 0u; gap /= 2u)
        for (i = gap; i < n; i++) {
            uint64_t v = x[i];
            for (j = i; j >= gap && x[j - gap] > v; j -= gap) x[j] = x[j - gap];
            x[j] = v;
        }
}

static uint32_t g_streams, g_skipped;

#if H_HOST
/* The host compares the bigger cases (the torus at level 4: 5.5 MB of subd_loop output). */
#define BIG_ARENA_BYTES (24u * 1024u * 1024u)
static uint8_t big_arena[BIG_ARENA_BYTES] __attribute__((aligned(8)));
#define CMP_BUF big_arena
#define CMP_BYTES BIG_ARENA_BYTES
#else
#define CMP_BUF h_arena_buf
#define CMP_BYTES H_ARENA_BYTES
#endif

/* Streams `in` at `levels` with rule b and compares with subd_loop. Returns 0 when the
 * arena cannot hold subd_loop's output (the case is skipped and counted). */
static int compare_one(subd_arena *a, const subd_mesh *in, uint32_t levels, subd_loop_boundary b, uint32_t flags,
                       uint32_t *hash)
{
    subd_loop_opts o, so;
    subd_mesh ref;
    subd_diag d;
    uint32_t plan, splan, mark = subd_arena_mark(a), v, nid = 0, used;
    cmp_sink s;
    subd_loop_sink sink;
    uint64_t *ids;
    int st;
    subd_diag_clear(&d);
    o.levels = levels;
    o.boundary = b;
    o.flags = flags & SUBD_LOOP_STREAM_LIMIT ? SUBD_LOOP_ADJACENCY : 0u; /* the reference */
    so = o;
    so.flags = flags;
    if (!CHECK_OK(subd_loop_plan(in, &o, &plan, 0), &d) || !CHECK_OK(subd_loop_stream_plan(in, &so, &splan, 0), &d)) return 0;
    if ((uint64_t)plan + splan + 16u * 1024u > subd_arena_free_bytes(a)) {
        g_skipped++;
        return 0;
    }
    if (!CHECK_OK(subd_loop(a, in, &o, &ref, &d), &d)) return 0;
    s.lpos = s.lnrm = 0;
    if (flags & SUBD_LOOP_STREAM_LIMIT) {
        subd_real *lp = 0, *ln = 0;
        uint32_t lplan;
        if (!CHECK_OK(subd_loop_limit_plan(&ref, &(subd_loop_limit_opts){b, SUBD_LOOP_LIMIT_NORMALS}, &lplan, 0), &d)) return 0;
        if ((uint64_t)lplan + ref.num_verts * 8u + splan + 64u > subd_arena_free_bytes(a)) {
            subd_arena_rewind(a, mark);
            g_skipped++;
            return 0;
        }
        if (!CHECK_OK(subd_loop_limit(a, &ref, &(subd_loop_limit_opts){b, SUBD_LOOP_LIMIT_NORMALS}, &lp, &ln, &d), &d)) return 0;
        s.lpos = lp;
        s.lnrm = ln;
    }
    if ((uint64_t)ref.num_verts * 8u + splan + 64u > subd_arena_free_bytes(a)) {
        subd_arena_rewind(a, mark);
        g_skipped++;
        return 0;
    }
    ids = (uint64_t *)subd_arena_alloc(a, ref.num_verts * 8u);
    for (v = 0; v < ref.num_verts; v++) ids[v] = UINT64_MAX;
    s.ref = &ref;
    s.v2id = ids;
    s.j = s.bad_pos = s.bad_id = s.stop_after = 0;
    s.hash = *hash;
    sink.tri = cmp_tri;
    sink.ctx = &s;
    used = subd_arena_mark(a);
    subd_arena_reset_peak(a);
    st = subd_loop_stream(a, in, &so, &sink, &d);
    CHECK_OK(st, &d);
    CHECK_EQ(subd_arena_mark(a), used);          /* nothing left in the arena */
    CHECK(a->peak - used <= splan);                /* the plan holds */
    CHECK_EQ(s.j, ref.num_faces);                  /* every triangle, once */
    CHECK_EQ(s.bad_pos, 0);                        /* same corners, same bits */
    CHECK_EQ(s.bad_id, 0);                         /* one id per vertex */
    /* control vertices keep their ids; no two vertices share one */
    for (v = 0; v < ref.num_verts; v++) {
        if (ids[v] == UINT64_MAX) continue; /* isolated */
        if (v < in->num_verts && !CHECK_EQ(ids[v], v)) break;
        ids[nid++] = ids[v];
    }
    CHECK_EQ(nid, ref.num_verts - ref.num_isolated);
    sort_ids(ids, nid);
    for (v = 1; v < nid; v++)
        if (!CHECK(ids[v - 1u] < ids[v])) break;
    *hash = s.hash;
    g_streams++;
    subd_arena_rewind(a, mark);
    return 1;
}

static void stream_equals_loop(void)
{
    int id;
    uint32_t hash = 2166136261u, lim;
    g_streams = g_skipped = 0;
    for (id = 0; id < (H_HOST ? S_COUNT : S_DEVICE); id++) {
        subd_arena a;
        subd_mesh in;
        uint32_t levels;
        subd_arena_init(&a, CMP_BUF, CMP_BYTES);
        if (!make_shape(id, &a, &in)) return;
        for (lim = 0; lim < 2u; lim++)
            for (levels = 1; levels <= (lim ? 3u : 4u); levels++) {
                compare_one(&a, &in, levels, SUBD_LOOP_BOUNDARY_PAPER, lim ? SUBD_LOOP_STREAM_LIMIT : 0u, &hash);
                compare_one(&a, &in, levels, SUBD_LOOP_BOUNDARY_BSPLINE, lim ? SUBD_LOOP_STREAM_LIMIT : 0u, &hash);
            }
    }
    CHECK(g_streams >= (H_HOST ? 126u : 60u)); /* the host runs every case; say how many */
    h_str("  streams compared ");
    h_u32(g_streams);
    h_str(", skipped (subd_loop's output too big for the test arena) ");
    h_u32(g_skipped);
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
        if (!make_shape(id, &a, &in)) return;
        compare_one(&a, &in, 2, SUBD_LOOP_BOUNDARY_PAPER, 0, &hash);
        compare_one(&a, &in, 3, SUBD_LOOP_BOUNDARY_BSPLINE, 0, &hash);
        compare_one(&a, &in, 2, SUBD_LOOP_BOUNDARY_PAPER, SUBD_LOOP_STREAM_LIMIT, &hash);
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
    if (!make_shape(S_ICO, &a, &ico) || !make_shape(S_TET, &a, &tet) || !make_shape(S_CUBE_CREASE, &a, &cube) ||
        !make_shape(S_FAN64, &a, &fan))
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

static int count_tri(void *ctx, const subd_loop_tri *t)
{
    (void)t;
    (*(uint32_t *)ctx)++;
    return 0;
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
    if (!make_shape(S_CUBE_CREASE, &a, &in)) return;
    o.levels = 3;
    o.boundary = SUBD_LOOP_BOUNDARY_PAPER;
    o.flags = 0;
    if (!CHECK_OK(subd_loop_stream_plan(&in, &o, &plan, 0), &d)) return;
    buf = (uint8_t *)subd_arena_alloc(&a, plan);
    if (!CHECK(buf != 0)) return;
    sink.tri = count_tri;
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
    if (!make_shape(S_ICO, &a, &in)) return;
    o.levels = 2;
    o.boundary = SUBD_LOOP_BOUNDARY_PAPER;
    o.flags = 0;
    if (!CHECK_OK(subd_loop(&a, &in, &o, &ref, &d), &d)) return;
    (void)ids;
    for (k = 0; k < sizeof stops / sizeof stops[0]; k++) {
        uint64_t *v2id = (uint64_t *)subd_arena_alloc(&a, ref.num_verts * 8u);
        uint32_t v, mark;
        if (!CHECK(v2id != 0)) return;
        for (v = 0; v < ref.num_verts; v++) v2id[v] = UINT64_MAX;
        s.ref = &ref;
        s.lpos = s.lnrm = 0;
        s.v2id = v2id;
        s.j = s.bad_pos = s.bad_id = 0;
        s.stop_after = stops[k];
        s.hash = 0;
        sink.tri = cmp_tri;
        sink.ctx = &s;
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
    if (!make_shape(S_ICO, &a, &in) || !load_file(&a, "test/data/cube_quad.obj", &quad)) return;
    o.levels = 2;
    o.boundary = SUBD_LOOP_BOUNDARY_PAPER;
    o.flags = 0;
    sink.tri = count_tri;
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
    sink.tri = count_tri;
    sink.ctx = &count;
    CHECK_EQ(subd_loop_stream(&a, &in, &o, &sink, &d), want);
    CHECK_EQ(subd_arena_mark(&a), mark);
    if (want != SUBD_OK) CHECK(d.face < in.num_faces);
    else CHECK_EQ(count, 4u * in.num_faces);
}

/* ------------------------------------------------------------------------------------ */
/* Regular tiles (src/loop_tile.c) meeting irregular patches                              */

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
    uint32_t ovf = 0;
    if (!CHECK(blk != 0 && tb != 0)) return 0;
    wc.have = 0;
    p.h = &head;
    p.pos = (subd_real *)(void *)(blk + off[A_POS]);
    p.vflag = blk + off[A_VFLAG];
    p.vout = (uint16_t *)(void *)(blk + off[A_VOUT]);
    p.cv = (uint16_t *)(void *)(blk + off[A_CV]);
    p.tw = (uint16_t *)(void *)(blk + off[A_TW]);
    p.slot = (uint16_t *)(void *)(blk + off[A_SLOT]);
    p.sh = blk + off[A_SH];
    p.cpos = 0;
    p.cflag = 0;
    p.cface = (uint32_t *)(void *)(blk + off[A_CFACE]);
    p.cvert = (uint32_t *)(void *)(blk + off[A_CVERT]);
    subd_lt_carve(&tl, tb, 0, 4u, 0); /* subd_lt_start needs no table */
    for (f = 0; f < m->num_faces; f++) {
        int r;
        subd_lp_build_control(m, f, &p, 4u);
        r = subd_lt_start(&tl, &p, &wc, &ovf);
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
    g_streams = g_skipped = 0;
    for (id = 0; id < 2u; id++) {
        subd_arena a;
        subd_mesh in;
        subd_arena_init(&a, CMP_BUF, CMP_BYTES);
        if (!make_grid(&a, 6u, id == 0u, id == 1u, &in)) return;
        nreg = count_tiles(&a, &in);
        CHECK(nreg > 0u && nreg < in.num_faces);
        for (levels = 2; levels <= 3u; levels++) {
            compare_one(&a, &in, levels, SUBD_LOOP_BOUNDARY_PAPER, 0, &hash);
            compare_one(&a, &in, levels, SUBD_LOOP_BOUNDARY_BSPLINE, 0, &hash);
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
            compare_one(&a, &in, levels, SUBD_LOOP_BOUNDARY_PAPER, 0, &hash);
            compare_one(&a, &in, levels, SUBD_LOOP_BOUNDARY_BSPLINE, 0, &hash);
        }
    }
    {
        subd_arena a;
        subd_mesh in;
        subd_arena_init(&a, CMP_BUF, CMP_BYTES);
        if (!make_shape(S_ICO, &a, &in)) return;
        compare_one(&a, &in, 6, SUBD_LOOP_BOUNDARY_PAPER, 0, &hash);
        subd_arena_init(&a, CMP_BUF, CMP_BYTES);
        if (!make_shape(S_TORUS, &a, &in)) return;
        CHECK_EQ(count_tiles(&a, &in), in.num_faces); /* valence 6 everywhere */
        compare_one(&a, &in, 4, SUBD_LOOP_BOUNDARY_PAPER, 0, &hash);
    }
    CHECK_EQ(g_skipped, 0);
    CHECK_EQ(g_streams, 8u + 2u * 4u + 2u); /* level 6 of the grids: stream_level6 */
#else
    CHECK_EQ(g_streams + g_skipped, 8u);
#endif
    h_str("  tile streams compared ");
    h_u32(g_streams);
    h_str(", skipped ");
    h_u32(g_skipped);
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
    g_streams = g_skipped = 0;
    for (id = 0; id < 2u; id++) {
        subd_arena a;
        subd_mesh in;
        subd_arena_init(&a, CMP_BUF, CMP_BYTES);
        if (!make_grid(&a, 6u, id == 0u, id == 1u, &in)) return;
        compare_one(&a, &in, 2, SUBD_LOOP_BOUNDARY_PAPER, SUBD_LOOP_STREAM_LIMIT, &hash);
        compare_one(&a, &in, 2, SUBD_LOOP_BOUNDARY_BSPLINE, SUBD_LOOP_STREAM_LIMIT, &hash);
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
            compare_one(&a, &in, levels, SUBD_LOOP_BOUNDARY_PAPER, SUBD_LOOP_STREAM_LIMIT, &hash);
            compare_one(&a, &in, levels, SUBD_LOOP_BOUNDARY_BSPLINE, SUBD_LOOP_STREAM_LIMIT, &hash);
        }
    }
    {
        subd_arena a;
        subd_mesh in;
        subd_arena_init(&a, CMP_BUF, CMP_BYTES);
        if (!make_shape(S_ICO, &a, &in)) return;
        compare_one(&a, &in, 6, SUBD_LOOP_BOUNDARY_PAPER, SUBD_LOOP_STREAM_LIMIT, &hash);
        subd_arena_init(&a, CMP_BUF, CMP_BYTES);
        if (!make_shape(S_TORUS, &a, &in)) return;
        compare_one(&a, &in, 4, SUBD_LOOP_BOUNDARY_BSPLINE, SUBD_LOOP_STREAM_LIMIT, &hash);
    }
    CHECK_EQ(g_skipped, 0);
    CHECK_EQ(g_streams, 4u + 2u * 6u + 2u); /* level 6 of the grids: stream_level6 */
#else
    CHECK_EQ(g_skipped, 0);
    CHECK_EQ(g_streams, 4u);
#endif
    h_str("  limit tile streams compared ");
    h_u32(g_streams);
    h_str(", skipped ");
    h_u32(g_skipped);
    h_nl();
}

/* The position hash of cmp_tri (each corner's three coordinates in emission order) without
 * a reference: the device's side of stream_level6. */
/* Tiles near the top of the range (src/loop_tile.c, LT_HUGE): the tile's rules are not
 * checked for overflow (convex combinations of the patch's level-0 points), so a patch with
 * a coordinate beyond SUBD_REAL_MAX / 2 must take the checked general path. The flipped grid
 * moved to coordinates 0.375..0.45 SUBD_REAL_MAX (every regular patch tiled, unchecked) and
 * 0.925..1.0 SUBD_REAL_MAX (every patch refused, the general path): the stream's status is
 * subd_loop's, and
 * when both succeed the bits are (compare_one), levels 2 and 3, plain and limit. Q16.16 has
 * no such patches (LT_HUGE is 0 there): the same scaled grids check it too. */
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
                sink.tri = count_tri;
                sink.ctx = &count;
                if (lim && want == SUBD_OK) { /* the limit reference may overflow where the levels do not */
                    if (compare_one(&a, &in, levels, SUBD_LOOP_BOUNDARY_PAPER, SUBD_LOOP_STREAM_LIMIT, &hash)) continue;
                    CHECK_EQ(subd_arena_mark(&a), mark);
                    continue;
                }
                CHECK_EQ(subd_loop_stream(&a, &in, &o, &sink, &d), want);
                CHECK_EQ(subd_arena_mark(&a), mark);
                if (want == SUBD_OK && !lim) CHECK(compare_one(&a, &in, levels, SUBD_LOOP_BOUNDARY_PAPER, 0, &hash));
                if (!SUBD_FIXED && s == 0u) CHECK_EQ(want, SUBD_OK); /* 0.45: in range everywhere */
            }
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
    g_streams = g_skipped = 0;
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
                CHECK(compare_one(&a, &in, 6, b, fl, &hash));
                CHECK_EQ(own, hash); /* the device's hash is the checked one */
#endif
                hash = own;
            }
            h_hash(names[2u * id + lim], hash);
        }
#if H_HOST
    CHECK_EQ(g_streams, 4u);
    CHECK_EQ(g_skipped, 0);
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
    if (!make_shape(S_ICO, &a, &in)) return;
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
            compare_one(&a, &in, levels, SUBD_LOOP_BOUNDARY_PAPER, fl, &hash);
            compare_one(&a, &in, levels, SUBD_LOOP_BOUNDARY_BSPLINE, fl, &hash);
        }
    CHECK_EQ(g_skipped, 0);
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
    uint32_t hash = 2166136261u, levels, k, g0 = g_streams;
    subd_arena a;
    subd_mesh in;
    subd_diag d;
    static const uint32_t stops[] = {1, 15, 16, 17, 250};
    subd_diag_clear(&d);
    subd_arena_init(&a, CMP_BUF, CMP_BYTES);
    if (!load_file(&a, "test/data/nefertiti_patch.obj", &in)) return;
    CHECK_EQ(in.num_verts, 115u);
    for (levels = 1; levels <= 4u; levels++) {
        compare_one(&a, &in, levels, SUBD_LOOP_BOUNDARY_PAPER, 0u, &hash);
        if (levels <= 3u) compare_one(&a, &in, levels, SUBD_LOOP_BOUNDARY_BSPLINE, 0u, &hash);
    }
    for (k = 0; k < sizeof stops / sizeof stops[0]; k++) {
        subd_loop_opts o;
        subd_loop_sink sink;
        uint32_t n = 0, mark = subd_arena_mark(&a);
        cmp_sink s;
        subd_mesh ref;
        uint64_t *v2id;
        o.levels = H_HOST ? 3u : 2u; /* the device's test arena holds subd_loop's level 2 */
        o.boundary = SUBD_LOOP_BOUNDARY_PAPER;
        o.flags = 0;
        if (!CHECK_OK(subd_loop(&a, &in, &o, &ref, &d), &d)) return;
        v2id = (uint64_t *)subd_arena_alloc(&a, ref.num_verts * 8u);
        if (!CHECK(v2id != 0)) return;
        for (n = 0; n < ref.num_verts; n++) v2id[n] = UINT64_MAX;
        s.ref = &ref;
        s.lpos = s.lnrm = 0;
        s.v2id = v2id;
        s.j = s.bad_pos = s.bad_id = 0;
        s.stop_after = stops[k];
        s.hash = 0;
        sink.tri = cmp_tri;
        sink.ctx = &s;
        CHECK_EQ(subd_loop_stream(&a, &in, &o, &sink, &d), 7);
        CHECK_EQ(d.face, (stops[k] - 1u) >> (2u * o.levels)); /* 4^L triangles per control face */
        CHECK_EQ(s.j, stops[k]);
        CHECK_EQ(s.bad_pos, 0);
        CHECK_EQ(s.bad_id, 0);
        subd_arena_rewind(&a, mark);
    }
    h_str("  irregular disk: streams compared ");
    h_u32(g_streams - g0);
    h_nl();
    (void)hash;
}

const test_case suite_loop_stream[] = {
    {"stream_equals_loop", stream_equals_loop},
    {"stream_hashes", stream_hashes},
    {"stream_plan", stream_plan},
    {"stream_small_arenas", stream_small_arenas},
    {"stream_sink_stop", stream_sink_stop},
    {"stream_errors", stream_errors},
    {"stream_range", stream_range},
    {"stream_tiles", stream_tiles},
    {"stream_tiles_limit", stream_tiles_limit},
    {"stream_tiles_huge", stream_tiles_huge},
    {"stream_level6", stream_level6},
    {"stream_tiles_partial", stream_tiles_partial},
    {"stream_tiles_limit5", stream_tiles_limit5},
    {"stream_irregular", stream_irregular},
    {0, 0},
};
