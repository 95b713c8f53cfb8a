/* SPDX-License-Identifier: MIT */
/* Arena: a bump allocator over a caller-owned buffer, with mark/rewind and a peak counter.
 *
 * Offsets, not addresses, are aligned: every allocation is rounded up to SUBD_ARENA_ALIGN
 * bytes, so the bytes an operation uses depend only on its input, never on where the
 * buffer lives. That is what makes a plan computed on a PC valid on the device.
 */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "subd.h"

#define ALIGN_MASK ((uint32_t)SUBD_ARENA_ALIGN - 1u)

void subd_arena_init(subd_arena *a, void *buf, uint32_t size)
{
    uintptr_t p = (uintptr_t)buf;
    uint32_t skip = (uint32_t)((SUBD_ARENA_ALIGN - (p & ALIGN_MASK)) & ALIGN_MASK);
    if (buf == 0 || size < skip) {
        a->base = (uint8_t *)buf;
        a->size = 0;
    } else {
        a->base = (uint8_t *)buf + skip;
        a->size = size - skip;
    }
    a->used = 0;
    a->peak = 0;
}

void *subd_arena_alloc(subd_arena *a, uint32_t bytes)
{
    uint32_t free_bytes = a->size - a->used;
    uint32_t rounded;
    void *p;
    if (bytes > UINT32_MAX - ALIGN_MASK) return 0;
    rounded = (bytes + ALIGN_MASK) & ~ALIGN_MASK;
    if (rounded > free_bytes) return 0;
    p = a->base + a->used;
    a->used += rounded;
    if (a->used > a->peak) a->peak = a->used;
    return p;
}

uint32_t subd_arena_mark(const subd_arena *a) { return a->used; }

void subd_arena_rewind(subd_arena *a, uint32_t mark)
{
    if (mark <= a->used) a->used = mark;
}

uint32_t subd_arena_free_bytes(const subd_arena *a) { return a->size - a->used; }

void subd_arena_reset_peak(subd_arena *a) { a->peak = a->used; }

void subd_size_add(uint32_t *total, uint32_t count, uint32_t elem_bytes)
{
    uint64_t bytes = (uint64_t)count * elem_bytes;
    uint64_t t;
    if (*total == UINT32_MAX) return;
    bytes = (bytes + ALIGN_MASK) & ~(uint64_t)ALIGN_MASK;
    t = (uint64_t)*total + bytes;
    *total = (t >= UINT32_MAX) ? UINT32_MAX : (uint32_t)t;
}
