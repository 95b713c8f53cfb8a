/* SPDX-License-Identifier: MIT */
/* Regular tiles of streaming Loop (loop_tile.h): the last levels of a regular patch refined
 * breadth first on a triangular grid, each vertex computed once, by loop_rules.h's rules, bit
 * for bit as subd_loop computes them. Paper: loop-progressive-interpolation.txt, section 1
 * (Loop's smooth rules; a regular patch has no boundary, crease or corner). Windowed
 * refinement of a regular region is the classic scheme of Pulli and Segal (1996).
 *
 * Grid. Level t of a tile is the 1-ring of the tile's face refined t times: a triangle of
 * side 2^t + 3 in lattice coordinates whose three corner vertices are missing (they lie
 * outside the 1-ring); the face itself is the side-2^t triangle at (1, 1). Level t + 1
 * point (I, J) lies at (I + 1, J + 1) / 2 in level t coordinates: both even, an old vertex
 * (the vertex rule); otherwise the midpoint of an edge (the edge rule). Every point of level
 * t + 1's grid has its stencil in level t's grid (the 1-rings nest, as loop_stream.c's header
 * argues for the patches), so a level is one pass with index arithmetic, no topology.
 *
 * Bit-identity. A float rule gives subd_loop's bits only if it adds the same products in the
 * same order, so the grid carries, per level, what fixes the order in subd_loop:
 *   - the ring start of each vertex (dir: the lattice direction of its vert_out; rings run
 *     counter-clockwise, lattice directions 0..5 are counter-clockwise too). Refinement keeps
 *     an old vertex's direction (child vert_out = first child half-edge of its vert_out); a
 *     new vertex starts (topo_loop_new_vout) towards the midpoint of c - a when the lower
 *     half-edge a -> b is corner 0 or 1 of its face (c the third corner), i.e. in direction
 *     c - b, and towards b when it is corner 2, i.e. in direction b - a;
 *   - which side of each edge holds its lower half-edge (low), since the edge rule adds the
 *     lower face's opposite vertex before the other's: child half-edges along a parent edge
 *     keep its lower side (children of face f are numbered 4f..4f+3), and an inner edge is
 *     lower in the corner child than in the middle one;
 *   - each face's rotation (which lattice corner is its corner 0; rot), for the corner index
 *     above: a corner child's corner 0 is the parent's corner it holds, so the child at
 *     lattice corner k has rotation k; the middle child (m0, m1, m2) of an up triangle of
 *     rotation r has rotation r, of a down triangle r + 1.
 * Level 0 takes all three from the patch (its vert_out, its faces' corner order, its sorted
 * half-edge numbering, which compares as subd_loop's does: loop_stream.c's header).
 * Q16.16 sums are exact (64-bit sums of products), so there any order gives subd_loop's bits:
 * a Q16.16 tile ignores ring starts and lower sides (LT_ORDERED), and a plain one carries
 * none (only limit mode's ring starts need them there).
 *
 * Regular: the patch has exactly 13 faces and 12 vertices, its three corners are interior,
 * of valence 6, untagged, with no sharp edge, and it embeds in the lattice consistently
 * (every neighbour at one lattice point, every face a lattice triangle in counter-clockwise
 * order). Then no rule in the tile meets a sharp edge: the edges refined are the corners'
 * edges and their descendants, and new vertices of smooth edges are smooth of valence 6.
 *
 * The last level is made one quarter at a time (child c of the tile's face at the level
 * before), in the quarter's own frame, so that one table gives subd_loop's emission order
 * of every quarter and the grid for the last level is a quarter's size. Limit mode's depth 5
 * goes one step further (lt_split): it makes a quarter's last level with margin once, and
 * its limit points a sixteenth (a quarter's child) at a time, so that those records, their
 * normals and the emission table are a depth-4 quarter's and the plan stays within 16 KiB at
 * 8 levels and valence 16 (a vertex's limit point depends on its quarter coordinates alone:
 * the sixteenths give the quarter's bits).
 *
 * The tile vertices' ids (subd_lt_ids) are loop_tile_ids.c's. */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "layout.h" /* subd_bytes_add, subd_bytes_max */
#include "loop_tile.h"

