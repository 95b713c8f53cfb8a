/* SPDX-License-Identifier: MIT */
/* Variable-resolution extraction from the semi-regular 4-8 hierarchy (src/sr48_extract.c,
 * paper section 3 and 7). Hierarchies are built here by an independent routine that
 * follows the index rules of subd_sr48.h (a square = one diamond, a cube = six
 * diamonds projected to the unit sphere; vertices carry integer parameters so every
 * position is a function of the parameter), and, when the scheme's builder is linked, by
 * subd_sr48_build from the corpus meshes.
 * Every extracted mesh is checked against independent properties computed here in double:
 *  - it is a cut of the hierarchy: each output face is a hierarchy triangle (found through
 *    the positions), in the hierarchy's orientation, and the faces partition level
 *    max_level exactly (every level-max triangle lies under exactly one face);
 *  - conforming: no output vertex lies strictly inside an output edge (through the
 *    hierarchy's base-edge midpoints, recursively), the validator accepted it (each edge
 *    shared by at most two faces, consistently oriented), closed input gives zero boundary
 *    edges, the Euler characteristic is that of level 0; edge neighbours differ by at most
 *    one level;
 *  - the local level follows the adaptation function up to forced splits: every face below
 *    max_level does not want a split, every split diamond either wanted it or has a split
 *    child (removing its split would break the cut); the forced count matches when no
 *    triangle is within the rounding tolerance of its threshold;
 *  - CHORD: every vertex of levels <= max_level is within eps of the output (distance to
 *    the face over it; on the host also the brute-force minimum over all faces), and
 *    saved = uniform faces - faces;
 *  - UNIFORM is level k of the hierarchy (counts from level_tri / level_verts), plan = peak;
 *  - every too-small arena fails cleanly, bad parameters, output hashes for host = QEMU. */
#include "harness.h"
#include "fixtures.h"
#include "subd_sr48.h"
#include "corpus.h"
#include <stdlib.h>
#if H_HOST
#include <stdio.h>
#endif

#define MAXT 8192
#define MAXV 4096
#define PSCALE 4096 /* parameter of the square's / cube's corners */

static uint32_t g_tv[3 * MAXT], g_nb[MAXT], g_mid[MAXT];
static subd_real g_pos[3 * MAXV];
static int32_t g_par[3 * MAXV];
static subd_sr48 g_h;
static int g_have_par; /* g_par holds the parameters of g_h's vertices (hand-built)   */

/* ------------------------------------------------------------------------------------ */
/* Scalars                                                                                 */

