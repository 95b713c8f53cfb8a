/* SPDX-License-Identifier: MIT */
/* Streamed alpha curves (src/alpha_stream.c) against the materialising subd_alpha_curve:
 * every point's bits and id at uniform levels 1..8 (closed and open polygons, every kernel,
 * several orders, stiffnesses and tags), the same points pulled in batches of 1, 7 and 4096
 * as pushed; the adaptive mode's guarantee measured in double (every uniform point within
 * chord of the emitted polyline, emitted points = uniform points), fewer points on straight
 * runs, the C-curve circle's emitted points on the circle; exact plans (= the macro, every
 * smaller arena refused with NOMEM and the arena unchanged); every error of
 * subd_alpha_curve refused with the same status and nothing emitted; the sink's stop value;
 * the point writers (.xyz, G-code) read back by a small parser written here. */
#include "harness.h"
#include "subd_alpha.h"
#if H_HOST
#include <math.h>
#endif

/* device RAM is scarce: points are checked as they come (against subd_alpha_curve's
 * output), only a few are stored */
#define AS_MAXP (H_HOST ? 2600u : 600u)
#define AS_PULL (H_HOST ? 4096u : 512u)
#define AS_MAXID 2600u
static subd_real s_in[3 * 64];
static int32_t s_tags[64];
static subd_point s_pts[AS_MAXP];
static subd_point s_pull[AS_PULL];
static uint32_t s_ids[AS_MAXID];
static uint32_t s_state = 2024u;

#define AS_WORK_BYTES H_ARENA_BYTES
#define AS_WORK h_arena_buf

static void as_opts(subd_alpha_opts *o, uint32_t order, uint32_t levels, uint32_t kernel, int32_t num, int32_t den)
{
    subd_alpha_opts_default(o);
    o->order = order;
    o->levels = levels;
    o->kernel = kernel;
    o->alpha_num = num;
    o->alpha_den = den;
}

static void as_rand_poly(uint32_t m)
{
    uint32_t i;
    for (i = 0; i < 3u * m; i++) s_in[i] = h_int((int32_t)(h_rand(&s_state) % 129u) - 64);
}

/* A sink that gathers the points (stop = the value it returns after `stop_after` points). */
typedef struct as_sink {
    subd_point *p;
    uint32_t n, cap, stop_after;
    int stop;
    const subd_real *ref; /* subd_alpha_curve's points: each point is compared as it comes */
    uint32_t ref_n, level, bad, hash;
} as_sink;

static as_sink s_last; /* the last push's sink: the checks' results */

static int as_gather(void *ctx, const subd_point *p)
{
    as_sink *s = (as_sink *)ctx;
    uint32_t k;
    if (s->n >= s->stop_after) return s->stop;
    if (s->n < s->cap) s->p[s->n] = *p;
    if (s->n < AS_MAXID) s_ids[s->n] = (uint32_t)p->id;
    if (s->ref) {
        if (p->id >= s->ref_n || p->level != s->level || p->curve != 0u) s->bad++;
        else
            for (k = 0; k < 3u; k++)
                if (!h_same(p->pos[k], s->ref[3u * p->id + k]) || p->tangent[k] != 0) s->bad++;
    }
    for (k = 0; k < 3u; k++) {
        uint32_t b = subd_real_bits(p->pos[k]);
        s->hash = h_fnv(s->hash, &b, 4);
    }
    s->hash = h_fnv(s->hash, &p->id, 8);
    s->n++;
    return 0;
}

/* Pushes the stream; with ref (subd_alpha_curve's output of ref_n points) every point is
 * checked against it (s_last.bad counts mismatches). */
static int as_push_ref(subd_arena *a, uint32_t m, int closed, const subd_alpha_opts *o, subd_real chord,
                       const subd_real *ref, uint32_t ref_n, uint32_t *n, subd_diag *d)
{
    subd_point_sink sk;
    int st;
    s_last.p = s_pts;
    s_last.n = 0;
    s_last.cap = AS_MAXP;
    s_last.stop_after = UINT32_MAX;
    s_last.stop = 0;
    s_last.ref = ref;
    s_last.ref_n = ref_n;
    s_last.level = o ? o->levels : 0u;
    s_last.bad = 0;
    s_last.hash = 2166136261u;
    sk.point = as_gather;
    sk.ctx = &s_last;
    st = subd_alpha_curve_stream(a, s_in, m, closed, o, chord, &sk, d);
    *n = s_last.n;
    return st;
}

static int as_push(subd_arena *a, uint32_t m, int closed, const subd_alpha_opts *o, subd_real chord, uint32_t *n,
                   subd_diag *d)
{
    return as_push_ref(a, m, closed, o, chord, 0, 0, n, d);
}

