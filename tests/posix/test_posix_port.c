/* SPDX-License-Identifier: MIT */
/*
 * Tests of the POSIX port: the frame port's band handling, the PBM/PGM/PPM
 * and ASCII writers (exact bytes, and netpbm's pamvalidate accepting them),
 * atomic replacement under failures, and the PNM reader on good and
 * malformed files.  Files live in a fresh directory under $TMPDIR (or /tmp),
 * removed at the end.
 */
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include "stp_posix.h"

#ifndef STP_PAMVALIDATE_PATH
#define STP_PAMVALIDATE_PATH "/usr/bin/pamvalidate"
#endif

/* ------------------------------------------------------------ helpers */

static char g_dir[512];

/* dir/name in one of a few rotating buffers, so two can be live at once. */
static const char *tpath(const char *name)
{
    static char bufs[4][1024];
    static int next;
    char *b = bufs[next];

    next = (next + 1) % 4;
    snprintf(b, sizeof bufs[0], "%s/%s", g_dir, name);
    return b;
}

static void remove_tree(const char *path)
{
    struct stat st;
    DIR *d;
    struct dirent *e;

    if (lstat(path, &st) != 0)
        return;
    if (!S_ISDIR(st.st_mode)) {
        (void)unlink(path);
        return;
    }
    d = opendir(path);
    if (d != NULL) {
        while ((e = readdir(d)) != NULL) {
            char sub[1024];

            if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0)
                continue;
            snprintf(sub, sizeof sub, "%s/%s", path, e->d_name);
            remove_tree(sub);
        }
        closedir(d);
    }
    (void)rmdir(path);
}

static int group_setup(void **state)
{
    const char *base = getenv("TMPDIR");

    (void)state;
    if (base == NULL || *base == '\0')
        base = "/tmp";
    snprintf(g_dir, sizeof g_dir, "%s/stp_posix_test.XXXXXX", base);
    return mkdtemp(g_dir) != NULL ? 0 : -1;
}

static int group_teardown(void **state)
{
    (void)state;
    remove_tree(g_dir);
    return 0;
}

/* The whole file; *len gets its size.  Fails the test if it cannot. */
static uint8_t *slurp(const char *path, size_t *len)
{
    FILE *fp = fopen(path, "rb");
    uint8_t *buf;
    long n;

    if (fp == NULL)
        fail_msg("cannot open %s: %s", path, strerror(errno));
    assert_int_equal(fseek(fp, 0, SEEK_END), 0);
    n = ftell(fp);
    assert_true(n >= 0);
    rewind(fp);
    buf = (uint8_t *)malloc((size_t)n + 1u);
    assert_non_null(buf);
    assert_int_equal(fread(buf, 1, (size_t)n, fp), (size_t)n);
    fclose(fp);
    buf[n] = 0;
    *len = (size_t)n;
    return buf;
}

static void spit(const char *path, const void *data, size_t len)
{
    FILE *fp = fopen(path, "wb");

    if (fp == NULL)
        fail_msg("cannot create %s: %s", path, strerror(errno));
    assert_int_equal(fwrite(data, 1, len, fp), len);
    assert_int_equal(fclose(fp), 0);
}

static void assert_file_bytes(const char *path, const void *want, size_t want_len)
{
    size_t len;
    uint8_t *got = slurp(path, &len);

    assert_int_equal(len, want_len);
    assert_memory_equal(got, want, want_len);
    free(got);
}

#define assert_contains(hay, needle)                                                 \
    do {                                                                             \
        if (strstr((hay), (needle)) == NULL)                                         \
            fail_msg("message \"%s\" lacks \"%s\"", (hay), (needle));               \
    } while (0)

/* Entries of dir whose names start with '.', other than . and ..: the
 * writer's temporary files. */
static int count_hidden(const char *dir)
{
    DIR *d = opendir(dir);
    struct dirent *e;
    int n = 0;

    assert_non_null(d);
    while ((e = readdir(d)) != NULL) {
        if (e->d_name[0] == '.' && strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0)
            n++;
    }
    closedir(d);
    return n;
}

/* Feeds src (rows of row_bytes, packed) to the port as the bands
 * [0, split) and [split, height), from a buffer whose rows are 3 bytes
 * longer than needed and filled with junk there, as a renderer with a
 * wider band buffer would send them. */
static void feed_bands(stp_port *port, const uint8_t *src, size_t row_bytes, uint32_t split)
{
    size_t stride = row_bytes + 3u;
    uint8_t *band = (uint8_t *)malloc(stride * port->height);
    uint32_t y;

    assert_non_null(band);
    memset(band, 0xA5, stride * port->height);
    for (y = 0; y < port->height; y++)
        memcpy(band + (size_t)y * stride, src + (size_t)y * row_bytes, row_bytes);
    assert_int_equal(port->flush(port, 0, split, band, stride), 0);
    assert_int_equal(port->flush(port, split, port->height - split,
                                 band + (size_t)split * stride, stride), 0);
    free(band);
}

/* Runs pamvalidate on path; its exit status.  A missing tool fails the test:
 * the check must not pass by being skipped.  quiet hides its complaints
 * where a failure is expected. */
