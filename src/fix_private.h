/* Private helpers of the fixed-point code shared by the core's files. */
#ifndef STIPPLE_FIX_PRIVATE_H
#define STIPPLE_FIX_PRIVATE_H

#include <stdint.h>

/* Arithmetic shift right rounding toward minus infinity, for negative values
 * too (C99 leaves >> of a negative value to the implementation). */
static inline int64_t stp_asr64(int64_t v, int s)
{
    return v >= 0 ? v >> s : -((-(v + 1)) >> s) - 1;
}

/* floor(a / b) for b > 0. */
static inline int64_t stp_floordiv64(int64_t a, int64_t b)
{
    int64_t q = a / b;
    return (a % b != 0 && a < 0) ? q - 1 : q;
}

#endif
