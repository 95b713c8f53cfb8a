/* SPDX-License-Identifier: MIT */
/* subd tool: `sr48`, the semi-regular 4-8 scheme (include/subd_sr48.h): uniform at -l N, or
 * a variable-resolution cut up to level N by a mode (--point [--radius], --ramp, --plane,
 * --chord), materialised (subd_sr48_build + subd_sr48_extract) or streamed (--stream:
 * subd_sr48_base + subd_sr48_stream, through the triangle sinks of subd_stream.c). The
 * spellings of 0.5, `semireg48` (uniform) and `adapt` (a mode required, -l default 6), are
 * deprecated descriptors of the same functions, kept until 1.0: the same output bytes.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdlib.h>
#include <string.h>
#include "subd_tool.h"
#include "host_real.h"

#define SR48_MODE_LEVELS 6u /* -l without a value when a mode is given */

/* sr48: build the hierarchy of right triangles (subd_sr48_build), then cut the output mesh
 * out of it (subd_sr48_extract; uniform at level N without a mode). The
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

/* The cut: the mode and its parameters, max_level = -l; the materialised run and the stream. */
static subd_sr48_adapt sr48_adapt_of(const tool_opts *o)
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
    ad.eps = host_real_from_double(o->chord);
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

/* sr48 --stream: the base mesh (exact, with the cluster count) plus the stream's plan
 * (which needs the base: built once in host memory). */
