/* SPDX-License-Identifier: MIT */
/* Tag files on memory buffers: 'crease I J', 'corner I', 'fixed I' lines (include/subd_tags.h)
 * turned into the mesh's SUBD_ETAG_CREASE, SUBD_VTAG_CORNER and SUBD_VTAG_FIXED bits, the
 * features the schemes honour (Hoppe et al. creases and corners, the quasi 4-8 paper's
 * section 4.3 tagged features); and 'alpha V A', 'falpha F A' lines, the semi-stationary
 * paper's per-vertex and per-face parameters (section 3), turned into alpha numerators over
 * a caller's denominator (subd_tags_alpha) for subd_alpha_opts.tag_num.
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
#include "subd_alpha.h"
#include "text.h"
#include "wide.h"

/* Parses an element number field [s, e): SUBD_OK with *v 0-based, SUBD_ERR_PARSE when it is
 * not all digits, SUBD_ERR_INDEX when it is outside 1..count. */
static int tag_index(const char *s, const char *e, uint32_t count, uint32_t *v)
{
    uint64_t n = 0;
    for (; s < e; s++) {
        if (*s < '0' || *s > '9') return SUBD_ERR_PARSE;
        if (n <= count) n = n * 10u + (uint64_t)(*s - '0'); /* stays below 2^36 */
    }
    if (n == 0 || n > count) return SUBD_ERR_INDEX;
    *v = (uint32_t)(n - 1u);
    return SUBD_OK;
}

/* An alpha value [s, e) as a reduced fraction *num / *den of a turn (den >= 1), in the one
 * grammar of subd_tags.h (a tag file's A and the tool's --alpha, by subd_tags_parse_alpha):
 * "N" or "N/D" (|N| <= 10^9, D in 1..10^9), or "Xdeg" (degrees, optional sign, at most 4
 * decimals, no exponent, |X| <= 36000). SUBD_ERR_PARSE otherwise. */
static int alpha_value(const char *s, const char *e, int64_t *num, int64_t *den)
{
    int32_t n, d = 1;
    int64_t g;
    const char *slash;
    if (e - s > 3 && e[-3] == 'd' && e[-2] == 'e' && e[-1] == 'g') {
        int64_t v = 0;
        uint32_t decimals = 0, digits = 0;
        int neg = 0, dot = 0;
        e -= 3;
        if (s < e && (*s == '-' || *s == '+')) neg = *s++ == '-';
        for (; s < e; s++) {
            if (*s == '.' && !dot) {
                dot = 1;
                continue;
            }
            if (*s < '0' || *s > '9' || (dot && decimals == 4u)) return SUBD_ERR_PARSE;
            v = v * 10 + (*s - '0');
            digits++;
            if (dot) decimals++;
            if (v > 360000000) return SUBD_ERR_PARSE; /* 36000 degrees */
        }
        if (!digits) return SUBD_ERR_PARSE;
        for (; decimals < 4u; decimals++) v *= 10;
        if (v > 360000000) return SUBD_ERR_PARSE;
        *num = neg ? -v : v;
        *den = 3600000; /* 10^-4 degree units */
    } else {
        for (slash = s; slash < e && *slash != '/'; slash++) {
        }
        if (subd_text_parse_int(s, slash, &n) != SUBD_OK || n > 1000000000 || n < -1000000000) return SUBD_ERR_PARSE;
        if (slash < e && (slash + 1 == e || slash[1] == '-' || slash[1] == '+' ||
                          subd_text_parse_int(slash + 1, e, &d) != SUBD_OK || d < 1 || d > 1000000000))
            return SUBD_ERR_PARSE;
        *num = n;
        *den = d;
    }
    g = (int64_t)subd_gcd64(*num, *den);
    *num /= g;
    *den /= g;
    return SUBD_OK;
}

int subd_tags_parse_alpha(const char *text, uint32_t len, int32_t *num, int32_t *den)
{
    int64_t n, d;
    int st;
    if (!text || !num || !den) return SUBD_ERR_PARAM;
    st = alpha_value(text, text + len, &n, &d);
    if (st != SUBD_OK) return st;
    *num = (int32_t)n; /* |n| <= 10^9 and 1 <= d <= 10^9 after the grammar's bounds */
    *den = (int32_t)d;
    return SUBD_OK;
}

int32_t subd_tags_common_den(int32_t a, int32_t b)
{
    int64_t l;
    if (a < 1 || b < 1) return 0;
    l = (int64_t)a / (int64_t)subd_gcd64(a, b) * b; /* <= (2^31 - 1)^2 < 2^62 */
    return l <= INT32_MAX ? (int32_t)l : 0;
}

/* Where subd_tags_alpha puts the values (den > 0), or NULL. */
typedef struct alpha_fill {
    int32_t den;
    int32_t *vnum, *fnum;
} alpha_fill;

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

/* One pass over the file. out == NULL and write == 0 checks only (with af: also that every
 * alpha converts to af->den); out == m sets the bits, write != 0 stores the alphas in af's
 * arrays (both called only after a checking pass succeeded, so they cannot fail half-way). */
