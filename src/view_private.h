/* SPDX-License-Identifier: MIT */
/* Private: the view frame shared by the polygon renderer and the ray
 * tracer, and the cross product the core's files share. */
#ifndef STIPPLE_VIEW_PRIVATE_H
#define STIPPLE_VIEW_PRIVATE_H

#include "stipple/render.h"

/* A view turned into what both renderers use: an orthonormal left-handed
 * basis (unit stp_vec3: x right, y up, z forward along the line of sight),
 * the centre of projection and the focal length: perspective, pixels per
 * unit of x/z; parallel, pixels per world unit (F fractional bits). */
typedef struct stp_view_frame {
    stp_vec3 from, right, up, forward;
    stp_fix focal, hither;
    stp_projection projection;
} stp_view_frame;

/* The frame of view v on a width x height device.  Returns STP_OK,
 * STP_ERR_VIEW (from == at, up along the line of sight, fov outside
 * (0, 180), hither or window_half <= 0) or STP_ERR_ARG (a bad projection);
 * *out is written only on success. */
int stp_view_frame_make(const stp_view *v, uint32_t width, uint32_t height, stp_view_frame *out);

/* World to view coordinates: the view's axes and the eye's coordinate
 * along each (from . axis, 2F fractional bits, below 2^49), so a point's
 * view coordinates are p . axis - from . axis, exact in 64 bits. */
typedef struct stp_view_transform {
    stp_vec3 right, up, forward;
    int64_t from_right, from_up, from_forward;
    /* the same split for 32-bit targets (view.c): from . axis = high 2^16
     * + low, low in [0, 2^16), for right, up, forward */
    int64_t from_high[3];
    int32_t from_low[3];
} stp_view_transform;

void stp_view_transform_make(const stp_view_frame *vf, stp_view_transform *out);
/* The transform of axes right, up, forward (unit: |component| < 2^17) and
 * eye from, as stp_view_transform_make forms it from a frame. */
void stp_view_transform_of_axes(stp_vec3 right, stp_vec3 up, stp_vec3 forward, stp_vec3 from,
                                stp_view_transform *out);

/* p (world) in view coordinates, each floor((p - from) . axis), saturated. */
void stp_view_transform_point(const stp_view_transform *t, stp_vec3 p, stp_vec3 *out);

/* Which side of triangle v (world coordinates) an eye at from (perspective)
 * or looking along forward (parallel: unit, F fractional bits) sees, by the
 * exact sign of ((v1 - v0) x (v2 - v0)).(from - v0), or of -N.forward:
 * 1 the front (counter-clockwise seen from the eye in the left-handed view
 * system), -1 the back or edge-on, 0 not decided: a zero normal, or
 * coordinates too far apart to decide in 64 bits or to be sure that none of
 * the vertices' view coordinates saturates (differences from one another
 * and from `from` of 2^29 raw units or more; see view.c). */
int stp_view_triangle_side(stp_vec3 from, stp_vec3 forward, int parallel, const stp_vec3 *v);

/* The one perspective projection: project_private.h. */
#include "project_private.h"

/* a x b with F fractional bits, each component saturated. */
stp_vec3 stp_vec3_cross(stp_vec3 a, stp_vec3 b);

#endif
