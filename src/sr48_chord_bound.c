/* SPDX-License-Identifier: MIT */
/* Streaming semi-regular 4-8 refinement, CHORD: a sound upper bound on the chordal deviations
 * below a node, from one window level, to prune the exhaustive walk (sr48_chord_walk.c; the
 * criterion: sr48_chord.c). Paper: semi-regular-4-8-refinement-box-splines.txt, sections 4
 * (the 4-8 lattice, its refinement) and 6 (the box-spline smoothing); the bound is beyond it.
 * A pruned subtree is one no test of the walk can find beyond eps, so every decision, every
 * memo entry and every emitted bit is the exhaustive walk's (test_sr48_chord_prune.c compares
 * the cuts with the pruning on and off).
 *
 * The rules are convex and reproduce affine functions. Every position of level l + 1 is a
 * convex combination of level-l positions: a new vertex the midpoint of its diamond's apexes
 * (smoothing on) or of its base ends (off, or a boundary half-diamond), an old vertex after an
 * even level the average of its new neighbours (subd_s48_refine_). Where the level-l mesh
 * around a node q is a piece of the regular 4-8 lattice (a chart u maps it onto the lattice,
 * leg neighbours sharing their apex, diamonds squares, every vertex of valence 4 as the apex
 * of all its triangles or 8 as the apex of none) both rules map affine functions of u to the
 * same affine functions (u of a new vertex: its base midpoint; the apexes of a square average
 * to its centre, the new neighbours of a regular vertex are symmetric about it), and the
 * refined mesh is again regular there. So for every finest vertex v in q's closure (created
 * under q, or a corner of q) and any affine A of u:
 *   P(v) - A(u(v)) = sum over x of w_vx (P_l(x) - A(u(x))),  w_vx >= 0, sum 1,
 * x over the level-l vertices v depends on. Which ones: the ring rule of the windows
 * (sr48_window.c): the subtree of q is computed exactly from q and its two vertex rings of
 * level l (the tile crops to exactly that and checks every finest corner exact), so v depends
 * on V2(q), the vertices of the triangles within two rings of q, and only the vertices V1(q)
 * of the triangles within one ring are smoothed on the way (a smoothed vertex needs its ring;
 * one of V2(q) \ V1(q) would need a third). In the regular lattice this is the same for every
 * q of a level's parity and orientation (the rules are those of the lattice), so the tiles
 * the tests run check it for all of them. Hence
 *   |P(v) - A(u(v))| <= max over x in V2(q) of |r_A(x)|,   r_A(x) = P_l(x) - A(u(x)),
 * and r_A(v) lies in the convex hull K_A(q) of the r_A(x).
 * The bounds (all in subd_s48b_*_; l = max_level - rem):
 *  - q's own subtree: for d = q or a triangle below it, the corners of d and the vertices it
 *    creates are finest vertices of q's closure, L_d(v) - A(u(v)) is their convex combination,
 *    so E(d) = max |r_A(v) - (L_d - A)(v)| <= diam K_A(q) <= D(q), the diagonal of the
 *    per-axis bounding box of the r_A(x) (A: the affine map of q's level-l corners; any A
 *    works, a near-tangent one makes D small). Also |P(c) - P_l(c)| <= D(q) for a corner c.
 *  - an interpolant with known finest corners (a walk ancestor a of the node: L_a, carried
 *    down to q's corners by the walk's midpoint steps, extended affinely in u): every vertex
 *    below q has |P(v) - L_a(v)| <= max over V2(q) of |P_l(x) - L_a(u(x))|.
 *  - a tile node h above level l (its finest corners not computed yet): with Ah the affine
 *    map of h's level-l corners, L_h - Ah interpolates P(c) - P_l(c) at h's corners, each at
 *    most max D(q) over the level-l nodes: |P(v) - L_h(v)| <= max |r_Ah| over V2(q) + max D.
 * When all the bounds of a node (or of every level-l node of a tile) are at most eps minus
 * the margin below, no test of the walk below it can answer "beyond": the node is not
 * entered, or the tile stops at level l with no deviation bit set (its memo entry is then
 * exact too: every bit it holds, for every node and every walk ancestor, is 0).
 * Regular, checked (subd_s48b_begin_): the window is unfolded from the first node (chart
 * coordinates, integers in units of the level's legs: legs are unit axis vectors, bases
 * diagonal ones), the relation of every pair of local neighbours checked in a last pass
 * (the base neighbour mutual and reversed with the apex at a + b - c, a leg neighbour sharing
 * the apex with its third vertex at 2c - b or 2c - a); a vertex of a failed relation, of a
 * boundary or window edge (its fan not closed in the window) or of irregular valence is
 * "open". Every vertex of V1(q) (found by ring marks) must be closed, regular and exact: then
 * V1's fans close, so V2(q) is in the window, and q's frame reaches every vertex of V2(q)
 * through checked relations (within chart distance 3). The region is V2(q)'s exact vertices:
 * in a proper window (the walk's, where the exhaustive path reports a vertex of the cone that
 * is not exact as an error, or a tile started from one) a vertex that is not exact is not in
 * the cone (exactness is the AND of a rule's inputs, and the cone's results are exact);
 * elsewhere (a loose tile's or a memo tile's root from any window) the tile is pruned only
 * when all of V2(root) is exact (subd_s48b_proper_: then it is as good as a proper one).
 * Anything else: no pruning, the exhaustive path (extraordinary vertices, boundaries, seams).
 * Measured (why this is reverted on the branch): D(q) is about 36 E(q) on a smooth surface
 * (the residual of a quadratic over two rings against its interpolation error over q), so a
 * subtree is pruned only about 5 levels below the cut; icosahedron 9 steps, eps 0.01: best
 * D / limit per level 2..8 = 81, 39, 17, 9.7, 4.4, 2.2, 1.1 (never pruned); spot 6 steps, eps
 * 0.002: 0.58 .. 0.13 at levels 2..5 in places, refined triangles -6 %, time 2.5x (the checks).
 * Margin (why the computed bits follow the exact argument): float: each level of rules adds
 * at most about 5 ulp of the largest magnitude M to a position (a midpoint: one rounding; an
 * average of 4: three sums and a division), the interpolant's midpoints one more, the bound's
 * own evaluation about 20 ulp, the test |d|^2 > eps^2 a relative 2^-21: the limit is
 *   eps (1 - 2^-8) - (rem + 4) 2^-18 M,  M >= every |coordinate| involved,
 * about 16x that. Q16.16: a rule rounds once to 1/2 LSB per level (subd_div_round), the
 * interpolant is Q32.32 (exact to 2^-32 per halving), the test rounds its difference to 1/2
 * LSB: the limit is eps (1 - 2^-8) - 2 (rem + 3) - 1 LSB, the bound's residuals rounded up to
 * whole LSBs. Nothing is pruned when the limit is not positive. */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "sr48_chord_bound.h"

