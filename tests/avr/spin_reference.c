/* SPDX-License-Identifier: MIT */
/*
 * The host's pictures of the Arduino spinning examples: frame N of the
 * cube or the teapot (the examples' generated mesh headers, drawn by
 * ports/arduino/src/stipple_spin.c and the host core) as a 128x64 PBM in
 * the simulator's convention (a lit pixel is white, PBM 0), straight from
 * the bands' rows (the sketch packs them into pages: the comparison checks
 * that too), to compare with the panel of a sketch run in simavr.
 *
 *   spin_reference cube|teapot N OUT.pbm
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "stipple/render.h"
#include "stipple_spin.h"

#include "../../ports/arduino/examples/SpinningCube/cube_mesh.h"
#include "../../ports/arduino/examples/SpinningTeapot/teapot_mesh.h"

#define W 128u
#define H 64u
#define STRIDE (W / 8u)

int main(int argc, char **argv)
{
    static stp_direct_point points[TEAPOT_VERTEX_COUNT > CUBE_VERTEX_COUNT ? TEAPOT_VERTEX_COUNT
                                                                           : CUBE_VERTEX_COUNT];
    static uint16_t faces[TEAPOT_TRIANGLE_COUNT > CUBE_TRIANGLE_COUNT ? TEAPOT_TRIANGLE_COUNT
                                                                      : CUBE_TRIANGLE_COUNT];
    uint8_t band[8 * STRIDE], pbm[H * STRIDE];
    const stp_mesh *mesh;
    stipple_spin spin;
    unsigned n, p, i;
    FILE *f;
    if (argc != 4 || (strcmp(argv[1], "cube") && strcmp(argv[1], "teapot"))) {
        fprintf(stderr, "usage: spin_reference cube|teapot N OUT.pbm\n");
        return 2;
    }
    mesh = !strcmp(argv[1], "cube") ? &cube_mesh : &teapot_mesh;
    n = (unsigned)strtoul(argv[2], 0, 10);
    if (stipple_spin_begin(&spin, mesh, points, faces) != STP_OK ||
        stipple_spin_frame(&spin, (uint16_t)n) != STP_OK) {
        fprintf(stderr, "spin_reference: frame %u of %s not drawn\n", n, argv[1]);
        return 1;
    }
    for (p = 0; p < H / 8u; p++) {
        if (stp_direct_draw_band(&spin.frame, band, STRIDE, (uint16_t)(8u * p), 8) != STP_OK)
            return 1;
        for (i = 0; i < sizeof band; i++)
            pbm[8u * p * STRIDE + i] = (uint8_t)~band[i]; /* ON (lit) is PBM 0 */
    }
    f = fopen(argv[3], "wb");
    if (!f || fprintf(f, "P4\n%u %u\n", W, H) < 0 || fwrite(pbm, 1, sizeof pbm, f) != sizeof pbm ||
        fclose(f) != 0) {
        perror(argv[3]);
        return 2;
    }
    return 0;
}
