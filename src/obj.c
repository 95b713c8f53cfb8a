/* SPDX-License-Identifier: MIT */
/* Wavefront OBJ reader and writer on memory buffers.
 *
 * Read: `v x y z [w | r g b]`, `f` with `v`, `v/vt`, `v//vn`, `v/vt/vn` corners (1-based or
 * negative = relative to the vertices so far), `l` polylines, comments. Statements that carry
 * no geometry for us (`vt vn vp g o s usemtl mtllib`) are skipped. Any other statement is a
 * syntax error: silently ignoring it would hide e.g. free-form geometry we cannot represent,
 * and garbage must not pass as an empty mesh.
 *
 * One scan routine serves the plan (count) and the read (fill) through the reader driver
 * (reader.c), so the two cannot disagree.
 * Validation errors found after parsing (repeated vertex, non-manifold, orientation) name a
 * face or vertex; the reader turns that back into a line by rescanning, which costs no memory.
 */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "mesh_internal.h"
#include "text.h"

typedef struct obj_scan {
    mesh_counts c;      /* counted so far (plan) or filled so far (read)               */
    subd_mesh *m;       /* NULL while planning                                          */
    uint32_t nv_total;  /* vertices in the file (known when reading)                     */
    uint32_t lines;     /* lines in the buffer (for errors about the file as a whole)   */
} obj_scan;

static int is_ignored(const char *s, const char *e)
{
    static const char *const words[] = {"vt", "vn", "vp", "g", "o", "s", "usemtl", "mtllib", 0};
    int i;
    for (i = 0; words[i]; i++)
        if (subd_text_token_is(s, e, words[i])) return 1;
    return 0;
}

/* One face corner or polyline vertex: the vertex index is the part before the first '/';
 * the optional texture and normal parts must be integers too (or empty) but are not kept. */
static int parse_ref(const char *s, const char *e, uint32_t nv_so_far, uint32_t nv_total, uint32_t *out)
{
    const char *slash = s;
    int32_t idx, dummy;
    int st, parts = 0;
    while (slash < e && *slash != '/') slash++;
    st = subd_text_parse_int(s, slash, &idx);
    if (st != SUBD_OK) return st;
    while (slash < e) { /* "/vt", "//vn", "/vt/vn" */
        const char *q = slash + 1;
        const char *r = q;
        if (++parts > 2) return SUBD_ERR_PARSE;
        while (r < e && *r != '/') r++;
        if (r > q && subd_text_parse_int(q, r, &dummy) == SUBD_ERR_PARSE) return SUBD_ERR_PARSE;
        if (r == q && (r == e)) return SUBD_ERR_PARSE; /* trailing '/' */
        slash = r;
    }
    if (idx == 0) return SUBD_ERR_INDEX;
    if (idx < 0) {
        if ((uint32_t)(-(int64_t)idx) > nv_so_far) return SUBD_ERR_INDEX;
        *out = nv_so_far - (uint32_t)(-(int64_t)idx);
    } else {
        if ((uint32_t)idx > nv_total) return SUBD_ERR_INDEX;
        *out = (uint32_t)idx - 1u;
    }
    return SUBD_OK;
}

/* Scans the whole buffer. Planning (sc->m == NULL) counts elements and checks syntax that
 * does not need the vertex count; reading fills the arrays. Stops at the first error with
 * d->line set. */
