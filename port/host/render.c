/* SPDX-License-Identifier: MIT */
/* Host-only software rasteriser: automatic framing, orthographic view (yaw about y, then
 * pitch about x), z-buffer, flat Lambert shading with a headlight plus ambient, back faces
 * in a different tint, depth-tested dark edges, polylines on top. Deterministic: plain
 * double arithmetic in a fixed order, no threads, no clocks.
 *
 * Pictures that show what an operation did: an optional input mesh (the control net) is
 * framed together with the result and drawn over it in one colour no shade can take
 * (thick where visible, dashed where the result hides it), and captions are drawn in a
 * built-in 5x7 font (render_text.c). Edges of a dense result are left out automatically (a dark line
 * every few pixels is a black silhouette, not a picture): the threshold is the mean
 * projected edge length, RENDER_DENSE_PX. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "render.h"

#define BG_R 242
#define BG_G 242
#define BG_B 240
#define MARGIN 0.05
#define MAX_DIM 16384

void render_opts_default(render_opts *o)
{
    if (!o) return;
    o->width = 800;
    o->height = 600;
    o->yaw_deg = 30.0;
    o->pitch_deg = 20.0;
    o->edges = RENDER_EDGES_AUTO;
    o->input = 0;
    o->label = 0;
    o->input_label = 0;
}

typedef struct canvas {
    int w, h;
    uint8_t *rgb;
    double *z; /* larger = nearer the viewer; -HUGE_VAL = empty */
} canvas;

typedef struct pv {
    double x, y, z; /* screen x, y (pixels, y down), depth (larger = nearer) */
    int ok;         /* finite input */
    int used;       /* referenced by a drawable face or polyline: takes part in framing */
} pv;

static void put_px(canvas *c, int x, int y, const uint8_t col[3])
{
    uint8_t *p;
    if (x < 0 || y < 0 || x >= c->w || y >= c->h) return;
    p = c->rgb + ((size_t)y * (size_t)c->w + (size_t)x) * 3u;
    p[0] = col[0];
    p[1] = col[1];
    p[2] = col[2];
}

static double edge_fn(double ax, double ay, double bx, double by, double px, double py)
{
    return (bx - ax) * (py - ay) - (by - ay) * (px - ax);
}

static void fill_tri(canvas *c, const pv *a, const pv *b, const pv *d, const uint8_t col[3])
{
    double area = edge_fn(a->x, a->y, b->x, b->y, d->x, d->y);
    double minx, maxx, miny, maxy, inv;
    int x0, x1, y0, y1, x, y;
    if (!(area != 0.0) || !isfinite(area)) return;
    inv = 1.0 / area;
    minx = fmin(a->x, fmin(b->x, d->x));
    maxx = fmax(a->x, fmax(b->x, d->x));
    miny = fmin(a->y, fmin(b->y, d->y));
    maxy = fmax(a->y, fmax(b->y, d->y));
    if (maxx < 0.0 || maxy < 0.0 || minx > (double)c->w || miny > (double)c->h) return;
    x0 = minx < 0.0 ? 0 : (int)floor(minx);
    y0 = miny < 0.0 ? 0 : (int)floor(miny);
    x1 = maxx > (double)(c->w - 1) ? c->w - 1 : (int)ceil(maxx);
    y1 = maxy > (double)(c->h - 1) ? c->h - 1 : (int)ceil(maxy);
    for (y = y0; y <= y1; y++) {
        double py = (double)y + 0.5;
        for (x = x0; x <= x1; x++) {
            double px = (double)x + 0.5;
            /* Barycentric weights, normalised so that inside means all >= 0. */
            double w0 = edge_fn(b->x, b->y, d->x, d->y, px, py) * inv;
            double w1 = edge_fn(d->x, d->y, a->x, a->y, px, py) * inv;
            double w2 = edge_fn(a->x, a->y, b->x, b->y, px, py) * inv;
            double z;
            size_t i;
            if (w0 < 0.0 || w1 < 0.0 || w2 < 0.0) continue;
            z = w0 * a->z + w1 * b->z + w2 * d->z;
            i = (size_t)y * (size_t)c->w + (size_t)x;
            if (z > c->z[i]) {
                c->z[i] = z;
                put_px(c, x, y, col);
            }
        }
    }
}

