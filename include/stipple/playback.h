/* SPDX-License-Identifier: MIT */
/*
 * Playback of a display file entered elsewhere: `stipple compile --static`
 * enters, shades, clips and projects a scene on the host and writes the
 * display file as const data; a firmware opens a renderer over it here and
 * draws it with stp_renderer_render, band by band.  Nothing of the entry side
 * (transform, shading, clipping, sin/cos, halftone cell construction) is
 * called, so a linker that drops unused sections leaves it out.
 */
#ifndef STIPPLE_PLAYBACK_H
#define STIPPLE_PLAYBACK_H

#include "stipple/render.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A renderer in mem (stp_renderer_size() bytes, aligned for int64_t) whose
 * display file is display_file[0, used), one visible closed segment, for a
 * width x height device (1..32767 each) with `levels` INTENSITY levels
 * (2..256) and fill_style (1..levels) in force before the first SHADE
 * instruction.  stp_renderer_render only reads the display file, so it may live in
 * read-only memory; no entry call may be made on this renderer.  Returns
 * the renderer, or NULL for a bad argument or too little memory. */
stp_renderer *stp_playback_create(void *mem, size_t mem_size, const stp_instr *display_file,
                                  uint32_t used, uint32_t width, uint32_t height, int levels,
                                  int fill_style);

#ifdef __cplusplus
}
#endif

#endif
