/* SPDX-License-Identifier: MIT */
/* The semi-regular 4-8 stream (subd_sr48_stream) against the materialised hierarchy, every
 * mode on every shape (issue 20's "Done when"), with a face-set comparison that does not
 * depend on positions, so cuts with coincident faces are compared too.
 *
 * Shapes: tetrahedron (closed, input valence 3; smoothed, its coarse cuts have distinct
 * vertices at identical positions), cube of triangles (closed), icosahedron (closed), hexagon
 * fan (open), 8x8 grid (open), two triangles + one (pre-processing splits an isolated
 * triangle; open), torus (closed, genus 1) and closed bipyramids whose apexes have valence
 * 3..12 (the base then has vertices of valence 4 to 12: checked).
 * Modes: UNIFORM, POINT (radius, default radius), RAMP (x, y, z), PLANE, CALLBACK (a monotone
 * viewer function), CHORD (two tolerances); smoothing on and off; levels 0.. (fewer on the
 * device, whose RAM and time are small); both arithmetics through the build.
 *
 * For every cut, independently of the stream's code:
 *  - ids: the closed form of include/subd_sr48.h recomputed from the hierarchy of
 *    subd_sr48_build(steps = L) (a level-0 vertex keeps its index; the vertex made at level k
 *    by the diamond whose lower triangle is the i-th of level k-1 gets V0 + T0 (2^(k-1) - 1) +
 *    i); every streamed corner's id names a hierarchy vertex whose position has the corner's
 *    bits;
 *  - every streamed triangle is a hierarchy triangle: the one of level t.level below level-0
 *    triangle t.face with exactly these corners (apex, b0, b1) in this order;
 *  - UNIFORM, POINT, RAMP, PLANE, CALLBACK: the streamed set is subd_sr48_extract's: the
 *    extraction's vertices are the used hierarchy vertices in increasing order, so a streamed
 *    triangle's corners name extraction vertices by rank; each extraction face is hit exactly
 *    once (faces are matched by vertex numbers, not positions: coincident faces are told
 *    apart), the used vertices have the extraction's bits, and the ids are a bijection onto
 *    them; UNIFORM also in the extraction's order; the extraction forces no split (these
 *    modes are nested) and CALLBACK's function is called as often by the stream as by it;
 *  - CHORD: every hierarchy vertex (level <= L) lies within eps (+ 2^-16 per axis in Q16.16,
 *    1e-6 in float32) of the nearest streamed triangle (brute force, double); the cut has at
 *    least subd_sr48_extract(CHORD)'s faces and at most the uniform cut's;
 *  - conformity, welded by id: no directed edge twice; an edge without its reverse joins two
 *    boundary vertices of the hierarchy (found from the base's boundary edges and the
 *    half-diamonds' new vertices); a closed input gives none (a closed 2-manifold); V - E + F
 *    is the input's Euler characteristic;
 *  - the arena: plan = the mode's macro (SUBD_SR48_STREAM_BYTES / _ADAPT_ / _CHORD_) = the
 *    peak, and the arena is given back. */
#include <stdlib.h> /* qsort, bsearch: the extraction's faces and the welded edges, sorted */
#include <string.h>
#include "harness.h"
#include "corpus.h"
#include "fixtures.h"
#if H_HOST
#include <stdio.h>
#define SH_NOTE(...) printf(__VA_ARGS__)
#else
#define SH_NOTE(...) ((void)0)
#endif

#define SH_ST_ARENA (96u * 1024u) /* the stream's arena: the top of h_arena_buf */
#define SH_MAT_ARENA (H_ARENA_BYTES - SH_ST_ARENA)
#define SH_MAXF (H_HOST ? 16384u : 1024u)  /* streamed triangles kept */
#define SH_MAXID (H_HOST ? 65536u : 4096u) /* closed-form id space */
#define SH_MAXV (H_HOST ? 32768u : 2048u)  /* hierarchy vertices */

static uint32_t g_bn = 5; /* the bipyramid's apex valence */

