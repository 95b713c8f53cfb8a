/* SPDX-License-Identifier: MIT */
/* Private interface of src/sqrt.c: the float32 software square root, which subd_sqrt uses
 * where the machine has no square root instruction (and for the inputs it does not hand to
 * the instruction). Declared here so that the sqrt test can compare the two paths bit for
 * bit on every target (test/test_loop_limit.c). No paper: IEEE 754 binary32. */
#ifndef SUBD_SQRT_INTERNAL_H
#define SUBD_SQRT_INTERNAL_H
#include "subd.h"

#if !SUBD_FIXED /* Q16.16 has one path (subd_isqrt64) */
/* Correctly rounded sqrt(x) in integer arithmetic; the special values as subd_sqrt's
 * (include/subd_real.h): -0 -> -0, +inf -> +inf, negative or -inf -> 0x7fc00000, a NaN
 * quieted. */
float subd_sqrt_soft(float x);
#endif
#endif
