/* SPDX-License-Identifier: MIT */
/* SPI panels through spidev (see stp_spipanel.h). */
#include "stp_spipanel.h"
#include "stp_error.h"

#include <errno.h>
#include <fcntl.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include <linux/spi/spidev.h>
#include <sys/ioctl.h>

#define SPIDEV_BUFSIZ_PATH "/sys/module/spidev/parameters/bufsiz"
#define SPIDEV_DEFAULT_BUFSIZ 4096u
/* transfers in one SPI_IOC_MESSAGE (the ioctl's size field allows 511) */
#define MAX_TRANSFERS 64u

struct stp_spipanel {
    stp_port port;
    const stp_panel_controller *c;
    stp_spipanel_lines lines;
    stp_panel_bus bus;
    int fd;
    char path[128];
    uint32_t speed_hz;
    size_t max_transfer;
    unsigned busy_timeout_ms;
    int dc_level;          /* -1 until first set */
    int vcom_level;        /* software VCOM (M1) */
    char after[40];        /* the last thing sent: "after command 0x12" */
    char stage[40];        /* what is being done: "init", "page 3", ... */
    size_t mono_row_bytes; /* a MONO1 row of the panel's width (PAGES: a page) */
    uint8_t *frame;        /* WINDOW_COUNTERS: height packed rows */
    uint8_t *buf;          /* LINES: one write; others: packing scratch */
    size_t sent;           /* bytes sent since the frame began */
    char error[320];
};

static const struct {
    const char *name;
    const stp_panel_controller *controller;
} controllers[] = {
    {"ssd1306", &stp_panel_ssd1306},
    {"sharp-ls013b7dh03", &stp_panel_sharp_ls013b7dh03},
    {"ssd1680", &stp_panel_ssd1680},
    {"ssd1680-128x296", &stp_panel_ssd1680_128x296},
};

/* p->error = "NAME on PATH: " + the message */
static void panel_err(stp_spipanel *p, const char *fmt, ...)
{
    va_list ap;
    char prefix[sizeof p->error];
    snprintf(prefix, sizeof prefix, "%s on %s: ", p->c->name, p->path);
    va_start(ap, fmt);
    stp_error_vset(p->error, sizeof p->error, prefix, fmt, ap);
    va_end(ap);
}

void stp_spipanel_options_default(stp_spipanel_options *opt)
{
    memset(opt, 0, sizeof *opt);
}

const stp_panel_controller *stp_spipanel_find_controller(const char *name)
{
    size_t i;
    for (i = 0; name && i < sizeof controllers / sizeof controllers[0]; i++)
        if (strcmp(name, controllers[i].name) == 0)
            return controllers[i].controller;
    return NULL;
}

const char *stp_spipanel_controller_names(void)
{
    return "ssd1306, sharp-ls013b7dh03, ssd1680, ssd1680-128x296";
}

static void delay_us(stp_spipanel *p, unsigned us)
{
    struct timespec ts;
    if (p->lines.delay_us) {
        p->lines.delay_us(p->lines.ctx, us);
        return;
    }
    ts.tv_sec = (time_t)(us / 1000000u);
    ts.tv_nsec = (long)(us % 1000000u) * 1000L;
    while (nanosleep(&ts, &ts) != 0 && errno == EINTR) {
    }
}

/* ------------------------------------------------------------------ bus */

static void fill_transfer(stp_spipanel *p, struct spi_ioc_transfer *x, const uint8_t *bytes,
                          size_t n)
{
    memset(x, 0, sizeof *x);
    x->tx_buf = (uint64_t)(uintptr_t)bytes;
    x->len = (uint32_t)n;
    x->speed_hz = p->speed_hz;
    x->bits_per_word = 8;
}

/* One SPI message (one chip-select frame) of count transfers, total bytes
 * (<= max_transfer).  what says what it was, for the message. */
