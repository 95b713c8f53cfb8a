/* SPDX-License-Identifier: MIT */
/* Index mesh builder: adjacency checked against brute-force searches written here, exact
 * planning (every too-small arena fails cleanly), each validation error, ring traversal. */
#include "harness.h"
#include "fixtures.h"
#include "subd_loop.h"

#define MAXV 400
#define MAXC 2400

static subd_real g_pos[3 * MAXV];
static uint32_t g_idx[MAXC], g_size[MAXC];

static void set_pos_grid(uint32_t nv)
{
    uint32_t i, ovf = 0;
    for (i = 0; i < nv; i++) {
        g_pos[3 * i] = subd_from_int((int32_t)(i % 17u), &ovf);
        g_pos[3 * i + 1] = subd_from_int((int32_t)(i / 17u), &ovf);
        g_pos[3 * i + 2] = subd_from_int((int32_t)((i * 7u) % 5u), &ovf);
    }
}

static subd_face_list tri_list(uint32_t nv, uint32_t nf, const uint32_t *idx)
{
    subd_face_list fl = {0, 0, 0, 0, 0, 0, 0, 0};
    set_pos_grid(nv);
    fl.num_verts = nv;
    fl.pos = g_pos;
    fl.num_faces = nf;
    fl.index = idx;
    return fl;
}

/* Torus of n x m quads, each split into two triangles (or kept as quads). */
static subd_face_list torus_list(uint32_t n, uint32_t m, int quads)
{
    uint32_t i, j, k = 0, f = 0;
    subd_face_list fl = tri_list(n * m, 0, g_idx);
    for (i = 0; i < n; i++) {
        for (j = 0; j < m; j++) {
            uint32_t a = i * m + j, b = ((i + 1) % n) * m + j;
            uint32_t c = ((i + 1) % n) * m + (j + 1) % m, d = i * m + (j + 1) % m;
            if (quads) {
                g_idx[k++] = a; g_idx[k++] = b; g_idx[k++] = c; g_idx[k++] = d;
                g_size[f++] = 4;
            } else {
                g_idx[k++] = a; g_idx[k++] = b; g_idx[k++] = c;
                g_idx[k++] = a; g_idx[k++] = c; g_idx[k++] = d;
                g_size[f++] = 3; g_size[f++] = 3;
            }
        }
    }
    fl.num_faces = f;
    fl.face_size = g_size;
    return fl;
}

/* Planar (n+1) x (m+1) grid of triangles: an open disk (fx_grid's triangles). */
static subd_face_list grid_list(uint32_t n, uint32_t m)
{
    subd_face_list fl = tri_list((n + 1) * (m + 1), 2 * n * m, g_idx);
    (void)fx_grid(n, m, 0, 0, 0, g_idx);
    return fl;
}

static const uint32_t tet[] = {0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 3, 2};
static const uint32_t oct[] = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};
/* annulus: outer square 0..3, inner square 4..7 */
static const uint32_t annulus[] = {0, 1, 5, 0, 5, 4, 1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7};

