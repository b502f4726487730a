/* SPDX-License-Identifier: MIT */
/* JPEG input through libjpeg: see stp_posix_jpeg.h. */
#include "stp_posix_jpeg.h"

#include <errno.h>
#include <setjmp.h>
#include <stdlib.h>
#include <string.h>

#include <jpeglib.h>

#include "posix_internal.h"

typedef struct jpeg_failure {
    struct jpeg_error_mgr mgr;
    jmp_buf back;
    char message[JMSG_LENGTH_MAX];
} jpeg_failure;

static void on_error(j_common_ptr info)
{
    jpeg_failure *f = (jpeg_failure *)info->err;
    info->err->format_message(info, f->message);
    longjmp(f->back, 1);
}

/* A warning (level -1) is corrupt or missing data that libjpeg would fill
 * in with grey: a failure here, never a wrong picture; trace messages
 * (level >= 0) stay quiet. */
static void on_emit(j_common_ptr info, int level)
{
    if (level < 0)
        on_error(info);
}

/* Decode from fp into img; returns 0, or -1 with f->message set. */
static int decode(FILE *fp, stp_posix_image *img, int grey, struct jpeg_decompress_struct *info, jpeg_failure *f)
{
    size_t row_bytes;
    jpeg_stdio_src(info, fp);
    (void)jpeg_read_header(info, TRUE);
    if (info->jpeg_color_space == JCS_CMYK || info->jpeg_color_space == JCS_YCCK) {
        snprintf(f->message, sizeof f->message, "CMYK JPEG files are not read");
        return -1;
    }
    info->out_color_space = grey || info->num_components == 1 ? JCS_GRAYSCALE : JCS_RGB;
    (void)jpeg_start_decompress(info);
    if (info->output_width < 1 || info->output_height < 1 || info->output_width > 32767 ||
        info->output_height > 32767) {
        snprintf(f->message, sizeof f->message, "size %ux%u beyond 1..32767", (unsigned)info->output_width,
                 (unsigned)info->output_height);
        return -1;
    }
    img->width = info->output_width;
    img->height = info->output_height;
    img->channels = info->output_components;
    img->maxval = 255;
    row_bytes = (size_t)img->width * (size_t)img->channels;
    img->samples = malloc(row_bytes * img->height);
    if (!img->samples) {
        snprintf(f->message, sizeof f->message, "out of memory");
        return -1;
    }
    while (info->output_scanline < info->output_height) {
        JSAMPROW row = img->samples + row_bytes * info->output_scanline;
        (void)jpeg_read_scanlines(info, &row, 1);
    }
    (void)jpeg_finish_decompress(info);
    return 0;
}

int stp_posix_read_jpeg(const char *path, stp_posix_image *img, int grey, char *err, size_t errlen)
{
    struct jpeg_decompress_struct info;
    jpeg_failure f;
    FILE *volatile fp;
    int rc;
    memset(img, 0, sizeof *img);
    fp = strcmp(path, "-") ? fopen(path, "rb") : stdin;
    if (!fp) {
        stp_posix_priv_error(err, errlen, "%s: cannot open: %s", path, strerror(errno));
        return -1;
    }
    memset(&f, 0, sizeof f);
    info.err = jpeg_std_error(&f.mgr);
    f.mgr.error_exit = on_error;
    f.mgr.emit_message = on_emit;
    jpeg_create_decompress(&info);
    if (setjmp(f.back) == 0)
        rc = decode(fp, img, grey, &info, &f);
    else
        rc = -1;
    jpeg_destroy_decompress(&info);
    if (fp != stdin)
        (void)fclose(fp);
    if (rc != 0) {
        stp_posix_priv_error(err, errlen, "%s: not a readable JPEG file: %s", path, f.message);
        stp_posix_image_free(img);
    }
    return rc;
}
