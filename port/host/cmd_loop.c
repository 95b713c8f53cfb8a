/* SPDX-License-Identifier: MIT */
/* subd tool: the Loop commands. `loop` (subd_loop; --stream: subd_loop_stream, --stream
 * --limit: its limit form, --stream --limit --chord EPS: subd_loop_adapt_stream) and `limit`
 * (subd_loop_limit: the control vertices moved to their limit positions, --normals). Their
 * boundary rule (--boundary paper|bspline) and its description are shared with pia
 * (cmd_pia.c) through tool_loop_boundary / tool_loop_describe_rules.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdlib.h>
#include <string.h>
#include "subd_tool.h"
#include "cmd_loop.h"
#include "host_real.h"

/* The subd_loop_opts of the loop command: --stream --limit sets SUBD_LOOP_STREAM_LIMIT. */
static subd_loop_opts loop_opts_of(const tool_opts *o)
{
    subd_loop_opts lo;
    lo.levels = o->levels;
    lo.boundary = o->boundary;
    lo.flags = o->limit ? SUBD_LOOP_STREAM_LIMIT : 0u;
    return lo;
}

/* loop --stream --limit --chord EPS: the adaptive limit stream's options. */
static subd_loop_adapt_opts loop_adapt_opts_of(const tool_opts *o)
{
    subd_loop_adapt_opts ao;
    memset(&ao, 0, sizeof ao);
    ao.loop = loop_opts_of(o);
    ao.mode = SUBD_LOOP_ADAPT_CHORD;
    ao.chord = host_real_from_double(o->chord);
    return ao;
}

static int loop_chord(const tool_opts *o) { return o->has_chord; }

static int loop_plan(const subd_mesh *in, const tool_opts *o, uint32_t *bytes, subd_diag *d)
{
    subd_loop_opts lo = loop_opts_of(o);
    if (o->stream && loop_chord(o)) { /* loop --stream --limit --chord EPS */
        subd_loop_adapt_opts ao = loop_adapt_opts_of(o);
        return subd_loop_adapt_stream_plan(in, &ao, bytes, d);
    }
    return o->stream ? subd_loop_stream_plan(in, &lo, bytes, d) : subd_loop_plan(in, &lo, bytes, d);
}

