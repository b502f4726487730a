/* SPDX-License-Identifier: MIT */
/*
 * Host side: palette pictures (palette.h) as files: PNG, PPM or PGM
 * showing the palette's colours, and the black/white/red planes an
 * SSD1680 takes (docs/palettes.md).
 */
#ifndef STIPPLE_TOOLS_PALETTE_OUTPUT_H
#define STIPPLE_TOOLS_PALETTE_OUTPUT_H

#include <stddef.h>
#include <stdint.h>

#include "palette.h"

/* 1 if path's extension is one a palette picture can be written as: .png,
 * .ppm, and .pgm for a grey palette ("-": PPM on stdout). */
int stp_palette_output_accepts(const stp_palette *p, const char *path);

/* Writes the picture (width x height palette indices) to path: .png (8-bit
 * grey for a grey palette, else RGB), .ppm (RGB), .pgm (grey palettes
 * only), "-" PPM on stdout; atomically, as stp_posix_write.  Returns 0, or
 * -1 with a message in err. */
int stp_palette_write(const stp_palette *p, const uint8_t *index, uint32_t width, uint32_t height,
                      const char *path, char *err, size_t err_size);

/* Writes a bwr picture's two planes (stp_palette_bwr_planes) to
 * PREFIX.bw and PREFIX.red, raw bytes, each atomically.  Returns 0, or -1
 * with a message in err (the bw file may then exist without the red one). */
int stp_palette_write_planes(const uint8_t *index, uint32_t width, uint32_t height,
                             const char *prefix, char *err, size_t err_size);

#endif
