/* SPDX-License-Identifier: MIT */
/* A frame into a u8g2 page buffer (stipple_u8g2.h). */
#include "stipple_u8g2.h"

#include "stipple/render.h"

int stipple_u8g2_draw(const stp_direct_frame *f, uint8_t *buffer, uint8_t tile_rows,
                      uint8_t tile_row, uint8_t *scratch)
{
    stp_direct_frame pages;
    unsigned t, x;
    if (f == 0 || buffer == 0 || scratch == 0 || tile_rows == 0)
        return STP_ERR_ARG;
    pages = *f;
    pages.layout = STP_BAND_PAGES;
    for (t = 0; t < tile_rows; t++) {
        uint32_t y0 = 8u * ((uint32_t)tile_row + t), rows;
        uint8_t *out = buffer + (size_t)t * f->width;
        int status;
        if (y0 >= f->height)
            break;
        rows = f->height - y0 < 8u ? f->height - y0 : 8u;
        status = stp_direct_draw_band(&pages, scratch, f->width, (uint16_t)y0, (uint16_t)rows);
        if (status != STP_OK)
            return status;
        for (x = 0; x < f->width; x++)
            out[x] = (uint8_t)(out[x] | scratch[x]);
    }
    return STP_OK;
}
