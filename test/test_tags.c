/* SPDX-License-Identifier: MIT */
/* Tag files (src/tags.c): every error path with its status and line, the mesh unchanged on
 * any error, comments, CRLF and lone CR, empty files, boundary edges named either way, and the
 * tags equal to what the host tool's own --tags parser produced before it moved into the
 * library (golden output bytes of the original tool, and the cube's edges = crease angle). */
#include <string.h>
#include "harness.h"
#include "corpus.h"

static uint32_t slen(const char *s)
{
    uint32_t n = 0;
    while (s[n]) n++;
    return n;
}

static int read_mesh(const char *name, subd_arena *a, subd_mesh *m)
{
    const corpus_file *f = corpus_find(name);
    subd_diag d;
    if (!CHECK(f != 0)) return 0;
    subd_arena_init(a, h_arena_buf, H_ARENA_BYTES);
    return CHECK_OK(subd_obj_read(a, f->data, f->len, m, &d), &d);
}

/* Hash of the tag arrays: the state a tag file may change. */
static uint32_t tag_hash(const subd_mesh *m)
{
    return h_fnv(h_fnv(2166136261u, m->vert_tag, m->num_verts), m->edge_tag, m->num_corners);
}

/* Applies text to a fresh icosahedron (12 vertices) and checks the status, the line and that
 * a failure changed nothing. */
static void expect(const char *text, int status, uint32_t line, const char *what)
{
    subd_arena a;
    subd_mesh m;
    subd_diag d;
    subd_tags_report rep;
    uint32_t before;
    int st;
    if (!read_mesh("test/data/icosahedron.obj", &a, &m)) return;
    before = tag_hash(&m);
    CHECK_FAIL(subd_tags_check(text, slen(text), &m, &rep, &d), &d, status);
    CHECK_EQ(tag_hash(&m), before); /* check never changes the mesh */
    st = subd_tags_apply(text, slen(text), &m, &rep, &d);
    if (!CHECK_EQ(st, status) || !CHECK_EQ(d.line, line) || !CHECK_EQ(d.status, status)) {
        h_str("    case: ");
        h_str(what);
        h_nl();
    }
    if (st != SUBD_OK) CHECK_EQ(tag_hash(&m), before);
}

static void tags_parse_errors(void)
{
    expect("corner 1\nCorner 2\n", SUBD_ERR_PARSE, 2, "keywords are lower case");
    expect("corner 1\nedge 1 2\n", SUBD_ERR_PARSE, 2, "unknown keyword");
    expect("crease 1\n", SUBD_ERR_PARSE, 1, "crease with one vertex");
    expect("crease 1 2 3\n", SUBD_ERR_PARSE, 1, "crease with three vertices");
    expect("crease 1 2 3 4 5\n", SUBD_ERR_PARSE, 1, "many fields");
    expect("corner\n", SUBD_ERR_PARSE, 1, "corner without a vertex");
    expect("fixed 1 2\n", SUBD_ERR_PARSE, 1, "fixed with two vertices");
    expect("corner x\n", SUBD_ERR_PARSE, 1, "not a number");
    expect("corner 1x\n", SUBD_ERR_PARSE, 1, "trailing garbage");
    expect("corner +1\n", SUBD_ERR_PARSE, 1, "signed number");
    expect("corner -1\n", SUBD_ERR_PARSE, 1, "negative number");
    expect("crease 1 2.0\n", SUBD_ERR_PARSE, 1, "decimal number");
    expect("\n\n# c\n  \ncorner 1 # ok\n1 corner\n", SUBD_ERR_PARSE, 6, "line numbers count blank and comment lines");
}

