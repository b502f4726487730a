/* SPDX-License-Identifier: MIT */
/*
 * stp_view_transform_point built for 32-bit targets (STP_WIDE_ARITH 0:
 * view.c's products from 16-bit halves, this test's own copy of view.c)
 * against the plain 64-bit formula, floor((p . axis - from . axis) / 2^16)
 * saturated to stp_fix: the same value for random points over the whole
 * int32 range (both of view.c's cases: every |coordinate| below 2^28, and
 * not), unit axes (exactly +-1 among them) and eyes; the one perspective
 * projection's 32-bit form against C's 64-bit division.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include <cmocka.h>

#include "view_private.h"

#if STP_WIDE_ARITH
#error "this test is built with STP_WIDE_ARITH 0"
#endif

#define TEST_RANDOM_SEED 0x9E3779B97F4A7C15u
#include "test_random.h" /* next_random */

/* a random int32 of a random bit length (small and huge values alike) */
static int32_t random_coordinate(void)
{
    int bits = (int)(next_random() % 32);
    int32_t v = (int32_t)(next_random() & (((uint32_t)1 << bits) - 1u));
    if (next_random() & 1u)
        v = -v;
    return (next_random() % 16u) == 0 ? (int32_t)next_random() : v;
}

/* an axis component in [-2^16, 2^16]: exactly +-1 or 0 one time in four */
static int32_t random_axis(void)
{
    static const int32_t exact[4] = {65536, -65536, 0, 46341};
    if (next_random() % 4u == 0)
        return exact[next_random() % 4u];
    return (int32_t)(next_random() % 131073u) - 65536;
}

static stp_fix reference(stp_vec3 p, stp_vec3 a, int64_t from)
{
    int64_t v = (int64_t)p.x * a.x + (int64_t)p.y * a.y + (int64_t)p.z * a.z - from;
    int64_t q = v >= 0 ? v / 65536 : -((-v + 65535) / 65536); /* floor */
    return q > INT32_MAX ? STP_FIX_MAX : q < -INT32_MAX ? STP_FIX_MIN : (stp_fix)q;
}

static void test_exact(void **state)
{
    long i, saturated = 0, small = 0;
    (void)state;
    for (i = 0; i < 2000000; i++) {
        stp_view_transform t;
        stp_vec3 p, out, axis[3], from;
        int k;
        for (k = 0; k < 3; k++) {
            axis[k].x = random_axis();
            axis[k].y = random_axis();
            axis[k].z = random_axis();
        }
        from.x = random_coordinate();
        from.y = random_coordinate();
        from.z = random_coordinate();
        stp_view_transform_of_axes(axis[0], axis[1], axis[2], from, &t);
        assert_true(t.from_right == (int64_t)from.x * axis[0].x + (int64_t)from.y * axis[0].y +
                                        (int64_t)from.z * axis[0].z);
        p.x = random_coordinate();
        p.y = random_coordinate();
        p.z = random_coordinate();
        stp_view_transform_point(&t, p, &out);
        assert_int_equal(out.x, reference(p, t.right, t.from_right));
        assert_int_equal(out.y, reference(p, t.up, t.from_up));
        assert_int_equal(out.z, reference(p, t.forward, t.from_forward));
        saturated += out.x == STP_FIX_MAX || out.x == STP_FIX_MIN;
        small += llabs(p.x) < (1 << 28) && llabs(p.y) < (1 << 28) && llabs(p.z) < (1 << 28);
    }
    /* both the exact and the saturated ranges were visited */
    assert_true(saturated > 1000 && saturated < 1000000);
    assert_true(small > 100000 && small < 1900000);
}

/* Axes of squared length up to 5 2^30 (view.c's short form for a unit
 * transform) and just past it, points up to the short form's edges
 * (-2^28 and 2^28 - 1 per coordinate, signs with and against the axis)
 * and eyes below and at the narrow bound: the same values as the 64-bit
 * formula, and the short form was taken. */
