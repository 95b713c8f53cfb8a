/* SPDX-License-Identifier: MIT */
/* Semi-regular 4-8 refinement (subd_sr48_build): section 5's pre-processing claims
 * (valence parity and bound, the valence transition table), the hierarchy's structure level
 * by level checked against meshes rebuilt by the validator (diamond counts, base
 * neighbours, parent/child layout, valences after double steps, Euler characteristic),
 * the factored smoothing against an independent Zwart-Powell dual quad scheme, planes and
 * affine maps, refinement-only positions, exact planning (every too-small arena fails
 * cleanly), errors, and output hashes for host = QEMU. Everything fits the shared 256 KiB
 * test arena. */
#include "harness.h"
#include "fixtures.h"
#include "subd_sr48.h"
#include "corpus.h"

#define MAXV 4096
#define MAXF 4096
static subd_real g_pos[3 * MAXV];
static uint32_t g_idx[3 * MAXF];
static uint32_t g_state = 0x5e48u;

static subd_sr48_opts sopts(uint32_t steps, uint32_t flags)
{
    subd_sr48_opts o;
    o.steps = steps;
    o.flags = flags;
    return o;
}

static subd_face_list tri_list(uint32_t nv, const subd_real *pos, uint32_t nf, const uint32_t *idx)
{
    subd_face_list fl;
    fl.num_verts = nv;
    fl.pos = pos;
    fl.num_faces = nf;
    fl.face_size = 0;
    fl.index = idx;
    fl.num_lines = 0;
    fl.line_size = fl.line_index = 0;
    return fl;
}

/* An embedded OBJ as a triangle mesh (polygons fanned from their first corner). */
static int load_tri(subd_arena *a, const char *name, subd_mesh *m)
{
    const corpus_file *cf = corpus_find(name);
    subd_mesh raw;
    subd_diag d;
    subd_face_list fl;
    uint32_t f, k = 0, i;
    if (!CHECK(cf != 0)) return 0;
    if (!CHECK_EQ(subd_obj_read(a, cf->data, cf->len, &raw, &d), SUBD_OK)) return 0;
    if (raw.num_corners == 3u * raw.num_faces) {
        *m = raw;
        return 1;
    }
    if (!CHECK(raw.num_verts <= MAXV)) return 0;
    for (i = 0; i < 3u * raw.num_verts; i++) g_pos[i] = raw.pos[i];
    for (f = 0; f < raw.num_faces; f++) {
        uint32_t s = raw.face_start[f], n = subd_face_size(&raw, f), j;
        for (j = 1; j + 1u < n; j++) {
            if (!CHECK(k + 3u <= 3u * MAXF)) return 0;
            g_idx[k++] = raw.corner_vert[s];
            g_idx[k++] = raw.corner_vert[s + j];
            g_idx[k++] = raw.corner_vert[s + j + 1u];
        }
    }
    fl = tri_list(raw.num_verts, g_pos, k / 3u, g_idx);
    return h_build(a, &fl, m);
}

/* Planar n x n grid of unit squares, every square (a, b, c, d) cut by the same diagonal
 * a-c, heights z[(n+1) * j + i] (or 0): fx_grid's triangles. */
static subd_face_list grid_list(uint32_t n, const subd_real *z)
{
    (void)fx_grid(n, n, 0, z, g_pos, g_idx);
    return tri_list((n + 1u) * (n + 1u), g_pos, 2u * n * n, g_idx);
}

static int sr48(subd_arena *a, const subd_mesh *in, const subd_sr48_opts *o, subd_sr48 *h)
{
    subd_diag d;
    int st = subd_sr48_build(a, in, o, h, &d);
    return CHECK_OK(st, &d);
}

/* The triangles of level k as a validated mesh (vertices [0, level_verts[k])). */
static int level_mesh(subd_arena *a, const subd_sr48 *h, uint32_t k, subd_mesh *m)
{
    subd_face_list fl = tri_list(h->level_verts[k], h->pos, h->level_tri[k + 1u] - h->level_tri[k],
                                 h->tri_vert + 3u * h->level_tri[k]);
    return h_build(a, &fl, m);
}

static uint32_t fnv_u32(uint32_t hs, uint32_t v)
{
    uint8_t b[4];
    b[0] = (uint8_t)v; b[1] = (uint8_t)(v >> 8); b[2] = (uint8_t)(v >> 16); b[3] = (uint8_t)(v >> 24);
    return h_fnv(hs, b, 4);
}

/* Hash of a hierarchy: counts, positions (bit patterns), triangles, base neighbours. */
static uint32_t sr48_hash(const subd_sr48 *h)
{
    uint32_t hs = 2166136261u, i;
    hs = fnv_u32(hs, h->num_verts);
    hs = fnv_u32(hs, h->num_tris);
    hs = fnv_u32(hs, h->num_clusters);
    for (i = 0; i <= h->steps; i++) hs = fnv_u32(fnv_u32(hs, h->level_verts[i]), h->level_tri[i]);
    for (i = 0; i < 3u * h->num_verts; i++) hs = fnv_u32(hs, subd_real_bits(h->pos[i]));
    for (i = 0; i < 3u * h->num_tris; i++) hs = fnv_u32(hs, h->tri_vert[i]);
    for (i = 0; i < h->num_tris; i++) hs = fnv_u32(hs, h->tri_base_nb[i]);
    return hs;
}

static void info_counts(const char *name, const subd_sr48 *h)
{
    uint32_t k;
    h_str("    ");
    h_str(name);
    h_str(": clusters ");
    h_u32(h->num_clusters);
    h_str(", isolated ");
    h_u32(h->num_isolated);
    h_str("; level V/F:");
    for (k = 0; k <= h->steps; k++) {
        h_str(" ");
        h_u32(h->level_verts[k]);
        h_str("/");
        h_u32(h->level_tri[k + 1u] - h->level_tri[k]);
    }
    h_nl();
}

/* ------------------------------------------------------------------------------------ */
/* (1) Pre-processing: valence parity, bound, transition table                           */

#define VT_MAX 16u /* table rows/columns 0..15, larger valences listed separately */
static uint32_t g_vt[2][VT_MAX][2 * VT_MAX];
static uint16_t g_tri_at[MAXV];