/* The stream equals subd_alpha_curve point by point (bits, ids, level); 1 when it does. */
static int as_same_as_curve(uint32_t m, int closed, const subd_alpha_opts *o, uint32_t *hash)
{
    subd_arena a;
    subd_alpha_curve_out out;
    subd_diag d;
    uint32_t n = 0, i, k, ok = 1, mark;
    int st;
    subd_arena_init(&a, AS_WORK, AS_WORK_BYTES);
    st = subd_alpha_curve(&a, s_in, m, closed, o, &out, &d);
    if (!CHECK_EQ(st, SUBD_OK)) return 0;
    mark = subd_arena_mark(&a);
    st = as_push_ref(&a, m, closed, o, 0, out.pos, out.num_points, &n, &d);
    if (!CHECK_EQ(st, SUBD_OK)) return 0;
    CHECK_EQ(subd_arena_mark(&a), mark);
    if (!CHECK_EQ(n, out.num_points)) return 0;
    ok = s_last.bad == 0u;
    for (i = 0; i < n && i < AS_MAXID; i++) ok &= s_ids[i] == i;
    (void)k;
    if (hash) *hash = h_fnv(*hash, &s_last.hash, 4);
    return CHECK(ok);
}

/* ------------------------------------------------------------------------------------ */

static void astream_uniform_levels(void)
{
    static const uint32_t orders[] = {2, 3, 4, 5, 8};
    uint32_t kern, oi, lev, shape, h = 2166136261u;
    for (shape = 0; shape < 4u; shape++) {
        uint32_t m = shape == 0 ? 3u : shape == 1 ? 5u : shape == 2 ? 2u : 4u;
        int closed = shape < 2u;
        for (kern = 0; kern < 4u; kern++)
            for (oi = 0; oi < sizeof orders / sizeof orders[0]; oi++)
                for (lev = 1; lev <= SUBD_MAX_LEVELS; lev++) {
                    subd_alpha_opts o;
                    as_rand_poly(m);
                    as_opts(&o, orders[oi], lev, kern, 1, 2 * (int32_t)m + 1);
                    if (!as_same_as_curve(m, closed, &o, &h)) {
                        h_str("  at shape ");
                        h_u32(shape);
                        h_str(" kernel ");
                        h_u32(kern);
                        h_str(" order ");
                        h_u32(orders[oi]);
                        h_str(" level ");
                        h_u32(lev);
                        h_nl();
                        return;
                    }
                }
    }
    h_hash("alpha_stream_uniform", h);
}

/* Stiffness (GC0, not smooth, stiff), tags, levels 0, longer polygons, every order. */
static void astream_uniform_params(void)
{
    static const int32_t stiff_num[] = {1, 3, -1, 5, 2};
    static const int32_t stiff_den[] = {1, 10, 4, 2, 1};
    uint32_t si, k, closed, tagged, h = 2166136261u;
    for (si = 0; si < 5u; si++)
        for (k = 2; k <= SUBD_ALPHA_MAX_ORDER; k++)
            for (closed = 0; closed < 2u; closed++)
                for (tagged = 0; tagged < 2u; tagged++) {
                    subd_alpha_opts o;
                    uint32_t m = 7u + k, i;
                    as_rand_poly(m);
                    for (i = 0; i < m; i++) s_tags[i] = (int32_t)(h_rand(&s_state) % 9u) - 4;
                    as_opts(&o, k, 1u + (si + k) % 4u, si % 4u, 1, 9);
                    o.stiffness = SUBD_REAL_FRAC(stiff_num[si], stiff_den[si]);
                    if (tagged) o.tag_num = s_tags;
                    if (!as_same_as_curve(m, (int)closed, &o, &h)) {
                        h_str("  at stiffness ");
                        h_u32(si);
                        h_str(" order ");
                        h_u32(k);
                        h_str(closed ? " closed" : " open");
                        h_str(tagged ? " tagged" : "");
                        h_nl();
                        return;
                    }
                }
    /* levels 0: the control polygon itself */
    {
        subd_alpha_opts o;
        as_rand_poly(6);
        as_opts(&o, 3, 0, SUBD_ALPHA_COS, 1, 6);
        (void)as_same_as_curve(6, 1, &o, &h);
        (void)as_same_as_curve(6, 0, &o, &h);
    }
    h_hash("alpha_stream_params", h);
}

