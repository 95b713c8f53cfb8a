/* SPDX-License-Identifier: MIT */
/* The limit stream's fast paths against the calls they must equal bit for bit:
 *  - subd_loop_limit_reg6 (src/loop_limit.c: the valence-6 masks as fixed sums, float32 with
 *    products by 1, -1 and 0 dropped and the sign-of-zero argument of lim_reg6_axis; Q16.16
 *    regrouped exact integer sums) and its general loop (fast = 0) against subd_loop_limit's
 *    positions and normals, for every smooth valence-6 vertex of jittered tori, and of tori
 *    whose coordinates are chosen to reach the corner cases of that argument: +0 and -0
 *    (differences of -0 only from p = -0, v = +0), the smallest subnormals (halving ties),
 *    large values (float32: near 2^120; Q16.16: 33-bit differences);
 *  - subd_isqrt64 (src/sqrt.c: a Karatsuba step on a 32-bit Newton root) against the
 *    digit-by-digit square root it replaced, written out here: every x < 2^16, squares and
 *    their neighbours, powers of two and random values of every length;
 *  - Q16.16 subd_w3_unit (src/vec3w.c: two 32-bit divisions) against the 64-bit division it
 *    replaced, on random vectors of every length and sign, zeros included.
 * Host and QEMU (fewer random cases on QEMU). The stream itself equals subd_loop_limit on
 * the test shapes in test_loop_stream.c.
 */
#include "harness.h"
#include "../src/loop_limit_internal.h" /* lim_reg6, subd_loop_limit_reg6 */
#include "../src/topo.h"                /* topo_ring */
#include "loop_limit_ref.h"            /* tmesh, tm_torus, tm_build */

static tmesh g_t6;

/* Coordinates for the corner cases (kind 1: zeros of both signs in z; kind 2: tiny values
 * in every coordinate; kind 3: large values), else the torus's own. */
static subd_real r6_coord(uint32_t *s, uint32_t kind, subd_real x)
{
    uint32_t u = h_rand(s);
#if SUBD_FIXED
    if (kind == 1u) return (subd_real)(u & 1u); /* 0 or 1 LSB */
    if (kind == 2u) return (subd_real)(u % 5u) - 2;
    if (kind == 3u) return (subd_real)(int32_t)(u | 1u); /* any int32 but INT32_MIN */
#else
    union { float f; uint32_t b; } c;
    if (kind == 1u) return (u & 1u) ? -0.0f : 0.0f;
    if (kind == 2u) {
        c.b = (u & 3u) | ((u >> 2) & 1u) << 31; /* +-0, +-1, 2, 3 times 2^-149 */
        return c.f;
    }
    if (kind == 3u) {
        c.b = 0x7b000000u + (u & 0x00ffffffu) + ((u >> 24) & 1u) * 0x80000000u; /* |x| ~ 2^119 */
        return c.f;
    }
#endif
    return x;
}

/* Every smooth valence-6 vertex of the torus: its ring copied in subd_loop_limit's order
 * (topo.h's walk from vert_out), then both forms of subd_loop_limit_reg6 against
 * subd_loop_limit. *n: vertices compared. Returns the mismatches. */
static uint32_t r6_torus(uint32_t kind, uint32_t seed, uint32_t *n)
{
    static const int32_t ring[6] = {3, 6, 9, 12, 15, 18};
    subd_arena a;
    subd_mesh m;
    subd_diag d;
    subd_real *pos, *nrm;
    lim_reg6 k, kg;
    uint32_t v, i, c, s = seed, bad = 0, ovf;
    int st;
    tm_torus(&g_t6, 20u, 16u, seed);
    for (i = 0; i < 3u * g_t6.nv; i++) {
        if (kind == 1u && i % 3u != 2u) continue;
        g_t6.pos[i] = r6_coord(&s, kind, g_t6.pos[i]);
    }
    subd_arena_init(&a, h_arena_buf, H_ARENA_BYTES);
    if (!tm_build(&a, &g_t6, &m)) return 1000u;
    st = subd_loop_limit(&a, &m, &(subd_loop_limit_opts){SUBD_LOOP_BOUNDARY_PAPER, SUBD_LOOP_LIMIT_NORMALS}, &pos, &nrm,
                         &d);
    if (st != SUBD_OK) return 1000u;
    subd_loop_limit_reg6_init(&k);
    kg = k;
    kg.fast = 0;
    for (v = 0; v < m.num_verts; v++) {
        loop_vinfo cl;
        topo_ring r;
        subd_real pts[21], p1[3], n1[3], p2[3], n2[3];
        subd_loop_classify(&m, v, &cl);
        if (cl.cls != LOOP_SMOOTH || cl.valence != 6u) continue;
        for (c = 0; c < 3u; c++) pts[c] = m.pos[3u * v + c];
        topo_ring_begin(&r, &m, v);
        for (i = 0; i < 6u && topo_ring_step(&r); i++)
            for (c = 0; c < 3u; c++) pts[3u * (i + 1u) + c] = m.pos[3u * r.nb + c];
        ovf = 0;
        subd_loop_limit_reg6(&k, pts, ring, p1, n1, &ovf);
        subd_loop_limit_reg6(&kg, pts, ring, p2, n2, &ovf);
        for (c = 0; c < 3u; c++) {
            uint32_t want_p = subd_real_bits(pos[3u * v + c]), want_n = subd_real_bits(nrm[3u * v + c]);
            if (subd_real_bits(p1[c]) != want_p || subd_real_bits(n1[c]) != want_n) bad++;
            if (subd_real_bits(p2[c]) != want_p || subd_real_bits(n2[c]) != want_n) bad++;
        }
        if (ovf) bad++; /* subd_loop_limit succeeded: no position overflows */
        ++*n;
    }
    return bad;
}

