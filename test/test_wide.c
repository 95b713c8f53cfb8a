/* SPDX-License-Identifier: MIT */
/* Tests of the wide integer arithmetic (src/wide.h, src/wide.c).
 *
 * Device-capable. The references are written here, independently of wide.c:
 *  - products: a schoolbook multiplication in 16-bit digits (h_mul16), so a carry lost in
 *    wide.h's 32-bit halves shows up; on the host also unsigned __int128 where the compiler
 *    has it;
 *  - division: the defining property n = q d + r, 0 <= r < d, checked with h_mul16;
 *  - float conversion: the result decoded back and checked to be the nearest float (half an
 *    ulp at most, the even one on a tie), a property that fixes the answer uniquely;
 *  - Q16.16 tie rules: closed forms with floor division;
 *  - gcd: trial division.
 * Edge tables cover carries (all-ones halves), extremes (0, 1, 2^63, 2^64 - 1) and the
 * boundary between the division's two paths (d = 2^32 - 1, 2^32). */
#include "harness.h"
#include "subd_alpha.h"
#include "../src/wide.h"

/* a * b as four 32-bit words, least significant first, by 16-bit digits. */
static void h_mul16(uint64_t a, uint64_t b, uint32_t w[4])
{
    uint32_t da[4], db[4], acc[8], i, j;
    uint64_t carry;
    for (i = 0; i < 4u; i++) {
        da[i] = (uint32_t)(a >> (16u * i)) & 0xffffu;
        db[i] = (uint32_t)(b >> (16u * i)) & 0xffffu;
    }
    for (i = 0; i < 8u; i++) acc[i] = 0;
    for (i = 0; i < 4u; i++) {
        carry = 0;
        for (j = 0; j < 4u; j++) {
            uint64_t t = (uint64_t)da[i] * db[j] + acc[i + j] + carry;
            acc[i + j] = (uint32_t)(t & 0xffffu);
            carry = t >> 16;
        }
        for (j = i + 4u; j < 8u && carry; j++) {
            uint64_t t = acc[j] + carry;
            acc[j] = (uint32_t)(t & 0xffffu);
            carry = t >> 16;
        }
    }
    for (i = 0; i < 4u; i++) w[i] = acc[2u * i] | (acc[2u * i + 1u] << 16);
}

static int h_same128(subd_u128 x, const uint32_t w[4])
{
    return x.lo == ((uint64_t)w[1] << 32 | w[0]) && x.hi == ((uint64_t)w[3] << 32 | w[2]);
}

static const uint64_t wide_edges[] = {
    0u, 1u, 2u, 3u, 0xffffu, 0x10000u, 0xffffffffu, 0x100000000u, 0x100000001u, 0x7fffffffffffffffu,
    0x8000000000000000u, 0x8000000000000001u, 0xfffffffeffffffffu, 0xffffffff00000000u,
    0xffffffffffffffffu, 0xc90fdaa22168c235u, 0x5a827999fcef3242u};
#define WIDE_NEDGE (sizeof wide_edges / sizeof wide_edges[0])

static uint64_t h_rand64(uint32_t *st)
{
    uint64_t hi = h_rand(st);
    uint32_t sh = h_rand(st) % 64u; /* vary the size, so small operands occur too */
    return ((hi << 32) | h_rand(st)) >> sh;
}

static void wide_mul(void)
{
    uint32_t i, j, w[4], st = 7u, bad = 0;
    for (i = 0; i < WIDE_NEDGE; i++)
        for (j = 0; j < WIDE_NEDGE; j++) {
            h_mul16(wide_edges[i], wide_edges[j], w);
            if (!h_same128(subd_u128_mul(wide_edges[i], wide_edges[j]), w)) bad++;
        }
    for (i = 0; i < 20000u; i++) {
        uint64_t a = h_rand64(&st), b = h_rand64(&st);
        h_mul16(a, b, w);
        if (!h_same128(subd_u128_mul(a, b), w)) bad++;
#if H_HOST && defined(__SIZEOF_INT128__)
        {
            __extension__ typedef unsigned __int128 h_u128;
            h_u128 p = (h_u128)a * b;
            subd_u128 r = subd_u128_mul(a, b);
            if (r.lo != (uint64_t)p || r.hi != (uint64_t)(p >> 64)) bad++;
        }
#endif
    }
    CHECK_EQ(bad, 0);
    /* (2^64 - 1)^2 = 2^128 - 2^65 + 1: every carry of the halves taken */
    CHECK(subd_u128_mul(UINT64_MAX, UINT64_MAX).hi == UINT64_MAX - 1u);
    CHECK(subd_u128_mul(UINT64_MAX, UINT64_MAX).lo == 1u);
}

