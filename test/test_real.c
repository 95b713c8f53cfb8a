/* SPDX-License-Identifier: MIT */
/* Tests of subd_real_parse / subd_real_format (src/real_text.c).
 *
 * Device-capable tests use integer references only: edge tables, exact float32 halfway
 * integers (expected result from ties-to-even in integers), a Q16.16 reference by direct
 * division, and format -> parse round trips of random bit patterns. On the host the parser
 * is also compared bit for bit with the C library (strtof, correctly rounded in glibc) and
 * the formatter with printf. */
#include "harness.h"

#if H_HOST
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#endif

#define N_DEV 3000u      /* random cases on the device */
#define N_HOST 200000u   /* random cases on the host */
#define N_RAND (H_HOST ? N_HOST : N_DEV)

static uint32_t slen(const char *s)
{
    uint32_t n = 0;
    while (s[n]) n++;
    return n;
}

/* Parses the whole C string s; returns rc, *used = characters consumed (0 on error). */
static int parse_str(const char *s, subd_real *out, uint32_t *used)
{
    const char *p = s;
    int rc = subd_real_parse(&p, s + slen(s), out);
    *used = (uint32_t)(p - s);
    return rc;
}

/* Writes v in decimal at b, returns length. */
static uint32_t put_u64(char *b, uint64_t v)
{
    char t[24];
    uint32_t n = 0, i;
    do { t[n++] = (char)('0' + (int)(v % 10u)); v /= 10u; } while (v);
    for (i = 0; i < n; i++) b[i] = t[n - 1u - i];
    return n;
}

static uint32_t put_i32(char *b, int32_t v)
{
    if (v < 0) { b[0] = '-'; return 1u + put_u64(b + 1, (uint64_t)(-(int64_t)v)); }
    return put_u64(b, (uint64_t)v);
}

typedef struct edge_case {
    const char *s;
    int rc;
    uint32_t used; /* characters consumed on success */
    uint32_t bits; /* float32 bit pattern or Q16.16 integer */
} edge_case;

