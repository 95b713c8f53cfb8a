/* SPDX-License-Identifier: MIT */
/* STL reader and writer (src/stl.c) and the IEEE bits conversions they use (src/real_bits.c).
 *
 * References are independent of the code under test: the conversions against double
 * arithmetic (float32: C's correctly rounded double -> float; Q16.16: x * 65536 exact in
 * double, rounded half away from zero by truncation and the exact fraction); STL read back
 * against the OBJ the data came from (corner positions bit for bit, the topology counts, and
 * Loop output compared as a set of triangles, since welding numbers vertices by first use);
 * every malformed case with its status and record; every too-small arena. */
#include "harness.h"
#include "corpus.h"

#define IO_BUF 20000u
static char io_buf[IO_BUF];
static char io_buf2[1024];
static uint8_t io_sweep[16u * 1024u] __attribute__((aligned(8)));

static uint32_t slen(const char *s)
{
    uint32_t n = 0;
    while (s[n]) n++;
    return n;
}

static int read_corpus_obj(subd_arena *a, const char *name, subd_mesh *m)
{
    const corpus_file *f = corpus_find(name);
    subd_diag d;
    if (!CHECK(f != 0)) return 0;
    return CHECK_EQ(subd_obj_read(a, f->data, f->len, m, &d), SUBD_OK);
}

/* ---------------------------------------------------------------------------- bits */

static float f_of(uint32_t b)
{
    union { uint32_t u; float f; } c;
    c.u = b;
    return c.f;
}

static double d_of(uint64_t b)
{
    union { uint64_t u; double d; } c;
    c.u = b;
    return c.d;
}

/* Reference: the subd_real nearest to the double v (finite), or SUBD_ERR_RANGE. */
static int ref_real(double v, subd_real *out)
{
    if (SUBD_FIXED) {
        double x = v * 65536.0, ax = x < 0.0 ? -x : x, fr;
        int64_t r;
        if (ax >= 2147483649.0) return SUBD_ERR_RANGE;
        r = (int64_t)ax;
        fr = ax - (double)r; /* exact */
        if (fr >= 0.5) r++;
        if (x < 0.0) r = -r;
        if (r > 2147483647 || r < -2147483647 - 1) return SUBD_ERR_RANGE;
        *out = (subd_real)r;
    } else {
        float f = (float)v;
        uint32_t b;
        union { float f; uint32_t u; } c;
        c.f = f;
        b = c.u;
        if ((b & 0x7f800000u) == 0x7f800000u) return SUBD_ERR_RANGE;
        *out = (subd_real)f;
    }
    return SUBD_OK;
}

