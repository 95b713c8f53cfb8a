/* SPDX-License-Identifier: MIT */
/* libFuzzer target: the semi-regular 4-8 base mesh (subd_sr48_base) and its stream
 * (subd_sr48_stream, include/subd_sr48.h) on a small mesh decoded from the input bytes
 * (fuzz_mesh.h), against the materialising calls.
 *
 * The bytes choose the mesh, the smoothing flags (also invalid ones), the cut (every mode,
 * also CHORD, which does not stream yet, and an unknown one; max_level 0..4 and sometimes out
 * of range; point, normal, radius, axis and eps through fz_coord, so also NaN, infinity and
 * huge values) and a monotone CALLBACK (detail near a viewer point) or a NULL one. Checks:
 *  - every status is known; base and stream leave the arena at its mark on failure, guard
 *    bytes intact, peak <= plan; the input mesh and the input bytes unchanged;
 *  - subd_sr48_base: an arena of its plan (with the cluster count) never gives NOMEM;
 *  - the stream's plan fills diag (status, no bytes_needed); an arena of plan - 1 gives
 *    SUBD_ERR_NOMEM with bytes_needed = the plan and nothing emitted; an arena of the plan
 *    never gives NOMEM and is handed back;
 *  - whenever subd_sr48_build(steps = max_level) and subd_sr48_extract fit FZ_MAX_ARENA
 *    and the mode streams: the stream plan's status is the extraction plan's; a stream that
 *    fails gives the extraction's status or SUBD_ERR_RANGE where the extraction had no
 *    overflow to see (float32: only positions it never computes); a stream that succeeds
 *    gives the extraction's triangles as a multiset of corner bits, one id per extraction
 *    vertex, equal ids with equal bits. */
#include "fuzz_check.h"
#include "fuzz_mesh.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* CALLBACK: level max - floor(d / r) at distance d from the viewer to the box (double in
 * the harness; NaN-safe: a NaN distance asks for max everywhere). Monotone. */
static double g_view[3], g_vr;
static uint32_t g_vmax;
static uint32_t view_cb(void *ctx, const subd_real *lo, const subd_real *hi)
{
    double d2 = 0;
    (void)ctx;
    for (int i = 0; i < 3; i++) {
        double l = (double)lo[i], h = (double)hi[i];
#if SUBD_FIXED
        l /= 65536.0;
        h /= 65536.0;
#endif
        double e = g_view[i] < l ? l - g_view[i] : g_view[i] > h ? g_view[i] - h : 0;
        d2 += e * e;
    }
    for (uint32_t n = 0; n <= g_vmax; n++) {
        double lim = (double)(g_vmax - n) * g_vr;
        if (lim * lim <= d2)
            return n;
    }
    return g_vmax;
}

/* A triangle as 9 coordinate bit patterns (the multiset key). */
typedef struct tkey {
    uint32_t w[9];
} tkey;
static int tkey_cmp(const void *a, const void *b) { return memcmp(a, b, sizeof(tkey)); }
typedef struct idbits {
    uint64_t id;
    uint32_t w[3];
} idbits;
static int idbits_cmp(const void *a, const void *b)
{
    const idbits *x = (const idbits *)a, *y = (const idbits *)b;
    if (x->id != y->id)
        return x->id < y->id ? -1 : 1;
    return memcmp(x->w, y->w, sizeof x->w);
}

typedef struct collect {
    tkey *t;
    idbits *ids;
    uint32_t n, cap;
} collect;
static int collect_tri(void *ctx, const subd_tri *t)
{
    collect *c = (collect *)ctx;
    FZ_CHECK(c->n < c->cap, "sr48 stream: more triangles than the uniform level", c->n, c->cap);
    for (uint32_t i = 0; i < 3u; i++) {
        idbits *e = &c->ids[3u * c->n + i];
        e->id = t->id[i];
        for (uint32_t k = 0; k < 3u; k++) {
            c->t[c->n].w[3u * i + k] = subd_real_bits(t->pos[i][k]);
            e->w[k] = subd_real_bits(t->pos[i][k]);
        }
    }
    c->n++;
    return 0;
}
static int count_tri(void *ctx, const subd_tri *t)
{
    (void)t;
    ++*(uint32_t *)ctx;
    return 0;
}

