/* SPDX-License-Identifier: MIT */
/* Streaming alpha curves: S_k(f; n) (Zhang & Wang 2002, section 1, definitions 2 and 3) to
 * the point sink of the common stream interface (include/subd.h "Streams", src/stream.c),
 * bit-identical to subd_alpha_curve, in memory that depends on the level count and the
 * order only; and an adaptive mode that drops points where the curve is straight.
 * Its adaptive mode's chord test (is a span's every point within eps of its segment) is
 * alpha_chord.c's.
 *
 * The refinement is local. One level is a chain of primitive steps: S_2 (an output pair per
 * input edge), k - 2 averages C (an output per input edge) and, on a closed polygon, the
 * shift B^r, r = (k - 2) / 2 (alpha_curve.c). Each step reads its input in order and needs
 * at most its previous input point (plus, on a closed polygon, its first one for the wrap
 * edge, and B^r its first r points, which go to the end). So the whole refinement is a
 * pipeline of L * k small stages, each with a window of a few points; the caller's control
 * polygon is read in order at the bottom and the max level's points come out at the top in
 * subd_alpha_curve's output order. Pulling one point walks down the stages that need input
 * and back up (an explicit stage index, no recursion): the depth-first walk over the
 * control polygon's spans, with a local window per level. Each stage computes exactly the
 * operation alpha_curve.c computes on the same inputs (the same lerp, the same tie-to-even
 * midpoint, the same tag rules, the same Q32.32 weights), so every point has the same bits.
 * The point counts of every stage are the closed forms of alpha_curve.c, so each stage
 * knows which of its inputs is the last (the open end rules need it; no look-ahead).
 *
 * Run-time failures. subd_alpha_curve fails as a whole (a kernel value that fails on some
 * level's edge alpha, or an overflow anywhere, SUBD_ERR_RANGE); a stream that had already
 * emitted points could not take them back. So the begin call proves that the run cannot
 * fail: without tags every level's f_n is computed (a failing one fails the begin with its
 * status, the first level as subd_alpha_curve); when every f_n >= 0, every step is a convex
 * combination and no point can leave the input's bounding box, so with the input's extent
 * inside the range (Q16.16: every coordinate difference below 2^31 units, the lerp's own
 * guard; float: every |coordinate| < 2^126) nothing can overflow. Otherwise (tags, a
 * negative f_n or a wide input) the begin call runs the whole stream once without output
 * and reports what subd_alpha_curve would (a kernel failure: the lowest level's; else an
 * overflow: SUBD_ERR_RANGE), so a stream that starts never fails and a refused input emits
 * nothing. Choice where the paper is silent: none here, the operators are alpha_curve.c's.
 *
 * Adaptive mode (chord > 0). The max level's points are gathered in blocks of
 * ASTREAM_BLOCK segments (consecutive blocks share their end point); inside a block the
 * decision is top-down and nested: a span [a, b] of max-level indices is kept as one
 * segment when every max-level point strictly inside it lies within chord of the segment
 * from point a to point b (subd_alpha_span_near, alpha_chord.c: each distance bounded from
 * above), else it is split
 * at its middle index (explicit stack of spans). Every emitted point is a max-level point
 * with its uniform id and bits (on a C-curve circle they are on the circle) and every
 * max-level point is within chord of the emitted polyline. The cost is the uniform stream's
 * (every max-level point is computed), the output is smaller. Why measured distances
 * instead of an a-priori bound from second differences: the bound's constant depends on
 * the kernel, the stiffness and the tags per level, and a bound loose by the usual factor
 * 2..4 would emit several times the points; the measurement is exact and the memory one
 * block.
 */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "alpha_internal.h"
#include "stream_internal.h"
#include "layout.h"
#include "entry.h"
#include "real_avg.h"

