/* SPDX-License-Identifier: MIT */
/* Doo-Sabin type alpha-subdivision surface (src/alpha_surface.c, formula (3)): f = 1 on a
 * quad gives 9/16, 3/16, 3/16, 1/16; on a regular quad grid the operator is the tensor
 * product of the curve operator S_2 for any f; theorem 2 (each face's centroid is kept;
 * the circulant eigenvalues lambda_j); closed-form counts over levels, Euler characteristic
 * and boundary loops kept; exact plans with every too-small arena; error paths; hashes.
 * Higher orders S_k = C^(k-2) S_2: S_3 with f = 1 on a regular quad grid is the tensor
 * cubic B-spline refinement (exact); closed-form counts, Euler characteristic, boundary
 * loops, plan = peak and hashes for k = 3..5; every too-small arena for S_3 and S_4. */
#include <string.h>
#include "harness.h"
#include "corpus.h"
#include "subd_alpha.h"
#include "subd_loop.h"
#if H_HOST
#include <math.h>
#include <stdio.h>
#endif

#define MAXV 400
#define MAXC 1600
static subd_real g_pos[3 * MAXV];
static uint32_t g_idx[MAXC], g_size[MAXC];
static uint32_t g_state = 4242u;

#if H_HOST
#define WORK_BYTES (8u * 1024u * 1024u)
static uint8_t work_buf[WORK_BYTES] __attribute__((aligned(8)));
#define WORK_BUF work_buf
#else
#define WORK_BYTES H_ARENA_BYTES
#define WORK_BUF h_arena_buf
#endif


static void sopts(subd_alpha_opts *o, uint32_t levels, uint32_t kernel, int32_t num, int32_t den, subd_real s)
{
    subd_alpha_opts_default(o);
    o->levels = levels;
    o->kernel = kernel;
    o->alpha_num = num;
    o->alpha_den = den;
    o->stiffness = s;
}

/* The quantities the closed-form counts use, by brute force over the input: interior edges,
 * interior vertices and the sum of the interior vertices' valences. */
static void interior_counts(const subd_mesh *m, uint32_t *ei, uint32_t *vi, uint32_t *s)
{
    uint32_t h;
    *ei = *vi = *s = 0;
    for (h = 0; h < m->num_corners; h++)
        if (m->twin[h] != SUBD_NONE && h < m->twin[h]) (*ei)++;
    for (h = 0; h < m->num_verts; h++)
        if (!(m->vert_tag[h] & (SUBD_VTAG_BOUNDARY | SUBD_VTAG_ISOLATED))) {
            (*vi)++;
            *s += subd_vertex_valence(m, h);
        }
}

/* (n+1) x (m+1) planar grid of quads, z a bumpy integer height; an open disk. */
static subd_face_list quad_grid(uint32_t n, uint32_t m)
{
    subd_face_list fl = {0, 0, 0, 0, 0, 0, 0, 0};
    uint32_t i, j, k = 0, f = 0;
    for (i = 0; i <= n; i++)
        for (j = 0; j <= m; j++) {
            uint32_t v = i * (m + 1u) + j;
            g_pos[3u * v] = h_int((int32_t)j * 4);
            g_pos[3u * v + 1u] = h_int((int32_t)i * 4);
            g_pos[3u * v + 2u] = h_int((int32_t)(h_rand(&g_state) % 9u) - 4);
        }
    for (i = 0; i < n; i++)
        for (j = 0; j < m; j++) {
            uint32_t a = i * (m + 1u) + j;
            g_idx[k++] = a;
            g_idx[k++] = a + 1u;
            g_idx[k++] = a + m + 2u;
            g_idx[k++] = a + m + 1u;
            g_size[f++] = 4;
        }
    fl.num_verts = (n + 1u) * (m + 1u);
    fl.pos = g_pos;
    fl.num_faces = f;
    fl.face_size = g_size;
    fl.index = g_idx;
    return fl;
}

/* One N-gon, vertices given. */
static subd_face_list one_face(uint32_t n)
{
    subd_face_list fl = {0, 0, 0, 0, 0, 0, 0, 0};
    uint32_t i;
    for (i = 0; i < n; i++) g_idx[i] = i;
    g_size[0] = n;
    fl.num_verts = n;
    fl.pos = g_pos;
    fl.num_faces = 1;
    fl.face_size = g_size;
    fl.index = g_idx;
    return fl;
}

static int read_obj(subd_arena *a, const char *name, subd_mesh *m)
{
    const corpus_file *f = corpus_find(name);
    subd_diag d;
    if (!CHECK(f != 0)) return 0;
    return CHECK_EQ(subd_obj_read(a, f->data, f->len, m, &d), SUBD_OK);
}

static int ds(subd_arena *a, const subd_mesh *in, const subd_alpha_opts *o, subd_mesh *out)
{
    subd_diag d;
    subd_alpha_surface_info info;
    return CHECK_EQ(subd_alpha_surface(a, in, o, out, &info, &d), SUBD_OK);
}

/* ------------------------------------------------------------------------------------ */

static void alpha_ds_quad_weights(void)
{
    subd_arena a;
    subd_mesh in, out;
    subd_alpha_opts o;
    subd_face_list fl = one_face(4);
    uint32_t i, c, ovf = 0, ok = 1;
    for (i = 0; i < 12u; i++) g_pos[i] = h_int((int32_t)(h_rand(&g_state) % 41u) - 20);
    subd_arena_init(&a, WORK_BUF, WORK_BYTES);
    if (!h_build(&a, &fl, &in)) return;
    sopts(&o, 1, SUBD_ALPHA_BSPLINE, 0, 1, SUBD_REAL_ONE);
    if (!ds(&a, &in, &o, &out)) return;
    CHECK_EQ(out.num_verts, 4);
    CHECK_EQ(out.num_faces, 1);
    for (i = 0; i < 4u; i++)
        for (c = 0; c < 3u; c++) {
            subd_acc acc = subd_acc_zero();
            acc = subd_acc_add(acc, SUBD_REAL_FRAC(9, 16), g_pos[3u * i + c]);
            acc = subd_acc_add(acc, SUBD_REAL_FRAC(3, 16), g_pos[3u * ((i + 1u) % 4u) + c]);
            acc = subd_acc_add(acc, SUBD_REAL_FRAC(1, 16), g_pos[3u * ((i + 2u) % 4u) + c]);
            acc = subd_acc_add(acc, SUBD_REAL_FRAC(3, 16), g_pos[3u * ((i + 3u) % 4u) + c]);
            ok &= h_same(out.pos[3u * i + c], subd_acc_real(acc, &ovf));
        }
    CHECK(ok);
    /* the cube: 24 vertices, 6 + 12 + 8 faces, closed, Euler 2 */
    subd_arena_init(&a, WORK_BUF, WORK_BYTES);
    if (!read_obj(&a, "test/data/cube_quad.obj", &in) || !ds(&a, &in, &o, &out)) return;
    CHECK_EQ(out.num_verts, 24);
    CHECK_EQ(out.num_faces, 26);
    CHECK_EQ(out.num_boundary_edges, 0);
    CHECK_EQ(subd_mesh_euler(&out), 2);
    h_hash("alpha_ds_cube", h_mesh_hash(&out));
}

#if H_HOST
/* Regular quad grid: every output corner of face (i, j) is the tensor product of the
 * curve weights w0 = (1+2f)/(2+2f), w1 = 1/(2+2f): w0^2 p + w0 w1 (p_prev + p_next) + w1^2
 * p_opposite; f from the kernel, for several kernels and stiffnesses. */
static void alpha_ds_tensor(void)
{
    static const int32_t s8[4] = {3, 8, 20, 1}; /* s = -1/2 (was here) is refused now */
    uint32_t si, kern;
    double worst = 0;
    for (kern = 0; kern < 2u; kern++)
        for (si = 0; si < 4u; si++) {
            subd_arena a;
            subd_mesh in, out;
            subd_alpha_opts o;
            subd_face_list fl = quad_grid(5, 4);
            subd_real fr;
            double f, w0, w1;
            uint32_t fc, i, c;
            sopts(&o, 1, kern, 1, 7, SUBD_REAL_FRAC(s8[si], 8));
            subd_arena_init(&a, WORK_BUF, WORK_BYTES);
            if (!h_build(&a, &fl, &in) || !ds(&a, &in, &o, &out)) return;
            if (!CHECK_EQ(subd_alpha_kernel_value(kern, 1, 7, 0, o.stiffness, &fr), SUBD_OK)) return;
            f = h_dbl(fr);
            w0 = (1 + 2 * f) / (2 + 2 * f);
            w1 = 1 / (2 + 2 * f);
            for (fc = 0; fc < in.num_faces; fc++)
                for (i = 0; i < 4u; i++)
                    for (c = 0; c < 3u; c++) {
                        uint32_t b = in.face_start[fc];
                        double p = h_dbl(in.pos[3u * in.corner_vert[b + i] + c]);
                        double pn = h_dbl(in.pos[3u * in.corner_vert[b + (i + 1u) % 4u] + c]);
                        double po = h_dbl(in.pos[3u * in.corner_vert[b + (i + 2u) % 4u] + c]);
                        double pp = h_dbl(in.pos[3u * in.corner_vert[b + (i + 3u) % 4u] + c]);
                        double want = w0 * w0 * p + w0 * w1 * (pn + pp) + w1 * w1 * po;
                        double e = fabs(h_dbl(out.pos[3u * (b + i) + c]) - want);
                        if (e > worst) worst = e;
                    }
        }
    /* coordinates up to 20: float 1e-6 relative to that; fixed 2 LSB */
    CHECK(worst <= (SUBD_FIXED ? 2.0 / 65536.0 : 2e-5));
    {
        char buf[120];
        snprintf(buf, sizeof buf, "  note: DS tensor-product max abs error = %.3g%s\n",
                 SUBD_FIXED ? worst * 65536.0 : worst, SUBD_FIXED ? " LSB" : "");
        h_str(buf);
    }
}

