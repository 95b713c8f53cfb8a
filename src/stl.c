/* SPDX-License-Identifier: MIT */
/* STL on memory buffers: reader (binary and ASCII) and binary writer.
 *
 * Which kind: a buffer of 84 + 50 n bytes whose 32-bit count at byte 80 is n is binary, even
 * when its 80-byte header starts with "solid" (many CAD exporters write such headers).
 * Otherwise a buffer that starts with "solid" is ASCII, unless it holds bytes no text has
 * (NUL or control characters other than tab, CR, LF, FF, VT): then it is a binary file with
 * a "solid" header whose count the size contradicts, and is reported as one. Everything else
 * is binary. A text file is never taken for binary by the size rule: its bytes 80..83 are
 * text (>= 0x09), so the count would be at least 0x09000000 and 84 + 50 n over 4 GB. Binary
 * errors name the facet (diag.face, 0-based); ASCII errors name the line.
 * Normals and the attribute bytes are ignored (ASCII normals may even be "nan").
 *
 * Welding. STL stores every facet's three corners by value; the mesh needs shared vertices
 * for its adjacency. Corners are welded when their three coordinates, as subd_reals, have
 * the same bits (-0 and +0 count as the same coordinate; the vertex keeps the bits of its
 * first corner). The 3F corners are sorted by their 96-bit keys with a stable LSD radix sort
 * (12 byte-wide counting passes, a pass skipped when every key has the same byte there), so
 * equal keys keep file order and the first corner of each group is its representative;
 * vertices are numbered in the order of their first corner in the file. No hashing, no
 * comparison sort: the result is the same on every target and O(F) whatever the input.
 *
 * Memory. The number of vertices is known only after the weld, but the plan has no memory
 * to weld in; so the plan is the bytes for the worst case, no corner welded (V = 3F): the
 * mesh arrays and subd_mesh_build's scratch for that V, which also holds the weld's arrays
 * (the keys, two index arrays, 256 counters). The read takes the whole plan first, so its
 * peak is exactly the plan for every file, welds in the top of it, then builds the welded
 * mesh from the bottom; the mesh left in the arena is that of the real V. The weld's arrays
 * sit so that each is read before the mesh arrays reach it (see stl_build).
 *
 * The writer writes binary STL: an 80-byte header that does not start with "solid", the
 * triangle count, and per triangle (polygons as fans from their first corner) the unit
 * normal (vec3w.h's subd_w3_unit) and the corners as float32 (subd_real_to_f32_bits).
 */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "mesh_internal.h"
#include "entry.h"
#include "layout.h"
#include "vec3w.h"
#include "bin_le.h"

#define STL_HEAD 84u   /* 80-byte header + uint32 facet count */
#define STL_REC 50u    /* normal, 3 corners (12 float32), uint16 attribute */
#define STL_RADIX 256u /* counters of one radix pass */

static int stl_is_space(char c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v';
}

static char stl_lower(char c) { return (c >= 'A' && c <= 'Z') ? (char)(c - 'A' + 'a') : c; }

/* Case-insensitive: [s, e) is the word w. */
static int stl_word(const char *s, const char *e, const char *w)
{
    while (s < e && *w && stl_lower(*s) == *w) { s++; w++; }
    return s == e && *w == 0;
}

/* ---------------------------------------------------------------------------- ASCII */

/* A token cursor that counts lines (LF, CRLF or a lone CR end a line). */
typedef struct stl_tok {
    const char *p, *end; /* still to read                        */
    const char *s, *e;   /* the current token                    */
    uint32_t line;       /* line of p                            */
    uint32_t tline;      /* line of the current token            */
} stl_tok;