/* per stage: meta words, point slots (3 subd_reals and an int32 tag each) */
#define ASTREAM_META 8u
#define ASTREAM_SLOTS 9u
#define AM_KIND 0u
#define AM_LEVEL 1u
#define AM_N 2u   /* input count */
#define AM_VC 3u  /* open: the input is vertex-centred */
#define AM_GOT 4u /* inputs received */
#define AM_QH 5u  /* output queue head */
#define AM_QN 6u  /* output queue count */
#define AM_R 7u   /* B^r: r */
#define AS_PREV 0u
#define AS_FIRST 1u
#define AS_STORE 2u /* 3 slots: B^r's first r points */
#define AS_Q 5u     /* 4 slots: the output queue */
#define ASTREAM_QCAP 4u
#define ASTREAM_S2 0u
#define ASTREAM_C 1u
#define ASTREAM_BLOCK 256u /* adaptive: segments per block (the header says 256) */
#define ASTREAM_SHIFT 2u

typedef struct astream_state {
    subd_stream_impl impl; /* first (stream_internal.h) */
    subd_stream_ring ring;
    subd_alpha_opts o;
    const subd_real *pos;
    uint32_t *meta;
    subd_real *pts;
    int32_t *tags;
    subd_real *blk; /* adaptive: ASTREAM_BLOCK + 2 points */
    int64_t s_q32;
    uint32_t m, closed, nst, src, pulled, total, ovf, dry;
    int32_t kerr_level, kerr;
    /* per level: the last edge alpha's weights (as alpha_curve.c's one-entry cache) */
    int32_t wnum[SUBD_MAX_LEVELS];
    uint32_t wok[SUBD_MAX_LEVELS];
    subd_alpha_wt w[SUBD_MAX_LEVELS], w2[SUBD_MAX_LEVELS];
    /* adaptive */
    uint32_t adaptive, blk_base, blk_cnt, sp, ended, wrapped, last_done;
    uint32_t stk[2u * 10u]; /* spans: 1 + log2(ASTREAM_BLOCK) = 9 at most */
    subd_real eps; /* the chord tolerance as given (subd_alpha_span_near adds its own margin) */
} astream_state;
SUBD_STREAM_STATE_FITS(astream_state);

/* ---------------------------------------------------------------------------------- */
/* One primitive step per stage                                                          */

static subd_real *astream_slot(astream_state *st, uint32_t s, uint32_t k)
{
    return st->pts + 3u * (ASTREAM_SLOTS * s + k);
}

static int32_t *astream_tag(astream_state *st, uint32_t s, uint32_t k) { return st->tags + ASTREAM_SLOTS * s + k; }

static void astream_copy3(subd_real *o, const subd_real *a)
{
    o[0] = a[0];
    o[1] = a[1];
    o[2] = a[2];
}

/* The next queue slot of stage s (the queue is empty whenever a stage is fed). */
static subd_real *astream_qput(astream_state *st, uint32_t s, int32_t tag)
{
    uint32_t *mt = st->meta + ASTREAM_META * s;
    uint32_t k = AS_Q + (mt[AM_QH] + mt[AM_QN]) % ASTREAM_QCAP;
    mt[AM_QN]++;
    *astream_tag(st, s, k) = tag;
    return astream_slot(st, s, k);
}

static void astream_qcopy(astream_state *st, uint32_t s, const subd_real *p, int32_t tag)
{
    astream_copy3(astream_qput(st, s, tag), p);
}

