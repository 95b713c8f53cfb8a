/* SPDX-License-Identifier: MIT */
/* Benchmark sections: Loop levels 1-5 (loop), the Loop stream next to subd_loop (stream), the
 *  firmware demo's streaming step on the host (demostream) and Loop limit positions + normals
 *  (limit). Part of bench (bench/bench.h).
 */
#include "bench.h"

/* ==================================================================================== */
/* Section 1: Loop levels 1-5                                                           */

void section_loop(void)
{
    int i;
    uint32_t level;
    printf("\n== Loop subdivision (subd_loop, boundary PAPER, flags 0 = no output adjacency), levels 1-5; "
           "reproduce: " REPRO "\n");
    printf("%-24s %5s %10s %10s %10s %10s %13s %7s %5s\n", "mesh", "level", "out verts", "out faces", "ms/call",
           "Mfaces/s", "arena bytes", "peak", "runs");
    for (i = 0; i < g_nmesh; i++) {
        bmesh *m = &g_mesh[i];
        if (!m->tri) {
            printf("%-24s skipped: not all triangles (Loop needs triangles)\n", m->name);
            continue;
        }
        for (level = 1; level <= 5; level++) {
            run_ctx c;
            double ns, first, faces_est, out_est;
            int runs, st;
            char pk[16];
            memset(&c, 0, sizeof c);
            c.kind = RUN_LOOP;
            c.in = &m->hm.mesh;
            c.lo.levels = level;
            c.lo.boundary = SUBD_LOOP_BOUNDARY_PAPER;
            c.lo.flags = 0;
            st = run_plan(&c);
            faces_est = (double)m->hm.mesh.num_faces * pow(4.0, (double)level);
            out_est = faces_est * (4.0 + 3.0 * 9.0) + 0.5 * faces_est * 13.0;
            if (st == SUBD_ERR_TOO_BIG) {
                printf("%-24s %5lu skipped (plan exceeds 32-bit sizes)\n", m->name, (unsigned long)level);
                continue;
            }
            if (st != SUBD_OK) {
                printf("%-24s %5lu plan FAILED: %s\n", m->name, (unsigned long)level, subd_status_str(st));
                continue;
            }
            if ((double)c.plan > PLAN_LIMIT || out_est > OUT_LIMIT) {
                printf("%-24s %5lu skipped (plan %lu bytes)\n", m->name, (unsigned long)level, (unsigned long)c.plan);
                continue;
            }
            if (run_first(&c, m->name, &first) != SUBD_OK) { run_free(&c); continue; }
            ns = time_run(&c, first, &runs);
            printf("%-24s %5lu %10lu %10lu %10.2f %10.2f %13lu %7s %5d\n", m->name, (unsigned long)level,
                   (unsigned long)c.out.num_verts, (unsigned long)c.out.num_faces, ns / 1e6,
                   (double)c.out.num_faces / 1e6 / (ns / 1e9), (unsigned long)c.plan, peak_str(&c, pk, sizeof pk), runs);
            fflush(stdout);
            run_free(&c);
        }
    }
}

/* ==================================================================================== */
/* Section 1b: streaming Loop (subd_loop_stream into a checksum sink) next to subd_loop     */

/* The checksum of demo_mesh.h over subd_loop's output faces in order: equal to the stream's
 * when the j-th emitted triangle is output face j with the same bits (subd_loop_stream's
 * contract). */
static uint32_t loop_output_hash(const subd_mesh *m)
{
    uint32_t h = DEMO_FNV_BASIS, f, c;
    for (f = 0; f < m->num_faces; f++) {
        const subd_real *p[3];
        for (c = 0; c < 3u; c++) p[c] = m->pos + 3u * m->corner_vert[m->face_start[f] + c];
        h = demo_hash_pos(h, p);
    }
    return h;
}


