/* SPDX-License-Identifier: MIT */
/*
 * One output device from one string: the Linux ports (fbdev, USB receipt
 * printer, SPI panel) behind a device spec, for the stipple command's
 * --device option and for programs.
 *
 * Specs (keys after the target, comma-separated, each at most once):
 *   fb:/dev/fbN[,format=mono1|grey8|rgb888]
 *       stp_linuxfb.  Port: the visible area (or options.width x height, at
 *       most that), MONO1 on 1 bpp screens, GREY8 on the others (format=
 *       or options.format ask for another).
 *   usb:VID:PID[,width=DOTS][,height=ROWS][,feed=LINES][,cut]
 *   usb:class[,...]   or   usb[,...]
 *       stp_usbprint: the printer with that vendor and product id (1..4 hex
 *       digits each), or the first USB printer-class device.  Port: MONO1,
 *       width dots across (384: 58 mm paper; 576 for 80 mm) x height rows
 *       (384); the job begins at open (paper-out refused) and ends with
 *       stp_device_finish (feed, cut).
 *   spi:/dev/spidevB.C,controller=NAME[,dc=LINE][,reset=LINE][,busy=LINE]
 *       [,vcom=LINE][,enable=LINE][,speed=HZ][,timeout=MS]
 *       stp_spipanel; NAME: ssd1306, sharp-ls013b7dh03, ssd1680,
 *       ssd1680-128x296.  LINE as in stp_gpio.h ("[!]CHIP:LINE" or
 *       "[!]LINE": "GPIO25", "gpiochip0:24", "!GPIO24"); enable is asserted
 *       while the device is open (Sharp DISP, a panel power switch); vcom
 *       drives Sharp EXTCOMIN (without it VCOM goes through the M1 bit).
 *       speed: SCLK in hertz (the controller's default otherwise); timeout:
 *       every BUSY wait in ms (the controller's own otherwise).  Port: the
 *       panel's size, MONO1.
 * Keys spec and options both set: the spec wins.
 *
 * Use (the caller owns nothing but the handle):
 *     char err[256];
 *     stp_device *d = stp_device_open(spec, NULL, err, sizeof err);
 *     if (!d) { fprintf(stderr, "%s\n", err); ... }
 *     stp_port *port = stp_device_port(d);
 *     render at port->width x port->height into port (its format is what
 *     the port wants: MONO1, GREY8 or RGB888; the core halftones MONO1);
 *     if the render fails, stp_device_error(d) says what the device saw;
 *     stp_device_finish(d, err, sizeof err);   (USB feed/cut; else nothing)
 *     stp_device_close(d);
 *
 * Built pieces: fb and spi always (Linux headers); usb only with libusb-1.0
 * and spi control lines only with libgpiod >= 2; without them those specs
 * fail with "built without ...".
 *
 * Host code.  Functions that fail return NULL or -1 and write a one-line
 * message into err (errlen bytes, NUL-terminated; err may be NULL); a bad
 * spec's message quotes the spec and names the offending part.
 */
#ifndef STP_DEVICE_H
#define STP_DEVICE_H

#include <stddef.h>
#include <stdint.h>

#include "stipple/port.h"

#ifdef __cplusplus
extern "C" {
#endif

#define STP_DEVICE_FORMAT_AUTO (-1)

typedef struct stp_device_options {
    uint32_t width, height; /* pixels, 0: the device's own (see above); an SPI
                               panel refuses any other size than its own */
    int format;             /* STP_DEVICE_FORMAT_AUTO or an stp_pixel_format:
                               fb takes MONO1, GREY8, RGB888; usb and spi
                               MONO1 only */
} stp_device_options;

typedef struct stp_device stp_device;

void stp_device_options_default(stp_device_options *opt);

/* Parses spec, opens the device and sets up its port; opt NULL = defaults.
 * Errors: a bad spec, a kind this build lacks, the device's own open error
 * (not found, permission, printer out of paper, panel busy, ...). */
stp_device *stp_device_open(const char *spec, const stp_device_options *opt, char *err,
                            size_t errlen);

/* The port to render into (valid until close): width, height, format. */
stp_port *stp_device_port(stp_device *d);

/* What was opened, for messages: "SSD1306 128x64 MONO1_PAGES on /dev/spidev0.0". */
const char *stp_device_describe(const stp_device *d);

/* Why the port's flush failed during a render ("" if it did not). */
const char *stp_device_error(const stp_device *d);

/* Ends the picture: USB printers feed (and cut); others nothing.  Call it
 * after a successful render; once.  Returns 0 or -1. */
int stp_device_finish(stp_device *d, char *err, size_t errlen);

/* Keeps a picture alive: a Sharp memory LCD flips VCOM (call about once a
 * second while the picture stays up); others nothing.  Returns 0 or -1. */
int stp_device_tick(stp_device *d, char *err, size_t errlen);

/* Releases the device (an SSD1680 goes to deep sleep when a reset line can
 * wake it; a USB printer is given back to usblp).  d may be NULL. */
void stp_device_close(stp_device *d);

#ifdef __cplusplus
}
#endif

#endif
