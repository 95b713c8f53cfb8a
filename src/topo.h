/* SPDX-License-Identifier: MIT */
/* Topology helpers with one home (private): the idioms every scheme walks a mesh with, written
 * once next to the mesh (mesh.c, mesh_internal.h) and tested on their own (test/test_topo.c)
 * against brute-force computations.
 *   - topo_ring: the ordered one-ring walk that also yields the boundary "tail" neighbour.
 *   - subd_topo_has: does this mesh carry the arrays (the adjacency) this call needs.
 *   - topo_edge_sharp: the one sharp-edge rule.
 *   - Loop's 1->4 child tables (corner order, vert_out of a child vertex, outer twins).
 *   - The table of the library's private tag bits.
 * No paper: these are the conventions of subd.h's half-edge mesh. A fast path kept for speed
 * is a documented specialisation of the helper here, and a test holds it equal to the helper
 * on the same input: topo_tri_fan_step (loop.c's smooth vertices) lives here;
 * loop_patch.c's 16-bit patch walk lives with its patch. */
#ifndef SUBD_TOPO_H
#define SUBD_TOPO_H
#include "subd.h"
#include "mesh_internal.h" /* tri_next, tri_prev */

/* The walk's steps are forced inline (GCC, clang): inlined next to topo_ring_begin_tri, the
 * face lookups fold away (r->fs is a known null) and the iterator lives in registers; left
 * to its heuristics, gcc -O2 keeps topo_ring_step out of line in quasi48.c and edge_sort.c,
 * which cost quasi 4-8 ~8% more instructions than its own walk before topo.h. */
#if defined(__GNUC__)
#define TOPO_INLINE static inline __attribute__((always_inline))
#else
#define TOPO_INLINE static inline
#endif

/* ------------------------------------------------------------------------------------ */
/* Private tag bits: the one table.                                                       */
/*                                                                                        */
/* subd.h reserves vert_tag bits 0x40 and 0x80 for the library (a caller's mesh must have   */
/* them 0: subd_loop_tags_public). The kinds of mesh that carry them never meet, so a bit   */
/* may mean one thing on each:                                                             */
/*   bit   loop.c's intermediate levels      loop_stream.c's patch views (read by loop_limit.c) */
/*   0x80  TOPO_VTAG_REGULAR: a regular crease vertex (loop_rules.h's "regular")  -- both    */
/*   0x40  TOPO_VTAG_SMOOTH: smooth interior,  TOPO_VTAG_KNOWN: the class is given by the    */
/*         valence in the level's val array     REGULAR bit; do not walk the (cut) ring      */
/* loop.c reads a level's private bits only on levels it made, never on a caller's input.  */
/* The patch vertex flags of loop_patch.h (a byte per patch vertex, not a vert_tag) use the */
/* same bits for the same ideas, plus the caller's corner bit where subd.h has it:          */
/*   TOPO_PF_REGULAR = TOPO_VTAG_REGULAR, TOPO_PF_SMOOTH6 = TOPO_VTAG_SMOOTH (valence 6),    */
/*   TOPO_PF_CORNER = SUBD_VTAG_CORNER.                                                     */
/* Edge tags: the library keeps no private edge bit in a finished mesh; a pass may use      */
/* TOPO_ETAG_VISITED (0x80) for the duration of one walk (boundary loops) and clears it.    */
#define TOPO_VTAG_REGULAR 0x80u
#define TOPO_VTAG_SMOOTH 0x40u
#define TOPO_VTAG_KNOWN 0x40u
#define TOPO_VTAG_PRIVATE (TOPO_VTAG_REGULAR | TOPO_VTAG_SMOOTH)
#define TOPO_PF_REGULAR TOPO_VTAG_REGULAR
#define TOPO_PF_SMOOTH6 TOPO_VTAG_SMOOTH
#define TOPO_PF_CORNER SUBD_VTAG_CORNER
#define TOPO_ETAG_VISITED 0x80u

/* ------------------------------------------------------------------------------------ */
/* Adjacency check                                                                        */

/* The arrays a call needs (subd_topo_has's `need`), and when: by default an array is needed
 * when the count it is sized by is non-zero (num_verts for pos, vert_out and vert_tag;
 * num_corners for corner_vert, corner_face, twin and edge_tag; face_start has num_faces + 1
 * entries and is always needed); TOPO_IF_FACES: only when the mesh has faces;
 * TOPO_ALWAYS: whatever the counts. The guards are those the calls had before this helper
 * (their statuses on an empty mesh stay as they were). */
