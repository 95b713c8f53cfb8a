/* SPDX-License-Identifier: MIT */
/* Benchmark sections: OBJ parsing and mesh building (per file), and the fan/grid build
 *  comparison (fanbuild). Part of bench (bench/bench.h).
 */
#include "bench.h"

/* ==================================================================================== */
/* Section 0: OBJ parse and mesh build                                                   */

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

int bench_file(const char *path)
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

/* ==================================================================================== */
/* Mesh build at high valence: one vertex of valence 65 536 against a grid                */

/* A closed fan (centre 0, ring 1..n, triangles (0, i, i+1)) with n = 65 536, and a
 * 128 x 256 quad grid split into the same number of triangles (65 536, so the same corner
 * count). The builder is O(corners), so the two build times should be about equal (the
 * ratio fan/grid near 1); an O(valence^2) builder takes seconds on the fan. */
#define FAN_VALENCE 65536u
#define GRID_NX 128u
#define GRID_NY 256u

static int fan_build_case(const char *what, build_ctx *bc, double *ns)
{
    uint32_t plan = 0;
    void *mem = NULL;
    int runs = 0, st = subd_mesh_plan(&bc->fl, &plan);
    if (st == SUBD_OK) {
        mem = host_arena_alloc(&bc->arena, plan);
        if (!mem) st = SUBD_ERR_NOMEM;
    }
    if (st == SUBD_OK) st = op_build(bc);
    if (st == SUBD_OK && bc->arena.peak > plan) st = SUBD_ERR_NOMEM;
    if (st != SUBD_OK) {
        fprintf(stderr, "fanbuild: %s: %s\n", what, subd_status_str(st));
        free(mem);
        return 1;
    }
    *ns = measure(op_build, bc, &runs);
    printf("%-28s %8lu %8lu %8lu %10.2f %9.3f %11lu %6d\n", what, (unsigned long)bc->fl.num_verts,
           (unsigned long)bc->fl.num_faces, (unsigned long)(3u * bc->fl.num_faces),
           (3.0 * bc->fl.num_faces / 1e6) / (*ns / 1e9), *ns / 1e6, (unsigned long)plan, runs);
    fflush(stdout);
    free(mem);
    return *ns > 0.0 ? 0 : 1;
}

int section_fanbuild(void)
{
    const uint32_t n = FAN_VALENCE, gv = (GRID_NX + 1u) * (GRID_NY + 1u), gf = 2u * GRID_NX * GRID_NY;
    subd_real *pos = (subd_real *)calloc(3u * (size_t)(gv > n + 1u ? gv : n + 1u), sizeof *pos);
    uint32_t *idx = (uint32_t *)malloc(3u * (size_t)(gf > n ? gf : n) * sizeof *idx);
    build_ctx bc;
    double fan_ns = 0.0, grid_ns = 0.0;
    uint32_t i, x, y, t = 0;
    int failed = 0;
    printf("\n== mesh build at high valence; reproduce: " REPRO "\n"
           "subd_mesh_build of a closed fan (one vertex of valence %lu) and of a %lux%lu grid of split quads with the\n"
           "same corner count; ratio = fan ms / grid ms (an O(corners) builder gives about 1).\n",
           (unsigned long)n, (unsigned long)GRID_NX, (unsigned long)GRID_NY);
    printf("%-28s %8s %8s %8s %10s %9s %11s %6s\n", "mesh", "verts", "faces", "corners", "build Mc/s", "build ms",
           "arena bytes", "runs");
    if (!pos || !idx) {
        fprintf(stderr, "fanbuild: out of memory\n");
        free(pos);
        free(idx);
        return 1;
    }
    memset(&bc, 0, sizeof bc);
    for (i = 0; i < n; i++) {
        idx[3u * i] = 0;
        idx[3u * i + 1u] = 1u + i;
        idx[3u * i + 2u] = 1u + (i + 1u) % n;
    }
    bc.fl.num_verts = n + 1u;
    bc.fl.pos = pos;
    bc.fl.num_faces = n;
    bc.fl.index = idx;
    failed += fan_build_case("fan (valence 65536)", &bc, &fan_ns);
    for (y = 0; y < GRID_NY; y++)
        for (x = 0; x < GRID_NX; x++) {
            uint32_t a = y * (GRID_NX + 1u) + x, b = a + 1u, c = a + GRID_NX + 1u, d = c + 1u;
            idx[t++] = a; idx[t++] = b; idx[t++] = d;
            idx[t++] = a; idx[t++] = d; idx[t++] = c;
        }
    memset(&bc, 0, sizeof bc);
    bc.fl.num_verts = gv;
    bc.fl.pos = pos;
    bc.fl.num_faces = gf;
    bc.fl.index = idx;
    failed += fan_build_case("grid (128x256, split quads)", &bc, &grid_ns);
    if (!failed) printf("ratio fan/grid: %.2f\n", fan_ns / grid_ns);
    free(pos);
    free(idx);
    return failed;
}