/* The reference: build(steps = max_level) and extract; 1 with *out filled (arena kept open
 * in *fa for the caller to close), 0 when it does not fit or fails (status in *st). */
static int reference(const subd_mesh *in, uint32_t flags, const subd_sr48_adapt *ad, fz_arena *fa, subd_mesh *out,
                     int *pst, int *xplan_st)
{
    subd_sr48_opts o = {ad->max_level, flags};
    subd_sr48 h;
    subd_diag d;
    uint32_t bound = 0, xp = 0;
    *xplan_st = 1;
    int st = subd_sr48_plan(in, &o, SUBD_SR48_CLUSTERS_UNKNOWN, &bound, &d);
    *pst = st;
    if (st != SUBD_OK || bound > FZ_MAX_ARENA / 2u)
        return 0;
    fz_arena_open(fa, FZ_MAX_ARENA);
    st = subd_sr48_build(&fa->a, in, &o, &h, &d);
    *pst = st;
    if (st != SUBD_OK) {
        fz_arena_close(fa);
        return 0;
    }
    *xplan_st = subd_sr48_extract_plan(&h, ad, &xp, &d);
    if (*xplan_st != SUBD_OK || xp > subd_arena_free_bytes(&fa->a)) {
        *pst = *xplan_st;
        fz_arena_close(fa);
        return 0;
    }
    st = subd_sr48_extract(&fa->a, &h, ad, out, NULL, &d);
    *pst = st;
    if (st != SUBD_OK) {
        fz_arena_close(fa);
        return 0;
    }
    return 1;
}

