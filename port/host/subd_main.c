/* subd — the tinysubd host command-line tool.
 *
 *   subd COMMAND [options] INPUT [-o OUTPUT]
 *
 * Every command runs the same path: parse options -> read INPUT (.obj/.off) into an arena
 * sized by the reader's plan call -> plan and run the command's operation (scheme commands)
 * -> write OUTPUT by extension (.obj/.off via the library writers, .png via the renderer) ->
 * human report and/or --stats JSON. A scheme command is one row in the command table below
 * with a plan and a run function; everything else (options, arena budget, errors, exit codes,
 * output, stats) is shared.
 *
 * Exit status: 0 ok, 1 usage, 2 bad input, 3 resource limit, 4 output not writable.
 *
 * The tool is built once per arithmetic (subd = float32, subd-fixed = Q16.16), so tool users
 * see exactly what a device build of that arithmetic produces.
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "subd.h"
#include "fileio.h"
#include "host_real.h"
#include "render.h"

enum {
    EXIT_OK = 0,
    EXIT_USAGE = 1,
    EXIT_INPUT = 2,
    EXIT_LIMIT = 3,
    EXIT_OUTPUT = 4
};

#if SUBD_FIXED
#define ARITHMETIC "q16.16"
#else
#define ARITHMETIC "float32"
#endif

/* ------------------------------------------------------------------------------------ */
/* Options and the command table                                                         */

typedef struct tool_opts {
    const char *input;
    const char *output;
    host_format out_format;
    int stats;
    int has_budget;
    uint32_t budget;
    int has_levels;
    uint32_t levels;
    int render_opt_given; /* any of --size/--yaw/--pitch/--no-edges */
    render_opts ropt;
    /* scheme options */
    const char *boundary_name;   /* --boundary, interpreted by the command               */
    subd_loop_boundary boundary; /* loop/limit/pia: paper (default) | bspline             */
    subd_q48_boundary q48_boundary; /* quasi48: fixed (default) | smooth                  */
    int no_smooth;               /* --no-smooth (quasi48): refinement only                */
    int tag_boundary;            /* --tag-boundary: tag boundary edges as creases first   */
    int has_crease_angle;
    double crease_deg;           /* --crease-angle DEG: tag sharper edges as creases      */
    const char *tags;            /* --tags FILE: crease edges, corner and fixed vertices  */
    int normals;                 /* --normals (limit): write limit normals as OBJ vn      */
    double tol;                  /* --tol T (pia)                                         */
    uint32_t max_iter;           /* --max-iter K (pia)                                    */
    subd_pia_method method;      /* --method paper|fast (pia)                             */
    subd_alpha_opts alpha;       /* --order, --kernel, --alpha, --stiffness (alpha)       */
    subd_adapt_mode adapt_mode;  /* adapt: --point, --ramp, --plane or --chord            */
    double adapt_val[6];         /* the point (and plane normal), or the chord tolerance  */
    uint32_t adapt_axis;         /* --ramp x|y|z                                          */
    double radius;               /* --radius R (adapt --point)                            */
    unsigned given;              /* OPT_* bits of the scheme options given                */
} tool_opts;

/* Scheme options, as bits: each command lists the ones it accepts. */
#define OPT_BOUNDARY 0x01u
#define OPT_CREASE 0x02u
#define OPT_NORMALS 0x04u
#define OPT_TOL 0x08u
#define OPT_MAX_ITER 0x10u
#define OPT_METHOD 0x20u
#define OPT_Q48 0x40u /* --tag-boundary, --boundary fixed|smooth */
#define OPT_ALPHA 0x80u /* --order, --kernel, --alpha, --stiffness */
#define OPT_NO_SMOOTH 0x100u /* --no-smooth */
#define OPT_ADAPT 0x200u /* --point, --ramp, --plane, --chord, --radius */

/* What a scheme produced besides the output mesh: optional per-vertex normals (written as
 * OBJ vn) and extra --stats members (a JSON fragment without braces, e.g. "iterations":9). */
typedef struct scheme_extra {
    subd_real *normals;
    char json[256];
    void *host_mem; /* output arrays a scheme built in host memory (freed at exit) */
} scheme_extra;

/* Command flags. */
#define CMD_OUTPUT_NONE 0x01u     /* takes no -o (report only)                              */
#define CMD_OUTPUT_REQUIRED 0x02u /* -o is mandatory                                        */
#define CMD_PNG_ONLY 0x04u        /* the output must be .png                                */
#define CMD_LEVELS 0x08u          /* accepts -l N                                           */
#define CMD_LEVEL0 0x10u          /* -l 0 is meaningful                                     */

struct tool_run;

typedef struct command {
    const char *name;
    const char *synopsis; /* arguments after the name, for the usage text */
    const char *summary;  /* one line (continued lines start with '\n') */
    unsigned flags;
    const char *scheme;       /* paper scheme name for --stats, NULL for plain commands  */
    uint32_t default_levels;  /* used when -l is not given (CMD_LEVELS)                  */
    uint32_t max_levels;      /* largest -l N                                            */
    unsigned options;         /* OPT_* scheme options the command accepts                */
    /* Scheme commands: exact arena bytes run() needs for this input (after the input mesh,
     * which stays in the arena), and the operation itself (arena, const input -> output).
     * Both NULL: the output is the input mesh. Return a subd_status, diag filled. */
    int (*plan)(const subd_mesh *in, const tool_opts *o, uint32_t *bytes, subd_diag *d);
    int (*run)(subd_arena *a, const subd_mesh *in, const tool_opts *o, subd_mesh *out, scheme_extra *x,
               subd_diag *d);
    /* Human-readable report (info), written to `f`. */
    int (*report)(FILE *f, const struct tool_run *r);
} command;

/* Everything one invocation produced, for the report and --stats. */
typedef struct tool_run {
    const command *cmd;
    tool_opts o;
    host_mesh in;
    subd_mesh out;         /* result of run(), or a copy of in.mesh                       */
    void *work_mem;        /* separate arena for run() when there is no --arena budget    */
    subd_arena work;
    uint32_t planned;      /* arena bytes one device arena needs for the whole command    */
    uint32_t used;         /* measured peak of that (virtual) arena                       */
    double lib_ns;         /* time spent in library calls (parse, build, plan, run)       */
    uint32_t out_bytes;    /* bytes written to OUTPUT                                     */
    scheme_extra extra;
    int out_width, out_height;
} tool_run;

static int info_report(FILE *f, const tool_run *r);

/* ------------------------------------------------------------------------------------ */
/* Scheme commands: a plan and a run function each (the common path does the rest).      */

static subd_loop_opts loop_opts_of(const tool_opts *o)
{
    subd_loop_opts lo;
    lo.levels = o->levels;
    lo.boundary = o->boundary;
    lo.flags = 0;
    return lo;
}

static int loop_plan(const subd_mesh *in, const tool_opts *o, uint32_t *bytes, subd_diag *d)
{
    subd_loop_opts lo = loop_opts_of(o);
    (void)d;
    return subd_loop_plan(in, &lo, bytes);
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
    (void)d;
    return subd_loop_limit_plan(in, o->boundary, o->normals, bytes);
}

/* The limit and interpolation commands move the vertices: the output is the input's
 * topology with new positions. */
static int limit_run(subd_arena *a, const subd_mesh *in, const tool_opts *o, subd_mesh *out, scheme_extra *x,
                     subd_diag *d)
{
    subd_real *pos = NULL;
    int st = subd_loop_limit(a, in, o->boundary, &pos, o->normals ? &x->normals : NULL, d);
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
    (void)d;
    return subd_pia_plan(in, &po, bytes);
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
    snprintf(x->json, sizeof x->json,
             "\"method\":\"%s\",\"tol\":%.9g,\"iterations\":%lu,\"max_err\":%.9g,\"mean_err\":%.9g,\"converged\":%s",
             o->method == SUBD_PIA_FAST ? "fast" : "paper", o->tol, (unsigned long)res.iterations,
             host_real_to_double(res.max_err), host_real_to_double(res.mean_err), res.converged ? "true" : "false");
    if (!o->stats)
        fprintf(stderr, "pia: %lu iterations, max error %.6g, mean error %.6g, %s\n", (unsigned long)res.iterations,
                host_real_to_double(res.max_err), host_real_to_double(res.mean_err),
                res.converged ? "converged" : "NOT converged (raise --max-iter or --tol)");
    return SUBD_OK;
}

