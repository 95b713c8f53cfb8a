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
} tool_opts;

/* Command flags. */
#define CMD_OUTPUT_NONE 0x01u     /* takes no -o (report only)                              */
#define CMD_OUTPUT_REQUIRED 0x02u /* -o is mandatory                                        */
#define CMD_PNG_ONLY 0x04u        /* the output must be .png                                */
#define CMD_LEVELS 0x08u          /* accepts -l N                                           */

struct tool_run;

typedef struct command {
    const char *name;
    const char *synopsis; /* arguments after the name, for the usage text */
    const char *summary;  /* one line (continued lines start with '\n') */
    unsigned flags;
    const char *scheme;       /* paper scheme name for --stats, NULL for plain commands  */
    uint32_t default_levels;  /* used when -l is not given (CMD_LEVELS)                  */
    /* Scheme commands: exact arena bytes run() needs for this input (after the input mesh,
     * which stays in the arena), and the operation itself (arena, const input -> output).
     * Both NULL: the output is the input mesh. Return a subd_status, diag filled. */
    int (*plan)(const subd_mesh *in, const tool_opts *o, uint32_t *bytes, subd_diag *d);
    int (*run)(subd_arena *a, const subd_mesh *in, const tool_opts *o, subd_mesh *out, subd_diag *d);
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
    int out_width, out_height;
} tool_run;

static int info_report(FILE *f, const tool_run *r);

/* To add a scheme (e.g. loop): write
 *   static int loop_plan(const subd_mesh *in, const tool_opts *o, uint32_t *bytes, subd_diag *d)
 *   { return subd_loop_plan(in, o->levels, bytes, d); }
 *   static int loop_run(subd_arena *a, const subd_mesh *in, const tool_opts *o, subd_mesh *out,
 *                       subd_diag *d)
 *   { return subd_loop(a, in, o->levels, out, d); }
 * and add a row
 *   {"loop", "[-l N] INPUT -o OUTPUT", "Loop subdivision (triangles)", CMD_OUTPUT_REQUIRED |
 *    CMD_LEVELS, "loop", 1, loop_plan, loop_run, NULL},
 * Scheme-specific options go into tool_opts and parse_option(). */
static const command commands[] = {
    {"info", "INPUT", "counts, components, Euler characteristic, genus,\n"
                      "valences and bounding box of a mesh",
     CMD_OUTPUT_NONE, NULL, 0, NULL, NULL, info_report},
    {"convert", "INPUT -o OUTPUT", "write the mesh in OUTPUT's format",
     CMD_OUTPUT_REQUIRED, NULL, 0, NULL, NULL, NULL},
    {"render", "INPUT -o OUTPUT.png", "draw the mesh (shaded, with edges) as a PNG",
     CMD_OUTPUT_REQUIRED | CMD_PNG_ONLY, NULL, 0, NULL, NULL, NULL},
};
#define NUM_COMMANDS (sizeof commands / sizeof commands[0])

static const command *find_command(const char *name)
{
    size_t i;
    for (i = 0; i < NUM_COMMANDS; i++)
        if (strcmp(commands[i].name, name) == 0) return &commands[i];
    return NULL;
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
            ".png is written (a rendering of the result).\n"
            "\noptions:\n"
            "  -o FILE          output file\n"
            "  -l N             subdivision levels, 0..%d (scheme commands)\n"
            "  --stats          print exactly one JSON object on stdout (keys: command, scheme,\n"
            "                   levels, arithmetic, input, output, arena_budget, arena_planned,\n"
            "                   arena_used, time_ms = milliseconds in library calls); the\n"
            "                   human report of 'info' then goes to stderr\n"
            "  --arena BYTES    simulate a device arena of BYTES bytes (suffix k = 1024,\n"
            "                   m = 1048576): exit 3 when the command needs more\n"
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
            SUBD_MAX_LEVELS);
}

static int usage_error(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fprintf(stderr, "subd: ");
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fprintf(stderr, "\n\n");
    usage(stderr);
    return EXIT_USAGE;
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
        if (strcmp(name, "--stats") == 0 || strcmp(name, "--no-edges") == 0) {
            if (val) return usage_error("option '%s' takes no value", name);
            if (strcmp(name, "--stats") == 0) o->stats = 1;
            else { o->ropt.edges = 0; o->render_opt_given = 1; }
            continue;
        }
        if (strcmp(name, "-o") && strcmp(name, "-l") && strcmp(name, "--arena") &&
            strcmp(name, "--size") && strcmp(name, "--yaw") && strcmp(name, "--pitch"))
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
            if (parse_u32(val, SUBD_MAX_LEVELS, &o->levels))
                return usage_error("bad level count '%s' (expected 0..%d)", val, SUBD_MAX_LEVELS);
            o->has_levels = 1;
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
            return usage_error("cannot write '%s': output must be .obj, .off or .png", o->output);
        if ((cmd->flags & CMD_PNG_ONLY) && o->out_format != HOST_FMT_PNG)
            return usage_error("'%s' writes a .png picture", cmd->name);
    } else if (cmd->flags & CMD_OUTPUT_REQUIRED) {
        return usage_error("'%s' needs an output file (-o OUTPUT)", cmd->name);
    }
    if (o->render_opt_given && o->out_format != HOST_FMT_PNG)
        return usage_error("picture options (--size, --yaw, --pitch, --no-edges) need a .png output");
    if (!o->has_levels) o->levels = cmd->default_levels;
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

static int write_mesh(tool_run *r)
{
    int (*writer)(const subd_mesh *, char *, uint32_t, uint32_t *) =
        (r->o.out_format == HOST_FMT_OBJ) ? subd_obj_write : subd_off_write;
    uint32_t len = 0;
    char *buf;
    int st = writer(&r->out, NULL, 0, &len);
    if (st != SUBD_OK) {
        fprintf(stderr, "subd: %s: %s\n", r->o.output, subd_status_str(st));
        return st == SUBD_ERR_TOO_BIG ? EXIT_LIMIT : EXIT_OUTPUT;
    }
    if (r->o.out_format == HOST_FMT_OFF && r->out.num_lines)
        fprintf(stderr, "subd: warning: %s: OFF has no polylines; %lu polyline(s) not written\n",
                r->o.output, (unsigned long)r->out.num_lines);
    buf = (char *)malloc((size_t)len + 1u);
    if (!buf) return out_of_memory();
    st = writer(&r->out, buf, len, &len);
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
    fprintf(f, ",\"arena_planned\":%lu,\"arena_used\":%lu,\"time_ms\":%.3f}\n", (unsigned long)r->planned,
            (unsigned long)r->used, r->lib_ns / 1e6);
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
        st = cmd->run(a, &r->in.mesh, &r->o, &r->out, &d);
        r->lib_ns += host_now_ns() - t0;
        if (st != SUBD_OK) return library_error(r->o.input, st, &d, r->o.has_budget, r->o.budget);
        if (r->o.has_budget) {
            r->used = r->in.arena.peak;
        } else if (base + r->work.peak > r->used) {
            r->used = base + r->work.peak;
        }
    }

    if (r->o.output) {
        st = (r->o.out_format == HOST_FMT_PNG) ? write_png(r) : write_mesh(r);
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
        fprintf(stderr, "subd: missing command\n\n");
        usage(stderr);
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
    if (fflush(stdout) != 0 && rc == EXIT_OK) {
        fprintf(stderr, "subd: cannot write standard output: %s\n", strerror(errno));
        rc = EXIT_OUTPUT;
    }
    return rc;
}
