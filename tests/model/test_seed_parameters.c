/* SPDX-License-Identifier: MIT */
/*
 * The seed's user parameters (docs/model.md section 2) through the public
 * API.  COPY-LIGHT and SET-LIGHT: a segment keeps the lighting that was
 * current when it was created, so a light set while the segment is open
 * shades only the polygons of the next segment (seen through stp_renderer_last_shade,
 * the shade SHADE-CHECK gave the last polygon: one square lit head-on and at
 * a grazing angle).  SET-SHADING: with shading off a polygon is drawn in the
 * current fill style; on, in the INTENSITY style of its shade.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "stipple/stipple.h"

static stp_fix fx(double v)
{
    return (stp_fix)(v * STP_FIX_ONE + (v < 0 ? -0.5 : 0.5));
}

static stp_vec3 vec(double x, double y, double z)
{
    stp_vec3 v;
    v.x = fx(x);
    v.y = fx(y);
    v.z = fx(z);
    return v;
}

static stp_renderer_storage storage;
static stp_instr display_file[64];

/* A renderer looking down -z at the origin (perspective, from z = 20),
 * shading on. */
static stp_renderer *renderer(void)
{
    stp_renderer *r = stp_renderer_create(&storage, sizeof storage, display_file, 64, 32, 32);
    stp_view v;
    assert_non_null(r);
    memset(&v, 0, sizeof v);
    v.from = vec(3, -2, 20);
    v.up = vec(0, 1, 0);
    v.fov_degrees = fx(60);
    v.hither = fx(1);
    v.projection = STP_PERSPECTIVE;
    assert_int_equal(stp_renderer_set_view(r, &v), STP_OK);
    stp_renderer_set_shading(r, 1);
    return r;
}

/* The unit square at z = 0 facing +z; returns its shade. */
static stp_fix square(stp_renderer *r)
{
    const stp_vec3 v[4] = {vec(-1, -1, 0), vec(1, -1, 0), vec(1, 1, 0), vec(-1, 1, 0)};
    assert_int_equal(stp_renderer_polygon(r, v, 4), STP_OK);
    return stp_renderer_last_shade(r);
}

static void light_a(stp_renderer *r) { stp_renderer_set_light(r, vec(0, 0, 1.5), fx(1), fx(0.2)); }
static void light_b(stp_renderer *r) { stp_renderer_set_light(r, vec(30, 0, 2), fx(1), fx(0.2)); }

static void test_copy_light_per_segment(void **state)
{
    stp_renderer *r;
    stp_fix under_a, a_after_change, under_b, fresh_b;
    (void)state;

    /* light B alone, for reference */
    r = renderer();
    light_b(r);
    assert_int_equal(stp_segment_create(r, 1), STP_OK);
    fresh_b = square(r);

    r = renderer();
    light_a(r);
    assert_int_equal(stp_segment_create(r, 1), STP_OK);
    under_a = square(r);
    light_b(r); /* the open segment keeps A */
    a_after_change = square(r);
    assert_int_equal(stp_segment_close(r), STP_OK);
    assert_int_equal(stp_segment_create(r, 2), STP_OK); /* copies B */
    under_b = square(r);

    assert_int_equal(a_after_change, under_a);
    assert_int_equal(under_b, fresh_b);
    /* head-on light against a grazing one: clearly brighter */
    assert_true(under_a - under_b > STP_FIX_ONE / 8);
}

#define SIDE 16
static uint8_t frame[SIDE * SIDE];

static int flush(stp_port *port, uint32_t y0, uint32_t rows, const uint8_t *px, size_t stride)
{
    uint32_t y;
    (void)port;
    for (y = 0; y < rows; y++)
        memcpy(&frame[(y0 + y) * SIDE], px + y * stride, SIDE);
    return 0;
}

/* A square filling a 16x16 STYLE8 frame, shading on or off (fill style 7),
 * lit head-on; returns the number of pixels of the expected style. */
static int pixels_of_square(int shading, int *expected_style)
{
    static uint8_t band[SIDE * SIDE];
    stp_renderer *r = stp_renderer_create(&storage, sizeof storage, display_file, 64, SIDE, SIDE);
    const stp_vec3 v[4] = {vec(-9, -9, 0), vec(9, -9, 0), vec(9, 9, 0), vec(-9, 9, 0)};
    stp_port port = {SIDE, SIDE, STP_PIXEL_STYLE8, flush, NULL};
    stp_output out;
    stp_frame_memory fm;
    stp_view view;
    int i, count = 0;
    assert_non_null(r);
    memset(&view, 0, sizeof view);
    view.from = vec(0, 0, 100);
    view.up = vec(0, 1, 0);
    view.window_half = fx(SIDE / 2.0);
    view.hither = fx(1);
    view.projection = STP_PARALLEL;
    assert_int_equal(stp_renderer_set_view(r, &view), STP_OK);
    stp_renderer_set_light(r, vec(0, 0, 3), fx(1), fx(0.1));
    stp_renderer_set_shading(r, shading);
    stp_renderer_set_fill_style(r, 7);
    assert_int_equal(stp_segment_create(r, 1), STP_OK);
    assert_int_equal(stp_renderer_polygon(r, v, 4), STP_OK);
    assert_int_equal(stp_segment_close(r), STP_OK);
    *expected_style = shading ? stp_intensity_index(stp_renderer_last_shade(r), 16) : 7;
    memset(&out, 0, sizeof out);
    out.hidden = STP_HIDDEN_NONE;
    memset(&fm, 0, sizeof fm);
    fm.band = band;
    fm.band_size = sizeof band;
    fm.band_rows = SIDE;
    memset(frame, 0, sizeof frame);
    assert_int_equal(stp_renderer_render(r, &port, &out, &fm), STP_OK);
    for (i = 0; i < SIDE * SIDE; i++)
        count += frame[i] == *expected_style;
    return count;
}

static void test_set_shading(void **state)
{
    int off_style, on_style;
    (void)state;
    assert_int_equal(pixels_of_square(0, &off_style), SIDE * SIDE);
    assert_int_equal(off_style, 7);
    assert_int_equal(pixels_of_square(1, &on_style), SIDE * SIDE);
    /* lit head-on from 3 units: a light style, not the fill style */
    assert_true(on_style > 7);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_copy_light_per_segment),
        cmocka_unit_test(test_set_shading),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
