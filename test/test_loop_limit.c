/* SPDX-License-Identifier: MIT */
/* Loop limit positions and normals (src/loop_limit.c) and the deterministic square root
 * (src/sqrt.c).
 *
 * The main check is against an independent reference (host only, double precision, shares
 * no code with src/: test/loop_limit_ref.c, which states how it works): a plain Loop
 * subdivider with the same rules that follows one vertex through 60 levels.
 *
 * Tolerances: float32 positions within 1e-5 of the mesh size (measured: < 4e-8); normals
 * within 0.1 degree (measured: < 0.02). Q16.16 positions within the stated LSB bound
 * 0.51 + 2^-13 * sum_i max_c |p_i - v|_c (real units): 0.5 for the one final rounding,
 * 2^-29 per rounded Q28 weight times the neighbour's offset, 0.01 for the reference
 * (measured: at most 0.499 LSB, i.e. correctly rounded in every case tested); normals
 * within 0.1 degree (measured: < 0.003 except where float32 is also larger).
 * Exceptions, with the reason at the test: Loop's corner normal (no tangent plane in
 * general; only sectors of <= 2 faces are checked) and the B-spline valence-7 boundary
 * vertex (Jordan block: the reference converges like 1/L; 2 degrees).
 *
 * Everywhere (host and QEMU): subd_sqrt exact rounding checked from bit patterns, its
 * instruction path (where the target has one) equal to the software path bit for bit, chi(n),
 * constants and translations reproduced (Q16.16: exactly), planar normals exactly (0,0,1),
 * outward normals on a convex mesh, apply = limit, every too-small arena, errors, and
 * HASH lines of positions and normals compared host = QEMU.
 */
#include "harness.h"
#include "corpus.h"
#include "../src/loop_internal.h" /* subd_loop_limit_apply */
#include "../src/sqrt_internal.h" /* subd_sqrt_soft */

#if H_HOST
#include <math.h>
#endif

#include "loop_limit_ref.h"

static tmesh g_tm;


/* ------------------------------------------------------------------------------------ */
/* Properties that run everywhere (host and QEMU)                                          */

static uint32_t hash_reals(uint32_t h, const subd_real *x, uint32_t n)
{
    uint32_t i;
    for (i = 0; i < n; i++) {
        uint32_t b = subd_real_bits(x[i]);
        h = h_fnv(h, &b, 4); /* little-endian on every target we run */
    }
    return h;
}

/* Limit of a mesh built from t in h_arena_buf; returns 0 on any failure. */
static int limit_of(const tmesh *t, subd_loop_boundary rule, subd_arena *a, subd_mesh *m, subd_real **pos,
                    subd_real **nrm)
{
    subd_diag d;
    subd_arena_init(a, h_arena_buf, H_ARENA_BYTES);
    if (!tm_build(a, t, m)) return 0;
    return subd_loop_limit(a, m, &(subd_loop_limit_opts){rule, (nrm) ? SUBD_LOOP_LIMIT_NORMALS : 0u}, pos, nrm, &d) == SUBD_OK;
}

/* The interior weight chi(n) seen through a fan: centre 0, neighbour 0 at x = 1. */
static void weights_test(void)
{
    uint32_t n, i;
    for (n = 3; n <= 12; n++) {
        subd_arena a;
        subd_mesh m;
        subd_real *pos, *nrm;
        tm_bipyramid(&g_tm, n, 1u);
        for (i = 0; i < 3u * g_tm.nv; i++) g_tm.pos[i] = 0;
        g_tm.pos[3 * 2] = SUBD_REAL_ONE; /* equator vertex 2: a neighbour of apex 0 */
        if (!CHECK(limit_of(&g_tm, SUBD_LOOP_BOUNDARY_PAPER, &a, &m, &pos, &nrm))) return;
        CHECK(pos[1] == 0 && pos[2] == 0);
        if (n == 3) CHECK(pos[0] == SUBD_REAL_FRAC(1, 5));   /* chi(3) = 1/5 */
        if (n == 6) CHECK(pos[0] == SUBD_REAL_FRAC(1, 12));  /* regular: 1/12, centre 1/2 */
#if H_HOST
        {
            double x = 0.375 + 0.25 * cos(2.0 * REF_PI / n), bb = 0.625 - x * x;
            double chi = 8.0 * bb / (n * (8.0 * bb + 3.0));
#if SUBD_FIXED
            CHECK(fabs(rdbl(pos[0]) - chi) <= 0.5 / 65536.0 + 1e-12); /* rounded once */
#else
            CHECK(fabs(rdbl(pos[0]) - chi) <= 0.5 * ldexp(1.0, ilogb(chi) - 23) + 1e-15);
#endif
        }
#endif
    }
}

/* A constant mesh stays exactly where it is (weights sum to one; float: the difference
 * form), and every tangent vanishes. Both rules, every vertex class. */
static void constant_test(void)
{
    uint32_t r, i, k, bad = 0;
    for (r = 0; r < 2; r++) {
        subd_arena a;
        subd_mesh m;
        subd_real *pos, *nrm;
        tm_torus(&g_tm, 10, 8, 5u);
        for (i = 0; i < g_tm.nv; i++) {
            g_tm.pos[3 * i] = q10(-3377);
            g_tm.pos[3 * i + 1] = q10(12345);
            g_tm.pos[3 * i + 2] = q10(777);
        }
        if (!CHECK(limit_of(&g_tm, r ? SUBD_LOOP_BOUNDARY_BSPLINE : SUBD_LOOP_BOUNDARY_PAPER, &a, &m, &pos, &nrm))) return;
        for (i = 0; i < g_tm.nv; i++)
            for (k = 0; k < 3; k++) {
                if (subd_real_bits(pos[3 * i + k]) != subd_real_bits(g_tm.pos[3 * i + k])) bad++;
                if (nrm[3 * i + k] != 0) bad++;
            }
    }
    CHECK_EQ(bad, 0);
}

/* Translation: Q16.16 exact for any translation (the weights sum to exactly ONE and the sum
 * is exact in 64 bits); float32 within a few ulps of the coordinates. Normals unchanged
 * (float: up to rounding). */