/* Line from a to b. bias < 0: no depth test; otherwise a pixel is drawn when the line is at
 * most `bias` behind the surface already there. thick = 1 or 2 pixels. */
static void draw_line(canvas *c, const pv *a, const pv *b, const uint8_t col[3], double bias, int thick)
{
    double dx = b->x - a->x, dy = b->y - a->y;
    double len = fmax(fabs(dx), fabs(dy));
    int n, k;
    if (!isfinite(len)) return;
    if (len > 4.0 * (double)(c->w + c->h)) return; /* cannot happen after framing; be safe */
    n = (int)ceil(len);
    if (n < 1) n = 1;
    for (k = 0; k <= n; k++) {
        double t = (double)k / (double)n;
        double fx = a->x + dx * t, fy = a->y + dy * t, z = a->z + (b->z - a->z) * t;
        int x = (int)floor(fx), y = (int)floor(fy), i, j;
        for (j = 0; j < thick; j++) {
            for (i = 0; i < thick; i++) {
                int px = x + i, py = y + j;
                if (px < 0 || py < 0 || px >= c->w || py >= c->h) continue;
                if (bias >= 0.0) {
                    size_t zi = (size_t)py * (size_t)c->w + (size_t)px;
                    if (z + bias < c->z[zi]) continue;
                }
                put_px(c, px, py, col);
            }
        }
    }
}

static void dot(canvas *c, const pv *p, const uint8_t col[3])
{
    int x = (int)floor(p->x), y = (int)floor(p->y), i, j;
    for (j = -2; j <= 2; j++)
        for (i = -2; i <= 2; i++)
            if (i * i + j * j <= 5) put_px(c, x + i, y + j, col);
}

static uint8_t shade8(double base, double k)
{
    double v = base * k;
    if (!(v > 0.0)) return 0;
    if (v > 255.0) return 255;
    return (uint8_t)(v + 0.5);
}

static int face_ok(const render_mesh *m, const pv *p, uint32_t f, uint32_t *s, uint32_t *e)
{
    uint32_t i;
    *s = m->face_start[f];
    *e = m->face_start[f + 1];
    if (*e < *s || *e - *s < 3u) return 0;
    for (i = *s; i < *e; i++) {
        uint32_t v = m->corner_vert[i];
        if (v >= m->num_verts || !p[v].ok) return 0;
    }
    return 1;
}

static int label_scale(int w)
{
    return w >= 640 ? 2 : 1;
}

/* Pixel rows the captions take at the top (0 without captions). */
static int label_rows(const render_opts *o, int w, int h)
{
    int sc = label_scale(w), n = 0;
    if (h < 3 * RENDER_GLYPH_H * sc) return 0;
    n += o->label && o->label[0];
    n += o->input_label && o->input_label[0] && o->input;
    return n ? 3 * sc + n * (RENDER_GLYPH_H + 2) * sc : 0;
}

/* ------------------------------------------------------------------------------------ */
/* Projection                                                                             */

/* Marks the finite vertices (ok) and those a drawable face or polyline uses (used): only
 * those take part in framing, so a stray unreferenced vertex cannot shrink the picture. */
