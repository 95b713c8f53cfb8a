/* SPDX-License-Identifier: MIT */
/* subd_w3_unit: the unit vector along a wide 3-vector (see vec3w.h for the contract). Out
 * of line because it needs the square roots of sqrt.c. loop_limit.c's limit normals use it
 * (it replaced that file's own lim_unit without changing a bit). */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "vec3w.h"

void subd_w3_unit(const subd_wide *c, subd_real *out)
{
    subd_wide n[3];
    uint32_t k;
    subd_w3_normalize(c, n, 30u);
#if SUBD_FIXED /* integer square root and rounded Q16.16 division; float32 uses subd_sqrt */
    {
        uint32_t len = subd_isqrt64((uint64_t)subd_w3_dot(n, n)); /* dot < 3 * 2^60 */
        for (k = 0; k < 3u; k++) {
            int64_t q = n[k] * 65536, h = (int64_t)(len / 2u);
            out[k] = len == 0u ? 0 : (subd_real)(q < 0 ? (q - h) / (int64_t)len : (q + h) / (int64_t)len);
        }
    }
#else
    {
        float len = subd_sqrt(subd_w3_dot(n, n));
        for (k = 0; k < 3u; k++) out[k] = len > 0.0f ? n[k] / len : 0.0f;
    }
#endif
}
