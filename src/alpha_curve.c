/* SPDX-License-Identifier: MIT */
/* alpha-subdivision curves S_k(f; n) (Zhang & Wang 2002, section 1, definitions 2 and 3).
 *
 * One level of S_k is S_2 of formula (2) followed by k - 2 averaging steps C (definition 3;
 * S_2k = B C S_2k-1, S_2k+1 = C S_2k). The shift B only renumbers: on a closed polygon it
 * rotates the start by one point per B, i.e. (k - 2) / 2 points per level (done by three
 * reversals); on an open polyline it is not applied (the ends fix the numbering).
 *
 * S_2 on an edge (a, b) with w = 1/(2 + 2 f_n) gives a + w (b - a) and b + w (a - b), i.e.
 * the weights (1+2f)/(2+2f), 1/(2+2f) of formula (2); the two points keep the edge's
 * midpoint. w comes from the kernel in Q32.32 (alpha_kernel.c).
 *
 * Open polylines (the paper treats bi-infinite sequences only): the sequence is continued
 * by the point reflection through each end point e, p[-j] = 2e - p[j]. S_2 and C map such
 * point-symmetric sequences to point-symmetric ones, so e stays fixed. Depending on the
 * last operator, e is either a vertex of the continued sequence ("vertex-centred", after
 * an odd number of C steps) or the midpoint of its end edge ("edge-centred": the input and
 * everything after S_2). Only the points from e inwards are stored, so each operator has
 * two open variants, written out below; reflected points enter only through the end
 * edge, as lerp(x1, e, 2w) (the far end of that edge is 2e - x1).
 *
 * Every operator runs in place in one buffer sized for the largest intermediate count:
 * the ones that grow the sequence go backwards, the others forwards (each loop's comment
 * says why no unread point is overwritten).
 */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "alpha_internal.h"
#include "layout.h"
#include "entry.h"
#include "real_avg.h"

typedef struct curve_ctx {
    const subd_alpha_opts *o;
    int64_t s_q32;
    uint32_t level;
    subd_alpha_kcache kc; /* the kernel value of the last edge's alpha */
    subd_alpha_wt w, w2;
    uint32_t ovf;
    int status;
} curve_ctx;

static uint32_t s2_count(uint32_t n, int closed, int vc)
{
    if (closed || vc) return 2u * n;
    return n >= 3u ? 2u * n - 2u : n;
}

static uint32_t c_count(uint32_t n, int closed, int vc)
{
    if (closed) return n;
    if (vc) return n + 1u;
    return n >= 3u ? n - 1u : n;
}

/* The largest and the final point count, or UINT32_MAX when they grow past 2^26. */
static void curve_counts(uint32_t m, int closed, const subd_alpha_opts *o, uint32_t *max, uint32_t *final)
{
    uint32_t n = m, mx = m, l, j;
    int vc = 0;
    if (m > (1u << 26)) { /* also with levels = 0 */
        *max = *final = UINT32_MAX;
        return;
    }
    for (l = 0; l < o->levels; l++) {
        n = s2_count(n, closed, vc);
        vc = 0;
        if (n > mx) mx = n;
        for (j = 2; j < o->order; j++) {
            n = c_count(n, closed, vc);
            vc = !vc;
            if (n > mx) mx = n;
        }
        if (mx > (1u << 26)) {
            *max = *final = UINT32_MAX;
            return;
        }
    }
    *max = mx;
    *final = n;
}

/* The one layout (layout.h): the points, and the tags when the caller gives them; both sized
 * for the largest intermediate count. With a == NULL it only counts (p, t may be NULL). */
static int curve_layout(subd_arena *a, uint32_t mx, const subd_alpha_opts *o, subd_real **p, int32_t **t,
                        uint32_t *bytes)
{
    subd_layout l;
    subd_real *pp;
    int32_t *tt = 0;
    subd_layout_begin(&l, a);
    pp = subd_layout_take(&l, mx, 3u * (uint32_t)sizeof(subd_real));
    if (o->tag_num) tt = subd_layout_take(&l, mx, 4u);
    if (p) *p = pp;
    if (t) *t = tt;
    return subd_layout_end(&l, bytes);
}