/* floor(n / 2^s) and its half-up rounding against a shift of the 16-bit-digit product. */
static void wide_shift(void)
{
    uint32_t i, s, w[4], st = 11u, bad = 0;
    subd_u128 n;
    for (i = 0; i < 3000u; i++) {
        uint64_t a = i < WIDE_NEDGE ? wide_edges[i] : h_rand64(&st), b = h_rand64(&st);
        n = subd_u128_mul(a, b);
        h_mul16(a, b, w);
        for (s = 1; s < 128u; s++) {
            /* reference: the words shifted right by s, bit by bit */
            uint64_t q = 0, half;
            uint32_t k;
            for (k = 0; k < 64u && s + k < 128u; k++) q |= (uint64_t)((w[(s + k) / 32u] >> ((s + k) % 32u)) & 1u) << k;
            half = (w[(s - 1u) / 32u] >> ((s - 1u) % 32u)) & 1u;
            if (subd_u128_shr(n, s) != q) bad++;
            if (subd_u128_shr_round(n, s) != q + half) bad++;
        }
    }
    CHECK_EQ(bad, 0);
    n.hi = 0;
    n.lo = UINT64_MAX;
    n = subd_u128_add64(n, 1u); /* carry into hi */
    CHECK(n.hi == 1u && n.lo == 0u);
}

/* n = q d + r with 0 <= r < d, for n.hi < d. */
static int h_div_ok(subd_u128 n, uint64_t d)
{
    uint64_t r, q = subd_u128_div(n, d, &r);
    uint32_t w[4];
    subd_u128 back;
    if (r >= d) return 0;
    h_mul16(q, d, w);
    back.lo = (uint64_t)w[1] << 32 | w[0];
    back.hi = (uint64_t)w[3] << 32 | w[2];
    back = subd_u128_add64(back, r);
    return back.hi == n.hi && back.lo == n.lo;
}

static void wide_div(void)
{
    static const uint64_t ds[] = {1u, 2u, 3u, 7u, 0xfffffffeu, 0xffffffffu, 0x100000000u, 0x100000001u,
                                  0x7fffffffffffffffu, 0x8000000000000000u, 0xfffffffffffffffeu, UINT64_MAX};
    uint32_t i, j, st = 13u, bad = 0;
    subd_u128 n;
    for (i = 0; i < sizeof ds / sizeof ds[0]; i++) {
        for (j = 0; j < WIDE_NEDGE; j++) {
            /* the largest numerators: hi = d - 1 with every low pattern */
            n.hi = ds[i] - 1u;
            n.lo = wide_edges[j];
            if (!h_div_ok(n, ds[i])) bad++;
            n.hi = 0;
            if (!h_div_ok(n, ds[i])) bad++;
        }
    }
    for (i = 0; i < 20000u; i++) {
        uint64_t d = h_rand64(&st) | 1u;
        n.hi = h_rand64(&st) % d;
        n.lo = h_rand64(&st);
        if (!h_div_ok(n, d)) bad++;
        d >>= 32; /* the two-digit path */
        if (d == 0u) d = 1u;
        n.hi %= d;
        if (!h_div_ok(n, d)) bad++;
    }
    CHECK_EQ(bad, 0);
    /* trig.c's use: floor(2^64 / 3) = 0x5555555555555555, remainder 1 */
    {
        uint64_t r;
        n.hi = 1u;
        n.lo = 0u;
        CHECK(subd_u128_div(n, 3u, &r) == 0x5555555555555555u);
        CHECK_EQ(r, 1);
    }
}

