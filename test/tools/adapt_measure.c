/* SPDX-License-Identifier: MIT */
/* Measures the adaptive Loop limit stream against the uniform one at equal guarantee:
 * for each tolerance, the triangles of subd_loop_adapt_stream (CHORD, max level L) and of the
 * coarsest uniform limit mesh (every face at one level l, = subd_loop_adapt_stream CALLBACK
 * with every face at l) that keeps every vertex of the uniform level-L limit stream within
 * eps, by a brute-force point-to-triangle distance (double) against the triangles of the
 * faces around the vertex's control face. Host only, float32.
 * usage: adapt_measure MESH.obj L EPS [EPS ...]
 * build: gcc -O2 -std=c99 -Iinclude -DSUBD_FIXED=0 test/tools/adapt_measure.c src/(*).c -lm -o adapt_measure */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include "subd.h"

typedef struct coll {
    subd_tri *t;
    uint32_t n, cap;
} coll;

static int keep(void *ctx, const subd_tri *t)
{
    coll *c = (coll *)ctx;
    if (c->n < c->cap) c->t[c->n++] = *t;
    return 0;
}

static uint32_t g_l;
static uint32_t at_l(void *u, uint32_t f)
{
    (void)u;
    (void)f;
    return g_l;
}

static double pt_tri2(const double p[3], const double a[3], const double b[3], const double c[3])
{
    double ab[3], ac[3], ap[3], bp[3], cp[3], q[3], d1, d2, d3, d4, d5, d6, va, vb, vc, v, w, den, r = 0;
    int k;
    for (k = 0; k < 3; k++) {
        ab[k] = b[k] - a[k]; ac[k] = c[k] - a[k]; ap[k] = p[k] - a[k]; bp[k] = p[k] - b[k]; cp[k] = p[k] - c[k];
    }
    d1 = ab[0] * ap[0] + ab[1] * ap[1] + ab[2] * ap[2];
    d2 = ac[0] * ap[0] + ac[1] * ap[1] + ac[2] * ap[2];
    d3 = ab[0] * bp[0] + ab[1] * bp[1] + ab[2] * bp[2];
    d4 = ac[0] * bp[0] + ac[1] * bp[1] + ac[2] * bp[2];
    d5 = ab[0] * cp[0] + ab[1] * cp[1] + ab[2] * cp[2];
    d6 = ac[0] * cp[0] + ac[1] * cp[1] + ac[2] * cp[2];
    vc = d1 * d4 - d3 * d2; vb = d5 * d2 - d1 * d6; va = d3 * d6 - d5 * d4;
    if (d1 <= 0 && d2 <= 0) for (k = 0; k < 3; k++) q[k] = a[k];
    else if (d3 >= 0 && d4 <= d3) for (k = 0; k < 3; k++) q[k] = b[k];
    else if (vc <= 0 && d1 >= 0 && d3 <= 0) { v = d1 / (d1 - d3); for (k = 0; k < 3; k++) q[k] = a[k] + v * ab[k]; }
    else if (d6 >= 0 && d5 <= d6) for (k = 0; k < 3; k++) q[k] = c[k];
    else if (vb <= 0 && d2 >= 0 && d6 <= 0) { w = d2 / (d2 - d6); for (k = 0; k < 3; k++) q[k] = a[k] + w * ac[k]; }
    else if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
        w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        for (k = 0; k < 3; k++) q[k] = b[k] + w * (c[k] - b[k]);
    } else {
        den = 1.0 / (va + vb + vc); v = vb * den; w = vc * den;
        for (k = 0; k < 3; k++) q[k] = a[k] + ab[k] * v + ac[k] * w;
    }
    for (k = 0; k < 3; k++) r += (p[k] - q[k]) * (p[k] - q[k]);
    return r;
}

