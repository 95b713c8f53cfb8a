/* SPDX-License-Identifier: MIT */
/* Deterministic cos and sin of 2*pi*num/den in integer arithmetic.
 *
 * The schemes' weights are cosines of rational fractions of a turn (Loop's
 * cos(2*pi/n), the alpha-kernel's cos(2^-(k+1) * alpha), ...), so the angle is taken as the
 * exact fraction num/den and never rounded before the range reduction:
 *   1. r = num mod den in [0, den) (int64, so no overflow for any int32 input);
 *   2. quadrant q = floor(4r / den), remainder r4 = 4r - q*den in [0, den): the angle is
 *      q quarter turns plus r4/den of a quarter turn;
 *   3. octant fold: if 2*r4 > den use a = den - r4 and swap sin/cos, so the polynomial only
 *      sees x = (pi/2) * a/den in [0, pi/4].
 * All three steps are exact integer operations, so cos(-t) == cos(t), sin(-t) == -sin(t),
 * cos(t + k) == cos(t), cos(1/2 - t) == -cos(t) and sin(1/4 - t) == cos(t) hold bit for bit
 * (mirrored angles reach the polynomial with the same a). At a = den/2 (45 degrees) both
 * values are the constant sqrt(1/2) so the fold's tie cannot break a symmetry; at a = 0 and
 * a = den/3 (0 and 30 degrees) sin is exactly 0 and 1/2, so cos(1/4 turn) == 0 and
 * cos(1/6 turn) == 1/2 exactly.
 *
 * Fixed point: unsigned Q63 (value * 2^63; 1.0 = 2^63 fits). a/den is formed as
 * t = floor(a * 2^64 / den) by two 64/32-bit long-division steps, x = t * (pi/2) with a
 * 64x64->128-bit product built from 32-bit halves (no __int128, which 32-bit ARM lacks):
 * both from wide.h.
 * sin and cos are the Taylor series evaluated by Horner's rule on x^2:
 *   sin x = x (1 - x^2/(2*3) (1 - x^2/(4*5) (1 - ... x^2/(20*21)))),
 *   cos x =    1 - x^2/(1*2) (1 - x^2/(3*4) (1 - ... x^2/(21*22))).
 * Truncation error: x^23/23! < 2^-81 and x^24/24! < 2^-86 for x <= pi/4. Every Horner
 * factor is < 1, so each step's rounding error (<= 1 unit of 2^-63 from the product and
 * the division) is damped, not amplified; with the errors of t (2^-64), of pi/2 (2^-64) and
 * of the final product, the Q63 result is within a few units of 2^-63 of the true value.
 * Measured against __float128 (all num/den with den <= 600, |num| <= 2 den, and 6 million
 * random num/den with den up to 2^31): Q2.62 error <= 2^-61.8, and every float32 result
 * correctly rounded. One rounding to subd_real follows (subd_real_from_q62).
 *
 * Constants (exact digits via Python's decimal module, 80-digit pi):
 *   PIO2_Q63   = round(pi/2 * 2^63)      = 0xc90fdaa22168c235
 *   SQRT12_Q63 = round(sqrt(1/2) * 2^63) = 0x5a827999fcef3242 (= isqrt(2^125))
 */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "subd.h"
#include "wide.h"

#define ONE_Q63 ((uint64_t)1 << 63)
#define PIO2_Q63 UINT64_C(0xc90fdaa22168c235)
#define SQRT12_Q63 UINT64_C(0x5a827999fcef3242)

/* round(a * b / 2^63) for a, b <= 2^63 (Q63 product, rounded half up). */
static uint64_t mul_q63(uint64_t a, uint64_t b)
{
    return subd_u128_shr_round(subd_u128_mul(a, b), 63u);
}

/* y = 1 - x2 * y / c, rounded: the Horner step of both series. */
static uint64_t horner_step(uint64_t x2, uint64_t y, uint32_t c)
{
    return ONE_Q63 - (mul_q63(x2, y) + c / 2u) / c;
}

static uint64_t sin_q63(uint64_t x)
{
    uint64_t x2 = mul_q63(x, x), y = ONE_Q63;
    uint32_t k;
    for (k = 10; k >= 1u; k--) y = horner_step(x2, y, (2u * k) * (2u * k + 1u));
    return mul_q63(x, y);
}

static uint64_t cos_q63(uint64_t x)
{
    uint64_t x2 = mul_q63(x, x), y = ONE_Q63;
    uint32_t k;
    for (k = 11; k >= 1u; k--) y = horner_step(x2, y, (2u * k - 1u) * (2u * k));
    return y;
}

/* Q63 magnitude (<= 2^63) to signed Q2.62, rounded half away from zero. */
static int64_t to_q62(uint64_t v, int neg)
{
    int64_t m = (int64_t)((v + 1u) >> 1);
    return neg ? -m : m;
}

static void sincos_q62(int32_t num, int32_t den, int64_t *c, int64_t *s)
{
    int64_t r, r4, q, a, d = den;
    uint64_t cp, sp, t;
    if (den <= 0) { *c = 0; *s = 0; return; }
    r = (int64_t)num % d;
    if (r < 0) r += d;
    r4 = 4 * r;
    q = r4 / d;
    r4 -= q * d;
    a = (2 * r4 > d) ? d - r4 : r4; /* 0 <= a <= den/2 */
    if (a == 0) {
        cp = ONE_Q63;
        sp = 0;
    } else if (2 * a == d) {
        cp = SQRT12_Q63;
        sp = SQRT12_Q63;
    } else {
        uint64_t rem, x;
        subd_u128 n;
        /* t = floor(a * 2^64 / den) < 2^63 (a < den < 2^31: two 32-bit digit steps) */
        n.hi = (uint64_t)a;
        n.lo = 0;
        t = subd_u128_div(n, (uint64_t)d, &rem);
        x = subd_u128_shr_round(subd_u128_mul(t, PIO2_Q63), 64u); /* (pi/2) * a/den in Q63, <= pi/4 */
        cp = cos_q63(x);
        sp = (3 * a == d) ? ONE_Q63 / 2u : sin_q63(x);
    }
    if (2 * r4 > d) { t = cp; cp = sp; sp = t; } /* octant fold: swap */
    switch (q) {
    case 0: *c = to_q62(cp, 0); *s = to_q62(sp, 0); break;
    case 1: *c = to_q62(sp, 1); *s = to_q62(cp, 0); break;
    case 2: *c = to_q62(cp, 1); *s = to_q62(sp, 1); break;
    default: *c = to_q62(sp, 0); *s = to_q62(cp, 1); break;
    }
}

int64_t subd_cos_turns_q62(int32_t num, int32_t den)
{
    int64_t c, s;
    sincos_q62(num, den, &c, &s);
    return c;
}

int64_t subd_sin_turns_q62(int32_t num, int32_t den)
{
    int64_t c, s;
    sincos_q62(num, den, &c, &s);
    return s;
}

/* Q16.16 rounds ties away from zero (subd_real.h), so a negated value rounds to the negated
 * result; float32 is correctly rounded (wide.h). |q| <= 2^63 gives at most 2^17: no
 * saturation. */
subd_real subd_real_from_q62(int64_t q)
{
    uint32_t ovf = 0;
    return subd_real_from_scaled_away(q, 62u, &ovf);
}

subd_real subd_cos_turns(int32_t num, int32_t den)
{
    return subd_real_from_q62(subd_cos_turns_q62(num, den));
}

subd_real subd_sin_turns(int32_t num, int32_t den)
{
    return subd_real_from_q62(subd_sin_turns_q62(num, den));
}
