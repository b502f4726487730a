/* SPDX-License-Identifier: MIT */
/*
 * The animation of a scene (tools/animate.h, tools/camera.h):
 *  - the camera: an orbit turns the eye about up through the look-at
 *    point, keys are interpolated, elevation raises the eye (against
 *    double-precision formulas written out here);
 *  - the held halftone: hold 0 gives the core's own 1-bit frame, exactly;
 *    a hold keeps pixels whose grey stays near their threshold;
 *  - the target: on each shared scene at 128x64 turning 1 degree a frame
 *    (31 frames), at most 1 % of the pixels change between frames with the
 *    animation defaults, while the picture moves and is not blank.
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

#include "animate.h"
#include "camera.h"
#include "render_scene.h"
#include "test_scenes.h"

static const char *const shared[] = {"balls-s1", "balls-s2", "gears-s1", "mount-s2",
                                     "teapot-s1", "teapot-s2", "tetra-s1", "tetra-s2"};

static stp_scene_vec3 v3(double x, double y, double z)
{
    stp_scene_vec3 v;
    v.x = x;
    v.y = y;
    v.z = z;
    return v;
}

static void near3(stp_scene_vec3 got, double x, double y, double z)
{
    if (fabs(got.x - x) > 1e-9 || fabs(got.y - y) > 1e-9 || fabs(got.z - z) > 1e-9)
        fail_msg("got (%.12g, %.12g, %.12g), want (%g, %g, %g)", got.x, got.y, got.z, x, y, z);
}

/* A scene with a view: one square facing the eye on +z. */
static void square_scene(stp_scene *s, stp_scene_vec3 *vertices, stp_scene_polygon *poly)
{
    memset(s, 0, sizeof *s);
    memset(poly, 0, sizeof *poly);
    vertices[0] = v3(-1, -1, 0);
    vertices[1] = v3(1, -1, 0);
    vertices[2] = v3(1, 1, 0);
    vertices[3] = v3(-1, 1, 0);
    poly->count = 4;
    poly->material = -1;
    s->vertices = vertices;
    s->vertex_count = 4;
    s->polygons = poly;
    s->polygon_count = 1;
    s->has_view = 1;
    s->from = v3(0, 0, 4);
    s->at = v3(0, 0, 0);
    s->up = v3(0, 1, 0);
    s->angle = 45;
    s->hither = 0.01;
}

static void orbit_turns_the_eye(void **state)
{
    stp_scene s;
    stp_scene_vec3 vx[4];
    stp_scene_polygon poly;
    stp_tool_options opt;
    stp_tool_motion m;
    stp_tool_view v;
    double turn;
    char err[256];
    (void)state;
    square_scene(&s, vx, &poly);
    stp_tool_options_default(&opt);
    memset(&m, 0, sizeof m);
    m.frames = 4;
    m.orbit_degrees = 360;
    /* frame 1: a quarter turn about +y (right-handed): +z goes to +x */
    assert_int_equal(stp_tool_camera_view(&s, &opt, &m, 1, &v, &turn, err, sizeof err), 0);
    near3(v.from, 4, 0, 0);
    assert_true(fabs(turn - 3.14159265358979323846 / 2) < 1e-12);
    assert_int_equal(stp_tool_camera_view(&s, &opt, &m, 2, &v, &turn, err, sizeof err), 0);
    near3(v.from, 0, 0, -4);
    /* elevation 30: the same distance, 4 sin 30 = 2 above the horizon */
    m.elevation_given = 1;
    m.elevation_degrees = 30;
    assert_int_equal(stp_tool_camera_view(&s, &opt, &m, 0, &v, &turn, err, sizeof err), 0);
    near3(v.from, 0, 2, 4 * cos(30 * 3.14159265358979323846 / 180));
}

