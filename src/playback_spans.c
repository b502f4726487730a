/* SPDX-License-Identifier: MIT */
/* The span player of playback_spans.h: each run is one masked byte fill
 * per 8 pixels (the one 1-bit run filler, run_fill_private.h); nothing
 * is divided.  The data is read a byte at a time
 * through read_byte (program memory on an AVR). */
#include "stipple/playback_spans.h"

#include "run_fill_private.h" /* stp_halftone_fill_bits, the one run filler */

#if defined(__AVR__)
#define read_byte(p) pgm_read_byte(p)
#else
#define read_byte(p) (*(p))
#endif

void stp_spans_start(const stp_spans *spans, stp_spans_cursor *cursor)
{
    cursor->next = spans->runs;
    cursor->y = 0;
}

/* The call's arguments, and a cursor not before the data; one past it is
 * refused by the first run's read (rows >= 1: at least one run is read,
 * and checked before anything is written). */
static int spans_ok(const stp_spans *spans, const stp_spans_cursor *cursor, const uint8_t *band,
                    size_t stride, uint32_t rows)
{
    uint8_t cell_mask;
    if (spans == 0 || cursor == 0 || band == 0 || spans->patterns == 0 || spans->runs == 0 ||
        cursor->next == 0)
        return 0;
    cell_mask = (uint8_t)(spans->cell_rows - 1u);
    return rows > 0 && cursor->y <= spans->height && rows <= (uint32_t)spans->height - cursor->y &&
           spans->width >= 1u && spans->width <= 256u && stride >= ((size_t)spans->width + 7u) / 8u &&
           spans->cell_rows != 0 && cell_mask <= 7u && (spans->cell_rows & cell_mask) == 0 &&
           spans->run_bytes != 0 && cursor->next >= spans->runs;
}

int stp_spans_draw(const stp_spans *spans, stp_spans_cursor *cursor, uint8_t *band, size_t stride,
                   uint32_t rows)
{
    const uint8_t *p, *last_run;
    uint8_t cell_mask, right;
    if (!spans_ok(spans, cursor, band, stride, rows))
        return STP_ERR_ARG;
    p = cursor->next;
    /* a run's two bytes below run_bytes (>= 1): it starts before this */
    last_run = spans->runs + spans->run_bytes - 1u;
    cell_mask = (uint8_t)(spans->cell_rows - 1u);
    right = (uint8_t)(spans->width - 1u);
    for (; rows > 0; rows--, band += stride) {
        uint16_t x = 0; /* the row's next pixel: up to 256 */
        uint8_t last;
        const uint8_t *pattern_row = spans->patterns + (cursor->y & cell_mask);
        do {
            uint8_t shade;
            if (p >= last_run)
                return STP_ERR_ARG; /* the data ends inside the row */
            last = read_byte(p);
            shade = read_byte(p + 1);
            if (last < x || last >= spans->width || shade >= spans->shade_count)
                return STP_ERR_ARG;
            stp_halftone_fill_bits(band, 0, x, last,
                                   read_byte(pattern_row + (uint16_t)shade * spans->cell_rows));
            x = (uint16_t)(last + 1u);
            p += 2;
        } while (last != right);
        cursor->y++;
        cursor->next = p;
    }
    return STP_OK;
}
