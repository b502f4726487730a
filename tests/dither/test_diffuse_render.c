/* SPDX-License-Identifier: MIT */
/*
 * Error diffusion while rendering (render.h stp_output.diffusion, raytrace.h
 * stp_rt_render) on the shared scenes, every kernel, serpentine or not, and
 * with blue-noise threshold modulation (fs:blue, the still default):
 *  - the 1-bit picture equals the same scene rendered to 8-bit grey and
 *    then diffused row by row (stp_diffuse_row), pixel for pixel: so the
 *    diffusion sees exactly the shades the other formats show, flat,
 *    Gouraud, ray-traced and transparent (whose read-back is then the grey
 *    band's, not a 1-bit pixel's);
 *  - band rendering (1, 3 and 7 rows) equals the whole frame, pixel for
 *    pixel (the error rows carry across bands);
 *  - a band buffer sized for 1-bit rows is refused (the band is grey).
 */
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

static const char *const scene_names[] = {"tetra-s1", "tetra-s2", "mount-s2", "teapot-s1",
                                          "teapot-s2", "gears-s1", "balls-s1", "balls-s2"};
#define SCENE_COUNT (sizeof scene_names / sizeof scene_names[0])

typedef enum variant { FLAT, SMOOTH, TRANSPARENT_ZBUFFER, TRANSPARENT_PAINTER, RAYTRACED } variant;

static void options_for(stp_tool_options *opt, variant v, int kernel, int serpentine)
{
    stp_tool_options_default(opt);
    opt->levels = 256;
    opt->dither = STP_TOOL_DITHER_DIFFUSE;
    opt->diffuse_kernel = kernel;
    opt->diffuse_raster = serpentine != 1;
    opt->diffuse_noise = serpentine == 2; /* 2: rows left to right, blue-noise thresholds */
    switch (v) {
    case SMOOTH: opt->smooth = 1; break;
    case TRANSPARENT_ZBUFFER: opt->transparency = 1; break;
    case TRANSPARENT_PAINTER:
        opt->transparency = 1;
        opt->hidden = STP_HIDDEN_PAINTER;
        break;
    case RAYTRACED: opt->raytrace = 1; break;
    default: break;
    }
}

static void render(const stp_scene *scene, const stp_tool_options *opt, stp_pixel_format fmt,
                   stp_posix_frame *f)
{
    char err[512];
    assert_int_equal(stp_posix_frame_init(f, (uint32_t)opt->width, (uint32_t)opt->height, fmt), 0);
    if (stp_tool_render(scene, opt, &f->port, 0, err, sizeof err) != 0)
        fail_msg("render failed: %s", err);
}

static void check_scene(const char *name, variant v)
{
    stp_scene scene;
    int kernel, serpentine;
    stp_test_load_scene(name, &scene);
    for (kernel = 0; kernel < STP_DIFFUSE_KERNELS; kernel++)
        for (serpentine = 0; serpentine < 3; serpentine++) {
            stp_tool_options opt;
            stp_posix_frame whole, grey, banded;
            stp_diffusion d;
            uint32_t y;
            static const int bands[] = {1, 3, 7};
            size_t b, lit = 0;
            options_for(&opt, v, kernel, serpentine);
            render(&scene, &opt, STP_PIXEL_MONO1, &whole);
            /* the grey picture, diffused afterwards */
            opt.dither = STP_TOOL_DITHER_BAYER4;
            render(&scene, &opt, STP_PIXEL_GREY8, &grey);
            opt.dither = STP_TOOL_DITHER_DIFFUSE;
            assert_int_equal(stp_tool_diffusion(&opt, grey.width, &d), 1);
            for (y = 0; y < grey.height; y++) {
                uint8_t *row = grey.pixels + (size_t)y * grey.stride;
                size_t i;
                stp_diffuse_row(&d, row, grey.width, y);
                for (i = 0; i < whole.stride; i++)
                    lit += (size_t)__builtin_popcount(row[i]);
                if (memcmp(row, whole.pixels + (size_t)y * whole.stride, whole.stride) != 0)
                    fail_msg("%s variant %d kernel %d serpentine %d: row %u differs from the grey "
                             "picture diffused",
                             name, (int)v, kernel, serpentine, (unsigned)y);
            }
            free(d.errors);
            /* a picture with nothing lit would make the comparisons empty */
            assert_true(lit > 0);
            for (b = 0; b < sizeof bands / sizeof bands[0]; b++) {
                opt.band_rows = bands[b];
                render(&scene, &opt, STP_PIXEL_MONO1, &banded);
                if (memcmp(banded.pixels, whole.pixels, whole.stride * whole.height) != 0)
                    fail_msg("%s variant %d kernel %d serpentine %d: bands of %d rows differ from the "
                             "whole frame",
                             name, (int)v, kernel, serpentine, bands[b]);
                stp_posix_frame_free(&banded);
            }
            stp_posix_frame_free(&whole);
            stp_posix_frame_free(&grey);
        }
    stp_scene_free(&scene);
}