static int spi_message(stp_spipanel *p, struct spi_ioc_transfer *x, unsigned count, size_t total,
                       const char *what)
{
    unsigned long request =
        _IOC(_IOC_WRITE, SPI_IOC_MAGIC, 0, count * sizeof(struct spi_ioc_transfer));
    int r = ioctl(p->fd, request, x);
    if (r < 0 || (size_t)r != total) {
        int e = errno;
        panel_err(p, "%s: SPI transfer failed (%s; %zu bytes had gone out this frame): %s",
                  p->stage, what, p->sent, r < 0 ? strerror(e) : "short transfer");
        return -1;
    }
    p->sent += total;
    return 0;
}

/* Bytes in messages of at most max_transfer bytes, one transfer each. */
static int spi_send(stp_spipanel *p, const uint8_t *bytes, size_t n, const char *what)
{
    while (n > 0) {
        struct spi_ioc_transfer x;
        size_t k = n < p->max_transfer ? n : p->max_transfer;
        fill_transfer(p, &x, bytes, k);
        if (spi_message(p, &x, 1, k, what) != 0)
            return -1;
        bytes += k;
        n -= k;
    }
    return 0;
}

static int set_dc(stp_spipanel *p, int data)
{
    char msg[200];
    if (!(p->c->bus_flags & STP_PANEL_BUS_DC) || p->dc_level == data)
        return 0;
    msg[0] = '\0';
    if (p->lines.dc(p->lines.ctx, data, msg, sizeof msg) != 0) {
        p->dc_level = -1;
        panel_err(p, "%s: D/C line: %s", p->stage, msg);
        return -1;
    }
    p->dc_level = data;
    return 0;
}

static int bus_command(void *ctx, const uint8_t *bytes, size_t count)
{
    stp_spipanel *p = ctx;
    char what[48];
    if (count == 0)
        return 0;
    snprintf(what, sizeof what, "command 0x%02X", bytes[0]);
    if (p->c->bus_flags & STP_PANEL_BUS_DC) {
        size_t first = (p->c->bus_flags & STP_PANEL_BUS_PARAMS_AS_DATA) ? 1u : count;
        if (set_dc(p, 0) != 0 || spi_send(p, bytes, first, what) != 0)
            return -1;
        if (first < count) {
            snprintf(what, sizeof what, "parameters of command 0x%02X", bytes[0]);
            if (set_dc(p, 1) != 0 || spi_send(p, bytes + first, count - first, what) != 0)
                return -1;
        }
    } else if (spi_send(p, bytes, count, what) != 0) {
        return -1;
    }
    snprintf(p->after, sizeof p->after, "after command 0x%02X", bytes[0]);
    return 0;
}

static int bus_data(void *ctx, const uint8_t *bytes, size_t count)
{
    stp_spipanel *p = ctx;
    if (set_dc(p, 1) != 0)
        return -1;
    return spi_send(p, bytes, count, "pixel data");
}

static int run_step(void *ctx, unsigned op, unsigned arg)
{
    stp_spipanel *p = ctx;
    char msg[200];
    msg[0] = '\0';
    switch (op) {
    case STP_PANEL_STEP_RESET:
        if (!p->lines.reset)
            return 0; /* not wired: the panel's own power-on reset */
        if (p->lines.reset(p->lines.ctx, arg * 1000u, 0, msg, sizeof msg) != 0) {
            panel_err(p, "%s: reset line: %s", p->stage, msg);
            return -1;
        }
        snprintf(p->after, sizeof p->after, "after the reset pulse");
        return 0;
    case STP_PANEL_STEP_DELAY:
        delay_us(p, arg * 1000u);
        return 0;
    case STP_PANEL_STEP_WAIT_READY: {
        unsigned timeout = p->busy_timeout_ms ? p->busy_timeout_ms : arg;
        if (p->lines.wait_ready(p->lines.ctx, timeout, msg, sizeof msg) != 0) {
            panel_err(p, "%s: %s (%s)", p->stage, msg, p->after);
            return -1;
        }
        return 0;
    }
    default:
        panel_err(p, "%s: unknown sequence step %u", p->stage, op);
        return -1;
    }
}