static int stl_next(stl_tok *t)
{
    const char *p = t->p;
    while (p < t->end && stl_is_space(*p)) {
        if (*p == '\n' || (*p == '\r' && (p + 1 == t->end || p[1] != '\n'))) t->line++;
        p++;
    }
    t->tline = t->line;
    if (p >= t->end) { t->p = p; return 0; }
    t->s = p;
    while (p < t->end && !stl_is_space(*p)) p++;
    t->e = p;
    t->p = p;
    return 1;
}

/* Skips to the end of the line (a solid's name). */
static void stl_skip_line(stl_tok *t)
{
    while (t->p < t->end && *t->p != '\n' && *t->p != '\r') t->p++;
}

static int stl_expect(stl_tok *t, const char *w, subd_diag *d)
{
    int ok = stl_next(t);
    d->line = t->tline;
    return ok && stl_word(t->s, t->e, w) ? SUBD_OK : SUBD_ERR_PARSE;
}

/* One number token. A normal (keep == 0) may be nan/inf or out of range: it is ignored. */
static int stl_number(stl_tok *t, int keep, subd_real *x, subd_diag *d)
{
    const char *p;
    int st;
    if (!stl_next(t)) { d->line = t->tline; return SUBD_ERR_PARSE; }
    d->line = t->tline;
    p = t->s;
    st = subd_real_parse(&p, t->e, x);
    if (!keep && (st == SUBD_ERR_NAN || st == SUBD_ERR_RANGE)) return SUBD_OK;
    if (st != SUBD_OK) return st;
    return p == t->e ? SUBD_OK : SUBD_ERR_PARSE;
}

/* One facet after its "facet" keyword; coordinates to xyz[0..9) when xyz != NULL. */
static int stl_facet(stl_tok *t, subd_real *xyz, subd_diag *d)
{
    uint32_t fline = t->tline, n = 0, k;
    subd_real x;
    int st;
    if ((st = stl_expect(t, "normal", d)) != SUBD_OK) return st;
    for (k = 0; k < 3u; k++)
        if ((st = stl_number(t, 0, &x, d)) != SUBD_OK) return st;
    if ((st = stl_expect(t, "outer", d)) != SUBD_OK || (st = stl_expect(t, "loop", d)) != SUBD_OK) return st;
    for (;;) {
        if (!stl_next(t)) { d->line = t->tline; return SUBD_ERR_PARSE; }
        d->line = t->tline;
        if (stl_word(t->s, t->e, "endloop")) break;
        if (!stl_word(t->s, t->e, "vertex")) return SUBD_ERR_PARSE;
        if (n == 3u) { d->line = fline; return SUBD_ERR_FACE_SIZE; }
        for (k = 0; k < 3u; k++) {
            if ((st = stl_number(t, 1, &x, d)) != SUBD_OK) return st;
            if (xyz) xyz[3u * n + k] = x;
        }
        n++;
    }
    if (n != 3u) { d->line = fline; return SUBD_ERR_FACE_SIZE; }
    return stl_expect(t, "endfacet", d);
}

/* Walks the ASCII file: solids of facets. Counts the facets into *nf; stores the
 * coordinates, 9 per facet, when xyz != NULL; stops at facet `target` (SUBD_NONE: none) and
 * gives its line in *tline. Errors set d->line. */
static int stl_ascii_walk(const char *buf, uint32_t len, subd_real *xyz, uint32_t target, uint32_t *nf,
                          uint32_t *tline, subd_diag *d)
{
    stl_tok t;
    uint32_t n = 0;
    int st;
    t.p = buf;
    t.end = len ? buf + len : buf;
    t.s = t.e = buf;
    t.line = 1;
    t.tline = 1;
    while (stl_next(&t)) {
        d->line = t.tline;
        if (!stl_word(t.s, t.e, "solid")) return SUBD_ERR_PARSE;
        stl_skip_line(&t);
        for (;;) {
            if (!stl_next(&t)) { d->line = t.tline; return SUBD_ERR_PARSE; } /* no endsolid */
            d->line = t.tline;
            if (stl_word(t.s, t.e, "endsolid")) break;
            if (!stl_word(t.s, t.e, "facet")) return SUBD_ERR_PARSE;
            if (n == target) { *tline = t.tline; return SUBD_OK; }
            if (n == UINT32_MAX / 3u) return SUBD_ERR_TOO_BIG;
            if ((st = stl_facet(&t, xyz ? xyz + 9u * n : 0, d)) != SUBD_OK) return st;
            n++;
        }
        stl_skip_line(&t);
    }
    d->line = t.tline;
    if (n == 0u) return SUBD_ERR_EMPTY;
    d->line = 0;
    *nf = n;
    return SUBD_OK;
}