static void valence_table_mesh(const char *name, subd_arena *a, const subd_mesh *in, int validate)
{
    subd_sr48 h;
    subd_sr48_opts o = sopts(0, 0);
    uint32_t mark = subd_arena_mark(a), v, t, bad = 0;
    if (!sr48(a, in, &o, &h)) return;
    info_counts(name, &h);
    if (!CHECK(h.num_verts <= MAXV)) return;
    /* new valence from level 0 by counting: interior = triangles at v, boundary = +1 */
    for (v = 0; v < h.num_verts; v++) g_tri_at[v] = 0;
    for (t = 0; t < 3u * h.level_tri[1]; t++) g_tri_at[h.tri_vert[t]]++;
    if (validate) {
        subd_mesh m0;
        if (level_mesh(a, &h, 0, &m0)) {
            for (v = 0; v < h.num_verts; v++) {
                uint32_t val = subd_vertex_valence(&m0, v), bnd = (m0.vert_tag[v] & SUBD_VTAG_BOUNDARY) != 0;
                if (m0.vert_tag[v] & SUBD_VTAG_ISOLATED) continue;
                CHECK_EQ(val, g_tri_at[v] + bnd);
                if (bnd) CHECK(val & 1u); else CHECK((val & 1u) == 0);
                if (v < in->num_verts) CHECK_EQ(bnd, (in->vert_tag[v] & SUBD_VTAG_BOUNDARY) != 0);
            }
        }
    }
    for (v = 0; v < h.num_verts; v++) {
        uint32_t bnd, nw, old;
        if (g_tri_at[v] == 0) continue;
        bnd = v < in->num_verts ? (in->vert_tag[v] & SUBD_VTAG_BOUNDARY) != 0 : 0;
        nw = g_tri_at[v] + bnd;
        if (v >= in->num_verts) {
            /* face points: 8 or 6 triangles; edge points: 4, on the boundary 2 (valence 3) */
            if (!(nw == 2u || nw == 4u || nw == 6u || nw == 8u)) bad++;
            continue;
        }
        old = subd_vertex_valence(in, v);
        if (bnd ? !(nw & 1u) : (nw & 1u)) bad++;
        if (nw > 2u * old) bad++;
        if (old < VT_MAX && nw < 2u * VT_MAX) {
            g_vt[bnd][old][nw]++;
        } else {
            h_str(bnd ? "    large boundary valence " : "    large interior valence ");
            h_u32(old);
            h_str(" -> ");
            h_u32(nw);
            h_nl();
        }
    }
    CHECK_EQ(bad, 0);
    subd_arena_rewind(a, mark);
}

static void sr48_preprocess_valences(void)
{
    static const char *const files[] = {"test/data/icosahedron.obj", "test/data/torus_tri.obj",
                                        "test/data/grid_tri_8x8.obj", "test/data/spot_control_mesh.obj",
                                        "test/data/hexfan.obj", "test/data/fan64.obj"};
    subd_arena a;
    subd_mesh in;
    subd_face_list fl;
    uint32_t i, b, o, n;
    for (b = 0; b < 2; b++)
        for (o = 0; o < VT_MAX; o++)
            for (n = 0; n < 2 * VT_MAX; n++) g_vt[b][o][n] = 0;
    for (i = 0; i < sizeof files / sizeof files[0]; i++) {
        subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
        if (!load_tri(&a, files[i], &in)) continue;
        valence_table_mesh(files[i] + 10, &a, &in, i != 1u); /* torus_tri: counting only (memory) */
    }
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    fl = h_torus(12, 6, g_pos, g_idx);
    if (h_build(&a, &fl, &in)) valence_table_mesh("torus 12x6", &a, &in, 1);
    h_str("    pre-processing valence transitions on these meshes (old -> new x count):");
    h_nl();
    for (b = 0; b < 2; b++) {
        for (o = 0; o < VT_MAX; o++) {
            uint32_t any = 0;
            for (n = 0; n < 2 * VT_MAX; n++) {
                if (!g_vt[b][o][n]) continue;
                if (!any) {
                    h_str(b ? "    boundary " : "    interior ");
                    h_u32(o);
                    h_str(" ->");
                    any = 1;
                }
                h_str(" ");
                h_u32(n);
                h_str("x");
                h_u32(g_vt[b][o][n]);
            }
            if (any) h_nl();
        }
    }
}

/* ------------------------------------------------------------------------------------ */
/* (2) The hierarchy level by level                                                       */

static uint32_t g_val[1][MAXV];

