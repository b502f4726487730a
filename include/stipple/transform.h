/* SPDX-License-Identifier: MIT */
/*
 * Model transforms (the seed's segment transformations): rotation, scale
 * and translation of the points a caller enters, so a spinning or moving
 * model is re-entered every frame from the caller's own, unchanging vertex
 * array (render.h, stp_renderer_set_transform).
 *
 * A transform maps a point p to m p + t: m is a 3x3 matrix of stp_fix
 * (rotations times scales, row-major), t a translation in world units.
 * Composition: each stp_transform_* call applies its operation after the
 * transform so far (t <- X t), so calls read in the order they act.
 * Precision: entries are stp_fix (step 2^-F); a rotation's entries come
 * from stp_fix_sin_deg/cos_deg (error < 2^-14), so a rotated point is
 * within about |p| 2^-13 of the exact one; products are formed in 64 bits
 * and rounded, results saturated to stp_fix's range.
 */
#ifndef STIPPLE_TRANSFORM_H
#define STIPPLE_TRANSFORM_H

#include "stipple/fix.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct stp_transform {
    stp_fix m[3][3]; /* row-major: p'_i = sum_j m[i][j] p_j + t_i */
    stp_vec3 t;      /* world units */
} stp_transform;

/* The identity (m = I, t = 0). */
void stp_transform_identity(stp_transform *t);

/* Then rotate about the world axis `axis` (0: x, 1: y, 2: z) by `degrees`
 * (any value; positive turns y towards z, z towards x, x towards y: the
 * right-hand rule in the right-handed world).  An axis outside 0..2 leaves
 * t unchanged. */
void stp_transform_rotate(stp_transform *t, int axis, stp_fix degrees);

/* Then scale by (sx, sy, sz) about the origin (entries saturate). */
void stp_transform_scale(stp_transform *t, stp_fix sx, stp_fix sy, stp_fix sz);

/* Then move by d (world units, saturating). */
void stp_transform_translate(stp_transform *t, stp_vec3 d);

/* The transformed point m p + t (rounded, saturated). */
stp_vec3 stp_transform_point(const stp_transform *t, stp_vec3 p);

/* The transformed direction m d (no translation; rounded, saturated).  For
 * normals this is exact up to length with rotations and uniform scales;
 * with non-uniform scales it is the approximation m n (not the inverse
 * transpose). */
stp_vec3 stp_transform_direction(const stp_transform *t, stp_vec3 d);

#ifdef __cplusplus
}
#endif

#endif
