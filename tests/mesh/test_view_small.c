/* SPDX-License-Identifier: MIT */
/*
 * The geometry stage's transform for points near the eye (view.c:
 * stp_view_small_point, stp_view_compose_small; direct drawing's), built
 * twice: on the host's 64-bit arithmetic and on the 32-bit target
 * arithmetic (its 16 x 16-bit estimate and the products' sum mod 2^32).
 *   - every view coordinate against floor((a . p - from) / 2^16) formed
 *     here in 64 bits, for random and extreme axes (|a_i| < 2^17), points
 *     (|p_i| < 2^23) and eye terms (|high| < 2^26, low in [0, 2^16));
 *   - the composed transform against the renderer's
 *     (stp_view_transform_compose of stp_view_transform_of_axes): the same
 *     view coordinates for random points, rotations turned as direct
 *     drawing turns them, scales from 2^-6 to 2 and eyes up to 2^23 raw
 *     from the model; refused (0) exactly where the renderer's is (for
 *     similarities: below about 2^-6 the renderer takes its two steps and
 *     direct drawing refuses the model, its model frame unusable);
 *   - the face stage's side for direct drawing's ranges
 *     (stp_render_face_side_near) against the exact sign;
 *   - the face side's 32-bit estimate (stp_render_side_estimate) against
 *     the exact sign where it says it is sure.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include <cmocka.h>

#include "stipple/direct.h"
#include "render_private.h" /* stp_render_face_side_near */
#include "view_private.h"

#if STP_FIX_FRAC_BITS != 16
#error "this test is built with 16 fractional bits"
#endif

#define TEST_RANDOM_SEED 0x2545F4914F6CDD1Du
#include "test_random.h" /* next_random */

/* a value in (-limit, limit), its extremes one time in eight */
static int32_t random_within(int32_t limit)
{
    uint32_t r = next_random();
    if (r % 8u == 0)
        return (r & 16u) ? limit - 1 : -(limit - 1);
    return (int32_t)(next_random() % (2u * (uint32_t)limit - 1u)) - (limit - 1);
}

static stp_vec3 random_vec(int32_t limit)
{
    stp_vec3 v;
    v.x = random_within(limit);
    v.y = random_within(limit);
    v.z = random_within(limit);
    return v;
}

/* floor((a . p - (high 2^16 + low)) / 2^16) in 64 bits: |a . p| < 3 2^40 */
static int32_t reference(stp_vec3 a, stp_vec3 p, int32_t high, uint32_t low)
{
    int64_t s = (int64_t)a.x * p.x + (int64_t)a.y * p.y + (int64_t)a.z * p.z - ((int64_t)high * 65536 + low);
    int64_t q = s >= 0 ? s / 65536 : -((-s + 65535) / 65536);
    return (int32_t)q;
}

static void test_small_point_exact(void **state)
{
    long n;
    (void)state;
    for (n = 0; n < 400000; n++) {
        stp_vec3 axes[3], p, out;
        stp_view_small t;
        int32_t high = random_within((int32_t)1 << 26);
        uint32_t low = next_random() & 0xFFFFu;
        int k;
        for (k = 0; k < 3; k++)
            axes[k] = random_vec((int32_t)1 << 17);
        stp_view_small_of_axes(axes, high, low, &t);
        p = random_vec((int32_t)1 << 23);
        stp_view_small_point(&t, &p, &out);
        assert_int_equal(out.x, reference(axes[0], p, high, low));
        assert_int_equal(out.y, reference(axes[1], p, high, low));
        assert_int_equal(out.z, reference(axes[2], p, high, low));
    }
}

/* The 32-bit form's window at its edges: axis and point components whose
 * split leaves the largest remainders (a = 2^5 ah + al with al = 31 and
 * |ah| near 2^12, p = 2^11 ph + pl with pl = 2047 and |ph| near 2^12),
 * of either sign, with the eye terms' extremes: the products' remainder
 * reaches about 1.48 2^30 either way, past 2^30 (a window 2^15 wide on
 * either side of the estimate holds it; half that would not) */
