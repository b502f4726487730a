/* SPDX-License-Identifier: MIT */
/*
 * Edge anti-aliasing (stp_output.edge_aa, src/edge_aa.c) through the public
 * API:
 *  - exact pixels of half-planes over a known grey background, worked out
 *    by hand (an edge at 45 degrees through pixel centres leaves 1/2 on
 *    them; a vertical edge 1/4 pixel left of centres 1/4; the pixels a
 *    polygon owns keep its shade);
 *  - the coverage written against exact areas (double precision polygon
 *    clipping of each pixel square) on random triangles: the mean and
 *    largest error on the pixels the pass writes, and the whole picture's
 *    error with and without it;
 *  - the Z buffer: only where the polygon's plane is nearer, no depth
 *    written; Gouraud: the crossing's shade;
 *  - a 1-bit port equals the grey picture thresholded by the cell, and
 *    band rendering equals the whole frame, Z buffer and painter.
 * The view maps one world unit to one device pixel (as tests/core/
 * test_raster.c): device (dx, dy) is world (W/2 - dx, H/2 - dy).
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

#include "stipple/stipple.h"

#define ONE STP_FIX_ONE

static stp_fix fx(double v)
{
    return (stp_fix)floor(v * ONE + 0.5);
}

typedef struct dpt {
    double x, y;
} dpt;

typedef struct fixture {
    uint32_t w, h;
    void *mem;
    stp_instr *df;
    stp_renderer *r;
} fixture;

static void fixture_open(fixture *f, uint32_t w, uint32_t h, int levels)
{
    stp_view v;
    uint32_t short_side = w < h ? w : h;
    f->w = w;
    f->h = h;
    f->mem = malloc(stp_renderer_size());
    f->df = calloc(4096, sizeof *f->df);
    assert_true(f->mem && f->df);
    f->r = stp_renderer_create(f->mem, stp_renderer_size(), f->df, 4096, w, h);
    assert_non_null(f->r);
    memset(&v, 0, sizeof v);
    v.from.z = fx(-10);
    v.up.y = ONE;
    v.window_half = fx(short_side / 2.0);
    v.hither = fx(1);
    v.fov_degrees = fx(90);
    v.projection = STP_PARALLEL;
    assert_int_equal(stp_renderer_set_view(f->r, &v), STP_OK);
    assert_int_equal(stp_renderer_set_levels(f->r, levels), STP_OK);
    assert_int_equal(stp_segment_create(f->r, 1), STP_OK);
}

static void fixture_close(fixture *f)
{
    free(f->mem);
    free(f->df);
}

/* A polygon in device coordinates at world depth z (larger: farther from
 * the eye at z = -10) in a style, or with per-vertex shades (Gouraud). */
static void poly(fixture *f, const dpt *p, int n, double z, int style, const stp_fix *shades)
{
    stp_vec3 v[16];
    int i;
    for (i = 0; i < n; i++) {
        v[i].x = fx(f->w / 2.0 - p[i].x);
        v[i].y = fx(f->h / 2.0 - p[i].y);
        v[i].z = fx(z);
    }
    assert_int_equal(stp_renderer_set_fill_style(f->r, style), STP_OK);
    if (shades)
        assert_int_equal(stp_renderer_polygon_vertex_shades(f->r, v, shades, n), STP_OK);
    else
        assert_int_equal(stp_renderer_polygon(f->r, v, n), STP_OK);
}

typedef struct capture {
    stp_port port;
    uint8_t *frame;
    size_t stride;
} capture;

static int flush_copy(stp_port *port, uint32_t y0, uint32_t rows, const uint8_t *pixels, size_t stride)
{
    capture *c = port->user;
    uint32_t y;
    for (y = 0; y < rows; y++)
        memcpy(c->frame + (size_t)(y0 + y) * c->stride, pixels + (size_t)y * stride, c->stride);
    return 0;
}

typedef struct setting {
    stp_pixel_format format;
    stp_hidden hidden;
    uint32_t band_rows; /* 0: whole frame */
    int edge_aa;
    stp_fix background;
    const stp_cell *cell;
    const stp_diffusion *diffusion;
} setting;

