/* SPDX-License-Identifier: MIT */
/*
 * stp_renderer_polygon's back-face removal of a triangle (render.c's
 * model_normal_and_side, whose 32-bit early test, small_triangle_side,
 * decides small triangles near the eye where 64-bit products are library
 * calls): a triangle is stored with back faces removed exactly when it is
 * stored with them kept and the reference side is positive.  The reference:
 * the sign of n.(eye - v0) in 64-bit integers, n the triangle's normal
 * rounded to Q1.14 (stp_render_triangle_normal: the normal the face stage
 * shades with, stp_render_face_side's side), the eye the view's `from`
 * (no model transform).  Random triangles with edges from 2^4 to 2^17 raw
 * units (across the early test's 2^15 bound), near the view centre and
 * far off it (across its 2^29 bound on eye - v0), with the eye a hair off
 * their plane (grazing: where only the exact side decides), and
 * degenerate ones (STP_ERR_DEGENERATE either way).  Built against the
 * host core and the 32-bit target arithmetic (test_small_side_narrow).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include <cmocka.h>

#include "render_private.h"

#define ONE STP_FIX_ONE

#define TEST_RANDOM_SEED 0x9E3779B97F4A7C15u
#include "test_random.h" /* next_random */

/* uniform in [-2^bits, 2^bits) for 0 <= bits <= 30 */
static int32_t random_signed(int bits)
{
    return (int32_t)(next_random() >> (31 - bits)) - ((int32_t)1 << bits);
}

static stp_renderer_storage storage;
static stp_instr display_file[256];

static stp_renderer *make_renderer(stp_vec3 from)
{
    stp_view view;
    stp_renderer *r = stp_renderer_create(&storage, sizeof storage, display_file, 256, 256, 256);
    assert_non_null(r);
    view.from = from;
    view.at.x = view.at.y = view.at.z = 0;
    view.up.x = view.up.z = 0;
    view.up.y = ONE;
    view.fov_degrees = 90 * ONE;
    view.window_half = ONE;
    view.hither = ONE / 64;
    view.projection = STP_PERSPECTIVE;
    assert_int_equal(stp_renderer_set_view(r, &view), STP_OK);
    stp_renderer_set_shading(r, 1);
    /* the reference's eye is the face stage's */
    assert_non_null(stp_render_model_frame(r));
    assert_int_equal(stp_render_model_frame(r)->eye[0], from.x);
    assert_int_equal(stp_render_model_frame(r)->eye[1], from.y);
    assert_int_equal(stp_render_model_frame(r)->eye[2], from.z);
    return r;
}

/* Triangle v entered alone (segment 1) with back faces removed or kept:
 * the status, *stored the display-file records it added. */
static int enter(stp_renderer *r, const stp_vec3 v[3], int removal, uint32_t *stored)
{
    uint32_t before;
    int status;
    assert_int_equal(stp_renderer_set_backface_removal(r, removal), STP_OK);
    assert_int_equal(stp_segment_create(r, 1), STP_OK);
    before = stp_renderer_display_file_used(r);
    status = stp_renderer_polygon(r, v, 3);
    *stored = stp_renderer_display_file_used(r) - before;
    assert_int_equal(stp_segment_close(r), STP_OK);
    assert_int_equal(stp_segment_delete(r, 1), STP_OK);
    return status;
}

typedef struct tally {
    long tried, stored, front, back, near_plane;
} tally;

/* The reference side of v from eye (see above), 0 for a zero normal or an
 * eye in the rounded normal's plane; *dot: n.(eye - v0). */
static int reference_side(const stp_vec3 v[3], stp_vec3 eye, int64_t *dot)
{
    int16_t n[3];
    if (!stp_render_triangle_normal(v, n)) {
        *dot = 0;
        return 0;
    }
    *dot = (int64_t)n[0] * ((int64_t)eye.x - v[0].x) + (int64_t)n[1] * ((int64_t)eye.y - v[0].y) +
           (int64_t)n[2] * ((int64_t)eye.z - v[0].z);
    return *dot > 0 ? 1 : (*dot < 0 ? -1 : 0);
}

static void check_one(stp_renderer *r, const stp_vec3 v[3], stp_vec3 eye, tally *t)
{
    uint32_t kept, removed;
    int64_t dot;
    int16_t n[3];
    int side = reference_side(v, eye, &dot);
    int status_kept = enter(r, v, 0, &kept), status_removed = enter(r, v, 1, &removed);
    t->tried++;
    if (!stp_render_triangle_normal(v, n)) {
        assert_int_equal(status_kept, STP_ERR_DEGENERATE);
        assert_int_equal(status_removed, STP_ERR_DEGENERATE);
        return;
    }
    assert_int_equal(status_kept, STP_OK);
    assert_int_equal(status_removed, STP_OK);
    if (kept == 0)
        return; /* out of view or between row centres: nothing to compare */
    t->stored++;
    if (side > 0)
        t->front++;
    else
        t->back++;
    /* within the early test's undecided band or near it: |n.d| below
     * 2^-9 of |n| |d|1 */
    if (llabs(dot) < 32 * (llabs((int64_t)eye.x - v[0].x) + llabs((int64_t)eye.y - v[0].y) +
                           llabs((int64_t)eye.z - v[0].z)))
        t->near_plane++;
    if (removed != (side > 0 ? kept : 0u))
        fprintf(stderr, "side %d (n.d %lld): stored %u kept, %u removed; v0 (%ld %ld %ld)\n", side,
                (long long)dot, (unsigned)kept, (unsigned)removed, (long)v[0].x, (long)v[0].y,
                (long)v[0].z);
    assert_int_equal(removed, side > 0 ? kept : 0u);
}

