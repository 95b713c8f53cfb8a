/* SPDX-License-Identifier: MIT */
/* Test harness implementation: counting, printing, hashing, guard bytes, PRNG, and each
 * suite's cost: a line `TIME suite_NAME N ms` (host: CPU milliseconds of the process, ASan
 * included) or `TIME suite_NAME N Minsn` (Cortex-M under QEMU -icount: millions of
 * instructions, exact), and `TIME   test_name N ...` for each test that costs at least the
 * threshold: 1 000 ms / 250 Minsn, on the host the environment's SUBD_TEST_TIMES=N (0: every
 * test). The lines are for finding where make test's time goes; nothing compares them.
 * SUBD_TEST_LONG=1 (host; make test-long) sets h_long; SUBD_TEST_ONLY=suite_X (host) runs one
 * suite. */
#include "harness.h"
#if H_HOST
#include <stdlib.h>
#include <string.h>
#include <time.h>
#else
#include "port_cm.h"
#endif

static uint32_t g_checks_failed_in_test;
static uint32_t g_tests_passed, g_tests_failed;

uint8_t h_arena_buf[H_ARENA_BYTES] __attribute__((aligned(8)));
int h_long;

int h_check(int cond, const char *file, int line, const char *expr)
{
    if (!cond) {
        g_checks_failed_in_test++;
        h_str("  FAIL ");
        h_str(file);
        h_str(":");
        h_u32((uint32_t)line);
        h_str(": ");
        h_str(expr);
        h_nl();
    }
    return cond;
}

int h_check_eq_i(int64_t got, int64_t want, const char *file, int line, const char *expr)
{
    if (got != want) {
        h_check(0, file, line, expr);
        h_str("    got ");
        h_i64(got);
        h_str(" want ");
        h_i64(want);
        h_nl();
        return 0;
    }
    return 1;
}

int h_check_ok(int status, const subd_diag *d, const char *file, int line, const char *expr)
{
    if (!h_check_eq_i(status, SUBD_OK, file, line, expr)) {
        h_str("    bytes_needed ");
        h_u32(d->bytes_needed);
        h_nl();
        return 0;
    }
    return 1;
}

void h_diag_poison(subd_diag *d)
{
    d->status = 0x5eed;
    d->line = d->face = d->vertex = d->polyline = d->bytes_needed = 0xa5a5a5a5u;
}

int h_fail_rule(int status, const subd_diag *d, int want)
{
    if (status != want) return 1;
    if (d->status != want) return 2;
    if ((want == SUBD_ERR_NOMEM) != (d->bytes_needed != 0u)) return 3;
    return 0;
}

int h_check_fail(int status, const subd_diag *d, int want, const char *file, int line, const char *expr)
{
    int r = h_fail_rule(status, d, want);
    if (r) {
        h_check(0, file, line, expr);
        h_str("    status ");
        h_i32(status);
        h_str(" want ");
        h_i32(want);
        h_str(", diag status ");
        h_i32(d->status);
        h_str(" bytes_needed ");
        h_u32(d->bytes_needed);
        h_nl();
    }
    return !r;
}

int h_build(subd_arena *a, const subd_face_list *fl, subd_mesh *m)
{
    subd_diag d;
    int st = subd_mesh_build(a, fl, m, &d);
    return CHECK_OK(st, &d);
}

int h_tetra_no_adjacency(subd_arena *a, subd_mesh *m, subd_mesh *noadj)
{
    static const uint32_t idx[] = {0, 2, 1, 0, 1, 3, 1, 2, 3, 2, 0, 3};
    static subd_real pos[12];
    subd_face_list fl = {4, 0, 4, 0, idx, 0, 0, 0};
    subd_loop_opts lo = {1, SUBD_LOOP_BOUNDARY_PAPER, 0};
    subd_diag d;
    uint32_t k;
    for (k = 0; k < 12u; k++) pos[k] = h_int((int32_t)((k * 7u) % 5u));
    pos[0] = h_int(9);
    fl.pos = pos;
    if (!h_build(a, &fl, m)) return 0;
    if (!CHECK_EQ(subd_loop(a, m, &lo, noadj, &d), SUBD_OK)) return 0;
    return CHECK(noadj->twin == 0 && noadj->vert_out == 0);
}

