/* SPDX-License-Identifier: MIT */
/*
 * Linux fbdev port (see stp_linuxfb.h for the rules it follows).
 */
#include "stp_linuxfb.h"
#include "stp_error.h"

#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <sys/mman.h>
#include <unistd.h>

#include <linux/fb.h>
#include <linux/kd.h>

enum pack_kind { PACK_MONO, PACK_INDEX, PACK_FIELDS };

struct stp_linuxfb {
    stp_port port;
    int fd;
    uint8_t *map;          /* mmap'ed area */
    size_t map_len;
    uint8_t *base;         /* pixel (0, 0) of the port: panning origin */
    size_t line_length;
    size_t mem_len;        /* smem_len: bytes from the framebuffer start */
    size_t base_off;       /* base - framebuffer start */
    struct fb_var_screeninfo var;
    struct fb_fix_screeninfo fix;
    enum pack_kind kind;
    unsigned bytes_pp;     /* 1..4 (0 for mono) */
    int lsb_first, on_is_one;
    uint32_t lut[256];     /* grey level -> pixel value (index and fields) */
    uint32_t transp_bits;
    struct fb_cmap saved;  /* colour map to put back (len 0: none) */
    uint16_t *saved_mem;
    int console_switched;
};

/* ------------------------------------------------------------ messages */

/* ------------------------------------------------------------ console */

/* One VT per process; the state is global because signal handlers and
 * atexit need it. */
static volatile sig_atomic_t g_vt_active;
static int g_vt_fd = -1;
static int g_vt_old_mode = KD_TEXT;
static int g_atexit_done;
static const int g_signals[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT};
#define NSIG_HANDLED (sizeof g_signals / sizeof g_signals[0])
static struct sigaction g_old_actions[NSIG_HANDLED];

static void vt_restore_mode(void)
{
    if (g_vt_active) {
        g_vt_active = 0;
        (void)ioctl(g_vt_fd, KDSETMODE, g_vt_old_mode);
    }
}

static void vt_signal(int sig)
{
    size_t i;
    int saved_errno = errno;
    vt_restore_mode();
    for (i = 0; i < NSIG_HANDLED; i++)
        if (g_signals[i] == sig)
            (void)sigaction(sig, &g_old_actions[i], NULL);
    errno = saved_errno;
    (void)raise(sig); /* delivered when this handler returns */
}

static void vt_atexit(void)
{
    vt_restore_mode();
}

static void vt_release(void)
{
    size_t i;
    if (g_vt_fd < 0)
        return;
    vt_restore_mode();
    for (i = 0; i < NSIG_HANDLED; i++)
        (void)sigaction(g_signals[i], &g_old_actions[i], NULL);
    close(g_vt_fd);
    g_vt_fd = -1;
}

/* 1: switched, 0: skipped quietly, -1: error (message written). */
static int vt_take(const char *tty, char *err, size_t errlen)
{
    const char *path = tty ? tty : "/dev/tty0";
    int explicit_tty = tty != NULL;
    int fd, mode = 0;
    size_t i;
    struct sigaction sa;

    if (tty && tty[0] == '\0')
        return 0;
    if (g_vt_fd >= 0) {
        if (!explicit_tty)
            return 0;
        stp_error_set(err, errlen, "%s: the console is already held by another framebuffer", path);
        return -1;
    }
    fd = open(path, O_RDWR | O_NOCTTY | O_CLOEXEC);
    if (fd < 0) {
        if (!explicit_tty)
            return 0;
        stp_error_set(err, errlen, "%s: cannot open: %s", path, strerror(errno));
        return -1;
    }
    if (ioctl(fd, KDGETMODE, &mode) != 0) {
        int e = errno;
        close(fd);
        if (!explicit_tty)
            return 0;
        stp_error_set(err, errlen, "%s: not a virtual terminal (KDGETMODE: %s)", path, strerror(e));
        return -1;
    }
    g_vt_fd = fd;
    g_vt_old_mode = mode;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = vt_signal;
    sigemptyset(&sa.sa_mask);
    for (i = 0; i < NSIG_HANDLED; i++)
        (void)sigaction(g_signals[i], &sa, &g_old_actions[i]);
    if (!g_atexit_done && atexit(vt_atexit) == 0)
        g_atexit_done = 1;
    if (mode != KD_GRAPHICS) {
        if (ioctl(fd, KDSETMODE, KD_GRAPHICS) != 0) {
            int e = errno;
            vt_release();
            if (!explicit_tty)
                return 0;
            stp_error_set(err, errlen, "%s: KDSETMODE KD_GRAPHICS: %s", path, strerror(e));
            return -1;
        }
        g_vt_active = 1;
    }
    return 1;
}

