/* SPDX-License-Identifier: MIT */
/* The firmware demo's streaming input and checksum, shared by port/cortex-m/demo.c (on the
 * device) and bench/bench.c (`bench -s demostream`, the host check), so both compute the
 * same bits from the same code.
 *
 * The control mesh is a geodesic sphere: every face of the icosahedron (vertices
 * (0, +-1, +-p) cyclically, p = 1.618, as the demo's OBJ text) cut into DEMO_GEO_FREQ^2
 * triangles on its barycentric lattice, the lattice points projected onto the unit sphere.
 * Lattice points are found and shared in integer coordinates (exact); the projection is
 * subd_real arithmetic only (subd_from_int, subd_div, subd_mul, subd_sqrt), so float32 and
 * Q16.16 each give one set of bits on every target. Frequency 5: 252 vertices, 500 faces,
 * 750 edges, closed, the 12 icosahedron corners of valence 5 and the rest of valence 6.
 *
 * The checksum is 32-bit FNV-1a over the four little-endian bytes of subd_real_bits of every
 * emitted position coordinate (corner 0 x y z, corner 1, corner 2), triangle by triangle in
 * emission order, starting from the FNV offset basis 2166136261 (the tool's --stats
 * "checksum"): the one checksum sink of demo.c, demo_sr48.c and demo_pipe.c. Header-only
 * (static inline: a file uses what it needs), no heap. */
#ifndef DEMO_MESH_H
#define DEMO_MESH_H

#include "subd.h"

#define DEMO_GEO_FREQ 5u
#define DEMO_GEO_FACES (20u * DEMO_GEO_FREQ * DEMO_GEO_FREQ)      /* 500 */
#define DEMO_GEO_VERTS (10u * DEMO_GEO_FREQ * DEMO_GEO_FREQ + 2u) /* 252 */
#define DEMO_GEO_MAX_VALENCE 6u
#define DEMO_STREAM_LEVELS 6u
#define DEMO_FNV_BASIS 2166136261u
#define DEMO_FNV_PRIME 16777619u

typedef struct demo_geo {
    int32_t ip[3u * DEMO_GEO_VERTS];  /* integer lattice coordinates (sharing test)   */
    subd_real pos[3u * DEMO_GEO_VERTS];
    uint32_t index[3u * DEMO_GEO_FACES];
    uint32_t num_verts;
} demo_geo;

/* Builds the geodesic sphere's face list in g (fl points into g). Returns SUBD_OK, or
 * SUBD_ERR_RANGE if the projection overflowed (it cannot: |coordinates| < 2). */
