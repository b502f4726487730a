/* SPDX-License-Identifier: MIT */
/*
 * The panel page layout (STP_PIXEL_MONO1_PAGES, port.h) against 1-bit rows.
 *
 * - Every shared scene, through the hidden-surface methods, flat and smooth
 *   shading, transparency, ordered dither with cells of every kind (Bayer,
 *   pattern, blue noise, a 6-wide clustered screen), error diffusion, edge
 *   anti-aliasing, shadow maps and the ray tracer (stp_rt_render), at 128x64 and 100x60 (neither side a multiple of 8), in
 *   bands of 8, 16, 24 rows and the whole frame: each band the port receives
 *   is checked (page stride, bands on page boundaries, the unused bits of a
 *   last partial page 0) and its pages gathered, and every pixel must equal
 *   the same scene rendered whole as MONO1 rows.  This test reads the pages
 *   with its own lines, not the ports' packer.
 * - Band heights that are not whole pages are refused (STP_ERR_ARG), a band
 *   buffer short of whole pages too (STP_ERR_MEMORY), and the frame-memory
 *   helpers size and split page bands in whole pages.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "render_scene.h"
#include "stp_posix.h"
#include "test_scenes.h"

static const char *const scenes[] = {"tetra-s1", "tetra-s2", "mount-s2", "teapot-s1",
                                     "teapot-s2", "gears-s1", "balls-s1", "balls-s2"};
#define SCENE_COUNT (sizeof scenes / sizeof scenes[0])

/* What the page port gathers: the frame's pages, and how the bands came. */
typedef struct page_sink {
    uint8_t *pages; /* (height + 7) / 8 pages of width bytes */
    uint32_t width, height, next_y;
    int bad; /* a band against the layout's rules: the test fails */
    char why[160];
} page_sink;

static int page_flush(stp_port *port, uint32_t y0, uint32_t rows, const uint8_t *pixels, size_t stride)
{
    page_sink *s = (page_sink *)port->user;
    uint32_t count = (rows + 7u) / 8u, x;
    if (s->bad)
        return 0;
    if (stride != s->width || y0 != s->next_y || y0 % 8u != 0 || y0 + rows > s->height) {
        s->bad = 1;
        snprintf(s->why, sizeof s->why, "band y0 %u rows %u stride %zu", (unsigned)y0, (unsigned)rows, stride);
        return 0;
    }
    if (rows % 8u != 0) /* the last page's bits below the band: 0 */
        for (x = 0; x < s->width; x++)
            if (pixels[(size_t)(count - 1u) * stride + x] >> (rows % 8u)) {
                s->bad = 1;
                snprintf(s->why, sizeof s->why, "band y0 %u: bits past its %u rows set at x %u", (unsigned)y0,
                         (unsigned)rows, (unsigned)x);
                return 0;
            }
    memcpy(s->pages + (size_t)(y0 / 8u) * s->width, pixels, (size_t)count * s->width);
    s->next_y = y0 + rows;
    return 0;
}

/* Render the scene to pages (band_rows as opt) and compare every pixel with
 * rows, the MONO1 render: 0 when equal, else the failure's message printed. */
static int compare_pages(const stp_scene *scene, const stp_tool_options *opt, const stp_posix_frame *rows,
                         const char *what)
{
    page_sink sink;
    stp_port port;
    char err[512];
    uint32_t x, y, differ = 0;
    memset(&sink, 0, sizeof sink);
    sink.width = (uint32_t)opt->width;
    sink.height = (uint32_t)opt->height;
    sink.pages = calloc(((size_t)sink.height + 7u) / 8u, sink.width);
    assert_non_null(sink.pages);
    port.width = sink.width;
    port.height = sink.height;
    port.format = STP_PIXEL_MONO1_PAGES;
    port.flush = page_flush;
    port.user = &sink;
    if (stp_tool_render(scene, opt, &port, 0, err, sizeof err) != 0)
        fail_msg("%s: pages render failed: %s", what, err);
    if (sink.bad || sink.next_y != sink.height) {
        print_error("%s, bands of %d: %s (rows sent %u)\n", what, opt->band_rows, sink.why,
                    (unsigned)sink.next_y);
        free(sink.pages);
        return 1;
    }
    for (y = 0; y < sink.height; y++)
        for (x = 0; x < sink.width; x++) {
            int in_rows = (rows->pixels[(size_t)y * rows->stride + x / 8u] >> (7u - x % 8u)) & 1u;
            int in_pages = (sink.pages[(size_t)(y / 8u) * sink.width + x] >> (y % 8u)) & 1u;
            differ += in_rows != in_pages;
        }
    free(sink.pages);
    if (differ)
        print_error("%s, bands of %d: %u pixels differ from the rows\n", what, opt->band_rows, (unsigned)differ);
    return differ != 0;
}

enum { VARIANTS = 13 };

