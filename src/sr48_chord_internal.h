/* SPDX-License-Identifier: MIT */
/* Streaming semi-regular 4-8 refinement, CHORD: the private interface between the walk
 * (sr48_chord_walk.c) and the counting region F(D) it asks (sr48_chord_region.c). Paper:
 * semi-regular-4-8-refinement-box-splines.txt, sections 3 and 4; the criterion and why it
 * nests: sr48_chord.c. The region's state (F(D)'s first levels: cdesc, cdn) is a block of
 * the stream's state, s48_state in sr48_stream_internal.h. Names are subd_s48_chord_*_
 * (unique in src/: the library is also one translation unit, make amalgamate). */
#ifndef SUBD_SR48_CHORD_INTERNAL_H
#define SUBD_SR48_CHORD_INTERNAL_H
#include "sr48_stream_internal.h"

/* Is `v` (word `wd` of the entries: 0 packed, 1 key) in F(D)'s sorted level d? */
int subd_s48_chord_has_(const s48_state *s, uint32_t d, uint64_t v, uint32_t wd);
/* F(D)'s first levels for the current triangle t of the level-k window; 0 on failure. */
int subd_s48_chord_desc_(s48_state *s, uint32_t k, uint32_t t);
/* Does the walk's node cur (window w of level j >= k) count for the level-k decision? */
uint32_t subd_s48_chord_counts_(const s48_state *s, uint32_t k, uint32_t j, const s48_win *w, uint32_t cur);
/* May the subtree of triangle i of the level-k window hold a counting node? */
int subd_s48_chord_may_(const s48_state *s, const s48_win *w, uint32_t k, uint32_t i);
/* The same for the walk's node cur of window w of level j, k <= j < k + S48C_M. */
int subd_s48_chord_may_at_(const s48_state *s, const s48_win *w, uint32_t k, uint32_t j, uint32_t cur);

/* The tiles (sr48_chord_tile.c). The memo entry (5 words) of the tile root with key `key` at
 * level j; the walk's tile of node r of the level-j window for the level-k decision (1
 * beyond, 0 within, -1 failure, -2 a loose tile's window misses part of what it needs); the
 * memo's tile of triangle r of the level-j window into entry mk (1 done, 0 not exact, -1
 * failure). */
uint32_t *subd_s48_chord_mk_(const s48_state *s, uint64_t key, uint32_t j);
/* The same entry if the memo holds it, else NULL, without counting it as used. */
const uint32_t *subd_s48_chord_mk_find_(const s48_state *s, uint64_t key, uint32_t j);
int subd_s48_chord_tile_(s48_state *s, uint32_t k, uint32_t j, uint32_t r, uint32_t loose);
int subd_s48_chord_bits_(s48_state *s, uint32_t j, uint32_t r, uint32_t *mk);
/* Keeps the finest position p of vertex id in the cache (sr48_chord_walk.c). */
void subd_s48_chord_put_(s48_state *s, uint64_t id, const subd_real *p);

#endif
