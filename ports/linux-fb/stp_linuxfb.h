/* SPDX-License-Identifier: MIT */
/*
 * Linux framebuffer (fbdev) port: draws the renderer's bands straight into
 * the memory of /dev/fbN.
 *
 * Opening a device reads FBIOGET_VSCREENINFO and FBIOGET_FSCREENINFO, maps
 * the framebuffer (mmap of smem_len, the in-page offset of smem_start
 * honoured), and sets up an stp_port whose flush converts each band into the
 * device's pixel format, row by row, fix.line_length bytes apart, starting at
 * the panning origin (var.xoffset, var.yoffset).
 *
 * Render format (what the port asks the core for): MONO1 (halftoned by the
 * core) for 1 bpp devices, GREY8 for everything else; a caller may ask for
 * MONO1, GREY8 or RGB888 on any device instead (options.format).
 *
 * Device formats (fix.type must be FB_TYPE_PACKED_PIXELS):
 *  - 1 bpp, visual MONO10 (1 = white) or MONO01 (1 = black): stipple's ON
 *    (light) pixel is written as 1 on MONO10 and as 0 on MONO01.  Bit order
 *    inside a byte follows the kernel's own fbdev drawing code (cfb/sys
 *    helpers, fb_be_math()): on a little-endian CPU pixel x is bit (x % 8)
 *    (least significant bit first, as ssd1307fb and vfb are read), on a
 *    big-endian CPU bit 7 - (x % 8); var.nonstd & FB_NONSTD_REV_PIX_IN_B
 *    reverses that.  options.bit_order overrides it for odd drivers.
 *    Visual PSEUDOCOLOR at 1 bpp gets the colour map 0 = black, 1 = white.
 *    A grey or colour source on a mono device is thresholded at half
 *    intensity (the core's halftoning is what MONO1 is for).
 *  - 8 bpp PSEUDOCOLOR (and any visual with var.grayscale == 1): pixel value
 *    = grey level, after loading the grey ramp entry i = (i, i, i) * 257
 *    with FBIOPUTCMAP (the old map is read first and put back on close).
 *    STATIC_PSEUDOCOLOR: the fixed map is read with FBIOGETCMAP and each
 *    grey level goes to the entry nearest in luminance.
 *  - TRUECOLOR at 8, 16, 24 or 32 bpp: the var.red/green/blue bitfields
 *    (offset, length; msb_right must be 0).  A level g (0..255) becomes
 *    round(g * (2^length - 1) / 255) in each field; transp bits, if any, are
 *    all set (opaque).  RGB565, ARGB1555, RGB888, XRGB8888, BGR variants all
 *    come from the same code.  Pixels are stored in the CPU's byte order
 *    (24 bpp: the 3 low bytes of the value, in that order).
 *  - DIRECTCOLOR: as TRUECOLOR after loading a linear ramp per channel.
 * Anything else (planar, interleaved, FOURCC, 2/4/12 bpp, msb_right fields)
 * fails to open with a message naming what the device has.
 *
 * Console: while the port is open the virtual terminal (options.tty,
 * default /dev/tty0 = the foreground VT) is put in KD_GRAPHICS mode so that
 * fbcon neither draws text nor blinks its cursor over the picture.  The old
 * mode is put back by stp_linuxfb_close, at exit() and on SIGINT, SIGTERM,
 * SIGHUP and SIGQUIT (the handler restores the mode, then re-raises the
 * signal with the action that was there before).  Only one device per
 * process may hold the console.  A tty that cannot be opened or is not a VT
 * is skipped unless it was named explicitly.
 *
 * Host code (libc, POSIX, Linux ioctls).  Functions that can fail return
 * NULL or -1 and write a one-line message into err (errlen bytes, always
 * NUL-terminated; err may be NULL).
 */
#ifndef STP_LINUXFB_H
#define STP_LINUXFB_H

#include <stddef.h>
#include <stdint.h>

#include "stipple/port.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum stp_linuxfb_bit_order {
    STP_LINUXFB_BITS_AUTO = 0,  /* the kernel's convention (see above) */
    STP_LINUXFB_BITS_LSB_FIRST, /* pixel x at bit x % 8 */
    STP_LINUXFB_BITS_MSB_FIRST  /* pixel x at bit 7 - x % 8 */
} stp_linuxfb_bit_order;

#define STP_LINUXFB_FORMAT_AUTO (-1)

typedef struct stp_linuxfb_options {
    uint32_t width, height; /* the port's size; 0: the visible xres/yres.
                               Must fit in the visible area; the picture
                               sits at its top-left corner. */
    int format;             /* STP_LINUXFB_FORMAT_AUTO or an stp_pixel_format
                               (MONO1, GREY8, RGB888) */
    int clear;              /* 1: paint the visible area black on open (1) */
    stp_linuxfb_bit_order bit_order; /* 1 bpp only (AUTO) */
    const char *tty;        /* VT to switch to graphics mode: NULL = try
                               /dev/tty0 quietly, "" = leave the console */
} stp_linuxfb_options;

/* What the device is, for messages and tests. */
typedef struct stp_linuxfb_info {
    char id[17];                   /* fix.id */
    uint32_t xres, yres;           /* visible size */
    uint32_t xoffset, yoffset;     /* panning origin */
    uint32_t bits_per_pixel;
    uint32_t line_length;          /* bytes between rows */
    uint32_t visual;               /* FB_VISUAL_* */
    uint32_t grayscale;
    uint32_t red_offset, red_length, green_offset, green_length;
    uint32_t blue_offset, blue_length, transp_offset, transp_length;
    int lsb_first;                 /* 1 bpp: 1 if pixel x is bit x % 8 */
    int on_is_one;                 /* 1 bpp: 1 if a light pixel is bit 1 */
    stp_pixel_format format;       /* what the port asks the core for */
    int console_switched;          /* 1 if a VT was put in graphics mode */
} stp_linuxfb_info;

typedef struct stp_linuxfb stp_linuxfb;

void stp_linuxfb_options_default(stp_linuxfb_options *opt);

/* Opens path (e.g. "/dev/fb0") read-write; opt NULL = defaults. */
stp_linuxfb *stp_linuxfb_open(const char *path, const stp_linuxfb_options *opt,
                              char *err, size_t errlen);

/* The port to hand to the renderer (valid until close).  Its flush returns
 * -1 for a band outside the port or a stride below the packed row size. */
stp_port *stp_linuxfb_port(stp_linuxfb *fb);

void stp_linuxfb_get_info(const stp_linuxfb *fb, stp_linuxfb_info *info);

/* Paints the whole visible area black (level 0; OFF on mono panels). */
void stp_linuxfb_clear(stp_linuxfb *fb);

/* Puts back the colour map and the console mode, unmaps and closes.
 * fb may be NULL. */
void stp_linuxfb_close(stp_linuxfb *fb);

#ifdef __cplusplus
}
#endif

#endif
