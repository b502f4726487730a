/* SPDX-License-Identifier: MIT */
/* Bands of any height onto an 8-row-page controller (stp_panel.h,
 * stp_panel_pages). */
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
