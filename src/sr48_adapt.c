/* SPDX-License-Identifier: MIT */
/* The adaptation geometry of the semi-regular 4-8 extraction (sr48_extract.c's cut asks it
 * once per active triangle; subd_sr48_stream shares the parameter check, the box predicates,
 * the adaptation box and POINT's default radius through sr48_internal.h; the private
 * interface with the cut: sr48_extract_internal.h).
 *
 * Paper: L. Velho, "Semi-regular 4-8 refinement and box spline surfaces"
 * (semi-regular-4-8-refinement-box-splines.txt), section 7 (figure 20: tessellations
 * extracted by point location, a linear ramp and a step across a plane). Beyond the paper:
 * a chordal tolerance (CHORD; its test is in sr48_chord.c) and a caller callback.
 *
 * Adaptation functions. POINT, RAMP and PLANE are evaluated on a nested region, so that
 * a top-down decision without lookahead (subd_sr48_stream) gives the same cut:
 *  - L is the piecewise-linear interpolant of the level-0 mesh at its vertices' finest
 *    positions: L at a level-0 vertex is its position, L at a vertex created by splitting a
 *    diamond is the midpoint (subd_mid) of L at its base ends (the parameter midpoint;
 *    commutative, so every triangle that has the vertex computes the same L);
 *  - the region of a diamond D of level k is B(D), the bounding box of L over the corners
 *    of every level-k triangle that shares a vertex with D (its "star", walked fan by fan;
 *    a leg neighbour is the parent of the base neighbour of the child whose base is that
 *    leg, so no adjacency is stored);
 *  - nesting: a child diamond D' = {c, c'} of level k+1 (c a child of p, c' of p', p and
 *    p' sharing the leg that is c's base) touches only m, m' (the new vertices of D(p),
 *    D(p')) and the ends of that leg, so its star lies in the children of the stars of
 *    D(p) and of D(p'); corners of children are corners or base midpoints of their
 *    parents and a midpoint lies between its ends in both arithmetics, so
 *    B(D') is inside B(D(p)) and B(D(p')). Each predicate below is monotone in the box
 *    and in the level (a coarser level asks for no less), so a diamond that asks for a
 *    split has parent diamonds that ask too: the least conforming cut has no forced
 *    split, it is exactly {D : pred(B(D), level of D)}, evaluable top-down;
 *  - POINT: split a level-k diamond iff dist(point, B) < (max_level - k) * radius
 *    (compared as squares; Q16.16 floors the per-axis distances and the limit by one
 *    common shift to below 2^30 so the squares sum in int64);
 *  - RAMP: split iff (k + 1)(hi - lo) <= max_level (x - lo), x = B's maximum on the axis;
 *    Q16.16 exact;
 *  - PLANE: split iff the corner of B furthest along the normal has (q - point).normal
 *    >= 0; Q16.16: exact sign (the three 64-bit products are summed as high and low 32-bit
 *    halves, vec3w.h).
 *  The star costs O(4 valence) triangles of O(k) each (L down the child path) per
 *  evaluation. CALLBACK and CHORD are not nested (forced splits may occur):
 *  - CALLBACK: fn(ctx, the triangle's apex, b0, b1 finest positions) > k;
 *  - CHORD: the chordal deviation of t is the largest |P(v) - L_t(v)| over the vertices v
 *    of t's subtree down to level max_level (the "finest level" of this extraction; deeper
 *    vertices cannot be honoured, max_level triangles are never split), L_t the linear
 *    interpolation of t's corners at v's dyadic parameter. The subtree is walked depth
 *    first with an explicit arena stack carrying L at the three corners of each node: the
 *    parameter of a split vertex is the midpoint of its node's base, so L there is the
 *    average of L at the base ends (Q16.16: L is kept in Q32.32, so 16 halvings are exact).
 *    The walk stops at the first vertex beyond eps; only active triangles are walked, so
 *    the work is O(faces of level max_level * levels) at most.
 *  The bounding box (RAMP, POINT's default radius) is that of the vertices of levels
 *  0..max_level.
 */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "subd_sr48.h"
#include "vec3w.h"
#include "sr48_internal.h"
#include "sr48_extract_internal.h"

/* ------------------------------------------------------------------------------------ */
/* The modes' parameters.                                                                 */

