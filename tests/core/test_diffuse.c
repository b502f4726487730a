/* SPDX-License-Identifier: MIT */
/*
 * Error diffusion (include/stipple/diffuse.h): rows worked out by hand for
 * every kernel (the decisions the right-hand taps make, the shares the taps
 * below receive, serpentine mirroring), the error-row sizes and checks, and
 * whole pictures against the double-precision reference
 * (tests/reference/diffuse_ref.c).
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

#include "reference/diffuse_ref.h"
#include "stipple/diffuse.h"
#include "stipple/dither.h"
#include "stipple/render.h"

enum { MAX_W = 64 };

static int16_t errors[3 * (MAX_W + 4)];

static stp_diffusion make(int kernel, int serpentine, uint32_t width)
{
    stp_diffusion d;
    memset(&d, 0, sizeof d);
    d.kernel = (uint8_t)kernel;
    d.serpentine = (uint8_t)serpentine;
    d.errors = errors;
    d.error_count = stp_diffusion_error_count(kernel, width);
    assert_int_equal(stp_diffusion_check(&d, width), STP_OK);
    return d;
}

static void test_error_count_and_check(void **state)
{
    stp_diffusion d;
    (void)state;
    memset(&d, 0, sizeof d);
    /* two rows for kernels reaching one row down, three for two rows */
    assert_int_equal(stp_diffusion_error_count(STP_DIFFUSE_FLOYD_STEINBERG, 128), 2 * 132);
    assert_int_equal(stp_diffusion_error_count(STP_DIFFUSE_SIERRA_LITE, 128), 2 * 132);
    assert_int_equal(stp_diffusion_error_count(STP_DIFFUSE_BURKES, 128), 2 * 132);
    assert_int_equal(stp_diffusion_error_count(STP_DIFFUSE_ATKINSON, 128), 3 * 132);
    assert_int_equal(stp_diffusion_error_count(STP_DIFFUSE_JARVIS_JUDICE_NINKE, 400), 3 * 404);
    assert_int_equal(stp_diffusion_error_count(STP_DIFFUSE_STUCKI, 1), 3 * 5);
    assert_int_equal(stp_diffusion_error_count(6, 128), 0);
    assert_int_equal(stp_diffusion_error_count(-1, 128), 0);
    assert_int_equal(stp_diffusion_error_count(0, 0), 0);
    assert_int_equal(stp_diffusion_error_count(0, 32768), 0);
    d.kernel = STP_DIFFUSE_FLOYD_STEINBERG;
    d.serpentine = 0;
    d.errors = errors;
    d.error_count = 2 * 132 - 1;
    assert_int_equal(stp_diffusion_check(&d, 128), STP_ERR_MEMORY);
    d.error_count = 2 * 132;
    assert_int_equal(stp_diffusion_check(&d, 128), STP_OK);
    d.kernel = 6;
    assert_int_equal(stp_diffusion_check(&d, 128), STP_ERR_ARG);
    d.kernel = 0;
    d.errors = 0;
    assert_int_equal(stp_diffusion_check(&d, 128), STP_ERR_ARG);
    assert_int_equal(stp_diffusion_check(0, 128), STP_ERR_ARG);
}

/* One row [v, v, 0, 0, 0, 0]: pixel 0 is OFF (v < 127.5) and hands
 * v w_right / divisor to pixel 1, which is ON when that reaches 127.5.
 * v = 100: FS 100 + 700/16 = 143.75 ON; Atkinson 100 + 100/8 = 112.5 OFF;
 * Sierra-Lite 100 + 200/4 = 150 ON; JJN 100 + 700/48 = 114.6 OFF; Stucki
 * 100 + 800/42 = 119.0 OFF; Burkes 100 + 800/32 = 125 OFF.  v = 120: all
 * ON (the smallest, Atkinson, 135).  Everything after stays OFF: pixel 1's
 * error is -111 or less (ON) or at most 125 spread thinly (OFF). */
