/* SPDX-License-Identifier: MIT */
/*
 * SPI panels through the real stp_spipanel and stp_device code, talking
 * spidev ioctls to emulated controllers (spi_sim.c) under umockdev; the
 * control lines are the emulated panel's pins behind the same
 * stp_spipanel_lines interface the libgpiod lines implement.  Run under
 * umockdev-wrapper.
 *
 * For SSD1306 (128x64), Sharp LS013B7DH03 (128x128) and SSD1680 (122x250
 * and 128x296): a shared scene (STP_SCENES_DIR) rendered through the port
 * in bands of 1, 3, 8 rows and the whole frame must leave the emulated
 * glass equal, pixel for pixel, to the MONO1 render of the same scene in
 * memory, with no protocol violation, every SPI message within spidev's
 * bufsiz, the BUSY waits exercised (SSD1680) and VCOM alternated (Sharp).
 * Error paths: spidev that cannot be opened, EIO in the middle of a frame,
 * BUSY that never drops (at init and at refresh), missing control lines,
 * and bad device specs for stp_device_open.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>
#include <linux/spi/spidev.h>

#include "render_scene.h"
#include "scene.h"
#include "spi_expect.h"
#include "spi_sim.h"
#include "test_scenes.h"
#include "stp_device.h"
#include "stp_posix.h"
#include "stp_spipanel.h"

static const uint32_t band_heights[] = {1, 3, 8, 0}; /* 0: the whole frame */

static void tool_options(stp_tool_options *to, uint32_t w, uint32_t h, uint32_t band)
{
    stp_tool_options_default(to);
    to->width = (int)w;
    to->height = (int)h;
    to->band_rows = (int)band;
}

static void assert_clean(spi_sim *sim)
{
    char *v = spi_sim_violations(sim);
    if (*v) {
        print_error("protocol violations: %s\n", v);
        g_free(v);
        fail();
    }
    g_free(v);
    assert_int_equal(sim->oversize, 0);
    assert_int_equal(sim->unknown_ioctls, 0);
    assert_true(sim->max_message <= sim->bufsiz);
}

static stp_spipanel *open_panel(spi_sim *sim, const stp_panel_controller *c, int with_vcom,
                                const stp_spipanel_options *opt)
{
    stp_spipanel_lines lines;
    char err[512];
    stp_spipanel *p;
    spi_sim_lines(sim, with_vcom, &lines);
    p = stp_spipanel_open("/dev/spidev0.0", c, &lines, opt, err, sizeof err);
    if (!p)
        fail_msg("open: %s", err);
    return p;
}

/* Renders scene through p in bands of every height and compares each time;
 * the panel's memory is scrambled before each frame. */
static void render_bands(spi_sim *sim, stp_spipanel *p, const char *scene_name, const char *label)
{
    stp_scene scene;
    stp_posix_frame want;
    size_t i;
    stp_port *port = stp_spipanel_port(p);
    /* a page controller takes pages (bands of 1 and 3 rows become 8) */
    assert_true(port->format == STP_PIXEL_MONO1 || port->format == STP_PIXEL_MONO1_PAGES);
    stp_test_load_scene(scene_name, &scene);
    spi_expected_render(&scene, port->width, port->height, &want);
    for (i = 0; i < sizeof band_heights / sizeof band_heights[0]; i++) {
        stp_tool_options to;
        char err[512], name[128];
        tool_options(&to, port->width, port->height, band_heights[i]);
        spi_sim_scramble(sim, (guint32)(7 + i));
        if (stp_tool_render(&scene, &to, port, NULL, err, sizeof err) != 0)
            fail_msg("%s, bands of %u: %s (%s)", label, band_heights[i], err,
                     stp_spipanel_error(p));
        snprintf(name, sizeof name, "%s-band%u", label, band_heights[i]);
        spi_assert_glass(sim, &want, name);
        assert_clean(sim);
    }
    stp_posix_frame_free(&want);
    stp_scene_free(&scene);
}

/* ---------------------------------------------------------------- SSD1306 */

