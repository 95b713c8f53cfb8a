/* SPDX-License-Identifier: MIT */
/* Host file wrappers: whole-file I/O, a buffered output file and the writers' record
 * formatting, and mesh reading by extension (see fileio.h). */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <sys/stat.h>
#include "fileio.h"

/* Largest buffer: the input cap plus the terminator (a file that grows past the cap while
 * it is read is refused like one that was too big at the start). */
#define HOST_FILE_MAX ((size_t)HOST_INPUT_MAX + 1u)

static int is_regular(const char *path)
{
    struct stat sb;
    return stat(path, &sb) == 0 && S_ISREG(sb.st_mode);
}

int host_read_file(const char *path, char **buf, uint32_t *len)
{
    FILE *f;
    char *p = NULL;
    size_t cap = 0, n = 0;
    int err = 0;
    struct stat sb;

    *buf = NULL;
    *len = 0;
    if (!path) { errno = EINVAL; return -1; }
    /* Checked before opening: fopen on a FIFO blocks until a writer comes, and a device
     * such as /dev/urandom never ends. */
    if (stat(path, &sb) != 0) return -1;
    if (!S_ISREG(sb.st_mode)) return HOST_READ_NOT_REGULAR;
    if ((unsigned long long)sb.st_size > HOST_INPUT_MAX) return HOST_READ_TOO_BIG;
    f = fopen(path, "rb");
    if (!f) return -1;
    if (fstat(fileno(f), &sb) != 0 || !S_ISREG(sb.st_mode)) { /* replaced since the stat */
        fclose(f);
        return HOST_READ_NOT_REGULAR;
    }
    for (;;) {
        size_t got;
        if (cap - n < 65536u && cap < HOST_FILE_MAX) {
            size_t ncap = cap ? cap * 2u : (size_t)1 << 20;
            char *q;
            if (ncap > HOST_FILE_MAX) ncap = HOST_FILE_MAX;
            q = (char *)realloc(p, ncap);
            if (!q) { err = ENOMEM; break; }
            p = q;
            cap = ncap;
        }
        if (cap - n - 1u == 0) { /* full: only fine if the file ends exactly here */
            if (fgetc(f) != EOF) err = -1; /* grew past the cap */
            else if (ferror(f)) err = errno ? errno : EIO;
            break;
        }
        errno = 0;
        got = fread(p + n, 1, cap - n - 1u, f); /* keep one byte for the terminator */
        n += got;
        if (got == 0) {
            if (ferror(f)) err = errno ? errno : EIO;
            break;
        }
    }
    fclose(f);
    if (err == -1) {
        free(p);
        return HOST_READ_TOO_BIG;
    }
    if (err) {
        free(p);
        errno = err;
        return -1;
    }
    if (!p) { /* empty file */
        p = (char *)malloc(1);
        if (!p) { errno = ENOMEM; return -1; }
    }
    p[n] = '\0';
    *buf = p;
    *len = (uint32_t)n;
    return 0;
}

int host_write_file(const char *path, const void *buf, uint32_t len)
{
    FILE *f;
    int err = 0;
    if (!path || (!buf && len)) { errno = EINVAL; return -1; }
    f = fopen(path, "wb");
    if (!f) return -1;
    errno = 0;
    if (len && fwrite(buf, 1, len, f) != len) err = errno ? errno : EIO;
    errno = 0;
    if (fclose(f) != 0 && !err) err = errno ? errno : EIO;
    if (err) {
        /* a partial regular file goes; a device or FIFO named as output is left alone */
        if (is_regular(path)) remove(path);
        errno = err;
        return -1;
    }
    return 0;
}

int host_out_open(host_out *o, const char *path)
{
    struct stat sb;
    o->path = path;
    o->err = 0;
    o->fill = 0;
    o->bytes = 0;
    o->regular = 0;
    if (!path) { errno = EINVAL; return -1; }
    o->f = fopen(path, "wb");
    if (!o->f) return -1;
    o->regular = fstat(fileno(o->f), &sb) == 0 && S_ISREG(sb.st_mode);
    return 0;
}

