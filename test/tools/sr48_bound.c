/* SPDX-License-Identifier: MIT */
/* Measures how far an a-priori chordal bound from second differences of the level-k control
 * net could go for semi-regular 4-8 chordal cuts (issue 20, item 4), before anyone derives
 * one: for every triangle d of levels < S of subd_sr48_build's hierarchy it computes
 *   E(d)   the exact chordal deviation (subd_sr48_extract's: the largest |P(v) - L_d(v)| over
 *          the vertices v of d's subtree, P the finest positions, L_d the dyadic linear
 *          interpolant of d's corners), in double;
 *   s1(d)  the largest second difference |a + b - c - c'| over d's three edges (a, b the
 *          edge's ends, c, c' the opposite vertices of the two level-k triangles on it), on
 *          the level-k positions (the positions of a k-step build: the control net a stream
 *          holds when it decides at level k);
 *   s*(d)  the same over every level-k edge at one of d's corners (d's star);
 * then the smallest constants C with E <= C s over all triangles (and at quantiles), and the
 * faces of the least conforming cut that splits every triangle of the hierarchy with
 * C s(d) > eps (with its forced ancestors) against the same cut of E > eps. That closure
 * asks every triangle; subd_sr48_extract asks only the triangles its cut reaches, so its
 * count (printed beside) can be smaller (spot, 6 steps, eps 5e-4: 75 248 against 76 092).
 * The ratios compare two cuts made the same way.
 * Such a bound is valid only with a C proven for every configuration; the empirical C is a
 * lower limit for it, so the face ratios printed are the best any bound of this form can do.
 * Host only, float32 build, double arithmetic here.
 * usage: sr48_bound MESH STEPS EPS [EPS ...]
 * build: make build/bin/sr48_bound */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "subd.h"
#include "fileio.h" /* host_read_mesh (port/host) */

#define R2D(x) ((double)(x))

static subd_sr48 g_h[SUBD_SR48_MAX_STEPS + 1];

static void pos_of(const subd_sr48 *h, uint32_t v, double p[3])
{
    p[0] = R2D(h->pos[3u * v]);
    p[1] = R2D(h->pos[3u * v + 1u]);
    p[2] = R2D(h->pos[3u * v + 2u]);
}

typedef struct node {
    uint32_t t;
    double l[3][3]; /* L at apex, b0, b1 */
} node;

/* E(d): walk d's subtree with an explicit stack, L carried by midpoints. */
static double exact_e(const subd_sr48 *h, uint32_t S, uint32_t k, uint32_t t, node *st)
{
    uint32_t sp = 0, lev[64], c, j;
    double e2 = 0.0;
    st[0].t = t;
    for (j = 0; j < 3; j++) pos_of(h, h->tri_vert[3u * t + j], st[0].l[j]);
    lev[0] = k;
    sp = 1;
    while (sp) {
        node n = st[--sp];
        uint32_t lk = lev[sp], i, ch, m;
        double lm[3], pm[3], d2 = 0.0;
        if (lk >= S) continue;
        i = n.t - h->level_tri[lk];
        ch = h->level_tri[lk + 1u] + 2u * i;
        m = h->tri_vert[3u * ch]; /* child 0 = (m; c, a) */
        pos_of(h, m, pm);
        for (c = 0; c < 3; c++) {
            lm[c] = 0.5 * (n.l[1][c] + n.l[2][c]);
            d2 += (pm[c] - lm[c]) * (pm[c] - lm[c]);
        }
        if (d2 > e2) e2 = d2;
        if (lk + 1u < S) {
            /* child 0 = (m; c, a), child 1 = (m; b, c) */
            st[sp].t = ch;
            memcpy(st[sp].l[0], lm, sizeof lm);
            memcpy(st[sp].l[1], n.l[0], sizeof lm);
            memcpy(st[sp].l[2], n.l[1], sizeof lm);
            lev[sp++] = lk + 1u;
            st[sp].t = ch + 1u;
            memcpy(st[sp].l[0], lm, sizeof lm);
            memcpy(st[sp].l[1], n.l[2], sizeof lm);
            memcpy(st[sp].l[2], n.l[0], sizeof lm);
            lev[sp++] = lk + 1u;
        }
    }
    return sqrt(e2);
}

typedef struct half {
    uint32_t a, b, opp;
} half;

static int half_cmp(const void *x, const void *y)
{
    const half *p = (const half *)x, *q = (const half *)y;
    if (p->a != q->a) return p->a < q->a ? -1 : 1;
    if (p->b != q->b) return p->b < q->b ? -1 : 1;
    return 0;
}

static int dbl_cmp(const void *x, const void *y)
{
    double p = *(const double *)x, q = *(const double *)y;
    return p < q ? -1 : p > q ? 1 : 0;
}

