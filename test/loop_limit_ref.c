/* SPDX-License-Identifier: MIT */
/* Fixtures of test/test_loop_limit.c: test meshes (face lists with sharp edges and corners,
 * exact in both arithmetics) and the independent reference.
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
 */
#include "loop_limit_ref.h"
#if H_HOST
#include <math.h>
#endif

/* ------------------------------------------------------------------------------------ */
/* Test meshes: a face list with sharp edges and corner tags.                             */




/* A coordinate k / 1024: exact in both arithmetics. */
subd_real q10(int32_t k)
{
#if SUBD_FIXED
    return (subd_real)(k * 64);
#else
    return (subd_real)k / 1024.0f;
#endif
}

/* Uniform integer in [-r, r]. */
int32_t jit(uint32_t *s, int32_t r)
{
    return (int32_t)(h_rand(s) % (uint32_t)(2 * r + 1)) - r;
}

void tm_clear(tmesh *t)
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

void tm_face(tmesh *t, uint32_t a, uint32_t b, uint32_t c)
{
    t->idx[3 * t->nf] = a;
    t->idx[3 * t->nf + 1] = b;
    t->idx[3 * t->nf + 2] = c;
    t->nf++;
}

void tm_sharp(tmesh *t, uint32_t a, uint32_t b)
{
    t->sharp[t->ns][0] = a;
    t->sharp[t->ns][1] = b;
    t->ns++;
}

/* Bipyramid over a jittered n-gon: apexes 0 and 1 have valence n, the equator valence 4. */
void tm_bipyramid(tmesh *t, uint32_t n, uint32_t seed)
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
void tm_grid(tmesh *t, uint32_t w, uint32_t h, uint32_t seed, int flat)
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
void tm_torus(tmesh *t, uint32_t n, uint32_t m, uint32_t seed)
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
void tm_fan(tmesh *t, uint32_t k, uint32_t seed)
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

int tm_build(subd_arena *a, const tmesh *t, subd_mesh *m)
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

typedef struct ref_mesh {
    int nv, nf, ns;
    double p[RV][3];
    unsigned char bnd[RV];    /* on a true boundary (not a cut of the patch) */
    unsigned char corner[RV]; /* SUBD_VTAG_CORNER */
    int f[RF][3];
    int s[RS][3];             /* sharp edges: a, b, 1 if a boundary edge */
} ref_mesh;

static ref_mesh g_ra, g_rb;
int g_ref_levels = REF_LEVELS;
static int g_nsh[RV], g_shn[RV][8], g_shb[RV][8]; /* sharp edges per vertex: count, other end, boundary */
static int g_vfs[RV + 1], g_vf[3 * RF];    /* faces of each vertex (counting sort) */
static int g_eo[RV][RMAXVAL], g_ei[RV][RMAXVAL], g_en[RV]; /* edges: other end, new vertex */
static int g_dist[RV], g_map[RV];

double rdbl(subd_real x)
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

void v3_cross(const double *a, const double *b, double *c)
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

double v3_len(const double *a) { return sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

/* Configuration of a crease vertex for the paper's rule: 0..5 = (R;RR) (R;RE) (R;EE)
 * (E;RR) (E;RE) (E;EE), from the level-0 mesh. */
int ref_config(const tmesh *t, uint32_t v)
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

double ref_angle(const double *a, const double *b)
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
int ref_limit(const tmesh *t, uint32_t v, subd_loop_boundary rule, double *pos, double *nrm)
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
