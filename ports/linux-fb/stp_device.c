/* SPDX-License-Identifier: MIT */
/* Device specs onto the Linux ports (see stp_device.h).  STP_DEVICE_WITH_USB
 * and STP_DEVICE_WITH_GPIO say which optional pieces this build has. */
#include "stp_device.h"
#include "stp_error.h"

#include <ctype.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "stp_linuxfb.h"
#include "stp_spipanel.h"
#ifdef STP_DEVICE_WITH_USB
#include "stp_usbprint.h"
#endif
#ifdef STP_DEVICE_WITH_GPIO
#include "stp_gpio.h"
#endif

#define SPEC_MAX 1024
#define KEYS_MAX 16

typedef enum { KIND_FB, KIND_USB, KIND_SPI } device_kind;

struct stp_device {
    device_kind kind;
    stp_port *port;
    stp_linuxfb *fb;
    stp_spipanel *spi;
#ifdef STP_DEVICE_WITH_USB
    stp_usbprint *usb;
#endif
#ifdef STP_DEVICE_WITH_GPIO
    stp_gpio_panel *gpio;
#endif
    int finished;
    char description[200];
};

/* A spec cut into its parts (pointers into a copy). */
typedef struct spec_parts {
    char text[SPEC_MAX];
    const char *kind;
    const char *target;        /* "" when absent */
    const char *key[KEYS_MAX];
    const char *value[KEYS_MAX]; /* NULL for a bare key ("cut") */
    int keys;
} spec_parts;

/* "device spec 'SPEC': " + the message */
static void spec_err(char *err, size_t errlen, const char *spec, const char *fmt, ...)
{
    va_list ap;
    char prefix[224];
    snprintf(prefix, sizeof prefix, "device spec '%.200s': ", spec);
    va_start(ap, fmt);
    stp_error_vset(err, errlen, prefix, fmt, ap);
    va_end(ap);
}

void stp_device_options_default(stp_device_options *opt)
{
    memset(opt, 0, sizeof *opt);
    opt->format = STP_DEVICE_FORMAT_AUTO;
}

static int split_spec(const char *spec, spec_parts *s, char *err, size_t errlen)
{
    char *p, *item;
    size_t kind_len;
    memset(s, 0, sizeof *s);
    if (strlen(spec) >= SPEC_MAX) {
        spec_err(err, errlen, spec, "longer than %d characters", SPEC_MAX - 1);
        return -1;
    }
    strcpy(s->text, spec);
    kind_len = strcspn(s->text, ":,");
    s->kind = s->text;
    p = s->text + kind_len;
    if (*p == ':') {
        *p++ = '\0';
        item = p;
        p += strcspn(p, ",");
        if (*p == ',')
            *p++ = '\0';
        else
            p = NULL;
        s->target = item;
    } else {
        s->target = "";
        if (*p == ',')
            *p++ = '\0';
        else
            p = NULL;
    }
    while (p) {
        char *eq;
        item = p;
        p += strcspn(p, ",");
        if (*p == ',')
            *p++ = '\0';
        else
            p = NULL;
        if (*item == '\0') {
            spec_err(err, errlen, spec, "empty option (two commas, or a comma at the end)");
            return -1;
        }
        if (s->keys == KEYS_MAX) {
            spec_err(err, errlen, spec, "more than %d options", KEYS_MAX);
            return -1;
        }
        eq = strchr(item, '=');
        if (eq)
            *eq = '\0';
        s->key[s->keys] = item;
        s->value[s->keys] = eq ? eq + 1 : NULL;
        s->keys++;
    }
    return 0;
}

/* Checks every key is one of allowed (a NULL-terminated list), at most once,
 * with a value unless it is in bare (keys that may stand alone). */