/* s1 and s* of every level-k triangle, from the k-step build's positions. */
static void second_diffs(const subd_sr48 *hs, const subd_sr48 *hk, uint32_t k, double *s1, double *sstar)
{
    uint32_t t0 = hs->level_tri[k], nt = hs->level_tri[k + 1u] - t0, nv = hs->level_verts[k], i, j, n = 0;
    half *hv = malloc(3u * nt * sizeof(half));
    double *vmax = calloc(nv, sizeof(double)), *ed = calloc(3u * nt, sizeof(double));
    for (i = 0; i < nt; i++)
        for (j = 0; j < 3; j++) {
            uint32_t a = hs->tri_vert[3u * (t0 + i) + (j + 1u) % 3u], b = hs->tri_vert[3u * (t0 + i) + (j + 2u) % 3u];
            hv[n].a = a < b ? a : b;
            hv[n].b = a < b ? b : a;
            hv[n].opp = hs->tri_vert[3u * (t0 + i) + j];
            n++;
        }
    qsort(hv, n, sizeof(half), half_cmp);
    /* per interior edge: its second difference, on both halves and into both ends' vmax */
    for (i = 0; i + 1u < n; i++) {
        double pa[3], pb[3], pc[3], pd[3], d2 = 0.0, dd;
        if (hv[i].a != hv[i + 1u].a || hv[i].b != hv[i + 1u].b) continue;
        pos_of(hk, hv[i].a, pa);
        pos_of(hk, hv[i].b, pb);
        pos_of(hk, hv[i].opp, pc);
        pos_of(hk, hv[i + 1u].opp, pd);
        for (j = 0; j < 3; j++) d2 += (pa[j] + pb[j] - pc[j] - pd[j]) * (pa[j] + pb[j] - pc[j] - pd[j]);
        dd = sqrt(d2);
        ed[i] = ed[i + 1u] = dd;
        if (dd > vmax[hv[i].a]) vmax[hv[i].a] = dd;
        if (dd > vmax[hv[i].b]) vmax[hv[i].b] = dd;
        i++;
    }
    for (i = 0; i < nt; i++) {
        const uint32_t *tv = hs->tri_vert + 3u * (t0 + i);
        uint32_t e;
        s1[i] = sstar[i] = 0.0;
        for (e = 0; e < 3; e++) {
            uint32_t a = tv[(e + 1u) % 3u], b = tv[(e + 2u) % 3u];
            half key, *f;
            key.a = a < b ? a : b;
            key.b = a < b ? b : a;
            f = bsearch(&key, hv, n, sizeof(half), half_cmp);
            if (f && ed[f - hv] > s1[i]) s1[i] = ed[f - hv];
            if (vmax[tv[e]] > sstar[i]) sstar[i] = vmax[tv[e]];
        }
    }
    free(hv);
    free(vmax);
    free(ed);
}

/* Least conforming cut of the asks (ask[t] for t of levels < S): faces. */
static uint32_t cut_faces(const subd_sr48 *h, uint32_t S, const uint8_t *ask0, uint8_t *sp)
{
    uint32_t k, t, faces = 0, nt = h->level_tri[S];
    memcpy(sp, ask0, nt);
    for (t = 0; t < nt; t++)
        if (sp[t] && h->tri_base_nb[t] != SUBD_NONE) sp[h->tri_base_nb[t]] = 1;
    for (k = S - 1u; k >= 1u; k--)
        for (t = h->level_tri[k]; t < h->level_tri[k + 1u]; t++)
            if (sp[t]) {
                uint32_t p = h->level_tri[k - 1u] + (t - h->level_tri[k]) / 2u;
                sp[p] = 1;
                if (h->tri_base_nb[p] != SUBD_NONE) sp[h->tri_base_nb[p]] = 1;
            }
    for (k = 0; k <= S; k++)
        for (t = h->level_tri[k]; t < h->level_tri[k + 1u]; t++) {
            int par = k == 0 || sp[h->level_tri[k - 1u] + (t - h->level_tri[k]) / 2u];
            int split = k < S && sp[t];
            if (par && !split) faces++;
        }
    return faces;
}

static uint32_t g_xfaces[64];
static uint8_t *g_buf[SUBD_SR48_MAX_STEPS + 1];

