/* SPDX-License-Identifier: MIT */
/* SSD1306 over Arduino's SPI library (StippleSSD1306.h). */
#include <Arduino.h>
#include <SPI.h>

#include "StippleSSD1306.h"

StippleSSD1306::StippleSSD1306(uint8_t cs_pin, uint8_t dc_pin, uint8_t reset_pin)
    : cs_(cs_pin), dc_(dc_pin), reset_(reset_pin)
{
    bus_.command = command;
    bus_.data = data;
    bus_.ctx = this;
    pages_.controller = &stp_panel_ssd1306;
    pages_.bus = &bus_;
    pages_.width = width;
    pages_.height = height;
    pages_.row_bytes = width / 8;
    pages_.page_rows = page_rows_;
    pages_.columns = columns_;
}

void StippleSSD1306::send(const uint8_t *bytes, size_t count, bool is_data)
{
    /* the datasheet's 100 ns clock cycle: 8 MHz is within it */
    SPI.beginTransaction(SPISettings(8000000, MSBFIRST, SPI_MODE0));
    digitalWrite(dc_, is_data ? HIGH : LOW);
    digitalWrite(cs_, LOW);
    while (count--)
        SPI.transfer(*bytes++);
    digitalWrite(cs_, HIGH);
    SPI.endTransaction();
}

int StippleSSD1306::command(void *ctx, const uint8_t *bytes, size_t count)
{
    static_cast<StippleSSD1306 *>(ctx)->send(bytes, count, false);
    return 0;
}

int StippleSSD1306::data(void *ctx, const uint8_t *bytes, size_t count)
{
    static_cast<StippleSSD1306 *>(ctx)->send(bytes, count, true);
    return 0;
}

int StippleSSD1306::step(void *ctx, unsigned op, unsigned arg)
{
    StippleSSD1306 *self = static_cast<StippleSSD1306 *>(ctx);
    switch (op) {
    case STP_PANEL_STEP_RESET:
        digitalWrite(self->reset_, LOW);
        delay(arg);
        digitalWrite(self->reset_, HIGH);
        return 0;
    case STP_PANEL_STEP_DELAY:
        delay(arg);
        return 0;
    default:
        return -1;
    }
}

int StippleSSD1306::flush(stp_port *port, uint32_t y0, uint32_t rows, const uint8_t *pixels,
                          size_t stride)
{
    StippleSSD1306 *self = static_cast<StippleSSD1306 *>(port->user);
    return stp_panel_pages_put(&self->pages_, y0, rows, pixels, stride) == 0 ? 0 : -1;
}

int StippleSSD1306::begin()
{
    pinMode(cs_, OUTPUT);
    pinMode(dc_, OUTPUT);
    pinMode(reset_, OUTPUT);
    digitalWrite(cs_, HIGH);
    digitalWrite(reset_, HIGH);
    SPI.begin();
    return stp_panel_run(stp_panel_ssd1306.init, stp_panel_ssd1306.init_length, &bus_, step,
                         this) == 0
               ? STP_OK
               : STP_ERR_PORT;
}

int StippleSSD1306::draw(const stp_scene_data &scene)
{
    stp_renderer *r;
    stp_port port;
    stp_output out;
    stp_frame_memory mem;
    int status;
    if (scene.width != width || scene.height != height)
        return STP_ERR_ARG;
    status = stp_scene_data_enter(&scene, &renderer_, sizeof renderer_, &r);
    if (status != STP_OK)
        return status;
    stp_scene_data_output(&scene, &out);
    stp_scene_frame_memory(&mem, band_, sizeof band_, STIPPLE_BAND_ROWS, scene.sort,
                           scene.sort_count);
#if STP_WITH_ZBUFFER
    mem.zbuf = zbuf_;
    mem.zbuf_count = sizeof zbuf_ / sizeof zbuf_[0];
#endif
    port.width = width;
    port.height = height;
    port.format = STP_PIXEL_MONO1;
    port.flush = flush;
    port.user = this;
    return stp_renderer_render(r, &port, &out, &mem);
}