static int loop_run(subd_arena *a, const subd_mesh *in, const tool_opts *o, subd_mesh *out, scheme_extra *x,
                    subd_diag *d)
{
    subd_loop_opts lo = loop_opts_of(o);
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

/* ------------------------------------------------------------------------------------ */
/* loop --stream                                                                          */

/* The level-L counts in closed form (subd_loop.h): triangles 4^L F, the vertices some
 * triangle uses, edges, and the size of the id space. */
static stream_counts loop_counts(const subd_mesh *in, uint32_t levels)
{
    uint64_t n = (uint64_t)1 << levels, f = in->num_faces;
    uint64_t inner = f * ((n - 1u) * (n - 2u) / 2u);
    stream_counts c;
    c.tris = f * n * n;
    c.verts = (uint64_t)(in->num_verts - in->num_isolated) + (uint64_t)in->num_edges * (n - 1u) + inner;
    c.edges = (uint64_t)in->num_edges * n + 3u * f * (n * (n - 1u) / 2u);
    c.ids = (uint64_t)in->num_verts + (uint64_t)in->num_corners * (n - 1u) + inner;
    c.boundary_edges = (uint64_t)in->num_boundary_edges << levels;
    c.verts_exact = 1;
    c.tris_bound = 0;
    return c;
}

static int loop_pass(void *ctx, subd_arena *a, const subd_tri_sink *sink, subd_diag *d)
{
    const tool_run *r = (const tool_run *)ctx;
    subd_loop_opts lo = loop_opts_of(&r->o);
    return subd_loop_stream(a, &r->in.mesh, &lo, sink, d);
}

static int loop_adapt_pass(void *ctx, subd_arena *a, const subd_tri_sink *sink, subd_diag *d)
{
    const tool_run *r = (const tool_run *)ctx;
    subd_loop_adapt_opts ao = loop_adapt_opts_of(&r->o);
    return subd_loop_adapt_stream(a, &r->in.mesh, &ao, sink, d);
}

/* loop --stream: Loop's closed-form counts; with --chord the triangle count is the stream's
 * choice, so a first pass counts (STL writes it first, the gathering sinks size by it); the
 * ids are those of level L, the vertex count is gathered. */
static int loop_stream(tool_run *r, subd_arena *a, subd_diag *d)
{
    const subd_mesh *in = &r->in.mesh;
    subd_loop_opts lo = loop_opts_of(&r->o);
    subd_loop_adapt_opts ao = loop_adapt_opts_of(&r->o);
    tool_stream ts;
    stream_result res;
    uint32_t sb = 0;
    int st;
    memset(&ts, 0, sizeof ts);
    ts.pass = loop_chord(&r->o) ? loop_adapt_pass : loop_pass;
    ts.ctx = r;
    ts.limit = r->o.limit;
    ts.c = loop_counts(in, r->o.levels);
    if (loop_chord(&r->o)) {
        uint64_t n = 0;
        if ((st = tool_stream_count(r, a, &ts, d, &n)) != SUBD_OK) return st;
        ts.c.tris = n;
        ts.c.verts = ts.c.ids < 3u * n ? ts.c.ids : 3u * n; /* a bound: the sink counts them */
        ts.c.verts_exact = 0;
        ts.c.edges = 3u * n / 2u;
    }
    st = tool_stream_write(r, a, &ts, d, &res);
    /* the stream's own arena (its plan; the mesh not counted), beside arena_planned */
    if ((loop_chord(&r->o) ? subd_loop_adapt_stream_plan(in, &ao, &sb, NULL) : subd_loop_stream_plan(in, &lo, &sb, NULL)) !=
        SUBD_OK)
        sb = 0;
    snprintf(r->extra.json, sizeof r->extra.json,
             "\"stream\":true,\"limit\":%s,\"triangles\":%llu,\"checksum\":\"%08lx\",\"stream_arena\":%lu",
             r->o.limit ? "true" : "false", (unsigned long long)res.tris, (unsigned long)res.hash, (unsigned long)sb);
    return st;
}

/* ------------------------------------------------------------------------------------ */
/* Options, checks, descriptors                                                           */

static int loop_set_flag(const opt_ctx *c)
{
    if (strcmp(c->name, "--limit") == 0) c->o->limit = 1;
    else c->o->normals = 1; /* --normals */
    return EXIT_OK;
}

static const tool_option loop_options[] = {
    {"--limit", NULL, NULL, 0, OPT_STREAM, loop_set_flag,
     "(loop --stream) limit positions and unit limit normals: OBJ vn\n"
     "records; STL facets keep the unit normal of the triangle"},
};

static const tool_option limit_options[] = {
    {"--normals", NULL, NULL, 0, OPT_NORMALS, loop_set_flag,
     "(limit) also write unit limit normals as OBJ vn records"},
};

int tool_loop_boundary(const command *cmd, tool_opts *o)
{
    const char *b = o->boundary_name;
    if (!b) return EXIT_OK; /* paper, the default (zero) */
    if (strcmp(b, "paper") == 0) o->boundary = SUBD_LOOP_BOUNDARY_PAPER;
    else if (strcmp(b, "bspline") == 0) o->boundary = SUBD_LOOP_BOUNDARY_BSPLINE;
    else return tool_usage_error("bad boundary rule '%s' for '%s' (expected paper or bspline)", b, cmd->name);
    return EXIT_OK;
}

size_t tool_loop_describe_rules(const tool_opts *o, char *buf, size_t k, size_t n)
{
    if (o->boundary == SUBD_LOOP_BOUNDARY_BSPLINE) k = tool_describe_add(buf, k, n, " --boundary bspline");
    if (o->has_crease_angle) k = tool_describe_add(buf, k, n, " --crease-angle %g", o->crease_deg);
    return k;
}

static int loop_check(const command *cmd, tool_opts *o)
{
    (void)cmd;
    if (loop_chord(o) && !(o->stream && o->limit))
        return tool_usage_error("loop: --chord needs --stream --limit (the adaptive limit stream)");
    return EXIT_OK;
}

static int limit_finish(const command *cmd, tool_opts *o)
{
    int rc = tool_loop_boundary(cmd, o);
    if (rc == EXIT_OK && o->normals && o->out_format != HOST_FMT_OBJ)
        return tool_usage_error("--normals needs an .obj output");
    return rc;
}

static size_t loop_describe(const tool_opts *o, char *buf, size_t k, size_t n)
{
    if (o->stream) k = tool_describe_add(buf, k, n, " --stream%s", o->limit ? " --limit" : "");
    return tool_loop_describe_rules(o, buf, k, n);
}

#define LOOP_OPTS (OPT_BOUNDARY | OPT_CREASE | OPT_TAGS)
const command tool_cmd_loop = {
    .name = "loop",
    .canonical = "loop",
    .synopsis = "[-l N] INPUT -o OUTPUT",
    .summary = "Loop subdivision of a triangle mesh (default 1 level);\n"
               "--boundary paper|bspline, --crease-angle DEG;\n"
               "--stream [--limit]: one triangle at a time (.stl)",
    .flags = CMD_OUTPUT_REQUIRED | CMD_LEVELS,
    .scheme = "loop",
    .default_levels = 1,
    .max_levels = SUBD_MAX_LEVELS,
    .options = LOOP_OPTS | OPT_STREAM | OPT_CHORD,
    .opts = loop_options,
    .num_opts = sizeof loop_options / sizeof loop_options[0],
    .check = loop_check,
    .finish = tool_loop_boundary,
    .plan = loop_plan,
    .run = loop_run,
    .stream = loop_stream,
    .describe = loop_describe,
};

const command tool_cmd_limit = {
    .name = "limit",
    .canonical = "limit",
    .synopsis = "INPUT -o OUTPUT",
    .summary = "control vertices moved to their Loop limit positions;\n"
               "--normals adds limit normals (OBJ vn)",
    .flags = CMD_OUTPUT_REQUIRED,
    .scheme = "limit",
    .options = LOOP_OPTS | OPT_NORMALS,
    .opts = limit_options,
    .num_opts = sizeof limit_options / sizeof limit_options[0],
    .finish = limit_finish,
    .plan = limit_plan,
    .run = limit_run,
    .describe = tool_loop_describe_rules,
};