static void tags_index_errors(void)
{
    subd_arena a;
    subd_mesh m;
    subd_diag d;
    subd_tags_report rep;
    static const char noedge[] = "crease 1 2\ncrease 1 7\n"; /* 1 and 7 are opposite */
    expect("corner 0\n", SUBD_ERR_INDEX, 1, "vertex 0 (numbers are 1-based)");
    expect("fixed 13\n", SUBD_ERR_INDEX, 1, "one past the last vertex");
    expect("corner 99999999999999999999\n", SUBD_ERR_INDEX, 1, "a number beyond 64 bits");
    expect("crease 1 2\ncrease 2 13\n", SUBD_ERR_INDEX, 2, "second crease vertex out of range");
    expect("crease 1 7\n", SUBD_ERR_INDEX, 1, "opposite vertices share no edge");
    expect("crease 3 3\n", SUBD_ERR_INDEX, 1, "a vertex and itself");
    if (!read_mesh("test/data/icosahedron.obj", &a, &m)) return;
    CHECK_FAIL(subd_tags_apply("fixed 13\n", 9, &m, &rep, &d), &d, SUBD_ERR_INDEX);
    CHECK_EQ(d.vertex, SUBD_NONE);
    CHECK_EQ(rep.edge[0], SUBD_NONE);
    CHECK_FAIL(subd_tags_apply(noedge, slen(noedge), &m, &rep, &d), &d, SUBD_ERR_INDEX);
    CHECK_EQ(d.line, 2);
    CHECK_EQ(d.vertex, 0);
    CHECK_EQ(rep.edge[0], 0);
    CHECK_EQ(rep.edge[1], 6);
}

static void tags_params(void)
{
    subd_arena a;
    subd_mesh m;
    subd_diag d;
    subd_tags_report rep;
    if (!read_mesh("test/data/icosahedron.obj", &a, &m)) return;
    CHECK_FAIL(subd_tags_apply("corner 1\n", 9, 0, &rep, &d), &d, SUBD_ERR_PARAM);
    CHECK_FAIL(subd_tags_check(0, 3, &m, &rep, &d), &d, SUBD_ERR_PARAM);
    CHECK_EQ(subd_tags_apply(0, 0, &m, &rep, &d), SUBD_OK); /* an empty file */
    CHECK_EQ(rep.creases + rep.vertex_tags, 0);
    CHECK_EQ(subd_tags_apply("corner 1\n", 9, &m, 0, 0), SUBD_OK); /* report and diag optional */
    CHECK_EQ(m.vert_tag[0] & SUBD_VTAG_CORNER, SUBD_VTAG_CORNER);
}

/* Comments, blank lines, CRLF, lone CR, tabs, no final newline, an edge named twice, and what
 * each line sets. */
static void tags_syntax(void)
{
    static const char text[] = "# comment only\r\n"
                               "\r\n"
                               "corner 1\r\n"
                               "crease 1 2#no blank before the comment\r"
                               "\tfixed\t3\t\n"
                               "crease 2 1\n"
                               "   \n"
                               "fixed 12";
    subd_arena a;
    subd_mesh m;
    subd_diag d;
    subd_tags_report rep;
    uint32_t h, v, creases = 0;
    if (!read_mesh("test/data/icosahedron.obj", &a, &m)) return;
    if (!CHECK_OK(subd_tags_apply(text, slen(text), &m, &rep, &d), &d)) return;
    CHECK_EQ(rep.creases, 2);
    CHECK_EQ(rep.vertex_tags, 3);
    CHECK_EQ(rep.edge[0], SUBD_NONE);
    for (v = 0; v < m.num_verts; v++) {
        uint8_t want = (uint8_t)(v == 0 ? SUBD_VTAG_CORNER : (v == 2 || v == 11) ? SUBD_VTAG_FIXED : 0u);
        CHECK_EQ(m.vert_tag[v] & (SUBD_VTAG_CORNER | SUBD_VTAG_FIXED), want);
    }
    for (h = 0; h < m.num_corners; h++)
        if (m.edge_tag[h] & SUBD_ETAG_CREASE) {
            uint32_t a0 = subd_he_origin(&m, h), b0 = subd_he_dest(&m, h);
            CHECK((a0 == 0 && b0 == 1) || (a0 == 1 && b0 == 0));
            creases++;
        }
    CHECK_EQ(creases, 2); /* both half-edges of the one edge */
}

/* Writes "crease A B\n" for 0-based vertices a, b < 9 (1-based single digits in the file);
 * returns its length. */
static uint32_t crease_line(char *p, uint32_t a, uint32_t b)
{
    uint32_t n = 0, k;
    for (k = 0; k < 7u; k++) p[n++] = "crease "[k];
    p[n++] = (char)('1' + (int)a);
    p[n++] = ' ';
    p[n++] = (char)('1' + (int)b);
    p[n++] = '\n';
    return n;
}