static void translate_test(void)
{
    uint32_t r, i, k, bad = 0, badn = 0;
    static subd_real p0[3 * TMV], n0[3 * TMV];
    for (r = 0; r < 2; r++) {
        subd_arena a;
        subd_mesh m;
        subd_real *pos, *nrm, t[3];
        subd_loop_boundary rule = r ? SUBD_LOOP_BOUNDARY_BSPLINE : SUBD_LOOP_BOUNDARY_PAPER;
        tm_torus(&g_tm, 10, 8, 9u);
        if (!CHECK(limit_of(&g_tm, rule, &a, &m, &pos, &nrm))) return;
        for (i = 0; i < 3u * g_tm.nv; i++) { p0[i] = pos[i]; n0[i] = nrm[i]; }
        t[0] = q10(5 * 1024);
        t[1] = q10(-7 * 1024 + 3);
        t[2] = q10(123);
        for (i = 0; i < g_tm.nv; i++)
            for (k = 0; k < 3; k++) g_tm.pos[3 * i + k] += t[k];
        if (!CHECK(limit_of(&g_tm, rule, &a, &m, &pos, &nrm))) return;
        for (i = 0; i < g_tm.nv; i++)
            for (k = 0; k < 3; k++) {
                subd_real want = p0[3 * i + k] + t[k], got = pos[3 * i + k];
#if SUBD_FIXED
                if (got != want) bad++;
                if (nrm[3 * i + k] != n0[3 * i + k]) badn++;
#else
                float e = got - want, tol = 8.0f * 1.2e-7f * 16.0f;
                if (e > tol || e < -tol) bad++;
                e = nrm[3 * i + k] - n0[3 * i + k];
                if (e > 1e-3f || e < -1e-3f) badn++;
#endif
            }
    }
    CHECK_EQ(bad, 0);
    CHECK_EQ(badn, 0);
}

/* A planar mesh (z = const) with boundary, creases, darts and corners: every normal is
 * exactly (0, 0, 1) (counter-clockwise faces seen from +z). */
static void planar_test(void)
{
    uint32_t r, i, bad = 0, zero = 0;
    for (r = 0; r < 2; r++) {
        subd_arena a;
        subd_mesh m;
        subd_real *pos, *nrm;
        tm_grid(&g_tm, 6, 5, 21u, 1);
        for (i = 0; i < 6; i++) tm_sharp(&g_tm, 2 * 7 + i, 2 * 7 + i + 1); /* crease row j = 2 */
        tm_sharp(&g_tm, 3 * 7 + 3, 4 * 7 + 3);                            /* a dart line */
        g_tm.corner[g_tm.nc++] = 0;
        g_tm.corner[g_tm.nc++] = 3 * 7 + 5; /* a tagged corner inside */
        if (!CHECK(limit_of(&g_tm, r ? SUBD_LOOP_BOUNDARY_BSPLINE : SUBD_LOOP_BOUNDARY_PAPER, &a, &m, &pos, &nrm))) return;
        for (i = 0; i < g_tm.nv; i++) {
            if (nrm[3 * i] != 0 || nrm[3 * i + 1] != 0 || nrm[3 * i + 2] != SUBD_REAL_ONE) bad++;
            if (pos[3 * i + 2] != q10(77)) zero++;
        }
    }
    CHECK_EQ(bad, 0);
    CHECK_EQ(zero, 0);
}

static int read_corpus(const char *name, subd_arena *a, subd_mesh *m)
{
    const corpus_file *f = corpus_find(name);
    subd_diag d;
    if (!f) return 0;
    subd_arena_init(a, h_arena_buf, H_ARENA_BYTES);
    return subd_obj_read(a, f->data, f->len, m, &d) == SUBD_OK;
}

/* Normals of a closed convex mesh with counter-clockwise faces point outwards. */
static void convex_test(void)
{
    subd_arena a;
    subd_mesh m;
    subd_real *pos, *nrm;
    subd_diag d;
    uint32_t i, bad = 0;
    if (!CHECK(read_corpus("test/data/icosahedron.obj", &a, &m))) return;
    if (!CHECK_EQ(subd_loop_limit(&a, &m, &(subd_loop_limit_opts){SUBD_LOOP_BOUNDARY_PAPER, SUBD_LOOP_LIMIT_NORMALS}, &pos, &nrm, &d), SUBD_OK)) return;
    for (i = 0; i < m.num_verts; i++) {
        uint32_t ovf = 0;
        subd_real dot = subd_add(subd_add(subd_mul(nrm[3 * i], m.pos[3 * i], &ovf),
                                          subd_mul(nrm[3 * i + 1], m.pos[3 * i + 1], &ovf), &ovf),
                                 subd_mul(nrm[3 * i + 2], m.pos[3 * i + 2], &ovf), &ovf);
        if (!(dot > 0)) bad++;
    }
    CHECK_EQ(bad, 0);
}

/* subd_loop_limit_apply gives the positions of subd_loop_limit, bit for bit. */
static void apply_test(void)
{
    static subd_real lim[3 * TMV];
    uint32_t r, i, bad = 0, ovf = 0;
    for (r = 0; r < 2; r++) {
        subd_arena a;
        subd_mesh m;
        subd_real *pos, *nrm;
        subd_loop_boundary rule = r ? SUBD_LOOP_BOUNDARY_BSPLINE : SUBD_LOOP_BOUNDARY_PAPER;
        tm_torus(&g_tm, 10, 8, 3u);
        if (!CHECK(limit_of(&g_tm, rule, &a, &m, &pos, &nrm))) return;
        subd_loop_limit_apply(&m, rule, m.pos, lim, &ovf);
        for (i = 0; i < 3u * m.num_verts; i++) if (subd_real_bits(lim[i]) != subd_real_bits(pos[i])) bad++;
    }
    CHECK_EQ(bad, 0);
    CHECK_EQ(ovf, 0);
}

/* Consistency with the refinement (loop.c): a control vertex's limit point and normal do not
 * change when the mesh is subdivided first (vertex i stays vertex i), for every class and
 * both rule sets. Float32: within 2e-6 of the mesh size; Q16.16: within 3 LSB (each level
 * of refinement rounds once). Normals (corners excepted) within 0.36 degree (float) or 0.8
 * degree (Q16.16: the dot product test itself rounds). */