static subd_q48_opts q48_opts_of(const tool_opts *o)
{
    subd_q48_opts qo;
    qo.steps = o->levels;
    qo.boundary = o->q48_boundary;
    qo.flags = o->no_smooth ? SUBD_Q48_NO_SMOOTH : 0u;
    qo.len_bits = 0;
    return qo;
}

static int q48_plan(const subd_mesh *in, const tool_opts *o, uint32_t *bytes, subd_diag *d)
{
    subd_q48_opts qo = q48_opts_of(o);
    (void)d;
    return subd_quasi48_plan(in, &qo, bytes);
}

static int q48_run(subd_arena *a, const subd_mesh *in, const tool_opts *o, subd_mesh *out, scheme_extra *x,
                   subd_diag *d)
{
    subd_q48_opts qo = q48_opts_of(o);
    int st = subd_quasi48(a, in, &qo, out, d);
    if (st == SUBD_OK)
        snprintf(x->json, sizeof x->json, "\"binary_steps\":%lu,\"smoothing\":%s,\"boundary\":\"%s\"",
                 (unsigned long)o->levels, o->no_smooth ? "false" : "true",
                 o->q48_boundary == SUBD_Q48_BOUNDARY_SMOOTH ? "smooth" : "fixed");
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

static subd_adapt sr48_adapt_of(const tool_opts *o)
{
    subd_adapt ad;
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
    int st = subd_sr48_plan(in, so, SUBD_SR48_CLUSTERS_UNKNOWN, &bound);
    if (st != SUBD_OK) return st;
    mem = host_arena_alloc(&tmp, bound);
    if (!mem) return SUBD_ERR_NOMEM;
    st = subd_sr48_count_clusters(&tmp, in, &clusters, d);
    free(mem);
    if (st != SUBD_OK) return st;
    return subd_sr48_plan(in, so, clusters, bytes);
}

static int sr48_plan(const subd_mesh *in, const tool_opts *o, uint32_t *bytes, subd_diag *d)
{
    subd_sr48_opts so = sr48_opts_of(o);
    subd_adapt ad = sr48_adapt_of(o);
    uint32_t build = 0, extract = 0, keep;
    subd_arena tmp;
    subd_sr48 h;
    void *mem;
    int st = sr48_build_plan(in, &so, &build, d);
    if (st != SUBD_OK) return st;
    mem = host_arena_alloc(&tmp, build);
    if (!mem) return SUBD_ERR_NOMEM;
    st = subd_sr48_build(&tmp, in, &so, &h, d);
    keep = tmp.used; /* the hierarchy; the build's scratch above it is given back */
    if (st == SUBD_OK) st = subd_sr48_extract_plan(&h, &ad, &extract);
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
    subd_adapt ad = sr48_adapt_of(o);
    subd_adapt_report rep;
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
    if (!o->stats && ad.mode != SUBD_ADAPT_UNIFORM)
        fprintf(stderr, "adapt: %lu triangles (uniform level %lu: %lu, saved %lu), %lu forced splits\n",
                (unsigned long)rep.faces, (unsigned long)o->levels, (unsigned long)rep.uniform_faces,
                (unsigned long)(rep.uniform_faces - rep.faces), (unsigned long)rep.forced_splits);
    return SUBD_OK;
}

/* alpha: the semi-stationary operators. A mesh with faces gets the Doo-Sabin type surface
 * operator; a mesh of polylines (OBJ l records) gets the curve operator S_k once per
 * polyline, closed when its last index repeats its first. Curves are refined one at a time
 * in the arena (the plan is the largest single curve) and collected in host memory. */
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
    uint32_t l, most = 0, b, pts, m;
    int st;
    (void)d;
    if (in->num_faces) return subd_alpha_surface_plan(in, &o->alpha, bytes);
    if (!in->num_lines) return SUBD_ERR_EMPTY;
    for (l = 0; l < in->num_lines; l++) {
        int closed = alpha_is_closed(in, l, &m);
        st = subd_alpha_curve_plan(m, closed, &o->alpha, &b, &pts);
        if (st != SUBD_OK) return st;
        /* room for the gathered input points too */
        b += (3u * m * (uint32_t)sizeof(subd_real) + 7u) & ~7u;
        if (b > most) most = b;
    }
    *bytes = most;
    return SUBD_OK;
}