/* 1 when every corner of u is within eps of c's triangles of the faces sharing a vertex. */
static int meets(const subd_mesh *in, const coll *u, const coll *c, double eps)
{
    uint32_t *start = calloc(in->num_faces + 1u, 4), *nb = calloc(in->num_faces, 4), i, j, k, g, t, f = SUBD_NONE, nn = 0;
    int ok = 1;
    for (g = 0, t = 0; g <= in->num_faces; g++) {
        while (t < c->n && c->t[t].face < g) t++;
        start[g] = t;
    }
    for (i = 0; ok && i < u->n; i++) {
        if (u->t[i].face != f) {
            f = u->t[i].face;
            for (g = 0, nn = 0; g < in->num_faces; g++) {
                int s = 0;
                for (j = 0; j < 9u; j++) s |= in->corner_vert[3u * f + j / 3u] == in->corner_vert[3u * g + j % 3u];
                if (s) nb[nn++] = g;
            }
        }
        for (j = 0; ok && j < 3u; j++) {
            double p[3], best = 1e300;
            for (k = 0; k < 3u; k++) p[k] = u->t[i].pos[j][k];
            for (g = 0; g < nn && best > eps * eps; g++)
                for (t = start[nb[g]]; t < start[nb[g] + 1u]; t++) {
                    double a[3], b[3], cc[3], d2;
                    for (k = 0; k < 3u; k++) {
                        a[k] = c->t[t].pos[0][k]; b[k] = c->t[t].pos[1][k]; cc[k] = c->t[t].pos[2][k];
                    }
                    d2 = pt_tri2(p, a, b, cc);
                    if (d2 < best) best = d2;
                }
            if (best > eps * eps) ok = 0;
        }
    }
    free(start);
    free(nb);
    return ok;
}

int main(int argc, char **argv)
{
    static uint8_t buf[64u << 20];
    subd_arena a;
    subd_mesh in;
    subd_diag d;
    subd_loop_adapt_opts o;
    subd_tri_sink s;
    coll u, c;
    uint32_t L, plan = 0, lv;
    int e;
    FILE *fp;
    char *txt;
    long len;
    if (argc < 4) return 2;
    fp = fopen(argv[1], "rb");
    if (!fp) return 2;
    fseek(fp, 0, SEEK_END);
    len = ftell(fp);
    fseek(fp, 0, SEEK_SET);
    txt = malloc((size_t)len);
    if (fread(txt, 1, (size_t)len, fp) != (size_t)len) return 2;
    fclose(fp);
    subd_arena_init(&a, buf, sizeof buf);
    if (subd_obj_read(&a, txt, (uint32_t)len, &in, &d) != SUBD_OK) return 3;
    L = (uint32_t)atoi(argv[2]);
    u.cap = c.cap = in.num_faces << (2u * L);
    u.t = malloc(u.cap * sizeof(subd_tri));
    c.t = malloc(c.cap * sizeof(subd_tri));
    o.loop.levels = L;
    o.loop.boundary = SUBD_LOOP_BOUNDARY_PAPER;
    o.loop.flags = 0;
    o.mode = SUBD_LOOP_ADAPT_CALLBACK;
    o.face_level = at_l;
    o.user = 0;
    o.chord = 0;
    s.tri = keep;
    g_l = L;
    s.ctx = &u;
    u.n = 0;
    if (subd_loop_adapt_stream(&a, &in, &o, &s, &d) != SUBD_OK) return 4;
    (void)subd_loop_adapt_stream_plan(&in, &o, &plan, &d);
    printf("mesh %s: %u faces, L %u, uniform level-L triangles %u, stream arena %u bytes\n", argv[1], in.num_faces, L,
           u.n, plan);
    for (e = 3; e < argc; e++) {
        double eps = atof(argv[e]);
        uint32_t hist[SUBD_MAX_LEVELS + 1] = {0}, i, ul = L + 1u;
        o.mode = SUBD_LOOP_ADAPT_CHORD;
        o.chord = (float)eps;
        s.ctx = &c;
        c.n = 0;
        if (subd_loop_adapt_stream(&a, &in, &o, &s, &d) != SUBD_OK) return 5;
        for (i = 0; i < c.n; i++) hist[c.t[i].level]++;
        printf("eps %g: adaptive %u triangles (%s within eps);", eps, c.n, meets(&in, &u, &c, eps) ? "checked" : "NOT");
        o.mode = SUBD_LOOP_ADAPT_CALLBACK;
        for (lv = 0; lv <= L && ul > L; lv++) {
            coll w = c;
            g_l = lv;
            w.n = 0;
            s.ctx = &w;
            if (subd_loop_adapt_stream(&a, &in, &o, &s, &d) != SUBD_OK) return 6;
            if (meets(&in, &u, &w, eps)) ul = lv;
        }
        if (ul <= L)
            printf(" uniform needs level %u: %u triangles; ratio %.3f\n", ul, in.num_faces << (2u * ul),
                   (double)c.n / (double)(in.num_faces << (2u * ul)));
        else
            printf(" uniform needs more than level %u\n", L);
    }
    return 0;
}
