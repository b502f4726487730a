/* SPDX-License-Identifier: MIT */
/* The emulated USB receipt printer (see printer_sim.h). */
#include "printer_sim.h"

#include <errno.h>
#include <stddef.h>
#include <string.h>

#include <sys/ioctl.h>
#include <linux/usbdevice_fs.h>

static void logf_locked(printer_sim *sim, const char *fmt, ...) G_GNUC_PRINTF(2, 3);
static void logf_locked(printer_sim *sim, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    g_ptr_array_add(sim->log, g_strdup_vprintf(fmt, ap));
    va_end(ap);
}

/* Marks an URB complete: it will be handed out by the next reap. */
static void finish_urb(printer_sim *sim, UMockdevIoctlData *urb_data, int status, int actual)
{
    struct usbdevfs_urb *urb = (struct usbdevfs_urb *)urb_data->data;
    urb->status = status;
    urb->actual_length = actual;
    g_queue_push_tail(&sim->done, g_object_ref(urb_data));
}

static gboolean submit_urb(printer_sim *sim, UMockdevIoctlClient *client, UMockdevIoctlData *arg)
{
    UMockdevIoctlData *urb_data, *buf;
    struct usbdevfs_urb *urb;

    urb_data = umockdev_ioctl_data_resolve(arg, 0, sizeof(struct usbdevfs_urb), NULL);
    if (!urb_data) {
        umockdev_ioctl_client_complete(client, -1, EFAULT);
        return TRUE;
    }
    urb = (struct usbdevfs_urb *)urb_data->data;
    buf = urb->buffer_length > 0
              ? umockdev_ioctl_data_resolve(urb_data, G_STRUCT_OFFSET(struct usbdevfs_urb, buffer),
                                            (gsize)urb->buffer_length, NULL)
              : NULL;
    if (urb->type == USBDEVFS_URB_TYPE_CONTROL && buf && urb->buffer_length >= 8) {
        const guint8 *s = buf->data;
        guint req_type = s[0], req = s[1];
        guint value = s[2] | (s[3] << 8), index = s[4] | (s[5] << 8), length = s[6] | (s[7] << 8);
        logf_locked(sim, "CONTROL %02x %02x %04x %04x %u", req_type, req, value, index, length);
        if (req_type == 0xA1 && req == 1 && index == 0 && length >= 1 &&
            urb->buffer_length >= 9) {
            buf->data[8] = sim->status;
            finish_urb(sim, urb_data, 0, 1);
        } else {
            finish_urb(sim, urb_data, -EPIPE, 0);
        }
        umockdev_ioctl_client_complete(client, 0, 0);
    } else if (urb->type == USBDEVFS_URB_TYPE_BULK && urb->endpoint == 0x01) {
        int armed = sim->fault != SIM_FAULT_NONE && sim->job->len >= sim->fault_at;
        logf_locked(sim, "BULK %d", urb->buffer_length);
        if ((guint)urb->buffer_length > sim->max_bulk)
            sim->max_bulk = (guint)urb->buffer_length;
        if (sim->halted || (armed && sim->fault == SIM_FAULT_STALL)) {
            sim->halted = 1;
            sim->fault = SIM_FAULT_NONE;
            finish_urb(sim, urb_data, -EPIPE, 0);
        } else if (armed && sim->fault == SIM_FAULT_HANG) {
            sim->flying = g_list_append(sim->flying, g_object_ref(urb_data));
        } else if (armed && sim->fault == SIM_FAULT_UNPLUG) {
            /* the URB in flight ends first; from then on the device is gone */
            finish_urb(sim, urb_data, -ESHUTDOWN, 0);
            sim->unplugged = 1;
            logf_locked(sim, "UNPLUGGED");
        } else {
            if (buf)
                g_byte_array_append(sim->job, buf->data, (guint)urb->buffer_length);
            finish_urb(sim, urb_data, 0, urb->buffer_length);
        }
        umockdev_ioctl_client_complete(client, 0, 0);
    } else {
        logf_locked(sim, "SUBMIT type %u ep %02x refused", urb->type, urb->endpoint);
        umockdev_ioctl_client_complete(client, -1, ENOENT);
    }
    if (buf)
        g_object_unref(buf);
    g_object_unref(urb_data);
    return TRUE;
}

static gboolean reap_urb(printer_sim *sim, UMockdevIoctlClient *client, UMockdevIoctlData *arg)
{
    UMockdevIoctlData *urb_data = g_queue_pop_head(&sim->done), *ptr;
    if (!urb_data) {
        /* after a disconnect, completed URBs are still reaped, then ENODEV */
        umockdev_ioctl_client_complete(client, -1, sim->unplugged ? ENODEV : EAGAIN);
        return TRUE;
    }
    ptr = umockdev_ioctl_data_resolve(arg, 0, sizeof(gpointer), NULL);
    umockdev_ioctl_data_set_ptr(ptr, 0, urb_data);
    umockdev_ioctl_client_complete(client, 0, 0);
    g_object_unref(ptr);
    g_object_unref(urb_data);
    return TRUE;
}

