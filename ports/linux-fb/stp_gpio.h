/* SPDX-License-Identifier: MIT */
/*
 * Panel control lines through the GPIO character device (libgpiod v2).
 *
 * Lines are named in a configuration, never hard-coded:
 *     "[!]CHIP:LINE" or "[!]LINE"
 * CHIP is "gpiochipN", a path ("/dev/gpiochipN") or a chip label
 * ("pinctrl-bcm2835", "gpio-sim.0-node0"); LINE a line name ("GPIO25",
 * "RST") or an offset ("25").  Without CHIP every chip is searched for the
 * line name.  A leading '!' inverts the line's usual polarity.
 *
 * Polarity (what "asserted" means electrically):
 *   reset      asserted = LOW  (every supported controller resets on low)
 *   dc         data = HIGH, command = LOW (SSD1306 D/C#)
 *   busy       busy = HIGH (SSD1680 and most e-paper; '!' for UC8151-type
 *              controllers, whose BUSY# is low while busy)
 *   enable     on = HIGH;  backlight  on = HIGH
 *   vcom       Sharp memory LCD EXTCOMIN: toggled, starts LOW
 * Outputs start deasserted (reset released, panel off, backlight off,
 * D/C = command, VCOM low).
 *
 * Host code (libc, POSIX threads, libgpiod >= 2).  Functions that fail
 * return NULL or -1 and write a one-line message into err (errlen bytes;
 * err may be NULL).
 */
#ifndef STP_GPIO_H
#define STP_GPIO_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct stp_gpio_panel_config {
    const char *reset, *dc, *busy, *enable, *backlight, *vcom; /* NULL: absent */
    const char *consumer; /* label shown by gpioinfo (NULL: "stipple") */
} stp_gpio_panel_config;

typedef struct stp_gpio_panel stp_gpio_panel;

stp_gpio_panel *stp_gpio_panel_open(const stp_gpio_panel_config *cfg, char *err, size_t errlen);

/* Asserts RESET for assert_us microseconds, releases it, then waits
 * settle_us before returning (the controller's reset recovery time). */
int stp_gpio_panel_reset(stp_gpio_panel *p, unsigned assert_us, unsigned settle_us, char *err,
                         size_t errlen);

/* D/C select: data (1) or command (0). */
int stp_gpio_panel_dc(stp_gpio_panel *p, int data, char *err, size_t errlen);

/* Waits until BUSY is released, at most timeout_ms; edge events when the
 * chip has interrupts, else polling every millisecond.  Returns 0 when the
 * panel is ready, -1 with "panel still busy after N ms" on timeout. */
int stp_gpio_panel_wait_ready(stp_gpio_panel *p, unsigned timeout_ms, char *err, size_t errlen);

int stp_gpio_panel_enable(stp_gpio_panel *p, int on, char *err, size_t errlen);
int stp_gpio_panel_backlight(stp_gpio_panel *p, int on, char *err, size_t errlen);

/* Flips VCOM once; returns the new level (0/1) or -1. */
int stp_gpio_panel_vcom_toggle(stp_gpio_panel *p, char *err, size_t errlen);

/* Toggles VCOM every 1000 / (2 * hz) ms in a thread (a square wave of hz
 * hertz; Sharp memory LCDs want 0.5..60 Hz) until stop or close. */
int stp_gpio_panel_vcom_start(stp_gpio_panel *p, unsigned hz, char *err, size_t errlen);
void stp_gpio_panel_vcom_stop(stp_gpio_panel *p);

/* Stops VCOM, releases the lines (they keep their last level). */
void stp_gpio_panel_close(stp_gpio_panel *p);

#ifdef __cplusplus
}
#endif

#endif
