/* SPDX-License-Identifier: MIT */
/* The reader checks shared by fuzz_obj.c, fuzz_off.c, fuzz_stl.c and fuzz_ply.c. */
#ifndef FUZZ_READER_H
#define FUZZ_READER_H
#include "fuzz_check.h"
/* fmt: 0 OBJ, 1 OFF, 2 STL, 3 PLY */
void fz_reader_run(const uint8_t *data, size_t size, int fmt);
#endif