/* bits is the nearest binary32 to q 2^-frac (ties to even), normal, with q's sign. */
static int h_nearest_f32(uint32_t bits, int64_t q, uint32_t frac)
{
    uint64_t u = q < 0 ? 0u - (uint64_t)q : (uint64_t)q, m;
    uint32_t ef = (bits >> 23) & 0xffu;
    int32_t k;
    if (u == 0u) return bits == 0u;
    if ((bits >> 31) != (q < 0 ? 1u : 0u) || ef == 0u || ef == 0xffu) return 0;
    m = (bits & 0x7fffffu) | 0x800000u;
    k = (int32_t)ef - 150 + (int32_t)frac; /* value 2^frac = m 2^k */
    if (k < 0) return (m & ((1u << -k) - 1u)) == 0u && (m >> -k) == u; /* exact, u < 2^24 */
    {
        /* m 2^k as 128 bits against u: |m 2^k - u| <= 2^(k-1), = only with m even */
        subd_u128 v, diff;
        v.hi = k >= 64 ? m << (k - 64) : (k == 0 ? 0u : m >> (64 - k));
        v.lo = k >= 64 ? 0u : m << k;
        if (v.hi != 0u || v.lo >= u) {
            diff.lo = v.lo - u;
            diff.hi = v.hi - (v.lo < u ? 1u : 0u);
        } else {
            diff.lo = u - v.lo;
            diff.hi = 0;
        }
        if (k == 0) return diff.hi == 0u && diff.lo == 0u;
        if (diff.hi != 0u || diff.lo > ((uint64_t)1 << (k - 1))) return 0;
        return diff.lo < ((uint64_t)1 << (k - 1)) || (m & 1u) == 0u;
    }
}

static void wide_f32(void)
{
    uint32_t i, st = 17u, bad = 0, frac;
    for (frac = 0; frac <= 62u; frac++) {
        for (i = 0; i < WIDE_NEDGE; i++) {
            int64_t q = (int64_t)wide_edges[i];
            if (!h_nearest_f32(subd_f32_bits_from_scaled(q, frac), q, frac)) bad++;
            if (q != INT64_MIN && !h_nearest_f32(subd_f32_bits_from_scaled(-q, frac), -q, frac)) bad++;
        }
        for (i = 0; i < 1000u; i++) {
            int64_t q = (int64_t)h_rand64(&st);
            /* ties: 25 significant bits ending in 1 */
            int64_t t = (int64_t)((h_rand(&st) | 0x1000000u) & 0x1ffffffu) | 1;
            t <<= h_rand(&st) % 39u;
            if (!h_nearest_f32(subd_f32_bits_from_scaled(q, frac), q, frac)) bad++;
            if (!h_nearest_f32(subd_f32_bits_from_scaled(t, frac), t, frac)) bad++;
            if (!h_nearest_f32(subd_f32_bits_from_scaled(-t, frac), -t, frac)) bad++;
        }
    }
    CHECK_EQ(bad, 0);
    /* hand-made: 2^-62, 1, ties to even at 1 + 2^-24 and 1 + 3 2^-24, 2^64 - 1 -> 2^64 */
    CHECK_EQ(subd_f32_bits_from_scaled(1, 62u), 0x20800000u);
    CHECK_EQ(subd_f32_bits_from_scaled((int64_t)1 << 32, 32u), 0x3f800000u);
    CHECK_EQ(subd_f32_bits_from_scaled(((int64_t)1 << 24) + 1, 24u), 0x3f800000u);
    CHECK_EQ(subd_f32_bits_from_scaled(((int64_t)1 << 24) + 3, 24u), 0x3f800002u);
    CHECK_EQ(subd_f32_bits_from_scaled(-1, 0u), 0xbf800000u);
    CHECK_EQ(subd_f32_bits_from_scaled(INT64_MIN, 0u), 0xdf000000u); /* -2^63 */
    CHECK_EQ(subd_f32_bits_from_scaled(INT64_MAX, 0u), 0x5f000000u); /* rounds up to 2^63 */
}

