/* SPDX-License-Identifier: MIT */
/* Loop subdivision (Loop 1987) with the boundary rules of the progressive-interpolation
 * paper (loop-progressive-interpolation.txt, section 1 for the scheme, section 4 for the
 * boundary rules) and Hoppe et al. 1994 creases and corners.
 *
 * The rules, the vertex classification (smooth / dart / crease / corner, "regular" for the
 * paper's 5/8-3/8 sharp-edge rule) and the weights are in loop_rules.h / loop_rules.c, the
 * one home that loop_limit.c, pia.c and loop_stream.c use as well. Here:
 *   - SUBD_VTAG_FIXED is carried to the output but does not change any rule (Loop is an
 *     approximating scheme; tag a vertex CORNER to pin it).
 *   - Every sharp edge, boundary or crease, uses the sharp-edge rule of the chosen set,
 *     including one that ends at a dart (the dart end counts as extraordinary). New vertices
 *     on a sharp edge are always regular, as the paper requires.
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
 * convention exactly (the boundary half-edge, else the smallest corner) and is derived in
 * O(1) per vertex: an old vertex's child vert_out is the first child half-edge of its
 * parent vert_out, a new vertex's is a fixed corner of the lower half-edge's face (see
 * new_vout). So with SUBD_LOOP_ADJACENCY the output equals subd_mesh_build of its own face
 * list (the test checks this array by array).
 *
 * Speed (the work is per output face, so constant factors matter; see make bench):
 *   - One pass over the parent faces writes each face's 12 child corners, edge tags and
 *     twins contiguously; the new vertex of an edge is created (position, tag, vert_out) at
 *     its lower half-edge and read back from the twin face's children at the upper one.
 *   - Classes are inherited: refinement keeps every old vertex's valence and number of
 *     sharp edges, and makes new vertices smooth of valence 6 (interior edge) or regular
 *     crease vertices (sharp edge). So only level 1 classifies by walking the input's rings;
 *     on the levels this file made, a smooth vertex (private tag bit TOPO_VTAG_SMOOTH, valence in
 *     a byte array) takes exactly `valence` ring steps with no sharpness tests, and only
 *     crease, corner and high-valence vertices take the general walk. The order of the
 *     weighted sums is the same in both paths (bit-identical output).
 *   - Loop's weights b(n), 1 - n b(n) are cached per valence during a call.
 *
 * Memory (one block, plan = its size; laid out by loop_layout_of, used by plan and run):
 *   [ output: pos corners tags (twins vert_out) | face_start corner_face ]
 *   [ = level L-2, L-4, ... while alive          | level L-1, L-3, ...    ]
 * face_start and corner_face are filled last, after level L is complete, so level L-1 (read
 * while level L is written into the front arrays) lives in their place; level L-2, read
 * while level L-1 is built, lives in the front arrays, which are not written yet. Each
 * region starts where the other ends (region A at max(front arrays, level L-2)), so the
 * plan is max(output arrays, A offset + level L-1): the output alone whenever level L-1
 * fits into face_start + corner_face (16 bytes per output face against about 9), which is
 * every mesh that is not mostly isolated vertices. After success the arena keeps only the
 * output arrays. No other scratch: the per-vertex class is a private tag bit plus a
 * valence byte of the intermediate levels.
 */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "loop_internal.h"
#include "entry.h"
#include "layout.h"
#include "loop_rules.h"
#include "mesh_internal.h"
#include "topo.h"

/* The private class bits of the levels made here: topo.h's table (REGULAR: a regular
 * crease vertex, PAPER sharp-edge rule; SMOOTH: a smooth interior vertex whose valence is in
 * the level's val array, 1..255). */
#define LOOP_VTAG_CALLER (SUBD_VTAG_CORNER | SUBD_VTAG_FIXED)

/* Counts of one level. */
typedef struct loop_counts {
    uint32_t nv, nf, ne, nbe;
} loop_counts;

/* A level as read (the input mesh or an intermediate level). Faces are triangles, so
 * corner c belongs to face c / 3 and face_start / corner_face are not needed. `made` is 1
 * for a level this file made: its vertex tags carry the private class bits, val holds
 * valences, both halves of an edge carry the same tags and vert_out follows the builder's
 * convention. The input gives no such guarantees (made = 0, val = NULL). */
typedef struct loop_src {
    uint32_t nv, nf;
    const subd_real *pos;
    const uint32_t *cv, *twin, *vout;
    const uint8_t *vtag, *val, *etag;
    int made;
} loop_src;

