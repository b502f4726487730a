/* SPDX-License-Identifier: MIT */
/*
 * Property tests of the fixed-point layer (include/stipple/fix.h) against
 * double (or exact 64/128-bit integer) arithmetic, with a fixed-seed PRNG so
 * every run checks the same cases.  Each assertion is the error bound the
 * header documents; where the header documents none (pow, unity), the bound
 * used is derived in a comment beside it.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "stipple/fix.h"
#include "stipple/transform.h"
#include "fix_private.h" /* STP_UNIT (src/) */

#define F STP_FIX_FRAC_BITS
#define ONE STP_FIX_ONE
#define LSB (1.0 / (double)ONE)
#define CASES 20000
#define PI 3.14159265358979323846

__extension__ typedef __int128 i128;
__extension__ typedef unsigned __int128 u128;

/* ---- fixed-seed PRNG (splitmix64) ---- */

static uint64_t prng_state;

static void prng_seed(uint64_t seed)
{
    prng_state = seed;
}

static uint64_t prng_next(void)
{
    uint64_t z = (prng_state += 0x9E3779B97F4A7C15u);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9u;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBu;
    return z ^ (z >> 31);
}

/* Uniform in [0, n). */
static uint64_t prng_below(uint64_t n)
{
    return prng_next() % n;
}

/* A stp_fix of log-uniform magnitude (1 LSB .. full range) and random sign:
 * small and large values are both well covered. */
static stp_fix rand_fix(void)
{
    int bits = (int)prng_below(32); /* 0..31 significant bits */
    uint32_t m = bits == 0 ? 0 : (uint32_t)(prng_next() >> (64 - bits));
    stp_fix v = (stp_fix)(m > (uint32_t)INT32_MAX ? (uint32_t)INT32_MAX : m);
    return (prng_next() & 1) ? -v : v;
}

static stp_fix rand_fix_positive(void)
{
    stp_fix v = rand_fix();
    v = v < 0 ? -v : v;
    return v == 0 ? 1 : v;
}

static double to_d(stp_fix a)
{
    return (double)a * LSB;
}

static double sat_d(double v_lsb)
{
    return v_lsb > (double)STP_FIX_MAX ? (double)STP_FIX_MAX
                                       : (v_lsb < (double)STP_FIX_MIN ? (double)STP_FIX_MIN : v_lsb);
}

/* ---- conversions and saturating add/sub ---- */

static void test_from_int_and_ratio(void **state)
{
    (void)state;
    assert_int_equal(stp_fix_from_int(3), 3 * ONE);
    assert_int_equal(stp_fix_from_int(-7), -7 * ONE);
    assert_int_equal(stp_fix_from_int(INT32_MAX), STP_FIX_MAX);
    assert_int_equal(stp_fix_from_int(INT32_MIN), STP_FIX_MIN);
    assert_int_equal(stp_fix_from_ratio(1, 2), ONE / 2);
    assert_int_equal(stp_fix_from_ratio(-1, 2), -ONE / 2);
    assert_int_equal(stp_fix_from_ratio(1, -4), -ONE / 4);
    /* 1/3 rounded to nearest */
    assert_int_equal(stp_fix_from_ratio(1, 3), (stp_fix)floor((double)ONE / 3.0 + 0.5));
    assert_int_equal(stp_fix_from_ratio(2, 3), (stp_fix)floor(2.0 * ONE / 3.0 + 0.5));
    assert_int_equal(stp_fix_from_ratio(5, 0), STP_FIX_MAX);
    assert_int_equal(stp_fix_from_ratio(-5, 0), STP_FIX_MIN);
    assert_int_equal(stp_fix_from_ratio(0, 0), 0);
    assert_int_equal(stp_fix_from_ratio(INT32_MAX, 1), STP_FIX_MAX);
}

static void test_add_sub_saturate(void **state)
{
    int i;
    (void)state;
    assert_int_equal(stp_fix_add(STP_FIX_MAX, 1), STP_FIX_MAX);
    assert_int_equal(stp_fix_add(STP_FIX_MAX, STP_FIX_MAX), STP_FIX_MAX);
    assert_int_equal(stp_fix_add(STP_FIX_MIN, -1), STP_FIX_MIN);
    assert_int_equal(stp_fix_sub(STP_FIX_MIN, STP_FIX_MAX), STP_FIX_MIN);
    assert_int_equal(stp_fix_sub(STP_FIX_MAX, STP_FIX_MIN), STP_FIX_MAX);
    assert_int_equal(stp_fix_add(INT32_MIN, INT32_MIN), STP_FIX_MIN);
    prng_seed(11);
    for (i = 0; i < CASES; i++) {
        stp_fix a = rand_fix(), b = rand_fix();
        assert_int_equal(stp_fix_add(a, b), (stp_fix)sat_d((double)a + (double)b));
        assert_int_equal(stp_fix_sub(a, b), (stp_fix)sat_d((double)a - (double)b));
    }
}

/* ---- mul ---- */

/* round(p / 2^F), ties away from zero, in exact integers. */
static int64_t round_shift_away(int64_t p)
{
    int64_t mag = p < 0 ? -p : p;
    int64_t q = (mag + ((int64_t)1 << (F - 1))) >> F;
    return p < 0 ? -q : q;
}

static void test_mul_rounds_to_nearest(void **state)
{
    int i;
    (void)state;
    prng_seed(1);
    for (i = 0; i < 4 * CASES; i++) {
        stp_fix a = rand_fix(), b = rand_fix();
        stp_fix got = stp_fix_mul(a, b);
        double exact_lsb = (double)a * (double)b * LSB; /* rel. error 2^-53 */
        int64_t want = round_shift_away((int64_t)a * b);
        want = want > STP_FIX_MAX ? STP_FIX_MAX : (want < STP_FIX_MIN ? STP_FIX_MIN : want);
        if (got != want)
            fail_msg("mul(%d, %d) = %d, want %lld", a, b, got, (long long)want);
        /* against double: within half an LSB (plus double's own rounding) */
        if (fabs(exact_lsb) < (double)STP_FIX_MAX)
            assert_true(fabs((double)got - exact_lsb) <= 0.5 + fabs(exact_lsb) * 0x1p-50);
    }
    /* ties round away from zero */
    assert_int_equal(stp_fix_mul(1, ONE / 2), 1);
    assert_int_equal(stp_fix_mul(-1, ONE / 2), -1);
    assert_int_equal(stp_fix_mul(3, ONE / 2), 2);
    assert_int_equal(stp_fix_mul(-3, ONE / 2), -2);
    assert_int_equal(stp_fix_mul(ONE, ONE), ONE);
    assert_int_equal(stp_fix_mul(-ONE, ONE), -ONE);
}