static void mark_used(const render_mesh *m, pv *p)
{
    uint32_t nv = m->num_verts, v, f, l, k;
    for (v = 0; v < nv; v++) {
        const double *q = m->pos + 3u * (size_t)v;
        p[v].ok = isfinite(q[0]) && isfinite(q[1]) && isfinite(q[2]);
    }
    if (m->num_faces && m->face_start && m->corner_vert)
        for (f = 0; f < m->num_faces; f++) {
            uint32_t s, e;
            if (!face_ok(m, p, f, &s, &e)) continue;
            for (k = s; k < e; k++) p[m->corner_vert[k]].used = 1;
        }
    if (m->num_lines && m->line_start && m->line_vert)
        for (l = 0; l < m->num_lines; l++)
            for (k = m->line_start[l]; k < m->line_start[l + 1]; k++) {
                uint32_t a = m->line_vert[k];
                if (a < nv && p[a].ok) p[a].used = 1;
            }
}

static double max_abs_used(const render_mesh *m, const pv *p, double maxabs)
{
    uint32_t v;
    for (v = 0; v < m->num_verts; v++) {
        const double *q = m->pos + 3u * (size_t)v;
        if (p[v].used) maxabs = fmax(maxabs, fmax(fabs(q[0]), fmax(fabs(q[1]), fabs(q[2]))));
    }
    return maxabs;
}

/* Rotates the used vertices into the view frame (yaw about y, then pitch about x; positive
 * pitch looks down onto the model) and grows the bounding box bb (any: bb holds a point). */
static void rotate_used(const render_mesh *m, pv *p, double maxabs, const double rot[4], double bb[6], int *any)
{
    uint32_t v;
    double cy = rot[0], sy = rot[1], cp = rot[2], sp = rot[3];
    for (v = 0; v < m->num_verts; v++) {
        const double *q = m->pos + 3u * (size_t)v;
        double x, y, z, x1, z1, y2, z2;
        if (!p[v].used) continue;
        x = q[0] / maxabs;
        y = q[1] / maxabs;
        z = q[2] / maxabs;
        x1 = cy * x + sy * z;
        z1 = -sy * x + cy * z;
        y2 = cp * y - sp * z1;
        z2 = sp * y + cp * z1;
        p[v].x = x1;
        p[v].y = y2;
        p[v].z = z2;
        if (!*any) {
            bb[0] = bb[1] = x1;
            bb[2] = bb[3] = y2;
            bb[4] = bb[5] = z2;
            *any = 1;
        } else {
            bb[0] = fmin(bb[0], x1); bb[1] = fmax(bb[1], x1);
            bb[2] = fmin(bb[2], y2); bb[3] = fmax(bb[3], y2);
            bb[4] = fmin(bb[4], z2); bb[5] = fmax(bb[5], z2);
        }
    }
}

static void to_screen(const render_mesh *m, pv *p, const canvas *c, double cxv, double cyv, double scale)
{
    uint32_t v;
    for (v = 0; v < m->num_verts; v++) {
        if (!p[v].used) continue;
        p[v].x = 0.5 * (double)c->w + (p[v].x - cxv) * scale;
        p[v].y = 0.5 * (double)c->h - (p[v].y - cyv) * scale;
        p[v].z = p[v].z * scale;
    }
}

/* Mean projected length of the face edges, in pixels (each interior edge counted from both
 * sides, which does not change the mean). */
static double mean_edge_px(const render_mesh *m, const pv *p)
{
    double sum = 0.0;
    uint32_t f, n = 0;
    for (f = 0; f < m->num_faces; f++) {
        uint32_t s, e, k;
        if (!face_ok(m, p, f, &s, &e)) continue;
        for (k = s; k < e; k++) {
            const pv *a = &p[m->corner_vert[k]], *b = &p[m->corner_vert[k + 1 < e ? k + 1 : s]];
            sum += sqrt((a->x - b->x) * (a->x - b->x) + (a->y - b->y) * (a->y - b->y));
            n++;
        }
    }
    return n ? sum / (double)n : 0.0;
}

/* ------------------------------------------------------------------------------------ */
/* The input over the result                                                              */

/* A line of the input: 2 px where it is in front of the result (within the edge bias),
 * 1 px dashed where the result hides it (4 on, 4 off along x + y, so that the two faces'
 * copies of an edge dash alike). */
