/* SPDX-License-Identifier: MIT */
/*
 * USB ESC/POS printer port (see stp_usbprint.h).
 */
#include "stp_usbprint.h"
#include "stp_error.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <libusb.h>

struct stp_usbprint {
    stp_port port;
    stp_usbprint_options opt;
    libusb_context *ctx;
    libusb_device_handle *handle;
    int iface;
    unsigned char ep_out;
    int detached;          /* usblp was detached by us */
    int released;          /* the device has been given up after an error */
    uint8_t *buf;          /* one raster command */
    size_t buf_size;
    char error[256];
};

void stp_usbprint_options_default(stp_usbprint_options *opt)
{
    memset(opt, 0, sizeof *opt);
    opt->width = 384;
    opt->height = 384;
    opt->chunk_size = 4096;
    opt->timeout_ms = 5000;
    opt->check_status = 1;
    opt->feed_lines = 4;
    opt->cut = 0;
}

/* Gives the device up: release, reattach usblp, close.  Keeps the context
 * so that messages and later calls stay valid. */
static void release_device(stp_usbprint *p)
{
    if (!p->handle)
        return;
    (void)libusb_release_interface(p->handle, p->iface);
    if (p->detached)
        (void)libusb_attach_kernel_driver(p->handle, p->iface);
    p->detached = 0;
    libusb_close(p->handle);
    p->handle = NULL;
}

/* Records the first error, releases the device, copies the message out. */
static int fail_job(stp_usbprint *p, char *err, size_t errlen, const char *fmt, ...)
{
    va_list ap;
    if (!p->released) {
        va_start(ap, fmt);
        stp_error_vset(p->error, sizeof p->error, NULL, fmt, ap);
        va_end(ap);
        p->released = 1;
        release_device(p);
    }
    stp_error_set(err, errlen, "%s", p->error);
    return -1;
}

static int usable(stp_usbprint *p, char *err, size_t errlen)
{
    if (p->released || !p->handle) {
        stp_error_set(err, errlen, "printer released: %s", p->error[0] ? p->error : "closed");
        return 0;
    }
    return 1;
}

/* Sends len bytes in chunks; on failure releases the device. */
static int send_bytes(stp_usbprint *p, const uint8_t *data, size_t len, char *err, size_t errlen)
{
    size_t sent = 0;
    while (sent < len) {
        size_t n = len - sent;
        int done = 0, rc;
        if (n > p->opt.chunk_size)
            n = p->opt.chunk_size;
        rc = libusb_bulk_transfer(p->handle, p->ep_out, (unsigned char *)(uintptr_t)(data + sent),
                                  (int)n, &done, p->opt.timeout_ms);
        if (done > 0)
            sent += (size_t)done;
        if (rc == 0 && (size_t)done == n)
            continue;
        switch (rc) {
        case LIBUSB_ERROR_PIPE:
            (void)libusb_clear_halt(p->handle, p->ep_out);
            return fail_job(p, err, errlen,
                            "printer stalled bulk OUT endpoint 0x%02x after %lu of %lu bytes "
                            "(halt cleared, job aborted)",
                            p->ep_out, (unsigned long)sent, (unsigned long)len);
        case LIBUSB_ERROR_TIMEOUT:
            return fail_job(p, err, errlen,
                            "printer accepted no data for %u ms (timed out after %lu of %lu "
                            "bytes, job aborted)",
                            p->opt.timeout_ms, (unsigned long)sent, (unsigned long)len);
        case LIBUSB_ERROR_NO_DEVICE:
            return fail_job(p, err, errlen,
                            "printer unplugged during the job (%lu of %lu bytes sent)",
                            (unsigned long)sent, (unsigned long)len);
        case 0:
            return fail_job(p, err, errlen, "short bulk transfer: %d of %lu bytes (%lu of %lu sent)",
                            done, (unsigned long)n, (unsigned long)sent, (unsigned long)len);
        default:
            return fail_job(p, err, errlen, "bulk transfer failed: %s (%lu of %lu bytes sent)",
                            libusb_strerror(rc), (unsigned long)sent, (unsigned long)len);
        }
    }
    return 0;
}

/* Does this interface look like a printer we can drive?  Sets ep_out. */
static int pick_interface(const struct libusb_config_descriptor *cfg, int want_class,
                          int *iface, unsigned char *ep)
{
    int i, a, e;
    for (i = 0; i < cfg->bNumInterfaces; i++) {
        const struct libusb_interface *it = &cfg->interface[i];
        for (a = 0; a < it->num_altsetting; a++) {
            const struct libusb_interface_descriptor *d = &it->altsetting[a];
            if (want_class && d->bInterfaceClass != LIBUSB_CLASS_PRINTER)
                continue;
            for (e = 0; e < d->bNumEndpoints; e++) {
                const struct libusb_endpoint_descriptor *ed = &d->endpoint[e];
                if ((ed->bmAttributes & 3) == LIBUSB_TRANSFER_TYPE_BULK &&
                    (ed->bEndpointAddress & LIBUSB_ENDPOINT_IN) == 0) {
                    *iface = d->bInterfaceNumber;
                    *ep = ed->bEndpointAddress;
                    return 1;
                }
            }
        }
    }
    return 0;
}

