/* SPDX-License-Identifier: MIT */
/*
 * stp_bit_length32 (src/arith_private.h) against a plain loop: 0, every
 * power of two and its neighbours, and random values of every length.
 * Built twice (tests/core/CMakeLists.txt): with the build's flags (the
 * table's form, or the instruction), and with -Os and no 32-bit multiply
 * (STP_LEAN_CODE: the AVR's byte-then-bit form), which EXPECT_LEAN makes
 * this file check it got.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "arith_private.h"

#if defined(EXPECT_LEAN) && !STP_LEAN_CODE
#error "test_bit_length_lean is built without STP_LEAN_CODE"
#endif

static int reference_length(uint32_t v)
{
    int n = 0;
    while (v != 0) {
        v >>= 1;
        n++;
    }
    return n;
}

static void test_edges(void **state)
{
    int k;
    (void)state;
    assert_int_equal(stp_bit_length32(0), 0);
    for (k = 0; k < 32; k++) {
        uint32_t p = (uint32_t)1 << k;
        assert_int_equal(stp_bit_length32(p), k + 1);
        assert_int_equal(stp_bit_length32(p - 1u), reference_length(p - 1u));
        assert_int_equal(stp_bit_length32(p + 1u), reference_length(p + 1u));
        assert_int_equal(stp_bit_length32(p | (p - 1u)), k + 1);
    }
    assert_int_equal(stp_bit_length32(0xFFFFFFFFu), 32);
}

static void test_random(void **state)
{
    uint64_t seed = 0x2545F4914F6CDD1Du;
    long i;
    (void)state;
    for (i = 0; i < 200000; i++) {
        uint32_t v;
        seed = seed * 6364136223846793005u + 1442695040888963407u;
        v = (uint32_t)(seed >> 32) >> (uint32_t)(seed % 32u); /* every length */
        assert_int_equal(stp_bit_length32(v), reference_length(v));
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_edges),
        cmocka_unit_test(test_random),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
