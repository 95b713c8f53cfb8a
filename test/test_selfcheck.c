/* SPDX-License-Identifier: MIT */
/* subd_selfcheck (src/selfcheck.c): SUBD_OK on every target as built by make test, and
 * SUBD_ERR_ARITH when the arithmetic is made to differ at run time: rounding modes other than
 * to-nearest (fenv on the host, FPSCR.RMode on the Cortex-M4F) and flush-to-zero (MXCSR.FTZ
 * on x86, FPSCR.FZ on the Cortex-M4F). The compile-time half (contraction) is covered by the
 * host-gnu suite and test/scripts/contract_proofs.sh. */
#include "harness.h"

#if H_HOST && !SUBD_FIXED
#include <fenv.h>
#if defined(__SSE2__)
#include <xmmintrin.h>
#endif
#endif

#if !H_HOST && !SUBD_FIXED && defined(__ARM_FP)
static uint32_t fpscr_get(void)
{
    uint32_t v;
    __asm__ volatile("vmrs %0, fpscr" : "=r"(v));
    return v;
}
static void fpscr_set(uint32_t v) { __asm__ volatile("vmsr fpscr, %0" : : "r"(v) : "memory"); }
#endif

static void selfcheck_ok(void)
{
    CHECK_EQ(subd_selfcheck(), SUBD_OK);
    CHECK(subd_status_str(SUBD_ERR_ARITH)[0] == 'a');
    CHECK(subd_status_str(SUBD_ERR_NOT_TRIANGLES)[0] == 'n');
}

#if !SUBD_FIXED
static void selfcheck_detects(void)
{
#if H_HOST
    static const int modes[3] = {FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO};
    int i, saved = fegetround();
    for (i = 0; i < 3; i++) {
        if (fesetround(modes[i]) != 0) continue;
        CHECK_EQ(subd_selfcheck(), SUBD_ERR_ARITH);
        fesetround(saved);
    }
    CHECK_EQ(subd_selfcheck(), SUBD_OK);
#if defined(__SSE2__)
    {
        unsigned int csr = _mm_getcsr();
        _mm_setcsr(csr | 0x8000u); /* FTZ */
        CHECK_EQ(subd_selfcheck(), SUBD_ERR_ARITH);
        _mm_setcsr(csr);
        CHECK_EQ(subd_selfcheck(), SUBD_OK);
    }
#endif
#elif defined(__ARM_FP)
    uint32_t saved = fpscr_get(), rm;
    for (rm = 1; rm < 4u; rm++) { /* RMode: towards +inf, -inf, zero */
        fpscr_set((saved & ~0x00c00000u) | (rm << 22));
        CHECK_EQ(subd_selfcheck(), SUBD_ERR_ARITH);
        fpscr_set(saved);
    }
    fpscr_set(saved | 0x01000000u); /* FZ */
    CHECK_EQ(subd_selfcheck(), SUBD_ERR_ARITH);
    fpscr_set(saved);
    CHECK_EQ(subd_selfcheck(), SUBD_OK);
#endif
}
#endif

const test_case suite_selfcheck[] = {
    {"selfcheck_ok", selfcheck_ok},
#if !SUBD_FIXED
    {"selfcheck_detects", selfcheck_detects},
#endif
    {0, 0}
};