static int port_flush(stp_port *port, uint32_t y0, uint32_t rows, const uint8_t *pixels,
                      size_t stride);

stp_usbprint *stp_usbprint_open(const stp_usbprint_options *opt_in, char *err, size_t errlen)
{
    stp_usbprint_options opt;
    stp_usbprint *p;
    libusb_device **list = NULL;
    libusb_device *found = NULL;
    ssize_t n, i;
    int rc, by_id;

    if (opt_in)
        opt = *opt_in;
    else
        stp_usbprint_options_default(&opt);
    if (opt.width == 0 || opt.height == 0 || opt.width > 32767 || opt.height > 32767 ||
        (opt.width + 7) / 8 > 65535u || opt.chunk_size == 0 || opt.chunk_size > (1u << 20)) {
        stp_error_set(err, errlen, "usb printer: bad options (size %ux%u, chunk %lu)",
                (unsigned)opt.width, (unsigned)opt.height, (unsigned long)opt.chunk_size);
        return NULL;
    }
    p = calloc(1, sizeof *p);
    if (!p) {
        stp_error_set(err, errlen, "usb printer: out of memory");
        return NULL;
    }
    p->opt = opt;
    p->iface = -1;
    rc = libusb_init(&p->ctx);
    if (rc != 0) {
        stp_error_set(err, errlen, "usb printer: libusb_init: %s", libusb_strerror(rc));
        free(p);
        return NULL;
    }
    n = libusb_get_device_list(p->ctx, &list);
    if (n < 0) {
        stp_error_set(err, errlen, "usb printer: cannot list USB devices: %s", libusb_strerror((int)n));
        goto fail;
    }
    by_id = opt.vendor_id != 0 || opt.product_id != 0;
    for (i = 0; i < n && !found; i++) {
        struct libusb_device_descriptor dd;
        struct libusb_config_descriptor *cfg;
        if (libusb_get_device_descriptor(list[i], &dd) != 0)
            continue;
        if (by_id && (dd.idVendor != opt.vendor_id || dd.idProduct != opt.product_id))
            continue;
        if (libusb_get_active_config_descriptor(list[i], &cfg) != 0 &&
            libusb_get_config_descriptor(list[i], 0, &cfg) != 0)
            continue;
        if (pick_interface(cfg, !by_id, &p->iface, &p->ep_out))
            found = list[i];
        libusb_free_config_descriptor(cfg);
        if (by_id && !found) {
            stp_error_set(err, errlen, "usb printer %04x:%04x has no bulk OUT endpoint",
                    opt.vendor_id, opt.product_id);
            goto fail;
        }
    }
    if (!found) {
        if (by_id)
            stp_error_set(err, errlen, "usb printer %04x:%04x not found", opt.vendor_id, opt.product_id);
        else
            stp_error_set(err, errlen, "no USB printer (class 7 with a bulk OUT endpoint) found");
        goto fail;
    }
    rc = libusb_open(found, &p->handle);
    if (rc != 0) {
        stp_error_set(err, errlen, "usb printer %03u/%03u: cannot open: %s%s",
                libusb_get_bus_number(found), libusb_get_device_address(found),
                libusb_strerror(rc),
                rc == LIBUSB_ERROR_ACCESS ? " (needs a udev rule giving you the device)" : "");
        p->handle = NULL;
        goto fail;
    }
    rc = libusb_kernel_driver_active(p->handle, p->iface);
    if (rc == 1) {
        rc = libusb_detach_kernel_driver(p->handle, p->iface);
        if (rc != 0) {
            stp_error_set(err, errlen, "usb printer: cannot detach the kernel driver (usblp) from "
                    "interface %d: %s", p->iface, libusb_strerror(rc));
            goto fail;
        }
        p->detached = 1;
    }
    rc = libusb_claim_interface(p->handle, p->iface);
    if (rc != 0) {
        stp_error_set(err, errlen, "usb printer: cannot claim interface %d: %s%s", p->iface,
                libusb_strerror(rc), rc == LIBUSB_ERROR_BUSY ? " (in use by another program?)" : "");
        goto fail;
    }
    libusb_free_device_list(list, 1);
    p->buf_size = 8u + (size_t)((opt.width + 7u) / 8u) * 255u;
    p->buf = malloc(p->buf_size);
    if (!p->buf) {
        stp_error_set(err, errlen, "usb printer: out of memory");
        stp_usbprint_close(p);
        return NULL;
    }
    p->port.width = opt.width;
    p->port.height = opt.height;
    p->port.format = STP_PIXEL_MONO1;
    p->port.flush = port_flush;
    p->port.user = p;
    return p;

fail:
    if (list)
        libusb_free_device_list(list, 1);
    stp_usbprint_close(p);
    return NULL;
}