static gboolean handle_ioctl(UMockdevIoctlBase *handler, UMockdevIoctlClient *client,
                             gpointer user_data)
{
    printer_sim *sim = user_data;
    gulong request = umockdev_ioctl_client_get_request(client);
    UMockdevIoctlData *arg = umockdev_ioctl_client_get_arg(client);
    gboolean handled = TRUE;
    (void)handler;

    g_mutex_lock(&sim->lock);
    if (request == USBDEVFS_REAPURB || request == USBDEVFS_REAPURBNDELAY) {
        handled = reap_urb(sim, client, arg);
        g_mutex_unlock(&sim->lock);
        return handled;
    }
    if (sim->unplugged) {
        logf_locked(sim, "ENODEV %#lx", request);
        umockdev_ioctl_client_complete(client, -1, ENODEV);
        g_mutex_unlock(&sim->lock);
        return TRUE;
    }
    switch (request) {
    case USBDEVFS_GET_CAPABILITIES: {
        UMockdevIoctlData *d = umockdev_ioctl_data_resolve(arg, 0, sizeof(guint32), NULL);
        *(guint32 *)d->data = USBDEVFS_CAP_BULK_CONTINUATION | USBDEVFS_CAP_NO_PACKET_SIZE_LIM |
                              USBDEVFS_CAP_REAP_AFTER_DISCONNECT;
        umockdev_ioctl_client_complete(client, 0, 0);
        g_object_unref(d);
        break;
    }
    case USBDEVFS_GETDRIVER: {
        UMockdevIoctlData *d =
            umockdev_ioctl_data_resolve(arg, 0, sizeof(struct usbdevfs_getdriver), NULL);
        struct usbdevfs_getdriver *gd = (struct usbdevfs_getdriver *)d->data;
        logf_locked(sim, "GETDRIVER %u", gd->interface);
        if (gd->interface == 0 && sim->usblp_bound) {
            g_strlcpy(gd->driver, "usblp", sizeof gd->driver);
            umockdev_ioctl_client_complete(client, 0, 0);
        } else if (gd->interface == 0 && sim->claimed) {
            g_strlcpy(gd->driver, "usbfs", sizeof gd->driver);
            umockdev_ioctl_client_complete(client, 0, 0);
        } else {
            umockdev_ioctl_client_complete(client, -1, ENODATA);
        }
        g_object_unref(d);
        break;
    }
    case USBDEVFS_IOCTL: {
        UMockdevIoctlData *d = umockdev_ioctl_data_resolve(arg, 0, sizeof(struct usbdevfs_ioctl), NULL);
        struct usbdevfs_ioctl *io = (struct usbdevfs_ioctl *)d->data;
        if (io->ioctl_code == (int)USBDEVFS_DISCONNECT) {
            logf_locked(sim, "DISCONNECT %d", io->ifno);
            if (io->ifno == 0 && sim->usblp_bound) {
                sim->usblp_bound = 0;
                umockdev_ioctl_client_complete(client, 0, 0);
            } else {
                umockdev_ioctl_client_complete(client, -1, ENODATA);
            }
        } else if (io->ioctl_code == (int)USBDEVFS_CONNECT) {
            logf_locked(sim, "CONNECT %d", io->ifno);
            if (io->ifno == 0 && !sim->claimed) {
                sim->usblp_bound = 1;
                umockdev_ioctl_client_complete(client, 0, 0);
            } else {
                umockdev_ioctl_client_complete(client, -1, EBUSY);
            }
        } else {
            logf_locked(sim, "IOCTL %d %#x", io->ifno, (unsigned)io->ioctl_code);
            sim->unknown++;
            umockdev_ioctl_client_complete(client, -1, ENOTTY);
        }
        g_object_unref(d);
        break;
    }
    case USBDEVFS_CLAIMINTERFACE:
    case USBDEVFS_RELEASEINTERFACE: {
        UMockdevIoctlData *d = umockdev_ioctl_data_resolve(arg, 0, sizeof(unsigned int), NULL);
        unsigned int ifno = *(unsigned int *)d->data;
        int claim = request == USBDEVFS_CLAIMINTERFACE;
        logf_locked(sim, "%s %u", claim ? "CLAIM" : "RELEASE", ifno);
        if (ifno != 0)
            umockdev_ioctl_client_complete(client, -1, ENOENT);
        else if (claim && sim->usblp_bound)
            umockdev_ioctl_client_complete(client, -1, EBUSY);
        else if (!claim && !sim->claimed)
            umockdev_ioctl_client_complete(client, -1, EINVAL);
        else {
            sim->claimed = claim;
            umockdev_ioctl_client_complete(client, 0, 0);
        }
        g_object_unref(d);
        break;
    }
    case USBDEVFS_CLEAR_HALT: {
        UMockdevIoctlData *d = umockdev_ioctl_data_resolve(arg, 0, sizeof(unsigned int), NULL);
        logf_locked(sim, "CLEAR_HALT %02x", *(unsigned int *)d->data);
        sim->halted = 0;
        umockdev_ioctl_client_complete(client, 0, 0);
        g_object_unref(d);
        break;
    }
    case USBDEVFS_SUBMITURB:
        handled = submit_urb(sim, client, arg);
        break;
    case USBDEVFS_DISCARDURB: {
        gulong addr = *(gulong *)arg->data; /* the URB pointer itself */
        GList *l;
        for (l = sim->flying; l; l = l->next)
            if (((UMockdevIoctlData *)l->data)->client_addr == addr)
                break;
        logf_locked(sim, "DISCARD%s", l ? "" : " (not in flight)");
        if (l) {
            UMockdevIoctlData *u = l->data;
            sim->flying = g_list_delete_link(sim->flying, l);
            finish_urb(sim, u, -ENOENT, 0);
            g_object_unref(u);
            umockdev_ioctl_client_complete(client, 0, 0);
        } else {
            umockdev_ioctl_client_complete(client, -1, EINVAL);
        }
        break;
    }
    default:
        logf_locked(sim, "UNKNOWN %#lx", request);
        sim->unknown++;
        umockdev_ioctl_client_complete(client, -1, ENOTTY);
        break;
    }
    g_mutex_unlock(&sim->lock);
    return handled;
}

