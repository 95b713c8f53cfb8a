/* SPDX-License-Identifier: MIT */
/* PLY reader (src/ply.c): ASCII and binary little-endian files of the icosahedron (made from
 * test/data/icosahedron.obj, with properties and elements to skip) give the OBJ's mesh bit for
 * bit and the same Loop output; binary buffers built here with every count and index type;
 * every malformed case with its status and line or record; every too-small arena. */
#include "harness.h"
#include "corpus.h"

static char ply_buf[4096];
static uint8_t ply_sweep[16u * 1024u] __attribute__((aligned(8)));

static uint32_t slen(const char *s)
{
    uint32_t n = 0;
    while (s[n]) n++;
    return n;
}

static int same_mesh(const subd_mesh *a, const subd_mesh *b)
{
    uint32_t i;
    if (a->num_verts != b->num_verts || a->num_faces != b->num_faces || a->num_corners != b->num_corners) return 0;
    for (i = 0; i < 3u * a->num_verts; i++)
        if (!h_same(a->pos[i], b->pos[i])) return 0;
    for (i = 0; i <= a->num_faces; i++)
        if (a->face_start[i] != b->face_start[i]) return 0;
    for (i = 0; i < a->num_corners; i++)
        if (a->corner_vert[i] != b->corner_vert[i]) return 0;
    return 1;
}

/* Positions and faces (a Loop output has no twin arrays for h_mesh_hash). */
static uint32_t geo_hash(const subd_mesh *m)
{
    uint32_t h = 2166136261u, i, b;
    for (i = 0; i < 3u * m->num_verts; i++) {
        b = subd_real_bits(m->pos[i]);
        h = h_fnv(h, &b, 4);
    }
    return h_fnv(h, m->corner_vert, 4u * m->num_corners);
}

static void ply_same_as_obj(void)
{
    static const char *const files[2] = {"test/data/icosahedron.ply", "test/data/icosahedron_le.ply"};
    const corpus_file *fo = corpus_find("test/data/icosahedron.obj");
    subd_loop_opts o = {2, SUBD_LOOP_BOUNDARY_PAPER, 0};
    subd_arena a;
    subd_mesh m, p, lm, lp;
    subd_diag d;
    uint32_t i, plan;
    if (!CHECK(fo != 0)) return;
    for (i = 0; i < 2u; i++) {
        const corpus_file *f = corpus_find(files[i]);
        if (!CHECK(f != 0)) continue;
        subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
        if (!CHECK_EQ(subd_obj_read(&a, fo->data, fo->len, &m, &d), SUBD_OK)) return;
        if (!CHECK_EQ(subd_ply_plan(f->data, f->len, &plan, &d), SUBD_OK) ||
            !CHECK_EQ(subd_ply_read(&a, f->data, f->len, &p, &d), SUBD_OK)) {
            h_str("    "); h_str(files[i]); h_str(" line "); h_u32(d.line); h_nl();
            continue;
        }
        CHECK(same_mesh(&m, &p));
        CHECK_EQ(h_mesh_hash(&m), h_mesh_hash(&p));
        if (!CHECK_OK(subd_loop(&a, &m, &o, &lm, &d), &d) || !CHECK_OK(subd_loop(&a, &p, &o, &lp, &d), &d)) continue;
        CHECK(same_mesh(&lm, &lp));
        h_hash(i ? "ply_ico_le_loop2" : "ply_ico_ascii_loop2", geo_hash(&lp));
        (void)h_reader_sweep(subd_ply_read, f->data, f->len, ply_sweep, sizeof ply_sweep, plan);
    }
}

/* ------------------------------------------------------------------ binary buffers */

typedef struct wbuf {
    char *p;
    uint32_t n;
} wbuf;

static void w_str(wbuf *w, const char *s)
{
    while (*s) w->p[w->n++] = *s++;
}
static void w_le(wbuf *w, uint64_t v, uint32_t bytes)
{
    uint32_t i;
    for (i = 0; i < bytes; i++) w->p[w->n++] = (char)((v >> (8u * i)) & 0xffu);
}
static uint32_t f32b(float f)
{
    union { float f; uint32_t u; } c;
    c.f = f;
    return c.u;
}
static uint64_t f64b(double x)
{
    union { double d; uint64_t u; } c;
    c.d = x;
    return c.u;
}

/* A unit square of two triangles (0 1 2, 0 2 3) as binary PLY: coordinates float or double,
 * list count type ctype (bytes cb) and index type itype (bytes ib), with an extra scalar
 * before x, a list after z and a trailing element to skip. */