static void keys_are_interpolated(void **state)
{
    stp_scene s;
    stp_scene_vec3 vx[4];
    stp_scene_polygon poly;
    stp_tool_options opt;
    stp_tool_motion m;
    stp_tool_view v;
    double turn;
    char err[256];
    (void)state;
    square_scene(&s, vx, &poly);
    stp_tool_options_default(&opt);
    opt.eye[0] = v3(0, 0, 5);
    opt.eye[1] = v3(10, 0, 5);
    opt.eye[2] = v3(10, 10, 5);
    opt.eye_count = 3;
    memset(&m, 0, sizeof m);
    m.frames = 11;
    assert_int_equal(stp_tool_camera_view(&s, &opt, &m, 0, &v, &turn, err, sizeof err), 0);
    near3(v.from, 0, 0, 5);
    assert_int_equal(stp_tool_camera_view(&s, &opt, &m, 4, &v, &turn, err, sizeof err), 0);
    near3(v.from, 8, 0, 5);
    assert_int_equal(stp_tool_camera_view(&s, &opt, &m, 10, &v, &turn, err, sizeof err), 0);
    near3(v.from, 10, 10, 5);
    /* the eye on the look-at point, up along the line of sight: refused */
    opt.eye_count = 1;
    opt.eye[0] = v3(0, 0, 0);
    assert_int_equal(stp_tool_camera_view(&s, &opt, &m, 0, &v, &turn, err, sizeof err), -1);
    assert_non_null(strstr(err, "look-at"));
    opt.eye[0] = v3(0, 5, 0);
    assert_int_equal(stp_tool_camera_view(&s, &opt, &m, 0, &v, &turn, err, sizeof err), -1);
    assert_non_null(strstr(err, "line of sight"));
}

static int bit(const stp_posix_frame *f, uint32_t x, uint32_t y)
{
    return (f->pixels[y * f->stride + x / 8] >> (7 - x % 8)) & 1;
}

static void held_halftone(void **state)
{
    stp_posix_frame grey, before, out;
    stp_cell cell;
    uint32_t x, y;
    const uint8_t *t;
    (void)state;
    stp_cell_blue_noise(&cell);
    t = stp_cell_table(&cell);
    assert_int_equal(stp_posix_frame_init(&grey, 70, 66, STP_PIXEL_GREY8), 0);
    assert_int_equal(stp_posix_frame_init(&before, 70, 66, STP_PIXEL_MONO1), 0);
    assert_int_equal(stp_posix_frame_init(&out, 70, 66, STP_PIXEL_MONO1), 0);
    for (y = 0; y < 66; y++)
        for (x = 0; x < 70; x++)
            grey.pixels[y * grey.stride + x] = (uint8_t)((x * 37 + y * 11) % 256);
    /* before: every other pixel lit */
    for (y = 0; y < 66; y++)
        for (x = 0; x < 70; x++)
            if ((x + y) % 2)
                before.pixels[y * before.stride + x / 8] |= (uint8_t)(0x80 >> (x % 8));
    stp_tool_halftone_held(&grey, &cell, 5, &before, &out);
    for (y = 0; y < 66; y++)
        for (x = 0; x < 70; x++) {
            int g = grey.pixels[y * grey.stride + x], th = t[(y % 64) * 64 + x % 64];
            int want = (x + y) % 2 ? g > th - 5 : g > th + 5;
            if (bit(&out, x, y) != want)
                fail_msg("pixel %u,%u: grey %d threshold %d was %d: got %d", x, y, g, th, (int)((x + y) % 2),
                         bit(&out, x, y));
        }
    /* no frame before, or hold 0: the plain screen, the core's own */
    stp_tool_halftone_held(&grey, &cell, 5, NULL, &out);
    for (y = 0; y < 66; y++) {
        uint8_t row[9];
        stp_halftone_row(row, grey.pixels + y * grey.stride, 70, y, &cell);
        for (x = 0; x < 70; x++)
            assert_int_equal(bit(&out, x, y), (row[x / 8] >> (7 - x % 8)) & 1);
    }
    stp_posix_frame_free(&grey);
    stp_posix_frame_free(&before);
    stp_posix_frame_free(&out);
}

typedef struct gathered {
    stp_posix_frame first, last;
    unsigned long lit_first;
    int count;
} gathered;

static unsigned long lit(const stp_posix_frame *f)
{
    unsigned long n = 0;
    uint32_t x, y;
    for (y = 0; y < f->height; y++)
        for (x = 0; x < f->width; x++)
            n += (unsigned long)bit(f, x, y);
    return n;
}