static int sr48_stream_plan(const subd_mesh *in, const tool_opts *o, uint32_t *bytes, subd_diag *d)
{
    uint32_t flags = o->no_smooth ? SUBD_SR48_NO_SMOOTH : 0u, bound, clusters = 0, base_bytes = 0, sb = 0;
    subd_sr48_stream_opts so;
    subd_arena tmp;
    subd_sr48 base;
    void *mem;
    int st = subd_sr48_base_plan(in, flags, SUBD_SR48_CLUSTERS_UNKNOWN, &bound);
    /* with a mode: the cut's mode decides the stream's plan */
    if (st != SUBD_OK) return st;
    mem = host_arena_alloc(&tmp, bound);
    if (!mem) return SUBD_ERR_NOMEM;
    st = subd_sr48_count_clusters(&tmp, in, &clusters, d);
    if (st == SUBD_OK) st = subd_sr48_base_plan(in, flags, clusters, &base_bytes);
    if (st == SUBD_OK) st = subd_sr48_base(&tmp, in, flags, &base, d);
    memset(&so, 0, sizeof so);
    so.adapt = sr48_adapt_of(o);
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
    subd_sr48_adapt ad = sr48_adapt_of(o);
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
    subd_sr48_adapt ad = sr48_adapt_of(o);
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

/* ------------------------------------------------------------------------------------ */
/* sr48 --stream                                                                          */

typedef struct sr48_stream_ctx {
    const tool_run *r;
    const subd_sr48 *base;
} sr48_stream_ctx;

static int sr48_pass(void *ctx, subd_arena *a, const subd_tri_sink *sink, subd_diag *d)
{
    const sr48_stream_ctx *c = (const sr48_stream_ctx *)ctx;
    subd_sr48_stream_opts so;
    memset(&so, 0, sizeof so);
    so.adapt = sr48_adapt_of(&c->r->o);
    return subd_sr48_stream(a, c->base, &so, sink, d);
}

/* The base mesh (subd_sr48_base) in the arena, then subd_sr48_stream above it. Counts: n0 2^L
 * triangles (n0 = the base's triangles; with a mode a bound, the uniform count); ids below
 * V0 + n0 (2^L - 1) (subd_sr48.h); the vertex count is what the sink gathers. */
static int sr48_stream(tool_run *r, subd_arena *a, subd_diag *d)
{
    static const char *const mode_name[] = {"uniform", "point", "ramp", "plane", "callback", "chord"};
    uint32_t flags = r->o.no_smooth ? SUBD_SR48_NO_SMOOTH : 0u, stream_bytes = 0;
    subd_sr48_adapt ad = sr48_adapt_of(&r->o);
    subd_sr48_stream_opts so;
    subd_sr48 base;
    sr48_stream_ctx ctx;
    tool_stream ts;
    stream_result res;
    stream_counts *c = &ts.c;
    double t0 = host_now_ns();
    int st = subd_sr48_base(a, &r->in.mesh, flags, &base, d);
    memset(&so, 0, sizeof so);
    so.adapt = ad;
    if (st == SUBD_OK) st = subd_sr48_stream_plan(&base, &so, &stream_bytes, d);
    r->lib_ns += host_now_ns() - t0;
    if (st != SUBD_OK) return st;
    memset(&ts, 0, sizeof ts);
    ctx.r = r;
    ctx.base = &base;
    ts.pass = sr48_pass;
    ts.ctx = &ctx;
    c->tris = (uint64_t)base.level_tri[1] << r->o.levels;
    c->ids = (uint64_t)base.num_verts + (uint64_t)base.level_tri[1] * (((uint64_t)1 << r->o.levels) - 1u);
    c->verts = c->ids < 3u * c->tris ? c->ids : 3u * c->tris; /* a bound: the sink counts them */
    c->verts_exact = 0;
    c->edges = 0;
    c->tris_bound = ad.mode != SUBD_SR48_ADAPT_UNIFORM;
    c->boundary_edges = c->tris_bound ? 0u : (uint64_t)r->in.mesh.num_boundary_edges << r->o.levels; /* a cut: not counted */
    st = tool_stream_write(r, a, &ts, d, &res);
    snprintf(r->extra.json, sizeof r->extra.json,
             "\"stream\":true,\"stream_arena\":%lu,\"stream_valence\":%lu,\"binary_steps\":%lu,\"smoothing\":%s,\"adapt\":\"%s\","
             "\"base_triangles\":%lu,\"faces\":%llu,\"triangles\":%llu,\"uniform_faces\":%llu,"
             "\"saved_faces\":%llu,\"checksum\":\"%08lx\"",
             (unsigned long)stream_bytes, (unsigned long)base.stream_valence, (unsigned long)r->o.levels, r->o.no_smooth ? "false" : "true",
             (unsigned)ad.mode < 6u ? mode_name[ad.mode] : "?", (unsigned long)base.level_tri[1],
             (unsigned long long)res.tris, (unsigned long long)res.tris, (unsigned long long)c->tris,
             (unsigned long long)(c->tris - res.tris), (unsigned long)res.hash);
    return st;
}

/* ------------------------------------------------------------------------------------ */
/* Options, checks, descriptors                                                           */

/* --point, --plane and --ramp: the adaptation mode, one per command line (--chord is a
 * shared option, subd_options.c). */
static int set_adapt_mode(const opt_ctx *c)
{
    tool_opts *o = c->o;
    const char *val = c->val;
    if (o->mode_given) return tool_usage_error("give one adaptation mode (--point, --ramp, --plane or --chord)");
    o->mode_given = 1;
    if (strcmp(c->name, "--point") == 0) {
        if (tool_parse_doubles(val, 3, o->adapt_val)) return tool_usage_error("bad point '%s' (expected X,Y,Z)", val);
        o->adapt_mode = SUBD_SR48_ADAPT_POINT;
    } else if (strcmp(c->name, "--plane") == 0) {
        if (tool_parse_doubles(val, 6, o->adapt_val) ||
            (o->adapt_val[3] == 0.0 && o->adapt_val[4] == 0.0 && o->adapt_val[5] == 0.0))
            return tool_usage_error("bad plane '%s' (expected X,Y,Z,NX,NY,NZ with a nonzero normal)", val);
        o->adapt_mode = SUBD_SR48_ADAPT_PLANE;
    } else { /* --ramp */
        if (strlen(val) != 1 || val[0] < 'x' || val[0] > 'z')
            return tool_usage_error("bad ramp axis '%s' (expected x, y or z)", val);
        o->adapt_axis = (uint32_t)(val[0] - 'x');
        o->adapt_mode = SUBD_SR48_ADAPT_RAMP;
    }
    return EXIT_OK;
}

static int set_radius(const opt_ctx *c)
{
    if (tool_parse_double(c->val, 0.0, 1e30, &c->o->radius) || !(c->o->radius > 0.0))
        return tool_usage_error("bad radius '%s' (a positive number, input units)", c->val);
    return EXIT_OK;
}

static const tool_option sr48_options[] = {
    {"--point", NULL, "X,Y,Z", 0, OPT_ADAPT, set_adapt_mode,
     "(sr48) finest at this point, one level coarser per radius away"},
    {"--radius", NULL, "R", 0, OPT_ADAPT, set_radius,
     "(sr48 --point) distance per level (default: bounding-box\n"
     "diagonal / (2 N))"},
    {"--ramp", NULL, "A", 0, OPT_ADAPT, set_adapt_mode,
     "(sr48) level rising along axis x, y or z from 0 to N"},
    {"--plane", NULL, "P,N", 0, OPT_ADAPT, set_adapt_mode,
     "(sr48) level N on the side of the plane through P the normal N\n"
     "points to, level 0 elsewhere (X,Y,Z,NX,NY,NZ)"},
};

static int sr48_check(const command *cmd, tool_opts *o)
{
    (void)cmd;
    if (o->limit && o->stream) return tool_usage_error("--limit applies to 'loop --stream' only");
    return EXIT_OK;
}

/* -l defaults to 2 uniform, 6 with a mode (adapt's default). */
static int sr48_finish(const command *cmd, tool_opts *o)
{
    (void)cmd;
    if (o->has_chord) o->adapt_mode = SUBD_SR48_ADAPT_CHORD; /* the shared --chord is a mode here */
    if (!o->has_levels && o->adapt_mode != SUBD_SR48_ADAPT_UNIFORM) o->levels = SR48_MODE_LEVELS;
    if (o->radius > 0.0 && o->adapt_mode != SUBD_SR48_ADAPT_POINT) return tool_usage_error("--radius goes with --point");
    return EXIT_OK;
}

/* adapt (deprecated): a mode is required. */
static int adapt_finish(const command *cmd, tool_opts *o)
{
    if (o->adapt_mode == SUBD_SR48_ADAPT_UNIFORM && !o->has_chord)
        return tool_usage_error("'%s' needs an adaptation mode (--point, --ramp, --plane or --chord)", cmd->name);
    return sr48_finish(cmd, o);
}

static size_t sr48_describe(const tool_opts *o, char *buf, size_t k, size_t n)
{
    static const char *const mode[] = {"", " --point", " --ramp", " --plane", "", " --chord"};
    if (o->stream) k = tool_describe_add(buf, k, n, " --stream");
    if (o->no_smooth) k = tool_describe_add(buf, k, n, " --no-smooth");
    if ((unsigned)o->adapt_mode < 6u) k = tool_describe_add(buf, k, n, "%s", mode[o->adapt_mode]);
    return k;
}

/* What the three spellings share: the functions, the options, the level range. */
#define SR48_DESCRIPTOR                                                                              \
    .canonical = "sr48", .scheme = "sr48", .max_levels = SUBD_SR48_MAX_STEPS, .opts = sr48_options,    \
    .num_opts = sizeof sr48_options / sizeof sr48_options[0], .check = sr48_check, .plan = sr48_plan, \
    .run = sr48_run, .stream = sr48_stream, .describe = sr48_describe

const command tool_cmd_sr48 = {
    .name = "sr48",
    .synopsis = "[-l N] [MODE] INPUT -o OUTPUT",
    .summary = "semi-regular 4-8 refinement with Zwart-Powell box-spline\n"
               "smoothing, N binary steps after pre-processing (default 2;\n"
               "-l 0 writes the pre-processed mesh); with a MODE, a variable-\n"
               "resolution mesh up to level N (default 6): --point X,Y,Z\n"
               "[--radius R] | --ramp x|y|z | --plane X,Y,Z,NX,NY,NZ |\n"
               "--chord EPS; --no-smooth; --stream: one triangle at a time",
    .flags = CMD_OUTPUT_REQUIRED | CMD_LEVELS | CMD_LEVEL0,
    .default_levels = 2,
    .options = OPT_NO_SMOOTH | OPT_ADAPT | OPT_CHORD | OPT_STREAM,
    .finish = sr48_finish,
    SR48_DESCRIPTOR,
};

/* Deprecated until 1.0: `semireg48 ...` = `sr48 ...` without a mode. */
const command tool_cmd_semireg48 = {
    .name = "semireg48",
    .synopsis = "(deprecated)",
    .summary = "the 0.5 name of 'sr48' without a MODE, kept until 1.0",
    .flags = CMD_OUTPUT_REQUIRED | CMD_LEVELS | CMD_LEVEL0 | CMD_DEPRECATED,
    .default_levels = 2,
    .options = OPT_NO_SMOOTH | OPT_STREAM,
    .finish = sr48_finish,
    SR48_DESCRIPTOR,
};

/* Deprecated until 1.0: `adapt -l MAX MODE ...` = `sr48 -l MAX MODE ...` (MODE required,
 * -l default 6). */
const command tool_cmd_adapt = {
    .name = "adapt",
    .synopsis = "(deprecated)",
    .summary = "the 0.5 name of 'sr48' with a MODE (required; -l default 6),\n"
               "kept until 1.0",
    .flags = CMD_OUTPUT_REQUIRED | CMD_LEVELS | CMD_LEVEL0 | CMD_DEPRECATED,
    .default_levels = SR48_MODE_LEVELS,
    .options = OPT_NO_SMOOTH | OPT_ADAPT | OPT_CHORD | OPT_STREAM,
    .finish = adapt_finish,
    SR48_DESCRIPTOR,
};
