/* SPDX-License-Identifier: MIT */
/* subd_real_format: a subd_real as the shortest decimal text that reads back to the same bits,
 * in 32/64-bit integer arithmetic only (no libm, no stdio, no heap, no 128-bit type), so the
 * bytes are the same on a PC and on a Cortex-M.
 *
 * Float32: the digit search of Ulf Adams, "Ryu: fast float-to-string conversion" (PLDI 2018),
 * section 3, written for float32. With the significand m2 and exponent e2 scaled by 4 (so the
 * half-gaps to the neighbouring floats are integers), the value v = mv 2^e2, the upper bound
 * mp 2^e2 and the lower bound mm 2^e2 (mm is closer at the bottom of a binade) are multiplied by
 * 10^-e10 with one 32x64-bit product each against a table entry of 5^+-i, giving the exact
 * floors vr, vp, vm (Ryu's lemma: 59 / 61 table bits suffice for every 24-bit significand).
 * Then decimal digits are removed while the interval (vm, vp] still holds a shorter number,
 * and the last removed digit rounds the result. The choices, made to give the bytes of the
 * exact bignum method (Steele & White / Burger & Dybvig free format) this replaced and that
 * test/ref_format.h keeps as the reference:
 *   - the rounding interval is closed when m2 is even, open when odd (a correctly rounded
 *     reader sends a tie to the even significand); exact bounds are detected by divisibility
 *     (vm_exact, and vp moved inside when the open bound is exact);
 *   - among the shortest candidates the closest to v wins, and an exact tie rounds UP (the
 *     reference compares 2r >= s). Ryu rounds such ties to even; here they go up, which is
 *     why Ryu's "vr is trailing zeros" bookkeeping is not needed.
 * Tables (generated, Python 3, exact integers; bitlen = int.bit_length):
 *   k_pow5_inv[i] = (1 << (bitlen(5**i) - 1 + 59)) // 5**i + 1          i = 0..30
 *   k_pow5[i]     = 5**i >> (bitlen(5**i) - 61)  (<< when negative)      i = 0..47
 * A wrong entry shows as a mismatch against test/ref_format.h: make test samples every
 * exponent, make check-format-exhaustive every bit pattern.
 * Text layout (unchanged): positional for decimal exponents -4..8 ("0.0001", "123456790"),
 * else d.ddde+XX with a sign and at least two exponent digits ("1e-05", "3.4028235e+38");
 * "-0" for negative zero, "inf", "-inf", and "nan" for every NaN (no sign).
 *
 * Q16.16: the exact value x / 65536 (at most 16 fraction digits), trailing zeros removed.
 *
 * Stack: about 120 bytes (Cortex-M4F, -fstack-usage); every loop is bounded by the digit
 * count (at most 10 removals, 11 divisions by 5, 16 fraction digits).
 */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "text.h" /* subd_q16_format */

/* Two ASCII digits of 0..99, for writing numbers two digits per step. */
static const char k_digits2[200] = {
    '0','0','0','1','0','2','0','3','0','4','0','5','0','6','0','7','0','8','0','9',
    '1','0','1','1','1','2','1','3','1','4','1','5','1','6','1','7','1','8','1','9',
    '2','0','2','1','2','2','2','3','2','4','2','5','2','6','2','7','2','8','2','9',
    '3','0','3','1','3','2','3','3','3','4','3','5','3','6','3','7','3','8','3','9',
    '4','0','4','1','4','2','4','3','4','4','4','5','4','6','4','7','4','8','4','9',
    '5','0','5','1','5','2','5','3','5','4','5','5','5','6','5','7','5','8','5','9',
    '6','0','6','1','6','2','6','3','6','4','6','5','6','6','6','7','6','8','6','9',
    '7','0','7','1','7','2','7','3','7','4','7','5','7','6','7','7','7','8','7','9',
    '8','0','8','1','8','2','8','3','8','4','8','5','8','6','8','7','8','8','8','9',
    '9','0','9','1','9','2','9','3','9','4','9','5','9','6','9','7','9','8','9','9'
};

