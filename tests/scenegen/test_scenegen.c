/* SPDX-License-Identifier: MIT */
/*
 * The procedural scenes (`stipple scene`, tools/scenegen/): each one, at
 * several sizes, is parsed by the project's NFF reader and rendered; the
 * teapot, the tetrahedron and the sphereflake are compared with the SPD's
 * own files of the same size (teapot-sS, tetra-sS, balls-sS in the shared
 * scenes); counts, bounds and the geometry's defining distances are
 * checked exactly or to the 6 printed digits.
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "render_scene.h"
#include "scenegen.h"
#include "stp_posix.h"
#include "test_scenes.h"

/* Six significant digits on numbers up to 12 in size. */
#define PRINTED 2e-5

static void generate(const char *name, int size, stp_scene *scene)
{
    const stp_scenegen *gen = stp_scenegen_find(name);
    stp_scene_options sopt;
    char *text = NULL, err[512];
    size_t length = 0;
    FILE *out;
    assert_non_null(gen);
    out = open_memstream(&text, &length);
    assert_non_null(out);
    assert_int_equal(gen->write(out, size), 0);
    assert_int_equal(fclose(out), 0);
    stp_scene_options_default(&sopt);
    if (stp_scene_parse(text, length, "nff", name, &sopt, scene, err, sizeof err) != 0)
        fail_msg("%s size %d does not parse: %s", name, size, err);
    free(text);
}

static double distance(stp_scene_vec3 a, stp_scene_vec3 b)
{
    return sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) + (a.z - b.z) * (a.z - b.z));
}

static void assert_close(double a, double b, double tolerance)
{
    if (!(fabs(a - b) <= tolerance))
        fail_msg("%.9g differs from %.9g by more than %g", a, b, tolerance);
}

static void assert_vec_close(stp_scene_vec3 a, stp_scene_vec3 b, double tolerance)
{
    assert_close(a.x, b.x, tolerance);
    assert_close(a.y, b.y, tolerance);
    assert_close(a.z, b.z, tolerance);
}

/* View, lights and materials equal (to the printed digits). */
static void assert_same_setting(const stp_scene *a, const stp_scene *b)
{
    size_t i;
    int k;
    assert_true(a->has_view && b->has_view);
    assert_vec_close(a->from, b->from, PRINTED);
    assert_vec_close(a->at, b->at, PRINTED);
    assert_vec_close(a->up, b->up, PRINTED);
    assert_close(a->angle, b->angle, 0);
    assert_close(a->hither, b->hither, 0);
    assert_int_equal(a->light_count, b->light_count);
    for (i = 0; i < a->light_count; i++)
        assert_vec_close(a->lights[i].position, b->lights[i].position, PRINTED);
    assert_int_equal(a->material_count, b->material_count);
    for (i = 0; i < a->material_count; i++) {
        for (k = 0; k < 3; k++)
            assert_close(a->materials[i].color[k], b->materials[i].color[k], 0);
        assert_close(a->materials[i].kd, b->materials[i].kd, 0);
        assert_close(a->materials[i].ks, b->materials[i].ks, 0);
        assert_close(a->materials[i].shine, b->materials[i].shine, 0);
    }
}

/* Renders at 64x48 into line-printer styles: the scene must show at least
 * two styles (something lit in front of the background). */
static void assert_renders(const stp_scene *scene)
{
    stp_tool_options opt;
    stp_tool_stats stats;
    stp_posix_frame frame;
    char err[512];
    uint32_t i, seen = 0;
    stp_tool_options_default(&opt);
    opt.width = 64;
    opt.height = 48;
    assert_int_equal(stp_posix_frame_init(&frame, 64, 48, STP_PIXEL_STYLE8), 0);
    if (stp_tool_render(scene, &opt, stp_posix_frame_port(&frame), &stats, err, sizeof err) != 0)
        fail_msg("render failed: %s", err);
    for (i = 0; i < 64u * 48u; i++)
        seen |= 1u << (frame.pixels[(i / 64) * frame.stride + i % 64] & 31);
    stp_posix_frame_free(&frame);
    assert_true(stats.polygons_in > 0);
    assert_true(seen & (seen - 1)); /* more than one style */
}

