/* SPDX-License-Identifier: MIT */
/*
 * stipple firmware for an ATmega2560 (Arduino Mega 2560 wiring, no Arduino
 * core): render the compiled scene in bands onto an SSD1306 128x64 OLED on
 * the SPI (avr_ssd1306_spi.h), then stop.
 *
 * 8 KB of SRAM, and avr-gcc keeps const data there too: the scene's
 * vertices, the display file (what the scene enters), the renderer object
 * (STP_RENDERER_BYTES of the scene's configuration), STP_FW_BAND_ROWS rows
 * of MONO1 pixels, their Z-buffer rows and one 8-row page being gathered.
 *
 * The verdict goes to GPIOR0 (0: drawn; 1: the scene's size; 2: entering;
 * 3: the panel's init; 4: rendering; 5: STP_RENDERER_BYTES, which the
 * firmware build measures, is not stp_renderer_size()), then the CPU sleeps
 * with interrupts off, which ends a simavr run (tests/avr).
 */
#include <avr/interrupt.h>
#include <avr/io.h>
#include <avr/sleep.h>

#include "avr_ssd1306_spi.h"
#include "stp_panel.h"
#include "stp_scene_data.h"
#include "stipple/stipple.h"

#ifndef STP_FW_BAND_ROWS
#define STP_FW_BAND_ROWS 4
#endif

#define PANEL_W 128u
#define PANEL_H 64u
#define ROW_BYTES (PANEL_W / 8u)

static stp_renderer_storage renderer;
static uint8_t band[STP_FW_BAND_ROWS * ROW_BYTES];
#if STP_WITH_ZBUFFER
static uint16_t zbuf[STP_FW_BAND_ROWS * PANEL_W];
#endif
static uint8_t page_rows[8u * ROW_BYTES];
static uint8_t columns[PANEL_W];

static const stp_panel_pages pages = {&stp_panel_ssd1306, &stp_avr_ssd1306_bus, PANEL_W, PANEL_H,
                                      ROW_BYTES, page_rows, columns};

static int flush(stp_port *port, uint32_t y0, uint32_t rows, const uint8_t *pixels, size_t stride)
{
    (void)port;
    return stp_panel_pages_put(&pages, y0, rows, pixels, stride) == 0 ? 0 : -1;
}

static void finish(uint8_t verdict)
{
    GPIOR0 = verdict;
    cli();
    sleep_enable();
    sleep_cpu();
    for (;;)
        ;
}

int main(void)
{
    const stp_scene_data *scene = &stp_compiled_scene;
    stp_renderer *r;
    stp_port port;
    stp_output out;
    stp_frame_memory mem;

    if (scene->width != PANEL_W || scene->height != PANEL_H)
        finish(1);
    if (stp_scene_data_enter(scene, &renderer, sizeof renderer, &r) != STP_OK)
        finish(2);
    stp_avr_ssd1306_setup();
    if (stp_panel_run(stp_panel_ssd1306.init, stp_panel_ssd1306.init_length, &stp_avr_ssd1306_bus,
                      stp_avr_ssd1306_step, 0) != 0)
        finish(3);

    stp_scene_data_output(scene, &out);
    stp_scene_frame_memory(&mem, band, sizeof band, STP_FW_BAND_ROWS, scene->sort,
                           scene->sort_count);
#if STP_WITH_ZBUFFER
    mem.zbuf = zbuf;
    mem.zbuf_count = sizeof zbuf / sizeof zbuf[0];
#endif
    port.width = PANEL_W;
    port.height = PANEL_H;
    port.format = STP_PIXEL_MONO1;
    port.user = 0;
    port.flush = flush;
    if (stp_renderer_render(r, &port, &out, &mem) != STP_OK)
        finish(4);
    finish(STP_RENDERER_BYTES == stp_renderer_size() ? 0 : 5);
    return 0;
}