static inline int demo_geo_build(demo_geo *g, subd_face_list *fl)
{
    /* the icosahedron of demo.c's OBJ text, times 1000, and its 20 faces (0-based) */
    static const int16_t ico_v[12][3] = {
        {0, 1000, 1618},  {0, -1000, 1618},  {0, 1000, -1618}, {0, -1000, -1618},
        {1000, 1618, 0},  {-1000, 1618, 0},  {1000, -1618, 0}, {-1000, -1618, 0},
        {1618, 0, 1000},  {-1618, 0, 1000},  {1618, 0, -1000}, {-1618, 0, -1000}};
    static const uint8_t ico_f[20][3] = {
        {0, 1, 8},  {0, 9, 1},  {0, 8, 4},   {0, 4, 5},  {0, 5, 9},  {1, 6, 8},  {1, 7, 6},
        {1, 9, 7},  {2, 3, 11}, {2, 10, 3},  {2, 4, 10}, {2, 5, 4},  {2, 11, 5}, {3, 10, 6},
        {3, 6, 7},  {3, 7, 11}, {4, 8, 10},  {5, 11, 9}, {6, 10, 8}, {7, 9, 11}};
    const uint32_t n = DEMO_GEO_FREQ;
    uint32_t f, i, j, k, nf = 0, ovf = 0;
    uint32_t lat[(DEMO_GEO_FREQ + 1u) * (DEMO_GEO_FREQ + 1u)]; /* vertex of lattice point (i, j) */
    subd_real scale = subd_from_int((int32_t)(1000u * n), &ovf);
    g->num_verts = 0;
    for (f = 0; f < 20u; f++) {
        const int16_t *a = ico_v[ico_f[f][0]], *b = ico_v[ico_f[f][1]], *c = ico_v[ico_f[f][2]];
        for (i = 0; i <= n; i++)
            for (j = 0; i + j <= n; j++) {
                int32_t p[3];
                uint32_t v;
                for (k = 0; k < 3u; k++)
                    p[k] = (int32_t)(n - i - j) * a[k] + (int32_t)i * b[k] + (int32_t)j * c[k];
                for (v = 0; v < g->num_verts; v++) /* shared with an earlier face? (exact) */
                    if (g->ip[3u * v] == p[0] && g->ip[3u * v + 1u] == p[1] && g->ip[3u * v + 2u] == p[2]) break;
                if (v == g->num_verts) {
                    subd_real x[3], len;
                    subd_acc s = subd_acc_zero();
                    if (v == DEMO_GEO_VERTS) return SUBD_ERR_RANGE; /* cannot happen */
                    for (k = 0; k < 3u; k++) {
                        g->ip[3u * v + k] = p[k];
                        x[k] = subd_div(subd_from_int(p[k], &ovf), scale, &ovf);
                    }
                    for (k = 0; k < 3u; k++) s = subd_acc_add(s, x[k], x[k]);
                    len = subd_sqrt(subd_acc_real(s, &ovf));
                    for (k = 0; k < 3u; k++) g->pos[3u * v + k] = subd_div(x[k], len, &ovf);
                    g->num_verts++;
                }
                lat[i * (n + 1u) + j] = v;
            }
        for (i = 0; i < n; i++)
            for (j = 0; i + j < n; j++) {
                /* "up" triangle (i, j) (i+1, j) (i, j+1), oriented as the icosahedron face */
                g->index[3u * nf] = lat[i * (n + 1u) + j];
                g->index[3u * nf + 1u] = lat[(i + 1u) * (n + 1u) + j];
                g->index[3u * nf + 2u] = lat[i * (n + 1u) + j + 1u];
                nf++;
                if (i + j + 2u <= n) { /* "down" triangle (i+1, j) (i+1, j+1) (i, j+1) */
                    g->index[3u * nf] = lat[(i + 1u) * (n + 1u) + j];
                    g->index[3u * nf + 1u] = lat[(i + 1u) * (n + 1u) + j + 1u];
                    g->index[3u * nf + 2u] = lat[i * (n + 1u) + j + 1u];
                    nf++;
                }
            }
    }
    fl->num_verts = g->num_verts;
    fl->pos = g->pos;
    fl->num_faces = nf;
    fl->face_size = 0;
    fl->index = g->index;
    fl->num_lines = 0;
    fl->line_size = 0;
    fl->line_index = 0;
    return ovf ? SUBD_ERR_RANGE : SUBD_OK;
}

/* The checksum sink's state: ctx of demo_hash_tri. */
typedef struct demo_hash {
    uint32_t h;
    uint32_t tris;
} demo_hash;

static inline void demo_hash_init(demo_hash *s)
{
    s->h = DEMO_FNV_BASIS;
    s->tris = 0;
}

/* 32-bit FNV-1a of one triangle's nine coordinates (little-endian bytes of their bits):
 * corners c[0], c[1], c[2], three coordinates each. */
static inline uint32_t demo_hash_pos(uint32_t h, const subd_real *const c[3])
{
    uint32_t i, k, b;
    for (i = 0; i < 3u; i++)
        for (k = 0; k < 3u; k++) {
            uint32_t w = subd_real_bits(c[i][k]);
            for (b = 0; b < 4u; b++) {
                h ^= (w >> (8u * b)) & 0xffu;
                h *= DEMO_FNV_PRIME;
            }
        }
    return h;
}

static inline int demo_hash_tri(void *ctx, const subd_loop_tri *t)
{
    demo_hash *s = (demo_hash *)ctx;
    const subd_real *c[3];
    c[0] = t->pos[0];
    c[1] = t->pos[1];
    c[2] = t->pos[2];
    s->h = demo_hash_pos(s->h, c);
    s->tris++;
    return 0;
}

/* The cheapest sink (counts): for the stream's own instruction count. */
static inline int demo_count_tri(void *ctx, const subd_loop_tri *t)
{
    (void)t;
    ++*(uint32_t *)ctx;
    return 0;
}

#endif