static void test_right_taps_by_hand(void **state)
{
    static const uint8_t on_at_100[STP_DIFFUSE_KERNELS] = {1, 0, 1, 0, 0, 0};
    int k;
    (void)state;
    for (k = 0; k < STP_DIFFUSE_KERNELS; k++) {
        stp_diffusion d = make(k, 0, 6);
        uint8_t row[6] = {100, 100, 0, 0, 0, 0};
        stp_diffuse_row(&d, row, 6, 0);
        assert_int_equal(row[0], on_at_100[k] ? 0x40 : 0x00);
        memcpy(row, (const uint8_t[6]){120, 120, 0, 0, 0, 0}, 6);
        stp_diffuse_row(&d, row, 6, 0);
        assert_int_equal(row[0], 0x40);
    }
}

/* The taps below: a lone OFF pixel of 126 at the end of a row of zeros
 * has error 126 levels = 504 quarter levels, and each tap below holds
 * exactly 504 * weight (the entries hold error * weight, read over the
 * divisor), and nothing else is touched.  The weights here are written out
 * again from the published kernels. */
typedef struct below_tap {
    int dx, dy, weight;
} below_tap;
static const struct {
    int divisor, count;
    below_tap taps[10];
} below[STP_DIFFUSE_KERNELS] = {
    {16, 3, {{-1, 1, 3}, {0, 1, 5}, {1, 1, 1}}},
    {8, 4, {{-1, 1, 1}, {0, 1, 1}, {1, 1, 1}, {0, 2, 1}}},
    {4, 2, {{-1, 1, 1}, {0, 1, 1}}},
    {48, 10, {{-2, 1, 3}, {-1, 1, 5}, {0, 1, 7}, {1, 1, 5}, {2, 1, 3}, {-2, 2, 1}, {-1, 2, 3}, {0, 2, 5}, {1, 2, 3}, {2, 2, 1}}},
    {42, 10, {{-2, 1, 2}, {-1, 1, 4}, {0, 1, 8}, {1, 1, 4}, {2, 1, 2}, {-2, 2, 1}, {-1, 2, 2}, {0, 2, 4}, {1, 2, 2}, {2, 2, 1}}},
    {32, 5, {{-2, 1, 2}, {-1, 1, 4}, {0, 1, 8}, {1, 1, 4}, {2, 1, 2}}},
};

static void check_below(int k, int y, int x, int mirror, uint32_t width)
{
    size_t span = width + 4, rows = stp_diffusion_error_count(k, width) / span, i;
    int16_t expect[3 * (MAX_W + 4)];
    int t;
    memset(expect, 0, sizeof expect);
    for (t = 0; t < below[k].count; t++) {
        const below_tap *b = &below[k].taps[t];
        size_t slot = (size_t)(y + b->dy) % rows;
        expect[slot * span + (size_t)(x + 2 + mirror * b->dx)] = (int16_t)(504 * b->weight);
    }
    for (i = 0; i < rows * span; i++)
        if (errors[i] != expect[i])
            fail_msg("kernel %d: error entry %zu (row slot %zu, column %d) is %d, expected %d", k, i,
                     i / span, (int)(i % span) - 2, errors[i], expect[i]);
}

static void test_below_taps_by_hand(void **state)
{
    int k;
    (void)state;
    for (k = 0; k < STP_DIFFUSE_KERNELS; k++) {
        stp_diffusion d = make(k, 0, 5);
        uint8_t row[5] = {0, 0, 0, 0, 126};
        stp_diffuse_row(&d, row, 5, 0);
        assert_int_equal(row[0], 0);
        check_below(k, 0, 4, 1, 5);
    }
}

/* Serpentine: row 1 runs right to left, so its pixel 0 is the last and its
 * kernel is mirrored: the taps below land at x - dx.  And [0, 0, 0, v, v]
 * on row 1 turns pixel 3 ON exactly where [v, v, 0, 0, 0] turned pixel 1
 * ON on a row run left to right. */
static void test_serpentine_by_hand(void **state)
{
    static const uint8_t on_at_100[STP_DIFFUSE_KERNELS] = {1, 0, 1, 0, 0, 0};
    int k;
    (void)state;
    for (k = 0; k < STP_DIFFUSE_KERNELS; k++) {
        stp_diffusion d = make(k, 1, 5);
        uint8_t row[5] = {0, 0, 0, 0, 0}, row1[5] = {126, 0, 0, 0, 0}, row2[5] = {0, 0, 0, 100, 100};
        stp_diffuse_row(&d, row, 5, 0);
        stp_diffuse_row(&d, row1, 5, 1);
        assert_int_equal(row1[0], 0);
        check_below(k, 1, 0, -1, 5);
        /* a fresh picture for the decision test */
        memset(row, 0, sizeof row);
        stp_diffuse_row(&d, row, 5, 0);
        stp_diffuse_row(&d, row2, 5, 1);
        assert_int_equal(row2[0], on_at_100[k] ? 0x10 : 0x00);
    }
}

