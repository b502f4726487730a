/* SPDX-License-Identifier: MIT */
/*
 * Drawing a direct-drawing frame into a u8g2 page buffer, so a sketch that
 * already drives its panel with u8g2 adds a 3D picture under its text.
 * u8g2's buffer for the SSD1306 family (u8g2_ll_hvline_vertical_top_lsb)
 * is tile rows of 8 pixel rows; within a tile row, byte x holds column x,
 * bit r the r-th row from the top; the page buffer of the _1/_2 page
 * constructors holds u8g2_GetBufferTileHeight() tile rows starting at
 * u8g2_GetBufferCurrTileRow(), the full buffer (_F) all of them.
 *
 * In the page loop (u8g2.firstPage() / nextPage()), before the text:
 *   stipple_u8g2_draw(&frame, u8g2.getBufferPtr(), u8g2.getBufferTileHeight(),
 *                     u8g2.getBufferCurrTileRow(), scratch);
 */
#ifndef STIPPLE_U8G2_H
#define STIPPLE_U8G2_H

#include <stdint.h>

#include "stipple/direct.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The rows of frame f that the buffer holds (tile rows tile_row ..
 * tile_row + tile_rows - 1, cut at the frame's height), drawn a tile row
 * at a time in the page layout (STP_BAND_PAGES) into scratch (width
 * bytes) and OR'ed into buffer (width bytes per tile row: the buffer's
 * width must be the frame's).  Returns STP_OK, STP_ERR_ARG (a pointer
 * NULL, tile_rows 0) or the error of stp_direct_draw_band. */
int stipple_u8g2_draw(const stp_direct_frame *f, uint8_t *buffer, uint8_t tile_rows,
                      uint8_t tile_row, uint8_t *scratch);

#ifdef __cplusplus
}
#endif

#endif
