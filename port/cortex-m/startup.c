/* SPDX-License-Identifier: MIT */
/* Startup for the Cortex-M builds on QEMU's MPS2 boards (mps2-an385 Cortex-M3, mps2-an386
 * Cortex-M4F): the vector table, the reset handler that prepares memory and the FPU before
 * calling main(), and fault handlers that report over semihosting and end the run with a
 * non-zero status so that a crash can never look like a passing test.
 *
 * Linked with -nostartfiles, so nothing else runs before Reset_Handler: no crt0, no
 * constructors (C has none), no newlib initialisation (nothing uses stdio). */
#include <stdint.h>
#include "port_cm.h"

int main(void);

/* Linker-script symbols: .data's load address in flash-like SSRAM1, its run range in RAM,
 * and the .bss range. Declared as arrays so only their addresses are ever used. */
extern uint32_t __data_load[];
extern uint32_t __data_start[];
extern uint32_t __data_end[];
extern uint32_t __bss_start[];
extern uint32_t __bss_end[];

void Reset_Handler(void) __attribute__((noreturn));
void Fault_Handler(void);
void SysTick_Handler(void);
/* Global (not static) only so that the naked Fault_Handler can branch to it by name. */
void cm_fault_report(const uint32_t *frame, uint32_t exc_return) __attribute__((noreturn));

/* Run-time status for a fault (any value but 0 and 1, so a fault differs from a test
 * failure, and below 124 so it differs from the runner's timeout). */
#define FAULT_EXIT_CODE 3

#define SCB_CPACR (*(volatile uint32_t *)0xE000ED88u)
#define SCB_CFSR (*(volatile uint32_t *)0xE000ED28u)
#define SCB_HFSR (*(volatile uint32_t *)0xE000ED2Cu)

void Reset_Handler(void)
{
#ifdef __ARM_FP
    /* Full access to CP10/CP11 (the FPU) before any floating-point instruction: with the
     * hard-float ABI even integer-looking code may move values through s-registers. The
     * DSB/ISB make sure the new access rights apply to the very next instruction. */
    SCB_CPACR |= (3u << 20) | (3u << 22);
    __asm__ volatile("dsb\n\tisb" ::: "memory");
#endif
    /* The copy and zero loops go through volatile pointers so that gcc does not turn them
     * into memcpy/memset calls (-ftree-loop-distribute-patterns at -O2). */
    {
        const uint32_t *src = __data_load;
        volatile uint32_t *dst = __data_start;
        while (dst < __data_end) {
            *dst++ = *src++;
        }
    }
    {
        volatile uint32_t *p = __bss_start;
        while (p < __bss_end) {
            *p++ = 0u;
        }
    }
    /* Paint the unused stack (everything below the current stack pointer) so that
     * port_stack_used() can find the deepest point reached later. */
    {
        volatile uint32_t *p = __StackLimit;
        uint32_t sp;
        __asm__ volatile("mov %0, sp" : "=r"(sp));
        while ((uint32_t)p < sp - 16u) {
            *p++ = PORT_STACK_PAINT;
        }
    }
    port_exit(main());
}

/* Own hex formatter: the fault path must not depend on any library code. */
#define PUT_HEX(label, v) put_hex(label, sizeof(label) - 1u, v)
static void put_hex(const char *label, uint32_t label_len, uint32_t v)
{
    char b[10];
    int i;
    b[0] = '0';
    b[1] = 'x';
    for (i = 0; i < 8; i++) {
        b[9 - i] = "0123456789abcdef"[v & 0xFu];
        v >>= 4;
    }
    port_write(label, label_len);
    port_write(b, 10u);
}

static void put_dec2(uint32_t v)
{
    char b[2];
    b[0] = (char)('0' + (v / 10u) % 10u);
    b[1] = (char)('0' + v % 10u);
    port_write(b, 2u);
}

/* Reached from Fault_Handler with the stacked exception frame (r0-r3, r12, lr, pc, xpsr) and
 * the EXC_RETURN value. The exception number comes from IPSR: 3 is HardFault, 4-6 the
 * configurable faults (only reached if the firmware enables them in SHCSR; otherwise they
 * escalate to HardFault), anything else is a vector that nobody installed. */
