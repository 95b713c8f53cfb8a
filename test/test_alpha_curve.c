/* SPDX-License-Identifier: MIT */
/* alpha-subdivision curves (src/alpha_curve.c, src/alpha_kernel.c): f == 1 gives Chaikin and
 * the uniform cubic and quartic B-spline masks written here; C-curves (cos kernel) keep a
 * regular N-gon regular with every edge midpoint on the circle (N = 3..12, S_2, S_3, S_4);
 * affine invariance (ellipses); the B-spline kernel's radial deviation and an open arc's
 * distance from the arc (reported); the cosh kernel's hyperbola; stiffness (table 1: the
 * error, the continuity report, measured contraction); per-vertex alpha; exact plans with
 * every too-small arena; error paths; output hashes compared host = QEMU. */
#include "harness.h"
#include "subd_alpha.h"
#if H_HOST
#include <math.h>
#include <stdio.h>
#endif

#define MAXP 4096
static subd_real g_in[3 * 64];
static uint32_t g_state = 12345u;

#if H_HOST
#define WORK_BYTES (4u * 1024u * 1024u)
static uint8_t work_buf[WORK_BYTES] __attribute__((aligned(8)));
#define WORK_BUF work_buf
static void note(const char *what, double v)
{
    char buf[160];
    snprintf(buf, sizeof buf, "  note: %s = %.3g\n", what, v);
    h_str(buf);
}
#else
#define WORK_BYTES H_ARENA_BYTES
#define WORK_BUF h_arena_buf
#endif


static uint32_t hash_curve(const subd_alpha_curve_out *c)
{
    uint32_t h = 2166136261u, i;
    for (i = 0; i < 3u * c->num_points; i++) {
        uint32_t b = subd_real_bits(c->pos[i]);
        h = h_fnv(h, &b, 4);
    }
    return h_fnv(h, &c->num_points, 4);
}

static void opts(subd_alpha_opts *o, uint32_t order, uint32_t levels, uint32_t kernel, int32_t num, int32_t den)
{
    subd_alpha_opts_default(o);
    o->order = order;
    o->levels = levels;
    o->kernel = kernel;
    o->alpha_num = num;
    o->alpha_den = den;
}

static int run(subd_arena *a, const subd_real *p, uint32_t m, int closed, const subd_alpha_opts *o,
               subd_alpha_curve_out *out)
{
    subd_diag d;
    int st = subd_alpha_curve(a, p, m, closed, o, out, &d);
    return CHECK_EQ(st, SUBD_OK);
}

/* Random polygon with integer coordinates in [-64, 64]. */
static void rand_poly(uint32_t m)
{
    uint32_t i;
    for (i = 0; i < 3u * m; i++) g_in[i] = h_int((int32_t)(h_rand(&g_state) % 129u) - 64);
}

/* ------------------------------------------------------------------------------------ */
/* Kernel values                                                                          */

static void alpha_kernel_values(void)
{
    subd_real f;
    uint32_t n;
    /* B-spline: f == s */
    CHECK_EQ(subd_alpha_kernel_value(SUBD_ALPHA_BSPLINE, 3, 7, 2, SUBD_REAL_FRAC(3, 4), &f), SUBD_OK);
    CHECK(h_same(f, SUBD_REAL_FRAC(3, 4)));
    /* cos: alpha = 1/3 turn, level 0: cos(60 degrees) = 1/2 exactly; level n equals the
     * scalar layer's cos of 1/(3 2^(n+1)) turn */
    CHECK_EQ(subd_alpha_kernel_value(SUBD_ALPHA_COS, 1, 3, 0, SUBD_REAL_ONE, &f), SUBD_OK);
    CHECK(h_same(f, SUBD_REAL_FRAC(1, 2)));
    for (n = 0; n < 8u; n++) {
        CHECK_EQ(subd_alpha_kernel_value(SUBD_ALPHA_COS, 2, 7, n, SUBD_REAL_ONE, &f), SUBD_OK);
        CHECK(h_same(f, subd_cos_turns(2, 7 << (n + 1u))));
    }
    /* alpha = 0: every kernel is 1 (times s) */
    for (n = 0; n < 4u; n++) {
        CHECK_EQ(subd_alpha_kernel_value(n, 0, 1, 3, SUBD_REAL_FRAC(5, 4), &f), SUBD_OK);
        CHECK(h_same(f, SUBD_REAL_FRAC(5, 4)));
    }
    /* errors */
    CHECK_EQ(subd_alpha_kernel_value(SUBD_ALPHA_COS, 1, 0, 0, SUBD_REAL_ONE, &f), SUBD_ERR_PARAM);
    CHECK_EQ(subd_alpha_kernel_value(4, 1, 3, 0, SUBD_REAL_ONE, &f), SUBD_ERR_PARAM);
    CHECK_EQ(subd_alpha_kernel_value(SUBD_ALPHA_COS, 1, 3, 0, h_int(-1), &f), SUBD_ERR_PARAM);
    /* the kernel alone accepts s in (-1, -1/2] (only the operators need theorem 1) */
    CHECK_EQ(subd_alpha_kernel_value(SUBD_ALPHA_COS, 0, 3, 0, SUBD_REAL_FRAC(-3, 4), &f), SUBD_OK);
    CHECK_EQ(subd_alpha_kernel_value(SUBD_ALPHA_COS, 1, INT32_MAX, 0, SUBD_REAL_ONE, &f), SUBD_ERR_PARAM);
    /* cosh(10 turns * pi) is about 2^44: too big */
    CHECK_EQ(subd_alpha_kernel_value(SUBD_ALPHA_COSH, 20, 1, 0, SUBD_REAL_ONE, &f), SUBD_ERR_RANGE);
#if H_HOST
    {
        /* poly and cosh against double, many angles and levels */
        double maxe = 0;
        int32_t num;
        for (num = -40; num <= 40; num++)
            for (n = 0; n < 6u; n++) {
                uint32_t k;
                for (k = SUBD_ALPHA_POLY; k <= SUBD_ALPHA_COSH; k++) {
                    double x = 2.0 * 3.14159265358979323846 * num / 16.0 / (double)(2u << n);
                    double want = (k == SUBD_ALPHA_POLY) ? 1.0 - x * x / 2.0 : cosh(x), e;
                    if (!CHECK_EQ(subd_alpha_kernel_value(k, num, 16, n, SUBD_REAL_ONE, &f), SUBD_OK)) return;
                    e = fabs(h_dbl(f) - want) / (SUBD_FIXED ? 1.0 / 65536.0 : fabs(want));
                    if (e > maxe) maxe = e;
                }
            }
        /* float: within 1 ulp (relative 2^-23); fixed: within 1 LSB */
        CHECK(maxe <= (SUBD_FIXED ? 1.0 : 1.2e-7));
        note(SUBD_FIXED ? "poly/cosh kernel max error (LSB)" : "poly/cosh kernel max relative error", maxe);
    }
#endif
}

/* ------------------------------------------------------------------------------------ */
/* f == 1: Chaikin, cubic and quartic B-splines (exact: integer input, dyadic weights)     */

