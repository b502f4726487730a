/* SPDX-License-Identifier: MIT */
/*
 * The one 1-bit run filler (src/run_fill_private.h), stp_halftone_fill_bits,
 * against a pixel-at-a-time reference: every run x1..x2 of a 48-pixel line,
 * in both band layouts (rows, MSB first; pages, one bit a byte), for
 * all-OFF, all-ON and mixed patterns, over a line of random bytes whose
 * bits outside the run must survive.  Built twice (tests/core/CMakeLists.txt):
 * with the build's flags (head, whole bytes, tail) and with -Os (the size
 * form: one loop of masked stores), which EXPECT_SIZE makes this file check
 * it got.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "run_fill_private.h"

#if defined(EXPECT_SIZE) && !defined(__OPTIMIZE_SIZE__)
#error "test_run_fill_size is built without -Os"
#endif

#define WIDTH 48

static uint32_t seed = 12345u;

static uint8_t random_byte(void)
{
    seed = seed * 1103515245u + 12345u;
    return (uint8_t)(seed >> 16);
}

/* pixel x of a row line (page_bit 0) or of a page line (its bit) set to
 * the pattern's bit 7 - (x mod 8) */
static void reference_fill(uint8_t *line, uint8_t page_bit, unsigned x1, unsigned x2, uint8_t pattern)
{
    unsigned x;
    for (x = x1; x <= x2; x++) {
        int on = (pattern >> (7u - (x & 7u))) & 1;
        unsigned i = page_bit ? x : x >> 3;
        uint8_t bit = (uint8_t)(page_bit ? page_bit : 0x80u >> (x & 7u));
        line[i] = (uint8_t)(on ? line[i] | bit : line[i] & ~bit);
    }
}

static void check_layout(uint8_t page_bit)
{
    static const uint8_t patterns[] = {0x00u, 0xFFu, 0xA5u, 0x01u, 0x80u, 0x3Cu};
    uint8_t line[WIDTH], expected[WIDTH];
    unsigned x1, x2, k;
    for (k = 0; k < sizeof patterns; k++)
        for (x1 = 0; x1 < WIDTH; x1++)
            for (x2 = x1; x2 < WIDTH; x2++) {
                unsigned i;
                for (i = 0; i < WIDTH; i++)
                    line[i] = expected[i] = random_byte();
                stp_halftone_fill_bits(line, page_bit, x1, x2, patterns[k]);
                reference_fill(expected, page_bit, x1, x2, patterns[k]);
                assert_memory_equal(line, expected, WIDTH);
            }
}

static void test_rows(void **state)
{
    (void)state;
    check_layout(0);
}

static void test_pages(void **state)
{
    uint8_t page_bit;
    (void)state;
    for (page_bit = 1; page_bit != 0; page_bit = (uint8_t)(page_bit << 1))
        check_layout(page_bit);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_rows),
        cmocka_unit_test(test_pages),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
