/* SPDX-License-Identifier: MIT */
/* Loop's vertex classification (src/loop_rules.h), the one rule loop.c, loop_limit.c and
 * pia.c share, and the case on which pia.c used to disagree: an interior valence-6 crease
 * vertex is regular only when its two crease edges are opposite (three faces per side),
 * not when they are two ring steps apart. subd_loop_classify is checked on small built meshes
 * (smooth, dart, boundary crease of valence 3/4/5, corner by tag and by three sharp edges,
 * every crease-edge pair of interior valence 5, 6 and 7, isolated) against the definition
 * restated here. Then the three users on a 7 x 7 triangle grid whose crease runs straight
 * through vertex (3,3) ("opposite") or turns there by two ring steps ("bent"): the limit
 * positions (PAPER rule) equal l S0 computed here from the curve rules (l the stationary
 * eigenvector for v's class, S0 the first level's curve matrix; checked against the table
 * in loop_limit.c's header), one level of subd_loop gives the crease-edge vertices the
 * midpoint when both ends are regular and 5/8 - 3/8 when one is (exact: the coordinates
 * are multiples of 1/8), and subd_pia (FAST and PAPER) converges on the bent grid with
 * subd_loop_limit of its result, and the masks applied here in double to it, within tol of
 * the input. Expected values are computed in double from closed forms; tolerances: float32
 * 2^-20 (1 + max |coordinate|), Q16.16 0.51 + 2^-13 sum_i max_c |p_i - v|_c LSB (one
 * rounding plus the Q28 weight rounding, as test_loop_limit.c states). */
#include "harness.h"
#include "fixtures.h"
#include "../src/loop_rules.h"

#define GN 7u /* grid vertices per side */
#define GV(i, j) ((uint32_t)(j) * GN + (uint32_t)(i))
#define MAXV 64u
#define MAXF 96u

static subd_real g_pos[3 * MAXV];
static uint32_t g_idx[3 * MAXF];
static uint8_t g_work[64 * 1024] __attribute__((aligned(8)));

static double dabs(double x) { return x < 0.0 ? -x : x; }

/* num / 8 as a subd_real (exact in both arithmetics) */
static subd_real E8(int32_t num)
{
    uint32_t ovf = 0;
    return subd_div(subd_from_int(num, &ovf), subd_from_int(8, &ovf), &ovf);
}

static void set_pos(uint32_t v, int32_t x8, int32_t y8, int32_t z8)
{
    g_pos[3 * v] = E8(x8);
    g_pos[3 * v + 1] = E8(y8);
    g_pos[3 * v + 2] = E8(z8);
}

static int build(subd_arena *a, uint32_t nv, uint32_t nf, subd_mesh *m)
{
    subd_face_list fl = {0, 0, 0, 0, 0, 0, 0, 0};
    fl.num_verts = nv;
    fl.pos = g_pos;
    fl.num_faces = nf;
    fl.index = g_idx;
    return h_build(a, &fl, m);
}

/* Fan around vertex 0 with ring 1..n: closed (n triangles, 0 interior of valence n) or open
 * (n - 1 triangles, 0 on the boundary with valence n). `isolated` adds vertex n + 1, used by
 * no face. */
static int build_fan(subd_arena *a, uint32_t n, int closed, int isolated, subd_mesh *m)
{
    uint32_t k, nf = closed ? n : n - 1u;
    set_pos(0, 0, 0, 4);
    for (k = 1; k <= n; k++) set_pos(k, (int32_t)(8 * subd_cos_turns((int32_t)k, (int32_t)n) / SUBD_REAL_ONE),
                                      (int32_t)(8 * subd_sin_turns((int32_t)k, (int32_t)n) / SUBD_REAL_ONE),
                                      (int32_t)((k * 5u) % 7u) - 3);
    if (isolated) set_pos(n + 1u, 1, 2, 3);
    for (k = 0; k < nf; k++) {
        g_idx[3 * k] = 0;
        g_idx[3 * k + 1] = k + 1u;
        g_idx[3 * k + 2] = k % n + 2u > n ? 1u : k + 2u;
    }
    return build(a, n + 1u + (isolated ? 1u : 0u), nf, m);
}