static int real_ok(subd_real x) { return subd_real_is_finite(x); }

/* The mode's own parameters (sr48_internal.h: the stream checks them here too). */
int subd_sr48_adapt_check_(const subd_sr48_adapt *ad)
{
    uint32_t i;
    switch (ad->mode) {
    case SUBD_SR48_ADAPT_UNIFORM: break;
    case SUBD_SR48_ADAPT_POINT:
        for (i = 0; i < 3u; i++) if (!real_ok(ad->point[i])) return SUBD_ERR_PARAM;
        if (!real_ok(ad->radius) || ad->radius < 0) return SUBD_ERR_PARAM;
        break;
    case SUBD_SR48_ADAPT_RAMP:
        if (ad->axis > 2u) return SUBD_ERR_PARAM;
        break;
    case SUBD_SR48_ADAPT_PLANE:
        for (i = 0; i < 3u; i++)
            if (!real_ok(ad->point[i]) || !real_ok(ad->normal[i])) return SUBD_ERR_PARAM;
        if (ad->normal[0] == 0 && ad->normal[1] == 0 && ad->normal[2] == 0) return SUBD_ERR_PARAM;
        break;
    case SUBD_SR48_ADAPT_CALLBACK:
        if (!ad->fn) return SUBD_ERR_PARAM;
        break;
    case SUBD_SR48_ADAPT_CHORD:
        if (!real_ok(ad->eps) || !(ad->eps > 0)) return SUBD_ERR_PARAM;
        break;
    default: return SUBD_ERR_PARAM;
    }
    return SUBD_OK;
}

/* ------------------------------------------------------------------------------------ */
/* Adaptation functions.                                                                  */

static const subd_real *ex_pos(const ex_ctx *c, uint32_t v) { return c->h->pos + 3u * v; }

/* The nested region of POINT, RAMP and PLANE (see the file comment): the box of the
 * level-0 interpolant L over the star of t's diamond at level k. */

/* L at the corners of triangle x of level k (apex, b0, b1): from its level-0 ancestor's
 * corners (finest positions), one base midpoint per level along the child path in x's
 * index (child 0 = (m; apex, b0), child 1 = (m; b1, apex)). The level-0 ancestor is checked
 * before its vertices are read; no other index is read. */
static int ex_tri_lin(ex_ctx *c, uint32_t x, uint32_t k, subd_real *l)
{
    const subd_sr48 *h = c->h;
    uint32_t i = x - h->level_tri[k], a = i >> k, j, q, ovf = 0;
    if (!ex_ok(c, a, 0)) return 0;
    for (j = 0; j < 9u; j++) l[j] = ex_pos(c, h->tri_vert[3u * a + j / 3u])[j % 3u];
    for (j = k; j > 0u; j--) {
        subd_real m[3], o[6];
        for (q = 0; q < 3u; q++) m[q] = subd_mid(l[3u + q], l[6u + q], &ovf);
        if ((i >> (j - 1u)) & 1u) {
            for (q = 0; q < 3u; q++) { o[q] = l[6u + q]; o[3u + q] = l[q]; }
        } else {
            for (q = 0; q < 3u; q++) { o[q] = l[q]; o[3u + q] = l[3u + q]; }
        }
        for (q = 0; q < 3u; q++) { l[q] = m[q]; l[3u + q] = o[q]; l[6u + q] = o[3u + q]; }
    }
    return 1;
}

/* The neighbour of x (level k < max, checked) across slot 0 (base), 1 (leg 0: apex-b0) or
 * 2 (leg 1: b1-apex): a leg of x is the base of one of its children, whose base neighbour's
 * parent is x's leg neighbour. SUBD_NONE on the boundary or when a child breaks the index
 * rules (c->bad set). */
static uint32_t ex_nbr(ex_ctx *c, uint32_t x, uint32_t k, uint32_t slot)
{
    const subd_sr48 *h = c->h;
    uint32_t ch, nb;
    if (slot == 0u) return h->tri_base_nb[x];
    ch = h->level_tri[k + 1u] + 2u * (x - h->level_tri[k]) + (slot - 1u);
    if (!ex_ok(c, ch, k + 1u)) return SUBD_NONE;
    nb = h->tri_base_nb[ch];
    return nb == SUBD_NONE ? SUBD_NONE : h->level_tri[k] + (nb - h->level_tri[k + 1u]) / 2u;
}