#if SUBD_FIXED
static const edge_case k_edges[] = {
    {"0", SUBD_OK, 1, 0},
    {"-0", SUBD_OK, 2, 0},
    {"+1.5", SUBD_OK, 4, 98304},
    {"1", SUBD_OK, 1, 65536},
    {".5", SUBD_OK, 2, 32768},
    {"5.", SUBD_OK, 2, 327680},
    {"-.5e1", SUBD_OK, 5, (uint32_t)-327680},
    {"0.99999999999", SUBD_OK, 13, 65536},
    {"32767.99999", SUBD_OK, 11, 0x7fffffffu},
    {"32767.9999923706054", SUBD_OK, 19, 0x7fffffffu},    /* just below the tie 32768-2^-17 */
    {"32767.9999923706055", SUBD_ERR_RANGE, 0, 0},        /* just above: rounds to 32768 */
    {"-32768", SUBD_OK, 6, 0x80000000u},
    {"-32768.0000076293945", SUBD_OK, 20, 0x80000000u},   /* below the tie */
    {"-32768.0000076293946", SUBD_ERR_RANGE, 0, 0},
    {"32768", SUBD_ERR_RANGE, 0, 0},
    {"-32769", SUBD_ERR_RANGE, 0, 0},
    {"99999", SUBD_ERR_RANGE, 0, 0},
    {"1e4", SUBD_OK, 3, 655360000u},
    {"1e5", SUBD_ERR_RANGE, 0, 0},
    {"1e30", SUBD_ERR_RANGE, 0, 0},
    {"3.4028235e38", SUBD_ERR_RANGE, 0, 0},
    {"0.00000762939453125", SUBD_OK, 19, 1},              /* 2^-17: tie, away from zero */
    {"-0.00000762939453125", SUBD_OK, 20, (uint32_t)-1},
    {"0.0000076293945312", SUBD_OK, 18, 0},
    {"0.0000152587890625", SUBD_OK, 18, 1},
    {"0.00001525878906249", SUBD_OK, 19, 1},
    {"0.0000228881835937", SUBD_OK, 18, 1},               /* just below 1.5 LSB */
    {"0.0000228881835938", SUBD_OK, 18, 2},
    {"1e-999999999", SUBD_OK, 12, 0},
    {"1e999999999", SUBD_ERR_RANGE, 0, 0},
    {"0e999999999", SUBD_OK, 11, 0},
    {"1e99999999999999999999999", SUBD_ERR_RANGE, 0, 0},
    {"100000000000000000000000000000000000000000000000000e-50", SUBD_OK, 55, 65536},
    {"0.000000000000000000000000000000000000000000000000001e51", SUBD_OK, 56, 65536},
    {"1234.5678", SUBD_OK, 9, 80908635},                  /* 1234.5678*65536 = 80908635.34 */
    {"0x10", SUBD_OK, 1, 0},
    {"1e", SUBD_OK, 1, 65536},
    {"1e+", SUBD_OK, 1, 65536},
    {"1E-x", SUBD_OK, 1, 65536},
    {"1e+1x", SUBD_OK, 4, 655360},
    {"1.2.3", SUBD_OK, 3, 78643},                         /* 1.2*65536 = 78643.2 */
#else
static const edge_case k_edges[] = {
    {"0", SUBD_OK, 1, 0},
    {"-0", SUBD_OK, 2, 0x80000000u},
    {"+1.5", SUBD_OK, 4, 0x3fc00000u},
    {"1", SUBD_OK, 1, 0x3f800000u},
    {".5", SUBD_OK, 2, 0x3f000000u},
    {"5.", SUBD_OK, 2, 0x40a00000u},
    {"-.5e1", SUBD_OK, 5, 0xc0a00000u},
    {"0.1", SUBD_OK, 3, 0x3dcccccdu},
    {"0.99999999999", SUBD_OK, 13, 0x3f800000u},
    {"32767.99999", SUBD_OK, 11, 0x47000000u},
    {"-32768", SUBD_OK, 6, 0xc7000000u},
    {"16777217", SUBD_OK, 8, 0x4b800000u},                /* tie -> even 16777216 */
    {"16777219", SUBD_OK, 8, 0x4b800002u},                /* tie -> even 16777220 */
    {"16777217.000000001", SUBD_OK, 18, 0x4b800001u},     /* just above the tie */
    {"3.4028235e38", SUBD_OK, 12, 0x7f7fffffu},
    {"3.402823466385288598e38", SUBD_OK, 23, 0x7f7fffffu}, /* FLT_MAX, 19 digits */
    {"3.402823567797336616e38", SUBD_OK, 23, 0x7f7fffffu}, /* just below FLT_MAX + half ulp */
    {"3.402823567797336617e38", SUBD_ERR_RANGE, 0, 0},     /* just above: rounds to 2^128 */
    {"3.5e38", SUBD_ERR_RANGE, 0, 0},
    {"-3.5e38", SUBD_ERR_RANGE, 0, 0},
    {"1e38", SUBD_OK, 4, 0x7e967699u},
    {"1e39", SUBD_ERR_RANGE, 0, 0},
    {"1e30", SUBD_OK, 4, 0x7149f2cau},
    {"1.17549435e-38", SUBD_OK, 14, 0x00800000u},         /* FLT_MIN */
    {"1.1754942e-38", SUBD_OK, 13, 0x007fffffu},          /* largest subnormal */
    {"1e-45", SUBD_OK, 5, 0x00000001u},
    {"1.4e-45", SUBD_OK, 7, 0x00000001u},
    {"2.1e-45", SUBD_OK, 7, 0x00000001u},                 /* 1.499 * 2^-149 */
    {"2.2e-45", SUBD_OK, 7, 0x00000002u},
    {"7.006e-46", SUBD_OK, 9, 0},                         /* below 2^-150 */
    {"7.007e-46", SUBD_OK, 9, 0x00000001u},               /* above 2^-150 */
    {"-1e-50", SUBD_OK, 6, 0x80000000u},
    {"1e-999999999", SUBD_OK, 12, 0},
    {"-1e-999999999", SUBD_OK, 13, 0x80000000u},
    {"1e999999999", SUBD_ERR_RANGE, 0, 0},
    {"0e999999999", SUBD_OK, 11, 0},
    {"1e99999999999999999999999", SUBD_ERR_RANGE, 0, 0},
    {"100000000000000000000000000000000000000000000000000e-50", SUBD_OK, 55, 0x3f800000u},
    {"0.000000000000000000000000000000000000000000000000001e51", SUBD_OK, 56, 0x3f800000u},
    {"1.00000005960464477539", SUBD_OK, 22, 0x3f800000u}, /* 1+2^-24 tie, truncated to 19 digits */
    {"0x10", SUBD_OK, 1, 0},
    {"1e", SUBD_OK, 1, 0x3f800000u},
    {"1e+", SUBD_OK, 1, 0x3f800000u},
    {"1E-x", SUBD_OK, 1, 0x3f800000u},
    {"1e+1x", SUBD_OK, 4, 0x41200000u},
    {"1.5E-1", SUBD_OK, 6, 0x3e19999au},
    {"1.2.3", SUBD_OK, 3, 0x3f99999au},
#endif
    /* errors: *p and *out must stay untouched */
    {"", SUBD_ERR_PARSE, 0, 0},
    {"-", SUBD_ERR_PARSE, 0, 0},
    {"+", SUBD_ERR_PARSE, 0, 0},
    {".", SUBD_ERR_PARSE, 0, 0},
    {"-.", SUBD_ERR_PARSE, 0, 0},
    {".e5", SUBD_ERR_PARSE, 0, 0},
    {"e5", SUBD_ERR_PARSE, 0, 0},
    {" 1", SUBD_ERR_PARSE, 0, 0},
    {"+-1", SUBD_ERR_PARSE, 0, 0},
    {"x", SUBD_ERR_PARSE, 0, 0},
    {"in", SUBD_ERR_PARSE, 0, 0},
    {"na", SUBD_ERR_PARSE, 0, 0},
    {"nan", SUBD_ERR_NAN, 0, 0},
    {"NaN", SUBD_ERR_NAN, 0, 0},
    {"-nan(0x1)", SUBD_ERR_NAN, 0, 0},
    {"-inf", SUBD_ERR_NAN, 0, 0},
    {"+Infinity", SUBD_ERR_NAN, 0, 0},
    {"INF", SUBD_ERR_NAN, 0, 0},
    {0, 0, 0, 0}
};

static void real_parse_edges(void)
{
    const edge_case *c;
    for (c = k_edges; c->s; c++) {
        subd_real v = SUBD_REAL_ONE;
        uint32_t used;
        int rc = parse_str(c->s, &v, &used);
        if (!CHECK_EQ(rc, c->rc)) { h_str("    input: "); h_str(c->s); h_nl(); continue; }
        if (rc == SUBD_OK) {
            CHECK_EQ(used, c->used);
            if (!CHECK_EQ(subd_real_bits(v), c->bits)) { h_str("    input: "); h_str(c->s); h_nl(); }
        } else {
            CHECK_EQ(used, 0);
            CHECK_EQ(subd_real_bits(v), subd_real_bits(SUBD_REAL_ONE));
        }
    }
    {
        /* a NULL argument is a parameter error; a pointer at or past end is no number */
        const char *s = "1", *p = s;
        subd_real v;
        CHECK_EQ(subd_real_parse(0, s + 1, &v), SUBD_ERR_PARAM);
        CHECK_EQ(subd_real_parse(&p, s + 1, 0), SUBD_ERR_PARAM);
        CHECK_EQ(subd_real_parse(&p, s, &v), SUBD_ERR_PARSE);
        CHECK(p == s);
        /* end cuts the text: only [p, end) is read */
        CHECK_EQ(subd_real_parse(&p, s + 1, &v), SUBD_OK);
        CHECK(p == s + 1);
    }
    {
        const char *s = "123e45", *p = s;
        subd_real v = 0;
        CHECK_EQ(subd_real_parse(&p, s + 2, &v), SUBD_OK); /* "12" */
        CHECK(p == s + 2);
        CHECK_EQ(subd_real_bits(v), subd_real_bits(subd_from_int(12, &(uint32_t){0})));
        p = s;
        CHECK_EQ(subd_real_parse(&p, s + 4, &v), SUBD_OK); /* "123e": exponent incomplete */
        CHECK(p == s + 3);
    }
}

/* A random decimal string with 1..19 significant digits whose value lies near 10^x10,
 * x10 in [xlo, xhi], written in one of several shapes. Returns its length. */
static uint32_t rand_decimal(uint32_t *st, char *b, int32_t xlo, int32_t xhi)
{
    uint32_t nd = 1u + h_rand(st) % 19u, n = 0, i, shape = h_rand(st) % 4u;
    int32_t x10 = xlo + (int32_t)(h_rand(st) % (uint32_t)(xhi - xlo + 1));
    char dg[20];
    for (i = 0; i < nd; i++) dg[i] = (char)('0' + h_rand(st) % 10u);
    if (dg[0] == '0') dg[0] = '1';
    if (h_rand(st) & 1u) b[n++] = '-';
    else if ((h_rand(st) & 7u) == 0u) b[n++] = '+';
    if (shape == 0u) {
        /* d.ddd e x10 */
        b[n++] = dg[0];
        if (nd > 1u) { b[n++] = '.'; for (i = 1; i < nd; i++) b[n++] = dg[i]; }
        b[n++] = 'e';
        n += put_i32(b + n, x10);
    } else if (shape == 1u) {
        /* integer digits e (x10 - nd + 1) */
        for (i = 0; i < nd; i++) b[n++] = dg[i];
        b[n++] = 'E';
        n += put_i32(b + n, x10 - (int32_t)nd + 1);
    } else if (shape == 2u && x10 >= -8 && x10 < 0) {
        /* 0.000ddd */
        b[n++] = '0';
        b[n++] = '.';
        for (i = 0; i < (uint32_t)(-x10 - 1); i++) b[n++] = '0';
        for (i = 0; i < nd; i++) b[n++] = dg[i];
    } else {
        /* leading zeros, point inside the digits, exponent */
        uint32_t pt = h_rand(st) % (nd + 1u);
        b[n++] = '0';
        for (i = 0; i < nd; i++) { if (i == pt) b[n++] = '.'; b[n++] = dg[i]; }
        b[n++] = 'e';
        n += put_i32(b + n, x10 - (int32_t)pt + 1);
    }
    b[n] = 0;
    return n;
}

#if !SUBD_FIXED
/* Exact float32 halfway points written as integers (<= 19 digits): M = (2s+1) * 2^(k-1)
 * lies between the floats s*2^k and (s+1)*2^k. Ties go to the even significand, M+1 and
 * M-1 to the nearer one. Expected bits from integers only, so this runs on the device. */
static void real_parse_halfway_exact(void)
{
    uint32_t st = 0x9e3779b9u, i, fails = 0;
    for (i = 0; i < N_RAND / 4u; i++) {
        uint32_t s = 0x800000u | (h_rand(&st) & 0x7fffffu);
        uint32_t k = 1u + h_rand(&st) % 39u; /* (2^25) * 2^38 < 10^19 */
        uint64_t m = ((uint64_t)(2u * s + 1u)) << (k - 1u);
        uint32_t base = ((k + 23u + 127u) << 23) + (s - 0x800000u); /* bits of s * 2^k */
        uint32_t want_tie = base + (s & 1u), j;
        for (j = 0; j < 3u; j++) {
            char b[32];
            subd_real v = 0;
            uint32_t used, n;
            uint64_t mm = j == 0u ? m : (j == 1u ? m - 1u : m + 1u);
            uint32_t want = j == 0u ? want_tie : (j == 1u ? base : base + 1u);
            n = put_u64(b, mm);
            b[n] = 0;
            if (parse_str(b, &v, &used) != SUBD_OK || subd_real_bits(v) != want || used != n) {
                if (fails++ < 5u) { h_str("    halfway: "); h_str(b); h_nl(); }
            }
        }
    }
    CHECK_EQ(fails, 0);
}
#endif

#if H_HOST && !SUBD_FIXED
static uint32_t fbits(float f)
{
    uint32_t u;
    memcpy(&u, &f, 4);
    return u;
}

/* Random strings (1..19 digits, values 1e-47..1e39) and near-halfway strings: bit-exact
 * against glibc strtof, including subnormals, underflow to signed zero, and overflow
 * (strtof's +-inf must be our SUBD_ERR_RANGE). */
static void real_parse_vs_strtof(void)
{
    uint32_t st = 12345u, i, fails = 0, n_range = 0, n_sub = 0;
    char b[80];
    for (i = 0; i < N_HOST; i++) {
        uint32_t n = rand_decimal(&st, b, -47, 39), used;
        float want = strtof(b, 0), v = 0.0f;
        int rc = parse_str(b, &v, &used);
        uint32_t wb = fbits(want);
        if ((wb & 0x7fffffffu) == 0x7f800000u) {
            n_range++;
            if (rc != SUBD_ERR_RANGE && fails++ < 5u) printf("    want RANGE: %s\n", b);
            continue;
        }
        if ((wb & 0x7f800000u) == 0u) n_sub++;
        if ((rc != SUBD_OK || fbits(v) != wb || used != n) && fails++ < 5u)
            printf("    %s: got %08x want %08x\n", b, (unsigned)fbits(v), (unsigned)wb);
    }
    /* near-halfway: the exact midpoint of two neighbouring floats (exact in double), printed
     * with 19 significant digits (so it is just above or below the tie), and its neighbours
     * in the last digit */
    for (i = 0; i < N_HOST / 4u; i++) {
        uint32_t fb = h_rand(&st) & 0x7f7fffffu, j;
        float f0, f1;
        double mid;
        memcpy(&f0, &fb, 4);
        fb++;
        memcpy(&f1, &fb, 4);
        mid = ((double)f0 + (double)f1) * 0.5;
        for (j = 0; j < 3u; j++) {
            uint32_t n, used;
            float want, v = 0.0f;
            int rc;
            n = (uint32_t)snprintf(b, sizeof b, "%.18e", mid);
            if (j) {
                /* bump the last mantissa digit by -1 / +1 (stay within 0..9) */
                char *e = strchr(b, 'e');
                if (j == 1u && e[-1] > '0') e[-1]--;
                if (j == 2u && e[-1] < '9') e[-1]++;
            }
            want = strtof(b, 0);
            rc = parse_str(b, &v, &used);
            if ((fbits(want) & 0x7fffffffu) == 0x7f800000u) {
                if (rc != SUBD_ERR_RANGE && fails++ < 5u) printf("    want RANGE: %s\n", b);
                continue;
            }
            if ((rc != SUBD_OK || fbits(v) != fbits(want) || used != n) && fails++ < 5u)
                printf("    halfway %s: got %08x want %08x\n", b, (unsigned)fbits(v), (unsigned)fbits(want));
        }
    }
    CHECK_EQ(fails, 0);
    CHECK(n_range > 100u); /* the generator really reaches overflow and subnormals */
    CHECK(n_sub > 100u);
}
#endif

#if SUBD_FIXED
/* Q16.16 reference by direct division: "I.F" with F of nd <= 9 digits is
 * I + F / 10^nd; times 65536 rounded half away from zero = I*65536 + round(F*65536/10^nd). */
static void real_parse_fixed_ref(void)
{
    uint32_t st = 777u, i, fails = 0;
    for (i = 0; i < N_RAND; i++) {
        uint32_t ip = h_rand(&st) % 32769u, nd = 1u + h_rand(&st) % 9u, j, n = 0, used;
        uint64_t p10 = 1, fr = 0, q, rem;
        int neg = (int)(h_rand(&st) & 1u);
        int64_t want;
        int want_rc = SUBD_OK, rc;
        char b[40];
        subd_real v = 0;
        if (neg) b[n++] = '-';
        n += put_u64(b + n, ip);
        b[n++] = '.';
        for (j = 0; j < nd; j++) {
            uint32_t dg = h_rand(&st) % 10u;
            b[n++] = (char)('0' + dg);
            fr = fr * 10u + dg;
            p10 *= 10u;
        }
        b[n] = 0;
        q = (fr * 65536u) / p10;
        rem = (fr * 65536u) % p10;
        if (2u * rem >= p10) q++;
        want = (int64_t)ip * 65536 + (int64_t)q;
        if (neg) want = -want;
        if (want > INT32_MAX || want < INT32_MIN) want_rc = SUBD_ERR_RANGE;
        rc = parse_str(b, &v, &used);
        if (rc != want_rc || (rc == SUBD_OK && ((int64_t)v != want || used != n))) {
            if (fails++ < 5u) { h_str("    "); h_str(b); h_str(" got "); h_i32(v); h_nl(); }
        }
    }
    CHECK_EQ(fails, 0);
#if H_HOST
    /* With exponents: strtod is exact enough for <= 9 significant digits (a 9-digit decimal
     * that is not a tie is farther than 7e-15 relative from one, double errs by 1.1e-16),
     * so round-half-away of strtod(s) * 65536 in double is the exact reference. */
    fails = 0;
    for (i = 0; i < N_HOST; i++) {
        char b[80];
        uint32_t n, used, k, nd = 0;
        double x, r;
        subd_real v = 0;
        int rc, want_rc = SUBD_OK;
        n = rand_decimal(&st, b, -7, 5);
        for (k = 0; k < n && b[k] != 'e' && b[k] != 'E'; k++) if (b[k] >= '0' && b[k] <= '9') nd++;
        if (nd > 10u) continue; /* one leading '0' in some shapes */
        x = strtod(b, 0) * 65536.0;
        r = floor(fabs(x) + 0.5);
        if (x < 0) r = -r;
        if (r > 2147483647.0 || r < -2147483648.0) want_rc = SUBD_ERR_RANGE;
        rc = parse_str(b, &v, &used);
        if (rc != want_rc || (rc == SUBD_OK && ((double)v != r || used != n))) {
            if (fails++ < 5u) printf("    %s: got %d (rc %d) want %.0f\n", b, (int)v, rc, r);
        }
    }
    CHECK_EQ(fails, 0);
#endif
}
#endif

/* Random byte strings over a number-ish alphabet: never reads outside [p, end) (on the
 * host the text sits at the very end of a malloc block, so ASan sees any over-read; on the
 * device guard bytes follow it), *p moves only on success and stays within the text, and
 * the consumed prefix alone parses to the same value. */
static void real_parse_fuzz(void)
{
    static const char alpha[] = "0123456789+-.eEnaifx 9";
    uint32_t st = 4242u, i, fails = 0;
    uint8_t store[64 + 16];
    for (i = 0; i < N_RAND; i++) {
        uint32_t len = h_rand(&st) % 24u, j;
        char *b;
        const char *p;
        subd_real v = 0, v2 = 0;
        int rc;
#if H_HOST
        char *heap = (char *)malloc(len ? len : 1u);
        b = heap + (len ? 0 : 1); /* len 0: end == one past the block */
#else
        b = (char *)store + 64 - len;
        h_guard_fill(store + 64, 16);
#endif
        for (j = 0; j < len; j++) b[j] = alpha[h_rand(&st) % (sizeof alpha - 1u)];
        p = b;
        rc = subd_real_parse(&p, b + len, &v);
        if (rc == SUBD_OK) {
            const char *q = b;
            if (p <= b || p > b + len) fails++;
            else if (subd_real_parse(&q, p, &v2) != SUBD_OK || q != p ||
                     subd_real_bits(v2) != subd_real_bits(v))
                fails++;
        } else {
            if (p != b) fails++;
            if (rc != SUBD_ERR_PARSE && rc != SUBD_ERR_NAN && rc != SUBD_ERR_RANGE) fails++;
        }
#if H_HOST
        free(heap);
#else
        if (!h_guard_ok(store + 64, 16)) fails++;
#endif
    }
    (void)store;
    CHECK_EQ(fails, 0);
}

/* Formatting: fixed tables of expected text. */
static void real_format_table(void)
{
    static const struct { uint32_t bits; const char *s; } t[] = {
#if SUBD_FIXED
        {0, "0"}, {65536, "1"}, {(uint32_t)-32768, "-0.5"}, {196608, "3"},
        {1, "0.0000152587890625"}, {(uint32_t)-1, "-0.0000152587890625"},
        {0x80000000u, "-32768"}, {0x7fffffffu, "32767.9999847412109375"},
#else
        {0x3f800000u, "1"}, {0x3dcccccdu, "0.1"}, {0xbfa00000u, "-1.25"},
        {0x7149f2cau, "1e+30"}, {0x7149f2cbu, "1.0000001e+30"}, {0x80000000u, "-0"},
        {0x00000000u, "0"}, {0x7f7fffffu, "3.4028235e+38"}, {0x00000001u, "1e-45"},
        {0x00800000u, "1.1754944e-38"}, {0x3727c5acu, "1e-05"}, {0x38d1b717u, "0.0001"},
        {0x4cbebc20u, "100000000"}, {0x4e6e6b28u, "1e+09"}, {0x4ceb79a3u, "123456790"},
        {0x3e99999au, "0.3"}, {0x4b800000u, "16777216"}, {0xc7000000u, "-32768"},
        {0x7f800000u, "inf"}, {0xff800000u, "-inf"}, {0x7fc00000u, "nan"},
#endif
        {0, 0}
    };
    uint32_t i;
    for (i = 0; t[i].s; i++) {
        char buf[32];
        uint32_t n, k, want_n = slen(t[i].s);
        subd_real x;
#if SUBD_FIXED
        x = (subd_real)t[i].bits;
#else
        union { uint32_t u; float f; } c;
        c.u = t[i].bits;
        x = c.f;
#endif
        n = subd_real_format(x, buf);
        k = 0;
        if (n == want_n) for (k = 0; k < n && buf[k] == t[i].s[k]; k++) {}
        if (!CHECK(n == want_n && k == n)) {
            buf[n < 31u ? n : 31u] = 0;
            h_str("    got \"");
            h_str(buf);
            h_str("\" want \"");
            h_str(t[i].s);
            h_str("\"");
            h_nl();
        }
    }
}

/* format -> parse gives the same bits, for random bit patterns and the extremes; the text
 * fits 24 bytes. On the host also: strtof reads the same float and no shorter %.Ng
 * decimal reads back (the output is the shortest); Q16.16 text equals printf's exact
 * decimal of x / 65536. */
static void real_format_roundtrip(void)
{
    uint32_t st = 99u, i, fails = 0, longest = 0;
    for (i = 0; i < N_RAND + 64u; i++) {
        char buf[40];
        uint32_t n, bits, k;
        subd_real x, y = 0;
        const char *p;
        bits = h_rand(&st);
        if (i < 16u) bits = i;                         /* tiny values */
        else if (i < 32u) bits = 0x7f7ffff0u + (i - 16u); /* near FLT_MAX / INT32_MAX */
        else if (i < 48u) bits = 0x80000000u + (i - 32u);
        else if (i < 64u) bits = 0x007ffff8u + (i - 48u); /* subnormal/normal border */
        for (k = 0; k < sizeof buf; k++) buf[k] = '#';
#if SUBD_FIXED
        if (i >= 16u && i < 32u) bits = 0x7fffffffu - (i - 16u);
        x = (subd_real)bits;
#else
        {
            union { uint32_t u; float f; } c;
            if ((bits & 0x7f800000u) == 0x7f800000u) continue;
            c.u = bits;
            x = c.f;
        }
#endif
        n = subd_real_format(x, buf);
        if (n > longest) longest = n;
        for (k = n; k < sizeof buf; k++) if (buf[k] != '#') { fails++; break; }
        p = buf;
        if (n > 24u || subd_real_parse(&p, buf + n, &y) != SUBD_OK || p != buf + n ||
            subd_real_bits(y) != subd_real_bits(x)) {
            if (fails++ < 5u) { h_str("    bits "); h_hex32(bits); h_nl(); }
            continue;
        }
#if H_HOST
        buf[n] = 0;
#if SUBD_FIXED
        {
            char ref[64];
            int m = snprintf(ref, sizeof ref, "%.16f", (double)x / 65536.0);
            while (m > 0 && ref[m - 1] == '0') m--;
            if (m > 0 && ref[m - 1] == '.') m--;
            ref[m] = 0;
            if (strcmp(ref, buf) != 0 && fails++ < 5u) printf("    %s vs printf %s\n", buf, ref);
        }
#else
        {
            char ref[64];
            uint32_t sig = 0, started = 0, last = 0, d;
            if (fbits(strtof(buf, 0)) != bits && fails++ < 5u) printf("    strtof(%s)\n", buf);
            /* significant digits of our text */
            for (k = 0; k < n && buf[k] != 'e'; k++) {
                if (buf[k] >= '1' && buf[k] <= '9') started = 1;
                if (started && buf[k] >= '0' && buf[k] <= '9') { sig++; if (buf[k] != '0') last = sig; }
            }
            sig = last;
            if (sig > 9u && fails++ < 5u) printf("    too long: %s\n", buf);
            for (d = 1; d < sig; d++) {
                snprintf(ref, sizeof ref, "%.*g", (int)d, (double)x);
                if (fbits(strtof(ref, 0)) == bits) {
                    if (fails++ < 5u) printf("    not shortest: %s vs %s\n", buf, ref);
                    break;
                }
            }
        }
#endif
#endif
    }
    CHECK_EQ(fails, 0);
    CHECK(longest <= (SUBD_FIXED ? 23u : 15u)); /* the lengths subd_real.h promises */
}

#if SUBD_FIXED
/* A few exact Q16.16 decimals, independent of printf. */
static void real_format_fixed_exact(void)
{
    char buf[32];
    uint32_t n = subd_real_format((subd_real)80908635, buf), k;
    /* 80908635 / 65536 = 1234.5677947998046875 exactly */
    CHECK_EQ(n, 21);
    for (k = 0; k < 21u; k++) CHECK_EQ(buf[k], "1234.5677947998046875"[k]);
    n = subd_real_format((subd_real)(-98304), buf);
    CHECK_EQ(n, 4);
    CHECK(buf[0] == '-' && buf[1] == '1' && buf[2] == '.' && buf[3] == '5');
}
#endif

/* Bit patterns of a deterministic set of parse results and formatted texts: printed as
 * HASH lines that the Makefile compares between host and QEMU. */
static void real_hash(void)
{
    uint32_t st = 2024u, i, hp = 2166136261u, hf = 2166136261u;
    char b[80];
    for (i = 0; i < 2000u; i++) {
        uint32_t n = rand_decimal(&st, b, SUBD_FIXED ? -7 : -47, SUBD_FIXED ? 5 : 39), used, u;
        subd_real v = 0;
        int32_t rc = (int32_t)parse_str(b, &v, &used);
        u = subd_real_bits(v);
        hp = h_fnv(hp, &rc, 4);
        hp = h_fnv(hp, &u, 4);
        hp = h_fnv(hp, &used, 4);
        (void)n;
    }
    for (i = 0; i < 2000u; i++) {
        uint32_t bits = h_rand(&st), n;
        subd_real x;
#if SUBD_FIXED
        x = (subd_real)bits;
#else
        union { uint32_t u; float f; } c;
        c.u = bits;
        x = c.f;
#endif
        n = subd_real_format(x, b);
        hf = h_fnv(hf, b, n);
    }
    h_hash("real_parse", hp);
    h_hash("real_format", hf);
}

const test_case suite_real[] = {
    {"real_parse_edges", real_parse_edges},
#if !SUBD_FIXED
    {"real_parse_halfway_exact", real_parse_halfway_exact},
#endif
#if H_HOST && !SUBD_FIXED
    {"real_parse_vs_strtof", real_parse_vs_strtof},
#endif
#if SUBD_FIXED
    {"real_parse_fixed_ref", real_parse_fixed_ref},
    {"real_format_fixed_exact", real_format_fixed_exact},
#endif
    {"real_parse_fuzz", real_parse_fuzz},
    {"real_format_table", real_format_table},
    {"real_format_roundtrip", real_format_roundtrip},
    {"real_hash", real_hash},
    {0, 0}
};
