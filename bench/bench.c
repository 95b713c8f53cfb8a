/* SPDX-License-Identifier: MIT */
/* Host benchmark (`make bench`): OBJ parsing and mesh building, then every scheme on real
 * meshes, number formatting (float32 and Q16.16 text per coordinate), Loop (levels 1-5), Loop limit positions + normals, quasi 4-8 (1, 2, 4, 8 binary
 * steps), alpha-subdivision curves (S_2, S_3, S_4) and Doo-Sabin type surfaces (levels 1-3),
 * a quality comparison quasi 4-8 vs Loop (volume shrinkage, maximum dihedral angle),
 * progressive interpolation (PIA, method PAPER vs FAST) and streaming Loop (levels 3-5,
 * subd_loop_stream into a checksum sink next to subd_loop in the same run).
 *
 *   bench [-t SECONDS] [-s SECTIONS] [FILE.obj ...]
 *
 * Each measurement first runs the operation once (checking its status and that the arena
 * peak equals the plan), then repeats it until about SECONDS (default 0.5) have passed (at
 * least 5 runs, but a run is not started when it would take the measurement past 3 x
 * SECONDS) and reports the median run (CLOCK_MONOTONIC). Arenas are malloc'd, sized from the
 * plan calls, and reused across the repeats. Without files it takes every .obj in
 * ../shared/data/meshes/bench/ (relative to the working directory, i.e. the repository when
 * run by `make bench`) and says so when there is none. SECTIONS is a comma list of
 * parse,format,loop,limit,q48,alpha,quality,pia,sr48,sr48stream,stream,fanbuild (default: all), valence48 (only when
 * named: the semi-regular 4-8 valence transition table), sr48chord (only when named: the chordal
 * stream against build + extract(CHORD), 6 steps, eps 0.002 and 5e-4) and demostream (only when named,
 * alone, no files read: the firmware demo's streaming step on the host, the same lines and
 * hash as port/cortex-m/demo.c prints under QEMU; compile with -DSUBD_FIXED=1 for the
 * Q16.16 hash) and sr48table (only when named, alone: the 4-8 stream's arena table from the
 * plan macros). Build with -O2, no sanitizers.
 */
#include "bench.h"


double g_seconds = 0.5;

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Runs op() repeatedly for about g_seconds (at least MIN_RUNS runs unless the next run would
 * take the measurement past 3 x g_seconds); returns the median nanoseconds of one run, or a
 * negative value when op fails. */
double measure(bench_op op, void *ctx, int *runs_out)
{
    static double t[MAX_RUNS];
    double start = host_now_ns(), med, elapsed;
    int n = 0;
    while (n < MAX_RUNS) {
        double t0 = host_now_ns();
        if (op(ctx) != SUBD_OK) return -1.0;
        t[n++] = host_now_ns() - t0;
        elapsed = host_now_ns() - start;
        if (elapsed >= g_seconds * 1e9 && n >= MIN_RUNS) break;
        if (elapsed + t[n - 1] > 3.0 * g_seconds * 1e9) break;
    }
    qsort(t, (size_t)n, sizeof t[0], cmp_double); /* host timing only: order of ties irrelevant */
    med = (n % 2) ? t[n / 2] : 0.5 * (t[n / 2 - 1] + t[n / 2]);
    *runs_out = n;
    return med;
}

const char *base_name(const char *path)
{
    const char *s = strrchr(path, '/');
    return s ? s + 1 : path;
}

/* ==================================================================================== */
/* Scheme runs: one context, one op, for every scheme                                   */


int op_run(void *p)
{
    run_ctx *c = (run_ctx *)p;
    subd_arena_rewind(&c->arena, c->kind == RUN_SR48X ? c->xmark : 0u);
    switch (c->kind) {
    case RUN_LOOP: return subd_loop(&c->arena, c->in, &c->lo, &c->out, &c->diag);
    case RUN_LIMIT: return subd_loop_limit(&c->arena, c->in, &(subd_loop_limit_opts){SUBD_LOOP_BOUNDARY_PAPER, SUBD_LOOP_LIMIT_NORMALS}, &c->lpos, &c->lnrm, &c->diag);
    case RUN_Q48: return subd_quasi48(&c->arena, c->in, &c->qo, &c->out, &c->diag);
    case RUN_CURVE: return subd_alpha_curve(&c->arena, c->cpos, c->cm, 1, &c->ao, &c->co, &c->diag);
    case RUN_SURF: return subd_alpha_surface(&c->arena, c->in, &c->ao, &c->out, NULL, &c->diag);
    case RUN_PIA: return subd_pia(&c->arena, c->in, &c->po, &c->ppos, &c->pr, &c->diag);
    case RUN_SR48: return subd_sr48_build(&c->arena, c->in, &c->so, &c->h, &c->diag);
    case RUN_SR48X: return subd_sr48_extract(&c->arena, &c->h, &c->ad, &c->out, &c->rep, &c->diag);
    case RUN_STREAM:
        demo_hash_init(&c->hash);
        c->sink.tri = demo_hash_tri;
        c->sink.ctx = &c->hash;
        return subd_loop_stream(&c->arena, c->in, &c->lo, &c->sink, &c->diag);
    }
    return SUBD_ERR_PARAM;
}