/* ------------------------------------------------------------------------------------ */
/* The sink: every triangle kept. */
typedef struct sh_sink {
    uint32_t n, over;
} sh_sink;
static uint64_t g_id[3u * SH_MAXF];
static subd_real g_pos[9u * SH_MAXF];
static uint32_t g_face[SH_MAXF], g_level[SH_MAXF];
static sh_sink g_s;

static int sh_tri(void *ctx, const subd_tri *t)
{
    sh_sink *k = (sh_sink *)ctx;
    uint32_t c, q;
    if (k->n >= SH_MAXF) {
        k->over = 1;
        return 0;
    }
    for (c = 0; c < 3u; c++) {
        g_id[3u * k->n + c] = t->id[c];
        for (q = 0; q < 3u; q++) g_pos[9u * k->n + 3u * c + q] = t->pos[c][q];
    }
    g_face[k->n] = t->face;
    g_level[k->n] = t->level;
    k->n++;
    return 0;
}

/* The closed-form ids over the hierarchy (fx_sr48_id_map): g_map[id] = hierarchy vertex. */
static uint32_t g_map[SH_MAXID];

/* Boundary vertices of the hierarchy, from its structure: the ends of level-0 base edges
 * without a neighbour, the three vertices on a hybrid triangle's boundary base edge (its
 * ends and the level-0 vertex that split it), and the new vertex of every half-diamond. */
static uint8_t g_bnd[SH_MAXV];
static void sh_boundary(const subd_sr48 *h, const subd_sr48 *base, uint32_t levels)
{
    uint32_t k, t, H;
    for (t = 0; t < h->num_verts && t < SH_MAXV; t++) g_bnd[t] = 0;
    for (H = 0; H < base->level_tri[1] / 2u; H++)
        if (base->hyb_base_nb[H] == SUBD_NONE) {
            /* children 2H = (m; c, a), 2H+1 = (m; b, c): the base a-b is split at m */
            g_bnd[base->tri_vert[3u * (2u * H)]] = 1;
            g_bnd[base->tri_vert[3u * (2u * H) + 2u]] = 1;
            g_bnd[base->tri_vert[3u * (2u * H + 1u) + 1u]] = 1;
        }
    for (k = 0; k <= levels; k++)
        for (t = h->level_tri[k]; t < h->level_tri[k + 1u]; t++) {
            if (h->tri_base_nb[t] != SUBD_NONE) continue;
            g_bnd[h->tri_vert[3u * t + 1u]] = 1;
            g_bnd[h->tri_vert[3u * t + 2u]] = 1;
            if (k < levels) g_bnd[h->tri_vert[3u * (h->level_tri[k + 1u] + 2u * (t - h->level_tri[k]))]] = 1;
        }
}

static uint64_t g_key[2u * SH_MAXF];  /* extraction faces: (corner key, face), sorted   */
static uint8_t g_hit[SH_MAXF];
static uint32_t g_rank[SH_MAXV];      /* hierarchy vertex -> extraction vertex + 1       */
static uint64_t g_edge[2u * 3u * SH_MAXF];

static int sh_cmp2(const void *a, const void *b)
{
    const uint64_t *x = (const uint64_t *)a, *y = (const uint64_t *)b;
    if (x[0] != y[0]) return x[0] < y[0] ? -1 : 1;
    return x[1] < y[1] ? -1 : x[1] > y[1];
}
static int sh_cmp1(const void *a, const void *b)
{
    uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return x < y ? -1 : x > y;
}
static uint64_t sh_fkey(uint32_t a, uint32_t b, uint32_t c)
{
    return ((uint64_t)a << 42) | ((uint64_t)b << 21) | (uint64_t)c;
}

/* What the cases covered (printed on the host, some checked at the end). */
static uint32_t g_cases, g_coincident, g_faces, g_chord_faces, g_chord_exact, g_uni, g_vmin = 99, g_vmax;
static uint32_t g_modes_seen;

