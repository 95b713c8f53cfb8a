/* SPDX-License-Identifier: MIT */
/* subd tool: the command table and the scheme commands. A scheme command is one row with a
 * plan function (exact arena bytes for this input, after the input mesh) and a run function
 * (arena, const input -> output mesh, plus optional normals and --stats members); the common
 * path in subd_main.c does everything else. The table also gives each command's synopsis and
 * summary for --help, the options it accepts and its level range.
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include "subd_tool.h"
#include "host_real.h"

subd_loop_opts tool_loop_opts(const tool_opts *o)
{
    subd_loop_opts lo;
    lo.levels = o->levels;
    lo.boundary = o->boundary;
    lo.flags = o->limit ? SUBD_LOOP_STREAM_LIMIT : 0u;
    return lo;
}

/* loop --stream --limit --chord EPS: the adaptive limit stream's options. */
subd_loop_adapt_opts tool_loop_adapt_opts(const tool_opts *o)
{
    subd_loop_adapt_opts ao;
    memset(&ao, 0, sizeof ao);
    ao.loop = tool_loop_opts(o);
    ao.mode = SUBD_LOOP_ADAPT_CHORD;
    ao.chord = host_real_from_double(o->adapt_val[0]);
    return ao;
}

static int loop_plan(const subd_mesh *in, const tool_opts *o, uint32_t *bytes, subd_diag *d)
{
    subd_loop_opts lo = tool_loop_opts(o);
    if (o->stream && o->adapt_mode == SUBD_SR48_ADAPT_CHORD) { /* loop --stream --limit --chord EPS */
        subd_loop_adapt_opts ao = tool_loop_adapt_opts(o);
        return subd_loop_adapt_stream_plan(in, &ao, bytes, d);
    }
    return o->stream ? subd_loop_stream_plan(in, &lo, bytes, d) : subd_loop_plan(in, &lo, bytes, d);
}

static int loop_run(subd_arena *a, const subd_mesh *in, const tool_opts *o, subd_mesh *out, scheme_extra *x,
                    subd_diag *d)
{
    subd_loop_opts lo = tool_loop_opts(o);
    (void)x;
    return subd_loop(a, in, &lo, out, d);
}

static int limit_plan(const subd_mesh *in, const tool_opts *o, uint32_t *bytes, subd_diag *d)
{
    return subd_loop_limit_plan(in, &(subd_loop_limit_opts){o->boundary, o->normals ? SUBD_LOOP_LIMIT_NORMALS : 0u}, bytes, d);
}

/* The limit and interpolation commands move the vertices: the output is the input's
 * topology with new positions. */
static int limit_run(subd_arena *a, const subd_mesh *in, const tool_opts *o, subd_mesh *out, scheme_extra *x,
                     subd_diag *d)
{
    subd_real *pos = NULL;
    int st = subd_loop_limit(a, in, &(subd_loop_limit_opts){o->boundary, o->normals ? SUBD_LOOP_LIMIT_NORMALS : 0u}, &pos, o->normals ? &x->normals : NULL, d);
    if (st != SUBD_OK) return st;
    *out = *in;
    out->pos = pos;
    return SUBD_OK;
}

static subd_pia_opts pia_opts_of(const tool_opts *o)
{
    subd_pia_opts po;
    po.boundary = o->boundary;
    po.tol = host_real_from_double(o->tol);
    po.max_iter = o->max_iter;
    po.method = o->method;
    return po;
}

static int pia_plan(const subd_mesh *in, const tool_opts *o, uint32_t *bytes, subd_diag *d)
{
    subd_pia_opts po = pia_opts_of(o);
    return subd_pia_plan(in, &po, bytes, d);
}

