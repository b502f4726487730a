/* SPDX-License-Identifier: MIT */
/* The division-free reciprocal and 64-bit division (src/recip.c): the
 * reciprocal against a double-precision reference and the exact floor over
 * its whole input range [2^31, 2^32) (every seed interval's ends, a sweep
 * and random values), the division against C's operator over every pair of
 * operand lengths, signs and extremes.  Built twice: as the host compiles
 * it, and with STP_WIDE_ARITH=0 (the products from 16-bit halves that
 * 32-bit targets use). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <cmocka.h>

#include "recip_private.h"

static uint64_t rng_state = 0x9E3779B97F4A7C15u;

static uint64_t next_random(void)
{
    /* xorshift64* */
    rng_state ^= rng_state >> 12;
    rng_state ^= rng_state << 25;
    rng_state ^= rng_state >> 27;
    return rng_state * 0x2545F4914F6CDD1Du;
}

static double worst_relative = 0.0;

static void check_recip(uint32_t m)
{
    uint32_t got = stp_recip32(m);
    uint64_t want = UINT64_MAX / m - ((uint64_t)1 << 32);
#if STP_HAVE_MUL32
    /* the estimate the projection corrects itself: the floor or up to 2
     * below it */
    uint32_t estimate = stp_recip32_estimate(m);
    if (estimate > want || want - estimate > 2u)
        fail_msg("stp_recip32_estimate(%lu) = %lu, the floor %llu", (unsigned long)m, (unsigned long)estimate,
                 (unsigned long long)want);
#endif
    /* against double: (2^32 + r) 2^-64 approximates 1/m */
    double rel = ((4294967296.0 + (double)got) / 18446744073709551616.0 - 1.0 / (double)m) * (double)m;
    if (rel < 0)
        rel = -rel;
    if (rel > worst_relative)
        worst_relative = rel;
    if (got != want)
        fail_msg("stp_recip32(%lu) = %lu, floor((2^64 - 1) / m) - 2^32 = %llu", (unsigned long)m,
                 (unsigned long)got, (unsigned long long)want);
}

static void test_recip_whole_range(void **state)
{
    uint32_t i, m;
    (void)state;
    worst_relative = 0.0;
    /* the ends of every seed interval and their neighbours */
    for (i = 0; i < 128; i++) {
        uint32_t lo = 0x80000000u + (i << 24), hi = lo + 0xFFFFFFu;
        check_recip(lo);
        check_recip(lo + 1);
        check_recip(hi);
        check_recip(hi - 1);
        check_recip(lo + 0x800000u);
    }
    check_recip(0xFFFFFFFFu);
    /* a sweep with an odd step through the whole range */
    for (m = 0x80000000u; m >= 0x80000000u && m <= 0xFFFFFFFFu - 2047u; m += 2047u)
        check_recip(m);
    for (i = 0; i < 1000000u; i++)
        check_recip((uint32_t)(next_random() >> 32) | 0x80000000u);
    /* exact floors are within one unit of 2^-32 relative */
    printf("stp_recip32: worst relative error against double %.3g (2^-32 = %.3g)\n", worst_relative,
           1.0 / 4294967296.0);
    assert_true(worst_relative <= 1.0 / 4294967296.0);
    /* outside the range: 0 */
    assert_int_equal(stp_recip32(0x7FFFFFFFu), 0);
    assert_int_equal(stp_recip32(0), 0);
}

static void check_udiv(uint64_t n, uint64_t d)
{
    uint64_t got = stp_udiv64_recip(n, d), want = n / d;
    if (got != want)
        fail_msg("stp_udiv64_recip(%llu, %llu) = %llu, C gives %llu", (unsigned long long)n,
                 (unsigned long long)d, (unsigned long long)got, (unsigned long long)want);
}

static uint64_t random_bits(int bits)
{
    uint64_t v = next_random();
    if (bits == 0)
        return 0;
    v >>= 64 - bits;
    return v | ((uint64_t)1 << (bits - 1)); /* exactly that long */
}

static void test_udiv_every_length(void **state)
{
    int ln, ld, k;
    (void)state;
    for (ln = 0; ln <= 64; ln++)
        for (ld = 1; ld <= 64; ld++)
            for (k = 0; k < 200; k++) {
                uint64_t n = random_bits(ln), d = random_bits(ld);
                check_udiv(n, d);
                /* quotients next to an integer: n a multiple of d, +-1 */
                if (ld < 64 && ln > ld) {
                    uint64_t q = n / d, p = q * d;
                    check_udiv(p, d);
                    check_udiv(p - 1, d);
                    check_udiv(p + d - 1, d);
                }
            }
}

static void test_udiv_edges(void **state)
{
    static const uint64_t values[] = {1, 2, 3, 5, 0xFFFFu, 0x10000u, 0xFFFFFFFFu, 0x100000000u,
                                      0x100000001u, 0x1FFFFFFFFu, 0xFFFFFFFF00000001u,
                                      0xFFFFFFFF80000000u, 0x7FFFFFFFFFFFFFFFu,
                                      0x8000000000000000u, UINT64_MAX - 1, UINT64_MAX};
    size_t i, j;
    (void)state;
    for (i = 0; i < sizeof values / sizeof values[0]; i++) {
        check_udiv(0, values[i]);
        for (j = 0; j < sizeof values / sizeof values[0]; j++)
            check_udiv(values[i], values[j]);
    }
    /* two-word divisors with all-ones top words (the estimate's
     * corrections) */
    check_udiv(UINT64_MAX, 0xFFFFFFFF00000001u);
    check_udiv(UINT64_MAX, 0x1FFFFFFFFu);
    check_udiv(0xFFFFFFFFFFFFu, 0x1FFFFFFFFu);
    assert_true(stp_udiv64_recip(5, 0) == UINT64_MAX);
}