/* The weights of an edge of level `level` with tag sum num2 (subd_alpha_edge_w, as alpha_curve.c's edge_weight). 0 on a kernel failure. */
static int astream_weight(astream_state *st, uint32_t level, int64_t num2)
{
    int64_t f;
    int s;
    if (st->wok[level] && (int64_t)st->wnum[level] == num2) return 1;
    s = subd_alpha_kernel_q32(st->o.kernel, (int32_t)num2, 2 * st->o.alpha_den, level, st->s_q32, &f);
    if (s == SUBD_OK && f <= -SUBD_Q32_ONE) s = SUBD_ERR_PARAM; /* 1 + f_n <= 0 */
    if (s != SUBD_OK) {
        if (st->kerr == SUBD_OK || (int32_t)level < st->kerr_level) {
            st->kerr = s;
            st->kerr_level = (int32_t)level;
        }
        if (!st->dry) return 0;
        /* the dry run goes on with any weight: subd_alpha_curve stops at the lowest failing
         * level, which a depth-first walk may meet after a higher one */
        f = 0;
    }
    subd_alpha_edge_w(f, &st->w[level], &st->w2[level], &st->ovf);
    st->wnum[level] = (int32_t)num2;
    st->wok[level] = 1u;
    return 1;
}

static int astream_edge(astream_state *st, uint32_t level, int32_t ta, int32_t tb)
{
    int64_t num2 = st->o.tag_num ? (int64_t)ta + tb : 2 * (int64_t)st->o.alpha_num;
    return astream_weight(st, level, num2);
}


/* S_2's two points of the edge (a, b): lerp(a, b, w) (tag ta), lerp(b, a, w) (tag tb). */
static int astream_pair(astream_state *st, uint32_t s, uint32_t level, const subd_real *a, int32_t ta,
                        const subd_real *b, int32_t tb)
{
    if (!astream_edge(st, level, ta, tb)) return 0;
    subd_alpha_lerp3(astream_qput(st, s, ta), a, b, st->w[level], &st->ovf);
    subd_alpha_lerp3(astream_qput(st, s, tb), b, a, st->w[level], &st->ovf);
    return 1;
}

static int astream_feed_s2(astream_state *st, uint32_t s, const subd_real *p, int32_t t)
{
    uint32_t *mt = st->meta + ASTREAM_META * s;
    uint32_t i = mt[AM_GOT], n = mt[AM_N], lv = mt[AM_LEVEL];
    subd_real *prev = astream_slot(st, s, AS_PREV);
    int32_t *tprev = astream_tag(st, s, AS_PREV);
    if (st->closed) { /* alpha_curve.c s2_closed: edge i -> 2i, 2i+1; the wrap edge last */
        if (i == 0u) {
            astream_copy3(astream_slot(st, s, AS_FIRST), p);
            *astream_tag(st, s, AS_FIRST) = t;
        } else if (!astream_pair(st, s, lv, prev, *tprev, p, t))
            return 0;
        if (i + 1u == n && !astream_pair(st, s, lv, p, t, astream_slot(st, s, AS_FIRST), *astream_tag(st, s, AS_FIRST)))
            return 0;
    } else if (mt[AM_VC]) { /* s2_open_vertex: [c, pairs of every edge, d] */
        if (i == 0u) astream_qcopy(st, s, p, t);
        else if (!astream_pair(st, s, lv, prev, *tprev, p, t))
            return 0;
        if (i > 0u && i + 1u == n) astream_qcopy(st, s, p, t);
    } else if (n < 3u) { /* a segment stays a segment */
        astream_qcopy(st, s, p, t);
    } else { /* s2_open_edge: [c, start edge's second point, pairs, end edge's first point, d] */
        if (i == 0u) astream_qcopy(st, s, p, t);
        else if (i == 1u) {
            if (!astream_edge(st, lv, t, t)) return 0;
            subd_alpha_lerp3(astream_qput(st, s, t), p, prev, st->w2[lv], &st->ovf); /* lerp(x1, c, 2w) */
        } else if (i + 1u < n) {
            if (!astream_pair(st, s, lv, prev, *tprev, p, t)) return 0;
        } else {
            if (!astream_edge(st, lv, *tprev, *tprev)) return 0;
            subd_alpha_lerp3(astream_qput(st, s, *tprev), prev, p, st->w2[lv], &st->ovf); /* lerp(x(L-2), d, 2w) */
            astream_qcopy(st, s, p, t);
        }
    }
    astream_copy3(prev, p);
    *tprev = t;
    mt[AM_GOT] = i + 1u;
    return 1;
}