subd_face_list h_torus(uint32_t n, uint32_t m, subd_real *pos, uint32_t *idx)
{
    subd_face_list fl;
    uint32_t i, j, k = 0, ovf = 0;
    subd_real r = subd_div(h_int(2), h_int(5), &ovf);
    for (i = 0; i < n; i++)
        for (j = 0; j < m; j++) {
            subd_real cu = subd_cos_turns((int32_t)i, (int32_t)n), su = subd_sin_turns((int32_t)i, (int32_t)n);
            subd_real cv = subd_cos_turns((int32_t)j, (int32_t)m), sv = subd_sin_turns((int32_t)j, (int32_t)m);
            subd_real rad = subd_add(SUBD_REAL_ONE, subd_mul(r, cv, &ovf), &ovf);
            uint32_t v = i * m + j;
            pos[3 * v] = subd_mul(rad, cu, &ovf);
            pos[3 * v + 1] = subd_mul(rad, su, &ovf);
            pos[3 * v + 2] = subd_mul(r, sv, &ovf);
        }
    for (i = 0; i < n; i++)
        for (j = 0; j < m; j++) {
            uint32_t a = i * m + j, b = ((i + 1) % n) * m + j;
            uint32_t c = ((i + 1) % n) * m + (j + 1) % m, d = i * m + (j + 1) % m;
            idx[k++] = a; idx[k++] = b; idx[k++] = c;
            idx[k++] = a; idx[k++] = c; idx[k++] = d;
        }
    CHECK_EQ(ovf, 0);
    fl.num_verts = n * m;
    fl.pos = pos;
    fl.num_faces = 2 * n * m;
    fl.face_size = 0;
    fl.index = idx;
    fl.num_lines = 0;
    fl.line_size = fl.line_index = 0;
    return fl;
}

uint32_t h_fnv(uint32_t h, const void *data, uint32_t n)
{
    const uint8_t *p = (const uint8_t *)data;
    uint32_t i;
    for (i = 0; i < n; i++) { h ^= p[i]; h *= 16777619u; }
    return h;
}

static uint32_t fnv_u32(uint32_t h, uint32_t v)
{
    uint8_t b[4];
    b[0] = (uint8_t)v; b[1] = (uint8_t)(v >> 8); b[2] = (uint8_t)(v >> 16); b[3] = (uint8_t)(v >> 24);
    return h_fnv(h, b, 4);
}

uint32_t h_mesh_hash(const subd_mesh *m)
{
    uint32_t h = 2166136261u, i;
    h = fnv_u32(h, m->num_verts);
    h = fnv_u32(h, m->num_faces);
    for (i = 0; i < 3u * m->num_verts; i++) h = fnv_u32(h, subd_real_bits(m->pos[i]));
    for (i = 0; i <= m->num_faces; i++) h = fnv_u32(h, m->face_start[i]);
    for (i = 0; i < m->num_corners; i++) {
        h = fnv_u32(h, m->corner_vert[i]);
        h = fnv_u32(h, m->twin[i]);
        h = fnv_u32(h, m->edge_tag[i]);
    }
    for (i = 0; i < m->num_verts; i++) {
        h = fnv_u32(h, m->vert_out[i]);
        h = fnv_u32(h, m->vert_tag[i]);
    }
    for (i = 0; i < m->num_line_verts; i++) h = fnv_u32(h, m->line_vert[i]);
    return h;
}

void h_hash(const char *name, uint32_t value)
{
    h_str("HASH ");
    h_str(name);
    h_str(" ");
    h_hex32(value);
    h_nl();
}

uint32_t h_rand(uint32_t *s)
{
    uint32_t x = *s ? *s : 2463534242u;
    x ^= x << 13; x ^= x >> 17; x ^= x << 5;
    *s = x;
    return x;
}

