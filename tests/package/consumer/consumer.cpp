// SPDX-License-Identifier: MIT
// A C++ program built against an installed stipple (find_package or
// pkg-config), core only: its own port keeps the frame; it renders a lit
// square and checks pixels (centre lit, corner background).
#include <cstdio>
#include <vector>

#include "stipple/stipple.h"

namespace {

const unsigned size = 16;

struct memory_port {
    stp_port port;
    std::vector<uint8_t> pixels;
};

int keep_rows(stp_port *port, uint32_t y0, uint32_t rows, const uint8_t *pixels, size_t stride)
{
    memory_port *self = static_cast<memory_port *>(port->user);
    for (uint32_t y = 0; y < rows; y++)
        for (uint32_t x = 0; x < size; x++)
            self->pixels[(y0 + y) * size + x] = pixels[y * stride + x];
    return 0;
}

} // namespace

int main()
{
    static stp_renderer_storage storage;
    static stp_instr display_file[64];
    static uint8_t band[size * 4];
    static uint16_t zbuf[size * 4];
    const stp_vec3 square[4] = {{-STP_FIX_ONE / 2, -STP_FIX_ONE / 2, 0},
                                {STP_FIX_ONE / 2, -STP_FIX_ONE / 2, 0},
                                {STP_FIX_ONE / 2, STP_FIX_ONE / 2, 0},
                                {-STP_FIX_ONE / 2, STP_FIX_ONE / 2, 0}};
    const stp_vec3 light = {0, 0, -2 * STP_FIX_ONE};
    memory_port out;
    out.pixels.assign(size * size, 0);
    out.port.width = size;
    out.port.height = size;
    out.port.format = STP_PIXEL_GREY8;
    out.port.flush = keep_rows;
    out.port.user = &out;
    // fields by name: later versions may add members
    stp_output output;
    stp_output_default(&output);
    stp_frame_memory memory = stp_frame_memory();
    memory.band = band;
    memory.band_size = sizeof band;
    memory.band_rows = 4;
    memory.zbuf = zbuf;
    memory.zbuf_count = size * 4;

    stp_renderer *r = stp_renderer_create(&storage, sizeof storage, display_file, 64, size, size);
    if (r == nullptr) {
        std::fprintf(stderr, "stp_renderer_create failed\n");
        return 1;
    }
    stp_renderer_set_light(r, light, STP_FIX_ONE, STP_FIX_ONE / 5);
    stp_renderer_set_shading(r, 1);
    stp_segment_create(r, 1);
    int status = stp_renderer_polygon(r, square, 4);
    stp_segment_close(r);
    if (status == STP_OK)
        status = stp_renderer_render(r, &out.port, &output, &memory);
    if (status != STP_OK) {
        std::fprintf(stderr, "stipple: %s\n", stp_status_text(status));
        return 1;
    }
    unsigned centre = out.pixels[8 * size + 8], corner = out.pixels[0];
    std::printf("stipple %s (C++): centre %u, corner %u\n", stp_version(), centre, corner);
    return centre > 0 && corner == 0 ? 0 : 1;
}
