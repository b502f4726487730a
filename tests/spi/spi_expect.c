/* SPDX-License-Identifier: MIT */
/* The expected picture and the glass comparison: see spi_expect.h. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "render_scene.h"
#include "spi_expect.h"
#include "test_scenes.h"

void spi_expected_render(const stp_scene *scene, uint32_t w, uint32_t h, stp_posix_frame *frame)
{
    stp_tool_options to;
    char err[512];
    uint32_t x, y, on = 0;
    stp_tool_options_default(&to);
    to.width = (int)w;
    to.height = (int)h;
    assert_int_equal(stp_posix_frame_init(frame, w, h, STP_PIXEL_MONO1), 0);
    if (stp_tool_render(scene, &to, stp_posix_frame_port(frame), NULL, err, sizeof err) != 0)
        fail_msg("render in memory: %s", err);
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++)
            on += (frame->pixels[y * frame->stride + x / 8] >> (7 - x % 8)) & 1u;
    if (!(on > w * h / 20 && on < w * h - w * h / 20))
        fail_msg("%u of %u pixels ON: not a useful test picture", on, w * h);
}

/* Saves a failing glass beside the build for a look. */
static void save_glass(spi_sim *sim, const char *name)
{
    stp_posix_frame f;
    char path[1024], err[256];
    uint32_t y;
    if (stp_posix_frame_init(&f, sim->width, sim->height, STP_PIXEL_MONO1) != 0)
        return;
    for (y = 0; y < sim->height; y++)
        memcpy(f.pixels + y * f.stride, sim->glass + y * sim->stride, f.stride);
    snprintf(path, sizeof path, "%s/%s.glass.pbm", stp_test_env_or("STP_BINARY_DIR", "."), name);
    if (stp_posix_write(&f, path, STP_POSIX_FILE_P4, err, sizeof err) == 0)
        print_message("glass saved as %s\n", path);
    stp_posix_frame_free(&f);
}

void spi_assert_glass(spi_sim *sim, const stp_posix_frame *want, const char *name)
{
    uint32_t x, y, diff = 0, fx = 0, fy = 0;
    assert_int_equal(sim->width, want->width);
    assert_int_equal(sim->height, want->height);
    g_mutex_lock(&sim->lock);
    for (y = 0; y < want->height; y++)
        for (x = 0; x < want->width; x++) {
            unsigned a = (sim->glass[y * sim->stride + x / 8] >> (7 - x % 8)) & 1u;
            unsigned b = (want->pixels[y * want->stride + x / 8] >> (7 - x % 8)) & 1u;
            if (a != b && diff++ == 0) {
                fx = x;
                fy = y;
            }
        }
    g_mutex_unlock(&sim->lock);
    if (diff) {
        save_glass(sim, name);
        fail_msg("%s: %u pixels differ from the render, the first at (%u, %u)", name, diff, fx,
                 fy);
    }
}
