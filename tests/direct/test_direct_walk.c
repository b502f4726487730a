/* SPDX-License-Identifier: MIT */
/*
 * Direct drawing's band fill (stp_direct_draw_band: the triangle walk of
 * src/edge_walk_private.h, compiled for direct drawing's points at a moved
 * origin) against the fill rule written out independently here, pixel for
 * pixel: random triangles with device positions anywhere in the range
 * direct.h allows ([-8192, 8192) in Q4, most of them on or near a 96 x 40
 * panel, some far off it, some thin or with a horizontal edge), drawn with
 * every pixel's pattern ON, in bands of 1, 5, 8 and 40 rows, in rows and in
 * the panel's pages.
 *
 * The rule (include/stipple/render.h): pixel (px, py) is drawn when row
 * centre yc = 16 py + 8 lies in [ya, yb) of exactly two edges (a - b taken
 * downwards) and its centre 16 px + 8 lies in [xl, xr) of their
 * crossings, an edge crossing yc at floor((xa 2^16 + (yc - ya) s) / 2^16),
 * s = trunc(2^16 (xb - xa) / (yb - ya)).  Formed here per pixel in 64-bit
 * arithmetic straight from that formula, with no walk and no accumulator.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "stipple/direct.h"

#define W 96
#define H 40
#define STRIDE (W / 8)

/* floor(a / b) for b > 0 */
static int64_t floor_div(int64_t a, int64_t b)
{
    int64_t q = a / b;
    return (a % b != 0 && a < 0) ? q - 1 : q;
}

/* The crossing of row centre yc by edge a - b, or 0 when yc is outside the
 * edge's rows [ya, yb) (taken downwards). */
static int crossing(const stp_direct_point *a, const stp_direct_point *b, int64_t yc, int64_t *x)
{
    int64_t xa = a->dx, ya = a->dy, xb = b->dx, yb = b->dy, s;
    if (ya > yb) {
        int64_t t = xa;
        xa = xb;
        xb = t;
        t = ya;
        ya = yb;
        yb = t;
    }
    if (!(ya <= yc && yc < yb))
        return 0;
    s = (xb - xa) * 65536 / (yb - ya); /* C's division truncates */
    *x = floor_div(xa * 65536 + (yc - ya) * s, 65536);
    return 1;
}

/* Whether the rule draws pixel (px, py) of triangle p. */
static int covered(const stp_direct_point p[3], int px, int py)
{
    int64_t yc = 16 * (int64_t)py + 8, xc = 16 * (int64_t)px + 8, x[3], lo, hi;
    int i, n = 0;
    for (i = 0; i < 3; i++)
        if (crossing(&p[i], &p[(i + 1) % 3], yc, &x[n]))
            n++;
    if (n != 2)
        return 0;
    lo = x[0] < x[1] ? x[0] : x[1];
    hi = x[0] < x[1] ? x[1] : x[0];
    return lo <= xc && xc < hi;
}

static uint32_t next(uint32_t *seed)
{
    *seed ^= *seed << 13;
    *seed ^= *seed >> 17;
    *seed ^= *seed << 5;
    return *seed;
}

/* A device coordinate: near the panel (extent in pixels, a margin either
 * side) most of the time, anywhere in [-8192, 8192) sometimes. */
static int16_t coordinate(uint32_t *seed, int extent)
{
    uint32_t r = next(seed);
    if ((r & 15u) == 0)
        return (int16_t)((int32_t)(next(seed) % 16384u) - 8192);
    return (int16_t)((int32_t)(next(seed) % (uint32_t)(16 * (extent + 16))) - 16 * 8);
}

