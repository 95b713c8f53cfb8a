/* SPDX-License-Identifier: MIT */
/* Host-only conversions between subd_real and double (tool, tests, benchmarks). Never used
 * by src/: the core does not touch double. */
#ifndef HOST_REAL_H
#define HOST_REAL_H
#include "subd_real.h"

static inline double host_real_to_double(subd_real r)
{
#if SUBD_FIXED
    return (double)r / 65536.0;
#else
    return (double)r;
#endif
}

static inline subd_real host_real_from_double(double d)
{
#if SUBD_FIXED
    double s = d * 65536.0;
    return (subd_real)(s < 0 ? s - 0.5 : s + 0.5);
#else
    return (subd_real)d;
#endif
}
#endif
