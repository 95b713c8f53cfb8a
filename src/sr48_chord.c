/* SPDX-License-Identifier: MIT */
/* Chordal cuts of the streamed semi-regular 4-8 surface (SUBD_SR48_ADAPT_CHORD in
 * subd_sr48_stream, src/sr48_stream.c): the deviation test of one vertex against the linear
 * interpolant of one ancestor triangle. Paper: semi-regular-4-8-refinement-box-splines.txt,
 * section 3 (a diamond is split as a whole, splits force their parents: the restricted
 * hierarchy) and section 7 (adaptive extraction); the chordal tolerance is beyond the paper,
 * as in sr48_extract.c.
 *
 * The criterion (design note; the choices where the paper is silent). P(v) is the position
 * of vertex v at the finest level max_level (subd_sr48_build's), L_d the linear
 * interpolation of triangle d's corners P at dyadic parameters (the parameter of a split
 * vertex is the midpoint of its node's base, as in sr48_extract.c's walk), and
 *   E(d)  = max |P(v) - L_d(v)| over the vertices v created inside d's subtree down to
 *           max_level (subd_sr48_extract's exact chordal deviation of d),
 *   W(t)  = max E(d) over t and its descendants of levels < max_level (saturated: W of a
 *           child is at most W of its parent, because its descendants are a subset),
 *   star(D) = the level-k triangles that share a vertex with diamond D (sr48_extract.c's
 *           nested region: the star of a child diamond lies in the children of the stars
 *           of both parent diamonds).
 * The stream splits a level-k diamond D iff W(s) > eps for some s in star(D). Nested: a
 * child diamond's star is made of children of triangles of both parents' stars, and W does
 * not grow from parent to child (the computed values are the same numbers: E(d) depends on
 * d only), so a diamond that splits has parents that split - the cut is exactly the set of
 * diamonds that ask, decided top down with no lookahead and no forced split. Conservative:
 * a leaf t of the cut (its diamond does not split) has E(t) <= W(t) <= eps, so every
 * finest-level vertex created inside t lies within eps of the emitted triangle (L_t(v) is a
 * point of it), up to the rounding documented below; every finest vertex lies in some leaf.
 * The cut contains subd_sr48_extract(CHORD)'s (a diamond whose triangle has E > eps has
 * W > eps, and its forced parents are split by nesting): more faces, never fewer.
 *
 * Why exact and not an a-priori bound from the level-k control net (second differences
 * times the box spline's contraction): a rigorous constant needs the contraction at
 * extraordinary vertices, with smoothing on and off, in both arithmetics; not derived yet
 * (issue 20, item 4). W is computed by walking the subtree with the stream's own windows
 * (sr48_stream.c, s48_chord_walk); this file holds the arithmetic of one test.
 *
 * Rounding (subd_sr48_extract's CHORD uses this same test): L is
 * carried in Q32.32 in Q16.16 builds (16 halvings exact, then rounded to Q16.16 and
 * compared per axis and as a sum of squares in 64 bits: within eps + 2^-16), in float as
 * (a + b) * 0.5f (a relative error of a few ulp of the coordinates per level). */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "sr48_internal.h"

#if SUBD_FIXED /* the representation differs: Q16.16 keeps the interpolant in Q32.32 */
subd_sr48_lin subd_sr48_lin_of_(subd_real x) { return (int64_t)x * 65536; }
subd_sr48_lin subd_sr48_lin_mid_(subd_sr48_lin a, subd_sr48_lin b) { return (a + b) >> 1; }
#else
subd_sr48_lin subd_sr48_lin_of_(subd_real x) { return x; }
subd_sr48_lin subd_sr48_lin_mid_(subd_sr48_lin a, subd_sr48_lin b) { return (a + b) * 0.5f; }
#endif

/* |P - L| > eps (subd_sr48_extract's CHORD and the stream's). */
int subd_sr48_beyond_(const subd_real *p, const subd_sr48_lin *l, subd_real eps)
{
#if SUBD_FIXED /* the algorithm differs: Q32.32 differences, an early exit keeps the squares in 64 bits */
    uint64_t sum = 0, e = (uint64_t)eps;
    uint32_t i;
    for (i = 0; i < 3u; i++) {
        int64_t d = ((int64_t)p[i] * 65536 - l[i] + 32768) >> 16;
        uint64_t ad = (uint64_t)(d < 0 ? -d : d);
        if (ad > e) return 1;
        sum += ad * ad;
    }
    return sum > e * e;
#else
    float d0 = p[0] - l[0], d1 = p[1] - l[1], d2 = p[2] - l[2];
    float s0 = d0 * d0, s1 = d1 * d1, s2 = d2 * d2;
    return s0 + s1 + s2 > eps * eps;
#endif
}

int subd_sr48_chord_beyond_(const subd_real *c, uint32_t path, uint32_t n, const subd_real *p, subd_real eps)
{
    subd_sr48_lin l[9], t[9], m[3];
    uint32_t i, s;
    for (i = 0; i < 9u; i++) l[i] = subd_sr48_lin_of_(c[i]);
    for (s = 0; s < n; s++) {
        /* child 0 = (m; apex, b0), child 1 = (m; b1, apex) */
        uint32_t bit = (path >> s) & 1u;
        for (i = 0; i < 3u; i++) {
            m[i] = subd_sr48_lin_mid_(l[3u + i], l[6u + i]);
            t[i] = m[i];
            t[3u + i] = bit ? l[6u + i] : l[i];
            t[6u + i] = bit ? l[i] : l[3u + i];
        }
        for (i = 0; i < 9u; i++) l[i] = t[i];
    }
    for (i = 0; i < 3u; i++) m[i] = subd_sr48_lin_mid_(l[3u + i], l[6u + i]);
    return subd_sr48_beyond_(p, m, eps);
}