#define TOPO_POS 0x001u
#define TOPO_FACE_START 0x002u
#define TOPO_CORNER_VERT 0x004u
#define TOPO_CORNER_FACE 0x008u
#define TOPO_TWIN 0x010u
#define TOPO_VERT_OUT 0x020u
#define TOPO_VERT_TAG 0x040u
#define TOPO_EDGE_TAG 0x080u
#define TOPO_IF_FACES 0x100u
#define TOPO_ALWAYS 0x200u

/* 1 when m is not NULL and carries every array `need` names (under its guard), else 0. The
 * caller turns 0 into its own status (SUBD_ERR_PARAM for the schemes). */
int subd_topo_has(const subd_mesh *m, uint32_t need);

/* ------------------------------------------------------------------------------------ */
/* The sharp-edge rule                                                                    */

/* An edge is sharp when it has no twin (a boundary edge) or when EITHER of its half-edges
 * carries SUBD_ETAG_CREASE (subd_edge_tag_set tags both, but a caller writing edge_tag
 * directly may tag one; the edge is one edge whichever half is asked). SUBD_ETAG_BOUNDARY
 * is not read: the builder derives it from the twin, and a stray BOUNDARY bit on an
 * interior half-edge does not make it sharp. Every scheme that honours creases asks this
 * (Loop, its limit, progressive interpolation, quasi 4-8). */
static inline int topo_edge_sharp(const uint32_t *twin, const uint8_t *etag, uint32_t h)
{
    uint32_t t = twin[h];
    return t == SUBD_NONE || ((etag[h] | etag[t]) & SUBD_ETAG_CREASE) != 0u;
}
static inline int topo_mesh_edge_sharp(const subd_mesh *m, uint32_t h)
{
    return topo_edge_sharp(m->twin, m->edge_tag, h);
}

/* ------------------------------------------------------------------------------------ */
/* The one-ring iterator                                                                  */

/* Neighbours of a vertex in ring order: the outgoing half-edges from vert_out, rotating with
 * twin(prev(h)) (counter-clockwise for counter-clockwise faces, subd_ring_next), each giving
 * its destination; when the walk ends at a half-edge without twin (a boundary vertex, whose
 * vert_out is its outgoing boundary half-edge) one more, the "tail": the origin of that
 * incoming boundary half-edge. So a boundary vertex of f faces has f + 1 neighbours, the
 * first and last along its boundary edges. Bounded by the number of half-edges whatever the
 * input. The order is the one every scheme's weighted sums are written in (bit-exact results
 * depend on it). Use:
 *     topo_ring r;
 *     topo_ring_begin(&r, m, v);
 *     while (topo_ring_step(&r)) { ... r.nb, r.he, r.tail ... }                            */
typedef struct topo_ring {
    const uint32_t *cv, *twin;
    const uint32_t *fs, *cf; /* face_start, corner_face; NULL: all triangles, face f = 3f..3f+2 */
    uint32_t nc;             /* number of half-edges: the bound                               */
    uint32_t first;          /* vert_out of the vertex                                        */
    uint32_t next;           /* next outgoing half-edge to yield, or SUBD_NONE                */
    uint32_t pend;           /* the tail's half-edge still to yield, or SUBD_NONE             */
    uint32_t steps;
    /* the current neighbour, once topo_ring_step returned 1: */
    uint32_t nb;   /* its vertex                                                             */
    uint32_t he;   /* the edge to it: v's outgoing half-edge, or for the tail the incoming
                    * boundary half-edge nb -> v                                             */
    uint32_t tail; /* 1 for the tail                                                         */
} topo_ring;

/* Walk of vertex v of mesh m (any face sizes; needs corner_vert, twin, vert_out, face_start
 * and corner_face). An isolated vertex has no neighbours. */
static inline void topo_ring_begin(topo_ring *r, const subd_mesh *m, uint32_t v)
{
    r->cv = m->corner_vert;
    r->twin = m->twin;
    r->fs = m->face_start;
    r->cf = m->corner_face;
    r->nc = m->num_corners;
    r->first = r->next = m->vert_out[v];
    r->pend = SUBD_NONE;
    r->steps = 0;
    r->nb = r->he = SUBD_NONE;
    r->tail = 0;
}

