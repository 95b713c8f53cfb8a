/* SPDX-License-Identifier: MIT */
/* One API shape (0.4.0): every plan call takes (in, opts, &bytes, diag) and fills diag as the
 * call it plans would: a triangle scheme's plan names the first polygon in diag.face (a quad
 * mesh whose first face is a quad), the status is in diag.status, bytes_needed stays 0 (a plan
 * needs no arena), a NULL diag is allowed and gives the same status; a success clears diag.
 * And the one failure exit: a failed call reports bytes_needed only with SUBD_ERR_NOMEM
 * (entry.h), checked here on calls that compute their need before they fail otherwise. */
#include "harness.h"
#include "corpus.h"
#include "subd_quasi48.h"
#include "subd_semireg48.h" /* the deprecated header name still works */

/* A quad then a triangle: the first non-triangle is face 0. */
static const char mixed_obj[] = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nf 1 2 3 4\nf 2 5 3\n";
static const char tri_obj[] = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n";

static int load(subd_arena *a, const char *txt, subd_mesh *m)
{
    subd_diag d;
    uint32_t n = 0;
    while (txt[n]) n++;
    return CHECK_EQ(subd_obj_read(a, txt, n, m, &d), SUBD_OK);
}

typedef int (*plan_fn)(const subd_mesh *in, subd_diag *d, uint32_t *bytes);

static int p_loop(const subd_mesh *in, subd_diag *d, uint32_t *b)
{
    subd_loop_opts o = {1, SUBD_LOOP_BOUNDARY_PAPER, 0};
    return subd_loop_plan(in, &o, b, d);
}
static int p_stream(const subd_mesh *in, subd_diag *d, uint32_t *b)
{
    subd_loop_opts o = {2, SUBD_LOOP_BOUNDARY_PAPER, 0};
    return subd_loop_stream_plan(in, &o, b, d);
}
static int p_limit(const subd_mesh *in, subd_diag *d, uint32_t *b)
{
    subd_loop_limit_opts o;
    subd_loop_limit_opts_default(&o);
    return subd_loop_limit_plan(in, &o, b, d);
}
static int p_pia(const subd_mesh *in, subd_diag *d, uint32_t *b)
{
    subd_pia_opts o;
    subd_pia_opts_default(&o);
    return subd_pia_plan(in, &o, b, d);
}
static int p_q48(const subd_mesh *in, subd_diag *d, uint32_t *b)
{
    subd_quasi48_opts o;
    subd_quasi48_opts_default(&o);
    return subd_quasi48_plan(in, &o, b, d);
}

static int p_sr48(const subd_mesh *in, subd_diag *d, uint32_t *b)
{
    subd_sr48_opts o = {2, 0};
    return subd_sr48_plan(in, &o, SUBD_SR48_CLUSTERS_UNKNOWN, b, d);
}

/* The defaults are valid options (each plan succeeds with them on a triangle mesh). */
static void plans_fill_diag(void)
{
    static const plan_fn plans[] = {p_loop, p_stream, p_limit, p_pia, p_q48, p_sr48};
    subd_arena a;
    subd_mesh mixed, tri;
    uint32_t k;
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    if (!load(&a, mixed_obj, &mixed) || !load(&a, tri_obj, &tri)) return;
    for (k = 0; k < sizeof plans / sizeof plans[0]; k++) {
        subd_diag d;
        uint32_t bytes = 12345u;
        d.face = 77u;
        d.bytes_needed = 99u;
        CHECK_EQ(plans[k](&mixed, &d, &bytes), SUBD_ERR_NOT_TRIANGLES);
        CHECK_EQ(d.status, SUBD_ERR_NOT_TRIANGLES);
        CHECK_EQ(d.face, 0);
        CHECK_EQ(d.bytes_needed, 0);
        CHECK_EQ(bytes, 12345u);                                          /* untouched */
        CHECK_EQ(plans[k](&mixed, 0, &bytes), SUBD_ERR_NOT_TRIANGLES);    /* diag optional */
        CHECK_EQ(plans[k](0, &d, &bytes), SUBD_ERR_PARAM);
        CHECK_EQ(d.status, SUBD_ERR_PARAM);
        CHECK_EQ(plans[k](&tri, &d, 0), SUBD_ERR_PARAM);
        d.face = 77u;
        CHECK_OK(plans[k](&tri, &d, &bytes), &d);
        CHECK_EQ(d.face, SUBD_NONE); /* cleared */
        CHECK(bytes > 0u);
    }
}

/* The limit options: unknown flags refused by plan and call; the normals pointer is needed
 * exactly with SUBD_LOOP_LIMIT_NORMALS; the plan without normals is smaller. */
