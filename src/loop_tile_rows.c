/* SPDX-License-Identifier: MIT */
/* Regular tiles of streaming Loop (loop_tile.h): the row walker, which makes the points of a
 * region of the next level from a tile's grid, each by loop_rules.h's rules with subd_loop's
 * bits (paper: loop-progressive-interpolation.txt, section 1, Loop's smooth rules; the grid,
 * its ring starts, rotations and lower sides and the bit-identity argument are
 * loop_tile.c's header). Kept apart from loop_tile.c, which lays a tile out, reads its level
 * 0 from the patch, carries the order of the sums and walks the pieces.
 * Choices: along a row of the grid's lattice the kinds of point alternate (vertex rule and
 * edge 0 in even rows, edges 2 and 1 in odd ones), so one loop per row takes two points per
 * turn, and a tile's fixed frames (its refinement's, its four plain quarters') are constants
 * in their walkers (forced inline), their bounds and index steps folded: the rows of a tile
 * are most of its instructions (M4F profile of the level-6 demo sphere: 0.9 points per
 * triangle). In Q16.16 the sums are exact, so a rule takes no ring start or lower side and
 * sums in 32 bits (loop_tile.c's lt_move bounds the coordinates). */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "loop_tile.h"

/* One even point: the smooth vertex rule of valence 6 around c from ring start o (six
 * offsets in subd_reals, lt_ring_offsets), the products in subd_loop's order. */
TOPO_INLINE void lt_vpt(const subd_real *c, const int32_t *o, subd_real *out, loop_weights w)
{
#if SUBD_FIXED
    /* valence 6: b = 1/16 and 1 - 6b = 5/8 exactly (loop_rules.h), so the exact sum is
     * 2^12 (10 v + p_0 + ... + p_5) and subd_acc_real's rounding, (sum + 2^15) >> 16, is
     * (10 v + p_0 + ... + p_5 + 8) >> 4: the same bits in 32-bit sums (loop_tile.c's lt_move bounds them
     * by 2^31 - 16); the result lies between the least and the largest input */
    uint32_t j;
    (void)w;
    for (j = 0; j < 3u; j++) {
        int32_t y = 8 * c[j] + 2 * c[j] + c[o[0] + (int32_t)j] + c[o[1] + (int32_t)j] + c[o[2] + (int32_t)j] +
                    c[o[3] + (int32_t)j] + c[o[4] + (int32_t)j] + c[o[5] + (int32_t)j];
        out[j] = (y + 8) >> 4;
    }
#else
    subd_acc acc[3];
    uint32_t dead = 0; /* a tile's rules cannot overflow (loop_tile.c's LT_HUGE): unread */
    loop_smooth_begin(acc, w, c);
    loop_smooth_add(acc, w, c + o[0]);
    loop_smooth_add(acc, w, c + o[1]);
    loop_smooth_add(acc, w, c + o[2]);
    loop_smooth_add(acc, w, c + o[3]);
    loop_smooth_add(acc, w, c + o[4]);
    loop_smooth_add(acc, w, c + o[5]);
    loop_smooth_end(out, acc, &dead);
    (void)dead;
#endif
}

/* One odd point: the interior edge rule on edge d of U (c: its corner (i, j)), d a constant
 * (the index rules below), row R the length of U's row: a -> b the edge, v the opposite
 * corner in U, e the one in the down triangle across. When the other side is lower, the
 * reference swaps a with b and v with e: only the second matters, since (0 + x) + y and
 * (0 + y) + x are the same float for every x, y (addition commutes, and 0 + x differs from x
 * only for x = -0, where both give +0 + y, or +0 when y = -0 too) and Q16.16 sums are
 * exact. */
TOPO_INLINE void lt_ept(const subd_real *c, uint32_t low, uint32_t d, int32_t R, subd_real *o)
{
    int32_t oa, ob, oc, oe;
    const subd_real *a, *b, *v, *e;
    uint32_t dead = 0;
    if (d == 0u) {
        oa = 0; ob = 3; oc = 3 * R; oe = -3 * R;
    } else if (d == 1u) {
        oa = 3; ob = 3 * R; oc = 0; oe = 3 * (R + 1);
    } else {
        oa = 3 * R; ob = 0; oc = 3; oe = 3 * (R - 1);
    }
    a = c + oa;
    b = c + ob;
#if LT_ORDERED
    if ((low >> d) & 1u) {
        v = c + oc;
        e = c + oe;
    } else {
        v = c + oe;
        e = c + oc;
    }
    o[0] = loop_rule_edge1(a[0], b[0], v[0], e[0], &dead);
    o[1] = loop_rule_edge1(a[1], b[1], v[1], e[1], &dead);
    o[2] = loop_rule_edge1(a[2], b[2], v[2], e[2], &dead);
    (void)dead;
#else
    /* the exact sum 3/8 (a + b) + 1/8 (v + e) is 2^13 (3 (a + b) + v + e), rounded as
     * subd_acc_real does, (sum + 2^15) >> 16 = (3 (a + b) + v + e + 4) >> 3: 32-bit sums
     * (loop_tile.c's lt_move), the same bits */
    (void)low;
    (void)dead;
    v = c + oc;
    e = c + oe;
    o[0] = (3 * (a[0] + b[0]) + v[0] + e[0] + 4) >> 3;
    o[1] = (3 * (a[1] + b[1]) + v[1] + e[1] + 4) >> 3;
    o[2] = (3 * (a[2] + b[2]) + v[2] + e[2] + 4) >> 3;
#endif
}

