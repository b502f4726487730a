/* SPDX-License-Identifier: MIT */
/*
 * The POSIX port's PNG files (ports/posix/png.c): frames of every writable
 * format go out and come back with exactly their pixels and the PNG header
 * fields expected (bit depth, colour type, read from the file's bytes, not
 * through libpng); colour reads as grey with the BT.601 weights; STYLE8 is
 * refused and a failed write leaves an existing file as it was; damaged
 * files give a message naming the path; PNG and PNM are told apart.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cmocka.h>

#include "stp_posix.h"
#include "stp_posix_png.h"

static char dir[] = "/tmp/stp_test_pngXXXXXX";

static const char *path_of(const char *name)
{
    static char buf[128];
    snprintf(buf, sizeof buf, "%s/%s", dir, name);
    return buf;
}

/* The CRC of a PNG chunk (type and data): reflected CRC-32, polynomial
 * 0xedb88320, as the PNG specification gives it; written here so the test
 * does not take libpng's (or zlib's) word for the file it feeds libpng. */
static unsigned long crc32_of(const unsigned char *p, size_t n)
{
    unsigned long c = 0xffffffffUL;
    size_t i;
    int k;
    for (i = 0; i < n; i++) {
        c ^= p[i];
        for (k = 0; k < 8; k++)
            c = (c >> 1) ^ (0xedb88320UL & (0UL - (c & 1UL)));
    }
    return c ^ 0xffffffffUL;
}

static size_t read_file(const char *path, unsigned char *buf, size_t cap)
{
    FILE *f = fopen(path, "rb");
    size_t n;
    assert_non_null(f);
    n = fread(buf, 1, cap, f);
    fclose(f);
    return n;
}

/* A frame with a pattern that differs in every pixel and channel. */
static void fill(stp_posix_frame *f)
{
    uint32_t y;
    size_t i;
    for (y = 0; y < f->height; y++)
        for (i = 0; i < f->stride; i++)
            f->pixels[y * f->stride + i] = (uint8_t)(i * 37 + y * 101 + 13);
    if (f->format == STP_PIXEL_MONO1 && f->width % 8) /* padding bits stay 0 */
        for (y = 0; y < f->height; y++)
            f->pixels[y * f->stride + f->stride - 1] &= (uint8_t)(0xFF << (8 - f->width % 8));
}

/* IHDR: bit depth at byte 24, colour type at byte 25 (PNG spec, 11.2.2). */
static void check_header(const char *path, uint32_t w, uint32_t h, int depth, int type)
{
    unsigned char b[64];
    assert_true(read_file(path, b, sizeof b) >= 33);
    assert_memory_equal(b, "\x89PNG\r\n\x1a\n", 8);
    assert_memory_equal(b + 12, "IHDR", 4);
    assert_int_equal(((uint32_t)b[16] << 24) | ((uint32_t)b[17] << 16) | ((uint32_t)b[18] << 8) | b[19], w);
    assert_int_equal(((uint32_t)b[20] << 24) | ((uint32_t)b[21] << 16) | ((uint32_t)b[22] << 8) | b[23], h);
    assert_int_equal(b[24], depth);
    assert_int_equal(b[25], type);
}

static void roundtrip(stp_pixel_format fmt, uint32_t w, uint32_t h, int depth, int type)
{
    stp_posix_frame f;
    stp_posix_image img;
    char err[256];
    uint32_t x, y;
    const char *path = path_of("round.png");
    assert_int_equal(stp_posix_frame_init(&f, w, h, fmt), 0);
    fill(&f);
    assert_int_equal(stp_posix_write_png(&f, path, err, sizeof err), 0);
    check_header(path, w, h, depth, type);
    assert_int_equal(stp_posix_read_png(path, &img, 0, err, sizeof err), 0);
    assert_int_equal(img.width, w);
    assert_int_equal(img.height, h);
    assert_int_equal(img.channels, fmt == STP_PIXEL_RGB888 ? 3 : 1);
    for (y = 0; y < h; y++)
        for (x = 0; x < w * (uint32_t)img.channels; x++) {
            const uint8_t *row = f.pixels + y * f.stride;
            uint8_t want = fmt == STP_PIXEL_MONO1 ? ((row[x / 8] >> (7 - x % 8)) & 1 ? 255 : 0)
                                                  : row[x];
            assert_int_equal(img.samples[y * w * (uint32_t)img.channels + x], want);
        }
    stp_posix_image_free(&img);
    stp_posix_frame_free(&f);
}

static void test_roundtrip(void **state)
{
    (void)state;
    roundtrip(STP_PIXEL_MONO1, 13, 5, 1, 0);
    roundtrip(STP_PIXEL_MONO1, 16, 2, 1, 0);
    roundtrip(STP_PIXEL_GREY8, 7, 9, 8, 0);
    roundtrip(STP_PIXEL_RGB888, 5, 4, 8, 2);
}