int subd_s48b_off_ = 0;

#define S48B_NONE 0xffffffffu /* chart: vertex not reached                                */
#define S48B_OPEN 0x80u       /* fan byte: not closed, or a failed relation, at the vertex */
#define S48B_REG 64u          /* most vertices of a node's region (49 in a regular chart)  */

#if SUBD_FIXED /* the representation differs: residuals in whole LSBs, squares in 64 bits */
typedef int64_t s48b_len;
typedef uint64_t s48b_sq;
#else
typedef float s48b_len;
typedef float s48b_sq;
#endif

/* Chart coordinates (s->cnt, free outside a refinement), x and y biased by 2^15. */
static uint32_t s48b_pack(int32_t x, int32_t y) { return ((uint32_t)(x + 32768) << 16) | (uint32_t)(y + 32768); }
static int32_t s48b_cx(uint32_t c) { return (int32_t)(c >> 16) - 32768; }
static int32_t s48b_cy(uint32_t c) { return (int32_t)(c & 0xffffu) - 32768; }
static int32_t s48b_abs(int32_t x) { return x < 0 ? -x : x; }

/* The fan byte (s->dist, free outside a refinement): triangles at the vertex (bits 0..3,
 * saturated), of which it is the apex (4..6, saturated), open (7). Regular: 4 all apex, or
 * 8 none. */
