/* SPDX-License-Identifier: MIT */
/* OBJ reader/writer: every supported syntax against hand-written expectations, round trip,
 * exact plan, writer buffer contract, and the bundled test meshes (hashes for host = QEMU). */
#include "harness.h"
#include "corpus.h"

static int read_obj(const char *text, uint32_t len, subd_mesh *m, subd_diag *d)
{
    subd_arena a;
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    return subd_obj_read(&a, text, len, m, d);
}

static uint32_t slen(const char *s)
{
    uint32_t n = 0;
    while (s[n]) n++;
    return n;
}

static subd_real R(int32_t num, int32_t den)
{
    uint32_t ovf = 0;
    return subd_div(subd_from_int(num, &ovf), subd_from_int(den, &ovf), &ovf);
}

static void obj_syntax(void)
{
    static const char text[] =
        "# all the syntax\r\n"
        "mtllib x.mtl\r\n"
        "o thing\n"
        "v 0 0 0\n"
        "v 1.5 0 0 1.0\n"          /* w ignored */
        "v   1.5\t2 -0.25   \n"     /* tabs, trailing blanks */
        "vt 0.5 0.5\n"
        "vn 0 0 1\n"
        "v 0 2 +1e0 0.1 0.2 0.3\n" /* colour ignored */
        "g group\ns 1\nusemtl m\n"
        "f 1/1 2/1 3/1\n"
        "f 1//1 3//1 4//1\n"
        "\n"
        "   # indented comment\n"
        "v 0 -1 0\n"
        "f -5/1/1 -1/1/1 -4/1/1\r"  /* relative indices; lone CR line end */
        "l 1 2 3 -1\n"
        "v 9 9 9\n";
    static const uint32_t want_corners[] = {0, 1, 2, 0, 2, 3, 0, 4, 1};
    subd_mesh m;
    subd_diag d;
    uint32_t i;
    if (!CHECK_EQ(read_obj(text, slen(text), &m, &d), SUBD_OK)) {
        h_str("    line "); h_u32(d.line); h_nl();
        return;
    }
    CHECK_EQ(m.num_verts, 6);
    CHECK_EQ(m.num_faces, 3);
    CHECK_EQ(m.num_lines, 1);
    CHECK_EQ(m.num_line_verts, 4);
    for (i = 0; i < 9; i++) CHECK_EQ(m.corner_vert[i], want_corners[i]);
    CHECK_EQ(m.line_vert[3], 4);
    CHECK(m.pos[3] == R(3, 2));
    CHECK(m.pos[8] == R(-1, 4));
    CHECK(m.pos[11] == R(1, 1));
    CHECK(m.vert_tag[5] & SUBD_VTAG_ISOLATED);
    CHECK_EQ(m.num_isolated, 1);
    CHECK_EQ(m.num_boundary_loops, 1);
}

static void obj_roundtrip(void)
{
    static char buf[65536];
    const corpus_file *f = corpus_find("test/data/spot_control_mesh.obj");
    subd_mesh a, b;
    subd_arena ar;
    subd_diag d;
    uint32_t len, len2, i, mark;
    if (!CHECK(f != 0)) return;
    subd_arena_init(&ar, h_arena_buf, H_ARENA_BYTES);
    if (!CHECK_EQ(subd_obj_read(&ar, f->data, f->len, &a, &d), SUBD_OK)) return;
    CHECK_EQ(a.num_verts, 188);
    CHECK_EQ(a.num_faces, 180);
    CHECK_EQ(subd_mesh_euler(&a), 2);
    CHECK_EQ(subd_obj_write(&a, 0, 0, &len), SUBD_OK);
    CHECK(len < sizeof buf);
    /* too small: NOMEM, size reported, nothing written */
    buf[0] = 'X';
    CHECK_EQ(subd_obj_write(&a, buf, len - 1u, &len2), SUBD_ERR_NOMEM);
    CHECK_EQ(len2, len);
    CHECK(buf[0] == 'X');
    CHECK_EQ(subd_obj_write(&a, buf, sizeof buf, &len2), SUBD_OK);
    CHECK_EQ(len2, len);
    mark = subd_arena_mark(&ar);
    if (!CHECK_EQ(subd_obj_read(&ar, buf, len, &b, &d), SUBD_OK)) return;
    CHECK(subd_arena_mark(&ar) > mark);
    CHECK_EQ(b.num_verts, a.num_verts);
    CHECK_EQ(b.num_corners, a.num_corners);
    for (i = 0; i < 3u * a.num_verts; i++)
        if (!CHECK(subd_real_bits(a.pos[i]) == subd_real_bits(b.pos[i]))) break;
    for (i = 0; i < a.num_corners; i++)
        if (!CHECK_EQ(a.corner_vert[i], b.corner_vert[i])) break;
    CHECK_EQ(h_mesh_hash(&a), h_mesh_hash(&b));
}