/* On an open mesh a boundary edge is one half-edge: either vertex order must find it. */
static void tags_boundary_edge(void)
{
    subd_arena a;
    subd_mesh m;
    subd_diag d;
    uint32_t h, k;
    if (!read_mesh("test/data/hexfan.obj", &a, &m) || !CHECK(m.num_verts <= 9u)) return;
    h = 0;
    while (h < m.num_corners && m.twin[h] != SUBD_NONE) h++;
    if (!CHECK(h < m.num_corners)) return;
    for (k = 0; k < 2u; k++) {
        char text[32];
        uint32_t o = subd_he_origin(&m, h), e = subd_he_dest(&m, h);
        uint32_t len = k ? crease_line(text, e, o) : crease_line(text, o, e);
        m.edge_tag[h] &= (uint8_t)~SUBD_ETAG_CREASE;
        CHECK_OK(subd_tags_apply(text, len, &m, 0, &d), &d);
        CHECK(m.edge_tag[h] & SUBD_ETAG_CREASE);
    }
}

/* The tool test's check, in the library: the cube's 12 edges (vertex pairs that differ in
 * exactly one coordinate) as a tag file give the same crease tags as the dihedral angle rule. */
static void tags_cube_edges(void)
{
    static char text[512];
    subd_arena a;
    subd_mesh m;
    subd_diag d;
    subd_tags_report rep;
    uint32_t i, j, k, len = 0, by_angle;
    if (!read_mesh("test/data/cube_quad.obj", &a, &m) || !CHECK(m.num_verts <= 9u)) return;
    for (i = 0; i < m.num_verts; i++)
        for (j = i + 1u; j < m.num_verts; j++) {
            uint32_t differ = 0;
            for (k = 0; k < 3u; k++) differ += !h_same(m.pos[3u * i + k], m.pos[3u * j + k]);
            if (differ == 1u) len += crease_line(text + len, i, j);
        }
    by_angle = subd_mesh_tag_crease_angle(&m, subd_cos_turns(60, 360));
    CHECK_EQ(by_angle, 12);
    i = tag_hash(&m);
    for (k = 0; k < m.num_corners; k++) m.edge_tag[k] &= (uint8_t)~SUBD_ETAG_CREASE;
    if (!CHECK_OK(subd_tags_apply(text, len, &m, &rep, &d), &d)) return;
    CHECK_EQ(rep.creases, 12);
    CHECK_EQ(tag_hash(&m), i);
}

/* A tag file through loop -l 1 gives the exact OBJ bytes the host tool wrote with its own
 * parser before the parser moved here (FNV-1a of the output of the original `subd loop -l 1
 * --tags` on test/data/icosahedron.obj, float32 and Q16.16). */
static void tags_equal_old_tool(void)
{
    static const char text[] = "# golden tags for test_tags.c\n"
                               "corner 1\r\n"
                               "crease 1 2\n"
                               "\n"
                               "  fixed\t3 # comment\n"
                               "crease 2 6\r\n"
                               "crease 6 2\n"
                               "crease 12 5\n";
    static char out[4096];
    subd_arena a;
    subd_mesh m, r;
    subd_diag d;
    subd_loop_opts lo;
    subd_tags_report rep;
    uint32_t len = 0;
    if (!read_mesh("test/data/icosahedron.obj", &a, &m)) return;
    if (!CHECK_OK(subd_tags_apply(text, slen(text), &m, &rep, &d), &d)) return;
    CHECK_EQ(rep.creases, 4);
    CHECK_EQ(rep.vertex_tags, 2);
    lo.levels = 1;
    lo.boundary = SUBD_LOOP_BOUNDARY_PAPER;
    lo.flags = 0;
    if (!CHECK_OK(subd_loop(&a, &m, &lo, &r, &d), &d)) return;
    if (!CHECK_EQ(subd_obj_write(&r, out, sizeof out, &len), SUBD_OK)) return;
    CHECK_EQ(len, SUBD_FIXED ? 2868 : 2136);
    CHECK_EQ(h_fnv(2166136261u, out, len), SUBD_FIXED ? 0x527e1d06u : 0xf91c1170u);
    h_hash("tags_loop1_icosahedron_obj", h_fnv(2166136261u, out, len));
}

