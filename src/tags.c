/* SPDX-License-Identifier: MIT */
/* Tag files on memory buffers: 'crease I J', 'corner I', 'fixed I' lines (include/subd_tags.h)
 * turned into the mesh's SUBD_ETAG_CREASE, SUBD_VTAG_CORNER and SUBD_VTAG_FIXED bits, the
 * features the schemes honour (Hoppe et al. creases and corners, the quasi 4-8 paper's
 * section 4.3 tagged features).
 *
 * Choices:
 * - Two passes of one scan routine: the first only checks every line, the second (only when
 *   the first found nothing wrong) sets the bits. A bad file therefore changes nothing, and
 *   no list of parsed tags has to be stored, so no arena is needed.
 * - Lines are cut by the same cursor as the OBJ and OFF readers (text.h): LF, CRLF and lone
 *   CR line ends, spaces, tabs and CR between fields; '#' ends the line's content wherever it
 *   appears, as in OBJ.
 * - Vertex numbers are plain decimal digits (no sign), 1-based as in OBJ. A field that is not
 *   a number is a syntax error (SUBD_ERR_PARSE); a number outside 1..num_verts, and a crease
 *   pair that is not an edge of the mesh, are bad references (SUBD_ERR_INDEX). There is no
 *   line length limit: nothing is copied.
 * - A crease pair is looked up by walking the one-ring of I and then of J (a boundary edge
 *   exists as one half-edge only, in either direction): O(valence), no edge table.
 */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include <stddef.h>
#include "mesh_internal.h"
#include "text.h"

/* Parses a vertex number field [s, e): SUBD_OK with *v 0-based, SUBD_ERR_PARSE when it is not
 * all digits, SUBD_ERR_INDEX when it is outside 1..m->num_verts. */
static int tag_vertex(const char *s, const char *e, const subd_mesh *m, uint32_t *v)
{
    uint64_t n = 0;
    for (; s < e; s++) {
        if (*s < '0' || *s > '9') return SUBD_ERR_PARSE;
        if (n <= m->num_verts) n = n * 10u + (uint64_t)(*s - '0'); /* stays below 2^36 */
    }
    if (n == 0 || n > m->num_verts) return SUBD_ERR_INDEX;
    *v = (uint32_t)(n - 1u);
    return SUBD_OK;
}

/* The half-edge from a to b or, when the edge only runs b -> a (a boundary edge), that one;
 * SUBD_NONE when a and b share no edge. */
static uint32_t find_edge(const subd_mesh *m, uint32_t a, uint32_t b)
{
    uint32_t k;
    for (k = 0; k < 2u; k++) {
        uint32_t from = k ? b : a, to = k ? a : b, first = m->vert_out[from], h;
        for (h = first; h != SUBD_NONE; h = subd_ring_next(m, first, h))
            if (subd_he_dest(m, h) == to) return h;
    }
    return SUBD_NONE;
}

/* One pass over the file. out == NULL checks only; out == m sets the bits (called only after
 * a checking pass succeeded, so it cannot fail half-way). */
static int tags_pass(const char *buf, uint32_t len, const subd_mesh *m, subd_mesh *out, subd_tags_report *r,
                     subd_diag *d)
{
    text_cursor t;
    subd_text_init(&t, buf, len);
    r->creases = r->vertex_tags = 0;
    while (subd_text_next_line(&t)) {
        const char *tok[3], *tend[3], *s, *e = t.line;
        uint32_t n = 0, v[2], h = SUBD_NONE;
        int st = SUBD_OK, crease;
        uint8_t vbit = 0;
        while (e < t.line_end && *e != '#') e++;
        /* up to three fields; s < e afterwards means there is a fourth */
        for (s = subd_text_skip_ws(t.line, e); s < e && n < 3u; s = subd_text_skip_ws(tend[n++], e)) {
            tok[n] = s;
            tend[n] = subd_text_token_end(s, e);
        }
        if (n == 0) continue;
        crease = subd_text_token_is(tok[0], tend[0], "crease");
        if (subd_text_token_is(tok[0], tend[0], "corner")) vbit = SUBD_VTAG_CORNER;
        if (subd_text_token_is(tok[0], tend[0], "fixed")) vbit = SUBD_VTAG_FIXED;
        if (s < e || n != (crease ? 3u : 2u) || (!crease && !vbit)) st = SUBD_ERR_PARSE;
        if (st == SUBD_OK) st = tag_vertex(tok[1], tend[1], m, &v[0]);
        if (st == SUBD_OK && crease) st = tag_vertex(tok[2], tend[2], m, &v[1]);
        if (st == SUBD_OK && crease && (h = find_edge(m, v[0], v[1])) == SUBD_NONE) {
            r->edge[0] = d->vertex = v[0];
            r->edge[1] = v[1];
            st = SUBD_ERR_INDEX;
        }
        if (st != SUBD_OK) {
            d->line = t.lineno;
            return subd_fail(d, st);
        }
        if (crease) {
            if (out) subd_edge_tag_set(out, h, SUBD_ETAG_CREASE);
            r->creases++;
        } else {
            if (out) out->vert_tag[v[0]] |= vbit;
            r->vertex_tags++;
        }
    }
    return SUBD_OK;
}

/* The shared entry: clears diag and report, checks the arguments, checks the whole file and,
 * when out is not NULL, applies it. */
static int tags_run(const char *buf, uint32_t len, const subd_mesh *m, subd_mesh *out, subd_tags_report *report,
                    subd_diag *diag)
{
    subd_diag dummy;
    subd_tags_report rdummy;
    subd_diag *d = diag ? diag : &dummy;
    subd_tags_report *r = report ? report : &rdummy;
    int st;
    subd_diag_clear(d);
    r->creases = r->vertex_tags = 0;
    r->edge[0] = r->edge[1] = SUBD_NONE;
    if (!m || (!buf && len)) return subd_fail(d, SUBD_ERR_PARAM);
    if (len == 0) return SUBD_OK; /* an empty file has no tags (and buf may be NULL) */
    st = tags_pass(buf, len, m, NULL, r, d);
    if (st == SUBD_OK && out) st = tags_pass(buf, len, m, out, r, d);
    return st;
}

int subd_tags_check(const char *buf, uint32_t len, const subd_mesh *m, subd_tags_report *report, subd_diag *diag)
{
    return tags_run(buf, len, m, NULL, report, diag);
}

int subd_tags_apply(const char *buf, uint32_t len, subd_mesh *m, subd_tags_report *report, subd_diag *diag)
{
    return tags_run(buf, len, m, m, report, diag);
}
