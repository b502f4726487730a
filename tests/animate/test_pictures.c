/* SPDX-License-Identifier: MIT */
/*
 * Small pictures that read well (tools/render_scene.c):
 *  - --smooth shades a coarse mesh's faces as flat shading does: on
 *    teapot-s1 at 128x64 the spout's region has, smooth, a mean grey within
 *    0.05 of the flat picture's (it was 0.199 against 0.407: a near-black
 *    spout, from analytic vertex normals turned far from their faces).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "render_scene.h"
#include "stp_posix.h"
#include "test_scenes.h"

/* Mean grey (0..1) of the GREY8 render's box [x0, x1] x [y0, y1]. */
static double region_mean(const stp_scene *scene, const stp_tool_options *opt, int x0, int y0, int x1, int y1)
{
    stp_posix_frame f;
    char err[512];
    double sum = 0;
    int x, y;
    assert_int_equal(stp_posix_frame_init(&f, (uint32_t)opt->width, (uint32_t)opt->height, STP_PIXEL_GREY8), 0);
    if (stp_tool_render(scene, opt, stp_posix_frame_port(&f), 0, err, sizeof err) != 0)
        fail_msg("render: %s", err);
    for (y = y0; y <= y1; y++)
        for (x = x0; x <= x1; x++)
            sum += f.pixels[(size_t)y * f.stride + (size_t)x];
    stp_posix_frame_free(&f);
    return sum / 255.0 / ((x1 - x0 + 1) * (y1 - y0 + 1));
}

static void smooth_spout_as_flat(void **state)
{
    stp_scene scene;
    stp_tool_options opt;
    double flat, smooth;
    (void)state;
    stp_test_load_scene("teapot-s1", &scene);
    stp_tool_options_default(&opt);
    opt.levels = 256;
    /* the spout, left of the body */
    flat = region_mean(&scene, &opt, 37, 22, 49, 29);
    opt.smooth = 1;
    smooth = region_mean(&scene, &opt, 37, 22, 49, 29);
    print_message("teapot-s1 spout region: flat %.3f, smooth %.3f\n", flat, smooth);
    assert_true(flat > 0.3);
    assert_true(smooth > flat - 0.05 && smooth < flat + 0.05);
    stp_scene_free(&scene);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(smooth_spout_as_flat),
    };
    return cmocka_run_group_tests(tests, 0, 0);
}