static subd_real mix(const int32_t *w, int32_t den, const subd_real *p, uint32_t m, uint32_t i0, uint32_t c)
{
    /* sum w[j] p[i0 + j] / den over j = 0..3, closed indexing */
    subd_acc acc = subd_acc_zero();
    uint32_t j, ovf = 0;
    for (j = 0; j < 4u; j++)
        if (w[j]) acc = subd_acc_add(acc, SUBD_REAL_FRAC(w[j], den), p[3u * ((i0 + j) % m) + c]);
    return subd_acc_real(acc, &ovf);
}

/* One level of a closed uniform B-spline mask: even/odd rules over p[i..i+3]. */
static void ref_level(const subd_real *p, uint32_t m, subd_real *q, const int32_t *even, const int32_t *odd, int32_t den)
{
    uint32_t i, c;
    for (i = 0; i < m; i++)
        for (c = 0; c < 3u; c++) {
            q[3u * (2u * i) + c] = mix(even, den, p, m, i, c);
            q[3u * (2u * i + 1u) + c] = mix(odd, den, p, m, i, c);
        }
}

static void alpha_bspline_masks(void)
{
    /* Chaikin: 3/4 1/4 | 1/4 3/4. Cubic (S_3 = C S_2): edge 1/2 1/2 | vertex 1/8 3/4 1/8.
     * Quartic (S_4 = B C S_3): the mask (1 5 10 10 5 1)/16 split into its even and odd
     * rules, aligned by the shift B: out[2i] = (p_i + 10 p_i+1 + 5 p_i+2)/16,
     * out[2i+1] = (5 p_i+1 + 10 p_i+2 + p_i+3)/16. */
    static const int32_t ch_e[4] = {3, 1, 0, 0}, ch_o[4] = {1, 3, 0, 0};
    static const int32_t cu_e[4] = {4, 4, 0, 0}, cu_o[4] = {1, 6, 1, 0};
    static const int32_t qu_e[4] = {1, 10, 5, 0}, qu_o[4] = {0, 5, 10, 1};
    static subd_real r0[3 * MAXP], r1[3 * MAXP];
    uint32_t k, m, lev;
    for (k = 2; k <= 4u; k++)
        for (m = 3; m <= 9u; m += 3u)
            for (lev = 1; lev <= 3u; lev++) {
                subd_arena a;
                subd_alpha_opts o;
                subd_alpha_curve_out out;
                const int32_t *e = k == 2u ? ch_e : k == 3u ? cu_e : qu_e, *od = k == 2u ? ch_o : k == 3u ? cu_o : qu_o;
                int32_t den = k == 2u ? 4 : k == 3u ? 8 : 16;
                uint32_t n = m, l, i, ok = 1;
                rand_poly(m);
                for (i = 0; i < 3u * m; i++) r0[i] = g_in[i];
                for (l = 0; l < lev; l++) {
                    ref_level(r0, n, r1, e, od, den);
                    n *= 2u;
                    for (i = 0; i < 3u * n; i++) r0[i] = r1[i];
                }
                opts(&o, k, lev, SUBD_ALPHA_BSPLINE, 0, 1);
                subd_arena_init(&a, WORK_BUF, WORK_BYTES);
                if (!run(&a, g_in, m, 1, &o, &out)) return;
                if (!CHECK_EQ(out.num_points, n)) return;
                for (i = 0; i < 3u * n; i++) ok &= h_same(out.pos[i], r0[i]);
                CHECK(ok);
                CHECK_EQ(out.continuity, (int32_t)k - 1);
            }
    /* the cos kernel at alpha = 0 is the B-spline kernel, bit for bit */
    {
        subd_arena a;
        subd_alpha_opts o;
        subd_alpha_curve_out x, y;
        uint32_t i, ok = 1;
        rand_poly(7);
        subd_arena_init(&a, WORK_BUF, WORK_BYTES);
        opts(&o, 3, 3, SUBD_ALPHA_BSPLINE, 0, 1);
        if (!run(&a, g_in, 7, 0, &o, &x)) return;
        opts(&o, 3, 3, SUBD_ALPHA_COS, 0, 5);
        if (!run(&a, g_in, 7, 0, &o, &y)) return;
        for (i = 0; i < 3u * x.num_points; i++) ok &= h_same(x.pos[i], y.pos[i]);
        CHECK(ok);
    }
}

/* Open polylines, f == 1: the end condition written out. S_2 maps [p0 .. p(m-1)] to
 * [p0, (p0 + p1)/2, Chaikin pairs of the inner edges, (p(m-2) + p(m-1))/2, p(m-1)]; with
 * general f the second point is (p0 + f p1)/(1 + f). End points never move. */
static void alpha_open_end_condition(void)
{
    subd_arena a;
    subd_alpha_opts o;
    subd_alpha_curve_out out;
    uint32_t m = 6, i, c, ok = 1, k, lev;
    uint32_t ovf = 0;
    rand_poly(m);
    opts(&o, 2, 1, SUBD_ALPHA_BSPLINE, 0, 1);
    subd_arena_init(&a, WORK_BUF, WORK_BYTES);
    if (!run(&a, g_in, m, 0, &o, &out)) return;
    CHECK_EQ(out.num_points, 2u * m - 2u);
    for (c = 0; c < 3u; c++) {
        subd_real h = SUBD_REAL_FRAC(1, 2), q = SUBD_REAL_FRAC(1, 4), t = SUBD_REAL_FRAC(3, 4);
        ok &= h_same(out.pos[c], g_in[c]);
        ok &= h_same(out.pos[3 + c], subd_add(subd_mul(h, g_in[c], &ovf), subd_mul(h, g_in[3 + c], &ovf), &ovf));
        for (i = 1; i + 2u < m; i++) {
            ok &= h_same(out.pos[3u * (2u * i) + c],
                       subd_add(subd_mul(t, g_in[3u * i + c], &ovf), subd_mul(q, g_in[3u * (i + 1u) + c], &ovf), &ovf));
            ok &= h_same(out.pos[3u * (2u * i + 1u) + c],
                       subd_add(subd_mul(q, g_in[3u * i + c], &ovf), subd_mul(t, g_in[3u * (i + 1u) + c], &ovf), &ovf));
        }
        ok &= h_same(out.pos[3u * (2u * m - 4u) + c],
                   subd_add(subd_mul(h, g_in[3u * (m - 2u) + c], &ovf), subd_mul(h, g_in[3u * (m - 1u) + c], &ovf), &ovf));
        ok &= h_same(out.pos[3u * (2u * m - 3u) + c], g_in[3u * (m - 1u) + c]);
    }
    CHECK(ok);
    /* every order and level keeps both end points exactly; counts as documented */
    for (k = 2; k <= 6u; k++)
        for (lev = 0; lev <= 4u; lev++) {
            uint32_t want = m, l, j;
            int vc = 0; /* the input is edge-centred; S_2 from a vertex-centred one doubles */
            for (l = 0; l < lev; l++) {
                want = vc ? 2u * want : 2u * want - 2u;
                vc = 0;
                for (j = 2; j < k; j++) {
                    want = vc ? want + 1u : want - 1u;
                    vc = !vc;
                }
            }
            opts(&o, k, lev, SUBD_ALPHA_COS, 1, 9);
            subd_arena_init(&a, WORK_BUF, WORK_BYTES);
            if (!run(&a, g_in, m, 0, &o, &out)) return;
            CHECK_EQ(out.num_points, want);
            for (c = 0; c < 3u; c++) {
                CHECK(h_same(out.pos[c], g_in[c]));
                CHECK(h_same(out.pos[3u * (out.num_points - 1u) + c], g_in[3u * (m - 1u) + c]));
            }
        }
    /* a two-point polyline stays a segment */
    opts(&o, 4, 3, SUBD_ALPHA_BSPLINE, 0, 1);
    subd_arena_init(&a, WORK_BUF, WORK_BYTES);
    if (!run(&a, g_in, 2, 0, &o, &out)) return;
    CHECK(out.num_points >= 2u);
}

