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
 *
 * Regular: the patch has exactly 13 faces and 12 vertices, its three corners are interior,
 * of valence 6, untagged, with no sharp edge, and it embeds in the lattice consistently
 * (every neighbour at one lattice point, every face a lattice triangle in counter-clockwise
 * order). Then no rule in the tile meets a sharp edge: the edges refined are the corners'
 * edges and their descendants, and new vertices of smooth edges are smooth of valence 6.
 *
 * The last level is made one quarter at a time (child c of the tile's face at the level
 * before), in the quarter's own frame, so that one table gives subd_loop's emission order
 * of every quarter and the grid for the last level is a quarter's size. */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "loop_tile.h"

/* Lattice directions, counter-clockwise: (1,0) (0,1) (-1,1) (-1,0) (0,-1) (1,-1). */
static const int8_t lt_dx[6] = {1, 0, -1, -1, 0, 1};
static const int8_t lt_dy[6] = {0, 1, 1, 0, -1, -1};
/* Lattice corner k of U(i, j) and of D(i, j), as offsets from (i, j). */
static const uint8_t lt_uoff[3][2] = {{0u, 0u}, {1u, 0u}, {0u, 1u}};
static const uint8_t lt_doff[3][2] = {{1u, 0u}, {1u, 1u}, {0u, 1u}};

static uint32_t lt_side(uint32_t t) { return (1u << t) + 3u; }

uint32_t subd_lt_layout(uint32_t t, int limit, uint32_t off[LT_N])
{
    uint32_t own[LT_N], b = 0, nA = lt_count(lt_side(t - 1u)), nB = lt_count(lt_side(t - 2u)), m = 1u << (t - 1u);
    uint32_t qn = lt_count(m), rs = 3u * (uint32_t)sizeof(subd_real);
    /* the second grid's positions also hold the last level's quarter (limit mode: with its
     * margin, a grid of side m + 3 = the first grid's) */
    uint32_t nq = limit ? nA : qn, nb = nB > nq ? nB : nq, nl = limit ? qn : 0u;
    if (!off) off = own;
    off[LT_APOS] = b; subd_size_add(&b, nA, rs);
    off[LT_ADIR] = b; subd_size_add(&b, nA, 1u);
    off[LT_AROT] = b; subd_size_add(&b, nA, 2u);
    off[LT_ALOW] = b; subd_size_add(&b, nA, 1u);
    off[LT_BPOS] = b; subd_size_add(&b, nb, rs);
    off[LT_BDIR] = b; subd_size_add(&b, nB, 1u);
    off[LT_BROT] = b; subd_size_add(&b, nB, 2u);
    off[LT_BLOW] = b; subd_size_add(&b, nB, 1u);
    off[LT_QID] = b;  subd_size_add(&b, qn, 8u);
    off[LT_LPOS] = b; subd_size_add(&b, nl, rs);
    off[LT_LNRM] = b; subd_size_add(&b, nl, rs);
    return b;
}

uint32_t subd_lt_tab_bytes(uint32_t t)
{
    uint32_t b = 0, m = 1u << (t - 1u);
    subd_size_add(&b, m * m, 3u); /* 4^(t-1) triangles */
    return b;
}

void subd_lt_carve(lt_tile *tl, uint8_t *block, uint8_t *tab, uint32_t t, int limit)
{
    uint32_t off[LT_N];
    (void)subd_lt_layout(t, limit, off);
    tl->g[0].pos = (subd_real *)(void *)(block + off[LT_APOS]);
    tl->g[0].dir = block + off[LT_ADIR];
    tl->g[0].rot = block + off[LT_AROT];
    tl->g[0].low = block + off[LT_ALOW];
    tl->g[1].pos = (subd_real *)(void *)(block + off[LT_BPOS]);
    tl->g[1].dir = block + off[LT_BDIR];
    tl->g[1].rot = block + off[LT_BROT];
    tl->g[1].low = block + off[LT_BLOW];
    tl->mpos = tl->g[1].pos;
    tl->qpos = limit ? (subd_real *)(void *)(block + off[LT_LPOS]) : tl->g[1].pos;
    tl->qnrm = limit ? (subd_real *)(void *)(block + off[LT_LNRM]) : 0;
    tl->lk = 0;
    tl->qid = (uint32_t *)(void *)(block + off[LT_QID]);
    tl->tab = tab;
    tl->depth = t;
}

