/* SPDX-License-Identifier: MIT */
/* Private: the one 1-bit run filler, used by every route that writes 1-bit
 * pixels from a pattern byte (dither.c's HALFTONE-FILLIN, raster.c's span
 * writers, direct_band.c's bands).  Inline, so each caller's loop keeps
 * the single-byte run (most runs of a small polygon) free of a call. */
#ifndef STIPPLE_RUN_FILL_PRIVATE_H
#define STIPPLE_RUN_FILL_PRIVATE_H

#include <stdint.h>

#include "stipple/dither.h" /* stp_band_layout; STP_WITH_PAGES (config.h) */
#include "arith_private.h"    /* STP_WIDE_ARITH */

/* The page layout's run (stp_halftone_fill_bits): byte x of the page gets
 * bit page_bit from the pattern's bit 7 - (x mod 8).  Walked by pointer
 * (no 32-bit index per pixel on an 8-bit core); an all-OFF or all-ON
 * pattern is one AND or OR per byte, another takes its bits from the
 * pattern rotated so that bit 7 is pixel x1's and turned a bit per pixel
 * (no shift by a variable count per pixel: an 8-bit core has none). */
static inline void stp_halftone_fill_page_run(uint8_t *page, uint8_t page_bit, unsigned x1, unsigned x2,
                                              uint8_t pattern)
{
    uint8_t *p = page + x1, *const last = page + x2, keep = (uint8_t)~page_bit, turn = (uint8_t)(x1 & 7u);
    if (pattern == 0u) {
        do
            *p = (uint8_t)(*p & keep);
        while (p++ != last);
        return;
    }
    if (pattern == 0xFFu) {
        do
            *p = (uint8_t)(*p | page_bit);
        while (p++ != last);
        return;
    }
    if (turn)
        pattern = (uint8_t)((unsigned)pattern << turn | (unsigned)pattern >> (8u - turn));
    do {
        *p = (uint8_t)((pattern & 0x80u) ? *p | page_bit : *p & keep);
        pattern = (uint8_t)((unsigned)pattern << 1 | (unsigned)pattern >> 7);
    } while (p++ != last);
}

/* (STP_WITH_PAGES 0: page_bit is taken as 0, and the page path is not
 * compiled: no caller passes one, they are refused before.)
 * Pixels x1..x2 (x1 <= x2 < 32768: a port's width, so unsigned, 16 bits
 * on an 8-bit core) of one band row from a pattern byte (pixel x takes
 * bit 7 - (x mod 8) of pattern), in either stp_band_layout:
 *   page_bit 0: line is a STP_BAND_ROWS row (MSB first), filled a byte at
 *     a time between the two partial end bytes;
 *   page_bit 1 << (y mod 8): line is the first byte of row y's page of a
 *     STP_BAND_PAGES band; byte x gets bit page_bit, its other bits kept. */
static inline void stp_halftone_fill_bits(uint8_t *line, uint8_t page_bit, unsigned x1, unsigned x2,
                                          uint8_t pattern)
{
#if defined(__OPTIMIZE_SIZE__)
    /* a build for size: one loop of masked stores, the first byte's mask
     * cut at x1, the last's at x2 (the same bytes as below) */
    unsigned i = x1 >> 3, last = x2 >> 3;
    uint8_t mask = (uint8_t)(0xFFu >> (x1 & 7u));
    if (STP_WITH_PAGES && page_bit) {
        stp_halftone_fill_page_run(line, page_bit, x1, x2, pattern);
        return;
    }
    for (;; i++) {
        if (i == last)
            mask = (uint8_t)(mask & (0xFF00u >> ((x2 & 7u) + 1u)));
        line[i] = (uint8_t)((line[i] & ~mask) | (pattern & mask));
        if (i == last)
            return;
        mask = 0xFFu;
    }
#else
    unsigned first = x1 >> 3, last = x2 >> 3, b;
#if STP_WIDE_ARITH
    /* 64-bit hosts: head, the bits of x1 and right of it in its byte;
     * after, those right of x2 in its byte (in x1's byte a part of head:
     * the run's bits there are head ^ after); bytes changed as line ^
     * ((line ^ pattern) & bits) (x86-64 mesh torus 2 000 / 10 000 / 21 000
     * instructions a frame fewer at 128x64 / 400x240 / 640x480; ARMv6-M
     * direct frame 30 000 more, so the form below stays there) */
    uint8_t head = (uint8_t)(0xFFu >> (x1 & 7u)), after = (uint8_t)(0x7Fu >> (x2 & 7u));
    if (STP_WITH_PAGES && page_bit) {
        stp_halftone_fill_page_run(line, page_bit, x1, x2, pattern);
        return;
    }
    if (first == last) {
        line[first] = (uint8_t)(line[first] ^ ((line[first] ^ pattern) & (head ^ after)));
        return;
    }
    line[first] = (uint8_t)(line[first] ^ ((line[first] ^ pattern) & head));
    for (b = first + 1; b < last; b++)
        line[b] = pattern;
    line[last] = (uint8_t)(pattern ^ ((line[last] ^ pattern) & after));
#else
    uint8_t head = (uint8_t)(0xFFu >> (x1 & 7u)), tail = (uint8_t)(0xFFu << (7u - (x2 & 7u)));
    if (STP_WITH_PAGES && page_bit) {
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
#endif
#endif
}

/* Pixel x of a band line in either stp_band_layout (line and page_bit as
 * stp_halftone_fill_bits: page_bit 0 a STP_BAND_ROWS row, else row y's
 * page and its bit 1 << (y mod 8)): set ON (on != 0) or OFF, or read. */
static inline void stp_mono_put(uint8_t *line, uint8_t page_bit, uint32_t x, int on)
{
    int pages = STP_WITH_PAGES && page_bit;
    uint32_t i = pages ? x : x >> 3;
    uint8_t bit = (uint8_t)(pages ? page_bit : 0x80u >> (x & 7u));
    line[i] = (uint8_t)(on ? line[i] | bit : line[i] & ~bit);
}

/* Row y's pixels as bytes 0 (OFF) / 1 (ON), bits[0..width), into its
 * page line of a STP_BAND_PAGES band (page_bit 1 << (y mod 8)): the
 * page's top row (page_bit 1) sets the bytes, so the page's other bits
 * start 0, the others add their bit.  bits may be line itself (byte x is
 * read before it is written), which lets a band drawn as grey rows be
 * made pages in place: row r's page lies on grey row r / 8, read before. */
static inline void stp_mono_page_from_bytes(uint8_t *line, uint8_t page_bit, const uint8_t *bits, uint32_t width)
{
    uint32_t x;
    if (page_bit == 1u) {
        for (x = 0; x < width; x++)
            line[x] = (uint8_t)(bits[x] != 0);
        return;
    }
    for (x = 0; x < width; x++)
        if (bits[x])
            line[x] = (uint8_t)(line[x] | page_bit);
}

static inline int stp_mono_get(const uint8_t *line, uint8_t page_bit, uint32_t x)
{
    return STP_WITH_PAGES && page_bit ? (line[x] & page_bit) != 0 : (line[x >> 3] & (0x80u >> (x & 7u))) != 0;
}

#endif
