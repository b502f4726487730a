/* SPDX-License-Identifier: MIT */
/* The quality bench's measure (quality.c), shared with the tests that hold
 * the still default to it (tests/dither/test_worms.c): see quality_measure.h. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "quality_measure.h"
#include "tone.h"

/* ---- a port that keeps the whole frame ---- */

typedef struct frame {
    stp_port port;
    uint8_t *px;
    size_t stride;
} frame;

static int frame_flush(stp_port *port, uint32_t y0, uint32_t rows, const uint8_t *pixels, size_t stride)
{
    frame *f = (frame *)port->user;
    uint32_t r;
    for (r = 0; r < rows; r++)
        memcpy(f->px + (size_t)(y0 + r) * f->stride, pixels + (size_t)r * stride, f->stride);
    return 0;
}

static int frame_init(frame *f, int w, int h, stp_pixel_format format)
{
    memset(f, 0, sizeof *f);
    f->stride = stp_row_bytes(format, (uint32_t)w);
    f->px = calloc(f->stride, (size_t)h);
    f->port.width = (uint32_t)w;
    f->port.height = (uint32_t)h;
    f->port.format = format;
    f->port.flush = frame_flush;
    f->port.user = f;
    return f->px ? 0 : -1;
}

/* ---- the ideal ---- */

/* 256-level grey render at 4x, box-filtered: ideal[w*h] in [0, 1]. */
int qm_render_ideal(const stp_scene *scene, const qm_method *m, int w, int h, double *ideal)
{
    stp_tool_options opt;
    frame f;
    char err[256];
    int x, y, i, j;
    stp_tool_options_default(&opt);
    /* the method's tone (exposure, grey from colour, background) is part
     * of what its picture stands for */
    if (m && m->setup)
        m->setup(&opt);
    opt.dither = STP_TOOL_DITHER_BAYER4;
    opt.band_rows = 0;
    if (opt.exposure_auto) {
        /* the picture's exposure, found at the picture's size */
        double gain;
        opt.width = w;
        opt.height = h;
        if (stp_tool_exposure_gain(scene, &opt, &gain, err, sizeof err) != 0) {
            fprintf(stderr, "bench_quality: exposure %dx%d: %s\n", w, h, err);
            return -1;
        }
        opt.brightness *= gain;
        opt.exposure_auto = 0;
    }
    opt.width = 4 * w;
    opt.height = 4 * h;
    opt.levels = 256;
    opt.outlines = 0; /* lines are drawn for the eye, not part of the scene (exposure kept) */
    if (frame_init(&f, opt.width, opt.height, STP_PIXEL_GREY8) != 0)
        return -1;
    if (stp_tool_render(scene, &opt, &f.port, 0, err, sizeof err) != 0) {
        fprintf(stderr, "bench_quality: ideal %dx%d: %s\n", w, h, err);
        free(f.px);
        return -1;
    }
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            double s = 0;
            for (j = 0; j < 4; j++)
                for (i = 0; i < 4; i++)
                    s += f.px[(size_t)(4 * y + j) * f.stride + (size_t)(4 * x + i)];
            ideal[(size_t)y * (size_t)w + (size_t)x] = s / (16.0 * 255.0);
        }
    free(f.px);
    return 0;
}

/* ---- the measure ---- */

/* Separable Gaussian blur, sigma 1.5, taps to 3 sigma, renormalised at the
 * frame's edges. */
void qm_gauss_blur(const double *in, double *out, int w, int h)
{
    enum { RADIUS = 5 };
    double k[2 * RADIUS + 1], *tmp = malloc(sizeof *tmp * (size_t)w * (size_t)h);
    int x, y, d;
    for (d = -RADIUS; d <= RADIUS; d++)
        k[d + RADIUS] = exp(-(double)(d * d) / (2.0 * 1.5 * 1.5));
    if (!tmp)
        exit(2);
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            double s = 0, ws = 0;
            for (d = -RADIUS; d <= RADIUS; d++)
                if (x + d >= 0 && x + d < w) {
                    s += k[d + RADIUS] * in[(size_t)y * (size_t)w + (size_t)(x + d)];
                    ws += k[d + RADIUS];
                }
            tmp[(size_t)y * (size_t)w + (size_t)x] = s / ws;
        }
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            double s = 0, ws = 0;
            for (d = -RADIUS; d <= RADIUS; d++)
                if (y + d >= 0 && y + d < h) {
                    s += k[d + RADIUS] * tmp[(size_t)(y + d) * (size_t)w + (size_t)x];
                    ws += k[d + RADIUS];
                }
            out[(size_t)y * (size_t)w + (size_t)x] = s / ws;
        }
    free(tmp);
}

/* Mean absolute difference of the blurred 0/1 picture and blurred ideal. */
double qm_picture_error(const unsigned char *bits, const double *ideal_blurred, int w, int h)
{
    size_t n = (size_t)w * (size_t)h, i;
    double *p = calloc(n, sizeof *p), *pb = calloc(n, sizeof *pb), sum = 0;
    if (!p || !pb)
        exit(2);
    for (i = 0; i < n; i++)
        p[i] = bits[i];
    qm_gauss_blur(p, pb, w, h);
    for (i = 0; i < n; i++)
        sum += fabs(pb[i] - ideal_blurred[i]);
    free(p);
    free(pb);
    return sum / (double)n;
}

/* ---- methods ---- */

/* Render with a method's options to MONO1 and unpack to 0/1. */
int qm_render_bits(const stp_scene *scene, const qm_method *m, int w, int h, unsigned char *bits)
{
    stp_tool_options opt;
    frame f;
    char err[256];
    int x, y;
    stp_tool_options_default(&opt);
    opt.width = w;
    opt.height = h;
    if (m->setup)
        m->setup(&opt);
    if (frame_init(&f, w, h, STP_PIXEL_MONO1) != 0)
        return -1;
    if (stp_tool_render(scene, &opt, &f.port, 0, err, sizeof err) != 0) {
        fprintf(stderr, "bench_quality: %s %dx%d: %s\n", m->name, w, h, err);
        free(f.px);
        return -1;
    }
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++)
            bits[(size_t)y * (size_t)w + (size_t)x] =
                (unsigned char)((f.px[(size_t)y * f.stride + (size_t)(x >> 3)] >> (7 - (x & 7))) & 1);
    free(f.px);
    return 0;
}
