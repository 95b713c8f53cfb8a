/* SPDX-License-Identifier: MIT */
/* Private interface of streaming Loop's regular tiles (loop_tile.c): where the 1-ring patch of
 * a face is regular (its three corners smooth, valence 6, interior, no sharp edge), the last
 * levels are refined breadth first on a triangular grid (index arithmetic, no topology), each
 * vertex once, bit-identical to subd_loop (the ring starts and the lower sides of subd_loop's
 * levels are carried into the grid: see loop_tile.c). loop_stream.c decides where a tile
 * starts, holds its memory in the stream's layout and emits its triangles. */
#ifndef SUBD_LOOP_TILE_H
#define SUBD_LOOP_TILE_H
#include "loop_patch.h"
#include "loop_limit_internal.h"

/* Grid of level t of a tile: the 1-ring of the tile's face refined t times, a triangle of side
 * 2^t + 3 (less its three corners) in lattice coordinates (i, j), i + j <= side, vertex
 * (i, j) at row start(j) + i. Up triangle U(i, j) = (i, j), (i+1, j), (i, j+1); down triangle
 * D(i, j) = (i+1, j), (i+1, j+1), (i, j+1); both are indexed like vertex (i, j). */
typedef struct lt_grid {
    subd_real *pos; /* 3 per vertex                                                         */
    uint8_t *dir;   /* ring start of each vertex: lattice direction 0..5 of its vert_out     */
    uint8_t *rot;   /* 2 per index: U's and D's rotation (which lattice corner is corner 0)  */
    uint8_t *low;   /* per U: bit d set when U's half-edge d is its edge's lower half-edge   */
} lt_grid;

/* One vertex of the last level's piece (a quarter: lt_split) as the emission loop reads it: its position and
 * its id's low word side by side, four words, so that a triangle corner is one address
 * (index times 16) and one load of four words. The high words are an array of their own
 * (lt_tile's qhi), read only when a stream's ids reach 2^32 (loop_stream_emit.c). */
typedef struct lt_rec {
    subd_real p[3];
    uint32_t id;
} lt_rec;
typedef char lt_rec_is_4_words[sizeof(lt_rec) == 4u * sizeof(subd_real) ? 1 : -1];
/* Bytes of a piece vertex in a tile's block: its record and its id's high word (the 20 of
 * SUBD_LOOP_TILE_BYTES_). */
#define LT_REC_BYTES ((uint32_t)sizeof(lt_rec) + 4u)

/* A tile of depth t (2 <= t <= SUBD_LOOP_TILE_LEVELS): levels 0..t-1 in two grids used in
 * turn, then the last level one piece (a quarter, a child of the tile's face at level 1, or
 * in limit mode's depth 5 a quarter's child: lt_split) at a time: its vertices' positions
 * and ids (q, qhi: plain mode in the second grid's memory, dead by then) and the emission order
 * of its triangles (tab: 3 piece-vertex indices per triangle, subd_loop's depth-first order;
 * filled once per stream by subd_lt_table). */
typedef struct lt_tile {
    lt_grid g[2];
    lt_rec *q;
    uint32_t *qhi; /* the high words of q's ids, after q's records (LT_REC_BYTES)          */
    uint8_t *tab;
    uint32_t depth;
    uint32_t split; /* lt_split: the last level is made by faces of level split (pieces)     */
    /* limit mode (lk set by the caller after subd_lt_carve): q's positions and qnrm are the
     * piece's limit positions and unit normals, from its quarter's last-level positions
     * with a one-vertex margin (mpos: a grid of side 2^(t-1) + 3 in the quarter's frame, in
     * the second grid's memory); else qnrm is NULL and q's positions the last level's. */
    subd_real *qnrm, *mpos;
    const lim_reg6 *lk;
} lt_tile;

enum { LT_APOS, LT_ADIR, LT_AROT, LT_ALOW, LT_BPOS, LT_BDIR, LT_BROT, LT_BLOW, LT_QREC, LT_LNRM, LT_N };

