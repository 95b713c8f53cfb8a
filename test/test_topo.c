/* SPDX-License-Identifier: MIT */
/* The topology helpers of src/topo.h, each against a brute-force computation written here, on
 * closed meshes (bipyramids: apex valence 3..12), open ones (fans: centre valence 3..12 on
 * the boundary; a triangle grid), meshes with isolated vertices and a polygon (quad) grid:
 *   - topo_ring: the ring of every vertex equals the one found by searching the faces (no
 *     twins, no prev): from the vert_out edge, the next neighbour is the vertex before v in
 *     the current face, the next edge the one from v to it, found by a search; a missing
 *     edge ends the walk there (the tail). Also the half-edge of each step and the set of
 *     neighbours (every vertex sharing an edge with v).
 *   - loop_patch.c's 16-bit patch walk (subd_lp_ring) equals topo_ring on the input, at the
 *     three corners of every control face's patch.
 *   - subd_topo_has against the rule restated (each array, each guard, empty counts).
 *   - topo_edge_sharp against "no face holds the reversed edge, or a half-edge of the edge
 *     carries CREASE", with crease bits on one half only.
 *   - Loop's 1->4 tables against subd_loop's output: child 4f+k's corners are the points
 *     TOPO_LOOP_CHILD_POINTS[k] of (v0, v1, v2, m0, m1, m2), m_i found by the documented
 *     numbering (input vertices, then one per edge by lower half-edge); the new vertices'
 *     vert_out equals topo_loop_new_vout (and the builder's, which test_loop checks).
 *   - topo_loop_child_corners / topo_loop_child_edge_tags (loop.c's straight-line writers)
 *     against the child order restated literally here.
 *   - topo_tri_fan_step (loop.c's fast walk of smooth vertices) equals topo_ring_step on
 *     every vertex of the triangle meshes above, of creased grids with corner tags and of
 *     their Loop levels 1 and 2: the same neighbours and half-edges, ending at vert_out
 *     (interior) or SUBD_NONE (boundary, where topo_ring yields its tail).
 *   - The sharp-edge rule followed by every scheme: a crease tagged on one half-edge only
 *     (either one) gives bit for bit the output of the same crease tagged on both halves:
 *     subd_loop, subd_loop_limit (positions and normals), subd_pia PAPER and FAST,
 *     subd_quasi48 (positions and corners). Before topo.h, pia_fast.c's preconditioner read
 *     only the asked half (FAST results differed when only the twin half was tagged). */
#include "harness.h"
#include "subd_loop.h"
#include "subd_quasi48.h"
#include "../src/topo.h"
#include "../src/loop_patch.h"

#define TMAXV 256u
#define TMAXF 400u
#define TMAXC (4u * TMAXF)

static subd_real t_pos[3 * TMAXV];
static uint32_t t_idx[TMAXC], t_size[TMAXF];
static uint8_t t_work[128u * 1024u] __attribute__((aligned(8)));

/* A face list over t_pos / t_idx (t_size when quads). */
static subd_face_list t_list(uint32_t nv, uint32_t nf, int quads)
{
    subd_face_list fl = {0, 0, 0, 0, 0, 0, 0, 0};
    fl.num_verts = nv;
    fl.pos = t_pos;
    fl.num_faces = nf;
    fl.face_size = quads ? t_size : 0;
    fl.index = t_idx;
    return fl;
}

static void t_set(uint32_t v, int32_t x, int32_t y, int32_t z)
{
    t_pos[3 * v] = h_int(x);
    t_pos[3 * v + 1] = h_int(y);
    t_pos[3 * v + 2] = h_int(z);
}

/* Meshes by id: 0..9 bipyramid n = 3..12 (closed), 10..19 fan n = 3..12 (open, centre on the
 * boundary) with two isolated vertices, 20 a 6 x 5 triangle grid, 21 a 4 x 4 quad grid with an
 * isolated vertex, 22 a closed fan n = 7 (centre interior) with an isolated vertex first. */
#define T_MESHES 23u

