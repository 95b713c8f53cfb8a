/* Host file wrappers: whole-file I/O and mesh reading by extension (see fileio.h). */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "fileio.h"

/* Largest buffer (file + terminator): lengths are uint32_t. */
#define HOST_FILE_MAX ((size_t)UINT32_MAX)

int host_read_file(const char *path, char **buf, uint32_t *len)
{
    FILE *f;
    char *p = NULL;
    size_t cap = 0, n = 0;
    int err = 0;

    *buf = NULL;
    *len = 0;
    if (!path) { errno = EINVAL; return -1; }
    f = fopen(path, "rb");
    if (!f) return -1;
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
            if (fgetc(f) != EOF) err = EFBIG;
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
        remove(path);
        errno = err;
        return -1;
    }
    return 0;
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
    default: return "unknown";
    }
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
    } else {
        return HOST_ERR_FORMAT;
    }
    if (host_read_file(path, &text, &len) != 0) return errno == ENOMEM ? HOST_ERR_OOM : HOST_ERR_IO;
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
    free(text);
    return st;
}

void host_mesh_free(host_mesh *hm)
{
    if (!hm) return;
    free(hm->mem);
    hm->mem = NULL;
}
