/* SPDX-License-Identifier: MIT */
/* Quasi 4-8 subdivision: the paper's stated results (figures 5-9), per-step invariants
 * checked by brute force against the step's input, smoothing properties (planarity,
 * affine invariance, tags and boundaries), exact planning (every too-small arena fails
 * cleanly), errors, and output hashes for host = QEMU. */
#include "harness.h"
#include "fixtures.h"
#include "subd_quasi48.h"
#include "corpus.h"
#include <math.h>
#if H_HOST
#include <stdio.h>
#endif

#define BIG_BYTES (768u * 1024u)
static uint8_t g_big[BIG_BYTES] __attribute__((aligned(8)));

#define MAXV 2048
#define MAXF 2048
static subd_real g_pos[3 * MAXV];
static uint32_t g_idx[3 * MAXF];

static subd_quasi48_opts opts(uint32_t steps, uint32_t flags)
{
    subd_quasi48_opts o;
    o.steps = steps;
    o.boundary = SUBD_QUASI48_BOUNDARY_FIXED;
    o.flags = flags;
    o.len_bits = 0;
    return o;
}

static subd_real R(int32_t num, int32_t den)
{
    uint32_t ovf = 0;
    return subd_div(subd_from_int(num, &ovf), subd_from_int(den, &ovf), &ovf);
}

/* Planar fan: centre (vertex 0) at (cx, 0), n rim vertices at radius radius[i] (or 1) on
 * angles i/n turns, faces (0, i, i+1). */
static void fan_list(subd_face_list *fl, uint32_t n, const subd_real *radius, subd_real cx)
{
    uint32_t i, ovf = 0;
    g_pos[0] = cx; g_pos[1] = 0; g_pos[2] = 0;
    for (i = 0; i < n; i++) {
        subd_real c = subd_cos_turns((int32_t)i, (int32_t)n), s = subd_sin_turns((int32_t)i, (int32_t)n);
        subd_real r = radius ? radius[i] : SUBD_REAL_ONE;
        g_pos[3 * (i + 1)] = subd_mul(r, c, &ovf);
        g_pos[3 * (i + 1) + 1] = subd_mul(r, s, &ovf);
        g_pos[3 * (i + 1) + 2] = 0;
        g_idx[3 * i] = 0;
        g_idx[3 * i + 1] = i + 1;
        g_idx[3 * i + 2] = (i + 1) % n + 1;
    }
    CHECK_EQ(ovf, 0);
    fl->num_verts = n + 1;
    fl->pos = g_pos;
    fl->num_faces = n;
    fl->face_size = 0;
    fl->index = g_idx;
    fl->num_lines = 0;
    fl->line_size = fl->line_index = 0;
}

/* Planar (n+1) x (n+1) grid of unit squares cut by alternating diagonals: an open disk. */
static void grid_list(subd_face_list *fl, uint32_t n)
{
    (void)fx_grid(n, n, 1, 0, g_pos, g_idx);
    fl->num_verts = (n + 1) * (n + 1);
    fl->pos = g_pos;
    fl->num_faces = 2 * n * n;
    fl->face_size = 0;
    fl->index = g_idx;
    fl->num_lines = 0;
    fl->line_size = fl->line_index = 0;
}

static int run(subd_arena *a, const subd_mesh *in, const subd_quasi48_opts *o, subd_mesh *out)
{
    subd_diag d;
    int st = subd_quasi48(a, in, o, out, &d);
    return CHECK_OK(st, &d);
}

/* One step, checked against its input by brute force:
 *  - every face of `a` is either copied unchanged or split once: face f = (x, m, z) and
 *    the next appended face = (m, y, z), with (x, y, z) = a's face rotated and m a new vertex;
 *  - V' = V + splits (each new vertex used), F' = F + split faces, old positions moved only
 *    by smoothing (refine-only: unchanged, new = midpoint of its edge);
 *  - the output passes the validator again (rebuilt from its face list: same twins), closed
 *    stays closed, Euler characteristic unchanged, all faces triangles. */
static uint8_t g_used[MAXV];
static void check_step(const subd_mesh *a, const subd_mesh *b, int refine_only)
{
    uint32_t f, k = a->num_faces, j, v, nsplit = 0;
    subd_arena tmp;
    subd_face_list fl;
    subd_mesh c;
    if (!CHECK(b->num_verts < MAXV)) return;
    for (v = 0; v < b->num_verts; v++) g_used[v] = 0;
    CHECK_EQ(b->num_corners, 3u * b->num_faces);
    for (f = 0; f < a->num_faces; f++) {
        const uint32_t *p = a->corner_vert + 3u * f, *q = b->corner_vert + 3u * f;
        if (q[0] == p[0] && q[1] == p[1] && q[2] == p[2]) continue;
        nsplit++;
        if (!CHECK(k < b->num_faces)) return;
        for (j = 0; j < 3u; j++) {
            const uint32_t *r = b->corner_vert + 3u * k;
            uint32_t x = p[j], y = p[(j + 1) % 3], z = p[(j + 2) % 3], mm = q[1];
            if (q[0] != x) continue;
            CHECK(mm >= a->num_verts);
            CHECK(q[2] == z);
            CHECK(r[0] == mm && r[1] == y && r[2] == z);
            if (mm < MAXV) g_used[mm] = 1;
            if (refine_only && mm >= a->num_verts) {
                uint32_t t;
                for (t = 0; t < 3u; t++) {
                    uint32_t ovf = 0;
                    subd_real px = a->pos[3u * x + t], py = a->pos[3u * y + t];
                    subd_real lo = px < py ? px : py, hi = px < py ? py : px;
                    subd_real mid = b->pos[3u * mm + t];
                    (void)ovf;
                    CHECK(mid >= lo && mid <= hi);
                }
            }
            break;
        }
        CHECK(j < 3u);
        k++;
    }
    CHECK_EQ(b->num_faces, a->num_faces + nsplit);
    for (v = a->num_verts; v < b->num_verts; v++) CHECK(g_used[v]);
    if (refine_only)
        for (v = 0; v < 3u * a->num_verts; v++) CHECK(a->pos[v] == b->pos[v]);
    CHECK_EQ(subd_mesh_euler(b), subd_mesh_euler(a));
    if (a->num_boundary_edges == 0) CHECK_EQ(b->num_boundary_edges, 0);
    CHECK_EQ(b->num_boundary_loops, a->num_boundary_loops);
    /* validator: rebuild from the plain face list, compare adjacency */
    fl.num_verts = b->num_verts;
    fl.pos = b->pos;
    fl.num_faces = b->num_faces;
    fl.face_size = 0;
    fl.index = b->corner_vert;
    fl.num_lines = 0;
    fl.line_size = fl.line_index = 0;
    subd_arena_init(&tmp, h_arena_buf, H_ARENA_BYTES);
    if (CHECK_EQ(subd_mesh_build(&tmp, &fl, &c, 0), SUBD_OK)) {
        const uint8_t vb = SUBD_VTAG_BOUNDARY | SUBD_VTAG_ISOLATED, keep = SUBD_VTAG_CORNER | SUBD_VTAG_FIXED;
        for (j = 0; j < b->num_corners; j++) CHECK(c.twin[j] == b->twin[j]);
        for (v = 0; v < b->num_verts; v++) CHECK(c.vert_out[v] == b->vert_out[v]);
        CHECK_EQ(c.num_edges, b->num_edges);
        /* tags: the builder's bits exactly; the caller's vertex bits kept on old vertices, none
         * on new ones; edges: BOUNDARY exactly where the builder puts it, CREASE only on
         * halves of a parent crease (same on both halves when the parent's were) */
        for (v = 0; v < b->num_verts; v++) {
            CHECK_EQ(b->vert_tag[v] & vb, c.vert_tag[v] & vb);
            CHECK_EQ(b->vert_tag[v] & keep, v < a->num_verts ? (a->vert_tag[v] & keep) : 0u);
            CHECK_EQ(b->vert_tag[v] & (uint8_t)~(vb | keep), 0u);
        }
        for (j = 0; j < b->num_corners; j++) {
            CHECK_EQ(b->edge_tag[j] & SUBD_ETAG_BOUNDARY, c.edge_tag[j] & SUBD_ETAG_BOUNDARY);
            CHECK_EQ(b->edge_tag[j] & (uint8_t)~(SUBD_ETAG_BOUNDARY | SUBD_ETAG_CREASE), 0u);
            if (b->twin[j] != SUBD_NONE) {
                uint32_t pa = b->corner_vert[j], pb = subd_he_dest(b, j), k2, crease = 0;
                /* a crease half lies on a parent crease edge: its ends are a parent crease's
                 * ends or the new vertex on it, so at least one end is an old vertex of a
                 * parent crease edge */
                for (k2 = 0; k2 < a->num_corners && (b->edge_tag[j] & SUBD_ETAG_CREASE); k2++)
                    if ((a->edge_tag[k2] & SUBD_ETAG_CREASE) &&
                        (a->corner_vert[k2] == pa || a->corner_vert[k2] == pb || subd_he_dest(a, k2) == pa ||
                         subd_he_dest(a, k2) == pb))
                        crease = 1;
                if (b->edge_tag[j] & SUBD_ETAG_CREASE) CHECK(crease);
            }
        }
        CHECK_EQ(c.num_boundary_edges, b->num_boundary_edges);
        CHECK_EQ(c.num_boundary_loops, b->num_boundary_loops);
        CHECK_EQ(c.num_isolated, b->num_isolated);
    }
}