static int32_t astream_tmean(int32_t a, int32_t b) { return subd_alpha_tag_mean((int64_t)a + b, 2u); }

static void astream_feed_c(astream_state *st, uint32_t s, const subd_real *p, int32_t t)
{
    uint32_t *mt = st->meta + ASTREAM_META * s;
    uint32_t i = mt[AM_GOT], n = mt[AM_N];
    subd_real *prev = astream_slot(st, s, AS_PREV);
    int32_t *tprev = astream_tag(st, s, AS_PREV);
    if (st->closed) { /* c_closed: mid(p_i, p_i+1), the wrap with p_0 last */
        if (i == 0u) {
            astream_copy3(astream_slot(st, s, AS_FIRST), p);
            *astream_tag(st, s, AS_FIRST) = t;
        } else
            subd_alpha_mid3(astream_qput(st, s, astream_tmean(*tprev, t)), prev, p, &st->ovf);
        if (i + 1u == n)
            subd_alpha_mid3(astream_qput(st, s, astream_tmean(t, *astream_tag(st, s, AS_FIRST))), p,
                        astream_slot(st, s, AS_FIRST), &st->ovf);
    } else if (mt[AM_VC]) { /* c_open_vertex: [c, mid(c, x1) .. mid(x(L-2), d), d] */
        if (i == 0u) astream_qcopy(st, s, p, t);
        else
            subd_alpha_mid3(astream_qput(st, s, astream_tmean(*tprev, t)), prev, p, &st->ovf);
        if (i > 0u && i + 1u == n) astream_qcopy(st, s, p, t);
    } else if (n < 3u) {
        astream_qcopy(st, s, p, t);
    } else { /* c_open_edge: [c (x1's tag), mid(x1, x2) .. mid(x(L-3), x(L-2)), d (x(L-2)'s tag)] */
        if (i == 0u) {
            astream_copy3(astream_slot(st, s, AS_FIRST), p);
        } else if (i == 1u) {
            astream_qcopy(st, s, astream_slot(st, s, AS_FIRST), t);
        } else if (i + 1u < n) {
            subd_alpha_mid3(astream_qput(st, s, astream_tmean(*tprev, t)), prev, p, &st->ovf);
        } else {
            astream_qcopy(st, s, p, *tprev);
        }
    }
    astream_copy3(prev, p);
    *tprev = t;
    mt[AM_GOT] = i + 1u;
}

/* B^r: the first r points go to the end. */
static void astream_feed_shift(astream_state *st, uint32_t s, const subd_real *p, int32_t t)
{
    uint32_t *mt = st->meta + ASTREAM_META * s;
    uint32_t i = mt[AM_GOT], n = mt[AM_N], r = mt[AM_R], j;
    if (i < r) {
        astream_copy3(astream_slot(st, s, AS_STORE + i), p);
        *astream_tag(st, s, AS_STORE + i) = t;
    } else
        astream_qcopy(st, s, p, t);
    if (i + 1u == n)
        for (j = 0; j < r; j++) astream_qcopy(st, s, astream_slot(st, s, AS_STORE + j), *astream_tag(st, s, AS_STORE + j));
    mt[AM_GOT] = i + 1u;
}

static int astream_feed(astream_state *st, uint32_t s, const subd_real *p, int32_t t)
{
    uint32_t kind = st->meta[ASTREAM_META * s + AM_KIND];
    if (kind == ASTREAM_S2) return astream_feed_s2(st, s, p, t);
    if (kind == ASTREAM_C) astream_feed_c(st, s, p, t);
    else
        astream_feed_shift(st, s, p, t);
    return 1;
}

/* The stages of levels * (S_2, C^(k-2), B^r) with their input counts (alpha_curve.c's
 * s2_count / c_count rules); resets every window, the source and the weight cache. */