void h_guard_fill(uint8_t *p, uint32_t n)
{
    uint32_t i;
    for (i = 0; i < n; i++) p[i] = (uint8_t)(0xA5u ^ i);
}

int h_guard_ok(const uint8_t *p, uint32_t n)
{
    uint32_t i;
    for (i = 0; i < n; i++) if (p[i] != (uint8_t)(0xA5u ^ i)) return 0;
    return 1;
}

h_sweep h_sweep_make(int (*run)(void *, subd_arena *, subd_diag *), void *ctx, uint8_t *buf,
                     uint32_t buf_bytes, uint32_t plan)
{
    h_sweep s;
    uint8_t *p = (uint8_t *)&s;
    uint32_t i;
    for (i = 0; i < sizeof s; i++) p[i] = 0;
    s.run = run;
    s.ctx = ctx;
    s.buf = buf;
    s.buf_bytes = buf_bytes;
    s.plan = s.need_lo = s.need_hi = plan;
    s.step = 1;
    return s;
}

static void fill_out(uint8_t *p, uint32_t n)
{
    uint32_t i;
    for (i = 0; i < n; i++) p[i] = (uint8_t)(0x5au ^ i);
}

static int out_untouched(const uint8_t *p, uint32_t n)
{
    uint32_t i;
    for (i = 0; i < n; i++) if (p[i] != (uint8_t)(0x5au ^ i)) return 0;
    return 1;
}

#define SWEEP_CHECK(c) h_check((c) ? 1 : 0, file, line, "arena sweep: " #c)

/* The failing checks' size, status and bytes_needed; returns 0. */
static int sweep_failed(const h_sweep *s, uint32_t size, int st, const subd_diag *d)
{
    h_str("    arena sweep failed at size ");
    h_u32(size);
    h_str(" of plan ");
    h_u32(s->plan);
    h_str(": status ");
    h_i32(st);
    h_str(" bytes_needed ");
    h_u32(d->bytes_needed);
    h_nl();
    return 0;
}

/* One call of the sweep with an arena of size bytes after the prefix; 1 when its checks
 * pass, 2 when it succeeded (the sweep ends), 0 when a check failed. */
static int sweep_one(h_sweep *s, uint32_t size, const char *file, int line, uint32_t mh, uint32_t ih)
{
    subd_arena a;
    subd_diag d;
    uint8_t *end = s->buf + s->prefix + size;
    int st, ok = 1;
    if (s->out) fill_out((uint8_t *)s->out, s->out_bytes);
    subd_arena_init(&a, s->buf, s->prefix + size);
    subd_arena_alloc(&a, s->prefix);
    h_guard_fill(end, 64);
    st = s->run(s->ctx, &a, &d);
    ok &= SWEEP_CHECK(h_guard_ok(end, 64));
    if (s->in_mesh) ok &= SWEEP_CHECK(h_mesh_hash(s->in_mesh) == mh);
    if (s->in) ok &= SWEEP_CHECK(h_fnv(2166136261u, s->in, s->in_bytes) == ih);
    if (size < s->plan && !(s->plan_is_bound && st == SUBD_OK)) {
        ok &= SWEEP_CHECK(st == SUBD_ERR_NOMEM);
        ok &= h_check_eq_i(subd_arena_mark(&a), s->prefix, file, line, "arena sweep: mark == prefix");
        if (s->keep_peak) ok &= h_check_eq_i(a.peak, s->prefix, file, line, "arena sweep: peak == prefix");
        ok &= SWEEP_CHECK(d.bytes_needed > size);
        ok &= SWEEP_CHECK(d.bytes_needed >= s->need_lo && d.bytes_needed <= s->need_hi);
        if (s->out) ok &= SWEEP_CHECK(out_untouched((const uint8_t *)s->out, s->out_bytes));
        return ok ? 1 : sweep_failed(s, size, st, &d);
    }
    if (!SWEEP_CHECK(st == SUBD_OK)) return sweep_failed(s, size, st, &d);
    s->need = size;
    s->peak = a.peak - s->prefix;
    if (s->peak_le) ok &= SWEEP_CHECK(s->peak <= size);
    else ok &= h_check_eq_i(s->peak, size, file, line, "arena sweep: peak - prefix == plan");
    if (s->ok) s->ok(s->ctx, &a, &d);
    return ok ? 2 : sweep_failed(s, size, st, &d);
}

