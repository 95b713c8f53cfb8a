/* SPDX-License-Identifier: MIT */
/* subd tool: the shared options and the parser. One row per option (subd_tool.h:
 * tool_option) gives its name, its value placeholder, the scheme-option bit it records, the
 * function that checks and stores its value, and its --help text, so parsing and the help
 * cannot disagree (gltfpack keeps its command line the same way). The options shared by
 * several commands are the table here; an option only one scheme reads is a row of that
 * scheme's module (command.opts). Checks that need the whole command line (the output
 * format, a command's required options) run after the rows, in tool_parse_args, and in the
 * command's check and finish functions. Nothing here names a scheme.
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include "subd_tool.h"
#include "host_real.h"

/* Option values */


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
    if (tool_parse_u32(buf, 8192u, &a) || tool_parse_u32(x + 1, 8192u, &b) || a == 0 || b == 0) return -1;
    *w = (int)a;
    *h = (int)b;
    return 0;
}

/* ------------------------------------------------------------------------------------ */
/* The table                                                                             */

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
    else if (strcmp(c->name, "--no-smooth") == 0) o->no_smooth = 1;
    else if (strcmp(c->name, "--stream") == 0) o->stream = 1;
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
    if (tool_parse_u32(c->val, cmd->max_levels, &c->o->levels))
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
    if (tool_parse_double(c->val, 0.0, 180.0, &c->o->crease_deg))
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

/* --chord EPS: a chordal tolerance (sr48's cut, alpha --stream, loop --stream --limit). */
static int set_chord(const opt_ctx *c)
{
    tool_opts *o = c->o;
    if (o->mode_given)
        return tool_usage_error("give one adaptation mode (--point, --ramp, --plane or --chord)");
    if (tool_parse_double(c->val, 0.0, 1e30, &o->chord) || !(o->chord > 0.0))
        return tool_usage_error("bad chordal tolerance '%s' (a positive number, input units)", c->val);
    o->has_chord = 1;
    o->mode_given = 1;
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
    if (tool_parse_double(c->val, -1e6, 1e6, &c->o->ropt.yaw_deg)) return tool_usage_error("bad yaw angle '%s' (degrees)", c->val);
    c->o->render_opt_given = 1;
    return EXIT_OK;
}

static int set_pitch(const opt_ctx *c)
{
    if (tool_parse_double(c->val, -90.0, 90.0, &c->o->ropt.pitch_deg))
        return tool_usage_error("bad pitch angle '%s' (degrees, -90..90)", c->val);
    c->o->render_opt_given = 1;
    return EXIT_OK;
}

/* In --help order: these rows, then the rows of the scheme modules (command.opts, in the
 * command table's order), then options_tail. */
static const tool_option options[] = {
    {"-o", NULL, "FILE", 0, 0, set_output, "output file"},
    {"-l", NULL, "N", 0, 0, set_levels,
     "subdivision levels (scheme commands; binary steps for quasi48\n"
     "and sr48, up to %d; other schemes up to %d)"},
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
     "(quasi48, sr48) refinement only, no smoothing"},
    {"--crease-angle", NULL, "D", 0, OPT_CREASE, set_crease_angle,
     "tag edges whose faces meet at more than D degrees as creases"},
    {"--tags", NULL, "FILE", 0, OPT_TAGS, set_tags,
     "(loop, limit, pia, quasi48) tags from a text file, one per line:\n"
     "'crease I J' (the edge between vertices I and J), 'corner I',\n"
     "'fixed I'; vertex numbers 1-based as in OBJ, '#' comments;\n"
     "(alpha) 'alpha V A' (curves, odd --order) and 'falpha F A' (faces\n"
     "in file order, even --order): A as for --alpha"},
    {"--stream", NULL, NULL, 0, OPT_STREAM, set_flag,
     "(loop, sr48) stream the triangles one at a time\n"
     "(subd_loop_stream, subd_sr48_stream), in an\n"
     "arena set by the level and largest valence only: .stl is written as\n"
     "they come (memory independent of the output; may be a pipe);\n"
     ".obj/.off are gathered on the host by vertex id; with --stats, -o\n"
     "may be left out (a counting sink, for timing); (alpha) the points\n"
     "of curves, to .xyz or G-code"},
    {"--chord", NULL, "EPS", 0, OPT_CHORD, set_chord,
     "(sr48) refine only where a triangle is more than EPS from the\n"
     "level-N surface (chordal tolerance, input units); (alpha\n"
     "--stream) only the points that keep every level-N point within EPS;\n"
     "(loop --stream --limit) each face at the level that keeps every\n"
     "level-L limit point within EPS, watertight (subd_loop_adapt_stream)"},
};
#define NUM_OPTIONS (sizeof options / sizeof options[0])

