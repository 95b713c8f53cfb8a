/* SPDX-License-Identifier: MIT */
/* Benchmark sections: alpha-subdivision curves and surfaces (alpha), quasi 4-8 vs Loop quality
 *  (quality), progressive interpolation (pia) and number formatting (format). Part of bench
 *  (bench/bench.h).
 */
#include "bench.h"

/* ==================================================================================== */
/* Section 4: alpha-subdivision curves and Doo-Sabin type surfaces                      */

#define CURVE_POINTS 4000u
#define CURVE_LEVELS 8u

void section_alpha(void)
{
    static const uint32_t orders[] = {2u, 3u, 4u};
    subd_real *poly;
    uint32_t j;
    size_t s;
    int i;
    double headline = -1.0;

    printf("\n== Alpha-subdivision curves (subd_alpha_curve, cos kernel, alpha = 1/%u turn, s = 1), closed "
           "regular %u-gon, %u levels; reproduce: " REPRO "\n",
           CURVE_POINTS, CURVE_POINTS, CURVE_LEVELS);
    printf("   (%u points x 2^%u: SUBD_MAX_LEVELS = %u caps the levels, so the polygon has %u points, not 1000)\n",
           CURVE_POINTS, CURVE_LEVELS, (unsigned)SUBD_MAX_LEVELS, CURVE_POINTS);
    printf("%-24s %10s %10s %10s %13s %7s %5s\n", "operator", "out points", "ms/call", "Mpoints/s", "arena bytes",
           "peak", "runs");
    poly = (subd_real *)malloc(3u * CURVE_POINTS * sizeof *poly);
    if (!poly) {
        printf("out of memory\n");
        return;
    }
    for (j = 0; j < CURVE_POINTS; j++) {
        double a = 2.0 * 3.14159265358979323846 * (double)j / (double)CURVE_POINTS;
        poly[3u * j] = D2R(cos(a));
        poly[3u * j + 1u] = D2R(sin(a));
        poly[3u * j + 2u] = D2R(0.0);
    }
    for (s = 0; s < sizeof orders / sizeof orders[0]; s++) {
        run_ctx c;
        double ns, first;
        int runs, st;
        char pk[16], label[32];
        memset(&c, 0, sizeof c);
        c.kind = RUN_CURVE;
        c.cpos = poly;
        c.cm = CURVE_POINTS;
        subd_alpha_opts_default(&c.ao);
        c.ao.order = orders[s];
        c.ao.levels = CURVE_LEVELS;
        c.ao.kernel = SUBD_ALPHA_COS;
        c.ao.alpha_num = 1;
        c.ao.alpha_den = (int32_t)CURVE_POINTS;
        snprintf(label, sizeof label, "S_%lu", (unsigned long)orders[s]);
        st = run_plan(&c);
        if (st != SUBD_OK) {
            printf("%-24s plan FAILED: %s\n", label, subd_status_str(st));
            continue;
        }
        if (run_first(&c, label, &first) != SUBD_OK) { run_free(&c); continue; }
        ns = time_run(&c, first, &runs);
        printf("%-24s %10lu %10.3f %10.2f %13lu %7s %5d\n", label, (unsigned long)c.co.num_points, ns / 1e6,
               (double)c.co.num_points / 1e6 / (ns / 1e9), (unsigned long)c.plan, peak_str(&c, pk, sizeof pk), runs);
        fflush(stdout);
        run_free(&c);
    }
    free(poly);

    printf("\n== Doo-Sabin type surfaces (subd_alpha_surface, order 2, B-spline kernel, s = 1: classical Doo-Sabin "
           "weights), levels 1-3; reproduce: " REPRO "\n");
    printf("%-24s %5s %10s %10s %10s %10s %13s %7s %5s\n", "mesh", "level", "out verts", "out faces", "ms/call",
           "Mfaces/s", "arena bytes", "peak", "runs");
    for (i = 0; i < g_nmesh; i++) {
        bmesh *m = &g_mesh[i];
        uint32_t level;
        for (level = 1; level <= 3; level++) {
            run_ctx c;
            double ns, first;
            int runs, st;
            char pk[16];
            memset(&c, 0, sizeof c);
            c.kind = RUN_SURF;
            c.in = &m->hm.mesh;
            subd_alpha_opts_default(&c.ao);
            c.ao.levels = level;
            st = run_plan(&c);
            if (st != SUBD_OK) {
                printf("%-24s %5lu plan FAILED: %s\n", m->name, (unsigned long)level, subd_status_str(st));
                continue;
            }
            if ((double)c.plan > PLAN_LIMIT) {
                printf("%-24s %5lu skipped (plan %lu bytes)\n", m->name, (unsigned long)level, (unsigned long)c.plan);
                continue;
            }
            if (run_first(&c, m->name, &first) != SUBD_OK) { run_free(&c); continue; }
            ns = time_run(&c, first, &runs);
            printf("%-24s %5lu %10lu %10lu %10.2f %10.2f %13lu %7s %5d\n", m->name, (unsigned long)level,
                   (unsigned long)c.out.num_verts, (unsigned long)c.out.num_faces, ns / 1e6,
                   (double)c.out.num_faces / 1e6 / (ns / 1e9), (unsigned long)c.plan, peak_str(&c, pk, sizeof pk), runs);
            fflush(stdout);
            if (level == 3 && strcmp(m->name, "stanford-bunny-open") == 0) headline = ns;
            run_free(&c);
        }
    }
    if (headline > 0.0)
        printf("headline: Doo-Sabin level 3 of stanford-bunny-open: %.3f s per call (CGAL: about 2.7 s on this "
               "machine)\n",
               headline / 1e9);
}

