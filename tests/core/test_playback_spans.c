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
    s.run_bytes = sizeof runs;
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
    s.run_bytes = sizeof backwards;
    stp_spans_start(&s, &c);
    assert_int_equal(stp_spans_draw(&s, &c, band, STRIDE, 1), STP_ERR_ARG);
    s.runs = past_row;
    s.run_bytes = sizeof past_row;
    stp_spans_start(&s, &c);
    assert_int_equal(stp_spans_draw(&s, &c, band, STRIDE, 1), STP_ERR_ARG);
    s.runs = bad_shade;
    s.run_bytes = sizeof bad_shade;
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

/* A NULL band, spans, cursor or array is refused, not read or written. */
static void test_null_refused(void **state)
{
    stp_spans s = make();
    stp_spans_cursor c;
    uint8_t band[H * STRIDE];
    (void)state;
    stp_spans_start(&s, &c);
    assert_int_equal(stp_spans_draw(&s, &c, 0, STRIDE, 1), STP_ERR_ARG);
    assert_int_equal(stp_spans_draw(0, &c, band, STRIDE, 1), STP_ERR_ARG);
    assert_int_equal(stp_spans_draw(&s, 0, band, STRIDE, 1), STP_ERR_ARG);
    s.patterns = 0;
    assert_int_equal(stp_spans_draw(&s, &c, band, STRIDE, 1), STP_ERR_ARG);
    s = make();
    s.runs = 0;
    stp_spans_start(&s, &c);
    assert_int_equal(stp_spans_draw(&s, &c, band, STRIDE, 1), STP_ERR_ARG);
}

/* Width 0 (whose last column would be 255 after the wrap) and widths past
 * 256 are refused; so are rows 0 and a stride narrower than a row. */
static void test_sizes_refused(void **state)
{
    stp_spans s = make();
    stp_spans_cursor c;
    uint8_t band[H * STRIDE];
    (void)state;
    s.width = 0;
    stp_spans_start(&s, &c);
    assert_int_equal(stp_spans_draw(&s, &c, band, STRIDE, 1), STP_ERR_ARG);
    s.width = 257;
    assert_int_equal(stp_spans_draw(&s, &c, band, 64, 1), STP_ERR_ARG);
    s = make();
    assert_int_equal(stp_spans_draw(&s, &c, band, STRIDE, 0), STP_ERR_ARG);
    assert_int_equal(stp_spans_draw(&s, &c, band, 2, 1), STP_ERR_ARG);
}

/* Runs that never reach the last column: the player stops at run_bytes
 * (the copies below are exactly that long, so under ASan a read past them
 * is caught) with STP_ERR_ARG. */
static void test_short_runs_refused(void **state)
{
    static const uint8_t short_row[] = {3, 0, 9, 1};       /* row 0 ends at x 9 of 20 */
    static const uint8_t short_rows[] = {20, 0, 20, 1, 5, 2}; /* row 2 cut short */
    uint8_t *copy;
    stp_spans s = make();
    stp_spans_cursor c;
    uint8_t band[H * STRIDE];
    (void)state;
    copy = test_malloc(sizeof short_row);
    memcpy(copy, short_row, sizeof short_row);
    s.runs = copy;
    s.run_bytes = sizeof short_row;
    stp_spans_start(&s, &c);
    assert_int_equal(stp_spans_draw(&s, &c, band, STRIDE, 1), STP_ERR_ARG);
    test_free(copy);
    copy = test_malloc(sizeof short_rows);
    memcpy(copy, short_rows, sizeof short_rows);
    s.runs = copy;
    s.run_bytes = sizeof short_rows;
    stp_spans_start(&s, &c);
    assert_int_equal(stp_spans_draw(&s, &c, band, STRIDE, 2), STP_OK);
    assert_int_equal(stp_spans_draw(&s, &c, band, STRIDE, 1), STP_ERR_ARG);
    assert_int_equal(c.y, 2);
    test_free(copy);
    /* the whole picture with one byte too few */
    s = make();
    s.run_bytes = sizeof runs - 1u;
    stp_spans_start(&s, &c);
    assert_int_equal(stp_spans_draw(&s, &c, band, STRIDE, H), STP_ERR_ARG);
}

/* A cursor outside the data is refused before anything is written: before
 * the runs, at their end, and past it (the arrays around the runs are
 * real, so every pointer here is valid to form). */
static void test_cursor_outside_refused(void **state)
{
    static const uint8_t data[] = {20, 0, 20, 1, 20, 2, 20, 0, 20, 1};
    stp_spans s = make();
    stp_spans_cursor c;
    uint8_t band[STRIDE];
    (void)state;
    s.runs = data + 2;
    s.run_bytes = 4; /* rows {20, 1} and {20, 2} */
    memset(band, 0x5A, sizeof band);
    stp_spans_start(&s, &c);
    c.next = data;
    assert_int_equal(stp_spans_draw(&s, &c, band, STRIDE, 1), STP_ERR_ARG);
    c.next = data + 1;
    assert_int_equal(stp_spans_draw(&s, &c, band, STRIDE, 1), STP_ERR_ARG);
    c.next = data + 6; /* the end of the data */
    assert_int_equal(stp_spans_draw(&s, &c, band, STRIDE, 1), STP_ERR_ARG);
    c.next = data + 8;
    assert_int_equal(stp_spans_draw(&s, &c, band, STRIDE, 1), STP_ERR_ARG);
    c.next = data + 5; /* one byte of data left */
    assert_int_equal(stp_spans_draw(&s, &c, band, STRIDE, 1), STP_ERR_ARG);
    c.next = s.runs; /* no data at all */
    s.run_bytes = 0;
    assert_int_equal(stp_spans_draw(&s, &c, band, STRIDE, 1), STP_ERR_ARG);
    s.run_bytes = 4;
    assert_int_equal(band[0], 0x5A);
    assert_int_equal(c.y, 0);
    /* inside: drawn, and the cursor moves on to the end */
    c.next = data + 4;
    assert_int_equal(stp_spans_draw(&s, &c, band, STRIDE, 1), STP_OK);
    assert_ptr_equal(c.next, data + 6);
    assert_int_equal(band[0], 0x81);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_whole_picture),
        cmocka_unit_test(test_bands_of_one_row),
        cmocka_unit_test(test_bad_data_refused),
        cmocka_unit_test(test_null_refused),
        cmocka_unit_test(test_sizes_refused),
        cmocka_unit_test(test_short_runs_refused),
        cmocka_unit_test(test_cursor_outside_refused),
    };
    return cmocka_run_group_tests(tests, 0, 0);
}
