/* SPDX-License-Identifier: MIT */
/* The spinning scene of the firmware (ports/spin) on the host: frames 0..N
 * entered and rendered by the same spin_frame.c, the picture after frame N
 * written as a binary PBM as stipple writes it (1 = black = OFF), for the
 * firmware test to compare the panel with.
 *
 * usage: spin_host [-s WxH] [-n FRAME] [-b BAND_ROWS] -o OUT.pbm
 *   -s WxH        frame size (default 128x64)
 *   -n FRAME      the last frame rendered (default 0)
 *   -b BAND_ROWS  rows per band (default: the whole frame)
 * Exit status: 0, 1 (a core error, a write error), 2 (usage). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "spin_frame.h"

typedef struct picture {
    uint8_t *pixels;
    size_t stride;
} picture;

static int keep_band(stp_port *port, uint32_t y0, uint32_t rows, const uint8_t *pixels, size_t stride)
{
    picture *p = (picture *)port->user;
    memcpy(p->pixels + (size_t)y0 * p->stride, pixels, stride * rows);
    return 0;
}

int main(int argc, char **argv)
{
    unsigned w = 128, h = 64, band_rows = 0, last = 0, n;
    const char *out_path = 0;
    int i, status;
    stp_renderer *r;
    void *rmem;
    stp_port port;
    stp_frame_memory mem;
    picture pic;
    FILE *f;
    for (i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "-s") && i + 1 < argc && sscanf(argv[i + 1], "%ux%u", &w, &h) == 2)
            i++;
        else if (!strcmp(argv[i], "-n") && i + 1 < argc)
            last = (unsigned)atoi(argv[++i]);
        else if (!strcmp(argv[i], "-b") && i + 1 < argc)
            band_rows = (unsigned)atoi(argv[++i]);
        else if (!strcmp(argv[i], "-o") && i + 1 < argc)
            out_path = argv[++i];
        else
            break;
    }
    if (i < argc || !out_path || w < 1 || h < 1 || w > 4096 || h > 4096) {
        fprintf(stderr, "usage: spin_host [-s WxH] [-n FRAME] [-b BAND_ROWS] -o OUT.pbm\n");
        return 2;
    }
    if (band_rows == 0 || band_rows > h)
        band_rows = h;
    rmem = malloc(stp_renderer_size());
    pic.stride = stp_row_bytes(STP_PIXEL_MONO1, w);
    pic.pixels = calloc(pic.stride, h);
    memset(&mem, 0, sizeof mem);
    mem.band_rows = band_rows;
    mem.band_size = pic.stride * band_rows;
    mem.band = malloc(mem.band_size);
    mem.zbuf_count = (size_t)w * band_rows;
    mem.zbuf = malloc(sizeof *mem.zbuf * mem.zbuf_count);
    if (!rmem || !pic.pixels || !mem.band || !mem.zbuf) {
        fprintf(stderr, "spin_host: out of memory\n");
        return 1;
    }
    port.width = w;
    port.height = h;
    port.format = STP_PIXEL_MONO1;
    port.flush = keep_band;
    port.user = &pic;
    r = stp_renderer_create(rmem, stp_renderer_size(), spin_display_file, spin_display_file_capacity, w, h);
    status = r ? spin_setup(r) : STP_ERR_ARG;
    for (n = 0; n <= last && status == STP_OK; n++) {
        status = spin_enter(r, n);
        if (status == STP_OK)
            status = spin_render(r, &port, &mem);
    }
    if (status != STP_OK) {
        fprintf(stderr, "spin_host: frame %u: %s\n", n, stp_status_text(status));
        return 1;
    }
    for (n = 0; n < pic.stride * h; n++) /* MONO1 1 = ON (white): PBM 1 = black */
        pic.pixels[n] = (uint8_t)~pic.pixels[n];
    f = fopen(out_path, "wb");
    if (!f || fprintf(f, "P4\n%u %u\n", w, h) < 0 || fwrite(pic.pixels, pic.stride, h, f) != h ||
        fclose(f) != 0) {
        perror(out_path);
        remove(out_path);
        return 1;
    }
    free(rmem);
    free(pic.pixels);
    free(mem.band);
    free(mem.zbuf);
    return 0;
}
