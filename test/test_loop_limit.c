/* SPDX-License-Identifier: MIT */
/* Loop limit positions and normals (src/loop_limit.c) and the deterministic square root
 * (src/sqrt.c).
 *
 * The main check is against an independent reference written here (host only, double
 * precision, shares no code with src/): a plain Loop subdivider with the same rules
 * (Loop's weights, Hoppe et al. 1994 sharp-edge classification, the paper's or the B-spline
 * boundary rule) that follows one vertex through 60 levels. Subdividing a whole mesh 60
 * times is out of the question, so after every level the mesh is cut down to the faces
 * that touch a vertex within REF_KEEP rings of the tracked vertex. That is exact for the
 * tracked vertex and everything near it: a new vertex within R rings depends only on old
 * vertices within about R/2 + 1 rings (vertex rule: its 1-ring; edge rule: the two faces;
 * the paper's regularity test: the neighbours' valences), and the cut only damages
 * vertices at distance >= REF_KEEP, whose descendants are at distance >= 2 REF_KEEP - 1.
 * After every level the patch is also translated to put the tracked vertex at the origin and
 * scaled to unit size (subdivision is affine invariant), so 60 levels lose no precision;
 * the limit position is the accumulated translation. The limit normal is the normalised
 * sum of the face normals of the tracked vertex's fan at the last level, per sector between
 * sharp edges (the tangent plane of a flat-enough fan), the per-sector unit normals summed
 * and normalised again, as the library defines it for crease vertices.
 *
 * Tolerances: float32 positions within 1e-5 of the mesh size (measured: < 4e-8); normals
 * within 0.1 degree (measured: < 0.02). Q16.16 positions within the stated LSB bound
 * 0.51 + 2^-13 * sum_i max_c |p_i - v|_c (real units): 0.5 for the one final rounding,
 * 2^-29 per rounded Q28 weight times the neighbour's offset, 0.01 for the reference
 * (measured: at most 0.499 LSB, i.e. correctly rounded in every case tested); normals
 * within 0.1 degree (measured: < 0.003 except where float32 is also larger).
 * Exceptions, with the reason at the test: Loop's corner normal (no tangent plane in
 * general; only sectors of <= 2 faces are checked) and the B-spline valence-7 boundary
 * vertex (Jordan block: the reference converges like 1/L; 2 degrees).
 *
 * Everywhere (host and QEMU): subd_sqrt exact rounding checked from bit patterns, chi(n),
 * constants and translations reproduced (Q16.16: exactly), planar normals exactly (0,0,1),
 * outward normals on a convex mesh, apply = limit, every too-small arena, errors, and
 * HASH lines of positions and normals compared host = QEMU.
 */
#include "harness.h"
#include "corpus.h"
#include "../src/loop_internal.h" /* subd_loop_limit_apply */

#if H_HOST
#include <math.h>
#define REF_PI 3.14159265358979323846
#endif

/* ------------------------------------------------------------------------------------ */
/* Test meshes: a face list with sharp edges and corner tags.                             */

#define TMV 400
#define TMF 800
#define TMS 200

typedef struct tmesh {
    uint32_t nv, nf, ns, nc;
    subd_real pos[3 * TMV];
    uint32_t idx[3 * TMF];
    uint32_t sharp[TMS][2];
    uint32_t corner[16];
} tmesh;

static tmesh g_tm;

/* A coordinate k / 1024: exact in both arithmetics. */
static subd_real q10(int32_t k)
{
#if SUBD_FIXED
    return (subd_real)(k * 64);
#else
    return (subd_real)k / 1024.0f;
#endif
}

/* Uniform integer in [-r, r]. */
static int32_t jit(uint32_t *s, int32_t r)
{
    return (int32_t)(h_rand(s) % (uint32_t)(2 * r + 1)) - r;
}

static void tm_clear(tmesh *t)
{
    t->nv = t->nf = t->ns = t->nc = 0;
}

static uint32_t tm_vert(tmesh *t, int32_t x, int32_t y, int32_t z)
{
    uint32_t v = t->nv++;
    t->pos[3 * v] = q10(x);
    t->pos[3 * v + 1] = q10(y);
    t->pos[3 * v + 2] = q10(z);
    return v;
}

/* A vertex (x, y, z) + uniform jitter in [-r, r] per coordinate, drawn in x, y, z order
 * (never as function arguments: their evaluation order differs between compilers). */
static uint32_t tm_vert_j(tmesh *t, uint32_t *s, int32_t x, int32_t y, int32_t z, int32_t rx, int32_t ry, int32_t rz)
{
    int32_t jx = rx ? jit(s, rx) : 0, jy, jz;
    jy = ry ? jit(s, ry) : 0;
    jz = rz ? jit(s, rz) : 0;
    return tm_vert(t, x + jx, y + jy, z + jz);
}

static void tm_face(tmesh *t, uint32_t a, uint32_t b, uint32_t c)
{
    t->idx[3 * t->nf] = a;
    t->idx[3 * t->nf + 1] = b;
    t->idx[3 * t->nf + 2] = c;
    t->nf++;
}

static void tm_sharp(tmesh *t, uint32_t a, uint32_t b)
{
    t->sharp[t->ns][0] = a;
    t->sharp[t->ns][1] = b;
    t->ns++;
}

/* Bipyramid over a jittered n-gon: apexes 0 and 1 have valence n, the equator valence 4. */
static void tm_bipyramid(tmesh *t, uint32_t n, uint32_t seed)
{
    uint32_t i, s = seed;
    tm_clear(t);
    tm_vert_j(t, &s, 0, 0, 1400, 100, 100, 100);
    tm_vert_j(t, &s, 0, 0, -1200, 100, 100, 100);
    for (i = 0; i < n; i++) {
        /* the equator on a circle of radius 1024, rounded, jittered */
        subd_real c = subd_cos_turns((int32_t)i, (int32_t)n), sn = subd_sin_turns((int32_t)i, (int32_t)n);
#if SUBD_FIXED
        int32_t x = (c * 1024 + 32768) >> 16, y = (sn * 1024 + 32768) >> 16;
#else
        int32_t x = (int32_t)(c * 1024.0f), y = (int32_t)(sn * 1024.0f);
#endif
        tm_vert_j(t, &s, x, y, 0, 80, 80, 150);
    }
    for (i = 0; i < n; i++) {
        uint32_t a = 2 + i, b = 2 + (i + 1) % n;
        tm_face(t, 0, a, b);
        tm_face(t, 1, b, a);
    }
}

/* (w+1) x (h+1) grid over a bumpy height field, each quad split along a random diagonal
 * (so boundary vertices get valences 2..5: every configuration of the paper's rule). */
static void tm_grid(tmesh *t, uint32_t w, uint32_t h, uint32_t seed, int flat)
{
    uint32_t i, j, s = seed;
    tm_clear(t);
    for (j = 0; j <= h; j++)
        for (i = 0; i <= w; i++)
            tm_vert_j(t, &s, (int32_t)i * 512, (int32_t)j * 512, flat ? 77 : 0, 90, 90, flat ? 0 : 300);
    for (j = 0; j < h; j++)
        for (i = 0; i < w; i++) {
            uint32_t a = j * (w + 1) + i, b = a + 1, c = a + w + 2, d = a + w + 1;
            if (h_rand(&s) & 1u) {
                tm_face(t, a, b, c);
                tm_face(t, a, c, d);
            } else {
                tm_face(t, a, b, d);
                tm_face(t, b, c, d);
            }
        }
}

/* n x m torus, random diagonals, with sharp features: a closed crease loop (ring i = 0), an
 * open crease line ending in two darts (column j = 0, i = 2..5), and a short line from the
 * loop (column j = m/2, i = 0..2) that makes a corner (3 sharp edges) where it meets it and
 * a dart at its end. */
static void tm_torus(tmesh *t, uint32_t n, uint32_t m, uint32_t seed)
{
    uint32_t i, j, s = seed;
    tm_clear(t);
    for (i = 0; i < n; i++) {
        subd_real cu = subd_cos_turns((int32_t)i, (int32_t)n), su = subd_sin_turns((int32_t)i, (int32_t)n);
        for (j = 0; j < m; j++) {
            subd_real cv = subd_cos_turns((int32_t)j, (int32_t)m), sv = subd_sin_turns((int32_t)j, (int32_t)m);
#if SUBD_FIXED
            int64_t r = 2048 * 65536 + (int64_t)cv * 800;  /* Q16 * 65536 */
            int32_t x = (int32_t)((r / 65536 * cu + 32768) >> 16), y = (int32_t)((r / 65536 * su + 32768) >> 16);
            int32_t z = (int32_t)(((int64_t)sv * 800 + 32768) >> 16);
#else
            float r = 2048.0f + cv * 800.0f;
            int32_t x = (int32_t)(r * cu), y = (int32_t)(r * su), z = (int32_t)(sv * 800.0f);
#endif
            tm_vert_j(t, &s, x, y, z, 60, 60, 60);
        }
    }
    for (i = 0; i < n; i++)
        for (j = 0; j < m; j++) {
            uint32_t a = i * m + j, b = ((i + 1) % n) * m + j;
            uint32_t c = ((i + 1) % n) * m + (j + 1) % m, d = i * m + (j + 1) % m;
            if (h_rand(&s) & 1u) {
                tm_face(t, a, b, c);
                tm_face(t, a, c, d);
            } else {
                tm_face(t, a, b, d);
                tm_face(t, b, c, d);
            }
        }
    for (j = 0; j < m; j++) tm_sharp(t, j, (j + 1) % m);
    for (i = 2; i < 5; i++) tm_sharp(t, i * m, (i + 1) * m);
    for (i = 0; i < 2; i++) tm_sharp(t, i * m + m / 2, (i + 1) * m + m / 2);
}

/* Boundary vertex 0 with k neighbours on a jittered half circle (k - 1 faces), and a
 * ring of 2k - 1 vertices around them: a boundary fan of any valence. */
