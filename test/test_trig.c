/* SPDX-License-Identifier: MIT */
/* Tests of the deterministic cos/sin of 2*pi*num/den (src/trig.c).
 *
 * Device-capable: exact values, symmetries that must hold bit for bit, monotonicity,
 * sin^2 + cos^2 = 1, the rounding of subd_real_from_q62, and output hashes. On the host the
 * results are compared with libm cos/sin in double (and cosl/sinl for the Q2.62 values). */
#include "harness.h"

#if H_HOST
#include <stdio.h>
#include <math.h>
#endif

#define Q62_ONE ((int64_t)1 << 62)
#define H_2PI 6.283185307179586476925286766559 /* 2 pi, host reference only */

static uint32_t rbits(subd_real x) { return subd_real_bits(x); }

static void trig_exact_values(void)
{
    uint32_t ovf = 0;
    subd_real one = SUBD_REAL_ONE, half = SUBD_REAL_FRAC(1, 2);
    subd_real mone = subd_neg(one, &ovf), mhalf = subd_neg(half, &ovf);
    CHECK_EQ(subd_cos_turns_q62(0, 1), Q62_ONE);
    CHECK_EQ(subd_sin_turns_q62(0, 1), 0);
    CHECK_EQ(subd_cos_turns_q62(1, 4), 0);
    CHECK_EQ(subd_sin_turns_q62(1, 4), Q62_ONE);
    CHECK_EQ(subd_cos_turns_q62(1, 2), -Q62_ONE);
    CHECK_EQ(subd_sin_turns_q62(1, 2), 0);
    CHECK_EQ(subd_sin_turns_q62(3, 4), -Q62_ONE);
    CHECK_EQ(subd_cos_turns_q62(1, 6), Q62_ONE / 2);
    CHECK_EQ(subd_sin_turns_q62(1, 12), Q62_ONE / 2);
    CHECK_EQ(subd_cos_turns_q62(1, 3), -Q62_ONE / 2);
    CHECK_EQ(subd_sin_turns_q62(5, 12), Q62_ONE / 2);
    CHECK_EQ(subd_sin_turns_q62(7, 12), -Q62_ONE / 2);
    CHECK_EQ(subd_cos_turns_q62(1, 8), subd_sin_turns_q62(1, 8));
    /* sqrt(1/2) in Q2.62, rounded: 0x2d413cccfe779921 (= round(2^61.5)) */
    CHECK_EQ(subd_cos_turns_q62(1, 8), (int64_t)0x2d413cccfe779921LL);

    CHECK_EQ(rbits(subd_cos_turns(0, 1)), rbits(one));
    CHECK_EQ(rbits(subd_cos_turns(5, 5)), rbits(one));
    CHECK_EQ(rbits(subd_cos_turns(1, 4)), 0u); /* +0, not -0 */
    CHECK_EQ(rbits(subd_cos_turns(3, 4)), 0u);
    CHECK_EQ(rbits(subd_sin_turns(1, 2)), 0u);
    CHECK_EQ(rbits(subd_sin_turns(-1, 2)), 0u);
    CHECK_EQ(rbits(subd_cos_turns(1, 2)), rbits(mone));
    CHECK_EQ(rbits(subd_sin_turns(1, 4)), rbits(one));
    CHECK_EQ(rbits(subd_cos_turns(1, 6)), rbits(half));
    CHECK_EQ(rbits(subd_cos_turns(-1, 6)), rbits(half));
    CHECK_EQ(rbits(subd_cos_turns(2, 6)), rbits(mhalf));
    CHECK_EQ(rbits(subd_sin_turns(1, 12)), rbits(half));
    CHECK_EQ(rbits(subd_sin_turns(-5, 12)), rbits(mhalf));
    /* extreme arguments: no overflow in the reduction */
    CHECK_EQ(subd_cos_turns_q62(INT32_MAX, INT32_MAX), Q62_ONE);
    CHECK_EQ(subd_cos_turns_q62(INT32_MIN, 1), Q62_ONE);
    CHECK_EQ(subd_cos_turns_q62(INT32_MIN, 2), Q62_ONE); /* -2^31 / 2 is a whole turn */
    CHECK_EQ(subd_cos_turns_q62(INT32_MIN, 4), Q62_ONE);
    CHECK_EQ(subd_sin_turns_q62(INT32_MIN + 1, 4), Q62_ONE); /* -2^31+1 = 1 mod 4 */
    CHECK_EQ(subd_cos_turns_q62(INT32_MIN, INT32_MAX), subd_cos_turns_q62(-1, INT32_MAX));
    /* den <= 0 is invalid: documented result 0 */
    CHECK_EQ(subd_cos_turns_q62(1, 0), 0);
    CHECK_EQ(subd_sin_turns_q62(1, -4), 0);
    CHECK_EQ(ovf, 0);
}

