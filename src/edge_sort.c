/* SPDX-License-Identifier: MIT */
/* Edge sort and cluster marking: quasi 4-8 subdivision's sort_edges and mark_cluster
 * (paper: quasi-4-8-subdivision.txt, section 3.1, Algorithm 1), shared with the
 * semi-regular 4-8 pre-processing's find_clusters (semi-regular-4-8-refinement-box-splines.txt,
 * section 5, Algorithm 1), which uses the same two routines.
 *
 * Choices where the papers are silent (moved here unchanged from quasi48.c):
 *  - "sorts edges by decreasing length and radially around each vertex": edges are first
 *    numbered radially (vertices in index order; around each vertex its not yet numbered
 *    edges in one-ring order from vert_out), then stably sorted by decreasing squared
 *    length, so equal lengths are processed in that radial order.
 *  - Lengths are compared after rounding the squared length to `bits` significant bits
 *    (round to nearest; integer/bit arithmetic only), so lengths equal in exact arithmetic
 *    but not after rounding the vertices stay equal.
 *  - Squared lengths: Q16.16 exactly, in 64-bit integers from the raw differences (each
 *    square < 2^64, the sum kept in 66 bits), encoded as a monotonic 64-bit key (bit length
 *    << 52 | 52 bits below the leading one); float32: dx*dx + dy*dy + dz*dz in float32
 *    (deterministic, no fused multiply-add), key from its bit pattern in the same format.
 *    The sort is an LSD radix sort (8-bit digits, passes over constant digits skipped):
 *    stable, so no tie key is needed, and no qsort.
 *
 * Speed (the results are those of the straightforward version, bit for bit):
 *  - The rounded key is sorted shifted down by the dropped bits, r = rounded >> (53 - bits)
 *    <= 2^60 >> (53 - bits) = 2^(bits + 7): with `bits` <= 24 it fits in 32 bits, so key
 *    and half-edge travel as one 64-bit word and each pass moves 8 bytes, not 12. Only
 *    digits where two keys differ are sorted (bits 12: about 15 varying bits, two passes,
 *    where the 64-bit keys took three plus a counting pass for each of the 8 digits); the
 *    first digit is counted while the keys are made. Descending order comes from handing
 *    out the bucket offsets from the top digit down, which keeps the sort stable.
 *  - Q16.16 bit length by halving, not a loop over up to 64 bits.
 *  - The sort carries the edge's half-edge, not its number: the marking needs the
 *    half-edge for every edge but the number only for the selected ones.
 *  - Marking by face: an edge is in a marked cluster exactly when one of its faces
 *    contains a selected edge (a selected edge lies in its own faces, and a cluster is
 *    its edge's faces). So one flag per face (at most 2E/3 faces, in the `mark` array)
 *    replaces the per-edge marks: a test is two flag reads, a selection two writes.
 *  - Triangles: a face's corners are 3f..3f+2, so next/previous half-edge is arithmetic
 *    on h instead of two dependent loads (corner_face, face_start) per ring step.
 */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "edge_sort.h"
#include "mesh_internal.h" /* tri_next, tri_prev */
#include "topo.h"
#include "vec3w.h" /* subd_bitlen64 */

#define ES_KEY_FRAC 52u
/* With at most this many significant bits the shifted rounded key fits in 32 bits. */
#define ES_PACK_BITS 24u

/* True when every face is a triangle: then face f's corners are 3f, 3f+1, 3f+2 (faces have
 * at least 3 corners and face_start[0] == 0, so 3 per face on average means 3 each). */
static int es_all_tris(const subd_mesh *m) { return m->num_corners == 3u * m->num_faces; }

/* ------------------------------------------------------------------------------------ */
/* sort_edges                                                                             */


/* Squared length of the edge from corner p to corner q as a monotonic key: (bit length of
 * the value in units of the arithmetic) << 52 | the 52 bits below its leading one. */
