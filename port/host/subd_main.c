/* SPDX-License-Identifier: MIT */
/* subd — the tinysubd host command-line tool.
 *
 *   subd COMMAND [options] INPUT [-o OUTPUT]
 *
 * Every command runs the same path: parse options -> read INPUT (.obj/.off) into an arena
 * sized by the reader's plan call -> apply tags (--tag-boundary, --crease-angle, --tags through
 * the library's tag-file parser) -> plan and run the command's operation (scheme commands)
 * -> write OUTPUT by extension (.obj/.off via the library writers, .png via the renderer) ->
 * human report and/or --stats JSON. --stream replaces run and write by the command's stream
 * into a sink that writes OUTPUT (subd_stream.c for triangles). A scheme command is one
 * descriptor (subd_tool.h: command) in its module (cmd_*.c) with plan, run and stream
 * functions; everything else (options, arena budget, errors, exit codes, output, stats) is
 * shared and names no scheme. subd_tool.h says which file owns what.
 *
 * Exit status: 0 ok, 1 usage, 2 bad input, 3 resource limit, 4 output not writable, 5 pia
 * did not reach --tol (output written). With --stats a failure still prints one JSON object.
 *
 * The tool is built once per arithmetic (subd = float32, subd-fixed = Q16.16), so tool users
 * see exactly what a device build of that arithmetic produces.
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <unistd.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "subd_tool.h"
#include "host_real.h"

/* ------------------------------------------------------------------------------------ */
/* Tag files (--tags)                                                                     */

/* Applies a tag file to the input mesh with subd_tags_apply (src/tags.c): nothing is applied
 * unless the whole file is valid. Errors name FILE:LINE and exit 2. */
static int apply_tag_file(const char *path, subd_mesh *m, int quiet)
{
    char *buf = NULL;
    uint32_t len = 0;
    subd_tags_report rep;
    subd_diag d;
    int st;
    if ((st = host_read_file(path, &buf, &len)) != 0) {
        tool_error("cannot read tag file '%s': %s", path, host_read_error_str(st));
        return EXIT_INPUT;
    }
    st = subd_tags_apply(buf, len, m, &rep, &d);
    free(buf);
    if (st == SUBD_ERR_INDEX && rep.edge[0] != SUBD_NONE) {
        fprintf(stderr, "%s:%lu: vertices %lu and %lu share no edge\n", path, (unsigned long)d.line,
                (unsigned long)rep.edge[0] + 1u, (unsigned long)rep.edge[1] + 1u);
        return EXIT_INPUT;
    }
    if (st == SUBD_ERR_PARSE || st == SUBD_ERR_INDEX) {
        fprintf(stderr,
                "%s:%lu: expected 'crease I J', 'corner I', 'fixed I' or 'alpha I A' with vertex numbers 1..%lu, "
                "or 'falpha F A' with face numbers 1..%lu\n",
                path, (unsigned long)d.line, (unsigned long)m->num_verts, (unsigned long)m->num_faces);
        return EXIT_INPUT;
    }
    if (st != SUBD_OK) return tool_library_error(path, st, &d, 0, 0);
    if (!quiet) {
        progress_pause();
        fprintf(stderr, "subd: %s: %lu crease edge(s), %lu vertex tag(s), %lu alpha(s)\n", path,
                (unsigned long)rep.creases, (unsigned long)rep.vertex_tags,
                (unsigned long)(rep.vertex_alphas + rep.face_alphas));
    }
    return EXIT_OK;
}

/* ------------------------------------------------------------------------------------ */
/* Progress phases and pictures                                                           */

static const char *base_name(const char *path)
{
    const char *s = strrchr(path, '/');
    return s ? s + 1 : path;
}

static void progress_phase_file(const char *verb, const char *path)
{
    char what[96];
    snprintf(what, sizeof what, "%s %s", verb, base_name(path));
    progress_phase(what);
}

/* The command with the options that change its result, e.g. "alpha -l 5 --kernel cos
 * --alpha 1/4": the progress phase and the picture's caption. The scheme's one name (a
 * deprecated spelling describes itself by the new one), -l, the scheme's own options
 * (command.describe), --tags. */
static void describe_command(const tool_run *r, char *buf, size_t n)
{
    const tool_opts *o = &r->o;
    const command *cmd = r->cmd;
    size_t k = tool_describe_add(buf, 0, n, "%s", cmd->canonical);
    if (cmd->flags & CMD_LEVELS) k = tool_describe_add(buf, k, n, " -l %lu", (unsigned long)o->levels);
    if (cmd->describe) k = cmd->describe(o, buf, k, n);
    if (o->tags) k = tool_describe_add(buf, k, n, " --tags %s", base_name(o->tags)); /* tags change the result */
}