/* A level as written. twin and vout are NULL for a final level without adjacency; val
 * and the private tag bits (other than REGULAR, cleared at the end) only on intermediate
 * levels (val != NULL). */
typedef struct loop_dst {
    subd_real *pos;
    uint32_t *cv, *twin, *vout;
    uint8_t *vtag, *val, *etag;
} loop_dst;

typedef struct loop_layout {
    loop_counts c0;          /* the input                                           */
    loop_counts cl;          /* level L                                             */
    uint32_t out_bytes;      /* the output arrays                                   */
    uint32_t a_off;          /* region A (levels L-1, L-3, ...); region B is at 0   */
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

/* The arrays of the one block, laid out by layout.h's one walk: given no arena it counts,
 * given one it carves. The block is one allocation (so a too-small arena fails before
 * anything is taken); its regions are carved through an arena over the region's bytes
 * (block_region), and plan and run call the same two functions below. */

/* An intermediate level's arrays (val and the private tag bits included). The
 * SUBD_LOOP_LEVEL_BYTES_ sum in subd_loop.h is the same walk. */
static int level_layout(subd_arena *a, const loop_counts *c, loop_dst *t, uint32_t *bytes)
{
    subd_layout l;
    uint32_t nc = 3u * c->nf;
    subd_layout_begin(&l, a);
    t->pos = subd_layout_take(&l, c->nv, 3u * (uint32_t)sizeof(subd_real));
    t->cv = subd_layout_take(&l, nc, 4u);
    t->twin = subd_layout_take(&l, nc, 4u);
    t->vout = subd_layout_take(&l, c->nv, 4u);
    t->vtag = subd_layout_take(&l, c->nv, 1u);
    t->val = subd_layout_take(&l, c->nv, 1u);
    t->etag = subd_layout_take(&l, nc, 1u);
    return subd_layout_end(&l, bytes);
}

/* The output arrays: first the front arrays that level L is refined into (t; *front = their
 * bytes), then face_start (*fs) and corner_face (*cf), filled last over level L-1.
 * SUBD_LOOP_OUT_BYTES_ / SUBD_LOOP_FRONT_BYTES_ in subd_loop.h are the same walk. */
static int out_layout(subd_arena *a, const loop_counts *c, int adjacency, loop_dst *t, uint32_t **fs,
                      uint32_t **cf, uint32_t *front, uint32_t *bytes)
{
    subd_layout l;
    uint32_t nc = 3u * c->nf;
    subd_layout_begin(&l, a);
    t->pos = subd_layout_take(&l, c->nv, 3u * (uint32_t)sizeof(subd_real));
    t->cv = subd_layout_take(&l, nc, 4u);
    t->vtag = subd_layout_take(&l, c->nv, 1u);
    t->etag = subd_layout_take(&l, nc, 1u);
    t->twin = adjacency ? subd_layout_take(&l, nc, 4u) : 0;
    t->vout = adjacency ? subd_layout_take(&l, c->nv, 4u) : 0;
    t->val = 0;
    (void)subd_layout_end(&l, front);
    *fs = subd_layout_take(&l, c->nf + 1u, 4u);
    *cf = subd_layout_take(&l, nc, 4u);
    return subd_layout_end(&l, bytes);
}

/* An arena over the block's bytes [off, total): what a region's layout carves from. The
 * block and every offset are SUBD_ARENA_ALIGN-aligned, so the region arena skips nothing. */
static void block_region(subd_arena *r, uint8_t *base, uint32_t off, uint32_t total)
{
    subd_arena_init(r, base + off, total - off);
}

/* The arrays subd_loop reads (topo.h's guard: each when its count is non-zero). */
#define LOOP_NEEDS                                                                                            \
    (TOPO_FACE_START | TOPO_POS | TOPO_VERT_OUT | TOPO_VERT_TAG | TOPO_CORNER_VERT | TOPO_TWIN | TOPO_EDGE_TAG)

int subd_loop_check(const subd_mesh *in, const subd_loop_opts *o, uint32_t flags, subd_diag *d)
{
    int st;
    if (!o || !subd_topo_has(in, LOOP_NEEDS)) return subd_fail(d, SUBD_ERR_PARAM);
    if (o->levels < 1u || o->levels > SUBD_MAX_LEVELS) return subd_fail(d, SUBD_ERR_PARAM);
    if (o->boundary != SUBD_LOOP_BOUNDARY_PAPER && o->boundary != SUBD_LOOP_BOUNDARY_BSPLINE)
        return subd_fail(d, SUBD_ERR_PARAM);
    if (o->flags & ~flags) return subd_fail(d, SUBD_ERR_PARAM);
    if (in->face_start[0] != 0u || in->face_start[in->num_faces] != in->num_corners)
        return subd_fail(d, SUBD_ERR_PARAM);
    if ((st = subd_require_triangles(in, d)) != SUBD_OK) return st;
    return SUBD_OK;
}

/* Checks the arguments and the input, and computes the one layout of plan and run. */
static int loop_layout_of(const subd_mesh *in, const subd_loop_opts *o, loop_layout *lay, subd_diag *d)
{
    loop_counts prev2, prev1, cur;
    loop_dst scratch;
    uint32_t *fs, *cf;
    uint32_t h, nbe = 0, k, b1 = 0, b2 = 0, front;
    int st = subd_loop_check(in, o, SUBD_LOOP_ADJACENCY, d);
    if (st != SUBD_OK) return st;
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
    st = out_layout(0, &cur, (o->flags & SUBD_LOOP_ADJACENCY) != 0u, &scratch, &fs, &cf, &front, &lay->out_bytes);
    if (st == SUBD_OK && o->levels >= 2u) st = level_layout(0, &prev1, &scratch, &b1);
    if (st == SUBD_OK && o->levels >= 3u) st = level_layout(0, &prev2, &scratch, &b2);
    if (st != SUBD_OK) return subd_fail(d, st); /* counting fails only with SUBD_ERR_TOO_BIG */
    lay->a_off = front > b2 ? front : b2;
    if (b1 >= UINT32_MAX - lay->a_off) return subd_fail(d, SUBD_ERR_TOO_BIG);
    lay->total = lay->a_off + b1 > lay->out_bytes ? lay->a_off + b1 : lay->out_bytes;
    return SUBD_OK;
}

int subd_loop_plan(const subd_mesh *in, const subd_loop_opts *o, uint32_t *bytes, subd_diag *diag)
{
    subd_diag own, *d = subd_plan_begin(&own, diag);
    loop_layout lay;
    int st;
    if (!bytes) return subd_plan_end(d, SUBD_ERR_PARAM);
    st = loop_layout_of(in, o, &lay, d);
    if (st == SUBD_OK) *bytes = lay.total;
    return subd_plan_end(d, st);
}

/* ------------------------------------------------------------------------------------ */
/* Navigation on a triangle level (tri_next, tri_prev: mesh_internal.h)                   */

/* Rings are walked by topo.h's iterator (topo_ring_begin_tri over the level's arrays) and
 * sharpness is topo_edge_sharp; the 1->4 child numbering is topo.h's as well. */

/* Child corner index of corner j of child k of face f. */
#define LOOP_CC(f, k, j) (12u * (f) + 3u * (k) + (j))

static void ring_begin(const loop_src *s, uint32_t v, topo_ring *it)
{
    topo_ring_begin_tri(it, s->cv, s->twin, 3u * s->nf, s->vout[v]);
}

/* ------------------------------------------------------------------------------------ */
/* Position rules                                                                         */

static const subd_real *P(const loop_src *s, uint32_t v) { return s->pos + 3u * v; }

/* Smooth rule on a level this file made: v is interior with valence n, so the ring is
 * exactly n steps from vert_out: topo.h's fast path topo_tri_fan_step (no tail, no
 * sharpness, no end test), which test_topo holds equal to topo_ring; test loop_compose holds
 * the result equal to the general walk (levels = k against k calls of one level, whose
 * every level is walked by topo_ring), bit for bit. */
static void smooth_fast(const loop_src *s, subd_real *out, uint32_t v, uint32_t n, loop_weights w, uint32_t *ovf)
{
    subd_acc acc[3];
    uint32_t h = s->vout[v], k, nc = 3u * s->nf;
    loop_smooth_begin(acc, w, P(s, v));
    for (k = 0; k < n; k++) {
        loop_smooth_add(acc, w, P(s, topo_tri_fan_step(s->cv, s->twin, &h)));
        if (h >= nc) break; /* cannot happen on a made level; keeps reads in bounds */
    }
    loop_smooth_end(out, acc, ovf);
}

/* Even vertex v by the general walk, which also classifies it: child position, child tag
 * (public bits, REGULAR, and SMOOTH + valence when t->val is given) and child vert_out. */
static void vertex_general(const loop_src *s, const loop_dst *t, uint32_t v, loop_wcache *bc, uint32_t *ovf)
{
    subd_real *out = t->pos + 3u * v;
    const subd_real *pv = P(s, v);
    uint8_t tag = (uint8_t)(s->vtag[v] & LOOP_VTAG_CALLER);
    uint32_t j, hmin = SUBD_NONE, n;
    int boundary;
    topo_ring it;
    loop_vinfo c;

    if (s->vout[v] == SUBD_NONE) { /* isolated: copied */
        for (j = 0; j < 3u; j++) out[j] = pv[j];
        t->vtag[v] = (uint8_t)(tag | SUBD_VTAG_ISOLATED);
        if (t->vout) t->vout[v] = SUBD_NONE;
        return;
    }
    boundary = s->twin[s->vout[v]] == SUBD_NONE;
    if (boundary) tag |= SUBD_VTAG_BOUNDARY;
    ring_begin(s, v, &it);
    subd_loop_classify_ring(&it, s->etag, (s->vtag[v] & SUBD_VTAG_CORNER) != 0u, &c, &hmin);
    n = c.valence;
    /* vert_out as the builder chooses it: the boundary half-edge, else the smallest corner
     * (the children of v's corners are ordered like them) */
    if (t->vout) t->vout[v] = topo_loop_half_first(boundary ? s->vout[v] : hmin);
    if (c.cls == LOOP_CORNER) { /* corner: fixed */
        for (j = 0; j < 3u; j++) out[j] = pv[j];
    } else if (c.cls == LOOP_CREASE) { /* crease (or boundary) vertex */
        loop_rule_crease(out, pv, P(s, c.c0), P(s, c.c1), ovf);
        if (c.regular) tag |= TOPO_VTAG_REGULAR;
    } else { /* smooth or dart: Loop's rule */
        loop_weights w = subd_loop_weights_of(bc, n, ovf);
        subd_acc acc[3];
        loop_smooth_begin(acc, w, pv);
        ring_begin(s, v, &it);
        while (topo_ring_step(&it)) loop_smooth_add(acc, w, P(s, it.nb));
        loop_smooth_end(out, acc, ovf);
        /* the child keeps the class: interior, valence n (not boundary: two sharp edges) */
        if (t->val && n <= 255u) {
            tag |= TOPO_VTAG_SMOOTH;
            t->val[v] = (uint8_t)n;
        }
    }
    t->vtag[v] = tag;
}

/* ------------------------------------------------------------------------------------ */
/* One level                                                                              */

/* vert_out of the new vertex on the edge of lower half-edge h = 3f + i (twin tw): its
 * boundary half-edge, else its smallest corner, which is in face f (the twin face has a
 * larger index): topo_loop_new_vout. */
static uint32_t new_vout(uint32_t f, uint32_t i, uint32_t tw)
{
    return 12u * f + topo_loop_new_vout(i, tw == SUBD_NONE);
}

static void refine_level(const loop_src *s, const loop_dst *t, subd_loop_boundary rule, loop_wcache *bc,
                         uint32_t *ovf)
{
    uint32_t v, f, e = s->nv;
    /* class bits kept on the child's new vertices (none on the output) */
    uint8_t keep = t->val ? (uint8_t)TOPO_VTAG_PRIVATE : (uint8_t)0u;

    /* Even vertices. On a made level the class is known: smooth ones take the fast walk. */
    for (v = 0; v < s->nv; v++) {
        uint8_t st = s->made ? s->vtag[v] : (uint8_t)0u;
        if (st & TOPO_VTAG_SMOOTH) {
            uint32_t n = s->val[v];
            smooth_fast(s, t->pos + 3u * v, v, n, subd_loop_weights_of(bc, n, ovf), ovf);
            /* same class, same tags: interior, so only the caller bits and the class */
            t->vtag[v] = (uint8_t)(st & (LOOP_VTAG_CALLER | keep));
            if (t->val) t->val[v] = (uint8_t)n;
            if (t->vout) t->vout[v] = topo_loop_half_first(s->vout[v]);
        } else {
            vertex_general(s, t, v, bc, ovf);
        }
    }

    /* Faces in order: new vertices are numbered by lower half-edge, which is face order;
     * each face's 12 child corners, edge tags and twins are written together. */
    for (f = 0; f < s->nf; f++) {
        uint32_t m[3], i, h0 = 3u * f;
        uint32_t *cv = t->cv + 12u * f;
        uint8_t *et = t->etag + 12u * f;
        uint8_t tag[3];
        for (i = 0; i < 3u; i++) {
            uint32_t h = h0 + i, tw = s->twin[h];
            uint32_t a = s->cv[h], b = s->cv[i == 2u ? h0 : h + 1u];
            uint8_t tg;
            int sharp;
            if (s->made) { /* both halves carry the same BOUNDARY / CREASE bits, nothing else:
                            * topo_edge_sharp in one byte (LOOP_ETAG_SHARP) */
                tg = s->etag[h];
                sharp = (tg & LOOP_ETAG_SHARP) != 0u;
            } else {
                tg = (uint8_t)(s->etag[h] & SUBD_ETAG_CREASE);
                tg = (uint8_t)(tg | (tw == SUBD_NONE ? SUBD_ETAG_BOUNDARY : (s->etag[tw] & SUBD_ETAG_CREASE)));
                sharp = topo_edge_sharp(s->twin, s->etag, h);
            }
            tag[i] = tg;
            if (tw != SUBD_NONE && tw < h) { /* upper half: made at the twin's face */
                m[i] = t->cv[LOOP_CC(tw / 3u, tw % 3u, 1u)];
                continue;
            }
            m[i] = e;
            {
                const subd_real *xa = P(s, a), *xb = P(s, b);
                subd_real *out = t->pos + 3u * e;
                if (!sharp) {
                    loop_rule_edge(out, xa, xb, P(s, s->cv[i == 0u ? h0 + 2u : h - 1u]), P(s, s->cv[tri_prev(tw)]), ovf);
                    t->vtag[e] = (uint8_t)(TOPO_VTAG_SMOOTH & keep);
                    if (t->val) t->val[e] = 6u;
                } else {
                    loop_rule_sharp_edge(out, xa, xb, rule, (t->vtag[a] & TOPO_VTAG_REGULAR) != 0u,
                                         (t->vtag[b] & TOPO_VTAG_REGULAR) != 0u, ovf);
                    /* a new vertex on a sharp edge is a regular crease vertex */
                    t->vtag[e] = (uint8_t)((tw == SUBD_NONE ? SUBD_VTAG_BOUNDARY : 0u) | (TOPO_VTAG_REGULAR & keep));
                }
                if (t->vout) t->vout[e] = new_vout(f, i, tw);
            }
            e++;
        }
        /* child i = (v_i, m_i, m_{i-1}), child 3 = (m0, m1, m2): topo.h's table; parent
         * edge i is split into its two halves, inner edges are untagged */
        {
            uint32_t x[6];
            x[0] = s->cv[h0];
            x[1] = s->cv[h0 + 1u];
            x[2] = s->cv[h0 + 2u];
            x[3] = m[0];
            x[4] = m[1];
            x[5] = m[2];
            topo_loop_child_corners(cv, x);
            topo_loop_child_edge_tags(et, tag);
        }
        if (t->twin) {
            uint32_t *tt = t->twin + 12u * f;
            for (i = 0; i < 3u; i++) {
                uint32_t tw = s->twin[h0 + i], i1 = (i + 1u) % 3u;
                /* outer: v_i -> m_i pairs with the twin's second half, m_i -> v_{i+1} with
                 * its first half; inner: (m_i, m_{i-1}) of child i with child 3's edge
                 * m_{i-1} -> m_i, which is LOOP_CC(3, i+2) */
                tt[topo_loop_first_half(i)] = (tw == SUBD_NONE) ? SUBD_NONE : 12u * (tw / 3u) + topo_loop_second_half(tw % 3u);
                tt[topo_loop_second_half(i)] = (tw == SUBD_NONE) ? SUBD_NONE : topo_loop_half_first(tw);
                tt[3u * i + 1u] = LOOP_CC(f, 3u, (i + 2u) % 3u);
                tt[9u + i] = LOOP_CC(f, i1, 1u);
            }
        }
    }
    /* REGULAR was only for this level's sharp edges; the output has no private bits */
    if (!t->val)
        for (v = 0; v < s->nv; v++) t->vtag[v] = (uint8_t)(t->vtag[v] & ~TOPO_VTAG_PRIVATE);
}

/* ------------------------------------------------------------------------------------ */

/* Carves level c into the region of the block at off and makes it the next source. */
static void carve_level(uint8_t *base, uint32_t off, uint32_t total, const loop_counts *c, loop_dst *t,
                        loop_src *next)
{
    subd_arena r;
    block_region(&r, base, off, total);
    (void)level_layout(&r, c, t, 0); /* cannot fail: the plan fitted the level here */
    next->nv = c->nv;
    next->nf = c->nf;
    next->pos = t->pos;
    next->cv = t->cv;
    next->twin = t->twin;
    next->vout = t->vout;
    next->vtag = t->vtag;
    next->val = t->val;
    next->etag = t->etag;
    next->made = 1;
}

int subd_loop(subd_arena *a, const subd_mesh *in, const subd_loop_opts *o, subd_mesh *out, subd_diag *diag)
{
    subd_entry e;
    subd_diag *d = subd_entry_begin(&e, a, diag);
    subd_arena whole;
    loop_layout lay;
    loop_counts cur;
    loop_src src;
    loop_dst fin;
    loop_wcache bc;
    subd_mesh m;
    uint8_t *base;
    uint32_t *fs, *cf;
    uint32_t k, ovf = 0, f, c, v, isolated = 0, front;
    int st;

    if (!a || !out) return subd_entry_fail(&e, SUBD_ERR_PARAM);
    st = loop_layout_of(in, o, &lay, d);
    if (st != SUBD_OK) return subd_entry_fail(&e, st);
    d->bytes_needed = lay.total;
    base = (uint8_t *)subd_arena_alloc(a, lay.total);
    if (!base) return subd_entry_fail(&e, SUBD_ERR_NOMEM);
    bc.have = 0;

    src.nv = in->num_verts;
    src.nf = in->num_faces;
    src.pos = in->pos;
    src.cv = in->corner_vert;
    src.twin = in->twin;
    src.vout = in->vert_out;
    src.vtag = in->vert_tag;
    src.val = 0;
    src.etag = in->edge_tag;
    src.made = 0;
    /* the final level goes straight into the output's front arrays */
    block_region(&whole, base, 0, lay.total);
    (void)out_layout(&whole, &lay.cl, (o->flags & SUBD_LOOP_ADJACENCY) != 0u, &fin, &fs, &cf, &front, 0);
    cur = lay.c0;
    for (k = 1; k <= o->levels; k++) {
        loop_counts child = {0, 0, 0, 0}; /* counts_next sets it; zero for gcc -O2 on dist/tinysubd.c */
        loop_dst dst = fin;
        loop_src next;
        (void)counts_next(&cur, &child); /* cannot fail: the layout checked every level */
        /* levels L-1, L-3, ... in region A; L-2, L-4, ... in region B (the front arrays) */
        if (k < o->levels)
            carve_level(base, ((o->levels - 1u - k) % 2u == 0u) ? lay.a_off : 0u, lay.total, &child, &dst, &next);
        refine_level(&src, &dst, o->boundary, &bc, &ovf);
        if (ovf) {
            d->bytes_needed = 0;
            return subd_entry_fail(&e, SUBD_ERR_RANGE);
        }
        if (k < o->levels) src = next;
        cur = child;
    }

    /* level L-1 is dead: its region becomes face_start and corner_face */
    m.num_verts = cur.nv;
    m.num_faces = cur.nf;
    m.num_corners = 3u * cur.nf;
    m.pos = fin.pos;
    m.face_start = fs;
    m.corner_vert = fin.cv;
    m.corner_face = cf;
    m.twin = fin.twin;
    m.vert_out = fin.vout;
    m.vert_tag = fin.vtag;
    m.edge_tag = fin.etag;
    for (f = 0; f <= cur.nf; f++) m.face_start[f] = 3u * f;
    for (f = 0, c = 0; f < cur.nf; f++, c += 3u) {
        m.corner_face[c] = f;
        m.corner_face[c + 1u] = f;
        m.corner_face[c + 2u] = f;
    }
    m.num_lines = m.num_line_verts = 0;
    m.line_start = m.line_vert = 0;
    m.num_edges = cur.ne;
    m.num_boundary_edges = cur.nbe;
    m.num_boundary_loops = in->num_boundary_loops; /* refinement splits edges, keeps loops */
    for (v = 0; v < in->num_verts; v++)
        if (in->vert_out[v] == SUBD_NONE) isolated++;
    m.num_isolated = isolated;
    subd_arena_rewind(a, e.mark + lay.out_bytes); /* only the output arrays stay */
    *out = m;
    return subd_entry_ok(&e);
}

void subd_loop_opts_default(subd_loop_opts *o)
{
    if (!o) return;
    o->levels = 1;
    o->boundary = SUBD_LOOP_BOUNDARY_PAPER;
    o->flags = 0;
}