/* The plan of c (fills c->plan). */
int run_plan(run_ctx *c)
{
    uint32_t pts;
    switch (c->kind) {
    case RUN_LOOP: return subd_loop_plan(c->in, &c->lo, &c->plan, 0);
    case RUN_LIMIT: return subd_loop_limit_plan(c->in, &(subd_loop_limit_opts){SUBD_LOOP_BOUNDARY_PAPER, SUBD_LOOP_LIMIT_NORMALS}, &c->plan, 0);
    case RUN_Q48: return subd_quasi48_plan(c->in, &c->qo, &c->plan, 0);
    case RUN_CURVE: return subd_alpha_curve_plan(c->cm, 1, &c->ao, &c->plan, &pts);
    case RUN_SURF: return subd_alpha_surface_plan(c->in, &c->ao, &c->plan, 0);
    case RUN_PIA: return subd_pia_plan(c->in, &c->po, &c->plan, 0);
    case RUN_SR48: { /* exact: find_clusters first, in a scratch arena */
        uint32_t bound, clusters;
        subd_arena tmp;
        void *mem;
        int st = subd_sr48_plan(c->in, &c->so, SUBD_SR48_CLUSTERS_UNKNOWN, &bound, &c->diag);
        if (st != SUBD_OK) return st;
        if ((double)bound > PLAN_LIMIT) return SUBD_ERR_TOO_BIG;
        if (!(mem = host_arena_alloc(&tmp, bound))) return SUBD_ERR_NOMEM;
        st = subd_sr48_count_clusters(&tmp, c->in, &clusters, &c->diag);
        free(mem);
        return st == SUBD_OK ? subd_sr48_plan(c->in, &c->so, clusters, &c->plan, &c->diag) : st;
    }
    case RUN_SR48X: return SUBD_ERR_PARAM; /* planned by section_sr48 (needs the hierarchy) */
    case RUN_STREAM: return subd_loop_stream_plan(c->in, &c->lo, &c->plan, 0);
    }
    return SUBD_ERR_PARAM;
}

/* Allocates the planned arena and runs once (status, peak). Returns SUBD_OK or the failing
 * status (message printed with `label`). */
int run_first(run_ctx *c, const char *label, double *first_ns)
{
    int st;
    double t0;
    c->mem = host_arena_alloc(&c->arena, c->plan);
    if (!c->mem) {
        printf("%s: host out of memory for %lu arena bytes\n", label, (unsigned long)c->plan);
        return SUBD_ERR_NOMEM;
    }
    memset(c->arena.base, 0, c->plan); /* fault the pages in: the first run is then a fair sample */
    t0 = host_now_ns();
    st = op_run(c);
    if (first_ns) *first_ns = host_now_ns() - t0;
    if (st != SUBD_OK) {
        printf("%s: FAILED: %s (plan %lu, diag.bytes_needed %lu)\n", label, subd_status_str(st),
               (unsigned long)c->plan, (unsigned long)c->diag.bytes_needed);
        return st;
    }
    return SUBD_OK;
}

/* The median time of c; a case whose checked first run already took more than 4 x g_seconds
 * is not repeated (runs = 1: that run is the measurement). */
double time_run(run_ctx *c, double first_ns, int *runs)
{
    if (first_ns > 4.0 * g_seconds * 1e9) {
        *runs = 1;
        return first_ns;
    }
    return measure(op_run, c, runs);
}

void run_free(run_ctx *c)
{
    free(c->mem);
    c->mem = NULL;
}

/* "=" when the peak equals the plan, else "peak/plan %". */
const char *peak_str(const run_ctx *c, char *buf, size_t n)
{
    if (c->arena.peak == c->plan)
        snprintf(buf, n, "=plan");
    else
        snprintf(buf, n, "%.1f%%", 100.0 * (double)c->arena.peak / (double)c->plan);
    return buf;
}

/* ==================================================================================== */
/* Bench meshes                                                                         */


bmesh g_mesh[MAX_FILES];
int g_nmesh;

static void mesh_name(char *dst, size_t n, const char *path)
{
    const char *b = base_name(path);
    size_t len = strlen(b);
    if (len > 4 && strcmp(b + len - 4, ".obj") == 0) len -= 4;
    if (len >= n) len = n - 1u;
    memcpy(dst, b, len);
    dst[len] = '\0';
}

