/* SPDX-License-Identifier: MIT */
/* libFuzzer target: every scheme on a small mesh decoded from the input bytes.
 *
 * The bytes choose a mesh (a template - tetrahedron, octahedron, grid, quad cube, fan, strip -
 * with perturbed positions, or a random face list that is often invalid), tags (creases,
 * corners, fixed vertices, reserved bits, crease angle) and the parameters of every scheme
 * (levels 1..3, boundary rule, flags, PIA, quasi 4-8 with its three boundary modes, semi-
 * regular 4-8 and an extraction, alpha order / kernel / angle / stiffness / tags: per point
 * for curves, per vertex (odd order) or per face (even order) for surfaces), including
 * out-of-range values. Each scheme runs with an arena of exactly its plan, of plan - 1 and
 * of a smaller size chosen by the input, and fuzz_check.c's checks apply: known status; on
 * failure arena mark, input mesh and input bytes unchanged; on success peak <= plan, guard
 * bytes intact, outputs validated. Also: an arena of the plan never gives SUBD_ERR_NOMEM;
 * the stream emits subd_loop's triangles bit for bit and nothing stays in its arena; PIA's
 * per-phase result adds up (iterations, vertex sets, max error); quasi 4-8 keeps its bounds
 * and input vertices, its normal mode gives the fixed mode's bits on a mesh in z = 0 and
 * commutes with a 90-degree rotation about z; equal alpha tags give the untagged bits.
 *
 * Length (~820 lines): one adapter per scheme (run + checks: Loop with its stream and limit,
 * PIA, quasi 4-8, semi-regular 4-8, alpha curves and surfaces) behind one entry, because one
 * input drives every scheme on the same decoded mesh; the decoder and the shared checks live
 * in fuzz_mesh.h and fuzz_check.c.
 *
 * FZ_AVOID_KNOWN (default 0) keeps the decoder away from bugs reported but not yet fixed; it
 * kept the cosh kernel's large angles out while their int64 overflow (issue 13) was open. */
#include "fuzz_check.h"
#include "fuzz_mesh.h"

#include <stdlib.h>
#include <string.h>

#ifndef FZ_AVOID_KNOWN
#define FZ_AVOID_KNOWN 0
#endif

/* ---------------------------------------------------------------- the input mesh */
static subd_mesh g_in;
static const subd_face_list *g_fl; /* g_in's face list */
static fz_snap g_in_snap, g_desc_snap, g_data_snap;

static void check_inputs(const char *call)
{
    fz_snap_check(&g_in_snap, call);
    fz_snap_check(&g_desc_snap, call);
    fz_snap_check(&g_data_snap, call);
}

/* Runs one call with arenas of plan, plan - 1 and plan * r / 256 bytes. run returns the
 * status; ok (may be NULL) validates the outputs after a success. */
typedef int (*run_fn)(void *ctx, subd_arena *a, subd_diag *d);
typedef void (*ok_fn)(void *ctx, subd_arena *a, int first);
static void run_sized(const char *call, uint32_t plan, run_fn run, ok_fn ok, void *ctx, uint8_t r, int extra)
{
    if (plan > FZ_MAX_ARENA)
        return;
    uint32_t sizes[3] = {plan, plan ? plan - 1u : 0u, (uint32_t)(((uint64_t)plan * r) >> 8)};
    uint32_t n = plan ? 3u : 1u;
    for (uint32_t i = 0; i < n; i++) {
        fz_arena fa;
        fz_arena_open(&fa, sizes[i]);
        subd_diag d;
        subd_diag_clear(&d);
        int st = run(ctx, &fa.a, &d);
        fz_status_known(st, extra, call);
        fz_arena_after(&fa, st, 0, plan, call);
        check_inputs(call);
        if (i == 0)
            FZ_CHECK(st != SUBD_ERR_NOMEM, call, st, plan); /* the plan is enough */
        if (st == SUBD_ERR_NOMEM)
            FZ_CHECK(d.bytes_needed > sizes[i] || d.bytes_needed == 0, call, d.bytes_needed, sizes[i]);
        if (st == SUBD_OK && ok)
            ok(ctx, &fa.a, i == 0);
        fz_arena_close(&fa);
    }
}

/* ---------------------------------------------------------------- Loop, stream, limit */
typedef struct loop_ctx {
    subd_loop_opts o;
    subd_mesh out;
    /* a copy of the plan-sized run's output, for the stream comparison */
    int have;
    uint32_t nf;
    subd_real *pos;
    uint32_t *cv;
} loop_ctx;

static int loop_run(void *x, subd_arena *a, subd_diag *d)
{
    loop_ctx *c = (loop_ctx *)x;
    return subd_loop(a, &g_in, &c->o, &c->out, d);
}
static void loop_ok(void *x, subd_arena *a, int first)
{
    loop_ctx *c = (loop_ctx *)x;
    (void)a;
    fz_validate_mesh(&c->out, (c->o.flags & SUBD_LOOP_ADJACENCY) != 0, "subd_loop output");
    FZ_CHECK(c->out.num_faces == g_in.num_faces << (2u * c->o.levels), "subd_loop faces", c->out.num_faces, 0);
    if (first) {
        c->have = 1;
        c->nf = c->out.num_faces;
        c->pos = (subd_real *)malloc((size_t)c->out.num_verts * 3u * sizeof(subd_real));
        c->cv = (uint32_t *)malloc((size_t)c->out.num_corners * 4u);
        memcpy(c->pos, c->out.pos, (size_t)c->out.num_verts * 3u * sizeof(subd_real));
        memcpy(c->cv, c->out.corner_vert, (size_t)c->out.num_corners * 4u);
    }
}

