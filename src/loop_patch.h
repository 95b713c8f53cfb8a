/* SPDX-License-Identifier: MIT */
/* Private interface of the streaming Loop files: a patch is one level of a control face's
 * depth-first refinement, the 1-ring of its current face (the "centre") with local 16-bit
 * indices, its faces sorted by their index in subd_loop's level and each face's corners in
 * that level's order (so local half-edge comparisons are global ones). loop_patch.c builds
 * the control level's patch, computes a patch's refined values (its corners' vertex points
 * and the edge points of every edge at them: the cache, by loop_rules.h's rules) and
 * extracts a child's 1-ring; loop_stream.c lays the levels out, walks them depth first and
 * emits triangles. */
#ifndef SUBD_LOOP_PATCH_H
#define SUBD_LOOP_PATCH_H
#include "loop_rules.h"
#include "mesh_internal.h" /* tri_next, tri_prev */

#define LP_TW_NONE 0xffffu   /* no twin: a boundary edge                        */
#define LP_TW_BORDER 0xfffeu /* the twin face is outside the patch              */
#define LP_NO_SLOT 0xffffu
/* Sharpness of a patch half-edge, by topo_edge_sharp: since that is the one rule for a level
 * and for its children alike, the two bits are set together (loop_stream.c reads both). */
#define LP_SH_RULE 1u  /* sharp for this level's rules                                   */
#define LP_SH_CHILD 2u /* sharp for its children                                         */
/* Patch vertex flags: topo.h's table (TOPO_PF_REGULAR: a regular crease vertex, the paper's
 * sharp-edge rule; TOPO_PF_CORNER: the caller's CORNER tag; TOPO_PF_SMOOTH6: levels >= 1,
 * smooth (or dart) of valence 6, the class inherited as loop.c's TOPO_VTAG_SMOOTH: one walk
 * of six steps, no classification). */

/* Level header, in the arena (32-bit fields only: the same plan on host and device). */
typedef struct sp_head {
    uint32_t nv, nf, nc; /* vertices, faces, cached values                              */
    uint32_t cf;         /* the centre face (its corners are local vertices 0, 1, 2)     */
    uint32_t child;      /* next child of the centre to visit                            */
    uint32_t ca[3], cb[3]; /* lattice coordinates of the centre's corners (units 1/2^L)   */
    uint32_t nr;         /* region vertices: local 0..nr-1, whose vertex points the cache
                          * holds at slots 0..nr-1 (3: the centre's corners; a window: 6)   */
} sp_head;

enum { A_POS, A_VFLAG, A_VOUT, A_CV, A_TW, A_SLOT, A_SH, A_CPOS, A_CFLAG, A_CFACE, A_CVERT, A_N };

/* One level's arrays. */
typedef struct sp_level {
    sp_head *h;
    subd_real *pos;  /* 3 nv                                                          */
    uint8_t *vflag;  /* nv: TOPO_PF_*                                                 */
    uint16_t *vout;  /* nv: ring start (only the centre's corners are used)            */
    uint16_t *cv;    /* 3 nf: local vertex of each corner                              */
    uint16_t *tw;    /* 3 nf: local twin, LP_TW_NONE or LP_TW_BORDER                   */
    uint16_t *slot;  /* 3 nf: the cached value of the half-edge's new vertex, or LP_NO_SLOT */
    uint8_t *sh;     /* 3 nf: LP_SH_*                                                  */
    subd_real *cpos; /* 3 nc: slots 0..2 the corners' vertex points, then edge points  */
    uint8_t *cflag;  /* nc: the TOPO_PF_* of each cached vertex at the next level           */
    uint32_t *cface; /* level 0: the input face of each local face                      */
    uint32_t *cvert; /* level 0: the input vertex of each local vertex                  */
} sp_level;

/* Faces, vertices and cached values of a level whose three corner valences sum to s. */
static inline uint32_t cap_f(uint32_t s) { return s - 2u; }
static inline uint32_t cap_v(uint32_t s) { return s - 3u; }