static int run_sequence(stp_spipanel *p, const uint8_t *seq, uint16_t length, const char *stage)
{
    int status;
    snprintf(p->stage, sizeof p->stage, "%s", stage);
    p->error[0] = '\0';
    status = stp_panel_run(seq, length, &p->bus, run_step, p);
    if (status != 0 && p->error[0] == '\0')
        panel_err(p, "%s: malformed sequence in the controller description", stage);
    return status != 0 ? -1 : 0;
}

/* ----------------------------------------------------------------- flush */

/* PAGES: a STP_PIXEL_MONO1_PAGES band, each page sent as it is (the
 * renderer's bands start on pages; a short last page's rows below are 0). */
static int flush_pages(stp_spipanel *p, uint32_t y0, uint32_t rows, const uint8_t *pixels,
                       size_t stride)
{
    const stp_panel_controller *c = p->c;
    uint32_t k;
    if (y0 % 8u != 0) {
        panel_err(p, "band at row %u: a page band starts on a page (a multiple of 8)", (unsigned)y0);
        return -1;
    }
    for (k = 0; k < (rows + 7u) / 8u; k++) {
        snprintf(p->stage, sizeof p->stage, "page %u", (unsigned)(y0 / 8u + k));
        if (stp_panel_send_page(c, &p->bus, y0 / 8u + k, pixels + (size_t)k * stride, c->width) != 0)
            return -1;
    }
    return 0;
}

/* LINES: each band as writes of whole lines, each write one SPI message
 * (one chip-select frame) within max_transfer bytes. */
static int flush_lines(stp_spipanel *p, uint32_t y0, uint32_t rows, const uint8_t *pixels,
                       size_t stride)
{
    const stp_panel_controller *c = p->c;
    struct spi_ioc_transfer x[MAX_TRANSFERS];
    size_t record = stp_panel_line_record_bytes(c);
    size_t per = (p->max_transfer - 1u - c->write_trailer) / record;
    uint32_t done = 0;
    int vcom = (p->c->bus_flags & STP_PANEL_BUS_VCOM) && !p->lines.vcom_toggle ? p->vcom_level : 0;
    if (per > MAX_TRANSFERS - 2u)
        per = MAX_TRANSFERS - 2u;
    while (done < rows) {
        uint32_t n = rows - done < per ? rows - done : (uint32_t)per, i;
        size_t at = 1;
        unsigned count = 1;
        char what[48];
        p->buf[0] = stp_panel_line_mode(c, 0, vcom);
        fill_transfer(p, &x[0], p->buf, 1);
        for (i = 0; i < n; i++) {
            size_t len = stp_panel_line_record(c, y0 + done + i,
                                               pixels + (size_t)(done + i) * stride, p->buf + at);
            fill_transfer(p, &x[count++], p->buf + at, len);
            at += len;
        }
        if (c->write_trailer) {
            memset(p->buf + at, 0, c->write_trailer);
            fill_transfer(p, &x[count++], p->buf + at, c->write_trailer);
            at += c->write_trailer;
        }
        snprintf(p->stage, sizeof p->stage, "rows %u..%u", (unsigned)(y0 + done),
                 (unsigned)(y0 + done + n - 1u));
        snprintf(what, sizeof what, "a write of %u lines", (unsigned)n);
        if (spi_message(p, x, count, at, what) != 0)
            return -1;
        done += n;
    }
    return 0;
}

/* WINDOW_COUNTERS: gather the frame; after its last row, RAM and refresh. */
static int flush_frame(stp_spipanel *p, uint32_t y0, uint32_t rows, const uint8_t *pixels,
                       size_t stride)
{
    const stp_panel_controller *c = p->c;
    size_t rb = stp_panel_row_bytes(c, c->width);
    uint32_t r;
    for (r = 0; r < rows; r++)
        stp_panel_pack_mono_row(c, pixels + (size_t)r * stride, c->width,
                                p->frame + (size_t)(y0 + r) * rb);
    if (y0 + rows < c->height)
        return 0;
    snprintf(p->stage, sizeof p->stage, "frame");
    if (stp_panel_window_counters_all(c, &p->bus) != 0 ||
        bus_data(p, p->frame, rb * c->height) != 0)
        return -1;
    return run_sequence(p, c->refresh, c->refresh_length, "refresh");
}

