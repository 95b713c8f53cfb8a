/* SPDX-License-Identifier: MIT */
/* libFuzzer target: the PLY reader (subd_ply_plan, subd_ply_read, a write/read round trip,
 * the tag checks with an empty tag file), through fuzz_reader.c. */
#include "fuzz_reader.h"

int FUZZ_ENTRY(const uint8_t *data, size_t size)
{
    fz_reader_run(data, size, 3);
    return 0;
}