static void test_small_point_extremes(void **state)
{
    static const int32_t axis_values[6] = {131071, -131041, 131039, -131071, 0, 65536};
    static const int32_t point_values[6] = {8388607, -8386561, -8388607, 2047, -1, 0};
    static const int32_t highs[3] = {0, ((int32_t)1 << 26) - 1, -((int32_t)1 << 26) + 1};
    static const uint32_t lows[2] = {0, 0xFFFFu};
    int ax, ay, az, px, py, pz, e;
    (void)state;
    for (ax = 0; ax < 6; ax++)
        for (ay = 0; ay < 6; ay++)
            for (az = 0; az < 6; az++)
                for (e = 0; e < 6; e++) {
                    stp_vec3 axes[3];
                    stp_view_small t;
                    int k;
                    for (k = 0; k < 3; k++) {
                        /* the three axes: the combination, turned */
                        axes[k].x = axis_values[(ax + k) % 6];
                        axes[k].y = axis_values[(ay + 2 * k) % 6];
                        axes[k].z = axis_values[(az + k) % 6];
                    }
                    stp_view_small_of_axes(axes, highs[e % 3], lows[e / 3], &t);
                    for (px = 0; px < 6; px++)
                        for (py = 0; py < 6; py++)
                            for (pz = 0; pz < 6; pz++) {
                                stp_vec3 p, out;
                                p.x = point_values[px];
                                p.y = point_values[py];
                                p.z = point_values[pz];
                                stp_view_small_point(&t, &p, &out);
                                assert_int_equal(out.x, reference(axes[0], p, highs[e % 3], lows[e / 3]));
                                assert_int_equal(out.y, reference(axes[1], p, highs[e % 3], lows[e / 3]));
                                assert_int_equal(out.z, reference(axes[2], p, highs[e % 3], lows[e / 3]));
                            }
                }
}

/* the renderer's composed transform of view (axes, from) and model m
 * with translation from - d against stp_view_compose_small's */
static int compare_compose(const stp_vec3 axes[3], const int32_t d[3], const stp_transform *model, stp_vec3 from)
{
    stp_view_transform view, composed;
    stp_view_small small;
    stp_transform m = *model;
    int ok_small, ok_full, n;
    m.t.x = from.x - d[0];
    m.t.y = from.y - d[1];
    m.t.z = from.z - d[2];
    stp_view_transform_of_axes(axes[0], axes[1], axes[2], from, &view);
    ok_full = stp_view_transform_compose(&view, &m, &composed);
    ok_small = stp_view_compose_small(axes, d, model, &small);
    if (!stp_view_similar(&m))
        return 0; /* no similarity (a scale near 2^-6): the renderer takes its
                     two steps, direct drawing refuses it (its model frame) */
    assert_int_equal(ok_small, ok_full);
    if (!ok_full)
        return 0;
    for (n = 0; n < 64; n++) {
        stp_vec3 p = random_vec((int32_t)1 << 23), a, b;
        stp_view_transform_point(&composed, p, &a);
        stp_view_small_point(&small, &p, &b);
        assert_int_equal(a.x, b.x);
        assert_int_equal(a.y, b.y);
        assert_int_equal(a.z, b.z);
    }
    return 1;
}

static void test_compose_is_the_renderers(void **state)
{
    long n, composed = 0;
    (void)state;
    for (n = 0; n < 20000; n++) {
        stp_vec3 axes[3], from, at, up, dir, zero = {0, 0, 0};
        stp_direct_model pose;
        stp_transform m;
        int32_t d[3];
        stp_fix scale;
        /* the view: a look-at's axes (unit, the renderer's) */
        from = random_vec((int32_t)1 << 22);
        at = random_vec((int32_t)1 << 22);
        up = random_vec((int32_t)1 << 16);
        dir.x = at.x - from.x; /* each below 2^23: no overflow */
        dir.y = at.y - from.y;
        dir.z = at.z - from.z;
        if (stp_view_axes(&dir, &up, axes) != STP_OK)
            continue;
        /* the model: a turn as direct drawing makes it, a scale in [2^-6, 2) */
        scale = (stp_fix)(1024 + next_random() % (2u * STP_FIX_ONE - 1024u));
        if (n % 16 == 0)
            scale = 2 * STP_FIX_ONE - 1 - (stp_fix)(next_random() % 64u); /* near 2: may be refused */
        stp_direct_model_turn(&pose, (uint16_t)next_random(), (uint16_t)next_random(), scale, zero);
        stp_direct_model_transform(&pose, &m);
        d[0] = random_within((int32_t)1 << 23);
        d[1] = random_within((int32_t)1 << 23);
        d[2] = random_within((int32_t)1 << 23);
        composed += compare_compose(axes, d, &m, from);
    }
    printf("%ld of 20000 models composed (the rest refused by both, or no similarity)\n", composed);
    assert_true(composed > 15000);
}

/* The face stage's side for direct drawing's ranges against the exact
 * sign formed here in 64 bits: random and extreme normals (|n_i| <= 2^14),
 * eyes (|.| < 2^30) and vertices (|.| < 2^23), and planes through the eye */
