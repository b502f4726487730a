/* SPDX-License-Identifier: MIT */
/*
 * Golden images and band rendering on the shared scenes.
 *
 * - Each scene rendered at 128x64 to 1 bit (the stipple command's defaults)
 *   must equal tests/golden/NAME-128x64.pbm pixel for pixel.  On a mismatch
 *   the render is saved as NAME-128x64.actual.pbm in the build folder and the
 *   differing pixels are counted in the message.
 * - Band rendering: every scene, every pixel format and hidden-surface method,
 *   band heights 1, 3, 7 and 64 give the same bytes as one full frame.
 * The same program is also built over a core with Gouraud, colour and
 * transparency compiled out (test_golden_minimal): the flat scenes must come
 * out byte for byte the same.
 * Regenerate the goldens after an intended change with
 * tools/update_golden.sh (and say why in the commit).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "render_scene.h"
#include "stp_posix.h"
#include "test_scenes.h"

static const char *const scenes[] = {"tetra-s1", "tetra-s2", "mount-s2", "teapot-s1",
                                     "teapot-s2", "gears-s1", "balls-s1", "balls-s2"};
#define SCENE_COUNT (sizeof scenes / sizeof scenes[0])

static void render(const stp_scene *scene, const stp_tool_options *opt, stp_posix_frame *frame,
                   stp_pixel_format fmt)
{
    char err[512];
    assert_int_equal(stp_posix_frame_init(frame, (uint32_t)opt->width, (uint32_t)opt->height, fmt), 0);
    if (stp_tool_render(scene, opt, stp_posix_frame_port(frame), 0, err, sizeof err) != 0)
        fail_msg("render failed: %s", err);
}

/* Compare a 1-bit frame with tests/golden/<name>.pbm; on a mismatch save the
 * render beside the build as <name>.actual.pbm.  Returns the failures (0/1). */
static int compare_golden(const stp_posix_frame *frame, const char *name)
{
    stp_posix_image golden;
    char path[1024], err[512];
    uint32_t x, y, differ = 0;
    snprintf(path, sizeof path, "%s/tests/golden/%s.pbm", stp_test_env_or("STP_SOURCE_DIR", "."), name);
    if (stp_posix_read_pnm(path, &golden, err, sizeof err) != 0) {
        print_error("%s: no golden image (%s)\n", name, err);
        return 1;
    }
    assert_int_equal(golden.width, frame->width);
    assert_int_equal(golden.height, frame->height);
    for (y = 0; y < frame->height; y++)
        for (x = 0; x < frame->width; x++) {
            /* MONO1 bit 1 = ON = light; the PBM reader gives 255 for white */
            int on = (frame->pixels[y * frame->stride + x / 8] >> (7 - x % 8)) & 1;
            if (on != (golden.samples[y * golden.width + x] == 255))
                differ++;
        }
    stp_posix_image_free(&golden);
    if (differ) {
        char actual[1024];
        snprintf(actual, sizeof actual, "%s/%s.actual.pbm", stp_test_env_or("STP_BINARY_DIR", "."), name);
        (void)stp_posix_write(frame, actual, STP_POSIX_FILE_P4, err, sizeof err);
        print_error("%s: %u pixels differ from the golden image; render saved as %s\n", name,
                    differ, actual);
        return 1;
    }
    return 0;
}

#if STP_WITH_GOURAUD
/* Gouraud shading of the teapot's pp patches (smooth) against its golden. */
static void test_golden_smooth_teapot(void **state)
{
    stp_scene scene;
    stp_tool_options opt;
    stp_posix_frame frame;
    (void)state;
    stp_test_load_scene("teapot-s2", &scene);
    stp_tool_options_default(&opt);
    opt.smooth = 1;
    render(&scene, &opt, &frame, STP_PIXEL_MONO1);
    stp_scene_free(&scene);
    assert_int_equal(compare_golden(&frame, "teapot-s2-smooth-128x64"), 0);
    stp_posix_frame_free(&frame);
}

#endif

#if STP_WITH_EDGE_AA
/* Edge anti-aliasing (--edge-aa) on teapot-s1 against its golden, and bands
 * of 1, 3 and 7 rows equal to the whole frame, ordered dither and
 * Floyd-Steinberg, flat and (teapot-s2) Gouraud. */