static int t_make(uint32_t id, subd_arena *a, subd_mesh *m)
{
    uint32_t nv = 0, nf = 0, k, i, j;
    int quads = 0;
    subd_face_list fl;
    if (id < 10u) { /* bipyramid: apexes 0 (top) and n + 1 (bottom), ring 1..n */
        uint32_t n = id + 3u;
        t_set(0, 0, 0, 5);
        t_set(n + 1u, 0, 0, -5);
        for (k = 1; k <= n; k++) t_set(k, (int32_t)(k * 7u % 11u) - 5, (int32_t)(k * 5u % 9u) - 4, (int32_t)(k % 3u));
        for (k = 0; k < n; k++) {
            uint32_t a1 = k + 1u, b1 = (k + 1u) % n + 1u;
            t_idx[3 * nf] = 0; t_idx[3 * nf + 1] = a1; t_idx[3 * nf + 2] = b1; nf++;
            t_idx[3 * nf] = n + 1u; t_idx[3 * nf + 1] = b1; t_idx[3 * nf + 2] = a1; nf++;
        }
        nv = n + 2u;
    } else if (id < 20u) { /* open fan around 0, ring 1..n, isolated n + 1 and n + 2 */
        uint32_t n = id - 7u;
        t_set(0, 0, 0, 1);
        for (k = 1; k <= n; k++) t_set(k, (int32_t)(k * 3u % 7u) + 1, (int32_t)(k * 5u % 8u) - 4, (int32_t)(k % 2u));
        t_set(n + 1u, 9, 9, 9);
        t_set(n + 2u, -9, 9, 9);
        for (k = 0; k + 1u < n; k++) {
            t_idx[3 * nf] = 0; t_idx[3 * nf + 1] = k + 1u; t_idx[3 * nf + 2] = k + 2u; nf++;
        }
        nv = n + 3u;
    } else if (id == 20u) { /* triangle grid 6 x 5 vertices */
        for (j = 0; j < 5u; j++)
            for (i = 0; i < 6u; i++) t_set(j * 6u + i, (int32_t)i, (int32_t)j, (int32_t)((i * j) % 3u));
        for (j = 0; j + 1u < 5u; j++)
            for (i = 0; i + 1u < 6u; i++) {
                uint32_t v = j * 6u + i;
                t_idx[3 * nf] = v; t_idx[3 * nf + 1] = v + 1u; t_idx[3 * nf + 2] = v + 7u; nf++;
                t_idx[3 * nf] = v; t_idx[3 * nf + 1] = v + 7u; t_idx[3 * nf + 2] = v + 6u; nf++;
            }
        nv = 30u;
    } else if (id == 21u) { /* quad grid 4 x 4 vertices, isolated vertex 16 */
        for (j = 0; j < 4u; j++)
            for (i = 0; i < 4u; i++) t_set(j * 4u + i, (int32_t)i, (int32_t)j, (int32_t)((i + j) % 2u));
        t_set(16, 7, 7, 7);
        for (j = 0; j + 1u < 4u; j++)
            for (i = 0; i + 1u < 4u; i++) {
                uint32_t v = j * 4u + i;
                t_size[nf] = 4;
                t_idx[4 * nf] = v; t_idx[4 * nf + 1] = v + 1u; t_idx[4 * nf + 2] = v + 5u; t_idx[4 * nf + 3] = v + 4u;
                nf++;
            }
        nv = 17u;
        quads = 1;
    } else { /* closed fan n = 7 around 1 with its ring 2..8 and a cap: isolated vertex 0 */
        uint32_t n = 7u;
        t_set(0, 9, 9, 9);
        t_set(1, 0, 0, 2);
        t_set(n + 2u, 0, 0, -3);
        for (k = 0; k < n; k++) t_set(k + 2u, (int32_t)(k * 3u % 5u) - 2, (int32_t)(k * 2u % 7u) - 3, 0);
        for (k = 0; k < n; k++) {
            uint32_t a1 = k + 2u, b1 = (k + 1u) % n + 2u;
            t_idx[3 * nf] = 1; t_idx[3 * nf + 1] = a1; t_idx[3 * nf + 2] = b1; nf++;
            t_idx[3 * nf] = n + 2u; t_idx[3 * nf + 1] = b1; t_idx[3 * nf + 2] = a1; nf++;
        }
        nv = n + 3u;
    }
    fl = t_list(nv, nf, quads);
    return h_build(a, &fl, m);
}