static void test_mul_saturates_at_extremes(void **state)
{
    (void)state;
    assert_int_equal(stp_fix_mul(STP_FIX_MAX, STP_FIX_MAX), STP_FIX_MAX);
    assert_int_equal(stp_fix_mul(STP_FIX_MIN, STP_FIX_MIN), STP_FIX_MAX);
    assert_int_equal(stp_fix_mul(STP_FIX_MAX, STP_FIX_MIN), STP_FIX_MIN);
    assert_int_equal(stp_fix_mul(INT32_MIN, INT32_MIN), STP_FIX_MAX);
    assert_int_equal(stp_fix_mul(INT32_MIN, INT32_MAX), STP_FIX_MIN);
    assert_int_equal(stp_fix_mul(STP_FIX_MAX, ONE), STP_FIX_MAX);
    assert_int_equal(stp_fix_mul(STP_FIX_MIN, ONE), STP_FIX_MIN);
    assert_int_equal(stp_fix_mul(STP_FIX_MAX, 0), 0);
    /* (range/2)^2 overflows for every F */
    assert_int_equal(stp_fix_mul(STP_FIX_MAX / 2, STP_FIX_MAX / 2), STP_FIX_MAX);
    assert_int_equal(stp_fix_mul(-(STP_FIX_MAX / 2), STP_FIX_MAX / 2), STP_FIX_MIN);
}

/* ---- div ---- */

static void test_div_truncates_toward_zero(void **state)
{
    int i;
    (void)state;
    prng_seed(2);
    for (i = 0; i < 4 * CASES; i++) {
        stp_fix a = rand_fix(), b = rand_fix();
        stp_fix got;
        double q;
        if (b == 0)
            continue;
        got = stp_fix_div(a, b);
        q = (double)a / (double)b * (double)ONE; /* exact quotient in LSB */
        if (fabs(q) >= (double)STP_FIX_MAX) {
            assert_int_equal(got, q > 0 ? STP_FIX_MAX : STP_FIX_MIN);
            continue;
        }
        /* truncation: |got| <= |q| < |got| + 1, same sign (or zero) */
        if (!(fabs((double)got) <= fabs(q) * (1.0 + 0x1p-50) &&
              fabs(q) < fabs((double)got) + 1.0 + fabs(q) * 0x1p-50 && (double)got * q >= 0.0))
            fail_msg("div(%d, %d) = %d, quotient %.6f LSB", a, b, got, q);
    }
    assert_int_equal(stp_fix_div(ONE, 3 * ONE), ONE / 3);
    assert_int_equal(stp_fix_div(-ONE, 3 * ONE), -(ONE / 3));
    assert_int_equal(stp_fix_div(7 * ONE, -2 * ONE), -7 * ONE / 2);
}

static void test_div_by_zero_and_overflow_saturate(void **state)
{
    (void)state;
    assert_int_equal(stp_fix_div(ONE, 0), STP_FIX_MAX);
    assert_int_equal(stp_fix_div(-ONE, 0), STP_FIX_MIN);
    assert_int_equal(stp_fix_div(0, 0), 0);
    assert_int_equal(stp_fix_div(1, 0), STP_FIX_MAX);
    assert_int_equal(stp_fix_div(STP_FIX_MAX, 1), STP_FIX_MAX);
    assert_int_equal(stp_fix_div(STP_FIX_MIN, 1), STP_FIX_MIN);
    assert_int_equal(stp_fix_div(STP_FIX_MIN, -1), STP_FIX_MAX);
    assert_int_equal(stp_fix_div(INT32_MIN, -1), STP_FIX_MAX);
    assert_int_equal(stp_fix_div(INT32_MIN, INT32_MIN), ONE);
    assert_int_equal(stp_fix_div(STP_FIX_MAX, ONE / 2), STP_FIX_MAX);
}

/* ---- square roots ---- */

static void test_isqrt64_is_exact_floor(void **state)
{
    int i;
    static const uint64_t edges[] = {0, 1, 2, 3, 4, 5, 8, 9, 15, 16, 17, 0xFFFFFFFFu,
                                     0x100000000u, 0xFFFFFFFE00000001u, 0xFFFFFFFE00000000u,
                                     0xFFFFFFFFFFFFFFFFu, 0x8000000000000000u, 0x4000000000000000u,
                                     0x3FFFFFFFFFFFFFFFu};
    (void)state;
    prng_seed(3);
    for (i = 0; i < (int)(sizeof edges / sizeof edges[0]) + 4 * CASES; i++) {
        uint64_t v;
        uint32_t r;
        if (i < (int)(sizeof edges / sizeof edges[0])) {
            v = edges[i];
        } else if (i % 3 == 0) {
            /* around a perfect square k^2 */
            uint64_t k = prng_next() >> (32 + prng_below(32));
            v = k * k + (uint64_t)prng_below(3) - 1u;
        } else {
            v = prng_next() >> prng_below(64);
        }
        r = stp_isqrt64(v);
        if (!((u128)r * r <= v && ((u128)r + 1) * ((u128)r + 1) > v))
            fail_msg("isqrt64(%llu) = %u", (unsigned long long)v, r);
    }
}

/* The 32-bit root (stp_shade_fast's compact route, and stp_isqrt64 below
 * 2^32): at every square k^2 and k^2 - 1 (all k < 2^16), the top of the
 * range and random values, floor(sqrt(v)) by r^2 <= v < (r + 1)^2. */
static void test_isqrt32_is_exact_floor(void **state)
{
    uint32_t k;
    int i;
    (void)state;
    for (k = 0; k < 0x10000u; k++) {
        uint32_t sq = k * k;
        assert_int_equal(stp_isqrt32(sq), k);
        if (k > 0)
            assert_int_equal(stp_isqrt32(sq - 1u), k - 1u);
    }
    assert_int_equal(stp_isqrt32(0xFFFFFFFFu), 0xFFFFu);
    prng_seed(5);
    for (i = 0; i < 4 * CASES; i++) {
        uint32_t v = (uint32_t)(prng_next() >> (32 + prng_below(32)));
        uint64_t r = stp_isqrt32(v);
        if (!(r * r <= v && (r + 1) * (r + 1) > v))
            fail_msg("isqrt32(%lu) = %lu", (unsigned long)v, (unsigned long)r);
    }
}