/* ------------------------------------------------------------ formats */

static uint32_t scale_level(unsigned g, unsigned bits)
{
    uint32_t max;
    if (bits == 0)
        return 0;
    if (bits > 16)
        bits = 16; /* no real device has more; keep the arithmetic in range */
    max = (1u << bits) - 1u;
    return (g * max + 127u) / 255u;
}

static const char *visual_name(uint32_t v)
{
    switch (v) {
    case FB_VISUAL_MONO01: return "MONO01";
    case FB_VISUAL_MONO10: return "MONO10";
    case FB_VISUAL_TRUECOLOR: return "TRUECOLOR";
    case FB_VISUAL_PSEUDOCOLOR: return "PSEUDOCOLOR";
    case FB_VISUAL_DIRECTCOLOR: return "DIRECTCOLOR";
    case FB_VISUAL_STATIC_PSEUDOCOLOR: return "STATIC_PSEUDOCOLOR";
    case FB_VISUAL_FOURCC: return "FOURCC";
    default: return "unknown";
    }
}

static int put_cmap(stp_linuxfb *fb, uint32_t len, uint16_t *r, uint16_t *g, uint16_t *b)
{
    struct fb_cmap cm;
    memset(&cm, 0, sizeof cm);
    cm.start = 0;
    cm.len = len;
    cm.red = r;
    cm.green = g;
    cm.blue = b;
    return ioctl(fb->fd, FBIOPUTCMAP, &cm);
}

/* Reads the current colour map (len entries) into fb->saved. */
static int save_cmap(stp_linuxfb *fb, uint32_t len)
{
    fb->saved_mem = calloc((size_t)len * 3u, sizeof(uint16_t));
    if (!fb->saved_mem)
        return -1;
    memset(&fb->saved, 0, sizeof fb->saved);
    fb->saved.len = len;
    fb->saved.red = fb->saved_mem;
    fb->saved.green = fb->saved_mem + len;
    fb->saved.blue = fb->saved_mem + 2u * len;
    if (ioctl(fb->fd, FBIOGETCMAP, &fb->saved) != 0) {
        free(fb->saved_mem);
        fb->saved_mem = NULL;
        fb->saved.len = 0;
        return -1;
    }
    return 0;
}

/* Loads a ramp of len entries, entry i = i * 65535 / (len - 1) on all
 * three channels.  (For 1 bpp pseudocolour this gives black, white.) */
static int load_ramp(stp_linuxfb *fb, uint32_t len, const char *path, char *err, size_t errlen)
{
    uint16_t *ramp;
    uint32_t i;
    int rc;
    if (len < 2 || len > 256) {
        stp_error_set(err, errlen, "%s: colour map of %u entries not supported", path, (unsigned)len);
        return -1;
    }
    (void)save_cmap(fb, len); /* not fatal: some drivers cannot read it */
    ramp = malloc(len * sizeof *ramp);
    if (!ramp) {
        stp_error_set(err, errlen, "%s: out of memory", path);
        return -1;
    }
    for (i = 0; i < len; i++)
        ramp[i] = (uint16_t)((i * 65535u) / (len - 1u));
    rc = put_cmap(fb, len, ramp, ramp, ramp);
    free(ramp);
    if (rc != 0) {
        stp_error_set(err, errlen, "%s: FBIOPUTCMAP (grey ramp of %u entries): %s", path,
                (unsigned)len, strerror(errno));
        return -1;
    }
    return 0;
}

