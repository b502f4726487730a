/* SPDX-License-Identifier: MIT */
/* A frame into a u8g2 page buffer (stipple_u8g2.h). */
#include "stipple_u8g2.h"

#include "stipple/render.h"
#include "stp_panel.h"

int stipple_u8g2_draw(const stp_direct_frame *f, uint8_t *buffer, uint8_t tile_rows,
                      uint8_t tile_row, uint8_t *band, uint8_t *page)
{
    unsigned t, x;
    size_t stride;
    if (f == 0 || buffer == 0 || band == 0 || page == 0 || tile_rows == 0)
        return STP_ERR_ARG;
    stride = ((size_t)f->width + 7u) / 8u;
    for (t = 0; t < tile_rows; t++) {
        uint32_t y0 = 8u * ((uint32_t)tile_row + t), rows;
        uint8_t *out = buffer + (size_t)t * f->width;
        int status;
        if (y0 >= f->height)
            break;
        rows = f->height - y0 < 8u ? f->height - y0 : 8u;
        status = stp_direct_draw_band(f, band, stride, (uint16_t)y0, (uint16_t)rows);
        if (status != STP_OK)
            return status;
        for (x = (unsigned)rows * stride; x < 8u * stride; x++)
            band[x] = 0; /* rows past the frame: background */
        stp_panel_pack_page(band, stride, f->width, page);
        for (x = 0; x < f->width; x++)
            out[x] = (uint8_t)(out[x] | page[x]);
    }
    return STP_OK;
}
