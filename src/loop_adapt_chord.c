/* SPDX-License-Identifier: MIT */
/* Adaptive Loop limit stream, the levels (loop_adapt.c emits; loop_adapt_internal.h shares the
 * types): CALLBACK's levels, CHORD's edge and face chord tests with the nearby-triangle
 * search, and CHORD's fallback pass.
 *
 * Paper: loop-progressive-interpolation.txt (nothing here computes a rule: every point is
 * loop_adapt.c's level-L limit point). The paper says nothing about adaptive tessellation;
 * the choices:
 *
 * Levels. Each control edge gets a level e, each face a level l >= its edges'.
 *   CALLBACK: l = min(callback(face), L); an edge's e = the smaller of its two faces' levels
 *     (the callback is a function of the face index, so both faces compute the same).
 *   CHORD: an edge's e is the larger of (a) the smallest level whose chord polyline (the
 *     level-e lattice points of the edge, as limit points) holds every level-L limit point of
 *     the edge within eps, walked from the end with the smaller control vertex on the same
 *     bits from both faces, and (b) the smaller of its two faces' "own" levels (the smallest
 *     level at which the face's uniform triangles hold its level-L points within eps; a
 *     function of that face alone), so both faces decide the same e and no edge is coarser
 *     than both its faces would take uniformly. A face's l is the smallest level >= its
 *     edges' at which every level-L limit point of the face lies within eps of the triangle
 *     (of this face's triangulation at l) that contains it in the parameter domain; at l = L
 *     this holds by construction (every level-L point is a vertex or lies on a chord its
 *     edge's e was chosen for), so l = L needs no check. A point farther than eps from its
 *     own triangle may still be near another emitted triangle of the face (the limit
 *     parametrisation is not the chord's: near extraordinary vertices a point lies over the
 *     neighbouring triangle): the check tries the face's triangles in the 3 x 3 level-l
 *     cells around it and the ring triangles beside it (la_near_holds; any emitted triangle
 *     is a sound witness), which took the icosahedron (eps 0.001) and the cube (eps 0.003)
 *     from 4x the uniform count to 1x. The neighbouring FACES' triangles are not tried (their
 *     levels are decided from this face's: a cycle), so a level that only they make
 *     sufficient is missed (open work). "Within eps": float32, the Euclidean
 *     distance to that triangle (segment, for an edge) plus a rounding margin of 2^-18 of the
 *     coordinates' magnitude; Q16.16, whose resolution cannot hold the squared distances of
 *     fine levels, the bound |x - p|_1 + 8 LSB, p the triangle's point at x's barycentric
 *     coordinates (>= the Euclidean distance, so Q16.16 refines more). Either way the
 *     distance to the emitted mesh is within eps: an exact check on the points the guarantee
 *     is about, not an estimate. Work: at L <= 4 a face's level-L limit points are computed
 *     once into a point cache (loop_adapt.c's la_pc_fill: one depth-first pass over the
 *     face's level-L triangles) that every level tried reads, and faces' own levels are
 *     remembered in 64 slots (face mod 64); above level 4 each level tried re-evaluates its
 *     points (about one uniform level-L pass per level tried).
 *   CHORD fallback (subd_la_prepass): the level choice runs once over the whole mesh before the
 *     first triangle, counting the adaptive cut's triangles A and taking U = the largest
 *     over the faces of the smallest uniform level that passes the check with the edge
 *     neighbours' uniform triangles beside the shared edge as witnesses too (la_twin_holds:
 *     at a uniform level every face's triangles are emitted, so the cycle that keeps the
 *     adaptive check to a face's own triangles is not there); if A > 4^U F and every face
 *     passes that check at U (checked again: the level per face is only the first that
 *     passes), every face is emitted at U, uniformly: the stream never emits more than that
 *     uniform level, at the price of a second pass.
 */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "loop_adapt_internal.h"

/* ------------------------------------------------------------------------------------ */
/* The chord check                                                                        */

static subd_real la_abs(subd_real x, uint32_t *ovf) { return x < 0 ? subd_neg(x, ovf) : x; }

#if !SUBD_FIXED
/* Float32: the Euclidean distance from x to the triangle (c0, c1, c2), or to the segment
 * (c0, c1) when c2 is NULL (Ericson, Real-Time Collision Detection, 5.1.2 and 5.1.5: the
 * closest point q by Voronoi regions); returns |x - q|^2. A rounding that misjudges a region
 * gives a farther q: the bound only grows. */
