/* SPDX-License-Identifier: MIT */
/*
 * SPI panels with no kernel driver: the display controllers described as
 * data in ports/controllers (stp_panel.h) driven through the spidev
 * character device /dev/spidevB.C, with the panel's control lines (reset,
 * D/C, BUSY, VCOM) reached through a small interface, stp_spipanel_lines.
 * Its real implementation is stp_gpio_panel (libgpiod v2, stp_gpio.h):
 * stp_spipanel_lines_from_gpio; tests plug in an emulated panel's pins.
 *
 * Controllers (stp_spipanel_find_controller names; each controller file in
 * ports/controllers gives the datasheet facts):
 *   "ssd1306"            128x64 mono OLED, 4-wire SPI with D/C; RESET optional
 *   "sharp-ls013b7dh03"  128x128 Sharp memory LCD, no D/C, chip select active
 *                        high; VCOM through EXTCOMIN if a vcom line is given,
 *                        else through the M1 bit of each command
 *   "ssd1680"            122x250 (2.13") e-paper, D/C and BUSY required,
 *                        RESET recommended
 *   "ssd1680-128x296"    the same controller on 128x296 (2.9") glass
 * Any stp_panel_controller with an SPI description (spi_hz set) and PAGES,
 * LINES or WINDOW_COUNTERS addressing works; SSD0303/SSD0323, described for
 * their firmware buses only, are refused.
 *
 * The port (stp_spipanel_port): width x height of the controller, format
 * STP_PIXEL_MONO1_PAGES for page controllers (SSD1306: the renderer writes
 * the panel's own layout), STP_PIXEL_MONO1 for the others.  Bit 1 = ON =
 * light in both.  ON becomes:
 *   SSD1306: a lit pixel (RAM bit 1, normal display mode);
 *   Sharp:   a white pixel (data bit 1 = white);
 *   SSD1680: a white pixel (B/W RAM bit 1 = white).
 * Orientation: each panel's own; no rotation, no column offset (pixel (0, 0)
 * is RAM column 0 of page 0 / gate line 1 / RAM X 0, Y 0).  Bands of any
 * height arrive top to bottom:
 *   SSD1306 (pages of 8 rows): each page of a band goes out as it is (no
 *     packing, no buffer); bands start on pages (port.h: stp_renderer_render
 *     takes whole pages), a band at another row is refused.
 *   Sharp (line records): each band's lines are written at once.
 *   SSD1680 (RAM window + refresh): the rows are gathered in a frame buffer
 *     the port allocates; after the frame's last row the whole RAM is
 *     written and the refresh runs, waiting for BUSY (seconds).
 *
 * Bus: the spidev device gets SPI_IOC_WR_MODE (the controller's mode, plus
 * SPI_CS_HIGH for Sharp), SPI_IOC_WR_BITS_PER_WORD 8 and
 * SPI_IOC_WR_MAX_SPEED_HZ; everything goes out with SPI_IOC_MESSAGE, MSB
 * first.  spidev refuses a message whose bytes add up to more than its
 * buffer (the module parameter bufsiz, /sys/module/spidev/parameters/bufsiz,
 * 4096 by default): every message here stays within it (read at open, else
 * 4096; options.max_transfer overrides).  A Sharp write must be one
 * chip-select frame, so a band is split into writes of whole lines.
 *
 * VCOM (Sharp): alternates at the start of each frame and at every
 * stp_spipanel_vcom_tick; a program that keeps a picture up should call it
 * about once a second (the panel's DC bias).
 *
 * Host code (libc, POSIX, Linux spidev ioctls; no libgpiod needed).
 * Functions that fail return NULL or -1 and write a one-line message into
 * err (errlen bytes, NUL-terminated; err may be NULL).
 */
#ifndef STP_SPIPANEL_H
#define STP_SPIPANEL_H

#include <stddef.h>
#include <stdint.h>

#include "stipple/port.h"
#include "stp_panel.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The panel's control lines.  Every member may be NULL when the line is not
 * wired; stp_spipanel_open refuses a controller that needs a missing one
 * (dc for D/C controllers, wait_ready for BUSY controllers).  Functions
 * return 0 (vcom_toggle: the new level 0/1) or -1 with a one-line message in
 * err. */
