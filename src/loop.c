/* Loop subdivision (Loop 1987) with the boundary rules of the progressive-interpolation
 * paper (loop-progressive-interpolation.txt, section 1 for the scheme, section 4 for the
 * boundary rules) and Hoppe et al. 1994 creases and corners.
 *
 * Rules, with v the old vertex, n its valence and p_i its neighbours:
 *   smooth vertex        (1 - n b) v + b sum p_i,  b = (5/8 - (3/8 + 1/4 cos(2 pi/n))^2) / n
 *   interior edge        3/8 (v0 + v1) + 1/8 (q0 + q1)   (q: the two opposite vertices)
 *   crease/boundary vtx  3/4 v + 1/8 (c0 + c1)           (c: the two sharp neighbours)
 *   sharp edge, PAPER    midpoint when both ends are regular or both extraordinary,
 *                        else 5/8 regular end + 3/8 extraordinary end
 *   sharp edge, BSPLINE  midpoint
 *   corner               stays where it is
 *
 * Choices where the paper is silent:
 *   - Sharp edges are boundary edges and edges tagged SUBD_ETAG_CREASE (on either half).
 *     A vertex is classified by its number of sharp edges (Hoppe et al. 1994): 0 smooth,
 *     1 dart (smooth rule), 2 crease (crease rule with its two sharp neighbours), 3 or more
 *     corner (fixed); SUBD_VTAG_CORNER forces corner. A boundary vertex always has two
 *     boundary edges, so it is a crease vertex unless tagged or a crease edge ends there.
 *   - Every sharp edge, boundary or crease, uses the sharp-edge rule of the chosen set,
 *     including one that ends at a dart (the dart end counts as extraordinary).
 *   - "Regular" for the PAPER edge rule: a crease vertex that looks like the ones
 *     refinement creates. On a boundary: valence 4 (the paper). In the interior: valence 6
 *     with the two crease edges opposite (three faces on each side; Hoppe's regular crease
 *     vertex). Darts, corners and every other crease vertex are extraordinary. New vertices on
 *     a sharp edge are always regular under this definition, as the paper requires.
 *   - SUBD_VTAG_FIXED is carried to the output but does not change any rule (Loop is an
 *     approximating scheme; tag a vertex CORNER to pin it).
 *   - The weight b comes from the deterministic cos of src/trig.c in Q2.62 and 64-bit
 *     integer arithmetic, rounded once to subd_real; the centre weight is ONE - n b in
 *     subd_real, so in Q16.16 the weights of every rule sum to exactly ONE (constants are
 *     reproduced exactly). In float32 the dyadic rules (edge, crease, n = 3, 4, 6) are exact;
 *     for other n the centre weight is the float nearest 1 - fl(n b), within 1 ulp.
 *
 * Overflow: every rule is a convex combination (b > 0 and 1 - n b > 0 for n >= 2), and in
 * Q16.16 the weights are non-negative integers summing to exactly 2^16 and the sum is
 * accumulated exactly in 64 bits, so a result never leaves the range of its inputs:
 * SUBD_ERR_RANGE cannot happen in Q16.16 (the flag is still checked). In float32 it
 * happens when an intermediate sum of coordinates near FLT_MAX rounds to infinity.
 *
 * Order of the output (a documented, platform-independent order):
 *   - vertices: input vertex i stays vertex i; then one new vertex per edge, in the order
 *     of the edge's lower half-edge index (levels nest: level k's vertices are a prefix of
 *     level k+1's).
 *   - faces: face f of a level has children 4f..4f+3. With corners (v0, v1, v2) and m_i the
 *     new vertex on edge v_i -> v_{i+1}: child 4f+i = (v_i, m_i, m_{i-1}) for i = 0, 1, 2,
 *     child 4f+3 = (m0, m1, m2). Orientation is kept.
 *   - tags: child edges of a boundary/crease edge keep its BOUNDARY/CREASE bits, new
 *     interior edges have none; vertices keep CORNER and FIXED; BOUNDARY and ISOLATED are
 *     set as the mesh builder sets them.
 *   - polylines of the input are not part of the surface and are not carried over.
 *
 * Topology is refined directly from the parent's twins (OpenSubdiv's separation of
 * topology and position refinement): the twins of the eight outer child half-edges follow
 * from the parent twin, the nine inner ones are fixed within the four children. This is
 * O(C) with no scratch memory, where re-bucketing with the builder would cost
 * O(C + sum valence^2) time and (V + C + 1) words. vert_out follows the builder's
 * convention exactly (the boundary half-edge, else the smallest corner), so with
 * SUBD_LOOP_ADJACENCY the output equals subd_mesh_build of its own face list (the test
 * checks this array by array).
 *
 * Memory (one block, plan = its size; all offsets from loop_layout_of, used by plan and run):
 *   [ output arrays of level L          ][ level L-1 (twins, vert_out, tags) ]
 *   [ = level L-2, L-4, ... while alive  ]  level L-3, L-5, ... as well
 * Level L is written into the output arrays while reading level L-1; level L-1 is built from
 * L-2, which lives in the (not yet used) output region. The output region is the larger of
 * the output arrays and level L-2. Peak = input + output + level L-1 (plus the excess of
 * level L-2 over the output when isolated vertices dominate). After success the arena
 * keeps only the output arrays. No other scratch: the new-vertex index of each edge goes
 * straight into the child corner arrays and the per-vertex class into a private tag bit.
 */
