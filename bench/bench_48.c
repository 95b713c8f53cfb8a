/* SPDX-License-Identifier: MIT */
/* Benchmark sections of the 4-8 schemes: quasi 4-8 (q48), the semi-regular 4-8 valence table
 *  (valence48), build + extract (sr48), the uniform stream (sr48stream), the chordal stream
 *  (sr48chord) and the stream's arena table (sr48table). Part of bench (bench/bench.h).
 */
#include "bench.h"

/* ==================================================================================== */
/* Section 3: quasi 4-8                                                                 */

void section_q48(void)
{
    static const uint32_t steps_list[] = {1u, 2u, 4u, 8u};
    int i;
    size_t s;
    printf("\n== Quasi 4-8 (subd_quasi48, smoothing on, boundary FIXED, len_bits default), 1/2/4/8 binary steps; "
           "reproduce: " REPRO "\n");
    printf("   (the plan is an upper bound: 2^steps x faces; \"peak\" = measured peak / plan)\n");
    printf("%-24s %5s %10s %10s %7s %10s %10s %10s %13s %7s %5s\n", "mesh", "steps", "out verts", "out faces",
           "max val", "ms/call", "steps/s", "Mfaces/s", "arena bytes", "peak", "runs");
    for (i = 0; i < g_nmesh; i++) {
        bmesh *m = &g_mesh[i];
        if (!m->tri) {
            printf("%-24s skipped: not all triangles (quasi 4-8 needs triangles)\n", m->name);
            continue;
        }
        for (s = 0; s < sizeof steps_list / sizeof steps_list[0]; s++) {
            run_ctx c;
            double ns;
            int runs;
            char pk[16];
            memset(&c, 0, sizeof c);
            c.kind = RUN_Q48;
            c.in = &m->hm.mesh;
            c.qo.steps = steps_list[s];
            c.qo.boundary = SUBD_QUASI48_BOUNDARY_FIXED;
            c.qo.flags = 0;
            c.qo.len_bits = 0;
            if (!stepped_case(&c, m->name, c.qo.steps, &ns, &runs)) continue;
            printf("%-24s %5lu %10lu %10lu %7lu %10.2f %10.1f %10.2f %13lu %7s %5d\n", m->name,
                   (unsigned long)c.qo.steps, (unsigned long)c.out.num_verts, (unsigned long)c.out.num_faces,
                   (unsigned long)max_valence(&c.out), ns / 1e6,
                   (double)c.qo.steps / (ns / 1e9), (double)c.out.num_faces / 1e6 / (ns / 1e9), (unsigned long)c.plan,
                   peak_str(&c, pk, sizeof pk), runs);
            fflush(stdout);
            run_free(&c);
        }
    }
}

/* ==================================================================================== */
/* Section 3b: semi-regular 4-8 (pre-processing, uniform levels, adaptive extraction)     */

/* Valence of every vertex of a triangle list (a manifold: interior valence = incident
 * triangles, boundary = incident triangles + 1; boundary from unmatched directed edges). */
static void tri_valences(const uint32_t *tv, uint32_t nt, uint32_t nv, uint32_t *val, uint8_t *bnd)
{
    uint32_t t, k, i;
    uint32_t *head = (uint32_t *)calloc(nv, sizeof *head), *nxt = (uint32_t *)malloc(3u * nt * sizeof *nxt);
    memset(val, 0, nv * sizeof *val);
    memset(bnd, 0, nv);
    if (!head || !nxt) { free(head); free(nxt); return; }
    for (i = 0; i < nv; i++) head[i] = SUBD_NONE;
    for (t = 0; t < 3u * nt; t++) { /* directed edges bucketed by start vertex */
        nxt[t] = head[tv[t]];
        head[tv[t]] = t;
    }
    for (t = 0; t < nt; t++)
        for (k = 0; k < 3u; k++) {
            uint32_t a = tv[3u * t + k], b = tv[3u * t + (k + 1u) % 3u], e, twin = 0;
            val[a]++;
            for (e = head[b]; e != SUBD_NONE; e = nxt[e])
                if (tv[3u * (e / 3u) + (e % 3u + 1u) % 3u] == a) twin = 1;
            if (!twin) { bnd[a] = bnd[b] = 1; }
        }
    for (i = 0; i < nv; i++) if (bnd[i]) val[i]++;
    free(head);
    free(nxt);
}

