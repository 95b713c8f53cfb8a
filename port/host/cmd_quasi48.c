/* SPDX-License-Identifier: MIT */
/* subd tool: `quasi48`, quasi 4-8 subdivision (subd_quasi48): N binary steps (two make one
 * 4-8 refinement), --no-smooth, --boundary fixed|smooth|normal, --tag-boundary.
 */
#define _POSIX_C_SOURCE 200809L
#include <string.h>
#include "subd_tool.h"

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

static int set_tag_boundary(const opt_ctx *c)
{
    c->o->tag_boundary = 1;
    return EXIT_OK;
}

static const tool_option q48_options[] = {
    {"--tag-boundary", NULL, NULL, 0, OPT_Q48, set_tag_boundary,
     "(quasi48) tag boundary edges as creases (they stay put)"},
};

static int q48_finish(const command *cmd, tool_opts *o)
{
    const char *b = o->boundary_name;
    if (!b) return EXIT_OK;
    if (strcmp(b, "fixed") == 0) o->q48_boundary = SUBD_QUASI48_BOUNDARY_FIXED;
    else if (strcmp(b, "smooth") == 0) o->q48_boundary = SUBD_QUASI48_BOUNDARY_SMOOTH;
    else if (strcmp(b, "normal") == 0) o->q48_boundary = SUBD_QUASI48_BOUNDARY_NORMAL;
    else return tool_usage_error("bad boundary mode '%s' for '%s' (expected fixed, smooth or normal)", b, cmd->name);
    return EXIT_OK;
}

static size_t q48_describe(const tool_opts *o, char *buf, size_t k, size_t n)
{
    if (o->no_smooth) k = tool_describe_add(buf, k, n, " --no-smooth");
    if (o->has_crease_angle) k = tool_describe_add(buf, k, n, " --crease-angle %g", o->crease_deg);
    return k;
}

const command tool_cmd_quasi48 = {
    .name = "quasi48",
    .canonical = "quasi48",
    .synopsis = "[-l N] INPUT -o OUTPUT",
    .summary = "quasi 4-8 subdivision, N binary steps (default 2 = one\n"
               "4-8 refinement); --no-smooth, --boundary fixed|smooth|normal,\n"
               "--tag-boundary, --crease-angle DEG",
    .flags = CMD_OUTPUT_REQUIRED | CMD_LEVELS,
    .scheme = "quasi48",
    .default_levels = 2,
    .max_levels = SUBD_QUASI48_MAX_STEPS,
    .options = OPT_Q48 | OPT_NO_SMOOTH | OPT_CREASE | OPT_TAGS | OPT_BOUNDARY,
    .opts = q48_options,
    .num_opts = sizeof q48_options / sizeof q48_options[0],
    .finish = q48_finish,
    .plan = q48_plan,
    .run = q48_run,
    .describe = q48_describe,
};
