/* SPDX-License-Identifier: MIT */
/* subd_w3_unit: the unit vector along a wide 3-vector, and subd_w3_dist2 / subd_w3_dist_root:
 * a squared distance and its root (see vec3w.h for the contracts). Out of line because they
 * need the square roots of sqrt.c. loop_limit.c's limit normals use subd_w3_unit (it replaced
 * that file's own lim_unit without changing a bit); PIA's error measure uses the distance
 * (moved from pia.c without changing a bit). */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "vec3w.h"

#if SUBD_FIXED /* integer square roots, exact 64-bit squares, rounded Q16.16 division; float32
                * uses subd_sqrt, products rounded one at a time and plain sums */
/* floor(a / l) for a < 2^47 and 2^29 <= l < 2^31 with two 32-bit divisions (a 64-bit one is
 * a library call of about eighty instructions on a Cortex-M3): each step divides by a
 * divisor rounded up, so it never undershoots the remainder; the first leaves one below
 * 18 l (a / l < 2^18 and (l >> 15) + 1 overstates l / 2^15 by at most 2^-14 of it: a
 * deficit below 2^18 2^-14 + 2), so r >> 4 < 2^32; the second leaves one below 2 l, and
 * the loop takes the last step. */
static uint32_t vec3w_div47(uint64_t a, uint32_t l)
{
    uint32_t q = (uint32_t)(a >> 15) / ((l >> 15) + 1u), q2;
    uint64_t r = a - (uint64_t)q * l;
    q2 = (uint32_t)(r >> 4) / ((l >> 4) + 1u);
    r -= (uint64_t)q2 * l;
    q += q2;
    while (r >= l) {
        r -= l;
        q++;
    }
    return q;
}

/* out = n / |n| rounded to nearest, ties away from zero: (|q| + len/2) / len with the sign of
 * q = n * 2^16, as C's truncating division of q +- len/2 gives. n from
 * subd_w3_normalize(., ., 30): the largest |n_k| in [2^29, 2^30), so len in [2^29, 2^31)
 * and |q| + len/2 < 2^47 (vec3w_div47's range); n = 0 gives len = 0 and out = 0. */
static void vec3w_scale(const subd_wide *n, subd_real *out)
{
    uint32_t k, len = subd_isqrt64((uint64_t)subd_w3_dot(n, n)); /* dot < 3 * 2^60 */
    for (k = 0; k < 3u; k++) {
        int64_t q = n[k] * 65536;
        uint32_t m = len == 0u ? 0u : vec3w_div47((q < 0 ? 0u - (uint64_t)q : (uint64_t)q) + len / 2u, len);
        out[k] = q < 0 ? -(subd_real)m : (subd_real)m;
    }
}

static subd_dist_sq vec3w_sq(subd_real x)
{
    int64_t r = x; /* |r| <= 2^31 after subd_sub's saturation */
    return (uint64_t)(r * r);
}

static void vec3w_sum_check(subd_dist_sq s, uint32_t *ovf)
{
    (void)s; /* exact: cannot overflow */
    (void)ovf;
}

static subd_real vec3w_root(subd_dist_sq s, uint32_t *ovf)
{
    uint32_t r = subd_isqrt64(s);
    if (r > (uint32_t)INT32_MAX) {
        *ovf |= 1u;
        return INT32_MAX;
    }
    return (subd_real)r;
}
#else
static void vec3w_scale(const subd_wide *n, subd_real *out)
{
    float len = subd_sqrt(subd_w3_dot(n, n));
    if (len > 0.0f) { /* written out: as subd_w3_normalize */
        out[0] = n[0] / len;
        out[1] = n[1] / len;
        out[2] = n[2] / len;
    } else {
        out[0] = out[1] = out[2] = 0.0f;
    }
}

static subd_dist_sq vec3w_sq(subd_real x) { return x * x; }

static void vec3w_sum_check(subd_dist_sq s, uint32_t *ovf) { (void)subd_chk(s, ovf); }

static subd_real vec3w_root(subd_dist_sq s, uint32_t *ovf)
{
    (void)ovf;
    return subd_sqrt(s);
}
#endif

void subd_w3_unit(const subd_wide *c, subd_real *out)
{
    subd_wide n[3];
    subd_w3_normalize_shr(c, n, 30u);
    vec3w_scale(n, out);
}

subd_dist_sq subd_w3_dist2(const subd_real *p, const subd_real *q, uint32_t *ovf)
{
    subd_dist_sq s = 0;
    uint32_t k;
    for (k = 0; k < 3u; k++) {
        subd_dist_sq r2 = vec3w_sq(subd_sub(p[k], q[k], ovf));
        s = s + r2;
    }
    vec3w_sum_check(s, ovf);
    return s;
}

subd_real subd_w3_dist_root(subd_dist_sq s, uint32_t *ovf) { return vec3w_root(s, ovf); }
