/* SPDX-License-Identifier: MIT */
/* The subd tool's error reporting, in one place (tool_error.h): the last message (for the
 * --stats JSON of a failed run), usage errors, the messages of library failures (FILE:LINE,
 * the element diag names, arena limits) and their exit statuses. Every other tool file calls
 * these; this file calls only the library, the readers' line lookups and the progress line,
 * so it includes no other tool header and no tool file depends on subd_main.c. */
#define _POSIX_C_SOURCE 200809L
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include "tool_error.h"
#include "progress.h"

/* ------------------------------------------------------------------------------------ */
/* Errors                                                                                 */

static char g_error[512]; /* the last error message, for --stats on failure */

static void error_vrecord(const char *fmt, va_list ap)
{
    progress_pause(); /* every caller prints the message on stderr next */
    vsnprintf(g_error, sizeof g_error, fmt, ap);
}

void tool_error_record(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    error_vrecord(fmt, ap);
    va_end(ap);
}

void tool_error(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    error_vrecord(fmt, ap);
    va_end(ap);
    fprintf(stderr, "subd: %s\n", g_error);
}

void tool_error_at(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    error_vrecord(fmt, ap);
    va_end(ap);
    fprintf(stderr, "%s\n", g_error);
}

static void error_element_str(const subd_diag *d, char *buf, size_t n)
{
    buf[0] = '\0';
    if (d->face != SUBD_NONE) snprintf(buf, n, " (face %lu)", (unsigned long)d->face);
    else if (d->polyline != SUBD_NONE) snprintf(buf, n, " (polyline %lu)", (unsigned long)d->polyline);
    else if (d->vertex != SUBD_NONE) snprintf(buf, n, " (vertex %lu)", (unsigned long)d->vertex);
}

/* --stats of a failed run: one JSON object with the exit status and the message. */
void tool_failure_json(const char *command, int rc)
{
    const char *m = g_error[0] ? g_error : "failed (see stderr)";
    printf("{\"command\":\"%s\",\"status\":\"error\",\"exit\":%d,\"message\":\"", command, rc);
    for (; *m; m++) {
        unsigned char c = (unsigned char)*m;
        if (c == '"' || c == '\\') printf("\\%c", c);
        else if (c < 0x20u) printf("\\u%04x", c);
        else putchar(c);
    }
    printf("\"}\n");
}

int tool_arena_too_small(uint32_t needed, uint32_t have)
{
    tool_error("arena too small: needs %lu bytes, have %lu", (unsigned long)needed, (unsigned long)have);
    return EXIT_LIMIT;
}

/* Maps a library failure on `file` to a message and an exit status. */
int tool_library_error(const char *file, int st, const subd_diag *d, int have_budget, uint32_t budget)
{
    char el[64];
    if (st == SUBD_ERR_NOMEM) {
        if (have_budget) return tool_arena_too_small(d->bytes_needed, budget);
        tool_error("%s: internal error: arena planned too small (needs %lu bytes)", file,
                   (unsigned long)d->bytes_needed);
        return EXIT_LIMIT;
    }
    error_element_str(d, el, sizeof el);
    if (!d->line && d->face != SUBD_NONE && host_format_of(file) == HOST_FMT_STL) /* binary STL: its record */
        tool_error_record("%s: facet %lu: %s", file, (unsigned long)d->face, subd_status_str(st));
    else if (d->line) tool_error_record("%s:%lu: %s%s", file, (unsigned long)d->line, subd_status_str(st), el);
    else tool_error_record("%s: %s%s", file, subd_status_str(st), el);
    fprintf(stderr, "%s\n", g_error);
    if (st == SUBD_ERR_TOO_BIG) return EXIT_LIMIT;
    if (st == SUBD_ERR_PARAM) return EXIT_USAGE;
    return EXIT_INPUT;
}

/* A scheme's failure on the input mesh: a triangle-only scheme names the first polygon in
 * diag.face (found here when a plan left it out), which the reader maps back to its line in
 * the input file (subd_obj_line_of / subd_off_line_of / subd_ply_line_of). */
int tool_input_error(const char *file, host_format fmt, const subd_mesh *m, int st, subd_diag *d, int have_budget,
                     uint32_t budget)
{
    uint32_t f;
    if (st == SUBD_ERR_NOT_TRIANGLES && d->face == SUBD_NONE)
        for (f = 0; f < m->num_faces && d->face == SUBD_NONE; f++)
            if (m->face_start[f + 1u] - m->face_start[f] != 3u) d->face = f;
    if (st == SUBD_ERR_NOT_TRIANGLES && d->line == 0u && d->face != SUBD_NONE) {
        char *buf = NULL;
        uint32_t len = 0;
        if (host_read_file(file, &buf, &len) == 0) {
            d->line = fmt == HOST_FMT_OFF   ? subd_off_line_of(buf, len, d)
                      : fmt == HOST_FMT_PLY ? subd_ply_line_of(buf, len, d)
                      : fmt == HOST_FMT_STL ? 0u
                                            : subd_obj_line_of(buf, len, d);
            free(buf);
        }
    }
    return tool_library_error(file, st, d, have_budget, budget);
}

int tool_out_of_memory(void)
{
    tool_error("out of memory");
    return EXIT_LIMIT;
}


/* After a usage error: the synopsis and where the rest is, not the whole help (the
 * specific message above it stays visible). */
void tool_usage_short(FILE *f)
{
    fprintf(f, "usage: subd COMMAND [options] INPUT [-o OUTPUT]\n"
               "run 'subd --help' for the commands, options and exit codes\n");
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