static int curve_bytes(uint32_t m, int closed, const subd_alpha_opts *o, uint32_t *bytes, uint32_t *out_points)
{
    uint32_t mx, fin, total;
    curve_counts(m, closed, o, &mx, &fin);
    if (mx == UINT32_MAX) return SUBD_ERR_TOO_BIG;
    if (curve_layout(0, mx, o, 0, 0, &total) != SUBD_OK) return SUBD_ERR_TOO_BIG;
    *bytes = total;
    if (out_points) *out_points = fin;
    return SUBD_OK;
}

static int check_m(uint32_t m, int closed)
{
    return (m < (closed ? 3u : 2u)) ? SUBD_ERR_EMPTY : SUBD_OK;
}

int subd_alpha_curve_plan(uint32_t m, int closed, const subd_alpha_opts *o, uint32_t *bytes, uint32_t *out_points)
{
    int64_t s;
    int st;
    if (!bytes) return SUBD_ERR_PARAM;
    if ((st = subd_alpha_check_opts(o, SUBD_ALPHA_MAX_ORDER, &s)) != SUBD_OK) return st;
    if ((st = check_m(m, closed)) != SUBD_OK) return st;
    return curve_bytes(m, closed, o, bytes, out_points);
}

/* Sets ctx->w and w2 = 2w for an edge whose ends carry tags ta, tb (or the uniform alpha).
 * The edge's alpha is (ta + tb) / (2 den), exact. Returns 0 on failure (ctx->status set). */
static int edge_weight(curve_ctx *c, const int32_t *tag, uint32_t ia, uint32_t ib)
{
    int64_t num2 = tag ? (int64_t)tag[ia] + tag[ib] : 2 * (int64_t)c->o->alpha_num, f;
    int st, fresh;
    st = subd_alpha_kcache_get(&c->kc, c->o, num2, 2 * c->o->alpha_den, c->level, c->s_q32, &f, &fresh);
    if (st != SUBD_OK) {
        c->status = st;
        return 0;
    }
    if (!fresh) return 1;
    subd_alpha_edge_w(f, &c->w, &c->w2, &c->ovf);
    return 1;
}


static void copy3(subd_real *out, const subd_real *a)
{
    out[0] = a[0];
    out[1] = a[1];
    out[2] = a[2];
}

static int32_t tag_mean(int32_t a, int32_t b) { return subd_alpha_tag_mean((int64_t)a + b, 2u); }

/* S_2's two points on the edge (ia, ib), into points o and o + 1 (ia's side first) with the
 * tags of ia and ib; both ends are read before anything is written, so o may be ia. */
static int s2_edge(curve_ctx *c, subd_real *p, int32_t *t, uint32_t ia, uint32_t ib, uint32_t o)
{
    subd_real a[3], b[3];
    int32_t ta = 0, tb = 0;
    if (!edge_weight(c, t, ia, ib)) return 0;
    copy3(a, p + 3u * ia);
    copy3(b, p + 3u * ib);
    if (t) {
        ta = t[ia];
        tb = t[ib];
    }
    subd_alpha_lerp3(p + 3u * o, a, b, c->w, &c->ovf);
    subd_alpha_lerp3(p + 3u * (o + 1u), b, a, c->w, &c->ovf);
    if (t) {
        t[o] = ta;
        t[o + 1u] = tb;
    }
    return 1;
}

/* S_2 on a closed polygon of n points, in place, backwards: edge i writes 2i and 2i+1 and
 * later edges read only i' <= i < 2i (i >= 1); the wrap edge (n-1, 0) is done first. */
static int s2_closed(curve_ctx *c, subd_real *p, int32_t *t, uint32_t n)
{
    uint32_t i = n - 1u, j;
    for (j = 0; j < n; j++, i = n - 1u - j)
        if (!s2_edge(c, p, t, i, (i + 1u == n) ? 0u : i + 1u, 2u * i)) return 0;
    return 1;
}

/* S_2 on an open, edge-centred polyline of L >= 3 points [c, x1 .. x(L-2), d] ->
 * [c, w1 .. w(2L-4), d]. Backwards; d is saved before slot 2L-3 (> L-1) is written. */
