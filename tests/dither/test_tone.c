/* SPDX-License-Identifier: MIT */
/*
 * Tone (tools/tone.h): automatic exposure brings the brightest drawn pixel
 * to the top level and scales the rest with it; --grey contrast keeps the
 * colours' contrast (the SPD tetrahedron's red faces and blue background
 * have nearly the same luminance); --background replaces the frame's.
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

#include "render_scene.h"
#include "stp_posix.h"
#include "test_scenes.h"
#include "tone.h"

static void grey_render(const stp_scene *scene, const stp_tool_options *opt, stp_posix_frame *f)
{
    char err[512];
    assert_int_equal(stp_posix_frame_init(f, (uint32_t)opt->width, (uint32_t)opt->height, STP_PIXEL_GREY8), 0);
    if (stp_tool_render(scene, opt, &f->port, 0, err, sizeof err) != 0)
        fail_msg("render failed: %s", err);
}

static unsigned brightest(const stp_posix_frame *f)
{
    size_t i;
    unsigned m = 0;
    for (i = 0; i < (size_t)f->width * f->height; i++)
        if (f->pixels[i] > m)
            m = f->pixels[i];
    return m;
}

/* teapot-s1 is dim: its brightest pixel is well below white; with
 * exposure it is 255 (256 levels), and a pixel's level grows by the same
 * factor where neither is clipped (within INTENSITY's floor: 1 level). */
static void test_exposure(void **state)
{
    stp_scene scene;
    stp_tool_options opt;
    stp_posix_frame plain, exposed;
    double gain;
    char err[256];
    size_t i;
    (void)state;
    stp_test_load_scene("teapot-s1", &scene);
    stp_tool_options_default(&opt);
    opt.levels = 256;
    opt.background_given = 1; /* a black frame: only drawn pixels */
    grey_render(&scene, &opt, &plain);
    opt.exposure_auto = 1;
    grey_render(&scene, &opt, &exposed);
    assert_true(brightest(&plain) < 200);
    assert_int_equal(brightest(&exposed), 255);
    assert_int_equal(stp_tool_exposure_gain(&scene, &opt, &gain, err, sizeof err), 0);
    assert_true(fabs(gain - 255.0 / brightest(&plain)) < 1e-9);
    for (i = 0; i < (size_t)plain.width * plain.height; i++) {
        double want = plain.pixels[i] * gain;
        if (want < 250 && fabs(exposed.pixels[i] - want) > gain + 1)
            fail_msg("pixel %zu: %u exposed to %u, expected about %.1f", i, plain.pixels[i],
                     exposed.pixels[i], want);
    }
    stp_posix_frame_free(&plain);
    stp_posix_frame_free(&exposed);
    stp_scene_free(&scene);
}

/* The tetrahedron (colour 1 .2 .2) on blue (.078 .361 .753): luminances
 * 0.44 and 0.32; the contrast greys are the two ends of their axis,
 * 1.087 / sqrt 3 = 0.63 apart around the mean luminance 0.38, so 0.69 and
 * 0.07; a grey scene keeps its greys. */
static void test_contrast_greys(void **state)
{
    stp_scene scene;
    double greys[4], bg = -1;
    (void)state;
    stp_test_load_scene("tetra-s1", &scene);
    assert_int_equal(scene.material_count, 1);
    stp_tool_contrast_greys(&scene, greys, &bg);
    assert_true(fabs(greys[0] - (0.3797 + 0.3138)) < 0.01);
    assert_true(fabs(bg - (0.3797 - 0.3138)) < 0.01);
    scene.materials[0].color[0] = scene.materials[0].color[1] = scene.materials[0].color[2] = 0.6;
    scene.background[0] = scene.background[1] = scene.background[2] = 0.2;
    stp_tool_contrast_greys(&scene, greys, &bg);
    assert_true(fabs(greys[0] - 0.6) < 1e-9);
    assert_true(fabs(bg - 0.2) < 1e-9);
    stp_scene_free(&scene);
}

/* In grey pictures the faces stand out from the background with --grey
 * contrast and hardly without. */
static void test_contrast_render(void **state)
{
    stp_scene scene;
    stp_tool_options opt;
    stp_posix_frame lum, con;
    unsigned bg_lum, bg_con;
    (void)state;
    stp_test_load_scene("tetra-s1", &scene);
    stp_tool_options_default(&opt);
    opt.levels = 256;
    grey_render(&scene, &opt, &lum);
    opt.grey_contrast = 1;
    grey_render(&scene, &opt, &con);
    bg_lum = lum.pixels[0];
    bg_con = con.pixels[0];
    assert_true(abs((int)bg_lum - 81) <= 1); /* luminance .319 */
    assert_true(abs((int)bg_con - 17) <= 1); /* contrast grey .066 */
    assert_true(brightest(&con) - bg_con > 2 * (brightest(&lum) - bg_lum));
    stp_posix_frame_free(&lum);
    stp_posix_frame_free(&con);
    stp_scene_free(&scene);
}

static void test_background(void **state)
{
    stp_scene scene;
    stp_tool_options opt;
    stp_posix_frame f;
    (void)state;
    stp_test_load_scene("tetra-s1", &scene);
    stp_tool_options_default(&opt);
    opt.levels = 256;
    opt.background_given = 1;
    opt.background_rgb[0] = opt.background_rgb[1] = opt.background_rgb[2] = 1.0;
    grey_render(&scene, &opt, &f);
    assert_int_equal(f.pixels[0], 255);
    stp_posix_frame_free(&f);
    stp_scene_free(&scene);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_exposure),        cmocka_unit_test(test_contrast_greys),
        cmocka_unit_test(test_contrast_render), cmocka_unit_test(test_background),
    };
    return cmocka_run_group_tests(tests, 0, 0);
}
