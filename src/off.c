/* SPDX-License-Identifier: MIT */
/* OFF (Object File Format, ASCII) reader and writer on memory buffers.
 *
 *   OFF                      keyword line (counts may follow on the same line)
 *   nv nf ne                 counts; ne is read and ignored
 *   x y z [...]              nv vertex lines; anything after z (colours) is ignored
 *   k i0 ... i(k-1) [...]    nf faces, 0-based indices; anything after them on the line of the
 *                            last index is ignored (colours)
 * Blank lines and `#` comments may appear anywhere. Text after the last face is an error.
 * OFF is whitespace-separated, so a face's indices may continue on the following lines (as
 * some exporters wrap long faces): when a line ends before k indices, the next content line
 * goes on. A face starts on a new line; an error in a face names the line it starts on.
 * Counts larger than the file could possibly hold (a vertex needs at least 6 bytes, a face
 * 8) are rejected on the header line before anything is allocated.
 * As in obj.c, one scan serves plan and read (reader.c).
 */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "mesh_internal.h"
#include "text.h"

/* Next line that is not blank or a comment; returns the first non-blank character or NULL
 * at end of buffer. */
static const char *off_next(text_cursor *t)
{
    while (subd_text_next_line(t)) {
        const char *s = subd_text_skip_ws(t->line, t->line_end);
        if (s < t->line_end && *s != '#') return s;
        if (!subd_text_line_is_text(t->line, t->line_end)) return t->line;
    }
    return 0;
}

static int off_uint(const char **s, const char *e, uint32_t *out)
{
    const char *p = subd_text_skip_ws(*s, e), *te = subd_text_token_end(p, e);
    int32_t v;
    int st = subd_text_parse_int(p, te, &v);
    if (st == SUBD_ERR_INDEX) return SUBD_ERR_PARSE;
    if (st != SUBD_OK || v < 0) return SUBD_ERR_PARSE;
    *out = (uint32_t)v;
    *s = te;
    return SUBD_OK;
}

/* The scan behind plan, read and line_of: with target != SUBD_NONE it stops at the start of
 * element `target` (vertex i, or face nv + i) and returns its line in *target_line. */
static int off_walk(const char *buf, uint32_t len, mesh_counts *c, subd_mesh *m, subd_diag *d, uint32_t target,
                    uint32_t *target_line)
{
    text_cursor t;
    const char *s, *e;
    uint32_t nv, nf, ne, i, k, j, nc = 0;
    int st;

    subd_text_init(&t, buf, len);
    s = off_next(&t);
    d->line = t.lineno ? t.lineno : 1u;
    if (!s) return subd_fail(d, SUBD_ERR_EMPTY);
    e = t.line_end;
    if (!subd_text_line_is_text(t.line, e)) return subd_fail(d, SUBD_ERR_PARSE);
    if (!subd_text_token_is(s, subd_text_token_end(s, e), "OFF")) return subd_fail(d, SUBD_ERR_PARSE);
    s = subd_text_skip_ws(subd_text_token_end(s, e), e);
    if (s == e || *s == '#') {
        s = off_next(&t);
        d->line = t.lineno;
        if (!s) return subd_fail(d, SUBD_ERR_PARSE);
        e = t.line_end;
    }
    if (off_uint(&s, e, &nv) || off_uint(&s, e, &nf) || off_uint(&s, e, &ne)) return subd_fail(d, SUBD_ERR_PARSE);
    (void)ne;
    if ((uint64_t)nv * 6u + (uint64_t)nf * 8u > (uint64_t)len + 8u) return subd_fail(d, SUBD_ERR_PARSE);
    if (nv == 0) return subd_fail(d, SUBD_ERR_EMPTY);

    for (i = 0; i < nv; i++) {
        s = off_next(&t);
        d->line = t.lineno + (s ? 0u : 1u);
        if (!s) return subd_fail(d, SUBD_ERR_PARSE);
        e = t.line_end;
        if (i == target) {
            *target_line = t.lineno;
            return SUBD_OK;
        }
        if (!subd_text_line_is_text(t.line, e)) return subd_fail(d, SUBD_ERR_PARSE);
        for (k = 0; k < 3u; k++) {
            subd_real x;
            if ((st = subd_text_parse_real(&s, e, &x)) != SUBD_OK) return subd_fail(d, st);
            if (m) m->pos[3u * i + k] = x;
        }
    }
    for (i = 0; i < nf; i++) {
        uint32_t fs;
        s = off_next(&t);
        d->line = t.lineno + (s ? 0u : 1u);
        if (!s) return subd_fail(d, SUBD_ERR_PARSE);
        e = t.line_end;
        if (target != SUBD_NONE && nv + i == target) {
            *target_line = t.lineno;
            return SUBD_OK;
        }
        if (!subd_text_line_is_text(t.line, e)) return subd_fail(d, SUBD_ERR_PARSE);
        if (off_uint(&s, e, &fs)) return subd_fail(d, SUBD_ERR_PARSE);
        if (fs < 3u || fs > SUBD_MAX_FACE_SIZE) return subd_fail(d, SUBD_ERR_FACE_SIZE);
        for (j = 0; j < fs; j++) {
            uint32_t vi;
            const char *p = subd_text_skip_ws(s, e), *te;
            int32_t v;
            if (p == e || *p == '#') { /* the face goes on on the next content line */
                uint32_t first = d->line;
                s = off_next(&t);
                d->line = s ? t.lineno : t.lineno + 1u;
                if (!s) return subd_fail(d, SUBD_ERR_PARSE);
                e = t.line_end;
                if (!subd_text_line_is_text(t.line, e)) return subd_fail(d, SUBD_ERR_PARSE);
                d->line = first; /* errors in the face name the line it starts on */
                p = s;
            }
            te = subd_text_token_end(p, e);
            st = subd_text_parse_int(p, te, &v);
            if (st != SUBD_OK) return subd_fail(d, st);
            if (v < 0 || (uint32_t)v >= nv) return subd_fail(d, SUBD_ERR_INDEX);
            vi = (uint32_t)v;
            if (m) m->corner_vert[nc + j] = vi;
            s = te;
        }
        nc += fs;
        if (m) m->face_start[i + 1u] = nc;
    }
    if (off_next(&t)) {
        d->line = t.lineno;
        return subd_fail(d, SUBD_ERR_PARSE);
    }
    d->line = 0;
    c->nv = nv;
    c->nf = nf;
    c->nc = nc;
    c->nl = 0;
    c->nlv = 0;
    return SUBD_OK;
}