/* ------------------------------------------------------------------------------------ */
/* Brute force                                                                            */

/* The half-edge from a to b, by search (SUBD_NONE when no face has it). */
static uint32_t bf_edge(const subd_mesh *m, uint32_t a, uint32_t b)
{
    uint32_t f, c;
    for (f = 0; f < m->num_faces; f++)
        for (c = m->face_start[f]; c < m->face_start[f + 1]; c++) {
            uint32_t c1 = c + 1u == m->face_start[f + 1] ? m->face_start[f] : c + 1u;
            if (m->corner_vert[c] == a && m->corner_vert[c1] == b) return c;
        }
    return SUBD_NONE;
}

/* The corner before c in its face, by search over the face's corners. */
static uint32_t bf_prev(const subd_mesh *m, uint32_t c)
{
    uint32_t f;
    for (f = 0; f < m->num_faces; f++)
        if (c >= m->face_start[f] && c < m->face_start[f + 1]) return c == m->face_start[f] ? m->face_start[f + 1] - 1u : c - 1u;
    return SUBD_NONE;
}

/* v's ring by search: neighbours into nb, the half-edges into he (the tail's: the incoming
 * boundary edge); returns the count. */
static uint32_t bf_ring(const subd_mesh *m, uint32_t v, uint32_t *nb, uint32_t *he, uint32_t max)
{
    uint32_t h = m->vert_out[v], n = 0;
    if (h == SUBD_NONE) return 0;
    while (n < max) {
        uint32_t p = bf_prev(m, h), u = m->corner_vert[p], next;
        /* the destination of h: the corner after h in its face */
        {
            uint32_t f, c1 = SUBD_NONE;
            for (f = 0; f < m->num_faces; f++)
                if (h >= m->face_start[f] && h < m->face_start[f + 1])
                    c1 = h + 1u == m->face_start[f + 1] ? m->face_start[f] : h + 1u;
            nb[n] = m->corner_vert[c1];
        }
        he[n++] = h;
        next = bf_edge(m, v, u);
        if (next == SUBD_NONE) { /* boundary: u is the tail, along p = u -> v */
            if (n < max) {
                nb[n] = u;
                he[n++] = p;
            }
            break;
        }
        if (next == m->vert_out[v]) break;
        h = next;
    }
    return n;
}

/* ------------------------------------------------------------------------------------ */

static void topo_ring_brute(void)
{
    uint32_t id, v, k;
    for (id = 0; id < T_MESHES; id++) {
        subd_arena a;
        subd_mesh m;
        subd_arena_init(&a, t_work, sizeof t_work);
        if (!t_make(id, &a, &m)) return;
        for (v = 0; v < m.num_verts; v++) {
            static uint32_t nb[32], he[32];
            static uint8_t adj[TMAXV];
            uint32_t n = bf_ring(&m, v, nb, he, 32u), i = 0, ntail = 0;
            topo_ring r;
            topo_ring_begin(&r, &m, v);
            while (topo_ring_step(&r)) {
                if (!CHECK(i < n)) break;
                CHECK_EQ(r.nb, nb[i]);
                CHECK_EQ(r.he, he[i]);
                CHECK_EQ(r.tail, i + 1u == n && (m.vert_tag[v] & SUBD_VTAG_BOUNDARY) ? 1u : 0u);
                ntail += r.tail;
                i++;
            }
            CHECK_EQ(i, n);
            CHECK_EQ(ntail, (m.vert_tag[v] & SUBD_VTAG_BOUNDARY) ? 1u : 0u);
            CHECK_EQ(subd_vertex_valence(&m, v), n);
            /* the neighbours are exactly the vertices sharing an edge with v, once each */
            for (k = 0; k < m.num_verts; k++) adj[k] = 0;
            for (k = 0; k < m.num_corners; k++) {
                uint32_t c1 = k + 1u == m.face_start[m.corner_face[k] + 1u] ? m.face_start[m.corner_face[k]] : k + 1u;
                if (m.corner_vert[k] == v) adj[m.corner_vert[c1]] = 1;
                if (m.corner_vert[c1] == v) adj[m.corner_vert[k]] = 1;
            }
            for (k = 0; k < n; k++) {
                CHECK(adj[nb[k]] == 1u);
                adj[nb[k]] = 2;
            }
            for (k = 0; k < m.num_verts; k++) CHECK(adj[k] != 1u);
            /* the triangle form over the same arrays walks the same ring */
            if (id != 21u) {
                topo_ring_begin_tri(&r, m.corner_vert, m.twin, m.num_corners, m.vert_out[v]);
                for (i = 0; topo_ring_step(&r); i++) CHECK(i < n && r.nb == nb[i] && r.he == he[i]);
                CHECK_EQ(i, n);
            }
        }
    }
}