static void test_flat(void **state)
{
    size_t i;
    (void)state;
    for (i = 0; i < SCENE_COUNT; i++)
        check_scene(scene_names[i], FLAT);
}

static void test_smooth(void **state)
{
    (void)state;
    check_scene("teapot-s2", SMOOTH);
    check_scene("balls-s1", SMOOTH);
}

static void test_transparent(void **state)
{
    (void)state;
    /* mount-s2's glass spheres are transparent (T > 0) */
    check_scene("mount-s2", TRANSPARENT_ZBUFFER);
    check_scene("mount-s2", TRANSPARENT_PAINTER);
}

static void test_raytraced(void **state)
{
    (void)state;
    check_scene("tetra-s1", RAYTRACED);
    check_scene("mount-s2", RAYTRACED);
}

/* The band holds grey rows while diffusing: a 1-bit-sized band is refused,
 * as is an error row one entry short. */
static void test_memory_checked(void **state)
{
    stp_renderer_storage storage;
    stp_instr df[64];
    stp_renderer *r = stp_renderer_create(&storage, sizeof storage, df, 64, 16, 4);
    uint8_t band[16 * 4];
    int16_t errs[2 * 20];
    stp_diffusion d;
    stp_output out;
    stp_frame_memory mem;
    stp_posix_frame f;
    (void)state;
    assert_non_null(r);
    assert_int_equal(stp_posix_frame_init(&f, 16, 4, STP_PIXEL_MONO1), 0);
    memset(&out, 0, sizeof out);
    memset(&mem, 0, sizeof mem);
    memset(&d, 0, sizeof d);
    d.kernel = STP_DIFFUSE_FLOYD_STEINBERG;
    d.serpentine = 0;
    d.errors = errs;
    d.error_count = 2 * 20;
    out.hidden = STP_HIDDEN_NONE;
    out.background = STP_FIX_ONE / 2;
    out.diffusion = &d;
    mem.band = band;
    mem.band_rows = 4;
    mem.band_size = 2 * 4; /* MONO1 rows */
    assert_int_equal(stp_renderer_render(r, &f.port, &out, &mem), STP_ERR_MEMORY);
    mem.band_size = sizeof band;
    d.error_count = 2 * 20 - 1;
    assert_int_equal(stp_renderer_render(r, &f.port, &out, &mem), STP_ERR_MEMORY);
    d.error_count = 2 * 20;
    assert_int_equal(stp_renderer_render(r, &f.port, &out, &mem), STP_OK);
    /* a mid-grey frame: FS gives a checkerboard of 0x55 / 0xAA rows (by
     * hand: 127 is OFF, passing 7/16 of 127 right; 182.6 is ON ...) */
    assert_true(f.pixels[0] == 0x55 || f.pixels[0] == 0xAA);
    stp_posix_frame_free(&f);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_memory_checked), cmocka_unit_test(test_flat),
        cmocka_unit_test(test_smooth),         cmocka_unit_test(test_transparent),
        cmocka_unit_test(test_raytraced),
    };
    return cmocka_run_group_tests(tests, 0, 0);
}
