/* The README's firmware embedding example, extracted from README.md at build time
 * (build/gen/readme_example.c), so the documented code is compiled and run on every target. */
#include "harness.h"
#include "readme_example.c"

static void embed_readme_example(void)
{
    uint32_t faces = 0, used = 0, plan = 0;
    subd_diag d;
    CHECK_EQ(example_build_tetra(&faces, &used), SUBD_OK);
    CHECK_EQ(faces, 4);
    CHECK_EQ(subd_obj_plan(tetra_obj, sizeof tetra_obj - 1, &plan, &d), SUBD_OK);
    CHECK_EQ(used, plan);
    CHECK(plan <= sizeof arena_buf);
}

const test_case suite_embed[] = {
    {"embed_readme_example", embed_readme_example},
    {0, 0}
};
