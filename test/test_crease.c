/* SPDX-License-Identifier: MIT */
/* Crease tagging by dihedral angle, against angles known by construction. */
#include "harness.h"
#include "subd_loop.h"
#include "corpus.h"

static uint32_t count_crease_edges(const subd_mesh *m)
{
    uint32_t h, n = 0;
    for (h = 0; h < m->num_corners; h++)
        if ((m->edge_tag[h] & SUBD_ETAG_CREASE) && m->twin[h] != SUBD_NONE && h < m->twin[h]) n++;
    return n;
}

static void clear_creases(subd_mesh *m)
{
    uint32_t h;
    for (h = 0; h < m->num_corners; h++) m->edge_tag[h] &= (uint8_t)~SUBD_ETAG_CREASE;
}

static void crease_cube(void)
{
    const corpus_file *f = corpus_find("test/data/cube_quad.obj");
    subd_arena a;
    subd_mesh m;
    subd_diag d;
    if (!CHECK(f != 0)) return;
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    if (!CHECK_EQ(subd_obj_read(&a, f->data, f->len, &m, &d), SUBD_OK)) return;
    CHECK_EQ(subd_mesh_tag_crease_angle(&m, subd_cos_turns(30, 360)), 12); /* all 90 degree edges */
    CHECK_EQ(count_crease_edges(&m), 12);
    clear_creases(&m);
    CHECK_EQ(subd_mesh_tag_crease_angle(&m, subd_cos_turns(89, 360)), 12);
    clear_creases(&m);
    CHECK_EQ(subd_mesh_tag_crease_angle(&m, subd_cos_turns(91, 360)), 0);
    CHECK_EQ(subd_mesh_tag_crease_angle(&m, subd_cos_turns(179, 360)), 0);
}

static void crease_flat_grid(void)
{
    const corpus_file *f = corpus_find("test/data/grid_tri_8x8.obj");
    subd_arena a;
    subd_mesh m;
    subd_diag d;
    if (!CHECK(f != 0)) return;
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    if (!CHECK_EQ(subd_obj_read(&a, f->data, f->len, &m, &d), SUBD_OK)) return;
    CHECK_EQ(subd_mesh_tag_crease_angle(&m, subd_cos_turns(1, 360)), 0);
}

/* Two triangles folded along the x axis so that their normals are `deg` degrees apart;
 * thresholds one degree either side must tag / not tag the shared edge. */
static void crease_fold_angles(void)
{
    int32_t deg;
    for (deg = 5; deg <= 175; deg += 10) {
        subd_real pos[12];
        static const uint32_t idx[] = {0, 1, 2, 1, 0, 3};
        subd_face_list fl = {4, 0, 2, 0, idx, 0, 0, 0};
        subd_arena a;
        subd_mesh m;
        subd_diag d;
        uint32_t ovf = 0, k;
        for (k = 0; k < 12; k++) pos[k] = 0;
        pos[3] = subd_from_int(1, &ovf);                /* v1 = (1, 0, 0) on the fold axis */
        pos[7] = subd_from_int(1, &ovf);                /* v2 = (0, 1, 0) */
        pos[10] = subd_neg(subd_cos_turns(deg, 360), &ovf); /* v3 = (0, -cos, sin) */
        pos[11] = subd_sin_turns(deg, 360);
        fl.pos = pos;
        subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
        if (!CHECK_EQ(subd_mesh_build(&a, &fl, &m, &d), SUBD_OK)) return;
        CHECK_EQ(subd_mesh_tag_crease_angle(&m, subd_cos_turns(deg - 1, 360)), 1);
        clear_creases(&m);
        CHECK_EQ(subd_mesh_tag_crease_angle(&m, subd_cos_turns(deg + 1, 360)), 0);
        CHECK(ovf == 0);
    }
}


/* Issue 13: a mesh without adjacency tags nothing and returns 0 (it used to dereference
 * twin); a cosine limit outside [-1, 1] is clamped: > 1 tags every interior edge, < -1 none
 * (Q16.16 used to overflow int64 squaring it). */
static void crease_robust(void)
{
    subd_arena a;
    subd_mesh m, tri;
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    if (!h_tetra_no_adjacency(&a, &m, &tri)) return;
    CHECK_EQ(subd_mesh_tag_crease_angle(&m, h_int(2)), 6);
    clear_creases(&m);
#if SUBD_FIXED
    CHECK_EQ(subd_mesh_tag_crease_angle(&m, INT32_MAX), 6);
    clear_creases(&m);
    CHECK_EQ(subd_mesh_tag_crease_angle(&m, INT32_MIN), 0);
#else
    CHECK_EQ(subd_mesh_tag_crease_angle(&m, 3e38f), 6);
    clear_creases(&m);
    CHECK_EQ(subd_mesh_tag_crease_angle(&m, -3e38f), 0);
#endif
    CHECK_EQ(subd_mesh_tag_crease_angle(&m, h_int(-2)), 0);
    CHECK_EQ(subd_mesh_tag_crease_angle(0, 0), 0);
    CHECK_EQ(subd_mesh_tag_crease_angle(&tri, 0), 0);
}

const test_case suite_crease[] = {
    {"crease_cube", crease_cube},
    {"crease_flat_grid", crease_flat_grid},
    {"crease_fold_angles", crease_fold_angles},
    {"crease_robust", crease_robust},
    {0, 0}
};