/* Runs `steps` single steps, checking each; returns the centre (vertex 0) valence after the
 * last one, *mesh receives the final mesh (in arena a). */
static uint32_t stepwise(subd_arena *a, const subd_mesh *in, uint32_t steps, uint32_t flags, subd_mesh *mesh)
{
    subd_quasi48_opts o = opts(1, flags);
    subd_mesh cur = *in, nxt;
    uint32_t s;
    for (s = 0; s < steps; s++) {
        if (!run(a, &cur, &o, &nxt)) return 0;
        check_step(&cur, &nxt, (flags & SUBD_QUASI48_NO_SMOOTH) != 0);
        cur = nxt;
    }
    *mesh = cur;
    return subd_vertex_valence(&cur, 0);
}

/* Figure 5: regular n-gons, n = 3..6, centre valence 2n (6 for the hexagon) after 1 and 4
 * steps, with and without smoothing; one call of 4 steps = four calls of 1 step. */
static void q48_regular_polygons(void)
{
    uint32_t n, pass, hashes = 2166136261u;
    for (pass = 0; pass < 2; pass++) {
        uint32_t flags = pass ? 0u : SUBD_QUASI48_NO_SMOOTH;
        for (n = 3; n <= 6; n++) {
            subd_arena a;
            subd_face_list fl;
            subd_mesh in, m1, m4, once;
            subd_quasi48_opts o = opts(4, flags);
            uint32_t want = n == 6 ? 6u : 2u * n;
            subd_arena_init(&a, g_big, BIG_BYTES);
            fan_list(&fl, n, 0, 0);
            if (!h_build(&a, &fl, &in)) return;
            CHECK_EQ(stepwise(&a, &in, 1, flags, &m1), want);
            CHECK_EQ(stepwise(&a, &in, 4, flags, &m4), want);
            if (run(&a, &in, &o, &once)) {
                CHECK_EQ(h_mesh_hash(&once), h_mesh_hash(&m4));
                hashes = h_fnv(hashes, &m4.num_faces, 4);
                h_hash(pass ? "q48_fan_smooth" : "q48_fan_refine", h_mesh_hash(&once));
            }
            if (n == 6) CHECK_EQ(m1.num_verts, 10); /* three alternate spokes split */
        }
    }
}

/* Figure 8: 12-gon keeps centre valence 12 and 60-degree symmetry at every step; 9-gon:
 * centre valence 10. */
static subd_real cx_[MAXF], cy_[MAXF];
static uint8_t taken[MAXF];
static int rotation_invariant(const subd_mesh *m, int32_t num, int32_t den)
{
    uint32_t f, g, ok = 1, ovf = 0;
    subd_real c = subd_cos_turns(num, den), s = subd_sin_turns(num, den), third = R(1, 3);
#if SUBD_FIXED
    subd_real tol = 64;
#else
    subd_real tol = 1e-4f;
#endif
    for (f = 0; f < m->num_faces && f < MAXF; f++) {
        const uint32_t *p = m->corner_vert + 3u * f;
        subd_real x = 0, y = 0;
        uint32_t j;
        for (j = 0; j < 3u; j++) {
            x = subd_add(x, subd_mul(m->pos[3u * p[j]], third, &ovf), &ovf);
            y = subd_add(y, subd_mul(m->pos[3u * p[j] + 1u], third, &ovf), &ovf);
        }
        cx_[f] = x;
        cy_[f] = y;
        taken[f] = 0;
    }
    for (f = 0; f < m->num_faces && f < MAXF && ok; f++) {
        subd_real rx = subd_sub(subd_mul(cx_[f], c, &ovf), subd_mul(cy_[f], s, &ovf), &ovf);
        subd_real ry = subd_add(subd_mul(cx_[f], s, &ovf), subd_mul(cy_[f], c, &ovf), &ovf);
        for (g = 0; g < m->num_faces; g++) {
            subd_real dx = subd_sub(rx, cx_[g], &ovf), dy = subd_sub(ry, cy_[g], &ovf);
            if (!taken[g] && dx <= tol && -dx <= tol && dy <= tol && -dy <= tol) break;
        }
        if (g == m->num_faces) ok = 0;
        else taken[g] = 1;
    }
    return ok && ovf == 0;
}