/* alpha / falpha lines (the semi-stationary paper's parameters): syntax and index errors
 * with their line numbers, through the same check and apply as every other tag. */
static void tags_alpha_errors(void)
{
    expect("alpha 1\n", SUBD_ERR_PARSE, 1, "alpha without a value");
    expect("alpha 1 1/8 3\n", SUBD_ERR_PARSE, 1, "alpha with two values");
    expect("corner 2\nalpha 1 x\n", SUBD_ERR_PARSE, 2, "alpha value not a number");
    expect("alpha 1 1/0\n", SUBD_ERR_PARSE, 1, "zero denominator");
    expect("alpha 1 1/-8\n", SUBD_ERR_PARSE, 1, "negative denominator");
    expect("alpha 1 1/\n", SUBD_ERR_PARSE, 1, "empty denominator");
    expect("alpha 1 /8\n", SUBD_ERR_PARSE, 1, "empty numerator");
    expect("alpha 1 1/8/2\n", SUBD_ERR_PARSE, 1, "two slashes");
    expect("alpha 1 2000000000\n", SUBD_ERR_PARSE, 1, "numerator above 10^9");
    expect("alpha 1 10.12345deg\n", SUBD_ERR_PARSE, 1, "five decimals");
    expect("alpha 1 deg\n", SUBD_ERR_PARSE, 1, "degrees without digits");
    expect("alpha 1 1.2.3deg\n", SUBD_ERR_PARSE, 1, "two points");
    expect("alpha 1 36000.0001deg\n", SUBD_ERR_PARSE, 1, "more than 36000 degrees");
    expect("alpha 1 45 deg\n", SUBD_ERR_PARSE, 1, "unit as a field");
    expect("Alpha 1 1/8\n", SUBD_ERR_PARSE, 1, "keywords are lower case");
    expect("falpha 1\n", SUBD_ERR_PARSE, 1, "falpha without a value");
    expect("alpha x 1/8\n", SUBD_ERR_PARSE, 1, "vertex not a number");
    expect("# c\n\nalpha 13 1/8\n", SUBD_ERR_INDEX, 3, "one past the last vertex");
    expect("alpha 0 1/8\n", SUBD_ERR_INDEX, 1, "vertex 0");
    expect("falpha 21 1/8\n", SUBD_ERR_INDEX, 1, "one past the last face");
    expect("falpha 0 1/8\n", SUBD_ERR_INDEX, 1, "face 0");
    expect("falpha 20 -1/8\nalpha 12 36000deg\nalpha 12 -36000deg\nalpha 2 7 # turns\n", SUBD_OK, 0,
           "last face, last vertex, extremes");
}

/* The values: exact numerators over the caller's den, the last line for an element wins,
 * entries no line names keep theirs, the least common denominator in the report; a den that
 * does not make every value whole, or a numerator out of range, is SUBD_ERR_RANGE with the
 * line and nothing stored; apply sets no bits for alpha lines. */
