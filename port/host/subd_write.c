/* SPDX-License-Identifier: MIT */
/* subd tool: the writers. OUTPUT by extension: .obj/.off through the library's writers
 * (sized by their counting call, then written in one piece), .png through the renderer,
 * .xyz as plain points; and the one --stats JSON object on stdout.
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include "subd_tool.h"
#include "host_real.h"

static int write_failed(const char *path)
{
    tool_error("cannot write '%s': %s", path, strerror(errno));
    return EXIT_OUTPUT;
}

static int write_png(tool_run *r)
{
    const subd_mesh *m = &r->out;
    render_mesh rm;
    double *pos;
    uint8_t *rgb = NULL, *png = NULL;
    uint32_t i, len = 0;
    int w = 0, h = 0, rc;

    pos = (double *)malloc(3u * (size_t)m->num_verts * sizeof *pos + 1u);
    if (!pos) return tool_out_of_memory();
    for (i = 0; i < 3u * m->num_verts; i++) pos[i] = host_real_to_double(m->pos[i]);
    rm.num_verts = m->num_verts;
    rm.pos = pos;
    rm.num_faces = m->num_faces;
    rm.face_start = m->face_start;
    rm.corner_vert = m->corner_vert;
    rm.num_lines = m->num_lines;
    rm.line_start = m->line_start;
    rm.line_vert = m->line_vert;
    rc = render_rgb(&rm, &r->o.ropt, &rgb, &w, &h);
    free(pos);
    if (rc != 0) return tool_out_of_memory();
    rc = png_encode_rgb(rgb, w, h, &png, &len);
    free(rgb);
    if (rc != 0) return tool_out_of_memory();
    rc = host_write_file(r->o.output, png, len);
    free(png);
    if (rc != 0) return write_failed(r->o.output);
    r->out_bytes = len;
    r->out_width = w;
    r->out_height = h;
    return EXIT_OK;
}

/* Plain points for CNC use: "x y z" per line in the library's exact decimal form; the
 * points of each polyline in order with a blank line between polylines, or every vertex
 * when there are no polylines. */
static int write_xyz(tool_run *r)
{
    const subd_mesh *m = &r->out;
    FILE *f = fopen(r->o.output, "w");
    uint32_t l, c, nl = m->num_lines ? m->num_lines : 1u;
    long n;
    if (!f) return write_failed(r->o.output);
    for (l = 0; l < nl; l++) {
        uint32_t s = m->num_lines ? m->line_start[l] : 0u;
        uint32_t e = m->num_lines ? m->line_start[l + 1u] : m->num_verts;
        if (l) fputc('\n', f);
        for (c = s; c < e; c++) {
            uint32_t v = m->num_lines ? m->line_vert[c] : c, k;
            for (k = 0; k < 3u; k++) {
                char b[32];
                uint32_t len = subd_real_format(m->pos[3u * v + k], b);
                fwrite(b, 1, len, f);
                fputc(k < 2u ? ' ' : '\n', f);
            }
        }
    }
    n = ftell(f);
    if (ferror(f) | (fclose(f) != 0)) return write_failed(r->o.output);
    r->out_bytes = n > 0 ? (uint32_t)n : 0u;
    return EXIT_OK;
}