/* Circulant eigenvalues: one N-gon whose x, y are the real and imaginary parts of the
 * eigenvector W_j (radius 8) is mapped to lambda_j times itself. lambda_j is computed
 * independently by lemma 1 from the paper's own circulant row S_2^(n) = Cir_N[(1/N + f +
 * f^2), (1/N + f/2), 1/N, .., 1/N, (1/N + f/2)] / (1+f)^2 (which is formula (3)):
 * lambda_j = sum_i a_i w_j^(i-1) = f/(1+f) + f/(1+f)^2 cos(2 pi (j-1)/N).
 * The closed form printed in the paper's proof of theorem 2, f/(1+f) + 2f/(1+f)^2 cos(..),
 * has the cosine term twice too large: it contradicts the circulant just above it and
 * Doo-Sabin's quad eigenvalues 1, 1/2, 1/4 at f = 1 (it gives 1, 1/2, 0). The test shows
 * that the measured values match lemma 1 and differ from the printed form by exactly
 * f/(1+f)^2 cos(2 pi (j-1)/N). Theorem 2's conclusions (|lambda_j| < 1 for j > 1 and
 * f_n > 0, lambda_2 = lambda_N the largest) hold for the corrected values as well. */
static void alpha_ds_eigen(void)
{
    static const int32_t s8[3] = {4, 8, 24};
    uint32_t n, j, si;
    double worst = 0;
    for (n = 3; n <= 8u; n++)
        for (j = 1; j <= n; j++)
            for (si = 0; si < 4u; si++) {
                subd_arena a;
                subd_mesh in, out;
                subd_alpha_opts o;
                subd_face_list fl;
                subd_real fr;
                double f, lam, num = 0, den = 0, res = 0, th;
                uint32_t i, kern = si == 3u ? SUBD_ALPHA_COS : SUBD_ALPHA_BSPLINE;
                for (i = 0; i < n; i++) {
                    th = 2 * 3.14159265358979323846 * (double)((j - 1u) * i) / n;
                    /* j = 1: the constant vector, shifted off the origin */
                    g_pos[3u * i] = (subd_real)(SUBD_FIXED ? floor(8 * cos(th) * 65536 + 0.5) : 8 * cos(th));
                    g_pos[3u * i + 1u] = (subd_real)(SUBD_FIXED ? floor(8 * sin(th) * 65536 + 0.5) : 8 * sin(th));
                    g_pos[3u * i + 2u] = 0;
                }
                fl = one_face(n);
                sopts(&o, 1, kern, 1, 5, si == 3u ? SUBD_REAL_ONE : SUBD_REAL_FRAC(s8[si], 8));
                subd_arena_init(&a, WORK_BUF, WORK_BYTES);
                if (!h_build(&a, &fl, &in) || !ds(&a, &in, &o, &out)) return;
                if (!CHECK_EQ(subd_alpha_kernel_value(kern, 1, 5, 0, o.stiffness, &fr), SUBD_OK)) return;
                f = h_dbl(fr);
                {
                    /* lemma 1 on the circulant row, summed term by term (real part) */
                    double re = 0, im = 0, q = 1.0 / ((1 + f) * (1 + f)), printed;
                    for (i = 0; i < n; i++) {
                        double ai = (i == 0u) ? (1.0 / n + f + f * f) * q
                                    : (i == 1u || i == n - 1u) ? (1.0 / n + f / 2) * q : q / n;
                        double ph = 2 * 3.14159265358979323846 * (double)((j - 1u) * i) / n;
                        re += ai * cos(ph);
                        im += ai * sin(ph);
                    }
                    CHECK(fabs(im) < 1e-12);
                    lam = re;
                    printed = (j == 1u) ? 1.0 : f / (1 + f) + 2 * f * q * cos(2 * 3.14159265358979323846 * (j - 1u) / n);
                    CHECK(fabs((printed - lam) - ((j == 1u) ? 0.0 : f * q * cos(2 * 3.14159265358979323846 * (j - 1u) / n))) < 1e-12);
                    if (n == 4u && si == 1u) /* f = 1: Doo-Sabin's 1, 1/2, 1/4, 1/2 */
                        CHECK(fabs(lam - (j == 1u ? 1.0 : j == 3u ? 0.25 : 0.5)) < 1e-12);
                }
                for (i = 0; i < n; i++) {
                    double x = h_dbl(in.pos[3u * i]), y = h_dbl(in.pos[3u * i + 1u]);
                    double u = h_dbl(out.pos[3u * i]), v = h_dbl(out.pos[3u * i + 1u]);
                    num += u * x + v * y;
                    den += x * x + y * y;
                }
                for (i = 0; i < n; i++) {
                    double e = hypot(h_dbl(out.pos[3u * i]) - num / den * h_dbl(in.pos[3u * i]),
                                     h_dbl(out.pos[3u * i + 1u]) - num / den * h_dbl(in.pos[3u * i + 1u]));
                    if (e > res) res = e;
                }
                /* the measured eigenvalue and the paper's lambda_j agree; the output is
                 * lambda times the input (an eigenvector) */
                if (fabs(num / den - lam) > worst) worst = fabs(num / den - lam);
                CHECK(fabs(num / den - lam) <= (SUBD_FIXED ? 2e-5 : 1e-6));
                CHECK(res <= (SUBD_FIXED ? 3.0 / 65536.0 : 4e-6));
            }
    {
        char buf[120];
        snprintf(buf, sizeof buf, "  note: circulant eigenvalue max |measured - lambda_j| = %.3g\n", worst);
        h_str(buf);
    }
}
#endif

/* Theorem 2: every face's centroid is kept by a step (up to one rounding). Checked in
 * subd_real arithmetic so it also runs on the device. */
static subd_real face_centroid(const subd_real *pos, const uint32_t *cv, uint32_t s, uint32_t e, uint32_t k,
                               int direct)
{
    uint32_t i, ovf = 0;
#if SUBD_FIXED
    int64_t sum = 0, n = (int64_t)(e - s);
    for (i = s; i < e; i++) sum += pos[3u * (direct ? i : cv[i]) + k];
    (void)ovf;
    return (subd_real)((sum >= 0) ? (sum + n / 2) / n : -((-sum + n / 2) / n));
#else
    float sum = 0.0f;
    for (i = s; i < e; i++) sum = subd_add(sum, pos[3u * (direct ? i : cv[i]) + k], &ovf);
    return sum / (float)(e - s);
#endif
}

static void alpha_ds_centroid(void)
{
    /* stiffness * 8 and the allowed shift: 2 units (LSB, or 1e-7 in float where the
     * coordinates are within 1) for s > 0, where the weights f/(1+f) + f/(1+f)^2 of the
     * centroid's own rounding error are < 1; for s = -3/8 (not smooth; theorem 1 refuses
     * s <= -1/2) f/(1+f) = -0.6 and f/(2(1+f)^2) = -0.48 magnify that 1/2-unit error (and
     * in float the rounding of every weighted difference as well) */
    static const int32_t s8[5] = {2, 8, 40, -3, 8}, bound[5] = {2, 2, 2, SUBD_FIXED ? 10 : 20, 2};
    uint32_t si, f, k;
    for (si = 0; si < 5u; si++) {
        subd_arena a;
        subd_mesh in, out;
        subd_alpha_opts o;
        uint32_t worst = 0;
        subd_arena_init(&a, WORK_BUF, WORK_BYTES);
        if (!read_obj(&a, "test/data/spot_control_mesh.obj", &in)) return;
        sopts(&o, 1, si == 4u ? SUBD_ALPHA_COS : SUBD_ALPHA_BSPLINE, 1, 6, SUBD_REAL_FRAC(s8[si], 8));
        if (!ds(&a, &in, &o, &out)) return;
        for (f = 0; f < in.num_faces; f++)
            for (k = 0; k < 3u; k++) {
                uint32_t s = in.face_start[f], e = in.face_start[f + 1u];
                subd_real c0 = face_centroid(in.pos, in.corner_vert, s, e, k, 0);
                subd_real c1 = face_centroid(out.pos, out.corner_vert, s, e, k, 0);
#if SUBD_FIXED
                uint32_t diff = (uint32_t)(c0 > c1 ? c0 - c1 : c1 - c0);
#else
                float dd = c0 > c1 ? c0 - c1 : c1 - c0;
                uint32_t diff = (uint32_t)(dd * 1e7f); /* in units of 1e-7 (coordinates ~1) */
#endif
                if (diff > worst) worst = diff;
            }
        /* the output F-face f has the same corner range as the input face f */
        CHECK_EQ(out.face_start[in.num_faces], in.num_corners);
        CHECK(worst <= (uint32_t)bound[si]);
        h_str("  note: DS centroid max shift, s = ");
        h_i32(s8[si]);
        h_str("/8: ");
        h_u32(worst);
        h_str(SUBD_FIXED ? " LSB" : " x 1e-7");
        h_nl();
    }
}

