/* SPDX-License-Identifier: MIT */
/*
 * Host torus benchmark (issue 11): frames of the torus workload (torus.h)
 * at 128x64, 400x240 and 640x480.
 *
 * usage: torus_bench [--frames N] [--rounds N] [--size WxH]... [--pbm PREFIX]
 *                    [--spin] [--edge-aa] [--mesh]
 *   --frames N   frames per timed batch (default 200)
 *   --rounds N   batches per size, the sizes interleaved; each size's figure
 *                is its fastest batch, so a busy machine inflates it least
 *                (process CPU time, so time the machine gives other work is not
 *                counted; default 5; 0: run --frames frames per size untimed, for
 *                callgrind)
 *   --size WxH   a size to run (repeatable; default the three above)
 *   --pbm PREFIX write each size's last frame to PREFIX-WxH.pbm
 *   --spin       spin the model: each frame is entered through a new model
 *                transform (tilt 20 degrees, spin 3 degrees more each frame)
 *   --mesh       enter the torus as one indexed mesh (stp_renderer_mesh,
 *                normals prepared at set-up) instead of 1000 calls of
 *                stp_renderer_polygon
 *   --edge-aa    anti-aliased polygon edges (stp_output.edge_aa; the band
 *                is then drawn grey and thresholded by the cell)
 * Prints one line per size: "WxH us_per_frame". Instructions per frame are
 * counted by tools/bench/torus_bench.sh, which runs this under callgrind
 * with --toggle-collect=torus_frame (only the frames are counted).
 */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "torus.h"

#define MAX_SIZES 8

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

static int write_pbm(const torus_bench *b, const char *prefix)
{
    char path[1024];
    FILE *f;
    int y;
    snprintf(path, sizeof path, "%s-%dx%d.pbm", prefix, b->width, b->height);
    f = fopen(path, "wb");
    if (!f) {
        fprintf(stderr, "torus_bench: cannot write %s\n", path);
        return -1;
    }
    /* MONO1 is MSB-first with 1 = ON (lit); PBM's 1 is black */
    fprintf(f, "P4\n%d %d\n", b->width, b->height);
    for (y = 0; y < b->height; y++) {
        size_t x;
        for (x = 0; x < b->stride; x++)
            fputc(~b->frame[(size_t)y * b->stride + x] & 0xFF, f);
    }
    if (fclose(f) != 0) {
        fprintf(stderr, "torus_bench: cannot write %s\n", path);
        return -1;
    }
    return 0;
}

int main(int argc, char **argv)
{
    int sizes[MAX_SIZES][2], nsizes = 0, frames = 200, rounds = 5, i, k, round;
    const char *pbm = 0;
    int spin = 0, edge_aa = 0, mesh = 0;
    long frame_no = 0;
    static torus_bench bench[MAX_SIZES];
    double best[MAX_SIZES];
    char err[256];
    for (i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--frames") && i + 1 < argc) {
            frames = atoi(argv[++i]);
        } else if (!strcmp(argv[i], "--rounds") && i + 1 < argc) {
            rounds = atoi(argv[++i]);
        } else if (!strcmp(argv[i], "--size") && i + 1 < argc && nsizes < MAX_SIZES) {
            if (sscanf(argv[++i], "%dx%d", &sizes[nsizes][0], &sizes[nsizes][1]) != 2 ||
                sizes[nsizes][0] < 1 || sizes[nsizes][1] < 1 || sizes[nsizes][0] > 32767 ||
                sizes[nsizes][1] > 32767) {
                fprintf(stderr, "torus_bench: bad size %s (WxH)\n", argv[i]);
                return 2;
            }
            nsizes++;
        } else if (!strcmp(argv[i], "--spin")) {
            spin = 1;
        } else if (!strcmp(argv[i], "--mesh")) {
            mesh = 1;
        } else if (!strcmp(argv[i], "--edge-aa")) {
            edge_aa = 1;
        } else if (!strcmp(argv[i], "--pbm") && i + 1 < argc) {
            pbm = argv[++i];
        } else {
            fprintf(stderr, "usage: torus_bench [--frames N] [--rounds N] [--size WxH]... "
                            "[--pbm PREFIX] [--spin] [--edge-aa] [--mesh]\n");
            return 2;
        }
    }
    if (frames < 1 || rounds < 0) {
        fprintf(stderr, "torus_bench: --frames must be >= 1 and --rounds >= 0\n");
        return 2;
    }
    if (nsizes == 0) {
        static const int def[3][2] = {{128, 64}, {400, 240}, {640, 480}};
        for (nsizes = 0; nsizes < 3; nsizes++) {
            sizes[nsizes][0] = def[nsizes][0];
            sizes[nsizes][1] = def[nsizes][1];
        }
    }
    for (k = 0; k < nsizes; k++) {
        if (torus_bench_init(&bench[k], sizes[k][0], sizes[k][1], err, sizeof err) != 0) {
            fprintf(stderr, "torus_bench: %dx%d: %s\n", sizes[k][0], sizes[k][1], err);
            return 1;
        }
        if (mesh && torus_bench_use_mesh(&bench[k], err, sizeof err) != 0) {
            fprintf(stderr, "torus_bench: %dx%d: %s\n", sizes[k][0], sizes[k][1], err);
            return 1;
        }
        if (edge_aa) {
            /* anti-aliased edges: the 1-bit band is drawn grey (render.h) */
            size_t bytes = (size_t)sizes[k][0] * (size_t)sizes[k][1];
            uint8_t *grey = malloc(bytes);
            if (!grey) {
                fprintf(stderr, "torus_bench: out of memory\n");
                return 1;
            }
            free(bench[k].band);
            bench[k].band = grey;
            bench[k].memory.band = grey;
            bench[k].memory.band_size = bytes;
            bench[k].output.edge_aa = 1;
        }
        best[k] = 1e30;
    }
    for (round = 0; round < (rounds > 0 ? rounds : 1); round++) {
        for (k = 0; k < nsizes; k++) {
            double t0 = now(), t;
            int f;
            for (f = 0; f < frames; f++) {
                if (spin)
                    torus_bench_pose(&bench[k], 20, 3.0 * (double)(frame_no++ % 120), 0, 0, 0);
                if (torus_frame(&bench[k]) != 0) {
                    fprintf(stderr, "torus_bench: %dx%d: the core refused a frame\n",
                            sizes[k][0], sizes[k][1]);
                    return 1;
                }
            }
            t = (now() - t0) / frames;
            if (t < best[k])
                best[k] = t;
        }
    }
    for (k = 0; k < nsizes; k++) {
        if (rounds > 0)
            printf("%dx%d %.1f\n", sizes[k][0], sizes[k][1], best[k] * 1e6);
        else
            printf("%dx%d %d frames\n", sizes[k][0], sizes[k][1], frames);
        if (pbm && write_pbm(&bench[k], pbm) != 0)
            return 1;
        torus_bench_free(&bench[k]);
    }
    return 0;
}