static void refine_test(void)
{
    static subd_real p0[3 * TMV], n0[3 * TMV];
    uint32_t r, f, lev, bad = 0, badn = 0, i, k;
    for (f = 0; f < 3; f++) {
        for (r = 0; r < 2; r++) {
            subd_loop_boundary rule = r ? SUBD_LOOP_BOUNDARY_BSPLINE : SUBD_LOOP_BOUNDARY_PAPER;
            subd_arena a;
            subd_mesh m, out;
            subd_real *pos, *nrm;
            subd_diag d;
            uint32_t nv;
            if (f == 0) tm_torus(&g_tm, 10, 8, 5u);
            if (f == 1) {
                tm_grid(&g_tm, 5, 4, 11u, 0);
                g_tm.corner[g_tm.nc++] = 0;
                g_tm.corner[g_tm.nc++] = 29;
            }
            if (f == 2) {
                tm_bipyramid(&g_tm, 7, 12u);
                tm_sharp(&g_tm, 0, 2);
            }
            if (!CHECK(limit_of(&g_tm, rule, &a, &m, &pos, &nrm))) return;
            nv = m.num_verts;
            for (i = 0; i < 3u * nv; i++) { p0[i] = pos[i]; n0[i] = nrm[i]; }
            for (lev = 1; lev <= 2; lev++) {
                subd_loop_opts o;
                uint32_t mark = subd_arena_mark(&a);
                o.levels = lev;
                o.boundary = rule;
                o.flags = SUBD_LOOP_ADJACENCY;
                if (!CHECK_EQ(subd_loop(&a, &m, &o, &out, &d), SUBD_OK)) return;
                if (!CHECK_EQ(subd_loop_limit(&a, &out, &(subd_loop_limit_opts){rule, SUBD_LOOP_LIMIT_NORMALS}, &pos, &nrm, &d), SUBD_OK)) return;
                for (i = 0; i < nv; i++) {
                    for (k = 0; k < 3; k++) {
                        subd_real e = pos[3 * i + k] - p0[3 * i + k];
#if SUBD_FIXED
                        if (e > 3 || e < -3) bad++;
#else
                        if (e > 2e-6f * 8.0f || e < -2e-6f * 8.0f) bad++;
#endif
                    }
                    {
                        /* normals: dot of unit vectors */
                        uint32_t ovf = 0;
                        subd_real dot = subd_add(subd_add(subd_mul(nrm[3 * i], n0[3 * i], &ovf),
                                                          subd_mul(nrm[3 * i + 1], n0[3 * i + 1], &ovf), &ovf),
                                                 subd_mul(nrm[3 * i + 2], n0[3 * i + 2], &ovf), &ovf);
                        int corner = (m.vert_tag[i] & SUBD_VTAG_CORNER) != 0;
                        /* float: 0.99998 = cos 0.36 deg; Q16.16: the dot of two rounded unit
                         * vectors, itself rounded three times, can be 2 LSB below 1 for equal
                         * directions, so 0.9999 (0.8 deg) */
                        if (!corner && dot < (SUBD_FIXED ? SUBD_REAL_FRAC(9999, 10000) : SUBD_REAL_FRAC(99998, 100000))) badn++;
                    }
                }
                subd_arena_rewind(&a, mark);
            }
        }
    }
    CHECK_EQ(bad, 0);
    CHECK_EQ(badn, 0);
}

typedef struct limit_call {
    const subd_mesh *m;
    subd_real *out[2]; /* positions, normals */
    int normals;
} limit_call;

static int limit_run(void *ctx, subd_arena *a, subd_diag *d)
{
    limit_call *c = (limit_call *)ctx;
    return subd_loop_limit(a, c->m, &(subd_loop_limit_opts){SUBD_LOOP_BOUNDARY_PAPER, c->normals ? SUBD_LOOP_LIMIT_NORMALS : 0u}, &c->out[0], c->normals ? &c->out[1] : 0, d);
}

/* only the results stay allocated: all of the plan */
static void limit_ok(void *ctx, const subd_arena *a, const subd_diag *d)
{
    (void)ctx;
    (void)d;
    CHECK_EQ(a->used, a->peak);
}

/* Every arena size below the plan fails cleanly; the plan itself is enough and is the
 * measured peak; nothing is written past the arena. */
static void arena_test(void)
{
    static uint8_t buf[8 + 4096 + 64] __attribute__((aligned(8)));
    subd_arena ma;
    subd_mesh m;
    uint32_t plan, plan_np;
    limit_call c;
    h_sweep s;
    tm_torus(&g_tm, 10, 8, 5u);
    subd_arena_init(&ma, h_arena_buf, H_ARENA_BYTES);
    if (!CHECK(tm_build(&ma, &g_tm, &m))) return;
    CHECK_EQ(subd_loop_limit_plan(&m, &(subd_loop_limit_opts){SUBD_LOOP_BOUNDARY_PAPER, SUBD_LOOP_LIMIT_NORMALS}, &plan, 0), SUBD_OK);
    CHECK_EQ(subd_loop_limit_plan(&m, &(subd_loop_limit_opts){SUBD_LOOP_BOUNDARY_BSPLINE, 0u}, &plan_np, 0), SUBD_OK);
    CHECK_EQ(plan, 2u * SUBD_ALIGN_UP(3u * 80u * (uint32_t)sizeof(subd_real)));
    CHECK_EQ(plan_np, SUBD_ALIGN_UP(3u * 80u * (uint32_t)sizeof(subd_real)));
    c.m = &m;
    for (c.normals = 0; c.normals < 2; c.normals++) {
        s = h_sweep_make(limit_run, &c, buf, sizeof buf, c.normals ? plan : plan_np);
        s.prefix = 8;
        s.out = c.out;
        s.out_bytes = sizeof c.out;
        s.in_mesh = &m;
        s.ok = limit_ok;
        if (!h_arena_sweep(&s)) return;
    }
}

