/* SPDX-License-Identifier: MIT */
/* Cortex-M start-up for the Stellaris port: vector table, reset handler, and
 * fault handlers that report over semihosting (a fault under QEMU should end
 * the test with a message, not hang until its timeout).  A bench image
 * (STP_FW_BENCH) also fills the free RAM below the stack with a pattern, so
 * stp_stack_never_used can tell how deep the stack went. */
#include <stdint.h>

#include "stellaris.h"

/* From the linker script. */
extern uint32_t __stack_top;
extern uint32_t __data_load, __data_start, __data_end, __bss_start, __bss_end;

int main(void);
#define STACK_PATTERN 0x57AC57ACu /* a free RAM word the stack never reached */
void stp_reset_handler(void) __attribute__((noreturn));
void stp_fault_handler(void) __attribute__((noreturn));
void stp_systick_handler(void);

typedef struct vector_table {
    uint32_t *stack_top;
    void (*handlers[15])(void);
} vector_table;

/* Only the 16 system vectors: the firmware polls its peripherals, so no
 * device interrupt is ever enabled. */
__attribute__((section(".vectors"), used)) const vector_table stp_vectors = {
    &__stack_top,
    {
        stp_reset_handler,   /* reset */
        stp_fault_handler,   /* NMI */
        stp_fault_handler,   /* hard fault */
        stp_fault_handler,   /* memory management */
        stp_fault_handler,   /* bus fault */
        stp_fault_handler,   /* usage fault */
        0, 0, 0, 0,          /* reserved */
        stp_fault_handler,   /* SVCall */
        stp_fault_handler,   /* debug monitor */
        0,                   /* reserved */
        stp_fault_handler,   /* PendSV */
        stp_systick_handler, /* SysTick */
    }};

void stp_reset_handler(void)
{
    /* word copies: the linker script aligns these sections to 4 bytes.
     * volatile keeps the compiler from turning the loops into calls of
     * memcpy/memset, which must not run before .data exists. */
    volatile uint32_t *dst = &__data_start;
    const uint32_t *src = &__data_load;
    while (dst < &__data_end)
        *dst++ = *src++;
    for (dst = &__bss_start; dst < &__bss_end;)
        *dst++ = 0;
#if STP_FW_BENCH
    {
        uint32_t here; /* this frame's bottom, near the top of the stack */
        for (dst = &__bss_end; dst < &here - 16; dst++)
            *dst = STACK_PATTERN;
    }
#endif
    stp_semihost_exit(main());
}

#if STP_FW_BENCH
uint32_t stp_stack_never_used(void)
{
    const volatile uint32_t *p = &__bss_end;
    while (p < &__stack_top && *p == STACK_PATTERN)
        p++;
    return (uint32_t)(p - (const volatile uint32_t *)&__bss_end) * 4u;
}
#endif

void stp_fault_handler(void)
{
    stp_semihost_write("stipple: fault\n");
    stp_semihost_exit(3);
}
