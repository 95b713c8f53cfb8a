/* SPDX-License-Identifier: MIT */
/* Loop subdivision's rules, written once (private; paper: loop-progressive-interpolation.txt,
 * section 1 for the scheme, section 4 for the boundary rules; Hoppe et al. 1994 for creases
 * and corners). Used by loop.c (subdivision), loop_limit.c (limit positions and normals),
 * pia.c (progressive interpolation) and loop_stream.c (the streaming form), so the four
 * classify a vertex the same way and sum a stencil in the same order (OpenSubdiv keeps one
 * vertex-rule function in Sdc for the same reason).
 *
 * Classification (Hoppe et al. 1994, by the number of sharp edges at the vertex; sharp edges
 * are boundary edges and edges tagged SUBD_ETAG_CREASE on either half: topo_edge_sharp): 0 smooth, 1 dart
 * (smooth rule), 2 crease (crease rule with its two sharp neighbours), 3 or more corner
 * (fixed); SUBD_VTAG_CORNER forces corner. "Regular", for the paper's 5/8-3/8 sharp-edge
 * rule: a crease vertex that looks like the ones refinement creates: valence 4 on a boundary
 * (the paper); inside, valence 6 with its two sharp edges opposite (three faces on each
 * side; Hoppe's regular crease vertex). Darts, corners and every other crease vertex are
 * extraordinary. A ring is walked from vert_out rotating counter-clockwise; on a boundary
 * the last neighbour is the origin of the incoming boundary half-edge, at position n - 1.
 *
 * The position rules are static inline so the hot loops of loop.c pay no call; each fixes
 * the order of its weighted sum (it matters in float32: a bit-identical stream must add the
 * same products in the same order). Every rule is a convex combination: Q16.16 weights are
 * non-negative and sum to exactly 2^16 and the sum is exact in 64 bits, so a result never
 * leaves the range of its inputs (the overflow flag is still passed on); in float32 it can
 * overflow only when a sum near FLT_MAX rounds to infinity. */
#ifndef SUBD_LOOP_RULES_H
#define SUBD_LOOP_RULES_H
#include "subd.h"
#include "topo.h"

/* On a level loop.c made, both halves of an edge carry the same bits and BOUNDARY marks
 * exactly the edges without twin, so there topo_edge_sharp is the test of one byte. */
#define LOOP_ETAG_SHARP (SUBD_ETAG_BOUNDARY | SUBD_ETAG_CREASE)

/* Vertex tag bits 0x40 and 0x80 are the library's (subd.h: keep them 0); their meanings are
 * in topo.h's one table: loop.c marks its intermediate levels' classes with them, and
 * loop_stream.c's patch views (a level-L 1-ring whose outer vertices lack whole rings) give
 * an outer vertex's class with them: LOOP_VTAG_KNOWN set means "regular is
 * LOOP_VTAG_REGULAR, do not walk the ring". */
#define LOOP_VTAG_KNOWN TOPO_VTAG_KNOWN
#define LOOP_VTAG_REGULAR TOPO_VTAG_REGULAR
#define LOOP_VTAG_PRIVATE TOPO_VTAG_PRIVATE

/* SUBD_OK when no vertex of m uses the library's private tag bits, else SUBD_ERR_PARAM with
 * d->vertex (d may be NULL). For the public calls that take a caller's mesh. */
int subd_loop_tags_public(const subd_mesh *m, subd_diag *d);

/* Vertex classes. */
enum { LOOP_ISOLATED, LOOP_SMOOTH, LOOP_DART, LOOP_CREASE, LOOP_CORNER };

/* A classified vertex. */
typedef struct loop_vinfo {
    uint32_t cls;      /* LOOP_*                                                          */
    uint32_t valence;  /* number of neighbours (faces + 1 on a boundary)                  */
    uint32_t c0, c1;   /* LOOP_CREASE: the two neighbours along sharp edges, in ring order */
    uint32_t i0, i1;   /* their positions in the ring (0 .. valence-1)                    */
    uint32_t boundary; /* 1 on a boundary                                                 */
    uint32_t nsharp;   /* number of sharp edges                                           */
    uint32_t regular;  /* 1: a regular crease vertex (see above)                          */
} loop_vinfo;

/* The class from the number of sharp edges and the caller's CORNER tag. */
static inline uint32_t loop_class_of(uint32_t nsharp, int corner_tag)
{
    if (corner_tag || nsharp >= 3u) return LOOP_CORNER;
    return nsharp == 0u ? LOOP_SMOOTH : nsharp == 1u ? LOOP_DART : LOOP_CREASE;
}

/* Regular crease vertex: valence n, boundary flag, ring positions i0 < i1 of its sharp
 * neighbours. */
static inline uint32_t loop_regular_of(uint32_t cls, uint32_t n, uint32_t boundary, uint32_t i0, uint32_t i1)
{
    if (cls != LOOP_CREASE) return 0;
    return boundary ? n == 4u : (n == 6u && i1 - i0 == 3u);
}

/* Classifies vertex v of a triangle or polygon mesh with adjacency by walking its ring once
 * (bounded by num_corners whatever the input). */
void subd_loop_classify(const subd_mesh *m, uint32_t v, loop_vinfo *o);

/* The same from a walk r already begun at a non-isolated vertex (loop.c's levels, which carry
 * no face_start: topo_ring_begin_tri), with edge tags etag and the vertex's CORNER tag; *hmin
 * (if not NULL) gets the smallest outgoing half-edge (loop.c's vert_out choice). */
void subd_loop_classify_ring(topo_ring *r, const uint8_t *etag, int corner_tag, loop_vinfo *o, uint32_t *hmin);

/* ------------------------------------------------------------------------------------ */
/* Weights                                                                                */