static void reg6_test(void)
{
    lim_reg6 k;
    uint32_t kind, seed, n = 0, bad = 0;
    subd_loop_limit_reg6_init(&k);
    CHECK_EQ(k.fast, 1); /* the trig tables are the fixed weights lim_reg6_fast assumes */
    for (kind = 0; kind < 4u; kind++)
        for (seed = 1; seed <= (H_HOST ? 6u : 2u); seed++) bad += r6_torus(kind, 977u * seed + kind, &n);
    CHECK_EQ(bad, 0);
    CHECK(n > (H_HOST ? 1000u : 300u)); /* the tori have many valence-6 vertices */
}

/* floor(sqrt(x)) digit by digit (two bits of x per root bit), rounded to nearest as
 * subd_isqrt64 specifies: rem > root exactly when sqrt(x) >= root + 1/2. */
static uint32_t r6_isqrt_ref(uint64_t x)
{
    uint64_t rem = x, res = 0, bit = (uint64_t)1 << 62;
    while (bit > rem) bit >>= 2;
    while (bit != 0u) {
        if (rem >= res + bit) {
            rem -= res + bit;
            res = (res >> 1) + bit;
        } else {
            res >>= 1;
        }
        bit >>= 2;
    }
    return (rem > res && res != UINT32_MAX) ? (uint32_t)res + 1u : (uint32_t)res;
}

static uint32_t r6_isqrt_bad(uint64_t x) { return subd_isqrt64(x) != r6_isqrt_ref(x) ? 1u : 0u; }

static void isqrt_test(void)
{
    uint32_t s = 4242u, i, j, bad = 0, nr = H_HOST ? 1000000u : 20000u;
    for (i = 0; i < 65536u; i++) bad += r6_isqrt_bad(i);
    for (i = 0; i < 64u; i++) {
        uint64_t p = (uint64_t)1 << i;
        bad += r6_isqrt_bad(p) + r6_isqrt_bad(p - 1u) + r6_isqrt_bad(p + 1u) + r6_isqrt_bad(p | (p - 1u));
    }
    for (i = 0; i < nr; i++) {
        uint64_t x = (uint64_t)h_rand(&s) << 32, q, y;
        x |= h_rand(&s);
        x >>= h_rand(&s) & 63u;
        q = h_rand(&s);
        q >>= h_rand(&s) & 31u;
        y = q * q;
        bad += r6_isqrt_bad(x);
        for (j = 0; j < 3u; j++) bad += r6_isqrt_bad(y + j * q) + r6_isqrt_bad(y + j * q + 1u) + r6_isqrt_bad(y - 1u + j);
    }
    bad += r6_isqrt_bad(UINT64_MAX) + r6_isqrt_bad(UINT64_MAX - 1u);
    CHECK_EQ(bad, 0);
}

#if SUBD_FIXED
/* subd_w3_unit (vec3w.c, Q16.16: the quotients by two 32-bit divisions) against the 64-bit
 * division it replaced: q = n 2^16, (q +- len/2) / len truncated, n = c rescaled to 30 bits. */
static void unit_test(void)
{
    uint32_t s = 99u, i, k, bad = 0;
    for (i = 0; i < (H_HOST ? 300000u : 5000u); i++) {
        subd_wide c[3], n[3];
        subd_real got[3];
        uint32_t len;
        for (k = 0; k < 3u; k++) {
            uint32_t u = h_rand(&s);
            int64_t v = (int64_t)(((uint64_t)h_rand(&s) << 30 | h_rand(&s)) >> (u & 31u));
            c[k] = (u & 32u) ? -v : (u & 448u) == 0u ? 0 : v;
        }
        subd_w3_unit(c, got);
        subd_w3_normalize(c, n, 30u);
        len = subd_isqrt64((uint64_t)subd_w3_dot(n, n));
        for (k = 0; k < 3u; k++) {
            int64_t q = n[k] * 65536, h = (int64_t)(len / 2u);
            subd_real want = len == 0u ? 0 : (subd_real)(q < 0 ? (q - h) / (int64_t)len : (q + h) / (int64_t)len);
            if (got[k] != want) bad++;
        }
    }
    CHECK_EQ(bad, 0);
}
#endif

const test_case suite_loop_limit6[] = {
#if SUBD_FIXED
    {"limit6_unit_division", unit_test},
#endif
    {"limit6_reg6_equals_limit", reg6_test},
    {"limit6_isqrt64", isqrt_test},
    {0, 0}
};
