/* SPDX-License-Identifier: MIT */
/*
 * The core's ray tracer (include/stipple/raytrace.h):
 *   - every shared scene against the double-precision reference ray tracer
 *     (tools/bench/raytrace_ref.c, given the same quantised inputs), pixel
 *     by pixel;
 *   - the hierarchy sees exactly what testing every object sees;
 *   - band heights and pixel formats do not change the picture;
 *   - stiff cases (the stability suite of the ray tracer): distant and
 *     near-limit objects, grazing and tangent rays, secondary rays leaving
 *     a surface (reflection, refraction, shadows at a low sun), cones;
 *   - the shadow-terminator seams: the teapot at size 3, whose patches
 *     must not be shadowed by their own neighbouring facets where the
 *     interpolated normal faces the light;
 *   - argument errors.
 */
#define _POSIX_C_SOURCE 200809L
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "render_scene.h"
#include "rt_compare.h"
#include "test_scenes.h"
#include "scene.h"
#include "scenegen_private.h"
#include "stipple/stipple.h"

static const char *const scenes[] = {"tetra-s1", "tetra-s2", "mount-s2", "teapot-s1",
                                     "teapot-s2", "gears-s1", "balls-s1", "balls-s2"};
#define SCENE_COUNT (sizeof scenes / sizeof scenes[0])

static void parse(const char *text, stp_scene *scene)
{
    char err[512];
    stp_scene_options sopt;
    stp_scene_options_default(&sopt);
    if (stp_scene_parse(text, strlen(text), "nff", "case", &sopt, scene, err, sizeof err) != 0)
        fail_msg("cannot parse: %s", err);
}

static void options(stp_tool_options *opt, int w, int h)
{
    stp_tool_options_default(opt);
    opt->raytrace = 1;
    opt->width = w;
    opt->height = h;
}

/* Core against reference over a whole frame: the mean error and the share
 * of pixels more than 1/30 off (another object seen: silhouettes, shadow
 * edges) must stay within the bounds.  Returns the error for more checks. */
static stp_rt_error check_against_reference(const char *name, const stp_scene *scene,
                                            const stp_tool_options *opt, double mean_bound,
                                            double share_bound)
{
    stp_rt_error e;
    char err[512];
    double share;
    if (stp_rt_compare(scene, opt, &e, 0, err, sizeof err) != 0)
        fail_msg("%s: %s", name, err);
    share = (double)e.above_step / (double)e.pixels;
    print_message("%-22s max %.3e at (%d, %d), mean %.3e, %ld of %ld pixels above 1/30, %ld "
                  "styles differ\n",
                  name, e.max, e.max_x, e.max_y, e.mean, e.above_step, e.pixels, e.style_differs);
    if (e.mean > mean_bound || share > share_bound)
        fail_msg("%s: mean error %.3e (bound %.1e), %.3f%% of pixels above 1/30 (bound %.2f%%)",
                 name, e.mean, mean_bound, 100 * share, 100 * share_bound);
    return e;
}

/* The shared scenes at 96 x 64, depth 4. */
static void test_scenes_against_reference(void **state)
{
    size_t i;
    (void)state;
    for (i = 0; i < SCENE_COUNT; i++) {
        stp_scene scene;
        stp_tool_options opt;
        stp_test_load_scene(scenes[i], &scene);
        options(&opt, 96, 64);
        (void)check_against_reference(scenes[i], &scene, &opt, 2e-3, 0.01);
        stp_scene_free(&scene);
    }
}

/* Every pixel's shade through the hierarchy equals the one from testing
 * every object (same nearest hit, ties to the lower index). */
static void test_hierarchy_equals_every_object(void **state)
{
    size_t i;
    (void)state;
    for (i = 0; i < SCENE_COUNT; i++) {
        stp_scene scene;
        stp_tool_options opt;
        stp_tool_rt with, without;
        stp_tool_stats st;
        stp_rt_stats a, b;
        char err[512];
        uint32_t x, y;
        long differ = 0;
        stp_test_load_scene(scenes[i], &scene);
        options(&opt, 80, 60);
        memset(&st, 0, sizeof st);
        assert_int_equal(stp_tool_rt_build(&scene, &opt, &with, &st, err, sizeof err), 0);
        opt.rt_hierarchy = 0;
        assert_int_equal(stp_tool_rt_build(&scene, &opt, &without, &st, err, sizeof err), 0);
        for (y = 0; y < 60; y++)
            for (x = 0; x < 80; x++) {
                stp_fix s1[3], s2[3];
                assert_int_equal(stp_rt_trace_pixel(with.rt, x, y, 0, s1), STP_OK);
                assert_int_equal(stp_rt_trace_pixel(without.rt, x, y, 0, s2), STP_OK);
                differ += s1[0] != s2[0];
            }
        stp_rt_get_stats(with.rt, &a);
        stp_rt_get_stats(without.rt, &b);
        if (differ)
            fail_msg("%s: %ld pixels differ between the hierarchy and every object", scenes[i],
                     differ);
        /* and it must save work where there is something to save */
        if (stp_rt_object_count(with.rt) > 16 && a.object_tests * 2 > b.object_tests)
            fail_msg("%s: the hierarchy tested %u objects, every-object %u", scenes[i],
                     a.object_tests, b.object_tests);
        assert_int_equal(a.rays, b.rays);
        stp_tool_rt_free(&with);
        stp_tool_rt_free(&without);
        stp_scene_free(&scene);
    }
}

