/* SPDX-License-Identifier: MIT */
/*
 * One entry (issues 20 and 21): a polygon entered through
 * stp_renderer_polygon goes through the same face stage as a triangle of
 * stp_renderer_mesh (render_private.h), so the benchmark torus
 * (tools/bench/torus.c) entered both ways gives the same display file,
 * record for record, and the same frame, byte for byte: still and in 8
 * poses (one across the window's edge, so clipped triangles too), at
 * 128x64 and 400x240, with the Z buffer, the painter's sort and no
 * hidden-surface removal.  Built against the host core (test_entry_identical)
 * and the 32-bit target arithmetic (test_entry_identical_narrow:
 * stipple_core_m0plus_full).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "torus.h"

/* A pose of torus_bench_pose: tilt, spin (degrees), offset (units). */
typedef struct pose {
    double tilt, spin, dx, dy, dz;
} pose;

static const pose poses[8] = {
    {20, 0, 0, 0, 0},          {30, 37, 0.05, -0.03, 0.04}, {40, 133, 0, 0, 0},
    {50, 250, -0.1, 0.05, 0},  {25, 71, 0, 0, 0.3},         {65, 305, 0.02, 0.2, -0.5},
    {10, 20, 0.3, 1.6, 0}, /* across the window's top side: clipped */
    {90, 180, 0, -0.2, 0.1}};

/* The polygons of a display file and how many of them are clipped (more
 * than 3 vertices). */
static uint32_t polygons(const torus_bench *b, uint32_t *clipped)
{
    uint32_t used = stp_renderer_display_file_used(b->r), i = 0, n = 0;
    *clipped = 0;
    while (i < used) {
        int32_t op = b->df[i].op;
        if (op >= 3) {
            n++;
            *clipped += op > 3;
            i += (uint32_t)op;
        } else {
            i++;
        }
    }
    return n;
}

/* The hidden-surface method for the next frames, with the painter's sort
 * memory when needed. */
static void set_hidden(torus_bench *b, stp_hidden hidden, stp_sort_entry *sort, size_t sort_count)
{
    b->output.hidden = hidden;
    b->memory.sort = hidden == STP_HIDDEN_PAINTER ? sort : 0;
    b->memory.sort_count = hidden == STP_HIDDEN_PAINTER ? sort_count : 0;
    if (hidden != STP_HIDDEN_ZBUFFER) {
        b->memory.zbuf = 0;
        b->memory.zbuf_count = 0;
    }
}

/* The torus at w x h under pose p (NULL: still), hidden-surface method
 * hidden, entered polygon by polygon and as one mesh: identical display
 * files and frames. */
static void entry_identical(int w, int h, const pose *p, stp_hidden hidden, uint32_t *clipped_total)
{
    static torus_bench poly, mesh;
    static stp_sort_entry sort_poly[TORUS_TRIANGLES], sort_mesh[TORUS_TRIANGLES];
    char err[256];
    uint32_t used, np, nm, cp, cm;
    int round;
    assert_int_equal(torus_bench_init(&poly, w, h, err, sizeof err), 0);
    assert_int_equal(torus_bench_init(&mesh, w, h, err, sizeof err), 0);
    assert_int_equal(torus_bench_use_mesh(&mesh, err, sizeof err), 0);
    set_hidden(&poly, hidden, sort_poly, TORUS_TRIANGLES);
    set_hidden(&mesh, hidden, sort_mesh, TORUS_TRIANGLES);
    if (p) {
        torus_bench_pose(&poly, p->tilt, p->spin, p->dx, p->dy, p->dz);
        torus_bench_pose(&mesh, p->tilt, p->spin, p->dx, p->dy, p->dz);
    }
    /* twice, as the bench does: the second frame re-enters into a used
     * display file with the shading and the model frame kept */
    for (round = 0; round < 2; round++) {
        memset(poly.frame, 0x55, poly.stride * (size_t)h);
        memset(mesh.frame, 0xAA, mesh.stride * (size_t)h);
        assert_int_equal(torus_frame(&poly), 0);
        assert_int_equal(torus_frame(&mesh), 0);
        used = stp_renderer_display_file_used(poly.r);
        assert_int_equal(stp_renderer_display_file_used(mesh.r), used);
        assert_memory_equal(poly.df, mesh.df, sizeof *poly.df * used);
        assert_int_equal(memcmp(poly.frame, mesh.frame, poly.stride * (size_t)h), 0);
        assert_int_equal(stp_renderer_last_shade(poly.r) >= 0, stp_renderer_last_shade(mesh.r) >= 0);
    }
    np = polygons(&poly, &cp);
    nm = polygons(&mesh, &cm);
    assert_int_equal(np, nm);
    assert_int_equal(cp, cm);
    assert_in_range(np, 150, 650); /* about half the faces front (fewer when partly outside) */
    *clipped_total += cp;
    fprintf(stderr, "  %dx%d pose %g/%g hidden %d: %u polygons (%u clipped), %u records, frames equal\n",
            w, h, p ? p->tilt : 0, p ? p->spin : 0, (int)hidden, (unsigned)np, (unsigned)cp,
            (unsigned)used);
    torus_bench_free(&poly);
    torus_bench_free(&mesh);
}