static int out_flush(host_out *o)
{
    if (o->err) return -1;
    errno = 0;
    if (o->fill && fwrite(o->buf, 1, o->fill, o->f) != o->fill) {
        o->err = errno ? errno : EIO;
        return -1;
    }
    o->bytes += o->fill;
    o->fill = 0;
    return 0;
}

char *host_out_room(host_out *o, uint32_t n)
{
    if (o->fill + n > HOST_OUT_BUF && out_flush(o) != 0) return NULL;
    return o->err ? NULL : o->buf + o->fill;
}

int host_out_close(host_out *o, int ok)
{
    if (!o->f) return -1;
    if (ok) (void)out_flush(o);
    errno = 0;
    if (fclose(o->f) != 0 && !o->err) o->err = errno ? errno : EIO;
    o->f = NULL;
    if (!ok && !o->err) o->err = EIO; /* the caller's failure: the file is incomplete */
    if (o->err) {
        if (o->regular) remove(o->path);
        errno = o->err;
        return -1;
    }
    return 0;
}

uint32_t host_fmt_u32(char *b, uint32_t v)
{
    char t[10];
    uint32_t n = 0, i;
    do {
        t[n++] = (char)('0' + v % 10u);
        v /= 10u;
    } while (v);
    for (i = 0; i < n; i++) b[i] = t[n - 1u - i];
    return n;
}

uint32_t host_fmt_xyz(char *b, const char *kw, const subd_real *p)
{
    uint32_t n = 0, k;
    while (kw[n]) {
        b[n] = kw[n];
        n++;
    }
    for (k = 0; k < 3u; k++) {
        n += subd_real_format(p[k], b + n);
        b[n++] = k < 2u ? ' ' : '\n';
    }
    return n;
}

const char *host_read_error_str(int rc)
{
    if (rc == HOST_READ_NOT_REGULAR)
        return "not a regular file (FIFOs, devices and directories are refused: inputs are read whole)";
    if (rc == HOST_READ_TOO_BIG) return "larger than the input cap of " HOST_INPUT_MAX_STR " bytes (2 GiB)";
    return strerror(errno);
}

static int lower(int c) { return (c >= 'A' && c <= 'Z') ? c - 'A' + 'a' : c; }

static int ends_with_ci(const char *s, const char *suffix)
{
    size_t n = strlen(s), k = strlen(suffix), i;
    if (n < k) return 0;
    for (i = 0; i < k; i++)
        if (lower((unsigned char)s[n - k + i]) != lower((unsigned char)suffix[i])) return 0;
    return 1;
}

host_format host_format_of(const char *path)
{
    if (!path) return HOST_FMT_UNKNOWN;
    if (ends_with_ci(path, ".obj")) return HOST_FMT_OBJ;
    if (ends_with_ci(path, ".off")) return HOST_FMT_OFF;
    if (ends_with_ci(path, ".png")) return HOST_FMT_PNG;
    if (ends_with_ci(path, ".xyz")) return HOST_FMT_XYZ;
    if (ends_with_ci(path, ".stl")) return HOST_FMT_STL;
    if (ends_with_ci(path, ".ply")) return HOST_FMT_PLY;
    if (ends_with_ci(path, ".gcode") || ends_with_ci(path, ".nc")) return HOST_FMT_GCODE;
    return HOST_FMT_UNKNOWN;
}

const char *host_format_name(host_format f)
{
    switch (f) {
    case HOST_FMT_OBJ: return "obj";
    case HOST_FMT_OFF: return "off";
    case HOST_FMT_PNG: return "png";
    case HOST_FMT_XYZ: return "xyz";
    case HOST_FMT_STL: return "stl";
    case HOST_FMT_PLY: return "ply";
    case HOST_FMT_GCODE: return "gcode";
    default: return "unknown";
    }
}

