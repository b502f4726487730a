/* SPDX-License-Identifier: MIT */
/* Private: the 64-bit division of size-first builds (div64.c), for the
 * edge walker and the raster. */
#ifndef STIPPLE_DIV64_PRIVATE_H
#define STIPPLE_DIV64_PRIVATE_H

#include <stdint.h>

#include "stipple/config.h" /* STP_SMALL_DIVISION */

/* num / den truncated toward zero for den != 0 and a quotient that fits:
 * C's operator, or with STP_SMALL_DIVISION (stipple/config.h) the bit-serial loop
 * of div64.c, so the C library's 64-bit division is not linked. */
#if STP_SMALL_DIVISION
int64_t stp_div64_trunc(int64_t num, int64_t den);
#define STP_DIV64(num, den) stp_div64_trunc((int64_t)(num), (int64_t)(den))
#else
#define STP_DIV64(num, den) ((int64_t)(num) / (int64_t)(den))
#endif

#endif
