/* SPDX-License-Identifier: MIT */
/* Private: the division of the direct-drawing files, which direct_view.c
 * defines (stp_direct_udiv) and direct.c and direct_band.c use, and their
 * call attribute; a header of its own, so direct_view.c needs nothing of
 * direct.c's.  Shifts and magnitudes: arith_private.h. */
#ifndef STIPPLE_DIRECT_VIEW_PRIVATE_H
#define STIPPLE_DIRECT_VIEW_PRIVATE_H

#include <stdint.h>

#include "arith_private.h" /* STP_LEAN_CODE, stp_asr32, stp_abs32 */

/* A small helper kept a call in builds for size (-Os) on cores without a
 * 32-bit multiply (AVR), where each inlined copy of its 32-bit arithmetic
 * costs more than the call (measured one by one on the Uno image); inlined
 * as the compiler likes elsewhere (on a Cortex-M0+ the calls cost more
 * than they save). */
#if defined(__GNUC__) && STP_LEAN_CODE
#define STP_DIRECT_KEEP __attribute__((noinline))
#else
#define STP_DIRECT_KEEP
#endif
#define STP_DIRECT_CALL static STP_DIRECT_KEEP

/* floor(n / d) for d >= 1: shift-and-subtract over the quotient's bits
 * (no table; on AVR the C library's division, the same loop: setup code
 * only, never per pixel). */
uint32_t stp_direct_udiv(uint32_t n, uint32_t d);

#endif
