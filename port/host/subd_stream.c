/* SPDX-License-Identifier: MIT */
/* subd tool: the triangle streams' output, for every scheme. A scheme module (cmd_loop.c,
 * cmd_sr48.c) hands over a tool_stream (subd_tool.h): one pass of its triangles into a
 * subd_tri_sink (include/subd.h) and its counts at the level; the sinks here take them, by
 * OUTPUT's format, and name no scheme:
 *   .stl   binary STL streamed straight to the file through one fixed 64 KiB buffer, so the
 *          memory is independent of the output. The triangle count (Loop: 4^L F) is written
 *          first (known in advance, or for an adaptive cut found by a counting pass, so OUTPUT
 *          may be a pipe; checked against the emitted count). The 80-byte header names the
 *          command's scheme (command.canonical).
 *          Facet normal: the unit normal of the triangle's positions (cross product in
 *          double; (0,0,0) for a degenerate triangle), also with --limit: the per-vertex
 *          limit normals go to OBJ vn records only.
 *   .obj   gathered on the host by global vertex id: an id -> number table over the id space
 *          (4 bytes per id, V + C (2^L - 1) + F (2^L - 1)(2^L - 2) / 2 ids); each vertex (and
 *          with --limit its vn) is written the first time a triangle uses it, just before that
 *          f line, so vertices are numbered in first-use order; the text is streamed.
 *   .off   needs its counts first: vertices and triangles are gathered in host memory and
 *          written at the end by the tool's OFF writer (subd_write.c, streamed to the file).
 *   none   (--stats without -o) a counting sink, for timing the stream alone.
 * Coordinates in .obj/.off are subd_real_format's, the bytes `subd loop` writes for the same
 * vertex; in .stl float32 (Q16.16: x / 65536.0 rounded to float). Isolated control vertices
 * are in no triangle, so they are not written. Every sink counts the triangles and hashes the
 * position bits (FNV-1a 32 over the little-endian bytes of each coordinate's bits, in emission
 * order), reported by --stats as "checksum": the hash of test/test_loop_stream.c and of the
 * firmware demo's checksum sink (port/cortex-m/demo_mesh.h), so host and device agree.
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "subd_tool.h"
#include "host_real.h"

#define STREAM_BUF 65536u
/* Sink statuses: positive, so the library's streams return them unchanged (subd.h). */
#define SINK_WRITE 1 /* OUTPUT could not be written (errno in err)                       */
#define SINK_COUNT 2 /* more ids, vertices or triangles than the closed forms say        */

typedef struct stream_sink {
    FILE *f;           /* OUTPUT (.stl, .obj), else NULL                              */
    int err;           /* errno of the failed write                                   */
    uint32_t fill;     /* bytes in buf                                                */
    uint64_t bytes;    /* bytes written to f                                          */
    uint64_t tris;     /* triangles received                                          */
    uint32_t hash;
    int limit;
    uint32_t *index;   /* .obj/.off: id -> 1 + the vertex's number, 0 before first use */
    uint64_t ids;
    uint32_t nv, max_v;
    subd_real *pos;    /* .off: 3 * max_v gathered positions                          */
    uint32_t *corner;  /* .off: 3 * max_t corners                                     */
    uint64_t max_t;
    unsigned char buf[STREAM_BUF];
} stream_sink;

static int out_flush(stream_sink *s)
{
    errno = 0;
    if (s->fill && fwrite(s->buf, 1, s->fill, s->f) != s->fill) {
        s->err = errno ? errno : EIO;
        return SINK_WRITE;
    }
    s->bytes += s->fill;
    s->fill = 0;
    return 0;
}

/* n bytes of room at buf + fill (flushing first when needed), or NULL on a write error. */
static unsigned char *out_room(stream_sink *s, uint32_t n)
{
    if (s->fill + n > STREAM_BUF && out_flush(s)) return NULL;
    return s->buf + s->fill;
}

static void hash_tri(stream_sink *s, const subd_tri *t)
{
    uint32_t h = s->hash, c, k, i;
    for (c = 0; c < 3u; c++)
        for (k = 0; k < 3u; k++) {
            uint32_t w = subd_real_bits(t->pos[c][k]);
            for (i = 0; i < 4u; i++) h = (h ^ ((w >> (8u * i)) & 0xffu)) * 16777619u;
        }
    s->hash = h;
    s->tris++;
    if (!(s->tris & 0xfffu)) progress_update(s->tris, s->max_t); /* progress.h: stores a number */
}

