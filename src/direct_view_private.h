/* SPDX-License-Identifier: MIT */
/* Private: the 32-bit integer helpers of the direct-drawing files, which
 * direct_view.c defines (stp_direct_udiv) and direct.c and direct_band.c
 * use; a header of its own, so direct_view.c needs nothing of direct.c's. */
#ifndef STIPPLE_DIRECT_VIEW_PRIVATE_H
#define STIPPLE_DIRECT_VIEW_PRIVATE_H

#include <stdint.h>

#include "arith_private.h" /* STP_HAVE_MUL32 */

/* floor(v / 2^s) for any int32 v, 0 <= s <= 31.  C leaves >> of a
 * negative value to the implementation: where it is the arithmetic shift
 * (every compiler the project builds with; the test folds away) that
 * shift, else the complement form, exact everywhere (gcc-avr does not
 * fold the complement form into a shift: twice the code). */
static inline int32_t stp_direct_asr(int32_t v, int s)
{
    if ((int32_t)-1 >> 1 == (int32_t)-1)
        return v >> s;
    return v >= 0 ? v >> s : (int32_t)~(~(uint32_t)v >> s);
}

static inline uint32_t stp_direct_abs(int32_t v)
{
    return v < 0 ? 0u - (uint32_t)v : (uint32_t)v;
}

/* A small helper kept a call in builds for size (-Os) on cores without a
 * 32-bit multiply (AVR), where each inlined copy of its 32-bit arithmetic
 * costs more than the call (measured one by one on the Uno image); inlined
 * as the compiler likes elsewhere (on a Cortex-M0+ the calls cost more
 * than they save). */
#if defined(__GNUC__) && defined(__OPTIMIZE_SIZE__) && !STP_HAVE_MUL32
#define STP_DIRECT_KEEP __attribute__((noinline))
#else
#define STP_DIRECT_KEEP
#endif
#define STP_DIRECT_CALL static STP_DIRECT_KEEP

/* floor(n / d) for d >= 1: shift-and-subtract over the quotient's bits
 * (no library call, no table: setup code only, never per pixel). */
uint32_t stp_direct_udiv(uint32_t n, uint32_t d);

#endif