typedef struct capture {
    uint8_t *pixels;
    size_t stride;
} capture;

static int capture_flush(stp_port *port, uint32_t y0, uint32_t rows, const uint8_t *pixels,
                         size_t stride)
{
    capture *c = (capture *)port->user;
    uint32_t r;
    for (r = 0; r < rows; r++)
        memcpy(c->pixels + (size_t)(y0 + r) * c->stride, pixels + (size_t)r * stride, stride);
    return 0;
}

/* The picture does not depend on the band height, in every format. */
static void test_bands_equal_full_frame(void **state)
{
    static const stp_pixel_format formats[] = {STP_PIXEL_MONO1, STP_PIXEL_GREY8,
                                               STP_PIXEL_STYLE8, STP_PIXEL_RGB888};
    static const uint32_t bands[] = {1, 3, 7};
    const uint32_t w = 67, h = 45;
    stp_scene scene;
    stp_tool_options opt;
    stp_tool_rt t;
    stp_tool_stats st;
    char err[512];
    size_t f, b;
    (void)state;
    stp_test_load_scene("balls-s1", &scene);
    options(&opt, (int)w, (int)h);
    memset(&st, 0, sizeof st);
    assert_int_equal(stp_tool_rt_build(&scene, &opt, &t, &st, err, sizeof err), 0);
    for (f = 0; f < 4; f++) {
        size_t stride = stp_row_bytes(formats[f], w);
        uint8_t *full = calloc(stride * h, 1), *banded = calloc(stride * h, 1);
        uint8_t *band = malloc(stride * h);
        stp_output out;
        stp_port port;
        capture cap;
        memset(&out, 0, sizeof out);
        out.background = STP_FIX_ONE / 3;
        port.width = w;
        port.height = h;
        port.format = formats[f];
        port.flush = capture_flush;
        port.user = &cap;
        cap.stride = stride;
        cap.pixels = full;
        assert_int_equal(stp_rt_render(t.rt, &port, &out, band, stride * h, h), STP_OK);
        for (b = 0; b < 3; b++) {
            memset(banded, 0xA5, stride * h);
            cap.pixels = banded;
            assert_int_equal(stp_rt_render(t.rt, &port, &out, band, stride * bands[b], bands[b]),
                             STP_OK);
            if (memcmp(full, banded, stride * h) != 0)
                fail_msg("format %d, bands of %u rows: picture differs", (int)formats[f], bands[b]);
        }
        /* a band buffer too small is refused */
        assert_int_equal(stp_rt_render(t.rt, &port, &out, band, stride * 2 - 1, 2), STP_ERR_MEMORY);
        free(full);
        free(banded);
        free(band);
    }
    stp_tool_rt_free(&t);
    stp_scene_free(&scene);
}

/* ---- the stability suite ---------------------------------------------- */

typedef struct stiff_case {
    const char *name;
    const char *nff;
    double mean_bound, share_bound;
} stiff_case;

