/* SPDX-License-Identifier: MIT */
/* Adaptive extraction from the semi-regular 4-8 hierarchy (paper:
 * semi-regular-4-8-refinement-box-splines.txt, sections 3 and 7), private interface between
 * the cut (sr48_extract.c: parameters, lazy validation, marks, forced splits, output) and
 * the adaptation geometry (sr48_adapt.c: the modes' parameter rules, the nested star box,
 * the POINT/RAMP/PLANE/CALLBACK predicates, the CHORD walk). Shared: the extraction's
 * context, the mark bits and the lazy validation ex_ok, static inline here because the
 * geometry calls it for every triangle it reads (its fast path is one mark test). */
#ifndef SUBD_SR48_EXTRACT_INTERNAL_H
#define SUBD_SR48_EXTRACT_INTERNAL_H
#include "subd.h"
#include "subd_sr48.h"
#include "sr48_internal.h"

#define EX_SPLIT 0x1u
#define EX_WANT 0x2u
#define EX_OK 0x4u /* subd_sr48_ex_check_tri_ passed (lazy validation, see ex_ok) */

/* A node of the chordal-deviation walk: the triangle, its level and the linear
 * interpolant of the walk's root at its three corners (apex, b0, b1). The arena reserves
 * EX_CNODE_BYTES per node in both arithmetics so the plan does not depend on the build. */
typedef subd_sr48_lin ex_lin; /* sr48_internal.h: Q32.32 in Q16.16 */
typedef struct ex_cnode {
    uint32_t tri, level;
    ex_lin l[9];
} ex_cnode;
#define EX_CNODE_BYTES 80u
typedef char ex_cnode_fits[(sizeof(ex_cnode) <= EX_CNODE_BYTES) ? 1 : -1];


typedef struct ex_ctx {
    const subd_sr48 *h;
    const subd_sr48_adapt *ad;
    uint32_t max, uniform;
    uint8_t *mark;
    uint32_t *work;    /* worklist, then per-vertex used flags                          */
    uint32_t *fstack;  /* force_split stack, max + 1 entries                            */
    ex_cnode *cstack;  /* CHORD walk stack, max + 1 entries                             */
    uint32_t qtail;
    uint32_t forced;
    int bad;           /* a visited triangle broke the index rules: stop, SUBD_ERR_PARAM */
    subd_real lo[3], hi[3];
    subd_real radius;
} ex_ctx;

/* The cut (sr48_extract.c): triangle t of level k against the hierarchy's index rules
 * (SUBD_OK or SUBD_ERR_PARAM). */
int subd_sr48_ex_check_tri_(const subd_sr48 *h, uint32_t t, uint32_t k, uint32_t max);

/* Lazy validation (adaptive modes): a triangle's index rules are checked the first time
 * the extraction touches it - dequeued as active, on top of the forced-split stack, walked
 * by CHORD, or emitted at level max - and before any of its indices is used, so the work
 * follows the triangles visited instead of the whole hierarchy. EX_OK remembers the
 * result for triangles below max (they have a mark byte); level-max triangles are touched
 * once, when they are emitted. On failure c->bad is set and phase 1 stops. */
static inline int ex_ok(ex_ctx *c, uint32_t t, uint32_t k)
{
    if (k < c->max && (c->mark[t] & EX_OK)) return 1;
    if (subd_sr48_ex_check_tri_(c->h, t, k, c->max) != SUBD_OK) {
        c->bad = 1;
        return 0;
    }
    if (k < c->max) c->mark[t] = (uint8_t)(c->mark[t] | EX_OK);
    return 1;
}

/* The adaptation geometry (sr48_adapt.c): does triangle t of level k < max (checked) ask for
 * a split (c->bad set on a broken hierarchy)? The adaptation box of RAMP and POINT's default
 * radius into c->lo, c->hi (0 when a level-0 corner is out of range). */
int subd_sr48_ex_wants_(ex_ctx *c, uint32_t t, uint32_t k);
int subd_sr48_ex_bbox_(ex_ctx *c);

#endif