static int s2_open_edge(curve_ctx *c, subd_real *p, int32_t *t, uint32_t L)
{
    subd_real d[3], a[3], b[3];
    int32_t td = t ? t[L - 1u] : 0;
    uint32_t j;
    copy3(d, p + 3u * (L - 1u));
    copy3(p + 3u * (2u * L - 3u), d);
    if (t) t[2u * L - 3u] = td;
    /* end edge (x(L-2), 2d - x(L-2)): its first point, tag of x(L-2) on both ends */
    if (!edge_weight(c, t, L - 2u, L - 2u)) return 0;
    copy3(a, p + 3u * (L - 2u));
    subd_alpha_lerp3(p + 3u * (2u * L - 4u), a, d, c->w2, &c->ovf);
    if (t) t[2u * L - 4u] = t[L - 2u];
    for (j = L - 3u; j >= 1u; j--)
        if (!s2_edge(c, p, t, j, j + 1u, 2u * j)) return 0;
    /* start edge (2c - x1, x1): its second point */
    if (!edge_weight(c, t, 1u, 1u)) return 0;
    copy3(a, p + 3u);
    copy3(b, p);
    subd_alpha_lerp3(p + 3u, a, b, c->w2, &c->ovf);
    return 1; /* t[1] keeps x1's tag, which is the tag w1 inherits */
}

/* S_2 on an open, vertex-centred polyline of L >= 2 points [c, x1 .. d] ->
 * [c, two points per stored edge, d] (2L points). Backwards: edge j writes 2j+1, 2j+2 and
 * later edges read only j' + 1 <= j < 2j + 1. */
static int s2_open_vertex(curve_ctx *c, subd_real *p, int32_t *t, uint32_t L)
{
    subd_real a[3];
    uint32_t j;
    copy3(a, p + 3u * (L - 1u));
    copy3(p + 3u * (2u * L - 1u), a);
    if (t) t[2u * L - 1u] = t[L - 1u];
    for (j = L - 1u; j-- > 0;)
        if (!s2_edge(c, p, t, j, j + 1u, 2u * j + 1u)) return 0;
    return 1;
}

/* C on a closed polygon: forwards, p[0] saved for the wrap. */
static void c_closed(subd_real *p, int32_t *t, uint32_t n, uint32_t *ovf)
{
    subd_real first[3];
    int32_t t0 = t ? t[0] : 0;
    uint32_t i;
    copy3(first, p);
    for (i = 0; i + 1u < n; i++) {
        subd_alpha_mid3(p + 3u * i, p + 3u * i, p + 3u * (i + 1u), ovf);
        if (t) t[i] = tag_mean(t[i], t[i + 1u]);
    }
    subd_alpha_mid3(p + 3u * (n - 1u), p + 3u * (n - 1u), first, ovf);
    if (t) t[n - 1u] = tag_mean(t[n - 1u], t0);
}

/* C on an open edge-centred polyline, L >= 3: [c, x1 .. x(L-2), d] -> [c, mid(x1, x2) ..
 * mid(x(L-3), x(L-2)), d] (L - 1 points, now vertex-centred). Forwards. */
static void c_open_edge(subd_real *p, int32_t *t, uint32_t L, uint32_t *ovf)
{
    subd_real d[3];
    int32_t td = t ? t[L - 2u] : 0;
    uint32_t j;
    copy3(d, p + 3u * (L - 1u));
    if (t) t[0] = t[1];
    for (j = 1; j + 2u < L; j++) {
        subd_alpha_mid3(p + 3u * j, p + 3u * j, p + 3u * (j + 1u), ovf);
        if (t) t[j] = tag_mean(t[j], t[j + 1u]);
    }
    copy3(p + 3u * (L - 2u), d);
    if (t) t[L - 2u] = td;
}

/* C on an open vertex-centred polyline, L >= 2: [c, x1 .. d] -> [c, mid(c, x1) .. mid(x(L-2),
 * d), d] (L + 1 points, now edge-centred). Backwards. */
static void c_open_vertex(subd_real *p, int32_t *t, uint32_t L, uint32_t *ovf)
{
    uint32_t j;
    copy3(p + 3u * L, p + 3u * (L - 1u));
    if (t) t[L] = t[L - 1u];
    for (j = L - 1u; j >= 1u; j--) {
        subd_alpha_mid3(p + 3u * j, p + 3u * (j - 1u), p + 3u * j, ovf);
        if (t) t[j] = tag_mean(t[j - 1u], t[j]);
    }
}

