/* SPDX-License-Identifier: MIT */
/* The reference for subd_real_format: the exact bignum formatter src/real_text.c used before
 * src/real_format.c replaced it, kept unchanged (only renamed) so the fast formatter is
 * compared byte for byte with an independent method: Steele & White / Burger & Dybvig free-
 * format shortest digits on exact big integers ("Printing floating-point numbers quickly and
 * accurately", 1996). r/s is the value, m+/s and m-/s the half-gaps to the neighbouring floats;
 * digits are produced until the printed prefix lies inside the rounding interval (boundaries
 * included when the significand is even); the last digit is the closer of d and d + 1 (a tie
 * goes to d + 1). Slow (about 0.75 M numbers/s) and obviously exact: only big-integer multiply
 * by 10, add, subtract and compare. Q16.16: the exact value, one fraction digit per step.
 * Included (static functions) by test/test_format.c and test/tools/format_exhaustive.c; both
 * ref_format_float exists in the float build, ref_format_fixed (int32 only) in both. */
#ifndef REF_FORMAT_H
#define REF_FORMAT_H
#include <stdint.h>
#include "subd_config.h"

#if !SUBD_FIXED

#define REF_BN_CAP 10u

typedef struct ref_bn {
    uint32_t n;             /* limbs in use; w[n-1] != 0 unless n == 0 */
    uint32_t w[REF_BN_CAP]; /* little-endian 32-bit limbs */
} ref_bn;

static const uint32_t ref_pow10[10] = {
    1u, 10u, 100u, 1000u, 10000u, 100000u, 1000000u, 10000000u, 100000000u, 1000000000u
};

static void ref_bn_set_u64(ref_bn *a, uint64_t v)
{
    a->w[0] = (uint32_t)v;
    a->w[1] = (uint32_t)(v >> 32);
    a->n = a->w[1] ? 2u : (a->w[0] ? 1u : 0u);
}

