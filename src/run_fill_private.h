/* SPDX-License-Identifier: MIT */
/* Private: the one 1-bit run filler, used by every route that writes 1-bit
 * pixels from a pattern byte (dither.c's HALFTONE-FILLIN, raster.c's span
 * writers, direct_band.c's bands).  Inline, so each caller's loop keeps
 * the single-byte run (most runs of a small polygon) free of a call. */
#ifndef STIPPLE_RUN_FILL_PRIVATE_H
#define STIPPLE_RUN_FILL_PRIVATE_H

#include <stdint.h>

#include "stipple/dither.h" /* stp_band_layout */

/* The page layout's run (stp_halftone_fill_bits): byte x of the page gets
 * bit page_bit from the pattern's bit 7 - (x mod 8), found by a mask that
 * walks right and wraps (no shift by a variable count per pixel: an 8-bit
 * core has none). */
static inline void stp_halftone_fill_page_run(uint8_t *page, uint8_t page_bit, unsigned x1, unsigned x2,
                                              uint8_t pattern)
{
    uint8_t mask = (uint8_t)(0x80u >> (x1 & 7u)), keep = (uint8_t)~page_bit;
    for (; x1 <= x2; x1++) {
        page[x1] = (uint8_t)((pattern & mask) ? page[x1] | page_bit : page[x1] & keep);
        mask = (uint8_t)(mask >> 1);
        if (mask == 0)
            mask = 0x80u;
    }
}

/* Pixels x1..x2 (x1 <= x2 < 32768: a port's width, so unsigned, 16 bits
 * on an 8-bit core) of one band row from a pattern byte (pixel x takes
 * bit 7 - (x mod 8) of pattern), in either stp_band_layout:
 *   page_bit 0: line is a STP_BAND_ROWS row (MSB first), filled a byte at
 *     a time between the two partial end bytes;
 *   page_bit 1 << (y mod 8): line is the first byte of row y's page of a
 *     STP_BAND_PAGES band; byte x gets bit page_bit, its other bits kept. */
static inline void stp_halftone_fill_bits(uint8_t *line, uint8_t page_bit, unsigned x1, unsigned x2,
                                          uint8_t pattern)
{
    unsigned first = x1 >> 3, last = x2 >> 3, b;
    uint8_t head = (uint8_t)(0xFFu >> (x1 & 7u)), tail = (uint8_t)(0xFFu << (7u - (x2 & 7u)));
    if (page_bit) {
        stp_halftone_fill_page_run(line, page_bit, x1, x2, pattern);
        return;
    }
    if (first == last)
        head = (uint8_t)(head & tail);
    line[first] = (uint8_t)((line[first] & ~head) | (pattern & head));
    if (first == last)
        return;
    /* whole bytes: a plain store loop (compilers turn it into memset) */
    for (b = first + 1; b < last; b++)
        line[b] = pattern;
    line[last] = (uint8_t)((line[last] & ~tail) | (pattern & tail));
}

#endif