/* z of grid vertex (i, j), in eighths: varied so that no crease is straight in 3D */
static int32_t grid_z8(uint32_t i, uint32_t j) { return (int32_t)((3u * i * i + 5u * j + 2u * i * j) % 7u) - 3; }

/* GN x GN grid, quads split by the diagonal (i,j)-(i+1,j+1): every interior vertex has
 * valence 6, ring (1,0) (1,1) (0,1) (-1,0) (-1,-1) (0,-1). Vertex (i,j) at
 * (i - 3, j - 3, grid_z8 / 8). */
static int build_grid(subd_arena *a, subd_mesh *m)
{
    uint32_t i, j, f = 0;
    for (j = 0; j < GN; j++)
        for (i = 0; i < GN; i++) set_pos(GV(i, j), 8 * ((int32_t)i - 3), 8 * ((int32_t)j - 3), grid_z8(i, j));
    for (j = 0; j + 1u < GN; j++)
        for (i = 0; i + 1u < GN; i++) {
            g_idx[3 * f] = GV(i, j);
            g_idx[3 * f + 1] = GV(i + 1u, j);
            g_idx[3 * f + 2] = GV(i + 1u, j + 1u);
            f++;
            g_idx[3 * f] = GV(i, j);
            g_idx[3 * f + 1] = GV(i + 1u, j + 1u);
            g_idx[3 * f + 2] = GV(i, j + 1u);
            f++;
        }
    return build(a, GN * GN, f, m);
}

/* Tags or clears edge a-b as a crease (either direction). */
static int crease(subd_mesh *m, uint32_t a, uint32_t b, int on)
{
    uint32_t h = fx_find_he(m, a, b);
    if (h == SUBD_NONE) h = fx_find_he(m, b, a);
    if (h == SUBD_NONE) return 0;
    if (on) subd_edge_tag_set(m, h, SUBD_ETAG_CREASE);
    else subd_edge_tag_clear(m, h, SUBD_ETAG_CREASE);
    return 1;
}

/* The grid's crease: (0,3) .. (3,3), then straight on to (6,3) (bent = 0), or turning two
 * ring steps to the diagonal (4,4) .. (6,6) (bent = 1). Ends on the boundary: corners. */
static int grid_crease(subd_mesh *m, int bent)
{
    uint32_t k;
    int ok = 1;
    for (k = 0; k < 3u; k++) ok &= crease(m, GV(k, 3), GV(k + 1u, 3), 1);
    for (k = 3; k < 6u; k++)
        ok &= bent ? crease(m, GV(k, k), GV(k + 1u, k + 1u), 1) : crease(m, GV(k, 3), GV(k + 1u, 3), 1);
    return CHECK(ok);
}

/* The far end of the crease from (3,3) */
static uint32_t grid_right(int bent, uint32_t k) { return bent ? GV(3u + k, 3u + k) : GV(3u + k, 3); }

/* ------------------------------------------------------------------------------------ */
/* 1. subd_loop_classify                                                                       */

static int has_pair(const loop_vinfo *c, uint32_t a, uint32_t b)
{
    return (c->c0 == a && c->c1 == b) || (c->c0 == b && c->c1 == a);
}

