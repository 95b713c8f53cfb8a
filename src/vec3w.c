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
static void vec3w_scale(const subd_wide *n, subd_real *out)
{
    uint32_t k, len = subd_isqrt64((uint64_t)subd_w3_dot(n, n)); /* dot < 3 * 2^60 */
    for (k = 0; k < 3u; k++) {
        int64_t q = n[k] * 65536, h = (int64_t)(len / 2u);
        out[k] = len == 0u ? 0 : (subd_real)(q < 0 ? (q - h) / (int64_t)len : (q + h) / (int64_t)len);
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
    subd_w3_normalize(c, n, 30u);
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
