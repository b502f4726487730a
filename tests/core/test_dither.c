/* SPDX-License-Identifier: MIT */
/*
 * Halftone cells and HALFTONE-FILLIN (include/stipple/dither.h): Bayer
 * thresholds against ImageMagick's published rank matrices, the seed's 2x2
 * cells and spacings, pattern cells, and the exact bits a span writes.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "stipple/dither.h"
#include "dither_private.h" /* stp_cell_default, stp_halftone_pattern_byte */

/* ImageMagick's ordered-dither maps o2x2, o4x4, o8x8 (thresholds.xml,
 * "levels" with divisors 5, 17, 65), row-major, y down.  Value v is the
 * rank v - 1: the pixel turns on at the v-th of m + 1 grey levels. */
static const uint8_t im_o2x2[4] = {
    1, 3,
    4, 2,
};
static const uint8_t im_o4x4[16] = {
    1,  9,  3,  11,
    13, 5,  15, 7,
    4,  12, 2,  10,
    16, 8,  14, 6,
};
static const uint8_t im_o8x8[64] = {
    1,  49, 13, 61, 4,  52, 16, 64,
    33, 17, 45, 29, 36, 20, 48, 32,
    9,  57, 5,  53, 12, 60, 8,  56,
    41, 25, 37, 21, 44, 28, 40, 24,
    3,  51, 15, 63, 2,  50, 14, 62,
    35, 19, 47, 31, 34, 18, 46, 30,
    11, 59, 7,  55, 10, 58, 6,  54,
    43, 27, 39, 23, 42, 26, 38, 22,
};

static const uint8_t *im_map(int n)
{
    return n == 2 ? im_o2x2 : (n == 4 ? im_o4x4 : im_o8x8);
}

/* ceil(255 (r + 1) / (m + 1)) - 1, in integers */
static int linear_threshold(int r, int m)
{
    return (255 * (r + 1) + m) / (m + 1) - 1;
}

static void test_bayer_thresholds_match_imagemagick_ranks(void **state)
{
    static const int sizes[] = {2, 4, 8};
    int s, x, y;
    (void)state;
    for (s = 0; s < 3; s++) {
        int n = sizes[s], m = n * n;
        const uint8_t *map = im_map(n);
        stp_cell cell;
        memset(&cell, 0xEE, sizeof cell);
        assert_int_equal(stp_cell_bayer(&cell, n), 0);
        assert_int_equal(cell.kind, STP_CELL_THRESHOLD);
        assert_int_equal(cell.width, n);
        assert_int_equal(cell.height, n);
        for (y = 0; y < n; y++)
            for (x = 0; x < n; x++) {
                int r = map[y * n + x] - 1;
                if (cell.thresholds[y * n + x] != linear_threshold(r, m))
                    fail_msg("bayer %d: (%d,%d) threshold %d, want %d (rank %d)", n, x, y,
                             cell.thresholds[y * n + x], linear_threshold(r, m), r);
            }
    }
}

static void test_bayer_on_matches_imagemagick_comparison(void **state)
{
    /* ImageMagick's rule on 8-bit grey v: level floor(v (m+1) / 255), the
     * pixel of rank r is on when that level >= r + 1, i.e. v (m+1) >=
     * 255 (r+1).  stp_cell_on must agree for every v and position. */
    static const int sizes[] = {2, 4, 8};
    int s, x, y, v;
    (void)state;
    for (s = 0; s < 3; s++) {
        int n = sizes[s], m = n * n;
        const uint8_t *map = im_map(n);
        stp_cell cell;
        assert_int_equal(stp_cell_bayer(&cell, n), 0);
        for (v = 0; v < 256; v++)
            for (y = 0; y < 2 * n; y++) /* two tiles: x, y wrap */
                for (x = 0; x < 2 * n; x++) {
                    int r = map[(y % n) * n + (x % n)] - 1;
                    int want = v * (m + 1) >= 255 * (r + 1);
                    if (stp_cell_on(&cell, (uint32_t)x, (uint32_t)y, (uint8_t)v) != want)
                        fail_msg("bayer %d at (%d,%d), v=%d: on=%d, want %d", n, x, y, v,
                                 stp_cell_on(&cell, (uint32_t)x, (uint32_t)y, (uint8_t)v), want);
                }
        /* black is all off, white all on */
        for (y = 0; y < n; y++)
            for (x = 0; x < n; x++) {
                assert_false(stp_cell_on(&cell, (uint32_t)x, (uint32_t)y, 0));
                assert_true(stp_cell_on(&cell, (uint32_t)x, (uint32_t)y, 255));
            }
    }
}

