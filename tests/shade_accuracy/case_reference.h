/* SPDX-License-Identifier: MIT */
/*
 * The double-precision reference shade of an accuracy case (cases.h),
 * through tests/reference/shade_ref.c: shared by test_shade_accuracy and
 * tools/bench/shade_error_cost so both judge against the same values.
 */
#ifndef STP_CASE_REFERENCE_H
#define STP_CASE_REFERENCE_H

#include "cases.h"

/* The reference shade of c in [0, 1]; when raw is not NULL, also its value
 * before min(1, .) (the same sum taken far below the cap). */
double acc_reference(const acc_case *c, double *raw);

#endif