#define VT_MAX 40
/* The section 5 valence transition table of one mesh: old valence -> new valence counts of
 * the input vertices after pre-processing, interior and boundary separately. */
static void valence_table(const bmesh *m)
{
    static uint32_t tab[2][VT_MAX + 1][2 * VT_MAX + 2];
    run_ctx c;
    uint32_t v, nv = m->hm.mesh.num_verts, *val, bad = 0, doubled = 0, n0;
    uint8_t *bnd;
    int side, o, w;
    memset(&c, 0, sizeof c);
    memset(tab, 0, sizeof tab);
    c.kind = RUN_SR48;
    c.in = &m->hm.mesh;
    c.so.steps = 0;
    if (run_plan(&c) != SUBD_OK || run_first(&c, m->name, NULL) != SUBD_OK) {
        printf("%-24s skipped (plan/build failed)\n", m->name);
        run_free(&c);
        return;
    }
    n0 = c.h.level_verts[0];
    val = (uint32_t *)malloc(n0 * sizeof *val);
    bnd = (uint8_t *)malloc(n0);
    if (!val || !bnd) { free(val); free(bnd); run_free(&c); return; }
    tri_valences(c.h.tri_vert, c.h.level_tri[1], n0, val, bnd);
    for (v = 0; v < n0; v++) { /* section 5: interior even, boundary odd */
        if (val[v] == 0) continue;
        if ((val[v] % 2u == 0u) == (bnd[v] != 0)) bad++;
    }
    for (v = 0; v < nv; v++) {
        uint32_t old, nw;
        if (m->hm.mesh.vert_tag[v] & SUBD_VTAG_ISOLATED) continue;
        old = subd_vertex_valence(&m->hm.mesh, v);
        nw = val[v];
        if (nw > 2u * old) doubled++;
        side = bnd[v] ? 1 : 0;
        tab[side][old > VT_MAX ? VT_MAX : old][nw > 2 * VT_MAX + 1 ? 2 * VT_MAX + 1 : nw]++;
    }
    printf("%-24s %lu clusters, %lu isolated triangles; level 0: %lu vertices with wrong valence parity, "
           "%lu input vertices more than doubled\n", m->name, (unsigned long)c.h.num_clusters,
           (unsigned long)c.h.num_isolated, (unsigned long)bad, (unsigned long)doubled);
    for (side = 0; side < 2; side++)
        for (o = 0; o <= VT_MAX; o++) {
            uint32_t tot = 0, best = 0;
            int bw = 0;
            for (w = 0; w <= 2 * VT_MAX + 1; w++) {
                tot += tab[side][o][w];
                if (tab[side][o][w] > best) { best = tab[side][o][w]; bw = w; }
            }
            if (!tot) continue;
            printf("   %-8s %3d%s -> ", side ? "boundary" : "interior", o, o == VT_MAX ? "+" : " ");
            for (w = 0; w <= 2 * VT_MAX + 1; w++)
                if (tab[side][o][w]) printf(" %d:%lu", w, (unsigned long)tab[side][o][w]);
            printf("   (most: %d, %.0f%%)\n", bw, 100.0 * best / tot);
        }
    free(val);
    free(bnd);
    run_free(&c);
}

void section_valence48(void)
{
    int i;
    printf("\n== Semi-regular 4-8 pre-processing (section 5): valence transition of the input vertices, "
           "old -> new:count;\n   reproduce: make bench (table for every mesh in ../shared/data/meshes)\n");
    for (i = 0; i < g_nmesh; i++) {
        if (!g_mesh[i].tri) {
            printf("%-24s skipped: not all triangles\n", g_mesh[i].name);
            continue;
        }
        valence_table(&g_mesh[i]);
        fflush(stdout);
    }
}

