/* SPDX-License-Identifier: MIT */
/* subd tool: progress on stderr for commands that run longer than about a second.
 *
 * The tool's work is a few phases (read INPUT, run the scheme, write OUTPUT); a phase may
 * report how far it is (progress_update: loop --stream's sink counts triangles). The line
 *     subd loop: writing out.obj (3/3)  67%  2.4 s
 * is redrawn in place ('\r') a few times per second, only when stderr is a terminal and
 * --quiet is not given, and only once the command has run for about a second; the last
 * line ends with a newline. Nothing is printed otherwise, so logs and pipes see no change.
 *
 * The library has no progress callback (and gets none: a firmware caller has its own
 * means). A phase that is one long library call (subd_loop, a writer) therefore reports no
 * fraction; its line still moves, because a monotonic interval timer (timer_create on
 * CLOCK_MONOTONIC, SIGALRM with SA_RESTART) redraws it with the elapsed time. The signal
 * handler only formats integers into a static buffer and calls write(2), both
 * async-signal-safe. Host only.
 */
#ifndef SUBD_PROGRESS_H
#define SUBD_PROGRESS_H
#include <stdint.h>

/* Starts the display for `command` ("loop") with `phases` phases to come. enabled = 0
 * (--quiet, or stderr is no terminal: the caller decides with isatty(2)) makes every
 * progress call a no-op. The delay before the first line is 1000 ms; the environment
 * variable SUBD_PROGRESS_DELAY_MS overrides it (tests use 0). */
void progress_begin(const char *command, int enabled, unsigned phases);

/* The next phase, e.g. "reading spot.obj" (copied; at most 63 bytes shown). */
void progress_phase(const char *what);

/* done of total units of the current phase are finished (total 0: unknown). Cheap: stores
 * one number; the timer draws it. */
void progress_update(uint64_t done, uint64_t total);

/* Call before printing another message on stderr: clears the progress line. The next
 * progress_phase or progress_update resumes the display below the message. */
void progress_pause(void);

/* Stops the timer. ok != 0: when the display was on (or the command ran past the delay),
 * the final line "... done 100%" ends with a newline. ok == 0: the line is cleared. */
void progress_end(int ok);
#endif