void section_stream(void)
{
    int i;
    uint32_t level;
    printf("\n== Streaming Loop (subd_loop_stream, boundary PAPER, into a checksum sink: FNV-1a of every emitted "
           "position)\nnext to subd_loop (flags 0) in the same run, levels 3-5; speed = stream triangles/s / subd_loop "
           "output faces/s;\nmem = subd_loop plan / stream plan; check = stream hash vs the same hash over subd_loop's "
           "output faces; reproduce: " REPRO "\n");
    printf("%-24s %2s %10s %4s | %9s %8s %10s %6s %4s | %9s %8s %12s %4s | %6s %9s %6s\n", "mesh", "L", "triangles",
           "maxv", "stream ms", "Mtri/s", "plan bytes", "peak", "runs", "loop ms", "Mf/s", "plan bytes", "runs", "speed",
           "mem", "check");
    for (i = 0; i < g_nmesh; i++) {
        bmesh *m = &g_mesh[i];
        if (!m->tri) {
            printf("%-24s skipped: not all triangles (Loop needs triangles)\n", m->name);
            continue;
        }
        for (level = 3; level <= 5; level++) {
            run_ctx sc, lc;
            double sns = 0.0, lns = 0.0, first, faces_est, out_est;
            int sruns = 0, lruns = 0, st, have_loop = 0;
            uint32_t lhash = 0;
            char pk[16], lms[16], lmf[16], lplan[16], lr[8], sp[16], mr[16];
            const char *check = "-";
            memset(&sc, 0, sizeof sc);
            memset(&lc, 0, sizeof lc);
            sc.kind = RUN_STREAM;
            lc.kind = RUN_LOOP;
            sc.in = lc.in = &m->hm.mesh;
            sc.lo.levels = lc.lo.levels = level;
            sc.lo.boundary = lc.lo.boundary = SUBD_LOOP_BOUNDARY_PAPER;
            sc.lo.flags = lc.lo.flags = 0;
            if ((st = run_plan(&sc)) != SUBD_OK) {
                printf("%-24s %2lu stream plan FAILED: %s\n", m->name, (unsigned long)level, subd_status_str(st));
                continue;
            }
            /* subd_loop in the same run, when its output fits the host (as section_loop) */
            faces_est = (double)m->hm.mesh.num_faces * pow(4.0, (double)level);
            out_est = faces_est * (4.0 + 3.0 * 9.0) + 0.5 * faces_est * 13.0;
            if (run_plan(&lc) == SUBD_OK && (double)lc.plan <= PLAN_LIMIT && out_est <= OUT_LIMIT &&
                run_first(&lc, m->name, &first) == SUBD_OK) {
                lns = time_run(&lc, first, &lruns);
                if (lns > 0.0) {
                    have_loop = 1;
                    lhash = loop_output_hash(&lc.out);
                }
            }
            run_free(&lc);
            if (run_first(&sc, m->name, &first) != SUBD_OK) { run_free(&sc); continue; }
            sns = time_run(&sc, first, &sruns);
            if (sns <= 0.0) {
                printf("%-24s %2lu stream: a repeated run failed\n", m->name, (unsigned long)level);
                run_free(&sc);
                continue;
            }
            snprintf(lms, sizeof lms, "-");
            snprintf(lmf, sizeof lmf, "-");
            snprintf(lplan, sizeof lplan, have_loop ? "%lu" : "skipped", (unsigned long)lc.plan);
            snprintf(lr, sizeof lr, "-");
            snprintf(sp, sizeof sp, "-");
            snprintf(mr, sizeof mr, "-");
            if (have_loop) {
                snprintf(lms, sizeof lms, "%.2f", lns / 1e6);
                snprintf(lmf, sizeof lmf, "%.2f", (double)lc.out.num_faces / 1e6 / (lns / 1e9));
                snprintf(lr, sizeof lr, "%d", lruns);
                snprintf(sp, sizeof sp, "%.2f", ((double)sc.hash.tris / sns) / ((double)lc.out.num_faces / lns));
                snprintf(mr, sizeof mr, "%.0f", (double)lc.plan / (double)sc.plan);
                check = (lhash == sc.hash.h && lc.out.num_faces == sc.hash.tris) ? "=loop" : "DIFFERS";
            }
            printf("%-24s %2lu %10lu %4lu | %9.2f %8.2f %10lu %6s %4d | %9s %8s %12s %4s | %6s %9s %6s\n", m->name,
                   (unsigned long)level, (unsigned long)sc.hash.tris, (unsigned long)max_valence(&m->hm.mesh), sns / 1e6,
                   (double)sc.hash.tris / 1e6 / (sns / 1e9), (unsigned long)sc.plan, peak_str(&sc, pk, sizeof pk),
                   sruns, lms, lmf, lplan, lr, sp, mr, check);
            fflush(stdout);
            run_free(&sc);
        }
    }
}

