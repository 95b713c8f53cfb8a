/* SPDX-License-Identifier: MIT */
/* Checks shared by the fuzz targets (fuzz/fuzz_*.c). The same code runs under libFuzzer
 * (clang, make fuzz) and in the corpus replay of make test (gcc, fuzz/replay.c). Every
 * violated check prints what failed and calls abort(). Not part of the library: the
 * harness may use malloc and stdio. */
#ifndef FUZZ_CHECK_H
#define FUZZ_CHECK_H

#include <stddef.h>
#include <stdint.h>
#include "subd.h"

/* Each target defines its entry under this name; the replay renames them (-DFUZZ_ENTRY=...). */
#ifndef FUZZ_ENTRY
#define FUZZ_ENTRY LLVMFuzzerTestOneInput
#endif
int FUZZ_ENTRY(const uint8_t *data, size_t size);

/* Largest arena a target gives one call (bigger plans are only checked for their status). */
#define FZ_MAX_ARENA (16u << 20)
#define FZ_GUARD 64u

void fz_fail(const char *what, const char *detail, long a, long b);
#define FZ_CHECK(cond, detail, a, b) \
    do { if (!(cond)) fz_fail(#cond, (detail), (long)(a), (long)(b)); } while (0)

/* Status is SUBD_OK or one of the negative subd_status codes (extra: an allowed positive
 * value, e.g. a stream sink's return; 0 = none). */
void fz_status_known(int st, int extra, const char *call);

/* An arena of exactly `size` bytes in a malloc'd block followed by FZ_GUARD guard bytes. */
typedef struct fz_arena {
    uint8_t *block;
    uint32_t size;
    subd_arena a;
} fz_arena;
void fz_arena_open(fz_arena *fa, uint32_t size);
/* After a call: guard intact; on failure (st != 0) the arena is back at `mark`; on success
 * the peak above the mark is <= plan. */
void fz_arena_after(fz_arena *fa, int st, uint32_t mark, uint32_t plan, const char *call);
void fz_arena_close(fz_arena *fa);

/* Snapshot of bytes that must not change (input data, an input mesh's arena). */
typedef struct fz_snap {
    const uint8_t *p;
    size_t n;
    uint8_t *copy;
} fz_snap;
void fz_snap_take(fz_snap *s, const void *p, size_t n);
void fz_snap_check(const fz_snap *s, const char *call);
void fz_snap_free(fz_snap *s);

/* The validator: subd_mesh_build of m's own face list (and polylines) must succeed. With
 * same_adjacency, m's twin/vert_out/counts must equal the rebuilt ones. */
void fz_validate_mesh(const subd_mesh *m, int same_adjacency, const char *call);
/* Every coordinate finite (float32; always true in Q16.16). */
void fz_check_finite(const subd_real *p, uint32_t n, const char *call);

#endif