typedef struct stream_ctx {
    subd_loop_opts o;
    const loop_ctx *loop; /* subd_loop's output with the same levels and rule, or NULL */
    uint32_t count, stop_at;
} stream_ctx;

static int stream_tri(void *x, const subd_loop_tri *t)
{
    stream_ctx *c = (stream_ctx *)x;
    fz_check_finite(&t->pos[0][0], 9, "stream triangle");
    fz_check_finite(&t->normal[0][0], 9, "stream normal");
    if (c->loop) {
        FZ_CHECK(c->count < c->loop->nf, "stream: more triangles than subd_loop", c->count, c->loop->nf);
        for (uint32_t k = 0; k < 3; k++) {
            uint32_t v = c->loop->cv[3u * c->count + k];
            FZ_CHECK(memcmp(t->pos[k], c->loop->pos + 3u * v, 3u * sizeof(subd_real)) == 0,
                     "stream = subd_loop bit for bit", c->count, k);
        }
    }
    c->count++;
    return c->count == c->stop_at ? 7 : 0;
}
static int stream_run(void *x, subd_arena *a, subd_diag *d)
{
    stream_ctx *c = (stream_ctx *)x;
    subd_loop_sink s = {stream_tri, c};
    c->count = 0;
    int st = subd_loop_stream(a, &g_in, &c->o, &s, d);
    FZ_CHECK(a->used == 0, "subd_loop_stream leaves nothing in the arena", a->used, st);
    if (st == 7)
        FZ_CHECK(c->count == c->stop_at, "stream stop", c->count, c->stop_at);
    else if (st != SUBD_OK)
        FZ_CHECK(st < 0, "stream status", st, 0);
    return st;
}
static void stream_ok(void *x, subd_arena *a, int first)
{
    stream_ctx *c = (stream_ctx *)x;
    (void)a, (void)first;
    FZ_CHECK(c->count == g_in.num_faces << (2u * c->o.levels), "stream triangle count", c->count, g_in.num_faces);
}

typedef struct limit_ctx {
    subd_loop_boundary b;
    int normals;
    subd_real *pos, *nrm;
} limit_ctx;
static int limit_run(void *x, subd_arena *a, subd_diag *d)
{
    limit_ctx *c = (limit_ctx *)x;
    return subd_loop_limit(a, &g_in, &(subd_loop_limit_opts){c->b, c->normals ? SUBD_LOOP_LIMIT_NORMALS : 0u}, &c->pos, c->normals ? &c->nrm : NULL, d);
}
static void limit_ok(void *x, subd_arena *a, int first)
{
    limit_ctx *c = (limit_ctx *)x;
    (void)a, (void)first;
    fz_check_finite(c->pos, 3u * g_in.num_verts, "subd_loop_limit pos");
    if (c->normals)
        fz_check_finite(c->nrm, 3u * g_in.num_verts, "subd_loop_limit normals");
}

/* ---------------------------------------------------------------- PIA */
typedef struct pia_ctx {
    subd_pia_opts o;
    subd_real *pos;
    subd_pia_result r;
} pia_ctx;
static int pia_run(void *x, subd_arena *a, subd_diag *d)
{
    pia_ctx *c = (pia_ctx *)x;
    return subd_pia(a, &g_in, &c->o, &c->pos, &c->r, d);
}
static void pia_ok(void *x, subd_arena *a, int first)
{
    pia_ctx *c = (pia_ctx *)x;
    (void)a, (void)first;
    fz_check_finite(c->pos, 3u * g_in.num_verts, "subd_pia pos");
    const subd_pia_result *r = &c->r;
    FZ_CHECK(r->iterations <= c->o.max_iter, "subd_pia iterations", r->iterations, c->o.max_iter);
    /* the per-phase result (subd_loop.h, subd_pia_phase): the phases' iterations add up;
     * boundary = the SUBD_VTAG_BOUNDARY vertices, interior = every other vertex (counted
     * here from the input's tags); each error is finite and >= 0, and the overall max is
     * the max over the two sets; a closed mesh has an empty boundary phase */
    FZ_CHECK(r->boundary.iterations + r->interior.iterations == r->iterations, "subd_pia phase iterations",
             r->boundary.iterations, r->interior.iterations);
    uint32_t nb = 0;
    for (uint32_t v = 0; v < g_in.num_verts; v++)
        nb += (g_in.vert_tag[v] & SUBD_VTAG_BOUNDARY) ? 1u : 0u;
    FZ_CHECK(r->boundary.verts == nb, "subd_pia boundary verts", r->boundary.verts, nb);
    FZ_CHECK(r->interior.verts == g_in.num_verts - nb, "subd_pia interior verts", r->interior.verts, g_in.num_verts);
    const subd_real e[6] = {r->max_err, r->mean_err, r->boundary.max_err, r->boundary.mean_err,
                            r->interior.max_err, r->interior.mean_err};
    fz_check_finite(e, 6u, "subd_pia errors");
    for (uint32_t k = 0; k < 6u; k++)
        FZ_CHECK(e[k] >= 0, "subd_pia error >= 0", k, subd_real_bits(e[k]));
    subd_real mx = r->boundary.max_err > r->interior.max_err ? r->boundary.max_err : r->interior.max_err;
    FZ_CHECK(r->max_err == mx, "subd_pia max_err = max of the phases", subd_real_bits(r->max_err), subd_real_bits(mx));
    FZ_CHECK(r->converged == (r->max_err <= c->o.tol), "subd_pia converged", r->converged, subd_real_bits(r->max_err));
    if (nb == 0u)
        FZ_CHECK(r->boundary.max_err == 0 && r->boundary.mean_err == 0, "subd_pia empty boundary errors", 0, 0);
    if (g_in.num_boundary_edges == 0u)
        FZ_CHECK(r->boundary.iterations == 0u && nb == 0u, "subd_pia closed: empty boundary phase",
                 r->boundary.iterations, nb);
}

