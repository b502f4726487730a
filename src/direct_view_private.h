/* SPDX-License-Identifier: MIT */
/* Private: the call attribute of the direct-drawing files' helpers; a
 * header of its own, so direct_view.c needs nothing of direct.c's.  Shifts
 * and magnitudes: arith_private.h; division: div64_private.h. */
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

/* A helper with several callers kept one call in builds for size on AVR
 * (STP_LEAN_CODE) and in size-first builds (-Os with STP_SMALL_DIVISION),
 * inlined elsewhere (a call per face cost the Cortex-M0+ direct frame
 * 8 000 instructions at -O2). */
#if defined(__GNUC__) && defined(__OPTIMIZE_SIZE__) && (STP_LEAN_CODE || STP_SMALL_DIVISION)
#define STP_DIRECT_SMALL static __attribute__((noinline))
#elif defined(__GNUC__)
#define STP_DIRECT_SMALL static inline __attribute__((always_inline))
#else
#define STP_DIRECT_SMALL static
#endif

#endif
