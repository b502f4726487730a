/* SPDX-License-Identifier: MIT */
/*
 * Smooth shading over large polygons (tools/subdivide.h): balls-s1's floor
 * (one 24 x 24 square, the lights 5.6 to 6.3 from its middle) is split into
 * two fans of 32 x 32 triangles that cover exactly the square, in its
 * plane, with its winding; the spheres' facets are left alone; and the
 * smooth picture's floor keeps the flat picture's brightness instead of
 * going dark.
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
#include "subdivide.h"
#include "test_scenes.h"

/* Twice the signed area of polygon p projected on z (the floor is z = -0.5). */
static double area_z(const stp_scene *s, const stp_scene_polygon *p)
{
    double a = 0;
    int k;
    for (k = 0; k < p->count; k++) {
        stp_scene_vec3 u = s->vertices[p->first + (size_t)k],
                       v = s->vertices[p->first + (size_t)((k + 1) % p->count)];
        a += u.x * v.y - v.x * u.y;
    }
    return a;
}

static void test_floor_split(void **state)
{
    stp_scene scene, split;
    stp_tool_options opt;
    char err[256];
    size_t i, floor_pieces = 0;
    double floor_area = 0;
    (void)state;
    stp_test_load_scene("balls-s1", &scene);
    stp_tool_options_default(&opt);
    opt.smooth = 1;
    assert_int_equal(stp_tool_subdivide(&scene, &opt, &split, err, sizeof err), 1);
    /* floor: the only polygon with every vertex at z = -0.5 */
    for (i = 0; i < split.polygon_count; i++) {
        const stp_scene_polygon *p = &split.polygons[i];
        int k, on_floor = 1;
        for (k = 0; k < p->count; k++)
            on_floor &= fabs(split.vertices[p->first + (size_t)k].z + 0.5) < 1e-12;
        if (on_floor) {
            floor_pieces++;
            floor_area += area_z(&split, p);
            assert_true(area_z(&split, p) > 0); /* the square's winding */
        }
    }
    assert_int_equal(floor_pieces, 2 * 32 * 32);
    assert_true(fabs(floor_area / 2 - 24.0 * 24.0) < 1e-9);
    /* everything else (the tessellated spheres) is kept */
    assert_int_equal(split.polygon_count, scene.polygon_count - 1 + 2 * 32 * 32);
    stp_tool_subdivided_free(&split);
    stp_scene_free(&scene);
}

static double mean_grey(const stp_posix_frame *f, int x0, int y0, int size)
{
    double s = 0;
    int x, y;
    for (y = y0; y < y0 + size; y++)
        for (x = x0; x < x0 + size; x++)
            s += f->pixels[(size_t)y * f->stride + (size_t)x];
    return s / (size * size);
}

static void test_floor_keeps_its_light(void **state)
{
    stp_scene scene;
    stp_tool_options opt;
    stp_posix_frame flat, smooth;
    char err[256];
    double f, s;
    (void)state;
    stp_test_load_scene("balls-s1", &scene);
    stp_tool_options_default(&opt);
    opt.levels = 256;
    assert_int_equal(stp_posix_frame_init(&flat, 128, 64, STP_PIXEL_GREY8), 0);
    assert_int_equal(stp_posix_frame_init(&smooth, 128, 64, STP_PIXEL_GREY8), 0);
    assert_int_equal(stp_tool_render(&scene, &opt, &flat.port, 0, err, sizeof err), 0);
    opt.smooth = 1;
    assert_int_equal(stp_tool_render(&scene, &opt, &smooth.port, 0, err, sizeof err), 0);
    /* the floor left of the balls, below the horizon */
    f = mean_grey(&flat, 8, 40, 16);
    s = mean_grey(&smooth, 8, 40, 16);
    printf("floor: flat %.1f, smooth %.1f\n", f, s);
    assert_true(fabs(f - s) < 0.1 * 255);
    stp_posix_frame_free(&flat);
    stp_posix_frame_free(&smooth);
    stp_scene_free(&scene);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_floor_split),
        cmocka_unit_test(test_floor_keeps_its_light),
    };
    return cmocka_run_group_tests(tests, 0, 0);
}