/* Counts over levels follow the closed form; Euler characteristic and boundary loops are
 * kept; hashes. */
static void alpha_ds_levels(void)
{
    static const char *const files[3] = {"test/data/cube_quad.obj", "test/data/hexfan.obj",
                                          "test/data/spot_control_mesh.obj"};
    uint32_t fi, lev;
    g_state = 4242u; /* host-only tests draw random numbers too: restart for the hashes */
    for (fi = 0; fi < 4u; fi++)
        /* the device arena (256 KiB) holds the spot mesh's level 1 only */
        for (lev = 1; lev <= (H_HOST ? 3u : fi == 2u ? 1u : 2u); lev++) {
            subd_arena a;
            subd_mesh in, out;
            subd_alpha_opts o;
            uint32_t v, f, c, ei, vi, s, l, plan;
            subd_arena_init(&a, WORK_BUF, WORK_BYTES);
            if (fi < 3u) {
                if (!read_obj(&a, files[fi], &in)) return;
            } else {
                subd_face_list fl = quad_grid(4, 3);
                if (!h_build(&a, &fl, &in)) return;
            }
            /* closed form */
            v = in.num_verts;
            f = in.num_faces;
            c = in.num_corners;
            interior_counts(&in, &ei, &vi, &s);
            for (l = 0; l < lev; l++) {
                uint32_t nf = f + ei + vi, nc = c + 4u * ei + s;
                v = c;
                f = nf;
                c = nc;
                ei = 2u * ei + s;
                vi = s;
                s = 4u * s;
            }
            sopts(&o, lev, SUBD_ALPHA_COS, 1, 4, SUBD_REAL_FRAC(7, 8));
            if (!CHECK_EQ(subd_alpha_surface_plan(&in, &o, &plan, 0), SUBD_OK)) return;
            {
                uint32_t m0 = subd_arena_mark(&a);
                if (!ds(&a, &in, &o, &out)) return;
                CHECK(a.peak - m0 <= plan);
            }
            CHECK_EQ(out.num_verts, v);
            CHECK_EQ(out.num_faces, f);
            CHECK_EQ(out.num_corners, c);
            CHECK_EQ(out.num_edges - out.num_boundary_edges, ei);
            CHECK_EQ(subd_mesh_euler(&out), subd_mesh_euler(&in) - (int32_t)in.num_isolated);
            CHECK_EQ(out.num_boundary_loops, in.num_boundary_loops);
            if (lev == (fi == 2u ? 1u : 2u))
                h_hash(fi == 0u ? "alpha_ds_cube_l2" : fi == 1u ? "alpha_ds_hexfan_l2"
                       : fi == 2u ? "alpha_ds_spot_l1" : "alpha_ds_grid_l2",
                       h_mesh_hash(&out));
        }
}

static int surface_run(void *ctx, subd_arena *a, subd_diag *d)
{
    h_mesh_call *c = (h_mesh_call *)ctx;
    return subd_alpha_surface(a, c->in, (const subd_alpha_opts *)c->opts, &c->out, 0, d);
}

static void check_plan_exhaustive(const subd_mesh *in, const subd_alpha_opts *o)
{
    static uint8_t buf[40000 + 8 + 64] __attribute__((aligned(8)));
    uint32_t plan;
    h_mesh_call c;
    h_sweep s;
    if (!CHECK_EQ(subd_alpha_surface_plan(in, o, &plan, 0), SUBD_OK)) return;
    c.in = in;
    c.opts = o;
    s = h_mesh_sweep(surface_run, &c, buf, sizeof buf, plan);
    s.prefix = 8;
    s.step = H_HOST ? 1u : 8u; /* every size on the host; every 8th (and the last 64) on the device */
    (void)h_arena_sweep(&s);
}

static void alpha_ds_plan_exact(void)
{
    subd_arena a;
    subd_mesh cube, grid;
    subd_alpha_opts o;
    subd_face_list fl = quad_grid(3, 2);
    uint32_t lev;
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    if (!read_obj(&a, "test/data/cube_quad.obj", &cube) || !h_build(&a, &fl, &grid)) return;
    for (lev = 1; lev <= 2u; lev++) {
        sopts(&o, lev, SUBD_ALPHA_COS, 1, 4, SUBD_REAL_ONE);
        check_plan_exhaustive(&cube, &o);
        check_plan_exhaustive(&grid, &o);
    }
}

static void alpha_ds_errors(void)
{
    subd_arena a;
    subd_mesh in, out;
    subd_alpha_opts o;
    subd_diag d;
    subd_face_list fl = quad_grid(2, 2);
    uint32_t plan, i, m0;
    subd_arena_init(&a, WORK_BUF, WORK_BYTES);
    if (!h_build(&a, &fl, &in)) return;
    m0 = subd_arena_mark(&a);
    sopts(&o, 1, SUBD_ALPHA_COS, 1, 4, SUBD_REAL_ONE);
    CHECK_FAIL(subd_alpha_surface(0, &in, &o, &out, 0, &d), &d, SUBD_ERR_PARAM);
    CHECK_FAIL(subd_alpha_surface(&a, 0, &o, &out, 0, &d), &d, SUBD_ERR_PARAM);
    CHECK_FAIL(subd_alpha_surface(&a, &in, &o, 0, 0, &d), &d, SUBD_ERR_PARAM);
    CHECK_EQ(subd_alpha_surface_plan(&in, &o, 0, 0), SUBD_ERR_PARAM);
    o.levels = 0;
    CHECK_FAIL(subd_alpha_surface(&a, &in, &o, &out, 0, &d), &d, SUBD_ERR_PARAM);
    o.levels = 1;
    o.order = SUBD_ALPHA_MAX_ORDER + 1u;
    CHECK_FAIL(subd_alpha_surface(&a, &in, &o, &out, 0, &d), &d, SUBD_ERR_PARAM);
    CHECK_EQ(subd_alpha_surface_plan(&in, &o, &plan, 0), SUBD_ERR_PARAM);
    o.order = 1;
    CHECK_FAIL(subd_alpha_surface(&a, &in, &o, &out, 0, &d), &d, SUBD_ERR_PARAM);
    o.order = 2;
    CHECK_EQ(subd_arena_mark(&a), m0);
    o.stiffness = h_int(-1); /* table 1 and theorem 1: diverges */
    CHECK_FAIL(subd_alpha_surface(&a, &in, &o, &out, 0, &d), &d, SUBD_ERR_DIVERGENT);
    CHECK_EQ(subd_alpha_surface_plan(&in, &o, &plan, 0), SUBD_ERR_DIVERGENT);
#if !SUBD_FIXED
    o.stiffness = 3e9f; /* outside the internal Q32.32 range */
    CHECK_FAIL(subd_alpha_surface(&a, &in, &o, &out, 0, &d), &d, SUBD_ERR_PARAM);
    CHECK_EQ(subd_alpha_surface_plan(&in, &o, &plan, 0), SUBD_ERR_PARAM);
#endif
    /* a level with f_n <= -1: s = 2, cos kernel, f_0 = 2 cos(0.45 turn) */
    sopts(&o, 1, SUBD_ALPHA_COS, 9, 10, h_int(2));
    CHECK_FAIL(subd_alpha_surface(&a, &in, &o, &out, 0, &d), &d, SUBD_ERR_PARAM);
    sopts(&o, 1, SUBD_ALPHA_COS, 1, 4, SUBD_REAL_ONE);
    /* s in (-1/2, 0]: accepted, not smooth; s in (0, 1/2]: GC0; above: GC1 */
    {
        subd_alpha_surface_info info;
        o.stiffness = SUBD_REAL_FRAC(-49, 100);
        if (CHECK_EQ(subd_alpha_surface(&a, &in, &o, &out, &info, &d), SUBD_OK)) CHECK_EQ(info.continuity, -1);
        subd_arena_rewind(&a, m0);
        o.stiffness = SUBD_REAL_FRAC(1, 2);
        if (CHECK_EQ(subd_alpha_surface(&a, &in, &o, &out, &info, &d), SUBD_OK)) CHECK_EQ(info.continuity, 0);
        subd_arena_rewind(&a, m0);
        o.stiffness = SUBD_REAL_ONE;
        if (CHECK_EQ(subd_alpha_surface(&a, &in, &o, &out, &info, &d), SUBD_OK)) CHECK_EQ(info.continuity, 1);
        subd_arena_rewind(&a, m0);
    }
    /* overflow: s = 2, cos kernel, f_0 = 2 cos(0.3 turn) = -0.62 makes f/(1+f) = -1.6 */
    sopts(&o, 1, SUBD_ALPHA_COS, 3, 5, h_int(2));
    for (i = 0; i < in.num_verts; i++) in.pos[3u * i] = SUBD_FIXED ? h_int((int32_t)(i * 4000u)) : (float)i * 4e37f;
    CHECK_FAIL(subd_alpha_surface(&a, &in, &o, &out, 0, &d), &d, SUBD_ERR_RANGE);
    CHECK_EQ(subd_arena_mark(&a), m0);
    /* a vertex of valence 33 > SUBD_MAX_FACE_SIZE would make a 33-gon */
    {
        subd_face_list fan = {0, 0, 0, 0, 0, 0, 0, 0};
        uint32_t n = SUBD_MAX_FACE_SIZE + 1u;
        for (i = 0; i <= n; i++) {
            g_pos[3u * i] = h_int(i == 0 ? 0 : (int32_t)(i % 7u));
            g_pos[3u * i + 1u] = h_int(i == 0 ? 0 : (int32_t)(i % 5u));
            g_pos[3u * i + 2u] = h_int((int32_t)i);
        }
        for (i = 0; i < n; i++) {
            g_idx[3u * i] = 0;
            g_idx[3u * i + 1u] = 1u + i;
            g_idx[3u * i + 2u] = 1u + (i + 1u) % n;
        }
        fan.num_verts = n + 1u;
        fan.pos = g_pos;
        fan.num_faces = n;
        fan.index = g_idx;
        subd_arena_rewind(&a, m0);
        if (!h_build(&a, &fan, &in)) return;
        sopts(&o, 1, SUBD_ALPHA_BSPLINE, 0, 1, SUBD_REAL_ONE);
        CHECK_FAIL(subd_alpha_surface(&a, &in, &o, &out, 0, &d), &d, SUBD_ERR_FACE_SIZE);
        CHECK_EQ(d.vertex, 0);
    }
    /* no faces */
    {
        subd_face_list pts = {0, 0, 0, 0, 0, 0, 0, 0};
        pts.num_verts = 3;
        pts.pos = g_pos;
        subd_arena_rewind(&a, m0);
        if (!h_build(&a, &pts, &in)) return;
        CHECK_FAIL(subd_alpha_surface(&a, &in, &o, &out, 0, &d), &d, SUBD_ERR_EMPTY);
    }
}