static int off_scan(const char *buf, uint32_t len, mesh_counts *c, subd_mesh *m, subd_diag *d)
{
    return off_walk(buf, len, c, m, d, SUBD_NONE, 0);
}

/* Line on which vertex or face n (faces numbered after the vertices) starts: the same walk
 * as the scan, so faces spread over several lines are counted as the scan reads them. */
static uint32_t off_element_line(const char *buf, uint32_t len, uint32_t n)
{
    mesh_counts c;
    subd_diag d;
    uint32_t line = 0;
    subd_diag_clear(&d);
    if (off_walk(buf, len, &c, 0, &d, n, &line) != SUBD_OK) return 0;
    return line;
}

static uint32_t off_line_of(const char *buf, uint32_t len, const mesh_counts *c, const subd_diag *d)
{
    if (d->face != SUBD_NONE) return off_element_line(buf, len, c->nv + d->face);
    if (d->vertex != SUBD_NONE) return off_element_line(buf, len, d->vertex);
    return 0;
}

static const subd_reader off_reader = {off_scan, off_line_of};

int subd_off_plan(const char *buf, uint32_t len, uint32_t *bytes, subd_diag *diag)
{
    return subd_reader_plan(&off_reader, buf, len, bytes, diag);
}

int subd_off_read(subd_arena *arena, const char *buf, uint32_t len, subd_mesh *out, subd_diag *diag)
{
    return subd_reader_read(&off_reader, arena, buf, len, out, diag);
}

uint32_t subd_off_line_of(const char *buf, uint32_t len, const subd_diag *diag)
{
    return subd_reader_line_of(&off_reader, buf, len, diag);
}

static void off_emit(const subd_mesh *m, const subd_real *normals, text_sink *k)
{
    (void)normals;
    uint32_t v, f, c;
    subd_sink_str(k, "OFF\n");
    subd_sink_u32(k, m->num_verts);
    subd_sink_str(k, " ");
    subd_sink_u32(k, m->num_faces);
    subd_sink_str(k, " ");
    subd_sink_u32(k, m->num_edges);
    subd_sink_str(k, "\n");
    for (v = 0; v < m->num_verts; v++) {
        subd_sink_real(k, m->pos[3u * v]);
        subd_sink_str(k, " ");
        subd_sink_real(k, m->pos[3u * v + 1u]);
        subd_sink_str(k, " ");
        subd_sink_real(k, m->pos[3u * v + 2u]);
        subd_sink_str(k, "\n");
    }
    for (f = 0; f < m->num_faces; f++) {
        subd_sink_u32(k, subd_face_size(m, f));
        for (c = m->face_start[f]; c < m->face_start[f + 1u]; c++) {
            subd_sink_str(k, " ");
            subd_sink_u32(k, m->corner_vert[c]);
        }
        subd_sink_str(k, "\n");
    }
}

int subd_off_write(const subd_mesh *m, char *buf, uint32_t cap, uint32_t *len)
{
    return subd_text_write(off_emit, m, 0, buf, cap, len);
}
