/* SPDX-License-Identifier: MIT */
/*
 * The tests' pseudo-random numbers: a 64-bit linear congruential generator
 * (Knuth's MMIX constants), its high 32 bits a draw.  A test file defines
 * TEST_RANDOM_SEED before it includes this header and so keeps its own
 * sequence (its cases stay what they were).  next_random: one draw.
 */
#ifndef STIPPLE_TESTS_TEST_RANDOM_H
#define STIPPLE_TESTS_TEST_RANDOM_H

#include <stdint.h>

#ifndef TEST_RANDOM_SEED
#error "define TEST_RANDOM_SEED (the file's seed) before including test_random.h"
#endif

static uint64_t test_random_state = TEST_RANDOM_SEED;

static uint32_t next_random(void)
{
    test_random_state = test_random_state * 6364136223846793005u + 1442695040888963407u;
    return (uint32_t)(test_random_state >> 32);
}

#endif