static void ref_bn_shl(ref_bn *a, uint32_t k)
{
    uint32_t limbs = k / 32u, bits = k % 32u, i;
    if (a->n == 0u) return;
    if (a->n + limbs + 1u > REF_BN_CAP) return; /* unreachable by the documented bounds */
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

static uint32_t ref_bitlen64(uint64_t v)
{
    uint32_t b = 0;
    while (v) { b++; v >>= 1; }
    return b;
}

static void ref_bn_mul_small(ref_bn *a, uint32_t f)
{
    uint64_t carry = 0;
    uint32_t i;
    for (i = 0; i < a->n; i++) {
        uint64_t t = (uint64_t)a->w[i] * f + carry;
        a->w[i] = (uint32_t)t;
        carry = t >> 32;
    }
    if (carry && a->n < REF_BN_CAP) a->w[a->n++] = (uint32_t)carry;
}

static void ref_bn_mul_pow10(ref_bn *a, uint32_t n)
{
    while (n >= 9u) { ref_bn_mul_small(a, ref_pow10[9]); n -= 9u; }
    if (n) ref_bn_mul_small(a, ref_pow10[n]);
}

static void ref_bn_add(ref_bn *dst, const ref_bn *a, const ref_bn *b)
{
    uint64_t carry = 0;
    uint32_t i, n = a->n > b->n ? a->n : b->n;
    for (i = 0; i < n; i++) {
        uint64_t t = carry;
        if (i < a->n) t += a->w[i];
        if (i < b->n) t += b->w[i];
        dst->w[i] = (uint32_t)t;
        carry = t >> 32;
    }
    if (carry && n < REF_BN_CAP) dst->w[n++] = (uint32_t)carry;
    dst->n = n;
}

static void ref_bn_sub(ref_bn *a, const ref_bn *b)
{
    uint32_t i, borrow = 0;
    for (i = 0; i < a->n; i++) {
        uint32_t bi = i < b->n ? b->w[i] : 0u;
        uint64_t t = (uint64_t)a->w[i] - bi - borrow;
        a->w[i] = (uint32_t)t;
        borrow = (uint32_t)(t >> 63);
    }
    while (a->n > 0u && a->w[a->n - 1u] == 0u) a->n--;
}

static int ref_bn_cmp(const ref_bn *a, const ref_bn *b)
{
    uint32_t i;
    if (a->n != b->n) return a->n > b->n ? 1 : -1;
    for (i = a->n; i-- > 0u;)
        if (a->w[i] != b->w[i]) return a->w[i] > b->w[i] ? 1 : -1;
    return 0;
}

static void ref_bn_pow2(ref_bn *a, uint32_t k)
{
    ref_bn_set_u64(a, 1u);
    ref_bn_shl(a, k);
}

static uint32_t ref_put_str(char *buf, uint32_t n, const char *s)
{
    while (*s) buf[n++] = *s++;
    return n;
}

static uint32_t ref_shortest_digits(uint32_t bits, uint8_t *dig, int32_t *kout)
{
    ref_bn r, s, mp, mm, t;
    uint32_t ex = bits >> 23, f = bits & 0x7fffffu, nd = 0, i;
    int32_t e, k, l2;
    int even;
    if (ex == 0u) e = -149; else { f |= 0x800000u; e = (int32_t)ex - 150; }
    even = (f & 1u) == 0u;
    /* r/s = value; mp/s, mm/s = half the gap to the next float above / below. The gap below
     * is half as wide at the bottom of a binade (f == 2^23, ex > 1). */
    if (e >= 0) {
        if (f != 0x800000u) {
            ref_bn_set_u64(&r, f); ref_bn_shl(&r, (uint32_t)e + 1u);
            ref_bn_set_u64(&s, 2u);
            ref_bn_pow2(&mp, (uint32_t)e); mm = mp;
        } else {
            ref_bn_set_u64(&r, f); ref_bn_shl(&r, (uint32_t)e + 2u);
            ref_bn_set_u64(&s, 4u);
            ref_bn_pow2(&mp, (uint32_t)e + 1u); ref_bn_pow2(&mm, (uint32_t)e);
        }
    } else {
        if (ex <= 1u || f != 0x800000u) {
            ref_bn_set_u64(&r, (uint64_t)f << 1);
            ref_bn_pow2(&s, (uint32_t)(1 - e));
            ref_bn_set_u64(&mp, 1u); mm = mp;
        } else {
            ref_bn_set_u64(&r, (uint64_t)f << 2);
            ref_bn_pow2(&s, (uint32_t)(2 - e));
            ref_bn_set_u64(&mp, 2u); ref_bn_set_u64(&mm, 1u);
        }
    }
    /* Estimate k = floor(floor(log2 v) * log10(2)) from below (78913 / 2^18 is within
     * 1e-4 of log10 2 over this range), then raise it until (r + mp) / s < 1. The estimate
     * is at most 3 short. Sizes: s <= 2^151 (e < 0) or 4 * 10^43 (e >= 0); r < 10^4 s. */
    l2 = e + (int32_t)ref_bitlen64(f) - 1;
    k = ((l2 * 78913 + (64 << 18)) >> 18) - 64;
    if (k >= 0) {
        ref_bn_mul_pow10(&s, (uint32_t)k);
    } else {
        ref_bn_mul_pow10(&r, (uint32_t)-k);
        ref_bn_mul_pow10(&mp, (uint32_t)-k);
        ref_bn_mul_pow10(&mm, (uint32_t)-k);
    }
    for (i = 0; i < 4u; i++) {
        int c;
        ref_bn_add(&t, &r, &mp);
        c = ref_bn_cmp(&t, &s);
        if (even ? c < 0 : c <= 0) break;
        ref_bn_mul_small(&s, 10u);
        k++;
    }
    /* Digit generation. The loop ends after at most 9 digits for float32 (9 significant
     * digits always identify a float); 17 is a safe bound. */
    for (nd = 0; nd < 17u;) {
        uint32_t dg = 0;
        int tc1, tc2, c;
        ref_bn_mul_small(&r, 10u);
        ref_bn_mul_small(&mp, 10u);
        ref_bn_mul_small(&mm, 10u);
        while (ref_bn_cmp(&r, &s) >= 0 && dg < 10u) { ref_bn_sub(&r, &s); dg++; }
        c = ref_bn_cmp(&r, &mm);
        tc1 = even ? c <= 0 : c < 0;
        ref_bn_add(&t, &r, &mp);
        c = ref_bn_cmp(&t, &s);
        tc2 = even ? c >= 0 : c > 0;
        if (!tc1 && !tc2) { dig[nd++] = (uint8_t)dg; continue; }
        if (tc1 && tc2) {
            ref_bn_add(&t, &r, &r);
            if (ref_bn_cmp(&t, &s) >= 0) dg++; /* closer to d + 1 (tie: d + 1) */
        } else if (tc2) {
            dg++;
        }
        dig[nd++] = (uint8_t)dg;
        break;
    }
    *kout = k;
    return nd;
}

#endif /* !SUBD_FIXED */

static uint32_t ref_format_fixed(int32_t x, char *buf)
{
    uint32_t n = 0, u, ip, frac;
    char tmp[8];
    uint32_t t = 0;
    if (x < 0) { buf[n++] = '-'; u = 0u - (uint32_t)x; } else u = (uint32_t)x;
    ip = u >> 16;
    frac = u & 0xffffu;
    do { tmp[t++] = (char)('0' + ip % 10u); ip /= 10u; } while (ip);
    while (t) buf[n++] = tmp[--t];
    if (frac) {
        buf[n++] = '.';
        /* frac / 65536 = digits of frac * 10^k / 65536; terminates within 16 digits */
        while (frac) {
            frac *= 10u;
            buf[n++] = (char)('0' + (frac >> 16));
            frac &= 0xffffu;
        }
    }
    return n;
}

#if !SUBD_FIXED

static uint32_t ref_format_float(float x, char *buf)
{
    union { float f; uint32_t u; } c;
    uint32_t bits, n = 0, nd, i;
    uint8_t dig[17];
    int32_t k, xp;
    c.f = x;
    bits = c.u;
    if (bits >> 31) { buf[n++] = '-'; bits &= 0x7fffffffu; }
    if (bits > 0x7f800000u) return ref_put_str(buf, 0u, "nan");
    if (bits == 0x7f800000u) return ref_put_str(buf, n, "inf");
    if (bits == 0u) { buf[n++] = '0'; return n; }
    nd = ref_shortest_digits(bits, dig, &k);
    xp = k - 1; /* value = d.ddd * 10^xp */
    if (xp >= -4 && xp < 9) {
        /* positional, like %g */
        if (xp < 0) {
            buf[n++] = '0';
            buf[n++] = '.';
            for (i = 0; i < (uint32_t)(-xp - 1); i++) buf[n++] = '0';
            for (i = 0; i < nd; i++) buf[n++] = (char)('0' + dig[i]);
        } else {
            uint32_t ip = (uint32_t)xp + 1u; /* digits before the point */
            for (i = 0; i < ip; i++) buf[n++] = (char)('0' + (i < nd ? dig[i] : 0u));
            if (nd > ip) {
                buf[n++] = '.';
                for (i = ip; i < nd; i++) buf[n++] = (char)('0' + dig[i]);
            }
        }
    } else {
        uint32_t ax;
        buf[n++] = (char)('0' + dig[0]);
        if (nd > 1u) {
            buf[n++] = '.';
            for (i = 1; i < nd; i++) buf[n++] = (char)('0' + dig[i]);
        }
        buf[n++] = 'e';
        buf[n++] = xp < 0 ? '-' : '+';
        ax = (uint32_t)(xp < 0 ? -xp : xp);
        if (ax >= 10u) buf[n++] = (char)('0' + ax / 10u);
        else buf[n++] = '0';
        buf[n++] = (char)('0' + ax % 10u);
    }
    return n;
}

#endif /* !SUBD_FIXED */
#endif