/* Exhaustive too-small arenas for the reader, like the builder test. */
static void obj_plan_exact(void)
{
    static uint8_t buf[4096 + 64] __attribute__((aligned(8)));
    const corpus_file *f = corpus_find("test/data/icosahedron.obj");
    uint32_t plan;
    subd_diag d;
    if (!CHECK(f != 0)) return;
    if (!CHECK_EQ(subd_obj_plan(f->data, f->len, &plan, &d), SUBD_OK)) return;
    CHECK(plan <= SUBD_MESH_BYTES(12u, 20u, 60u, 0u, 0u));
    (void)h_reader_sweep(subd_obj_read, f->data, f->len, buf, sizeof buf, plan);
}

/* Every bundled good mesh reads, validates, and prints its hash for host = QEMU. */
static void obj_corpus(void)
{
    uint32_t i;
    for (i = 0; i < corpus_count; i++) {
        const corpus_file *f = &corpus_files[i];
        const char *n = f->name;
        uint32_t k = slen(n);
        subd_mesh m;
        subd_diag d;
        int st;
        if (k < 14 || n[5] != 'd' || n[9] != '/') continue; /* test/data/ only */
        if (n[k - 3] == 'o' && n[k - 2] == 'b' && n[k - 1] == 'j') st = read_obj(f->data, f->len, &m, &d);
        else continue;
        if (!CHECK_EQ(st, SUBD_OK)) { h_str("    in "); h_str(n); h_nl(); continue; }
        h_hash(n, h_mesh_hash(&m));
    }
}

/* The normals writer: `vn` per vertex, `f a//a` corners; reading it back gives the mesh. */
static void obj_write_normals(void)
{
    static char buf[4096];
    const corpus_file *f = corpus_find("test/data/cube_quad.obj");
    subd_arena a;
    subd_mesh m, n;
    subd_diag d;
    subd_real nrm[24];
    uint32_t len, i, vn = 0, slashes = 0;
    if (!CHECK(f != 0)) return;
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    if (!CHECK_EQ(subd_obj_read(&a, f->data, f->len, &m, &d), SUBD_OK)) return;
    for (i = 0; i < 24; i++) nrm[i] = m.pos[i];
    CHECK_EQ(subd_obj_write_normals(&m, 0, buf, sizeof buf, &len), SUBD_ERR_PARAM);
    if (!CHECK_EQ(subd_obj_write_normals(&m, nrm, buf, sizeof buf, &len), SUBD_OK)) return;
    for (i = 0; i + 3 < len; i++) {
        if (buf[i] == '\n' && buf[i + 1] == 'v' && buf[i + 2] == 'n' && buf[i + 3] == ' ') vn++;
        if (buf[i] == '/' && buf[i + 1] == '/') slashes++;
    }
    CHECK_EQ(vn, 8);
    CHECK_EQ(slashes, 24);
    if (!CHECK_EQ(subd_obj_read(&a, buf, len, &n, &d), SUBD_OK)) return;
    CHECK_EQ(h_mesh_hash(&n), h_mesh_hash(&m));
}

const test_case suite_obj[] = {
    {"obj_write_normals", obj_write_normals},
    {"obj_syntax", obj_syntax},
    {"obj_roundtrip", obj_roundtrip},
    {"obj_plan_exact", obj_plan_exact},
    {"obj_corpus", obj_corpus},
    {0, 0}
};
