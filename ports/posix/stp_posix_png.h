/* SPDX-License-Identifier: MIT */
/*
 * stipple POSIX port: PNG output and input through libpng (Debian's
 * libpng-dev).  A library of its own (stipple_posix_png), so that users of
 * the PNM port do not need libpng.
 *
 * Conventions as in stp_posix.h: 0 on success, -1 on failure with a
 * one-line message "<path>: <what is wrong>" in err (truncated to errlen,
 * always NUL-terminated; err may be NULL or errlen 0).
 */
#ifndef STP_POSIX_PNG_H
#define STP_POSIX_PNG_H

#include <stddef.h>

#include "stp_posix.h"

#ifdef __cplusplus
extern "C" {
#endif

/* 1 if path ends in ".png" (case-insensitive), else 0 (also for NULL). */
int stp_posix_png_path(const char *path);

/* Writes frame f as a PNG file: MONO1 as 1-bit grey (ON, light, is white:
 * PNG's 1), GREY8 as 8-bit grey, RGB888 as 8-bit RGB; not interlaced, no
 * gamma chunk.  STYLE8 frames are refused (their bytes are style codes, not
 * light).  path "-" writes to stdout; any other path is replaced atomically
 * exactly as stp_posix_write_file does (temporary file, fsync, rename), so
 * an existing file is untouched on any failure. */
int stp_posix_write_png(const stp_posix_frame *f, const char *path, char *err, size_t errlen);

/* Encodes f as PNG onto an open stream (no flush, no close).  Returns 0, or
 * -1 with errno EINVAL (bad frame or STYLE8), ENOMEM, or the stream's error
 * (EIO when it gives none). */
int stp_posix_encode_png(const stp_posix_frame *f, FILE *out);

/* Reads a PNG file ("-": stdin) into 8-bit samples: grey files (any bit
 * depth) give channels 1, colour and palette files channels 3; 16-bit
 * samples are scaled to 8 bits with rounding (libpng's png_set_scale_16),
 * 1/2/4-bit grey to 0..255, palettes expanded; an alpha channel or tRNS
 * transparency is dropped (the colour samples are kept as they are).  With
 * grey set, colour is turned into grey exactly as stp_posix_read_grey does
 * (BT.601 weights 0.299, 0.587, 0.114 on the 8-bit samples, rounded).
 * img->pnm_type is 0 and img->maxval 255.  Width and height are limited to
 * 1..32767.  Errors: cannot open; not a PNG file; whatever libpng finds
 * (bad CRC, truncated data, ...), with libpng's message; out of memory. */
int stp_posix_read_png(const char *path, stp_posix_image *img, int grey, char *err,
                       size_t errlen);

/* Reads a PNG or a PNM file, told apart by their first byte (PNG's 0x89,
 * PNM's 'P'), as grey (stp_posix_read_grey for PNM).  path "-": stdin. */
int stp_posix_read_image_grey(const char *path, stp_posix_image *img, char *err, size_t errlen);

#ifdef __cplusplus
}
#endif

#endif
