/* SPDX-License-Identifier: MIT */
/*
 * An SSD1306 128x64 OLED on Arduino's SPI library (4-wire: SCK, MOSI, and
 * the three pins given to begin: CS#, D/C#, RES#), drawing a compiled scene
 * band by band.
 */
#ifndef STIPPLE_ARDUINO_SSD1306_H
#define STIPPLE_ARDUINO_SSD1306_H

#include <stdint.h>

#include "stipple/stipple.h"
#include "stp_panel.h"
#include "stp_scene_data.h"

#ifndef STIPPLE_BAND_ROWS
#define STIPPLE_BAND_ROWS 2 /* rows rendered at a time: RAM against passes (4 leaves the
                              * teapot-s1 sketch too little stack on a Mega 2560) */
#endif

class StippleSSD1306 {
public:
    static const uint8_t width = 128, height = 64;

    /* Pins: chip select, data/command, reset (any digital pins). */
    StippleSSD1306(uint8_t cs_pin, uint8_t dc_pin, uint8_t reset_pin);

    /* SPI up, the panel reset and initialised.  Returns STP_OK, or
     * STP_ERR_PORT. */
    int begin();

    /* Enter the scene (the renderer lives in this object) and draw it.
     * Returns STP_OK or the core's error (stipple/render.h); the scene must
     * be compiled for 128x64 (stipple compile -s 128x64). */
    int draw(const stp_scene_data &scene);

private:
    uint8_t cs_, dc_, reset_;
    stp_panel_bus bus_;
    stp_panel_pages pages_;
    stp_renderer_storage renderer_;
    uint8_t band_[STIPPLE_BAND_ROWS * (width / 8)];
#if STP_WITH_ZBUFFER
    uint16_t zbuf_[STIPPLE_BAND_ROWS * width];
#endif
    uint8_t page_rows_[8 * (width / 8)];
    uint8_t columns_[width];

    static int command(void *ctx, const uint8_t *bytes, size_t count);
    static int data(void *ctx, const uint8_t *bytes, size_t count);
    static int step(void *ctx, unsigned op, unsigned arg);
    static int flush(stp_port *port, uint32_t y0, uint32_t rows, const uint8_t *pixels,
                     size_t stride);
    void send(const uint8_t *bytes, size_t count, bool is_data);
};

#endif
