/* SPDX-License-Identifier: MIT */
/*
 * Drawing into a u8g2 page buffer (ports/arduino/src/stipple_u8g2.c: page
 * layout bands, STP_BAND_PAGES) and the page packer of span pictures
 * (ports/controllers/panel.c stp_panel_pack_block), against u8g2's documented
 * buffer layout for the SSD1306 family (u8g2_ll_hvline_vertical_top_lsb):
 * pixel (x, y) of tile row t = y / 8 is bit y % 8 of byte
 * (t - first tile row) * width + x.  The picture is the spinning cube of
 * the Arduino examples, drawn in one band of 64 rows as MONO1 (pixel x of
 * a row in bit 7 - x % 8) for the reference; the u8g2 buffer is filled in
 * page mode (1 and 2 tile rows, every page in turn) and full-buffer mode
 * (8), over earlier content that must stay (u8g2 draws are OR'ed).  Also
 * the examples' view kept as data against stp_direct_view_look.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include "stipple/render.h"
#include "stipple_spin.h"
#include "stipple_u8g2.h"
#include "stp_panel.h"

#include "../../ports/arduino/examples/SpinningCube/cube_mesh.h"

#define W 128u
#define H 64u
#define STRIDE (W / 8u)

static int mono_bit(const uint8_t *mono, unsigned x, unsigned y)
{
    return (mono[y * STRIDE + x / 8u] >> (7u - x % 8u)) & 1u;
}

/* the frame n of the cube, and its rows as the reference */
static void cube_frame(stipple_spin *spin, stp_direct_point *points, uint16_t *faces, uint16_t n,
                       uint8_t *mono)
{
    assert_int_equal(stipple_spin_begin(spin, &cube_mesh, points, faces), STP_OK);
    assert_int_equal(stipple_spin_frame(spin, n), STP_OK);
    assert_int_equal(stp_direct_draw_band(&spin->frame, mono, STRIDE, 0, H), STP_OK);
}

/* earlier content: a pattern u8g2 might have drawn (a frame line) */
static int earlier(unsigned x, unsigned y)
{
    return y == 0 || x == 0 || (x + y) % 29u == 0;
}

static void check_tile_rows(unsigned tile_rows)
{
    static stp_direct_point points[CUBE_VERTEX_COUNT];
    static uint16_t faces[CUBE_TRIANGLE_COUNT];
    uint8_t mono[H * STRIDE], buffer[8 * W], scratch[W];
    stipple_spin spin;
    uint16_t n;
    unsigned first, x, y, lit = 0;
    for (n = 0; n < 16; n += 5) {
        cube_frame(&spin, points, faces, n, mono);
        for (first = 0; first < H / 8u; first += tile_rows) {
            memset(buffer, 0, sizeof buffer);
            for (y = 8u * first; y < 8u * (first + tile_rows); y++)
                for (x = 0; x < W; x++)
                    if (earlier(x, y))
                        buffer[(y / 8u - first) * W + x] |= (uint8_t)(1u << (y % 8u));
            assert_int_equal(stipple_u8g2_draw(&spin.frame, buffer, (uint8_t)tile_rows, (uint8_t)first,
                                               scratch),
                             STP_OK);
            for (y = 8u * first; y < 8u * (first + tile_rows); y++)
                for (x = 0; x < W; x++) {
                    int got = (buffer[(y / 8u - first) * W + x] >> (y % 8u)) & 1u;
                    int want = mono_bit(mono, x, y) | earlier(x, y);
                    if (got != want)
                        fail_msg("frame %u, %u tile rows from %u: pixel (%u, %u) is %d, want %d", n,
                                 tile_rows, first, x, y, got, want);
                    lit += (unsigned)mono_bit(mono, x, y);
                }
        }
    }
    assert_true(lit > 1000u); /* the cube is there */
}

static void test_page_mode_one_tile_row(void **state)
{
    (void)state;
    check_tile_rows(1);
}

static void test_page_mode_two_tile_rows(void **state)
{
    (void)state;
    check_tile_rows(2);
}

static void test_full_buffer(void **state)
{
    (void)state;
    check_tile_rows(8);
}

/* every 8x8 block of random rows, against the bit-by-bit layout */
static void test_pack_block(void **state)
{
    uint8_t rows[8 * 3], out[8];
    uint32_t seed = 12345u;
    unsigned t, r, c;
    (void)state;
    for (t = 0; t < 2000u; t++) {
        for (r = 0; r < sizeof rows; r++) {
            seed = seed * 1103515245u + 12345u;
            rows[r] = (uint8_t)(t % 7u == 0 ? 0u : seed >> 24);
        }
        stp_panel_pack_block(rows + 1, 3, out);
        for (c = 0; c < 8u; c++)
            for (r = 0; r < 8u; r++)
                assert_int_equal((out[c] >> r) & 1u, (rows[1 + 3u * r] >> (7u - c)) & 1u);
    }
}

/* The examples' view, kept as data (stipple_spin.h), is the one
 * stp_direct_view_look makes today. */
static int32_t vec3_component(const stp_vec3 *v, int i)
{
    return i == 0 ? v->x : (i == 1 ? v->y : v->z);
}

static void test_spin_view(void **state)
{
    static stp_direct_point points[CUBE_VERTEX_COUNT];
    static uint16_t faces[CUBE_TRIANGLE_COUNT];
    const stp_direct_view kept = STIPPLE_SPIN_VIEW;
    stp_direct_view v;
    stp_vec3 from = {0, STP_FIX_ONE, 27 * STP_FIX_ONE / 8}, at = {0, 0, 0}, up = {0, STP_FIX_ONE, 0};
    stipple_spin spin;
    int i, j;
    (void)state;
    assert_int_equal(stp_direct_view_look(&v, from, at, up, 6651316, 6554, W, H), STP_OK);
    assert_int_equal(stipple_spin_begin(&spin, &cube_mesh, points, faces), STP_OK);
    assert_int_equal(spin.view.from.x, v.from.x);
    assert_int_equal(spin.view.from.y, v.from.y);
    assert_int_equal(spin.view.from.z, v.from.z);
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) {
            assert_int_equal(vec3_component(&spin.view.axis[i], j), vec3_component(&v.axis[i], j));
            assert_int_equal(vec3_component(&kept.axis[i], j), vec3_component(&v.axis[i], j));
        }
    assert_int_equal(spin.view.focal, v.focal);
    assert_int_equal(spin.view.hither, v.hither);
    assert_int_equal(spin.view.width, v.width);
    assert_int_equal(spin.view.height, v.height);
}

static void test_bad_arguments(void **state)
{
    uint8_t buffer[W], scratch[W];
    stp_direct_frame f;
    (void)state;
    memset(&f, 0, sizeof f);
    f.width = W;
    f.height = H;
    assert_int_equal(stipple_u8g2_draw(0, buffer, 1, 0, scratch), STP_ERR_ARG);
    assert_int_equal(stipple_u8g2_draw(&f, 0, 1, 0, scratch), STP_ERR_ARG);
    assert_int_equal(stipple_u8g2_draw(&f, buffer, 0, 0, scratch), STP_ERR_ARG);
    assert_int_equal(stipple_u8g2_draw(&f, buffer, 1, 0, 0), STP_ERR_ARG);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_page_mode_one_tile_row),
        cmocka_unit_test(test_page_mode_two_tile_rows),
        cmocka_unit_test(test_full_buffer),
        cmocka_unit_test(test_pack_block),
        cmocka_unit_test(test_spin_view),
        cmocka_unit_test(test_bad_arguments),
    };
    return cmocka_run_group_tests(tests, 0, 0);
}
