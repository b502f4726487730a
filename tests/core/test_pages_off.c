/* SPDX-License-Identifier: MIT */
/*
 * The core built without the panels' page layout (STP_WITH_PAGES 0: the
 * m0plus_minimal configuration, cmake/stipple_configurations.cmake): a
 * render to a STP_PIXEL_MONO1_PAGES port and a direct-drawing band in
 * STP_BAND_PAGES are refused with STP_ERR_UNSUPPORTED, sending and writing
 * nothing; in rows the same scene draws its pixels (test_golden_minimal
 * checks whole scenes in rows against their goldens).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "stipple/direct.h"
#include "stipple/stipple.h"

#if STP_WITH_PAGES
#error "this test is built with STP_WITH_PAGES 0"
#endif

#define W 16
#define H 8

static uint8_t frame[H * W];
static int flushes;

static int flush_copy(stp_port *port, uint32_t y0, uint32_t rows, const uint8_t *pixels, size_t stride)
{
    uint32_t y;
    (void)port;
    flushes++;
    for (y = 0; y < rows; y++)
        memcpy(frame + (size_t)(y0 + y) * W, pixels + (size_t)y * stride, stride < W ? stride : W);
    return 0;
}

/* A white square over device x 0..8 (world x = 8 - device x), all rows:
 * MONO1 rows hold 0xFF in byte 0 of every row, 0x00 in byte 1. */
static void test_render(void **state)
{
    static stp_renderer_storage storage;
    static stp_instr df[64];
    uint8_t band[W * H];
    uint16_t zbuf[W * H];
    stp_renderer *r = stp_renderer_create(&storage, sizeof storage, df, 64, W, H);
    stp_view v;
    stp_output out;
    stp_frame_memory mem;
    stp_port port;
    stp_vec3 sq[4];
    int y;
    (void)state;
    assert_non_null(r);
    memset(&v, 0, sizeof v);
    v.from.z = -10 * STP_FIX_ONE;
    v.up.y = STP_FIX_ONE;
    v.window_half = 4 * STP_FIX_ONE; /* one unit per pixel */
    v.hither = STP_FIX_ONE;
    v.fov_degrees = 90 * STP_FIX_ONE;
    v.projection = STP_PARALLEL;
    assert_int_equal(stp_renderer_set_view(r, &v), STP_OK);
    assert_int_equal(stp_renderer_set_levels(r, 256), STP_OK);
    assert_int_equal(stp_renderer_set_fill_style(r, 256), STP_OK);
    memset(sq, 0, sizeof sq);
    sq[0].x = 8 * STP_FIX_ONE, sq[0].y = 4 * STP_FIX_ONE;
    sq[1].x = 0, sq[1].y = 4 * STP_FIX_ONE;
    sq[2].x = 0, sq[2].y = -4 * STP_FIX_ONE;
    sq[3].x = 8 * STP_FIX_ONE, sq[3].y = -4 * STP_FIX_ONE;
    assert_int_equal(stp_renderer_polygon(r, sq, 4), STP_OK);
    memset(&port, 0, sizeof port);
    port.width = W;
    port.height = H;
    port.format = STP_PIXEL_MONO1_PAGES;
    port.flush = flush_copy;
    assert_int_equal(stp_output_default(&out), STP_OK);
    memset(&mem, 0, sizeof mem);
    mem.band = band;
    mem.band_size = sizeof band;
    mem.band_rows = H;
    mem.zbuf = zbuf;
    mem.zbuf_count = W * H;
    assert_int_equal(stp_renderer_render(r, &port, &out, &mem), STP_ERR_UNSUPPORTED);
    assert_int_equal(flushes, 0);
    port.format = STP_PIXEL_MONO1;
    memset(frame, 0xA5, sizeof frame);
    assert_int_equal(stp_renderer_render(r, &port, &out, &mem), STP_OK);
    assert_int_equal(flushes, 1);
    for (y = 0; y < H; y++) {
        assert_int_equal(frame[y * W], 0xFF);
        assert_int_equal(frame[y * W + 1], 0x00);
    }
}

/* One direct-drawing face over the band's top left: drawn in rows (pixel
 * (2, 2) ON), refused in pages with the band untouched. */
static void test_direct_band(void **state)
{
    static const stp_vec3 vertices[3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
    static const uint16_t triangles[3] = {0, 1, 2};
    static const uint8_t cell[16] = {0};
    stp_mesh mesh;
    stp_direct_point points[3];
    uint16_t faces[1] = {256 + 255};
    stp_direct_frame f;
    uint8_t band[W * H];
    (void)state;
    memset(&mesh, 0, sizeof mesh);
    mesh.vertices = vertices;
    mesh.triangles = triangles;
    mesh.vertex_count = 3;
    mesh.triangle_count = 1;
    memset(points, 0, sizeof points);
    /* counter-clockwise on the screen (y down): (0, 0), (0, 8), (8, 0) pixels */
    points[0].dx = 0, points[0].dy = 0;
    points[1].dx = 0, points[1].dy = 8 * 16;
    points[2].dx = 8 * 16, points[2].dy = 0;
    memset(&f, 0, sizeof f);
    f.mesh = &mesh;
    f.points = points;
    f.faces = faces;
    f.cell = cell;
    f.width = W;
    f.height = H;
    f.layout = STP_BAND_PAGES;
    memset(band, 0xA5, sizeof band);
    assert_int_equal(stp_direct_draw_band(&f, band, W, 0, H), STP_ERR_UNSUPPORTED);
    assert_int_equal(band[0], 0xA5);
    assert_int_equal(band[sizeof band - 1], 0xA5);
    f.layout = STP_BAND_ROWS;
    assert_int_equal(stp_direct_draw_band(&f, band, W / 8, 0, H), STP_OK);
    assert_int_equal(band[2 * (W / 8)] & 0x20, 0x20); /* pixel (2, 2) */
    assert_int_equal(band[7 * (W / 8) + 1], 0x00);    /* right of the face */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_render),
        cmocka_unit_test(test_direct_band),
    };
    return cmocka_run_group_tests(tests, 0, 0);
}
