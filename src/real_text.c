/* SPDX-License-Identifier: MIT */
/* Decimal text -> subd_real, in integer arithmetic only.
 *
 * The OBJ/OFF readers go through this function (the writers through subd_real_format, in
 * src/real_format.c), so a file gives the same
 * bits on a PC and on a Cortex-M whatever the C library's strtof/printf would do, and the
 * fixed-point build never touches float at all.
 *
 * Parsing (subd_real_parse). The text is reduced to m * 10^e with m < 10^19 (at most 19
 * significant digits; further digits are dropped, i.e. truncated) and e a clamped int64.
 * The value is then converted *exactly*, with a small fixed-size big integer (bn, at most
 * BN_CAP 32-bit limbs, on the stack):
 *   e >= 0:  N = m * 10^e exactly (N < 10^58 < 2^193, because larger values are rejected
 *            first), and the float is N rounded to 24 bits.
 *   e < 0:   N = m * 2^s is divided by 10^-e in chunks of 10^9 (64/32-bit divisions), giving
 *            the exact quotient q = floor(m * 2^s / 10^-e) and a sticky bit "remainder != 0".
 *            s is chosen so that q has at least 26 bits, so the bit that decides rounding and
 *            everything above it are exact bits of q, and the sticky bit says exactly whether
 *            anything non-zero lies below. Rounding q + sticky is therefore the same as
 *            rounding the exact rational value: the result is correctly rounded (to nearest,
 *            ties to even), subnormals included, with no error analysis needed.
 * Q16.16 uses the same machinery: q = floor(|x| * 2^17) exactly, then (q + 1) >> 1 is |x|
 * rounded to the nearest 2^-16 with ties away from zero.
 *
 * Formatting (subd_real_format) is its own concept, in src/real_format.c.
 *
 * Stack: the largest frame holds one bn (44 bytes).
 */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "subd.h"
#include "real_bits.h"

#define BN_CAP 10u /* 320 bits: the bounds below never need more than 256 */

typedef struct bn {
    uint32_t n;         /* limbs in use; w[n-1] != 0 unless n == 0 */
    uint32_t w[BN_CAP]; /* little-endian 32-bit limbs */
} bn;

static void bn_set_u64(bn *a, uint64_t v)
{
    a->w[0] = (uint32_t)v;
    a->w[1] = (uint32_t)(v >> 32);
    a->n = a->w[1] ? 2u : (a->w[0] ? 1u : 0u);
}

/* a <<= k. The callers' bounds keep the result below 2^(32 * BN_CAP). */
static void bn_shl(bn *a, uint32_t k)
{
    uint32_t limbs = k / 32u, bits = k % 32u, i;
    if (a->n == 0u) return;
    if (a->n + limbs + 1u > BN_CAP) return; /* unreachable by the documented bounds */
    a->w[a->n + limbs] = 0u;
    for (i = a->n; i-- > 0u;) {
        uint32_t lo = a->w[i];
        if (bits) {
            a->w[i + limbs + 1u] |= lo >> (32u - bits);
            a->w[i + limbs] = lo << bits;
        } else {
            a->w[i + limbs] = lo;
        }
    }
    for (i = 0; i < limbs; i++) a->w[i] = 0u;
    a->n += limbs + 1u;
    while (a->n > 0u && a->w[a->n - 1u] == 0u) a->n--;
}

/* a /= d (d != 0); returns the remainder. */
static uint32_t bn_div_small(bn *a, uint32_t d)
{
    uint64_t rem = 0;
    uint32_t i;
    for (i = a->n; i-- > 0u;) {
        uint64_t cur = (rem << 32) | a->w[i];
        a->w[i] = (uint32_t)(cur / d);
        rem = cur % d;
    }
    while (a->n > 0u && a->w[a->n - 1u] == 0u) a->n--;
    return (uint32_t)rem;
}

static uint64_t bn_low_u64(const bn *a)
{
    uint64_t v = a->n > 0u ? a->w[0] : 0u;
    if (a->n > 1u) v |= (uint64_t)a->w[1] << 32;
    return v;
}

static const uint32_t k_pow10[10] = {
    1u, 10u, 100u, 1000u, 10000u, 100000u, 1000000u, 10000000u, 100000000u, 1000000000u
};

/* a = floor(a / 10^n); returns 1 when the division was not exact. */
static uint32_t bn_div_pow10(bn *a, uint32_t n)
{
    uint32_t sticky = 0;
    while (n >= 9u) { sticky |= bn_div_small(a, k_pow10[9]); n -= 9u; }
    if (n) sticky |= bn_div_small(a, k_pow10[n]);
    return sticky != 0u;
}

#if !SUBD_FIXED

static uint32_t bitlen64(uint64_t v)
{
    uint32_t b = 0;
    while (v) { b++; v >>= 1; }
    return b;
}

static void bn_mul_small(bn *a, uint32_t f)
{
    uint64_t carry = 0;
    uint32_t i;
    for (i = 0; i < a->n; i++) {
        uint64_t t = (uint64_t)a->w[i] * f + carry;
        a->w[i] = (uint32_t)t;
        carry = t >> 32;
    }
    if (carry && a->n < BN_CAP) a->w[a->n++] = (uint32_t)carry;
}

