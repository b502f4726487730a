/* SPDX-License-Identifier: MIT */
/* Private: frame_memory.c's band size, for the rasteriser and the ray
 * tracer's checks of the caller's band. */
#ifndef STIPPLE_FRAME_MEMORY_PRIVATE_H
#define STIPPLE_FRAME_MEMORY_PRIVATE_H

#include <stddef.h>
#include <stdint.h>

#include "stipple/port.h"

/* Bytes of a band of rows rows of width pixels in format fmt: rows
 * stp_row_bytes, or (rows + 7) / 8 pages of width bytes for
 * STP_PIXEL_MONO1_PAGES; 0 for an unknown format or a size that does not
 * fit size_t. */
size_t stp_band_bytes(stp_pixel_format fmt, uint32_t width, uint32_t rows);

/* The format is the panels' page layout: never without STP_WITH_PAGES
 * (config.h), whose renders of it the rasteriser and the ray tracer
 * refuse, so the page paths behind this test compile to nothing there. */
#define STP_PAGES_FORMAT(format) (STP_WITH_PAGES && (format) == STP_PIXEL_MONO1_PAGES)

#endif