/* ------------------------------------------------------------------------------------ */
/* C-curves                                                                               */

/* Regular N-gon circumscribing the circle of radius r about the origin (z = 0): vertex i
 * at angle (i + 1/2)/N turn and radius r / cos(1/(2N) turn), so edge i touches the circle
 * at its midpoint, angle i/N turn. Deterministic on every target. */
/* r / cos(num/den turn) and the point r (cos, sin)(num/den turn), both within 1 LSB / 1 ulp:
 * in Q16.16 from the Q62 cosine (a Q16.16 cosine times r would be off by r/2 LSB). */
#if SUBD_FIXED
static int64_t cos32(int32_t num, int32_t den) { return (subd_cos_turns_q62(num, den) + (1 << 29)) >> 30; }
static int64_t sin32(int32_t num, int32_t den) { return (subd_sin_turns_q62(num, den) + (1 << 29)) >> 30; }
static subd_real over_cos(subd_real r, int32_t num, int32_t den)
{
    int64_t c = cos32(num, den);
    return (subd_real)((((int64_t)r << 32) + c / 2) / c);
}
static void polar(subd_real *p, subd_real r, int32_t num, int32_t den)
{
    p[0] = (subd_real)((r * cos32(num, den) + ((int64_t)1 << 31)) >> 32);
    p[1] = (subd_real)((r * sin32(num, den) + ((int64_t)1 << 31)) >> 32);
    p[2] = 0;
}
#else
static subd_real over_cos(subd_real r, int32_t num, int32_t den) { return r / subd_cos_turns(num, den); }
static void polar(subd_real *p, subd_real r, int32_t num, int32_t den)
{
    p[0] = r * subd_cos_turns(num, den);
    p[1] = r * subd_sin_turns(num, den);
    p[2] = 0;
}
#endif

static void ngon(uint32_t nn, subd_real r)
{
    uint32_t i;
    subd_real big = over_cos(r, 1, 2 * (int32_t)nn);
    for (i = 0; i < nn; i++) polar(g_in + 3u * i, big, 2 * (int32_t)i + 1, 2 * (int32_t)nn);
}

#define CIRCLE_R (SUBD_FIXED ? 64 : 1)
#define CIRCLE_LEVELS (H_HOST ? 6u : 4u)

#if H_HOST
/* Max over a closed polygon of |midpoint radius - r| / r, and the relative spread of its
 * edge lengths and of its vertex radii (0 for a regular polygon). */
static void polygon_stats(const subd_alpha_curve_out *c, double r, double *mid_err, double *edge_spread,
                          double *rad_spread)
{
    double emin = 1e300, emax = 0, rmin = 1e300, rmax = 0, me = 0;
    uint32_t i, n = c->num_points;
    for (i = 0; i < n; i++) {
        const subd_real *p = c->pos + 3u * i, *q = c->pos + 3u * ((i + 1u) % n);
        double x = h_dbl(p[0]), y = h_dbl(p[1]), u = h_dbl(q[0]), v = h_dbl(q[1]);
        double e = hypot(u - x, v - y), rr = hypot(x, y), mr = hypot((x + u) / 2, (y + v) / 2);
        if (e < emin) emin = e;
        if (e > emax) emax = e;
        if (rr < rmin) rmin = rr;
        if (rr > rmax) rmax = rr;
        if (fabs(mr - r) / r > me) me = fabs(mr - r) / r;
    }
    *mid_err = me;
    *edge_spread = (emax - emin) / r; /* relative to the size, not to the (short) edges */
    *rad_spread = (rmax - rmin) / r;
}
#endif

static void alpha_ccurve_circle(void)
{
    uint32_t nn, k, lev;
#if H_HOST
    double worst_mid = 0, worst_edge = 0, worst_rad = 0, bs_dev[13] = {0};
    /* tolerances, relative to r: float 1e-6; fixed, in LSB of r = 64 (one LSB = 2^-16 / 64
     * relative): midpoints on the circle within 3 LSB (measured 1.8); edge lengths and
     * vertex radii equal within 6 LSB (measured 3.4 and 4.3; S_4 at level 6 runs 18
     * rounding steps per point) */
    const double tol = SUBD_FIXED ? 3.0 / 65536.0 / CIRCLE_R : 1e-6;
    const double tol_reg = SUBD_FIXED ? 6.0 / 65536.0 / CIRCLE_R : 2e-6;
#endif
    for (nn = 3; nn <= 12u; nn++)
        for (k = 2; k <= 4u; k++)
            for (lev = 1; lev <= CIRCLE_LEVELS; lev++) {
                subd_arena a;
                subd_alpha_opts o;
                subd_alpha_curve_out out;
                ngon(nn, h_int(CIRCLE_R));
                opts(&o, k, lev, SUBD_ALPHA_COS, 1, (int32_t)nn);
                subd_arena_init(&a, WORK_BUF, WORK_BYTES);
                if (!run(&a, g_in, nn, 1, &o, &out)) return;
                CHECK_EQ(out.num_points, nn << lev);
                if (lev == 3u) h_hash(k == 2u ? "alpha_ccurve_s2" : k == 3u ? "alpha_ccurve_s3" : "alpha_ccurve_s4",
                                      hash_curve(&out));
#if H_HOST
                {
                    double me, es, rs;
                    polygon_stats(&out, CIRCLE_R, &me, &es, &rs);
                    /* every level regular (equal edges, equal vertex radii); for S_2 the
                     * edge midpoints are on the circle */
                    if (!CHECK(es <= tol_reg) || !CHECK(rs <= tol_reg)) {
                        printf("N=%u k=%u level=%u edge spread %.3g radius spread %.3g\n", nn, k, lev, es, rs);
                        return;
                    }
                    if (k == 2u && !CHECK(me <= tol)) {
                        printf("N=%u level=%u midpoint error %.3g\n", nn, lev, me);
                        return;
                    }
                    if (k == 2u && me > worst_mid) worst_mid = me;
                    if (es > worst_edge) worst_edge = es;
                    if (rs > worst_rad) worst_rad = rs;
                }
#endif
            }
#if H_HOST
    note(SUBD_FIXED ? "C-curve S_2 max midpoint radius error (LSB of r)" : "C-curve S_2 max midpoint radius error (relative)",
         SUBD_FIXED ? worst_mid * CIRCLE_R * 65536.0 : worst_mid);
    note(SUBD_FIXED ? "C-curve S_2..S_4 max edge-length spread (LSB)" : "C-curve S_2..S_4 max edge-length spread / r",
         SUBD_FIXED ? worst_edge * CIRCLE_R * 65536.0 : worst_edge);
    note(SUBD_FIXED ? "C-curve S_2..S_4 max vertex-radius spread (LSB)" : "C-curve S_2..S_4 max vertex-radius spread / r",
         SUBD_FIXED ? worst_rad * CIRCLE_R * 65536.0 : worst_rad);
    /* S_3 = C S_2: level 1 is inscribed in the circle (C takes the S_2 edge midpoints), and
     * each later level L shrinks by cos(pi / (N 2^(L-1))), the inscribed polygon's own
     * C-curve circle: R_L = r prod_{l=1}^{L-1} cos(pi/(N 2^l)) -> r sin(pi/N) / (pi/N). */
    for (nn = 3; nn <= 12u; nn++) {
        subd_arena a;
        subd_alpha_opts o;
        subd_alpha_curve_out out;
        double want = CIRCLE_R, worst = 0;
        ngon(nn, h_int(CIRCLE_R));
        for (lev = 1; lev <= 6u; lev++) {
            double rr;
            if (lev >= 2u) want *= cos(3.14159265358979323846 / (nn * (double)(1u << (lev - 1u))));
            opts(&o, 3, lev, SUBD_ALPHA_COS, 1, (int32_t)nn);
            subd_arena_init(&a, WORK_BUF, WORK_BYTES);
            if (!run(&a, g_in, nn, 1, &o, &out)) return;
            rr = hypot(h_dbl(out.pos[0]), h_dbl(out.pos[1]));
            if (fabs(rr - want) / CIRCLE_R > worst) worst = fabs(rr - want) / CIRCLE_R;
        }
        CHECK(worst <= tol_reg);
        if (nn == 5u) note("C-curve S_3 pentagon: level-6 radius / r (limit sinc(pi/5) = 0.9355)", want / CIRCLE_R);
    }
    /* B-spline kernel on the same polygons: its limit is not the circle */
    for (nn = 3; nn <= 12u; nn++) {
        subd_arena a;
        subd_alpha_opts o;
        subd_alpha_curve_out out;
        double me, es, rs;
        ngon(nn, h_int(CIRCLE_R));
        opts(&o, 2, 6, SUBD_ALPHA_BSPLINE, 0, 1);
        subd_arena_init(&a, WORK_BUF, WORK_BYTES);
        if (!run(&a, g_in, nn, 1, &o, &out)) return;
        polygon_stats(&out, CIRCLE_R, &me, &es, &rs);
        bs_dev[nn] = me;
        CHECK(me > 1e-4); /* clearly off the circle */
    }
    {
        char buf[200];
        snprintf(buf, sizeof buf, "  note: B-spline (Chaikin) kernel, level-6 max radial deviation of edge "
                                  "midpoints, N=3..12: %.3g %.3g %.3g %.3g %.3g %.3g %.3g %.3g %.3g %.3g\n",
                 bs_dev[3], bs_dev[4], bs_dev[5], bs_dev[6], bs_dev[7], bs_dev[8], bs_dev[9], bs_dev[10],
                 bs_dev[11], bs_dev[12]);
        h_str(buf);
    }
#endif
}