/* Writes the decimal digits of v (exactly nd of them, nd = its digit count) at buf. */
static void put_digits(char *buf, uint32_t v, uint32_t nd)
{
    char *p = buf + nd;
    while (v >= 100u) {
        uint32_t r = v % 100u;
        v /= 100u;
        p -= 2;
        p[0] = k_digits2[2u * r];
        p[1] = k_digits2[2u * r + 1u];
    }
    if (v >= 10u) {
        p -= 2;
        p[0] = k_digits2[2u * v];
        p[1] = k_digits2[2u * v + 1u];
    } else {
        p[-1] = (char)('0' + v);
    }
}

static uint32_t digit_count(uint32_t v)
{
    uint32_t n = 1;
    while (v >= 10u) { v /= 10u; n++; }
    return n;
}

/* Q16.16 text of x / 65536 (src/text.h). Compiled in both builds: int32 arithmetic only, and
 * the float build's benchmark and tests measure it too (a device image drops it unused). */
uint32_t subd_q16_format(int32_t x, char *buf)
{
    uint32_t n = 0, u, ip, frac, nd;
    if (x < 0) { buf[n++] = '-'; u = 0u - (uint32_t)x; } else u = (uint32_t)x;
    ip = u >> 16;
    frac = u & 0xffffu;
    nd = digit_count(ip);
    put_digits(buf + n, ip, nd);
    n += nd;
    if (frac) {
        buf[n++] = '.';
        /* frac / 65536 = digits of frac * 10^k / 65536; terminates within 16 digits. Two
         * digits per step (frac * 100 < 2^23); the second is dropped when it is the last
         * and zero. */
        while (frac) {
            uint32_t d;
            frac *= 100u;
            d = frac >> 16;
            frac &= 0xffffu;
            buf[n++] = k_digits2[2u * d];
            if (!frac && k_digits2[2u * d + 1u] == '0') break;
            buf[n++] = k_digits2[2u * d + 1u];
        }
    }
    return n;
}

#if SUBD_FIXED

uint32_t subd_real_format(subd_real x, char *buf)
{
    return subd_q16_format(x, buf);
}

#else

static const uint64_t k_pow5_inv[31] = {
    0x0800000000000001u, 0x0666666666666667u, 0x051eb851eb851eb9u,
    0x04189374bc6a7efau, 0x068db8bac710cb2au, 0x053e2d6238da3c22u,
    0x0431bde82d7b634eu, 0x06b5fca6af2bd216u, 0x055e63b88c230e78u,
    0x044b82fa09b5a52du, 0x06df37f675ef6eaeu, 0x057f5ff85e592558u,
    0x0465e6604b7a8447u, 0x0709709a125da071u, 0x05a126e1a84ae6c1u,
    0x0480ebe7b9d58567u, 0x0734aca5f6226f0bu, 0x05c3bd5191b525a3u,
    0x049c97747490eae9u, 0x0760f253edb4ab0eu, 0x05e72843249088d8u,
    0x04b8ed0283a6d3e0u, 0x078e480405d7b966u, 0x060b6cd004ac9452u,
    0x04d5f0a66a23a9dbu, 0x07bcb43d769f762bu, 0x063090312bb2c4efu,
    0x04f3a68dbc8f03f3u, 0x07ec3daf94180651u, 0x065697bfa9acd1dau,
    0x051212ffbaf0a7e2u,
};

static const uint64_t k_pow5[48] = {
    0x1000000000000000u, 0x1400000000000000u, 0x1900000000000000u,
    0x1f40000000000000u, 0x1388000000000000u, 0x186a000000000000u,
    0x1e84800000000000u, 0x1312d00000000000u, 0x17d7840000000000u,
    0x1dcd650000000000u, 0x12a05f2000000000u, 0x174876e800000000u,
    0x1d1a94a200000000u, 0x12309ce540000000u, 0x16bcc41e90000000u,
    0x1c6bf52634000000u, 0x11c37937e0800000u, 0x16345785d8a00000u,
    0x1bc16d674ec80000u, 0x1158e460913d0000u, 0x15af1d78b58c4000u,
    0x1b1ae4d6e2ef5000u, 0x10f0cf064dd59200u, 0x152d02c7e14af680u,
    0x1a784379d99db420u, 0x108b2a2c28029094u, 0x14adf4b7320334b9u,
    0x19d971e4fe8401e7u, 0x1027e72f1f128130u, 0x1431e0fae6d7217cu,
    0x193e5939a08ce9dbu, 0x1f8def8808b02452u, 0x13b8b5b5056e16b3u,
    0x18a6e32246c99c60u, 0x1ed09bead87c0378u, 0x13426172c74d822bu,
    0x1812f9cf7920e2b6u, 0x1e17b84357691b64u, 0x12ced32a16a1b11eu,
    0x178287f49c4a1d66u, 0x1d6329f1c35ca4bfu, 0x125dfa371a19e6f7u,
    0x16f578c4e0a060b5u, 0x1cb2d6f618c878e3u, 0x11efc659cf7d4b8du,
    0x166bb7f0435c9e71u, 0x1c06a5ec5433c60du, 0x118427b3b4a05bc8u,
};

