/* SPDX-License-Identifier: MIT */
/* Bit-level conversions into subd_real with one home (private), the inverse direction of
 * subd_real.h's subd_real_bits; used by the binary readers' conversions (real_bits.c), the
 * decimal parser (real_text.c) and the self-check (selfcheck.c). No paper: IEEE 754 binary32 bit patterns and the Q16.16 range of subd_real.h.
 *   - subd_real_from_mag (Q16.16): a sign and a magnitude in units of 2^-16, already rounded
 *     by the caller, to a subd_real, or SUBD_ERR_RANGE outside int32 (-2^31 is in range,
 *     +2^31 is not).
 *   - subd_f32_of_bits (float32): the float whose bit pattern is b (a union: no aliasing). */
#ifndef SUBD_REAL_BITS_H
#define SUBD_REAL_BITS_H
#include "subd.h"

#if SUBD_FIXED /* each arithmetic has its own conversion (see subd_real.h) */
static inline int subd_real_from_mag(uint32_t neg, uint64_t mag, subd_real *out)
{
    if (neg) {
        if (mag > 0x80000000u) return SUBD_ERR_RANGE;
        *out = (subd_real)(-(int64_t)mag);
    } else {
        if (mag > 0x7fffffffu) return SUBD_ERR_RANGE;
        *out = (subd_real)mag;
    }
    return SUBD_OK;
}
#else /* float32: the fixed-point build never touches float */
static inline float subd_f32_of_bits(uint32_t b)
{
    union { uint32_t u; float f; } c;
    c.u = b;
    return c.f;
}
#endif
#endif