/* An affine image of the input gives the affine image of the output: a C-curve ellipse. */
static void alpha_ccurve_affine(void)
{
    static subd_real img[3 * 64];
    uint32_t nn, k;
    for (nn = 3; nn <= 12u; nn += 3u)
        for (k = 2; k <= 4u; k++) {
            subd_arena a;
            subd_alpha_opts o;
            subd_alpha_curve_out x, y;
            uint32_t i, ovf = 0;
            /* A(p) = (2x + y/2 + 3, 3y/4 - 1, x/4 + z) */
            const subd_real A[3][4] = {{h_int(2), SUBD_REAL_FRAC(1, 2), 0, h_int(3)},
                                       {0, SUBD_REAL_FRAC(3, 4), 0, h_int(-1)},
                                       {SUBD_REAL_FRAC(1, 4), 0, SUBD_REAL_ONE, 0}};
            ngon(nn, h_int(CIRCLE_R));
            for (i = 0; i < nn; i++) {
                uint32_t r;
                for (r = 0; r < 3u; r++) {
                    subd_acc acc = subd_acc_zero();
                    uint32_t c;
                    for (c = 0; c < 3u; c++) acc = subd_acc_add(acc, A[r][c], g_in[3u * i + c]);
                    img[3u * i + r] = subd_add(subd_acc_real(acc, &ovf), A[r][3], &ovf);
                }
            }
            opts(&o, k, 4, SUBD_ALPHA_COS, 1, (int32_t)nn);
            subd_arena_init(&a, WORK_BUF, WORK_BYTES);
            if (!run(&a, g_in, nn, 1, &o, &x) || !run(&a, img, nn, 1, &o, &y)) return;
            if (nn == 6u) h_hash("alpha_ellipse", hash_curve(&y));
#if H_HOST
            {
                double worst = 0;
                for (i = 0; i < x.num_points; i++) {
                    uint32_t r;
                    for (r = 0; r < 3u; r++) {
                        double want = h_dbl(A[r][3]), got = h_dbl(y.pos[3u * i + r]);
                        uint32_t c;
                        for (c = 0; c < 3u; c++) want += h_dbl(A[r][c]) * h_dbl(x.pos[3u * i + c]);
                        if (fabs(got - want) > worst) worst = fabs(got - want);
                    }
                }
                /* float: 1e-6 of the size (about 4); fixed: 6 LSB, measured 4 (the 2.5 x
                 * magnification of A applied to the first run's rounding, plus the second's) */
                CHECK(worst <= (SUBD_FIXED ? 6.0 / 65536.0 : 4e-6));
                if (nn == 12u && k == 4u)
                    note(SUBD_FIXED ? "affine image max error (LSB)" : "affine image max abs error (size ~4)",
                         SUBD_FIXED ? worst * 65536.0 : worst);
            }
#endif
        }
}

/* Open arc: 135 degrees in K = 3 pieces; control points p0 and p(K+1) are the arc's end
 * points (tangent points), p1..pK the circumscribing vertices. With S_2 and the cos kernel
 * every edge midpoint lies on the arc; S_3 and S_4 are reported. */
static void alpha_open_arc(void)
{
    uint32_t k;
    const uint32_t K = 3;
    for (k = 2; k <= 4u; k++) {
        subd_arena a;
        subd_alpha_opts o;
        subd_alpha_curve_out out;
        uint32_t i, ovf = 0, m = K + 2u;
        subd_real r = h_int(CIRCLE_R), big = over_cos(r, 1, 16);
        /* alpha = 1/8 turn: tangent points at i/8 turn, vertices at (2i-1)/16 turn */
        polar(g_in, r, 0, 1);
        for (i = 1; i <= K; i++) polar(g_in + 3u * i, big, 2 * (int32_t)i - 1, 16);
        polar(g_in + 3u * (K + 1u), r, 3, 8);
        (void)ovf;
        opts(&o, k, 5, SUBD_ALPHA_COS, 1, 8);
        subd_arena_init(&a, WORK_BUF, WORK_BYTES);
        if (!run(&a, g_in, m, 0, &o, &out)) return;
        h_hash(k == 2u ? "alpha_arc_s2" : k == 3u ? "alpha_arc_s3" : "alpha_arc_s4", hash_curve(&out));
#if H_HOST
        {
            double worst_mid = 0, worst_pt = 0;
            for (i = 0; i < out.num_points; i++) {
                double x = h_dbl(out.pos[3u * i]), y = h_dbl(out.pos[3u * i + 1u]);
                double e = fabs(hypot(x, y) - CIRCLE_R) / CIRCLE_R;
                if (e > worst_pt) worst_pt = e;
                /* the first and last stored segments are halves of the virtual end edges
                 * (whose midpoints are the end points themselves) */
                if (i >= 1u && i + 2u < out.num_points) {
                    double u = h_dbl(out.pos[3u * i + 3u]), v = h_dbl(out.pos[3u * i + 4u]);
                    e = fabs(hypot((x + u) / 2, (y + v) / 2) - CIRCLE_R) / CIRCLE_R;
                    if (e > worst_mid) worst_mid = e;
                }
            }
            if (k == 2u) {
                CHECK(worst_mid <= (SUBD_FIXED ? 3.0 / 65536.0 / CIRCLE_R : 1e-6));
                note("open arc S_2 cos: max edge-midpoint radius error (relative)", worst_mid);
            } else {
                char buf[120];
                snprintf(buf, sizeof buf, "open arc S_%u cos level 5: max |radius - r| / r of the points", k);
                note(buf, worst_pt);
                CHECK(worst_pt < 0.1);
            }
        }
#endif
    }
}

