/* SPDX-License-Identifier: MIT */
/* Chordal cuts of the streamed semi-regular 4-8 surface (SUBD_SR48_ADAPT_CHORD in
 * subd_sr48_stream, src/sr48_stream.c; its walk: src/sr48_chord_walk.c): the deviation test
 * of one vertex against the linear interpolant of one ancestor triangle. Paper:
 * semi-regular-4-8-refinement-box-splines.txt, section 3 (a diamond is split as a whole,
 * splits force their parents: the restricted hierarchy) and section 7 (adaptive extraction);
 * the chordal tolerance is beyond the paper, as in sr48_adapt.c.
 *
 * The criterion (design note; the choices where the paper is silent). P(v) is the position
 * of vertex v at the finest level max_level (subd_sr48_build's), L_d the linear
 * interpolation of triangle d's corners P at dyadic parameters (the parameter of a split
 * vertex is the midpoint of its node's base, as in sr48_adapt.c's walk), and
 *   E(d)    = max |P(v) - L_d(v)| over the vertices v created inside d's subtree down to
 *             max_level (subd_sr48_extract's exact chordal deviation of d; d asks for a
 *             split iff E(d) > eps),
 *   star(D) = the triangles of D's level that share a vertex with diamond D,
 *   F(D)    = the diamonds whose split forces D's: a child diamond of D (a child c of a
 *             triangle of D with c's base neighbour, a child of a leg neighbour) needs both
 *             its triangles' parents split, so D and the leg neighbour's diamond; F(D) is
 *             the closure: level k + 1 the diamonds of the children of D's triangles,
 *             level j + 1 those of the children of level j's triangles. The materialised
 *             cut splits D iff a diamond of {D} + F(D) has a triangle that asks (forced
 *             splits travel exactly along this relation), evaluated on active triangles.
 *   S(D)    = for D of level k and M = SUBD_SR48_STREAM_CHORD_EXACT_ (3): the triangles of
 *             {D} + F(D) of levels k .. k + M - 1, and every triangle of level >= k + M in
 *             the subtrees of star(G) for the diamonds G of F(D) of level k + M (none when
 *             k + M >= max_level: then S(D) is all of {D} + F(D) below max_level).
 * The stream splits a level-k diamond D iff E(d) > eps for some d in S(D).
 *
 * Lemma (stars nest; sr48_adapt.c's nested region): for a child diamond D' of level
 * k + 1 and each of its two parent diamonds P (the diamonds of its triangles' parents),
 * star(D') lies in the children of star(P): D' touches only the two new vertices of its
 * parents and the ends of the leg between them, and a triangle at such a vertex is a
 * child of a level-k triangle at it or at the leg's ends.
 * Nested: let D' split (E(d) > eps for a d in S(D')), D' a child diamond of D (D is one of
 * its parents, D' is in F(D)). (a) d in {D'} + F(D') of level < k + 1 + M: that set is in
 * F(D) (a closure), so d is in F(D) at a level k + 1 .. k + M: in the first part of S(D) below
 * k + M, else d's diamond is a G of level k + M and d is in star(G). (b) d of level
 * >= k + 1 + M under star(H) for H in F(D') of level k + 1 + M: a parent diamond P of H is
 * in F(D') at level k + M (H is forced through a chain), so in F(D), and by the lemma d
 * lies under star(P): in the second part of S(D). So S(D') is in S(D) and D splits: a
 * diamond that splits has parents that split, the cut is exactly the set of diamonds that
 * ask, decided top down with no lookahead and no forced split.
 * D's subtrees: every triangle under D's two triangles (down to max_level - 1) is in S(D): the
 * children of D's triangles are triangles of diamonds of F(D) one level down, their children of
 * F(D)'s next level, and so on down to level k + M, where each such triangle d lies in its own
 * diamond G, so in star(G), and the whole subtree of d is in the second part (when k + M >=
 * max_level, F(D) holds them all). So one
 * triangle under D with E > eps splits D, whatever the rest of S(D) (sr48_chord_walk.c answers
 * such decisions from the tiles' deviation bits without finding F(D)).
 * Conservative: D is in S(D), so a leaf t of the cut (its diamond does not split) has
 * E(t) <= eps: every finest-level vertex created inside t lies within eps of the emitted
 * triangle (L_t(v) is a point of it), up to the rounding below; every finest vertex lies
 * in some leaf. The cut contains subd_sr48_extract(CHORD)'s: a diamond split there has a
 * diamond in {D} + F(D) with a triangle that asks, and that triangle is in S(D).
 * How far from it: the stream also counts triangles that are not active in the
 * materialised cut, and the ring of star(G) around F(D) from level k + M on, where
 * deviations are about 2^-M of level k's on a smooth surface (E scales with the squared
 * edge length, which halves per level). Measured: subd_sr48.h. The criterion of
 * 0.4.0 (every triangle under star(D), about 4x F(D)'s area near level k) cut 1.77x.
 *
 * Where S(D) lies: F(D) is under star(D) (the lemma, by induction along the chain), so is
 * every star(G) of level k + M; the stream walks the subtrees of star(D)'s triangles that
 * may hold a member (sr48_chord_walk.c with its windows; the test: sr48_chord_region.c,
 * subd_s48_chord_may_), finds F(D)'s first M + 1 levels from the level-k window's adjacency
 * by the refinement's local neighbour rule (sr48_chord_region.c; every triangle asked for
 * is under star(D), so in the window), and does not enter a
 * level k + M triangle outside the stars of F(D)'s. How it is searched changes nothing of
 * the above: the last SUBD_SR48_STREAM_CHORD_TILE_ levels of a subtree are refined breadth
 * first (a tile), and the deviations E(d) > eps of a tile's triangles (and of the walk's
 * ancestors over the tile's subtree) are kept per tile root, the answers per diamond:
 * functions of the triangle or diamond, not of the decision, so every decision is the one
 * the exhaustive walk takes (sr48_chord_walk.c). A decision of level k >= tl = max_level -
 * SUBD_SR48_STREAM_CHORD_TILE_ (0 when max_level is smaller) reads E(d) > eps of the
 * triangles d under a star triangle from the tile of its level-tl ancestor (every d of
 * levels tl .. max_level - 1 is a node of exactly one such tile), and decides the
 * membership of d in S(D) from F(D)'s keys when d is less than M levels below k; a
 * deviating d deeper than that needs the star test, on the windows, as before.
 * test_sr48_chord.c evaluates S(D) exhaustively on the materialised hierarchy and compares
 * the cuts triangle for triangle. Why exact and not an a-priori bound
 * from the level-k control net (second differences times the box spline's contraction):
 * a rigorous constant needs the contraction at extraordinary vertices, with smoothing on
 * and off, in both arithmetics; not derived (issue 20, item 4).
 *
 * Rounding (subd_sr48_extract's CHORD uses this same test): L is
 * carried in Q32.32 in Q16.16 builds (16 halvings exact, then rounded to Q16.16 and
 * compared per axis and as a sum of squares in 64 bits: within eps + 2^-16), in float as
 * (a + b) * 0.5f (a relative error of a few ulp of the coordinates per level). */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "sr48_internal.h"

/* subd_sr48_lin_of_, subd_sr48_lin_mid_, subd_sr48_beyond_: static inline in sr48_internal.h (the
 * innermost loop of every chordal test). */
int subd_sr48_chord_beyond_(const subd_real *c, uint32_t path, uint32_t n, const subd_real *p, subd_real eps)
{
    subd_sr48_lin l[9], t[9], m[3];
    uint32_t i, s;
    for (i = 0; i < 9u; i++) l[i] = subd_sr48_lin_of_(c[i]);
    for (s = 0; s < n; s++) {
        /* child 0 = (m; apex, b0), child 1 = (m; b1, apex) */
        uint32_t bit = (path >> s) & 1u;
        for (i = 0; i < 3u; i++) {
            m[i] = subd_sr48_lin_mid_(l[3u + i], l[6u + i]);
            t[i] = m[i];
            t[3u + i] = bit ? l[6u + i] : l[i];
            t[6u + i] = bit ? l[i] : l[3u + i];
        }
        for (i = 0; i < 9u; i++) l[i] = t[i];
    }
    for (i = 0; i < 3u; i++) m[i] = subd_sr48_lin_mid_(l[3u + i], l[6u + i]);
    return subd_sr48_beyond_(p, m, eps);
}