static void rules_classify_fans(void)
{
    subd_arena a;
    subd_mesh m;
    loop_vinfo c;
    uint32_t n, p, q, r;
    /* interior: smooth, dart, every crease pair, three sharp edges, the corner tag */
    for (n = 5; n <= 7u; n++) {
        subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
        if (!build_fan(&a, n, 1, 0, &m)) return;
        subd_loop_classify(&m, 0, &c);
        CHECK_EQ(c.cls, LOOP_SMOOTH);
        CHECK_EQ(c.valence, n);
        CHECK_EQ(c.nsharp, 0);
        CHECK_EQ(c.boundary, 0);
        CHECK_EQ(c.regular, 0);
        for (p = 1; p <= n; p++) {
            crease(&m, 0, p, 1);
            subd_loop_classify(&m, 0, &c);
            CHECK_EQ(c.cls, LOOP_DART);
            CHECK_EQ(c.nsharp, 1);
            CHECK_EQ(c.regular, 0);
            for (q = p + 1u; q <= n; q++) {
                /* regular exactly when three faces lie on each side: q - p == 3 at n = 6 */
                uint32_t want = n == 6u && q - p == 3u;
                crease(&m, 0, q, 1);
                subd_loop_classify(&m, 0, &c);
                CHECK_EQ(c.cls, LOOP_CREASE);
                CHECK_EQ(c.nsharp, 2);
                CHECK_EQ(c.valence, n);
                CHECK_EQ(c.boundary, 0);
                CHECK(has_pair(&c, p, q));
                CHECK(c.i0 < c.i1 && c.i1 < n);
                if (!CHECK_EQ(c.regular, want)) {
                    h_str("  n ");
                    h_u32(n);
                    h_str(" crease to ");
                    h_u32(p);
                    h_str(", ");
                    h_u32(q);
                    h_nl();
                }
                for (r = q + 1u; r <= n; r++) {
                    crease(&m, 0, r, 1);
                    subd_loop_classify(&m, 0, &c);
                    CHECK_EQ(c.cls, LOOP_CORNER);
                    CHECK_EQ(c.nsharp, 3);
                    CHECK_EQ(c.regular, 0);
                    crease(&m, 0, r, 0);
                }
                m.vert_tag[0] |= SUBD_VTAG_CORNER;
                subd_loop_classify(&m, 0, &c);
                CHECK_EQ(c.cls, LOOP_CORNER);
                CHECK_EQ(c.regular, 0);
                m.vert_tag[0] &= (uint8_t)~SUBD_VTAG_CORNER;
                crease(&m, 0, q, 0);
            }
            crease(&m, 0, p, 0);
        }
    }
    /* boundary: crease vertex with its two boundary neighbours, regular only at valence 4 */
    for (n = 3; n <= 5u; n++) {
        subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
        if (!build_fan(&a, n, 0, 1, &m)) return;
        subd_loop_classify(&m, 0, &c);
        CHECK_EQ(c.cls, LOOP_CREASE);
        CHECK_EQ(c.boundary, 1);
        CHECK_EQ(c.valence, n);
        CHECK_EQ(c.nsharp, 2);
        CHECK(has_pair(&c, 1, n));
        CHECK_EQ(c.regular, n == 4u);
        /* the ring vertices 2..n-1: boundary, valence 3, extraordinary */
        subd_loop_classify(&m, 2, &c);
        CHECK_EQ(c.cls, LOOP_CREASE);
        CHECK_EQ(c.valence, 3);
        CHECK_EQ(c.regular, 0);
        /* the CORNER tag wins */
        m.vert_tag[0] |= SUBD_VTAG_CORNER;
        subd_loop_classify(&m, 0, &c);
        CHECK_EQ(c.cls, LOOP_CORNER);
        CHECK_EQ(c.regular, 0);
        m.vert_tag[0] &= (uint8_t)~SUBD_VTAG_CORNER;
        /* a crease edge inside makes three sharp edges: a corner */
        crease(&m, 0, 2, 1);
        subd_loop_classify(&m, 0, &c);
        CHECK_EQ(c.cls, LOOP_CORNER);
        CHECK_EQ(c.nsharp, 3);
        /* the vertex no face uses */
        subd_loop_classify(&m, n + 1u, &c);
        CHECK_EQ(c.cls, LOOP_ISOLATED);
        CHECK_EQ(c.regular, 0);
        CHECK_EQ(c.valence, 0);
    }
}