void subd_lt_table(const lt_tile *tl)
{
    static const uint8_t pts[4][3] = TOPO_LOOP_CHILD_POINTS;
    uint32_t q = tl->depth - 1u, m = 1u << q, n = m * m, j, l, k;
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

/* The index offsets of a grid vertex's six neighbours (i, j) + (1, 0), (0, 1), (-1, 1),
 * (-1, 0), (0, -1), (1, -1), for a vertex in a row of `row` vertices of the row-major
 * triangular grid (lt_vi); unsigned wrap-around gives the negative ones. */
static inline void lt_ring_offsets(uint32_t row, uint32_t *off)
{
    off[0] = 1u;
    off[1] = row;
    off[2] = row - 1u;
    off[3] = (uint32_t)0u - 1u;
    off[4] = (uint32_t)0u - (row + 1u);
    off[5] = (uint32_t)0u - row;
}

/* Position of the level t + 1 point (px, py) / 2 of grid g (side s): the smooth vertex rule
 * of valence 6 from the vertex's ring start, or the interior edge rule from the lower side.
 * Indices from U(ui, uj)'s: vertex (i, j) + (1, 0) is +1, + (0, 1) is +row (row = s + 1 - j,
 * the length of row j), + (-1, 1) is +row - 1, + (0, -1) is -(row + 1), + (1, -1) is -row. */
/* Forced inline (topo.h's TOPO_INLINE) into each loop over a grid: out of line, the call and
 * the classification cost the M4F 7 instructions per emitted triangle (demo level 6). */
TOPO_INLINE void lt_point(const lt_grid *g, uint32_t s, uint32_t px, uint32_t py, loop_weights w, subd_real *out,
                          uint32_t *ovf)
{
    uint32_t ui, uj, d, l0, row;
    int even;
    const subd_real *P = g->pos;
    lt_classify(px, py, &even, &ui, &uj, &d);
    l0 = lt_vi(s, ui, uj);
    row = s + 1u - uj;
    if (even) {
        /* the ring twice over, so that its six from the ring start are r[0..5]: the adds
         * unrolled, in the ring's order */
        uint32_t k, off[6];
        const subd_real *q[12], *const *r;
        subd_acc acc[3];
        lt_ring_offsets(row, off);
        for (k = 0; k < 6u; k++) q[k] = q[k + 6u] = P + 3u * (l0 + off[k]);
        r = q + g->dir[l0];
        loop_smooth_begin(acc, w, P + 3u * l0);
        loop_smooth_add(acc, w, r[0]);
        loop_smooth_add(acc, w, r[1]);
        loop_smooth_add(acc, w, r[2]);
        loop_smooth_add(acc, w, r[3]);
        loop_smooth_add(acc, w, r[4]);
        loop_smooth_add(acc, w, r[5]);
        loop_smooth_end(out, acc, ovf);
    } else {
        uint32_t a, b, c, e;
        if (d == 0u) {
            a = l0; b = l0 + 1u; c = l0 + row; e = l0 - row;
        } else if (d == 1u) {
            a = l0 + 1u; b = l0 + row; c = l0; e = l0 + row + 1u;
        } else {
            a = l0 + row; b = l0; c = l0 + 1u; e = l0 + row - 1u;
        }
        if (((uint32_t)g->low[l0] >> d) & 1u)
            loop_rule_edge(out, P + 3u * a, P + 3u * b, P + 3u * c, P + 3u * e, ovf);
        else
            loop_rule_edge(out, P + 3u * b, P + 3u * a, P + 3u * e, P + 3u * c, ovf);
    }
}

/* Ring start of the new vertex on edge d of U(ui, uj) (see the header: by the lower
 * half-edge's corner index in its face). */
static uint8_t lt_new_dir(const lt_grid *g, uint32_t s, uint32_t ui, uint32_t uj, uint32_t d)
{
    uint32_t r, k, ci;
    if (((uint32_t)g->low[lt_vi(s, ui, uj)] >> d) & 1u) { /* U's half-edge, lattice edge d, direction 2d */
        r = g->rot[2u * lt_vi(s, ui, uj)];
        ci = (d + 3u - r) % 3u;
        return (uint8_t)(ci == 2u ? 2u * d : 2u * ((d + 1u) % 3u));
    }
    /* the down triangle across: lattice edge k, direction 2k + 1 */
    if (d == 0u) {
        r = g->rot[2u * lt_vi(s, ui, uj - 1u) + 1u];
        k = 1;
    } else if (d == 1u) {
        r = g->rot[2u * lt_vi(s, ui, uj) + 1u];
        k = 2;
    } else {
        r = g->rot[2u * lt_vi(s, ui - 1u, uj) + 1u];
        k = 0;
    }
    ci = (k + 3u - r) % 3u;
    return (uint8_t)(ci == 2u ? 2u * k + 1u : 2u * ((k + 1u) % 3u) + 1u);
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

/* Faces of level t + 1 (side s2) from those of level t (side s): rotations and lower sides. */
static void lt_put_u(const lt_grid *h, uint32_t s2, uint32_t i, uint32_t j, uint32_t r, uint32_t low)
{
    if (i >= s2 || j >= s2 || i + j + 1u > s2) return; /* outside the next grid (-1 wraps) */
    h->rot[2u * lt_vi(s2, i, j)] = (uint8_t)r;
    h->low[lt_vi(s2, i, j)] = (uint8_t)low;
}

static void lt_put_d(const lt_grid *h, uint32_t s2, uint32_t i, uint32_t j, uint32_t r)
{
    if (i >= s2 || j >= s2 || i + j + 2u > s2) return;
    h->rot[2u * lt_vi(s2, i, j) + 1u] = (uint8_t)r;
}

/* Every face of level t + 1's grid is a child of a face of level t's (the three corner up
 * triangles of a grid are not faces of its 1-ring and are skipped). */
static void lt_faces(const lt_grid *g, uint32_t s, const lt_grid *h, uint32_t s2)
{
    uint32_t i, j;
    for (j = 0; j < s; j++)
        for (i = 0; i + j + 1u <= s; i++) {
            uint32_t v = lt_vi(s, i, j), r;
            uint32_t I = 2u * i - 1u, J = 2u * j - 1u; /* may wrap: lt_put_* drop them */
            if (!((i == 0u && j == 0u) || (i + 1u == s && j == 0u) || (i == 0u && j + 1u == s))) {
                uint32_t b = g->low[v]; /* U(i, j): three corner children, the middle one */
                r = g->rot[2u * v];
                lt_put_u(h, s2, I, J, 0u, (b & 5u) | 2u);
                lt_put_u(h, s2, I + 1u, J, 1u, (b & 3u) | 4u);
                lt_put_u(h, s2, I, J + 1u, 2u, (b & 6u) | 1u);
                lt_put_d(h, s2, I, J, r);
            }
            if (i + j + 2u <= s) { /* D(i, j) */
                r = g->rot[2u * v + 1u];
                lt_put_d(h, s2, I + 1u, J, 0u);
                lt_put_d(h, s2, I + 1u, J + 1u, 1u);
                lt_put_d(h, s2, I, J + 1u, 2u);
                lt_put_u(h, s2, I + 1u, J + 1u, (r + 1u) % 3u, 0u);
            }
        }
}

/* Level t + 1 (h, side 2s - 3) from level t (g, side s); `meta`: its ring starts, rotations
 * and lower sides too (not for the level the tile ends at). */
static void lt_refine(const lt_grid *g, uint32_t s, const lt_grid *h, int meta, loop_weights w, uint32_t *ovf)
{
    uint32_t s2 = 2u * s - 3u, I, J, lo = 0, v = 0; /* the flag in a register, not through *ovf */
    for (J = 0; J <= s2; J++)
        for (I = 0; I + J <= s2; I++, v++) { /* v = lt_vi(s2, I, J) */
            if ((I == 0u && J == 0u) || (I == s2 && J == 0u) || (I == 0u && J == s2)) continue;
            lt_point(g, s, I + 1u, J + 1u, w, h->pos + 3u * v, &lo);
            /* ring starts: the next level's old vertices are this level's face's, at
             * I, J >= 1, I + J <= s2 - 1 */
            if (meta && I >= 1u && J >= 1u && I + J + 1u <= s2) h->dir[v] = (uint8_t)lt_dir_at(g, s, I + 1u, J + 1u);
        }
    *ovf |= lo;
    if (meta) lt_faces(g, s, h, s2);
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

int subd_lt_start(lt_tile *tl, const sp_level *p, loop_wcache *wc, uint32_t *ovf)
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
        pos[3u * v] = p->pos[3u * v];
        pos[3u * v + 1u] = p->pos[3u * v + 1u];
        pos[3u * v + 2u] = p->pos[3u * v + 2u];
    }
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
    for (t = 0; t + 1u < tl->depth; t++)
        lt_refine(&tl->g[(tl->depth - 1u - t) & 1u], lt_side(t), &tl->g[(tl->depth - 2u - t) & 1u], 1, w, ovf);
    return 1;
}

/* Limit mode's quarter c (frame ox, oy, e1, e2 as in subd_lt_quarter; g: level depth - 1,
 * side s): its last-level positions with a one-vertex margin into mpos (a grid of side
 * m + 3 less its corners: the quarter at (1, 1)), then each quarter vertex's limit position
 * and normal from its ring there, started at its vert_out (the level's ring start in the
 * tile's lattice, turned into the quarter's: the quarter's lattice directions are the tile's
 * turned by qrot[c] sixths, counter-clockwise, as e1 is direction qrot[c]). */
static void lt_limit_quarter(const lt_tile *tl, uint32_t c, const lt_grid *g, uint32_t s, int32_t ox, int32_t oy,
                             const int32_t e1[2], const int32_t e2[2], loop_weights w, uint32_t *lo)
{
    static const uint8_t qrot[4] = {0u, 2u, 4u, 1u};
    uint32_t m = 1u << (tl->depth - 1u), S = m + 3u, X, Y, v = 0, x, y, k = 0;
    const subd_real *M = tl->mpos;
    for (Y = 0; Y <= S; Y++)
        for (X = 0; X + Y <= S; X++, v++) { /* v = lt_vi(S, X, Y) */
            int32_t qx = (int32_t)X - 1, qy = (int32_t)Y - 1;
            if ((X == 0u && Y == 0u) || (X == S && Y == 0u) || (X == 0u && Y == S)) continue;
            lt_point(g, s, (uint32_t)(ox + qx * e1[0] + qy * e2[0]), (uint32_t)(oy + qx * e1[1] + qy * e2[1]), w,
                     tl->mpos + 3u * v, lo);
        }
    for (y = 0; y <= m; y++) {
        /* the ring's offsets in subd_reals (lt_ring_offsets' six, twice over, so that the six
         * from any start are consecutive) for row y + 1 of the margin grid */
        int32_t row = (int32_t)(S - y), o3[12];
        uint32_t l0 = lt_vi(S, 1u, y + 1u), j;
        o3[0] = 3;
        o3[1] = 3 * row;
        o3[2] = 3 * (row - 1);
        o3[3] = -3;
        o3[4] = -3 * (row + 1);
        o3[5] = -3 * row;
        for (j = 0; j < 6u; j++) o3[j + 6u] = o3[j];
        for (x = 0; x + y <= m; x++, k++, l0++) { /* k = lt_vi(m, x, y), l0 = lt_vi(S, x + 1, y + 1) */
            int32_t px = ox + (int32_t)x * e1[0] + (int32_t)y * e2[0], py = oy + (int32_t)x * e1[1] + (int32_t)y * e2[1];
            uint32_t d = (lt_dir_at(g, s, (uint32_t)px, (uint32_t)py) + 6u - qrot[c]) % 6u;
            subd_loop_limit_reg6(tl->lk, M + 3u * l0, o3 + d, tl->qpos + 3u * k, tl->qnrm + 3u * k, lo);
        }
    }

}

void subd_lt_quarter(const lt_tile *tl, uint32_t c, loop_wcache *wc, uint32_t *ovf, int32_t org[2], int32_t e1[2],
                     int32_t e2[2])
{
    const lt_grid *g = &tl->g[0]; /* level depth - 1 */
    uint32_t m = 1u << (tl->depth - 1u), s = lt_side(tl->depth - 1u), x, y, lo = 0;
    int32_t im = (int32_t)m, ox, oy;
    loop_weights w = subd_loop_weights_of(wc, 6u, ovf);
    /* the quarter's corner 0 and edge directions in the last level, relative to the tile
     * face's corner 0: child c = (v_c, m_c, m_c-1), child 3 = (m0, m1, m2) */
    static const int8_t fr[4][6] = {{0, 0, 1, 0, 0, 1}, {2, 0, -1, 1, -1, 0}, {0, 2, 0, -1, 1, -1}, {1, 0, 0, 1, -1, 1}};
    org[0] = fr[c][0] * im;
    org[1] = fr[c][1] * im;
    e1[0] = fr[c][2];
    e1[1] = fr[c][3];
    e2[0] = fr[c][4];
    e2[1] = fr[c][5];
    /* grid coordinates are the tile face's plus one, and lt_point takes them plus one */
    ox = org[0] + 2;
    oy = org[1] + 2;
    if (tl->lk) {
        lt_limit_quarter(tl, c, g, s, ox, oy, e1, e2, w, &lo);
        *ovf |= lo;
        return;
    }
    for (y = 0; y <= m; y++)
        for (x = 0; x + y <= m; x++) {
            int32_t px = ox + (int32_t)x * e1[0] + (int32_t)y * e2[0], py = oy + (int32_t)x * e1[1] + (int32_t)y * e2[1];
            lt_point(g, s, (uint32_t)px, (uint32_t)py, w, tl->qpos + 3u * lt_vi(m, x, y), &lo);
        }
    *ovf |= lo;
}

void subd_lt_ids(const lt_tile *tl, const subd_mesh *in, uint32_t f, uint32_t lv, const uint32_t ca[3],
                 const uint32_t cb[3], const int32_t org[2], const int32_t e1[2], const int32_t e2[2])
{
    uint32_t m = 1u << (tl->depth - 1u), x, y, k = 0, n1 = (uint32_t)1 << lv;
    int32_t n = (int32_t)1 << tl->depth, a0, b0, ea, eb, fa, fb;
    uint64_t nm1 = n1 - 1u, base = (uint64_t)in->num_verts + (uint64_t)in->num_corners * nm1 +
                                   (uint64_t)f * (nm1 * (nm1 - 1u) / 2u);
    a0 = (int32_t)ca[0];
    b0 = (int32_t)cb[0];
    ea = ((int32_t)ca[1] - a0) / n; /* the face's edges 0 -> 1 and 0 -> 2 per last-level step */
    eb = ((int32_t)cb[1] - b0) / n;
    fa = ((int32_t)ca[2] - a0) / n;
    fb = ((int32_t)cb[2] - b0) / n;
    /* per row: (a, b) step by (da, db) (each -1, 0 or 1), and the interior closed form
     * id = r(a) + b - 1 with r(a) = base + (a - 1) nm1 - (a - 1) a / 2 follows a step of a by
     * r(a + 1) = r(a) + nm1 - a */
    for (y = 0; y <= m; y++) {
        int32_t gx = org[0] + (int32_t)y * e2[0], gy = org[1] + (int32_t)y * e2[1];
        int32_t ia = a0 + gx * ea + gy * fa, ib = b0 + gx * eb + gy * fb;
        int32_t da = e1[0] * ea + e1[1] * fa, db = e1[0] * eb + e1[1] * fb;
        int64_t r = (int64_t)base + ((int64_t)ia - 1) * (int64_t)nm1 - ((int64_t)ia - 1) * (int64_t)ia / 2;
        for (x = 0; x + y <= m; x++, k++) {
            uint32_t a = (uint32_t)ia, b = (uint32_t)ib;
            uint64_t id;
            if (a >= 1u && b >= 1u && a + b < n1) /* vertex_id's face interior */
                id = (uint64_t)(r + (int64_t)b - 1);
            else
                id = subd_lp_vertex_id(in, f, a, b, lv);
            tl->qid[2u * k] = (uint32_t)id;
            tl->qid[2u * k + 1u] = (uint32_t)(id >> 32);
            if (da > 0)
                r += (int64_t)nm1 - ia;
            else if (da < 0)
                r -= (int64_t)nm1 - (ia - 1);
            ia += da;
            ib += db;
        }
    }
}