static void astream_setup(astream_state *st)
{
    uint32_t n = st->m, l, j, s = 0, k = st->o.order, r;
    uint32_t vc = 0;
    for (l = 0; l < st->o.levels; l++) {
        uint32_t *mt = st->meta + ASTREAM_META * s++;
        mt[AM_KIND] = ASTREAM_S2;
        mt[AM_LEVEL] = l;
        mt[AM_N] = n;
        mt[AM_VC] = vc;
        n = (st->closed || vc) ? 2u * n : (n >= 3u ? 2u * n - 2u : n);
        vc = 0;
        for (j = 2; j < k; j++) {
            mt = st->meta + ASTREAM_META * s++;
            mt[AM_KIND] = ASTREAM_C;
            mt[AM_LEVEL] = l;
            mt[AM_N] = n;
            mt[AM_VC] = vc;
            n = st->closed ? n : vc ? n + 1u : (n >= 3u ? n - 1u : n);
            vc = !vc;
        }
        r = st->closed ? ((k - 2u) / 2u) % n : 0u;
        if (r) {
            mt = st->meta + ASTREAM_META * s++;
            mt[AM_KIND] = ASTREAM_SHIFT;
            mt[AM_LEVEL] = l;
            mt[AM_N] = n;
            mt[AM_VC] = 0;
            mt[AM_R] = r;
        }
    }
    for (j = 0; j < s; j++) {
        uint32_t *mt = st->meta + ASTREAM_META * j;
        mt[AM_GOT] = mt[AM_QH] = mt[AM_QN] = 0;
    }
    for (l = 0; l < SUBD_MAX_LEVELS; l++) st->wok[l] = 0;
    st->nst = s;
    st->total = n;
    st->src = st->pulled = 0;
    st->blk_base = st->blk_cnt = st->sp = st->ended = st->wrapped = st->last_done = 0;
}

/* The next max-level point into p (3 subd_reals): 1, or 0 at the end, or -1 on a kernel
 * failure (st->kerr). Walks down to the first stage that can give a point and back up. */
static int astream_pull(astream_state *st, subd_real *p)
{
    uint32_t s = st->nst, guard;
    subd_real x[3];
    int32_t t = 0;
    if (st->pulled >= st->total) return 0;
    if (s == 0u) { /* levels = 0: the control polygon itself */
        astream_copy3(p, st->pos + 3u * st->src++);
        st->pulled++;
        return 1;
    }
    s--;
    /* each round trip feeds one stage; a point needs at most a few per stage */
    for (guard = 0; guard < 64u * (st->nst + 1u); guard++) {
        uint32_t *mt = st->meta + ASTREAM_META * s;
        if (mt[AM_QN] > 0u) {
            uint32_t k = AS_Q + mt[AM_QH];
            astream_copy3(x, astream_slot(st, s, k));
            t = *astream_tag(st, s, k);
            mt[AM_QH] = (mt[AM_QH] + 1u) % ASTREAM_QCAP;
            mt[AM_QN]--;
            if (s + 1u == st->nst) {
                astream_copy3(p, x);
                st->pulled++;
                return 1;
            }
            if (!astream_feed(st, s + 1u, x, t)) return -1;
            s++;
        } else if (s == 0u) {
            if (st->src >= st->m) break; /* cannot happen: the counts are exact */
            t = st->o.tag_num ? st->o.tag_num[st->src] : 0;
            if (!astream_feed(st, 0, st->pos + 3u * st->src, t)) return -1;
            st->src++;
        } else
            s--;
    }
    st->kerr = SUBD_ERR_PARAM; /* unreachable */
    return -1;
}

/* ---------------------------------------------------------------------------------- */
/* The step: one point per round into the queue                                           */

