/* SPDX-License-Identifier: MIT */
/*
 * Palettes (tools/palette.h): the built-in palettes and palette files, the
 * nearest colour in the codes' light or in linear light, ordered and
 * diffused dithering worked out by hand, and the SSD1680's two planes.
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "palette.h"

static stp_palette load(const char *name)
{
    stp_palette p;
    char err[256];
    if (stp_palette_load(name, &p, err, sizeof err) != 0)
        fail_msg("%s", err);
    return p;
}

static void test_builtin(void **state)
{
    stp_palette p;
    (void)state;
    p = load("bw");
    assert_int_equal(p.count, 2);
    assert_true(p.grey);
    assert_false(p.bwr);
    p = load("bwr");
    assert_int_equal(p.count, 3);
    assert_false(p.grey);
    assert_true(p.bwr);
    assert_memory_equal(p.rgb[2], ((const uint8_t[]){255, 0, 0}), 3);
    p = load("grey4");
    assert_int_equal(p.count, 4);
    assert_true(p.grey);
    assert_int_equal(p.rgb[1][0], 85);
    assert_int_equal(p.rgb[2][2], 170);
    p = load("gray16");
    assert_int_equal(p.count, 16);
    assert_int_equal(p.rgb[15][1], 255);
    assert_int_equal(p.rgb[7][0], 119);
    p = load("rgb8");
    assert_int_equal(p.count, 8);
    assert_false(p.grey);
    /* index = 4 R + 2 G + B */
    assert_memory_equal(p.rgb[6], ((const uint8_t[]){255, 255, 0}), 3);
    assert_memory_equal(p.rgb[1], ((const uint8_t[]){0, 0, 255}), 3);
    assert_true(stp_palette_is_name("grey4"));
    assert_false(stp_palette_is_name("grey"));
}

static void write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(text, f);
    fclose(f);
}

static void test_file(void **state)
{
    char path[] = "/tmp/stp_palette_XXXXXX";
    char err[256];
    stp_palette p;
    int fd = mkstemp(path);
    (void)state;
    assert_true(fd >= 0);
    write_text(path, "# three inks\n0 0 0 black\n\n  255 255 255\n0 128 255 sky\n");
    assert_int_equal(stp_palette_load(path, &p, err, sizeof err), 0);
    assert_int_equal(p.count, 3);
    assert_memory_equal(p.rgb[2], ((const uint8_t[]){0, 128, 255}), 3);
    assert_false(p.grey);
    write_text(path, "0 0 0\n255 255\n");
    assert_int_equal(stp_palette_load(path, &p, err, sizeof err), -1);
    assert_non_null(strstr(err, ":2: expected three codes"));
    write_text(path, "0 0 0\n1 2 256\n");
    assert_int_equal(stp_palette_load(path, &p, err, sizeof err), -1);
    assert_non_null(strstr(err, ":2:"));
    write_text(path, "7 7 7\n");
    assert_int_equal(stp_palette_load(path, &p, err, sizeof err), -1);
    assert_non_null(strstr(err, "at least 2 colours"));
    remove(path);
    assert_int_equal(stp_palette_load(path, &p, err, sizeof err), -1);
    assert_non_null(strstr(err, "cannot open"));
}

/* grey4's codes 0, 85, 170, 255 are light 0, 1/3, 2/3, 1, or decoded from
 * sRGB 0, 0.0908, 0.4020, 1: light 0.25 is nearest 1/3 (index 1) in the
 * first reading and 0.4020 (index 2) in linear light. */
static void test_nearest(void **state)
{
    stp_palette p = load("grey4");
    double quarter[3] = {0.25, 0.25, 0.25}, red[3] = {0.9, 0.1, 0.1}, pale[3] = {0.6, 0.6, 0.6};
    (void)state;
    assert_int_equal(stp_palette_nearest(&p, 0, quarter), 1);
    assert_int_equal(stp_palette_nearest(&p, 1, quarter), 2);
    assert_true(fabs(stp_palette_value(85, 1) - 0.0908) < 1e-4);
    p = load("bwr");
    assert_int_equal(stp_palette_nearest(&p, 0, red), 2);
    assert_int_equal(stp_palette_nearest(&p, 0, pale), 1);
}

/* Ordered, grey4 with a 2x2 user cell of thresholds 0 64 / 128 192: code
 * 128 (0.50196) lies between 1/3 and 2/3 at f = 0.50588, intensity
 * round(129.0) = 129, which is above 0, 64 and 128: three pixels take
 * the upper level (index 2), the one with threshold 192 the lower. */