/* Brute-force invariants, independent of the builder's bucketing. */
static void check_invariants(const subd_mesh *m)
{
    uint32_t h, g, v, f, c, nbe = 0, loops = 0, edges = 0;
    static uint32_t ring[64];
    static uint8_t seen[MAXC];
    for (h = 0; h < m->num_corners; h++) {
        uint32_t a = subd_he_origin(m, h), b = subd_he_dest(m, h), t = m->twin[h], want = SUBD_NONE;
        for (g = 0; g < m->num_corners; g++)
            if (subd_he_origin(m, g) == b && subd_he_dest(m, g) == a) want = g;
        if (!CHECK(t == want)) return;
        CHECK(((m->edge_tag[h] & SUBD_ETAG_BOUNDARY) != 0) == (t == SUBD_NONE));
        if (t == SUBD_NONE) nbe++;
        if (t == SUBD_NONE || h < t) edges++;
        CHECK(subd_he_next(m, subd_he_prev(m, h)) == h);
        CHECK(m->corner_face[h] < m->num_faces);
    }
    CHECK_EQ(m->num_boundary_edges, nbe);
    CHECK_EQ(m->num_edges, edges);
    CHECK_EQ(subd_mesh_euler(m), (int32_t)m->num_verts - (int32_t)edges + (int32_t)m->num_faces);
    /* boundary loops by following "a boundary half-edge that starts where this one ends" */
    for (h = 0; h < m->num_corners; h++) seen[h] = 0;
    for (h = 0; h < m->num_corners; h++) {
        uint32_t cur = h, steps = 0;
        if (m->twin[h] != SUBD_NONE || seen[h]) continue;
        loops++;
        do {
            uint32_t nxt = SUBD_NONE;
            seen[cur] = 1;
            for (g = 0; g < m->num_corners; g++)
                if (m->twin[g] == SUBD_NONE && subd_he_origin(m, g) == subd_he_dest(m, cur)) nxt = g;
            cur = nxt;
        } while (cur != h && cur != SUBD_NONE && ++steps < m->num_corners);
    }
    CHECK_EQ(m->num_boundary_loops, loops);
    for (v = 0; v < m->num_verts; v++) {
        uint32_t corners = 0, bout = 0, n, i;
        for (c = 0; c < m->num_corners; c++) {
            if (m->corner_vert[c] != v) continue;
            corners++;
            if (m->twin[c] == SUBD_NONE) bout++;
        }
        if (corners == 0) {
            CHECK(m->vert_out[v] == SUBD_NONE);
            CHECK(m->vert_tag[v] & SUBD_VTAG_ISOLATED);
            CHECK_EQ(subd_vertex_valence(m, v), 0);
            continue;
        }
        CHECK_EQ(subd_he_origin(m, m->vert_out[v]), v);
        CHECK(((m->vert_tag[v] & SUBD_VTAG_BOUNDARY) != 0) == (bout == 1));
        if (bout) CHECK(m->twin[m->vert_out[v]] == SUBD_NONE);
        n = subd_vertex_ring(m, v, ring, 64);
        CHECK_EQ(n, corners + bout);
        /* consecutive neighbours span a face around v, in the face's own order */
        for (i = 0; i + 1 < n || (!bout && i < n); i++) {
            uint32_t p = ring[i], q = ring[(i + 1) % n], found = 0;
            for (f = 0; f < m->num_faces; f++)
                for (c = m->face_start[f]; c < m->face_start[f + 1]; c++)
                    if (m->corner_vert[c] == v && subd_he_dest(m, c) == p &&
                        m->corner_vert[subd_he_prev(m, c)] == q)
                        found = 1;
            CHECK(found);
        }
    }
}

static void build_ok(const subd_face_list *fl, subd_mesh *m)
{
    subd_arena a;
    subd_diag d;
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    CHECK_EQ(subd_mesh_build(&a, fl, m, &d), SUBD_OK);
}

static void mesh_closed(void)
{
    subd_face_list fl;
    subd_mesh m;
    uint32_t v;
    fl = tri_list(4, 4, tet);
    build_ok(&fl, &m);
    check_invariants(&m);
    CHECK_EQ(m.num_edges, 6);
    CHECK_EQ(subd_mesh_euler(&m), 2);
    CHECK_EQ(m.num_boundary_loops, 0);
    for (v = 0; v < 4; v++) CHECK_EQ(subd_vertex_valence(&m, v), 3);
    h_hash("mesh_tet", h_mesh_hash(&m));
    fl = tri_list(6, 8, oct);
    build_ok(&fl, &m);
    check_invariants(&m);
    CHECK_EQ(subd_mesh_euler(&m), 2);
    for (v = 0; v < 6; v++) CHECK_EQ(subd_vertex_valence(&m, v), 4);
    fl = torus_list(6, 4, 0);
    build_ok(&fl, &m);
    check_invariants(&m);
    CHECK_EQ(subd_mesh_euler(&m), 0);
    for (v = 0; v < m.num_verts; v++) CHECK_EQ(subd_vertex_valence(&m, v), 6);
    h_hash("mesh_torus_tri", h_mesh_hash(&m));
    fl = torus_list(5, 3, 1);
    build_ok(&fl, &m);
    check_invariants(&m);
    CHECK_EQ(subd_mesh_euler(&m), 0);
    for (v = 0; v < m.num_verts; v++) CHECK_EQ(subd_vertex_valence(&m, v), 4);
}

