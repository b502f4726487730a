/* SPDX-License-Identifier: MIT */
/*
 * An emulated USB ESC/POS receipt printer for umockdev: the sysfs entries of
 * a printer-class device and a usbfs ioctl handler that behaves as the
 * kernel and the printer would.  The real libusb-1.0 talks to it through
 * umockdev's preload library (run the test under umockdev-wrapper).
 *
 * What it does (Linux usbfs semantics):
 *  - GETDRIVER names "usblp" while that driver is bound to interface 0;
 *    USBDEVFS_IOCTL(DISCONNECT / CONNECT) unbinds / binds it;
 *    CLAIMINTERFACE fails with EBUSY while usblp is bound.
 *  - Control URBs: GET_PORT_STATUS (0xA1, 1, wIndex 0, wLength >= 1) returns
 *    the status byte; any other request stalls (-EPIPE), as printers do.
 *  - Bulk OUT URBs on endpoint 0x01 are accepted and their bytes appended to
 *    the received job; completions are handed out by REAPURB(NDELAY).
 *  - Faults, armed once the job holds at least fault_at bytes: STALL (the
 *    URB ends -EPIPE, and so does every later one until CLEAR_HALT), HANG
 *    (the URB never completes until DISCARDURB, which ends it -ENOENT),
 *    UNPLUG (the URB in flight completes -ESHUTDOWN first, then every ioctl
 *    fails ENODEV, as usbfs does after a disconnect).
 *  - Every ioctl is logged as one text line ("CLAIM 0", "BULK 64", ...).
 */
#ifndef PRINTER_SIM_H
#define PRINTER_SIM_H

#include <glib.h>
#include <umockdev.h>

typedef enum { SIM_FAULT_NONE, SIM_FAULT_STALL, SIM_FAULT_HANG, SIM_FAULT_UNPLUG } sim_fault;

typedef struct printer_sim {
    UMockdevTestbed *testbed;
    UMockdevIoctlBase *handler;
    GMutex lock;
    /* device state */
    int usblp_bound;
    int claimed;
    int halted;
    int unplugged;
    unsigned char status;   /* port status byte */
    sim_fault fault;
    gsize fault_at;
    /* what libusb did */
    GByteArray *job;        /* bulk OUT bytes accepted, in order */
    GPtrArray *log;         /* one string per ioctl */
    guint max_bulk;         /* largest bulk OUT URB */
    guint unknown;          /* ioctls the simulation does not know */
    /* URBs */
    GQueue done;            /* completed, waiting to be reaped */
    GList *flying;          /* submitted, not completed (HANG) */
} printer_sim;

#define SIM_VID 0x0416
#define SIM_PID 0x5011

printer_sim *printer_sim_new(void);
void printer_sim_free(printer_sim *sim);
/* 1 if some log line equals line. */
int printer_sim_logged(printer_sim *sim, const char *line);
/* The log as one string, lines joined by "; " (g_free it). */
char *printer_sim_log_text(printer_sim *sim);

#endif