static uint64_t es_len_key(const subd_real *p, const subd_real *q)
{
#if SUBD_FIXED /* the algorithm differs: the exact 66-bit squared length of Q16.16 differences; float32 keys the float sum's bit pattern */
    uint64_t lo = 0, hi = 0, top;
    uint32_t i, n = 0;
    for (i = 0; i < 3u; i++) {
        int64_t dd = (int64_t)q[i] - p[i];
        uint64_t ad = (uint64_t)(dd < 0 ? -dd : dd); /* < 2^32 */
        uint64_t sq = ad * ad;                         /* < 2^64 */
        lo += sq;
        if (lo < sq) hi++;
    }
    if (hi == 0 && lo == 0) return 0;
    /* bit length n of hi:lo (hi <= 2) */
    if (hi) n = 64u + (hi > 1u ? 2u : 1u);
    else n = subd_bitlen64(lo);
    if (n <= ES_KEY_FRAC + 1u) {
        top = lo << (ES_KEY_FRAC + 1u - n);
    } else {
        uint32_t sh = n - (ES_KEY_FRAC + 1u);
        top = lo >> sh;
        if (hi) top |= hi << (64u - sh); /* n >= 65, so 12 <= sh <= 13 */
    }
    return ((uint64_t)n << ES_KEY_FRAC) | (top & ((1ull << ES_KEY_FRAC) - 1u));
#else
    uint32_t ovf = 0, b;
    subd_real dx = subd_sub(q[0], p[0], &ovf), dy = subd_sub(q[1], p[1], &ovf), dz = subd_sub(q[2], p[2], &ovf);
    subd_real xx = dx * dx, yy = dy * dy, zz = dz * dz;
    subd_real s = xx + yy;
    s = s + zz;
    b = subd_real_bits(s) & 0x7fffffffu; /* s >= 0 (or +inf) */
    return ((uint64_t)(b >> 23) << ES_KEY_FRAC) | ((uint64_t)(b & 0x7fffffu) << (ES_KEY_FRAC - 23u));
#endif
}

/* subd_edge_number's walk, forced inline into its two calls so that `tri` is a constant in
 * each: the triangle one walks without face lookups (topo.h's TOPO_INLINE). */
TOPO_INLINE uint32_t es_number(const subd_mesh *m, const subd_edge_work *w, uint32_t cap, int tri)
{
    /* locals: the stores into edge_of (uint32_t) could otherwise alias m->num_corners */
    const uint32_t nc = m->num_corners, nv = m->num_verts;
    const uint32_t *twin = m->twin, *vert_out = m->vert_out;
    uint32_t *edge_of = w->edge_of, *edge_he = w->edge_he;
    uint32_t h, v, ne = 0;
    for (h = 0; h < nc; h++) edge_of[h] = SUBD_NONE;
    for (v = 0; v < nv; v++) {
        topo_ring r; /* topo.h's walk: on a boundary the incoming boundary edge (the tail) last */
        if (vert_out[v] == SUBD_NONE) continue;
        if (tri) topo_ring_begin_tri(&r, m->corner_vert, twin, nc, vert_out[v]);
        else topo_ring_begin(&r, m, v);
        while (topo_ring_step(&r)) {
            h = r.he;
            if (edge_of[h] == SUBD_NONE) {
                if (ne == cap) return SUBD_NONE;
                edge_of[h] = ne;
                if (twin[h] != SUBD_NONE) edge_of[twin[h]] = ne;
                edge_he[ne++] = h;
            }
        }
    }
    return ne;
}

uint32_t subd_edge_number(const subd_mesh *m, const subd_edge_work *w, uint32_t cap)
{
    return es_all_tris(m) ? es_number(m, w, cap, 1) : es_number(m, w, cap, 0);
}

/* Stable LSD radix sort of ks[0..n) (with os[0..n) alongside unless os is a null pointer) by
 * descending (word >> lo), 8-bit digits; `vary` has a bit set wherever two of the shifted
 * words differ, and digits without one are skipped. On entry cnt holds the counts of the
 * lowest digit (the caller's key pass counts them, saving a pass over the keys). Returns
 * the array that holds the words (*os_out: the one that holds os). */
