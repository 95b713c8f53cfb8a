/* SPDX-License-Identifier: MIT */
/* Private interface of the alpha-subdivision files (alpha_kernel.c, alpha_curve.c,
 * alpha_surface.c, alpha_tags.c, alpha_stream.c, alpha_chord.c): exact integer helpers, the
 * kernel in Q32.32, the weight type, the parameter-tag rules and the curve stream's chord
 * test.
 *
 * Weights are computed in Q32.32 integers (int64, value * 2^32) from the kernel value and
 * then kept as subd_alpha_wt: a float in the float build (rounded once, correctly), the
 * Q32.32 integer itself in the fixed build, where a product weight * coordinate is formed
 * exactly in 128 bits and rounded once to Q16.16. That keeps the Q16.16 weights' own error
 * (2^-17 for a Q16.16 weight, i.e. up to edge length * 2^-17) out of the positions.
 */
#ifndef SUBD_ALPHA_INTERNAL_H
#define SUBD_ALPHA_INTERNAL_H
#include "subd_alpha.h"
#include "mesh_internal.h"
#include "real_avg.h" /* subd_mid_of_sum_even */

#define SUBD_Q32_ONE ((int64_t)1 << 32)

/* round(a * b / 2^shift), shift in 1..63, half away from zero; sets *ovf when the result
 * does not fit int64. */
int64_t subd_alpha_mulq(int64_t a, int64_t b, uint32_t shift, uint32_t *ovf);
/* round(a * 2^shift / b), shift in 0..63, b != 0, half away from zero; *ovf on overflow. */
int64_t subd_alpha_divq(int64_t a, int64_t b, uint32_t shift, uint32_t *ovf);
/* Q32.32 -> subd_real (float: correctly rounded to nearest even; fixed: half up, saturated
 * with *ovf). */
subd_real subd_alpha_q32_to_real(int64_t q, uint32_t *ovf);
/* subd_real -> Q32.32 (float: rounded to nearest, *ovf when |x| >= 2^31 or not finite). */
int64_t subd_alpha_real_to_q32(subd_real x, uint32_t *ovf);

/* Kernel value f(alpha; n) = s g(2^-(n+1) alpha), alpha = 2 pi num / den, in Q32.32.
 * Returns SUBD_OK, SUBD_ERR_PARAM or SUBD_ERR_RANGE (see subd_alpha_kernel_value). */
int subd_alpha_kernel_q32(uint32_t kernel, int32_t num, int32_t den, uint32_t level, int64_t s_q32,
                          int64_t *f_q32);

/* The kernel value of one alpha numerator, cached (one home for alpha_curve.c's edge weights
 * and alpha_surface.c's formula (3) weights): with no tags, or equal ones, the kernel runs
 * once per level. subd_alpha_kcache_get gives f = subd_alpha_kernel_q32(o->kernel, num, den,
 * level, s_q32) and checks 1 + f > 0, which every weight dividing by 1 + f needs
 * (SUBD_ERR_PARAM otherwise; the kernel's own errors as they come); it runs the kernel only
 * when num differs from the cached numerator, and then sets *fresh = 1 (the caller's weights
 * derived from f are stale), else *fresh = 0 and *f is the cached value. Reset the cache
 * whenever level, den or s_q32 change. */
typedef struct subd_alpha_kcache {
    int64_t num; /* INT64_MIN: nothing cached */
    int64_t f;
} subd_alpha_kcache;
static inline void subd_alpha_kcache_reset(subd_alpha_kcache *c) { c->num = INT64_MIN; }
int subd_alpha_kcache_get(subd_alpha_kcache *c, const subd_alpha_opts *o, int64_t num, int32_t den, uint32_t level,
                          int64_t s_q32, int64_t *f, int *fresh);

/* Common option checks (order <= max_order, levels, kernel, den, num, stiffness); *s_q32
 * receives the stiffness. */
int subd_alpha_check_opts(const subd_alpha_opts *o, uint32_t max_order, int64_t *s_q32);
/* Table 1 / theorems 1-2: -1 for s <= 0, 0 for s <= 1/2, else smooth_class. */
int32_t subd_alpha_continuity(int64_t s_q32, int32_t smooth_class);

/* Parameter tags (alpha_tags.c; the rule is the table in subd_alpha.h). Tags are alpha
 * numerators over the options' alpha_den. vertex_tags != 0: t has one tag per vertex of m,
 * else one per face. */
/* floor(sum / n), n >= 1: the arithmetic mean of n tags, in whole units of 1/den turn. */
int32_t subd_alpha_tag_mean(int64_t sum, uint32_t n);
/* The alpha numerator formula (3) uses on face f: its tag, or the mean of its corners'. */
int32_t subd_alpha_face_num(const subd_mesh *m, int vertex_tags, const int32_t *t, uint32_t f);
/* The face tags of the Doo-Sabin type step's output (its face order) into out. */
void subd_alpha_tags_s2(const subd_mesh *m, int vertex_tags, const int32_t *t, int32_t *out);
/* The dual step C's output tags into out: vertex tags from face tags, face tags from vertex
 * tags (C's vertex and face order). */
void subd_alpha_tags_dual(const subd_mesh *m, int vertex_tags, const int32_t *t, int32_t *out);