/* ------------------------------------------------------------- teapot */

static void test_teapot_equals_spd(void **state)
{
    int size;
    (void)state;
    for (size = 1; size <= 2; size++) {
        char spd_name[32];
        stp_scene ours, spd;
        size_t i;
        snprintf(spd_name, sizeof spd_name, "teapot-s%d", size);
        generate("teapot", size, &ours);
        stp_test_load_scene(spd_name, &spd);
        assert_same_setting(&ours, &spd);
        assert_int_equal(ours.polygon_count, spd.polygon_count);
        assert_int_equal(ours.vertex_count, spd.vertex_count);
        for (i = 0; i < ours.polygon_count; i++) {
            assert_int_equal(ours.polygons[i].count, spd.polygons[i].count);
            assert_int_equal(ours.polygons[i].material, spd.polygons[i].material);
            assert_int_equal(ours.polygons[i].has_normals, spd.polygons[i].has_normals);
        }
        for (i = 0; i < ours.vertex_count; i++) {
            assert_vec_close(ours.vertices[i], spd.vertices[i], PRINTED);
            assert_vec_close(ours.normals[i], spd.normals[i], PRINTED);
        }
        stp_scene_free(&ours);
        stp_scene_free(&spd);
    }
}

static void test_teapot_counts_and_bounds(void **state)
{
    int size;
    (void)state;
    for (size = 1; size <= 4; size++) {
        stp_scene s;
        double lo[3] = {1e9, 1e9, 1e9}, hi[3] = {-1e9, -1e9, -1e9};
        size_t i, patches = 0;
        generate("teapot", size, &s);
        for (i = 0; i < s.polygon_count; i++) {
            const stp_scene_polygon *p = &s.polygons[i];
            int k;
            if (!p->has_normals)
                continue;
            patches++;
            assert_int_equal(p->count, 3);
            for (k = 0; k < 3; k++) {
                stp_scene_vec3 v = s.vertices[p->first + (size_t)k], n = s.normals[p->first + (size_t)k];
                const double c[3] = {v.x, v.y, v.z};
                int a;
                assert_close(sqrt(n.x * n.x + n.y * n.y + n.z * n.z), 1, PRINTED);
                for (a = 0; a < 3; a++) {
                    lo[a] = c[a] < lo[a] ? c[a] : lo[a];
                    hi[a] = c[a] > hi[a] ? c[a] : hi[a];
                }
            }
        }
        /* 32 patches of 2*size^2 triangles, less size at each of the 8 collapsed edges */
        assert_int_equal(patches, (size_t)(64 * size * size - 8 * size));
        assert_int_equal(s.polygon_count - patches, (size_t)(size * size)); /* the floor */
        /* patch corners that are the extremes: handle's back, body's sides, lid's
         * knob, bottom's centre; the spout reaches into its control hull */
        assert_close(lo[0], -3, 1e-9);
        assert_close(lo[1], -2, 1e-9);
        assert_close(hi[1], 2, 1e-9);
        assert_close(lo[2], 0, 1e-9);
        assert_close(hi[2], 3.15, 1e-9);
        assert_true(hi[0] > 3.2 && hi[0] <= 3.525);
        if (size <= 2)
            assert_renders(&s);
        stp_scene_free(&s);
    }
}

/* ------------------------------------------------------------- tetra */

/* A triangle as text with its corners rotated to start at the smallest,
 * so equal triangles of equal winding compare equal. */
static void triangle_key(const stp_scene *s, const stp_scene_polygon *p, char *key, size_t len)
{
    char corner[3][64];
    int k, first = 0;
    for (k = 0; k < 3; k++) {
        stp_scene_vec3 v = s->vertices[p->first + (size_t)k];
        snprintf(corner[k], sizeof corner[k], "%+.9f %+.9f %+.9f", v.x, v.y, v.z);
        if (strcmp(corner[k], corner[first]) < 0)
            first = k;
    }
    snprintf(key, len, "%s|%s|%s", corner[first], corner[(first + 1) % 3], corner[(first + 2) % 3]);
}