static void test_ssd1306_scene(void **state)
{
    spi_sim *sim = spi_sim_new(SPI_SIM_SSD1306, 128, 64, 0);
    stp_spipanel *p;
    (void)state;
    p = open_panel(sim, &stp_panel_ssd1306, 0, NULL);
    assert_int_equal(stp_spipanel_max_transfer(p), 4096); /* no bufsiz file: spidev's default */
    assert_int_equal(sim->resets, 1);
    assert_int_equal(sim->mode & 0xFF, 0); /* mode 0, chip select active low */
    assert_int_equal(stp_spipanel_port(p)->format, STP_PIXEL_MONO1_PAGES);
    render_bands(sim, p, "tetra-s1.nff", "ssd1306-tetra");
    assert_int_equal(sim->speed_min, 8000000);
    assert_int_equal(sim->speed_max, 8000000);
    {
        /* a page band must start on a page */
        static const uint8_t page[128];
        stp_port *port = stp_spipanel_port(p);
        assert_int_equal(port->flush(port, 3, 5, page, 128), -1);
        assert_non_null(strstr(stp_spipanel_error(p), "starts on a page"));
    }
    stp_spipanel_close(p);
    assert_clean(sim);
    spi_sim_free(sim);
}

/* A bufsiz of 40 bytes: each 128-byte page goes out in 4 messages. */
static void test_ssd1306_small_bufsiz(void **state)
{
    spi_sim *sim = spi_sim_new(SPI_SIM_SSD1306, 128, 64, 40);
    stp_spipanel_options o;
    stp_spipanel *p;
    (void)state;
    stp_spipanel_options_default(&o);
    o.speed_hz = 2000000;
    p = open_panel(sim, &stp_panel_ssd1306, 0, &o);
    assert_int_equal(stp_spipanel_max_transfer(p), 40);
    render_bands(sim, p, "teapot-s1.nff", "ssd1306-teapot");
    assert_int_equal(sim->max_message, 40);
    assert_int_equal(sim->speed_max, 2000000);
    stp_spipanel_close(p);
    spi_sim_free(sim);
}

/* ---------------------------------------------------------------- Sharp */

static void test_sharp_scene_software_vcom(void **state)
{
    spi_sim *sim = spi_sim_new(SPI_SIM_SHARP, 128, 128, 0);
    stp_spipanel *p;
    char err[256];
    guint changes, commands;
    (void)state;
    p = open_panel(sim, &stp_panel_sharp_ls013b7dh03, 0, NULL);
    assert_int_equal(sim->mode & 0xFF, SPI_CS_HIGH); /* mode 0, SCS active high, MSB first */
    render_bands(sim, p, "teapot-s1.nff", "sharp-teapot");
    assert_int_equal(sim->lines_written, 4 * 128);
    assert_int_equal(sim->speed_max, 1000000);
    /* M1 alternates once per frame: 4 frames after the init's clear */
    assert_int_equal(sim->m1_changes, 4);
    changes = sim->m1_changes;
    commands = sim->vcom_commands;
    assert_int_equal(stp_spipanel_vcom_tick(p, err, sizeof err), 0);
    assert_int_equal(sim->m1_changes, changes + 1);
    assert_int_equal(sim->vcom_commands, commands + 1);
    assert_int_equal(sim->extcomin_edges, 0);
    stp_spipanel_close(p);
    assert_clean(sim);
    spi_sim_free(sim);
}

/* EXTCOMIN wired (EXTMODE high): VCOM goes through the line, and a bufsiz of
 * 100 bytes forces writes of 5 lines (1 + 5 * 18 + 1 = 92 bytes). */
static void test_sharp_extcomin_small_bufsiz(void **state)
{
    spi_sim *sim = spi_sim_new(SPI_SIM_SHARP, 128, 128, 100);
    stp_spipanel *p;
    char err[256];
    (void)state;
    sim->extmode = 1;
    p = open_panel(sim, &stp_panel_sharp_ls013b7dh03, 1, NULL);
    render_bands(sim, p, "tetra-s2.nff", "sharp-tetra");
    assert_int_equal(sim->max_message, 92);
    assert_int_equal(sim->extcomin_edges, 4); /* one per frame */
    assert_int_equal(stp_spipanel_vcom_tick(p, err, sizeof err), 0);
    assert_int_equal(sim->extcomin_edges, 5);
    assert_int_equal(sim->vcom_commands, 0);
    stp_spipanel_close(p);
    assert_clean(sim);
    spi_sim_free(sim);
}

/* ---------------------------------------------------------------- SSD1680 */

