/* SPDX-License-Identifier: MIT */
/* Arena: alignment, mark/rewind, peak, failure leaves state unchanged, size arithmetic. */
#include "harness.h"

static void arena_basic(void)
{
    subd_arena a;
    uint8_t *p, *q;
    subd_arena_init(&a, h_arena_buf, 100);
    CHECK_EQ(a.size, 100);
    p = (uint8_t *)subd_arena_alloc(&a, 3);
    CHECK(p == h_arena_buf);
    CHECK_EQ(subd_arena_mark(&a), 8);
    q = (uint8_t *)subd_arena_alloc(&a, 8);
    CHECK(q == h_arena_buf + 8);
    CHECK_EQ(a.peak, 16);
    subd_arena_rewind(&a, 8);
    CHECK_EQ(subd_arena_mark(&a), 8);
    CHECK_EQ(a.peak, 16);
    CHECK_EQ(subd_arena_free_bytes(&a), 92);
    /* too big: NULL and nothing changes */
    CHECK(subd_arena_alloc(&a, 93) == 0);
    CHECK_EQ(subd_arena_mark(&a), 8);
    CHECK(subd_arena_alloc(&a, 92) == 0); /* 92 rounds up to 96 > 92 free */
    CHECK(subd_arena_alloc(&a, 88) != 0);
    CHECK_EQ(subd_arena_free_bytes(&a), 4);
    CHECK(subd_arena_alloc(&a, 0) != 0);
    CHECK(subd_arena_alloc(&a, UINT32_MAX) == 0);
    CHECK(subd_arena_alloc(&a, UINT32_MAX - 3u) == 0);
    /* a new peak measurement starts at the current position */
    subd_arena_rewind(&a, 8);
    subd_arena_reset_peak(&a);
    CHECK_EQ(a.peak, 8);
    CHECK(subd_arena_alloc(&a, 16) != 0);
    CHECK_EQ(a.peak, 24);
    /* rewinding forward is ignored */
    subd_arena_rewind(&a, 8);
    subd_arena_rewind(&a, 50);
    CHECK_EQ(subd_arena_mark(&a), 8);
}

static void arena_misaligned(void)
{
    subd_arena a;
    uint8_t *p;
    uint32_t off;
    for (off = 0; off < 8u; off++) {
        subd_arena_init(&a, h_arena_buf + off, 64);
        p = (uint8_t *)subd_arena_alloc(&a, 4);
        CHECK(p != 0);
        CHECK(((uintptr_t)p & 7u) == 0);
        CHECK(p >= h_arena_buf + off);
        CHECK_EQ(a.size, 64u - ((8u - off) & 7u));
    }
    subd_arena_init(&a, h_arena_buf + 1, 3); /* smaller than the alignment skip */
    CHECK_EQ(a.size, 0);
    CHECK(subd_arena_alloc(&a, 1) == 0);
    subd_arena_init(&a, 0, 100);
    CHECK_EQ(a.size, 0);
    CHECK(subd_arena_alloc(&a, 1) == 0);
}

static void size_arith(void)
{
    uint32_t t = 0;
    subd_size_add(&t, 3, 1);
    CHECK_EQ(t, 8);
    subd_size_add(&t, 10, 4);
    CHECK_EQ(t, 48);
    subd_size_add(&t, 0x40000000u, 4u); /* 2^32: does not fit */
    CHECK(t == UINT32_MAX);
    subd_size_add(&t, 1, 1); /* sticky */
    CHECK(t == UINT32_MAX);
    t = UINT32_MAX - 16u;
    subd_size_add(&t, 9, 1);
    CHECK(t == UINT32_MAX);
    t = 0;
    subd_size_add(&t, 0xffffffffu, 0xffffffffu);
    CHECK(t == UINT32_MAX);
}

const test_case suite_arena[] = {
    {"arena_basic", arena_basic},
    {"arena_misaligned", arena_misaligned},
    {"arena_size_arith", size_arith},
    {0, 0}
};