static int compare_keys(const void *a, const void *b)
{
    return strcmp((const char *)a, (const char *)b);
}

#define KEY_LEN 200

static char *sorted_keys(const stp_scene *s)
{
    char *keys = calloc(s->polygon_count, KEY_LEN);
    size_t i;
    assert_non_null(keys);
    for (i = 0; i < s->polygon_count; i++) {
        assert_int_equal(s->polygons[i].count, 3);
        triangle_key(s, &s->polygons[i], keys + i * KEY_LEN, KEY_LEN);
    }
    qsort(keys, s->polygon_count, KEY_LEN, compare_keys);
    return keys;
}

static void test_tetra_equals_spd(void **state)
{
    int size;
    (void)state;
    for (size = 1; size <= 2; size++) {
        char spd_name[32], *ours_keys, *spd_keys;
        stp_scene ours, spd;
        size_t i;
        snprintf(spd_name, sizeof spd_name, "tetra-s%d", size);
        generate("tetra", size, &ours);
        stp_test_load_scene(spd_name, &spd);
        assert_same_setting(&ours, &spd);
        assert_int_equal(ours.polygon_count, spd.polygon_count);
        ours_keys = sorted_keys(&ours);
        spd_keys = sorted_keys(&spd);
        for (i = 0; i < ours.polygon_count; i++)
            assert_string_equal(ours_keys + i * KEY_LEN, spd_keys + i * KEY_LEN);
        free(ours_keys);
        free(spd_keys);
        assert_renders(&ours);
        stp_scene_free(&ours);
        stp_scene_free(&spd);
    }
}

static void test_tetra_counts_area_winding(void **state)
{
    int size;
    (void)state;
    for (size = 1; size <= 5; size++) {
        stp_scene s;
        double area = 0, volume = 0;
        size_t i;
        generate("tetra", size, &s);
        assert_int_equal(s.polygon_count, (size_t)1 << (2 * size));
        for (i = 0; i < s.polygon_count; i++) {
            const stp_scene_vec3 *v = &s.vertices[s.polygons[i].first];
            double ux = v[1].x - v[0].x, uy = v[1].y - v[0].y, uz = v[1].z - v[0].z;
            double wx = v[2].x - v[0].x, wy = v[2].y - v[0].y, wz = v[2].z - v[0].z;
            double nx = uy * wz - uz * wy, ny = uz * wx - ux * wz, nz = ux * wy - uy * wx;
            /* signed volume of the cone from a point on no face's plane */
            double px = v[0].x - 0.1234, py = v[0].y - 0.0567, pz = v[0].z - 0.0891;
            int k;
            for (k = 0; k < 3; k++)
                assert_true(fabs(v[k].x) <= 1 && fabs(v[k].y) <= 1 && fabs(v[k].z) <= 1);
            area += sqrt(nx * nx + ny * ny + nz * nz) / 2;
            volume += (px * nx + py * ny + pz * nz) / 6;
        }
        /* faces wound outwards enclose the 4^(size-1) tetrahedra of 1/8^(size-1)
         * the volume 8/3 of the first */
        assert_close(volume, 8.0 / 3.0 / (1 << (size - 1)), 1e-9);
        /* four half-size copies keep the area: that of the first, 8 sqrt(3) */
        assert_close(area, 8 * sqrt(3.0), 1e-9);
        stp_scene_free(&s);
    }
}

/* ------------------------------------------------------------- sphereflake */

