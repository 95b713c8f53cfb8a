/* SPDX-License-Identifier: MIT */
/* tinysubd scalar layer: subd_real is IEEE float32 or signed Q16.16, chosen by SUBD_FIXED.
 *
 * One algorithm source is written against these operations; both builds give the same
 * results on a PC and on a Cortex-M (float: IEEE single, every product rounded: no fused
 * multiply-add, whatever the compiler flags, by src/fp_contract.h's pragmas; fixed: integer
 * arithmetic only). subd_selfcheck() (subd.h) tests this at run time.
 *
 * Scaling and overflow contract (Q16.16):
 *   - a subd_real r stands for r / 65536; range [-32768, 32768 - 2^-16].
 *   - products are formed in 64 bits and rounded to nearest, ties towards +infinity
 *     ((p + 2^15) >> 16, arithmetic shift).
 *   - a weighted sum is accumulated exactly in a 64-bit subd_acc (Q32.32) and rounded once
 *     when it is turned back into a subd_real.
 *   - any result outside the range sets a sticky overflow flag (*ovf |= 1) and saturates;
 *     the operation that owns the flag turns it into SUBD_ERR_RANGE. The saturated value is
 *     never mistaken for a result because the flag, not the value, signals the overflow.
 * Float32: the same calls set *ovf when a result is not finite (Inf or NaN).
 */
#ifndef SUBD_REAL_H
#define SUBD_REAL_H

#include <stdint.h>
#include "subd_config.h"