static void mesh_open(void)
{
    subd_face_list fl;
    subd_mesh m;
    uint32_t ring[8], n;
    fl = grid_list(4, 3);
    build_ok(&fl, &m);
    check_invariants(&m);
    CHECK_EQ(m.num_boundary_loops, 1);
    CHECK_EQ(m.num_boundary_edges, 14);
    CHECK_EQ(subd_mesh_euler(&m), 1);
    CHECK_EQ(subd_vertex_valence(&m, 0), 3);       /* corner with the diagonal */
    CHECK_EQ(subd_vertex_valence(&m, 5), 6);       /* interior */
    CHECK_EQ(subd_vertex_valence(&m, 3), 2);       /* corner without a diagonal */
    /* boundary ring of vertex 0: ends are its boundary neighbours 1 and 4 */
    n = subd_vertex_ring(&m, 0, ring, 8);
    CHECK_EQ(n, 3);
    CHECK((ring[0] == 1 && ring[2] == 4) || (ring[0] == 4 && ring[2] == 1));
    CHECK_EQ(ring[1], 5);
    h_hash("mesh_grid", h_mesh_hash(&m));
    fl = tri_list(8, 8, annulus);
    build_ok(&fl, &m);
    check_invariants(&m);
    CHECK_EQ(m.num_boundary_loops, 2);
    CHECK_EQ(subd_mesh_euler(&m), 0);
    /* ring truncated to max still reports the valence */
    CHECK_EQ(subd_vertex_ring(&m, 0, ring, 1), subd_vertex_valence(&m, 0));
}

static void mesh_polygons_and_isolated(void)
{
    /* a pentagon fan around vertex 5 made of a pentagon-less mix: 1 quad + 3 triangles,
     * plus an unreferenced vertex 7 and a polyline */
    static const uint32_t idx[] = {0, 1, 5, 4, /**/ 1, 2, 5, /**/ 2, 3, 5, /**/ 3, 4, 5, /**/ 0, 6, 1};
    static const uint32_t sizes[] = {4, 3, 3, 3, 3};
    static const uint32_t lsize[] = {3};
    static const uint32_t lidx[] = {7, 6, 0};
    subd_face_list fl = tri_list(8, 5, idx);
    subd_mesh m;
    fl.face_size = sizes;
    fl.num_lines = 1;
    fl.line_size = lsize;
    fl.line_index = lidx;
    build_ok(&fl, &m);
    check_invariants(&m);
    CHECK_EQ(m.num_isolated, 1);
    CHECK(m.vert_tag[7] & SUBD_VTAG_ISOLATED);
    CHECK_EQ(m.num_lines, 1);
    CHECK_EQ(m.line_vert[0], 7);
    CHECK_EQ(subd_vertex_valence(&m, 5), 4);
    CHECK(!(m.vert_tag[5] & SUBD_VTAG_BOUNDARY));
    CHECK_EQ(m.num_boundary_loops, 1);
    CHECK_EQ(subd_mesh_euler(&m), 2); /* disk (1) + isolated vertex (1) */
    h_hash("mesh_poly", h_mesh_hash(&m));
}

typedef struct build_call {
    const subd_face_list *fl;
    subd_mesh m;
} build_call;

static int build_run(void *ctx, subd_arena *a, subd_diag *d)
{
    build_call *c = (build_call *)ctx;
    return subd_mesh_build(a, c->fl, &c->m, d);
}

/* Every arena size below the plan fails with NOMEM and leaves mark, output and the bytes
 * after the buffer untouched; exactly the plan succeeds with peak = plan. */
static void check_plan_exhaustive(const subd_face_list *fl)
{
    static uint8_t buf[8192 + 64] __attribute__((aligned(8)));
    uint32_t plan;
    build_call c;
    h_sweep s;
    if (!CHECK_EQ(subd_mesh_plan(fl, &plan), SUBD_OK)) return;
    c.fl = fl;
    s = h_sweep_make(build_run, &c, buf, sizeof buf, plan);
    s.prefix = 8;
    s.out = &c.m;
    s.out_bytes = sizeof c.m;
    s.in = fl->pos;
    s.in_bytes = 3u * fl->num_verts * (uint32_t)sizeof(subd_real);
    (void)h_arena_sweep(&s);
}