/* One extraction case on a built hierarchy (c->h in c's arena below c->xmark). */
static void sr48_extract_row(run_ctx *c, const char *mesh, const char *what)
{
    uint32_t xplan;
    double first, ns, t0;
    int runs, st;
    if (subd_sr48_extract_plan(&c->h, &c->ad, &xplan, 0) != SUBD_OK || xplan > c->arena.size - c->xmark) {
        printf("%-24s %-22s skipped (extract plan)\n", mesh, what);
        return;
    }
    t0 = host_now_ns();
    st = op_run(c);
    first = host_now_ns() - t0;
    if (st != SUBD_OK) {
        printf("%-24s %-22s FAILED: %s\n", mesh, what, subd_status_str(st));
        return;
    }
    ns = time_run(c, first, &runs);
    printf("%-24s %-22s %10lu %10lu %9lu %10.2f %10.2f %13lu %5d\n", mesh, what, (unsigned long)c->rep.faces,
           (unsigned long)c->rep.uniform_faces, (unsigned long)c->rep.forced_splits, ns / 1e6,
           (double)c->rep.faces / 1e6 / (ns / 1e9), (unsigned long)xplan, runs);
    fflush(stdout);
}

void section_sr48(void)
{
    static const uint32_t steps_list[] = {0u, 2u, 4u, 6u};
    int i;
    size_t s;
    printf("\n== Semi-regular 4-8 (subd_sr48_build: pre-processing + N binary steps with ZP smoothing; "
           "reproduce: " REPRO ")\n");
    printf("   build = the whole hierarchy (all levels); arena bytes = the exact plan (clusters counted first)\n");
    printf("%-24s %5s %10s %12s %10s %10s %13s %7s %5s\n", "mesh", "steps", "verts", "triangles", "ms/call",
           "Mtris/s", "arena bytes", "peak", "runs");
    for (i = 0; i < g_nmesh; i++) {
        bmesh *m = &g_mesh[i];
        if (!m->tri) {
            printf("%-24s skipped: not all triangles\n", m->name);
            continue;
        }
        for (s = 0; s < sizeof steps_list / sizeof steps_list[0]; s++) {
            run_ctx c;
            double ns;
            int runs;
            char pk[16];
            memset(&c, 0, sizeof c);
            c.kind = RUN_SR48;
            c.in = &m->hm.mesh;
            c.so.steps = steps_list[s];
            if (!stepped_case(&c, m->name, c.so.steps, &ns, &runs)) continue;
            printf("%-24s %5lu %10lu %12lu %10.2f %10.2f %13lu %7s %5d\n", m->name, (unsigned long)c.so.steps,
                   (unsigned long)c.h.num_verts, (unsigned long)c.h.num_tris, ns / 1e6,
                   (double)c.h.num_tris / 1e6 / (ns / 1e9), (unsigned long)c.plan, peak_str(&c, pk, sizeof pk), runs);
            fflush(stdout);
            run_free(&c);
        }
    }
    printf("\n   extraction (subd_sr48_extract) from a 6-step hierarchy, or 4 steps when hierarchy + extraction "
           "would exceed %.1f GB;\n   max_level = the hierarchy's steps; faces/s = output triangles per second\n",
           PLAN_LIMIT / 1e9);
    printf("%-24s %-22s %10s %10s %9s %10s %10s %13s %5s\n", "mesh", "mode", "faces", "uniform", "forced",
           "ms/call", "Mfaces/s", "arena bytes", "runs");
    for (i = 0; i < g_nmesh; i++) {
        bmesh *m = &g_mesh[i];
        run_ctx c;
        uint32_t build, k, steps, ok = 0;
        char what[40];
        double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
        if (!m->tri) continue;
        for (steps = 6; steps >= 4 && !ok; steps -= 2) {
            memset(&c, 0, sizeof c);
            c.kind = RUN_SR48;
            c.in = &m->hm.mesh;
            c.so.steps = steps;
            if (run_plan(&c) != SUBD_OK) continue; /* e.g. SUBD_ERR_TOO_BIG: try fewer steps */
            build = c.plan;
            if ((double)build > PLAN_LIMIT || run_first(&c, m->name, NULL) != SUBD_OK) { run_free(&c); continue; }
            /* one arena for the hierarchy and the largest extraction above it */
            {
                uint32_t xmax = 0, xp, keep = c.arena.used;
                subd_sr48_adapt ad;
                memset(&ad, 0, sizeof ad);
                ad.max_level = steps;
                ad.eps = D2R(1e-4 * m->diag);
                ad.normal[0] = D2R(1.0);
                for (ad.mode = SUBD_SR48_ADAPT_UNIFORM; ad.mode <= SUBD_SR48_ADAPT_CHORD; ad.mode++)
                    if (ad.mode != SUBD_SR48_ADAPT_CALLBACK && subd_sr48_extract_plan(&c.h, &ad, &xp, 0) == SUBD_OK &&
                        xp > xmax)
                        xmax = xp;
                run_free(&c);
                c.plan = keep + xmax > build ? keep + xmax : build;
                if ((double)keep + xmax > PLAN_LIMIT || run_first(&c, m->name, NULL) != SUBD_OK) {
                    run_free(&c);
                    continue;
                }
            }
            ok = 1;
        }
        if (!ok) {
            printf("%-24s skipped (hierarchy + extraction above %.1f GB)\n", m->name, PLAN_LIMIT / 1e9);
            continue;
        }
        steps = c.so.steps;
        c.xmark = subd_arena_mark(&c.arena);
        c.kind = RUN_SR48X;
        for (k = 0; k < m->hm.mesh.num_verts; k++) {
            int a;
            for (a = 0; a < 3; a++) {
                double x = R2D(m->hm.mesh.pos[3u * k + (uint32_t)a]);
                if (x < lo[a]) lo[a] = x;
                if (x > hi[a]) hi[a] = x;
            }
        }
        memset(&c.ad, 0, sizeof c.ad);
        c.ad.max_level = steps;
        c.ad.mode = SUBD_SR48_ADAPT_UNIFORM;
        snprintf(what, sizeof what, "uniform %u", (unsigned)steps);
        sr48_extract_row(&c, m->name, what);
        c.ad.mode = SUBD_SR48_ADAPT_POINT;
        for (k = 0; k < 3u; k++) c.ad.point[k] = D2R(hi[k]);
        sr48_extract_row(&c, m->name, "point (bbox corner)");
        c.ad.mode = SUBD_SR48_ADAPT_RAMP;
        c.ad.axis = 0;
        sr48_extract_row(&c, m->name, "ramp x");
        c.ad.mode = SUBD_SR48_ADAPT_PLANE;
        for (k = 0; k < 3u; k++) c.ad.point[k] = D2R(0.5 * (lo[k] + hi[k]));
        c.ad.normal[0] = D2R(1.0);
        sr48_extract_row(&c, m->name, "plane x > mid");
        c.ad.mode = SUBD_SR48_ADAPT_CHORD;
        c.ad.eps = D2R(1e-3 * m->diag);
        snprintf(what, sizeof what, "chord 1e-3 x diag");
        sr48_extract_row(&c, m->name, what);
        c.ad.eps = D2R(1e-4 * m->diag);
        snprintf(what, sizeof what, "chord 1e-4 x diag");
        sr48_extract_row(&c, m->name, what);
        run_free(&c);
    }
}

