/* SPDX-License-Identifier: MIT */
/* subd_layout_take: count-or-carve for the one-walk layout functions (see layout.h). Kept
 * out of line: it is called once per array, never in an inner loop. */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "layout.h"

void *subd_layout_take(subd_layout *l, uint32_t count, uint32_t elem)
{
    void *p;
    subd_size_add(&l->bytes, count, elem);
    if (l->bytes == UINT32_MAX && l->st == SUBD_OK) l->st = SUBD_ERR_TOO_BIG;
    if (!l->a || l->st != SUBD_OK) return 0;
    p = subd_arena_alloc(l->a, count * elem); /* fits: the saturating total did not */
    if (!p) l->st = SUBD_ERR_NOMEM;
    return p;
}
