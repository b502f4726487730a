/* SPDX-License-Identifier: MIT */
/*
 * Host side: an image made fit for a panel before it is halftoned (stipple
 * dither): turned, mirrored, resized to the panel, made negative.  On
 * stp_posix_image (channels 1 or 3); each call replaces img's samples.
 */
#ifndef STIPPLE_TOOLS_IMAGE_OPS_H
#define STIPPLE_TOOLS_IMAGE_OPS_H

#include <stdint.h>
#include "stp_posix.h"

typedef enum stp_tool_resize {
    STP_TOOL_RESIZE_FIT,     /* the whole image, centred, black bars around */
    STP_TOOL_RESIZE_FILL,    /* the panel covered, the image's centre kept */
    STP_TOOL_RESIZE_STRETCH  /* each axis scaled on its own */
} stp_tool_resize;

/* Turn clockwise by degrees: 0, 90, 180 or 270.  Returns 0, or -1 (out of
 * memory or another angle; img untouched). */
int stp_tool_image_rotate(stp_posix_image *img, int degrees);

/* Mirror left to right. */
void stp_tool_image_flip(stp_posix_image *img);

/* Each sample v made 255 - v (the negative). */
void stp_tool_image_invert(stp_posix_image *img);

/* Resample to width x height (1..32767 each) as mode says: each output
 * pixel the mean of the source area it covers (each source pixel weighted
 * by the share of it inside), rounded; FIT pads with black (0), centred
 * (the odd pixel right and below).  Returns 0, or -1 (out of memory or a
 * bad size; img untouched). */
int stp_tool_image_resize(stp_posix_image *img, uint32_t width, uint32_t height, stp_tool_resize mode);

#endif
