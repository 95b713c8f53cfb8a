/* SPDX-License-Identifier: MIT */
/* The host benchmark's shared pieces (bench/bench.c: measurement, scheme runs, bench meshes,
 * main; the sections in bench_build.c, bench_loop.c, bench_48.c, bench_misc.c). Host only:
 * malloc, stdio and libm are fine here (never part of the library). */
#ifndef TINYSUBD_BENCH_H
#define TINYSUBD_BENCH_H
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include "subd.h"
#include "fileio.h"
#include "cortex-m/demo_mesh.h" /* the firmware demo's streaming mesh and checksum */
#include "../src/text.h"          /* subd_q16_format: the Q16.16 formatter, int32 code */

#define DEFAULT_DIR "../shared/data/meshes/bench"
#define MIN_RUNS 5
#define MAX_RUNS 100000
#define MAX_FILES 64
#define PLAN_LIMIT 1500000000.0  /* skip a case whose arena plan exceeds ~1.5 GB          */
#define OUT_LIMIT 2147483648.0   /* ... or whose output would exceed 2^31 bytes           */
#define REPRO "make bench"

#if SUBD_FIXED
#define ARITHMETIC "q16.16"
#define R2D(x) ((double)(x) / 65536.0)
#define D2R(x) ((subd_real)lround((x) * 65536.0))
#else
#define ARITHMETIC "float32"
#define R2D(x) ((double)(x))
#define D2R(x) ((subd_real)(x))
#endif

extern double g_seconds; /* -t: seconds per measurement */

typedef int (*bench_op)(void *ctx);
/* Runs op() repeatedly for about g_seconds; the median nanoseconds of one run (< 0: op failed). */
double measure(bench_op op, void *ctx, int *runs_out);
const char *base_name(const char *path);

typedef enum run_kind { RUN_LOOP, RUN_LIMIT, RUN_Q48, RUN_CURVE, RUN_SURF, RUN_PIA, RUN_SR48, RUN_SR48X, RUN_STREAM } run_kind;

typedef struct run_ctx {
    run_kind kind;
    const subd_mesh *in;
    subd_arena arena;
    void *mem;
    uint32_t plan;
    subd_diag diag;
    subd_mesh out;
    subd_loop_opts lo;
    subd_quasi48_opts qo;
    subd_alpha_opts ao;
    subd_pia_opts po;
    subd_pia_result pr;
    subd_real *lpos, *lnrm, *ppos;
    const subd_real *cpos; /* curve input */
    uint32_t cm;
    subd_alpha_curve_out co;
    subd_sr48_opts so;     /* RUN_SR48: build the hierarchy                                */
    subd_sr48 h;           /* RUN_SR48X: extract from this hierarchy (built once, below)   */
    subd_sr48_adapt ad;
    subd_sr48_adapt_report rep;
    uint32_t xmark;        /* RUN_SR48X: arena mark above the hierarchy                    */
    subd_loop_sink sink;   /* RUN_STREAM: subd_loop_stream with lo into the checksum sink  */
    demo_hash hash;
} run_ctx;

int op_run(void *p);
int run_plan(run_ctx *c);
int run_first(run_ctx *c, const char *label, double *first_ns);
double time_run(run_ctx *c, double first_ns, int *runs);
void run_free(run_ctx *c);
const char *peak_str(const run_ctx *c, char *buf, size_t n);

typedef struct bmesh {
    char name[80];
    const char *path;
    host_mesh hm;
    int tri;     /* all faces are triangles */
    int closed;  /* no boundary edge */
    double diag; /* bounding-box diagonal */
} bmesh;
extern bmesh g_mesh[MAX_FILES];
extern int g_nmesh;
bmesh *find_mesh(const char *name);
uint32_t max_valence(const subd_mesh *m); /* largest vertex valence (mesh with adjacency) */
int stepped_case(run_ctx *c, const char *name, uint32_t steps, double *ns, int *runs);

/* The sections (each prints its table; the int ones return the count of failures). */
int bench_file(const char *path);
int section_fanbuild(void);
void section_loop(void);
void section_stream(void);
int section_demostream(void);
void section_limit(void);
void section_q48(void);
void section_valence48(void);
void section_sr48(void);
void section_sr48stream(void);
void section_sr48chord(void);
int section_sr48table(void);
void section_alpha(void);
void section_quality(void);
void section_pia(void);
void section_format(void);

#endif