/* loop_patch.c's walk of a control patch's corners equals topo_ring on the input. */
static void topo_patch_ring(void)
{
    uint32_t id, f, v, i;
    for (id = 0; id < T_MESHES; id++) {
        subd_arena a;
        subd_mesh m;
        uint32_t off[A_N], s = 96u, bytes;
        uint8_t *blk;
        sp_head head;
        sp_level p;
        if (id == 21u) continue; /* the stream is for triangles */
        subd_arena_init(&a, t_work, sizeof t_work);
        if (!t_make(id, &a, &m)) return;
        bytes = subd_lp_level_layout(s, 0, 1, off);
        blk = (uint8_t *)subd_arena_alloc(&a, bytes);
        if (!CHECK(blk != 0)) return;
        p.h = &head;
        subd_lp_level_bind(blk, off, &p); /* the library's carve (loop_patch.c) */
        p.cpos = 0; /* a control patch without the cache */
        p.cflag = 0;
        for (f = 0; f < m.num_faces; f++) {
            subd_lp_build_control(&m, f, &p, 2u);
            for (v = 0; v < 3u; v++) {
                static uint32_t nb[32], he[32];
                uint32_t n = subd_lp_ring(&p, v, nb, he, 32u);
                topo_ring r;
                CHECK_EQ(p.cvert[v], m.corner_vert[3u * f + v]);
                topo_ring_begin(&r, &m, p.cvert[v]);
                for (i = 0; topo_ring_step(&r); i++) {
                    if (!CHECK(i < n)) break;
                    CHECK_EQ(p.cvert[nb[i]], r.nb);
                    CHECK_EQ(3u * p.cface[he[i] / 3u] + he[i] % 3u, r.he);
                    /* the patch's sharp bits are the rule's */
                    CHECK_EQ((p.sh[he[i]] & LP_SH_RULE) != 0u, topo_mesh_edge_sharp(&m, r.he));
                }
                CHECK_EQ(i, n);
            }
        }
    }
}

/* subd_topo_has against its rule, array by array. */
static void topo_has_rule(void)
{
    static const uint32_t bits[8] = {TOPO_POS,  TOPO_FACE_START, TOPO_CORNER_VERT, TOPO_CORNER_FACE,
                                     TOPO_TWIN, TOPO_VERT_OUT,   TOPO_VERT_TAG,    TOPO_EDGE_TAG};
    static const uint32_t guards[3] = {0u, TOPO_IF_FACES, TOPO_ALWAYS};
    subd_arena a;
    subd_mesh m;
    uint32_t shape, g, b, drop;
    subd_arena_init(&a, t_work, sizeof t_work);
    if (!t_make(10, &a, &m)) return;
    CHECK_EQ(subd_topo_has(0, 0), 0);
    CHECK_EQ(subd_topo_has(&m, 0), 1);
    for (shape = 0; shape < 3u; shape++) { /* full; points only (no faces); empty */
        subd_mesh s = m;
        if (shape >= 1u) {
            s.num_faces = 0;
            s.num_corners = 0;
        }
        if (shape == 2u) s.num_verts = 0;
        for (g = 0; g < 3u; g++)
            for (drop = 0; drop < 8u; drop++) {
                subd_mesh t = s;
                uint32_t count;
                switch (drop) {
                case 0: t.pos = 0; count = t.num_verts; break;
                case 1: t.face_start = 0; count = 1; break;
                case 2: t.corner_vert = 0; count = t.num_corners; break;
                case 3: t.corner_face = 0; count = t.num_corners; break;
                case 4: t.twin = 0; count = t.num_corners; break;
                case 5: t.vert_out = 0; count = t.num_verts; break;
                case 6: t.vert_tag = 0; count = t.num_verts; break;
                default: t.edge_tag = 0; count = t.num_corners; break;
                }
                for (b = 0; b < 8u; b++) {
                    uint32_t need = guards[g] | bits[b], want = 1;
                    if (b == drop) {
                        uint32_t needed = g == 2u ? 1u : g == 1u ? (t.num_faces != 0u) : (count != 0u);
                        want = needed ? 0u : 1u;
                    }
                    CHECK_EQ(subd_topo_has(&t, need), want);
                }
            }
    }
}