static void test_unit_axes(void **state)
{
    static const int32_t ends[] = {-(1 << 28), (1 << 28) - 1, -(1 << 28) + 1, (1 << 28) - 16385, 16383, -16384, 0};
    long i, unit = 0;
    (void)state;
    for (i = 0; i < 400000; i++) {
        stp_view_transform t;
        stp_vec3 p, out, axis[3], from;
        int k;
        for (k = 0; k < 3; k++) {
            /* a random direction scaled to about 73271 (sqrt(5 2^30)), or
             * one component that large */
            int32_t big = 73271 + (int32_t)(next_random() % 5u) - 2;
            if (next_random() % 3u == 0) {
                axis[k].x = (next_random() & 1u) ? big : -big;
                axis[k].y = (int32_t)(next_random() % 9u) - 4;
                axis[k].z = 0;
            } else {
                axis[k].x = (int32_t)(next_random() % 84601u) - 42300;
                axis[k].y = (int32_t)(next_random() % 84601u) - 42300;
                axis[k].z = (int32_t)(next_random() % 84601u) - 42300;
            }
        }
        from.x = (int32_t)(next_random() % 0x20000001u) - 0x10000000;
        from.y = i % 5 == 0 ? INT32_MAX : (int32_t)(next_random() % 0x20000001u) - 0x10000000;
        from.z = (int32_t)(next_random() % 0x20000001u) - 0x10000000;
        stp_view_transform_of_axes(axis[0], axis[1], axis[2], from, &t);
        unit += t.unit;
        p.x = (next_random() & 1u) ? ends[next_random() % 7u] : random_coordinate();
        p.y = (next_random() & 1u) ? ends[next_random() % 7u] : random_coordinate();
        p.z = (next_random() & 1u) ? ends[next_random() % 7u] : random_coordinate();
        stp_view_transform_point(&t, p, &out);
        assert_int_equal(out.x, reference(p, t.right, t.from_right));
        assert_int_equal(out.y, reference(p, t.up, t.from_up));
        assert_int_equal(out.z, reference(p, t.forward, t.from_forward));
    }
#if STP_NARROW_FORMS
    assert_true(unit > 10000 && unit < 390000);
#else
    assert_true(unit == 0);
#endif
}

/* view.c's short form at its extremes: axes of three components of
 * magnitude 42299 (the longest equal components view.c takes as unit),
 * points whose low 14 bits are all 0 or all 16383 (the part below the
 * estimate's 2^14 steps at its largest, |L| = 0.968 2^31: the estimate
 * is then 31724 below or 31723 above the value, against the 2^15 it may
 * be off), high parts up to the edges of [-2^28, 2^28), signs with and
 * against the axis, and eyes over the narrow range: the 64-bit formula's
 * values, and the short form taken. */
static void test_unit_extremes(void **state)
{
    long i, unit = 0;
    (void)state;
    for (i = 0; i < 1000000; i++) {
        stp_view_transform t;
        stp_vec3 p, out, axis[3], from;
        int32_t c[3];
        int k;
        for (k = 0; k < 3; k++) {
            axis[k].x = (next_random() & 1u) ? 42299 : -42299;
            axis[k].y = (next_random() & 1u) ? 42299 : -42299;
            axis[k].z = (next_random() & 1u) ? 42299 : -42299;
        }
        for (k = 0; k < 3; k++) {
            /* h in [-2^14, 2^14): the edges one time in four */
            int32_t h = (next_random() % 4u == 0) ? ((next_random() & 1u) ? 16383 : -16384)
                                                  : (int32_t)(next_random() % 32768u) - 16384;
            int32_t l = (next_random() % 8u == 0) ? (int32_t)(next_random() % 16384u)
                                                  : ((next_random() & 1u) ? 16383 : 0);
            c[k] = h * 16384 + l;
        }
        p.x = c[0];
        p.y = c[1];
        p.z = c[2];
        from.x = (int32_t)(next_random() % 0x2001u) - 0x1000;
        from.y = (int32_t)(next_random() % 0x2001u) - 0x1000;
        from.z = (int32_t)(next_random() % 0x2001u) - 0x1000;
        stp_view_transform_of_axes(axis[0], axis[1], axis[2], from, &t);
        unit += t.unit;
        stp_view_transform_point(&t, p, &out);
        assert_int_equal(out.x, reference(p, t.right, t.from_right));
        assert_int_equal(out.y, reference(p, t.up, t.from_up));
        assert_int_equal(out.z, reference(p, t.forward, t.from_forward));
    }
#if STP_NARROW_FORMS
    assert_true(unit == 1000000);
#else
    assert_true(unit == 0);
#endif
}