#if H_HOST
/* cosh kernel: the "circumscribing" polygon of the hyperbola (cosh t, sinh t) with tangent
 * points at t = i a has vertices (cosh, sinh)((i + 1/2) a) / cosh(a/2); S_2 with
 * f = cosh(a/2) keeps every edge midpoint on the hyperbola (x^2 - y^2 = 1). */
static void alpha_cosh_hyperbola(void)
{
    subd_arena a;
    subd_alpha_opts o;
    subd_alpha_curve_out out;
    const double al = 2.0 * 3.14159265358979323846 / 16.0; /* alpha = 1/16 turn */
    uint32_t i, m = 7;
    double worst = 0;
    /* open, 5 pieces: tangent points at t = -2.5a .. 2.5a, the ends are the first and the
     * last, the vertices are at t = -2a .. 2a */
    for (i = 0; i < m; i++) {
        double t = (i == 0) ? -2.5 * al : (i == m - 1u) ? 2.5 * al : ((double)i - 3.0) * al;
        double s = (i == 0 || i == m - 1u) ? 1.0 : 1.0 / cosh(al / 2);
        g_in[3u * i] = (subd_real)(SUBD_FIXED ? floor(cosh(t) * s * 65536.0 + 0.5) : cosh(t) * s);
        g_in[3u * i + 1u] = (subd_real)(SUBD_FIXED ? floor(sinh(t) * s * 65536.0 + 0.5) : sinh(t) * s);
        g_in[3u * i + 2u] = 0;
    }
    opts(&o, 2, 5, SUBD_ALPHA_COSH, 1, 16);
    subd_arena_init(&a, WORK_BUF, WORK_BYTES);
    if (!run(&a, g_in, m, 0, &o, &out)) return;
    for (i = 1; i + 2u < out.num_points; i++) {
        double x = (h_dbl(out.pos[3u * i]) + h_dbl(out.pos[3u * i + 3u])) / 2;
        double y = (h_dbl(out.pos[3u * i + 1u]) + h_dbl(out.pos[3u * i + 4u])) / 2;
        if (fabs(x * x - y * y - 1.0) > worst) worst = fabs(x * x - y * y - 1.0);
    }
    CHECK(worst <= (SUBD_FIXED ? 8.0 / 65536.0 : 2e-6));
    note("cosh kernel S_2: max |x^2 - y^2 - 1| of edge midpoints", worst);
}
#endif

/* ------------------------------------------------------------------------------------ */
/* Stiffness                                                                              */

#if SUBD_FIXED
typedef int64_t sq_t; /* exact squared length in Q32 (coordinates < 2^14) */
static sq_t sqlen(const subd_real *p, const subd_real *q)
{
    int64_t s = 0;
    uint32_t c;
    for (c = 0; c < 3u; c++) s += ((int64_t)q[c] - p[c]) * ((int64_t)q[c] - p[c]);
    return s;
}
#else
typedef float sq_t;
static sq_t sqlen(const subd_real *p, const subd_real *q)
{
    float s = 0;
    uint32_t c;
    for (c = 0; c < 3u; c++) {
        float d = q[c] - p[c], dd = d * d;
        s = s + dd;
    }
    return s;
}
#endif

static sq_t max_edge(const subd_alpha_curve_out *c)
{
    sq_t m = 0;
    uint32_t i;
    for (i = 0; i < c->num_points; i++) {
        sq_t e = sqlen(c->pos + 3u * i, c->pos + 3u * ((i + 1u) % c->num_points));
        if (e > m) m = e;
    }
    return m;
}

static void alpha_stiffness(void)
{
    subd_arena a;
    subd_alpha_opts o;
    subd_alpha_curve_out out;
    subd_diag d;
    uint32_t si, k;
    /* s in (0, inf) in 1/8 steps: 1/8, 1/2, 1, 2, 8 */
    static const int32_t s8[5] = {1, 4, 8, 16, 64};
    rand_poly(9);
    opts(&o, 2, 1, SUBD_ALPHA_BSPLINE, 0, 1);
    subd_arena_init(&a, WORK_BUF, WORK_BYTES);
    /* theorem 1: s <= -1/2 diverges -> SUBD_ERR_DIVERGENT, arena untouched */
    o.stiffness = h_int(-1);
    CHECK_FAIL(subd_alpha_curve(&a, g_in, 9, 1, &o, &out, &d), &d, SUBD_ERR_DIVERGENT);
    o.stiffness = SUBD_REAL_FRAC(-3, 2);
    CHECK_FAIL(subd_alpha_curve(&a, g_in, 9, 1, &o, &out, &d), &d, SUBD_ERR_DIVERGENT);
    CHECK_EQ(subd_alpha_curve_plan(9, 1, &o, &si, 0), SUBD_ERR_DIVERGENT);
    CHECK_EQ(subd_arena_mark(&a), 0);
    /* s in (-1/2, 0]: accepted, reported as not smooth */
    o.stiffness = SUBD_REAL_FRAC(-49, 100);
    if (run(&a, g_in, 9, 1, &o, &out)) CHECK_EQ(out.continuity, -1);
    o.stiffness = 0;
    if (run(&a, g_in, 9, 1, &o, &out)) CHECK_EQ(out.continuity, -1);
    o.stiffness = SUBD_REAL_FRAC(1, 2);
    if (run(&a, g_in, 9, 1, &o, &out)) CHECK_EQ(out.continuity, 0);
    o.stiffness = SUBD_REAL_FRAC(3, 4);
    o.order = 4;
    if (run(&a, g_in, 9, 1, &o, &out)) CHECK_EQ(out.continuity, 3);
    /* a level with f_n <= -1: s = 2, cos kernel, alpha = 0.9 turn: f_0 = 2 cos(0.45 turn) */
    opts(&o, 2, 2, SUBD_ALPHA_COS, 9, 10);
    o.stiffness = h_int(2);
    CHECK_FAIL(subd_alpha_curve(&a, g_in, 9, 1, &o, &out, &d), &d, SUBD_ERR_PARAM);
    /* s > 0: successive levels contract: the longest edge shrinks every level, by at most
     * max(s, 1)/(1 + s) (the inner edge is f/(1+f) of its parent, the corner edge at most
     * 1/(1+f) of the longer parent) */
    for (k = 2; k <= 4u; k++)
        for (si = 0; si < 5u; si++) {
            uint32_t lev;
            sq_t prev;
            rand_poly(9);
            opts(&o, k, 0, SUBD_ALPHA_BSPLINE, 0, 1);
            o.stiffness = SUBD_REAL_FRAC(s8[si], 8);
            if (!run(&a, g_in, 9, 1, &o, &out)) return;
            prev = max_edge(&out);
            for (lev = 1; lev <= 4u; lev++) {
                sq_t cur;
                o.levels = lev;
                subd_arena_init(&a, WORK_BUF, WORK_BYTES);
                if (!run(&a, g_in, 9, 1, &o, &out)) return;
                cur = max_edge(&out);
                CHECK(cur < prev);
#if H_HOST
                if (k == 2u && lev == 4u) {
                    char buf[100];
                    double sv = s8[si] / 8.0, bound = (sv > 1 ? sv : 1) / (1 + sv);
                    double ratio = sqrt((double)cur / (double)prev);
                    CHECK(ratio <= bound + 1e-6);
                    snprintf(buf, sizeof buf, "S_2 longest-edge ratio level 3->4, s = %.3g (bound %.3g)", sv, bound);
                    note(buf, ratio);
                }
#endif
                prev = cur;
            }
        }
#if H_HOST
    /* s in (-1/2, 0): not contracting every level; report the same ratio for s = -0.49 */
    {
        sq_t e3, e4;
        opts(&o, 2, 3, SUBD_ALPHA_BSPLINE, 0, 1);
        o.stiffness = SUBD_REAL_FRAC(-49, 100);
        rand_poly(9);
        subd_arena_init(&a, WORK_BUF, WORK_BYTES);
        if (!run(&a, g_in, 9, 1, &o, &out)) return;
        e3 = max_edge(&out);
        o.levels = 4;
        if (!run(&a, g_in, 9, 1, &o, &out)) return;
        e4 = max_edge(&out);
        note("S_2 longest-edge ratio level 3->4, s = -0.49 (not smooth)", sqrt((double)e4 / (double)e3));
    }
#endif
}