/* The grid: vertex (3,3) and its crease neighbours, opposite and bent. */
static void rules_classify_grid(void)
{
    int bent;
    for (bent = 0; bent < 2; bent++) {
        subd_arena a;
        subd_mesh m;
        loop_vinfo c;
        uint32_t k;
        subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
        if (!build_grid(&a, &m)) return;
        subd_loop_classify(&m, GV(3, 1), &c);
        CHECK_EQ(c.cls, LOOP_SMOOTH);
        CHECK_EQ(c.valence, 6);
        subd_loop_classify(&m, GV(3, 0), &c); /* boundary, valence 4 */
        CHECK_EQ(c.cls, LOOP_CREASE);
        CHECK_EQ(c.valence, 4);
        CHECK_EQ(c.regular, 1);
        subd_loop_classify(&m, GV(0, 0), &c); /* boundary, valence 3 */
        CHECK_EQ(c.valence, 3);
        CHECK_EQ(c.regular, 0);
        if (!grid_crease(&m, bent)) return;
        subd_loop_classify(&m, GV(3, 3), &c);
        CHECK_EQ(c.cls, LOOP_CREASE);
        CHECK_EQ(c.valence, 6);
        CHECK_EQ(c.boundary, 0);
        CHECK(has_pair(&c, GV(2, 3), grid_right(bent, 1)));
        CHECK_EQ(c.i1 - c.i0 == 3u, !bent); /* ring distance 3, or 2 either way round */
        CHECK_EQ(c.i1 - c.i0 == 2u || c.i1 - c.i0 == 4u, bent);
        CHECK_EQ(c.regular, !bent);
        for (k = 1; k < 3u; k++) {
            subd_loop_classify(&m, GV(k, 3), &c);
            CHECK_EQ(c.regular, 1);
            subd_loop_classify(&m, grid_right(bent, k), &c);
            CHECK_EQ(c.cls, LOOP_CREASE);
            CHECK_EQ(c.regular, 1);
        }
        subd_loop_classify(&m, GV(0, 3), &c);
        CHECK_EQ(c.cls, LOOP_CORNER);
        subd_loop_classify(&m, grid_right(bent, 3), &c);
        CHECK_EQ(c.cls, LOOP_CORNER);
        CHECK_EQ(c.nsharp, 3);
    }
}

/* ------------------------------------------------------------------------------------ */
/* 2. Limit positions (PAPER rule)                                                        */

/* The curve limit mask (weight of c0, v, c1) from the rules alone: from level 1 on the
 * neighbours are regular and v keeps its class, so the stationary matrix is
 * [1-w w 0; 1/8 3/4 1/8; 0 w 1-w] with w v's weight on its sharp edges (1/2 regular, 3/8
 * not), left eigenvector (a, 8wa, a), a = 1/(2 + 8w). Level 0: edge (c_i, v) puts x_i on
 * c_i: 1/2 for the same class, 5/8 for a regular c_i and extraordinary v, 3/8 the other way;
 * the mask is l S0. */
static void curve_mask(int rv, int r0, int r1, double w[3])
{
    double wv = rv ? 0.5 : 0.375, aa = 1.0 / (2.0 + 8.0 * wv), bb = 8.0 * wv * aa;
    double x0 = r0 == rv ? 0.5 : r0 ? 0.625 : 0.375;
    double x1 = r1 == rv ? 0.5 : r1 ? 0.625 : 0.375;
    w[0] = aa * x0 + bb / 8.0;
    w[1] = aa * (1.0 - x0) + 0.75 * bb + aa * (1.0 - x1);
    w[2] = aa * x1 + bb / 8.0;
}

/* The derivation above against loop_limit.c's table (R; R R) 1/6 2/3 1/6 ... */
static void rules_mask_table(void)
{
    static const int cls[6][3] = {{1, 1, 1}, {1, 1, 0}, {1, 0, 0}, {0, 1, 1}, {0, 1, 0}, {0, 0, 0}};
    static const int32_t num[6][3] = {{8, 32, 8}, {8, 33, 7}, {7, 34, 7}, {8, 24, 8}, {8, 25, 7}, {7, 26, 7}};
    static const int32_t den[6] = {48, 48, 48, 40, 40, 40};
    uint32_t t, k;
    for (t = 0; t < 6u; t++) {
        double w[3];
        curve_mask(cls[t][0], cls[t][1], cls[t][2], w);
        for (k = 0; k < 3u; k++) CHECK(dabs(w[k] - (double)num[t][k] / (double)den[t]) < 1e-15);
        CHECK(dabs(w[0] + w[1] + w[2] - 1.0) < 1e-15);
    }
}

/* Tolerance of one library result of a combination of v and p[0..np), in real units. */
static double lim_tol(const subd_real *pos, uint32_t v, const uint32_t *p, uint32_t np)
{
#if SUBD_FIXED
    double s = 0.0;
    uint32_t i, k;
    for (i = 0; i < np; i++) {
        double mx = 0.0;
        for (k = 0; k < 3u; k++) {
            double d = dabs(h_dbl(pos[3 * p[i] + k]) - h_dbl(pos[3 * v + k]));
            if (d > mx) mx = d;
        }
        s += mx;
    }
    return (0.51 + s / 8192.0) / 65536.0;
#else
    double mx = 0.0;
    uint32_t i, k;
    for (k = 0; k < 3u; k++) {
        if (dabs(h_dbl(pos[3 * v + k])) > mx) mx = dabs(h_dbl(pos[3 * v + k]));
        for (i = 0; i < np; i++)
            if (dabs(h_dbl(pos[3 * p[i] + k])) > mx) mx = dabs(h_dbl(pos[3 * p[i] + k]));
    }
    return (1.0 + mx) / 1048576.0;
#endif
}