/* Grows box (lo, hi) by L over the level-k triangles around vertex v, starting at x0 (which
 * has v as a corner): the fan is walked in one direction until it closes or meets the
 * boundary, then in the other; duplicates do not change a box. 0 on a broken hierarchy. */
static int ex_fan_box(ex_ctx *c, uint32_t x0, uint32_t k, uint32_t v, subd_real *lo, subd_real *hi)
{
    const subd_sr48 *h = c->h;
    uint32_t dir, steps, cap = h->level_tri[k + 1u] - h->level_tri[k];
    for (dir = 0; dir < 2u; dir++) {
        uint32_t x = x0, prev = SUBD_NONE;
        for (steps = 0; steps <= cap; steps++) {
            const uint32_t *tv;
            subd_real l[9];
            uint32_t j, s0, s1, nx;
            if (!ex_ok(c, x, k) || !ex_tri_lin(c, x, k, l)) return 0;
            for (j = 0; j < 9u; j++) {
                if (l[j] < lo[j % 3u]) lo[j % 3u] = l[j];
                if (l[j] > hi[j % 3u]) hi[j % 3u] = l[j];
            }
            tv = h->tri_vert + 3u * x;
            /* the two slots at v: corner 0 (apex) -> legs (slots 1, 2); b0 -> 1, 0; b1 -> 2, 0 */
            if (tv[0] == v) { s0 = 1u; s1 = 2u; }
            else if (tv[1] == v) { s0 = 1u; s1 = 0u; }
            else if (tv[2] == v) { s0 = 2u; s1 = 0u; }
            else return 0;
            if (dir) { j = s0; s0 = s1; s1 = j; }
            nx = ex_nbr(c, x, k, s0);
            if (c->bad) return 0;
            if (nx == prev && prev != SUBD_NONE) nx = ex_nbr(c, x, k, s1);
            if (c->bad) return 0;
            if (nx == SUBD_NONE || nx == x0) break;
            if (nx < h->level_tri[k] || nx >= h->level_tri[k + 1u]) return 0;
            prev = x;
            x = nx;
        }
    }
    return 1;
}

/* The box of L over every level-k triangle sharing a vertex with t's diamond. */
static int ex_star_box(ex_ctx *c, uint32_t t, uint32_t k, subd_real *lo, subd_real *hi)
{
    const subd_sr48 *h = c->h;
    uint32_t j, nb = h->tri_base_nb[t];
    for (j = 0; j < 3u; j++) {
        lo[j] = SUBD_REAL_MAX;
        hi[j] = -SUBD_REAL_MAX;
    }
    for (j = 0; j < 3u; j++)
        if (!ex_fan_box(c, t, k, h->tri_vert[3u * t + j], lo, hi)) return 0;
    if (nb != SUBD_NONE && !ex_fan_box(c, nb, k, h->tri_vert[3u * nb], lo, hi)) return 0;
    return 1;
}

/* POINT: dist(point, box) < n * radius (n = max_level - k levels to go). Every step is
 * monotone in the box and in n, which is all the nesting needs. */
static int ex_point_wants(const subd_sr48_adapt *ad, subd_real radius, const subd_real *lo, const subd_real *hi, uint32_t n)
{
    subd_wide d[3], lim = subd_wide_mulu(n, subd_wide_of(radius));
    uint32_t i;
    for (i = 0; i < 3u; i++) {
        subd_real p = ad->point[i];
        d[i] = p < lo[i] ? subd_wide_diff(lo[i], p) : p > hi[i] ? subd_wide_diff(p, hi[i]) : 0;
        if (d[i] >= lim) return 0;
    }
#if SUBD_FIXED /* the algorithm differs: one common floor shift keeps the squares in int64 */
    {
        int32_t s = (int32_t)subd_bitlen64((uint64_t)lim) - 30;
        uint64_t sum = 0, l2;
        if (s < 0) s = 0;
        for (i = 0; i < 3u; i++) sum += ((uint64_t)d[i] >> s) * ((uint64_t)d[i] >> s);
        l2 = ((uint64_t)lim >> s) * ((uint64_t)lim >> s);
        return sum < l2;
    }
#else
    {
        float s0 = d[0] * d[0], s1 = d[1] * d[1], s2 = d[2] * d[2];
        return s0 + s1 + s2 < lim * lim;
    }
#endif
}

