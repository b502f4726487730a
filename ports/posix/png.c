/* SPDX-License-Identifier: MIT */
/*
 * PNG files through libpng: see stp_posix_png.h.  libpng reports errors by
 * longjmp; each function keeps what it must free in a context struct that
 * outlives the jump, so every path frees the same way.
 */
#include <errno.h>
#include <png.h>
#include <stdlib.h>
#include <string.h>

#include "posix_internal.h"
#include "stp_posix_png.h"

#define PNG_MAX_SIDE 32767u

/* libpng's error message, kept for ours; warnings are not errors, but the
 * first one is kept: libpng gives the reason for a refused header (a side
 * over the limit) only as a warning before its error "Invalid IHDR data". */
typedef struct png_context {
    char message[200];
    char warning[120];
} png_context;

static void on_error(png_structp png, png_const_charp msg)
{
    png_context *ctx = (png_context *)png_get_error_ptr(png);
    if (strstr(ctx->warning, "exceeds user limit") != NULL)
        snprintf(ctx->message, sizeof ctx->message,
                 "wider or taller than %u pixels, the most read (%s)", PNG_MAX_SIDE, ctx->warning);
    else if (ctx->warning[0] != 0)
        snprintf(ctx->message, sizeof ctx->message, "%s (%s)", msg, ctx->warning);
    else
        snprintf(ctx->message, sizeof ctx->message, "%s", msg);
    png_longjmp(png, 1);
}

static void on_warning(png_structp png, png_const_charp msg)
{
    png_context *ctx = (png_context *)png_get_error_ptr(png);
    if (ctx->warning[0] == 0)
        snprintf(ctx->warning, sizeof ctx->warning, "%s", msg);
}

int stp_posix_png_path(const char *path)
{
    size_t n = path ? strlen(path) : 0;
    const char *ext;
    if (n < 4)
        return 0;
    ext = path + n - 4;
    return ext[0] == '.' && (ext[1] == 'p' || ext[1] == 'P') && (ext[2] == 'n' || ext[2] == 'N') &&
           (ext[3] == 'g' || ext[3] == 'G');
}

/* ------------------------------------------------------------- writing */

/* State of one encode that must survive a longjmp. */
typedef struct png_writer {
    png_context ctx;
    png_structp png;
    png_infop info;
} png_writer;

static int encode_rows(png_writer *w, const stp_posix_frame *f, FILE *out)
{
    int depth = f->format == STP_PIXEL_MONO1 ? 1 : 8;
    int type = f->format == STP_PIXEL_RGB888 ? PNG_COLOR_TYPE_RGB : PNG_COLOR_TYPE_GRAY;
    uint32_t y;
    if (setjmp(png_jmpbuf(w->png)))
        return -1;
    png_init_io(w->png, out);
    png_set_IHDR(w->png, w->info, f->width, f->height, depth, type, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(w->png, w->info);
    /* The frame's rows are already PNG's layout: MONO1 packs the leftmost
     * pixel in the high bit with 1 light, PNG's 1-bit grey 1 is white. */
    for (y = 0; y < f->height; y++)
        png_write_row(w->png, f->pixels + (size_t)y * f->stride);
    png_write_end(w->png, w->info);
    return 0;
}

int stp_posix_encode_png(const stp_posix_frame *f, FILE *out)
{
    png_writer w;
    int rc;
    if (f == NULL || f->pixels == NULL || out == NULL || f->width == 0 || f->height == 0 ||
        (f->format != STP_PIXEL_MONO1 && f->format != STP_PIXEL_GREY8 &&
         f->format != STP_PIXEL_RGB888)) {
        errno = EINVAL;
        return -1;
    }
    memset(&w, 0, sizeof w);
    w.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &w.ctx, on_error, on_warning);
    w.info = w.png ? png_create_info_struct(w.png) : NULL;
    if (w.info == NULL) {
        png_destroy_write_struct(&w.png, NULL);
        errno = ENOMEM;
        return -1;
    }
    errno = 0;
    rc = encode_rows(&w, f, out);
    png_destroy_write_struct(&w.png, &w.info);
    if (rc != 0 && errno == 0)
        errno = ferror(out) ? EIO : ENOMEM;
    return rc;
}

static int emit_png(FILE *out, void *ctx)
{
    return stp_posix_encode_png((const stp_posix_frame *)ctx, out);
}

int stp_posix_write_png(const stp_posix_frame *f, const char *path, char *err, size_t errlen)
{
    if (f == NULL || f->pixels == NULL) {
        stp_posix_priv_error(err, errlen, "%s: no frame to write", path ? path : "(no path)");
        return -1;
    }
    if (f->format != STP_PIXEL_MONO1 && f->format != STP_PIXEL_GREY8 &&
        f->format != STP_PIXEL_RGB888) {
        stp_posix_priv_error(err, errlen, "%s: a %s frame cannot be written as PNG",
                             path ? path : "(no path)", stp_posix_priv_format_name(f->format));
        return -1;
    }
    return stp_posix_write_file(path, emit_png, (void *)f, err, errlen);
}

/* ------------------------------------------------------------- reading */

typedef struct png_reader {
    png_context ctx;
    png_structp png;
    png_infop info;
    uint8_t *pixels;    /* the file's rows after the transforms */
    png_bytep *rows;
    FILE *fp;
} png_reader;

/* BT.601 luminance of 8-bit samples, as pnm.c computes it for maxval 255. */
static uint8_t luminance(const uint8_t *p)
{
    uint32_t y = 299u * p[0] + 587u * p[1] + 114u * p[2];
    return (uint8_t)((y * 255u + 127500u) / 255000u);
}

/* Reads the whole image into rd->pixels (channels 1 or 3 per pixel, 8-bit).
 * Returns 0, or -1 with rd->ctx.message set. */