static subd_real la_dot(const subd_real *a, const subd_real *b, uint32_t *ovf)
{
    subd_real r = subd_mul(a[0], b[0], ovf);
    r = subd_add(r, subd_mul(a[1], b[1], ovf), ovf);
    return subd_add(r, subd_mul(a[2], b[2], ovf), ovf);
}

static subd_real la_dist2(const subd_real *x, const subd_real *c0, const subd_real *c1, const subd_real *c2,
                          uint32_t *ovf)
{
    subd_real ab[3], ac[3], ap[3], bp[3], cp[3], q[3], e[3], d1, d2, d3, d4, d5, d6, va, vb, vc, v, w;
    const subd_real *base = c0, *dir2 = ac;
    uint32_t k;
    for (k = 0; k < 3u; k++) {
        ab[k] = subd_sub(c1[k], c0[k], ovf);
        ap[k] = subd_sub(x[k], c0[k], ovf);
        bp[k] = subd_sub(x[k], c1[k], ovf);
        ac[k] = c2 ? subd_sub(c2[k], c0[k], ovf) : 0;
        cp[k] = c2 ? subd_sub(x[k], c2[k], ovf) : 0;
    }
    v = w = 0;
    d1 = la_dot(ab, ap, ovf);
    if (!c2) { /* the segment: t = clamp(ab.ap / ab.ab, 0, 1) */
        d3 = la_dot(ab, ab, ovf);
        if (d1 > 0) v = d1 >= d3 ? SUBD_REAL_ONE : subd_div(d1, d3, ovf);
    } else {
        d2 = la_dot(ac, ap, ovf);
        d3 = la_dot(ab, bp, ovf);
        d4 = la_dot(ac, bp, ovf);
        d5 = la_dot(ab, cp, ovf);
        d6 = la_dot(ac, cp, ovf);
        vc = subd_sub(subd_mul(d1, d4, ovf), subd_mul(d3, d2, ovf), ovf);
        vb = subd_sub(subd_mul(d5, d2, ovf), subd_mul(d1, d6, ovf), ovf);
        va = subd_sub(subd_mul(d3, d6, ovf), subd_mul(d5, d4, ovf), ovf);
        if (d1 <= 0 && d2 <= 0) {
        } else if (d3 >= 0 && d4 <= d3) {
            v = SUBD_REAL_ONE;
        } else if (vc <= 0 && d1 >= 0 && d3 <= 0) {
            v = subd_div(d1, subd_sub(d1, d3, ovf), ovf);
        } else if (d6 >= 0 && d5 <= d6) {
            w = SUBD_REAL_ONE;
        } else if (vb <= 0 && d2 >= 0 && d6 <= 0) {
            w = subd_div(d2, subd_sub(d2, d6, ovf), ovf);
        } else if (va <= 0 && subd_sub(d4, d3, ovf) >= 0 && subd_sub(d5, d6, ovf) >= 0) {
            subd_real n = subd_sub(d4, d3, ovf);
            w = subd_div(n, subd_add(n, subd_sub(d5, d6, ovf), ovf), ovf);
            base = c1; /* q = c1 + w (c2 - c1) */
            for (k = 0; k < 3u; k++) e[k] = subd_sub(c2[k], c1[k], ovf);
            dir2 = e;
        } else {
            subd_real den = subd_add(subd_add(va, vb, ovf), vc, ovf);
            v = subd_div(vb, den, ovf);
            w = subd_div(vc, den, ovf);
        }
    }
    for (k = 0; k < 3u; k++) {
        q[k] = subd_add(base[k], subd_mul(base == c0 ? v : 0, ab[k], ovf), ovf);
        q[k] = subd_add(q[k], subd_mul(w, dir2[k], ovf), ovf);
        q[k] = subd_sub(x[k], q[k], ovf);
    }
    return la_dot(q, q, ovf);
}
#endif

/* 1 when x lies within eps of the triangle (c0, c1, c2) (the segment (c0, c1) when c2 is
 * NULL), with a margin for rounding. Float32: the Euclidean distance (la_dist2) plus 2^-18 of
 * the coordinates' magnitude. Q16.16: |x - p|_1 + 8 LSB, p the point of the triangle at x's
 * barycentric coordinates (r1, r2) in the parameter domain (|.|_2 <= |.|_1; a bound, larger
 * than the distance: squared distances of fine levels are below Q16.16's resolution). */
