/* SPDX-License-Identifier: MIT */
/*
 * Host side of static scenes: a painter's order for a display file that
 * gives exactly the Z buffer's picture, so the firmware needs no Z buffer.
 */
#ifndef STIPPLE_TOOLS_STATIC_ORDER_H
#define STIPPLE_TOOLS_STATIC_ORDER_H

#include <stdint.h>
#include "stipple/stipple.h"

/* df[0, used): a display file of flat polygons and STP_OP_SHADE
 * instructions for a width x height device.  Finds an order of its polygons
 * in which drawing them one over another (STP_HIDDEN_NONE) gives every
 * pixel the style the Z buffer gives it: polygon A goes after polygon B when
 * A wins a pixel B also covers; a polygon that wins no pixel is left out.
 * Returns 1 with *out (malloc'ed, *out_used
 * entries: the polygons in that order, each after the STP_OP_SHADE in force
 * for it where the style changes), checked pixel for pixel against the Z
 * buffer on the host; 0 when there is none (those constraints form a cycle:
 * cyclic overlap, or polygons that share pixels both ways) or the display
 * file holds something else (lines, transparency, shadow records, more than
 * 255 polygons); -1 when out of memory. */
int stp_tool_static_order(const stp_instr *df, uint32_t used, uint32_t width, uint32_t height,
                          stp_instr **out, uint32_t *out_used);

#endif