static void all_poses(int w, int h, stp_hidden hidden)
{
    uint32_t clipped = 0;
    size_t i;
    entry_identical(w, h, 0, hidden, &clipped);
    for (i = 0; i < sizeof poses / sizeof poses[0]; i++)
        entry_identical(w, h, &poses[i], hidden, &clipped);
    assert_true(clipped >= 5); /* the pose across the edge clips */
}

static void test_zbuffer_128x64(void **state)
{
    (void)state;
    all_poses(128, 64, STP_HIDDEN_ZBUFFER);
}

static void test_zbuffer_400x240(void **state)
{
    (void)state;
    all_poses(400, 240, STP_HIDDEN_ZBUFFER);
}

static void test_painter_128x64(void **state)
{
    (void)state;
    all_poses(128, 64, STP_HIDDEN_PAINTER);
}

static void test_painter_400x240(void **state)
{
    (void)state;
    all_poses(400, 240, STP_HIDDEN_PAINTER);
}

static void test_none_128x64(void **state)
{
    (void)state;
    all_poses(128, 64, STP_HIDDEN_NONE);
}

static void test_none_400x240(void **state)
{
    (void)state;
    all_poses(400, 240, STP_HIDDEN_NONE);
}

/* Back faces kept (removal off): both sides of every face entered alike. */
static void test_backfaces_kept(void **state)
{
    static torus_bench poly, mesh;
    char err[256];
    uint32_t used;
    (void)state;
    assert_int_equal(torus_bench_init(&poly, 128, 64, err, sizeof err), 0);
    assert_int_equal(torus_bench_init(&mesh, 128, 64, err, sizeof err), 0);
    assert_int_equal(torus_bench_use_mesh(&mesh, err, sizeof err), 0);
    stp_renderer_set_backface_removal(poly.r, 0);
    stp_renderer_set_backface_removal(mesh.r, 0);
    torus_bench_pose(&poly, 35, 50, 0, 0, 0);
    torus_bench_pose(&mesh, 35, 50, 0, 0, 0);
    assert_int_equal(torus_frame(&poly), 0);
    assert_int_equal(torus_frame(&mesh), 0);
    used = stp_renderer_display_file_used(poly.r);
    assert_true(used >= 3 * 900);
    assert_int_equal(stp_renderer_display_file_used(mesh.r), used);
    assert_memory_equal(poly.df, mesh.df, sizeof *poly.df * used);
    assert_int_equal(memcmp(poly.frame, mesh.frame, poly.stride * 64), 0);
    torus_bench_free(&poly);
    torus_bench_free(&mesh);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_zbuffer_128x64), cmocka_unit_test(test_zbuffer_400x240),
        cmocka_unit_test(test_painter_128x64), cmocka_unit_test(test_painter_400x240),
        cmocka_unit_test(test_none_128x64),    cmocka_unit_test(test_none_400x240),
        cmocka_unit_test(test_backfaces_kept),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