static int s48b_regular(uint8_t f)
{
    return !(f & S48B_OPEN) && (f == (4u | (4u << 4)) || f == 8u);
}

static void s48b_open3(uint8_t *fl, const uint16_t *tv)
{
    fl[tv[0]] |= S48B_OPEN;
    fl[tv[1]] |= S48B_OPEN;
    fl[tv[2]] |= S48B_OPEN;
}

/* The regular relation of triangle i = (c; a, b) and its local neighbour across slot k (the
 * refinement's local rule, subd_s48_refine_): base: mutual, the base reversed; leg 0 (c-a):
 * its leg 1 is i's, the same apex, a its b1; leg 1 (b-c): its leg 0 is i's, the same apex,
 * b its b0. 1 with its third vertex in *w, 0 when not local or not regular. */
static int s48b_nbr(const s48_win *p, uint32_t i, uint32_t k, uint16_t *w)
{
    const uint16_t *tv = p->tv + 3u * i, nb = p->tn[3u * i + k];
    const uint16_t *nv;
    if (!s48_local(nb)) return 0;
    nv = p->tv + 3u * nb;
    if (k == 0u) {
        if (p->tn[3u * nb] != i || nv[1] != tv[2] || nv[2] != tv[1]) return 0;
        *w = nv[0];
    } else if (k == 1u) {
        if (p->tn[3u * nb + 2u] != i || nv[0] != tv[0] || nv[2] != tv[1]) return 0;
        *w = nv[1];
    } else {
        if (p->tn[3u * nb + 1u] != i || nv[0] != tv[0] || nv[1] != tv[2]) return 0;
        *w = nv[2];
    }
    return 1;
}

/* The chart coordinates the relation across slot k gives the third vertex (i's corners
 * charted): base a + b - c, leg 0 2c - b, leg 1 2c - a. */
static uint32_t s48b_third(const uint32_t *cc, const uint16_t *tv, uint32_t k)
{
    const int32_t cx = s48b_cx(cc[tv[0]]), cy = s48b_cy(cc[tv[0]]);
    const int32_t ax = s48b_cx(cc[tv[1]]), ay = s48b_cy(cc[tv[1]]);
    const int32_t bx = s48b_cx(cc[tv[2]]), by = s48b_cy(cc[tv[2]]);
    if (k == 0u) return s48b_pack(ax + bx - cx, ay + by - cy);
    if (k == 1u) return s48b_pack(2 * cx - bx, 2 * cy - by);
    return s48b_pack(2 * cx - ax, 2 * cy - ay);
}

/* The chart of window p unfolded from triangle t0 (apex (0, 0), b0 (1, 0), b1 (0, 1)), breadth
 * first over the regular relations (queue: s->mtab, seen: s->tmap), then every relation and
 * every triangle's shape checked: vertices of a failed one are open. 0 when coordinates leave
 * their range. */
