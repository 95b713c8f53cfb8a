/* SPDX-License-Identifier: MIT */
/* subd tool: the progress line on stderr (see progress.h for what is shown and when).
 *
 * State shared with the SIGALRM handler is either a sig_atomic_t (the phase number, the
 * fraction in permille, the paused flag) or the phase text, which the main flow changes only
 * with SIGALRM blocked. The handler formats with its own integer code (no stdio, which is
 * not async-signal-safe) and keeps errno. The line is padded with spaces to the length of
 * the one before, so a shorter line leaves nothing of a longer one behind.
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
#include "progress.h"

#define PROGRESS_PERIOD_NS 250000000L /* four redraws a second */
#define TEXT_MAX 64

static volatile sig_atomic_t g_on;        /* progress_begin(enabled = 1) and not ended   */
static int g_timer_ok;                    /* g_timer exists                              */
static timer_t g_timer;
static struct timespec g_t0;              /* CLOCK_MONOTONIC at progress_begin            */
static long g_delay_ms = 1000;
static char g_cmd[24];
static char g_text[TEXT_MAX];             /* the phase; changed with SIGALRM blocked      */
static volatile sig_atomic_t g_phase;     /* 1..g_phases; 0 before the first phase        */
static volatile sig_atomic_t g_phases;
static volatile sig_atomic_t g_permille;  /* of the current phase; -1: unknown            */
static volatile sig_atomic_t g_paused;    /* a message is being printed: draw nothing     */
static volatile sig_atomic_t g_visible;   /* a progress line is on the terminal now       */
static volatile sig_atomic_t g_shown;     /* a line was drawn at some time                */
static volatile sig_atomic_t g_last_len;  /* length of the line on the terminal           */

static long elapsed_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t); /* async-signal-safe (POSIX.1-2008) */
    return (long)(t.tv_sec - g_t0.tv_sec) * 1000L + (long)(t.tv_nsec - g_t0.tv_nsec) / 1000000L;
}

static char *put_str(char *p, char *end, const char *s)
{
    while (*s && p < end) *p++ = *s++;
    return p;
}

static char *put_uint(char *p, char *end, unsigned long v)
{
    char d[24];
    int n = 0;
    do {
        d[n++] = (char)('0' + (int)(v % 10u));
        v /= 10u;
    } while (v);
    while (n && p < end) *p++ = d[--n];
    return p;
}

/* Writes all of buf to stderr, retrying after EINTR. */
static void write_all(const char *buf, size_t n)
{
    while (n) {
        ssize_t w = write(2, buf, n);
        if (w < 0 && errno == EINTR) continue;
        if (w <= 0) return;
        buf += w;
        n -= (size_t)w;
    }
}

/* "\rsubd CMD: TEXT (k/n)  PP%  T.T s", padded; final: "... done 100% ...\n". The percent
 * is of the whole command: finished phases count whole, the current one by its fraction. */
static void draw(int final)
{
    char buf[3 * TEXT_MAX + 64];
    char *p = buf, *end = buf + sizeof buf - 2;
    long ms = elapsed_ms(), pm = g_permille < 0 ? 0 : g_permille;
    long n = g_phases > 0 ? g_phases : 1, k = g_phase > 0 ? g_phase : 1, pct;
    int len;
    pct = final ? 100 : ((k - 1) * 1000 + pm) / (10 * n);
    if (pct > 100) pct = 100;
    p = put_str(p, end, "\rsubd ");
    p = put_str(p, end, g_cmd);
    p = put_str(p, end, ": ");
    if (final) {
        p = put_str(p, end, "done");
    } else {
        p = put_str(p, end, g_text);
        p = put_str(p, end, " (");
        p = put_uint(p, end, (unsigned long)k);
        p = put_str(p, end, "/");
        p = put_uint(p, end, (unsigned long)n);
        p = put_str(p, end, ")");
    }
    p = put_str(p, end, "  ");
    p = put_uint(p, end, (unsigned long)pct);
    p = put_str(p, end, "%  ");
    p = put_uint(p, end, (unsigned long)(ms / 1000));
    p = put_str(p, end, ".");
    p = put_uint(p, end, (unsigned long)(ms / 100 % 10));
    p = put_str(p, end, " s");
    len = (int)(p - buf);
    while (len < g_last_len && p < end) { /* blank what is left of a longer line */
        *p++ = ' ';
        len++;
    }
    g_last_len = (sig_atomic_t)len;
    if (final) *p++ = '\n';
    write_all(buf, (size_t)(p - buf));
    g_visible = !final;
    g_shown = 1;
}