static void bn_mul_pow10(bn *a, uint32_t n)
{
    while (n >= 9u) { bn_mul_small(a, k_pow10[9]); n -= 9u; }
    if (n) bn_mul_small(a, k_pow10[n]);
}

static uint32_t bn_bitlen(const bn *a)
{
    uint32_t top;
    if (a->n == 0u) return 0;
    top = a->w[a->n - 1u];
    return 32u * (a->n - 1u) + bitlen64(top);
}

static uint32_t bn_bit(const bn *a, uint32_t pos)
{
    uint32_t limb = pos / 32u;
    if (limb >= a->n) return 0;
    return (a->w[limb] >> (pos % 32u)) & 1u;
}

/* 1 when any bit below position pos is set. */
static uint32_t bn_any_below(const bn *a, uint32_t pos)
{
    uint32_t limb = pos / 32u, i;
    for (i = 0; i < limb && i < a->n; i++)
        if (a->w[i]) return 1;
    if (limb < a->n && (pos % 32u) && (a->w[limb] & ((1u << (pos % 32u)) - 1u))) return 1;
    return 0;
}

/* N * 2^-s (plus "a little more" when sticky) rounded to float32 (nearest, ties to even),
 * as a bit pattern without sign. Precondition: when sticky is set the rounding position lies
 * at least one bit above bit 0 of N (guaranteed by the caller's choice of s), so the
 * rounding bit is exact. Returns SUBD_ERR_RANGE when the result is >= 2^128. */
static int bn_to_float_bits(const bn *a, int32_t s, uint32_t sticky, uint32_t *bits)
{
    int32_t blen = (int32_t)bn_bitlen(a);
    int32_t e2 = blen - 1 - s; /* a * 2^-s lies in [2^e2, 2^(e2+1)) */
    int32_t sh;
    uint32_t sig = 0, i;
    if (blen == 0) { *bits = 0; return SUBD_OK; }
    if (e2 >= 128) return SUBD_ERR_RANGE;
    sh = blen - 24;
    if (e2 < -126) sh = s - 149; /* subnormal: units of 2^-149 */
    if (sh <= 0) {
        /* exact: at most 24 bits, shifted up */
        sig = (uint32_t)bn_low_u64(a) << (uint32_t)(-sh);
    } else {
        uint32_t ush = (uint32_t)sh, rb, rest;
        for (i = 0; i < 24u; i++) sig |= bn_bit(a, ush + i) << i;
        rb = bn_bit(a, ush - 1u);
        rest = sticky | bn_any_below(a, ush - 1u);
        if (rb && (rest || (sig & 1u))) sig++;
    }
    if (e2 < -126) {
        *bits = sig; /* sig <= 2^23; 2^23 is the smallest normal, as it should be */
    } else {
        /* sig in [2^23, 2^24]; a carry to 2^24 moves into the exponent field */
        *bits = ((uint32_t)(e2 + 126) << 23) + sig;
    }
    if (*bits >= 0x7f800000u) return SUBD_ERR_RANGE;
    return SUBD_OK;
}

#endif /* !SUBD_FIXED */

/* ---------------------------------------------------------------------------- parsing */

#define MAX_SIG_DIGITS 19
#define EXP_CLAMP 1000000000000LL /* exponent digits saturate here (int64, no overflow) */

typedef struct dec {
    uint64_t m;  /* significant digits, < 10^19, first digit non-zero (or m == 0) */
    int32_t nd;  /* number of digits in m */
    int64_t e;   /* value = m * 10^e */
    int neg;
} dec;

static int is_digit(char c) { return c >= '0' && c <= '9'; }

static int lower(char c) { return (c >= 'A' && c <= 'Z') ? c - 'A' + 'a' : c; }

/* Case-insensitive match of the three letters w at [s, end). */
static int word3(const char *s, const char *end, const char *w)
{
    int i;
    if (end - s < 3) return 0;
    for (i = 0; i < 3; i++)
        if (lower(s[i]) != w[i]) return 0;
    return 1;
}

