/* SPDX-License-Identifier: MIT */
/* Semi-regular 4-8 refinement, private interface between the pre-processing
 * (sr48_pre.c, paper section 5) and the binary steps, smoothing and planning
 * (sr48_refine.c, sections 4 and 6). Paper: semi-regular-4-8-refinement-box-splines.txt.
 *
 * Level -1 is the hybrid subdivision (section 5, step 2), which is never stored: hybrid
 * triangle H of input face f is fstart[f] + j (two per cluster face, three per isolated
 * face), and its base neighbour (the hybrid triangle across its base, an original edge) is
 * hnb[H], a hybrid index or SUBD_NONE. Level 0 triangles 2H and 2H + 1 are its children,
 * exactly as every later level's triangles are children of the level before, so one binary
 * step function and one smoothing function serve the pre-processing step and all later
 * steps: they take the parent level's base neighbours as (array, index of its first
 * triangle). */
#ifndef SUBD_SR48_INTERNAL_H
#define SUBD_SR48_INTERNAL_H
#include "subd.h"
#include "edge_sort.h"
#include "layout.h"   /* subd_layout: the count-or-carve walks below */
#include "real_avg.h" /* subd_sum, subd_avg, subd_mid: the rounding averages */

#define SR48_DIAG 0xfffffffeu  /* sel[e]: the edge is a cluster diagonal                  */
#define SR48_BFLAG 0x80000000u /* sums count: the vertex is on the boundary of the step   */

/* Counts and bytes of one build, from the input, the options and the cluster count. */
typedef struct sr48_layout {
    uint32_t steps, smooth;
    uint32_t keep;   /* the base mesh: keep the hybrid level's base neighbours (hnb)        */
    uint32_t nf, ne, clusters, isolated;
    uint32_t nhyb;   /* hybrid triangles 4C + 3I                                           */
    uint32_t nv_hyb; /* vertices before the edge points: V + C + I                         */
    uint32_t level_verts[SUBD_SR48_MAX_STEPS + 1];
    uint32_t level_tri[SUBD_SR48_MAX_STEPS + 2];
    uint32_t out_bytes; /* pos, tri_vert, tri_base_nb                                      */
    uint32_t a_bytes;   /* find_clusters: edge numbering and sort                          */
    uint32_t b_bytes;   /* hybrid subdivision, level 0 and its smoothing, step 0 -> 1       */
    uint32_t s_bytes;   /* largest smoothing sums of a later double step                   */
    uint32_t c_bytes;   /* the base mesh: the census of its level-0 windows (sr48_census.c) */
    uint32_t bytes;     /* the plan: out + max(a, b, s, c)                                 */
} sr48_layout;

/* Pre-processing working memory (sr48_pre.c). */
typedef struct sr48_pre {
    subd_edge_work es;
    uint32_t *sel;    /* per edge: SR48_DIAG or its edge point                              */
    uint32_t *fstart; /* per face: its first hybrid triangle                                */
    uint32_t *fpt;    /* per face: its face point                                           */
    uint32_t *hnb;    /* per hybrid triangle: base neighbour (hybrid index) or SUBD_NONE     */
} sr48_pre;

/* Per-vertex smoothing sums. */
typedef struct sr48_sums {
    subd_sum *s;   /* 3 per vertex                                                         */
    uint32_t *cnt; /* per vertex: number of summed neighbours | SR48_BFLAG                 */
} sr48_sums;

/* Phase A (find_clusters) and phase B (hybrid subdivision) memory: layout functions
 * (layout.h), so with a == NULL only *bytes is computed (w may be NULL). Phase B allocates
 * on top of phase A's first three arrays (edge_of, edge_he, sel: *keep bytes), which stay. */
int subd_sr48_pre_alloc_a(subd_arena *a, const subd_mesh *in, sr48_pre *w, uint32_t *bytes, uint32_t *keep);
int subd_sr48_pre_alloc_b(subd_arena *a, const sr48_layout *L, sr48_pre *w, uint32_t *bytes);

/* find_clusters (section 5, Algorithm 1): numbers and sorts the edges and selects the
 * cluster diagonals (sel[e] != SUBD_NONE). Returns SUBD_OK (count in *clusters) or
 * SUBD_ERR_PARAM when the mesh's edge count is inconsistent. */
int subd_sr48_find_clusters(const subd_mesh *in, sr48_pre *w, uint32_t *clusters);

/* Hybrid subdivision and the first binary step: level 0 triangles, base neighbours and the
 * positions of the input vertices, face points and edge points (before smoothing), and
 * hnb. Needs find_clusters' result in w. */
int subd_sr48_level0(const subd_mesh *in, const sr48_layout *L, sr48_pre *w, subd_sr48 *h);

/* One binary step level k -> k+1 (k < steps): children, new vertices, base neighbours of
 * level k+1. pnb/pbase: base neighbours of level k-1 (hnb, 0 for k = 0). */
int subd_sr48_step(subd_sr48 *h, uint32_t k, const uint32_t *pnb, uint32_t pbase, int smooth);

