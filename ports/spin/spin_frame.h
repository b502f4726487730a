/* SPDX-License-Identifier: MIT */
/*
 * Frames of the spinning scene (spin_scene.h), the same code on the host
 * and on the chip: the still parts entered once into segment 1, the
 * spinning parts re-entered every frame into a fresh segment 2 through
 * stp_renderer_mesh with a rotation of SPIN_DEGREES_PER_FRAME per frame
 * about the vertical line through spin_axis_point.
 */
#ifndef STIPPLE_SPIN_FRAME_H
#define STIPPLE_SPIN_FRAME_H

#include "spin_scene.h"

#define SPIN_DEGREES_PER_FRAME 12 /* 30 frames per turn */

/* View, lighting, levels and switches on r (created on spin_display_file
 * at the panel's size); the still parts entered into segment 1.
 * Returns STP_OK or the core's error. */
int spin_setup(stp_renderer *r);

/* Frame `frame`'s spinning parts: segment 2 deleted (absent the first
 * time), created again with the rotation by frame * SPIN_DEGREES_PER_FRAME
 * degrees, every spinning part entered with its material.  Returns STP_OK
 * or the core's error. */
int spin_enter(stp_renderer *r, uint32_t frame);

/* stp_renderer_render of the display file to port (MONO1) through mem, with
 * the scene's output: Z buffer, Bayer 4x4, its background.  Returns STP_OK
 * or the core's error. */
int spin_render(stp_renderer *r, stp_port *port, const stp_frame_memory *mem);

#endif