/* "642 vertices, 1280 faces" or, for polylines, "129 points, 1 curve". */
static void mesh_counts(const subd_mesh *m, char *buf, size_t n)
{
    if (!m->num_faces && m->num_lines)
        snprintf(buf, n, "%lu points, %lu curve%s", (unsigned long)m->num_verts, (unsigned long)m->num_lines,
                 m->num_lines == 1u ? "" : "s");
    else
        snprintf(buf, n, "%lu vertices, %lu faces", (unsigned long)m->num_verts, (unsigned long)m->num_faces);
}

/* --with-input FILE: read like INPUT (its own arena), positions as doubles for the picture. */
static int read_overlay(tool_run *r)
{
    host_mesh *h = &r->overlay;
    render_mesh *rm = &r->overlay_rm;
    subd_diag d;
    int st = host_read_mesh(r->o.with_input, NULL, h, &d, NULL);
    if (st == HOST_ERR_IO) {
        tool_error("cannot read '%s': %s", r->o.with_input, host_read_error_str(h->read_rc));
        return EXIT_INPUT;
    }
    if (st == HOST_ERR_OOM) return tool_out_of_memory();
    if (st != SUBD_OK) return tool_library_error(r->o.with_input, st, &d, 0, 0);
    if (tool_render_view(&h->mesh, rm, &r->overlay_pos) != 0) return tool_out_of_memory();
    r->o.ropt.input = rm;
    return EXIT_OK;
}

/* The captions of a picture: what the result is (the command, or the file for render and
 * convert) with its counts, and the --with-input file with its counts. */
static void picture_captions(tool_run *r)
{
    char what[96], counts[64];
    if (r->o.no_labels) return;
    if (r->cmd->run) {
        describe_command(r, what, sizeof what);
        mesh_counts(&r->out, counts, sizeof counts);
        snprintf(r->label[0], sizeof r->label[0], "result of %s: %s", what, counts);
    } else {
        mesh_counts(&r->out, counts, sizeof counts);
        snprintf(r->label[0], sizeof r->label[0], "%s: %s", base_name(r->o.input), counts);
    }
    r->o.ropt.label = r->label[0];
    if (r->o.with_input) {
        mesh_counts(&r->overlay.mesh, counts, sizeof counts);
        snprintf(r->label[1], sizeof r->label[1], "input %s: %s", base_name(r->o.with_input), counts);
        r->o.ropt.input_label = r->label[1];
    }
}

/* ------------------------------------------------------------------------------------ */
/* The common path                                                                        */

static int tool_scheme_error(const tool_run *r, int st, subd_diag *d)
{
    return tool_input_error(r->o.input, r->in.format, &r->in.mesh, st, d, r->o.has_budget, r->o.budget);
}

