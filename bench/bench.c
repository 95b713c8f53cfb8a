/* Host benchmark: OBJ parsing (subd_obj_plan + subd_obj_read) and mesh building
 * (subd_mesh_build from a plain face list) on real meshes.
 *
 *   bench [-t SECONDS] [FILE.obj ...]
 *
 * Each measurement repeats the operation until about SECONDS (default 1) have passed (at
 * least 5 runs) and reports the median run. Without files it takes the largest .obj in
 * ../shared/data/meshes/bench/ (relative to the working directory, i.e. the repository when
 * run by `make bench`) and says so when there is none. Build with -O2 and no sanitizers.
 */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "subd.h"
#include "fileio.h"

#define DEFAULT_DIR "../shared/data/meshes/bench"
#define MIN_RUNS 5
#define MAX_RUNS 100000

#if SUBD_FIXED
#define ARITHMETIC "q16.16"
#else
#define ARITHMETIC "float32"
#endif

static double g_seconds = 1.0;

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Runs op() repeatedly for about g_seconds; returns the median nanoseconds of one run, or a
 * negative value when op fails. */
typedef int (*bench_op)(void *ctx);
static double measure(bench_op op, void *ctx, int *runs_out)
{
    static double t[MAX_RUNS];
    double start = host_now_ns(), med;
    int n = 0;
    while (n < MAX_RUNS && (n < MIN_RUNS || host_now_ns() - start < g_seconds * 1e9)) {
        double t0 = host_now_ns();
        if (op(ctx) != SUBD_OK) return -1.0;
        t[n++] = host_now_ns() - t0;
    }
    qsort(t, (size_t)n, sizeof t[0], cmp_double); /* host timing only: order of ties irrelevant */
    med = (n % 2) ? t[n / 2] : 0.5 * (t[n / 2 - 1] + t[n / 2]);
    *runs_out = n;
    return med;
}

typedef struct parse_ctx {
    const char *text;
    uint32_t len;
    subd_arena arena;
    subd_mesh mesh;
    subd_diag diag;
} parse_ctx;

static int op_parse(void *p)
{
    parse_ctx *c = (parse_ctx *)p;
    uint32_t bytes;
    int st = subd_obj_plan(c->text, c->len, &bytes, &c->diag);
    if (st != SUBD_OK) return st;
    if (bytes > c->arena.size) return SUBD_ERR_NOMEM;
    subd_arena_rewind(&c->arena, 0);
    return subd_obj_read(&c->arena, c->text, c->len, &c->mesh, &c->diag);
}

typedef struct build_ctx {
    subd_face_list fl;
    subd_arena arena;
    subd_mesh mesh;
    subd_diag diag;
} build_ctx;

static int op_build(void *p)
{
    build_ctx *c = (build_ctx *)p;
    subd_arena_rewind(&c->arena, 0);
    return subd_mesh_build(&c->arena, &c->fl, &c->mesh, &c->diag);
}

static const char *base_name(const char *path)
{
    const char *s = strrchr(path, '/');
    return s ? s + 1 : path;
}