static void test_sqrt_is_floor_of_root(void **state)
{
    int i;
    (void)state;
    prng_seed(4);
    for (i = 0; i < 4 * CASES; i++) {
        stp_fix a = rand_fix_positive();
        stp_fix got = stp_fix_sqrt(a);
        uint64_t scaled = (uint64_t)a << F; /* sqrt(a 2^F) has F fraction bits */
        double exact = sqrt((double)a * LSB) * (double)ONE;
#if STP_SQRT_FAST
        assert_true(fabs((double)got - exact) <= exact * 0x1p-15 + 1.0);
        (void)scaled;
#else
        if (!((u128)(uint32_t)got * (uint32_t)got <= scaled &&
              ((u128)got + 1) * ((u128)got + 1) > scaled))
            fail_msg("sqrt(%d) = %d, not the floor of the root", a, got);
        assert_true((double)got <= exact + 1e-6 && exact < (double)got + 1.0);
#endif
    }
    assert_int_equal(stp_fix_sqrt(4 * ONE), 2 * ONE);
    assert_int_equal(stp_fix_sqrt(ONE), ONE);
    assert_int_equal(stp_fix_sqrt(ONE / 4), ONE / 2);
}

static void test_sqrt_of_negative_and_extremes(void **state)
{
    (void)state;
    assert_int_equal(stp_fix_sqrt(0), 0);
    assert_int_equal(stp_fix_sqrt(-1), 0);
    assert_int_equal(stp_fix_sqrt(-ONE), 0);
    assert_int_equal(stp_fix_sqrt(STP_FIX_MIN), 0);
    assert_int_equal(stp_fix_sqrt(INT32_MIN), 0);
    /* sqrt(MAX) = sqrt(2^31 - 1) 2^(F/2): floor */
    assert_true(fabs((double)stp_fix_sqrt(STP_FIX_MAX) - sqrt((double)STP_FIX_MAX * ONE)) < 1.0);
    /* 1 LSB: sqrt(2^-F) = 2^-F/2 */
    assert_true(fabs((double)stp_fix_sqrt(1) - sqrt((double)ONE)) < 1.0);
    assert_int_equal(stp_fix_sqrt_wide(-1), 0);
    assert_int_equal(stp_fix_sqrt_wide(INT64_MIN), 0);
    assert_int_equal(stp_fix_sqrt_wide(0), 0);
    assert_int_equal(stp_fix_sqrt_wide(INT64_MAX), STP_FIX_MAX);
    assert_int_equal(stp_fix_sqrt_wide((int64_t)ONE * ONE), ONE);
}

static void test_sqrt_wide_is_floor_and_saturates(void **state)
{
    int i;
    (void)state;
    prng_seed(5);
    for (i = 0; i < 4 * CASES; i++) {
        int64_t v = (int64_t)(prng_next() >> (1 + prng_below(63)));
        stp_fix got = stp_fix_sqrt_wide(v);
        uint64_t r = (uint64_t)got;
#if STP_SQRT_FAST
        double exact = sqrt((double)v);
        assert_true(fabs((double)got - (exact > (double)STP_FIX_MAX ? (double)STP_FIX_MAX : exact)) <=
                    exact * 0x1p-15 + 1.0);
        (void)r;
#else
        if ((u128)STP_FIX_MAX * STP_FIX_MAX <= (u128)v) {
            /* a root above the range saturates (or is MAX exactly) */
            assert_int_equal(got, STP_FIX_MAX);
        } else if (!((u128)r * r <= (u128)v && (u128)(r + 1) * (r + 1) > (u128)v)) {
            fail_msg("sqrt_wide(%lld) = %d", (long long)v, got);
        }
#endif
    }
}

/* ---- log2, exp2, pow ---- */

static void test_log2_within_two_lsb(void **state)
{
    int i, j;
    (void)state;
    prng_seed(6);
    for (i = 0; i < 4 * CASES; i++) {
        stp_fix a = rand_fix_positive();
        double exact = log2(to_d(a)) * (double)ONE;
        stp_fix got = stp_fix_log2(a);
        /* documented: absolute error < 2^-(F-1), i.e. 2 LSB */
        if (!(fabs((double)got - exact) < 2.0))
            fail_msg("log2(%d) = %d, exact %.4f LSB", a, got, exact);
    }
    for (j = 0; j < 31; j++) /* powers of two: integers */
        assert_true(abs(stp_fix_log2((stp_fix)1 << j) - (j - F) * ONE) < 2);
    assert_int_equal(stp_fix_log2(0), STP_FIX_MIN);
    assert_int_equal(stp_fix_log2(-ONE), STP_FIX_MIN);
    assert_int_equal(stp_fix_log2(STP_FIX_MIN), STP_FIX_MIN);
}

static void test_exp2_relative_error(void **state)
{
    /* Documented: relative error < 2^-(F-2).  A result is a multiple of
     * 2^-F, so rounding alone costs 0.5 LSB: the relative bound can hold
     * only for results >= 2^-3 (0.5 LSB / 2^-3 = 2^-(F-2)); below that the
     * assertion is the relative bound plus half an LSB. */
    double worst_rel = 0.0;
    int i;
    (void)state;
    prng_seed(7);
    for (i = 0; i < 4 * CASES; i++) {
        /* exponents over [-(F+2), 15]: results from below 1 LSB to the top */
        stp_fix a = (stp_fix)((int64_t)prng_below((uint64_t)(F + 17) << F) - ((int64_t)(F + 2) << F));
        double exact = exp2(to_d(a)) * (double)ONE; /* in LSB */
        stp_fix got = stp_fix_exp2(a);
        double err = fabs((double)got - exact);
        if (exact >= (double)STP_FIX_MAX) {
            assert_int_equal(got, STP_FIX_MAX);
            continue;
        }
        if (exact >= (double)ONE / 8.0) {
            if (err / exact > worst_rel)
                worst_rel = err / exact;
            if (!(err / exact < ldexp(1.0, -(F - 2))))
                fail_msg("exp2(%d) = %d, exact %.4f LSB, rel. error %.3g", a, got, exact, err / exact);
        } else if (!(err <= exact * ldexp(1.0, -(F - 2)) + 0.5)) {
            fail_msg("exp2(%d) = %d, exact %.4f LSB", a, got, exact);
        }
    }
    print_message("exp2: worst relative error %.3g (bound %.3g)\n", worst_rel, ldexp(1.0, -(F - 2)));
}