int stp_usbprint_status(stp_usbprint *p, uint8_t *status, char *err, size_t errlen)
{
    unsigned char b = 0;
    int rc;
    if (!p || !usable(p, err, errlen))
        return -1;
    rc = libusb_control_transfer(p->handle,
                                 LIBUSB_ENDPOINT_IN | LIBUSB_REQUEST_TYPE_CLASS |
                                     LIBUSB_RECIPIENT_INTERFACE,
                                 1 /* GET_PORT_STATUS */, 0, (uint16_t)p->iface, &b, 1,
                                 p->opt.timeout_ms);
    if (rc == 1) {
        *status = b;
        return 0;
    }
    if (rc == LIBUSB_ERROR_NO_DEVICE)
        return fail_job(p, err, errlen, "printer unplugged (reading its port status)");
    if (rc == LIBUSB_ERROR_PIPE)
        stp_error_set(err, errlen, "printer refused GET_PORT_STATUS (stall)");
    else if (rc >= 0)
        stp_error_set(err, errlen, "printer answered GET_PORT_STATUS with %d bytes", rc);
    else
        stp_error_set(err, errlen, "reading the printer's port status failed: %s", libusb_strerror(rc));
    return -1;
}

int stp_usbprint_begin(stp_usbprint *p, char *err, size_t errlen)
{
    static const uint8_t init[2] = {0x1B, 0x40};
    if (!p || !usable(p, err, errlen))
        return -1;
    if (p->opt.check_status) {
        uint8_t st = 0;
        if (stp_usbprint_status(p, &st, err, errlen) != 0)
            return -1;
        if (st & STP_USBPRINT_PAPER_EMPTY) {
            stp_error_set(err, errlen, "printer reports paper out (port status 0x%02x); nothing sent", st);
            return -1;
        }
        if (!(st & STP_USBPRINT_NOT_ERROR)) {
            stp_error_set(err, errlen, "printer reports an error (port status 0x%02x%s); nothing sent", st,
                    (st & STP_USBPRINT_SELECTED) ? "" : ", offline");
            return -1;
        }
    }
    return send_bytes(p, init, sizeof init, err, errlen);
}

static int port_flush(stp_port *port, uint32_t y0, uint32_t rows, const uint8_t *pixels,
                      size_t stride)
{
    stp_usbprint *p = port->user;
    size_t rb = (port->width + 7u) / 8u;
    uint8_t last_mask = (uint8_t)(0xFFu << ((8u - port->width % 8u) % 8u));
    uint32_t done = 0;
    if (!p || !pixels || y0 > port->height || rows > port->height - y0 ||
        (rows > 1 && stride < rb))
        return -1;
    if (!usable(p, NULL, 0))
        return -1;
    while (done < rows) {
        uint32_t n = rows - done > 255u ? 255u : rows - done, r;
        size_t i, len = 8u + rb * n;
        uint8_t *d = p->buf + 8;
        p->buf[0] = 0x1D;
        p->buf[1] = 0x76;
        p->buf[2] = 0x30;
        p->buf[3] = 0x00;
        p->buf[4] = (uint8_t)(rb & 0xFFu);
        p->buf[5] = (uint8_t)(rb >> 8);
        p->buf[6] = (uint8_t)(n & 0xFFu);
        p->buf[7] = (uint8_t)(n >> 8);
        for (r = 0; r < n; r++) {
            const uint8_t *s = pixels + (size_t)(done + r) * stride;
            for (i = 0; i < rb; i++)
                d[i] = (uint8_t)~s[i]; /* ON (light) -> no dot */
            d[rb - 1] &= last_mask;
            d += rb;
        }
        if (send_bytes(p, p->buf, len, NULL, 0) != 0)
            return -1;
        done += n;
    }
    return 0;
}

stp_port *stp_usbprint_port(stp_usbprint *p)
{
    return p ? &p->port : NULL;
}

int stp_usbprint_end(stp_usbprint *p, char *err, size_t errlen)
{
    uint8_t tail[6];
    size_t n = 0;
    if (!p || !usable(p, err, errlen))
        return -1;
    tail[n++] = 0x1B;
    tail[n++] = 0x64;
    tail[n++] = (uint8_t)(p->opt.feed_lines > 255 ? 255 : p->opt.feed_lines);
    if (p->opt.cut) {
        tail[n++] = 0x1D;
        tail[n++] = 0x56;
        tail[n++] = 0x01;
    }
    return send_bytes(p, tail, n, err, errlen);
}

const char *stp_usbprint_error(const stp_usbprint *p)
{
    return p ? p->error : "";
}

void stp_usbprint_close(stp_usbprint *p)
{
    if (!p)
        return;
    release_device(p);
    if (p->ctx)
        libusb_exit(p->ctx);
    free(p->buf);
    free(p);
}
