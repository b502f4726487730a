/* SPDX-License-Identifier: MIT */
/* The raster's arithmetic for targets without wide arithmetic (ARMv6-M,
 * RV32, AVR), compiled here on the host with STP_WIDE_ARITH 0: the 32 x
 * 32-bit products from 16-bit halves (with their one- and two-product
 * shortcuts), the slopes of short edges from the reciprocal table, the
 * Q12 quotients through one reciprocal and the division by 3 (arith_private.h)
 * from 32-bit products, against the host's own 64-bit operators. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#define STP_WIDE_ARITH 0
#include "edge_walk_private.h"

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
    if (stp_umul32x32(a, b) != want)
        fail_msg("stp_umul32x32(%u, %u) = %llu, want %llu", a, b, (unsigned long long)stp_umul32x32(a, b),
                 (unsigned long long)want);
    if (stp_smul32x32((int32_t)a, (int32_t)b) != swant)
        fail_msg("stp_smul32x32(%d, %d) = %lld, want %lld", (int32_t)a, (int32_t)b,
                 (long long)stp_smul32x32((int32_t)a, (int32_t)b), (long long)swant);
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

/* stp_slope_q16_short: stp_slope_q16 for |num| < 2^15 (a narrow triangle's
 * edges), every numerator against every short denominator the table
 * serves and random longer ones */
static void test_short_slopes_against_division(void **state)
{
    int32_t num, den;
    uint32_t s = 521288629u;
    int k;
    (void)state;
    /* STP_SLOPE_RECIP_FITS: un < m / 2^16 gives un den < 2^16 */
    for (den = 2; den < STP_SLOPE_RECIP; den++)
        assert_true((stp_slope_recip[den] >> 16) * (uint32_t)den <= 65536u);
    for (den = 1; den < 160; den++)
        for (num = -(1 << 15) + 1; num < (1 << 15); num++) {
            int64_t want = ((int64_t)num * 65536) / den;
            if (stp_slope_q16_short(num, den) != want)
                fail_msg("stp_slope_q16_short(%d, %d) = %d, want %lld", num, den, stp_slope_q16_short(num, den),
                         (long long)want);
        }
    for (k = 0; k < 200000; k++) {
        int32_t n = (int32_t)(next_random(&s) % ((1u << 16) - 1u)) - (1 << 15) + 1; /* |n| < 2^15 */
        int32_t d = (int32_t)(next_random(&s) % (1u << (k % 21 + 1))) + 1;
        assert_true(stp_slope_q16_short(n, d) == ((int64_t)n * 65536) / d);
    }
}

static void check_recip_quotient(uint32_t a, uint32_t d)
{
    uint32_t got = stp_quotient_q12_by_recip(a << 12, d, 0xFFFFFFFFu / d), want = (a << 12) / d;
    if (got != want)
        fail_msg("stp_quotient_q12_by_recip(%u, %u) = %u, want %u", a, d, got, want);
}

/* stp_umulhi32 against the 64-bit product; stp_quotient_q12_by_recip (a <
 * 2^19, 2 <= d < 2^31: every a for divisors at the edges of the range and
 * of its products' parts, the quotient's steps for every small d, random
 * ones of every size) and stp_div3_u32 (s < 2^30) against C's division */
static void test_reciprocal_quotients_against_division(void **state)
{
    static const uint32_t big[] = {0x7FFFFFFFu, 0x7FFFFFFEu, 0x40000000u, 0x3FFFFFFFu, 0x10000u, 0xFFFFu, 0x1FFFFu};
    static const uint32_t edge_d[] = {2u, 3u, 5u, 7u, 4095u, 4096u, 4097u, 0xFFFFu, 0x10000u, 0x10001u,
                                      0xFFFFFu, 0x100000u, 0x100001u, 0x7FFFFFFu, 0x8000001u, 0x3FFFFFFFu,
                                      0x40000000u, 0x7FFFFFFEu, 0x7FFFFFFFu};
    uint32_t s = 3141592653u, n, d;
    size_t i, j;
    int k;
    (void)state;
    for (i = 0; i < sizeof big / sizeof big[0]; i++)
        for (j = 0; j < sizeof big / sizeof big[0]; j++) {
            check_recip_quotient(big[i] & 0x7FFFFu, big[j]);
            check_recip_quotient(big[i] >> 12, big[j]);
            assert_true(stp_umulhi32x32(big[i], big[j] << 1) == (uint32_t)(((uint64_t)big[i] * (big[j] << 1)) >> 32));
        }
    for (i = 0; i < sizeof edge_d / sizeof edge_d[0]; i++)
        for (n = 0; n < (1u << 19); n++)
            check_recip_quotient(n, edge_d[i]);
    for (d = 2; d < 3000; d++) {
        check_recip_quotient(0x7FFFFu, d);
        /* a 2^12 just below and at each multiple of d the quotient reaches */
        for (n = 1; n < 64; n++) {
            uint32_t a = (n * d + 4095u) >> 12;
            check_recip_quotient(a, d);
            check_recip_quotient(a - 1u, d);
            check_recip_quotient(0x7FFFFu - n, d);
        }
        for (n = 0; n < 600; n++)
            check_recip_quotient(n, d);
    }
    for (k = 0; k < 1000000; k++) {
        uint32_t a = next_random(&s), b = next_random(&s);
        assert_true(stp_umulhi32x32(a, b) == (uint32_t)(((uint64_t)a * b) >> 32));
        n = (a & 0x7FFFFu) >> (k % 19);
        d = (b >> 1 >> ((k >> 5) % 30)) | 2u;
        check_recip_quotient(n, d);
        assert_true(stp_div3_u32(a >> 2) == (a >> 2) / 3u);
    }
    for (n = 0; n < (1u << 20); n++)
        assert_true(stp_div3_u32(n) == n / 3u && stp_div3_u32(0x3FFFFFFFu - n) == (0x3FFFFFFFu - n) / 3u);
}

/* stp_div3_u32 over the whole 32-bit range (its three forms meet at 2^16
 * and 2^30) and stp_div3_toward_zero against C's signed division */
static void test_division_by_3_against_division(void **state)
{
    static const uint32_t edge[] = {0xFFFFu, 0x10000u, 0x3FFFFFFFu, 0x40000000u, 0x7FFFFFFFu, 0x80000000u,
                                    0xFFFFFFFEu, 0xFFFFFFFFu};
    uint32_t s = 2718281828u, u;
    size_t i;
    int k, d;
    (void)state;
    for (i = 0; i < sizeof edge / sizeof edge[0]; i++)
        for (d = -3; d <= 3; d++) {
            u = edge[i] + (uint32_t)d;
            assert_int_equal(stp_div3_u32(u), u / 3u);
            assert_int_equal(stp_div3_toward_zero((int32_t)u), (int32_t)u == INT32_MIN ? INT32_MIN / 3
                                                                                       : (int32_t)u / 3);
        }
    for (k = 0; k < 1000000; k++) {
        u = next_random(&s) >> (k % 32);
        assert_int_equal(stp_div3_u32(u), u / 3u);
        assert_int_equal(stp_div3_toward_zero((int32_t)u), (int32_t)u / 3);
        assert_int_equal(stp_div3_toward_zero(-(int32_t)(u >> 1)), -(int32_t)(u >> 1) / 3);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_products_against_64_bit),
        cmocka_unit_test(test_slopes_against_division),
        cmocka_unit_test(test_short_slopes_against_division),
        cmocka_unit_test(test_reciprocal_quotients_against_division),
        cmocka_unit_test(test_division_by_3_against_division),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