/* Row 0 clears whatever the rows held; padding bits are 0. */
static void test_row0_clears_and_padding(void **state)
{
    stp_diffusion d = make(STP_DIFFUSE_FLOYD_STEINBERG, 0, 10);
    uint8_t row[10];
    size_t i;
    (void)state;
    for (i = 0; i < sizeof errors / sizeof errors[0]; i++)
        errors[i] = 8000;
    memset(row, 255, sizeof row);
    stp_diffuse_row(&d, row, 10, 0);
    assert_int_equal(row[0], 0xFF);
    assert_int_equal(row[1], 0xC0); /* pixels 8, 9 ON, 6 padding bits 0 */
    memset(row, 0, sizeof row);
    stp_diffuse_row(&d, row, 10, 0);
    assert_int_equal(row[0], 0);
    assert_int_equal(row[1], 0);
}

/* Threshold modulation by hand (Floyd-Steinberg, divisor 16, a lone first
 * pixel so no error comes in): the midpoint moves by (m - 127.5) a / 256
 * w levels.  a = 255, w = 1: m = 255 puts it at 254.5 (254 OFF, 255 ON),
 * m = 0 at 0.5 (0 OFF, 1 ON), m = 128 at 127.998 (127 OFF, 128 ON: the
 * plain midpoint too).  band 10: level 140 (|2p - 255| = 25) gets w = 3/8,
 * the midpoint 127.5 + 127.5 * 255/256 * 3/8 = 175.1: OFF; level 150 (45)
 * gets w = 0: ON as without modulation; level 100 under m = 0 with a = 64,
 * band 128: midpoint 127.5 - 31.9 = 95.6, ON (OFF unmodulated). */
static void test_modulation_by_hand(void **state)
{
    static uint8_t mask[64 * 64];
    static const struct {
        uint8_t m, amplitude, band, level, on;
    } cases[] = {{255, 255, 128, 254, 0}, {255, 255, 128, 255, 1}, {0, 255, 128, 0, 0},
                 {0, 255, 128, 1, 1},     {128, 255, 128, 127, 0}, {128, 255, 128, 128, 1},
                 {255, 255, 10, 140, 0},  {255, 255, 10, 150, 1},  {0, 64, 128, 100, 1},
                 {0, 0, 128, 100, 0}};
    size_t i;
    (void)state;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        stp_diffusion d = make(STP_DIFFUSE_FLOYD_STEINBERG, 0, 2);
        uint8_t row[2];
        memset(mask, 0, sizeof mask);
        mask[0] = cases[i].m;
        d.noise = mask;
        d.noise_amplitude = cases[i].amplitude;
        d.noise_band = cases[i].band;
        row[0] = cases[i].level;
        row[1] = 0;
        stp_diffuse_row(&d, row, 2, 0);
        if ((row[0] >> 7) != cases[i].on)
            fail_msg("case %zu: mask %d amplitude %d band %d level %d: ON %d, expected %d", i,
                     cases[i].m, cases[i].amplitude, cases[i].band, cases[i].level, row[0] >> 7,
                     cases[i].on);
    }
    /* the mask repeats every 64 pixels and rows: pixel (64, 64) reads mask[0] */
    {
        static uint8_t rows[65][72];
        stp_diffusion d;
        int16_t big[2 * (72 + 4)];
        uint32_t y;
        memset(&d, 0, sizeof d);
        d.errors = big;
        d.error_count = stp_diffusion_error_count(0, 72);
        memset(mask, 128, sizeof mask);
        mask[0] = 255;
        d.noise = mask;
        d.noise_amplitude = 255;
        d.noise_band = 128;
        for (y = 0; y < 65; y++) {
            memset(rows[y], 0, sizeof rows[y]);
            if (y == 64)
                rows[y][64] = 200; /* ON at 127.998, OFF at 254.5 */
            stp_diffuse_row(&d, rows[y], 72, y);
        }
        assert_int_equal(rows[64][8], 0x00);
    }
}

