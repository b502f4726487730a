/*
 * stipple firmware for the lm3s6965evb: render the compiled scene in bands
 * onto the SSD0323 OLED, report instruction counts over semihosting, exit.
 *
 * RAM: the renderer object, the scene's display file (in the generated
 * source), and per band STP_FW_BAND_ROWS rows of MONO1 pixels plus their
 * Z-buffer rows; the picture itself lives only in the panel.
 */
#include "lm3s6965_oled.h"
#include "stellaris.h"
#include "stp_panel.h"
#include "stp_scene_data.h"
#include "stipple/stipple.h"

#ifndef STP_FW_BAND_ROWS
#define STP_FW_BAND_ROWS 4
#endif

#define PANEL_W 128u
#define PANEL_H 64u
#define ROW_BYTES (PANEL_W / 8u)

/* The renderer object in static storage, sized by STP_RENDERER_BYTES (the
 * compile-time bound of stp_renderer_size()). */
static stp_renderer_storage renderer;

static uint8_t band[STP_FW_BAND_ROWS * ROW_BYTES];
#if STP_WITH_ZBUFFER
static uint16_t zbuf[STP_FW_BAND_ROWS * PANEL_W];
#endif
static uint8_t packed[PANEL_W / 2u];

static int panel_flush(stp_port *port, uint32_t y0, uint32_t rows, const uint8_t *pixels,
                       size_t stride)
{
    (void)port;
    (void)y0; /* bands come top to bottom and the window was set for the frame */
    return stp_panel_send_mono_rows(&stp_panel_ssd0323, &stp_lm3s6965_oled_bus, pixels, stride,
                                    PANEL_W, rows, packed) == 0
               ? 0
               : -1;
}

static int discard_flush(stp_port *port, uint32_t y0, uint32_t rows, const uint8_t *pixels,
                         size_t stride)
{
    (void)port;
    (void)y0;
    (void)rows;
    (void)pixels;
    (void)stride;
    return 0;
}

/* Hold the picture until the board's "up" key (PE0) changes level, then
 * return: a test harness takes its screendump first and then presses the
 * key (QMP send-key up), so the firmware's own exit status still ends QEMU.
 * A change rather than a level: QEMU's gamepad drives PE0 through an
 * inverter and the pin reads 0 until the first key event. */
static void wait_for_key(void)
{
    uint32_t first;
    STP_SYSCTL_RCGC2 |= 1u << 4;
    STP_GPIO_DIR(STP_GPIO_E) &= ~1u;
    STP_GPIO_DEN(STP_GPIO_E) |= 1u;
    first = STP_GPIO_DATA(STP_GPIO_E, 1u);
    stp_semihost_write("stipple: frame done; press up to finish\n");
    while (STP_GPIO_DATA(STP_GPIO_E, 1u) == first)
        ;
}

static void report(const char *what, uint64_t count)
{
    char num[12];
    stp_semihost_write("stipple: ");
    stp_semihost_write(what);
    stp_semihost_write(" ");
    stp_semihost_write(stp_utoa(count > 0xFFFFFFFFu ? 0xFFFFFFFFu : (uint32_t)count, num));
    stp_semihost_write("\n");
}

static int fail(const char *what, int status)
{
    stp_semihost_write("stipple: ");
    stp_semihost_write(what);
    stp_semihost_write(": ");
    stp_semihost_write(stp_status_text(status));
    stp_semihost_write("\n");
    return 1;
}

int main(void)
{
    const stp_scene_data *scene = &stp_compiled_scene;
    stp_renderer *r;
    stp_port port;
    stp_output out;
    stp_frame_memory mem;
    uint64_t t0, t1, t2, t3, t4;
    uint32_t per_tick;
    int status;

    stp_count_start();
    per_tick = stp_count_calibrate();
    if (scene->width != PANEL_W || scene->height != PANEL_H)
        return fail("scene size", STP_ERR_ARG);

    t0 = stp_count_now();
    status = stp_scene_data_enter(scene, &renderer, sizeof renderer, &r);
    t1 = stp_count_now();
    if (status != STP_OK)
        return fail("enter", status);

    stp_scene_data_output(scene, &out);
    mem.band = band;
    mem.band_size = sizeof band;
    mem.band_rows = STP_FW_BAND_ROWS;
#if STP_WITH_ZBUFFER
    mem.zbuf = zbuf;
    mem.zbuf_count = sizeof zbuf / sizeof zbuf[0];
#else
    mem.zbuf = 0;
    mem.zbuf_count = 0;
#endif
    mem.sort = scene->sort;
    mem.sort_count = scene->sort_count;

    port.width = PANEL_W;
    port.height = PANEL_H;
    port.format = STP_PIXEL_MONO1;
    port.user = 0;

    /* the frame through the core alone, the panel's transfer left out */
    port.flush = discard_flush;
    status = stp_render(r, &port, &out, &mem);
    t2 = stp_count_now();
    if (status != STP_OK)
        return fail("render", status);

    stp_lm3s6965_oled_setup();
    if (stp_panel_init(&stp_panel_ssd0323, &stp_lm3s6965_oled_bus) != 0 ||
        stp_panel_window_all(&stp_panel_ssd0323, &stp_lm3s6965_oled_bus) != 0)
        return fail("panel", STP_ERR_PORT);
    t3 = stp_count_now();
    port.flush = panel_flush;
    status = stp_render(r, &port, &out, &mem);
    if (status != STP_OK)
        return fail("render to panel", status);

    t4 = stp_count_now();
    report("instructions per SysTick tick:", per_tick);
    report("instructions to enter the scene:", (t1 - t0) * per_tick);
    report("instructions per frame (core):", (t2 - t1) * per_tick);
    report("instructions per frame (core + panel):", (t4 - t3) * per_tick);
    report("band rows:", STP_FW_BAND_ROWS);
    report("renderer bytes:", stp_renderer_size());
    report("display-file entries:", stp_display_file_used(r));
    wait_for_key();
    return 0;
}