static int check_keys(const char *spec, const spec_parts *s, const char *const *allowed,
                      const char *const *bare, const char *allowed_text, char *err, size_t errlen)
{
    int i, j;
    for (i = 0; i < s->keys; i++) {
        int known = 0, may_be_bare = 0;
        for (j = 0; allowed[j]; j++)
            known |= strcmp(s->key[i], allowed[j]) == 0;
        for (j = 0; bare && bare[j]; j++)
            may_be_bare |= strcmp(s->key[i], bare[j]) == 0;
        if (!known) {
            spec_err(err, errlen, spec, "unknown option '%s' for %s devices (%s)", s->key[i],
                     s->kind, allowed_text);
            return -1;
        }
        if (!s->value[i] && !may_be_bare) {
            spec_err(err, errlen, spec, "option '%s' needs a value (%s=...)", s->key[i], s->key[i]);
            return -1;
        }
        if (s->value[i] && s->value[i][0] == '\0') {
            spec_err(err, errlen, spec, "option '%s' has an empty value", s->key[i]);
            return -1;
        }
        for (j = 0; j < i; j++)
            if (strcmp(s->key[i], s->key[j]) == 0) {
                spec_err(err, errlen, spec, "option '%s' given twice", s->key[i]);
                return -1;
            }
    }
    return 0;
}

static const char *find_key(const spec_parts *s, const char *key)
{
    int i;
    for (i = 0; i < s->keys; i++)
        if (strcmp(s->key[i], key) == 0)
            return s->value[i] ? s->value[i] : "";
    return NULL;
}

/* A decimal number in [lo, hi]. */
static int parse_number(const char *text, unsigned long lo, unsigned long hi, unsigned long *out)
{
    unsigned long v = 0;
    const char *c;
    if (!*text)
        return -1;
    for (c = text; *c; c++) {
        if (!isdigit((unsigned char)*c))
            return -1;
        if (v > (hi - (unsigned long)(*c - '0')) / 10u)
            return -1;
        v = v * 10u + (unsigned long)(*c - '0');
    }
    if (v < lo)
        return -1;
    *out = v;
    return 0;
}

static int number_key(const char *spec, const spec_parts *s, const char *key, unsigned long lo,
                      unsigned long hi, const char *unit, unsigned long *out, char *err,
                      size_t errlen)
{
    const char *v = find_key(s, key);
    if (!v)
        return 0;
    if (parse_number(v, lo, hi, out) != 0) {
        spec_err(err, errlen, spec, "%s '%s' is not a number of %s (%lu..%lu)", key, v, unit, lo,
                 hi);
        return -1;
    }
    return 1;
}

static const char *format_name(int f)
{
    switch (f) {
    case STP_PIXEL_MONO1:
        return "MONO1";
    case STP_PIXEL_GREY8:
        return "GREY8";
    case STP_PIXEL_RGB888:
        return "RGB888";
    case STP_PIXEL_STYLE8:
        return "STYLE8";
    case STP_PIXEL_MONO1_PAGES:
        return "MONO1_PAGES";
    }
    return "?";
}

/* ---------------------------------------------------------------- fb */

static int open_fb(stp_device *d, const char *spec, const spec_parts *s,
                   const stp_device_options *opt, char *err, size_t errlen)
{
    static const char *const keys[] = {"format", NULL};
    stp_linuxfb_options fo;
    const char *fmt;
    stp_linuxfb_info info;
    if (check_keys(spec, s, keys, NULL, "format", err, errlen) != 0)
        return -1;
    if (s->target[0] != '/') {
        spec_err(err, errlen, spec, "fb needs a device path, e.g. fb:/dev/fb0");
        return -1;
    }
    stp_linuxfb_options_default(&fo);
    fo.width = opt->width;
    fo.height = opt->height;
    fo.format = opt->format;
    fmt = find_key(s, "format");
    if (fmt) {
        if (strcmp(fmt, "mono1") == 0)
            fo.format = STP_PIXEL_MONO1;
        else if (strcmp(fmt, "grey8") == 0)
            fo.format = STP_PIXEL_GREY8;
        else if (strcmp(fmt, "rgb888") == 0)
            fo.format = STP_PIXEL_RGB888;
        else {
            spec_err(err, errlen, spec, "format '%s' is not mono1, grey8 or rgb888", fmt);
            return -1;
        }
    }
    if (fo.format != STP_LINUXFB_FORMAT_AUTO && fo.format != STP_PIXEL_MONO1 &&
        fo.format != STP_PIXEL_GREY8 && fo.format != STP_PIXEL_RGB888) {
        spec_err(err, errlen, spec, "framebuffers take MONO1, GREY8 or RGB888, not %s",
                 format_name(fo.format));
        return -1;
    }
    d->fb = stp_linuxfb_open(s->target, &fo, err, errlen);
    if (!d->fb)
        return -1;
    d->port = stp_linuxfb_port(d->fb);
    stp_linuxfb_get_info(d->fb, &info);
    snprintf(d->description, sizeof d->description, "framebuffer %s (%s) %ux%u %s", s->target,
             info.id, (unsigned)d->port->width, (unsigned)d->port->height,
             format_name(d->port->format));
    return 0;
}