static double dsqrt(double x)
{
    double r = x > 1 ? x : 1;
    int i;
    if (x <= 0) return 0;
    for (i = 0; i < 60; i++) r = 0.5 * (r + x / r);
    return r;
}
static double dabs(double x) { return x < 0 ? -x : x; }
static double dot3(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
static void sub3(const double *a, const double *b, double *r)
{
    r[0] = a[0] - b[0]; r[1] = a[1] - b[1]; r[2] = a[2] - b[2];
}
static void hpos(const subd_sr48 *h, uint32_t v, double *p)
{
    p[0] = h_dbl(h->pos[3 * v]); p[1] = h_dbl(h->pos[3 * v + 1]); p[2] = h_dbl(h->pos[3 * v + 2]);
}

static double seg_dist(const double *p, const double *a, const double *b)
{
    double ab[3], ap[3], q[3], t, l2;
    sub3(b, a, ab); sub3(p, a, ap);
    l2 = dot3(ab, ab);
    t = l2 > 0 ? dot3(ap, ab) / l2 : 0;
    if (t < 0) t = 0;
    if (t > 1) t = 1;
    q[0] = ap[0] - t * ab[0]; q[1] = ap[1] - t * ab[1]; q[2] = ap[2] - t * ab[2];
    return dsqrt(dot3(q, q));
}

/* Point to triangle, written differently from the library: projection onto the plane with
 * barycentric coordinates (inside: the plane distance), otherwise the nearest edge. */
static double tri_dist(const double *p, const double *a, const double *b, const double *c)
{
    double e0[3], e1[3], ap[3], d00, d01, d11, d20, d21, den, v, w, u, best, s;
    sub3(b, a, e0); sub3(c, a, e1); sub3(p, a, ap);
    d00 = dot3(e0, e0); d01 = dot3(e0, e1); d11 = dot3(e1, e1);
    d20 = dot3(ap, e0); d21 = dot3(ap, e1);
    den = d00 * d11 - d01 * d01;
    if (den > 1e-300) {
        v = (d11 * d20 - d01 * d21) / den;
        w = (d00 * d21 - d01 * d20) / den;
        u = 1 - v - w;
        if (u >= 0 && v >= 0 && w >= 0) {
            double q[3];
            q[0] = ap[0] - v * e0[0] - w * e1[0];
            q[1] = ap[1] - v * e0[1] - w * e1[1];
            q[2] = ap[2] - v * e0[2] - w * e1[2];
            return dsqrt(dot3(q, q));
        }
    }
    best = seg_dist(p, a, b);
    s = seg_dist(p, b, c); if (s < best) best = s;
    s = seg_dist(p, c, a); if (s < best) best = s;
    return best;
}

/* ------------------------------------------------------------------------------------ */
/* An independent hierarchy builder following the header's index rules.                  */

typedef void (*pos_fn)(const int32_t *par, double *p);

static int key_cmp(const void *x, const void *y)
{
    const uint64_t *a = (const uint64_t *)x, *b = (const uint64_t *)y;
    return a[0] < b[0] ? -1 : a[0] > b[0] ? 1 : 0;
}

/* Base neighbours of triangles [t0, t1): the one with the same base edge reversed. */
static uint64_t g_keys[2 * MAXT];
static void match_bases(uint32_t t0, uint32_t t1)
{
    uint32_t t, n = 0, i;
    for (t = t0; t < t1; t++) {
        uint32_t a = g_tv[3 * t + 1], b = g_tv[3 * t + 2];
        uint32_t lo = a < b ? a : b, hi = a < b ? b : a;
        g_keys[2 * n] = ((uint64_t)lo << 32) | hi;
        g_keys[2 * n + 1] = t;
        g_nb[t] = SUBD_NONE;
        n++;
    }
    qsort(g_keys, n, 2 * sizeof(uint64_t), key_cmp);
    for (i = 0; i + 1 < n; i++) {
        if (g_keys[2 * i] == g_keys[2 * i + 2]) {
            uint32_t a = (uint32_t)g_keys[2 * i + 1], b = (uint32_t)g_keys[2 * i + 3];
            CHECK(g_tv[3 * a + 1] == g_tv[3 * b + 2] && g_tv[3 * a + 2] == g_tv[3 * b + 1]);
            g_nb[a] = b;
            g_nb[b] = a;
        }
    }
}

static int hb_build(uint32_t nv0, const int32_t *par0, uint32_t nt0, const uint32_t *tv0, uint32_t steps,
                    pos_fn f, subd_sr48 *h)
{
    uint32_t k, t, i, nv = nv0;
    if (!CHECK(nt0 * ((1u << (steps + 1)) - 1u) <= MAXT)) return 0;
    for (i = 0; i < 3 * nv0; i++) g_par[i] = par0[i];
    for (i = 0; i < 3 * nt0; i++) g_tv[i] = tv0[i];
    h->steps = steps;
    h->flags = 0;
    h->num_input_verts = nv0;
    h->level_tri[0] = 0;
    h->level_tri[1] = nt0;
    h->level_verts[0] = nv0;
    match_bases(0, nt0);
    for (k = 0; k < steps; k++) {
        uint32_t t0 = h->level_tri[k], t1 = h->level_tri[k + 1], n = t1 - t0;
        for (t = t0; t < t1; t++) g_mid[t] = SUBD_NONE;
        for (t = t0; t < t1; t++) {
            uint32_t c = g_tv[3 * t], a = g_tv[3 * t + 1], b = g_tv[3 * t + 2], m, c0;
            if (g_mid[t] == SUBD_NONE) {
                if (!CHECK(nv < MAXV)) return 0;
                m = nv++;
                for (i = 0; i < 3; i++) {
                    int32_t s = g_par[3 * a + i] + g_par[3 * b + i];
                    CHECK((s & 1) == 0);
                    g_par[3 * m + i] = s / 2;
                }
                g_mid[t] = m;
                if (g_nb[t] != SUBD_NONE) g_mid[g_nb[t]] = m;
            }
            m = g_mid[t];
            c0 = t1 + 2 * (t - t0);
            g_tv[3 * c0] = m; g_tv[3 * c0 + 1] = c; g_tv[3 * c0 + 2] = a;
            g_tv[3 * c0 + 3] = m; g_tv[3 * c0 + 4] = b; g_tv[3 * c0 + 5] = c;
        }
        h->level_tri[k + 2] = t1 + 2 * n;
        h->level_verts[k + 1] = nv;
        match_bases(t1, t1 + 2 * n);
    }
    for (i = 0; i < nv; i++) {
        double p[3];
        f(g_par + 3 * i, p);
        g_pos[3 * i] = fx_real(p[0]); g_pos[3 * i + 1] = fx_real(p[1]); g_pos[3 * i + 2] = fx_real(p[2]);
    }
    h->num_verts = nv;
    h->num_tris = h->level_tri[steps + 1];
    h->pos = g_pos;
    h->tri_vert = g_tv;
    h->tri_base_nb = g_nb;
    h->num_clusters = h->num_isolated = 0;
    g_have_par = 1;
    return 1;
}

/* The unit square as one diamond, lifted to a smooth hill z(x, y). */
static void square_pos(const int32_t *par, double *p)
{
    double x = (double)par[0] / PSCALE, y = (double)par[1] / PSCALE;
    p[0] = x; p[1] = y;
    p[2] = 3.2 * x * y * (1 - x) * (1 - y) + 0.1 * x * x * x;
}
static int build_square(uint32_t steps)
{
    static const int32_t par[12] = {0, 0, 0, PSCALE, 0, 0, PSCALE, PSCALE, 0, 0, PSCALE, 0};
    static const uint32_t tv[6] = {1, 2, 0, 3, 0, 2}; /* (B; C, A), (D; A, C) */
    return hb_build(4, par, 2, tv, steps, square_pos, &g_h);
}

/* A cube (six diamonds, one per face) projected to the unit sphere. */
static void sphere_pos(const int32_t *par, double *p)
{
    double x = par[0], y = par[1], z = par[2], l = dsqrt(x * x + y * y + z * z);
    p[0] = x / l; p[1] = y / l; p[2] = z / l;
}
static int build_cube(uint32_t steps)
{
    static const uint32_t quad[24] = {0, 2, 3, 1, 4, 5, 7, 6, 0, 1, 5, 4, 2, 6, 7, 3, 0, 4, 6, 2, 1, 3, 7, 5};
    int32_t par[24];
    uint32_t tv[36], i;
    for (i = 0; i < 8; i++) {
        par[3 * i] = (i & 1) ? PSCALE : -PSCALE;
        par[3 * i + 1] = (i & 2) ? PSCALE : -PSCALE;
        par[3 * i + 2] = (i & 4) ? PSCALE : -PSCALE;
    }
    for (i = 0; i < 6; i++) {
        const uint32_t *q = quad + 4 * i;
        tv[6 * i] = q[1]; tv[6 * i + 1] = q[2]; tv[6 * i + 2] = q[0];
        tv[6 * i + 3] = q[3]; tv[6 * i + 4] = q[0]; tv[6 * i + 5] = q[2];
    }
    return hb_build(8, par, 12, tv, steps, sphere_pos, &g_h);
}

/* ------------------------------------------------------------------------------------ */
/* Independent evaluation of the adaptation functions (double).                            */

typedef struct tctx {
    const subd_sr48 *h;
    const subd_sr48_adapt *ad;
    double lo[3], hi[3], radius;
    uint32_t max;
} tctx;

static uint32_t tri_level(const subd_sr48 *h, uint32_t t)
{
    uint32_t k = 0;
    while (t >= h->level_tri[k + 1]) k++;
    return k;
}
static uint32_t parent_of(const subd_sr48 *h, uint32_t t, uint32_t k)
{
    return h->level_tri[k - 1] + (t - h->level_tri[k]) / 2;
}

/* Largest |P(v) - L_t(v)| over t's subtree down to level max (recursion is fine in tests). */
static double chord_dev(const tctx *c, uint32_t t, uint32_t k, const double *la, const double *lb0, const double *lb1)
{
    const subd_sr48 *h = c->h;
    uint32_t c0 = h->level_tri[k + 1] + 2 * (t - h->level_tri[k]), m = h->tri_vert[3 * c0], i;
    double lm[3], p[3], dv, s;
    for (i = 0; i < 3; i++) lm[i] = 0.5 * (lb0[i] + lb1[i]);
    hpos(h, m, p);
    sub3(p, lm, p);
    dv = dsqrt(dot3(p, p));
    if (k + 1 < c->max) {
        s = chord_dev(c, c0, k + 1, lm, la, lb0);
        if (s > dv) dv = s;
        s = chord_dev(c, c0 + 1, k + 1, lm, lb1, la);
        if (s > dv) dv = s;
    }
    return dv;
}

/* The nested region of POINT, RAMP and PLANE, brute force: L (the level-0 triangles'
 * finest corner positions, interpolated by base midpoints down the child path) over every
 * level-k triangle that shares a vertex with t's diamond, found by scanning the level. */
static void tri_lin(const subd_sr48 *h, uint32_t x, uint32_t k, double *l)
{
    uint32_t i = x - h->level_tri[k], a = i >> k, j, q;
    for (j = 0; j < 3; j++) hpos(h, h->tri_vert[3 * a + j], l + 3 * j);
    for (j = k; j > 0; j--) {
        double m[3], o[6];
        for (q = 0; q < 3; q++) m[q] = 0.5 * (l[3 + q] + l[6 + q]);
        for (q = 0; q < 3; q++) {
            o[q] = ((i >> (j - 1)) & 1) ? l[6 + q] : l[q];
            o[3 + q] = ((i >> (j - 1)) & 1) ? l[q] : l[3 + q];
        }
        for (q = 0; q < 3; q++) { l[q] = m[q]; l[3 + q] = o[q]; l[6 + q] = o[3 + q]; }
    }
}
static void star_box(const subd_sr48 *h, uint32_t t, uint32_t k, double *lo, double *hi)
{
    uint32_t vs[4], nv = 3, u, j, q, nb = h->tri_base_nb[t];
    for (j = 0; j < 3; j++) vs[j] = h->tri_vert[3 * t + j];
    if (nb != SUBD_NONE) vs[nv++] = h->tri_vert[3 * nb];
    for (j = 0; j < 3; j++) { lo[j] = 1e300; hi[j] = -1e300; }
    for (u = h->level_tri[k]; u < h->level_tri[k + 1]; u++) {
        int touch = 0;
        double l[9];
        for (j = 0; j < 3; j++)
            for (q = 0; q < nv; q++) if (h->tri_vert[3 * u + j] == vs[q]) touch = 1;
        if (!touch) continue;
        tri_lin(h, u, k, l);
        for (j = 0; j < 9; j++) {
            if (l[j] < lo[j % 3]) lo[j % 3] = l[j];
            if (l[j] > hi[j % 3]) hi[j % 3] = l[j];
        }
    }
}

static uint32_t g_cb_calls;
/* The callback's level rule on a region box (monotone: a smaller box - lower hi, higher lo -
 * never gets a higher level), in double for the reference; *near: how close the box is to
 * a threshold (a rounding difference there could change the answer). */
static uint32_t cb_rule(const double *lo, const double *hi, double *near)
{
    double n = dabs(hi[2] - 0.5);
    if (dabs(hi[2] - 0.1) < n) n = dabs(hi[2] - 0.1);
    if (dabs(lo[0] + 0.05) < n) n = dabs(lo[0] + 0.05);
    *near = n;
    if (hi[2] > 0.5) return 6;
    if (hi[2] > 0.1) return 4;
    if (lo[0] < -0.05) return 2;
    return 1;
}
static uint32_t cb_level(void *ctx, const subd_real *lo, const subd_real *hi)
{
    /* finest where the region reaches high z, coarse elsewhere */
    double l[3], h[3], near;
    uint32_t i;
    (void)ctx;
    g_cb_calls++;
    for (i = 0; i < 3; i++) {
        l[i] = h_dbl(lo[i]);
        h[i] = h_dbl(hi[i]);
    }
    return cb_rule(l, h, &near);
}

/* > 0: the triangle asks for a split; |margin| <= tolerance: too close to call. */
static double margin(const tctx *c, uint32_t t, uint32_t k)
{
    const subd_sr48 *h = c->h;
    const subd_sr48_adapt *ad = c->ad;
    double p[3][3], blo[3], bhi[3], m = -1e300;
    uint32_t i;
    for (i = 0; i < 3; i++) hpos(h, h->tri_vert[3 * t + i], p[i]);
    switch (ad->mode) {
    case SUBD_SR48_ADAPT_UNIFORM: return 1;
    case SUBD_SR48_ADAPT_POINT: {
        double d2 = 0, r = (double)(c->max - k) * c->radius;
        star_box(h, t, k, blo, bhi);
        for (i = 0; i < 3; i++) {
            double pv = h_dbl(ad->point[i]), d = pv < blo[i] ? blo[i] - pv : pv > bhi[i] ? pv - bhi[i] : 0;
            d2 += d * d;
        }
        return r - dsqrt(d2);
    }
    case SUBD_SR48_ADAPT_RAMP: {
        double lo = c->lo[ad->axis], hi = c->hi[ad->axis];
        star_box(h, t, k, blo, bhi);
        return (double)c->max * (bhi[ad->axis] - lo) - (double)(k + 1) * (hi - lo) + 1e-12;
    }
    case SUBD_SR48_ADAPT_PLANE:
        star_box(h, t, k, blo, bhi);
        for (i = 0; i < 8; i++) {
            double s = 0;
            uint32_t j;
            for (j = 0; j < 3; j++) s += (((i >> j) & 1) ? bhi[j] : blo[j]) * h_dbl(ad->normal[j]) -
                                         h_dbl(ad->point[j]) * h_dbl(ad->normal[j]);
            if (s > m) m = s;
        }
        return m + 1e-12;
    case SUBD_SR48_ADAPT_CALLBACK: {
        double near;
        uint32_t lv;
        star_box(h, t, k, blo, bhi);
        lv = cb_rule(blo, bhi, &near);
        if (near < 1e-4) return 0; /* too close to call (the library's box is rounded) */
        return (double)lv - (double)k - 0.5;
    }
    case SUBD_SR48_ADAPT_CHORD:
        return chord_dev(c, t, k, p[0], p[1], p[2]) - h_dbl(ad->eps);
    }
    return 0;
}

static void tctx_init(tctx *c, const subd_sr48 *h, const subd_sr48_adapt *ad)
{
    uint32_t v, i, nv;
    double p[3], dg;
    c->h = h;
    c->ad = ad;
    c->max = ad->max_level;
    /* the adaptation box: the level-0 triangles' corners */
    hpos(h, h->tri_vert[0], c->lo);
    hpos(h, h->tri_vert[0], c->hi);
    nv = 3 * h->level_tri[1];
    for (v = 1; v < nv; v++) {
        hpos(h, h->tri_vert[v], p);
        for (i = 0; i < 3; i++) {
            if (p[i] < c->lo[i]) c->lo[i] = p[i];
            if (p[i] > c->hi[i]) c->hi[i] = p[i];
        }
    }
    sub3(c->hi, c->lo, p);
    dg = dsqrt(dot3(p, p));
    c->radius = h_dbl(ad->radius);
    if (ad->mode == SUBD_SR48_ADAPT_POINT && ad->radius == 0 && c->max > 0) c->radius = dg / (2.0 * c->max);
}

/* ------------------------------------------------------------------------------------ */
/* The property checks.                                                                   */

static uint32_t g_omap[MAXV];      /* output vertex -> hierarchy vertex                   */
static uint8_t g_used[MAXV];       /* hierarchy vertex used by the output                 */
static uint32_t g_leaf[MAXT];      /* output face -> hierarchy triangle                   */
static uint8_t g_state[MAXT];      /* 1 leaf, 2 split                                      */
static uint8_t g_cover[MAXT];
#define g_edge g_keys           /* base edge key -> midpoint (after the face lookup)   */
static uint32_t g_nedge;

static uint64_t ekey(uint32_t a, uint32_t b)
{
    return a < b ? ((uint64_t)a << 32) | b : ((uint64_t)b << 32) | a;
}
static uint32_t edge_mid(uint32_t a, uint32_t b)
{
    uint64_t k[2];
    const uint64_t *r;
    k[0] = ekey(a, b);
    r = (const uint64_t *)bsearch(k, g_edge, g_nedge, 2 * sizeof(uint64_t), key_cmp);
    return r ? (uint32_t)r[1] : SUBD_NONE;
}
/* Is a used vertex strictly inside the hierarchy edge (a, b)? Its halves are base edges
 * two levels finer. */
static int inside_used(uint32_t a, uint32_t b)
{
    uint32_t m = edge_mid(a, b);
    if (m == SUBD_NONE) return 0;
    if (g_used[m]) return 1;
    return inside_used(a, m) || inside_used(m, b);
}

typedef struct cut_result {
    uint32_t ambiguous, forced, leaves_below_max;
} cut_result;

/* Euler characteristic and closedness of level 0, from its edges (each undirected edge
 * twice: closed). */
static void level0_topology(const subd_sr48 *h, int32_t *chi, int *closed)
{
    uint32_t n = 0, t, j, e = 0, nv = 0, bnd = 0;
    for (t = 0; t < h->level_tri[1]; t++)
        for (j = 0; j < 3; j++) {
            g_keys[2 * n] = ekey(h->tri_vert[3 * t + j], h->tri_vert[3 * t + (j + 1) % 3]);
            g_keys[2 * n + 1] = 0;
            n++;
        }
    qsort(g_keys, n, 2 * sizeof(uint64_t), key_cmp);
    for (j = 0; j < n; j++) {
        if (j > 0 && g_keys[2 * j] == g_keys[2 * j - 2]) continue;
        e++;
        if (j + 1 >= n || g_keys[2 * j + 2] != g_keys[2 * j]) bnd++;
    }
    for (j = 0; j < h->level_verts[0]; j++) g_used[j] = 0;
    for (t = 0; t < 3 * h->level_tri[1]; t++) g_used[h->tri_vert[t]] = 1;
    for (j = 0; j < h->level_verts[0]; j++) nv += g_used[j];
    *chi = (int32_t)nv - (int32_t)e + (int32_t)h->level_tri[1];
    *closed = bnd == 0;
}

static int same_bits(const subd_real *a, const subd_real *b)
{
    return h_same(a[0], b[0]) && h_same(a[1], b[1]) && h_same(a[2], b[2]);
}

static void check_cut(const subd_sr48 *h, const subd_sr48_adapt *ad, const subd_mesh *out, const subd_sr48_adapt_report *rep,
                      double tol, cut_result *res)
{
    tctx c;
    uint32_t max = ad->max_level, v, j, f, t, k, nt = h->level_tri[max + 1], hv = 0;
    uint32_t total = h->level_tri[max + 1] - h->level_tri[max], lf[SUBD_SR48_MAX_STEPS + 1];
    int32_t chi0;
    int closed0;
    tctx_init(&c, h, ad);
    level0_topology(h, &chi0, &closed0);
    res->ambiguous = res->forced = res->leaves_below_max = 0;
    if (!CHECK(nt <= MAXT && h->num_verts <= MAXV && out->num_verts <= MAXV)) return;
    CHECK_EQ(out->num_corners, 3 * out->num_faces);
    /* output vertices: the used hierarchy vertices in increasing order (matched by bits) */
    for (v = 0; v < h->num_verts; v++) g_used[v] = 0;
    for (j = 0; j < out->num_verts; j++) {
        while (hv < h->level_verts[max] && !same_bits(h->pos + 3 * hv, out->pos + 3 * j)) hv++;
        if (!CHECK(hv < h->level_verts[max])) return;
        g_omap[j] = hv;
        g_used[hv] = 1;
        hv++;
    }
    /* triangles of levels <= max by sorted vertex triple */
    for (t = 0; t < nt; t++) {
        uint32_t a = h->tri_vert[3 * t], b = h->tri_vert[3 * t + 1], d = h->tri_vert[3 * t + 2], x;
        if (a > b) { x = a; a = b; b = x; }
        if (b > d) { x = b; b = d; d = x; }
        if (a > b) { x = a; a = b; b = x; }
        g_keys[2 * t] = ((uint64_t)a << 42) | ((uint64_t)b << 21) | d;
        g_keys[2 * t + 1] = t;
        g_state[t] = 0;
    }
    qsort(g_keys, nt, 2 * sizeof(uint64_t), key_cmp);
    for (k = 0; k <= SUBD_SR48_MAX_STEPS; k++) lf[k] = 0;
    for (f = 0; f < out->num_faces; f++) {
        uint32_t w[3], a, b, d, x, r;
        uint64_t key[2];
        const uint64_t *hit;
        const uint32_t *tv;
        for (j = 0; j < 3; j++) w[j] = g_omap[out->corner_vert[3 * f + j]];
        a = w[0]; b = w[1]; d = w[2];
        if (a > b) { x = a; a = b; b = x; }
        if (b > d) { x = b; b = d; d = x; }
        if (a > b) { x = a; a = b; b = x; }
        key[0] = ((uint64_t)a << 42) | ((uint64_t)b << 21) | d;
        hit = (const uint64_t *)bsearch(key, g_keys, nt, 2 * sizeof(uint64_t), key_cmp);
        if (!CHECK(hit != 0)) return;
        t = (uint32_t)hit[1];
        g_leaf[f] = t;
        tv = h->tri_vert + 3 * t;
        /* same orientation: a rotation of (apex, b0, b1) */
        for (r = 0; r < 3; r++)
            if (w[0] == tv[r] && w[1] == tv[(r + 1) % 3] && w[2] == tv[(r + 2) % 3]) break;
        CHECK(r < 3);
        CHECK(g_state[t] == 0);
        g_state[t] = 1;
        lf[tri_level(h, t)]++;
    }
    /* partition of level max */
    for (j = 0; j < total; j++) g_cover[j] = 0;
    for (f = 0; f < out->num_faces; f++) {
        uint32_t lv = tri_level(h, g_leaf[f]), i = g_leaf[f] - h->level_tri[lv], s = max - lv;
        for (j = i << s; j < (i + 1) << s; j++) g_cover[j]++;
        for (t = g_leaf[f], k = lv; k > 0; k--) {
            t = parent_of(h, t, k);
            CHECK(g_state[t] != 1); /* a face under another face */
            g_state[t] = 2;
        }
    }
    for (j = 0; j < total; j++)
        if (!CHECK_EQ(g_cover[j], 1)) break;
    /* report */
    CHECK_EQ(rep->faces, out->num_faces);
    CHECK_EQ(rep->uniform_faces, total);
    for (k = 0; k <= SUBD_SR48_MAX_STEPS; k++) CHECK_EQ(rep->level_faces[k], lf[k]);
    /* edge neighbours differ by at most one level; no used vertex inside an output edge */
    g_nedge = 0;
    for (t = 0; t < h->level_tri[h->steps]; t++) {
        uint32_t nb = h->tri_base_nb[t], kk = tri_level(h, t);
        if (nb != SUBD_NONE && nb < t) continue;
        g_edge[2 * g_nedge] = ekey(h->tri_vert[3 * t + 1], h->tri_vert[3 * t + 2]);
        g_edge[2 * g_nedge + 1] = h->tri_vert[3 * (h->level_tri[kk + 1] + 2 * (t - h->level_tri[kk]))];
        g_nedge++;
    }
    qsort(g_edge, g_nedge, 2 * sizeof(uint64_t), key_cmp);
    for (j = 0; j < out->num_corners; j++) {
        uint32_t tw = out->twin[j], f0 = j / 3, a = g_omap[out->corner_vert[j]];
        uint32_t b = g_omap[out->corner_vert[f0 * 3 + (j + 1) % 3]];
        if (tw != SUBD_NONE) {
            int32_t d = (int32_t)tri_level(h, g_leaf[f0]) - (int32_t)tri_level(h, g_leaf[tw / 3]);
            CHECK(d >= -1 && d <= 1);
        }
        if (!CHECK(!inside_used(a, b))) break;
    }
    /* brute force in parameter space (hand-built hierarchies: integer parameters, every
     * edge inside one plane of the square or a cube face): no output vertex strictly
     * inside an output edge */
    if (g_have_par && h == &g_h) {
        uint32_t bad = 0;
        for (j = 0; j < out->num_corners && !bad; j++) {
            const int32_t *pa = g_par + 3 * g_omap[out->corner_vert[j]];
            const int32_t *pb = g_par + 3 * g_omap[out->corner_vert[(j / 3) * 3 + (j + 1) % 3]];
            int64_t e[3], l2;
            e[0] = pb[0] - pa[0]; e[1] = pb[1] - pa[1]; e[2] = pb[2] - pa[2];
            l2 = e[0] * e[0] + e[1] * e[1] + e[2] * e[2];
            for (v = 0; v < out->num_verts; v++) {
                const int32_t *px = g_par + 3 * g_omap[v];
                int64_t q[3], dt;
                q[0] = px[0] - pa[0]; q[1] = px[1] - pa[1]; q[2] = px[2] - pa[2];
                if (q[1] * e[2] - q[2] * e[1] || q[2] * e[0] - q[0] * e[2] || q[0] * e[1] - q[1] * e[0]) continue;
                dt = q[0] * e[0] + q[1] * e[1] + q[2] * e[2];
                if (dt > 0 && dt < l2) bad++;
            }
        }
        CHECK_EQ(bad, 0);
    }
    /* closed stays closed, Euler characteristic of level 0 */
    CHECK_EQ(subd_mesh_euler(out), chi0);
    if (closed0) CHECK_EQ(out->num_boundary_edges, 0);
    /* the adaptation function, up to forced splits */
    for (t = 0; t < h->level_tri[max]; t++) {
        double mg;
        uint32_t kk = tri_level(h, t), nb = h->tri_base_nb[t];
        if (g_state[t] == 0) continue;
        mg = margin(&c, t, kk);
        if (dabs(mg) <= tol) res->ambiguous++;
        if (g_state[t] == 1) {
            res->leaves_below_max++;
            if (!CHECK(mg <= tol)) {
                h_str("    leaf wants a split: level ");
                h_u32(kk);
                h_nl();
            }
            continue;
        }
        /* split: the diamond as a whole */
        if (nb != SUBD_NONE) CHECK_EQ(g_state[nb], 2);
        if (nb != SUBD_NONE && nb < t) continue;
        {
            double mn = nb != SUBD_NONE ? margin(&c, nb, kk) : -1e300;
            uint32_t c0 = h->level_tri[kk + 1] + 2 * (t - h->level_tri[kk]), needed;
            if (nb != SUBD_NONE && dabs(mn) <= tol) res->ambiguous++;
            if (mg > 0 || mn > 0) continue;
            needed = g_state[c0] == 2 || g_state[c0 + 1] == 2;
            if (nb != SUBD_NONE) {
                uint32_t c1 = h->level_tri[kk + 1] + 2 * (nb - h->level_tri[kk]);
                needed = needed || g_state[c1] == 2 || g_state[c1 + 1] == 2;
            }
            res->forced++;
            if (!CHECK(needed || mg > -tol || mn > -tol)) {
                h_str("    unneeded split at level ");
                h_u32(kk);
                h_nl();
            }
        }
    }
    if (res->ambiguous == 0) CHECK_EQ(rep->forced_splits, res->forced);
    /* POINT, RAMP and PLANE are nested (a wanted split's parent diamonds want theirs): the
     * least conforming cut needs no forced split */
    if (ad->mode == SUBD_SR48_ADAPT_POINT || ad->mode == SUBD_SR48_ADAPT_RAMP || ad->mode == SUBD_SR48_ADAPT_PLANE ||
        ad->mode == SUBD_SR48_ADAPT_CALLBACK) { /* CALLBACK: cb_level is monotone */
        CHECK_EQ(rep->forced_splits, 0);
        if (res->ambiguous == 0) CHECK_EQ(res->forced, 0);
    }
}

/* CHORD: every vertex of levels <= max is within eps (+ slack) of the face over it. */
static double g_worst;
static void chord_walk(const subd_sr48 *h, uint32_t max, uint32_t t, uint32_t k, const double *a, const double *b,
                       const double *c)
{
    uint32_t c0, m;
    double p[3], d;
    if (k >= max) return;
    c0 = h->level_tri[k + 1] + 2 * (t - h->level_tri[k]);
    m = h->tri_vert[3 * c0];
    hpos(h, m, p);
    d = tri_dist(p, a, b, c);
    if (d > g_worst) g_worst = d;
    chord_walk(h, max, c0, k + 1, a, b, c);
    chord_walk(h, max, c0 + 1, k + 1, a, b, c);
}
static double chord_worst(const subd_sr48 *h, const subd_sr48_adapt *ad, const subd_mesh *out)
{
    uint32_t f, i;
    g_worst = 0;
    for (f = 0; f < out->num_faces; f++) {
        uint32_t t = g_leaf[f];
        double p[3][3];
        for (i = 0; i < 3; i++) hpos(h, h->tri_vert[3 * t + i], p[i]);
        /* the subtree of the face: start the walk at the face itself */
        {
            uint32_t k = tri_level(h, t);
            uint32_t kk = k, tt = t;
            /* walk its own subtree, positions compared with the face's plane triangle */
            chord_walk(h, ad->max_level, tt, kk, p[0], p[1], p[2]);
        }
    }
#if H_HOST
    {
        /* brute force: the minimum over all output faces */
        uint32_t v;
        double worst = 0;
        for (v = 0; v < h->level_verts[ad->max_level]; v++) {
            double p[3], best = 1e300;
            hpos(h, v, p);
            for (f = 0; f < out->num_faces; f++) {
                double a[3], b[3], c[3], d;
                const uint32_t *cv = out->corner_vert + 3 * f;
                a[0] = h_dbl(out->pos[3 * cv[0]]); a[1] = h_dbl(out->pos[3 * cv[0] + 1]); a[2] = h_dbl(out->pos[3 * cv[0] + 2]);
                b[0] = h_dbl(out->pos[3 * cv[1]]); b[1] = h_dbl(out->pos[3 * cv[1] + 1]); b[2] = h_dbl(out->pos[3 * cv[1] + 2]);
                c[0] = h_dbl(out->pos[3 * cv[2]]); c[1] = h_dbl(out->pos[3 * cv[2] + 1]); c[2] = h_dbl(out->pos[3 * cv[2] + 2]);
                d = tri_dist(p, a, b, c);
                if (d < best) best = d;
            }
            if (best > worst) worst = best;
        }
        CHECK(worst <= g_worst + 1e-12);
    }
#endif
    return g_worst;
}

/* ------------------------------------------------------------------------------------ */

static subd_sr48_adapt adapt(subd_sr48_adapt_mode mode, uint32_t max)
{
    subd_sr48_adapt a;
    uint32_t i;
    a.mode = mode;
    a.max_level = max;
    for (i = 0; i < 3; i++) a.point[i] = a.normal[i] = 0;
    a.radius = 0;
    a.axis = 0;
    a.eps = 0;
    a.fn = 0;
    a.ctx = 0;
    return a;
}

static int extract(subd_arena *a, const subd_sr48 *h, const subd_sr48_adapt *ad, subd_mesh *out, subd_sr48_adapt_report *rep)
{
    subd_diag d;
    uint32_t plan;
    int st;
    if (!CHECK_EQ(subd_sr48_extract_plan(h, ad, &plan, 0), SUBD_OK)) return 0;
    subd_arena_reset_peak(a);
    st = subd_sr48_extract(a, h, ad, out, rep, &d);
    return CHECK_OK(st, &d);
}

/* Extract into a fresh arena, run every property check, return the face count. */
static uint32_t run_checked(const subd_sr48 *h, const subd_sr48_adapt *ad, double tol, const char *hash, cut_result *res)
{
    subd_arena a;
    subd_mesh out;
    subd_sr48_adapt_report rep;
    uint32_t plan;
    cut_result dummy;
    if (!res) res = &dummy;
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    if (!CHECK_EQ(subd_sr48_extract_plan(h, ad, &plan, 0), SUBD_OK)) return 0;
    if (!extract(&a, h, ad, &out, &rep)) return 0;
    CHECK(a.peak <= plan);
    check_cut(h, ad, &out, &rep, tol, res);
    if (ad->mode == SUBD_SR48_ADAPT_CHORD) {
        double w = chord_worst(h, ad, &out);
        double slack = SUBD_FIXED ? 4.0 / 65536.0 : 1e-6;
        if (!CHECK(w <= h_dbl(ad->eps) + slack)) {
            h_str("    chordal error above eps\n");
        }
    }
    if (hash) h_hash(hash, h_mesh_hash(&out));
#ifdef SR48X_VERBOSE
    h_str("    mode "); h_u32(ad->mode); h_str(" faces "); h_u32(out.num_faces); h_str(" forced ");
    h_u32(rep.forced_splits); h_str(" ambiguous "); h_u32(res->ambiguous); h_str(" test-forced ");
    h_u32(res->forced); h_str(" levels"); { uint32_t k; for (k = 0; k <= ad->max_level; k++) { h_str(" "); h_u32(rep.level_faces[k]); } }
    h_nl();
#endif
    return out.num_faces;
}

/* UNIFORM at every level is level k of the hierarchy; the plan is exact. */
static void sr48x_uniform(void)
{
    uint32_t pass, k;
    for (pass = 0; pass < 2; pass++) {
        uint32_t steps = pass ? 5 : 6;
        if (!(pass ? build_cube(steps) : build_square(steps))) return;
        for (k = 0; k <= steps; k++) {
            subd_sr48_adapt ad = adapt(SUBD_SR48_ADAPT_UNIFORM, k);
            subd_arena a;
            subd_mesh out;
            subd_sr48_adapt_report rep;
            uint32_t plan, f;
            cut_result res;
            subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
            if (!CHECK_EQ(subd_sr48_extract_plan(&g_h, &ad, &plan, 0), SUBD_OK)) return;
            if (!extract(&a, &g_h, &ad, &out, &rep)) return;
            CHECK_EQ(a.peak, plan);
            CHECK_EQ(out.num_faces, g_h.level_tri[k + 1] - g_h.level_tri[k]);
            CHECK_EQ(out.num_verts, g_h.level_verts[k]);
            CHECK_EQ(rep.faces, out.num_faces);
            CHECK_EQ(rep.uniform_faces, out.num_faces);
            CHECK_EQ(rep.forced_splits, 0);
            CHECK_EQ(rep.level_faces[k], out.num_faces);
            CHECK_EQ(subd_mesh_euler(&out), pass ? 2 : 1);
            if (pass) CHECK_EQ(out.num_boundary_edges, 0);
            else CHECK_EQ(out.num_boundary_edges, 4u << (k / 2));
            for (f = 0; f < out.num_faces; f++) CHECK_EQ(out.face_start[f], 3 * f);
            check_cut(&g_h, &ad, &out, &rep, 0, &res);
            CHECK_EQ(res.leaves_below_max, 0);
            if (k == steps) h_hash(pass ? "sr48x_cube_uniform5" : "sr48x_square_uniform6", h_mesh_hash(&out));
        }
    }
}

static void sr48x_point(void)
{
    subd_sr48_adapt ad = adapt(SUBD_SR48_ADAPT_POINT, 6);
    cut_result res;
    uint32_t n;
    if (!build_cube(6)) return;
    ad.point[0] = fx_real(0.8); ad.point[1] = fx_real(0.5); ad.point[2] = fx_real(0.33);
    n = run_checked(&g_h, &ad, 2e-3, "sr48x_cube_point", &res);
    CHECK(n > 0 && n < 12u * 64u);
    ad.radius = fx_real(0.05);
    n = run_checked(&g_h, &ad, 2e-3, "sr48x_cube_point_r", &res);
    CHECK(n > 0 && n < 12u * 64u);
    /* far away with a tiny radius: level 0 everywhere */
    ad.point[0] = fx_real(30); ad.radius = fx_real(0.001);
    CHECK_EQ(run_checked(&g_h, &ad, 2e-3, 0, &res), 12);
    if (!build_square(8)) return;
    ad = adapt(SUBD_SR48_ADAPT_POINT, 8);
    ad.point[0] = fx_real(0.3); ad.point[1] = fx_real(0.7); ad.point[2] = fx_real(0.1);
    n = run_checked(&g_h, &ad, 2e-3, "sr48x_square_point", &res);
    CHECK(n > 0 && n < 512u);
}

static void sr48x_ramp_plane(void)
{
    uint32_t ax;
    cut_result res;
    static const char *names[3] = {"sr48x_cube_ramp_x", "sr48x_cube_ramp_y", "sr48x_cube_ramp_z"};
    subd_sr48_adapt ad;
    uint32_t n;
    if (!build_cube(6)) return;
    for (ax = 0; ax < 3; ax++) {
        ad = adapt(SUBD_SR48_ADAPT_RAMP, 6);
        ad.axis = ax;
        n = run_checked(&g_h, &ad, 1e-6, names[ax], &res);
        CHECK(n > 12 && n < 12u * 64u);
    }
    ad = adapt(SUBD_SR48_ADAPT_PLANE, 6);
    ad.point[0] = fx_real(0.25); ad.normal[0] = fx_real(1); ad.normal[1] = fx_real(0.5);
    n = run_checked(&g_h, &ad, 1e-6, "sr48x_cube_plane", &res);
    CHECK(n > 12 && n < 12u * 64u);
    /* a step, but the region is nested (star box): the transition needs no forced split */
    CHECK_EQ(res.forced, 0);
    /* the whole surface on the finest side: uniform */
    ad.point[0] = fx_real(-2);
    ad.normal[1] = 0;
    CHECK_EQ(run_checked(&g_h, &ad, 1e-6, 0, &res), 12u * 64u);
    if (!build_square(8)) return;
    ad = adapt(SUBD_SR48_ADAPT_RAMP, 8);
    ad.axis = 1;
    n = run_checked(&g_h, &ad, 1e-6, "sr48x_square_ramp", &res);
    CHECK(n > 2 && n < 512u);
}

static void sr48x_callback(void)
{
    subd_sr48_adapt ad = adapt(SUBD_SR48_ADAPT_CALLBACK, 6);
    cut_result res;
    subd_arena a;
    subd_mesh out;
    subd_sr48_adapt_report rep;
    uint32_t n;
    if (!build_cube(6)) return;
    ad.fn = cb_level;
    g_cb_calls = 0;
    n = run_checked(&g_h, &ad, 1e-9, "sr48x_cube_callback", &res);
    CHECK(n > 12 && n < 12u * 64u);
    /* one call per triangle evaluated: the active ones below max_level */
    g_cb_calls = 0;
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    if (!extract(&a, &g_h, &ad, &out, &rep)) return;
    CHECK(g_cb_calls > 0 && g_cb_calls <= g_h.level_tri[6]);
    CHECK(g_cb_calls <= 2u * rep.faces);
}

static void sr48x_chord(void)
{
    static const double eps_list[4] = {0.1, 0.03, 0.015, 0.006};
    cut_result res;
    uint32_t i, prev = 0;
    if (!build_cube(6)) return;
    for (i = 0; i < 4; i++) {
        subd_sr48_adapt ad = adapt(SUBD_SR48_ADAPT_CHORD, 6);
        subd_arena a;
        subd_mesh out;
        subd_sr48_adapt_report rep;
        ad.eps = fx_real(eps_list[i]);
        (void)run_checked(&g_h, &ad, 1e-5, i == 2 ? "sr48x_cube_chord" : 0, &res);
        subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
        if (!extract(&a, &g_h, &ad, &out, &rep)) return;
        CHECK(rep.faces >= prev); /* a smaller tolerance never gives fewer faces */
        prev = rep.faces;
        CHECK_EQ(rep.uniform_faces - rep.faces, 12u * 64u - out.num_faces);
        h_str("    cube->sphere level 6, eps ");
        h_u32((uint32_t)(eps_list[i] * 1000 + 0.5));
        h_str("e-3: faces ");
        h_u32(rep.faces);
        h_str(" of ");
        h_u32(rep.uniform_faces);
        h_str(", saved ");
        h_u32(rep.uniform_faces - rep.faces);
        h_str(", forced ");
        h_u32(rep.forced_splits);
        h_nl();
    }
    /* a flat surface: nothing deviates, level 0 is within any tolerance */
    {
        subd_sr48_adapt ad = adapt(SUBD_SR48_ADAPT_CHORD, 6);
        uint32_t v;
        if (!build_square(6)) return;
        for (v = 0; v < g_h.num_verts; v++) g_pos[3 * v + 2] = 0;
        ad.eps = fx_real(1e-4);
        CHECK_EQ(run_checked(&g_h, &ad, 1e-6, 0, &res), 2);
        build_square(8);
        ad = adapt(SUBD_SR48_ADAPT_CHORD, 8);
        ad.eps = fx_real(0.002);
        (void)run_checked(&g_h, &ad, 1e-5, "sr48x_square_chord", &res);
    }
}

/* Every arena size below the need fails cleanly (NOMEM, arena mark unchanged, output
 * untouched, guard bytes intact, bytes_needed >= the need); at the need it succeeds with
 * the same mesh; UNIFORM's need is the plan and its peak. */
typedef struct extract_call {
    const subd_sr48 *h;
    const subd_sr48_adapt *ad;
    subd_mesh out;
    subd_sr48_adapt_report rep;
    uint32_t h0; /* the reference mesh's hash */
} extract_call;

static int extract_run(void *ctx, subd_arena *a, subd_diag *d)
{
    extract_call *c = (extract_call *)ctx;
    return subd_sr48_extract(a, c->h, c->ad, &c->out, &c->rep, d);
}

static void extract_ok(void *ctx, const subd_arena *a, const subd_diag *d)
{
    extract_call *c = (extract_call *)ctx;
    (void)a;
    (void)d;
    CHECK_EQ(h_mesh_hash(&c->out), c->h0);
}

static void plan_case(const subd_sr48 *h, const subd_sr48_adapt *ad)
{
    uint32_t plan, size, need, peak, h0, ref_used;
    subd_mesh out, ref;
    subd_sr48_adapt_report rep;
    subd_diag d;
    subd_arena a;
    extract_call c;
    h_sweep s;
    if (!CHECK_EQ(subd_sr48_extract_plan(h, ad, &plan, 0), SUBD_OK)) return;
    if (!CHECK(plan + 64u <= H_ARENA_BYTES)) return;
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    if (!extract(&a, h, ad, &ref, &rep)) return;
    h0 = h_mesh_hash(&ref);
    ref_used = a.used;
    c.h = h;
    c.ad = ad;
    c.h0 = h0;
    s = h_sweep_make(extract_run, &c, h_arena_buf, H_ARENA_BYTES, plan);
    s.plan_is_bound = 1; /* the first size that succeeds is the need */
    s.peak_le = 1;
    s.need_lo = 0;
    s.out = &c.out;
    s.out_bytes = sizeof c.out;
    s.in = h;
    s.in_bytes = sizeof *h;
    s.ok = extract_ok;
    if (!h_arena_sweep(&s)) return;
    need = s.need;
    peak = s.peak;
    CHECK(need > 0 && peak <= need);
    if (ad->mode == SUBD_SR48_ADAPT_UNIFORM) {
        CHECK_EQ(need, plan);
        CHECK_EQ(peak, plan);
    }
    /* the need reported by a failing call just below it is exact */
    subd_arena_init(&a, h_arena_buf, need - 1);
    CHECK_FAIL(subd_sr48_extract(&a, h, ad, &out, &rep, &d), &d, SUBD_ERR_NOMEM);
    CHECK_EQ(d.bytes_needed, need);
    /* and every larger arena works too */
    for (size = need; size <= plan; size += 1 + (plan - need) / 7) {
        subd_arena_init(&a, h_arena_buf, size);
        if (!CHECK_EQ(subd_sr48_extract(&a, h, ad, &out, &rep, &d), SUBD_OK)) return;
        CHECK_EQ(a.used, ref_used);
        CHECK_EQ(h_mesh_hash(&out), h0);
    }
}

/* The device one level less (the sweep is quadratic in the level's size: 13 G instructions
 * at the host's levels; the plan is the same number on both, the host sweeps the deeper). */
static void sr48x_plan_exhaustive(void)
{
    subd_sr48_adapt ad;
    uint32_t sq = H_HOST ? 4u : 3u, cu = H_HOST ? 3u : 2u;
    if (!build_square(sq)) return;
    ad = adapt(SUBD_SR48_ADAPT_UNIFORM, sq);
    plan_case(&g_h, &ad);
    ad = adapt(SUBD_SR48_ADAPT_UNIFORM, 0);
    plan_case(&g_h, &ad);
    ad = adapt(SUBD_SR48_ADAPT_POINT, sq);
    ad.point[0] = fx_real(0.1); ad.point[1] = fx_real(0.2);
    plan_case(&g_h, &ad);
    ad = adapt(SUBD_SR48_ADAPT_CHORD, sq);
    ad.eps = fx_real(0.01);
    plan_case(&g_h, &ad);
    if (!build_cube(cu)) return;
    ad = adapt(SUBD_SR48_ADAPT_PLANE, cu);
    ad.normal[2] = fx_real(1);
    plan_case(&g_h, &ad);
}

/* The result occupies exactly its own arrays: the marks are given back. */
static void sr48x_compact(void)
{
    subd_sr48_adapt ad = adapt(SUBD_SR48_ADAPT_CHORD, 6);
    subd_arena a;
    subd_mesh out;
    subd_sr48_adapt_report rep;
    subd_face_list fl;
    uint32_t used, plan;
    if (!build_cube(6)) return;
    ad.eps = fx_real(0.01);
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    if (!extract(&a, &g_h, &ad, &out, &rep)) return;
    used = a.used;
    /* the same mesh built from its face list takes the same array bytes */
    fl.num_verts = out.num_verts; fl.pos = out.pos; fl.num_faces = out.num_faces; fl.face_size = 0;
    fl.index = out.corner_vert; fl.num_lines = 0; fl.line_size = fl.line_index = 0;
    {
        subd_mesh m2;
        subd_diag d;
        uint32_t before = a.used;
        if (!CHECK_EQ(subd_mesh_build(&a, &fl, &m2, &d), SUBD_OK)) return;
        CHECK_EQ(a.used - before, used);
        CHECK_EQ(h_mesh_hash(&m2), h_mesh_hash(&out));
    }
    CHECK_EQ(subd_sr48_extract_plan(&g_h, &ad, &plan, 0), SUBD_OK);
    CHECK(used < plan);
}

static void sr48x_errors(void)
{
    subd_sr48_adapt ad;
    subd_arena a;
    subd_mesh out;
    subd_sr48_adapt_report rep;
    subd_diag d;
    subd_sr48 bad;
    uint32_t plan, i;
    if (!build_square(3)) return;
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    out.num_faces = 777;
#define BAD(expr_ad, want)                                                                   \
    do {                                                                                     \
        ad = adapt(SUBD_SR48_ADAPT_UNIFORM, 2);                                                   \
        expr_ad;                                                                             \
        CHECK_FAIL(subd_sr48_extract(&a, &g_h, &ad, &out, &rep, &d), &d, want);                    \
        CHECK_EQ(d.status, want);                                                            \
        CHECK_EQ(subd_sr48_extract_plan(&g_h, &ad, &plan, 0), want);                            \
        CHECK_EQ(a.used, 0);                                                                 \
        CHECK_EQ(out.num_faces, 777);                                                        \
    } while (0)
    BAD(ad.mode = (subd_sr48_adapt_mode)17, SUBD_ERR_PARAM);
    BAD(ad.max_level = 4, SUBD_ERR_PARAM);
    BAD((ad.mode = SUBD_SR48_ADAPT_RAMP, ad.axis = 3), SUBD_ERR_PARAM);
    BAD((ad.mode = SUBD_SR48_ADAPT_CHORD, ad.eps = 0), SUBD_ERR_PARAM);
    BAD((ad.mode = SUBD_SR48_ADAPT_CHORD, ad.eps = fx_real(-1)), SUBD_ERR_PARAM);
    BAD(ad.mode = SUBD_SR48_ADAPT_CALLBACK, SUBD_ERR_PARAM);
    BAD((ad.mode = SUBD_SR48_ADAPT_POINT, ad.radius = fx_real(-1)), SUBD_ERR_PARAM);
    BAD(ad.mode = SUBD_SR48_ADAPT_PLANE, SUBD_ERR_PARAM); /* zero normal */
#if !SUBD_FIXED
    {
        union { uint32_t u; float f; } nan;
        nan.u = 0x7fc00000u;
        BAD((ad.mode = SUBD_SR48_ADAPT_CHORD, ad.eps = nan.f), SUBD_ERR_PARAM);
        BAD((ad.mode = SUBD_SR48_ADAPT_POINT, ad.point[1] = nan.f), SUBD_ERR_PARAM);
    }
#endif
#undef BAD
    ad = adapt(SUBD_SR48_ADAPT_UNIFORM, 2);
    CHECK_FAIL(subd_sr48_extract(0, &g_h, &ad, &out, &rep, &d), &d, SUBD_ERR_PARAM);
    CHECK_FAIL(subd_sr48_extract(&a, 0, &ad, &out, &rep, &d), &d, SUBD_ERR_PARAM);
    CHECK_FAIL(subd_sr48_extract(&a, &g_h, 0, &out, &rep, &d), &d, SUBD_ERR_PARAM);
    CHECK_FAIL(subd_sr48_extract(&a, &g_h, &ad, 0, &rep, &d), &d, SUBD_ERR_PARAM);
    CHECK_EQ(subd_sr48_extract_plan(&g_h, &ad, 0, 0), SUBD_ERR_PARAM);
    CHECK_EQ(subd_sr48_extract_plan(0, &ad, &plan, 0), SUBD_ERR_PARAM);
    /* the plan fills diag: status, face cleared, no bytes_needed */
    d.face = 77u;
    d.bytes_needed = 99u;
    CHECK_FAIL(subd_sr48_extract_plan(0, &ad, &plan, &d), &d, SUBD_ERR_PARAM);
    CHECK_EQ(d.status, SUBD_ERR_PARAM);
    CHECK_EQ(d.bytes_needed, 0u);
    CHECK_EQ(d.face, SUBD_NONE);
    d.bytes_needed = 99u;
    CHECK_OK(subd_sr48_extract_plan(&g_h, &ad, &plan, &d), &d);
    CHECK_EQ(d.bytes_needed, 0u);
    /* NULL report and diag are fine */
    if (CHECK_EQ(subd_sr48_extract(&a, &g_h, &ad, &out, 0, 0), SUBD_OK)) CHECK_EQ(out.num_faces, 8);
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    out.num_faces = 777;
    /* an inconsistent hierarchy is rejected, never read out of bounds */
    for (i = 0; i < 6; i++) {
        bad = g_h;
        switch (i) {
        case 0: bad.level_tri[2] += 1; break;
        case 1: bad.num_tris += 1; break;
        case 2: bad.steps = SUBD_SR48_MAX_STEPS + 1; break;
        case 3: g_nb[3] = 5; break;                  /* partner on the wrong triangle */
        case 4: g_tv[3 * 4] = g_h.num_verts + 7; break; /* vertex out of range */
        case 5: bad.tri_vert = 0; break;
        }
        ad = adapt(SUBD_SR48_ADAPT_UNIFORM, 3);
        CHECK_FAIL(subd_sr48_extract(&a, &bad, &ad, &out, &rep, &d), &d, SUBD_ERR_PARAM);
        CHECK_EQ(a.used, 0);
        CHECK_EQ(out.num_faces, 777);
        build_square(3);
    }
}

/* Hierarchies from the scheme's own builder on the corpus meshes. */
static void sr48x_corpus(void)
{
    static const struct { const char *file; uint32_t steps; const char *hash; } cases[] = {
        {"test/data/icosahedron.obj", 3, "sr48x_ico"},
        {"test/data/grid_tri_8x8.obj", 2, "sr48x_grid"},
        {"test/data/hexfan.obj", 4, "sr48x_hexfan"},
    };
    uint32_t i;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const corpus_file *cf = corpus_find(cases[i].file);
        subd_arena a;
        subd_mesh in;
        subd_diag d;
        subd_sr48 h;
        subd_sr48_opts o;
        subd_sr48_adapt ad;
        cut_result res;
        uint32_t keep, m;
        if (!CHECK(cf != 0)) return;
        subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
        if (!CHECK_EQ(subd_obj_read(&a, cf->data, cf->len, &in, &d), SUBD_OK)) return;
        o.steps = cases[i].steps;
        o.flags = 0;
        if (!CHECK_EQ(subd_sr48_build(&a, &in, &o, &h, &d), SUBD_OK)) return;
        if (!CHECK(h.num_tris <= MAXT && h.num_verts <= MAXV)) return;
        keep = subd_arena_mark(&a);
        (void)keep;
        /* the hierarchy lives in the arena: extraction runs above it (run_checked uses the
         * whole buffer), so copy it to the static arrays first */
        for (m = 0; m < 3 * h.num_tris; m++) g_tv[m] = h.tri_vert[m];
        for (m = 0; m < h.num_tris; m++) g_nb[m] = h.tri_base_nb[m];
        for (m = 0; m < 3 * h.num_verts; m++) g_pos[m] = h.pos[m];
        h.tri_vert = g_tv; h.tri_base_nb = g_nb; h.pos = g_pos;
        g_h = h;
        g_have_par = 0;
        ad = adapt(SUBD_SR48_ADAPT_UNIFORM, h.steps);
        CHECK_EQ(run_checked(&g_h, &ad, 0, 0, &res), h.level_tri[h.steps + 1] - h.level_tri[h.steps]);
        ad = adapt(SUBD_SR48_ADAPT_CHORD, h.steps);
        ad.eps = fx_real(0.02);
        (void)run_checked(&g_h, &ad, 1e-5, cases[i].hash, &res);
        ad = adapt(SUBD_SR48_ADAPT_POINT, h.steps);
        ad.point[0] = h.pos[0]; ad.point[1] = h.pos[1]; ad.point[2] = h.pos[2];
        (void)run_checked(&g_h, &ad, 2e-3, 0, &res);
        ad = adapt(SUBD_SR48_ADAPT_RAMP, h.steps);
        ad.axis = 2;
        (void)run_checked(&g_h, &ad, 1e-6, 0, &res);
        ad = adapt(SUBD_SR48_ADAPT_PLANE, h.steps);
        ad.normal[0] = fx_real(1);
        (void)run_checked(&g_h, &ad, 1e-6, 0, &res);
        ad = adapt(SUBD_SR48_ADAPT_CALLBACK, h.steps);
        ad.fn = cb_level;
        (void)run_checked(&g_h, &ad, 1e-9, 0, &res);
    }
}

const test_case suite_sr48_extract[] = {
    {"sr48x_uniform", sr48x_uniform},
    {"sr48x_point", sr48x_point},
    {"sr48x_ramp_plane", sr48x_ramp_plane},
    {"sr48x_callback", sr48x_callback},
    {"sr48x_chord", sr48x_chord},
    {"sr48x_plan_exhaustive", sr48x_plan_exhaustive},
    {"sr48x_compact", sr48x_compact},
    {"sr48x_errors", sr48x_errors},
    {"sr48x_corpus", sr48x_corpus},
    {0, 0},
};
