/* SPDX-License-Identifier: MIT */
/*
 * COPY-LIGHT and SET-LIGHT (docs/model.md section 2): a segment keeps the
 * lighting that was current when it was created, so a light set while the
 * segment is open shades only the polygons of the next segment.  Checked
 * through stp_last_shade, the shade SHADE-CHECK gave the last polygon: the
 * same square lit head-on (light A) and at a grazing angle (light B).
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
    assert_int_equal(stp_set_view(r, &v), STP_OK);
    stp_set_shading(r, 1);
    return r;
}

/* The unit square at z = 0 facing +z; returns its shade. */
static stp_fix square(stp_renderer *r)
{
    const stp_vec3 v[4] = {vec(-1, -1, 0), vec(1, -1, 0), vec(1, 1, 0), vec(-1, 1, 0)};
    assert_int_equal(stp_polygon(r, v, 4), STP_OK);
    return stp_last_shade(r);
}

static void light_a(stp_renderer *r) { stp_set_light(r, vec(0, 0, 1.5), fx(1), fx(0.2)); }
static void light_b(stp_renderer *r) { stp_set_light(r, vec(30, 0, 2), fx(1), fx(0.2)); }

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

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_copy_light_per_segment),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
