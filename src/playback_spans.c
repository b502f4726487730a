/* SPDX-License-Identifier: MIT */
/* The span player of playback_spans.h: each run is one masked byte fill
 * per 8 pixels; nothing is divided. */
#include "stipple/playback_spans.h"

void stp_spans_start(const stp_spans *spans, stp_spans_cursor *cursor)
{
    cursor->next = spans->runs;
    cursor->y = 0;
}

/* Pixels x1..x2 (x1 <= x2) of a MONO1 row set from the pattern byte. */
static void fill_run(uint8_t *row, uint32_t x1, uint32_t x2, uint8_t pattern)
{
    uint32_t i = x1 >> 3, last = x2 >> 3;
    uint8_t mask = (uint8_t)(0xFFu >> (x1 & 7u));
    for (;; i++) {
        if (i == last)
            mask = (uint8_t)(mask & (0xFF00u >> ((x2 & 7u) + 1u)));
        row[i] = (uint8_t)((row[i] & ~mask) | (pattern & mask));
        if (i == last)
            return;
        mask = 0xFFu;
    }
}

int stp_spans_draw(const stp_spans *spans, stp_spans_cursor *cursor, uint8_t *band, size_t stride,
                   uint32_t rows)
{
    const uint8_t *p = cursor->next;
    uint32_t cell_mask = (uint32_t)spans->cell_rows - 1u, right = (uint32_t)spans->width - 1u;
    if (rows > (uint32_t)spans->height - cursor->y || cell_mask > 7u ||
        (spans->cell_rows & cell_mask) != 0)
        return STP_ERR_ARG;
    for (; rows > 0; rows--, band += stride) {
        uint32_t x = 0, last;
        const uint8_t *pattern_row = spans->patterns + (cursor->y & cell_mask);
        do {
            last = p[0];
            if (last < x || last > right || p[1] >= spans->shade_count)
                return STP_ERR_ARG;
            fill_run(band, x, last, pattern_row[(uint32_t)p[1] * spans->cell_rows]);
            x = last + 1u;
            p += 2;
        } while (last != right);
        cursor->y++;
        cursor->next = p;
    }
    return STP_OK;
}