/* Static pseudocolour: grey level -> nearest entry by luminance. */
static int static_map(stp_linuxfb *fb, const char *path, char *err, size_t errlen)
{
    uint32_t len = 1u << fb->var.bits_per_pixel, i, g;
    struct fb_cmap cm;
    uint16_t *mem = calloc((size_t)len * 3u, sizeof(uint16_t));
    if (!mem) {
        stp_error_set(err, errlen, "%s: out of memory", path);
        return -1;
    }
    memset(&cm, 0, sizeof cm);
    cm.len = len;
    cm.red = mem;
    cm.green = mem + len;
    cm.blue = mem + 2u * len;
    if (ioctl(fb->fd, FBIOGETCMAP, &cm) != 0) {
        stp_error_set(err, errlen, "%s: STATIC_PSEUDOCOLOR but FBIOGETCMAP failed: %s", path,
                strerror(errno));
        free(mem);
        return -1;
    }
    for (g = 0; g < 256; g++) {
        uint32_t best = 0;
        unsigned long best_d = (unsigned long)-1;
        for (i = 0; i < len; i++) {
            /* BT.601 luminance of the entry, on 0..255 */
            unsigned long y = (299ul * (cm.red[i] >> 8) + 587ul * (cm.green[i] >> 8) +
                               114ul * (cm.blue[i] >> 8) + 500ul) / 1000ul;
            unsigned long d = y > g ? y - g : g - y;
            if (d < best_d) {
                best_d = d;
                best = i;
            }
        }
        fb->lut[g] = best;
    }
    free(mem);
    return 0;
}