static void alpha_ds_hashes(void)
{
    uint32_t kern;
    for (kern = 0; kern < 4u; kern++) {
        subd_arena a;
        subd_mesh in, out;
        subd_alpha_opts o;
        char name[] = "alpha_ds_spot_k0";
        subd_arena_init(&a, WORK_BUF, WORK_BYTES);
        if (!read_obj(&a, "test/data/spot_control_mesh.obj", &in)) return;
        sopts(&o, 1, kern, 1, 6, SUBD_REAL_FRAC(5, 4));
        if (!ds(&a, &in, &o, &out)) return;
        name[15] = (char)('0' + kern);
        h_hash(name, h_mesh_hash(&out));
    }
}

/* ------------------------------------------------------------------------------------ */
/* Higher orders S_k = C^(k-2) S_2 (section 2.2).                                          */

/* S_3 = C S_2 with f = 1 on a regular quad grid is the tensor-product cubic B-spline
 * refinement (Catmull-Clark on regular quads): the face-copy centroids are the face points
 * (1/4 each corner), the edge-quad centroids the edge points ((1 6 1)/8 across times (1 1)/2
 * along), the vertex-face centroids the vertex points ((1 6 1)/8 x (1 6 1)/8). Expected
 * values from those masks in integers (64ths) on the input grid; exact in both arithmetics
 * (every intermediate is a short dyadic). Output vertex j < F + E_i + V_i is the centroid
 * of the Doo-Sabin mesh's face j (documented order: input faces, interior edges by
 * half-edge, interior vertices by index). */
static int64_t ival(subd_real x) /* an integer-valued subd_real's value */
{
#if SUBD_FIXED
    return (int64_t)(x / 65536);
#else
    return (int64_t)(int32_t)x;
#endif
}

static void alpha_s3_bspline(void)
{
    subd_arena a;
    subd_mesh in, out;
    subd_alpha_opts o;
    subd_face_list fl;
    uint32_t f, h, v, k, j = 0, bad = 0;
    int64_t want[3];
    g_state = 555u; /* host-only tests draw random numbers too */
    fl = quad_grid(4, 5);
    subd_arena_init(&a, WORK_BUF, WORK_BYTES);
    if (!h_build(&a, &fl, &in)) return;
    sopts(&o, 1, SUBD_ALPHA_BSPLINE, 0, 1, SUBD_REAL_ONE);
    o.order = 3;
    if (!ds(&a, &in, &o, &out)) return;
#define FACE_SUM(ff, kk, acc)                                                                    \
    do {                                                                                       \
        uint32_t c_;                                                                           \
        for (c_ = in.face_start[ff]; c_ < in.face_start[(ff) + 1u]; c_++)                      \
            acc += ival(in.pos[3u * in.corner_vert[c_] + (kk)]); \
    } while (0)
    for (f = 0; f < in.num_faces; f++, j++)
        for (k = 0; k < 3u; k++) {
            int64_t sum = 0;
            FACE_SUM(f, k, sum);
            want[k] = 16 * sum;
            bad += !h_same(out.pos[3u * j + k], subd_div(h_int((int32_t)want[k]), h_int(64), &bad));
        }
    for (h = 0; h < in.num_corners; h++) {
        uint32_t t = in.twin[h];
        if (t == SUBD_NONE || t < h) continue;
        for (k = 0; k < 3u; k++) {
            int64_t s1 = 0, s2 = 0;
            FACE_SUM(in.corner_face[h], k, s1);
            FACE_SUM(in.corner_face[t], k, s2);
            want[k] = 4 * (s1 + s2) + 16 * (ival(in.pos[3u * in.corner_vert[h] + k]) + ival(in.pos[3u * in.corner_vert[t] + k]));
            bad += !h_same(out.pos[3u * j + k], subd_div(h_int((int32_t)want[k]), h_int(64), &bad));
        }
        j++;
    }
    for (v = 0; v < in.num_verts; v++) {
        uint32_t nbr[8], n, i, first = in.vert_out[v];
        if (in.vert_tag[v] & SUBD_VTAG_BOUNDARY) continue;
        n = subd_vertex_ring(&in, v, nbr, 8);
        if (!CHECK_EQ(n, 4)) return;
        for (k = 0; k < 3u; k++) {
            int64_t sf = 0, se = 0;
            for (h = first; h != SUBD_NONE; h = subd_ring_next(&in, first, h)) FACE_SUM(in.corner_face[h], k, sf);
            for (i = 0; i < n; i++) se += ival(in.pos[3u * nbr[i] + k]);
            want[k] = sf + 4 * se + 32 * ival(in.pos[3u * v + k]);
            bad += !h_same(out.pos[3u * j + k], subd_div(h_int((int32_t)want[k]), h_int(64), &bad));
        }
        j++;
    }
#undef FACE_SUM
    CHECK_EQ(j, 20u + 31u + 12u);
    CHECK_EQ(bad, 0);
    h_hash("alpha_s3_grid_bspline", h_mesh_hash(&out));
}

/* C's boundary rule: after S_2 (out2), S_3 (out3) has out2's face centroids, then the
 * midpoints of out2's boundary edges (half-edge order), then out2's boundary vertices
 * unchanged (vertex order); the boundary loops keep their shape. */