/* v0 near `centre`, edges of scale 2^edge_bits */
static void random_triangle(stp_vec3 v[3], stp_vec3 centre, int centre_bits, int edge_bits)
{
    int i;
    v[0].x = centre.x + random_signed(centre_bits);
    v[0].y = centre.y + random_signed(centre_bits);
    v[0].z = centre.z + random_signed(centre_bits);
    for (i = 1; i < 3; i++) {
        v[i].x = v[0].x + random_signed(edge_bits);
        v[i].y = v[0].y + random_signed(edge_bits);
        v[i].z = v[0].z + random_signed(edge_bits);
    }
}

/* v2 moved (within 2^edge_bits, plus a wobble of `wobble` raw units) so
 * that the triangle's plane passes near eye: v2 = v0 + a e1 + b (eye - v0)
 * scaled to the edge length. */
static void graze(stp_vec3 v[3], stp_vec3 eye, int edge_bits, int wobble)
{
    int64_t dx = (int64_t)eye.x - v[0].x, dy = (int64_t)eye.y - v[0].y, dz = (int64_t)eye.z - v[0].z;
    int64_t big = llabs(dx) > llabs(dy) ? llabs(dx) : llabs(dy);
    int shift = 0, a = (int)(next_random() % 5u) - 2;
    big = big > llabs(dz) ? big : llabs(dz);
    while ((big >> shift) >= ((int64_t)1 << edge_bits))
        shift++;
    v[2].x = (stp_fix)(v[0].x + a * ((int64_t)v[1].x - v[0].x) / 2 + (dx >> shift) +
                       (wobble ? random_signed(wobble) : 0));
    v[2].y = (stp_fix)(v[0].y + a * ((int64_t)v[1].y - v[0].y) / 2 + (dy >> shift) +
                       (wobble ? random_signed(wobble) : 0));
    v[2].z = (stp_fix)(v[0].z + a * ((int64_t)v[1].z - v[0].z) / 2 + (dz >> shift) +
                       (wobble ? random_signed(wobble) : 0));
}

static void run(int far, tally *t)
{
    stp_vec3 eye, centre;
    stp_renderer *r;
    int round;
    /* near: the eye 6 units off (eye - v0 below 2^29); far: 2^13.5 units
     * off, with triangles around the view centre (eye - v0 near 2^29.5:
     * both sides of the early test's bound) */
    eye.x = far ? 5000 * ONE : ONE;
    eye.y = far ? 7000 * ONE : 3 * ONE;
    eye.z = far ? 9000 * ONE : 5 * ONE;
    r = make_renderer(eye);
    centre.x = centre.y = centre.z = 0;
    for (round = 0; round < 200000; round++) {
        stp_vec3 v[3];
        int edge_bits = 4 + (int)(next_random() % 14u);
        int centre_bits = far ? 24 + (int)(next_random() % 5u) : 16;
        if (far)
            edge_bits += 8;
        random_triangle(v, centre, centre_bits, edge_bits);
        switch (round % 4) {
        case 0: break;
        case 1: graze(v, eye, edge_bits, 0); break;
        case 2: graze(v, eye, edge_bits, 1 + (int)(next_random() % 8u)); break;
        default: /* collinear now and then: a zero normal */
            if (next_random() % 8u == 0) {
                v[2].x = v[0].x + 2 * (v[1].x - v[0].x);
                v[2].y = v[0].y + 2 * (v[1].y - v[0].y);
                v[2].z = v[0].z + 2 * (v[1].z - v[0].z);
            }
        }
        check_one(r, v, eye, t);
    }
}

/* One eye distance's run, printed; each kind of triangle at least as many
 * times as asked, so the run cannot pass by testing nothing */
static void run_counted(int far, const char *name, long min_side, long min_near_plane)
{
    tally t = {0, 0, 0, 0, 0};
    run(far, &t);
    fprintf(stderr, "  %s: %ld triangles, %ld stored (%ld front, %ld back, %ld near the plane)\n", name, t.tried,
            t.stored, t.front, t.back, t.near_plane);
    assert_true(t.front > min_side && t.back > min_side && t.near_plane > min_near_plane);
}

static void test_near_eye(void **state)
{
    (void)state;
    run_counted(0, "near", 20000, 2000);
}

static void test_far_eye(void **state)
{
    (void)state;
    run_counted(1, "far", 5000, 500);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_near_eye),
        cmocka_unit_test(test_far_eye),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
