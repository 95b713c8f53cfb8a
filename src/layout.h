/* SPDX-License-Identifier: MIT */
/* The one way to lay out arena arrays, so that a plan and the allocation it predicts
 * cannot drift apart.
 *
 * Each operation writes ONE layout function that walks its arrays once, in allocation
 * order, through subd_layout_take. Plan and run both call that function:
 *  - counting (subd_layout_begin(&l, NULL)): take() only adds the rounded bytes to l.bytes
 *    and returns NULL; the function's output pointers receive NULL (point them at a scratch
 *    struct when the caller has none);
 *  - carving (subd_layout_begin(&l, arena)): take() adds the same bytes and allocates the
 *    array from the arena, returning it.
 * So the bytes counted are exactly the bytes carved, array by array. Sizes follow
 * subd_size_add: every array is rounded up to SUBD_ARENA_ALIGN, totals saturate at
 * UINT32_MAX ("too big for 32-bit sizes") and stay there.
 *
 *     static int op_layout(subd_arena *a, const op_counts *c, op_work *w, uint32_t *bytes)
 *     {
 *         subd_layout l;
 *         subd_layout_begin(&l, a);
 *         w->pos = subd_layout_take(&l, c->nv, 3u * (uint32_t)sizeof(subd_real));
 *         w->idx = subd_layout_take(&l, c->nc, 4u);
 *         return subd_layout_end(&l, bytes);
 *     }
 *
 * Errors are sticky: after the first failing take() the later ones allocate nothing (they
 * still count), and subd_layout_end returns the first error: SUBD_ERR_TOO_BIG when the total
 * saturated (checked before each allocation, so count * elem never wraps), SUBD_ERR_NOMEM
 * when the arena ran out. A failed carve leaves the arena advanced: callers rewind to their
 * own mark (src/entry.h does that for public entry points). Counting never fails except
 * with SUBD_ERR_TOO_BIG.
 *
 * The plan arithmetic that composes layouts (phases that reuse memory: a + max(b, c)) uses
 * subd_bytes_add / subd_bytes_max, which saturate the same way. */
#ifndef SUBD_LAYOUT_H
#define SUBD_LAYOUT_H
#include "subd.h"

typedef struct subd_layout {
    subd_arena *a;  /* NULL: count only                                                    */
    uint32_t bytes; /* bytes of the arrays taken so far (aligned, saturating)                */
    int st;         /* SUBD_OK, or the first error                                          */
} subd_layout;

static inline void subd_layout_begin(subd_layout *l, subd_arena *a)
{
    l->a = a;
    l->bytes = 0;
    l->st = SUBD_OK;
}

/* Counts count * elem bytes (rounded up to SUBD_ARENA_ALIGN) and, when carving and no error
 * came before, allocates them. Returns the array, or NULL when counting or on error. */
void *subd_layout_take(subd_layout *l, uint32_t count, uint32_t elem);

/* *bytes (may be NULL) = total counted; returns SUBD_OK or the first error. */
static inline int subd_layout_end(const subd_layout *l, uint32_t *bytes)
{
    if (bytes) *bytes = l->bytes;
    return l->st;
}

/* *total += b, saturating at UINT32_MAX (either operand UINT32_MAX: UINT32_MAX). */
static inline void subd_bytes_add(uint32_t *total, uint32_t b)
{
    if (b == UINT32_MAX || *total > UINT32_MAX - b) *total = UINT32_MAX;
    else *total += b;
}

static inline uint32_t subd_bytes_max(uint32_t a, uint32_t b) { return a > b ? a : b; }

#endif
