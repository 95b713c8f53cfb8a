/* SPDX-License-Identifier: MIT */
/* Firmware demo: what a device build of tinysubd does, inside one static arena: read a mesh
 * from OBJ text, then Loop subdivision (3 levels), Loop limit positions and normals, quasi
 * 4-8 subdivision, and a semi-regular 4-8 hierarchy with a chordal-tolerance extraction of
 * it, printing counts, arena bytes and instruction counts. Then streaming Loop: level 6 of a
 * 500-face geodesic sphere built in code (demo_mesh.h), triangle by triangle through a sink,
 * in a static arena of SUBD_LOOP_STREAM_BYTES(6, 6) bytes, with a checksum of every emitted
 * position that the host reproduces (`bench -s demostream`). Run by `make demo` under QEMU
 * on both targets (Cortex-M4F float32, Cortex-M3 Q16.16). */
#include "subd.h"
#include "print.h"
#include "port_cm.h"
#include "demo_mesh.h"
#include "demo_print.h" /* demo_kv, demo_fail: the report lines */
#include "demo_sr48.h" /* the 4-8 chordal stream step (demo_sr48.c) */

/* The whole memory budget of the demo. The plan calls below say exactly how much of it
 * each step needs; the demo checks before it builds. */
static uint8_t arena_buf[96 * 1024] __attribute__((aligned(8)));

/* The streaming step's own arena, sized at compile time for level 6 and valence 6: the
 * control mesh lives in arena_buf, the stream needs only this, whatever the level. */
static uint8_t stream_arena[SUBD_LOOP_STREAM_BYTES(DEMO_STREAM_LEVELS, DEMO_GEO_MAX_VALENCE)]
    __attribute__((aligned(8)));
typedef char stream_arena_within_16k[sizeof stream_arena <= 16u * 1024u ? 1 : -1];
/* The same stream in limit mode (limit positions and normals): its own plan. */
static uint8_t stream_limit_arena[SUBD_LOOP_STREAM_BYTES_LIMIT(DEMO_STREAM_LEVELS, DEMO_GEO_MAX_VALENCE)]
    __attribute__((aligned(8)));
/* The semi-regular 4-8 stream's own arena: 8 binary steps, base valence up to 8 (the
 * icosahedron's level 0). The materialised hierarchy of 8 steps would take ~1 MB. */
#define DEMO_SR48_STEPS 8u
static uint8_t sr48_stream_arena[SUBD_SR48_STREAM_BYTES(DEMO_SR48_STEPS, 8)] __attribute__((aligned(8)));
static demo_geo geo; /* the generator's face list (copied into arena_buf by the builder) */

static const char icosahedron_obj[] =
    "# regular icosahedron (vertices (0, +-1, +-p) cyclically, p = golden ratio)\n"
    "v 0 1 1.618034\nv 0 -1 1.618034\nv 0 1 -1.618034\nv 0 -1 -1.618034\n"
    "v 1 1.618034 0\nv -1 1.618034 0\nv 1 -1.618034 0\nv -1 -1.618034 0\n"
    "v 1.618034 0 1\nv -1.618034 0 1\nv 1.618034 0 -1\nv -1.618034 0 -1\n"
    "f 1 2 9\nf 1 10 2\nf 1 9 5\nf 1 5 6\nf 1 6 10\nf 2 7 9\nf 2 8 7\nf 2 10 8\n"
    "f 3 4 12\nf 3 11 4\nf 3 5 11\nf 3 6 5\nf 3 12 6\nf 4 11 7\nf 4 7 8\nf 4 8 12\n"
    "f 5 9 11\nf 6 12 10\nf 7 11 9\nf 8 10 12\n";

/* Marks the arena and starts a new peak measurement there, so each step's peak can be
 * compared with its own plan. */
static uint32_t start_measure(subd_arena *a)
{
    subd_arena_reset_peak(a);
    return subd_arena_mark(a);
}