static int s48b_chart(s48_state *s, const s48_win *p, uint32_t t0)
{
    const uint32_t nt = p->hd[0], nv = p->hd[1];
    uint32_t *cc = s->cnt, i, k, head = 0, tail = 0;
    uint8_t *fl = s->dist;
    uint16_t *qu = s->mtab, *seen = s->tmap, w;
    for (i = 0; i < nv; i++) {
        cc[i] = S48B_NONE;
        fl[i] = 0;
    }
    for (i = 0; i < nt; i++) {
        const uint16_t *tv = p->tv + 3u * i;
        seen[i] = 0;
        for (k = 0; k < 3u; k++) {
            uint8_t f = fl[tv[k]];
            if ((f & 15u) < 15u) f++;
            if (k == 0u && ((f >> 4) & 7u) < 7u) f = (uint8_t)(f + 16u);
            fl[tv[k]] = f;
            if (!s48_local(p->tn[3u * i + k])) { /* slot k's ends: (a, b), (c, a), (b, c) */
                fl[tv[k == 0u ? 1u : 0u]] |= S48B_OPEN;
                fl[tv[k == 2u ? 2u : k == 0u ? 2u : 1u]] |= S48B_OPEN;
            }
        }
    }
    cc[p->tv[3u * t0]] = s48b_pack(0, 0);
    cc[p->tv[3u * t0 + 1u]] = s48b_pack(1, 0);
    cc[p->tv[3u * t0 + 2u]] = s48b_pack(0, 1);
    qu[tail++] = (uint16_t)t0;
    seen[t0] = 1;
    while (head < tail) {
        const uint32_t t = qu[head++];
        const uint16_t *tv = p->tv + 3u * t;
        for (k = 0; k < 3u; k++) {
            uint16_t nb = p->tn[3u * t + k];
            uint32_t c;
            if (!s48b_nbr(p, t, k, &w) || seen[nb]) continue;
            c = s48b_third(cc, tv, k);
            if (s48b_abs(s48b_cx(c)) > 16000 || s48b_abs(s48b_cy(c)) > 16000) return 0;
            if (cc[w] == S48B_NONE) cc[w] = c;
            seen[nb] = 1;
            qu[tail++] = nb;
        }
    }
    for (i = 0; i < nt; i++) { /* every relation and shape, whatever path charted it */
        const uint16_t *tv = p->tv + 3u * i;
        int32_t ax, ay, bx, by;
        if (cc[tv[0]] == S48B_NONE || cc[tv[1]] == S48B_NONE || cc[tv[2]] == S48B_NONE) {
            s48b_open3(fl, tv);
            continue;
        }
        ax = s48b_cx(cc[tv[1]]) - s48b_cx(cc[tv[0]]);
        ay = s48b_cy(cc[tv[1]]) - s48b_cy(cc[tv[0]]);
        bx = s48b_cx(cc[tv[2]]) - s48b_cx(cc[tv[0]]);
        by = s48b_cy(cc[tv[2]]) - s48b_cy(cc[tv[0]]);
        if (s48b_abs(ax) + s48b_abs(ay) != 1 || s48b_abs(bx) + s48b_abs(by) != 1 || ax * bx + ay * by != 0) {
            s48b_open3(fl, tv);
            continue;
        }
        for (k = 0; k < 3u; k++) {
            const uint16_t nb = p->tn[3u * i + k];
            if (!s48_local(nb)) continue;
            if (!s48b_nbr(p, i, k, &w) || cc[w] != s48b_third(cc, tv, k)) {
                s48b_open3(fl, tv);
                s48b_open3(fl, p->tv + 3u * nb);
            }
        }
    }
    return 1;
}

/* The vertex rings of p's triangle q (marks in s->vmap, free outside a crop): 0 q's corners,
 * 1 V1(q) (the vertices of the triangles at a corner), 2 V2(q) (of the triangles at a
 * vertex of V1), 3 the others. */
static void s48b_rings(const s48_state *s, const s48_win *p, uint32_t q)
{
    const uint16_t *tv = p->tv + 3u * q;
    const uint32_t nt = p->hd[0], nv = p->hd[1];
    uint16_t *mk = s->vmap;
    uint32_t v, i, r;
    for (v = 0; v < nv; v++) mk[v] = 3;
    mk[tv[0]] = mk[tv[1]] = mk[tv[2]] = 0;
    for (r = 1; r <= 2u; r++) /* ring r: the triangles at a vertex of ring r - 1 */
        for (i = 0; i < nt; i++) {
            const uint16_t *t = p->tv + 3u * i;
            if (mk[t[0]] + 1u > r && mk[t[1]] + 1u > r && mk[t[2]] + 1u > r) continue;
            if (mk[t[0]] > r) mk[t[0]] = (uint16_t)r;
            if (mk[t[1]] > r) mk[t[1]] = (uint16_t)r;
            if (mk[t[2]] > r) mk[t[2]] = (uint16_t)r;
        }
}