/* One row of level t + 1 points: (px, py) for px = pa..pb (pa <= pb) of natural row py
 * (`odd`: py odd), whose parents lie in row uj = py / 2 of grid g (length R, U(l) the parent
 * of px = pa, l = that row's start + pa / 2); point px goes to out + k, k stepping by sk
 * and sk by -dd per point (the destination frame's quadratic index, lt_rows). Along a row
 * the kinds alternate (lt_classify): even py: px even the vertex rule at (ui, uj) = U(l),
 * px odd the midpoint of U(l)'s edge 0; odd py: px even edge 2 of U(l), px odd edge 1 of
 * U(l); l steps after each odd px. Index rules from U(ui, uj)'s l: vertex (i, j) + (1, 0) is
 * +1, + (0, 1) is +R, + (-1, 1) is +R - 1, + (0, -1) is -(R + 1), + (1, -1) is -R. One
 * loop per row takes two points per turn (forced inline, TOPO_INLINE: each parity its own
 * loop, its offsets folded). */
TOPO_INLINE void lt_row(const lt_grid *g, int32_t R, int odd, int32_t pa, int32_t pb, uint32_t l, int32_t k,
                        int32_t sk, int32_t dd, subd_real *out, loop_weights w)
{
    const subd_real *P = g->pos;
    const uint8_t *lw = g->low;
    int32_t px = pa;
#if LT_ORDERED
#define LT_LOW(l) ((uint32_t)lw[l])
#else
#define LT_LOW(l) 0u
    (void)lw;
#endif
#define LT_STEP() (k += sk, sk -= dd)
    if (!odd) {
        int32_t o3[12];
        const uint8_t *dir = g->dir;
        lt_ring_offsets(R, o3);
#if LT_ORDERED
#define LT_DIR(l) ((uint32_t)dir[l])
#else
#define LT_DIR(l) 0u
        (void)dir;
#endif
        if (px & 1) {
            lt_ept(P + 3u * l, LT_LOW(l), 0u, R, out + k);
            LT_STEP();
            l++;
            px++;
        }
        for (; px < pb; px += 2, l++) {
            lt_vpt(P + 3u * l, o3 + LT_DIR(l), out + k, w);
            LT_STEP();
            lt_ept(P + 3u * l, LT_LOW(l), 0u, R, out + k);
            LT_STEP();
        }
        if (px == pb) lt_vpt(P + 3u * l, o3 + LT_DIR(l), out + k, w);
#undef LT_DIR
    } else {
        if (px & 1) {
            lt_ept(P + 3u * l, LT_LOW(l), 1u, R, out + k);
            LT_STEP();
            l++;
            px++;
        }
        for (; px < pb; px += 2, l++) {
            lt_ept(P + 3u * l, LT_LOW(l), 2u, R, out + k);
            LT_STEP();
            lt_ept(P + 3u * l, LT_LOW(l), 1u, R, out + k);
            LT_STEP();
        }
        if (px == pb) lt_ept(P + 3u * l, LT_LOW(l), 2u, R, out + k);
    }
#undef LT_STEP
#undef LT_LOW
}

/* The points of region fr from grid g (side s) by rows of g's lattice (lt_row: the kinds
 * alternate along a row, and the parent row's offsets are the row's); the destination index
 * follows the frame: point (x, y) of the region goes to lt_vi(S, x, y), which a unit step
 * (u, -q) along the row changes by sk = u - q (2S + 3 + q) / 2 + q y (lt_vi's row step),
 * itself falling by q^2 per step. Each point gets subd_loop's value. Forced inline, so that
 * the fixed frames of a tile (its refinement, its plain quarters) are constants in their
 * callers (lt_rows_at). */