/* The rounding of Q2.62 to subd_real, on hand-made values. */
static void trig_from_q62(void)
{
#if SUBD_FIXED
    CHECK_EQ(subd_real_from_q62(Q62_ONE), 65536);
    CHECK_EQ(subd_real_from_q62((int64_t)1 << 45), 1);        /* half an LSB: away from 0 */
    CHECK_EQ(subd_real_from_q62(((int64_t)1 << 45) - 1), 0);
    CHECK_EQ(subd_real_from_q62(-((int64_t)1 << 45)), -1);
    CHECK_EQ(subd_real_from_q62(-((int64_t)1 << 45) + 1), 0);
    CHECK_EQ(subd_real_from_q62((int64_t)3 << 45), 2);
    CHECK_EQ(subd_real_from_q62(INT64_MIN), -131072);
    CHECK_EQ(subd_real_from_q62(INT64_MAX), 131072);
    CHECK_EQ(subd_real_from_q62(0), 0);
#else
    CHECK_EQ(rbits(subd_real_from_q62(0)), 0u);
    CHECK_EQ(rbits(subd_real_from_q62(1)), 0x20800000u);             /* 2^-62 */
    CHECK_EQ(rbits(subd_real_from_q62(-1)), 0xa0800000u);
    CHECK_EQ(rbits(subd_real_from_q62(Q62_ONE)), 0x3f800000u);
    CHECK_EQ(rbits(subd_real_from_q62(Q62_ONE + ((int64_t)1 << 38))), 0x3f800000u); /* tie: even */
    CHECK_EQ(rbits(subd_real_from_q62(Q62_ONE + ((int64_t)1 << 38) + 1)), 0x3f800001u);
    CHECK_EQ(rbits(subd_real_from_q62(Q62_ONE + ((int64_t)3 << 38))), 0x3f800002u); /* tie: even */
    CHECK_EQ(rbits(subd_real_from_q62(Q62_ONE - ((int64_t)1 << 38))), 0x3f7fffffu); /* 1 - 2^-24: exact */
    CHECK_EQ(rbits(subd_real_from_q62(Q62_ONE - ((int64_t)1 << 37))), 0x3f800000u); /* tie: even 1.0 */
    CHECK_EQ(rbits(subd_real_from_q62(Q62_ONE - ((int64_t)1 << 37) - 1)), 0x3f7fffffu);
    CHECK_EQ(rbits(subd_real_from_q62(INT64_MAX)), 0x40000000u);       /* rounds up to 2.0 */
    CHECK_EQ(rbits(subd_real_from_q62(INT64_MIN)), 0xc0000000u);       /* -2.0 exactly */
    CHECK_EQ(rbits(subd_real_from_q62(0xffffff)), 0x2c7fffffu);        /* (2^24-1) 2^-62: exact */
#endif
}

/* Symmetries that the exact integer range reduction makes bit-exact. */
static void trig_symmetry(void)
{
    uint32_t fails = 0;
    int32_t den, num;
    for (den = 1; den <= 64; den++) {
        for (num = -3 * den; num <= 3 * den; num++) {
            int64_t c = subd_cos_turns_q62(num, den), s = subd_sin_turns_q62(num, den);
            if (subd_cos_turns_q62(-num, den) != c) fails++;
            if (subd_sin_turns_q62(-num, den) != -s) fails++;
            if (subd_cos_turns_q62(num + den, den) != c) fails++;
            /* the same rational angle with another denominator */
            if (subd_cos_turns_q62(7 * num, 7 * den) != c) fails++;
            if (subd_sin_turns_q62(3 * num, 3 * den) != s) fails++;
            /* cos(1/2 - t) = -cos t, sin(1/4 - t) = cos t, cos(t + 1/4) = -sin t */
            if (subd_cos_turns_q62(den - 2 * num, 2 * den) != -c) fails++;
            if (subd_sin_turns_q62(den - 4 * num, 4 * den) != c) fails++;
            if (subd_cos_turns_q62(4 * num + den, 4 * den) != -s) fails++;
            if (rbits(subd_cos_turns(-num, den)) != rbits(subd_cos_turns(num, den))) fails++;
#if SUBD_FIXED
            if (subd_sin_turns(-num, den) != -subd_sin_turns(num, den)) fails++;
#else
            if (s != 0 && rbits(subd_sin_turns(-num, den)) != (rbits(subd_sin_turns(num, den)) ^ 0x80000000u))
                fails++;
#endif
            /* |values| <= 1 */
            if (c > Q62_ONE || c < -Q62_ONE || s > Q62_ONE || s < -Q62_ONE) fails++;
        }
    }
    CHECK_EQ(fails, 0);
}