int FUZZ_ENTRY(const uint8_t *data, size_t size)
{
    if (size > 4096)
        return 0;
    cur c = {data, size, 0};
    fz_snap data_snap, in_snap, desc_snap;
    fz_snap_take(&data_snap, data, size);
    fz_decoded dm;
    fz_decode_mesh(&c, &dm);
    subd_face_list fl;
    memset(&fl, 0, sizeof fl);
    fl.num_verts = dm.nv;
    fl.pos = dm.pos;
    fl.num_faces = dm.nf;
    fl.face_size = dm.fsize;
    fl.index = dm.idx;
    uint32_t plan = 0;
    subd_diag d;
    int st = subd_mesh_plan(&fl, &plan);
    if (st != SUBD_OK || plan > FZ_MAX_ARENA) {
        fz_snap_free(&data_snap);
        return 0;
    }
    fz_arena in_arena;
    fz_arena_open(&in_arena, plan);
    subd_mesh in;
    st = subd_mesh_build(&in_arena.a, &fl, &in, &d);
    if (st != SUBD_OK) {
        fz_arena_close(&in_arena);
        fz_snap_free(&data_snap);
        return 0;
    }
    fz_snap_take(&in_snap, in_arena.block, in_arena.a.used);
    fz_snap_take(&desc_snap, &in, sizeof in);

    /* the base, in an arena of its exact plan */
    uint8_t fb = u8(&c);
    uint32_t flags = fb < 240u ? fb % 2u : fb % 4u;
    uint32_t bound = 0, clusters = SUBD_SR48_CLUSTERS_UNKNOWN, bplan = 0;
    st = subd_sr48_base_plan(&in, flags, SUBD_SR48_CLUSTERS_UNKNOWN, &bound);
    fz_status_known(st, 0, "subd_sr48_base_plan");
    if (st != SUBD_OK || bound > FZ_MAX_ARENA)
        goto done;
    {
        fz_arena ca;
        fz_arena_open(&ca, bound);
        st = subd_sr48_count_clusters(&ca.a, &in, &clusters, &d);
        fz_status_known(st, 0, "subd_sr48_count_clusters");
        fz_arena_close(&ca);
        if (st != SUBD_OK)
            goto done;
    }
    st = subd_sr48_base_plan(&in, flags, clusters, &bplan);
    FZ_CHECK(st == SUBD_OK && bplan <= bound, "subd_sr48_base_plan exact <= bound", bplan, bound);
    fz_arena ba;
    fz_arena_open(&ba, bplan);
    subd_sr48 base;
    st = subd_sr48_base(&ba.a, &in, flags, &base, &d);
    fz_status_known(st, 0, "subd_sr48_base");
    fz_arena_after(&ba, st, 0, bplan, "subd_sr48_base");
    fz_snap_check(&in_snap, "subd_sr48_base");
    fz_snap_check(&desc_snap, "subd_sr48_base");
    FZ_CHECK(st != SUBD_ERR_NOMEM, "subd_sr48_base in its plan", st, bplan);
    if (st != SUBD_OK) {
        fz_arena_close(&ba);
        goto done;
    }

    /* the cut */
    subd_sr48_stream_opts so;
    memset(&so, 0, sizeof so);
    subd_sr48_adapt *ad = &so.adapt;
    uint8_t mb = u8(&c);
    ad->mode = (subd_sr48_adapt_mode)(mb < 250u ? mb % 6u : 6u + (mb & 1u) * 100u);
    uint8_t lb = u8(&c);
    ad->max_level = lb < 250u ? lb % 5u : SUBD_SR48_MAX_STEPS + 1u;
    for (int k = 0; k < 3; k++) {
        ad->point[k] = fz_coord(0, u8(&c), 0);
        ad->normal[k] = fz_coord(0, u8(&c), 0);
    }
    uint8_t rb = u8(&c);
    ad->radius = rb < 64u ? 0 : fz_coord(0, rb, 0);
    ad->axis = u8(&c) % 4u;
    ad->eps = fz_coord(0, u8(&c), 0);
    ad->fn = u8(&c) < 8u ? NULL : view_cb;
    for (int k = 0; k < 3; k++)
        g_view[k] = (double)(int8_t)u8(&c) / 32.0;
    g_vr = (double)(1u + u8(&c)) / 128.0;
    g_vmax = ad->max_level;

    uint32_t splan = 0;
    memset(&d, 0x5A, sizeof d);
    int sps = subd_sr48_stream_plan(&base, &so, &splan, &d);
    fz_status_known(sps, 0, "subd_sr48_stream_plan");
    FZ_CHECK(d.status == sps && d.bytes_needed == 0u, "subd_sr48_stream_plan fills diag", d.status, d.bytes_needed);
    FZ_CHECK(sps == SUBD_OK || splan == 0u, "subd_sr48_stream_plan: *bytes only on success", sps, splan);

    /* the reference (the materialised hierarchy and cut) */
    fz_arena ra;
    subd_mesh out;
    int rst = 0, xps = 1;
    int have = reference(&in, flags, ad, &ra, &out, &rst, &xps);
    int streams = ad->mode != SUBD_SR48_ADAPT_CHORD;
    if (xps != 1 && streams)
        FZ_CHECK(xps == sps, "stream plan status = extraction plan status", sps, xps);

    if (sps == SUBD_OK && splan <= FZ_MAX_ARENA) {
        uint32_t cap = base.level_tri[1] << (ad->max_level > 8u ? 8u : ad->max_level), n = 0;
        subd_tri_sink sink;
        /* plan - 1: NOMEM, bytes_needed = the plan, nothing emitted, arena unchanged */
        if (splan > 0u) {
            fz_arena sa;
            fz_arena_open(&sa, splan - 1u);
            sink.tri = count_tri;
            sink.ctx = &n;
            st = subd_sr48_stream(&sa.a, &base, &so, &sink, &d);
            FZ_CHECK(st == SUBD_ERR_NOMEM && d.bytes_needed == splan && n == 0u,
                     "sr48 stream below the plan: NOMEM, bytes_needed = plan, nothing emitted", st, d.bytes_needed);
            fz_arena_after(&sa, st, 0, splan, "subd_sr48_stream (plan - 1)");
            FZ_CHECK(sa.a.peak == 0u, "sr48 stream below the plan takes nothing", sa.a.peak, 0);
            fz_arena_close(&sa);
        }
        /* the plan: every triangle, the arena handed back */
        if (ad->max_level <= 8u) {
            collect col;
            col.cap = cap;
            col.n = 0;
            col.t = (tkey *)malloc((size_t)cap * sizeof(tkey) + 1u);
            col.ids = (idbits *)malloc(3u * (size_t)cap * sizeof(idbits) + 1u);
            FZ_CHECK(col.t && col.ids, "malloc", cap, 0);
            fz_arena sa;
            fz_arena_open(&sa, splan);
            sink.tri = collect_tri;
            sink.ctx = &col;
            st = subd_sr48_stream(&sa.a, &base, &so, &sink, &d);
            fz_status_known(st, 0, "subd_sr48_stream");
            FZ_CHECK(st != SUBD_ERR_NOMEM, "subd_sr48_stream in its plan", st, splan);
            fz_arena_after(&sa, st, 0, splan, "subd_sr48_stream");
            FZ_CHECK(subd_arena_mark(&sa.a) == 0u, "subd_sr48_stream hands the arena back", subd_arena_mark(&sa.a), st);
            fz_arena_close(&sa);
            fz_snap_check(&in_snap, "subd_sr48_stream");
            if (have && streams) {
                if (st != SUBD_OK) {
                    /* the extraction succeeded on the same surface: only an overflow the
                     * extraction never computes could stop the stream */
                    FZ_CHECK(st == SUBD_ERR_RANGE, "sr48 stream fails where the extraction works", st, 0);
                } else {
                    FZ_CHECK(col.n == out.num_faces, "sr48 stream: the extraction's face count", col.n, out.num_faces);
                    tkey *ref = (tkey *)malloc((size_t)out.num_faces * sizeof(tkey) + 1u);
                    FZ_CHECK(ref != NULL, "malloc", out.num_faces, 0);
                    for (uint32_t f = 0; f < out.num_faces; f++)
                        for (uint32_t i = 0; i < 3u; i++)
                            for (uint32_t k = 0; k < 3u; k++)
                                ref[f].w[3u * i + k] = subd_real_bits(out.pos[3u * out.corner_vert[3u * f + i] + k]);
                    qsort(ref, out.num_faces, sizeof(tkey), tkey_cmp);
                    qsort(col.t, col.n, sizeof(tkey), tkey_cmp);
                    FZ_CHECK(memcmp(ref, col.t, (size_t)col.n * sizeof(tkey)) == 0,
                             "sr48 stream: the extraction's triangles (corner bits)", col.n, 0);
                    free(ref);
                    /* ids: equal ids carry equal bits; as many ids as extraction vertices */
                    qsort(col.ids, 3u * (size_t)col.n, sizeof(idbits), idbits_cmp);
                    uint32_t distinct = col.n ? 1u : 0u;
                    for (uint32_t i = 1; i < 3u * col.n; i++) {
                        if (col.ids[i].id != col.ids[i - 1u].id) {
                            distinct++;
                            continue;
                        }
                        FZ_CHECK(memcmp(col.ids[i].w, col.ids[i - 1u].w, sizeof col.ids[i].w) == 0,
                                 "sr48 stream: one position per id", i, 0);
                    }
                    FZ_CHECK(distinct == out.num_verts, "sr48 stream: one id per extraction vertex", distinct,
                             out.num_verts);
                }
            }
            if (getenv("FZ_VERBOSE")) /* what an input exercised (corpus curation) */
                fprintf(stderr, "sr48s: mode %d max_level %u stream %d (%u triangles) reference %d (%u faces)\n",
                        (int)ad->mode, ad->max_level, st, col.n, have ? 0 : rst, have ? out.num_faces : 0u);
            free(col.t);
            free(col.ids);
        }
    } else if (have && streams && sps != SUBD_OK) {
        FZ_CHECK(0, "sr48 stream plan refuses a cut the extraction makes", sps, 0);
    }
    if (have)
        fz_arena_close(&ra);
    fz_arena_close(&ba);
done:
    fz_snap_check(&data_snap, "fuzz_sr48s");
    fz_snap_free(&in_snap);
    fz_snap_free(&desc_snap);
    fz_snap_free(&data_snap);
    fz_arena_close(&in_arena);
    return 0;
}