static void mesh_plan_exact(void)
{
    subd_face_list fl;
    static const uint32_t idx[] = {0, 1, 5, 4, 1, 2, 5, 2, 3, 5, 3, 4, 5};
    static const uint32_t sizes[] = {4, 3, 3, 3};
    uint32_t plan;
    fl = tri_list(4, 4, tet);
    check_plan_exhaustive(&fl);
    CHECK_EQ(subd_mesh_plan(&fl, &plan), SUBD_OK);
    CHECK(plan <= SUBD_MESH_BYTES(4u, 4u, 12u, 0u, 0u));
    fl = grid_list(5, 4);
    check_plan_exhaustive(&fl);
    CHECK_EQ(subd_mesh_plan(&fl, &plan), SUBD_OK);
    CHECK(plan <= SUBD_MESH_BYTES(30u, 40u, 120u, 0u, 0u));
    fl = tri_list(7, 4, idx);
    fl.face_size = sizes;
    check_plan_exhaustive(&fl);
}

/* One failing build: specific status and element, arena mark and output unchanged. */
static void expect_fail(const subd_face_list *fl, int status, uint32_t face, uint32_t vertex)
{
    subd_arena a;
    subd_diag d;
    subd_mesh m;
    uint32_t i;
    uint8_t *pm = (uint8_t *)&m;
    int same = 1;
    for (i = 0; i < sizeof m; i++) pm[i] = 0x77;
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    subd_arena_alloc(&a, 16);
    CHECK_FAIL(subd_mesh_build(&a, fl, &m, &d), &d, status);
    CHECK_EQ(d.status, status);
    CHECK_EQ(subd_arena_mark(&a), 16);
    for (i = 0; i < sizeof m; i++) same &= (pm[i] == 0x77);
    CHECK(same);
    CHECK_EQ(d.face, face);
    CHECK_EQ(d.vertex, vertex);
}

static void mesh_errors(void)
{
    static const uint32_t bad_index[] = {0, 1, 2, 0, 2, 4};
    static const uint32_t repeated[] = {0, 1, 2, 0, 3, 3};
    static const uint32_t nm_edge[] = {0, 1, 2, 1, 0, 3, 1, 0, 4};
    static const uint32_t flipped[] = {0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 2, 3};
    static const uint32_t bowtie[] = {0, 1, 2, 0, 3, 4};
    static const uint32_t bowtie_closed[] = {0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 3, 2, /* tet 0..3 */
                                             0, 5, 4, 0, 4, 6, 4, 5, 6, 0, 6, 5}; /* tet 0,4,5,6 */
    static const uint32_t sizes_bad[] = {3, 2};
    static const uint32_t sizes_big[] = {3, SUBD_MAX_FACE_SIZE + 1u};
    static const uint32_t lsize[] = {2};
    static const uint32_t lidx[] = {0, 9};
    subd_face_list fl;
    subd_arena a;
    subd_mesh m;
    uint32_t plan;

    fl = tri_list(4, 2, bad_index);
    expect_fail(&fl, SUBD_ERR_INDEX, 1, SUBD_NONE);
    fl = tri_list(4, 2, repeated);
    expect_fail(&fl, SUBD_ERR_DEGENERATE, 1, SUBD_NONE);
    fl = tri_list(5, 3, nm_edge);
    expect_fail(&fl, SUBD_ERR_NONMANIFOLD_EDGE, 2, SUBD_NONE);
    fl = tri_list(4, 4, flipped);
    expect_fail(&fl, SUBD_ERR_ORIENTATION, 3, SUBD_NONE);
    fl = tri_list(5, 2, bowtie);
    expect_fail(&fl, SUBD_ERR_NONMANIFOLD_VERTEX, SUBD_NONE, 0);
    fl = tri_list(7, 8, bowtie_closed);
    expect_fail(&fl, SUBD_ERR_NONMANIFOLD_VERTEX, SUBD_NONE, 0);
    fl = tri_list(4, 2, tet);
    fl.face_size = sizes_bad;
    expect_fail(&fl, SUBD_ERR_FACE_SIZE, 1, SUBD_NONE);
    CHECK_EQ(subd_mesh_plan(&fl, &plan), SUBD_ERR_FACE_SIZE);
    fl.face_size = sizes_big;
    expect_fail(&fl, SUBD_ERR_FACE_SIZE, 1, SUBD_NONE);
    fl = tri_list(4, 4, tet);
    fl.num_lines = 1;
    fl.line_size = lsize;
    fl.line_index = lidx;
    expect_fail(&fl, SUBD_ERR_INDEX, SUBD_NONE, SUBD_NONE);
    fl = tri_list(0, 0, tet);
    expect_fail(&fl, SUBD_ERR_EMPTY, SUBD_NONE, SUBD_NONE);
    fl = tri_list(4, 4, 0);
    expect_fail(&fl, SUBD_ERR_PARAM, SUBD_NONE, SUBD_NONE);
#if !SUBD_FIXED
    {
        union { uint32_t u; float f; } nan_bits;
        fl = tri_list(4, 4, tet);
        nan_bits.u = 0x7fc00000u;
        g_pos[3 * 2 + 1] = nan_bits.f;
        expect_fail(&fl, SUBD_ERR_NAN, SUBD_NONE, 2);
        nan_bits.u = 0xff800000u; /* -inf */
        g_pos[3 * 2 + 1] = 0.0f;
        g_pos[3 * 3] = nan_bits.f;
        expect_fail(&fl, SUBD_ERR_NAN, SUBD_NONE, 3);
    }
#endif
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    CHECK_EQ(subd_mesh_build(&a, 0, &m, 0), SUBD_ERR_PARAM);
    CHECK_EQ(subd_mesh_build(0, &fl, &m, 0), SUBD_ERR_PARAM);
    CHECK_EQ(subd_mesh_plan(0, &plan), SUBD_ERR_PARAM);
}