/* ---------------------------------------------------------------- quasi 4-8 */
typedef struct q48_ctx {
    subd_quasi48_opts o;
    subd_mesh out;
} q48_ctx;
static int q48_run(void *x, subd_arena *a, subd_diag *d)
{
    q48_ctx *c = (q48_ctx *)x;
    return subd_quasi48(a, &g_in, &c->o, &c->out, d);
}
/* -x does not fit (Q16.16 INT32_MIN; float32 negation is exact) */
static int neg_overflows(subd_real x)
{
#if SUBD_FIXED
    return x == INT32_MIN;
#else
    (void)x;
    return 0;
#endif
}

/* subd_quasi48 on `in` with c's options but boundary mode b, in an arena of its plan; the
 * output is copied to malloc'd arrays (*pos, *cv; free them) and the status returned. */
static int q48_again(const q48_ctx *c, const subd_mesh *in, subd_quasi48_boundary b, subd_mesh *out, subd_real **pos,
                     uint32_t **cv)
{
    subd_quasi48_opts o = c->o;
    o.boundary = b;
    uint32_t plan = 0;
    int st = subd_quasi48_plan(in, &o, &plan, 0);
    FZ_CHECK(st == SUBD_OK, "subd_quasi48_plan (again)", st, b);
    fz_arena fa;
    fz_arena_open(&fa, plan);
    subd_diag d;
    st = subd_quasi48(&fa.a, in, &o, out, &d);
    fz_status_known(st, 0, "subd_quasi48 (again)");
    fz_arena_after(&fa, st, 0, plan, "subd_quasi48 (again)");
    *pos = NULL, *cv = NULL;
    if (st == SUBD_OK) {
        *pos = (subd_real *)malloc((size_t)out->num_verts * 3u * sizeof(subd_real) + 1u);
        *cv = (uint32_t *)malloc((size_t)out->num_corners * 4u + 1u);
        FZ_CHECK(*pos != NULL && *cv != NULL, "malloc", 0, 0);
        memcpy(*pos, out->pos, (size_t)out->num_verts * 3u * sizeof(subd_real));
        memcpy(*cv, out->corner_vert, (size_t)out->num_corners * 4u);
        out->pos = NULL, out->corner_vert = NULL; /* in the closed arena */
    }
    fz_arena_close(&fa);
    return st;
}

static void q48_ok(void *x, subd_arena *a, int first)
{
    q48_ctx *c = (q48_ctx *)x;
    const subd_mesh *o = &c->out;
    (void)a;
    fz_validate_mesh(o, 1, "subd_quasi48 output");
    /* the bounds of subd_quasi48.h; vertex i of the input is vertex i of the output, and
     * without smoothing nothing moves */
    FZ_CHECK(o->num_faces <= SUBD_QUASI48_MAX_FACES(g_in.num_faces, c->o.steps), "quasi48 face bound", o->num_faces, 0);
    FZ_CHECK(o->num_verts <= SUBD_QUASI48_MAX_VERTS(g_in.num_verts, g_in.num_faces, c->o.steps), "quasi48 vertex bound",
             o->num_verts, 0);
    FZ_CHECK(o->num_verts >= g_in.num_verts, "quasi48 keeps the input vertices", o->num_verts, g_in.num_verts);
    if (c->o.flags & SUBD_QUASI48_NO_SMOOTH)
        FZ_CHECK(memcmp(o->pos, g_in.pos, (size_t)g_in.num_verts * 3u * sizeof(subd_real)) == 0,
                 "quasi48 NO_SMOOTH keeps the input positions", 0, 0);
    if (!first || c->o.boundary != SUBD_QUASI48_BOUNDARY_NORMAL)
        return;
    subd_mesh o2;
    subd_real *pos2;
    uint32_t *cv2;
    /* normal mode: a planar mesh in z = 0 gives bit for bit the FIXED result */
    int planar = 1;
    for (uint32_t v = 0; v < g_in.num_verts; v++)
        planar &= subd_real_bits(g_in.pos[3u * v + 2u]) == 0u;
    if (planar && !(c->o.flags & SUBD_QUASI48_NO_SMOOTH)) {
        int st = q48_again(c, &g_in, SUBD_QUASI48_BOUNDARY_FIXED, &o2, &pos2, &cv2);
        FZ_CHECK(st == SUBD_OK, "quasi48 planar: FIXED succeeds too", st, 0);
        FZ_CHECK(o2.num_verts == o->num_verts && o2.num_corners == o->num_corners, "quasi48 planar counts",
                 o2.num_verts, o->num_verts);
        FZ_CHECK(memcmp(cv2, o->corner_vert, (size_t)o->num_corners * 4u) == 0, "quasi48 planar faces", 0, 0);
        FZ_CHECK(memcmp(pos2, o->pos, (size_t)o->num_verts * 3u * sizeof(subd_real)) == 0,
                 "quasi48 planar NORMAL = FIXED bit for bit", 0, 0);
        free(pos2);
        free(cv2);
    }
    /* normal mode: a rotation by 90 degrees about z, (x, y) -> (-y, x), maps the output (the
     * same faces, rotated positions; compared as values: -0 == +0) */
    for (uint32_t i = 0; i < 3u * g_in.num_verts; i++)
        if (!subd_real_is_finite(g_in.pos[i]) || neg_overflows(g_in.pos[i]))
            return;
    static subd_real rp[3 * MAXV];
    for (uint32_t v = 0; v < g_in.num_verts; v++) {
        rp[3u * v] = -g_in.pos[3u * v + 1u];
        rp[3u * v + 1u] = g_in.pos[3u * v];
        rp[3u * v + 2u] = g_in.pos[3u * v + 2u];
    }
    subd_face_list fl = *g_fl;
    fl.pos = rp;
    uint32_t plan = 0;
    FZ_CHECK(subd_mesh_plan(&fl, &plan) == SUBD_OK, "quasi48 rotated plan", 0, 0);
    fz_arena fa;
    fz_arena_open(&fa, plan);
    subd_mesh rin;
    subd_diag d;
    int st = subd_mesh_build(&fa.a, &fl, &rin, &d);
    FZ_CHECK(st == SUBD_OK, "quasi48 rotated input builds", st, 0);
    FZ_CHECK(rin.num_corners == g_in.num_corners && rin.num_verts == g_in.num_verts, "rotated counts", 0, 0);
    memcpy(rin.vert_tag, g_in.vert_tag, g_in.num_verts); /* the same tags (crease angle: geometric) */
    memcpy(rin.edge_tag, g_in.edge_tag, g_in.num_corners);
    st = q48_again(c, &rin, SUBD_QUASI48_BOUNDARY_NORMAL, &o2, &pos2, &cv2);
    FZ_CHECK(st == SUBD_OK, "quasi48 rotated: succeeds too", st, 0);
    FZ_CHECK(o2.num_verts == o->num_verts && o2.num_corners == o->num_corners, "quasi48 rotated counts",
             o2.num_verts, o->num_verts);
    FZ_CHECK(memcmp(cv2, o->corner_vert, (size_t)o->num_corners * 4u) == 0, "quasi48 rotated faces", 0, 0);
    for (uint32_t v = 0; v < o->num_verts; v++) {
        const subd_real *p = o->pos + 3u * v, *q = pos2 + 3u * v;
        FZ_CHECK(q[0] == -p[1] && q[1] == p[0] && q[2] == p[2], "quasi48 NORMAL: rotation about z", v,
                 subd_real_bits(q[0]) ^ subd_real_bits(-p[1]));
    }
    free(pos2);
    free(cv2);
    fz_arena_close(&fa);
}