/* Checks level k of h (and the step k-1 -> k) against meshes rebuilt by the validator. */
static void check_levels(subd_arena *a, const subd_mesh *in, const subd_sr48 *h)
{
    uint32_t k, t, v, mark = subd_arena_mark(a);
    uint32_t prevE = 0, prevV = 0, prevF = 0, di = 0, db = 0;
    int32_t euler = subd_mesh_euler(in);
    const uint32_t *tv = h->tri_vert, *bn = h->tri_base_nb;
    CHECK_EQ(h->level_tri[0], 0);
    CHECK_EQ(h->num_tris, h->level_tri[h->steps + 1u]);
    CHECK_EQ(h->num_verts, h->level_verts[h->steps]);
    CHECK_EQ(h->num_input_verts, in->num_verts);
    CHECK_EQ(2u * h->num_clusters + h->num_isolated, in->num_faces);
    CHECK_EQ(h->level_tri[1], 8u * h->num_clusters + 6u * h->num_isolated);
    CHECK_EQ(h->level_verts[0], in->num_verts + h->num_clusters + h->num_isolated + in->num_edges - h->num_clusters);
    if (!CHECK(h->num_verts <= MAXV)) return;
    for (k = 0; k <= h->steps; k++) {
        subd_mesh m;
        const uint32_t t0 = h->level_tri[k], t1 = h->level_tri[k + 1u];
        const uint32_t vnew0 = k ? h->level_verts[k - 1u] : in->num_verts + h->num_clusters + h->num_isolated;
        uint32_t bad = 0, ndi = 0, ndb = 0;
        subd_arena_rewind(a, mark);
        if (!level_mesh(a, h, k, &m)) return;
        CHECK_EQ(subd_mesh_euler(&m), euler);
        CHECK_EQ(m.num_verts - m.num_isolated + in->num_isolated, m.num_verts);
        for (t = t0; t < t1; t++) {
            const uint32_t *p = tv + 3u * t, nb = bn[t];
            uint32_t f = t - t0, hb = m.face_start[f] + 1u; /* half-edge b0 -> b1 */
            /* the apex is the level's newest vertex, the base ends are older */
            if (p[0] < vnew0 || p[0] >= h->level_verts[k] || p[1] >= vnew0 || p[2] >= vnew0) bad++;
            if (nb == SUBD_NONE) {
                ndb++;
                if (m.twin[hb] != SUBD_NONE) bad++;
            } else {
                if (nb < t0 || nb >= t1 || bn[nb] != t) { bad++; continue; }
                if (tv[3u * nb + 1u] != p[2] || tv[3u * nb + 2u] != p[1]) bad++;
                if (m.twin[hb] == SUBD_NONE || m.corner_face[m.twin[hb]] != nb - t0) bad++;
                if (nb > t) ndi++;
            }
            /* children */
            if (k < h->steps) {
                const uint32_t c = h->level_tri[k + 1u] + 2u * (t - t0), *q = tv + 3u * c;
                if (q[0] != q[3] || q[1] != p[0] || q[2] != p[1] || q[4] != p[2] || q[5] != p[0]) bad++;
            }
        }
        CHECK_EQ(bad, 0);
        if (k > 0) {
            /* diamond counts of level k-1 (counted there) against the formulas */
            CHECK_EQ(m.num_verts, prevV + di + db);
            CHECK_EQ(m.num_faces, 2u * prevF);
            CHECK_EQ(m.num_edges, prevE + 3u * di + 2u * db);
        }
        /* valences after a double step: the step's new vertices 4 (boundary 3), the previous
         * step's 8 (never on the boundary); older vertices: check_even_valences */
        if (k >= 2u && (k & 1u) == 0u) {
            uint32_t vb = 0;
            for (v = 0; v < m.num_verts; v++) {
                uint32_t val = subd_vertex_valence(&m, v), bnd = (m.vert_tag[v] & SUBD_VTAG_BOUNDARY) != 0;
                if (v >= h->level_verts[k - 1u]) { if (val != (bnd ? 3u : 4u)) vb++; }
                else if (v >= h->level_verts[k - 2u]) { if (bnd || val != 8u) vb++; }
            }
            CHECK_EQ(vb, 0);
        }
        prevV = m.num_verts;
        prevF = m.num_faces;
        prevE = m.num_edges;
        di = ndi;
        db = ndb;
    }
    subd_arena_rewind(a, mark);
}

/* Valences at even levels k >= 2: a vertex that was the newest at level k-2 has gained one
 * neighbour per triangle (4 -> 8, boundary 3 -> 5); every older vertex keeps its valence. */
static void check_even_valences(subd_arena *a, const subd_sr48 *h)
{
    uint32_t k, v, mark = subd_arena_mark(a);
    const uint32_t nv_hyb = h->num_input_verts + h->num_clusters + h->num_isolated;
    subd_mesh m;
    if (!CHECK(h->num_verts <= MAXV)) return;
    for (k = 0; k <= h->steps; k += 2u) {
        uint32_t bad = 0;
        subd_arena_rewind(a, mark);
        if (!level_mesh(a, h, k, &m)) return;
        for (v = 0; v < m.num_verts; v++) {
            uint32_t val = subd_vertex_valence(&m, v), bnd = (m.vert_tag[v] & SUBD_VTAG_BOUNDARY) != 0;
            if (k >= 2u) {
                uint32_t older = k >= 3u ? h->level_verts[k - 3u] : nv_hyb;
                if (v < older && val != g_val[0][v]) bad++;
                if (v >= older && v < h->level_verts[k - 2u] && val != (bnd ? 5u : 8u)) bad++;
            }
            g_val[0][v] = val;
        }
        CHECK_EQ(bad, 0);
    }
    subd_arena_rewind(a, mark);
}

static void levels_case(const char *name, const subd_mesh *in, subd_arena *a, uint32_t steps, uint32_t flags)
{
    subd_sr48 h;
    subd_sr48_opts o = sopts(steps, flags);
    uint32_t mark = subd_arena_mark(a);
    if (!sr48(a, in, &o, &h)) return;
    check_levels(a, in, &h);
    check_even_valences(a, &h);
    if (flags == 0) info_counts(name, &h);
    subd_arena_rewind(a, mark);
}

static void sr48_levels(void)
{
    static const uint32_t one_idx[3] = {0, 1, 2};
    subd_arena a;
    subd_mesh in;
    subd_face_list fl;
    subd_real tpos[9];
    uint32_t i;
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    if (load_tri(&a, "test/data/icosahedron.obj", &in)) {
        levels_case("icosahedron", &in, &a, 4, 0);
        levels_case("icosahedron", &in, &a, 3, SUBD_SR48_NO_SMOOTH);
    }
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    if (load_tri(&a, "test/data/hexfan.obj", &in)) levels_case("hexfan", &in, &a, 5, 0);
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    if (load_tri(&a, "test/data/spot_control_mesh.obj", &in)) levels_case("spot_control_mesh (fanned)", &in, &a, 0, 0);
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    fl = h_torus(6, 3, g_pos, g_idx);
    if (h_build(&a, &fl, &in)) levels_case("torus 6x3", &in, &a, 3, 0);
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    fl = grid_list(2, 0);
    if (h_build(&a, &fl, &in)) levels_case("grid 2x2", &in, &a, 4, 0);
    for (i = 0; i < 9; i++) tpos[i] = 0;
    tpos[3] = SUBD_REAL_ONE;
    tpos[7] = SUBD_REAL_ONE;
    fl = tri_list(3, tpos, 1, one_idx);
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    if (h_build(&a, &fl, &in)) levels_case("one triangle", &in, &a, 6, 0);
}

/* ------------------------------------------------------------------------------------ */
/* (3) Zwart-Powell equivalence on a regular grid                                         */

