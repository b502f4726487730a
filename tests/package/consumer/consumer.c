/* SPDX-License-Identifier: MIT */
/* A C program built against an installed stipple (find_package or
 * pkg-config): it renders a lit square into the POSIX port's frame and
 * checks pixels, so a broken package (headers, library, configuration) makes
 * it fail to build or exit non-zero. */
#include <stdio.h>
#include <string.h>

#include "stipple/stipple.h"
#include "stp_posix.h"

#define SIZE 16

int main(void)
{
    static stp_renderer_storage storage;
    static stp_instr display_file[64];
    static uint8_t band[SIZE * SIZE];
    static uint16_t zbuf[SIZE * SIZE];
    const stp_vec3 square[4] = {{-STP_FIX_ONE / 2, -STP_FIX_ONE / 2, 0},
                                {STP_FIX_ONE / 2, -STP_FIX_ONE / 2, 0},
                                {STP_FIX_ONE / 2, STP_FIX_ONE / 2, 0},
                                {-STP_FIX_ONE / 2, STP_FIX_ONE / 2, 0}};
    const stp_vec3 light = {0, 0, -2 * STP_FIX_ONE};
    stp_posix_frame frame;
    stp_output output;
    stp_frame_memory memory;
    stp_renderer *r;
    int status;
    uint8_t centre, corner;

    /* fields by name: later versions may add members */
    stp_output_default(&output);
    memset(&memory, 0, sizeof memory);
    memory.band = band;
    memory.band_size = sizeof band;
    memory.band_rows = SIZE;
    memory.zbuf = zbuf;
    memory.zbuf_count = SIZE * SIZE;
    if (stp_posix_frame_init(&frame, SIZE, SIZE, STP_PIXEL_GREY8) != 0)
        return 1;
    r = stp_renderer_create(&storage, sizeof storage, display_file, 64, SIZE, SIZE);
    if (r == NULL) {
        fprintf(stderr, "stp_renderer_create failed\n");
        return 1;
    }
    stp_renderer_set_light(r, light, STP_FIX_ONE, STP_FIX_ONE / 5);
    stp_renderer_set_shading(r, 1);
    stp_segment_create(r, 1);
    status = stp_renderer_polygon(r, square, 4);
    stp_segment_close(r);
    if (status == STP_OK)
        status = stp_renderer_render(r, stp_posix_frame_port(&frame), &output, &memory);
    if (status != STP_OK) {
        fprintf(stderr, "stipple: %s\n", stp_status_text(status));
        return 1;
    }
    centre = frame.pixels[8 * frame.stride + 8];
    corner = frame.pixels[0];
    stp_posix_frame_free(&frame);
    printf("stipple %s: centre %u, corner %u\n", stp_version(), centre, corner);
    return centre > 0 && corner == 0 ? 0 : 1;
}
