/* SPDX-License-Identifier: MIT */
/* tinysubd: the 0.3 name of subd_sr48.h (deprecated, until 1.0). The
 * semi-regular 4-8 scheme has one name, sr48, across its header, types, calls, files and tool
 * command; this header only includes the new one, whose aliases keep the 0.3 type names
 * (subd_adapt*, SUBD_ADAPT_*) compiling. */
#ifndef SUBD_SEMIREG48_H
#define SUBD_SEMIREG48_H

#include "subd_sr48.h"

#endif