static int decode(png_reader *rd, uint32_t *width, uint32_t *height, int *channels)
{
    png_uint_32 w, h, y;
    int depth, type;
    size_t rowbytes;
    if (setjmp(png_jmpbuf(rd->png)))
        return -1;
    png_init_io(rd->png, rd->fp);
    png_set_sig_bytes(rd->png, 8);
    /* refuse large images in the header, before anything is allocated */
    png_set_user_limits(rd->png, PNG_MAX_SIDE, PNG_MAX_SIDE);
    png_read_info(rd->png, rd->info);
    png_get_IHDR(rd->png, rd->info, &w, &h, &depth, &type, NULL, NULL, NULL);
    png_set_expand(rd->png); /* palette to RGB, low-bit grey to 8, tRNS to alpha */
    png_set_scale_16(rd->png);
    png_set_strip_alpha(rd->png);
    (void)png_set_interlace_handling(rd->png);
    png_read_update_info(rd->png, rd->info);
    *channels = png_get_channels(rd->png, rd->info);
    rowbytes = png_get_rowbytes(rd->png, rd->info);
    if ((*channels != 1 && *channels != 3) || rowbytes != (size_t)w * (size_t)*channels) {
        snprintf(rd->ctx.message, sizeof rd->ctx.message, "unexpected layout after decoding");
        return -1;
    }
    rd->pixels = (uint8_t *)malloc(rowbytes * h);
    rd->rows = (png_bytep *)malloc(sizeof *rd->rows * h);
    if (rd->pixels == NULL || rd->rows == NULL) {
        snprintf(rd->ctx.message, sizeof rd->ctx.message, "out of memory");
        return -1;
    }
    for (y = 0; y < h; y++)
        rd->rows[y] = rd->pixels + rowbytes * y;
    png_read_image(rd->png, rd->rows);
    png_read_end(rd->png, NULL);
    *width = w;
    *height = h;
    return 0;
}

static int read_png_stream(png_reader *rd, const char *name, stp_posix_image *img, int grey,
                           char *err, size_t errlen)
{
    unsigned char sig[8];
    uint32_t w = 0, h = 0, i;
    int channels = 0;
    if (fread(sig, 1, sizeof sig, rd->fp) != sizeof sig || png_sig_cmp(sig, 0, sizeof sig) != 0) {
        stp_posix_priv_error(err, errlen, "%s: not a PNG file (no PNG signature)", name);
        return -1;
    }
    rd->png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &rd->ctx, on_error, on_warning);
    rd->info = rd->png ? png_create_info_struct(rd->png) : NULL;
    if (rd->info == NULL) {
        stp_posix_priv_error(err, errlen, "%s: out of memory", name);
        return -1;
    }
    if (decode(rd, &w, &h, &channels) != 0) {
        stp_posix_priv_error(err, errlen, "%s: bad PNG: %s", name, rd->ctx.message);
        return -1;
    }
    img->width = w;
    img->height = h;
    img->maxval = 255;
    img->pnm_type = 0;
    if (!grey || channels == 1) {
        /* the decoded rows are the image */
        img->channels = channels;
        img->samples = rd->pixels;
        rd->pixels = NULL;
        return 0;
    }
    img->channels = 1;
    img->samples = (uint8_t *)malloc((size_t)w * h);
    if (img->samples == NULL) {
        stp_posix_priv_error(err, errlen, "%s: out of memory", name);
        return -1;
    }
    for (i = 0; i < w * h; i++)
        img->samples[i] = luminance(rd->pixels + 3u * i);
    return 0;
}

int stp_posix_read_png(const char *path, stp_posix_image *img, int grey, char *err,
                       size_t errlen)
{
    png_reader rd;
    int from_stdin, rc;
    if (img != NULL)
        memset(img, 0, sizeof *img);
    if (path == NULL || *path == '\0' || img == NULL) {
        stp_posix_priv_error(err, errlen, "%s: invalid arguments to the PNG reader",
                             path != NULL && *path != '\0' ? path : "(no path)");
        return -1;
    }
    memset(&rd, 0, sizeof rd);
    from_stdin = strcmp(path, "-") == 0;
    rd.fp = from_stdin ? stdin : fopen(path, "rb");
    if (rd.fp == NULL) {
        stp_posix_priv_error(err, errlen, "%s: cannot open: %s", path, strerror(errno));
        return -1;
    }
    rc = read_png_stream(&rd, from_stdin ? "stdin" : path, img, grey, err, errlen);
    png_destroy_read_struct(&rd.png, &rd.info, NULL);
    free(rd.pixels);
    free(rd.rows);
    if (!from_stdin)
        (void)fclose(rd.fp);
    if (rc != 0)
        stp_posix_image_free(img);
    return rc;
}

int stp_posix_read_image_grey(const char *path, stp_posix_image *img, char *err, size_t errlen)
{
    int first;
    if (img != NULL)
        memset(img, 0, sizeof *img);
    if (path == NULL || *path == '\0' || img == NULL)
        return stp_posix_read_grey(path, img, err, errlen); /* it reports the bad call */
    if (strcmp(path, "-") == 0) {
        /* one byte of push-back is all stdio promises, and all it takes */
        first = getc(stdin);
        if (first != EOF)
            (void)ungetc(first, stdin);
    } else {
        FILE *fp = fopen(path, "rb");
        if (fp == NULL) {
            stp_posix_priv_error(err, errlen, "%s: cannot open: %s", path, strerror(errno));
            return -1;
        }
        first = getc(fp);
        (void)fclose(fp);
    }
    if (first == 0x89)
        return stp_posix_read_png(path, img, 1, err, errlen);
    return stp_posix_read_grey(path, img, err, errlen);
}