/* Largest coordinate difference between lim[v] and the mask (c0, v, c1 with classes rv,
 * r0, r1) applied to ctrl; *sep: the same for the mask of v's other class (how far apart
 * the two answers are). */
static double mask_err(const subd_real *ctrl, const subd_real *lim, uint32_t v, uint32_t c0, uint32_t c1, int rv,
                       int r0, int r1, double *sep)
{
    double w[3], o[3], e = 0.0, s = 0.0;
    uint32_t k;
    curve_mask(rv, r0, r1, w);
    curve_mask(!rv, r0, r1, o);
    for (k = 0; k < 3u; k++) {
        double x0 = h_dbl(ctrl[3 * c0 + k]), xv = h_dbl(ctrl[3 * v + k]), x1 = h_dbl(ctrl[3 * c1 + k]);
        double want = w[0] * x0 + w[1] * xv + w[2] * x1, other = o[0] * x0 + o[1] * xv + o[2] * x1;
        if (dabs(h_dbl(lim[3 * v + k]) - want) > e) e = dabs(h_dbl(lim[3 * v + k]) - want);
        if (dabs(other - want) > s) s = dabs(other - want);
    }
    if (sep) *sep = s;
    return e;
}

/* Checks lim[v] against the mask; the other class's mask must be far outside the tolerance
 * (else the case would not tell the classes apart). */
static void check_mask(const subd_real *ctrl, const subd_real *lim, uint32_t v, uint32_t c0, uint32_t c1, int rv,
                       int r0, int r1, const char *what)
{
    uint32_t p[2];
    double sep, tol, e;
    p[0] = c0;
    p[1] = c1;
    tol = lim_tol(ctrl, v, p, 2);
    e = mask_err(ctrl, lim, v, c0, c1, rv, r0, r1, &sep);
    CHECK(sep > 16.0 * tol);
    if (!CHECK(e <= tol)) {
        h_str("  limit mask: ");
        h_str(what);
        h_str(" vertex ");
        h_u32(v);
        h_str(" error (2^-30 units) ");
        h_u32((uint32_t)(e * 1073741824.0));
        h_nl();
    }
}

static int limit_of(subd_arena *a, const subd_mesh *m, subd_real **lim)
{
    subd_diag d;
    return CHECK_OK(subd_loop_limit(a, m, &(subd_loop_limit_opts){SUBD_LOOP_BOUNDARY_PAPER, 0u}, lim, 0, &d), &d);
}

/* Interior valence-6 fan, crease to ring vertices 1 and 4 (opposite: regular) or 1 and 3
 * (not). The ring vertices are boundary vertices; 1 and 3/4 have a third sharp edge, so
 * they are corners (extraordinary): masks (R; E E) 7/48 17/24 7/48 and (E; E E) 7/40 13/20
 * 7/40. */
static void rules_limit_fan(void)
{
    uint32_t other;
    for (other = 3; other <= 4u; other++) {
        subd_arena a;
        subd_mesh m;
        subd_real *lim;
        subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
        if (!build_fan(&a, 6, 1, 0, &m)) return;
        crease(&m, 0, 1, 1);
        crease(&m, 0, other, 1);
        if (!limit_of(&a, &m, &lim)) return;
        check_mask(m.pos, lim, 0, 1, other, other == 4u, 0, 0, other == 4u ? "fan opposite" : "fan bent");
    }
}

/* The grid: (3,3) with regular neighbours, (R; R R) 1/6 2/3 1/6 (opposite) or (E; R R)
 * 1/5 3/5 1/5 (bent); its neighbours (2,3) and (4,4) see it as regular or not:
 * (R; R R) or (R; R E) 1/6 11/16 7/48; the next ones out are (R; R R); (5,3)/(5,5) have a
 * corner on the far side: (R; R E). */
