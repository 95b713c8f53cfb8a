/* SPDX-License-Identifier: MIT */
/* Regular tiles of streaming Loop (loop_tile.h): the global ids of a tile piece's vertices,
 * the closed form of subd_lp_vertex_id (loop_patch.c: a vertex inside control face f at
 * lattice point (a, b) of level lv has id num_verts + num_corners (2^lv - 1) +
 * f (2^lv - 1)(2^lv - 2) / 2 + r(a) + b - 1) stepped along the piece's rows, so an id costs
 * two additions instead of the general function's case analysis; a point on a control edge
 * or vertex (outside the open face) still takes subd_lp_vertex_id. Paper: none (the ids
 * are the library's: include/subd_loop.h, "Global vertex ids, closed form"). Kept apart
 * from loop_tile.c, which refines the tile's positions: the ids read only the piece's
 * frame and the control face's corners. */
#include "fp_contract.h" /* first, as in every source file (test/scripts/contract_proofs.sh) */
#include "loop_tile.h"
#include "loop_patch.h"

/* (a, b) inside control face lattice of side n1 (subd_lp_vertex_id's closed form). */
static int lt_inner(int32_t a, int32_t b, int32_t n1) { return a >= 1 && b >= 1 && a + b <= n1 - 1; }

void subd_lt_ids(const lt_tile *tl, const subd_mesh *in, uint32_t f, uint32_t lv, const uint32_t ca[3],
                 const uint32_t cb[3], const int32_t org[2], const int32_t e1[2], const int32_t e2[2])
{
    uint32_t m = 1u << (tl->depth - tl->split), n1 = (uint32_t)1 << lv, nm1 = n1 - 1u;
    int32_t n = (int32_t)1 << tl->depth, a0, b0, ea, eb, fa, fb, da, db, dd, ra, rb, ia, ib, y, in1 = (int32_t)n1;
    uint64_t base = (uint64_t)in->num_verts + (uint64_t)in->num_corners * nm1 +
                    (uint64_t)f * ((uint64_t)nm1 * (nm1 - 1u) / 2u);
    lt_rec *q = tl->q;
    uint32_t *qh = tl->qhi; /* the high words, index for index with q */
    a0 = (int32_t)ca[0];
    b0 = (int32_t)cb[0];
    ea = ((int32_t)ca[1] - a0) / n; /* the face's edges 0 -> 1 and 0 -> 2 per last-level step */
    eb = ((int32_t)cb[1] - b0) / n;
    fa = ((int32_t)ca[2] - a0) / n;
    fb = ((int32_t)cb[2] - b0) / n;
    da = e1[0] * ea + e1[1] * fa; /* a row's step in (a, b): each -1, 0 or 1 */
    db = e1[0] * eb + e1[1] * fb;
    dd = da * da;
    ra = e2[0] * ea + e2[1] * fa; /* the next row's */
    rb = e2[0] * eb + e2[1] * fb;
    ia = a0 + org[0] * ea + org[1] * fa;
    ib = b0 + org[0] * eb + org[1] * fb;
    if (lt_inner(ia, ib, in1) && lt_inner(ia + (int32_t)m * da, ib + (int32_t)m * db, in1) &&
        lt_inner(ia + (int32_t)m * ra, ib + (int32_t)m * rb, in1)) {
        /* the whole piece inside the control face's interior (its three corners are, and
         * the interior is convex): every row is one run (below), its start stepped from the
         * row before's as the run steps along a row: a row step moves a by ra, so the
         * start's r(a) + b changes by tr = ra (nm1 - a) - (ra < 0) + rb, which falls by ra^2
         * per row, and the run's first dl by da ra */
        uint32_t am = (uint32_t)(ia - 1), t0 = am * nm1 - am * (am + 1u) / 2u + (uint32_t)(ib - 1);
        uint32_t dl0 = (uint32_t)(da * (int32_t)(nm1 - 1u - am) - (da < 0 ? 1 : 0) + db);
        uint32_t tr = (uint32_t)(ra * (int32_t)(nm1 - 1u - am) - (ra < 0 ? 1 : 0) + rb);
        for (y = 0; y <= (int32_t)m; y++) {
            uint32_t t = t0, dl = dl0;
            lt_rec *qe = q + ((int32_t)m - y) + 1;
            for (; q != qe; q++, qh++) {
                uint64_t id = base + t;
                q->id = (uint32_t)id;
                *qh = (uint32_t)(id >> 32);
                t += dl;
                dl -= (uint32_t)dd;
            }
            t0 += tr;
            tr -= (uint32_t)(ra * ra);
            dl0 -= (uint32_t)(da * ra);
        }
        return;
    }
    /* per row: (a, b) = (ia + x da, ib + x db) for x = 0..m - y. The control face's
     * interior (subd_lp_vertex_id's closed form: a >= 1, b >= 1, a + b <= n1 - 1) is one
     * range of x, found once per row (lt_bound); there the closed form
     * id = base + r(a) + b - 1, r(a) = (a - 1) nm1 - (a - 1) a / 2 (below nm1^2 / 2 < 2^31),
     * is stepped along the row: a step changes r(a) + b by dl = r(a + da) - r(a) + db =
     * da (nm1 - a) - (da < 0) + db, and dl itself by -da^2 per step; the points before and
     * after the range take subd_lp_vertex_id */
    for (y = 0; y <= (int32_t)m; y++, ia += ra, ib += rb) {
        int32_t xe = (int32_t)m - y, lo = 0, hi = xe, x;
        lt_bound(da, ia - 1, &lo, &hi);
        lt_bound(db, ib - 1, &lo, &hi);
        lt_bound(-da - db, in1 - 1 - ia - ib, &lo, &hi);
        if (lo > hi) lo = xe + 1; /* no interior point: every point by subd_lp_vertex_id */
        for (x = 0; x <= xe; x++, q++, qh++) {
            uint64_t id;
            if (x == lo) { /* the interior run */
                uint32_t am = (uint32_t)(ia + x * da - 1);
                uint32_t t = am * nm1 - am * (am + 1u) / 2u + (uint32_t)(ib + x * db - 1);
                uint32_t dl = (uint32_t)(da * (int32_t)(nm1 - 1u - am) - (da < 0 ? 1 : 0) + db);
                lt_rec *qe = q + (hi - x) + 1;
                for (; q != qe; q++, qh++) {
                    id = base + t;
                    q->id = (uint32_t)id;
                    *qh = (uint32_t)(id >> 32);
                    t += dl;
                    dl -= (uint32_t)dd;
                }
                x = hi + 1;
                if (x > xe) break;
            }
            id = subd_lp_vertex_id(in, f, (uint32_t)(ia + x * da), (uint32_t)(ib + x * db), lv);
            q->id = (uint32_t)id;
            *qh = (uint32_t)(id >> 32);
        }
    }
}