static setting grey(stp_hidden hidden, int edge_aa)
{
    setting s;
    memset(&s, 0, sizeof s);
    s.format = STP_PIXEL_GREY8;
    s.hidden = hidden;
    s.edge_aa = edge_aa;
    return s;
}

/* Render (the status into *status); the frame is the caller's to free. */
static uint8_t *render_status(const fixture *f, const setting *s, int *status)
{
    capture c;
    stp_output out;
    stp_frame_memory mem;
    uint32_t rows = s->band_rows ? s->band_rows : f->h;
    size_t polygons = stp_renderer_polygon_count(f->r) + 1;
    memset(&c, 0, sizeof c);
    c.port.width = f->w;
    c.port.height = f->h;
    c.port.format = s->format;
    c.port.flush = flush_copy;
    c.port.user = &c;
    c.stride = stp_row_bytes(s->format, f->w);
    c.frame = calloc(f->h, c.stride);
    assert_non_null(c.frame);
    assert_int_equal(stp_output_default(&out), STP_OK);
    out.hidden = s->hidden;
    out.background = s->background;
    out.cell = s->cell;
    out.diffusion = s->diffusion;
    out.edge_aa = s->edge_aa;
    memset(&mem, 0, sizeof mem);
    mem.band_rows = rows;
    mem.band_size = (size_t)f->w * 3u * rows; /* room for any format, grey bands too */
    mem.band = malloc(mem.band_size);
    mem.zbuf_count = (size_t)f->w * rows;
    mem.zbuf = malloc(mem.zbuf_count * sizeof *mem.zbuf);
    mem.sort_count = polygons;
    mem.sort = malloc(polygons * sizeof *mem.sort);
    assert_true(mem.band && mem.zbuf && mem.sort);
    memset(mem.band, 0xA5, mem.band_size); /* nothing may depend on it */
    memset(mem.zbuf, 0xA5, mem.zbuf_count * sizeof *mem.zbuf);
    *status = stp_renderer_render(f->r, &c.port, &out, &mem);
    free(mem.band);
    free(mem.zbuf);
    free(mem.sort);
    return c.frame;
}

static uint8_t *render(const fixture *f, const setting *s)
{
    int status;
    uint8_t *frame = render_status(f, s, &status);
    assert_int_equal(status, STP_OK);
    return frame;
}

/* ---- exact pixels, by hand ---- */

/* 9 levels: shades k/8, linear levels round(255 k / 8).  Background 1/2
 * (level 128, read back as 1/2 exactly); the polygon style 9 (shade 1,
 * level 255).  A pixel of coverage c becomes 1/2 + c/2: c = 1/2 -> 3/4
 * (style 7, level 191), c = 1/4 -> 5/8 (style 6, level 159). */
#define BG 128
#define FULL 255
#define HALF 191
#define QUARTER 159

static void test_half_planes_by_hand(void **state)
{
    fixture f;
    setting s = grey(STP_HIDDEN_NONE, 1);
    uint8_t *frame, *plain;
    uint32_t x, y;
    /* left: a vertical edge at x = 2.5 (through centres: owned, full);
     * right: x = y + 8, a 45-degree edge through the centres of pixels
     * (8 + y, y): outside by the fill rule, covered 1/2; their right
     * neighbours are touched at a corner only (0) */
    static const dpt wedge[4] = {{2.5, 0}, {8, 0}, {24, 16}, {2.5, 16}};
    /* a vertical right edge at x = 28.25: pixel 28's centre is 1/4 pixel
     * outside, covered 1/4 */
    static const dpt bar[4] = {{26, 0}, {28.25, 0}, {28.25, 16}, {26, 16}};
    (void)state;
    fixture_open(&f, 32, 16, 9);
    s.background = ONE / 2;
    poly(&f, wedge, 4, 0, 9, 0);
    poly(&f, bar, 4, 0, 9, 0);
    frame = render(&f, &s);
    s.edge_aa = 0;
    plain = render(&f, &s);
    for (y = 0; y < 16; y++)
        for (x = 0; x < 32; x++) {
            int want = BG, got = frame[y * 32 + x];
            if (x >= 2 && x < 8 + y)
                want = FULL;
            else if (x == 8 + y)
                want = HALF;
            else if (x >= 26 && x < 28)
                want = FULL;
            else if (x == 28)
                want = QUARTER;
            if (got != want)
                fail_msg("pixel (%u,%u) is %d, by hand %d", x, y, got, want);
            /* off: the same pixels owned, nothing blended */
            if (plain[y * 32 + x] != (want == FULL ? FULL : BG))
                fail_msg("without edge_aa pixel (%u,%u) is %d", x, y, plain[y * 32 + x]);
        }
    free(frame);
    free(plain);
    fixture_close(&f);
}