/* ---------------------------------------------------------------- semi-regular 4-8 */
static uint8_t g_cb_level;
/* Not monotone (a hash of the region box): the extraction must still give a conforming cut
 * (forced splits); only a monotone callback makes it the stream's. */
static uint32_t adapt_cb(void *ctx, const subd_real *lo, const subd_real *hi)
{
    (void)ctx;
    uint32_t h = subd_real_bits(lo[0]) ^ subd_real_bits(hi[1]) * 3u ^ subd_real_bits(hi[2]) * 7u;
    return (h + g_cb_level) % 6u;
}

typedef struct ext_ctx {
    const subd_sr48 *h;
    subd_sr48_adapt ad;
    subd_mesh out;
    subd_sr48_adapt_report rep;
} ext_ctx;
static int ext_run(void *x, subd_arena *a, subd_diag *d)
{
    ext_ctx *c = (ext_ctx *)x;
    return subd_sr48_extract(a, c->h, &c->ad, &c->out, &c->rep, d);
}
static void ext_ok(void *x, subd_arena *a, int first)
{
    ext_ctx *c = (ext_ctx *)x;
    (void)a, (void)first;
    fz_validate_mesh(&c->out, 1, "subd_sr48_extract output");
    FZ_CHECK(c->rep.faces == c->out.num_faces, "extract report", c->rep.faces, c->out.num_faces);
}

typedef struct sr48_ctx {
    subd_sr48_opts o;
    subd_sr48 out;
    ext_ctx ext;
    uint8_t r;
} sr48_ctx;
static int sr48_run(void *x, subd_arena *a, subd_diag *d)
{
    sr48_ctx *c = (sr48_ctx *)x;
    return subd_sr48_build(a, &g_in, &c->o, &c->out, d);
}
static void sr48_ok(void *x, subd_arena *a, int first)
{
    sr48_ctx *c = (sr48_ctx *)x;
    (void)a;
    const subd_sr48 *h = &c->out;
    FZ_CHECK(h->num_tris == h->level_tri[h->steps + 1u], "sr48 counts", h->num_tris, 0);
    for (uint32_t i = 0; i < 3u * h->num_tris; i++)
        FZ_CHECK(h->tri_vert[i] < h->num_verts, "sr48 tri_vert", i, h->tri_vert[i]);
    fz_check_finite(h->pos, 3u * h->num_verts, "sr48 pos");
    if (!first)
        return;
    c->ext.h = h;
    uint32_t plan = 0;
    int st = subd_sr48_extract_plan(h, &c->ext.ad, &plan, 0);
    fz_status_known(st, 0, "subd_sr48_extract_plan");
    if (st == SUBD_OK)
        run_sized("subd_sr48_extract", plan, ext_run, ext_ok, &c->ext, c->r, 0);
}

/* ---------------------------------------------------------------- alpha */
/* Tags of the alpha calls (subd_alpha_opts.tag_num): curves one per point, surfaces one per
 * vertex (odd order) or per face (even order). Static, bounded by the decoded mesh. */
