/* SPDX-License-Identifier: MIT */
/*
 * stp_fix: the core's fixed-point scalar.
 *
 * Format: signed two's complement in 32 bits with STP_FIX_FRAC_BITS (F)
 * fractional bits.  Default F = 16: range [-32768, 32768), step 2^-16.
 * Products and quotients are formed in 64 bits and then saturated to
 * [STP_FIX_MIN, STP_FIX_MAX]: no operation here overflows or is undefined
 * for any input.  Additions that can overflow use stp_fix_add/sub, which
 * saturate; plain + is used only where the operands' ranges are documented
 * to make overflow impossible.
 *
 * Rounding: mul rounds to nearest (ties away from zero); div truncates toward
 * zero; sqrt returns the floor of the exact root (STP_SQRT_FAST: rounded
 * down within 2^-29 relative, a few units of the root at most).
 */
#ifndef STIPPLE_FIX_H
#define STIPPLE_FIX_H

#include <stdint.h>
#include "stipple/config.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef int32_t stp_fix;

#define STP_FIX_ONE ((stp_fix)1 << STP_FIX_FRAC_BITS)
#define STP_FIX_HALF ((stp_fix)1 << (STP_FIX_FRAC_BITS - 1))
#define STP_FIX_MAX ((stp_fix)INT32_MAX)
#define STP_FIX_MIN ((stp_fix)-INT32_MAX) /* symmetric: negation never overflows */

/* Integer n to stp_fix; saturates outside the range. */
stp_fix stp_fix_from_int(int32_t n);

/* num/den as stp_fix, rounded to nearest; den == 0 saturates to the sign of
 * num (0/0 gives 0). */
stp_fix stp_fix_from_ratio(int32_t num, int32_t den);

/* Saturating a + b and a - b. */
stp_fix stp_fix_add(stp_fix a, stp_fix b);
stp_fix stp_fix_sub(stp_fix a, stp_fix b);

/* a * b, rounded to nearest, saturated. */
stp_fix stp_fix_mul(stp_fix a, stp_fix b);

/* a / b, truncated, saturated; b == 0 gives STP_FIX_MAX or STP_FIX_MIN by the
 * sign of a (0 for a == 0). */
stp_fix stp_fix_div(stp_fix a, stp_fix b);

/* Square root of a >= 0 (a < 0 gives 0).  Error: see the file comment. */
stp_fix stp_fix_sqrt(stp_fix a);

/* Square root of a 64-bit value v holding a number with 2F fractional bits
 * (a product of two stp_fix), returned with F fractional bits, saturated. */
stp_fix stp_fix_sqrt_wide(int64_t v);

/* log2(a) for a > 0, absolute error < 2^-(F-1); a <= 0 gives STP_FIX_MIN. */
stp_fix stp_fix_log2(stp_fix a);

/* 2^a, relative error < 2^-(F-2); saturates above, 0 below the range. */
stp_fix stp_fix_exp2(stp_fix a);

/* base^e for base > 0 (base <= 0 gives 0), through log2/exp2. */
stp_fix stp_fix_pow(stp_fix base, stp_fix e);

/* sin and cos of an angle in degrees (any value), absolute error < 2^-14. */
stp_fix stp_fix_sin_deg(stp_fix degrees);
stp_fix stp_fix_cos_deg(stp_fix degrees);

/* Three-component vector of stp_fix. */
typedef struct stp_vec3 {
    stp_fix x, y, z;
} stp_vec3;

/* Dot product, in 64 bits then rounded and saturated to stp_fix. */
stp_fix stp_vec3_dot(stp_vec3 a, stp_vec3 b);

/* UNITY (Algorithm 10.2): *out = v/|v|; returns |v| (saturated).  Works at
 * full precision for any non-zero v, however short or long (v is scaled up
 * before the root).  A zero vector returns 0 and leaves *out = {0,0,0}: the
 * caller must treat it as "no direction". */
stp_fix stp_vec3_unity(stp_vec3 v, stp_vec3 *out);

#ifdef __cplusplus
}
#endif

#endif