void cm_fault_report(const uint32_t *frame, uint32_t exc_return)
{
    uint32_t ipsr;
    __asm__ volatile("mrs %0, ipsr" : "=r"(ipsr));
    ipsr &= 0x1FFu;
    if (ipsr == 3u) {
        port_write("\nHARDFAULT", 10u);
    } else if (ipsr >= 4u && ipsr <= 6u) {
        port_write("\nFAULT exc=", 11u);
        put_dec2(ipsr);
    } else {
        port_write("\nUNHANDLED EXCEPTION exc=", 25u);
        put_dec2(ipsr);
    }
    PUT_HEX(" pc=", frame[6]);
    PUT_HEX(" lr=", frame[5]);
    PUT_HEX(" cfsr=", SCB_CFSR);
    PUT_HEX(" hfsr=", SCB_HFSR);
    PUT_HEX(" exc_return=", exc_return);
    port_write("\n", 1u);
    port_exit(FAULT_EXIT_CODE);
}

/* Every fault and unused vector lands here. Naked, so that no prologue changes SP or LR
 * before the stacked frame is located (MSP or PSP, from EXC_RETURN bit 2). */
__attribute__((naked)) void Fault_Handler(void)
{
    __asm__ volatile(
        "tst lr, #4\n\t"
        "ite eq\n\t"
        "mrseq r0, msp\n\t"
        "mrsne r0, psp\n\t"
        "mov r1, lr\n\t"
        "b cm_fault_report\n\t");
}

/* port_cm.c defines the real SysTick handler; this weak one keeps images that never start
 * SysTick linkable and turns a stray SysTick into a report. */
__attribute__((weak, alias("Fault_Handler"))) void SysTick_Handler(void);

typedef union vector {
    void *sp;
    void (*fn)(void);
} vector;

/* 16 system exceptions plus the 32 external interrupts QEMU wires on these boards. Unused
 * entries point at Fault_Handler too, which tells them apart by IPSR. Reserved slots are 0
 * as the architecture expects. */
__attribute__((section(".vectors"), used)) static const vector vector_table[16 + 32] = {
    {.sp = __StackTop},
    {.fn = Reset_Handler},
    {.fn = Fault_Handler}, /* NMI */
    {.fn = Fault_Handler}, /* HardFault */
    {.fn = Fault_Handler}, /* MemManage */
    {.fn = Fault_Handler}, /* BusFault */
    {.fn = Fault_Handler}, /* UsageFault */
    {0},
    {0},
    {0},
    {0},
    {.fn = Fault_Handler}, /* SVCall */
    {.fn = Fault_Handler}, /* DebugMonitor */
    {0},
    {.fn = Fault_Handler}, /* PendSV */
    {.fn = SysTick_Handler},
    {.fn = Fault_Handler}, {.fn = Fault_Handler}, {.fn = Fault_Handler}, {.fn = Fault_Handler},
    {.fn = Fault_Handler}, {.fn = Fault_Handler}, {.fn = Fault_Handler}, {.fn = Fault_Handler},
    {.fn = Fault_Handler}, {.fn = Fault_Handler}, {.fn = Fault_Handler}, {.fn = Fault_Handler},
    {.fn = Fault_Handler}, {.fn = Fault_Handler}, {.fn = Fault_Handler}, {.fn = Fault_Handler},
    {.fn = Fault_Handler}, {.fn = Fault_Handler}, {.fn = Fault_Handler}, {.fn = Fault_Handler},
    {.fn = Fault_Handler}, {.fn = Fault_Handler}, {.fn = Fault_Handler}, {.fn = Fault_Handler},
    {.fn = Fault_Handler}, {.fn = Fault_Handler}, {.fn = Fault_Handler}, {.fn = Fault_Handler},
    {.fn = Fault_Handler}, {.fn = Fault_Handler}, {.fn = Fault_Handler}, {.fn = Fault_Handler},
};