static void test_grey_of_colour(void **state)
{
    stp_posix_frame f;
    stp_posix_image img;
    char err[256];
    uint32_t i;
    (void)state;
    assert_int_equal(stp_posix_frame_init(&f, 6, 3, STP_PIXEL_RGB888), 0);
    fill(&f);
    assert_int_equal(stp_posix_write_png(&f, path_of("c.png"), err, sizeof err), 0);
    assert_int_equal(stp_posix_read_png(path_of("c.png"), &img, 1, err, sizeof err), 0);
    assert_int_equal(img.channels, 1);
    for (i = 0; i < 18; i++) {
        const uint8_t *p = f.pixels + 3 * i;
        /* 0.299 R + 0.587 G + 0.114 B, rounded half up, in whole thousandths */
        unsigned want = (299u * p[0] + 587u * p[1] + 114u * p[2] + 500u) / 1000u;
        assert_int_equal(img.samples[i], want);
    }
    stp_posix_image_free(&img);
    /* the dispatcher gives the same for the PNG, and reads PNM too */
    assert_int_equal(stp_posix_read_image_grey(path_of("c.png"), &img, err, sizeof err), 0);
    assert_int_equal(img.channels, 1);
    stp_posix_image_free(&img);
    assert_int_equal(stp_posix_write(&f, path_of("c.ppm"), STP_POSIX_FILE_P6, err, sizeof err), 0);
    assert_int_equal(stp_posix_read_image_grey(path_of("c.ppm"), &img, err, sizeof err), 0);
    assert_int_equal(img.pnm_type, 6);
    stp_posix_image_free(&img);
    stp_posix_frame_free(&f);
}

static void test_refusals(void **state)
{
    stp_posix_frame f;
    stp_posix_image img;
    unsigned char b[600], keep[] = "keep me";
    char err[256];
    size_t n;
    FILE *out;
    (void)state;
    /* STYLE8 is not light: refused, the existing file untouched */
    out = fopen(path_of("k.png"), "wb");
    assert_non_null(out);
    fwrite(keep, 1, sizeof keep, out);
    fclose(out);
    assert_int_equal(stp_posix_frame_init(&f, 4, 4, STP_PIXEL_STYLE8), 0);
    assert_int_equal(stp_posix_write_png(&f, path_of("k.png"), err, sizeof err), -1);
    assert_non_null(strstr(err, "cannot be written as PNG"));
    assert_int_equal(read_file(path_of("k.png"), b, sizeof b), sizeof keep);
    assert_memory_equal(b, keep, sizeof keep);
    stp_posix_frame_free(&f);

    /* not a PNG */
    assert_int_equal(stp_posix_read_png(path_of("k.png"), &img, 0, err, sizeof err), -1);
    assert_string_equal(err + strlen(dir) + 1, "k.png: not a PNG file (no PNG signature)");
    assert_null(img.samples);

    /* truncated: every cut of a valid file fails with libpng's message */
    assert_int_equal(stp_posix_frame_init(&f, 20, 20, STP_PIXEL_GREY8), 0);
    fill(&f);
    assert_int_equal(stp_posix_write_png(&f, path_of("t.png"), err, sizeof err), 0);
    n = read_file(path_of("t.png"), b, sizeof b);
    assert_true(n > 60 && n < sizeof b);
    {
        size_t cut;
        for (cut = 9; cut < n - 12; cut += 7) { /* IEND is the last 12 bytes */
            out = fopen(path_of("cut.png"), "wb");
            fwrite(b, 1, cut, out);
            fclose(out);
            assert_int_equal(stp_posix_read_png(path_of("cut.png"), &img, 0, err, sizeof err), -1);
            assert_non_null(strstr(err, "cut.png: bad PNG: "));
            assert_null(img.samples);
        }
    }
    /* a flipped bit in the image data: the CRC catches it */
    b[n - 20] ^= 0x10;
    out = fopen(path_of("crc.png"), "wb");
    fwrite(b, 1, n, out);
    fclose(out);
    assert_int_equal(stp_posix_read_png(path_of("crc.png"), &img, 0, err, sizeof err), -1);
    assert_non_null(strstr(err, "crc.png: bad PNG: "));
    stp_posix_frame_free(&f);
    /* a header 40 000 pixels wide: the limit named, not libpng's bare
     * "Invalid IHDR data" (the header's CRC is right, so only the width is
     * refused) */
    {
        static const unsigned char wide[] = {
            0x89, 'P', 'N', 'G', 0x0d, 0x0a, 0x1a, 0x0a, 0, 0, 0, 13, 'I', 'H', 'D', 'R',
            0, 0, 0x9c, 0x40, 0, 0, 0, 1, 8, 0, 0, 0, 0};
        unsigned char file[sizeof wide + 4];
        unsigned long crc = crc32_of(wide + 12, sizeof wide - 12);
        memcpy(file, wide, sizeof wide);
        file[sizeof wide] = (unsigned char)(crc >> 24);
        file[sizeof wide + 1] = (unsigned char)(crc >> 16);
        file[sizeof wide + 2] = (unsigned char)(crc >> 8);
        file[sizeof wide + 3] = (unsigned char)crc;
        out = fopen(path_of("wide.png"), "wb");
        assert_non_null(out);
        fwrite(file, 1, sizeof file, out);
        fclose(out);
        assert_int_equal(stp_posix_read_png(path_of("wide.png"), &img, 0, err, sizeof err), -1);
        assert_non_null(strstr(err, "wide.png: bad PNG: wider or taller than 32767 pixels"));
        assert_null(img.samples);
    }
    assert_int_equal(stp_posix_read_png(path_of("missing.png"), &img, 0, err, sizeof err), -1);
    assert_non_null(strstr(err, "missing.png: cannot open"));
}

static int setup(void **state)
{
    (void)state;
    return mkdtemp(dir) ? 0 : -1;
}

static int teardown(void **state)
{
    static const char *const names[] = {"round.png", "c.png", "c.ppm", "k.png", "t.png",
                                        "cut.png", "crc.png", "wide.png"};
    size_t i;
    (void)state;
    for (i = 0; i < sizeof names / sizeof names[0]; i++)
        unlink(path_of(names[i]));
    return rmdir(dir);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_roundtrip),
        cmocka_unit_test(test_grey_of_colour),
        cmocka_unit_test(test_refusals),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
