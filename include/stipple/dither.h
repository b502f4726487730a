/* SPDX-License-Identifier: MIT */
/*
 * Halftone cells (docs/model.md section 3): ordered-dither threshold matrices and
 * 2x2 pattern cells.  An intensity is an 8-bit drive value 0..255 (after the
 * gamma table); HALFTONE-FILLIN's rule turns a pixel ON (lit, light) when
 * intensity > threshold of the cell entry under it.
 */
#ifndef STIPPLE_DITHER_H
#define STIPPLE_DITHER_H

#include <stdint.h>
#include "stipple/fix.h"

#ifdef __cplusplus
extern "C" {
#endif

#define STP_CELL_MAX 16 /* largest cell side */

typedef enum stp_cell_kind {
    STP_CELL_THRESHOLD = 0, /* ordered dither: ON when intensity > threshold */
    STP_CELL_PATTERN = 1    /* pattern cell: the level picks a whole pattern */
} stp_cell_kind;

/* A halftone cell, held by value (no pointers) so it can be copied and
 * stored in ROM.  Threshold cells: thresholds[y*width + x], 0..255.
 * Pattern cells (width = height = 2, 5 levels): the intensity is quantised to
 * level = (intensity*4 + 127)/255 and patterns[level] holds the pixels
 * that are ON, bit (y*2 + x). */
typedef struct stp_cell {
    uint8_t kind;
    uint8_t width, height;
    uint8_t thresholds[STP_CELL_MAX * STP_CELL_MAX];
    uint8_t patterns[5];
} stp_cell;

/* Threshold spacings for stp_cell_bayer_spaced. */
typedef enum stp_spacing {
    STP_SPACING_LINEAR = 0,      /* t_r = ceil(255(r+1)/(m+1)) - 1, as ImageMagick */
    STP_SPACING_EXPONENTIAL = 1, /* t_r = 255 * 2^(-5(m-r)/(m+1)): five doublings,
                                    the seed's 1,2,4,8,16 for a 2x2 cell */
    STP_SPACING_CUBIC = 2        /* t_r = 255 * ((r+1)/(m+1))^3: the seed's
                                    1,8,27,64 (over 125) for a 2x2 cell */
} stp_spacing;

/* Bayer cell of side n in {2, 4, 8}, linear spacing: entry with Bayer rank r
 * (0..m-1, m = n*n) gets threshold ceil(255(r+1)/(m+1)) - 1.  The ranks are
 * those of ImageMagick's o2x2/o4x4/o8x8 maps (the 8x8 is the transpose of the
 * recursive construction), so 8-bit grey input gives the same pixels as
 * `convert -ordered-dither oNxN`.  Returns 0, or -1 for another n. */
int stp_cell_bayer(stp_cell *cell, int n);

/* As stp_cell_bayer with the given spacing of thresholds over the ranks. */
int stp_cell_bayer_spaced(stp_cell *cell, int n, stp_spacing spacing);

/* The seed's 2x2 example (Figure 10-30): lower right ON above 50, upper
 * right above 100, lower left above 150, upper left above 200. */
void stp_cell_seed2x2(stp_cell *cell);

/* A user cell: width x height thresholds, row-major.  Sides 1..STP_CELL_MAX;
 * returns 0, or -1 (cell untouched) for a bad size or NULL thresholds. */
int stp_cell_user(stp_cell *cell, int width, int height, const uint8_t *thresholds);

/* The seed's 2x2 pattern cell (Figure 10-26): 5 levels, level L turns ON
 * the first L pixels of the order lower-right, upper-left, upper-right,
 * lower-left (diagonal pairs first, so level 2 is a checkerboard). */
void stp_cell_pattern2x2(stp_cell *cell);

/* Whether a pixel at (x, y) >= 0 with 8-bit intensity is ON. */
static inline int stp_cell_on(const stp_cell *cell, uint32_t x, uint32_t y, uint8_t intensity)
{
    uint32_t cx = x % cell->width, cy = y % cell->height;
    if (cell->kind == STP_CELL_PATTERN) {
        uint32_t level = ((uint32_t)intensity * 4u + 127u) / 255u;
        return (cell->patterns[level] >> (cy * 2u + cx)) & 1u;
    }
    return intensity > cell->thresholds[cy * cell->width + cx];
}

/* HALFTONE-FILLIN (Algorithm 10.12) on one row of a 1-bit buffer: pixels
 * x1..x2 inclusive (0 <= x1 <= x2) of row y are set ON (bit 1) where
 * intensity > threshold, OFF (bit 0) elsewhere.  Rows are packed most
 * significant bit first (pixel 0 is bit 7 of byte 0), as in PBM.  Unlike the
 * seed's listing, x1 == x2 fills one pixel: the fill rule, not this routine,
 * decides which pixels a polygon owns. */
void stp_halftone_fillin(uint8_t *row, uint32_t x1, uint32_t x2, uint32_t y,
                         const stp_cell *cell, uint8_t intensity);

/* Halftone a whole 8-bit grey row (image dithering): out bit x is ON where
 * grey[x] is ON under the cell at (x, y). */
void stp_halftone_row(uint8_t *out, const uint8_t *grey, uint32_t width, uint32_t y,
                      const stp_cell *cell);

#ifdef __cplusplus
}
#endif

#endif