static int run_command(tool_run *r)
{
    const command *cmd = r->cmd;
    subd_diag d;
    double ns = 0.0, t0;
    int st;

    progress_phase_file("reading", r->o.input);
    st = host_read_mesh(r->o.input, r->o.has_budget ? &r->o.budget : NULL, &r->in, &d, &ns);
    r->lib_ns += ns;
    if (st == HOST_ERR_IO) {
        tool_error("cannot read '%s': %s", r->o.input, host_read_error_str(r->in.read_rc));
        return EXIT_INPUT;
    }
    if (st == HOST_ERR_OOM) return tool_out_of_memory();
    if (st == HOST_ERR_FORMAT) return tool_usage_error("cannot read '%s': input must be " HOST_READABLE, r->o.input);
    if (st == SUBD_ERR_PARSE && r->in.big_endian_ply) {
        tool_error_at("%s:%lu: big-endian PLY is not supported (ascii and binary_little_endian are)", r->o.input,
                      (unsigned long)d.line);
        return EXIT_INPUT;
    }
    if (st != SUBD_OK) return tool_library_error(r->o.input, st, &d, r->o.has_budget, r->o.budget);
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
        if (!r->o.stats && !r->o.quiet) {
            progress_pause();
            fprintf(stderr, "subd: %lu crease edge(s) tagged\n", (unsigned long)n);
        }
    }
    if (r->o.tags && (st = apply_tag_file(r->o.tags, &r->in.mesh, r->o.stats || r->o.quiet)) != EXIT_OK) return st;
    if (r->o.with_input && (st = read_overlay(r)) != EXIT_OK) return st;

    if (cmd->run) {
        uint32_t bytes = 0, base = r->in.arena.used, need;
        subd_arena *a;
        char what[96];
        describe_command(r, what, sizeof what);
        progress_phase(what);
        t0 = host_now_ns();
        st = cmd->plan(&r->in.mesh, &r->o, &bytes, &d);
        r->lib_ns += host_now_ns() - t0;
        if (st > 0) return st; /* an EXIT_* the plan already reported (alpha's tag file) */
        if (st != SUBD_OK) return tool_scheme_error(r, st, &d);
        need = (bytes > UINT32_MAX - base) ? UINT32_MAX : base + bytes;
        if (need > r->planned) r->planned = need;
        if (r->o.has_budget) {
            if (r->planned > r->o.budget) return tool_arena_too_small(r->planned, r->o.budget);
            a = &r->in.arena;
        } else {
            r->work_mem = host_arena_alloc(&r->work, bytes);
            if (!r->work_mem) return tool_out_of_memory();
            a = &r->work;
        }
        if (r->o.stream) {
            /* --stream: the triangles (points) go straight to OUTPUT (subd_stream.c for
             * triangles), and the stream times its library calls */
            st = cmd->stream(r, a, &d);
            if (st > 0) return st;
        } else {
            t0 = host_now_ns();
            st = cmd->run(a, &r->in.mesh, &r->o, &r->out, &r->extra, &d);
            r->lib_ns += host_now_ns() - t0;
        }
        if (st != SUBD_OK) return tool_scheme_error(r, st, &d);
        if (r->o.has_budget) {
            r->used = r->in.arena.peak;
        } else if (base + r->work.peak > r->used) {
            r->used = base + r->work.peak;
        }
    }

    if (r->o.output && !r->o.stream) {
        progress_phase_file("writing", r->o.output);
        if (r->o.out_format == HOST_FMT_PNG) picture_captions(r);
        st = tool_write_output(r);
        if (st != EXIT_OK) return st;
    }
    progress_end(1); /* the final line, before reports and notes */
    if (cmd->report) {
        st = cmd->report(r->o.stats ? stderr : stdout, r);
        if (st != EXIT_OK) return st;
    }
    if (r->o.stats) tool_print_stats(stdout, r);
    if (r->extra.warning[0]) {
        progress_pause();
        fprintf(stderr, "%s", r->extra.warning);
    }
    return r->extra.exit_status; /* pia: EXIT_NOT_CONVERGED, the --stats object above says why */
}

int main(int argc, char **argv)
{
    const command *cmd;
    tool_run r;
    int rc;

    if (argc < 2) {
        fprintf(stderr, "subd: missing command\n");
        tool_usage_short(stderr);
        return EXIT_USAGE;
    }
    if (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0 || strcmp(argv[1], "help") == 0) {
        tool_usage(stdout);
        return EXIT_OK;
    }
    if (strcmp(argv[1], "--version") == 0) {
        printf("subd %s (tinysubd, %s)\n", SUBD_VERSION, ARITHMETIC);
        return EXIT_OK;
    }
    cmd = tool_find_command(argv[1]);
    if (!cmd) return tool_usage_error("unknown command '%s'", argv[1]);
    memset(&r, 0, sizeof r);
    r.cmd = cmd;
    rc = tool_parse_args(cmd, argc, argv, &r.o);
    if (rc != EXIT_OK) {
        if (r.o.stats) tool_failure_json(cmd->name, rc);
        return rc;
    }
    /* phases: read, run (scheme commands), write (unless --stream writes as it runs) */
    progress_begin(cmd->name, !r.o.quiet && isatty(2),
                   1u + (cmd->run ? 1u : 0u) + (r.o.output && !r.o.stream ? 1u : 0u));
    rc = run_command(&r);
    progress_end(rc == EXIT_OK || rc == EXIT_NOT_CONVERGED);
    if (rc != EXIT_OK && rc != EXIT_NOT_CONVERGED && r.o.stats) tool_failure_json(cmd->name, rc);
    host_mesh_free(&r.in);
    host_mesh_free(&r.overlay);
    free(r.overlay_pos);
    free(r.work_mem);
    free(r.extra.host_mem);
    if (fflush(stdout) != 0 && rc == EXIT_OK) {
        fprintf(stderr, "subd: cannot write standard output: %s\n", strerror(errno));
        rc = EXIT_OUTPUT;
    }
    return rc;
}

