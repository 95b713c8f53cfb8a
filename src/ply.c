/* SPDX-License-Identifier: MIT */
/* PLY reader on memory buffers: `format ascii 1.0` and `format binary_little_endian 1.0`.
 *
 * The header is parsed into a small table on the stack (at most PLY_MAX_ELEMS elements and
 * PLY_MAX_PROPS properties in all, far more than real files declare; more is a syntax error
 * at the line that exceeds it): per property its type, a list's count type, and its role
 * (x, y, z of `vertex`; vertex_indices / vertex_index of `face`). The body is then walked
 * element by element in header order, every property read or skipped by its declared type,
 * so unknown elements and properties (colours, normals, texture lists, edges, materials)
 * cost nothing but the walk. Coordinates: float32 and float64 by subd_real_from_f32_bits /
 * _f64_bits, ASCII by subd_real_parse. Big-endian files are refused at their `format` line
 * rather than byte-swapped: no writer in use produces them by default, and a path that is
 * never exercised is a path that is wrong.
 *
 * One walk serves the plan (counting), the read (filling) and line_of (stopping at a record)
 * through the reader driver (reader.c), so they cannot disagree. ASCII records are one per
 * line (blank lines between them are skipped); errors name the line. Binary records are
 * named by diag.vertex / diag.face, or for other elements by the line of their `element`
 * declaration.
 */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "mesh_internal.h"
#include "text.h"
#include "bin_le.h"

#define PLY_MAX_ELEMS 16u
#define PLY_MAX_PROPS 64u

/* Types 1..8: char uchar short ushort int uint float double (and their intN names). */
#define PLY_FLOAT 7u
#define PLY_DOUBLE 8u
static const uint8_t ply_size[9] = {0, 1, 1, 2, 2, 4, 4, 4, 8};

/* Roles: what a property is to the mesh. */
#define PLY_ROLE_OTHER 0u
#define PLY_ROLE_X 1u /* .. PLY_ROLE_X + 2 = z */
#define PLY_ROLE_INDEX 4u

#define PLY_KIND_OTHER 0u
#define PLY_KIND_VERTEX 1u
#define PLY_KIND_FACE 2u

typedef struct ply_elem {
    uint32_t count;  /* records                                  */
    uint32_t line;   /* line of its `element` declaration        */
    uint8_t kind, first, nprops, roles; /* roles: bit per role found */
} ply_elem;

typedef struct ply_head {
    uint32_t nelems, nprops, binary;
    uint32_t nv, nf;      /* records of `vertex` and `face` (0 when absent)        */
    uint32_t end_line;    /* line of end_header                                    */
    text_cursor t;        /* after the header                                      */
    uint16_t prop[PLY_MAX_PROPS]; /* type | list count type << 4 | role << 8      */
    ply_elem el[PLY_MAX_ELEMS];
} ply_head;

static uint32_t ply_type(const char *s, const char *e)
{
    static const char *const names[] = {"char", "uchar", "short", "ushort", "int", "uint", "float", "double",
                                        "int8", "uint8", "int16", "uint16", "int32", "uint32", "float32", "float64"};
    uint32_t i;
    for (i = 0; i < 16u; i++)
        if (subd_text_token_is(s, e, names[i])) return i % 8u + 1u;
    return 0;
}

/* Next token of the line [*s, e) into [*ts, *te); 0 when the line has no more. */
static int ply_token(const char **s, const char *e, const char **ts, const char **te)
{
    const char *p = subd_text_skip_ws(*s, e);
    if (p == e) return 0;
    *ts = p;
    *te = subd_text_token_end(p, e);
    *s = *te;
    return 1;
}

/* An unsigned decimal count (all digits, <= UINT32_MAX). */
static int ply_uint(const char *s, const char *e, uint32_t *out)
{
    uint64_t v = 0;
    if (s == e) return 0;
    for (; s < e; s++) {
        if (*s < '0' || *s > '9') return 0;
        v = v * 10u + (uint32_t)(*s - '0');
        if (v > UINT32_MAX) return 0;
    }
    *out = (uint32_t)v;
    return 1;
}