static int pia_run(subd_arena *a, const subd_mesh *in, const tool_opts *o, subd_mesh *out, scheme_extra *x,
                   subd_diag *d)
{
    subd_pia_opts po = pia_opts_of(o);
    subd_pia_result res;
    subd_real *pos = NULL;
    int st = subd_pia(a, in, &po, &pos, &res, d);
    if (st != SUBD_OK) return st;
    *out = *in;
    out->pos = pos;
    {
        /* the paper's two phases (section 4), as subd_pia_result reports them */
        char ph[2][160];
        const subd_pia_phase *p[2];
        int k;
        p[0] = &res.boundary;
        p[1] = &res.interior;
        for (k = 0; k < 2; k++)
            snprintf(ph[k], sizeof ph[k], "{\"iterations\":%lu,\"vertices\":%lu,\"max_err\":%.9g,\"mean_err\":%.9g}",
                     (unsigned long)p[k]->iterations, (unsigned long)p[k]->verts, host_real_to_double(p[k]->max_err),
                     host_real_to_double(p[k]->mean_err));
        snprintf(x->json, sizeof x->json,
                 "\"method\":\"%s\",\"tol\":%.9g,\"iterations\":%lu,\"max_err\":%.9g,\"mean_err\":%.9g,\"converged\":%s,"
                 "\"boundary_phase\":%s,\"interior_phase\":%s",
                 o->method == SUBD_PIA_FAST ? "fast" : "paper", o->tol, (unsigned long)res.iterations,
                 host_real_to_double(res.max_err), host_real_to_double(res.mean_err), res.converged ? "true" : "false",
                 ph[0], ph[1]);
    }
    x->not_converged = !res.converged;
    x->max_err = host_real_to_double(res.max_err);
    if (!o->stats && !o->quiet) {
        progress_pause();
        fprintf(stderr, "pia: %lu iterations (boundary %lu, interior %lu), max error %.6g, mean error %.6g, %s\n",
                (unsigned long)res.iterations, (unsigned long)res.boundary.iterations,
                (unsigned long)res.interior.iterations, host_real_to_double(res.max_err),
                host_real_to_double(res.mean_err), res.converged ? "converged" : "NOT converged (raise --max-iter or --tol)");
    }
    return SUBD_OK;
}

static subd_quasi48_opts q48_opts_of(const tool_opts *o)
{
    subd_quasi48_opts qo;
    qo.steps = o->levels;
    qo.boundary = o->q48_boundary;
    qo.flags = o->no_smooth ? SUBD_QUASI48_NO_SMOOTH : 0u;
    qo.len_bits = 0;
    return qo;
}

static int q48_plan(const subd_mesh *in, const tool_opts *o, uint32_t *bytes, subd_diag *d)
{
    subd_quasi48_opts qo = q48_opts_of(o);
    return subd_quasi48_plan(in, &qo, bytes, d);
}

static int q48_run(subd_arena *a, const subd_mesh *in, const tool_opts *o, subd_mesh *out, scheme_extra *x,
                   subd_diag *d)
{
    subd_quasi48_opts qo = q48_opts_of(o);
    int st = subd_quasi48(a, in, &qo, out, d);
    if (st == SUBD_OK)
        snprintf(x->json, sizeof x->json, "\"binary_steps\":%lu,\"smoothing\":%s,\"boundary\":\"%s\"",
                 (unsigned long)o->levels, o->no_smooth ? "false" : "true",
                 o->q48_boundary == SUBD_QUASI48_BOUNDARY_SMOOTH   ? "smooth"
                 : o->q48_boundary == SUBD_QUASI48_BOUNDARY_NORMAL ? "normal"
                                                               : "fixed");
    return st;
}

/* semireg48 and adapt: build the hierarchy of right triangles (subd_sr48_build), then cut
 * the output mesh out of it (subd_sr48_extract; uniform at level N for semireg48). The
 * device arena holds both, so the plan is the build's exact bytes (with the cluster count
 * found first) plus the extraction's; the extraction plan needs the hierarchy, so the plan
 * builds it once in host memory. */
static subd_sr48_opts sr48_opts_of(const tool_opts *o)
{
    subd_sr48_opts so;
    so.steps = o->levels;
    so.flags = o->no_smooth ? SUBD_SR48_NO_SMOOTH : 0u;
    return so;
}

subd_sr48_adapt tool_sr48_adapt(const tool_opts *o)
{
    subd_sr48_adapt ad;
    int i;
    memset(&ad, 0, sizeof ad);
    ad.mode = o->adapt_mode;
    ad.max_level = o->levels;
    for (i = 0; i < 3; i++) {
        ad.point[i] = host_real_from_double(o->adapt_val[i]);
        ad.normal[i] = host_real_from_double(o->adapt_val[3 + i]);
    }
    ad.radius = host_real_from_double(o->radius);
    ad.axis = o->adapt_axis;
    ad.eps = host_real_from_double(o->adapt_val[0]);
    return ad;
}