static void test_ssd1680_scene(void **state)
{
    spi_sim *sim = spi_sim_new(SPI_SIM_SSD1680, 122, 250, 0);
    stp_spipanel *p;
    (void)state;
    p = open_panel(sim, &stp_panel_ssd1680, 0, NULL);
    assert_int_equal(sim->resets, 1);
    assert_int_equal(sim->epd.swresets, 1);
    assert_true(sim->busy_polls > 0); /* the init waited for BUSY */
    render_bands(sim, p, "teapot-s2.nff", "ssd1680-teapot");
    assert_int_equal(sim->refreshes, 4);
    assert_int_equal(sim->epd.entry, 3);
    /* 16 bytes a row, 250 rows: 4000 bytes of RAM in one message */
    assert_int_equal(sim->max_message, 4000);
    stp_spipanel_close(p);
    assert_int_equal(sim->epd.deep_sleep, 1); /* the reset line can wake it */
    assert_clean(sim);
    spi_sim_free(sim);
}

/* 128x296: 4736 bytes of RAM, over spidev's default 4096: two messages. */
static void test_ssd1680_296(void **state)
{
    spi_sim *sim = spi_sim_new(SPI_SIM_SSD1680, 128, 296, 0);
    stp_spipanel *p;
    stp_scene scene;
    stp_posix_frame want;
    stp_tool_options to;
    char err[512];
    guint polls;
    (void)state;
    p = open_panel(sim, &stp_panel_ssd1680_128x296, 0, NULL);
    stp_test_load_scene("mount-s2.nff", &scene);
    spi_expected_render(&scene, 128, 296, &want);
    tool_options(&to, 128, 296, 5);
    polls = sim->busy_polls;
    if (stp_tool_render(&scene, &to, stp_spipanel_port(p), NULL, err, sizeof err) != 0)
        fail_msg("%s (%s)", err, stp_spipanel_error(p));
    assert_true(sim->busy_polls > polls); /* the refresh waited for BUSY */
    spi_assert_glass(sim, &want, "ssd1680-296-mount");
    assert_int_equal(sim->max_message, 4096);
    assert_clean(sim);
    stp_spipanel_close(p);
    stp_posix_frame_free(&want);
    stp_scene_free(&scene);
    spi_sim_free(sim);
}

/* ---------------------------------------------------------------- errors */

static void test_open_failure(void **state)
{
    spi_sim *sim = spi_sim_new(SPI_SIM_SHARP, 128, 128, 0);
    char err[256];
    (void)state;
    assert_null(stp_spipanel_open("/dev/spidev7.3", &stp_panel_sharp_ls013b7dh03, NULL, NULL, err,
                                  sizeof err));
    assert_string_equal(err, "spi /dev/spidev7.3: cannot open: No such file or directory "
                             "(is SPI enabled? Raspberry Pi: dtparam=spi=on)");
    spi_sim_free(sim);
}

static void test_missing_lines(void **state)
{
    spi_sim *sim = spi_sim_new(SPI_SIM_SSD1680, 122, 250, 0);
    stp_spipanel_lines lines;
    char err[256];
    (void)state;
    assert_null(
        stp_spipanel_open("/dev/spidev0.0", &stp_panel_ssd1306, NULL, NULL, err, sizeof err));
    assert_string_equal(err, "spi /dev/spidev0.0: controller SSD1306 needs a D/C line (dc=LINE)");
    spi_sim_lines(sim, 0, &lines);
    lines.wait_ready = NULL;
    assert_null(
        stp_spipanel_open("/dev/spidev0.0", &stp_panel_ssd1680, &lines, NULL, err, sizeof err));
    assert_string_equal(err,
                        "spi /dev/spidev0.0: controller SSD1680 needs a BUSY line (busy=LINE)");
    /* the firmware-only description of the SSD0323 is refused */
    assert_null(
        stp_spipanel_open("/dev/spidev0.0", &stp_panel_ssd0323, &lines, NULL, err, sizeof err));
    assert_string_equal(err, "spi /dev/spidev0.0: controller SSD0323 has no SPI description here");
    assert_int_equal(sim->messages, 0);
    spi_sim_free(sim);
}

/* EIO on the message that passes byte 500: rows 24..31 of a Sharp frame in
 * bands of 8 (2 bytes of init clear, then 146 bytes a band). */
