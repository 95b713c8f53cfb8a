/* SPDX-License-Identifier: MIT */
/* Self-test of the Cortex-M test machinery (startup, port, linker script, qemu/run.sh).
 * Built once per mode with -DSELFTEST_MODE=n; the Makefile runs every image and requires:
 *   0  passes: checks startup did its job (.data, .bss, FPU), prints, exits 0
 *   1  a failing check: exits 1 by returning from main (startup's exit path)
 *   2  HardFault (undefined instruction): the fault handler reports and exits non-zero
 *   3  hangs: the runner must time out with status 124
 * A runner that turned any of these into the wrong status would let broken tests pass. */
#include <stdint.h>
#include "port_cm.h"

#ifndef SELFTEST_MODE
#error "compile with -DSELFTEST_MODE=0..3"
#endif

int main(void);

static void put(const char *s)
{
    uint32_t n = 0;
    while (s[n] != '\0') {
        n++;
    }
    port_write(s, n);
}

#if SELFTEST_MODE == 0
static void put_hex(uint32_t v)
{
    char b[10];
    int i;
    b[0] = '0';
    b[1] = 'x';
    for (i = 0; i < 8; i++) {
        b[9 - i] = "0123456789abcdef"[v & 0xFu];
        v >>= 4;
    }
    port_write(b, 10u);
}

static void put_u32(uint32_t v)
{
    char b[10];
    uint32_t n = 0;
    do {
        b[9 - n] = (char)('0' + v % 10u);
        v /= 10u;
        n++;
    } while (v != 0u);
    port_write(b + 10 - n, n);
}
#endif

#if SELFTEST_MODE <= 1
static int g_failed;

static void check(int ok, const char *what)
{
    put(ok ? "ok   " : "FAIL ");
    put(what);
    put("\n");
    if (!ok) {
        g_failed = 1;
    }
}
#endif

/* Startup must copy .data from its load address and zero .bss; the 1 MB array also shows
 * that a large static arena fits the RAM layout. */
static volatile uint32_t g_data_word = 0x12345678u;
static volatile uint8_t g_big_bss[1024u * 1024u];

#if SELFTEST_MODE == 0
static int run_pass(void)
{
    uint32_t t0;
    uint32_t t1;
    volatile uint32_t spin;

    /* Not NUL-terminated on purpose: port_write must honour n exactly. */
    port_write("selftest mode 0 XXXX", 15u);
    put(
#if defined(__ARM_FP)
        " fpu=hard"
#else
        " fpu=none"
#endif
        "\n");
    check(g_data_word == 0x12345678u, ".data copied");
    check(g_big_bss[0] == 0u && g_big_bss[sizeof g_big_bss / 2u] == 0u &&
              g_big_bss[sizeof g_big_bss - 1u] == 0u,
          ".bss zeroed (1 MB array)");
    g_big_bss[sizeof g_big_bss - 1u] = 7u;
    check(g_big_bss[sizeof g_big_bss - 1u] == 7u, ".bss writable at its end");

#if defined(__ARM_FP)
    {
        /* A real vmul.f32: without CPACR set by startup this would be a NOCP UsageFault. */
        volatile float a = 1.5f;
        volatile float b = 2.25f;
        float c = a * b;
        union {
            float f;
            uint32_t u;
        } bits;
        bits.f = c;
        put("float 1.5f*2.25f bits=");
        put_hex(bits.u);
        put("\n");
        check(bits.u == 0x40580000u, "float multiply (3.375f)");
        check((*(volatile uint32_t *)0xE000ED88u & (0xFu << 20)) == (0xFu << 20),
              "CPACR grants CP10/CP11");
    }
#endif

    /* 1000 iterations of a short loop; under -icount shift=0 the tick count is exact
     * and the same on every run. */
    t0 = port_cycles();
    for (spin = 0; spin < 1000u; spin++) {
    }
    t1 = port_cycles();
    put("ticks for 1000-iteration loop=");
    put_u32(t1 - t0);
    put("\n");
    check(t1 - t0 > 0u, "SysTick counts");

    put("stack used=");
    put_u32(port_stack_used());
    put(" of ");
    put_u32(port_stack_size());
    put(" below ");
    put_hex((uint32_t)__StackTop);
    put("\n");
    check(port_stack_used() > 0u && port_stack_used() < port_stack_size(), "stack paint");
    return g_failed;
}
#endif

int main(void)
{
#if SELFTEST_MODE == 0
    if (run_pass() != 0) {
        return 1;
    }
    put("1 passed, 0 failed\n");
    port_exit(0);
#elif SELFTEST_MODE == 1
    put("selftest mode 1: a check that fails\n");
    check(g_data_word == 0u, "deliberately false");
    return g_failed;
#elif SELFTEST_MODE == 2
    put("selftest mode 2: undefined instruction\n");
    __asm__ volatile("udf #0");
    return 0;
#elif SELFTEST_MODE == 3
    {
        volatile uint32_t forever = 1u;
        put("selftest mode 3: hang\n");
        while (forever != 0u) {
        }
    }
    return 0;
#else
#error "SELFTEST_MODE must be 0..3"
#endif
}