/* Walk from outgoing half-edge `first` of a triangle level given by its arrays (corner c in
 * face c / 3; nc half-edges), for the schemes' own levels that carry no face_start. */
static inline void topo_ring_begin_tri(topo_ring *r, const uint32_t *cv, const uint32_t *twin, uint32_t nc,
                                       uint32_t first)
{
    r->cv = cv;
    r->twin = twin;
    r->fs = 0;
    r->cf = 0;
    r->nc = nc;
    r->first = r->next = first;
    r->pend = SUBD_NONE;
    r->steps = 0;
    r->nb = r->he = SUBD_NONE;
    r->tail = 0;
}

TOPO_INLINE uint32_t topo_ring_prev_he(const topo_ring *r, uint32_t h)
{
    uint32_t f;
    if (!r->fs) return tri_prev(h);
    f = r->cf[h];
    return (h == r->fs[f]) ? r->fs[f + 1u] - 1u : h - 1u;
}
TOPO_INLINE uint32_t topo_ring_next_he(const topo_ring *r, uint32_t h)
{
    uint32_t f;
    if (!r->fs) return tri_next(h);
    f = r->cf[h];
    return (h + 1u == r->fs[f + 1u]) ? r->fs[f] : h + 1u;
}

/* Advances to the next neighbour: 1 with r->nb, r->he, r->tail set; 0 at the end. */
TOPO_INLINE int topo_ring_step(topo_ring *r)
{
    uint32_t h = r->next, p, t;
    if (h == SUBD_NONE) {
        if (r->pend == SUBD_NONE) return 0;
        r->he = r->pend;
        r->nb = r->cv[r->pend];
        r->tail = 1;
        r->pend = SUBD_NONE;
        return 1;
    }
    r->he = h;
    r->nb = r->cv[topo_ring_next_he(r, h)];
    r->tail = 0;
    p = topo_ring_prev_he(r, h);
    t = r->twin[p];
    if (t == SUBD_NONE) {
        r->next = SUBD_NONE;
        r->pend = p;
    } else if (t == r->first || ++r->steps >= r->nc) {
        r->next = SUBD_NONE;
    } else {
        r->next = t;
    }
    return 1;
}

/* The fast path of the walk on a triangle level (corner c in face c / 3), for a vertex known
 * to be interior whose valence n is known (loop.c's smooth vertices of the levels it made):
 * from h = vert_out, n calls yield the neighbours topo_ring_step yields, in its order, with
 * no tail, no sharpness and no end test; *h becomes the next outgoing half-edge (twin of
 * prev, SUBD_NONE past a boundary, where topo_ring would turn to its tail). One remainder
 * serves both the next and the prev corner. test_topo's topo_fan_fast holds it equal to
 * topo_ring_step on every vertex of closed, open, creased and subdivided meshes. */
TOPO_INLINE uint32_t topo_tri_fan_step(const uint32_t *cv, const uint32_t *twin, uint32_t *h)
{
    uint32_t x = *h, r = x % 3u;
    uint32_t nb = cv[r == 2u ? x - 2u : x + 1u];
    *h = twin[r == 0u ? x + 2u : x - 1u];
    return nb;
}

/* 1 when r's half-edge leads to a sharp edge (the tail's is a boundary edge). */
static inline int topo_ring_sharp(const topo_ring *r, const uint8_t *etag)
{
    return r->tail || topo_edge_sharp(r->twin, etag, r->he);
}

/* ------------------------------------------------------------------------------------ */
/* Loop's 1->4 split (loop.c's output order, used by loop_patch.c and loop_stream.c)       */

/* A triangle (v0, v1, v2) with new vertices m_i on its edges v_i -> v_{i+1} has children
 * 4f..4f+3: child i = (v_i, m_i, m_{i-1}) for i = 0, 1, 2, child 3 = (m0, m1, m2). With the
 * points numbered v0 v1 v2 m0 m1 m2 = 0..5, corner j of child k is point
 * TOPO_LOOP_CHILD_POINTS[k][j] (an initialiser: `static const uint8_t x[4][3] = ...;` where a
 * file needs the table, so no header defines an object a file might not use). */
