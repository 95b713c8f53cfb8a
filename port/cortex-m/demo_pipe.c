/* SPDX-License-Identifier: MIT */
/* Firmware demo, the pipeline of issue 22 (item 4): from measured points to a surface within
 * a chord tolerance, on the controller. The points are the vertices of a real mesh, spot's
 * control mesh triangulated (demo/spot_control_tri.obj, 188 vertices, 372 triangles, public
 * domain; embedded as OBJ text by the Makefile: $(B)/gen/demo_pipe_obj.h). The device reads
 * it, fits a control mesh by progressive interpolation (subd_pia: its Loop limit surface
 * passes through the points within tol 2^-12) and streams that limit surface adaptively
 * to the chord tolerance eps 2^-7 (subd_loop_adapt_stream, CHORD, max level
 * DEMO_PIPE_LEVELS) into a checksum sink, in static arenas; it prints the triangle count
 * against the uniform level-L count, the checksum and the instructions per triangle.
 *
 * The host reproduces the checksum with the tool on the same file and numbers
 * (demo/host_demo.sh: `subd pia --tol T`, then `subd loop -l L --stream --limit --chord EPS
 * --stats`, whose "checksum" is the same FNV-1a over the position bits), and `make demo`
 * compares the two; the host also draws the adaptive mesh and finds, by brute force in
 * double, the uniform level that meets the same tolerance (test/tools/adapt_measure.c).
 *
 * Choices: tol and eps are powers of two (2^-12 and 2^-7), exact in float32 and Q16.16, so
 * the tool's decimal options give the same bits on every build; the checksum is the tool's
 * (FNV-1a 32 over the little-endian bytes of subd_real_bits of each corner's x, y, z, in
 * emission order, from 2166136261). */
#include "subd.h"
#include "print.h"
#include "port_cm.h"
#include "demo_mesh.h" /* the checksum sink (demo_hash_tri) */
#include "demo_print.h" /* demo_kv, demo_fail: the report lines */
#include "demo_pipe_obj.h" /* static const char demo_pipe_obj[]: the OBJ text */

#define DEMO_PIPE_LEVELS 3u
#define DEMO_PIPE_MAX_VALENCE 9u /* the file's largest valence (checked below)          */

int demo_pipe(void);

static uint8_t pipe_arena[48 * 1024] __attribute__((aligned(8)));
static uint8_t pipe_stream_arena[SUBD_LOOP_ADAPT_STREAM_BYTES(DEMO_PIPE_LEVELS, DEMO_PIPE_MAX_VALENCE)]
    __attribute__((aligned(8)));


int demo_pipe(void)
{
    subd_arena a, sa;
    subd_mesh m, fit;
    subd_pia_opts po;
    subd_pia_result pr;
    subd_loop_adapt_opts ao;
    subd_tri_sink sink;
    subd_diag d;
    subd_real *pos = 0;
    demo_hash k;
    uint32_t plan, v, maxval = 0, t0, t1, n = (uint32_t)sizeof demo_pipe_obj - 1u;
    uint64_t insns;
    int st;
    print_str("pipeline: points -> progressive interpolation -> adaptive Loop limit stream to a chord tolerance:\n");
    subd_arena_init(&a, pipe_arena, sizeof pipe_arena);
    if ((st = subd_obj_read(&a, demo_pipe_obj, n, &m, &d)) != SUBD_OK) return demo_fail("reading the points", st, &d);
    for (v = 0; v < m.num_verts; v++)
        if (subd_vertex_valence(&m, v) > maxval) maxval = subd_vertex_valence(&m, v);
    if (maxval > DEMO_PIPE_MAX_VALENCE) return demo_fail("valence", SUBD_ERR_TOO_BIG, &d);
    demo_kv("points (spot's control mesh, triangulated)", m.num_verts);
    demo_kv("triangles", m.num_faces);
    demo_kv("mesh arena bytes", a.used);

    subd_pia_opts_default(&po);
    po.tol = SUBD_REAL_FRAC(1, 4096);
    if ((st = subd_pia_plan(&m, &po, &plan, &d)) != SUBD_OK) return demo_fail("pia plan", st, &d);
    demo_kv("pia arena bytes planned", plan);
    subd_arena_reset_peak(&a);
    v = a.used;
    t0 = port_cycles();
    st = subd_pia(&a, &m, &po, &pos, &pr, &d);
    t1 = port_cycles();
    if (st != SUBD_OK) return demo_fail("pia", st, &d);
    demo_kv("pia arena bytes used (peak)", a.peak - v);
    demo_kv("pia iterations (tol 2^-12)", pr.iterations);
    demo_kv("pia converged", (uint32_t)pr.converged);
    demo_kv("pia instructions", (t1 - t0) * PORT_QEMU_INSNS_PER_TICK);
    fit = m;
    fit.pos = pos; /* the control mesh: the points' topology, the fitted positions */

    ao.loop.levels = DEMO_PIPE_LEVELS;
    ao.loop.boundary = SUBD_LOOP_BOUNDARY_PAPER;
    ao.loop.flags = SUBD_LOOP_STREAM_LIMIT;
    ao.mode = SUBD_LOOP_ADAPT_CHORD;
    ao.chord = SUBD_REAL_FRAC(1, 128);
    ao.face_level = 0;
    ao.user = 0;
    if ((st = subd_loop_adapt_stream_plan(&fit, &ao, &plan, &d)) != SUBD_OK) return demo_fail("stream plan", st, &d);
    demo_kv("stream arena bytes (static)", (uint32_t)sizeof pipe_stream_arena);
    demo_kv("stream arena bytes planned", plan);
    subd_arena_init(&sa, pipe_stream_arena, sizeof pipe_stream_arena);
    demo_hash_init(&k);
    sink.tri = demo_hash_tri;
    sink.ctx = &k;
    t0 = port_cycles();
    st = subd_loop_adapt_stream(&sa, &fit, &ao, &sink, &d);
    t1 = port_cycles();
    if (st != SUBD_OK) return demo_fail("adaptive stream", st, &d);
    insns = (uint64_t)(t1 - t0) * PORT_QEMU_INSNS_PER_TICK;
    demo_kv("max level", DEMO_PIPE_LEVELS);
    print_str("  chord tolerance 2^-7 (0.0078125)\n");
    demo_kv("stream arena bytes used (peak)", sa.peak);
    demo_kv("adaptive triangles", k.tris);
    demo_kv("uniform level-L triangles", m.num_faces << (2u * DEMO_PIPE_LEVELS));
    demo_kv_hex("pipeline checksum", k.h);
    demo_kv64("instructions, adaptive stream + checksum sink", insns);
    demo_kv("instructions per triangle", (uint32_t)(insns / (k.tris ? k.tris : 1u)));
    return SUBD_OK;
}
