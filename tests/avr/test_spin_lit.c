/* SPDX-License-Identifier: MIT */
/*
 * The Arduino examples' prepared light (ports/arduino/src/stipple_spin.c,
 * kept as data so a sketch links no prepare): built in the Arduino
 * library's configuration on the AVR's arithmetic (the arduino core
 * configuration), it must equal, field by field, what
 * stp_direct_light_prepare (shade_fast.c's stp_shade_fast_prepare) makes
 * for the examples' view and light; on a mismatch the test prints the
 * fields to write into stipple_spin.c.  The frames drawn with it equal
 * those of stp_direct_frame_project, which prepares the light itself.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <cmocka.h>

#include "direct_private.h"
#include "stipple/render.h"
#include "stipple_spin.h"

#include "../../ports/arduino/examples/SpinningCube/cube_mesh.h"

static void print_lit(const stp_shade_fast *f)
{
    printf("prepared: .count = %u, .ambient_shade = %ld, .ambient = %ld, .light = {{%ld, %ld, %ld}}, "
           ".power_refl = {{%lu, %d}}, .attenuation_c = {%lu, %d}\n",
           f->count, (long)f->ambient_shade, (long)f->ambient, (long)f->light[0].x, (long)f->light[0].y,
           (long)f->light[0].z, (unsigned long)f->power_refl[0].m, f->power_refl[0].e,
           (unsigned long)f->attenuation_c.m, f->attenuation_c.e);
}

static void check_dir(const stp_shade_fast_dir *a, const stp_shade_fast_dir *b)
{
    int i;
    for (i = 0; i < 3; i++)
        assert_int_equal(a->w[i], b->w[i]);
    assert_int_equal(a->q, b->q);
    assert_int_equal(a->r, b->r);
    assert_int_equal(a->j, b->j);
    assert_int_equal(a->shift, b->shift);
}

static void test_lit_is_prepared(void **state)
{
    static stp_direct_point points[CUBE_VERTEX_COUNT];
    static uint16_t faces[CUBE_TRIANGLE_COUNT];
    stipple_spin spin;
    stp_direct_light light;
    stp_direct_lit want;
    const stp_shade_fast *got, *w = &want.fast;
    int j;
    (void)state;
    assert_int_equal(stipple_spin_begin(&spin, &cube_mesh, points, faces), STP_OK);
    assert_non_null(spin.lit);
    stipple_spin_light(&light);
    memset(&want, 0, sizeof want);
    assert_true(stp_direct_light_prepare(&want, &spin.view, &light));
    got = &spin.lit->fast;
    if (memcmp(got, w, sizeof *w) != 0)
        print_lit(w);
    assert_int_equal(got->count, w->count);
    assert_int_equal(got->parallel, w->parallel);
    assert_int_equal(got->specular, w->specular);
    assert_int_equal(got->refl_negative, w->refl_negative);
    assert_int_equal(got->ambient_shade, w->ambient_shade);
    assert_int_equal(got->ambient, w->ambient);
    assert_memory_equal(&got->eye, &w->eye, sizeof w->eye);
    assert_int_equal(got->eye_big, w->eye_big);
    check_dir(&got->e, &w->e);
    for (j = 0; j < STP_MAX_LIGHTS; j++) {
        assert_int_equal(got->light[j].x, w->light[j].x);
        assert_int_equal(got->light[j].y, w->light[j].y);
        assert_int_equal(got->light[j].z, w->light[j].z);
        assert_int_equal(got->light_big[j], w->light_big[j]);
        assert_int_equal(got->power_refl[j].m, w->power_refl[j].m);
        assert_int_equal(got->power_refl[j].e, w->power_refl[j].e);
    }
    assert_int_equal(got->attenuation_c.m, w->attenuation_c.m);
    assert_int_equal(got->attenuation_c.e, w->attenuation_c.e);
    /* every field compared: nothing else differs */
    assert_memory_equal(got, w, sizeof *w);
}

/* a frame of the spin (the prepared light as data) against the same frame
 * of stp_direct_frame_project (the light prepared there) */
static void test_frames_equal(void **state)
{
    static stp_direct_point points[CUBE_VERTEX_COUNT], points2[CUBE_VERTEX_COUNT];
    static uint16_t faces[CUBE_TRIANGLE_COUNT], faces2[CUBE_TRIANGLE_COUNT];
    static const uint8_t cell[16] = {14, 134, 44, 164, 194, 74, 224, 104, 59, 179, 29, 149, 239, 119, 209, 89};
    stipple_spin spin;
    stp_direct_light light;
    stp_direct_frame f2;
    stp_direct_model pose;
    stp_vec3 origin = {0, 0, 0};
    uint16_t n;
    unsigned drawn = 0, k;
    (void)state;
    assert_int_equal(stipple_spin_begin(&spin, &cube_mesh, points, faces), STP_OK);
    stipple_spin_light(&light);
    for (n = 0; n < 200; n++) {
        assert_int_equal(stipple_spin_frame(&spin, n), STP_OK);
        stp_direct_model_turn(&pose, (uint16_t)(n * 1024u), (uint16_t)(n * 410u), STP_FIX_ONE, origin);
        assert_int_equal(stp_direct_frame_project(&f2, &cube_mesh, &pose, &spin.view, &light, 16, cell,
                                                  points2, CUBE_VERTEX_COUNT, faces2, CUBE_TRIANGLE_COUNT),
                         STP_OK);
        assert_memory_equal(faces, faces2, sizeof faces);
        assert_memory_equal(points, points2, sizeof points);
        for (k = 0; k < CUBE_TRIANGLE_COUNT; k++)
            drawn += faces[k] != 0;
    }
    assert_true(drawn >= 200u * 3u); /* a cube shows 3..6 triangles */
    assert_int_equal(stp_direct_frame_project_lit(&f2, &cube_mesh, &pose, &spin.view, 0, 16, cell, points2,
                                                  CUBE_VERTEX_COUNT, faces2, CUBE_TRIANGLE_COUNT),
                     STP_ERR_ARG);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_lit_is_prepared),
        cmocka_unit_test(test_frames_equal),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
