/* SPDX-License-Identifier: MIT */
/* OFF reader/writer: syntax against hand-written expectations, OBJ -> OFF -> mesh equality,
 * exact plan. */
#include "harness.h"
#include "corpus.h"

static uint32_t slen(const char *s)
{
    uint32_t n = 0;
    while (s[n]) n++;
    return n;
}

static void off_syntax(void)
{
    static const char text[] =
        "OFF # header comment\n"
        "# counts follow\n"
        "\n"
        "5 2 0\n"
        "0 0 0\n"
        "1 0 0 255 0 0\n" /* colour ignored */
        "1 1 0\r\n"
        "0 1 0\n"
        "0.5 0.5 7\n"
        "4 0 1 2 3 0.5 0.5 0.5 1\n"
        "3 1 0 4\n";
    subd_arena a;
    subd_mesh m;
    subd_diag d;
    uint32_t ovf = 0;
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    if (!CHECK_EQ(subd_off_read(&a, text, slen(text), &m, &d), SUBD_OK)) {
        h_str("    line "); h_u32(d.line); h_nl();
        return;
    }
    CHECK_EQ(m.num_verts, 5);
    CHECK_EQ(m.num_faces, 2);
    CHECK_EQ(subd_face_size(&m, 0), 4);
    CHECK_EQ(m.corner_vert[4], 1);
    CHECK_EQ(m.corner_vert[6], 4);
    CHECK(m.pos[14] == subd_from_int(7, &ovf));
    CHECK_EQ(m.num_edges, 6);
    /* counts on the keyword line */
    {
        static const char t2[] = "OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
        CHECK_EQ(subd_off_read(&a, t2, slen(t2), &m, &d), SUBD_OK);
        CHECK_EQ(m.num_faces, 1);
    }
}

static void off_from_obj(void)
{
    static char buf[32768];
    const corpus_file *f = corpus_find("test/data/cube_quad.obj");
    subd_arena a;
    subd_mesh m, n;
    subd_diag d;
    uint32_t len, i, plan;
    static uint8_t abuf[2048 + 64] __attribute__((aligned(8)));
    if (!CHECK(f != 0)) return;
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    if (!CHECK_EQ(subd_obj_read(&a, f->data, f->len, &m, &d), SUBD_OK)) return;
    CHECK_EQ(subd_off_write(&m, buf, sizeof buf, &len), SUBD_OK);
    CHECK_EQ(subd_off_write(&m, buf, len - 1u, &i), SUBD_ERR_NOMEM);
    if (!CHECK_EQ(subd_off_read(&a, buf, len, &n, &d), SUBD_OK)) return;
    CHECK_EQ(n.num_verts, 8);
    CHECK_EQ(n.num_faces, 6);
    for (i = 0; i < 3u * m.num_verts; i++) CHECK(subd_real_bits(m.pos[i]) == subd_real_bits(n.pos[i]));
    for (i = 0; i < m.num_corners; i++) CHECK_EQ(m.corner_vert[i], n.corner_vert[i]);
    CHECK_EQ(h_mesh_hash(&m), h_mesh_hash(&n));
    h_hash("off_cube", h_mesh_hash(&n));
    /* exact plan */
    CHECK_EQ(subd_off_plan(buf, len, &plan, &d), SUBD_OK);
    (void)h_reader_sweep(subd_off_read, buf, len, abuf, sizeof abuf, plan);
}

/* OFF is whitespace-separated: a face's indices may go on over the following lines (with
 * blank and comment lines between); errors in a later face still name the line it starts on. */
static void off_multiline_faces(void)
{
    static const char text[] =
        "OFF\n"
        "5 3 0\n"
        "0 0 0\n"
        "1 0 0\n"
        "1 1 0\n"
        "0 1 0\n"
        "0.5 0.5 7\n"
        "4 0 1\n"    /* line 8: face 0 starts */
        "  2 3\n"
        "3\n"        /* line 10: face 1, the count alone */
        "# a comment inside the face\n"
        "1 0 4\n"
        "3 2 1 4 # line 13: face 2 on one line\n";
    static const char bad[] = /* face 1 (line 8) uses an edge in the same direction as face 0 */
        "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n"
        "3 0 1\n2\n"
        "3 0\n1 2\n";
    static const char cut[] = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1\n";
    subd_arena a;
    subd_mesh m;
    subd_diag d;
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    if (!CHECK_EQ(subd_off_read(&a, text, slen(text), &m, &d), SUBD_OK)) {
        h_str("    line "); h_u32(d.line); h_nl();
        return;
    }
    CHECK_EQ(m.num_faces, 3);
    CHECK_EQ(subd_face_size(&m, 0), 4);
    CHECK_EQ(m.corner_vert[2], 2);
    CHECK_EQ(m.corner_vert[3], 3);
    CHECK_EQ(m.corner_vert[4], 1);
    CHECK_EQ(m.corner_vert[6], 4);
    CHECK_EQ(m.corner_vert[7], 2);
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    CHECK_FAIL(subd_off_read(&a, bad, slen(bad), &m, &d), &d, SUBD_ERR_ORIENTATION);
    CHECK_EQ(d.line, 8);
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    CHECK_FAIL(subd_off_read(&a, cut, slen(cut), &m, &d), &d, SUBD_ERR_PARSE);
    CHECK_EQ(d.line, 7);
}

const test_case suite_off[] = {
    {"off_multiline_faces", off_multiline_faces},
    {"off_syntax", off_syntax},
    {"off_from_obj", off_from_obj},
    {0, 0}
};