static void reverse(subd_real *p, int32_t *t, uint32_t lo, uint32_t hi)
{
    while (lo + 1u < hi) {
        subd_real tmp[3];
        hi--;
        copy3(tmp, p + 3u * lo);
        copy3(p + 3u * lo, p + 3u * hi);
        copy3(p + 3u * hi, tmp);
        if (t) {
            int32_t x = t[lo];
            t[lo] = t[hi];
            t[hi] = x;
        }
        lo++;
    }
}

/* B^r on a closed polygon: p'[i] = p[i + r]. */
static void shift_closed(subd_real *p, int32_t *t, uint32_t n, uint32_t r)
{
    r %= n;
    if (r == 0) return;
    reverse(p, t, 0, r);
    reverse(p, t, r, n);
    reverse(p, t, 0, n);
}

int subd_alpha_curve(subd_arena *arena, const subd_real *pos, uint32_t m, int closed,
                     const subd_alpha_opts *o, subd_alpha_curve_out *out, subd_diag *diag)
{
    subd_entry e;
    subd_diag *d = subd_entry_begin(&e, arena, diag);
    curve_ctx c;
    uint32_t bytes, mx, fin, n, i, l, j;
    subd_real *p;
    int32_t *t = 0;
    int vc = 0, st;

    if (!arena || !pos || !out) return subd_entry_fail(&e, SUBD_ERR_PARAM);
    if ((st = subd_alpha_check_opts(o, SUBD_ALPHA_MAX_ORDER, &c.s_q32)) != SUBD_OK) return subd_entry_fail(&e, st);
    if ((st = check_m(m, closed)) != SUBD_OK) return subd_entry_fail(&e, st);
    /* the size check first: it bounds m (< 2^26), so 3 m below cannot wrap */
    if ((st = curve_bytes(m, closed, o, &bytes, &fin)) != SUBD_OK) return subd_entry_fail(&e, st);
    for (i = 0; i < 3u * m; i++)
        if (!subd_real_is_finite(pos[i])) {
            d->vertex = i / 3u;
            return subd_entry_fail(&e, SUBD_ERR_NAN);
        }
    curve_counts(m, closed, o, &mx, &fin);
    if (bytes > subd_arena_free_bytes(arena)) {
        d->bytes_needed = bytes;
        return subd_entry_fail(&e, SUBD_ERR_NOMEM);
    }
    if ((st = curve_layout(arena, mx, o, &p, &t, &bytes)) != SUBD_OK) return subd_entry_fail(&e, st);
    for (i = 0; i < 3u * m; i++) p[i] = pos[i];
    if (t) {
        for (i = 0; i < m; i++) {
            if (o->tag_num[i] > SUBD_ALPHA_MAX_NUM || o->tag_num[i] < -SUBD_ALPHA_MAX_NUM) {
                d->vertex = i;
                return subd_entry_fail(&e, SUBD_ERR_PARAM);
            }
            t[i] = o->tag_num[i];
        }
    }
    c.o = o;
    c.ovf = 0;
    c.status = SUBD_OK;
    n = m;
    for (l = 0; l < o->levels && c.status == SUBD_OK; l++) {
        int ok;
        c.level = l;
        subd_alpha_kcache_reset(&c.kc);
        if (closed) ok = s2_closed(&c, p, t, n);
        else if (vc) ok = s2_open_vertex(&c, p, t, n);
        else ok = (n >= 3u) ? s2_open_edge(&c, p, t, n) : 1;
        if (!ok) break;
        n = s2_count(n, closed, vc);
        vc = 0;
        for (j = 2; j < o->order; j++) {
            if (closed) c_closed(p, t, n, &c.ovf);
            else if (vc) c_open_vertex(p, t, n, &c.ovf);
            else if (n >= 3u) c_open_edge(p, t, n, &c.ovf);
            n = c_count(n, closed, vc);
            vc = !vc;
        }
        if (closed) shift_closed(p, t, n, (o->order - 2u) / 2u);
    }
    if (c.status == SUBD_OK && c.ovf) c.status = SUBD_ERR_RANGE;
    if (c.status != SUBD_OK) return subd_entry_fail(&e, c.status);
    if (t) subd_arena_rewind(arena, e.mark + (uint32_t)((uint8_t *)t - (uint8_t *)p)); /* the tags were scratch */
    out->num_points = n;
    out->pos = p;
    out->continuity = subd_alpha_continuity(c.s_q32, (int32_t)o->order - 1);
    return subd_entry_ok(&e);
}