/* The 32-bit difference of a point below 2^28 and an eye within int32
 * at its edges: exactly -2^31 (saturated to STP_FIX_MIN, -(2^31 - 1)),
 * wrapping below and above int32, and just inside it. */
static void test_edges(void **state)
{
    static const int32_t cases[][2] = {
        /* p.x, from.x: view x = p.x - from.x with the identity axes */
        {-(1 << 27), 2013265920},         /* -2^31 exactly */
        {-(1 << 27), INT32_MAX},          /* below -2^31: wraps */
        {(1 << 27), -INT32_MAX},          /* above 2^31 - 1: wraps */
        {(1 << 27) - 1, -2013265920},     /* 2^31 - 1 exactly */
        {-(1 << 27) + 1, 2013265920},     /* -2^31 + 1 exactly */
        {5, 3},
    };
    size_t i;
    (void)state;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        stp_view_transform t;
        stp_vec3 right = {65536, 0, 0}, up = {0, 65536, 0}, forward = {0, 0, 65536}, from, p, out;
        from.x = cases[i][1];
        from.y = from.z = 0;
        p.x = cases[i][0];
        p.y = p.z = 0;
        stp_view_transform_of_axes(right, up, forward, from, &t);
        stp_view_transform_point(&t, p, &out);
        assert_int_equal(out.x, reference(p, t.right, t.from_right));
        assert_int_equal(out.y, 0);
    }
}

/* floor(v / 2^s) of a 64-bit value, by plain division (no shift of a
 * negative value) */
static int64_t floor_div_pow2(int64_t v, int s)
{
    int64_t d = (int64_t)1 << s, q = v / d;
    return (v % d != 0 && v < 0) ? q - 1 : q;
}

/* stp_view_perspective of p against C's 64-bit division: the offsets
 * floor(trunc(focal x / z) 2^-12) and the key trunc(hither 2^30 / z), z
 * raised to hither */
static void check_perspective(stp_fix focal, stp_fix hither, stp_vec3 p)
{
    int64_t x, y, z = p.z < hither ? hither : p.z;
    int32_t key;
    stp_view_perspective(focal, hither, p, &x, &y, &key);
    assert_true(x == floor_div_pow2(((int64_t)focal * p.x) / z, STP_FIX_FRAC_BITS - STP_SUBPIXEL_BITS));
    assert_true(y == floor_div_pow2(((int64_t)focal * p.y) / z, STP_FIX_FRAC_BITS - STP_SUBPIXEL_BITS));
    assert_true(key == (int32_t)((((int64_t)hither) << 30) / z));
}

/* stp_view_perspective's 32-bit form (the exact 32-bit quotients and the
 * 64-bit fallback by a reciprocal) against C's 64-bit division: the same
 * offsets and depth key for random points, near and far, focal lengths and
 * hither distances, and z below hither raised to it. */
static void test_perspective(void **state)
{
    int i;
    (void)state;
    for (i = 0; i < 400000; i++) {
        stp_fix focal = (stp_fix)(1 + next_random() % (1u << (i % 4 == 0 ? 30 : 24)));
        stp_fix hither = (stp_fix)(1 + next_random() % (1u << (8 + i % 16)));
        int zbits = 1 + (int)(next_random() % 31), xbits = 1 + (int)(next_random() % 31);
        stp_vec3 p;
        p.x = (int32_t)(next_random() & (0xFFFFFFFFu >> (32 - xbits)));
        p.x = (next_random() & 1) ? p.x : -p.x;
        p.y = (int32_t)next_random() >> (next_random() % 32);
        p.z = (int32_t)(next_random() >> (32 - zbits)) & 0x7FFFFFFF;
        if (i % 7 == 0)
            p.z = -(int32_t)(next_random() >> 8); /* behind: raised to hither */
        check_perspective(focal, hither, p);
    }
}