static void random_triangle(uint32_t *seed, stp_direct_point p[3])
{
    int i;
    for (i = 0; i < 3; i++) {
        memset(&p[i], 0, sizeof p[i]);
        p[i].dx = coordinate(seed, W);
        p[i].dy = coordinate(seed, H);
    }
    switch (next(seed) % 8u) {
    case 0: /* a horizontal edge */
        p[1].dy = p[0].dy;
        break;
    case 1: /* thin: two corners a subpixel or two apart */
        p[2].dx = (int16_t)(p[0].dx + (int16_t)(next(seed) % 3u));
        p[2].dy = (int16_t)(p[0].dy + 64);
        break;
    case 2: /* corners on pixel centres */
        for (i = 0; i < 3; i++) {
            p[i].dx = (int16_t)((p[i].dx & ~15) | 8);
            p[i].dy = (int16_t)((p[i].dy & ~15) | 8);
        }
        break;
    default:
        break;
    }
}

/* The picture of triangle p drawn by stp_direct_draw_band in bands of
 * band_rows rows, in rows (pages 0) or pages (1), unpacked to one byte a
 * pixel. */
static void draw(const stp_direct_point p[3], int band_rows, int pages, uint8_t out[H][W])
{
    static const uint16_t triangle[3] = {0, 1, 2};
    static const uint8_t cell[16] = {0}; /* every threshold 0: intensity 255 turns every pixel ON */
    uint16_t faces[1] = {256 + 255};
    uint8_t band[40 * STRIDE + W];
    stp_mesh mesh;
    stp_direct_frame f;
    int y0, x, y;
    memset(&mesh, 0, sizeof mesh);
    mesh.triangles = triangle;
    mesh.vertex_count = 3;
    mesh.triangle_count = 1;
    memset(&f, 0, sizeof f);
    f.mesh = &mesh;
    f.points = p;
    f.faces = faces;
    f.cell = cell;
    f.width = W;
    f.height = H;
    f.layout = pages ? STP_BAND_PAGES : STP_BAND_ROWS;
    for (y0 = 0; y0 < H; y0 += band_rows) {
        int rows = H - y0 < band_rows ? H - y0 : band_rows;
        size_t stride = pages ? W : STRIDE;
        memset(band, 0xA5, sizeof band);
        assert_int_equal(stp_direct_draw_band(&f, band, stride, (uint16_t)y0, (uint16_t)rows), STP_OK);
        for (y = 0; y < rows; y++)
            for (x = 0; x < W; x++)
                out[y0 + y][x] = pages ? (uint8_t)((band[(size_t)(y / 8) * stride + (size_t)x] >> (y % 8)) & 1)
                                       : (uint8_t)((band[(size_t)y * stride + (size_t)(x / 8)] >> (7 - x % 8)) & 1);
    }
}

static void check_triangles(int band_rows, int pages, uint32_t seed, int count)
{
    static uint8_t got[H][W];
    int k, x, y, drawn = 0;
    for (k = 0; k < count; k++) {
        stp_direct_point p[3];
        random_triangle(&seed, p);
        draw(p, band_rows, pages, got);
        for (y = 0; y < H; y++)
            for (x = 0; x < W; x++) {
                int want = covered(p, x, y);
                if (got[y][x] != want)
                    fail_msg("triangle %d (%d,%d) (%d,%d) (%d,%d), %d-row bands%s: pixel (%d, %d) is %d, the rule "
                             "says %d",
                             k, p[0].dx, p[0].dy, p[1].dx, p[1].dy, p[2].dx, p[2].dy, band_rows,
                             pages ? " in pages" : "", x, y, got[y][x], want);
                drawn += want;
            }
    }
    assert_true(drawn > count * 20); /* the triangles do reach the panel */
}

static void test_rows_whole(void **state)
{
    (void)state;
    check_triangles(H, 0, 0x1234567u, 3000);
}

static void test_rows_bands(void **state)
{
    (void)state;
    check_triangles(1, 0, 0xBEEF01u, 600);
    check_triangles(5, 0, 0xBEEF02u, 600);
}

static void test_pages(void **state)
{
    (void)state;
    check_triangles(8, 1, 0xC0FFEEu, 1500);
    check_triangles(H, 1, 0xC0FFEFu, 600);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_rows_whole),
        cmocka_unit_test(test_rows_bands),
        cmocka_unit_test(test_pages),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
