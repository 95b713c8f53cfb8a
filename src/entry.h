/* SPDX-License-Identifier: MIT */
/* The one failure exit of the public entry points (littlefs's single cleanup exit).
 *
 * Contract that every public call taking an arena promises (DESIGN.md "Errors, never
 * crashes"): on failure the arena is back at its mark of the call, the outputs are exactly
 * as the caller left them, and diag (when not NULL) holds the status and the error's
 * details. The pair below makes that hold by construction:
 *
 *     int subd_X(subd_arena *a, const subd_mesh *in, const opts *o, subd_mesh *out, subd_diag *diag)
 *     {
 *         subd_entry e;
 *         subd_diag *d = subd_entry_begin(&e, a, diag);  // diag cleared, arena mark taken
 *         subd_mesh m;                                     // the result is built in locals
 *         int st;
 *         if (!a || !out) return subd_entry_fail(&e, SUBD_ERR_PARAM);
 *         ...
 *         if (st != SUBD_OK) return subd_entry_fail(&e, st); // or: goto fail
 *         *out = m;                                        // outputs written last ...
 *         return subd_entry_ok(&e);                        // ... after the last failure
 *     }
 *
 *  - subd_entry_begin: d = diag, or a private diag inside e when diag is NULL, so the body
 *    can always write d->face, d->bytes_needed, ...; subd_diag_clear(d); records the arena
 *    mark (a may be NULL: nothing to rewind then, the body reports SUBD_ERR_PARAM).
 *  - subd_entry_fail(e, st): rewinds the arena to the mark, sets d->status = st, returns st.
 *    It leaves d's other fields alone (set face, vertex, line, and with SUBD_ERR_NOMEM
 *    bytes_needed, before calling it), except bytes_needed, which it clears for every other
 *    status: a call that computed a need before the work and then failed otherwise reports
 *    no need, by construction.
 *    Functions that already set d->status (subd_fail, subd_mesh_finish) may be followed by it.
 *  - subd_entry_ok(e): d->bytes_needed = 0 and d->status = SUBD_OK, returns SUBD_OK. It does
 *    not rewind: what the call allocated above the mark is its output.
 * Outputs are not cleared on failure but left untouched: the public headers promise "*out
 * untouched" and the tests compare the output descriptor byte for byte with a sentinel.
 * Storing the result only after the last failure point is what gives that.
 *
 * subd_entry must stay in the entry point's frame (d may point into it); never copy it. */
#ifndef SUBD_ENTRY_H
#define SUBD_ENTRY_H
#include "subd.h"

typedef struct subd_entry {
    subd_arena *a;
    uint32_t mark;
    subd_diag *d;
    subd_diag own; /* used when the caller passed diag == NULL */
} subd_entry;

static inline subd_diag *subd_entry_begin(subd_entry *e, subd_arena *a, subd_diag *diag)
{
    e->a = a;
    e->mark = a ? subd_arena_mark(a) : 0u;
    e->d = diag ? diag : &e->own;
    subd_diag_clear(e->d);
    return e->d;
}

static inline int subd_entry_fail(subd_entry *e, int st)
{
    if (e->a) subd_arena_rewind(e->a, e->mark);
    e->d->status = st;
    if (st != SUBD_ERR_NOMEM) e->d->bytes_needed = 0; /* a need is reported only with NOMEM */
    return st;
}

static inline int subd_entry_ok(subd_entry *e)
{
    e->d->bytes_needed = 0;
    e->d->status = SUBD_OK;
    return SUBD_OK;
}

/* The plan calls' half of the same contract: plan(in, opts, &bytes, diag) fills diag (when
 * not NULL) like the call it plans, through one exit:
 *     subd_diag own, *d = subd_plan_begin(&own, diag);   // d = diag or own, cleared
 *     ...
 *     return subd_plan_end(d, st);                         // d->status = st, no need reported
 * A plan needs no arena, so it never reports bytes_needed. */
static inline subd_diag *subd_plan_begin(subd_diag *own, subd_diag *diag)
{
    subd_diag *d = diag ? diag : own;
    subd_diag_clear(d);
    return d;
}

static inline int subd_plan_end(subd_diag *d, int st)
{
    d->status = st;
    d->bytes_needed = 0;
    return st;
}

#endif