/* Random vertex relabelling must not change the topology counts. */
static void mesh_relabel_property(void)
{
    uint32_t seed = 12345u, trial;
    for (trial = 0; trial < 8; trial++) {
        subd_face_list fl = torus_list(7, 5, (int)(trial & 1u));
        static uint32_t perm[MAXV];
        subd_mesh m;
        uint32_t i, nc = (trial & 1u) ? 4u * fl.num_faces : 3u * fl.num_faces;
        for (i = 0; i < fl.num_verts; i++) perm[i] = i;
        for (i = fl.num_verts - 1u; i > 0; i--) {
            uint32_t j = h_rand(&seed) % (i + 1u), t = perm[i];
            perm[i] = perm[j];
            perm[j] = t;
        }
        for (i = 0; i < nc; i++) g_idx[i] = perm[g_idx[i]];
        build_ok(&fl, &m);
        check_invariants(&m);
        CHECK_EQ(subd_mesh_euler(&m), 0);
        for (i = 0; i < m.num_verts; i++) CHECK_EQ(subd_vertex_valence(&m, i), (trial & 1u) ? 4 : 6);
    }
}

static void mesh_edge_tags(void)
{
    subd_face_list fl = tri_list(4, 4, tet);
    subd_mesh m;
    build_ok(&fl, &m);
    subd_edge_tag_set(&m, 0, SUBD_ETAG_CREASE);
    CHECK(m.edge_tag[0] & SUBD_ETAG_CREASE);
    CHECK(m.edge_tag[m.twin[0]] & SUBD_ETAG_CREASE);
    subd_edge_tag_clear(&m, m.twin[0], SUBD_ETAG_CREASE);
    CHECK(!(m.edge_tag[0] & SUBD_ETAG_CREASE));
    CHECK(!(m.edge_tag[m.twin[0]] & SUBD_ETAG_CREASE));
}

/* One vertex of valence FAN_N (the builder is O(corners); the bucket-scan builder before it
 * was O(valence^2) here). Fan faces i = (0, 1+i, 1+(i+1)%n), corners 3i..3i+2: the twin of
 * spoke 0 -> 1+i (corner 3i) is 1+i -> 0 in face i-1 (corner 3(i-1)+2); the rim edges 3i+1
 * are the boundary; vert_out is the smallest corner of the interior centre and the outgoing
 * rim edge of each rim vertex. Checked against these closed forms, then with every corner's
 * twin found by a search over all corners of its two vertices, then with one extra face
 * (non-manifold spoke, named by the extra face) and with a second fan on the centre
 * (bow-tie centre). */
