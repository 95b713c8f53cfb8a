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
 */
#include "edge_sort.h"

#define ES_KEY_FRAC 52u

/* ------------------------------------------------------------------------------------ */
/* sort_edges                                                                             */

/* Squared length of the edge of half-edge h as a monotonic key: (bit length of the value
 * in units of the arithmetic) << 52 | the 52 bits below its leading one. */
static uint64_t es_len_key(const subd_mesh *m, uint32_t h)
{
    const subd_real *p = m->pos + 3u * subd_he_origin(m, h), *q = m->pos + 3u * subd_he_dest(m, h);
#if SUBD_FIXED
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
    else for (top = lo; top; top >>= 1) n++;
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

/* Rounds a key to `bits` significant bits (1..53), to nearest; the carry into the bit
 * length field is the correct result (as for floating-point numbers). */
static uint64_t es_round_key(uint64_t k, uint32_t bits)
{
    uint32_t drop = ES_KEY_FRAC + 1u - bits;
    if (drop == 0 || k == 0) return k;
    k += 1ull << (drop - 1u);
    return k & ~((1ull << drop) - 1u);
}

uint32_t subd_edge_number(const subd_mesh *m, const subd_edge_work *w, uint32_t cap)
{
    uint32_t h, v, ne = 0;
    for (h = 0; h < m->num_corners; h++) w->edge_of[h] = SUBD_NONE;
    for (v = 0; v < m->num_verts; v++) {
        uint32_t first = m->vert_out[v], last = SUBD_NONE, steps = 0;
        if (first == SUBD_NONE) continue;
        for (h = first; h != SUBD_NONE && steps < m->num_corners; h = subd_ring_next(m, first, h), steps++) {
            last = h;
            if (w->edge_of[h] != SUBD_NONE) continue;
            if (ne == cap) return SUBD_NONE;
            w->edge_of[h] = ne;
            if (m->twin[h] != SUBD_NONE) w->edge_of[m->twin[h]] = ne;
            w->edge_he[ne++] = h;
        }
        if (m->twin[first] == SUBD_NONE) { /* boundary: the incoming boundary edge comes last */
            h = subd_he_prev(m, last);
            if (w->edge_of[h] == SUBD_NONE) {
                if (ne == cap) return SUBD_NONE;
                w->edge_of[h] = ne;
                w->edge_he[ne++] = h;
            }
        }
    }
    return ne;
}

/* Stable LSD radix sort of ord[0][0..n) by key[0] ascending, 8-bit digits; passes where
 * every key has the same digit are skipped. Returns the array that holds the result. */
static const uint32_t *es_radix_sort(subd_edge_work *w, uint32_t n)
{
    uint64_t *ks = w->key[0], *kd = w->key[1], *kt;
    uint32_t *os = w->ord[0], *od = w->ord[1], *ot;
    uint32_t shift, i, d;
    for (shift = 0; shift < 64u; shift += 8u) {
        uint32_t sum = 0, skip = 0;
        for (d = 0; d < 256u; d++) w->cnt[d] = 0;
        for (i = 0; i < n; i++) w->cnt[(uint32_t)(ks[i] >> shift) & 255u]++;
        for (d = 0; d < 256u; d++) {
            uint32_t c = w->cnt[d];
            if (c == n) skip = 1;
            w->cnt[d] = sum;
            sum += c;
        }
        if (skip) continue;
        for (i = 0; i < n; i++) {
            uint32_t at = w->cnt[(uint32_t)(ks[i] >> shift) & 255u]++;
            kd[at] = ks[i];
            od[at] = os[i];
        }
        kt = ks; ks = kd; kd = kt;
        ot = os; os = od; od = ot;
    }
    return os;
}

/* ------------------------------------------------------------------------------------ */
/* Marks e and every edge of the faces that contain e. */
static void es_mark_cluster(const subd_mesh *m, const subd_edge_work *w, uint32_t e)
{
    uint32_t side, h = w->edge_he[e];
    w->mark[e] = 1;
    for (side = 0; side < 2u; side++) {
        uint32_t s;
        if (h == SUBD_NONE) break;
        s = m->face_start[m->corner_face[h]];
        w->mark[w->edge_of[s]] = 1;
        w->mark[w->edge_of[s + 1u]] = 1;
        w->mark[w->edge_of[s + 2u]] = 1;
        h = m->twin[h];
    }
}

uint32_t subd_edge_clusters(const subd_mesh *m, subd_edge_work *w, uint32_t ne, uint32_t bits, int interior_only,
                            uint32_t base, uint32_t *sel)
{
    uint32_t e, i, ns = 0;
    const uint32_t *ord;
    for (e = 0; e < ne; e++) {
        w->key[0][e] = ~es_round_key(es_len_key(m, w->edge_he[e]), bits); /* ascending = longest first */
        w->ord[0][e] = e;
        sel[e] = SUBD_NONE;
        w->mark[e] = 0;
    }
    ord = es_radix_sort(w, ne);
    for (i = 0; i < ne; i++) {
        e = ord[i];
        if (w->mark[e]) continue;
        if (interior_only && m->twin[w->edge_he[e]] == SUBD_NONE) continue;
        sel[e] = base + ns++;
        es_mark_cluster(m, w, e);
    }
    return ns;
}