static int count_tri(void *ctx, const subd_tri *t)
{
    hash_tri((stream_sink *)ctx, t);
    return 0;
}

/* ------------------------------------------------------------------------------------ */
/* Binary STL                                                                             */

static void put_u32le(unsigned char *p, uint32_t v)
{
    p[0] = (unsigned char)(v & 0xffu);
    p[1] = (unsigned char)((v >> 8) & 0xffu);
    p[2] = (unsigned char)((v >> 16) & 0xffu);
    p[3] = (unsigned char)(v >> 24);
}

static void put_f32le(unsigned char *p, double x)
{
    float f = (float)x;
    uint32_t u;
    memcpy(&u, &f, sizeof u);
    put_u32le(p, u);
}

/* One facet: normal, three vertices (float32 LE), attribute 0. */
static int stl_tri(void *ctx, const subd_tri *t)
{
    stream_sink *s = (stream_sink *)ctx;
    unsigned char *o = out_room(s, 50u);
    double p[3][3], u[3], v[3], n[3], len;
    uint32_t c, k;
    if (!o) return SINK_WRITE;
    hash_tri(s, t);
    for (c = 0; c < 3u; c++)
        for (k = 0; k < 3u; k++) p[c][k] = host_real_to_double(t->pos[c][k]);
    for (k = 0; k < 3u; k++) {
        u[k] = p[1][k] - p[0][k];
        v[k] = p[2][k] - p[0][k];
    }
    n[0] = u[1] * v[2] - u[2] * v[1];
    n[1] = u[2] * v[0] - u[0] * v[2];
    n[2] = u[0] * v[1] - u[1] * v[0];
    len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (k = 0; k < 3u; k++) put_f32le(o + 4u * k, len > 0.0 ? n[k] / len : 0.0);
    for (c = 0; c < 3u; c++)
        for (k = 0; k < 3u; k++) put_f32le(o + 12u + 12u * c + 4u * k, p[c][k]);
    o[48] = 0;
    o[49] = 0;
    s->fill += 50u;
    return 0;
}

/* 80-byte header (not starting with "solid", which would announce ASCII STL) and the
 * triangle count. */
static int stl_begin(stream_sink *s, const tool_run *r, uint32_t tris)
{
    char head[96];
    unsigned char *p = out_room(s, 84u);
    int n = snprintf(head, sizeof head, "tinysubd %s stream, level %lu, %s%s", r->cmd->canonical,
                     (unsigned long)r->o.levels, ARITHMETIC, s->limit ? ", limit" : "");
    if (!p) return SINK_WRITE;
    memset(p, ' ', 80u);
    memcpy(p, head, n > 80 ? 80u : (size_t)n);
    put_u32le(p + 80, tris);
    s->fill += 84u;
    return 0;
}

/* ------------------------------------------------------------------------------------ */
/* .obj and .off: vertices gathered by id                                                 */

/* The vertex number (1-based) of id; *fresh is 1 when this is its first use. */
static int gather_id(stream_sink *s, uint64_t id, uint32_t *num, int *fresh)
{
    if (id >= s->ids) return SINK_COUNT;
    *fresh = 0;
    if (!s->index[id]) {
        if (s->nv >= s->max_v) return SINK_COUNT;
        s->index[id] = ++s->nv;
        *fresh = 1;
    }
    *num = s->index[id];
    return 0;
}

static int obj_tri(void *ctx, const subd_tri *t)
{
    stream_sink *s = (stream_sink *)ctx;
    uint32_t c, num[3], n = 0;
    char *o;
    int fresh, st;
    hash_tri(s, t);
    for (c = 0; c < 3u; c++) {
        if ((st = gather_id(s, t->id[c], &num[c], &fresh)) != 0) return st;
        if (!fresh) continue;
        if (!(o = (char *)out_room(s, 160u))) return SINK_WRITE;
        n = host_fmt_xyz(o, "v ", t->pos[c]);
        if (s->limit) n += host_fmt_xyz(o + n, "vn ", t->normal[c]);
        s->fill += n;
    }
    if (!(o = (char *)out_room(s, 80u))) return SINK_WRITE;
    n = 0;
    o[n++] = 'f';
    for (c = 0; c < 3u; c++) {
        o[n++] = ' ';
        n += host_fmt_u32(o + n, num[c]);
        if (s->limit) {
            o[n++] = '/';
            o[n++] = '/';
            n += host_fmt_u32(o + n, num[c]);
        }
    }
    o[n++] = '\n';
    s->fill += n;
    return 0;
}

