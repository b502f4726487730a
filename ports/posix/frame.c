/* SPDX-License-Identifier: MIT */
/*
 * The frame port: gathers a renderer's bands into one buffer, and the
 * dispatch from a frame to the file writers.
 */
#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "posix_internal.h"

#define FRAME_MAX_SIDE 32767u

size_t stp_posix_priv_row_bytes(stp_pixel_format fmt, uint32_t width)
{
    switch (fmt) {
    case STP_PIXEL_MONO1:
        return ((size_t)width + 7u) / 8u;
    case STP_PIXEL_GREY8:
    case STP_PIXEL_STYLE8:
        return (size_t)width;
    case STP_PIXEL_RGB888:
        return (size_t)width * 3u;
    case STP_PIXEL_MONO1_PAGES: /* a panel's layout: posix frames hold rows */
        return 0;
    }
    return 0;
}

void stp_posix_priv_error(char *err, size_t errlen, const char *fmt, ...)
{
    va_list ap;

    if (err == NULL || errlen == 0)
        return;
    va_start(ap, fmt);
    vsnprintf(err, errlen, fmt, ap);
    va_end(ap);
}

const char *stp_posix_priv_format_name(stp_pixel_format fmt)
{
    switch (fmt) {
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
    return "unknown-format";
}

const char *stp_posix_priv_kind_name(stp_posix_file_kind kind)
{
    switch (kind) {
    case STP_POSIX_FILE_P4:
        return "PBM (P4)";
    case STP_POSIX_FILE_P1:
        return "plain PBM (P1)";
    case STP_POSIX_FILE_P5:
        return "PGM (P5)";
    case STP_POSIX_FILE_P6:
        return "PPM (P6)";
    case STP_POSIX_FILE_ASCII:
        return "ASCII text";
    case STP_POSIX_FILE_UNKNOWN:
        break;
    }
    return "unknown file kind";
}

/* Keeps written files independent of whatever the renderer left in the
 * bits past the last pixel of a MONO1 row. */
static void clear_mono_padding(uint8_t *row, uint32_t width)
{
    unsigned spare = width % 8u;

    if (spare != 0)
        row[(width - 1u) / 8u] &= (uint8_t)(0xFFu << (8u - spare));
}

static int frame_flush(stp_port *port, uint32_t y0, uint32_t rows,
                       const uint8_t *pixels, size_t stride)
{
    stp_posix_frame *f;
    uint32_t r;

    if (port == NULL || port->user == NULL)
        return -1;
    f = (stp_posix_frame *)port->user;
    if (f->pixels == NULL)
        return -1;
    if (rows == 0)
        return 0;
    if (pixels == NULL || y0 >= f->height || rows > f->height - y0)
        return -1;
    /* With one row the stride is never used, so any value is fine. */
    if (rows > 1 && stride < f->stride)
        return -1;
    for (r = 0; r < rows; r++) {
        uint8_t *dst = f->pixels + (size_t)(y0 + r) * f->stride;

        memcpy(dst, pixels + (size_t)r * stride, f->stride);
        if (f->format == STP_PIXEL_MONO1)
            clear_mono_padding(dst, f->width);
    }
    f->bands++;
    if (y0 + rows > f->rows_filled)
        f->rows_filled = y0 + rows;
    return 0;
}

int stp_posix_frame_init(stp_posix_frame *f, uint32_t width, uint32_t height,
                         stp_pixel_format fmt)
{
    size_t stride;

    if (f == NULL || width == 0 || height == 0 || width > FRAME_MAX_SIDE ||
        height > FRAME_MAX_SIDE) {
        errno = EINVAL;
        return -1;
    }
    stride = stp_posix_priv_row_bytes(fmt, width);
    if (stride == 0) {
        errno = EINVAL;
        return -1;
    }
    memset(f, 0, sizeof *f);
    /* 32767 rows of 98301 bytes do not fit a 32-bit size_t. */
    if (stride > SIZE_MAX / height) {
        errno = ENOMEM;
        return -1;
    }
    f->pixels = (uint8_t *)calloc(height, stride);
    if (f->pixels == NULL) {
        errno = ENOMEM;
        return -1;
    }
    f->stride = stride;
    f->width = width;
    f->height = height;
    f->format = fmt;
    f->port.width = width;
    f->port.height = height;
    f->port.format = fmt;
    f->port.flush = frame_flush;
    f->port.user = f;
    return 0;
}

stp_port *stp_posix_frame_port(stp_posix_frame *f)
{
    return f != NULL ? &f->port : NULL;
}

void stp_posix_frame_clear(stp_posix_frame *f)
{
    if (f == NULL || f->pixels == NULL)
        return;
    memset(f->pixels, 0, f->stride * f->height);
    f->bands = 0;
    f->rows_filled = 0;
}

void stp_posix_frame_free(stp_posix_frame *f)
{
    if (f == NULL)
        return;
    free(f->pixels);
    memset(f, 0, sizeof *f);
}

/* ASCII lower-casing without the locale: extensions are plain ASCII. */
static int lower_ascii(int c)
{
    return (c >= 'A' && c <= 'Z') ? c - 'A' + 'a' : c;
}

static int has_extension(const char *path, size_t len, const char *ext)
{
    size_t elen = strlen(ext);
    size_t i;

    if (len <= elen)
        return 0;
    for (i = 0; i < elen; i++) {
        if (lower_ascii((unsigned char)path[len - elen + i]) != ext[i])
            return 0;
    }
    /* ".pbm" alone (or "dir/.pbm") is a hidden file's name, not an extension. */
    return path[len - elen - 1] != '/';
}

stp_posix_file_kind stp_posix_kind_from_path(const char *path)
{
    size_t len;

    if (path == NULL)
        return STP_POSIX_FILE_UNKNOWN;
    len = strlen(path);
    if (has_extension(path, len, ".pbm"))
        return STP_POSIX_FILE_P4;
    if (has_extension(path, len, ".pgm"))
        return STP_POSIX_FILE_P5;
    if (has_extension(path, len, ".ppm"))
        return STP_POSIX_FILE_P6;
    if (has_extension(path, len, ".txt"))
        return STP_POSIX_FILE_ASCII;
    return STP_POSIX_FILE_UNKNOWN;
}

stp_posix_file_kind stp_posix_kind_for_format(stp_pixel_format fmt)
{
    switch (fmt) {
    case STP_PIXEL_MONO1:
        return STP_POSIX_FILE_P4;
    case STP_PIXEL_GREY8:
        return STP_POSIX_FILE_P5;
    case STP_PIXEL_RGB888:
        return STP_POSIX_FILE_P6;
    case STP_PIXEL_STYLE8:
        return STP_POSIX_FILE_ASCII;
    case STP_PIXEL_MONO1_PAGES: /* no file holds pages */
        return STP_POSIX_FILE_UNKNOWN;
    }
    return STP_POSIX_FILE_UNKNOWN;
}

int stp_posix_kind_accepts(stp_posix_file_kind kind, stp_pixel_format fmt)
{
    switch (kind) {
    case STP_POSIX_FILE_P4:
    case STP_POSIX_FILE_P1:
        return fmt == STP_PIXEL_MONO1;
    case STP_POSIX_FILE_P5:
        return fmt == STP_PIXEL_GREY8 || fmt == STP_PIXEL_MONO1;
    case STP_POSIX_FILE_P6:
        return fmt == STP_PIXEL_RGB888 || fmt == STP_PIXEL_GREY8 ||
               fmt == STP_PIXEL_MONO1;
    case STP_POSIX_FILE_ASCII:
        return fmt == STP_PIXEL_STYLE8;
    case STP_POSIX_FILE_UNKNOWN:
        break;
    }
    return 0;
}

static int frame_valid(const stp_posix_frame *f)
{
    return f != NULL && f->pixels != NULL && f->width > 0 && f->height > 0 &&
           f->stride == stp_posix_priv_row_bytes(f->format, f->width);
}

int stp_posix_encode(const stp_posix_frame *f, stp_posix_file_kind kind, FILE *out)
{
    if (!frame_valid(f) || out == NULL || !stp_posix_kind_accepts(kind, f->format)) {
        errno = EINVAL;
        return -1;
    }
    if (kind == STP_POSIX_FILE_ASCII)
        return stp_posix_priv_encode_ascii(f, out);
    return stp_posix_priv_encode_pnm(f, kind, out);
}

typedef struct encode_job {
    const stp_posix_frame *frame;
    stp_posix_file_kind kind;
} encode_job;

static int emit_frame(FILE *out, void *ctx)
{
    const encode_job *job = (const encode_job *)ctx;

    return stp_posix_encode(job->frame, job->kind, out);
}

int stp_posix_write(const stp_posix_frame *f, const char *path,
                    stp_posix_file_kind kind, char *err, size_t errlen)
{
    encode_job job;

    if (path == NULL || *path == '\0') {
        stp_posix_priv_error(err, errlen, "(no path): no output file named");
        return -1;
    }
    if (!frame_valid(f)) {
        stp_posix_priv_error(err, errlen, "%s: the frame is not initialised", path);
        return -1;
    }
    /* Checked before anything touches the file system. */
    if (!stp_posix_kind_accepts(kind, f->format)) {
        stp_posix_priv_error(err, errlen, "%s: a %s frame cannot be written as %s",
                             path, stp_posix_priv_format_name(f->format),
                             stp_posix_priv_kind_name(kind));
        return -1;
    }
    job.frame = f;
    job.kind = kind;
    return stp_posix_write_file(path, emit_frame, &job, err, errlen);
}
