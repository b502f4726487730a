/* SPDX-License-Identifier: MIT */
/* STP_SMALL_DIVISION's bit-serial 64-bit and 32-bit divisions (src/div64.c,
 * built here with the switch on) against C's own operator: signs, extremes
 * and a pseudo-random sweep of magnitudes; and its computed reciprocal
 * seeds (src/recip.c, stp_recip_seed) in stp_recip32. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "div64_private.h"
#include "recip_private.h"

static void check(int64_t num, int64_t den)
{
    int64_t got = stp_div64_trunc(num, den), want = num / den;
    if (got != want)
        fail_msg("%lld / %lld: got %lld, C gives %lld", (long long)num, (long long)den, (long long)got,
                 (long long)want);
}

static void test_signs_and_edges(void **state)
{
    static const int64_t values[] = {0, 1, 2, 3, 7, 15, 16, 65535, 65536, 4096, 1000003,
                                     ((int64_t)1 << 31) - 1, (int64_t)1 << 32, ((int64_t)1 << 48) + 5,
                                     (int64_t)1 << 60, INT64_MAX, INT64_MAX - 1};
    size_t i, j;
    (void)state;
    for (i = 0; i < sizeof values / sizeof values[0]; i++)
        for (j = 0; j < sizeof values / sizeof values[0]; j++) {
            if (values[j] == 0)
                continue;
            check(values[i], values[j]);
            check(-values[i], values[j]);
            check(values[i], -values[j]);
            check(-values[i], -values[j]);
        }
    check(INT64_MIN, 1);
    check(INT64_MIN, 2);
    check(INT64_MIN, INT64_MAX);
    check(INT64_MIN, INT64_MIN);
    check(5, INT64_MIN);
}

static void test_random_magnitudes(void **state)
{
    uint64_t seed = 0x9E3779B97F4A7C15u;
    int i;
    (void)state;
    for (i = 0; i < 200000; i++) {
        int64_t num, den;
        seed = seed * 6364136223846793005u + 1442695040888963407u;
        num = (int64_t)(seed >> (seed & 63u)) * ((seed >> 7) & 1u ? -1 : 1);
        seed = seed * 6364136223846793005u + 1442695040888963407u;
        den = (int64_t)((seed >> (seed & 63u)) | 1u) * ((seed >> 9) & 1u ? -1 : 1);
        check(num, den);
    }
}

static void check32(uint32_t n, uint32_t d)
{
    uint32_t got = STP_UDIV32(n, d), want = n / d;
    if (got != want)
        fail_msg("%lu / %lu: got %lu, C gives %lu", (unsigned long)n, (unsigned long)d, (unsigned long)got,
                 (unsigned long)want);
}

/* STP_UDIV32: the loop (this test builds as for a core without a divide
 * instruction, STP_HAVE_DIV 0: CMakeLists.txt), the
 * edges' slopes' division in size-first builds (edge_walk_private.h) */
static void test_udiv32(void **state)
{
    static const uint32_t values[] = {1, 2, 3, 7, 15, 16, 17, 255, 256, 65535, 65536, 65537, 1000003,
                                      0x3FFF0000u, 0x7FFFFFFFu, 0x80000000u, 0xFFFFFFFEu, 0xFFFFFFFFu};
    uint32_t seed = 0x2545F491u;
    size_t i, j;
    int k;
    (void)state;
    for (i = 0; i < sizeof values / sizeof values[0]; i++) {
        check32(0, values[i]);
        for (j = 0; j < sizeof values / sizeof values[0]; j++)
            check32(values[i], values[j]);
    }
    for (k = 0; k < 200000; k++) {
        uint32_t n, d;
        seed ^= seed << 13;
        seed ^= seed >> 17;
        seed ^= seed << 5;
        n = seed >> (seed & 31u);
        seed ^= seed << 13;
        seed ^= seed >> 17;
        seed ^= seed << 5;
        d = (seed >> (seed & 31u)) | 1u;
        check32(n, d);
        check32(n, d + 1u > d ? d + 1u : d); /* even divisors too */
    }
}

/* stp_recip_seed against the quotient for every d, and stp_recip32 (whose
 * seeds it computes here; without a 32-bit multiply, STP_ARITH32's
 * builds, its loop) against C's 64-bit division */
static void test_recip_seed(void **state)
{
    uint32_t d, seed = 0x9E3779B9u;
    int k;
    (void)state;
#if STP_HAVE_MUL32
    for (d = 513; d < 1024; d++) {
        uint32_t want = (((uint32_t)1 << 25) + (d >> 1)) / d;
        if (stp_recip_seed(d) != want)
            fail_msg("stp_recip_seed(%lu): got %lu, want %lu", (unsigned long)d, (unsigned long)stp_recip_seed(d),
                     (unsigned long)want);
    }
#endif
    for (k = 0; k < 200000; k++) {
        uint32_t want;
        seed ^= seed << 13;
        seed ^= seed >> 17;
        seed ^= seed << 5;
        d = seed | 0x80000000u;
        if (k < 2)
            d = k == 0 ? 0x80000000u : 0xFFFFFFFFu;
        want = (uint32_t)(UINT64_MAX / d - ((uint64_t)1 << 32));
        if (stp_recip32(d) != want)
            fail_msg("stp_recip32(%lu): got %lu, want %lu", (unsigned long)d, (unsigned long)stp_recip32(d),
                     (unsigned long)want);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_signs_and_edges),
        cmocka_unit_test(test_random_magnitudes),
        cmocka_unit_test(test_udiv32),
        cmocka_unit_test(test_recip_seed),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