/* A shallow edge (slope 4 pixels a row) covers a ramp of pixels in each
 * row, each by the area on the edge's inner side, by hand. */
static void test_shallow_edge_ramp(void **state)
{
    fixture f;
    setting s = grey(STP_HIDDEN_NONE, 1);
    uint8_t *frame;
    uint32_t x;
    /* right edge from (4, 0) to (36, 8): x = 4 + 4 y; row 1's centre
     * (y = 1.5) crosses at 10; pixel 10's centre (10.5) is 1/2 outside:
     * at h = 0.5 / (1 + 4) = 0.1 of its extent along the normal past the
     * edge; pixel 11: 0.3; pixel 12: beyond */
    static const dpt tri[4] = {{0, 0}, {4, 0}, {36, 8}, {0, 8}};
    (void)state;
    fixture_open(&f, 40, 8, 256);
    poly(&f, tri, 4, 0, 256, 0);
    frame = render(&f, &s);
    for (x = 0; x < 10; x++)
        assert_int_equal(frame[40 + x], 255);
    /* exact areas: pixel 10 covered 0.5 - 1/8 = 0.375, pixel 11 0.125; in
     * 1/256 (edge_aa.c): t = 128 - round(h 2^12 / w) with h in 1/16 pixel,
     * w = 256 (1 + 4): h = 8 -> 102, h = 24 -> 51; the corner share a =
     * round(256 / 5) = 51; t >= a: round((2t - a) 128 / (256 - a)) = 96 and
     * 32 (exactly 0.375 and 0.125); over background 0 at 256 levels the
     * level is floor(255 c / 256) */
    assert_int_equal(frame[40 + 10], 255 * 96 / 256);
    assert_int_equal(frame[40 + 11], 255 * 32 / 256);
    assert_int_equal(frame[40 + 12], 0);
    free(frame);
    fixture_close(&f);
}

/* ---- coverage against exact areas ---- */

/* Area of the part of pixel (i, j) inside triangle t (double precision:
 * the square clipped by each edge's half-plane). */
static double exact_coverage(const dpt *t, int i, int j)
{
    dpt a[16], b[16];
    int n = 4, k, e;
    double area = 0, orient = (t[1].x - t[0].x) * (t[2].y - t[0].y) - (t[1].y - t[0].y) * (t[2].x - t[0].x);
    a[0].x = i, a[0].y = j;
    a[1].x = i + 1, a[1].y = j;
    a[2].x = i + 1, a[2].y = j + 1;
    a[3].x = i, a[3].y = j + 1;
    for (e = 0; e < 3 && n > 0; e++) {
        dpt p = t[e], q = t[(e + 1) % 3];
        int m = 0;
        for (k = 0; k < n; k++) {
            dpt u = a[k], v = a[(k + 1) % n];
            double su = ((q.x - p.x) * (u.y - p.y) - (q.y - p.y) * (u.x - p.x)) * orient;
            double sv = ((q.x - p.x) * (v.y - p.y) - (q.y - p.y) * (v.x - p.x)) * orient;
            if (su >= 0)
                b[m++] = u;
            if ((su >= 0) != (sv >= 0)) {
                double r = su / (su - sv);
                b[m].x = u.x + r * (v.x - u.x);
                b[m].y = u.y + r * (v.y - u.y);
                m++;
            }
        }
        memcpy(a, b, sizeof(dpt) * (size_t)m);
        n = m;
    }
    for (k = 0; k < n; k++)
        area += a[k].x * a[(k + 1) % n].y - a[(k + 1) % n].x * a[k].y;
    return fabs(area) / 2;
}

