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

/* One item, copied as its own type (struct assignment: no aliasing through other types). */
static void copy_item(uint8_t *dst, const uint8_t *src, uint32_t size)
{
    if (size == (uint32_t)sizeof(subd_tri)) *(subd_tri *)(void *)dst = *(const subd_tri *)(const void *)src;
    else *(subd_point *)(void *)dst = *(const subd_point *)(const void *)src;
}

void *subd_stream_q_put(subd_stream_q *q)
{
    subd_stream_ring *r = q->r;
    uint32_t slot;
    if (q->one) return q->one;
    if (q->n < q->max) return q->out + (q->n++) * q->size;
    if (r->count >= r->cap) return 0;
    slot = r->head + r->count;
    if (slot >= r->cap) slot -= r->cap;
    r->count++;
    return q->ring + slot * q->size;
}

static int q_deliver(const subd_stream_q *q, const uint8_t *item)
{
    return q->ts ? q->ts->tri(q->ts->ctx, (const subd_tri *)(const void *)item)
                 : q->ps->point(q->ps->ctx, (const subd_point *)(const void *)item);
}

int subd_stream_q_commit(subd_stream_q *q)
{
    if (!q->one) return 0;
    q->stop = q_deliver(q, q->one);
    return q->stop;
}

static void q_init(subd_stream_q *q, subd_stream_impl *impl, uint32_t kind)
{
    q->out = 0;
    q->max = q->n = 0;
    q->ring = impl->ring_items;
    q->r = impl->ring;
    q->size = ITEM_BYTES(kind);
    q->ended = impl->ring->done;
    q->ts = 0;
    q->ps = 0;
    q->one = 0;
    q->stop = 0;
}

/* A failure: the stream stays failed with its status, the arena is given back. */
static int stream_fail(subd_stream *s, int st)
{
    s->diag.status = st;
    s->status_ = st;
    subd_arena_rewind(s->arena_, s->mark_);
    return st;
}

static int handle_ok(const subd_stream *s) { return s && s->magic_ == STREAM_MAGIC && s->state_; }

/* Pull: drains the ring into the caller's buffer, then runs the scheme's batches until the
 * buffer is full or the stream ends. */
static int run_next(subd_stream *s, void *buf, uint32_t max, uint32_t kind)
{
    subd_stream_impl *impl;
    subd_stream_ring *r;
    subd_stream_q q;
    if (!handle_ok(s)) return SUBD_ERR_PARAM;
    if (s->status_ < 0) return s->status_;
    if (s->status_ > 0) return 0;
    if (!buf || max == 0u || s->kind_ != kind) return SUBD_ERR_PARAM;
    impl = (subd_stream_impl *)s->state_;
    r = impl->ring;
    q_init(&q, impl, kind);
    q.out = (uint8_t *)buf;
    q.max = max;
    while (q.n < max && r->count > 0u) {
        copy_item(q.out + q.n * q.size, q.ring + r->head * q.size, q.size);
        q.n++;
        r->head = (r->head + 1u == r->cap) ? 0u : r->head + 1u;
        r->count--;
    }
    while (q.n < max && !q.ended) {
        int st = impl->step(impl, &q, &s->diag);
        if (st != SUBD_OK) return stream_fail(s, st < 0 ? st : SUBD_ERR_PARAM); /* > 0: no sink here */
    }
    r->done = q.ended;
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
    if (!handle_ok(s)) return;
    if (s->status_ == SUBD_OK) {
        s->status_ = 1;
        subd_arena_rewind(s->arena_, s->mark_);
    }
}

/* Push: what a pull left in the ring first, then every batch straight to the sink through
 * one item (no ring, no copy: the push form costs what a direct sink call costs). */
static int run_push(subd_stream *s, void *item, uint32_t kind, const subd_tri_sink *ts, const subd_point_sink *ps,
                    subd_diag *diag)
{
    subd_stream_impl *impl;
    subd_stream_ring *r;
    subd_stream_q q;
    int st = SUBD_OK;
    if (diag) subd_diag_clear(diag);
    if (!handle_ok(s) || s->kind_ != kind || (kind == SUBD_STREAM_TRIS ? !ts || !ts->tri : !ps || !ps->point)) {
        subd_stream_end(s);
        if (diag) diag->status = SUBD_ERR_PARAM;
        return SUBD_ERR_PARAM;
    }
    if (s->status_ < 0) st = s->status_;
    if (s->status_ == SUBD_OK) {
        impl = (subd_stream_impl *)s->state_;
        r = impl->ring;
        q_init(&q, impl, kind);
        q.ts = ts;
        q.ps = ps;
        while (st == SUBD_OK && r->count > 0u) {
            copy_item((uint8_t *)item, q.ring + r->head * q.size, q.size);
            st = q_deliver(&q, (const uint8_t *)item);
            r->head = (r->head + 1u == r->cap) ? 0u : r->head + 1u;
            r->count--;
        }
        q.one = (uint8_t *)item;
        while (st == SUBD_OK && !q.ended) st = impl->step(impl, &q, &s->diag);
        if (st > 0) { /* the sink stopped: its value, and where the item came from */
            if (kind == SUBD_STREAM_TRIS) s->diag.face = ((const subd_tri *)item)->face;
            else s->diag.polyline = ((const subd_point *)item)->curve;
            s->diag.status = st;
            subd_stream_end(s);
        } else if (st < 0) {
            (void)stream_fail(s, st);
        } else {
            subd_stream_end(s);
        }
    }
    if (diag) {
        *diag = s->diag;
        diag->status = st;
        diag->bytes_needed = 0;
    }
    return st;
}

/* The push form's one item: a union so that it is as large as either kind (copy_item's
 * branches see one object size whichever kind it is called with once inlined). */
typedef union {
    subd_tri t;
    subd_point p;
} stream_item;

int subd_stream_run_tris(subd_stream *s, const subd_tri_sink *sink, subd_diag *diag)
{
    stream_item it;
    return run_push(s, &it.t, SUBD_STREAM_TRIS, sink, 0, diag);
}

int subd_stream_run_points(subd_stream *s, const subd_point_sink *sink, subd_diag *diag)
{
    stream_item it;
    return run_push(s, &it.p, SUBD_STREAM_POINTS, 0, sink, diag);
}
