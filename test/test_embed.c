/* SPDX-License-Identifier: MIT */
/* The README's firmware embedding example, extracted from README.md at build time
 * (build/gen/readme_example.c), so the documented code is compiled and run on every target. */
#include "harness.h"
#include "readme_example.c"

static void embed_readme_example(void)
{
    subd_mesh fine;
    subd_arena a;
    subd_mesh coarse;
    subd_diag d;
    subd_loop_opts o = {2, SUBD_LOOP_BOUNDARY_PAPER, 0};
    uint32_t read_plan, loop_plan;
    CHECK_EQ(example_subdivide(&fine), SUBD_OK);
    CHECK_EQ(fine.num_faces, 4u * 4u * 4u); /* F' = 4F per level */
    CHECK_EQ(fine.num_verts, 34);            /* V + E + (2E + 3F) = 4 + 6 + 24 */
    /* the buffer is big enough by the plans, computed independently here */
    CHECK_EQ(subd_obj_plan(tetra_obj, sizeof tetra_obj - 1, &read_plan, &d), SUBD_OK);
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    CHECK_EQ(subd_obj_read(&a, tetra_obj, sizeof tetra_obj - 1, &coarse, &d), SUBD_OK);
    CHECK_EQ(subd_loop_plan(&coarse, &o, &loop_plan, 0), SUBD_OK);
    CHECK(read_plan <= sizeof arena_buf);
    CHECK(subd_arena_mark(&a) + loop_plan <= sizeof arena_buf);
}

/* The README's streaming example: 6 levels of the tetrahedron, 4^6 * 4 triangles, in the
 * compile-time buffer, which equals the plan. */
static void embed_readme_stream(void)
{
    uint32_t n = 0, plan;
    subd_arena a;
    subd_mesh m;
    subd_diag d;
    subd_loop_opts o = {6, SUBD_LOOP_BOUNDARY_PAPER, 0};
    CHECK_EQ(example_stream(&n), SUBD_OK);
    CHECK_EQ(n, 4u * 4096u);
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    CHECK_EQ(subd_obj_read(&a, tetra_obj, sizeof tetra_obj - 1, &m, &d), SUBD_OK);
    CHECK_EQ(subd_loop_stream_plan(&m, &o, &plan, 0), SUBD_OK);
    CHECK_EQ(plan, sizeof stream_buf);
}

const test_case suite_embed[] = {
    {"embed_readme_example", embed_readme_example},
    {"embed_readme_stream", embed_readme_stream},
    {0, 0}
};
