/* SPDX-License-Identifier: MIT */
/*
 * stipple POSIX port: 1-bit frames as C source for firmware: XBM (what
 * u8g2's drawXBM/drawXBMP take), a byte array of rows (Adafruit GFX
 * drawBitmap, u8g2 drawBitmap) and a byte array of SSD1306 pages (the
 * controller's GDDRAM, to send as it is).  In every layout a set bit is a
 * lit pixel (MONO1's ON).
 *
 * Conventions as in stp_posix.h: 0 on success, -1 on failure with a
 * one-line message "<path>: <what is wrong>" in err.
 */
#ifndef STP_POSIX_BITMAP_H
#define STP_POSIX_BITMAP_H

#include <stddef.h>

#include "stp_posix.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum stp_posix_bitmap_layout {
    /* X11 bitmap: NAME_width, NAME_height, NAME_bits[]; rows top first,
     * (width + 7) / 8 bytes a row, the leftmost pixel in the least
     * significant bit */
    STP_POSIX_BITMAP_XBM,
    /* NAME_WIDTH, NAME_HEIGHT, NAME[]: rows top first, (width + 7) / 8
     * bytes a row, the leftmost pixel in the most significant bit */
    STP_POSIX_BITMAP_ROWS,
    /* NAME_WIDTH, NAME_HEIGHT, NAME[]: (height + 7) / 8 pages of width
     * bytes, page p holding rows 8p..8p+7: bit k of byte x of page p is the
     * pixel (x, 8p + k), rows past the bottom unlit */
    STP_POSIX_BITMAP_PAGES
} stp_posix_bitmap_layout;

/* The layout a file name asks for: ".xbm" XBM, ".h" rows; -1 otherwise. */
int stp_posix_bitmap_layout_from_path(const char *path);

/* The array's name from path: its base name without the extension, every
 * character that may not stand in a C identifier replaced by '_', and '_'
 * before a leading digit ("img" when nothing is left).  Truncated to size. */
void stp_posix_bitmap_name(const char *path, char *name, size_t size);

/* Writes MONO1 frame f to path ("-": stdout) as C source in layout, the
 * array named after path (stp_posix_bitmap_name); replaced atomically as
 * stp_posix_write_file does.  Errors: not a MONO1 frame, I/O. */
int stp_posix_write_bitmap(const stp_posix_frame *f, const char *path, stp_posix_bitmap_layout layout,
                           char *err, size_t errlen);

#ifdef __cplusplus
}
#endif

#endif