static void q48_polygons_9_12(void)
{
    uint32_t pass;
    for (pass = 0; pass < 2; pass++) {
        uint32_t flags = pass ? 0u : SUBD_QUASI48_NO_SMOOTH, s;
        subd_arena a;
        subd_face_list fl;
        subd_mesh in, m, cur;
        subd_arena_init(&a, g_big, BIG_BYTES);
        fan_list(&fl, 12, 0, 0);
        if (!h_build(&a, &fl, &in)) return;
        cur = in;
        for (s = 1; s <= 4; s++) {
            CHECK_EQ(stepwise(&a, &cur, 1, flags, &m), 12);
            if (!CHECK(rotation_invariant(&m, 1, 6))) {
                h_str("    12-gon not 60-degree symmetric after step ");
                h_u32(s);
                h_nl();
            }
            cur = m;
        }
        h_hash(pass ? "q48_12gon_smooth" : "q48_12gon_refine", h_mesh_hash(&m));
        fan_list(&fl, 9, 0, 0);
        if (!h_build(&a, &fl, &in)) return;
        CHECK_EQ(stepwise(&a, &in, 1, flags, &m), 10);
        CHECK(!rotation_invariant(&m, 1, 9)); /* odd n: the decomposition is not radial */
        stepwise(&a, &in, 4, flags, &m);
#if H_HOST
        printf("    9-gon after 4 steps (%s): centre valence %u\n", pass ? "smoothed" : "refine only",
               (unsigned)subd_vertex_valence(&m, 0));
#endif
    }
}

/* Figure 6: hexagon warped so that the horizontal interior edges have lengths 4/3 (right)
 * and 2/3 (left): the long one is the first split, the short one is not split. */
static void q48_warped_hexagon(void)
{
    subd_arena a;
    subd_face_list fl;
    subd_mesh in, m;
    subd_quasi48_opts o = opts(1, SUBD_QUASI48_NO_SMOOTH);
    uint32_t f, ovf = 0;
    subd_arena_init(&a, g_big, BIG_BYTES);
    fan_list(&fl, 6, 0, R(-1, 3));
    if (!h_build(&a, &fl, &in) || !run(&a, &in, &o, &m)) return;
    check_step(&in, &m, 1);
    /* vertex 7 = first split = midpoint of centre (0) and rim vertex 1 (1, 0) */
    {
        subd_real dd = subd_sub(m.pos[3 * 7], R(1, 3), &ovf);
        CHECK(dd <= 2 * SUBD_REAL_ONE / 65536 && -dd <= 2 * SUBD_REAL_ONE / 65536);
    }
    CHECK(m.pos[3 * 7 + 1] == 0);
    /* the edge 0-4 (to (-1, 0)) is still an edge */
    for (f = 0; f < m.num_corners; f++)
        if (m.corner_vert[f] == 0 && subd_he_dest(&m, f) == 4) break;
    CHECK(f < m.num_corners);
    h_hash("q48_warped", h_mesh_hash(&m));
}

/* Figure 7: radial perturbation 1 + a u_i of the hexagon's rim, u_i uniform in [-1, 1],
 * a = 0.1 and 0.3: same topology for both amplitudes; centre valence distribution over
 * 200 fixed-seed patterns after 1 and 4 steps. */
static int same_faces(const subd_mesh *a, const subd_mesh *b)
{
    uint32_t c;
    if (a->num_faces != b->num_faces || a->num_verts != b->num_verts) return 0;
    for (c = 0; c < a->num_corners; c++)
        if (a->corner_vert[c] != b->corner_vert[c]) return 0;
    return 1;
}

static void valence_hist(const subd_mesh *m, uint32_t *hist);

static void q48_perturbed_hexagon(void)
{
    static uint32_t hist[2][2][16], h4[2][16];
    uint32_t t, seed = 12345u, same1 = 0, same4 = 0, i, j, amp, ovf = 0;
    subd_real rad[2][6];
    for (i = 0; i < 16; i++) hist[0][0][i] = hist[0][1][i] = hist[1][0][i] = hist[1][1][i] = 0;
    for (t = 0; t < 200; t++) {
        subd_mesh m1[2], m4[2];
        for (i = 0; i < 6; i++) {
            int32_t u = (int32_t)(h_rand(&seed) % 2001u) - 1000; /* u_i = u / 1000 */
            rad[0][i] = subd_add(SUBD_REAL_ONE, R(u, 10000), &ovf);
            rad[1][i] = subd_add(SUBD_REAL_ONE, R(3 * u, 10000), &ovf);
        }
        for (amp = 0; amp < 2; amp++) {
            subd_arena a;
            subd_face_list fl;
            subd_mesh in;
            subd_quasi48_opts o = opts(4, SUBD_QUASI48_NO_SMOOTH), o1 = opts(1, SUBD_QUASI48_NO_SMOOTH);
            uint32_t v1, v4;
            subd_arena_init(&a, g_big + amp * (BIG_BYTES / 2u), BIG_BYTES / 2u);
            fan_list(&fl, 6, rad[amp], 0);
            if (!h_build(&a, &fl, &in) || !run(&a, &in, &o1, &m1[amp]) || !run(&a, &in, &o, &m4[amp])) return;
            v1 = subd_vertex_valence(&m1[amp], 0);
            v4 = subd_vertex_valence(&m4[amp], 0);
            hist[amp][0][v1 < 16u ? v1 : 15u]++;
            hist[amp][1][v4 < 16u ? v4 : 15u]++;
            valence_hist(&m4[amp], h4[amp]);
        }
        same1 += (uint32_t)same_faces(&m1[0], &m1[1]);
        for (i = 0; i < 16 && h4[0][i] == h4[1][i]; i++) {}
        same4 += (i == 16);
    }
    for (amp = 0; amp < 2; amp++) {
        for (j = 0; j < 2; j++) {
            uint32_t best = 0;
            for (i = 0; i < 16; i++) if (hist[amp][j][i] > hist[amp][j][best]) best = i;
            CHECK_EQ(best, 8);
            h_str(amp ? "    a = 0.3" : "    a = 0.1");
            h_str(j ? ", after 4 steps" : ", after 1 step");
            h_str(": centre valence");
            for (i = 0; i < 16; i++) if (hist[amp][j][i]) { h_str(" "); h_u32(i); h_str("x"); h_u32(hist[amp][j][i]); }
            h_nl();
        }
    }
    h_str("    same step-1 connectivity for a = 0.1 and 0.3: ");
    h_u32(same1);
    h_str("/200; same valence histogram after 4 steps: ");
    h_u32(same4);
    h_str("/200");
    h_nl();
    CHECK(2u * same1 > 200u);
    CHECK(2u * same4 > 200u);
    CHECK_EQ(ovf, 0);
}