/* Loop subdivision, level 3, of the mesh: plan, check the budget, run, report. */
static int demo_loop(subd_arena *arena, const subd_mesh *in)
{
    subd_loop_opts o;
    subd_mesh out;
    subd_diag d;
    uint32_t plan, t0, t1, mark = start_measure(arena), insns;
    int st;
    o.levels = 3;
    o.boundary = SUBD_LOOP_BOUNDARY_PAPER;
    o.flags = 0;
    print_str("Loop subdivision, 3 levels:\n");
    if ((st = subd_loop_plan(in, &o, &plan, 0)) != SUBD_OK) return st;
    demo_kv("arena bytes planned", plan);
    if (plan > subd_arena_free_bytes(arena)) return SUBD_ERR_NOMEM;
    t0 = port_cycles();
    st = subd_loop(arena, in, &o, &out, &d);
    t1 = port_cycles();
    if (st != SUBD_OK) return demo_fail(0, st, &d);
    insns = (t1 - t0) * PORT_QEMU_INSNS_PER_TICK;
    demo_kv("arena bytes used (peak)", arena->peak - mark);
    demo_kv("output vertices", out.num_verts);
    demo_kv("output faces", out.num_faces);
    demo_kv("instructions", insns);
    demo_kv("instructions per output face", insns / out.num_faces);
    subd_arena_rewind(arena, mark);
    return SUBD_OK;
}

static int demo_limit(subd_arena *arena, const subd_mesh *in)
{
    subd_real *pos = 0, *nrm = 0;
    subd_diag d;
    uint32_t plan, t0, t1, mark = start_measure(arena);
    int st;
    print_str("Loop limit positions and normals:\n");
    if ((st = subd_loop_limit_plan(in, &(subd_loop_limit_opts){SUBD_LOOP_BOUNDARY_PAPER, SUBD_LOOP_LIMIT_NORMALS}, &plan, 0)) != SUBD_OK) return st;
    demo_kv("arena bytes planned", plan);
    t0 = port_cycles();
    st = subd_loop_limit(arena, in, &(subd_loop_limit_opts){SUBD_LOOP_BOUNDARY_PAPER, SUBD_LOOP_LIMIT_NORMALS}, &pos, &nrm, &d);
    t1 = port_cycles();
    if (st != SUBD_OK) return demo_fail(0, st, &d);
    demo_kv("arena bytes used (peak)", arena->peak - mark);
    demo_kv("instructions per vertex", (t1 - t0) * PORT_QEMU_INSNS_PER_TICK / in->num_verts);
    subd_arena_rewind(arena, mark);
    return SUBD_OK;
}

static int demo_quasi48(subd_arena *arena, const subd_mesh *in)
{
    subd_quasi48_opts o;
    subd_mesh out;
    subd_diag d;
    uint32_t plan, t0, t1, mark = start_measure(arena), insns;
    int st;
    o.steps = 4;
    o.boundary = SUBD_QUASI48_BOUNDARY_FIXED;
    o.flags = 0;
    o.len_bits = 0;
    print_str("quasi 4-8 subdivision, 4 binary steps:\n");
    if ((st = subd_quasi48_plan(in, &o, &plan, 0)) != SUBD_OK) return st;
    demo_kv("arena bytes planned", plan);
    if (plan > subd_arena_free_bytes(arena)) return SUBD_ERR_NOMEM;
    t0 = port_cycles();
    st = subd_quasi48(arena, in, &o, &out, &d);
    t1 = port_cycles();
    if (st != SUBD_OK) return demo_fail(0, st, &d);
    insns = (t1 - t0) * PORT_QEMU_INSNS_PER_TICK;
    demo_kv("arena bytes used (peak)", arena->peak - mark);
    demo_kv("output faces", out.num_faces);
    demo_kv("instructions per output face", insns / out.num_faces);
    subd_arena_rewind(arena, mark);
    return SUBD_OK;
}

/* Semi-regular 4-8: the hierarchy (exact plan from the cluster count), then the coarsest
 * conforming mesh within a chordal tolerance of its finest level, as a CNC controller
 * would ask for it, above the hierarchy in the same arena. */