/* topo_edge_sharp against the rule, with one-sided crease bits. */
static void topo_sharp_rule(void)
{
    uint32_t id, h;
    for (id = 0; id < T_MESHES; id++) {
        subd_arena a;
        subd_mesh m;
        subd_arena_init(&a, t_work, sizeof t_work);
        if (!t_make(id, &a, &m)) return;
        for (h = 0; h < m.num_corners; h++) /* a pattern of one-sided and two-sided creases */
            if (h % 5u == 1u) m.edge_tag[h] |= SUBD_ETAG_CREASE;
        for (h = 0; h < m.num_corners; h++) {
            uint32_t f = m.corner_face[h], h1 = h + 1u == m.face_start[f + 1u] ? m.face_start[f] : h + 1u;
            uint32_t a0 = m.corner_vert[h], b0 = m.corner_vert[h1], rev = bf_edge(&m, b0, a0);
            int want = rev == SUBD_NONE || (m.edge_tag[h] & SUBD_ETAG_CREASE) || (m.edge_tag[rev] & SUBD_ETAG_CREASE);
            CHECK_EQ(topo_mesh_edge_sharp(&m, h), want);
            CHECK_EQ(topo_edge_sharp(m.twin, m.edge_tag, h), want);
            /* a stray BOUNDARY bit on an interior half-edge does not make it sharp */
            if (rev != SUBD_NONE && !want) {
                uint8_t keep = m.edge_tag[h];
                m.edge_tag[h] |= SUBD_ETAG_BOUNDARY;
                CHECK_EQ(topo_mesh_edge_sharp(&m, h), 0);
                m.edge_tag[h] = keep;
            }
        }
    }
}

/* Loop's 1->4 tables against subd_loop's output. */
static void topo_loop_child_tables(void)
{
    static const uint8_t pts[4][3] = TOPO_LOOP_CHILD_POINTS;
    uint32_t id, f, k, j;
    for (id = 0; id < T_MESHES; id++) {
        subd_arena a;
        subd_mesh m, out;
        subd_loop_opts o;
        subd_diag d;
        static uint32_t mnum[TMAXC];
        uint32_t h, e;
        if (id == 21u) continue;
        subd_arena_init(&a, t_work, sizeof t_work);
        if (!t_make(id, &a, &m)) return;
        o.levels = 1;
        o.boundary = SUBD_LOOP_BOUNDARY_PAPER;
        o.flags = SUBD_LOOP_ADJACENCY;
        if (!CHECK_OK(subd_loop(&a, &m, &o, &out, &d), &d)) return;
        /* new vertex of each half-edge: input vertices first, then one per edge in the order
         * of its lower half-edge */
        for (h = 0, e = m.num_verts; h < m.num_corners; h++)
            if (m.twin[h] == SUBD_NONE || h < m.twin[h]) mnum[h] = e++;
        for (h = 0; h < m.num_corners; h++)
            if (m.twin[h] != SUBD_NONE && m.twin[h] < h) mnum[h] = mnum[m.twin[h]];
        CHECK_EQ(e, out.num_verts);
        for (f = 0; f < m.num_faces; f++) {
            uint32_t x[6];
            for (j = 0; j < 3u; j++) {
                x[j] = m.corner_vert[3u * f + j];
                x[3u + j] = mnum[3u * f + j];
            }
            for (k = 0; k < 4u; k++)
                for (j = 0; j < 3u; j++) CHECK_EQ(out.corner_vert[12u * f + 3u * k + j], x[pts[k][j]]);
            for (j = 0; j < 3u; j++) {
                uint32_t h0 = 3u * f + j, a1 = topo_loop_first_half(j), a2 = topo_loop_second_half(j);
                /* the halves: v_j -> m_j and m_j -> v_j+1 */
                CHECK_EQ(out.corner_vert[12u * f + a1], x[j]);
                CHECK_EQ(subd_he_dest(&out, 12u * f + a1), x[3u + j]);
                CHECK_EQ(out.corner_vert[12u * f + a2], x[3u + j]);
                CHECK_EQ(subd_he_dest(&out, 12u * f + a2), x[(j + 1u) % 3u]);
                CHECK_EQ(topo_loop_half_first(h0), 12u * f + a1);
                if (m.twin[h0] == SUBD_NONE || h0 < m.twin[h0])
                    CHECK_EQ(out.vert_out[mnum[h0]], 12u * f + topo_loop_new_vout(j, m.twin[h0] == SUBD_NONE));
            }
        }
    }
}