static void test_face_side_near(void **state)
{
    long k;
    (void)state;
    for (k = 0; k < 400000; k++) {
        stp_model_frame f;
        int16_t n[3];
        stp_vec3 v0;
        int64_t dot;
        int i, want;
        for (i = 0; i < 3; i++) {
            n[i] = (int16_t)random_within(16385);
            f.eye[i] = random_within((int32_t)1 << 30);
        }
        v0 = random_vec((int32_t)1 << 23);
        if (k % 5 == 0) { /* the eye in the face's plane, or a unit off it */
            n[0] = 16384;
            n[1] = 0;
            n[2] = 0;
            f.eye[0] = v0.x + (int32_t)(k % 3) - 1;
        }
        dot = (int64_t)n[0] * ((int64_t)f.eye[0] - v0.x) + (int64_t)n[1] * ((int64_t)f.eye[1] - v0.y) +
              (int64_t)n[2] * ((int64_t)f.eye[2] - v0.z);
        want = dot > 0 ? 1 : (dot < 0 ? -1 : 0);
        assert_int_equal(stp_render_face_side_near(&f, n, &v0), want);
    }
}

/* A unit normal rounded to Q1.14 (|n| <= 2^14 + 1): random, or one of
 * the largest |n_0| + |n_1| + |n_2| (all three near 2^14 / sqrt 3) */
static void random_unit_normal(int16_t n[3])
{
    double v[3], len = 0.0;
    int i;
    if (next_random() % 8u == 0) {
        for (i = 0; i < 3; i++)
            n[i] = (int16_t)((next_random() & 1u) ? 9459 : -9459);
        return;
    }
    do {
        len = 0.0;
        for (i = 0; i < 3; i++) {
            v[i] = (double)random_within(1 << 20);
            len += v[i] * v[i];
        }
    } while (len < 1.0);
    len = sqrt(len);
    for (i = 0; i < 3; i++)
        n[i] = (int16_t)lround(v[i] / len * 16384.0);
}

/* The face stage's 32-bit side estimate (stp_render_side_estimate, the
 * mesh route's and direct drawing's first test) against the exact sign
 * formed here in 64 bits: where it says its sign is sure it is the exact
 * side's, for unit normals, eyes below 2^30 and vertices within the bound
 * the estimate was made for (direct drawing's 2^23 - 1, or a mesh's box),
 * planes through the eye among them (never sure there).  Also counts the
 * faces left to the exact test: the estimate is of use only when few are. */
static void test_side_estimate(void **state)
{
    long k, unsure = 0, cases = 400000;
    (void)state;
    for (k = 0; k < cases; k++) {
        stp_model_frame f;
        stp_side_estimate e;
        int16_t n[3];
        stp_vec3 v0;
        int64_t dot;
        int32_t est, box = k % 2 ? ((int32_t)1 << 23) - 1 : (int32_t)(next_random() % ((uint32_t)1 << 23)) + 1;
        int i, want;
        random_unit_normal(n);
        for (i = 0; i < 3; i++)
            f.eye[i] = random_within((int32_t)1 << 30);
        v0 = random_vec(box + 1);
        if (k % 7 == 0) { /* the eye on the face's plane, or a unit off it, near the face */
            n[0] = 16384;
            n[1] = 0;
            n[2] = 0;
            f.eye[0] = v0.x + (int32_t)(k % 3) - 1;
            f.eye[1] = v0.y + random_within(1 << 16);
            f.eye[2] = v0.z + random_within(1 << 16);
        }
        dot = (int64_t)n[0] * ((int64_t)f.eye[0] - v0.x) + (int64_t)n[1] * ((int64_t)f.eye[1] - v0.y) +
              (int64_t)n[2] * ((int64_t)f.eye[2] - v0.z);
        want = dot > 0 ? 1 : (dot < 0 ? -1 : 0);
        stp_render_side_estimate_make(&f, (uint32_t)box, &e);
        est = stp_render_side_estimate(&e, n, &v0);
        if (stp_render_side_sure(est))
            assert_int_equal(est > 0 ? 1 : -1, want);
        else
            unsure++;
    }
    /* the planes through the eye (1 in 7, of which those within a unit)
     * and few others */
    printf("side estimate: %ld of %ld cases left to the exact test\n", unsure, cases);
    assert_true(unsure < cases / 7 + cases / 100);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_small_point_exact),
        cmocka_unit_test(test_small_point_extremes),
        cmocka_unit_test(test_compose_is_the_renderers),
        cmocka_unit_test(test_face_side_near),
        cmocka_unit_test(test_side_estimate),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
