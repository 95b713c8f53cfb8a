/* SPDX-License-Identifier: MIT */
/* Streaming semi-regular 4-8 refinement, CHORD: the counting region of a decision (paper:
 * semi-regular-4-8-refinement-box-splines.txt, section 3: a diamond is split as a whole and
 * its split forces its parents'; section 4: the binary 4-8 refinement whose neighbour rule
 * finds F(D)). The criterion, S(D) and F(D), and why it nests and is conservative:
 * sr48_chord.c; the walk that asks this file: sr48_chord_walk.c; the interface:
 * sr48_chord_internal.h.
 *
 * For the diamond D of the current triangle t of the level-k window, F(D) (the diamonds
 * whose split forces D's) is found level by level down to k + min(S48C_M, levels - 1 - k)
 * from the level-k window's adjacency alone: the refinement's neighbour rule in its local
 * form (s48c_nbr) gives a descendant's neighbours from its level-k ancestor and child bits,
 * without refining (every triangle asked for is under star(D), so in the window:
 * sr48_chord.c). Each level is kept sorted (packed form and key agree in order: the window
 * is sorted by key) in the stream state's cdesc block, so membership is a binary search
 * (subd_s48_chord_has_). The walk then asks, per node, whether it counts (a member of F(D)
 * above level k + S48C_M, at that level a triangle of the stars of its members, below it
 * every node of an entered subtree) and, per subtree, whether it may hold a counting node
 * (subd_s48_chord_may_, _may_at_), so that it enters only those. No memo here: the answers
 * are a function of the decision and its window, rebuilt per decision. */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "sr48_chord_internal.h"

/* CHORD's counting region (the criterion and its proof: sr48_chord.c). The level-(k + d)
 * triangle (i, p), d <= S48C_M, is window-k triangle i's descendant along the d child bits
 * of p (the first step the highest bit); its key is key(i) * 2^d + p. Packed: i << 8 | p. */

/* Its neighbour across slot `slot` (0 base, 1 leg 0, 2 leg 1) by the local form of the
 * refinement's rule (subd_s48_refine_): child 0 has base child 1 of the parent's leg-0
 * neighbour, leg 0 its sibling, leg 1 child 1 of the parent's base neighbour; child 1 has
 * base child 0 of the parent's leg-1 neighbour, leg 0 child 0 of the parent's base
 * neighbour, leg 1 its sibling. 1 found (*oi, *op), 0 the mesh boundary, -1 outside
 * window k. */
static int s48c_nbr(const s48_win *w, uint32_t i, uint32_t p, uint32_t d, uint32_t slot, uint32_t *oi,
                    uint32_t *op)
{
    uint32_t push = 0, np = 0, q;
    for (q = 0; q <= S48C_M; q++) { /* at most d + 1 <= S48C_M + 1 rounds */
        uint32_t b = p & 1u;
        if (d == 0u) {
            uint16_t n = w->tn[3u * i + slot];
            if (n == S48_BND) return 0;
            if (n == S48_OUT) return -1;
            i = n;
            p = 0;
            break;
        }
        if (b == 0u && slot == 1u) {
            p |= 1u;
            break;
        }
        if (b == 1u && slot == 2u) {
            p &= ~1u;
            break;
        }
        push |= (1u - b) << np; /* the answer is that child of the parent's neighbour */
        np++;
        slot = b == 0u ? (slot == 0u ? 1u : 0u) : (slot == 0u ? 2u : 0u);
        p >>= 1;
        d--;
    }
    while (np > 0u) { /* the last parent-level step is the first child bit */
        np--;
        p = (p << 1) | ((push >> np) & 1u);
    }
    *oi = i;
    *op = p;
    return 1;
}

/* The first entry of level d's descendants (3 words each; at most 2 * 4^d of them). */
static uint32_t s48c_off(uint32_t d) { return 2u * ((1u << (2u * d)) - 1u) / 3u; }

