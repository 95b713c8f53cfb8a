/* SPDX-License-Identifier: MIT */
/* Test harness shared by the host and QEMU builds: explicit test tables, CHECK macros that
 * report file:line and keep going, and output through one port write function with an own
 * integer formatter so host and target print the same bytes. */
#ifndef HARNESS_H
#define HARNESS_H

#include <stdint.h>
#include "subd.h"

#include "print.h" /* port_write, port_exit, print_* (port/print.c) */

typedef void (*test_fn)(void);
typedef struct test_case {
    const char *name;
    test_fn fn;
} test_case;

/* Every suite is a table ending with {0, 0}; the Makefile lists them in build/gen/suites.h
 * (every `const test_case suite_NAME[] = {` of test/test_*.c, in file name order). */
#define SUITE(name) extern const test_case name[];
#include "suites.h"
#undef SUITE

#define h_str print_str
#define h_u32 print_u32
#define h_i32 print_i32
#define h_u64 print_u64
#define h_i64 print_i64
#define h_hex32 print_hex32
#define h_nl print_nl

/* Records one check; prints the failing location and expression. Returns cond. */
int h_check(int cond, const char *file, int line, const char *expr);
int h_check_eq_i(int64_t got, int64_t want, const char *file, int line, const char *expr);

#define CHECK(c) h_check((c) ? 1 : 0, __FILE__, __LINE__, #c)
#define CHECK_EQ(got, want) h_check_eq_i((int64_t)(got), (int64_t)(want), __FILE__, __LINE__, #got " == " #want)

/* A library call's status must be SUBD_OK; on failure also prints diag.bytes_needed. */
int h_check_ok(int status, const subd_diag *d, const char *file, int line, const char *expr);
#define CHECK_OK(st, d) h_check_ok((st), (d), __FILE__, __LINE__, #st " == SUBD_OK")

/* An expected failure of a call that takes the diag d (not NULL): CHECK_FAIL(call, d, want)
 * poisons *d, makes the call and checks that it returned want and that d obeys the one
 * failure exit (src/entry.h): d->status == want, and d->bytes_needed nonzero with
 * SUBD_ERR_NOMEM, zero with every other status. h_fail_rule is that rule alone: 0 when it
 * holds, else which part broke (1 status, 2 diag status, 3 bytes_needed); h_diag_poison sets
 * every field of d to a value no call reports. */
