/* SPDX-License-Identifier: MIT */
/* Private: the geometry stage's step for an entered point on the
 * renderer's state, the one polygon entry, mesh entry (render.c, mesh.c)
 * and the shadow maps (shadow.c) take; render.c sets r->geometry
 * (stp_render_geometry_update).  Inline, no .c file of its own. */
#ifndef STIPPLE_GEOMETRY_STAGE_PRIVATE_H
#define STIPPLE_GEOMETRY_STAGE_PRIVATE_H

#include "renderer_state.h"
#include "view_private.h" /* stp_view_point_two_steps, STP_VIEW_TRANSFORM_POINT */

#if !STP_PLAYBACK_ONLY
#define STP_GEOMETRY_VIEW 0
#define STP_GEOMETRY_COMPOSED 1
#define STP_GEOMETRY_TWO_STEPS 2

/* The geometry stage for an entered point *p (model coordinates, not out):
 * its view coordinates in *out, each saturated; returns 1 when the model
 * transform
 * (two steps: stp_view_point_two_steps, view.c) saturated it: the point
 * lies beyond what the coordinates hold (the caller reports
 * STP_ERR_RANGE), else 0. */
#if STP_WIDE_ARITH
STP_HOT_INLINE int stp_render_point_at_view_in(const stp_renderer *r, const stp_vec3 *p, stp_vec3 *out, int bounded)
{
    if (r->geometry == STP_GEOMETRY_TWO_STEPS)
        return stp_view_point_two_steps(&r->model, &r->to_view, *p, out);
    stp_view_transform_point_wide_in(&r->point_view, *p, out, bounded); /* inline where 64-bit products are */
    return 0;
}

STP_HOT_INLINE int stp_render_point_at_view(const stp_renderer *r, const stp_vec3 *p, stp_vec3 *out)
{
    return stp_render_point_at_view_in(r, p, out, 0);
}

/* stp_render_point_at_view for a point whose view coordinates the caller
 * knows below 2^29 in magnitude (mesh.c's box_inside): the same values,
 * without the saturation tests where they are inline (STP_WIDE_ARITH:
 * 3 instructions a coordinate); elsewhere stp_render_point_at_view */
STP_HOT_INLINE int stp_render_point_at_view_bounded(const stp_renderer *r, const stp_vec3 *p, stp_vec3 *out)
{
    return stp_render_point_at_view_in(r, p, out, 1);
}
#else
STP_HOT_INLINE int stp_render_point_at_view(const stp_renderer *r, const stp_vec3 *p, stp_vec3 *out)
{
    if (r->geometry == STP_GEOMETRY_TWO_STEPS)
        return stp_view_point_two_steps(&r->model, &r->to_view, *p, out);
    stp_view_transform_point_at(&r->point_view, p, out);
    return 0;
}

#define stp_render_point_at_view_bounded stp_render_point_at_view
#endif

/* stp_render_point_at_view of a point passed by value */
STP_HOT_INLINE int stp_render_point_to_view(const stp_renderer *r, stp_vec3 p, stp_vec3 *out)
{
    return stp_render_point_at_view(r, &p, out);
}
#endif

#endif
