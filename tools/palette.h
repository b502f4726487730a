/* SPDX-License-Identifier: MIT */
/*
 * Host side: dithering to a small palette of panel colours (docs/palettes.md):
 * black/white, black/white/red e-paper (SSD1680's two RAM planes), 4 and 16
 * grey levels, the 8 colours of 1-bit RGB, or a palette file.
 *
 * Values: a channel's 8-bit code c stands for c / 255 of full light, or,
 * with linear set, for the sRGB decoding of c (IEC 61966-2-1); image and
 * palette are read the same way, so "nearest" is measured in the light the
 * codes stand for.  Nearest: smallest sum of squared channel differences,
 * ties to the lower index.
 */
#ifndef STIPPLE_TOOLS_PALETTE_H
#define STIPPLE_TOOLS_PALETTE_H

#include <stddef.h>
#include <stdint.h>

#include "stipple/stipple.h"

#define STP_PALETTE_MAX 256

typedef struct stp_palette {
    int count;                          /* 2..STP_PALETTE_MAX entries */
    uint8_t rgb[STP_PALETTE_MAX][3];    /* 8-bit codes, R G B */
    int grey;                           /* 1: every entry has R = G = B */
    int bwr;                            /* 1: the black/white/red palette
                                           (entries 0 black, 1 white, 2 red) */
} stp_palette;

/* 1 if name is a built-in palette: bw, bwr, grey4 (gray4), grey16
 * (gray16), rgb8. */
int stp_palette_is_name(const char *name);

/* A built-in palette by name, else a palette file: one colour per line as
 * three decimal codes "R G B" (0..255; anything after them is a name and
 * ignored), blank lines and lines starting with '#' skipped, 2..256
 * colours.  Returns 0, or -1 with "FILE:LINE: what" (or "FILE: what") in
 * err. */
int stp_palette_load(const char *spec, stp_palette *p, char *err, size_t err_size);

/* How the picture is dithered. */
typedef struct stp_palette_method {
    int diffuse;          /* 1: error diffusion, else the ordered cell */
    int kernel;           /* diffuse: stp_diffusion_kernel */
    int serpentine;       /* diffuse: odd rows right to left */
    const stp_cell *cell; /* ordered: the threshold cell */
    int linear;           /* 1: codes are sRGB, decoded to linear light */
} stp_palette_method;

/* Dither an image of width x height pixels (rows top first, channels 1
 * (grey) or 3 (R G B) bytes per pixel) to palette indices (width x height
 * bytes into index).
 * Ordered: each channel is placed between the two neighbouring values
 * that palette entries take in that channel (below v: L, above: U), the
 * upper one taken where the cell turns a pixel of intensity
 * round(255 (v - L) / (U - L)) ON; the resulting colour is mapped to the
 * nearest entry (it is an entry itself for bw, the greys and rgb8).
 * Diffusion: the pixel's value plus the error it received, clamped to
 * 0..1 per channel, goes to the nearest entry; the difference (per
 * channel) is spread with the kernel's weights (as stp_diffuse_row:
 * shares to the right and below, mirrored on right-to-left rows).
 * Returns 0, or -1 (out of memory, bad arguments). */
int stp_palette_dither(const stp_palette *p, const stp_palette_method *m, const uint8_t *pixels,
                       int channels, uint32_t width, uint32_t height, uint8_t *index);

/* The nearest entry to the colour (r, g, b) in the working values of
 * stp_palette_dither (0..1 each), with `linear` as in the method. */
int stp_palette_nearest(const stp_palette *p, int linear, const double rgb[3]);

/* The light an 8-bit code stands for: c / 255, or with linear the sRGB
 * decoding of c. */
double stp_palette_value(int code, int linear);

/* The black/white/red picture as the SSD1680's two RAM planes, for a bwr
 * palette's indices: rows top first, (width + 7) / 8 bytes per row, the
 * leftmost pixel in the most significant bit.  bw: 1 = white (RAM 0x24;
 * a red pixel is white there too), pad bits 1; red: 1 = red (RAM 0x26),
 * pad bits 0.  Each plane holds height * ((width + 7) / 8) bytes. */
void stp_palette_bwr_planes(const uint8_t *index, uint32_t width, uint32_t height, uint8_t *bw,
                            uint8_t *red);

#endif