/* No rule of a tile can overflow, so its rules skip the check (lt_vpt, lt_ept): each is a convex
 * combination (weights >= 0 summing to one, 3/8 3/8 1/8 1/8 and 5/8 1/16 x 6, exact in both
 * arithmetics), so no point of a tile leaves the range of its level-0 points: in Q16.16 the
 * exact 64-bit sum rounds into it, and in float32 a partial sum stays below
 * max |x| (1 + 2^-24)^k, which is finite when every level-0 coordinate is below
 * SUBD_REAL_MAX / 2. A patch with a larger (or a NaN) coordinate is refused (LT_HUGE) and
 * takes the general path, whose rules check. Q16.16 tiles sum in 32 bits (lt_vpt, lt_ept:
 * at most 16 times a coordinate), which their level-0 coordinates below 2^27 (2048.0) in
 * magnitude keep from overflowing. A patch with a larger one is moved first: on each axis
 * where a coordinate is beyond 2^27 - 1 units, by T = the middle of the patch's extent
 * (whole units), when that brings all of them within 2^27 - 1 (an extent up to about
 * 4096.0); the tile is made from x - T and T is added back to the last level's records
 * (subd_lt_quarter), which gives subd_loop's bits: every Q16.16 rule of a tile is
 * equivariant under a whole-unit move, (S - D T + D/2) >> log2 D = ((S + D/2) >> log2 D) - T
 * for the vertex (D = 16) and edge (D = 8) rules, whose weights sum to D exactly (an
 * arithmetic shift is a floor), and limit mode's v + chi sum(p_j - v) and its tangents read
 * differences (T cancels); the moved-back values are subd_loop's, within the patch's range,
 * so the addition cannot overflow. A patch too wide for that takes the general path (the
 * same bits, in 64-bit sums). */
#if SUBD_FIXED
#define LT_FIX_MAX ((subd_real)134217727) /* 2^27 - 1 */
/* The move of a patch (see above): T per axis into org, the positions moved; 0 when the patch
 * is too wide for the 32-bit sums even after the move. */
static int lt_move(subd_real *pos, uint32_t n, subd_real org[3])
{
    uint32_t v, k;
    for (k = 0; k < 3u; k++) {
        int64_t lo = pos[k], hi = pos[k], t;
        for (v = 1; v < n; v++) {
            if (pos[3u * v + k] < lo) lo = pos[3u * v + k];
            if (pos[3u * v + k] > hi) hi = pos[3u * v + k];
        }
        org[k] = 0;
        if (lo >= -(int64_t)LT_FIX_MAX && hi <= (int64_t)LT_FIX_MAX) continue;
        t = lo + (hi - lo) / 2; /* within [lo, hi]: a subd_real */
        if (hi - t > (int64_t)LT_FIX_MAX || t - lo > (int64_t)LT_FIX_MAX) return 0;
        org[k] = (subd_real)t;
        for (v = 0; v < n; v++) pos[3u * v + k] = (subd_real)(pos[3u * v + k] - t);
    }
    return 1;
}
#else
#define LT_HUGE(x) (!((x) <= SUBD_REAL_MAX / 2.0f && (x) >= -(SUBD_REAL_MAX / 2.0f)))
#endif

/* Lattice directions, counter-clockwise: (1,0) (0,1) (-1,1) (-1,0) (0,-1) (1,-1). */
static const int8_t lt_dx[6] = {1, 0, -1, -1, 0, 1};
static const int8_t lt_dy[6] = {0, 1, 1, 0, -1, -1};
/* Lattice corner k of U(i, j) and of D(i, j), as offsets from (i, j). */
static const uint8_t lt_uoff[3][2] = {{0u, 0u}, {1u, 0u}, {0u, 1u}};
static const uint8_t lt_doff[3][2] = {{1u, 0u}, {1u, 1u}, {0u, 1u}};

static uint32_t lt_side(uint32_t t) { return (1u << t) + 3u; }

uint32_t subd_lt_layout(uint32_t t, int limit, uint32_t off[LT_N])
{
    uint32_t own[LT_N], b = 0, nA = lt_count(lt_side(t - 1u)), nB = lt_count(lt_side(t - 2u));
    uint32_t qn = lt_count(1u << (t - lt_split(t, limit))), rs = 3u * (uint32_t)sizeof(subd_real), g1 = 0, u = 0;
    /* the second grid's memory, dead once the last level is made, also holds the quarter's
     * records (limit mode: the quarter's last-level positions with their margin, a grid of
     * side 2^(t-1) + 3 = the first grid's; a piece's records follow: lt_split) */
    if (!off) off = own;
    off[LT_APOS] = b; subd_size_add(&b, nA, rs);
    off[LT_ADIR] = b; subd_size_add(&b, nA, 1u);
    off[LT_AROT] = b; subd_size_add(&b, nA, 2u);
    off[LT_ALOW] = b; subd_size_add(&b, nA, 1u);
    off[LT_BPOS] = b;
    subd_size_add(&g1, nB, rs);
    off[LT_BDIR] = b + g1; subd_size_add(&g1, nB, 1u);
    off[LT_BROT] = b + g1; subd_size_add(&g1, nB, 2u);
    off[LT_BLOW] = b + g1; subd_size_add(&g1, nB, 1u);
    subd_size_add(&u, limit ? nA : qn, limit ? rs : LT_REC_BYTES);
    subd_bytes_add(&b, subd_bytes_max(g1, u));
    off[LT_QREC] = limit ? b : off[LT_BPOS];
    if (limit) subd_size_add(&b, qn, LT_REC_BYTES);
    off[LT_LNRM] = b;
    if (limit) subd_size_add(&b, qn, rs);
    return b;
}

