/* SPDX-License-Identifier: MIT */
/* Kernel functions of semi-stationary alpha-subdivision (Zhang & Wang 2002, section 1,
 * definition 2 and the kernels listed after theorem 1), evaluated without libm.
 *
 * f(alpha; n) = s * g(x), x = 2^-(n+1) alpha, alpha = 2 pi num / den (exact turns).
 *   B-spline: g = 1. cos: g = cos x = subd_cos_turns_q62(num, den << (n+1)), the scalar
 *   layer's deterministic cosine of an exact fraction of a turn. poly: g = 1 - x^2/2.
 *   cosh: g = (e^x + e^-x)/2 with x = k ln 2 + r, |r| <= ln2/2, e^+-r from the Taylor series
 *   in Q62 (28 terms: r^28/28! < 2^-110), then scaled by 2^+-k.
 * The paper is silent on the level argument of its poly and cosh kernels; we use the cos
 * kernel's 2^-(n+1) alpha for all (see subd_alpha.h). x for poly and cosh is formed in
 * Q32.32 from the turns num/(den 2^(n+1)) (rounded to 2^-32) times 2 pi in Q60; the result
 * is within a few 2^-32 (relative, cosh) of the true value, far below one float32 ulp.
 * Everything is integer arithmetic: the same bits on every target, and no float code at all
 * in the Q16.16 build (the float conversion, wide.h's, builds the IEEE bit pattern by hand).
 */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "alpha_internal.h"
#include "wide.h"

#define TWOPI_Q60 INT64_C(0x6487ed5110b4611a) /* round(2 pi 2^60) */
#define LN2_Q62 INT64_C(0x2c5c85fdf473de6b)   /* round(ln 2 2^62) */

static uint64_t mag(int64_t a) { return a < 0 ? (uint64_t)0 - (uint64_t)a : (uint64_t)a; }

static int64_t signed_result(uint64_t m, int neg, uint32_t *ovf)
{
    if (m > (uint64_t)INT64_MAX) {
        *ovf |= 1u;
        return neg ? -INT64_MAX : INT64_MAX;
    }
    return neg ? -(int64_t)m : (int64_t)m;
}

int64_t subd_alpha_mulq(int64_t a, int64_t b, uint32_t shift, uint32_t *ovf)
{
    int neg = (a < 0) != (b < 0);
    /* add 2^(shift-1) for rounding, with carry into hi */
    subd_u128 p = subd_u128_add64(subd_u128_mul(mag(a), mag(b)), (uint64_t)1 << (shift - 1u));
    if ((p.hi >> shift) != 0) {
        *ovf |= 1u;
        return neg ? -INT64_MAX : INT64_MAX;
    }
    return signed_result(subd_u128_shr(p, shift), neg, ovf);
}

int64_t subd_alpha_divq(int64_t a, int64_t b, uint32_t shift, uint32_t *ovf)
{
    uint64_t d = mag(b), rem, q;
    int neg = (a < 0) != (b < 0);
    subd_u128 n;
    if (d == 0) {
        *ovf |= 1u;
        return 0;
    }
    /* numerator |a| * 2^shift as 128 bits */
    n.lo = shift ? mag(a) << shift : mag(a);
    n.hi = shift ? mag(a) >> (64u - shift) : 0;
    if (n.hi >= d) {
        *ovf |= 1u;
        return neg ? -INT64_MAX : INT64_MAX;
    }
    q = subd_u128_div(n, d, &rem);
    /* round half away from zero: rem >= d - rem */
    if (rem >= d - rem) {
        if (q == UINT64_MAX) {
            *ovf |= 1u;
            return neg ? -INT64_MAX : INT64_MAX;
        }
        q++;
    }
    return signed_result(q, neg, ovf);
}

/* The conversions live in wide.h: Q16.16 rounds the kernel's Q32.32 values half up (towards
 * +infinity), unlike subd_real_from_q62 (half away from zero); see wide.h and test_wide.c. */
subd_real subd_alpha_q32_to_real(int64_t q, uint32_t *ovf) { return subd_real_from_scaled_up(q, 32u, ovf); }

int64_t subd_alpha_real_to_q32(subd_real x, uint32_t *ovf) { return subd_real_to_q32(x, ovf); }

/* e^r for |r| <= 1/2 in Q62 (r in Q62): Taylor series, 28 terms. */
static int64_t exp_q62(int64_t r, uint32_t *ovf)
{
    int64_t sum = (int64_t)1 << 62, term = (int64_t)1 << 62;
    int32_t i;
    for (i = 1; i <= 28 && term != 0; i++) {
        term = subd_alpha_mulq(term, r, 62, ovf) / i;
        sum += term;
    }
    return sum;
}

static int64_t round_shift(int64_t v, uint32_t sh)
{
    if (sh == 0) return v;
    if (sh > 62u) return 0;
    return (v + ((int64_t)1 << (sh - 1u))) >> sh;
}

