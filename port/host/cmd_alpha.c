/* SPDX-License-Identifier: MIT */
/* subd tool: `alpha`, the semi-stationary alpha-subdivision (subd_alpha_*): curves (OBJ l
 * records) and the Doo-Sabin type surface, their options (--order, --kernel, --alpha,
 * --stiffness; --tags alpha lines), and alpha --stream (subd_alpha_curve_stream_begin: the
 * points of each curve to .xyz or G-code, --chord, --feed).
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include "subd_tool.h"
#include "host_real.h"

/* alpha: the semi-stationary operators. A mesh with faces gets the Doo-Sabin type surface
 * operator; a mesh of polylines (OBJ l records) gets the curve operator S_k once per
 * polyline, closed when its last index repeats its first. Curves are refined one at a time
 * in the arena (the plan is the largest single curve) and collected in host memory.
 *
 * --tags FILE with 'alpha V A' / 'falpha F A' lines (subd_tags.h): per-vertex alphas for
 * curves and odd orders, per-face alphas for even orders (section 3), as one array of alpha
 * numerators in the arena (counted by the plan). Every value and --alpha are put over one
 * common denominator (their least common one), so equal tags give exactly the untagged
 * result. The file was already checked line by line (subd_main.c); what is left to refuse
 * here is a line of the kind the operator does not tag and a denominator too fine for the
 * levels: those are reported here (FILE:LINE), and the plan returns EXIT_INPUT. */
typedef struct alpha_tagging {
    subd_alpha_opts ao; /* o->alpha, over the common den when tagged                     */
    int vertex;         /* tags per vertex (curves, odd k) or per face (even k)           */
    uint32_t count;     /* 0: no alpha lines, untagged                                    */
    char *buf;          /* the tag file (host memory, freed by alpha_tagging_done)        */
    uint32_t len;
} alpha_tagging;

static void alpha_tagging_done(alpha_tagging *t)
{
    free(t->buf);
    t->buf = NULL;
}

/* Reads o->tags and fills *t; EXIT_INPUT (reported) or SUBD_OK. */
static int alpha_tagging_load(const subd_mesh *in, const tool_opts *o, alpha_tagging *t)
{
    subd_tags_report rep;
    subd_diag d;
    int64_t den, num;
    uint32_t wrong;
    memset(t, 0, sizeof *t);
    t->ao = o->alpha;
    t->ao.tag_num = NULL;
    if (!o->tags) return SUBD_OK;
    if (host_read_file(o->tags, &t->buf, &t->len) != 0 ||
        subd_tags_check(t->buf, t->len, in, &rep, &d) != SUBD_OK) { /* main checked it already */
        tool_error("%s: cannot read the tag file again", o->tags);
        alpha_tagging_done(t);
        return EXIT_INPUT;
    }
    if (rep.vertex_alphas + rep.face_alphas == 0) {
        alpha_tagging_done(t);
        return SUBD_OK;
    }
    t->vertex = !in->num_faces || (o->alpha.order & 1u);
    wrong = t->vertex ? rep.alpha_line[1] : rep.alpha_line[0];
    if (wrong) {
        tool_error("%s:%lu: %s", o->tags, (unsigned long)wrong,
                          !in->num_faces ? "'falpha' (per-face alpha) needs a surface; curves take 'alpha V A'"
                          : t->vertex ? "'falpha' (per-face alpha) needs an even --order; odd orders tag vertices"
                                      : "'alpha' (per-vertex alpha) needs an odd --order (or a curve); even orders "
                                        "tag faces ('falpha F A')");
        alpha_tagging_done(t);
        return EXIT_INPUT;
    }
    /* one denominator for --alpha and every tag */
    den = subd_tags_common_den(o->alpha.alpha_den, rep.alpha_den); /* 0: beyond int32 */
    num = den ? (int64_t)o->alpha.alpha_num * (den / o->alpha.alpha_den) : 0;
    if (den <= 0 || den > (INT32_MAX >> (o->levels + 2u)) || num > SUBD_ALPHA_MAX_NUM || num < -SUBD_ALPHA_MAX_NUM) {
        tool_error("%s: the alphas and --alpha need a common denominator %s%lld turns, too fine for %lu "
                   "level(s) (at most %ld): use coarser fractions",
                   o->tags, den ? "of " : "beyond ", den ? (long long)den : (long long)INT32_MAX,
                   (unsigned long)o->levels, (long)(INT32_MAX >> (o->levels + 2u)));
        alpha_tagging_done(t);
        return EXIT_INPUT;
    }
    t->ao.alpha_num = (int32_t)num;
    t->ao.alpha_den = (int32_t)den;
    t->count = t->vertex ? in->num_verts : in->num_faces;
    return SUBD_OK;
}

