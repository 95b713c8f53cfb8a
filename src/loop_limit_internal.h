/* SPDX-License-Identifier: MIT */
/* What loop_limit.c (positions, public calls) and loop_limit_normal.c (normals) share,
 * private: the vertex class type, the regularity of a neighbour, the per-call trig table of
 * the tangent masks, and the normal of one vertex. No paper beyond loop_limit.c's header. */
#ifndef SUBD_LOOP_LIMIT_INTERNAL_H
#define SUBD_LOOP_LIMIT_INTERNAL_H
#include "subd.h"
#include "loop_internal.h"
#include "loop_rules.h"
#include "vec3w.h" /* subd_wide */

/* Vertex classes: loop_rules.h (the one classification of loop.c, loop_limit.c and pia.c). */
typedef loop_vinfo lim_vert;

/* The class of neighbour v (regular or not, for the paper's curve rules): from its ring, or
 * given by LOOP_VTAG_KNOWN (loop_stream.c's patch views, where v's ring may be cut). */
static inline int lim_regular(const subd_mesh *m, uint32_t v)
{
    lim_vert c;
    if (m->vert_tag[v] & LOOP_VTAG_KNOWN) return (m->vert_tag[v] & LOOP_VTAG_REGULAR) != 0u;
    subd_loop_classify(m, v, &c);
    return (int)c.regular;
}

/* Per-call table of the interior tangent weights subd_cos_turns(j, n), subd_sin_turns(j, n)
 * for the common valences LIM_TRIG_LO..LIM_TRIG_HI, j = 0..n/2, each valence filled on its
 * first use (the integer trig was most of the normals' time). The other half of the ring
 * follows bit for bit from the exact range reduction of trig.c: cos((n-j)/n) == cos(j/n),
 * sin((n-j)/n) == -sin(j/n) in Q62, and subd_real_from_q62 rounds the magnitude, so the
 * negation commutes with it (sin is 0 only at j = 0 and n/2, which are stored). Lives in
 * subd_loop_limit's frame: no global state, no arena memory. */
#define LIM_TRIG_LO 4u
#define LIM_TRIG_HI 8u
#define LIM_TRIG_SLOTS 19u /* sum of (n/2 + 1) for n = LIM_TRIG_LO..LIM_TRIG_HI */

typedef struct lim_trig {
    uint32_t filled; /* bit n: valence n present */
    subd_real c[LIM_TRIG_SLOTS], s[LIM_TRIG_SLOTS];
} lim_trig;

/* The position masks' weights (loop_limit.c): Q28 in an int64 in Q16.16, float in float32.
 * Why the #if: the masks' own precision, not a scalar twin (loop_limit.c, "Position weights"). */
#if SUBD_FIXED
typedef int64_t lim_w;
#else
typedef float lim_w;
#endif

/* Per-call caches of subd_loop_limit_vertex_cached: chi of valences 2..17 (0: not yet) and the
 * trig table. subd_loop_limit_cache_init empties them. */
#define LIM_CACHE 16u
typedef struct lim_cache {
    lim_w chi[LIM_CACHE];
    lim_trig tab;
} lim_cache;
void subd_loop_limit_cache_init(lim_cache *lc);
/* subd_loop_limit_vertex with the caller's caches (loop_stream.c keeps one per stream). */
void subd_loop_limit_vertex_cached(const subd_mesh *m, subd_loop_boundary b, const subd_real *ctrl, uint32_t v,
                                   lim_cache *lc, subd_real *pos, subd_real *normal, uint32_t *ovf);

/* The masks of a smooth vertex of valence 6 (every vertex inside loop_tile.c's regular
 * tiles), computed once: chi(6) and cos, sin(2 pi j/6) as the trig table gives them.
 * subd_loop_limit_reg6: the limit position and unit normal of centre pv with its ring at
 * pv + ring[0..5] (offsets in subd_reals, from vert_out, counter-clockwise), bit for bit as subd_loop_limit computes a smooth
 * valence-6 vertex (the same sums in the same order: loop_limit.c's lim_position, then
 * loop_limit_normal.c's lim_smooth_tangents and lim_unit_cross, which
 * subd_loop_limit_unit_cross is: the unit vector along t1 x t2). */
typedef struct lim_reg6 {
    lim_w chi;
    subd_real c[6], s[6];
    uint32_t fast; /* 1: c, s are (1, 1/2, -1/2, -1, -1/2, 1/2), (0, r, r, 0, -r, -r): loop_limit.c */
} lim_reg6;
void subd_loop_limit_reg6_init(lim_reg6 *k);
void subd_loop_limit_reg6_trig(lim_reg6 *k); /* loop_limit_normal.c: c and s */
void subd_loop_limit_reg6(const lim_reg6 *k, const subd_real *pv, const int32_t *ring, subd_real *pos, subd_real *nrm,
                          uint32_t *ovf);
/* The unit vector along t1 x t2 (every limit normal but the corners' sums): both rescaled
 * first with subd_w3_normalize(_shr) to 30 bits (float32: largest component 1), so the cross
 * product cannot overflow (Q16.16: below 2^61) or underflow; only the directions matter.
 * Inline so that the valence-6 path keeps its tangents in registers. */
static inline void subd_loop_limit_unit_cross(const subd_wide *t1, const subd_wide *t2, subd_real *out)
{
    subd_wide a[3], b[3], c[3];
    subd_w3_normalize_shr(t1, a, 30u);
    subd_w3_normalize_shr(t2, b, 30u);
    subd_w3_cross(a, b, c);
    subd_w3_unit(c, out);
}

/* The unit limit normal of vertex v of class c (control points ctrl, rule b) into out[3];
 * tab: the caller's trig table (filled = 0 before its first use in a call), or NULL.
 * loop_limit_normal.c; loop_limit.c calls it by its former static name lim_normal. */
void subd_loop_limit_normal(const subd_mesh *m, subd_loop_boundary b, const subd_real *ctrl, uint32_t v,
                            const lim_vert *c, lim_trig *tab, subd_real *out);
#define lim_normal subd_loop_limit_normal
#endif
