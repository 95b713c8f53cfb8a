/* SPDX-License-Identifier: MIT */
/* Little-endian loads and stores on byte buffers of any alignment, shared by the binary
 * readers and writers (stl.c, ply.c). Byte by byte, so the result does not depend on the
 * host's byte order or alignment rules. */
#ifndef SUBD_BIN_LE_H
#define SUBD_BIN_LE_H
#include <stdint.h>

static inline uint32_t subd_le_u16(const char *p)
{
    return (uint32_t)(uint8_t)p[0] | (uint32_t)(uint8_t)p[1] << 8;
}
static inline uint32_t subd_le_u32(const char *p)
{
    return (uint32_t)(uint8_t)p[0] | (uint32_t)(uint8_t)p[1] << 8 | (uint32_t)(uint8_t)p[2] << 16 |
           (uint32_t)(uint8_t)p[3] << 24;
}
static inline uint64_t subd_le_u64(const char *p)
{
    return (uint64_t)subd_le_u32(p) | (uint64_t)subd_le_u32(p + 4) << 32;
}
static inline void subd_le_put_u32(char *p, uint32_t v)
{
    p[0] = (char)(uint8_t)v;
    p[1] = (char)(uint8_t)(v >> 8);
    p[2] = (char)(uint8_t)(v >> 16);
    p[3] = (char)(uint8_t)(v >> 24);
}
#endif