/* ---------------------------------------------------------------- usb */

/* 1..4 hex digits */
static int parse_hex16(const char *text, size_t len, unsigned *out)
{
    unsigned v = 0;
    size_t i;
    if (len == 0 || len > 4)
        return -1;
    for (i = 0; i < len; i++) {
        int c = (unsigned char)text[i];
        if (!isxdigit(c))
            return -1;
        v = v * 16u + (unsigned)(isdigit(c) ? c - '0' : tolower(c) - 'a' + 10);
    }
    *out = v;
    return 0;
}

static int open_usb(stp_device *d, const char *spec, const spec_parts *s,
                    const stp_device_options *opt, char *err, size_t errlen)
{
    static const char *const keys[] = {"width", "height", "feed", "cut", NULL};
    static const char *const bare[] = {"cut", NULL};
    unsigned vid = 0, pid = 0;
    unsigned long width = opt->width, height = opt->height, feed = 4, cut = 0;
    const char *cut_text;
    if (check_keys(spec, s, keys, bare, "width, height, feed, cut", err, errlen) != 0)
        return -1;
    if (s->target[0] != '\0' && strcmp(s->target, "class") != 0) {
        const char *colon = strchr(s->target, ':');
        if (!colon) {
            spec_err(err, errlen, spec, "'%s' is not VID:PID (hex) or 'class'", s->target);
            return -1;
        }
        if (parse_hex16(s->target, (size_t)(colon - s->target), &vid) != 0) {
            spec_err(err, errlen, spec, "vendor id '%.*s' is not 1..4 hex digits",
                     (int)(colon - s->target), s->target);
            return -1;
        }
        if (parse_hex16(colon + 1, strlen(colon + 1), &pid) != 0) {
            spec_err(err, errlen, spec, "product id '%s' is not 1..4 hex digits", colon + 1);
            return -1;
        }
        if (vid == 0 && pid == 0) {
            spec_err(err, errlen, spec,
                     "0000:0000 is no device (use usb:class for the first printer)");
            return -1;
        }
    }
    if (number_key(spec, s, "width", 8, 32767, "dots", &width, err, errlen) < 0 ||
        number_key(spec, s, "height", 1, 32767, "rows", &height, err, errlen) < 0 ||
        number_key(spec, s, "feed", 0, 255, "lines", &feed, err, errlen) < 0)
        return -1;
    cut_text = find_key(s, "cut");
    if (cut_text) {
        if (*cut_text == '\0' || strcmp(cut_text, "1") == 0)
            cut = 1;
        else if (strcmp(cut_text, "0") != 0) {
            spec_err(err, errlen, spec, "cut '%s' is not 0 or 1", cut_text);
            return -1;
        }
    }
    if (opt->format != STP_DEVICE_FORMAT_AUTO && opt->format != STP_PIXEL_MONO1) {
        spec_err(err, errlen, spec, "USB printers take MONO1 pictures, not %s",
                 format_name(opt->format));
        return -1;
    }
#ifdef STP_DEVICE_WITH_USB
    {
        stp_usbprint_options uo;
        stp_usbprint_options_default(&uo);
        uo.vendor_id = (uint16_t)vid;
        uo.product_id = (uint16_t)pid;
        if (width)
            uo.width = (uint32_t)width;
        if (height)
            uo.height = (uint32_t)height;
        uo.feed_lines = (unsigned)feed;
        uo.cut = (int)cut;
        d->usb = stp_usbprint_open(&uo, err, errlen);
        if (!d->usb)
            return -1;
        if (stp_usbprint_begin(d->usb, err, errlen) != 0)
            return -1;
        d->port = stp_usbprint_port(d->usb);
        if (vid || pid)
            snprintf(d->description, sizeof d->description, "USB printer %04x:%04x %ux%u MONO1",
                     vid, pid, (unsigned)d->port->width, (unsigned)d->port->height);
        else
            snprintf(d->description, sizeof d->description,
                     "USB printer (first of class 7) %ux%u MONO1", (unsigned)d->port->width,
                     (unsigned)d->port->height);
        return 0;
    }
#else
    (void)d;
    (void)vid;
    (void)pid;
    (void)width;
    (void)height;
    (void)feed;
    (void)cut;
    spec_err(err, errlen, spec, "built without libusb-1.0: USB printers are not available");
    return -1;
#endif
}

