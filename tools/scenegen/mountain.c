/* SPDX-License-Identifier: MIT */
/*
 * A fractal mountain by midpoint displacement (diamond-square) over the
 * square [-1,1]^2: a grid of (2^size+1)^2 heights, corners 0, each level's
 * new points the mean of their neighbours plus a uniform offset in
 * [-a, a], a = 0.4 at the first level and half as much at each next one;
 * 2*4^size triangles.  The offsets come from a fixed xorshift
 * sequence consumed level by level, so every size repeats the smaller
 * sizes' heights at their grid points and |height| < 0.4/(1 - 1/2) = 0.8.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "scenegen_private.h"

#define MOUNTAIN_FIRST_AMPLITUDE 0.4
#define MOUNTAIN_DECAY 0.5

/* A uniform number in [-1, 1] from a xorshift32 state. */
static double next_offset(uint32_t *state)
{
    uint32_t x = *state;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    *state = x;
    return (double)x / 2147483647.5 - 1.0;
}

/* h[j * n + i] at grid point (i, j), n = 2^size + 1. */
static void displace(double *h, int n, uint32_t *state)
{
    double amplitude = MOUNTAIN_FIRST_AMPLITUDE;
    int step, i, j;
    for (step = n - 1; step > 1; step /= 2, amplitude *= MOUNTAIN_DECAY) {
        int half = step / 2;
        /* diamond: square centres from their four corners */
        for (j = half; j < n; j += step)
            for (i = half; i < n; i += step)
                h[j * n + i] = (h[(j - half) * n + i - half] + h[(j - half) * n + i + half] +
                                h[(j + half) * n + i - half] + h[(j + half) * n + i + half]) / 4 +
                               amplitude * next_offset(state);
        /* square: edge midpoints from the neighbours inside the grid */
        for (j = 0; j < n; j += half)
            for (i = (j / half) % 2 == 0 ? half : 0; i < n; i += step) {
                double sum = 0;
                int count = 0;
                if (i >= half) sum += h[j * n + i - half], count++;
                if (i + half < n) sum += h[j * n + i + half], count++;
                if (j >= half) sum += h[(j - half) * n + i], count++;
                if (j + half < n) sum += h[(j + half) * n + i], count++;
                h[j * n + i] = sum / count + amplitude * next_offset(state);
            }
    }
}

int stp_sg_write_mountain(FILE *out, int size)
{
    const int n = (1 << size) + 1;
    uint32_t state = 0x9e3779b9u;
    double *h = calloc((size_t)n * (size_t)n, sizeof *h);
    int i, j;
    if (!h)
        return -1;
    displace(h, n, &state);
    stp_sg_comment(out, "mountain", size);
    stp_sg_background(out, 0.078, 0.361, 0.753);
    stp_sg_view(out, stp_sg_v(-1.6, 1.6, 1.7), stp_sg_v(0, 0, 0), stp_sg_v(0, 0, 1), 45, 0.01, 512);
    stp_sg_light(out, stp_sg_v(-100, -100, 100));
    stp_sg_material(out, 0.5, 0.45, 0.35, 1, 0, 100000, 0, 0);
    for (j = 0; j + 1 < n; j++)
        for (i = 0; i + 1 < n; i++) {
            stp_sg_vec c[4], t[3];
            const double x0 = -1 + 2.0 * i / (n - 1), x1 = -1 + 2.0 * (i + 1) / (n - 1);
            const double y0 = -1 + 2.0 * j / (n - 1), y1 = -1 + 2.0 * (j + 1) / (n - 1);
            c[0] = stp_sg_v(x0, y0, h[j * n + i]);
            c[1] = stp_sg_v(x1, y0, h[j * n + i + 1]);
            c[2] = stp_sg_v(x1, y1, h[(j + 1) * n + i + 1]);
            c[3] = stp_sg_v(x0, y1, h[(j + 1) * n + i]);
            t[0] = c[0], t[1] = c[1], t[2] = c[2];
            stp_sg_polygon(out, 3, t);
            t[0] = c[2], t[1] = c[3], t[2] = c[0];
            stp_sg_polygon(out, 3, t);
        }
    free(h);
    return stp_sg_status(out);
}