static void errors_test(void)
{
    subd_arena a;
    subd_mesh m;
    subd_real *pos = 0, *nrm = 0;
    subd_diag d;
    uint32_t plan, mark;
    /* a quad mesh */
    if (!CHECK(read_corpus("test/data/cube_quad.obj", &a, &m))) return;
    mark = subd_arena_mark(&a);
    CHECK_EQ(subd_loop_limit_plan(&m, &(subd_loop_limit_opts){SUBD_LOOP_BOUNDARY_PAPER, SUBD_LOOP_LIMIT_NORMALS}, &plan, 0), SUBD_ERR_NOT_TRIANGLES);
    CHECK_FAIL(subd_loop_limit(&a, &m, &(subd_loop_limit_opts){SUBD_LOOP_BOUNDARY_PAPER, SUBD_LOOP_LIMIT_NORMALS}, &pos, &nrm, &d), &d, SUBD_ERR_NOT_TRIANGLES);
    CHECK_EQ(d.status, SUBD_ERR_NOT_TRIANGLES);
    CHECK_EQ(d.face, 0);
    CHECK_EQ(subd_arena_mark(&a), mark);
    CHECK(pos == 0 && nrm == 0);
    /* parameters */
    if (!CHECK(read_corpus("test/data/icosahedron.obj", &a, &m))) return;
    CHECK_EQ(subd_loop_limit_plan(0, &(subd_loop_limit_opts){SUBD_LOOP_BOUNDARY_PAPER, SUBD_LOOP_LIMIT_NORMALS}, &plan, 0), SUBD_ERR_PARAM);
    CHECK_EQ(subd_loop_limit_plan(&m, &(subd_loop_limit_opts){SUBD_LOOP_BOUNDARY_PAPER, SUBD_LOOP_LIMIT_NORMALS}, 0, 0), SUBD_ERR_PARAM);
    CHECK_EQ(subd_loop_limit_plan(&m, &(subd_loop_limit_opts){(subd_loop_boundary)7, SUBD_LOOP_LIMIT_NORMALS}, &plan, 0), SUBD_ERR_PARAM);
    CHECK_FAIL(subd_loop_limit(0, &m, &(subd_loop_limit_opts){SUBD_LOOP_BOUNDARY_PAPER, 0u}, &pos, 0, &d), &d, SUBD_ERR_PARAM);
    CHECK_FAIL(subd_loop_limit(&a, 0, &(subd_loop_limit_opts){SUBD_LOOP_BOUNDARY_PAPER, 0u}, &pos, 0, &d), &d, SUBD_ERR_PARAM);
    CHECK_FAIL(subd_loop_limit(&a, &m, &(subd_loop_limit_opts){SUBD_LOOP_BOUNDARY_PAPER, 0u}, 0, 0, &d), &d, SUBD_ERR_PARAM);
    CHECK_EQ(subd_loop_limit(&a, &m, &(subd_loop_limit_opts){(subd_loop_boundary)7, 0u}, &pos, 0, 0), SUBD_ERR_PARAM);
    CHECK(pos == 0);
#if !SUBD_FIXED
    {
        /* float: coordinates near FLT_MAX make a difference overflow: SUBD_ERR_RANGE */
        uint32_t i;
        mark = subd_arena_mark(&a);
        for (i = 0; i < m.num_verts; i++) m.pos[3 * i] = (i & 1u) ? 3.0e38f : -3.0e38f;
        CHECK_FAIL(subd_loop_limit(&a, &m, &(subd_loop_limit_opts){SUBD_LOOP_BOUNDARY_PAPER, SUBD_LOOP_LIMIT_NORMALS}, &pos, &nrm, &d), &d, SUBD_ERR_RANGE);
        CHECK_EQ(subd_arena_mark(&a), mark);
        CHECK(pos == 0 && nrm == 0);
    }
#endif
}

/* Output hashes (compared between host and QEMU) of limit positions and normals. */
static void hashes_test(void)
{
    static const char *const files[] = {"test/data/icosahedron.obj", "test/data/torus_tri.obj",
                                        "test/data/grid_tri_8x8.obj", "test/data/hexfan.obj"};
    static const char *const names[2][4] = {
        {"limit_paper_icosahedron", "limit_paper_torus_tri", "limit_paper_grid_8x8", "limit_paper_hexfan"},
        {"limit_bspline_icosahedron", "limit_bspline_torus_tri", "limit_bspline_grid_8x8", "limit_bspline_hexfan"}};
    uint32_t f, r;
    for (f = 0; f < 4; f++) {
        for (r = 0; r < 2; r++) {
            subd_arena a;
            subd_mesh m;
            subd_real *pos, *nrm;
            subd_diag d;
            uint32_t h = 2166136261u;
            if (!CHECK(read_corpus(files[f], &a, &m))) return;
            if (!CHECK_EQ(subd_loop_limit(&a, &m, &(subd_loop_limit_opts){r ? SUBD_LOOP_BOUNDARY_BSPLINE : SUBD_LOOP_BOUNDARY_PAPER, SUBD_LOOP_LIMIT_NORMALS}, &pos,
                                          &nrm, &d),
                          SUBD_OK))
                return;
            h = hash_reals(h, pos, 3u * m.num_verts);
            h = hash_reals(h, nrm, 3u * m.num_verts);
            h_hash(names[r][f], h);
        }
    }
    for (r = 0; r < 2; r++) {
        subd_arena a;
        subd_mesh m;
        subd_real *pos, *nrm;
        uint32_t h = 2166136261u, k;
        subd_loop_boundary rule = r ? SUBD_LOOP_BOUNDARY_BSPLINE : SUBD_LOOP_BOUNDARY_PAPER;
        tm_torus(&g_tm, 10, 8, 5u);
        if (!CHECK(limit_of(&g_tm, rule, &a, &m, &pos, &nrm))) return;
        h = hash_reals(hash_reals(h, pos, 3u * m.num_verts), nrm, 3u * m.num_verts);
        for (k = 2; k <= 12; k++) {
            tm_fan(&g_tm, k, 300u + k);
            if (!CHECK(limit_of(&g_tm, rule, &a, &m, &pos, &nrm))) return;
            h = hash_reals(hash_reals(h, pos, 3u * m.num_verts), nrm, 3u * m.num_verts);
        }
        for (k = 3; k <= 16; k++) {
            tm_bipyramid(&g_tm, k, 500u + k);
            tm_sharp(&g_tm, 0, 2);
            if (!CHECK(limit_of(&g_tm, rule, &a, &m, &pos, &nrm))) return;
            h = hash_reals(hash_reals(h, pos, 3u * m.num_verts), nrm, 3u * m.num_verts);
        }
        h_hash(r ? "limit_bspline_features" : "limit_paper_features", h);
    }
}

/* ------------------------------------------------------------------------------------ */
/* Library against the reference (host)                                                   */

#if H_HOST
typedef struct lim_stats {
    double pos_rel;      /* max |lib - ref| / mesh size (float) */
    double lsb_excess;   /* max (|lib - ref| in LSB - allowed) (fixed) */
    double lsb_max;      /* max |lib - ref| in LSB (fixed) */
    double ang[4];       /* max normal angle (degrees) per class */
    uint32_t n[4], bad_pos, bad_nrm;
    uint32_t configs[6];
} lim_stats;

static const char *const g_cls_name[4] = {"smooth", "dart", "crease", "corner"};
static int g_verbose = 0;

static void print_dbl(double x, int decimals)
{
    /* host only: enough for the report lines */
    int32_t ip;
    uint32_t frac, sc = 1, i;
    if (x < 0) { h_str("-"); x = -x; }
    for (i = 0; i < (uint32_t)decimals; i++) sc *= 10u;
    ip = (int32_t)x;
    frac = (uint32_t)((x - ip) * sc + 0.5);
    if (frac >= sc) { ip++; frac -= sc; }
    h_i32(ip);
    h_str(".");
    for (i = sc / 10u; i > 1u && frac < i; i /= 10u) h_str("0");
    h_u32(frac);
}

