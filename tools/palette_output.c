/* SPDX-License-Identifier: MIT */
/* Host side: palette pictures as files (palette_output.h). */
#include "palette_output.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "stp_posix.h"
#include "stp_posix_png.h"

int stp_palette_output_accepts(const stp_palette *p, const char *path)
{
    stp_posix_file_kind kind;
    if (!strcmp(path, "-") || stp_posix_png_path(path))
        return 1;
    kind = stp_posix_kind_from_path(path);
    return kind == STP_POSIX_FILE_P6 || (kind == STP_POSIX_FILE_P5 && p->grey);
}

int stp_palette_write(const stp_palette *p, const uint8_t *index, uint32_t width, uint32_t height,
                      const char *path, char *err, size_t err_size)
{
    stp_posix_frame frame;
    int png = stp_posix_png_path(path), rc;
    stp_posix_file_kind kind = !strcmp(path, "-") ? STP_POSIX_FILE_P6 : stp_posix_kind_from_path(path);
    int grey = png ? p->grey : kind == STP_POSIX_FILE_P5;
    uint32_t x, y;
    if (!stp_palette_output_accepts(p, path)) {
        snprintf(err, err_size, "%s: a palette picture is written as .png, .ppm%s", path,
                 p->grey ? " or .pgm" : "");
        return -1;
    }
    if (stp_posix_frame_init(&frame, width, height, grey ? STP_PIXEL_GREY8 : STP_PIXEL_RGB888) != 0) {
        snprintf(err, err_size, "out of memory for the frame");
        return -1;
    }
    for (y = 0; y < height; y++)
        for (x = 0; x < width; x++) {
            const uint8_t *c = p->rgb[index[(size_t)y * width + x]];
            uint8_t *out = frame.pixels + (size_t)y * frame.stride + (grey ? x : 3 * (size_t)x);
            if (grey)
                out[0] = c[0];
            else
                memcpy(out, c, 3);
        }
    rc = png ? stp_posix_write_png(&frame, path, err, err_size)
             : stp_posix_write(&frame, path, grey ? STP_POSIX_FILE_P5 : STP_POSIX_FILE_P6, err, err_size);
    stp_posix_frame_free(&frame);
    return rc;
}

typedef struct plane_bytes {
    const uint8_t *bytes;
    size_t size;
} plane_bytes;

static int emit_plane(FILE *out, void *ctx)
{
    const plane_bytes *b = ctx;
    return fwrite(b->bytes, 1, b->size, out) == b->size ? 0 : -1;
}

int stp_palette_write_planes(const uint8_t *index, uint32_t width, uint32_t height,
                             const char *prefix, char *err, size_t err_size)
{
    size_t size = ((size_t)width + 7) / 8 * height, n = strlen(prefix) + 8;
    uint8_t *bw = malloc(size), *red = malloc(size);
    char *path = malloc(n);
    int rc = -1;
    if (!bw || !red || !path) {
        snprintf(err, err_size, "out of memory for the planes");
    } else {
        plane_bytes b;
        stp_palette_bwr_planes(index, width, height, bw, red);
        b.size = size;
        b.bytes = bw;
        snprintf(path, n, "%s.bw", prefix);
        if (stp_posix_write_file(path, emit_plane, &b, err, err_size) == 0) {
            b.bytes = red;
            snprintf(path, n, "%s.red", prefix);
            rc = stp_posix_write_file(path, emit_plane, &b, err, err_size);
        }
    }
    free(bw);
    free(red);
    free(path);
    return rc;
}