static void alpha_s3_boundary(void)
{
    subd_arena a;
    subd_mesh in, out2, out3;
    subd_alpha_opts o;
    subd_face_list fl;
    uint32_t h, v, k, n, bad = 0;
    g_state = 99u;
    fl = quad_grid(3, 4);
    subd_arena_init(&a, WORK_BUF, WORK_BYTES);
    if (!h_build(&a, &fl, &in)) return;
    sopts(&o, 1, SUBD_ALPHA_COS, 1, 7, SUBD_REAL_FRAC(5, 4));
    if (!ds(&a, &in, &o, &out2)) return;
    o.order = 3;
    if (!ds(&a, &in, &o, &out3)) return;
    n = out2.num_faces;
    for (h = 0; h < out2.num_corners; h++) {
        uint32_t p = out2.corner_vert[h], q;
        if (out2.twin[h] != SUBD_NONE) continue;
        q = subd_he_dest(&out2, h);
        for (k = 0; k < 3u; k++) {
            subd_real m = out3.pos[3u * n + k], x = out2.pos[3u * p + k], y = out2.pos[3u * q + k];
#if SUBD_FIXED
            int64_t e = 2 * (int64_t)m - ((int64_t)x + y);
            bad += (e < -1 || e > 1);
#else
            uint32_t ovf = 0;
            bad += !h_same(subd_add(m, m, &ovf), subd_add(x, y, &ovf));
#endif
        }
        n++;
    }
    for (v = 0; v < out2.num_verts; v++) {
        if (!(out2.vert_tag[v] & SUBD_VTAG_BOUNDARY)) continue;
        for (k = 0; k < 3u; k++) bad += !h_same(out3.pos[3u * n + k], out2.pos[3u * v + k]);
        n++;
    }
    CHECK_EQ(n, out3.num_verts);
    CHECK_EQ(bad, 0);
    CHECK_EQ(out3.num_boundary_edges, 2u * out2.num_boundary_edges);
    CHECK_EQ(out3.num_boundary_loops, 1);
    h_hash("alpha_s3_grid_cos", h_mesh_hash(&out3));
}

/* Closed-form counts of S_k over levels (S_2 then k - 2 times C per level, header
 * formulas), Euler characteristic and boundary loops kept, plan >= peak, hashes. */
static void alpha_sk_levels(void)
{
    static const char *const files[2] = {"test/data/cube_quad.obj", "test/data/hexfan.obj"};
    uint32_t fi, lev, order;
    for (fi = 0; fi < 4u; fi++)
        for (order = 3; order <= 5u; order++)
            for (lev = 1; lev <= (H_HOST ? 3u : 2u); lev++) {
                subd_arena a;
                subd_mesh in, out;
                subd_alpha_opts o;
                uint32_t v, f, c, ei, vi, s, b = 0, h, l, t, plan, m0;
                subd_arena_init(&a, WORK_BUF, WORK_BYTES);
                g_state = 777u; /* the same grid for every run, host and device */
                if (fi < 2u) {
                    if (!read_obj(&a, files[fi], &in)) return;
                } else {
                    subd_face_list fl = fi == 2u ? quad_grid(3, 2) : one_face(5);
                    if (fi == 3u)
                        for (h = 0; h < 15u; h++) g_pos[h] = h_int((int32_t)((h * 7u) % 11u));
                    if (!h_build(&a, &fl, &in)) return;
                }
                v = in.num_verts;
                f = in.num_faces;
                c = in.num_corners;
                interior_counts(&in, &ei, &vi, &s);
                for (l = 0; l < lev; l++) {
                    /* S_2: V' = C, F' = F + E_i + V_i, C' = C + 4 E_i + S, E_i' = 2 E_i + S,
                     * V_i' = S, S' = 4 S, B' = C - S */
                    uint32_t nf = f + ei + vi, nc = c + 4u * ei + s;
                    b = c - s;
                    v = c;
                    f = nf;
                    c = nc;
                    ei = 2u * ei + s;
                    vi = s;
                    s = 4u * s;
                    for (t = 2; t < order; t++) {
                        /* C: V' = F + 2B, F' = V, C' = C + 3B, E_i' = E_i + B, V_i' = F,
                         * S' = C, B' = 2B */
                        uint32_t nv = f + 2u * b;
                        nf = v;
                        nc = c + 3u * b;
                        ei = ei + b;
                        vi = f;
                        s = c;
                        v = nv;
                        f = nf;
                        c = nc;
                        b = 2u * b;
                    }
                }
                sopts(&o, lev, SUBD_ALPHA_COS, 1, 5, SUBD_REAL_FRAC(3, 4));
                o.order = order;
                if (!CHECK_EQ(subd_alpha_surface_plan(&in, &o, &plan, 0), SUBD_OK)) return;
                if (!CHECK(plan <= subd_arena_free_bytes(&a))) return;
                m0 = subd_arena_mark(&a);
                if (!ds(&a, &in, &o, &out)) return;
                CHECK_EQ(a.peak - m0, plan);
                CHECK_EQ(out.num_verts, v);
                CHECK_EQ(out.num_faces, f);
                CHECK_EQ(out.num_corners, c);
                CHECK_EQ(out.num_edges - out.num_boundary_edges, ei);
                CHECK_EQ(out.num_boundary_edges, b);
                CHECK_EQ(out.num_isolated, 0);
                CHECK_EQ(subd_mesh_euler(&out), subd_mesh_euler(&in) - (int32_t)in.num_isolated);
                CHECK_EQ(out.num_boundary_loops, in.num_boundary_loops);
                if (lev == 2u) {
                    char name[] = "alpha_sk_m0_k0_l2";
                    name[10] = (char)('0' + fi);
                    name[13] = (char)('0' + order);
                    h_hash(name, h_mesh_hash(&out));
                }
            }
}

/* Every too-small arena fails cleanly for S_3 and S_4; plan = peak. */
static void alpha_sk_plan_exact(void)
{
    subd_arena a;
    subd_mesh cube, grid;
    subd_alpha_opts o;
    subd_face_list fl = quad_grid(2, 2);
    uint32_t order;
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    if (!read_obj(&a, "test/data/cube_quad.obj", &cube) || !h_build(&a, &fl, &grid)) return;
    for (order = 3; order <= 4u; order++) {
        sopts(&o, 1, SUBD_ALPHA_POLY, 1, 3, SUBD_REAL_ONE);
        o.order = order;
        check_plan_exhaustive(&cube, &o);
        check_plan_exhaustive(&grid, &o);
    }
    sopts(&o, 2, SUBD_ALPHA_COS, 1, 4, SUBD_REAL_ONE);
    o.order = 3;
    check_plan_exhaustive(&grid, &o);
}


/* ------------------------------------------------------------------------------------ */
/* Robustness (issue 13).                                                                 */

/* A mesh without adjacency (subd_loop output without SUBD_LOOP_ADJACENCY: twin and
 * vert_out are NULL) is refused with SUBD_ERR_PARAM by the plan and the call (it used to be
 * dereferenced), the arena untouched. */
static void alpha_ds_no_adjacency(void)
{
    subd_arena a;
    subd_mesh ico, tri, out;
    subd_loop_opts lo = {1, SUBD_LOOP_BOUNDARY_PAPER, 0};
    subd_alpha_opts o;
    subd_diag d;
    uint32_t plan = 7, m0;
    subd_arena_init(&a, WORK_BUF, WORK_BYTES);
    if (!read_obj(&a, "test/data/icosahedron.obj", &ico)) return;
    if (!CHECK_EQ(subd_loop(&a, &ico, &lo, &tri, &d), SUBD_OK)) return;
    CHECK(tri.twin == 0 || tri.vert_out == 0);
    m0 = subd_arena_mark(&a);
    sopts(&o, 1, SUBD_ALPHA_COS, 1, 4, SUBD_REAL_ONE);
    CHECK_EQ(subd_alpha_surface_plan(&tri, &o, &plan, 0), SUBD_ERR_PARAM);
    CHECK_EQ(plan, 7);
    CHECK_FAIL(subd_alpha_surface(&a, &tri, &o, &out, 0, &d), &d, SUBD_ERR_PARAM);
    CHECK_EQ(subd_arena_mark(&a), m0);
}

/* The cube with edge (0, 1) split at its midpoint (vertex 8): its two faces become
 * pentagons and vertex 8 is an interior vertex of valence 2, whose Doo-Sabin vertex face
 * would be a digon. Coordinates +-2, the split edge along x through x = 0. */
static subd_face_list split_cube(void)
{
    static const uint32_t idx[] = {0, 4, 6, 2, 1, 3, 7, 5, 0, 8, 1, 5, 4, 2, 6, 7, 3, 0, 2, 3, 1, 8, 4, 5, 7, 6};
    static const uint32_t size[] = {4, 4, 5, 4, 5, 4};
    subd_face_list fl = {0, 0, 0, 0, 0, 0, 0, 0};
    uint32_t i;
    for (i = 0; i < 8u; i++) {
        g_pos[3u * i] = h_int((i & 1u) ? 2 : -2);
        g_pos[3u * i + 1u] = h_int((i & 2u) ? 2 : -2);
        g_pos[3u * i + 2u] = h_int((i & 4u) ? 2 : -2);
    }
    g_pos[24] = 0;
    g_pos[25] = h_int(-2);
    g_pos[26] = h_int(-2);
    for (i = 0; i < 26u; i++) g_idx[i] = idx[i];
    for (i = 0; i < 6u; i++) g_size[i] = size[i];
    fl.num_verts = 9;
    fl.pos = g_pos;
    fl.num_faces = 6;
    fl.face_size = g_size;
    fl.index = g_idx;
    return fl;
}

