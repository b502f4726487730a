/* SPDX-License-Identifier: MIT */
/*
 * ImageMagick check: stp_halftone_row with stp_cell_bayer(n) on the 8-bit
 * "camera" picture gives exactly the pixels of
 * `convert camera.pgm -ordered-dither oNxN` for N = 2, 4, 8.
 *
 * The files are made by tests/fetch_camera.sh (the CTest fixture "camera")
 * in $STP_BINARY_DIR/data.  A missing or malformed file is a failure, never a
 * skip.  The PNM reader is here so the test depends on the core only.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "stipple/dither.h"

/* ---- a tiny reader of raw PBM (P4) and PGM (P5, maxval 255) ---- */

typedef struct pnm {
    int kind; /* 4 or 5 */
    uint32_t width, height;
    size_t stride; /* bytes per row */
    uint8_t *pixels;
} pnm;

/* Next header number, skipping white space and # comments. */
static int read_number(FILE *f, uint32_t *out)
{
    int c = fgetc(f);
    uint64_t v = 0;
    int digits = 0;
    for (;;) {
        while (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f')
            c = fgetc(f);
        if (c != '#')
            break;
        while (c != '\n' && c != EOF)
            c = fgetc(f);
    }
    while (c >= '0' && c <= '9') {
        v = v * 10 + (uint64_t)(c - '0');
        if (v > 1000000)
            return -1;
        digits++;
        c = fgetc(f);
    }
    /* exactly one white-space character ends the number */
    if (digits == 0 || !(c == ' ' || c == '\t' || c == '\n' || c == '\r'))
        return -1;
    *out = (uint32_t)v;
    return 0;
}

/* Reads path into *img; returns 0, or fails the test with a message. */
static void read_pnm(const char *path, pnm *img)
{
    FILE *f = fopen(path, "rb");
    char magic[2];
    uint32_t maxval = 1;
    size_t size;
    if (f == NULL)
        fail_msg("cannot open %s (run tests/fetch_camera.sh: the fixture \"camera\")", path);
    if (fread(magic, 1, 2, f) != 2 || magic[0] != 'P' || (magic[1] != '4' && magic[1] != '5'))
        fail_msg("%s: not a raw PBM or PGM", path);
    img->kind = magic[1] - '0';
    if (read_number(f, &img->width) != 0 || read_number(f, &img->height) != 0 ||
        (img->kind == 5 && read_number(f, &maxval) != 0))
        fail_msg("%s: bad header", path);
    if (img->width == 0 || img->height == 0 || (img->kind == 5 && maxval != 255))
        fail_msg("%s: %ux%u maxval %u, want 8-bit", path, img->width, img->height, maxval);
    img->stride = img->kind == 4 ? (img->width + 7) / 8 : img->width;
    size = img->stride * img->height;
    img->pixels = malloc(size);
    assert_non_null(img->pixels);
    if (fread(img->pixels, 1, size, f) != size)
        fail_msg("%s: short raster", path);
    fclose(f);
}

static const char *data_dir(void)
{
    const char *bin = getenv("STP_BINARY_DIR");
    static char dir[4096];
    if (bin == NULL || *bin == '\0')
        fail_msg("STP_BINARY_DIR is not set (run through CTest)");
    snprintf(dir, sizeof dir, "%s/data", bin);
    return dir;
}

static void check_map(int n)
{
    char path[4200];
    pnm grey, pbm, pgm;
    stp_cell cell;
    uint8_t *row;
    uint32_t x, y;
    long diff_pbm = 0, diff_pgm = 0, on = 0, ties = 0;
    int seen[256] = {0}, levels = 0, i;
    const char *dir = data_dir();

    snprintf(path, sizeof path, "%s/camera.pgm", dir);
    read_pnm(path, &grey);
    assert_int_equal(grey.kind, 5);
    snprintf(path, sizeof path, "%s/o%dx%d.pbm", dir, n, n);
    read_pnm(path, &pbm);
    assert_int_equal(pbm.kind, 4);
    snprintf(path, sizeof path, "%s/o%dx%d.pgm", dir, n, n);
    read_pnm(path, &pgm);
    assert_int_equal(pgm.kind, 5);
    assert_int_equal(pbm.width, grey.width);
    assert_int_equal(pbm.height, grey.height);
    assert_int_equal(pgm.width, grey.width);
    assert_int_equal(pgm.height, grey.height);

    /* the picture must exercise the comparison: most grey levels present */
    for (i = 0; i < (int)(grey.width * grey.height); i++)
        seen[grey.pixels[i]] = 1;
    for (i = 0; i < 256; i++)
        levels += seen[i];
    assert_true(levels >= 200);

    assert_int_equal(stp_cell_bayer(&cell, n), 0);
    row = calloc(grey.stride, 1); /* >= (width + 7) / 8 */
    assert_non_null(row);
    for (y = 0; y < grey.height; y++) {
        const uint8_t *g = grey.pixels + (size_t)y * grey.stride;
        stp_halftone_row(row, g, grey.width, y, &cell);
        for (x = 0; x < grey.width; x++) {
            int ours = (row[x >> 3] >> (7 - (x & 7))) & 1;
            /* PBM: 1 = black = OFF, so ImageMagick's ON pixels are 0 bits */
            int im_pbm = !((pbm.pixels[(size_t)y * pbm.stride + (x >> 3)] >> (7 - (x & 7))) & 1);
            uint8_t v = pgm.pixels[(size_t)y * pgm.stride + x];
            int m = n * n, k;
            if (v != 0 && v != 255)
                fail_msg("o%dx%d.pgm (%u,%u) = %u: not bilevel", n, n, x, y, v);
            /* exact ties v (m+1) = 255 (r+1), where float rounding could
             * decide: counted, for the report */
            for (k = 1; k <= m; k++)
                if ((int)g[x] * (m + 1) == 255 * k)
                    ties++;
            on += ours;
            if (ours != im_pbm) {
                if (diff_pbm == 0)
                    print_error("o%dx%d: first PBM difference at (%u,%u), grey %u: ours %d, ImageMagick %d\n",
                                n, n, x, y, g[x], ours, im_pbm);
                diff_pbm++;
            }
            if (ours != (v == 255)) {
                if (diff_pgm == 0)
                    print_error("o%dx%d: first PGM difference at (%u,%u), grey %u: ours %d, ImageMagick %d\n",
                                n, n, x, y, g[x], ours, v == 255);
                diff_pgm++;
            }
        }
    }
    print_message("o%dx%d: %ux%u pixels, %ld on, %ld at exact ties; %ld PBM and %ld PGM differences\n", n, n,
                  grey.width, grey.height, on, ties, diff_pbm, diff_pgm);
    free(row);
    free(grey.pixels);
    free(pbm.pixels);
    free(pgm.pixels);
    assert_int_equal(diff_pbm, 0);
    assert_int_equal(diff_pgm, 0);
}

static void test_bayer2_equals_imagemagick_o2x2(void **state)
{
    (void)state;
    check_map(2);
}

static void test_bayer4_equals_imagemagick_o4x4(void **state)
{
    (void)state;
    check_map(4);
}

static void test_bayer8_equals_imagemagick_o8x8(void **state)
{
    (void)state;
    check_map(8);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_bayer2_equals_imagemagick_o2x2),
        cmocka_unit_test(test_bayer4_equals_imagemagick_o4x4),
        cmocka_unit_test(test_bayer8_equals_imagemagick_o8x8),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
