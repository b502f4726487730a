/* SPDX-License-Identifier: MIT */
/* Private: the 32-bit integer helpers the direct-drawing files
 * (direct_view.c, direct.c, direct_band.c) share. */
#ifndef STIPPLE_DIRECT_PRIVATE_H
#define STIPPLE_DIRECT_PRIVATE_H

#include <stdint.h>

#include "stipple/direct.h"
#include "shade_fast_private.h"
#include "fix_private.h" /* stp_bit_length32 */

/* floor(v / 2^s) for any int32 v, 0 <= s <= 31 (C leaves >> of a negative
 * value to the implementation: the complement form is exact everywhere,
 * and compilers fold it to one arithmetic shift). */
static inline int32_t stp_direct_asr(int32_t v, int s)
{
    return v >= 0 ? v >> s : (int32_t)~(~(uint32_t)v >> s);
}

static inline uint32_t stp_direct_abs(int32_t v)
{
    return v < 0 ? 0u - (uint32_t)v : (uint32_t)v;
}

/* floor(n / d) for d >= 1: shift-and-subtract over the quotient's bits
 * (no library call, no table: setup code only, never per pixel). */
uint32_t stp_direct_udiv(uint32_t n, uint32_t d);

/* A frame's shading: shade_fast.c's constants and C = V R, the model's
 * rotation into view coordinates (Q1.14), for the normals. */
typedef struct stp_direct_shading {
    stp_shade_fast fast;
    int16_t rot[3][3];
} stp_direct_shading;

/* *s for a frame (direct.c): C = V R rounded from Q28, and shade_fast.c's
 * constants for light (its values checked by the caller); 0 when the
 * light's offset from the eye is not below 2^23 raw. */
int stp_direct_shading_prepare(stp_direct_shading *s, const stp_direct_view *view,
                               const stp_direct_model *model, const stp_direct_light *light);

/* The shade in [0, 1] of a face with model normal (Q1.14) and projected
 * vertices p (direct.c). */
stp_fix stp_direct_face_shade(const stp_direct_shading *s, const int16_t *normal,
                              const stp_direct_point *const p[3]);

#endif
