/* SPDX-License-Identifier: MIT */
/* subd tool: the writers. OUTPUT by extension: .obj/.off/.xyz as text streamed to the file
 * through one fixed 64 KiB buffer (host_out, fileio.h): the bytes of the library's writers
 * (subd_obj_write, subd_off_write, with subd_real_format's numbers), but no copy of the text in
 * memory, so writing costs the mesh and 64 KiB. .png through the renderer; and the one
 * --stats JSON object on stdout.
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

int tool_render_view(const subd_mesh *m, render_mesh *rm, double **pos)
{
    uint32_t i;
    double *p = (double *)malloc(3u * (size_t)m->num_verts * sizeof *p + 1u);
    *pos = p;
    if (!p) return -1;
    for (i = 0; i < 3u * m->num_verts; i++) p[i] = host_real_to_double(m->pos[i]);
    memset(rm, 0, sizeof *rm);
    rm->num_verts = m->num_verts;
    rm->pos = p;
    rm->num_faces = m->num_faces;
    rm->face_start = m->face_start;
    rm->corner_vert = m->corner_vert;
    rm->num_lines = m->num_lines;
    rm->line_start = m->line_start;
    rm->line_vert = m->line_vert;
    return 0;
}

static int write_png(tool_run *r)
{
    render_mesh rm;
    double *pos;
    uint8_t *rgb = NULL, *png = NULL;
    uint32_t len = 0;
    int w = 0, h = 0, rc;

    if (tool_render_view(&r->out, &rm, &pos) != 0) return tool_out_of_memory();
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

/* Opens OUTPUT for a streamed text writer: the host_out (64 KiB buffer) or NULL after
 * reporting the failure in *rc. */
static host_out *out_open(tool_run *r, int *rc)
{
    host_out *o = (host_out *)malloc(sizeof *o);
    if (!o) {
        *rc = tool_out_of_memory();
        return NULL;
    }
    if (host_out_open(o, r->o.output) != 0) {
        free(o);
        *rc = write_failed(r->o.output);
        return NULL;
    }
    return o;
}

/* Closes OUTPUT (ok: the whole text went into o), sets out_bytes; the tool's exit status. */
static int out_finish(tool_run *r, host_out *o, int ok)
{
    int rc = host_out_close(o, ok);
    uint64_t n = o->bytes;
    free(o);
    if (rc != 0) return write_failed(r->o.output);
    r->out_bytes = n > UINT32_MAX ? UINT32_MAX : (uint32_t)n;
    return EXIT_OK;
}

/* Plain points for CNC use: "x y z" per line in the library's exact decimal form; the
 * points of each polyline in order with a blank line between polylines, or every vertex
 * when there are no polylines. */
static int write_xyz(tool_run *r)
{
    const subd_mesh *m = &r->out;
    uint32_t l, c, nl = m->num_lines ? m->num_lines : 1u;
    int rc = EXIT_OK, ok = 1;
    host_out *o = out_open(r, &rc);
    char *p;
    if (!o) return rc;
    for (l = 0; ok && l < nl; l++) {
        uint32_t s = m->num_lines ? m->line_start[l] : 0u;
        uint32_t e = m->num_lines ? m->line_start[l + 1u] : m->num_verts;
        if (l) {
            if (!(p = host_out_room(o, 1u))) { ok = 0; break; }
            *p = '\n';
            o->fill++;
        }
        for (c = s; c < e; c++) {
            uint32_t v = m->num_lines ? m->line_vert[c] : c;
            if (!(p = host_out_room(o, 96u))) { ok = 0; break; }
            o->fill += host_fmt_xyz(p, "", &m->pos[3u * v]);
        }
    }
    return out_finish(r, o, ok);
}

/* The library's OBJ text (src/obj.c: subd_obj_write, subd_obj_write_normals), written
 * record by record into the output buffer instead of being counted and formatted into
 * memory first: "# tinysubd", v (then vn when there are normals: vertex i has normal i),
 * f (1-based; "a//a" with normals), l. */