static int flip_vcom(stp_spipanel *p, char *msg, size_t msglen)
{
    if (!(p->c->bus_flags & STP_PANEL_BUS_VCOM))
        return 0;
    if (p->lines.vcom_toggle)
        return p->lines.vcom_toggle(p->lines.ctx, msg, msglen) < 0 ? -1 : 0;
    p->vcom_level = !p->vcom_level; /* goes out in the next mode byte */
    return 0;
}

static int port_flush(stp_port *port, uint32_t y0, uint32_t rows, const uint8_t *pixels,
                      size_t stride)
{
    stp_spipanel *p = port ? port->user : NULL;
    const stp_panel_controller *c;
    if (!p)
        return -1;
    c = p->c;
    if (!pixels || y0 >= c->height || rows > c->height - y0 ||
        (rows > (c->addressing == STP_PANEL_PAGES ? 8u : 1u) && stride < p->mono_row_bytes)) {
        panel_err(p, "band of rows %u..+%u (stride %zu) does not fit the %ux%u panel",
                  (unsigned)y0, (unsigned)rows, stride, (unsigned)c->width, (unsigned)c->height);
        return -1;
    }
    if (rows == 0)
        return 0;
    if (y0 == 0) {
        char msg[200];
        p->sent = 0;
        p->error[0] = '\0';
        msg[0] = '\0';
        snprintf(p->stage, sizeof p->stage, "frame start");
        if (flip_vcom(p, msg, sizeof msg) != 0) {
            panel_err(p, "vcom line: %s", msg);
            return -1;
        }
    }
    switch (c->addressing) {
    case STP_PANEL_PAGES:
        return flush_pages(p, y0, rows, pixels, stride);
    case STP_PANEL_LINES:
        return flush_lines(p, y0, rows, pixels, stride);
    case STP_PANEL_WINDOW_COUNTERS:
        return flush_frame(p, y0, rows, pixels, stride);
    default: /* refused at open */
        return -1;
    }
}

/* ------------------------------------------------------------ open/close */

static size_t spidev_bufsiz(void)
{
    FILE *f = fopen(SPIDEV_BUFSIZ_PATH, "r");
    unsigned long v = 0;
    if (!f)
        return SPIDEV_DEFAULT_BUFSIZ;
    if (fscanf(f, "%lu", &v) != 1 || v == 0)
        v = SPIDEV_DEFAULT_BUFSIZ;
    fclose(f);
    return (size_t)v;
}