#include "mesh_internal.h"

#define ETAG_SHARP (SUBD_ETAG_BOUNDARY | SUBD_ETAG_CREASE)
#define VTAG_CALLER (SUBD_VTAG_CORNER | SUBD_VTAG_FIXED)
#define VTAG_REGULAR 0x80u /* private, while one level is refined: regular crease vertex */
#define BETA_CACHE 16u     /* b(n) kept for n < BETA_CACHE during one call */

/* Counts of one level. */
typedef struct loop_counts {
    uint32_t nv, nf, ne, nbe;
} loop_counts;

/* A level as read (the input mesh or an intermediate level). Faces are triangles, so
 * corner c belongs to face c / 3 and face_start / corner_face are not needed. */
typedef struct loop_src {
    uint32_t nv, nf;
    const subd_real *pos;
    const uint32_t *cv, *twin, *vout;
    const uint8_t *vtag, *etag;
} loop_src;

/* A level as written. twin and vout are NULL for a final level without adjacency. */
typedef struct loop_dst {
    subd_real *pos;
    uint32_t *cv, *twin, *vout;
    uint8_t *vtag, *etag;
} loop_dst;

/* Array offsets inside the block. Intermediate levels: pos, cv, twin, vout, vtag, etag.
 * Output: pos, face_start, corner_vert, corner_face, vert_tag, edge_tag, twin, vert_out. */
enum { LV_POS, LV_CV, LV_TWIN, LV_VOUT, LV_VTAG, LV_ETAG, LV_N };
enum { OUT_POS, OUT_FS, OUT_CV, OUT_CF, OUT_VTAG, OUT_ETAG, OUT_TWIN, OUT_VOUT, OUT_N };

typedef struct loop_layout {
    loop_counts c0;          /* the input                                           */
    loop_counts cl;          /* level L                                             */
    uint32_t out_off[OUT_N];
    uint32_t out_bytes;      /* the output arrays                                   */
    uint32_t y_bytes;        /* region at offset 0: max(out_bytes, level L-2)       */
    uint32_t x_off;          /* region of level L-1                                 */
    uint32_t total;          /* the plan                                            */
} loop_layout;

/* ------------------------------------------------------------------------------------ */
/* Counts and layout                                                                      */

/* One level's counts from its parent's: V' = V + E, F' = 4F, E' = 2E + 3F, B' = 2B.
 * Returns 0 when a count (or 3F, the corners) does not fit below SUBD_NONE. */