/* The tag array in the arena: the uniform alpha, then the file's values over the common den
 * (cannot fail after alpha_tagging_load: same file, same den). */
static int alpha_tagging_fill(subd_arena *a, const subd_mesh *in, alpha_tagging *t, int32_t **tags, subd_diag *d)
{
    uint32_t i;
    *tags = (int32_t *)subd_arena_alloc(a, 4u * t->count);
    if (!*tags) return SUBD_ERR_NOMEM;
    for (i = 0; i < t->count; i++) (*tags)[i] = t->ao.alpha_num;
    return subd_tags_alpha(t->buf, t->len, in, t->ao.alpha_den, t->vertex ? *tags : NULL, t->vertex ? NULL : *tags,
                           NULL, d);
}

static int alpha_is_closed(const subd_mesh *in, uint32_t l, uint32_t *m)
{
    uint32_t s = in->line_start[l], e = in->line_start[l + 1u];
    *m = e - s;
    if (*m >= 4u && in->line_vert[s] == in->line_vert[e - 1u]) {
        (*m)--;
        return 1;
    }
    return 0;
}

static int alpha_plan(const subd_mesh *in, const tool_opts *o, uint32_t *bytes, subd_diag *d)
{
    uint32_t l, most = 0, b, pts, m, tag_arr;
    alpha_tagging t;
    static const int32_t dummy = 0; /* the plans only test tag_num for NULL */
    int st;
    if ((st = alpha_tagging_load(in, o, &t)) != SUBD_OK) return st;
    alpha_tagging_done(&t);
    tag_arr = t.count ? SUBD_ALIGN_UP(4u * t.count) : 0u;
    if (t.count) t.ao.tag_num = &dummy;
    if (in->num_faces) {
        st = subd_alpha_surface_plan(in, &t.ao, bytes, d);
        if (st == SUBD_OK) *bytes += tag_arr;
        return st;
    }
    if (!in->num_lines) return SUBD_ERR_EMPTY;
    for (l = 0; l < in->num_lines; l++) {
        int closed = alpha_is_closed(in, l, &m);
        st = subd_alpha_curve_plan(m, closed, &t.ao, &b, &pts);
        if (st != SUBD_OK) return st;
        /* alpha --stream: the stream's plan (the level count and the order only) instead */
        if (o->stream && (st = subd_alpha_curve_stream_plan(m, closed, &t.ao, 0, &b)) != SUBD_OK) return st;
        /* room for the gathered input points (and their tags) too */
        b += SUBD_ALIGN_UP(3u * m * (uint32_t)sizeof(subd_real));
        if (t.count) b += SUBD_ALIGN_UP(4u * m);
        if (b > most) most = b;
    }
    *bytes = most + tag_arr;
    return SUBD_OK;
}