/* The ZP control net of an n x n grid after pre-processing is the edge points (midpoints);
 * its quads are the four edge points around each grid vertex and each face point. In the
 * lattice a = x + y - 1/2, b = x - y - 1/2 + n the edge points are the integer points
 * (a, b) in [0, 2n)^2 whose (x, y) lies in the grid, and the quads are the unit cells whose
 * four corners are edge points. One ZP step (dual quad scheme, each face corner
 * 1/2 v + 1/4 of its two face neighbours) maps an N x N lattice to 2(N-1) x 2(N-1): corner
 * (a+da, b+db) of cell (a, b) goes to (2a+da, 2b+db); a point exists when its cell does. */
#define ZP_N 26
static double g_zp[2][ZP_N * ZP_N][3];
static uint8_t g_zv[2][ZP_N * ZP_N];

static uint32_t zp_init(uint32_t n, const subd_real *z)
{
    uint32_t a, b, N = 2u * n;
    for (a = 0; a < N; a++)
        for (b = 0; b < N; b++) {
            int32_t x2 = (int32_t)a + (int32_t)b - (int32_t)n + 1, y2 = (int32_t)a - (int32_t)b + (int32_t)n;
            uint32_t i = a * N + b, v0, v1;
            g_zv[0][i] = (uint8_t)(x2 >= 0 && y2 >= 0 && x2 <= 2 * (int32_t)n && y2 <= 2 * (int32_t)n);
            if (!g_zv[0][i]) continue;
            if (x2 & 1) { /* horizontal edge ((x2-1)/2, y) - ((x2+1)/2, y) */
                v0 = (uint32_t)(y2 / 2) * (n + 1u) + (uint32_t)((x2 - 1) / 2);
                v1 = v0 + 1u;
            } else {
                v0 = (uint32_t)((y2 - 1) / 2) * (n + 1u) + (uint32_t)(x2 / 2);
                v1 = v0 + n + 1u;
            }
            g_zp[0][i][0] = 0.5 * x2;
            g_zp[0][i][1] = 0.5 * y2;
            g_zp[0][i][2] = 0.5 * (h_dbl(z[v0]) + h_dbl(z[v1]));
        }
    return N;
}

static uint32_t zp_step(uint32_t N, uint32_t src)
{
    uint32_t a, b, da, db, q, M = 2u * (N - 1u), dst = src ^ 1u;
    for (a = 0; a < M * M; a++) g_zv[dst][a] = 0;
    for (a = 0; a + 1u < N; a++)
        for (b = 0; b + 1u < N; b++) {
            if (!g_zv[src][a * N + b] || !g_zv[src][(a + 1u) * N + b] || !g_zv[src][a * N + b + 1u] ||
                !g_zv[src][(a + 1u) * N + b + 1u])
                continue;
            for (da = 0; da < 2u; da++)
                for (db = 0; db < 2u; db++) {
                    const double *p = g_zp[src][(a + da) * N + b + db];
                    const double *p1 = g_zp[src][(a + 1u - da) * N + b + db];
                    const double *p2 = g_zp[src][(a + da) * N + b + 1u - db];
                    uint32_t i = (2u * a + da) * M + 2u * b + db;
                    for (q = 0; q < 3u; q++) g_zp[dst][i][q] = 0.5 * p[q] + 0.25 * p1[q] + 0.25 * p2[q];
                    g_zv[dst][i] = 1;
                }
        }
    return M;
}

static double dabs(double x) { return x < 0 ? -x : x; }

/* 2L binary steps on an n x n grid with heights z against L ZP steps: every ZP point is
 * exactly one vertex created by step 2L (matched by x, y), with the same height. */
static void zp_case(uint32_t n, uint32_t L, const subd_real *z)
{
    subd_arena a;
    subd_mesh in;
    subd_sr48 h;
    subd_sr48_opts o = sopts(2u * L, 0);
    subd_face_list fl = grid_list(n, z);
    uint32_t N, l, src = 0, i, v, matched = 0, missing = 0, zbad = 0, nzp = 0;
    double worst = 0;
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    if (!h_build(&a, &fl, &in) || !sr48(&a, &in, &o, &h)) return;
    CHECK_EQ(h.num_clusters, n * n);
    CHECK_EQ(h.num_isolated, 0);
    N = zp_init(n, z);
    for (l = 0; l < L; l++) {
        N = zp_step(N, src);
        src ^= 1u;
    }
    for (i = 0; i < N * N; i++) {
        const double *p = g_zp[src][i];
        uint32_t found = 0;
        if (!g_zv[src][i]) continue;
        nzp++;
        for (v = h.level_verts[2u * L - 1u]; v < h.level_verts[2u * L]; v++) {
            double dx = h_dbl(h.pos[3u * v]) - p[0], dy = h_dbl(h.pos[3u * v + 1u]) - p[1], dz;
            if (dabs(dx) > 1e-9 || dabs(dy) > 1e-9) continue;
            found++;
            dz = dabs(h_dbl(h.pos[3u * v + 2u]) - p[2]);
            if (dz > worst) worst = dz;
            if (dz > 1e-9) zbad++;
        }
        if (found == 1u) matched++;
        else missing++;
    }
    CHECK(nzp > 0);
    CHECK_EQ(missing, 0);
    CHECK_EQ(zbad, 0);
    h_str("    ZP grid ");
    h_u32(n);
    h_str("x");
    h_u32(n);
    h_str(", L = ");
    h_u32(L);
    h_str(": ");
    h_u32(matched);
    h_str(" ZP points = vertices of step ");
    h_u32(2u * L);
    h_str(worst == 0 ? " (heights bit-exact)" : " (heights differ)");
    h_nl();
}

static void sr48_zp_equivalence(void)
{
    static subd_real z[25];
    uint32_t i, ovf = 0;
    for (i = 0; i < 25; i++) /* heights k/8, |k| <= 2: the diagonals stay the longest edges */
        z[i] = subd_div(h_int((int32_t)(h_rand(&g_state) % 5u) - 2), h_int(8), &ovf);
    CHECK_EQ(ovf, 0);
    zp_case(4, 1, z);
    zp_case(4, 2, z);
    zp_case(2, 3, z);
    zp_case(1, 4, z);
}