static void astream_emit(astream_state *st, subd_stream_q *q, const subd_real *p, uint32_t id)
{
    subd_point *o = (subd_point *)subd_stream_q_put(q);
    uint32_t k;
    for (k = 0; k < 3u; k++) {
        o->pos[k] = p[k];
        o->tangent[k] = 0;
    }
    o->id = id;
    o->curve = 0;
    o->level = st->o.levels;
    (void)subd_stream_q_commit(q); /* push: the sink's value, in q->stop (subd_stream_q_full) */
}

/* The end of the stream (after the last point went out). */
static int astream_end(subd_stream_q *q)
{
    q->ended = 1;
    return SUBD_OK;
}

static int astream_fail(astream_state *st, subd_diag *d)
{
    (void)d;
    return st->kerr;
}

/* Adaptive: fills the next block; returns 0 when no block is left. */
static int astream_fill(astream_state *st)
{
    uint32_t keep = st->blk_cnt;
    int r;
    if (keep > 0u) { /* the last point is the next block's first */
        astream_copy3(st->blk, st->blk + 3u * (keep - 1u));
        st->blk_base += keep - 1u;
        st->blk_cnt = 1u;
    }
    while (st->blk_cnt < ASTREAM_BLOCK + 1u && !st->ended) {
        r = astream_pull(st, st->blk + 3u * st->blk_cnt);
        if (r < 0) return -1;
        if (r == 0) {
            st->ended = 1u;
            break;
        }
        if (st->pulled == 1u) astream_copy3(st->blk + 3u * (ASTREAM_BLOCK + 1u), st->blk); /* point 0 */
        st->blk_cnt++;
    }
    if (st->ended && st->closed && !st->wrapped && st->blk_cnt < ASTREAM_BLOCK + 1u) {
        astream_copy3(st->blk + 3u * st->blk_cnt++, st->blk + 3u * (ASTREAM_BLOCK + 1u));
        st->wrapped = 1u;
    }
    if (st->blk_cnt < 2u) return 0;
    st->stk[0] = 0;
    st->stk[1] = st->blk_cnt - 1u;
    st->sp = 1u;
    return 1;
}

static int astream_step(void *state, subd_stream_q *q, subd_diag *d)
{
    astream_state *st = (astream_state *)state;
    subd_real p[3];
    uint32_t guard;
    if (!st->adaptive) {
        while (!subd_stream_q_full(q)) {
            int r = astream_pull(st, p);
            if (r < 0) return astream_fail(st, d);
            if (r == 0) return astream_end(q);
            astream_emit(st, q, p, st->pulled - 1u);
        }
        if (q->stop) return q->stop;
        return st->pulled >= st->total ? astream_end(q) : SUBD_OK;
    }
    for (guard = 0; guard < 4u * ASTREAM_BLOCK + 8u && !subd_stream_q_full(q); guard++) {
        if (st->sp > 0u) {
            uint32_t a = st->stk[2u * (st->sp - 1u)], b = st->stk[2u * (st->sp - 1u) + 1u];
            st->sp--;
            if (b - a <= 1u || subd_alpha_span_near(st->eps, st->blk, a, b)) {
                astream_emit(st, q, st->blk + 3u * a, st->blk_base + a);
            } else { /* the left half first: points in index order */
                uint32_t mid = a + (b - a) / 2u;
                st->stk[2u * st->sp] = mid;
                st->stk[2u * st->sp + 1u] = b;
                st->stk[2u * st->sp + 2u] = a;
                st->stk[2u * st->sp + 3u] = mid;
                st->sp += 2u;
            }
            continue;
        }
        if (st->last_done) return astream_end(q);
        {
            int r = astream_fill(st);
            if (r < 0) return astream_fail(st, d);
            if (r == 0) {
                /* open: the last point ends the polyline (closed: it is point 0, emitted) */
                st->last_done = 1u;
                if (!st->closed && st->blk_cnt > 0u)
                    astream_emit(st, q, st->blk + 3u * (st->blk_cnt - 1u), st->blk_base + st->blk_cnt - 1u);
                if (q->stop) return q->stop;
                return astream_end(q);
            }
        }
    }
    return q->stop; /* 0, or the push form's sink asked to stop */
}