uint32_t subd_lt_tab_bytes(uint32_t t)
{
    uint32_t b = 0, u;
    for (u = 2; u <= t; u++) {
        uint32_t m = 1u << (u - 1u);
        subd_size_add(&b, m * m, 3u); /* 4^(u-1) triangles */
    }
    return b;
}

void subd_lt_carve(lt_tile *tl, uint8_t *block, uint8_t *tab, uint32_t t, int limit)
{
    uint32_t off[LT_N];
    uint32_t td = lt_table_depth(t, limit);
    (void)subd_lt_layout(t, limit, off);
    tl->tab = tab ? tab + subd_lt_tab_bytes(td - 1u) : 0; /* depth td's table follows 2..td-1's */
    tl->g[0].pos = (subd_real *)(void *)(block + off[LT_APOS]);
    tl->g[0].dir = block + off[LT_ADIR];
    tl->g[0].rot = block + off[LT_AROT];
    tl->g[0].low = block + off[LT_ALOW];
    tl->g[1].pos = (subd_real *)(void *)(block + off[LT_BPOS]);
    tl->g[1].dir = block + off[LT_BDIR];
    tl->g[1].rot = block + off[LT_BROT];
    tl->g[1].low = block + off[LT_BLOW];
    tl->mpos = tl->g[1].pos;
    tl->q = (lt_rec *)(void *)(block + off[LT_QREC]);
    tl->qhi = (uint32_t *)(void *)(tl->q + lt_count(1u << (t - lt_split(t, limit)))); /* after a piece's records */
    tl->qnrm = limit ? (subd_real *)(void *)(block + off[LT_LNRM]) : 0;
    tl->lk = 0;
    tl->depth = t;
    tl->split = lt_split(t, limit);
}

void subd_lt_table(const lt_tile *tl)
{
    static const uint8_t pts[4][3] = TOPO_LOOP_CHILD_POINTS;
    uint32_t q = tl->depth - tl->split, m = 1u << q, n = m * m, j, l, k;
    for (j = 0; j < n; j++) {
        uint32_t x[6], y[6];
        x[0] = 0; y[0] = 0; x[1] = m; y[1] = 0; x[2] = 0; y[2] = m;
        for (l = 0; l < q; l++) {
            uint32_t dg = (j >> (2u * (q - 1u - l))) & 3u, nx[3], ny[3];
            for (k = 0; k < 3u; k++) {
                x[3u + k] = (x[k] + x[(k + 1u) % 3u]) / 2u;
                y[3u + k] = (y[k] + y[(k + 1u) % 3u]) / 2u;
            }
            for (k = 0; k < 3u; k++) {
                nx[k] = x[pts[dg][k]];
                ny[k] = y[pts[dg][k]];
            }
            for (k = 0; k < 3u; k++) {
                x[k] = nx[k];
                y[k] = ny[k];
            }
        }
        for (k = 0; k < 3u; k++) tl->tab[3u * j + k] = (uint8_t)lt_vi(m, x[k], y[k]);
    }
}

/* ------------------------------------------------------------------------------------ */
/* One point of level t + 1 from level t                                                  */

/* Level t + 1 point at (px, py) / 2 of level t (side s): *even = 1 and (ui, uj) the old
 * vertex, or *even = 0 and the edge d of U(ui, uj) it halves. */
static inline void lt_classify(uint32_t px, uint32_t py, int *even, uint32_t *ui, uint32_t *uj, uint32_t *d)
{
    *even = 0;
    if (px & 1u) {
        *ui = (px - 1u) / 2u;
        if (py & 1u) {
            *uj = (py - 1u) / 2u;
            *d = 1;
        } else {
            *uj = py / 2u;
            *d = 0;
        }
    } else if (py & 1u) {
        *ui = px / 2u;
        *uj = (py - 1u) / 2u;
        *d = 2;
    } else {
        *ui = px / 2u;
        *uj = py / 2u;
        *d = 0;
        *even = 1;
    }
}