/* Figure 9: torus 12 x 6 is 4-8 regular after 1, 2 and 4 steps (with smoothing). Coarser
 * tori: histograms reported. */
static void valence_hist(const subd_mesh *m, uint32_t *hist)
{
    uint32_t v, i;
    for (i = 0; i < 16; i++) hist[i] = 0;
    for (v = 0; v < m->num_verts; v++) {
        uint32_t k = subd_vertex_valence(m, v);
        hist[k < 16u ? k : 15u]++;
    }
}

static void q48_torus(void)
{
    static const uint32_t dims[3][2] = {{12, 6}, {8, 4}, {6, 3}};
    uint32_t t, s, hist[16], i;
    for (t = 0; t < 3; t++) {
        subd_arena a;
        subd_face_list fl;
        subd_mesh in, cur, m;
        subd_arena_init(&a, g_big, BIG_BYTES);
        fl = h_torus(dims[t][0], dims[t][1], g_pos, g_idx);
        if (!h_build(&a, &fl, &in)) return;
        cur = in;
        for (s = 1; s <= 4; s++) {
            stepwise(&a, &cur, 1, 0, &m);
            cur = m;
            valence_hist(&m, hist);
            if (t == 0) CHECK_EQ(hist[4] + hist[8], m.num_verts);
            if (t == 0 && s == 4) {
                /* one call of 4 steps gives the same mesh; report plan and peak */
                subd_arena b;
                subd_mesh once;
                subd_quasi48_opts o4 = opts(4, 0);
                uint32_t plan = 0;
                subd_arena_init(&b, g_big + BIG_BYTES / 2u, BIG_BYTES / 2u);
                CHECK_EQ(subd_quasi48_plan(&in, &o4, &plan, 0), SUBD_OK);
                if (run(&b, &in, &o4, &once)) {
                    CHECK_EQ(h_mesh_hash(&once), h_mesh_hash(&m));
                    CHECK(b.peak <= plan);
                    h_str("    torus 12x6, 4 steps in one call: plan ");
                    h_u32(plan);
                    h_str(" bytes, peak ");
                    h_u32(b.peak);
                    h_str(", output keeps ");
                    h_u32(b.used);
                    h_nl();
                }
            }
            if (t == 0 && s == 4) h_hash("q48_torus12x6_4", h_mesh_hash(&m));
            h_str("    torus ");
            h_u32(dims[t][0]);
            h_str("x");
            h_u32(dims[t][1]);
            h_str(" step ");
            h_u32(s);
            h_str(" valences:");
            for (i = 0; i < 16; i++) if (hist[i]) { h_str(" "); h_u32(i); h_str("x"); h_u32(hist[i]); }
            h_nl();
        }
    }
}

/* Smoothing: planar stays planar; affine (similarity) invariance; fixed/tagged vertices,
 * creases and fixed boundaries don't move; smooth-boundary rule. */
static void q48_smoothing(void)
{
    subd_arena a;
    subd_face_list fl;
    subd_mesh in, m, in2, m2;
    subd_quasi48_opts o = opts(3, 0);
    uint32_t v, k, ovf = 0, c;
    static subd_real pos2[3 * 64];
#if SUBD_FIXED
    subd_real tol = 8;
#else
    subd_real tol = 1e-5f;
#endif
    subd_arena_init(&a, g_big, BIG_BYTES);
    grid_list(&fl, 4);
    if (!h_build(&a, &fl, &in) || !run(&a, &in, &o, &m)) return;
    for (v = 0; v < m.num_verts; v++) CHECK(m.pos[3 * v + 2] == 0);
    /* boundary fixed: old boundary vertices exactly in place, new ones on the boundary square */
    for (v = 0; v < m.num_verts; v++) {
        if (!(m.vert_tag[v] & SUBD_VTAG_BOUNDARY)) continue;
        if (v < in.num_verts) {
            CHECK(m.pos[3 * v] == in.pos[3 * v] && m.pos[3 * v + 1] == in.pos[3 * v + 1]);
        } else {
            subd_real x = m.pos[3 * v], y = m.pos[3 * v + 1], four = subd_from_int(4, &ovf);
            CHECK(x == 0 || y == 0 || x == four || y == four);
        }
    }
    /* similarity: axes permuted (x, y, z) -> (y, z, x), scaled by 2, translated */
    for (v = 0; v < in.num_verts; v++) {
        subd_real t[3];
        t[0] = R(1, 2); t[1] = R(-1, 4); t[2] = SUBD_REAL_ONE;
        for (k = 0; k < 3u; k++)
            pos2[3 * v + (k + 1) % 3] = subd_add(subd_add(in.pos[3 * v + k], in.pos[3 * v + k], &ovf), t[(k + 1) % 3], &ovf);
    }
    fl.pos = pos2;
    if (!h_build(&a, &fl, &in2) || !run(&a, &in2, &o, &m2)) return;
    CHECK_EQ(m2.num_faces, m.num_faces);
    for (c = 0; c < m.num_corners && c < m2.num_corners; c++) CHECK(m.corner_vert[c] == m2.corner_vert[c]);
    for (v = 0; v < m.num_verts && v < m2.num_verts; v++) {
        subd_real t[3];
        t[0] = R(1, 2); t[1] = R(-1, 4); t[2] = SUBD_REAL_ONE;
        for (k = 0; k < 3u; k++) {
            subd_real want = subd_add(subd_add(m.pos[3 * v + k], m.pos[3 * v + k], &ovf), t[(k + 1) % 3], &ovf);
            subd_real got = m2.pos[3 * v + (k + 1) % 3], dd = subd_sub(want, got, &ovf);
            CHECK(dd <= tol && -dd <= tol);
        }
    }
    CHECK_EQ(ovf, 0);
    h_hash("q48_grid_smooth", h_mesh_hash(&m));
}