/* A mesh rebuilt from its own face list by the validator (subd_mesh_build). */
static int rebuilds(const subd_mesh *m)
{
    static uint32_t sz[16384];
    static uint8_t buf[H_HOST ? (1u << 20) : 8u] __attribute__((aligned(8))); /* host only: the device skips the rebuild */
    subd_face_list fl = {0, 0, 0, 0, 0, 0, 0, 0};
    subd_arena b;
    subd_mesh r;
    subd_diag d;
    uint32_t f;
    if (!CHECK(m->num_faces <= 16384u)) return 0;
    for (f = 0; f < m->num_faces; f++) sz[f] = m->face_start[f + 1u] - m->face_start[f];
    fl.num_verts = m->num_verts;
    fl.pos = m->pos;
    fl.num_faces = m->num_faces;
    fl.face_size = sz;
    fl.index = m->corner_vert;
    subd_arena_init(&b, buf, H_HOST ? sizeof buf : 0u);
    if (!H_HOST) return 1;
    return CHECK_EQ(subd_mesh_build(&b, &fl, &r, &d), SUBD_OK) && CHECK_EQ(r.num_corners, m->num_corners);
}

/* Every output vertex has a mirror image (x -> -x) among the output vertices, within a
 * rounding tolerance (the mirrored faces are traversed in the other order). */
static int mirror_symmetric(const subd_mesh *m)
{
    uint32_t i, j, bad = 0;
    double tol = SUBD_FIXED ? 8.0 / 65536.0 : 1e-5;
    for (i = 0; i < m->num_verts; i++) {
        const subd_real *p = &m->pos[3u * i];
        int found = 0;
        for (j = 0; j < m->num_verts && !found; j++) {
            const subd_real *q = &m->pos[3u * j];
            double dx = h_dbl(p[0]) + h_dbl(q[0]), dy = h_dbl(p[1]) - h_dbl(q[1]), dz = h_dbl(p[2]) - h_dbl(q[2]);
            found = dx <= tol && dx >= -tol && dy <= tol && dy >= -tol && dz <= tol && dz >= -tol;
        }
        if (!found) bad++;
    }
    return CHECK_EQ(bad, 0);
}

/* Issue 13, item 3: a mesh with an interior vertex of valence 2 works at every order (the
 * digon collapses to an edge): success, closed-form counts, the output validates, mirror
 * symmetry kept, plan = peak (and every smaller arena fails cleanly at one level). */
static void alpha_ds_valence2(void)
{
    subd_arena a;
    subd_mesh in, out;
    subd_alpha_opts o;
    subd_diag d;
    subd_face_list fl = split_cube();
    uint32_t order, lev, plan, m0;
    subd_arena_init(&a, WORK_BUF, WORK_BYTES);
    if (!h_build(&a, &fl, &in)) return;
    m0 = subd_arena_mark(&a);
    for (order = 2; order <= 5u; order++)
        for (lev = 1; lev <= (H_HOST ? 2u : 1u); lev++) { /* the device: one level (soft double) */
            sopts(&o, lev, SUBD_ALPHA_COS, 1, 5, SUBD_REAL_ONE);
            o.order = order;
            if (!CHECK_EQ(subd_alpha_surface_plan(&in, &o, &plan, 0), SUBD_OK)) return;
            subd_diag_clear(&d);
            a.peak = a.used;
            if (!CHECK_EQ(subd_alpha_surface(&a, &in, &o, &out, 0, &d), SUBD_OK)) {
                CHECK_EQ(d.face, SUBD_NONE); /* never an element of an intermediate mesh */
                return;
            }
            CHECK_EQ(a.peak - m0, plan);
            CHECK_EQ(out.num_boundary_loops, 0);
            CHECK_EQ(subd_mesh_euler(&out), 2);
            if (order == 2u && lev == 1u) {
                /* 9 vertices, 26 corners, 13 edges (all interior); vertex 8 makes no face */
                CHECK_EQ(out.num_verts, 26);
                CHECK_EQ(out.num_faces, 6 + 13 + 8);
                CHECK_EQ(out.num_corners, 26 + 4 * 13 + 24);
            }
            rebuilds(&out);
            if (H_HOST || out.num_verts <= 400u) mirror_symmetric(&out); /* O(V^2) in double */
            subd_arena_rewind(&a, m0);
        }
    for (order = 2; order <= 5u; order++) {
        sopts(&o, 1, SUBD_ALPHA_POLY, 1, 3, SUBD_REAL_FRAC(3, 4));
        o.order = order;
        check_plan_exhaustive(&in, &o);
    }
}

static double max_edge_len(const subd_mesh *m)
{
    uint32_t h, k;
    double best = 0;
    for (h = 0; h < m->num_corners; h++) {
        const subd_real *p = &m->pos[3u * m->corner_vert[h]], *q = &m->pos[3u * subd_he_dest(m, h)];
        double s = 0;
        for (k = 0; k < 3u; k++) s += (h_dbl(p[k]) - h_dbl(q[k])) * (h_dbl(p[k]) - h_dbl(q[k]));
        if (s > best) best = s;
    }
    return best;
}

/* Issue 13, item 4 (theorem 1: convergence for s > -1/2): s = -1/2 and below are refused
 * with SUBD_ERR_DIVERGENT; s = -0.49 is accepted and contracts (the longest edge of the
 * cube shrinks from level 1 to level 5; 1 to 3 on the device). */
static void alpha_ds_divergent(void)
{
    subd_arena a;
    subd_mesh in, out;
    subd_alpha_opts o;
    subd_diag d;
    uint32_t plan, m0;
    subd_arena_init(&a, WORK_BUF, WORK_BYTES);
    if (!read_obj(&a, "test/data/cube_quad.obj", &in)) return;
    m0 = subd_arena_mark(&a);
    sopts(&o, 1, SUBD_ALPHA_BSPLINE, 0, 1, SUBD_REAL_FRAC(-1, 2));
    CHECK_FAIL(subd_alpha_surface(&a, &in, &o, &out, 0, &d), &d, SUBD_ERR_DIVERGENT);
    CHECK_EQ(subd_alpha_surface_plan(&in, &o, &plan, 0), SUBD_ERR_DIVERGENT);
    o.stiffness = SUBD_REAL_FRAC(-3, 5);
    CHECK_FAIL(subd_alpha_surface(&a, &in, &o, &out, 0, &d), &d, SUBD_ERR_DIVERGENT);
    CHECK_EQ(subd_arena_mark(&a), m0);
    o.stiffness = SUBD_REAL_FRAC(-49, 100);
    {
        double e1 = 0, en = 0;
        if (CHECK_EQ(subd_alpha_surface(&a, &in, &o, &out, 0, &d), SUBD_OK)) e1 = max_edge_len(&out);
        subd_arena_rewind(&a, m0);
        o.levels = H_HOST ? 5u : 3u;
        if (CHECK_EQ(subd_alpha_surface(&a, &in, &o, &out, 0, &d), SUBD_OK)) en = max_edge_len(&out);
        subd_arena_rewind(&a, m0);
#if H_HOST
        {
            char buf[120];
            snprintf(buf, sizeof buf, "  note: DS s = -0.49 cube: longest edge level 1 -> 5: %.4g -> %.4g\n", sqrt(e1),
                     sqrt(en));
            h_str(buf);
        }
#endif
        CHECK(en < e1);
    }
}

/* ------------------------------------------------------------------------------------ */
/* Tags (section 3): per-face alpha for even k, per-vertex alpha for odd k; the rule is    */
/* the table in subd_alpha.h.                                                             */

/* A closed n x m quad torus (topology only matters; z a bumpy integer height). */
static subd_face_list quad_torus(uint32_t n, uint32_t m)
{
    subd_face_list fl = {0, 0, 0, 0, 0, 0, 0, 0};
    uint32_t i, j, k = 0, f = 0;
    for (i = 0; i < n; i++)
        for (j = 0; j < m; j++) {
            uint32_t v = i * m + j;
            g_pos[3u * v] = h_int((int32_t)j * 4 + (int32_t)(i % 2u));
            g_pos[3u * v + 1u] = h_int((int32_t)i * 4);
            g_pos[3u * v + 2u] = h_int((int32_t)(h_rand(&g_state) % 9u) - 4);
        }
    for (i = 0; i < n; i++)
        for (j = 0; j < m; j++) {
            g_idx[k++] = i * m + j;
            g_idx[k++] = i * m + (j + 1u) % m;
            g_idx[k++] = ((i + 1u) % n) * m + (j + 1u) % m;
            g_idx[k++] = ((i + 1u) % n) * m + j;
            g_size[f++] = 4;
        }
    fl.num_verts = n * m;
    fl.pos = g_pos;
    fl.num_faces = f;
    fl.face_size = g_size;
    fl.index = g_idx;
    return fl;
}

static int tag_run(subd_arena *a, const subd_mesh *in, uint32_t order, uint32_t levels, uint32_t kernel, int32_t num,
                   int32_t den, const int32_t *tags, subd_mesh *out)
{
    subd_alpha_opts o;
    sopts(&o, levels, kernel, num, den, SUBD_REAL_ONE);
    o.order = order;
    o.tag_num = tags;
    return ds(a, in, &o, out);
}