/* Ring start of the new vertex on edge d of U(ui, uj) (see the header: by the lower
 * half-edge's corner index in its face), tabulated: when U holds the lower half-edge (lattice
 * edge d, direction 2d) and U has rotation r, its corner index is ci = (d - r) mod 3 and the
 * ring starts in direction 2d when ci = 2, else 2 ((d + 1) mod 3): lt_ndir_u[d][r]; else the
 * down triangle across (D(ui, uj-1), D(ui, uj), D(ui-1, uj) for d = 0, 1, 2) holds it as its
 * lattice edge k = (d + 1) mod 3, direction 2k + 1, and with its rotation r, ci = (k - r)
 * mod 3: direction 2k + 1 when ci = 2, else 2 ((k + 1) mod 3) + 1: lt_ndir_d[d][r]. */
static const uint8_t lt_ndir_u[3][3] = {{2u, 0u, 2u}, {4u, 4u, 2u}, {4u, 0u, 0u}};
static const uint8_t lt_ndir_d[3][3] = {{5u, 5u, 3u}, {5u, 1u, 1u}, {3u, 1u, 3u}};

/* The ring start of the new vertex on edge d of U(u) of g, x the down triangle across it. */
TOPO_INLINE uint8_t lt_ndir(const lt_grid *g, uint32_t u, uint32_t x, uint32_t d)
{
    return (((uint32_t)g->low[u] >> d) & 1u) ? lt_ndir_u[d][g->rot[2u * u]] : lt_ndir_d[d][g->rot[2u * x + 1u]];
}

static uint8_t lt_new_dir(const lt_grid *g, uint32_t s, uint32_t ui, uint32_t uj, uint32_t d)
{
    uint32_t v = lt_vi(s, ui, uj);
    /* the D across: lt_vi's row step */
    return lt_ndir(g, v, d == 0u ? v - (s + 2u - uj) : d == 1u ? v : v - 1u, d);
}

/* Ring start (lattice direction of vert_out) of the level t + 1 point (px, py) / 2 of grid g
 * (side s), a point of the tile's face. */
static inline uint32_t lt_dir_at(const lt_grid *g, uint32_t s, uint32_t px, uint32_t py)
{
    uint32_t ui, uj, d;
    int even;
    lt_classify(px, py, &even, &ui, &uj, &d);
    return even ? g->dir[lt_vi(s, ui, uj)] : lt_new_dir(g, s, ui, uj, d);
}

/* Faces of level t + 1 (h, side s2) from those of level t (g, side s): rotations and lower
 * sides, by rows of h. Every face of h is a child of a face of g (the three corner up
 * triangles of a grid are not faces of its 1-ring and have no children in h), and U(I, J)
 * and D(I, J) of h are children of the face of g at index lt_vi(s, (I + 1) >> 1,
 * (J + 1) >> 1) (I, J of h are 2i - 1 + the child's offset), which the parities say:
 *   J odd,  I odd:  U corner child 0 of U (rotation 0), D the middle child of U (U's);
 *   J odd,  I even: U corner child 1 of U (rotation 1), D corner child 0 of D (rotation 0);
 *   J even, I odd:  U corner child 2 of U (rotation 2), D corner child 2 of D (rotation 2);
 *   J even, I even: U the middle child of D (D's + 1), D corner child 1 of D (rotation 1).
 * A corner child at lattice corner k has rotation k; the middle child of an up triangle
 * keeps its rotation, of a down one adds one (the header). Lower sides: a corner child's
 * edges along the parent's keep the parent's bits, its inner edge is lower on its side; the
 * middle child holds no lower half-edge. `rot` (a constant: forced inline): the rotations
 * too (plain mode's last grid needs only the lower sides: its rotations would serve the ring
 * starts of a level it does not make). */