static void test_eio_mid_frame(void **state)
{
    spi_sim *sim = spi_sim_new(SPI_SIM_SHARP, 128, 128, 0);
    stp_spipanel *p;
    stp_scene scene;
    stp_tool_options to;
    char err[512];
    (void)state;
    p = open_panel(sim, &stp_panel_sharp_ls013b7dh03, 0, NULL);
    sim->fail_after = 500;
    stp_test_load_scene("tetra-s1.nff", &scene);
    tool_options(&to, 128, 128, 8);
    assert_int_not_equal(stp_tool_render(&scene, &to, stp_spipanel_port(p), NULL, err, sizeof err),
                         0);
    assert_int_equal(sim->failed, 1);
    assert_string_equal(stp_spipanel_error(p),
                        "LS013B7DH03 on /dev/spidev0.0: rows 24..31: SPI transfer failed (a write "
                        "of 8 lines; 438 bytes had gone out this frame): Input/output error");
    stp_scene_free(&scene);
    stp_spipanel_close(p);
    spi_sim_free(sim);
}

/* EIO in the middle of an SSD1680 RAM write, bufsiz 1000. */
static void test_eio_ssd1680_ram(void **state)
{
    spi_sim *sim = spi_sim_new(SPI_SIM_SSD1680, 122, 250, 1000);
    stp_spipanel *p;
    uint8_t rows[250 * 16];
    stp_port *port;
    gsize before;
    (void)state;
    memset(rows, 0x5A, sizeof rows);
    p = open_panel(sim, &stp_panel_ssd1680, 0, NULL);
    port = stp_spipanel_port(p);
    before = sim->bytes;
    sim->fail_after = before + 2500; /* window commands, then 1000-byte chunks */
    assert_int_equal(port->flush(port, 0, 200, rows, 16), 0); /* gathered, nothing sent */
    assert_int_equal(sim->bytes, before);
    assert_int_equal(port->flush(port, 200, 50, rows, 16), -1);
    assert_non_null(strstr(stp_spipanel_error(p),
                           "SSD1680 on /dev/spidev0.0: frame: SPI transfer failed (pixel data; "));
    assert_non_null(strstr(stp_spipanel_error(p), "): Input/output error"));
    assert_int_equal(sim->refreshes, 0); /* no refresh of a half-written RAM */
    stp_spipanel_close(p);
    spi_sim_free(sim);
}

static void test_busy_timeout_refresh(void **state)
{
    spi_sim *sim = spi_sim_new(SPI_SIM_SSD1680, 122, 250, 0);
    stp_spipanel_options o;
    stp_spipanel *p;
    uint8_t rows[250 * 16];
    stp_port *port;
    gint64 t0;
    (void)state;
    memset(rows, 0xF0, sizeof rows);
    stp_spipanel_options_default(&o);
    o.busy_timeout_ms = 50;
    p = open_panel(sim, &stp_panel_ssd1680, 0, &o);
    sim->stuck_busy_after = 0x20;
    port = stp_spipanel_port(p);
    t0 = g_get_monotonic_time();
    assert_int_equal(port->flush(port, 0, 250, rows, 16), -1);
    assert_true(g_get_monotonic_time() - t0 >= 50000);
    assert_string_equal(stp_spipanel_error(p), "SSD1680 on /dev/spidev0.0: refresh: panel still "
                                               "busy after 50 ms (after command 0x20)");
    assert_int_equal(sim->refreshes, 1);
    stp_spipanel_close(p); /* waits for BUSY before deep sleep, gives up: sends nothing */
    assert_int_equal(sim->epd.deep_sleep, 0);
    assert_clean(sim);
    spi_sim_free(sim);
}

static void test_busy_timeout_init(void **state)
{
    spi_sim *sim = spi_sim_new(SPI_SIM_SSD1680, 122, 250, 0);
    stp_spipanel_options o;
    stp_spipanel_lines lines;
    char err[256];
    (void)state;
    sim->stuck_busy_after = 0x12;
    stp_spipanel_options_default(&o);
    o.busy_timeout_ms = 30;
    spi_sim_lines(sim, 0, &lines);
    assert_null(
        stp_spipanel_open("/dev/spidev0.0", &stp_panel_ssd1680, &lines, &o, err, sizeof err));
    assert_string_equal(err, "SSD1680 on /dev/spidev0.0: init: panel still busy after 30 ms "
                             "(after command 0x12)");
    assert_clean(sim); /* it waited: nothing was sent while BUSY */
    spi_sim_free(sim);
}

/* ---------------------------------------------------------------- devices */

