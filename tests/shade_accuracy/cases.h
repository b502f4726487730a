/* SPDX-License-Identifier: MIT */
/*
 * Deterministic shading cases for the accuracy test (test_shade_accuracy.c)
 * and its Cortex-M0+ run (m0/main.c): case i depends on i only, is built
 * with double + - * / (no libm: the same bits on the host and under the
 * ARM soft-float library) and is quantised to the inputs the shaders take
 * (stp_fix positions and parameters, a Q1.14 normal).  About 70 % of the
 * cases are pushed to extremes: grazing light and eye, near-mirror, light
 * behind, light 3e-4 to 2.5e4 away, n 1.003 to 3000, k 1.6e-5 to 1000,
 * BRIGHT 0.01 to 10 000, C down to 2^-16, 1 to 4 lights, power-0 lights
 * with BRIGHT >= 512.
 */
#ifndef STIPPLE_TESTS_SHADE_ACCURACY_CASES_H
#define STIPPLE_TESTS_SHADE_ACCURACY_CASES_H

#include <stdint.h>

#include "stipple/shade.h"

/* flags: what a case was pushed to (for the per-kind report) */
#define ACC_EXTREME 1u       /* any of the below */
#define ACC_GRAZING_EYE 2u
#define ACC_GRAZING_LIGHT 4u
#define ACC_NEAR_MIRROR 8u
#define ACC_BEHIND 16u
#define ACC_TINY_GLOSS 32u   /* k <= 2e-4 */
#define ACC_BIG_BRIGHT 64u   /* BRIGHT >= 512 */
#define ACC_POWER_ZERO 128u  /* a light of power 0 */
#define ACC_SMALL_C 256u     /* C <= 2^-8 */
#define ACC_NEAR_LIGHT 512u  /* a light closer than 1e-2 */

typedef struct acc_case {
    stp_lighting lighting;
    stp_material material;
    int16_t normal[3]; /* Q1.14, |N| = 1 within 2^-13 */
    stp_vec3 point;
    stp_vec3 eye;
    int parallel;
    stp_vec3 parallel_dir;
    unsigned flags;
} acc_case;

/* Case number index (any uint32) into *c. */
void acc_case_make(acc_case *c, uint32_t index);

/* A 32-bit digest of the quantised inputs (to check that the host and the
 * target generated the same case). */
uint32_t acc_case_digest(const acc_case *c);

#endif
