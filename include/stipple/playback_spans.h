/* SPDX-License-Identifier: MIT */
/*
 * Playback of a picture made on the host as visible spans (`stipple compile
 * --spans`): the host enters, shades, clips, projects and hides the scene,
 * then writes each row of its picture as runs of one shade; the chip fills
 * each run from that shade's halftone pattern rows.  Nothing is divided,
 * sorted or depth-tested on the chip, and the only frame memory is the band.
 *
 * Data (const, read in place; on an AVR both arrays are in program memory,
 * STP_SPANS_ROM, and read with pgm_read_byte, so a picture takes no RAM):
 *   runs      rows top to bottom; a row is runs left to right, each two
 *             bytes {last x of the run, shade index}; a row ends with the
 *             run whose last x is width - 1.
 *   patterns  for shade k and cell row cy, the MONO1 byte (pixel 0 in bit
 *             7) that every 8 pixels of a row repeat:
 *             patterns[k * cell_rows + cy], cy = y & (cell_rows - 1).
 */
#ifndef STIPPLE_PLAYBACK_SPANS_H
#define STIPPLE_PLAYBACK_SPANS_H

#include <stddef.h>
#include <stdint.h>

#include "stipple/render.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Where the arrays live: program memory on an AVR (avr-gcc would copy
 * plain const data into RAM at start-up), ordinary const data elsewhere.
 * `stipple compile --spans` writes its arrays with STP_SPANS_ROM. */
#if defined(__AVR__)
#include <avr/pgmspace.h>
#define STP_SPANS_ROM PROGMEM
#else
#define STP_SPANS_ROM
#endif

typedef struct stp_spans {
    uint16_t width, height; /* the picture, 1..256 wide, 1..32767 high */
    uint8_t cell_rows;      /* pattern rows per shade: 1, 2, 4 or 8 */
    uint8_t shade_count;    /* entries of patterns: shade_count * cell_rows */
    const uint8_t *patterns; /* STP_SPANS_ROM */
    const uint8_t *runs;     /* STP_SPANS_ROM, run_bytes bytes */
    uint32_t run_bytes;      /* bytes of runs (twice the number of runs) */
} stp_spans;

/* Where playback has got to: the next row and its first run. */
typedef struct stp_spans_cursor {
    const uint8_t *next;
    uint16_t y;
} stp_spans_cursor;

/* Put the cursor on row 0 of the picture (spans and cursor not NULL; no
 * errors: the data is checked as stp_spans_draw reads it). */
void stp_spans_start(const stp_spans *spans, stp_spans_cursor *cursor);

/* Draw the cursor's next `rows` rows (1..height - cursor row) as MONO1 into
 * band (row r at band + r * stride, stride >= (width + 7) / 8 bytes; every
 * pixel of the rows is written) and move the cursor past them.  Returns
 * STP_OK, or STP_ERR_ARG for a NULL spans, cursor, band or array, rows 0
 * or beyond the picture, width not in 1..256, stride too small, a cell_rows
 * that is not 1, 2, 4 or 8, a run that goes backwards or past the row, a
 * row whose runs end before its last column (the data runs out: a run is
 * read only below run_bytes), or a shade index of shade_count or more (the
 * band is then partly drawn and the cursor stays at the bad row). */
int stp_spans_draw(const stp_spans *spans, stp_spans_cursor *cursor, uint8_t *band, size_t stride,
                   uint32_t rows);

#ifdef __cplusplus
}
#endif

#endif