static void test_golden_edge_aa(void **state)
{
    static const char *const names[] = {"teapot-s1", "teapot-s2"};
    static const int bands[] = {1, 3, 7};
    size_t n, b;
    int smooth, diffuse;
    (void)state;
    for (n = 0; n < 2; n++) {
        stp_scene scene;
        stp_test_load_scene(names[n], &scene);
        for (smooth = 0; smooth < 1 + STP_WITH_GOURAUD; smooth++)
            for (diffuse = 0; diffuse < 2; diffuse++) {
                stp_tool_options opt;
                stp_posix_frame whole, plain, banded;
                stp_tool_options_default(&opt);
                opt.edge_aa = 1;
                opt.smooth = smooth;
                if (diffuse)
                    opt.dither = STP_TOOL_DITHER_DIFFUSE; /* Floyd-Steinberg, serpentine */
                render(&scene, &opt, &whole, STP_PIXEL_MONO1);
                if (n == 0 && !smooth && !diffuse)
                    assert_int_equal(compare_golden(&whole, "teapot-s1-edge-aa-128x64"), 0);
                opt.edge_aa = 0;
                render(&scene, &opt, &plain, STP_PIXEL_MONO1);
                opt.edge_aa = 1;
                assert_memory_not_equal(plain.pixels, whole.pixels, whole.stride * whole.height);
                stp_posix_frame_free(&plain);
                for (b = 0; b < sizeof bands / sizeof bands[0]; b++) {
                    opt.band_rows = bands[b];
                    render(&scene, &opt, &banded, STP_PIXEL_MONO1);
                    if (memcmp(banded.pixels, whole.pixels, whole.stride * whole.height) != 0)
                        fail_msg("%s smooth %d diffusion %d: bands of %d rows differ from the frame",
                                 names[n], smooth, diffuse, bands[b]);
                    stp_posix_frame_free(&banded);
                }
                stp_posix_frame_free(&whole);
            }
        stp_scene_free(&scene);
    }
}
#endif

#if STP_WITH_SHADOWS || STP_WITH_RAYTRACE
/* Render each named scene at 128 x 64 with the default options changed by
 * `adjust` and compare it with tests/golden/<name><suffix>.pbm.  Returns
 * the failures. */
static int golden_series(const char *const *names, size_t count,
                         void (*adjust)(stp_tool_options *opt), const char *suffix)
{
    size_t i;
    int failures = 0;
    for (i = 0; i < count; i++) {
        stp_scene scene;
        stp_tool_options opt;
        stp_posix_frame frame;
        char name[128];
        stp_test_load_scene(names[i], &scene);
        stp_tool_options_default(&opt);
        adjust(&opt);
        render(&scene, &opt, &frame, STP_PIXEL_MONO1);
        stp_scene_free(&scene);
        snprintf(name, sizeof name, "%s%s", names[i], suffix);
        failures += compare_golden(&frame, name);
        stp_posix_frame_free(&frame);
    }
    return failures;
}
#endif

#if STP_WITH_SHADOWS
static void with_shadows(stp_tool_options *opt)
{
    opt->shadow_resolution = 256;
}

/* Shadow maps (256 texels square per light) on the balls and mount scenes. */
static void test_golden_shadows(void **state)
{
    static const char *const names[] = {"balls-s1", "mount-s2"};
    (void)state;
    assert_int_equal(golden_series(names, 2, with_shadows, "-shadows-128x64"), 0);
}
#endif

#if STP_WITH_RAYTRACE
static void with_raytrace(stp_tool_options *opt)
{
    opt->raytrace = 1;
}

/* Every scene ray-traced (stipple render --raytrace: depth 4, min weight
 * 1/64, the hierarchy) against its golden. */
static void test_golden_raytrace(void **state)
{
    (void)state;
    assert_int_equal(golden_series(scenes, SCENE_COUNT, with_raytrace, "-raytrace-128x64"), 0);
}
#endif

#if STP_WITH_COLOUR
/* Colour shading (10.45) to RGB888 against golden PPMs, byte for byte. */
static void test_golden_colour(void **state)
{
    /* the last one again with its glass spheres transparent, back to front */
    static const char *const colour_scenes[] = {"balls-s1", "mount-s2", "tetra-s1", "mount-s2"};
    static const char *const suffix[] = {"", "", "", "-transparent"};
    size_t i;
    int failures = 0;
    (void)state;
    for (i = 0; i < 4; i++) {
        stp_scene scene;
        stp_tool_options opt;
        stp_posix_frame frame;
        stp_posix_image golden;
        char path[1024], err[512];
        size_t k, differ = 0;
        stp_test_load_scene(colour_scenes[i], &scene);
        stp_tool_options_default(&opt);
        opt.colour = 1;
        if (*suffix[i]) {
            opt.transparency = STP_WITH_TRANSPARENCY;
            opt.hidden = STP_HIDDEN_PAINTER;
        }
        render(&scene, &opt, &frame, STP_PIXEL_RGB888);
        stp_scene_free(&scene);
        snprintf(path, sizeof path, "%s/tests/golden/%s%s-colour-128x64.ppm",
                 stp_test_env_or("STP_SOURCE_DIR", "."), colour_scenes[i], suffix[i]);
        if (stp_posix_read_pnm(path, &golden, err, sizeof err) != 0) {
            print_error("%s\n", err);
            failures++;
        } else {
            assert_int_equal(golden.channels, 3);
            assert_int_equal(golden.width * golden.height * 3, frame.stride * frame.height);
            for (k = 0; k < frame.stride * frame.height; k++)
                differ += frame.pixels[k] != golden.samples[k];
            stp_posix_image_free(&golden);
        }
        if (differ) {
            snprintf(path, sizeof path, "%s/%s%s-colour-128x64.actual.ppm", stp_test_env_or("STP_BINARY_DIR", "."),
                     colour_scenes[i], suffix[i]);
            (void)stp_posix_write(&frame, path, STP_POSIX_FILE_P6, err, sizeof err);
            print_error("%s: %zu samples differ; render saved as %s\n", colour_scenes[i], differ, path);
            failures++;
        }
        stp_posix_frame_free(&frame);
    }
    assert_int_equal(failures, 0);
}

