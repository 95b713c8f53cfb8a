/* SPDX-License-Identifier: MIT */
/* Point paths as text on memory buffers: plain ".xyz" lines and a plain G-code tool path,
 * for the point streams (subd_alpha.h "Streamed curves"). Numbers by subd_real_format
 * through src/text.c's sink, so the host and the device write the same bytes; two passes
 * (count, then write) by text.c's subd_text_run, as subd_obj_write, so a too-small buffer is
 * left untouched.
 *
 * G-code choices (the issue asks for plain G-code, no dialect): millimetres (G21) and
 * absolute coordinates (G90) in the header, a rapid move G0 to the first point, then one
 * linear move "G1 X Y Z" per point; the feed rate, when given, once on the first G1 (F is
 * modal). No spindle, tool or end commands: the caller's program wraps the path. The first
 * index tells a call in the middle of a stream where it is, so a path can be written in
 * pieces of any size with the same bytes as in one piece. */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "subd_alpha.h"
#include "text.h"

typedef struct path_job {
    const subd_point *p;
    uint32_t n, first, format;
    subd_real feed;
} path_job;

static void path_emit(const void *job, text_sink *k)
{
    const path_job *j = (const path_job *)job;
    uint32_t i;
    static const char *const axis[3] = {"X", " Y", " Z"};
    for (i = 0; i < j->n; i++) {
        uint32_t at = j->first + i, c;
        if (j->format == SUBD_PATH_XYZ) {
            for (c = 0; c < 3u; c++) {
                if (c) subd_sink_str(k, " ");
                subd_sink_real(k, j->p[i].pos[c]);
            }
            subd_sink_str(k, "\n");
            continue;
        }
        if (at == 0u) subd_sink_str(k, "G21\nG90\nG0 ");
        else
            subd_sink_str(k, "G1 ");
        for (c = 0; c < 3u; c++) {
            subd_sink_str(k, axis[c]);
            subd_sink_real(k, j->p[i].pos[c]);
        }
        if (at == 1u && j->feed > 0) {
            subd_sink_str(k, " F");
            subd_sink_real(k, j->feed);
        }
        subd_sink_str(k, "\n");
    }
}

int subd_path_write(const subd_point *p, uint32_t n, uint32_t first_index, uint32_t format, subd_real feed,
                    char *buf, uint32_t cap, uint32_t *len)
{
    path_job j;
    if (!len || (!p && n) || (format != SUBD_PATH_XYZ && format != SUBD_PATH_GCODE) ||
        !subd_real_is_finite(feed) || feed < 0)
        return SUBD_ERR_PARAM;
    j.p = p;
    j.n = n;
    j.first = first_index;
    j.format = format;
    j.feed = feed;
    return subd_text_run(path_emit, &j, buf, cap, len); /* text.c's size-then-write */
}