/* RAMP: (k + 1)(hi - lo) <= max (x - lo), x the box's largest coordinate on the axis. */
static int ex_ramp_wants(const subd_sr48_adapt *ad, const subd_real *rlo, const subd_real *rhi, const subd_real *hi,
                         uint32_t k)
{
    uint32_t ax = ad->axis;
    subd_real lo = rlo[ax], top = rhi[ax];
    return subd_wide_mulu(k + 1u, subd_wide_diff(top, lo)) <= subd_wide_mulu(ad->max_level, subd_wide_diff(hi[ax], lo));
}

/* PLANE: the box's corner furthest along the normal is on the side (x - point).normal >= 0
 * (exact in Q16.16, vec3w.h). */
static int ex_plane_wants(const subd_sr48_adapt *ad, const subd_real *lo, const subd_real *hi)
{
    subd_real q[3];
    uint32_t i;
    for (i = 0; i < 3u; i++) q[i] = ad->normal[i] >= 0 ? hi[i] : lo[i];
    return subd_w3_side(q, ad->point, ad->normal);
}

/* POINT, RAMP or PLANE on a diamond of level k < max_level with region box (lo, hi)
 * (sr48_internal.h: the stream takes its decisions here too). radius: POINT's (resolved);
 * rlo, rhi: RAMP's bounding box. */
int subd_sr48_box_wants_(const subd_sr48_adapt *ad, subd_real radius, const subd_real *rlo, const subd_real *rhi,
                         const subd_real *lo, const subd_real *hi, uint32_t k)
{
    if (ad->mode == SUBD_SR48_ADAPT_POINT) return ex_point_wants(ad, radius, lo, hi, ad->max_level - k);
    if (ad->mode == SUBD_SR48_ADAPT_RAMP) return ex_ramp_wants(ad, rlo, rhi, hi, k);
    if (ad->mode == SUBD_SR48_ADAPT_CALLBACK) return ad->fn(ad->ctx, lo, hi) > k;
    return ex_plane_wants(ad, lo, hi);
}

/* Chordal deviation of t (level k < max, checked) beyond eps: depth-first walk of t's
 * subtree down to level max, stopping at the first vertex that deviates. Stack: pop one
 * node, push its two children, so at most (max - k) + 1 <= max + 1 entries. Each node is
 * checked before its child is read (a failure sets c->bad and answers 0). */
static int ex_chord_wants(ex_ctx *c, uint32_t t, uint32_t k)
{
    const subd_sr48 *h = c->h;
    ex_cnode *st = c->cstack;
    uint32_t sp = 1, i;
    st[0].tri = t;
    st[0].level = k;
    for (i = 0; i < 9u; i++) st[0].l[i] = subd_sr48_lin_of_(ex_pos(c, h->tri_vert[3u * t + i / 3u])[i % 3u]);
    while (sp > 0u) {
        ex_cnode nd = st[--sp];
        uint32_t kk = nd.level, c0, m;
        ex_lin lm[3];
        if (!ex_ok(c, nd.tri, kk)) return 0; /* before reading its child's apex */
        c0 = h->level_tri[kk + 1u] + 2u * (nd.tri - h->level_tri[kk]);
        m = h->tri_vert[3u * c0];
        for (i = 0; i < 3u; i++) lm[i] = subd_sr48_lin_mid_(nd.l[3u + i], nd.l[6u + i]);
        if (subd_sr48_beyond_(ex_pos(c, m), lm, c->ad->eps)) return 1;
        if (kk + 1u >= c->max) continue;
        if (sp + 2u > c->max + 1u) return 1; /* cannot happen (see above); stay in bounds */
        /* child 2i = (m; apex, b0), child 2i+1 = (m; b1, apex) */
        st[sp].tri = c0;
        st[sp + 1u].tri = c0 + 1u;
        st[sp].level = st[sp + 1u].level = kk + 1u;
        for (i = 0; i < 3u; i++) {
            st[sp].l[i] = lm[i];
            st[sp].l[3u + i] = nd.l[i];
            st[sp].l[6u + i] = nd.l[3u + i];
            st[sp + 1u].l[i] = lm[i];
            st[sp + 1u].l[3u + i] = nd.l[6u + i];
            st[sp + 1u].l[6u + i] = nd.l[i];
        }
        sp += 2u;
    }
    return 0;
}

