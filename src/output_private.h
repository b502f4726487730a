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

#endif
