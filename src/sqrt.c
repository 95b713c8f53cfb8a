/* SPDX-License-Identifier: MIT */
/* Deterministic square roots in integer arithmetic (no libm: sqrtf would pull libm into the
 * device image, and the link proofs forbid it).
 *
 * subd_isqrt64: the integer square root of a uint64 (isqrt_floor: one Karatsuba step on a
 * 32-bit Newton root, integer operations only), rounded to nearest. Exact integer
 * arithmetic, so it gives the same result on every target (the result saturates at 2^32 - 1
 * above (2^32 - 1/2)^2). Round to nearest: with r = floor(sqrt(x)) and rem = x - r^2,
 * sqrt(x) >= r + 1/2 exactly when x >= r^2 + r + 1/4, i.e. (integers) rem > r; an exact
 * half cannot occur.
 *
 * subd_sqrt, float32: correctly rounded (round to nearest, ties to even; a tie cannot occur
 * for a square root of a float) and therefore bit-identical to IEEE sqrt for every
 * non-negative input, +0, -0 (gives -0), subnormals and +inf. The argument is taken apart
 * as m * 2^e with an integer m < 2^24 (subnormals normalised), m is shifted left so that
 * M = m * 2^s has 47 or 48 bits and e - s is even; then floor(sqrt(M)) has exactly 24 bits
 * and the remainder decides the rounding as above (a carry into bit 24 is absorbed by the
 * exponent field when the pattern is assembled by addition). Negative inputs (not -0) and
 * -inf give the quiet NaN 0x7fc00000 (the ARM default NaN; x86's sqrtss gives 0xffc00000,
 * so NaN bits are the one place a host libm differs); a NaN input is returned quieted.
 *
 * subd_sqrt, float32, hardware (the coordinator's decision, issue 21): IEEE 754 sqrt is
 * correctly rounded too, so where the machine has it the instruction gives the same bits as
 * the software path (subd_sqrt_soft, which stays compiled and is tested against it bit for
 * bit: test/test_loop_limit.c's sqrt_test). A Cortex-M with a single-precision FPU
 * (__ARM_FP & 4, float builds) uses vsqrt.f32, an x86-64 host sqrtss, both through inline
 * asm, so no compiler flag (-ffast-math, -mrecip) can turn them into an approximation; every
 * other target keeps the software path. Only positive normal inputs (0x00800000 to
 * 0x7f7fffff) go to the instruction: everything else (+-0, subnormals, +inf, negatives, -inf,
 * NaNs) takes the software path, so the NaN bits above hold on every target (x86's sqrtss
 * would give 0xffc00000 for a negative input, ARM's vsqrt the default NaN with FPSCR.DN)
 * and the result does not depend on flush-to-zero or denormals-are-zero modes (FPSCR.FZ,
 * MXCSR.DAZ/FTZ: a normal input has a normal root). The rounding mode must be the default
 * (to nearest), as everywhere else in the library's float arithmetic.
 *
 * subd_sqrt, Q16.16: the nearest Q16.16 value to sqrt(x / 2^16), i.e. the rounded integer
 * square root of x * 2^16 (< 2^47, result < 2^24); negative inputs give 0.
 */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "subd.h"
#include "sqrt_internal.h"

/* floor(sqrt(n)) for n < 2^32 by Newton's integer iteration x <- (x + n / x) / 2 from
 * x0 = (n / 2^16 + 2^16) / 2 >= sqrt(n) (the mean of n / 2^16 and 2^16 is at least their
 * geometric mean): from at or above floor(sqrt(n)) the iterates fall to it and the first
 * that does not fall is it (Hacker's Delight 11-1). All 32-bit: x <= 2^16, n / x < 2^32. */
static uint32_t isqrt32_floor(uint32_t n)
{
    uint32_t x = (n >> 17) + 32768u, y;
    if (n == 0u) return 0u;
    for (;;) {
        y = (x + n / x) >> 1;
        if (y >= x) return x;
        x = y;
    }
}

/* floor(sqrt(x)) and the remainder x - floor(sqrt(x))^2. x is scaled by 4^k into
 * [2^62, 2^64) (so the root gains exactly k bits), then one step of Zimmermann's Karatsuba
 * square root (1999) with base 2^16: s1 = floor(sqrt(top 32 bits)) and r1 = its remainder
 * (< 2^17), q = floor((r1 2^16 + a1) / (2 s1)) = floor((r1 2^15 + a1 / 2) / s1) (32-bit),
 * s = s1 2^16 + q, r = (remainder of q) 2^16 + a0 - q^2, which is the root and remainder
 * after at most one correction (r < 0: s - 1); the loops below enforce 0 <= r <= 2 s, i.e.
 * s^2 <= y < (s + 1)^2, whatever the estimate. Then floor(sqrt(x)) = floor(s / 2^k). Was a
 * 32-step digit-by-digit loop of 64-bit operations: about 540 instructions on a Cortex-M3,
 * now about 80 (32-bit divisions, which the M3 and M4 have). Same results: the floor root
 * is unique. */