TOPO_INLINE void lt_faces(const lt_grid *g, uint32_t s, const lt_grid *h, uint32_t s2, int rot)
{
    static const uint8_t next3[3] = {1u, 2u, 0u}; /* (r + 1) mod 3 */
    const uint8_t *gl = g->low, *gr = g->rot;
    uint32_t I, J;
    for (J = 0; J < s2; J++) {
        /* U(I, J) and D(I, J) of h from the face p = p0 + (I + 1) / 2 of g: I = 0 alone, then
         * I odd and I + 1 (one p) in one turn */
        uint32_t v = lt_vi(s2, 0u, J), n = s2 - J, p = lt_vi(s, 0u, (J + 1u) >> 1);
        uint8_t *hl = h->low + v, *hr = h->rot + 2u * v;
#define LT_FACE(i, lw, ru, rd)                                          \
        do {                                                            \
            hl[i] = (uint8_t)(lw);                                      \
            if (rot) {                                                  \
                hr[2u * (i)] = (uint8_t)(ru);                           \
                if ((i) + 1u < n) hr[2u * (i) + 1u] = (uint8_t)(rd); /* D(I, J) is in h */ \
            }                                                           \
        } while (0)
        if (J & 1u) { /* I even: corner children 1 of U, 0 of D; I odd: corner child 0 of U, U's middle child */
            LT_FACE(0u, (gl[p] & 3u) | 4u, 1u, 0u);
            for (I = 1u, p++; I + 1u < n; I += 2u, p++) {
                LT_FACE(I, (gl[p] & 5u) | 2u, 0u, gr[2u * p]);
                LT_FACE(I + 1u, (gl[p] & 3u) | 4u, 1u, 0u);
            }
            if (I < n) LT_FACE(I, (gl[p] & 5u) | 2u, 0u, gr[2u * p]);
        } else { /* I even: D's middle child, corner child 1 of D; I odd: corner children 2 */
            LT_FACE(0u, 0u, next3[gr[2u * p + 1u]], 1u);
            for (I = 1u, p++; I + 1u < n; I += 2u, p++) {
                LT_FACE(I, (gl[p] & 6u) | 1u, 2u, 2u);
                LT_FACE(I + 1u, 0u, next3[gr[2u * p + 1u]], 1u);
            }
            if (I < n) LT_FACE(I, (gl[p] & 6u) | 1u, 2u, 2u);
        }
#undef LT_FACE
    }
}

/* Level t + 1 (h, side 2s - 3) from level t (g, side s); `meta`: 0 its positions only, 1
 * its ring starts and lower sides too, 2 its rotations too (subd_lt_start). */
static void lt_refine(const lt_grid *g, uint32_t s, const lt_grid *h, int meta, loop_weights w)
{
    uint32_t s2 = 2u * s - 3u, i, J;
    subd_lt_rows_refine(g, s, (int32_t)s2, h->pos, w);
    if (!meta) return;
    /* ring starts: the next level's old vertices are this level's face's, at I, J >= 1,
     * I + J <= s2 - 1 */
    for (J = 1; J + 2u <= s2; J++) {
        /* lt_dir_at of (I + 1, J + 1), by rows: the point lies in U(u) of g, u = lt_vi(s,
         * (I + 1) >> 1, (J + 1) >> 1) whatever its parities (I odd and I + 1: one u, in one
         * turn); lt_new_dir's D across is D(u) for edge 1, D(u - 1) for edge 2, and for edge
         * 0 the D below (one row of g back) */
        uint32_t uj = (J + 1u) >> 1, u = lt_vi(s, 0u, uj) + 1u, back = s + 2u - uj, n = s2 - J - 1u;
        uint8_t *hd = h->dir + lt_vi(s2, 1u, J);
        if (J & 1u) { /* py even: px even (I odd) the old vertex keeps its ring start; I even edge 0 */
            for (i = 0; i + 1u < n; i += 2u, u++) {
                hd[i] = g->dir[u];
                hd[i + 1u] = lt_ndir(g, u, u - back, 0u);
            }
            if (i < n) hd[i] = g->dir[u];
        } else { /* I odd edge 2, I even edge 1 */
            for (i = 0; i + 1u < n; i += 2u, u++) {
                hd[i] = lt_ndir(g, u, u - 1u, 2u);
                hd[i + 1u] = lt_ndir(g, u, u, 1u);
            }
            if (i < n) hd[i] = lt_ndir(g, u, u - 1u, 2u);
        }
    }
    if (meta > 1)
        lt_faces(g, s, h, s2, 1);
    else
        lt_faces(g, s, h, s2, 0);
}

/* ------------------------------------------------------------------------------------ */
/* Level 0 from the patch                                                                 */

/* Lattice direction of (ddx, ddy), or 6. */
static uint32_t lt_dir_of(int32_t ddx, int32_t ddy)
{
    uint32_t d;
    for (d = 0; d < 6u; d++)
        if (lt_dx[d] == ddx && lt_dy[d] == ddy) return d;
    return 6u;
}