static void real_bits(void)
{
    uint32_t seed = 0x5eed1234u, i, bad = 0;
    subd_real x, y;
    /* specials */
    CHECK_EQ(subd_real_from_f32_bits(0x7f800000u, &x), SUBD_ERR_NAN);
    CHECK_EQ(subd_real_from_f32_bits(0xffc00000u, &x), SUBD_ERR_NAN);
    CHECK_EQ(subd_real_from_f64_bits(0x7ff0000000000000ull, &x), SUBD_ERR_NAN);
    CHECK_EQ(subd_real_from_f64_bits(0x7ff8000000000001ull, &x), SUBD_ERR_NAN);
    CHECK_EQ(subd_real_from_f32_bits(0, 0), SUBD_ERR_PARAM);
    x = h_int(5);
    CHECK_EQ(subd_real_from_f64_bits(0x7ff0000000000000ull, &x), SUBD_ERR_NAN);
    CHECK(h_same(x, h_int(5))); /* unchanged on error */
    CHECK_EQ(subd_real_from_f32_bits(0x3f800000u, &x), SUBD_OK);
    CHECK(h_same(x, h_int(1)));
    CHECK_EQ(subd_real_from_f64_bits(0xc000000000000000ull, &x), SUBD_OK); /* -2 */
    CHECK(h_same(x, h_int(-2)));
    /* Q16.16 edges: -32768 fits, 32768 does not; ties away from zero (2^-17, -3 * 2^-17) */
    CHECK_EQ(subd_real_from_f32_bits(0xc7000000u, &x), SUBD_OK);
    CHECK_EQ(subd_real_from_f32_bits(0x47000000u, &y), SUBD_FIXED ? SUBD_ERR_RANGE : SUBD_OK);
    CHECK_EQ(subd_real_from_f32_bits(0x37000000u, &x), SUBD_OK);
    CHECK_EQ(subd_real_bits(x), SUBD_FIXED ? 1u : 0x37000000u);
    CHECK_EQ(subd_real_from_f64_bits(0xbef8000000000000ull, &x), SUBD_OK); /* -3 * 2^-17 */
    CHECK_EQ(subd_real_bits(x), SUBD_FIXED ? (uint32_t)-2 : 0xb7c00000u);
    /* float32 input: the same as the double of the same value; random patterns */
    for (i = 0; i < (H_HOST ? 200000u : 4000u); i++) {
        uint32_t b = h_rand(&seed), e = (b >> 23) & 0xffu;
        int st, want;
        subd_real r = 0;
        if (i % 2u) b = (b & 0x807fffffu) | ((112u + e % 32u) << 23); /* near the Q16.16 range */
        e = (b >> 23) & 0xffu;
        st = subd_real_from_f32_bits(b, &x);
        if (e == 0xffu) { bad += st != SUBD_ERR_NAN; continue; }
        want = ref_real((double)f_of(b), &r);
        bad += st != want || (st == SUBD_OK && !h_same(x, r));
    }
    CHECK_EQ(bad, 0);
    /* float64: random patterns around the float32 and Q16.16 ranges, halfway cases included */
    for (i = 0; i < (H_HOST ? 200000u : 4000u); i++) {
        uint64_t b = (uint64_t)h_rand(&seed) << 32 | h_rand(&seed), e;
        int st, want;
        subd_real r = 0;
        uint32_t mode = i % 4u;
        if (mode == 1u) b = (b & 0x800fffffffffffffull) | (uint64_t)(1023u - 150u + h_rand(&seed) % 300u) << 52;
        if (mode == 2u) b = (b & 0x800fffffffffffffull) | (uint64_t)(1023u - 20u + h_rand(&seed) % 36u) << 52;
        if (mode == 3u) { /* short tails: many exact ties */
            b &= ~(((uint64_t)1 << (20u + h_rand(&seed) % 32u)) - 1u);
            b = (b & 0x800fffffffffffffull) | (uint64_t)(1023u - 30u + h_rand(&seed) % 60u) << 52;
        }
        e = (b >> 52) & 0x7ffu;
        st = subd_real_from_f64_bits(b, &x);
        if (e == 0x7ffu) { bad += st != SUBD_ERR_NAN; continue; }
        want = ref_real(d_of(b), &r);
        bad += st != want || (st == SUBD_OK && !h_same(x, r));
    }
    CHECK_EQ(bad, 0);
    /* to float32: float32 its own bits; Q16.16 nearest (exact below 256) */
    for (i = 0; i < (H_HOST ? 100000u : 3000u); i++) {
        uint32_t b = h_rand(&seed), out;
        subd_real v;
        double want;
        if (SUBD_FIXED) {
            v = (subd_real)b;
            if (i % 2u) v = (subd_real)((int32_t)b >> (b % 16u));
            want = (double)(float)((double)v / 65536.0);
            out = subd_real_to_f32_bits(v);
            bad += (double)f_of(out) != want;
            if ((int32_t)v < (1 << 24) && (int32_t)v > -(1 << 24)) bad += (double)f_of(out) * 65536.0 != (double)v;
        } else {
            if (((b >> 23) & 0xffu) == 0xffu) continue;
            v = (subd_real)f_of(b);
            bad += subd_real_to_f32_bits(v) != b;
        }
    }
    CHECK_EQ(bad, 0);
}