int host_format_readable(host_format f)
{
    return f == HOST_FMT_OBJ || f == HOST_FMT_OFF || f == HOST_FMT_STL || f == HOST_FMT_PLY;
}

void *host_arena_alloc(subd_arena *a, uint32_t bytes)
{
    /* Over-allocate by the alignment and start the arena at an aligned address, so the arena
     * holds exactly `bytes` usable bytes whatever malloc's alignment is. */
    size_t total = (size_t)bytes + SUBD_ARENA_ALIGN;
    uint8_t *mem = (uint8_t *)malloc(total ? total : 1u);
    uintptr_t addr, aligned;
    if (!mem) return NULL;
    addr = (uintptr_t)mem;
    aligned = (addr + (SUBD_ARENA_ALIGN - 1u)) & ~(uintptr_t)(SUBD_ARENA_ALIGN - 1u);
    subd_arena_init(a, mem + (aligned - addr), bytes);
    return mem;
}

double host_now_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e9 + (double)ts.tv_nsec;
}

int host_read_mesh(const char *path, const uint32_t *budget, host_mesh *hm, subd_diag *diag,
                   double *parse_ns)
{
    char *text = NULL;
    uint32_t len = 0, plan = 0, size;
    int st;
    double t0, t1 = 0.0;
    int (*plan_fn)(const char *, uint32_t, uint32_t *, subd_diag *);
    int (*read_fn)(subd_arena *, const char *, uint32_t, subd_mesh *, subd_diag *);

    memset(hm, 0, sizeof *hm);
    subd_diag_clear(diag);
    if (parse_ns) *parse_ns = 0.0;
    hm->format = host_format_of(path);
    if (hm->format == HOST_FMT_OBJ) {
        plan_fn = subd_obj_plan;
        read_fn = subd_obj_read;
    } else if (hm->format == HOST_FMT_OFF) {
        plan_fn = subd_off_plan;
        read_fn = subd_off_read;
    } else if (hm->format == HOST_FMT_STL) {
        plan_fn = subd_stl_plan;
        read_fn = subd_stl_read;
    } else if (hm->format == HOST_FMT_PLY) {
        plan_fn = subd_ply_plan;
        read_fn = subd_ply_read;
    } else {
        return HOST_ERR_FORMAT;
    }
    hm->read_rc = host_read_file(path, &text, &len);
    if (hm->read_rc != 0) return (hm->read_rc == -1 && errno == ENOMEM) ? HOST_ERR_OOM : HOST_ERR_IO;
    hm->file_bytes = len;

    t0 = host_now_ns();
    st = plan_fn(text, len, &plan, diag);
    t1 += host_now_ns() - t0;
    if (st != SUBD_OK) goto done;
    hm->planned = plan;
    if (budget && plan > *budget) {
        diag->status = SUBD_ERR_NOMEM;
        diag->bytes_needed = plan;
        st = SUBD_ERR_NOMEM;
        goto done;
    }
    size = budget ? *budget : plan;
    hm->mem = host_arena_alloc(&hm->arena, size);
    if (!hm->mem) { st = HOST_ERR_OOM; goto done; }
    t0 = host_now_ns();
    st = read_fn(&hm->arena, text, len, &hm->mesh, diag);
    t1 += host_now_ns() - t0;
    if (st != SUBD_OK) {
        free(hm->mem);
        hm->mem = NULL;
    }
done:
    if (parse_ns) *parse_ns = t1;
    if (st == SUBD_ERR_PARSE && hm->format == HOST_FMT_PLY && diag->line > 0u) {
        /* the library refuses big-endian PLY as a syntax error on its format line: say why */
        const char *p = text, *end = text + len;
        uint32_t line = 1;
        while (p < end && line < diag->line) line += *p++ == '\n';
        hm->big_endian_ply = (size_t)(end - p) >= 24u && memcmp(p, "format binary_big_endian", 24) == 0;
    }
    free(text);
    return st;
}

void host_mesh_free(host_mesh *hm)
{
    if (!hm) return;
    free(hm->mem);
    hm->mem = NULL;
}