#if SUBD_FIXED /* the weight type differs: Q32.32 integers, products formed in 128 bits (see above) */
typedef int64_t subd_alpha_wt;
static inline subd_alpha_wt subd_alpha_wt_from_q32(int64_t q, uint32_t *ovf) { (void)ovf; return q; }
/* a + w (b - a), rounded once. */
static inline subd_real subd_alpha_lerp(subd_real a, subd_real b, subd_alpha_wt w, uint32_t *ovf)
{
    int64_t d = subd_alpha_mulq((int64_t)b - a, w, 32, ovf);
    if (d > INT32_MAX || d < -(int64_t)INT32_MAX) { *ovf |= 1u; return a; }
    return subd_real_sat((int64_t)a + d, ovf);
}
/* c + wa * da + wb * db, with da, db differences of subd_reals (exact in int64 here). */
static inline subd_real subd_alpha_comb(subd_real c, subd_alpha_wt wa, int64_t da, subd_alpha_wt wb, int64_t db,
                                        uint32_t *ovf)
{
    int64_t x = subd_alpha_mulq(da, wa, 16, ovf), y = subd_alpha_mulq(db, wb, 16, ovf);
    int64_t s;
    if (x > ((int64_t)1 << 60) || x < -((int64_t)1 << 60) || y > ((int64_t)1 << 60) || y < -((int64_t)1 << 60)) {
        *ovf |= 1u;
        return c;
    }
    s = x + y; /* Q32 */
    return subd_real_sat((int64_t)c + ((s + ((int64_t)1 << 15)) >> 16), ovf);
}
typedef int64_t subd_alpha_diff;
static inline subd_alpha_diff subd_alpha_sub(subd_real a, subd_real b, uint32_t *ovf)
{
    (void)ovf;
    return (int64_t)a - b;
}
static inline subd_alpha_diff subd_alpha_dadd(subd_alpha_diff a, subd_alpha_diff b, uint32_t *ovf)
{
    (void)ovf;
    return a + b;
}
#else
typedef float subd_alpha_wt;
static inline subd_alpha_wt subd_alpha_wt_from_q32(int64_t q, uint32_t *ovf) { return subd_alpha_q32_to_real(q, ovf); }
static inline subd_real subd_alpha_lerp(subd_real a, subd_real b, subd_alpha_wt w, uint32_t *ovf)
{
    subd_real d = subd_sub(b, a, ovf);
    return subd_add(a, subd_mul(w, d, ovf), ovf);
}
static inline subd_real subd_alpha_comb(subd_real c, subd_alpha_wt wa, float da, subd_alpha_wt wb, float db,
                                        uint32_t *ovf)
{
    subd_real x = subd_mul(wa, da, ovf), y = subd_mul(wb, db, ovf);
    return subd_add(c, subd_add(x, y, ovf), ovf);
}
typedef float subd_alpha_diff;
static inline subd_alpha_diff subd_alpha_sub(subd_real a, subd_real b, uint32_t *ovf) { return subd_sub(a, b, ovf); }
static inline subd_alpha_diff subd_alpha_dadd(subd_alpha_diff a, subd_alpha_diff b, uint32_t *ovf)
{
    return subd_add(a, b, ovf);
}
#endif


/* ------------------------------------------------------------------------------------ */
/* The curve rules on points, one home for the materialising call (alpha_curve.c) and the
 * stream (alpha_stream.c), so both compute every point with the same operations. */

/* out = lerp(a, b, w) per coordinate (out may alias a or b: the three are read first). */
static inline void subd_alpha_lerp3(subd_real *out, const subd_real *a, const subd_real *b, subd_alpha_wt w,
                                    uint32_t *ovf)
{
    subd_real x = subd_alpha_lerp(a[0], b[0], w, ovf), y = subd_alpha_lerp(a[1], b[1], w, ovf);
    subd_real z = subd_alpha_lerp(a[2], b[2], w, ovf);
    out[0] = x;
    out[1] = y;
    out[2] = z;
}

/* (a + b) / 2, the averaging operator C. Q16.16: ties to even, not the scalar layer's
 * ties-up, because C runs many times per level and a one-sided rounding would drift the whole
 * curve by 1/4 LSB per step (measured: 12 C steps moved a C-curve circle by 3 LSB). Float:
 * one rounding. */
static inline void subd_alpha_mid3(subd_real *out, const subd_real *a, const subd_real *b, uint32_t *ovf)
{
    uint32_t i;
    for (i = 0; i < 3u; i++) out[i] = subd_mid_of_sum_even(a[i], b[i], ovf);
}

/* An edge's weights from the kernel value f = f_n (Q32.32): w = 1 / (2 + 2 f) in Q32.32,
 * rounded once, and w2 = 2w, each as subd_alpha_wt. */
static inline void subd_alpha_edge_w(int64_t f, subd_alpha_wt *w, subd_alpha_wt *w2, uint32_t *ovf)
{
    int64_t w1 = subd_alpha_divq(SUBD_Q32_ONE, 2 * (SUBD_Q32_ONE + f), 32, ovf);
    *w = subd_alpha_wt_from_q32(w1, ovf);
    *w2 = subd_alpha_wt_from_q32(2 * w1, ovf);
}

/* alpha_chord.c: 1 when every point pts[i], a < i < b, lies within eps of the segment
 * pts[a] pts[b] (each distance bounded from above with a margin for rounding; 0 on inf or
 * NaN), else 0. The streaming curve's adaptive mode (alpha_stream.c) splits the span then. */
int subd_alpha_span_near(subd_real eps, const subd_real *pts, uint32_t a, uint32_t b);

#endif