/* Floyd-Steinberg's weights in the band (diffuse.h), with a mask of
 * amplitude 0 (no threshold moves) and band 42 (weights 5 2 6 3 for
 * levels 82..173, |2p - 255| <= 91): [90, 90, 0, 0, 0, 0] keeps pixel 1
 * OFF (90 + 90 * 5/16 = 118.1; with 7/16 it was 129.4, ON), while
 * [81, 81, 0...] (|2p - 255| = 93, outside) hands on 7/16 as before:
 * 81 + 35.4 = 116.4 OFF, and [100, 100, 0...] (in the band) 100 + 31.25 =
 * 131.25 ON.  Below: a lone 126 (in the band; error 504 quarter levels)
 * puts exactly 504 * 2, 504 * 6 and 504 * 3 below-left, below and
 * below-right, a lone 81 (outside) 324 * 3, 5, 1, and the band's last
 * levels 82 and 173 and the first outside, 174, likewise; the other
 * kernels keep their weights in the band. */
static void test_band_weights_by_hand(void **state)
{
    static const uint8_t zero_mask[64 * 64];
    static const struct {
        uint8_t level, on;
    } right[] = {{90, 0}, {81, 0}, {100, 1}, {120, 1}};
    static const struct {
        uint8_t level;
        int16_t weights[3];
    } lone[] = {{126, {2, 6, 3}}, {81, {3, 5, 1}}, {82, {2, 6, 3}}, {173, {2, 6, 3}}, {174, {3, 5, 1}}};
    size_t i;
    int k;
    (void)state;
    for (i = 0; i < sizeof right / sizeof right[0]; i++) {
        stp_diffusion d = make(STP_DIFFUSE_FLOYD_STEINBERG, 0, 6);
        uint8_t row[6] = {0, 0, 0, 0, 0, 0};
        d.noise = zero_mask;
        d.noise_band = 42;
        row[0] = row[1] = right[i].level;
        stp_diffuse_row(&d, row, 6, 0);
        if (row[0] != (right[i].on ? 0x40 : 0x00))
            fail_msg("level %d: row 0x%02x", right[i].level, row[0]);
    }
    for (i = 0; i < sizeof lone / sizeof lone[0]; i++) {
        stp_diffusion d = make(STP_DIFFUSE_FLOYD_STEINBERG, 0, 5);
        uint8_t row[5] = {0, 0, 0, 0, 0};
        int32_t e = (int32_t)lone[i].level * 4 - (lone[i].level > 127 ? 1020 : 0);
        d.noise = zero_mask;
        d.noise_band = 42;
        row[4] = lone[i].level;
        stp_diffuse_row(&d, row, 5, 0);
        /* row 1's entry of column x is errors[9 + 2 + x] (rows of 5 + 4
         * entries; column 5 is the margin that takes the share past the edge) */
        assert_int_equal(errors[9 + 2 + 3], (int16_t)(e * lone[i].weights[0]));
        assert_int_equal(errors[9 + 2 + 4], (int16_t)(e * lone[i].weights[1]));
        assert_int_equal(errors[9 + 2 + 5], (int16_t)(e * lone[i].weights[2]));
    }
    /* the other kernels: the same pictures as without a mask */
    for (k = 1; k < STP_DIFFUSE_KERNELS; k++) {
        stp_diffusion d = make(k, 0, 5);
        uint8_t row[5] = {0, 0, 0, 0, 126};
        d.noise = zero_mask;
        d.noise_band = 42;
        stp_diffuse_row(&d, row, 5, 0);
        check_below(k, 0, 4, 1, 5);
    }
}

/* A test picture: smooth ramps and a disc, values 0..255. */
static void test_picture(uint8_t *grey, int w, int h)
{
    int x, y;
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            double dx = x - w * 0.6, dy = y - h * 0.4;
            double v = 255.0 * x / (w - 1) * 0.7 + 60.0 * y / (h - 1);
            if (dx * dx + dy * dy < (h * 0.3) * (h * 0.3))
                v = 40 + 2 * y;
            grey[y * w + x] = (uint8_t)(v > 255 ? 255 : v);
        }
}