static void q48_tags_and_boundary(void)
{
    subd_arena a;
    subd_face_list fl;
    subd_mesh in, m;
    subd_quasi48_opts o = opts(2, 0);
    uint32_t v, h, moved = 0, ovf = 0;
    subd_real p0[3];
    /* torus with a fixed vertex, a corner and a crease loop (a meridian j = 0 ring) */
    subd_arena_init(&a, g_big, BIG_BYTES);
    fl = h_torus(8, 4, g_pos, g_idx);
    if (!h_build(&a, &fl, &in)) return;
    in.vert_tag[5] |= SUBD_VTAG_FIXED;
    in.vert_tag[9] |= SUBD_VTAG_CORNER;
    for (h = 0; h < in.num_corners; h++) {
        uint32_t x = subd_he_origin(&in, h), y = subd_he_dest(&in, h);
        if (x % 4u == 0 && y % 4u == 0) subd_edge_tag_set(&in, h, SUBD_ETAG_CREASE); /* ring j = 0 */
    }
    for (v = 0; v < 3; v++) p0[v] = in.pos[3 * 5 + v];
    if (!run(&a, &in, &o, &m)) return;
    CHECK(m.vert_tag[5] & SUBD_VTAG_FIXED);
    CHECK(m.vert_tag[9] & SUBD_VTAG_CORNER);
    for (v = 0; v < 3; v++) {
        CHECK(m.pos[3 * 5 + v] == p0[v]);
        CHECK(m.pos[3 * 9 + v] == in.pos[3 * 9 + v]);
    }
    for (v = 0; v < in.num_verts; v++) {
        if (v % 4u == 0) CHECK(m.pos[3 * v] == in.pos[3 * v] && m.pos[3 * v + 1] == in.pos[3 * v + 1] &&
                               m.pos[3 * v + 2] == in.pos[3 * v + 2]);
        else if (m.pos[3 * v] != in.pos[3 * v]) moved++;
    }
    CHECK(moved > 0);
    /* every crease edge of the output lies in the plane z = 0.4 (j = 0 ring), both halves
     * of a split crease edge are creases, and crease edges still form closed loops */
    {
        uint32_t ncrease = 0;
        for (h = 0; h < m.num_corners; h++) {
            if (!(m.edge_tag[h] & SUBD_ETAG_CREASE)) continue;
            ncrease++;
            CHECK(m.pos[3 * subd_he_origin(&m, h) + 2] == 0);
            CHECK(m.edge_tag[m.twin[h]] & SUBD_ETAG_CREASE);
        }
        CHECK(ncrease >= 2u * 8u);
    }
    h_hash("q48_torus_tags", h_mesh_hash(&m));
    { /* the same two steps one at a time, each checked against the builder (tags included) */
        subd_mesh cur = in, nxt;
        subd_quasi48_opts o1 = opts(1, 0);
        uint32_t s;
        for (s = 0; s < 2u; s++) {
            if (!run(&a, &cur, &o1, &nxt)) return;
            check_step(&cur, &nxt, 0);
            cur = nxt;
        }
        CHECK_EQ(h_mesh_hash(&cur), h_mesh_hash(&m));
    }

    /* boundary smoothing: an old boundary vertex with new boundary neighbours moves to
     * 1/2 own + 1/2 their average; new boundary vertices stay on the boundary edge */
    {
        subd_mesh g0, g, g1;
        subd_quasi48_opts o1 = opts(1, 0);
        uint32_t checked = 0;
#if SUBD_FIXED
        subd_real tol = 2;
#else
        subd_real tol = 1e-6f;
#endif
        o1.boundary = SUBD_QUASI48_BOUNDARY_SMOOTH;
        grid_list(&fl, 3);
        /* the first step splits the diagonals only; the second splits boundary edges */
        if (!h_build(&a, &fl, &g0) || !run(&a, &g0, &o1, &g) || !run(&a, &g, &o1, &g1)) return;
        check_step(&g, &g1, 0);
        for (v = 0; v < g.num_verts; v++) {
            uint32_t ring[16], n, j, k, cnt = 0;
            subd_real sum[3] = {0, 0, 0};
            if (!(g1.vert_tag[v] & SUBD_VTAG_BOUNDARY)) continue;
            n = subd_vertex_ring(&g1, v, ring, 16);
            for (j = 0; j < 2; j++) {
                uint32_t u = j ? ring[n - 1] : ring[0];
                if (u < g.num_verts) continue;
                cnt++;
                for (k = 0; k < 3; k++) sum[k] = subd_add(sum[k], g1.pos[3 * u + k], &ovf);
            }
            for (k = 0; k < 3; k++) {
                subd_real want = g.pos[3 * v + k], dd;
                if (cnt) want = subd_add(subd_mul(want, R(1, 2), &ovf),
                                         subd_div(sum[k], subd_from_int((int32_t)(2 * cnt), &ovf), &ovf), &ovf);
                dd = subd_sub(want, g1.pos[3 * v + k], &ovf);
                CHECK(dd <= tol && -dd <= tol);
            }
            checked += cnt != 0;
        }
        CHECK(checked > 0);
        CHECK_EQ(ovf, 0);
        h_hash("q48_grid_bsmooth", h_mesh_hash(&g1));
    }
}

/* ------------------------------------------------------------------------------------ */
/* Normal boundary mode (section 4.3: boundary vertices move along the surface normal). */

/* Figure 11(a): a triangulated box with two open sides, a square tube along x: nseg + 1
 * rings of 8 vertices (corners and edge midpoints of the square |y|, |z| <= 1) at x = 0..4
 * (step 4 / nseg), quads between rings cut by alternating diagonals. Two boundary loops. */
static void tube_list(subd_face_list *fl, uint32_t nseg)
{
    static const int32_t ry[8] = {1, 1, 1, 0, -1, -1, -1, 0}, rz[8] = {-1, 0, 1, 1, 1, 0, -1, -1};
    uint32_t i, k, n = 0, ovf = 0;
    for (i = 0; i <= nseg; i++)
        for (k = 0; k < 8u; k++) {
            uint32_t v = 8u * i + k;
            g_pos[3 * v] = R((int32_t)(4u * i), (int32_t)nseg);
            g_pos[3 * v + 1] = subd_from_int(ry[k], &ovf);
            g_pos[3 * v + 2] = subd_from_int(rz[k], &ovf);
        }
    for (i = 0; i < nseg; i++)
        for (k = 0; k < 8u; k++) {
            uint32_t a = 8u * i + k, b = 8u * (i + 1u) + k, c = 8u * (i + 1u) + (k + 1u) % 8u,
                     d = 8u * i + (k + 1u) % 8u;
            if ((i + k) & 1u) {
                g_idx[n++] = a; g_idx[n++] = b; g_idx[n++] = c;
                g_idx[n++] = a; g_idx[n++] = c; g_idx[n++] = d;
            } else {
                g_idx[n++] = a; g_idx[n++] = b; g_idx[n++] = d;
                g_idx[n++] = b; g_idx[n++] = c; g_idx[n++] = d;
            }
        }
    CHECK_EQ(ovf, 0);
    fl->num_verts = 8u * (nseg + 1u);
    fl->pos = g_pos;
    fl->num_faces = 16u * nseg;
    fl->face_size = 0;
    fl->index = g_idx;
    fl->num_lines = 0;
    fl->line_size = fl->line_index = 0;
}

static subd_quasi48_opts opts_normal(uint32_t steps)
{
    subd_quasi48_opts o = opts(steps, 0);
    o.boundary = SUBD_QUASI48_BOUNDARY_NORMAL;
    return o;
}