static void test_device_sharp(void **state)
{
    spi_sim *sim = spi_sim_new(SPI_SIM_SHARP, 128, 128, 0);
    stp_device *d;
    stp_port *port;
    stp_scene scene;
    stp_posix_frame want;
    stp_tool_options to;
    char err[512];
    (void)state;
    d = stp_device_open("spi:/dev/spidev0.0,controller=sharp-ls013b7dh03,speed=500000", NULL, err,
                        sizeof err);
    if (!d)
        fail_msg("%s", err);
    port = stp_device_port(d);
    assert_int_equal(port->width, 128);
    assert_int_equal(port->height, 128);
    assert_int_equal(port->format, STP_PIXEL_MONO1);
    assert_string_equal(stp_device_describe(d), "LS013B7DH03 128x128 MONO1 on /dev/spidev0.0");
    stp_test_load_scene("balls-s1.nff", &scene);
    spi_expected_render(&scene, 128, 128, &want);
    tool_options(&to, 128, 128, 16);
    spi_sim_scramble(sim, 99);
    if (stp_tool_render(&scene, &to, port, NULL, err, sizeof err) != 0)
        fail_msg("%s (%s)", err, stp_device_error(d));
    spi_assert_glass(sim, &want, "device-sharp-balls");
    assert_int_equal(stp_device_finish(d, err, sizeof err), 0);
    assert_int_equal(stp_device_tick(d, err, sizeof err), 0);
    assert_int_equal(sim->speed_max, 500000);
    assert_string_equal(stp_device_error(d), "");
    stp_device_close(d);
    assert_clean(sim);
    stp_posix_frame_free(&want);
    stp_scene_free(&scene);
    spi_sim_free(sim);
}

static void test_device_size_mismatch(void **state)
{
    spi_sim *sim = spi_sim_new(SPI_SIM_SHARP, 128, 128, 0);
    stp_device_options o;
    char err[512];
    (void)state;
    stp_device_options_default(&o);
    o.width = 128;
    o.height = 64;
    assert_null(stp_device_open("spi:/dev/spidev0.0,controller=sharp-ls013b7dh03", &o, err,
                                sizeof err));
    assert_string_equal(err, "device spec 'spi:/dev/spidev0.0,controller=sharp-ls013b7dh03': the "
                             "LS013B7DH03 panel is 128x128, not 128x64");
    o.height = 0;
    o.format = STP_PIXEL_GREY8;
    assert_null(stp_device_open("spi:/dev/spidev0.0,controller=sharp-ls013b7dh03", &o, err,
                                sizeof err));
    assert_string_equal(err, "device spec 'spi:/dev/spidev0.0,controller=sharp-ls013b7dh03': SPI "
                             "panels take MONO1 pictures, not GREY8");
    assert_int_equal(sim->messages, 0);
    spi_sim_free(sim);
}