/* Box mean over 4x4 blocks of the difference of two 0/1 pictures. */
static double block_difference(const unsigned char *a, const unsigned char *b, int w, int h)
{
    int bx, by, x, y;
    double worst = 0;
    for (by = 0; by + 4 <= h; by += 4)
        for (bx = 0; bx + 4 <= w; bx += 4) {
            int d = 0;
            for (y = by; y < by + 4; y++)
                for (x = bx; x < bx + 4; x++)
                    d += a[y * w + x] - b[y * w + x];
            if (fabs(d / 16.0) > worst)
                worst = fabs(d / 16.0);
        }
    return worst;
}

/* Whole pictures against the double reference: the fixed-point shares
 * differ from exact ones by 1/64 level at most, so the two agree pixel for
 * pixel until a value falls within that of 127.5, after which the patterns
 * drift apart but keep the same density: so the first row agrees exactly
 * (its error only travels right, where rounding is smallest), the ON pixels
 * number the same within 4 of 3072, and no 4x4 block differs by more than
 * 4 of its 16 pixels. */
static void test_against_double_reference(void **state)
{
    enum { W = 64, H = 48 };
    static uint8_t grey[W * H], row[W];
    static double ref_in[W * H];
    static unsigned char ref_bits[W * H], bits[W * H];
    int k, serp, x, y;
    (void)state;
    test_picture(grey, W, H);
    for (x = 0; x < W * H; x++)
        ref_in[x] = grey[x] / 255.0;
    for (k = 0; k < STP_DIFFUSE_KERNELS; k++)
        for (serp = 0; serp < 4; serp++) {
            /* serp 2, 3: rows left to right, then serpentine, with the
             * still default's modulation (blue noise, band 42; amplitude
             * 20 and band weights for Floyd-Steinberg, 96 for the others) */
            stp_diffusion d = make(k, serp & 1, W);
            long same = 0, on = 0, ref_on = 0;
            if (serp >= 2) {
                d.noise = stp_cell_blue_noise_64;
                d.noise_amplitude = STP_DIFFUSE_NOISE_AMPLITUDE_OF(k);
                d.noise_band = STP_DIFFUSE_NOISE_BAND;
            }
            ref_diffuse_noise(ref_in, W, H, (ref_kernel)k, serp & 1, serp >= 2 ? stp_cell_blue_noise_64 : 0,
                              STP_DIFFUSE_NOISE_AMPLITUDE_OF(k), STP_DIFFUSE_NOISE_BAND, ref_bits);
            for (y = 0; y < H; y++) {
                memcpy(row, grey + y * W, W);
                stp_diffuse_row(&d, row, W, (uint32_t)y);
                for (x = 0; x < W; x++)
                    bits[y * W + x] = (unsigned char)((row[x >> 3] >> (7 - (x & 7))) & 1);
            }
            /* a moved threshold is off the grid of the rounded errors, so
             * with modulation a value within rounding of it may fall the
             * other way and row 0 drift from there: only the counts and
             * blocks below hold then (the arithmetic is checked by hand) */
            for (x = 0; x < W && serp < 2; x++)
                if (bits[x] != ref_bits[x])
                    fail_msg("kernel %d serpentine %d: row 0 pixel %d differs", k, serp, x);
            for (x = 0; x < W * H; x++) {
                same += bits[x] == ref_bits[x];
                on += bits[x];
                ref_on += ref_bits[x];
            }
            printf("kernel %d serpentine %d: %ld of %d pixels equal, ON %ld vs %ld, worst 4x4 block %.3f\n",
                   k, serp, same, W * H, on, ref_on, block_difference(bits, ref_bits, W, H));
            assert_true(labs(on - ref_on) <= 4);
            assert_true(block_difference(bits, ref_bits, W, H) <= 0.25);
        }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_error_count_and_check),
        cmocka_unit_test(test_right_taps_by_hand),
        cmocka_unit_test(test_below_taps_by_hand),
        cmocka_unit_test(test_serpentine_by_hand),
        cmocka_unit_test(test_row0_clears_and_padding),
        cmocka_unit_test(test_modulation_by_hand),
        cmocka_unit_test(test_band_weights_by_hand),
        cmocka_unit_test(test_against_double_reference),
    };
    return cmocka_run_group_tests(tests, 0, 0);
}
