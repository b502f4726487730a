/* SPDX-License-Identifier: MIT */
/* Private: what direct.c gives direct_band.c (the frame's shading), with
 * the integer helpers of direct_view_private.h. */
#ifndef STIPPLE_DIRECT_PRIVATE_H
#define STIPPLE_DIRECT_PRIVATE_H

#include <stdint.h>

#include "stipple/direct.h"
#include "shade_fast_private.h"
#include "direct_view_private.h" /* stp_direct_udiv, STP_DIRECT_CALL */

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