static void tags_alpha_values(void)
{
    static const char text[] = "alpha 1 1/8\nalpha 3 -45deg\nfalpha 2 1/3\n# c\nalpha 1 2/8\nfalpha 20 10.5deg\n";
    subd_arena a;
    subd_mesh m;
    subd_diag d;
    subd_tags_report rep;
    int32_t vn[12], fn[20], v0[12], f0[20];
    uint32_t i, ok = 1, before;
    if (!read_mesh("test/data/icosahedron.obj", &a, &m)) return;
    for (i = 0; i < 12u; i++) vn[i] = v0[i] = 5;
    for (i = 0; i < 20u; i++) fn[i] = f0[i] = 5;
    CHECK_EQ(subd_tags_check(text, slen(text), &m, &rep, &d), SUBD_OK);
    CHECK_EQ(rep.vertex_alphas, 3);
    CHECK_EQ(rep.face_alphas, 2);
    CHECK_EQ(rep.alpha_den, 240); /* lcm of 8, 8, 3, 4 and 10.5 / 360 = 7 / 240 */
    CHECK_EQ(rep.alpha_line[0], 1);
    CHECK_EQ(rep.alpha_line[1], 3);
    CHECK_EQ(subd_tags_alpha(text, slen(text), &m, 240, vn, fn, &rep, &d), SUBD_OK);
    for (i = 0; i < 12u; i++) ok &= vn[i] == (i == 0 ? 60 : i == 2u ? -30 : 5);
    for (i = 0; i < 20u; i++) ok &= fn[i] == (i == 1u ? 80 : i == 19u ? 7 : 5);
    CHECK(ok);
    /* den 8: 1/3 (line 3) is not a whole number of eighths */
    for (i = 0; i < 12u; i++) vn[i] = v0[i];
    for (i = 0; i < 20u; i++) fn[i] = f0[i];
    CHECK_FAIL(subd_tags_alpha(text, slen(text), &m, 8, vn, fn, &rep, &d), &d, SUBD_ERR_RANGE);
    CHECK_EQ(d.line, 3);
    CHECK(memcmp(vn, v0, sizeof vn) == 0 && memcmp(fn, f0, sizeof fn) == 0);
    /* a numerator beyond SUBD_ALPHA_MAX_NUM: 8 turns over 2^28 */
    CHECK_FAIL(subd_tags_alpha("corner 1\nalpha 1 8\n", 19, &m, 1 << 28, vn, fn, &rep, &d), &d, SUBD_ERR_RANGE);
    CHECK_EQ(d.line, 2);
    CHECK(memcmp(vn, v0, sizeof vn) == 0);
    CHECK_EQ(subd_tags_alpha("alpha 1 -3\n", 11, &m, 1 << 28, vn, fn, &rep, &d), SUBD_OK);
    CHECK_EQ(vn[0], -3 * (1 << 28));
    CHECK_FAIL(subd_tags_alpha(text, slen(text), &m, 0, vn, fn, &rep, &d), &d, SUBD_ERR_PARAM);
    CHECK_EQ(subd_tags_alpha(text, slen(text), &m, 240, 0, 0, &rep, &d), SUBD_OK); /* checked only */
    /* a common denominator beyond int32 is reported as 0 */
    CHECK_EQ(subd_tags_check("alpha 1 1/999999937\nalpha 2 1/999999929\n", 40, &m, &rep, &d), SUBD_OK);
    CHECK_EQ(rep.alpha_den, 0);
    /* apply: alpha lines are counted, no bits set */
    before = tag_hash(&m);
    CHECK_EQ(subd_tags_apply(text, slen(text), &m, &rep, &d), SUBD_OK);
    CHECK_EQ(tag_hash(&m), before);
    CHECK_EQ(rep.vertex_alphas + rep.face_alphas, 5);
    CHECK_EQ(rep.vertex_tags + rep.creases, 0);
}

/* The one alpha grammar (subd_tags.h), by subd_tags_parse_alpha: accepted texts give the
 * reduced fraction written here by hand; degrees agree with X / 360 turns (checked by
 * cross-multiplication); refused texts (exponents, too many decimals, blanks, signs after
 * '/', out of range) leave the outputs alone and are refused on an alpha line as well. */
