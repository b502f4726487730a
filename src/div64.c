/* SPDX-License-Identifier: MIT */
/* 64-bit division in a few dozen bytes of code (STP_SMALL_DIVISION, see
 * div64_private.h): for a playback-only image where the C library's 64-bit
 * division routines (about 1 KB on ARMv6-M) outweigh the rest of the
 * rasterizer's arithmetic. */
#include "div64_private.h"

#if STP_SMALL_DIVISION
int64_t stp_div64_trunc(int64_t num, int64_t den)
{
    uint64_t n = num < 0 ? 0u - (uint64_t)num : (uint64_t)num;
    uint64_t d = den < 0 ? 0u - (uint64_t)den : (uint64_t)den;
    uint64_t q = 0, bit = 1;
    /* align d's top bit with n's (restoring division, one bit a step) */
    while (d < n && (d >> 63) == 0) {
        d <<= 1;
        bit <<= 1;
    }
    while (bit != 0) {
        if (n >= d) {
            n -= d;
            q |= bit;
        }
        d >>= 1;
        bit >>= 1;
    }
    /* negated as unsigned: INT64_MIN / 1 has no positive counterpart */
    return (int64_t)((num < 0) != (den < 0) ? 0u - q : q);
}
#endif
