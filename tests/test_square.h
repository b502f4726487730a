/* SPDX-License-Identifier: MIT */
/*
 * Shared by the tests of a core built without a feature (test_edge_aa_off,
 * test_pages_off): a 16 x 8 renderer holding one white square under a
 * parallel view of one world unit per pixel (world x = 8 - device x), and
 * the frame memory of one 8-row band with its Z buffer, and a flush that
 * keeps what it is sent.  Include after
 * <cmocka.h>.
 */
#ifndef STIPPLE_TESTS_TEST_SQUARE_H
#define STIPPLE_TESTS_TEST_SQUARE_H

#include <string.h>

#include "stipple/stipple.h"

#define STP_TEST_SQUARE_W 16
#define STP_TEST_SQUARE_H 8

/* The renderer in storage and df (64 entries), levels and fill 256, with
 * the square from world x = 8 to left_x (device x 0 to 8 - left_x), all
 * rows; fails the test on any error. */
static inline stp_renderer *stp_test_square(stp_renderer_storage *storage, stp_instr *df, stp_fix left_x)
{
    stp_renderer *r = stp_renderer_create(storage, sizeof *storage, df, 64, STP_TEST_SQUARE_W, STP_TEST_SQUARE_H);
    stp_view v;
    stp_vec3 sq[4];
    assert_non_null(r);
    memset(&v, 0, sizeof v);
    v.from.z = -10 * STP_FIX_ONE;
    v.up.y = STP_FIX_ONE;
    v.window_half = 4 * STP_FIX_ONE; /* one unit per pixel */
    v.hither = STP_FIX_ONE;
    v.fov_degrees = 90 * STP_FIX_ONE;
    v.projection = STP_PARALLEL;
    assert_int_equal(stp_renderer_set_view(r, &v), STP_OK);
    assert_int_equal(stp_renderer_set_levels(r, 256), STP_OK);
    assert_int_equal(stp_renderer_set_fill_style(r, 256), STP_OK);
    memset(sq, 0, sizeof sq);
    sq[0].x = 8 * STP_FIX_ONE, sq[0].y = 4 * STP_FIX_ONE;
    sq[1].x = left_x, sq[1].y = 4 * STP_FIX_ONE;
    sq[2].x = left_x, sq[2].y = -4 * STP_FIX_ONE;
    sq[3].x = 8 * STP_FIX_ONE, sq[3].y = -4 * STP_FIX_ONE;
    assert_int_equal(stp_renderer_polygon(r, sq, 4), STP_OK);
    return r;
}

/* What a port's flushes sent (port->user): each row's first 16 bytes (or
 * its stride, when shorter) at row y of frame, and the number of flushes. */
typedef struct stp_test_capture {
    uint8_t frame[STP_TEST_SQUARE_W * STP_TEST_SQUARE_H];
    int flushes;
} stp_test_capture;

static inline int stp_test_capture_flush(stp_port *port, uint32_t y0, uint32_t rows, const uint8_t *pixels,
                                         size_t stride)
{
    stp_test_capture *c = port->user;
    size_t n = stride < STP_TEST_SQUARE_W ? stride : STP_TEST_SQUARE_W;
    uint32_t y;
    c->flushes++;
    for (y = 0; y < rows; y++)
        memcpy(c->frame + (size_t)(y0 + y) * STP_TEST_SQUARE_W, pixels + (size_t)y * stride, n);
    return 0;
}

/* A 16 x 8 port of format whose flushes got keeps (emptied here). */
static inline void stp_test_capture_port(stp_port *port, stp_pixel_format format, stp_test_capture *got)
{
    memset(got, 0, sizeof *got);
    memset(port, 0, sizeof *port);
    port->width = STP_TEST_SQUARE_W;
    port->height = STP_TEST_SQUARE_H;
    port->format = format;
    port->flush = stp_test_capture_flush;
    port->user = got;
}

/* One band of all 8 rows: band (16 x 8 bytes) and zbuf (16 x 8 entries). */
static inline void stp_test_square_memory(stp_frame_memory *mem, uint8_t *band, uint16_t *zbuf)
{
    memset(mem, 0, sizeof *mem);
    mem->band = band;
    mem->band_size = STP_TEST_SQUARE_W * STP_TEST_SQUARE_H;
    mem->band_rows = STP_TEST_SQUARE_H;
    mem->zbuf = zbuf;
    mem->zbuf_count = STP_TEST_SQUARE_W * STP_TEST_SQUARE_H;
}

#endif
