/* SPDX-License-Identifier: MIT */
/* libFuzzer target: the OBJ reader (subd_obj_plan, subd_obj_read, writer round trip, tags). */
#include "fuzz_reader.h"

int FUZZ_ENTRY(const uint8_t *data, size_t size)
{
    fz_reader_run(data, size, 0);
    return 0;
}
