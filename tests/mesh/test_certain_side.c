/* SPDX-License-Identifier: MIT */
/*
 * The polygon route's early back-face test (stp_render_certain_side,
 * render_private.h): whenever it decides a side from a triangle's
 * unnormalised cross product, that side is the one the face stage finds
 * from the normal rounded to Q1.14 (stp_render_face_side, the side the
 * mesh route finds from its prepared normals) and the geometric one
 * (checked in double precision).  Random triangles at scales from 2^4 to
 * 2^30 raw units, eyes anywhere in range, and eyes put within a hair of
 * the triangle's plane (grazing: where the rounded normal can turn the
 * sign).  Built against the host core and the 32-bit target arithmetic.
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

#include "render_private.h"

#define TEST_RANDOM_SEED 0x2545F4914F6CDD1Du
#include "test_random.h" /* next_random */

/* uniform in [-2^bits, 2^bits) for bits <= 31 */
static int64_t random_signed(int bits)
{
    uint64_t r = ((uint64_t)next_random() << 32) | next_random();
    return (int64_t)(r >> (63 - bits)) - ((int64_t)1 << bits);
}

static stp_fix clamp_fix(double v)
{
    double limit = 1073741823.0; /* the eye's documented range, |.| < 2^30 */
    return (stp_fix)(v > limit ? limit : (v < -limit ? -limit : v));
}

typedef struct tally {
    long tried, certain, grazing_certain, grazing_tried;
} tally;

/* Triangle v's edges e1 = v1 - v0, e2 = v2 - v0 and their cross product g,
 * in double precision (the reference). */
static void double_edges(const stp_vec3 v[3], double e1[3], double e2[3], double g[3])
{
    e1[0] = (double)v[1].x - v[0].x;
    e1[1] = (double)v[1].y - v[0].y;
    e1[2] = (double)v[1].z - v[0].z;
    e2[0] = (double)v[2].x - v[0].x;
    e2[1] = (double)v[2].y - v[0].y;
    e2[2] = (double)v[2].z - v[0].z;
    g[0] = e1[1] * e2[2] - e1[2] * e2[1];
    g[1] = e1[2] * e2[0] - e1[0] * e2[2];
    g[2] = e1[0] * e2[1] - e1[1] * e2[0];
}

/* One triangle v and eye: a decided side agrees with the rounded normal's
 * and with the geometric sign. */
static void check_one(const stp_vec3 v[3], const stp_vec3 *eye, int grazing, tally *t)
{
    stp_model_frame f;
    int64_t c[3];
    int16_t n[3] = {0, 0, 0};
    int sure, exact;
    double e1[3], e2[3], g[3], d[3], geometric;
    f.eye[0] = eye->x;
    f.eye[1] = eye->y;
    f.eye[2] = eye->z;
    stp_render_triangle_cross(v, c);
    if (c[0] == 0 && c[1] == 0 && c[2] == 0)
        return;
    assert_int_equal(stp_render_unit_q14(c[0], c[1], c[2], n), 1);
    exact = stp_render_face_side(&f, n, v[0]);
    sure = stp_render_certain_side(&f, c, v[0]);
    t->tried++;
    t->grazing_tried += grazing;
    if (sure == 0)
        return;
    t->certain++;
    t->grazing_certain += grazing;
    if (sure != exact)
        fprintf(stderr, "certain %d, rounded normal %d: v0 (%d %d %d) eye (%d %d %d)\n", sure, exact,
                (int)v[0].x, (int)v[0].y, (int)v[0].z, (int)eye->x, (int)eye->y, (int)eye->z);
    assert_int_equal(sure, exact);
    double_edges(v, e1, e2, g);
    d[0] = (double)eye->x - v[0].x;
    d[1] = (double)eye->y - v[0].y;
    d[2] = (double)eye->z - v[0].z;
    geometric = g[0] * d[0] + g[1] * d[1] + g[2] * d[2];
    assert_int_equal(sure, geometric > 0 ? 1 : -1);
}

/* a triangle of edge scale 2^edge_bits around a centre of scale
 * 2^centre_bits (both <= 29, so every coordinate fits stp_fix) */
static void random_triangle(stp_vec3 v[3], int centre_bits, int edge_bits)
{
    int64_t cx = random_signed(centre_bits), cy = random_signed(centre_bits),
            cz = random_signed(centre_bits);
    int i;
    for (i = 0; i < 3; i++) {
        v[i].x = (stp_fix)(cx + random_signed(edge_bits));
        v[i].y = (stp_fix)(cy + random_signed(edge_bits));
        v[i].z = (stp_fix)(cz + random_signed(edge_bits));
    }
}