static int counts_next(const loop_counts *p, loop_counts *c)
{
    uint64_t nv = (uint64_t)p->nv + p->ne, nf = 4u * (uint64_t)p->nf;
    uint64_t ne = 2u * (uint64_t)p->ne + 3u * (uint64_t)p->nf, nbe = 2u * (uint64_t)p->nbe;
    if (nv >= SUBD_NONE || 3u * nf >= SUBD_NONE || ne >= SUBD_NONE || nbe >= SUBD_NONE) return 0;
    c->nv = (uint32_t)nv;
    c->nf = (uint32_t)nf;
    c->ne = (uint32_t)ne;
    c->nbe = (uint32_t)nbe;
    return 1;
}

/* Offsets of an intermediate level's arrays; returns its bytes (UINT32_MAX: too big). */
static uint32_t level_layout(const loop_counts *c, uint32_t off[LV_N])
{
    uint32_t t = 0, nc = 3u * c->nf;
    off[LV_POS] = t;  subd_size_add(&t, c->nv, 3u * (uint32_t)sizeof(subd_real));
    off[LV_CV] = t;   subd_size_add(&t, nc, 4u);
    off[LV_TWIN] = t; subd_size_add(&t, nc, 4u);
    off[LV_VOUT] = t; subd_size_add(&t, c->nv, 4u);
    off[LV_VTAG] = t; subd_size_add(&t, c->nv, 1u);
    off[LV_ETAG] = t; subd_size_add(&t, nc, 1u);
    return t;
}

static uint32_t out_layout(const loop_counts *c, int adjacency, uint32_t off[OUT_N])
{
    uint32_t t = 0, nc = 3u * c->nf;
    off[OUT_POS] = t;  subd_size_add(&t, c->nv, 3u * (uint32_t)sizeof(subd_real));
    off[OUT_FS] = t;   subd_size_add(&t, c->nf + 1u, 4u);
    off[OUT_CV] = t;   subd_size_add(&t, nc, 4u);
    off[OUT_CF] = t;   subd_size_add(&t, nc, 4u);
    off[OUT_VTAG] = t; subd_size_add(&t, c->nv, 1u);
    off[OUT_ETAG] = t; subd_size_add(&t, nc, 1u);
    off[OUT_TWIN] = t; if (adjacency) subd_size_add(&t, nc, 4u);
    off[OUT_VOUT] = t; if (adjacency) subd_size_add(&t, c->nv, 4u);
    return t;
}

static int mesh_ok(const subd_mesh *m)
{
    if (!m->face_start) return 0;
    if (m->num_verts && (!m->pos || !m->vert_out || !m->vert_tag)) return 0;
    if (m->num_corners && (!m->corner_vert || !m->twin || !m->edge_tag)) return 0;
    return 1;
}

/* Checks the arguments and the input, and computes the one layout of plan and run. */
static int loop_layout_of(const subd_mesh *in, const subd_loop_opts *o, loop_layout *lay, subd_diag *d)
{
    loop_counts prev2, prev1, cur;
    uint32_t f, h, nbe = 0, k, lv_off[LV_N], b1 = 0, b2 = 0, t;
    if (!in || !o || !mesh_ok(in)) return subd_fail(d, SUBD_ERR_PARAM);
    if (o->levels < 1u || o->levels > SUBD_MAX_LEVELS) return subd_fail(d, SUBD_ERR_PARAM);
    if (o->boundary != SUBD_LOOP_BOUNDARY_PAPER && o->boundary != SUBD_LOOP_BOUNDARY_BSPLINE)
        return subd_fail(d, SUBD_ERR_PARAM);
    if (o->flags & ~SUBD_LOOP_ADJACENCY) return subd_fail(d, SUBD_ERR_PARAM);
    if (in->face_start[0] != 0u || in->face_start[in->num_faces] != in->num_corners)
        return subd_fail(d, SUBD_ERR_PARAM);
    for (f = 0; f < in->num_faces; f++) {
        if (in->face_start[f + 1u] - in->face_start[f] != 3u) {
            d->face = f;
            return subd_fail(d, SUBD_ERR_FACE_SIZE);
        }
    }
    for (h = 0; h < in->num_corners; h++)
        if (in->twin[h] == SUBD_NONE) nbe++;
    cur.nv = in->num_verts;
    cur.nf = in->num_faces;
    cur.ne = (in->num_corners + nbe) / 2u;
    cur.nbe = nbe;
    lay->c0 = cur;
    prev1 = prev2 = cur;
    for (k = 1; k <= o->levels; k++) {
        prev2 = prev1;
        prev1 = cur;
        if (!counts_next(&prev1, &cur)) return subd_fail(d, SUBD_ERR_TOO_BIG);
    }
    lay->cl = cur;
    lay->out_bytes = out_layout(&cur, (o->flags & SUBD_LOOP_ADJACENCY) != 0u, lay->out_off);
    if (o->levels >= 2u) b1 = level_layout(&prev1, lv_off);
    if (o->levels >= 3u) b2 = level_layout(&prev2, lv_off);
    lay->y_bytes = lay->out_bytes > b2 ? lay->out_bytes : b2;
    lay->x_off = lay->y_bytes;
    t = lay->y_bytes;
    if (lay->out_bytes == UINT32_MAX || b1 == UINT32_MAX || b2 == UINT32_MAX || b1 > UINT32_MAX - t)
        return subd_fail(d, SUBD_ERR_TOO_BIG);
    lay->total = t + b1;
    if (lay->total == UINT32_MAX) return subd_fail(d, SUBD_ERR_TOO_BIG);
    return SUBD_OK;
}