/* CALLBACK: a viewer at g_view, one level per g_vr of distance from the box (monotone). */
static double g_view[3] = {0.6, 0.2, 0.9}, g_vr = 0.25;
static uint32_t g_want_max, g_view_calls;
static uint32_t sh_view_level(void *ctx, const subd_real *lo, const subd_real *hi)
{
    double d2 = 0, lim;
    uint32_t i, n;
    (void)ctx;
    g_view_calls++;
    for (i = 0; i < 3u; i++) {
        double l = h_dbl(lo[i]), u = h_dbl(hi[i]);
        double e = g_view[i] < l ? l - g_view[i] : g_view[i] > u ? g_view[i] - u : 0;
        d2 += e * e;
    }
    for (n = 0; n <= g_want_max; n++) {
        lim = (double)(g_want_max - n) * g_vr;
        if (lim * lim <= d2) return n;
    }
    return g_want_max;
}

/* One cut of one shape: every property of the file comment. */
static void sh_case(int shape, uint32_t levels, uint32_t flags, const subd_sr48_adapt *ad0, const char *hash)
{
    subd_arena a, sa;
    static subd_mesh in, out; /* static: the device's stack limit */
    static subd_sr48 h, base;
    static subd_sr48_adapt_report rep;
    subd_sr48_opts o;
    subd_sr48_stream_opts so;
    subd_diag d;
    subd_tri_sink sink;
    uint32_t plan = 0, want, nid = 0, i, c, q, bad = 0, ne = 0, nb = 0, nvert = 0, nused = 0, val, low = 0, xcalls;
    int chord = ad0->mode == SUBD_SR48_ADAPT_CHORD, uniform = ad0->mode == SUBD_SR48_ADAPT_UNIFORM;
    subd_arena_init(&a, h_arena_buf, SH_MAT_ARENA);
    if (!fx_sr48_shape(shape, g_bn, &a, &in)) return;
    o.steps = levels;
    o.flags = flags;
    if (!CHECK_EQ(subd_sr48_build(&a, &in, &o, &h, &d), SUBD_OK)) return;
    so.adapt = *ad0;
    so.adapt.max_level = levels;
    g_want_max = levels;
    g_view_calls = 0;
    if (!CHECK_EQ(subd_sr48_extract(&a, &h, &so.adapt, &out, &rep, &d), SUBD_OK)) {
        SH_NOTE("shape %d levels %u flags %u mode %u: extract status %d needs %u\n", shape, levels, flags,
                (unsigned)ad0->mode, d.status, d.bytes_needed);
        return;
    }
    if (!CHECK(out.num_faces <= SH_MAXF && h.num_verts <= SH_MAXV)) return;
    xcalls = g_view_calls;
    if (!chord) CHECK_EQ(rep.forced_splits, 0u); /* nested modes: the cut is the diamonds that ask */
    if (!CHECK_EQ(subd_sr48_base(&a, &in, flags, &base, &d), SUBD_OK)) {
        SH_NOTE("shape %d levels %u: base status %d needs %u\n", shape, levels, d.status, d.bytes_needed);
        return;
    }
    val = fx_sr48_valence(&base, &low);
    if (val > g_vmax) g_vmax = val;
    if (low < g_vmin) g_vmin = low;
    if (!CHECK_EQ(subd_sr48_stream_plan(&base, &so, &plan, &d), SUBD_OK)) return;
    want = chord ? SUBD_SR48_STREAM_CHORD_BYTES(levels, val)
                 : uniform ? SUBD_SR48_STREAM_BYTES(levels, val) : SUBD_SR48_STREAM_ADAPT_BYTES(levels, val);
    CHECK_EQ(plan, want);
    if (!CHECK(plan <= SH_ST_ARENA)) return;
    subd_arena_init(&sa, h_arena_buf + SH_MAT_ARENA, SH_ST_ARENA);
    g_s.n = 0;
    g_s.over = 0;
    sink.tri = sh_tri;
    sink.ctx = &g_s;
    subd_arena_reset_peak(&sa);
    g_view_calls = 0;
    if (!CHECK_EQ(subd_sr48_stream(&sa, &base, &so, &sink, &d), SUBD_OK)) {
        SH_NOTE("shape %d levels %u flags %u mode %u: status %d\n", shape, levels, flags, (unsigned)ad0->mode,
                d.status);
        return;
    }
    CHECK_EQ(g_view_calls, xcalls); /* CALLBACK: one call per evaluated triangle, as the extraction */
    CHECK_EQ(sa.peak, plan);
    CHECK_EQ(subd_arena_mark(&sa), 0u);
    if (!CHECK_EQ(g_s.over, 0u)) return;
    g_cases++;
    g_modes_seen |= 1u << (uint32_t)ad0->mode;
    if (hash) { /* host = device: the streamed triangles' bits and ids, in order */
        uint32_t hv = 2166136261u;
        for (i = 0; i < 9u * g_s.n; i++) {
            uint32_t b = subd_real_bits(g_pos[i]);
            hv = h_fnv(hv, &b, 4);
        }
        for (i = 0; i < 3u * g_s.n; i++) hv = h_fnv(hv, &g_id[i], 8);
        h_hash(hash, hv);
    }

    /* ids -> hierarchy vertices, bits; every triangle a hierarchy triangle */
    if ((nid = fx_sr48_id_map(&h, levels, g_map, SH_MAXID)) == 0u) return;
    for (i = 0; i < h.num_verts; i++) g_rank[i] = 0;
    for (i = 0; i < g_s.n; i++) {
        uint32_t v[3], k = g_level[i], f = g_face[i], t, t0;
        for (c = 0; c < 3u; c++) {
            uint64_t id = g_id[3u * i + c];
            v[c] = id < nid ? g_map[(uint32_t)id] : SUBD_NONE;
            if (v[c] == SUBD_NONE || v[c] >= h.num_verts) {
                bad++;
                v[c] = 0;
                continue;
            }
            g_rank[v[c]] = 1;
            for (q = 0; q < 3u; q++)
                if (!h_same(g_pos[9u * i + 3u * c + q], h.pos[3u * v[c] + q])) bad++;
        }
        if (k > levels || f >= h.level_tri[1] || (uniform && k != levels)) {
            bad++;
            continue;
        }
        t0 = h.level_tri[k] + (f << k);
        for (t = t0; t < t0 + (1u << k); t++)
            if (h.tri_vert[3u * t] == v[0] && h.tri_vert[3u * t + 1u] == v[1] && h.tri_vert[3u * t + 2u] == v[2])
                break;
        if (t == t0 + (1u << k)) bad++;
    }
    if (!CHECK_EQ(bad, 0u))
        SH_NOTE("shape %d levels %u flags %u mode %u: %u id/position/triangle mismatches\n", shape, levels, flags,
                (unsigned)ad0->mode, bad);
    /* used hierarchy vertices -> their rank (the extraction's numbering) */
    for (i = 0; i < h.num_verts; i++)
        if (g_rank[i]) g_rank[i] = ++nused;

    if (!chord) {
        /* the extraction's faces by vertex numbers; coincident corner positions counted */
        uint32_t coinc = 0;
        CHECK_EQ(nused, out.num_verts);
        CHECK_EQ(g_s.n, out.num_faces);
        for (i = 0; i < out.num_faces; i++) {
            const uint32_t *cv = out.corner_vert + 3u * i;
            g_key[2u * i] = sh_fkey(cv[0], cv[1], cv[2]);
            g_key[2u * i + 1u] = i;
            g_hit[i] = 0;
        }
        qsort(g_key, out.num_faces, 2u * sizeof(uint64_t), sh_cmp2);
        for (i = 0; i + 1u < out.num_faces && !coinc; i++) {
            const uint32_t *x = out.corner_vert + 3u * i;
            uint32_t j;
            for (j = i + 1u; j < out.num_faces && !coinc; j++) {
                const uint32_t *y = out.corner_vert + 3u * j;
                uint32_t same = 1;
                for (c = 0; c < 9u && same; c++)
                    same = h_same(out.pos[3u * x[c / 3u] + c % 3u], out.pos[3u * y[c / 3u] + c % 3u]);
                coinc = same;
            }
            if (!H_HOST) break; /* the device looks at the first face only (time) */
        }
        if (coinc) g_coincident++;
        bad = 0;
        for (i = 0; i < g_s.n; i++) {
            uint64_t k[2];
            const uint64_t *r;
            uint32_t r3[3], f;
            for (c = 0; c < 3u; c++) {
                uint64_t id = g_id[3u * i + c];
                uint32_t v = id < nid ? g_map[(uint32_t)id] : SUBD_NONE;
                r3[c] = v < h.num_verts && g_rank[v] ? g_rank[v] - 1u : 0x1fffffu;
            }
            k[0] = sh_fkey(r3[0], r3[1], r3[2]);
            k[1] = 0;
            r = (const uint64_t *)bsearch(k, g_key, out.num_faces, 2u * sizeof(uint64_t), sh_cmp1);
            if (!r) {
                bad++;
                continue;
            }
            f = (uint32_t)r[1];
            if (g_hit[f]++) bad++;
            if (uniform && f != i) bad++; /* UNIFORM: the extraction's order */
            for (c = 0; c < 3u; c++)
                for (q = 0; q < 3u; q++)
                    if (!h_same(g_pos[9u * i + 3u * c + q], out.pos[3u * r3[c] + q])) bad++;
        }
        for (i = 0; i < out.num_faces; i++)
            if (g_hit[i] != 1u) bad++;
        if (!CHECK_EQ(bad, 0u))
            SH_NOTE("shape %d levels %u flags %u mode %u: face set differs (%u)\n", shape, levels, flags,
                    (unsigned)ad0->mode, bad);
        g_faces += g_s.n;
    } else {
        /* the guarantee: every hierarchy vertex within eps of the streamed mesh */
        double eps = h_dbl(so.adapt.eps), slack = SUBD_FIXED ? 4.0 / 65536.0 : 1e-6;
        double worst = fx_worst_dist2(h.pos, h.num_verts, g_pos, g_s.n, (eps + slack) * (eps + slack));
        if (!CHECK(worst <= (eps + slack) * (eps + slack)))
            SH_NOTE("shape %d levels %u flags %u eps %g: worst squared distance %g\n", shape, levels, flags, eps, worst);
        CHECK(g_s.n >= out.num_faces);
        CHECK(g_s.n <= rep.uniform_faces);
        g_chord_faces += g_s.n;
        g_chord_exact += out.num_faces;
    }
    g_uni += rep.uniform_faces;

    /* welded by id: conforming; the boundary on the hierarchy's boundary; Euler */
    if (!CHECK(h.num_verts <= SH_MAXV)) return;
    sh_boundary(&h, &base, levels);
    for (i = 0; i < g_s.n; i++)
        for (c = 0; c < 3u; c++) {
            g_edge[2u * ne] = g_id[3u * i + c];
            g_edge[2u * ne + 1u] = g_id[3u * i + (c + 1u) % 3u];
            ne++;
        }
    qsort(g_edge, ne, 2u * sizeof(uint64_t), sh_cmp2);
    bad = 0;
    for (i = 0; i < ne; i++) {
        uint64_t r[2];
        if (i > 0u && g_edge[2u * i] == g_edge[2u * i - 2u] && g_edge[2u * i + 1u] == g_edge[2u * i - 1u]) bad++;
        if (i == 0u || g_edge[2u * i] != g_edge[2u * i - 2u]) nvert++;
        r[0] = g_edge[2u * i + 1u];
        r[1] = g_edge[2u * i];
        if (bsearch(r, g_edge, ne, 2u * sizeof(uint64_t), sh_cmp2)) continue;
        nb++;
        if (r[0] >= nid || r[1] >= nid || !g_bnd[g_map[(uint32_t)r[0]]] || !g_bnd[g_map[(uint32_t)r[1]]]) bad++;
    }
    if (!CHECK_EQ(bad, 0u))
        SH_NOTE("shape %d levels %u flags %u mode %u: %u welding faults\n", shape, levels, flags, (unsigned)ad0->mode,
                bad);
    CHECK_EQ(nb == 0u, in.num_boundary_edges == 0u);
    /* every vertex starts an edge (a closed fan or a boundary fan): the distinct ids */
    CHECK_EQ(nvert, nused);
    CHECK_EQ((int32_t)nvert - (int32_t)((ne - nb) / 2u + nb) + (int32_t)g_s.n,
             (int32_t)(in.num_verts - in.num_isolated) - (int32_t)in.num_edges + (int32_t)in.num_faces);
}