static void on_tick(int sig)
{
    int saved = errno;
    (void)sig;
    if (g_on && !g_paused) draw(0);
    errno = saved;
}

/* Clears the line on the terminal (spaces over it, back to column 0). */
static void clear_line(void)
{
    char buf[3 * TEXT_MAX + 72];
    int n = 0, i;
    buf[n++] = '\r';
    for (i = 0; i < g_last_len && n < (int)sizeof buf - 1; i++) buf[n++] = ' ';
    buf[n++] = '\r';
    write_all(buf, (size_t)n);
    g_visible = 0;
    g_last_len = 0;
}

static void block_tick(int block)
{
    sigset_t s;
    sigemptyset(&s);
    sigaddset(&s, SIGALRM);
    sigprocmask(block ? SIG_BLOCK : SIG_UNBLOCK, &s, NULL);
}

void progress_begin(const char *command, int enabled, unsigned phases)
{
    struct sigaction sa;
    struct sigevent ev;
    struct itimerspec its;
    const char *env = getenv("SUBD_PROGRESS_DELAY_MS");
    size_t n = strlen(command);
    g_on = 0;
    if (!enabled) return;
    if (env && *env) {
        char *e;
        long v = strtol(env, &e, 10);
        if (*e == '\0' && v >= 0 && v <= 3600000L) g_delay_ms = v;
    }
    if (n >= sizeof g_cmd) n = sizeof g_cmd - 1u;
    memcpy(g_cmd, command, n);
    g_cmd[n] = '\0';
    g_text[0] = '\0';
    g_phase = 0;
    g_phases = (sig_atomic_t)(phases ? phases : 1u);
    g_permille = -1;
    g_paused = 0;
    g_visible = 0;
    g_shown = 0;
    g_last_len = 0;
    clock_gettime(CLOCK_MONOTONIC, &g_t0);
    g_on = 1;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_tick;
    sa.sa_flags = SA_RESTART; /* reads and writes of the main flow continue after a tick */
    sigemptyset(&sa.sa_mask);
    if (sigaction(SIGALRM, &sa, NULL) != 0) return; /* no live redraw; progress_end still reports */
    memset(&ev, 0, sizeof ev);
    ev.sigev_notify = SIGEV_SIGNAL;
    ev.sigev_signo = SIGALRM;
    if (timer_create(CLOCK_MONOTONIC, &ev, &g_timer) != 0) return;
    g_timer_ok = 1;
    memset(&its, 0, sizeof its);
    its.it_value.tv_sec = g_delay_ms / 1000;
    its.it_value.tv_nsec = g_delay_ms % 1000 * 1000000L + 1; /* 0 would disarm the timer */
    its.it_interval.tv_nsec = PROGRESS_PERIOD_NS;
    timer_settime(g_timer, 0, &its, NULL);
}

void progress_phase(const char *what)
{
    size_t n;
    if (!g_on) return;
    n = strlen(what);
    if (n >= TEXT_MAX) n = TEXT_MAX - 1u;
    block_tick(1);
    memcpy(g_text, what, n);
    g_text[n] = '\0';
    if (g_phase < g_phases) g_phase++;
    g_permille = -1;
    g_paused = 0;
    block_tick(0);
}

void progress_update(uint64_t done, uint64_t total)
{
    if (!g_on) return;
    g_permille = total ? (sig_atomic_t)(done >= total ? 1000u : done * 1000u / total) : -1;
    g_paused = 0;
}

void progress_pause(void)
{
    if (!g_on) return;
    g_paused = 1; /* from here on the handler draws nothing */
    if (g_visible) clear_line();
}

void progress_end(int ok)
{
    if (!g_on) return;
    g_paused = 1; /* a tick still pending after timer_delete draws nothing */
    if (g_timer_ok) timer_delete(g_timer);
    g_timer_ok = 0;
    if (ok && (g_shown || elapsed_ms() >= g_delay_ms)) draw(1);
    else if (g_visible) clear_line();
    g_on = 0;
}