static int setup_format(stp_linuxfb *fb, const stp_linuxfb_options *opt, const char *path,
                        char *err, size_t errlen)
{
    struct fb_var_screeninfo *v = &fb->var;
    uint32_t bpp = v->bits_per_pixel, visual = fb->fix.visual;
    unsigned g;

    if (fb->fix.type != FB_TYPE_PACKED_PIXELS) {
        stp_error_set(err, errlen, "%s: unsupported framebuffer type %u (only packed pixels)", path,
                (unsigned)fb->fix.type);
        return -1;
    }
    if (bpp == 1) {
        int reverse = (v->nonstd & FB_NONSTD_REV_PIX_IN_B) != 0;
        fb->kind = PACK_MONO;
        fb->bytes_pp = 0;
        switch (opt->bit_order) {
        case STP_LINUXFB_BITS_LSB_FIRST: fb->lsb_first = 1; break;
        case STP_LINUXFB_BITS_MSB_FIRST: fb->lsb_first = 0; break;
        default: {
            const uint16_t probe = 1;
            int little = *(const uint8_t *)&probe == 1;
            fb->lsb_first = reverse ? !little : little;
        }
        }
        if (visual == FB_VISUAL_MONO10)
            fb->on_is_one = 1;
        else if (visual == FB_VISUAL_MONO01)
            fb->on_is_one = 0;
        else if (visual == FB_VISUAL_PSEUDOCOLOR) {
            if (load_ramp(fb, 2, path, err, errlen) != 0)
                return -1;
            fb->on_is_one = 1;
        } else {
            stp_error_set(err, errlen, "%s: unsupported 1 bpp visual %s", path, visual_name(visual));
            return -1;
        }
        return 0;
    }
    if (bpp != 8 && bpp != 16 && bpp != 24 && bpp != 32) {
        stp_error_set(err, errlen, "%s: unsupported depth %u bits per pixel (visual %s)", path,
                (unsigned)bpp, visual_name(visual));
        return -1;
    }
    fb->bytes_pp = bpp / 8u;
    if (visual == FB_VISUAL_PSEUDOCOLOR && bpp == 8) {
        if (load_ramp(fb, 256, path, err, errlen) != 0)
            return -1;
        fb->kind = PACK_INDEX;
        for (g = 0; g < 256; g++)
            fb->lut[g] = g;
        return 0;
    }
    if (visual == FB_VISUAL_STATIC_PSEUDOCOLOR && bpp == 8) {
        fb->kind = PACK_INDEX;
        return static_map(fb, path, err, errlen);
    }
    if (visual == FB_VISUAL_TRUECOLOR || visual == FB_VISUAL_DIRECTCOLOR) {
        const struct fb_bitfield *f[4];
        int i;
        f[0] = &v->red;
        f[1] = &v->green;
        f[2] = &v->blue;
        f[3] = &v->transp;
        for (i = 0; i < 4; i++) {
            if (f[i]->length > 0 &&
                (f[i]->msb_right != 0 || f[i]->length > 16 || f[i]->offset + f[i]->length > bpp)) {
                stp_error_set(err, errlen,
                        "%s: unsupported %u bpp bitfields (red %u:%u green %u:%u blue %u:%u%s)",
                        path, (unsigned)bpp, (unsigned)v->red.offset, (unsigned)v->red.length,
                        (unsigned)v->green.offset, (unsigned)v->green.length,
                        (unsigned)v->blue.offset, (unsigned)v->blue.length,
                        f[i]->msb_right ? ", msb_right" : "");
                return -1;
            }
        }
        if (v->red.length == 0 || v->green.length == 0 || v->blue.length == 0) {
            stp_error_set(err, errlen, "%s: %u bpp %s without colour bitfields", path, (unsigned)bpp,
                    visual_name(visual));
            return -1;
        }
        if (visual == FB_VISUAL_DIRECTCOLOR) {
            /* one ramp per channel, as long as the longest field */
            uint32_t len = v->red.length;
            if (v->green.length > len)
                len = v->green.length;
            if (v->blue.length > len)
                len = v->blue.length;
            if (len > 8) {
                stp_error_set(err, errlen, "%s: DIRECTCOLOR fields over 8 bits not supported", path);
                return -1;
            }
            if (load_ramp(fb, 1u << len, path, err, errlen) != 0)
                return -1;
        }
        fb->kind = PACK_FIELDS;
        fb->transp_bits = v->transp.length ? (uint32_t)(((1u << v->transp.length) - 1u)
                                                        << v->transp.offset) : 0u;
        for (g = 0; g < 256; g++)
            fb->lut[g] = (scale_level(g, v->red.length) << v->red.offset) |
                         (scale_level(g, v->green.length) << v->green.offset) |
                         (scale_level(g, v->blue.length) << v->blue.offset) | fb->transp_bits;
        return 0;
    }
    stp_error_set(err, errlen, "%s: unsupported visual %s at %u bpp", path, visual_name(visual),
            (unsigned)bpp);
    return -1;
}

/* ------------------------------------------------------------ drawing */

static void put_pixel(stp_linuxfb *fb, uint8_t *row, uint32_t x, uint32_t value)
{
    switch (fb->bytes_pp) {
    case 1:
        row[x] = (uint8_t)value;
        break;
    case 2: {
        uint16_t v = (uint16_t)value;
        memcpy(row + 2u * x, &v, 2);
        break;
    }
    case 3: {
        /* the value's three low bytes in the CPU's order */
        const uint16_t probe = 1;
        uint8_t *p = row + 3u * x;
        if (*(const uint8_t *)&probe == 1) {
            p[0] = (uint8_t)value;
            p[1] = (uint8_t)(value >> 8);
            p[2] = (uint8_t)(value >> 16);
        } else {
            p[0] = (uint8_t)(value >> 16);
            p[1] = (uint8_t)(value >> 8);
            p[2] = (uint8_t)value;
        }
        break;
    }
    default:
        memcpy(row + 4u * x, &value, 4);
        break;
    }
}