static int alpha_run(subd_arena *a, const subd_mesh *in, const tool_opts *o, subd_mesh *out, scheme_extra *x,
                     subd_diag *d)
{
    uint32_t l, total = 0, k, m, pts, b;
    int32_t continuity = 1, *tags = NULL;
    subd_real *pos;
    uint32_t *lstart, *lvert;
    alpha_tagging t;
    int st;
    if ((st = alpha_tagging_load(in, o, &t)) != SUBD_OK) return SUBD_ERR_PARAM; /* the plan reported it */
    if (t.count) {
        st = alpha_tagging_fill(a, in, &t, &tags, d);
        alpha_tagging_done(&t);
        if (st != SUBD_OK) return st;
    }
    if (in->num_faces) {
        subd_alpha_surface_info info;
        t.ao.tag_num = tags;
        st = subd_alpha_surface(a, in, &t.ao, out, &info, d);
        if (st == SUBD_OK)
            snprintf(x->json, sizeof x->json, "\"order\":%lu,\"continuity\":%ld,\"geometry\":\"surface\"%s",
                     (unsigned long)o->alpha.order, (long)info.continuity, tags ? ",\"tagged\":true" : "");
        return st;
    }
    for (l = 0; l < in->num_lines; l++) {
        int closed = alpha_is_closed(in, l, &m);
        if ((st = subd_alpha_curve_plan(m, closed, &t.ao, &b, &pts)) != SUBD_OK) return st;
        total += pts + (uint32_t)closed;
    }
    x->host_mem = malloc((size_t)total * (3u * sizeof(subd_real) + sizeof(uint32_t)) +
                         (in->num_lines + 1u) * sizeof(uint32_t) + sizeof(uint32_t));
    if (!x->host_mem) return SUBD_ERR_NOMEM;
    pos = (subd_real *)x->host_mem;
    lvert = (uint32_t *)(void *)(pos + 3u * total);
    lstart = lvert + total;
    lstart[0] = 0;
    total = 0;
    for (l = 0; l < in->num_lines; l++) {
        uint32_t mark = subd_arena_mark(a), s = in->line_start[l];
        int closed = alpha_is_closed(in, l, &m);
        subd_alpha_curve_out co;
        subd_real *p = (subd_real *)subd_arena_alloc(a, 3u * m * (uint32_t)sizeof(subd_real));
        int32_t *lt = NULL;
        if (!p) return SUBD_ERR_NOMEM;
        for (k = 0; k < 3u * m; k++) p[k] = in->pos[3u * in->line_vert[s + k / 3u] + k % 3u];
        if (tags) {
            /* this polyline's points' tags, in its order */
            if (!(lt = (int32_t *)subd_arena_alloc(a, 4u * m))) return SUBD_ERR_NOMEM;
            for (k = 0; k < m; k++) lt[k] = tags[in->line_vert[s + k]];
        }
        t.ao.tag_num = lt;
        st = subd_alpha_curve(a, p, m, closed, &t.ao, &co, d);
        if (st != SUBD_OK) {
            d->polyline = l;
            return st;
        }
        for (k = 0; k < 3u * co.num_points; k++) pos[3u * total + k] = co.pos[k];
        for (k = 0; k < co.num_points; k++) lvert[lstart[l] + k] = total + k;
        if (closed) lvert[lstart[l] + co.num_points] = total; /* repeat the first point */
        lstart[l + 1u] = lstart[l] + co.num_points + (uint32_t)closed;
        total += co.num_points;
        if (co.continuity < continuity) continuity = co.continuity;
        subd_arena_rewind(a, mark);
    }
    memset(out, 0, sizeof *out);
    out->num_verts = total;
    out->pos = pos;
    out->face_start = lstart; /* any valid pointer: there are no faces */
    out->num_lines = in->num_lines;
    out->num_line_verts = lstart[in->num_lines];
    out->line_start = lstart;
    out->line_vert = lvert;
    snprintf(x->json, sizeof x->json, "\"order\":%lu,\"continuity\":%ld,\"geometry\":\"curves\"%s",
             (unsigned long)o->alpha.order, (long)continuity, tags ? ",\"tagged\":true" : "");
    return SUBD_OK;
}

/* alpha --stream: each polyline streamed (subd_alpha_curve_stream_begin, pulled 256 points
 * at a time) into OUTPUT through subd_path_write: .xyz lines ("x y z", a blank line between
 * polylines, as the .xyz writer) or G-code (.gcode/.nc: G21, G90, G0 to each polyline's
 * start, G1 per point, --feed once). A closed polyline's first point is written again at its
 * end (the path closes, as `subd alpha` repeats it in OBJ l records). --chord EPS: the
 * adaptive stream. Memory: the stream's plan plus the polyline's gathered points (and tags)
 * in the arena; the text goes out through one 64 KiB host buffer. --stats: stream_arena is
 * the largest polyline's stream plan (subd_alpha_curve_stream_plan), the points not counted. */
#define ALPHA_STREAM_BATCH 256u
static int alpha_stream_io_error(const char *path)
{
    tool_error("cannot write '%s': %s", path ? path : "(none)", strerror(errno ? errno : EIO));
    return EXIT_OUTPUT;
}