static void limit_opts(void)
{
    subd_arena a;
    subd_mesh tri;
    subd_loop_limit_opts o;
    subd_real *pos = 0, *nrm = 0;
    subd_diag d;
    uint32_t with, without, mark;
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    if (!load(&a, tri_obj, &tri)) return;
    subd_loop_limit_opts_default(&o);
    CHECK_EQ(o.boundary, SUBD_LOOP_BOUNDARY_PAPER);
    CHECK_EQ(o.flags, SUBD_LOOP_LIMIT_NORMALS);
    subd_loop_limit_opts_default(0);
    if (!CHECK_OK(subd_loop_limit_plan(&tri, &o, &with, &d), &d)) return;
    o.flags = 0;
    if (!CHECK_OK(subd_loop_limit_plan(&tri, &o, &without, &d), &d)) return;
    CHECK(without < with);
    o.flags = 0x80u;
    CHECK_FAIL(subd_loop_limit_plan(&tri, &o, &with, &d), &d, SUBD_ERR_PARAM);
    mark = subd_arena_mark(&a);
    CHECK_FAIL(subd_loop_limit(&a, &tri, &o, &pos, &nrm, &d), &d, SUBD_ERR_PARAM);
    o.flags = SUBD_LOOP_LIMIT_NORMALS;
    CHECK_FAIL(subd_loop_limit(&a, &tri, &o, &pos, 0, &d), &d, SUBD_ERR_PARAM);
    CHECK_EQ(subd_arena_mark(&a), mark);
    CHECK(pos == 0);
    o.flags = 0;
    CHECK_OK(subd_loop_limit(&a, &tri, &o, &pos, 0, &d), &d);
    CHECK_EQ(subd_arena_mark(&a) - mark, without);
    CHECK(pos != 0);
}

/* A call that knows its need before it fails for another reason reports no need. */
static void failure_has_no_need(void)
{
    subd_arena a, small;
    subd_mesh tri;
    subd_loop_opts o = {1, SUBD_LOOP_BOUNDARY_PAPER, 0};
    subd_mesh out;
    subd_stream s;
    subd_diag d;
    uint8_t *buf;
    uint32_t plan;
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    if (!load(&a, tri_obj, &tri)) return;
    if (!CHECK_OK(subd_loop_plan(&tri, &o, &plan, &d), &d)) return;
    buf = (uint8_t *)subd_arena_alloc(&a, plan);
    if (!CHECK(buf != 0)) return;
    subd_arena_init(&small, buf, plan - 1u);
    CHECK_FAIL(subd_loop(&small, &tri, &o, &out, &d), &d, SUBD_ERR_NOMEM);
    CHECK_EQ(d.bytes_needed, plan);
    o.boundary = (subd_loop_boundary)9;
    CHECK_FAIL(subd_loop(&small, &tri, &o, &out, &d), &d, SUBD_ERR_PARAM);
    CHECK_EQ(d.bytes_needed, 0);
    CHECK_FAIL(subd_loop_stream_begin(&small, &tri, &o, &s, &d), &d, SUBD_ERR_PARAM);
    CHECK_EQ(d.bytes_needed, 0);
}

/* The 0.3 quasi 4-8 names still compile and mean the new ones (deprecated aliases). */
static void quasi48_old_names(void)
{
    subd_q48_opts o;
    subd_quasi48_opts n;
    subd_quasi48_opts_default(&o);
    subd_quasi48_opts_default(&n);
    CHECK(sizeof o == sizeof n);
    CHECK_EQ(o.steps, n.steps);
    CHECK_EQ((uint32_t)o.boundary, (uint32_t)SUBD_Q48_BOUNDARY_FIXED);
    CHECK_EQ((uint32_t)SUBD_Q48_BOUNDARY_NORMAL, (uint32_t)SUBD_QUASI48_BOUNDARY_NORMAL);
    CHECK_EQ(SUBD_Q48_NO_SMOOTH, SUBD_QUASI48_NO_SMOOTH);
    CHECK_EQ(SUBD_Q48_MAX_FACES(3u, 2u), SUBD_QUASI48_MAX_FACES(3u, 2u));
}

/* The 0.3 names of the semi-regular 4-8 types (subd_adapt*, SUBD_ADAPT_*, the header
 * subd_semireg48.h) still compile and mean the same (deprecated aliases, until 1.0). */
static void sr48_old_names(void)
{
    subd_adapt o;
    subd_sr48_adapt n;
    subd_adapt_report r;
    subd_adapt_fn fn = 0;
    CHECK(sizeof o == sizeof n);
    CHECK(sizeof r == sizeof(subd_sr48_adapt_report));
    CHECK(sizeof(subd_adapt_mode) == sizeof(subd_sr48_adapt_mode));
    CHECK(fn == (subd_sr48_adapt_fn)0);
    CHECK_EQ((uint32_t)SUBD_ADAPT_UNIFORM, (uint32_t)SUBD_SR48_ADAPT_UNIFORM);
    CHECK_EQ((uint32_t)SUBD_ADAPT_POINT, (uint32_t)SUBD_SR48_ADAPT_POINT);
    CHECK_EQ((uint32_t)SUBD_ADAPT_RAMP, (uint32_t)SUBD_SR48_ADAPT_RAMP);
    CHECK_EQ((uint32_t)SUBD_ADAPT_PLANE, (uint32_t)SUBD_SR48_ADAPT_PLANE);
    CHECK_EQ((uint32_t)SUBD_ADAPT_CALLBACK, (uint32_t)SUBD_SR48_ADAPT_CALLBACK);
    CHECK_EQ((uint32_t)SUBD_ADAPT_CHORD, (uint32_t)SUBD_SR48_ADAPT_CHORD);
}

const test_case suite_api[] = {
    {"quasi48_old_names", quasi48_old_names},
    {"sr48_old_names", sr48_old_names},
    {"plans_fill_diag", plans_fill_diag},
    {"limit_opts", limit_opts},
    {"failure_has_no_need", failure_has_no_need},
    {0, 0},
};