/* cos strictly decreasing on [0, 1/2] turn and sin strictly increasing on [0, 1/4] turn,
 * through all octant folds; sin^2 + cos^2 = 1 within 2^-58. */
static void trig_monotone_pythagoras(void)
{
    static const int32_t dens[] = {360, 1000, 4096, 65537, 12345678};
    uint32_t fails = 0, i;
    for (i = 0; i < sizeof dens / sizeof dens[0]; i++) {
        int32_t den = dens[i], num, step = den > 5000 ? den / 4999 : 1;
        int64_t prev_c = subd_cos_turns_q62(0, den) + 1, prev_s = -1;
        for (num = 0; num <= den / 2; num += step) {
            int64_t c = subd_cos_turns_q62(num, den), s = subd_sin_turns_q62(num, den);
            int64_t cs = c >> 31, ss = s >> 31; /* Q31: squares fit int64 as Q62 */
            int64_t err = cs * cs + ss * ss - Q62_ONE;
            if (c >= prev_c) fails++;
            if (4 * (int64_t)num <= den && s <= prev_s) fails++;
            /* truncation to Q31 costs < 2 * 2^-30 in the sum; allow 2^-28 */
            if (err > ((int64_t)1 << 34) || err < -((int64_t)1 << 34)) fails++;
            prev_c = c;
            prev_s = s;
        }
    }
    CHECK_EQ(fails, 0);
#if !SUBD_FIXED
    {
        /* the same identity on the rounded float values: within a few float ulps */
        int32_t num;
        fails = 0;
        for (num = 0; num < 200; num++) {
            float c = subd_cos_turns(num, 200), s = subd_sin_turns(num, 200);
            float p = c * c, q = s * s, e = p + q - 1.0f;
            if (e > 4.0e-7f || e < -4.0e-7f) fails++;
        }
        CHECK_EQ(fails, 0);
    }
#endif
}

#if H_HOST
/* Against libm in double for every num/den with den 1..64, num -2den..3den and some huge
 * num: float within 1 ulp of the double reference (and counted: how many differ from the
 * double reference rounded to float), Q16.16 within 1 LSB, Q2.62 within 2^-48 of double
 * (double's own error near 2 pi is ~2^-51) and within 2^-59 of long double (measured
 * 2^-60.5, mostly the reference's error; against __float128 the error is 2^-61.8). The
 * reference angle is reduced exactly first (num mod den), since 2*pi*num/den in double
 * would lose bits for huge num. */
