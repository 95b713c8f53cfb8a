/* SPDX-License-Identifier: MIT */
/* Progressive interpolation, private interface between the driver and the paper's method
 * (pia.c: validation, layout, errors, the paper's iteration, the phases and the result)
 * and the accelerated method (pia_fast.c: CG, SGS-preconditioned CG, Chebyshev).
 * Paper: loop-progressive-interpolation.txt, sections 2-4; the choices are in pia.c and
 * pia_fast.c. */
#ifndef SUBD_PIA_INTERNAL_H
#define SUBD_PIA_INTERNAL_H
#include "subd.h"
#include "loop_internal.h"
#include "vec3w.h" /* subd_dist_sq, subd_w3_dist2, subd_w3_dist_root */

#define PIA_STALL 10u         /* iterations without a new minimum that end a phase        */
#define PIA_TOL_MIN_LSB 2     /* Q16.16: smallest accepted tol, in units of 2^-16         */
#define PIA_MAX_VALENCE 4096u /* larger valences get this valence's CG weight             */
#define PIA_WCACHE 20u        /* CG weights of valences below this are computed once      */

/* Vertex classes (FAST), mirroring loop_limit.c's classification by sharp edges; a curve
 * vertex that is regular (loop_rules.h) also carries PIA_CLS_REGULAR, which picks its limit
 * masks (subd_loop_limit_curve_frac). pia_cls() is the class without the flag. */
enum { PIA_CLS_FIXED = 0, PIA_CLS_CURVE = 1, PIA_CLS_SMOOTH = 2, PIA_CLS_MASK = 3, PIA_CLS_REGULAR = 4 };

/* Vertex sets a phase moves and measures. */
enum { PIA_SET_ALL, PIA_SET_BOUNDARY, PIA_SET_INTERIOR, PIA_SET_CURVE, PIA_SET_SMOOTH, PIA_SET_MOVABLE };

/* Why the #if: the errors and the CG inner products are computed exactly in integers in
 * Q16.16 (no float in the fixed build; see "Arithmetic" above), in float32 as plain sums. */
typedef subd_dist_sq pia_sq; /* squared distance (vec3w.h) */
#if SUBD_FIXED
/* A weighted dot product: the 128-bit two's complement integer (hi, lo) times 2^e. */
typedef struct pia_dotv {
    uint64_t lo;
    int64_t hi;
    int32_t e;
} pia_dotv;
#else
typedef float pia_dotv;
#endif

typedef struct pia_state {
    const subd_mesh *m;
    const subd_pia_opts *o;
    subd_real *v;   /* control points being improved                                    */
    subd_real *lv;  /* L v: exact when lv_true, else only on the current phase's set     */
    subd_real *p;   /* FAST: search direction (0 outside the phase's set)                */
    subd_real *q;   /* FAST: L p                                                         */
    subd_real *w;   /* FAST: CG inner-product weight per vertex                          */
    subd_real *pt;  /* FAST, SGS: K' p (the Eisenstat companion of p)                     */
    subd_real *z;   /* FAST, SGS: y = K^-1 r                                              */
    subd_real *od;  /* FAST: off-diagonal weight chi of a smooth vertex's row of L        */
    uint8_t *cls;   /* FAST: PIA_CLS_* per vertex                                        */
    subd_real ell;  /* FAST: lower bound of L's spectrum on the movable vertices          */
    int darts;      /* FAST: some smooth vertex has one sharp edge                       */
    uint64_t half;  /* work done in half iterations (one application of L = 2)           */
    uint64_t half_bnd; /* of which the boundary phase's (subd_pia_result.boundary)      */
    uint32_t ovf;
    int lv_true;
} pia_state;

static inline uint32_t pia_cls(const pia_state *s, uint32_t v) { return s->cls[v] & (uint32_t)PIA_CLS_MASK; }

/* 1 if vertex v belongs to the set. */
static inline int pia_in_set(const pia_state *s, uint32_t v, uint32_t set)
{
    int bnd = (s->m->vert_tag[v] & SUBD_VTAG_BOUNDARY) != 0u;
    switch (set) {
    case PIA_SET_BOUNDARY: return bnd;
    case PIA_SET_INTERIOR: return !bnd;
    case PIA_SET_CURVE: return pia_cls(s, v) == PIA_CLS_CURVE;
    case PIA_SET_SMOOTH: return pia_cls(s, v) == PIA_CLS_SMOOTH;
    case PIA_SET_MOVABLE: return pia_cls(s, v) != PIA_CLS_FIXED;
    default: return 1;
    }
}

/* lv = L v, exactly. */
static inline void pia_limit(pia_state *s)
{
    subd_loop_limit_apply(s->m, s->o->boundary, s->v, s->lv, &s->ovf);
    s->lv_true = 1;
}

/* 1 if h more half iterations fit the budget of max_iter iterations. */
static inline int pia_budget(const pia_state *s, uint32_t h)
{
    return s->half + h <= 2u * (uint64_t)s->o->max_iter;
}

/* pia.c */
subd_real subd_pia_max_err(pia_state *s, uint32_t set);                      /* max |P - L V|     */
int subd_pia_stalled(subd_real err, uint32_t k, subd_real *best, uint32_t *stall);
void subd_pia_phase_paper(pia_state *s, uint32_t set);

/* pia_fast.c: SUBD_PIA_FAST from V = P with an exact lv; sets half_bnd. */
void subd_pia_fast(pia_state *s);
/* pia_fast.c, shared with pia_sgs.c: the W inner product <a - as, b - bs>_W over the set
 * (as, bs may be NULL), the ratio x / y of two of them (*ok = 0 when it does not fit
 * subd_real or y <= 0), and the end of a CG or PCG iteration (a PIA_GO_ON / PIA_DONE /
 * PIA_SAFEGUARD verdict; see its definition). */
enum { PIA_GO_ON, PIA_DONE, PIA_SAFEGUARD };
pia_dotv subd_pia_dot(const pia_state *s, uint32_t set, const subd_real *a, const subd_real *as, const subd_real *b,
                      const subd_real *bs);
subd_real subd_pia_ratio(pia_dotv x, pia_dotv y, int *ok);
int subd_pia_cg_advance(pia_state *s, uint32_t set, subd_real alpha, uint32_t halves, subd_real start,
                        subd_real *best, uint32_t *stall);
/* pia_sgs.c: the SGS-preconditioned CG phase, and 1 when every vertex of the set has the same
 * row shape (CG weight and diagonal of L: plain CG then). */
void subd_pia_phase_sgs(pia_state *s, uint32_t set);
int subd_pia_uniform(pia_state *s, uint32_t set);

#endif