#endif

static void test_golden_128x64(void **state)
{
    size_t i;
    int failures = 0;
    (void)state;
    for (i = 0; i < SCENE_COUNT; i++) {
        stp_scene scene;
        stp_tool_options opt;
        stp_posix_frame frame;
        char name[128];
        stp_test_load_scene(scenes[i], &scene);
        stp_tool_options_default(&opt);
        render(&scene, &opt, &frame, STP_PIXEL_MONO1);
        stp_scene_free(&scene);
        snprintf(name, sizeof name, "%s-128x64", scenes[i]);
        failures += compare_golden(&frame, name);
        stp_posix_frame_free(&frame);
    }
    assert_int_equal(failures, 0);
}

static void test_bands_equal_full_frame(void **state)
{
    static const stp_pixel_format formats[] = {STP_PIXEL_MONO1, STP_PIXEL_GREY8, STP_PIXEL_STYLE8};
    static const stp_hidden methods[] = {STP_HIDDEN_ZBUFFER, STP_HIDDEN_PAINTER, STP_HIDDEN_NONE};
    static const int bands[] = {1, 3, 7};
    size_t i, f, m, b;
    (void)state;
    for (i = 0; i < SCENE_COUNT; i++) {
        stp_scene scene;
        stp_test_load_scene(scenes[i], &scene);
        for (f = 0; f < 3; f++)
            for (m = 0; m < 3; m++) {
                stp_tool_options opt;
                stp_posix_frame full;
                stp_tool_options_default(&opt);
                opt.hidden = methods[m];
                opt.smooth = STP_WITH_GOURAUD ? (int)(i % 2) : 0; /* flat and Gouraud alike */
                render(&scene, &opt, &full, formats[f]);
                for (b = 0; b < 3; b++) {
                    stp_posix_frame banded;
                    opt.band_rows = bands[b];
                    render(&scene, &opt, &banded, formats[f]);
                    if (memcmp(full.pixels, banded.pixels, full.stride * full.height) != 0)
                        fail_msg("%s: format %d, hidden %d: %d-row bands differ from the full frame",
                                 scenes[i], (int)formats[f], (int)methods[m], bands[b]);
                    /* one flush per band proves the bands really were bands */
                    assert_int_equal(banded.bands, (64 + bands[b] - 1) / bands[b]);
                    stp_posix_frame_free(&banded);
                }
                assert_int_equal(full.bands, 1);
                stp_posix_frame_free(&full);
            }
        stp_scene_free(&scene);
    }
}

/* A render is not all one value: guards the goldens against pinning an
 * empty picture. */
static void test_renders_show_something(void **state)
{
    size_t i;
    (void)state;
    for (i = 0; i < SCENE_COUNT; i++) {
        stp_scene scene;
        stp_tool_options opt;
        stp_posix_frame frame;
        size_t k, levels_seen = 0;
        int seen[256] = {0};
        stp_test_load_scene(scenes[i], &scene);
        stp_tool_options_default(&opt);
        render(&scene, &opt, &frame, STP_PIXEL_STYLE8);
        for (k = 0; k < frame.stride * frame.height; k++)
            if (!seen[frame.pixels[k]]++)
                levels_seen++;
        if (levels_seen < 3)
            fail_msg("%s: only %zu styles in the picture", scenes[i], levels_seen);
        stp_posix_frame_free(&frame);
        stp_scene_free(&scene);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_golden_128x64),
#if STP_WITH_GOURAUD
        cmocka_unit_test(test_golden_smooth_teapot),
#endif
#if STP_WITH_EDGE_AA
        cmocka_unit_test(test_golden_edge_aa),
#endif
#if STP_WITH_COLOUR
        cmocka_unit_test(test_golden_colour),
#endif
#if STP_WITH_SHADOWS
        cmocka_unit_test(test_golden_shadows),
#endif
#if STP_WITH_RAYTRACE
        cmocka_unit_test(test_golden_raytrace),
#endif
        cmocka_unit_test(test_bands_equal_full_frame),
        cmocka_unit_test(test_renders_show_something),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