static int pamvalidate(const char *path, int quiet)
{
    const char *tool = STP_PAMVALIDATE_PATH;
    pid_t pid;
    int status;

    if (access(tool, X_OK) != 0)
        fail_msg("pamvalidate not found at %s (install netpbm): %s", tool, strerror(errno));
    fflush(NULL);
    pid = fork();
    assert_true(pid >= 0);
    if (pid == 0) {
        int in = open(path, O_RDONLY);
        int out = open("/dev/null", O_WRONLY);

        if (in < 0 || out < 0 || dup2(in, 0) < 0 || dup2(out, 1) < 0 ||
            (quiet && dup2(out, 2) < 0))
            _exit(126);
        execl(tool, "pamvalidate", (char *)NULL);
        _exit(127);
    }
    assert_int_equal(waitpid(pid, &status, 0), pid);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

/* ------------------------------------------------------- known pictures */

/* 10 x 5 MONO1 (2 bytes a row, 6 padding bits): row 0 alternate pixels ON,
 * row 1 all ON, row 2 all OFF, row 3 only x = 9, row 4 only x = 0.  The
 * padding bits are set here on purpose: they must not reach the files. */
static const uint8_t k_mono[5 * 2] = {
    0xAA, 0xBF,
    0xFF, 0xFF,
    0x00, 0x3F,
    0x00, 0x40,
    0x80, 0x01,
};

/* PBM: ON (light) is 0, padding 0. */
static const uint8_t k_mono_p4[] = {
    'P', '4', '\n', '1', '0', ' ', '5', '\n',
    0x55, 0x40,
    0x00, 0x00,
    0xFF, 0xC0,
    0xFF, 0x80,
    0x7F, 0xC0,
};

static const char k_mono_p1[] =
    "P1\n10 5\n"
    "0101010101\n"
    "0000000000\n"
    "1111111111\n"
    "1111111110\n"
    "0111111111\n";

/* The same picture as 8-bit grey, as the reader gives it. */
static const uint8_t k_mono_grey[5 * 10] = {
    255, 0, 255, 0, 255, 0, 255, 0, 255, 0,
    255, 255, 255, 255, 255, 255, 255, 255, 255, 255,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 255,
    255, 0, 0, 0, 0, 0, 0, 0, 0, 0,
};

static const uint8_t k_grey[4 * 3] = {
    0, 1, 127, 128,
    254, 255, 10, 200,
    '\n', 'P', '#', 32,
};

static const uint8_t k_rgb[3 * 2 * 3] = {
    255, 0, 0,    0, 255, 0,    0, 0, 255,
    255, 255, 255, 10, 20, 30,  0, 0, 0,
};

/* round(0.299 R + 0.587 G + 0.114 B) of k_rgb. */
static const uint8_t k_rgb_luma[3 * 2] = { 76, 150, 29, 255, 18, 0 };

static void make_mono(stp_posix_frame *f)
{
    assert_int_equal(stp_posix_frame_init(f, 10, 5, STP_PIXEL_MONO1), 0);
    feed_bands(stp_posix_frame_port(f), k_mono, 2, 3);
}

static void make_grey(stp_posix_frame *f)
{
    assert_int_equal(stp_posix_frame_init(f, 4, 3, STP_PIXEL_GREY8), 0);
    feed_bands(stp_posix_frame_port(f), k_grey, 4, 2);
}

static void make_rgb(stp_posix_frame *f)
{
    assert_int_equal(stp_posix_frame_init(f, 3, 2, STP_PIXEL_RGB888), 0);
    feed_bands(stp_posix_frame_port(f), k_rgb, 9, 1);
}

static void write_ok(const stp_posix_frame *f, const char *path, stp_posix_file_kind kind)
{
    char err[512] = "";

    if (stp_posix_write(f, path, kind, err, sizeof err) != 0)
        fail_msg("writing %s failed: %s", path, err);
}

/* ------------------------------------------------------------ the port */

static void test_frame_init(void **state)
{
    stp_posix_frame f;

    (void)state;
    errno = 0;
    assert_int_equal(stp_posix_frame_init(&f, 0, 5, STP_PIXEL_GREY8), -1);
    assert_int_equal(errno, EINVAL);
    assert_int_equal(stp_posix_frame_init(&f, 5, 32768, STP_PIXEL_GREY8), -1);
    assert_int_equal(stp_posix_frame_init(&f, 5, 5, (stp_pixel_format)9), -1);
    assert_int_equal(stp_posix_frame_init(NULL, 5, 5, STP_PIXEL_GREY8), -1);

    assert_int_equal(stp_posix_frame_init(&f, 17, 2, STP_PIXEL_MONO1), 0);
    assert_int_equal(f.stride, 3);
    assert_ptr_equal(stp_posix_frame_port(&f), &f.port);
    assert_int_equal(f.port.width, 17);
    assert_int_equal(f.port.height, 2);
    assert_int_equal(f.port.format, STP_PIXEL_MONO1);
    assert_ptr_equal(f.port.user, &f);
    assert_non_null(f.port.flush);
    stp_posix_frame_free(&f);
    assert_null(f.pixels);
    stp_posix_frame_free(&f); /* twice is harmless */

    assert_int_equal(stp_posix_frame_init(&f, 32767, 1, STP_PIXEL_RGB888), 0);
    assert_int_equal(f.stride, 32767u * 3u);
    stp_posix_frame_free(&f);
}

static void test_frame_bands(void **state)
{
    stp_posix_frame f;
    stp_port *port;
    uint8_t row[8];

    (void)state;
    make_mono(&f);
    port = stp_posix_frame_port(&f);
    assert_int_equal(f.bands, 2);
    assert_int_equal(f.rows_filled, 5);
    /* Padding bits cleared, pixels kept. */
    assert_int_equal(f.pixels[0], 0xAA);
    assert_int_equal(f.pixels[1], 0x80);
    assert_int_equal(f.pixels[3], 0xC0);
    assert_int_equal(f.pixels[9], 0x00);

    memset(row, 0xFF, sizeof row);
    /* Bands outside the frame, without pixels or with a short stride. */
    assert_int_equal(port->flush(port, 5, 1, row, 2), -1);
    assert_int_equal(port->flush(port, 4, 2, row, 2), -1);
    assert_int_equal(port->flush(port, UINT32_MAX, 2, row, 2), -1);
    assert_int_equal(port->flush(port, 0, 1, NULL, 2), -1);
    assert_int_equal(port->flush(port, 0, 2, row, 1), -1);
    assert_int_equal(f.pixels[4], 0x00); /* row 2 untouched */
    assert_int_equal(f.bands, 2);
    /* Empty bands are fine; one row needs no stride. */
    assert_int_equal(port->flush(port, 0, 0, NULL, 0), 0);
    assert_int_equal(port->flush(port, 2, 1, row, 0), 0);
    assert_int_equal(f.pixels[4], 0xFF);
    assert_int_equal(f.pixels[5], 0xC0);

    stp_posix_frame_clear(&f);
    assert_int_equal(f.bands, 0);
    assert_int_equal(f.rows_filled, 0);
    assert_int_equal(f.pixels[4], 0x00);
    stp_posix_frame_free(&f);
}

static void test_kind_selection(void **state)
{
    (void)state;
    assert_int_equal(stp_posix_kind_from_path("out.pbm"), STP_POSIX_FILE_P4);
    assert_int_equal(stp_posix_kind_from_path("dir.x/OUT.PGM"), STP_POSIX_FILE_P5);
    assert_int_equal(stp_posix_kind_from_path("/a/b.ppm"), STP_POSIX_FILE_P6);
    assert_int_equal(stp_posix_kind_from_path("pic.Txt"), STP_POSIX_FILE_ASCII);
    assert_int_equal(stp_posix_kind_from_path("-"), STP_POSIX_FILE_UNKNOWN);
    assert_int_equal(stp_posix_kind_from_path(".pbm"), STP_POSIX_FILE_UNKNOWN);
    assert_int_equal(stp_posix_kind_from_path("d/.pbm"), STP_POSIX_FILE_UNKNOWN);
    assert_int_equal(stp_posix_kind_from_path("x.png"), STP_POSIX_FILE_UNKNOWN);
    assert_int_equal(stp_posix_kind_from_path("pbm"), STP_POSIX_FILE_UNKNOWN);
    assert_int_equal(stp_posix_kind_from_path(NULL), STP_POSIX_FILE_UNKNOWN);

    assert_int_equal(stp_posix_kind_for_format(STP_PIXEL_MONO1), STP_POSIX_FILE_P4);
    assert_int_equal(stp_posix_kind_for_format(STP_PIXEL_GREY8), STP_POSIX_FILE_P5);
    assert_int_equal(stp_posix_kind_for_format(STP_PIXEL_RGB888), STP_POSIX_FILE_P6);
    assert_int_equal(stp_posix_kind_for_format(STP_PIXEL_STYLE8), STP_POSIX_FILE_ASCII);

    assert_true(stp_posix_kind_accepts(STP_POSIX_FILE_P1, STP_PIXEL_MONO1));
    assert_false(stp_posix_kind_accepts(STP_POSIX_FILE_P4, STP_PIXEL_GREY8));
    assert_true(stp_posix_kind_accepts(STP_POSIX_FILE_P5, STP_PIXEL_MONO1));
    assert_false(stp_posix_kind_accepts(STP_POSIX_FILE_P5, STP_PIXEL_RGB888));
    assert_true(stp_posix_kind_accepts(STP_POSIX_FILE_P6, STP_PIXEL_GREY8));
    assert_false(stp_posix_kind_accepts(STP_POSIX_FILE_P6, STP_PIXEL_STYLE8));
    assert_true(stp_posix_kind_accepts(STP_POSIX_FILE_ASCII, STP_PIXEL_STYLE8));
    assert_false(stp_posix_kind_accepts(STP_POSIX_FILE_ASCII, STP_PIXEL_GREY8));
    assert_false(stp_posix_kind_accepts(STP_POSIX_FILE_UNKNOWN, STP_PIXEL_MONO1));
}

/* ------------------------------------------------------------ writers */

static void test_write_pbm(void **state)
{
    stp_posix_frame f;
    stp_posix_image img;
    char err[512] = "";

    (void)state;
    make_mono(&f);
    write_ok(&f, tpath("mono.pbm"), STP_POSIX_FILE_P4);
    assert_file_bytes(tpath("mono.pbm"), k_mono_p4, sizeof k_mono_p4);
    write_ok(&f, tpath("mono_plain.pbm"), STP_POSIX_FILE_P1);
    assert_file_bytes(tpath("mono_plain.pbm"), k_mono_p1, strlen(k_mono_p1));

    /* Both read back as the picture (ON = white = 255). */
    assert_int_equal(stp_posix_read_pnm(tpath("mono.pbm"), &img, err, sizeof err), 0);
    assert_int_equal(img.width, 10);
    assert_int_equal(img.height, 5);
    assert_int_equal(img.channels, 1);
    assert_int_equal(img.pnm_type, 4);
    assert_int_equal(img.maxval, 1);
    assert_memory_equal(img.samples, k_mono_grey, sizeof k_mono_grey);
    stp_posix_image_free(&img);
    assert_int_equal(stp_posix_read_pnm(tpath("mono_plain.pbm"), &img, err, sizeof err), 0);
    assert_int_equal(img.pnm_type, 1);
    assert_memory_equal(img.samples, k_mono_grey, sizeof k_mono_grey);
    stp_posix_image_free(&img);
    stp_posix_frame_free(&f);
}

static void test_write_plain_long_rows(void **state)
{
    stp_posix_frame f;
    stp_posix_image img;
    uint8_t src[2 * 10];
    char want[64 + 2 * 78];
    size_t len;
    uint8_t *got;
    char err[512] = "";
    uint32_t x;

    (void)state;
    /* 75 pixels, row 0 all OFF, row 1 all ON: lines of 70 + 5 digits. */
    memset(src, 0x00, 10);
    memset(src + 10, 0xFF, 10);
    assert_int_equal(stp_posix_frame_init(&f, 75, 2, STP_PIXEL_MONO1), 0);
    feed_bands(stp_posix_frame_port(&f), src, 10, 1);
    write_ok(&f, tpath("wide.pbm"), STP_POSIX_FILE_P1);

    strcpy(want, "P1\n75 2\n");
    len = strlen(want);
    for (x = 0; x < 150; x++) {
        want[len++] = x < 75 ? '1' : '0';
        if (x % 75 == 69 || x % 75 == 74)
            want[len++] = '\n';
    }
    got = slurp(tpath("wide.pbm"), &len);
    assert_int_equal(len, strlen("P1\n75 2\n") + 150 + 4);
    assert_memory_equal(got, want, len);
    free(got);

    assert_int_equal(stp_posix_read_pnm(tpath("wide.pbm"), &img, err, sizeof err), 0);
    for (x = 0; x < 150; x++)
        assert_int_equal(img.samples[x], x < 75 ? 0 : 255);
    stp_posix_image_free(&img);
    assert_int_equal(pamvalidate(tpath("wide.pbm"), 0), 0);
    stp_posix_frame_free(&f);
}

static void test_write_pgm(void **state)
{
    stp_posix_frame f;
    stp_posix_image img;
    uint8_t want[64];
    char err[512] = "";
    size_t h;

    (void)state;
    make_grey(&f);
    write_ok(&f, tpath("grey.pgm"), STP_POSIX_FILE_P5);
    h = (size_t)sprintf((char *)want, "P5\n4 3\n255\n");
    memcpy(want + h, k_grey, sizeof k_grey);
    assert_file_bytes(tpath("grey.pgm"), want, h + sizeof k_grey);
    assert_int_equal(stp_posix_read_pnm(tpath("grey.pgm"), &img, err, sizeof err), 0);
    assert_int_equal(img.channels, 1);
    assert_int_equal(img.maxval, 255);
    assert_memory_equal(img.samples, k_grey, sizeof k_grey);
    stp_posix_image_free(&img);
    stp_posix_frame_free(&f);

    /* MONO1 as 0/255 grey. */
    make_mono(&f);
    write_ok(&f, tpath("mono.pgm"), STP_POSIX_FILE_P5);
    h = (size_t)sprintf((char *)want, "P5\n10 5\n255\n");
    {
        uint8_t *buf = (uint8_t *)malloc(h + sizeof k_mono_grey);

        assert_non_null(buf);
        memcpy(buf, want, h);
        memcpy(buf + h, k_mono_grey, sizeof k_mono_grey);
        assert_file_bytes(tpath("mono.pgm"), buf, h + sizeof k_mono_grey);
        free(buf);
    }
    stp_posix_frame_free(&f);
}

static void test_write_ppm(void **state)
{
    stp_posix_frame f;
    stp_posix_image img;
    uint8_t want[128];
    char err[512] = "";
    size_t h, i;

    (void)state;
    make_rgb(&f);
    write_ok(&f, tpath("rgb.ppm"), STP_POSIX_FILE_P6);
    h = (size_t)sprintf((char *)want, "P6\n3 2\n255\n");
    memcpy(want + h, k_rgb, sizeof k_rgb);
    assert_file_bytes(tpath("rgb.ppm"), want, h + sizeof k_rgb);

    assert_int_equal(stp_posix_read_pnm(tpath("rgb.ppm"), &img, err, sizeof err), 0);
    assert_int_equal(img.channels, 3);
    assert_int_equal(img.pnm_type, 6);
    assert_memory_equal(img.samples, k_rgb, sizeof k_rgb);
    stp_posix_image_free(&img);
    assert_int_equal(stp_posix_read_grey(tpath("rgb.ppm"), &img, err, sizeof err), 0);
    assert_int_equal(img.channels, 1);
    assert_memory_equal(img.samples, k_rgb_luma, sizeof k_rgb_luma);
    stp_posix_image_free(&img);
    stp_posix_frame_free(&f);

    /* GREY8 replicated into R = G = B. */
    make_grey(&f);
    write_ok(&f, tpath("grey.ppm"), STP_POSIX_FILE_P6);
    h = (size_t)sprintf((char *)want, "P6\n4 3\n255\n");
    for (i = 0; i < sizeof k_grey; i++)
        want[h + 3 * i] = want[h + 3 * i + 1] = want[h + 3 * i + 2] = k_grey[i];
    assert_file_bytes(tpath("grey.ppm"), want, h + 3 * sizeof k_grey);
    /* Grey through luminance comes back unchanged. */
    assert_int_equal(stp_posix_read_grey(tpath("grey.ppm"), &img, err, sizeof err), 0);
    assert_memory_equal(img.samples, k_grey, sizeof k_grey);
    stp_posix_image_free(&img);
    stp_posix_frame_free(&f);
}

static void test_write_ascii(void **state)
{
    stp_posix_frame f;
    stp_style_table table;
    uint8_t src[5 * 3];
    static const char want[] = "@M&B%\n$#kao\n=+-:.\n";
    int i, j;

    (void)state;
    stp_posix_lineprinter_table(&table);
    assert_int_equal(table.levels, 16);
    assert_ptr_equal(table.codes, stp_posix_lineprinter_styles);
    for (i = 0; i < 15; i++)
        src[i] = table.codes[i];
    assert_int_equal(stp_posix_frame_init(&f, 5, 3, STP_PIXEL_STYLE8), 0);
    feed_bands(stp_posix_frame_port(&f), src, 5, 2);
    write_ok(&f, tpath("styles.txt"), STP_POSIX_FILE_ASCII);
    assert_file_bytes(tpath("styles.txt"), want, strlen(want));
    stp_posix_frame_free(&f);

    /* Darkest '@' first, blank last, all printable and distinct. */
    assert_int_equal(stp_posix_lineprinter_styles[0], '@');
    assert_int_equal(stp_posix_lineprinter_styles[15], ' ');
    for (i = 0; i < 16; i++) {
        assert_true(stp_posix_lineprinter_styles[i] >= 0x20 &&
                    stp_posix_lineprinter_styles[i] < 0x7F);
        for (j = 0; j < i; j++)
            assert_int_not_equal(stp_posix_lineprinter_styles[i], stp_posix_lineprinter_styles[j]);
    }
}

static void test_pamvalidate_accepts(void **state)
{
    stp_posix_frame f;
    static const char truncated[] = "P5\n4 3\n255\n\x01\x02";

    (void)state;
    make_mono(&f);
    write_ok(&f, tpath("v4.pbm"), STP_POSIX_FILE_P4);
    write_ok(&f, tpath("v1.pbm"), STP_POSIX_FILE_P1);
    write_ok(&f, tpath("vm.pgm"), STP_POSIX_FILE_P5);
    write_ok(&f, tpath("vm.ppm"), STP_POSIX_FILE_P6);
    stp_posix_frame_free(&f);
    make_grey(&f);
    write_ok(&f, tpath("v5.pgm"), STP_POSIX_FILE_P5);
    write_ok(&f, tpath("vg.ppm"), STP_POSIX_FILE_P6);
    stp_posix_frame_free(&f);
    make_rgb(&f);
    write_ok(&f, tpath("v6.ppm"), STP_POSIX_FILE_P6);
    stp_posix_frame_free(&f);

    assert_int_equal(pamvalidate(tpath("v4.pbm"), 0), 0);
    assert_int_equal(pamvalidate(tpath("v1.pbm"), 0), 0);
    assert_int_equal(pamvalidate(tpath("vm.pgm"), 0), 0);
    assert_int_equal(pamvalidate(tpath("vm.ppm"), 0), 0);
    assert_int_equal(pamvalidate(tpath("v5.pgm"), 0), 0);
    assert_int_equal(pamvalidate(tpath("vg.ppm"), 0), 0);
    assert_int_equal(pamvalidate(tpath("v6.ppm"), 0), 0);
    /* The validator does reject a bad file, so the checks above mean something. */
    spit(tpath("bad.pgm"), truncated, sizeof truncated - 1);
    assert_int_not_equal(pamvalidate(tpath("bad.pgm"), 1), 0);
}

static void test_write_stdout(void **state)
{
    stp_posix_frame f;
    char err[512] = "";
    int saved, fd, rc;

    (void)state;
    make_mono(&f);
    fflush(stdout);
    saved = dup(1);
    assert_true(saved >= 0);
    fd = open(tpath("stdout.pbm"), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    assert_true(fd >= 0);
    assert_true(dup2(fd, 1) >= 0);
    close(fd);
    rc = stp_posix_write(&f, "-", STP_POSIX_FILE_P1, err, sizeof err);
    fflush(stdout);
    assert_true(dup2(saved, 1) >= 0);
    close(saved);
    if (rc != 0)
        fail_msg("writing stdout failed: %s", err);
    assert_file_bytes(tpath("stdout.pbm"), k_mono_p1, strlen(k_mono_p1));
    stp_posix_frame_free(&f);
}

/* -------------------------------------------------------- atomic writes */

static void test_atomic_replace(void **state)
{
    stp_posix_frame f;
    struct stat st;
    mode_t old_mask;

    (void)state;
    make_mono(&f);
    spit(tpath("replace.pbm"), "OLD", 3);
    assert_int_equal(chmod(tpath("replace.pbm"), 0640), 0);
    write_ok(&f, tpath("replace.pbm"), STP_POSIX_FILE_P4);
    assert_file_bytes(tpath("replace.pbm"), k_mono_p4, sizeof k_mono_p4);
    assert_int_equal(stat(tpath("replace.pbm"), &st), 0);
    assert_int_equal(st.st_mode & 07777, 0640); /* the old file's mode kept */

    /* A new file gets 0666 less the umask, not mkstemp's 0600. */
    old_mask = umask(022);
    write_ok(&f, tpath("fresh.pbm"), STP_POSIX_FILE_P4);
    umask(old_mask);
    assert_int_equal(stat(tpath("fresh.pbm"), &st), 0);
    assert_int_equal(st.st_mode & 07777, 0644);
    assert_int_equal(count_hidden(g_dir), 0);
    stp_posix_frame_free(&f);
}

static void test_atomic_bad_directory(void **state)
{
    stp_posix_frame f;
    char err[512] = "";
    char want[256];

    (void)state;
    make_mono(&f);

    /* The directory does not exist. */
    assert_int_equal(stp_posix_write(&f, tpath("nosuch/x.pbm"), STP_POSIX_FILE_P4, err,
                                     sizeof err), -1);
    snprintf(want, sizeof want, "%s: ", tpath("nosuch/x.pbm"));
    assert_contains(err, want);
    assert_contains(err, strerror(ENOENT));

    /* The "directory" is a regular file, which must survive. */
    spit(tpath("plainfile"), "KEEP", 4);
    assert_int_equal(stp_posix_write(&f, tpath("plainfile/x.pbm"), STP_POSIX_FILE_P4, err,
                                     sizeof err), -1);
    assert_contains(err, tpath("plainfile/x.pbm"));
    assert_contains(err, strerror(ENOTDIR));
    assert_file_bytes(tpath("plainfile"), "KEEP", 4);

    /* A path naming a directory. */
    assert_int_equal(stp_posix_write(&f, tpath("sub/"), STP_POSIX_FILE_P4, err, sizeof err), -1);
    assert_contains(err, "directory");
    assert_int_equal(count_hidden(g_dir), 0);
    stp_posix_frame_free(&f);
}

static void test_atomic_rename_fails(void **state)
{
    stp_posix_frame f;
    char err[512] = "";
    struct stat st;

    (void)state;
    /* The target is a non-empty directory: everything succeeds up to the
     * rename, so the written temporary file must be cleaned up. */
    assert_int_equal(mkdir(tpath("isdir.pgm"), 0755), 0);
    spit(tpath("isdir.pgm/inside"), "IN", 2);
    make_grey(&f);
    assert_int_equal(stp_posix_write(&f, tpath("isdir.pgm"), STP_POSIX_FILE_P5, err,
                                     sizeof err), -1);
    assert_contains(err, tpath("isdir.pgm"));
    assert_contains(err, "directory");
    assert_int_equal(stat(tpath("isdir.pgm"), &st), 0);
    assert_true(S_ISDIR(st.st_mode));
    assert_file_bytes(tpath("isdir.pgm/inside"), "IN", 2);
    assert_int_equal(count_hidden(g_dir), 0);
    stp_posix_frame_free(&f);
}

static void test_atomic_write_fails(void **state)
{
    stp_posix_frame f;
    pid_t pid;
    int status;

    (void)state;
    spit(tpath("big.pgm"), "OLD", 3);
    assert_int_equal(stp_posix_frame_init(&f, 200, 200, STP_PIXEL_GREY8), 0);
    memset(f.pixels, 0x77, f.stride * f.height);
    fflush(NULL);
    /* A child with a 1000-byte file size limit: the write itself fails
     * (EFBIG) half-way through the data. */
    pid = fork();
    assert_true(pid >= 0);
    if (pid == 0) {
        struct rlimit rl;
        char err[512] = "";
        int rc;

        signal(SIGXFSZ, SIG_IGN);
        rl.rlim_cur = rl.rlim_max = 1000;
        if (setrlimit(RLIMIT_FSIZE, &rl) != 0)
            _exit(3);
        rc = stp_posix_write(&f, tpath("big.pgm"), STP_POSIX_FILE_P5, err, sizeof err);
        if (rc != -1)
            _exit(1);
        if (strstr(err, strerror(EFBIG)) == NULL || strstr(err, tpath("big.pgm")) == NULL) {
            fprintf(stderr, "unexpected message: %s\n", err);
            _exit(2);
        }
        _exit(0);
    }
    assert_int_equal(waitpid(pid, &status, 0), pid);
    assert_true(WIFEXITED(status));
    assert_int_equal(WEXITSTATUS(status), 0);
    assert_file_bytes(tpath("big.pgm"), "OLD", 3);
    assert_int_equal(count_hidden(g_dir), 0);
    stp_posix_frame_free(&f);
}

/* Targets that are not plain files (issue 13): a symbolic link keeps being
 * a link and its target is replaced; a dangling link creates its target; a
 * FIFO and a character device are written in place, never replaced by a
 * regular file. */
static void test_atomic_special_targets(void **state)
{
    stp_posix_frame f;
    struct stat st;
    char err[512] = "";
    int p[2];

    (void)state;
    make_mono(&f);
    spit(tpath("real.pbm"), "OLD", 3);
    assert_int_equal(symlink("real.pbm", tpath("link.pbm")), 0);
    write_ok(&f, tpath("link.pbm"), STP_POSIX_FILE_P4);
    assert_int_equal(lstat(tpath("link.pbm"), &st), 0);
    assert_true(S_ISLNK(st.st_mode));
    assert_file_bytes(tpath("real.pbm"), k_mono_p4, sizeof k_mono_p4);

    assert_int_equal(symlink("made.pbm", tpath("dangling.pbm")), 0);
    write_ok(&f, tpath("dangling.pbm"), STP_POSIX_FILE_P4);
    assert_int_equal(lstat(tpath("dangling.pbm"), &st), 0);
    assert_true(S_ISLNK(st.st_mode));
    assert_file_bytes(tpath("made.pbm"), k_mono_p4, sizeof k_mono_p4);

    /* /dev/null through a link in the test's directory: the link stays */
    assert_int_equal(symlink("/dev/null", tpath("null.pbm")), 0);
    write_ok(&f, tpath("null.pbm"), STP_POSIX_FILE_P4);
    assert_int_equal(lstat(tpath("null.pbm"), &st), 0);
    assert_true(S_ISLNK(st.st_mode));
    assert_int_equal(stat("/dev/null", &st), 0);
    assert_true(S_ISCHR(st.st_mode));

    /* a FIFO: a child writes, the parent reads what came through */
    assert_int_equal(mkfifo(tpath("fifo.pbm"), 0600), 0);
    assert_int_equal(pipe(p), 0);
    fflush(NULL);
    {
        pid_t pid = fork();
        uint8_t got[256];
        size_t n = 0;
        ssize_t r;
        int fd, status;
        assert_true(pid >= 0);
        if (pid == 0)
            _exit(stp_posix_write(&f, tpath("fifo.pbm"), STP_POSIX_FILE_P4, err, sizeof err) == 0
                      ? 0
                      : 1);
        fd = open(tpath("fifo.pbm"), O_RDONLY);
        assert_true(fd >= 0);
        while (n < sizeof got && (r = read(fd, got + n, sizeof got - n)) > 0)
            n += (size_t)r;
        close(fd);
        assert_int_equal(waitpid(pid, &status, 0), pid);
        assert_true(WIFEXITED(status));
        assert_int_equal(WEXITSTATUS(status), 0);
        assert_int_equal(n, sizeof k_mono_p4);
        assert_memory_equal(got, k_mono_p4, n);
    }
    close(p[0]);
    close(p[1]);
    assert_int_equal(lstat(tpath("fifo.pbm"), &st), 0);
    assert_true(S_ISFIFO(st.st_mode));
    assert_int_equal(count_hidden(g_dir), 0);
    stp_posix_frame_free(&f);
}

/* An emit that writes 64 KiB, tells the parent through the pipe that the
 * temporary file exists, then waits for the parent's signal. */
static int g_ready_fd = -1;
static int emit_then_wait(FILE *out, void *ctx)
{
    static char chunk[65536];
    (void)ctx;
    memset(chunk, 'x', sizeof chunk);
    if (fwrite(chunk, 1, sizeof chunk, out) != sizeof chunk || fflush(out) != 0)
        return -1;
    if (write(g_ready_fd, "r", 1) != 1)
        return -1;
    for (;;)
        pause();
}

/* SIGINT, SIGTERM and SIGHUP during the write remove the temporary file,
 * leave the old output as it was and still end the process by the signal. */
static void test_atomic_signal_removes_temporary(void **state)
{
    static const int sigs[] = {SIGINT, SIGTERM, SIGHUP};
    size_t k;

    (void)state;
    spit(tpath("signalled.pgm"), "OLD", 3);
    for (k = 0; k < sizeof sigs / sizeof sigs[0]; k++) {
        int p[2], status;
        char c;
        pid_t pid;
        assert_int_equal(pipe(p), 0);
        fflush(NULL);
        pid = fork();
        assert_true(pid >= 0);
        if (pid == 0) {
            char err[512];
            close(p[0]);
            g_ready_fd = p[1];
            signal(sigs[k], SIG_DFL);
            (void)stp_posix_write_file(tpath("signalled.pgm"), emit_then_wait, NULL, err,
                                       sizeof err);
            _exit(9);
        }
        close(p[1]);
        assert_int_equal(read(p[0], &c, 1), 1);
        close(p[0]);
        assert_int_equal(count_hidden(g_dir), 1); /* the temporary file is there */
        assert_int_equal(kill(pid, sigs[k]), 0);
        assert_int_equal(waitpid(pid, &status, 0), pid);
        assert_true(WIFSIGNALED(status));
        assert_int_equal(WTERMSIG(status), sigs[k]);
        assert_int_equal(count_hidden(g_dir), 0);
        assert_file_bytes(tpath("signalled.pgm"), "OLD", 3);
    }
}

static void test_write_rejects_kind(void **state)
{
    stp_posix_frame f;
    stp_posix_frame empty;
    char err[512] = "";
    struct stat st;

    (void)state;
    make_grey(&f);
    assert_int_equal(stp_posix_write(&f, tpath("grey_as.pbm"), STP_POSIX_FILE_P4, err,
                                     sizeof err), -1);
    assert_contains(err, tpath("grey_as.pbm"));
    assert_contains(err, "GREY8");
    assert_int_not_equal(stat(tpath("grey_as.pbm"), &st), 0);
    assert_int_equal(stp_posix_write(&f, tpath("grey_as.txt"), STP_POSIX_FILE_ASCII, err,
                                     sizeof err), -1);
    assert_int_equal(stp_posix_write(&f, tpath("x.pgm"), STP_POSIX_FILE_UNKNOWN, err,
                                     sizeof err), -1);
    stp_posix_frame_free(&f);

    memset(&empty, 0, sizeof empty);
    assert_int_equal(stp_posix_write(&empty, tpath("e.pgm"), STP_POSIX_FILE_P5, err,
                                     sizeof err), -1);
    assert_contains(err, "not initialised");
    assert_int_equal(stp_posix_write(NULL, tpath("e.pgm"), STP_POSIX_FILE_P5, NULL, 0), -1);
    assert_int_equal(count_hidden(g_dir), 0);
}

/* ------------------------------------------------------------- reading */

static void read_ok(const char *name, const void *data, size_t len, stp_posix_image *img,
                    int grey)
{
    char err[512] = "";
    int rc;

    spit(tpath(name), data, len);
    rc = grey ? stp_posix_read_grey(tpath(name), img, err, sizeof err)
              : stp_posix_read_pnm(tpath(name), img, err, sizeof err);
    if (rc != 0)
        fail_msg("reading %s failed: %s", name, err);
}

static void test_read_good(void **state)
{
    stp_posix_image img;
    static const char p2[] = "P2\n# made by hand\n3 # width\n2\n# maxval next\n4\n0 1 2\n3 4 0\n";
    static const uint8_t p2_want[] = { 0, 64, 128, 191, 255, 0 };
    static const char p5_16[] = "P5 2 1 65535\n\xFF\xFF\x80\x00";
    static const char p3[] = "P3 2 1 1  1 0 0  1 1 1";
    static const uint8_t p3_rgb[] = { 255, 0, 0, 255, 255, 255 };
    static const char p1[] = "P1\n4 2\n0110\n1001\n";
    static const uint8_t p1_want[] = { 255, 0, 0, 255, 0, 255, 255, 0 };
    static const char p6c[] = "P6\n1 1\n255#comment ends the header\n\x0A\x14\x1E";
    static const char p4[] = "P4\n9 2\n\x80\x7F\x00\x80";
    static const uint8_t p4_want[] = { 0, 255, 255, 255, 255, 255, 255, 255, 255,
                                       255, 255, 255, 255, 255, 255, 255, 255, 0 };

    (void)state;
    read_ok("g.pgm", p2, sizeof p2 - 1, &img, 0);
    assert_int_equal(img.width, 3);
    assert_int_equal(img.height, 2);
    assert_int_equal(img.pnm_type, 2);
    assert_int_equal(img.maxval, 4);
    assert_memory_equal(img.samples, p2_want, sizeof p2_want);
    stp_posix_image_free(&img);

    read_ok("w.pgm", p5_16, sizeof p5_16 - 1, &img, 0);
    assert_int_equal(img.samples[0], 255);
    assert_int_equal(img.samples[1], 128);
    stp_posix_image_free(&img);

    read_ok("c.ppm", p3, sizeof p3 - 1, &img, 0);
    assert_int_equal(img.channels, 3);
    assert_memory_equal(img.samples, p3_rgb, sizeof p3_rgb);
    stp_posix_image_free(&img);
    read_ok("c.ppm", p3, sizeof p3 - 1, &img, 1);
    assert_int_equal(img.channels, 1);
    assert_int_equal(img.samples[0], 76);
    assert_int_equal(img.samples[1], 255);
    stp_posix_image_free(&img);

    read_ok("p1.pbm", p1, sizeof p1 - 1, &img, 0);
    assert_memory_equal(img.samples, p1_want, sizeof p1_want);
    stp_posix_image_free(&img);

    read_ok("comment.ppm", p6c, sizeof p6c - 1, &img, 0);
    assert_int_equal(img.samples[0], 10);
    assert_int_equal(img.samples[1], 20);
    assert_int_equal(img.samples[2], 30);
    stp_posix_image_free(&img);

    read_ok("p4.pbm", p4, sizeof p4 - 1, &img, 1);
    assert_memory_equal(img.samples, p4_want, sizeof p4_want);
    stp_posix_image_free(&img);
}

typedef struct bad_case {
    const char *name;
    const char *data;
    size_t len;
    const char *message;
} bad_case;

#define BAD(name, data, message) { name, data, sizeof data - 1, message }

static void test_read_malformed(void **state)
{
    static const bad_case cases[] = {
        BAD("empty.pgm", "", "empty file"),
        BAD("magic7.pgm", "P7\n1 1\n255\n\x00", "not a PBM/PGM/PPM file"),
        BAD("magicq.pgm", "Q5\n1 1\n255\n\x00", "not a PBM/PGM/PPM file"),
        BAD("w0.pgm", "P5\n0 1\n255\n", "width 0"),
        BAD("h0.pgm", "P5\n1 0\n255\n", "height 0"),
        BAD("wbig.pgm", "P5\n40000 1\n255\n", "width 40000 too large"),
        BAD("hhuge.pgm", "P5\n1 99999999999\n255\n", "height too large"),
        BAD("m0.pgm", "P5\n2 2\n0\n\x00\x00\x00\x00", "maxval 0"),
        BAD("m65536.pgm", "P5\n2 2\n65536\n\x00\x00\x00\x00", "maxval 65536 over 65535"),
        BAD("wnan.pgm", "P5\nx 1\n255\n", "width is not a number"),
        BAD("wx.pgm", "P5\n2x2\n255\n", "width is followed by 'x'"),
        BAD("noh.pgm", "P5\n2", "truncated"),
        BAD("nomax.pgm", "P5\n2 2 # no maxval\n", "truncated"),
        /* Refused from the file's length, before allocating 3 GB. */
        BAD("huge.ppm", "P6\n32767 32767\n255\n\x00\x00\x00",
            "truncated: the raster needs 3221028867 bytes, the file has 3"),
        BAD("short5.pgm", "P5\n2 2\n255\n\x01\x02\x03", "truncated"),
        BAD("short6.ppm", "P6\n2 1\n255\n\x01\x02\x03\x04\x05", "truncated"),
        BAD("short16.pgm", "P5\n2 1\n300\n\x00\x01\x00", "truncated"),
        BAD("short4.pbm", "P4\n9 2\n\x00\x00\x00", "truncated"),
        BAD("short2.pgm", "P2\n2 2\n255\n1 2 3", "truncated"),
        BAD("short1.pbm", "P1\n3 2\n010\n01", "truncated"),
        BAD("over2.pgm", "P2\n2 1\n100\n5 101\n", "sample 101 over maxval 100 in row 0"),
        BAD("over5.pgm", "P5\n2 1\n100\n\x05\xC8", "sample 200 over maxval 100"),
        BAD("over16.pgm", "P5\n1 1\n1000\n\x03\xE9", "sample 1001 over maxval 1000"),
        BAD("stray1.pbm", "P1\n3 1\n0 2 1\n", "unexpected '2' in row 0"),
        BAD("stray3.ppm", "P3\n1 1\n255\n1 -2 3\n", "unexpected '-'"),
    };
    stp_posix_image img;
    char err[512];
    char want[600];
    size_t i;

    (void)state;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const char *path = tpath(cases[i].name);

        spit(path, cases[i].data, cases[i].len);
        memset(&img, 0x5A, sizeof img);
        strcpy(err, "");
        if (stp_posix_read_pnm(path, &img, err, sizeof err) != -1)
            fail_msg("%s was accepted", cases[i].name);
        assert_null(img.samples);
        assert_int_equal(img.width, 0);
        snprintf(want, sizeof want, "%s: ", path);
        if (strncmp(err, want, strlen(want)) != 0)
            fail_msg("message \"%s\" does not start with the path", err);
        assert_contains(err, cases[i].message);
    }

    /* A file that is not there: the path and the system's reason. */
    assert_int_equal(stp_posix_read_pnm(tpath("absent.pgm"), &img, err, sizeof err), -1);
    assert_contains(err, tpath("absent.pgm"));
    assert_contains(err, strerror(ENOENT));
    assert_int_equal(stp_posix_read_pnm(NULL, &img, err, sizeof err), -1);
    /* err may be omitted. */
    assert_int_equal(stp_posix_read_pnm(tpath("empty.pgm"), &img, NULL, 0), -1);
}

/* Reads "-" with stdin on a pipe holding data: a stream whose length cannot
 * be checked up front, so truncation is found row by row. */
static int read_stdin(const char *data, size_t len, stp_posix_image *img, char *err,
                      size_t errlen)
{
    int fds[2];
    int saved;
    int rc;

    assert_int_equal(pipe(fds), 0);
    assert_int_equal(write(fds[1], data, len), (ssize_t)len);
    close(fds[1]);
    saved = dup(0);
    assert_true(saved >= 0);
    assert_true(dup2(fds[0], 0) >= 0);
    close(fds[0]);
    clearerr(stdin);
    rc = stp_posix_read_pnm("-", img, err, errlen);
    assert_true(dup2(saved, 0) >= 0);
    close(saved);
    clearerr(stdin);
    return rc;
}

static void test_read_stdin(void **state)
{
    static const char good[] = "P5\n2 2\n255\n\x01\x02\x03\x04";
    static const char shortraw[] = "P5\n2 2\n255\n\x01\x02\x03";
    stp_posix_image img;
    char err[512] = "";

    (void)state;
    if (read_stdin(good, sizeof good - 1, &img, err, sizeof err) != 0)
        fail_msg("reading stdin failed: %s", err);
    assert_int_equal(img.samples[3], 4);
    stp_posix_image_free(&img);

    assert_int_equal(read_stdin(shortraw, sizeof shortraw - 1, &img, err, sizeof err), -1);
    assert_contains(err, "stdin: truncated: the file ends in row 1 of 2");
    assert_null(img.samples);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_frame_init),
        cmocka_unit_test(test_frame_bands),
        cmocka_unit_test(test_kind_selection),
        cmocka_unit_test(test_write_pbm),
        cmocka_unit_test(test_write_plain_long_rows),
        cmocka_unit_test(test_write_pgm),
        cmocka_unit_test(test_write_ppm),
        cmocka_unit_test(test_write_ascii),
        cmocka_unit_test(test_pamvalidate_accepts),
        cmocka_unit_test(test_write_stdout),
        cmocka_unit_test(test_atomic_replace),
        cmocka_unit_test(test_atomic_bad_directory),
        cmocka_unit_test(test_atomic_rename_fails),
        cmocka_unit_test(test_atomic_write_fails),
        cmocka_unit_test(test_atomic_special_targets),
        cmocka_unit_test(test_atomic_signal_removes_temporary),
        cmocka_unit_test(test_write_rejects_kind),
        cmocka_unit_test(test_read_good),
        cmocka_unit_test(test_read_malformed),
        cmocka_unit_test(test_read_stdin),
    };

    return cmocka_run_group_tests_name("posix_port", tests, group_setup, group_teardown);
}