/* Node q's region: the exact vertices of V2(q) (all of V1(q); strict: all of V2(q)), as
 * indices and coordinates in q's frame (apex 0, b0 (1, 0), b1 (0, 1)); 0 when a vertex of
 * V1(q) is not closed and regular, one of the region is not charted within distance 3, a
 * vertex that must be exact is not, or there are more than S48B_REG. */
static uint32_t s48b_region(const s48_state *s, const s48_win *p, uint32_t q, int strict, uint16_t *rv, int8_t *ra,
                            int8_t *rb)
{
    const uint16_t *tv = p->tv + 3u * q, *mk = s->vmap;
    const uint32_t *cc = s->cnt, nv = p->hd[1];
    int32_t cx, cy, e1x, e1y, e2x, e2y;
    uint32_t v, nr = 0;
    if (cc[tv[0]] == S48B_NONE || cc[tv[1]] == S48B_NONE || cc[tv[2]] == S48B_NONE) return 0;
    cx = s48b_cx(cc[tv[0]]);
    cy = s48b_cy(cc[tv[0]]);
    e1x = s48b_cx(cc[tv[1]]) - cx;
    e1y = s48b_cy(cc[tv[1]]) - cy;
    e2x = s48b_cx(cc[tv[2]]) - cx;
    e2y = s48b_cy(cc[tv[2]]) - cy;
    if (s48b_abs(e1x) + s48b_abs(e1y) != 1 || s48b_abs(e2x) + s48b_abs(e2y) != 1 || e1x * e2x + e1y * e2y != 0) return 0;
    s48b_rings(s, p, q);
    for (v = 0; v < nv; v++) {
        int32_t dx, dy;
        if (mk[v] > 2u) continue;
        if (!(p->vf[v] & S48_EXACT)) {
            if (strict || mk[v] <= 1u) return 0;
            continue; /* not in q's dependency cone: this file's header */
        }
        if (cc[v] == S48B_NONE || (mk[v] <= 1u && !s48b_regular(s->dist[v]))) return 0;
        dx = s48b_cx(cc[v]) - cx;
        dy = s48b_cy(cc[v]) - cy;
        if (s48b_abs(dx) > 3 || s48b_abs(dy) > 3 || nr >= S48B_REG) return 0;
        rv[nr] = (uint16_t)v;
        ra[nr] = (int8_t)(dx * e1x + dy * e1y);
        rb[nr] = (int8_t)(dx * e2x + dy * e2y);
        nr++;
    }
    return nr;
}

int subd_s48b_proper_(s48_state *s, const s48_win *p, uint32_t q)
{
    const uint16_t *mk = s->vmap;
    uint32_t v, i, k;
    s48b_rings(s, p, q);
    for (v = 0; v < p->hd[1]; v++)
        if (mk[v] <= 2u && !(p->vf[v] & S48_EXACT)) return 0;
    for (i = 0; i < p->hd[0]; i++) /* V1's fans closed: V2 is all there */
        for (k = 0; k < 3u; k++) {
            const uint16_t *tv = p->tv + 3u * i;
            if (s48_local(p->tn[3u * i + k])) continue;
            if (mk[tv[k == 0u ? 1u : 0u]] <= 1u || mk[tv[k == 1u ? 1u : 2u]] <= 1u) return 0;
        }
    return 1;
}

/* Over the region: the largest |P_l(x) - I(u(x))|^2 (I: 9 values at q's corners c, a, b,
 * extended affinely: I_c + alpha (I_a - I_c) + beta (I_b - I_c)) and, when rng, the per-axis
 * ranges of the residual. Q16.16: whole LSBs rounded up, saturated at 2^31. */
