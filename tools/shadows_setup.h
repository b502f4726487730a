/* SPDX-License-Identifier: MIT */
/*
 * Host side: shadow maps that cover a scene, for stp_tool_render and the
 * stipple command (render.h, stp_renderer_set_shadow_map).
 */
#ifndef STIPPLE_TOOLS_SHADOWS_SETUP_H
#define STIPPLE_TOOLS_SHADOWS_SETUP_H

#include <stddef.h>
#include <stdint.h>
#include "scene.h"
#include "stipple/stipple.h"

/* The shadow view with which a light at `light` sees the sphere (centre,
 * radius): target the centre; with d = |light - centre|, fov =
 * 2 asin(radius / d) plus 2 degrees (at most 170), near = 0.9 (d - radius)
 * (at least d / 1000).  A light within 1.05 radius of the centre (inside
 * what it must cover) cannot see all of it through one map: fov 150
 * degrees towards the centre, near = radius / 1000; what lies outside
 * that pyramid is lit by it (render.h).  Returns 0, or -1 for a light at
 * the centre. */
int stp_tool_shadow_view(stp_scene_vec3 centre, double radius, stp_scene_vec3 light,
                         stp_shadow_view *out);

/* Give each light of `lighting` (what was passed to stp_renderer_set_lighting, light
 * positions in world units) a resolution x resolution map.  What a map
 * covers: the scene's bounding sphere, or when smaller the sphere the view
 * sees, centred where the line of sight passes the scene's centre (its
 * depth d along the line of sight, at least a quarter of the scene's
 * radius; parallel views: the look-at point), with twice the radius of the
 * window there (d tan(fov / 2), or window_half, times the aspect width /
 * height when above 1): 'at' only gives the direction, as NFF's SPD rings
 * puts it right next to the eye, so the map's texels are not spent on a
 * floor that reaches far out of the picture.  maps holds map_count >=
 * lighting->count * resolution^2 entries, light j's map from
 * maps + j * resolution^2.  Call after stp_renderer_set_view and stp_renderer_set_lighting,
 * before entering any polygon (the maps are drawn as polygons are
 * entered); keep maps until stp_renderer_render returns.  Returns 0, or -1 with a
 * message in err. */
int stp_tool_shadows_setup(stp_renderer *r, const stp_scene *scene, const stp_view *view,
                           double aspect, const stp_lighting *lighting, uint32_t resolution,
                           uint16_t *maps, size_t map_count, char *err, size_t err_size);

#endif
