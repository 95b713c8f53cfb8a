/* SPDX-License-Identifier: MIT */
/* Firmware demo, issue 20: a chordal cut of the semi-regular 4-8 surface streamed in a static
 * buffer, where the materialised hierarchy would not fit the board's RAM.
 *
 * The mesh is test/data/icosahedron.obj, read from the same bytes the host tool reads (the
 * test corpus, build/gen/corpus.c, is linked into the demo). Its base mesh (subd_sr48_base)
 * stays in the main arena; then subd_sr48_stream cuts it with SUBD_SR48_ADAPT_CHORD (eps 0.01,
 * DSR_STEPS binary steps) into a checksum sink (the FNV-1a of `subd ... --stream --stats`),
 * in a static buffer of SUBD_SR48_STREAM_CHORD_BYTES(DSR_STEPS, 10) bytes (the base's largest
 * valence is 10): the demo checks buffer = plan = the arena's peak. 9 steps: the least at
 * which the materialised path needs more than the board's 4 MiB (the chordal stream's time
 * grows with the uniform level's faces, so more steps only make the demo slower). The host reproduces the checksum with
 *     subd sr48 --stream --chord 0.01 -l 9 test/data/icosahedron.obj --stats
 * (demo/host_demo.sh compares it with this demo's output, and the uniform one below with
 * subd sr48 --stream -l 6 ... --stats).
 *
 * What the materialised path would need at DSR_STEPS: subd_sr48_plan (the build's exact peak,
 * with subd_sr48_count_clusters) and, above the kept hierarchy, subd_sr48_extract_plan(CHORD).
 * The hierarchy is not built, so the extract plan is asked of a hierarchy header with the
 * counts of DSR_STEPS in closed form (closed base: every triangle is in a diamond, so level k
 * has T0 2^k triangles and level k + 1 adds T0 2^(k-1) vertices) and the kept bytes are its
 * three arrays (pos, tri_vert, tri_base_nb); both are checked against a real build at
 * DSR_CHECK_STEPS first, so the closed form cannot drift from the library's layout.
 * Instructions are counted as in demo.c (QEMU -icount: ticks x PORT_QEMU_INSNS_PER_TICK),
 * sink included (about 150 instructions per triangle). The uniform stream at DSR_COUNT_STEPS
 * runs twice, into the checksum sink and into a counting sink (the triangles counted, nothing
 * read), so that the stream's own instructions per face stand next to the checksum figure. */
#include <string.h>
#include "subd.h"
#include "print.h"
#include "port_cm.h"
#include "demo_print.h" /* demo_kv, demo_fail: the report lines */
#include "demo_mesh.h" /* the checksum sink (demo_hash_tri) */
#include "corpus.h"
#include "demo_sr48.h"

#define DSR_MESH "test/data/icosahedron.obj"
#define DSR_STEPS 9u        /* binary steps of the chordal cut                           */
#define DSR_VALENCE 10u     /* the base's largest valence the static buffer is sized for */
#define DSR_UNIFORM_STEPS 6u /* the uniform stream's steps (instructions per face)       */
#define DSR_COUNT_STEPS 8u  /* the uniform stream with the counting sink (its own cost)   */
#define DSR_CHECK_STEPS 3u  /* the closed form checked against a real build              */
#define DSR_RAM (4u * 1024u * 1024u) /* mps2-an386 / an385: 4 MiB of RAM (linker/mps2_*.ld)  */

static uint8_t dsr_buf[SUBD_SR48_STREAM_CHORD_BYTES(DSR_STEPS, DSR_VALENCE)] __attribute__((aligned(8)));

static uint32_t dsr_align(uint32_t n) { return (n + (SUBD_ARENA_ALIGN - 1u)) & ~(uint32_t)(SUBD_ARENA_ALIGN - 1u); }

/* The hierarchy header of `steps` binary steps over a closed base, in closed form (see the
 * file comment); the arrays point at the base's (the plan reads counts only). Returns its
 * arrays' bytes. */
static uint32_t dsr_counts(const subd_sr48 *base, uint32_t steps, subd_sr48 *h)
{
    uint32_t k, t0 = base->level_tri[1], v = base->num_verts;
    *h = *base;
    h->steps = steps;
    h->level_tri[0] = 0;
    for (k = 0; k <= steps; k++) {
        h->level_tri[k + 1u] = h->level_tri[k] + (t0 << k);
        h->level_verts[k] = v;
        v += (t0 << k) / 2u;
    }
    h->num_verts = h->level_verts[steps];
    h->num_tris = h->level_tri[steps + 1u];
    h->hyb_base_nb = 0;
    return dsr_align(12u * h->num_verts) + dsr_align(12u * h->num_tris) + dsr_align(4u * h->num_tris);
}

static int dsr_closed(const subd_sr48 *b)
{
    uint32_t t;
    for (t = 0; t < b->level_tri[1]; t++)
        if (b->tri_base_nb[t] == SUBD_NONE) return 0;
    for (t = 0; t < b->level_tri[1] / 2u; t++)
        if (b->hyb_base_nb[t] == SUBD_NONE) return 0;
    return 1;
}

