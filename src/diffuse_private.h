/* SPDX-License-Identifier: MIT */
/* Private: error diffusion into the page layout, for the polygon raster. */
#ifndef STIPPLE_DIFFUSE_PRIVATE_H
#define STIPPLE_DIFFUSE_PRIVATE_H

#include <stdint.h>

#include "stipple/diffuse.h"

/* stp_diffuse_row (diffuse.h) with its bits going to row y's page line of
 * a STP_PIXEL_MONO1_PAGES band (bit y mod 8 of byte x) rather than packed
 * into the row: stp_mono_page_from_bytes's rules, so line may lie on a
 * grey row already diffused or on pixels itself (a band's row 0). */
void stp_diffuse_row_page(const stp_diffusion *d, uint8_t *pixels, uint32_t width, uint32_t y, uint8_t *line);

#endif