static const stiff_case stiff_cases[] = {
    /* a sphere of radius 4 3000 units away, filling most of the view (fov
     * 0.2 degrees; the focal length, 18335 pixels, is near stp_fix's
     * limit): b = 3000, h^2 = r^2 - |p|^2 of order 10 */
    {"distant sphere",
     "v\nfrom 0 0 3000\nat 0 0 0\nup 0 1 0\nangle 0.2\nhither 1\nresolution 64 64\n"
     "b 0.1 0.1 0.1\nl 10 20 3000\nf 1 1 1 0.8 0.2 20 0 1\ns 0 0 0 4\n",
     2e-3, 0.02},
    /* objects near the coordinate limit (4096 at F = 16) */
    {"near the limit",
     "v\nfrom 4000 4000 4000\nat 3990 3990 3990\nup 0 0 1\nangle 40\nhither 0.01\n"
     "resolution 64 64\nb 0 0 0\nl 4000 3990 4000\nf 1 1 1 0.8 0.3 20 0 1\n"
     "s 3990 3990 3990 3\np 4\n3980 3980 3987\n4000 3980 3987\n4000 4000 3987\n3980 4000 3987\n",
     2e-3, 0.02},
    /* a floor seen at a grazing angle: the eye 0.02 above a 200-unit
     * plane; rays near its horizon meet it at cosines down to 1e-4 */
    {"grazing floor",
     "v\nfrom 0 0 0.02\nat 10 0 0\nup 0 0 1\nangle 30\nhither 0.001\nresolution 64 64\n"
     "b 0.3 0.3 0.3\nl 5 5 5\nf 1 1 1 0.9 0 20 0 1\n"
     "p 4\n-100 -100 0\n100 -100 0\n100 100 0\n-100 100 0\n",
     2e-3, 0.03},
    /* a low sun (1 degree above a mirror floor): shadow and reflected rays
     * start on the floor almost along it; none may hit the floor itself */
    {"low sun on a mirror",
     "v\nfrom 0 -8 3\nat 0 0 0\nup 0 0 1\nangle 45\nhither 0.01\nresolution 64 64\n"
     "b 0.2 0.3 0.5\nl 0 1000 17.45\nf 1 1 1 0.6 0.8 20 0 1\n"
     "p 4\n-20 -20 0\n20 -20 0\n20 20 0\n-20 20 0\nf 1 1 1 0.7 0.3 20 0 1\ns 0 0 1 1\n",
     2e-3, 0.02},
    /* glass spheres (n 1.5): refracted rays start on a sphere heading in
     * and must take its far side, then leave */
    {"glass spheres",
     "v\nfrom 0 -6 2\nat 0 0 1\nup 0 0 1\nangle 40\nhither 0.01\nresolution 64 64\n"
     "b 0.5 0.5 0.5\nl 3 -4 8\nf 1 1 1 0.8 0 20 0 1\n"
     "p 4\n-10 -10 0\n10 -10 0\n10 10 0\n-10 10 0\nf 1 1 1 0.1 0.1 50 0.9 1.5\n"
     "s -1 0 1 1\ns 1.2 0.5 1 0.8\n",
     2e-3, 0.03},
    /* cones: a cylinder, a cone to a point, a truncated cone and a steep
     * one (slope 8), lit from the side */
    {"cones",
     "v\nfrom 0 -10 4\nat 0 0 1\nup 0 0 1\nangle 40\nhither 0.01\nresolution 64 64\n"
     "b 0.4 0.4 0.4\nl 5 -5 8\nf 1 1 1 0.8 0.3 20 0 1\n"
     "c\n-3 0 0 0.7\n-3 0 2.5 0.7\nc\n-1 0 0 1\n-1 0 2.5 0\nc\n1.2 0 0 0.3\n1.2 0 2 1\n"
     "c\n3 0 0.5 0.05\n3 0 0.6 0.85\n",
     2e-3, 0.03},
    /* a ray along a cylinder's axis, and rays tangent to a sphere: a view
     * straight down an open pipe with a ball whose silhouette falls on the
     * pixel centres */
    {"axis and tangents",
     "v\nfrom 0 0 10\nat 0 0 0\nup 0 1 0\nangle 30\nhither 0.01\nresolution 64 64\n"
     "b 0.9 0.9 0.9\nl 1 1 20\nf 1 1 1 0.8 0.3 20 0 1\nc\n0 0 -2 1\n0 0 4 1\n"
     "s 0 0 -3 0.5\n",
     2e-3, 0.03},
};

static void test_stiff_cases(void **state)
{
    size_t i;
    (void)state;
    for (i = 0; i < sizeof stiff_cases / sizeof stiff_cases[0]; i++) {
        stp_scene scene;
        stp_tool_options opt;
        parse(stiff_cases[i].nff, &scene);
        options(&opt, 64, 64);
        opt.auto_power = 0; /* the lights' powers as the case gives them */
        (void)check_against_reference(stiff_cases[i].name, &scene, &opt, stiff_cases[i].mean_bound,
                                      stiff_cases[i].share_bound);
        stp_scene_free(&scene);
    }
}

/* The low sun must not darken the mirror floor where nothing is between
 * it and the sun: every floor pixel the reference sees lit, the core sees
 * lit too (no self-shadowing "acne"). */
