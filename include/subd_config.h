/* SPDX-License-Identifier: MIT */
/* tinysubd build-time configuration.
 *
 * Every option has a default here. A firmware build overrides options by defining
 * SUBD_CONFIG_FILE as the name of its own header (e.g. -DSUBD_CONFIG_FILE='"my_subd.h"'),
 * which is included first, or by -D flags. Impossible combinations stop the build.
 */
#ifndef SUBD_CONFIG_H
#define SUBD_CONFIG_H

#ifdef SUBD_CONFIG_FILE
#include SUBD_CONFIG_FILE
#endif

/* SUBD_FIXED: 0 = subd_real is IEEE float32 (default), 1 = signed Q16.16 fixed point. */
#ifndef SUBD_FIXED
#define SUBD_FIXED 0
#endif
#if SUBD_FIXED != 0 && SUBD_FIXED != 1
#error "SUBD_FIXED must be 0 (float32) or 1 (Q16.16)"
#endif

/* Largest polygon accepted by the mesh builder and the readers. Bounds the per-face
 * stack work of validation (repeated-vertex check is O(k^2) on k <= SUBD_MAX_FACE_SIZE). */
#ifndef SUBD_MAX_FACE_SIZE
#define SUBD_MAX_FACE_SIZE 32
#endif
#if SUBD_MAX_FACE_SIZE < 3 || SUBD_MAX_FACE_SIZE > 255
#error "SUBD_MAX_FACE_SIZE must be in 3..255"
#endif

/* Largest number of subdivision levels a scheme call accepts. */
#ifndef SUBD_MAX_LEVELS
#define SUBD_MAX_LEVELS 8
#endif
#if SUBD_MAX_LEVELS < 1 || SUBD_MAX_LEVELS > 16
#error "SUBD_MAX_LEVELS must be in 1..16"
#endif

/* Arena allocations are rounded up to this many bytes, relative to the arena start, so
 * that plans do not depend on the buffer address. Must be a power of two >= 4. */
#ifndef SUBD_ARENA_ALIGN
#define SUBD_ARENA_ALIGN 8u
#endif

/* Levels the Loop stream refines breadth first in one regular tile (src/loop_tile.c): 2..5,
 * or 0 for none; SUBD_LOOP_TILE_LEVELS_LIMIT likewise for limit mode (whose tile also holds
 * limit positions and normals). More levels spread a patch's cost over more triangles
 * (4^levels per tile: Cortex-M4F, level 6 of the demo's sphere, counting sink, 269
 * instructions per triangle at 4, 171 at 5; limit mode 572 at 4, 460 at 5) and take more
 * arena (the tile's block, 2.3 KB at 4 and 6.6 KB at 5; limit mode 3.6 KB at 4 and 7.3 KB
 * at 5, whose last level is made by a quarter's children: loop_tile.h's lt_split), which
 * shares memory with the levels below the tile's (SUBD_LOOP_STREAM_BYTES). The defaults
 * keep the plans within 16 KiB at 8 levels and valence 16. */
#ifndef SUBD_LOOP_TILE_LEVELS
#define SUBD_LOOP_TILE_LEVELS 5
#endif
#if SUBD_LOOP_TILE_LEVELS != 0 && (SUBD_LOOP_TILE_LEVELS < 2 || SUBD_LOOP_TILE_LEVELS > 5)
#error "SUBD_LOOP_TILE_LEVELS must be 0 or in 2..5"
#endif
#ifndef SUBD_LOOP_TILE_LEVELS_LIMIT
#define SUBD_LOOP_TILE_LEVELS_LIMIT 5
#endif
#if SUBD_LOOP_TILE_LEVELS_LIMIT != 0 && (SUBD_LOOP_TILE_LEVELS_LIMIT < 2 || SUBD_LOOP_TILE_LEVELS_LIMIT > 5)
#error "SUBD_LOOP_TILE_LEVELS_LIMIT must be 0 or in 2..5"
#endif

#endif