int subd_lt_start(lt_tile *tl, const sp_level *p, loop_wcache *wc, uint32_t *ovf, subd_real org[3])
{
    const lt_grid *g = &tl->g[(tl->depth - 1u) & 1u];
    /* everything is read from the patch and checked first, then written: the stream lends
     * the tile the patch's own memory (loop_stream.c's layout), and a refused patch must
     * stay whole */
    uint8_t lx[12], ly[12], used[30], cdir[3], rot[30], low[15];
    subd_real pos[36];
    uint32_t c, k, f, v, t;
    loop_weights w;
    if (p->h->nv != 12u || p->h->nf != 13u) return 0;
    for (v = 0; v < 12u; v++) lx[v] = ly[v] = 0xffu;
    for (k = 0; k < 30u; k++) used[k] = 0;
    lx[0] = 1; ly[0] = 1; lx[1] = 2; ly[1] = 1; lx[2] = 1; ly[2] = 2;
    for (c = 0; c < 3u; c++) {
        uint32_t nbr[7], he[7], s = 6u;
        if (p->vflag[c] & TOPO_PF_CORNER) return 0;
        if (subd_lp_ring(p, c, nbr, he, 7u) != 6u) return 0;
        for (k = 0; k < 6u; k++) {
            if (p->tw[he[k]] >= LP_TW_BORDER || p->sh[he[k]] != 0u || nbr[k] >= 12u) return 0;
            if (nbr[k] == (c + 1u) % 3u) s = (2u * c + 6u - k) % 6u; /* corner c -> c+1: direction 2c */
        }
        if (s == 6u) return 0;
        cdir[c] = (uint8_t)s;
        for (k = 0; k < 6u; k++) {
            uint32_t d = (s + k) % 6u, u = nbr[k];
            uint8_t x = (uint8_t)((int32_t)lx[c] + lt_dx[d]), y = (uint8_t)((int32_t)ly[c] + lt_dy[d]);
            if (lx[u] == 0xffu) {
                lx[u] = x;
                ly[u] = y;
            } else if (lx[u] != x || ly[u] != y) {
                return 0;
            }
        }
    }
    for (v = 0; v < 12u; v++) { /* every vertex placed, no two at one point */
        uint32_t q;
        if (lx[v] == 0xffu) return 0;
        q = lt_vi(4u, lx[v], ly[v]);
        if (used[q]) return 0;
        used[q] = 1;
        for (k = 0; k < 3u; k++) {
            pos[3u * v + k] = p->pos[3u * v + k];
#if !SUBD_FIXED
            if (LT_HUGE(pos[3u * v + k])) return 0; /* the general path checks every rule */
#endif
        }
    }
#if SUBD_FIXED
    if (!lt_move(pos, 12u, org)) return 0;
#else
    (void)org; /* float32 tiles are never moved (NULL) */
#endif
    for (k = 0; k < 15u; k++) {
        low[k] = 0;
        used[k] = 0;
    }
    for (k = 15u; k < 30u; k++) used[k] = 0;
    for (f = 0; f < 13u; f++) { /* faces: lattice triangles, counter-clockwise */
        uint32_t u0 = p->cv[3u * f], u1 = p->cv[3u * f + 1u], u2 = p->cv[3u * f + 2u], d, r, dn, i, j, q;
        const uint8_t(*off)[2];
        d = lt_dir_of((int32_t)lx[u1] - (int32_t)lx[u0], (int32_t)ly[u1] - (int32_t)ly[u0]);
        if (d == 6u) return 0;
        dn = d & 1u; /* even directions are up triangles' edges, odd ones down triangles' */
        r = d / 2u;
        off = dn ? lt_doff : lt_uoff;
        if (lx[u0] < off[r][0] || ly[u0] < off[r][1]) return 0;
        i = lx[u0] - off[r][0];
        j = ly[u0] - off[r][1];
        if (i + off[(r + 2u) % 3u][0] != lx[u2] || j + off[(r + 2u) % 3u][1] != ly[u2]) return 0;
        q = 2u * lt_vi(4u, i, j) + dn;
        if (used[q]) return 0;
        used[q] = 1;
        rot[q] = (uint8_t)r;
        if (!dn)
            for (k = 0; k < 3u; k++) {
                uint32_t h = 3u * f + k, tw = p->tw[h];
                if (tw < LP_TW_BORDER && h < tw) low[lt_vi(4u, i, j)] = (uint8_t)(low[lt_vi(4u, i, j)] | (1u << ((r + k) % 3u)));
            }
    }
    /* the patch is regular: level 0 of the tile */
    for (c = 0; c < 3u; c++) g->dir[lt_vi(4u, lx[c], ly[c])] = cdir[c];
    for (v = 0; v < 12u; v++) {
        uint32_t q = lt_vi(4u, lx[v], ly[v]);
        g->pos[3u * q] = pos[3u * v];
        g->pos[3u * q + 1u] = pos[3u * v + 1u];
        g->pos[3u * q + 2u] = pos[3u * v + 2u];
    }
    for (k = 0; k < 30u; k++)
        if (used[k]) g->rot[k] = rot[k];
    for (k = 0; k < 15u; k++) g->low[k] = low[k];
    w = subd_loop_weights_of(wc, 6u, ovf);
    /* the ring starts, rotations and lower sides of every level: for the order of float32
     * sums (LT_ORDERED) and limit mode's ring starts (lt_dir_at); a plain Q16.16 tile needs
     * none of them */
    for (t = 0; t + 1u < tl->depth; t++) {
        /* a level's rotations serve the ring starts of the next: plain mode's last grid
         * needs none; limit mode reads them there (lt_dir_at) */
        int meta = !(LT_ORDERED || tl->qnrm) ? 0 : t + 2u == tl->depth && !tl->qnrm ? 1 : 2;
        lt_refine(&tl->g[(tl->depth - 1u - t) & 1u], lt_side(t), &tl->g[(tl->depth - 2u - t) & 1u], meta, w);
    }
    return 1;
}