/* n b(n) = 5/8 - (3/8 + 1/4 cos(2 pi / n))^2 in Q2.62 (Loop's beta times n), n >= 1, from
 * the deterministic cos of trig.c in 64-bit integers. In [15/64, 5/8]. */
uint64_t subd_loop_nbeta_q62(uint32_t n);

/* Neighbour weight b and centre weight 1 - n b of the smooth rule for valence n. b is
 * n b(n) / n rounded once to subd_real; wc is ONE - n b in subd_real, so in Q16.16 the weights
 * sum to exactly ONE (constants are reproduced exactly). Exact at n = 3, 4, 6. */
typedef struct loop_weights {
    subd_real b, wc;
} loop_weights;

#define LOOP_WCACHE 16u /* weights kept for n < LOOP_WCACHE during one call */
typedef struct loop_wcache {
    loop_weights w[LOOP_WCACHE];
    uint32_t have; /* bit n: w[n] is valid; set to 0 before first use */
} loop_wcache;

/* The weights of valence n, cached for n < LOOP_WCACHE (no overflow is possible there, so
 * the cache drops no flag). */
loop_weights subd_loop_weights_of(loop_wcache *c, uint32_t n, uint32_t *ovf);

/* ------------------------------------------------------------------------------------ */
/* Position rules (each coordinate: the products in the order written, summed left to right)*/

/* Interior edge: 3/8 (a + b) + 1/8 c + 1/8 d, with a -> b the edge's lower half-edge, c the
 * opposite vertex in its face and d the one in the twin's face. */
/* One coordinate of it (loop_tile.c unrolls the three). */
static inline subd_real loop_rule_edge1(subd_real a, subd_real b, subd_real c, subd_real d, uint32_t *ovf)
{
    subd_acc acc = subd_acc_add(subd_acc_zero(), SUBD_REAL_FRAC(3, 8), a);
    acc = subd_acc_add(acc, SUBD_REAL_FRAC(3, 8), b);
    acc = subd_acc_add(acc, SUBD_REAL_FRAC(1, 8), c);
    acc = subd_acc_add(acc, SUBD_REAL_FRAC(1, 8), d);
    return subd_acc_real(acc, ovf);
}
static inline void loop_rule_edge(subd_real *out, const subd_real *xa, const subd_real *xb, const subd_real *xc,
                                  const subd_real *xd, uint32_t *ovf)
{
    uint32_t j;
    for (j = 0; j < 3u; j++) out[j] = loop_rule_edge1(xa[j], xb[j], xc[j], xd[j], ovf);
}

/* Sharp edge a -> b (a: the lower half-edge's origin), ends regular ra, rb: the midpoint, or
 * for the paper's rule with one regular end 5/8 regular + 3/8 extraordinary. */
static inline void loop_rule_sharp_edge(subd_real *out, const subd_real *xa, const subd_real *xb,
                                        subd_loop_boundary rule, uint32_t ra, uint32_t rb, uint32_t *ovf)
{
    subd_real wa = SUBD_REAL_FRAC(1, 2), wb = SUBD_REAL_FRAC(1, 2);
    uint32_t j;
    if (rule == SUBD_LOOP_BOUNDARY_PAPER && ra != rb) {
        wa = ra ? SUBD_REAL_FRAC(5, 8) : SUBD_REAL_FRAC(3, 8);
        wb = rb ? SUBD_REAL_FRAC(5, 8) : SUBD_REAL_FRAC(3, 8);
    }
    for (j = 0; j < 3u; j++) {
        subd_acc acc = subd_acc_add(subd_acc_zero(), wa, xa[j]);
        acc = subd_acc_add(acc, wb, xb[j]);
        out[j] = subd_acc_real(acc, ovf);
    }
}

/* Crease (or boundary) vertex v with sharp neighbours c0, c1 in ring order:
 * 3/4 v + 1/8 c0 + 1/8 c1. */
static inline void loop_rule_crease(subd_real *out, const subd_real *pv, const subd_real *x0, const subd_real *x1,
                                    uint32_t *ovf)
{
    uint32_t j;
    for (j = 0; j < 3u; j++) {
        subd_acc acc = subd_acc_add(subd_acc_zero(), SUBD_REAL_FRAC(3, 4), pv[j]);
        acc = subd_acc_add(acc, SUBD_REAL_FRAC(1, 8), x0[j]);
        acc = subd_acc_add(acc, SUBD_REAL_FRAC(1, 8), x1[j]);
        out[j] = subd_acc_real(acc, ovf);
    }
}

/* Smooth (and dart) vertex: (1 - n b) v + b p_0 + ... + b p_(n-1), the ring in walk order:
 * begin with v, add each neighbour, end. */
static inline void loop_smooth_begin(subd_acc acc[3], loop_weights w, const subd_real *pv)
{
    acc[0] = subd_acc_add(subd_acc_zero(), w.wc, pv[0]);
    acc[1] = subd_acc_add(subd_acc_zero(), w.wc, pv[1]);
    acc[2] = subd_acc_add(subd_acc_zero(), w.wc, pv[2]);
}
static inline void loop_smooth_add(subd_acc acc[3], loop_weights w, const subd_real *q)
{
    acc[0] = subd_acc_add(acc[0], w.b, q[0]);
    acc[1] = subd_acc_add(acc[1], w.b, q[1]);
    acc[2] = subd_acc_add(acc[2], w.b, q[2]);
}
static inline void loop_smooth_end(subd_real *out, const subd_acc acc[3], uint32_t *ovf)
{
    out[0] = subd_acc_real(acc[0], ovf);
    out[1] = subd_acc_real(acc[1], ovf);
    out[2] = subd_acc_real(acc[2], ovf);
}
#endif