static s48b_sq s48b_eval(const s48_win *p, const uint16_t *rv, const int8_t *ra, const int8_t *rb, uint32_t nr,
                         const subd_sr48_lin *l, s48b_len *rng)
{
    subd_sr48_lin lo[3], hi[3];
    s48b_sq best = 0;
    uint32_t i, q;
    for (i = 0; i < nr; i++) {
        s48b_sq sq = 0;
        for (q = 0; q < 3u; q++) {
#if SUBD_FIXED /* the algorithm differs: exact Q32.32 residuals, rounded up to LSBs */
            const int64_t a = ra[i], b = rb[i];
            const int64_t r = subd_sr48_lin_of_(p->vp[3u * rv[i] + q]) - (l[q] + a * (l[3u + q] - l[q]) + b * (l[6u + q] - l[q]));
            uint64_t m = (uint64_t)(r < 0 ? -r : r);
            m = (m + 0xffffu) >> 16;
            if (m > 0x80000000u) m = 0x80000000u;
            sq += m * m;
#else
            const float a = (float)ra[i], b = (float)rb[i];
            const float r = p->vp[3u * rv[i] + q] - (l[q] + a * (l[3u + q] - l[q]) + b * (l[6u + q] - l[q]));
            sq += r * r;
#endif
            if (rng) {
                if (i == 0u || r < lo[q]) lo[q] = r;
                if (i == 0u || r > hi[q]) hi[q] = r;
            }
        }
        if (sq > best) best = sq;
    }
    if (rng)
        for (q = 0; q < 3u; q++) {
#if SUBD_FIXED /* the representation differs: the range in LSBs, rounded up */
            uint64_t m = nr ? (uint64_t)(hi[q] - lo[q]) : 0u;
            m = (m + 0xffffu) >> 16;
            rng[q] = (int64_t)(m > 0x80000000u ? 0x80000000u : m);
#else
            rng[q] = nr ? hi[q] - lo[q] : 0.0f;
#endif
        }
    return best;
}

/* The limit of a bound (the margin: this file's header), or <= 0 when none is usable. */
static s48b_len s48b_limit(const s48_state *s, uint32_t rem, subd_real mag)
{
#if SUBD_FIXED /* the representation differs: LSBs */
    const int64_t e = s->ad.eps;
    (void)mag;
    return e - e / 256 - 2 * ((int64_t)rem + 3) - 1;
#else
    const float e = s->ad.eps;
    return e - e * 0.00390625f - (float)(rem + 4u) * 3.814697265625e-06f * mag - 1e-30f;
#endif
}

/* Is |r|^2 <= lim^2 (lim > 0)? */
static int s48b_within(s48b_sq sq, s48b_len lim)
{
    if (!(lim > 0)) return 0;
#if SUBD_FIXED /* the representation differs: lim < 2^31, its square in 64 bits */
    return sq <= (uint64_t)lim * (uint64_t)lim;
#else
    return sq <= lim * lim;
#endif
}

/* The values of p's positions at three window vertices, as an interpolant's 9 values. */
static void s48b_at(const s48_win *p, const uint16_t *tv, subd_sr48_lin *l)
{
    uint32_t q;
    for (q = 0; q < 9u; q++) l[q] = subd_sr48_lin_of_(p->vp[3u * tv[q / 3u] + q % 3u]);
}

/* The interpolant l (9 values at heap node h's corners) carried down s levels to heap node g
 * (h = g >> s) by the walk's midpoint steps, into l. */
static void s48b_down(subd_sr48_lin *l, uint32_t g, uint32_t s)
{
    subd_sr48_lin t[9];
    uint32_t i, q;
    for (i = 0; i < s; i++) {
        subd_s48c_lin_child_(l, (g >> (s - 1u - i)) & 1u, t);
        for (q = 0; q < 9u; q++) l[q] = t[q];
    }
}

static uint32_t s48b_depth(uint32_t n)
{
    uint32_t d = 0;
    while ((1u << d) < n) d++;
    return d;
}

