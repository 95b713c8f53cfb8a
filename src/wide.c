/* SPDX-License-Identifier: MIT */
/* Wide integer arithmetic: the out-of-line parts of wide.h (its header states every
 * contract). Integer code only, the same in both arithmetics. */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "wide.h"

uint64_t subd_u128_div(subd_u128 n, uint64_t d, uint64_t *rem)
{
    uint64_t q = 0, r = n.hi, lo = n.lo;
    uint32_t i;
    if (d >> 32 == 0u) {
        /* n < d 2^64 < 2^96: two 64/32-bit digit steps, each quotient digit < 2^32 */
        uint64_t x = (r << 32) | (lo >> 32), q1 = x / d;
        x = ((x % d) << 32) | (uint32_t)lo;
        *rem = x % d;
        return (q1 << 32) | (x / d);
    }
    /* restoring division, one quotient bit per step; r < d throughout, and the bit shifted
     * out of r (carry) means r >= 2^64 > d */
    for (i = 0; i < 64u; i++) {
        uint64_t carry = r >> 63;
        r = (r << 1) | (lo >> 63);
        lo <<= 1;
        q <<= 1;
        if (carry || r >= d) {
            r -= d;
            q |= 1u;
        }
    }
    *rem = r;
    return q;
}

uint32_t subd_f32_bits_from_scaled(int64_t q, uint32_t frac)
{
    uint64_t u = q < 0 ? 0u - (uint64_t)q : (uint64_t)q, rest, half, m;
    uint32_t p = 63u, sign = q < 0 ? 0x80000000u : 0u;
    if (u == 0u) return 0u;
    while (!((u >> p) & 1u)) p--;
    if (p > 23u) {
        uint32_t sh = p - 23u;
        rest = u & (((uint64_t)1 << sh) - 1u);
        half = (uint64_t)1 << (sh - 1u);
        m = u >> sh;
        if (rest > half || (rest == half && (m & 1u))) m++;
        if (m == ((uint64_t)1 << 24)) { /* rounded up to the next binade */
            m >>= 1;
            p++;
        }
    } else {
        m = u << (23u - p);
    }
    /* value = m 2^(p - 23 - frac) with m in [2^23, 2^24): biased exponent p - frac + 127 */
    return sign | ((p + 127u - frac) << 23) | ((uint32_t)m & 0x7fffffu);
}

uint64_t subd_gcd64(int64_t a, int64_t b)
{
    uint64_t x = a < 0 ? 0u - (uint64_t)a : (uint64_t)a, y = b < 0 ? 0u - (uint64_t)b : (uint64_t)b;
    while (y != 0u) {
        uint64_t r = x % y;
        x = y;
        y = r;
    }
    return x;
}