stp_spipanel *stp_spipanel_open(const char *path, const stp_panel_controller *c,
                                const stp_spipanel_lines *lines, const stp_spipanel_options *opt_in,
                                char *err, size_t errlen)
{
    stp_spipanel_options opt;
    stp_spipanel *p;
    uint8_t mode, bits = 8;
    size_t need, bufsize;

    if (opt_in)
        opt = *opt_in;
    else
        stp_spipanel_options_default(&opt);
    if (!path || !*path || !c) {
        stp_error_set(err, errlen, "spi: no device path or no controller");
        return NULL;
    }
    if (c->width == 0 || c->height == 0 || c->width > 32767 || c->height > 32767) {
        stp_error_set(err, errlen, "spi %s: controller %s: bad description", path, c->name);
        return NULL;
    }
    /* SSD0303/SSD0323 are described for their firmware buses only */
    if (c->spi_hz == 0 || (c->addressing != STP_PANEL_PAGES && c->addressing != STP_PANEL_LINES &&
                           c->addressing != STP_PANEL_WINDOW_COUNTERS)) {
        stp_error_set(err, errlen, "spi %s: controller %s has no SPI description here", path, c->name);
        return NULL;
    }
    if (c->addressing == STP_PANEL_PAGES && c->packing != STP_PANEL_MONO_COLUMN_LSB_TOP) {
        stp_error_set(err, errlen, "spi %s: controller %s: pages need column packing", path, c->name);
        return NULL;
    }
    if (c->addressing != STP_PANEL_PAGES && c->packing != STP_PANEL_MONO_ROW_MSB_LEFT) {
        stp_error_set(err, errlen, "spi %s: controller %s: rows need 1-bit row packing", path, c->name);
        return NULL;
    }
    if ((c->bus_flags & STP_PANEL_BUS_DC) && (!lines || !lines->dc)) {
        stp_error_set(err, errlen, "spi %s: controller %s needs a D/C line (dc=LINE)", path, c->name);
        return NULL;
    }
    if ((c->bus_flags & STP_PANEL_BUS_BUSY) && (!lines || !lines->wait_ready)) {
        stp_error_set(err, errlen, "spi %s: controller %s needs a BUSY line (busy=LINE)", path, c->name);
        return NULL;
    }
    if (opt.speed_hz > 100000000u) {
        stp_error_set(err, errlen, "spi %s: speed %lu Hz out of range (1..100000000)", path,
                (unsigned long)opt.speed_hz);
        return NULL;
    }
    p = calloc(1, sizeof *p);
    if (!p) {
        stp_error_set(err, errlen, "spi %s: out of memory", path);
        return NULL;
    }
    p->fd = -1;
    p->c = c;
    if (lines)
        p->lines = *lines;
    snprintf(p->path, sizeof p->path, "%s", path);
    p->speed_hz = opt.speed_hz ? opt.speed_hz : c->spi_hz;
    p->busy_timeout_ms = opt.busy_timeout_ms;
    p->dc_level = -1;
    p->mono_row_bytes = c->addressing == STP_PANEL_PAGES ? (size_t)c->width : ((size_t)c->width + 7u) / 8u;
    snprintf(p->after, sizeof p->after, "before any command");
    p->bus.command = bus_command;
    p->bus.data = bus_data;
    p->bus.ctx = p;

    p->fd = open(path, O_RDWR | O_CLOEXEC);
    if (p->fd < 0) {
        int e = errno;
        stp_error_set(err, errlen, "spi %s: cannot open: %s%s", path, strerror(e),
                e == ENOENT   ? " (is SPI enabled? Raspberry Pi: dtparam=spi=on)"
                : e == EACCES ? " (join the group owning it, see ports/linux-fb/README.md)"
                              : "");
        stp_spipanel_close(p);
        return NULL;
    }
    mode = (uint8_t)(c->spi_mode & 3u);
    if (c->bus_flags & STP_PANEL_BUS_CS_HIGH)
        mode = (uint8_t)(mode | SPI_CS_HIGH);
    if (ioctl(p->fd, SPI_IOC_WR_MODE, &mode) < 0) {
        stp_error_set(err, errlen, "spi %s: cannot set SPI mode %u%s: %s", path, (unsigned)(mode & 3u),
                (mode & SPI_CS_HIGH) ? " with chip select active high" : "", strerror(errno));
        stp_spipanel_close(p);
        return NULL;
    }
    if (ioctl(p->fd, SPI_IOC_WR_BITS_PER_WORD, &bits) < 0) {
        stp_error_set(err, errlen, "spi %s: cannot set 8 bits per word: %s", path, strerror(errno));
        stp_spipanel_close(p);
        return NULL;
    }
    if (ioctl(p->fd, SPI_IOC_WR_MAX_SPEED_HZ, &p->speed_hz) < 0) {
        stp_error_set(err, errlen, "spi %s: cannot set %lu Hz: %s", path, (unsigned long)p->speed_hz,
                strerror(errno));
        stp_spipanel_close(p);
        return NULL;
    }
    p->max_transfer = opt.max_transfer ? opt.max_transfer : spidev_bufsiz();

    /* buffers: the smallest message a controller needs must fit */
    if (c->addressing == STP_PANEL_LINES) {
        need = 1u + stp_panel_line_record_bytes(c) + c->write_trailer;
        bufsize = p->max_transfer;
    } else {
        need = 1u;
        bufsize = stp_panel_row_bytes(c, c->width);
        if (c->addressing == STP_PANEL_PAGES)
            bufsize = c->width;
    }
    if (p->max_transfer < need) {
        stp_error_set(err, errlen,
                "spi %s: messages of %zu bytes cannot hold one %s line write (%zu bytes)", path,
                p->max_transfer, c->name, need);
        stp_spipanel_close(p);
        return NULL;
    }
    p->buf = malloc(bufsize);
    if (c->addressing == STP_PANEL_WINDOW_COUNTERS)
        p->frame = calloc(c->height, stp_panel_row_bytes(c, c->width));
    if (!p->buf || (c->addressing == STP_PANEL_WINDOW_COUNTERS && !p->frame)) {
        stp_error_set(err, errlen, "spi %s: out of memory", path);
        stp_spipanel_close(p);
        return NULL;
    }
    p->port.width = c->width;
    p->port.height = c->height;
    /* a page controller takes the renderer's pages as they are */
    p->port.format = c->addressing == STP_PANEL_PAGES ? STP_PIXEL_MONO1_PAGES : STP_PIXEL_MONO1;
    p->port.flush = port_flush;
    p->port.user = p;

    if (run_sequence(p, c->init, c->init_length, "init") != 0) {
        stp_error_set(err, errlen, "%s", p->error);
        p->c = NULL; /* no sleep sequence for a panel that did not start */
        stp_spipanel_close(p);
        return NULL;
    }
    p->error[0] = '\0';
    return p;
}

