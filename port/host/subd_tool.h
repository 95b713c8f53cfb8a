/* SPDX-License-Identifier: MIT */
/* The subd host tool's shared types: the parsed options, an option's row, a command's
 * descriptor, and what one invocation produced. Each concept lives in its own file:
 *   subd_main.c      main, the common path (read, tag, plan, run, write, report)
 *   tool_error.c     error messages, their exit statuses and the failure JSON (tool_error.h:
 *                    includes no other tool header, so there is no include circle)
 *   tool_parse.c     option values' parsers and the description builder (a leaf too: the
 *                    scheme modules use it, not the parser, which reaches them by the table)
 *   subd_options.c   the shared options: parsing argv and the --help text, both from the
 *                    option rows (the shared table and the rows each scheme module owns)
 *   subd_commands.c  the command table: the plain commands (info, convert, render) and the
 *                    descriptors the scheme modules export, in --help order
 *   cmd_loop.c       loop (also --stream, --stream --limit [--chord]) and limit
 *   cmd_pia.c        pia
 *   cmd_quasi48.c    quasi48
 *   cmd_alpha.c      alpha (also --stream: curves to .xyz / G-code)
 *   cmd_sr48.c       sr48 (uniform and adaptive, also --stream) and its deprecated spellings
 *                    semireg48 and adapt
 *   subd_info.c      the `info` report (topology, valences, bounding box)
 *   subd_write.c     the output writers (.obj/.off, .png, .xyz) and the --stats JSON
 *   subd_stream.c    the triangle streams' sinks (binary .stl, .obj/.off gathered by vertex
 *                    id, a counting sink for --stats without -o) and the counting pass; a
 *                    scheme module hands it a tool_stream (its pass and its counts)
 *   progress.c       the progress line on stderr (a terminal only; --quiet)
 * The common path (subd_main.c, subd_options.c, subd_write.c, subd_stream.c) knows no
 * particular scheme: what differs goes through the command's function pointers.
 * Host only (stdio, malloc); never linked into device images.
 */
#ifndef SUBD_TOOL_H
#define SUBD_TOOL_H
#include <stddef.h>
#include <stdio.h>
#include "subd.h"
#include "fileio.h"
#include "render.h"
#include "progress.h"
#include "tool_error.h"
#include "tool_parse.h"

#if SUBD_FIXED
#define ARITHMETIC "q16.16"
#else
#define ARITHMETIC "float32"
#endif

typedef struct tool_opts {
    const char *input;
    const char *output;
    host_format out_format;
    int stats;
    int has_budget;
    uint32_t budget;
    int has_levels;
    uint32_t levels;
    int render_opt_given; /* any of --size/--yaw/--pitch/--no-edges/--edges/--with-input/--no-labels */
    render_opts ropt;
    const char *with_input; /* --with-input FILE: drawn over the picture (render.h)        */
    int no_labels;        /* --no-labels: no captions in the picture                      */
    int quiet;            /* --quiet: no progress line, no informational notes on stderr  */
    /* scheme options: the shared ones (subd_options.c) and those of the scheme modules,
     * each read by the modules named */
    const char *boundary_name;   /* --boundary, interpreted by the command's finish       */
    subd_loop_boundary boundary; /* loop/limit/pia: paper (default) | bspline             */
    subd_quasi48_boundary q48_boundary; /* quasi48: fixed (default) | smooth | normal         */
    int no_smooth;               /* --no-smooth (quasi48, sr48): refinement only          */
    int tag_boundary;            /* --tag-boundary (quasi48): boundary edges tagged as creases
                                  * by the common path, with --crease-angle and --tags    */
    int has_crease_angle;
    double crease_deg;           /* --crease-angle DEG: tag sharper edges as creases      */
    const char *tags;            /* --tags FILE: crease edges, corner and fixed vertices  */
    int normals;                 /* --normals (limit): write limit normals as OBJ vn      */
    double tol;                  /* --tol T (pia)                                         */
    uint32_t max_iter;           /* --max-iter K (pia)                                    */
    subd_pia_method method;      /* --method paper|fast (pia)                             */
    subd_alpha_opts alpha;       /* --order, --kernel, --alpha, --stiffness (alpha)       */
    subd_sr48_adapt_mode adapt_mode;  /* sr48: --point, --ramp, --plane (--chord: set by sr48's finish) */
    int has_chord;               /* --chord EPS given (sr48, alpha --stream, loop --stream --limit) */
    int mode_given;              /* a mode option (--point, --ramp, --plane, --chord): one at most */
    double chord;                /* its EPS, input units                                  */
    double adapt_val[6];         /* sr48: the point (and plane normal)                    */
    uint32_t adapt_axis;         /* --ramp x|y|z                                          */
    double radius;               /* --radius R (sr48 --point)                             */
    int stream;                  /* --stream: the command's stream (command.stream)        */
    int limit;                   /* --limit (loop --stream): limit positions and normals   */
    double feed;                 /* --feed F (alpha --stream, G-code): feed rate, 0 none   */
    unsigned given;              /* OPT_* bits of the scheme options given                */
} tool_opts;

