/* SPDX-License-Identifier: MIT */
/*
 * The core built with STP_WITH_EDGE_AA 0 (tests/edge_aa/CMakeLists.txt):
 * a render asking for edge anti-aliasing is refused with
 * STP_ERR_UNSUPPORTED and sends nothing to the port; without it the
 * picture is drawn, the pixel the edge partly covers left as the
 * background.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "stipple/stipple.h"

#if STP_WITH_EDGE_AA
#error "this test is built with STP_WITH_EDGE_AA 0"
#endif

static uint8_t frame[8 * 16];
static int flushes;

static int flush_copy(stp_port *port, uint32_t y0, uint32_t rows, const uint8_t *pixels, size_t stride)
{
    uint32_t y;
    (void)port;
    flushes++;
    for (y = 0; y < rows; y++)
        memcpy(frame + (size_t)(y0 + y) * 16, pixels + (size_t)y * stride, 16);
    return 0;
}

static void test_refused_when_compiled_out(void **state)
{
    static stp_renderer_storage storage;
    static stp_instr df[64];
    uint8_t band[16 * 8];
    uint16_t zbuf[16 * 8];
    stp_renderer *r = stp_renderer_create(&storage, sizeof storage, df, 64, 16, 8);
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
    /* device x from 0 to 8.25 (world x = 8 - device x), all rows */
    memset(sq, 0, sizeof sq);
    sq[0].x = 8 * STP_FIX_ONE, sq[0].y = 4 * STP_FIX_ONE;
    sq[1].x = -STP_FIX_ONE / 4, sq[1].y = 4 * STP_FIX_ONE;
    sq[2].x = -STP_FIX_ONE / 4, sq[2].y = -4 * STP_FIX_ONE;
    sq[3].x = 8 * STP_FIX_ONE, sq[3].y = -4 * STP_FIX_ONE;
    assert_int_equal(stp_renderer_polygon(r, sq, 4), STP_OK);
    memset(&port, 0, sizeof port);
    port.width = 16;
    port.height = 8;
    port.format = STP_PIXEL_GREY8;
    port.flush = flush_copy;
    assert_int_equal(stp_output_default(&out), STP_OK);
    assert_int_equal(out.edge_aa, 0);
    memset(&mem, 0, sizeof mem);
    mem.band = band;
    mem.band_size = sizeof band;
    mem.band_rows = 8;
    mem.zbuf = zbuf;
    mem.zbuf_count = 16 * 8;
    out.edge_aa = 1;
    assert_int_equal(stp_renderer_render(r, &port, &out, &mem), STP_ERR_UNSUPPORTED);
    assert_int_equal(flushes, 0);
    out.edge_aa = 0;
    assert_int_equal(stp_renderer_render(r, &port, &out, &mem), STP_OK);
    for (y = 0; y < 8; y++) {
        assert_int_equal(frame[y * 16 + 7], 255);
        assert_int_equal(frame[y * 16 + 8], 0); /* a build with it: 1/4 of 255 */
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_refused_when_compiled_out)};
    return cmocka_run_group_tests(tests, 0, 0);
}