static void test_bayer_rejects_other_sizes(void **state)
{
    static const int bad[] = {0, 1, 3, 5, 32, -2};
    stp_cell cell, before;
    int i;
    (void)state;
    memset(&cell, 0x33, sizeof cell);
    before = cell;
    for (i = 0; i < 6; i++) {
        assert_int_equal(stp_cell_bayer(&cell, bad[i]), -1);
        assert_int_equal(stp_cell_bayer_spaced(&cell, bad[i], STP_SPACING_CUBIC), -1);
    }
    assert_memory_equal(&cell, &before, sizeof cell);
    assert_int_equal(stp_cell_bayer(NULL, 4), -1);
}

/* The renderer's default cell (a mask on a constant table on 32-bit
 * targets) against the cell stp_cell_bayer(4) makes: the same thresholds,
 * every pixel and pattern byte the same at every intensity. */
static void test_default_cell_is_bayer4(void **state)
{
    stp_cell made, fixed;
    uint32_t x, y;
    int v;
    (void)state;
    assert_int_equal(stp_cell_bayer(&made, 4), 0);
    memset(&fixed, 0x5A, sizeof fixed);
    stp_cell_default(&fixed);
    assert_int_equal(fixed.kind, made.kind);
    assert_int_equal(fixed.width, 4);
    assert_int_equal(fixed.height, 4);
    assert_memory_equal(fixed.patterns, made.patterns, sizeof made.patterns);
    assert_memory_equal(stp_cell_table(&fixed), stp_cell_table(&made), 16);
    for (v = 0; v < 256; v++)
        for (y = 0; y < 8; y++) {
            assert_int_equal(stp_halftone_pattern_byte(&fixed, y, (uint8_t)v),
                             stp_halftone_pattern_byte(&made, y, (uint8_t)v));
            for (x = 0; x < 8; x++)
                assert_int_equal(stp_cell_on(&fixed, x, y, (uint8_t)v), stp_cell_on(&made, x, y, (uint8_t)v));
        }
}

static void test_seed_2x2_cell_values(void **state)
{
    /* Figure 10-30 on a 0-255 scale: lower right on above 50, upper right
     * above 100, lower left above 150, upper left above 200 (y down, so
     * "upper" is y = 0) */
    static const struct {
        uint32_t x, y;
        int threshold;
    } corners[4] = {{1, 1, 50}, {1, 0, 100}, {0, 1, 150}, {0, 0, 200}};
    stp_cell cell;
    int i;
    (void)state;
    stp_cell_seed2x2(&cell);
    assert_int_equal(cell.kind, STP_CELL_THRESHOLD);
    assert_int_equal(cell.width, 2);
    assert_int_equal(cell.height, 2);
    for (i = 0; i < 4; i++) {
        int t = corners[i].threshold;
        assert_int_equal(cell.thresholds[corners[i].y * 2 + corners[i].x], t);
        assert_false(stp_cell_on(&cell, corners[i].x, corners[i].y, (uint8_t)t));
        assert_true(stp_cell_on(&cell, corners[i].x, corners[i].y, (uint8_t)(t + 1)));
        /* and tiled */
        assert_true(stp_cell_on(&cell, corners[i].x + 6, corners[i].y + 10, (uint8_t)(t + 1)));
        assert_false(stp_cell_on(&cell, corners[i].x + 6, corners[i].y + 10, (uint8_t)t));
    }
}

static void test_spacings_for_2x2_equal_documented_numbers(void **state)
{
    /* ranks of the 2x2 cell: (0,0) 0, (1,0) 2, (0,1) 3, (1,1) 1 (o2x2) */
    static const int rank_at[4] = {0, 2, 3, 1};
    /* exponential: 255 2^(-5 (m-r)/(m+1)) with m = 4 is 255 (1, 2, 4, 8)/16,
     * the seed's 1, 2, 4, 8 (16 = full scale): 15.9, 31.9, 63.75, 127.5 */
    static const int expo[4] = {16, 32, 64, 128};
    /* cubic: 255 ((r+1)/5)^3 = 255 (1, 8, 27, 64)/125 */
    static const int cubic[4] = {2, 16, 55, 131};
    stp_cell e, c, l;
    int i;
    (void)state;
    assert_int_equal(stp_cell_bayer_spaced(&e, 2, STP_SPACING_EXPONENTIAL), 0);
    assert_int_equal(stp_cell_bayer_spaced(&c, 2, STP_SPACING_CUBIC), 0);
    assert_int_equal(stp_cell_bayer_spaced(&l, 2, STP_SPACING_LINEAR), 0);
    for (i = 0; i < 4; i++) {
        assert_int_equal(e.thresholds[i], expo[rank_at[i]]);
        assert_int_equal(c.thresholds[i], cubic[rank_at[i]]);
        assert_int_equal(l.thresholds[i], linear_threshold(rank_at[i], 4));
    }
    /* linear spacing is stp_cell_bayer */
    {
        stp_cell b;
        assert_int_equal(stp_cell_bayer(&b, 2), 0);
        assert_memory_equal(b.thresholds, l.thresholds, 4);
    }
}

