/* SPDX-License-Identifier: MIT */
/*
 * The port interface: the only door between the core and a device.
 *
 * A device says its size and pixel format and receives the picture as bands:
 * runs of whole rows, top to bottom.  A device with a frame's worth of RAM
 * asks for one band as tall as the frame; a panel with little RAM gives a
 * buffer of a few rows and is called once per band.  The core knows nothing
 * else of devices; ports know nothing of shading.
 */
#ifndef STIPPLE_PORT_H
#define STIPPLE_PORT_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum stp_pixel_format {
    /* 1 bit per pixel, rows packed most significant bit first (pixel 0 of a
     * row is bit 7 of its first byte), a row padded to whole bytes; bit 1 =
     * ON = lit/light (PBM is the opposite: its writer inverts). */
    STP_PIXEL_MONO1 = 0,
    /* 8-bit grey, 0 = black, 255 = white: the gamma-mapped intensity. */
    STP_PIXEL_GREY8 = 1,
    /* 24-bit R, G, B bytes per pixel, 0 = dark. */
    STP_PIXEL_RGB888 = 2,
    /* 8-bit style codes: each pixel holds the code the style table gives for
     * its INTENSITY index (a line printer's character, say); without a table,
     * the index 1..levels itself (so at most 255 levels: stp_renderer_render refuses
     * 256 with STP_ERR_ARG) (0 where nothing is drawn and the
     * background is 0). */
    STP_PIXEL_STYLE8 = 3,
    /* 1 bit per pixel in the SSD1306 / SH1106 page layout (stipple/dither.h,
     * STP_BAND_PAGES), bit 1 = ON as MONO1: a band is pages of 8 rows, one
     * byte a column, least significant bit on top, so pixel (x, y) of a band
     * starting at row y0 is bit (y - y0) mod 8 of byte ((y - y0) / 8) width
     * + x, and each page goes to the panel as it is.  The stride of a band
     * (stp_row_bytes, the flush's stride) is the bytes of one page, width;
     * a band of rows rows takes (rows + 7) / 8 pages, (rows + 7) / 8 width
     * bytes, the bits of rows past the last band's rows 0.  stp_renderer_render and
     * stp_rt_render ask for band_rows a multiple of 8 unless one band holds
     * the whole frame (so every band but the frame's last is whole pages
     * and starts on a page), else STP_ERR_ARG. */
    STP_PIXEL_MONO1_PAGES = 4
} stp_pixel_format;

/* The stride of a band of format fmt and width pixels: the bytes of one
 * row, or for STP_PIXEL_MONO1_PAGES the bytes of one page of 8 rows
 * (width); 0 for an unknown format. */
size_t stp_row_bytes(stp_pixel_format fmt, uint32_t width);

struct stp_port;

/* Receives rows [y0, y0 + rows) of the picture; pixels holds them, row
 * stride bytes apart (STP_PIXEL_MONO1_PAGES: (rows + 7) / 8 pages, stride
 * bytes apart).  The buffer is the renderer's until the call returns
 * (the core reuses it for the next band).  Return 0 to go on, or a negative
 * value to stop the frame: stp_renderer_render then returns STP_ERR_PORT. */
typedef int (*stp_flush_fn)(struct stp_port *port, uint32_t y0, uint32_t rows,
                            const uint8_t *pixels, size_t stride);

typedef struct stp_port {
    uint32_t width, height;       /* pixels, 1..32767 each */
    stp_pixel_format format;
    stp_flush_fn flush;
    void *user;                   /* the port's own state */
} stp_port;

#ifdef __cplusplus
}
#endif

#endif