/* The boundary: its control polygon is the boundary edge points; after 2L steps the
 * boundary vertices step 2L created are L steps of Chaikin's corner cutting (3/4, 1/4; the
 * quadratic B-spline) of that polygon, written here independently. */
#define CH_MAX 256
static double g_ch[2][CH_MAX][3];

static void sr48_boundary_chaikin(void)
{
    static subd_real z[25];
    const uint32_t n = 4;
    uint32_t L, i, ovf = 0;
    for (i = 0; i < 25; i++) z[i] = subd_div(h_int((int32_t)(h_rand(&g_state) % 5u) - 2), h_int(8), &ovf);
    CHECK_EQ(ovf, 0);
    for (L = 1; L <= 2; L++) {
        subd_arena a;
        subd_mesh in;
        subd_sr48 h;
        subd_sr48_opts o = sopts(2u * L, 0);
        subd_face_list fl = grid_list(n, z);
        uint32_t np = 0, l, src = 0, v, missing = 0, zbad = 0;
        /* boundary edges counter-clockwise from (0, 0): (x0, y0) -> (x0 + dx, y0 + dy) */
        for (i = 0; i < 4u * n; i++) {
            uint32_t side = i / n, j = i % n, x0, y0, x1, y1;
            if (side == 0) { x0 = j; y0 = 0; x1 = j + 1u; y1 = 0; }
            else if (side == 1) { x0 = n; y0 = j; x1 = n; y1 = j + 1u; }
            else if (side == 2) { x0 = n - j; y0 = n; x1 = n - j - 1u; y1 = n; }
            else { x0 = 0; y0 = n - j; x1 = 0; y1 = n - j - 1u; }
            g_ch[0][np][0] = 0.5 * (x0 + x1);
            g_ch[0][np][1] = 0.5 * (y0 + y1);
            g_ch[0][np][2] = 0.5 * (h_dbl(z[y0 * (n + 1u) + x0]) + h_dbl(z[y1 * (n + 1u) + x1]));
            np++;
        }
        for (l = 0; l < L; l++) {
            uint32_t q;
            for (i = 0; i < np; i++) {
                const double *p = g_ch[src][i], *r = g_ch[src][(i + 1u) % np];
                for (q = 0; q < 3u; q++) {
                    g_ch[src ^ 1u][2u * i][q] = 0.75 * p[q] + 0.25 * r[q];
                    g_ch[src ^ 1u][2u * i + 1u][q] = 0.25 * p[q] + 0.75 * r[q];
                }
            }
            np *= 2u;
            src ^= 1u;
        }
        subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
        if (!h_build(&a, &fl, &in) || !sr48(&a, &in, &o, &h)) return;
        for (i = 0; i < np; i++) {
            const double *p = g_ch[src][i];
            uint32_t found = 0;
            for (v = h.level_verts[2u * L - 1u]; v < h.level_verts[2u * L]; v++) {
                if (dabs(h_dbl(h.pos[3u * v]) - p[0]) > 1e-9 || dabs(h_dbl(h.pos[3u * v + 1u]) - p[1]) > 1e-9) continue;
                found++;
                if (dabs(h_dbl(h.pos[3u * v + 2u]) - p[2]) > 1e-9) zbad++;
            }
            if (found != 1u) missing++;
        }
        CHECK_EQ(missing, 0);
        CHECK_EQ(zbad, 0);
        h_str("    boundary after ");
        h_u32(2u * L);
        h_str(" steps: ");
        h_u32(np);
        h_str(" Chaikin points = boundary vertices of the last step");
        h_nl();
    }
}

/* ------------------------------------------------------------------------------------ */
/* (4) Planes, affine maps, refinement only                                               */

static void sr48_planes(void)
{
    subd_arena a;
    subd_mesh in;
    subd_sr48 h;
    subd_sr48_opts o = sopts(4, 0);
    subd_face_list fl;
    static subd_real z[16];
    uint32_t v, bad = 0, ovf = 0;
#if SUBD_FIXED
    const double tol = 64.0 / 65536.0;
#else
    const double tol = 1e-5;
#endif
    double worst = 0;
    /* z = 0 stays exactly 0 */
    fl = grid_list(4, 0);
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    if (!h_build(&a, &fl, &in) || !sr48(&a, &in, &o, &h)) return;
    for (v = 0; v < h.num_verts; v++) {
        if (h.pos[3u * v + 2u] != 0) bad++;
        if (h_dbl(h.pos[3u * v]) < 0 || h_dbl(h.pos[3u * v]) > 4.0 || h_dbl(h.pos[3u * v + 1u]) < 0 ||
            h_dbl(h.pos[3u * v + 1u]) > 4.0)
            bad++;
    }
    CHECK_EQ(bad, 0);
    h_hash("sr48_grid4_flat_4", sr48_hash(&h));
    /* a tilted plane z = x/2 - y/4 + 1 */
    for (v = 0; v < 16; v++)
        z[v] = subd_add(subd_sub(subd_div(h_int((int32_t)(v % 4u)), h_int(2), &ovf),
                                 subd_div(h_int((int32_t)(v / 4u)), h_int(4), &ovf), &ovf),
                        SUBD_REAL_ONE, &ovf);
    fl = grid_list(3, z);
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    if (!h_build(&a, &fl, &in) || !sr48(&a, &in, &o, &h)) return;
    for (v = 0; v < h.num_verts; v++) {
        double want = 0.5 * h_dbl(h.pos[3u * v]) - 0.25 * h_dbl(h.pos[3u * v + 1u]) + 1.0;
        double dz = dabs(h_dbl(h.pos[3u * v + 2u]) - want);
        if (dz > worst) worst = dz;
    }
    CHECK(worst <= tol);
    CHECK_EQ(ovf, 0);
    h_hash("sr48_grid3_tilted_4", sr48_hash(&h));
}

/* Maps of the icosahedron moved to (4, 4, 4): (x, y, z) -> (-y, z, x) is exact in both
 * arithmetics; adding a positive dyadic translation is exact in Q16.16 (one rounding per
 * average, ties away from zero, is translation invariant while no value changes sign);
 * scaling by 2 within rounding. */
