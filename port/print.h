/* SPDX-License-Identifier: MIT */
/* Text output shared by the test harness and the demos on every platform: an own integer
 * formatter over the port's write function, so host and target print the same bytes. */
#ifndef PORT_PRINT_H
#define PORT_PRINT_H
#include <stdint.h>

/* Provided by each port (port/host/test_port.c, port/cortex-m/port_cm.c). */
void port_write(const char *s, uint32_t n);
void port_exit(int code);

void print_str(const char *s);
/* Decimal digits of v into b[0..20) (no terminator); returns how many (1 to 20). */
uint32_t print_fmt_u64(char *b, uint64_t v);
void print_u64(uint64_t v);
void print_i64(int64_t v);
void print_u32(uint32_t v);
void print_i32(int32_t v);
void print_hex32(uint32_t v);
void print_nl(void);
#endif