static int demo_semireg48(subd_arena *arena, const subd_mesh *in)
{
    subd_sr48_opts o;
    subd_sr48 h;
    subd_sr48_adapt ad;
    subd_sr48_adapt_report rep;
    subd_mesh out;
    subd_diag d;
    uint32_t plan, clusters, t0, t1, mark = start_measure(arena), mark2, insns;
    uint32_t ovf = 0;
    int st;
    o.steps = 4;
    o.flags = 0;
    print_str("semi-regular 4-8 hierarchy, 4 binary steps:\n");
    if ((st = subd_sr48_count_clusters(arena, in, &clusters, &d)) != SUBD_OK) return demo_fail(0, st, &d);
    if ((st = subd_sr48_plan(in, &o, clusters, &plan, &d)) != SUBD_OK) return demo_fail(0, st, &d);
    demo_kv("arena bytes planned", plan);
    if (plan > subd_arena_free_bytes(arena)) return SUBD_ERR_NOMEM;
    t0 = port_cycles();
    st = subd_sr48_build(arena, in, &o, &h, &d);
    t1 = port_cycles();
    if (st != SUBD_OK) return demo_fail(0, st, &d);
    insns = (t1 - t0) * PORT_QEMU_INSNS_PER_TICK;
    demo_kv("arena bytes used (peak)", arena->peak - mark);
    demo_kv("triangles (all levels)", h.num_tris);
    demo_kv("instructions per triangle", insns / h.num_tris);

    ad.mode = SUBD_SR48_ADAPT_CHORD;
    ad.max_level = 4;
    ad.eps = subd_div(subd_from_int(1, &ovf), subd_from_int(20, &ovf), &ovf); /* 0.05 units */
    ad.point[0] = ad.point[1] = ad.point[2] = 0;
    ad.normal[0] = ad.normal[1] = ad.normal[2] = 0;
    ad.radius = 0;
    ad.axis = 0;
    ad.fn = 0;
    ad.ctx = 0;
    if (ovf) return SUBD_ERR_RANGE;
    print_str("chordal extraction, eps 0.05, up to level 4:\n");
    mark2 = start_measure(arena);
    if ((st = subd_sr48_extract_plan(&h, &ad, &plan, &d)) != SUBD_OK) return demo_fail(0, st, &d);
    demo_kv("arena bytes planned (bound)", plan);
    t0 = port_cycles();
    st = subd_sr48_extract(arena, &h, &ad, &out, &rep, &d);
    t1 = port_cycles();
    if (st != SUBD_OK) return demo_fail(0, st, &d);
    insns = (t1 - t0) * PORT_QEMU_INSNS_PER_TICK;
    demo_kv("arena bytes used (peak)", arena->peak - mark2);
    demo_kv("output faces", rep.faces);
    demo_kv("faces of uniform level 4", rep.uniform_faces);
    demo_kv("forced splits", rep.forced_splits);
    demo_kv("instructions per output face", insns / rep.faces);
    subd_arena_rewind(arena, mark);
    return SUBD_OK;
}

static int demo_sr48_stream(subd_arena *arena, const subd_mesh *in)
{
    subd_sr48 base;
    subd_sr48_stream_opts so;
    subd_arena sa;
    subd_diag d;
    subd_tri_sink sink;
    demo_hash k;
    uint32_t plan, t0, t1, mark = start_measure(arena);
    uint64_t insns;
    int st;
    print_str("semi-regular 4-8 stream, uniform, 8 binary steps:\n");
    if ((st = subd_sr48_base(arena, in, 0, &base, &d)) != SUBD_OK) return demo_fail(0, st, &d);
    demo_kv("base mesh arena bytes", arena->peak - mark);
    so.adapt.mode = SUBD_SR48_ADAPT_UNIFORM;
    so.adapt.max_level = DEMO_SR48_STEPS;
    if ((st = subd_sr48_stream_plan(&base, &so, &plan, &d)) != SUBD_OK) return demo_fail(0, st, &d);
    demo_kv("stream arena bytes planned", plan);
    demo_kv("static buffer bytes", (uint32_t)sizeof sr48_stream_arena);
    subd_arena_init(&sa, sr48_stream_arena, sizeof sr48_stream_arena);
    demo_hash_init(&k); /* the tool's --stats checksum */
    sink.tri = demo_hash_tri;
    sink.ctx = &k;
    t0 = port_cycles();
    st = subd_sr48_stream(&sa, &base, &so, &sink, &d);
    t1 = port_cycles();
    if (st != SUBD_OK) return demo_fail(0, st, &d);
    insns = (uint64_t)(t1 - t0) * PORT_QEMU_INSNS_PER_TICK;
    demo_kv("stream arena bytes used (peak)", sa.peak);
    demo_kv("triangles", k.tris);
    demo_kv_hex("checksum", k.h);
    demo_kv64("instructions, stream + checksum sink", insns);
    demo_kv("instructions per triangle", (uint32_t)(insns / k.tris));
    subd_arena_rewind(arena, mark);
    return SUBD_OK;
}