static void test_device_bad_specs(void **state)
{
    static const struct {
        const char *spec, *message;
    } cases[] = {
        {"", "device spec is empty (fb:/dev/fbN, usb:VID:PID, usb:class, "
             "spi:/dev/spidevB.C,controller=NAME,...)"},
        {"lpt:/dev/lp0", "device spec 'lpt:/dev/lp0': unknown device kind 'lpt' (fb, usb, spi)"},
        {"fb", "device spec 'fb': fb needs a device path, e.g. fb:/dev/fb0"},
        {"fb:/dev/fb0,format=cmyk",
         "device spec 'fb:/dev/fb0,format=cmyk': format 'cmyk' is not mono1, grey8 or rgb888"},
        {"fb:/dev/fb0,depth=8",
         "device spec 'fb:/dev/fb0,depth=8': unknown option 'depth' for fb devices (format)"},
        {"usb:04g6:5011", "device spec 'usb:04g6:5011': vendor id '04g6' is not 1..4 hex digits"},
        {"usb:0416:50111",
         "device spec 'usb:0416:50111': product id '50111' is not 1..4 hex digits"},
        {"usb:0416", "device spec 'usb:0416': '0416' is not VID:PID (hex) or 'class'"},
        {"usb:class,width=wide",
         "device spec 'usb:class,width=wide': width 'wide' is not a number of dots (8..32767)"},
        {"usb:class,cut=maybe", "device spec 'usb:class,cut=maybe': cut 'maybe' is not 0 or 1"},
        {"usb:class,,cut",
         "device spec 'usb:class,,cut': empty option (two commas, or a comma at the end)"},
        {"spi:/dev/spidev0.0",
         "device spec 'spi:/dev/spidev0.0': no controller=NAME (ssd1306, sharp-ls013b7dh03, "
         "ssd1680, ssd1680-128x296)"},
        {"spi:/dev/spidev0.0,controller=st7789",
         "device spec 'spi:/dev/spidev0.0,controller=st7789': unknown controller 'st7789' "
         "(ssd1306, sharp-ls013b7dh03, ssd1680, ssd1680-128x296)"},
        {"spi:/dev/spidev0.0,controller=ssd1306,speed=fast",
         "device spec 'spi:/dev/spidev0.0,controller=ssd1306,speed=fast': speed 'fast' is not a "
         "number of hertz (1..100000000)"},
        {"spi:/dev/spidev0.0,controller=ssd1306,dc",
         "device spec 'spi:/dev/spidev0.0,controller=ssd1306,dc': option 'dc' needs a value "
         "(dc=...)"},
        {"spi:/dev/spidev0.0,controller=ssd1306,dc=GPIO25,dc=GPIO24",
         "device spec 'spi:/dev/spidev0.0,controller=ssd1306,dc=GPIO25,dc=GPIO24': option 'dc' "
         "given twice"},
        {"spi:/dev/spidev0.0,controller=ssd1306,cs=GPIO8",
         "device spec 'spi:/dev/spidev0.0,controller=ssd1306,cs=GPIO8': unknown option 'cs' for "
         "spi devices (controller, dc, reset, busy, vcom, enable, speed, timeout)"},
        {"spi:spidev0.0,controller=ssd1306",
         "device spec 'spi:spidev0.0,controller=ssd1306': spi needs a spidev path, e.g. "
         "spi:/dev/spidev0.0,controller=ssd1306"},
        {"spi:/dev/spidev0.0,controller=ssd1306",
         "spi /dev/spidev0.0: controller SSD1306 needs a D/C line (dc=LINE)"},
    };
    size_t i;
    (void)state;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char err[512];
        stp_device *d = stp_device_open(cases[i].spec, NULL, err, sizeof err);
        if (d) {
            stp_device_close(d);
            fail_msg("'%s' opened", cases[i].spec);
        }
        if (strcmp(err, cases[i].message) != 0)
            fail_msg("'%s':\n  got      %s\n  expected %s", cases[i].spec, err, cases[i].message);
    }
}

/* Errors from the ports behind a well-formed spec. */
static void test_device_open_errors(void **state)
{
    spi_sim *sim = spi_sim_new(SPI_SIM_SSD1306, 128, 64, 0);
    char err[512];
    (void)state;
    assert_null(stp_device_open("fb:/dev/fb9", NULL, err, sizeof err));
    assert_non_null(strstr(err, "/dev/fb9"));
    assert_null(stp_device_open("spi:/dev/spidev3.1,controller=sharp-ls013b7dh03", NULL, err,
                                sizeof err));
    assert_string_equal(err, "spi /dev/spidev3.1: cannot open: No such file or directory "
                             "(is SPI enabled? Raspberry Pi: dtparam=spi=on)");
#ifdef STP_SPIPANEL_WITH_GPIO
    /* the testbed has no GPIO chip: the libgpiod path names the line */
    assert_null(stp_device_open("spi:/dev/spidev0.0,controller=ssd1306,dc=NO_SUCH_LINE", NULL, err,
                                sizeof err));
    assert_string_equal(err, "dc line 'NO_SUCH_LINE' not found on any GPIO chip");
#endif
    assert_int_equal(sim->messages, 0);
    spi_sim_free(sim);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_ssd1306_scene),
        cmocka_unit_test(test_ssd1306_small_bufsiz),
        cmocka_unit_test(test_sharp_scene_software_vcom),
        cmocka_unit_test(test_sharp_extcomin_small_bufsiz),
        cmocka_unit_test(test_ssd1680_scene),
        cmocka_unit_test(test_ssd1680_296),
        cmocka_unit_test(test_open_failure),
        cmocka_unit_test(test_missing_lines),
        cmocka_unit_test(test_eio_mid_frame),
        cmocka_unit_test(test_eio_ssd1680_ram),
        cmocka_unit_test(test_busy_timeout_refresh),
        cmocka_unit_test(test_busy_timeout_init),
        cmocka_unit_test(test_device_sharp),
        cmocka_unit_test(test_device_size_mismatch),
        cmocka_unit_test(test_device_bad_specs),
        cmocka_unit_test(test_device_open_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