/* The closed form against subd_sr48_build at DSR_CHECK_STEPS: counts, kept bytes, extract
 * plan. */
static int dsr_check_counts(subd_arena *arena, const subd_mesh *m, const subd_sr48 *base, const subd_sr48_adapt *ad)
{
    subd_sr48_opts o;
    subd_sr48 h, c;
    subd_sr48_adapt a2 = *ad;
    subd_diag d;
    uint32_t mark = subd_arena_mark(arena), kept, k, p1 = 0, p2 = 0;
    int st, ok;
    o.steps = DSR_CHECK_STEPS;
    o.flags = 0;
    a2.max_level = DSR_CHECK_STEPS;
    if ((st = subd_sr48_build(arena, m, &o, &h, &d)) != SUBD_OK) return demo_fail("subd_sr48_build", st, &d);
    kept = dsr_counts(base, DSR_CHECK_STEPS, &c);
    ok = kept == subd_arena_mark(arena) - mark && c.num_verts == h.num_verts && c.num_tris == h.num_tris;
    for (k = 0; k <= DSR_CHECK_STEPS; k++) ok = ok && c.level_verts[k] == h.level_verts[k] && c.level_tri[k] == h.level_tri[k];
    if (ok && (subd_sr48_extract_plan(&h, &a2, &p1, 0) != SUBD_OK || subd_sr48_extract_plan(&c, &a2, &p2, 0) != SUBD_OK))
        ok = 0;
    subd_arena_rewind(arena, mark);
    if (!ok || p1 != p2) {
        print_str("  error: the closed-form hierarchy counts differ from subd_sr48_build's\n");
        return SUBD_ERR_PARAM;
    }
    demo_kv("closed-form hierarchy counts = subd_sr48_build's at binary steps", DSR_CHECK_STEPS);
    return SUBD_OK;
}

/* One stream of the base into the checksum sink in dsr_buf: plan, buffer, peak, hash and
 * instructions per face printed. */
static int dsr_stream(const subd_sr48 *base, const subd_sr48_adapt *ad, uint32_t *faces)
{
    subd_sr48_stream_opts so;
    subd_arena sa;
    subd_diag d;
    subd_tri_sink sink;
    demo_hash k;
    uint32_t plan = 0, t0, t1;
    uint64_t insns;
    int st;
    so.adapt = *ad;
    if ((st = subd_sr48_stream_plan(base, &so, &plan, &d)) != SUBD_OK) return demo_fail("subd_sr48_stream_plan", st, &d);
    demo_kv("stream arena bytes planned (subd_sr48_stream_plan)", plan);
    if (plan > sizeof dsr_buf) return demo_fail("the static buffer is below the plan", SUBD_ERR_NOMEM, 0);
    subd_arena_init(&sa, dsr_buf, plan);
    demo_hash_init(&k);
    sink.tri = demo_hash_tri;
    sink.ctx = &k;
    t0 = port_cycles();
    st = subd_sr48_stream(&sa, base, &so, &sink, &d);
    t1 = port_cycles();
    if (st != SUBD_OK) return demo_fail("subd_sr48_stream", st, &d);
    insns = (uint64_t)(t1 - t0) * PORT_QEMU_INSNS_PER_TICK;
    demo_kv("stream arena bytes used (peak)", sa.peak);
    demo_kv("output faces", k.tris);
    demo_kv_hex("checksum", k.h);
    demo_kv64("instructions, stream + checksum sink", insns);
    demo_kv("instructions per output face", k.tris ? (uint32_t)(insns / k.tris) : 0u);
    if (sa.peak != plan) return demo_fail("the peak differs from the plan", SUBD_ERR_PARAM, 0);
    *faces = k.tris;
    return SUBD_OK;
}

/* The counting sink: the triangles only, so that the instructions are the stream's own. */
static int dsr_count_tri(void *ctx, const subd_tri *t)
{
    (void)t;
    ++*(uint32_t *)ctx;
    return 0;
}

/* The uniform stream of DSR_COUNT_STEPS into the checksum sink (dsr_stream), then again into
 * the counting sink: the stream's own instructions per face next to the checksum sink's
 * (the same triangles: the counts must agree). */
static int dsr_uniform_count(const subd_sr48 *base)
{
    subd_sr48_adapt ad;
    subd_sr48_stream_opts so;
    subd_arena sa;
    subd_diag d;
    subd_tri_sink sink;
    uint32_t plan = 0, t0, t1, faces = 0, n = 0;
    uint64_t insns;
    int st;
    memset(&ad, 0, sizeof ad);
    ad.mode = SUBD_SR48_ADAPT_UNIFORM;
    ad.max_level = DSR_COUNT_STEPS;
    if ((st = dsr_stream(base, &ad, &faces)) != SUBD_OK) return st;
    so.adapt = ad;
    if ((st = subd_sr48_stream_plan(base, &so, &plan, &d)) != SUBD_OK) return demo_fail("subd_sr48_stream_plan", st, &d);
    subd_arena_init(&sa, dsr_buf, plan);
    sink.tri = dsr_count_tri;
    sink.ctx = &n;
    t0 = port_cycles();
    st = subd_sr48_stream(&sa, base, &so, &sink, &d);
    t1 = port_cycles();
    if (st != SUBD_OK) return demo_fail("subd_sr48_stream", st, &d);
    if (n != faces) return demo_fail("the counting sink's faces differ from the checksum sink's", SUBD_ERR_PARAM, 0);
    insns = (uint64_t)(t1 - t0) * PORT_QEMU_INSNS_PER_TICK;
    demo_kv64("instructions, stream + counting sink", insns);
    demo_kv("instructions per output face, stream + counting sink", n ? (uint32_t)(insns / n) : 0u);
    return SUBD_OK;
}

