/* SPDX-License-Identifier: MIT */
/* Private: dither.c's MONO1 span filling, for the polygon raster. */
#ifndef STIPPLE_DITHER_PRIVATE_H
#define STIPPLE_DITHER_PRIVATE_H

#include <stdint.h>

#include "stipple/dither.h"

/* MONO1 span filling (dither.c).  The pattern byte of cell row y % height
 * for an intensity: bit 7 - b is ON when pixel b of any byte of the row is
 * (needs a threshold cell whose width divides 8). */
uint8_t stp_halftone_pattern_byte(const stp_cell *cell, uint32_t y, uint8_t intensity);
/* stp_halftone_fillin (dither.h) into a band line of either layout:
 * line and page_bit as stp_halftone_fill_bits (run_fill_private.h). */
void stp_halftone_fillin_line(uint8_t *line, uint8_t page_bit, uint32_t x1, uint32_t x2, uint32_t y,
                              const stp_cell *cell, uint8_t intensity);
/* The renderer's default cell into *cell (not NULL): Bayer 4 x 4 with
 * linear spacing, the thresholds of stp_cell_bayer(cell, 4), read through
 * stp_cell_table (32-bit targets: a mask on a constant table, made in a
 * few stores; AVR: made by stp_cell_bayer). */
void stp_cell_default(stp_cell *cell);
/* The one 1-bit run filler: stp_halftone_fill_bits (run_fill_private.h). */
#include "run_fill_private.h"

#endif