/* The firmware demo's streaming step (port/cortex-m/demo.c) on the host: the same mesh, plan,
 * stream and checksum lines, to compare with the QEMU output. */
int section_demostream(void)
{
    static demo_geo geo;
    static uint8_t stream_arena[SUBD_LOOP_STREAM_BYTES(DEMO_STREAM_LEVELS, DEMO_GEO_MAX_VALENCE)];
    subd_face_list fl;
    subd_mesh m;
    subd_arena ma, sa;
    subd_loop_opts o;
    subd_loop_sink sink;
    subd_diag d;
    demo_hash hs;
    uint32_t plan, v, maxval = 0;
    void *mem;
    double t0, t1;
    int st;
    printf("tinysubd %s firmware demo streaming step on the host, arithmetic %s\n", SUBD_VERSION,
           SUBD_FIXED ? "Q16.16" : "float32");
    printf("streaming Loop, level 6, geodesic sphere built in code:\n");
    if ((st = demo_geo_build(&geo, &fl)) != SUBD_OK || (st = subd_mesh_plan(&fl, &plan)) != SUBD_OK) goto fail;
    if (!(mem = host_arena_alloc(&ma, plan))) return 1;
    if ((st = subd_mesh_build(&ma, &fl, &m, &d)) != SUBD_OK) goto fail;
    for (v = 0; v < m.num_verts; v++)
        if (subd_vertex_valence(&m, v) > maxval) maxval = subd_vertex_valence(&m, v);
    printf("  control vertices %lu\n  control faces %lu\n  max valence %lu\n", (unsigned long)m.num_verts,
           (unsigned long)m.num_faces, (unsigned long)maxval);
    o.levels = DEMO_STREAM_LEVELS;
    o.boundary = SUBD_LOOP_BOUNDARY_PAPER;
    o.flags = 0;
    if ((st = subd_loop_stream_plan(&m, &o, &plan, 0)) != SUBD_OK) goto fail;
    printf("  stream arena bytes (static) %lu\n  stream arena bytes planned %lu\n", (unsigned long)sizeof stream_arena,
           (unsigned long)plan);
    subd_arena_init(&sa, stream_arena, sizeof stream_arena);
    demo_hash_init(&hs);
    sink.tri = demo_hash_tri;
    sink.ctx = &hs;
    t0 = host_now_ns();
    st = subd_loop_stream(&sa, &m, &o, &sink, &d);
    t1 = host_now_ns();
    if (st != SUBD_OK) goto fail;
    printf("  stream arena bytes used (peak) %lu\n  triangles %lu\n  position hash (FNV-1a) 0x%08lx\n",
           (unsigned long)sa.peak, (unsigned long)hs.tris, (unsigned long)hs.h);
    printf("  host: %.3f s, %.2f M triangles/s (stream + checksum sink, one run)\n", (t1 - t0) / 1e9,
           (double)hs.tris / 1e6 / ((t1 - t0) / 1e9));
    v = 0;
    sink.tri = demo_count_tri;
    sink.ctx = &v;
    t0 = host_now_ns();
    st = subd_loop_stream(&sa, &m, &o, &sink, &d);
    t1 = host_now_ns();
    if (st != SUBD_OK) goto fail;
    printf("  host: %.3f s, %.2f M triangles/s (stream + counting sink, one run)\n", (t1 - t0) / 1e9,
           (double)v / 1e6 / ((t1 - t0) / 1e9));
    { /* limit mode, as the firmware demo's limit step (counting sink) */
        static uint8_t limit_arena[SUBD_LOOP_STREAM_BYTES_LIMIT(DEMO_STREAM_LEVELS, DEMO_GEO_MAX_VALENCE)];
        subd_loop_opts lo = o;
        lo.flags = SUBD_LOOP_STREAM_LIMIT;
        subd_arena_init(&sa, limit_arena, sizeof limit_arena);
        v = 0;
        t0 = host_now_ns();
        st = subd_loop_stream(&sa, &m, &lo, &sink, &d);
        t1 = host_now_ns();
        if (st != SUBD_OK) goto fail;
        printf("  host: %.3f s, %.2f M triangles/s (limit stream + counting sink, one run)\n", (t1 - t0) / 1e9,
               (double)v / 1e6 / ((t1 - t0) / 1e9));
    }
    { /* the same hash over subd_loop's level-6 output faces (the stream's contract) */
        subd_arena la;
        subd_mesh out;
        void *lmem;
        uint32_t lh;
        if ((st = subd_loop_plan(&m, &o, &plan, 0)) != SUBD_OK) goto fail;
        if (!(lmem = host_arena_alloc(&la, plan))) return 1;
        if ((st = subd_loop(&la, &m, &o, &out, &d)) != SUBD_OK) goto fail;
        lh = loop_output_hash(&out);
        printf("  host: subd_loop level 6: %lu faces, hash over its faces 0x%08lx (%s the stream's)\n",
               (unsigned long)out.num_faces, (unsigned long)lh,
               lh == hs.h && out.num_faces == hs.tris ? "equal to" : "DIFFERS from");
        free(lmem);
    }
    free(mem);
    return 0;
fail:
    printf("demostream FAILED: %s\n", subd_status_str(st));
    return 1;
}