static void test_no_self_shadow(void **state)
{
    stp_scene scene;
    stp_tool_options opt;
    stp_rt_error e;
    char err[512];
    double *shades;
    long acne = 0, i, n = 64 * 64;
    (void)state;
    parse(stiff_cases[3].nff, &scene);
    options(&opt, 64, 64);
    opt.auto_power = 0;
    opt.rt_depth = 0; /* local shade only: shadows, no reflections */
    shades = malloc(sizeof *shades * 2 * (size_t)n);
    assert_non_null(shades);
    assert_int_equal(stp_rt_compare(&scene, &opt, &e, shades, err, sizeof err), 0);
    for (i = 0; i < n; i++)
        if (shades[n + i] - shades[i] > 0.02)
            acne++;
    print_message("low sun, depth 0: %ld of %ld pixels darker than the reference\n", acne, n);
    assert_true(acne <= n / 200);
    free(shades);
    stp_scene_free(&scene);
}

/* The SPD teapot at size 3 (stipple scene teapot --size 3), parsed. */
static void teapot_s3(stp_scene *scene)
{
    char *text = 0, err[512];
    size_t len = 0;
    stp_scene_options sopt;
    FILE *f = open_memstream(&text, &len);
    assert_non_null(f);
    assert_int_equal(stp_sg_write_teapot(f, 3), 0);
    assert_int_equal(fclose(f), 0);
    stp_scene_options_default(&sopt);
    if (stp_scene_parse(text, len, "nff", "teapot-s3", &sopt, scene, err, sizeof err) != 0)
        fail_msg("cannot parse teapot-s3: %s", err);
    free(text);
}

/* The seams: the ray-traced teapot (depth 0: local shade and shadows)
 * against the double reference whose shadow rays leaving a patch ignore
 * the facets sharing a corner with it (the smooth surface, which does not
 * shade itself where its normal faces the light).  A pixel the core draws
 * more than 1/30 darker is a seam.  Before the terminator fix 72 of 32 768
 * pixels (the lid's rim, the base); after it 0.  The bound 8 leaves room
 * for a shadow edge that falls a pixel apart (the core's shadow ray starts
 * STP_RT_OFFSET off the facet, the reference's on it). */
static void test_terminator_seams(void **state)
{
    stp_scene scene;
    stp_tool_options opt;
    stp_rt_error e;
    char err[512];
    double *shades;
    long seams = 0, i, n = 256 * 128;
    (void)state;
    teapot_s3(&scene);
    options(&opt, 256, 128);
    opt.rt_depth = 0;
    shades = malloc(sizeof *shades * 2 * (size_t)n);
    assert_non_null(shades);
    if (stp_rt_compare(&scene, &opt, &e, shades, err, sizeof err) != 0)
        fail_msg("teapot-s3: %s", err);
    for (i = 0; i < n; i++)
        if (shades[n + i] - shades[i] > 1.0 / 30)
            seams++;
    print_message("teapot-s3, depth 0: %ld of %ld pixels darker than the reference (seams)\n",
                  seams, n);
    assert_true(seams <= 8);
    free(shades);
    stp_scene_free(&scene);
}

/* ---- arguments ---------------------------------------------------------- */