/* Line of facet f in an ASCII file (0 when there is none). */
static uint32_t stl_facet_line(const char *buf, uint32_t len, uint32_t f)
{
    subd_diag d;
    uint32_t nf, line = 0;
    subd_diag_clear(&d);
    if (stl_ascii_walk(buf, len, 0, f, &nf, &line, &d) != SUBD_OK) return 0;
    return line;
}

/* ---------------------------------------------------------------------------- binary */

static int stl_binary_bytes(const char *buf, uint32_t len)
{
    uint32_t i;
    for (i = 0; i < len; i++) {
        uint8_t c = (uint8_t)buf[i];
        if ((c < 0x20u && !stl_is_space((char)c)) || c == 0x7fu) return 1;
    }
    return 0;
}

/* Decodes (and checks) the 9 coordinates of every facet; into xyz when not NULL. */
static int stl_binary_coords(const char *buf, uint32_t nf, subd_real *xyz, subd_diag *d)
{
    uint32_t f, k;
    for (f = 0; f < nf; f++) {
        const char *p = buf + STL_HEAD + STL_REC * f + 12u;
        for (k = 0; k < 9u; k++) {
            subd_real x = 0;
            int st = subd_real_from_f32_bits(subd_le_u32(p + 4u * k), &x);
            if (st != SUBD_OK) { d->face = f; return st; }
            if (xyz) xyz[9u * f + k] = x;
        }
    }
    return SUBD_OK;
}

/* Decides the kind, counts the facets and checks the whole file (coordinates included); with
 * xyz, stores the coordinates (binary: the counting call decided the kind already). */
static int stl_scan(const char *buf, uint32_t len, int *binary, uint32_t *nf, subd_real *xyz, subd_diag *d)
{
    uint32_t n, i = 0;
    if (len == 0u) return SUBD_ERR_EMPTY;
    n = len >= STL_HEAD ? subd_le_u32(buf + 80) : 0u;
    *binary = 1;
    if (len < STL_HEAD || (uint64_t)STL_HEAD + (uint64_t)STL_REC * n != len) {
        while (i < len && stl_is_space(buf[i])) i++;
        if (len - i >= 5u && stl_word(buf + i, buf + i + 5, "solid") && (len - i == 5u || stl_is_space(buf[i + 5])) &&
            !(len >= STL_HEAD && stl_binary_bytes(buf, len))) {
            *binary = 0;
            return stl_ascii_walk(buf, len, xyz, SUBD_NONE, nf, &i, d);
        }
        if (len < STL_HEAD) return SUBD_ERR_PARSE; /* not even a header */
        /* truncated: the first incomplete facet; too long: the first facet beyond the count */
        d->face = (uint64_t)STL_HEAD + (uint64_t)STL_REC * n > len ? (len - STL_HEAD) / STL_REC : n;
        return SUBD_ERR_PARSE;
    }
    if (n == 0u) return SUBD_ERR_EMPTY;
    if (n > UINT32_MAX / 3u) return SUBD_ERR_TOO_BIG;
    *nf = n;
    return stl_binary_coords(buf, n, xyz, d);
}

/* ---------------------------------------------------------------------------- weld */

