/* SPDX-License-Identifier: MIT */
/* Private: the 64-bit and 32-bit divisions of size-first builds (div64.c),
 * for the edge walkers, the raster and direct drawing. */
#ifndef STIPPLE_DIV64_PRIVATE_H
#define STIPPLE_DIV64_PRIVATE_H

#include <stdint.h>

#include "stipple/config.h" /* STP_SMALL_DIVISION */
#include "arith_private.h"  /* STP_HAVE_MUL32, STP_HAVE_DIV */

/* num / den truncated toward zero for den != 0 and a quotient that fits:
 * C's operator, or with STP_SMALL_DIVISION (stipple/config.h) the bit-serial loop
 * of div64.c, so the C library's 64-bit division is not linked. */
#if STP_SMALL_DIVISION
int64_t stp_div64_trunc(int64_t num, int64_t den);
#define STP_DIV64(num, den) stp_div64_trunc((int64_t)(num), (int64_t)(den))
#else
#define STP_DIV64(num, den) ((int64_t)(num) / (int64_t)(den))
#endif

/* floor(n / d) for d >= 1: C's operator, or with STP_SMALL_DIVISION on a
 * core with a 32-bit multiply and no divide instruction (ARMv6-M, where
 * the C library's 32-bit division is routines of about 500 bytes) the
 * bit-serial loop of div64.c (STP_UDIV32_LOOP 1).  Without the multiply
 * (AVR) the C library's division is such a loop already; with a divide
 * instruction (Cortex-M3, hosts) it is one instruction. */
#if STP_SMALL_DIVISION && STP_HAVE_MUL32 && !STP_HAVE_DIV
#define STP_UDIV32_LOOP 1
uint32_t stp_udiv32_small(uint32_t n, uint32_t d);
#define STP_UDIV32(n, d) stp_udiv32_small((n), (d))
#else
#define STP_UDIV32_LOOP 0
#define STP_UDIV32(n, d) ((uint32_t)(n) / (uint32_t)(d))
#endif

#endif