/* ---------------------------------------------------------------------------- helpers */

static void corner_pos(const subd_mesh *m, uint32_t c, uint32_t *bits)
{
    uint32_t k;
    for (k = 0; k < 3u; k++) bits[k] = subd_real_bits(m->pos[3u * m->corner_vert[c] + k]);
}

/* True when every face of a and b (in order, corner order kept) has the same positions. */
static int same_corner_positions(const subd_mesh *a, const subd_mesh *b)
{
    uint32_t c, pa[3], pb[3];
    if (a->num_corners != b->num_corners) return 0;
    for (c = 0; c < a->num_corners; c++) {
        corner_pos(a, c, pa);
        corner_pos(b, c, pb);
        if (pa[0] != pb[0] || pa[1] != pb[1] || pa[2] != pb[2]) return 0;
    }
    return 1;
}

/* A hash of the triangles as a set (each rotated to start at its smallest corner, so the
 * orientation stays), independent of vertex and face numbering. */
static uint32_t tri_set_hash(const subd_mesh *m)
{
    uint32_t f, sum = 0, mix = 0;
    for (f = 0; f < m->num_faces; f++) {
        uint32_t p[3][3], s = 0, k, j, h = 2166136261u;
        for (k = 0; k < 3u; k++) corner_pos(m, m->face_start[f] + k, p[k]);
        for (k = 1; k < 3u; k++)
            for (j = 0; j < 3u; j++) {
                if (p[k][j] != p[s][j]) { if (p[k][j] < p[s][j]) s = k; break; }
            }
        for (k = 0; k < 3u; k++) h = h_fnv(h, p[(s + k) % 3u], 12u);
        sum += h;
        mix ^= h * 2654435761u + (h >> 7);
    }
    return sum ^ (mix << 1) ^ m->num_faces;
}

static int stl_of(const subd_mesh *m, char *buf, uint32_t *len)
{
    return CHECK_EQ(subd_stl_write(m, buf, IO_BUF, len), SUBD_OK);
}

/* ---------------------------------------------------------------------------- tests */

/* Written by subd_stl_write, read back by subd_stl_read: the same triangles with the same
 * bits (every test mesh is below 256 in Q16.16, where float32 is exact), welded back into the
 * same topology. */
static void stl_round_trip(void)
{
    static const char *const files[] = {"test/data/icosahedron.obj", "test/data/torus_tri.obj",
                                        "test/data/hexfan.obj", "test/data/spot_control_mesh.obj"};
    uint32_t i;
    for (i = 0; i < 4u; i++) {
        subd_arena a;
        subd_mesh m, s;
        subd_diag d;
        uint32_t len = 0, plan = 0, big = 0;
        const corpus_file *f = corpus_find(files[i]);
        subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
        if (!read_corpus_obj(&a, files[i], &m)) continue;
        uint32_t tris = 0, f2;
        for (f2 = 0; f2 < m.num_faces; f2++) tris += subd_face_size(&m, f2) - 2u;
        if (!CHECK_EQ(subd_stl_write(&m, 0, 0, &big), SUBD_OK)) continue;
        CHECK_EQ(big, 84u + 50u * tris);
        if (big > IO_BUF) {
            /* too big for the static buffer: the writer's contract only */
            CHECK_EQ(subd_stl_write(&m, io_buf, IO_BUF, &len), SUBD_ERR_NOMEM);
            CHECK_EQ(len, big);
            continue;
        }
        if (!stl_of(&m, io_buf, &len)) continue;
        CHECK(!(io_buf[0] == 's' && io_buf[1] == 'o' && io_buf[2] == 'l'));
        if (!CHECK_EQ(subd_stl_plan(io_buf, len, &plan, &d), SUBD_OK)) continue;
        if (!CHECK_EQ(subd_stl_read(&a, io_buf, len, &s, &d), SUBD_OK)) { h_str("    "); h_str(files[i]); h_nl(); continue; }
        CHECK_EQ(s.num_faces, tris);
        CHECK_EQ(s.num_verts, m.num_verts - m.num_isolated);
        CHECK_EQ(subd_mesh_euler(&s), subd_mesh_euler(&m)); /* fans add as many edges as faces */
        if (tris != m.num_faces) continue;                   /* polygons: fans, checked above */
        CHECK(same_corner_positions(&m, &s));
        CHECK_EQ(s.num_edges, m.num_edges);
        CHECK_EQ(s.num_boundary_edges, m.num_boundary_edges);
        CHECK_EQ(s.num_boundary_loops, m.num_boundary_loops);
        /* first-use numbering */
        CHECK_EQ(s.corner_vert[0], 0);
        CHECK_EQ(s.corner_vert[1], 1);
        CHECK_EQ(s.corner_vert[2], 2);
        if (i == 0u) {
            h_hash("stl_ico", h_mesh_hash(&s));
            (void)h_reader_sweep(subd_stl_read, io_buf, len, io_sweep, sizeof io_sweep, plan);
        }
        (void)f;
    }
}