int subd_loop_plan(const subd_mesh *in, const subd_loop_opts *o, uint32_t *bytes)
{
    loop_layout lay;
    subd_diag d;
    int st;
    if (!bytes) return SUBD_ERR_PARAM;
    subd_diag_clear(&d);
    st = loop_layout_of(in, o, &lay, &d);
    if (st != SUBD_OK) return st;
    *bytes = lay.total;
    return SUBD_OK;
}

/* ------------------------------------------------------------------------------------ */
/* Weights                                                                                */

/* round(A^2 / 2^66) for A < 2^64, from four 32x32 -> 64-bit products. */
static uint64_t sq_q66(uint64_t a)
{
    uint64_t a0 = (uint32_t)a, a1 = a >> 32;
    uint64_t p00 = a0 * a0, p01 = a0 * a1, p11 = a1 * a1;
    uint64_t mid = (p00 >> 32) + (uint32_t)p01 + (uint32_t)p01;
    uint64_t hi = p11 + (p01 >> 32) + (p01 >> 32) + (mid >> 32);
    return (hi >> 2) + ((hi >> 1) & 1u);
}

/* Loop's b(n) = (5/8 - (3/8 + 1/4 cos(2 pi / n))^2) / n, n >= 1. In Q2.62:
 * A = 4 (3/8 + c/4) = 3/2 + c lies in [1/2, 5/2] (as an unsigned value * 2^62 < 2^64),
 * (A/4)^2 = A^2 / 2^66 in Q62, the quotient by n rounded to nearest, then one rounding to
 * subd_real. Exact at n = 3, 4, 6 (3/16, 31/256, 1/16), where cos is exact. */
static subd_real loop_beta(uint32_t n)
{
    int64_t c = subd_cos_turns_q62(1, (int32_t)n);
    uint64_t a = ((uint64_t)3 << 61) + (uint64_t)c; /* c >= -2^62 > -3 * 2^61: no wrap */
    uint64_t num = ((uint64_t)5 << 59) - sq_q66(a); /* >= 0: (A/4)^2 <= 25/64 < 5/8 */
    return subd_real_from_q62((int64_t)((num + n / 2u) / n));
}

typedef struct beta_cache {
    subd_real b[BETA_CACHE];
    uint32_t have; /* bit n: b[n] is valid */
} beta_cache;

static subd_real beta_of(beta_cache *bc, uint32_t n)
{
    if (n >= BETA_CACHE) return loop_beta(n);
    if (!(bc->have & (1u << n))) {
        bc->b[n] = loop_beta(n);
        bc->have |= 1u << n;
    }
    return bc->b[n];
}

/* ------------------------------------------------------------------------------------ */
/* Navigation on a triangle level                                                         */