/* ---------------------------------------------------------------------------------- */
/* Plan, begin, push                                                                        */

/* The one layout: the state block, the ring (one point), the stages, the adaptive block. */
static int astream_layout(subd_arena *a, uint32_t levels, uint32_t order, astream_state **st, uint8_t **ring,
                          uint32_t *bytes)
{
    subd_layout l;
    uint32_t ns = levels * order;
    void *sp, *rp, *mp, *pp, *tp, *bp;
    subd_layout_begin(&l, a);
    sp = subd_layout_take(&l, 1u, SUBD_STREAM_STATE_BYTES);
    rp = subd_layout_take(&l, 1u, (uint32_t)sizeof(subd_point));
    mp = subd_layout_take(&l, ns, 4u * ASTREAM_META);
    pp = subd_layout_take(&l, ns, 3u * (uint32_t)sizeof(subd_real) * ASTREAM_SLOTS);
    tp = subd_layout_take(&l, ns, 4u * ASTREAM_SLOTS);
    bp = subd_layout_take(&l, ASTREAM_BLOCK + 2u, 3u * (uint32_t)sizeof(subd_real));
    if (st) {
        *st = (astream_state *)sp;
        *ring = (uint8_t *)rp;
        (*st)->meta = (uint32_t *)mp;
        (*st)->pts = (subd_real *)pp;
        (*st)->tags = (int32_t *)tp;
        (*st)->blk = (subd_real *)bp;
    }
    return subd_layout_end(&l, bytes);
}

/* The checks of subd_alpha_curve that need no memory, in its order, and the chord. */
static int astream_check(const subd_real *pos, uint32_t m, int closed, const subd_alpha_opts *o, subd_real chord,
                         int64_t *s_q32, subd_diag *d)
{
    uint32_t bytes, pts, i;
    int st;
    if (!pos) return SUBD_ERR_PARAM;
    if ((st = subd_alpha_check_opts(o, SUBD_ALPHA_MAX_ORDER, s_q32)) != SUBD_OK) return st;
    if (!subd_real_is_finite(chord) || chord < 0) return SUBD_ERR_PARAM;
    if ((st = subd_alpha_curve_plan(m, closed, o, &bytes, &pts)) != SUBD_OK) return st;
    for (i = 0; i < 3u * m; i++)
        if (!subd_real_is_finite(pos[i])) {
            d->vertex = i / 3u;
            return SUBD_ERR_NAN;
        }
    return SUBD_OK;
}

int subd_alpha_curve_stream_plan(uint32_t m, int closed, const subd_alpha_opts *o, subd_real chord, uint32_t *bytes)
{
    int64_t s;
    uint32_t b, pts;
    int st;
    if (!bytes) return SUBD_ERR_PARAM;
    if ((st = subd_alpha_check_opts(o, SUBD_ALPHA_MAX_ORDER, &s)) != SUBD_OK) return st;
    if (!subd_real_is_finite(chord) || chord < 0) return SUBD_ERR_PARAM;
    if ((st = subd_alpha_curve_plan(m, closed, o, &b, &pts)) != SUBD_OK) return st;
    return astream_layout(0, o->levels, o->order, 0, 0, bytes);
}

/* Can the run fail? 0: no (proved as the file comment says), 1: a dry run must tell. */
static int astream_may_fail(astream_state *st)
{
    uint32_t l, k, i;
    if (st->o.tag_num) return 1;
    for (l = 0; l < st->o.levels; l++) {
        int64_t f;
        int s = subd_alpha_kernel_q32(st->o.kernel, 2 * st->o.alpha_num, 2 * st->o.alpha_den, l, st->s_q32, &f);
        if (s != SUBD_OK || f < 0) return 1;
    }
    for (k = 0; k < 3u; k++) {
        subd_real lo = st->pos[k], hi = st->pos[k];
        for (i = 1; i < st->m; i++) {
            subd_real v = st->pos[3u * i + k];
            if (v < lo) lo = v;
            if (v > hi) hi = v;
        }
#if SUBD_FIXED /* the guard differs: the lerp's difference (alpha_internal.h) must be below 2^31 units */
        if ((int64_t)hi - lo >= (int64_t)INT32_MAX) return 1;
#else
        if (lo <= -0x1p126f || hi >= 0x1p126f) return 1;
#endif
    }
    return 0;
}