static void trig_vs_libm(void)
{
    uint32_t fails = 0, n = 0, not_cr = 0, k;
    int32_t den;
#if !SUBD_FIXED
    double max_ulp = 0.0;
#endif
    long double max_q62 = 0.0L;
    for (den = 1; den <= 64; den++) {
        for (k = 0; k < 5u * (uint32_t)den + 8u; k++) {
            int32_t num = k < 5u * (uint32_t)den ? (int32_t)k - 2 * den
                        : (int32_t)(k & 1u ? INT32_MAX - (int32_t)k : INT32_MIN + (int32_t)k);
            int32_t r = (int32_t)(((int64_t)num % den + den) % den);
            int w;
            for (w = 0; w < 2; w++) {
                double ref = w ? sin(H_2PI * r / den) : cos(H_2PI * r / den);
                long double angl = 2.0L * 3.14159265358979323846264338327950288L * r / den;
                long double refl = w ? sinl(angl) : cosl(angl);
                int64_t q = w ? subd_sin_turns_q62(num, den) : subd_cos_turns_q62(num, den);
                subd_real v = w ? subd_sin_turns(num, den) : subd_cos_turns(num, den);
                long double dq = fabsl((long double)q / 4611686018427387904.0L - refl);
                if (fabs(ref) < 1e-15) { ref = 0.0; refl = 0.0L; dq = fabsl((long double)q); }
                if (dq > max_q62) max_q62 = dq;
                if (dq > ldexpl(1.0L, -59)) fails++; /* long double reference: ~2^-61 */
                /* double's own error: 2*pi*r/den near 2*pi is off by ~2^-51 */
                if (fabs((double)q / 4611686018427387904.0 - ref) > ldexp(1.0, -48)) fails++;
                n++;
#if SUBD_FIXED
                if (fabs((double)v - ref * 65536.0) > 1.0) fails++;
                if ((double)v != floor(fabs(ref * 65536.0) + 0.5) * (ref < 0 ? -1.0 : 1.0)) not_cr++;
#else
                {
                    float cr = (float)ref;
                    double ulp = ref == 0.0 ? ldexp(1.0, -149)
                                            : (double)nextafterf(fabsf(cr), INFINITY) - (double)fabsf(cr);
                    double e = fabs((double)v - ref) / ulp;
                    if (e > max_ulp) max_ulp = e;
                    if (e > 1.0) fails++;
                    if (v != cr) not_cr++;
                }
#endif
            }
        }
    }
    printf("    %u values; %u differ from the double reference rounded once; max |q62 - cosl| = 2^%.1f",
           (unsigned)n, (unsigned)not_cr, (double)log2l(max_q62));
#if !SUBD_FIXED
    printf("; max error %.3f ulp", max_ulp);
#endif
    printf("\n");
    CHECK_EQ(fails, 0);
}

/* Random num and large den (up to 2^31 - 1) against long double. */
static void trig_vs_libm_large(void)
{
    uint32_t st = 31337u, i, fails = 0;
    long double max_q62 = 0.0L;
    for (i = 0; i < 200000u; i++) {
        int32_t den = (int32_t)(h_rand(&st) >> (1u + h_rand(&st) % 31u)), num = (int32_t)h_rand(&st);
        int32_t r;
        long double ang;
        int w;
        if (den <= 0) den = 1;
        r = (int32_t)(((int64_t)num % den + den) % den);
        ang = 2.0L * 3.14159265358979323846264338327950288L * r / den;
        for (w = 0; w < 2; w++) {
            long double ref = w ? sinl(ang) : cosl(ang);
            int64_t q = w ? subd_sin_turns_q62(num, den) : subd_cos_turns_q62(num, den);
            long double d = fabsl((long double)q / 4611686018427387904.0L - ref);
            if (d > max_q62) max_q62 = d;
            if (d > ldexpl(1.0L, -59)) fails++;
        }
    }
    printf("    random den < 2^31: max |q62 - long double| = 2^%.1f\n", (double)log2l(max_q62));
    CHECK_EQ(fails, 0);
}
#endif

/* Bits of a deterministic set of results: HASH lines compared between host and QEMU. */
static void trig_hash(void)
{
    uint32_t h = 2166136261u, hq = 2166136261u, st = 555u, i;
    int32_t den, num;
    for (den = 1; den <= 64; den++) {
        for (num = -den; num <= den; num++) {
            uint32_t c = rbits(subd_cos_turns(num, den)), s = rbits(subd_sin_turns(num, den));
            int64_t qc = subd_cos_turns_q62(num, den);
            h = h_fnv(h, &c, 4);
            h = h_fnv(h, &s, 4);
            hq = h_fnv(hq, &qc, 8);
        }
    }
    for (i = 0; i < 500u; i++) {
        int32_t d = (int32_t)(h_rand(&st) >> 1) | 1, n = (int32_t)h_rand(&st);
        int64_t qs = subd_sin_turns_q62(n, d);
        uint32_t c = rbits(subd_cos_turns(n, d));
        h = h_fnv(h, &c, 4);
        hq = h_fnv(hq, &qs, 8);
    }
    h_hash("trig_real", h);
    h_hash("trig_q62", hq);
}

const test_case suite_trig[] = {
    {"trig_exact_values", trig_exact_values},
    {"trig_from_q62", trig_from_q62},
    {"trig_symmetry", trig_symmetry},
    {"trig_monotone_pythagoras", trig_monotone_pythagoras},
#if H_HOST
    {"trig_vs_libm", trig_vs_libm},
    {"trig_vs_libm_large", trig_vs_libm_large},
#endif
    {"trig_hash", trig_hash},
    {0, 0}
};