/* One `property` line (after the keyword) of element el. */
static int ply_property(ply_head *h, ply_elem *el, const char *s, const char *e)
{
    const char *a, *ae, *b, *be;
    uint32_t type, ctype = 0, role = PLY_ROLE_OTHER;
    if (!ply_token(&s, e, &a, &ae)) return SUBD_ERR_PARSE;
    if (subd_text_token_is(a, ae, "list")) {
        if (!ply_token(&s, e, &a, &ae)) return SUBD_ERR_PARSE;
        ctype = ply_type(a, ae);
        if (ctype == 0u || ctype >= PLY_FLOAT) return SUBD_ERR_PARSE; /* counts are integers */
        if (!ply_token(&s, e, &a, &ae)) return SUBD_ERR_PARSE;
    }
    type = ply_type(a, ae);
    if (type == 0u || !ply_token(&s, e, &b, &be) || subd_text_skip_ws(s, e) != e) return SUBD_ERR_PARSE;
    if (el->kind == PLY_KIND_VERTEX && be - b == 1 && *b >= 'x' && *b <= 'z') {
        if (ctype || (type != PLY_FLOAT && type != PLY_DOUBLE)) return SUBD_ERR_PARSE;
        role = PLY_ROLE_X + (uint32_t)(*b - 'x');
    } else if (el->kind == PLY_KIND_FACE &&
               (subd_text_token_is(b, be, "vertex_indices") || subd_text_token_is(b, be, "vertex_index"))) {
        if (!ctype || type >= PLY_FLOAT) return SUBD_ERR_PARSE;
        role = PLY_ROLE_INDEX;
    }
    if (role != PLY_ROLE_OTHER) {
        if (el->roles & (1u << role)) return SUBD_ERR_PARSE; /* twice */
        el->roles = (uint8_t)(el->roles | (1u << role));
    }
    if (h->nprops == PLY_MAX_PROPS) return SUBD_ERR_PARSE;
    h->prop[h->nprops++] = (uint16_t)(type | ctype << 4 | role << 8);
    el->nprops++;
    return SUBD_OK;
}