static void sr48_affine(void)
{
    static subd_real p0[3 * 12];
    subd_arena a;
    subd_mesh in, in2;
    subd_sr48 h, h2;
    subd_sr48_opts o = sopts(3, 0);
    subd_face_list fl;
    uint32_t v, pass, ovf = 0, nv;
    subd_real t[3];
    t[0] = subd_div(h_int(1), h_int(2), &ovf);
    t[1] = subd_div(h_int(3), h_int(4), &ovf);
    t[2] = h_int(2);
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    if (!load_tri(&a, "test/data/icosahedron.obj", &in) || !CHECK_EQ(in.num_verts, 12)) return;
    for (v = 0; v < 36; v++) p0[v] = subd_add(in.pos[v], h_int(4), &ovf);
    fl = tri_list(12, p0, in.num_faces, in.corner_vert);
    if (!h_build(&a, &fl, &in) || !sr48(&a, &in, &o, &h)) return;
    nv = h.num_verts;
    for (pass = 0; pass < 3; pass++) {
        uint32_t mark = subd_arena_mark(&a), bad = 0, i;
        double worst = 0;
#if SUBD_FIXED
        const double tol = pass == 2 ? 8.0 / 65536.0 : 0.0;
#else
        const double tol = pass == 0 ? 0.0 : 1e-5;
#endif
        for (v = 0; v < 12; v++) {
            subd_real q[3];
            q[0] = subd_neg(p0[3 * v + 1], &ovf);
            q[1] = p0[3 * v + 2];
            q[2] = p0[3 * v];
            for (i = 0; i < 3; i++) {
                if (pass >= 1) q[i] = subd_add(q[i], t[i], &ovf);
                if (pass == 2) q[i] = subd_add(q[i], q[i], &ovf);
            }
            for (i = 0; i < 3; i++) g_pos[3 * v + i] = q[i];
        }
        fl = tri_list(12, g_pos, in.num_faces, in.corner_vert);
        if (!h_build(&a, &fl, &in2) || !sr48(&a, &in2, &o, &h2)) return;
        if (!CHECK_EQ(h2.num_tris, h.num_tris) || !CHECK_EQ(h2.num_verts, nv)) return;
        for (i = 0; i < 3u * h.num_tris; i++) if (h.tri_vert[i] != h2.tri_vert[i]) bad++;
        CHECK_EQ(bad, 0);
        for (v = 0; v < nv; v++) {
            double q[3];
            q[0] = -h_dbl(h.pos[3 * v + 1]);
            q[1] = h_dbl(h.pos[3 * v + 2]);
            q[2] = h_dbl(h.pos[3 * v]);
            for (i = 0; i < 3; i++) {
                double d;
                if (pass >= 1) q[i] += h_dbl(t[i]);
                if (pass == 2) q[i] *= 2.0;
                d = dabs(q[i] - h_dbl(h2.pos[3 * v + i]));
                if (d > worst) worst = d;
            }
        }
        if (!CHECK(worst <= tol)) {
            h_str("    affine map ");
            h_u32(pass);
            h_str(" not within tolerance");
            h_nl();
        }
        subd_arena_rewind(&a, mark);
    }
    CHECK_EQ(ovf, 0);
}

/* NO_SMOOTH: input vertices stay, every new vertex is its base edge's midpoint (within one
 * rounding), face points on the diagonal / barycentre, so every vertex lies on the input
 * polyhedron. */
static int on_face(const subd_mesh *in, const subd_real *p, double tol)
{
    uint32_t f, k;
    for (f = 0; f < in->num_faces; f++) {
        const subd_real *A = in->pos + 3u * in->corner_vert[3u * f], *B = in->pos + 3u * in->corner_vert[3u * f + 1u];
        const subd_real *C = in->pos + 3u * in->corner_vert[3u * f + 2u];
        double u[3], w[3], r[3], nn[3], len2, dist, uu = 0, uw = 0, ww = 0, ru = 0, rw = 0, det, s, t;
        for (k = 0; k < 3u; k++) {
            u[k] = h_dbl(B[k]) - h_dbl(A[k]);
            w[k] = h_dbl(C[k]) - h_dbl(A[k]);
            r[k] = h_dbl(p[k]) - h_dbl(A[k]);
        }
        nn[0] = u[1] * w[2] - u[2] * w[1];
        nn[1] = u[2] * w[0] - u[0] * w[2];
        nn[2] = u[0] * w[1] - u[1] * w[0];
        len2 = nn[0] * nn[0] + nn[1] * nn[1] + nn[2] * nn[2];
        dist = r[0] * nn[0] + r[1] * nn[1] + r[2] * nn[2];
        if (dist * dist > tol * tol * len2) continue;
        for (k = 0; k < 3u; k++) {
            uu += u[k] * u[k]; uw += u[k] * w[k]; ww += w[k] * w[k];
            ru += r[k] * u[k]; rw += r[k] * w[k];
        }
        det = uu * ww - uw * uw;
        s = (ru * ww - rw * uw) / det;
        t = (rw * uu - ru * uw) / det;
        if (s >= -1e-3 && t >= -1e-3 && s + t <= 1.0 + 1e-3) return 1;
    }
    return 0;
}

static void sr48_refine_only(void)
{
    subd_arena a;
    subd_mesh in;
    subd_sr48 h;
    subd_sr48_opts o = sopts(4, SUBD_SR48_NO_SMOOTH);
    uint32_t v, k, t, bad = 0, off = 0, q;
#if SUBD_FIXED
    const double tol = 1.0 / 65536.0;
#else
    const double tol = 1e-6;
#endif
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    if (!load_tri(&a, "test/data/icosahedron.obj", &in) || !sr48(&a, &in, &o, &h)) return;
    for (v = 0; v < 3u * in.num_verts; v++) if (!h_same(h.pos[v], in.pos[v])) bad++;
    /* level 0: edge point = midpoint of the hybrid base (child 0's b1, child 1's b0) */
    for (t = 0; t < h.level_tri[1]; t += 2u) {
        const uint32_t *c = h.tri_vert + 3u * t;
        for (q = 0; q < 3u; q++)
            if (dabs(h_dbl(h.pos[3u * c[0] + q]) - 0.5 * (h_dbl(h.pos[3u * c[2] + q]) + h_dbl(h.pos[3u * c[4] + q]))) > tol)
                bad++;
    }
    for (k = 0; k < h.steps; k++)
        for (t = h.level_tri[k]; t < h.level_tri[k + 1u]; t++) {
            const uint32_t *p = h.tri_vert + 3u * t, m = h.tri_vert[3u * (h.level_tri[k + 1u] + 2u * (t - h.level_tri[k]))];
            for (q = 0; q < 3u; q++)
                if (dabs(h_dbl(h.pos[3u * m + q]) - 0.5 * (h_dbl(h.pos[3u * p[1] + q]) + h_dbl(h.pos[3u * p[2] + q]))) > tol)
                    bad++;
        }
    CHECK_EQ(bad, 0);
    for (v = 0; v < h.num_verts; v++) if (!on_face(&in, h.pos + 3u * v, 8 * tol)) off++;
    CHECK_EQ(off, 0);
}