/* ==================================================================================== */
/* Section 2: Loop limit positions + normals                                            */

void section_limit(void)
{
    int i;
    printf("\n== Loop limit positions + normals (subd_loop_limit, boundary PAPER) of the input vertices; "
           "reproduce: " REPRO "\n");
    printf("%-24s %10s %10s %10s %13s %7s %5s\n", "mesh", "verts", "ms/call", "Mverts/s", "arena bytes", "peak",
           "runs");
    for (i = 0; i < g_nmesh; i++) {
        bmesh *m = &g_mesh[i];
        run_ctx c;
        double ns, first;
        int runs, st;
        char pk[16];
        if (!m->tri) {
            printf("%-24s skipped: not all triangles\n", m->name);
            continue;
        }
        memset(&c, 0, sizeof c);
        c.kind = RUN_LIMIT;
        c.in = &m->hm.mesh;
        st = run_plan(&c);
        if (st != SUBD_OK) {
            printf("%-24s plan FAILED: %s\n", m->name, subd_status_str(st));
            continue;
        }
        if (run_first(&c, m->name, &first) != SUBD_OK) { run_free(&c); continue; }
        ns = time_run(&c, first, &runs);
        printf("%-24s %10lu %10.3f %10.2f %13lu %7s %5d\n", m->name, (unsigned long)m->hm.mesh.num_verts, ns / 1e6,
               (double)m->hm.mesh.num_verts / 1e6 / (ns / 1e9), (unsigned long)c.plan, peak_str(&c, pk, sizeof pk),
               runs);
        fflush(stdout);
        run_free(&c);
    }
}