int subd_alpha_curve_stream_begin(subd_arena *arena, const subd_real *pos, uint32_t m, int closed,
                                  const subd_alpha_opts *o, subd_real chord, subd_stream *s, subd_diag *diag)
{
    subd_entry e;
    subd_diag *d = subd_entry_begin(&e, arena, diag);
    astream_state *st;
    uint8_t *ring;
    uint32_t bytes, i;
    int64_t s_q32;
    int r;
    if (!arena || !s) return subd_entry_fail(&e, SUBD_ERR_PARAM);
    if ((r = astream_check(pos, m, closed, o, chord, &s_q32, d)) != SUBD_OK) return subd_entry_fail(&e, r);
    astream_layout(0, o->levels, o->order, 0, 0, &bytes);
    if (bytes > subd_arena_free_bytes(arena)) {
        d->bytes_needed = bytes;
        return subd_entry_fail(&e, SUBD_ERR_NOMEM);
    }
    if (astream_layout(arena, o->levels, o->order, &st, &ring, &bytes) != SUBD_OK)
        return subd_entry_fail(&e, SUBD_ERR_NOMEM);
    if (o->tag_num)
        for (i = 0; i < m; i++)
            if (o->tag_num[i] > SUBD_ALPHA_MAX_NUM || o->tag_num[i] < -SUBD_ALPHA_MAX_NUM) {
                d->vertex = i;
                return subd_entry_fail(&e, SUBD_ERR_PARAM);
            }
    st->o = *o;
    st->pos = pos;
    st->m = m;
    st->closed = closed ? 1u : 0u;
    st->s_q32 = s_q32;
    st->ovf = 0;
    st->kerr = SUBD_OK;
    st->kerr_level = 0;
    st->dry = 0;
    st->eps = chord;
    st->adaptive = chord > 0 ? 1u : 0u;
    astream_setup(st);
    if (astream_may_fail(st)) { /* the dry run: what subd_alpha_curve would report */
        subd_real p[3];
        uint32_t n;
        st->dry = 1u;
        for (n = 0; n <= st->total; n++)
            if (astream_pull(st, p) <= 0) break;
        st->dry = 0;
        if (st->kerr != SUBD_OK) return subd_entry_fail(&e, st->kerr);
        if (st->ovf) return subd_entry_fail(&e, SUBD_ERR_RANGE);
        astream_setup(st);
    }
    st->impl.step = astream_step;
    st->impl.ring = &st->ring;
    st->impl.ring_items = ring;
    subd_stream_start(s, arena, e.mark, SUBD_STREAM_POINTS, &st->impl, 1u);
    d->status = SUBD_OK;
    d->bytes_needed = 0;
    return SUBD_OK;
}

int subd_alpha_curve_stream(subd_arena *arena, const subd_real *pos, uint32_t m, int closed,
                            const subd_alpha_opts *o, subd_real chord, const subd_point_sink *sink, subd_diag *diag)
{
    subd_stream s;
    int r;
    if (!sink || !sink->point) {
        if (diag) {
            subd_diag_clear(diag);
            diag->status = SUBD_ERR_PARAM;
        }
        return SUBD_ERR_PARAM;
    }
    r = subd_alpha_curve_stream_begin(arena, pos, m, closed, o, chord, &s, diag);
    if (r != SUBD_OK) return r;
    return subd_stream_run_points(&s, sink, diag);
}
