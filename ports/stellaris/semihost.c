/* SPDX-License-Identifier: MIT */
/* ARM semihosting and SysTick instruction counting for the Stellaris port. */
#include "stellaris.h"

#define SYS_WRITE0 0x04u
#define SYS_EXIT_EXTENDED 0x20u
#define ADP_STOPPED_APPLICATION_EXIT 0x20026u

static uint32_t semihost_call(uint32_t op, const void *arg)
{
    register uint32_t r0 __asm__("r0") = op;
    register const void *r1 __asm__("r1") = arg;
    /* the debugger (QEMU) reads r0/r1 and memory at r1, and may write r0 */
    __asm__ volatile("bkpt 0xAB" : "+r"(r0) : "r"(r1) : "memory");
    return r0;
}

void stp_semihost_write(const char *text)
{
    (void)semihost_call(SYS_WRITE0, text);
}

void stp_semihost_exit(int status)
{
    /* EXIT_EXTENDED rather than EXIT: on 32-bit ARM only the extended call
     * carries an exit status (QEMU then exits with it) */
    uint32_t block[2];
    block[0] = ADP_STOPPED_APPLICATION_EXIT;
    block[1] = (uint32_t)status;
    for (;;)
        (void)semihost_call(SYS_EXIT_EXTENDED, block);
}

char *stp_utoa(uint32_t v, char *buf)
{
    char tmp[10];
    int n = 0, i;
    do {
        tmp[n++] = (char)('0' + v % 10u);
        v /= 10u;
    } while (v);
    for (i = 0; i < n; i++)
        buf[i] = tmp[n - 1 - i];
    buf[n] = '\0';
    return buf;
}

static volatile uint32_t wraps;

void stp_systick_handler(void);
void stp_systick_handler(void)
{
    wraps++;
}

void stp_count_start(void)
{
    STP_SYST_RVR = 0x00FFFFFFu;
    STP_SYST_CVR = 0;
    /* processor clock, interrupt on wrap, enabled */
    STP_SYST_CSR = 0x7u;
    /* QEMU starts the counter lazily: until it has been seen to move, a read
     * can give 0 and a first count would be off by a whole period */
    while (STP_SYST_CVR == 0)
        ;
    wraps = 0;
}

uint32_t stp_count_calibrate(void)
{
    /* 2 instructions per iteration (subtract, branch), 2^20 iterations */
    uint32_t n = 1u << 20;
    uint64_t t0, t1;
    t0 = stp_count_now();
    /* GCC hands ARMv6-M inline assembly over in divided syntax and restores
     * unified syntax after it: ask for unified so one spelling serves all */
    __asm__ volatile(".syntax unified\n1:\tsubs %0, %0, #1\n\tbne 1b" : "+l"(n) : : "cc");
    t1 = stp_count_now();
    return t1 > t0 ? (uint32_t)((((uint64_t)2u << 20) + (t1 - t0) / 2u) / (t1 - t0)) : 0u;
}

uint64_t stp_count_now(void)
{
    uint32_t w, v;
    /* a wrap between the two reads would pair the old wrap count with the
     * new counter value: read until the wrap count is stable */
    do {
        w = wraps;
        v = STP_SYST_CVR;
    } while (w != wraps);
    return ((uint64_t)w << 24) + (0x00FFFFFFu - v);
}