/* ==================================================================================== */
/* Section 5: quality, quasi 4-8 (8 binary steps) vs Loop level 4                       */

/* Enclosed volume by the divergence theorem (fan triangulation of each face), in double. */
static double mesh_volume(const subd_mesh *m)
{
    double vol = 0.0;
    uint32_t f;
    for (f = 0; f < m->num_faces; f++) {
        uint32_t s = m->face_start[f], e = m->face_start[f + 1u], c;
        const subd_real *p0 = m->pos + 3u * m->corner_vert[s];
        for (c = s + 1u; c + 1u < e; c++) {
            const subd_real *p1 = m->pos + 3u * m->corner_vert[c];
            const subd_real *p2 = m->pos + 3u * m->corner_vert[c + 1u];
            double ax = R2D(p0[0]), ay = R2D(p0[1]), az = R2D(p0[2]);
            double bx = R2D(p1[0]), by = R2D(p1[1]), bz = R2D(p1[2]);
            double cx = R2D(p2[0]), cy = R2D(p2[1]), cz = R2D(p2[2]);
            vol += ax * (by * cz - bz * cy) + ay * (bz * cx - bx * cz) + az * (bx * cy - by * cx);
        }
    }
    return vol / 6.0;
}

/* Unit normal of face f (Newell's method, double); returns 0 for a degenerate face. */
static int face_normal(const subd_mesh *m, uint32_t f, double n[3])
{
    uint32_t s = m->face_start[f], e = m->face_start[f + 1u], c;
    double len;
    n[0] = n[1] = n[2] = 0.0;
    for (c = s; c < e; c++) {
        const subd_real *p = m->pos + 3u * m->corner_vert[c];
        const subd_real *q = m->pos + 3u * m->corner_vert[c + 1u == e ? s : c + 1u];
        double px = R2D(p[0]), py = R2D(p[1]), pz = R2D(p[2]), qx = R2D(q[0]), qy = R2D(q[1]), qz = R2D(q[2]);
        n[0] += (py - qy) * (pz + qz);
        n[1] += (pz - qz) * (px + qx);
        n[2] += (px - qx) * (py + qy);
    }
    len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(len > 0.0)) return 0;
    n[0] /= len;
    n[1] /= len;
    n[2] /= len;
    return 1;
}

/* Maximum and mean angle (degrees) between the normals of two faces sharing an edge (0 =
 * flat); edges next to a degenerate face are counted in *skipped. Needs twin. */