static int la_within(la_state *s, const subd_real *x, const subd_real *c0, const subd_real *c1, const subd_real *c2,
                     subd_real r1, subd_real r2)
{
    uint32_t k, ovf = 0;
    subd_real dev = 0, mag = 0, margin;
#if SUBD_FIXED /* why: see above; Q16.16 resolves no squared distance of a fine level */
    for (k = 0; k < 3u; k++) {
        subd_real p = subd_add(c0[k], subd_mul(r1, subd_sub(c1[k], c0[k], &ovf), &ovf), &ovf);
        if (c2) p = subd_add(p, subd_mul(r2, subd_sub(c2[k], c0[k], &ovf), &ovf), &ovf);
        dev = subd_add(dev, la_abs(subd_sub(x[k], p, &ovf), &ovf), &ovf);
    }
    (void)mag;
    margin = (subd_real)8;
    dev = subd_add(dev, margin, &ovf);
    return !ovf && dev <= s->o.chord;
#else
    (void)r1;
    (void)r2;
    for (k = 0; k < 3u; k++) {
        mag = subd_add(mag, la_abs(x[k], &ovf), &ovf);
        mag = subd_add(mag, la_abs(c0[k], &ovf), &ovf);
        mag = subd_add(mag, la_abs(c1[k], &ovf), &ovf);
        if (c2) mag = subd_add(mag, la_abs(c2[k], &ovf), &ovf);
    }
    margin = subd_mul(mag, SUBD_REAL_FRAC(1, 262144), &ovf);
    if (margin >= s->o.chord) return 0;
    dev = subd_sub(s->o.chord, margin, &ovf);
    dev = subd_mul(dev, dev, &ovf);
    return la_dist2(x, c0, c1, c2, &ovf) <= dev && !ovf;
#endif
}

/* CHORD: the level of edge j of the current face. The edge is walked from its end with the
 * smaller control vertex, so the other face takes the same steps on the same bits. */
static uint32_t la_edge_chord(la_state *s, uint32_t j)
{
    const subd_mesh *in = s->in;
    uint32_t L = s->o.loop.levels, e, k;
    int32_t n = (int32_t)1 << L, m, m0, seg;
    la_pt t[3], u, w, x;
    subd_real c0[3], c1[3], y[3];
    la_root(t, n);
    u = t[j];
    w = t[(j + 1u) % 3u];
    if (in->corner_vert[3u * s->f + j] > in->corner_vert[3u * s->f + (j + 1u) % 3u]) {
        u = t[(j + 1u) % 3u];
        w = t[j];
    }
    for (e = 0; e < L; e++) {
        int ok = 1;
        seg = n >> e;
        for (k = 0; ok && k < ((uint32_t)1 << e); k++) {
            m0 = (int32_t)k * seg;
            x.a = u.a + (w.a - u.a) / n * m0;
            x.b = u.b + (w.b - u.b) / n * m0;
            subd_la_eval_point(s, x, c0, 0);
            x.a = u.a + (w.a - u.a) / n * (m0 + seg);
            x.b = u.b + (w.b - u.b) / n * (m0 + seg);
            subd_la_eval_point(s, x, c1, 0);
            for (m = 1; ok && m < seg; m++) {
                x.a = u.a + (w.a - u.a) / n * (m0 + m);
                x.b = u.b + (w.b - u.b) / n * (m0 + m);
                subd_la_eval_point(s, x, y, 0);
                ok = la_within(s, y, c0, c1, 0, SUBD_REAL_FRAC(m, seg), 0);
            }
        }
        if (ok) return e;
    }
    return L;
}

/* Barycentric weights (w0, w1, w2) of x in triangle t (sum: its doubled area > 0), negative
 * ones set to 0: the weights of a point OF the triangle (x's own point when t contains x). */
static int64_t la_bary(const la_tri *t, la_pt x, int64_t *w1, int64_t *w2)
{
    int64_t area = la_cross(t->p[0], t->p[1], t->p[2]), a1 = la_cross(t->p[2], t->p[0], x);
    int64_t a2 = la_cross(t->p[0], t->p[1], x), a0 = area - a1 - a2;
    if (a0 < 0) a0 = 0;
    if (a1 < 0) a1 = 0;
    if (a2 < 0) a2 = 0;
    *w1 = a1;
    *w2 = a2;
    return a0 + a1 + a2;
}

