/* SPDX-License-Identifier: MIT */
/*
 * An SSD1306 128x64 OLED for the Arduino library, on I2C (the Wire
 * library, 400 kHz) or 4-wire SPI (the SPI library, at half the CPU clock
 * up to 8 MHz: SCK, MOSI and the three pins given to beginSPI).  Pictures
 * go out a page (8 rows) at a time from one 8-row band of 128 bytes and a
 * 128-byte page of packed columns: 256 bytes in all.
 */
#ifndef STIPPLE_ARDUINO_SSD1306_H
#define STIPPLE_ARDUINO_SSD1306_H

#include <stddef.h>
#include <stdint.h>

#include "stipple/direct.h"
#include "stipple/playback_spans.h"
#include "stp_panel.h"

class StippleSSD1306 {
public:
    static const uint8_t width = 128, height = 64;

    StippleSSD1306();

    /* The panel on I2C at address (0x3C, or 0x3D with its SA0 high), the
     * bus at clock_hz; reset and initialised.  Returns STP_OK or
     * STP_ERR_PORT (no acknowledge). */
    int beginI2C(uint8_t address = 0x3C, uint32_t clock_hz = 400000ul);

    /* The panel on SPI: chip select, data/command and reset pins (any
     * digital pins).  Returns STP_OK or STP_ERR_PORT. */
    int beginSPI(uint8_t cs_pin, uint8_t dc_pin, uint8_t reset_pin);

    /* Draw a direct-drawing frame (stp_direct_frame_project, 128x64) page by
     * page.  Returns STP_OK, the error of stp_direct_draw_band, or
     * STP_ERR_PORT. */
    int drawFrame(const stp_direct_frame &frame);

    /* Play a span picture (stipple compile --spans, 128x64) from the start.
     * Returns STP_OK, the error of stp_spans_draw, or STP_ERR_PORT. */
    int drawSpans(const stp_spans &spans);

    /* Send one page (rows 8 page .. 8 page + 7) of a MONO1 picture, rows
     * stride bytes apart.  Returns STP_OK or STP_ERR_PORT. */
    int sendPage(uint8_t page, const uint8_t *rows, size_t stride);

private:
    uint8_t address_, cs_, dc_, reset_;
    bool spi_;
    stp_panel_bus bus_;
    uint8_t band_[8 * (width / 8)];
    uint8_t page_[width];

    int begin();
    void frameDone(int status);
    static int command(void *ctx, const uint8_t *bytes, size_t count);
    static int data(void *ctx, const uint8_t *bytes, size_t count);
    static int step(void *ctx, unsigned op, unsigned arg);
    int send(const uint8_t *bytes, size_t count, bool is_data);
};

#endif