static int obj_scan_buffer(obj_scan *sc, const char *buf, uint32_t len, subd_diag *d)
{
    text_cursor t;
    subd_mesh *m = sc->m;
    uint32_t nv_total = m ? sc->nv_total : UINT32_MAX;
    int st = SUBD_OK;

    subd_text_init(&t, buf, len);
    while (subd_text_next_line(&t)) {
        const char *s = subd_text_skip_ws(t.line, t.line_end), *e = t.line_end, *kw_end;
        d->line = t.lineno;
        if (!subd_text_line_is_text(t.line, e)) return subd_fail(d, SUBD_ERR_PARSE);
        if (s == e || *s == '#') continue;
        kw_end = subd_text_token_end(s, e);
        if (subd_text_token_is(s, kw_end, "v")) {
            subd_real xyz[3], extra;
            uint32_t k, n_extra = 0;
            s = kw_end;
            for (k = 0; k < 3u; k++)
                if ((st = subd_text_parse_real(&s, e, &xyz[k])) != SUBD_OK) return subd_fail(d, st);
            /* optional w or r g b: checked for syntax, not kept */
            for (s = subd_text_skip_ws(s, e); s < e; s = subd_text_skip_ws(s, e)) {
                if (++n_extra > 4u) return subd_fail(d, SUBD_ERR_PARSE);
                st = subd_real_parse(&s, e, &extra);
                if (st != SUBD_OK && st != SUBD_ERR_RANGE) return subd_fail(d, st == SUBD_ERR_NAN ? SUBD_ERR_PARSE : st);
                if (s < e && *s != ' ' && *s != '\t' && *s != '\r') return subd_fail(d, SUBD_ERR_PARSE);
            }
            if (m) for (k = 0; k < 3u; k++) m->pos[3u * sc->c.nv + k] = xyz[k];
            if (sc->c.nv == UINT32_MAX - 1u) return subd_fail(d, SUBD_ERR_TOO_BIG);
            sc->c.nv++;
        } else if (subd_text_token_is(s, kw_end, "f") || subd_text_token_is(s, kw_end, "l")) {
            int is_face = (*s == 'f');
            uint32_t n = 0, base = is_face ? sc->c.nc : sc->c.nlv;
            for (s = subd_text_skip_ws(kw_end, e); s < e; s = subd_text_skip_ws(s, e)) {
                const char *te = subd_text_token_end(s, e);
                uint32_t vi = 0;
                st = parse_ref(s, te, sc->c.nv, nv_total, &vi);
                if (st != SUBD_OK) return subd_fail(d, st);
                if (is_face && n >= SUBD_MAX_FACE_SIZE) return subd_fail(d, SUBD_ERR_FACE_SIZE);
                if (m) {
                    if (is_face) m->corner_vert[base + n] = vi;
                    else m->line_vert[base + n] = vi;
                }
                if (n == UINT32_MAX - base - 1u) return subd_fail(d, SUBD_ERR_TOO_BIG);
                n++;
                s = te;
            }
            if (is_face) {
                if (n < 3u) return subd_fail(d, SUBD_ERR_FACE_SIZE);
                if (sc->c.nf == UINT32_MAX - 1u) return subd_fail(d, SUBD_ERR_TOO_BIG);
                sc->c.nf++;
                sc->c.nc += n;
                if (m) m->face_start[sc->c.nf] = sc->c.nc;
            } else {
                if (n < 2u) return subd_fail(d, SUBD_ERR_PARSE);
                if (sc->c.nl == UINT32_MAX - 1u) return subd_fail(d, SUBD_ERR_TOO_BIG);
                sc->c.nl++;
                sc->c.nlv += n;
                if (m) m->line_start[sc->c.nl] = sc->c.nlv;
            }
        } else if (!is_ignored(s, kw_end)) {
            return subd_fail(d, SUBD_ERR_PARSE);
        }
    }
    d->line = 0;
    sc->lines = t.lineno;
    return SUBD_OK;
}

/* Line of the n-th statement whose keyword is kw ("v", "f" or "l"). */
static uint32_t obj_statement_line(const char *buf, uint32_t len, const char *kw, uint32_t n)
{
    text_cursor t;
    uint32_t seen = 0;
    subd_text_init(&t, buf, len);
    while (subd_text_next_line(&t)) {
        const char *s = subd_text_skip_ws(t.line, t.line_end);
        if (subd_text_token_is(s, subd_text_token_end(s, t.line_end), kw) && seen++ == n) return t.lineno;
    }
    return 0;
}