static const uint64_t *es_radix_sort(subd_edge_work *w, uint64_t *ks, uint64_t *kd, uint32_t *os, uint32_t *od,
                                     uint32_t n, uint32_t lo, uint64_t vary, const uint32_t **os_out)
{
    uint32_t *cnt = w->cnt;
    uint32_t shift, i, d;
    for (shift = 0; shift < 64u - lo && (vary >> shift) != 0; shift += 8u) {
        const uint32_t s = lo + shift;
        uint32_t sum = 0;
        uint64_t *kt;
        uint32_t *ot;
        if (((vary >> shift) & 255u) == 0) continue; /* the same digit in every word */
        if (shift) {
            for (d = 0; d < 256u; d++) cnt[d] = 0;
            for (i = 0; i < n; i++) cnt[(uint32_t)(ks[i] >> s) & 255u]++;
        }
        for (d = 256u; d-- > 0;) { /* largest digit first */
            uint32_t c = cnt[d];
            cnt[d] = sum;
            sum += c;
        }
        if (os) {
            for (i = 0; i < n; i++) {
                uint32_t at = cnt[(uint32_t)(ks[i] >> s) & 255u]++;
                kd[at] = ks[i];
                od[at] = os[i];
            }
            ot = os; os = od; od = ot;
        } else {
            for (i = 0; i < n; i++) kd[cnt[(uint32_t)(ks[i] >> s) & 255u]++] = ks[i];
        }
        kt = ks; ks = kd; kd = kt;
    }
    *os_out = os;
    return ks;
}

/* ------------------------------------------------------------------------------------ */
uint32_t subd_edge_clusters(const subd_mesh *m, subd_edge_work *w, uint32_t ne, uint32_t bits, int interior_only,
                            uint32_t base, uint32_t *sel)
{
    /* rounding to `bits` significant bits: add half of the lowest kept bit, shift the
     * dropped bits out (the carry into the bit length field is the correct result, as for
     * floating-point numbers; a key of 0 stays 0) */
    const uint32_t drop = ES_KEY_FRAC + 1u - bits;
    const uint64_t half = drop ? 1ull << (drop - 1u) : 0u;
    const int packed = bits <= ES_PACK_BITS; /* key << 32 | half-edge in one word */
    const uint32_t lo = packed ? 32u : 0u;
    const uint32_t *cv = m->corner_vert, *twin = m->twin, *edge_he = w->edge_he, *edge_of = w->edge_of;
    const subd_real *pos = m->pos;
    uint64_t *key = w->key[0], k_or = 0, k_and = ~0ull;
    uint32_t *cnt = w->cnt;
    uint32_t *ord = w->ord[0];
    uint8_t *used = w->mark; /* per face: contains a selected edge (see the file header) */
    const uint64_t *sorted;
    const uint32_t *sorted_he;
    uint32_t e, i, f, ns = 0;
    for (i = 0; i < 256u; i++) cnt[i] = 0;
    for (e = 0; e < ne; e++) {
        uint32_t h = edge_he[e];
        uint64_t r = (es_len_key(pos + 3u * cv[h], pos + 3u * cv[tri_next(h)]) + half) >> drop;
        k_or |= r;
        k_and &= r;
        cnt[(uint32_t)r & 255u]++; /* the sort's first digit */
        if (packed) {
            key[e] = r << 32 | h;
        } else {
            key[e] = r;
            ord[e] = h;
        }
        sel[e] = SUBD_NONE;
    }
    for (f = 0; f < m->num_faces; f++) used[f] = 0;
    sorted = es_radix_sort(w, key, w->key[1], packed ? (uint32_t *)0 : ord, w->ord[1], ne, lo, k_or ^ k_and, &sorted_he);
    for (i = 0; i < ne; i++) {
        uint32_t h = packed ? (uint32_t)sorted[i] : sorted_he[i], t = twin[h];
        if (used[h / 3u] || (t != SUBD_NONE && used[t / 3u])) continue; /* in a cluster */
        if (t == SUBD_NONE && interior_only) continue;
        sel[edge_of[h]] = base + ns++;
        used[h / 3u] = 1;
        if (t != SUBD_NONE) used[t / 3u] = 1;
    }
    return ns;
}