static int demo_icosahedron(subd_arena *arena)
{
    subd_mesh m;
    subd_diag d;
    uint32_t plan, t0, t1, mark = start_measure(arena);
    int st = subd_obj_plan(icosahedron_obj, sizeof icosahedron_obj - 1u, &plan, &d);
    print_str("icosahedron from OBJ text:\n");
    if (st != SUBD_OK) return st;
    demo_kv("arena bytes planned", plan);
    if (plan > subd_arena_free_bytes(arena)) return SUBD_ERR_NOMEM;
    t0 = port_cycles();
    st = subd_obj_read(arena, icosahedron_obj, sizeof icosahedron_obj - 1u, &m, &d);
    t1 = port_cycles();
    if (st != SUBD_OK) {
        print_str("  at line ");
        print_u32(d.line);
        print_nl();
        return demo_fail(0, st, &d);
    }
    demo_kv("arena bytes used (peak)", arena->peak - mark);
    demo_kv("vertices", m.num_verts);
    demo_kv("faces", m.num_faces);
    demo_kv("edges", m.num_edges);
    print_str("  euler characteristic ");
    print_i32(subd_mesh_euler(&m));
    print_nl();
    demo_kv("valence of vertex 0", subd_vertex_valence(&m, 0));
    demo_kv("instructions (parse + validate + adjacency)", (t1 - t0) * PORT_QEMU_INSNS_PER_TICK);
    /* the schemes work on the mesh just read, above it in the same arena */
    if ((st = demo_loop(arena, &m)) != SUBD_OK) return st;
    if ((st = demo_limit(arena, &m)) != SUBD_OK) return st;
    if ((st = demo_quasi48(arena, &m)) != SUBD_OK) return st;
    if ((st = demo_semireg48(arena, &m)) != SUBD_OK) return st;
    if ((st = demo_sr48_stream(arena, &m)) != SUBD_OK) return st;
    subd_arena_rewind(arena, mark);
    return SUBD_OK;
}

/* One timed subd_loop_stream call: its instructions in *insns (QEMU's counter). */
static int demo_loop_timed(subd_arena *sa, const subd_mesh *m, const subd_loop_opts *o, const subd_loop_sink *sink,
                           uint64_t *insns)
{
    subd_diag d;
    uint32_t t0 = port_cycles(), t1;
    int st = subd_loop_stream(sa, m, o, sink, &d);
    t1 = port_cycles();
    if (st != SUBD_OK) return demo_fail(0, st, &d);
    *insns = (uint64_t)(t1 - t0) * PORT_QEMU_INSNS_PER_TICK;
    return SUBD_OK;
}

/* The stream into a counting sink (the stream's own instructions per triangle, without a
 * checksum's), reported under the two labels; the count must be `tris`. */
static int demo_loop_counted(subd_arena *sa, const subd_mesh *m, const subd_loop_opts *o, uint32_t tris,
                             const char *label_total, const char *label_per_tri)
{
    subd_loop_sink sink;
    uint32_t count = 0;
    uint64_t insns;
    int st;
    sink.tri = demo_count_tri;
    sink.ctx = &count;
    if ((st = demo_loop_timed(sa, m, o, &sink, &insns)) != SUBD_OK) return st;
    if (count != tris) return SUBD_ERR_PARAM;
    demo_kv64(label_total, insns);
    demo_kv(label_per_tri, (uint32_t)(insns / count));
    return SUBD_OK;
}

/* Streaming Loop, level 6, of the geodesic sphere: build the control mesh in the main arena,
 * plan the stream and check it against the static stream arena, then stream twice: into the
 * checksum sink (the hash the host reproduces) and into a counting sink (the stream's own
 * instructions per triangle, without the checksum's). */