static void test_exp2_saturates_and_underflows(void **state)
{
    (void)state;
    assert_int_equal(stp_fix_exp2(0), ONE);
    assert_int_equal(stp_fix_exp2(ONE), 2 * ONE);
    assert_int_equal(stp_fix_exp2(-ONE), ONE / 2);
    assert_int_equal(stp_fix_exp2((31 - F) * ONE), STP_FIX_MAX);
    assert_int_equal(stp_fix_exp2(STP_FIX_MAX), STP_FIX_MAX);
    assert_int_equal(stp_fix_exp2(STP_FIX_MIN), 0);
    assert_int_equal(stp_fix_exp2(INT32_MIN), 0);
    assert_int_equal(stp_fix_exp2(-(F + 2) * ONE), 0);
    assert_int_equal(stp_fix_exp2(-F * ONE), 1);
}

static void test_pow_against_double(void **state)
{
    /* No bound is documented; pow = exp2(e * log2(base)).  log2 is within
     * 2 LSB, the product e*lg rounds by 0.5 LSB, so the exponent handed to
     * exp2 is off by at most (2|e| + 0.5) LSB, which scales the result by
     * 2^that: relative (2|e| + 0.5) 2^-F ln 2; exp2 adds 2^-(F-2) relative
     * and 0.5 LSB.  Asserted: err <= exact (ln2 (2|e| + 0.5) 2^-F + 2^-(F-2))
     * + 1 LSB. */
    int i;
    (void)state;
    prng_seed(8);
    for (i = 0; i < 4 * CASES; i++) {
        stp_fix base = (stp_fix)(1 + prng_below(100u * (uint64_t)ONE)); /* (0, 100] */
        stp_fix e = (stp_fix)((int64_t)prng_below(8u * (uint64_t)ONE) - 4 * (int64_t)ONE); /* [-4, 4) */
        double exact = pow(to_d(base), to_d(e)) * (double)ONE;
        stp_fix got = stp_fix_pow(base, e);
        double bound = exact * (log(2.0) * (2.0 * fabs(to_d(e)) + 0.5) * LSB + ldexp(1.0, -(F - 2))) + 1.0;
        if (exact >= (double)STP_FIX_MAX) {
            assert_true(got >= (stp_fix)((double)STP_FIX_MAX * (1.0 - 1e-3)));
            continue;
        }
        if (!(fabs((double)got - exact) <= bound))
            fail_msg("pow(%d, %d) = %d, exact %.3f LSB, bound %.3f", base, e, got, exact, bound);
    }
    assert_int_equal(stp_fix_pow(0, ONE), 0);
    assert_int_equal(stp_fix_pow(-ONE, ONE), 0);
    assert_true(abs(stp_fix_pow(4 * ONE, ONE / 2) - 2 * ONE) <= 2);
    assert_true(abs(stp_fix_pow(ONE, 3 * ONE) - ONE) <= 1);
}

/* ---- sin, cos ---- */

static double sin_deg_ref(stp_fix deg)
{
    /* reduce exactly in double (deg is a multiple of 2^-F), then convert */
    double d = fmod(to_d(deg), 360.0);
    return sin(d * (PI / 180.0));
}

static double cos_deg_ref(stp_fix deg)
{
    double d = fmod(to_d(deg), 360.0);
    return cos(d * (PI / 180.0));
}

/* fix.h documents an absolute error < 2^-14 for any angle.  That cannot
 * hold when the LSB itself is coarser: the result is floored to F bits (cos 0
 * comes out as 1 - 1 LSB), so for F < 15 the bound is 1 LSB plus the
 * polynomial's 2e-6. */
#define SINCOS_TOL (F >= 15 ? 0x1p-14 : 1.0 / (double)ONE + 2e-6)

static void check_sin_cos(stp_fix deg)
{
    double s = to_d(stp_fix_sin_deg(deg)), c = to_d(stp_fix_cos_deg(deg));
    if (!(fabs(s - sin_deg_ref(deg)) < SINCOS_TOL))
        fail_msg("sin_deg(%d = %.5f deg) = %.6f, want %.6f", deg, to_d(deg), s, sin_deg_ref(deg));
    if (!(fabs(c - cos_deg_ref(deg)) < SINCOS_TOL))
        fail_msg("cos_deg(%d = %.5f deg) = %.6f, want %.6f", deg, to_d(deg), c, cos_deg_ref(deg));
}

static void test_sin_cos_within_2e14_any_angle(void **state)
{
    int i, k;
    (void)state;
    prng_seed(9);
    for (i = 0; i < 4 * CASES; i++)
        check_sin_cos(rand_fix());
    for (i = 0; i < CASES; i++) /* dense over one turn */
        check_sin_cos((stp_fix)((int64_t)prng_below(720u * (uint64_t)ONE) - 360 * (int64_t)ONE));
    for (k = -8; k <= 8; k++) { /* multiples of 45 degrees, and one LSB around */
        check_sin_cos(k * 45 * ONE);
        check_sin_cos(k * 45 * ONE + 1);
        check_sin_cos(k * 45 * ONE - 1);
    }
}

static void test_sin_cos_at_range_ends(void **state)
{
    stp_fix d;
    (void)state;
    /* "any value": the top 90 degrees of the range, where degrees + 90 does
     * not fit in stp_fix, and the bottom */
    for (d = STP_FIX_MAX; d > STP_FIX_MAX - 100 * ONE; d -= ONE / 3)
        check_sin_cos(d);
    for (d = STP_FIX_MIN; d < STP_FIX_MIN + 100 * ONE; d += ONE / 3)
        check_sin_cos(d);
    check_sin_cos(INT32_MIN);
    check_sin_cos(STP_FIX_MAX);
}

/* ---- vectors ---- */

static stp_vec3 vec(stp_fix x, stp_fix y, stp_fix z)
{
    stp_vec3 v;
    v.x = x;
    v.y = y;
    v.z = z;
    return v;
}

static void test_vec3_dot_rounds_and_saturates(void **state)
{
    int i;
    (void)state;
    prng_seed(10);
    for (i = 0; i < 4 * CASES; i++) {
        stp_vec3 a = vec(rand_fix(), rand_fix(), rand_fix());
        stp_vec3 b = vec(rand_fix(), rand_fix(), rand_fix());
        i128 exact2 = (i128)a.x * b.x + (i128)a.y * b.y + (i128)a.z * b.z; /* 2F fraction bits */
        double exact = (double)exact2 / (double)ONE;                         /* LSB */
        stp_fix got = stp_vec3_dot(a, b);
        if (exact >= (double)STP_FIX_MAX || exact <= (double)STP_FIX_MIN) {
            assert_int_equal(got, exact > 0 ? STP_FIX_MAX : STP_FIX_MIN);
            continue;
        }
        /* rounded: within half an LSB (and a hair for double's rounding and
         * the halving of the products) */
        if (!(fabs((double)got - exact) <= 0.5 + 1e-3))
            fail_msg("dot = %d, exact %.6f LSB", got, exact);
    }
    assert_int_equal(stp_vec3_dot(vec(ONE, 0, 0), vec(ONE, 0, 0)), ONE);
    assert_int_equal(stp_vec3_dot(vec(ONE, ONE, ONE), vec(-ONE, ONE, 2 * ONE)), 2 * ONE);
    assert_int_equal(stp_vec3_dot(vec(STP_FIX_MAX, STP_FIX_MAX, STP_FIX_MAX),
                                  vec(STP_FIX_MAX, STP_FIX_MAX, STP_FIX_MAX)), STP_FIX_MAX);
    assert_int_equal(stp_vec3_dot(vec(STP_FIX_MIN, STP_FIX_MIN, STP_FIX_MIN),
                                  vec(STP_FIX_MAX, STP_FIX_MAX, STP_FIX_MAX)), STP_FIX_MIN);
    assert_int_equal(stp_vec3_dot(vec(INT32_MIN, INT32_MIN, INT32_MIN),
                                  vec(INT32_MIN, INT32_MIN, INT32_MIN)), STP_FIX_MAX);
}