static void check_div(int64_t n, int64_t d)
{
    int64_t got = stp_div64_recip(n, d), want = n / d, fast = stp_div64_fast(n, d);
    if (got != want || fast != want)
        fail_msg("%lld / %lld: stp_div64_recip %lld, stp_div64_fast %lld, C gives %lld",
                 (long long)n, (long long)d, (long long)got, (long long)fast, (long long)want);
}

static void test_div_signs(void **state)
{
    static const int64_t values[] = {0, 1, 2, 3, 7, 65536, 1000003, ((int64_t)1 << 31) - 1,
                                     (int64_t)1 << 32, ((int64_t)1 << 48) + 5, (int64_t)1 << 60,
                                     INT64_MAX - 1, INT64_MAX};
    size_t i, j;
    int k;
    (void)state;
    for (i = 0; i < sizeof values / sizeof values[0]; i++)
        for (j = 1; j < sizeof values / sizeof values[0]; j++) {
            check_div(values[i], values[j]);
            check_div(-values[i], values[j]);
            check_div(values[i], -values[j]);
            check_div(-values[i], -values[j]);
        }
    check_div(INT64_MIN, 2);
    check_div(INT64_MIN, INT64_MAX);
    check_div(INT64_MIN, INT64_MIN);
    for (k = 0; k < 100000; k++) {
        int64_t n = (int64_t)random_bits(1 + (int)(next_random() % 63)),
                d = (int64_t)random_bits(1 + (int)(next_random() % 63));
        check_div(k & 1 ? -n : n, k & 2 ? -d : d);
    }
}

/* a prepared divisor gives C's quotients for any numerator */
static void test_prepared_divisor(void **state)
{
    static const uint32_t divisors[] = {1, 2, 3, 7, 65535, 65536, 1000003, 0x7FFFFFFFu,
                                        0x80000000u, 0xFFFFFFFFu};
    size_t i;
    int k;
    (void)state;
    for (i = 0; i < sizeof divisors / sizeof divisors[0]; i++) {
        stp_recip_divisor p;
        stp_recip_divisor_init(&p, divisors[i]);
        assert_true(stp_udiv64_by(&p, UINT64_MAX) == UINT64_MAX / divisors[i]);
        assert_true(stp_div64_by(&p, INT64_MAX) == INT64_MAX / (int64_t)divisors[i]);
        assert_true(stp_div64_by(&p, -INT64_MAX) == -INT64_MAX / (int64_t)divisors[i]);
        assert_true(stp_div64_by(&p, 0) == 0);
    }
    for (k = 0; k < 100000; k++) {
        uint32_t d = (uint32_t)random_bits(1 + (int)(next_random() % 32));
        int64_t n = (int64_t)random_bits(1 + (int)(next_random() % 63));
        stp_recip_divisor p;
        if (d == 0)
            d = 1;
        stp_recip_divisor_init(&p, d);
        n = k & 1 ? -n : n;
        if (stp_div64_by(&p, n) != n / (int64_t)d)
            fail_msg("stp_div64_by(%lld / %lu) = %lld", (long long)n, (unsigned long)d,
                     (long long)stp_div64_by(&p, n));
    }
}

#if STP_RECIP_U32
/* stp_recip_u32 against C's 32-bit division (the whole range [1, 2^32)
 * was checked once off line; here a sample heavy at its edges) */
static void check_recip_u32(uint32_t d)
{
    uint32_t got = stp_recip_u32(d), want = 0xFFFFFFFFu / d;
    if (got != want)
        fail_msg("stp_recip_u32(%lu) = %lu, floor((2^32 - 1) / d) = %lu", (unsigned long)d, (unsigned long)got,
                 (unsigned long)want);
}

static void test_recip_u32_edges(void **state)
{
    uint32_t d, i;
    int s;
    (void)state;
    /* every divisor below 2^17: every normalisation shift from 15 up,
     * the remainder step's whole range (shifts above 20) among them */
    for (d = 1; d < 0x20000u; d++)
        check_recip_u32(d);
    /* for every shift, the ends of every seed interval (the seed's worst
     * error) and their neighbours, and the middle */
    for (s = 0; s < 32; s++)
        for (i = 0; i < 128; i++) {
            uint32_t lo = (0x80000000u + (i << 24)) >> s, hi = (0x80000000u + (i << 24) + 0xFFFFFFu) >> s;
            check_recip_u32(lo);
            check_recip_u32(lo + 1u);
            check_recip_u32(hi);
            if (hi > 1u)
                check_recip_u32(hi - 1u);
            check_recip_u32((0x80800000u + (i << 24)) >> s);
        }
    check_recip_u32(0xFFFFFFFFu);
    /* random divisors of every length */
    for (i = 0; i < 2000000u; i++) {
        d = (uint32_t)(next_random() >> 32) >> (i % 32u);
        check_recip_u32(d != 0 ? d : 1u);
    }
}
#endif

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_recip_whole_range),
        cmocka_unit_test(test_udiv_every_length),
        cmocka_unit_test(test_udiv_edges),
        cmocka_unit_test(test_div_signs),
        cmocka_unit_test(test_prepared_divisor),
#if STP_RECIP_U32
        cmocka_unit_test(test_recip_u32_edges),
#endif
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