typedef struct stp_spipanel_lines {
    /* Assert RESET for assert_us microseconds, release it, wait settle_us. */
    int (*reset)(void *ctx, unsigned assert_us, unsigned settle_us, char *err, size_t errlen);
    /* D/C select: data (1) or command (0). */
    int (*dc)(void *ctx, int data, char *err, size_t errlen);
    /* Wait until BUSY is released, at most timeout_ms milliseconds; on
     * timeout -1 with "panel still busy after N ms". */
    int (*wait_ready)(void *ctx, unsigned timeout_ms, char *err, size_t errlen);
    /* Flip VCOM (Sharp EXTCOMIN) once. */
    int (*vcom_toggle)(void *ctx, char *err, size_t errlen);
    /* Sleep us microseconds (NULL: nanosleep). */
    void (*delay_us)(void *ctx, unsigned us);
    void *ctx;
} stp_spipanel_lines;

typedef struct stp_spipanel_options {
    uint32_t speed_hz;        /* SCLK in hertz, 1..100000000 (0: the controller's) */
    size_t max_transfer;      /* bytes per SPI message (0: spidev's bufsiz, else 4096) */
    unsigned busy_timeout_ms; /* every BUSY wait (0: the controller's own, e.g.
                                 15000 for an SSD1680 refresh) */
} stp_spipanel_options;

typedef struct stp_spipanel stp_spipanel;

void stp_spipanel_options_default(stp_spipanel_options *opt);

/* The controller a name stands for (the list above; case matters), or NULL. */
const stp_panel_controller *stp_spipanel_find_controller(const char *name);

/* The names stp_spipanel_find_controller knows, comma-separated, for
 * messages. */
const char *stp_spipanel_controller_names(void);

/* Opens path (e.g. "/dev/spidev0.0"), sets the bus up and runs the
 * controller's init sequence (reset pulse, BUSY waits).  lines is copied
 * (NULL: no lines); opt NULL = defaults.  Errors: the device cannot be
 * opened or configured, a needed line is missing, a transfer fails, the
 * panel stays busy. */
stp_spipanel *stp_spipanel_open(const char *path, const stp_panel_controller *controller,
                                const stp_spipanel_lines *lines, const stp_spipanel_options *opt,
                                char *err, size_t errlen);

/* The MONO1 port to hand to the renderer (valid until close).  Its flush
 * returns -1 for a band outside the panel, a stride below the packed row
 * size, a transfer error or a BUSY timeout; stp_spipanel_error then says
 * why. */
stp_port *stp_spipanel_port(stp_spipanel *p);

/* Why the last flush failed ("" if none). */
const char *stp_spipanel_error(const stp_spipanel *p);

/* Bytes per SPI message in use (spidev's limit). */
size_t stp_spipanel_max_transfer(const stp_spipanel *p);

/* Sharp: flip VCOM once (EXTCOMIN, else a VCOM-only command with the M1
 * bit); other controllers: nothing.  Returns 0 or -1. */
int stp_spipanel_vcom_tick(stp_spipanel *p, char *err, size_t errlen);

/* Runs the controller's sleep sequence (SSD1680 deep sleep, only when a
 * reset line can wake it again), closes the device.  p may be NULL.  The
 * lines' owner closes them afterwards. */
void stp_spipanel_close(stp_spipanel *p);

#ifdef STP_SPIPANEL_WITH_GPIO
#include "stp_gpio.h"
/* Fills lines with stp_gpio_panel's functions for the lines cfg names
 * (NULL for the others).  g must stay open while the panel is.  Built only
 * with libgpiod (CMake target stipple_gpio; then STP_SPIPANEL_WITH_GPIO is
 * defined for users of stipple_spipanel). */
void stp_spipanel_lines_from_gpio(stp_gpio_panel *g, const stp_gpio_panel_config *cfg,
                                  stp_spipanel_lines *lines);
#endif

#ifdef __cplusplus
}
#endif

#endif