static uint32_t tri_next(uint32_t h) { return (h % 3u == 2u) ? h - 2u : h + 1u; }
static uint32_t tri_prev(uint32_t h) { return (h % 3u == 0u) ? h + 2u : h - 1u; }

static int edge_sharp(const loop_src *s, uint32_t h)
{
    uint32_t t = s->twin[h];
    if (t == SUBD_NONE || (s->etag[h] & ETAG_SHARP)) return 1;
    return (s->etag[t] & SUBD_ETAG_CREASE) != 0u;
}

/* One-ring iterator: outgoing half-edges from vert_out, rotating with twin(prev(h)); on a
 * boundary the last neighbour is the origin of the incoming boundary half-edge. Bounded by
 * the number of corners whatever the input. */
typedef struct ring_it {
    uint32_t h0, h, steps, tail;
} ring_it;

static void ring_begin(const loop_src *s, uint32_t v, ring_it *it)
{
    it->h0 = it->h = s->vout[v];
    it->steps = 0;
    it->tail = 0;
}

/* Next neighbour (SUBD_NONE at the end); *sharp says whether the edge to it is sharp. */
static uint32_t ring_step(const loop_src *s, ring_it *it, int *sharp)
{
    uint32_t h = it->h, p, t, nb;
    if (h == SUBD_NONE) return SUBD_NONE;
    if (it->tail) {
        it->h = SUBD_NONE;
        *sharp = 1;
        return s->cv[h];
    }
    nb = s->cv[tri_next(h)];
    *sharp = edge_sharp(s, h);
    p = tri_prev(h);
    t = s->twin[p];
    if (t == SUBD_NONE) {
        it->h = p;
        it->tail = 1;
    } else if (t == it->h0 || ++it->steps >= 3u * s->nf) {
        it->h = SUBD_NONE;
    } else {
        it->h = t;
    }
    return nb;
}

/* ------------------------------------------------------------------------------------ */
/* Position rules                                                                         */

static const subd_real *P(const loop_src *s, uint32_t v) { return s->pos + 3u * v; }

/* out = sum w_i x_i over k points, accumulated per coordinate in the given order. */
static void combine(subd_real *out, uint32_t k, const subd_real *w, const subd_real *const *x, uint32_t *ovf)
{
    uint32_t j, i;
    for (j = 0; j < 3u; j++) {
        subd_acc acc = subd_acc_zero();
        for (i = 0; i < k; i++) acc = subd_acc_add(acc, w[i], x[i][j]);
        out[j] = subd_acc_real(acc, ovf);
    }
}

