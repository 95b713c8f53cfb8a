/* tinysubd scalar layer: subd_real is IEEE float32 or signed Q16.16, chosen by SUBD_FIXED.
 *
 * One algorithm source is written against these operations; both builds give the same
 * results on a PC and on a Cortex-M (float: IEEE single with -ffp-contract=off, so no fused
 * multiply-add; fixed: integer arithmetic only).
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

/* Converts decimal text [*p, end) to the nearest subd_real using integer arithmetic only,
 * so a file gives identical bits on every target. Accepts [+-]digits[.digits][(e|E)[+-]digits]
 * and also ".5", "5.", and the words nan/inf/infinity (any case) so that they can be
 * reported as SUBD_ERR_NAN. On success *p points after the number.
 * Float32 results are correctly rounded (round to nearest even) for inputs of up to 19
 * significant digits; more digits are truncated to 19 before rounding.
 * Returns 0 (SUBD_OK), SUBD_ERR_PARSE (no number here), SUBD_ERR_NAN (nan/inf text), or
 * SUBD_ERR_RANGE (magnitude too large for the format: |x| >= 32768 in Q16.16, >= 2^128 after
 * rounding in float32). Values too small for the format round to (signed) zero. */
int subd_real_parse(const char **p, const char *end, subd_real *out);

/* Writes x as shortest-enough decimal text into buf (at least 24 bytes), without a
 * terminator; returns the number of characters. Float32: 9 significant digits, enough to
 * read back the same bits. Q16.16: exact decimal value of the fixed-point number (up to
 * 16 fraction digits, trailing zeros removed). */
uint32_t subd_real_format(subd_real x, char *buf);

/* Deterministic cos and sin of the angle 2*pi*num/den (den > 0), the form every weight of
 * the schemes takes. Integer arithmetic with 62-bit intermediate precision, then one
 * rounding to subd_real, so the result is the same on every target and within 1 ulp
 * (float32) or 1 LSB (Q16.16) of the true value. */
subd_real subd_cos_turns(int32_t num, int32_t den);
subd_real subd_sin_turns(int32_t num, int32_t den);

/* Q2.62 versions of the above (value * 2^62), for callers that build weights at higher
 * precision than subd_real before one final rounding. */
int64_t subd_cos_turns_q62(int32_t num, int32_t den);
int64_t subd_sin_turns_q62(int32_t num, int32_t den);

/* Rounds a Q2.62 value to the nearest subd_real. */
subd_real subd_real_from_q62(int64_t q);

#endif