static double mesh_size(const tmesh *t)
{
    double lo[3] = {1e30, 1e30, 1e30}, hi[3] = {-1e30, -1e30, -1e30}, d[3];
    uint32_t i, k;
    for (i = 0; i < t->nv; i++)
        for (k = 0; k < 3; k++) {
            double x = rdbl(t->pos[3 * i + k]);
            if (x < lo[k]) lo[k] = x;
            if (x > hi[k]) hi[k] = x;
        }
    for (k = 0; k < 3; k++) d[k] = hi[k] - lo[k];
    return v3_len(d);
}

/* Compares every vertex of t (build + subd_loop_limit) with the reference. */
static void compare_mesh(const tmesh *t, subd_loop_boundary rule, lim_stats *st)
{
    subd_arena a;
    subd_mesh m;
    subd_real *pos = 0, *nrm = 0;
    subd_diag d;
    double size = mesh_size(t);
    uint32_t v, k;
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    if (!CHECK(tm_build(&a, t, &m))) return;
    if (!CHECK_EQ(subd_loop_limit(&a, &m, &(subd_loop_limit_opts){rule, SUBD_LOOP_LIMIT_NORMALS}, &pos, &nrm, &d), SUBD_OK)) return;
    for (v = 0; v < t->nv; v++) {
        double rp[3], rn[3], ln[3], err = 0, dot = 0, ang, l;
        int cls = ref_limit(t, v, rule, rp, rn), cfg;
        for (k = 0; k < 3; k++) {
            double e = fabs(rdbl(pos[3 * v + k]) - rp[k]);
            if (e > err) err = e;
        }
#if SUBD_FIXED
        {
            /* allowed: 0.5 LSB + 2^-13 LSB per unit of sum |p_i - v| + 0.01 LSB */
            uint32_t ring[64], n = subd_vertex_ring(&m, v, ring, 64), i;
            double sum = 0, allowed, got = err * 65536.0;
            for (i = 0; i < n && i < 64; i++) {
                double mx = 0;
                for (k = 0; k < 3; k++) {
                    double dd = fabs(rdbl(t->pos[3 * ring[i] + k]) - rdbl(t->pos[3 * v + k]));
                    if (dd > mx) mx = dd;
                }
                sum += mx;
            }
            allowed = 0.51 + sum / 8192.0;
            if (got - allowed > st->lsb_excess) st->lsb_excess = got - allowed;
            if (got > st->lsb_max) st->lsb_max = got;
            if (got > allowed) st->bad_pos++;
        }
#else
        if (err / size > st->pos_rel) st->pos_rel = err / size;
        if (err > 1e-5 * size) st->bad_pos++;
#endif
        for (k = 0; k < 3; k++) ln[k] = rdbl(nrm[3 * v + k]);
        l = v3_len(ln);
        for (k = 0; k < 3; k++) dot += ln[k] * rn[k];
        ang = l > 0 ? acos(dot / l > 1.0 ? 1.0 : dot / l) * 180.0 / REF_PI : 180.0;
        if (ang > st->ang[cls]) st->ang[cls] = ang;
        st->n[cls]++;
        if ((cls == R_SMOOTH || cls == R_CREASE) && ang > 0.1) st->bad_nrm++;
        if (g_verbose && (ang > 0.1 || err > 1e-5 * size)) {
            h_str(rule == SUBD_LOOP_BOUNDARY_PAPER ? "    P v " : "    B v ");
            h_u32(v);
            h_str(" ");
            h_str(g_cls_name[cls]);
            h_str(" val ");
            h_u32(subd_vertex_valence(&m, v));
            h_str(" cfg ");
            h_i32(ref_config(t, v));
            h_str(" err ");
            print_dbl(err / size * 1e6, 3);
            h_str("e-6 angle ");
            print_dbl(ang, 4);
            h_nl();
        }
        if (rule == SUBD_LOOP_BOUNDARY_PAPER && cls == R_CREASE && (cfg = ref_config(t, v)) >= 0) st->configs[cfg]++;
    }
}

static void report(const char *what, const lim_stats *st)
{
    uint32_t c;
    h_str("  ");
    h_str(what);
#if SUBD_FIXED
    h_str(": position error max ");
    print_dbl(st->lsb_max, 3);
    h_str(" LSB, over bound ");
    print_dbl(st->lsb_excess, 3);
#else
    h_str(": position error/size ");
    print_dbl(st->pos_rel * 1e9, 2);
    h_str("e-9");
#endif
    for (c = 0; c < 4; c++) {
        if (!st->n[c]) continue;
        h_str(", ");
        h_str(g_cls_name[c]);
        h_str(" ");
        h_u32(st->n[c]);
        h_str(" max ");
        print_dbl(st->ang[c], 4);
        h_str(" deg");
    }
    h_nl();
}

static void stats_clear(lim_stats *st)
{
    uint32_t i;
    st->pos_rel = 0;
    st->lsb_excess = -1e9;
    st->lsb_max = 0;
    for (i = 0; i < 4; i++) { st->ang[i] = 0; st->n[i] = 0; }
    for (i = 0; i < 6; i++) st->configs[i] = 0;
    st->bad_pos = st->bad_nrm = 0;
}

static void ref_interior(void)
{
    lim_stats st;
    uint32_t n;
    stats_clear(&st);
    for (n = 3; n <= 12; n++) {
        tm_bipyramid(&g_tm, n, 100u + n);
        compare_mesh(&g_tm, SUBD_LOOP_BOUNDARY_PAPER, &st);
    }
    report("interior valence 3..12", &st);
    CHECK_EQ(st.bad_pos, 0);
    CHECK_EQ(st.bad_nrm, 0);
}

static void ref_boundary(void)
{
    lim_stats st;
    uint32_t seed, c, r;
    for (r = 0; r < 2; r++) {
        stats_clear(&st);
        for (seed = 1; seed <= 3; seed++) {
            tm_grid(&g_tm, 6, 5, 7u * seed, 0);
            compare_mesh(&g_tm, r ? SUBD_LOOP_BOUNDARY_BSPLINE : SUBD_LOOP_BOUNDARY_PAPER, &st);
        }
        report(r ? "boundary BSPLINE" : "boundary PAPER", &st);
        CHECK_EQ(st.bad_pos, 0);
        CHECK_EQ(st.bad_nrm, 0);
        if (!r) {
            h_str("  PAPER configurations (R;RR) (R;RE) (R;EE) (E;RR) (E;RE) (E;EE):");
            for (c = 0; c < 6; c++) { h_str(" "); h_u32(st.configs[c]); CHECK(st.configs[c] > 0); }
            h_nl();
        }
    }
}