/* ---------------------------------------------------------------- spi */

static int open_spi(stp_device *d, const char *spec, const spec_parts *s,
                    const stp_device_options *opt, char *err, size_t errlen)
{
    static const char *const keys[] = {"controller", "dc",    "reset", "busy", "vcom",
                                       "enable",     "speed", "timeout", NULL};
    static const char *const line_keys[] = {"dc", "reset", "busy", "vcom", "enable", NULL};
    const stp_panel_controller *c;
    const char *name;
    unsigned long speed = 0, timeout = 0;
    stp_spipanel_options so;
    stp_spipanel_lines lines;
    int i, any_line = 0;
    if (check_keys(spec, s, keys, NULL, "controller, dc, reset, busy, vcom, enable, speed, timeout",
                   err, errlen) != 0)
        return -1;
    if (s->target[0] != '/') {
        spec_err(err, errlen, spec,
                 "spi needs a spidev path, e.g. spi:/dev/spidev0.0,controller=ssd1306");
        return -1;
    }
    name = find_key(s, "controller");
    if (!name) {
        spec_err(err, errlen, spec, "no controller=NAME (%s)", stp_spipanel_controller_names());
        return -1;
    }
    c = stp_spipanel_find_controller(name);
    if (!c) {
        spec_err(err, errlen, spec, "unknown controller '%s' (%s)", name,
                 stp_spipanel_controller_names());
        return -1;
    }
    if (number_key(spec, s, "speed", 1, 100000000ul, "hertz", &speed, err, errlen) < 0 ||
        number_key(spec, s, "timeout", 1, 600000ul, "milliseconds", &timeout, err, errlen) < 0)
        return -1;
    if ((opt->width && opt->width != c->width) || (opt->height && opt->height != c->height)) {
        spec_err(err, errlen, spec, "the %s panel is %ux%u, not %ux%u", c->name,
                 (unsigned)c->width, (unsigned)c->height,
                 (unsigned)(opt->width ? opt->width : c->width),
                 (unsigned)(opt->height ? opt->height : c->height));
        return -1;
    }
    if (opt->format != STP_DEVICE_FORMAT_AUTO && opt->format != STP_PIXEL_MONO1) {
        spec_err(err, errlen, spec, "SPI panels take MONO1 pictures, not %s",
                 format_name(opt->format));
        return -1;
    }
    for (i = 0; line_keys[i]; i++)
        if (find_key(s, line_keys[i]))
            any_line = 1;
    memset(&lines, 0, sizeof lines);
    if (any_line) {
#ifdef STP_DEVICE_WITH_GPIO
        stp_gpio_panel_config gc;
        memset(&gc, 0, sizeof gc);
        gc.reset = find_key(s, "reset");
        gc.dc = find_key(s, "dc");
        gc.busy = find_key(s, "busy");
        gc.vcom = find_key(s, "vcom");
        gc.enable = find_key(s, "enable");
        gc.consumer = "stipple";
        d->gpio = stp_gpio_panel_open(&gc, err, errlen);
        if (!d->gpio)
            return -1;
        if (gc.enable && stp_gpio_panel_enable(d->gpio, 1, err, errlen) != 0)
            return -1;
        stp_spipanel_lines_from_gpio(d->gpio, &gc, &lines);
#else
        for (i = 0; line_keys[i]; i++)
            if (find_key(s, line_keys[i])) {
                spec_err(err, errlen, spec, "built without libgpiod: cannot drive %s=%s",
                         line_keys[i], find_key(s, line_keys[i]));
                return -1;
            }
#endif
    }
    stp_spipanel_options_default(&so);
    so.speed_hz = (uint32_t)speed;
    so.busy_timeout_ms = (unsigned)timeout;
    d->spi = stp_spipanel_open(s->target, c, &lines, &so, err, errlen);
    if (!d->spi)
        return -1;
    d->port = stp_spipanel_port(d->spi);
    snprintf(d->description, sizeof d->description, "%s %ux%u %s on %s", c->name, (unsigned)c->width,
             (unsigned)c->height, format_name(d->port->format), s->target);
    return 0;
}