printer_sim *printer_sim_new(void)
{
    printer_sim *sim = g_new0(printer_sim, 1);
    GError *error = NULL;
    g_mutex_init(&sim->lock);
    g_queue_init(&sim->done);
    sim->job = g_byte_array_new();
    sim->log = g_ptr_array_new_with_free_func(g_free);
    sim->usblp_bound = 1;
    sim->status = 0x18; /* selected, no error, paper present */
    sim->testbed = umockdev_testbed_new();
    sim->handler = umockdev_ioctl_base_new();
    g_signal_connect(sim->handler, "handle-ioctl", G_CALLBACK(handle_ioctl), sim);
    if (!umockdev_testbed_attach_ioctl(sim->testbed, "/dev/bus/usb/001/003", sim->handler,
                                       &error))
        g_error("attach_ioctl: %s", error->message);

    /* Another device first, so that "find by class" has to look: a mouse. */
    if (!umockdev_testbed_add_from_string(sim->testbed,
            "P: /devices/pci0000:00/usb1/1-1\n"
            "N: bus/usb/001/002\n"
            "E: SUBSYSTEM=usb\n"
            "E: DEVTYPE=usb_device\n"
            "E: DEVNAME=/dev/bus/usb/001/002\n"
            "E: BUSNUM=001\n"
            "E: DEVNUM=002\n"
            "A: busnum=1\\n\n"
            "A: devnum=2\\n\n"
            "A: bConfigurationValue=1\\n\n"
            "A: speed=12\\n\n"
            "H: descriptors=12011001000000086d041cc3000101020001"
            "09022200010100a0320904000001030102000921110100012234000705810304000a\n",
            &error))
        g_error("add mouse: %s", error->message);
    /* The printer: class 7, subclass 1, protocol 2; bulk OUT 0x01, IN 0x82. */
    if (!umockdev_testbed_add_from_string(sim->testbed,
            "P: /devices/pci0000:00/usb1/1-2\n"
            "N: bus/usb/001/003\n"
            "E: SUBSYSTEM=usb\n"
            "E: DEVTYPE=usb_device\n"
            "E: DEVNAME=/dev/bus/usb/001/003\n"
            "E: BUSNUM=001\n"
            "E: DEVNUM=003\n"
            "A: busnum=1\\n\n"
            "A: devnum=3\\n\n"
            "A: bConfigurationValue=1\\n\n"
            "A: speed=12\\n\n"
            "H: descriptors=120100020000004016041150000101020001"
            "0902200001010080320904000002070102000705010240000007058202400000\n",
            &error))
        g_error("add printer: %s", error->message);
    return sim;
}

void printer_sim_free(printer_sim *sim)
{
    if (!sim)
        return;
    g_clear_object(&sim->handler);
    g_clear_object(&sim->testbed);
    g_queue_clear_full(&sim->done, g_object_unref);
    g_list_free_full(sim->flying, g_object_unref);
    g_byte_array_unref(sim->job);
    g_ptr_array_unref(sim->log);
    g_mutex_clear(&sim->lock);
    g_free(sim);
}

int printer_sim_logged(printer_sim *sim, const char *line)
{
    guint i;
    int found = 0;
    g_mutex_lock(&sim->lock);
    for (i = 0; i < sim->log->len && !found; i++)
        found = strcmp(g_ptr_array_index(sim->log, i), line) == 0;
    g_mutex_unlock(&sim->lock);
    return found;
}

char *printer_sim_log_text(printer_sim *sim)
{
    GString *s = g_string_new("");
    guint i;
    g_mutex_lock(&sim->lock);
    for (i = 0; i < sim->log->len; i++)
        g_string_append_printf(s, "%s%s", i ? "; " : "", (char *)g_ptr_array_index(sim->log, i));
    g_mutex_unlock(&sim->lock);
    return g_string_free(s, FALSE);
}
