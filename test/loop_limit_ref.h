/* SPDX-License-Identifier: MIT */
/* Test fixtures of the Loop limit tests (test/loop_limit_ref.c): small face lists with sharp
 * edges and corner tags built in both arithmetics (tmesh), and, on the host, the independent
 * double-precision reference that follows one vertex through plain Loop subdivision (the
 * derivation is at the top of loop_limit_ref.c). */
#ifndef TINYSUBD_LOOP_LIMIT_REF_H
#define TINYSUBD_LOOP_LIMIT_REF_H
#include "harness.h"

#define TMV 400
#define TMF 800
#define TMS 200

typedef struct tmesh {
    uint32_t nv, nf, ns, nc;
    subd_real pos[3 * TMV];
    uint32_t idx[3 * TMF];
    uint32_t sharp[TMS][2];
    uint32_t corner[16];
} tmesh;

subd_real q10(int32_t k);
int32_t jit(uint32_t *s, int32_t r);
void tm_clear(tmesh *t);
void tm_face(tmesh *t, uint32_t a, uint32_t b, uint32_t c);
void tm_sharp(tmesh *t, uint32_t a, uint32_t b);
void tm_bipyramid(tmesh *t, uint32_t n, uint32_t seed);
void tm_grid(tmesh *t, uint32_t w, uint32_t h, uint32_t seed, int flat);
void tm_torus(tmesh *t, uint32_t n, uint32_t m, uint32_t seed);
void tm_fan(tmesh *t, uint32_t k, uint32_t seed);
int tm_build(subd_arena *a, const tmesh *t, subd_mesh *m);

#if H_HOST
#define REF_PI 3.14159265358979323846
#define REF_LEVELS 60 /* default of g_ref_levels */
enum { R_SMOOTH, R_DART, R_CREASE, R_CORNER }; /* the classes ref_limit returns */
extern int g_ref_levels; /* levels the reference follows a vertex */
double rdbl(subd_real x);
int ref_limit(const tmesh *t, uint32_t v, subd_loop_boundary rule, double *pos, double *nrm);
double ref_angle(const double *a, const double *b);
int ref_config(const tmesh *t, uint32_t v);
double v3_len(const double *a);
void v3_cross(const double *a, const double *b, double *c);
#endif

#endif