int h_arena_sweep_at(h_sweep *s, const char *file, int line)
{
    uint32_t size, mh = s->in_mesh ? h_mesh_hash(s->in_mesh) : 0u;
    uint32_t ih = s->in ? h_fnv(2166136261u, s->in, s->in_bytes) : 0u;
    s->need = s->peak = 0;
    if (!SWEEP_CHECK(s->prefix + s->plan + 64u <= s->buf_bytes)) return 0;
    for (size = s->first; size <= s->plan; size += (size + 64u >= s->plan || !s->step) ? 1u : s->step) {
        int r = sweep_one(s, size, file, line, mh, ih);
        if (r != 1) return r == 2;
    }
    return SWEEP_CHECK(0); /* not reached: the plan itself ends the sweep */
}

h_sweep h_mesh_sweep(int (*run)(void *, subd_arena *, subd_diag *), h_mesh_call *c, uint8_t *buf,
                     uint32_t buf_bytes, uint32_t plan)
{
    h_sweep s = h_sweep_make(run, c, buf, buf_bytes, plan);
    s.out = &c->out;
    s.out_bytes = sizeof c->out;
    s.in_mesh = c->in;
    return s;
}

typedef struct reader_call {
    h_reader read;
    const char *text;
    uint32_t len;
    subd_mesh m;
} reader_call;

static int reader_run(void *ctx, subd_arena *a, subd_diag *d)
{
    reader_call *c = (reader_call *)ctx;
    return c->read(a, c->text, c->len, &c->m, d);
}

int h_reader_sweep_at(h_reader read, const char *text, uint32_t len, uint8_t *buf, uint32_t buf_bytes,
                      uint32_t plan, const char *file, int line)
{
    reader_call c;
    h_sweep s = h_sweep_make(reader_run, &c, buf, buf_bytes, plan);
    c.read = read;
    c.text = text;
    c.len = len;
    s.out = &c.m;
    s.out_bytes = sizeof c.m;
    s.in = text;
    s.in_bytes = len;
    return h_arena_sweep_at(&s, file, line);
}

int h_reader_expect(h_reader read, h_reader_plan plan, const char *buf, uint32_t len, uint32_t arena_bytes, int st,
                    uint32_t line, uint32_t face, uint32_t vert, int src_line)
{
    subd_arena a;
    subd_mesh m;
    subd_diag d;
    uint32_t i, same = 1, bytes = 0, fails;
    int got, pst;
    uint8_t *pm = (uint8_t *)&m;
    for (i = 0; i < sizeof m; i++) pm[i] = 0x3c;
    subd_arena_init(&a, h_arena_buf, arena_bytes);
    subd_arena_alloc(&a, 40);
    h_diag_poison(&d);
    got = read(&a, buf, len, &m, &d);
    for (i = 0; i < sizeof m; i++) same &= pm[i] == 0x3c;
    pst = plan(buf, len, &bytes, 0);
    /* every check runs (a sum, not ||), so a failing case reports all its differences */
    fails = (uint32_t)!CHECK_EQ(got, st) + (uint32_t)!CHECK_EQ(d.status, st) + (uint32_t)!CHECK_EQ(d.line, line) +
            (uint32_t)!CHECK_EQ(d.face, face) + (uint32_t)!CHECK(vert == H_ANY || d.vertex == vert) +
            (uint32_t)!CHECK_EQ(subd_arena_mark(&a), 40) + (uint32_t)!CHECK(same) +
            (uint32_t)!CHECK_EQ(h_fail_rule(got, &d, st), 0) +
            (uint32_t)!CHECK(pst == st || (pst == SUBD_OK && st <= SUBD_ERR_DEGENERATE));
    if (fails != 0u) {
        h_str("    case at test line ");
        h_u32((uint32_t)src_line);
        h_nl();
        return 0;
    }
    return 1;
}

