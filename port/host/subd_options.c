/* SPDX-License-Identifier: MIT */
/* subd tool: the option table. One row per option gives its name, its value placeholder, the
 * scheme-option bit it records, the function that checks and stores its value, and its --help
 * text, so parsing and the help cannot disagree (gltfpack keeps its command line the same
 * way). Checks that need the whole command line (the output format, a command's required
 * options) run after the table, in tool_parse_args.
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include "subd_tool.h"
#include "host_real.h"

/* Option values */

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

/* alpha as an exact fraction of a turn: the library's one grammar for alpha values
 * (subd_tags.h: "N", "N/D" or "Xdeg", at most 4 decimals, no exponent), as in a tag file. */
static int parse_alpha(const char *s, int32_t *num, int32_t *den)
{
    size_t len = strlen(s);
    if (len > UINT32_MAX) return -1;
    return subd_tags_parse_alpha(s, (uint32_t)len, num, den) == SUBD_OK ? 0 : -1;
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

/* ------------------------------------------------------------------------------------ */
/* The table                                                                             */

/* What an option's set function sees: the command, the options so far, the option's name
 * as given (without =VALUE) and its value (NULL for a flag). */
typedef struct opt_ctx {
    const command *cmd;
    tool_opts *o;
    const char *name;
    const char *val;
} opt_ctx;

/* tool_option.flags */
#define OPTF_HELP 0x1u  /* -h/--help: print the help and exit, whatever follows            */
#define OPTF_FIRST 0x2u /* only as the first argument (--version), unknown after a command */

typedef struct tool_option {
    const char *name;  /* "--tags", "-o"                                                   */
    const char *alias; /* another name ("-h" for --help), or NULL                          */
    const char *meta;  /* placeholder of the value in --help ("FILE"); NULL: a flag         */
    unsigned flags;    /* OPTF_*                                                            */
    unsigned given;    /* OPT_* bit recorded in tool_opts.given once the option is stored   */
    int (*set)(const opt_ctx *c); /* checks and stores; EXIT_OK or EXIT_USAGE (message out) */
    /* --help text; a printf format given (2 * SUBD_MAX_LEVELS, SUBD_MAX_LEVELS); each '\n'
     * continues under the text column */
    const char *help;
} tool_option;

static int set_none(const opt_ctx *c)
{
    (void)c;
    return EXIT_OK;
}

/* The flags (options without a value). */
static int set_flag(const opt_ctx *c)
{
    tool_opts *o = c->o;
    if (strcmp(c->name, "--stats") == 0) o->stats = 1;
    else if (strcmp(c->name, "--normals") == 0) o->normals = 1;
    else if (strcmp(c->name, "--no-smooth") == 0) o->no_smooth = 1;
    else if (strcmp(c->name, "--tag-boundary") == 0) o->tag_boundary = 1;
    else if (strcmp(c->name, "--stream") == 0) o->stream = 1;
    else if (strcmp(c->name, "--limit") == 0) o->limit = 1;
    else if (strcmp(c->name, "--quiet") == 0 || strcmp(c->name, "-q") == 0) o->quiet = 1;
    else if (strcmp(c->name, "--no-labels") == 0) {
        o->no_labels = 1;
        o->render_opt_given = 1;
    } else { /* --no-edges, --edges */
        o->ropt.edges = strcmp(c->name, "--edges") == 0;
        o->render_opt_given = 1;
    }
    return EXIT_OK;
}

static int set_output(const opt_ctx *c)
{
    if (c->o->output) return tool_usage_error("more than one output file ('%s')", c->val);
    if (!*c->val) return tool_usage_error("empty output file name");
    c->o->output = c->val;
    return EXIT_OK;
}

static int set_levels(const opt_ctx *c)
{
    const command *cmd = c->cmd;
    if (!(cmd->flags & CMD_LEVELS)) return tool_usage_error("option -l does not apply to '%s'", cmd->name);
    if (parse_u32(c->val, cmd->max_levels, &c->o->levels))
        return tool_usage_error("bad level count '%s' (expected 0..%lu)", c->val, (unsigned long)cmd->max_levels);
    c->o->has_levels = 1;
    return EXIT_OK;
}

static int set_arena(const opt_ctx *c)
{
    if (parse_bytes(c->val, &c->o->budget))
        return tool_usage_error("bad arena size '%s' (bytes, optional k or m suffix, < 4 GiB)", c->val);
    c->o->has_budget = 1;
    return EXIT_OK;
}

static int set_boundary(const opt_ctx *c)
{
    c->o->boundary_name = c->val; /* checked in tool_parse_args, once the command is known */
    return EXIT_OK;
}

static int set_crease_angle(const opt_ctx *c)
{
    if (parse_double(c->val, 0.0, 180.0, &c->o->crease_deg))
        return tool_usage_error("bad crease angle '%s' (degrees, 0..180)", c->val);
    c->o->has_crease_angle = 1;
    return EXIT_OK;
}

static int set_with_input(const opt_ctx *c)
{
    if (c->o->with_input) return tool_usage_error("more than one --with-input file ('%s')", c->val);
    if (!host_format_readable(host_format_of(c->val)))
        return tool_usage_error("cannot read '%s': --with-input must be " HOST_READABLE, c->val);
    c->o->with_input = c->val;
    c->o->render_opt_given = 1;
    return EXIT_OK;
}

static int set_tags(const opt_ctx *c)
{
    if (c->o->tags) return tool_usage_error("more than one tag file ('%s')", c->val);
    c->o->tags = c->val;
    return EXIT_OK;
}

static int set_tol(const opt_ctx *c)
{
    if (parse_double(c->val, 0.0, 1e30, &c->o->tol) || !(c->o->tol > 0.0))
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
    if (parse_u32(c->val, 1000000u, &c->o->max_iter) || c->o->max_iter == 0)
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

static int set_order(const opt_ctx *c)
{
    if (parse_u32(c->val, SUBD_ALPHA_MAX_ORDER, &c->o->alpha.order) || c->o->alpha.order < 2)
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
    if (parse_double(c->val, -1e4, 1e4, &sv)) return tool_usage_error("bad stiffness '%s'", c->val);
    if (sv <= -0.5)
        return tool_usage_error("stiffness %s <= -1/2: the subdivision diverges (paper, theorem 1: convergent for s > -1/2)",
                                c->val);
    c->o->alpha.stiffness = host_real_from_double(sv);
    return EXIT_OK;
}

/* --feed F: the G-code feed rate of alpha --stream. */
static int set_feed(const opt_ctx *c)
{
    if (parse_double(c->val, 0.0, 1e9, &c->o->feed) || !(c->o->feed > 0.0))
        return tool_usage_error("bad feed rate '%s' (a positive number, units per minute)", c->val);
    return EXIT_OK;
}

/* --point, --plane, --ramp and --chord: the adaptation mode, one per command line. */
static int set_adapt_mode(const opt_ctx *c)
{
    tool_opts *o = c->o;
    const char *val = c->val;
    if (o->adapt_mode != SUBD_SR48_ADAPT_UNIFORM)
        return tool_usage_error("give one adaptation mode (--point, --ramp, --plane or --chord)");
    if (strcmp(c->name, "--point") == 0) {
        if (parse_doubles(val, 3, o->adapt_val)) return tool_usage_error("bad point '%s' (expected X,Y,Z)", val);
        o->adapt_mode = SUBD_SR48_ADAPT_POINT;
    } else if (strcmp(c->name, "--plane") == 0) {
        if (parse_doubles(val, 6, o->adapt_val) ||
            (o->adapt_val[3] == 0.0 && o->adapt_val[4] == 0.0 && o->adapt_val[5] == 0.0))
            return tool_usage_error("bad plane '%s' (expected X,Y,Z,NX,NY,NZ with a nonzero normal)", val);
        o->adapt_mode = SUBD_SR48_ADAPT_PLANE;
    } else if (strcmp(c->name, "--ramp") == 0) {
        if (strlen(val) != 1 || val[0] < 'x' || val[0] > 'z')
            return tool_usage_error("bad ramp axis '%s' (expected x, y or z)", val);
        o->adapt_axis = (uint32_t)(val[0] - 'x');
        o->adapt_mode = SUBD_SR48_ADAPT_RAMP;
    } else { /* --chord */
        if (parse_double(val, 0.0, 1e30, &o->adapt_val[0]) || !(o->adapt_val[0] > 0.0))
            return tool_usage_error("bad chordal tolerance '%s' (a positive number, input units)", val);
        o->adapt_mode = SUBD_SR48_ADAPT_CHORD;
    }
    return EXIT_OK;
}

static int set_radius(const opt_ctx *c)
{
    if (parse_double(c->val, 0.0, 1e30, &c->o->radius) || !(c->o->radius > 0.0))
        return tool_usage_error("bad radius '%s' (a positive number, input units)", c->val);
    return EXIT_OK;
}

static int set_size(const opt_ctx *c)
{
    if (parse_size(c->val, &c->o->ropt.width, &c->o->ropt.height))
        return tool_usage_error("bad picture size '%s' (expected WxH, 1..8192 each)", c->val);
    c->o->render_opt_given = 1;
    return EXIT_OK;
}

static int set_yaw(const opt_ctx *c)
{
    if (parse_double(c->val, -1e6, 1e6, &c->o->ropt.yaw_deg)) return tool_usage_error("bad yaw angle '%s' (degrees)", c->val);
    c->o->render_opt_given = 1;
    return EXIT_OK;
}

static int set_pitch(const opt_ctx *c)
{
    if (parse_double(c->val, -90.0, 90.0, &c->o->ropt.pitch_deg))
        return tool_usage_error("bad pitch angle '%s' (degrees, -90..90)", c->val);
    c->o->render_opt_given = 1;
    return EXIT_OK;
}

/* In --help order. */
static const tool_option options[] = {
    {"-o", NULL, "FILE", 0, 0, set_output, "output file"},
    {"-l", NULL, "N", 0, 0, set_levels,
     "subdivision levels (scheme commands; binary steps for quasi48,\n"
     "semireg48 and adapt, up to %d; other schemes up to %d)"},
    {"--stats", NULL, NULL, 0, 0, set_flag,
     "print exactly one JSON object on stdout (keys: command, scheme,\n"
     "levels, arithmetic, input, output, arena_budget, arena_planned,\n"
     "arena_used, time_ms = milliseconds in library calls; --stream adds\n"
     "stream, limit, triangles, checksum, stream_arena = the stream's own\n"
     "arena, its plan, the mesh not counted); the human report of 'info'\n"
     "then goes to stderr"},
    {"--arena", NULL, "BYTES", 0, 0, set_arena,
     "simulate a device arena of BYTES bytes (suffix k = 1024,\n"
     "m = 1048576): exit 3 when the command needs more"},
    {"--boundary", NULL, "R", 0, 0, set_boundary,
     "loop/limit/pia: boundary and crease rule, paper (the paper's\n"
     "section 4, default) or bspline (midpoints, as OpenSubdiv and\n"
     "CGAL); quasi48: fixed (default), smooth or normal (along the\n"
     "surface normal, section 4.3) boundary vertices"},
    {"--no-smooth", NULL, NULL, 0, OPT_NO_SMOOTH, set_flag,
     "(quasi48, semireg48, adapt) refinement only, no smoothing"},
    {"--tag-boundary", NULL, NULL, 0, OPT_Q48, set_flag,
     "(quasi48) tag boundary edges as creases (they stay put)"},
    {"--crease-angle", NULL, "D", 0, OPT_CREASE, set_crease_angle,
     "tag edges whose faces meet at more than D degrees as creases"},
    {"--tags", NULL, "FILE", 0, OPT_TAGS, set_tags,
     "(loop, limit, pia, quasi48) tags from a text file, one per line:\n"
     "'crease I J' (the edge between vertices I and J), 'corner I',\n"
     "'fixed I'; vertex numbers 1-based as in OBJ, '#' comments;\n"
     "(alpha) 'alpha V A' (curves, odd --order) and 'falpha F A' (faces\n"
     "in file order, even --order): A as for --alpha"},
    {"--normals", NULL, NULL, 0, OPT_NORMALS, set_flag,
     "(limit) also write unit limit normals as OBJ vn records"},
    {"--stream", NULL, NULL, 0, OPT_STREAM, set_flag,
     "(loop, semireg48) stream the triangles one at a time\n"
     "(subd_loop_stream, subd_sr48_stream), in an\n"
     "arena set by the level and largest valence only: .stl is written as\n"
     "they come (memory independent of the output; may be a pipe);\n"
     ".obj/.off are gathered on the host by vertex id; with --stats, -o\n"
     "may be left out (a counting sink, for timing)"},
    {"--limit", NULL, NULL, 0, OPT_STREAM, set_flag,
     "(loop --stream) limit positions and unit limit normals: OBJ vn\n"
     "records; STL facets keep the unit normal of the triangle"},
    {"--tol", NULL, "T", 0, OPT_TOL, set_tol,
     "(pia) stop when every limit point is within T of its input vertex"},
    {"--max-iter", NULL, "K", 0, OPT_MAX_ITER, set_max_iter, "(pia) at most K iterations (default 100)"},
    {"--method", NULL, "M", 0, OPT_METHOD, set_method,
     "(pia) paper (V += P - LV) or fast (default; see src/pia.c)"},
    {"--order", NULL, "K", 0, OPT_ALPHA, set_order,
     "(alpha) operator order S_K, 2..8 (S_3: the paper's Catmull-Clark variant)"},
    {"--kernel", NULL, "K", 0, OPT_ALPHA, set_kernel,
     "(alpha) bspline (default), cos (C-curves: circles), poly, cosh"},
    {"--alpha", NULL, "A", 0, OPT_ALPHA, set_alpha,
     "(alpha) angle as a fraction of a turn N/D (1/8) or degrees (45deg)"},
    {"--stiffness", NULL, "S", 0, OPT_ALPHA, set_stiffness,
     "(alpha) s = f(0), default 1; s <= -1/2 diverges (rejected)"},
    {"--point", NULL, "X,Y,Z", 0, OPT_ADAPT, set_adapt_mode,
     "(adapt) finest at this point, one level coarser per radius away"},
    {"--radius", NULL, "R", 0, OPT_ADAPT, set_radius,
     "(adapt --point) distance per level (default: bounding-box\n"
     "diagonal / (2 MAX))"},
    {"--ramp", NULL, "A", 0, OPT_ADAPT, set_adapt_mode,
     "(adapt) level rising along axis x, y or z from 0 to MAX"},
    {"--plane", NULL, "P,N", 0, OPT_ADAPT, set_adapt_mode,
     "(adapt) MAX on the side of the plane through P the normal N\n"
     "points to, level 0 elsewhere (X,Y,Z,NX,NY,NZ)"},
    {"--chord", NULL, "EPS", 0, OPT_ADAPT, set_adapt_mode,
     "(adapt) refine only where a triangle is more than EPS from the\n"
     "level-MAX surface (chordal tolerance, input units); (alpha\n"
     "--stream) only the points that keep every level-N point within EPS;\n"
     "(loop --stream --limit) each face at the level that keeps every\n"
     "level-L limit point within EPS, watertight (subd_loop_adapt_stream)"},
    {"--feed", NULL, "F", 0, OPT_ALPHA, set_feed, "(alpha --stream, G-code output) feed rate F on the first G1"},
    {"--size", NULL, "WxH", 0, 0, set_size, "picture size in pixels (default 800x600, up to 8192x8192)"},
    {"--yaw", NULL, "DEG", 0, 0, set_yaw, "view rotation about the up axis (default 30)"},
    {"--pitch", NULL, "DEG", 0, 0, set_pitch, "view elevation, -90..90 (default 20)"},
    {"--no-edges", NULL, NULL, 0, 0, set_flag, "do not draw polygon edges"},
    {"--edges", NULL, NULL, 0, 0, set_flag,
     "draw polygon edges even when the mesh is dense (by default they are\n"
     "left out when the mean edge is under 6 pixels: a black silhouette)"},
    {"--with-input", NULL, "FILE", 0, 0, set_with_input,
     "draw FILE (.obj/.off, e.g. the INPUT of a scheme command: its control\n"
     "net or polylines) over the picture in orange, dashed where hidden,\n"
     "framed together with the result, and name it in the caption"},
    {"--no-labels", NULL, NULL, 0, 0, set_flag, "no captions in the picture (what is drawn, its counts)"},
    {"--quiet", "-q", NULL, 0, 0, set_flag,
     "no progress line and no notes on stderr (errors and warnings stay);\n"
     "progress is shown only when stderr is a terminal and the command\n"
     "runs longer than about a second"},
    {"--help", "-h", NULL, OPTF_HELP, 0, set_none, "print this text"},
    {"--version", NULL, NULL, OPTF_FIRST, 0, set_none, "print the version and the arithmetic of this build"},
};
#define NUM_OPTIONS (sizeof options / sizeof options[0])

static const tool_option *find_option(const char *name)
{
    size_t i;
    for (i = 0; i < NUM_OPTIONS; i++)
        if (strcmp(options[i].name, name) == 0 || (options[i].alias && strcmp(options[i].alias, name) == 0))
            return &options[i];
    return NULL;
}

/* ------------------------------------------------------------------------------------ */
/* Parsing                                                                               */

int tool_parse_args(const command *cmd, int argc, char **argv, tool_opts *o)
{
    int i, no_more_options = 0;
    memset(o, 0, sizeof *o);
    render_opts_default(&o->ropt);
    subd_alpha_opts_default(&o->alpha);
    for (i = 2; i < argc; i++) {
        const char *a = argv[i], *val = NULL, *eq;
        const tool_option *t;
        opt_ctx c;
        char name[32];
        int rc;
        if (no_more_options || a[0] != '-' || a[1] == '\0') {
            if (o->input) return tool_usage_error("more than one input file ('%s')", a);
            o->input = a;
            continue;
        }
        if (strcmp(a, "--") == 0) { no_more_options = 1; continue; }
        /* --name=value */
        eq = (a[1] == '-') ? strchr(a, '=') : NULL;
        if (eq) {
            size_t n = (size_t)(eq - a);
            if (n >= sizeof name) return tool_usage_error("unknown option '%s'", a);
            memcpy(name, a, n);
            name[n] = '\0';
            val = eq + 1;
        } else {
            size_t n = strlen(a);
            if (n >= sizeof name) return tool_usage_error("unknown option '%s'", a);
            memcpy(name, a, n + 1u);
        }
        t = find_option(name);
        if (t && (t->flags & OPTF_HELP)) {
            tool_usage(stdout);
            exit(EXIT_OK);
        }
        if (!t || (t->flags & OPTF_FIRST)) return tool_usage_error("unknown option '%s'", a);
        if (!t->meta && val) return tool_usage_error("option '%s' takes no value", name);
        if (t->meta && !val) {
            if (i + 1 >= argc) return tool_usage_error("option '%s' needs a value", name);
            val = argv[++i];
        }
        /* named here, where the option is known (several share one bit); --stream and
         * --limit get their own messages below */
        if (t->given & ~cmd->options & ~OPT_STREAM &&
            !(strcmp(name, "--chord") == 0 && (strcmp(cmd->name, "alpha") == 0 || strcmp(cmd->name, "loop") == 0)))
            /* alpha --stream --chord; loop --stream --limit --chord */
            return tool_usage_error("option '%s' is not accepted by '%s' (see subd --help)", name, cmd->name);
        c.cmd = cmd;
        c.o = o;
        c.name = name;
        c.val = val;
        if ((rc = t->set(&c)) != EXIT_OK) return rc;
        o->given |= t->given;
    }
    if (!o->input) return tool_usage_error("'%s' needs an input file", cmd->name);
    /* --stream and --limit: before the output checks, which depend on them */
    if (o->stream && !(cmd->options & OPT_STREAM))
        return tool_usage_error("--stream applies to 'loop', 'semireg48', 'adapt' and 'alpha' only (not '%s')",
                                cmd->name);
    o->sr48_stream = o->stream && (strcmp(cmd->name, "semireg48") == 0 || strcmp(cmd->name, "adapt") == 0);
    if (o->limit && o->sr48_stream) return tool_usage_error("--limit applies to 'loop --stream' only");
    if (strcmp(cmd->name, "alpha") == 0) { /* alpha --stream: --chord, --feed; .xyz or G-code */
        if (o->limit) return tool_usage_error("--limit applies to 'loop --stream' only");
        if (!o->stream && o->adapt_mode == SUBD_SR48_ADAPT_CHORD) return tool_usage_error("alpha: --chord needs --stream");
        if (!o->stream && o->feed > 0.0) return tool_usage_error("alpha: --feed needs --stream (and G-code output)");
        if (o->stream && o->output && host_format_of(o->output) != HOST_FMT_XYZ &&
            host_format_of(o->output) != HOST_FMT_GCODE)
            return tool_usage_error("cannot write '%s': alpha --stream writes .xyz, .gcode or .nc", o->output);
        if (o->feed > 0.0 && o->output && host_format_of(o->output) != HOST_FMT_GCODE)
            return tool_usage_error("--feed goes with G-code output (.gcode, .nc)");
    }
    if (strcmp(cmd->name, "loop") == 0 && o->adapt_mode == SUBD_SR48_ADAPT_CHORD && !(o->stream && o->limit))
        return tool_usage_error("loop: --chord needs --stream --limit (the adaptive limit stream)");
    if (o->limit && !o->stream)
        return tool_usage_error("--limit needs --stream (for the limit of a mesh's own vertices: 'subd limit')");
    if (!host_format_readable(host_format_of(o->input)))
        return tool_usage_error("cannot read '%s': input must be " HOST_READABLE, o->input);
    if (o->output) {
        if (cmd->flags & CMD_OUTPUT_NONE) return tool_usage_error("'%s' writes no output file (no -o)", cmd->name);
        o->out_format = host_format_of(o->output);
        if (o->out_format == HOST_FMT_UNKNOWN || o->out_format == HOST_FMT_PLY)
            return tool_usage_error("cannot write '%s': output must be .obj, .off, .png, .xyz, .stl, .gcode or .nc", o->output);
        if ((cmd->flags & CMD_PNG_ONLY) && o->out_format != HOST_FMT_PNG)
            return tool_usage_error("'%s' writes a .png picture", cmd->name);
        if (o->out_format == HOST_FMT_STL && !o->stream)
            return tool_usage_error("cannot write '%s': .stl is written by --stream only", o->output);
        if (o->out_format == HOST_FMT_GCODE && !(o->stream && strcmp(cmd->name, "alpha") == 0))
            return tool_usage_error("cannot write '%s': G-code is written by 'alpha --stream' only", o->output);
        if (o->stream && strcmp(cmd->name, "alpha") != 0 &&
            (o->out_format == HOST_FMT_PNG || o->out_format == HOST_FMT_XYZ || o->out_format == HOST_FMT_GCODE))
            return tool_usage_error("cannot write '%s': --stream writes .stl, .obj or .off", o->output);
    } else if (o->stream && o->stats) {
        /* loop --stream --stats without -o: the counting sink */
    } else if (cmd->flags & CMD_OUTPUT_REQUIRED) {
        return tool_usage_error("'%s' needs an output file (-o OUTPUT%s)", cmd->name,
                                o->stream ? "; with --stats, --stream may leave it out" : "");
    }
    if (o->render_opt_given && o->out_format != HOST_FMT_PNG)
        return tool_usage_error("picture options (--size, --yaw, --pitch, --no-edges, --edges, --with-input, "
                                "--no-labels) need a .png output");
    if (o->boundary_name) {
        const char *b = o->boundary_name;
        if (cmd->options & OPT_BOUNDARY) {
            if (strcmp(b, "paper") == 0) o->boundary = SUBD_LOOP_BOUNDARY_PAPER;
            else if (strcmp(b, "bspline") == 0) o->boundary = SUBD_LOOP_BOUNDARY_BSPLINE;
            else return tool_usage_error("bad boundary rule '%s' for '%s' (expected paper or bspline)", b, cmd->name);
        } else if (cmd->options & OPT_Q48) {
            if (strcmp(b, "fixed") == 0) o->q48_boundary = SUBD_QUASI48_BOUNDARY_FIXED;
            else if (strcmp(b, "smooth") == 0) o->q48_boundary = SUBD_QUASI48_BOUNDARY_SMOOTH;
            else if (strcmp(b, "normal") == 0) o->q48_boundary = SUBD_QUASI48_BOUNDARY_NORMAL;
            else return tool_usage_error("bad boundary mode '%s' for '%s' (expected fixed, smooth or normal)", b, cmd->name);
        } else {
            return tool_usage_error("option --boundary does not apply to '%s'", cmd->name);
        }
    }
    if ((cmd->options & OPT_TOL) && !(o->given & OPT_TOL)) return tool_usage_error("'%s' needs --tol T", cmd->name);
    if (o->normals && o->out_format != HOST_FMT_OBJ) return tool_usage_error("--normals needs an .obj output");
    if (!(o->given & OPT_MAX_ITER)) o->max_iter = 100;
    if (!(o->given & OPT_METHOD)) o->method = SUBD_PIA_FAST;
    if (!o->has_levels) o->levels = cmd->default_levels;
    o->alpha.levels = o->levels;
    if ((cmd->flags & CMD_LEVELS) && !(cmd->flags & CMD_LEVEL0) && cmd->run && o->levels == 0)
        return tool_usage_error("'%s' needs at least one level (-l 1..%lu)", cmd->name, (unsigned long)cmd->max_levels);
    if ((cmd->options & OPT_ADAPT) && o->adapt_mode == SUBD_SR48_ADAPT_UNIFORM)
        return tool_usage_error("'%s' needs an adaptation mode (--point, --ramp, --plane or --chord)", cmd->name);
    if (o->radius > 0.0 && o->adapt_mode != SUBD_SR48_ADAPT_POINT) return tool_usage_error("--radius goes with --point");
    return EXIT_OK;
}

/* ------------------------------------------------------------------------------------ */
/* Usage and --help                                                                      */

/* After a usage error: the synopsis and where the rest is, not the whole help (the
 * specific message above it stays visible). */
void tool_usage_short(FILE *f)
{
    fprintf(f, "usage: subd COMMAND [options] INPUT [-o OUTPUT]\n"
               "run 'subd --help' for the commands, options and exit codes\n");
}

/* Prints text; each '\n' in it starts a new line indented by `indent` spaces. */
static void print_continued(FILE *f, const char *text, int indent)
{
    for (; *text; text++) {
        if (*text == '\n') fprintf(f, "\n%*s", indent, "");
        else fputc(*text, f);
    }
    fputc('\n', f);
}

/* The help is generated from the command table and the option table. */
void tool_usage(FILE *f)
{
    size_t i;
    int w = 0;
    for (i = 0; i < tool_num_commands; i++)
        if ((int)strlen(tool_commands[i].synopsis) > w) w = (int)strlen(tool_commands[i].synopsis);
    fprintf(f, "usage: subd COMMAND [options] INPUT [-o OUTPUT]\n"
               "       subd help | --help | --version\n\n"
               "tinysubd %s host tool, %s build (%s).\n\ncommands:\n",
            SUBD_VERSION, ARITHMETIC, SUBD_FIXED ? "Q16.16 fixed point" : "IEEE single precision");
    for (i = 0; i < tool_num_commands; i++) {
        fprintf(f, "  %-8s %-*s  ", tool_commands[i].name, w, tool_commands[i].synopsis);
        print_continued(f, tool_commands[i].summary, 2 + 8 + 1 + w + 2);
    }
    fprintf(f, "\nformats, by extension (any case): .obj and .off are read and written;\n"
               ".png is written (a rendering of the result); .xyz is written as plain 'x y z'\n"
               "lines, polylines separated by a blank line (for CNC use); .stl (binary STL,\n"
               "one facet per triangle with its unit normal) is written by loop --stream;\n"
               ".stl (binary or ASCII, corners welded by equal coordinates) and .ply (ASCII or\n"
               "binary little-endian) are read.\n"
               "\noptions:\n");
    for (i = 0; i < NUM_OPTIONS; i++) {
        const tool_option *t = &options[i];
        char col[32], text[512];
        if (t->alias) snprintf(col, sizeof col, "%s, %s", t->alias, t->name);
        else snprintf(col, sizeof col, "%s%s%s", t->name, t->meta ? " " : "", t->meta ? t->meta : "");
        snprintf(text, sizeof text, t->help, 2 * SUBD_MAX_LEVELS, SUBD_MAX_LEVELS);
        fprintf(f, "  %-17s ", col);
        print_continued(f, text, 2 + 17 + 1);
    }
    fprintf(f, "Long options also take the form --name=VALUE. Picture options need a .png output.\n"
               "\nexit status:\n"
               "  0  success\n"
               "  1  usage error (unknown command or option, missing or bad argument)\n"
               "  2  bad input: INPUT unreadable, or 'FILE:LINE: reason' on stderr\n"
               "     (elements named in parentheses are 0-based, as in subd_diag)\n"
               "  3  resource limit: arena too small (says how many bytes are needed),\n"
               "     counts too large for 32-bit sizes, or host out of memory\n"
               "  4  OUTPUT cannot be written\n"
               "  5  pia: --tol not reached within --max-iter (OUTPUT is written; the\n"
               "     error reached is on stderr)\n"
               "With --stats a failed run still prints one JSON object on stdout:\n"
               "{\"command\", \"status\":\"error\", \"exit\", \"message\"}.\n"
               "Inputs must be regular files of at most 2 GiB (FIFOs and devices are refused).\n");
}

int tool_usage_error(const char *fmt, ...)
{
    va_list ap;
    char msg[512];
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    fprintf(stderr, "subd: %s\n", msg);
    tool_error_record("%s", msg);
    tool_usage_short(stderr);
    return EXIT_USAGE;
}