/* Variant v of the options (the default: Z buffer, flat, Bayer 4x4); its
 * name in *name.  0 when the build lacks what the variant needs. */
static int variant_options(int v, stp_tool_options *opt, const char **name)
{
    static const char *const names[VARIANTS] = {"Z buffer",   "painter",      "smooth",     "transparent",
                                                "diffusion",  "edge AA",      "blue noise", "pattern 2x2",
                                                "clustered 6", "no hidden",   "ray traced", "ray traced, diffusion",
                                                "shadow maps"};
    *name = names[v];
    switch (v) {
    case 1: opt->hidden = STP_HIDDEN_PAINTER; return STP_WITH_PAINTER;
    case 2: opt->smooth = 1; return STP_WITH_GOURAUD;
    case 3:
        opt->transparency = 1;
        opt->hidden = STP_HIDDEN_PAINTER;
        return STP_WITH_TRANSPARENCY && STP_WITH_PAINTER;
    case 4:
        opt->dither = STP_TOOL_DITHER_DIFFUSE;
        opt->levels = 256;
        return STP_WITH_DIFFUSION;
    case 5: opt->edge_aa = 1; return STP_WITH_EDGE_AA;
    case 6: opt->dither = STP_TOOL_DITHER_BLUE_NOISE; return 1;
    case 7: opt->dither = STP_TOOL_DITHER_PATTERN2X2; return 1;
    case 8:
        opt->dither = STP_TOOL_DITHER_CLUSTERED;
        opt->clustered_n = 6;
        opt->clustered_angle = 45;
        return 1;
    case 9: opt->hidden = STP_HIDDEN_NONE; return 1;
    case 10: opt->raytrace = 1; return STP_WITH_RAYTRACE;
    case 11:
        opt->raytrace = 1;
        opt->dither = STP_TOOL_DITHER_DIFFUSE;
        opt->levels = 256;
        return STP_WITH_RAYTRACE && STP_WITH_DIFFUSION;
    case 12: opt->shadow_resolution = 128; return STP_WITH_SHADOWS;
    default: return STP_WITH_ZBUFFER;
    }
}

static void check_size(int width, int height)
{
    static const int bands[] = {8, 16, 24, 0};
    size_t n, b;
    int v, failures = 0, lit_frames = 0;
    for (n = 0; n < SCENE_COUNT; n++) {
        stp_scene scene;
        stp_test_load_scene(scenes[n], &scene);
        for (v = 0; v < VARIANTS; v++) {
            stp_tool_options opt;
            stp_posix_frame rows;
            const char *name;
            char what[128], err[512];
            size_t i;
            stp_tool_options_default(&opt);
            opt.width = width;
            opt.height = height;
            if (!variant_options(v, &opt, &name))
                continue;
            assert_int_equal(stp_posix_frame_init(&rows, (uint32_t)width, (uint32_t)height, STP_PIXEL_MONO1), 0);
            if (stp_tool_render(&scene, &opt, stp_posix_frame_port(&rows), 0, err, sizeof err) != 0)
                fail_msg("%s %s: render failed: %s", scenes[n], name, err);
            for (i = 0; i < rows.stride * rows.height; i++)
                if (rows.pixels[i]) {
                    lit_frames++;
                    break;
                }
            snprintf(what, sizeof what, "%s %dx%d %s", scenes[n], width, height, name);
            for (b = 0; b < sizeof bands / sizeof bands[0]; b++) {
                opt.band_rows = bands[b];
                failures += compare_pages(&scene, &opt, &rows, what);
            }
            stp_posix_frame_free(&rows);
        }
        stp_scene_free(&scene);
    }
    /* pictures with nothing lit would make the comparisons empty */
    assert_true(lit_frames >= (int)SCENE_COUNT);
    assert_int_equal(failures, 0);
}

static void test_pages_equal_rows_128x64(void **state)
{
    (void)state;
    check_size(128, 64);
}

static void test_pages_equal_rows_100x60(void **state)
{
    (void)state;
    check_size(100, 60);
}

static int discard(stp_port *port, uint32_t y0, uint32_t rows, const uint8_t *pixels, size_t stride)
{
    (void)port;
    (void)y0;
    (void)rows;
    (void)pixels;
    (void)stride;
    return 0;
}

/* One triangle, rendered to a page port of height rows in bands of
 * band_rows with band_size bytes of band: stp_renderer_render's status. */
