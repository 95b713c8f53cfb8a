/* SPDX-License-Identifier: MIT */
/* The subd tool's error reporting (tool_error.c): the exit statuses, the messages of usage
 * errors and library failures, and the --stats object of a failed run. It depends on the
 * library, the readers (fileio.h) and the progress line only, never on another tool file, so
 * every tool file can include it without an include circle.
 */
#ifndef TOOL_ERROR_H
#define TOOL_ERROR_H
#include <stdint.h>
#include <stdio.h>
#include "subd.h"
#include "fileio.h"

enum {
    EXIT_OK = 0,
    EXIT_USAGE = 1,
    EXIT_INPUT = 2,
    EXIT_LIMIT = 3,
    EXIT_OUTPUT = 4,
    EXIT_NOT_CONVERGED = 5 /* pia: output written, but --tol not reached in --max-iter */
};

/* "out of memory": EXIT_LIMIT. */
int tool_out_of_memory(void);
/* Records an error message (printf format) for the --stats JSON of a failed run; the
 * caller prints it to stderr as well. The last one recorded is reported. */
void tool_error_record(const char *fmt, ...);
/* Prints "subd: MESSAGE" on stderr and records it (tool_error_record). */
void tool_error(const char *fmt, ...);
/* Prints "MESSAGE" (one that starts with FILE:LINE) on stderr and records it. */
void tool_error_at(const char *fmt, ...);
/* A usage error: "subd: MESSAGE", recorded, and the short usage; EXIT_USAGE. */
int tool_usage_error(const char *fmt, ...);
/* The synopsis and where the rest is (after a usage error). */
void tool_usage_short(FILE *f);
/* "arena too small: needs N bytes, have M" (--arena): EXIT_LIMIT. */
int tool_arena_too_small(uint32_t needed, uint32_t have);
/* A library failure on `file` (its line, element, arena need): the message and the EXIT_*
 * status (EXIT_LIMIT for NOMEM/TOO_BIG, EXIT_USAGE for PARAM, else EXIT_INPUT). */
int tool_library_error(const char *file, int st, const subd_diag *d, int have_budget, uint32_t budget);
/* A scheme's failure on the input mesh m read from `file` (format fmt): tool_library_error
 * with the input line of diag.face (the readers' line lookups). */
int tool_input_error(const char *file, host_format fmt, const subd_mesh *m, int st, subd_diag *d, int have_budget,
                     uint32_t budget);
/* --stats of a failed run: one JSON object with the command, the exit status and the last
 * message. */
void tool_failure_json(const char *command, int rc);
#endif