static void put_mono(stp_linuxfb *fb, uint8_t *row, uint32_t x, int on)
{
    uint32_t xx = x + fb->var.xoffset; /* bit position counts from the fb's row start */
    uint8_t mask = fb->lsb_first ? (uint8_t)(1u << (xx & 7u)) : (uint8_t)(0x80u >> (xx & 7u));
    uint8_t *p = row + (xx >> 3);
    if ((on != 0) == (fb->on_is_one != 0))
        *p = (uint8_t)(*p | mask);
    else
        *p = (uint8_t)(*p & ~mask);
}

/* Source pixel x of a row as a grey level (0..255) and, for RGB888, colour. */
static void fetch(stp_pixel_format fmt, const uint8_t *src, uint32_t x, unsigned rgb[3])
{
    switch (fmt) {
    case STP_PIXEL_MONO1:
        rgb[0] = rgb[1] = rgb[2] = (src[x >> 3] & (0x80u >> (x & 7u))) ? 255u : 0u;
        break;
    case STP_PIXEL_RGB888:
        rgb[0] = src[3u * x];
        rgb[1] = src[3u * x + 1u];
        rgb[2] = src[3u * x + 2u];
        break;
    default:
        rgb[0] = rgb[1] = rgb[2] = src[x];
        break;
    }
}

static unsigned luma(const unsigned rgb[3])
{
    return (299u * rgb[0] + 587u * rgb[1] + 114u * rgb[2] + 500u) / 1000u;
}

static void draw_row(stp_linuxfb *fb, uint8_t *dst, const uint8_t *src)
{
    uint32_t x, w = fb->port.width;
    unsigned rgb[3];
    const struct fb_var_screeninfo *v = &fb->var;

    if (fb->kind == PACK_MONO) {
        for (x = 0; x < w; x++) {
            fetch(fb->port.format, src, x, rgb);
            put_mono(fb, dst, x, luma(rgb) >= 128u);
        }
        return;
    }
    /* byte-addressed formats: column offset of the panning origin */
    dst += (size_t)v->xoffset * fb->bytes_pp;
    if (fb->kind == PACK_FIELDS && fb->port.format == STP_PIXEL_RGB888) {
        for (x = 0; x < w; x++) {
            fetch(fb->port.format, src, x, rgb);
            put_pixel(fb, dst, x,
                      (scale_level(rgb[0], v->red.length) << v->red.offset) |
                          (scale_level(rgb[1], v->green.length) << v->green.offset) |
                          (scale_level(rgb[2], v->blue.length) << v->blue.offset) |
                          fb->transp_bits);
        }
        return;
    }
    if (fb->port.format == STP_PIXEL_GREY8 && fb->bytes_pp == 1 && fb->kind == PACK_INDEX) {
        for (x = 0; x < w; x++)
            dst[x] = (uint8_t)fb->lut[src[x]];
        return;
    }
    for (x = 0; x < w; x++) {
        fetch(fb->port.format, src, x, rgb);
        put_pixel(fb, dst, x, fb->lut[luma(rgb)]);
    }
}

static int fb_flush(stp_port *port, uint32_t y0, uint32_t rows, const uint8_t *pixels,
                    size_t stride)
{
    stp_linuxfb *fb = port->user;
    size_t need = stp_row_bytes(port->format, port->width);
    uint32_t r;
    if (!fb || !pixels || y0 > port->height || rows > port->height - y0)
        return -1;
    if (rows > 1 && stride < need)
        return -1;
    for (r = 0; r < rows; r++)
        draw_row(fb, fb->base + (size_t)(y0 + r) * fb->line_length, pixels + (size_t)r * stride);
    return 0;
}

