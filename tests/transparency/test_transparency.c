/* SPDX-License-Identifier: MIT */
/*
 * Transparency (docs/model.md section 5, (10.20), (10.21)) through the public API:
 * an opaque square behind a transparent one; in the overlap the pixel must
 * be INTENSITY(v_r + t v_t), with v_t recovered from the frame by the inverse
 * of INTENSITY, whatever the hidden-surface method and the entry order.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "stipple/stipple.h"

#define W 32
#define H 32
#define LEVELS 16

static uint8_t frame[W * H];

static int flush(stp_port *port, uint32_t y0, uint32_t rows, const uint8_t *px, size_t stride)
{
    uint32_t y;
    (void)port;
    for (y = 0; y < rows; y++)
        memcpy(&frame[(y0 + y) * W], px + y * stride, W);
    return 0;
}

static stp_fix fx(double v)
{
    return (stp_fix)lround(v * STP_FIX_ONE);
}

/* A square from (x0, y0) to (x1, y1) in pixels at depth z (world units =
 * pixels; the eye looks down -z from z = 100, parallel). */
static void square(stp_renderer *r, double x0, double y0, double x1, double y1, double z)
{
    stp_vec3 v[4];
    v[0].x = fx(x0 - W / 2.0); v[0].y = fx(H / 2.0 - y0); v[0].z = fx(z);
    v[1].x = fx(x1 - W / 2.0); v[1].y = fx(H / 2.0 - y0); v[1].z = fx(z);
    v[2].x = fx(x1 - W / 2.0); v[2].y = fx(H / 2.0 - y1); v[2].z = fx(z);
    v[3].x = fx(x0 - W / 2.0); v[3].y = fx(H / 2.0 - y1); v[3].z = fx(z);
    assert_int_equal(stp_renderer_polygon(r, v, 4), STP_OK);
}

/* Style index of the frame pixel for STYLE8 (no table: the index itself). */
static int render_scene(stp_hidden hidden, int transparent_first, double t, int *overlap,
                        int *back_only, int *front_only)
{
    static uint8_t mem[1 << 16];
    static stp_instr df[64];
    static uint8_t band[W * H];
    static uint16_t zbuf[W * H];
    static stp_sort_entry sort[8];
    stp_renderer *r = stp_renderer_create(mem, sizeof mem, df, 64, W, H);
    stp_view v;
    stp_port port = {W, H, STP_PIXEL_STYLE8, flush, NULL};
    stp_output out;
    stp_frame_memory fm;
    int k;
    memset(&v, 0, sizeof v);
    v.from.z = fx(100);
    v.up.y = STP_FIX_ONE;
    v.window_half = fx(H / 2.0);
    v.hither = fx(1);
    v.projection = STP_PARALLEL;
    assert_non_null(r);
    assert_int_equal(stp_renderer_set_view(r, &v), STP_OK);
    assert_int_equal(stp_segment_create(r, 1), STP_OK);
    for (k = 0; k < 2; k++) {
        if ((k == 0) == (transparent_first != 0)) {
            /* front (z = 10), transparent, style 6 */
            assert_int_equal(stp_renderer_set_transparency(r, fx(t), fx(t), 2, 0, 0), STP_OK);
            stp_renderer_set_fill_style(r, 6);
            square(r, 8, 8, 24, 24, 10);
        } else {
            /* back (z = 0), opaque, style 9 */
            assert_int_equal(stp_renderer_set_transparency(r, 0, 0, 2, 0, 0), STP_OK);
            stp_renderer_set_fill_style(r, 9);
            square(r, 0, 0, 16, 16, 0);
        }
    }
    memset(&out, 0, sizeof out);
    out.hidden = hidden;
    out.background = stp_intensity_shade(4, LEVELS); /* style 4 exactly */
    memset(&fm, 0, sizeof fm);
    fm.band = band;
    fm.setup = 0; /* no per-polygon setups kept between bands */
    fm.setup_count = 0;
    fm.band_size = sizeof band;
    fm.band_rows = 5;
    fm.zbuf = zbuf;
    fm.zbuf_count = W * 5;
    fm.sort = sort;
    fm.sort_count = 8;
    assert_int_equal(stp_renderer_render(r, &port, &out, &fm), STP_OK);
    *overlap = frame[12 * W + 12];    /* both squares */
    *back_only = frame[4 * W + 4];    /* the opaque one */
    *front_only = frame[20 * W + 20]; /* the transparent one over the background */
    return 0;
}

/* INTENSITY of v_r + t v_t with the seed's formula, in double. */
static int expected(int front_style, double t, int under_style)
{
    double v_r = (front_style - 1) / (double)(LEVELS - 1);
    double v_t = (under_style - 1) / (double)(LEVELS - 1);
    double v = v_r + t * v_t;
    if (v > 1)
        v = 1;
    return (int)floor(v * (LEVELS - 1) + 1e-9) + 1;
}

static void test_blend_over_opaque_and_background(void **state)
{
    static const stp_hidden methods[] = {STP_HIDDEN_PAINTER, STP_HIDDEN_ZBUFFER};
    static const double ts[] = {0.5, 0.25, 1.0};
    int m, order, ti;
    (void)state;
    for (m = 0; m < 2; m++)
        for (order = 0; order < 2; order++)
            for (ti = 0; ti < 3; ti++) {
                int overlap, back, front;
                render_scene(methods[m], order, ts[ti], &overlap, &back, &front);
                assert_int_equal(back, 9);
                assert_int_equal(overlap, expected(6, ts[ti], 9));
                assert_int_equal(front, expected(6, ts[ti], 4));
            }
}

/* Stiff: t = 0 is opaque (the front style alone); t = 1 with a bright
 * polygon saturates at the top style. */
static void test_opaque_and_fully_transparent(void **state)
{
    int overlap, back, front;
    (void)state;
    render_scene(STP_HIDDEN_PAINTER, 0, 0.0, &overlap, &back, &front);
    assert_int_equal(overlap, 6);
    assert_int_equal(front, 6);
    render_scene(STP_HIDDEN_ZBUFFER, 1, 1.0, &overlap, &back, &front);
    assert_int_equal(overlap, expected(6, 1.0, 9)); /* 5/15 + 8/15 = 13/15: style 14 */
    assert_int_equal(overlap, 14);
}

static void test_bad_arguments(void **state)
{
    static uint8_t mem[1 << 16];
    static stp_instr df[8];
    stp_renderer *r = stp_renderer_create(mem, sizeof mem, df, 8, W, H);
    (void)state;
    assert_int_equal(stp_renderer_set_transparency(r, fx(-0.1), fx(0.5), 2, 0, 0), STP_ERR_ARG);
    assert_int_equal(stp_renderer_set_transparency(r, 0, fx(1.5), 2, 0, 0), STP_ERR_ARG);
    assert_int_equal(stp_renderer_set_transparency(r, 0, fx(0.5), 0, 0, 0), STP_ERR_ARG);
    assert_int_equal(stp_renderer_set_transparency(r, 0, fx(0.5), 2, fx(-1), 0), STP_ERR_ARG);
    assert_int_equal(stp_renderer_set_transparency(r, 0, fx(0.5), 2, fx(1), fx(2)), STP_OK);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_blend_over_opaque_and_background),
        cmocka_unit_test(test_opaque_and_fully_transparent),
        cmocka_unit_test(test_bad_arguments),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