/* Pulling in batches of 1, 7 and 4096 gives the push form's points. */
static void astream_batches(void)
{
    static const uint32_t sizes[] = {1, 7, 4096};
    uint32_t bi, closed, adaptive;
    for (adaptive = 0; adaptive < 2u; adaptive++)
        for (closed = 0; closed < 2u; closed++) {
            subd_arena a;
            subd_alpha_opts o;
            subd_diag d;
            uint32_t n = 0;
            subd_real chord = adaptive ? SUBD_REAL_FRAC(1, 64) : 0;
            as_rand_poly(9);
            subd_alpha_curve_out out;
            uint32_t mark;
            as_opts(&o, 4, 6, SUBD_ALPHA_COS, 1, 9);
            subd_arena_init(&a, AS_WORK, AS_WORK_BYTES);
            if (!CHECK_EQ(subd_alpha_curve(&a, s_in, 9, (int)closed, &o, &out, &d), SUBD_OK)) return;
            mark = subd_arena_mark(&a);
            if (!CHECK_EQ(as_push_ref(&a, 9, (int)closed, &o, chord, out.pos, out.num_points, &n, &d), SUBD_OK)) return;
            if (!CHECK(n <= AS_MAXID && s_last.bad == 0u)) return;
            for (bi = 0; bi < 3u; bi++) {
                subd_stream s;
                uint32_t got = 0, calls = 0, i, ok = 1, want = sizes[bi] < AS_PULL ? sizes[bi] : AS_PULL;
                int r;
                if (!CHECK_EQ(subd_alpha_curve_stream_begin(&a, s_in, 9, (int)closed, &o, chord, &s, &d), SUBD_OK))
                    return;
                /* each batch against the pushed ids and subd_alpha_curve's points */
                while ((r = subd_stream_next_points(&s, s_pull, want)) > 0) {
                    CHECK((uint32_t)r <= want);
                    for (i = 0; i < (uint32_t)r; i++) {
                        uint32_t k, id = (uint32_t)s_pull[i].id;
                        ok &= got + i < n && id == s_ids[got + i] && id < out.num_points;
                        if (id < out.num_points)
                            for (k = 0; k < 3u; k++) ok &= h_same(s_pull[i].pos[k], out.pos[3u * id + k]);
                    }
                    got += (uint32_t)r;
                    if (++calls > 2u * AS_MAXID) break;
                }
                CHECK_EQ(r, 0);
                CHECK_EQ(got, n);
                CHECK(ok);
                CHECK_EQ(subd_arena_mark(&a), mark);
                /* after the end every call returns 0 */
                CHECK_EQ(subd_stream_next_points(&s, s_pull, 4), 0);
            }
            /* ending early gives the arena back */
            {
                subd_stream s;
                if (CHECK_EQ(subd_alpha_curve_stream_begin(&a, s_in, 9, (int)closed, &o, chord, &s, &d), SUBD_OK)) {
                    CHECK(subd_arena_mark(&a) > mark);
                    CHECK_EQ(subd_stream_next_points(&s, s_pull, 3), 3);
                    subd_stream_end(&s);
                    CHECK_EQ(subd_arena_mark(&a), mark);
                    subd_stream_end(&s);
                    CHECK_EQ(subd_stream_next_points(&s, s_pull, 3), 0);
                }
            }
        }
}

/* ------------------------------------------------------------------------------------ */
/* Adaptive                                                                               */

#if H_HOST
/* Distance in double from p to the segment a b. */
static double as_seg_dist(const subd_real *p, const subd_real *a, const subd_real *b)
{
    double u[3], d[3], t = 0, uu = 0, ud = 0, e = 0;
    uint32_t k;
    for (k = 0; k < 3u; k++) {
        u[k] = h_dbl(b[k]) - h_dbl(a[k]);
        d[k] = h_dbl(p[k]) - h_dbl(a[k]);
        uu += u[k] * u[k];
        ud += u[k] * d[k];
    }
    if (uu > 0) t = ud / uu;
    if (t < 0) t = 0;
    if (t > 1) t = 1;
    for (k = 0; k < 3u; k++) e += (d[k] - t * u[k]) * (d[k] - t * u[k]);
    return sqrt(e);
}
#endif

/* The adaptive stream of (m, closed, o, chord) against subd_alpha_curve: ids strictly
 * increasing from 0 (open: ending at the last), each emitted point = the uniform point of
 * its id, every uniform point within chord of the segment of its emitted neighbours
 * (host: in double). Returns the number emitted, 0 on a failed check. */
static uint32_t as_check_adaptive(uint32_t m, int closed, const subd_alpha_opts *o, subd_real chord, double *worst)
{
    subd_arena a;
    subd_alpha_curve_out out;
    subd_diag d;
    uint32_t n = 0, i, k, ok = 1;
    subd_arena_init(&a, AS_WORK, AS_WORK_BYTES);
    if (!CHECK_EQ(subd_alpha_curve(&a, s_in, m, closed, o, &out, &d), SUBD_OK)) return 0;
    if (!CHECK_EQ(as_push_ref(&a, m, closed, o, chord, out.pos, out.num_points, &n, &d), SUBD_OK)) return 0;
    if (!CHECK(n >= 2u && n <= out.num_points && n <= AS_MAXID)) return 0;
    if (!CHECK(s_last.bad == 0u)) return 0; /* every point = the uniform point of its id */
    if (!CHECK(s_ids[0] == 0u)) return 0;
    if (!closed && !CHECK(s_ids[n - 1u] == out.num_points - 1u)) return 0;
    for (i = 1; i < n; i++) ok &= s_ids[i] > s_ids[i - 1u] && s_ids[i] - s_ids[i - 1u] <= 256u;
    (void)k;
    if (!CHECK(ok)) return 0;
#if H_HOST
    {
        double eps = h_dbl(chord), w = 0;
        uint32_t seg = closed ? n : n - 1u;
        for (i = 0; i < seg; i++) {
            uint32_t a0 = s_ids[i], b0 = i + 1u < n ? s_ids[i + 1u] : out.num_points, j;
            const subd_real *pa = out.pos + 3u * a0, *pb = out.pos + 3u * (b0 % out.num_points);
            for (j = a0 + 1u; j < b0; j++) {
                double e = as_seg_dist(out.pos + 3u * j, pa, pb);
                if (e > w) w = e;
            }
        }
        if (worst && w > *worst) *worst = w;
        if (!CHECK(w <= eps)) return 0;
    }
#else
    (void)worst;
#endif
    return n;
}

