/* SPDX-License-Identifier: MIT */
/* Private interface of the Loop stream's two files: loop_stream.c (the layout, the plan, the
 * depth-first walk and its pull-form driver) and loop_stream_emit.c (the emitters of the
 * general path and the regular tiles' hand-off to the sink), which share the one level
 * layout, the run state and the walk's position in it. loop_stream.c's header comment gives
 * the method, the bit-identity argument and the memory. */
#ifndef SUBD_LOOP_STREAM_INTERNAL_H
#define SUBD_LOOP_STREAM_INTERNAL_H
#include "loop_internal.h"
#include "loop_patch.h"
#include "loop_tile.h"
#include "stream_internal.h"

/* The blocks stream_layout takes (NULL when it only counts). A level's own arrays are an
 * offset table inside its block (off0, off1 from level_layout) rather than carved: the
 * same table addresses every level block of its size, and level_at re-addresses a level
 * at each visit of the depth-first walk (several times per emitted batch), so the offsets
 * are computed once. It is the same idea as a carving walk: one function (level_layout)
 * computes every offset, and plan and run both get them from stream_layout. */
/* The arrays of limit mode's subd_mesh view of level L (the rest of the mesh is filled at
 * each use; only the arrays live in the run state). */
typedef struct sp_view {
    uint32_t *face_start, *corner_vert, *corner_face, *twin, *vert_out;
    uint8_t *vert_tag, *edge_tag;
} sp_view;

/* Limit mode's masks, kept for the whole stream: loop_limit.c's caches (chi and the trig
 * table once per valence, not per vertex) and the tiles' valence-6 masks. A block of
 * SUBD_LOOP_SMASK_ bytes in the arena (a fixed size: the plan is the same for both
 * arithmetics, whose lim_w differ). */
typedef struct sp_masks {
    lim_cache lc;
    lim_reg6 lk;
} sp_masks;
typedef char sp_masks_fit[sizeof(sp_masks) <= SUBD_LOOP_SMASK_ ? 1 : -1];

typedef struct sp_layout {
    uint32_t n;         /* the largest valence, at least 6                                */
    uint32_t off0[A_N]; /* level 0's arrays, inside lev0                                   */
    uint32_t off1[A_N]; /* a later level's arrays, inside its block of size1               */
    sp_head *head;      /* L + 1 level headers                                             */
    uint8_t *lev0;      /* level 0's block                                                 */
    uint8_t *lev1;      /* levels 1, 2, ...: blocks of size1 bytes, one after the other     */
    union {             /* one mode's or the other's (the run state has room for one)     */
        sp_view view;   /* limit mode: level L's patch as a subd_mesh (arrays only) for
                         * loop_limit.c's masks                                             */
        uint32_t offw[A_N]; /* plain mode from 3 levels: the window's arrays, inside level
                             * L-2's block (loop_stream.c's window_layout)                 */
    } m;
    uint16_t *smap, *fmap; /* one extraction's slot map and child-face map                */
    uint8_t *tile;         /* the region of the regular tiles' blocks (loop_tile.h), when
                            * tdepth >= 2: it shares memory with the levels from tk on    */
    uint8_t *tab;          /* the tiles' emission tables (depths 2..lt_table_depth)        */
    sp_masks *mk;          /* limit mode: the limit masks' caches                          */
    uint32_t tdepth;       /* levels a tile at level tk refines (tile_depth); 0: none      */
    uint32_t tk;           /* the first level with tiles: L - tdepth                       */
    uint32_t size1, total;
} sp_layout;

/* Block index of level k in the level blocks (level 0 has its own block, lev0; a tile at
 * level 0 starts where level 1's block does). */
static inline uint32_t tile_bi(uint32_t k) { return k ? k - 1u : 0u; }

/* The block of a tile at level k >= tk (depth L - k): level k's own block, which the tile
 * may overwrite (subd_lt_start reads the patch first) with the deeper levels', idle while it
 * is made and emitted; levels tk..k-1 above it are live (their next children). */
static inline uint32_t tile_off(const sp_layout *l, uint32_t k) { return (tile_bi(k) - tile_bi(l->tk)) * l->size1; }

/* Level k's arrays (loop_patch.h's subd_lp_level_at on the stream's layout). */
static inline void level_at(const sp_layout *l, uint32_t k, sp_level *lv)
{
    subd_lp_level_at(l->head, l->lev0, l->lev1, l->size1, l->off0, l->off1, k, lv);
}

