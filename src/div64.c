/* SPDX-License-Identifier: MIT */
/* 64-bit and 32-bit division in a few dozen bytes of code each
 * (STP_SMALL_DIVISION, see div64_private.h): for a size-first image where
 * the C library's division routines (about 1 KB for 64 bits and 500 bytes
 * for 32 on ARMv6-M) outweigh the rest of the arithmetic. */
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

#if STP_UDIV32_LOOP
uint32_t stp_udiv32_small(uint32_t n, uint32_t d)
{
    uint32_t q = 0;
    int shift;
    if (n < d)
        return 0;
    /* d aligned under n's top bit (below 2^32), then one step per
     * quotient bit: bits(n) - bits(d) + 1 of them (n >= d >= 1: "| 1"
     * changes neither bit length, and spares a library count's test of 0) */
    shift = stp_bit_length32(n | 1u) - stp_bit_length32(d | 1u);
    d <<= shift;
    for (; shift >= 0; shift--) {
        q <<= 1;
        if (n >= d) {
            n -= d;
            q |= 1u;
        }
        d >>= 1;
    }
    return q;
}
#endif