#define MAXT (MAXV > MAXF ? MAXV : MAXF)
static int32_t g_ctags[MAXT], g_stags[MAXT];

typedef struct curve_ctx {
    uint32_t m;
    int closed;
    int uniform; /* every tag equal: the result must be the untagged one with that alpha */
    subd_alpha_opts o;
    uint32_t points;
    subd_alpha_curve_out out;
} curve_ctx;
static int curve_run(void *x, subd_arena *a, subd_diag *d)
{
    curve_ctx *c = (curve_ctx *)x;
    return subd_alpha_curve(a, g_in.pos, c->m, c->closed, &c->o, &c->out, d);
}
/* The curve stream (subd_alpha_curve_stream) against subd_alpha_curve's points: every point
 * the uniform stream emits has the bits of the same index (ids 0, 1, ...). */
typedef struct curve_cmp {
    const subd_alpha_curve_out *ref;
    uint32_t n, bad;
} curve_cmp;
static int curve_cmp_point(void *x, const subd_point *p)
{
    curve_cmp *k = (curve_cmp *)x;
    if (p->id != k->n || k->n >= k->ref->num_points ||
        memcmp(p->pos, k->ref->pos + 3u * k->n, 3u * sizeof(subd_real)) != 0)
        k->bad++;
    k->n++;
    return 0;
}
static void curve_stream_check(const curve_ctx *c)
{
    uint32_t plan = 0;
    int st = subd_alpha_curve_stream_plan(c->m, c->closed, &c->o, 0, &plan);
    FZ_CHECK(st == SUBD_OK, "alpha curve ok -> stream plan ok", st, c->m);
    if (st != SUBD_OK || plan > FZ_MAX_ARENA)
        return;
    fz_arena fa;
    fz_arena_open(&fa, plan);
    curve_cmp k = {&c->out, 0, 0};
    subd_point_sink sk = {curve_cmp_point, &k};
    subd_diag d;
    st = subd_alpha_curve_stream(&fa.a, g_in.pos, c->m, c->closed, &c->o, 0, &sk, &d);
    fz_arena_after(&fa, st, 0, plan, "subd_alpha_curve_stream");
    FZ_CHECK(st == SUBD_OK, "alpha curve ok -> stream ok", st, plan);
    FZ_CHECK(k.n == c->out.num_points && k.bad == 0, "alpha curve stream = subd_alpha_curve bit for bit", k.n, k.bad);
    fz_arena_close(&fa);
}

static void curve_ok(void *x, subd_arena *a, int first)
{
    curve_ctx *c = (curve_ctx *)x;
    (void)a;
    FZ_CHECK(c->out.num_points == c->points, "alpha curve points", c->out.num_points, c->points);
    fz_check_finite(c->out.pos, 3u * c->out.num_points, "alpha curve pos");
    if (first)
        curve_stream_check(c);
    if (!first || !c->uniform)
        return;
    /* "Equal tags give exactly the uniform result" (subd_alpha.h) */
    curve_ctx u = *c;
    u.o.tag_num = NULL;
    u.o.alpha_num = c->o.tag_num[0];
    uint32_t plan = 0, pts = 0;
    int st = subd_alpha_curve_plan(u.m, u.closed, &u.o, &plan, &pts);
    FZ_CHECK(st == SUBD_OK && pts == c->points, "alpha curve untagged plan", st, pts);
    fz_arena fa;
    fz_arena_open(&fa, plan);
    subd_diag d;
    st = subd_alpha_curve(&fa.a, g_in.pos, u.m, u.closed, &u.o, &u.out, &d);
    FZ_CHECK(st == SUBD_OK, "alpha curve: equal tags ok -> untagged ok", st, u.o.alpha_num);
    FZ_CHECK(u.out.num_points == c->out.num_points && u.out.continuity == c->out.continuity,
             "alpha curve equal tags: counts", u.out.num_points, c->out.num_points);
    FZ_CHECK(memcmp(u.out.pos, c->out.pos, (size_t)c->out.num_points * 3u * sizeof(subd_real)) == 0,
             "alpha curve: equal tags = untagged bit for bit", c->out.num_points, u.o.alpha_num);
    fz_arena_close(&fa);
}

typedef struct surf_ctx {
    subd_alpha_opts o;
    int uniform;
    subd_mesh out;
    subd_alpha_surface_info info;
} surf_ctx;
static int surf_run(void *x, subd_arena *a, subd_diag *d)
{
    surf_ctx *c = (surf_ctx *)x;
    return subd_alpha_surface(a, &g_in, &c->o, &c->out, &c->info, d);
}
static void surf_ok(void *x, subd_arena *a, int first)
{
    surf_ctx *c = (surf_ctx *)x;
    (void)a;
    fz_validate_mesh(&c->out, 1, "subd_alpha_surface output");
    if (!first || !c->uniform)
        return;
    /* "equal tags reproduce the untagged result bit for bit" (subd_alpha.h) */
    surf_ctx u = *c;
    u.o.tag_num = NULL;
    u.o.alpha_num = c->o.tag_num[0];
    uint32_t plan = 0;
    int st = subd_alpha_surface_plan(&g_in, &u.o, &plan, 0);
    FZ_CHECK(st == SUBD_OK, "alpha surface untagged plan", st, 0);
    fz_arena fa;
    fz_arena_open(&fa, plan);
    subd_diag d;
    st = subd_alpha_surface(&fa.a, &g_in, &u.o, &u.out, &u.info, &d);
    FZ_CHECK(st == SUBD_OK, "alpha surface: equal tags ok -> untagged ok", st, u.o.alpha_num);
    const subd_mesh *p = &c->out, *q = &u.out;
    FZ_CHECK(q->num_verts == p->num_verts && q->num_faces == p->num_faces && q->num_corners == p->num_corners &&
                 u.info.continuity == c->info.continuity,
             "alpha surface equal tags: counts", q->num_corners, p->num_corners);
    FZ_CHECK(memcmp(q->face_start, p->face_start, ((size_t)p->num_faces + 1u) * 4u) == 0 &&
                 memcmp(q->corner_vert, p->corner_vert, (size_t)p->num_corners * 4u) == 0,
             "alpha surface equal tags: faces", 0, 0);
    FZ_CHECK(memcmp(q->pos, p->pos, (size_t)p->num_verts * 3u * sizeof(subd_real)) == 0,
             "alpha surface: equal tags = untagged bit for bit", p->num_verts, u.o.alpha_num);
    fz_arena_close(&fa);
}