static void mesh_dihedral(const subd_mesh *m, double *max_deg, double *mean_deg, uint32_t *skipped)
{
    uint32_t h, n = 0;
    double mx = 0.0, sum = 0.0;
    *skipped = 0;
    for (h = 0; h < m->num_corners; h++) {
        uint32_t t = m->twin[h];
        double a[3], b[3], d, ang;
        if (t == SUBD_NONE || t < h) continue;
        if (!face_normal(m, m->corner_face[h], a) || !face_normal(m, m->corner_face[t], b)) {
            (*skipped)++;
            continue;
        }
        d = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        if (d > 1.0) d = 1.0;
        if (d < -1.0) d = -1.0;
        ang = acos(d) * (180.0 / 3.14159265358979323846);
        if (ang > mx) mx = ang;
        sum += ang;
        n++;
    }
    *max_deg = mx;
    *mean_deg = n ? sum / (double)n : 0.0;
}

static void quality_row(const char *what, const subd_mesh *m, double vol_in)
{
    double vol = mesh_volume(m), mx, mean;
    uint32_t skipped;
    mesh_dihedral(m, &mx, &mean, &skipped);
    printf("  %-34s %10lu %14.6g %11.3f %12.2f %12.3f", what, (unsigned long)m->num_faces, vol,
           100.0 * (vol - vol_in) / vol_in, mx, mean);
    if (skipped) printf("  (%lu edges at degenerate faces skipped)", (unsigned long)skipped);
    printf("\n");
}

void section_quality(void)
{
    int i, any = 0;
    printf("\n== Quality: quasi 4-8 (8 binary steps, smoothing on) vs Loop level 4 (boundary PAPER) on the closed "
           "triangle meshes; reproduce: " REPRO "\n");
    printf("   volume by the divergence theorem in double; shrinkage = (V - V_input) / V_input; dihedral = angle "
           "between\n   the normals of two faces sharing an edge (0 = flat), max and mean over the edges\n");
    for (i = 0; i < g_nmesh; i++) {
        bmesh *m = &g_mesh[i];
        run_ctx q, l;
        double vol_in;
        int st;
        if (!m->tri || !m->closed) continue;
        any = 1;
        memset(&q, 0, sizeof q);
        memset(&l, 0, sizeof l);
        q.kind = RUN_Q48;
        q.in = &m->hm.mesh;
        q.qo.steps = 8;
        q.qo.boundary = SUBD_QUASI48_BOUNDARY_FIXED;
        l.kind = RUN_LOOP;
        l.in = &m->hm.mesh;
        l.lo.levels = 4;
        l.lo.boundary = SUBD_LOOP_BOUNDARY_PAPER;
        l.lo.flags = SUBD_LOOP_ADJACENCY;
        st = run_plan(&q);
        if (st == SUBD_OK) st = run_plan(&l);
        if (st != SUBD_OK) {
            printf("%s: plan FAILED: %s\n", m->name, subd_status_str(st));
            continue;
        }
        if ((double)q.plan > PLAN_LIMIT || (double)l.plan > PLAN_LIMIT) {
            printf("%s: skipped (plans %lu and %lu bytes)\n", m->name, (unsigned long)q.plan, (unsigned long)l.plan);
            continue;
        }
        vol_in = mesh_volume(&m->hm.mesh);
        printf("%s:\n  %-34s %10s %14s %11s %12s %12s\n", m->name, "mesh", "faces", "volume", "shrinkage%",
               "max dihedral", "mean dihedr.");
        quality_row("input", &m->hm.mesh, vol_in);
        if (run_first(&q, m->name, NULL) == SUBD_OK) quality_row("quasi 4-8, 8 binary steps", &q.out, vol_in);
        run_free(&q);
        if (run_first(&l, m->name, NULL) == SUBD_OK) quality_row("Loop, level 4", &l.out, vol_in);
        run_free(&l);
        fflush(stdout);
    }
    if (!any) printf("no closed triangle mesh among the inputs; skipped\n");
}

/* ==================================================================================== */
/* Section 6: progressive interpolation, PAPER vs FAST                                  */

