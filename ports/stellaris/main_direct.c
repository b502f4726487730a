/* SPDX-License-Identifier: MIT */
/*
 * The shipping firmware of direct drawing (issue 15 item 3): the spinning
 * torus of ports/direct/direct_spin.h on the board's panel (board.h; the
 * lm3s6965evb's 128x64 OLED), frame after frame, in STP_FW_BAND_ROWS-row
 * bands of caller memory (u8g2-style page mode).  No display file, no
 * renderer object: RAM is the model (its vertices, triangles and normals,
 * here built on the chip), one 16-byte point per vertex, two bytes per
 * triangle and the band.  tools/firmware_lean_sizes.sh measures it; the
 * same frames are checked pixel for pixel on the mps2-an385
 * (tools/bench/mps2_direct.sh).  STP_DIRECT_FRAMES > 0 stops after that
 * many frames and holds the picture (board->hold); 0 spins for ever.
 * The bands are in the board's format (board.h): MONO1 rows, or a page
 * panel's own pages (STP_BAND_PAGES, whole 8-row pages) sent as drawn.
 */
#include "board.h"
#include "direct_spin.h"
#include "stellaris.h"

#ifndef STP_FW_BAND_ROWS
#define STP_FW_BAND_ROWS 8
#endif
#ifndef STP_DIRECT_FRAMES
#define STP_DIRECT_FRAMES 0
#endif

static direct_spin spin;
/* rows of SPIN_STRIDE bytes, or as many bytes in pages of SPIN_WIDTH */
static uint8_t band[SPIN_STRIDE * STP_FW_BAND_ROWS];

int main(void)
{
    const stp_board *board = &stp_board_this;
    stp_direct_frame f;
    stp_port port;
    uint16_t n;
    uint32_t y;
    int status, pages = board->format == STP_PIXEL_MONO1_PAGES;
    size_t stride = pages ? SPIN_WIDTH : SPIN_STRIDE;
    port.width = SPIN_WIDTH;
    port.height = SPIN_HEIGHT;
    port.format = board->format;
    port.flush = board->flush;
    port.user = 0;
    if (board->width != SPIN_WIDTH || board->height != SPIN_HEIGHT ||
        (pages && STP_FW_BAND_ROWS % 8u != 0) || board->panel_start() != 0 ||
        direct_spin_init(&spin) != STP_OK) {
        stp_semihost_write("stipple: direct setup failed\n");
        return 1;
    }
#if STP_DIRECT_FRAMES > 0
    for (n = 0; n < STP_DIRECT_FRAMES; n++) {
#else
    for (n = 0;; n++) {
#endif
        status = direct_spin_frame(&spin, n, &f);
        f.layout = pages ? STP_BAND_PAGES : STP_BAND_ROWS;
        for (y = 0; status == STP_OK && y < SPIN_HEIGHT; y += STP_FW_BAND_ROWS) {
            status = stp_direct_draw_band(&f, band, stride, (uint16_t)y, STP_FW_BAND_ROWS);
            if (status == STP_OK && board->flush(&port, y, STP_FW_BAND_ROWS, band, stride) != 0)
                status = STP_ERR_PORT;
        }
        if (status != STP_OK) {
            stp_semihost_write("stipple: direct frame failed\n");
            return 1;
        }
    }
    board->hold();
    return 0;
}