int subd_s48b_begin_(s48_state *s, s48b_ctx *c, const s48_win *p, uint32_t lo, uint32_t n, uint32_t rem, int strict)
{
    uint16_t rv[S48B_REG];
    int8_t ra[S48B_REG], rb[S48B_REG];
    subd_sr48_lin l[9];
    s48b_len rng[3], lim, ds;
    uint32_t i, g, nr;
    subd_real mag = 0;
    if (subd_s48b_off_ || s->ad.mode != SUBD_SR48_ADAPT_CHORD) return 0;
    for (i = 0; i < 3u * p->hd[1]; i++) {
        const subd_real v = p->vp[i] < 0 ? -p->vp[i] : p->vp[i];
        if (v > mag) mag = v;
    }
    c->p = p;
    c->lo = lo;
    c->n = n;
    c->rem = rem;
    c->strict = strict;
    c->mag = mag;
    c->dsum = 0;
    lim = s48b_limit(s, rem, mag);
    if (!(lim > 0) || !s48b_chart(s, p, lo)) return 0;
    for (g = 0; g < n; g++) {
        nr = s48b_region(s, p, lo + g, strict, rv, ra, rb);
        if (nr == 0u) return 0;
        s48b_at(p, p->tv + 3u * (lo + g), l);
        (void)s48b_eval(p, rv, ra, rb, nr, l, rng); /* D(q)^2: the squared ranges */
#if SUBD_FIXED /* the representation differs: ranges < 2^31 LSB, squares in 64 bits */
        if ((uint64_t)rng[0] * (uint64_t)rng[0] + (uint64_t)rng[1] * (uint64_t)rng[1] +
                (uint64_t)rng[2] * (uint64_t)rng[2] > (uint64_t)lim * (uint64_t)lim)
            return 0;
#else
        if (rng[0] * rng[0] + rng[1] * rng[1] + rng[2] * rng[2] > lim * lim) return 0;
#endif
        ds = rng[0] + rng[1] + rng[2];
        if (ds > c->dsum) c->dsum = ds;
    }
    return 1;
}

int subd_s48b_inner_(s48_state *s, const s48b_ctx *c, const uint16_t *hc)
{
    uint16_t rv[S48B_REG];
    int8_t ra[S48B_REG], rb[S48B_REG];
    subd_sr48_lin l[9];
    const s48_win *p = c->p;
    const uint32_t dd = s48b_depth(c->n);
    const s48b_len lim = s48b_limit(s, c->rem, c->mag) - c->dsum;
    uint32_t g, h, nr;
    if (c->n <= 1u) return 1;
    if (!(lim > 0)) return 0;
    for (g = c->n; g < 2u * c->n; g++) {
        nr = s48b_region(s, p, c->lo + g - c->n, c->strict, rv, ra, rb);
        if (nr == 0u) return 0;
        for (h = 1; h <= dd; h++) { /* the ancestor g >> h */
            s48b_at(p, hc + 3u * (g >> h), l);
            s48b_down(l, g, h);
            if (!s48b_within(s48b_eval(p, rv, ra, rb, nr, l, 0), lim)) return 0;
        }
    }
    return 1;
}

int subd_s48b_known_(s48_state *s, const s48b_ctx *c, const subd_sr48_lin *l1, subd_real mag, uint32_t steps)
{
    uint16_t rv[S48B_REG];
    int8_t ra[S48B_REG], rb[S48B_REG];
    subd_sr48_lin l[9];
    const s48_win *p = c->p;
    const uint32_t dd = s48b_depth(c->n);
    s48b_len lim;
    uint32_t g, q, nr;
    if (mag < c->mag) mag = c->mag;
    lim = s48b_limit(s, c->rem + dd + steps, mag);
    for (g = c->n; g < 2u * c->n; g++) {
        nr = s48b_region(s, p, c->lo + g - c->n, c->strict, rv, ra, rb);
        if (nr == 0u) return 0;
        for (q = 0; q < 9u; q++) l[q] = l1[q];
        s48b_down(l, g, dd);
        if (!s48b_within(s48b_eval(p, rv, ra, rb, nr, l, 0), lim)) return 0;
    }
    return 1;
}