static void astream_adaptive_chord(void)
{
    static const int32_t chord_den[] = {4, 32, 256, 2048};
    uint32_t ci, closed, k, kern, h = 2166136261u;
    double worst = 0;
    for (closed = 0; closed < 2u; closed++)
        for (k = 2; k <= 4u; k++)
            for (kern = 0; kern < 4u; kern++) {
                uint32_t prev = 0;
                subd_alpha_opts o;
                as_rand_poly(12);
                as_opts(&o, k, 6, kern, 1, 12);
                for (ci = 0; ci < 4u; ci++) {
                    uint32_t n = as_check_adaptive(12, (int)closed, &o, SUBD_REAL_FRAC(1, chord_den[ci]), &worst);
                    if (!n) return;
                    CHECK(n >= prev); /* a smaller chord never emits fewer points */
                    prev = n;
                    h = h_fnv(h, &s_last.hash, 4);
                }
            }
    /* tags and a stiff, level-8 curve */
    {
        subd_alpha_opts o;
        uint32_t i;
        as_rand_poly(10);
        for (i = 0; i < 10u; i++) s_tags[i] = (int32_t)i - 3;
        as_opts(&o, 3, 8, SUBD_ALPHA_COS, 1, 10);
        o.tag_num = s_tags;
        o.stiffness = SUBD_REAL_FRAC(3, 2);
        if (!as_check_adaptive(10, 1, &o, SUBD_REAL_FRAC(1, 100), &worst)) return;
    }
    h_hash("alpha_stream_adaptive", h);
}

/* A straight open polyline: the adaptive stream keeps only every 256th point (block ends). */
static void astream_adaptive_straight(void)
{
    subd_alpha_opts o;
    uint32_t i, n, total;
    subd_arena a;
    subd_alpha_curve_out out;
    subd_diag d;
    for (i = 0; i < 6u; i++) {
        s_in[3u * i] = h_int((int32_t)(i * i)); /* uneven spacing along the x axis */
        s_in[3u * i + 1u] = h_int(2 * (int32_t)(i * i));
        s_in[3u * i + 2u] = h_int(-(int32_t)(i * i));
    }
    as_opts(&o, 3, 7, SUBD_ALPHA_BSPLINE, 0, 1);
    n = as_check_adaptive(6, 0, &o, SUBD_REAL_FRAC(1, 1000), 0);
    subd_arena_init(&a, AS_WORK, AS_WORK_BYTES);
    if (!CHECK_EQ(subd_alpha_curve(&a, s_in, 6, 0, &o, &out, &d), SUBD_OK)) return;
    total = out.num_points;
    CHECK_EQ(n, (total - 1u + 255u) / 256u + 1u);
}

/* C-curve circle (cos kernel, alpha = 1/N turn, the N-gon circumscribing the circle of
 * radius r): the adaptive stream's points are on the circle (they are uniform points) and
 * the chord holds; fewer points than the uniform stream. */
#define AS_R (SUBD_FIXED ? 64 : 1)
static void astream_circle(void)
{
    uint32_t nn, k, i;
    for (nn = 3; nn <= 8u; nn += 5u)
        for (k = 2; k <= 4u; k++) {
            subd_alpha_opts o;
            uint32_t n;
            for (i = 0; i < nn; i++) {
                /* vertex i at angle (i + 1/2)/N turn and radius r / cos(1/(2N) turn) */
                subd_real big = SUBD_FIXED ? (subd_real)(((int64_t)h_int(AS_R) << 30) /
                                                         (subd_cos_turns_q62(1, 2 * (int32_t)nn) >> 32))
                                           : h_int(AS_R) / subd_cos_turns(1, 2 * (int32_t)nn);
#if SUBD_FIXED
                s_in[3u * i] = (subd_real)(((int64_t)big * (subd_cos_turns_q62(2 * (int32_t)i + 1, 2 * (int32_t)nn) >> 30) +
                                            ((int64_t)1 << 31)) >> 32);
                s_in[3u * i + 1u] = (subd_real)(((int64_t)big * (subd_sin_turns_q62(2 * (int32_t)i + 1, 2 * (int32_t)nn) >> 30) +
                                                 ((int64_t)1 << 31)) >> 32);
#else
                s_in[3u * i] = big * subd_cos_turns(2 * (int32_t)i + 1, 2 * (int32_t)nn);
                s_in[3u * i + 1u] = big * subd_sin_turns(2 * (int32_t)i + 1, 2 * (int32_t)nn);
#endif
                s_in[3u * i + 2u] = 0;
            }
            as_opts(&o, k, 7, SUBD_ALPHA_COS, 1, (int32_t)nn);
            n = as_check_adaptive(nn, 1, &o, SUBD_REAL_FRAC(AS_R, 200), 0);
            if (!n) return;
#if H_HOST
            {
                double worst = 0;
                /* tolerance: float 2e-6 relative; fixed 8 LSB of r (test_alpha_curve's
                 * measured radius spread at these orders is below 6) */
                double tol = SUBD_FIXED ? 8.0 / 65536.0 : 2e-6 * AS_R;
                /* closed forms (test_alpha_curve): S_2's level-7 polygon of M = 128 N points
                 * circumscribes the circle (vertices at r / cos(pi / M)); S_3's vertices are
                 * at r prod_{l=1}^{6} cos(pi / (N 2^l)); S_4: all at one radius (regular) */
                double want = AS_R / cos(3.14159265358979323846 / (128.0 * nn)), lo = 1e300, hi = 0;
                uint32_t l;
                if (k == 3u)
                    for (want = AS_R, l = 1; l <= 6u; l++) want *= cos(3.14159265358979323846 / (nn * (double)(1u << l)));
                for (i = 0; i < n && i < AS_MAXP; i++) {
                    double r = hypot(h_dbl(s_pts[i].pos[0]), h_dbl(s_pts[i].pos[1]));
                    if (k <= 3u && fabs(r - want) > worst) worst = fabs(r - want);
                    if (r < lo) lo = r;
                    if (r > hi) hi = r;
                }
                if (hi - lo > worst) worst = hi - lo;
                if (!CHECK(worst <= tol)) {
                    h_str("  order ");
                    h_u32(k);
                    h_str(" N ");
                    h_u32(nn);
                    h_str(" worst (1e-9) ");
                    h_u32((uint32_t)(worst * 1e9));
                    h_nl();
                }
            }
#endif
            CHECK(n < 64u * nn); /* fewer than the uniform 128 N points */
        }
}

