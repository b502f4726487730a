/* SPDX-License-Identifier: MIT */
/* Private: how a style index becomes a device value, shared by the polygon
 * raster and the ray tracer so both map shades to pixels identically. */
#ifndef STIPPLE_OUTPUT_PRIVATE_H
#define STIPPLE_OUTPUT_PRIVATE_H

#include "stipple/render.h"

/* 8-bit drive value of style index (clamped to 1..levels): the output's
 * gamma table, or linear round((index - 1) 255 / (levels - 1)). */
uint8_t stp_output_level(const stp_output *out, int levels, int index);

/* STYLE8 code of a style index: the style table's code, or the index
 * itself; indices above levels show as the top style, 0 stays 0. */
uint8_t stp_output_style_code(const stp_output *out, int levels, int index);

/* One pixel of shade s (stp_fix, clamped to [0, 1]) at column x of a band
 * row, y its device row (MONO1_PAGES: row is the first byte of row y's
 * page, in a band that starts on a page boundary): INTENSITY, then the
 * format's value: MONO1 the level against the cell's threshold at (x, y)
 * (the combined scheme), GREY8 the
 * level, RGB888 the level in all three channels, STYLE8 the style code.
 * Used per pixel by smooth spans and by the ray tracer. */
void stp_output_put_shade(uint8_t *row, stp_pixel_format format, uint32_t x, uint32_t y,
                          const stp_output *out, const stp_cell *cell, int levels, stp_fix shade);

#endif
