/* SPDX-License-Identifier: MIT */
/* Private interface of the adaptive Loop limit stream (include/subd_loop_adapt.h): the types
 * and lattice geometry that loop_adapt.c (lattice walk, limit points, a face's triangulation,
 * the stream) and loop_adapt_chord.c (the levels: CHORD's chord tests and fallback, CALLBACK)
 * share. Lattice points are integers in units 1/2^L of the control face (0,0), (N,0), (0,N);
 * loop_adapt.c's header comment gives the choices (values, triangulation, memory),
 * loop_adapt_chord.c's the level rules. */
#ifndef SUBD_LOOP_ADAPT_INTERNAL_H
#define SUBD_LOOP_ADAPT_INTERNAL_H
#include "loop_internal.h"
#include "loop_patch.h"
#include "stream_internal.h"

/* The blocks (NULL when counting), the uniform limit stream's layout. */
typedef struct la_layout {
    uint32_t n;
    uint32_t off0[A_N], off1[A_N];
    sp_head *head;
    uint8_t *lev0, *lev1; /* levels 1..L: blocks of size1 bytes (level L without its cache) */
    subd_mesh view;
    uint16_t *smap, *fmap;
    loop_wcache *wc; /* the smooth rule's weights, cached (subd_reals and a word: arena data) */
    subd_real *pc;   /* CHORD, L <= SUBD_LOOP_ADAPT_PC_LEVELS_: one face's level-L limit points (else NULL) */
    uint32_t *pbits; /* which of them are filled                                            */
    uint32_t *memo;  /* with pc: SUBD_LOOP_ADAPT_MEMO_ (face, own level) pairs, by face mod the count */
    uint32_t size1, total;
} la_layout;


/* ------------------------------------------------------------------------------------ */
/* Lattice geometry (integers, units 1/2^L of the control face (0,0), (N,0), (0,N))        */

typedef struct la_pt {
    int32_t a, b;
} la_pt;

/* A triangle of a face's triangulation: its corners and, for a uniform level-l triangle, its
 * index among the face's 4^l (digits: the children from the top), else LA_NO_SUB. */
#define LA_NO_SUB 0xffffffffu
typedef struct la_tri {
    la_pt p[3];
    uint32_t sub;
} la_tri;

static inline int64_t la_cross(la_pt o, la_pt u, la_pt v)
{
    return (int64_t)(u.a - o.a) * (v.b - o.b) - (int64_t)(u.b - o.b) * (v.a - o.a);
}

static inline la_pt la_mid(la_pt u, la_pt v)
{
    la_pt m;
    m.a = (u.a + v.a) / 2;
    m.b = (u.b + v.b) / 2;
    return m;
}

/* Child c of triangle t (topo.h's table: child i = (v_i, m_i, m_i-1), child 3 = (m0, m1, m2)). */
static inline void la_child(la_pt t[3], uint32_t c)
{
    la_pt m0 = la_mid(t[0], t[1]), m1 = la_mid(t[1], t[2]), m2 = la_mid(t[2], t[0]);
    if (c == 3u) {
        t[0] = m0; t[1] = m1; t[2] = m2;
    } else {
        la_pt v = t[c], mc = c == 0u ? m0 : c == 1u ? m1 : m2, mp = c == 0u ? m2 : c == 1u ? m0 : m1;
        t[0] = v; t[1] = mc; t[2] = mp;
    }
}

static inline void la_root(la_pt t[3], int32_t n)
{
    t[0].a = 0; t[0].b = 0;
    t[1].a = n; t[1].b = 0;
    t[2].a = 0; t[2].b = n;
}

/* Corners of uniform level-l triangle `sub`. */
static inline void la_sub_corners(uint32_t sub, uint32_t l, int32_t n, la_pt t[3])
{
    uint32_t k;
    la_root(t, n);
    for (k = 0; k < l; k++) la_child(t, (sub >> (2u * (l - 1u - k))) & 3u);
}

/* ------------------------------------------------------------------------------------ */
/* State                                                                                  */

typedef struct la_face {
    uint32_t l, e[3]; /* face and edge levels                                        */
    uint32_t trans;   /* some edge coarser than l                                    */
    uint32_t no, ni;  /* ring: outer and inner loop vertex counts                    */
    uint32_t own;     /* CHORD: the face's own uniform level (la_face_own)          */
} la_face;

typedef struct la_iter {
    uint32_t phase; /* 0 uniform triangles, 1 the ring, 2 done                        */
    uint32_t j;     /* phase 0: next level-l triangle; phase 1 (fan): next step        */
    uint32_t io, ii;
} la_iter;

typedef struct la_state {
    subd_stream_impl impl; /* first: stream.c's view of the state */
    subd_stream_ring ring;
    la_layout lay;
    const subd_mesh *in;
    subd_loop_adapt_opts o;
    uint32_t f, started, ovf;
    uint32_t gf; /* the control face whose hierarchy la_goto descends (f, or a neighbour) */
    uint32_t pathf, depth, view_ok; /* the stack holds face pathf's levels 0..depth  */
    uint8_t path[SUBD_MAX_LEVELS + 1u];
    la_face fc;
    la_iter it;
    uint32_t pre; /* CHORD: the pre-pass (la_prepass) has run                        */
    uint32_t uni; /* CHORD: every face at this uniform level, or SUBD_NONE: adaptive */
    uint32_t pcf; /* the control face whose level-L points lay.pc holds, or SUBD_NONE  */
    uint32_t nb;  /* CHORD's fallback check: every face uniform at fc.l, so the edge
                   * neighbours' triangles are emitted too and may hold a point          */
} la_state;
/* loop_adapt.c: the limit point (and normal, if nrm) of lattice point x of face s->gf; of
 * corner c of triangle t of the current face's triangulation; the triangulation's next
 * triangle (0 after the last); a face's ring counts from its levels. */
void subd_la_eval_point(la_state *s, la_pt x, subd_real *pos, subd_real *nrm);
void subd_la_eval_corner(la_state *s, const la_tri *t, uint32_t c, subd_real *pos, subd_real *nrm);
int subd_la_next(const la_face *fc, uint32_t L, la_iter *it, la_tri *t);
void subd_la_face_setup_ring(la_face *fc);
/* loop_adapt_chord.c: the levels of face s->f and its edges (s->fc); every face at uniform
 * level u; CHORD's pass before the first triangle (the uniform fallback: s->uni). */
void subd_la_face_levels(la_state *s);
void subd_la_face_uniform(la_face *fc, uint32_t u);
int subd_la_prepass(la_state *s, subd_diag *d);
#endif