/* The ratios E / s over the triangles with E > 0, and the cuts of C s > eps. */
static void report(const char *name, uint32_t S, uint32_t nt, const double *E, const double *sv, uint8_t *ask,
                   uint8_t *sp, int argc, char **argv)
{
    double *r = malloc(nt * sizeof(double)), q[6];
    uint32_t n = 0, inf = 0, t, i;
    int e;
    static const double qs[6] = {0.5, 0.9, 0.99, 0.999, 0.9999, 1.0};
    for (t = 0; t < nt; t++) {
        if (E[t] <= 0.0) continue;
        if (sv[t] <= 0.0) {
            inf++;
            continue;
        }
        r[n++] = E[t] / sv[t];
    }
    qsort(r, n, sizeof(double), dbl_cmp);
    for (i = 0; i < 6; i++) q[i] = r[(uint32_t)(qs[i] * (double)(n - 1u) + 0.5)];
    printf("E / %s: %u triangles, %u with s = 0 < E\n", name, n, inf);
    printf("  median %.4f  p90 %.4f  p99 %.4f  p99.9 %.4f  p99.99 %.4f  max %.4f\n", q[0], q[1], q[2], q[3], q[4],
           q[5]);
    for (e = 3; e < argc; e++) {
        double eps = atof(argv[e]);
        uint32_t fx, fb[4];
        for (t = 0; t < nt; t++) ask[t] = E[t] > eps;
        fx = cut_faces(&g_h[S], S, ask, sp);
        for (i = 0; i < 4; i++) {
            double C = q[i + 2u];
            for (t = 0; t < nt; t++) ask[t] = C * sv[t] > eps;
            fb[i] = cut_faces(&g_h[S], S, ask, sp);
        }
        printf("  eps %g: exact cut %u faces (extract CHORD %u); C s > eps, C = p99: %u (%.2fx), p99.9: %u (%.2fx), "
               "p99.99: %u (%.2fx), max: %u (%.2fx)\n",
               eps, fx, g_xfaces[e], fb[0], (double)fb[0] / fx, fb[1], (double)fb[1] / fx, fb[2], (double)fb[2] / fx,
               fb[3], (double)fb[3] / fx);
    }
    free(r);
}

int main(int argc, char **argv)
{
    host_mesh hm;
    subd_mesh in;
    subd_diag d;
    uint32_t S, k, t, nt, plan;
    double *E, *s1, *ss;
    uint8_t *ask, *sp;
    node *stk;
    int e;
    if (argc < 4) {
        fprintf(stderr, "usage: sr48_bound MESH STEPS EPS [EPS ...]\n");
        return 2;
    }
    if (host_read_mesh(argv[1], NULL, &hm, &d, NULL) != SUBD_OK) {
        fprintf(stderr, "sr48_bound: cannot read %s\n", argv[1]);
        return 3;
    }
    in = hm.mesh;
    S = (uint32_t)atoi(argv[2]);
    for (k = 0; k <= S; k++) {
        subd_sr48_opts o;
        subd_arena ak;
        o.steps = k;
        o.flags = 0;
        if (subd_sr48_plan(&in, &o, SUBD_SR48_CLUSTERS_UNKNOWN, &plan, &d) != SUBD_OK) return 4;
        g_buf[k] = malloc(plan + 64u);
        subd_arena_init(&ak, g_buf[k], plan + 64u);
        if (subd_sr48_build(&ak, &in, &o, &g_h[k], &d) != SUBD_OK) return 5;
    }
    nt = g_h[S].level_tri[S];
    E = malloc(nt * sizeof(double));
    s1 = malloc(nt * sizeof(double));
    ss = malloc(nt * sizeof(double));
    ask = malloc(g_h[S].num_tris);
    sp = malloc(g_h[S].num_tris);
    stk = malloc(256u * sizeof(node));
    for (k = 0; k < S; k++) {
        uint32_t t0 = g_h[S].level_tri[k];
        for (t = t0; t < g_h[S].level_tri[k + 1u]; t++) E[t] = exact_e(&g_h[S], S, k, t, stk);
        second_diffs(&g_h[S], &g_h[k], k, s1 + t0, ss + t0);
    }
    printf("mesh %s: %u input faces, %u steps, level-0 triangles %u, triangles of levels < %u: %u\n", argv[1],
           in.num_faces, S, g_h[S].level_tri[1], S, nt);
    for (e = 3; e < argc && e < 64; e++) {
        subd_sr48_adapt ad;
        subd_sr48_adapt_report rep;
        subd_mesh out;
        subd_arena ax;
        uint32_t xplan = 0;
        uint8_t *xb;
        memset(&ad, 0, sizeof ad);
        ad.mode = SUBD_SR48_ADAPT_CHORD;
        ad.max_level = S;
        ad.eps = (subd_real)atof(argv[e]);
        if (subd_sr48_extract_plan(&g_h[S], &ad, &xplan, &d) != SUBD_OK) return 6;
        xb = malloc(xplan + 64u);
        subd_arena_init(&ax, xb, xplan + 64u);
        if (subd_sr48_extract(&ax, &g_h[S], &ad, &out, &rep, &d) != SUBD_OK) return 7;
        g_xfaces[e] = rep.faces;
        free(xb);
    }
    report("s1 (the triangle's own edges)", S, nt, E, s1, ask, sp, argc, argv);
    report("s* (every edge at a corner)", S, nt, E, ss, ask, sp, argc, argv);
    return 0;
}
