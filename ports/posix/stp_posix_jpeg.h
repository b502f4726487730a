/* SPDX-License-Identifier: MIT */
/*
 * stipple POSIX port: JPEG input through libjpeg (Debian's
 * libjpeg62-turbo-dev).  A library of its own (stipple_posix_jpeg), built
 * when libjpeg is found.  Conventions as in stp_posix.h.
 */
#ifndef STP_POSIX_JPEG_H
#define STP_POSIX_JPEG_H

#include <stddef.h>

#include "stp_posix.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Reads a baseline or progressive JPEG file ("-": stdin) into 8-bit
 * samples: channels 1 with grey set (libjpeg's own colour-to-grey, the
 * BT.601 luminance of the decoded YCbCr) or for a greyscale file, else 3
 * (RGB; CMYK files are refused).  img->pnm_type 0, maxval 255.  Width and
 * height 1..32767.  Errors: cannot open; not a JPEG file or corrupt data,
 * with libjpeg's message; out of memory. */
int stp_posix_read_jpeg(const char *path, stp_posix_image *img, int grey, char *err, size_t errlen);

#ifdef __cplusplus
}
#endif

#endif
