/* SPDX-License-Identifier: MIT */
/*
 * Gouraud shading (docs/model.md section 4) through the public API: shades given
 * per vertex are interpolated along edges and spans; every pixel's shade is
 * checked against the interpolation written out here in double precision.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "stipple/stipple.h"

#define W 64
#define H 32

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

/* A parallel view whose window maps world x in [-W/2, W/2] onto device
 * columns 0..W and world y in [-H/2, H/2] onto rows H..0: world units are
 * pixels. */
static stp_renderer *make(void *mem, size_t size, stp_instr *df, uint32_t cap)
{
    stp_renderer *r = stp_renderer_create(mem, size, df, cap, W, H);
    stp_view v;
    memset(&v, 0, sizeof v);
    v.from.z = fx(10); /* looking down -z: world x to the right, y up */
    v.up.y = STP_FIX_ONE;
    v.window_half = fx(H / 2.0);
    v.hither = fx(1);
    v.projection = STP_PARALLEL;
    assert_non_null(r);
    assert_int_equal(stp_renderer_set_view(r, &v), STP_OK);
    assert_int_equal(stp_renderer_set_levels(r, 256), STP_OK);
    assert_int_equal(stp_segment_create(r, 1), STP_OK);
    return r;
}

static void render_grey(stp_renderer *r, uint32_t band_rows)
{
    static uint8_t band[W * H];
    stp_port port = {W, H, STP_PIXEL_GREY8, flush, NULL};
    stp_output out;
    stp_frame_memory mem;
    memset(&out, 0, sizeof out);
    memset(&mem, 0, sizeof mem);
    mem.band = band;
    mem.band_size = sizeof band;
    mem.band_rows = band_rows;
    memset(frame, 0xAA, sizeof frame);
    assert_int_equal(stp_renderer_render(r, &port, &out, &mem), STP_OK);
}

/* A rectangle across the whole device, shade 0 on the left edge and 1 on the
 * right: pixel x must show floor(255 * (x + 0.5) / W) within one level. */
static void test_horizontal_ramp(void **state)
{
    static uint8_t mem[1 << 16];
    static stp_instr df[64];
    stp_vec3 v[4];
    stp_fix s[4] = {0, STP_FIX_ONE, STP_FIX_ONE, 0};
    stp_renderer *r;
    int x, y, worst = 0;
    (void)state;
    r = make(mem, sizeof mem, df, 64);
    v[0].x = fx(-W / 2.0); v[0].y = fx(-H / 2.0); v[0].z = 0;
    v[1].x = fx(W / 2.0);  v[1].y = fx(-H / 2.0); v[1].z = 0;
    v[2].x = fx(W / 2.0);  v[2].y = fx(H / 2.0);  v[2].z = 0;
    v[3].x = fx(-W / 2.0); v[3].y = fx(H / 2.0);  v[3].z = 0;
    assert_int_equal(stp_renderer_polygon_vertex_shades(r, v, s, 4), STP_OK);
    render_grey(r, 5);
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            int want = (int)floor(255.0 * (x + 0.5) / W);
            int err = abs(frame[y * W + x] - want);
            if (err > worst)
                worst = err;
        }
    if (worst > 1)
        fail_msg("ramp differs from the interpolation by %d levels", worst);
}

/* A triangle with shades 0, 1, 0.5 at its corners: every covered pixel shows
 * the barycentric interpolation at its centre, within one level. */
static void test_triangle_barycentric(void **state)
{
    static uint8_t mem[1 << 16];
    static stp_instr df[64];
    double px[3] = {-30, 28, -5}, py[3] = {-14, -10, 15}, ps[3] = {0, 1, 0.5};
    stp_vec3 v[3];
    stp_fix s[3];
    stp_renderer *r;
    int i, x, y, worst = 0, covered = 0;
    (void)state;
    r = make(mem, sizeof mem, df, 64);
    for (i = 0; i < 3; i++) {
        v[i].x = fx(px[i]);
        v[i].y = fx(py[i]);
        v[i].z = 0;
        s[i] = fx(ps[i]);
    }
    assert_int_equal(stp_renderer_polygon_vertex_shades(r, v, s, 3), STP_OK);
    render_grey(r, H);
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            /* pixel centre in world units (y up) */
            double wx = x + 0.5 - W / 2.0, wy = H / 2.0 - (y + 0.5);
            double d = (py[1] - py[2]) * (px[0] - px[2]) + (px[2] - px[1]) * (py[0] - py[2]);
            double l0 = ((py[1] - py[2]) * (wx - px[2]) + (px[2] - px[1]) * (wy - py[2])) / d;
            double l1 = ((py[2] - py[0]) * (wx - px[2]) + (px[0] - px[2]) * (wy - py[2])) / d;
            double l2 = 1 - l0 - l1;
            /* pixels clearly inside: device coordinates have 1/16 pixel steps,
             * so centres within a few hundredths of an edge may go either way */
            if (l0 > 0.01 && l1 > 0.01 && l2 > 0.01) {
                double shade = l0 * ps[0] + l1 * ps[1] + l2 * ps[2];
                int err = abs(frame[y * W + x] - (int)floor(255.0 * shade));
                covered++;
                if (err > worst)
                    worst = err;
            }
        }
    assert_true(covered > 300);
    if (worst > 1)
        fail_msg("triangle differs from barycentric interpolation by %d levels", worst);
}

/* Stiff: a span of one pixel, and shades outside [0, 1] given by the caller
 * (clamped), must neither crash nor paint outside the polygon. */
static void test_one_pixel_span_and_clamping(void **state)
{
    static uint8_t mem[1 << 16];
    static stp_instr df[64];
    stp_vec3 v[3];
    stp_fix s[3] = {fx(-3), fx(7), STP_FIX_ONE / 2};
    stp_renderer *r;
    int x, y, painted = 0;
    (void)state;
    r = make(mem, sizeof mem, df, 64);
    /* a sliver one pixel wide around column 40 */
    v[0].x = fx(8.2); v[0].y = fx(-10); v[0].z = 0;
    v[1].x = fx(8.8); v[1].y = fx(-10); v[1].z = 0;
    v[2].x = fx(8.5); v[2].y = fx(10);  v[2].z = 0;
    assert_int_equal(stp_renderer_polygon_vertex_shades(r, v, s, 3), STP_OK);
    render_grey(r, 3);
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            uint8_t p = frame[y * W + x];
            if (x != 40)
                assert_int_equal(p, 0); /* background */
            else if (p != 0)
                painted++;
        }
    assert_true(painted > 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_horizontal_ramp),
        cmocka_unit_test(test_triangle_barycentric),
        cmocka_unit_test(test_one_pixel_span_and_clamping),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