/* Boundary fans of valence 2..12. With midpoints, valence 7 is the one case where the
 * boundary direction and the second interior mode share the eigenvalue 1/2 in a Jordan
 * block: the fan turns towards the library's plane only like 1/L, so after 60 levels the
 * reference is still about 1 degree away; it is checked with 2 degrees. */
static void ref_fans(void)
{
    lim_stats st, st7;
    uint32_t k, r;
    for (r = 0; r < 2; r++) {
        subd_loop_boundary rule = r ? SUBD_LOOP_BOUNDARY_BSPLINE : SUBD_LOOP_BOUNDARY_PAPER;
        stats_clear(&st);
        stats_clear(&st7);
        for (k = 2; k <= 12; k++) {
            /* the across mode and the next one are close for large k: 0.951 per level at 12 */
            g_ref_levels = k >= 8u ? 200 : REF_LEVELS;
            tm_fan(&g_tm, k, 300u + k);
            compare_mesh(&g_tm, rule, (r && k == 7u) ? &st7 : &st);
        }
        g_ref_levels = REF_LEVELS;
        report(r ? "boundary fans k = 2..12 BSPLINE" : "boundary fans k = 2..12 PAPER", &st);
        /* Hoppe et al.'s boundary tangent masks (as in pbrt) for comparison: they are the
         * eigenvectors of Hoppe's own (the paper's) rule, and wrong at k >= 5 for the
         * B-spline boundary, which is what pbrt combines them with */
        {
            double worst = 0, worst4 = 0;
            for (k = 2; k <= 12; k++) {
                double p[13][3], v0[3], along[3], across[3], hn[3], rp[3], rn[3], l;
                uint32_t i, c;
                tm_fan(&g_tm, k, 300u + k);
                for (c = 0; c < 3; c++) v0[c] = rdbl(g_tm.pos[c]);
                for (i = 0; i < k; i++)
                    for (c = 0; c < 3; c++) p[i][c] = rdbl(g_tm.pos[3 * (1 + i) + c]) - v0[c];
                for (c = 0; c < 3; c++) {
                    along[c] = p[k - 1][c] - p[0][c];
                    if (k == 2) across[c] = p[0][c] + p[1][c];
                    else if (k == 3) across[c] = p[1][c];
                    else if (k == 4) across[c] = -p[0][c] + 2 * p[1][c] + 2 * p[2][c] - p[3][c];
                    else {
                        double th = REF_PI / (k - 1), t = sin(th) * (p[0][c] + p[k - 1][c]);
                        for (i = 1; i + 1 < k; i++) t += (2 * cos(th) - 2) * sin(i * th) * p[i][c];
                        across[c] = -t;
                    }
                }
                v3_cross(across, along, hn);
                l = v3_len(hn);
                for (c = 0; c < 3; c++) hn[c] /= l;
                g_ref_levels = k >= 8u ? 200 : REF_LEVELS;
                ref_limit(&g_tm, 0, rule, rp, rn);
                g_ref_levels = REF_LEVELS;
                if (k >= 5u && ref_angle(hn, rn) > worst) worst = ref_angle(hn, rn);
                if (k <= 4u && ref_angle(hn, rn) > worst4 && (r || k == 4u)) worst4 = ref_angle(hn, rn);
            }
            h_str("    Hoppe/pbrt boundary masks: max error k >= 5 ");
            print_dbl(worst, 3);
            h_str(" deg (this library: see above)");
            h_nl();
            if (r) CHECK(worst > 0.5);   /* B-spline: the reason they are not used */
            else CHECK(worst < 0.01);    /* paper's rule: identical to ours */
            if (r) CHECK(worst4 < 0.01); /* B-spline rule, k <= 4: they agree */
        }
        CHECK_EQ(st.bad_pos, 0);
        CHECK_EQ(st.bad_nrm, 0);
        if (r) {
            report("boundary fan k = 7 BSPLINE (Jordan block)", &st7);
            CHECK_EQ(st7.bad_pos, 0);
            CHECK(st7.ang[R_CREASE] < 2.0);
        }
    }
}

/* Corners: grid corners (one or two faces) and a boundary vertex tagged CORNER (the library's
 * corner normal is exact for sectors of at most two faces; others are reported only). */
static void ref_corners(void)
{
    lim_stats st;
    uint32_t r, seed;
    for (r = 0; r < 2; r++) {
        subd_loop_boundary rule = r ? SUBD_LOOP_BOUNDARY_BSPLINE : SUBD_LOOP_BOUNDARY_PAPER;
        stats_clear(&st);
        for (seed = 1; seed <= 2; seed++) {
            tm_grid(&g_tm, 5, 4, 11u * seed, 0);
            g_tm.corner[g_tm.nc++] = 0;
            g_tm.corner[g_tm.nc++] = 5;
            g_tm.corner[g_tm.nc++] = 24;
            g_tm.corner[g_tm.nc++] = 29;
            compare_mesh(&g_tm, rule, &st);
        }
        report(r ? "grid corners BSPLINE" : "grid corners PAPER", &st);
        CHECK_EQ(st.bad_pos, 0);
        CHECK_EQ(st.bad_nrm, 0);
        CHECK_EQ(st.n[R_CORNER], 8);
        CHECK(st.ang[R_CORNER] <= 0.1);
        stats_clear(&st);
        tm_grid(&g_tm, 5, 4, 13u, 0);
        g_tm.corner[g_tm.nc++] = 2; /* middle of the bottom side */
        compare_mesh(&g_tm, rule, &st);
        report(r ? "side corner BSPLINE (approximate normal)" : "side corner PAPER (approximate normal)", &st);
        CHECK_EQ(st.bad_pos, 0);
        CHECK_EQ(st.bad_nrm, 0);
        /* a tagged corner with no sharp edge: fixed centre, interior tangents (exact) */
        stats_clear(&st);
        tm_bipyramid(&g_tm, 5, 77u);
        g_tm.corner[g_tm.nc++] = 0;
        compare_mesh(&g_tm, rule, &st);
        CHECK_EQ(st.bad_pos, 0);
        CHECK_EQ(st.n[R_CORNER], 1);
        CHECK(st.ang[R_CORNER] <= 0.1);
        /* ... and with one sharp edge: the fixed centre with a crease leaving it has no
         * tangent plane (the crease direction outgrows the ring); reported only */
        stats_clear(&st);
        tm_sharp(&g_tm, 0, 2);
        compare_mesh(&g_tm, rule, &st);
        report(r ? "corner with one crease BSPLINE (no tangent plane)" : "corner with one crease PAPER (no tangent plane)", &st);
        CHECK_EQ(st.bad_pos, 0);
        CHECK(st.ang[R_CORNER] < 180.0); /* a unit normal, not (0, 0, 0) */
    }
}