/* The two Q16.16 tie rules against closed forms; float32 gives the nearest float for both. */
static void wide_tie_rules(void)
{
    uint32_t frac, bad = 0, ovf = 0;
    int64_t j;
    for (frac = 17; frac <= 62u; frac += 5u) {
        uint32_t sh = frac - 16u;
        int64_t one = (int64_t)1 << sh; /* one LSB of Q16.16 */
        for (j = -40; j <= 40; j++) {
            /* q = j/4 LSB: every quarter, so ties (j = 2 mod 4) occur on both signs */
            int64_t q = j * (one / 4 > 0 ? one / 4 : 1), a = q < 0 ? -q : q;
            int64_t up = (2 * q + one) >= 0 ? (2 * q + one) / (2 * one) : -((-(2 * q + one) + 2 * one - 1) / (2 * one));
            int64_t away = (2 * a + one) / (2 * one);
            subd_real ru = subd_real_from_scaled_up(q, frac, &ovf), ra = subd_real_from_scaled_away(q, frac, &ovf);
            if (q < 0) away = -away;
#if SUBD_FIXED
            if (ru != up || ra != away) bad++;
#else
            (void)up;
            (void)away;
            if (!h_nearest_f32(subd_real_bits(ru), q, frac) || subd_real_bits(ru) != subd_real_bits(ra)) bad++;
#endif
        }
    }
    CHECK_EQ(bad, 0);
    CHECK_EQ(ovf, 0);
#if SUBD_FIXED
    /* where they differ: -1/2 LSB (half up: 0; away: -1 LSB), -3/2 LSB (-1; -2) */
    CHECK_EQ(subd_real_from_scaled_up(-((int64_t)1 << 15), 32u, &ovf), 0);
    CHECK_EQ(subd_real_from_scaled_away(-((int64_t)1 << 15), 32u, &ovf), -1);
    CHECK_EQ(subd_real_from_scaled_up(-((int64_t)3 << 45), 62u, &ovf), -1);
    CHECK_EQ(subd_real_from_scaled_away(-((int64_t)3 << 45), 62u, &ovf), -2);
    CHECK_EQ(subd_real_from_scaled_up((int64_t)1 << 15, 32u, &ovf), 1);
    CHECK_EQ(subd_real_from_scaled_away((int64_t)1 << 15, 32u, &ovf), 1);
    CHECK_EQ(ovf, 0);
    /* saturation */
    CHECK_EQ(subd_real_from_scaled_up(INT64_MAX, 32u, &ovf), INT32_MAX);
    CHECK_EQ(ovf, 1);
    ovf = 0;
    CHECK_EQ(subd_real_from_scaled_away(INT64_MIN, 32u, &ovf), INT32_MIN);
    CHECK_EQ(ovf, 1);
    ovf = 0;
    CHECK_EQ(subd_real_from_scaled_away(INT64_MIN, 62u, &ovf), -131072); /* subd_real_from_q62's range */
    CHECK_EQ(ovf, 0);
#endif
    /* The difference is observable: the alpha kernel's value -2^-17 (s = 2^-16 times
     * cos(2 pi / 3) = -1/2 exactly) rounds half up to 0 in Q16.16 (subd_real_from_q62's rule
     * would give -2^-16); float32 holds it exactly. */
    {
        subd_real f = 1;
#if SUBD_FIXED
        subd_real s = 1;
#else
        subd_real s = 1.0f / 65536.0f;
#endif
        CHECK_EQ(subd_alpha_kernel_value(SUBD_ALPHA_COS, 2, 3, 0, s, &f), SUBD_OK);
#if SUBD_FIXED
        CHECK_EQ(f, 0);
#else
        CHECK(f == -1.0f / 131072.0f);
#endif
    }
}