/* 1 when y (the limit point of lattice point x) lies within eps of emitted triangle t. */
static int la_tri_holds(la_state *s, const la_tri *t, la_pt x, const subd_real *y)
{
    subd_real c[3][3];
    int64_t w1, w2, sum = la_bary(t, x, &w1, &w2);
    uint32_t k;
    for (k = 0; k < 3u; k++) subd_la_eval_point(s, t->p[k], c[k], 0);
    return sum > 0 && la_within(s, y, c[0], c[1], c[2], SUBD_REAL_FRAC(w1, sum), SUBD_REAL_FRAC(w2, sum));
}

/* CHORD's fallback check (s->nb: every face at uniform level l = s->fc.l): 1 when a level-l
 * triangle of an edge neighbour, one with an edge on the shared control edge within one
 * level-l step of x's parameter along it, holds y (x within one level-l step of that edge).
 * Such a triangle is emitted when every face is at l. Its corners are evaluated with a
 * normal (so past the point cache, which keeps face f's points). */
static int la_twin_holds(la_state *s, la_pt x, const subd_real *y)
{
    const subd_mesh *in = s->in;
    uint32_t L = s->o.loop.levels, l = s->fc.l, j, k, c;
    int32_t n = (int32_t)1 << L, step = n >> l, m = (int32_t)1 << l, t, dist, sidx, i;
    la_pt r[3];
    int ok = 0;
    la_root(r, n);
    for (j = 0; !ok && j < 3u; j++) {
        uint32_t tw = in->twin[3u * s->f + j];
        dist = j == 0u ? x.b : j == 1u ? n - x.a - x.b : x.a;
        t = j == 0u ? x.a : j == 1u ? x.b : n - x.b; /* from corner j towards corner j + 1 */
        if (tw == SUBD_NONE || dist > step) continue;
        k = tw % 3u;
        t = n - t; /* the twin's parameter: from its corner k (f's corner j + 1) */
        s->gf = tw / 3u;
        for (i = -1; !ok && i <= 1; i++) {
            la_tri q;
            subd_real cc[3][3], nrm[3];
            int32_t a0;
            sidx = t / step + i;
            if (t == n) sidx--;
            if (sidx < 0 || sidx >= m) continue;
            a0 = sidx * step;
            q.sub = LA_NO_SUB;
            q.p[0].a = r[k].a + (r[(k + 1u) % 3u].a - r[k].a) / n * a0;
            q.p[0].b = r[k].b + (r[(k + 1u) % 3u].b - r[k].b) / n * a0;
            q.p[1].a = q.p[0].a + (r[(k + 1u) % 3u].a - r[k].a) / n * step;
            q.p[1].b = q.p[0].b + (r[(k + 1u) % 3u].b - r[k].b) / n * step;
            q.p[2].a = q.p[0].a + (r[(k + 2u) % 3u].a - r[k].a) / n * step;
            q.p[2].b = q.p[0].b + (r[(k + 2u) % 3u].b - r[k].b) / n * step;
            for (c = 0; c < 3u; c++) subd_la_eval_point(s, q.p[c], cc[c], nrm);
            ok = la_within(s, y, cc[0], cc[1], cc[2],
                           t <= a0 ? 0 : t >= a0 + step ? SUBD_REAL_ONE : SUBD_REAL_FRAC(t - a0, step), 0);
        }
        s->gf = s->f;
    }
    return ok;
}

/* CHORD, when y is farther than eps from the triangle containing x: 1 when another triangle
 * of the face's triangulation (s->fc) near x holds it (all of them are emitted, so any is a
 * sound witness): the uniform level-l triangles of the 3 x 3 lattice cells around x that the
 * triangulation keeps, then the ring triangles whose lattice box, one level-l step wider,
 * holds x. A subset (the nearest in the parameter domain), to bound the work: each
 * candidate costs three limit evaluations. */
