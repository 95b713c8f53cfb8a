/* SPDX-License-Identifier: MIT */
/* The firmware demos' report lines (demo.c, demo_pipe.c, demo_sr48.c): "  key value" in
 * decimal, 64-bit decimal or hex, and one error line, "  error: [what: ]status[, needs N
 * bytes]" (N only for SUBD_ERR_NOMEM, the one status that sets diag.bytes_needed). `make
 * demo` greps these lines, so the format lives here once. Static inline: a demo uses what it
 * needs, no heap, no stdio (port/print.h writes through semihosting). */
#ifndef TINYSUBD_DEMO_PRINT_H
#define TINYSUBD_DEMO_PRINT_H

#include "subd.h"
#include "print.h"

static inline void demo_kv(const char *key, uint32_t v)
{
    print_str("  ");
    print_str(key);
    print_str(" ");
    print_u32(v);
    print_nl();
}

static inline void demo_kv64(const char *key, uint64_t v)
{
    print_str("  ");
    print_str(key);
    print_str(" ");
    print_u64(v);
    print_nl();
}

static inline void demo_kv_hex(const char *key, uint32_t v)
{
    print_str("  ");
    print_str(key);
    print_str(" ");
    print_hex32(v);
    print_nl();
}

/* Prints the error line of a failed call (what may be NULL, d may be NULL) and returns st,
 * or SUBD_ERR_PARAM when st is SUBD_OK (a check of the demo's own failed). */
static inline int demo_fail(const char *what, int st, const subd_diag *d)
{
    print_str("  error: ");
    if (what) {
        print_str(what);
        print_str(": ");
    }
    print_str(subd_status_str(st));
    if (st == SUBD_ERR_NOMEM && d) {
        print_str(", needs ");
        print_u32(d->bytes_needed);
        print_str(" bytes");
    }
    print_nl();
    return st == SUBD_OK ? SUBD_ERR_PARAM : st;
}

#endif