/* Planar open mesh in z = 0: the normal is (0, 0, n_z) exactly and the displacement has
 * z = 0, so its normal component is exactly 0 in both arithmetics: the output equals the
 * FIXED mode's bit for bit (boundary vertices exactly in place, every z exactly 0). */
static void q48_normal_planar(void)
{
    subd_arena a;
    subd_face_list fl;
    subd_mesh in, mf, mn;
    subd_quasi48_opts of = opts(3, 0), on = opts_normal(3);
    uint32_t v, c;
    subd_arena_init(&a, g_big, BIG_BYTES);
    grid_list(&fl, 4);
    if (!h_build(&a, &fl, &in) || !run(&a, &in, &of, &mf) || !run(&a, &in, &on, &mn)) return;
    if (!CHECK_EQ(mn.num_verts, mf.num_verts) || !CHECK_EQ(mn.num_faces, mf.num_faces)) return;
    for (c = 0; c < mn.num_corners; c++) CHECK(mn.corner_vert[c] == mf.corner_vert[c]);
    for (v = 0; v < 3u * mn.num_verts; v++) CHECK(h_same(mn.pos[v], mf.pos[v]));
    for (v = 0; v < mn.num_verts; v++) {
        CHECK(mn.pos[3 * v + 2] == 0);
        if (v < in.num_verts && (in.vert_tag[v] & SUBD_VTAG_BOUNDARY))
            CHECK(mn.pos[3 * v] == in.pos[3 * v] && mn.pos[3 * v + 1] == in.pos[3 * v + 1]);
    }
}

/* Area-weighted normal of v in m, brute force over every face, in double. */
static void normal_dbl(const subd_mesh *m, uint32_t v, double *n)
{
    uint32_t f, j, k;
    n[0] = n[1] = n[2] = 0.0;
    for (f = 0; f < m->num_faces; f++) {
        const uint32_t *q = m->corner_vert + 3u * f;
        double e[2][3];
        for (j = 0; j < 3u && q[j] != v; j++) {}
        if (j == 3u) continue;
        for (k = 0; k < 3u; k++) {
            double p = h_dbl(m->pos[3u * v + k]);
            e[0][k] = h_dbl(m->pos[3u * q[(j + 1u) % 3u] + k]) - p;
            e[1][k] = h_dbl(m->pos[3u * q[(j + 2u) % 3u] + k]) - p;
        }
        n[0] += e[0][1] * e[1][2] - e[0][2] * e[1][1];
        n[1] += e[0][2] * e[1][0] - e[0][0] * e[1][2];
        n[2] += e[0][0] * e[1][1] - e[0][1] * e[1][0];
    }
}

/* One normal-mode step a -> b of the tube, checked in double: every old boundary vertex
 * moved by exactly the normal component of the interior rule's displacement (target 1/2 p
 * + 1/2 the mean of its new neighbours in b) along its area-weighted normal in a; so its
 * displacement x unit normal is ~0. New boundary vertices are the midpoints of their edge.
 * *worst_cross: the largest |displacement x unit normal|^2. Returns how many boundary
 * vertices moved by more than 1e-3. Tolerances: Q16.16 4 LSB
 * (the normal's direction is kept to 2^-19, the projection rounds once, the target once);
 * float32 2e-6 (coordinates below 4, a few roundings). */
static uint32_t check_normal_step(const subd_mesh *a, const subd_mesh *b, double *worst_cross)
{
    const double tol = SUBD_FIXED ? 4.0 / 65536.0 : 2e-6;
    uint32_t v, k, moved = 0;
    for (v = 0; v < b->num_verts; v++) {
        uint32_t ring[32], n, j, cnt = 0;
        double t[3] = {0, 0, 0}, p[3], nn[3], dd[3], dn = 0, n2 = 0, cr[3], c2;
        if (!(b->vert_tag[v] & SUBD_VTAG_BOUNDARY)) continue;
        n = subd_vertex_ring(b, v, ring, 32);
        if (!CHECK(n >= 2u && n <= 32u)) return moved;
        if (v >= a->num_verts) { /* new: midpoint of its boundary edge, in the input */
            uint32_t e0 = ring[0], e1 = ring[n - 1u];
            for (k = 0; k < 3u; k++) {
                double mid = 0.5 * (h_dbl(a->pos[3u * e0 + k]) + h_dbl(a->pos[3u * e1 + k]));
                CHECK(fabs(h_dbl(b->pos[3u * v + k]) - mid) <= tol);
            }
            continue;
        }
        for (k = 0; k < 3u; k++) p[k] = h_dbl(a->pos[3u * v + k]);
        for (j = 0; j < n; j++) {
            if (ring[j] < a->num_verts) continue;
            cnt++;
            for (k = 0; k < 3u; k++) t[k] += h_dbl(b->pos[3u * ring[j] + k]);
        }
        if (cnt == 0) {
            for (k = 0; k < 3u; k++) CHECK(b->pos[3u * v + k] == a->pos[3u * v + k]);
            continue;
        }
        normal_dbl(a, v, nn);
        for (k = 0; k < 3u; k++) {
            t[k] = 0.5 * p[k] + 0.5 * t[k] / (double)cnt;
            dn += (t[k] - p[k]) * nn[k];
            n2 += nn[k] * nn[k];
        }
        if (!CHECK(n2 > 0.0)) continue;
        for (k = 0; k < 3u; k++) {
            double want = p[k] + dn / n2 * nn[k];
            dd[k] = h_dbl(b->pos[3u * v + k]) - p[k];
            CHECK(fabs(h_dbl(b->pos[3u * v + k]) - want) <= tol);
        }
        /* |d x n|^2 / |n|^2 = |d x unit normal|^2, squared: no sqrt (libm) on the device */
        cr[0] = dd[1] * nn[2] - dd[2] * nn[1];
        cr[1] = dd[2] * nn[0] - dd[0] * nn[2];
        cr[2] = dd[0] * nn[1] - dd[1] * nn[0];
        c2 = (cr[0] * cr[0] + cr[1] * cr[1] + cr[2] * cr[2]) / n2;
        CHECK(c2 <= tol * tol);
        if (c2 > *worst_cross) *worst_cross = c2;
        if (dd[0] * dd[0] + dd[1] * dd[1] + dd[2] * dd[2] > 1e-6) moved++;
    }
    return moved;
}

/* Rotation by 90 degrees about z, (x, y, z) -> (-y, x, z), or (fixed only) about x,
 * (x, y, z) -> (x, -z, y): exact in both arithmetics. */
static void rot90(const subd_real *p, subd_real *q, int about_x)
{
    if (about_x) {
        q[0] = p[0]; q[1] = -p[2]; q[2] = p[1];
    } else {
        q[0] = -p[1]; q[1] = p[0]; q[2] = p[2];
    }
}

