/* SPDX-License-Identifier: MIT */
/* Test fixtures shared by several test files: see fixtures.h. The distance search keeps the
 * triangles' bounding boxes in a static table (no heap); more triangles than it holds are
 * measured without the box test. */
#include "fixtures.h"

static double fx_dot(const double *u, const double *v) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; }

double fx_tri_dist2(const double *p, const double *a, const double *b, const double *c)
{
    double ab[3], ac[3], ap[3], bp[3], cp[3], q[3], d1, d2, d3, d4, d5, d6, va, vb, vc, v, w, den;
    uint32_t i;
    for (i = 0; i < 3u; i++) {
        ab[i] = b[i] - a[i];
        ac[i] = c[i] - a[i];
        ap[i] = p[i] - a[i];
        bp[i] = p[i] - b[i];
        cp[i] = p[i] - c[i];
    }
    d1 = fx_dot(ab, ap);
    d2 = fx_dot(ac, ap);
    d3 = fx_dot(ab, bp);
    d4 = fx_dot(ac, bp);
    d5 = fx_dot(ab, cp);
    d6 = fx_dot(ac, cp);
    if (d1 <= 0 && d2 <= 0) {
        for (i = 0; i < 3u; i++) q[i] = a[i];
    } else if (d3 >= 0 && d4 <= d3) {
        for (i = 0; i < 3u; i++) q[i] = b[i];
    } else if (d6 >= 0 && d5 <= d6) {
        for (i = 0; i < 3u; i++) q[i] = c[i];
    } else if ((vc = d1 * d4 - d3 * d2) <= 0 && d1 >= 0 && d3 <= 0) {
        v = d1 / (d1 - d3);
        for (i = 0; i < 3u; i++) q[i] = a[i] + v * ab[i];
    } else if ((vb = d5 * d2 - d1 * d6) <= 0 && d2 >= 0 && d6 <= 0) {
        w = d2 / (d2 - d6);
        for (i = 0; i < 3u; i++) q[i] = a[i] + w * ac[i];
    } else if ((va = d3 * d6 - d5 * d4) <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
        w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        for (i = 0; i < 3u; i++) q[i] = b[i] + w * (c[i] - b[i]);
    } else {
        den = 1.0 / (va + vb + vc);
        v = vb * den;
        w = vc * den;
        for (i = 0; i < 3u; i++) q[i] = a[i] + ab[i] * v + ac[i] * w;
    }
    for (i = 0; i < 3u; i++) q[i] = p[i] - q[i];
    return fx_dot(q, q);
}

#define FX_BOXES (H_HOST ? 16384u : 1024u)
static double g_fx_box[6u * FX_BOXES]; /* per triangle: lo xyz, hi xyz */

/* Triangle t of tris as three double corners. */
static void fx_corners(const subd_real *tris, uint32_t t, double c[3][3])
{
    uint32_t r, q;
    for (r = 0; r < 3u; r++)
        for (q = 0; q < 3u; q++) c[r][q] = h_dbl(tris[9u * t + 3u * r + q]);
}

/* The squared distance from p to the nearest triangle, every one measured. */
static double fx_nearest2(const double *p, const subd_real *tris, uint32_t nt)
{
    double best = 1e300, c[3][3], d;
    uint32_t t;
    for (t = 0; t < nt && best > 0; t++) {
        fx_corners(tris, t, c);
        d = fx_tri_dist2(p, c[0], c[1], c[2]);
        if (d < best) best = d;
    }
    return best;
}