#define PIA_MAX_ITER 2000u

void section_pia(void)
{
    static const char *const names[] = {"spot_triangulated", "stanford-bunny-open"};
    static const double tol_rel[] = {1e-4, 1e-5, 1e-6};
    uint32_t req[2][2] = {{0, 0}, {0, 0}}; /* [mesh][PAPER, FAST] iterations at 1e-4 x diagonal */
    int req_ok[2] = {0, 0};
    size_t k, t;
    printf("\n== Progressive interpolation (subd_pia, boundary PAPER, tol = 1e-4 x bounding-box diagonal, max_iter "
           "%u), PAPER vs FAST; reproduce: " REPRO "\n"
           "   (1e-4 is the specified tolerance; the 1e-5 and 1e-6 rows are for information only;\n"
           "    FAST counts work in applications of L: an SGS-PCG step costs 1.5, see src/pia.c)\n",
           PIA_MAX_ITER);
    printf("%-24s %7s %6s %10s %6s %9s %11s %11s %10s %10s %5s\n", "mesh", "tol/diag", "method", "iterations",
           "conv", "tol", "max_err", "mean_err", "ms/call", "us/iter", "runs");
    for (k = 0; k < sizeof names / sizeof names[0]; k++) {
        bmesh *m = find_mesh(names[k]);
        if (!m) {
            printf("%-24s absent; skipped\n", names[k]);
            continue;
        }
        for (t = 0; t < sizeof tol_rel / sizeof tol_rel[0]; t++) {
            uint32_t it[2] = {0, 0};
            int conv[2] = {0, 0}, ok[2] = {0, 0}, meth;
            double tns[2] = {0.0, 0.0};
            for (meth = 0; meth < 2; meth++) {
                run_ctx c;
                double ns, first;
                int runs, st;
                memset(&c, 0, sizeof c);
                c.kind = RUN_PIA;
                c.in = &m->hm.mesh;
                c.po.boundary = SUBD_LOOP_BOUNDARY_PAPER;
                c.po.tol = D2R(tol_rel[t] * m->diag);
                c.po.max_iter = PIA_MAX_ITER;
                c.po.method = meth ? SUBD_PIA_FAST : SUBD_PIA_PAPER;
                st = run_plan(&c);
                if (st != SUBD_OK) {
                    printf("%-24s %7.0e %6s plan FAILED: %s\n", m->name, tol_rel[t], meth ? "FAST" : "PAPER",
                           subd_status_str(st));
                    continue;
                }
                if (run_first(&c, m->name, &first) != SUBD_OK) { run_free(&c); continue; }
                ns = time_run(&c, first, &runs);
                printf("%-24s %7.0e %6s %10lu %6s %9.3g %11.4g %11.4g %10.2f %10.2f %5d\n", m->name, tol_rel[t],
                       meth ? "FAST" : "PAPER", (unsigned long)c.pr.iterations, c.pr.converged ? "yes" : "no",
                       R2D(c.po.tol), R2D(c.pr.max_err), R2D(c.pr.mean_err), ns / 1e6,
                       c.pr.iterations ? ns / 1e3 / (double)c.pr.iterations : 0.0, runs);
                fflush(stdout);
                it[meth] = c.pr.iterations;
                conv[meth] = c.pr.converged;
                tns[meth] = ns;
                ok[meth] = 1;
                run_free(&c);
            }
            if (ok[0] && ok[1] && it[0] > 0u)
                printf("%-24s %7.0e  FAST/PAPER iterations %lu/%lu = %.3f (target <= 1/3: %s%s), time ratio %.3f\n",
                       m->name, tol_rel[t], (unsigned long)it[1], (unsigned long)it[0], (double)it[1] / (double)it[0],
                       3u * it[1] <= it[0] ? "holds" : "does NOT hold",
                       (conv[0] && conv[1]) ? "" : "; not both converged", tns[1] / tns[0]);
            if (t == 0 && ok[0] && ok[1] && conv[0] && conv[1] && it[0] > 0u) {
                req[k][0] = it[0];
                req[k][1] = it[1];
                req_ok[k] = 1;
            }
        }
    }
    /* issue 3: FAST <= PAPER / 3 iterations at tol = 1e-4 x diagonal, on both meshes */
    for (k = 0; k < sizeof names / sizeof names[0]; k++) {
        if (!req_ok[k]) {
            printf("PIA requirement %-20s FAIL (absent, failed or not converged)\n", names[k]);
            continue;
        }
        printf("PIA requirement %-20s PAPER %lu, FAST %lu, ratio %.3f (<= 1/3): %s\n", names[k],
               (unsigned long)req[k][0], (unsigned long)req[k][1], (double)req[k][1] / (double)req[k][0],
               3u * req[k][1] <= req[k][0] ? "PASS" : "FAIL");
    }
}