/* ------------------------------------------------------------------------------------ */
/* Plans, memory, errors                                                                  */

typedef struct as_call {
    uint32_t m;
    int closed;
    const subd_alpha_opts *o;
    subd_real chord;
    uint32_t n;
} as_call;

static int as_call_run(void *ctx, subd_arena *a, subd_diag *d)
{
    as_call *c = (as_call *)ctx;
    return as_push(a, c->m, c->closed, c->o, c->chord, &c->n, d);
}

static void astream_plan_exact(void)
{
    static uint8_t buf[SUBD_ALPHA_CURVE_STREAM_BYTES(8, 8) + 64 + 8] __attribute__((aligned(8)));
    uint32_t lev, k, plan, p2;
    subd_alpha_opts o;
    for (lev = 0; lev <= SUBD_MAX_LEVELS; lev++)
        for (k = 2; k <= SUBD_ALPHA_MAX_ORDER; k++) {
            as_opts(&o, k, lev, SUBD_ALPHA_COS, 1, 7);
            if (!CHECK_EQ(subd_alpha_curve_stream_plan(5, 1, &o, 0, &plan), SUBD_OK)) return;
            CHECK_EQ(plan, SUBD_ALPHA_CURVE_STREAM_BYTES(lev, k));
            /* independent of m, closed, chord and tags */
            o.tag_num = s_tags;
            CHECK_EQ(subd_alpha_curve_stream_plan(40, 0, &o, SUBD_REAL_ONE, &p2), SUBD_OK);
            CHECK_EQ(p2, plan);
        }
    CHECK(SUBD_ALPHA_CURVE_STREAM_BYTES(8, 8) <= 16u * 1024u);
    /* every smaller arena: NOMEM with the plan, nothing emitted, the arena unchanged */
    for (k = 2; k <= 5u; k += 3u) {
        uint32_t closed;
        for (closed = 0; closed < 2u; closed++) {
            as_call c;
            h_sweep s;
            as_rand_poly(7);
            as_opts(&o, k, 4, SUBD_ALPHA_COS, 1, 7);
            c.m = 7;
            c.closed = (int)closed;
            c.o = &o;
            c.chord = closed ? SUBD_REAL_FRAC(1, 50) : 0;
            if (!CHECK_EQ(subd_alpha_curve_stream_plan(7, (int)closed, &o, c.chord, &plan), SUBD_OK)) return;
            s = h_sweep_make(as_call_run, &c, buf, sizeof buf, plan);
            s.prefix = 8;
            s.step = 7;
            s.in = s_in;
            s.in_bytes = 3u * 7u * (uint32_t)sizeof(subd_real);
            if (!h_arena_sweep(&s)) return;
        }
    }
}

/* One bad input: the stream's status equals subd_alpha_curve's, nothing reaches the sink,
 * the arena is back at 0 and the handle untouched. */
static void as_same_error(uint32_t m, int closed, const subd_alpha_opts *o, int want)
{
    subd_arena a;
    subd_alpha_curve_out out;
    subd_diag d, d2;
    subd_stream s;
    uint32_t n = 99, i;
    uint8_t *sb = (uint8_t *)&s;
    int st, ok = 1;
    subd_arena_init(&a, AS_WORK, AS_WORK_BYTES);
    st = subd_alpha_curve(&a, s_in, m, closed, o, &out, &d);
    CHECK_EQ(st, want);
    CHECK_EQ(as_push(&a, m, closed, o, 0, &n, &d2), st);
    CHECK_EQ(n, 0);
    CHECK_EQ(d2.status, st);
    CHECK_EQ(d2.vertex, d.vertex);
    CHECK_EQ(subd_arena_mark(&a), 0);
    for (i = 0; i < sizeof s; i++) sb[i] = 0xa5u;
    CHECK_EQ(subd_alpha_curve_stream_begin(&a, s_in, m, closed, o, 0, &s, &d2), st);
    for (i = 0; i < sizeof s; i++) ok &= sb[i] == 0xa5u;
    CHECK(ok);
    CHECK_EQ(subd_arena_mark(&a), 0);
}

