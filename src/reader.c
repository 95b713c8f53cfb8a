/* SPDX-License-Identifier: MIT */
/* The two-pass reader driver shared by the OBJ and OFF readers: a counting scan gives the
 * exact arena plan, a second scan of the same routine fills the arrays in place, and the
 * mesh builder's validation runs on them. Parsing straight into the final arrays keeps the
 * peak at one mesh; a validation error names an element, which the format maps back to its
 * line by rescanning, so no per-element line table is ever stored. */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "mesh_internal.h"
#include "entry.h"

static int reader_count(const subd_reader *r, const char *buf, uint32_t len, mesh_counts *c, subd_diag *d)
{
    int st;
    c->nv = c->nf = c->nc = c->nl = c->nlv = 0;
    if ((st = r->scan(buf, len, c, 0, d)) != SUBD_OK) return st;
    if (subd_mesh_counts_bytes(c) == UINT32_MAX) return subd_fail(d, SUBD_ERR_TOO_BIG);
    return SUBD_OK;
}

int subd_reader_plan(const subd_reader *r, const char *buf, uint32_t len, uint32_t *bytes, subd_diag *diag)
{
    subd_diag dummy;
    subd_diag *d = diag ? diag : &dummy;
    mesh_counts c;
    int st;
    subd_diag_clear(d);
    if ((!buf && len) || !bytes) return subd_fail(d, SUBD_ERR_PARAM);
    if ((st = reader_count(r, buf, len, &c, d)) != SUBD_OK) return st;
    *bytes = subd_mesh_counts_bytes(&c);
    return SUBD_OK;
}

int subd_reader_read(const subd_reader *r, subd_arena *a, const char *buf, uint32_t len, subd_mesh *out,
                     subd_diag *diag)
{
    subd_entry e;
    subd_diag *d = subd_entry_begin(&e, a, diag);
    mesh_counts c, counted;
    subd_mesh m;
    int st;

    if (!a || !out || (!buf && len)) return subd_entry_fail(&e, SUBD_ERR_PARAM);
    if ((st = reader_count(r, buf, len, &c, d)) != SUBD_OK) return subd_entry_fail(&e, st);
    if ((st = subd_mesh_alloc_arrays(a, &c, &m)) != SUBD_OK) {
        d->bytes_needed = subd_mesh_counts_bytes(&c);
        return subd_entry_fail(&e, st);
    }
    m.face_start[0] = 0;
    m.line_start[0] = 0;
    counted = c;
    st = r->scan(buf, len, &c, &m, d);
    if (st == SUBD_OK) {
        st = subd_mesh_finish(a, &m, d);
        if (st != SUBD_OK) d->line = r->line_of(buf, len, &counted, d);
    }
    if (st != SUBD_OK) return subd_entry_fail(&e, st);
    *out = m;
    return subd_entry_ok(&e);
}

uint32_t subd_reader_line_of(const subd_reader *r, const char *buf, uint32_t len, const subd_diag *d)
{
    subd_diag scratch;
    mesh_counts c;
    if (!d || (!buf && len)) return 0;
    if (d->face == SUBD_NONE && d->polyline == SUBD_NONE && d->vertex == SUBD_NONE) return 0;
    subd_diag_clear(&scratch);
    if (reader_count(r, buf, len, &c, &scratch) != SUBD_OK) return 0;
    if ((d->face != SUBD_NONE && d->face >= c.nf) ||
        (d->face == SUBD_NONE && d->polyline != SUBD_NONE && d->polyline >= c.nl) ||
        (d->face == SUBD_NONE && d->polyline == SUBD_NONE && d->vertex >= c.nv))
        return 0;
    return r->line_of(buf, len, &c, d);
}
