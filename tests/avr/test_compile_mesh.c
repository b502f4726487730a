/* SPDX-License-Identifier: MIT */
/*
 * `stipple compile MODEL --mesh` (tools/compile_mesh.c), through the
 * headers it wrote for the Arduino examples (tests/avr/
 * check_arduino_generated.sh checks they are what it writes today),
 * against double-precision references: the vertices shared (no two
 * equal), centred with radius 1 (the cube's corners at +-1/sqrt(3)), every
 * index below the vertex count, every prepared normal within 2^-13 of the
 * unit normal of its triangle's stp_fix vertices, and the triangle counts
 * of the models (the cube's 6 quads: 12; the teapot's 56 triangles, less
 * the degenerate ones).
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <cmocka.h>

#include "stipple/mesh.h"

#include "../../ports/arduino/examples/SpinningCube/cube_mesh.h"
#include "../../ports/arduino/examples/SpinningTeapot/teapot_mesh.h"

static void check_mesh(const stp_mesh *m)
{
    double r_max = 0;
    unsigned i, j, t;
    for (i = 0; i < m->vertex_count; i++) {
        const stp_vec3 *v = &m->vertices[i];
        double r = sqrt((double)v->x * v->x + (double)v->y * v->y + (double)v->z * v->z) / STP_FIX_ONE;
        r_max = r > r_max ? r : r_max;
        for (j = 0; j < i; j++)
            assert_false(m->vertices[j].x == v->x && m->vertices[j].y == v->y && m->vertices[j].z == v->z);
    }
    assert_true(fabs(r_max - 1.0) < 2.0 / STP_FIX_ONE);
    for (t = 0; t < m->triangle_count; t++) {
        const uint16_t *k = &m->triangles[3 * t];
        double a[3], b[3], n[3], len;
        assert_true(k[0] < m->vertex_count && k[1] < m->vertex_count && k[2] < m->vertex_count);
        a[0] = (double)m->vertices[k[1]].x - m->vertices[k[0]].x;
        a[1] = (double)m->vertices[k[1]].y - m->vertices[k[0]].y;
        a[2] = (double)m->vertices[k[1]].z - m->vertices[k[0]].z;
        b[0] = (double)m->vertices[k[2]].x - m->vertices[k[0]].x;
        b[1] = (double)m->vertices[k[2]].y - m->vertices[k[0]].y;
        b[2] = (double)m->vertices[k[2]].z - m->vertices[k[0]].z;
        n[0] = a[1] * b[2] - a[2] * b[1];
        n[1] = a[2] * b[0] - a[0] * b[2];
        n[2] = a[0] * b[1] - a[1] * b[0];
        len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        assert_true(len > 0);
        for (i = 0; i < 3; i++) {
            double err = fabs(m->normals[3 * t + i] / (double)STP_MESH_NORMAL_ONE - n[i] / len);
            if (err > 1.0 / 8192)
                fail_msg("triangle %u normal %u off by %g", t, i, err);
        }
    }
}

static void test_cube(void **state)
{
    unsigned i;
    (void)state;
    assert_int_equal(cube_mesh.vertex_count, 8);
    assert_int_equal(cube_mesh.triangle_count, 12);
    for (i = 0; i < 8; i++) {
        long want = lround(STP_FIX_ONE / sqrt(3.0));
        assert_int_equal(labs((long)cube_vertices[i].x), want);
        assert_int_equal(labs((long)cube_vertices[i].y), want);
        assert_int_equal(labs((long)cube_vertices[i].z), want);
    }
    check_mesh(&cube_mesh);
}

static void test_teapot(void **state)
{
    (void)state;
    /* 37 distinct corners; 56 triangles less 4 degenerate ones (two equal
     * corners once in stp_fix) */
    assert_int_equal(teapot_mesh.vertex_count, 37);
    assert_int_equal(teapot_mesh.triangle_count, 52);
    check_mesh(&teapot_mesh);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_cube),
        cmocka_unit_test(test_teapot),
    };
    return cmocka_run_group_tests(tests, 0, 0);
}
