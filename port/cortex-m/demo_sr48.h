/* SPDX-License-Identifier: MIT */
/* Firmware demo, semi-regular 4-8 chordal stream (port/cortex-m/demo_sr48.c): the hook that
 * port/cortex-m/demo.c calls with its main arena. */
#ifndef DEMO_SR48_H
#define DEMO_SR48_H

#include "subd.h"

/* Runs the demo step; SUBD_OK or the failing status (printed). The arena is back where it
 * was afterwards. */
int demo_sr48_chord(subd_arena *arena);

#endif