#define FAN_N (H_HOST ? 4096u : 512u) /* the device: 4096 would put bss within 350 KB of QEMU's RAM top */
static uint32_t g_fan_idx[3u * (FAN_N + 1u)];
static uint8_t g_fan_arena[SUBD_MESH_BYTES(FAN_N + 1u, FAN_N + 1u, 3u * (FAN_N + 1u), 0u, 0u)]
    __attribute__((aligned(8)));
static subd_real g_fan_pos[3u * (FAN_N + 1u)];

static int fan_build(uint32_t nf, subd_mesh *m, subd_diag *d)
{
    subd_face_list fl = {0, 0, 0, 0, 0, 0, 0, 0};
    subd_arena a;
    fl.num_verts = FAN_N + 1u;
    fl.pos = g_fan_pos;
    fl.num_faces = nf;
    fl.index = g_fan_idx;
    subd_arena_init(&a, g_fan_arena, (uint32_t)sizeof g_fan_arena);
    return subd_mesh_build(&a, &fl, m, d);
}

static void mesh_high_valence_fan(void)
{
    const uint32_t n = FAN_N;
    subd_mesh m;
    subd_diag d;
    uint32_t i, h, g, bad = 0;
    for (i = 0; i < 3u * (n + 1u); i++) g_fan_pos[i] = 0;
    for (i = 0; i < n; i++) {
        g_fan_idx[3u * i] = 0;
        g_fan_idx[3u * i + 1u] = 1u + i;
        g_fan_idx[3u * i + 2u] = 1u + (i + 1u) % n;
    }
    if (!CHECK_EQ(fan_build(n, &m, &d), SUBD_OK)) return;
    CHECK_EQ(m.num_edges, 2u * n);
    CHECK_EQ(m.num_boundary_edges, n);
    CHECK_EQ(m.num_boundary_loops, 1);
    CHECK_EQ(m.num_isolated, 0);
    CHECK_EQ(subd_vertex_valence(&m, 0), n);
    CHECK_EQ(m.vert_out[0], 0);
    CHECK_EQ(m.vert_tag[0], 0);
    for (i = 0; i < n && !bad; i++) {
        bad |= m.twin[3u * i] != 3u * ((i + n - 1u) % n) + 2u;
        bad |= m.twin[3u * i + 1u] != SUBD_NONE;
        bad |= m.twin[3u * i + 2u] != 3u * ((i + 1u) % n);
        bad |= m.vert_out[1u + i] != 3u * i + 1u;
        bad |= m.vert_tag[1u + i] != SUBD_VTAG_BOUNDARY;
        bad |= m.edge_tag[3u * i + 1u] != SUBD_ETAG_BOUNDARY || m.edge_tag[3u * i] != 0;
    }
    CHECK_EQ(bad, 0);
    /* the twins of a sample of corners by a search over all corners */
    for (h = 0; h < m.num_corners && !bad; h += 61u) {
        uint32_t a = subd_he_origin(&m, h), b = subd_he_dest(&m, h), want = SUBD_NONE;
        for (g = 0; g < m.num_corners; g++)
            if (subd_he_origin(&m, g) == b && subd_he_dest(&m, g) == a) want = g;
        bad |= m.twin[h] != want;
    }
    CHECK_EQ(bad, 0);
    /* a second face on spoke 0 -> 1: non-manifold edge, named by the extra face */
    g_fan_idx[3u * n] = 0;
    g_fan_idx[3u * n + 1u] = 1;
    g_fan_idx[3u * n + 2u] = n / 2u;
    CHECK_EQ(fan_build(n + 1u, &m, &d), SUBD_ERR_NONMANIFOLD_EDGE);
    CHECK_EQ(d.face, n);
    /* two open fans on the centre (drop faces n/2 - 1 and n - 1): a bow-tie at vertex 0 */
    for (i = n / 2u - 1u; i < n - 2u; i++) {
        g_fan_idx[3u * i] = 0;
        g_fan_idx[3u * i + 1u] = 2u + i;
        g_fan_idx[3u * i + 2u] = 3u + i;
    }
    CHECK_EQ(fan_build(n - 2u, &m, &d), SUBD_ERR_NONMANIFOLD_VERTEX);
    CHECK_EQ(d.vertex, 0);
}

