/* SPDX-License-Identifier: MIT */
/*
 * Host side: the tone of a picture before it is drawn (issue 14, item 3):
 *  - grey from colour that keeps the colour picture's contrast (the scene's
 *    main axis of colour variation, instead of luminance alone);
 *  - a frame background of the user's choice;
 *  - automatic exposure: BRIGHT scaled so the brightest visible pixel
 *    reaches the top level (found by a probe render with a black frame).
 */
#ifndef STIPPLE_TOOLS_TONE_H
#define STIPPLE_TOOLS_TONE_H

#include <stddef.h>
#include "render_scene.h"

/* Whether opt asks for any of the above. */
int stp_tool_tone_wanted(const stp_tool_options *opt);

/* Render with the tone options applied (then cleared, and the render done
 * by stp_tool_render).  Returns 0, or -1 with a message. */
int stp_tool_render_toned(const stp_scene *scene, const stp_tool_options *opt, stp_port *port,
                          stp_tool_stats *stats, char *err, size_t err_size);

/* The factor automatic exposure would multiply BRIGHT by for this scene
 * and these options (their size included).  Returns 0, or -1 with a
 * message. */
int stp_tool_exposure_gain(const stp_scene *scene, const stp_tool_options *opt, double *gain, char *err,
                           size_t err_size);

/* The contrast-keeping grey of each colour: materials[i] of scene and its
 * background projected on the scene's first principal axis of colour
 * (sign: the one that agrees with luminance), grey = luminance of the mean
 * + projection / sqrt 3 (a black-to-white distance sqrt 3 becomes 1; a
 * grey scene keeps its greys), shifted into [0, 1] when it falls outside.
 * grey_of_material: material_count entries; *grey_background too.  A
 * scene with one colour keeps its luminance. */
void stp_tool_contrast_greys(const stp_scene *scene, double *grey_of_material, double *grey_background);

#endif
