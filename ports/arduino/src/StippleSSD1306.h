/* SPDX-License-Identifier: MIT */
/*
 * An SSD1306 128x64 OLED for the Arduino library: the drawing, whatever
 * the bus.  Pictures are drawn into one band of rows (the only frame
 * memory: 16 rows, 256 bytes, on SPI; 8 rows, 128 bytes, on I2C, whose
 * bus takes longer than a band's drawing anyway) and go out a page (8 rows)
 * at a time: a direct-drawing frame is drawn straight in the panel's page
 * layout (STP_BAND_PAGES) and sent as it is; a span picture's rows are
 * packed into columns 8x8 pixels at a time on their way to the bus.
 *
 * The bus is the class that derives from this template, header only, so a
 * sketch links only the Arduino library it uses: StippleSSD1306I2C.h
 * (Wire) or StippleSSD1306SPI.h (SPI).  A template rather than virtual
 * functions: each bus call is a direct call the compiler can inline (on
 * an Uno about 500 bytes of flash fewer than a vtable's indirect calls).
 * A bus class Bus provides, for the template's use:
 *   int command(const uint8_t *bytes, uint8_t count)  count command bytes
 *                                                      in one transfer
 *   int pageStart(const uint8_t *address, uint8_t count)  the page address
 *                                                      commands, then data
 *   int dataPut(const uint8_t *bytes, uint8_t count)  a page's data
 *   int dataEnd()                                      the page's end
 *   void reset(unsigned ms)                            RES# held ms (if wired)
 * each returning 0 or -1 (the bus failed).
 */
#ifndef STIPPLE_ARDUINO_SSD1306_H
#define STIPPLE_ARDUINO_SSD1306_H

#include <Arduino.h>
#include <stddef.h>
#include <stdint.h>
#ifdef __AVR__
#include <util/delay.h>
#endif

#include "stipple/direct.h"
#include "stipple/playback_spans.h"
#include "stipple/render.h"
#include "stipple_sim.h"
#include "stp_panel.h"

template <class Bus, uint8_t BandRows> class StippleSSD1306 {
public:
    static const uint8_t width = 128, height = 64;

    /* Draw a direct-drawing frame (stp_direct_frame_project, 128x64) band
     * by band.  Returns STP_OK, STP_ERR_ARG (not 128x64), the error of
     * stp_direct_draw_band, or STP_ERR_PORT (the bus failed). */
    int drawFrame(const stp_direct_frame &frame)
    {
        stp_direct_frame pages = frame;
        uint8_t y, p;
        int status = STP_OK;
        if (frame.width != width || frame.height != height)
            return STP_ERR_ARG;
        /* the copy's layout and size constants the compiler folds into
         * the inlined band fill (the caller's frame could be written by
         * the band's bytes as far as it knows) */
        pages.layout = STP_BAND_PAGES;
        pages.width = width;
        pages.height = height;
        for (y = 0; y < height && status == STP_OK; y = (uint8_t)(y + BandRows)) {
            status = stp_direct_draw_band(&pages, band_, width, y, BandRows);
            for (p = 0; p < BandRows / 8u && status == STP_OK; p++)
                status = sendPageBytes((uint8_t)(y / 8u + p), band_ + (size_t)p * width);
        }
        STIPPLE_SIM_FRAME(status);
        return status;
    }

    /* Play a span picture (stipple compile --spans, 128x64) from the start.
     * Returns STP_OK, STP_ERR_ARG, the error of stp_spans_draw, or
     * STP_ERR_PORT. */
    int drawSpans(const stp_spans &spans)
    {
        const size_t stride = width / 8;
        stp_spans_cursor cursor;
        uint8_t y, p;
        int status = STP_OK;
        if (spans.width != width || spans.height != height)
            return STP_ERR_ARG;
        stp_spans_start(&spans, &cursor);
        for (y = 0; y < height && status == STP_OK; y = (uint8_t)(y + BandRows)) {
            status = stp_spans_draw(&spans, &cursor, band_, stride, BandRows);
            for (p = 0; p < BandRows / 8u && status == STP_OK; p++)
                status = sendPage((uint8_t)(y / 8u + p), band_ + 8u * p * stride, stride);
        }
        STIPPLE_SIM_FRAME(status);
        return status;
    }

    /* Send one page (rows 8 page .. 8 page + 7) of a MONO1 picture 128
     * wide, rows stride bytes apart.  Returns STP_OK or STP_ERR_PORT. */
    int sendPage(uint8_t page, const uint8_t *rows, size_t stride)
    {
        uint8_t block[8], b;
        int status = pageAddress(page);
        for (b = 0; b < width / 8 && status == 0; b++) {
            stp_panel_pack_block(rows + b, stride, block);
            status = bus().dataPut(block, 8);
        }
        return bus().dataEnd() != 0 || status != 0 ? STP_ERR_PORT : STP_OK;
    }

protected:
    /* The reset pulse and the init sequence (ports/controllers/ssd1306.c).
     * Returns STP_OK or STP_ERR_PORT. */
    int initPanel()
    {
        stp_panel_bus b;
        b.command = busCommand;
        b.data = 0; /* the init sequence sends commands and steps only */
        b.ctx = this;
        return stp_panel_run(stp_panel_ssd1306.init, stp_panel_ssd1306.init_length, &b, step, this) == 0
                   ? STP_OK
                   : STP_ERR_PORT;
    }

    /* Wait ms milliseconds (the reset pulse, the init sequence's delays):
     * on an AVR a cycle-counted loop (util/delay.h at F_CPU), so a sketch
     * links neither delay() nor micros() (190 bytes of an Uno image);
     * elsewhere delay(). */
    static void wait(unsigned ms)
    {
#ifdef __AVR__
        while (ms-- != 0)
            _delay_ms(1);
#else
        delay(ms);
#endif
    }

private:
    uint8_t band_[BandRows * (width / 8)];

    Bus &bus() { return *static_cast<Bus *>(this); }

    /* page, column low and high nibbles, then the page's data may follow */
    int pageAddress(uint8_t page)
    {
        const stp_panel_controller *c = &stp_panel_ssd1306;
        uint8_t cmd[3];
        cmd[0] = (uint8_t)(c->page_command | page);
        cmd[1] = (uint8_t)(c->column_low_command | (c->column_offset & 15u));
        cmd[2] = (uint8_t)(c->column_high_command | (c->column_offset >> 4));
        return bus().pageStart(cmd, 3);
    }

    /* A page already in the panel's layout (width bytes). */
    int sendPageBytes(uint8_t page, const uint8_t *columns)
    {
        int status = pageAddress(page);
        if (status == 0)
            status = bus().dataPut(columns, width);
        return bus().dataEnd() != 0 || status != 0 ? STP_ERR_PORT : STP_OK;
    }

    static int busCommand(void *ctx, const uint8_t *bytes, size_t count)
    {
        return static_cast<Bus *>(static_cast<StippleSSD1306 *>(ctx))->command(bytes, (uint8_t)count);
    }

    static int step(void *ctx, unsigned op, unsigned arg)
    {
        if (op == STP_PANEL_STEP_RESET)
            static_cast<Bus *>(static_cast<StippleSSD1306 *>(ctx))->reset(arg);
        else if (op == STP_PANEL_STEP_DELAY)
            wait(arg);
        else
            return -1;
        return 0;
    }
};

#endif