/* A piece's frame in its quarter (or a quarter's in the tile's face): child c = (v_c, m_c,
 * m_c-1), child 3 = (m0, m1, m2): corner 0 in units of the child's side, e1, e2. */
static const int8_t lt_cfr[4][6] = {{0, 0, 1, 0, 0, 1}, {2, 0, -1, 1, -1, 0}, {0, 2, 0, -1, 1, -1}, {1, 0, 0, 1, -1, 1}};

/* Limit mode's piece c (lt_split; quarter qc = c >> 2 (split - 1), frame ox, oy, e1, e2 as in
 * subd_lt_quarter; g: level depth - 1, side s): at the quarter's first piece its last-level
 * positions with a one-vertex margin into mpos (a grid of side m + 3 less its corners: the
 * quarter at (1, 1)), then each piece vertex's limit position and normal from its ring
 * there, started at its vert_out (the level's ring start in the tile's lattice, turned into
 * the quarter's: the quarter's lattice directions are the tile's turned by qrot[qc] sixths,
 * counter-clockwise, as e1 is direction qrot[qc]). A piece vertex (x, y) is the quarter's
 * (X, Y) = o + x f1 + y f2 (the piece's frame in the quarter, lt_cfr; split 1: identity);
 * each vertex's value depends on (X, Y) alone, so the pieces give the quarter's bits. */
static void lt_limit_quarter(const lt_tile *tl, uint32_t c, const lt_grid *g, uint32_t s, int32_t ox, int32_t oy,
                             const int32_t e1[2], const int32_t e2[2], const int32_t po[2], const int32_t f1[2],
                             const int32_t f2[2], loop_weights w, uint32_t *lo)
{
    static const uint8_t qrot[4] = {0u, 2u, 4u, 1u};
    uint32_t m = 1u << (tl->depth - 1u), S = m + 3u, mp = 1u << (tl->depth - tl->split), x;
    uint32_t qc = c >> (2u * (tl->split - 1u));
    const subd_real *M = tl->mpos;
    const lim_reg6 *lk = tl->lk;
    lt_rec *q = tl->q;
    subd_real *nrm = tl->qnrm;
    int32_t o3[12], Y, ymin, ymax, dd = f1[1] * f1[1];
    uint32_t qr = 6u - qrot[qc];
    if (tl->split == 1u || (c & 3u) == 0u) { /* the quarter's first piece */
        lt_frame fr;
        fr.ox = ox; fr.oy = oy; fr.p = e1[0]; fr.q = e1[1]; fr.r = e2[0]; fr.u = e2[1];
        fr.lo = -1; fr.hi = (int32_t)m + 1; fr.skip = 1; fr.ds = 3;
        subd_lt_rows(g, s, &fr, tl->mpos, w);
    }
    /* by rows Y of the quarter (the ring's offsets are a row's, the margin index steps by
     * one), X over the piece's part of the row: x = f2y dX - f2x dY >= 0,
     * y = -f1y dX + f1x dY >= 0, x + y <= mp (dX = X - po[0], dY = Y - po[1]; the frame has
     * determinant 1) */
    ymin = ymax = po[1];
    for (x = 1; x < 3u; x++) {
        int32_t cy = po[1] + (int32_t)mp * (x == 1u ? f1[1] : f2[1]);
        if (cy < ymin) ymin = cy;
        if (cy > ymax) ymax = cy;
    }
    for (Y = ymin; Y <= ymax; Y++) {
        int32_t dY = Y - po[1], a = -0x40000000, b = 0x40000000, X, lx, ly, px, py, k, sk, n;
        uint32_t l0;
        lt_bound(f2[1], -f2[0] * dY, &a, &b);
        lt_bound(-f1[1], f1[0] * dY, &a, &b);
        lt_bound(f1[1] - f2[1], (int32_t)mp - (f1[0] - f2[0]) * dY, &a, &b);
        if (a > b) continue;
        lt_ring_offsets((int32_t)(S - (uint32_t)Y), o3); /* row Y + 1 of the margin grid */
        lx = f2[1] * a - f2[0] * dY;
        ly = -f1[1] * a + f1[0] * dY;
        X = po[0] + a;
        l0 = lt_vi(S, (uint32_t)X + 1u, (uint32_t)Y + 1u);
        px = ox + X * e1[0] + Y * e2[0];
        py = oy + X * e1[1] + Y * e2[1];
        /* the record index k = lt_vi(mp, lx, ly) stepped as lt_rows steps its destination:
         * (lx, ly) moves by (f2y, -f1y), k by sk, which falls by f1y^2 per step */
        k = ly * (2 * (int32_t)mp + 3 - ly) / 2 + lx;
        sk = f2[1] - f1[1] * (2 * (int32_t)mp + 3 + f1[1]) / 2 + ly * f1[1];
        for (n = b - a + 1; n > 0; n--, l0++, px += e1[0], py += e1[1], k += sk, sk -= dd) {
            uint32_t d = lt_dir_at(g, s, (uint32_t)px, (uint32_t)py) + qr;
            if (d >= 6u) d -= 6u;
            subd_loop_limit_reg6(lk, M + 3u * l0, o3 + d, q[k].p, nrm + 3 * k, lo);
        }
    }
}

