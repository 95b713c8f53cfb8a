/* SPDX-License-Identifier: MIT */
/* tinysubd driver for the peer comparison (bench/peers): DRIVER loop|doosabin|stream MESH.obj LEVELS
 * Reads the OBJ with subd_obj_plan + subd_obj_read into an arena of exactly the plan (untimed),
 * then times one call: subd_loop (boundary PAPER, flags 0), subd_alpha_surface
 * (subd_alpha_opts_default: B-spline kernel, stiffness 1 = Doo-Sabin type, order 2) or
 * subd_loop_stream (boundary PAPER, flags 0) into a checksum sink (32-bit FNV-1a over the
 * little-endian bytes of every emitted position coordinate, as port/cortex-m/demo_mesh.h), in a
 * second arena of exactly subd_loop_plan / subd_alpha_surface_plan / subd_loop_stream_plan
 * bytes. Prints one machine-readable line like the C++ peer drivers; arena_bytes = input mesh
 * + plan. The stream's line says peer=tinysubd-stream scheme=loop, faces = triangles emitted,
 * verts=0 (the stream stores none), and adds hash=. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <sys/resource.h>
#include "subd.h"
#include "subd_alpha.h"

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static double cpu_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static long rss_kb(void)
{
    long pages = 0, resident = 0;
    FILE *f = fopen("/proc/self/statm", "r");
    if (f) {
        if (fscanf(f, "%ld %ld", &pages, &resident) != 2) resident = 0;
        fclose(f);
    }
    return resident * 4;
}

static void *xmalloc(size_t n)
{
    void *p = malloc(n ? n : 1);
    if (!p) { fprintf(stderr, "out of memory (%lu bytes)\n", (unsigned long)n); exit(1); }
    return p;
}

typedef struct hash_sink {
    uint32_t h;
    unsigned long tris;
} hash_sink;

static int hash_tri(void *ctx, const subd_loop_tri *t)
{
    hash_sink *s = (hash_sink *)ctx;
    uint32_t h = s->h, c, k, b;
    for (c = 0; c < 3u; c++)
        for (k = 0; k < 3u; k++) {
            uint32_t w = subd_real_bits(t->pos[c][k]);
            for (b = 0; b < 4u; b++) {
                h ^= (w >> (8u * b)) & 0xffu;
                h *= 16777619u;
            }
        }
    s->h = h;
    s->tris++;
    return 0;
}

static void fail(const char *what, int st, const subd_diag *d)
{
    fprintf(stderr, "%s: %s (%d), line %lu, bytes_needed %lu\n", what, subd_status_str(st), st,
            (unsigned long)d->line, (unsigned long)d->bytes_needed);
    exit(1);
}

int main(int argc, char **argv)
{
    int loop, stream, levels;
    hash_sink hs;
    FILE *f;
    long len;
    char *text;
    uint32_t obj_bytes = 0, plan = 0;
    subd_arena in_arena, out_arena;
    subd_mesh in, out;
    subd_diag d;
    const char *name, *dot;
    int st, name_len;
    long rss_before;
    double t0, t1, c0 = 0.0, c1 = 0.0;
    struct rusage ru;

    if (argc != 4) { fprintf(stderr, "usage: %s loop|doosabin|stream MESH.obj LEVELS\n", argv[0]); return 2; }
    loop = strcmp(argv[1], "loop") == 0;
    stream = strcmp(argv[1], "stream") == 0;
    if (!loop && !stream && strcmp(argv[1], "doosabin") != 0) { fprintf(stderr, "unknown scheme %s\n", argv[1]); return 2; }
    hs.h = 2166136261u;
    hs.tris = 0;
    levels = atoi(argv[3]);
    f = fopen(argv[2], "rb");
    if (!f) { fprintf(stderr, "cannot open %s\n", argv[2]); return 1; }
    fseek(f, 0, SEEK_END);
    len = ftell(f);
    fseek(f, 0, SEEK_SET);
    text = (char *)xmalloc((size_t)len);
    if (fread(text, 1, (size_t)len, f) != (size_t)len) { fprintf(stderr, "read error\n"); return 1; }
    fclose(f);

    subd_diag_clear(&d);
    st = subd_obj_plan(text, (uint32_t)len, &obj_bytes, &d);
    if (st != SUBD_OK) fail("subd_obj_plan", st, &d);
    subd_arena_init(&in_arena, xmalloc(obj_bytes + SUBD_ARENA_ALIGN), obj_bytes + SUBD_ARENA_ALIGN);
    st = subd_obj_read(&in_arena, text, (uint32_t)len, &in, &d);
    if (st != SUBD_OK) fail("subd_obj_read", st, &d);
    free(text);

    if (stream) {
        subd_loop_opts o;
        subd_loop_sink sink;
        o.levels = (uint32_t)levels;
        o.boundary = SUBD_LOOP_BOUNDARY_PAPER;
        o.flags = 0;
        sink.tri = hash_tri;
        sink.ctx = &hs;
        st = subd_loop_stream_plan(&in, &o, &plan, 0);
        if (st != SUBD_OK) fail("subd_loop_stream_plan", st, &d);
        subd_arena_init(&out_arena, xmalloc((size_t)plan + SUBD_ARENA_ALIGN), plan + SUBD_ARENA_ALIGN);
        rss_before = rss_kb();
        c0 = cpu_s();
        t0 = now_s();
        st = subd_loop_stream(&out_arena, &in, &o, &sink, &d);
        t1 = now_s();
        c1 = cpu_s();
        if (st != SUBD_OK) fail("subd_loop_stream", st, &d);
        out.num_faces = (uint32_t)hs.tris;
        out.num_verts = 0;
    } else if (loop) {
        subd_loop_opts o;
        o.levels = (uint32_t)levels;
        o.boundary = SUBD_LOOP_BOUNDARY_PAPER;
        o.flags = 0;
        st = subd_loop_plan(&in, &o, &plan, 0);
        if (st != SUBD_OK) fail("subd_loop_plan", st, &d);
        subd_arena_init(&out_arena, xmalloc((size_t)plan + SUBD_ARENA_ALIGN), plan + SUBD_ARENA_ALIGN);
        rss_before = rss_kb();
        c0 = cpu_s();
        t0 = now_s();
        st = subd_loop(&out_arena, &in, &o, &out, &d);
        t1 = now_s();
        c1 = cpu_s();
        if (st != SUBD_OK) fail("subd_loop", st, &d);
    } else {
        subd_alpha_opts o;
        subd_alpha_opts_default(&o);
        o.levels = (uint32_t)levels;
        st = subd_alpha_surface_plan(&in, &o, &plan, 0);
        if (st != SUBD_OK) fail("subd_alpha_surface_plan", st, &d);
        subd_arena_init(&out_arena, xmalloc((size_t)plan + SUBD_ARENA_ALIGN), plan + SUBD_ARENA_ALIGN);
        rss_before = rss_kb();
        c0 = cpu_s();
        t0 = now_s();
        st = subd_alpha_surface(&out_arena, &in, &o, &out, NULL, &d);
        t1 = now_s();
        c1 = cpu_s();
        if (st != SUBD_OK) fail("subd_alpha_surface", st, &d);
    }
    if (out_arena.peak > plan) fprintf(stderr, "warning: arena peak %lu > plan %lu\n",
                                       (unsigned long)out_arena.peak, (unsigned long)plan);

    name = strrchr(argv[2], '/');
    name = name ? name + 1 : argv[2];
    dot = strrchr(name, '.');
    name_len = dot ? (int)(dot - name) : (int)strlen(name);
    getrusage(RUSAGE_SELF, &ru);
    printf("peer=%s scheme=%s mesh=%.*s level=%d faces=%lu verts=%lu wall_seconds=%.6f "
           "cpu_seconds=%.6f maxrss_kb=%ld rss_before_kb=%ld arena_bytes=%lu plan_bytes=%lu",
           stream ? "tinysubd-stream" : "tinysubd", loop || stream ? "loop" : "doosabin", name_len, name, levels,
           stream ? hs.tris : (unsigned long)out.num_faces, (unsigned long)out.num_verts, t1 - t0, c1 - c0,
           ru.ru_maxrss, rss_before, (unsigned long)in_arena.used + (unsigned long)plan, (unsigned long)plan);
    if (stream) printf(" hash=0x%08lx", (unsigned long)hs.h);
    printf("\n");
    return 0;
}