static int load_meshes(char **paths, int n)
{
    int i, failed = 0;
    for (i = 0; i < n && g_nmesh < MAX_FILES; i++) {
        bmesh *m = &g_mesh[g_nmesh];
        subd_diag d;
        uint32_t v;
        double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300}, dd = 0.0;
        int st, k;
        memset(m, 0, sizeof *m);
        st = host_read_mesh(paths[i], NULL, &m->hm, &d, NULL);
        if (st != SUBD_OK) {
            fprintf(stderr, "%s: cannot read (status %d, line %lu)\n", paths[i], st, (unsigned long)d.line);
            failed++;
            continue;
        }
        m->path = paths[i];
        mesh_name(m->name, sizeof m->name, paths[i]);
        m->tri = m->hm.mesh.num_corners == 3u * m->hm.mesh.num_faces;
        m->closed = m->hm.mesh.num_boundary_edges == 0u;
        for (v = 0; v < m->hm.mesh.num_verts; v++) {
            if (m->hm.mesh.vert_tag[v] & SUBD_VTAG_ISOLATED) continue;
            for (k = 0; k < 3; k++) {
                double x = R2D(m->hm.mesh.pos[3u * v + (uint32_t)k]);
                if (x < lo[k]) lo[k] = x;
                if (x > hi[k]) hi[k] = x;
            }
        }
        for (k = 0; k < 3; k++) dd += (hi[k] - lo[k]) * (hi[k] - lo[k]);
        m->diag = sqrt(dd);
        g_nmesh++;
    }
    return failed;
}

bmesh *find_mesh(const char *name)
{
    int i;
    for (i = 0; i < g_nmesh; i++)
        if (strcmp(g_mesh[i].name, name) == 0) return &g_mesh[i];
    return NULL;
}


/* Largest vertex valence of a mesh with adjacency. */
uint32_t max_valence(const subd_mesh *m)
{
    uint32_t v, mx = 0;
    for (v = 0; v < m->num_verts; v++) {
        uint32_t n = subd_vertex_valence(m, v);
        if (n > mx) mx = n;
    }
    return mx;
}

/* Plan, skip with a reason (too big for 32-bit sizes, plan above PLAN_LIMIT, a failed
 * plan), run once, then time: the common part of the per-steps rows of the quasi 4-8 and
 * semi-regular 4-8 sections. Returns 1 with c still allocated (run_free it), else 0. */
int stepped_case(run_ctx *c, const char *name, uint32_t steps, double *ns, int *runs)
{
    double first;
    int st = run_plan(c);
    if (st == SUBD_ERR_TOO_BIG) {
        printf("%-24s %5lu skipped (plan exceeds 32-bit sizes)\n", name, (unsigned long)steps);
        return 0;
    }
    if (st != SUBD_OK) {
        printf("%-24s %5lu plan FAILED: %s\n", name, (unsigned long)steps, subd_status_str(st));
        return 0;
    }
    if ((double)c->plan > PLAN_LIMIT) {
        printf("%-24s %5lu skipped (plan %lu bytes)\n", name, (unsigned long)steps, (unsigned long)c->plan);
        return 0;
    }
    if (run_first(c, name, &first) != SUBD_OK) {
        run_free(c);
        return 0;
    }
    *ns = time_run(c, first, runs);
    return 1;
}

/* Every .obj in dir (malloc'd paths, sorted by name), count in *n. */
static char **list_objs(const char *dir, int *n)
{
    DIR *d = opendir(dir);
    struct dirent *e;
    char **list = NULL;
    int cnt = 0, i, j;
    *n = 0;
    if (!d) return NULL;
    list = (char **)calloc(MAX_FILES, sizeof *list);
    if (!list) {
        closedir(d);
        return NULL;
    }
    while ((e = readdir(d)) != NULL && cnt < MAX_FILES) {
        size_t len = strlen(e->d_name);
        struct stat sb;
        char *p;
        if (len < 5 || host_format_of(e->d_name) != HOST_FMT_OBJ) continue;
        p = (char *)malloc(strlen(dir) + len + 2u);
        if (!p) break;
        sprintf(p, "%s/%s", dir, e->d_name);
        if (stat(p, &sb) == 0 && S_ISREG(sb.st_mode))
            list[cnt++] = p;
        else
            free(p);
    }
    closedir(d);
    for (i = 1; i < cnt; i++) /* insertion sort by name: a reproducible order */
        for (j = i; j > 0 && strcmp(list[j - 1], list[j]) > 0; j--) {
            char *t = list[j];
            list[j] = list[j - 1];
            list[j - 1] = t;
        }
    *n = cnt;
    return list;
}

