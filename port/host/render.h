/* SPDX-License-Identifier: MIT */
/* Host-only picture output: a software rasteriser (flat shading, visible edges, automatic
 * framing) and an own PNG writer (no external library). */
#ifndef RENDER_H
#define RENDER_H
#include <stdint.h>

typedef struct render_mesh {
    uint32_t num_verts;
    const double *pos;          /* 3 * num_verts */
    uint32_t num_faces;
    const uint32_t *face_start; /* num_faces + 1 */
    const uint32_t *corner_vert;
    uint32_t num_lines;         /* polylines, drawn as dark 1-2 px lines */
    const uint32_t *line_start; /* num_lines + 1 */
    const uint32_t *line_vert;
} render_mesh;

typedef struct render_opts {
    int width, height;   /* pixels; 0 -> 800 x 600 */
    double yaw_deg;      /* rotation of the view about the up axis (y); default 30 */
    double pitch_deg;    /* elevation of the view; default 20 */
    int edges;           /* 1 = draw polygon edges (default) */
} render_opts;

void render_opts_default(render_opts *o);

/* Renders into a freshly allocated RGB8 image (*rgb, width*height*3, caller frees).
 * Returns 0, or -1 when out of memory. */
int render_rgb(const render_mesh *m, const render_opts *o, uint8_t **rgb, int *width, int *height);

/* Encodes an RGB8 image as PNG (zlib stored or simple compressed blocks, CRC32 and Adler-32)
 * into a freshly allocated buffer (*png, *len; caller frees). Returns 0 or -1. */
int png_encode_rgb(const uint8_t *rgb, int width, int height, uint8_t **png, uint32_t *len);

/* render_rgb + png_encode_rgb + write file. Returns 0, or -1 (errno set) on failure. */
int render_png_file(const char *path, const render_mesh *m, const render_opts *o);

uint32_t png_crc32(const uint8_t *p, uint32_t n);
uint32_t png_adler32(const uint8_t *p, uint32_t n);
#endif