/* Exact build bytes: find_clusters first (in a temporary host arena). */
static int sr48_build_plan(const subd_mesh *in, const subd_sr48_opts *so, uint32_t *bytes, subd_diag *d)
{
    uint32_t bound, clusters = 0;
    subd_arena tmp;
    void *mem;
    int st = subd_sr48_plan(in, so, SUBD_SR48_CLUSTERS_UNKNOWN, &bound, d);
    if (st != SUBD_OK) return st;
    mem = host_arena_alloc(&tmp, bound);
    if (!mem) return SUBD_ERR_NOMEM;
    st = subd_sr48_count_clusters(&tmp, in, &clusters, d);
    free(mem);
    if (st != SUBD_OK) return st;
    return subd_sr48_plan(in, so, clusters, bytes, d);
}

/* semireg48 --stream: the base mesh (exact, with the cluster count) plus the stream's plan
 * (which needs the base: built once in host memory). */
static int sr48_stream_plan(const subd_mesh *in, const tool_opts *o, uint32_t *bytes, subd_diag *d)
{
    uint32_t flags = o->no_smooth ? SUBD_SR48_NO_SMOOTH : 0u, bound, clusters = 0, base_bytes = 0, sb = 0;
    subd_sr48_stream_opts so;
    subd_arena tmp;
    subd_sr48 base;
    void *mem;
    int st = subd_sr48_base_plan(in, flags, SUBD_SR48_CLUSTERS_UNKNOWN, &bound);
    /* adapt --stream: the cut's mode decides the stream's plan */
    if (st != SUBD_OK) return st;
    mem = host_arena_alloc(&tmp, bound);
    if (!mem) return SUBD_ERR_NOMEM;
    st = subd_sr48_count_clusters(&tmp, in, &clusters, d);
    if (st == SUBD_OK) st = subd_sr48_base_plan(in, flags, clusters, &base_bytes);
    if (st == SUBD_OK) st = subd_sr48_base(&tmp, in, flags, &base, d);
    memset(&so, 0, sizeof so);
    so.adapt = tool_sr48_adapt(o);
    if (st == SUBD_OK) st = subd_sr48_stream_plan(&base, &so, &sb, d);
    bound = tmp.used; /* the base; its build scratch above it is given back */
    free(mem);
    if (st != SUBD_OK) return st;
    if (sb > UINT32_MAX - bound) return SUBD_ERR_TOO_BIG;
    *bytes = bound + sb > base_bytes ? bound + sb : base_bytes;
    return SUBD_OK;
}

static int sr48_plan(const subd_mesh *in, const tool_opts *o, uint32_t *bytes, subd_diag *d)
{
    subd_sr48_opts so = sr48_opts_of(o);
    subd_sr48_adapt ad = tool_sr48_adapt(o);
    uint32_t build = 0, extract = 0, keep;
    subd_arena tmp;
    subd_sr48 h;
    void *mem;
    int st;
    if (o->stream) return sr48_stream_plan(in, o, bytes, d);
    st = sr48_build_plan(in, &so, &build, d);
    if (st != SUBD_OK) return st;
    mem = host_arena_alloc(&tmp, build);
    if (!mem) return SUBD_ERR_NOMEM;
    st = subd_sr48_build(&tmp, in, &so, &h, d);
    keep = tmp.used; /* the hierarchy; the build's scratch above it is given back */
    if (st == SUBD_OK) st = subd_sr48_extract_plan(&h, &ad, &extract, d);
    free(mem);
    if (st != SUBD_OK) return st;
    if (extract > UINT32_MAX - keep) return SUBD_ERR_TOO_BIG;
    *bytes = keep + extract > build ? keep + extract : build;
    return SUBD_OK;
}