/* Reads the grammar of subd_real_parse. On success *after is the end of the number. */
static int scan_decimal(const char *s, const char *end, dec *d, const char **after)
{
    int any = 0;
    uint64_t m = 0;
    int32_t nd = 0;
    int64_t adj = 0; /* bounded by the text length, so it cannot overflow */

    d->neg = 0;
    if (s < end && (*s == '+' || *s == '-')) { d->neg = (*s == '-'); s++; }
    if (word3(s, end, "nan") || word3(s, end, "inf")) return SUBD_ERR_NAN;
    while (s < end && is_digit(*s)) {
        uint32_t c = (uint32_t)(*s - '0');
        any = 1;
        if (nd == 0 && c == 0u) {
            /* leading zero: no significance */
        } else if (nd < MAX_SIG_DIGITS) {
            m = m * 10u + c;
            nd++;
        } else {
            adj++; /* dropped integer digit: scale by 10 */
        }
        s++;
    }
    if (s < end && *s == '.') {
        s++;
        while (s < end && is_digit(*s)) {
            uint32_t c = (uint32_t)(*s - '0');
            any = 1;
            if (nd == 0 && c == 0u) {
                adj--;
            } else if (nd < MAX_SIG_DIGITS) {
                m = m * 10u + c;
                nd++;
                adj--;
            }
            s++;
        }
    }
    if (!any) return SUBD_ERR_PARSE;
    /* The exponent is only taken when complete ("1e" and "1e+" stop before the 'e'). */
    if (s < end && (*s == 'e' || *s == 'E')) {
        const char *t = s + 1;
        int eneg = 0;
        if (t < end && (*t == '+' || *t == '-')) { eneg = (*t == '-'); t++; }
        if (t < end && is_digit(*t)) {
            int64_t ev = 0;
            while (t < end && is_digit(*t)) {
                ev = ev * 10 + (*t - '0');
                if (ev > EXP_CLAMP) ev = EXP_CLAMP;
                t++;
            }
            adj += eneg ? -ev : ev;
            s = t;
        }
    }
    d->m = m;
    d->nd = nd;
    d->e = adj;
    *after = s;
    return SUBD_OK;
}

#if SUBD_FIXED

/* |x| rounded to Q16.16 magnitude (ties away from zero); RANGE when the signed result does
 * not fit int32. */
static int dec_to_fixed(const dec *d, subd_real *out)
{
    uint64_t mag;
    if (d->m == 0u) { *out = 0; return SUBD_OK; }
    /* |x| >= 10^(nd-1+e): 10^5 > 32768 overflows for sure */
    if (d->nd - 1 + d->e >= 5) return SUBD_ERR_RANGE;
    /* |x| < 10^(nd+e) <= 10^-6 < 2^-17: rounds to 0 */
    if (d->nd + d->e <= -6) { *out = 0; return SUBD_OK; }
    if (d->e >= 0) {
        /* m * 10^e < 10^5: exact integer */
        uint64_t v = d->m;
        int64_t i;
        for (i = 0; i < d->e; i++) v *= 10u;
        mag = v << 16;
    } else {
        /* -e <= 6 + 19 = 25; m * 2^17 < 2^81 (3 limbs); the quotient is < 10^5 * 2^17 */
        bn n;
        bn_set_u64(&n, d->m);
        bn_shl(&n, 17u);
        (void)bn_div_pow10(&n, (uint32_t)(-d->e));
        mag = (bn_low_u64(&n) + 1u) >> 1; /* floor(2x) -> x rounded half away from zero */
    }
    return subd_real_from_mag(d->neg ? 1u : 0u, mag, out);
}

#else

static int dec_to_float(const dec *d, subd_real *out)
{
    uint32_t sign = d->neg ? 0x80000000u : 0u, bits = 0;
    int rc = SUBD_OK;
    if (d->m == 0u) {
        bits = 0;
    } else if (d->nd - 1 + d->e >= 39) {
        /* |x| >= 10^39 > FLT_MAX */
        return SUBD_ERR_RANGE;
    } else if (d->nd + d->e <= -46) {
        /* |x| < 10^-46 < 2^-150 (half the smallest subnormal): rounds to zero */
        bits = 0;
    } else if (d->e >= 0) {
        /* e <= 38: N < 10^19 * 10^38 < 2^190 */
        bn n;
        bn_set_u64(&n, d->m);
        bn_mul_pow10(&n, (uint32_t)d->e);
        rc = bn_to_float_bits(&n, 0, 0, &bits);
    } else {
        /* k = -e <= 45 + 19 = 64. Choose s with m * 2^s >= 2^25 * 10^k, so that the
         * quotient has >= 26 bits: m >= 2^(bm-1) and ceil(k * log2(10)) <= (3322k+999)/1000
         * (3.322 > log2 10). N = m * 2^s < 2^(26 + 213) = 2^239: 8 limbs. */
        bn n;
        uint32_t k = (uint32_t)(-d->e), sticky;
        int32_t s = 26 - (int32_t)bitlen64(d->m) + (int32_t)((k * 3322u + 999u) / 1000u);
        if (s < 0) s = 0;
        bn_set_u64(&n, d->m);
        bn_shl(&n, (uint32_t)s);
        sticky = bn_div_pow10(&n, k);
        rc = bn_to_float_bits(&n, s, sticky, &bits);
    }
    if (rc != SUBD_OK) return rc;
    *out = subd_f32_of_bits(bits | sign);
    return SUBD_OK;
}

#endif

int subd_real_parse(const char **p, const char *end, subd_real *out)
{
    dec d;
    const char *after = 0;
    subd_real v = 0;
    int rc;
    if (!p || !*p || !end || !out) return SUBD_ERR_PARAM;
    if (*p >= end) return SUBD_ERR_PARSE;
    rc = scan_decimal(*p, end, &d, &after);
    if (rc != SUBD_OK) return rc;
#if SUBD_FIXED
    rc = dec_to_fixed(&d, &v);
#else
    rc = dec_to_float(&d, &v);
#endif
    if (rc != SUBD_OK) return rc;
    *out = v;
    *p = after;
    return SUBD_OK;
}