/* The last level of a tile of depth t is made (and emitted) one piece at a time, a piece a
 * face of level lt_split (1: a quarter, 4 pieces; 2: a quarter's child, 16 pieces) of the
 * tile's face, of side 2^(t - lt_split) at the last level. Limit mode's depth 5 takes 2: its
 * pieces' limit records and normals and their emission table are then a depth-4 quarter's
 * (the plan's 16 KiB at 8 levels and valence 16 holds a depth-5 tile only so); the
 * quarter's last-level positions with margin (mpos) are still made once per quarter, for its
 * four pieces. SUBD_LOOP_TPD_ in subd_loop.h is lt_table_depth. */
static inline uint32_t lt_split(uint32_t t, int limit) { return limit && t >= 5u ? 2u : 1u; }
/* Depth whose emission table a tile of depth t uses (its pieces are that depth's quarters). */
static inline uint32_t lt_table_depth(uint32_t t, int limit) { return t + 1u - lt_split(t, limit); }

/* Vertices of a triangular grid of side s. */
static inline uint32_t lt_count(uint32_t s) { return (s + 1u) * (s + 2u) / 2u; }
/* Vertex (i, j) of a grid of side s. */
static inline uint32_t lt_vi(uint32_t s, uint32_t i, uint32_t j) { return j * (2u * s + 3u - j) / 2u + i; }

/* The arrays of a tile of depth t (limit: limit mode's too) as offsets in its block (off may
 * be NULL; returns its bytes), all but the emission tables, which have their own block
 * (subd_lt_tab_bytes: the tables of depths 2..t one after the other, for a tile of depth
 * t and the smaller tiles below it): the block is scratch while the tile is made and
 * emitted (the stream lends it the idle deeper levels' memory), the tables are filled once
 * per stream. The SUBD_LOOP_TILE_BYTES_ and SUBD_LOOP_TTAB_ sums in subd_loop.h are the
 * same. */
uint32_t subd_lt_layout(uint32_t t, int limit, uint32_t off[LT_N]);
uint32_t subd_lt_tab_bytes(uint32_t t);
/* The arrays of a tile of depth t in its block (subd_lt_layout's offsets) and its table in
 * the tables' block tab (may be NULL: no table); lk = NULL. */
void subd_lt_carve(lt_tile *tl, uint8_t *block, uint8_t *tab, uint32_t t, int limit);
/* Fills the emission table of a piece (4^(t-split) triangles). */
void subd_lt_table(const lt_tile *tl);
/* Level 0 of a tile from patch p (its centre's 1-ring): 1 when p is regular (then levels
 * 1..t-1 are refined too), 0 when it is not (nothing useful is written). org: Q16.16, the
 * move of a patch beyond the 32-bit sums' range (loop_tile.c's lt_move; zeros otherwise), for
 * subd_lt_quarter; float32: unused (may be NULL). */
int subd_lt_start(lt_tile *tl, const sp_level *p, loop_wcache *wc, uint32_t *ovf, subd_real org[3]);
/* The last level's positions of piece c (0..4^split - 1, lt_split: with split 1 quarter c,
 * child c of the tile's face at level 1, subd_loop's child order; with split 2 child c % 4
 * of quarter c / 4; the pieces must be made in order, as a quarter's last-level positions
 * with margin are made at its first piece) into q (limit mode: their limit positions, and
 * normals into qnrm), in the piece's own frame (corner k of the child at lattice corner k
 * of the piece grid), moved back by T (subd_lt_start's org; float32: unused, may be NULL);
 * *org, *e1, *e2: its frame in
 * the tile's last level (grid coordinates relative to the tile face's corner 0), for the
 * ids. */
void subd_lt_quarter(const lt_tile *tl, uint32_t c, loop_wcache *wc, uint32_t *ovf, const subd_real T[3], int32_t org[2],
                     int32_t e1[2], int32_t e2[2]);
/* Bounds of x from c x + d >= 0 (c in -1, 0, 1) narrowing [*a, *b] (empty: *b < *a); the
 * rows of a lattice region (loop_tile.c) and of a piece's ids (loop_tile_ids.c). */