/* Even vertex v: child position and child tag (with the private regular bit). */
static void refine_vertex(const loop_src *s, const loop_dst *t, uint32_t v, beta_cache *bc, uint32_t *ovf)
{
    subd_real *out = t->pos + 3u * v;
    const subd_real *pv = P(s, v);
    uint8_t tag = (uint8_t)(s->vtag[v] & VTAG_CALLER);
    uint32_t n = 0, nsharp = 0, nb, snb[2] = {0, 0}, sidx[2] = {0, 0}, j;
    int sharp, boundary;
    ring_it it;

    if (s->vout[v] == SUBD_NONE) { /* isolated: copied */
        for (j = 0; j < 3u; j++) out[j] = pv[j];
        t->vtag[v] = (uint8_t)(tag | SUBD_VTAG_ISOLATED);
        return;
    }
    boundary = s->twin[s->vout[v]] == SUBD_NONE;
    if (boundary) tag |= SUBD_VTAG_BOUNDARY;
    ring_begin(s, v, &it);
    while ((nb = ring_step(s, &it, &sharp)) != SUBD_NONE) {
        if (sharp) {
            if (nsharp < 2u) {
                snb[nsharp] = nb;
                sidx[nsharp] = n;
            }
            nsharp++;
        }
        n++;
    }
    if ((s->vtag[v] & SUBD_VTAG_CORNER) || nsharp >= 3u) { /* corner: fixed */
        for (j = 0; j < 3u; j++) out[j] = pv[j];
    } else if (nsharp == 2u) { /* crease (or boundary) vertex */
        const subd_real w[3] = {SUBD_REAL_FRAC(3, 4), SUBD_REAL_FRAC(1, 8), SUBD_REAL_FRAC(1, 8)};
        const subd_real *x[3];
        x[0] = pv;
        x[1] = P(s, snb[0]);
        x[2] = P(s, snb[1]);
        combine(out, 3, w, x, ovf);
        if (boundary ? n == 4u : (n == 6u && sidx[1] - sidx[0] == 3u)) tag |= VTAG_REGULAR;
    } else { /* smooth or dart: Loop's rule */
        subd_real b = beta_of(bc, n), wc = SUBD_REAL_ONE;
        subd_acc acc[3];
        /* b rounds to 0 in Q16.16 from n ~ 30000 on, before n overflows subd_from_int */
        if (b != (subd_real)0) wc = subd_sub(wc, subd_mul(subd_from_int((int32_t)n, ovf), b, ovf), ovf);
        for (j = 0; j < 3u; j++) acc[j] = subd_acc_add(subd_acc_zero(), wc, pv[j]);
        ring_begin(s, v, &it);
        while ((nb = ring_step(s, &it, &sharp)) != SUBD_NONE)
            for (j = 0; j < 3u; j++) acc[j] = subd_acc_add(acc[j], b, P(s, nb)[j]);
        for (j = 0; j < 3u; j++) out[j] = subd_acc_real(acc[j], ovf);
    }
    t->vtag[v] = tag;
}

/* New vertex m on the edge of half-edge h (the lower half-edge of its edge; tw its twin).
 * The child tags of the parent's vertices are already set (regular bit). */
static void refine_edge(const loop_src *s, const loop_dst *t, uint32_t h, uint32_t tw, uint32_t m,
                        subd_loop_boundary rule, uint32_t *ovf)
{
    uint32_t a = s->cv[h], b = s->cv[tri_next(h)];
    subd_real w[4];
    const subd_real *x[4];
    x[0] = P(s, a);
    x[1] = P(s, b);
    if (!edge_sharp(s, h)) {
        x[2] = P(s, s->cv[tri_prev(h)]);
        x[3] = P(s, s->cv[tri_prev(tw)]);
        w[0] = w[1] = SUBD_REAL_FRAC(3, 8);
        w[2] = w[3] = SUBD_REAL_FRAC(1, 8);
        combine(t->pos + 3u * m, 4, w, x, ovf);
        return;
    }
    {
        int ra = (t->vtag[a] & VTAG_REGULAR) != 0u, rb = (t->vtag[b] & VTAG_REGULAR) != 0u;
        if (rule == SUBD_LOOP_BOUNDARY_BSPLINE || ra == rb) {
            w[0] = w[1] = SUBD_REAL_FRAC(1, 2);
        } else {
            w[0] = ra ? SUBD_REAL_FRAC(5, 8) : SUBD_REAL_FRAC(3, 8);
            w[1] = rb ? SUBD_REAL_FRAC(5, 8) : SUBD_REAL_FRAC(3, 8);
        }
        combine(t->pos + 3u * m, 2, w, x, ovf);
    }
}

/* ------------------------------------------------------------------------------------ */
/* One level                                                                              */

/* Child corner index of corner j of child k of face f. */
#define CC(f, k, j) (12u * (f) + 3u * (k) + (j))

/* The two child half-edges along parent half-edge h = 3f + i (v_i -> v_{i+1}):
 * first v_i -> m_i is corner 0 of child i, second m_i -> v_{i+1} corner 2 of child i+1. */
static uint32_t half_first(uint32_t h) { return CC(h / 3u, h % 3u, 0u); }
static uint32_t half_second(uint32_t h)
{
    uint32_t f = h / 3u, i = h % 3u;
    return CC(f, (i + 1u) % 3u, 2u);
}