/* Parses the header; d->line names the offending line. */
static int ply_header(ply_head *h, const char *buf, uint32_t len, subd_diag *d)
{
    text_cursor *t = &h->t;
    int format = 0, st;
    uint32_t i;
    h->nelems = h->nprops = h->binary = h->nv = h->nf = 0;
    subd_text_init(t, buf, len);
    d->line = 1;
    if (!subd_text_next_line(t)) return SUBD_ERR_EMPTY;
    if (!subd_text_token_is(t->line, subd_text_token_end(t->line, t->line_end), "ply") ||
        subd_text_skip_ws(subd_text_token_end(t->line, t->line_end), t->line_end) != t->line_end)
        return SUBD_ERR_PARSE;
    for (;;) {
        const char *s, *e, *k, *ke, *a, *ae;
        if (!subd_text_next_line(t)) { d->line = t->lineno + 1u; return SUBD_ERR_PARSE; } /* no end_header */
        d->line = t->lineno;
        s = t->line;
        e = t->line_end;
        if (!subd_text_line_is_text(s, e)) return SUBD_ERR_PARSE;
        if (!ply_token(&s, e, &k, &ke)) return SUBD_ERR_PARSE;
        if (subd_text_token_is(k, ke, "comment") || subd_text_token_is(k, ke, "obj_info")) continue;
        if (subd_text_token_is(k, ke, "end_header")) {
            if (subd_text_skip_ws(s, e) != e) return SUBD_ERR_PARSE;
            break;
        }
        if (subd_text_token_is(k, ke, "format")) {
            if (format || !ply_token(&s, e, &a, &ae)) return SUBD_ERR_PARSE;
            if (subd_text_token_is(a, ae, "ascii")) h->binary = 0;
            else if (subd_text_token_is(a, ae, "binary_little_endian")) h->binary = 1;
            else return SUBD_ERR_PARSE; /* binary_big_endian (refused, see the top) or unknown */
            if (!ply_token(&s, e, &a, &ae) || !subd_text_token_is(a, ae, "1.0") || subd_text_skip_ws(s, e) != e)
                return SUBD_ERR_PARSE;
            format = 1;
        } else if (subd_text_token_is(k, ke, "element")) {
            ply_elem *el = &h->el[h->nelems];
            if (!format || h->nelems == PLY_MAX_ELEMS || !ply_token(&s, e, &a, &ae)) return SUBD_ERR_PARSE;
            el->kind = subd_text_token_is(a, ae, "vertex") ? PLY_KIND_VERTEX
                       : subd_text_token_is(a, ae, "face") ? PLY_KIND_FACE : PLY_KIND_OTHER;
            for (i = 0; i < h->nelems; i++)
                if (el->kind != PLY_KIND_OTHER && h->el[i].kind == el->kind) return SUBD_ERR_PARSE;
            if (!ply_token(&s, e, &a, &ae) || !ply_uint(a, ae, &el->count) || subd_text_skip_ws(s, e) != e)
                return SUBD_ERR_PARSE;
            el->line = t->lineno;
            el->first = (uint8_t)h->nprops;
            el->nprops = 0;
            el->roles = 0;
            if (el->kind == PLY_KIND_VERTEX) h->nv = el->count;
            if (el->kind == PLY_KIND_FACE) h->nf = el->count;
            h->nelems++;
        } else if (subd_text_token_is(k, ke, "property")) {
            if (h->nelems == 0u) return SUBD_ERR_PARSE;
            if ((st = ply_property(h, &h->el[h->nelems - 1u], s, e)) != SUBD_OK) return st;
        } else {
            return SUBD_ERR_PARSE;
        }
    }
    h->end_line = t->lineno;
    if (!format) return SUBD_ERR_PARSE;
    for (i = 0; i < h->nelems; i++) {
        const ply_elem *el = &h->el[i];
        d->line = el->line;
        if (el->kind == PLY_KIND_VERTEX && el->roles != 0x0eu) return SUBD_ERR_PARSE; /* x, y, z */
        if (el->kind == PLY_KIND_FACE && el->roles != (1u << PLY_ROLE_INDEX)) return SUBD_ERR_PARSE;
    }
    d->line = h->end_line;
    if (h->nv == 0u) return SUBD_ERR_EMPTY;
    d->line = 0;
    return SUBD_OK;
}

/* ---------------------------------------------------------------------------- body */

/* Where the walk is and what it fills. */
typedef struct ply_walk {
    const ply_head *h;
    mesh_counts c;        /* records / corners so far                                  */
    subd_mesh *m;         /* NULL while counting                                       */
    uint32_t tgt_face, tgt_vert, *tgt_line; /* line_of: stop at this record (ASCII)    */
} ply_walk;

/* One value of a record: a coordinate (role x..z), an index, or skipped. Binary: from *p;
 * ASCII: the next token of [*p, e). */
static int ply_value(ply_walk *w, uint32_t type, uint32_t role, const char **p, const char *e, uint32_t vi,
                     uint32_t ci)
{
    const ply_head *h = w->h;
    subd_real x = 0;
    int st;
    if (h->binary) {
        const char *q = *p;
        uint32_t n = ply_size[type];
        if ((uint32_t)(e - q) < n) return SUBD_ERR_PARSE;
        *p = q + n;
        if (role == PLY_ROLE_OTHER) return SUBD_OK;
        if (role == PLY_ROLE_INDEX) {
            uint32_t v = n == 1u ? (uint32_t)(uint8_t)q[0] : n == 2u ? subd_le_u16(q) : subd_le_u32(q);
            int neg = (type % 2u == 1u) && (v >> (8u * n - 1u)); /* signed types are odd */
            if (neg || v >= h->nv) return SUBD_ERR_INDEX;
            if (w->m) w->m->corner_vert[ci] = v;
            return SUBD_OK;
        }
        st = type == PLY_DOUBLE ? subd_real_from_f64_bits(subd_le_u64(q), &x) : subd_real_from_f32_bits(subd_le_u32(q), &x);
    } else {
        const char *ts, *te;
        if (role == PLY_ROLE_OTHER) return ply_token(p, e, &ts, &te) ? SUBD_OK : SUBD_ERR_PARSE;
        if (role == PLY_ROLE_INDEX) {
            int32_t v;
            if (!ply_token(p, e, &ts, &te)) return SUBD_ERR_PARSE;
            if ((st = subd_text_parse_int(ts, te, &v)) != SUBD_OK) return st;
            if (v < 0 || (uint32_t)v >= h->nv) return SUBD_ERR_INDEX;
            if (w->m) w->m->corner_vert[ci] = (uint32_t)v;
            return SUBD_OK;
        }
        st = subd_text_parse_real(p, e, &x);
    }
    if (st == SUBD_OK && w->m) w->m->pos[3u * vi + role - PLY_ROLE_X] = x;
    return st;
}