void stp_linuxfb_clear(stp_linuxfb *fb)
{
    uint32_t y, x;
    if (!fb)
        return;
    for (y = 0; y < fb->var.yres; y++) {
        uint8_t *row = fb->base + (size_t)y * fb->line_length;
        if (fb->kind == PACK_MONO) {
            for (x = 0; x < fb->var.xres; x++)
                put_mono(fb, row, x, 0);
        } else {
            uint8_t *d = row + (size_t)fb->var.xoffset * fb->bytes_pp;
            for (x = 0; x < fb->var.xres; x++)
                put_pixel(fb, d, x, fb->lut[0]);
        }
    }
}

/* ------------------------------------------------------------ open/close */

void stp_linuxfb_options_default(stp_linuxfb_options *opt)
{
    memset(opt, 0, sizeof *opt);
    opt->format = STP_LINUXFB_FORMAT_AUTO;
    opt->clear = 1;
    opt->bit_order = STP_LINUXFB_BITS_AUTO;
    opt->tty = NULL;
}

stp_linuxfb *stp_linuxfb_open(const char *path, const stp_linuxfb_options *opt_in,
                              char *err, size_t errlen)
{
    stp_linuxfb_options defaults;
    const stp_linuxfb_options *opt = opt_in;
    stp_linuxfb *fb;
    long page = sysconf(_SC_PAGESIZE);
    size_t in_page, start;
    int fmt;

    if (err && errlen)
        err[0] = '\0';
    if (!path) {
        stp_error_set(err, errlen, "no framebuffer device given");
        return NULL;
    }
    if (!opt) {
        stp_linuxfb_options_default(&defaults);
        opt = &defaults;
    }
    if (page <= 0)
        page = 4096;
    fb = calloc(1, sizeof *fb);
    if (!fb) {
        stp_error_set(err, errlen, "%s: out of memory", path);
        return NULL;
    }
    fb->fd = open(path, O_RDWR | O_CLOEXEC);
    if (fb->fd < 0) {
        stp_error_set(err, errlen, "%s: cannot open: %s", path, strerror(errno));
        free(fb);
        return NULL;
    }
    if (ioctl(fb->fd, FBIOGET_VSCREENINFO, &fb->var) != 0 ||
        ioctl(fb->fd, FBIOGET_FSCREENINFO, &fb->fix) != 0) {
        stp_error_set(err, errlen, "%s: not a framebuffer (FBIOGET_*SCREENINFO: %s)", path,
                strerror(errno));
        goto fail;
    }
    if (fb->var.xres == 0 || fb->var.yres == 0 || fb->fix.line_length == 0) {
        stp_error_set(err, errlen, "%s: device reports an empty screen (%ux%u, line %u bytes)", path,
                (unsigned)fb->var.xres, (unsigned)fb->var.yres, (unsigned)fb->fix.line_length);
        goto fail;
    }
    if (setup_format(fb, opt, path, err, errlen) != 0)
        goto fail;

    fmt = opt->format;
    if (fmt == STP_LINUXFB_FORMAT_AUTO)
        fmt = fb->kind == PACK_MONO ? STP_PIXEL_MONO1 : STP_PIXEL_GREY8;
    if (fmt != STP_PIXEL_MONO1 && fmt != STP_PIXEL_GREY8 && fmt != STP_PIXEL_RGB888) {
        stp_error_set(err, errlen, "%s: render format %d not supported (MONO1, GREY8 or RGB888)",
                path, fmt);
        goto fail;
    }
    fb->port.format = (stp_pixel_format)fmt;
    fb->port.width = opt->width ? opt->width : fb->var.xres;
    fb->port.height = opt->height ? opt->height : fb->var.yres;
    if (fb->port.width > fb->var.xres || fb->port.height > fb->var.yres ||
        fb->port.width > 32767u || fb->port.height > 32767u) {
        stp_error_set(err, errlen, "%s: %ux%u does not fit the %ux%u screen (or exceeds 32767)", path,
                (unsigned)fb->port.width, (unsigned)fb->port.height, (unsigned)fb->var.xres,
                (unsigned)fb->var.yres);
        goto fail;
    }
    fb->port.flush = fb_flush;
    fb->port.user = fb;

    /* the visible area must lie inside the memory the driver exports */
    fb->line_length = fb->fix.line_length;
    fb->mem_len = fb->fix.smem_len;
    fb->base_off = (size_t)fb->var.yoffset * fb->line_length;
    {
        size_t last = fb->base_off + (size_t)(fb->var.yres - 1u) * fb->line_length +
                      (((size_t)fb->var.xoffset + fb->var.xres) * fb->var.bits_per_pixel + 7u) / 8u;
        if (fb->mem_len == 0 || last > fb->mem_len) {
            stp_error_set(err, errlen,
                    "%s: visible area (%ux%u at +%u+%u, line %u bytes) outside the %lu bytes "
                    "of video memory", path, (unsigned)fb->var.xres, (unsigned)fb->var.yres,
                    (unsigned)fb->var.xoffset, (unsigned)fb->var.yoffset,
                    (unsigned)fb->fix.line_length, (unsigned long)fb->mem_len);
            goto fail;
        }
    }
    in_page = (size_t)(fb->fix.smem_start & (unsigned long)(page - 1));
    start = in_page;
    fb->map_len = (fb->mem_len + in_page + (size_t)page - 1u) & ~((size_t)page - 1u);
    fb->map = mmap(NULL, fb->map_len, PROT_READ | PROT_WRITE, MAP_SHARED, fb->fd, 0);
    if (fb->map == MAP_FAILED) {
        fb->map = NULL;
        stp_error_set(err, errlen, "%s: mmap of %lu bytes: %s", path, (unsigned long)fb->map_len,
                strerror(errno));
        goto fail;
    }
    fb->base = fb->map + start + fb->base_off;

    {
        int vt = vt_take(opt->tty, err, errlen);
        if (vt < 0)
            goto fail;
        fb->console_switched = vt == 1; /* this device holds the console */
    }
    if (opt->clear)
        stp_linuxfb_clear(fb);
    return fb;

fail:
    stp_linuxfb_close(fb);
    return NULL;
}

