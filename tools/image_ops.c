/* SPDX-License-Identifier: MIT */
/* Images made fit for a panel: see image_ops.h. */
#include "image_ops.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

int stp_tool_image_rotate(stp_posix_image *img, int degrees)
{
    uint32_t w = img->width, h = img->height, x, y, nw, nh;
    int c, ch = img->channels;
    uint8_t *out;
    if (degrees == 0)
        return 0;
    if (degrees != 90 && degrees != 180 && degrees != 270)
        return -1;
    nw = degrees == 180 ? w : h;
    nh = degrees == 180 ? h : w;
    out = malloc((size_t)w * h * (size_t)ch);
    if (!out)
        return -1;
    for (y = 0; y < nh; y++)
        for (x = 0; x < nw; x++) {
            /* the source pixel of output (x, y) */
            uint32_t sx = degrees == 90 ? y : degrees == 180 ? w - 1 - x : w - 1 - y;
            uint32_t sy = degrees == 90 ? h - 1 - x : degrees == 180 ? h - 1 - y : x;
            for (c = 0; c < ch; c++)
                out[((size_t)y * nw + x) * (size_t)ch + (size_t)c] =
                    img->samples[((size_t)sy * w + sx) * (size_t)ch + (size_t)c];
        }
    free(img->samples);
    img->samples = out;
    img->width = nw;
    img->height = nh;
    return 0;
}

void stp_tool_image_flip(stp_posix_image *img)
{
    uint32_t x, y;
    int c, ch = img->channels;
    for (y = 0; y < img->height; y++) {
        uint8_t *row = img->samples + (size_t)y * img->width * (size_t)ch;
        for (x = 0; x < img->width / 2; x++)
            for (c = 0; c < ch; c++) {
                uint8_t *a = row + (size_t)x * (size_t)ch + (size_t)c;
                uint8_t *b = row + (size_t)(img->width - 1 - x) * (size_t)ch + (size_t)c;
                uint8_t t = *a;
                *a = *b;
                *b = t;
            }
    }
}

void stp_tool_image_invert(stp_posix_image *img)
{
    size_t i, n = (size_t)img->width * img->height * (size_t)img->channels;
    for (i = 0; i < n; i++)
        img->samples[i] = (uint8_t)(255 - img->samples[i]);
}

/* Area weights of source samples for each of dst output samples covering
 * [offset, offset + dst * step) of the source: output i takes samples
 * first[i] .. first[i] + count[i] - 1 with weights w[i * span ...]. */
typedef struct area_map {
    uint32_t *first, *count, span;
    double *w;
} area_map;

static void area_free(area_map *m)
{
    free(m->first);
    free(m->count);
    free(m->w);
}

static int area_weights(area_map *m, uint32_t src, uint32_t dst, double offset, double step)
{
    uint32_t i, s;
    m->span = (uint32_t)ceil(step) + 2;
    m->first = calloc(dst, sizeof *m->first);
    m->count = calloc(dst, sizeof *m->count);
    m->w = calloc((size_t)dst * m->span, sizeof *m->w);
    if (!m->first || !m->count || !m->w) {
        area_free(m);
        return -1;
    }
    for (i = 0; i < dst; i++) {
        double a = offset + i * step, b = a + step, total = 0;
        uint32_t lo_s = a > 0 ? (uint32_t)floor(a) : 0;
        m->first[i] = lo_s;
        for (s = lo_s; s < src && s < b && m->count[i] < m->span; s++) {
            double lo = a > s ? a : s, hi = b < s + 1.0 ? b : s + 1.0;
            double part = hi > lo ? hi - lo : 0;
            m->w[(size_t)i * m->span + m->count[i]++] = part;
            total += part;
        }
        for (s = 0; s < m->count[i] && total > 0; s++)
            m->w[(size_t)i * m->span + s] /= total;
    }
    return 0;
}

/* The placement of the resized picture: its size cw x chh at (x0, y0) on
 * the panel, and the source window (ox, oy, step sx, sy per output pixel). */
static void placement(const stp_posix_image *img, uint32_t width, uint32_t height, stp_tool_resize mode,
                      uint32_t box[4], double win[4])
{
    double sx = (double)width / img->width, sy = (double)height / img->height, s;
    box[0] = box[1] = 0;
    box[2] = width;
    box[3] = height;
    win[0] = win[1] = 0;
    if (mode == STP_TOOL_RESIZE_FIT) {
        s = fmin(sx, sy);
        box[2] = (uint32_t)fmax(1, fmin(width, floor(img->width * s + 0.5)));
        box[3] = (uint32_t)fmax(1, fmin(height, floor(img->height * s + 0.5)));
        box[0] = (width - box[2]) / 2;
        box[1] = (height - box[3]) / 2;
        sx = (double)box[2] / img->width;
        sy = (double)box[3] / img->height;
    } else if (mode == STP_TOOL_RESIZE_FILL) {
        s = fmax(sx, sy);
        win[0] = (img->width - width / s) / 2;
        win[1] = (img->height - height / s) / 2;
        sx = sy = s;
    }
    win[2] = 1 / sx;
    win[3] = 1 / sy;
}

int stp_tool_image_resize(stp_posix_image *img, uint32_t width, uint32_t height, stp_tool_resize mode)
{
    uint32_t box[4], x, y, k;
    double win[4], *rows;
    area_map mx, my;
    int c, ch = img->channels;
    uint8_t *out;
    if (width < 1 || height < 1 || width > 32767 || height > 32767)
        return -1;
    placement(img, width, height, mode, box, win);
    if (area_weights(&mx, img->width, box[2], win[0], win[2]) != 0)
        return -1;
    if (area_weights(&my, img->height, box[3], win[1], win[3]) != 0) {
        area_free(&mx);
        return -1;
    }
    /* across first: every source row at the output's width */
    rows = malloc(sizeof *rows * (size_t)img->height * box[2] * (size_t)ch);
    out = calloc((size_t)width * height, (size_t)ch);
    if (!rows || !out) {
        area_free(&mx);
        area_free(&my);
        free(rows);
        free(out);
        return -1;
    }
    for (y = 0; y < img->height; y++)
        for (x = 0; x < box[2]; x++)
            for (c = 0; c < ch; c++) {
                double sum = 0;
                for (k = 0; k < mx.count[x]; k++)
                    sum += mx.w[(size_t)x * mx.span + k] *
                           img->samples[((size_t)y * img->width + mx.first[x] + k) * (size_t)ch + (size_t)c];
                rows[((size_t)y * box[2] + x) * (size_t)ch + (size_t)c] = sum;
            }
    for (y = 0; y < box[3]; y++)
        for (x = 0; x < box[2]; x++)
            for (c = 0; c < ch; c++) {
                double sum = 0;
                for (k = 0; k < my.count[y]; k++)
                    sum += my.w[(size_t)y * my.span + k] *
                           rows[((size_t)(my.first[y] + k) * box[2] + x) * (size_t)ch + (size_t)c];
                out[((size_t)(y + box[1]) * width + x + box[0]) * (size_t)ch + (size_t)c] =
                    (uint8_t)lround(sum < 0 ? 0 : sum > 255 ? 255 : sum);
            }
    area_free(&mx);
    area_free(&my);
    free(rows);
    free(img->samples);
    img->samples = out;
    img->width = width;
    img->height = height;
    return 0;
}