static int alpha_stream_run(tool_run *r, subd_arena *a, subd_diag *d)
{
    const subd_mesh *in = &r->in.mesh;
    const tool_opts *o = &r->o;
    uint32_t fmt = o->out_format == HOST_FMT_XYZ ? SUBD_PATH_XYZ : SUBD_PATH_GCODE, l, k, m, emitted = 0;
    uint32_t stream_arena = 0; /* the largest polyline's stream plan (the points not counted) */
    subd_real chord = o->has_chord ? host_real_from_double(o->chord) : 0;
    subd_real feed = o->feed > 0.0 ? host_real_from_double(o->feed) : 0;
    int32_t *tags = NULL;
    alpha_tagging t;
    subd_point *batch = (subd_point *)malloc(ALPHA_STREAM_BATCH * sizeof(subd_point));
    char *text = (char *)malloc(65536u);
    FILE *f = NULL;
    uint32_t hash = 2166136261u;
    double t0;
    int st = SUBD_OK;
    if (!batch || !text) {
        free(batch);
        free(text);
        return tool_out_of_memory();
    }
    if (in->num_faces || !in->num_lines) {
        free(batch);
        free(text);
        tool_error("alpha --stream: %s has %s; --stream streams curves (OBJ l records)", o->input,
                   in->num_faces ? "faces" : "no polylines");
        return EXIT_USAGE;
    }
    if ((st = alpha_tagging_load(in, o, &t)) != SUBD_OK) {
        free(batch);
        free(text);
        return SUBD_ERR_PARAM; /* the plan reported it */
    }
    if (t.count) {
        st = alpha_tagging_fill(a, in, &t, &tags, d);
        alpha_tagging_done(&t);
        if (st != SUBD_OK) goto done;
    }
    if (o->output && !(f = fopen(o->output, "wb"))) {
        free(batch);
        free(text);
        return alpha_stream_io_error(o->output);
    }
    for (l = 0; l < in->num_lines && st == SUBD_OK; l++) {
        uint32_t mark = subd_arena_mark(a), s0 = in->line_start[l], at = 0, len;
        int closed = alpha_is_closed(in, l, &m), n;
        subd_real *p = (subd_real *)subd_arena_alloc(a, 3u * m * (uint32_t)sizeof(subd_real));
        int32_t *lt = NULL;
        subd_point first;
        subd_stream s;
        if (!p) {
            st = SUBD_ERR_NOMEM;
            break;
        }
        for (k = 0; k < 3u * m; k++) p[k] = in->pos[3u * in->line_vert[s0 + k / 3u] + k % 3u];
        if (tags) {
            if (!(lt = (int32_t *)subd_arena_alloc(a, 4u * m))) {
                st = SUBD_ERR_NOMEM;
                break;
            }
            for (k = 0; k < m; k++) lt[k] = tags[in->line_vert[s0 + k]];
        }
        t.ao.tag_num = lt;
        if (subd_alpha_curve_stream_plan(m, closed, &t.ao, chord, &len) == SUBD_OK && len > stream_arena)
            stream_arena = len;
        t0 = host_now_ns();
        st = subd_alpha_curve_stream_begin(a, p, m, closed, &t.ao, chord, &s, d);
        r->lib_ns += host_now_ns() - t0;
        if (st != SUBD_OK) {
            d->polyline = l;
            break;
        }
        if (l > 0u && fmt == SUBD_PATH_XYZ && f && fputs("\n", f) < 0) st = -1000;
        for (;;) {
            t0 = host_now_ns();
            n = subd_stream_next_points(&s, batch, ALPHA_STREAM_BATCH);
            r->lib_ns += host_now_ns() - t0;
            if (n <= 0) {
                if (n < 0) st = n;
                break;
            }
            if (at == 0u) first = batch[0];
            for (k = 0; k < (uint32_t)n; k++) {
                uint32_t c;
                batch[k].curve = l;
                for (c = 0; c < 3u; c++) {
                    uint32_t bits = subd_real_bits(batch[k].pos[c]);
                    hash = (hash ^ (bits & 0xffu)) * 16777619u;
                    hash = (hash ^ ((bits >> 8) & 0xffu)) * 16777619u;
                    hash = (hash ^ ((bits >> 16) & 0xffu)) * 16777619u;
                    hash = (hash ^ (bits >> 24)) * 16777619u;
                }
            }
            if (f && (subd_path_write(batch, (uint32_t)n, at, fmt, feed, text, 65536u, &len) != SUBD_OK ||
                      fwrite(text, 1, len, f) != len)) {
                subd_stream_end(&s);
                st = -1000;
                break;
            }
            r->out_bytes += f ? len : 0u;
            at += (uint32_t)n;
        }
        if (st == SUBD_OK && closed && f) { /* the path closes */
            if (subd_path_write(&first, 1, at, fmt, feed, text, 65536u, &len) != SUBD_OK || fwrite(text, 1, len, f) != len)
                st = -1000;
            r->out_bytes += len;
        }
        emitted += at;
        subd_arena_rewind(a, mark);
    }
done:
    if (f && fclose(f) != 0 && st == SUBD_OK) st = -1000;
    free(batch);
    free(text);
    if (st == -1000) return alpha_stream_io_error(o->output);
    memset(&r->out, 0, sizeof r->out);
    r->out.num_verts = emitted;
    snprintf(r->extra.json, sizeof r->extra.json,
             "\"order\":%lu,\"geometry\":\"curves\",\"stream\":true,\"chord\":%g,\"points\":%lu,\"checksum\":\"%08lx\","
             "\"stream_arena\":%lu",
             (unsigned long)o->alpha.order, o->has_chord ? o->chord : 0.0,
             (unsigned long)emitted, (unsigned long)hash, (unsigned long)stream_arena);
    return st;
}

