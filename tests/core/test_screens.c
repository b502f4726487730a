/* SPDX-License-Identifier: MIT */
/*
 * Screens beyond the 2/4/8 Bayer cells (include/stipple/dither.h): Bayer
 * 16x16, the blue-noise mask, clustered-dot cells at 0 and 45 degrees and
 * mask cells larger than 16x16; checked by the properties that define
 * them (every rank once, cells worked out by hand, the growth of the dots)
 * and through HALFTONE-FILLIN.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "stipple/dither.h"

/* Threshold of rank r of m under linear spacing. */
static int linear(int r, int m)
{
    return (255 * (r + 1) + m) / (m + 1) - 1;
}

/* Every rank 0..m-1 once: the sorted thresholds are linear(0..m-1). */
static void check_ranks(const uint8_t *t, int m)
{
    static int count[256];
    int i, r = 0, v;
    memset(count, 0, sizeof count);
    for (i = 0; i < m; i++)
        count[t[i]]++;
    for (v = 0; v < 256; v++)
        while (count[v]-- > 0) {
            if (linear(r, m) != v)
                fail_msg("rank %d has threshold %d, expected %d", r, v, linear(r, m));
            r++;
        }
    assert_int_equal(r, m);
}

static void test_bayer16(void **state)
{
    stp_cell cell;
    int x, y;
    (void)state;
    assert_int_equal(stp_cell_bayer(&cell, 16), 0);
    assert_int_equal(cell.width, 16);
    check_ranks(cell.thresholds, 256);
    /* the recursive construction: B16 = 4 B8' + B2 of the quadrant, with B8'
     * the untransposed 8x8: so the top-left entry is rank 0 and (8, 8) is
     * rank 1 (B2 = [[0, 2], [3, 1]] at the coarsest level) */
    assert_int_equal(cell.thresholds[0], linear(0, 256));
    assert_int_equal(cell.thresholds[8 * 16 + 8], linear(1, 256));
    assert_int_equal(cell.thresholds[8], linear(2, 256));
    assert_int_equal(cell.thresholds[8 * 16], linear(3, 256));
    /* the finest level is the 2x2 Bayer: (1, 1) is rank 64, (1, 0) 128,
     * (0, 1) 192 */
    assert_int_equal(cell.thresholds[1 * 16 + 1], linear(64, 256));
    assert_int_equal(cell.thresholds[1], linear(128, 256));
    assert_int_equal(cell.thresholds[16], linear(192, 256));
    /* at grey 128, the ranks with ceil(255 (r+1) / 257) - 1 < 128, that is
     * r <= 128: 129 pixels ON */
    {
        int on = 0;
        for (y = 0; y < 16; y++)
            for (x = 0; x < 16; x++)
                on += stp_cell_on(&cell, (uint32_t)x, (uint32_t)y, 128);
        assert_int_equal(on, 129);
    }
}

static void test_blue_noise(void **state)
{
    stp_cell cell;
    uint8_t row[8];
    int x, y, on, level;
    (void)state;
    stp_cell_blue_noise(&cell);
    assert_int_equal(cell.width, 64);
    assert_int_equal(cell.height, 64);
    assert_ptr_equal(cell.mask, stp_cell_blue_noise_64);
    check_ranks(stp_cell_blue_noise_64, 4096);
    /* grey g turns on about g/255 of the pixels (linear spacing: exactly
     * the ranks below 4097 g / 255) and, being blue noise, spreads them:
     * at 1/16 grey no two ON pixels touch (8 neighbours, toroidally) */
    for (level = 0; level <= 255; level += 51) {
        on = 0;
        for (y = 0; y < 64; y++)
            for (x = 0; x < 64; x++)
                on += stp_cell_on(&cell, (uint32_t)x, (uint32_t)y, (uint8_t)level);
        assert_true(on >= 4096 * level / 255 - 16 && on <= 4096 * level / 255 + 16);
    }
    for (y = 0; y < 64; y++)
        for (x = 0; x < 64; x++) {
            int dx, dy;
            if (!stp_cell_on(&cell, (uint32_t)x, (uint32_t)y, 16))
                continue;
            for (dy = -1; dy <= 1; dy++)
                for (dx = -1; dx <= 1; dx++)
                    if ((dx || dy) && stp_cell_on(&cell, (uint32_t)((x + dx + 64) % 64),
                                                  (uint32_t)((y + dy + 64) % 64), 16))
                        fail_msg("ON pixels touch at (%d, %d) at grey 16", x, y);
        }
    /* HALFTONE-FILLIN over a mask: the span's bits are stp_cell_on's */
    memset(row, 0xA5, sizeof row);
    stp_halftone_fillin(row, 3, 60, 70, &cell, 100);
    for (x = 0; x < 64; x++) {
        int bit = (row[x >> 3] >> (7 - (x & 7))) & 1;
        int expect = (x < 3 || x > 60) ? ((0xA5 >> (7 - (x & 7))) & 1)
                                       : stp_cell_on(&cell, (uint32_t)x, 70, 100);
        assert_int_equal(bit, expect);
    }
}