/* The adaptation settings: UNIFORM, PLANE, POINT (radius 0.15; 0.6 from below), RAMP x, y,
 * z, POINT's default radius, CALLBACK, CHORD 0.05 and 0.01. */
#define SH_SETTINGS 11u
static void sh_setting(uint32_t m, subd_sr48_adapt *ad)
{
    memset(ad, 0, sizeof *ad);
    switch (m) {
    case 0: ad->mode = SUBD_SR48_ADAPT_UNIFORM; break;
    case 1:
        ad->mode = SUBD_SR48_ADAPT_PLANE;
        ad->point[0] = fx_real(0.1);
        ad->normal[0] = fx_real(1); ad->normal[1] = fx_real(0.5); ad->normal[2] = fx_real(0.25);
        break;
    case 2: case 3:
        ad->mode = SUBD_SR48_ADAPT_POINT;
        ad->point[0] = fx_real(0.5); ad->point[1] = fx_real(0.4); ad->point[2] = fx_real(m == 2u ? 0.3 : -2);
        ad->radius = fx_real(m == 2u ? 0.15 : 0.6);
        break;
    case 4: case 5: case 6: ad->mode = SUBD_SR48_ADAPT_RAMP; ad->axis = m - 4u; break;
    case 7:
        ad->mode = SUBD_SR48_ADAPT_POINT;
        ad->point[0] = fx_real(0.5); ad->point[1] = fx_real(0.4); ad->point[2] = fx_real(0.3);
        break;
    case 8: ad->mode = SUBD_SR48_ADAPT_CALLBACK; ad->fn = sh_view_level; break;
    default: ad->mode = SUBD_SR48_ADAPT_CHORD; ad->eps = fx_real(m == 9u ? 0.05 : 0.01); break;
    }
}

