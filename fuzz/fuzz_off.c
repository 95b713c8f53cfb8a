/* SPDX-License-Identifier: MIT */
/* libFuzzer target: the OFF reader (subd_off_plan, subd_off_read, writer round trip, tags). */
#include "fuzz_reader.h"

int FUZZ_ENTRY(const uint8_t *data, size_t size)
{
    fz_reader_run(data, size, 1);
    return 0;
}