/* Streaming semi-regular 4-8 (subd_sr48_stream, UNIFORM, into a counting/hash sink) next to the
 * materialised subd_sr48_build + subd_sr48_extract(UNIFORM) in the same run; the stream's plan
 * table SUBD_SR48_STREAM_BYTES(steps, valence). */
typedef struct sr48s_sink {
    uint64_t tris;
    uint32_t h;
} sr48s_sink;
static int sr48s_tri(void *ctx, const subd_tri *t)
{
    sr48s_sink *k = (sr48s_sink *)ctx;
    uint32_t c, q, w;
    for (c = 0; c < 3u; c++)
        for (q = 0; q < 3u; q++) {
            w = subd_real_bits(t->pos[c][q]);
            k->h = (k->h ^ w) * 16777619u;
        }
    k->tris++;
    return 0;
}

void section_sr48stream(void)
{
    static const uint32_t vals[5] = {4u, 8u, 12u, 16u, 32u};
    uint32_t st2, v, steps;
    int i;
    printf("\n== Streaming semi-regular 4-8 (subd_sr48_stream UNIFORM into a hash sink) next to subd_sr48_build + "
           "subd_sr48_extract(UNIFORM) in the same run;\n   speed = stream faces/s / materialised faces/s; mem = "
           "materialised peak / (base + stream plan); check = same triangles (hash); warm = the materialised "
           "calls again in their touched arena\n   (speed w = against that); reproduce: " REPRO "\n");
    printf("%-24s %5s %10s | %9s %8s %9s | %9s %8s %11s | %6s %7s %6s | %8s %7s\n", "mesh", "steps", "faces",
           "stream ms", "Mtri/s", "plan", "mat ms", "Mtri/s", "mat bytes", "speed", "mem", "check", "warm ms",
           "speed w");
    for (i = 0; i < g_nmesh; i++) {
        bmesh *m = &g_mesh[i];
        if (!m->tri) continue;
        for (steps = 2; steps <= 6u; steps += 2u) {
            subd_arena a, b;
            subd_sr48_opts so;
            subd_sr48 h, base;
            subd_sr48_stream_opts sso;
            subd_mesh out;
            subd_sr48_adapt_report rep;
            subd_diag d;
            subd_tri_sink sink;
            sr48s_sink k1, k2;
            uint32_t bound = 0, plan = 0, mh = 0, splan = 0;
            void *mem, *bmem;
            double t0, tm = 0.0, tw = 0.0, ts;
            uint32_t run;
            so.steps = steps;
            so.flags = 0;
            if (subd_sr48_plan(&m->hm.mesh, &so, SUBD_SR48_CLUSTERS_UNKNOWN, &bound, 0) != SUBD_OK) continue;
            if ((double)bound * 2.0 > PLAN_LIMIT) continue;
            memset(&sso, 0, sizeof sso);
            sso.adapt.mode = SUBD_SR48_ADAPT_UNIFORM;
            sso.adapt.max_level = steps;
            /* materialised: build + extract in one arena */
            mem = host_arena_alloc(&a, (uint32_t)((double)bound * 2.0 > 4e9 ? 4e9 : (double)bound * 2.0));
            if (!mem) continue;
            /* twice in the same arena: the first time (tm) includes the kernel's first touch
             * of the fresh memory (at 2 steps on spot most of it: about 45 ms against 10),
             * which a caller that keeps its buffer does not pay; the second (tw) is warm */
            for (run = 0; run < 2u; run++) {
                subd_arena_rewind(&a, 0u);
                t0 = host_now_ns();
                if (subd_sr48_build(&a, &m->hm.mesh, &so, &h, &d) != SUBD_OK ||
                    subd_sr48_extract(&a, &h, &sso.adapt, &out, &rep, &d) != SUBD_OK)
                    break;
                if (run == 0u) tm = host_now_ns() - t0;
                else tw = host_now_ns() - t0;
            }
            if (run < 2u) {
                free(mem);
                continue;
            }
            mh = a.peak;
            k1.tris = 0;
            k1.h = 2166136261u;
            for (v = 0; v < out.num_faces; v++) {
                subd_tri t;
                uint32_t c, q;
                for (c = 0; c < 3u; c++)
                    for (q = 0; q < 3u; q++) t.pos[c][q] = out.pos[3u * out.corner_vert[3u * v + c] + q];
                sr48s_tri(&k1, &t);
            }
            free(mem);
            /* stream: the base, then the stream in a buffer of exactly its plan */
            if (subd_sr48_base_plan(&m->hm.mesh, 0, SUBD_SR48_CLUSTERS_UNKNOWN, &bound) != SUBD_OK) continue;
            bmem = host_arena_alloc(&b, bound + 65536u);
            if (!bmem) continue;
            t0 = host_now_ns();
            st2 = (uint32_t)-subd_sr48_base(&b, &m->hm.mesh, 0, &base, &d);
            if (st2 == 0u) st2 = (uint32_t)-subd_sr48_stream_plan(&base, &sso, &splan, &d);
            plan = b.used;
            if (st2 == 0u && splan <= b.size - b.used) {
                k2.tris = 0;
                k2.h = 2166136261u;
                sink.tri = sr48s_tri;
                sink.ctx = &k2;
                st2 = (uint32_t)-subd_sr48_stream(&b, &base, &sso, &sink, &d);
            }
            ts = host_now_ns() - t0;
            free(bmem);
            if (st2 != 0u) {
                printf("%-24s %5lu stream FAILED %d\n", m->name, (unsigned long)steps, -(int)st2);
                continue;
            }
            printf("%-24s %5lu %10lu | %9.1f %8.2f %9lu | %9.1f %8.2f %11lu | %6.2f %7.0f %6s | %8.1f %7.2f\n",
                   m->name, (unsigned long)steps, (unsigned long)k2.tris, ts / 1e6,
                   (double)k2.tris / 1e6 / (ts / 1e9), (unsigned long)splan, tm / 1e6,
                   (double)out.num_faces / 1e6 / (tm / 1e9), (unsigned long)mh,
                   ((double)k2.tris / ts) / ((double)out.num_faces / tm), (double)mh / (double)(plan + splan),
                   (k1.h == k2.h && k1.tris == k2.tris) ? "=mat" : "DIFFERS", tw / 1e6,
                   ((double)k2.tris / ts) / ((double)out.num_faces / tw));
            fflush(stdout);
        }
    }
    printf("\n   SUBD_SR48_STREAM_BYTES(steps, valence) (bytes; the base mesh not counted)\n%6s", "steps");
    for (v = 0; v < 5u; v++) printf(" %9lu", (unsigned long)vals[v]);
    printf("\n");
    for (steps = 2; steps <= 16u; steps++) {
        printf("%6lu", (unsigned long)steps);
        for (v = 0; v < 5u; v++) printf(" %9lu", (unsigned long)SUBD_SR48_STREAM_BYTES(steps, vals[v]));
        printf("\n");
    }
}

