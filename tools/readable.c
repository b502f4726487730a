/* SPDX-License-Identifier: MIT */
/* Readable small pictures: see readable.h. */
#include "readable.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "outlines.h"

typedef struct side_sums {
    double sum[3];
    int n[3]; /* side A, side B, the edge */
} side_sums;

/* The three groups' sums around sample (px, py), along (ux, uy). */
static void sample_sums(const unsigned char *bits, int w, int h, double px, double py, double ux,
                        double uy, side_sums *s)
{
    int x, y;
    memset(s, 0, sizeof *s);
    for (y = (int)floor(py - 5); y <= (int)ceil(py + 5); y++)
        for (x = (int)floor(px - 5); x <= (int)ceil(px + 5); x++) {
            double cx = x + 0.5 - px, cy = y + 0.5 - py;
            double along = cx * ux + cy * uy, d = cx * -uy + cy * ux;
            int g;
            if (x < 0 || x >= w || y < 0 || y >= h || fabs(along) > 2.5)
                continue;
            if (d >= 1.5 && d <= 4.5)
                g = 0;
            else if (d <= -1.5 && d >= -4.5)
                g = 1;
            else if (fabs(d) <= 1.0)
                g = 2;
            else
                continue;
            s->sum[g] += bits[(size_t)y * (size_t)w + (size_t)x];
            s->n[g]++;
        }
}

/* 1: the sample reads, 0: it does not, -1: left out. */
static int sample_reads(const side_sums *s)
{
    double a, b, e;
    if (s->n[0] < 3 || s->n[1] < 3)
        return -1;
    a = s->sum[0] / s->n[0];
    b = s->sum[1] / s->n[1];
    if (fabs(a - b) >= STP_TOOL_READABLE_STEP)
        return 1;
    if (s->n[2] == 0)
        return 0;
    e = s->sum[2] / s->n[2];
    return (e - a >= STP_TOOL_READABLE_STEP && e - b >= STP_TOOL_READABLE_STEP) ||
           (a - e >= STP_TOOL_READABLE_STEP && b - e >= STP_TOOL_READABLE_STEP);
}

double stp_tool_readability(const unsigned char *bits, int w, int h, const double *xy, size_t count,
                            size_t *samples)
{
    return stp_tool_readability_lit(bits, w, h, xy, count, samples, 0);
}

double stp_tool_readability_lit(const unsigned char *bits, int w, int h, const double *xy, size_t count,
                                size_t *samples, double *lit)
{
    size_t i, counted = 0, read = 0;
    double on = 0, all = 0;
    for (i = 0; i < count; i++) {
        const double *q = xy + 4 * i;
        double dx = q[2] - q[0], dy = q[3] - q[1], len = sqrt(dx * dx + dy * dy);
        int n = (int)ceil(len), k;
        if (len < 1e-9)
            continue;
        for (k = 0; k < n; k++) {
            double t = (k + 0.5) / n;
            side_sums s;
            int r;
            sample_sums(bits, w, h, q[0] + t * dx, q[1] + t * dy, dx / len, dy / len, &s);
            r = sample_reads(&s);
            if (r < 0)
                continue;
            on += s.sum[0] + s.sum[1];
            all += s.n[0] + s.n[1];
            counted++;
            read += (size_t)r;
        }
    }
    if (samples)
        *samples = counted;
    if (lit)
        *lit = all > 0 ? on / all : 0;
    return counted ? (double)read / (double)counted : 1.0;
}

/* A port that unpacks the MONO1 rows it is sent into bits (0/1). */
typedef struct bits_port {
    stp_port port;
    unsigned char *bits;
} bits_port;

static int bits_flush(stp_port *port, uint32_t y0, uint32_t rows, const uint8_t *pixels, size_t stride)
{
    bits_port *b = (bits_port *)port->user;
    uint32_t r, x, w = port->width;
    for (r = 0; r < rows; r++)
        for (x = 0; x < w; x++)
            b->bits[(size_t)(y0 + r) * w + x] =
                (unsigned char)((pixels[(size_t)r * stride + (x >> 3)] >> (7 - (x & 7))) & 1);
    return 0;
}

int stp_tool_picture_readability(const stp_scene *scene, const stp_tool_options *opt, double *r,
                                 double *lit, char *err, size_t err_size)
{
    stp_tool_options plain = *opt;
    bits_port b;
    double *xy = 0;
    size_t count = 0;
    int rc = -1;
    plain.outlines = 0;
    plain.outlines_auto = 0;
    memset(&b, 0, sizeof b);
    b.port.width = (uint32_t)opt->width;
    b.port.height = (uint32_t)opt->height;
    b.port.format = STP_PIXEL_MONO1;
    b.port.flush = bits_flush;
    b.port.user = &b;
    b.bits = calloc((size_t)opt->width * (size_t)opt->height, 1);
    if (!b.bits)
        snprintf(err, err_size, "out of memory");
    else if (stp_tool_render(scene, &plain, &b.port, 0, err, err_size) == 0 &&
             stp_tool_outline_pixels(scene, &plain, STP_OUTLINE_SILHOUETTE, &xy, &count, err, err_size) == 0) {
        *r = stp_tool_readability_lit(b.bits, opt->width, opt->height, xy, count, 0, lit);
        rc = 0;
    }
    free(xy);
    free(b.bits);
    return rc;
}

int stp_tool_auto_outlines(const stp_scene *scene, const stp_tool_options *opt, int *silhouettes,
                           double *level, char *err, size_t err_size)
{
    double r, lit = 0;
    if (stp_tool_picture_readability(scene, opt, &r, &lit, err, err_size) != 0)
        return -1;
    *silhouettes = r < STP_TOOL_READABLE_SHARE;
    *level = lit < 0.5 ? 1.0 : 0.0;
    return 0;
}