/* Darts: a bipyramid with one crease edge from apex 0 to the equator (both ends darts). */
static void ref_darts(void)
{
    static const uint32_t ns[] = {3, 4, 5, 6, 7, 8, 9, 10, 12, 16};
    lim_stats st;
    uint32_t i, r;
    for (r = 0; r < 2; r++) {
        stats_clear(&st);
        for (i = 0; i < sizeof ns / sizeof ns[0]; i++) {
            /* the second tangent mode of a high-valence dart is close to the next one */
            g_ref_levels = ns[i] >= 12u ? 240 : 100;
            tm_bipyramid(&g_tm, ns[i], 500u + ns[i]);
            tm_sharp(&g_tm, 0, 2);
            compare_mesh(&g_tm, r ? SUBD_LOOP_BOUNDARY_BSPLINE : SUBD_LOOP_BOUNDARY_PAPER, &st);
        }
        g_ref_levels = REF_LEVELS;
        report(r ? "darts valence 3..16 BSPLINE" : "darts valence 3..16 PAPER", &st);
        CHECK_EQ(st.bad_pos, 0);
        CHECK_EQ(st.bad_nrm, 0);
        CHECK(st.ang[R_DART] <= 0.1);
    }
}

static void ref_crease(void)
{
    lim_stats st;
    uint32_t r;
    for (r = 0; r < 2; r++) {
        stats_clear(&st);
        tm_torus(&g_tm, 10, 8, 5u);
        compare_mesh(&g_tm, r ? SUBD_LOOP_BOUNDARY_BSPLINE : SUBD_LOOP_BOUNDARY_PAPER, &st);
        report(r ? "creases BSPLINE" : "creases PAPER", &st);
        CHECK_EQ(st.bad_pos, 0);
        CHECK_EQ(st.bad_nrm, 0);
    }
}
#endif

/* ------------------------------------------------------------------------------------ */
/* Square root                                                                            */

#if SUBD_FIXED
/* r is the rounded square root of x * 2^16 when (2r - 1)^2 <= 4X < (2r + 1)^2. */
static int sqrt_ok_fixed(subd_real x, subd_real r)
{
    uint64_t X4 = ((uint64_t)x << 16) * 4u, lo, hi;
    if (r < 0) return 0;
    lo = r > 0 ? (2u * (uint64_t)r - 1u) * (2u * (uint64_t)r - 1u) : 0u;
    hi = (2u * (uint64_t)r + 1u) * (2u * (uint64_t)r + 1u);
    return lo <= X4 && X4 < hi;
}
#else
/* Exact check of correct rounding from bit patterns, no float arithmetic: r = R 2^q with a
 * 24-bit R is the nearest float to sqrt(x), x = M 2^e, when
 * (2R - 1)^2 2^(2q-2) < M 2^e < (2R + 1)^2 2^(2q-2) (no ties are possible). */
static int sqrt_ok_float(uint32_t xb, uint32_t rb)
{
    uint64_t M, R, lo, hi;
    int32_t e, q, sh;
    if (xb >> 31) return 0;
    if ((xb & 0x7f800000u) == 0) { M = xb & 0x7fffffu; e = -149; }
    else { M = (xb & 0x7fffffu) | 0x800000u; e = (int32_t)(xb >> 23) - 150; }
    if (rb >> 31 || (rb & 0x7f800000u) == 0) return 0; /* results are positive normals */
    R = (rb & 0x7fffffu) | 0x800000u;
    q = (int32_t)(rb >> 23) - 150;
    lo = (2u * R - 1u) * (2u * R - 1u);
    hi = (2u * R + 1u) * (2u * R + 1u); /* < 2^50 */
    /* compare X = M 2^(e - 2q + 2) (about 4 R^2 < 2^50 when r is right) with lo, hi */
    sh = e - 2 * q + 2;
    if (sh < 0 || sh > 52 || M > (((uint64_t)1 << 52) >> sh)) return 0;
    M <<= sh;
    return lo < M && M < hi;
}
#endif

#if !SUBD_FIXED
/* subd_sqrt (the square root instruction where the target has one: src/sqrt.c) against the
 * software path subd_sqrt_soft, bit for bit, on a sweep over both signs and every exponent
 * field (0: +-0 and subnormals; 255: +-inf and NaNs) with the mantissa's edges, its single
 * bits and pseudo-random ones (host 4 096 per exponent, device 48); the software path's
 * results are also checked for correct rounding (non-negative finite inputs), so the two
 * cannot agree on a wrong value. */
static void sqrt_paths_test(void)
{
    static const uint32_t edge[] = {0x000000u, 0x000001u, 0x000002u, 0x000003u, 0x400000u, 0x400001u,
                                    0x3fffffu, 0x7ffffeu, 0x7fffffu, 0x555555u, 0x2aaaaau, 0x100000u};
    uint32_t sg, e, k, s = 777u, bad = 0, badr = 0, n = 0, nm = H_HOST ? 4096u : 48u;
    union { float f; uint32_t u; } x, a, b;
    for (sg = 0; sg < 2u; sg++)
        for (e = 0; e < 256u; e++)
            for (k = 0; k < 12u + 23u + nm; k++) {
                uint32_t m = k < 12u ? edge[k] : k < 35u ? (uint32_t)1 << (k - 12u) : h_rand(&s) & 0x7fffffu;
                x.u = (sg << 31) | (e << 23) | m;
                a.f = subd_sqrt(x.f);
                b.f = subd_sqrt_soft(x.f);
                if (a.u != b.u) bad++;
                if (!sg && e < 255u && x.u != 0u && !sqrt_ok_float(x.u, b.u)) badr++;
                n++;
            }
    CHECK_EQ(n, 2u * 256u * (35u + nm));
    CHECK_EQ(bad, 0);
    CHECK_EQ(badr, 0);
    /* the special values through both paths */
    x.u = 0xffc00001u; a.f = subd_sqrt(x.f); CHECK_EQ(a.u, 0xffc00001u); /* negative NaN: kept, quiet */
    x.u = 0xff800001u; a.f = subd_sqrt(x.f); CHECK_EQ(a.u, 0xffc00001u); /* negative sNaN: quieted */
    x.u = 0x80000001u; a.f = subd_sqrt(x.f); CHECK_EQ(a.u, 0x7fc00000u); /* negative subnormal */
    x.u = 0x80800000u; a.f = subd_sqrt(x.f); CHECK_EQ(a.u, 0x7fc00000u); /* negative normal */
    x.u = 0x00000001u; a.f = subd_sqrt(x.f); CHECK_EQ(a.u, 0x1a3504f3u); /* sqrt(2^-149) = 2^-74.5 */
    x.u = 0x7f7fffffu; a.f = subd_sqrt(x.f); CHECK_EQ(a.u, 0x5f7fffffu); /* sqrt(FLT_MAX) */
}
#endif