/* floor(log2 5^e) + 1 for 1 <= e <= 3528 (and 1 for e = 0): the bit length of 5^e. */
static int32_t pow5bits(int32_t e)
{
    return (int32_t)((((uint32_t)e * 1217359u) >> 19) + 1u);
}

/* floor(log10 2^e), 0 <= e <= 1650. */
static int32_t log10_pow2(int32_t e)
{
    return (int32_t)(((uint32_t)e * 78913u) >> 18);
}

/* floor(log10 5^e), 0 <= e <= 2620. */
static int32_t log10_pow5(int32_t e)
{
    return (int32_t)(((uint32_t)e * 732923u) >> 20);
}

/* floor(m * factor / 2^shift) for 32 < shift, from two 32x32->64 products (the low 32 bits
 * of m * factor_lo only feed a carry Ryu's bound shows is never needed). */
static uint32_t mul_shift(uint32_t m, uint64_t factor, int32_t shift)
{
    uint64_t lo = (uint64_t)m * (uint32_t)factor;
    uint64_t hi = (uint64_t)m * (uint32_t)(factor >> 32);
    return (uint32_t)(((lo >> 32) + hi) >> (uint32_t)(shift - 32));
}

/* 1 when 5^p divides v (v != 0). */
static int multiple_of_pow5(uint32_t v, int32_t p)
{
    int32_t c = 0;
    while (v % 5u == 0u) { v /= 5u; c++; }
    return c >= p;
}

/* Shortest digits of the positive finite non-zero float with these bits (sign cleared):
 * value = *digits * 10^*e10. */
static uint32_t shortest(uint32_t bits, int32_t *e10out)
{
    uint32_t mant = bits & 0x7fffffu, ex = bits >> 23, m2, mv, mp, mm, vr, vp, vm, last = 0, out;
    uint32_t mm_shift = (mant != 0u || ex <= 1u) ? 1u : 0u;
    int32_t e2, e10, q, removed = 0;
    int even, vm_exact = 0;
    if (ex == 0u) { e2 = 1 - 127 - 23 - 2; m2 = mant; }
    else { e2 = (int32_t)ex - 127 - 23 - 2; m2 = mant | 0x800000u; }
    even = (m2 & 1u) == 0u;
    mv = 4u * m2;
    mp = mv + 2u;
    mm = mv - 1u - mm_shift;
    if (e2 >= 0) {
        /* v * 10^-q with q = floor(e2 log10 2): divide by 5^q (times 2^k), shift by i */
        int32_t k, i;
        q = log10_pow2(e2);
        e10 = q;
        k = 59 + pow5bits(q) - 1;
        i = -e2 + q + k;
        vr = mul_shift(mv, k_pow5_inv[q], i);
        vp = mul_shift(mp, k_pow5_inv[q], i);
        vm = mul_shift(mm, k_pow5_inv[q], i);
        if (q != 0 && (vp - 1u) / 10u <= vm / 10u) {
            /* no digit will be removed below, but the rounding needs the next one */
            int32_t l = 59 + pow5bits(q - 1) - 1;
            last = mul_shift(mv, k_pow5_inv[q - 1], -e2 + q - 1 + l) % 10u;
        }
        /* A bound is exact when 5^q divides it (2^q divides, as e2 >= q). 5^11 > 4 * 2^24,
         * so from q = 11 on nothing divides. When mv is a multiple of 5, mm and mp are not. */
        if (q <= 10 && mv % 5u != 0u) {
            if (even) vm_exact = multiple_of_pow5(mm, q);
            else vp -= (uint32_t)multiple_of_pow5(mp, q); /* the open bound is excluded */
        }
    } else {
        /* v * 10^-e10 with e10 = q + e2 < 0: multiply by 5^i, shift by j */
        int32_t i, k, j;
        q = log10_pow5(-e2);
        e10 = q + e2;
        i = -e2 - q;
        k = pow5bits(i) - 61;
        j = q - k;
        vr = mul_shift(mv, k_pow5[i], j);
        vp = mul_shift(mp, k_pow5[i], j);
        vm = mul_shift(mm, k_pow5[i], j);
        if (q != 0 && (vp - 1u) / 10u <= vm / 10u) {
            j = q - 1 - (pow5bits(i + 1) - 61);
            last = mul_shift(mv, k_pow5[i + 1], j) % 10u;
        }
        /* The bounds are exact when 2^q divides them: mp = 4 m2 + 2 and mm = 4 m2 - 2 are
         * multiples of 2 but not 4, mm = 4 m2 - 1 is odd. */
        if (q <= 1) {
            if (even) vm_exact = (int)mm_shift;
            else vp--;
        }
    }
    if (vm_exact) {
        /* rare: the closed lower bound itself may be the shortest */
        while (vp / 10u > vm / 10u) {
            vm_exact &= vm % 10u == 0u;
            last = vr % 10u;
            vr /= 10u; vp /= 10u; vm /= 10u;
            removed++;
        }
        if (vm_exact)
            while (vm % 10u == 0u) {
                last = vr % 10u;
                vr /= 10u; vp /= 10u; vm /= 10u;
                removed++;
            }
        out = vr + (uint32_t)((vr == vm && !vm_exact) || last >= 5u);
    } else {
        while (vp / 10u > vm / 10u) {
            last = vr % 10u;
            vr /= 10u; vp /= 10u; vm /= 10u;
            removed++;
        }
        out = vr + (uint32_t)(vr == vm || last >= 5u);
    }
    *e10out = e10 + removed;
    return out;
}

