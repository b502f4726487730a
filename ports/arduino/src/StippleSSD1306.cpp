/* SPDX-License-Identifier: MIT */
/* SSD1306 on Wire or SPI (StippleSSD1306.h). */
#include <Arduino.h>
#include <SPI.h>
#include <Wire.h>

#include "StippleSSD1306.h"

#include "stipple/render.h"
#include "stipple_sim.h"

/* A control byte and up to this many bytes per transmission: Wire's buffer
 * (BUFFER_LENGTH, 32 on an AVR) less the control byte. */
#if defined(BUFFER_LENGTH) && BUFFER_LENGTH > 1
#define I2C_CHUNK (BUFFER_LENGTH - 1u)
#else
#define I2C_CHUNK 16u
#endif
#define NO_PIN 0xFFu

StippleSSD1306::StippleSSD1306()
    : address_(0x3C), cs_(NO_PIN), dc_(NO_PIN), reset_(NO_PIN), spi_(false)
{
    bus_.command = command;
    bus_.data = data;
    bus_.ctx = this;
}

int StippleSSD1306::send(const uint8_t *bytes, size_t count, bool is_data)
{
    if (spi_) {
        /* the datasheet's 100 ns clock cycle: 8 MHz is within it */
        SPI.beginTransaction(SPISettings(8000000, MSBFIRST, SPI_MODE0));
        digitalWrite(dc_, is_data ? HIGH : LOW);
        digitalWrite(cs_, LOW);
        STIPPLE_SIM_BUS(1); /* the bytes' transfer only */
        while (count--)
            SPI.transfer(*bytes++);
        STIPPLE_SIM_BUS(0);
        digitalWrite(cs_, HIGH);
        SPI.endTransaction();
    } else {
        /* control byte: 0x00 commands follow, 0x40 data follow */
        STIPPLE_SIM_BUS(1);
        while (count > 0) {
            size_t n = count < I2C_CHUNK ? count : I2C_CHUNK;
            Wire.beginTransmission(address_);
            Wire.write(is_data ? 0x40 : 0x00);
            Wire.write(bytes, n);
            if (Wire.endTransmission() != 0) {
                STIPPLE_SIM_BUS(0);
                return -1;
            }
            bytes += n;
            count -= n;
        }
        STIPPLE_SIM_BUS(0);
    }
    return 0;
}

int StippleSSD1306::command(void *ctx, const uint8_t *bytes, size_t count)
{
    return static_cast<StippleSSD1306 *>(ctx)->send(bytes, count, false);
}

int StippleSSD1306::data(void *ctx, const uint8_t *bytes, size_t count)
{
    return static_cast<StippleSSD1306 *>(ctx)->send(bytes, count, true);
}

int StippleSSD1306::step(void *ctx, unsigned op, unsigned arg)
{
    StippleSSD1306 *self = static_cast<StippleSSD1306 *>(ctx);
    switch (op) {
    case STP_PANEL_STEP_RESET:
        if (self->reset_ != NO_PIN) {
            digitalWrite(self->reset_, LOW);
            delay(arg);
            digitalWrite(self->reset_, HIGH);
        }
        return 0;
    case STP_PANEL_STEP_DELAY:
        delay(arg);
        return 0;
    default:
        return -1;
    }
}

int StippleSSD1306::begin()
{
    return stp_panel_run(stp_panel_ssd1306.init, stp_panel_ssd1306.init_length, &bus_, step,
                         this) == 0
               ? STP_OK
               : STP_ERR_PORT;
}

int StippleSSD1306::beginI2C(uint8_t address, uint32_t clock_hz)
{
    spi_ = false;
    address_ = address;
    Wire.begin();
    Wire.setClock(clock_hz);
    return begin();
}

int StippleSSD1306::beginSPI(uint8_t cs_pin, uint8_t dc_pin, uint8_t reset_pin)
{
    spi_ = true;
    cs_ = cs_pin;
    dc_ = dc_pin;
    reset_ = reset_pin;
    pinMode(cs_, OUTPUT);
    pinMode(dc_, OUTPUT);
    pinMode(reset_, OUTPUT);
    digitalWrite(cs_, HIGH);
    digitalWrite(reset_, HIGH);
    SPI.begin();
    return begin();
}

int StippleSSD1306::sendPage(uint8_t page, const uint8_t *rows, size_t stride)
{
    return stp_panel_send_mono_page(&stp_panel_ssd1306, &bus_, page, rows, stride, width, page_) == 0
               ? STP_OK
               : STP_ERR_PORT;
}

void StippleSSD1306::frameDone(int status)
{
    STIPPLE_SIM_FRAME(status);
    (void)status;
}

int StippleSSD1306::drawFrame(const stp_direct_frame &frame)
{
    uint8_t page;
    int status = STP_OK;
    for (page = 0; page < height / 8 && status == STP_OK; page++) {
        status = stp_direct_draw_band(&frame, band_, width / 8, (uint16_t)(page * 8u), 8);
        if (status == STP_OK)
            status = sendPage(page, band_, width / 8);
    }
    frameDone(status);
    return status;
}

int StippleSSD1306::drawSpans(const stp_spans &spans)
{
    stp_spans_cursor cursor;
    uint8_t page;
    int status = STP_OK;
    stp_spans_start(&spans, &cursor);
    for (page = 0; page < height / 8 && status == STP_OK; page++) {
        status = stp_spans_draw(&spans, &cursor, band_, width / 8, 8);
        if (status == STP_OK)
            status = sendPage(page, band_, width / 8);
    }
    frameDone(status);
    return status;
}