static void tm_fan(tmesh *t, uint32_t k, uint32_t seed)
{
    uint32_t i, s = seed;
    tm_clear(t);
    tm_vert_j(t, &s, 0, 0, 0, 0, 0, 100);
    for (i = 0; i < k; i++) {
        subd_real c = subd_cos_turns((int32_t)i, 2 * (int32_t)(k - 1)), sn = subd_sin_turns((int32_t)i, 2 * (int32_t)(k - 1));
#if SUBD_FIXED
        int32_t x = (c * 1024 + 32768) >> 16, y = (sn * 1024 + 32768) >> 16;
#else
        int32_t x = (int32_t)(c * 1024.0f), y = (int32_t)(sn * 1024.0f);
#endif
        tm_vert_j(t, &s, x, y, 0, 60, 60, 250);
    }
    for (i = 0; i < 2 * k - 1; i++) {
        subd_real c = subd_cos_turns((int32_t)i, 4 * (int32_t)(k - 1)), sn = subd_sin_turns((int32_t)i, 4 * (int32_t)(k - 1));
#if SUBD_FIXED
        int32_t x = (c * 2048 + 32768) >> 16, y = (sn * 2048 + 32768) >> 16;
#else
        int32_t x = (int32_t)(c * 2048.0f), y = (int32_t)(sn * 2048.0f);
#endif
        tm_vert_j(t, &s, x, y, 0, 60, 60, 250);
    }
    for (i = 0; i + 1 < k; i++) {
        uint32_t p = 1 + i, q = 1 + k + 2 * i;
        tm_face(t, 0, p, p + 1);
        tm_face(t, p, q, q + 1);
        tm_face(t, p, q + 1, p + 1);
        tm_face(t, p + 1, q + 1, q + 2);
    }
}

static int tm_build(subd_arena *a, const tmesh *t, subd_mesh *m)
{
    subd_face_list fl;
    subd_diag d;
    uint32_t k, h;
    fl.num_verts = t->nv;
    fl.pos = t->pos;
    fl.num_faces = t->nf;
    fl.face_size = 0;
    fl.index = t->idx;
    fl.num_lines = 0;
    fl.line_size = 0;
    fl.line_index = 0;
    if (subd_mesh_build(a, &fl, m, &d) != SUBD_OK) return 0;
    for (k = 0; k < t->ns; k++) {
        for (h = 0; h < m->num_corners; h++) {
            uint32_t o = m->corner_vert[h], e = subd_he_dest(m, h);
            if ((o == t->sharp[k][0] && e == t->sharp[k][1]) || (o == t->sharp[k][1] && e == t->sharp[k][0])) {
                subd_edge_tag_set(m, h, SUBD_ETAG_CREASE);
                break;
            }
        }
        if (h == m->num_corners) return 0;
    }
    for (k = 0; k < t->nc; k++) m->vert_tag[t->corner[k]] = (uint8_t)(m->vert_tag[t->corner[k]] | SUBD_VTAG_CORNER);
    return 1;
}

/* ------------------------------------------------------------------------------------ */
/* The reference (host only): plain Loop subdivision in double, following one vertex.    */

#if H_HOST
#define RV 6000
#define RF 12000
#define RS 3000
#define RMAXVAL 64
#define REF_KEEP 3      /* keep faces touching a vertex within this many rings         */
#define REF_LEVELS 60 /* default; g_ref_levels */

typedef struct ref_mesh {
    int nv, nf, ns;
    double p[RV][3];
    unsigned char bnd[RV];    /* on a true boundary (not a cut of the patch) */
    unsigned char corner[RV]; /* SUBD_VTAG_CORNER */
    int f[RF][3];
    int s[RS][3];             /* sharp edges: a, b, 1 if a boundary edge */
} ref_mesh;

static ref_mesh g_ra, g_rb;
static int g_ref_levels = REF_LEVELS;
static int g_nsh[RV], g_shn[RV][8], g_shb[RV][8]; /* sharp edges per vertex: count, other end, boundary */
static int g_vfs[RV + 1], g_vf[3 * RF];    /* faces of each vertex (counting sort) */
static int g_eo[RV][RMAXVAL], g_ei[RV][RMAXVAL], g_en[RV]; /* edges: other end, new vertex */
static int g_dist[RV], g_map[RV];

static double rdbl(subd_real x)
{
#if SUBD_FIXED
    return (double)x / 65536.0;
#else
    return (double)x;
#endif
}

static void ref_index(const ref_mesh *m)
{
    int i, k;
    for (i = 0; i <= m->nv; i++) g_vfs[i] = 0;
    for (i = 0; i < m->nf; i++)
        for (k = 0; k < 3; k++) g_vfs[m->f[i][k] + 1]++;
    for (i = 0; i < m->nv; i++) g_vfs[i + 1] += g_vfs[i];
    for (i = 0; i < m->nv; i++) g_en[i] = 0; /* reused as a fill counter */
    for (i = 0; i < m->nf; i++)
        for (k = 0; k < 3; k++) {
            int v = m->f[i][k];
            g_vf[g_vfs[v] + g_en[v]++] = i;
        }
    for (i = 0; i < m->nv; i++) g_nsh[i] = 0;
    for (i = 0; i < m->ns; i++) {
        int a = m->s[i][0], b = m->s[i][1];
        if (g_nsh[a] < 8) { g_shn[a][g_nsh[a]] = b; g_shb[a][g_nsh[a]] = m->s[i][2]; }
        if (g_nsh[b] < 8) { g_shn[b][g_nsh[b]] = a; g_shb[b][g_nsh[b]] = m->s[i][2]; }
        g_nsh[a]++;
        g_nsh[b]++;
    }
}

/* Whether edge (a, b) is sharp (from the per-vertex lists of ref_index). */
static int ref_sharp(const ref_mesh *m, int a, int b, int *isb)
{
    int i;
    (void)m;
    for (i = 0; i < g_nsh[a] && i < 8; i++)
        if (g_shn[a][i] == b) {
            *isb = g_shb[a][i];
            return 1;
        }
    return 0;
}

/* The ordered one-ring of v: faces (v, a, b) counter-clockwise give next(a) = b. An open
 * fan starts at the neighbour that no face leads to. Returns the number of neighbours;
 * *nfaces the number of faces. */
static int ref_ring(const ref_mesh *m, int v, int *ring, int *nfaces)
{
    int a[RMAXVAL], b[RMAXVAL], n = 0, i, j, start, cnt;
    for (i = g_vfs[v]; i < g_vfs[v + 1]; i++) {
        const int *f = m->f[g_vf[i]];
        int k = f[0] == v ? 0 : f[1] == v ? 1 : 2;
        if (n < RMAXVAL) {
            a[n] = f[(k + 1) % 3];
            b[n] = f[(k + 2) % 3];
            n++;
        }
    }
    *nfaces = n;
    if (n == 0) return 0;
    start = a[0];
    for (i = 0; i < n; i++) {
        int led = 0;
        for (j = 0; j < n; j++) if (b[j] == a[i]) led = 1;
        if (!led) { start = a[i]; break; }
    }
    ring[0] = start;
    cnt = 1;
    for (;;) {
        int cur = ring[cnt - 1], nx = -1;
        for (j = 0; j < n; j++) if (a[j] == cur) nx = b[j];
        if (nx < 0 || nx == start || cnt >= RMAXVAL) break;
        ring[cnt++] = nx;
    }
    return cnt;
}

enum { R_SMOOTH, R_DART, R_CREASE, R_CORNER };

static int ref_class(const ref_mesh *m, int v)
{
    if (m->corner[v] || g_nsh[v] >= 3) return R_CORNER;
    return g_nsh[v] == 2 ? R_CREASE : g_nsh[v] == 1 ? R_DART : R_SMOOTH;
}

/* Regular for the paper's rule: a crease vertex of valence 4 on a boundary, or of valence
 * 6 inside with its two sharp edges opposite (three faces on each side). */
static int ref_regular(const ref_mesh *m, int v)
{
    int ring[RMAXVAL], nf, n, i, i0 = -1, i1 = -1;
    if (ref_class(m, v) != R_CREASE) return 0;
    n = ref_ring(m, v, ring, &nf);
    if (m->bnd[v]) return n == 4;
    if (n != 6) return 0;
    for (i = 0; i < n; i++) {
        if (ring[i] == g_shn[v][0]) i0 = i;
        if (ring[i] == g_shn[v][1]) i1 = i;
    }
    return i0 >= 0 && i1 >= 0 && (i0 - i1 == 3 || i1 - i0 == 3);
}

static double ref_beta(int n)
{
    double x = 0.375 + 0.25 * cos(2.0 * REF_PI / n);
    return (0.625 - x * x) / n;
}

/* New vertex on edge (a, b); faces of a give the opposite vertices. */
static void ref_edge_point(const ref_mesh *m, subd_loop_boundary rule, int a, int b, double *o)
{
    int isb = 0, i, k, q[2], nq = 0;
    if (ref_sharp(m, a, b, &isb)) {
        double wa = 0.5;
        if (rule == SUBD_LOOP_BOUNDARY_PAPER) {
            int ra = ref_regular(m, a), rb = ref_regular(m, b);
            if (ra && !rb) wa = 0.625;
            if (!ra && rb) wa = 0.375;
        }
        for (k = 0; k < 3; k++) o[k] = wa * m->p[a][k] + (1.0 - wa) * m->p[b][k];
        return;
    }
    for (i = g_vfs[a]; i < g_vfs[a + 1]; i++) {
        const int *f = m->f[g_vf[i]];
        if (f[0] == b || f[1] == b || f[2] == b) {
            int c = (f[0] != a && f[0] != b) ? f[0] : (f[1] != a && f[1] != b) ? f[1] : f[2];
            if (nq < 2) q[nq++] = c;
        }
    }
    if (nq < 2) { /* a cut of the patch: any value, it is discarded */
        for (k = 0; k < 3; k++) o[k] = 0.5 * (m->p[a][k] + m->p[b][k]);
        return;
    }
    for (k = 0; k < 3; k++)
        o[k] = 0.375 * (m->p[a][k] + m->p[b][k]) + 0.125 * (m->p[q[0]][k] + m->p[q[1]][k]);
}