/* Writer: polygons as fans, the size call, a short buffer untouched, unit normals. */
static void stl_writer(void)
{
    subd_arena a;
    subd_mesh m, s;
    subd_diag d;
    uint32_t len = 0, len2 = 7, i, t;
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    if (!read_corpus_obj(&a, "test/data/cube_quad.obj", &m)) return;
    CHECK_EQ(subd_stl_write(&m, 0, 0, &len), SUBD_OK);
    CHECK_EQ(len, 84u + 50u * 12u);
    for (i = 0; i < len; i++) io_buf2[i] = 0x55;
    CHECK_EQ(subd_stl_write(&m, io_buf2, len - 1u, &len2), SUBD_ERR_NOMEM);
    CHECK_EQ(len2, len);
    for (i = 0, t = 0; i < len; i++) t += io_buf2[i] != 0x55;
    CHECK_EQ(t, 0);
    CHECK_EQ(subd_stl_write(0, io_buf, IO_BUF, &len), SUBD_ERR_PARAM);
    CHECK_EQ(subd_stl_write(&m, io_buf, IO_BUF, 0), SUBD_ERR_PARAM);
    if (!stl_of(&m, io_buf, &len)) return;
    CHECK_EQ((uint8_t)io_buf[80], 12);
    /* each facet: the normal is a unit vector orthogonal to both edges (double reference) */
    for (t = 0; t < 12u; t++) {
        const char *r = io_buf + 84u + 50u * t;
        double v[4][3], e1[3], e2[3], dot1 = 0, dot2 = 0, nn = 0;
        uint32_t k, c;
        for (c = 0; c < 4u; c++)
            for (k = 0; k < 3u; k++) {
                const uint8_t *q = (const uint8_t *)r + 12u * c + 4u * k;
                v[c][k] = (double)f_of((uint32_t)q[0] | (uint32_t)q[1] << 8 | (uint32_t)q[2] << 16 | (uint32_t)q[3] << 24);
            }
        for (k = 0; k < 3u; k++) {
            e1[k] = v[2][k] - v[1][k];
            e2[k] = v[3][k] - v[1][k];
            dot1 += v[0][k] * e1[k];
            dot2 += v[0][k] * e2[k];
            nn += v[0][k] * v[0][k];
        }
        CHECK(dot1 < 1e-4 && dot1 > -1e-4 && dot2 < 1e-4 && dot2 > -1e-4 && nn > 0.999 && nn < 1.001);
        /* outward: the cube is centred at the origin */
        CHECK(v[0][0] * v[1][0] + v[0][1] * v[1][1] + v[0][2] * v[1][2] > 0.0);
    }
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    if (!CHECK_EQ(subd_stl_read(&a, io_buf, len, &s, &d), SUBD_OK)) return;
    CHECK_EQ(s.num_faces, 12);
    CHECK_EQ(s.num_verts, 8);
    CHECK_EQ(s.num_boundary_edges, 0);
    CHECK_EQ(subd_mesh_euler(&s), 2);
}

