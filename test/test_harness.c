/* SPDX-License-Identifier: MIT */
/* The harness itself: its formatter, hash and PRNG against known values, target
 * assumptions the library relies on (arithmetic right shift, type sizes), and the failure
 * rule of CHECK_FAIL firing on diags that break it. Built once more
 * with -DH_INJECT_FAILURE=1 to prove that a failing check fails the run (Makefile). */
#include "harness.h"

/* print_fmt_u64(v) is the decimal text want. */
static int fmt_is(uint64_t v, const char *want)
{
    char b[20];
    uint32_t n = print_fmt_u64(b, v), i;
    for (i = 0; i < n; i++) if (want[i] != b[i]) return 0;
    return want[n] == 0;
}

static void harness_known_values(void)
{
    /* the formatter: 0, 32-bit limits and past them, the 64-bit maximum */
    CHECK(fmt_is(0u, "0"));
    CHECK(fmt_is(4294967295u, "4294967295"));
    CHECK(fmt_is(4294967296u, "4294967296"));
    CHECK(fmt_is(UINT64_MAX, "18446744073709551615"));
    /* FNV-1a 32-bit of "a" and of "foobar" (published test vectors) */
    CHECK(h_fnv(2166136261u, "a", 1) == 0xe40c292cu);
    CHECK(h_fnv(2166136261u, "foobar", 6) == 0xbf9cf968u);
    /* xorshift32 from seed 1: first outputs of Marsaglia's generator */
    {
        uint32_t s = 1;
        CHECK(h_rand(&s) == 270369u);
        CHECK(h_rand(&s) == 67634689u);
    }
    {
        uint8_t g[16];
        h_guard_fill(g, 16);
        CHECK(h_guard_ok(g, 16));
        g[15] ^= 1u;
        CHECK(!h_guard_ok(g, 16));
    }
}

static void harness_target_assumptions(void)
{
    volatile int64_t neg = -3;
    volatile int32_t neg32 = -3;
    CHECK(sizeof(uint32_t) == 4 && sizeof(int64_t) == 8);
    CHECK(sizeof(subd_real) == 4);
    /* Q16.16 rounding relies on >> of a negative value being an arithmetic shift */
    CHECK((neg >> 1) == -2);
    CHECK((neg32 >> 1) == -2);
}

/* The failure rule that CHECK_FAIL applies to every provoked failure fires: a wrong status,
 * a diag whose status was not written, bytes_needed with another status than NOMEM, none
 * with NOMEM; and a real failing call passes it. */
static void harness_fail_rule(void)
{
    subd_diag d;
    subd_arena a;
    subd_mesh out;
    subd_loop_opts lo = {1, SUBD_LOOP_BOUNDARY_PAPER, 0};
    subd_diag_clear(&d);
    d.status = SUBD_ERR_PARAM;
    CHECK_EQ(h_fail_rule(SUBD_ERR_PARAM, &d, SUBD_ERR_PARAM), 0);
    CHECK_EQ(h_fail_rule(SUBD_ERR_RANGE, &d, SUBD_ERR_PARAM), 1);
    CHECK_EQ(h_fail_rule(SUBD_OK, &d, SUBD_ERR_PARAM), 1);
    d.bytes_needed = 64u;
    CHECK_EQ(h_fail_rule(SUBD_ERR_PARAM, &d, SUBD_ERR_PARAM), 3);
    d.status = SUBD_ERR_NOMEM;
    CHECK_EQ(h_fail_rule(SUBD_ERR_NOMEM, &d, SUBD_ERR_NOMEM), 0);
    d.bytes_needed = 0u;
    CHECK_EQ(h_fail_rule(SUBD_ERR_NOMEM, &d, SUBD_ERR_NOMEM), 3);
    h_diag_poison(&d); /* a call that never wrote the diag */
    CHECK_EQ(h_fail_rule(SUBD_ERR_PARAM, &d, SUBD_ERR_PARAM), 2);
    /* a real call: NULL input -> PARAM, no need; an empty arena -> NOMEM with its need */
    subd_arena_init(&a, h_arena_buf, 0u);
    CHECK_FAIL(subd_loop(&a, 0, &lo, &out, &d), &d, SUBD_ERR_PARAM);
    {
        subd_mesh m, noadj;
        subd_arena big;
        subd_arena_init(&big, h_arena_buf, H_ARENA_BYTES);
        if (h_tetra_no_adjacency(&big, &m, &noadj)) CHECK_FAIL(subd_loop(&a, &m, &lo, &out, &d), &d, SUBD_ERR_NOMEM);
    }
}

#if defined(H_INJECT_FAILURE) && H_INJECT_FAILURE
/* The injected-failure image runs this suite alone (harness.c's main reads the flag): it
 * proves that one failing check fails a run and is counted, which needs no other suite, and
 * the whole device suite twice more under QEMU would cost minutes of make test. */
const int h_harness_only = 1;

static void harness_injected_failure(void)
{
    CHECK(1 + 1 == 3); /* must be reported and must fail the run */
}
#else
const int h_harness_only = 0;
#endif

const test_case suite_harness[] = {
    {"harness_known_values", harness_known_values},
    {"harness_target_assumptions", harness_target_assumptions},
    {"harness_fail_rule", harness_fail_rule},
#if defined(H_INJECT_FAILURE) && H_INJECT_FAILURE
    {"harness_injected_failure", harness_injected_failure},
#endif
    {0, 0}
};