/* One control face's run: where its triangles go. */
typedef struct sp_run {
    const subd_mesh *in;
    const subd_loop_opts *o;
    subd_stream_q *q; /* where this batch's triangles go (stream_internal.h) */
    uint32_t f;
} sp_run;


/* The run state, in the arena's fixed SUBD_STREAM_STATE_BYTES block. The walk's position is
 * (run.f, k, started) plus each level header's `child`, which are in the arena already. */
typedef struct sp_state {
    subd_stream_impl impl; /* first: stream.c's view of the state */
    subd_stream_ring ring;
    sp_layout lay;
    sp_run run;
    subd_loop_opts o;
    loop_wcache wc;
    uint32_t k, depth, ovf, limit;
    /* the regular tile: at level k >= lay.tk, of depth tdep = L - k; ton while its triangles
     * go out: piece tq (a quarter, or limit mode's depth 5 a quarter's child: lt_split), its
     * triangle tj, tready once the piece's positions and ids are made */
    uint32_t tdep, tq, tj;
#if SUBD_FIXED
    subd_real tmove[3]; /* the tile's move (beyond 2 048.0: subd_lt_start's org)        */
#endif
    uint32_t ntile[4]; /* tiles made so far, by depth 2..5 (subd_lt_stream_count) */
    uint32_t nwin;     /* windows made so far (subd_ls_stream_windows)                 */
    /* flags, bytes: the state block is full (SUBD_STREAM_STATE_BYTES) */
    uint8_t started, ton, tready;
    uint8_t idwide; /* some id of the stream may reach 2^32: the tiles' push loop reads
                     * their high words (loop_stream_emit.c); else they are zero     */
} sp_state;
SUBD_STREAM_STATE_FITS(sp_state);
/* The tile's move for subd_lt_start / subd_lt_quarter (float32 tiles are never moved). */
#if SUBD_FIXED
#define LS_TMOVE(s) ((s)->tmove)
#else
#define LS_TMOVE(s) ((subd_real *)0)
#endif

/* The emitters (loop_stream_emit.c). Each returns 0, SUBD_ERR_RANGE (overflow, fixed point)
 * or the sink's value. The centre's four children at the last level (one level in all), from
 * p's cache. */
int subd_ls_emit_children(const sp_run *r, const sp_level *p);
/* What a window's four children share when they go out in one step (the push form): the
 * level-L vertex points of the new vertices m0..m2 of the window's parent centre's edges
 * (mve: each a corner of two corner children and of the middle child; have: bit i, mve[i]
 * made) and the points on the middle child's edges (evm, eh1, eh2 as emit_grandchildren's
 * vm, h1, h2; its edge j = m_j -> m_j+1 is corner child j + 1's inner edge, reversed). */
typedef struct sp_gcshare {
    subd_real mve[3][3], evm[3][3], eh1[3][3], eh2[3][3];
    uint32_t have;
} sp_gcshare;

/* The last two levels at once: the 16 level-L triangles of level L-2's centre (p), from its
 * cache and its topology. sh: NULL, or a window's share, p's centre being the window's child
 * c, whose points the children before it made are taken from sh (and its own put there). */
int subd_ls_emit_grandchildren(const sp_run *r, const sp_level *p, sp_gcshare *sh, uint32_t c, loop_wcache *wc,
                               uint32_t *ovf);
/* Limit mode: the centre of level L's patch, its corners moved to the limit with their unit
 * normals (loop_limit.c's masks on lay's mesh view). */
int subd_ls_emit_limit(const sp_run *r, const sp_level *p, const sp_layout *lay, lim_cache *lc, uint32_t *ovf);
/* The regular tile at level s->k: its triangles piece by piece, from where the last call
 * stopped; s->ton stays set when the caller's buffer is full. */
int subd_ls_tile_emit(sp_state *s, subd_stream_q *q);
/* The windows (loop_patch.h) a Loop stream has made so far: for the tests, which check that
 * the window path is taken. */
uint32_t subd_ls_stream_windows(const subd_stream *h);
/* Makes a running Loop stream read its tile ids' high words as a stream whose ids reach 2^32
 * does (a mesh that large does not fit a test): for the tests of that path. */
void subd_ls_stream_wide_ids(subd_stream *h);
#endif
