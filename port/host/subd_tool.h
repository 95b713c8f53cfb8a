/* SPDX-License-Identifier: MIT */
/* The subd host tool's shared types: the parsed options, the command table's row, and what
 * one invocation produced. Each concept lives in its own file:
 *   subd_main.c      main, the common path (read, tag, plan, run, write, report)
 *   tool_error.c     error messages, their exit statuses and the failure JSON
 *   subd_options.c   the option table: parsing argv and the --help text, both from it
 *   subd_commands.c  the command table and the scheme commands' plan and run functions
 *   subd_info.c      the `info` report (topology, valences, bounding box)
 *   subd_write.c     the output writers (.obj/.off, .png, .xyz) and the --stats JSON
 *   subd_stream.c    loop --stream: the triangle sinks (binary .stl, .obj/.off gathered by
 *                    vertex id, a counting sink for --stats without -o)
 *   progress.c       the progress line on stderr (a terminal only; --quiet)
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

enum {
    EXIT_OK = 0,
    EXIT_USAGE = 1,
    EXIT_INPUT = 2,
    EXIT_LIMIT = 3,
    EXIT_OUTPUT = 4,
    EXIT_NOT_CONVERGED = 5 /* pia: output written, but --tol not reached in --max-iter */
};

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
    /* scheme options */
    const char *boundary_name;   /* --boundary, interpreted by the command               */
    subd_loop_boundary boundary; /* loop/limit/pia: paper (default) | bspline             */
    subd_quasi48_boundary q48_boundary; /* quasi48: fixed (default) | smooth                  */
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
    subd_sr48_adapt_mode adapt_mode;  /* adapt: --point, --ramp, --plane or --chord            */
    double adapt_val[6];         /* the point (and plane normal), or the chord tolerance  */
    uint32_t adapt_axis;         /* --ramp x|y|z                                          */
    double radius;               /* --radius R (adapt --point)                            */
    int stream;                  /* --stream (loop): subd_loop_stream, triangles to a sink */
    int sr48_stream;             /* --stream of semireg48: subd_sr48_stream                */
    int limit;                   /* --limit (loop --stream): limit positions and normals   */
    double feed;                 /* --feed F (alpha --stream, G-code): feed rate, 0 none   */
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
#define OPT_STREAM 0x400u /* --stream, --limit */
#define OPT_TAGS 0x800u /* --tags FILE */

/* What a scheme produced besides the output mesh: optional per-vertex normals (written as
 * OBJ vn) and extra --stats members (a JSON fragment without braces, e.g. "iterations":9). */
typedef struct scheme_extra {
    subd_real *normals;
    char json[512]; /* pia --stats: the totals and two phase objects, about 320 bytes */
    void *host_mem; /* output arrays a scheme built in host memory (freed at exit) */
    int not_converged; /* pia: the tolerance was not reached (exit EXIT_NOT_CONVERGED)   */
    double max_err;    /* pia: the error reached                                        */
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
    host_mesh overlay;     /* --with-input FILE, read before the command runs             */
    double *overlay_pos;   /* its positions as doubles, for render_opts.input             */
    render_mesh overlay_rm;
    char label[2][192];    /* the picture's captions: result, input                       */
} tool_run;

/* The command table (subd_commands.c). */
extern const command tool_commands[];
extern const size_t tool_num_commands;
const command *tool_find_command(const char *name);

/* Options and usage (subd_options.c). tool_parse_args parses argv[2..] into *o and returns
 * EXIT_OK or EXIT_USAGE (message printed); -h/--help prints the help and exits. */
int tool_parse_args(const command *cmd, int argc, char **argv, tool_opts *o);
void tool_usage(FILE *f);
void tool_usage_short(FILE *f);
int tool_usage_error(const char *fmt, ...);

/* Reports and output (subd_info.c, subd_write.c). Each returns an EXIT_* status. */
int tool_info_report(FILE *f, const tool_run *r);
int tool_write_output(tool_run *r);
/* The renderer's view of m: its topology shared, its positions as doubles in *pos (malloc'd,
 * the caller frees it after rendering). 0, or -1 when out of memory (*pos NULL). One home for
 * the result picture and the --with-input overlay. */
int tool_render_view(const subd_mesh *m, render_mesh *rm, double **pos);
void tool_print_stats(FILE *f, const tool_run *r);

/* loop --stream (subd_stream.c): streams the input into the sink OUTPUT's format needs (or a
 * counting sink without -o) in arena a, which holds the plan of tool_loop_opts(o). Returns
 * SUBD_OK, a subd_status < 0 with *d filled, or an EXIT_* > 0 already reported. */
int tool_stream_run(tool_run *r, subd_arena *a, subd_diag *d);

/* alpha --stream (subd_commands.c): every polyline streamed into OUTPUT (.xyz, .gcode/.nc)
 * in arena a (the plan of alpha_plan with --stream). Returns as tool_stream_run. */
int tool_alpha_stream_run(tool_run *r, subd_arena *a, subd_diag *d);

/* The subd_loop_opts of the loop command (subd_commands.c): --stream --limit sets
 * SUBD_LOOP_STREAM_LIMIT. */
subd_loop_opts tool_loop_opts(const tool_opts *o);
/* loop --stream --limit --chord EPS: subd_loop_adapt_stream's options (subd_commands.c). */
subd_loop_adapt_opts tool_loop_adapt_opts(const tool_opts *o);

/* The cut of semireg48 (uniform) and adapt (subd_commands.c): the mode and its parameters,
 * max_level = -l; used by both the materialised run and the stream. */
subd_sr48_adapt tool_sr48_adapt(const tool_opts *o);

/* Errors (tool_error.c): print the message, return the EXIT_* status. */
int tool_out_of_memory(void);
/* Records an error message (printf format) for the --stats JSON of a failed run; the
 * caller prints it to stderr as well. The last one recorded is reported. */
void tool_error_record(const char *fmt, ...);
/* Prints "subd: MESSAGE" on stderr and records it (tool_error_record). */
void tool_error(const char *fmt, ...);
/* Prints "MESSAGE" (one that starts with FILE:LINE) on stderr and records it. */
void tool_error_at(const char *fmt, ...);
/* "arena too small: needs N bytes, have M" (--arena): EXIT_LIMIT. */
int tool_arena_too_small(uint32_t needed, uint32_t have);
/* A library failure on `file` (its line, element, arena need): the message and the EXIT_*
 * status (EXIT_LIMIT for NOMEM/TOO_BIG, EXIT_USAGE for PARAM, else EXIT_INPUT). */
int tool_library_error(const char *file, int st, const subd_diag *d, int have_budget, uint32_t budget);
/* A scheme's failure on the input mesh: tool_library_error with the input line of
 * diag.face (the readers' line lookups). */
int tool_scheme_error(const tool_run *r, int st, subd_diag *d);
/* --stats of a failed run: one JSON object with the exit status and the last message. */
void tool_failure_json(const command *cmd, int rc);
#endif
