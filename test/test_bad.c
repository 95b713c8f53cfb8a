/* SPDX-License-Identifier: MIT */
/* The bad-input corpus (test/bad): every file gives its specific status and line, leaves
 * the arena mark where it was and the output descriptor untouched. Expectations come from
 * test/bad/EXPECT, which the tool check in the Makefile reads too. */
#include "harness.h"
#include "corpus.h"

static const struct { const char *name; int status; } status_names[] = {
    {"SUBD_ERR_NOMEM", SUBD_ERR_NOMEM}, {"SUBD_ERR_PARAM", SUBD_ERR_PARAM},
    {"SUBD_ERR_PARSE", SUBD_ERR_PARSE}, {"SUBD_ERR_NAN", SUBD_ERR_NAN},
    {"SUBD_ERR_RANGE", SUBD_ERR_RANGE}, {"SUBD_ERR_INDEX", SUBD_ERR_INDEX},
    {"SUBD_ERR_FACE_SIZE", SUBD_ERR_FACE_SIZE}, {"SUBD_ERR_DEGENERATE", SUBD_ERR_DEGENERATE},
    {"SUBD_ERR_NONMANIFOLD_EDGE", SUBD_ERR_NONMANIFOLD_EDGE},
    {"SUBD_ERR_ORIENTATION", SUBD_ERR_ORIENTATION},
    {"SUBD_ERR_NONMANIFOLD_VERTEX", SUBD_ERR_NONMANIFOLD_VERTEX},
    {"SUBD_ERR_TOO_BIG", SUBD_ERR_TOO_BIG}, {"SUBD_ERR_EMPTY", SUBD_ERR_EMPTY},
    {0, 0}
};

static int tok_eq(const char *s, uint32_t n, const char *w)
{
    uint32_t i;
    for (i = 0; i < n; i++) if (w[i] != s[i]) return 0;
    return w[n] == 0;
}

/* Splits the line [s, e) into up to 4 blank-separated tokens. */
static uint32_t split(const char *s, const char *e, const char **tok, uint32_t *len)
{
    uint32_t n = 0;
    while (s < e && n < 4) {
        while (s < e && (*s == ' ' || *s == '\t')) s++;
        if (s >= e) break;
        tok[n] = s;
        while (s < e && *s != ' ' && *s != '\t') s++;
        len[n] = (uint32_t)(s - tok[n]);
        n++;
    }
    return n;
}

static void bad_corpus(void)
{
    const corpus_file *ex = corpus_find("test/bad/EXPECT");
    const char *p, *end;
    uint32_t rows = 0, files = 0, i;
    if (!CHECK(ex != 0)) return;
    p = ex->data;
    end = p + ex->len;
    while (p < end) {
        const char *e = p, *tok[4];
        uint32_t len[4], n, j, line = 0;
        char path[96] = "test/bad/";
        const corpus_file *f;
        int status = 1, st;
        subd_arena a;
        subd_mesh m;
        subd_diag d;
        uint8_t *pm = (uint8_t *)&m;
        int same = 1, is_off;
        while (e < end && *e != '\n') e++;
        n = split(p, e, tok, len);
        p = e + 1;
        if (n == 0 || tok[0][0] == '#') continue;
        if (!CHECK(n >= 3 && len[0] < 80u)) continue;
        for (j = 0; status_names[j].name; j++)
            if (tok_eq(tok[1], len[1], status_names[j].name)) status = status_names[j].status;
        if (!CHECK(status != 1)) continue;
        for (j = 0; j < len[2]; j++) line = line * 10u + (uint32_t)(tok[2][j] - '0');
        if (n == 4 && tok_eq(tok[3], len[3], SUBD_FIXED ? "float" : "fixed")) continue;
        for (j = 0; j < len[0]; j++) path[9 + j] = tok[0][j];
        path[9 + len[0]] = 0;
        f = corpus_find(path);
        if (!CHECK(f != 0)) { h_str("    missing "); h_str(path); h_nl(); continue; }
        rows++;
        is_off = path[9 + len[0] - 1] == 'f' && path[9 + len[0] - 2] == 'f';
        for (j = 0; j < sizeof m; j++) pm[j] = 0x3c;
        subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES - 64u);
        subd_arena_alloc(&a, 24);
        h_guard_fill(h_arena_buf + H_ARENA_BYTES - 64u, 64);
        st = is_off ? subd_off_read(&a, f->data, f->len, &m, &d) : subd_obj_read(&a, f->data, f->len, &m, &d);
        for (j = 0; j < sizeof m; j++) same &= (pm[j] == 0x3c);
        /* every check runs (a sum, not ||: each reports its own failure) */
        if ((!CHECK_EQ(st, status)) + (!CHECK_EQ(d.line, line)) + (!CHECK_EQ(subd_arena_mark(&a), 24)) + (!CHECK(same)) +
            (!CHECK(h_guard_ok(h_arena_buf + H_ARENA_BYTES - 64u, 64)))) {
            h_str("    in ");
            h_str(path);
            h_nl();
        }
        /* the planning call agrees on syntax errors and never succeeds on them */
        {
            uint32_t bytes;
            int pst = is_off ? subd_off_plan(f->data, f->len, &bytes, &d) : subd_obj_plan(f->data, f->len, &bytes, &d);
            if (pst != SUBD_OK) CHECK_EQ(pst, status);
        }
    }
    for (i = 0; i < corpus_count; i++) {
        const char *nm = corpus_files[i].name;
        if (nm[5] == 'b' && nm[6] == 'a' && nm[7] == 'd' && nm[8] == '/' && !tok_eq(nm + 9, 6, "EXPECT")) files++;
    }
    /* every corpus file has a row (rows for the other arithmetic are skipped above) */
    CHECK(rows + 1u >= files);
    CHECK(files >= 25u);
}

const test_case suite_bad[] = {
    {"bad_corpus", bad_corpus},
    {0, 0}
};