#define TOPO_LOOP_CHILD_POINTS                                                                           \
    {{TOPO_LOOP_CP(0u, 0u), TOPO_LOOP_CP(0u, 1u), TOPO_LOOP_CP(0u, 2u)},                                  \
     {TOPO_LOOP_CP(1u, 0u), TOPO_LOOP_CP(1u, 1u), TOPO_LOOP_CP(1u, 2u)},                                  \
     {TOPO_LOOP_CP(2u, 0u), TOPO_LOOP_CP(2u, 1u), TOPO_LOOP_CP(2u, 2u)},                                  \
     {TOPO_LOOP_CP(3u, 0u), TOPO_LOOP_CP(3u, 1u), TOPO_LOOP_CP(3u, 2u)}}
/* The table's one formula, a constant expression for constant k, j (so the writers below
 * compile to straight-line stores): child i < 3 is (i, 3 + i, 3 + (i + 2) % 3), child 3 is
 * (3, 4, 5). */
#define TOPO_LOOP_CP(k, j)                                                                               \
    ((k) == 3u ? 3u + (j) : (j) == 0u ? (k) : (j) == 1u ? 3u + (k) : 3u + ((k) + 2u) % 3u)

/* The 12 child corners of a face (corner 3k + j = point TOPO_LOOP_CP(k, j) of
 * x = v0 v1 v2 m0 m1 m2), written out: the hot path of loop.c's level refinement, where a
 * loop over the table costs ~15 instructions per corner (gcc -O2 does not unroll it). */
static inline void topo_loop_child_corners(uint32_t *cv, const uint32_t x[6])
{
    cv[0] = x[TOPO_LOOP_CP(0u, 0u)];
    cv[1] = x[TOPO_LOOP_CP(0u, 1u)];
    cv[2] = x[TOPO_LOOP_CP(0u, 2u)];
    cv[3] = x[TOPO_LOOP_CP(1u, 0u)];
    cv[4] = x[TOPO_LOOP_CP(1u, 1u)];
    cv[5] = x[TOPO_LOOP_CP(1u, 2u)];
    cv[6] = x[TOPO_LOOP_CP(2u, 0u)];
    cv[7] = x[TOPO_LOOP_CP(2u, 1u)];
    cv[8] = x[TOPO_LOOP_CP(2u, 2u)];
    cv[9] = x[TOPO_LOOP_CP(3u, 0u)];
    cv[10] = x[TOPO_LOOP_CP(3u, 1u)];
    cv[11] = x[TOPO_LOOP_CP(3u, 2u)];
}

/* Child corners of a face are numbered 3k + j (child k, corner j), 0..11; the child corner
 * of parent face f is 12 f + that. */

/* The first half v_i -> m_i of parent side i: corner 0 of child i. */
static inline uint32_t topo_loop_first_half(uint32_t i) { return 3u * i; }
/* The second half m_i -> v_{i+1} of parent side i: corner 2 of child i+1. */
static inline uint32_t topo_loop_second_half(uint32_t i) { return 3u * ((i + 1u) % 3u) + 2u; }
/* The first child half-edge along parent half-edge h = 3f + i: 12 f + 3 i = 4 h - i. */
static inline uint32_t topo_loop_half_first(uint32_t h) { return 4u * h - h % 3u; }

/* The 12 child edge tags of a face whose parent sides carry tag[0..2]: both halves of side i
 * keep tag[i], the inner edges (corners 3k + 1 of children 0..2, child 3's) have none.
 * Written out for the same reason as topo_loop_child_corners. */
static inline void topo_loop_child_edge_tags(uint8_t *et, const uint8_t tag[3])
{
    et[1] = et[4] = et[7] = et[9] = et[10] = et[11] = 0u;
    et[topo_loop_first_half(0u)] = et[topo_loop_second_half(0u)] = tag[0];
    et[topo_loop_first_half(1u)] = et[topo_loop_second_half(1u)] = tag[1];
    et[topo_loop_first_half(2u)] = et[topo_loop_second_half(2u)] = tag[2];
}

/* vert_out of the new vertex on side i (the builder's convention, so the output equals the
 * builder's adjacency): on a boundary side its boundary half-edge m_i -> v_{i+1}, else its
 * smallest corner, which lies in the face of the edge's lower half-edge: corners 1 (child
 * 0), 4 (child 1) and 2 (child 0) for i = 0, 1, 2. Returns the child corner 0..11. */
static inline uint32_t topo_loop_new_vout(uint32_t i, int boundary)
{
    if (boundary) return topo_loop_second_half(i);
    return i == 0u ? 1u : i == 1u ? 4u : 2u;
}
#endif