/* The straight-line writers against the documented child order, restated here literally:
 * child i = (v_i, m_i, m_{i-1}), child 3 = (m0, m1, m2); the edge of corner j of child k
 * goes to corner j + 1: v_i -> m_i (side i), m_i -> m_{i-1} (inner), m_{i-1} -> v_i (side
 * i - 1); child 3's edges are inner. */
static void topo_loop_child_writers(void)
{
    static const uint8_t doc[4][3] = {{0u, 3u, 5u}, {1u, 4u, 3u}, {2u, 5u, 4u}, {3u, 4u, 5u}};
    static const uint8_t pts[4][3] = TOPO_LOOP_CHILD_POINTS;
    uint32_t x[6], cv[12], k, j;
    uint8_t et[12], tag[3] = {SUBD_ETAG_CREASE, SUBD_ETAG_BOUNDARY, SUBD_ETAG_CREASE | SUBD_ETAG_BOUNDARY};
    for (k = 0; k < 6u; k++) x[k] = 100u + 7u * k;
    for (k = 0; k < 12u; k++) {
        cv[k] = SUBD_NONE;
        et[k] = 0xffu;
    }
    topo_loop_child_corners(cv, x);
    topo_loop_child_edge_tags(et, tag);
    for (k = 0; k < 4u; k++)
        for (j = 0; j < 3u; j++) {
            uint8_t want = 0;
            CHECK_EQ(pts[k][j], doc[k][j]);
            CHECK_EQ(TOPO_LOOP_CP(k, j), doc[k][j]);
            CHECK_EQ(cv[3u * k + j], x[doc[k][j]]);
            if (k < 3u && j == 0u) want = tag[k];
            if (k < 3u && j == 2u) want = tag[(k + 2u) % 3u];
            CHECK_EQ(et[3u * k + j], want);
        }
}

/* ------------------------------------------------------------------------------------ */
/* Every scheme follows the rule: one-sided crease bits = two-sided ones.                 */

#define TG 7u /* grid side */

/* TG x TG triangle grid with a crease across row 3 (boundary to boundary: its interior
 * vertices are crease vertices, no darts) tagged on `side`: 0 both halves, 1 the half-edges
 * going +x only, 2 their twins only. */
static int t_grid(subd_arena *a, uint32_t side, subd_mesh *m)
{
    uint32_t i, j, nf = 0, h;
    subd_face_list fl;
    for (j = 0; j < TG; j++)
        for (i = 0; i < TG; i++)
            t_set(j * TG + i, 4 * (int32_t)i, 4 * (int32_t)j, (int32_t)((3u * i * i + 5u * j + 2u * i * j) % 7u) - 3);
    for (j = 0; j + 1u < TG; j++)
        for (i = 0; i + 1u < TG; i++) {
            uint32_t v = j * TG + i;
            t_idx[3 * nf] = v; t_idx[3 * nf + 1] = v + 1u; t_idx[3 * nf + 2] = v + TG + 1u; nf++;
            t_idx[3 * nf] = v; t_idx[3 * nf + 1] = v + TG + 1u; t_idx[3 * nf + 2] = v + TG; nf++;
        }
    fl = t_list(TG * TG, nf, 0);
    if (!h_build(a, &fl, m)) return 0;
    for (h = 0; h < m->num_corners; h++) {
        uint32_t u = m->corner_vert[h], w = subd_he_dest(m, h);
        if (u / TG != 3u || w / TG != 3u || m->twin[h] == SUBD_NONE) continue;
        if (w == u + 1u && side != 2u) m->edge_tag[h] |= SUBD_ETAG_CREASE;
        if (w + 1u == u && side != 1u) m->edge_tag[h] |= SUBD_ETAG_CREASE;
    }
    return 1;
}