static void q48_normal_box(void)
{
    subd_arena a;
    subd_face_list fl;
    subd_mesh in, cur, nxt, m, m2, in2;
    subd_quasi48_opts o1 = opts_normal(1), o3 = opts_normal(3);
    uint32_t s, moved = 0, v, c, axis;
    double worst = 0.0;
    static subd_real pos2[3 * 64];
    subd_arena_init(&a, g_big, BIG_BYTES);
    tube_list(&fl, 4);
    if (!h_build(&a, &fl, &in)) return;
    CHECK_EQ(in.num_boundary_loops, 2);
    cur = in;
    for (s = 0; s < 3u; s++) {
        if (!run(&a, &cur, &o1, &nxt)) return;
        check_step(&cur, &nxt, 0);
        moved += check_normal_step(&cur, &nxt, &worst);
        cur = nxt;
    }
    CHECK(moved >= 16u); /* at least the 16 input boundary vertices once */
#if H_HOST
    printf("    tube, normal boundary, 3 steps: boundary vertices moved %u, worst |displacement x unit normal| %.3g\n",
           (unsigned)moved, sqrt(worst));
#endif
    /* the same three steps in one call give the same mesh */
    if (!run(&a, &in, &o3, &m)) return;
    CHECK_EQ(m.num_verts, cur.num_verts);
    for (v = 0; v < 3u * m.num_verts && v < 3u * cur.num_verts; v++) CHECK(m.pos[v] == cur.pos[v]);
    h_hash("q48_tube_normal", h_mesh_hash(&m));
    /* rotation invariance, bit for bit */
    for (axis = 0; axis < (SUBD_FIXED ? 2u : 1u); axis++) {
        for (v = 0; v < in.num_verts; v++) rot90(in.pos + 3u * v, pos2 + 3u * v, (int)axis);
        fl.pos = pos2;
        if (!h_build(&a, &fl, &in2) || !run(&a, &in2, &o3, &m2)) return;
        if (!CHECK_EQ(m2.num_verts, m.num_verts)) return;
        for (c = 0; c < m.num_corners; c++) CHECK(m.corner_vert[c] == m2.corner_vert[c]);
        for (v = 0; v < m.num_verts; v++) {
            subd_real q[3];
            rot90(m.pos + 3u * v, q, (int)axis);
            /* ==: the same bits, but for the sign of a zero (float32 x - x is +0 whichever
             * sign x has, so -0 need not map to -0) */
            CHECK(q[0] == m2.pos[3u * v] && q[1] == m2.pos[3u * v + 1u] && q[2] == m2.pos[3u * v + 2u]);
        }
        fl.pos = g_pos;
    }
}

/* Normal mode, SUBD_ERR_RANGE: two faces folded along the edge (0, 2) whose vertex 0 is
 * the largest in y; its normal points between the faces, and the normal component of its
 * displacement (mostly along x) moves it up in y, beyond every input vertex (found by a
 * search over small integer folds). Q16.16: scaled by 1000 with y + 32000, vertex 0 would
 * leave the range (y about 33230); float32: scaled by 2^64, the normal's cross products
 * overflow. The fixed mode (convex combinations only) succeeds on the same mesh; the failed
 * call leaves the arena mark, the input and *out unchanged. */
static void q48_normal_range(void)
{
    static const int32_t base[12] = {0, 0, 0, 9, 0, -5, 8, -5, 5, 9, -3, -9};
    static const uint32_t idx[6] = {0, 1, 2, 0, 2, 3};
    subd_real pos[12], keep[12];
    subd_arena a;
    subd_face_list fl;
    subd_mesh in, out, out0;
    subd_diag d;
    subd_quasi48_opts of = opts(1, 0), on = opts_normal(1);
    uint32_t i, mark, ovf = 0;
    for (i = 0; i < 12u; i++) {
#if SUBD_FIXED
        pos[i] = subd_from_int(base[i] * 1000 + (i % 3u == 1u ? 32000 : 0), &ovf);
#else
        pos[i] = (float)base[i] * 18446744073709551616.0f; /* 2^64 */
#endif
        keep[i] = pos[i];
    }
    CHECK_EQ(ovf, 0);
    fl.num_verts = 4; fl.pos = pos; fl.num_faces = 2; fl.face_size = 0; fl.index = idx;
    fl.num_lines = 0; fl.line_size = fl.line_index = 0;
    subd_arena_init(&a, g_big, BIG_BYTES);
    if (!h_build(&a, &fl, &in) || !run(&a, &in, &of, &out0)) return;
    mark = subd_arena_mark(&a);
    out = out0;
    CHECK_FAIL(subd_quasi48(&a, &in, &on, &out, &d), &d, SUBD_ERR_RANGE);
    CHECK_EQ(subd_arena_mark(&a), mark);
    CHECK(out.pos == out0.pos && out.num_verts == out0.num_verts && out.num_faces == out0.num_faces);
    for (i = 0; i < 12u; i++) CHECK(h_same(in.pos[i], keep[i]));
}

/* hexfan.obj from the corpus (decimal positions): same result as the built fan. */
static void q48_hexfan_file(void)
{
    const corpus_file *cf = corpus_find("test/data/hexfan.obj");
    subd_arena a;
    subd_mesh in, m;
    subd_diag d;
    subd_quasi48_opts o = opts(1, SUBD_QUASI48_NO_SMOOTH);
    if (!CHECK(cf != 0)) return;
    subd_arena_init(&a, g_big, BIG_BYTES);
    if (!CHECK_EQ(subd_obj_read(&a, cf->data, cf->len, &in, &d), SUBD_OK) || !run(&a, &in, &o, &m)) return;
    CHECK_EQ(subd_vertex_valence(&m, 0), 6);
    h_hash("q48_hexfan", h_mesh_hash(&m));
}

/* Exact plan: every arena size below it fails cleanly (NOMEM, bytes_needed = plan, arena
 * mark unchanged, input untouched, guard bytes intact); at the plan it succeeds and the
 * peak stays within it; one step of a single triangle reaches the plan exactly. */
static int q48_run(void *ctx, subd_arena *a, subd_diag *d)
{
    h_mesh_call *c = (h_mesh_call *)ctx;
    return subd_quasi48(a, c->in, (const subd_quasi48_opts *)c->opts, &c->out, d);
}

static void plan_case(const subd_mesh *in, const subd_quasi48_opts *o, int exact)
{
    uint32_t plan;
    h_mesh_call c;
    h_sweep s;
    if (!CHECK_EQ(subd_quasi48_plan(in, o, &plan, 0), SUBD_OK)) return;
    c.in = in;
    c.opts = o;
    s = h_mesh_sweep(q48_run, &c, h_arena_buf, H_ARENA_BYTES, plan);
    s.peak_le = !exact;
    (void)h_arena_sweep(&s);
}

