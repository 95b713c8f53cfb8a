/* SPDX-License-Identifier: MIT */
/* The streaming Loop tests' shared comparison (loop_cmp.c): shapes, the comparing sink and
 * lc_compare_one, used by test_loop_stream.c and test_loop_tiles.c. */
#ifndef TEST_LOOP_CMP_H
#define TEST_LOOP_CMP_H
#include "harness.h"

enum { S_TET, S_CUBE_CREASE, S_ICO, S_HEXFAN, S_FAN64, S_GRID_CREASE, S_ISO, S_TORUS, S_TORUS_CREASE, S_COUNT };
#define S_DEVICE S_TORUS /* shapes 0..S_DEVICE-1 run on the device too, the rest on the host */

int lc_load_text(subd_arena *a, const char *txt, subd_mesh *m);
int lc_load_file(subd_arena *a, const char *name, subd_mesh *m);
/* Creases on every `every`-th interior edge (both halves) and two corner tags. */
void lc_tag_features(subd_mesh *m, uint32_t every);
int lc_make_shape(int id, subd_arena *a, subd_mesh *m);

/* The sink of the comparison: triangle j against face j of subd_loop's output. */
typedef struct cmp_sink {
    const subd_mesh *ref;
    const subd_real *lpos, *lnrm; /* limit mode: subd_loop_limit of ref (else NULL)     */
    uint64_t *v2id;   /* ref vertex -> id seen for it, UINT64_MAX before */
    uint32_t j, bad_pos, bad_id, stop_after;
    uint32_t hash;
} cmp_sink;
int lc_cmp_tri(void *ctx, const subd_loop_tri *t);
/* s and sink set up to compare with ref from its first face (v2id: ref->num_verts entries,
 * cleared here; stop_after: the sink's stop, 0 none; hash: the FNV-1a start). */
void lc_sink_init(cmp_sink *s, subd_loop_sink *sink, const subd_mesh *ref, uint64_t *v2id, uint32_t stop_after,
                  uint32_t hash);
/* A sink that counts the triangles (ctx: a uint32_t). */
int lc_count_tri(void *ctx, const subd_loop_tri *t);

/* Streams compared and cases skipped (the arena could not hold subd_loop's output). */
extern uint32_t lc_streams, lc_skipped;

#if H_HOST
/* The host compares the bigger cases (the torus at level 4: 5.5 MB of subd_loop output). */
#define LC_BIG_ARENA_BYTES (24u * 1024u * 1024u)
extern uint8_t lc_big_arena[LC_BIG_ARENA_BYTES];
#define CMP_BUF lc_big_arena
#define CMP_BYTES LC_BIG_ARENA_BYTES
#else
#define CMP_BUF h_arena_buf
#define CMP_BYTES H_ARENA_BYTES
#endif

/* Streams `in` at `levels` with rule b and compares with subd_loop. Returns 0 when the
 * arena cannot hold subd_loop's output (the case is skipped and counted). */
int lc_compare_one(subd_arena *a, const subd_mesh *in, uint32_t levels, subd_loop_boundary b, uint32_t flags,
                   uint32_t *hash);

#endif
