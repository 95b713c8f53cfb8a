/* SPDX-License-Identifier: MIT */
/* Test fixtures shared by several test files: see fixtures.h. The distance search keeps the
 * triangles' bounding boxes in a static table (no heap); more triangles than it holds are
 * measured without the box test. */
#include <string.h>
#include "fixtures.h"
#include "corpus.h"

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

subd_real fx_real(double x)
{
#if SUBD_FIXED
    return (subd_real)(x >= 0 ? (int32_t)(x * 65536.0 + 0.5) : -(int32_t)(-x * 65536.0 + 0.5));
#else
    return (float)x;
#endif
}

static const char fx_tet_obj[] = "v 1 1 1\nv 1 -1 -1\nv -1 1 -1\nv -1 -1 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n";
static const char fx_cube_obj[] =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
    "f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 2 3 7\nf 2 7 6\nf 3 4 8\nf 3 8 7\n"
    "f 4 1 5\nf 4 5 8\n";
static const char fx_two_obj[] = "v 0 0 0\nv 1 0 0\nv 1 1 0.3\nv 0 1 0.5\nv 2 0.5 0\nf 1 2 3\nf 1 3 4\nf 2 5 3\n";

static subd_real fx_bpos[3 * 18];
static uint32_t fx_bidx[3 * 32];
static int fx_bipyramid(subd_arena *a, subd_mesh *m, uint32_t n)
{
    subd_face_list fl;
    uint32_t i;
    if (!CHECK(n >= 3u && n <= 16u)) return 0;
    for (i = 0; i < n; i++) {
        double ang = 6.283185307179586 * (double)i / (double)n, c = 1, s = 0, x = ang, term = x;
        uint32_t k;
        /* cos and sin by their series in double (no libm in the device tests) */
        for (k = 1; k < 30u; k++) {
            term = -term * x * x / (double)((2u * k) * (2u * k + 1u));
            s += term;
        }
        s += x;
        term = 1;
        for (k = 1; k < 30u; k++) {
            term = -term * x * x / (double)((2u * k - 1u) * (2u * k));
            c += term;
        }
        fx_bpos[3 * i] = fx_real(c);
        fx_bpos[3 * i + 1] = fx_real(s);
        fx_bpos[3 * i + 2] = fx_real((i & 1u) ? 0.125 : 0.0);
        fx_bidx[6 * i] = n; fx_bidx[6 * i + 1] = i; fx_bidx[6 * i + 2] = (i + 1u) % n;
        fx_bidx[6 * i + 3] = n + 1u; fx_bidx[6 * i + 4] = (i + 1u) % n; fx_bidx[6 * i + 5] = i;
    }
    fx_bpos[3 * n] = 0; fx_bpos[3 * n + 1] = 0; fx_bpos[3 * n + 2] = h_int(1);
    fx_bpos[3 * n + 3] = 0; fx_bpos[3 * n + 4] = 0; fx_bpos[3 * n + 5] = -h_int(1);
    memset(&fl, 0, sizeof fl);
    fl.num_verts = n + 2u;
    fl.pos = fx_bpos;
    fl.num_faces = 2u * n;
    fl.index = fx_bidx;
    return h_build(a, &fl, m);
}

static int fx_text(subd_arena *a, const char *txt, uint32_t len, subd_mesh *m)
{
    subd_diag d;
    return CHECK_EQ(subd_obj_read(a, txt, len, m, &d), SUBD_OK);
}

int fx_sr48_shape(int id, uint32_t bipyr_n, subd_arena *a, subd_mesh *m)
{
    static subd_real tpos[3 * 64];
    static uint32_t tidx[6 * 64];
    const corpus_file *f = 0;
    switch (id) {
    case FX48_TET: return fx_text(a, fx_tet_obj, (uint32_t)sizeof fx_tet_obj - 1u, m);
    case FX48_CUBE: return fx_text(a, fx_cube_obj, (uint32_t)sizeof fx_cube_obj - 1u, m);
    case FX48_TWO: return fx_text(a, fx_two_obj, (uint32_t)sizeof fx_two_obj - 1u, m);
    case FX48_ICO: f = corpus_find("test/data/icosahedron.obj"); break;
    case FX48_HEXFAN: f = corpus_find("test/data/hexfan.obj"); break;
    case FX48_GRID: f = corpus_find("test/data/grid_tri_8x8.obj"); break;
    case FX48_DENSE: f = corpus_find("test/data/dense_ico.obj"); break;
    case FX48_BIPYR: return fx_bipyramid(a, m, bipyr_n);
    case FX48_TORUS: {
        subd_face_list fl = h_torus(6, 4, tpos, tidx);
        return h_build(a, &fl, m);
    }
    default: return CHECK(0);
    }
    if (!CHECK(f != 0)) return 0;
    return fx_text(a, f->data, f->len, m);
}

uint32_t fx_sr48_valence(const subd_sr48 *b, uint32_t *lowest)
{
    static uint16_t cnt[FX_SR48_MAXV];
    uint32_t t, best = 0, low = 0xffffffffu;
    if (!CHECK(b->num_verts <= FX_SR48_MAXV)) return 0;
    for (t = 0; t < b->num_verts; t++) cnt[t] = 0;
    for (t = 0; t < 3u * b->level_tri[1]; t++)
        if (++cnt[b->tri_vert[t]] > best) best = cnt[b->tri_vert[t]];
    for (t = 0; t < b->num_verts; t++)
        if (cnt[t] && cnt[t] < low) low = cnt[t];
    if (lowest) *lowest = low;
    return best;
}

void fx_tri_key(uint32_t *row, const subd_real *p)
{
    uint32_t c[9], i, r = 0, k;
    for (i = 0; i < 9u; i++) c[i] = subd_real_bits(p[i]);
    for (i = 1; i < 3u; i++)
        if (memcmp(&c[3u * i], &c[3u * r], 12) < 0) r = i;
    for (k = 0; k < 3u; k++) memcpy(&row[3u * k], &c[3u * ((r + k) % 3u)], 12);
}

int fx_tri_key_cmp(const void *a, const void *b) { return memcmp(a, b, 36); }

int fx_count_tri(void *ctx, const subd_tri *t)
{
    (void)t;
    ++*(uint32_t *)ctx;
    return 0;
}

uint32_t fx_sr48_plan_sweep(const subd_sr48 *base, const subd_sr48_stream_opts *so, uint8_t *buf, uint32_t plan,
                            uint32_t step, uint32_t near)
{
    subd_arena sa;
    subd_diag d;
    subd_tri_sink sink;
    uint32_t size, n, full = 0;
    int st;
    sink.tri = fx_count_tri;
    sink.ctx = &n;
    for (size = 0; size <= plan; size += (size + near < plan) ? step : 1u) {
        n = 0;
        subd_arena_init(&sa, buf, size);
        st = subd_sr48_stream(&sa, base, so, &sink, &d);
        if (size < plan) {
            if (!CHECK_EQ(st, SUBD_ERR_NOMEM) || !CHECK_EQ(d.bytes_needed, plan) || !CHECK_EQ(n, 0u) ||
                !CHECK_EQ(subd_arena_mark(&sa), 0u) || !CHECK_EQ(sa.peak, 0u))
                return 0;
        } else {
            CHECK_EQ(st, SUBD_OK);
            CHECK_EQ(sa.peak, plan);
            CHECK_EQ(d.bytes_needed, 0u);
            full = n;
        }
    }
    return full;
}