/* A level's arrays for corner valence sum s (offsets into its block; returns its bytes);
 * `cache`: with the refined values; `control`: with the input face and vertex of each local
 * element. SUBD_LOOP_SLEV_ in subd_loop.h is the same sum. */
uint32_t subd_lp_level_layout(uint32_t s, int cache, int control, uint32_t off[A_N]);
/* Points level lv's arrays into block b at the offsets subd_lp_level_layout gave (the
 * header lv->h is the caller's). */
void subd_lp_level_bind(uint8_t *b, const uint32_t *off, sp_level *lv);

/* Level 0 for input face f: every face around its corners, sorted; corners 0..2 are f's. */
void subd_lp_build_control(const subd_mesh *in, uint32_t f, const sp_level *p, uint32_t levels);

/* Vertex point of centre corner v (0..2), by loop.c's walk and rules. next = 0: of the
 * patch's level (from its positions; *child, if not NULL, gets the flags of v's child);
 * next = 1: of the level below, from the cache (v's child keeps v's ring shape). */
void subd_lp_vertex_point(const sp_level *p, uint32_t v, int next, loop_wcache *wc, uint32_t *ovf, subd_real *out,
                          uint8_t *child);

/* The patch's one-ring iterator (subd_lp_ring below describes the walk): one home for the
 * patch (loop_patch.c) and its children's extraction (loop_patch_child.c). */
typedef struct sp_ring {
    uint32_t h0, h, steps, tail;
} sp_ring;

static inline void sp_ring_begin(const sp_level *p, uint32_t v, sp_ring *it)
{
    it->h0 = it->h = p->vout[v];
    it->steps = 0;
    it->tail = 0;
}

/* Next neighbour (SUBD_NONE at the end); *he: a half-edge of the edge to it. */
static inline uint32_t sp_ring_step(const sp_level *p, sp_ring *it, uint32_t *he)
{
    uint32_t h = it->h, pr, t, nb;
    if (h == SUBD_NONE) return SUBD_NONE;
    *he = h;
    if (it->tail) {
        it->h = SUBD_NONE;
        return p->cv[h];
    }
    nb = p->cv[tri_next(h)];
    pr = tri_prev(h);
    t = p->tw[pr];
    if (t == LP_TW_NONE) {
        it->h = pr;
        it->tail = 1;
    } else if (t == it->h0 || t == LP_TW_BORDER || ++it->steps >= 3u * p->h->nf) {
        it->h = SUBD_NONE; /* a border cannot occur at a centre corner: the bound is a guard */
    } else {
        it->h = t;
    }
    return nb;
}


/* The lower half-edge of h's edge (the one loop.c makes the edge's new vertex at). */
static inline uint32_t lower_of(const sp_level *p, uint32_t h)
{
    uint32_t t = p->tw[h];
    return (t < LP_TW_BORDER && t < h) ? t : h;
}

/* The ring of patch vertex v (a centre corner) as the patch's walk sees it: neighbours into
 * nbr, the half-edge of each edge into he (for the tail the incoming boundary half-edge), at
 * most max of each; returns the valence. For the test that holds the walk equal to
 * topo_ring. */
uint32_t subd_lp_ring(const sp_level *p, uint32_t v, uint32_t *nbr, uint32_t *he, uint32_t max);

/* The cache: slots 0..nr-1 the region vertices' vertex points (nr = 3: the centre's
 * corners), then one slot per edge at a region vertex (`all`), or only the centre's three
 * edges. */
void subd_lp_fill_cache(const sp_level *p, subd_loop_boundary rule, int all, loop_wcache *wc, uint32_t *ovf);

/* Level k+1 (q) = the 1-ring of child c of level k's (p) centre; smap (one entry per cached
 * value) is scratch, fmap (4 per parent face) holds LP_NO_SLOT on entry and on return. */
void subd_lp_extract_child(const sp_level *p, const sp_level *q, uint32_t c, uint16_t *smap, uint16_t *fmap);
/* Lattice coordinates of child c's corners (units 1/2^L) from its parent's header ph. */
void subd_lp_child_lattice(const sp_head *ph, uint32_t c, uint32_t ca[3], uint32_t cb[3]);

