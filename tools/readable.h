/* SPDX-License-Identifier: MIT */
/*
 * Host side: whether a small 1-bit picture shows its objects (issue 25),
 * and the still default's rule that draws silhouettes when it would not.
 *
 * Readability R of a 1-bit picture along the visible silhouette edges
 * (outlines.h) in device pixels: each edge piece is sampled once per
 * pixel of its length; at a sample, with u along the edge and n across
 * it, the pixels whose centres lie within 2.5 pixels along u make three
 * groups by their distance d across: side A (1.5 <= d <= 4.5), side B
 * (-4.5 <= d <= -1.5) and the edge itself (|d| <= 1).  The sample reads
 * when the sides' means differ by at least 0.2 (a step between the object
 * and what is behind it) or the edge's mean differs from both sides' by
 * at least 0.2 the same way (a line along it).  Samples with fewer than 3
 * pixels on a side (at the frame's edges) are left out.  R = the share of
 * samples that read (1 when there are none).
 *
 * The rule (stp_tool_auto_outlines): silhouettes are drawn when the
 * picture without them has R < 0.45, i.e. when more than half of the
 * objects' outline is lost in the dither.  On the shared scenes at 128x64
 * that is balls-s1 (R 0.38) and balls-s2 (0.23), mid-grey objects on a
 * mid-grey floor, and none of the others (0.56 and up), whose shading
 * already separates object and background; at 400x240 none (0.48 and up:
 * the picture is large enough for the shading to show).
 */
#ifndef STIPPLE_TOOLS_READABLE_H
#define STIPPLE_TOOLS_READABLE_H

#include <stddef.h>

#include "render_scene.h"

#define STP_TOOL_READABLE_STEP 0.2   /* the difference of means that reads */
#define STP_TOOL_READABLE_SHARE 0.45 /* R below which silhouettes are drawn */

/* R of bits[w*h] (0/1, row-major) along count pieces xy (x0 y0 x1 y1 each,
 * device pixels); *samples: how many samples counted (may be NULL). */
double stp_tool_readability(const unsigned char *bits, int w, int h, const double *xy, size_t count,
                            size_t *samples);

/* As stp_tool_readability, and *lit (may be NULL): the share of ON
 * pixels on the counted samples' sides (0 when none). */
double stp_tool_readability_lit(const unsigned char *bits, int w, int h, const double *xy, size_t count,
                                size_t *samples, double *lit);

/* R of the 1-bit picture opt draws of scene (at opt's size, its outlines
 * and automatic outlines off) along its visible silhouette edges, and
 * *lit as above (may be NULL).  Returns 0, or -1 with a message. */
int stp_tool_picture_readability(const stp_scene *scene, const stp_tool_options *opt, double *r,
                                 double *lit, char *err, size_t err_size);

/* The rule above: *silhouettes = 1 when the 1-bit picture opt draws of
 * scene would have R < STP_TOOL_READABLE_SHARE; *level: the lines' shade,
 * black (0) where the picture around the edges is mostly lit, else white
 * (1).  Returns 0, or -1 with a message. */
int stp_tool_auto_outlines(const stp_scene *scene, const stp_tool_options *opt, int *silhouettes,
                           double *level, char *err, size_t err_size);

#endif