static void test_ordered_grey4(void **state)
{
    static const uint8_t thresholds[4] = {0, 64, 128, 192};
    stp_palette p = load("grey4");
    stp_cell cell;
    stp_palette_method m;
    uint8_t grey[4] = {128, 128, 128, 128}, index[4];
    static const uint8_t want[4] = {2, 2, 2, 1};
    (void)state;
    assert_int_equal(stp_cell_user(&cell, 2, 2, thresholds), 0);
    memset(&m, 0, sizeof m);
    m.cell = &cell;
    assert_int_equal(stp_palette_dither(&p, &m, grey, 1, 2, 2, index), 0);
    assert_memory_equal(index, want, 4);
    /* on a level exactly (170): no dither at all */
    memset(grey, 170, sizeof grey);
    assert_int_equal(stp_palette_dither(&p, &m, grey, 1, 2, 2, index), 0);
    assert_memory_equal(index, ((const uint8_t[]){2, 2, 2, 2}), 4);
}

/* Ordered with the black/white palette is the core's 1-bit halftone:
 * every pixel of a ramp equals stp_halftone_row's bit, Bayer 4x4. */
static void test_ordered_bw_is_halftone(void **state)
{
    enum { W = 64, H = 8 };
    stp_palette p = load("bw");
    stp_cell cell;
    stp_palette_method m;
    uint8_t grey[W * H], index[W * H], bits[W / 8];
    uint32_t x, y;
    (void)state;
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++)
            grey[y * W + x] = (uint8_t)((x * 4 + y * 3) & 255);
    assert_int_equal(stp_cell_bayer(&cell, 4), 0);
    memset(&m, 0, sizeof m);
    m.cell = &cell;
    assert_int_equal(stp_palette_dither(&p, &m, grey, 1, W, H, index), 0);
    for (y = 0; y < H; y++) {
        stp_halftone_row(bits, grey + y * W, W, y, &cell);
        for (x = 0; x < W; x++)
            assert_int_equal(index[y * W + x], (bits[x / 8] >> (7 - x % 8)) & 1);
    }
}

/* Ordered, rgb8: each channel thresholded alone.  A 1x1 cell of
 * threshold 100: channels 0.5 (intensity 128 > 100: up), 0.3 (77: down)
 * and 1 give (1, 0, 1), magenta, index 5. */
static void test_ordered_rgb8(void **state)
{
    static const uint8_t threshold[1] = {100};
    stp_palette p = load("rgb8");
    stp_cell cell;
    stp_palette_method m;
    uint8_t rgb[3] = {128, 77, 255}, index[1];
    (void)state;
    assert_int_equal(stp_cell_user(&cell, 1, 1, threshold), 0);
    memset(&m, 0, sizeof m);
    m.cell = &cell;
    assert_int_equal(stp_palette_dither(&p, &m, rgb, 3, 1, 1, index), 0);
    assert_int_equal(index[0], 5);
}

/* Floyd-Steinberg, rgb8, one row of two pixels (0.4, 0.6, 0): the first
 * is nearest green (index 2), error (0.4, -0.4, 0); 7/16 of it reaches
 * the second: (0.575, 0.425, 0), nearest red (index 4).  A mapping that
 * swapped channels or mixed up indices gives something else. */
static void test_diffuse_rgb8(void **state)
{
    stp_palette p = load("rgb8");
    stp_palette_method m;
    uint8_t rgb[6] = {102, 153, 0, 102, 153, 0}, index[2];
    (void)state;
    memset(&m, 0, sizeof m);
    m.diffuse = 1;
    m.kernel = STP_DIFFUSE_FLOYD_STEINBERG;
    assert_int_equal(stp_palette_dither(&p, &m, rgb, 3, 2, 1, index), 0);
    assert_int_equal(index[0], 2);
    assert_int_equal(index[1], 4);
}

/* Floyd-Steinberg, black and white, 3x2 pixels of 0.4 (code 102):
 * row 0: 0.4 -> 0 (err 0.4); 0.4 + 0.175 = 0.575 -> 1 (err -0.425);
 *        0.4 - 0.1859 = 0.2141 -> 0.
 * row 1: 0.4 + 5/16 0.4 + 3/16 (-0.425) = 0.4453 -> 0;
 *        0.4 + 1/16 0.4 + 5/16 (-0.425) + 3/16 0.2141 + 7/16 0.4453
 *        = 0.5271 -> 1;
 *        0.4 + 1/16 (-0.425) + 5/16 0.2141 + 7/16 (-0.4729) = 0.2334 -> 0.
 * Serpentine runs row 1 right to left, its last pixel first:
 *        0.4 + 1/16 (-0.425) + 5/16 0.2141 = 0.4403 -> 0 (err 0.4403);
 *        then the middle 0.4 + 0.025 - 0.1328 + 0.0401 + 7/16 0.4403
 *        = 0.5249 -> 1; the first 0.4 + 0.125 - 0.0797 + 7/16 (-0.4751)
 *        = 0.2375 -> 0. */