int demo_sr48_chord(subd_arena *arena)
{
    const corpus_file *f = corpus_find(DSR_MESH);
    const char *eps_text = "0.01", *p;
    subd_mesh m;
    subd_sr48 base, c;
    subd_sr48_opts o;
    subd_sr48_adapt ad;
    subd_diag d;
    uint32_t mark = subd_arena_mark(arena), clusters = 0, build = 0, extract = 0, kept, mat, faces = 0;
    int st;
    print_str("semi-regular 4-8 chordal stream (" DSR_MESH ", eps 0.01, 9 binary steps):\n");
    if (!f) return demo_fail("mesh not linked", SUBD_ERR_PARAM, 0);
    if ((st = subd_obj_read(arena, f->data, f->len, &m, &d)) != SUBD_OK) return demo_fail("subd_obj_read", st, &d);
    if ((st = subd_sr48_count_clusters(arena, &m, &clusters, &d)) != SUBD_OK)
        return demo_fail("subd_sr48_count_clusters", st, &d);
    if ((st = subd_sr48_base(arena, &m, 0, &base, &d)) != SUBD_OK) return demo_fail("subd_sr48_base", st, &d);
    demo_kv("input mesh + base mesh arena bytes (main arena)", subd_arena_mark(arena) - mark);
    demo_kv("base triangles", base.level_tri[1]);
    memset(&ad, 0, sizeof ad);
    ad.mode = SUBD_SR48_ADAPT_CHORD;
    ad.max_level = DSR_STEPS;
    p = eps_text;
    if ((st = subd_real_parse(&p, eps_text + 4, &ad.eps)) != SUBD_OK) return demo_fail("eps", st, 0);
    if (!dsr_closed(&base)) return demo_fail("the closed form needs a closed mesh", SUBD_ERR_PARAM, 0);
    if ((st = dsr_check_counts(arena, &m, &base, &ad)) != SUBD_OK) return st;

    /* the materialised path at DSR_STEPS, from the plans */
    o.steps = DSR_STEPS;
    o.flags = 0;
    if ((st = subd_sr48_plan(&m, &o, clusters, &build, &d)) != SUBD_OK) return demo_fail("subd_sr48_plan", st, &d);
    kept = dsr_counts(&base, DSR_STEPS, &c);
    if ((st = subd_sr48_extract_plan(&c, &ad, &extract, &d)) != SUBD_OK)
        return demo_fail("subd_sr48_extract_plan", st, &d);
    mat = kept + extract > build ? kept + extract : build;
    demo_kv("materialised: subd_sr48_build plan (peak)", build);
    demo_kv("materialised: hierarchy kept", kept);
    demo_kv("materialised: + subd_sr48_extract_plan(CHORD)", extract);
    demo_kv("materialised: bytes needed, max(build, kept + extract)", mat);
    demo_kv("board RAM bytes", DSR_RAM);
    demo_kv("static stream buffer bytes, SUBD_SR48_STREAM_CHORD_BYTES(9, 10)", (uint32_t)sizeof dsr_buf);
    if (mat <= DSR_RAM) return demo_fail("the materialised hierarchy would fit the RAM", SUBD_ERR_PARAM, 0);

    print_str("chordal stream, eps 0.01, 9 binary steps:\n");
    if ((st = dsr_stream(&base, &ad, &faces)) != SUBD_OK) return st;
    demo_kv("faces of uniform level 9", base.level_tri[1] << DSR_STEPS);
    {
        subd_sr48_stream_opts so;
        uint32_t plan = 0;
        so.adapt = ad;
        if (subd_sr48_stream_plan(&base, &so, &plan, 0) != SUBD_OK || plan != sizeof dsr_buf)
            return demo_fail("the static buffer is not the plan", SUBD_ERR_PARAM, 0);
    }

    print_str("uniform stream, 6 binary steps (same base):\n");
    memset(&ad, 0, sizeof ad);
    ad.mode = SUBD_SR48_ADAPT_UNIFORM;
    ad.max_level = DSR_UNIFORM_STEPS;
    if ((st = dsr_stream(&base, &ad, &faces)) != SUBD_OK) return st;

    print_str("uniform stream, 8 binary steps (same base), checksum sink then counting sink:\n");
    if ((st = dsr_uniform_count(&base)) != SUBD_OK) return st;
    subd_arena_rewind(arena, mark);
    return SUBD_OK;
}