static void rules_limit_grid(void)
{
    int bent;
    for (bent = 0; bent < 2; bent++) {
        subd_arena a;
        subd_mesh m;
        subd_real *lim;
        const char *what = bent ? "grid bent" : "grid opposite";
        subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
        if (!build_grid(&a, &m) || !grid_crease(&m, bent)) return;
        if (!limit_of(&a, &m, &lim)) return;
        check_mask(m.pos, lim, GV(3, 3), GV(2, 3), grid_right(bent, 1), !bent, 1, 1, what);
        check_mask(m.pos, lim, GV(2, 3), GV(1, 3), GV(3, 3), 1, 1, !bent, what);
        check_mask(m.pos, lim, grid_right(bent, 1), GV(3, 3), grid_right(bent, 2), 1, !bent, 1, what);
        check_mask(m.pos, lim, GV(1, 3), GV(0, 3), GV(2, 3), 1, 0, 1, what);
        check_mask(m.pos, lim, grid_right(bent, 2), grid_right(bent, 1), grid_right(bent, 3), 1, 1, 0, what);
    }
}

/* ------------------------------------------------------------------------------------ */
/* 3. One level of subd_loop (PAPER): the new vertex on a crease edge                     */

/* The output vertex on input edge a -> b (subd_loop's layout: face f's child 4f + i is
 * (v_i, m_i, m_(i-1)), m_i on the edge from corner i to i + 1), or SUBD_NONE. */
static uint32_t edge_child(const subd_mesh *in, const subd_mesh *out, uint32_t a, uint32_t b)
{
    uint32_t h = fx_find_he(in, a, b), f, c;
    if (h == SUBD_NONE) return SUBD_NONE;
    f = in->corner_face[h];
    c = out->face_start[4u * f + (h - in->face_start[f])];
    if (!CHECK_EQ(out->corner_vert[c], a)) return SUBD_NONE;
    return out->corner_vert[c + 1u];
}

/* out vertex o == wa p_a + (1 - wa) p_b of the input, exactly (the coordinates are
 * multiples of 1/8 and the weights of 1/8: every product and sum is exact). */
static void check_edge(const subd_mesh *in, const subd_mesh *out, uint32_t a, uint32_t b, double wa,
                       const char *what)
{
    uint32_t o = edge_child(in, out, a, b), k;
    if (o == SUBD_NONE) o = edge_child(in, out, b, a);
    if (!CHECK(o != SUBD_NONE && o < out->num_verts)) return;
    for (k = 0; k < 3u; k++) {
        double want = wa * h_dbl(in->pos[3 * a + k]) + (1.0 - wa) * h_dbl(in->pos[3 * b + k]);
        if (!CHECK(h_dbl(out->pos[3 * o + k]) == want)) {
            h_str("  edge rule: ");
            h_str(what);
            h_str(" edge ");
            h_u32(a);
            h_str("-");
            h_u32(b);
            h_nl();
            return;
        }
    }
}

static void rules_subdivide_grid(void)
{
    int bent;
    for (bent = 0; bent < 2; bent++) {
        subd_arena a;
        subd_mesh m, out;
        subd_loop_opts o;
        subd_diag d;
        const char *what = bent ? "bent" : "opposite";
        uint32_t v = GV(3, 3), l = GV(2, 3), r = grid_right(bent, 1), k;
        double wv = bent ? 0.375 : 0.5; /* (3,3)'s weight on its crease edges */
        subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
        if (!build_grid(&a, &m) || !grid_crease(&m, bent)) return;
        o.levels = 1;
        o.boundary = SUBD_LOOP_BOUNDARY_PAPER;
        o.flags = SUBD_LOOP_ADJACENCY; /* full output, for h_mesh_hash */
        if (!CHECK_OK(subd_loop(&a, &m, &o, &out, &d), &d)) return;
        check_edge(&m, &out, v, l, wv, what);
        check_edge(&m, &out, v, r, wv, what);
        check_edge(&m, &out, GV(1, 3), GV(2, 3), 0.5, what);             /* R - R */
        check_edge(&m, &out, grid_right(bent, 1), grid_right(bent, 2), 0.5, what);
        check_edge(&m, &out, grid_right(bent, 2), grid_right(bent, 3), 0.625, what); /* R - corner */
        check_edge(&m, &out, GV(1, 3), GV(0, 3), 0.625, what);
        /* the vertex itself: 3/4 v + 1/8 (l + r), whatever its class */
        for (k = 0; k < 3u; k++)
            CHECK(h_dbl(out.pos[3 * v + k]) ==
                  0.75 * h_dbl(m.pos[3 * v + k]) + 0.125 * (h_dbl(m.pos[3 * l + k]) + h_dbl(m.pos[3 * r + k])));
        h_hash(bent ? "loop-rules-subd-bent" : "loop-rules-subd-opposite", h_mesh_hash(&out));
    }
}