/* Does triangle t of level k < max (checked) ask for a split? */
int subd_sr48_ex_wants_(ex_ctx *c, uint32_t t, uint32_t k)
{
    subd_real lo[3], hi[3];
    switch (c->ad->mode) {
    case SUBD_SR48_ADAPT_POINT:
    case SUBD_SR48_ADAPT_RAMP:
    case SUBD_SR48_ADAPT_PLANE:
    case SUBD_SR48_ADAPT_CALLBACK:
        if (!ex_star_box(c, t, k, lo, hi)) {
            c->bad = 1;
            return 0;
        }
        return subd_sr48_box_wants_(c->ad, c->radius, c->lo, c->hi, lo, hi, k);
    case SUBD_SR48_ADAPT_CHORD: return ex_chord_wants(c, t, k);
    default: return 1;
    }
}

/* ------------------------------------------------------------------------------------ */
/* The adaptation box and POINT's default radius.                                         */

/* The adaptation box (RAMP's range, POINT's default radius; subd_sr48_adapt_mode): the box of
 * the finest positions of the corners of the level-0 triangles, i.e. of L over the whole
 * mesh. 0 when a level-0 corner is out of range. */
int subd_sr48_ex_bbox_(ex_ctx *c)
{
    const subd_sr48 *h = c->h;
    uint32_t t, n = 3u * h->level_tri[1];
    for (t = 0; t < n; t++)
        if (h->tri_vert[t] >= h->level_verts[0]) return 0;
    subd_sr48_box_grow_(h->pos, h->tri_vert, n, c->lo, c->hi, 1);
    return 1;
}

/* Grows (lo, hi) by the n points pos + 3 idx[i] (reset first when `init`); sr48_internal.h. */
void subd_sr48_box_grow_(const subd_real *pos, const uint32_t *idx, uint32_t n, subd_real *blo, subd_real *bhi,
                         int init)
{
    subd_real lo[3], hi[3]; /* locals, so the compiler keeps them in registers */
    uint32_t v, i;
    for (i = 0; i < 3u; i++) {
        lo[i] = init ? SUBD_REAL_MAX : blo[i];
        hi[i] = init ? -SUBD_REAL_MAX : bhi[i];
    }
    for (v = 0; v < n; v++) {
        const subd_real *p = pos + 3u * idx[v];
        for (i = 0; i < 3u; i++) {
            if (p[i] < lo[i]) lo[i] = p[i];
            if (p[i] > hi[i]) hi[i] = p[i];
        }
    }
    for (i = 0; i < 3u; i++) {
        blo[i] = lo[i];
        bhi[i] = hi[i];
    }
}

/* POINT's default radius (sr48_internal.h): the adaptation box's diagonal / (2 max_level),
 * at least one unit of the last place so the level function stays defined; max > 0. */
subd_real subd_sr48_default_radius_(const subd_real *blo, const subd_real *bhi, uint32_t max)
{
#if SUBD_FIXED /* the algorithm differs: integer square root, pre-shift keeps the squares in 64 bits */
    uint64_t d[3], sum = 0, diag;
    uint32_t i, sh = 0;
    for (i = 0; i < 3u; i++) {
        d[i] = (uint64_t)((int64_t)bhi[i] - blo[i]);
        if (d[i] >> 31) sh = 1u; /* keep each square below 2^62 */
    }
    for (i = 0; i < 3u; i++) sum += (d[i] >> sh) * (d[i] >> sh);
    diag = (uint64_t)subd_isqrt64(sum) << sh;
    diag /= 2u * max;
    if (diag == 0u) diag = 1u;
    return diag > (uint64_t)INT32_MAX ? SUBD_REAL_MAX : (subd_real)diag;
#else
    float dx = bhi[0] - blo[0], dy = bhi[1] - blo[1], dz = bhi[2] - blo[2];
    float sx = dx * dx, sy = dy * dy, sz = dz * dz;
    float r = subd_sqrt(sx + sy + sz) / (float)(2u * max);
    return r > 0.0f ? r : 1.0f;
#endif
}