/* ------------------------------------------------------------------------------------ */
/* (5) Plans                                                                              */

#define IN_BYTES (24u * 1024u)
static uint8_t g_in_buf[IN_BYTES] __attribute__((aligned(8)));

typedef struct build_call {
    const subd_mesh *in;
    const subd_sr48_opts *o;
    subd_sr48 h;
} build_call;

static int build_run(void *ctx, subd_arena *a, subd_diag *d)
{
    build_call *c = (build_call *)ctx;
    return subd_sr48_build(a, c->in, c->o, &c->h, d);
}

static void plan_case(const subd_mesh *in, const subd_sr48_opts *o, int exhaustive)
{
    uint32_t plan, bound, clusters;
    subd_arena a;
    subd_sr48 h;
    subd_diag d;
    build_call c;
    h_sweep s;
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    a.used = 40; /* not at the start: count_clusters must give everything back */
    if (!CHECK_EQ(subd_sr48_count_clusters(&a, in, &clusters, &d), SUBD_OK)) return;
    CHECK_EQ(a.used, 40);
    if (!CHECK_EQ(subd_sr48_plan(in, o, clusters, &plan, 0), SUBD_OK)) return;
    if (!CHECK_EQ(subd_sr48_plan(in, o, SUBD_SR48_CLUSTERS_UNKNOWN, &bound, 0), SUBD_OK)) return;
    CHECK(bound >= plan);
    if (!CHECK(plan + 64u <= H_ARENA_BYTES)) return;
    /* the exact plan is the measured peak */
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    subd_arena_reset_peak(&a);
    if (!sr48(&a, in, o, &h)) return;
    CHECK_EQ(a.peak, plan);
    CHECK_EQ(h.num_clusters, clusters);
    c.in = in;
    c.o = o;
    s = h_sweep_make(build_run, &c, h_arena_buf, H_ARENA_BYTES, plan);
    s.first = exhaustive ? 0u : plan - 1u;
    s.need_hi = bound; /* a failing call may ask for more than the exact plan */
    s.out = &c.h;
    s.out_bytes = sizeof c.h;
    s.in_mesh = in;
    if (!h_arena_sweep(&s)) return;
    if (exhaustive) {
        h_str("    plan ");
        h_u32(plan);
        h_str(" bytes (bound without the cluster count ");
        h_u32(bound);
        h_str("), every smaller arena fails cleanly");
        h_nl();
    }
}

static void sr48_plan_exhaustive(void)
{
    static const uint32_t one_idx[3] = {0, 1, 2};
    subd_real tpos[9];
    subd_arena a;
    subd_mesh tri, sq, fan, ico;
    subd_face_list fl;
    subd_sr48_opts o;
    uint32_t i;
    for (i = 0; i < 9; i++) tpos[i] = 0;
    tpos[3] = SUBD_REAL_ONE;
    tpos[7] = SUBD_REAL_ONE;
    subd_arena_init(&a, g_in_buf, IN_BYTES);
    fl = tri_list(3, tpos, 1, one_idx);
    if (!h_build(&a, &fl, &tri)) return;
    fl = grid_list(1, 0);
    if (!h_build(&a, &fl, &sq)) return;
    if (!load_tri(&a, "test/data/hexfan.obj", &fan)) return;
    o = sopts(0, 0);
    plan_case(&tri, &o, 1);
    o = sopts(2, 0);
    plan_case(&tri, &o, 1);
    o = sopts(3, 0);
    plan_case(&sq, &o, 1);
    o = sopts(2, SUBD_SR48_NO_SMOOTH);
    plan_case(&fan, &o, 1);
    o = sopts(3, 0);
    plan_case(&fan, &o, 0);
    if (!load_tri(&a, "test/data/icosahedron.obj", &ico)) return;
    o = sopts(4, 0);
    plan_case(&ico, &o, 0);
    o = sopts(5, SUBD_SR48_NO_SMOOTH);
    plan_case(&ico, &o, 0);
}