static int t_same(const subd_real *x, const subd_real *y, uint32_t n)
{
    uint32_t i;
    for (i = 0; i < n; i++)
        if (!h_same(x[i], y[i])) return 0;
    return 1;
}

/* ------------------------------------------------------------------------------------ */
/* The fast fan walk (topo_tri_fan_step, loop.c's smooth vertices) equals topo_ring.       */

/* On every vertex of m: from vert_out, the fan step yields topo_ring_step's non-tail
 * neighbours in order, its running half-edge is the ring's outgoing half-edge before each
 * step, and after the last one it is back at vert_out (interior) or SUBD_NONE (boundary).
 * Returns the number of vertices checked. */
static uint32_t t_fan_equal(const subd_mesh *m)
{
    uint32_t v, checked = 0;
    for (v = 0; v < m->num_verts; v++) {
        topo_ring r;
        uint32_t h = m->vert_out[v], n = 0;
        if (h == SUBD_NONE) continue;
        topo_ring_begin_tri(&r, m->corner_vert, m->twin, m->num_corners, h);
        while (topo_ring_step(&r) && !r.tail) {
            if (!CHECK(h < m->num_corners)) return checked;
            CHECK_EQ(h, r.he);
            CHECK_EQ(topo_tri_fan_step(m->corner_vert, m->twin, &h), r.nb);
            n++;
        }
        CHECK(n > 0u);
        CHECK_EQ(h, r.tail ? SUBD_NONE : m->vert_out[v]);
        CHECK_EQ(r.tail, (m->vert_tag[v] & SUBD_VTAG_BOUNDARY) ? 1u : 0u);
        checked++;
    }
    return checked;
}

static void topo_fan_fast(void)
{
    uint32_t id, side, nboundary = 0, ninterior = 0;
    /* the triangle meshes of t_make: closed, open fans (boundary centres), a grid */
    for (id = 0; id < T_MESHES; id++) {
        subd_arena a;
        subd_mesh m;
        if (id == 21u) continue; /* quads */
        subd_arena_init(&a, t_work, sizeof t_work);
        if (!t_make(id, &a, &m)) return;
        CHECK(t_fan_equal(&m) > 0u);
    }
    /* creased grids (a crease tagged on both halves or on one), with corner tags, and their
     * Loop levels 1 and 2 (the levels loop.c walks with the fast path) */
    for (side = 0; side < 3u; side++) {
        uint32_t lv;
        for (lv = 0; lv <= 2u; lv++) {
            subd_arena a;
            subd_mesh m, out;
            subd_diag d;
            uint32_t v;
            subd_arena_init(&a, t_work, sizeof t_work);
            if (!t_grid(&a, side, &m)) return;
            m.vert_tag[0] |= SUBD_VTAG_CORNER;
            m.vert_tag[3u * TG + 3u] |= SUBD_VTAG_CORNER;
            if (lv > 0u) {
                subd_loop_opts o;
                subd_loop_opts_default(&o);
                o.levels = lv;
                o.flags = SUBD_LOOP_ADJACENCY;
                if (!CHECK_OK(subd_loop(&a, &m, &o, &out, &d), &d)) return;
                m = out;
            }
            CHECK(t_fan_equal(&m) == m.num_verts);
            for (v = 0; v < m.num_verts; v++) {
                if (m.vert_tag[v] & SUBD_VTAG_BOUNDARY) nboundary++;
                else ninterior++;
            }
        }
    }
    CHECK(nboundary > 0u && ninterior > 0u);
}