static int off_tri(void *ctx, const subd_tri *t)
{
    stream_sink *s = (stream_sink *)ctx;
    uint64_t j = s->tris;
    uint32_t c, num;
    int fresh, st;
    if (j >= s->max_t) return SINK_COUNT;
    hash_tri(s, t);
    for (c = 0; c < 3u; c++) {
        if ((st = gather_id(s, t->id[c], &num, &fresh)) != 0) return st;
        if (fresh) memcpy(&s->pos[3u * (num - 1u)], t->pos[c], 3u * sizeof(subd_real));
        s->corner[3u * j + c] = num - 1u;
    }
    return 0;
}

/* ------------------------------------------------------------------------------------ */
/* The run                                                                                */

static uint32_t sat32(uint64_t v) { return v > UINT32_MAX ? UINT32_MAX : (uint32_t)v; }

/* Closes OUTPUT (removing a partial regular file on failure: never a device or a pipe). */
static int out_close(stream_sink *s, const char *path, int regular, int ok)
{
    int err = 0;
    if (!s->f) return ok ? 0 : SINK_WRITE;
    if (ok && out_flush(s) != 0) {
        ok = 0;
        err = s->err;
    }
    errno = 0;
    if (fclose(s->f) != 0 && ok) {
        ok = 0;
        err = errno ? errno : EIO;
    }
    s->f = NULL;
    if (!ok && regular) remove(path);
    if (err) s->err = err;
    return ok ? 0 : SINK_WRITE;
}

static int stream_limit(const char *what, const char *path)
{
    tool_error("%s: %s", path, what);
    return EXIT_LIMIT;
}

/* Allocates the gathering tables of .obj/.off; the .off arrays go in r->extra.host_mem
 * (freed at exit) since r->out points into them for the writer. */
static int gather_alloc(tool_run *r, stream_sink *s, const stream_counts *c)
{
    size_t t = (size_t)c->tris;
    s->index = (uint32_t *)calloc((size_t)c->ids + 1u, sizeof *s->index);
    if (!s->index) return tool_out_of_memory();
    if (r->o.out_format == HOST_FMT_OFF) {
        r->extra.host_mem = malloc(3u * (size_t)s->max_v * sizeof(subd_real) + (4u * t + 1u) * sizeof(uint32_t));
        if (!r->extra.host_mem) return tool_out_of_memory();
        s->pos = (subd_real *)r->extra.host_mem;
        s->corner = (uint32_t *)(void *)(s->pos + 3u * (size_t)s->max_v);
    }
    return EXIT_OK;
}

/* The triangle count of a stream that chooses its own cut (an adaptive cut: STL's header
 * needs it first and OUTPUT may be a pipe, so it cannot be patched afterwards), by one pass
 * into a counting sink. The one home of the tool's counting passes. */
static int stream_count_tri(void *ctx, const subd_tri *t)
{
    (void)t;
    ++*(uint64_t *)ctx;
    return 0;
}

int tool_stream_count(tool_run *r, subd_arena *a, const tool_stream *ts, subd_diag *d, uint64_t *n)
{
    subd_tri_sink sink;
    double t0 = host_now_ns();
    int st;
    *n = 0;
    sink.tri = stream_count_tri;
    sink.ctx = n;
    st = ts->pass(ts->ctx, a, &sink, d);
    r->lib_ns += host_now_ns() - t0;
    return st;
}