/* The same at the 32-bit form's edges: focal and hither lengths from 1 to
 * 2^31 - 1, z from 1 (raised to hither) to past 2^29 (the 64-bit
 * quotients), |x| up to 2^31 - 1 and -2^31, each quotient near 2^31 and
 * each power of two of z and its neighbours (the reciprocal's
 * normalisation and its seed intervals' ends). */
static void test_perspective_edges(void **state)
{
    static const stp_fix lengths[] = {1, 2, 3, 4096, 65535, 65536, 65537, 3604480, 0x00FFFFFF, 0x40000000,
                                      0x7FFFFFFE, 0x7FFFFFFF};
    static const int32_t coords[] = {0, 1, -1, 4095, -65536, 65536, 0x0FFFFFFF, -0x10000000, 0x7FFFFFFF,
                                     -0x7FFFFFFF, INT32_MIN};
    size_t a, b, c, k;
    (void)state;
    for (k = 0; k < 31; k++) {
        int d;
        for (d = -1; d <= 1; d++) {
            int32_t z = (int32_t)(((uint32_t)1 << k) + (uint32_t)d);
            for (a = 0; a < sizeof lengths / sizeof lengths[0]; a++)
                for (b = 0; b < sizeof lengths / sizeof lengths[0]; b += 3)
                    for (c = 0; c < sizeof coords / sizeof coords[0]; c++) {
                        stp_fix focal = lengths[a], hither = lengths[b];
                        stp_vec3 p;
                        if (z <= 0)
                            continue;
                        p.x = coords[c];
                        p.y = coords[(c + 3) % (sizeof coords / sizeof coords[0])];
                        p.z = z;
                        check_perspective(focal, hither, p);
                    }
        }
    }
}

/* The offsets where floor(focal |x| / z) is at or near a multiple of
 * 2^(F - STP_SUBPIXEL_BITS) (the 32-bit form's estimate decides the
 * offset without its correction only away from those, and must agree with
 * the exact quotient there): points whose quotient is that multiple plus
 * -8..8, either sign, random focal lengths and depths. */
static void test_perspective_subpixel_edges(void **state)
{
    const int64_t unit = (int64_t)1 << (STP_FIX_FRAC_BITS - STP_SUBPIXEL_BITS);
    int i, d;
    (void)state;
    for (i = 0; i < 20000; i++) {
        stp_fix focal = (stp_fix)(1 + next_random() % (1u << (i % 3 == 0 ? 30 : 24)));
        stp_fix hither = (stp_fix)(1 + next_random() % (1u << 12));
        int32_t z = (int32_t)(hither + (int32_t)(next_random() % (1u << (4 + i % 25))));
        int64_t k = (int64_t)(next_random() % (1u << (4 + i % 16)));
        for (d = -8; d <= 8; d++) {
            /* the least x with floor(focal x / z) >= k unit + d */
            int64_t target = k * unit + d, x;
            stp_vec3 p;
            if (target < 0)
                continue;
            x = (target * z + focal - 1) / focal;
            if (x >= INT32_MAX)
                continue;
            p.x = (int32_t)x;
            p.y = -(int32_t)x;
            p.z = z;
            check_perspective(focal, hither, p);
            if (x > 0) {
                p.x = (int32_t)x - 1;
                p.y = 1 - (int32_t)x;
                check_perspective(focal, hither, p);
            }
        }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_exact),
        cmocka_unit_test(test_edges),
        cmocka_unit_test(test_unit_axes),
        cmocka_unit_test(test_unit_extremes),
        cmocka_unit_test(test_perspective),
        cmocka_unit_test(test_perspective_edges),
        cmocka_unit_test(test_perspective_subpixel_edges),
    };
    return cmocka_run_group_tests(tests, 0, 0);
}