static int as_stop_sink(void *ctx, const subd_point *p)
{
    uint32_t *n = (uint32_t *)ctx;
    (void)p;
    return ++*n == 5u ? 42 : 0;
}

static void astream_errors(void)
{
    subd_arena a;
    subd_alpha_opts o;
    subd_diag d;
    subd_stream s;
    subd_point_sink sk;
    uint32_t plan, i, n = 0;
    as_rand_poly(5);
    subd_arena_init(&a, AS_WORK, AS_WORK_BYTES);
    as_opts(&o, 2, 2, SUBD_ALPHA_COS, 1, 5);
    sk.point = as_stop_sink;
    sk.ctx = &n;
    /* NULLs and bad options */
    CHECK_FAIL(subd_alpha_curve_stream(0, s_in, 5, 1, &o, 0, &sk, &d), &d, SUBD_ERR_PARAM);
    CHECK_FAIL(subd_alpha_curve_stream(&a, 0, 5, 1, &o, 0, &sk, &d), &d, SUBD_ERR_PARAM);
    CHECK_FAIL(subd_alpha_curve_stream(&a, s_in, 5, 1, 0, 0, &sk, &d), &d, SUBD_ERR_PARAM);
    CHECK_FAIL(subd_alpha_curve_stream(&a, s_in, 5, 1, &o, 0, 0, &d), &d, SUBD_ERR_PARAM);
    CHECK_FAIL(subd_alpha_curve_stream_begin(&a, s_in, 5, 1, &o, 0, 0, &d), &d, SUBD_ERR_PARAM);
    CHECK_EQ(subd_alpha_curve_stream_plan(5, 1, &o, 0, 0), SUBD_ERR_PARAM);
    CHECK_FAIL(subd_alpha_curve_stream(&a, s_in, 5, 1, &o, h_int(-1), &sk, &d), &d, SUBD_ERR_PARAM);
    CHECK_EQ(subd_alpha_curve_stream_plan(5, 1, &o, h_int(-1), &plan), SUBD_ERR_PARAM);
    CHECK_EQ(n, 0);
    as_same_error(2, 1, &o, SUBD_ERR_EMPTY);
    as_same_error(1, 0, &o, SUBD_ERR_EMPTY);
    o.order = 1;
    as_same_error(5, 1, &o, SUBD_ERR_PARAM);
    o.order = SUBD_ALPHA_MAX_ORDER + 1u;
    as_same_error(5, 1, &o, SUBD_ERR_PARAM);
    as_opts(&o, 2, SUBD_MAX_LEVELS + 1u, SUBD_ALPHA_COS, 1, 5);
    as_same_error(5, 1, &o, SUBD_ERR_PARAM);
    as_opts(&o, 2, 1, 7, 1, 5);
    as_same_error(5, 1, &o, SUBD_ERR_PARAM);
    as_opts(&o, 2, 1, SUBD_ALPHA_COS, 1, 0);
    as_same_error(5, 1, &o, SUBD_ERR_PARAM);
    as_opts(&o, 2, 1, SUBD_ALPHA_BSPLINE, 0, 1);
    o.stiffness = SUBD_REAL_FRAC(-1, 2);
    as_same_error(5, 1, &o, SUBD_ERR_DIVERGENT);
    /* too big: 2^26 points after a few levels */
    as_opts(&o, 2, 8, SUBD_ALPHA_BSPLINE, 0, 1);
    as_same_error(1u << 19, 1, &o, SUBD_ERR_TOO_BIG);
    /* run-time failures, refused at the begin: cosh of a large angle, a tag's f_n <= -1
     * (s = 4, cos kernel), overflow */
    as_opts(&o, 2, 1, SUBD_ALPHA_COSH, 40, 1);
    as_same_error(5, 1, &o, SUBD_ERR_RANGE);
    as_opts(&o, 3, 3, SUBD_ALPHA_COS, 0, 5);
    o.stiffness = h_int(4);
    for (i = 0; i < 5u; i++) s_tags[i] = i == 2u ? 8 : 0; /* edges at vertex 2: 0.8 turn, f_0 = 4 cos(0.4 turn) */
    o.tag_num = s_tags;
    as_same_error(5, 1, &o, SUBD_ERR_PARAM);
    as_same_error(5, 0, &o, SUBD_ERR_PARAM);
    s_tags[2] = SUBD_ALPHA_MAX_NUM + 1;
    as_same_error(5, 1, &o, SUBD_ERR_PARAM);
    as_opts(&o, 2, 3, SUBD_ALPHA_COS, 3, 5);
    o.stiffness = h_int(2);
#if SUBD_FIXED /* not a ternary: 3e38f has no Q16.16 value (clang -Wliteral-conversion) */
    s_in[0] = h_int(30000);
#else
    s_in[0] = 3e38f;
#endif
    as_same_error(5, 1, &o, SUBD_ERR_RANGE);
#if SUBD_FIXED
    /* a wide input with f_n >= 0 that still fits: no failure, the dry run passes */
    as_rand_poly(5);
    s_in[0] = h_int(-30000);
    s_in[3] = h_int(30000);
    as_opts(&o, 3, 3, SUBD_ALPHA_BSPLINE, 0, 1);
    (void)as_same_as_curve(5, 1, &o, 0);
#else
    {
        union { uint32_t u; float f; } nan;
        nan.u = 0x7fc00000u;
        as_rand_poly(5);
        s_in[7] = nan.f;
        as_opts(&o, 2, 1, SUBD_ALPHA_COS, 1, 5);
        as_same_error(5, 1, &o, SUBD_ERR_NAN);
        CHECK_FAIL(subd_alpha_curve_stream_begin(&a, s_in, 5, 1, &o, 0, &s, &d), &d, SUBD_ERR_NAN);
        CHECK_EQ(d.vertex, 2);
        as_rand_poly(5);
        CHECK_FAIL(subd_alpha_curve_stream(&a, s_in, 5, 1, &o, nan.f, &sk, &d), &d, SUBD_ERR_PARAM);
    }
#endif
    /* the sink's stop value, returned unchanged; the arena given back */
    as_rand_poly(5);
    as_opts(&o, 3, 4, SUBD_ALPHA_COS, 1, 5);
    n = 0;
    CHECK_EQ(subd_alpha_curve_stream(&a, s_in, 5, 1, &o, 0, &sk, &d), 42);
    CHECK_EQ(n, 5);
    CHECK_EQ(subd_arena_mark(&a), 0);
    /* a stream of points refuses the triangle call, a stale handle every call */
    if (CHECK_EQ(subd_alpha_curve_stream_begin(&a, s_in, 5, 1, &o, 0, &s, &d), SUBD_OK)) {
        subd_tri t;
        CHECK_EQ(subd_stream_next_tris(&s, &t, 1), SUBD_ERR_PARAM);
        CHECK_EQ(subd_stream_next_points(&s, s_pull, 0), SUBD_ERR_PARAM);
        subd_stream_end(&s);
    }
    CHECK_EQ(subd_arena_mark(&a), 0);
}


