/* SPDX-License-Identifier: MIT */
/* Cortex-M port for QEMU's MPS2 boards (mps2-an385 Cortex-M3, mps2-an386 Cortex-M4F):
 * semihosting output and exit, a tick counter, and stack-use measurement. The startup code
 * (startup.c) and the test harness are the users. Nothing here allocates or uses stdio. */
#ifndef PORT_CM_H
#define PORT_CM_H

#include <stdint.h>

/* Write n bytes (no NUL needed) to the host's stdout via semihosting. */
void port_write(const char *s, uint32_t n);

/* End the run: QEMU exits with `code` as its exit status (semihosting SYS_EXIT_EXTENDED).
 * Status values are truncated to 0..255 by the host, as for any process. */
void port_exit(int code) __attribute__((noreturn));

/* SysTick ticks on the processor clock since the first call (which starts SysTick and
 * returns 0). Take differences modulo 2^32. On real hardware a tick is one CPU cycle. On
 * QEMU's MPS2 boards the processor clock is 25 MHz of *virtual* time, so the count is
 * deterministic only under `-icount shift=0`, where one instruction takes 1 ns and hence
 * instructions = ticks * PORT_QEMU_INSNS_PER_TICK (to within one tick). Without -icount
 * the count follows host time and says nothing. Uses the SysTick interrupt to extend the
 * 24-bit counter. */
uint32_t port_cycles(void);
#define PORT_QEMU_INSNS_PER_TICK 40u

/* Deepest stack use since reset, in bytes: the stack is painted at reset and this scans
 * for the first overwritten word above the limit. Returns the whole stack size if the
 * paint is gone at the limit (overflow, or close to it). */
uint32_t port_stack_used(void);
uint32_t port_stack_size(void);

/* Linker-script symbols (linker/mps2_an38[56].ld). Addresses only; never read as values. */
extern uint32_t __StackLimit[];
extern uint32_t __StackTop[];

/* Word written over the whole stack at reset. */
#define PORT_STACK_PAINT 0xC5AC5AC5u

#endif