static void test_sphereflake_equals_spd(void **state)
{
    int size;
    (void)state;
    for (size = 1; size <= 2; size++) {
        char spd_name[32];
        stp_scene ours, spd;
        size_t i;
        snprintf(spd_name, sizeof spd_name, "balls-s%d", size);
        generate("sphereflake", size, &ours);
        stp_test_load_scene(spd_name, &spd);
        assert_same_setting(&ours, &spd);
        assert_int_equal(ours.prim_count, spd.prim_count);
        for (i = 0; i < ours.prim_count; i++) {
            assert_int_equal(ours.prims[i].kind, STP_SCENE_SPHERE);
            assert_vec_close(ours.prims[i].base, spd.prims[i].base, PRINTED);
            assert_close(ours.prims[i].base_radius, spd.prims[i].base_radius, PRINTED);
        }
        /* the floor */
        assert_int_equal(spd.polygons[0].prim, -1);
        for (i = 0; i < 4; i++)
            assert_vec_close(ours.vertices[i], spd.vertices[i], 0);
        assert_renders(&ours);
        stp_scene_free(&ours);
        stp_scene_free(&spd);
    }
}

static void test_sphereflake_touching_not_overlapping(void **state)
{
    stp_scene s;
    size_t i, j;
    (void)state;
    generate("sphereflake", 3, &s);
    assert_int_equal(s.prim_count, 1 + 9 + 81 + 729);
    for (i = 1; i < s.prim_count; i++) {
        const stp_scene_prim *a = &s.prims[i];
        int touches_parent = 0;
        for (j = 0; j < s.prim_count; j++) {
            const stp_scene_prim *b = &s.prims[j];
            double d = distance(a->base, b->base), sum = a->base_radius + b->base_radius;
            if (i == j)
                continue;
            assert_true(d >= sum - PRINTED);
            if (fabs(b->base_radius - 3 * a->base_radius) < PRINTED && fabs(d - sum) < PRINTED)
                touches_parent = 1;
        }
        assert_true(touches_parent);
    }
    stp_scene_free(&s);
}

/* ------------------------------------------------------------- torus */

static void test_torus(void **state)
{
    int size;
    (void)state;
    for (size = 1; size <= 3; size++) {
        stp_scene s;
        double zmax = 0, rmax = 0;
        size_t i;
        generate("torus", size, &s);
        assert_int_equal(s.polygon_count, 1 + (size_t)(96 * size * size));
        for (i = 1; i < s.polygon_count; i++) {
            const stp_scene_polygon *p = &s.polygons[i];
            int k;
            assert_int_equal(p->count, 4);
            assert_true(p->has_normals);
            for (k = 0; k < 4; k++) {
                stp_scene_vec3 v = s.vertices[p->first + (size_t)k], n = s.normals[p->first + (size_t)k];
                double rho = sqrt(v.x * v.x + v.y * v.y);
                stp_scene_vec3 core = {v.x / rho, v.y / rho, 0}, expect;
                /* on the tube: 0.35 from the unit circle, the normal pointing
                 * from the circle to the point */
                assert_close(distance(v, core), 0.35, PRINTED);
                expect.x = (v.x - core.x) / 0.35;
                expect.y = (v.y - core.y) / 0.35;
                expect.z = v.z / 0.35;
                assert_vec_close(n, expect, 1e-4);
                zmax = fabs(v.z) > zmax ? fabs(v.z) : zmax;
                rmax = rho > rmax ? rho : rmax;
            }
        }
        assert_close(zmax, 0.35, PRINTED);
        assert_close(rmax, 1.35, PRINTED);
        assert_renders(&s);
        stp_scene_free(&s);
    }
}

/* ------------------------------------------------------------- rings */

static double segment_gap(const stp_scene_prim *a, const stp_scene_prim *b)
{
    double best = 1e9;
    int i, j;
    for (i = 0; i <= 32; i++)
        for (j = 0; j <= 32; j++) {
            double s = i / 32.0, t = j / 32.0;
            stp_scene_vec3 p = {a->base.x + s * (a->apex.x - a->base.x), a->base.y + s * (a->apex.y - a->base.y),
                                a->base.z + s * (a->apex.z - a->base.z)};
            stp_scene_vec3 q = {b->base.x + t * (b->apex.x - b->base.x), b->base.y + t * (b->apex.y - b->base.y),
                                b->base.z + t * (b->apex.z - b->base.z)};
            double d = distance(p, q);
            best = d < best ? d : best;
        }
    return best;
}

