/* SPDX-License-Identifier: MIT */
/*
 * stp_renderer_mesh built with STP_WITH_MESH_FALLBACK 0 (config.h): src/mesh.c
 * compiled once more here under other names, beside the library's own
 * (fallback on).  A triangle inside the view enters as with the fallback;
 * one that needs clipping, or a state only stp_renderer_polygon handles, is
 * STP_ERR_UNSUPPORTED.
 */
#define STP_WITH_MESH_FALLBACK 0
#define stp_renderer_mesh stp_renderer_mesh_nofallback
#define stp_mesh_prepare_normals stp_mesh_prepare_normals_nofallback
#include "mesh.c"
#undef stp_renderer_mesh
#undef stp_mesh_prepare_normals

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

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_inside_view_enters),
        cmocka_unit_test(test_fallback_refused),
    };
    return cmocka_run_group_tests(tests, 0, 0);
}