/* Every setting on the fixed shapes, smoothing on and off, levels 0..maxl (the device: a
 * subset, levels <= 2, CHORD at <= 1: its RAM and its time limit). make test stops the host
 * at level 3; make test-long goes on to 5 on the tetrahedron and the two triangles, 4 on the
 * cube (the levels test_sr48_stream.c's adaptive comparison had). */
static void sr48sh_shapes(void)
{
    static const uint32_t maxl[FX48_BIPYR] = {H_HOST ? 5u : 2u, H_HOST ? 4u : 2u, H_HOST ? 3u : 1u, H_HOST ? 3u : 2u,
                                           H_HOST ? 1u : 0u, H_HOST ? 5u : 2u, H_HOST ? 3u : 1u};
    static const char *const names[FX48_BIPYR] = {"sr48sh_tet", "sr48sh_cube", "sr48sh_ico", "sr48sh_hexfan",
                                                "sr48sh_grid", "sr48sh_two", "sr48sh_torus"};
    subd_sr48_adapt ad;
    uint32_t s, l, f, m;
    for (m = 0; m < SH_SETTINGS; m++) {
        sh_setting(m, &ad);
        for (s = 0; s < FX48_BIPYR; s++)
            for (f = 0; f < 2u; f++)
                for (l = 0; l <= maxl[s]; l++) {
                    uint32_t lim = H_HOST && !h_long && maxl[s] > 3u ? 3u : maxl[s];
                    if (m >= 9u) lim = H_HOST ? (lim > 2u ? 2u + (s == FX48_TET || s == FX48_TWO) : lim) : (lim > 1u ? 1u : lim);
                    if (!H_HOST && f && m != 0u && m != 9u) continue;
                    if (l > lim) continue;
                    /* hashes where the host and the device both run the case */
                    sh_case((int)s, l, f ? SUBD_SR48_NO_SMOOTH : 0u, &ad,
                            (l == 1u && !f && s != FX48_GRID && (m == 0u || m == 8u || m == 9u)) ? names[s] : 0);
                }
    }
    /* every mode was streamed; the tetrahedron's coincident faces were compared */
    CHECK_EQ(g_modes_seen, 0x3fu);
    if (H_HOST) CHECK(g_coincident > 0u);
    CHECK(g_chord_faces >= g_chord_exact && g_chord_faces > 0u);
    SH_NOTE("stream = extraction: %u cuts (%u with coincident faces), %u faces; chord %u faces against %u "
            "exact (%.3fx)\n",
            g_cases, g_coincident, g_faces, g_chord_faces, g_chord_exact,
            (double)g_chord_faces / (double)(g_chord_exact ? g_chord_exact : 1u));
}