static int alpha_run(subd_arena *a, const subd_mesh *in, const tool_opts *o, subd_mesh *out, scheme_extra *x,
                     subd_diag *d)
{
    uint32_t l, total = 0, k, m, pts, b;
    int32_t continuity = 1;
    subd_real *pos;
    uint32_t *lstart, *lvert;
    int st;
    if (in->num_faces) {
        subd_alpha_surface_info info;
        st = subd_alpha_surface(a, in, &o->alpha, out, &info, d);
        if (st == SUBD_OK)
            snprintf(x->json, sizeof x->json, "\"order\":%lu,\"continuity\":%ld,\"geometry\":\"surface\"",
                     (unsigned long)o->alpha.order, (long)info.continuity);
        return st;
    }
    for (l = 0; l < in->num_lines; l++) {
        int closed = alpha_is_closed(in, l, &m);
        if ((st = subd_alpha_curve_plan(m, closed, &o->alpha, &b, &pts)) != SUBD_OK) return st;
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
        if (!p) return SUBD_ERR_NOMEM;
        for (k = 0; k < 3u * m; k++) p[k] = in->pos[3u * in->line_vert[s + k / 3u] + k % 3u];
        st = subd_alpha_curve(a, p, m, closed, &o->alpha, &co, d);
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
    snprintf(x->json, sizeof x->json, "\"order\":%lu,\"continuity\":%ld,\"geometry\":\"curves\"",
             (unsigned long)o->alpha.order, (long)continuity);
    return SUBD_OK;
}

#define LOOP_OPTS (OPT_BOUNDARY | OPT_CREASE)
static const command commands[] = {
    {"info", "INPUT", "counts, components, Euler characteristic, genus,\n"
                      "valences and bounding box of a mesh",
     CMD_OUTPUT_NONE, NULL, 0, 0, 0, NULL, NULL, info_report},
    {"convert", "INPUT -o OUTPUT", "write the mesh in OUTPUT's format",
     CMD_OUTPUT_REQUIRED, NULL, 0, 0, 0, NULL, NULL, NULL},
    {"render", "INPUT -o OUTPUT.png", "draw the mesh (shaded, with edges) as a PNG",
     CMD_OUTPUT_REQUIRED | CMD_PNG_ONLY, NULL, 0, 0, 0, NULL, NULL, NULL},
    {"loop", "[-l N] INPUT -o OUTPUT", "Loop subdivision of a triangle mesh (default 1 level);\n"
                                       "--boundary paper|bspline, --crease-angle DEG",
     CMD_OUTPUT_REQUIRED | CMD_LEVELS, "loop", 1, SUBD_MAX_LEVELS, LOOP_OPTS, loop_plan, loop_run, NULL},
    {"limit", "INPUT -o OUTPUT", "control vertices moved to their Loop limit positions;\n"
                                 "--normals adds limit normals (OBJ vn)",
     CMD_OUTPUT_REQUIRED, "limit", 0, 0, LOOP_OPTS | OPT_NORMALS, limit_plan, limit_run, NULL},
    {"pia", "--tol T INPUT -o OUTPUT", "progressive interpolation: a control mesh whose Loop\n"
                                       "limit surface passes through INPUT's vertices;\n"
                                       "--max-iter K (default 100), --method paper|fast",
     CMD_OUTPUT_REQUIRED, "pia", 0, 0, LOOP_OPTS | OPT_TOL | OPT_MAX_ITER | OPT_METHOD, pia_plan, pia_run, NULL},
    {"quasi48", "[-l N] INPUT -o OUTPUT", "quasi 4-8 subdivision, N binary steps (default 2 = one\n"
                                          "4-8 refinement); --no-smooth, --boundary fixed|smooth,\n"
                                          "--tag-boundary, --crease-angle DEG",
     CMD_OUTPUT_REQUIRED | CMD_LEVELS, "quasi48", 2, SUBD_Q48_MAX_STEPS, OPT_Q48 | OPT_NO_SMOOTH | OPT_CREASE, q48_plan, q48_run, NULL},
    {"alpha", "[-l N] INPUT -o OUTPUT", "semi-stationary alpha-subdivision: curves (OBJ l records)\n"
                                        "or the Doo-Sabin type surface; --order K, --kernel\n"
                                        "bspline|cos|poly|cosh, --alpha A, --stiffness S",
     CMD_OUTPUT_REQUIRED | CMD_LEVELS, "alpha", 1, SUBD_MAX_LEVELS, OPT_ALPHA, alpha_plan, alpha_run, NULL},
    {"semireg48", "[-l N] INPUT -o OUTPUT", "semi-regular 4-8 refinement with Zwart-Powell box-spline\n"
                                            "smoothing, N binary steps after pre-processing (default\n"
                                            "2; -l 0 writes the pre-processed mesh); --no-smooth",
     CMD_OUTPUT_REQUIRED | CMD_LEVELS | CMD_LEVEL0, "semireg48", 2, SUBD_SR48_MAX_STEPS, OPT_NO_SMOOTH, sr48_plan,
     sr48_run, NULL},
    {"adapt", "-l MAX MODE INPUT -o OUTPUT", "variable-resolution semi-regular 4-8 mesh up to MAX binary\n"
                                             "steps; MODE: --point X,Y,Z [--radius R] | --ramp x|y|z |\n"
                                             "--plane X,Y,Z,NX,NY,NZ | --chord EPS; --no-smooth",
     CMD_OUTPUT_REQUIRED | CMD_LEVELS | CMD_LEVEL0, "semireg48", 6, SUBD_SR48_MAX_STEPS, OPT_NO_SMOOTH | OPT_ADAPT,
     sr48_plan, sr48_run, NULL},
};
#define NUM_COMMANDS (sizeof commands / sizeof commands[0])

static const command *find_command(const char *name)
{
    size_t i;
    for (i = 0; i < NUM_COMMANDS; i++)
        if (strcmp(commands[i].name, name) == 0) return &commands[i];
    return NULL;
}

/* After a usage error: the synopsis and where the rest is, not the whole help (the
 * specific message above it stays visible). */
static void usage_short(FILE *f)
{
    fprintf(f, "usage: subd COMMAND [options] INPUT [-o OUTPUT]\n"
               "run 'subd --help' for the commands, options and exit codes\n");
}

static void usage(FILE *f)
{
    size_t i;
    int w = 0;
    for (i = 0; i < NUM_COMMANDS; i++)
        if ((int)strlen(commands[i].synopsis) > w) w = (int)strlen(commands[i].synopsis);
    fprintf(f, "usage: subd COMMAND [options] INPUT [-o OUTPUT]\n"
               "       subd help | --help | --version\n\n"
               "tinysubd %s host tool, %s build (%s).\n\ncommands:\n",
            SUBD_VERSION, ARITHMETIC, SUBD_FIXED ? "Q16.16 fixed point" : "IEEE single precision");
    for (i = 0; i < NUM_COMMANDS; i++) {
        const char *s = commands[i].summary;
        fprintf(f, "  %-8s %-*s  ", commands[i].name, w, commands[i].synopsis);
        for (; *s; s++) {
            if (*s == '\n') fprintf(f, "\n  %-8s %-*s  ", "", w, "");
            else fputc(*s, f);
        }
        fputc('\n', f);
    }
    fprintf(f,
            "\nformats, by extension (any case): .obj and .off are read and written;\n"
            ".png is written (a rendering of the result); .xyz is written as plain 'x y z'\n"
            "lines, polylines separated by a blank line (for CNC use).\n"
            "\noptions:\n"
            "  -o FILE          output file\n"
            "  -l N             subdivision levels (scheme commands; binary steps for quasi48,\n"
            "                   semireg48 and adapt, up to %d; other schemes up to %d)\n"
            "  --stats          print exactly one JSON object on stdout (keys: command, scheme,\n"
            "                   levels, arithmetic, input, output, arena_budget, arena_planned,\n"
            "                   arena_used, time_ms = milliseconds in library calls); the\n"
            "                   human report of 'info' then goes to stderr\n"
            "  --arena BYTES    simulate a device arena of BYTES bytes (suffix k = 1024,\n"
            "                   m = 1048576): exit 3 when the command needs more\n"
            "  --boundary R     loop/limit/pia: boundary and crease rule, paper (the paper's\n"
            "                   section 4, default) or bspline (midpoints, as OpenSubdiv and\n"
            "                   CGAL); quasi48: fixed (default) or smooth boundary vertices\n"
            "  --no-smooth      (quasi48, semireg48, adapt) refinement only, no smoothing\n"
            "  --tag-boundary   (quasi48) tag boundary edges as creases (they stay put)\n"
            "  --crease-angle D tag edges whose faces meet at more than D degrees as creases\n"
            "  --tags FILE      (loop, limit, pia, quasi48) tags from a text file, one per line:\n"
            "                   'crease I J' (the edge between vertices I and J), 'corner I',\n"
            "                   'fixed I'; vertex numbers 1-based as in OBJ, '#' comments\n"
            "  --normals        (limit) also write unit limit normals as OBJ vn records\n"
            "  --tol T          (pia) stop when every limit point is within T of its input vertex\n"
            "  --max-iter K     (pia) at most K iterations (default 100)\n"
            "  --method M       (pia) paper (V += P - LV) or fast (default; see src/pia.c)\n"
            "  --order K        (alpha) operator order S_K, 2..8 (S_3: the paper's Catmull-Clark variant)\n"
            "  --kernel K       (alpha) bspline (default), cos (C-curves: circles), poly, cosh\n"
            "  --alpha A        (alpha) angle as a fraction of a turn N/D (1/8) or degrees (45deg)\n"
            "  --stiffness S    (alpha) s = f(0), default 1; s <= -1 diverges (rejected)\n"
            "  --point X,Y,Z    (adapt) finest at this point, one level coarser per radius away\n"
            "  --radius R       (adapt --point) distance per level (default: bounding-box\n"
            "                   diagonal / (2 MAX))\n"
            "  --ramp A         (adapt) level rising along axis x, y or z from 0 to MAX\n"
            "  --plane P,N      (adapt) MAX on the side of the plane through P the normal N\n"
            "                   points to, level 0 elsewhere (X,Y,Z,NX,NY,NZ)\n"
            "  --chord EPS      (adapt) refine only where a triangle is more than EPS from the\n"
            "                   level-MAX surface (chordal tolerance, input units)\n"
            "  --size WxH       picture size in pixels (default 800x600, up to 8192x8192)\n"
            "  --yaw DEG        view rotation about the up axis (default 30)\n"
            "  --pitch DEG      view elevation, -90..90 (default 20)\n"
            "  --no-edges       do not draw polygon edges\n"
            "  -h, --help       print this text\n"
            "  --version        print the version and the arithmetic of this build\n"
            "Long options also take the form --name=VALUE. Picture options need a .png output.\n"
            "\nexit status:\n"
            "  0  success\n"
            "  1  usage error (unknown command or option, missing or bad argument)\n"
            "  2  bad input: INPUT unreadable, or 'FILE:LINE: reason' on stderr\n"
            "     (elements named in parentheses are 0-based, as in subd_diag)\n"
            "  3  resource limit: arena too small (says how many bytes are needed),\n"
            "     counts too large for 32-bit sizes, or host out of memory\n"
            "  4  OUTPUT cannot be written\n",
            2 * SUBD_MAX_LEVELS, SUBD_MAX_LEVELS);
}

static int usage_error(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fprintf(stderr, "subd: ");
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fprintf(stderr, "\n");
    usage_short(stderr);
    return EXIT_USAGE;
}

/* ------------------------------------------------------------------------------------ */
/* Tag files (--tags)                                                                     */

/* The half-edge from a to b or, when the edge only runs b -> a (a boundary edge), that
 * one; SUBD_NONE when a and b share no edge. */
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

/* One vertex number of a tag line: 1-based, within the mesh; returns 0 and sets *v, or 1. */
static int tag_vertex(const char *tok, const subd_mesh *m, uint32_t *v)
{
    char *end;
    unsigned long n;
    if (!tok || *tok < '0' || *tok > '9') return 1;
    errno = 0;
    n = strtoul(tok, &end, 10);
    if (errno || *end || n == 0 || n > m->num_verts) return 1;
    *v = (uint32_t)(n - 1u);
    return 0;
}

/* Applies a tag file to the input mesh: 'crease I J', 'corner I', 'fixed I' per line
 * (1-based vertex numbers, as in OBJ; '#' starts a comment; blank lines are skipped).
 * Errors name FILE:LINE and exit 2; nothing is applied unless the whole file is valid. */
static int apply_tag_file(const char *path, subd_mesh *m, int quiet)
{
    char *buf = NULL;
    uint32_t len = 0, pass, ncrease = 0, nvert = 0;
    if (host_read_file(path, &buf, &len) != 0) {
        fprintf(stderr, "subd: cannot read tag file '%s': %s\n", path, strerror(errno));
        return EXIT_INPUT;
    }
    /* pass 0 checks every line, pass 1 applies them: a bad file changes nothing */
    for (pass = 0; pass < 2u; pass++) {
        uint32_t pos = 0, line = 0;
        while (pos < len) {
            char text[256], *tok[5], *save = NULL, *hash;
            uint32_t n = 0, end = pos, v[2];
            while (end < len && buf[end] != '\n') end++;
            line++;
            if (end - pos >= sizeof text) {
                fprintf(stderr, "%s:%lu: line too long\n", path, (unsigned long)line);
                free(buf);
                return EXIT_INPUT;
            }
            memcpy(text, buf + pos, end - pos);
            text[end - pos] = '\0';
            pos = end + 1u;
            if ((hash = strchr(text, '#')) != NULL) *hash = '\0';
            /* up to four tokens, so a line with too many is seen as such */
            for (tok[n] = strtok_r(text, " \t\r", &save); tok[n] && n < 4u;)
                tok[++n] = strtok_r(NULL, " \t\r", &save);
            if (n == 0) continue;
            if (strcmp(tok[0], "crease") == 0 && n == 3 && !tag_vertex(tok[1], m, &v[0]) &&
                !tag_vertex(tok[2], m, &v[1])) {
                uint32_t h = find_edge(m, v[0], v[1]);
                if (h == SUBD_NONE) {
                    fprintf(stderr, "%s:%lu: vertices %s and %s share no edge\n", path, (unsigned long)line, tok[1],
                            tok[2]);
                    free(buf);
                    return EXIT_INPUT;
                }
                if (pass) {
                    subd_edge_tag_set(m, h, SUBD_ETAG_CREASE);
                    ncrease++;
                }
            } else if ((strcmp(tok[0], "corner") == 0 || strcmp(tok[0], "fixed") == 0) && n == 2 &&
                       !tag_vertex(tok[1], m, &v[0])) {
                if (pass) {
                    m->vert_tag[v[0]] |= (uint8_t)(tok[0][0] == 'c' ? SUBD_VTAG_CORNER : SUBD_VTAG_FIXED);
                    nvert++;
                }
            } else {
                fprintf(stderr, "%s:%lu: expected 'crease I J', 'corner I' or 'fixed I' with vertex numbers "
                                "1..%lu\n", path, (unsigned long)line, (unsigned long)m->num_verts);
                free(buf);
                return EXIT_INPUT;
            }
        }
    }
    free(buf);
    if (!quiet)
        fprintf(stderr, "subd: %s: %lu crease edge(s), %lu vertex tag(s)\n", path, (unsigned long)ncrease,
                (unsigned long)nvert);
    return EXIT_OK;
}

/* ------------------------------------------------------------------------------------ */
/* Option values                                                                          */

static int parse_u32(const char *s, uint32_t max, uint32_t *out)
{
    unsigned long long v = 0;
    if (!*s) return -1;
    for (; *s >= '0' && *s <= '9'; s++) {
        v = v * 10u + (unsigned)(*s - '0');
        if (v > max) return -1;
    }
    if (*s) return -1;
    *out = (uint32_t)v;
    return 0;
}

static int parse_bytes(const char *s, uint32_t *out)
{
    unsigned long long v = 0, mul = 1;
    if (!(*s >= '0' && *s <= '9')) return -1;
    for (; *s >= '0' && *s <= '9'; s++) {
        v = v * 10u + (unsigned)(*s - '0');
        if (v > UINT32_MAX) return -1;
    }
    if (*s == 'k' || *s == 'K') { mul = 1024u; s++; }
    else if (*s == 'm' || *s == 'M') { mul = 1048576u; s++; }
    if (*s) return -1;
    if (v * mul > UINT32_MAX) return -1;
    *out = (uint32_t)(v * mul);
    return 0;
}

static int parse_double(const char *s, double lo, double hi, double *out)
{
    char *end;
    double v;
    errno = 0;
    v = strtod(s, &end);
    if (end == s || *end || errno || !(v >= lo && v <= hi)) return -1;
    *out = v;
    return 0;
}

/* n comma-separated numbers (coordinates within +-1e6). */
static int parse_doubles(const char *s, int n, double *out)
{
    char buf[64];
    int i;
    for (i = 0; i < n; i++) {
        const char *c = strchr(s, ',');
        size_t len = (i + 1 < n) ? (c ? (size_t)(c - s) : sizeof buf) : strlen(s);
        if (len >= sizeof buf) return -1;
        memcpy(buf, s, len);
        buf[len] = '\0';
        if (parse_double(buf, -1e6, 1e6, &out[i])) return -1;
        s += len + (i + 1 < n ? 1u : 0u);
    }
    return 0;
}

/* alpha as an exact fraction of a turn: "N/D" or "DEGdeg" (degrees with up to 4 decimals,
 * turned into DEG * 10^4 / 3600000). */
static int parse_alpha(const char *s, int32_t *num, int32_t *den)
{
    char *end;
    long n, dd;
    size_t len = strlen(s);
    if (len > 3 && strcmp(s + len - 3, "deg") == 0) {
        double deg = strtod(s, &end);
        if (end != s + len - 3 || !(deg >= -36000.0 && deg <= 36000.0)) return -1;
        *num = (int32_t)(deg * 1e4 + (deg < 0 ? -0.5 : 0.5));
        *den = 3600000;
        return 0;
    }
    n = strtol(s, &end, 10);
    if (end == s) return -1;
    if (*end == '\0') { dd = 1; }
    else {
        const char *q = end + 1;
        if (*end != '/') return -1;
        dd = strtol(q, &end, 10);
        if (end == q || *end != '\0') return -1;
    }
    if (dd <= 0 || dd > 1000000000L || n < -1000000000L || n > 1000000000L) return -1;
    *num = (int32_t)n;
    *den = (int32_t)dd;
    return 0;
}

static int parse_size(const char *s, int *w, int *h)
{
    const char *x = strchr(s, 'x');
    char buf[32];
    uint32_t a, b;
    size_t n;
    if (!x) x = strchr(s, 'X');
    if (!x) return -1;
    n = (size_t)(x - s);
    if (n == 0 || n >= sizeof buf) return -1;
    memcpy(buf, s, n);
    buf[n] = '\0';
    if (parse_u32(buf, 8192u, &a) || parse_u32(x + 1, 8192u, &b) || a == 0 || b == 0) return -1;
    *w = (int)a;
    *h = (int)b;
    return 0;
}

/* Parses argv[2..] into *o. Returns EXIT_OK or EXIT_USAGE (message printed). */
static int parse_args(const command *cmd, int argc, char **argv, tool_opts *o)
{
    int i, no_more_options = 0;
    memset(o, 0, sizeof *o);
    render_opts_default(&o->ropt);
    subd_alpha_opts_default(&o->alpha);
    for (i = 2; i < argc; i++) {
        const char *a = argv[i], *val = NULL, *eq;
        char name[32];
        if (no_more_options || a[0] != '-' || a[1] == '\0') {
            if (o->input) return usage_error("more than one input file ('%s')", a);
            o->input = a;
            continue;
        }
        if (strcmp(a, "--") == 0) { no_more_options = 1; continue; }
        /* --name=value */
        eq = (a[1] == '-') ? strchr(a, '=') : NULL;
        if (eq) {
            size_t n = (size_t)(eq - a);
            if (n >= sizeof name) return usage_error("unknown option '%s'", a);
            memcpy(name, a, n);
            name[n] = '\0';
            val = eq + 1;
        } else {
            size_t n = strlen(a);
            if (n >= sizeof name) return usage_error("unknown option '%s'", a);
            memcpy(name, a, n + 1u);
        }
        if (strcmp(name, "-h") == 0 || strcmp(name, "--help") == 0) {
            usage(stdout);
            exit(EXIT_OK);
        }
        if (strcmp(name, "--stats") == 0 || strcmp(name, "--no-edges") == 0 || strcmp(name, "--normals") == 0 ||
            strcmp(name, "--no-smooth") == 0 || strcmp(name, "--tag-boundary") == 0) {
            if (val) return usage_error("option '%s' takes no value", name);
            if (strcmp(name, "--stats") == 0) o->stats = 1;
            else if (strcmp(name, "--normals") == 0) { o->normals = 1; o->given |= OPT_NORMALS; }
            else if (strcmp(name, "--no-smooth") == 0) { o->no_smooth = 1; o->given |= OPT_NO_SMOOTH; }
            else if (strcmp(name, "--tag-boundary") == 0) { o->tag_boundary = 1; o->given |= OPT_Q48; }
            else { o->ropt.edges = 0; o->render_opt_given = 1; }
            continue;
        }
        if (strcmp(name, "-o") && strcmp(name, "-l") && strcmp(name, "--arena") &&
            strcmp(name, "--size") && strcmp(name, "--yaw") && strcmp(name, "--pitch") &&
            strcmp(name, "--boundary") && strcmp(name, "--crease-angle") && strcmp(name, "--tol") &&
            strcmp(name, "--max-iter") && strcmp(name, "--method") && strcmp(name, "--order") &&
            strcmp(name, "--kernel") && strcmp(name, "--alpha") && strcmp(name, "--stiffness") &&
            strcmp(name, "--point") && strcmp(name, "--ramp") && strcmp(name, "--plane") &&
            strcmp(name, "--chord") && strcmp(name, "--radius") && strcmp(name, "--tags"))
            return usage_error("unknown option '%s'", a);
        if (!val) {
            if (i + 1 >= argc) return usage_error("option '%s' needs a value", name);
            val = argv[++i];
        }
        if (strcmp(name, "-o") == 0) {
            if (o->output) return usage_error("more than one output file ('%s')", val);
            if (!*val) return usage_error("empty output file name");
            o->output = val;
        } else if (strcmp(name, "-l") == 0) {
            if (!(cmd->flags & CMD_LEVELS)) return usage_error("option -l does not apply to '%s'", cmd->name);
            if (parse_u32(val, cmd->max_levels, &o->levels))
                return usage_error("bad level count '%s' (expected 0..%lu)", val, (unsigned long)cmd->max_levels);
            o->has_levels = 1;
        } else if (strcmp(name, "--boundary") == 0) {
            o->boundary_name = val; /* checked below, once the command is known */
        } else if (strcmp(name, "--tags") == 0) {
            if (o->tags) return usage_error("more than one tag file ('%s')", val);
            o->tags = val;
            o->given |= OPT_CREASE;
        } else if (strcmp(name, "--crease-angle") == 0) {
            if (parse_double(val, 0.0, 180.0, &o->crease_deg))
                return usage_error("bad crease angle '%s' (degrees, 0..180)", val);
            o->has_crease_angle = 1;
            o->given |= OPT_CREASE;
        } else if (strcmp(name, "--tol") == 0) {
            if (parse_double(val, 0.0, 1e30, &o->tol) || !(o->tol > 0.0))
                return usage_error("bad tolerance '%s' (a positive number, input units)", val);
#if SUBD_FIXED
            /* Q16.16 resolves 2^-16; the limit operator's rounding leaves about 1.7 LSB */
            if (o->tol < 2.0 / 65536.0)
                return usage_error("--tol %s is below what Q16.16 can resolve (minimum 2 LSB = 3.05e-05)", val);
#endif
            o->given |= OPT_TOL;
        } else if (strcmp(name, "--max-iter") == 0) {
            if (parse_u32(val, 1000000u, &o->max_iter) || o->max_iter == 0)
                return usage_error("bad iteration count '%s' (1..1000000)", val);
            o->given |= OPT_MAX_ITER;
        } else if (strcmp(name, "--method") == 0) {
            if (strcmp(val, "paper") == 0) o->method = SUBD_PIA_PAPER;
            else if (strcmp(val, "fast") == 0) o->method = SUBD_PIA_FAST;
            else return usage_error("bad method '%s' (expected paper or fast)", val);
            o->given |= OPT_METHOD;
        } else if (strcmp(name, "--order") == 0) {
            if (parse_u32(val, SUBD_ALPHA_MAX_ORDER, &o->alpha.order) || o->alpha.order < 2)
                return usage_error("bad order '%s' (2..%u)", val, SUBD_ALPHA_MAX_ORDER);
            o->given |= OPT_ALPHA;
        } else if (strcmp(name, "--kernel") == 0) {
            if (strcmp(val, "bspline") == 0) o->alpha.kernel = SUBD_ALPHA_BSPLINE;
            else if (strcmp(val, "cos") == 0) o->alpha.kernel = SUBD_ALPHA_COS;
            else if (strcmp(val, "poly") == 0) o->alpha.kernel = SUBD_ALPHA_POLY;
            else if (strcmp(val, "cosh") == 0) o->alpha.kernel = SUBD_ALPHA_COSH;
            else return usage_error("bad kernel '%s' (bspline, cos, poly or cosh)", val);
            o->given |= OPT_ALPHA;
        } else if (strcmp(name, "--alpha") == 0) {
            if (parse_alpha(val, &o->alpha.alpha_num, &o->alpha.alpha_den))
                return usage_error("bad alpha '%s' (a fraction of a turn N/D, e.g. 1/8, or degrees, e.g. 45deg)", val);
            o->given |= OPT_ALPHA;
        } else if (strcmp(name, "--stiffness") == 0) {
            double sv;
            if (parse_double(val, -1e4, 1e4, &sv)) return usage_error("bad stiffness '%s'", val);
            if (sv <= -1.0) return usage_error("stiffness %s <= -1: the subdivision diverges (paper, table 1)", val);
            o->alpha.stiffness = host_real_from_double(sv);
            o->given |= OPT_ALPHA;
        } else if (strcmp(name, "--point") == 0 || strcmp(name, "--plane") == 0 || strcmp(name, "--ramp") == 0 ||
                   strcmp(name, "--chord") == 0) {
            if (o->adapt_mode != SUBD_ADAPT_UNIFORM)
                return usage_error("give one adaptation mode (--point, --ramp, --plane or --chord)");
            if (strcmp(name, "--point") == 0) {
                if (parse_doubles(val, 3, o->adapt_val)) return usage_error("bad point '%s' (expected X,Y,Z)", val);
                o->adapt_mode = SUBD_ADAPT_POINT;
            } else if (strcmp(name, "--plane") == 0) {
                if (parse_doubles(val, 6, o->adapt_val) ||
                    (o->adapt_val[3] == 0.0 && o->adapt_val[4] == 0.0 && o->adapt_val[5] == 0.0))
                    return usage_error("bad plane '%s' (expected X,Y,Z,NX,NY,NZ with a nonzero normal)", val);
                o->adapt_mode = SUBD_ADAPT_PLANE;
            } else if (strcmp(name, "--ramp") == 0) {
                if (strlen(val) != 1 || val[0] < 'x' || val[0] > 'z')
                    return usage_error("bad ramp axis '%s' (expected x, y or z)", val);
                o->adapt_axis = (uint32_t)(val[0] - 'x');
                o->adapt_mode = SUBD_ADAPT_RAMP;
            } else {
                if (parse_double(val, 0.0, 1e30, &o->adapt_val[0]) || !(o->adapt_val[0] > 0.0))
                    return usage_error("bad chordal tolerance '%s' (a positive number, input units)", val);
                o->adapt_mode = SUBD_ADAPT_CHORD;
            }
            o->given |= OPT_ADAPT;
        } else if (strcmp(name, "--radius") == 0) {
            if (parse_double(val, 0.0, 1e30, &o->radius) || !(o->radius > 0.0))
                return usage_error("bad radius '%s' (a positive number, input units)", val);
            o->given |= OPT_ADAPT;
        } else if (strcmp(name, "--arena") == 0) {
            if (parse_bytes(val, &o->budget)) return usage_error("bad arena size '%s' (bytes, optional k or m suffix, < 4 GiB)", val);
            o->has_budget = 1;
        } else if (strcmp(name, "--size") == 0) {
            if (parse_size(val, &o->ropt.width, &o->ropt.height))
                return usage_error("bad picture size '%s' (expected WxH, 1..8192 each)", val);
            o->render_opt_given = 1;
        } else if (strcmp(name, "--yaw") == 0) {
            if (parse_double(val, -1e6, 1e6, &o->ropt.yaw_deg)) return usage_error("bad yaw angle '%s' (degrees)", val);
            o->render_opt_given = 1;
        } else { /* --pitch */
            if (parse_double(val, -90.0, 90.0, &o->ropt.pitch_deg))
                return usage_error("bad pitch angle '%s' (degrees, -90..90)", val);
            o->render_opt_given = 1;
        }
    }
    if (!o->input) return usage_error("'%s' needs an input file", cmd->name);
    if (host_format_of(o->input) != HOST_FMT_OBJ && host_format_of(o->input) != HOST_FMT_OFF)
        return usage_error("cannot read '%s': input must be .obj or .off", o->input);
    if (o->output) {
        if (cmd->flags & CMD_OUTPUT_NONE) return usage_error("'%s' writes no output file (no -o)", cmd->name);
        o->out_format = host_format_of(o->output);
        if (o->out_format == HOST_FMT_UNKNOWN)
            return usage_error("cannot write '%s': output must be .obj, .off, .png or .xyz", o->output);
        if ((cmd->flags & CMD_PNG_ONLY) && o->out_format != HOST_FMT_PNG)
            return usage_error("'%s' writes a .png picture", cmd->name);
    } else if (cmd->flags & CMD_OUTPUT_REQUIRED) {
        return usage_error("'%s' needs an output file (-o OUTPUT)", cmd->name);
    }
    if (o->render_opt_given && o->out_format != HOST_FMT_PNG)
        return usage_error("picture options (--size, --yaw, --pitch, --no-edges) need a .png output");
    if (o->boundary_name) {
        const char *b = o->boundary_name;
        if (cmd->options & OPT_BOUNDARY) {
            if (strcmp(b, "paper") == 0) o->boundary = SUBD_LOOP_BOUNDARY_PAPER;
            else if (strcmp(b, "bspline") == 0) o->boundary = SUBD_LOOP_BOUNDARY_BSPLINE;
            else return usage_error("bad boundary rule '%s' for '%s' (expected paper or bspline)", b, cmd->name);
        } else if (cmd->options & OPT_Q48) {
            if (strcmp(b, "fixed") == 0) o->q48_boundary = SUBD_Q48_BOUNDARY_FIXED;
            else if (strcmp(b, "smooth") == 0) o->q48_boundary = SUBD_Q48_BOUNDARY_SMOOTH;
            else return usage_error("bad boundary mode '%s' for '%s' (expected fixed or smooth)", b, cmd->name);
        } else {
            return usage_error("option --boundary does not apply to '%s'", cmd->name);
        }
    }
    if (o->given & ~cmd->options) return usage_error("option not accepted by '%s' (see subd --help)", cmd->name);
    if ((cmd->options & OPT_TOL) && !(o->given & OPT_TOL)) return usage_error("'%s' needs --tol T", cmd->name);
    if (o->normals && o->out_format != HOST_FMT_OBJ) return usage_error("--normals needs an .obj output");
    if (!(o->given & OPT_MAX_ITER)) o->max_iter = 100;
    if (!(o->given & OPT_METHOD)) o->method = SUBD_PIA_FAST;
    if (!o->has_levels) o->levels = cmd->default_levels;
    o->alpha.levels = o->levels;
    if ((cmd->flags & CMD_LEVELS) && !(cmd->flags & CMD_LEVEL0) && cmd->run && o->levels == 0)
        return usage_error("'%s' needs at least one level (-l 1..%lu)", cmd->name, (unsigned long)cmd->max_levels);
    if ((cmd->options & OPT_ADAPT) && o->adapt_mode == SUBD_ADAPT_UNIFORM)
        return usage_error("'%s' needs an adaptation mode (--point, --ramp, --plane or --chord)", cmd->name);
    if (o->radius > 0.0 && o->adapt_mode != SUBD_ADAPT_POINT) return usage_error("--radius goes with --point");
    return EXIT_OK;
}

/* ------------------------------------------------------------------------------------ */
/* Errors                                                                                 */

static void print_element(const subd_diag *d)
{
    if (d->face != SUBD_NONE) fprintf(stderr, " (face %lu)", (unsigned long)d->face);
    else if (d->polyline != SUBD_NONE) fprintf(stderr, " (polyline %lu)", (unsigned long)d->polyline);
    else if (d->vertex != SUBD_NONE) fprintf(stderr, " (vertex %lu)", (unsigned long)d->vertex);
}

static int arena_too_small(uint32_t needed, uint32_t have)
{
    fprintf(stderr, "subd: arena too small: needs %lu bytes, have %lu\n", (unsigned long)needed,
            (unsigned long)have);
    return EXIT_LIMIT;
}

/* Maps a library failure on `file` to a message and an exit status. */
static int library_error(const char *file, int st, const subd_diag *d, int have_budget, uint32_t budget)
{
    if (st == SUBD_ERR_NOMEM) {
        if (have_budget) return arena_too_small(d->bytes_needed, budget);
        fprintf(stderr, "subd: %s: internal error: arena planned too small (needs %lu bytes)\n", file,
                (unsigned long)d->bytes_needed);
        return EXIT_LIMIT;
    }
    if (d->line) fprintf(stderr, "%s:%lu: %s", file, (unsigned long)d->line, subd_status_str(st));
    else fprintf(stderr, "%s: %s", file, subd_status_str(st));
    print_element(d);
    fputc('\n', stderr);
    if (st == SUBD_ERR_TOO_BIG) return EXIT_LIMIT;
    if (st == SUBD_ERR_PARAM) return EXIT_USAGE;
    return EXIT_INPUT;
}

static int out_of_memory(void)
{
    fprintf(stderr, "subd: out of memory\n");
    return EXIT_LIMIT;
}

/* ------------------------------------------------------------------------------------ */
/* The info report                                                                        */

static uint32_t uf_find(uint32_t *parent, uint32_t x)
{
    while (parent[x] != x) {
        parent[x] = parent[parent[x]]; /* path halving; iterative, no recursion */
        x = parent[x];
    }
    return x;
}

/* Connected components of the faces (through shared edges, via twin). Returns the count, or
 * UINT32_MAX when out of memory. Vertex-only contact cannot join components: the builder
 * rejects such non-manifold vertices. */
static uint32_t face_components(const subd_mesh *m)
{
    uint32_t *parent, f, c, n = 0;
    if (m->num_faces == 0) return 0;
    parent = (uint32_t *)malloc((size_t)m->num_faces * sizeof *parent);
    if (!parent) return UINT32_MAX;
    for (f = 0; f < m->num_faces; f++) parent[f] = f;
    for (c = 0; c < m->num_corners; c++) {
        uint32_t t = m->twin[c];
        if (t != SUBD_NONE) {
            uint32_t a = uf_find(parent, m->corner_face[c]), b = uf_find(parent, m->corner_face[t]);
            if (a != b) {
                if (a < b) parent[b] = a;
                else parent[a] = b;
            }
        }
    }
    for (f = 0; f < m->num_faces; f++)
        if (uf_find(parent, f) == f) n++;
    free(parent);
    return n;
}

/* Prints "k:count" pairs of a histogram, or "none". */
static void print_hist(FILE *f, const uint32_t *h, uint32_t n)
{
    uint32_t k;
    int any = 0;
    for (k = 0; k < n; k++)
        if (h[k]) {
            fprintf(f, "%s%lu:%lu", any ? " " : "", (unsigned long)k, (unsigned long)h[k]);
            any = 1;
        }
    if (!any) fprintf(f, "none");
    fputc('\n', f);
}

static void print_real(FILE *f, subd_real x)
{
    char buf[32];
    uint32_t n = subd_real_format(x, buf);
    fwrite(buf, 1, n, f);
}

static int info_report(FILE *f, const tool_run *r)
{
    const subd_mesh *m = &r->in.mesh;
    uint32_t fsize[SUBD_MAX_FACE_SIZE + 1], *val_int = NULL, *val_bnd = NULL;
    uint32_t v, fc, k, max_val = 0, comps, used_verts;
    int32_t chi, chi_surf;
    int64_t twice_genus;
    subd_real lo[3], hi[3];

    memset(fsize, 0, sizeof fsize);
    for (fc = 0; fc < m->num_faces; fc++) {
        uint32_t s = subd_face_size(m, fc);
        if (s <= SUBD_MAX_FACE_SIZE) fsize[s]++;
    }
    for (v = 0; v < m->num_verts; v++) {
        uint32_t val = subd_vertex_valence(m, v);
        if (val > max_val) max_val = val;
    }
    val_int = (uint32_t *)calloc((size_t)max_val + 1u, sizeof *val_int);
    val_bnd = (uint32_t *)calloc((size_t)max_val + 1u, sizeof *val_bnd);
    comps = face_components(m);
    if (!val_int || !val_bnd || comps == UINT32_MAX) {
        free(val_int);
        free(val_bnd);
        return out_of_memory();
    }
    for (v = 0; v < m->num_verts; v++) {
        if (m->vert_tag[v] & SUBD_VTAG_ISOLATED) continue;
        if (m->vert_tag[v] & SUBD_VTAG_BOUNDARY) val_bnd[subd_vertex_valence(m, v)]++;
        else val_int[subd_vertex_valence(m, v)]++;
    }
    for (k = 0; k < 3u; k++) lo[k] = hi[k] = m->pos[k];
    for (v = 1; v < m->num_verts; v++)
        for (k = 0; k < 3u; k++) {
            subd_real x = m->pos[3u * v + k];
            if (x < lo[k]) lo[k] = x;
            if (x > hi[k]) hi[k] = x;
        }

    /* Euler characteristic and genus. chi = V - E + F counts isolated vertices (each adds 1
     * to chi and is a component of its own). For the surface part (faces only, which the
     * builder guarantees is an oriented 2-manifold with boundary) with c components and b
     * boundary loops: chi_s = chi - isolated = sum_i (2 - 2 g_i - b_i), so
     *   genus = sum_i g_i = (2c - chi_s - b) / 2. */
    chi = subd_mesh_euler(m);
    chi_surf = chi - (int32_t)m->num_isolated;
    used_verts = m->num_verts - m->num_isolated;
    twice_genus = 2 * (int64_t)comps - chi_surf - (int64_t)m->num_boundary_loops;

    fprintf(f, "file: %s (%s, %lu bytes)\n", r->o.input, host_format_name(r->in.format),
            (unsigned long)r->in.file_bytes);
    fprintf(f, "arithmetic: %s\n", ARITHMETIC);
    fprintf(f, "validation: ok\n");
    fprintf(f, "vertices: %lu (%lu on faces, %lu isolated)\n", (unsigned long)m->num_verts,
            (unsigned long)used_verts, (unsigned long)m->num_isolated);
    fprintf(f, "faces: %lu\n", (unsigned long)m->num_faces);
    fprintf(f, "corners: %lu\n", (unsigned long)m->num_corners);
    fprintf(f, "edges: %lu\n", (unsigned long)m->num_edges);
    fprintf(f, "face sizes: ");
    print_hist(f, fsize, SUBD_MAX_FACE_SIZE + 1u);
    fprintf(f, "boundary edges: %lu\n", (unsigned long)m->num_boundary_edges);
    fprintf(f, "boundary loops: %lu\n", (unsigned long)m->num_boundary_loops);
    fprintf(f, "isolated vertices: %lu\n", (unsigned long)m->num_isolated);
    fprintf(f, "polylines: %lu (%lu vertices)\n", (unsigned long)m->num_lines,
            (unsigned long)m->num_line_verts);
    fprintf(f, "components: %lu (%lu with faces, %lu isolated vertices)\n",
            (unsigned long)comps + m->num_isolated, (unsigned long)comps, (unsigned long)m->num_isolated);
    fprintf(f, "euler characteristic: %ld (V - E + F; surface only: %ld)\n", (long)chi, (long)chi_surf);
    if (twice_genus >= 0 && twice_genus % 2 == 0)
        fprintf(f, "genus: %ld\n", (long)(twice_genus / 2));
    else
        fprintf(f, "genus: n/a\n");
    fprintf(f, "valence interior: ");
    print_hist(f, val_int, max_val + 1u);
    fprintf(f, "valence boundary: ");
    print_hist(f, val_bnd, max_val + 1u);
    fprintf(f, "bbox min: ");
    print_real(f, lo[0]);
    fputc(' ', f);
    print_real(f, lo[1]);
    fputc(' ', f);
    print_real(f, lo[2]);
    fprintf(f, "\nbbox max: ");
    print_real(f, hi[0]);
    fputc(' ', f);
    print_real(f, hi[1]);
    fputc(' ', f);
    print_real(f, hi[2]);
    fprintf(f, "\narena bytes: %lu\n", (unsigned long)r->in.planned);
    free(val_int);
    free(val_bnd);
    return EXIT_OK;
}

/* ------------------------------------------------------------------------------------ */
/* Output                                                                                 */

static int write_failed(const char *path)
{
    fprintf(stderr, "subd: cannot write '%s': %s\n", path, strerror(errno));
    return EXIT_OUTPUT;
}

static int write_png(tool_run *r)
{
    const subd_mesh *m = &r->out;
    render_mesh rm;
    double *pos;
    uint8_t *rgb = NULL, *png = NULL;
    uint32_t i, len = 0;
    int w = 0, h = 0, rc;

    pos = (double *)malloc(3u * (size_t)m->num_verts * sizeof *pos + 1u);
    if (!pos) return out_of_memory();
    for (i = 0; i < 3u * m->num_verts; i++) pos[i] = host_real_to_double(m->pos[i]);
    rm.num_verts = m->num_verts;
    rm.pos = pos;
    rm.num_faces = m->num_faces;
    rm.face_start = m->face_start;
    rm.corner_vert = m->corner_vert;
    rm.num_lines = m->num_lines;
    rm.line_start = m->line_start;
    rm.line_vert = m->line_vert;
    rc = render_rgb(&rm, &r->o.ropt, &rgb, &w, &h);
    free(pos);
    if (rc != 0) return out_of_memory();
    rc = png_encode_rgb(rgb, w, h, &png, &len);
    free(rgb);
    if (rc != 0) return out_of_memory();
    rc = host_write_file(r->o.output, png, len);
    free(png);
    if (rc != 0) return write_failed(r->o.output);
    r->out_bytes = len;
    r->out_width = w;
    r->out_height = h;
    return EXIT_OK;
}

/* Plain points for CNC use: "x y z" per line in the library's exact decimal form; the
 * points of each polyline in order with a blank line between polylines, or every vertex
 * when there are no polylines. */
static int write_xyz(tool_run *r)
{
    const subd_mesh *m = &r->out;
    FILE *f = fopen(r->o.output, "w");
    uint32_t l, c, nl = m->num_lines ? m->num_lines : 1u;
    long n;
    if (!f) return write_failed(r->o.output);
    for (l = 0; l < nl; l++) {
        uint32_t s = m->num_lines ? m->line_start[l] : 0u;
        uint32_t e = m->num_lines ? m->line_start[l + 1u] : m->num_verts;
        if (l) fputc('\n', f);
        for (c = s; c < e; c++) {
            uint32_t v = m->num_lines ? m->line_vert[c] : c, k;
            for (k = 0; k < 3u; k++) {
                char b[32];
                uint32_t len = subd_real_format(m->pos[3u * v + k], b);
                fwrite(b, 1, len, f);
                fputc(k < 2u ? ' ' : '\n', f);
            }
        }
    }
    n = ftell(f);
    if (ferror(f) | (fclose(f) != 0)) return write_failed(r->o.output);
    r->out_bytes = n > 0 ? (uint32_t)n : 0u;
    return EXIT_OK;
}

static int write_mesh(tool_run *r)
{
    int (*writer)(const subd_mesh *, char *, uint32_t, uint32_t *) =
        (r->o.out_format == HOST_FMT_OBJ) ? subd_obj_write : subd_off_write;
    uint32_t len = 0;
    char *buf;
    int st = r->extra.normals ? subd_obj_write_normals(&r->out, r->extra.normals, NULL, 0, &len)
                              : writer(&r->out, NULL, 0, &len);
    if (st != SUBD_OK) {
        fprintf(stderr, "subd: %s: %s\n", r->o.output, subd_status_str(st));
        return st == SUBD_ERR_TOO_BIG ? EXIT_LIMIT : EXIT_OUTPUT;
    }
    if (r->o.out_format == HOST_FMT_OFF && r->out.num_lines)
        fprintf(stderr, "subd: warning: %s: OFF has no polylines; %lu polyline(s) not written\n",
                r->o.output, (unsigned long)r->out.num_lines);
    buf = (char *)malloc((size_t)len + 1u);
    if (!buf) return out_of_memory();
    st = r->extra.normals ? subd_obj_write_normals(&r->out, r->extra.normals, buf, len, &len)
                          : writer(&r->out, buf, len, &len);
    if (st != SUBD_OK) {
        free(buf);
        fprintf(stderr, "subd: %s: %s\n", r->o.output, subd_status_str(st));
        return EXIT_OUTPUT;
    }
    st = host_write_file(r->o.output, buf, len);
    free(buf);
    if (st != 0) return write_failed(r->o.output);
    r->out_bytes = len;
    return EXIT_OK;
}

/* ------------------------------------------------------------------------------------ */
/* --stats JSON                                                                           */

static void json_string(FILE *f, const char *s)
{
    fputc('"', f);
    for (; *s; s++) {
        unsigned char c = (unsigned char)*s;
        if (c == '"' || c == '\\') fprintf(f, "\\%c", c);
        else if (c < 0x20) fprintf(f, "\\u%04x", c);
        else fputc(c, f);
    }
    fputc('"', f);
}

static void json_mesh_counts(FILE *f, const subd_mesh *m)
{
    fprintf(f, "\"vertices\":%lu,\"faces\":%lu,\"corners\":%lu,\"edges\":%lu,\"boundary_edges\":%lu,"
               "\"boundary_loops\":%lu,\"isolated\":%lu,\"polylines\":%lu",
            (unsigned long)m->num_verts, (unsigned long)m->num_faces, (unsigned long)m->num_corners,
            (unsigned long)m->num_edges, (unsigned long)m->num_boundary_edges,
            (unsigned long)m->num_boundary_loops, (unsigned long)m->num_isolated, (unsigned long)m->num_lines);
}

static void print_stats(FILE *f, const tool_run *r)
{
    fprintf(f, "{\"command\":");
    json_string(f, r->cmd->name);
    fprintf(f, ",\"scheme\":");
    if (r->cmd->scheme) json_string(f, r->cmd->scheme);
    else fprintf(f, "null");
    fprintf(f, ",\"levels\":%lu,\"arithmetic\":\"%s\",\"input\":{\"file\":",
            (unsigned long)((r->cmd->flags & CMD_LEVELS) ? r->o.levels : 0u), ARITHMETIC);
    json_string(f, r->o.input);
    fprintf(f, ",\"format\":\"%s\",\"bytes\":%lu,", host_format_name(r->in.format),
            (unsigned long)r->in.file_bytes);
    json_mesh_counts(f, &r->in.mesh);
    fprintf(f, "},\"output\":");
    if (r->o.output) {
        fprintf(f, "{\"file\":");
        json_string(f, r->o.output);
        fprintf(f, ",\"format\":\"%s\",\"bytes\":%lu,", host_format_name(r->o.out_format),
                (unsigned long)r->out_bytes);
        json_mesh_counts(f, &r->out);
        fprintf(f, "}");
    } else {
        fprintf(f, "null");
    }
    fprintf(f, ",\"arena_budget\":");
    if (r->o.has_budget) fprintf(f, "%lu", (unsigned long)r->o.budget);
    else fprintf(f, "null");
    fprintf(f, ",\"arena_planned\":%lu,\"arena_used\":%lu,\"time_ms\":%.3f", (unsigned long)r->planned,
            (unsigned long)r->used, r->lib_ns / 1e6);
    if (r->extra.json[0]) fprintf(f, ",%s", r->extra.json);
    fprintf(f, "}\n");
}

/* ------------------------------------------------------------------------------------ */
/* The common path                                                                        */

static int run_command(tool_run *r)
{
    const command *cmd = r->cmd;
    subd_diag d;
    double ns = 0.0, t0;
    int st;

    st = host_read_mesh(r->o.input, r->o.has_budget ? &r->o.budget : NULL, &r->in, &d, &ns);
    r->lib_ns += ns;
    if (st == HOST_ERR_IO) {
        fprintf(stderr, "subd: cannot read '%s': %s\n", r->o.input, strerror(errno));
        return EXIT_INPUT;
    }
    if (st == HOST_ERR_OOM) return out_of_memory();
    if (st == HOST_ERR_FORMAT) return usage_error("cannot read '%s': input must be .obj or .off", r->o.input);
    if (st != SUBD_OK) return library_error(r->o.input, st, &d, r->o.has_budget, r->o.budget);
    /* One device arena holds the input mesh and then the operation's memory above it. */
    r->planned = r->in.planned;
    r->used = r->in.arena.peak;
    r->out = r->in.mesh;
    if (r->o.tag_boundary) {
        uint32_t h;
        for (h = 0; h < r->in.mesh.num_corners; h++)
            if (r->in.mesh.twin[h] == SUBD_NONE) r->in.mesh.edge_tag[h] |= SUBD_ETAG_CREASE;
    }
    if (r->o.has_crease_angle) {
        /* cos of the angle in whole hundredths of a degree, by the library's own cos */
        int32_t hundredths = (int32_t)(r->o.crease_deg * 100.0 + 0.5);
        uint32_t n = subd_mesh_tag_crease_angle(&r->in.mesh, subd_cos_turns(hundredths, 36000));
        if (!r->o.stats) fprintf(stderr, "subd: %lu crease edge(s) tagged\n", (unsigned long)n);
    }
    if (r->o.tags && (st = apply_tag_file(r->o.tags, &r->in.mesh, r->o.stats)) != EXIT_OK) return st;

    if (cmd->run) {
        uint32_t bytes = 0, base = r->in.arena.used, need;
        subd_arena *a;
        t0 = host_now_ns();
        st = cmd->plan(&r->in.mesh, &r->o, &bytes, &d);
        r->lib_ns += host_now_ns() - t0;
        if (st != SUBD_OK) return library_error(r->o.input, st, &d, r->o.has_budget, r->o.budget);
        need = (bytes > UINT32_MAX - base) ? UINT32_MAX : base + bytes;
        if (need > r->planned) r->planned = need;
        if (r->o.has_budget) {
            if (r->planned > r->o.budget) return arena_too_small(r->planned, r->o.budget);
            a = &r->in.arena;
        } else {
            r->work_mem = host_arena_alloc(&r->work, bytes);
            if (!r->work_mem) return out_of_memory();
            a = &r->work;
        }
        t0 = host_now_ns();
        st = cmd->run(a, &r->in.mesh, &r->o, &r->out, &r->extra, &d);
        r->lib_ns += host_now_ns() - t0;
        if (st != SUBD_OK) return library_error(r->o.input, st, &d, r->o.has_budget, r->o.budget);
        if (r->o.has_budget) {
            r->used = r->in.arena.peak;
        } else if (base + r->work.peak > r->used) {
            r->used = base + r->work.peak;
        }
    }

    if (r->o.output) {
        st = (r->o.out_format == HOST_FMT_PNG) ? write_png(r)
             : (r->o.out_format == HOST_FMT_XYZ) ? write_xyz(r) : write_mesh(r);
        if (st != EXIT_OK) return st;
    }
    if (cmd->report) {
        st = cmd->report(r->o.stats ? stderr : stdout, r);
        if (st != EXIT_OK) return st;
    }
    if (r->o.stats) print_stats(stdout, r);
    return EXIT_OK;
}

int main(int argc, char **argv)
{
    const command *cmd;
    tool_run r;
    int rc;

    if (argc < 2) {
        fprintf(stderr, "subd: missing command\n");
        usage_short(stderr);
        return EXIT_USAGE;
    }
    if (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0 || strcmp(argv[1], "help") == 0) {
        usage(stdout);
        return EXIT_OK;
    }
    if (strcmp(argv[1], "--version") == 0) {
        printf("subd %s (tinysubd, %s)\n", SUBD_VERSION, ARITHMETIC);
        return EXIT_OK;
    }
    cmd = find_command(argv[1]);
    if (!cmd) return usage_error("unknown command '%s'", argv[1]);
    memset(&r, 0, sizeof r);
    r.cmd = cmd;
    rc = parse_args(cmd, argc, argv, &r.o);
    if (rc != EXIT_OK) return rc;
    rc = run_command(&r);
    host_mesh_free(&r.in);
    free(r.work_mem);
    free(r.extra.host_mem);
    if (fflush(stdout) != 0 && rc == EXIT_OK) {
        fprintf(stderr, "subd: cannot write standard output: %s\n", strerror(errno));
        rc = EXIT_OUTPUT;
    }
    return rc;
}