static int same_mesh(const subd_mesh *x, const subd_mesh *y)
{
    uint32_t i;
    if (x->num_verts != y->num_verts || x->num_faces != y->num_faces || x->num_corners != y->num_corners) return 0;
    for (i = 0; i < 3u * x->num_verts; i++)
        if (!h_same(x->pos[i], y->pos[i])) return 0;
    for (i = 0; i < x->num_corners; i++)
        if (x->corner_vert[i] != y->corner_vert[i]) return 0;
    return 1;
}

/* Uniform tags (every tag = alpha_num) give the untagged result bit for bit: every order
 * 2..5, every kernel, on the cube, a torus and an open grid (boundary: C's midpoints and
 * kept boundary vertices get tags too); the device: the cube and the grid, fewer levels. */
static void alpha_tags_uniform(void)
{
    static int32_t tags[MAXV];
    uint32_t k, kern, mi, i;
    for (mi = 0; mi < 3u; mi++)
        for (k = 2; k <= 5u; k++)
            for (kern = 0; kern < 4u; kern++) {
                subd_arena a;
                subd_mesh in, x, y;
                subd_face_list fl = mi == 1u ? quad_torus(4, 5) : quad_grid(3, 2);
                uint32_t lev = H_HOST ? (k <= 3u ? 3u : 2u) : 1u, plan0, plan1;
                subd_alpha_opts o;
                if (!H_HOST && mi == 1u) continue;
                subd_arena_init(&a, WORK_BUF, WORK_BYTES);
                if (mi == 0) {
                    if (!read_obj(&a, "test/data/cube_quad.obj", &in)) return;
                } else if (!h_build(&a, &fl, &in)) {
                    return;
                }
                for (i = 0; i < MAXV; i++) tags[i] = 7;
                if (!tag_run(&a, &in, k, lev, kern, 7, 40, 0, &x)) return;
                if (!tag_run(&a, &in, k, lev, kern, 7, 40, tags, &y)) return;
                if (!CHECK(same_mesh(&x, &y))) {
                    h_str("  order ");
                    h_u32(k);
                    h_str(" kernel ");
                    h_u32(kern);
                    h_str("\n");
                    return;
                }
                /* the plan counts the tag arrays */
                sopts(&o, lev, kern, 7, 40, SUBD_REAL_ONE);
                o.order = k;
                CHECK_EQ(subd_alpha_surface_plan(&in, &o, &plan0, 0), SUBD_OK);
                o.tag_num = tags;
                CHECK_EQ(subd_alpha_surface_plan(&in, &o, &plan1, 0), SUBD_OK);
                CHECK(plan1 > plan0);
            }
}

/* Dependency flags through one step, from the topology alone (closed meshes): pd = "this
 * vertex's position can differ", td = "this tagged element's alpha can differ". */
#define TMAX (H_HOST ? 20000u : 1200u)
static uint8_t g_pd[2][TMAX], g_td[2][TMAX];

static uint32_t corner_next(const subd_mesh *m, uint32_t h)
{
    uint32_t f = m->corner_face[h];
    return h + 1u == m->face_start[f + 1u] ? m->face_start[f] : h + 1u;
}

/* S_2 on closed m (step output: corner j = vertex j; faces: face-faces, edge-faces (h <
 * twin), vertex-faces in vertex order). vt: m's tags are per vertex. */
static int deps_s2(const subd_mesh *m, int vt, const uint8_t *pd, const uint8_t *td, uint8_t *pd2, uint8_t *td2)
{
    uint32_t f, h, v, n = 0;
    if (m->num_corners > TMAX || m->num_faces + m->num_corners > TMAX) return 0;
    for (f = 0; f < m->num_faces; f++) {
        uint32_t s = m->face_start[f], e = m->face_start[f + 1u], i;
        uint8_t fa = vt ? 0 : td[f], any = 0;
        for (i = s; i < e; i++) {
            if (vt) fa |= td[m->corner_vert[i]];
            any |= pd[m->corner_vert[i]];
        }
        for (i = s; i < e; i++) pd2[i] = (uint8_t)(fa | any);
        td2[n++] = fa;
    }
    for (h = 0; h < m->num_corners; h++) {
        uint32_t t = m->twin[h];
        if (t < h) continue;
        td2[n++] = vt ? (uint8_t)(td[m->corner_vert[h]] | td[m->corner_vert[corner_next(m, h)]])
                      : (uint8_t)(td[m->corner_face[h]] | td[m->corner_face[t]]);
    }
    for (v = 0; v < m->num_verts; v++) {
        uint8_t x = 0;
        if (vt) {
            x = td[v];
        } else {
            for (h = 0; h < m->num_corners; h++)
                if (m->corner_vert[h] == v) x |= td[m->corner_face[h]];
        }
        td2[n++] = x;
    }
    return 1;
}

/* C on closed m: output vertex i is face i's centroid; vertex tags from face tags (one per
 * face) or face tags from vertex tags (one per vertex). */
static int deps_c(const subd_mesh *m, int vt, const uint8_t *pd, const uint8_t *td, uint8_t *pd2, uint8_t *td2)
{
    uint32_t f, v;
    if (m->num_faces > TMAX || m->num_verts > TMAX) return 0;
    for (f = 0; f < m->num_faces; f++) {
        uint32_t i;
        pd2[f] = 0;
        for (i = m->face_start[f]; i < m->face_start[f + 1u]; i++) pd2[f] |= pd[m->corner_vert[i]];
        if (!vt) td2[f] = td[f];
    }
    if (vt)
        for (v = 0; v < m->num_verts; v++) td2[v] = td[v];
    return 1;
}

/* Locality: one tag changed (a vertex for odd k, a face for even k) changes, after each
 * level, only the output points that the topology lets depend on it (flags pushed through
 * every S_2 and C step, using the intermediate meshes of B-spline runs: the topology does
 * not depend on alpha); every other point keeps its bits, and some inside do change.
 * Orders 2..5 on a torus, cos kernel. */
static void alpha_tags_locality(void)
{
    static int32_t ta[MAXV], tb[MAXV];
    uint32_t k, lmax = H_HOST ? 3u : 1u;
    for (k = 2; k <= (H_HOST ? 5u : 3u); k++) {
        subd_arena a;
        subd_mesh in, cur, prev, step, x, y;
        subd_face_list fl = quad_torus(6, 7);
        uint32_t l, j, i, ntag, src = 0;
        int vt = (k & 1u) != 0u;
        subd_arena_init(&a, WORK_BUF, WORK_BYTES);
        if (!h_build(&a, &fl, &in)) return;
        ntag = vt ? in.num_verts : in.num_faces;
        for (i = 0; i < ntag; i++) ta[i] = tb[i] = (int32_t)(i % 5u) * 3 - 4;
        tb[17] = 31; /* the changed element */
        for (i = 0; i < in.num_verts; i++) g_pd[0][i] = 0;
        for (i = 0; i < ntag; i++) g_td[0][i] = i == 17u;
        cur = in;
        for (l = 1; l <= lmax; l++) {
            uint32_t inside = 0, outside = 0, changed = 0, bad = 0, mark;
            int kind = vt;
            prev = cur;
            for (j = 0; j + 2u <= k; j++) {
                uint32_t dst = 1u - src;
                int ok;
                /* step j's output: C^j S_2 of cur */
                if (!tag_run(&a, &cur, j + 2u, 1, SUBD_ALPHA_BSPLINE, 0, 1, 0, &step)) return;
                if (!CHECK_EQ(step.num_boundary_edges, 0)) return;
                if (j == 0) ok = deps_s2(&prev, kind, g_pd[src], g_td[src], g_pd[dst], g_td[dst]);
                else ok = deps_c(&prev, kind, g_pd[src], g_td[src], g_pd[dst], g_td[dst]);
                if (!CHECK(ok) || !CHECK(step.num_verts <= TMAX)) return;
                kind = j == 0 ? 0 : !kind;
                src = dst;
                prev = step;
            }
            cur = prev;
            mark = subd_arena_mark(&a);
            if (!tag_run(&a, &in, k, l, SUBD_ALPHA_COS, 1, 16, ta, &x)) return;
            if (!tag_run(&a, &in, k, l, SUBD_ALPHA_COS, 1, 16, tb, &y)) return;
            if (!CHECK_EQ(x.num_verts, cur.num_verts)) return;
            for (i = 0; i < x.num_verts; i++) {
                int same = h_same(x.pos[3u * i], y.pos[3u * i]) && h_same(x.pos[3u * i + 1u], y.pos[3u * i + 1u]) &&
                           h_same(x.pos[3u * i + 2u], y.pos[3u * i + 2u]);
                if (g_pd[src][i]) {
                    inside++;
                    changed += !same;
                } else {
                    outside++;
                    bad += !same;
                }
            }
            CHECK_EQ(bad, 0);
            CHECK(changed > 0);
            CHECK(outside > 0u); /* the support is local: not every point */
            if (k == 3u && l == lmax) {
                h_str("  note: S_3 locality, last level: ");
                h_u32(inside);
                h_str(" of ");
                h_u32(inside + outside);
                h_str(" points in the support, ");
                h_u32(changed);
                h_str(" changed\n");
            }
            subd_arena_rewind(&a, mark);
        }
    }
}