/* The options; tags (one per vertex for odd order, nt_even for even order) with
 * probability 1/4: small numerators, sometimes all equal (*uniform), sometimes one at or
 * beyond +-SUBD_ALPHA_MAX_NUM (the error path). */
static void alpha_params(cur *c, subd_alpha_opts *o, int32_t *tags, uint32_t nt_odd, uint32_t nt_even, int *uniform)
{
    subd_alpha_opts_default(o);
    *uniform = 0;
    uint8_t b = u8(c);
    o->order = 2u + b % 8u;
    if (b >= 248u)
        o->order = b & 1u ? 1u : SUBD_ALPHA_MAX_ORDER + 1u;
    o->levels = u8(c) % 4u;
    o->kernel = u8(c) % 5u;
    o->alpha_num = s8(c);
    o->alpha_den = 1 + (int32_t)(u8(c) % 24u);
    uint8_t e = u8(c);
    if (e == 0xffu)
        o->alpha_num = SUBD_ALPHA_MAX_NUM;
    else if (e == 0xfeu)
        o->alpha_den = 0;
    else if (e == 0xfdu)
        o->alpha_den = INT32_MAX >> 2;
#if FZ_AVOID_KNOWN
    /* was known (issue 13, fixed): cosh of a large angle overflowed int64 */
    if (o->kernel == SUBD_ALPHA_COSH) {
        o->alpha_num %= 2;
        if (o->alpha_den < 4)
            o->alpha_den = 4;
    }
#endif
    int8_t s = s8(c);
#if SUBD_FIXED
    o->stiffness = (subd_real)s * 2048; /* -4 .. 4 in steps of 1/32 */
#else
    o->stiffness = (float)s / 32.0f;
#endif
    uint8_t tm = u8(c);
    uint32_t ntags = (o->order & 1u) ? nt_odd : nt_even;
    if (tm < 64u && ntags) {
        for (uint32_t i = 0; i < ntags; i++)
            tags[i] = s8(c);
        if (tm < 8u || tm >= 56u) { /* all equal: alpha_num or the first tag */
            int32_t t = tm < 8u ? o->alpha_num : tags[0];
            for (uint32_t i = 0; i < ntags; i++)
                tags[i] = t;
            *uniform = 1;
        } else if (tm < 16u) { /* one extreme tag: valid at +-MAX_NUM, invalid beyond */
            static const int32_t ex[6] = {SUBD_ALPHA_MAX_NUM, -SUBD_ALPHA_MAX_NUM, SUBD_ALPHA_MAX_NUM + 1,
                                          -SUBD_ALPHA_MAX_NUM - 1, INT32_MAX, INT32_MIN};
            uint8_t w = u8(c);
            tags[w % ntags] = ex[(w >> 5) % 6u];
        } else if (tm < 24u) { /* large tags: big angles (cosh/poly overflow) */
            for (uint32_t i = 0; i < ntags; i++)
                tags[i] *= (int32_t)1 << ((tm & 7u) * 3u);
        }
        o->tag_num = tags;
    }
}