/* Bipyramids with apexes of valence 3..12: every mode at level 2 (UNIFORM, PLANE, POINT,
 * RAMP z, POINT's default radius, CALLBACK, CHORD 0.05; the device: UNIFORM, PLANE and CHORD
 * at level 1), smoothing on and off. */
static void sr48sh_valences(void)
{
    subd_sr48_adapt ad;
    uint32_t m, f;
    g_vmin = 99;
    g_vmax = 0;
    for (g_bn = 3; g_bn <= 12u; g_bn++)
        for (m = 0; m < SH_SETTINGS; m++) {
            if (m == 3u || m == 4u || m == 5u || m == 10u) continue;
            if (!H_HOST && m != 0u && m != 1u && m != 9u) continue;
            sh_setting(m, &ad);
            for (f = 0; f < 2u; f++) sh_case(FX48_BIPYR, H_HOST ? 2u : 1u, f ? SUBD_SR48_NO_SMOOTH : 0u, &ad, 0);
        }
    g_bn = 5;
    /* the bases have vertices of valence 4 (regular 4-8) up to 12 (the apexes) */
    CHECK_EQ(g_vmin, 4u);
    CHECK_EQ(g_vmax, 12u);
    SH_NOTE("bipyramids n = 3..12: base valences %u..%u\n", g_vmin, g_vmax);
}

