/* SPDX-License-Identifier: MIT */
/* HALFTONE-FILLIN against memset on the same 1-bit buffer (issue 11): whole
 * rows of a W x 480 MONO1 buffer, W = 640 and 128, filled by
 * stp_halftone_fillin (Bayer 4x4, a new intensity every row, as a polygon
 * span would) and by memset of the same bytes.  The two are timed in turns
 * (CLOCK_MONOTONIC, 200 rounds by default, the best batch of each), so machine load
 * hits both alike; the table gives ns per row and the speed ratio
 * memset time / fill time (1: as fast as memset).
 *
 * usage: fill_bench [--rounds N] */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "stipple/stipple.h"

#define ROWS 480
#define MAX_W 640
#define BATCH 50 /* whole-buffer passes per timed batch */

static uint8_t buffer[(MAX_W / 8) * ROWS];
static volatile uint8_t sink;

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

static double fill_batch(uint32_t w, const stp_cell *cell, unsigned seed)
{
    size_t stride = w / 8;
    double t0 = now();
    int k;
    uint32_t y;
    for (k = 0; k < BATCH; k++)
        for (y = 0; y < ROWS; y++)
            stp_halftone_fillin(buffer + y * stride, 0, w - 1, y, cell,
                                (uint8_t)((seed + (unsigned)k) * 37u + y));
    sink = buffer[seed % sizeof buffer];
    return now() - t0;
}

static double memset_batch(uint32_t w, unsigned seed)
{
    size_t stride = w / 8;
    double t0 = now();
    int k;
    uint32_t y;
    for (k = 0; k < BATCH; k++)
        for (y = 0; y < ROWS; y++)
            memset(buffer + y * stride, (int)(((seed + (unsigned)k) * 37u + y) & 255u), stride);
    sink = buffer[seed % sizeof buffer];
    return now() - t0;
}

int main(int argc, char **argv)
{
    static const uint32_t widths[] = {640, 128};
    int rounds = 200, i, r;
    stp_cell cell;
    if (argc == 3 && strcmp(argv[1], "--rounds") == 0 && atoi(argv[2]) > 0) {
        rounds = atoi(argv[2]);
    } else if (argc != 1) {
        fprintf(stderr, "usage: fill_bench [--rounds N]\n");
        return 2;
    }
    (void)stp_cell_bayer(&cell, 4);
    printf("%-10s %14s %14s %10s\n", "row width", "fill ns/row", "memset ns/row", "ratio");
    for (i = 0; i < 2; i++) {
        double best_fill = 1e30, best_memset = 1e30;
        for (r = 0; r < rounds; r++) {
            double f = fill_batch(widths[i], &cell, (unsigned)r), m = memset_batch(widths[i], (unsigned)r);
            if (f < best_fill)
                best_fill = f;
            if (m < best_memset)
                best_memset = m;
        }
        printf("%-10u %14.2f %14.2f %10.3f\n", (unsigned)widths[i], best_fill * 1e9 / (BATCH * ROWS),
               best_memset * 1e9 / (BATCH * ROWS), best_memset / best_fill);
    }
    return 0;
}