/* The move back of a moved Q16.16 tile (lt_move): T added to the piece's records. */
static void lt_move_back(const lt_tile *tl, const subd_real *T)
{
#if SUBD_FIXED
    uint32_t k, n = lt_count(1u << (tl->depth - tl->split));
    if (!(T[0] | T[1] | T[2])) return;
    for (k = 0; k < n; k++) {
        tl->q[k].p[0] += T[0];
        tl->q[k].p[1] += T[1];
        tl->q[k].p[2] += T[2];
    }
#else
    (void)tl;
    (void)T;
#endif
}

void subd_lt_quarter(const lt_tile *tl, uint32_t c, loop_wcache *wc, uint32_t *ovf, const subd_real T[3], int32_t org[2],
                     int32_t e1[2], int32_t e2[2])
{
    const lt_grid *g = &tl->g[0]; /* level depth - 1 */
    uint32_t m = 1u << (tl->depth - 1u), s = lt_side(tl->depth - 1u), lo = 0, qc = c >> (2u * (tl->split - 1u));
    int32_t im = (int32_t)m, ox, oy;
    loop_weights w = subd_loop_weights_of(wc, 6u, ovf);
    /* the quarter's corner 0 and edge directions in the last level, relative to the tile
     * face's corner 0 */
    const int8_t *fr = lt_cfr[qc];
    org[0] = fr[0] * im;
    org[1] = fr[1] * im;
    e1[0] = fr[2];
    e1[1] = fr[3];
    e2[0] = fr[4];
    e2[1] = fr[5];
    /* grid coordinates are the tile face's plus one, and lt_rows takes them plus one */
    ox = org[0] + 2;
    oy = org[1] + 2;
    if (tl->lk) {
        /* the piece's frame in the quarter (split 2: child c % 4 of side m / 2), and in the
         * tile's last level for the ids */
        int32_t po[2] = {0, 0}, f1[2] = {1, 0}, f2[2] = {0, 1}, k;
        if (tl->split == 2u) {
            const int8_t *pf = lt_cfr[c & 3u];
            po[0] = pf[0] * (im / 2);
            po[1] = pf[1] * (im / 2);
            f1[0] = pf[2]; f1[1] = pf[3]; f2[0] = pf[4]; f2[1] = pf[5];
        }
        lt_limit_quarter(tl, c, g, s, ox, oy, e1, e2, po, f1, f2, w, &lo);
        lt_move_back(tl, T);
        *ovf |= lo;
        org[0] += po[0] * e1[0] + po[1] * e2[0];
        org[1] += po[0] * e1[1] + po[1] * e2[1];
        for (k = 0; k < 2; k++) {
            int32_t a = e1[k], b = e2[k];
            e1[k] = f1[0] * a + f1[1] * b;
            e2[k] = f2[0] * a + f2[1] * b;
        }
        return;
    }
    subd_lt_rows_quarter(g, s, qc, ox, oy, (int32_t)m, (subd_real *)(void *)tl->q, w); /* the records' positions */
    lt_move_back(tl, T);
    *ovf |= lo;
}