/* A list's count. */
static int ply_count(const ply_head *h, uint32_t ctype, const char **p, const char *e, uint32_t *n)
{
    if (h->binary) {
        const char *q = *p;
        uint32_t s = ply_size[ctype], v;
        if ((uint32_t)(e - q) < s) return SUBD_ERR_PARSE;
        v = s == 1u ? (uint32_t)(uint8_t)q[0] : s == 2u ? subd_le_u16(q) : subd_le_u32(q);
        if ((ctype % 2u == 1u) && (v >> (8u * s - 1u))) return SUBD_ERR_PARSE; /* negative */
        *p = q + s;
        *n = v;
    } else {
        const char *ts, *te;
        int32_t v;
        if (!ply_token(p, e, &ts, &te) || subd_text_parse_int(ts, te, &v) != SUBD_OK || v < 0) return SUBD_ERR_PARSE;
        *n = (uint32_t)v;
    }
    return SUBD_OK;
}

/* One record of element el (index i); [*p, e) is the rest of the body (binary) or of the
 * record's line (ASCII). */
static int ply_record(ply_walk *w, const ply_elem *el, uint32_t i, const char **p, const char *e)
{
    uint32_t k, j;
    int st;
    for (k = el->first; k < (uint32_t)el->first + el->nprops; k++) {
        uint32_t pr = w->h->prop[k], type = pr & 15u, ctype = (pr >> 4) & 15u, role = pr >> 8, n;
        if (!ctype) {
            if ((st = ply_value(w, type, role, p, e, i, 0)) != SUBD_OK) return st;
            continue;
        }
        if ((st = ply_count(w->h, ctype, p, e, &n)) != SUBD_OK) return st;
        if (role == PLY_ROLE_INDEX) {
            if (n < 3u || n > SUBD_MAX_FACE_SIZE) return SUBD_ERR_FACE_SIZE;
            if (w->c.nc > UINT32_MAX - n) return SUBD_ERR_TOO_BIG;
        } else if (w->h->binary && (uint64_t)n * ply_size[type] > (uint64_t)(e - *p)) {
            return SUBD_ERR_PARSE; /* a skipped list past the end: no need to walk it */
        }
        for (j = 0; j < n; j++)
            if ((st = ply_value(w, type, role, p, e, i, w->c.nc + j)) != SUBD_OK) return st;
        if (role == PLY_ROLE_INDEX) {
            w->c.nc += n;
            if (w->m) w->m->face_start[i + 1u] = w->c.nc;
        }
    }
    return SUBD_OK;
}

/* Names the record of a body error: ASCII the line (set by the caller), binary the vertex or
 * face, else the element's line. */
static void ply_blame(const ply_head *h, const ply_elem *el, uint32_t i, subd_diag *d)
{
    if (!h->binary) return;
    if (el->kind == PLY_KIND_VERTEX) d->vertex = i;
    else if (el->kind == PLY_KIND_FACE) d->face = i;
    else d->line = el->line;
}