/* ------------------------------------------------------------------------------------ */
/* Per-vertex alpha                                                                       */

static void alpha_per_vertex(void)
{
    static int32_t tags[64];
    subd_arena a;
    subd_alpha_opts o;
    subd_alpha_curve_out x, y;
    subd_diag d;
    uint32_t k, closed, i, m = 12;
    g_state = 99u; /* host-only tests draw random numbers too: restart for the hashes */
    for (closed = 0; closed < 2u; closed++)
        for (k = 2; k <= 5u; k++) {
            uint32_t ok = 1, far_ok = 1, diff = 0;
            rand_poly(m);
            for (i = 0; i < m; i++) tags[i] = 3;
            opts(&o, k, 3, SUBD_ALPHA_COS, 3, 20);
            subd_arena_init(&a, WORK_BUF, WORK_BYTES);
            if (!run(&a, g_in, m, (int)closed, &o, &x)) return;
            o.tag_num = tags;
            if (!run(&a, g_in, m, (int)closed, &o, &y)) return;
            /* equal tags == uniform, bit for bit */
            CHECK_EQ(x.num_points, y.num_points);
            for (i = 0; i < 3u * x.num_points; i++) ok &= h_same(x.pos[i], y.pos[i]);
            CHECK(ok);
            /* one vertex tagged differently (vertex 6, alpha = 1/4 turn): only points near it
             * move; after 3 levels of S_k the influence stays within (k + 1) input edges */
            tags[6] = 5;
            if (!run(&a, g_in, m, (int)closed, &o, &y)) return;
            for (i = 0; i < x.num_points; i++) {
                uint32_t c, moved = 0;
                /* point i at level 3 lies near input parameter i / 8 */
                int32_t dist = (int32_t)(i / 8u) - 6;
                for (c = 0; c < 3u; c++) moved |= !h_same(x.pos[3u * i + c], y.pos[3u * i + c]);
                diff += moved;
                if (moved && (dist > (int32_t)k + 1 || dist < -(int32_t)k - 2)) far_ok = 0;
            }
            CHECK(diff > 0);
            CHECK(far_ok);
            if (closed && k == 3u) h_hash("alpha_tags", hash_curve(&y));
            o.tag_num = 0;
        }
    /* a tag out of range */
    tags[2] = SUBD_ALPHA_MAX_NUM + 1;
    opts(&o, 2, 1, SUBD_ALPHA_COS, 1, 8);
    o.tag_num = tags;
    subd_arena_init(&a, WORK_BUF, WORK_BYTES);
    CHECK_FAIL(subd_alpha_curve(&a, g_in, m, 1, &o, &x, &d), &d, SUBD_ERR_PARAM);
    CHECK_EQ(d.vertex, 2);
    CHECK_EQ(subd_arena_mark(&a), 0);
}

/* ------------------------------------------------------------------------------------ */
/* Plans, errors, hashes                                                                  */

typedef struct curve_call {
    uint32_t m, pts, plan;
    int closed;
    const subd_alpha_opts *o;
    subd_alpha_curve_out out;
} curve_call;

static int curve_run(void *ctx, subd_arena *a, subd_diag *d)
{
    curve_call *c = (curve_call *)ctx;
    return subd_alpha_curve(a, g_in, c->m, c->closed, c->o, &c->out, d);
}

static void curve_ok(void *ctx, const subd_arena *a, const subd_diag *d)
{
    curve_call *c = (curve_call *)ctx;
    uint32_t kept = subd_arena_mark(a) - 8u;
    (void)d;
    CHECK_EQ(c->out.num_points, c->pts);
    /* only the point buffer (sized for the largest level) stays allocated */
    if (c->o->tag_num) CHECK(kept < c->plan);
    else CHECK_EQ(kept, c->plan);
    CHECK(c->pts * 3u * (uint32_t)sizeof(subd_real) <= kept);
}

static void check_plan_exhaustive(uint32_t m, int closed, const subd_alpha_opts *o)
{
    static uint8_t buf[24576 + 8 + 64] __attribute__((aligned(8)));
    curve_call c;
    h_sweep s;
    c.m = m;
    c.closed = closed;
    c.o = o;
    if (!CHECK_EQ(subd_alpha_curve_plan(m, closed, o, &c.plan, &c.pts), SUBD_OK)) return;
    s = h_sweep_make(curve_run, &c, buf, sizeof buf, c.plan);
    s.prefix = 8;
    s.out = &c.out;
    s.out_bytes = sizeof c.out;
    s.in = g_in;
    s.in_bytes = 3u * m * (uint32_t)sizeof(subd_real);
    s.ok = curve_ok;
    (void)h_arena_sweep(&s);
}

static void alpha_plan_exact(void)
{
    static int32_t tags[16];
    subd_alpha_opts o;
    uint32_t k, closed, i;
    rand_poly(10);
    for (i = 0; i < 10u; i++) tags[i] = (int32_t)i;
    for (closed = 0; closed < 2u; closed++)
        for (k = 2; k <= 5u; k++) {
            opts(&o, k, 3, SUBD_ALPHA_COS, 1, 7);
            check_plan_exhaustive(10, (int)closed, &o);
            o.tag_num = tags;
            check_plan_exhaustive(10, (int)closed, &o);
        }
}

