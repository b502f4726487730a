/* SPDX-License-Identifier: MIT */
/*
 * Stellaris (LM3S) bare-metal port: registers, semihosting, instruction
 * counting.  Only what the stipple firmware uses.
 */
#ifndef STIPPLE_PORTS_STELLARIS_H
#define STIPPLE_PORTS_STELLARIS_H

#include <stdint.h>

#define STP_REG(addr) (*(volatile uint32_t *)(uintptr_t)(addr))

/* System control: run-mode clock gating (a real part ignores peripherals
 * whose clock is off; QEMU does not care, real silicon does). */
#define STP_SYSCTL_RCGC1 STP_REG(0x400FE104u) /* bit 4 SSI0, bit 12 I2C0 */
#define STP_SYSCTL_RCGC2 STP_REG(0x400FE108u) /* bit n: GPIO port A + n */

/* GPIO ports (PL061-like): DATA is masked by address bits 9:2, so writing at
 * base + (mask << 2) touches only the pins in mask. */
#define STP_GPIO_A 0x40004000u
#define STP_GPIO_B 0x40005000u
#define STP_GPIO_C 0x40006000u
#define STP_GPIO_D 0x40007000u
#define STP_GPIO_E 0x40024000u
#define STP_GPIO_DATA(port, mask) STP_REG((port) + ((uint32_t)(mask) << 2))
#define STP_GPIO_DIR(port) STP_REG((port) + 0x400u)
#define STP_GPIO_AFSEL(port) STP_REG((port) + 0x420u)
#define STP_GPIO_DEN(port) STP_REG((port) + 0x51Cu)

/* SysTick */
#define STP_SYST_CSR STP_REG(0xE000E010u)
#define STP_SYST_RVR STP_REG(0xE000E014u)
#define STP_SYST_CVR STP_REG(0xE000E018u)

/* Semihosting (ARM's interface, BKPT 0xAB on M-profile). */
void stp_semihost_write(const char *text);
void stp_semihost_exit(int status) __attribute__((noreturn));

/* Decimal text of v into buf (at least 11 bytes); returns buf. */
char *stp_utoa(uint32_t v, char *buf);

/* Instruction counting with SysTick.  Under QEMU -icount shift=0 every
 * emulated instruction advances the clock by one tick, so the counts are
 * emulated instructions and the same on every run.  stp_count_start starts
 * the counter (once); stp_count_now returns ticks since then, 64 bits wide
 * (the 24-bit counter's wraps are counted by the SysTick interrupt). */
void stp_count_start(void);
uint64_t stp_count_now(void);

/* Instructions per SysTick tick, measured over a loop of known length
 * (QEMU clocks SysTick from the emulated system clock, so a tick is a fixed
 * number of instructions under -icount shift=0; the ratio depends on the
 * clock configuration, not on the code).  0 if the counter did not move. */
uint32_t stp_count_calibrate(void);

/* Bench images (STP_FW_BENCH): bytes of RAM between the static data and
 * the stack that the stack has not reached since reset (startup.c fills
 * them with a pattern; a word the program happens to leave holding it
 * counts as unreached).  0: the stack reached the static data, whose last
 * words may then have been overwritten. */
uint32_t stp_stack_never_used(void);

#endif