/* Chordal stream (subd_sr48_stream, SUBD_SR48_ADAPT_CHORD) next to the materialised
 * subd_sr48_build + subd_sr48_extract(CHORD) in the same run (only when named: -s sr48chord;
 * one timed run each, the stream is slow): faces of the nested cut against the exact
 * materialised cut, faces/s ratio, the stream's plan against the materialised peak. */
void section_sr48chord(void)
{
    static const double epss[2] = {0.002, 5e-4};
    uint32_t steps = 6, e;
    int i;
    printf("\n== Chordal stream (subd_sr48_stream CHORD into a counting sink) next to subd_sr48_build + "
           "subd_sr48_extract(CHORD), %u binary steps, absolute eps;\n   faces x = stream faces / extract faces; "
           "speed = stream faces/s / materialised faces/s; reproduce: build/bench/bench -s sr48chord FILES\n",
           (unsigned)steps);
    printf("%-24s %8s %9s %9s %7s | %9s %8s | %9s %11s | %6s\n", "mesh", "eps", "faces", "mat faces", "faces x",
           "stream ms", "plan", "mat ms", "mat bytes", "speed");
    for (i = 0; i < g_nmesh; i++) {
        bmesh *m = &g_mesh[i];
        if (!m->tri) continue;
        for (e = 0; e < 2u; e++) {
            subd_arena a, b;
            subd_sr48_opts so;
            subd_sr48 h, base;
            subd_sr48_stream_opts sso;
            subd_mesh out;
            subd_sr48_adapt_report rep;
            subd_diag d;
            subd_tri_sink sink;
            sr48s_sink k2;
            uint32_t bound = 0, xplan = 0, mh, splan = 0, mfaces;
            void *mem, *bmem;
            double t0, tm, ts;
            int st;
            so.steps = steps;
            so.flags = 0;
            memset(&sso, 0, sizeof sso);
            sso.adapt.mode = SUBD_SR48_ADAPT_CHORD;
            sso.adapt.max_level = steps;
            sso.adapt.eps = D2R(epss[e]);
            if (subd_sr48_plan(&m->hm.mesh, &so, SUBD_SR48_CLUSTERS_UNKNOWN, &bound, 0) != SUBD_OK) continue;
            if ((double)bound * 2.0 > 2.0 * PLAN_LIMIT) { /* the bunny's 6 steps need ~1.6 GB */
                printf("%-24s skipped (materialised above %.1f GB)\n", m->name, 2.0 * PLAN_LIMIT / 1e9);
                continue;
            }
            mem = host_arena_alloc(&a, (uint32_t)((double)bound * 2.0 > 4e9 ? 4e9 : (double)bound * 2.0));
            if (!mem) continue;
            t0 = host_now_ns();
            st = subd_sr48_build(&a, &m->hm.mesh, &so, &h, &d);
            if (st == SUBD_OK) st = subd_sr48_extract_plan(&h, &sso.adapt, &xplan, &d);
            if (st == SUBD_OK) st = subd_sr48_extract(&a, &h, &sso.adapt, &out, &rep, &d);
            tm = host_now_ns() - t0;
            mh = a.peak;
            mfaces = st == SUBD_OK ? out.num_faces : 0u;
            free(mem);
            if (st != SUBD_OK) {
                printf("%-24s materialised FAILED %d\n", m->name, st);
                continue;
            }
            if (subd_sr48_base_plan(&m->hm.mesh, 0, SUBD_SR48_CLUSTERS_UNKNOWN, &bound) != SUBD_OK) continue;
            bmem = host_arena_alloc(&b, bound + 262144u);
            if (!bmem) continue;
            t0 = host_now_ns();
            st = subd_sr48_base(&b, &m->hm.mesh, 0, &base, &d);
            if (st == SUBD_OK) st = subd_sr48_stream_plan(&base, &sso, &splan, &d);
            k2.tris = 0;
            k2.h = 2166136261u;
            if (st == SUBD_OK) {
                sink.tri = sr48s_tri;
                sink.ctx = &k2;
                st = subd_sr48_stream(&b, &base, &sso, &sink, &d);
            }
            ts = host_now_ns() - t0;
            free(bmem);
            if (st != SUBD_OK) {
                printf("%-24s stream FAILED %d\n", m->name, st);
                continue;
            }
            printf("%-24s %8.4g %9lu %9lu %7.3f | %9.1f %8lu | %9.1f %11lu | %6.3f\n", m->name, epss[e],
                   (unsigned long)k2.tris, (unsigned long)mfaces, (double)k2.tris / (double)mfaces, ts / 1e6,
                   (unsigned long)splan, tm / 1e6, (unsigned long)mh,
                   ((double)k2.tris / ts) / ((double)mfaces / tm));
            fflush(stdout);
        }
    }
}