static void refine_level(const loop_src *s, const loop_dst *t, subd_loop_boundary rule, beta_cache *bc,
                         uint32_t *ovf)
{
    uint32_t v, f, i, h, e = 0, nc = 3u * s->nf;

    for (v = 0; v < s->nv; v++) refine_vertex(s, t, v, bc, ovf);

    /* New vertices in lower-half-edge order; their index goes straight into the three
     * child corners of each adjacent face that use it. */
    for (h = 0; h < nc; h++) {
        uint32_t tw = s->twin[h], m, g;
        if (tw != SUBD_NONE && tw < h) continue;
        m = s->nv + e++;
        for (g = h;; g = tw) {
            uint32_t gf = g / 3u, gi = g % 3u;
            t->cv[CC(gf, gi, 1u)] = m;
            t->cv[CC(gf, (gi + 1u) % 3u, 2u)] = m;
            t->cv[CC(gf, 3u, gi)] = m;
            if (g == tw || tw == SUBD_NONE) break;
        }
        t->vtag[m] = (tw == SUBD_NONE) ? (uint8_t)SUBD_VTAG_BOUNDARY : (uint8_t)0u;
        refine_edge(s, t, h, tw, m, rule, ovf);
    }

    /* Old vertices in the corner children, edge tags, twins. */
    for (f = 0; f < s->nf; f++) {
        for (i = 0; i < 3u; i++) {
            uint32_t hp = 3u * f + i, tw = s->twin[hp];
            uint8_t tag = (uint8_t)(s->etag[hp] & SUBD_ETAG_CREASE);
            if (tw == SUBD_NONE) tag = (uint8_t)(tag | SUBD_ETAG_BOUNDARY);
            else tag = (uint8_t)(tag | (s->etag[tw] & SUBD_ETAG_CREASE));
            t->cv[CC(f, i, 0u)] = s->cv[hp];
            t->etag[half_first(hp)] = tag;
            t->etag[half_second(hp)] = tag;
            t->etag[CC(f, i, 1u)] = 0;
            t->etag[CC(f, 3u, i)] = 0;
            if (t->twin) {
                t->twin[half_first(hp)] = (tw == SUBD_NONE) ? SUBD_NONE : half_second(tw);
                t->twin[half_second(hp)] = (tw == SUBD_NONE) ? SUBD_NONE : half_first(tw);
                t->twin[CC(f, i, 1u)] = CC(f, 3u, (i + 2u) % 3u);
                t->twin[CC(f, 3u, i)] = CC(f, (i + 1u) % 3u, 1u);
            }
        }
    }

    /* vert_out as the builder chooses it: a boundary vertex's boundary half-edge, else
     * its smallest corner. */
    if (t->vout) {
        uint32_t cnv = s->nv + e;
        for (v = 0; v < cnv; v++) t->vout[v] = SUBD_NONE;
        for (h = 0; h < 4u * nc; h++)
            if (t->vout[t->cv[h]] == SUBD_NONE) t->vout[t->cv[h]] = h;
        for (h = 0; h < 4u * nc; h++)
            if (t->twin[h] == SUBD_NONE) t->vout[t->cv[h]] = h;
    }
    for (v = 0; v < s->nv; v++) t->vtag[v] = (uint8_t)(t->vtag[v] & ~VTAG_REGULAR);
}

/* ------------------------------------------------------------------------------------ */

static void carve_level(uint8_t *base, const loop_counts *c, loop_dst *t, loop_src *next)
{
    uint32_t off[LV_N];
    (void)level_layout(c, off);
    t->pos = (subd_real *)(void *)(base + off[LV_POS]);
    t->cv = (uint32_t *)(void *)(base + off[LV_CV]);
    t->twin = (uint32_t *)(void *)(base + off[LV_TWIN]);
    t->vout = (uint32_t *)(void *)(base + off[LV_VOUT]);
    t->vtag = base + off[LV_VTAG];
    t->etag = base + off[LV_ETAG];
    next->nv = c->nv;
    next->nf = c->nf;
    next->pos = t->pos;
    next->cv = t->cv;
    next->twin = t->twin;
    next->vout = t->vout;
    next->vtag = t->vtag;
    next->etag = t->etag;
}