static uint32_t obj_line_of(const char *buf, uint32_t len, const mesh_counts *c, const subd_diag *d)
{
    (void)c;
    if (d->face != SUBD_NONE) return obj_statement_line(buf, len, "f", d->face);
    if (d->polyline != SUBD_NONE) return obj_statement_line(buf, len, "l", d->polyline);
    if (d->vertex != SUBD_NONE) return obj_statement_line(buf, len, "v", d->vertex);
    return 0;
}

static int obj_scan_fn(const char *buf, uint32_t len, mesh_counts *c, subd_mesh *m, subd_diag *d)
{
    obj_scan sc;
    int st;
    sc.c.nv = sc.c.nf = sc.c.nc = sc.c.nl = sc.c.nlv = 0;
    sc.m = m;
    sc.nv_total = m ? c->nv : 0;
    sc.lines = 0;
    if ((st = obj_scan_buffer(&sc, buf, len, d)) != SUBD_OK) return st;
    if (sc.c.nv == 0) {
        d->line = sc.lines ? sc.lines : 1u;
        return subd_fail(d, SUBD_ERR_EMPTY);
    }
    *c = sc.c;
    return SUBD_OK;
}

static const subd_reader obj_reader = {obj_scan_fn, obj_line_of};

int subd_obj_plan(const char *buf, uint32_t len, uint32_t *bytes, subd_diag *diag)
{
    return subd_reader_plan(&obj_reader, buf, len, bytes, diag);
}

int subd_obj_read(subd_arena *arena, const char *buf, uint32_t len, subd_mesh *out, subd_diag *diag)
{
    return subd_reader_read(&obj_reader, arena, buf, len, out, diag);
}

uint32_t subd_obj_line_of(const char *buf, uint32_t len, const subd_diag *diag)
{
    return subd_reader_line_of(&obj_reader, buf, len, diag);
}

static void obj_xyz(text_sink *k, const char *kw, const subd_real *p)
{
    subd_sink_str(k, kw);
    subd_sink_real(k, p[0]);
    subd_sink_str(k, " ");
    subd_sink_real(k, p[1]);
    subd_sink_str(k, " ");
    subd_sink_real(k, p[2]);
    subd_sink_str(k, "\n");
}

/* With normals, vertex i has normal i and faces are written as `f a//a b//b ...`. */
static void obj_emit(const subd_mesh *m, const subd_real *normals, text_sink *k)
{
    uint32_t v, f, c, l;
    subd_sink_str(k, "# tinysubd\n");
    for (v = 0; v < m->num_verts; v++) obj_xyz(k, "v ", &m->pos[3u * v]);
    if (normals)
        for (v = 0; v < m->num_verts; v++) obj_xyz(k, "vn ", &normals[3u * v]);
    for (f = 0; f < m->num_faces; f++) {
        subd_sink_str(k, "f");
        for (c = m->face_start[f]; c < m->face_start[f + 1u]; c++) {
            subd_sink_str(k, " ");
            subd_sink_u32(k, m->corner_vert[c] + 1u);
            if (normals) {
                subd_sink_str(k, "//");
                subd_sink_u32(k, m->corner_vert[c] + 1u);
            }
        }
        subd_sink_str(k, "\n");
    }
    for (l = 0; l < m->num_lines; l++) {
        subd_sink_str(k, "l");
        for (c = m->line_start[l]; c < m->line_start[l + 1u]; c++) {
            subd_sink_str(k, " ");
            subd_sink_u32(k, m->line_vert[c] + 1u);
        }
        subd_sink_str(k, "\n");
    }
}

int subd_obj_write(const subd_mesh *m, char *buf, uint32_t cap, uint32_t *len)
{
    return subd_text_write(obj_emit, m, 0, buf, cap, len);
}

int subd_obj_write_normals(const subd_mesh *m, const subd_real *normals, char *buf, uint32_t cap, uint32_t *len)
{
    if (!normals) return SUBD_ERR_PARAM;
    return subd_text_write(obj_emit, m, normals, buf, cap, len);
}
