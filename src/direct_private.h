/* SPDX-License-Identifier: MIT */
/* Private: what direct.c gives direct_band.c (the frame's shading), with
 * the integer helpers of direct_view_private.h. */
#ifndef STIPPLE_DIRECT_PRIVATE_H
#define STIPPLE_DIRECT_PRIVATE_H

#include <stdint.h>

#include "stipple/direct.h"
#include "shade_fast_private.h"
#include "view_private.h" /* stp_model_frame */
#include "direct_view_private.h" /* STP_DIRECT_CALL */

/* Direct drawing's Z buffer (stp_direct_frame_depth): not in the compact
 * form, and only with the renderer's (config.h) */
#define STP_DIRECT_DEPTH (!STP_DIRECT_COMPACT && STP_WITH_ZBUFFER)

/* A light prepared for a view (include/stipple/direct.h: stp_direct_lit):
 * the face shader's constants (shade_fast.c's stp_shade_fast_prepare for
 * the one light in view coordinates, eye at the view origin, no
 * highlight).  They depend on the view and the light only, not on the
 * model, so a program whose view and light are fixed may carry them as
 * data made on the host in its own configuration (the layout follows
 * STP_MAX_LIGHTS, STP_WITH_SPECULAR and the target's arithmetic) and never
 * link the prepare (ports/arduino/src/stipple_spin.c). */
struct stp_direct_lit {
    stp_shade_fast fast;
};

/* *lit for light seen from view (its values checked by the caller); 0
 * when the light's offset from the eye is not below 2^23 raw. */
int stp_direct_light_prepare(stp_direct_lit *lit, const stp_direct_view *view, const stp_direct_light *light);

/* A frame's shading: the prepared light and the face stage's model frame
 * (view_private.h: the rotation of model normals into view coordinates
 * and the eye in model coordinates, as the mesh route forms them). */
typedef struct stp_direct_shading {
    const stp_shade_fast *fast;
#if STP_DIRECT_COMPACT
    int16_t rot[3][3]; /* the compact form: C = V R rounded to Q1.14, its
                          composite and normal rotation (the scale is 1) */
#else
    stp_model_frame frame;
    stp_side_estimate side_estimate; /* the face side's first, 32-bit test */
    stp_transform model;             /* the model's (stp_direct_model_transform) */
#endif
} stp_direct_shading;

/* *s for a frame (direct.c): lit's shader and the model frame of view
 * and model (in the compact form C = V R, view.c's stp_view_compose_q14);
 * 0 when the model frame is not usable (rot not a rotation, or a scale
 * below 2^-6; in the compact form C leaving Q1.14), else 1. */
int stp_direct_shading_prepare(stp_direct_shading *s, const stp_direct_lit *lit, const stp_direct_view *view,
                               const stp_direct_model *model);

/* The shade in [0, 1] of a front face (the side its normal points to
 * seen) with model normal (Q1.14) and projected vertices p (direct.c). */
stp_fix stp_direct_face_shade(const stp_direct_shading *s, const int16_t *normal,
                              const stp_direct_point *const p[3]);

#endif