static void test_spacings_for_4x4_and_8x8_follow_formula(void **state)
{
    /* For the larger cells: the same formulas rounded to nearest (0.5; the
     * exponential goes through stp_fix_exp2, relative 2^-14 of 255 = 0.016
     * more), and never decreasing with the rank. */
    static const int sizes[] = {4, 8};
    int s, i;
    (void)state;
    for (s = 0; s < 2; s++) {
        int n = sizes[s], m = n * n;
        const uint8_t *map = im_map(n);
        stp_cell e, c;
        assert_int_equal(stp_cell_bayer_spaced(&e, n, STP_SPACING_EXPONENTIAL), 0);
        assert_int_equal(stp_cell_bayer_spaced(&c, n, STP_SPACING_CUBIC), 0);
        for (i = 0; i < m; i++) {
            int r = map[i] - 1;
            double want_e = 255.0 * pow(2.0, -5.0 * (m - r) / (m + 1));
            double want_c = 255.0 * pow((double)(r + 1) / (m + 1), 3.0);
            int j;
            if (!(fabs(e.thresholds[i] - want_e) <= 0.52))
                fail_msg("exponential %dx%d rank %d: %d, want %.3f", n, n, r, e.thresholds[i], want_e);
            if (!(fabs(c.thresholds[i] - want_c) <= 0.5 + 1e-9))
                fail_msg("cubic %dx%d rank %d: %d, want %.3f", n, n, r, c.thresholds[i], want_c);
            for (j = 0; j < m; j++)
                if (map[j] - 1 > r)
                    assert_true(e.thresholds[j] >= e.thresholds[i] && c.thresholds[j] >= c.thresholds[i]);
        }
    }
}

static void test_user_cell(void **state)
{
    static const uint8_t t3x2[6] = {10, 20, 30, 40, 50, 60};
    uint8_t big[STP_CELL_MAX * STP_CELL_MAX];
    stp_cell cell, before;
    (void)state;
    assert_int_equal(stp_cell_user(&cell, 3, 2, t3x2), 0);
    assert_int_equal(cell.width, 3);
    assert_int_equal(cell.height, 2);
    assert_int_equal(cell.kind, STP_CELL_THRESHOLD);
    assert_memory_equal(cell.thresholds, t3x2, 6);
    assert_true(stp_cell_on(&cell, 5, 3, 61));  /* (2, 1): 60 */
    assert_false(stp_cell_on(&cell, 5, 3, 60));
    memset(big, 7, sizeof big);
    assert_int_equal(stp_cell_user(&cell, STP_CELL_MAX, STP_CELL_MAX, big), 0);
    assert_int_equal(stp_cell_user(&cell, 1, 1, big), 0);
    before = cell;
    assert_int_equal(stp_cell_user(&cell, 0, 2, t3x2), -1);
    assert_int_equal(stp_cell_user(&cell, 2, 0, t3x2), -1);
    assert_int_equal(stp_cell_user(&cell, STP_CELL_MAX + 1, 1, big), -1);
    assert_int_equal(stp_cell_user(&cell, 1, STP_CELL_MAX + 1, big), -1);
    assert_int_equal(stp_cell_user(&cell, 2, 2, NULL), -1);
    assert_memory_equal(&cell, &before, sizeof cell);
}

/* ---- pattern cell ---- */

/* Level L of the seed's 2x2 pattern turns on the first L pixels of the order
 * lower-right, upper-left, upper-right, lower-left. */
static int pattern_pixel_on(int level, int x, int y)
{
    static const int order_x[4] = {1, 0, 1, 0}, order_y[4] = {1, 0, 0, 1};
    int i;
    for (i = 0; i < level; i++)
        if (order_x[i] == x && order_y[i] == y)
            return 1;
    return 0;
}

/* The documented quantisation: level = (intensity 4 + 127) / 255 (round to
 * nearest of 4 intensity / 255). */
static int pattern_level(int v)
{
    return (v * 4 + 127) / 255;
}