typedef struct stl_weld {
    uint32_t *cnt;  /* STL_RADIX counters                                         */
    uint32_t *ord;  /* R: sort order (ping)                                        */
    subd_real *xyz; /* 3R: corner coordinates, corner r at xyz[3r..3r+2]           */
    uint32_t *id;   /* R: sort order (pong), at the end the vertex of each corner  */
} stl_weld;

/* The weld's arrays for R corners, in this order (id last: at the top of the plan). */
static int stl_weld_layout(subd_arena *a, uint32_t r, stl_weld *w, uint32_t *bytes)
{
    subd_layout l;
    subd_layout_begin(&l, a);
    w->cnt = subd_layout_take(&l, STL_RADIX, 4u);
    w->ord = subd_layout_take(&l, r, 4u);
    w->xyz = subd_layout_take(&l, r, 3u * (uint32_t)sizeof(subd_real));
    w->id = subd_layout_take(&l, r, 4u);
    return subd_layout_end(&l, bytes);
}

/* The plan for nf facets: the unwelded mesh (V = C = 3 nf) with its build scratch, or the
 * weld at the top with room for 3 nf positions below it if that is more (small files: the
 * 1 KiB of counters). stl_build relies on both terms: the positions of any V <= 3 nf end
 * below the weld's arrays, and the mesh arrays of any V end below id. */
static uint32_t stl_plan_bytes(uint32_t nf)
{
    mesh_counts c;
    stl_weld w;
    uint32_t weld = 0;
    c.nv = c.nc = 3u * nf;
    c.nf = nf;
    c.nl = c.nlv = 0;
    (void)stl_weld_layout(0, c.nc, &w, &weld);
    subd_size_add(&weld, c.nv, 3u * (uint32_t)sizeof(subd_real));
    return subd_bytes_max(subd_mesh_counts_bytes(&c), weld);
}

/* Key word k of corner r: the coordinate's bits, -0 as +0. */
static uint32_t stl_key(const subd_real *xyz, uint32_t r, uint32_t k)
{
    subd_real x = xyz[3u * r + k];
    return x == (subd_real)0 ? 0u : subd_real_bits(x);
}

static int stl_same(const subd_real *xyz, uint32_t r, uint32_t q)
{
    uint32_t k;
    for (k = 0; k < 3u; k++)
        if (stl_key(xyz, r, k) != stl_key(xyz, q, k)) return 0;
    return 1;
}

/* Welds the R corners in w->xyz: w->id[r] = the vertex of corner r, vertices numbered by
 * first corner. Returns the vertex count. */
static uint32_t stl_weld_run(stl_weld *w, uint32_t R)
{
    uint32_t *src = w->ord, *dst = w->id, *rep, pass, i, nv = 0, lead = 0;
    for (i = 0; i < R; i++) src[i] = i;
    for (pass = 0; pass < 12u; pass++) { /* stable LSD radix sort, one byte per pass */
        uint32_t k = pass / 4u, sh = 8u * (pass % 4u), sum = 0, *tmp;
        for (i = 0; i < STL_RADIX; i++) w->cnt[i] = 0;
        for (i = 0; i < R; i++) w->cnt[(stl_key(w->xyz, i, k) >> sh) & 0xffu]++;
        if (w->cnt[(stl_key(w->xyz, 0, k) >> sh) & 0xffu] == R) continue; /* one byte value */
        for (i = 0; i < STL_RADIX; i++) {
            uint32_t c = w->cnt[i];
            w->cnt[i] = sum;
            sum += c;
        }
        for (i = 0; i < R; i++) {
            uint32_t r = src[i];
            dst[w->cnt[(stl_key(w->xyz, r, k) >> sh) & 0xffu]++] = r;
        }
        tmp = src;
        src = dst;
        dst = tmp;
    }
    /* src is sorted, equal keys in file order: the first of each run leads it */
    rep = dst;
    for (i = 0; i < R; i++) {
        if (i == 0u || !stl_same(w->xyz, src[i], src[i - 1u])) lead = src[i];
        rep[src[i]] = lead;
    }
    /* leads -> vertex numbers, in place: a lead is never after its corner */
    for (i = 0; i < R; i++) rep[i] = rep[i] == i ? nv++ : rep[rep[i]];
    if (rep != w->id)
        for (i = 0; i < R; i++) w->id[i] = rep[i]; /* ord lies below id: no overlap */
    return nv;
}