static int sr48_run(subd_arena *a, const subd_mesh *in, const tool_opts *o, subd_mesh *out, scheme_extra *x,
                    subd_diag *d)
{
    static const char *const mode_name[] = {"uniform", "point", "ramp", "plane", "callback", "chord"};
    subd_sr48_opts so = sr48_opts_of(o);
    subd_sr48_adapt ad = tool_sr48_adapt(o);
    subd_sr48_adapt_report rep;
    subd_sr48 h;
    uint32_t mark = subd_arena_mark(a);
    int st = subd_sr48_build(a, in, &so, &h, d);
    if (st != SUBD_OK) return st;
    st = subd_sr48_extract(a, &h, &ad, out, &rep, d);
    if (st != SUBD_OK) {
        subd_arena_rewind(a, mark);
        return st;
    }
    snprintf(x->json, sizeof x->json,
             "\"binary_steps\":%lu,\"smoothing\":%s,\"adapt\":\"%s\",\"clusters\":%lu,\"isolated_triangles\":%lu,"
             "\"hierarchy_triangles\":%lu,\"faces\":%lu,\"uniform_faces\":%lu,\"saved_faces\":%lu,"
             "\"forced_splits\":%lu",
             (unsigned long)o->levels, o->no_smooth ? "false" : "true", mode_name[ad.mode],
             (unsigned long)h.num_clusters, (unsigned long)h.num_isolated, (unsigned long)h.num_tris,
             (unsigned long)rep.faces, (unsigned long)rep.uniform_faces,
             (unsigned long)(rep.uniform_faces - rep.faces), (unsigned long)rep.forced_splits);
    if (!o->stats && !o->quiet && ad.mode != SUBD_SR48_ADAPT_UNIFORM) {
        progress_pause();
        fprintf(stderr, "adapt: %lu triangles (uniform level %lu: %lu, saved %lu), %lu forced splits\n",
                (unsigned long)rep.faces, (unsigned long)o->levels, (unsigned long)rep.uniform_faces,
                (unsigned long)(rep.uniform_faces - rep.faces), (unsigned long)rep.forced_splits);
    }
    return SUBD_OK;
}

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
 * in the arena; the text goes out through one 64 KiB host buffer. */
#define ALPHA_STREAM_BATCH 256u
static int alpha_stream_io_error(const char *path)
{
    tool_error("cannot write '%s': %s", path ? path : "(none)", strerror(errno ? errno : EIO));
    return EXIT_OUTPUT;
}

int tool_alpha_stream_run(tool_run *r, subd_arena *a, subd_diag *d)
{
    const subd_mesh *in = &r->in.mesh;
    const tool_opts *o = &r->o;
    uint32_t fmt = o->out_format == HOST_FMT_XYZ ? SUBD_PATH_XYZ : SUBD_PATH_GCODE, l, k, m, emitted = 0;
    subd_real chord = o->adapt_mode == SUBD_SR48_ADAPT_CHORD ? host_real_from_double(o->adapt_val[0]) : 0;
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
             "\"order\":%lu,\"geometry\":\"curves\",\"stream\":true,\"chord\":%g,\"points\":%lu,\"checksum\":\"%08lx\"",
             (unsigned long)o->alpha.order, o->adapt_mode == SUBD_SR48_ADAPT_CHORD ? o->adapt_val[0] : 0.0,
             (unsigned long)emitted, (unsigned long)hash);
    return st;
}