/* The semi-regular 4-8 stream's memory table (README): SUBD_SR48_STREAM_BYTES, and the plans of
 * the adaptive modes and of CHORD, for binary steps 2..16 and base valences 4, 8, 12, 16, 32,
 * computed from the header's macros (each equal to subd_sr48_stream_plan: test_sr48_stream*.c),
 * so the table follows any change of the layout. No files read. */
int section_sr48table(void)
{
    static const uint32_t val[5] = {4, 8, 12, 16, 32};
    uint32_t m, l, v;
    printf("tinysubd %s: semi-regular 4-8 stream arena bytes (reproduce: build/bench/bench -s sr48table)\n"
           "rows: binary steps L (adapt.max_level); columns: the base mesh's largest valence N (values below 8 "
           "count as 8);\nthe plan depends on nothing else (not on the mesh size or the output).\n",
           SUBD_VERSION);
    for (m = 0; m < 3u; m++) {
        printf("\n%s\n%5s", m == 0u ? "uniform: SUBD_SR48_STREAM_BYTES(L, N)"
                             : m == 1u ? "POINT, RAMP, PLANE, CALLBACK: SUBD_SR48_STREAM_ADAPT_BYTES(L, N)"
                                       : "CHORD: SUBD_SR48_STREAM_CHORD_BYTES(L, N)", "L");
        for (v = 0; v < 5u; v++) printf(" %9s%-2u", "N=", val[v]);
        printf("\n");
        for (l = 2; l <= SUBD_SR48_MAX_STEPS; l++) {
            printf("%5u", l);
            for (v = 0; v < 5u; v++)
                printf(" %11u", m == 0u ? SUBD_SR48_STREAM_BYTES(l, val[v])
                                : m == 1u ? SUBD_SR48_STREAM_ADAPT_BYTES(l, val[v]) : SUBD_SR48_STREAM_CHORD_BYTES(l, val[v]));
            printf("\n");
        }
    }
    printf("\ntarget (issue 20): uniform at L = 16, N = 16 <= 16384 bytes: %u (%.2fx)\n", SUBD_SR48_STREAM_BYTES(16, 16),
           (double)SUBD_SR48_STREAM_BYTES(16, 16) / 16384.0);
    return 0;
}