/* Whether pixel (i, j)'s centre is 2 pixels or more from every vertex of t
 * and its square meets one edge only (a half-plane there). */
static int clear_of_vertices(const dpt *t, int i, int j)
{
    int k;
    for (k = 0; k < 3; k++)
        if (hypot(t[k].x - (i + 0.5), t[k].y - (j + 0.5)) < 2)
            return 0;
    return 1;
}

/* Random triangles, white on black at 256 levels (a pixel's level is
 * floor(255 c)): the pixels the pass writes against their exact areas,
 * and every pixel's error with and without the pass; the pixels the
 * polygon owns are the same with and without it. */
static void test_coverage_against_exact_area(void **state)
{
    double outer_sum = 0, outer_max = 0, aa_sum = 0, plain_sum = 0, far_sum = 0, far_max = 0;
    long outer_n = 0, edge_n = 0, far_n = 0;
    unsigned seed = 12345;
    int trial;
    (void)state;
    for (trial = 0; trial < 200; trial++) {
        fixture f;
        setting s = grey(STP_HIDDEN_NONE, 1);
        dpt t[3];
        uint8_t *aa, *plain;
        int i, j, k;
        for (k = 0; k < 3; k++) {
            seed = seed * 1103515245u + 12345u;
            t[k].x = 1 + ((seed >> 8) % (62 * 16)) / 16.0;
            seed = seed * 1103515245u + 12345u;
            t[k].y = 1 + ((seed >> 8) % (62 * 16)) / 16.0;
        }
        if (fabs((t[1].x - t[0].x) * (t[2].y - t[0].y) - (t[1].y - t[0].y) * (t[2].x - t[0].x)) < 1)
            continue; /* no area: the renderer drops it */
        fixture_open(&f, 64, 64, 256);
        poly(&f, t, 3, 0, 256, 0);
        aa = render(&f, &s);
        s.edge_aa = 0;
        plain = render(&f, &s);
        for (j = 0; j < 64; j++)
            for (i = 0; i < 64; i++) {
                double exact = exact_coverage(t, i, j), got = aa[j * 64 + i] / 255.0;
                /* the pixels the polygon owns: its spans' (the fill rule
                 * as the scan converter computes the crossings) */
                int own = plain[j * 64 + i] == 255;
                if (own && aa[j * 64 + i] != 255)
                    fail_msg("triangle %d: owned pixel (%d,%d) is %d, not the full shade", trial, i, j,
                             aa[j * 64 + i]);
                if (!own && aa[j * 64 + i] > 0) {
                    double err = fabs(got - exact);
                    outer_sum += err;
                    outer_n++;
                    if (err > outer_max)
                        outer_max = err;
                    if (clear_of_vertices(t, i, j)) {
                        far_sum += err;
                        far_n++;
                        if (err > far_max)
                            far_max = err;
                    }
                }
                if (exact > 0 && exact < 1) {
                    aa_sum += fabs(got - exact);
                    plain_sum += fabs(plain[j * 64 + i] / 255.0 - exact);
                    edge_n++;
                }
            }
        free(aa);
        free(plain);
        fixture_close(&f);
    }
    print_message("pixels written by the pass: %ld, error against the exact area: mean %.4f, max %.4f\n",
                  outer_n, outer_sum / (double)outer_n, outer_max);
    print_message("of them 2 pixels or more from a vertex: %ld, mean %.4f, max %.4f\n", far_n,
                  far_sum / (double)far_n, far_max);
    print_message("pixels an edge crosses: %ld, mean error with the pass %.4f, without %.4f\n", edge_n,
                  aa_sum / (double)edge_n, plain_sum / (double)edge_n);
    assert_true(outer_n > 1000);
    /* exact for a half-plane but for the crossings' 1/16-pixel steps and
     * the 1/256 coverage steps; near vertices the edge's line is taken past
     * its end (capped by its x extent) and the polygon's other edges beyond
     * the span are not seen */
    assert_true(far_n > 1000);
    assert_true(far_sum / (double)far_n < 0.03);
    assert_true(far_max < 0.1);
    assert_true(outer_sum / (double)outer_n < 0.03);
    assert_true(outer_max < 0.5);
    /* owned pixels keep the full shade, so about half the error stays */
    assert_true(aa_sum < 0.6 * plain_sum);
}

