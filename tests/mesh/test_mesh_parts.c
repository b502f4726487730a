/* SPDX-License-Identifier: MIT */
/*
 * A mesh entered in parts (issue 21 item 3: meshes of more than 65 535
 * triangles, which one stp_mesh cannot count, go in as several): the
 * bench's finer torus (torus_bench_use_fine_mesh) in one part and in parts
 * of whole rings gives the same display file, record for record, and the
 * same frame, byte for byte; at 25 x 20 quads it is the benchmark torus
 * itself, and equals torus_bench_use_mesh's frame; at 250 x 200 (100 000
 * triangles, the side-by-side bench's large case) the parts hold at most
 * 65 535 triangles and vertices each and split finer give the same frame.
 * Built against the host core (test_mesh_parts) and the 32-bit target
 * arithmetic (test_mesh_parts_narrow: stipple_core_m0plus_full).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "torus.h"

/* Sets up a w x h bench of the around x tube torus in parts of at most
 * part_max triangles (0: one stp_mesh's most), posed (tilt, spin). */
static void fine(torus_bench *b, int w, int h, int around, int tube, unsigned part_max,
                 double tilt, double spin)
{
    char err[256];
    assert_int_equal(torus_bench_init_for(b, w, h, 2 * (size_t)around * (size_t)tube, err, sizeof err), 0);
    if (torus_bench_use_fine_mesh(b, around, tube, part_max, err, sizeof err) != 0)
        fail_msg("%s", err);
    torus_bench_pose(b, tilt, spin, 0, 0, 0);
}

/* Frames of a and b (twice each, as the bench renders) equal, display
 * files too; returns the records used. */
static uint32_t same_frames(torus_bench *a, torus_bench *b)
{
    uint32_t used = 0;
    int round;
    assert_int_equal(a->width, b->width);
    assert_int_equal(a->height, b->height);
    for (round = 0; round < 2; round++) {
        memset(a->frame, 0x55, a->stride * (size_t)a->height);
        memset(b->frame, 0xAA, b->stride * (size_t)b->height);
        assert_int_equal(torus_frame(a), 0);
        assert_int_equal(torus_frame(b), 0);
        used = stp_renderer_display_file_used(a->r);
        assert_int_equal(stp_renderer_display_file_used(b->r), used);
        assert_memory_equal(a->df, b->df, sizeof *a->df * used);
        assert_int_equal(memcmp(a->frame, b->frame, a->stride * (size_t)a->height), 0);
    }
    return used;
}

/* Lit pixels of a frame. */
static size_t lit(const torus_bench *b)
{
    size_t i, n = 0;
    for (i = 0; i < b->stride * (size_t)b->height; i++) {
        unsigned v = b->frame[i];
        for (; v; v &= v - 1)
            n++;
    }
    return n;
}

/* 25 x 20 in 1 part, in 5 parts of 5 rings (200 triangles), in 3 parts of
 * 9, 8 and 8 rings (at most 360), and the benchmark mesh: all alike, still
 * and posed, at 128 x 64 and 400 x 240. */
static void test_parts_small(void **state)
{
    static const double poses[3][2] = {{0, 0}, {20, 57}, {65, 305}};
    static const int sizes[2][2] = {{128, 64}, {400, 240}};
    static torus_bench one, five, three, bench;
    char err[256];
    int s, p;
    (void)state;
    for (s = 0; s < 2; s++) {
        for (p = 0; p < 3; p++) {
            int w = sizes[s][0], h = sizes[s][1];
            uint32_t used;
            fine(&one, w, h, 25, 20, 0, poses[p][0], poses[p][1]);
            fine(&five, w, h, 25, 20, 200, poses[p][0], poses[p][1]);
            fine(&three, w, h, 25, 20, 360, poses[p][0], poses[p][1]);
            assert_int_equal(one.part_count, 1);
            assert_int_equal(five.part_count, 5);
            assert_int_equal(three.part_count, 3);
            assert_int_equal(three.parts[0].triangle_count, 360);
            assert_int_equal(three.parts[2].triangle_count, 320);
            assert_int_equal(three.parts[2].vertex_count, 9 * 20);
            assert_int_equal(torus_bench_init(&bench, w, h, err, sizeof err), 0);
            assert_int_equal(torus_bench_use_mesh(&bench, err, sizeof err), 0);
            torus_bench_pose(&bench, poses[p][0], poses[p][1], 0, 0, 0);
            used = same_frames(&one, &five);
            assert_true(used > 150 * 4);
            (void)same_frames(&one, &three);
            (void)same_frames(&one, &bench);
            assert_true(lit(&one) > (size_t)w * (size_t)h / 20);
            fprintf(stderr, "  %dx%d pose %g/%g: 1, 3 and 5 parts and the bench mesh alike, "
                            "%u records, %lu lit\n",
                    w, h, poses[p][0], poses[p][1], (unsigned)used, (unsigned long)lit(&one));
            torus_bench_free(&one);
            torus_bench_free(&five);
            torus_bench_free(&three);
            torus_bench_free(&bench);
        }
    }
}

/* 250 x 200 (100 000 triangles) at 400 x 240: two parts of 125 rings
 * (50 000 triangles, 25 200 vertices), and in parts of at most 20 000
 * triangles the same frame. */
static void test_parts_100k(void **state)
{
    static torus_bench two, many;
    int p, total = 0;
    (void)state;
    fine(&two, 400, 240, 250, 200, 0, 20, 57);
    fine(&many, 400, 240, 250, 200, 20000, 20, 57);
    assert_int_equal(two.part_count, 2);
    for (p = 0; p < two.part_count; p++) {
        assert_int_equal(two.parts[p].triangle_count, 50000);
        assert_int_equal(two.parts[p].vertex_count, 126 * 200);
        total += two.parts[p].triangle_count;
    }
    assert_int_equal(total, 100000);
    assert_int_equal(many.part_count, 5); /* 50 rings: 20 000 triangles each */
    (void)same_frames(&two, &many);
    assert_true(lit(&two) > 400 * 240 / 20);
    torus_bench_free(&two);
    torus_bench_free(&many);
}

/* A part that cannot hold one ring, and a display file too small. */
static void test_parts_refused(void **state)
{
    static torus_bench b;
    char err[256];
    (void)state;
    assert_int_equal(torus_bench_init_for(&b, 128, 64, 1000, err, sizeof err), 0);
    assert_int_equal(torus_bench_use_fine_mesh(&b, 25, 20, 39, err, sizeof err), -1);
    assert_int_equal(torus_bench_use_fine_mesh(&b, 250, 200, 0, err, sizeof err), -1);
    assert_non_null(strstr(err, "display file"));
    torus_bench_free(&b);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_parts_small),
        cmocka_unit_test(test_parts_100k),
        cmocka_unit_test(test_parts_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