static void test_pattern2x2_levels(void **state)
{
    stp_cell cell;
    int v, x, y;
    (void)state;
    stp_cell_pattern2x2(&cell);
    assert_int_equal(cell.kind, STP_CELL_PATTERN);
    assert_int_equal(cell.width, 2);
    assert_int_equal(cell.height, 2);
    /* level boundaries: 0..31 -> 0, 32 -> 1, 96 -> 2, 160 -> 3, 224 -> 4 */
    assert_int_equal(pattern_level(31), 0);
    assert_int_equal(pattern_level(32), 1);
    assert_int_equal(pattern_level(95), 1);
    assert_int_equal(pattern_level(96), 2);
    assert_int_equal(pattern_level(159), 2);
    assert_int_equal(pattern_level(160), 3);
    assert_int_equal(pattern_level(223), 3);
    assert_int_equal(pattern_level(224), 4);
    for (v = 0; v < 256; v++)
        for (y = 0; y < 4; y++)
            for (x = 0; x < 4; x++) {
                int want = pattern_pixel_on(pattern_level(v), x % 2, y % 2);
                if (stp_cell_on(&cell, (uint32_t)x, (uint32_t)y, (uint8_t)v) != want)
                    fail_msg("pattern2x2 v=%d at (%d,%d): on=%d want %d", v, x, y,
                             stp_cell_on(&cell, (uint32_t)x, (uint32_t)y, (uint8_t)v), want);
            }
    /* level 2 is a checkerboard: upper-left and lower-right */
    assert_true(stp_cell_on(&cell, 0, 0, 128) && stp_cell_on(&cell, 1, 1, 128));
    assert_false(stp_cell_on(&cell, 1, 0, 128) || stp_cell_on(&cell, 0, 1, 128));
    /* the number of ON pixels is the level: 0..4 */
    for (v = 0; v < 256; v++) {
        int on = 0;
        for (y = 0; y < 2; y++)
            for (x = 0; x < 2; x++)
                on += stp_cell_on(&cell, (uint32_t)x, (uint32_t)y, (uint8_t)v);
        assert_int_equal(on, pattern_level(v));
    }
}

/* ---- HALFTONE-FILLIN ---- */

/* Independent model of one bit: pixel x of a PBM-ordered row. */
static void set_bit(uint8_t *row, uint32_t x, int on)
{
    if (on)
        row[x / 8] = (uint8_t)(row[x / 8] | (1u << (7 - x % 8)));
    else
        row[x / 8] = (uint8_t)(row[x / 8] & ~(1u << (7 - x % 8)));
}

static int get_bit(const uint8_t *row, uint32_t x)
{
    return (row[x / 8] >> (7 - x % 8)) & 1;
}

/* What a pixel should be by the cell's definition (not stp_cell_on). */
static int model_on(const stp_cell *cell, uint32_t x, uint32_t y, uint8_t v)
{
    if (cell->kind == STP_CELL_PATTERN)
        return pattern_pixel_on(pattern_level(v), (int)(x % 2), (int)(y % 2));
    return v > cell->thresholds[(y % cell->height) * cell->width + (x % cell->width)];
}

#define ROW_BYTES 12 /* 96 pixels */

static void check_fillin(const stp_cell *cell, uint32_t x1, uint32_t x2, uint32_t y, uint8_t v,
                         uint8_t fill)
{
    uint8_t got[ROW_BYTES + 2], want[ROW_BYTES + 2];
    uint32_t x;
    memset(got, fill, sizeof got);
    memset(want, fill, sizeof want);
    for (x = x1; x <= x2; x++)
        set_bit(want, x, model_on(cell, x, y, v));
    stp_halftone_fillin(got, x1, x2, y, cell, v);
    if (memcmp(got, want, sizeof got) != 0) {
        for (x = 0; x < 8 * (ROW_BYTES + 2); x++)
            if (get_bit(got, x) != get_bit(want, x))
                fail_msg("fillin(x1=%u, x2=%u, y=%u, v=%u, cell %ux%u kind %u, row 0x%02x): "
                         "pixel %u is %d, want %d",
                         x1, x2, y, v, cell->width, cell->height, cell->kind, fill, x, get_bit(got, x),
                         get_bit(want, x));
    }
}