/* ------------------------------------------------------------------------------------ */
/* Writers: .xyz and G-code read back                                                     */

static char s_text[12 * 1024];
static char s_text2[12 * 1024];

static int as_is_ws(char c) { return c == ' ' || c == '\t' || c == '\r'; }

/* A small G-code reader: the header G21, G90; then "G0 X Y Z" once and "G1 X Y Z [F f]"
 * lines; fills pts (pos) and returns how many, or UINT32_MAX on anything unexpected. *feed
 * receives the F value (0 when none) and *f_lines the number of lines with F. */
static uint32_t as_read_gcode(const char *t, uint32_t len, subd_point *pts, uint32_t cap, subd_real *feed,
                              uint32_t *f_lines)
{
    const char *p = t, *end = t + len;
    uint32_t n = 0, line = 0;
    *feed = 0;
    *f_lines = 0;
    while (p < end) {
        const char *e = p;
        uint32_t k, got = 0;
        while (e < end && *e != '\n') e++;
        if (e == end) return UINT32_MAX; /* every line ends with a newline */
        if (line == 0u && !(e - p == 3 && p[0] == 'G' && p[1] == '2' && p[2] == '1')) return UINT32_MAX;
        if (line == 1u && !(e - p == 3 && p[0] == 'G' && p[1] == '9' && p[2] == '0')) return UINT32_MAX;
        if (line >= 2u) {
            int g0 = e - p > 2 && p[0] == 'G' && p[1] == '0' && as_is_ws(p[2]);
            int g1 = e - p > 2 && p[0] == 'G' && p[1] == '1' && as_is_ws(p[2]);
            if ((n == 0u && !g0) || (n > 0u && !g1) || n >= cap) return UINT32_MAX;
            p += 2;
            while (p < e) {
                char w;
                subd_real v;
                while (p < e && as_is_ws(*p)) p++;
                if (p >= e) break;
                w = *p++;
                if (subd_real_parse(&p, e, &v) != SUBD_OK) return UINT32_MAX;
                if (w == 'X' || w == 'Y' || w == 'Z') {
                    k = w == 'X' ? 0u : w == 'Y' ? 1u : 2u;
                    if (got & (1u << k)) return UINT32_MAX;
                    got |= 1u << k;
                    pts[n].pos[k] = v;
                } else if (w == 'F') {
                    *feed = v;
                    ++*f_lines;
                } else
                    return UINT32_MAX;
            }
            if (got != 7u) return UINT32_MAX;
            n++;
        }
        p = e + 1;
        line++;
    }
    return n;
}

static uint32_t as_read_xyz(const char *t, uint32_t len, subd_point *pts, uint32_t cap)
{
    const char *p = t, *end = t + len;
    uint32_t n = 0, k;
    while (p < end) {
        if (n >= cap) return UINT32_MAX;
        for (k = 0; k < 3u; k++) {
            if (k && (p >= end || *p++ != ' ')) return UINT32_MAX;
            if (subd_real_parse(&p, end, &pts[n].pos[k]) != SUBD_OK) return UINT32_MAX;
        }
        if (p >= end || *p++ != '\n') return UINT32_MAX;
        n++;
    }
    return n;
}

