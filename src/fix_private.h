/* SPDX-License-Identifier: MIT */
/* Private helpers of the fixed-point code shared by the core's files. */
#ifndef STIPPLE_FIX_PRIVATE_H
#define STIPPLE_FIX_PRIVATE_H

#include <stdint.h>

#include "stipple/fix.h"

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


/* Where segment a-b crosses a plane, given the signed distances da >= 0 > db
 * or the reverse: the fraction t of the way from a, in Q30 ([0, 2^30]). */
static inline int64_t stp_clip_fraction(int64_t da, int64_t db)
{
    int64_t den = da - db;
    /* bring the distances below 2^32 so da << 30 cannot overflow */
    while (den >= ((int64_t)1 << 32) || den <= -((int64_t)1 << 32) ||
           da >= ((int64_t)1 << 32) || da <= -((int64_t)1 << 32)) {
        da /= 2;
        db /= 2;
        den = da - db;
    }
    return den == 0 ? 0 : (da * ((int64_t)1 << 30)) / den;
}

/* a + (b - a) t with t in Q30, saturated. */
static inline stp_fix stp_lerp_fix(stp_fix a, stp_fix b, int64_t t)
{
    return stp_fix_sat64(a + stp_asr64(((int64_t)b - a) * t, 30));
}

/* UNITY of a - b: *out = (a - b)/|a - b|, returning |a - b| with F
 * fractional bits in 64 bits.  The difference of two stp_fix can exceed the
 * range (points near opposite ends of it), and so can the length of a
 * difference within it: the difference is formed in 64 bits and halved
 * until its length fits (components below 2^30), which keeps its
 * direction, and the length is scaled back unsaturated (below 2^33). */
static inline int64_t stp_unity_diff(stp_vec3 a, stp_vec3 b, stp_vec3 *out)
{
    const int64_t lim = ((int64_t)1 << 30) - 1;
    int64_t dx = (int64_t)a.x - b.x, dy = (int64_t)a.y - b.y, dz = (int64_t)a.z - b.z;
    int shift = 0;
    stp_vec3 d;
    while (dx > lim || dx < -lim || dy > lim || dy < -lim || dz > lim || dz < -lim) {
        dx /= 2;
        dy /= 2;
        dz /= 2;
        shift++;
    }
    d.x = (stp_fix)dx;
    d.y = (stp_fix)dy;
    d.z = (stp_fix)dz;
    return (int64_t)stp_vec3_unity(d, out) * ((int64_t)1 << shift);
}

#endif