/* ---------------------------------------------------------------------------- read */

/* After the weld: the mesh of nv vertices from the arena mark, filled and validated. The
 * plan block is [mark, mark + plan); the weld's arrays end at its top. The positions (in the
 * first 12 * 3nf bytes) are written first, while xyz (above them, see stl_plan_bytes) is
 * still intact; corner_vert ends below id, which is read last. */
static int stl_build(subd_arena *a, const stl_weld *w, uint32_t nf, uint32_t nv, subd_mesh *m, subd_diag *d)
{
    mesh_counts c;
    uint32_t r, next = 0, k, R = 3u * nf;
    int st;
    c.nv = nv;
    c.nf = nf;
    c.nc = R;
    c.nl = c.nlv = 0;
    if ((st = subd_mesh_alloc_arrays(a, &c, m)) != SUBD_OK) return st;
    for (r = 0; r < R; r++)
        if (w->id[r] == next) {
            for (k = 0; k < 3u; k++) m->pos[3u * next + k] = w->xyz[3u * r + k];
            next++;
        }
    for (r = 0; r <= nf; r++) m->face_start[r] = 3u * r;
    for (r = 0; r < R; r++) m->corner_vert[r] = w->id[r];
    m->line_start[0] = 0;
    return subd_mesh_finish(a, m, d);
}

/* A validation error names a face (= facet) or a vertex: the facet that uses the vertex
 * first goes to diag.face too, and for ASCII the facet's line to diag.line. */
static void stl_locate(const char *buf, uint32_t len, int binary, const subd_mesh *m, subd_diag *d)
{
    uint32_t c;
    if (d->face == SUBD_NONE && d->vertex != SUBD_NONE)
        for (c = 0; c < m->num_corners && d->face == SUBD_NONE; c++)
            if (m->corner_vert[c] == d->vertex) d->face = c / 3u;
    if (!binary && d->face != SUBD_NONE) d->line = stl_facet_line(buf, len, d->face);
}

int subd_stl_plan(const char *buf, uint32_t len, uint32_t *bytes, subd_diag *diag)
{
    subd_diag own;
    subd_diag *d = diag ? diag : &own;
    uint32_t nf = 0, b;
    int binary, st;
    subd_diag_clear(d);
    if ((!buf && len) || !bytes) return subd_fail(d, SUBD_ERR_PARAM);
    if ((st = stl_scan(buf, len, &binary, &nf, 0, d)) != SUBD_OK) return subd_fail(d, st);
    if ((b = stl_plan_bytes(nf)) == UINT32_MAX) return subd_fail(d, SUBD_ERR_TOO_BIG);
    *bytes = b;
    return SUBD_OK;
}