static int section_on(const char *sections, const char *name)
{
    const char *p = sections;
    size_t n = strlen(name);
    if (!sections) return 1;
    while (*p) {
        const char *e = strchr(p, ',');
        size_t len = e ? (size_t)(e - p) : strlen(p);
        if (len == n && strncmp(p, name, n) == 0) return 1;
        if (!e) break;
        p = e + 1;
    }
    return 0;
}

static int usage(int rc)
{
    fprintf(rc ? stderr : stdout,
            "usage: bench [-t SECONDS] [-s parse,format,loop,limit,q48,alpha,quality,pia,sr48,sr48stream,stream,fanbuild,valence48] [FILE.obj ...]\n"
            "       bench -s demostream\n"
            "       bench -s sr48table\n");
    return rc;
}

int main(int argc, char **argv)
{
    int i = 1, failed = 0, nfiles, ndef = 0, k;
    char **def = NULL, **files;
    const char *sections = NULL;
    double t_start = host_now_ns();

    while (i < argc && argv[i][0] == '-') {
        if (strcmp(argv[i], "-t") == 0 && i + 1 < argc) {
            char *end;
            g_seconds = strtod(argv[i + 1], &end);
            if (*end || !(g_seconds >= 0.0 && g_seconds <= 600.0)) return usage(1);
            i += 2;
        } else if (strcmp(argv[i], "-s") == 0 && i + 1 < argc) {
            sections = argv[i + 1];
            i += 2;
        } else {
            return usage(argv[i][1] == 'h' || strcmp(argv[i], "--help") == 0 ? 0 : 1);
        }
    }
    if (sections && strcmp(sections, "demostream") == 0) return section_demostream();
    if (sections && strcmp(sections, "sr48table") == 0) return section_sr48table();
    nfiles = argc - i;
    files = argv + i;
    if (nfiles == 0) {
        def = list_objs(DEFAULT_DIR, &ndef);
        if (!def || ndef == 0) {
            printf("bench: no .obj files in %s/ (shared mesh data absent); mesh sections skipped, curves "
                   "only\n", DEFAULT_DIR);
            sections = "alpha,format";
        }
        nfiles = ndef;
        files = def;
    }
    printf("tinysubd %s host benchmark (%s; reproduce: " REPRO "). Median of repeated runs, ~%.2f s per "
           "measurement\n(fewer runs for slow cases; \"runs\" column), CLOCK_MONOTONIC; arenas malloc'd from the "
           "plan calls;\n\"peak\" = \"=plan\" when the measured arena peak equals the plan.\n",
           SUBD_VERSION, ARITHMETIC, g_seconds);
    if (section_on(sections, "parse")) {
        printf("\n== OBJ parse and mesh build; reproduce: " REPRO "\n"
               "parse = subd_obj_plan + subd_obj_read of the file in memory; build = subd_mesh_build from its face "
               "list\n(Mc/s = million corners per second); arena bytes = the plan (exact arena of one mesh).\n");
        printf("%-24s %10s %8s %8s %8s %10s %9s %10s %9s %11s %9s\n", "file", "size", "verts", "faces", "corners",
               "parse MB/s", "parse ms", "build Mc/s", "build ms", "arena bytes", "runs");
        for (k = 0; k < nfiles; k++) failed += bench_file(files[k]);
    }
    failed += load_meshes(files, nfiles);
    if (section_on(sections, "format")) section_format();
    if (section_on(sections, "loop")) section_loop();
    if (section_on(sections, "stream")) section_stream();
    if (section_on(sections, "limit")) section_limit();
    if (section_on(sections, "q48")) section_q48();
    if (section_on(sections, "alpha")) section_alpha();
    if (section_on(sections, "quality")) section_quality();
    if (section_on(sections, "pia")) section_pia();
    if (section_on(sections, "sr48")) section_sr48();
    if (section_on(sections, "sr48stream")) section_sr48stream();
    if (section_on(sections, "fanbuild")) failed += section_fanbuild();
    if (sections && section_on(sections, "valence48")) section_valence48();
    if (sections && section_on(sections, "sr48chord")) section_sr48chord();
    for (k = 0; k < g_nmesh; k++) host_mesh_free(&g_mesh[k].hm);
    for (k = 0; k < ndef; k++) free(def[k]);
    free(def);
    printf("\nbench: total %.1f s\n", (host_now_ns() - t_start) / 1e9);
    /* The valence table runs over every shared mesh, including the robustness set whose
     * non-manifold files are rejected on purpose: for it an unreadable file is reported only. */
    if (sections && strcmp(sections, "valence48") == 0) return 0;
    return failed ? 1 : 0;
}