static void test_rings(void **state)
{
    int size;
    (void)state;
    for (size = 1; size <= 3; size++) {
        stp_scene s;
        size_t i, j, spheres = 0, cones = 0;
        double closest = 1e9;
        generate("rings", size, &s);
        for (i = 0; i < s.prim_count; i++) {
            assert_close(s.prims[i].base_radius, 0.15, 0);
            if (s.prims[i].kind == STP_SCENE_SPHERE) {
                spheres++;
                continue;
            }
            cones++;
            assert_close(s.prims[i].apex_radius, 0.15, 0);
            /* each cylinder joins two neighbouring points of a unit circle */
            assert_close(distance(s.prims[i].base, s.prims[i].apex), 2 * sin(3.14159265358979 / 24), PRINTED);
            for (j = i + 1; j < s.prim_count; j++)
                if (s.prims[j].kind == STP_SCENE_CONE && s.prims[j].material != s.prims[i].material) {
                    double gap = segment_gap(&s.prims[i], &s.prims[j]);
                    closest = gap < closest ? gap : closest;
                }
        }
        assert_int_equal(spheres, (size_t)(24 * (size + 1)));
        assert_int_equal(cones, (size_t)(24 * (size + 1)));
        /* interlocked, not touching: tubes of radius 0.15 need 0.3 */
        assert_true(closest > 0.3 && closest < 0.6);
        assert_renders(&s);
        stp_scene_free(&s);
    }
}

/* ------------------------------------------------------------- mountain */

static void test_mountain(void **state)
{
    stp_scene coarse, fine;
    int size;
    size_t i, j, found = 0;
    (void)state;
    for (size = 1; size <= 5; size++) {
        stp_scene s;
        double zmax = 0;
        generate("mountain", size, &s);
        assert_int_equal(s.polygon_count, (size_t)2 << (2 * size));
        for (i = 0; i < s.vertex_count; i++) {
            stp_scene_vec3 v = s.vertices[i];
            assert_true(fabs(v.x) <= 1 && fabs(v.y) <= 1);
            if (fabs(v.x) == 1 && fabs(v.y) == 1)
                assert_close(v.z, 0, 0);
            zmax = fabs(v.z) > zmax ? fabs(v.z) : zmax;
        }
        assert_true(zmax > 0.05 && zmax < 0.8);
        if (size <= 2)
            assert_renders(&s);
        stp_scene_free(&s);
    }
    /* a larger size refines a smaller one: every grid point of size 2 is one
     * of size 3 with the same height */
    generate("mountain", 2, &coarse);
    generate("mountain", 3, &fine);
    for (i = 0; i < coarse.vertex_count; i++)
        for (j = 0; j < fine.vertex_count; j++)
            if (distance(coarse.vertices[i], fine.vertices[j]) == 0) {
                found++;
                break;
            }
    assert_int_equal(found, coarse.vertex_count);
    stp_scene_free(&coarse);
    stp_scene_free(&fine);
}

static void test_table(void **state)
{
    size_t count, i;
    const stp_scenegen *all = stp_scenegen_all(&count);
    (void)state;
    assert_int_equal(count, 6);
    for (i = 0; i < count; i++)
        assert_ptr_equal(stp_scenegen_find(all[i].name), &all[i]);
    assert_null(stp_scenegen_find("teapots"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_teapot_equals_spd),
        cmocka_unit_test(test_teapot_counts_and_bounds),
        cmocka_unit_test(test_tetra_equals_spd),
        cmocka_unit_test(test_tetra_counts_area_winding),
        cmocka_unit_test(test_sphereflake_equals_spd),
        cmocka_unit_test(test_sphereflake_touching_not_overlapping),
        cmocka_unit_test(test_torus),
        cmocka_unit_test(test_rings),
        cmocka_unit_test(test_mountain),
        cmocka_unit_test(test_table),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