static int la_near_holds(la_state *s, la_pt x, const subd_real *y)
{
    const la_face *fc = &s->fc;
    uint32_t L = s->o.loop.levels, l = fc->l, up, k;
    int32_t n = (int32_t)1 << L, step = n >> l, m = (int32_t)1 << l, ci = x.a / step, cj = x.b / step, i, j;
    la_tri t;
    la_iter it;
    t.sub = LA_NO_SUB;
    for (j = cj - 1; j <= cj + 1; j++)
        for (i = ci - 1; i <= ci + 1; i++)
            for (up = 0; up < 2u; up++) {
                uint32_t keep = 1;
                if (i < 0 || j < 0 || i + j + (up ? 2 : 1) > m) continue;
                /* cell (i, j): (i, j) (i+1, j) (i, j+1), and (i+1, j) (i+1, j+1) (i, j+1) */
                t.p[0].a = up ? (i + 1) * step : i * step;
                t.p[0].b = j * step;
                t.p[1].a = (i + 1) * step;
                t.p[1].b = up ? (j + 1) * step : j * step;
                t.p[2].a = i * step;
                t.p[2].b = (j + 1) * step;
                if (fc->trans)
                    for (k = 0; k < 3u; k++)
                        if (l < 2u || t.p[k].a < step || t.p[k].b < step || t.p[k].a + t.p[k].b > n - step) keep = 0;
                if (keep && la_tri_holds(s, &t, x, y)) return 1;
            }
    if (!fc->trans) return s->nb && la_twin_holds(s, x, y);
    it.phase = 1;
    it.j = it.io = it.ii = 0;
    while (subd_la_next(fc, L, &it, &t)) {
        la_pt lo = t.p[0], hi = t.p[0];
        for (k = 1; k < 3u; k++) {
            if (t.p[k].a < lo.a) lo.a = t.p[k].a;
            if (t.p[k].b < lo.b) lo.b = t.p[k].b;
            if (t.p[k].a > hi.a) hi.a = t.p[k].a;
            if (t.p[k].b > hi.b) hi.b = t.p[k].b;
        }
        if (x.a < lo.a - step || x.a > hi.a + step || x.b < lo.b - step || x.b > hi.b + step) continue;
        if (la_tri_holds(s, &t, x, y)) return 1;
    }
    return 0;
}

/* CHORD: 1 when every level-L lattice point of the face lies within eps of the face's
 * triangulation (s->fc): of the triangle that contains it, else of one near it
 * (la_near_holds). */
static int la_face_ok(la_state *s)
{
    uint32_t L = s->o.loop.levels, k;
    int32_t n = (int32_t)1 << L;
    la_iter it;
    la_tri t;
    it.phase = it.j = it.io = it.ii = 0;
    while (subd_la_next(&s->fc, L, &it, &t)) {
        subd_real c[3][3], y[3];
        la_pt x, lo = t.p[0], hi = t.p[0];
        int64_t area = la_cross(t.p[0], t.p[1], t.p[2]);
        for (k = 0; k < 3u; k++) {
            subd_la_eval_corner(s, &t, k, c[k], 0);
            if (t.p[k].a < lo.a) lo.a = t.p[k].a;
            if (t.p[k].b < lo.b) lo.b = t.p[k].b;
            if (t.p[k].a > hi.a) hi.a = t.p[k].a;
            if (t.p[k].b > hi.b) hi.b = t.p[k].b;
        }
        if (area <= 0) return 0; /* never: the triangulation does not fold */
        for (x.b = lo.b; x.b <= hi.b; x.b++)
            for (x.a = lo.a; x.a <= hi.a && x.a + x.b <= n; x.a++) {
                int64_t w1 = la_cross(t.p[2], t.p[0], x), w2 = la_cross(t.p[0], t.p[1], x);
                int64_t w0 = area - w1 - w2;
                if (w0 < 0 || w1 < 0 || w2 < 0 || w0 == area || w1 == area || w2 == area) continue;
                subd_la_eval_point(s, x, y, 0);
                if (!la_within(s, y, c[0], c[1], c[2], SUBD_REAL_FRAC(w1, area), SUBD_REAL_FRAC(w2, area)) &&
                    !la_near_holds(s, x, y))
                    return 0;
            }
        if (s->ovf) return 0;
    }
    return 1;
}

/* CHORD: the smallest level at which face g's uniform triangles (every edge at that level)
 * hold its level-L limit points within eps (L: always). A function of g alone, asked by g
 * and by its three neighbours in each pass: remembered in lay.memo when there is one. */
static uint32_t la_face_own(la_state *s, uint32_t g)
{
    uint32_t L = s->o.loop.levels, l, j, *mm = s->lay.memo ? s->lay.memo + 2u * (g % SUBD_LOOP_ADAPT_MEMO_) : 0;
    la_face keep = s->fc;
    if (mm && mm[0] == g) return mm[1];
    s->gf = g;
    for (l = 0; l < L; l++) {
        s->fc.l = l;
        for (j = 0; j < 3u; j++) s->fc.e[j] = l;
        subd_la_face_setup_ring(&s->fc);
        if (la_face_ok(s)) break;
    }
    s->fc = keep;
    s->gf = s->f;
    if (mm && !s->ovf) {
        mm[0] = g;
        mm[1] = l;
    }
    return l;
}

