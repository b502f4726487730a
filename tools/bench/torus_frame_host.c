/* SPDX-License-Identifier: MIT */
/* The Cortex-M bench's torus frame (ports/mps2/torus_frame.c) on the host:
 * renders it and writes the 1-bit picture as PBM, for the firmware test to
 * compare with, and as a callgrind driver for the raster's profile.
 *
 * usage: torus_frame_host [-s WxH] [--band-rows N] [--frames N] [--mesh] [-o OUT.pbm]
 *   -s WxH         frame size (default 128x64)
 *   --band-rows N  rows per band (default: the whole frame)
 *   --frames N     frames to render (default 1; the last one is written)
 *   --mesh         enter the torus as one mesh (torus_enter_mesh)
 *   -o OUT.pbm     write the picture (binary PBM) */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "torus_frame.h"

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
    unsigned w = 128, h = 64, band_rows = 0, frames = 1, f;
    const char *out_path = 0;
    int i, status = STP_OK, use_mesh = 0;
    stp_mesh mesh;
    stp_mesh_bounds bounds;
    stp_vec3 *mesh_vertices;
    uint16_t *triangles;
    int16_t *normals;
    stp_mesh_vertex *scratch;
    stp_vec3 *vertices;
    stp_instr *df;
    void *rmem;
    stp_renderer *r;
    stp_port port;
    stp_frame_memory mem;
    picture pic;
    for (i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "-s") && i + 1 < argc && sscanf(argv[i + 1], "%ux%u", &w, &h) == 2) {
            i++;
        } else if (!strcmp(argv[i], "--band-rows") && i + 1 < argc) {
            band_rows = (unsigned)atoi(argv[++i]);
        } else if (!strcmp(argv[i], "--frames") && i + 1 < argc) {
            frames = (unsigned)atoi(argv[++i]);
        } else if (!strcmp(argv[i], "--mesh")) {
            use_mesh = 1;
        } else if (!strcmp(argv[i], "-o") && i + 1 < argc) {
            out_path = argv[++i];
        } else {
            fprintf(stderr, "usage: torus_frame_host [-s WxH] [--band-rows N] [--frames N] [--mesh] [-o OUT.pbm]\n");
            return 2;
        }
    }
    if (w < 1 || h < 1 || w > 32767 || h > 32767 || frames < 1) {
        fprintf(stderr, "torus_frame_host: bad size or frame count\n");
        return 2;
    }
    if (band_rows == 0 || band_rows > h)
        band_rows = h;
    vertices = malloc(sizeof *vertices * 3 * TORUS_TRIANGLES);
    df = malloc(sizeof *df * TORUS_DF_CAPACITY);
    rmem = malloc(stp_renderer_size());
    mesh_vertices = malloc(sizeof *mesh_vertices * TORUS_MESH_VERTICES);
    triangles = malloc(sizeof *triangles * 3 * TORUS_TRIANGLES);
    normals = malloc(sizeof *normals * 3 * TORUS_TRIANGLES);
    scratch = malloc(sizeof *scratch * TORUS_MESH_VERTICES);
    pic.stride = stp_row_bytes(STP_PIXEL_MONO1, w);
    pic.pixels = calloc(pic.stride, h);
    memset(&mem, 0, sizeof mem);
    mem.band_rows = band_rows;
    mem.band_size = pic.stride * band_rows;
    mem.band = malloc(mem.band_size);
    mem.zbuf_count = (size_t)w * band_rows;
    mem.zbuf = malloc(sizeof *mem.zbuf * mem.zbuf_count);
    if (!vertices || !df || !rmem || !pic.pixels || !mem.band || !mem.zbuf || !mesh_vertices ||
        !triangles || !normals || !scratch) {
        fprintf(stderr, "torus_frame_host: out of memory\n");
        return 1;
    }
    r = stp_renderer_create(rmem, stp_renderer_size(), df, TORUS_DF_CAPACITY, w, h);
    torus_build(vertices);
    port.width = w;
    port.height = h;
    port.format = STP_PIXEL_MONO1;
    port.flush = keep_band;
    port.user = &pic;
    status = r ? torus_setup(r) : STP_ERR_ARG;
    if (status == STP_OK && use_mesh)
        status = torus_mesh_build(&mesh, mesh_vertices, triangles, normals, &bounds);
    for (f = 0; f < frames && status == STP_OK; f++) {
        status = use_mesh ? torus_enter_mesh(r, &mesh, scratch) : torus_enter(r, vertices);
        if (status == STP_OK)
            status = torus_render(r, &port, &mem);
    }
    if (status != STP_OK) {
        fprintf(stderr, "torus_frame_host: %s\n", stp_status_text(status));
        return 1;
    }
    if (out_path) {
        FILE *fp = fopen(out_path, "wb");
        if (!fp || fprintf(fp, "P4\n%u %u\n", w, h) < 0 || fwrite(pic.pixels, pic.stride, h, fp) != h ||
            fclose(fp) != 0) {
            fprintf(stderr, "torus_frame_host: cannot write %s\n", out_path);
            return 1;
        }
    }
    free(vertices);
    free(mesh_vertices);
    free(triangles);
    free(normals);
    free(scratch);
    free(df);
    free(rmem);
    free(pic.pixels);
    free(mem.band);
    free(mem.zbuf);
    return 0;
}