static int demo_stream(subd_arena *arena)
{
    subd_face_list fl;
    subd_mesh m;
    subd_arena sa;
    subd_loop_opts o;
    subd_loop_sink sink;
    subd_diag d;
    demo_hash hs;
    uint32_t plan, mark = start_measure(arena), v, maxval = 0;
    uint64_t insns_hash;
    int st;
    print_str("streaming Loop, level 6, geodesic sphere built in code:\n");
    if ((st = demo_geo_build(&geo, &fl)) != SUBD_OK) return st;
    if ((st = subd_mesh_plan(&fl, &plan)) != SUBD_OK) return st;
    if (plan > subd_arena_free_bytes(arena)) return SUBD_ERR_NOMEM;
    if ((st = subd_mesh_build(arena, &fl, &m, &d)) != SUBD_OK) return demo_fail(0, st, &d);
    for (v = 0; v < m.num_verts; v++)
        if (subd_vertex_valence(&m, v) > maxval) maxval = subd_vertex_valence(&m, v);
    demo_kv("control vertices", m.num_verts);
    demo_kv("control faces", m.num_faces);
    demo_kv("max valence", maxval);
    demo_kv("control mesh arena bytes (in the main arena)", arena->used - mark);
    o.levels = DEMO_STREAM_LEVELS;
    o.boundary = SUBD_LOOP_BOUNDARY_PAPER;
    o.flags = 0;
    if ((st = subd_loop_stream_plan(&m, &o, &plan, 0)) != SUBD_OK) return st;
    demo_kv("stream arena bytes (static)", (uint32_t)sizeof stream_arena);
    demo_kv("stream arena bytes planned", plan);
    if (plan > sizeof stream_arena) return SUBD_ERR_NOMEM;
    subd_arena_init(&sa, stream_arena, sizeof stream_arena);
    demo_hash_init(&hs);
    sink.tri = demo_hash_tri;
    sink.ctx = &hs;
    if ((st = demo_loop_timed(&sa, &m, &o, &sink, &insns_hash)) != SUBD_OK) return st;
    demo_kv("stream arena bytes used (peak)", sa.peak);
    demo_kv("triangles", hs.tris);
    demo_kv_hex("position hash (FNV-1a)", hs.h);
    demo_kv64("instructions, stream + checksum sink", insns_hash);
    demo_kv("instructions per triangle, stream + checksum sink", (uint32_t)(insns_hash / hs.tris));
    if ((st = demo_loop_counted(&sa, &m, &o, hs.tris, "instructions, stream + counting sink",
                                "instructions per triangle, stream + counting sink")) != SUBD_OK)
        return st;
    /* limit mode: limit positions and unit normals, same triangles */
    o.flags = SUBD_LOOP_STREAM_LIMIT;
    if ((st = subd_loop_stream_plan(&m, &o, &plan, 0)) != SUBD_OK) return st;
    demo_kv("limit stream arena bytes planned", plan);
    if (plan > sizeof stream_limit_arena) return SUBD_ERR_NOMEM;
    subd_arena_init(&sa, stream_limit_arena, sizeof stream_limit_arena);
    if ((st = demo_loop_counted(&sa, &m, &o, hs.tris, "instructions, limit stream + counting sink",
                                "instructions per triangle, limit stream + counting sink")) != SUBD_OK)
        return st;
    subd_arena_rewind(arena, mark);
    return SUBD_OK;
}

int main(void);
int main(void)
{
    subd_arena arena;
    int st;
    print_str("tinysubd " SUBD_VERSION " firmware demo, arithmetic ");
    print_str(SUBD_FIXED ? "Q16.16" : "float32");
    print_str(", static arena ");
    print_u32((uint32_t)sizeof arena_buf);
    print_str(" bytes\n");
    (void)port_cycles(); /* starts the counter */
    subd_arena_init(&arena, arena_buf, sizeof arena_buf);
    st = demo_icosahedron(&arena);
    if (st == SUBD_OK) st = demo_stream(&arena);
    if (st == SUBD_OK) st = demo_sr48_chord(&arena);
    if (st == SUBD_OK) { extern int demo_pipe(void); st = demo_pipe(); } /* demo_pipe.c: issue 22's pipeline */
    demo_kv("stack bytes used", port_stack_used());
    if (st != SUBD_OK) {
        print_str("demo failed: ");
        print_str(subd_status_str(st));
        print_nl();
        return 1;
    }
    print_str("demo ok\n");
    return 0;
}