/* ASCII STL of the icosahedron (coordinates copied from its OBJ, a nan normal, which is
 * ignored): the same corners and topology as the OBJ, and the same Loop output. */
static void stl_ascii_same_as_obj(void)
{
    const corpus_file *f = corpus_find("test/data/icosahedron.stl");
    subd_arena a;
    subd_mesh m, s, lm, ls;
    subd_diag d;
    subd_loop_opts o = {2, SUBD_LOOP_BOUNDARY_PAPER, 0};
    uint32_t plan = 0, i, map[12];
    if (!CHECK(f != 0)) return;
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    if (!read_corpus_obj(&a, "test/data/icosahedron.obj", &m)) return;
    if (!CHECK_EQ(subd_stl_plan(f->data, f->len, &plan, &d), SUBD_OK)) return;
    if (!CHECK_EQ(subd_stl_read(&a, f->data, f->len, &s, &d), SUBD_OK)) { h_str("    line "); h_u32(d.line); h_nl(); return; }
    CHECK(same_corner_positions(&m, &s));
    CHECK_EQ(s.num_verts, 12);
    CHECK_EQ(s.num_edges, 30);
    /* the weld is a bijection between the OBJ's vertices and the STL's */
    for (i = 0; i < 12u; i++) map[i] = SUBD_NONE;
    for (i = 0; i < m.num_corners; i++) {
        uint32_t v = m.corner_vert[i];
        if (map[v] == SUBD_NONE) map[v] = s.corner_vert[i];
        CHECK_EQ(map[v], s.corner_vert[i]);
    }
    if (!CHECK_OK(subd_loop(&a, &m, &o, &lm, &d), &d)) return;
    if (!CHECK_OK(subd_loop(&a, &s, &o, &ls, &d), &d)) return;
    CHECK_EQ(lm.num_faces, ls.num_faces);
    CHECK_EQ(lm.num_verts, ls.num_verts);
    CHECK_EQ(tri_set_hash(&lm), tri_set_hash(&ls));
    h_hash("stl_ico_loop2", tri_set_hash(&ls));
    (void)h_reader_sweep(subd_stl_read, f->data, f->len, io_sweep, sizeof io_sweep, plan);
}

/* Reads buf[0..len) expecting status st with the given line and face (harness.c's
 * h_reader_expect: the arena mark and *out unchanged), in the lower half of h_arena_buf. */
static int expect_at(const char *buf, uint32_t len, int st, uint32_t line, uint32_t face, int src_line)
{
    return h_reader_expect(subd_stl_read, subd_stl_plan, buf, len, H_ARENA_BYTES / 2u, st, line, face, H_ANY,
                           src_line);
}
#define EXPECT_AT(buf, len, st, line, face) expect_at((buf), (len), (st), (line), (face), __LINE__)
#define EXPECT_TXT(txt, st, line) expect_at((txt), slen(txt), (st), (line), SUBD_NONE, __LINE__)
#define EXPECT_VAL(txt, st, line, face) expect_at((txt), slen(txt), (st), (line), (face), __LINE__)

static void put_u32(char *p, uint32_t v)
{
    p[0] = (char)(v & 0xffu);
    p[1] = (char)((v >> 8) & 0xffu);
    p[2] = (char)((v >> 16) & 0xffu);
    p[3] = (char)(v >> 24);
}

