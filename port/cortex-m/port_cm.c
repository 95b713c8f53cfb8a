/* SPDX-License-Identifier: MIT */
/* Cortex-M port for QEMU's MPS2 boards: output and exit through Arm semihosting (`bkpt
 * 0xab`), a SysTick tick counter, and stack-use measurement. See port_cm.h.
 *
 * Semihosting needs QEMU's `-semihosting-config enable=on` (qemu/run.sh passes it). On real
 * hardware without a debugger attached, `bkpt` would fault instead. */
#include <stdint.h>
#include "port_cm.h"

void SysTick_Handler(void);

/* Semihosting operation numbers and exit reasons (Arm "Semihosting for AArch32 and
 * AArch64", version 2.0). */
#define SYS_OPEN 0x01u
#define SYS_WRITEC 0x03u
#define SYS_WRITE 0x05u
#define SYS_EXIT 0x18u
#define SYS_EXIT_EXTENDED 0x20u
#define ADP_STOPPED_APPLICATION_EXIT 0x20026u
#define ADP_STOPPED_RUNTIME_ERROR_UNKNOWN 0x20023u
#define SH_OPEN_MODE_W 4u

/* One semihosting call: operation in r0, parameter (usually a pointer to an argument
 * block) in r1, result in r0. The "memory" clobber makes the compiler store the argument
 * block before the trap and reload anything the host wrote. */
static uint32_t semihost(uint32_t op, const void *arg)
{
    register uint32_t r0 __asm__("r0") = op;
    register const void *r1 __asm__("r1") = arg;
    __asm__ volatile("bkpt 0xab" : "+r"(r0) : "r"(r1) : "memory");
    return r0;
}

/* Handle of the host console, opened on first use. Arm semihosting has no predefined
 * stdout handle: the console is the special file ":tt" opened for writing. */
static uint32_t console_handle;
static int console_state; /* 0 not tried, 1 open, -1 open failed */

void port_write(const char *s, uint32_t n)
{
    if (console_state == 0) {
        uint32_t args[3];
        args[0] = (uint32_t)":tt";
        args[1] = SH_OPEN_MODE_W;
        args[2] = 3u; /* strlen(":tt") */
        console_handle = semihost(SYS_OPEN, args);
        console_state = console_handle == 0xFFFFFFFFu ? -1 : 1;
    }
    if (console_state > 0) {
        /* SYS_WRITE returns the number of bytes *not* written; retry the rest, but give
         * up if the host makes no progress so a closed pipe cannot hang the target. */
        while (n > 0u) {
            uint32_t args[3];
            uint32_t left;
            args[0] = console_handle;
            args[1] = (uint32_t)s;
            args[2] = n;
            left = semihost(SYS_WRITE, args);
            if (left >= n) {
                break;
            }
            s += n - left;
            n = left;
        }
    } else {
        /* Byte at a time: slow, but needs no handle and no NUL terminator. */
        while (n > 0u) {
            semihost(SYS_WRITEC, s);
            s++;
            n--;
        }
    }
}

void port_exit(int code)
{
    uint32_t args[2];
    args[0] = ADP_STOPPED_APPLICATION_EXIT;
    args[1] = (uint32_t)code;
    semihost(SYS_EXIT_EXTENDED, args);
    /* Only reached if the host lacks SYS_EXIT_EXTENDED: plain SYS_EXIT can still tell
     * success from failure (the AArch32 form takes the reason in r1, not a block). */
    semihost(SYS_EXIT, (const void *)(code == 0 ? ADP_STOPPED_APPLICATION_EXIT
                                                : ADP_STOPPED_RUNTIME_ERROR_UNKNOWN));
    for (;;) {
        __asm__ volatile("wfi");
    }
}

/* ---- SysTick tick counter ---------------------------------------------------------- */

#define SYST_CSR (*(volatile uint32_t *)0xE000E010u)
#define SYST_RVR (*(volatile uint32_t *)0xE000E014u)
#define SYST_CVR (*(volatile uint32_t *)0xE000E018u)
#define SCB_ICSR (*(volatile uint32_t *)0xE000ED04u)
#define SYST_CSR_ENABLE 1u
#define SYST_CSR_TICKINT 2u
#define SYST_CSR_CLKSOURCE_CPU 4u
#define SCB_ICSR_PENDSTSET (1u << 26)
#define SYST_MAX 0xFFFFFFu

static volatile uint32_t systick_wraps;
static uint32_t systick_base;
static int systick_running;

/* Counts 2^24-tick wraps so that the 24-bit SysTick extends to 32 bits. */
void SysTick_Handler(void)
{
    systick_wraps++;
}

static uint32_t systick_read(void)
{
    uint32_t primask;
    uint32_t hi;
    uint32_t lo;
    /* With interrupts masked the wrap count cannot change under us; a wrap that happened
     * but is not yet counted shows as a pending SysTick, and then the counter is read
     * again so it is certainly past that wrap. */
    __asm__ volatile("mrs %0, primask\n\tcpsid i" : "=r"(primask)::"memory");
    hi = systick_wraps;
    lo = SYST_CVR;
    if ((SCB_ICSR & SCB_ICSR_PENDSTSET) != 0u) {
        hi++;
        lo = SYST_CVR;
    }
    __asm__ volatile("msr primask, %0" ::"r"(primask) : "memory");
    /* The counter runs 2^24-1, ..., 1, 0, reload, and the interrupt pends as it reaches 0,
     * so 0 is the first tick of the next wrap: elapsed ticks in this wrap = (2^24 - lo)
     * mod 2^24. This also makes the state right after the CVR write (0, no wrap counted)
     * read as 0. */
    return (hi << 24) + ((0u - lo) & SYST_MAX);
}

uint32_t port_cycles(void)
{
    if (!systick_running) {
        SYST_RVR = SYST_MAX;
        SYST_CVR = 0u;
        SYST_CSR = SYST_CSR_ENABLE | SYST_CSR_TICKINT | SYST_CSR_CLKSOURCE_CPU;
        systick_running = 1;
        systick_base = systick_read();
    }
    return systick_read() - systick_base;
}

/* ---- stack use ---------------------------------------------------------------------- */

uint32_t port_stack_used(void)
{
    const volatile uint32_t *p = __StackLimit;
    while (p < __StackTop && *p == PORT_STACK_PAINT) {
        p++;
    }
    return (uint32_t)__StackTop - (uint32_t)p;
}

uint32_t port_stack_size(void)
{
    return (uint32_t)__StackTop - (uint32_t)__StackLimit;
}