double fx_worst_dist2(const subd_real *pts, uint32_t np, const subd_real *tris, uint32_t nt, double bound2)
{
    /* a box is skipped only when clearly farther than the bound (rounding of the box test) */
    double worst = 0, skip2 = bound2 * (1.0 + 1e-9) + 1e-300, c[3][3];
    uint32_t i, t, q, boxes = nt <= FX_BOXES, start = 0;
    if (boxes)
        for (t = 0; t < nt; t++) {
            double *b = g_fx_box + 6u * t;
            fx_corners(tris, t, c);
            for (q = 0; q < 3u; q++) {
                b[q] = c[0][q] < c[1][q] ? c[0][q] : c[1][q];
                if (c[2][q] < b[q]) b[q] = c[2][q];
                b[3u + q] = c[0][q] > c[1][q] ? c[0][q] : c[1][q];
                if (c[2][q] > b[3u + q]) b[3u + q] = c[2][q];
            }
        }
    for (i = 0; i < np; i++) {
        double p[3], found = -1;
        uint32_t k;
        for (q = 0; q < 3u; q++) p[q] = h_dbl(pts[3u * i + q]);
        /* from the triangle that held the previous point: neighbours are often near */
        for (k = 0; k < nt && found < 0; k++) {
            double d;
            t = start + k < nt ? start + k : start + k - nt;
            if (boxes) {
                const double *b = g_fx_box + 6u * t;
                double e = 0;
                for (q = 0; q < 3u; q++) {
                    double x = p[q] < b[q] ? b[q] - p[q] : p[q] > b[3u + q] ? p[q] - b[3u + q] : 0;
                    e += x * x;
                }
                if (e > skip2) continue;
            }
            fx_corners(tris, t, c);
            d = fx_tri_dist2(p, c[0], c[1], c[2]);
            if (d <= bound2) {
                found = d;
                start = t;
            }
        }
        if (found < 0) found = fx_nearest2(p, tris, nt); /* none within: the nearest, for the report */
        if (found > worst) worst = found;
    }
    return worst;
}

uint32_t fx_find_he(const subd_mesh *m, uint32_t a, uint32_t b)
{
    uint32_t h;
    for (h = 0; h < m->num_corners; h++)
        if (subd_he_origin(m, h) == a && subd_he_dest(m, h) == b) return h;
    return SUBD_NONE;
}

uint32_t fx_find_edge(const subd_mesh *m, uint32_t a, uint32_t b)
{
    uint32_t h;
    for (h = 0; h < m->num_corners; h++) {
        uint32_t o = subd_he_origin(m, h), d = subd_he_dest(m, h);
        if ((o == a && d == b) || (o == b && d == a)) return h;
    }
    return SUBD_NONE;
}

uint32_t fx_grid(uint32_t n, uint32_t m, int alternate, const subd_real *z, subd_real *pos, uint32_t *idx)
{
    uint32_t i, j, k = 0;
    for (i = 0; pos && i <= n; i++)
        for (j = 0; j <= m; j++) {
            uint32_t v = i * (m + 1u) + j;
            pos[3u * v] = h_int((int32_t)j);
            pos[3u * v + 1u] = h_int((int32_t)i);
            pos[3u * v + 2u] = z ? z[v] : 0;
        }
    for (i = 0; i < n; i++)
        for (j = 0; j < m; j++) {
            uint32_t a = i * (m + 1u) + j, b = a + 1u, c = a + m + 2u, d = a + m + 1u;
            if (alternate && ((i + j) & 1u) == 0u) {
                idx[k++] = a; idx[k++] = b; idx[k++] = d;
                idx[k++] = b; idx[k++] = c; idx[k++] = d;
            } else {
                idx[k++] = a; idx[k++] = b; idx[k++] = c;
                idx[k++] = a; idx[k++] = c; idx[k++] = d;
            }
        }
    return 2u * n * m;
}

uint32_t fx_sr48_id_map(const subd_sr48 *h, uint32_t levels, uint32_t *map, uint32_t cap)
{
    uint32_t nv0 = h->level_verts[0], n0 = h->level_tri[1], k, i;
    uint32_t n = nv0 + n0 * ((1u << levels) - 1u);
    if (!CHECK(n <= cap)) return 0;
    for (i = 0; i < n; i++) map[i] = SUBD_NONE;
    for (i = 0; i < nv0; i++) map[i] = i;
    for (k = 1; k <= levels; k++)
        for (i = 0; i < (n0 << (k - 1u)); i++) {
            uint32_t t = h->level_tri[k - 1u] + i, nb = h->tri_base_nb[t];
            if (nb != SUBD_NONE && nb < t) continue; /* the diamond's lower triangle names it */
            map[nv0 + n0 * ((1u << (k - 1u)) - 1u) + i] = h->tri_vert[3u * (h->level_tri[k] + 2u * i)];
        }
    return n;
}