int subd_loop(subd_arena *a, const subd_mesh *in, const subd_loop_opts *o, subd_mesh *out, subd_diag *diag)
{
    subd_diag dummy;
    subd_diag *d = diag ? diag : &dummy;
    loop_layout lay;
    loop_counts cur;
    loop_src src;
    loop_dst fin;
    beta_cache bc;
    subd_mesh m;
    uint8_t *base;
    uint32_t mark, k, ovf = 0, f, c, v, isolated = 0;
    int st, adjacency;

    subd_diag_clear(d);
    if (!a || !out) return subd_fail(d, SUBD_ERR_PARAM);
    st = loop_layout_of(in, o, &lay, d);
    if (st != SUBD_OK) return st;
    d->bytes_needed = lay.total;
    mark = subd_arena_mark(a);
    base = (uint8_t *)subd_arena_alloc(a, lay.total);
    if (!base) return subd_fail(d, SUBD_ERR_NOMEM);
    adjacency = (o->flags & SUBD_LOOP_ADJACENCY) != 0u;
    bc.have = 0;

    src.nv = in->num_verts;
    src.nf = in->num_faces;
    src.pos = in->pos;
    src.cv = in->corner_vert;
    src.twin = in->twin;
    src.vout = in->vert_out;
    src.vtag = in->vert_tag;
    src.etag = in->edge_tag;
    /* the final level goes straight into the output arrays */
    fin.pos = (subd_real *)(void *)(base + lay.out_off[OUT_POS]);
    fin.cv = (uint32_t *)(void *)(base + lay.out_off[OUT_CV]);
    fin.vtag = base + lay.out_off[OUT_VTAG];
    fin.etag = base + lay.out_off[OUT_ETAG];
    fin.twin = adjacency ? (uint32_t *)(void *)(base + lay.out_off[OUT_TWIN]) : 0;
    fin.vout = adjacency ? (uint32_t *)(void *)(base + lay.out_off[OUT_VOUT]) : 0;
    cur = lay.c0;
    for (k = 1; k <= o->levels; k++) {
        loop_counts child;
        loop_dst dst = fin;
        loop_src next;
        (void)counts_next(&cur, &child); /* cannot fail: the layout checked every level */
        /* levels L-1, L-3, ... in region X; L-2, L-4, ... in the (still unused) output region */
        if (k < o->levels)
            carve_level(base + (((o->levels - 1u - k) % 2u == 0u) ? lay.x_off : 0u), &child, &dst, &next);
        refine_level(&src, &dst, o->boundary, &bc, &ovf);
        if (ovf) {
            subd_arena_rewind(a, mark);
            d->bytes_needed = 0;
            return subd_fail(d, SUBD_ERR_RANGE);
        }
        if (k < o->levels) src = next;
        cur = child;
    }

    m.num_verts = cur.nv;
    m.num_faces = cur.nf;
    m.num_corners = 3u * cur.nf;
    m.pos = fin.pos;
    m.face_start = (uint32_t *)(void *)(base + lay.out_off[OUT_FS]);
    m.corner_vert = fin.cv;
    m.corner_face = (uint32_t *)(void *)(base + lay.out_off[OUT_CF]);
    m.twin = fin.twin;
    m.vert_out = fin.vout;
    m.vert_tag = fin.vtag;
    m.edge_tag = fin.etag;
    for (f = 0; f <= cur.nf; f++) m.face_start[f] = 3u * f;
    for (c = 0; c < m.num_corners; c++) m.corner_face[c] = c / 3u;
    m.num_lines = m.num_line_verts = 0;
    m.line_start = m.line_vert = 0;
    m.num_edges = cur.ne;
    m.num_boundary_edges = cur.nbe;
    m.num_boundary_loops = in->num_boundary_loops; /* refinement splits edges, keeps loops */
    for (v = 0; v < in->num_verts; v++)
        if (in->vert_out[v] == SUBD_NONE) isolated++;
    m.num_isolated = isolated;
    subd_arena_rewind(a, mark + lay.out_bytes);
    d->bytes_needed = 0;
    *out = m;
    return SUBD_OK;
}