static void q48_plan_exhaustive(void)
{
    static const uint32_t tri_idx[3] = {0, 1, 2};
    subd_real tpos[9];
    subd_arena a;
    subd_face_list fl;
    subd_mesh in, in2;
    subd_quasi48_opts o = opts(1, 0);
    uint32_t i;
    for (i = 0; i < 9; i++) tpos[i] = 0;
    tpos[3] = SUBD_REAL_ONE;
    tpos[7] = R(1, 2);
    fl.num_verts = 3; fl.pos = tpos; fl.num_faces = 1; fl.face_size = 0; fl.index = tri_idx;
    fl.num_lines = 0; fl.line_size = fl.line_index = 0;
    subd_arena_init(&a, g_big, BIG_BYTES);
    if (!h_build(&a, &fl, &in)) return;
    plan_case(&in, &o, 1);
    o = opts_normal(1);
    plan_case(&in, &o, 1);
    o = opts(1, 0);
    fan_list(&fl, 5, 0, 0);
    if (!h_build(&a, &fl, &in2)) return;
    o = opts(3, 0);
    plan_case(&in2, &o, 0);
    o = opts(2, SUBD_QUASI48_NO_SMOOTH);
    o.boundary = SUBD_QUASI48_BOUNDARY_SMOOTH;
    plan_case(&in2, &o, 0);
    o = opts_normal(3);
    plan_case(&in2, &o, 0);
}

static void q48_errors(void)
{
    static const uint32_t quad_idx[4] = {0, 1, 2, 3}, quad_size[1] = {4};
    subd_real qpos[12];
    subd_arena a;
    subd_face_list fl;
    subd_mesh in, q, out;
    subd_diag d;
    subd_quasi48_opts o = opts(1, 0);
    uint32_t plan, i, ovf = 0;
    subd_arena_init(&a, g_big, BIG_BYTES);
    fan_list(&fl, 4, 0, 0);
    if (!h_build(&a, &fl, &in)) return;
    o.steps = 0;
    CHECK_EQ(subd_quasi48_plan(&in, &o, &plan, 0), SUBD_ERR_PARAM);
    CHECK_FAIL(subd_quasi48(&a, &in, &o, &out, &d), &d, SUBD_ERR_PARAM);
    o.steps = SUBD_QUASI48_MAX_STEPS + 1u;
    CHECK_FAIL(subd_quasi48(&a, &in, &o, &out, &d), &d, SUBD_ERR_PARAM);
    o = opts(1, 0);
    o.len_bits = SUBD_QUASI48_LEN_BITS_EXACT + 1u;
    CHECK_FAIL(subd_quasi48(&a, &in, &o, &out, &d), &d, SUBD_ERR_PARAM);
    o = opts(1, 0);
    o.boundary = (subd_quasi48_boundary)7;
    CHECK_FAIL(subd_quasi48(&a, &in, &o, &out, &d), &d, SUBD_ERR_PARAM);
    o = opts(1, 0);
    CHECK_FAIL(subd_quasi48(0, &in, &o, &out, &d), &d, SUBD_ERR_PARAM);
    CHECK_FAIL(subd_quasi48(&a, 0, &o, &out, &d), &d, SUBD_ERR_PARAM);
    CHECK_FAIL(subd_quasi48(&a, &in, 0, &out, &d), &d, SUBD_ERR_PARAM);
    CHECK_FAIL(subd_quasi48(&a, &in, &o, 0, &d), &d, SUBD_ERR_PARAM);
    CHECK_EQ(subd_quasi48_plan(&in, &o, 0, 0), SUBD_ERR_PARAM);
    for (i = 0; i < 12; i++) qpos[i] = 0;
    qpos[3] = qpos[6] = qpos[7] = qpos[10] = subd_from_int(1, &ovf);
    fl.num_verts = 4; fl.pos = qpos; fl.num_faces = 1; fl.face_size = quad_size; fl.index = quad_idx;
    if (!h_build(&a, &fl, &q)) return;
    CHECK_EQ(subd_quasi48_plan(&q, &o, &plan, 0), SUBD_ERR_NOT_TRIANGLES);
    CHECK_FAIL(subd_quasi48(&a, &q, &o, &out, &d), &d, SUBD_ERR_NOT_TRIANGLES);
    CHECK_EQ(d.face, 0);
    CHECK_EQ(ovf, 0);
    {
        const corpus_file *cf = corpus_find("test/data/cube_quad.obj");
        uint32_t mark;
        if (CHECK(cf != 0) && CHECK_EQ(subd_obj_read(&a, cf->data, cf->len, &q, &d), SUBD_OK)) {
            mark = subd_arena_mark(&a);
            CHECK_EQ(subd_quasi48_plan(&q, &o, &plan, 0), SUBD_ERR_NOT_TRIANGLES);
            CHECK_FAIL(subd_quasi48(&a, &q, &o, &out, &d), &d, SUBD_ERR_NOT_TRIANGLES);
            CHECK_EQ(d.status, SUBD_ERR_NOT_TRIANGLES);
            CHECK_EQ(d.face, 0);
            CHECK_EQ(subd_arena_mark(&a), mark);
        }
    }
}

/* len_bits: with exact comparison the fixed build's rounded hexagon rim makes the spokes
 * at 60 degrees longer than the horizontal ones (report what happens in each arithmetic). */
static void q48_len_bits(void)
{
    subd_arena a;
    subd_face_list fl;
    subd_mesh in, m;
    subd_quasi48_opts o = opts(1, SUBD_QUASI48_NO_SMOOTH);
    subd_arena_init(&a, g_big, BIG_BYTES);
    fan_list(&fl, 6, 0, 0);
    if (!h_build(&a, &fl, &in)) return;
    o.len_bits = SUBD_QUASI48_LEN_BITS_EXACT;
    if (!run(&a, &in, &o, &m)) return;
    h_str("    hexagon, exact length comparison: centre valence ");
    h_u32(subd_vertex_valence(&m, 0));
    h_nl();
    CHECK_EQ(subd_vertex_valence(&m, 0), SUBD_FIXED ? 8 : 6);
}

const test_case suite_quasi48[] = {
    {"q48_regular_polygons", q48_regular_polygons},
    {"q48_polygons_9_12", q48_polygons_9_12},
    {"q48_warped_hexagon", q48_warped_hexagon},
    {"q48_perturbed_hexagon", q48_perturbed_hexagon},
    {"q48_torus", q48_torus},
    {"q48_smoothing", q48_smoothing},
    {"q48_tags_and_boundary", q48_tags_and_boundary},
    {"q48_normal_planar", q48_normal_planar},
    {"q48_normal_box", q48_normal_box},
    {"q48_normal_range", q48_normal_range},
    {"q48_hexfan_file", q48_hexfan_file},
    {"q48_plan_exhaustive", q48_plan_exhaustive},
    {"q48_errors", q48_errors},
    {"q48_len_bits", q48_len_bits},
    {0, 0}
};