/* ---------------------------------------------------------------- API */

stp_device *stp_device_open(const char *spec, const stp_device_options *opt_in, char *err,
                            size_t errlen)
{
    stp_device_options opt;
    spec_parts *s;
    stp_device *d;
    int status;
    if (opt_in)
        opt = *opt_in;
    else
        stp_device_options_default(&opt);
    if (!spec || !*spec) {
        stp_error_set(err, errlen, "device spec is empty (fb:/dev/fbN, usb:VID:PID, usb:class, "
                             "spi:/dev/spidevB.C,controller=NAME,...)");
        return NULL;
    }
    if (opt.width > 32767 || opt.height > 32767) {
        spec_err(err, errlen, spec, "size %ux%u out of range (1..32767, 0: the device's)",
                 (unsigned)opt.width, (unsigned)opt.height);
        return NULL;
    }
    s = malloc(sizeof *s);
    d = calloc(1, sizeof *d);
    if (!s || !d) {
        stp_error_set(err, errlen, "out of memory");
        free(s);
        free(d);
        return NULL;
    }
    if (split_spec(spec, s, err, errlen) != 0) {
        free(s);
        free(d);
        return NULL;
    }
    if (strcmp(s->kind, "fb") == 0) {
        d->kind = KIND_FB;
        status = open_fb(d, spec, s, &opt, err, errlen);
    } else if (strcmp(s->kind, "usb") == 0) {
        d->kind = KIND_USB;
        status = open_usb(d, spec, s, &opt, err, errlen);
    } else if (strcmp(s->kind, "spi") == 0) {
        d->kind = KIND_SPI;
        status = open_spi(d, spec, s, &opt, err, errlen);
    } else {
        spec_err(err, errlen, spec, "unknown device kind '%s' (fb, usb, spi)", s->kind);
        status = -1;
    }
    free(s);
    if (status != 0) {
        stp_device_close(d);
        return NULL;
    }
    return d;
}

stp_port *stp_device_port(stp_device *d)
{
    return d ? d->port : NULL;
}

const char *stp_device_describe(const stp_device *d)
{
    return d ? d->description : "";
}

const char *stp_device_error(const stp_device *d)
{
    if (!d)
        return "";
    if (d->spi)
        return stp_spipanel_error(d->spi);
#ifdef STP_DEVICE_WITH_USB
    if (d->usb)
        return stp_usbprint_error(d->usb);
#endif
    return "";
}

int stp_device_finish(stp_device *d, char *err, size_t errlen)
{
    if (!d) {
        stp_error_set(err, errlen, "no device");
        return -1;
    }
    if (d->finished)
        return 0;
    d->finished = 1;
#ifdef STP_DEVICE_WITH_USB
    if (d->usb)
        return stp_usbprint_end(d->usb, err, errlen);
#endif
    return 0;
}

int stp_device_tick(stp_device *d, char *err, size_t errlen)
{
    if (!d) {
        stp_error_set(err, errlen, "no device");
        return -1;
    }
    return d->spi ? stp_spipanel_vcom_tick(d->spi, err, errlen) : 0;
}

void stp_device_close(stp_device *d)
{
    if (!d)
        return;
    stp_spipanel_close(d->spi);
#ifdef STP_DEVICE_WITH_GPIO
    stp_gpio_panel_close(d->gpio);
#endif
#ifdef STP_DEVICE_WITH_USB
    stp_usbprint_close(d->usb);
#endif
    stp_linuxfb_close(d->fb);
    free(d);
}