/* Scheme options, as bits: each command lists the ones it accepts. */
#define OPT_BOUNDARY 0x01u /* --boundary (its value checked by the command's finish) */
#define OPT_CREASE 0x02u
#define OPT_NORMALS 0x04u
#define OPT_TOL 0x08u
#define OPT_MAX_ITER 0x10u
#define OPT_METHOD 0x20u
#define OPT_Q48 0x40u /* --tag-boundary */
#define OPT_ALPHA 0x80u /* --order, --kernel, --alpha, --stiffness, --feed */
#define OPT_NO_SMOOTH 0x100u /* --no-smooth */
#define OPT_ADAPT 0x200u /* --point, --ramp, --plane, --radius */
#define OPT_STREAM 0x400u /* --stream, --limit */
#define OPT_TAGS 0x800u /* --tags FILE */
#define OPT_CHORD 0x1000u /* --chord EPS (sr48; alpha --stream; loop --stream --limit) */

/* What a scheme produced besides the output mesh: optional per-vertex normals (written as
 * OBJ vn) and extra --stats members (a JSON fragment without braces, e.g. "iterations":9). */
typedef struct scheme_extra {
    subd_real *normals;
    char json[512]; /* pia --stats: the totals and two phase objects, about 320 bytes */
    void *host_mem; /* output arrays a scheme built in host memory (freed at exit) */
    int exit_status;   /* EXIT_OK, or the status of a result written with a warning
                        * (pia: EXIT_NOT_CONVERGED), reported after --stats            */
    char warning[256]; /* that warning, printed on stderr after the reports         */
} scheme_extra;

/* Command flags. */
#define CMD_OUTPUT_NONE 0x01u     /* takes no -o (report only)                              */
#define CMD_OUTPUT_REQUIRED 0x02u /* -o is mandatory                                        */
#define CMD_PNG_ONLY 0x04u        /* the output must be .png                                */
#define CMD_LEVELS 0x08u          /* accepts -l N                                           */
#define CMD_LEVEL0 0x10u          /* -l 0 is meaningful                                     */
#define CMD_STREAM_POINTS 0x20u   /* --stream writes point paths (.xyz, G-code), not triangles */
#define CMD_DEPRECATED 0x40u      /* an old spelling of `canonical`, kept until 1.0         */

struct tool_run;
struct command;

/* One option: its name, its value placeholder, the scheme-option bit it records, the
 * function that checks and stores its value, and its --help text, so parsing and the help
 * cannot disagree (gltfpack keeps its command line the same way). The shared options are a
 * table in subd_options.c; an option only one scheme reads is a row of its module. */
typedef struct opt_ctx {
    const struct command *cmd;
    struct tool_opts *o;
    const char *name; /* the option's name as given (without =VALUE) */
    const char *val;  /* its value, NULL for a flag                    */
} opt_ctx;

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

