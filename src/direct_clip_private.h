/* SPDX-License-Identifier: MIT */
/* Private: direct drawing's faces that the picture's edge cuts, clipped
 * and projected as the renderer clips and projects them (direct_clip.c),
 * for the frame's painter's keys (direct.c) and the bands (direct_band.c). */
#ifndef STIPPLE_DIRECT_CLIP_PRIVATE_H
#define STIPPLE_DIRECT_CLIP_PRIVATE_H

#include <stdint.h>

#include "stipple/direct.h"
#include "stipple/render.h" /* stp_instr */
#include "clip_private.h" /* stp_clip_volume */

/* The most vertices a triangle keeps when clipped by the pyramid's five
 * planes (clip.c: one more a plane at most) */
#define STP_DIRECT_CLIP_MAX 8

/* The view pyramid of frame f (its focal length, hither, width and
 * height), as the renderer's view makes its clipping volume
 * (render.c's stp_renderer_set_view). */
void stp_direct_clip_volume(const stp_direct_frame *f, stp_clip_volume *v);

/* Face k (its vertex indices) of frame f clipped to the view's pyramid by
 * the renderer's clipper (clip.c) on its vertices' view coordinates, each
 * vertex then projected by the renderer's projection (render.c's
 * project: device x, y in Q4 clamped to [0, 16 width] and [0, 16 height],
 * and the depth key, a flat vertex as the display file holds it) into
 * out[0 .. n-1]; returns n, below 3 when nothing is left to draw. */
int stp_direct_face_clip(const stp_direct_frame *f, const uint16_t k[3], stp_instr out[STP_DIRECT_CLIP_MAX]);

#endif