/* ---- Z buffer and Gouraud ---- */

static void test_zbuffer_blends_only_where_nearer(void **state)
{
    fixture f;
    setting s = grey(STP_HIDDEN_ZBUFFER, 1);
    uint8_t *frame;
    uint32_t y;
    /* far square (z = 5, style 256) with its right edge at x = 8.25;
     * near square (z = 0, style 128) over rows 4..7 from x = 8 on, drawn
     * first: pixel 8 of those rows stays the near square's; other rows
     * take 1/4 of the far one over the background */
    static const dpt near_sq[4] = {{8, 4}, {16, 4}, {16, 8}, {8, 8}};
    static const dpt far_sq[4] = {{0, 0}, {8.25, 0}, {8.25, 12}, {0, 12}};
    static const dpt later[4] = {{8, 8}, {12, 8}, {12, 12}, {8, 12}};
    (void)state;
    fixture_open(&f, 16, 12, 256);
    poly(&f, near_sq, 4, 0, 128, 0);
    poly(&f, far_sq, 4, 5, 256, 0);
    /* farther still, drawn after: the pass wrote no depth, so it wins the
     * pixels the far square only partly covers */
    poly(&f, later, 4, 8, 200, 0);
    frame = render(&f, &s);
    for (y = 0; y < 12; y++) {
        /* 1/4 of 255 over 0: style 64, level 63; the near square's style
         * 128: level 127; the later square's 200: 199 */
        int want = y < 4 ? 63 : (y < 8 ? 127 : 199);
        assert_int_equal(frame[y * 16 + 7], 255);
        assert_int_equal(frame[y * 16 + 8], want);
        if (y >= 8)
            assert_int_equal(frame[y * 16 + 9], 199);
    }
    free(frame);
    fixture_close(&f);
}

static void test_gouraud_edge_takes_the_crossing_shade(void **state)
{
    fixture f;
    setting s = grey(STP_HIDDEN_NONE, 1);
    uint8_t *frame, *flat;
    uint32_t y;
    /* shades 1/4 on the left edge, 3/4 on the right one (x = 8.25): pixel
     * 8 is covered 1/4 by a polygon of shade 3/4 at that crossing */
    static const dpt sq[4] = {{0, 0}, {8.25, 0}, {8.25, 8}, {0, 8}};
    const stp_fix shades[4] = {ONE / 4, 3 * ONE / 4, 3 * ONE / 4, ONE / 4};
    (void)state;
    fixture_open(&f, 16, 8, 256);
    poly(&f, sq, 4, 0, 256, shades);
    frame = render(&f, &s);
    s.edge_aa = 0;
    flat = render(&f, &s);
    for (y = 0; y < 8; y++) {
        assert_int_equal(frame[y * 16 + 8], (int)(255 * 0.75 * 0.25));
        assert_memory_equal(frame + y * 16, flat + y * 16, 8); /* owned pixels unchanged */
    }
    free(frame);
    free(flat);
    fixture_close(&f);
}

/* ---- 1-bit ports and bands ---- */

/* A scene of overlapping triangles at several depths, flat and Gouraud. */
static void scene(fixture *f, int levels)
{
    unsigned seed = 777;
    int n, k;
    for (n = 0; n < 40; n++) {
        dpt t[3];
        stp_fix sh[3];
        for (k = 0; k < 3; k++) {
            seed = seed * 1103515245u + 12345u;
            t[k].x = ((seed >> 8) % (f->w * 16)) / 16.0;
            seed = seed * 1103515245u + 12345u;
            t[k].y = ((seed >> 8) % (f->h * 16)) / 16.0;
            sh[k] = (stp_fix)((seed >> 4) % (uint32_t)ONE);
        }
        if (fabs((t[1].x - t[0].x) * (t[2].y - t[0].y) - (t[1].y - t[0].y) * (t[2].x - t[0].x)) < 1)
            continue;
        poly(f, t, 3, (double)(n % 7), 1 + (n * 37) % levels, n % 2 ? sh : 0);
    }
}