static void sr48_errors(void)
{
    subd_arena a;
    subd_mesh in, q, pts;
    subd_sr48 h;
    subd_diag d;
    subd_sr48_opts o = sopts(1, 0);
    subd_face_list fl;
    uint32_t plan, c;
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    if (!load_tri(&a, "test/data/hexfan.obj", &in)) return;
    o.steps = SUBD_SR48_MAX_STEPS + 1u;
    CHECK_EQ(subd_sr48_plan(&in, &o, SUBD_SR48_CLUSTERS_UNKNOWN, &plan, 0), SUBD_ERR_PARAM);
    CHECK_FAIL(subd_sr48_build(&a, &in, &o, &h, &d), &d, SUBD_ERR_PARAM);
    o = sopts(1, 0x2u);
    CHECK_FAIL(subd_sr48_build(&a, &in, &o, &h, &d), &d, SUBD_ERR_PARAM);
    o = sopts(1, 0);
    CHECK_FAIL(subd_sr48_build(0, &in, &o, &h, &d), &d, SUBD_ERR_PARAM);
    CHECK_FAIL(subd_sr48_build(&a, 0, &o, &h, &d), &d, SUBD_ERR_PARAM);
    CHECK_FAIL(subd_sr48_build(&a, &in, 0, &h, &d), &d, SUBD_ERR_PARAM);
    CHECK_FAIL(subd_sr48_build(&a, &in, &o, 0, &d), &d, SUBD_ERR_PARAM);
    CHECK_EQ(subd_sr48_plan(&in, &o, SUBD_SR48_CLUSTERS_UNKNOWN, 0, 0), SUBD_ERR_PARAM);
    CHECK_EQ(subd_sr48_plan(&in, &o, 4, &plan, 0), SUBD_ERR_PARAM); /* 6 faces: at most 3 clusters */
    CHECK_EQ(subd_sr48_plan(&in, &o, 3, &plan, 0), SUBD_OK);
    CHECK_FAIL(subd_sr48_count_clusters(0, &in, &c, &d), &d, SUBD_ERR_PARAM);
    CHECK_FAIL(subd_sr48_count_clusters(&a, &in, 0, &d), &d, SUBD_ERR_PARAM);
    CHECK_EQ(a.used, subd_arena_mark(&a));
    /* count_clusters in too small an arena */
    {
        subd_arena small;
        subd_arena_init(&small, g_in_buf, 64);
        CHECK_FAIL(subd_sr48_count_clusters(&small, &in, &c, &d), &d, SUBD_ERR_NOMEM);
        CHECK(d.bytes_needed > 64u);
        CHECK_EQ(small.used, 0);
    }
    /* a quad mesh */
    if (!load_tri(&a, "test/data/icosahedron.obj", &q)) return;
    {
        const corpus_file *cf = corpus_find("test/data/cube_quad.obj");
        if (CHECK(cf != 0) && CHECK_EQ(subd_obj_read(&a, cf->data, cf->len, &q, &d), SUBD_OK)) {
            CHECK_EQ(subd_sr48_plan(&q, &o, SUBD_SR48_CLUSTERS_UNKNOWN, &plan, 0), SUBD_ERR_NOT_TRIANGLES);
            d.face = 77u;
            d.bytes_needed = 99u;
            CHECK_FAIL(subd_sr48_plan(&q, &o, SUBD_SR48_CLUSTERS_UNKNOWN, &plan, &d), &d, SUBD_ERR_NOT_TRIANGLES);
            CHECK_EQ(d.status, SUBD_ERR_NOT_TRIANGLES); /* the plan names the face as the build does */
            CHECK_EQ(d.face, 0);
            CHECK_EQ(d.bytes_needed, 0u);
            CHECK_FAIL(subd_sr48_build(&a, &q, &o, &h, &d), &d, SUBD_ERR_NOT_TRIANGLES);
            CHECK_EQ(d.face, 0);
            CHECK_FAIL(subd_sr48_count_clusters(&a, &q, &c, &d), &d, SUBD_ERR_NOT_TRIANGLES);
        }
    }
    /* points only: no faces */
    fl = tri_list(3, g_pos, 0, 0);
    g_pos[0] = g_pos[1] = g_pos[2] = 0;
    g_pos[3] = g_pos[4] = g_pos[5] = 0;
    g_pos[6] = g_pos[7] = g_pos[8] = 0;
    if (h_build(&a, &fl, &pts)) {
        CHECK_EQ(subd_sr48_plan(&pts, &o, SUBD_SR48_CLUSTERS_UNKNOWN, &plan, 0), SUBD_ERR_EMPTY);
        CHECK_FAIL(subd_sr48_build(&a, &pts, &o, &h, &d), &d, SUBD_ERR_EMPTY);
    }
#if !SUBD_FIXED
    /* float32: a face point beyond FLT_MAX */
    {
        static const uint32_t idx[3] = {0, 1, 2};
        subd_mesh big;
        uint32_t mark = subd_arena_mark(&a);
        g_pos[0] = 3e38f; g_pos[1] = 0; g_pos[2] = 0;
        g_pos[3] = 3e38f; g_pos[4] = 1; g_pos[5] = 0;
        g_pos[6] = 3e38f; g_pos[7] = 0; g_pos[8] = 1;
        fl = tri_list(3, g_pos, 1, idx);
        if (h_build(&a, &fl, &big)) {
            uint32_t used = a.used;
            CHECK_FAIL(subd_sr48_build(&a, &big, &o, &h, &d), &d, SUBD_ERR_RANGE);
            CHECK_EQ(a.used, used);
        }
        subd_arena_rewind(&a, mark);
    }
#endif
}

/* ------------------------------------------------------------------------------------ */
/* (6) Output hashes (host = QEMU per arithmetic)                                         */

static void sr48_hashes(void)
{
    static const char *const files[] = {"test/data/icosahedron.obj", "test/data/hexfan.obj",
                                        "test/data/grid_tri_8x8.obj", "test/data/spot_control_mesh.obj"};
    static const uint32_t steps[] = {4, 5, 2, 1};
    static const char *const names[2][4] = {
        {"sr48_icosahedron_4", "sr48_hexfan_5", "sr48_grid8_2", "sr48_spot_1"},
        {"sr48_icosahedron_4_refine", "sr48_hexfan_5_refine", "sr48_grid8_2_refine", "sr48_spot_1_refine"}};
    uint32_t i, pass;
    for (pass = 0; pass < 2; pass++)
        for (i = 0; i < 4; i++) {
            subd_arena a;
            subd_mesh in;
            subd_sr48 h;
            subd_sr48_opts o = sopts(steps[i], pass ? SUBD_SR48_NO_SMOOTH : 0u);
            subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
            if (!load_tri(&a, files[i], &in) || !sr48(&a, &in, &o, &h)) continue;
            h_hash(names[pass][i], sr48_hash(&h));
        }
}

const test_case suite_sr48[] = {
    {"sr48_preprocess_valences", sr48_preprocess_valences},
    {"sr48_levels", sr48_levels},
    {"sr48_zp_equivalence", sr48_zp_equivalence},
    {"sr48_boundary_chaikin", sr48_boundary_chaikin},
    {"sr48_planes", sr48_planes},
    {"sr48_affine", sr48_affine},
    {"sr48_refine_only", sr48_refine_only},
    {"sr48_plan_exhaustive", sr48_plan_exhaustive},
    {"sr48_errors", sr48_errors},
    {"sr48_hashes", sr48_hashes},
    {0, 0}
};
