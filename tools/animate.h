/* SPDX-License-Identifier: MIT */
/*
 * Host side: an animation of a scene (stipple animate): 1-bit frames from
 * a moving camera (camera.h), drawn so that they do not flicker: an
 * ordered screen whose thresholds stay put on the panel, and one exposure
 * for the whole sequence.  Each frame goes to a sink as it is drawn.
 */
#ifndef STIPPLE_TOOLS_ANIMATE_H
#define STIPPLE_TOOLS_ANIMATE_H

#include "camera.h"
#include "render_scene.h"
#include "scene.h"
#include "stp_posix.h"

typedef struct stp_tool_animation_stats {
    int frames;
    double mean_changed; /* mean share (0..1) of the pixels that differ
                            between consecutive frames (0 for one frame) */
    double max_changed;  /* the largest such share */
    double gain;         /* the exposure gain used for every frame (1: none) */
} stp_tool_animation_stats;

/* Receives frame `index` (a MONO1 frame, 1 = lit) once drawn.  Returns 0,
 * or -1 with a message in err to stop the animation. */
typedef int (*stp_tool_frame_sink)(const stp_posix_frame *frame, int index, void *ctx, char *err,
                                   size_t err_size);

/* The defaults of an animation where options did not say otherwise:
 * the 64x64 blue-noise screen, 256 levels, automatic exposure (found once
 * for the whole sequence by stp_tool_animate), hold STP_TOOL_DEFAULT_HOLD. */
void stp_tool_animation_defaults(stp_tool_options *opt);

/* The default hold (stp_tool_halftone_held), in grey steps of 255. */
#define STP_TOOL_DEFAULT_HOLD 6

/* 1 when the frames of opt are drawn with a hold: opt->hold > 0 and a
 * threshold cell (not error diffusion, not --edge-aa). */
int stp_tool_animation_holds(const stp_tool_options *opt);

/* Halftone the GREY8 frame grey into the MONO1 frame out (same size)
 * under the threshold cell: a pixel is lit where its grey exceeds its
 * threshold (as the core's stp_halftone_row), except that a pixel keeps
 * its state in the frame before (NULL: none) while its grey stays within
 * hold steps of the threshold on that state's side: lit stays lit while
 * grey > threshold - hold, unlit stays unlit while grey <= threshold +
 * hold.  Grey that barely moves then flips no pixels; hold 0 is the
 * plain screen. */
void stp_tool_halftone_held(const stp_posix_frame *grey, const stp_cell *cell, int hold,
                            const stp_posix_frame *before, stp_posix_frame *out);

/* The exposure gain of the whole animation: the smallest gain automatic
 * exposure would give any of up to 16 frames spread evenly over it (the
 * first among them), so the brightest frame reaches the top level and
 * none is clipped more than a still would be.  Returns 0, or -1 with a
 * message. */
int stp_tool_animation_gain(const stp_scene *scene, const stp_tool_options *opt,
                            const stp_tool_motion *motion, double *gain, char *err, size_t err_size);

/* Draw motion->frames frames of scene at opt's size into MONO1 frames and
 * hand each to sink; opt->exposure_auto means one gain for all of them
 * (stp_tool_animation_gain).  stats (may be NULL) gets the changing
 * pixels.  Returns 0, or -1 with a message ("frame N: ..." for a frame's
 * render, or the sink's). */
int stp_tool_animate(const stp_scene *scene, const stp_tool_options *opt,
                     const stp_tool_motion *motion, stp_tool_frame_sink sink, void *ctx,
                     stp_tool_animation_stats *stats, char *err, size_t err_size);

/* The number of pixels that differ between two MONO1 frames of one size. */
unsigned long stp_tool_changed_pixels(const stp_posix_frame *a, const stp_posix_frame *b);

#endif