static int bench_file(const char *path)
{
    parse_ctx pc;
    build_ctx bc;
    void *pmem = NULL, *bmem = NULL;
    uint32_t *face_size = NULL, *line_size = NULL, plan = 0, bplan = 0, f;
    double parse_ns, build_ns;
    int prun = 0, brun = 0, st, rc = 1;
    char *text = NULL, runs[32];
    uint32_t len = 0;

    memset(&pc, 0, sizeof pc);
    memset(&bc, 0, sizeof bc);
    if (host_read_file(path, &text, &len) != 0) {
        perror(path);
        return 1;
    }
    pc.text = text;
    pc.len = len;
    st = subd_obj_plan(text, len, &plan, &pc.diag);
    if (st == SUBD_OK) {
        pmem = host_arena_alloc(&pc.arena, plan);
        if (!pmem) st = SUBD_ERR_NOMEM;
    }
    if (st == SUBD_OK) st = op_parse(&pc);
    if (st != SUBD_OK) {
        fprintf(stderr, "%s:%lu: %s\n", path, (unsigned long)pc.diag.line, subd_status_str(st));
        goto done;
    }
    parse_ns = measure(op_parse, &pc, &prun);

    /* A plain face list from the parsed mesh (what an application would hand the builder). */
    face_size = (uint32_t *)malloc(((size_t)pc.mesh.num_faces + 1u) * sizeof *face_size);
    line_size = (uint32_t *)malloc(((size_t)pc.mesh.num_lines + 1u) * sizeof *line_size);
    if (!face_size || !line_size) {
        fprintf(stderr, "%s: out of memory\n", path);
        goto done;
    }
    for (f = 0; f < pc.mesh.num_faces; f++) face_size[f] = subd_face_size(&pc.mesh, f);
    for (f = 0; f < pc.mesh.num_lines; f++) line_size[f] = pc.mesh.line_start[f + 1u] - pc.mesh.line_start[f];
    bc.fl.num_verts = pc.mesh.num_verts;
    bc.fl.pos = pc.mesh.pos;
    bc.fl.num_faces = pc.mesh.num_faces;
    bc.fl.face_size = face_size;
    bc.fl.index = pc.mesh.corner_vert;
    bc.fl.num_lines = pc.mesh.num_lines;
    bc.fl.line_size = pc.mesh.num_lines ? line_size : NULL;
    bc.fl.line_index = pc.mesh.num_lines ? pc.mesh.line_vert : NULL;
    st = subd_mesh_plan(&bc.fl, &bplan);
    if (st == SUBD_OK) {
        bmem = host_arena_alloc(&bc.arena, bplan);
        if (!bmem) st = SUBD_ERR_NOMEM;
    }
    if (st == SUBD_OK) st = op_build(&bc);
    if (st != SUBD_OK) {
        fprintf(stderr, "%s: mesh build: %s\n", path, subd_status_str(st));
        goto done;
    }
    if (bc.mesh.num_edges != pc.mesh.num_edges || bc.mesh.num_boundary_loops != pc.mesh.num_boundary_loops) {
        fprintf(stderr, "%s: built mesh differs from the parsed mesh\n", path);
        goto done;
    }
    if (pc.arena.peak > plan || bc.arena.peak > bplan || bplan != plan)
        fprintf(stderr, "%s: note: read plan %lu (peak %lu), build plan %lu (peak %lu)\n", path, (unsigned long)plan,
                (unsigned long)pc.arena.peak, (unsigned long)bplan, (unsigned long)bc.arena.peak);
    build_ns = measure(op_build, &bc, &brun);
    if (parse_ns <= 0.0 || build_ns <= 0.0) {
        fprintf(stderr, "%s: a repeated run failed\n", path);
        goto done;
    }
    snprintf(runs, sizeof runs, "%d/%d", prun, brun);
    printf("%-24s %7.2f MB %8lu %8lu %8lu %10.1f %9.3f %10.2f %9.3f %11lu %9s\n", base_name(path),
           (double)len / 1e6, (unsigned long)pc.mesh.num_verts, (unsigned long)pc.mesh.num_faces,
           (unsigned long)pc.mesh.num_corners, ((double)len / 1e6) / (parse_ns / 1e9), parse_ns / 1e6,
           ((double)pc.mesh.num_corners / 1e6) / (build_ns / 1e9), build_ns / 1e6, (unsigned long)plan, runs);
    fflush(stdout);
    rc = 0;
done:
    free(face_size);
    free(line_size);
    free(pmem);
    free(bmem);
    free(text);
    return rc;
}

/* The largest .obj in dir (malloc'd path), or NULL. */
static char *largest_obj(const char *dir)
{
    DIR *d = opendir(dir);
    struct dirent *e;
    char *best = NULL;
    long long best_size = -1;
    if (!d) return NULL;
    while ((e = readdir(d)) != NULL) {
        size_t n = strlen(e->d_name);
        struct stat sb;
        char *p;
        if (n < 5 || host_format_of(e->d_name) != HOST_FMT_OBJ) continue;
        p = (char *)malloc(strlen(dir) + n + 2u);
        if (!p) break;
        sprintf(p, "%s/%s", dir, e->d_name);
        if (stat(p, &sb) == 0 && S_ISREG(sb.st_mode) &&
            ((long long)sb.st_size > best_size ||
             ((long long)sb.st_size == best_size && best && strcmp(p, best) < 0))) {
            free(best);
            best = p;
            best_size = (long long)sb.st_size;
        } else {
            free(p);
        }
    }
    closedir(d);
    return best;
}

int main(int argc, char **argv)
{
    int i = 1, failed = 0, nfiles;
    char *def = NULL;

    if (i + 1 < argc && strcmp(argv[i], "-t") == 0) {
        char *end;
        g_seconds = strtod(argv[i + 1], &end);
        if (*end || !(g_seconds >= 0.0 && g_seconds <= 600.0)) {
            fprintf(stderr, "usage: bench [-t SECONDS] [FILE.obj ...]\n");
            return 1;
        }
        i += 2;
    } else if (i < argc && argv[i][0] == '-') {
        fprintf(stderr, "usage: bench [-t SECONDS] [FILE.obj ...]\n");
        return argv[i][1] == 'h' || strcmp(argv[i], "--help") == 0 ? 0 : 1;
    }
    nfiles = argc - i;
    if (nfiles == 0) {
        def = largest_obj(DEFAULT_DIR);
        if (!def) {
            printf("bench: no .obj files in %s/ (shared mesh data absent); skipped\n", DEFAULT_DIR);
            return 0;
        }
    }
    printf("tinysubd %s host benchmark (%s). parse = subd_obj_plan + subd_obj_read of the file in memory;\n"
           "build = subd_mesh_build from its face list (Mc/s = million corners per second); median of\n"
           "repeated runs, ~%.1f s per measurement; arena bytes = the plan (exact arena of one mesh).\n",
           SUBD_VERSION, ARITHMETIC, g_seconds);
    printf("%-24s %10s %8s %8s %8s %10s %9s %10s %9s %11s %9s\n", "file", "size", "verts", "faces", "corners",
           "parse MB/s", "parse ms", "build Mc/s", "build ms", "arena bytes", "runs");
    if (def) {
        failed += bench_file(def);
        free(def);
    }
    for (; i < argc; i++) failed += bench_file(argv[i]);
    return failed ? 1 : 0;
}