stp_port *stp_spipanel_port(stp_spipanel *p)
{
    return p ? &p->port : NULL;
}

const char *stp_spipanel_error(const stp_spipanel *p)
{
    return p ? p->error : "";
}

size_t stp_spipanel_max_transfer(const stp_spipanel *p)
{
    return p ? p->max_transfer : 0;
}

int stp_spipanel_vcom_tick(stp_spipanel *p, char *err, size_t errlen)
{
    char msg[200];
    struct spi_ioc_transfer x;
    size_t n, i;
    if (!p)
        return -1;
    if (!(p->c->bus_flags & STP_PANEL_BUS_VCOM))
        return 0;
    msg[0] = '\0';
    if (p->lines.vcom_toggle) {
        if (p->lines.vcom_toggle(p->lines.ctx, msg, sizeof msg) < 0) {
            stp_error_set(err, errlen, "%s on %s: vcom line: %s", p->c->name, p->path, msg);
            return -1;
        }
        return 0;
    }
    if (p->max_transfer < 1u + p->c->write_trailer) {
        stp_error_set(err, errlen, "%s on %s: messages too small for a VCOM command", p->c->name,
                p->path);
        return -1;
    }
    p->vcom_level = !p->vcom_level;
    n = 0;
    p->buf[n++] = stp_panel_line_mode(p->c, 1, p->vcom_level);
    for (i = 0; i < p->c->write_trailer; i++)
        p->buf[n++] = 0;
    snprintf(p->stage, sizeof p->stage, "vcom");
    fill_transfer(p, &x, p->buf, n);
    if (spi_message(p, &x, 1, n, "a VCOM command") != 0) {
        stp_error_set(err, errlen, "%s", p->error);
        return -1;
    }
    return 0;
}

void stp_spipanel_close(stp_spipanel *p)
{
    if (!p)
        return;
    if (p->fd >= 0 && p->c && p->c->sleep_length && p->lines.reset)
        (void)run_sequence(p, p->c->sleep, p->c->sleep_length, "sleep");
    if (p->fd >= 0)
        close(p->fd);
    free(p->buf);
    free(p->frame);
    free(p);
}