uint32_t subd_real_format(subd_real x, char *buf)
{
    union { float f; uint32_t u; } c;
    uint32_t bits, n = 0, nd, dv, i;
    int32_t e10, xp;
    char dig[10];
    c.f = x;
    bits = c.u;
    if (bits >> 31) { buf[n++] = '-'; bits &= 0x7fffffffu; }
    if (bits > 0x7f800000u) { buf[0] = 'n'; buf[1] = 'a'; buf[2] = 'n'; return 3; }
    if (bits == 0x7f800000u) { buf[n] = 'i'; buf[n + 1u] = 'n'; buf[n + 2u] = 'f'; return n + 3u; }
    if (bits == 0u) { buf[n++] = '0'; return n; }
    dv = shortest(bits, &e10);
    nd = digit_count(dv);
    xp = e10 + (int32_t)nd - 1; /* value = d.ddd * 10^xp */
    if (xp >= -4 && xp < 9) {
        /* positional, like %g */
        if (xp < 0) {
            buf[n++] = '0';
            buf[n++] = '.';
            for (i = 0; i < (uint32_t)(-xp - 1); i++) buf[n++] = '0';
            put_digits(buf + n, dv, nd);
            n += nd;
        } else {
            uint32_t ip = (uint32_t)xp + 1u; /* digits before the point */
            if (nd <= ip) {
                put_digits(buf + n, dv, nd);
                n += nd;
                for (i = nd; i < ip; i++) buf[n++] = '0';
            } else {
                put_digits(dig, dv, nd);
                for (i = 0; i < ip; i++) buf[n++] = dig[i];
                buf[n++] = '.';
                for (; i < nd; i++) buf[n++] = dig[i];
            }
        }
    } else {
        uint32_t ax = (uint32_t)(xp < 0 ? -xp : xp);
        put_digits(dig, dv, nd);
        buf[n++] = dig[0];
        if (nd > 1u) {
            buf[n++] = '.';
            for (i = 1; i < nd; i++) buf[n++] = dig[i];
        }
        buf[n++] = 'e';
        buf[n++] = xp < 0 ? '-' : '+';
        /* |xp| <= 45 */
        buf[n++] = k_digits2[2u * ax];
        buf[n++] = k_digits2[2u * ax + 1u];
    }
    return n;
}

#endif