static int render_status(uint32_t height, uint32_t band_rows, size_t band_size, stp_hidden hidden)
{
    static stp_renderer_storage storage;
    static stp_instr df[64];
    static uint8_t band[16 * 8];
    static uint16_t zbuf[16 * 64];
    static stp_sort_entry sort[4];
    const stp_vec3 tri[3] = {{-STP_FIX_ONE / 2, -STP_FIX_ONE / 2, 0},
                             {STP_FIX_ONE / 2, -STP_FIX_ONE / 2, 0},
                             {0, STP_FIX_ONE / 2, 0}};
    stp_renderer *r = stp_renderer_create(&storage, sizeof storage, df, 64, 16, height);
    stp_port port = {16, 0, STP_PIXEL_MONO1_PAGES, discard, 0};
    stp_output out;
    stp_frame_memory mem;
    assert_non_null(r);
    port.height = height;
    assert_int_equal(stp_renderer_polygon(r, tri, 3), STP_OK);
    (void)stp_output_default(&out);
    out.hidden = hidden;
    memset(&mem, 0, sizeof mem);
    mem.band = band;
    mem.band_size = band_size;
    mem.band_rows = band_rows;
    mem.zbuf = zbuf;
    mem.zbuf_count = 16u * band_rows;
    mem.sort = sort;
    mem.sort_count = 4;
    return stp_renderer_render(r, &port, &out, &mem);
}

static void test_pages_band_rows(void **state)
{
    uint32_t rows;
    (void)state;
    /* 64 rows: bands of whole pages, or the whole frame; others refused */
    for (rows = 1; rows <= 64; rows++) {
        int want = rows % 8u == 0 ? STP_OK : STP_ERR_ARG;
        size_t need = (rows + 7u) / 8u * 16u; /* whole pages of 16 bytes */
        assert_int_equal(render_status(64, rows, need, STP_HIDDEN_PAINTER), want);
#if STP_WITH_ZBUFFER
        assert_int_equal(render_status(64, rows, need, STP_HIDDEN_ZBUFFER), want);
#endif
    }
    /* a frame of 20 rows: 20 (one band, 3 pages) or 8, 16; not 10 */
    assert_int_equal(render_status(20, 20, 48, STP_HIDDEN_PAINTER), STP_OK);
    assert_int_equal(render_status(20, 16, 32, STP_HIDDEN_PAINTER), STP_OK);
    assert_int_equal(render_status(20, 10, 48, STP_HIDDEN_PAINTER), STP_ERR_ARG);
    /* the band must hold whole pages: 20 rows are 3 pages of 16 bytes */
    assert_int_equal(render_status(20, 20, 47, STP_HIDDEN_PAINTER), STP_ERR_MEMORY);
    assert_int_equal(render_status(20, 8, 15, STP_HIDDEN_PAINTER), STP_ERR_MEMORY);
}

static void test_pages_memory_helpers(void **state)
{
    stp_port port = {100, 60, STP_PIXEL_MONO1_PAGES, discard, 0};
    stp_frame_memory mem;
    static uint8_t buffer[8192];
    (void)state;
    assert_int_equal(stp_row_bytes(STP_PIXEL_MONO1_PAGES, 100), 100);
    assert_int_equal(stp_tool_band_bytes(STP_PIXEL_MONO1_PAGES, 100, 9), 200);
    /* Z buffer: 8 rows are 100 bytes of page and 1600 of depth */
    assert_int_equal(stp_frame_memory_bytes(&port, STP_HIDDEN_ZBUFFER, 8, 0), 1700u + 3u);
    assert_int_equal(stp_frame_memory_bytes(&port, STP_HIDDEN_NONE, 60, 0), 800u + 3u);
    /* a split hands out whole pages: 2 pages fit in 3500 bytes, not 2.06 */
    assert_int_equal(stp_frame_memory_split(&mem, 0, &port, 0, buffer, 3500), STP_OK);
    assert_int_equal(mem.band_rows, 16);
    assert_int_equal(mem.zbuf_count, 1600);
    assert_true(mem.band_size >= 200);
    assert_int_equal(stp_frame_memory_split(&mem, 0, &port, 0, buffer, 1600), STP_ERR_MEMORY);
    /* 8192 bytes */
    assert_int_equal(stp_frame_memory_split(&mem, 0, &port, 0, buffer, sizeof buffer), STP_OK);
    assert_int_equal(mem.band_rows, 32); /* 4 pages of 1700 bytes */
    assert_int_equal(mem.band_size, 400);
    /* no Z buffer: all 60 rows, 8 pages */
    {
        stp_output out;
        (void)stp_output_default(&out);
        out.hidden = STP_HIDDEN_NONE;
        assert_int_equal(stp_frame_memory_split(&mem, 0, &port, &out, buffer, 803), STP_OK);
        assert_int_equal(mem.band_rows, 60);
        assert_int_equal(mem.band_size, 800);
        assert_int_equal(stp_frame_memory_split(&mem, 0, &port, &out, buffer, 799), STP_OK);
        assert_int_equal(mem.band_rows, 56);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_pages_equal_rows_128x64),
        cmocka_unit_test(test_pages_equal_rows_100x60),
        cmocka_unit_test(test_pages_band_rows),
        cmocka_unit_test(test_pages_memory_helpers),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