static void test_random_eyes(void **state)
{
    tally t = {0, 0, 0, 0};
    int round;
    (void)state;
    for (round = 0; round < 400000; round++) {
        stp_vec3 v[3], eye;
        int edge_bits = 4 + (int)(next_random() % 26u), centre_bits = edge_bits + (int)(next_random() % 4u);
        if (centre_bits > 29)
            centre_bits = 29;
        random_triangle(v, centre_bits, edge_bits);
        eye.x = (stp_fix)random_signed(29 + (int)(next_random() % 2u)) / 2 * 2;
        eye.y = (stp_fix)random_signed(29);
        eye.z = (stp_fix)random_signed(29);
        check_one(v, &eye, 0, &t);
    }
    fprintf(stderr, "  random: %ld triangles, %ld decided early\n", t.tried, t.certain);
    /* a random eye is seldom near the plane: nearly every face is decided
     * without normalising (the point of the test) */
    assert_true(t.certain * 100 >= t.tried * 99);
}

static void test_grazing_eyes(void **state)
{
    tally t = {0, 0, 0, 0};
    int round;
    (void)state;
    for (round = 0; round < 400000; round++) {
        stp_vec3 v[3], eye;
        double e1[3], e2[3], g[3], len, a, b, off, p[3];
        int edge_bits = 6 + (int)(next_random() % 22u), i;
        random_triangle(v, edge_bits + 1 > 28 ? 28 : edge_bits + 1, edge_bits);
        double_edges(v, e1, e2, g);
        len = sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
        if (len == 0)
            continue;
        /* a point of the plane some edges away, then off it by a distance
         * of 2^-18 .. 2^-6 of that (in raw units, at least a fraction) */
        a = (double)(int32_t)(next_random() % 64u) - 32.0;
        b = (double)(int32_t)(next_random() % 64u) - 32.0;
        off = ldexp((double)(int32_t)(next_random() % 2048u) - 1024.0, -(int)(next_random() % 13u) - 16);
        for (i = 0; i < 3; i++) {
            double base = i == 0 ? v[0].x : (i == 1 ? v[0].y : v[0].z);
            p[i] = base + a * e1[i] + b * e2[i];
        }
        off *= sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) + ldexp(1.0, edge_bits);
        eye.x = clamp_fix(floor(p[0] + off * g[0] / len + 0.5));
        eye.y = clamp_fix(floor(p[1] + off * g[1] / len + 0.5));
        eye.z = clamp_fix(floor(p[2] + off * g[2] / len + 0.5));
        check_one(v, &eye, 1, &t);
    }
    fprintf(stderr, "  grazing: %ld triangles, %ld decided early\n", t.grazing_tried,
            t.grazing_certain);
    /* both outcomes occur: the test reaches the undecided band and beyond it */
    assert_true(t.grazing_certain > 1000);
    assert_true(t.grazing_tried - t.grazing_certain > 1000);
}

/* floor(a / 2^15) by C's division (truncating) */
static int32_t floor_q15(int64_t a)
{
    int64_t q = a / 32768;
    return (int32_t)(a % 32768 != 0 && a < 0 ? q - 1 : q);
}

/* stp_render_view_normal against its definition: each component
 * floor((row . n + 2^14) / 2^15), negated when side <= 0, for random rows
 * (Q15, each entry within 1/2: the sums below 3 2^28, as a unit row's)
 * and normals (Q1.14), and for sums exactly half way
 * (the rounding's ties, where turning the normal before rounding would
 * differ). */
static void test_view_normal(void **state)
{
    stp_model_frame f;
    int i, j, k;
    (void)state;
    memset(&f, 0, sizeof f);
    for (i = 0; i < 200000; i++) {
        int16_t n[3], nv[3];
        int side = (int)(next_random() % 3) - 1;
        for (j = 0; j < 3; j++) {
            n[j] = (int16_t)((int32_t)(next_random() % 32769u) - 16384);
            for (k = 0; k < 3; k++)
                f.rot[j][k] = (int32_t)(next_random() % 32769u) - 16384;
        }
        if (i % 4 == 0) {
            /* row 0's sum an odd multiple of 2^14: rot . n = (2 m + 1) 2^14 */
            n[0] = 16384;
            n[1] = n[2] = 0;
            f.rot[0][0] = (int32_t)(next_random() % 65537u) - 32768;
            f.rot[0][0] |= 1;
        }
        stp_render_view_normal(&f, n, side, nv);
        for (j = 0; j < 3; j++) {
            int64_t sum = (int64_t)f.rot[j][0] * n[0] + (int64_t)f.rot[j][1] * n[1] +
                          (int64_t)f.rot[j][2] * n[2];
            int32_t want = floor_q15(sum + 16384);
            assert_int_equal(nv[j], side > 0 ? want : -want);
        }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_random_eyes),
        cmocka_unit_test(test_grazing_eyes),
        cmocka_unit_test(test_view_normal),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
