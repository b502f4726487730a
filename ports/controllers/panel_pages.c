/* SPDX-License-Identifier: MIT */
/* Bands onto an 8-row-page controller (stp_panel.h): MONO1 rows of any
 * height gathered into pages (stp_panel_pages), or page bands
 * (STP_PIXEL_MONO1_PAGES) sent as they are. */
#include "stp_panel.h"

#define PAGE_ROWS 8u

int stp_panel_pages_put(const stp_panel_pages *p, uint32_t y0, uint32_t rows,
                        const uint8_t *pixels, size_t stride)
{
    uint32_t r = 0;
    while (r < rows) {
        uint32_t y = y0 + r;
        uint32_t in_page = y % PAGE_ROWS;
        const uint8_t *src = pixels + (size_t)r * stride;
        size_t i;
        int status;
        if (in_page == 0 && rows - r >= PAGE_ROWS) {
            status = stp_panel_send_mono_page(p->controller, p->bus, y / PAGE_ROWS, src, stride,
                                              p->width, p->columns);
            if (status != 0)
                return status;
            r += PAGE_ROWS;
            continue;
        }
        for (i = 0; i < p->row_bytes; i++)
            p->page_rows[(size_t)in_page * p->row_bytes + i] = src[i];
        if (in_page == PAGE_ROWS - 1u || y == p->height - 1u) {
            status = stp_panel_send_mono_page(p->controller, p->bus, y / PAGE_ROWS, p->page_rows,
                                              p->row_bytes, p->width, p->columns);
            if (status != 0)
                return status;
        }
        r++;
    }
    return 0;
}

int stp_panel_pages_send(const stp_panel_controller *c, const stp_panel_bus *bus, uint32_t y0,
                         uint32_t rows, const uint8_t *pages, size_t stride, uint32_t width)
{
    uint32_t k, count = (rows + PAGE_ROWS - 1u) / PAGE_ROWS;
    if (y0 % PAGE_ROWS != 0)
        return -1;
    for (k = 0; k < count; k++) {
        int status = stp_panel_send_page(c, bus, y0 / PAGE_ROWS + k, pages + (size_t)k * stride, width);
        if (status != 0)
            return status;
    }
    return 0;
}