int subd_alpha_kernel_q32(uint32_t kernel, int32_t num, int32_t den, uint32_t level, int64_t s_q32,
                          int64_t *f_q32)
{
    uint32_t ovf = 0;
    int64_t g, x, turns, f;
    int32_t dn;
    if (den <= 0 || level > 29u || (den > (INT32_MAX >> (level + 1u))) || s_q32 <= -SUBD_Q32_ONE)
        return SUBD_ERR_PARAM;
    dn = den << (level + 1u);
    switch (kernel) {
    case SUBD_ALPHA_BSPLINE:
        g = SUBD_Q32_ONE;
        break;
    case SUBD_ALPHA_COS:
        g = round_shift(subd_cos_turns_q62(num, dn), 30);
        break;
    case SUBD_ALPHA_POLY:
    case SUBD_ALPHA_COSH:
        turns = subd_alpha_divq(num, dn, 32, &ovf);
        x = subd_alpha_mulq(turns, TWOPI_Q60, 60, &ovf);
        if (x < 0) x = -x;
        if (kernel == SUBD_ALPHA_POLY) {
            g = SUBD_Q32_ONE - subd_alpha_mulq(x, x, 33, &ovf);
        } else {
            int64_t ln2 = round_shift(LN2_Q62, 30), k, r, ep, em;
            /* cosh x >= 2^30 long before x = 2^8 (Q32: 2^40); this also keeps a saturated
             * x (ovf) away from the sum below */
            if (ovf || x > ((int64_t)1 << 40)) return SUBD_ERR_RANGE;
            k = (x + ln2 / 2) / ln2; /* round(x / ln 2) */
            if (k > 30) return SUBD_ERR_RANGE;
            r = x - subd_alpha_mulq(k, LN2_Q62, 30, &ovf); /* |r| <= ln2 / 2, Q32 */
            ep = exp_q62(r * ((int64_t)1 << 30), &ovf);
            em = exp_q62(-r * ((int64_t)1 << 30), &ovf);
            g = round_shift(ep, (uint32_t)(31 - k)) + round_shift(em, (uint32_t)(31 + k));
        }
        break;
    default:
        return SUBD_ERR_PARAM;
    }
    f = subd_alpha_mulq(s_q32, g, 32, &ovf);
    if (ovf || f > ((int64_t)1 << 62) || f < -((int64_t)1 << 62)) return SUBD_ERR_RANGE;
    *f_q32 = f;
    return SUBD_OK;
}

int subd_alpha_kernel_value(uint32_t kernel, int32_t num, int32_t den, uint32_t level, subd_real s,
                            subd_real *f)
{
    uint32_t ovf = 0;
    int64_t sq, fq;
    subd_real v;
    int st;
    if (!f) return SUBD_ERR_PARAM;
    sq = subd_alpha_real_to_q32(s, &ovf);
    if (ovf) return SUBD_ERR_PARAM;
    st = subd_alpha_kernel_q32(kernel, num, den, level, sq, &fq);
    if (st != SUBD_OK) return st;
    v = subd_alpha_q32_to_real(fq, &ovf);
    if (ovf) return SUBD_ERR_RANGE;
    *f = v;
    return SUBD_OK;
}

int subd_alpha_kcache_get(subd_alpha_kcache *c, const subd_alpha_opts *o, int64_t num, int32_t den, uint32_t level,
                          int64_t s_q32, int64_t *f, int *fresh)
{
    int st;
    *fresh = 0;
    if (num == c->num) {
        *f = c->f;
        return SUBD_OK;
    }
    st = subd_alpha_kernel_q32(o->kernel, (int32_t)num, den, level, s_q32, f);
    if (st == SUBD_OK && *f <= -SUBD_Q32_ONE) st = SUBD_ERR_PARAM; /* 1 + f_n <= 0 */
    if (st != SUBD_OK) return st;
    c->num = num;
    c->f = *f;
    *fresh = 1;
    return SUBD_OK;
}

void subd_alpha_opts_default(subd_alpha_opts *o)
{
    o->order = 2;
    o->levels = 1;
    o->kernel = SUBD_ALPHA_BSPLINE;
    o->alpha_num = 0;
    o->alpha_den = 1;
    o->stiffness = SUBD_REAL_ONE;
    o->tag_num = 0;
}

int subd_alpha_check_opts(const subd_alpha_opts *o, uint32_t max_order, int64_t *s_q32)
{
    uint32_t ovf = 0;
    int64_t s;
    if (!o || o->order < 2u || o->order > max_order || o->levels > SUBD_MAX_LEVELS ||
        o->kernel > SUBD_ALPHA_COSH || o->alpha_den <= 0 ||
        o->alpha_den > (INT32_MAX >> (o->levels + 2u)) || o->alpha_num > SUBD_ALPHA_MAX_NUM ||
        o->alpha_num < -SUBD_ALPHA_MAX_NUM)
        return SUBD_ERR_PARAM;
    s = subd_alpha_real_to_q32(o->stiffness, &ovf);
    if (ovf) return SUBD_ERR_PARAM;                             /* |s| >= 2^31 or not finite */
    if (s <= -SUBD_Q32_ONE / 2) return SUBD_ERR_DIVERGENT;       /* theorem 1: s > -1/2      */
    *s_q32 = s;
    return SUBD_OK;
}

int32_t subd_alpha_continuity(int64_t s_q32, int32_t smooth_class)
{
    if (s_q32 <= 0) return -1;
    if (s_q32 <= SUBD_Q32_ONE / 2) return 0;
    return smooth_class;
}