TOPO_INLINE void lt_rows_in(const lt_grid *g, uint32_t s, const lt_frame *fr, subd_real *out, loop_weights w)
{
    int32_t S = fr->hi - 2 * fr->lo, cx[3], cy[3], ymin, ymax, py, k, e = fr->hi - fr->lo;
    int32_t dd = fr->q * fr->q * fr->ds, sk0 = fr->u - fr->q * (2 * S + 3 + fr->q) / 2;
    cx[0] = fr->ox + fr->lo * (fr->p + fr->r);
    cy[0] = fr->oy + fr->lo * (fr->q + fr->u);
    cx[1] = fr->ox + e * fr->p + fr->lo * fr->r;
    cy[1] = fr->oy + e * fr->q + fr->lo * fr->u;
    cx[2] = fr->ox + fr->lo * fr->p + e * fr->r;
    cy[2] = fr->oy + fr->lo * fr->q + e * fr->u;
    ymin = ymax = cy[0];
    for (k = 1; k < 3; k++) {
        if (cy[k] < ymin) ymin = cy[k];
        if (cy[k] > ymax) ymax = cy[k];
    }
    for (py = ymin; py <= ymax; py++) {
        /* x = u dpx - r dpy, y = -q dpx + p dpy (the inverse frame), dpx = px - ox */
        int32_t dpy = py - fr->oy, a = -0x40000000, b = 0x40000000, pa, pb, dpx, x, y;
        uint32_t uj = (uint32_t)py >> 1, row = s + 1u - uj, rb = lt_vi(s, 0u, uj);
        lt_bound(fr->u, -fr->r * dpy - fr->lo, &a, &b);
        lt_bound(-fr->q, fr->p * dpy - fr->lo, &a, &b);
        lt_bound(fr->q - fr->u, fr->hi - (fr->p - fr->r) * dpy, &a, &b);
        pa = a + fr->ox;
        pb = b + fr->ox;
        if (fr->skip)
            for (k = 0; k < 3; k++)
                if (cy[k] == py) {
                    if (cx[k] == pa) pa++;
                    else if (cx[k] == pb) pb--;
                }
        if (pa > pb) continue;
        dpx = pa - fr->ox;
        x = fr->u * dpx - fr->r * dpy - fr->lo;
        y = -fr->q * dpx + fr->p * dpy - fr->lo;
        k = (int32_t)((uint32_t)(y * (2 * S + 3 - y)) / 2u) + x; /* y in 0..S: the product is even, >= 0 */
        if (py & 1)
            lt_row(g, (int32_t)row, 1, pa, pb, rb + ((uint32_t)pa >> 1), k * fr->ds, (sk0 + fr->q * y) * fr->ds, dd, out, w);
        else
            lt_row(g, (int32_t)row, 0, pa, pb, rb + ((uint32_t)pa >> 1), k * fr->ds, (sk0 + fr->q * y) * fr->ds, dd, out, w);
    }
}

/* The general walker (limit mode's quarters with margin, any frame). */
void subd_lt_rows(const lt_grid *g, uint32_t s, const lt_frame *fr, subd_real *out, loop_weights w)
{
    lt_rows_in(g, s, fr, out, w);
}

/* The walker with a tile's fixed frames as constants (their bounds, steps and index rules
 * folded): a level's refinement (the identity frame of the whole grid less its corners,
 * lt_refine) and plain mode's quarter c (lt_cfr[c]'s edges, corner 0 at (ox, oy), side hi,
 * into the records: subd_lt_quarter). */
void subd_lt_rows_refine(const lt_grid *g, uint32_t s, int32_t hi, subd_real *out, loop_weights w)
{
    const lt_frame fr = {1, 1, 1, 0, 0, 1, 0, hi, 3, 1};
    lt_rows_in(g, s, &fr, out, w);
}

#define LT_RDS ((int32_t)(sizeof(lt_rec) / sizeof(subd_real)))
void subd_lt_rows_quarter(const lt_grid *g, uint32_t s, uint32_t c, int32_t ox, int32_t oy, int32_t hi, subd_real *out,
                          loop_weights w)
{
    if (c == 0u) {
        const lt_frame fr = {ox, oy, 1, 0, 0, 1, 0, hi, LT_RDS, 0};
        lt_rows_in(g, s, &fr, out, w);
    } else if (c == 1u) {
        const lt_frame fr = {ox, oy, -1, 1, -1, 0, 0, hi, LT_RDS, 0};
        lt_rows_in(g, s, &fr, out, w);
    } else if (c == 2u) {
        const lt_frame fr = {ox, oy, 0, -1, 1, -1, 0, hi, LT_RDS, 0};
        lt_rows_in(g, s, &fr, out, w);
    } else {
        const lt_frame fr = {ox, oy, 0, 1, -1, 1, 0, hi, LT_RDS, 0};
        lt_rows_in(g, s, &fr, out, w);
    }
}
#undef LT_RDS
