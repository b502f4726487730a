/* SPDX-License-Identifier: MIT */
/*
 * Host side: the camera of a render or an animation (--eye, --at, --up,
 * --orbit, --elevation): the view each frame is drawn from, and the scene
 * handed to the renderer with that view in place of its own.  Distances
 * are in the scene file's units, angles in degrees.
 */
#ifndef STIPPLE_TOOLS_CAMERA_H
#define STIPPLE_TOOLS_CAMERA_H

#include <stddef.h>
#include "render_scene.h"
#include "scene.h"

/* The motion of an animation. */
typedef struct stp_tool_motion {
    int frames;               /* 1..STP_TOOL_MAX_FRAMES */
    double orbit_degrees;     /* the whole turn about the up axis through the
                                 look-at point, spread over the frames: frame
                                 i is turned by orbit * i / frames, so 360
                                 loops without a repeated frame */
    int elevation_given;
    double elevation_degrees; /* the eye's angle above the plane through the
                                 look-at point square to up, -89..89 */
} stp_tool_motion;

#define STP_TOOL_MAX_FRAMES 10000

/* 1 when opt gives --eye, --at or --up. */
int stp_tool_camera_wanted(const stp_tool_options *opt);

/* The view of frame `frame` (0..frames-1; motion NULL: a still, frame 0):
 * the scene's (stp_tool_view_of) with --eye and --at keys interpolated
 * linearly along the frames (keys evenly spaced, the first at frame 0 and
 * the last at the last frame), --up, then turned by the orbit and raised
 * to the elevation.  *turn_radians gets the orbit's angle (for the
 * lights).  Returns 0, or -1 with a message: an empty scene, the eye on
 * the look-at point, or up along the line of sight. */
int stp_tool_camera_view(const stp_scene *scene, const stp_tool_options *opt,
                         const stp_tool_motion *motion, int frame, stp_tool_view *view,
                         double *turn_radians, char *err, size_t err_size);

/* A scene seen from another view: a shallow copy of the original (which
 * must outlive it) with its view replaced, and its lights turned with the
 * orbit (own copy) so that the picture is the model turning in front of a
 * still camera and light. */
typedef struct stp_tool_camera_scene {
    stp_scene scene;
    stp_scene_light *lights;  /* the turned lights (malloc'ed), or NULL */
} stp_tool_camera_scene;

/* Build it for frame `frame` of motion (NULL: the still camera of opt).
 * opt_out gets opt with the camera options cleared and its --light
 * positions turned too.  Returns 0, or -1 with a message. */
int stp_tool_camera_apply(const stp_scene *scene, const stp_tool_options *opt,
                          const stp_tool_motion *motion, int frame, stp_tool_camera_scene *out,
                          stp_tool_options *opt_out, char *err, size_t err_size);
void stp_tool_camera_free(stp_tool_camera_scene *c);

/* Parse "X,Y,Z" into *v (finite numbers).  Returns 0, or -1. */
int stp_tool_parse_point(const char *s, stp_scene_vec3 *v);

#endif