/* Unity tolerances (fix.h documents "full precision", no number): the
 * components are scaled to ~30 bits, so each output component is a truncated
 * quotient by a floor root: within 1 LSB of v_i/|v|, 2 allowed.  The unit
 * length is then within UNIT_LEN_TOL LSB of 1.  The returned |v| is the floor
 * root: within 1 LSB, except when the largest component is >= 2^30 LSB and
 * the components are halved first (each halving truncates, the root is
 * doubled): within 4 LSB there (a relative 2^-28). */
#if STP_SQRT_FAST
/* the fast root is within 2^-15 relative: 2 more LSB on each component and
 * on the unit length, and 2^-15 of |v| on the returned length */
#define UNIT_COMPONENT_TOL 4.0
#define UNIT_LEN_TOL 5.0
#define UNIT_RET_TOL(big) (((big) ? 4.0 : 1.0) + len * 0x1p-15)
#else
#define UNIT_COMPONENT_TOL 2.0
#define UNIT_LEN_TOL 3.0
#define UNIT_RET_TOL(big) ((big) ? 4.0 : 1.0)
#endif

static void check_unity(stp_vec3 v)
{
    stp_vec3 u = vec(12345, 12345, 12345);
    double dx = v.x, dy = v.y, dz = v.z; /* in LSB */
    double len = sqrt(dx * dx + dy * dy + dz * dz);
    stp_fix ret = stp_vec3_unity(v, &u);
    double ulen = sqrt((double)u.x * u.x + (double)u.y * u.y + (double)u.z * u.z);
    int big;
    if (len == 0.0) {
        assert_int_equal(ret, 0);
        assert_true(u.x == 0 && u.y == 0 && u.z == 0);
        return;
    }
    big = labs((long)v.x) >= (1L << 30) || labs((long)v.y) >= (1L << 30) || labs((long)v.z) >= (1L << 30);
    if (len >= (double)STP_FIX_MAX) {
        /* saturated: MAX, or within the tolerance of it */
        if (!(ret <= STP_FIX_MAX && (double)ret >= (double)STP_FIX_MAX - UNIT_RET_TOL(big)))
            fail_msg("unity(%d,%d,%d) returned %d, |v| = %.3f LSB saturates", v.x, v.y, v.z, ret, len);
    } else if (!(fabs((double)ret - len) <= UNIT_RET_TOL(big)))
        fail_msg("unity(%d,%d,%d) returned %d, |v| = %.3f LSB", v.x, v.y, v.z, ret, len);
    if (!(fabs(u.x - dx / len * ONE) <= UNIT_COMPONENT_TOL &&
          fabs(u.y - dy / len * ONE) <= UNIT_COMPONENT_TOL &&
          fabs(u.z - dz / len * ONE) <= UNIT_COMPONENT_TOL))
        fail_msg("unity(%d,%d,%d) = (%d,%d,%d)", v.x, v.y, v.z, u.x, u.y, u.z);
    if (!(fabs(ulen - (double)ONE) <= UNIT_LEN_TOL))
        fail_msg("unity(%d,%d,%d): |out| = %.3f LSB, want %d", v.x, v.y, v.z, ulen, ONE);
}

static void test_vec3_unity_random(void **state)
{
    int i;
    (void)state;
    prng_seed(12);
    for (i = 0; i < 4 * CASES; i++) {
        /* a common magnitude scale so the components are comparable, as in
         * real direction vectors; then random ones of independent scale */
        if (i % 2 == 0) {
            int bits = 1 + (int)prng_below(31);
            stp_fix lim = (stp_fix)(((uint64_t)1 << bits) - 1);
            stp_vec3 v = vec((stp_fix)((int64_t)prng_below(2u * (uint64_t)lim + 1) - lim),
                             (stp_fix)((int64_t)prng_below(2u * (uint64_t)lim + 1) - lim),
                             (stp_fix)((int64_t)prng_below(2u * (uint64_t)lim + 1) - lim));
            check_unity(v);
        } else {
            check_unity(vec(rand_fix(), rand_fix(), rand_fix()));
        }
    }
}

static void test_vec3_unity_tiny_and_huge(void **state)
{
    (void)state;
    /* 1 LSB vectors keep full precision */
    check_unity(vec(1, 0, 0));
    check_unity(vec(0, -1, 0));
    check_unity(vec(0, 0, 1));
    check_unity(vec(1, 1, 1));
    check_unity(vec(1, -1, 0));
    check_unity(vec(1, 2, 3));
    check_unity(vec(-3, 1, 2));
    /* huge: components at the limits; |v| saturates */
    check_unity(vec(STP_FIX_MAX, STP_FIX_MAX, STP_FIX_MAX));
    check_unity(vec(STP_FIX_MIN, STP_FIX_MAX, 0));
    check_unity(vec(STP_FIX_MAX, 1, 0));
    check_unity(vec(INT32_MIN, 0, 0));
    check_unity(vec(INT32_MIN, INT32_MIN, INT32_MIN));
    check_unity(vec(1, STP_FIX_MAX, -1));
    check_unity(vec((stp_fix)1 << 30, (stp_fix)1 << 30, 0));
    check_unity(vec(((stp_fix)1 << 29) - 1, 1, 1));
    /* zero: no direction */
    check_unity(vec(0, 0, 0));
    {
        stp_vec3 u;
        assert_int_equal(stp_vec3_unity(vec(3 * ONE, 0, 4 * ONE), &u), 5 * ONE);
        assert_true(abs(u.x - stp_fix_from_ratio(3, 5)) <= 1);
        assert_true(abs(u.z - stp_fix_from_ratio(4, 5)) <= 1);
        assert_int_equal(u.y, 0);
    }
}