/* Smoothing of the vertices older than level k (k even) by the neighbours level k's step
 * created; pnb/pbase as above for level k-1, nold the number of older vertices. */
int subd_sr48_smooth(subd_sr48 *h, uint32_t k, const uint32_t *pnb, uint32_t pbase, uint32_t nold,
                     const sr48_sums *s);

/* Adaptive cuts (sr48_adapt.c, subd_sr48_extract's adaptation geometry), shared with the
 * stream (sr48_stream.c): the mode's parameter check (SUBD_OK or SUBD_ERR_PARAM), and the nested-region decision of POINT,
 * RAMP, PLANE and CALLBACK for a diamond of level k < max_level whose region box is (lo, hi)
 * (radius: POINT's, resolved; rlo, rhi: RAMP's bounding box). */
int subd_sr48_adapt_check_(const subd_sr48_adapt *ad);
int subd_sr48_box_wants_(const subd_sr48_adapt *ad, subd_real radius, const subd_real *rlo, const subd_real *rhi,
                         const subd_real *lo, const subd_real *hi, uint32_t k);
/* The adaptation box of RAMP and POINT's default radius (subd_sr48_adapt_mode): the box of the
 * finest positions of the level-0 triangles' corners. box_grow grows (blo, bhi) by the n
 * points pos + 3 idx[i] (reset to empty first when init); default_radius is POINT's radius
 * from that box for max_level max > 0. */
void subd_sr48_box_grow_(const subd_real *pos, const uint32_t *idx, uint32_t n, subd_real *blo, subd_real *bhi,
                         int init);
subd_real subd_sr48_default_radius_(const subd_real *blo, const subd_real *bhi, uint32_t max);

/* The chordal test (sr48_chord.c), one home for subd_sr48_extract's and the stream's: the
 * linear interpolant of a triangle's corners at a dyadic point, Q32.32 in Q16.16 (so 16
 * halvings are exact) and float in float32, and |P - L| > eps on it. */
#if SUBD_FIXED /* the representation differs: Q16.16 keeps the interpolant in Q32.32 */
typedef int64_t subd_sr48_lin;
#else
typedef float subd_sr48_lin;
#endif
#if SUBD_FIXED
static inline subd_sr48_lin subd_sr48_lin_of_(subd_real x) { return (int64_t)x * 65536; }
static inline subd_sr48_lin subd_sr48_lin_mid_(subd_sr48_lin a, subd_sr48_lin b) { return (a + b) >> 1; }
#else
static inline subd_sr48_lin subd_sr48_lin_of_(subd_real x) { return x; }
static inline subd_sr48_lin subd_sr48_lin_mid_(subd_sr48_lin a, subd_sr48_lin b) { return (a + b) * 0.5f; }
#endif

/* |P - L| > eps (subd_sr48_extract's CHORD and the stream's). Inline: the innermost loop of
 * every chordal test; a file that includes this header includes fp_contract.h first. */
static inline int subd_sr48_beyond_(const subd_real *p, const subd_sr48_lin *l, subd_real eps)
{
#if SUBD_FIXED /* the algorithm differs: Q32.32 differences, an early exit keeps the squares in 64 bits */
    uint64_t sum = 0, e = (uint64_t)eps;
    uint32_t i;
    for (i = 0; i < 3u; i++) {
        int64_t d = ((int64_t)p[i] * 65536 - l[i] + 32768) >> 16;
        uint64_t ad = (uint64_t)(d < 0 ? -d : d);
        if (ad > e) return 1;
        sum += ad * ad;
    }
    return sum > e * e;
#else
    float d0 = p[0] - l[0], d1 = p[1] - l[1], d2 = p[2] - l[2];
    float s0 = d0 * d0, s1 = d1 * d1, s2 = d2 * d2;
    return s0 + s1 + s2 > eps * eps;
#endif
}

/* Chordal cuts of the stream (sr48_chord.c): is finest position p farther than eps from
 * L_d(v), the linear interpolant of ancestor triangle d (corners c: apex, b0, b1, 9 reals)
 * at the vertex v created by splitting d's descendant reached by n child steps (bit s of
 * path: the child taken at step s, 0 = (m; apex, b0), 1 = (m; b1, apex))? n = 0: v is d's
 * own new vertex (the midpoint of its base). 1 beyond, 0 within. */
int subd_sr48_chord_beyond_(const subd_real *c, uint32_t path, uint32_t n, const subd_real *p, subd_real eps);

/* The census of the base's level-0 windows (sr48_census.c): its scratch bytes, and the
 * valence the stream sizes its windows with (0 when the arena lacks the scratch). */
uint32_t subd_s48_census_bytes_(uint32_t nv0, uint32_t nt0);
uint32_t subd_s48_census_(subd_arena *a, const subd_sr48 *b);
/* The fan of base vertex x from base triangle t (sr48_window.c): its triangles into out (at
 * most cap), their count, or UINT32_MAX beyond cap. */
uint32_t subd_s48_fan_(const subd_sr48 *b, uint32_t x, uint32_t t, uint32_t *out, uint32_t cap);

#endif