/* The levels of the current face and its edges. */
void subd_la_face_levels(la_state *s)
{
    const subd_mesh *in = s->in;
    uint32_t L = s->o.loop.levels, j, f = s->f, l, own, og[3];
    la_face *fc = &s->fc;
    if (s->o.mode == SUBD_LOOP_ADAPT_CALLBACK) {
        uint32_t lf = s->o.face_level(s->o.user, f);
        fc->l = lf < L ? lf : L;
        for (j = 0; j < 3u; j++) {
            uint32_t tw = in->twin[3u * f + j], lg;
            fc->e[j] = fc->l;
            if (tw == SUBD_NONE) continue;
            lg = s->o.face_level(s->o.user, tw / 3u);
            if (lg < fc->e[j]) fc->e[j] = lg;
        }
        subd_la_face_setup_ring(fc);
        return;
    }
    l = 0;
    for (j = 0; j < 3u; j++) { /* the neighbours first: face f's points stay in the cache after */
        uint32_t tw = in->twin[3u * f + j];
        og[j] = tw == SUBD_NONE ? SUBD_NONE : la_face_own(s, tw / 3u);
    }
    own = la_face_own(s, f);
    for (j = 0; j < 3u; j++) {
        uint32_t o1 = own, o2;
        fc->e[j] = la_edge_chord(s, j);
        /* not below the level both faces would take uniformly (la_face_own: a function of
         * the face alone, so both faces compute the same): a coarser edge would force its
         * faces into transitions finer than they need */
        o2 = og[j] == SUBD_NONE ? o1 : og[j];
        if (o2 < o1) o1 = o2;
        if (o1 > fc->e[j]) fc->e[j] = o1;
        if (fc->e[j] > l) l = fc->e[j];
    }
    s->gf = f;
    fc->own = own;
    for (; l < L; l++) {
        fc->l = l;
        subd_la_face_setup_ring(fc);
        if (la_face_ok(s)) return;
    }
    fc->l = L;
    subd_la_face_setup_ring(fc);
}

/* Every face at uniform level u (CHORD's fallback). */
void subd_la_face_uniform(la_face *fc, uint32_t u)
{
    fc->l = fc->e[0] = fc->e[1] = fc->e[2] = u;
    subd_la_face_setup_ring(fc);
}

/* CHORD, before the first triangle: the adaptive cut's triangle count A and the uniform
 * level U = the largest own level (la_face_own) over the faces; when A exceeds the 4^U F
 * triangles of level U and every face passes the chord check at U (la_face_ok: a face's own
 * level is the first that passes, a higher one is checked again), the stream emits level U
 * instead (s->uni), a cut with the same guarantee and fewer triangles. One pass of the level
 * choice over the mesh (the emission pass repeats it): about twice the work, no memory. */
int subd_la_prepass(la_state *s, subd_diag *d)
{
    uint32_t L = s->o.loop.levels, F = s->in->num_faces, f, u = 0, ok = 1, l;
    uint64_t adapt = 0;
    la_iter it;
    la_tri t;
    for (f = 0; f < F; f++) {
        s->f = s->gf = f;
        subd_la_face_levels(s);
        if (s->ovf) break;
        it.phase = it.j = it.io = it.ii = 0;
        while (subd_la_next(&s->fc, L, &it, &t)) adapt++;
        /* the face's smallest uniform level with its edge neighbours' triangles as
         * witnesses too (at most its own level, which passes without them) */
        s->nb = 1;
        for (l = 0; l < s->fc.own; l++) {
            la_face keep = s->fc;
            subd_la_face_uniform(&s->fc, l);
            ok = la_face_ok(s) && !s->ovf;
            s->fc = keep;
            if (ok) break;
        }
        s->nb = 0;
        if (l > u) u = l;
    }
    ok = 1;
    if (!s->ovf && adapt > ((uint64_t)F << (2u * u)) && u < L) {
        s->nb = 1;
        for (f = 0; ok && f < F; f++) {
            s->f = s->gf = f;
            subd_la_face_uniform(&s->fc, u);
            ok = la_face_ok(s) && !s->ovf;
        }
        s->nb = 0;
    }
    if (s->ovf) {
        d->face = s->f;
        return SUBD_ERR_RANGE;
    }
    s->uni = adapt > ((uint64_t)F << (2u * u)) && ok ? u : SUBD_NONE;
    s->f = s->gf = 0;
    s->pre = 1;
    return SUBD_OK;
}