/* ------------------------------------------------------------------------------------ */
/* Options, checks, descriptor                                                            */

/* alpha as an exact fraction of a turn: the library's one grammar for alpha values
 * (subd_tags.h: "N", "N/D" or "Xdeg", at most 4 decimals, no exponent), as in a tag file. */
static int parse_alpha(const char *s, int32_t *num, int32_t *den)
{
    size_t len = strlen(s);
    if (len > UINT32_MAX) return -1;
    return subd_tags_parse_alpha(s, (uint32_t)len, num, den) == SUBD_OK ? 0 : -1;
}

static int set_order(const opt_ctx *c)
{
    if (tool_parse_u32(c->val, SUBD_ALPHA_MAX_ORDER, &c->o->alpha.order) || c->o->alpha.order < 2)
        return tool_usage_error("bad order '%s' (2..%u)", c->val, SUBD_ALPHA_MAX_ORDER);
    return EXIT_OK;
}

static int set_kernel(const opt_ctx *c)
{
    static const char *const names[] = {"bspline", "cos", "poly", "cosh"};
    static const subd_alpha_kernel kernels[] = {SUBD_ALPHA_BSPLINE, SUBD_ALPHA_COS, SUBD_ALPHA_POLY,
                                                SUBD_ALPHA_COSH};
    size_t k;
    for (k = 0; k < sizeof names / sizeof names[0]; k++)
        if (strcmp(c->val, names[k]) == 0) {
            c->o->alpha.kernel = kernels[k];
            return EXIT_OK;
        }
    return tool_usage_error("bad kernel '%s' (bspline, cos, poly or cosh)", c->val);
}

static int set_alpha(const opt_ctx *c)
{
    if (parse_alpha(c->val, &c->o->alpha.alpha_num, &c->o->alpha.alpha_den))
        return tool_usage_error("bad alpha '%s' (a fraction of a turn N/D, e.g. 1/8, or degrees, e.g. 45deg)",
                                c->val);
    return EXIT_OK;
}

static int set_stiffness(const opt_ctx *c)
{
    double sv;
    if (tool_parse_double(c->val, -1e4, 1e4, &sv)) return tool_usage_error("bad stiffness '%s'", c->val);
    if (sv <= -0.5)
        return tool_usage_error("stiffness %s <= -1/2: the subdivision diverges (paper, theorem 1: convergent for s > -1/2)",
                                c->val);
    c->o->alpha.stiffness = host_real_from_double(sv);
    return EXIT_OK;
}

/* --feed F: the G-code feed rate of alpha --stream. */
static int set_feed(const opt_ctx *c)
{
    if (tool_parse_double(c->val, 0.0, 1e9, &c->o->feed) || !(c->o->feed > 0.0))
        return tool_usage_error("bad feed rate '%s' (a positive number, units per minute)", c->val);
    return EXIT_OK;
}