/* ==================================================================================== */
/* Section: number formatting (subd_real_format; the writers' cost per coordinate)        */

#define FMT_N 65536u

typedef struct fmt_ctx {
    float f[FMT_N];
    int32_t q[FMT_N];
    int q16;
    uint64_t bytes; /* keeps the work observable */
} fmt_ctx;

static int op_format(void *p)
{
    fmt_ctx *c = (fmt_ctx *)p;
    char b[32];
    uint32_t i;
    uint64_t n = 0;
    if (c->q16)
        for (i = 0; i < FMT_N; i++) n += subd_q16_format(c->q[i], b);
    else
        for (i = 0; i < FMT_N; i++) n += subd_real_format(c->f[i], b);
    c->bytes += n;
    return SUBD_OK;
}

static uint32_t xorshift32(uint32_t *s)
{
    uint32_t x = *s;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    return *s = x;
}

/* Float32 (subd_real_format) and Q16.16 (its integer formatter, subd_q16_format) on two inputs
 * each: uniform bit patterns (all exponents) and coordinate-like values (uniform in (-4, 4):
 * the 8-9 significant digits a subdivided mesh's coordinates have). */
void section_format(void)
{
    static fmt_ctx c;
    static const char *const what[4] = {"float32 bit patterns", "float32 in (-4, 4)", "q16.16 bit patterns",
                                        "q16.16 in (-4, 4)"};
    uint32_t st = 12345u, i;
    int k, runs;
    printf("\n== number formatting (subd_real_format, subd_q16_format); reproduce: " REPRO " -s format\n"
           "%u values per run, formatted into a stack buffer; M num/s = million values per second (median\n"
           "wall-clock run); CPU M num/s = the same from the mean process CPU time per run.\n",
           FMT_N);
    printf("%-24s %10s %10s %12s %12s %5s\n", "input", "ns/number", "M num/s", "CPU M num/s", "bytes/number",
           "runs");
    for (k = 0; k < 4; k++) {
        double ns, cpu;
        struct timespec c0, c1;
        for (i = 0; i < FMT_N; i++) {
            uint32_t r = xorshift32(&st);
            union { uint32_t u; float f; } u;
            if (k == 0) {
                while ((r & 0x7f800000u) == 0x7f800000u) r = xorshift32(&st);
                u.u = r;
                c.f[i] = u.f;
            } else if (k == 1) {
                c.f[i] = (float)((double)(int32_t)r / 536870912.0);
            } else if (k == 2) {
                c.q[i] = (int32_t)r;
            } else {
                c.q[i] = (int32_t)r >> 13;
            }
        }
        c.q16 = k >= 2;
        c.bytes = 0;
        clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &c0);
        ns = measure(op_format, &c, &runs);
        clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &c1);
        /* the mean process CPU time per run too: on a shared machine the wall clock also
         * counts the time other jobs held the CPU */
        cpu = ((double)(c1.tv_sec - c0.tv_sec) * 1e9 + (double)(c1.tv_nsec - c0.tv_nsec)) / runs;
        printf("%-24s %10.2f %10.2f %12.2f %12.2f %5d\n", what[k], ns / FMT_N, FMT_N / ns * 1e3,
               FMT_N / cpu * 1e3, (double)c.bytes / ((double)FMT_N * runs), runs);
    }
}

/* ==================================================================================== */