/* Issue 13: subd_vertex_ring / subd_vertex_valence on a mesh without adjacency (subd_loop
 * output without SUBD_LOOP_ADJACENCY) or with an out-of-range vertex return 0 (they used to
 * dereference the missing arrays); the readers take the empty (NULL, 0) buffer without
 * pointer arithmetic on NULL (clang's UBSan flags NULL + 0). */
static void mesh_no_adjacency(void)
{
    subd_arena a;
    subd_mesh m, tri;
    subd_diag d;
    uint32_t nbr[8] = {0}, bytes = 5;
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    if (!h_tetra_no_adjacency(&a, &m, &tri)) return;
    CHECK_EQ(subd_vertex_valence(&m, 0), 3);
    CHECK_EQ(subd_vertex_valence(&m, 4), 0);
    CHECK_EQ(subd_vertex_ring(&m, SUBD_NONE, nbr, 8), 0);
    CHECK_EQ(subd_vertex_valence(0, 0), 0);
    CHECK_EQ(subd_vertex_valence(&tri, 0), 0);
    CHECK_EQ(subd_vertex_ring(&tri, 1, nbr, 8), 0);
    CHECK_EQ(nbr[0], 0);
    /* edge tags without twins: only the half-edge itself changes (it used to read twin[h]);
     * out-of-range half-edges, a NULL mesh and a mesh without edge tags are left alone */
    {
        uint8_t before[64];
        uint32_t h, n = tri.num_corners < 64u ? tri.num_corners : 64u;
        for (h = 0; h < n; h++) before[h] = tri.edge_tag[h];
        subd_edge_tag_set(&tri, 5, SUBD_ETAG_CREASE);
        for (h = 0; h < n; h++)
            CHECK_EQ(tri.edge_tag[h], h == 5u ? (uint8_t)(before[h] | SUBD_ETAG_CREASE) : before[h]);
        subd_edge_tag_clear(&tri, 5, SUBD_ETAG_CREASE);
        for (h = 0; h < n; h++) CHECK_EQ(tri.edge_tag[h], (h == 5u ? (uint8_t)(before[h] & ~SUBD_ETAG_CREASE) : before[h]));
        subd_edge_tag_set(&tri, tri.num_corners, SUBD_ETAG_CREASE);
        subd_edge_tag_set(&tri, SUBD_NONE, SUBD_ETAG_CREASE);
        subd_edge_tag_set(0, 0, SUBD_ETAG_CREASE);
        subd_edge_tag_clear(0, 0, SUBD_ETAG_CREASE);
        for (h = 0; h < n; h++) CHECK_EQ(tri.edge_tag[h], (h == 5u ? (uint8_t)(before[h] & ~SUBD_ETAG_CREASE) : before[h]));
        tri.edge_tag = 0;
        subd_edge_tag_set(&tri, 0, SUBD_ETAG_CREASE);
        CHECK_EQ(subd_mesh_euler(0), 0);
    }
    /* the empty buffer */
    CHECK_EQ(subd_obj_plan(0, 0, &bytes, &d), subd_obj_plan("", 0, &bytes, &d));
    CHECK_EQ(subd_off_plan(0, 0, &bytes, &d), subd_off_plan("", 0, &bytes, &d));
    CHECK_EQ(subd_obj_read(&a, 0, 0, &m, &d), subd_obj_read(&a, "", 0, &m, &d));
    CHECK_EQ(subd_off_read(&a, 0, 0, &m, &d), subd_off_read(&a, "", 0, &m, &d));
}

const test_case suite_mesh[] = {
    {"mesh_closed", mesh_closed},
    {"mesh_open", mesh_open},
    {"mesh_polygons_and_isolated", mesh_polygons_and_isolated},
    {"mesh_plan_exact", mesh_plan_exact},
    {"mesh_errors", mesh_errors},
    {"mesh_relabel_property", mesh_relabel_property},
    {"mesh_edge_tags", mesh_edge_tags},
    {"mesh_high_valence_fan", mesh_high_valence_fan},
    {"mesh_no_adjacency", mesh_no_adjacency},
    {0, 0}
};