static const tool_option alpha_options[] = {
    {"--order", NULL, "K", 0, OPT_ALPHA, set_order,
     "(alpha) operator order S_K, 2..8 (S_3: the paper's Catmull-Clark variant)"},
    {"--kernel", NULL, "K", 0, OPT_ALPHA, set_kernel,
     "(alpha) bspline (default), cos (C-curves: circles), poly, cosh"},
    {"--alpha", NULL, "A", 0, OPT_ALPHA, set_alpha,
     "(alpha) angle as a fraction of a turn N/D (1/8) or degrees (45deg)"},
    {"--stiffness", NULL, "S", 0, OPT_ALPHA, set_stiffness,
     "(alpha) s = f(0), default 1; s <= -1/2 diverges (rejected)"},
    {"--feed", NULL, "F", 0, OPT_ALPHA, set_feed, "(alpha --stream, G-code output) feed rate F on the first G1"},
};

static void alpha_init(tool_opts *o) { subd_alpha_opts_default(&o->alpha); }

/* alpha --stream: --chord, --feed; .xyz or G-code */
static int alpha_check(const command *cmd, tool_opts *o)
{
    (void)cmd;
    if (o->limit) return tool_usage_error("--limit applies to 'loop --stream' only");
    if (!o->stream && o->has_chord) return tool_usage_error("alpha: --chord needs --stream");
    if (!o->stream && o->feed > 0.0) return tool_usage_error("alpha: --feed needs --stream (and G-code output)");
    if (o->stream && o->output && host_format_of(o->output) != HOST_FMT_XYZ &&
        host_format_of(o->output) != HOST_FMT_GCODE)
        return tool_usage_error("cannot write '%s': alpha --stream writes .xyz, .gcode or .nc", o->output);
    if (o->feed > 0.0 && o->output && host_format_of(o->output) != HOST_FMT_GCODE)
        return tool_usage_error("--feed goes with G-code output (.gcode, .nc)");
    return EXIT_OK;
}

static int alpha_finish(const command *cmd, tool_opts *o)
{
    (void)cmd;
    o->alpha.levels = o->levels;
    return EXIT_OK;
}

static size_t alpha_describe(const tool_opts *o, char *buf, size_t k, size_t n)
{
    static const char *const kernel[] = {"bspline", "cos", "poly", "cosh"};
    if (o->stream) k = tool_describe_add(buf, k, n, " --stream");
    if (o->alpha.order != 2u) k = tool_describe_add(buf, k, n, " --order %lu", (unsigned long)o->alpha.order);
    if (o->alpha.kernel != SUBD_ALPHA_BSPLINE && (unsigned)o->alpha.kernel < 4u)
        k = tool_describe_add(buf, k, n, " --kernel %s", kernel[o->alpha.kernel]);
    if (o->alpha.kernel != SUBD_ALPHA_BSPLINE)
        k = tool_describe_add(buf, k, n, " --alpha %ld/%ld", (long)o->alpha.alpha_num, (long)o->alpha.alpha_den);
    return k;
}

const command tool_cmd_alpha = {
    .name = "alpha",
    .canonical = "alpha",
    .synopsis = "[-l N] INPUT -o OUTPUT",
    .summary = "semi-stationary alpha-subdivision: curves (OBJ l records)\n"
               "or the Doo-Sabin type surface; --order K, --kernel\n"
               "bspline|cos|poly|cosh, --alpha A, --stiffness S;\n"
               "--tags FILE: 'alpha V A' (curves, odd K), 'falpha F A' (even K);\n"
               "--stream [--chord EPS] [--feed F]: curves point by point\n"
               "(.xyz, G-code .gcode/.nc)",
    .flags = CMD_OUTPUT_REQUIRED | CMD_LEVELS | CMD_STREAM_POINTS,
    .scheme = "alpha",
    .default_levels = 1,
    .max_levels = SUBD_MAX_LEVELS,
    .options = OPT_ALPHA | OPT_TAGS | OPT_STREAM | OPT_CHORD,
    .opts = alpha_options,
    .num_opts = sizeof alpha_options / sizeof alpha_options[0],
    .init = alpha_init,
    .check = alpha_check,
    .finish = alpha_finish,
    .plan = alpha_plan,
    .run = alpha_run,
    .stream = alpha_stream_run,
    .describe = alpha_describe,
};