void h_diag_poison(subd_diag *d);
int h_fail_rule(int status, const subd_diag *d, int want);
int h_check_fail(int status, const subd_diag *d, int want, const char *file, int line, const char *expr);
#define CHECK_FAIL(call, d, want) \
    h_check_fail((h_diag_poison(d), (call)), (d), (want), __FILE__, __LINE__, #call " fails with " #want)

/* Output hashes: FNV-1a 32-bit. Every test that builds output prints `HASH name value`
 * lines; the Makefile compares those lines between host and QEMU for each arithmetic. */
uint32_t h_fnv(uint32_t h, const void *data, uint32_t n);
uint32_t h_mesh_hash(const subd_mesh *m);
void h_hash(const char *name, uint32_t value);

/* An integer as a subd_real, and bit-identity of two subd_reals (for exactness checks). */
static inline subd_real h_int(int32_t i)
{
    uint32_t ovf = 0;
    return subd_from_int(i, &ovf);
}
static inline int h_same(subd_real a, subd_real b) { return subd_real_bits(a) == subd_real_bits(b); }

/* A subd_real as a double, for the tests' independent reference computations. */
static inline double h_dbl(subd_real x) { return SUBD_FIXED ? (double)x / 65536.0 : (double)x; }

/* subd_mesh_build of a face list that must succeed (a failed CHECK otherwise). */
int h_build(subd_arena *a, const subd_face_list *fl, subd_mesh *m);
/* A small tetrahedron built in a (*m, full adjacency) and its level-1 Loop output made without
 * SUBD_LOOP_ADJACENCY (*noadj: twin and vert_out NULL), the library's own mesh that every call
 * must refuse or handle without dereferencing the missing arrays. 1, or 0 after a failed CHECK. */
int h_tetra_no_adjacency(subd_arena *a, subd_mesh *m, subd_mesh *noadj);

/* Torus of n x m quads (R = 1, r = 0.4) cut by the diagonals a-c: a closed genus-1 triangle
 * mesh in pos (3 n m reals) and idx (6 n m indices). CHECKs that the coordinates fit. */
subd_face_list h_torus(uint32_t n, uint32_t m, subd_real *pos, uint32_t *idx);

/* Deterministic PRNG (xorshift32) for property tests: no rand(), no clocks. */
uint32_t h_rand(uint32_t *state);

/* Guard bytes: fill / verify a pattern around arena buffers (out-of-bounds detection that
 * works on the target, where there is no AddressSanitizer). */
void h_guard_fill(uint8_t *p, uint32_t n);
int h_guard_ok(const uint8_t *p, uint32_t n);

/* Every too-small arena: h_arena_sweep calls run() with an arena of prefix + size bytes, the
 * first prefix of them allocated before the call (so the call does not start at offset 0),
 * for every size from first to the plan, 64 guard bytes after the arena. Each size below the
 * plan must fail with SUBD_ERR_NOMEM, bytes_needed in [need_lo, need_hi] and above size, the
 * arena mark unchanged (and the peak too with keep_peak), the output bytes out[0..out_bytes)
 * as filled before the call, the inputs (in_mesh's hash, in[0..in_bytes)) unchanged and the
 * guard bytes intact. The plan itself must succeed with peak - prefix == plan (<= with
 * peak_le), then ok() runs for the suite's own checks. With plan_is_bound the plan is only an
 * upper bound: the first size that succeeds ends the sweep. need and peak report the size
 * that succeeded and its peak (without the prefix). Stops at the first size that fails a
 * check, printing it; returns whether every check passed. h_sweep_make sets the defaults:
 * every size, prefix 0, need_lo = need_hi = plan, nothing else watched. */
typedef struct h_sweep {
    int (*run)(void *ctx, subd_arena *a, subd_diag *d);           /* the call; its status */
    void (*ok)(void *ctx, const subd_arena *a, const subd_diag *d); /* 0 or after success */
    void *ctx;
    uint8_t *buf;         /* arena memory (8-aligned): prefix + plan + 64 bytes must fit */
    uint32_t buf_bytes;
    uint32_t plan, prefix, first, step; /* step > 1: every step-th size, the last 64 all */
    uint32_t need_lo, need_hi;
    void *out;            /* 0 or the output the failing calls must not write */
    uint32_t out_bytes;
    const subd_mesh *in_mesh; /* 0 or an input mesh the calls must not change */
    const void *in;           /* 0 or input bytes the calls must not change */
    uint32_t in_bytes;
    int plan_is_bound, peak_le, keep_peak;
    uint32_t need, peak;  /* results */
} h_sweep;
h_sweep h_sweep_make(int (*run)(void *, subd_arena *, subd_diag *), void *ctx, uint8_t *buf,
                     uint32_t buf_bytes, uint32_t plan);
int h_arena_sweep_at(h_sweep *s, const char *file, int line);
#define h_arena_sweep(s) h_arena_sweep_at((s), __FILE__, __LINE__)

/* The context of a call from one mesh to another (subd_loop, subd_quasi48, ...): the suite's
 * run() casts opts back. h_mesh_sweep watches out and in. */
typedef struct h_mesh_call {
    const subd_mesh *in;
    const void *opts;
    subd_mesh out;
} h_mesh_call;
h_sweep h_mesh_sweep(int (*run)(void *, subd_arena *, subd_diag *), h_mesh_call *c, uint8_t *buf,
                     uint32_t buf_bytes, uint32_t plan);

/* The sweep of a mesh reader (subd_obj_read, subd_off_read) over text[0..len) with that plan:
 * the output mesh and the text are watched. */
typedef int (*h_reader)(subd_arena *, const char *, uint32_t, subd_mesh *, subd_diag *);
int h_reader_sweep_at(h_reader read, const char *text, uint32_t len, uint8_t *buf, uint32_t buf_bytes,
                      uint32_t plan, const char *file, int line);
#define h_reader_sweep(read, text, len, buf, buf_bytes, plan) \
    h_reader_sweep_at((read), (text), (len), (buf), (buf_bytes), (plan), __FILE__, __LINE__)

/* A reader's failure, the one check of every reader's error tests (test_stl.c, test_ply.c):
 * read(buf[0..len)) into an arena over h_arena_buf[0..arena_bytes) that already holds a
 * block returns st with diag status st, line, face and vertex as given (H_ANY: not checked);
 * the arena mark and the output mesh are as before the call; the plan call either fails
 * with the same status or passes (SUBD_OK) for the failures only the read can see
 * (st <= SUBD_ERR_DEGENERATE: validation after parsing). On a mismatch it names the test
 * line src_line. Returns 1 when all held. */
#define H_ANY 0xfffffffeu
typedef int (*h_reader_plan)(const char *, uint32_t, uint32_t *, subd_diag *);
int h_reader_expect(h_reader read, h_reader_plan plan, const char *buf, uint32_t len, uint32_t arena_bytes, int st,
                    uint32_t line, uint32_t face, uint32_t vert, int src_line);

/* A shared scratch arena buffer for tests (static, 8-aligned). */
#define H_ARENA_BYTES (256u * 1024u)
extern uint8_t h_arena_buf[];
/* Nonzero in the injected-failure image (test_harness.c): main runs suite_harness alone. */
extern const int h_harness_only;
/* Nonzero for make test-long (host only: the environment's SUBD_TEST_LONG=1): the long
 * variants of the sweeps, the deepest levels that make test leaves out (each test says which). */
extern int h_long;

#if defined(SUBD_HOST)
#define H_HOST 1
#else
#define H_HOST 0
#endif

#endif