/* The adaptive walk's checkpoints (sr48_stream.c, as the uniform walk's): with max_level >
 * SUBD_SR48_STREAM_CKPT_ the level windows 1..max_level - 1 between checkpoints share slots and
 * are rebuilt (with L and their decision state) when the walk returns, and the descents to
 * the finest level keep their windows in the refined window's block. Every nested mode
 * (PLANE, POINT, RAMP x, y, z, POINT's default radius, CALLBACK) at levels 4..6 on the
 * tetrahedron, the two triangles, the cube and the hexagon fan, smoothing on and off, and bipyramids
 * of apex valence 3..12 at level 4, through sh_case: the extraction's set, bits and ids,
 * plan = the macro = the peak (the device: PLANE and POINT on the tetrahedron at level 4). */
static void sr48sh_adapt_checkpoints(void)
{
    static const int shapes[4] = {FX48_TET, FX48_TWO, FX48_CUBE, FX48_HEXFAN};
    static const uint32_t maxl[4] = {6u, 6u, 5u, 4u};
    subd_sr48_adapt ad;
    uint32_t m, s, l, f;
    for (m = 1; m <= 8u; m++) {
        if (!H_HOST && m != 1u && m != 2u) continue;
        sh_setting(m, &ad);
        for (s = 0; s < (H_HOST ? 4u : 1u); s++)
            for (f = 0; f < (H_HOST ? 2u : 1u); f++)
                for (l = 4; l <= (H_HOST ? maxl[s] : 4u); l++)
                    sh_case(shapes[s], l, f ? SUBD_SR48_NO_SMOOTH : 0u, &ad, 0);
        for (g_bn = 3; g_bn <= 12u && H_HOST; g_bn++) sh_case(FX48_BIPYR, 4, 0, &ad, 0);
        g_bn = 5;
    }
}

