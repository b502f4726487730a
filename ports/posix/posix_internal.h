/* SPDX-License-Identifier: MIT */
/*
 * Private to the POSIX port: shared between its source files, not installed.
 */
#ifndef STP_POSIX_INTERNAL_H
#define STP_POSIX_INTERNAL_H

#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "stp_posix.h"

#if defined(__GNUC__)
#define STP_POSIX_PRINTF(a, b) __attribute__((format(printf, a, b)))
#else
#define STP_POSIX_PRINTF(a, b)
#endif

/* Packed bytes per row of width pixels in fmt, 0 for an unknown format.
 * The port's own copy of the core's stp_row_bytes, so that this library
 * links without the core. */
size_t stp_posix_priv_row_bytes(stp_pixel_format fmt, uint32_t width);

/* Formats a message into err (if err && errlen), always NUL-terminated. */
void stp_posix_priv_error(char *err, size_t errlen, const char *fmt, ...)
    STP_POSIX_PRINTF(3, 4);

/* Human-readable names for messages. */
const char *stp_posix_priv_format_name(stp_pixel_format fmt);
const char *stp_posix_priv_kind_name(stp_posix_file_kind kind);

/* Encoders: f is a valid frame and kind accepts its format (the caller
 * checked).  Return 0, or -1 with errno set by the stream. */
int stp_posix_priv_encode_pnm(const stp_posix_frame *f, stp_posix_file_kind kind, FILE *out);
int stp_posix_priv_encode_ascii(const stp_posix_frame *f, FILE *out);

#endif
