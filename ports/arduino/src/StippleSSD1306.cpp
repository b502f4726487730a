/* SPDX-License-Identifier: MIT */
/* SSD1306 drawing, whatever the bus (StippleSSD1306.h). */
#include <Arduino.h>
#ifdef __AVR__
#include <util/delay.h>
#endif

#include "StippleSSD1306.h"

#include "stipple/render.h"
#include "stipple_sim.h"
#include "stp_panel.h"

void StippleSSD1306::wait(unsigned ms)
{
#ifdef __AVR__
    while (ms-- != 0)
        _delay_ms(1);
#else
    delay(ms);
#endif
}

int StippleSSD1306::busCommand(void *ctx, const uint8_t *bytes, size_t count)
{
    return static_cast<StippleSSD1306 *>(ctx)->command(bytes, (uint8_t)count);
}

int StippleSSD1306::busData(void *ctx, const uint8_t *bytes, size_t count)
{
    StippleSSD1306 *self = static_cast<StippleSSD1306 *>(ctx);
    int status;
    self->dataStart();
    status = self->dataPut(bytes, (uint8_t)count);
    return self->dataEnd() != 0 ? -1 : status;
}

int StippleSSD1306::step(void *ctx, unsigned op, unsigned arg)
{
    switch (op) {
    case STP_PANEL_STEP_RESET:
        static_cast<StippleSSD1306 *>(ctx)->reset(arg);
        return 0;
    case STP_PANEL_STEP_DELAY:
        wait(arg);
        return 0;
    default:
        return -1;
    }
}

int StippleSSD1306::initPanel()
{
    stp_panel_bus bus;
    bus.command = busCommand;
    bus.data = busData;
    bus.ctx = this;
    return stp_panel_run(stp_panel_ssd1306.init, stp_panel_ssd1306.init_length, &bus, step, this) == 0
               ? STP_OK
               : STP_ERR_PORT;
}

/* page, column low and high nibbles, then the page's data may follow */
int StippleSSD1306::pageAddress(uint8_t page)
{
    const stp_panel_controller *c = &stp_panel_ssd1306;
    uint8_t cmd[3];
    cmd[0] = (uint8_t)(c->page_command | page);
    cmd[1] = (uint8_t)(c->column_low_command | (c->column_offset & 15u));
    cmd[2] = (uint8_t)(c->column_high_command | (c->column_offset >> 4));
    return pageStart(cmd, 3);
}

int StippleSSD1306::pageStart(const uint8_t *address, uint8_t count)
{
    if (command(address, count) != 0)
        return -1;
    dataStart();
    return 0;
}

int StippleSSD1306::sendPage(uint8_t page, const uint8_t *rows, size_t stride)
{
    uint8_t block[8], b;
    int status;
    if (pageAddress(page) != 0)
        return STP_ERR_PORT;
    status = 0;
    for (b = 0; b < width / 8 && status == 0; b++) {
        stp_panel_pack_block(rows + b, stride, block);
        status = dataPut(block, 8);
    }
    if (dataEnd() != 0)
        status = -1;
    return status == 0 ? STP_OK : STP_ERR_PORT;
}

/* A page already in the panel's layout (width bytes). */
int StippleSSD1306::sendPageBytes(uint8_t page, const uint8_t *columns)
{
    int status;
    if (pageAddress(page) != 0)
        return STP_ERR_PORT;
    status = dataPut(columns, width);
    if (dataEnd() != 0)
        status = -1;
    return status == 0 ? STP_OK : STP_ERR_PORT;
}

/* A frame: bands drawn straight in the panel's page layout
 * (STP_BAND_PAGES), each page sent as it is. */
int StippleSSD1306::drawFrame(const stp_direct_frame &frame)
{
    stp_direct_frame pages = frame;
    uint8_t y, p;
    int status = STP_OK;
    if (frame.width != width || frame.height != height)
        return STP_ERR_ARG;
    pages.layout = STP_BAND_PAGES;
    for (y = 0; y < height && status == STP_OK; y = (uint8_t)(y + band_rows_)) {
        status = stp_direct_draw_band(&pages, band_, width, y, band_rows_);
        for (p = 0; p < band_rows_ / 8u && status == STP_OK; p++)
            status = sendPageBytes((uint8_t)(y / 8u + p), band_ + (size_t)p * width);
    }
    STIPPLE_SIM_FRAME(status);
    return status;
}

/* A span picture: the player writes rows, packed into pages on the way
 * out. */
int StippleSSD1306::drawSpans(const stp_spans &spans)
{
    const size_t stride = width / 8;
    stp_spans_cursor cursor;
    uint8_t y, p;
    int status = STP_OK;
    if (spans.width != width || spans.height != height)
        return STP_ERR_ARG;
    stp_spans_start(&spans, &cursor);
    for (y = 0; y < height && status == STP_OK; y = (uint8_t)(y + band_rows_)) {
        status = stp_spans_draw(&spans, &cursor, band_, stride, band_rows_);
        for (p = 0; p < band_rows_ / 8u && status == STP_OK; p++)
            status = sendPage((uint8_t)(y / 8u + p), band_ + 8u * p * stride, stride);
    }
    STIPPLE_SIM_FRAME(status);
    return status;
}