#define LOOP_OPTS (OPT_BOUNDARY | OPT_CREASE | OPT_TAGS)
const command tool_commands[] = {
    {"info", "INPUT", "counts, components, Euler characteristic, genus,\n"
                      "valences and bounding box of a mesh",
     CMD_OUTPUT_NONE, NULL, 0, 0, 0, NULL, NULL, tool_info_report},
    {"convert", "INPUT -o OUTPUT", "write the mesh in OUTPUT's format",
     CMD_OUTPUT_REQUIRED, NULL, 0, 0, 0, NULL, NULL, NULL},
    {"render", "INPUT -o OUTPUT.png", "draw the mesh (shaded, with edges) as a PNG",
     CMD_OUTPUT_REQUIRED | CMD_PNG_ONLY, NULL, 0, 0, 0, NULL, NULL, NULL},
    {"loop", "[-l N] INPUT -o OUTPUT", "Loop subdivision of a triangle mesh (default 1 level);\n"
                                       "--boundary paper|bspline, --crease-angle DEG;\n"
                                       "--stream [--limit]: one triangle at a time (.stl)",
     CMD_OUTPUT_REQUIRED | CMD_LEVELS, "loop", 1, SUBD_MAX_LEVELS, LOOP_OPTS | OPT_STREAM, loop_plan, loop_run,
     NULL},
    {"limit", "INPUT -o OUTPUT", "control vertices moved to their Loop limit positions;\n"
                                 "--normals adds limit normals (OBJ vn)",
     CMD_OUTPUT_REQUIRED, "limit", 0, 0, LOOP_OPTS | OPT_NORMALS, limit_plan, limit_run, NULL},
    {"pia", "--tol T INPUT -o OUTPUT", "progressive interpolation: a control mesh whose Loop\n"
                                       "limit surface passes through INPUT's vertices;\n"
                                       "--max-iter K (default 100), --method paper|fast",
     CMD_OUTPUT_REQUIRED, "pia", 0, 0, LOOP_OPTS | OPT_TOL | OPT_MAX_ITER | OPT_METHOD, pia_plan, pia_run, NULL},
    {"quasi48", "[-l N] INPUT -o OUTPUT", "quasi 4-8 subdivision, N binary steps (default 2 = one\n"
                                          "4-8 refinement); --no-smooth, --boundary fixed|smooth|normal,\n"
                                          "--tag-boundary, --crease-angle DEG",
     CMD_OUTPUT_REQUIRED | CMD_LEVELS, "quasi48", 2, SUBD_QUASI48_MAX_STEPS, OPT_Q48 | OPT_NO_SMOOTH | OPT_CREASE | OPT_TAGS, q48_plan, q48_run, NULL},
    {"alpha", "[-l N] INPUT -o OUTPUT", "semi-stationary alpha-subdivision: curves (OBJ l records)\n"
                                        "or the Doo-Sabin type surface; --order K, --kernel\n"
                                        "bspline|cos|poly|cosh, --alpha A, --stiffness S;\n"
                                        "--tags FILE: 'alpha V A' (curves, odd K), 'falpha F A' (even K);\n"
                                        "--stream [--chord EPS] [--feed F]: curves point by point\n"
                                        "(.xyz, G-code .gcode/.nc)",
     CMD_OUTPUT_REQUIRED | CMD_LEVELS, "alpha", 1, SUBD_MAX_LEVELS, OPT_ALPHA | OPT_TAGS | OPT_STREAM, alpha_plan,
     alpha_run, NULL},
    {"semireg48", "[-l N] INPUT -o OUTPUT", "semi-regular 4-8 refinement with Zwart-Powell box-spline\n"
                                            "smoothing, N binary steps after pre-processing (default\n"
                                            "2; -l 0 writes the pre-processed mesh); --no-smooth",
     CMD_OUTPUT_REQUIRED | CMD_LEVELS | CMD_LEVEL0, "semireg48", 2, SUBD_SR48_MAX_STEPS, OPT_NO_SMOOTH | OPT_STREAM, sr48_plan,
     sr48_run, NULL},
    {"adapt", "-l MAX MODE INPUT -o OUTPUT", "variable-resolution semi-regular 4-8 mesh up to MAX binary\n"
                                             "steps; MODE: --point X,Y,Z [--radius R] | --ramp x|y|z |\n"
                                             "--plane X,Y,Z,NX,NY,NZ | --chord EPS; --no-smooth;\n"
                                             "--stream: one triangle at a time (all modes but --chord)",
     CMD_OUTPUT_REQUIRED | CMD_LEVELS | CMD_LEVEL0, "semireg48", 6, SUBD_SR48_MAX_STEPS,
     OPT_NO_SMOOTH | OPT_ADAPT | OPT_STREAM,
     sr48_plan, sr48_run, NULL},
};
const size_t tool_num_commands = sizeof tool_commands / sizeof tool_commands[0];

const command *tool_find_command(const char *name)
{
    size_t i;
    for (i = 0; i < tool_num_commands; i++)
        if (strcmp(tool_commands[i].name, name) == 0) return &tool_commands[i];
    return NULL;
}
