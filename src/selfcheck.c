/* SPDX-License-Identifier: MIT */
/* subd_selfcheck: does this build, on this machine, compute the reference arithmetic?
 *
 * A few operations whose results differ when the arithmetic is not the one every other build
 * computes. The operands are read from volatile objects, so nothing is folded at compile time:
 * the checks run on this target's FPU (or integer unit) through subd_real.h's own inline
 * operations, combined as the schemes combine them.
 *   float32  a*a - c with a = 1 + 2^-12, c = 1 + 2^-11: a*a = 1 + 2^-11 + 2^-24 is a tie that
 *            rounds to even, c, so the result is 0; a fused multiply-subtract (contraction)
 *            or excess precision (x87) keeps 2^-24. Formed three ways, each from its own
 *            loads (a product used once, as contraction needs): subd_acc_add (the schemes'
 *            weighted sums), one C expression (what clang contracts by default), and
 *            subd_mul then subd_sub.
 *            1 + 2^-24 and 1 + 3 * 2^-25 (half and three quarters of an ulp) give 1 and
 *            1 + 2^-23 only when rounding to nearest, ties to even.
 *            2^-126 * 0.5 = 2^-127 (a subnormal) is 0 when flushed to zero (FPSCR.FZ on
 *            Cortex-M, FTZ/DAZ on x86).
 *   Q16.16   products round ties towards +infinity and >> on a negative int64 is arithmetic.
 */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "subd.h"
#include "real_bits.h"

#if SUBD_FIXED

static volatile int32_t g_fx[4] = {1, 32768, -1, 98304}; /* 2^-16, 1/2, -2^-16, 3/2 */

int subd_selfcheck(void)
{
    uint32_t ovf = 0;
    subd_real lsb = g_fx[0], half = g_fx[1], mlsb = g_fx[2], three_half = g_fx[3];
    int ok = subd_mul(lsb, half, &ovf) == 1 &&            /* +1/2 LSB rounds up        */
             subd_mul(mlsb, half, &ovf) == 0 &&           /* -1/2 LSB rounds up to 0   */
             subd_mul(mlsb, three_half, &ovf) == -1 &&    /* -3/2 LSB: arithmetic >>   */
             subd_acc_real(subd_acc_add(subd_acc_zero(), mlsb, three_half), &ovf) == -1;
    return ok && !ovf ? SUBD_OK : SUBD_ERR_ARITH;
}

#else

/* 1 + 2^-12, 1 + 2^-11, 1, 2^-24, 3 * 2^-25, 2^-126, 1/2 */
static volatile uint32_t g_bits[7] = {0x3f800800u, 0x3f801000u, 0x3f800000u, 0x33800000u,
                                      0x33c00000u, 0x00800000u, 0x3f000000u};
#define A 0u
#define C 1u

static subd_real from_bits(uint32_t i) { return subd_f32_of_bits(g_bits[i]); }

int subd_selfcheck(void)
{
    uint32_t ovf = 0;
    subd_real one = from_bits(2), tie = from_bits(3), most = from_bits(4), tiny = from_bits(5), half = from_bits(6);
    subd_real d1 = subd_acc_real(subd_acc_add(subd_neg(from_bits(C), &ovf), from_bits(A), from_bits(A)), &ovf);
    subd_real d2 = subd_chk(from_bits(A) * from_bits(A) - from_bits(C), &ovf);
    subd_real d3 = subd_sub(subd_mul(from_bits(A), from_bits(A), &ovf), from_bits(C), &ovf);
    subd_real r1 = subd_add(one, tie, &ovf), r2 = subd_add(one, most, &ovf);
    subd_real r3 = subd_sub(subd_neg(one, &ovf), tie, &ovf), r4 = subd_sub(subd_neg(one, &ovf), most, &ovf);
    subd_real s = subd_mul(tiny, half, &ovf);
    int ok = subd_real_bits(d1) == 0u && subd_real_bits(d2) == 0u && subd_real_bits(d3) == 0u &&
             subd_real_bits(r1) == 0x3f800000u &&
             subd_real_bits(r2) == 0x3f800001u && subd_real_bits(r3) == 0xbf800000u &&
             subd_real_bits(r4) == 0xbf800001u && subd_real_bits(s) == 0x00400000u;
    return ok && !ovf ? SUBD_OK : SUBD_ERR_ARITH;
}

#endif