static int emit_obj(host_out *o, const subd_mesh *m, const subd_real *nrm)
{
    uint32_t v, f, c;
    char *p;
    if (!(p = host_out_room(o, 11u))) return 0;
    memcpy(p, "# tinysubd\n", 11u);
    o->fill += 11u;
    for (v = 0; v < m->num_verts; v++) {
        if (!(p = host_out_room(o, 96u))) return 0;
        o->fill += host_fmt_xyz(p, "v ", &m->pos[3u * v]);
    }
    for (v = 0; nrm && v < m->num_verts; v++) {
        if (!(p = host_out_room(o, 96u))) return 0;
        o->fill += host_fmt_xyz(p, "vn ", &nrm[3u * v]);
    }
    for (f = 0; f < m->num_faces + m->num_lines; f++) {
        const uint32_t *start = f < m->num_faces ? m->face_start : m->line_start;
        const uint32_t *vert = f < m->num_faces ? m->corner_vert : m->line_vert;
        uint32_t i = f < m->num_faces ? f : f - m->num_faces;
        if (!(p = host_out_room(o, 2u))) return 0;
        *p = f < m->num_faces ? 'f' : 'l';
        o->fill++;
        for (c = start[i]; c < start[i + 1u]; c++) {
            uint32_t n;
            if (!(p = host_out_room(o, 24u))) return 0;
            p[0] = ' ';
            n = 1u + host_fmt_u32(p + 1, vert[c] + 1u);
            if (nrm && f < m->num_faces) {
                p[n++] = '/';
                p[n++] = '/';
                n += host_fmt_u32(p + n, vert[c] + 1u);
            }
            o->fill += n;
        }
        if (!(p = host_out_room(o, 1u))) return 0;
        *p = '\n';
        o->fill++;
    }
    return 1;
}

/* The library's OFF text (src/off.c: subd_off_write): "OFF", the counts V F E, "x y z" per
 * vertex, "n i j k ..." per face (0-based). */
static int emit_off(host_out *o, const subd_mesh *m)
{
    uint32_t v, f, c, n;
    char *p;
    if (!(p = host_out_room(o, 40u))) return 0;
    memcpy(p, "OFF\n", 4u);
    n = 4u;
    n += host_fmt_u32(p + n, m->num_verts);
    p[n++] = ' ';
    n += host_fmt_u32(p + n, m->num_faces);
    p[n++] = ' ';
    n += host_fmt_u32(p + n, m->num_edges);
    p[n++] = '\n';
    o->fill += n;
    for (v = 0; v < m->num_verts; v++) {
        if (!(p = host_out_room(o, 96u))) return 0;
        o->fill += host_fmt_xyz(p, "", &m->pos[3u * v]);
    }
    for (f = 0; f < m->num_faces; f++) {
        if (!(p = host_out_room(o, 12u))) return 0;
        o->fill += host_fmt_u32(p, m->face_start[f + 1u] - m->face_start[f]);
        for (c = m->face_start[f]; c < m->face_start[f + 1u]; c++) {
            if (!(p = host_out_room(o, 12u))) return 0;
            p[0] = ' ';
            o->fill += 1u + host_fmt_u32(p + 1, m->corner_vert[c]);
        }
        if (!(p = host_out_room(o, 1u))) return 0;
        *p = '\n';
        o->fill++;
    }
    return 1;
}

static int write_mesh(tool_run *r)
{
    host_out *o;
    int rc = EXIT_OK, ok;
    if (r->o.out_format == HOST_FMT_OFF && r->out.num_lines)
        fprintf(stderr, "subd: warning: %s: OFF has no polylines; %lu polyline(s) not written\n",
                r->o.output, (unsigned long)r->out.num_lines);
    if (!(o = out_open(r, &rc))) return rc;
    /* with normals the OBJ text, whatever the extension (as the library-writer version did) */
    ok = (r->extra.normals || r->o.out_format == HOST_FMT_OBJ) ? emit_obj(o, &r->out, r->extra.normals)
                                                                : emit_off(o, &r->out);
    return out_finish(r, o, ok);
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