static void ref_vertex_point(const ref_mesh *m, int v, double *o)
{
    int cls = ref_class(m, v), ring[RMAXVAL], nf, n, i, k;
    if (cls == R_CORNER) {
        for (k = 0; k < 3; k++) o[k] = m->p[v][k];
    } else if (cls == R_CREASE) {
        for (k = 0; k < 3; k++)
            o[k] = 0.75 * m->p[v][k] + 0.125 * (m->p[g_shn[v][0]][k] + m->p[g_shn[v][1]][k]);
    } else {
        double b;
        n = ref_ring(m, v, ring, &nf);
        if (n == 0) {
            for (k = 0; k < 3; k++) o[k] = m->p[v][k];
            return;
        }
        b = ref_beta(n);
        for (k = 0; k < 3; k++) {
            double sum = 0.0;
            for (i = 0; i < n; i++) sum += m->p[ring[i]][k];
            o[k] = (1.0 - n * b) * m->p[v][k] + b * sum;
        }
    }
}

/* Index of the new vertex on edge (a, b), creating it. */
static int ref_edge_vertex(const ref_mesh *m, ref_mesh *o, subd_loop_boundary rule, int a, int b)
{
    int lo = a < b ? a : b, hi = a < b ? b : a, i, isb = 0;
    for (i = 0; i < g_en[lo]; i++) if (g_eo[lo][i] == hi) return g_ei[lo][i];
    i = o->nv++;
    ref_edge_point(m, rule, a, b, o->p[i]);
    o->corner[i] = 0;
    o->bnd[i] = (unsigned char)(ref_sharp(m, a, b, &isb) && isb);
    if (g_en[lo] < RMAXVAL) {
        g_eo[lo][g_en[lo]] = hi;
        g_ei[lo][g_en[lo]] = i;
        g_en[lo]++;
    }
    return i;
}

static void ref_subdivide(const ref_mesh *m, ref_mesh *o, subd_loop_boundary rule)
{
    int v, i;
    ref_index(m);
    o->nv = m->nv;
    for (v = 0; v < m->nv; v++) {
        ref_vertex_point(m, v, o->p[v]);
        o->bnd[v] = m->bnd[v];
        o->corner[v] = m->corner[v];
        g_en[v] = 0;
    }
    o->nf = 0;
    for (i = 0; i < m->nf; i++) {
        int a = m->f[i][0], b = m->f[i][1], c = m->f[i][2];
        int ab = ref_edge_vertex(m, o, rule, a, b), bc = ref_edge_vertex(m, o, rule, b, c);
        int ca = ref_edge_vertex(m, o, rule, c, a);
        int t[4][3], j, k;
        t[0][0] = a; t[0][1] = ab; t[0][2] = ca;
        t[1][0] = b; t[1][1] = bc; t[1][2] = ab;
        t[2][0] = c; t[2][1] = ca; t[2][2] = bc;
        t[3][0] = ab; t[3][1] = bc; t[3][2] = ca;
        for (j = 0; j < 4; j++)
            for (k = 0; k < 3; k++) o->f[o->nf + j][k] = t[j][k];
        o->nf += 4;
    }
    o->ns = 0;
    for (i = 0; i < m->ns; i++) {
        int a = m->s[i][0], b = m->s[i][1], lo = a < b ? a : b, hi = a < b ? b : a, j, mid = -1;
        for (j = 0; j < g_en[lo]; j++) if (g_eo[lo][j] == hi) mid = g_ei[lo][j];
        if (mid < 0) continue; /* no face uses it any more (cut away) */
        o->s[o->ns][0] = a; o->s[o->ns][1] = mid; o->s[o->ns][2] = m->s[i][2]; o->ns++;
        o->s[o->ns][0] = mid; o->s[o->ns][1] = b; o->s[o->ns][2] = m->s[i][2]; o->ns++;
    }
}

/* Keeps the faces that touch a vertex within REF_KEEP rings of *t (renumbering *t). */
static void ref_crop(const ref_mesh *m, ref_mesh *o, int *t)
{
    int v, i, d, k, nv = 0;
    for (v = 0; v < m->nv; v++) g_dist[v] = 1000;
    g_dist[*t] = 0;
    for (d = 0; d < REF_KEEP; d++)
        for (i = 0; i < m->nf; i++) {
            int near = 0;
            for (k = 0; k < 3; k++) if (g_dist[m->f[i][k]] == d) near = 1;
            if (near)
                for (k = 0; k < 3; k++) if (g_dist[m->f[i][k]] > d + 1) g_dist[m->f[i][k]] = d + 1;
        }
    for (v = 0; v < m->nv; v++) g_map[v] = -1;
    o->nf = 0;
    for (i = 0; i < m->nf; i++) {
        int keep = 0;
        for (k = 0; k < 3; k++) if (g_dist[m->f[i][k]] <= REF_KEEP) keep = 1;
        if (!keep) continue;
        for (k = 0; k < 3; k++) {
            int u = m->f[i][k];
            if (g_map[u] < 0) {
                g_map[u] = nv;
                o->p[nv][0] = m->p[u][0]; o->p[nv][1] = m->p[u][1]; o->p[nv][2] = m->p[u][2];
                o->bnd[nv] = m->bnd[u];
                o->corner[nv] = m->corner[u];
                nv++;
            }
            o->f[o->nf][k] = g_map[u];
        }
        o->nf++;
    }
    o->nv = nv;
    o->ns = 0;
    for (i = 0; i < m->ns; i++) {
        int a = g_map[m->s[i][0]], b = g_map[m->s[i][1]];
        if (a < 0 || b < 0) continue;
        o->s[o->ns][0] = a; o->s[o->ns][1] = b; o->s[o->ns][2] = m->s[i][2]; o->ns++;
    }
    *t = g_map[*t];
}

/* Loads a test mesh; boundary edges (one face) become sharp boundary edges. */
static void ref_load(const tmesh *t, ref_mesh *m)
{
    uint32_t i, k, j;
    m->nv = (int)t->nv;
    m->nf = (int)t->nf;
    m->ns = 0;
    for (i = 0; i < t->nv; i++) {
        for (k = 0; k < 3; k++) m->p[i][k] = rdbl(t->pos[3 * i + k]);
        m->bnd[i] = 0;
        m->corner[i] = 0;
    }
    for (i = 0; i < t->nc; i++) m->corner[t->corner[i]] = 1;
    for (i = 0; i < t->nf; i++)
        for (k = 0; k < 3; k++) m->f[i][k] = (int)t->idx[3 * i + k];
    for (i = 0; i < t->nf; i++)
        for (k = 0; k < 3; k++) {
            uint32_t a = t->idx[3 * i + k], b = t->idx[3 * i + (k + 1) % 3];
            int twin = 0;
            for (j = 0; j < t->nf && !twin; j++) {
                uint32_t c;
                for (c = 0; c < 3; c++)
                    if (t->idx[3 * j + c] == b && t->idx[3 * j + (c + 1) % 3] == a) twin = 1;
            }
            if (!twin) {
                m->s[m->ns][0] = (int)a; m->s[m->ns][1] = (int)b; m->s[m->ns][2] = 1; m->ns++;
                m->bnd[a] = m->bnd[b] = 1;
            }
        }
    for (i = 0; i < t->ns; i++) {
        m->s[m->ns][0] = (int)t->sharp[i][0]; m->s[m->ns][1] = (int)t->sharp[i][1]; m->s[m->ns][2] = 0;
        m->ns++;
    }
}

static void v3_cross(const double *a, const double *b, double *c)
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