/* The window: level k+1 (q) = the union of the 1-rings of all four children of level k's (p)
 * centre, each vertex once (the children's corners are its region vertices 0..5: the
 * centre's corners' children 0..2, then the new vertices of the centre's edges 0..2), its
 * faces sorted as a patch's, so the four children are consecutive faces from q->h->child
 * on (a window's `child` field); after subd_lp_fill_cache(q, all) a two-level emitter runs on
 * each child in turn (q->h->cf and ca, cb set to the child's), so the four share their
 * values. Its block: subd_lp_window_layout, for p's corner valence sum s (faces, vertices
 * and cached values); smap and fmap as subd_lp_extract_child's. */
uint32_t subd_lp_window_layout(uint32_t s, uint32_t off[A_N]);
void subd_lp_extract_window(const sp_level *p, const sp_level *q, uint16_t *smap, uint16_t *fmap);
/* ------------------------------------------------------------------------------------ */
/* The Loop streams' shared pieces (loop_stream.c, loop_adapt.c): limit mode's mesh view,   */
/* the closed-form vertex ids, the input's largest valence.                                */

struct subd_layout;
/* The arrays of a subd_mesh view of a level with corner valence sum s (counted or carved by
 * layout.h's walk; SUBD_LOOP_SVIEW_ is the same sum). */
void subd_lp_view_take(struct subd_layout *y, uint32_t s, subd_mesh *w);
/* Fills view m (arrays from subd_lp_view_take) with level p as a subd_mesh for
 * subd_loop_limit_vertex: the centre's corners 0..2 have whole rings and their vert_out; an
 * outer vertex's class is given by LOOP_VTAG_KNOWN. */
void subd_lp_view_fill(const sp_level *p, subd_mesh *m);
/* Global id of lattice point (a, b) (units 1/2^levels) of input face f: subd_loop.h's formula
 * for the Loop streams. */
uint64_t subd_lp_vertex_id(const subd_mesh *in, uint32_t f, uint32_t a, uint32_t b, uint32_t levels);
/* The interior ids' constant part for face f (V + C (N - 1) + f (N - 1)(N - 2)/2). */
static inline uint64_t subd_lp_id_base(const subd_mesh *in, uint32_t f, uint32_t levels)
{
    uint64_t nm1 = ((uint64_t)1 << levels) - 1u;
    return (uint64_t)in->num_verts + (uint64_t)in->num_corners * nm1 + (uint64_t)f * (nm1 * (nm1 - 1u) / 2u);
}
/* subd_lp_vertex_id with the face interior's closed form tried first (base:
 * subd_lp_id_base), for the emitters, most of whose points lie inside the control face. */
static inline uint64_t subd_lp_vertex_id_b(const subd_mesh *in, uint32_t f, uint32_t a, uint32_t b, uint32_t levels,
                                           uint64_t base)
{
    uint32_t n1 = (uint32_t)1 << levels;
    if (a - 1u < n1 - 1u && b - 1u < n1 - 1u && a + b < n1) {
        uint64_t am = a - 1u;
        return base + am * (n1 - 1u) - am * (am + 1u) / 2u + (b - 1u);
    }
    return subd_lp_vertex_id(in, f, a, b, levels);
}
/* Largest valence of the input (outgoing half-edges, plus one on a boundary). */
uint32_t subd_lp_max_valence(const subd_mesh *in);
/* Level k's arrays in a Loop stream's layout (loop_stream.c, loop_adapt.c): level 0's block
 * lev0 at offsets off0, level k >= 1's the (k-1)-th block of size1 bytes from lev1 at offsets
 * off1, the header head[k]. */
static inline void subd_lp_level_at(sp_head *head, uint8_t *lev0, uint8_t *lev1, uint32_t size1, const uint32_t *off0,
                                    const uint32_t *off1, uint32_t k, sp_level *lv)
{
    lv->h = head + k;
    subd_lp_level_bind(k == 0u ? lev0 : lev1 + (k - 1u) * size1, k == 0u ? off0 : off1, lv);
}
#endif