typedef struct command {
    const char *name;
    const char *canonical; /* the scheme's one name, written into outputs (captions, STL
                            * headers): `name`, or the new name of a deprecated spelling */
    const char *synopsis; /* arguments after the name, for the usage text */
    const char *summary;  /* one line (continued lines start with '\n') */
    unsigned flags;
    const char *scheme;       /* paper scheme name for --stats, NULL for plain commands  */
    uint32_t default_levels;  /* used when -l is not given (CMD_LEVELS)                  */
    uint32_t max_levels;      /* largest -l N                                            */
    unsigned options;         /* OPT_* scheme options the command accepts                */
    const tool_option *opts;  /* the options its module owns (NULL: none)                */
    size_t num_opts;
    /* Defaults of the scheme's option values, before the command line is read. NULL: none. */
    void (*init)(struct tool_opts *o);
    /* Checks of the whole command line, EXIT_OK or a usage error (reported): `check` right
     * after --stream is known to apply (options that go together), `finish` once the
     * output and the levels are known (values, defaults). NULL: none. */
    int (*check)(const struct command *cmd, struct tool_opts *o);
    int (*finish)(const struct command *cmd, struct tool_opts *o);
    /* Scheme commands: exact arena bytes run() needs for this input (after the input mesh,
     * which stays in the arena), and the operation itself (arena, const input -> output).
     * Both NULL: the output is the input mesh. Return a subd_status, diag filled. */
    int (*plan)(const subd_mesh *in, const tool_opts *o, uint32_t *bytes, subd_diag *d);
    int (*run)(subd_arena *a, const subd_mesh *in, const tool_opts *o, subd_mesh *out, scheme_extra *x,
               subd_diag *d);
    /* --stream: the command's stream into OUTPUT in arena a (which holds the plan the plan
     * function gave with o->stream); SUBD_OK, a subd_status < 0 with *d filled, or an
     * EXIT_* > 0 already reported. NULL: no stream. */
    int (*stream)(struct tool_run *r, subd_arena *a, subd_diag *d);
    /* Appends the options that change the result (after "NAME -l N", before --tags) to
     * buf[k..n): the progress phase and the picture's caption. Returns the new k. */
    size_t (*describe)(const struct tool_opts *o, char *buf, size_t k, size_t n);
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
    host_mesh overlay;     /* --with-input FILE, read before the command runs             */
    double *overlay_pos;   /* its positions as doubles, for render_opts.input             */
    render_mesh overlay_rm;
    char label[2][192];    /* the picture's captions: result, input                       */
} tool_run;

/* The command table (subd_commands.c), in --help order, NULL-terminated. */
extern const command *const tool_commands[];
const command *tool_find_command(const char *name);
/* The scheme modules' descriptors. */
extern const command tool_cmd_loop, tool_cmd_limit, tool_cmd_pia, tool_cmd_quasi48, tool_cmd_alpha, tool_cmd_sr48,
    tool_cmd_semireg48, tool_cmd_adapt;

/* Options and usage (subd_options.c). tool_parse_args parses argv[2..] into *o and returns
 * EXIT_OK or EXIT_USAGE (message printed); -h/--help prints the help and exits. */
int tool_parse_args(const command *cmd, int argc, char **argv, tool_opts *o);
void tool_usage(FILE *f);

/* Reports and output (subd_info.c, subd_write.c). Each returns an EXIT_* status. */
int tool_info_report(FILE *f, const tool_run *r);
int tool_write_output(tool_run *r);
/* The renderer's view of m: its topology shared, its positions as doubles in *pos (malloc'd,
 * the caller frees it after rendering). 0, or -1 when out of memory (*pos NULL). One home for
 * the result picture and the --with-input overlay. */
int tool_render_view(const subd_mesh *m, render_mesh *rm, double **pos);
void tool_print_stats(FILE *f, const tool_run *r);

/* Triangle streams (subd_stream.c). A scheme's stream: one pass of its triangles into a
 * sink (the pass may run twice: a counting pass first when the count is a bound and the
 * output needs it first) and its counts at the level, from closed forms. */
typedef struct stream_counts {
    uint64_t tris, verts, edges, ids;
    uint64_t boundary_edges; /* of the output, for --stats (0 when not counted)         */
    int verts_exact; /* verts is the count, else a bound (the sinks count them)         */
    int tris_bound;  /* tris is a bound (an adaptive cut: the uniform count), else the count */
} stream_counts;

typedef struct tool_stream {
    int (*pass)(void *ctx, subd_arena *a, const subd_tri_sink *sink, subd_diag *d);
    void *ctx;
    stream_counts c;
    int limit; /* the triangles carry limit normals (written as OBJ vn)            */
} tool_stream;

/* What the sinks saw: triangles, the FNV-1a checksum of the position bits, vertices. */
typedef struct stream_result {
    uint64_t tris;
    uint32_t hash, verts;
} stream_result;

/* One pass into a counting sink: *n triangles. */
int tool_stream_count(tool_run *r, subd_arena *a, const tool_stream *s, subd_diag *d, uint64_t *n);
/* Streams s into OUTPUT's sink (.stl/.obj/.off, a counting sink without -o), fills r->out's
 * counts and r->out_bytes, *res. SUBD_OK, a subd_status < 0 (*d filled) or an EXIT_* > 0
 * already reported. */
int tool_stream_write(tool_run *r, subd_arena *a, tool_stream *s, subd_diag *d, stream_result *res);
#endif
