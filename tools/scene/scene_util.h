/* SPDX-License-Identifier: MIT */
/*
 * Helpers over a loaded stp_scene (host code).
 */
#ifndef STIPPLE_TOOLS_SCENE_UTIL_H
#define STIPPLE_TOOLS_SCENE_UTIL_H

#include "scene.h"

/* Axis-aligned bounds of all polygon vertices and analytic primitives
 * (spheres and cones exactly, so they also enclose the tessellations).
 * Returns 0, or -1 when the scene is NULL or has no geometry (lo and hi are
 * then left untouched).  lo or hi may be NULL. */
int stp_scene_bounds(const stp_scene *scene, stp_scene_vec3 *lo, stp_scene_vec3 *hi);

#endif
