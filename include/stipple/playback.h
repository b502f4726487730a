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

/* Check a display file before playing it back: every entry of
 * display_file[0, used) one that the entry side makes for a width x height
 * device (1..32767 each):
 *   - a polygon header (op 3..STP_MAX_POLYGON_VERTICES) followed by op - 1
 *     STP_OP_LINE entries, all inside [0, used);
 *   - points (polygon vertices, MOVE, LINE): x in 0..width << 4, y in
 *     0..height << 4 (Q27.4), z (depth key) in (INT32_MIN, 2^30]; with
 *     STP_WITH_GOURAUD a polygon's shades all -1 (flat) or all in [0, 1];
 *   - SHADE: style x in 1..256, shade y in [0, 1], colour z 0 or
 *     STP_COLOUR_FLAG with three channel bytes; LINE_STYLE: x in 1..256;
 *     TRANSPARENCY: x in [0, 1]; LIGHT_TERM: anything (not read here);
 *   - no other opcode.
 * Time: one pass over the entries.  Returns STP_OK; or STP_ERR_ARG, for
 * NULL, used 0, a side out of range or a bad entry, whose index then goes
 * to *bad (when bad is not NULL). */
int stp_playback_check(const stp_instr *display_file, uint32_t used, uint32_t width,
                       uint32_t height, uint32_t *bad);

/* A renderer in mem (stp_renderer_size() bytes, aligned for int64_t) whose
 * display file is display_file[0, used), one visible closed segment, for a
 * width x height device (1..32767 each) with `levels` INTENSITY levels
 * (2..256) and fill_style (1..levels) in force before the first SHADE
 * instruction.  stp_renderer_render only reads the display file, so it may live in
 * read-only memory; no entry call may be made on this renderer.  Returns
 * the renderer, or NULL for a bad argument, too little memory or a display
 * file that stp_playback_check refuses (the data is checked once, here:
 * data from flash or a file that was cut short or corrupted is refused
 * rather than read past its end). */
stp_renderer *stp_playback_create(void *mem, size_t mem_size, const stp_instr *display_file,
                                  uint32_t used, uint32_t width, uint32_t height, int levels,
                                  int fill_style);

#ifdef __cplusplus
}
#endif

#endif