static inline void lt_bound(int32_t c, int32_t d, int32_t *a, int32_t *b)
{
    if (c > 0) {
        if (-d > *a) *a = -d;
    } else if (c < 0) {
        if (d < *b) *b = d;
    } else if (d < 0) {
        *b = *a - 1;
    }
}
/* The ids of piece c's vertices into q (frame org, e1, e2 from subd_lt_quarter) of the
 * tile in control face f whose face has lattice corners (ca[k], cb[k]) at level lv (units
 * 1/2^lv, loop_patch.h's sp_head): a point inside the control face by subd_lp_vertex_id's
 * closed form, stepped along each row, the others by subd_lp_vertex_id (loop_tile_ids.c). */
void subd_lt_ids(const lt_tile *tl, const subd_mesh *in, uint32_t f, uint32_t lv, const uint32_t ca[3],
                 const uint32_t cb[3], const int32_t org[2], const int32_t e1[2], const int32_t e2[2]);
/* A region of level t + 1 points and where they go: the points (px, py) = O + x e1 + y e2
 * (level t + 1's coordinates plus one: the point halves (px, py) of level t's grid) with x, y >= lo, x + y <= hi (less the
 * region's three corners when `skip`), point (x, y) written to vertex (x - lo, y - lo) of a
 * grid of side hi - 2 lo, ds subd_reals per vertex (3: a grid's positions; 4: the quarter's
 * records, lt_rec). e1 = (p, q), e2 = (r, u): lattice directions of determinant 1. */
typedef struct lt_frame {
    int32_t ox, oy, p, q, r, u, lo, hi, ds;
    int skip;
} lt_frame;

/* The six neighbours of a grid vertex in a row of length `row`, as offsets in subd_reals
 * (+1, +row, +row - 1, -1, -(row + 1), -row: lt_row's index rules), twice over so that the
 * six from any ring start are consecutive. */
TOPO_INLINE void lt_ring_offsets(int32_t row, int32_t o3[12])
{
    int32_t i;
    o3[0] = 3;
    o3[1] = 3 * row;
    o3[2] = 3 * (row - 1);
    o3[3] = -3;
    o3[4] = -3 * (row + 1);
    o3[5] = -3 * row;
    for (i = 0; i < 6; i++) o3[i + 6] = o3[i];
}

/* Whether a rule's products go in subd_loop's order: float32 sums round at each step, so the
 * ring start of a vertex and the lower side of an edge matter; Q16.16 sums are exact (a
 * 64-bit sum of products: subd_real.h), so any order gives the same bits, and a tile there
 * starts every ring in direction 0, takes every edge from its up triangle's side and carries
 * no ring starts, rotations or lower sides (subd_lt_start). */
#define LT_ORDERED (!SUBD_FIXED)

/* The points of a region (loop_tile_rows.c: by rows of g's lattice, each by the rule of
 * its kind, subd_loop's bits) from grid g (side s) into out: any frame fr (limit mode's
 * quarters with their margin); the next level's grid (side 2s - 3, less its three corners:
 * lt_refine); plain mode's quarter c into the records (subd_lt_quarter's frame, its corner 0
 * at (ox, oy) in g's coordinates plus one, side hi). The last two take their frames as
 * constants. */
void subd_lt_rows(const lt_grid *g, uint32_t s, const lt_frame *fr, subd_real *out, loop_weights w);
void subd_lt_rows_refine(const lt_grid *g, uint32_t s, int32_t hi, subd_real *out, loop_weights w);
void subd_lt_rows_quarter(const lt_grid *g, uint32_t s, uint32_t c, int32_t ox, int32_t oy, int32_t hi, subd_real *out,
                          loop_weights w);
/* Tiles of depth t (2..5) a running Loop stream h (subd_loop_stream_begin) has made so far:
 * for the tests that count which path the stream took (loop_stream.c). */
uint32_t subd_lt_stream_count(const subd_stream *h, uint32_t t);
#endif