/* A binary STL of the triangles tri[9 t] (coordinates as small integers). */
static uint32_t make_bin(char *buf, const int32_t *tri, uint32_t t)
{
    uint32_t i, k;
    for (i = 0; i < 80u; i++) buf[i] = 'x';
    put_u32(buf + 80, t);
    for (i = 0; i < t; i++) {
        char *r = buf + 84u + 50u * i;
        for (k = 0; k < 12u; k++) {
            union { float f; uint32_t u; } c;
            c.f = k < 3u ? 0.0f : (float)tri[9u * i + k - 3u];
            put_u32(r + 4u * k, c.u);
        }
        r[48] = r[49] = 0;
    }
    return 84u + 50u * t;
}

static void stl_binary_errors(void)
{
    static const int32_t nm_edge[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, /**/ 1, 0, 0, 0, 0, 0, 0, -1, 0,
                                      0, 0, 0, 1, 0, 0, 0, 0, 1};
    static const int32_t flip[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, /**/ 0, 0, 0, 1, 0, 0, 0, -1, 0};
    static const int32_t degen[] = {0, 0, 0, 0, 0, 0, 0, 1, 0};
    static const int32_t bowtie[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, /**/ 0, 0, 0, -1, 0, 0, 0, -1, 0};
    subd_arena a, keep;
    subd_mesh m, s;
    subd_diag d;
    uint32_t len = 0, n;
    /* m lives in the upper half; the reads below use the lower half (as expect_at does) */
    subd_arena_init(&keep, h_arena_buf + H_ARENA_BYTES / 2u, H_ARENA_BYTES / 2u);
    if (!read_corpus_obj(&keep, "test/data/icosahedron.obj", &m) || !stl_of(&m, io_buf, &len)) return;
    /* truncated: the first incomplete facet */
    EXPECT_AT(io_buf, len - 1u, SUBD_ERR_PARSE, 0, 19);
    EXPECT_AT(io_buf, 84u + 50u * 5u + 10u, SUBD_ERR_PARSE, 0, 5);
    EXPECT_AT(io_buf, 84u, SUBD_ERR_PARSE, 0, 0);
    EXPECT_AT(io_buf, 83u, SUBD_ERR_PARSE, 0, SUBD_NONE); /* no header */
    EXPECT_AT(io_buf, 0u, SUBD_ERR_EMPTY, 0, SUBD_NONE);
    /* a count the size contradicts: too small (extra bytes) names the first facet beyond it */
    put_u32(io_buf + 80, 19);
    EXPECT_AT(io_buf, len, SUBD_ERR_PARSE, 0, 19);
    put_u32(io_buf + 80, 21);
    EXPECT_AT(io_buf, len, SUBD_ERR_PARSE, 0, 20);
    put_u32(io_buf + 80, 0xffffffffu);
    EXPECT_AT(io_buf, len, SUBD_ERR_PARSE, 0, 20);
    /* "solid" headers: binary when the size matches, also reported as binary when not */
    io_buf[0] = 's'; io_buf[1] = 'o'; io_buf[2] = 'l'; io_buf[3] = 'i'; io_buf[4] = 'd'; io_buf[5] = ' ';
    EXPECT_AT(io_buf, len, SUBD_ERR_PARSE, 0, 20);
    put_u32(io_buf + 80, 20);
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES / 2u);
    if (CHECK_EQ(subd_stl_read(&a, io_buf, len, &s, &d), SUBD_OK)) CHECK(same_corner_positions(&m, &s));
    /* NaN and infinity name the facet; a value outside Q16.16 too (fixed only) */
    put_u32(io_buf + 84 + 50 * 7 + 12 + 12 + 4, 0x7fc00000u);
    EXPECT_AT(io_buf, len, SUBD_ERR_NAN, 0, 7);
    put_u32(io_buf + 84 + 50 * 7 + 12 + 12 + 4, 0xff800000u);
    EXPECT_AT(io_buf, len, SUBD_ERR_NAN, 0, 7);
    put_u32(io_buf + 84 + 50 * 11 + 12 + 24 + 8, 0x471c4000u); /* 40000 */
    put_u32(io_buf + 84 + 50 * 7 + 12 + 12 + 4, 0u);
    if (SUBD_FIXED) EXPECT_AT(io_buf, len, SUBD_ERR_RANGE, 0, 7 + 4);
    /* a normal or attribute of any bits is ignored */
    stl_of(&m, io_buf, &len);
    put_u32(io_buf + 84 + 50 * 3, 0x7fc00000u);
    io_buf[84 + 50 * 3 + 48] = (char)0xff;
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES / 2u);
    if (CHECK_EQ(subd_stl_read(&a, io_buf, len, &s, &d), SUBD_OK)) CHECK(same_corner_positions(&m, &s));
    put_u32(io_buf + 80, 0);
    EXPECT_AT(io_buf, 84u, SUBD_ERR_EMPTY, 0, SUBD_NONE);
    /* faces that weld into a bad mesh: the facet subd_mesh_build names */
    n = make_bin(io_buf, nm_edge, 3);
    EXPECT_AT(io_buf, n, SUBD_ERR_NONMANIFOLD_EDGE, 0, 2);
    n = make_bin(io_buf, flip, 2);
    EXPECT_AT(io_buf, n, SUBD_ERR_ORIENTATION, 0, 1);
    n = make_bin(io_buf, degen, 1);
    EXPECT_AT(io_buf, n, SUBD_ERR_DEGENERATE, 0, 0);
    n = make_bin(io_buf, bowtie, 2);
    if (EXPECT_AT(io_buf, n, SUBD_ERR_NONMANIFOLD_VERTEX, 0, 0)) {
        subd_stl_read(&a, io_buf, n, &s, &d);
        CHECK_EQ(d.vertex, 0); /* the shared corner, welded first */
    }
    /* -0 and +0 weld: the two triangles share an edge */
    {
        static const int32_t pair[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, /**/ 1, 0, 0, 0, 0, 0, 0, -1, 0};
        n = make_bin(io_buf, pair, 2);
        put_u32(io_buf + 84 + 50 + 12 + 12 + 8, 0x80000000u); /* z of (0,0,0) in facet 1: -0 */
        subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES / 2u);
        if (CHECK_EQ(subd_stl_read(&a, io_buf, n, &s, &d), SUBD_OK)) {
            CHECK_EQ(s.num_verts, 4);
            CHECK_EQ(s.num_edges, 5);
        }
    }
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES / 2u);
    CHECK_FAIL(subd_stl_read(&a, 0, 5, &s, &d), &d, SUBD_ERR_PARAM);
    CHECK_FAIL(subd_stl_read(0, io_buf, n, &s, &d), &d, SUBD_ERR_PARAM);
    CHECK_FAIL(subd_stl_read(&a, io_buf, n, 0, &d), &d, SUBD_ERR_PARAM);
    CHECK_FAIL(subd_stl_plan(io_buf, n, 0, &d), &d, SUBD_ERR_PARAM);
    CHECK_FAIL(subd_stl_plan(0, 0, &len, &d), &d, SUBD_ERR_EMPTY);
    CHECK_EQ(subd_stl_read(&a, 0, 0, &s, 0), SUBD_ERR_EMPTY);
}