static void test_mono1_is_grey_thresholded(void **state)
{
    fixture f;
    stp_cell cell;
    uint8_t *grey_frame, *mono;
    uint32_t x, y;
    setting s = grey(STP_HIDDEN_ZBUFFER, 1);
    (void)state;
    fixture_open(&f, 67, 29, 256); /* a width not a multiple of 8 */
    scene(&f, 256);
    (void)stp_cell_bayer(&cell, 4);
    s.cell = &cell;
    s.background = ONE / 3;
    grey_frame = render(&f, &s);
    s.format = STP_PIXEL_MONO1;
    mono = render(&f, &s);
    for (y = 0; y < 29; y++) {
        for (x = 0; x < 67; x++) {
            int bit = (mono[y * 9 + x / 8] >> (7 - x % 8)) & 1;
            if (bit != stp_cell_on(&cell, x, y, grey_frame[y * 67 + x]))
                fail_msg("pixel (%u,%u): 1-bit %d, grey %d thresholded differs", x, y, bit,
                         grey_frame[y * 67 + x]);
        }
        assert_int_equal(mono[y * 9 + 8] & 0x1F, 0); /* padding bits */
    }
    free(grey_frame);
    free(mono);
    fixture_close(&f);
}

static void test_bands_equal_frame(void **state)
{
    static const stp_pixel_format formats[] = {STP_PIXEL_GREY8, STP_PIXEL_MONO1, STP_PIXEL_RGB888,
                                               STP_PIXEL_STYLE8};
    static const stp_hidden methods[] = {STP_HIDDEN_ZBUFFER, STP_HIDDEN_PAINTER, STP_HIDDEN_NONE};
    static const uint32_t bands[] = {1, 3, 7};
    int16_t errors[2 * (67 + 4)];
    stp_diffusion d;
    fixture f;
    size_t fm, m, b, diffuse;
    (void)state;
    fixture_open(&f, 67, 29, 16);
    scene(&f, 16);
    for (fm = 0; fm < sizeof formats / sizeof formats[0]; fm++)
        for (m = 0; m < sizeof methods / sizeof methods[0]; m++)
            for (diffuse = 0; diffuse < (formats[fm] == STP_PIXEL_MONO1 ? 2u : 1u); diffuse++) {
                setting s = grey(methods[m], 1);
                uint8_t *whole, *plain;
                size_t bytes = stp_row_bytes(formats[fm], 67) * 29;
                s.format = formats[fm];
                s.background = ONE / 5;
                memset(&d, 0, sizeof d);
                d.kernel = STP_DIFFUSE_FLOYD_STEINBERG;
                d.serpentine = 1;
                d.errors = errors;
                d.error_count = sizeof errors / sizeof errors[0];
                s.diffusion = diffuse ? &d : 0;
                whole = render(&f, &s);
                s.edge_aa = 0;
                plain = render(&f, &s);
                s.edge_aa = 1;
                /* the pass changes the picture: the comparison is not empty */
                if (memcmp(whole, plain, bytes) == 0)
                    fail_msg("format %d method %d: edge_aa changed nothing", (int)formats[fm], (int)methods[m]);
                for (b = 0; b < sizeof bands / sizeof bands[0]; b++) {
                    uint8_t *banded;
                    s.band_rows = bands[b];
                    banded = render(&f, &s);
                    if (memcmp(banded, whole, bytes) != 0)
                        fail_msg("format %d method %d diffusion %d: bands of %u rows differ from the frame",
                                 (int)formats[fm], (int)methods[m], (int)diffuse, bands[b]);
                    free(banded);
                }
                free(whole);
                free(plain);
            }
    fixture_close(&f);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_half_planes_by_hand),
        cmocka_unit_test(test_shallow_edge_ramp),
        cmocka_unit_test(test_coverage_against_exact_area),
        cmocka_unit_test(test_zbuffer_blends_only_where_nearer),
        cmocka_unit_test(test_gouraud_edge_takes_the_crossing_shade),
        cmocka_unit_test(test_mono1_is_grey_thresholded),
        cmocka_unit_test(test_bands_equal_frame),
    };
    return cmocka_run_group_tests(tests, 0, 0);
}
