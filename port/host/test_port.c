/* SPDX-License-Identifier: MIT */
/* Host port for the test harness (test images only; the subd tool has its own I/O): output to stdout, exit with the code. */
#include <stdio.h>
#include <stdlib.h>
#include "print.h"

void port_write(const char *s, uint32_t n)
{
    fwrite(s, 1, n, stdout);
}

void port_exit(int code)
{
    fflush(stdout);
    exit(code);
}