#if H_HOST
#define H_TIME_UNIT " ms"
/* Process CPU time in milliseconds. */
static uint32_t h_time_now(void) { return (uint32_t)((uint64_t)clock() * 1000u / (uint64_t)CLOCKS_PER_SEC); }
static int h_long_wanted(void)
{
    const char *e = getenv("SUBD_TEST_LONG");
    return e && *e && *e != '0';
}
/* SUBD_TEST_ONLY=suite_X (host): run that suite alone (the quick loop on one subject). */
static int h_suite_wanted(const char *name)
{
    const char *e = getenv("SUBD_TEST_ONLY");
    return !e || !*e || strcmp(e, name) == 0;
}
static uint32_t h_time_threshold(void)
{
    const char *e = getenv("SUBD_TEST_TIMES");
    uint32_t v = 0;
    if (!e || !*e) return 1000u;
    for (; *e >= '0' && *e <= '9'; e++) v = v * 10u + (uint32_t)(*e - '0');
    return v;
}
#else
#define H_TIME_UNIT " Minsn"
/* Millions of instructions (QEMU -icount shift=0; qemu/run.sh); differences modulo 2^32
 * ticks, far above any one suite. */
static uint32_t h_time_now(void) { return port_cycles() / (1000000u / PORT_QEMU_INSNS_PER_TICK); }
static uint32_t h_time_threshold(void) { return 250u; }
static int h_long_wanted(void) { return 0; }
static int h_suite_wanted(const char *name) { return name != 0; }
#endif

static void h_time_line(const char *indent, const char *name, uint32_t t)
{
    h_str("TIME ");
    h_str(indent);
    h_str(name);
    h_str(" ");
    h_u32(t);
    h_str(H_TIME_UNIT);
    h_nl();
}

static void run_suite(const test_case *t, const char *suite_name)
{
    uint32_t threshold = h_time_threshold(), t_suite = h_time_now();
    if (!h_suite_wanted(suite_name)) return;
    for (; t->name; t++) {
        uint32_t t0 = h_time_now(), dt;
        g_checks_failed_in_test = 0;
        t->fn();
        dt = h_time_now() - t0;
        if (g_checks_failed_in_test) {
            g_tests_failed++;
            h_str("FAIL ");
        } else {
            g_tests_passed++;
            h_str("ok   ");
        }
        h_str(t->name);
        h_nl();
        if (dt >= threshold) h_time_line("  ", t->name, dt);
    }
    h_time_line("", suite_name, h_time_now() - t_suite);
}

int main(void)
{
    /* Print the effective configuration so a misspelt option cannot pass silently. */
    h_str("tinysubd " SUBD_VERSION " tests: arithmetic=");
    h_str(SUBD_FIXED ? "q16.16" : "float32");
    h_str(" platform=");
    h_str(H_HOST ? "host" : "cortex-m");
    h_str(" max_face_size=");
    h_u32(SUBD_MAX_FACE_SIZE);
    h_str(" max_levels=");
    h_u32(SUBD_MAX_LEVELS);
    h_long = h_long_wanted();
    if (h_long) h_str(" long=1");
    h_nl();
    if (h_harness_only) {
        run_suite(suite_harness, "suite_harness");
    } else {
#define SUITE(name) run_suite(name, #name);
#include "suites.h"
#undef SUITE
    }
    h_u32(g_tests_passed);
    h_str(" passed, ");
    h_u32(g_tests_failed);
    h_str(" failed");
    h_nl();
    port_exit(g_tests_failed ? 1 : 0);
    return g_tests_failed ? 1 : 0;
}