stp_port *stp_linuxfb_port(stp_linuxfb *fb)
{
    return fb ? &fb->port : NULL;
}

void stp_linuxfb_get_info(const stp_linuxfb *fb, stp_linuxfb_info *info)
{
    memset(info, 0, sizeof *info);
    if (!fb)
        return;
    memcpy(info->id, fb->fix.id, sizeof fb->fix.id);
    info->id[16] = '\0';
    info->xres = fb->var.xres;
    info->yres = fb->var.yres;
    info->xoffset = fb->var.xoffset;
    info->yoffset = fb->var.yoffset;
    info->bits_per_pixel = fb->var.bits_per_pixel;
    info->line_length = fb->fix.line_length;
    info->visual = fb->fix.visual;
    info->grayscale = fb->var.grayscale;
    info->red_offset = fb->var.red.offset;
    info->red_length = fb->var.red.length;
    info->green_offset = fb->var.green.offset;
    info->green_length = fb->var.green.length;
    info->blue_offset = fb->var.blue.offset;
    info->blue_length = fb->var.blue.length;
    info->transp_offset = fb->var.transp.offset;
    info->transp_length = fb->var.transp.length;
    info->lsb_first = fb->lsb_first;
    info->on_is_one = fb->on_is_one;
    info->format = fb->port.format;
    info->console_switched = fb->console_switched;
}

void stp_linuxfb_close(stp_linuxfb *fb)
{
    if (!fb)
        return;
    if (fb->map)
        (void)msync(fb->map, fb->map_len, MS_SYNC);
    if (fb->console_switched)
        vt_release();
    if (fb->saved_mem) {
        (void)ioctl(fb->fd, FBIOPUTCMAP, &fb->saved);
        free(fb->saved_mem);
    }
    if (fb->map)
        munmap(fb->map, fb->map_len);
    if (fb->fd >= 0)
        close(fb->fd);
    free(fb);
}
