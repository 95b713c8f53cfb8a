/* SPDX-License-Identifier: MIT */
/* The one stream interface (include/subd.h "Streams"): the pull handle's next/end and the
 * push form over it, for every scheme. A scheme supplies a step function that produces one
 * internal batch at a time into a queue (stream_internal.h); this file hands items to the
 * caller's buffer, keeps what a batch makes beyond it in the overflow ring, rewinds the
 * arena at the end or on a failure, and makes a failed stream stay failed. */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "stream_internal.h"

#define ITEM_BYTES(kind) ((kind) == SUBD_STREAM_TRIS ? (uint32_t)sizeof(subd_tri) : (uint32_t)sizeof(subd_point))

/* A handle a begin call filled carries this value (a zeroed or stale handle does not). */
#define STREAM_MAGIC 0x53554244u

void subd_stream_start(subd_stream *s, subd_arena *a, uint32_t mark, uint32_t kind, subd_stream_impl *impl,
                       uint32_t ring_cap)
{
    impl->ring->head = impl->ring->count = impl->ring->done = 0;
    impl->ring->cap = ring_cap;
    s->magic_ = STREAM_MAGIC;
    s->state_ = impl;
    s->arena_ = a;
    s->mark_ = mark;
    s->status_ = SUBD_OK;
    s->kind_ = kind;
    s->items_ = 0;
    subd_diag_clear(&s->diag);
}

static void copy_item(uint8_t *dst, const uint8_t *src, uint32_t size)
{
    uint32_t i;
    for (i = 0; i < size; i++) dst[i] = src[i];
}

void *subd_stream_q_put(subd_stream_q *q)
{
    subd_stream_ring *r = q->r;
    uint32_t slot;
    if (q->n < q->max) return q->out + (q->n++) * q->size;
    if (r->count >= r->cap) return 0;
    slot = r->head + r->count;
    if (slot >= r->cap) slot -= r->cap;
    r->count++;
    return q->ring + slot * q->size;
}

/* Drains the ring into the caller's buffer, then runs the scheme's batches until the buffer
 * is full or the stream ends. */
static int run_next(subd_stream *s, void *buf, uint32_t max, uint32_t kind)
{
    subd_stream_impl *impl;
    subd_stream_ring *r;
    subd_stream_q q;
    if (!s) return SUBD_ERR_PARAM;
    if (s->magic_ != STREAM_MAGIC || !s->state_) return SUBD_ERR_PARAM;
    if (s->status_ < 0) return s->status_;
    if (s->status_ > 0) return 0;
    if (!buf || max == 0u || s->kind_ != kind) return SUBD_ERR_PARAM;
    impl = (subd_stream_impl *)s->state_;
    r = impl->ring;
    q.out = (uint8_t *)buf;
    q.max = max;
    q.n = 0;
    q.ring = impl->ring_items;
    q.r = r;
    q.size = ITEM_BYTES(kind);
    while (q.n < max && r->count > 0u) {
        copy_item(q.out + q.n * q.size, q.ring + r->head * q.size, q.size);
        q.n++;
        r->head = (r->head + 1u == r->cap) ? 0u : r->head + 1u;
        r->count--;
    }
    while (q.n < max && !r->done) {
        int st = impl->step(impl, &q, &s->diag);
        if (st < 0) {
            s->diag.status = st;
            s->status_ = st;
            subd_arena_rewind(s->arena_, s->mark_);
            return st;
        }
        if (st > 0) r->done = 1;
    }
    s->items_ = (s->items_ > UINT32_MAX - q.n) ? UINT32_MAX : s->items_ + q.n;
    if (q.n == 0u) { /* the end: nothing pending, nothing more to come */
        s->status_ = 1;
        subd_arena_rewind(s->arena_, s->mark_);
    }
    return (int)q.n;
}

int subd_stream_next_tris(subd_stream *s, subd_tri *buf, uint32_t max)
{
    return run_next(s, buf, max, SUBD_STREAM_TRIS);
}

int subd_stream_next_points(subd_stream *s, subd_point *buf, uint32_t max)
{
    return run_next(s, buf, max, SUBD_STREAM_POINTS);
}

void subd_stream_end(subd_stream *s)
{
    if (!s || s->magic_ != STREAM_MAGIC) return;
    if (s->status_ == SUBD_OK) {
        s->status_ = 1;
        subd_arena_rewind(s->arena_, s->mark_);
    }
}

/* The push form: one item at a time (a buffer of one keeps the stack small on a device;
 * the ring holds the rest of a batch, so the scheme's work is the same). */
static int run_push(subd_stream *s, void *item, uint32_t kind, const subd_tri_sink *ts, const subd_point_sink *ps,
                    subd_diag *diag)
{
    int n;
    if (diag) subd_diag_clear(diag);
    for (;;) {
        n = run_next(s, item, 1u, kind);
        if (n <= 0) break;
        n = (kind == SUBD_STREAM_TRIS) ? ts->tri(ts->ctx, (const subd_tri *)item)
                                       : ps->point(ps->ctx, (const subd_point *)item);
        if (n != 0) { /* the sink stopped: its value, and where the item came from */
            s->diag.status = n;
            if (kind == SUBD_STREAM_TRIS) s->diag.face = ((const subd_tri *)item)->face;
            else s->diag.polyline = ((const subd_point *)item)->curve;
            subd_stream_end(s);
            if (diag) *diag = s->diag;
            return n;
        }
    }
    if (n < 0) {
        if (diag) {
            *diag = s->diag;
            diag->status = n;
        }
        return n;
    }
    if (diag) {
        *diag = s->diag;
        diag->status = SUBD_OK;
        diag->bytes_needed = 0;
    }
    return SUBD_OK;
}

int subd_stream_run_tris(subd_stream *s, const subd_tri_sink *sink, subd_diag *diag)
{
    subd_tri t;
    if (!s || !sink || !sink->tri) {
        subd_stream_end(s);
        if (diag) {
            subd_diag_clear(diag);
            diag->status = SUBD_ERR_PARAM;
        }
        return SUBD_ERR_PARAM;
    }
    return run_push(s, &t, SUBD_STREAM_TRIS, sink, 0, diag);
}

int subd_stream_run_points(subd_stream *s, const subd_point_sink *sink, subd_diag *diag)
{
    subd_point p;
    if (!s || !sink || !sink->point) {
        subd_stream_end(s);
        if (diag) {
            subd_diag_clear(diag);
            diag->status = SUBD_ERR_PARAM;
        }
        return SUBD_ERR_PARAM;
    }
    return run_push(s, &p, SUBD_STREAM_POINTS, 0, sink, diag);
}