static void overlay_line(canvas *c, const pv *a, const pv *b, double bias)
{
    static const uint8_t col[3] = {RENDER_INPUT_R, RENDER_INPUT_G, RENDER_INPUT_B};
    double dx = b->x - a->x, dy = b->y - a->y, len = fmax(fabs(dx), fabs(dy));
    int n, k, i, j;
    if (!isfinite(len) || len > 4.0 * (double)(c->w + c->h)) return;
    n = (int)ceil(len);
    if (n < 1) n = 1;
    for (k = 0; k <= n; k++) {
        double t = (double)k / (double)n;
        double fx = a->x + dx * t, fy = a->y + dy * t, z = a->z + (b->z - a->z) * t;
        int x = (int)floor(fx), y = (int)floor(fy), hidden;
        if (x < 0 || y < 0 || x >= c->w || y >= c->h) continue;
        hidden = z + bias < c->z[(size_t)y * (size_t)c->w + (size_t)x];
        if (hidden) {
            if (((x + y) >> 2) & 1) continue; /* by position: overlapping lines dash alike */
            put_px(c, x, y, col);
            continue;
        }
        for (j = 0; j < 2; j++)
            for (i = 0; i < 2; i++) put_px(c, x + i, y + j, col);
    }
}

static void draw_overlay(canvas *c, const render_mesh *m, const pv *p, double bias)
{
    static const uint8_t col[3] = {RENDER_INPUT_R, RENDER_INPUT_G, RENDER_INPUT_B};
    uint32_t f, l, k, v, nv = m->num_verts;
    for (f = 0; m->face_start && m->corner_vert && f < m->num_faces; f++) {
        uint32_t s, e;
        if (!face_ok(m, p, f, &s, &e)) continue;
        for (k = s; k < e; k++) {
            uint32_t a = m->corner_vert[k], b = m->corner_vert[k + 1 < e ? k + 1 : s];
            overlay_line(c, &p[a], &p[b], bias);
        }
    }
    if (m->num_lines && m->line_start && m->line_vert)
        for (l = 0; l < m->num_lines; l++)
            for (k = m->line_start[l]; k + 1 < m->line_start[l + 1]; k++) {
                uint32_t a = m->line_vert[k], b = m->line_vert[k + 1];
                if (a < nv && b < nv && p[a].ok && p[b].ok) overlay_line(c, &p[a], &p[b], bias);
            }
    for (v = 0; v < nv; v++) {
        int x = (int)floor(p[v].x), y = (int)floor(p[v].y), i, j;
        if (!p[v].used) continue;
        for (j = -2; j <= 2; j++)
            for (i = -2; i <= 2; i++) put_px(c, x + i, y + j, col);
    }
}

/* ------------------------------------------------------------------------------------ */
/* The picture                                                                            */

int render_rgb(const render_mesh *m, const render_opts *o, uint8_t **rgb, int *width, int *height)
{
    return render_rgb_info(m, o, rgb, width, height, 0);
}

/* A dense input drawn over the result would hide it: the input and the result are then
 * drawn side by side instead, each framed on its own half, each with its caption. */
