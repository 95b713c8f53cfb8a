/* SPDX-License-Identifier: MIT */
/* Private interface between the Loop files (loop.c, loop_limit.c, pia.c, loop_stream.c). */
#ifndef SUBD_LOOP_INTERNAL_H
#define SUBD_LOOP_INTERNAL_H
#include "subd.h"

/* Applies the limit-position operator L to control positions ctrl (3 * num_verts) of the
 * mesh m's topology and writes L ctrl to lim (3 * num_verts; must not alias ctrl). Uses
 * no arena memory. Overflow (fixed point) is ORed into *ovf. Rule set b as subd_loop_limit.
 * Written by loop_limit.c; used by subd_loop_limit and by progressive interpolation. */
void subd_loop_limit_apply(const subd_mesh *m, subd_loop_boundary b, const subd_real *ctrl,
                           subd_real *lim, uint32_t *ovf);
/* Keeps a function out of its caller's frame, so the stack of a call is the deepest path, not
 * the sum of every helper inlined into it (-Wstack-usage on the device builds checks it). */
#if defined(__GNUC__)
#define SUBD_NOINLINE __attribute__((noinline))
#else
#define SUBD_NOINLINE
#endif

/* Limit position (and, when normal != NULL, unit limit normal) of vertex v alone, bit-identical
 * to what subd_loop_limit computes for v in a call on the whole mesh (the per-call caches only
 * memoise). Only v's own ring is walked; a neighbour's regular bit comes from LOOP_VTAG_KNOWN /
 * LOOP_VTAG_REGULAR when set (loop_rules.h), else from its ring. Written by loop_limit.c; used by loop_stream.c. */
void subd_loop_limit_vertex(const subd_mesh *m, subd_loop_boundary b, const subd_real *ctrl, uint32_t v,
                            subd_real *pos, subd_real *normal, uint32_t *ovf);

/* The checks subd_loop and subd_loop_stream share: arguments, levels, boundary rule, flags
 * (only those in `flags` allowed), a mesh with adjacency, triangles only (SUBD_ERR_NOT_TRIANGLES
 * with diag.face). Returns SUBD_OK or the status (diag set). Written by loop.c. */
int subd_loop_check(const subd_mesh *in, const subd_loop_opts *o, uint32_t flags, subd_diag *d);
/* The limit mask of a boundary or crease vertex v on one of its two curve neighbours u, as
 * the weight num/den (den > 0): the paper's rule by whether v and u are regular (loop_rules.h;
 * the six configurations derived at the top of loop_limit.c: 1/6, 7/48, 1/5, 7/40), the
 * B-spline rule's 1/6 whatever they are. Written by loop_limit.c; used by its positions and
 * by pia_fast.c (the rows of L its Gauss-Seidel sweeps apply). */
void subd_loop_limit_curve_frac(subd_loop_boundary b, int rv, int ru, int32_t *num, int32_t *den);

#endif
