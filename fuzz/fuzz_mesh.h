/* SPDX-License-Identifier: MIT */
/* The small-mesh decoder shared by the scheme fuzz targets (fuzz_schemes.c, fuzz_sr48s.c):
 * input bytes are read through a cursor (0 past the end), and fz_decode_mesh turns them into
 * a template mesh (tetrahedron, octahedron, 3x3 grid, quad cube, fan, one or two triangles,
 * triangulated cube) with perturbed positions, or a random face list that is often invalid.
 * Not part of the library: the harness may use anything. */
#ifndef FUZZ_MESH_H
#define FUZZ_MESH_H
#include <stddef.h>
#include <stdint.h>
#include "subd.h"

typedef struct cur {
    const uint8_t *p;
    size_t n, i;
} cur;
static inline uint8_t u8(cur *c) { return c->i < c->n ? c->p[c->i++] : 0u; }
static inline int8_t s8(cur *c) { return (int8_t)u8(c); }

#define FZ_MAXV 16
#define FZ_MAXF 24
#define MAXV FZ_MAXV
#define MAXF FZ_MAXF
typedef struct fz_decoded {
    uint32_t nv, nf;
    subd_real pos[3 * FZ_MAXV];
    uint32_t fsize[FZ_MAXF];
    uint32_t idx[4 * FZ_MAXF];
} fz_decoded;

/* An integer base coordinate plus a perturbation byte (1/64 units); b = 0x7f gives a special
 * value chosen by sel (huge, tiny, zero; float32 also NaN and infinity). */
subd_real fz_coord(int base, uint8_t b, uint8_t sel);

/* The mesh the next bytes describe (positions last; may flip the first face). */
void fz_decode_mesh(cur *c, fz_decoded *m);

#endif
