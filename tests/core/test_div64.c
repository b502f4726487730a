/* SPDX-License-Identifier: MIT */
/* STP_SMALL_DIVISION's bit-serial 64-bit division (src/div64.c, built here
 * with the switch on) against C's own operator: signs, extremes and a
 * pseudo-random sweep of magnitudes. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "div64_private.h"

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

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_signs_and_edges),
        cmocka_unit_test(test_random_magnitudes),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
