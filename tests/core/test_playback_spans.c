/* SPDX-License-Identifier: MIT */
/* The span player (src/playback_spans.c) against a pixel-by-pixel reference:
 * each pixel of a run takes bit (7 - x % 8) of its shade's pattern byte for
 * row y % cell_rows; runs across byte boundaries, bands drawn in pieces, and
 * every malformed input refused. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include "stipple/playback_spans.h"

#define W 21u
#define H 5u
#define STRIDE 4u /* (W + 7) / 8 = 3, plus a byte that must stay untouched */

/* three shades, cell of 2 rows */
static const uint8_t patterns[6] = {0xAA, 0x55, 0xFF, 0x00, 0x81, 0x3C};
static const uint8_t runs[] = {
    20, 0,                   /* row 0: one run */
    0, 1, 7, 2, 8, 0, 20, 1, /* row 1: one pixel, to a byte's end, one pixel, the rest */
    3, 2, 15, 0, 17, 1, 20, 2, /* row 2: a run across bytes ending at one's end */
    9, 1, 20, 2,             /* row 3 */
    20, 2,                   /* row 4 */
};

static stp_spans make(void)
{
    stp_spans s;
    s.width = W;
    s.height = H;
    s.cell_rows = 2;
    s.shade_count = 3;
    s.patterns = patterns;
    s.runs = runs;
    return s;
}

/* The reference: the runs decoded pixel by pixel. */
static int ref_bit(uint32_t x, uint32_t y)
{
    size_t i = 0;
    uint32_t row = 0;
    for (;;) {
        if (row == y && x <= runs[i])
            return (patterns[runs[i + 1] * 2u + (y % 2u)] >> (7u - x % 8u)) & 1u;
        if (runs[i] == W - 1u)
            row++;
        i += 2;
    }
}

static void check_picture(const uint8_t *band)
{
    uint32_t x, y;
    for (y = 0; y < H; y++) {
        for (x = 0; x < W; x++) {
            int got = (band[y * STRIDE + x / 8u] >> (7u - x % 8u)) & 1u;
            if (got != ref_bit(x, y))
                fail_msg("pixel (%u, %u): %d, want %d", x, y, got, ref_bit(x, y));
        }
        /* nothing past the row's last pixel is written */
        for (x = W; x < 24u; x++)
            assert_int_equal((band[y * STRIDE + x / 8u] >> (7u - x % 8u)) & 1u,
                             (0x5Au >> (7u - x % 8u)) & 1u);
        assert_int_equal(band[y * STRIDE + 3u], 0x5A);
    }
}

static void test_whole_picture(void **state)
{
    stp_spans s = make();
    stp_spans_cursor c;
    uint8_t band[H * STRIDE];
    (void)state;
    memset(band, 0x5A, sizeof band);
    stp_spans_start(&s, &c);
    assert_int_equal(stp_spans_draw(&s, &c, band, STRIDE, H), STP_OK);
    assert_int_equal(c.y, H);
    assert_ptr_equal(c.next, runs + sizeof runs);
    check_picture(band);
}

static void test_bands_of_one_row(void **state)
{
    stp_spans s = make();
    stp_spans_cursor c;
    uint8_t band[H * STRIDE];
    uint32_t y;
    (void)state;
    memset(band, 0x5A, sizeof band);
    stp_spans_start(&s, &c);
    for (y = 0; y < H; y++)
        assert_int_equal(stp_spans_draw(&s, &c, band + y * STRIDE, STRIDE, 1), STP_OK);
    check_picture(band);
    /* past the last row */
    assert_int_equal(stp_spans_draw(&s, &c, band, STRIDE, 1), STP_ERR_ARG);
}

static void test_bad_data_refused(void **state)
{
    static const uint8_t backwards[] = {5, 0, 4, 0, 20, 0};
    static const uint8_t past_row[] = {21, 0};
    static const uint8_t bad_shade[] = {20, 3};
    stp_spans s = make();
    stp_spans_cursor c;
    uint8_t band[H * STRIDE];
    (void)state;
    s.runs = backwards;
    stp_spans_start(&s, &c);
    assert_int_equal(stp_spans_draw(&s, &c, band, STRIDE, 1), STP_ERR_ARG);
    s.runs = past_row;
    stp_spans_start(&s, &c);
    assert_int_equal(stp_spans_draw(&s, &c, band, STRIDE, 1), STP_ERR_ARG);
    s.runs = bad_shade;
    stp_spans_start(&s, &c);
    assert_int_equal(stp_spans_draw(&s, &c, band, STRIDE, 1), STP_ERR_ARG);
    s = make();
    s.cell_rows = 3;
    stp_spans_start(&s, &c);
    assert_int_equal(stp_spans_draw(&s, &c, band, STRIDE, 1), STP_ERR_ARG);
    s.cell_rows = 0;
    assert_int_equal(stp_spans_draw(&s, &c, band, STRIDE, 1), STP_ERR_ARG);
    s.cell_rows = 16;
    assert_int_equal(stp_spans_draw(&s, &c, band, STRIDE, 1), STP_ERR_ARG);
    s = make();
    stp_spans_start(&s, &c);
    assert_int_equal(stp_spans_draw(&s, &c, band, STRIDE, H + 1u), STP_ERR_ARG);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_whole_picture),
        cmocka_unit_test(test_bands_of_one_row),
        cmocka_unit_test(test_bad_data_refused),
    };
    return cmocka_run_group_tests(tests, 0, 0);
}