/* ------------------------------------------------------------------------------------ */
/* 4. PIA on the bent grid                                                                */

static subd_real tol_std(void)
{
#if SUBD_FIXED
    return 16;
#else
    return 1e-5f;
#endif
}

static void rules_pia_bent(void)
{
    uint32_t meth;
    for (meth = 0; meth < 2u; meth++) {
        subd_arena a, w;
        subd_mesh m, mv;
        subd_pia_opts o;
        subd_pia_result res;
        subd_diag d;
        subd_real *V, *lim;
        double tol, slack, emax = 0.0;
        uint32_t i, k, hv = 2166136261u;
        subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
        if (!build_grid(&a, &m) || !grid_crease(&m, 1)) return;
        o.boundary = SUBD_LOOP_BOUNDARY_PAPER;
        o.tol = tol_std();
        o.max_iter = 300;
        o.method = (subd_pia_method)meth;
        subd_arena_init(&w, g_work, (uint32_t)sizeof g_work);
        if (!CHECK_OK(subd_pia(&w, &m, &o, &V, &res, &d), &d)) return;
        CHECK(res.converged);
        CHECK(res.iterations >= 1u && res.iterations <= o.max_iter);
        h_str(meth ? "  pia bent grid fast: " : "  pia bent grid paper: ");
        h_u32(res.iterations);
        h_str(" iterations");
        h_nl();
        mv = m;
        mv.pos = V;
        if (!limit_of(&w, &mv, &lim)) return;
        tol = h_dbl(o.tol);
        slack = SUBD_FIXED ? 1.0 / 65536.0 : 1e-6;
        /* |P - L V| at every vertex, computed here */
        for (i = 0; i < m.num_verts; i++) {
            double s = 0.0;
            for (k = 0; k < 3u; k++) {
                double dd = h_dbl(m.pos[3 * i + k]) - h_dbl(lim[3 * i + k]);
                s += dd * dd;
            }
            if (s > emax) emax = s;
        }
        CHECK(emax <= (tol + slack) * (tol + slack)); /* squared distances */
        /* and the masks applied here to V at the crease vertices next to the bend */
        {
            uint32_t p[2];
            double e0, e1, e2;
            p[0] = GV(2, 3);
            p[1] = GV(4, 4);
            e0 = mask_err(V, m.pos, GV(3, 3), GV(2, 3), GV(4, 4), 0, 1, 1, 0);
            e1 = mask_err(V, m.pos, GV(2, 3), GV(1, 3), GV(3, 3), 1, 1, 0, 0);
            e2 = mask_err(V, m.pos, GV(4, 4), GV(3, 3), GV(5, 5), 1, 0, 1, 0);
            slack = lim_tol(V, GV(3, 3), p, 2);
            CHECK(e0 <= tol + slack);
            CHECK(e1 <= tol + slack);
            CHECK(e2 <= tol + slack);
        }
        for (i = 0; i < 3u * m.num_verts; i++) {
            uint32_t bits = subd_real_bits(V[i]);
            hv = h_fnv(hv, &bits, 4);
        }
        h_hash(meth ? "loop-rules-pia-fast" : "loop-rules-pia-paper", hv);
    }
}

const test_case suite_loop_rules[] = {
    {"rules_classify_fans", rules_classify_fans},
    {"rules_classify_grid", rules_classify_grid},
    {"rules_mask_table", rules_mask_table},
    {"rules_limit_fan", rules_limit_fan},
    {"rules_limit_grid", rules_limit_grid},
    {"rules_subdivide_grid", rules_subdivide_grid},
    {"rules_pia_bent", rules_pia_bent},
    {0, 0}
};