static uint32_t isqrt_floor(uint64_t x, uint64_t *rem_out)
{
    uint64_t y = x, s;
    int64_t r;
    uint32_t k = 0, n, s1, r1, a1, a0, num, q, u, res;
    if (x == 0u) {
        *rem_out = 0;
        return 0;
    }
    if (y < ((uint64_t)1 << 32)) { y <<= 32; k += 16u; }
    if (y < ((uint64_t)1 << 48)) { y <<= 16; k += 8u; }
    if (y < ((uint64_t)1 << 56)) { y <<= 8; k += 4u; }
    if (y < ((uint64_t)1 << 60)) { y <<= 4; k += 2u; }
    if (y < ((uint64_t)1 << 62)) { y <<= 2; k += 1u; }
    n = (uint32_t)(y >> 32);            /* [2^30, 2^32) */
    s1 = isqrt32_floor(n);              /* [2^15, 2^16) */
    r1 = n - s1 * s1;                   /* <= 2 s1 < 2^17 */
    a1 = (uint32_t)(y >> 16) & 0xffffu;
    a0 = (uint32_t)y & 0xffffu;
    num = (r1 << 15) + (a1 >> 1);       /* < 2^32 */
    q = num / s1;                       /* <= 2^16 */
    u = ((num - q * s1) << 1) | (a1 & 1u); /* (r1 2^16 + a1) - 2 q s1, < 2 s1 */
    s = ((uint64_t)s1 << 16) + q;
    r = (int64_t)(((uint64_t)u << 16) + a0) - (int64_t)((uint64_t)q * q);
    while (r < 0) {
        r += (int64_t)(2u * s - 1u);
        s--;
    }
    while ((uint64_t)r > 2u * s) {
        s++;
        r -= (int64_t)(2u * s - 1u);
    }
    res = (uint32_t)(s >> k);
    *rem_out = x - (uint64_t)res * res;
    return res;
}

uint32_t subd_isqrt64(uint64_t x)
{
    uint64_t rem;
    uint32_t r = isqrt_floor(x, &rem);
    /* sqrt(x) >= r + 1/2 exactly when rem > r; saturate at 2^32 - 1 for x >= (2^32 - 1/2)^2 */
    return (rem > r && r != UINT32_MAX) ? r + 1u : r;
}

#if SUBD_FIXED

subd_real subd_sqrt(subd_real x)
{
    if (x <= 0) return 0;
    return (subd_real)subd_isqrt64((uint64_t)x << 16);
}

#else

float subd_sqrt_soft(float x)
{
    union { float f; uint32_t u; } c;
    uint32_t bits, expf, r;
    uint64_t m, rem;
    int32_t e;
    c.f = x;
    bits = c.u;
    if ((bits & 0x7fffffffu) == 0u) return x;               /* +0 -> +0, -0 -> -0 */
    if ((bits & 0x7f800000u) == 0x7f800000u && (bits & 0x007fffffu) != 0u) {
        c.u = bits | 0x00400000u;                              /* NaN: quiet it */
        return c.f;
    }
    if (bits & 0x80000000u) {                                  /* negative, -inf */
        c.u = 0x7fc00000u;
        return c.f;
    }
    if (bits == 0x7f800000u) return x;                         /* +inf */
    expf = bits >> 23;
    m = bits & 0x007fffffu;
    if (expf == 0u) {
        e = -149;                                              /* subnormal: m * 2^-149 */
    } else {
        m |= 0x00800000u;
        e = (int32_t)expf - 150;                               /* normal: m * 2^(E-150) */
    }
    /* shift m to 47 or 48 bits with an even exponent: x = M * 2^e, e even */
    while (m < ((uint64_t)1 << 46)) {
        m <<= 1;
        e--;
    }
    if (e & 1) {
        m <<= 1;
        e--;
    }
    /* M in [2^46, 2^48): r = floor(sqrt(M)) in [2^23, 2^24) */
    r = isqrt_floor(m, &rem);
    if (rem > r) r++;                                          /* nearest (no ties) */
    /* result = r * 2^(e/2), r a 24-bit significand (or 2^24 after rounding up) */
    c.u = ((uint32_t)(e / 2 + 149) << 23) + r; /* biased exponent e/2 + 150, hidden bit in r */
    return c.f;
}

#if defined(__GNUC__) && defined(__ARM_FP) && (__ARM_FP & 4)
#define SQRT_HW 1
/* VSQRT.F32 (ARMv7-M FPv4-SP and later): IEEE sqrt, correctly rounded. */
static float sqrt_hw(float x)
{
    float r;
    __asm__("vsqrt.f32 %0, %1" : "=t"(r) : "t"(x));
    return r;
}
#elif defined(__GNUC__) && defined(__x86_64__)
#define SQRT_HW 1
/* SQRTSS (SSE, always present on x86-64): IEEE sqrt, correctly rounded. */
static float sqrt_hw(float x)
{
    float r;
    __asm__("sqrtss %1, %0" : "=x"(r) : "x"(x));
    return r;
}
#else
#define SQRT_HW 0
#endif

subd_real subd_sqrt(subd_real x)
{
#if SQRT_HW
    union { float f; uint32_t u; } c;
    c.f = x;
    if (c.u - 0x00800000u < 0x7f000000u) return sqrt_hw(x); /* positive normal */
#endif
    return subd_sqrt_soft(x);
}

#endif