/* floor(s / n), written out independently of the library. */
static int32_t floor_div(int64_t s, int64_t n)
{
    int64_t q = s / n;
    if (q * n > s) q--;
    return (int32_t)q;
}

/* The mean rule on small meshes against a brute-force computation of the next level's tags:
 * running 2 levels equals running 1 level and then 1 more from its output with the tags
 * computed here (level 1 of den is level 0 of 2 den bit for bit: the kernel sees the same
 * fraction 2^-(n+1) num / den). S_2 with face tags and S_3 with vertex tags, on the cube
 * and the torus, tags chosen so that the means are not whole (floor) and some negative. */
static void alpha_tags_mean(void)
{
    static int32_t t0[MAXV], t1[4 * MAXC];
    uint32_t k, mi;
    for (mi = 0; mi < 2u; mi++)
        for (k = 2; k <= 3u; k++) {
            subd_arena a;
            subd_mesh in, two, one, next;
            subd_face_list fl = quad_torus(3, 4);
            uint32_t i, h, v, f, n = 0;
            int vt = k == 3u;
            subd_arena_init(&a, WORK_BUF, WORK_BYTES);
            if (mi == 0) {
                if (!read_obj(&a, "test/data/cube_quad.obj", &in)) return;
            } else if (!h_build(&a, &fl, &in)) {
                return;
            }
            for (i = 0; i < (vt ? in.num_verts : in.num_faces); i++) t0[i] = (int32_t)((i * 7u) % 11u) - 6;
            if (!tag_run(&a, &in, k, 2, SUBD_ALPHA_COS, 0, 24, t0, &two)) return;
            if (!tag_run(&a, &in, k, 1, SUBD_ALPHA_COS, 0, 24, t0, &one)) return;
            /* S_2's output faces: face-faces, edge-faces (h < twin), vertex-faces */
            for (f = 0; f < in.num_faces; f++) {
                int64_t s = 0;
                uint32_t e = in.face_start[f + 1u];
                for (i = in.face_start[f]; i < e; i++) s += vt ? t0[in.corner_vert[i]] : 0;
                t1[n++] = vt ? floor_div(s, e - in.face_start[f]) : t0[f];
            }
            for (h = 0; h < in.num_corners; h++) {
                uint32_t t = in.twin[h];
                if (t < h) continue;
                t1[n++] = vt ? floor_div((int64_t)t0[in.corner_vert[h]] + t0[in.corner_vert[corner_next(&in, h)]], 2)
                             : floor_div((int64_t)t0[in.corner_face[h]] + t0[in.corner_face[t]], 2);
            }
            for (v = 0; v < in.num_verts; v++) {
                int64_t s = 0;
                uint32_t c = 0;
                for (h = 0; h < in.num_corners; h++)
                    if (in.corner_vert[h] == v) {
                        s += t0[in.corner_face[h]];
                        c++;
                    }
                t1[n++] = vt ? t0[v] : floor_div(s, c);
            }
            /* S_3: C turns these face tags into the tags of the face centroids, in face order */
            if (!CHECK_EQ(n, vt ? one.num_verts : one.num_faces)) return;
            if (!tag_run(&a, &one, k, 1, SUBD_ALPHA_COS, 0, 48, t1, &next)) return;
            CHECK(same_mesh(&two, &next));
            /* and the rule matters: the untagged and uniform second levels differ */
            for (i = 0; i < n; i++) t1[i] = 0;
            if (!tag_run(&a, &one, k, 1, SUBD_ALPHA_COS, 0, 48, t1, &next)) return;
            CHECK(!same_mesh(&two, &next));
        }
}

/* Bad tags: SUBD_ERR_PARAM naming the first bad element (a vertex for odd k, a face for even
 * k), the arena back at its mark, the output and the input untouched; every too-small arena
 * of a tagged run fails cleanly (the plan is exact with the tag arrays). */
static void alpha_tags_errors(void)
{
    static int32_t tags[MAXV];
    subd_arena a;
    subd_mesh in, out, sentinel;
    subd_alpha_opts o;
    subd_diag d;
    uint32_t m0, hin, i;
    subd_arena_init(&a, WORK_BUF, WORK_BYTES);
    if (!read_obj(&a, "test/data/cube_quad.obj", &in)) return;
    m0 = subd_arena_mark(&a);
    hin = h_mesh_hash(&in);
    for (i = 0; i < MAXV; i++) tags[i] = 0;
    memset(&out, 0x5a, sizeof out);
    sentinel = out;
    sopts(&o, 2, SUBD_ALPHA_COS, 1, 8, SUBD_REAL_ONE);
    o.tag_num = tags;
    o.order = 3;
    tags[5] = SUBD_ALPHA_MAX_NUM + 1;
    tags[6] = -SUBD_ALPHA_MAX_NUM - 1;
    CHECK_FAIL(subd_alpha_surface(&a, &in, &o, &out, 0, &d), &d, SUBD_ERR_PARAM);
    CHECK_EQ(d.vertex, 5);
    CHECK_EQ(d.face, SUBD_NONE);
    tags[5] = SUBD_ALPHA_MAX_NUM; /* the largest tag is fine */
    CHECK_FAIL(subd_alpha_surface(&a, &in, &o, &out, 0, &d), &d, SUBD_ERR_PARAM);
    CHECK_EQ(d.vertex, 6);
    CHECK_EQ(subd_arena_mark(&a), m0);
    o.order = 2; /* even k: the same array is per face (6 faces: tag 5 is the last) */
    CHECK_EQ(subd_alpha_surface(&a, &in, &o, &out, 0, &d), SUBD_OK);
    subd_arena_rewind(&a, m0);
    tags[5] = -SUBD_ALPHA_MAX_NUM - 1;
    CHECK_FAIL(subd_alpha_surface(&a, &in, &o, &out, 0, &d), &d, SUBD_ERR_PARAM);
    CHECK_EQ(d.face, 5);
    CHECK_EQ(d.vertex, SUBD_NONE);
    CHECK_EQ(subd_arena_mark(&a), m0);
    out = sentinel;
    /* a tagged face whose level has f_n <= -1 (s = 2, f_0 = 2 cos(0.45 turn)), others fine */
    tags[5] = 9;
    o.alpha_den = 10;
    o.stiffness = h_int(2);
    for (i = 0; i < 5u; i++) tags[i] = 1;
    CHECK_FAIL(subd_alpha_surface(&a, &in, &o, &out, 0, &d), &d, SUBD_ERR_PARAM);
    CHECK_EQ(subd_arena_mark(&a), m0);
    CHECK(memcmp(&out, &sentinel, sizeof out) == 0);
    CHECK_EQ(h_mesh_hash(&in), hin);
    /* exact plans with tags: every too-small arena */
    for (i = 0; i < MAXV; i++) tags[i] = (int32_t)(i % 3u);
    sopts(&o, H_HOST ? 2u : 1u, SUBD_ALPHA_COS, 1, 8, SUBD_REAL_ONE);
    o.tag_num = tags;
    for (o.order = 2; o.order <= 4u; o.order++) check_plan_exhaustive(&in, &o);
    {
        subd_face_list fl = quad_grid(3, 2); /* with a boundary */
        subd_mesh grid;
        if (!h_build(&a, &fl, &grid)) return;
        o.levels = 1; /* the sweep's buffer holds 40000 bytes */
        for (o.order = 2; o.order <= 4u; o.order++) check_plan_exhaustive(&grid, &o);
    }
}

const test_case suite_alpha_surface[] = {
    {"alpha_ds_quad_weights", alpha_ds_quad_weights},
#if H_HOST
    {"alpha_ds_tensor", alpha_ds_tensor},
    {"alpha_ds_eigen", alpha_ds_eigen},
#endif
    {"alpha_ds_centroid", alpha_ds_centroid},
    {"alpha_ds_levels", alpha_ds_levels},
    {"alpha_ds_plan_exact", alpha_ds_plan_exact},
    {"alpha_ds_errors", alpha_ds_errors},
    {"alpha_ds_hashes", alpha_ds_hashes},
    {"alpha_s3_bspline", alpha_s3_bspline},
    {"alpha_s3_boundary", alpha_s3_boundary},
    {"alpha_sk_levels", alpha_sk_levels},
    {"alpha_sk_plan_exact", alpha_sk_plan_exact},
    {"alpha_ds_no_adjacency", alpha_ds_no_adjacency},
    {"alpha_ds_valence2", alpha_ds_valence2},
    {"alpha_ds_divergent", alpha_ds_divergent},
    {"alpha_tags_uniform", alpha_tags_uniform},
    {"alpha_tags_locality", alpha_tags_locality},
    {"alpha_tags_mean", alpha_tags_mean},
    {"alpha_tags_errors", alpha_tags_errors},
    {0, 0}
};
