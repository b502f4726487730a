/* SPDX-License-Identifier: MIT */
/*
 * USB ESC/POS thermal receipt printer port, through libusb-1.0.
 *
 * The printer is found by VID:PID, or as the first interface of USB class 7
 * (printer) with a bulk OUT endpoint.  Opening detaches the kernel's usblp
 * driver from that interface (it is attached again on close) and claims it.
 *
 * A job is:   stp_usbprint_begin   reads the printer-class port status
 *                                  (GET_PORT_STATUS: bmRequestType 0xA1,
 *                                  bRequest 1, wIndex = interface) and
 *                                  refuses on paper out (bit 5 set) or error
 *                                  (bit 3, "not error", clear); then sends
 *                                  ESC @ (1B 40, initialise);
 *             the port's bands     each band of rows becomes one raster
 *                                  command GS v 0 (1D 76 30 00 xL xH yL yH
 *                                  + data), at most 255 rows per command,
 *                                  xL/xH = bytes per row = ceil(width / 8);
 *                                  data bit 1 = a printed (dark) dot, so
 *                                  stipple's MONO1 ON (light) pixels are 0;
 *                                  pad bits past the width are 0;
 *             stp_usbprint_end     ESC d n (1B 64 n, feed n lines) and, if
 *                                  asked, GS V 1 (1D 56 01, partial cut).
 * Everything goes out on the bulk OUT endpoint in transfers of at most
 * chunk_size bytes.
 *
 * Errors: a stall (the halt is cleared), a timeout, the printer unplugged,
 * or any other transfer failure ends the job with a message saying which
 * and how many bytes had gone out; the device is then released at once
 * (interface released, usblp attached again where possible, handle closed)
 * and every later call fails with "printer released: <first error>".  The
 * port's flush returns -1 in that case, so stp_renderer_render returns STP_ERR_PORT
 * and stp_usbprint_error() holds the reason.
 *
 * Host code (libc, libusb-1.0).  Functions that fail return NULL or -1 and
 * write a one-line message into err (errlen bytes, NUL-terminated; err may
 * be NULL).
 */
#ifndef STP_USBPRINT_H
#define STP_USBPRINT_H

#include <stddef.h>
#include <stdint.h>

#include "stipple/port.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct stp_usbprint_options {
    uint16_t vendor_id, product_id; /* both 0: the first printer-class device */
    uint32_t width, height;         /* dots (384: 58 mm paper, 576: 80 mm) */
    size_t chunk_size;              /* bytes per bulk transfer (4096) */
    unsigned timeout_ms;            /* per transfer (5000) */
    int check_status;               /* 1: refuse on paper out / error (1) */
    unsigned feed_lines;            /* after the picture (4) */
    int cut;                        /* 1: partial cut at the end (0) */
} stp_usbprint_options;

/* Port status bits (USB printer class 1.1, GET_PORT_STATUS). */
#define STP_USBPRINT_PAPER_EMPTY 0x20u
#define STP_USBPRINT_SELECTED 0x10u
#define STP_USBPRINT_NOT_ERROR 0x08u

typedef struct stp_usbprint stp_usbprint;

void stp_usbprint_options_default(stp_usbprint_options *opt);

/* Finds, opens and claims the printer. */
stp_usbprint *stp_usbprint_open(const stp_usbprint_options *opt, char *err, size_t errlen);

/* Reads the port status byte. */
int stp_usbprint_status(stp_usbprint *p, uint8_t *status, char *err, size_t errlen);

/* Checks the status (if asked) and sends ESC @. */
int stp_usbprint_begin(stp_usbprint *p, char *err, size_t errlen);

/* The MONO1 port (width x height) whose bands go out as GS v 0. */
stp_port *stp_usbprint_port(stp_usbprint *p);

/* Feeds (and cuts). */
int stp_usbprint_end(stp_usbprint *p, char *err, size_t errlen);

/* The first error that released the printer ("" if none). */
const char *stp_usbprint_error(const stp_usbprint *p);

/* Releases the interface, gives it back to usblp, closes.  p may be NULL. */
void stp_usbprint_close(stp_usbprint *p);

#ifdef __cplusplus
}
#endif

#endif