/* The adaptive plan against a closed form from the plans without checkpoints (one level
 * window per level below max_level: W = plan(3) - plan(2) a window with its L): SLOTS =
 * (L - 1) / CKPT_ + CKPT_ - 1 windows for L - 1 >= CKPT_ and the walk state, 2 words per level
 * 0..L and one per slot, so plan(L) = plan(2) + (SLOTS - 2) W + the state rounded to 8, smaller
 * than plan(2) + (L - 2) W (one window per level); levels 4..16 on a base of valence 8 (the
 * cube) and 12 (a bipyramid). Then every arena below the plan at 5 levels (POINT, RAMP: the
 * adaptation box first) gives SUBD_ERR_NOMEM, bytes_needed = the plan, nothing emitted, the
 * arena unchanged; the plan itself streams the cut with peak = plan. */
static void sr48sh_adapt_plan(void)
{
    subd_arena a;
    subd_mesh in;
    static subd_sr48 base;
    subd_sr48_stream_opts so;
    subd_diag d;
    uint32_t p2, p3, w, l, plan, want, nw, b, m, low = 0;
    for (b = 0; b < 2u; b++) {
        g_bn = 12;
        subd_arena_init(&a, h_arena_buf, SH_MAT_ARENA);
        if (!fx_sr48_shape(b ? FX48_BIPYR : FX48_CUBE, g_bn, &a, &in) ||
            !CHECK_EQ(subd_sr48_base(&a, &in, 0, &base, &d), SUBD_OK))
            break;
        memset(&so, 0, sizeof so);
        so.adapt.mode = SUBD_SR48_ADAPT_PLANE;
        so.adapt.normal[0] = fx_real(1);
        so.adapt.max_level = 2;
        if (!CHECK_EQ(subd_sr48_stream_plan(&base, &so, &p2, &d), SUBD_OK)) break;
        so.adapt.max_level = 3;
        if (!CHECK_EQ(subd_sr48_stream_plan(&base, &so, &p3, &d), SUBD_OK)) break;
        w = p3 - p2;
        for (l = 4; l <= SUBD_SR48_MAX_STEPS; l++) {
            so.adapt.max_level = l;
            if (!CHECK_EQ(subd_sr48_stream_plan(&base, &so, &plan, &d), SUBD_OK)) break;
            nw = l - 1u >= SUBD_SR48_STREAM_CKPT_ ? (l - 1u) / SUBD_SR48_STREAM_CKPT_ + SUBD_SR48_STREAM_CKPT_ - 1u : l;
            want = p2 + (nw - 2u) * w +
                   (l - 1u >= SUBD_SR48_STREAM_CKPT_ ? ((4u * (2u * (l + 1u) + nw)) + 7u) & ~7u : 0u);
            if (!CHECK_EQ(plan, want)) SH_NOTE("adapt plan: base %u levels %u\n", b, l);
            CHECK(plan < p2 + (l - 2u) * w);
        }
    }
    g_bn = 5;
    subd_arena_init(&a, h_arena_buf, SH_MAT_ARENA);
    if (!fx_sr48_shape(FX48_CUBE, g_bn, &a, &in) || !CHECK_EQ(subd_sr48_base(&a, &in, 0, &base, &d), SUBD_OK)) return;
    for (m = 0; m < 2u; m++) {
        memset(&so, 0, sizeof so);
        so.adapt.max_level = 5;
        so.adapt.mode = m ? SUBD_SR48_ADAPT_RAMP : SUBD_SR48_ADAPT_POINT;
        so.adapt.point[0] = fx_real(0.5);
        so.adapt.radius = fx_real(0.2);
        so.adapt.axis = 1;
        if (!CHECK_EQ(subd_sr48_stream_plan(&base, &so, &plan, &d), SUBD_OK)) return;
        CHECK_EQ(plan, SUBD_SR48_STREAM_ADAPT_BYTES(5, fx_sr48_valence(&base, &low)));
        CHECK(fx_sr48_plan_sweep(&base, &so, h_arena_buf + SH_MAT_ARENA, plan, H_HOST ? 13u : 509u, 520u) > 0u);
    }
}

const test_case suite_sr48_stream_shapes[] = {
    {"sr48sh_shapes", sr48sh_shapes},
    {"sr48sh_valences", sr48sh_valences},
    {"sr48sh_adapt_checkpoints", sr48sh_adapt_checkpoints},
    {"sr48sh_adapt_plan", sr48sh_adapt_plan},
    {0, 0},
};