static void test_diffuse_bw(void **state)
{
    stp_palette p = load("bw");
    stp_palette_method m;
    uint8_t grey[6], index[6];
    static const uint8_t want[6] = {0, 1, 0, 0, 1, 0};
    (void)state;
    memset(grey, 102, sizeof grey);
    memset(&m, 0, sizeof m);
    m.diffuse = 1;
    m.kernel = STP_DIFFUSE_FLOYD_STEINBERG;
    assert_int_equal(stp_palette_dither(&p, &m, grey, 1, 3, 2, index), 0);
    assert_memory_equal(index, want, 6);
    m.serpentine = 1;
    assert_int_equal(stp_palette_dither(&p, &m, grey, 1, 3, 2, index), 0);
    assert_memory_equal(index, want, 6);
}

/* Sierra-Lite on bwr, one row: (1, 0.3, 0.3) is nearest red (distance
 * 0.18 against 0.98 for white), error (0, 0.3, 0.3); half of it reaches
 * the next pixel (0.6, 0.45, 0.45): white 0.16 + 0.3025 + 0.3025 = 0.765,
 * red 0.16 + 0.2025 + 0.2025 = 0.565, black 0.36 + 0.405 = 0.765: red. A
 * pure blue pixel (0, 0, 1) is nearest black; clamping keeps 1 + error
 * inside 0..1. */
static void test_diffuse_bwr(void **state)
{
    stp_palette p = load("bwr");
    stp_palette_method m;
    uint8_t rgb[9] = {255, 77, 77, 153, 77, 77, 0, 0, 255}, index[3];
    (void)state;
    memset(&m, 0, sizeof m);
    m.diffuse = 1;
    m.kernel = STP_DIFFUSE_SIERRA_LITE;
    assert_int_equal(stp_palette_dither(&p, &m, rgb, 3, 3, 1, index), 0);
    assert_int_equal(index[0], 2);
    assert_int_equal(index[1], 2);
    assert_int_equal(index[2], 0);
}

/* Linear light: code 188 decodes to 0.5029; dithered to black and white
 * with Floyd-Steinberg a 64x64 square has half its pixels white (2060 of
 * 4096); read as codes (0.737) three quarters (3019).  Shares that fall
 * off the edges are lost: within 2 %. */
static void test_linear(void **state)
{
    enum { W = 64, N = 64 * 64 };
    stp_palette p = load("bw");
    stp_palette_method m;
    uint8_t grey[N], index[N];
    int i, on_linear = 0, on_codes = 0;
    (void)state;
    memset(grey, 188, sizeof grey);
    memset(&m, 0, sizeof m);
    m.diffuse = 1;
    m.kernel = STP_DIFFUSE_FLOYD_STEINBERG;
    m.linear = 1;
    assert_int_equal(stp_palette_dither(&p, &m, grey, 1, W, W, index), 0);
    for (i = 0; i < N; i++)
        on_linear += index[i];
    m.linear = 0;
    assert_int_equal(stp_palette_dither(&p, &m, grey, 1, W, W, index), 0);
    for (i = 0; i < N; i++)
        on_codes += index[i];
    assert_in_range(on_linear, 2060 - 82, 2060 + 82);
    assert_in_range(on_codes, 3019 - 82, 3019 + 82);
}

/* The SSD1680 planes of a 10x1 picture black, white, red, five black,
 * white, red: bw 0110 0000 | 11 and pad 111111; red 0010 0000 |
 * 01 and pad 000000. */
static void test_planes(void **state)
{
    static const uint8_t index[10] = {0, 1, 2, 0, 0, 0, 0, 0, 1, 2};
    uint8_t bw[2], red[2];
    (void)state;
    stp_palette_bwr_planes(index, 10, 1, bw, red);
    assert_int_equal(bw[0], 0x60);
    assert_int_equal(bw[1], 0xFF);
    assert_int_equal(red[0], 0x20);
    assert_int_equal(red[1], 0x40);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_builtin),
        cmocka_unit_test(test_file),
        cmocka_unit_test(test_nearest),
        cmocka_unit_test(test_ordered_grey4),
        cmocka_unit_test(test_ordered_bw_is_halftone),
        cmocka_unit_test(test_ordered_rgb8),
        cmocka_unit_test(test_diffuse_rgb8),
        cmocka_unit_test(test_diffuse_bw),
        cmocka_unit_test(test_diffuse_bwr),
        cmocka_unit_test(test_linear),
        cmocka_unit_test(test_planes),
    };
    return cmocka_run_group_tests(tests, 0, 0);
}