static uint32_t square_bin(char *buf, int dbl, const char *ctype, uint32_t cb, const char *itype, uint32_t ib)
{
    static const int32_t xy[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    static const uint32_t tri[2][3] = {{0, 1, 2}, {0, 2, 3}};
    wbuf w;
    uint32_t v, k;
    w.p = buf;
    w.n = 0;
    w_str(&w, "ply\r\nformat binary_little_endian 1.0\r\ncomment square\r\nelement vertex 4\r\nproperty ushort tag\r\n");
    w_str(&w, dbl ? "property double x\r\nproperty double y\r\nproperty double z\r\n"
                  : "property float32 x\r\nproperty float32 y\r\nproperty float32 z\r\n");
    w_str(&w, "property list uchar int16 extra\r\nelement face 2\r\nproperty list ");
    w_str(&w, ctype);
    w_str(&w, " ");
    w_str(&w, itype);
    w_str(&w, " vertex_indices\r\nproperty double weight\r\nelement junk 2\r\nproperty list uint uchar bytes\r\nend_header\r\n");
    for (v = 0; v < 4u; v++) {
        w_le(&w, 0xbeefu, 2);
        for (k = 0; k < 3u; k++) {
            int32_t c = k < 2u ? xy[v][k] : 0;
            if (dbl) w_le(&w, f64b((double)c * 0.5), 8);
            else w_le(&w, f32b((float)c * 0.5f), 4);
        }
        w_le(&w, v, 1);
        for (k = 0; k < v; k++) w_le(&w, 0xffffu, 2);
    }
    for (v = 0; v < 2u; v++) {
        w_le(&w, 3, cb);
        for (k = 0; k < 3u; k++) w_le(&w, tri[v][k], ib);
        w_le(&w, f64b(1.0), 8);
    }
    w_le(&w, 2, 4);
    w_le(&w, 0x0a0du, 2);
    w_le(&w, 0, 4);
    return w.n;
}

static void ply_binary_types(void)
{
    static const char *const ct[4] = {"uchar", "int", "uint", "ushort"};
    static const uint32_t cb[4] = {1, 4, 4, 2};
    static const char *const it[4] = {"int", "uint", "uint8", "int16"};
    static const uint32_t ib[4] = {4, 4, 1, 2};
    uint32_t i, len, plan;
    subd_arena a;
    subd_mesh m;
    subd_diag d;
    for (i = 0; i < 8u; i++) {
        len = square_bin(ply_buf, (int)(i & 1u), ct[i / 2u], cb[i / 2u], it[(i + 1u) % 4u], ib[(i + 1u) % 4u]);
        subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
        if (!CHECK_EQ(subd_ply_plan(ply_buf, len, &plan, &d), SUBD_OK) ||
            !CHECK_EQ(subd_ply_read(&a, ply_buf, len, &m, &d), SUBD_OK)) {
            h_str("    case "); h_u32(i); h_str(" line "); h_u32(d.line); h_str(" face "); h_u32(d.face); h_nl();
            continue;
        }
        CHECK_EQ(m.num_verts, 4);
        CHECK_EQ(m.num_faces, 2);
        CHECK_EQ(m.corner_vert[4], 2);
        CHECK_EQ(m.corner_vert[5], 3);
        CHECK(h_same(m.pos[6], SUBD_REAL_FRAC(1, 2)) && h_same(m.pos[7], SUBD_REAL_FRAC(1, 2)));
        CHECK_EQ(m.num_edges, 5);
        if (i == 0u) (void)h_reader_sweep(subd_ply_read, ply_buf, len, ply_sweep, sizeof ply_sweep, plan);
    }
}

/* ------------------------------------------------------------------ errors */

/* harness.c's h_reader_expect for the PLY reader (vertex checked too). */
static int expect_ply(const char *buf, uint32_t len, int st, uint32_t line, uint32_t face, uint32_t vert, int src)
{
    return h_reader_expect(subd_ply_read, subd_ply_plan, buf, len, H_ARENA_BYTES, st, line, face, vert, src);
}
#define EXPECT_LINE(txt, st, line) expect_ply((txt), slen(txt), (st), (line), SUBD_NONE, SUBD_NONE, __LINE__)

#define HEAD "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
#define FACES "element face 2\nproperty list uchar int vertex_indices\nend_header\n"
#define VERTS "0 0 0\n1 0 0\n1 1 0\n0 1 0\n"

static void ply_ascii_errors(void)
{
    subd_arena a;
    subd_mesh m;
    subd_diag d;
    static const char ok[] = HEAD FACES VERTS "3 0 1 2\n\n3 0 2 3\n\n";
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    if (CHECK_EQ(subd_ply_read(&a, ok, slen(ok), &m, &d), SUBD_OK)) CHECK_EQ(m.num_edges, 5);
    /* header */
    EXPECT_LINE("", SUBD_ERR_EMPTY, 1);
    EXPECT_LINE("plx\n", SUBD_ERR_PARSE, 1);
    EXPECT_LINE("ply\nformat binary_big_endian 1.0\nelement vertex 1\nproperty float x\nend_header\n", SUBD_ERR_PARSE, 2);
    EXPECT_LINE("ply\nformat utf8 1.0\nend_header\n", SUBD_ERR_PARSE, 2);
    EXPECT_LINE("ply\nformat ascii 2.0\nend_header\n", SUBD_ERR_PARSE, 2);
    EXPECT_LINE("ply\nelement vertex 1\n", SUBD_ERR_PARSE, 2); /* element before format */
    EXPECT_LINE("ply\nformat ascii 1.0\nproperty float x\n", SUBD_ERR_PARSE, 3);
    EXPECT_LINE("ply\nformat ascii 1.0\nelement vertex 4\nproperty float128 x\n", SUBD_ERR_PARSE, 4);
    EXPECT_LINE("ply\nformat ascii 1.0\nelement vertex 4\nproperty int x\n", SUBD_ERR_PARSE, 4);
    EXPECT_LINE("ply\nformat ascii 1.0\nelement vertex 4\nproperty list uchar float x\n", SUBD_ERR_PARSE, 4);
    EXPECT_LINE("ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float x\n", SUBD_ERR_PARSE, 5);
    EXPECT_LINE("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n0 0\n",
                SUBD_ERR_PARSE, 3); /* no z */
    EXPECT_LINE(HEAD "element face 2\nproperty list float int vertex_indices\n", SUBD_ERR_PARSE, 8);
    EXPECT_LINE(HEAD "element face 2\nproperty list uchar float vertex_indices\n", SUBD_ERR_PARSE, 8);
    EXPECT_LINE(HEAD "element face 2\nproperty int vertex_indices\nend_header\n", SUBD_ERR_PARSE, 8);
    EXPECT_LINE(HEAD "element face 2\nelement vertex 3\n", SUBD_ERR_PARSE, 8);
    EXPECT_LINE(HEAD "element face -2\n", SUBD_ERR_PARSE, 7);
    EXPECT_LINE(HEAD "bogus\n", SUBD_ERR_PARSE, 7);
    EXPECT_LINE(HEAD FACES "junk", SUBD_ERR_PARSE, 10);
    EXPECT_LINE(HEAD "element face 2\nproperty list uchar int vertex_indices\n", SUBD_ERR_PARSE, 9); /* no end_header */
    EXPECT_LINE("ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\nproperty float z\nend_header\n",
                SUBD_ERR_EMPTY, 7);
    /* body: the record's line */
    EXPECT_LINE(HEAD FACES VERTS "3 0 1 4\n3 0 2 3\n", SUBD_ERR_INDEX, 14);
    EXPECT_LINE(HEAD FACES VERTS "3 0 1 2\n3 0 -2 3\n", SUBD_ERR_INDEX, 15);
    EXPECT_LINE(HEAD FACES VERTS "3 0 1 2\n3 0 2 99999999999\n", SUBD_ERR_INDEX, 15);
    EXPECT_LINE(HEAD FACES VERTS "2 0 1\n3 0 2 3\n", SUBD_ERR_FACE_SIZE, 14);
    EXPECT_LINE(HEAD FACES VERTS "3 0 1 2 3\n3 0 2 3\n", SUBD_ERR_PARSE, 14);
    EXPECT_LINE(HEAD FACES VERTS "3 0 1\n3 0 2 3\n", SUBD_ERR_PARSE, 14);
    EXPECT_LINE(HEAD FACES VERTS "3 0 1 2\n", SUBD_ERR_PARSE, 15);
    EXPECT_LINE(HEAD FACES VERTS "3 0 1 2\n3 0 2 3\n0\n", SUBD_ERR_PARSE, 16);
    EXPECT_LINE(HEAD FACES "0 0 0\n1 nan 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n", SUBD_ERR_NAN, 11);
    EXPECT_LINE(HEAD FACES "0 0 0\n1 0 0\n1 1 1e39\n0 1 0\n3 0 1 2\n3 0 2 3\n", SUBD_ERR_RANGE, 12);
    if (SUBD_FIXED) EXPECT_LINE(HEAD FACES "0 0 0\n1 0 0\n1 1 40000\n0 1 0\n3 0 1 2\n3 0 2 3\n", SUBD_ERR_RANGE, 12);
    EXPECT_LINE(HEAD FACES "0 0 0\n1 0 0x\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n", SUBD_ERR_PARSE, 11);
    /* validation: the face's line, and subd_ply_line_of agrees */
    {
        static const char flip[] = HEAD FACES VERTS "3 0 1 2\n\n3 0 3 2\n";
        if (expect_ply(flip, slen(flip), SUBD_ERR_ORIENTATION, 16, 1, SUBD_NONE, __LINE__)) {
            subd_diag q;
            subd_diag_clear(&q);
            q.face = 1;
            CHECK_EQ(subd_ply_line_of(flip, slen(flip), &q), 16);
            q.face = SUBD_NONE;
            q.vertex = 2;
            CHECK_EQ(subd_ply_line_of(flip, slen(flip), &q), 12);
            q.vertex = 9;
            CHECK_EQ(subd_ply_line_of(flip, slen(flip), &q), 0);
        }
    }
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    CHECK_FAIL(subd_ply_read(&a, 0, 3, &m, &d), &d, SUBD_ERR_PARAM);
    CHECK_FAIL(subd_ply_plan(ok, slen(ok), 0, &d), &d, SUBD_ERR_PARAM);
}

static void ply_binary_errors(void)
{
    uint32_t len, hlen, vrec = 2u + 12u, n;
    const char *eh;
    len = square_bin(ply_buf, 0, "uchar", 1, "int", 4);
    /* the body starts after end_header's line; records: vertex v = 2 + 12 + 1 + 2v bytes */
    for (eh = ply_buf; !(eh[0] == 'e' && eh[1] == 'n' && eh[2] == 'd' && eh[3] == '_'); eh++) {}
    hlen = (uint32_t)(eh - ply_buf) + 12u; /* "end_header\r\n" */
    /* truncated inside vertex 1, inside face 1, inside junk; trailing bytes */
    expect_ply(ply_buf, hlen + vrec + 1u + 5u, SUBD_ERR_PARSE, 0, SUBD_NONE, 1, __LINE__);
    n = hlen + 4u * (vrec + 1u) + 2u * (0u + 1u + 2u + 3u);
    expect_ply(ply_buf, n + 21u + 3u, SUBD_ERR_PARSE, 0, 1, SUBD_NONE, __LINE__);
    expect_ply(ply_buf, len - 1u, SUBD_ERR_PARSE, 13, SUBD_NONE, SUBD_NONE, __LINE__);
    ply_buf[len] = 0;
    expect_ply(ply_buf, len + 1u, SUBD_ERR_PARSE, 15, SUBD_NONE, SUBD_NONE, __LINE__);
    /* a coordinate NaN, an index out of range, a face of 2, a negative count */
    ply_buf[hlen + 2u * (vrec + 1u) + 2u + 2u + 4u + 3u] = (char)0x7f;
    ply_buf[hlen + 2u * (vrec + 1u) + 2u + 2u + 4u + 2u] = (char)0xc0;
    expect_ply(ply_buf, len, SUBD_ERR_NAN, 0, SUBD_NONE, 2, __LINE__);
    len = square_bin(ply_buf, 0, "uchar", 1, "int", 4);
    ply_buf[n + 21u + 1u + 8u] = 4;
    expect_ply(ply_buf, len, SUBD_ERR_INDEX, 0, 1, SUBD_NONE, __LINE__);
    ply_buf[n + 21u + 1u + 8u + 3u] = (char)0x80; /* negative */
    expect_ply(ply_buf, len, SUBD_ERR_INDEX, 0, 1, SUBD_NONE, __LINE__);
    len = square_bin(ply_buf, 0, "char", 1, "int", 4);
    n -= 1u; /* "char" is one letter shorter than "uchar" */
    ply_buf[n + 21u] = (char)0xff; /* count -1 */
    expect_ply(ply_buf, len, SUBD_ERR_PARSE, 0, 1, SUBD_NONE, __LINE__);
    ply_buf[n + 21u] = 2;
    expect_ply(ply_buf, len, SUBD_ERR_FACE_SIZE, 0, 1, SUBD_NONE, __LINE__);
    /* double out of range: both arithmetics */
    len = square_bin(ply_buf, 1, "uchar", 1, "int", 4);
    {
        wbuf w;
        for (eh = ply_buf; !(eh[0] == 'e' && eh[1] == 'n' && eh[2] == 'd' && eh[3] == '_'); eh++) {}
        w.p = ply_buf;
        w.n = (uint32_t)(eh - ply_buf) + 12u + 3u * (2u + 24u + 1u) + 2u * 3u + 2u + 16u;
        w_le(&w, f64b(1e300), 8);
        expect_ply(ply_buf, len, SUBD_ERR_RANGE, 0, SUBD_NONE, 3, __LINE__);
    }
}

const test_case suite_ply[] = {
    {"ply_same_as_obj", ply_same_as_obj},
    {"ply_binary_types", ply_binary_types},
    {"ply_ascii_errors", ply_ascii_errors},
    {"ply_binary_errors", ply_binary_errors},
    {0, 0}
};
