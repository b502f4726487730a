/* SPDX-License-Identifier: MIT */
/*
 * Every shading implementation against the independent double-precision
 * reference of the chapter's equations (tests/reference/shade_ref.c), over
 * ACC_CASES deterministic cases (cases.h), about 70 % of them extremes:
 *   classic  stp_shade_point (the per-point shader; the normal given as the
 *            case's Q1.14 normal in stp_fix)
 *   face     stp_shade_fast_prepare + stp_shade_fast_face (the one face
 *            shader, with the arithmetic this binary is built with: the
 *            64-bit host path, or the 32-bit target path with
 *            STP_WIDE_ARITH=0)
 * With an argument (a log of "stipple: case I DIGEST FACE CLASSIC" lines,
 * from m0/main.c under QEMU), the Cortex-M0+ shades of the logged cases are
 * checked instead, against the same reference computed here.
 *
 * Pass: for every case, |s - reference| <= ACC_TOL (2e-3); exactly 0 where
 * the reference is exactly 0; exactly 1 where the reference's unclamped
 * value is at least 1 + ACC_TOL (between 1 and 1 + ACC_TOL the tolerance
 * applies).  The reference takes the quantised inputs (stp_fix positions
 * and parameters, the Q1.14 normal normalised), so the cases are exactly
 * what the shaders see.  Prints per path the case count, the max and mean
 * error and the worst case.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>

#include <cmocka.h>

#include "cases.h"
#include "case_reference.h"
#include "shade_fast_private.h"
#include "recip_private.h"

#ifndef ACC_CASES
#define ACC_CASES 30000u
#endif
#define ACC_TOL 2e-3

static const char *m0_log;

typedef struct acc_stats {
    const char *name;
    unsigned long cases, bad, bad_zero, bad_one;
    double max, sum;
    uint32_t worst;
    double worst_ref;
    stp_fix worst_got;
} acc_stats;

static double fixd(stp_fix v)
{
    return (double)v / STP_FIX_ONE;
}

static void account(acc_stats *st, uint32_t index, stp_fix got, double ref, double raw, int verbose)
{
    double err = fabs(fixd(got) - ref);
    int bad = err > ACC_TOL;
    st->cases++;
    st->sum += err;
    if (ref == 0.0 && got != 0) {
        st->bad_zero++;
        bad = 1;
    }
    if (raw >= 1.0 + ACC_TOL && got != STP_FIX_ONE) {
        st->bad_one++;
        bad = 1;
    }
    if (bad) {
        st->bad++;
        if (verbose && st->bad <= 12)
            printf("  %s case %lu: got %.6f, reference %.6f (unclamped %.6g)\n", st->name, (unsigned long)index,
                   fixd(got), ref, raw);
    }
    if (err > st->max) {
        st->max = err;
        st->worst = index;
        st->worst_ref = ref;
        st->worst_got = got;
    }
}

static void report(const acc_stats *st, const char *arith)
{
    printf("shade accuracy: %-8s %-34s cases %lu  max %.3e (case %lu: %.6f against %.6f)  mean %.3e  "
           "over %.0e: %lu  (0 not exact: %lu, 1 not exact: %lu)\n",
           st->name, arith, st->cases, st->max, (unsigned long)st->worst, fixd(st->worst_got), st->worst_ref,
           st->cases ? st->sum / (double)st->cases : 0.0, ACC_TOL, st->bad, st->bad_zero, st->bad_one);
}

static stp_vec3 normal_fix(const int16_t n[3])
{
    stp_vec3 v;
    /* Q1.14 to stp_fix, exactly for F >= 14 */
    v.x = STP_FIX_FRAC_BITS >= 14 ? (stp_fix)n[0] * (1 << (STP_FIX_FRAC_BITS - 14)) : n[0] >> (14 - STP_FIX_FRAC_BITS);
    v.y = STP_FIX_FRAC_BITS >= 14 ? (stp_fix)n[1] * (1 << (STP_FIX_FRAC_BITS - 14)) : n[1] >> (14 - STP_FIX_FRAC_BITS);
    v.z = STP_FIX_FRAC_BITS >= 14 ? (stp_fix)n[2] * (1 << (STP_FIX_FRAC_BITS - 14)) : n[2] >> (14 - STP_FIX_FRAC_BITS);
    return v;
}

static const char *arith_name(void)
{
    return STP_WIDE_ARITH ? "(64-bit host arithmetic)" : "(32-bit target arithmetic, host)";
}

static void test_host(void **state)
{
    acc_stats classic = {"classic", 0, 0, 0, 0, 0.0, 0.0, 0, 0.0, 0};
    acc_stats face = {"face", 0, 0, 0, 0, 0.0, 0.0, 0, 0.0, 0};
    uint32_t i;
    (void)state;
    for (i = 0; i < ACC_CASES; i++) {
        acc_case c;
        stp_shade_fast fast;
        double raw, ref;
        acc_case_make(&c, i);
        ref = acc_reference(&c, &raw);
        account(&classic, i,
                stp_shade_point(&c.lighting, &c.material, normal_fix(c.normal), c.point, c.eye, c.parallel,
                                c.parallel_dir),
                ref, raw, 1);
        stp_shade_fast_prepare(&fast, &c.lighting, &c.material, c.eye, c.parallel, c.parallel_dir);
        account(&face, i, stp_shade_fast_face(&fast, c.normal, c.point), ref, raw, 1);
    }
    report(&classic, arith_name());
    report(&face, arith_name());
    assert_int_equal(classic.cases, ACC_CASES);
    assert_int_equal(classic.bad, 0);
    assert_int_equal(face.bad, 0);
}

static void test_m0_log(void **state)
{
    acc_stats classic = {"classic", 0, 0, 0, 0, 0.0, 0.0, 0, 0.0, 0};
    acc_stats face = {"face", 0, 0, 0, 0, 0.0, 0.0, 0, 0.0, 0};
    FILE *f = fopen(m0_log, "r");
    char line[256];
    unsigned long done = 0, expected = 0;
    (void)state;
    assert_non_null(f);
    while (fgets(line, sizeof line, f)) {
        unsigned long index, digest;
        long fs, cs;
        if (sscanf(line, "stipple: cases %lu", &expected) == 1)
            continue;
        if (sscanf(line, "stipple: case %lu %lu %ld %ld", &index, &digest, &fs, &cs) == 4) {
            acc_case c;
            double raw, ref;
            acc_case_make(&c, (uint32_t)index);
            assert_int_equal(acc_case_digest(&c), digest); /* the same case on both sides */
            ref = acc_reference(&c, &raw);
            account(&face, (uint32_t)index, (stp_fix)fs, ref, raw, 1);
            account(&classic, (uint32_t)index, (stp_fix)cs, ref, raw, 1);
            done++;
        }
    }
    fclose(f);
    report(&classic, "(32-bit target arithmetic, Cortex-M0+)");
    report(&face, "(32-bit target arithmetic, Cortex-M0+)");
    assert_true(expected > 0);
    assert_int_equal(done, expected);
    assert_int_equal(classic.bad, 0);
    assert_int_equal(face.bad, 0);
}

int main(int argc, char **argv)
{
    const struct CMUnitTest host[] = {cmocka_unit_test(test_host)};
    const struct CMUnitTest m0[] = {cmocka_unit_test(test_m0_log)};
    if (argc > 1) {
        m0_log = argv[1];
        return cmocka_run_group_tests(m0, NULL, NULL);
    }
    return cmocka_run_group_tests(host, NULL, NULL);
}