static int gather(const stp_posix_frame *frame, int index, void *ctx, char *err, size_t err_size)
{
    gathered *g = ctx;
    (void)err;
    (void)err_size;
    memcpy(index == 0 ? g->first.pixels : g->last.pixels, frame->pixels, frame->stride * frame->height);
    g->count++;
    return 0;
}

/* The frames of hold 0 are the core's 1-bit frames of the same camera. */
static void hold_zero_is_the_core(void **state)
{
    stp_scene scene;
    stp_tool_options opt;
    stp_tool_motion m;
    stp_tool_camera_scene moved;
    stp_tool_options still;
    stp_posix_frame direct;
    gathered g;
    char err[512];
    (void)state;
    stp_test_load_scene("teapot-s1", &scene);
    stp_tool_options_default(&opt);
    stp_tool_animation_defaults(&opt);
    opt.hold = 0;
    opt.exposure_auto = 0;
    memset(&m, 0, sizeof m);
    m.frames = 5;
    m.orbit_degrees = 40;
    memset(&g, 0, sizeof g);
    assert_int_equal(stp_posix_frame_init(&g.first, 128, 64, STP_PIXEL_MONO1), 0);
    assert_int_equal(stp_posix_frame_init(&g.last, 128, 64, STP_PIXEL_MONO1), 0);
    assert_int_equal(stp_tool_animate(&scene, &opt, &m, gather, &g, 0, err, sizeof err), 0);
    assert_int_equal(g.count, 5);
    assert_int_equal(stp_posix_frame_init(&direct, 128, 64, STP_PIXEL_MONO1), 0);
    assert_int_equal(stp_tool_camera_apply(&scene, &opt, &m, 4, &moved, &still, err, sizeof err), 0);
    assert_int_equal(stp_tool_render(&moved.scene, &still, stp_posix_frame_port(&direct), 0, err, sizeof err), 0);
    stp_tool_camera_free(&moved);
    assert_memory_equal(direct.pixels, g.last.pixels, direct.stride * 64);
    stp_posix_frame_free(&direct);
    stp_posix_frame_free(&g.first);
    stp_posix_frame_free(&g.last);
    stp_scene_free(&scene);
}

/* Each shared scene, 31 frames 1 degree apart at 128x64, the defaults. */
static void few_pixels_change(void **state)
{
    size_t i;
    (void)state;
    for (i = 0; i < sizeof shared / sizeof shared[0]; i++) {
        stp_scene scene;
        stp_tool_options opt;
        stp_tool_motion m;
        stp_tool_animation_stats st;
        gathered g;
        char err[512];
        stp_test_load_scene(shared[i], &scene);
        stp_tool_options_default(&opt);
        stp_tool_animation_defaults(&opt);
        memset(&m, 0, sizeof m);
        m.frames = 31;
        m.orbit_degrees = 31;
        memset(&g, 0, sizeof g);
        assert_int_equal(stp_posix_frame_init(&g.first, 128, 64, STP_PIXEL_MONO1), 0);
        assert_int_equal(stp_posix_frame_init(&g.last, 128, 64, STP_PIXEL_MONO1), 0);
        if (stp_tool_animate(&scene, &opt, &m, gather, &g, &st, err, sizeof err) != 0)
            fail_msg("%s: %s", shared[i], err);
        print_message("%-10s mean %.3f %% of pixels change a frame, at most %.3f %%, gain %.3f\n", shared[i],
                      100 * st.mean_changed, 100 * st.max_changed, st.gain);
        assert_int_equal(st.frames, 31);
        assert_true(st.mean_changed <= 0.01);
        /* the picture moved, and there is a picture */
        assert_true(stp_tool_changed_pixels(&g.first, &g.last) > 0);
        assert_true(lit(&g.first) > 128 * 64 / 50);
        stp_posix_frame_free(&g.first);
        stp_posix_frame_free(&g.last);
        stp_scene_free(&scene);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(orbit_turns_the_eye), cmocka_unit_test(keys_are_interpolated),
        cmocka_unit_test(held_halftone),       cmocka_unit_test(hold_zero_is_the_core),
        cmocka_unit_test(few_pixels_change),
    };
    return cmocka_run_group_tests(tests, 0, 0);
}
