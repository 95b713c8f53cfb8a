/* SPDX-License-Identifier: MIT */
/* The reader checks shared by fuzz_obj.c and fuzz_off.c. */
#ifndef FUZZ_READER_H
#define FUZZ_READER_H
#include "fuzz_check.h"
void fz_reader_run(const uint8_t *data, size_t size, int off);
#endif