int subd_stl_read(subd_arena *a, const char *buf, uint32_t len, subd_mesh *out, subd_diag *diag)
{
    subd_entry e;
    subd_diag *d = subd_entry_begin(&e, a, diag);
    uint32_t nf = 0, plan, weld = 0, nv, mark, unused;
    int binary, st;
    stl_weld w;
    subd_mesh m;

    if (!a || !out || (!buf && len)) return subd_entry_fail(&e, SUBD_ERR_PARAM);
    if ((st = stl_scan(buf, len, &binary, &nf, 0, d)) != SUBD_OK) return subd_entry_fail(&e, st);
    if ((plan = stl_plan_bytes(nf)) == UINT32_MAX) return subd_entry_fail(&e, SUBD_ERR_TOO_BIG);
    mark = subd_arena_mark(a);
    /* the whole plan first: the peak is the plan whatever the weld finds */
    if (!subd_arena_alloc(a, plan)) {
        d->bytes_needed = plan;
        return subd_entry_fail(&e, SUBD_ERR_NOMEM);
    }
    subd_arena_rewind(a, mark);
    (void)stl_weld_layout(0, 3u * nf, &w, &weld);
    if (plan > weld && !subd_arena_alloc(a, plan - weld)) return subd_entry_fail(&e, SUBD_ERR_NOMEM);
    if ((st = stl_weld_layout(a, 3u * nf, &w, 0)) != SUBD_OK) return subd_entry_fail(&e, st);
    if (binary) st = stl_binary_coords(buf, nf, w.xyz, d);
    else st = stl_ascii_walk(buf, len, w.xyz, SUBD_NONE, &nf, &unused, d);
    if (st != SUBD_OK) return subd_entry_fail(&e, st); /* the counting scan passed: unreachable */
    nv = stl_weld_run(&w, 3u * nf);
    subd_arena_rewind(a, mark);
    if ((st = stl_build(a, &w, nf, nv, &m, d)) != SUBD_OK) {
        if (st != SUBD_ERR_NOMEM) stl_locate(buf, len, binary, &m, d);
        return subd_entry_fail(&e, st);
    }
    *out = m;
    return subd_entry_ok(&e);
}

/* ---------------------------------------------------------------------------- write */

static void stl_put_xyz(char *o, const subd_real *p)
{
    uint32_t k;
    for (k = 0; k < 3u; k++) subd_le_put_u32(o + 4u * k, subd_real_to_f32_bits(p[k]));
}

/* One facet: the unit normal of (p0, p1, p2), the corners, attribute 0. */
static void stl_put_facet(char *o, const subd_real *p0, const subd_real *p1, const subd_real *p2)
{
    subd_wide u[3], v[3], c[3];
    subd_real n[3];
    subd_w3_diff(p1, p0, u);
    subd_w3_diff(p2, p0, v);
    subd_w3_fit(u, u, 30u); /* keeps the cross product in range (vec3w.h) */
    subd_w3_fit(v, v, 30u);
    subd_w3_cross(u, v, c);
    subd_w3_unit(c, n);
    stl_put_xyz(o, n);
    stl_put_xyz(o + 12, p0);
    stl_put_xyz(o + 24, p1);
    stl_put_xyz(o + 36, p2);
    o[48] = 0;
    o[49] = 0;
}

int subd_stl_write(const subd_mesh *m, char *buf, uint32_t cap, uint32_t *len)
{
    static const char head[] = "binary STL written by tinysubd";
    uint64_t tris = 0, bytes;
    uint32_t f, c, i;
    char *o;
    if (!m || !len) return SUBD_ERR_PARAM;
    for (f = 0; f < m->num_faces; f++) tris += subd_face_size(m, f) - 2u;
    bytes = STL_HEAD + STL_REC * tris;
    if (bytes > UINT32_MAX) return SUBD_ERR_TOO_BIG;
    *len = (uint32_t)bytes;
    if (!buf) return SUBD_OK;
    if (bytes > cap) return SUBD_ERR_NOMEM;
    for (i = 0; i < 80u; i++) buf[i] = i < sizeof head - 1u ? head[i] : ' ';
    subd_le_put_u32(buf + 80, (uint32_t)tris);
    o = buf + STL_HEAD;
    for (f = 0; f < m->num_faces; f++) {
        const subd_real *p0 = &m->pos[3u * m->corner_vert[m->face_start[f]]];
        for (c = m->face_start[f] + 1u; c + 1u < m->face_start[f + 1u]; c++) {
            stl_put_facet(o, p0, &m->pos[3u * m->corner_vert[c]], &m->pos[3u * m->corner_vert[c + 1u]]);
            o += STL_REC;
        }
    }
    return SUBD_OK;
}
