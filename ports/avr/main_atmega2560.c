/* SPDX-License-Identifier: MIT */
/*
 * stipple firmware for an ATmega2560 (Arduino Mega 2560 wiring, no Arduino
 * core): render the compiled scene in bands onto an SSD1306 128x64 OLED on
 * the SPI (avr_ssd1306_spi.h), then stop.
 *
 * 8 KB of SRAM, and avr-gcc keeps const data there too: the scene's
 * vertices, the display file (what the scene enters), the renderer object
 * (STP_RENDERER_BYTES of the scene's configuration), and a band of whole
 * 8-row pages (STP_FW_BAND_ROWS rounded up to a multiple of 8) in the
 * panel's own layout (STP_PIXEL_MONO1_PAGES) with its Z-buffer rows: each
 * page goes to the panel as the renderer wrote it, nothing repacked.
 *
 * For the simulator (tests/avr) GPIOR1 marks the end of the set-up (1)
 * and of the frame (2), and the bus sets GPIOR2 while it sends, so the
 * frame's cycles are counted with and without the bus.
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
/* page bands: whole pages of 8 rows (port.h, STP_PIXEL_MONO1_PAGES) */
#define BAND_ROWS ((STP_FW_BAND_ROWS + 7u) / 8u * 8u)

static stp_renderer_storage renderer;
static uint8_t band[BAND_ROWS / 8u * PANEL_W];
#if STP_WITH_ZBUFFER
static uint16_t zbuf[BAND_ROWS * PANEL_W];
#endif

static int flush(stp_port *port, uint32_t y0, uint32_t rows, const uint8_t *pixels, size_t stride)
{
    (void)port;
    return stp_panel_pages_send(&stp_panel_ssd1306, &stp_avr_ssd1306_bus, y0, rows, pixels, stride,
                                PANEL_W) == 0
               ? 0
               : -1;
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
    stp_scene_frame_memory(&mem, band, sizeof band, BAND_ROWS, scene->sort,
                           scene->sort_count);
#if STP_WITH_ZBUFFER
    mem.zbuf = zbuf;
    mem.zbuf_count = sizeof zbuf / sizeof zbuf[0];
#endif
    port.width = PANEL_W;
    port.height = PANEL_H;
    port.format = STP_PIXEL_MONO1_PAGES;
    port.user = 0;
    port.flush = flush;
    GPIOR1 = 1; /* the set-up's end */
    if (stp_renderer_render(r, &port, &out, &mem) != STP_OK)
        finish(4);
    GPIOR1 = 2; /* the frame's */
    finish(STP_RENDERER_BYTES == stp_renderer_size() ? 0 : 5);
    return 0;
}
