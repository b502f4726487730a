/* SPDX-License-Identifier: MIT */
/* The raster's arithmetic for targets without wide arithmetic (ARMv6-M,
 * RV32, AVR), compiled here on the host with STP_WIDE_ARITH 0: the 32 x
 * 32-bit products from 16-bit halves (with their one- and two-product
 * shortcuts) and the slopes of short edges from the reciprocal table,
 * against the host's own 64-bit operators. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#define STP_WIDE_ARITH 0
#include "raster_private.h"

/* xorshift: the same sequence every run */
static uint32_t next_random(uint32_t *s)
{
    *s ^= *s << 13;
    *s ^= *s >> 17;
    *s ^= *s << 5;
    return *s;
}

static void check_products(uint32_t a, uint32_t b)
{
    uint64_t want = (uint64_t)a * b;
    int64_t swant = (int64_t)(int32_t)a * (int32_t)b;
    if (stp_umul32(a, b) != want)
        fail_msg("stp_umul32(%u, %u) = %llu, want %llu", a, b, (unsigned long long)stp_umul32(a, b),
                 (unsigned long long)want);
    if (stp_smul32((int32_t)a, (int32_t)b) != swant)
        fail_msg("stp_smul32(%d, %d) = %lld, want %lld", (int32_t)a, (int32_t)b,
                 (long long)stp_smul32((int32_t)a, (int32_t)b), (long long)swant);
}

static void test_products_against_64_bit(void **state)
{
    static const uint32_t edges[] = {0, 1, 2, 0xFFFF, 0x10000, 0x10001, 0x7FFF, 0x8000, 0x1FFFF,
                                     0x7FFFFFFF, 0x80000000u, 0xFFFFFFFFu, 0xFFFF0000u, 0x0000FFFFu,
                                     12345, 0xABCDEF, 0x80000001u, 0xFFFF8000u};
    size_t i, j;
    uint32_t s = 2463534242u;
    int k;
    (void)state;
    for (i = 0; i < sizeof edges / sizeof edges[0]; i++)
        for (j = 0; j < sizeof edges / sizeof edges[0]; j++)
            check_products(edges[i], edges[j]);
    for (k = 0; k < 200000; k++) {
        uint32_t a = next_random(&s), b = next_random(&s);
        /* every size class: both, one or neither factor below 2^16 */
        a >>= (k & 3) * 8;
        b >>= ((k >> 2) & 3) * 8;
        check_products(a, b);
        check_products(0u - a, b);
    }
}

/* stp_slope_q16 is trunc(2^16 num / den) for den > 0, |num| < 2^21 */
static void check_slope(int32_t num, int32_t den)
{
    int64_t want = ((int64_t)num * 65536) / den, got = stp_slope_q16(num, den);
    if (got != want)
        fail_msg("stp_slope_q16(%d, %d) = %lld, want %lld", num, den, (long long)got, (long long)want);
}

static void test_slopes_against_division(void **state)
{
    int32_t num, den;
    uint32_t s = 88172645u;
    int k;
    (void)state;
    assert_int_equal(STP_SLOPE_RECIP, 128); /* the table path is the one tested */
    /* every short edge the table serves, and its neighbours that divide */
    for (den = 1; den < 200; den++)
        for (num = -1200; num <= 1200; num++)
            check_slope(num, den);
    for (k = 0; k < 200000; k++) {
        int32_t n = (int32_t)(next_random(&s) % (1u << 22)) - (1 << 21) + 1;
        int32_t d = (int32_t)(next_random(&s) % ((k & 1) ? 128u : (1u << 21))) + 1;
        check_slope(n >> (k % 21), d);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_products_against_64_bit),
        cmocka_unit_test(test_slopes_against_division),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