static double v3_len(const double *a) { return sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

/* Configuration of a crease vertex for the paper's rule: 0..5 = (R;RR) (R;RE) (R;EE)
 * (E;RR) (E;RE) (E;EE), from the level-0 mesh. */
static int ref_config(const tmesh *t, uint32_t v)
{
    int rv, r0, r1, ne;
    ref_load(t, &g_ra);
    ref_index(&g_ra);
    if (ref_class(&g_ra, (int)v) != R_CREASE) return -1;
    rv = ref_regular(&g_ra, (int)v);
    r0 = ref_regular(&g_ra, g_shn[v][0]);
    r1 = ref_regular(&g_ra, g_shn[v][1]);
    ne = (r0 ? 0 : 1) + (r1 ? 0 : 1);
    return (rv ? 0 : 3) + ne;
}

/* The normal of the tracked vertex's fan (see ref_limit); returns the fan's conditioning,
 * |sum of face normals| / (longest edge at the vertex)^2. */
static double ref_fan_normal(const ref_mesh *m, int tv, int cls, double *nrm)
{
    double big = 0, tot = 0;
    double acc[3] = {0, 0, 0}, sec[3] = {0, 0, 0};
    int ring[RMAXVAL], nf, n, i, j, k, start = 0;
    ref_index(m);
    n = ref_ring(m, tv, ring, &nf);
    for (i = 0; i < n; i++) /* start a sector at a sharp neighbour when there is one */
        if (g_nsh[tv] > 0 && (ring[i] == g_shn[tv][0] || ring[i] == g_shn[tv][1] ||
                              (g_nsh[tv] > 2 && ring[i] == g_shn[tv][2]))) {
            start = i;
            break;
        }
    for (j = 0; j < nf; j++) {
        int a = ring[(start + j) % n], b = ring[(start + j + 1) % n], isb = 0;
        double da[3], db[3], cr[3];
        if (nf < n && start + j + 1 >= n) break; /* open fan: n - 1 faces */
        for (k = 0; k < 3; k++) { da[k] = m->p[a][k] - m->p[tv][k]; db[k] = m->p[b][k] - m->p[tv][k]; }
        v3_cross(da, db, cr);
        if (v3_len(da) > big) big = v3_len(da);
        if (v3_len(db) > big) big = v3_len(db);
        tot += v3_len(cr);
        for (k = 0; k < 3; k++) sec[k] += cr[k];
        if (cls != R_SMOOTH && cls != R_DART && (ref_sharp(m, tv, b, &isb) || j == nf - 1)) {
            double l = v3_len(sec);
            if (l > 0) for (k = 0; k < 3; k++) acc[k] += sec[k] / l;
            sec[0] = sec[1] = sec[2] = 0.0;
        }
    }
    if (cls == R_SMOOTH || cls == R_DART) for (k = 0; k < 3; k++) acc[k] = sec[k];
    {
        double l = v3_len(acc);
        for (k = 0; k < 3; k++) nrm[k] = l > 0 ? acc[k] / l : 0.0;
    }
    (void)tot;
    return big > 0 ? v3_len(acc) * (cls == R_SMOOTH || cls == R_DART ? 1.0 : 0.0) / (big * big) +
                         (cls == R_SMOOTH || cls == R_DART ? 0.0 : tot / (big * big)) : 0.0;
}

static double ref_angle(const double *a, const double *b)
{
    double d = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    if (d > 1.0) d = 1.0;
    if (d < -1.0) d = -1.0;
    return acos(d) * 180.0 / REF_PI;
}

static double g_best[3], g_best_change;

/* Limit position and normal of vertex v of t under the rule set (REF_LEVELS levels). The
 * normal: per sector between sharp edges the normalised sum of the fan's face normals,
 * then the normalised sum over sectors, taken at the level where it changed least from
 * the level before (it converges geometrically until the fan gets too thin for double
 * precision, e.g. at a valence-2 boundary vertex whose across direction decays like
 * 2^-L relative to the along direction). Returns the class. */
static int ref_limit(const tmesh *t, uint32_t v, subd_loop_boundary rule, double *pos, double *nrm)
{
    double off[3] = {0, 0, 0}, scale = 1.0, prev[3] = {0, 0, 0};
    int tv = (int)v, lev, i, k, ring[RMAXVAL], nf, n, cls;
    g_best_change = 1e9;
    ref_load(t, &g_ra);
    ref_index(&g_ra);
    cls = ref_class(&g_ra, tv);
    for (lev = 0; lev < g_ref_levels; lev++) {
        double c[3], big = 0.0;
        ref_crop(&g_ra, &g_rb, &tv);
        ref_subdivide(&g_rb, &g_ra, rule);
        /* renormalise: tracked vertex to the origin, its ring to unit size */
        ref_index(&g_ra);
        n = ref_ring(&g_ra, tv, ring, &nf);
        for (k = 0; k < 3; k++) c[k] = g_ra.p[tv][k];
        for (i = 0; i < n; i++) {
            double d[3];
            for (k = 0; k < 3; k++) d[k] = g_ra.p[ring[i]][k] - c[k];
            if (v3_len(d) > big) big = v3_len(d);
        }
        if (big == 0.0) big = 1.0;
        for (k = 0; k < 3; k++) off[k] += c[k] / scale;
        for (i = 0; i < g_ra.nv; i++)
            for (k = 0; k < 3; k++) g_ra.p[i][k] = (g_ra.p[i][k] - c[k]) / big;
        scale /= big;
        {
            double cur[3], ch, cond;
            cond = ref_fan_normal(&g_ra, tv, cls, cur);
            ch = ref_angle(cur, prev);
            if (lev >= 3 && cond > 1e-6 && ch <= g_best_change) {
                g_best_change = ch;
                for (k = 0; k < 3; k++) g_best[k] = cur[k];
            }
            for (k = 0; k < 3; k++) prev[k] = cur[k];
        }
    }
    for (k = 0; k < 3; k++) pos[k] = off[k];
    for (k = 0; k < 3; k++) nrm[k] = g_best[k];
    return cls;
}
#endif

/* ------------------------------------------------------------------------------------ */
/* Properties that run everywhere (host and QEMU)                                          */

static uint32_t hash_reals(uint32_t h, const subd_real *x, uint32_t n)
{
    uint32_t i;
    for (i = 0; i < n; i++) {
        uint32_t b = subd_real_bits(x[i]);
        h = h_fnv(h, &b, 4); /* little-endian on every target we run */
    }
    return h;
}

/* Limit of a mesh built from t in h_arena_buf; returns 0 on any failure. */
static int limit_of(const tmesh *t, subd_loop_boundary rule, subd_arena *a, subd_mesh *m, subd_real **pos,
                    subd_real **nrm)
{
    subd_diag d;
    subd_arena_init(a, h_arena_buf, H_ARENA_BYTES);
    if (!tm_build(a, t, m)) return 0;
    return subd_loop_limit(a, m, &(subd_loop_limit_opts){rule, (nrm) ? SUBD_LOOP_LIMIT_NORMALS : 0u}, pos, nrm, &d) == SUBD_OK;
}

/* The interior weight chi(n) seen through a fan: centre 0, neighbour 0 at x = 1. */
static void weights_test(void)
{
    uint32_t n, i;
    for (n = 3; n <= 12; n++) {
        subd_arena a;
        subd_mesh m;
        subd_real *pos, *nrm;
        tm_bipyramid(&g_tm, n, 1u);
        for (i = 0; i < 3u * g_tm.nv; i++) g_tm.pos[i] = 0;
        g_tm.pos[3 * 2] = SUBD_REAL_ONE; /* equator vertex 2: a neighbour of apex 0 */
        if (!CHECK(limit_of(&g_tm, SUBD_LOOP_BOUNDARY_PAPER, &a, &m, &pos, &nrm))) return;
        CHECK(pos[1] == 0 && pos[2] == 0);
        if (n == 3) CHECK(pos[0] == SUBD_REAL_FRAC(1, 5));   /* chi(3) = 1/5 */
        if (n == 6) CHECK(pos[0] == SUBD_REAL_FRAC(1, 12));  /* regular: 1/12, centre 1/2 */
#if H_HOST
        {
            double x = 0.375 + 0.25 * cos(2.0 * REF_PI / n), bb = 0.625 - x * x;
            double chi = 8.0 * bb / (n * (8.0 * bb + 3.0));
#if SUBD_FIXED
            CHECK(fabs(rdbl(pos[0]) - chi) <= 0.5 / 65536.0 + 1e-12); /* rounded once */
#else
            CHECK(fabs(rdbl(pos[0]) - chi) <= 0.5 * ldexp(1.0, ilogb(chi) - 23) + 1e-15);
#endif
        }
#endif
    }
}

/* A constant mesh stays exactly where it is (weights sum to one; float: the difference
 * form), and every tangent vanishes. Both rules, every vertex class. */
static void constant_test(void)
{
    uint32_t r, i, k, bad = 0;
    for (r = 0; r < 2; r++) {
        subd_arena a;
        subd_mesh m;
        subd_real *pos, *nrm;
        tm_torus(&g_tm, 10, 8, 5u);
        for (i = 0; i < g_tm.nv; i++) {
            g_tm.pos[3 * i] = q10(-3377);
            g_tm.pos[3 * i + 1] = q10(12345);
            g_tm.pos[3 * i + 2] = q10(777);
        }
        if (!CHECK(limit_of(&g_tm, r ? SUBD_LOOP_BOUNDARY_BSPLINE : SUBD_LOOP_BOUNDARY_PAPER, &a, &m, &pos, &nrm))) return;
        for (i = 0; i < g_tm.nv; i++)
            for (k = 0; k < 3; k++) {
                if (subd_real_bits(pos[3 * i + k]) != subd_real_bits(g_tm.pos[3 * i + k])) bad++;
                if (nrm[3 * i + k] != 0) bad++;
            }
    }
    CHECK_EQ(bad, 0);
}

/* Translation: Q16.16 exact for any translation (the weights sum to exactly ONE and the sum
 * is exact in 64 bits); float32 within a few ulps of the coordinates. Normals unchanged
 * (float: up to rounding). */
static void translate_test(void)
{
    uint32_t r, i, k, bad = 0, badn = 0;
    static subd_real p0[3 * TMV], n0[3 * TMV];
    for (r = 0; r < 2; r++) {
        subd_arena a;
        subd_mesh m;
        subd_real *pos, *nrm, t[3];
        subd_loop_boundary rule = r ? SUBD_LOOP_BOUNDARY_BSPLINE : SUBD_LOOP_BOUNDARY_PAPER;
        tm_torus(&g_tm, 10, 8, 9u);
        if (!CHECK(limit_of(&g_tm, rule, &a, &m, &pos, &nrm))) return;
        for (i = 0; i < 3u * g_tm.nv; i++) { p0[i] = pos[i]; n0[i] = nrm[i]; }
        t[0] = q10(5 * 1024);
        t[1] = q10(-7 * 1024 + 3);
        t[2] = q10(123);
        for (i = 0; i < g_tm.nv; i++)
            for (k = 0; k < 3; k++) g_tm.pos[3 * i + k] += t[k];
        if (!CHECK(limit_of(&g_tm, rule, &a, &m, &pos, &nrm))) return;
        for (i = 0; i < g_tm.nv; i++)
            for (k = 0; k < 3; k++) {
                subd_real want = p0[3 * i + k] + t[k], got = pos[3 * i + k];
#if SUBD_FIXED
                if (got != want) bad++;
                if (nrm[3 * i + k] != n0[3 * i + k]) badn++;
#else
                float e = got - want, tol = 8.0f * 1.2e-7f * 16.0f;
                if (e > tol || e < -tol) bad++;
                e = nrm[3 * i + k] - n0[3 * i + k];
                if (e > 1e-3f || e < -1e-3f) badn++;
#endif
            }
    }
    CHECK_EQ(bad, 0);
    CHECK_EQ(badn, 0);
}

/* A planar mesh (z = const) with boundary, creases, darts and corners: every normal is
 * exactly (0, 0, 1) (counter-clockwise faces seen from +z). */
static void planar_test(void)
{
    uint32_t r, i, bad = 0, zero = 0;
    for (r = 0; r < 2; r++) {
        subd_arena a;
        subd_mesh m;
        subd_real *pos, *nrm;
        tm_grid(&g_tm, 6, 5, 21u, 1);
        for (i = 0; i < 6; i++) tm_sharp(&g_tm, 2 * 7 + i, 2 * 7 + i + 1); /* crease row j = 2 */
        tm_sharp(&g_tm, 3 * 7 + 3, 4 * 7 + 3);                            /* a dart line */
        g_tm.corner[g_tm.nc++] = 0;
        g_tm.corner[g_tm.nc++] = 3 * 7 + 5; /* a tagged corner inside */
        if (!CHECK(limit_of(&g_tm, r ? SUBD_LOOP_BOUNDARY_BSPLINE : SUBD_LOOP_BOUNDARY_PAPER, &a, &m, &pos, &nrm))) return;
        for (i = 0; i < g_tm.nv; i++) {
            if (nrm[3 * i] != 0 || nrm[3 * i + 1] != 0 || nrm[3 * i + 2] != SUBD_REAL_ONE) bad++;
            if (pos[3 * i + 2] != q10(77)) zero++;
        }
    }
    CHECK_EQ(bad, 0);
    CHECK_EQ(zero, 0);
}

static int read_corpus(const char *name, subd_arena *a, subd_mesh *m)
{
    const corpus_file *f = corpus_find(name);
    subd_diag d;
    if (!f) return 0;
    subd_arena_init(a, h_arena_buf, H_ARENA_BYTES);
    return subd_obj_read(a, f->data, f->len, m, &d) == SUBD_OK;
}

/* Normals of a closed convex mesh with counter-clockwise faces point outwards. */
static void convex_test(void)
{
    subd_arena a;
    subd_mesh m;
    subd_real *pos, *nrm;
    subd_diag d;
    uint32_t i, bad = 0;
    if (!CHECK(read_corpus("test/data/icosahedron.obj", &a, &m))) return;
    if (!CHECK_EQ(subd_loop_limit(&a, &m, &(subd_loop_limit_opts){SUBD_LOOP_BOUNDARY_PAPER, SUBD_LOOP_LIMIT_NORMALS}, &pos, &nrm, &d), SUBD_OK)) return;
    for (i = 0; i < m.num_verts; i++) {
        uint32_t ovf = 0;
        subd_real dot = subd_add(subd_add(subd_mul(nrm[3 * i], m.pos[3 * i], &ovf),
                                          subd_mul(nrm[3 * i + 1], m.pos[3 * i + 1], &ovf), &ovf),
                                 subd_mul(nrm[3 * i + 2], m.pos[3 * i + 2], &ovf), &ovf);
        if (!(dot > 0)) bad++;
    }
    CHECK_EQ(bad, 0);
}

/* subd_loop_limit_apply gives the positions of subd_loop_limit, bit for bit. */
static void apply_test(void)
{
    static subd_real lim[3 * TMV];
    uint32_t r, i, bad = 0, ovf = 0;
    for (r = 0; r < 2; r++) {
        subd_arena a;
        subd_mesh m;
        subd_real *pos, *nrm;
        subd_loop_boundary rule = r ? SUBD_LOOP_BOUNDARY_BSPLINE : SUBD_LOOP_BOUNDARY_PAPER;
        tm_torus(&g_tm, 10, 8, 3u);
        if (!CHECK(limit_of(&g_tm, rule, &a, &m, &pos, &nrm))) return;
        subd_loop_limit_apply(&m, rule, m.pos, lim, &ovf);
        for (i = 0; i < 3u * m.num_verts; i++) if (subd_real_bits(lim[i]) != subd_real_bits(pos[i])) bad++;
    }
    CHECK_EQ(bad, 0);
    CHECK_EQ(ovf, 0);
}

/* Consistency with the refinement (loop.c): a control vertex's limit point and normal do not
 * change when the mesh is subdivided first (vertex i stays vertex i), for every class and
 * both rule sets. Float32: within 2e-6 of the mesh size; Q16.16: within 3 LSB (each level
 * of refinement rounds once). Normals (corners excepted) within 0.36 degree (float) or 0.8
 * degree (Q16.16: the dot product test itself rounds). */
static void refine_test(void)
{
    static subd_real p0[3 * TMV], n0[3 * TMV];
    uint32_t r, f, lev, bad = 0, badn = 0, i, k;
    for (f = 0; f < 3; f++) {
        for (r = 0; r < 2; r++) {
            subd_loop_boundary rule = r ? SUBD_LOOP_BOUNDARY_BSPLINE : SUBD_LOOP_BOUNDARY_PAPER;
            subd_arena a;
            subd_mesh m, out;
            subd_real *pos, *nrm;
            subd_diag d;
            uint32_t nv;
            if (f == 0) tm_torus(&g_tm, 10, 8, 5u);
            if (f == 1) {
                tm_grid(&g_tm, 5, 4, 11u, 0);
                g_tm.corner[g_tm.nc++] = 0;
                g_tm.corner[g_tm.nc++] = 29;
            }
            if (f == 2) {
                tm_bipyramid(&g_tm, 7, 12u);
                tm_sharp(&g_tm, 0, 2);
            }
            if (!CHECK(limit_of(&g_tm, rule, &a, &m, &pos, &nrm))) return;
            nv = m.num_verts;
            for (i = 0; i < 3u * nv; i++) { p0[i] = pos[i]; n0[i] = nrm[i]; }
            for (lev = 1; lev <= 2; lev++) {
                subd_loop_opts o;
                uint32_t mark = subd_arena_mark(&a);
                o.levels = lev;
                o.boundary = rule;
                o.flags = SUBD_LOOP_ADJACENCY;
                if (!CHECK_EQ(subd_loop(&a, &m, &o, &out, &d), SUBD_OK)) return;
                if (!CHECK_EQ(subd_loop_limit(&a, &out, &(subd_loop_limit_opts){rule, SUBD_LOOP_LIMIT_NORMALS}, &pos, &nrm, &d), SUBD_OK)) return;
                for (i = 0; i < nv; i++) {
                    for (k = 0; k < 3; k++) {
                        subd_real e = pos[3 * i + k] - p0[3 * i + k];
#if SUBD_FIXED
                        if (e > 3 || e < -3) bad++;
#else
                        if (e > 2e-6f * 8.0f || e < -2e-6f * 8.0f) bad++;
#endif
                    }
                    {
                        /* normals: dot of unit vectors */
                        uint32_t ovf = 0;
                        subd_real dot = subd_add(subd_add(subd_mul(nrm[3 * i], n0[3 * i], &ovf),
                                                          subd_mul(nrm[3 * i + 1], n0[3 * i + 1], &ovf), &ovf),
                                                 subd_mul(nrm[3 * i + 2], n0[3 * i + 2], &ovf), &ovf);
                        int corner = (m.vert_tag[i] & SUBD_VTAG_CORNER) != 0;
                        /* float: 0.99998 = cos 0.36 deg; Q16.16: the dot of two rounded unit
                         * vectors, itself rounded three times, can be 2 LSB below 1 for equal
                         * directions, so 0.9999 (0.8 deg) */
                        if (!corner && dot < (SUBD_FIXED ? SUBD_REAL_FRAC(9999, 10000) : SUBD_REAL_FRAC(99998, 100000))) badn++;
                    }
                }
                subd_arena_rewind(&a, mark);
            }
        }
    }
    CHECK_EQ(bad, 0);
    CHECK_EQ(badn, 0);
}

typedef struct limit_call {
    const subd_mesh *m;
    subd_real *out[2]; /* positions, normals */
    int normals;
} limit_call;

static int limit_run(void *ctx, subd_arena *a, subd_diag *d)
{
    limit_call *c = (limit_call *)ctx;
    return subd_loop_limit(a, c->m, &(subd_loop_limit_opts){SUBD_LOOP_BOUNDARY_PAPER, c->normals ? SUBD_LOOP_LIMIT_NORMALS : 0u}, &c->out[0], c->normals ? &c->out[1] : 0, d);
}

/* only the results stay allocated: all of the plan */
static void limit_ok(void *ctx, const subd_arena *a, const subd_diag *d)
{
    (void)ctx;
    (void)d;
    CHECK_EQ(a->used, a->peak);
}

/* Every arena size below the plan fails cleanly; the plan itself is enough and is the
 * measured peak; nothing is written past the arena. */
static void arena_test(void)
{
    static uint8_t buf[8 + 4096 + 64] __attribute__((aligned(8)));
    subd_arena ma;
    subd_mesh m;
    uint32_t plan, plan_np;
    limit_call c;
    h_sweep s;
    tm_torus(&g_tm, 10, 8, 5u);
    subd_arena_init(&ma, h_arena_buf, H_ARENA_BYTES);
    if (!CHECK(tm_build(&ma, &g_tm, &m))) return;
    CHECK_EQ(subd_loop_limit_plan(&m, &(subd_loop_limit_opts){SUBD_LOOP_BOUNDARY_PAPER, SUBD_LOOP_LIMIT_NORMALS}, &plan, 0), SUBD_OK);
    CHECK_EQ(subd_loop_limit_plan(&m, &(subd_loop_limit_opts){SUBD_LOOP_BOUNDARY_BSPLINE, 0u}, &plan_np, 0), SUBD_OK);
    CHECK_EQ(plan, 2u * SUBD_ALIGN_UP(3u * 80u * (uint32_t)sizeof(subd_real)));
    CHECK_EQ(plan_np, SUBD_ALIGN_UP(3u * 80u * (uint32_t)sizeof(subd_real)));
    c.m = &m;
    for (c.normals = 0; c.normals < 2; c.normals++) {
        s = h_sweep_make(limit_run, &c, buf, sizeof buf, c.normals ? plan : plan_np);
        s.prefix = 8;
        s.out = c.out;
        s.out_bytes = sizeof c.out;
        s.in_mesh = &m;
        s.ok = limit_ok;
        if (!h_arena_sweep(&s)) return;
    }
}

static void errors_test(void)
{
    subd_arena a;
    subd_mesh m;
    subd_real *pos = 0, *nrm = 0;
    subd_diag d;
    uint32_t plan, mark;
    /* a quad mesh */
    if (!CHECK(read_corpus("test/data/cube_quad.obj", &a, &m))) return;
    mark = subd_arena_mark(&a);
    CHECK_EQ(subd_loop_limit_plan(&m, &(subd_loop_limit_opts){SUBD_LOOP_BOUNDARY_PAPER, SUBD_LOOP_LIMIT_NORMALS}, &plan, 0), SUBD_ERR_NOT_TRIANGLES);
    CHECK_FAIL(subd_loop_limit(&a, &m, &(subd_loop_limit_opts){SUBD_LOOP_BOUNDARY_PAPER, SUBD_LOOP_LIMIT_NORMALS}, &pos, &nrm, &d), &d, SUBD_ERR_NOT_TRIANGLES);
    CHECK_EQ(d.status, SUBD_ERR_NOT_TRIANGLES);
    CHECK_EQ(d.face, 0);
    CHECK_EQ(subd_arena_mark(&a), mark);
    CHECK(pos == 0 && nrm == 0);
    /* parameters */
    if (!CHECK(read_corpus("test/data/icosahedron.obj", &a, &m))) return;
    CHECK_EQ(subd_loop_limit_plan(0, &(subd_loop_limit_opts){SUBD_LOOP_BOUNDARY_PAPER, SUBD_LOOP_LIMIT_NORMALS}, &plan, 0), SUBD_ERR_PARAM);
    CHECK_EQ(subd_loop_limit_plan(&m, &(subd_loop_limit_opts){SUBD_LOOP_BOUNDARY_PAPER, SUBD_LOOP_LIMIT_NORMALS}, 0, 0), SUBD_ERR_PARAM);
    CHECK_EQ(subd_loop_limit_plan(&m, &(subd_loop_limit_opts){(subd_loop_boundary)7, SUBD_LOOP_LIMIT_NORMALS}, &plan, 0), SUBD_ERR_PARAM);
    CHECK_FAIL(subd_loop_limit(0, &m, &(subd_loop_limit_opts){SUBD_LOOP_BOUNDARY_PAPER, 0u}, &pos, 0, &d), &d, SUBD_ERR_PARAM);
    CHECK_FAIL(subd_loop_limit(&a, 0, &(subd_loop_limit_opts){SUBD_LOOP_BOUNDARY_PAPER, 0u}, &pos, 0, &d), &d, SUBD_ERR_PARAM);
    CHECK_FAIL(subd_loop_limit(&a, &m, &(subd_loop_limit_opts){SUBD_LOOP_BOUNDARY_PAPER, 0u}, 0, 0, &d), &d, SUBD_ERR_PARAM);
    CHECK_EQ(subd_loop_limit(&a, &m, &(subd_loop_limit_opts){(subd_loop_boundary)7, 0u}, &pos, 0, 0), SUBD_ERR_PARAM);
    CHECK(pos == 0);
#if !SUBD_FIXED
    {
        /* float: coordinates near FLT_MAX make a difference overflow: SUBD_ERR_RANGE */
        uint32_t i;
        mark = subd_arena_mark(&a);
        for (i = 0; i < m.num_verts; i++) m.pos[3 * i] = (i & 1u) ? 3.0e38f : -3.0e38f;
        CHECK_FAIL(subd_loop_limit(&a, &m, &(subd_loop_limit_opts){SUBD_LOOP_BOUNDARY_PAPER, SUBD_LOOP_LIMIT_NORMALS}, &pos, &nrm, &d), &d, SUBD_ERR_RANGE);
        CHECK_EQ(subd_arena_mark(&a), mark);
        CHECK(pos == 0 && nrm == 0);
    }
#endif
}

/* Output hashes (compared between host and QEMU) of limit positions and normals. */
static void hashes_test(void)
{
    static const char *const files[] = {"test/data/icosahedron.obj", "test/data/torus_tri.obj",
                                        "test/data/grid_tri_8x8.obj", "test/data/hexfan.obj"};
    static const char *const names[2][4] = {
        {"limit_paper_icosahedron", "limit_paper_torus_tri", "limit_paper_grid_8x8", "limit_paper_hexfan"},
        {"limit_bspline_icosahedron", "limit_bspline_torus_tri", "limit_bspline_grid_8x8", "limit_bspline_hexfan"}};
    uint32_t f, r;
    for (f = 0; f < 4; f++) {
        for (r = 0; r < 2; r++) {
            subd_arena a;
            subd_mesh m;
            subd_real *pos, *nrm;
            subd_diag d;
            uint32_t h = 2166136261u;
            if (!CHECK(read_corpus(files[f], &a, &m))) return;
            if (!CHECK_EQ(subd_loop_limit(&a, &m, &(subd_loop_limit_opts){r ? SUBD_LOOP_BOUNDARY_BSPLINE : SUBD_LOOP_BOUNDARY_PAPER, SUBD_LOOP_LIMIT_NORMALS}, &pos,
                                          &nrm, &d),
                          SUBD_OK))
                return;
            h = hash_reals(h, pos, 3u * m.num_verts);
            h = hash_reals(h, nrm, 3u * m.num_verts);
            h_hash(names[r][f], h);
        }
    }
    for (r = 0; r < 2; r++) {
        subd_arena a;
        subd_mesh m;
        subd_real *pos, *nrm;
        uint32_t h = 2166136261u, k;
        subd_loop_boundary rule = r ? SUBD_LOOP_BOUNDARY_BSPLINE : SUBD_LOOP_BOUNDARY_PAPER;
        tm_torus(&g_tm, 10, 8, 5u);
        if (!CHECK(limit_of(&g_tm, rule, &a, &m, &pos, &nrm))) return;
        h = hash_reals(hash_reals(h, pos, 3u * m.num_verts), nrm, 3u * m.num_verts);
        for (k = 2; k <= 12; k++) {
            tm_fan(&g_tm, k, 300u + k);
            if (!CHECK(limit_of(&g_tm, rule, &a, &m, &pos, &nrm))) return;
            h = hash_reals(hash_reals(h, pos, 3u * m.num_verts), nrm, 3u * m.num_verts);
        }
        for (k = 3; k <= 16; k++) {
            tm_bipyramid(&g_tm, k, 500u + k);
            tm_sharp(&g_tm, 0, 2);
            if (!CHECK(limit_of(&g_tm, rule, &a, &m, &pos, &nrm))) return;
            h = hash_reals(hash_reals(h, pos, 3u * m.num_verts), nrm, 3u * m.num_verts);
        }
        h_hash(r ? "limit_bspline_features" : "limit_paper_features", h);
    }
}

/* ------------------------------------------------------------------------------------ */
/* Library against the reference (host)                                                   */

#if H_HOST
typedef struct lim_stats {
    double pos_rel;      /* max |lib - ref| / mesh size (float) */
    double lsb_excess;   /* max (|lib - ref| in LSB - allowed) (fixed) */
    double lsb_max;      /* max |lib - ref| in LSB (fixed) */
    double ang[4];       /* max normal angle (degrees) per class */
    uint32_t n[4], bad_pos, bad_nrm;
    uint32_t configs[6];
} lim_stats;

static const char *const g_cls_name[4] = {"smooth", "dart", "crease", "corner"};
static int g_verbose = 0;

static void print_dbl(double x, int decimals)
{
    /* host only: enough for the report lines */
    int32_t ip;
    uint32_t frac, sc = 1, i;
    if (x < 0) { h_str("-"); x = -x; }
    for (i = 0; i < (uint32_t)decimals; i++) sc *= 10u;
    ip = (int32_t)x;
    frac = (uint32_t)((x - ip) * sc + 0.5);
    if (frac >= sc) { ip++; frac -= sc; }
    h_i32(ip);
    h_str(".");
    for (i = sc / 10u; i > 1u && frac < i; i /= 10u) h_str("0");
    h_u32(frac);
}

static double mesh_size(const tmesh *t)
{
    double lo[3] = {1e30, 1e30, 1e30}, hi[3] = {-1e30, -1e30, -1e30}, d[3];
    uint32_t i, k;
    for (i = 0; i < t->nv; i++)
        for (k = 0; k < 3; k++) {
            double x = rdbl(t->pos[3 * i + k]);
            if (x < lo[k]) lo[k] = x;
            if (x > hi[k]) hi[k] = x;
        }
    for (k = 0; k < 3; k++) d[k] = hi[k] - lo[k];
    return v3_len(d);
}

/* Compares every vertex of t (build + subd_loop_limit) with the reference. */
static void compare_mesh(const tmesh *t, subd_loop_boundary rule, lim_stats *st)
{
    subd_arena a;
    subd_mesh m;
    subd_real *pos = 0, *nrm = 0;
    subd_diag d;
    double size = mesh_size(t);
    uint32_t v, k;
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    if (!CHECK(tm_build(&a, t, &m))) return;
    if (!CHECK_EQ(subd_loop_limit(&a, &m, &(subd_loop_limit_opts){rule, SUBD_LOOP_LIMIT_NORMALS}, &pos, &nrm, &d), SUBD_OK)) return;
    for (v = 0; v < t->nv; v++) {
        double rp[3], rn[3], ln[3], err = 0, dot = 0, ang, l;
        int cls = ref_limit(t, v, rule, rp, rn), cfg;
        for (k = 0; k < 3; k++) {
            double e = fabs(rdbl(pos[3 * v + k]) - rp[k]);
            if (e > err) err = e;
        }
#if SUBD_FIXED
        {
            /* allowed: 0.5 LSB + 2^-13 LSB per unit of sum |p_i - v| + 0.01 LSB */
            uint32_t ring[64], n = subd_vertex_ring(&m, v, ring, 64), i;
            double sum = 0, allowed, got = err * 65536.0;
            for (i = 0; i < n && i < 64; i++) {
                double mx = 0;
                for (k = 0; k < 3; k++) {
                    double dd = fabs(rdbl(t->pos[3 * ring[i] + k]) - rdbl(t->pos[3 * v + k]));
                    if (dd > mx) mx = dd;
                }
                sum += mx;
            }
            allowed = 0.51 + sum / 8192.0;
            if (got - allowed > st->lsb_excess) st->lsb_excess = got - allowed;
            if (got > st->lsb_max) st->lsb_max = got;
            if (got > allowed) st->bad_pos++;
        }
#else
        if (err / size > st->pos_rel) st->pos_rel = err / size;
        if (err > 1e-5 * size) st->bad_pos++;
#endif
        for (k = 0; k < 3; k++) ln[k] = rdbl(nrm[3 * v + k]);
        l = v3_len(ln);
        for (k = 0; k < 3; k++) dot += ln[k] * rn[k];
        ang = l > 0 ? acos(dot / l > 1.0 ? 1.0 : dot / l) * 180.0 / REF_PI : 180.0;
        if (ang > st->ang[cls]) st->ang[cls] = ang;
        st->n[cls]++;
        if ((cls == R_SMOOTH || cls == R_CREASE) && ang > 0.1) st->bad_nrm++;
        if (g_verbose && (ang > 0.1 || err > 1e-5 * size)) {
            h_str(rule == SUBD_LOOP_BOUNDARY_PAPER ? "    P v " : "    B v ");
            h_u32(v);
            h_str(" ");
            h_str(g_cls_name[cls]);
            h_str(" val ");
            h_u32(subd_vertex_valence(&m, v));
            h_str(" cfg ");
            h_i32(ref_config(t, v));
            h_str(" err ");
            print_dbl(err / size * 1e6, 3);
            h_str("e-6 angle ");
            print_dbl(ang, 4);
            h_nl();
        }
        if (rule == SUBD_LOOP_BOUNDARY_PAPER && cls == R_CREASE && (cfg = ref_config(t, v)) >= 0) st->configs[cfg]++;
    }
}

static void report(const char *what, const lim_stats *st)
{
    uint32_t c;
    h_str("  ");
    h_str(what);
#if SUBD_FIXED
    h_str(": position error max ");
    print_dbl(st->lsb_max, 3);
    h_str(" LSB, over bound ");
    print_dbl(st->lsb_excess, 3);
#else
    h_str(": position error/size ");
    print_dbl(st->pos_rel * 1e9, 2);
    h_str("e-9");
#endif
    for (c = 0; c < 4; c++) {
        if (!st->n[c]) continue;
        h_str(", ");
        h_str(g_cls_name[c]);
        h_str(" ");
        h_u32(st->n[c]);
        h_str(" max ");
        print_dbl(st->ang[c], 4);
        h_str(" deg");
    }
    h_nl();
}

static void stats_clear(lim_stats *st)
{
    uint32_t i;
    st->pos_rel = 0;
    st->lsb_excess = -1e9;
    st->lsb_max = 0;
    for (i = 0; i < 4; i++) { st->ang[i] = 0; st->n[i] = 0; }
    for (i = 0; i < 6; i++) st->configs[i] = 0;
    st->bad_pos = st->bad_nrm = 0;
}

static void ref_interior(void)
{
    lim_stats st;
    uint32_t n;
    stats_clear(&st);
    for (n = 3; n <= 12; n++) {
        tm_bipyramid(&g_tm, n, 100u + n);
        compare_mesh(&g_tm, SUBD_LOOP_BOUNDARY_PAPER, &st);
    }
    report("interior valence 3..12", &st);
    CHECK_EQ(st.bad_pos, 0);
    CHECK_EQ(st.bad_nrm, 0);
}

static void ref_boundary(void)
{
    lim_stats st;
    uint32_t seed, c, r;
    for (r = 0; r < 2; r++) {
        stats_clear(&st);
        for (seed = 1; seed <= 3; seed++) {
            tm_grid(&g_tm, 6, 5, 7u * seed, 0);
            compare_mesh(&g_tm, r ? SUBD_LOOP_BOUNDARY_BSPLINE : SUBD_LOOP_BOUNDARY_PAPER, &st);
        }
        report(r ? "boundary BSPLINE" : "boundary PAPER", &st);
        CHECK_EQ(st.bad_pos, 0);
        CHECK_EQ(st.bad_nrm, 0);
        if (!r) {
            h_str("  PAPER configurations (R;RR) (R;RE) (R;EE) (E;RR) (E;RE) (E;EE):");
            for (c = 0; c < 6; c++) { h_str(" "); h_u32(st.configs[c]); CHECK(st.configs[c] > 0); }
            h_nl();
        }
    }
}

/* Boundary fans of valence 2..12. With midpoints, valence 7 is the one case where the
 * boundary direction and the second interior mode share the eigenvalue 1/2 in a Jordan
 * block: the fan turns towards the library's plane only like 1/L, so after 60 levels the
 * reference is still about 1 degree away; it is checked with 2 degrees. */
static void ref_fans(void)
{
    lim_stats st, st7;
    uint32_t k, r;
    for (r = 0; r < 2; r++) {
        subd_loop_boundary rule = r ? SUBD_LOOP_BOUNDARY_BSPLINE : SUBD_LOOP_BOUNDARY_PAPER;
        stats_clear(&st);
        stats_clear(&st7);
        for (k = 2; k <= 12; k++) {
            /* the across mode and the next one are close for large k: 0.951 per level at 12 */
            g_ref_levels = k >= 8u ? 200 : REF_LEVELS;
            tm_fan(&g_tm, k, 300u + k);
            compare_mesh(&g_tm, rule, (r && k == 7u) ? &st7 : &st);
        }
        g_ref_levels = REF_LEVELS;
        report(r ? "boundary fans k = 2..12 BSPLINE" : "boundary fans k = 2..12 PAPER", &st);
        /* Hoppe et al.'s boundary tangent masks (as in pbrt) for comparison: they are the
         * eigenvectors of Hoppe's own (the paper's) rule, and wrong at k >= 5 for the
         * B-spline boundary, which is what pbrt combines them with */
        {
            double worst = 0, worst4 = 0;
            for (k = 2; k <= 12; k++) {
                double p[13][3], v0[3], along[3], across[3], hn[3], rp[3], rn[3], l;
                uint32_t i, c;
                tm_fan(&g_tm, k, 300u + k);
                for (c = 0; c < 3; c++) v0[c] = rdbl(g_tm.pos[c]);
                for (i = 0; i < k; i++)
                    for (c = 0; c < 3; c++) p[i][c] = rdbl(g_tm.pos[3 * (1 + i) + c]) - v0[c];
                for (c = 0; c < 3; c++) {
                    along[c] = p[k - 1][c] - p[0][c];
                    if (k == 2) across[c] = p[0][c] + p[1][c];
                    else if (k == 3) across[c] = p[1][c];
                    else if (k == 4) across[c] = -p[0][c] + 2 * p[1][c] + 2 * p[2][c] - p[3][c];
                    else {
                        double th = REF_PI / (k - 1), t = sin(th) * (p[0][c] + p[k - 1][c]);
                        for (i = 1; i + 1 < k; i++) t += (2 * cos(th) - 2) * sin(i * th) * p[i][c];
                        across[c] = -t;
                    }
                }
                v3_cross(across, along, hn);
                l = v3_len(hn);
                for (c = 0; c < 3; c++) hn[c] /= l;
                g_ref_levels = k >= 8u ? 200 : REF_LEVELS;
                ref_limit(&g_tm, 0, rule, rp, rn);
                g_ref_levels = REF_LEVELS;
                if (k >= 5u && ref_angle(hn, rn) > worst) worst = ref_angle(hn, rn);
                if (k <= 4u && ref_angle(hn, rn) > worst4 && (r || k == 4u)) worst4 = ref_angle(hn, rn);
            }
            h_str("    Hoppe/pbrt boundary masks: max error k >= 5 ");
            print_dbl(worst, 3);
            h_str(" deg (this library: see above)");
            h_nl();
            if (r) CHECK(worst > 0.5);   /* B-spline: the reason they are not used */
            else CHECK(worst < 0.01);    /* paper's rule: identical to ours */
            if (r) CHECK(worst4 < 0.01); /* B-spline rule, k <= 4: they agree */
        }
        CHECK_EQ(st.bad_pos, 0);
        CHECK_EQ(st.bad_nrm, 0);
        if (r) {
            report("boundary fan k = 7 BSPLINE (Jordan block)", &st7);
            CHECK_EQ(st7.bad_pos, 0);
            CHECK(st7.ang[R_CREASE] < 2.0);
        }
    }
}

/* Corners: grid corners (one or two faces) and a boundary vertex tagged CORNER (the library's
 * corner normal is exact for sectors of at most two faces; others are reported only). */
static void ref_corners(void)
{
    lim_stats st;
    uint32_t r, seed;
    for (r = 0; r < 2; r++) {
        subd_loop_boundary rule = r ? SUBD_LOOP_BOUNDARY_BSPLINE : SUBD_LOOP_BOUNDARY_PAPER;
        stats_clear(&st);
        for (seed = 1; seed <= 2; seed++) {
            tm_grid(&g_tm, 5, 4, 11u * seed, 0);
            g_tm.corner[g_tm.nc++] = 0;
            g_tm.corner[g_tm.nc++] = 5;
            g_tm.corner[g_tm.nc++] = 24;
            g_tm.corner[g_tm.nc++] = 29;
            compare_mesh(&g_tm, rule, &st);
        }
        report(r ? "grid corners BSPLINE" : "grid corners PAPER", &st);
        CHECK_EQ(st.bad_pos, 0);
        CHECK_EQ(st.bad_nrm, 0);
        CHECK_EQ(st.n[R_CORNER], 8);
        CHECK(st.ang[R_CORNER] <= 0.1);
        stats_clear(&st);
        tm_grid(&g_tm, 5, 4, 13u, 0);
        g_tm.corner[g_tm.nc++] = 2; /* middle of the bottom side */
        compare_mesh(&g_tm, rule, &st);
        report(r ? "side corner BSPLINE (approximate normal)" : "side corner PAPER (approximate normal)", &st);
        CHECK_EQ(st.bad_pos, 0);
        CHECK_EQ(st.bad_nrm, 0);
        /* a tagged corner with no sharp edge: fixed centre, interior tangents (exact) */
        stats_clear(&st);
        tm_bipyramid(&g_tm, 5, 77u);
        g_tm.corner[g_tm.nc++] = 0;
        compare_mesh(&g_tm, rule, &st);
        CHECK_EQ(st.bad_pos, 0);
        CHECK_EQ(st.n[R_CORNER], 1);
        CHECK(st.ang[R_CORNER] <= 0.1);
        /* ... and with one sharp edge: the fixed centre with a crease leaving it has no
         * tangent plane (the crease direction outgrows the ring); reported only */
        stats_clear(&st);
        tm_sharp(&g_tm, 0, 2);
        compare_mesh(&g_tm, rule, &st);
        report(r ? "corner with one crease BSPLINE (no tangent plane)" : "corner with one crease PAPER (no tangent plane)", &st);
        CHECK_EQ(st.bad_pos, 0);
        CHECK(st.ang[R_CORNER] < 180.0); /* a unit normal, not (0, 0, 0) */
    }
}

/* Darts: a bipyramid with one crease edge from apex 0 to the equator (both ends darts). */
static void ref_darts(void)
{
    static const uint32_t ns[] = {3, 4, 5, 6, 7, 8, 9, 10, 12, 16};
    lim_stats st;
    uint32_t i, r;
    for (r = 0; r < 2; r++) {
        stats_clear(&st);
        for (i = 0; i < sizeof ns / sizeof ns[0]; i++) {
            /* the second tangent mode of a high-valence dart is close to the next one */
            g_ref_levels = ns[i] >= 12u ? 240 : 100;
            tm_bipyramid(&g_tm, ns[i], 500u + ns[i]);
            tm_sharp(&g_tm, 0, 2);
            compare_mesh(&g_tm, r ? SUBD_LOOP_BOUNDARY_BSPLINE : SUBD_LOOP_BOUNDARY_PAPER, &st);
        }
        g_ref_levels = REF_LEVELS;
        report(r ? "darts valence 3..16 BSPLINE" : "darts valence 3..16 PAPER", &st);
        CHECK_EQ(st.bad_pos, 0);
        CHECK_EQ(st.bad_nrm, 0);
        CHECK(st.ang[R_DART] <= 0.1);
    }
}

static void ref_crease(void)
{
    lim_stats st;
    uint32_t r;
    for (r = 0; r < 2; r++) {
        stats_clear(&st);
        tm_torus(&g_tm, 10, 8, 5u);
        compare_mesh(&g_tm, r ? SUBD_LOOP_BOUNDARY_BSPLINE : SUBD_LOOP_BOUNDARY_PAPER, &st);
        report(r ? "creases BSPLINE" : "creases PAPER", &st);
        CHECK_EQ(st.bad_pos, 0);
        CHECK_EQ(st.bad_nrm, 0);
    }
}
#endif

/* ------------------------------------------------------------------------------------ */
/* Square root                                                                            */

#if SUBD_FIXED
/* r is the rounded square root of x * 2^16 when (2r - 1)^2 <= 4X < (2r + 1)^2. */
static int sqrt_ok_fixed(subd_real x, subd_real r)
{
    uint64_t X4 = ((uint64_t)x << 16) * 4u, lo, hi;
    if (r < 0) return 0;
    lo = r > 0 ? (2u * (uint64_t)r - 1u) * (2u * (uint64_t)r - 1u) : 0u;
    hi = (2u * (uint64_t)r + 1u) * (2u * (uint64_t)r + 1u);
    return lo <= X4 && X4 < hi;
}
#else
/* Exact check of correct rounding from bit patterns, no float arithmetic: r = R 2^q with a
 * 24-bit R is the nearest float to sqrt(x), x = M 2^e, when
 * (2R - 1)^2 2^(2q-2) < M 2^e < (2R + 1)^2 2^(2q-2) (no ties are possible). */
static int sqrt_ok_float(uint32_t xb, uint32_t rb)
{
    uint64_t M, R, lo, hi;
    int32_t e, q, sh;
    if (xb >> 31) return 0;
    if ((xb & 0x7f800000u) == 0) { M = xb & 0x7fffffu; e = -149; }
    else { M = (xb & 0x7fffffu) | 0x800000u; e = (int32_t)(xb >> 23) - 150; }
    if (rb >> 31 || (rb & 0x7f800000u) == 0) return 0; /* results are positive normals */
    R = (rb & 0x7fffffu) | 0x800000u;
    q = (int32_t)(rb >> 23) - 150;
    lo = (2u * R - 1u) * (2u * R - 1u);
    hi = (2u * R + 1u) * (2u * R + 1u); /* < 2^50 */
    /* compare X = M 2^(e - 2q + 2) (about 4 R^2 < 2^50 when r is right) with lo, hi */
    sh = e - 2 * q + 2;
    if (sh < 0 || sh > 52 || M > (((uint64_t)1 << 52) >> sh)) return 0;
    M <<= sh;
    return lo < M && M < hi;
}
#endif

static void sqrt_test(void)
{
    uint32_t s = 12345u, i, bad = 0;
#if SUBD_FIXED
    static const subd_real fixed_cases[] = {0, 1, 2, 3, 4, 65535, 65536, 65537, 131072, 262144,
                                            0x7fffffff, 0x7ffffffe, 0x40000000, 12345678};
    CHECK_EQ(subd_sqrt(0), 0);
    CHECK_EQ(subd_sqrt(-5), 0);
    CHECK_EQ(subd_sqrt(SUBD_REAL_MIN), 0);
    CHECK_EQ(subd_sqrt(65536), 65536);
    CHECK_EQ(subd_sqrt(4 * 65536), 2 * 65536);
    CHECK_EQ(subd_sqrt(16384), 32768); /* sqrt(1/4) = 1/2 */
    for (i = 0; i < sizeof fixed_cases / sizeof fixed_cases[0]; i++)
        if (!sqrt_ok_fixed(fixed_cases[i], subd_sqrt(fixed_cases[i]))) bad++;
    for (i = 0; i < 200000u; i++) {
        uint32_t u = h_rand(&s);
        subd_real x = (subd_real)(u >> (u & 31u)) & 0x7fffffff;
        if (!sqrt_ok_fixed(x, subd_sqrt(x))) bad++;
    }
    CHECK_EQ(bad, 0);
#else
    union { float f; uint32_t u; } x, r;
    static const uint32_t specials[] = {0x00000001u, 0x00000002u, 0x00000003u, 0x007fffffu, 0x00800000u,
                                        0x3f800000u, 0x40000000u, 0x40800000u, 0x7f7fffffu, 0x3f7fffffu,
                                        0x3f800001u, 0x00400000u, 0x4b7fffffu, 0x1f800000u};
    x.f = 0.0f; r.f = subd_sqrt(x.f); CHECK_EQ(r.u, 0x00000000u);
    x.u = 0x80000000u; r.f = subd_sqrt(x.f); CHECK_EQ(r.u, 0x80000000u); /* -0 -> -0 */
    x.u = 0x7f800000u; r.f = subd_sqrt(x.f); CHECK_EQ(r.u, 0x7f800000u);
    x.f = -1.0f; r.f = subd_sqrt(x.f); CHECK_EQ(r.u, 0x7fc00000u);
    x.u = 0xff800000u; r.f = subd_sqrt(x.f); CHECK_EQ(r.u, 0x7fc00000u);
    x.u = 0x7f800001u; r.f = subd_sqrt(x.f); CHECK_EQ(r.u, 0x7fc00001u);  /* NaN quieted */
    x.f = 4.0f; CHECK(subd_sqrt(x.f) == 2.0f);
    x.f = 0.25f; CHECK(subd_sqrt(x.f) == 0.5f);
    for (i = 0; i < sizeof specials / sizeof specials[0]; i++) {
        x.u = specials[i];
        r.f = subd_sqrt(x.f);
        if (!sqrt_ok_float(x.u, r.u)) bad++;
#if H_HOST
        { union { float f; uint32_t u; } w; w.f = sqrtf(x.f); if (w.u != r.u) bad++; }
#endif
    }
    for (i = 0; i < (H_HOST ? 2000000u : 100000u); i++) {
        x.u = h_rand(&s) & 0x7fffffffu;
        if (x.u >= 0x7f800000u) continue;
        r.f = subd_sqrt(x.f);
        if (!sqrt_ok_float(x.u, r.u)) bad++;
#if H_HOST
        { union { float f; uint32_t u; } w; w.f = sqrtf(x.f); if (w.u != r.u) bad++; }
#endif
    }
    /* every subnormal pattern with few bits, and the edges of the binades */
    for (i = 1; i < 0x800000u; i = i * 3u + 1u) {
        x.u = i;
        r.f = subd_sqrt(x.f);
        if (!sqrt_ok_float(x.u, r.u)) bad++;
#if H_HOST
        { union { float f; uint32_t u; } w; w.f = sqrtf(x.f); if (w.u != r.u) bad++; }
#endif
    }
    CHECK_EQ(bad, 0);
#endif
    CHECK_EQ(subd_isqrt64(0), 0);
    CHECK_EQ(subd_isqrt64(2), 1);
    CHECK_EQ(subd_isqrt64(3), 2);     /* 1.73 -> 2 */
    CHECK_EQ(subd_isqrt64(6), 2);     /* 2.449 -> 2 */
    CHECK_EQ(subd_isqrt64(7), 3);     /* 2.645 -> 3 */
    CHECK_EQ(subd_isqrt64(UINT64_MAX), 0xffffffffu);
    CHECK_EQ(subd_isqrt64((uint64_t)0xfffffffeu * 0xfffffffeu), 0xfffffffeu);
}

const test_case suite_loop_limit[] = {
    {"limit_sqrt", sqrt_test},
    {"limit_weights", weights_test},
    {"limit_constant", constant_test},
    {"limit_translate", translate_test},
    {"limit_planar_normals", planar_test},
    {"limit_convex_outward", convex_test},
    {"limit_apply", apply_test},
    {"limit_refine_invariant", refine_test},
    {"limit_arena", arena_test},
    {"limit_errors", errors_test},
    {"limit_hashes", hashes_test},
#if H_HOST
    {"limit_ref_interior", ref_interior},
    {"limit_ref_boundary", ref_boundary},
    {"limit_ref_crease", ref_crease},
    {"limit_ref_fans", ref_fans},
    {"limit_ref_darts", ref_darts},
    {"limit_ref_corners", ref_corners},
#endif
    {0, 0}
};