static void test_halftone_fillin_exact_bits(void **state)
{
    static const uint8_t t3x5[15] = {0, 100, 200, 50, 150, 250, 25, 125, 225, 75, 175, 255, 12, 112, 212};
    static const uint8_t values[] = {0, 1, 50, 51, 100, 127, 128, 200, 201, 254, 255};
    static const uint8_t fills[] = {0x00, 0xFF, 0xA5};
    stp_cell cells[5];
    uint32_t x1, x2, y;
    int c, iv, f;
    (void)state;
    assert_int_equal(stp_cell_bayer(&cells[0], 4), 0);
    assert_int_equal(stp_cell_bayer(&cells[1], 8), 0);
    stp_cell_seed2x2(&cells[2]);
    assert_int_equal(stp_cell_user(&cells[3], 3, 5, t3x5), 0); /* width not a power of two */
    stp_cell_pattern2x2(&cells[4]);
    for (c = 0; c < 5; c++)
        for (y = 0; y < 6; y++)
            for (x1 = 0; x1 < 20; x1++)
                for (x2 = x1; x2 < 8 * ROW_BYTES; x2 += 1 + x2 % 5)
                    for (iv = 0; iv < (int)sizeof values; iv++)
                        for (f = 0; f < 3; f++)
                            check_fillin(&cells[c], x1, x2, y, values[iv], fills[f]);
}

static void test_halftone_fillin_single_pixel(void **state)
{
    /* x1 == x2 fills exactly one pixel (unlike the seed's listing, which
     * returns at once): here at every position in a byte */
    stp_cell cell;
    uint8_t row[4];
    uint32_t x;
    (void)state;
    stp_cell_seed2x2(&cell);
    for (x = 0; x < 32; x++) {
        memset(row, 0, sizeof row);
        stp_halftone_fillin(row, x, x, 1, &cell, 255);
        assert_int_equal(get_bit(row, x), 1);
        assert_int_equal(row[x / 8], (uint8_t)(0x80u >> (x % 8)));
        memset(row, 0xFF, sizeof row);
        stp_halftone_fillin(row, x, x, 1, &cell, 0);
        assert_int_equal(row[x / 8], (uint8_t)~(0x80u >> (x % 8)));
    }
}

static void test_halftone_fillin_uses_x_mod_cell(void **state)
{
    /* hx = X1 mod width: a span starting at an odd x takes the cell's odd
     * column first (seed cell, row 1: thresholds 150, 50) */
    stp_cell cell;
    uint8_t row[2] = {0, 0};
    (void)state;
    stp_cell_seed2x2(&cell);
    stp_halftone_fillin(row, 3, 6, 1, &cell, 100); /* 3:50 on, 4:150 off, 5 on, 6 off */
    assert_int_equal(row[0], 0x14);                 /* pixels 3 and 5 */
    assert_int_equal(row[1], 0x00);
    stp_halftone_fillin(row, 3, 6, 0, &cell, 150); /* row 0: 200, 100: 3 on, 5 on */
    assert_int_equal(row[0], 0x14);
    stp_halftone_fillin(row, 3, 6, 0, &cell, 201);
    assert_int_equal(row[0], 0x1E);
}

static void test_halftone_row(void **state)
{
    stp_cell cells[3];
    uint8_t grey[77], out[11]; /* 77 pixels: 10 bytes, and one more */
    uint32_t x, y;
    int c;
    (void)state;
    assert_int_equal(stp_cell_bayer(&cells[0], 8), 0);
    stp_cell_pattern2x2(&cells[1]);
    stp_cell_seed2x2(&cells[2]);
    for (x = 0; x < sizeof grey; x++)
        grey[x] = (uint8_t)(x * 37 + 11);
    for (c = 0; c < 3; c++)
        for (y = 0; y < 17; y++) {
            memset(out, 0x5A, sizeof out);
            stp_halftone_row(out, grey, sizeof grey, y, &cells[c]);
            for (x = 0; x < sizeof grey; x++)
                if (get_bit(out, x) != model_on(&cells[c], x, y, grey[x]))
                    fail_msg("halftone_row cell %d y=%u x=%u grey=%u: %d", c, y, x, grey[x], get_bit(out, x));
            /* bytes past the row are not written */
            assert_int_equal(out[10], 0x5A);
        }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_bayer_thresholds_match_imagemagick_ranks),
        cmocka_unit_test(test_bayer_on_matches_imagemagick_comparison),
        cmocka_unit_test(test_bayer_rejects_other_sizes),
        cmocka_unit_test(test_default_cell_is_bayer4),
        cmocka_unit_test(test_seed_2x2_cell_values),
        cmocka_unit_test(test_spacings_for_2x2_equal_documented_numbers),
        cmocka_unit_test(test_spacings_for_4x4_and_8x8_follow_formula),
        cmocka_unit_test(test_user_cell),
        cmocka_unit_test(test_pattern2x2_levels),
        cmocka_unit_test(test_halftone_fillin_exact_bits),
        cmocka_unit_test(test_halftone_fillin_single_pixel),
        cmocka_unit_test(test_halftone_fillin_uses_x_mod_cell),
        cmocka_unit_test(test_halftone_row),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
