/* SPDX-License-Identifier: MIT */
/* subd tool: `pia`, progressive interpolation (subd_pia): a control mesh whose Loop limit
 * surface passes through the input's vertices. Its options (--tol, required; --max-iter,
 * --method), its --stats members (the totals and the paper's two phases) and its warning
 * when --tol was not reached (exit 5, the output is written).
 */
#define _POSIX_C_SOURCE 200809L
#include <stdlib.h>
#include <string.h>
#include "subd_tool.h"
#include "cmd_loop.h"
#include "host_real.h"

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
    if (!res.converged) {
        /* after the reports: the --stats object says "converged":false */
        x->exit_status = EXIT_NOT_CONVERGED;
        snprintf(x->warning, sizeof x->warning,
                 "subd: pia: tolerance %.9g not reached: max error %.9g after --max-iter %lu iterations\n", o->tol,
                 host_real_to_double(res.max_err), (unsigned long)o->max_iter);
    }
    if (!o->stats && !o->quiet) {
        progress_pause();
        fprintf(stderr, "pia: %lu iterations (boundary %lu, interior %lu), max error %.6g, mean error %.6g, %s\n",
                (unsigned long)res.iterations, (unsigned long)res.boundary.iterations,
                (unsigned long)res.interior.iterations, host_real_to_double(res.max_err),
                host_real_to_double(res.mean_err), res.converged ? "converged" : "NOT converged (raise --max-iter or --tol)");
    }
    return SUBD_OK;
}

static int set_tol(const opt_ctx *c)
{
    if (tool_parse_double(c->val, 0.0, 1e30, &c->o->tol) || !(c->o->tol > 0.0))
        return tool_usage_error("bad tolerance '%s' (a positive number, input units)", c->val);
#if SUBD_FIXED
    /* Q16.16 resolves 2^-16; the limit operator's rounding leaves about 1.7 LSB */
    if (c->o->tol < 2.0 / 65536.0)
        return tool_usage_error("--tol %s is below what Q16.16 can resolve (minimum 2 LSB = 3.05e-05)", c->val);
#endif
    return EXIT_OK;
}

static int set_max_iter(const opt_ctx *c)
{
    if (tool_parse_u32(c->val, 1000000u, &c->o->max_iter) || c->o->max_iter == 0)
        return tool_usage_error("bad iteration count '%s' (1..1000000)", c->val);
    return EXIT_OK;
}

static int set_method(const opt_ctx *c)
{
    if (strcmp(c->val, "paper") == 0) c->o->method = SUBD_PIA_PAPER;
    else if (strcmp(c->val, "fast") == 0) c->o->method = SUBD_PIA_FAST;
    else return tool_usage_error("bad method '%s' (expected paper or fast)", c->val);
    return EXIT_OK;
}

static const tool_option pia_options[] = {
    {"--tol", NULL, "T", 0, OPT_TOL, set_tol,
     "(pia) stop when every limit point is within T of its input vertex"},
    {"--max-iter", NULL, "K", 0, OPT_MAX_ITER, set_max_iter, "(pia) at most K iterations (default 100)"},
    {"--method", NULL, "M", 0, OPT_METHOD, set_method,
     "(pia) paper (V += P - LV) or fast (default; see src/pia.c)"},
};

static void pia_init(tool_opts *o)
{
    o->max_iter = 100;
    o->method = SUBD_PIA_FAST;
}

static int pia_finish(const command *cmd, tool_opts *o)
{
    int rc = tool_loop_boundary(cmd, o);
    if (rc == EXIT_OK && !(o->given & OPT_TOL)) return tool_usage_error("'%s' needs --tol T", cmd->name);
    return rc;
}

static size_t pia_describe(const tool_opts *o, char *buf, size_t k, size_t n)
{
    if (o->given & OPT_TOL) k = tool_describe_add(buf, k, n, " --tol %g", o->tol);
    return tool_loop_describe_rules(o, buf, k, n);
}

const command tool_cmd_pia = {
    .name = "pia",
    .canonical = "pia",
    .synopsis = "--tol T INPUT -o OUTPUT",
    .summary = "progressive interpolation: a control mesh whose Loop\n"
               "limit surface passes through INPUT's vertices;\n"
               "--max-iter K (default 100), --method paper|fast",
    .flags = CMD_OUTPUT_REQUIRED,
    .scheme = "pia",
    .options = OPT_BOUNDARY | OPT_CREASE | OPT_TAGS | OPT_TOL | OPT_MAX_ITER | OPT_METHOD,
    .opts = pia_options,
    .num_opts = sizeof pia_options / sizeof pia_options[0],
    .init = pia_init,
    .finish = pia_finish,
    .plan = pia_plan,
    .run = pia_run,
    .describe = pia_describe,
};
