/* SPDX-License-Identifier: MIT */
/* The private side of the one stream interface (include/subd.h "Streams"): how a scheme's
 * begin call fills the caller's handle, and the output queue every scheme's `next` writes
 * through. A scheme produces its items in internal batches (Loop: a face's 16 grandchildren;
 * 4-8: one diamond's triangles); `next` must stop after `max` items, so what a batch makes
 * beyond the caller's buffer waits in a small overflow ring in the stream's arena state and
 * is handed out first by the next call. That keeps the work per call bounded (max items plus
 * one batch) and makes the order independent of the batch sizes the caller pulls with. */
#ifndef SUBD_STREAM_INTERNAL_H
#define SUBD_STREAM_INTERNAL_H
#include "subd.h"

/* A scheme's step: produce one internal batch: for each item, subd_stream_q_put gives the
 * slot to fill, subd_stream_q_commit hands it on (a non-zero value: the push form's sink
 * stopped; return it at once); at the end of the stream set q->ended. Return SUBD_OK, a
 * negative status with d's details, or the sink's non-zero value. */
typedef struct subd_stream_q subd_stream_q;
typedef int (*subd_stream_step_fn)(void *state, subd_stream_q *q, subd_diag *d);

/* The overflow ring's bookkeeping, kept in the scheme's state (32-bit fields only). */
typedef struct subd_stream_ring {
    uint32_t head, count, cap, done;
} subd_stream_ring;

struct subd_stream_q {
    uint8_t *out;   /* pull: the caller's buffer of this call            */
    uint32_t max, n;
    uint8_t *ring;  /* cap items of `size` bytes in the arena            */
    subd_stream_ring *r;
    uint32_t size;
    uint32_t ended; /* set by the step after the last item               */
    /* push: every item goes straight to the sink from `one` (no copy)   */
    const subd_tri_sink *ts;
    const subd_point_sink *ps;
    uint8_t *one;
    int stop;       /* push: the sink's last non-zero value              */
};

/* Fills the handle: state (in the arena above mark), kind, the scheme's step and ring. */
typedef struct subd_stream_impl {
    subd_stream_step_fn step;
    subd_stream_ring *ring; /* in the state                            */
    uint8_t *ring_items;    /* ring->cap items                          */
} subd_stream_impl;

/* subd_stream_start: a begin call's last act, after every check passed: the handle runs
 * `impl` on `state`; the arena is rewound to mark by the end call. impl must live in the
 * arena (it is the first member of the scheme's state by convention). */
void subd_stream_start(subd_stream *s, subd_arena *a, uint32_t mark, uint32_t kind, subd_stream_impl *impl,
                       uint32_t ring_cap);

/* A scheme's run state (a struct with pointers, so of different sizes on a 64-bit host and
 * a 32-bit device) takes a fixed SUBD_STREAM_STATE_BYTES in the arena, so plans are the same
 * everywhere; this stops the build where it would not fit. */
#define SUBD_STREAM_STATE_FITS(type) \
    typedef char subd_stream_fits_##type[sizeof(type) <= SUBD_STREAM_STATE_BYTES ? 1 : -1]

/* Where the next item goes (push: the one item handed to the sink; pull: the caller's
 * buffer, else the ring); NULL only when both are full, which a scheme whose batch is at most
 * ring_cap items never sees. */
void *subd_stream_q_put(subd_stream_q *q);
/* The item put last is complete: push: the sink's value (non-zero: stop; also kept in
 * q->stop); pull: 0. */
int subd_stream_q_commit(subd_stream_q *q);
/* For a step that makes several items per call: stop making them now (pull: the caller's
 * buffer is full; push: the sink asked to stop, return q->stop). */
static inline int subd_stream_q_full(const subd_stream_q *q) { return q->one ? q->stop != 0 : q->n >= q->max; }

#endif