static void sqrt_test(void)
{
    uint32_t s = 12345u, i, bad = 0;
#if SUBD_FIXED
    static const subd_real fixed_cases[] = {0, 1, 2, 3, 4, 65535, 65536, 65537, 131072, 262144,
                                            0x7fffffff, 0x7ffffffe, 0x40000000, 12345678};
    CHECK_EQ(subd_sqrt(0), 0);
    CHECK_EQ(subd_sqrt(-5), 0);
    CHECK_EQ(subd_sqrt(SUBD_REAL_MIN), 0);
    CHECK_EQ(subd_sqrt(65536), 65536);
    CHECK_EQ(subd_sqrt(4 * 65536), 2 * 65536);
    CHECK_EQ(subd_sqrt(16384), 32768); /* sqrt(1/4) = 1/2 */
    for (i = 0; i < sizeof fixed_cases / sizeof fixed_cases[0]; i++)
        if (!sqrt_ok_fixed(fixed_cases[i], subd_sqrt(fixed_cases[i]))) bad++;
    for (i = 0; i < 200000u; i++) {
        uint32_t u = h_rand(&s);
        subd_real x = (subd_real)(u >> (u & 31u)) & 0x7fffffff;
        if (!sqrt_ok_fixed(x, subd_sqrt(x))) bad++;
    }
    CHECK_EQ(bad, 0);
#else
    union { float f; uint32_t u; } x, r;
    static const uint32_t specials[] = {0x00000001u, 0x00000002u, 0x00000003u, 0x007fffffu, 0x00800000u,
                                        0x3f800000u, 0x40000000u, 0x40800000u, 0x7f7fffffu, 0x3f7fffffu,
                                        0x3f800001u, 0x00400000u, 0x4b7fffffu, 0x1f800000u};
    x.f = 0.0f; r.f = subd_sqrt(x.f); CHECK_EQ(r.u, 0x00000000u);
    x.u = 0x80000000u; r.f = subd_sqrt(x.f); CHECK_EQ(r.u, 0x80000000u); /* -0 -> -0 */
    x.u = 0x7f800000u; r.f = subd_sqrt(x.f); CHECK_EQ(r.u, 0x7f800000u);
    x.f = -1.0f; r.f = subd_sqrt(x.f); CHECK_EQ(r.u, 0x7fc00000u);
    x.u = 0xff800000u; r.f = subd_sqrt(x.f); CHECK_EQ(r.u, 0x7fc00000u);
    x.u = 0x7f800001u; r.f = subd_sqrt(x.f); CHECK_EQ(r.u, 0x7fc00001u);  /* NaN quieted */
    x.f = 4.0f; CHECK(subd_sqrt(x.f) == 2.0f);
    x.f = 0.25f; CHECK(subd_sqrt(x.f) == 0.5f);
    for (i = 0; i < sizeof specials / sizeof specials[0]; i++) {
        x.u = specials[i];
        r.f = subd_sqrt(x.f);
        if (!sqrt_ok_float(x.u, r.u)) bad++;
#if H_HOST
        { union { float f; uint32_t u; } w; w.f = sqrtf(x.f); if (w.u != r.u) bad++; }
#endif
    }
    for (i = 0; i < (H_HOST ? 2000000u : 100000u); i++) {
        x.u = h_rand(&s) & 0x7fffffffu;
        if (x.u >= 0x7f800000u) continue;
        r.f = subd_sqrt(x.f);
        if (!sqrt_ok_float(x.u, r.u)) bad++;
#if H_HOST
        { union { float f; uint32_t u; } w; w.f = sqrtf(x.f); if (w.u != r.u) bad++; }
#endif
    }
    /* every subnormal pattern with few bits, and the edges of the binades */
    for (i = 1; i < 0x800000u; i = i * 3u + 1u) {
        x.u = i;
        r.f = subd_sqrt(x.f);
        if (!sqrt_ok_float(x.u, r.u)) bad++;
#if H_HOST
        { union { float f; uint32_t u; } w; w.f = sqrtf(x.f); if (w.u != r.u) bad++; }
#endif
    }
    CHECK_EQ(bad, 0);
    sqrt_paths_test();
#endif
    CHECK_EQ(subd_isqrt64(0), 0);
    CHECK_EQ(subd_isqrt64(2), 1);
    CHECK_EQ(subd_isqrt64(3), 2);     /* 1.73 -> 2 */
    CHECK_EQ(subd_isqrt64(6), 2);     /* 2.449 -> 2 */
    CHECK_EQ(subd_isqrt64(7), 3);     /* 2.645 -> 3 */
    CHECK_EQ(subd_isqrt64(UINT64_MAX), 0xffffffffu);
    CHECK_EQ(subd_isqrt64((uint64_t)0xfffffffeu * 0xfffffffeu), 0xfffffffeu);
}

const test_case suite_loop_limit[] = {
    {"limit_sqrt", sqrt_test},
    {"limit_weights", weights_test},
    {"limit_constant", constant_test},
    {"limit_translate", translate_test},
    {"limit_planar_normals", planar_test},
    {"limit_convex_outward", convex_test},
    {"limit_apply", apply_test},
    {"limit_refine_invariant", refine_test},
    {"limit_arena", arena_test},
    {"limit_errors", errors_test},
    {"limit_hashes", hashes_test},
#if H_HOST
    {"limit_ref_interior", ref_interior},
    {"limit_ref_boundary", ref_boundary},
    {"limit_ref_crease", ref_crease},
    {"limit_ref_fans", ref_fans},
    {"limit_ref_darts", ref_darts},
    {"limit_ref_corners", ref_corners},
#endif
    {0, 0}
};