#ifdef __cplusplus
extern "C" {
#endif

#if SUBD_FIXED

typedef int32_t subd_real;
typedef int64_t subd_acc; /* Q32.32 accumulator of weight * value products */

#define SUBD_REAL_ONE ((subd_real)65536)
#define SUBD_REAL_FRAC_BITS 16
#define SUBD_REAL_MAX ((subd_real)INT32_MAX)
#define SUBD_REAL_MIN ((subd_real)INT32_MIN)
/* An exact rational constant num/den (den > 0), rounded to nearest; a compile-time
 * integer expression, so no float code is ever emitted. */
#define SUBD_REAL_FRAC(num, den) \
    ((subd_real)((((int64_t)(num) * 131072) + ((num) >= 0 ? (den) : -(den))) / (2 * (int64_t)(den))))

static inline subd_real subd_real_sat(int64_t x, uint32_t *ovf)
{
    if (x > INT32_MAX) { *ovf |= 1u; return INT32_MAX; }
    if (x < INT32_MIN) { *ovf |= 1u; return INT32_MIN; }
    return (subd_real)x;
}
static inline subd_real subd_add(subd_real a, subd_real b, uint32_t *ovf)
{
    return subd_real_sat((int64_t)a + b, ovf);
}
static inline subd_real subd_sub(subd_real a, subd_real b, uint32_t *ovf)
{
    return subd_real_sat((int64_t)a - b, ovf);
}
/* Rounds a Q32.32 (or any value with 16 extra fraction bits) to Q16.16. gcc and clang
 * implement >> on negative values as an arithmetic shift (documented implementation-defined
 * behaviour); the test suite checks it on every target. */
static inline subd_real subd_round16(int64_t q, uint32_t *ovf)
{
    if (q > INT64_MAX - 32768) { *ovf |= 1u; return INT32_MAX; }
    return subd_real_sat((q + 32768) >> 16, ovf);
}
static inline subd_real subd_mul(subd_real a, subd_real b, uint32_t *ovf)
{
    return subd_round16((int64_t)a * b, ovf);
}
/* a / b rounded to nearest (ties away from zero). b == 0 sets the overflow flag. */
static inline subd_real subd_div(subd_real a, subd_real b, uint32_t *ovf)
{
    int64_t n, d, q;
    if (b == 0) { *ovf |= 1u; return a >= 0 ? INT32_MAX : INT32_MIN; }
    n = (int64_t)a * 65536;
    d = b;
    if ((n < 0) != (d < 0)) q = (n - d / 2) / d; else q = (n + d / 2) / d;
    return subd_real_sat(q, ovf);
}
static inline subd_real subd_from_int(int32_t i, uint32_t *ovf)
{
    return subd_real_sat((int64_t)i * 65536, ovf);
}
static inline subd_acc subd_acc_zero(void) { return 0; }
static inline subd_acc subd_acc_add(subd_acc acc, subd_real w, subd_real v)
{
    return acc + (int64_t)w * v;
}
static inline subd_real subd_acc_real(subd_acc acc, uint32_t *ovf) { return subd_round16(acc, ovf); }
static inline int subd_real_is_finite(subd_real x) { (void)x; return 1; }
/* Raw bit pattern, for hashing output identically on every target. */
static inline uint32_t subd_real_bits(subd_real x) { return (uint32_t)x; }

#else /* float32 */

typedef float subd_real;
typedef float subd_acc;

#define SUBD_REAL_ONE 1.0f
#define SUBD_REAL_MAX 3.40282347e+38f
#define SUBD_REAL_MIN (-3.40282347e+38f)
/* Exact when den is a power of two; otherwise the correctly rounded float of the
 * compile-time quotient. */
#define SUBD_REAL_FRAC(num, den) ((float)(num) / (float)(den))

static inline uint32_t subd_real_bits(subd_real x)
{
    union { float f; uint32_t u; } c;
    c.f = x;
    return c.u;
}
static inline int subd_real_is_finite(subd_real x)
{
    return (subd_real_bits(x) & 0x7f800000u) != 0x7f800000u;
}
static inline subd_real subd_chk(subd_real x, uint32_t *ovf)
{
    if (!subd_real_is_finite(x)) *ovf |= 1u;
    return x;
}
static inline subd_real subd_add(subd_real a, subd_real b, uint32_t *ovf) { return subd_chk(a + b, ovf); }
static inline subd_real subd_sub(subd_real a, subd_real b, uint32_t *ovf) { return subd_chk(a - b, ovf); }
static inline subd_real subd_mul(subd_real a, subd_real b, uint32_t *ovf) { return subd_chk(a * b, ovf); }
static inline subd_real subd_div(subd_real a, subd_real b, uint32_t *ovf)
{
    if (b == 0.0f) { *ovf |= 1u; return 0.0f; }
    return subd_chk(a / b, ovf);
}
static inline subd_real subd_from_int(int32_t i, uint32_t *ovf) { (void)ovf; return (float)i; }
static inline subd_acc subd_acc_zero(void) { return 0.0f; }
static inline subd_acc subd_acc_add(subd_acc acc, subd_real w, subd_real v)
{
    subd_real p = w * v; /* separate statement: product rounded before the add, as on device */
    return acc + p;
}
static inline subd_real subd_acc_real(subd_acc acc, uint32_t *ovf) { return subd_chk(acc, ovf); }

#endif

static inline subd_real subd_neg(subd_real a, uint32_t *ovf) { return subd_sub((subd_real)0, a, ovf); }

/* subd_real_parse: converts decimal text [*p, end) to the nearest subd_real using integer
 * arithmetic only (src/real_text.c), so a file gives identical bits on every target. Grammar, with no
 * leading white space: [+-] digits [. digits] [(e|E) [+-] digits], where one of the two digit
 * runs may be empty (".5", "5."). The exponent is taken only when complete: "1e", "1e+" and
 * "1ex" read as 1 and stop before the 'e'; "0x10" reads as 0 and stops at the 'x'. Text that
 * starts, after an optional sign, with "nan" or "inf" (any case; so also "infinity",
 * "nan(...)") returns SUBD_ERR_NAN. Never reads outside [*p, end).
 * Rounding: the significant digits are truncated to the first 19 (leading zeros do not
 * count); that value is then rounded exactly. Float32: correctly rounded to nearest, ties to
 * even, subnormals included (identical to a correct strtof for <= 19 digits); below half the
 * smallest subnormal gives a zero of the text's sign. Q16.16: nearest multiple of 2^-16,
 * ties away from zero; "-0" gives 0. Decimal exponents of any size are accepted (clamped
 * internally, no overflow).
 * Memory: no arena; stack about 120 bytes.
 * Errors: SUBD_ERR_PARAM (a NULL pointer), SUBD_ERR_PARSE (no number at *p, including
 *   *p >= end), SUBD_ERR_NAN (nan/inf text), SUBD_ERR_RANGE (the rounded value does not
 *   fit: outside [-32768, 32768 - 2^-16] in Q16.16, magnitude >= 2^128 after rounding in
 *   float32). On SUBD_OK *out is set and *p is just after the number; on any error *p and
 *   *out are unchanged.
 * Cost: O(length of the text). */
int subd_real_parse(const char **p, const char *end, subd_real *out);

/* subd_real_format: writes x as decimal text into buf (at least 24 bytes), without a
 * terminator; returns the number of characters.
 * Memory: no arena; stack about 120 bytes (float).
 * Errors: none (every value has a text; buf must hold 24 bytes).
 * Cost: O(1): integer arithmetic only (float32: a shortest-digit search with 64-bit
 *   tables; Q16.16: two digits per step).
 * Notes: float32: the shortest decimal that subd_real_parse (or any correct
 * strtof) reads back to the same bits, at most 9 significant digits and 15 characters,
 * the nearest one when several are shortest (an exact tie: the larger magnitude); positional
 * when the decimal exponent of those
 * digits is -4..8, otherwise d.ddde+XX like printf's %g: "0.1", "-1.25", "100", "1e+30", "1.0000001e+30", "1e-45",
 * "-0". Non-finite values give "inf", "-inf", "nan" (which the parser rejects). Q16.16:
 * the exact value of x / 65536, up to 16 fraction digits, trailing zeros and point removed:
 * "3", "-0.5", "0.0000152587890625", at most 23 characters. */
uint32_t subd_real_format(subd_real x, char *buf);

/* subd_cos_turns, subd_sin_turns: deterministic cos and sin of the angle 2*pi*num/den
 * (src/trig.c), the form every weight of the schemes takes.
 * Memory: no arena; stack about 130 bytes (Cortex-M4).
 * Errors: none (den <= 0 is invalid and gives 0).
 * Cost: O(1) (exact range reduction, then a Taylor series of 11-12 terms in 64-bit integers).
 * Notes: the range reduction (num mod den, quadrant, octant) is exact integer
 * arithmetic; the Taylor series runs in Q63 fixed point (error < 2^-61 before the final
 * rounding), then one rounding to subd_real, so the result is the same on every target and
 * within 1 ulp (float32: correctly rounded in every case tested) or 1 LSB (Q16.16) of the
 * true value. Exact: cos and sin are +-1, +-1/2 or +0 at multiples of 1/12 turn where the
 * true value is; cos(-t) == cos(t), sin(-t) == -sin(t), and the values depend only on the
 * rational num/den (2/6 gives the same bits as 1/3). Any int32 num. */
subd_real subd_cos_turns(int32_t num, int32_t den);
subd_real subd_sin_turns(int32_t num, int32_t den);

/* subd_cos_turns_q62, subd_sin_turns_q62: Q2.62 versions of the above (value * 2^62, in
 * [-2^62, 2^62]), for callers that build weights at higher precision than subd_real before
 * one final rounding. Within 2^-61 of the true value (measured; the Q62 rounding alone is
 * 2^-63).
 * Memory: no arena; stack as subd_cos_turns.
 * Errors: none (den <= 0 gives 0).
 * Cost: O(1). */
int64_t subd_cos_turns_q62(int32_t num, int32_t den);
int64_t subd_sin_turns_q62(int32_t num, int32_t den);

/* subd_real_from_q62: rounds a Q2.62 value (any int64, i.e. [-2, 2)) to the nearest
 * subd_real: float32 correctly rounded, ties to even; Q16.16 ties away from zero.
 * Memory: none. Errors: none (every int64 is a valid input). Cost: O(1). */
subd_real subd_real_from_q62(int64_t q);

/* subd_sqrt: deterministic square root (src/sqrt.c; no libm).
 * Memory: none (a few words of stack).
 * Errors: none: a negative input gives NaN (float32) or 0 (Q16.16), see below.
 * Cost: O(1): float32 on a Cortex-M with an FPU or an x86-64 host one square root
 * instruction (positive normal inputs), else integer arithmetic, about 32 loop steps.
 * Notes: float32: correctly rounded, so
 * bit-identical to IEEE sqrt for every input >= 0 (-0 gives -0, +inf gives +inf,
 * subnormals included); a negative input or -inf gives the quiet NaN 0x7fc00000 and a NaN
 * is returned quieted. Q16.16: the nearest Q16.16 value to the square root (ties cannot
 * occur); a negative input gives 0. */
subd_real subd_sqrt(subd_real x);

/* subd_isqrt64: integer square root of x rounded to nearest (saturating at 2^32 - 1),
 * digit by digit.
 * Memory: none. Errors: none (every uint64 is a valid input). Cost: O(1), 32 loop steps. */
uint32_t subd_isqrt64(uint64_t x);

/* subd_real_from_f32_bits, subd_real_from_f64_bits: the subd_real of an IEEE binary32 /
 * binary64 value given by its bit pattern (as stored in binary STL and PLY files), rounded as
 * subd_real_parse rounds the same value written as text: float32 correctly rounded to
 * nearest, ties to even, subnormals kept (binary32 input: the value itself); Q16.16 the
 * nearest multiple of 2^-16, ties away from zero (src/real_bits.c).
 * Memory: no arena; a few words of stack.
 * Errors: SUBD_ERR_PARAM (out NULL), SUBD_ERR_NAN (NaN or infinity), SUBD_ERR_RANGE (the
 *   rounded value does not fit subd_real: magnitude >= 2^128 in float32, outside
 *   [-32768, 32768 - 2^-16] in Q16.16). On an error *out is unchanged.
 * Cost: O(1), integer arithmetic only (no float or double operation in either build). */
int subd_real_from_f32_bits(uint32_t bits, subd_real *out);
int subd_real_from_f64_bits(uint64_t bits, subd_real *out);

/* subd_real_to_f32_bits: x as IEEE binary32 bits: float32 its own bits; Q16.16 the nearest
 * float32 to x / 65536 (ties to even; exact when |x| < 2^24, i.e. |value| < 256, or x has at
 * most 24 significant bits), as (float)(x / 65536.0) gives on a host.
 * Memory: none. Errors: none (every subd_real has a float32). Cost: O(1), integers only. */
uint32_t subd_real_to_f32_bits(subd_real x);

#ifdef __cplusplus
}
#endif

#endif
