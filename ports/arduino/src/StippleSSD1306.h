/* SPDX-License-Identifier: MIT */
/*
 * An SSD1306 128x64 OLED for the Arduino library: the drawing, whatever
 * the bus.  Pictures are drawn into one band of rows (the only frame
 * memory: 16 rows, 256 bytes, on SPI; 8 rows, 128 bytes, on I2C, whose
 * bus takes longer than a band's drawing anyway) and go out a page (8 rows)
 * at a time: a direct-drawing frame is drawn straight in the panel's page
 * layout (STP_BAND_PAGES) and sent as it is; a span picture's rows are
 * packed into columns 8x8 pixels at a time on their way to the bus.  The bus is a subclass, header only, so a sketch links
 * only the Arduino library it uses: StippleSSD1306I2C.h (Wire) or
 * StippleSSD1306SPI.h (SPI).
 */
#ifndef STIPPLE_ARDUINO_SSD1306_H
#define STIPPLE_ARDUINO_SSD1306_H

#include <stddef.h>
#include <stdint.h>

#include "stipple/direct.h"
#include "stipple/playback_spans.h"

class StippleSSD1306 {
public:
    static const uint8_t width = 128, height = 64;

    /* Draw a direct-drawing frame (stp_direct_frame_project, 128x64) band
     * by band.  Returns STP_OK, STP_ERR_ARG (not 128x64), the error of
     * stp_direct_draw_band, or STP_ERR_PORT (the bus failed). */
    int drawFrame(const stp_direct_frame &frame);

    /* Play a span picture (stipple compile --spans, 128x64) from the start.
     * Returns STP_OK, STP_ERR_ARG, the error of stp_spans_draw, or
     * STP_ERR_PORT. */
    int drawSpans(const stp_spans &spans);

    /* Send one page (rows 8 page .. 8 page + 7) of a MONO1 picture 128
     * wide, rows stride bytes apart.  Returns STP_OK or STP_ERR_PORT. */
    int sendPage(uint8_t page, const uint8_t *rows, size_t stride);

protected:
    /* band: band_rows (a multiple of 8, dividing 64) x 16 bytes. */
    StippleSSD1306(uint8_t *band, uint8_t band_rows) : band_(band), band_rows_(band_rows) {}

    /* The reset pulse and the init sequence (ports/controllers/ssd1306.c).
     * Returns STP_OK or STP_ERR_PORT. */
    int initPanel();

    /* The bus: count command bytes in one transfer; a page's data as
     * dataStart, dataPut..., dataEnd; RES# asserted for ms (if wired).
     * Return 0 or -1. */
    virtual int command(const uint8_t *bytes, uint8_t count) = 0;
    virtual void dataStart() = 0;
    virtual int dataPut(const uint8_t *bytes, uint8_t count) = 0;
    virtual int dataEnd() = 0;
    virtual void reset(unsigned ms) = 0;
    /* The page address commands, then dataStart; a bus that can switch
     * from commands to data within one transfer overrides it. */
    virtual int pageStart(const uint8_t *address, uint8_t count);

    /* Wait ms milliseconds (the reset pulse, the init sequence's delays):
     * on an AVR a cycle-counted loop (util/delay.h at F_CPU), so a sketch
     * links neither delay() nor micros() (190 bytes of an Uno image);
     * elsewhere delay(). */
    static void wait(unsigned ms);

private:
    uint8_t *band_;
    uint8_t band_rows_;

    int pageAddress(uint8_t page);
    int sendPageBytes(uint8_t page, const uint8_t *columns);
    static int busCommand(void *ctx, const uint8_t *bytes, size_t count);
    static int busData(void *ctx, const uint8_t *bytes, size_t count);
    static int step(void *ctx, unsigned op, unsigned arg);
};

#endif