/* Model transforms (transform.h) against double: random rotations about
 * the three axes, scales and moves, applied to random points; the error
 * stays within |p| 2^-12 + 4 steps (the rotation entries carry sin/cos's
 * 2^-14).  The identity leaves points exactly as they are. */
static void test_transform_against_double(void **state)
{
    const double pi = 3.14159265358979323846, step = 1.0 / STP_FIX_ONE;
    uint32_t seed = 99u;
    double worst = 0;
    int i, k;
    (void)state;
    for (i = 0; i < 2000; i++) {
        stp_transform t;
        double m[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, tr[3] = {0, 0, 0}, r[12];
        stp_vec3 p, q;
        double pd[3], qd[3], err, mag;
        int a, b, c;
        for (k = 0; k < 12; k++) {
            seed = seed * 1664525u + 1013904223u;
            r[k] = (double)(seed >> 8) / (double)(1u << 24);
        }
        stp_transform_identity(&t);
        for (k = 0; k < 3; k++) {
            /* rotate about axis k by an angle of 16 fractional bits */
            stp_fix deg = (stp_fix)((r[k] * 720 - 360) * 65536) * (STP_FIX_ONE / 4096) / 16;
            double th = (double)deg * step * pi / 180, cth = cos(th), sth = sin(th), n[3][3];
            int u = (k + 1) % 3, v = (k + 2) % 3;
            stp_transform_rotate(&t, k, deg);
            for (a = 0; a < 3; a++) {
                for (b = 0; b < 3; b++) {
                    double rot_ab = a == b ? 1 : 0;
                    if (a == u && b == u) rot_ab = cth;
                    if (a == u && b == v) rot_ab = -sth;
                    if (a == v && b == u) rot_ab = sth;
                    if (a == v && b == v) rot_ab = cth;
                    n[a][b] = rot_ab;
                }
            }
            {
                double mm[3][3], tt[3];
                for (a = 0; a < 3; a++) {
                    tt[a] = 0;
                    for (b = 0; b < 3; b++) {
                        mm[a][b] = 0;
                        for (c = 0; c < 3; c++)
                            mm[a][b] += n[a][c] * m[c][b];
                        tt[a] += n[a][b] * tr[b];
                    }
                }
                memcpy(m, mm, sizeof m);
                memcpy(tr, tt, sizeof tr);
            }
        }
        {
            stp_fix s = (stp_fix)((0.5 + r[3] * 2) * STP_FIX_ONE);
            stp_vec3 d;
            stp_transform_scale(&t, s, s, s);
            for (a = 0; a < 3; a++) {
                for (b = 0; b < 3; b++)
                    m[a][b] *= (double)s * step;
                tr[a] *= (double)s * step;
            }
            d.x = (stp_fix)((r[4] * 20 - 10) * STP_FIX_ONE);
            d.y = (stp_fix)((r[5] * 20 - 10) * STP_FIX_ONE);
            d.z = (stp_fix)((r[6] * 20 - 10) * STP_FIX_ONE);
            stp_transform_translate(&t, d);
            tr[0] += d.x * step;
            tr[1] += d.y * step;
            tr[2] += d.z * step;
        }
        p.x = (stp_fix)((r[7] * 40 - 20) * STP_FIX_ONE);
        p.y = (stp_fix)((r[8] * 40 - 20) * STP_FIX_ONE);
        p.z = (stp_fix)((r[9] * 40 - 20) * STP_FIX_ONE);
        pd[0] = p.x * step;
        pd[1] = p.y * step;
        pd[2] = p.z * step;
        q = stp_transform_point(&t, p);
        mag = sqrt(pd[0] * pd[0] + pd[1] * pd[1] + pd[2] * pd[2]) * (0.5 + r[3] * 2);
        for (a = 0; a < 3; a++) {
            qd[a] = tr[a];
            for (b = 0; b < 3; b++)
                qd[a] += m[a][b] * pd[b];
        }
        err = fabs(q.x * step - qd[0]);
        if (fabs(q.y * step - qd[1]) > err)
            err = fabs(q.y * step - qd[1]);
        if (fabs(q.z * step - qd[2]) > err)
            err = fabs(q.z * step - qd[2]);
        assert_true(err <= mag / 4096 + 4 * step);
        if (err > worst)
            worst = err;
    }
    print_message("model transforms vs double, 2000 random: worst error %.2e units\n", worst);
    {
        stp_transform t;
        stp_vec3 p = {123456, -98765, 4321}, q;
        stp_transform_identity(&t);
        q = stp_transform_point(&t, p);
        assert_int_equal(q.x, p.x);
        assert_int_equal(q.y, p.y);
        assert_int_equal(q.z, p.z);
    }
}

/* stp_div3_toward_zero equals C's v / 3 at the ends of the range, around
 * every power of two and multiple of 3 near them, and at random values */
static void test_div3_toward_zero_matches_operator(void **state)
{
    int32_t k, b;
    uint32_t seed = 12345u;
    (void)state;
    for (b = 0; b < 31; b++)
        for (k = -4; k <= 4; k++) {
            int32_t v = (int32_t)(((uint32_t)1 << b) + (uint32_t)k);
            assert_int_equal(stp_div3_toward_zero(v), v / 3);
            assert_int_equal(stp_div3_toward_zero(-v), -v / 3);
        }
    for (k = 0; k < 8; k++) {
        assert_int_equal(stp_div3_toward_zero(INT32_MAX - k), (INT32_MAX - k) / 3);
        assert_int_equal(stp_div3_toward_zero(INT32_MIN + k), (INT32_MIN + k) / 3);
    }
    for (k = 0; k < 1000000; k++) {
        int32_t v;
        seed = seed * 1664525u + 1013904223u;
        v = (int32_t)seed;
        assert_int_equal(stp_div3_toward_zero(v), v / 3);
    }
}

/* stp_div3_u30 (two 32-bit products on the 32-bit targets) equals C's
 * u / 3 for every u below 2^20, around every split u = a 2^14 + b (b at
 * either end, every a) and at random values up to 2^30 */
static void test_div3_u30_matches_operator(void **state)
{
    uint32_t u, a, seed = 777u;
    int32_t k;
    (void)state;
    for (u = 0; u < ((uint32_t)1 << 20); u++)
        assert_int_equal(stp_div3_u30(u), u / 3u);
    for (a = 0; a < ((uint32_t)1 << 16); a++)
        for (k = 0; k < 4; k++) {
            u = (a << 14) + (uint32_t)k;
            assert_int_equal(stp_div3_u30(u), u / 3u);
            u = (a << 14) + 0x3FFFu - (uint32_t)k;
            assert_int_equal(stp_div3_u30(u), u / 3u);
        }
    for (k = 0; k < 1000000; k++) {
        seed = seed * 1664525u + 1013904223u;
        u = seed >> 2;
        assert_int_equal(stp_div3_u30(u), u / 3u);
    }
}

/* STP_UNIT normalisation (fix_private.h) against double: random vectors of
 * every magnitude from 1 to 2^61, each component within 4 units of Q30
 * (4e-9) of the exact direction and the length within 2^-27 relative plus
 * half a unit (it is rounded to the input's units); the
 * zero vector gives 0.  Also the scalar reciprocal root and fast root. */
static void test_unit_from64_against_double(void **state)
{
    uint64_t seed = 0x1234567ull;
    double worst_c = 0, worst_l = 0;
    int i, k;
    stp_unit3 u;
    (void)state;
    for (i = 0; i < 20000; i++) {
        int64_t v[3];
        double d[3], len, got;
        int bits;
        seed = seed * 6364136223846793005ull + 1442695040888963407ull;
        bits = 1 + (int)((seed >> 58) % 61);
        for (k = 0; k < 3; k++) {
            seed = seed * 6364136223846793005ull + 1442695040888963407ull;
            v[k] = (int64_t)(seed >> 3) >> (61 - bits);
            d[k] = (double)v[k];
        }
        len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        got = (double)stp_unit_from64(v[0], v[1], v[2], &u);
        if (len == 0) {
            assert_true(got == 0);
            continue;
        }
        /* rounded to nearest: half a unit on top of the relative error */
        if ((fabs(got - len) - 0.5) / len > worst_l)
            worst_l = (fabs(got - len) - 0.5) / len;
        for (k = 0; k < 3; k++) {
            double c = (k == 0 ? u.x : (k == 1 ? u.y : u.z)) / 1073741824.0, e = fabs(c - d[k] / len);
            if (e > worst_c)
                worst_c = e;
        }
    }
    print_message("STP_UNIT normalisation, 20000 random vectors: worst component error %.2e, "
                  "length %.2e relative\n", worst_c, worst_l);
    assert_true(worst_c <= 4.0 / 1073741824.0);
    assert_true(worst_l <= 1.0 / 134217728.0);
    assert_true(stp_unit_from64(0, 0, 0, &u) == 0 && u.x == 0 && u.y == 0 && u.z == 0);
    for (i = 0; i < 2000; i++) {
        uint64_t x;
        int e;
        double r;
        seed = seed * 6364136223846793005ull + 1442695040888963407ull;
        x = (seed >> (seed & 63)) | 1u;
        r = (double)stp_rsqrt64(x, &e) * pow(2.0, -e);
        assert_true(fabs(r * sqrt((double)x) - 1) < 1.0 / 268435456.0);
        r = (double)stp_sqrt64_fast(x);
        assert_true(fabs(r - sqrt((double)x)) <= sqrt((double)x) / 268435456.0 + 1);
    }
}

/* stp_unit_from64 and stp_unit_q14_from64 against their definition in
 * native 64-bit words: v scaled so the largest component has 30 bits,
 * inv = stp_rsqrt64(v.v) (2^-(e + 30)), each component floor((v inv +
 * 2^(e-1)) / 2^e) and q14 floor((that + 2^15) / 2^16).  The builds with
 * a 32-bit but no 64-bit product (STP_NARROW_FORMS: test_fix_narrow in the
 * plain build, ARMv6-M) form these in 32-bit words: millions of int32
 * vectors of every bit length (the length drawn first), with zero
 * components, the extremes and tiny vectors; the special vectors meet
 * ties of both roundings. */
static int64_t unit_reference(int64_t x, int64_t y, int64_t z, int64_t out[3])
{
    uint64_t m = 0, s;
    int64_t v[3] = {x, y, z}, inv;
    int k, bits = 0, up, ex;
    for (k = 0; k < 3; k++)
        m |= v[k] < 0 ? 0u - (uint64_t)v[k] : (uint64_t)v[k];
    while (bits < 64 && (m >> bits) != 0)
        bits++;
    up = 30 - bits;
    for (k = 0; k < 3; k++)
        v[k] = up >= 0 ? v[k] * ((int64_t)1 << up) : v[k] >> -up; /* floor */
    s = (uint64_t)(v[0] * v[0]) + (uint64_t)(v[1] * v[1]) + (uint64_t)(v[2] * v[2]);
    inv = (int64_t)stp_rsqrt64(s, &ex);
    ex -= 30;
    for (k = 0; k < 3; k++)
        out[k] = (v[k] * inv + ((int64_t)1 << (ex - 1))) >> ex;
    return ex;
}

static void check_unit_exact(int64_t x, int64_t y, int64_t z)
{
    int64_t ref[3];
    int16_t q[3];
    stp_unit3 u;
    int k;
    if ((x | y | z) == 0) {
        assert_int_equal(stp_unit_q14_from64(x, y, z, q), 0);
#if STP_NARROW_FORMS
        assert_int_equal(stp_unit_q14_from32(0, 0, 0, q), 0);
#endif
        return;
    }
    (void)unit_reference(x, y, z, ref);
    (void)stp_unit_from64(x, y, z, &u);
    assert_true(u.x == ref[0] && u.y == ref[1] && u.z == ref[2]);
    assert_int_equal(stp_unit_q14_from64(x, y, z, q), 1);
    for (k = 0; k < 3; k++)
        if (q[k] != (int16_t)((ref[k] + (1 << 15)) >> 16))
            fail_msg("q14 (%lld %lld %lld)[%d]: %d, expected %lld", (long long)x, (long long)y,
                     (long long)z, k, q[k], (long long)((ref[k] + (1 << 15)) >> 16));
#if STP_NARROW_FORMS
    /* the int32 entry: the same values */
    if (x == (int32_t)x && y == (int32_t)y && z == (int32_t)z) {
        int16_t q32[3];
        assert_int_equal(stp_unit_q14_from32((int32_t)x, (int32_t)y, (int32_t)z, q32), 1);
        assert_true(q32[0] == q[0] && q32[1] == q[1] && q32[2] == q[2]);
    }
#endif
}

static void test_unit_exact_int32(void **state)
{
    static const int32_t special[] = {0, 1, -1, 2, -2, 3, 0x7FFFFFFF, -0x7FFFFFFF, INT32_MIN,
                                      0x40000000, -0x40000000, 0x3FFFFFFF, 46341, -46341};
    const int ns = (int)(sizeof special / sizeof special[0]);
    uint64_t seed = 0x9E3779B97F4A7C15ull;
    long i;
    int a, b, c, k;
    (void)state;
    for (a = 0; a < ns; a++)
        for (b = 0; b < ns; b++)
            for (c = 0; c < ns; c++)
                check_unit_exact(special[a], special[b], special[c]);
    for (i = 0; i < 3000000; i++) {
        int64_t v[3];
        for (k = 0; k < 3; k++) {
            int bits;
            seed = seed * 6364136223846793005ull + 1442695040888963407ull;
            bits = (int)((seed >> 59) % 32); /* 0..31 bits */
            switch ((seed >> 40) & 15) {
            case 0:
                v[k] = 0;
                break;
            case 1:
                v[k] = (seed & 1) ? 0x7FFFFFFF : -0x7FFFFFFF;
                break;
            default:
                v[k] = bits == 0 ? 0 : (int64_t)((seed >> 8) & ((1ull << bits) - 1));
                if (seed & 2)
                    v[k] = -v[k];
            }
        }
        check_unit_exact(v[0], v[1], v[2]);
    }
}

/* stp_rsqrt64 for m in [2^30, 2^32) (rsqrt_q30's range: bit length 31 or
 * 32, no shift, exponent 45) against its definition in native 64-bit
 * words: the seed 1/sqrt(1 + (i + 1/2) / 64) in Q16 rounded (fix.c's
 * table), two Newton steps y <- floor(y (3 2^30 - floor(m floor(y^2 /
 * 2^30) / 2^30)) / 2^31).  The builds without a 64-bit product form the
 * second step from m y^2's distance to 2^60 (fix.c's rsqrt_step_narrow):
 * both ends of every seed's interval, the m where that distance is
 * greatest, and millions of random m. */
static uint32_t rsqrt_reference(uint32_t m)
{
    double i = (double)((m >> 24) - 64);
    uint64_t y = (uint64_t)floor(65536.0 / sqrt(1.0 + (i + 0.5) / 64.0) + 0.5) << 14;
    int k;
    for (k = 0; k < 2; k++) {
        uint64_t y2 = (y * y) >> 30;
        uint64_t my2 = ((uint64_t)m * y2) >> 30;
        y = (y * (((uint64_t)3 << 30) - my2)) >> 31;
    }
    return (uint32_t)y;
}

static void check_rsqrt_exact(uint32_t m)
{
    int e = 0;
    uint32_t got = stp_rsqrt64(m, &e), want = rsqrt_reference(m);
    if (got != want || e != 45)
        fail_msg("rsqrt(%lu): %lu 2^-%d, expected %lu 2^-45", (unsigned long)m, (unsigned long)got, e,
                 (unsigned long)want);
}

static void test_rsqrt_exact(void **state)
{
    /* the greatest and least 2^30 - my2 (48707 and -1), halfway */
    static const uint32_t special[] = {1073741826u, 1098903240u, 0x80000000u, 0xC0000000u};
    uint64_t seed = 0xD1B54A32D192ED03ull;
    uint32_t i, d;
    (void)state;
    for (i = 0; i < sizeof special / sizeof special[0]; i++)
        for (d = 0; d < 64; d++) {
            if (special[i] - d >= 0x40000000u)
                check_rsqrt_exact(special[i] - d);
            check_rsqrt_exact(special[i] + d);
        }
    for (i = 64; i < 256; i++)
        for (d = 0; d < 4096; d++) {
            check_rsqrt_exact((i << 24) + d);
            check_rsqrt_exact((i << 24) + 0xFFFFFFu - d);
        }
    for (i = 0; i < 4000000; i++) {
        seed = seed * 6364136223846793005ull + 1442695040888963407ull;
        check_rsqrt_exact((uint32_t)(((seed >> 32) * 3u) >> 2) + 0x40000000u);
    }
}

/* stp_rsqrt_norm at the middle of each 64th of [1, 4) (2^30 units) is
 * 2^15 times stp_rsqrt64's seed there, round(2^16 / sqrt(D / 128)) for D
 * = 129, 131, .., 511, within half a unit: builds for size take the
 * seeds from it (fix.c's RSQRT_SEED) */
static void test_rsqrt_seeds_from_norm(void **state)
{
    uint32_t d;
    (void)state;
    for (d = 129; d < 512; d += 2) {
        uint64_t s = (stp_rsqrt_norm(d << 23) + 0x4000u) >> 15, two41 = (uint64_t)1 << 41;
        /* round(sqrt(2^39 / d)) = s: d (2 s - 1)^2 <= 2^41 < d (2 s + 1)^2 */
        if (d * (2 * s - 1) * (2 * s - 1) > two41 || d * (2 * s + 1) * (2 * s + 1) <= two41)
            fail_msg("seed %lu for D %lu is not the rounded root", (unsigned long)s, (unsigned long)d);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_rsqrt_seeds_from_norm),
        cmocka_unit_test(test_from_int_and_ratio),
        cmocka_unit_test(test_add_sub_saturate),
        cmocka_unit_test(test_mul_rounds_to_nearest),
        cmocka_unit_test(test_mul_saturates_at_extremes),
        cmocka_unit_test(test_div_truncates_toward_zero),
        cmocka_unit_test(test_div_by_zero_and_overflow_saturate),
        cmocka_unit_test(test_isqrt64_is_exact_floor),
        cmocka_unit_test(test_isqrt32_is_exact_floor),
        cmocka_unit_test(test_sqrt_is_floor_of_root),
        cmocka_unit_test(test_sqrt_of_negative_and_extremes),
        cmocka_unit_test(test_sqrt_wide_is_floor_and_saturates),
        cmocka_unit_test(test_log2_within_two_lsb),
        cmocka_unit_test(test_exp2_relative_error),
        cmocka_unit_test(test_exp2_saturates_and_underflows),
        cmocka_unit_test(test_pow_against_double),
        cmocka_unit_test(test_sin_cos_within_2e14_any_angle),
        cmocka_unit_test(test_sin_cos_at_range_ends),
        cmocka_unit_test(test_vec3_dot_rounds_and_saturates),
        cmocka_unit_test(test_vec3_unity_random),
        cmocka_unit_test(test_vec3_unity_tiny_and_huge),
        cmocka_unit_test(test_transform_against_double),
        cmocka_unit_test(test_div3_toward_zero_matches_operator),
        cmocka_unit_test(test_div3_u30_matches_operator),
        cmocka_unit_test(test_unit_from64_against_double),
        cmocka_unit_test(test_unit_exact_int32),
        cmocka_unit_test(test_rsqrt_exact),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