static int ply_body(ply_walk *w, const char *buf, uint32_t len, subd_diag *d)
{
    const ply_head *h = w->h;
    text_cursor t = h->t;
    const char *p = t.p, *end = len ? buf + len : buf;
    uint32_t ei, i;
    int st;
    for (ei = 0; ei < h->nelems; ei++) {
        const ply_elem *el = &h->el[ei];
        if (el->nprops == 0u) continue; /* records of nothing */
        for (i = 0; i < el->count; i++) {
            if (h->binary) {
                st = ply_record(w, el, i, &p, end);
            } else {
                const char *s;
                do {
                    if (!subd_text_next_line(&t)) { d->line = t.lineno + 1u; return SUBD_ERR_PARSE; }
                    s = subd_text_skip_ws(t.line, t.line_end);
                } while (s == t.line_end);
                d->line = t.lineno;
                if ((el->kind == PLY_KIND_FACE && i == w->tgt_face) || (el->kind == PLY_KIND_VERTEX && i == w->tgt_vert)) {
                    *w->tgt_line = t.lineno;
                    return SUBD_OK;
                }
                st = subd_text_line_is_text(t.line, t.line_end) ? ply_record(w, el, i, &s, t.line_end) : SUBD_ERR_PARSE;
                if (st == SUBD_OK && subd_text_skip_ws(s, t.line_end) != t.line_end) st = SUBD_ERR_PARSE;
            }
            if (st != SUBD_OK) {
                ply_blame(h, el, i, d);
                return st;
            }
        }
    }
    if (h->binary) {
        if (p != end) { d->line = h->end_line; return SUBD_ERR_PARSE; } /* trailing bytes */
    } else {
        while (subd_text_next_line(&t))
            if (subd_text_skip_ws(t.line, t.line_end) != t.line_end) { d->line = t.lineno; return SUBD_ERR_PARSE; }
    }
    d->line = 0;
    return SUBD_OK;
}

static int ply_walk_all(const char *buf, uint32_t len, mesh_counts *c, subd_mesh *m, subd_diag *d, uint32_t tf,
                        uint32_t tv, uint32_t *tline)
{
    ply_head h;
    ply_walk w;
    int st;
    if ((st = ply_header(&h, buf, len, d)) != SUBD_OK) return subd_fail(d, st);
    w.h = &h;
    w.c.nv = h.nv;
    w.c.nf = h.nf;
    w.c.nc = w.c.nl = w.c.nlv = 0;
    w.m = m;
    w.tgt_face = tf;
    w.tgt_vert = tv;
    w.tgt_line = tline;
    if ((st = ply_body(&w, buf, len, d)) != SUBD_OK) return subd_fail(d, st);
    *c = w.c;
    return SUBD_OK;
}

static int ply_scan(const char *buf, uint32_t len, mesh_counts *c, subd_mesh *m, subd_diag *d)
{
    uint32_t unused;
    if (m) m->face_start[0] = 0;
    return ply_walk_all(buf, len, c, m, d, SUBD_NONE, SUBD_NONE, &unused);
}

static uint32_t ply_line_of_fn(const char *buf, uint32_t len, const mesh_counts *c, const subd_diag *d)
{
    subd_diag scratch;
    mesh_counts cc;
    uint32_t line = 0;
    (void)c;
    subd_diag_clear(&scratch);
    if (d->face != SUBD_NONE) (void)ply_walk_all(buf, len, &cc, 0, &scratch, d->face, SUBD_NONE, &line);
    else if (d->vertex != SUBD_NONE) (void)ply_walk_all(buf, len, &cc, 0, &scratch, SUBD_NONE, d->vertex, &line);
    return line;
}

static const subd_reader ply_reader = {ply_scan, ply_line_of_fn};

int subd_ply_plan(const char *buf, uint32_t len, uint32_t *bytes, subd_diag *diag)
{
    return subd_reader_plan(&ply_reader, buf, len, bytes, diag);
}

int subd_ply_read(subd_arena *arena, const char *buf, uint32_t len, subd_mesh *out, subd_diag *diag)
{
    return subd_reader_read(&ply_reader, arena, buf, len, out, diag);
}

uint32_t subd_ply_line_of(const char *buf, uint32_t len, const subd_diag *diag)
{
    return subd_reader_line_of(&ply_reader, buf, len, diag);
}