/* Is `v` (word `w` of the entries: 0 packed, 1 key) in level d's sorted descendants? */
int subd_s48_chord_has_(const s48_state *s, uint32_t d, uint64_t v, uint32_t wd)
{
    const uint32_t *e = s->cdesc + 3u * s48c_off(d);
    uint32_t lo = 0, hi = s->cdn[d];
    while (lo < hi) {
        uint32_t mid = (lo + hi) / 2u;
        uint64_t m = wd == 0u ? e[3u * mid] : (((uint64_t)e[3u * mid + 2u] << 32) | e[3u * mid + 1u]);
        if (m == v) return 1;
        if (m < v) lo = mid + 1u;
        else hi = mid;
    }
    return 0;
}

/* The diamonds whose split forces the split of the current triangle t's diamond (t in the
 * level-k window), level by level down to k + min(S48C_M, levels - 1 - k): level k is t and
 * its base neighbour; level d + 1 is the children of level d and their base neighbours
 * (the other triangle of each child's diamond: a diamond of level d + 1 forces both
 * diamonds its triangles' parents belong to). Each level sorted (by packed form, which is
 * key order: the window is sorted by key). All of them lie in the subtrees of t's star,
 * so every neighbour asked for is in the window (sr48_chord.c); 0 if not. */
int subd_s48_chord_desc_(s48_state *s, uint32_t k, uint32_t t)
{
    s48_win w;
    uint32_t m = s->levels - 1u - k, d, n, x, b, q;
    uint16_t nb;
    s48_lev(s, k, &w);
    if (m > S48C_M) m = S48C_M;
    nb = w.tn[3u * t];
    if (nb == S48_OUT) return 0;
    for (d = 0; d <= S48C_M; d++) s->cdn[d] = 0;
    for (d = 0; d <= m; d++) {
        uint32_t *e = s->cdesc + 3u * s48c_off(d);
        n = 0;
        if (d == 0u) {
            e[0] = t << 8;
            n = 1;
            if (s48_local(nb)) e[3u * n++] = (uint32_t)nb << 8;
        } else {
            const uint32_t *pe = s->cdesc + 3u * s48c_off(d - 1u);
            for (x = 0; x < s->cdn[d - 1u]; x++)
                for (b = 0; b < 2u; b++) {
                    uint32_t i = pe[3u * x] >> 8, p = ((pe[3u * x] & 0xffu) << 1) | b, oi, op;
                    int r;
                    e[3u * n++] = (i << 8) | p;
                    r = s48c_nbr(&w, i, p, d, 0, &oi, &op);
                    if (r < 0) return 0;
                    /* a base neighbour whose parent is of level d - 1's set is a child above;
                     * base neighbours are a bijection, so no other duplicate */
                    if (r == 0 || subd_s48_chord_has_(s, d - 1u, (oi << 8) | (op >> 1), 0)) continue;
                    e[3u * n++] = (oi << 8) | op;
                }
        }
        for (x = 1; x < n; x++) { /* insertion sort by packed form */
            uint32_t v = e[3u * x];
            q = x;
            while (q > 0u && e[3u * (q - 1u)] > v) {
                e[3u * q] = e[3u * (q - 1u)];
                q--;
            }
            e[3u * q] = v;
        }
        for (x = 0; x < n; x++) {
            uint64_t key = (s48_key(&w, e[3u * x] >> 8) << d) | (e[3u * x] & 0xffu);
            e[3u * x + 1u] = (uint32_t)key;
            e[3u * x + 2u] = (uint32_t)(key >> 32);
        }
        s->cdn[d] = n;
    }
    return 1;
}

/* Does the walk's node cur (window w of level j >= k) count for the diamond decided at
 * level k: levels k .. k + S48C_M - 1 the descendant diamonds, level k + S48C_M the star
 * of the descendant diamonds of that level (a triangle sharing a vertex with one; its
 * star is in the window), deeper levels through their level k + S48C_M ancestor (the walk
 * does not enter a subtree that does not count there). */