static int stream_into(tool_run *r, subd_arena *a, subd_diag *d, stream_sink *s, const tool_stream *ts)
{
    const tool_opts *o = &r->o;
    const stream_counts *c = &ts->c;
    host_format fmt = o->output ? o->out_format : HOST_FMT_UNKNOWN;
    subd_tri_sink sink;
    struct stat sb;
    int st = 0, regular = 0;
    double t0;
    uint64_t stl_tris = c->tris;
    if (fmt == HOST_FMT_STL && c->tris > UINT32_MAX && !c->tris_bound)
        return stream_limit("too many triangles for STL's 32-bit count", o->output);
    if ((fmt == HOST_FMT_OBJ || fmt == HOST_FMT_OFF) &&
        (c->verts >= UINT32_MAX || c->ids >= SIZE_MAX / 8u || (fmt == HOST_FMT_OFF && c->tris > UINT32_MAX / 4u)))
        return stream_limit("too many vertices for indexed output (.stl has no limit but 2^32 triangles)",
                            o->output);
    s->limit = ts->limit;
    s->hash = 2166136261u;
    s->ids = c->ids;
    s->max_v = sat32(c->verts);
    s->max_t = c->tris;
    if ((fmt == HOST_FMT_OBJ || fmt == HOST_FMT_OFF) && (st = gather_alloc(r, s, c)) != EXIT_OK) return st;
    if (fmt == HOST_FMT_STL && c->tris_bound) {
        /* an adaptive cut to .stl: the header's count first, by a counting pass */
        if ((st = tool_stream_count(r, a, ts, d, &stl_tris)) != 0) return st;
    }
    if (fmt == HOST_FMT_STL || fmt == HOST_FMT_OBJ) {
        if (!(s->f = fopen(o->output, "wb"))) {
            tool_error("cannot write '%s': %s", o->output, strerror(errno));
            return EXIT_OUTPUT;
        }
        regular = fstat(fileno(s->f), &sb) == 0 && S_ISREG(sb.st_mode);
        if (fmt == HOST_FMT_STL) st = stl_begin(s, r, (uint32_t)stl_tris);
        else {
            s->fill = 11u;
            memcpy(s->buf, "# tinysubd\n", s->fill);
        }
    }
    sink.tri = fmt == HOST_FMT_STL ? stl_tri : fmt == HOST_FMT_OBJ ? obj_tri : fmt == HOST_FMT_OFF ? off_tri : count_tri;
    sink.ctx = s;
    if (st == 0) {
        t0 = host_now_ns();
        st = ts->pass(ts->ctx, a, &sink, d);
        r->lib_ns += host_now_ns() - t0;
    }
    if (st == 0 && (c->tris_bound ? s->tris > c->tris : s->tris != c->tris)) st = SINK_COUNT;
    if (st == 0 && s->index && c->verts_exact && s->nv != c->verts) st = SINK_COUNT;
    if (out_close(s, o->output, regular, st == 0) != 0 && st == 0) st = SINK_WRITE;
    if (st < 0) return st; /* the library's status: subd_main.c reports it */
    if (st == SINK_WRITE) {
        tool_error("cannot write '%s': %s", o->output, strerror(s->err));
        return EXIT_OUTPUT;
    }
    if (st != 0) {
        fprintf(stderr, "subd: internal error: the stream gave %llu triangles, %lu vertices; expected %llu, %llu\n",
                (unsigned long long)s->tris, (unsigned long)s->nv, (unsigned long long)c->tris,
                (unsigned long long)c->verts);
        return EXIT_OUTPUT;
    }
    r->out_bytes = sat32(s->bytes);
    return 0;
}

int tool_stream_write(tool_run *r, subd_arena *a, tool_stream *ts, subd_diag *d, stream_result *res)
{
    const subd_mesh *in = &r->in.mesh;
    stream_counts c = ts->c;
    stream_sink *s = (stream_sink *)calloc(1, sizeof *s);
    subd_mesh *m = &r->out;
    uint32_t k;
    int st;
    memset(res, 0, sizeof *res);
    if (!s) return tool_out_of_memory();
    st = stream_into(r, a, d, s, ts);
    if (!c.verts_exact) c.verts = s->nv;
    if (c.tris_bound) c.tris = s->tris; /* an adaptive cut: what was cut */
    memset(m, 0, sizeof *m);
    m->num_verts = sat32(c.verts);
    m->num_faces = sat32(c.tris);
    m->num_corners = sat32(3u * c.tris);
    m->num_edges = sat32(c.edges);
    m->num_boundary_edges = sat32(c.boundary_edges);
    m->num_boundary_loops = in->num_boundary_loops;
    if (st == 0 && r->o.output && r->o.out_format == HOST_FMT_OFF) {
        /* the gathered mesh, through the library's OFF writer */
        m->pos = s->pos;
        m->corner_vert = s->corner;
        m->face_start = s->corner + 3u * (size_t)m->num_faces;
        for (k = 0; k <= m->num_faces; k++) m->face_start[k] = 3u * k;
        st = tool_write_output(r);
    }
    res->tris = s->tris;
    res->hash = s->hash;
    res->verts = s->nv;
    free(s->index);
    free(s);
    return st;
}