static int side_by_side(const render_mesh *m, const render_mesh *in, const render_opts *opt, uint8_t **rgb,
                        render_info *info)
{
    static const uint8_t sep[3] = {150, 150, 150};
    render_opts half = *opt;
    uint8_t *a = 0, *b = 0, *out;
    int wa = 0, ha = 0, wb = 0, hb = 0, x, y, w = opt->width, h = opt->height;
    half.input = 0;
    half.width = w / 2;
    half.label = opt->input_label;
    half.input_label = 0;
    if (render_rgb_info(in, &half, &a, &wa, &ha, 0) != 0) return -1;
    half.width = w - w / 2;
    half.label = opt->label;
    if (render_rgb_info(m, &half, &b, &wb, &hb, info) != 0) {
        free(a);
        return -1;
    }
    out = (uint8_t *)malloc((size_t)w * (size_t)h * 3u);
    if (!out) {
        free(a);
        free(b);
        return -1;
    }
    for (y = 0; y < h; y++) {
        memcpy(out + (size_t)y * (size_t)w * 3u, a + (size_t)y * (size_t)wa * 3u, (size_t)wa * 3u);
        memcpy(out + ((size_t)y * (size_t)w + (size_t)wa) * 3u, b + (size_t)y * (size_t)wb * 3u, (size_t)wb * 3u);
    }
    for (y = 0; y < h; y++)
        for (x = wa - 1; x <= wa; x++) memcpy(out + ((size_t)y * (size_t)w + (size_t)x) * 3u, sep, 3u);
    free(a);
    free(b);
    *rgb = out;
    return 0;
}

static int has_geometry(const render_mesh *m)
{
    return m && m->pos && m->num_verts &&
           ((m->num_faces && m->face_start && m->corner_vert) || (m->num_lines && m->line_start && m->line_vert));
}

