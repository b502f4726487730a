/* SPDX-License-Identifier: MIT */
/*
 * Readable small pictures: the still default (stipple render to a 1-bit
 * file) on the shared scenes at 128x64.
 *
 * The readability R (tools/readable.h): along the visible silhouette edges,
 * the share of samples where the two sides' means of the 1-bit picture
 * differ by 0.2 or more, or the edge itself differs from both (a line).
 *
 * Tests: the measure on hand-made pictures (a step, the same grey both
 * sides, a line, a small step, an edge along the frame); balls-s1 and
 * balls-s2 at 128x64: R < 0.45 without outlines (0.38, 0.23: the default
 * before), R >= 0.5 with the default options (the rule draws silhouettes:
 * 0.74, 0.59); the six other scenes at 128x64: the default is the picture
 * without outlines (the rule leaves them alone) and has R >= 0.5.  400x240
 * is printed.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "outlines.h"
#include "readable.h"
#include "render_scene.h"
#include "stp_posix.h"
#include "test_scenes.h"


static const char *const scene_names[] = {"tetra-s1", "tetra-s2", "mount-s2", "teapot-s1",
                                          "teapot-s2", "gears-s1", "balls-s1", "balls-s2"};
#define SCENE_COUNT (sizeof scene_names / sizeof scene_names[0])

static void render(const stp_scene *scene, const stp_tool_options *opt, int w, int h, stp_pixel_format fmt,
                   uint8_t *out)
{
    stp_posix_frame f;
    char err[512];
    int x, y;
    assert_int_equal(stp_posix_frame_init(&f, (uint32_t)w, (uint32_t)h, fmt), 0);
    if (stp_tool_render(scene, opt, &f.port, 0, err, sizeof err) != 0)
        fail_msg("render failed: %s", err);
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++)
            out[y * w + x] = fmt == STP_PIXEL_MONO1
                                 ? (uint8_t)((f.pixels[(size_t)y * f.stride + (size_t)(x >> 3)] >> (7 - (x & 7))) & 1)
                                 : f.pixels[(size_t)y * f.stride + (size_t)x];
    stp_posix_frame_free(&f);
}

static double picture_r(const stp_scene *scene, void (*setup)(stp_tool_options *), int w, int h,
                        size_t *samples)
{
    static uint8_t bits[800 * 480];
    stp_tool_options opt;
    double *xy = 0, r;
    size_t count = 0;
    char err[256];
    stp_tool_options_default(&opt);
    stp_tool_still_defaults(&opt);
    opt.width = w;
    opt.height = h;
    if (setup)
        setup(&opt);
    render(scene, &opt, w, h, STP_PIXEL_MONO1, bits);
    if (stp_tool_outline_pixels(scene, &opt, STP_OUTLINE_SILHOUETTE, &xy, &count, err, sizeof err) != 0)
        fail_msg("outline pieces: %s", err);
    r = stp_tool_readability(bits, w, h, xy, count, samples);
    free(xy);
    return r;
}

static void no_outlines(stp_tool_options *opt)
{
    opt->outlines = 0;
    opt->outlines_auto = 0;
}

static void silhouettes(stp_tool_options *opt)
{
    opt->outlines = STP_OUTLINE_SILHOUETTE;
    opt->outlines_auto = 0;
}

/* The measure by hand: a vertical edge at x = 16 of a 32x16 picture. */
static void test_measure_by_hand(void **state)
{
    static unsigned char bits[32 * 16];
    const double edge[4] = {16, 2, 16, 14};
    size_t samples;
    int x, y;
    (void)state;
    /* a step: lit left of the edge, dark right: every sample reads */
    for (y = 0; y < 16; y++)
        for (x = 0; x < 32; x++)
            bits[y * 32 + x] = x < 16;
    assert_true(stp_tool_readability(bits, 32, 16, edge, 1, &samples) == 1.0);
    assert_int_equal(samples, 12);
    /* a checkerboard both sides (the same grey): none reads */
    for (y = 0; y < 16; y++)
        for (x = 0; x < 32; x++)
            bits[y * 32 + x] = (x + y) & 1;
    assert_true(stp_tool_readability(bits, 32, 16, edge, 1, &samples) == 0.0);
    /* a dark line on the edge (pixels 15 and 16) in a lit field: reads */
    for (y = 0; y < 16; y++)
        for (x = 0; x < 32; x++)
            bits[y * 32 + x] = x != 15 && x != 16;
    assert_true(stp_tool_readability(bits, 32, 16, edge, 1, &samples) == 1.0);
    /* a step of 1/8 (checkerboard against 5/8 lit): does not read */
    for (y = 0; y < 16; y++)
        for (x = 0; x < 32; x++)
            bits[y * 32 + x] = x < 16 ? (x + y) & 1 : ((x + 2 * y) % 8) < 5;
    assert_true(stp_tool_readability(bits, 32, 16, edge, 1, &samples) < 0.5);
    /* an edge along the frame's side has no second side: left out */
    {
        const double side[4] = {0, 2, 0, 14};
        assert_true(stp_tool_readability(bits, 32, 16, side, 1, &samples) == 1.0);
        assert_int_equal(samples, 0);
    }
}

static void test_readability(void **state)
{
    size_t s;
    int z;
    (void)state;
    for (z = 0; z < 2; z++)
        for (s = 0; s < SCENE_COUNT; s++) {
            int w = z ? 400 : 128, h = z ? 240 : 64;
            int balls = !strncmp(scene_names[s], "balls", 5);
            stp_scene scene;
            size_t samples;
            double r_default, r_plain, r_sil;
            stp_test_load_scene(scene_names[s], &scene);
            r_default = picture_r(&scene, 0, w, h, &samples);
            r_plain = picture_r(&scene, no_outlines, w, h, &samples);
            r_sil = picture_r(&scene, silhouettes, w, h, &samples);
            printf("%-9s %dx%d %4zu samples: R default %.2f, without outlines %.2f, with silhouettes %.2f\n",
                   scene_names[s], w, h, samples, r_default, r_plain, r_sil);
            if (z == 0 && balls) {
                /* the example: unreadable without lines, readable by default */
                assert_true(r_plain < STP_TOOL_READABLE_SHARE);
                assert_true(r_default >= 0.5);
            } else if (z == 0) {
                /* the others read already: the rule leaves them alone */
                assert_true(r_default == r_plain);
                assert_true(r_default >= 0.5);
            }
            stp_scene_free(&scene);
        }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_measure_by_hand),
        cmocka_unit_test(test_readability),
    };
    return cmocka_run_group_tests(tests, 0, 0);
}
