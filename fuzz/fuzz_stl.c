/* SPDX-License-Identifier: MIT */
/* libFuzzer target: the STL reader (subd_stl_plan, subd_stl_read, a write/read round trip,
 * the tag checks with an empty tag file), through fuzz_reader.c. */
#include "fuzz_reader.h"

int FUZZ_ENTRY(const uint8_t *data, size_t size)
{
    fz_reader_run(data, size, 2);
    return 0;
}
