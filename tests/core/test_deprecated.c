/* SPDX-License-Identifier: MIT */
/*
 * The renderer's names before 0.3 still compile and reach the new functions
 * (include/stipple/deprecated.h).  scripts/rename-api.sh leaves this file
 * alone: it must keep the old names.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "stipple/stipple.h"

#define ONE STP_FIX_ONE

static int keep(stp_port *port, uint32_t y0, uint32_t rows, const uint8_t *px, size_t stride)
{
    uint8_t *frame = (uint8_t *)port->user;
    uint32_t y;
    for (y = 0; y < rows; y++)
        memcpy(frame + (y0 + y) * 8, px + y * stride, 8);
    return 0;
}

static void test_old_names(void **state)
{
    static stp_renderer_storage storage;
    static stp_instr display_file[64];
    static uint16_t memory_words[256];
    static uint16_t map[16 * 16];
    uint8_t frame[64];
    const stp_vec3 square[4] = {{-ONE, -ONE, 0}, {ONE, -ONE, 0}, {ONE, ONE, 0}, {-ONE, ONE, 0}};
    const stp_vec3 normals[4] = {{0, 0, -ONE}, {0, 0, -ONE}, {0, 0, -ONE}, {0, 0, -ONE}};
    const stp_fix shades[4] = {ONE, ONE, ONE, ONE};
    const stp_vec3 light = {0, 0, -2 * ONE};
    stp_port port = {8, 8, STP_PIXEL_GREY8, keep, NULL};
    stp_view view;
    stp_lighting lighting;
    stp_material material;
    stp_frame_memory memory;
    stp_renderer *r;
    (void)state;
    port.user = frame;
    memset(frame, 0, sizeof frame);
    r = stp_renderer_create(&storage, sizeof storage, display_file, 64, 8, 8);
    assert_non_null(r);
    memset(&view, 0, sizeof view);
    view.from.z = -ONE;
    view.up.y = ONE;
    view.fov_degrees = 90 * ONE;
    view.window_half = ONE;
    view.hither = ONE >> 8;
    assert_int_equal(stp_set_view(r, &view), STP_OK);
    assert_int_equal(stp_set_light(r, light, ONE, ONE / 5), STP_OK);
    stp_lighting_default(&lighting);
    lighting.lights[0].position = light;
    assert_int_equal(stp_set_lighting(r, &lighting), STP_OK);
    stp_material_default(&material);
    assert_int_equal(stp_set_object_shade(r, &material), STP_OK);
    assert_int_equal(stp_set_shading(r, 1), STP_OK);
    assert_int_equal(stp_set_fill_style(r, 3), STP_OK);
    assert_int_equal(stp_set_colour(r, 0), STP_OK);
    assert_int_equal(stp_set_transparency(r, 0, 0, 2, 0, 0), STP_OK);
    assert_int_equal(stp_set_levels(r, 16), STP_OK);
    assert_int_equal(stp_set_backface_removal(r, 0), STP_OK);
#if STP_WITH_SHADOWS
    assert_int_equal(stp_set_shadow_map(r, 0, map, 16 * 16, 16, 16, NULL), STP_OK);
    assert_int_equal(stp_remove_shadow_map(r, 0), STP_OK);
#else
    (void)map;
#endif
    assert_int_equal(stp_move(r, square[0]), STP_OK);
    assert_int_equal(stp_line(r, square[1]), STP_OK);
    assert_int_equal(stp_polygon(r, square, 4), STP_OK);
    assert_true(stp_last_shade(r) > 0);
#if STP_WITH_GOURAUD
    assert_int_equal(stp_polygon_smooth(r, square, normals, 4), STP_OK);
    assert_int_equal(stp_polygon_vertex_shades(r, square, shades, 4), STP_OK);
#else
    (void)normals;
    (void)shades;
#endif
    assert_true(stp_display_file_used(r) > 0);
    assert_true(stp_polygon_count(r) >= 1);
    assert_int_equal(stp_frame_memory_split(&memory, r, &port, NULL, memory_words, sizeof memory_words),
                     STP_OK);
    assert_int_equal(stp_render(r, &port, NULL, &memory), STP_OK);
    assert_true(frame[4 * 8 + 4] > 0); /* the square covers the centre */
}

int main(void)
{
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_old_names)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
