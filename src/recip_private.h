/* SPDX-License-Identifier: MIT */
/* Private: reciprocals and exact 64-bit division without a divide
 * instruction, for targets where C's 64-bit division is a library call
 * (ARMv6-M: libgcc's __aeabi_ldivmod, about 470-550 instructions).  The
 * shading (shade.c) divides through stp_div64_fast; on 64-bit hosts that is
 * C's operator (one instruction), elsewhere stp_div64_recip, which gives the
 * same quotient, so a picture is the same on both. */
#ifndef STIPPLE_RECIP_PRIVATE_H
#define STIPPLE_RECIP_PRIVATE_H

#include <stdint.h>

#include "stipple/config.h" /* STP_SMALL_DIVISION */
#include "arith_private.h" /* STP_WIDE_ARITH, stp_umul32x32 */

/* The reciprocal of d in [2^31, 2^32): floor((2^64 - 1) / d) - 2^32, in
 * [0, 2^32), so 2^32 + result approximates 2^64 / d to within one unit.
 * Exact (the floor, not an estimate): a 128-entry table of 16-bit seeds
 * (relative error below 1/257), two Newton steps in 32-bit arithmetic
 * (products from 16-bit halves on 32-bit targets) and a remainder
 * correction.  d outside the range returns 0. */
uint32_t stp_recip32(uint32_t d);

#if STP_HAVE_MUL32 && STP_SMALL_DIVISION
/* round(2^25 / d) for d in [513, 1024), exact (all checked: test_recip):
 * the reciprocal seeds (stp_recip32's 2^47 / m, shade_fast.c's 2^31 / m
 * at an interval's middle) computed in size-first builds, in place of
 * their tables. */
uint32_t stp_recip_seed(uint32_t d);
#endif

#if STP_HAVE_MUL32
/* stp_recip32's value or up to 2 below it (its seed and Newton steps
 * without the remainder's correction, a 32 x 32 -> 64-bit product and a
 * comparison of 64-bit values fewer), for a quotient that corrects its
 * own estimate (project_private.h).  d outside [2^31, 2^32) returns 0. */
uint32_t stp_recip32_estimate(uint32_t d);
#endif

/* floor((2^32 - 1) / d) for every d >= 1, exact (checked against C's
 * division for all 2^32 - 1 of them), without a divide instruction: d
 * normalised, the seed and a Newton step to the square of its error, one
 * remainder step for d < 2^11 and one correction (recip.c).  Compiled
 * where a 32-bit division is a library call and a build for speed has the
 * 32-bit multiply (ARMv6-M at -O2: ~60 instructions against __udivsi3's
 * ~150; STP_RECIP_U32). */
#if STP_NARROW_FORMS && !STP_HAVE_DIV
#define STP_RECIP_U32 1
#if defined(__GNUC__)
__attribute__((const)) /* a value of d alone (its seeds are constants): a caller's memory stays known */
#endif
uint32_t stp_recip_u32(uint32_t d);
#else
#define STP_RECIP_U32 0
#endif

/* floor(n / d) for d > 0, any n: exact, without a divide instruction:
 * word-by-word division by the normalised divisor's top word, one
 * stp_recip32 and a 2-by-1 step per quotient word (one or two), corrected
 * with the second word for divisors of 2^32 or more.  d = 0 returns
 * UINT64_MAX. */
uint64_t stp_udiv64_recip(uint64_t n, uint64_t d);

/* A divisor d in [1, 2^32) prepared once for several quotients: d
 * normalised (dn = d 2^s, top bit set) and stp_recip32(dn).  d = 0 makes
 * dn = 0, for which stp_udiv64_by returns UINT64_MAX. */
typedef struct stp_recip_divisor {
    uint32_t dn, v;
    int s;
} stp_recip_divisor;
void stp_recip_divisor_init(stp_recip_divisor *p, uint32_t d);

/* floor(n / d) for the prepared d, any n: stp_udiv64_recip's quotient
 * (two 2-by-1 steps, no reciprocal of its own). */
uint64_t stp_udiv64_by(const stp_recip_divisor *p, uint64_t n);

/* n / d truncated toward zero, as C's operator, for the prepared d > 0 and
 * any n but INT64_MIN with d = 1. */
int64_t stp_div64_by(const stp_recip_divisor *p, int64_t n);

/* n / d truncated toward zero, as C's operator, for d != 0 and a quotient
 * that fits int64_t (not INT64_MIN / -1), through stp_udiv64_recip. */
int64_t stp_div64_recip(int64_t n, int64_t d);

/* Reciprocals for slopes of short edges where a 32-bit division is a
 * library call (without wide arithmetic; AVR, with 16-bit pointers, keeps
 * the division and its flash): stp_slope_recip[d] = floor(2^32 / d) + 1
 * for 2 <= d < 128 (recip.c, for the edge walker, edge_walk_private.h;
 * made wherever pointers exceed 16 bits, except in size-first builds,
 * STP_SMALL_DIVISION, which divide). */
#define STP_SLOPE_RECIP_SIZE 128
#if UINTPTR_MAX > 0xFFFFu && !STP_SMALL_DIVISION
extern const uint32_t stp_slope_recip[STP_SLOPE_RECIP_SIZE];
#endif

/* The shading's 64-bit division: C's operator where it is one instruction,
 * stp_div64_recip elsewhere (the same quotient). */
#if STP_WIDE_ARITH
#define stp_div64_fast(n, d) ((int64_t)(n) / (int64_t)(d))
#else
#define stp_div64_fast(n, d) stp_div64_recip((int64_t)(n), (int64_t)(d))
#endif

#endif