static int write_mesh(tool_run *r)
{
    int (*writer)(const subd_mesh *, char *, uint32_t, uint32_t *) =
        (r->o.out_format == HOST_FMT_OBJ) ? subd_obj_write : subd_off_write;
    uint32_t len = 0;
    char *buf;
    int st = r->extra.normals ? subd_obj_write_normals(&r->out, r->extra.normals, NULL, 0, &len)
                              : writer(&r->out, NULL, 0, &len);
    if (st != SUBD_OK) {
        tool_error("%s: %s", r->o.output, subd_status_str(st));
        return st == SUBD_ERR_TOO_BIG ? EXIT_LIMIT : EXIT_OUTPUT;
    }
    if (r->o.out_format == HOST_FMT_OFF && r->out.num_lines)
        fprintf(stderr, "subd: warning: %s: OFF has no polylines; %lu polyline(s) not written\n",
                r->o.output, (unsigned long)r->out.num_lines);
    buf = (char *)malloc((size_t)len + 1u);
    if (!buf) return tool_out_of_memory();
    st = r->extra.normals ? subd_obj_write_normals(&r->out, r->extra.normals, buf, len, &len)
                          : writer(&r->out, buf, len, &len);
    if (st != SUBD_OK) {
        free(buf);
        tool_error("%s: %s", r->o.output, subd_status_str(st));
        return EXIT_OUTPUT;
    }
    st = host_write_file(r->o.output, buf, len);
    free(buf);
    if (st != 0) return write_failed(r->o.output);
    r->out_bytes = len;
    return EXIT_OK;
}

/* Writes OUTPUT in the format its extension names. */
int tool_write_output(tool_run *r)
{
    if (r->o.out_format == HOST_FMT_PNG) return write_png(r);
    if (r->o.out_format == HOST_FMT_XYZ) return write_xyz(r);
    return write_mesh(r);
}

/* --stats JSON */

static void json_string(FILE *f, const char *s)
{
    fputc('"', f);
    for (; *s; s++) {
        unsigned char c = (unsigned char)*s;
        if (c == '"' || c == '\\') fprintf(f, "\\%c", c);
        else if (c < 0x20) fprintf(f, "\\u%04x", c);
        else fputc(c, f);
    }
    fputc('"', f);
}

static void json_mesh_counts(FILE *f, const subd_mesh *m)
{
    fprintf(f, "\"vertices\":%lu,\"faces\":%lu,\"corners\":%lu,\"edges\":%lu,\"boundary_edges\":%lu,"
               "\"boundary_loops\":%lu,\"isolated\":%lu,\"polylines\":%lu",
            (unsigned long)m->num_verts, (unsigned long)m->num_faces, (unsigned long)m->num_corners,
            (unsigned long)m->num_edges, (unsigned long)m->num_boundary_edges,
            (unsigned long)m->num_boundary_loops, (unsigned long)m->num_isolated, (unsigned long)m->num_lines);
}

void tool_print_stats(FILE *f, const tool_run *r)
{
    fprintf(f, "{\"command\":");
    json_string(f, r->cmd->name);
    fprintf(f, ",\"scheme\":");
    if (r->cmd->scheme) json_string(f, r->cmd->scheme);
    else fprintf(f, "null");
    fprintf(f, ",\"levels\":%lu,\"arithmetic\":\"%s\",\"input\":{\"file\":",
            (unsigned long)((r->cmd->flags & CMD_LEVELS) ? r->o.levels : 0u), ARITHMETIC);
    json_string(f, r->o.input);
    fprintf(f, ",\"format\":\"%s\",\"bytes\":%lu,", host_format_name(r->in.format),
            (unsigned long)r->in.file_bytes);
    json_mesh_counts(f, &r->in.mesh);
    fprintf(f, "},\"output\":");
    if (r->o.output) {
        fprintf(f, "{\"file\":");
        json_string(f, r->o.output);
        fprintf(f, ",\"format\":\"%s\",\"bytes\":%lu,", host_format_name(r->o.out_format),
                (unsigned long)r->out_bytes);
        json_mesh_counts(f, &r->out);
        fprintf(f, "}");
    } else {
        fprintf(f, "null");
    }
    fprintf(f, ",\"arena_budget\":");
    if (r->o.has_budget) fprintf(f, "%lu", (unsigned long)r->o.budget);
    else fprintf(f, "null");
    fprintf(f, ",\"arena_planned\":%lu,\"arena_used\":%lu,\"time_ms\":%.3f", (unsigned long)r->planned,
            (unsigned long)r->used, r->lib_ns / 1e6);
    if (r->extra.json[0]) fprintf(f, ",%s", r->extra.json);
    fprintf(f, "}\n");
}
