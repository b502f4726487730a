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
#include "test_square.h"

#if STP_WITH_PAGES
#error "this test is built with STP_WITH_PAGES 0"
#endif

#define W STP_TEST_SQUARE_W
#define H STP_TEST_SQUARE_H

/* A white square over device x 0..8 (world x = 8 - device x), all rows:
 * MONO1 rows hold 0xFF in byte 0 of every row, 0x00 in byte 1. */
static void test_render(void **state)
{
    static stp_renderer_storage storage;
    static stp_instr df[64];
    uint8_t band[W * H];
    uint16_t zbuf[W * H];
    stp_renderer *r = stp_test_square(&storage, df, 0);
    stp_output out;
    stp_frame_memory mem;
    stp_port port;
    stp_test_capture got;
    int y;
    (void)state;
    stp_test_capture_port(&port, STP_PIXEL_MONO1_PAGES, &got);
    assert_int_equal(stp_output_default(&out), STP_OK);
    stp_test_square_memory(&mem, band, zbuf);
    assert_int_equal(stp_renderer_render(r, &port, &out, &mem), STP_ERR_UNSUPPORTED);
    assert_int_equal(got.flushes, 0);
    port.format = STP_PIXEL_MONO1;
    memset(got.frame, 0xA5, sizeof got.frame);
    assert_int_equal(stp_renderer_render(r, &port, &out, &mem), STP_OK);
    assert_int_equal(got.flushes, 1);
    for (y = 0; y < H; y++) {
        assert_int_equal(got.frame[y * W], 0xFF);
        assert_int_equal(got.frame[y * W + 1], 0x00);
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