static void tags_alpha_grammar(void)
{
    static const struct { const char *t; int32_t num, den; } ok[] = {
        {"1/8", 1, 8}, {"2/16", 1, 8}, {"45deg", 1, 8}, {"+45deg", 1, 8}, {"45.deg", 1, 8},
        {"45.0000deg", 1, 8}, {"-45deg", -1, 8}, {".5deg", 1, 720}, {"10.5deg", 7, 240},
        {"0.0001deg", 1, 3600000}, {"36000deg", 100, 1}, {"-36000deg", -100, 1}, {"3", 3, 1},
        {"+3", 3, 1}, {"-6/4", -3, 2}, {"0", 0, 1}, {"0/7", 0, 1}, {"0deg", 0, 1},
        {"1000000000", 1000000000, 1}, {"-1000000000/999999999", -1000000000, 999999999},
        {"1/1000000000", 1, 1000000000}, {"515.662deg", 257831, 180000}};
    static const char *const bad[] = {
        "", "deg", "-deg", ".deg", "4.5e1deg", "45e0deg", "1e1", "45.00001deg", "36000.0001deg",
        "1/+8", "1/-8", "1/0", "1/", "/8", " 45deg", "45deg ", "45 deg", "45DEG", "0x10",
        "1.5", "1000000001", "1/1000000001", "45..0deg", "4-5deg", "nandeg", "infdeg", "1/8/2"};
    uint32_t i, bad_ok = 0, good = 0;
    int32_t num, den;
    for (i = 0; i < sizeof ok / sizeof ok[0]; i++) {
        num = den = 77;
        if (subd_tags_parse_alpha(ok[i].t, slen(ok[i].t), &num, &den) == SUBD_OK && num == ok[i].num &&
            den == ok[i].den)
            good++;
        else
            h_str(ok[i].t), h_nl();
    }
    CHECK_EQ(good, sizeof ok / sizeof ok[0]);
    for (i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        num = den = 77;
        if (subd_tags_parse_alpha(bad[i], slen(bad[i]), &num, &den) == SUBD_ERR_PARSE && num == 77 && den == 77)
            bad_ok++;
        else
            h_str(bad[i]), h_nl();
    }
    CHECK_EQ(bad_ok, sizeof bad / sizeof bad[0]);
    /* degrees X = k / 10^4 for k up to 36000 degrees in steps: num / den == k / (360 10^4) */
    {
        uint32_t k, wrong = 0;
        char buf[16];
        for (k = 0; k <= 360000000u; k += 1234567u) {
            uint32_t n = 0, j, ip = k / 10000u, fp = k % 10000u;
            char digits[12];
            do { digits[n++] = (char)('0' + ip % 10u); ip /= 10u; } while (ip);
            for (j = 0; j < n; j++) buf[j] = digits[n - 1u - j];
            buf[n++] = '.';
            buf[n++] = (char)('0' + fp / 1000u);
            buf[n++] = (char)('0' + fp / 100u % 10u);
            buf[n++] = (char)('0' + fp / 10u % 10u);
            buf[n++] = (char)('0' + fp % 10u);
            buf[n++] = 'd';
            buf[n++] = 'e';
            buf[n++] = 'g';
            if (subd_tags_parse_alpha(buf, n, &num, &den) != SUBD_OK ||
                (int64_t)num * 3600000 != (int64_t)k * den)
                wrong++;
        }
        CHECK_EQ(wrong, 0);
    }
    CHECK_EQ(subd_tags_parse_alpha(0, 0, &num, &den), SUBD_ERR_PARAM);
    CHECK_EQ(subd_tags_parse_alpha("1", 1, 0, &den), SUBD_ERR_PARAM);
    CHECK_EQ(subd_tags_parse_alpha("1", 1, &num, 0), SUBD_ERR_PARAM);
    /* the common denominator: the least common multiple by search, 0 beyond int32 */
    {
        int32_t x, y, l, wrong = 0;
        for (x = 1; x <= 24; x++)
            for (y = 1; y <= 24; y++) {
                for (l = x > y ? x : y; l % x != 0 || l % y != 0; l++) {
                }
                if (subd_tags_common_den(x, y) != l) wrong++;
            }
        CHECK_EQ(wrong, 0);
        CHECK_EQ(subd_tags_common_den(3600000, 8), 3600000);
        CHECK_EQ(subd_tags_common_den(999999937, 999999929), 0);
        CHECK_EQ(subd_tags_common_den(INT32_MAX, INT32_MAX), INT32_MAX);
        CHECK_EQ(subd_tags_common_den(0, 5), 0);
        CHECK_EQ(subd_tags_common_den(5, -1), 0);
    }
    /* the same grammar on an alpha line: an exponent is refused there too */
    expect("alpha 1 4.5e1deg\n", SUBD_ERR_PARSE, 1, "alpha with an exponent");
}

const test_case suite_tags[] = {
    {"tags_parse_errors", tags_parse_errors},
    {"tags_index_errors", tags_index_errors},
    {"tags_params", tags_params},
    {"tags_syntax", tags_syntax},
    {"tags_boundary_edge", tags_boundary_edge},
    {"tags_cube_edges", tags_cube_edges},
    {"tags_equal_old_tool", tags_equal_old_tool},
    {"tags_alpha_errors", tags_alpha_errors},
    {"tags_alpha_values", tags_alpha_values},
    {"tags_alpha_grammar", tags_alpha_grammar},
    {0, 0}
};
