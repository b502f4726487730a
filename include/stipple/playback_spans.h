/* SPDX-License-Identifier: MIT */
/*
 * Playback of a picture made on the host as visible spans (`stipple compile
 * --spans`): the host enters, shades, clips, projects and hides the scene,
 * then writes each row of its picture as runs of one shade; the chip fills
 * each run from that shade's halftone pattern rows.  Nothing is divided,
 * sorted or depth-tested on the chip, and the only frame memory is the band.
 *
 * Data (const, read in place; on an AVR without PROGMEM it is copied to
 * SRAM at start-up like any const data):
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

typedef struct stp_spans {
    uint16_t width, height; /* the picture, 1..256 wide, 1..32767 high */
    uint8_t cell_rows;      /* pattern rows per shade: 1, 2, 4 or 8 */
    uint8_t shade_count;    /* entries of patterns: shade_count * cell_rows */
    const uint8_t *patterns;
    const uint8_t *runs;
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
 * STP_OK, or STP_ERR_ARG for rows beyond the picture, a cell_rows that is
 * not 1, 2, 4 or 8, a run that goes backwards or past the row, or a shade
 * index of shade_count or more (the band is then partly drawn).  width must
 * be 1..256 (not checked: `stipple compile --spans` refuses other sizes). */
int stp_spans_draw(const stp_spans *spans, stp_spans_cursor *cursor, uint8_t *band, size_t stride,
                   uint32_t rows);

#ifdef __cplusplus
}
#endif

#endif
