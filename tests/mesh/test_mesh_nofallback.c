/* SPDX-License-Identifier: MIT */
/*
 * stp_renderer_mesh built with STP_WITH_MESH_FALLBACK 0 (config.h): src/mesh.c
 * compiled once more here under other names, beside the library's own
 * (fallback on).  A triangle inside the view enters as with the fallback;
 * one that needs clipping, or a state only stp_renderer_polygon handles, is
 * STP_ERR_UNSUPPORTED.  Also the vertex average both entries share
 * (render_private.h) and its division by 3 (arith_private.h) against C's
 * operators (the projection is view.c's, tested by
 * test_view_narrow).
 */
#define STP_WITH_MESH_FALLBACK 0
#define stp_renderer_mesh stp_renderer_mesh_nofallback
#define stp_mesh_prepare_normals stp_mesh_prepare_normals_nofallback
#define stp_mesh_prepare_bounds stp_mesh_prepare_bounds_nofallback
#include "mesh.c"
#undef stp_renderer_mesh
#undef stp_mesh_prepare_normals
#undef stp_mesh_prepare_bounds

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <string.h>

#include <cmocka.h>

#include "torus.h"

int stp_renderer_mesh(stp_renderer *r, const stp_mesh *mesh, stp_mesh_vertex *scratch,
                      size_t scratch_count);

static int enter(torus_bench *b, int fallback)
{
    (void)stp_segment_close(b->r); /* open after a refused call */
    (void)stp_segment_delete(b->r, 1);
    assert_int_equal(stp_segment_create(b->r, 1), STP_OK);
    if (b->posed)
        assert_int_equal(stp_renderer_set_transform(b->r, &b->pose), STP_OK);
    stp_renderer_set_object_shade(b->r, &b->material);
    return fallback ? stp_renderer_mesh(b->r, &b->mesh, b->mesh_scratch, b->mesh.vertex_count)
                    : stp_renderer_mesh_nofallback(b->r, &b->mesh, b->mesh_scratch,
                                                   b->mesh.vertex_count);
}

static void test_inside_view_enters(void **state)
{
    static torus_bench a, b;
    char err[256];
    uint32_t used;
    (void)state;
    assert_int_equal(torus_bench_init(&a, 128, 64, err, sizeof err), 0);
    assert_int_equal(torus_bench_init(&b, 128, 64, err, sizeof err), 0);
    assert_int_equal(torus_bench_use_mesh(&a, err, sizeof err), 0);
    assert_int_equal(torus_bench_use_mesh(&b, err, sizeof err), 0);
    torus_bench_pose(&a, 20, 40, 0, 0, 0);
    torus_bench_pose(&b, 20, 40, 0, 0, 0);
    assert_int_equal(enter(&a, 1), STP_OK);
    assert_int_equal(enter(&b, 0), STP_OK);
    used = stp_renderer_display_file_used(a.r);
    assert_true(used > 1000);
    assert_int_equal(stp_renderer_display_file_used(b.r), used);
    assert_memory_equal(a.df, b.df, sizeof *a.df * used);
    torus_bench_free(&a);
    torus_bench_free(&b);
}

static void test_fallback_refused(void **state)
{
    static torus_bench b;
    char err[256];
    uint32_t used;
    (void)state;
    assert_int_equal(torus_bench_init(&b, 128, 64, err, sizeof err), 0);
    assert_int_equal(torus_bench_use_mesh(&b, err, sizeof err), 0);
    /* across the window's side: triangles to clip */
    torus_bench_pose(&b, 10, 20, 3.5, 0, 0);
    assert_int_equal(enter(&b, 0), STP_ERR_UNSUPPORTED);
    assert_int_equal(enter(&b, 1), STP_OK);
    /* a state only the polygon path handles: refused before anything is entered */
    assert_int_equal(stp_renderer_set_colour(b.r, 1), STP_OK);
    b.posed = 0;
    assert_int_equal(enter(&b, 0), STP_ERR_UNSUPPORTED);
    used = stp_renderer_display_file_used(b.r);
    assert_int_equal(used, 0);
    torus_bench_free(&b);
}

/* The entries' vertex average (render_private.h) against C's division of
 * the 64-bit sum. */
static void test_average_exact(void **state)
{
    static const int32_t edge[] = {0, 1, 2, 3, 4, 5, -1, -2, -3, INT32_MAX, INT32_MIN,
                                   INT32_MAX - 1, INT32_MIN + 1, 1 << 30, -(1 << 30)};
    uint32_t x = 12345u;
    size_t i, j, k;
    long n;
    (void)state;
    for (i = 0; i < sizeof edge / sizeof edge[0]; i++)
        for (j = 0; j < sizeof edge / sizeof edge[0]; j++)
            for (k = 0; k < sizeof edge / sizeof edge[0]; k++)
                assert_int_equal(stp_render_average3(0, edge[i], edge[j], edge[k]),
                                 ((int64_t)edge[i] + edge[j] + edge[k]) / 3);
    /* the division by 3 (arith_private.h): every u below 2^22 and from there
     * to 2^30 in steps that visit every residue */
    for (n = 0; n < (1L << 22); n++)
        assert_int_equal(stp_div3_u30((uint32_t)n), (uint32_t)n / 3u);
    for (n = 1L << 22; n < (1L << 30); n += 253)
        assert_int_equal(stp_div3_u30((uint32_t)n), (uint32_t)n / 3u);
    for (n = (1L << 30) - 1000; n < (1L << 30); n++)
        assert_int_equal(stp_div3_u30((uint32_t)n), (uint32_t)n / 3u);
    for (n = 0; n < 3000000; n++) {
        int32_t v[3];
        int shift;
        for (k = 0; k < 3; k++) {
            x = x * 1664525u + 1013904223u;
            v[k] = (int32_t)x;
        }
        shift = (int)(x >> 27); /* magnitudes of every size */
        for (k = 0; k < 3; k++)
            v[k] = v[k] / ((int32_t)1 << (shift > 30 ? 30 : shift));
        assert_int_equal(stp_render_average3(0, v[0], v[1], v[2]), ((int64_t)v[0] + v[1] + v[2]) / 3);
        for (k = 0; k < 3; k++)
            v[k] /= 8; /* below 2^28: the small case */
        assert_int_equal(stp_render_average3(1, v[0], v[1], v[2]), ((int64_t)v[0] + v[1] + v[2]) / 3);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_average_exact),
        cmocka_unit_test(test_inside_view_enters),
        cmocka_unit_test(test_fallback_refused),
    };
    return cmocka_run_group_tests(tests, 0, 0);
}