static void test_arguments(void **state)
{
    static stp_raytracer_storage storage;
    stp_rt_object objects[4];
    stp_vec3 points[8], tri[3];
    stp_rt_node nodes[7];
    uint32_t order[4];
    stp_rt_memory mem;
    stp_raytracer *rt;
    stp_rt_material mat;
    stp_vec3 c = {0, 0, 0};
    stp_fix out[3];
    (void)state;
    assert_true(stp_rt_size() <= sizeof storage);
    memset(&mem, 0, sizeof mem);
    mem.objects = objects;
    mem.object_capacity = 4;
    mem.points = points;
    mem.point_capacity = 8;
    mem.nodes = nodes;
    mem.node_capacity = 7;
    mem.order = order;
    assert_null(stp_rt_create(&storage, sizeof storage, &mem, 0, 10));
    assert_null(stp_rt_create(&storage, 8, &mem, 10, 10));
    assert_null(stp_rt_create(&storage, sizeof storage, 0, 10, 10));
    rt = stp_rt_create(&storage, sizeof storage, &mem, 16, 8);
    assert_non_null(rt);
    assert_int_equal(stp_rt_set_recursion(rt, STP_RT_MAX_DEPTH + 1, 0), STP_ERR_ARG);
    assert_int_equal(stp_rt_set_recursion(rt, 2, STP_FIX_ONE + 1), STP_ERR_ARG);
    assert_int_equal(stp_rt_set_levels(rt, 1), STP_ERR_ARG);
    assert_int_equal(stp_rt_sphere(rt, c, -1, 0), STP_ERR_ARG);
    assert_int_equal(stp_rt_sphere(rt, c, 0, 0), STP_ERR_DEGENERATE);
    c.x = STP_RT_COORD_LIMIT + 1;
    assert_int_equal(stp_rt_sphere(rt, c, STP_FIX_ONE, 0), STP_ERR_ARG);
    c.x = 0;
    /* a cone of no length, and one too flat (radius change 17 per unit) */
    assert_int_equal(stp_rt_cone(rt, c, STP_FIX_ONE, c, STP_FIX_ONE, 0), STP_ERR_DEGENERATE);
    {
        stp_vec3 apex = {0, 0, STP_FIX_ONE};
        assert_int_equal(stp_rt_cone(rt, c, 0, apex, 17 * STP_FIX_ONE, 0), STP_ERR_ARG);
        assert_int_equal(stp_rt_cone(rt, c, 0, apex, 0, 0), STP_ERR_ARG);
    }
    /* collinear triangle */
    tri[0] = c;
    tri[1].x = STP_FIX_ONE, tri[1].y = 0, tri[1].z = 0;
    tri[2].x = 2 * STP_FIX_ONE, tri[2].y = 0, tri[2].z = 0;
    assert_int_equal(stp_rt_polygon(rt, tri, 0, 3, 0), STP_ERR_DEGENERATE);
    assert_int_equal(stp_rt_polygon(rt, tri, 0, 2, 0), STP_ERR_DEGENERATE);
    tri[2].y = STP_FIX_ONE;
    assert_int_equal(stp_rt_polygon(rt, tri, 0, 3, 0), STP_OK);
    assert_int_equal(stp_rt_polygon(rt, tri, 0, 3, 0), STP_OK);
    /* points full: 6 of 8 used, a patch needs 6 more */
    assert_int_equal(stp_rt_polygon(rt, tri, tri, 3, 0), STP_ERR_FULL);
    c.z = 5 * STP_FIX_ONE;
    assert_int_equal(stp_rt_sphere(rt, c, STP_FIX_ONE, 1), STP_OK);
    assert_int_equal(stp_rt_sphere(rt, c, STP_FIX_ONE, 0), STP_OK);
    assert_int_equal(stp_rt_sphere(rt, c, STP_FIX_ONE, 0), STP_ERR_FULL);
    assert_int_equal(stp_rt_object_count(rt), 4);
    /* material 1 is outside a table of one */
    stp_material_default(&mat.surface);
    mat.transmission = mat.absorption = 0;
    assert_int_equal(stp_rt_set_materials(rt, &mat, 1), STP_OK);
    assert_int_equal(stp_rt_trace_pixel(rt, 0, 0, 0, out), STP_ERR_ARG);
    assert_int_equal(stp_rt_set_materials(rt, 0, 3), STP_ERR_ARG);
    /* the hierarchy needs 2n - 1 nodes */
    mem.node_capacity = 6;
    rt = stp_rt_create(&storage, sizeof storage, &mem, 16, 8);
    assert_non_null(rt);
    assert_int_equal(stp_rt_sphere(rt, c, STP_FIX_ONE, 0), STP_OK);
    assert_int_equal(stp_rt_sphere(rt, c, STP_FIX_ONE, 0), STP_OK);
    assert_int_equal(stp_rt_sphere(rt, c, STP_FIX_ONE, 0), STP_OK);
    assert_int_equal(stp_rt_build(rt), STP_OK);
    assert_int_equal(stp_rt_sphere(rt, c, STP_FIX_ONE, 0), STP_OK);
    assert_int_equal(stp_rt_build(rt), STP_ERR_MEMORY);
    assert_int_equal(stp_rt_set_materials(rt, &mat, 1), STP_OK);
    assert_int_equal(stp_rt_trace_pixel(rt, 16, 0, 0, out), STP_ERR_ARG);
    assert_int_equal(stp_rt_trace_pixel(rt, 8, 4, 0, out), STP_OK);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_arguments),
        cmocka_unit_test(test_scenes_against_reference),
        cmocka_unit_test(test_hierarchy_equals_every_object),
        cmocka_unit_test(test_bands_equal_full_frame),
        cmocka_unit_test(test_stiff_cases),
        cmocka_unit_test(test_no_self_shadow),
        cmocka_unit_test(test_terminator_seams),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