int render_rgb_info(const render_mesh *m, const render_opts *o, uint8_t **rgb, int *width, int *height,
                    render_info *info)
{
    render_opts opt;
    canvas c;
    pv *p = 0, *q = 0;
    const render_mesh *in = 0;
    size_t npx, i;
    uint32_t f, l;
    double maxabs = 0.0, bb[6] = {0, 0, 0, 0, 0, 0}, scale, cxv, cyv, zspan, bias, rot[4];
    double lx = -0.45, ly = 0.65, lz = 0.75, ll;
    int any = 0, edges = 0;
    int have_faces, have_lines;

    if (!rgb || !width || !height) return -1;
    *rgb = 0;
    *width = 0;
    *height = 0;
    if (info) memset(info, 0, sizeof *info);
    render_opts_default(&opt);
    if (o) {
        if (o->width > 0 && o->height > 0) {
            opt.width = o->width > MAX_DIM ? MAX_DIM : o->width;
            opt.height = o->height > MAX_DIM ? MAX_DIM : o->height;
        }
        if (isfinite(o->yaw_deg)) opt.yaw_deg = o->yaw_deg;
        if (isfinite(o->pitch_deg)) opt.pitch_deg = o->pitch_deg;
        opt.edges = o->edges;
        opt.label = o->label;
        opt.input_label = o->input_label;
        if (has_geometry(o->input)) in = o->input;
        opt.input = in;
    }
    c.w = opt.width;
    c.h = opt.height;
    npx = (size_t)c.w * (size_t)c.h;
    c.rgb = (uint8_t *)malloc(npx * 3u);
    c.z = (double *)malloc(npx * sizeof(double));
    if (!c.rgb || !c.z) goto oom;
    for (i = 0; i < npx; i++) {
        c.rgb[3 * i] = BG_R;
        c.rgb[3 * i + 1] = BG_G;
        c.rgb[3 * i + 2] = BG_B;
        c.z[i] = -HUGE_VAL;
    }

    if (!has_geometry(m)) m = 0;
    have_faces = m && m->num_faces && m->face_start && m->corner_vert;
    have_lines = m && m->num_lines && m->line_start && m->line_vert;
    if (!m && !in) goto labels;

    if (m && !(p = (pv *)calloc(m->num_verts, sizeof(pv)))) goto oom;
    if (in && !(q = (pv *)calloc(in->num_verts, sizeof(pv)))) goto oom;
    /* Normalise by the largest finite magnitude first, so huge coordinates cannot overflow
     * in the centring and rotation below; both meshes share one frame. */
    if (m) mark_used(m, p);
    if (in) mark_used(in, q);
    if (m) maxabs = max_abs_used(m, p, maxabs);
    if (in) maxabs = max_abs_used(in, q, maxabs);
    if (!(maxabs > 0.0)) maxabs = 1.0;

    rot[0] = cos(opt.yaw_deg * (3.14159265358979323846 / 180.0));
    rot[1] = sin(opt.yaw_deg * (3.14159265358979323846 / 180.0));
    rot[2] = cos(opt.pitch_deg * (3.14159265358979323846 / 180.0));
    rot[3] = sin(opt.pitch_deg * (3.14159265358979323846 / 180.0));
    if (m) rotate_used(m, p, maxabs, rot, bb, &any);
    if (in) rotate_used(in, q, maxabs, rot, bb, &any);
    if (!any) goto labels;

    {
        /* captions take rows at the top: the model is framed below them */
        int top = label_rows(&opt, c.w, c.h);
        double sxr = bb[1] - bb[0], syr = bb[3] - bb[2];
        double aw = (double)c.w * (1.0 - 2.0 * MARGIN), ah = (double)(c.h - top) * (1.0 - 2.0 * MARGIN);
        if (sxr > 0.0 && syr > 0.0) scale = fmin(aw / sxr, ah / syr);
        else if (sxr > 0.0) scale = aw / sxr;
        else if (syr > 0.0) scale = ah / syr;
        else scale = 1.0;
        if (!(scale < 1e12)) scale = 1e12; /* near-zero extent away from the origin */
        cxv = 0.5 * (bb[0] + bb[1]);
        cyv = 0.5 * (bb[2] + bb[3]) + 0.5 * (double)top / scale; /* centre of the rows below */
        zspan = (bb[5] - bb[4]) * scale; /* depth in pixel units, like x and y */
    }
    if (m) to_screen(m, p, &c, cxv, cyv, scale);
    if (in) to_screen(in, q, &c, cxv, cyv, scale);
    if (in && in->num_faces && mean_edge_px(in, q) < RENDER_INPUT_DENSE_PX && c.w >= 64) {
        free(p);
        free(q);
        free(c.z);
        free(c.rgb);
        if (side_by_side(m, in, &opt, rgb, info) != 0) return -1;
        *width = opt.width;
        *height = opt.height;
        return 0;
    }
    /* Edge depth bias: a couple of pixels' worth of depth, plus a little of the depth range
     * (edges on faces seen at grazing angles), so surface edges win but hidden ones lose. */
    bias = 1.5 + 0.004 * zspan;

    ll = sqrt(lx * lx + ly * ly + lz * lz);
    lx /= ll;
    ly /= ll;
    lz /= ll;

    if (have_faces) {
        double mean = mean_edge_px(m, p);
        edges = opt.edges == RENDER_EDGES_AUTO ? !(mean < RENDER_DENSE_PX) : opt.edges != 0;
        if (info) info->mean_edge_px = mean;
        for (f = 0; f < m->num_faces; f++) {
            uint32_t s, e, k;
            double nx = 0.0, ny = 0.0, nz = 0.0, nl, lam, inten;
            uint8_t col[3];
            if (!face_ok(m, p, f, &s, &e)) continue;
            /* Newell's normal in screen space (y down -> flip y and z sign conventions back
             * to a right-handed view frame: use view x, -screen y, depth). */
            for (k = s; k < e; k++) {
                const pv *a = &p[m->corner_vert[k]];
                const pv *b = &p[m->corner_vert[k + 1 < e ? k + 1 : s]];
                double ay = -a->y, by = -b->y;
                nx += (ay - by) * (a->z + b->z);
                ny += (a->z - b->z) * (a->x + b->x);
                nz += (a->x - b->x) * (ay + by);
            }
            nl = sqrt(nx * nx + ny * ny + nz * nz);
            if (nl > 0.0 && isfinite(nl)) {
                nx /= nl;
                ny /= nl;
                nz /= nl;
            } else {
                nx = ny = 0.0;
                nz = 1.0;
            }
            if (nz >= 0.0) { /* front face: cool blue-grey */
                lam = nx * lx + ny * ly + nz * lz;
                inten = 0.38 + 0.62 * (lam > 0.0 ? lam : 0.0);
                col[0] = shade8(160.0, inten);
                col[1] = shade8(190.0, inten);
                col[2] = shade8(235.0, inten);
            } else { /* back face (inside of an open mesh): warm tint */
                lam = -(nx * lx + ny * ly + nz * lz);
                inten = 0.35 + 0.55 * (lam > 0.0 ? lam : 0.0);
                col[0] = shade8(225.0, inten);
                col[1] = shade8(165.0, inten);
                col[2] = shade8(120.0, inten);
            }
            for (k = s + 1; k + 1 < e; k++)
                fill_tri(&c, &p[m->corner_vert[s]], &p[m->corner_vert[k]], &p[m->corner_vert[k + 1]], col);
        }
        if (edges) {
            static const uint8_t ecol[3] = {40, 44, 56};
            for (f = 0; f < m->num_faces; f++) {
                uint32_t s, e, k;
                if (!face_ok(m, p, f, &s, &e)) continue;
                for (k = s; k < e; k++)
                    draw_line(&c, &p[m->corner_vert[k]], &p[m->corner_vert[k + 1 < e ? k + 1 : s]], ecol, bias, 1);
            }
        }
    }

    if (have_lines) {
        static const uint8_t lcol[3] = {120, 16, 28};
        static const uint8_t dcol[3] = {20, 20, 20};
        uint32_t nv = m->num_verts;
        for (l = 0; l < m->num_lines; l++) {
            uint32_t s = m->line_start[l], e = m->line_start[l + 1], k;
            if (e < s) continue;
            for (k = s; k + 1 < e; k++) {
                uint32_t a = m->line_vert[k], b = m->line_vert[k + 1];
                if (a >= nv || b >= nv || !p[a].ok || !p[b].ok) continue;
                draw_line(&c, &p[a], &p[b], lcol, -1.0, 2);
            }
        }
        for (l = 0; l < m->num_lines; l++) {
            uint32_t s = m->line_start[l], e = m->line_start[l + 1], k;
            if (e < s) continue;
            for (k = s; k < e; k++) {
                uint32_t a = m->line_vert[k];
                if (a < nv && p[a].ok) dot(&c, &p[a], dcol);
            }
        }
    }
    if (in) draw_overlay(&c, in, q, bias);

labels:
    {
        static const uint8_t tcol[3] = {40, 40, 40};
        static const uint8_t icol[3] = {RENDER_INPUT_R, RENDER_INPUT_G, RENDER_INPUT_B};
        static const uint8_t bg[3] = {BG_R, BG_G, BG_B}; /* a box so captions read over the model */
        int sc = label_scale(c.w), y;
        /* the small font when a caption would not fit the large one */
        if ((opt.label && render_text_width(opt.label, sc) + 8 * sc > c.w) ||
            (in && opt.input_label && render_text_width(opt.input_label, sc) + 8 * sc > c.w))
            sc = 1;
        y = 3 * sc;
        if (opt.label && opt.label[0] && c.h >= 3 * RENDER_GLYPH_H * sc) {
            render_text(c.rgb, c.w, c.h, 4 * sc, y, sc, opt.label, tcol, bg);
            y += (RENDER_GLYPH_H + 2) * sc;
        }
        if (in && opt.input_label && opt.input_label[0] && c.h >= 3 * RENDER_GLYPH_H * sc)
            render_text(c.rgb, c.w, c.h, 4 * sc, y, sc, opt.input_label, icol, bg);
    }
    if (info) info->edges_drawn = edges;
    free(p);
    free(q);
    free(c.z);
    *rgb = c.rgb;
    *width = c.w;
    *height = c.h;
    return 0;
oom:
    free(p);
    free(q);
    free(c.rgb);
    free(c.z);
    return -1;
}
