/* SPDX-License-Identifier: MIT */
/* Status codes as text, for messages; the library's version. */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "subd.h"

uint32_t subd_version(void) { return (uint32_t)SUBD_VERSION_NUMBER; }

const char *subd_status_str(int status)
{
    switch (status) {
    case SUBD_OK: return "ok";
    case SUBD_ERR_NOMEM: return "arena too small";
    case SUBD_ERR_PARAM: return "invalid parameter";
    case SUBD_ERR_PARSE: return "syntax error";
    case SUBD_ERR_NAN: return "coordinate is NaN or infinite";
    case SUBD_ERR_RANGE: return "value out of range";
    case SUBD_ERR_INDEX: return "vertex index out of range";
    case SUBD_ERR_FACE_SIZE: return "face has too few or too many vertices";
    case SUBD_ERR_DEGENERATE: return "face repeats a vertex";
    case SUBD_ERR_NONMANIFOLD_EDGE: return "non-manifold edge (more than two faces)";
    case SUBD_ERR_ORIENTATION: return "inconsistent face orientation";
    case SUBD_ERR_NONMANIFOLD_VERTEX: return "non-manifold vertex (faces form several fans)";
    case SUBD_ERR_TOO_BIG: return "counts too large";
    case SUBD_ERR_EMPTY: return "empty input";
    case SUBD_ERR_NOT_TRIANGLES: return "not a triangle mesh";
    case SUBD_ERR_ARITH: return "arithmetic differs from the reference (contraction, rounding or flush-to-zero)";
    case SUBD_ERR_DIVERGENT: return "parameter makes the subdivision diverge";
    default: return "unknown status";
    }
}
