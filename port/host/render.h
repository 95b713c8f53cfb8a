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

/* render_opts.edges */
#define RENDER_EDGES_AUTO (-1) /* default: edges unless the mesh is dense (below)          */
/* Auto edges are off when the mean projected length of the result's face edges is below
 * this many pixels: a 1-pixel dark line every few pixels turns the picture into a black
 * silhouette. */
#define RENDER_DENSE_PX 6.0
/* An input (render_opts.input) whose mean projected edge is below this many pixels would
 * hide the result under its lines: input and result are then drawn side by side. */
#define RENDER_INPUT_DENSE_PX 16.0

/* The colour of the input drawn over the result (render_opts.input): not a shade the
 * surface, its edges or its polylines can take, so tests can find it. */
#define RENDER_INPUT_R 235
#define RENDER_INPUT_G 90
#define RENDER_INPUT_B 0

typedef struct render_opts {
    int width, height;   /* pixels; 0 -> 800 x 600 */
    double yaw_deg;      /* rotation of the view about the up axis (y); default 30 */
    double pitch_deg;    /* elevation of the view; default 20 */
    int edges;           /* 1 = draw polygon edges, 0 = none, RENDER_EDGES_AUTO (default) */
    /* Optional: a second mesh (the input of the operation, its control net) drawn over the
     * shaded result as thin lines in the RENDER_INPUT colour (dashed where the result
     * hides them), its vertices as small squares; both meshes are framed together. A dense
     * input (RENDER_INPUT_DENSE_PX) is drawn shaded beside the result instead. */
    const render_mesh *input;
    /* Optional captions, top left in a built-in 5x7 font (upper case): the result's in dark
     * grey, the input's below it in the input colour. */
    const char *label;
    const char *input_label;
} render_opts;

/* What render_rgb_info decided, for the tool's report and the tests. */
typedef struct render_info {
    int edges_drawn;      /* the result's edges were drawn                                */
    double mean_edge_px;  /* mean projected length of the result's face edges (0: none)   */
} render_info;

void render_opts_default(render_opts *o);

/* Renders into a freshly allocated RGB8 image (*rgb, width*height*3, caller frees).
 * Returns 0, or -1 when out of memory. */
int render_rgb(const render_mesh *m, const render_opts *o, uint8_t **rgb, int *width, int *height);
/* The same, also filling *info when not NULL. */
int render_rgb_info(const render_mesh *m, const render_opts *o, uint8_t **rgb, int *width, int *height,
                    render_info *info);

/* Encodes an RGB8 image as PNG (zlib stored or simple compressed blocks, CRC32 and Adler-32)
 * into a freshly allocated buffer (*png, *len; caller frees). Returns 0 or -1. */
int png_encode_rgb(const uint8_t *rgb, int width, int height, uint8_t **png, uint32_t *len);

/* render_rgb + png_encode_rgb + write file. Returns 0, or -1 (errno set) on failure. */
int render_png_file(const char *path, const render_mesh *m, const render_opts *o);

/* Captions (render_text.c): a built-in 5x7 font, upper case, each font pixel a scale x
 * scale block, glyphs RENDER_GLYPH_W x RENDER_GLYPH_H pixels (gaps included) before
 * scaling. render_text draws s with its top left at (x, y) over a box of colour `box` one
 * font pixel larger than the text, clipped to the w x h image. */
#define RENDER_GLYPH_W 6
#define RENDER_GLYPH_H 9
int render_text_width(const char *s, int scale);
void render_text(uint8_t *rgb, int w, int h, int x, int y, int scale, const char *s, const uint8_t col[3],
                 const uint8_t box[3]);

uint32_t png_crc32(const uint8_t *p, uint32_t n);
uint32_t png_adler32(const uint8_t *p, uint32_t n);
#endif
