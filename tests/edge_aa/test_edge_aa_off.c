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
#include "test_square.h"

#if STP_WITH_EDGE_AA
#error "this test is built with STP_WITH_EDGE_AA 0"
#endif

static void test_refused_when_compiled_out(void **state)
{
    static stp_renderer_storage storage;
    static stp_instr df[64];
    uint8_t band[16 * 8];
    uint16_t zbuf[16 * 8];
    /* device x from 0 to 8.25, all rows */
    stp_renderer *r = stp_test_square(&storage, df, -STP_FIX_ONE / 4);
    stp_output out;
    stp_frame_memory mem;
    stp_port port;
    stp_test_capture got;
    int y;
    (void)state;
    stp_test_capture_port(&port, STP_PIXEL_GREY8, &got);
    assert_int_equal(stp_output_default(&out), STP_OK);
    assert_int_equal(out.edge_aa, 0);
    stp_test_square_memory(&mem, band, zbuf);
    out.edge_aa = 1;
    assert_int_equal(stp_renderer_render(r, &port, &out, &mem), STP_ERR_UNSUPPORTED);
    assert_int_equal(got.flushes, 0);
    out.edge_aa = 0;
    assert_int_equal(stp_renderer_render(r, &port, &out, &mem), STP_OK);
    for (y = 0; y < 8; y++) {
        assert_int_equal(got.frame[y * 16 + 7], 255);
        assert_int_equal(got.frame[y * 16 + 8], 0); /* a build with it: 1/4 of 255 */
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_refused_when_compiled_out)};
    return cmocka_run_group_tests(tests, 0, 0);
}