/* ---------------------------------------------------------------- the entry */
int FUZZ_ENTRY(const uint8_t *data, size_t size)
{
    if (size > 4096)
        return 0;
    cur c = {data, size, 0};
    fz_snap_take(&g_data_snap, data, size);
    fz_decoded dm;
    fz_decode_mesh(&c, &dm);
    subd_face_list fl;
    memset(&fl, 0, sizeof fl);
    fl.num_verts = dm.nv;
    fl.pos = dm.pos;
    fl.num_faces = dm.nf;
    fl.face_size = dm.fsize;
    fl.index = dm.idx;
    g_fl = &fl;

    /* the builder itself, with arenas of plan, plan - 1 and smaller */
    uint32_t plan = 0;
    int st = subd_mesh_plan(&fl, &plan);
    fz_status_known(st, 0, "subd_mesh_plan");
    if (st != SUBD_OK || plan > FZ_MAX_ARENA) {
        fz_snap_free(&g_data_snap);
        return 0;
    }
    uint8_t r = u8(&c);
    fz_arena in_arena;
    int built = 0;
    for (uint32_t i = 0; i < 3u && !built; i++) {
        uint32_t sz = i == 0 ? plan : i == 1 ? (plan ? plan - 1u : 0u) : (uint32_t)(((uint64_t)plan * r) >> 8);
        fz_arena fa;
        fz_arena_open(&fa, sz);
        subd_diag d;
        memset(&g_in, 0x5A, sizeof g_in);
        subd_mesh m0 = g_in;
        st = subd_mesh_build(&fa.a, &fl, &g_in, &d);
        fz_status_known(st, 0, "subd_mesh_build");
        fz_arena_after(&fa, st, 0, plan, "subd_mesh_build");
        fz_snap_check(&g_data_snap, "subd_mesh_build");
        if (st != SUBD_OK) {
            FZ_CHECK(memcmp(&g_in, &m0, sizeof m0) == 0, "subd_mesh_build: *out untouched", st, 0);
            FZ_CHECK(i > 0 || st != SUBD_ERR_NOMEM, "subd_mesh_build plan", st, plan);
            fz_arena_close(&fa);
            if (i == 0)
                break; /* invalid input: every size fails the same way */
            continue;
        }
        fz_validate_mesh(&g_in, 1, "subd_mesh_build");
        if (i == 0) {
            in_arena = fa; /* keep the plan-sized build as the schemes' input */
            built = 1;
        } else {
            fz_arena_close(&fa);
        }
    }
    if (!built) {
        fz_snap_free(&g_data_snap);
        return 0;
    }

    /* tags */
    uint32_t ntag = u8(&c) % 8u;
    for (uint32_t i = 0; i < ntag; i++) {
        uint8_t k = u8(&c), x = u8(&c);
        switch (k % 6u) {
        case 0:
        case 1:
            if (g_in.num_corners)
                subd_edge_tag_set(&g_in, x % g_in.num_corners, SUBD_ETAG_CREASE);
            break;
        case 2:
            g_in.vert_tag[x % g_in.num_verts] |= SUBD_VTAG_CORNER;
            break;
        case 3:
            g_in.vert_tag[x % g_in.num_verts] |= SUBD_VTAG_FIXED;
            break;
        case 4:
            if (x < 16u)
                g_in.vert_tag[x % g_in.num_verts] |= 0x40u; /* reserved: limit and PIA refuse it */
            else if (g_in.num_corners)
                subd_edge_tag_clear(&g_in, x % g_in.num_corners, SUBD_ETAG_CREASE);
            break;
        default:
            (void)subd_mesh_tag_crease_angle(&g_in, subd_cos_turns((int32_t)(x % 64u), 64));
            break;
        }
    }
    fz_snap_take(&g_in_snap, in_arena.block, in_arena.a.used);
    fz_snap_take(&g_desc_snap, &g_in, sizeof g_in);

    /* Loop */
    loop_ctx lc;
    memset(&lc, 0, sizeof lc);
    lc.o.levels = 1u + u8(&c) % 3u;
    uint8_t b = u8(&c);
    lc.o.boundary = (subd_loop_boundary)(b < 250u ? b % 2u : 2u + (b & 1u));
    uint8_t fb = u8(&c);
    lc.o.flags = fb < 240u ? fb % 2u : fb;
    if (u8(&c) == 0xffu)
        lc.o.levels = u8(&c) & 1u ? 0u : SUBD_MAX_LEVELS + 1u;
    st = subd_loop_plan(&g_in, &lc.o, &plan, 0);
    fz_status_known(st, 0, "subd_loop_plan");
    check_inputs("subd_loop_plan");
    if (st == SUBD_OK)
        run_sized("subd_loop", plan, loop_run, loop_ok, &lc, u8(&c), 0);

    /* Loop stream (same levels and rule) */
    stream_ctx sc;
    memset(&sc, 0, sizeof sc);
    sc.o = lc.o;
    uint8_t sf = u8(&c);
    sc.o.flags = sf < 240u ? (sf & 1u) * SUBD_LOOP_STREAM_LIMIT : sf;
    sc.stop_at = u8(&c) < 32u ? 1u + u8(&c) : 0u;
    sc.loop = (lc.have && sc.o.flags == 0) ? &lc : NULL;
    st = subd_loop_stream_plan(&g_in, &sc.o, &plan, 0);
    fz_status_known(st, 0, "subd_loop_stream_plan");
    check_inputs("subd_loop_stream_plan");
    if (st == SUBD_OK)
        run_sized("subd_loop_stream", plan, stream_run, stream_ok, &sc, u8(&c), 7);
    free(lc.pos);
    free(lc.cv);

    /* Loop limit */
    limit_ctx lim;
    memset(&lim, 0, sizeof lim);
    lim.b = lc.o.boundary;
    lim.normals = u8(&c) & 1u;
    st = subd_loop_limit_plan(&g_in, &(subd_loop_limit_opts){lim.b, (lim.normals) ? SUBD_LOOP_LIMIT_NORMALS : 0u}, &plan, 0);
    fz_status_known(st, 0, "subd_loop_limit_plan");
    check_inputs("subd_loop_limit_plan");
    if (st == SUBD_OK)
        run_sized("subd_loop_limit", plan, limit_run, limit_ok, &lim, u8(&c), 0);

    /* PIA */
    pia_ctx pc;
    memset(&pc, 0, sizeof pc);
    pc.o.boundary = lc.o.boundary;
    uint8_t tb = u8(&c);
#if SUBD_FIXED
    pc.o.tol = (subd_real)tb * 64;
#else
    pc.o.tol = (float)tb / 256.0f;
#endif
    pc.o.max_iter = u8(&c) % 9u;
    pc.o.method = (subd_pia_method)(u8(&c) % 3u);
    st = subd_pia_plan(&g_in, &pc.o, &plan, 0);
    fz_status_known(st, 0, "subd_pia_plan");
    check_inputs("subd_pia_plan");
    if (st == SUBD_OK)
        run_sized("subd_pia", plan, pia_run, pia_ok, &pc, u8(&c), 0);

    /* quasi 4-8 */
    q48_ctx qc;
    memset(&qc, 0, sizeof qc);
    qc.o.steps = u8(&c) % 5u;
    uint8_t qb = u8(&c); /* all three modes (FIXED, SMOOTH, NORMAL) and invalid ones */
    qc.o.boundary = (subd_quasi48_boundary)(qb < 250u ? qb % 3u : qb & 1u ? 3u : 0x7fffffffu);
    qc.o.flags = u8(&c) % 3u;
    qc.o.len_bits = u8(&c) % 56u;
    st = subd_quasi48_plan(&g_in, &qc.o, &plan, 0);
    fz_status_known(st, 0, "subd_quasi48_plan");
    check_inputs("subd_quasi48_plan");
    if (st == SUBD_OK)
        run_sized("subd_quasi48", plan, q48_run, q48_ok, &qc, u8(&c), 0);

    /* semi-regular 4-8 and one extraction */
    sr48_ctx rc;
    memset(&rc, 0, sizeof rc);
    rc.o.steps = u8(&c) % 5u;
    rc.o.flags = u8(&c) % 3u;
    rc.r = u8(&c);
    {
        subd_sr48_adapt *ad = &rc.ext.ad;
        ad->mode = (subd_sr48_adapt_mode)(u8(&c) % 7u);
        ad->max_level = u8(&c) % (rc.o.steps + 2u);
        for (int k = 0; k < 3; k++) {
            ad->point[k] = fz_coord(0, u8(&c), 0);
            ad->normal[k] = fz_coord(0, u8(&c), 0);
        }
        ad->radius = fz_coord(0, u8(&c), 0);
        ad->axis = u8(&c) % 4u;
        ad->eps = fz_coord(0, u8(&c), 0);
        ad->fn = u8(&c) < 8u ? NULL : adapt_cb;
        g_cb_level = u8(&c);
    }
    uint32_t bound = 0;
    int stb = subd_sr48_plan(&g_in, &rc.o, SUBD_SR48_CLUSTERS_UNKNOWN, &bound, 0);
    fz_status_known(stb, 0, "subd_sr48_plan (bound)");
    uint32_t clusters = SUBD_SR48_CLUSTERS_UNKNOWN;
    if (stb == SUBD_OK && bound <= FZ_MAX_ARENA) {
        fz_arena fa;
        fz_arena_open(&fa, bound); /* the bound covers the cluster sort */
        subd_diag d;
        st = subd_sr48_count_clusters(&fa.a, &g_in, &clusters, &d);
        fz_status_known(st, 0, "subd_sr48_count_clusters");
        FZ_CHECK(fa.a.used == 0, "subd_sr48_count_clusters leaves the arena", fa.a.used, st);
        fz_arena_after(&fa, SUBD_ERR_NOMEM, 0, 0, "subd_sr48_count_clusters");
        check_inputs("subd_sr48_count_clusters");
        fz_arena_close(&fa);
        FZ_CHECK(st != SUBD_ERR_NOMEM, "subd_sr48_count_clusters in the plan bound", st, bound);
        if (st != SUBD_OK)
            clusters = SUBD_SR48_CLUSTERS_UNKNOWN;
    }
    st = subd_sr48_plan(&g_in, &rc.o, clusters, &plan, 0);
    fz_status_known(st, 0, "subd_sr48_plan");
    check_inputs("subd_sr48_plan");
    if (st == SUBD_OK && stb == SUBD_OK)
        FZ_CHECK(plan <= bound, "sr48 exact plan <= bound", plan, bound);
    if (st == SUBD_OK)
        run_sized("subd_sr48_build", plan, sr48_run, sr48_ok, &rc, rc.r, 0);

    /* alpha curve through the first m vertices */
    curve_ctx cc;
    memset(&cc, 0, sizeof cc);
    cc.m = u8(&c) % (g_in.num_verts + 1u);
    cc.closed = u8(&c) & 1u;
    alpha_params(&c, &cc.o, g_ctags, cc.m, cc.m, &cc.uniform);
    st = subd_alpha_curve_plan(cc.m, cc.closed, &cc.o, &plan, &cc.points);
    fz_status_known(st, 0, "subd_alpha_curve_plan");
    if (st == SUBD_OK)
        run_sized("subd_alpha_curve", plan, curve_run, curve_ok, &cc, u8(&c), 0);

    /* alpha surface */
    surf_ctx uc;
    memset(&uc, 0, sizeof uc);
    alpha_params(&c, &uc.o, g_stags, g_in.num_verts, g_in.num_faces, &uc.uniform);
    if (uc.o.levels == 0u && (u8(&c) & 1u))
        uc.o.levels = 1u;
    if (uc.o.order > 4u && uc.o.levels > 1u && uc.o.order <= SUBD_ALPHA_MAX_ORDER)
        uc.o.levels = 1u; /* keeps the outputs (and the O(valence^2) builds) small: speed */
    st = subd_alpha_surface_plan(&g_in, &uc.o, &plan, 0);
    fz_status_known(st, 0, "subd_alpha_surface_plan");
    check_inputs("subd_alpha_surface_plan");
    if (st == SUBD_OK)
        run_sized("subd_alpha_surface", plan, surf_run, surf_ok, &uc, u8(&c), 0);

    fz_snap_free(&g_in_snap);
    fz_snap_free(&g_desc_snap);
    fz_snap_free(&g_data_snap);
    fz_arena_close(&in_arena);
    return 0;
}
