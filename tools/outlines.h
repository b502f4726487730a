/* SPDX-License-Identifier: MIT */
/*
 * Host side: outlines for tiny panels (docs/outlines.md).  The silhouette
 * and crease edges of a scene's polygons, as the eye sees them, cut down
 * to their visible pieces, for the renderer to draw as lines over the
 * polygons.
 *
 *   silhouette: an edge between a polygon facing the eye and one facing
 *               away, or an edge of one polygon only (a boundary) or of
 *               more than two;
 *   crease:     an edge whose two polygons' normals differ by more than
 *               the crease angle (a silhouette edge can be one too).
 * Polygons share an edge when its two end points are the same (positions
 * equal to 1e-5 of the scene's size).  Two polygons that run the shared
 * edge the same way (inconsistent winding) have one normal turned round
 * first, so such files do not show false silhouettes.
 *
 * Visibility: a point of an edge is visible when the segment from it to
 * the eye (parallel projection: towards the viewer along the line of
 * sight) meets no polygon other than the edge's own, in double precision.
 * Each edge is tested at the centres of n equal parts, n = 4 per pixel of
 * its length on screen (at least 1, at most 4096); a run of visible parts
 * is one piece.
 */
#ifndef STIPPLE_TOOLS_OUTLINES_H
#define STIPPLE_TOOLS_OUTLINES_H

#include <stddef.h>

#include "scene.h"

#define STP_OUTLINE_SILHOUETTE 1
#define STP_OUTLINE_CREASE 2

/* The eye as the core's view sets it up (src/view.c): from, at, up, the
 * full field of view in degrees (perspective) or the half width of the
 * window in scene units (parallel), and the picture's size in pixels. */
typedef struct stp_outline_view {
    int perspective;
    stp_scene_vec3 from, at, up;
    double fov_degrees, window_half;
    int width, height;
} stp_outline_view;

/* A piece of an edge, in scene coordinates; kind: the edge's kinds, a
 * mask of STP_OUTLINE_* (an edge can be both). */
typedef struct stp_outline_segment {
    stp_scene_vec3 a, b;
    int kind;
} stp_outline_segment;

/* Device coordinates (pixels, x right, y down, (0, 0) the top left
 * corner of the picture) of a scene point, as src/render.c projects it;
 * returns 0, or -1 for a point at or behind the eye (perspective). */
int stp_outline_project(const stp_outline_view *view, stp_scene_vec3 p, double *x, double *y);

/* The visible pieces of the edges of the kinds asked for (a mask of
 * STP_OUTLINE_*), crease_degrees in 0..180.  *out is malloc'ed (free it;
 * NULL when there are none).  Returns 0, or -1: out of memory, or a view
 * with from = at or up along the line of sight. */
int stp_outlines_find(const stp_scene *scene, const stp_outline_view *view, int kinds,
                      double crease_degrees, stp_outline_segment **out, size_t *count);

#endif