static void topo_sharp_schemes(void)
{
    static uint32_t ref_cv[2048];
    uint32_t side, scheme;
    for (scheme = 0; scheme < 5u; scheme++) {
        subd_arena ra;
        subd_mesh rin;
        subd_diag d;
        const subd_real *ref = 0;
        uint32_t refn = 0;
        subd_arena_init(&ra, h_arena_buf, H_ARENA_BYTES); /* the reference's outputs */
        for (side = 0; side < 3u; side++) {
            subd_arena a;
            subd_mesh in, out;
            subd_real *pos = 0, *nrm = 0;
            const subd_real *got = 0;
            uint32_t n = 0;
            int st = SUBD_OK;
            subd_arena *use = side == 0u ? &ra : &a;
            subd_arena_init(&a, t_work, sizeof t_work);
            if (!t_grid(use, side, side == 0u ? &rin : &in)) return;
            if (side == 0u) in = rin;
            if (scheme == 0u) {
                subd_loop_opts o;
                o.levels = 2;
                o.boundary = SUBD_LOOP_BOUNDARY_PAPER;
                o.flags = 0;
                st = subd_loop(use, &in, &o, &out, &d);
                got = out.pos;
                n = 3u * out.num_verts;
            } else if (scheme == 1u) {
                subd_loop_limit_opts lim_o;
                subd_loop_limit_opts_default(&lim_o); /* paper rules, with normals */
                st = subd_loop_limit(use, &in, &lim_o, &pos, &nrm, &d);
                got = pos; /* positions then normals: one array of 6 V per call below */
                n = 3u * in.num_verts;
                if (st == SUBD_OK && side > 0u) CHECK(t_same(nrm, ref + n, n));
            } else if (scheme <= 3u) {
                subd_pia_opts o;
                subd_pia_result res;
                o.boundary = SUBD_LOOP_BOUNDARY_PAPER;
#if SUBD_FIXED
                o.tol = 4; /* LSB */
#else
                o.tol = 1e-4f;
#endif
                o.max_iter = 200;
                o.method = scheme == 2u ? SUBD_PIA_PAPER : SUBD_PIA_FAST;
                st = subd_pia(use, &in, &o, &pos, &res, &d);
                got = pos;
                n = 3u * in.num_verts;
            } else {
                subd_quasi48_opts o;
                o.steps = 3;
                o.boundary = SUBD_QUASI48_BOUNDARY_FIXED;
                o.flags = 0;
                o.len_bits = 0;
                st = subd_quasi48(use, &in, &o, &out, &d);
                got = out.pos;
                n = 3u * out.num_verts;
                if (st == SUBD_OK && CHECK(out.num_corners <= 2048u)) {
                    uint32_t c;
                    for (c = 0; c < out.num_corners; c++) {
                        if (side == 0u) ref_cv[c] = out.corner_vert[c];
                        else CHECK_EQ(out.corner_vert[c], ref_cv[c]);
                    }
                }
            }
            if (!CHECK_OK(st, &d)) return;
            if (side == 0u) {
                ref = got;
                refn = n;
                if (scheme == 1u) { /* keep positions and normals side by side */
                    subd_real *both = (subd_real *)subd_arena_alloc(&ra, 6u * (uint32_t)sizeof(subd_real) * in.num_verts);
                    if (!CHECK(both != 0)) return;
                    for (n = 0; n < 3u * in.num_verts; n++) {
                        both[n] = pos[n];
                        both[3u * in.num_verts + n] = nrm[n];
                    }
                    ref = both;
                }
            } else {
                CHECK_EQ(n, refn);
                if (!CHECK(t_same(got, ref, n))) {
                    h_str("  scheme ");
                    h_u32(scheme);
                    h_str(" side ");
                    h_u32(side);
                    h_nl();
                }
            }
        }
    }
}

const test_case suite_topo[] = {
    {"topo_ring_brute", topo_ring_brute},
    {"topo_patch_ring", topo_patch_ring},
    {"topo_has_rule", topo_has_rule},
    {"topo_sharp_rule", topo_sharp_rule},
    {"topo_loop_child_tables", topo_loop_child_tables},
    {"topo_sharp_schemes", topo_sharp_schemes},
    {"topo_fan_fast", topo_fan_fast},
    {"topo_loop_child_writers", topo_loop_child_writers},
    {0, 0}
};