static const tool_option options_tail[] = {
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
#define NUM_OPTIONS_TAIL (sizeof options_tail / sizeof options_tail[0])

static int option_is(const tool_option *t, const char *name)
{
    return strcmp(t->name, name) == 0 || (t->alias && strcmp(t->alias, name) == 0);
}

/* Whether a command before tool_commands[i] has an option of this name (deprecated
 * spellings share their command's rows): --help lists each option once. */
static int option_listed_before(size_t i, const char *name)
{
    size_t k, j;
    for (k = 0; k < i; k++)
        for (j = 0; j < tool_commands[k]->num_opts; j++)
            if (option_is(&tool_commands[k]->opts[j], name)) return 1;
    return 0;
}

/* The row of `name`: a shared option, or one a scheme module owns (any command's, so that
 * another command can say it does not accept it). */
static const tool_option *find_option(const char *name)
{
    size_t i, j;
    for (i = 0; i < NUM_OPTIONS; i++)
        if (option_is(&options[i], name)) return &options[i];
    for (i = 0; tool_commands[i]; i++)
        for (j = 0; j < tool_commands[i]->num_opts; j++)
            if (option_is(&tool_commands[i]->opts[j], name)) return &tool_commands[i]->opts[j];
    for (i = 0; i < NUM_OPTIONS_TAIL; i++)
        if (option_is(&options_tail[i], name)) return &options_tail[i];
    return NULL;
}

/* ------------------------------------------------------------------------------------ */
/* Parsing                                                                               */

/* "--stream applies to 'loop', 'alpha' and 'sr48' only (not 'convert')": the commands with
 * a stream, from the table (deprecated spellings left out). */
static int stream_not_accepted(const command *cmd)
{
    char list[160];
    size_t i, n = 0, k = 0, total = 0;
    for (i = 0; tool_commands[i]; i++)
        if (tool_commands[i]->stream && !(tool_commands[i]->flags & CMD_DEPRECATED)) total++;
    list[0] = '\0';
    for (i = 0; tool_commands[i]; i++) {
        const command *c = tool_commands[i];
        if (!c->stream || (c->flags & CMD_DEPRECATED)) continue;
        n++;
        k = tool_describe_add(list, k, sizeof list, "%s'%s'", n == 1u ? "" : n == total ? " and " : ", ", c->name);
    }
    return tool_usage_error("--stream applies to %s only (not '%s')", list, cmd->name);
}

/* The command whose stream writes point paths (G-code): named in the message. */
static const char *points_stream_command(void)
{
    size_t i;
    for (i = 0; tool_commands[i]; i++)
        if (tool_commands[i]->flags & CMD_STREAM_POINTS) return tool_commands[i]->name;
    return "?";
}


int tool_parse_args(const command *cmd, int argc, char **argv, tool_opts *o)
{
    int i, rc, no_more_options = 0;
    memset(o, 0, sizeof *o);
    render_opts_default(&o->ropt);
    if (cmd->init) cmd->init(o);
    for (i = 2; i < argc; i++) {
        const char *a = argv[i], *val = NULL, *eq;
        const tool_option *t;
        opt_ctx c;
        char name[32];
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
        if (t->given & ~cmd->options & ~OPT_STREAM)
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
    if (o->stream && !cmd->stream) return stream_not_accepted(cmd);
    if (cmd->check && (rc = cmd->check(cmd, o)) != EXIT_OK) return rc;
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
        if (o->out_format == HOST_FMT_GCODE && !(o->stream && (cmd->flags & CMD_STREAM_POINTS)))
            return tool_usage_error("cannot write '%s': G-code is written by '%s --stream' only", o->output,
                                    points_stream_command());
        if (o->stream && !(cmd->flags & CMD_STREAM_POINTS) &&
            (o->out_format == HOST_FMT_PNG || o->out_format == HOST_FMT_XYZ || o->out_format == HOST_FMT_GCODE))
            return tool_usage_error("cannot write '%s': --stream writes .stl, .obj or .off", o->output);
    } else if (o->stream && o->stats) {
        /* --stream --stats without -o: the counting sink */
    } else if (cmd->flags & CMD_OUTPUT_REQUIRED) {
        return tool_usage_error("'%s' needs an output file (-o OUTPUT%s)", cmd->name,
                                o->stream ? "; with --stats, --stream may leave it out" : "");
    }
    if (o->render_opt_given && o->out_format != HOST_FMT_PNG)
        return tool_usage_error("picture options (--size, --yaw, --pitch, --no-edges, --edges, --with-input, "
                                "--no-labels) need a .png output");
    if (o->boundary_name && !(cmd->options & OPT_BOUNDARY))
        return tool_usage_error("option --boundary does not apply to '%s'", cmd->name);
    if (!o->has_levels) o->levels = cmd->default_levels;
    /* the command's own checks: --boundary's value, required options, defaults */
    if (cmd->finish && (rc = cmd->finish(cmd, o)) != EXIT_OK) return rc;
    if ((cmd->flags & CMD_LEVELS) && !(cmd->flags & CMD_LEVEL0) && cmd->run && o->levels == 0)
        return tool_usage_error("'%s' needs at least one level (-l 1..%lu)", cmd->name, (unsigned long)cmd->max_levels);
    return EXIT_OK;
}

/* ------------------------------------------------------------------------------------ */
/* Usage and --help                                                                      */

/* Prints text; each '\n' in it starts a new line indented by `indent` spaces. */
static void print_continued(FILE *f, const char *text, int indent)
{
    for (; *text; text++) {
        if (*text == '\n') fprintf(f, "\n%*s", indent, "");
        else fputc(*text, f);
    }
    fputc('\n', f);
}

static void print_option(FILE *f, const tool_option *t)
{
    char col[32], text[512];
    if (t->alias) snprintf(col, sizeof col, "%s, %s", t->alias, t->name);
    else snprintf(col, sizeof col, "%s%s%s", t->name, t->meta ? " " : "", t->meta ? t->meta : "");
    snprintf(text, sizeof text, t->help, 2 * SUBD_MAX_LEVELS, SUBD_MAX_LEVELS);
    fprintf(f, "  %-17s ", col);
    print_continued(f, text, 2 + 17 + 1);
}

/* The help is generated from the command table and the option rows. */
void tool_usage(FILE *f)
{
    size_t i, j;
    int w = 0;
    for (i = 0; tool_commands[i]; i++)
        if ((int)strlen(tool_commands[i]->synopsis) > w) w = (int)strlen(tool_commands[i]->synopsis);
    fprintf(f, "usage: subd COMMAND [options] INPUT [-o OUTPUT]\n"
               "       subd help | --help | --version\n\n"
               "tinysubd %s host tool, %s build (%s).\n\ncommands:\n",
            SUBD_VERSION, ARITHMETIC, SUBD_FIXED ? "Q16.16 fixed point" : "IEEE single precision");
    for (i = 0; tool_commands[i]; i++) {
        fprintf(f, "  %-8s %-*s  ", tool_commands[i]->name, w, tool_commands[i]->synopsis);
        print_continued(f, tool_commands[i]->summary, 2 + 8 + 1 + w + 2);
    }
    fprintf(f, "\nformats, by extension (any case): .obj and .off are read and written;\n"
               ".png is written (a rendering of the result); .xyz is written as plain 'x y z'\n"
               "lines, polylines separated by a blank line (for CNC use); .stl (binary STL,\n"
               "one facet per triangle with its unit normal) is written by loop --stream;\n"
               ".stl (binary or ASCII, corners welded by equal coordinates) and .ply (ASCII or\n"
               "binary little-endian) are read.\n"
               "\noptions:\n");
    for (i = 0; i < NUM_OPTIONS; i++) print_option(f, &options[i]);
    for (i = 0; tool_commands[i]; i++)
        for (j = 0; j < tool_commands[i]->num_opts; j++)
            if (!option_listed_before(i, tool_commands[i]->opts[j].name)) print_option(f, &tool_commands[i]->opts[j]);
    for (i = 0; i < NUM_OPTIONS_TAIL; i++) print_option(f, &options_tail[i]);
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