static void astream_writers(void)
{
    subd_arena a;
    subd_alpha_opts o;
    subd_diag d;
    uint32_t n = 0, len = 0, len2, i, k, got, fl, fmt, ok;
    subd_real feed;
    as_rand_poly(6);
    as_opts(&o, 3, 5, SUBD_ALPHA_COS, 1, 6);
    subd_arena_init(&a, AS_WORK, AS_WORK_BYTES);
    if (!CHECK_EQ(as_push(&a, 6, 1, &o, SUBD_REAL_FRAC(1, 20), &n, &d), SUBD_OK)) return;
    if (!CHECK(n <= AS_MAXP && n <= AS_PULL)) return;
    for (fmt = SUBD_PATH_XYZ; fmt <= SUBD_PATH_GCODE; fmt++) {
        subd_real f_in = fmt == SUBD_PATH_GCODE ? SUBD_REAL_FRAC(1200, 1) : 0;
        /* sizing, then the whole path in one call */
        if (!CHECK_EQ(subd_path_write(s_pts, n, 0, fmt, f_in, 0, 0, &len), SUBD_OK)) return;
        if (!CHECK(len < sizeof s_text)) return;
        if (!CHECK_EQ(subd_path_write(s_pts, n, 0, fmt, f_in, s_text, sizeof s_text, &len2), SUBD_OK)) return;
        CHECK_EQ(len2, len);
        /* in pieces of 1 and 7 points: the same bytes */
        for (k = 1; k <= 7u; k += 6u) {
            uint32_t at = 0, fill = 0;
            while (at < n) {
                uint32_t m = n - at < k ? n - at : k, l;
                if (!CHECK_EQ(subd_path_write(s_pts + at, m, at, fmt, f_in, s_text2 + fill,
                                              (uint32_t)sizeof s_text2 - fill, &l), SUBD_OK))
                    return;
                fill += l;
                at += m;
            }
            CHECK_EQ(fill, len);
            for (ok = 1, i = 0; i < len && i < fill; i++) ok &= s_text[i] == s_text2[i];
            CHECK(ok);
        }
        /* read back: the same points, bit for bit */
        if (fmt == SUBD_PATH_GCODE) {
            got = as_read_gcode(s_text, len, s_pull, AS_PULL, &feed, &fl);
            CHECK_EQ(fl, 1);
            CHECK(h_same(feed, f_in));
        } else
            got = as_read_xyz(s_text, len, s_pull, AS_PULL);
        if (!CHECK_EQ(got, n)) return;
        for (ok = 1, i = 0; i < n; i++)
            for (k = 0; k < 3u; k++) ok &= h_same(s_pull[i].pos[k], s_pts[i].pos[k]);
        CHECK(ok);
        h_hash(fmt == SUBD_PATH_XYZ ? "alpha_stream_xyz" : "alpha_stream_gcode", h_fnv(2166136261u, s_text, len));
        /* too small: NOMEM, the size, nothing written */
        s_text2[0] = '#';
        CHECK_EQ(subd_path_write(s_pts, n, 0, fmt, f_in, s_text2, len - 1u, &len2), SUBD_ERR_NOMEM);
        CHECK_EQ(len2, len);
        CHECK(s_text2[0] == '#');
    }
    /* G-code without feed: no F */
    if (CHECK_EQ(subd_path_write(s_pts, n, 0, SUBD_PATH_GCODE, 0, s_text, sizeof s_text, &len), SUBD_OK)) {
        CHECK_EQ(as_read_gcode(s_text, len, s_pull, AS_PULL, &feed, &fl), n);
        CHECK_EQ(fl, 0);
    }
    CHECK_EQ(subd_path_write(s_pts, 0, 0, SUBD_PATH_GCODE, 0, s_text, sizeof s_text, &len), SUBD_OK);
    CHECK_EQ(len, 0);
    CHECK_EQ(subd_path_write(s_pts, n, 0, 3, 0, s_text, sizeof s_text, &len), SUBD_ERR_PARAM);
    CHECK_EQ(subd_path_write(0, n, 0, SUBD_PATH_XYZ, 0, s_text, sizeof s_text, &len), SUBD_ERR_PARAM);
    CHECK_EQ(subd_path_write(s_pts, n, 0, SUBD_PATH_XYZ, 0, s_text, sizeof s_text, 0), SUBD_ERR_PARAM);
    CHECK_EQ(subd_path_write(s_pts, n, 0, SUBD_PATH_GCODE, h_int(-1), s_text, sizeof s_text, &len), SUBD_ERR_PARAM);
}

const test_case suite_alpha_stream[] = {
    {"astream_uniform_levels", astream_uniform_levels},
    {"astream_uniform_params", astream_uniform_params},
    {"astream_batches", astream_batches},
    {"astream_adaptive_chord", astream_adaptive_chord},
    {"astream_adaptive_straight", astream_adaptive_straight},
    {"astream_circle", astream_circle},
    {"astream_plan_exact", astream_plan_exact},
    {"astream_errors", astream_errors},
    {"astream_writers", astream_writers},
    {0, 0},
};