#define FACET "facet normal 0 0 1\n outer loop\n"
#define TRI "  vertex 0 0 0\n  vertex 1 0 0\n  vertex 0 1 0\n"
#define END " endloop\nendfacet\n"

static void stl_ascii_errors(void)
{
    subd_arena a;
    subd_mesh s;
    subd_diag d;
    /* accepted: several solids, CRLF, upper case, blank names, a nan normal */
    static const char ok[] = "solid\r\nFACET NORMAL nan nan nan\r\nOUTER LOOP\r\nVERTEX 0 0 0\r\nvertex 1 0 0\r\n"
                             "vertex 0 1 0\r\nENDLOOP\r\nendfacet\r\nendsolid\r\nsolid b\n" FACET
                             "vertex 1 0 0\nvertex 0 0 0\nvertex 0 -1 0\n" END "endsolid b\n\n";
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    if (CHECK_EQ(subd_stl_read(&a, ok, slen(ok), &s, &d), SUBD_OK)) {
        CHECK_EQ(s.num_faces, 2);
        CHECK_EQ(s.num_verts, 4);
        CHECK_EQ(s.num_edges, 5);
    } else {
        h_str("    line "); h_u32(d.line); h_nl();
    }
    EXPECT_TXT("solid x\n" FACET TRI END, SUBD_ERR_PARSE, 9);                         /* no endsolid */
    EXPECT_TXT("solid x\n" FACET "vertex 0 0 0\nvertex 1 0 x\n", SUBD_ERR_PARSE, 5);  /* not a number */
    EXPECT_TXT("solid x\n" FACET "vertex 0 0 0\nvertex 1 0 1y\n", SUBD_ERR_PARSE, 5); /* trailing garbage */
    EXPECT_TXT("solid x\n" FACET "vertex 0 nan 0\n", SUBD_ERR_NAN, 4);
    EXPECT_TXT("solid x\n" FACET "vertex 0 -inf 0\n", SUBD_ERR_NAN, 4);
    EXPECT_TXT("solid x\n" FACET "vertex 0 1e39 0\n", SUBD_ERR_RANGE, 4);
    if (SUBD_FIXED) EXPECT_TXT("solid x\n" FACET "vertex 0 40000 0\n", SUBD_ERR_RANGE, 4);
    EXPECT_TXT("solid x\n" FACET TRI "vertex 1 1 1\n" END "endsolid\n", SUBD_ERR_FACE_SIZE, 2);
    EXPECT_TXT("solid x\n" FACET "vertex 0 0 0\nvertex 1 0 0\n" END "endsolid\n", SUBD_ERR_FACE_SIZE, 2);
    EXPECT_TXT("solid x\nfacet normal 0 0 1\n loop\n" TRI END "endsolid\n", SUBD_ERR_PARSE, 3);
    EXPECT_TXT("solid x\nfacet normal 0 0\n outer loop\n" TRI END "endsolid\n", SUBD_ERR_PARSE, 3);
    EXPECT_TXT("solid x\n" FACET TRI " endloop\nendsolid\n", SUBD_ERR_PARSE, 8);
    EXPECT_TXT("solid x\n" FACET TRI END "endsolid\ngarbage\n", SUBD_ERR_PARSE, 10);
    EXPECT_TXT("solid x\nendsolid x\n", SUBD_ERR_EMPTY, 3);
    EXPECT_TXT("solid", SUBD_ERR_PARSE, 1);
    EXPECT_TXT("solid x\n" FACET TRI END "endsolid x\n" FACET, SUBD_ERR_PARSE, 10); /* facet outside a solid */
    /* three facets on one edge: the third names its line */
    EXPECT_VAL("solid x\n" FACET TRI END FACET "vertex 1 0 0\nvertex 0 0 0\nvertex 0 -1 0\n" END FACET
               "vertex 0 0 0\nvertex 1 0 0\nvertex 0 0 1\n" END "endsolid x\n",
               SUBD_ERR_NONMANIFOLD_EDGE, 16, 2);
    EXPECT_VAL("solid x\n" FACET "vertex 0 0 0\nvertex 0 0 0\nvertex 0 1 0\n" END "endsolid x\n",
               SUBD_ERR_DEGENERATE, 2, 0);
}

const test_case suite_stl[] = {
    {"real_bits", real_bits},
    {"stl_round_trip", stl_round_trip},
    {"stl_writer", stl_writer},
    {"stl_ascii_same_as_obj", stl_ascii_same_as_obj},
    {"stl_binary_errors", stl_binary_errors},
    {"stl_ascii_errors", stl_ascii_errors},
    {0, 0}
};