static void wide_to_q32(void)
{
    uint32_t ovf = 0;
    CHECK_EQ(subd_real_to_q32(SUBD_REAL_ONE, &ovf), (int64_t)1 << 32);
    CHECK_EQ(subd_real_to_q32(SUBD_REAL_FRAC(-3, 2), &ovf), -((int64_t)3 << 31));
    CHECK_EQ(subd_real_to_q32(0, &ovf), 0);
    CHECK_EQ(ovf, 0);
#if SUBD_FIXED
    CHECK_EQ(subd_real_to_q32(INT32_MIN, &ovf), INT32_MIN * (int64_t)65536);
    CHECK_EQ(subd_real_to_q32(1, &ovf), 65536);
    CHECK_EQ(ovf, 0);
#else
    CHECK_EQ(subd_real_to_q32(1.0f / 4294967296.0f, &ovf), 1);               /* 2^-32 */
    CHECK_EQ(subd_real_to_q32(1.0f / 8589934592.0f, &ovf), 1);               /* 2^-33: half, up */
    CHECK_EQ(subd_real_to_q32(3.0f / 17179869184.0f, &ovf), 1);              /* 3 2^-34 = 0.75 */
    CHECK_EQ(subd_real_to_q32(1.0f / 17179869184.0f, &ovf), 0);              /* 2^-34: down */
    CHECK_EQ(subd_real_to_q32(-536870912.0f, &ovf), -((int64_t)1 << 61));   /* -2^29 */
    CHECK_EQ(ovf, 0);
    CHECK_EQ(subd_real_to_q32(1073741824.0f, &ovf), 0);                      /* 2^30: too large */
    CHECK_EQ(ovf, 1);
#endif
}

static void wide_gcd(void)
{
    uint32_t bad = 0;
    int64_t a, b;
    for (a = -30; a <= 30; a++)
        for (b = 1; b <= 40; b++) {
            int64_t g = b, aa = a < 0 ? -a : a;
            while (g > 1 && (aa % g != 0 || b % g != 0)) g--; /* the largest common divisor */
            if (subd_gcd64(a, b) != (uint64_t)g) bad++;
        }
    CHECK_EQ(bad, 0);
    CHECK(subd_gcd64(0, 3600000) == 3600000u);
    CHECK(subd_gcd64(-450000, 3600000) == 450000u);
    CHECK(subd_gcd64(INT64_MIN, 2) == 2u);
    CHECK(subd_gcd64(INT64_MAX, INT64_MAX - 1) == 1u);
}

/* Host and device must agree bit for bit: one hash over every operation. */
static void wide_hash(void)
{
    uint32_t h = 2166136261u, st = 23u, i, ovf = 0;
    for (i = 0; i < 2000u; i++) {
        uint64_t a = h_rand64(&st), b = h_rand64(&st) | 1u, r, q;
        subd_u128 p = subd_u128_mul(a, b), n;
        uint32_t f = subd_f32_bits_from_scaled((int64_t)a, i % 63u);
        subd_real x = subd_real_from_scaled_up((int64_t)a, 17u + i % 46u, &ovf);
        subd_real y = subd_real_from_scaled_away((int64_t)a, 17u + i % 46u, &ovf);
        n.hi = p.hi % b;
        n.lo = p.lo;
        q = subd_u128_div(n, b, &r);
        h = h_fnv(h, &p.hi, 8);
        h = h_fnv(h, &p.lo, 8);
        h = h_fnv(h, &q, 8);
        h = h_fnv(h, &r, 8);
        h = h_fnv(h, &f, 4);
        h = h_fnv(h, &x, sizeof x);
        h = h_fnv(h, &y, sizeof y);
    }
    h_hash("wide_ops", h);
}

const test_case suite_wide[] = {
    {"wide_mul", wide_mul},
    {"wide_shift", wide_shift},
    {"wide_div", wide_div},
    {"wide_f32", wide_f32},
    {"wide_tie_rules", wide_tie_rules},
    {"wide_to_q32", wide_to_q32},
    {"wide_gcd", wide_gcd},
    {"wide_hash", wide_hash},
    {0, 0}
};