static void alpha_curve_errors(void)
{
    subd_arena a;
    subd_alpha_opts o;
    subd_alpha_curve_out out;
    subd_diag d;
    uint32_t plan;
    rand_poly(5);
    subd_arena_init(&a, WORK_BUF, WORK_BYTES);
    opts(&o, 2, 2, SUBD_ALPHA_COS, 1, 5);
    CHECK_FAIL(subd_alpha_curve(0, g_in, 5, 1, &o, &out, &d), &d, SUBD_ERR_PARAM);
    CHECK_FAIL(subd_alpha_curve(&a, 0, 5, 1, &o, &out, &d), &d, SUBD_ERR_PARAM);
    CHECK_FAIL(subd_alpha_curve(&a, g_in, 5, 1, 0, &out, &d), &d, SUBD_ERR_PARAM);
    CHECK_FAIL(subd_alpha_curve(&a, g_in, 2, 1, &o, &out, &d), &d, SUBD_ERR_EMPTY);
    CHECK_FAIL(subd_alpha_curve(&a, g_in, 1, 0, &o, &out, &d), &d, SUBD_ERR_EMPTY);
    CHECK_EQ(subd_alpha_curve_plan(2, 1, &o, &plan, 0), SUBD_ERR_EMPTY);
    o.order = 1;
    CHECK_FAIL(subd_alpha_curve(&a, g_in, 5, 1, &o, &out, &d), &d, SUBD_ERR_PARAM);
    o.order = SUBD_ALPHA_MAX_ORDER + 1u;
    CHECK_FAIL(subd_alpha_curve(&a, g_in, 5, 1, &o, &out, &d), &d, SUBD_ERR_PARAM);
    opts(&o, 2, SUBD_MAX_LEVELS + 1u, SUBD_ALPHA_COS, 1, 5);
    CHECK_FAIL(subd_alpha_curve(&a, g_in, 5, 1, &o, &out, &d), &d, SUBD_ERR_PARAM);
    opts(&o, 2, 1, 7, 1, 5);
    CHECK_FAIL(subd_alpha_curve(&a, g_in, 5, 1, &o, &out, &d), &d, SUBD_ERR_PARAM);
    opts(&o, 2, 1, SUBD_ALPHA_COS, 1, 0);
    CHECK_FAIL(subd_alpha_curve(&a, g_in, 5, 1, &o, &out, &d), &d, SUBD_ERR_PARAM);
    opts(&o, 2, 1, SUBD_ALPHA_COS, SUBD_ALPHA_MAX_NUM + 1, 5);
    CHECK_FAIL(subd_alpha_curve(&a, g_in, 5, 1, &o, &out, &d), &d, SUBD_ERR_PARAM);
    /* cosh of a large angle does not fit */
    opts(&o, 2, 1, SUBD_ALPHA_COSH, 40, 1);
    CHECK_FAIL(subd_alpha_curve(&a, g_in, 5, 1, &o, &out, &d), &d, SUBD_ERR_RANGE);
    /* overflow of the positions: s = 2, cos kernel, alpha = 0.6 turn: f_0 = 2 cos(0.3 turn)
     * = -0.62 gives w = 1/(2 + 2 f_0) = 1.31 */
    opts(&o, 2, 3, SUBD_ALPHA_COS, 3, 5);
    o.stiffness = h_int(2);
#if SUBD_FIXED /* not a ternary: 3e38f has no Q16.16 value (clang -Wliteral-conversion) */
    g_in[0] = h_int(30000);
#else
    g_in[0] = 3e38f;
#endif
    CHECK_FAIL(subd_alpha_curve(&a, g_in, 5, 1, &o, &out, &d), &d, SUBD_ERR_RANGE);
#if !SUBD_FIXED
    {
        union { uint32_t u; float f; } nan;
        nan.u = 0x7fc00000u;
        rand_poly(5);
        g_in[7] = nan.f;
        opts(&o, 2, 1, SUBD_ALPHA_COS, 1, 5);
        CHECK_FAIL(subd_alpha_curve(&a, g_in, 5, 1, &o, &out, &d), &d, SUBD_ERR_NAN);
        CHECK_EQ(d.vertex, 2);
    }
#endif
    CHECK_EQ(subd_arena_mark(&a), 0);
    /* levels = 0 copies the input */
    rand_poly(5);
    opts(&o, 3, 0, SUBD_ALPHA_COS, 1, 5);
    if (run(&a, g_in, 5, 0, &o, &out)) {
        CHECK_EQ(out.num_points, 5);
        CHECK(h_same(out.pos[14], g_in[14]));
    }
}

static void alpha_curve_hashes(void)
{
    uint32_t kern, k, closed;
    for (kern = 0; kern < 4u; kern++)
        for (k = 2; k <= 5u; k++)
            for (closed = 0; closed < 2u; closed++) {
                subd_arena a;
                subd_alpha_opts o;
                subd_alpha_curve_out out;
                char name[] = "alpha_curve_k0_o0_c0";
                g_state = 777u;
                rand_poly(7);
                opts(&o, k, 4, kern, 1, 5);
                o.stiffness = SUBD_REAL_FRAC(7, 8);
                subd_arena_init(&a, WORK_BUF, WORK_BYTES);
                if (!run(&a, g_in, 7, (int)closed, &o, &out)) return;
                name[13] = (char)('0' + kern);
                name[16] = (char)('0' + k);
                name[19] = (char)('0' + closed);
                h_hash(name, hash_curve(&out));
            }
}


/* ------------------------------------------------------------------------------------ */
/* Robustness (issue 13)                                                                  */

/* The cosh kernel at the largest allowed angle returns SUBD_ERR_RANGE (it used to overflow
 * int64 rounding x / ln 2); a stiffness outside the internal Q32.32 range (|s| >= 2^31,
 * float build only) is SUBD_ERR_PARAM. */