uint32_t subd_s48_chord_counts_(const s48_state *s, uint32_t k, uint32_t j, const s48_win *w, uint32_t cur)
{
    uint32_t d = j - k, i, a, b;
    if (d < S48C_M) return (uint32_t)subd_s48_chord_has_(s, d, s48_key(w, cur), 1u);
    if (d > S48C_M) return 1u;
    for (i = 0; i < w->hd[0]; i++) {
        int touch = 0;
        for (a = 0; a < 3u; a++)
            for (b = 0; b < 3u; b++)
                if (w->tv[3u * i + a] == w->tv[3u * cur + b]) touch = 1;
        if (touch && subd_s48_chord_has_(s, d, s48_key(w, i), 1u)) return 1u;
    }
    return 0u;
}

/* May the subtree of triangle i of the level-k window (k < levels, after subd_s48_chord_desc_)
 * hold a counting node? Yes if i is an ancestor of a descendant of the deepest level kept (they
 * cover the shallower ones) or, when that level is k + S48C_M, shares a vertex with one (a
 * triangle sharing a vertex with a level k + S48C_M descendant has its level-k ancestor equal to
 * or sharing a vertex with the descendant's: a shared vertex inside a level-k edge makes the two
 * ancestors the triangles of that edge). */
int subd_s48_chord_may_(const s48_state *s, const s48_win *w, uint32_t k, uint32_t i)
{
    uint32_t m = s->levels - 1u - k, x, a, b, q, prev = 0xffffffffu;
    const uint32_t *e;
    if (m > S48C_M) m = S48C_M;
    e = s->cdesc + 3u * s48c_off(m);
    for (x = 0; x < s->cdn[m]; x++) {
        q = e[3u * x] >> 8; /* sorted: equal ancestors are consecutive */
        if (q == prev) continue;
        prev = q;
        if (q == i) return 1;
        if (m < S48C_M) continue;
        for (a = 0; a < 3u; a++)
            for (b = 0; b < 3u; b++)
                if (w->tv[3u * q + a] == w->tv[3u * i + b]) return 1;
    }
    return 0;
}

/* subd_s48_chord_may_ one level deeper: may the subtree of the walk's node cur (window w of level
 * j, k <= j < k + S48C_M) hold a counting node? The same test on level j's ancestors of the
 * deepest descendants kept (key >> (k + m - j)): equal to cur, or (m = S48C_M) sharing a vertex
 * with it (the lemma of subd_s48_chord_may_ holds at any level between: two triangles of one
 * level that meet share a vertex). An ancestor not in the window does not meet cur (the window
 * holds cur's rings). Only asked of a node that does not count: then none of its ancestors counts
 * either (the descendants of a counting node of level < k + S48C_M count, subd_s48_chord_desc_),
 * so no test of the walk involves its subtree when this says no. */
int subd_s48_chord_may_at_(const s48_state *s, const s48_win *w, uint32_t k, uint32_t j, uint32_t cur)
{
    uint32_t m = s->levels - 1u - k, x, a, b;
    uint64_t kc = s48_key(w, cur), prev = ~(uint64_t)0;
    const uint32_t *e;
    if (m > S48C_M) m = S48C_M;
    if (k + m < j) return 0;
    e = s->cdesc + 3u * s48c_off(m);
    for (x = 0; x < s->cdn[m]; x++) {
        uint64_t an = ((((uint64_t)e[3u * x + 2u] << 32) | e[3u * x + 1u])) >> (k + m - j);
        uint32_t lo = 0, hi = w->hd[0];
        if (an == prev) continue; /* sorted by key: equal ancestors are consecutive */
        prev = an;
        if (an == kc) return 1;
        if (m < S48C_M) continue;
        while (lo < hi) { /* the ancestor in the window (sorted by key) */
            uint32_t mid = (lo + hi) / 2u;
            if (s48_key(w, mid) < an) lo = mid + 1u;
            else hi = mid;
        }
        if (lo >= w->hd[0] || s48_key(w, lo) != an) continue;
        for (a = 0; a < 3u; a++)
            for (b = 0; b < 3u; b++)
                if (w->tv[3u * lo + a] == w->tv[3u * cur + b]) return 1;
    }
    return 0;
}