static int tags_pass(const char *buf, uint32_t len, const subd_mesh *m, subd_mesh *out, const alpha_fill *af,
                     int write, subd_tags_report *r, subd_diag *d)
{
    text_cursor t;
    subd_text_init(&t, buf, len);
    r->creases = r->vertex_tags = r->vertex_alphas = r->face_alphas = 0;
    r->alpha_den = 1;
    r->alpha_line[0] = r->alpha_line[1] = 0;
    while (subd_text_next_line(&t)) {
        const char *tok[3], *tend[3], *s, *e = t.line;
        uint32_t n = 0, v[2] = {0, 0}, h = SUBD_NONE;
        int st = SUBD_OK, crease, alpha, falpha;
        int64_t an = 0, ad = 1;
        uint8_t vbit = 0;
        while (e < t.line_end && *e != '#') e++;
        /* up to three fields; s < e afterwards means there is a fourth */
        for (s = subd_text_skip_ws(t.line, e); s < e && n < 3u; s = subd_text_skip_ws(tend[n++], e)) {
            tok[n] = s;
            tend[n] = subd_text_token_end(s, e);
        }
        if (n == 0) continue;
        crease = subd_text_token_is(tok[0], tend[0], "crease");
        alpha = subd_text_token_is(tok[0], tend[0], "alpha");
        falpha = subd_text_token_is(tok[0], tend[0], "falpha");
        if (subd_text_token_is(tok[0], tend[0], "corner")) vbit = SUBD_VTAG_CORNER;
        if (subd_text_token_is(tok[0], tend[0], "fixed")) vbit = SUBD_VTAG_FIXED;
        if (s < e || n != (crease || alpha || falpha ? 3u : 2u) || (!crease && !alpha && !falpha && !vbit))
            st = SUBD_ERR_PARSE;
        /* the value before the index: a malformed line is a syntax error whatever it names */
        if (st == SUBD_OK && (alpha || falpha)) st = alpha_value(tok[2], tend[2], &an, &ad);
        if (st == SUBD_OK) st = tag_index(tok[1], tend[1], falpha ? m->num_faces : m->num_verts, &v[0]);
        if (st == SUBD_OK && crease) st = tag_index(tok[2], tend[2], m->num_verts, &v[1]);
        if (st == SUBD_OK && (alpha || falpha) && af) {
            /* exact: ad (reduced) must divide den, and the numerator fit the tag range */
            int64_t q = an * (af->den / ad);
            if (af->den % ad != 0 || q > SUBD_ALPHA_MAX_NUM || q < -SUBD_ALPHA_MAX_NUM) st = SUBD_ERR_RANGE;
            else an = q;
        }
        if (st == SUBD_OK && crease && (h = find_edge(m, v[0], v[1])) == SUBD_NONE) {
            r->edge[0] = d->vertex = v[0];
            r->edge[1] = v[1];
            st = SUBD_ERR_INDEX;
        }
        if (st != SUBD_OK) {
            d->line = t.lineno;
            return subd_fail(d, st);
        }
        if (alpha || falpha) {
            int32_t *dst = alpha ? (af ? af->vnum : 0) : (af ? af->fnum : 0);
            r->alpha_den = subd_tags_common_den(r->alpha_den, (int32_t)ad); /* 0: no int32 common den */
            if (write && dst) dst[v[0]] = (int32_t)an;
            if (alpha) r->vertex_alphas++;
            else r->face_alphas++;
            if (!r->alpha_line[falpha]) r->alpha_line[falpha] = t.lineno;
        } else if (crease) {
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
 * when out is not NULL, sets its bits, when af is not NULL, stores its alphas. */
static int tags_run(const char *buf, uint32_t len, const subd_mesh *m, subd_mesh *out, const alpha_fill *af,
                    subd_tags_report *report, subd_diag *diag)
{
    subd_diag dummy;
    subd_tags_report rdummy;
    subd_diag *d = diag ? diag : &dummy;
    subd_tags_report *r = report ? report : &rdummy;
    int st;
    subd_diag_clear(d);
    r->creases = r->vertex_tags = r->vertex_alphas = r->face_alphas = 0;
    r->alpha_den = 1;
    r->alpha_line[0] = r->alpha_line[1] = 0;
    r->edge[0] = r->edge[1] = SUBD_NONE;
    if (!m || (!buf && len) || (af && af->den <= 0)) return subd_fail(d, SUBD_ERR_PARAM);
    if (len == 0) return SUBD_OK; /* an empty file has no tags (and buf may be NULL) */
    st = tags_pass(buf, len, m, NULL, af, 0, r, d);
    if (st == SUBD_OK && (out || af)) st = tags_pass(buf, len, m, out, af, 1, r, d);
    return st;
}

int subd_tags_check(const char *buf, uint32_t len, const subd_mesh *m, subd_tags_report *report, subd_diag *diag)
{
    return tags_run(buf, len, m, NULL, NULL, report, diag);
}

int subd_tags_apply(const char *buf, uint32_t len, subd_mesh *m, subd_tags_report *report, subd_diag *diag)
{
    return tags_run(buf, len, m, m, NULL, report, diag);
}

int subd_tags_alpha(const char *buf, uint32_t len, const subd_mesh *m, int32_t den, int32_t *vert_num,
                    int32_t *face_num, subd_tags_report *report, subd_diag *diag)
{
    alpha_fill af;
    af.den = den;
    af.vnum = vert_num;
    af.fnum = face_num;
    return tags_run(buf, len, m, NULL, &af, report, diag);
}