static void alpha_kernel_range(void)
{
    subd_real f = 0;
    uint32_t n;
    for (n = 0; n < 3u; n++) {
        CHECK_EQ(subd_alpha_kernel_value(SUBD_ALPHA_COSH, SUBD_ALPHA_MAX_NUM, 1, n, SUBD_REAL_ONE, &f), SUBD_ERR_RANGE);
        CHECK_EQ(subd_alpha_kernel_value(SUBD_ALPHA_COSH, -SUBD_ALPHA_MAX_NUM, 1, n, SUBD_REAL_ONE, &f), SUBD_ERR_RANGE);
        CHECK_EQ(subd_alpha_kernel_value(SUBD_ALPHA_COSH, INT32_MAX, 1, n, SUBD_REAL_ONE, &f), SUBD_ERR_RANGE);
        CHECK_EQ(subd_alpha_kernel_value(SUBD_ALPHA_COSH, INT32_MIN, 1, n, SUBD_REAL_ONE, &f), SUBD_ERR_RANGE);
        CHECK_EQ(subd_alpha_kernel_value(SUBD_ALPHA_POLY, INT32_MIN, 1, n, SUBD_REAL_ONE, &f), SUBD_ERR_RANGE);
    }
    /* level 0 evaluates at alpha / 2: cosh(pi 33 / 20) = 89.17 */
    CHECK_EQ(subd_alpha_kernel_value(SUBD_ALPHA_COSH, 33, 20, 0, SUBD_REAL_ONE, &f), SUBD_OK);
    CHECK(h_dbl(f) > 89.1 && h_dbl(f) < 89.2);
#if !SUBD_FIXED
    CHECK_EQ(subd_alpha_kernel_value(SUBD_ALPHA_BSPLINE, 0, 1, 0, 3e9f, &f), SUBD_ERR_PARAM);
    {
        subd_alpha_opts o;
        subd_alpha_curve_out out;
        subd_arena a;
        subd_diag d;
        uint32_t plan;
        rand_poly(5);
        subd_arena_init(&a, WORK_BUF, WORK_BYTES);
        opts(&o, 2, 1, SUBD_ALPHA_BSPLINE, 0, 1);
        o.stiffness = 3e9f;
        CHECK_FAIL(subd_alpha_curve(&a, g_in, 5, 1, &o, &out, &d), &d, SUBD_ERR_PARAM);
        CHECK_EQ(subd_alpha_curve_plan(5, 1, &o, &plan, 0), SUBD_ERR_PARAM);
    }
#endif
}

/* A point count whose 3 m wraps 32 bits is refused (SUBD_ERR_TOO_BIG) before any point is
 * read: the NaN scan used to run over 3 m mod 2^32 values first. */
static void alpha_curve_huge_m(void)
{
    subd_alpha_opts o;
    subd_alpha_curve_out out;
    subd_arena a;
    subd_diag d;
    uint32_t plan;
    subd_real p[6];
    uint32_t i, m = 0x55555556u; /* 3 m = 2^32 + 2 */
    for (i = 0; i < 6u; i++) p[i] = 0;
#if !SUBD_FIXED
    {
        union { uint32_t u; float f; } nan;
        nan.u = 0x7fc00000u;
        p[0] = nan.f;
    }
#endif
    subd_arena_init(&a, WORK_BUF, WORK_BYTES);
    opts(&o, 2, 1, SUBD_ALPHA_BSPLINE, 0, 1);
    CHECK_FAIL(subd_alpha_curve(&a, p, m, 1, &o, &out, &d), &d, SUBD_ERR_TOO_BIG);
    CHECK_FAIL(subd_alpha_curve(&a, p, m, 0, &o, &out, &d), &d, SUBD_ERR_TOO_BIG);
    CHECK_EQ(subd_alpha_curve_plan(m, 1, &o, &plan, 0), SUBD_ERR_TOO_BIG);
    o.levels = 0; /* no level to grow: the input count alone is checked */
    CHECK_FAIL(subd_alpha_curve(&a, p, m, 1, &o, &out, &d), &d, SUBD_ERR_TOO_BIG);
    CHECK_EQ(subd_arena_mark(&a), 0);
}

/* Theorem 1 (convergence for s > -1/2): s <= -1/2 is refused with SUBD_ERR_DIVERGENT (table
 * 1's s <= -1 was the old limit); s = -0.49 is accepted and contracts, slowly and not
 * every level (the first level makes the longest edge up to 2 / 1.02 times longer): the
 * longest edge after six levels is shorter than after one. A level with f_n <= -1/2 (s = 2, cos kernel,
 * f_0 = 2 cos(0.3 turn) = -0.62) is accepted (finitely many such levels do not affect
 * convergence) and amplifies: positions near the range overflow (SUBD_ERR_RANGE). */
static void alpha_divergent(void)
{
    subd_alpha_opts o;
    subd_alpha_curve_out out;
    subd_arena a;
    subd_diag d;
    uint32_t plan, k, closed;
    subd_arena_init(&a, WORK_BUF, WORK_BYTES);
    rand_poly(9);
    opts(&o, 2, 1, SUBD_ALPHA_BSPLINE, 0, 1);
    o.stiffness = SUBD_REAL_FRAC(-1, 2);
    CHECK_FAIL(subd_alpha_curve(&a, g_in, 9, 1, &o, &out, &d), &d, SUBD_ERR_DIVERGENT);
    CHECK_EQ(subd_alpha_curve_plan(9, 1, &o, &plan, 0), SUBD_ERR_DIVERGENT);
    o.stiffness = SUBD_REAL_FRAC(-9, 10);
    CHECK_FAIL(subd_alpha_curve(&a, g_in, 9, 0, &o, &out, &d), &d, SUBD_ERR_DIVERGENT);
    o.stiffness = h_int(-1);
    CHECK_FAIL(subd_alpha_curve(&a, g_in, 9, 1, &o, &out, &d), &d, SUBD_ERR_DIVERGENT);
    CHECK_EQ(subd_arena_mark(&a), 0);
    for (k = 2; k <= 4u; k++)
        for (closed = 1; closed < 2u; closed++) { /* closed: max_edge also measures p[m-1] p[0] */
            sq_t e0, e5;
            rand_poly(9);
            opts(&o, k, 1, SUBD_ALPHA_BSPLINE, 0, 1);
            o.stiffness = SUBD_REAL_FRAC(-49, 100);
            if (!run(&a, g_in, 9, (int)closed, &o, &out)) return;
            e0 = max_edge(&out);
            o.levels = 6;
            subd_arena_init(&a, WORK_BUF, WORK_BYTES);
            if (!run(&a, g_in, 9, (int)closed, &o, &out)) return;
            e5 = max_edge(&out);
            CHECK(e5 < e0);
            subd_arena_init(&a, WORK_BUF, WORK_BYTES);
        }
    rand_poly(5);
    opts(&o, 2, 1, SUBD_ALPHA_COS, 3, 5);
    o.stiffness = h_int(2);
#if SUBD_FIXED /* not a ternary: 3e38f has no Q16.16 value (clang -Wliteral-conversion) */
    g_in[0] = h_int(30000);
#else
    g_in[0] = 3e38f;
#endif
    CHECK_FAIL(subd_alpha_curve(&a, g_in, 5, 1, &o, &out, &d), &d, SUBD_ERR_RANGE);
    CHECK_EQ(subd_arena_mark(&a), 0);
}

const test_case suite_alpha_curve[] = {
    {"alpha_kernel_values", alpha_kernel_values},
    {"alpha_bspline_masks", alpha_bspline_masks},
    {"alpha_open_end_condition", alpha_open_end_condition},
    {"alpha_ccurve_circle", alpha_ccurve_circle},
    {"alpha_ccurve_affine", alpha_ccurve_affine},
    {"alpha_open_arc", alpha_open_arc},
#if H_HOST
    {"alpha_cosh_hyperbola", alpha_cosh_hyperbola},
#endif
    {"alpha_stiffness", alpha_stiffness},
    {"alpha_per_vertex", alpha_per_vertex},
    {"alpha_plan_exact", alpha_plan_exact},
    {"alpha_curve_errors", alpha_curve_errors},
    {"alpha_curve_hashes", alpha_curve_hashes},
    {"alpha_kernel_range", alpha_kernel_range},
    {"alpha_curve_huge_m", alpha_curve_huge_m},
    {"alpha_divergent", alpha_divergent},
    {0, 0}
};