static void test_mask_cells(void **state)
{
    static uint8_t big[40 * 20];
    stp_cell cell, before;
    int i;
    (void)state;
    for (i = 0; i < 40 * 20; i++)
        big[i] = (uint8_t)(i % 251);
    assert_int_equal(stp_cell_mask(&cell, 40, 20, big), 0);
    assert_int_equal(stp_cell_on(&cell, 39, 19, 249), 249 > big[19 * 40 + 39]);
    assert_int_equal(stp_cell_on(&cell, 41, 21, 2), 2 > big[1 * 40 + 1]);
    memset(&before, 0x11, sizeof before);
    cell = before;
    assert_int_equal(stp_cell_mask(&cell, 256, 20, big), -1);
    assert_int_equal(stp_cell_mask(&cell, 0, 20, big), -1);
    assert_int_equal(stp_cell_mask(&cell, 4, 4, NULL), -1);
    assert_memory_equal(&cell, &before, sizeof cell);
}

/* 0 degrees, 4x4 by hand: pixel centres in half pixels (1, 3, 5, 7), the
 * dot at (4, 4), the hole at the corners (0/8, 0/8).  Squared distances to
 * the dot: the middle four 2, the edge-middles 10, the corners 18; to the
 * hole: corners 2, edge-middles 10, middle 18.  So the middle four grow
 * first (ranks 0-3 in reading order), then the eight edge-middles (dot
 * side, ties with the hole go to the dot: ranks 4-11), then the corners
 * (ranks 12-15). */
static void test_clustered_by_hand(void **state)
{
    static const int ranks[16] = {12, 4, 5, 13, 6, 0, 1, 7, 8, 2, 3, 9, 14, 10, 11, 15};
    stp_cell cell;
    int i;
    (void)state;
    assert_int_equal(stp_cell_clustered(&cell, 4, 0), 0);
    for (i = 0; i < 16; i++)
        assert_int_equal(cell.thresholds[i], linear(ranks[i], 16));
}

/* Dots grow connected: for every size and both angles, every rank is a
 * neighbour (8-connected, toroidally) of an earlier one or a dot's first
 * pixel; ranks are all there; 45 degrees has two first pixels. */
static void test_clustered_grow_connected(void **state)
{
    int n, angle;
    (void)state;
    for (angle = 0; angle <= 45; angle += 45)
        for (n = angle ? 4 : 2; n <= 16; n += angle ? 2 : 1) {
            stp_cell cell;
            int x, y, seeds = 0;
            assert_int_equal(stp_cell_clustered(&cell, n, angle), 0);
            check_ranks(cell.thresholds, n * n);
            for (y = 0; y < n; y++)
                for (x = 0; x < n; x++) {
                    int t = cell.thresholds[y * n + x], dx, dy, joined = 0;
                    for (dy = -1; dy <= 1; dy++)
                        for (dx = -1; dx <= 1; dx++)
                            if ((dx || dy) && cell.thresholds[((y + dy + n) % n) * n + (x + dx + n) % n] < t)
                                joined = 1;
                    seeds += !joined;
                }
            if (seeds > (angle ? 2 : 1))
                fail_msg("clustered %d at %d degrees: %d dots start", n, angle, seeds);
        }
    {
        stp_cell cell;
        assert_int_equal(stp_cell_clustered(&cell, 6, 45), 0);
        assert_int_equal(stp_cell_clustered(&cell, 5, 45), -1);
        assert_int_equal(stp_cell_clustered(&cell, 17, 0), -1);
        assert_int_equal(stp_cell_clustered(&cell, 8, 30), -1);
        assert_int_equal(stp_cell_clustered(NULL, 8, 0), -1);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_bayer16),          cmocka_unit_test(test_blue_noise),
        cmocka_unit_test(test_mask_cells),       cmocka_unit_test(test_clustered_by_hand),
        cmocka_unit_test(test_clustered_grow_connected),
    };
    return cmocka_run_group_tests(tests, 0, 0);
}
