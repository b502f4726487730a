/* SPDX-License-Identifier: MIT */
/*
 * Tests of the scene readers: the shared SPD scenes with their known
 * counts, tessellation geometry, OBJ and OFF, on-disk fixtures, and a table
 * of malformed inputs with the exact "name:line:" of each message.
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

#include "scene.h"
#include "scene_private.h"
#include "scene_util.h"

#define ERR_SIZE 512

/* ---- helpers ----------------------------------------------------------- */

static void expect_double(double got, double want, double tol, const char *what, int line)
{
    if (!(fabs(got - want) <= tol)) {
        print_error("line %d: %s: got %.17g, want %.17g\n", line, what, got, want);
        fail();
    }
}
#define EXPECT_EQ_D(got, want) expect_double((got), (want), 0.0, #got, __LINE__)
#define EXPECT_NEAR(got, want, tol) expect_double((got), (want), (tol), #got, __LINE__)

static void expect_vec(stp_scene_vec3 v, double x, double y, double z, int line)
{
    expect_double(v.x, x, 0.0, "x", line);
    expect_double(v.y, y, 0.0, "y", line);
    expect_double(v.z, z, 0.0, "z", line);
}
#define EXPECT_VEC(v, x, y, z) expect_vec((v), (x), (y), (z), __LINE__)

static int parse_as(const char *format, const char *text, size_t size,
                    const stp_scene_options *opt, stp_scene *s, char *err)
{
    return stp_scene_parse(text, size, format, "t", opt, s, err, ERR_SIZE);
}

static void parse_ok(const char *format, const char *text, const stp_scene_options *opt,
                     stp_scene *s)
{
    char err[ERR_SIZE];
    int rc = parse_as(format, text, strlen(text), opt, s, err);
    if (rc != 0) {
        print_error("unexpected failure: %s\n", err);
        fail();
    }
}

static void assert_scene_empty(const stp_scene *s)
{
    assert_int_equal(s->has_view, 0);
    assert_int_equal(s->has_background, 0);
    assert_null(s->lights);
    assert_null(s->materials);
    assert_null(s->vertices);
    assert_null(s->normals);
    assert_null(s->polygons);
    assert_null(s->prims);
    assert_int_equal(s->light_count, 0);
    assert_int_equal(s->material_count, 0);
    assert_int_equal(s->vertex_count, 0);
    assert_int_equal(s->polygon_count, 0);
    assert_int_equal(s->prim_count, 0);
}

/* Properties every successfully read scene has: polygons tile the vertex
 * array in order, indices are in range, normals are zero where absent,
 * everything is finite. */
static void check_invariants(const stp_scene *s)
{
    size_t i, next = 0;
    for (i = 0; i < s->polygon_count; i++) {
        const stp_scene_polygon *p = &s->polygons[i];
        int k;
        assert_int_equal(p->first, next);
        assert_true(p->count >= 3);
        assert_true(p->first + (size_t)p->count <= s->vertex_count);
        assert_in_range(p->material, 0, s->material_count - 1);
        assert_true(p->source_line >= 1);
        for (k = 0; k < p->count; k++) {
            const stp_scene_vec3 *v = &s->vertices[p->first + (size_t)k];
            const stp_scene_vec3 *n = &s->normals[p->first + (size_t)k];
            assert_true(isfinite(v->x) && isfinite(v->y) && isfinite(v->z));
            if (!p->has_normals)
                assert_true(n->x == 0.0 && n->y == 0.0 && n->z == 0.0);
        }
        next += (size_t)p->count;
    }
    assert_int_equal(next, s->vertex_count);
    for (i = 0; i < s->prim_count; i++)
        assert_in_range(s->prims[i].material, 0, s->material_count - 1);
}

/* Newell's method: the polygon's area-weighted normal, following its
 * winding (counter-clockwise seen from where it points). */
static stp_scene_vec3 newell(const stp_scene *s, const stp_scene_polygon *p)
{
    stp_scene_vec3 n = {0.0, 0.0, 0.0};
    int i;
    for (i = 0; i < p->count; i++) {
        const stp_scene_vec3 *a = &s->vertices[p->first + (size_t)i];
        const stp_scene_vec3 *b = &s->vertices[p->first + (size_t)((i + 1) % p->count)];
        n.x += (a->y - b->y) * (a->z + b->z);
        n.y += (a->z - b->z) * (a->x + b->x);
        n.z += (a->x - b->x) * (a->y + b->y);
    }
    return n;
}

static stp_scene_vec3 centroid(const stp_scene *s, const stp_scene_polygon *p)
{
    stp_scene_vec3 c = {0.0, 0.0, 0.0};
    int i;
    for (i = 0; i < p->count; i++) {
        c.x += s->vertices[p->first + (size_t)i].x;
        c.y += s->vertices[p->first + (size_t)i].y;
        c.z += s->vertices[p->first + (size_t)i].z;
    }
    c.x /= p->count;
    c.y /= p->count;
    c.z /= p->count;
    return c;
}

static double dot(stp_scene_vec3 a, stp_scene_vec3 b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

static stp_scene_vec3 sub(stp_scene_vec3 a, stp_scene_vec3 b)
{
    stp_scene_vec3 r;
    r.x = a.x - b.x;
    r.y = a.y - b.y;
    r.z = a.z - b.z;
    return r;
}

static char *join_path(const char *env, const char *suffix)
{
    const char *dir = getenv(env);
    char *p;
    if (!dir) {
        print_error("%s is not set\n", env);
        fail();
        return NULL;
    }
    p = malloc(strlen(dir) + strlen(suffix) + 2);
    assert_non_null(p);
    sprintf(p, "%s/%s", dir, suffix);
    return p;
}

static void load_ok(const char *env, const char *file, const stp_scene_options *opt, stp_scene *s)
{
    char err[ERR_SIZE];
    char *path = join_path(env, file);
    int rc = stp_scene_load(path, opt, s, err, sizeof err);
    if (rc != 0) {
        print_error("loading %s failed: %s\n", path, err);
        free(path);
        fail();
    }
    free(path);
    check_invariants(s);
}

static void load_spd(const char *file, const stp_scene_options *opt, stp_scene *s)
{
    load_ok("STP_SCENES_DIR", file, opt, s);
}

/* Polygons and vertices one tessellated sphere / cone contributes. */
static size_t sphere_polygons(const stp_scene_options *o)
{
    return (size_t)o->sphere_slices * (size_t)o->sphere_stacks;
}

static size_t sphere_vertices(const stp_scene_options *o)
{
    /* triangle fans at both poles, quads in between */
    return (size_t)o->sphere_slices * (size_t)(2 * 3 + (o->sphere_stacks - 2) * 4);
}

static size_t count_polygons_with(const stp_scene *s, int count)
{
    size_t i, n = 0;
    for (i = 0; i < s->polygon_count; i++)
        n += s->polygons[i].count == count;
    return n;
}

/* ---- the SPD scenes ---------------------------------------------------- */

static void test_options_default(void **state)
{
    stp_scene_options o;
    (void)state;
    memset(&o, 0, sizeof o);
    stp_scene_options_default(&o);
    assert_int_equal(o.sphere_slices, 16);
    assert_int_equal(o.sphere_stacks, 8);
    assert_int_equal(o.cone_slices, 16);
}

static void test_spd_tetra_s1(void **state)
{
    stp_scene s;
    size_t i;
    (void)state;
    load_spd("tetra-s1.nff", NULL, &s);
    assert_int_equal(s.polygon_count, 4);
    assert_int_equal(s.vertex_count, 12);
    assert_int_equal(s.prim_count, 0);
    assert_int_equal(count_polygons_with(&s, 3), 4);

    assert_int_equal(s.has_view, 1);
    EXPECT_VEC(s.from, 1.02285, -3.17715, -2.17451);
    EXPECT_VEC(s.at, -0.004103, -0.004103, 0.216539);
    EXPECT_VEC(s.up, -0.816497, -0.816497, 0.816497);
    EXPECT_EQ_D(s.angle, 45.0);
    EXPECT_EQ_D(s.hither, 1.0);
    assert_int_equal(s.resolution[0], 512);
    assert_int_equal(s.resolution[1], 512);
    assert_int_equal(s.has_background, 1);
    EXPECT_EQ_D(s.background[0], 0.078);
    EXPECT_EQ_D(s.background[1], 0.361);
    EXPECT_EQ_D(s.background[2], 0.753);

    assert_int_equal(s.light_count, 1);
    EXPECT_VEC(s.lights[0].position, 2, -18, -5);
    EXPECT_EQ_D(s.lights[0].color[0], 1.0);
    EXPECT_EQ_D(s.lights[0].color[1], 1.0);
    EXPECT_EQ_D(s.lights[0].color[2], 1.0);

    assert_int_equal(s.material_count, 1);
    EXPECT_EQ_D(s.materials[0].color[0], 1.0);
    EXPECT_EQ_D(s.materials[0].color[1], 0.2);
    EXPECT_EQ_D(s.materials[0].color[2], 0.2);
    EXPECT_EQ_D(s.materials[0].kd, 1.0);
    EXPECT_EQ_D(s.materials[0].ks, 0.0);
    EXPECT_EQ_D(s.materials[0].shine, 100000.0);
    EXPECT_EQ_D(s.materials[0].t, 0.0);
    EXPECT_EQ_D(s.materials[0].ior, 0.0);

    for (i = 0; i < 4; i++) {
        assert_int_equal(s.polygons[i].material, 0);
        assert_int_equal(s.polygons[i].has_normals, 0);
        assert_int_equal(s.polygons[i].source_line, 11 + 4 * (int)i);
    }
    /* vertex order as in the file */
    EXPECT_VEC(s.vertices[0], -1, -1, 1);
    EXPECT_VEC(s.vertices[1], -1, 1, -1);
    EXPECT_VEC(s.vertices[2], 1, -1, -1);
    EXPECT_VEC(s.vertices[11], 1, 1, 1);
    stp_scene_free(&s);
    assert_scene_empty(&s);
}

static void test_spd_tetra_s2(void **state)
{
    stp_scene s;
    (void)state;
    load_spd("tetra-s2.nff", NULL, &s);
    assert_int_equal(s.polygon_count, 16);
    assert_int_equal(count_polygons_with(&s, 3), 16);
    assert_int_equal(s.vertex_count, 48);
    assert_int_equal(s.material_count, 1);
    assert_int_equal(s.light_count, 1);
    stp_scene_free(&s);
}

static void test_spd_mount_s2(void **state)
{
    stp_scene s;
    stp_scene_options o;
    size_t i;
    (void)state;
    stp_scene_options_default(&o);
    load_spd("mount-s2.nff", NULL, &s);
    assert_int_equal(s.prim_count, 4);
    assert_int_equal(s.polygon_count, 32 + 4 * sphere_polygons(&o));
    assert_int_equal(s.vertex_count, 32 * 3 + 4 * sphere_vertices(&o));
    assert_int_equal(s.material_count, 2);
    assert_int_equal(s.light_count, 1);
    EXPECT_VEC(s.lights[0].position, -100, -100, 100);
    EXPECT_EQ_D(s.hither, 0.01);
    /* spheres first (material 0: the glass), then the terrain (material 1) */
    for (i = 0; i < 4; i++) {
        assert_int_equal(s.prims[i].kind, STP_SCENE_SPHERE);
        assert_int_equal(s.prims[i].material, 0);
        EXPECT_EQ_D(s.prims[i].base_radius, 0.17);
    }
    EXPECT_VEC(s.prims[0].base, -0.8, 0.8, 1.20821);
    EXPECT_EQ_D(s.materials[0].t, 0.9);
    EXPECT_EQ_D(s.materials[0].ior, 1.5);
    for (i = 0; i < 4 * sphere_polygons(&o); i++) {
        assert_int_equal(s.polygons[i].material, 0);
        assert_int_equal(s.polygons[i].has_normals, 1);
    }
    for (; i < s.polygon_count; i++) {
        assert_int_equal(s.polygons[i].material, 1);
        assert_int_equal(s.polygons[i].count, 3);
        assert_int_equal(s.polygons[i].has_normals, 0);
    }
    stp_scene_free(&s);
}

static void test_spd_teapot_s1(void **state)
{
    stp_scene s;
    size_t i;
    (void)state;
    load_spd("teapot-s1.nff", NULL, &s);
    assert_int_equal(s.polygon_count, 57);
    assert_int_equal(s.vertex_count, 4 + 56 * 3);
    assert_int_equal(s.prim_count, 0);
    assert_int_equal(s.light_count, 2);
    assert_int_equal(s.material_count, 3);
    /* floor: the second f; patches: the third */
    assert_int_equal(s.polygons[0].count, 4);
    assert_int_equal(s.polygons[0].material, 1);
    assert_int_equal(s.polygons[0].has_normals, 0);
    EXPECT_EQ_D(s.materials[1].color[0], 0.5);
    EXPECT_EQ_D(s.materials[2].color[1], 0.5);
    EXPECT_EQ_D(s.materials[2].shine, 3.0827);
    for (i = 1; i < 57; i++) {
        assert_int_equal(s.polygons[i].count, 3);
        assert_int_equal(s.polygons[i].material, 2);
        assert_int_equal(s.polygons[i].has_normals, 1);
    }
    /* the first pp vertex and normal exactly as written */
    EXPECT_VEC(s.vertices[4], 1.4, 0, 2.4);
    EXPECT_VEC(s.normals[4], -0.902861, -0.0, -0.429934);
    EXPECT_VEC(s.normals[5], 7.30595e-17, 0.902861, -0.429934);
    stp_scene_free(&s);
}

static void test_spd_teapot_s2(void **state)
{
    stp_scene s;
    size_t i;
    (void)state;
    load_spd("teapot-s2.nff", NULL, &s);
    assert_int_equal(s.polygon_count, 244);
    assert_int_equal(count_polygons_with(&s, 4), 4);
    assert_int_equal(count_polygons_with(&s, 3), 240);
    assert_int_equal(s.material_count, 3);
    /* the checkered floor alternates between the first two materials */
    assert_int_equal(s.polygons[0].material, 0);
    assert_int_equal(s.polygons[1].material, 0);
    assert_int_equal(s.polygons[2].material, 1);
    assert_int_equal(s.polygons[3].material, 1);
    for (i = 4; i < s.polygon_count; i++)
        assert_int_equal(s.polygons[i].material, 2);
    stp_scene_free(&s);
}

static void test_spd_gears_s1(void **state)
{
    stp_scene s;
    size_t i;
    (void)state;
    load_spd("gears-s1.nff", NULL, &s);
    assert_int_equal(s.polygon_count, 147);
    assert_int_equal(count_polygons_with(&s, 144), 2);
    assert_int_equal(count_polygons_with(&s, 4), 145);
    assert_int_equal(s.vertex_count, 2 * 144 + 145 * 4);
    assert_int_equal(s.light_count, 5);
    assert_int_equal(s.material_count, 2);
    EXPECT_VEC(s.lights[4].position, -1.111, -2.121, 2.626);
    assert_int_equal(s.polygons[0].material, 0);
    assert_int_equal(s.polygons[1].count, 144);
    assert_int_equal(s.polygons[1].source_line, 21);
    for (i = 1; i < s.polygon_count; i++)
        assert_int_equal(s.polygons[i].material, 1);
    assert_int_equal(s.polygons[146].count, 144);
    assert_int_equal(s.polygons[146].source_line, 886);
    EXPECT_EQ_D(s.materials[1].t, 0.8);
    EXPECT_EQ_D(s.materials[1].ior, 1.1);
    stp_scene_free(&s);
}

static void check_balls(const char *file, size_t spheres, const stp_scene_options *opt)
{
    stp_scene s;
    stp_scene_options o;
    size_t i;
    if (opt)
        o = *opt;
    else
        stp_scene_options_default(&o);
    load_spd(file, opt, &s);
    assert_int_equal(s.prim_count, spheres);
    assert_int_equal(s.polygon_count, 1 + spheres * sphere_polygons(&o));
    assert_int_equal(s.vertex_count, 4 + spheres * sphere_vertices(&o));
    assert_int_equal(count_polygons_with(&s, 3), spheres * 2 * (size_t)o.sphere_slices);
    assert_int_equal(s.light_count, 3);
    assert_int_equal(s.material_count, 2);
    assert_int_equal(s.polygons[0].material, 0);
    for (i = 0; i < spheres; i++) {
        assert_int_equal(s.prims[i].kind, STP_SCENE_SPHERE);
        assert_int_equal(s.prims[i].material, 1);
    }
    EXPECT_VEC(s.prims[0].base, 0, 0, 0);
    EXPECT_EQ_D(s.prims[0].base_radius, 0.5);
    EXPECT_EQ_D(s.prims[1].base_radius, 0.166667);
    stp_scene_free(&s);
}

static void test_spd_balls_s1(void **state)
{
    stp_scene_options o;
    (void)state;
    check_balls("balls-s1.nff", 10, NULL);
    stp_scene_options_default(&o);
    o.sphere_slices = 5;
    o.sphere_stacks = 3;
    o.cone_slices = 3;
    check_balls("balls-s1.nff", 10, &o);
    o.sphere_slices = 3;
    o.sphere_stacks = 2; /* the smallest: two fans of triangles */
    check_balls("balls-s1.nff", 10, &o);
}

static void test_spd_balls_s2(void **state)
{
    (void)state;
    check_balls("balls-s2.nff", 91, NULL);
}

/* ---- tessellation ------------------------------------------------------ */

static void check_sphere(const char *text, int inside, const stp_scene_options *o)
{
    stp_scene s;
    stp_scene_vec3 c = {1.0, -2.0, 3.0};
    const double r = 2.5;
    size_t i;
    parse_ok("nff", text, o, &s);
    check_invariants(&s);
    assert_int_equal(s.prim_count, 1);
    assert_int_equal(s.polygon_count, sphere_polygons(o));
    assert_int_equal(s.vertex_count, sphere_vertices(o));
    assert_int_equal(count_polygons_with(&s, 3), 2 * (size_t)o->sphere_slices);
    assert_int_equal(count_polygons_with(&s, 4),
                     (size_t)o->sphere_slices * (size_t)(o->sphere_stacks - 2));
    for (i = 0; i < s.vertex_count; i++) {
        stp_scene_vec3 d = sub(s.vertices[i], c);
        stp_scene_vec3 n = s.normals[i];
        EXPECT_NEAR(sqrt(dot(d, d)), r, 1e-12);
        EXPECT_NEAR(sqrt(dot(n, n)), 1.0, 1e-12);
        /* normals radial: outward, or inward when the inside is visible */
        EXPECT_NEAR(dot(n, d) / r, inside ? -1.0 : 1.0, 1e-12);
    }
    for (i = 0; i < s.polygon_count; i++) {
        const stp_scene_polygon *p = &s.polygons[i];
        double facing = dot(newell(&s, p), sub(centroid(&s, p), c));
        assert_int_equal(p->has_normals, 1);
        assert_int_equal(p->source_line, 1);
        if (inside ? !(facing < 0.0) : !(facing > 0.0)) {
            print_error("polygon %zu faces the wrong way (%g)\n", i, facing);
            fail();
        }
    }
    stp_scene_free(&s);
}

static void test_sphere_tessellation(void **state)
{
    stp_scene_options o;
    (void)state;
    stp_scene_options_default(&o);
    check_sphere("s 1 -2 3 2.5\n", 0, &o);
    check_sphere("s 1 -2 3 -2.5\n", 1, &o);
    o.sphere_slices = 7;
    o.sphere_stacks = 2;
    check_sphere("s 1 -2 3 2.5\n", 0, &o);
    o.sphere_slices = 3;
    o.sphere_stacks = 5;
    check_sphere("s 1 -2 3 -2.5\n", 1, &o);
}

/* A cone along an arbitrary axis: every side polygon faces away from the
 * axis (or toward it), normals are unit and perpendicular to the slant. */
static void check_cone(const char *text, stp_scene_vec3 b, double rb, stp_scene_vec3 a, double ra,
                       int inside, int triangles)
{
    stp_scene s;
    stp_scene_options o;
    stp_scene_vec3 w = sub(a, b);
    double h = sqrt(dot(w, w));
    size_t i;
    stp_scene_options_default(&o);
    o.cone_slices = 9;
    w.x /= h;
    w.y /= h;
    w.z /= h;
    parse_ok("nff", text, &o, &s);
    check_invariants(&s);
    assert_int_equal(s.prim_count, 1);
    assert_int_equal(s.prims[0].kind, STP_SCENE_CONE);
    EXPECT_EQ_D(s.prims[0].base_radius, inside ? -rb : rb);
    EXPECT_EQ_D(s.prims[0].apex_radius, inside ? -ra : ra);
    assert_int_equal(s.polygon_count, 9);
    assert_int_equal(count_polygons_with(&s, triangles ? 3 : 4), 9);
    for (i = 0; i < s.vertex_count; i++) {
        stp_scene_vec3 d = sub(s.vertices[i], b);
        double along = dot(d, w);
        stp_scene_vec3 radial = {d.x - along * w.x, d.y - along * w.y, d.z - along * w.z};
        double dist = sqrt(dot(radial, radial));
        stp_scene_vec3 n = s.normals[i];
        /* on one of the two end circles */
        if (fabs(along) < 1e-9)
            EXPECT_NEAR(dist, rb, 1e-9);
        else {
            EXPECT_NEAR(along, h, 1e-9);
            EXPECT_NEAR(dist, ra, 1e-9);
        }
        EXPECT_NEAR(sqrt(dot(n, n)), 1.0, 1e-12);
        /* perpendicular to the slant line of the side: tilted toward the
         * narrow end by atan((rb - ra) / h) */
        EXPECT_NEAR(dot(n, w),
                    (inside ? -1.0 : 1.0) * (rb - ra) / sqrt(h * h + (rb - ra) * (rb - ra)),
                    1e-9);
    }
    for (i = 0; i < s.polygon_count; i++) {
        const stp_scene_polygon *p = &s.polygons[i];
        stp_scene_vec3 c = sub(centroid(&s, p), b);
        double along = dot(c, w);
        stp_scene_vec3 out = {c.x - along * w.x, c.y - along * w.y, c.z - along * w.z};
        double facing = dot(newell(&s, p), out);
        int k;
        if (inside ? !(facing < 0.0) : !(facing > 0.0)) {
            print_error("cone polygon %zu faces the wrong way (%g)\n", i, facing);
            fail();
        }
        /* every corner normal (the tip's too) leans the polygon's way */
        for (k = 0; k < p->count; k++) {
            stp_scene_vec3 n = s.normals[p->first + (size_t)k];
            double side = dot(n, out) - dot(n, w) * dot(out, w);
            if (inside ? !(side < 0.0) : !(side > 0.0)) {
                print_error("cone polygon %zu corner %d: normal leans away\n", i, k);
                fail();
            }
        }
    }
    stp_scene_free(&s);
}

static void test_cone_tessellation(void **state)
{
    stp_scene_vec3 b = {1, 2, 3}, a = {2, 0, 5};
    stp_scene_vec3 zb = {0, 0, 0}, za = {0, 0, 2};
    (void)state;
    check_cone("c\n1 2 3 0.5\n2 0 5 0.5\n", b, 0.5, a, 0.5, 0, 0);  /* cylinder */
    check_cone("c\n1 2 3 -0.5\n2 0 5 -0.5\n", b, 0.5, a, 0.5, 1, 0); /* seen inside */
    check_cone("c\n1 2 3 1\n2 0 5 0\n", b, 1.0, a, 0.0, 0, 1);      /* pointed cone */
    check_cone("c\n1 2 3 -1\n2 0 5 0\n", b, 1.0, a, 0.0, 1, 1);
    check_cone("c\n0 0 0 0\n0 0 2 1.5\n", zb, 0.0, za, 1.5, 0, 1);  /* apex wider */
    check_cone("c\n0 0 0 2\n0 0 2 1\n", zb, 2.0, za, 1.0, 0, 0);    /* frustum along z */
}

/* ---- NFF details ------------------------------------------------------- */

static void test_nff_default_material(void **state)
{
    stp_scene s;
    (void)state;
    parse_ok("nff",
             "p 3\n0 0 0\n1 0 0\n0 1 0\n"
             "s 0 0 0 1\n"
             "f 0.5 0.25 1 0.5 0.5 10 0 1.5\n"
             "p 3\n0 0 0\n1 0 0\n0 1 0\n",
             NULL, &s);
    check_invariants(&s);
    assert_int_equal(s.material_count, 2);
    EXPECT_EQ_D(s.materials[0].color[0], 1.0);
    EXPECT_EQ_D(s.materials[0].color[1], 1.0);
    EXPECT_EQ_D(s.materials[0].color[2], 1.0);
    EXPECT_EQ_D(s.materials[0].kd, 1.0);
    EXPECT_EQ_D(s.materials[0].ks, 0.0);
    EXPECT_EQ_D(s.materials[0].shine, 0.0);
    EXPECT_EQ_D(s.materials[0].t, 0.0);
    EXPECT_EQ_D(s.materials[0].ior, 1.0);
    EXPECT_EQ_D(s.materials[1].color[1], 0.25);
    EXPECT_EQ_D(s.materials[1].ior, 1.5);
    assert_int_equal(s.polygons[0].material, 0);
    assert_int_equal(s.prims[0].material, 0); /* the same default, not a second one */
    assert_int_equal(s.polygons[1].material, 0);
    assert_int_equal(s.polygons[s.polygon_count - 1].material, 1);
    assert_int_equal(s.has_view, 0);
    assert_int_equal(s.has_background, 0);
    stp_scene_free(&s);
}

static void test_nff_layout(void **state)
{
    stp_scene s;
    (void)state;
    /* comments, blank lines, tabs, CRLF, trailing comments, view fields in
     * another order, b after geometry, a light with colour */
    parse_ok("nff",
             "# header comment\r\n"
             "\r\n"
             "  v  \r\n"
             "\tresolution 640\t480\r\n"
             "at 0 0 0\n"
             "   # a comment inside the view\n"
             "from 0 0 -5 # trailing comment\n"
             "up 0 1 0\n"
             "hither 0\n"
             "angle 30.5\n"
             "l 1 2 3 0.25 0.5 0.75\n"
             "p   3  \n"
             "  0 0 0\n"
             "\n"
             "1e0 0 0\n"
             "0 +1 -0\n"
             "b 0.5 0.5 0.5\n",
             NULL, &s);
    check_invariants(&s);
    assert_int_equal(s.has_view, 1);
    assert_int_equal(s.resolution[0], 640);
    assert_int_equal(s.resolution[1], 480);
    EXPECT_VEC(s.from, 0, 0, -5);
    EXPECT_VEC(s.up, 0, 1, 0);
    EXPECT_EQ_D(s.angle, 30.5);
    EXPECT_EQ_D(s.hither, 0.0);
    assert_int_equal(s.light_count, 1);
    EXPECT_EQ_D(s.lights[0].color[0], 0.25);
    EXPECT_EQ_D(s.lights[0].color[2], 0.75);
    assert_int_equal(s.has_background, 1);
    assert_int_equal(s.polygon_count, 1);
    assert_int_equal(s.polygons[0].source_line, 12);
    EXPECT_VEC(s.vertices[1], 1, 0, 0);
    EXPECT_VEC(s.vertices[2], 0, 1, 0);
    stp_scene_free(&s);
}

static void expect_prefix(const char *err, const char *prefix, const char *what);

/* The layouts the SPD programs write (issue 13): a cone's eight numbers on
 * the "c" line, polygon vertices on the "p" line, CRLF, a light's colour on
 * the next line; the same scene as the one-entity-per-line form. */
static void test_nff_token_stream(void **state)
{
    stp_scene a, b;
    size_t i;
    (void)state;
    parse_ok("nff",
             "v\nfrom 0 0 -5\nat 0 0 0\nup 0 1 0\nangle 45\nhither 1\nresolution 8 8\n"
             "l 1 2 3\n1 1 1\n"
             "f 1 0 0 1 0 0 0 1\n"
             "c\n0 0 0 1\n0 0 1 0.5\n"
             "p 3\n0 0 0\n1 0 0\n0 1 0\n"
             "s 0 0 0 1\n",
             NULL, &a);
    parse_ok("nff",
             "v from 0 0 -5 at 0 0 0 up 0 1 0 angle 45 hither 1 resolution 8 8\r\n"
             "l 1 2 3 1 1 1\r\n"
             "f 1 0 0 1 0 0 0 1\r\n"
             "c 0 0 0 1 0 0 1 0.5\r\n"
             "p 3 0 0 0 1 0 0\r\n0 1 0\r\n"
             "s 0 0 0\t1 # a comment\r\n",
             NULL, &b);
    check_invariants(&a);
    check_invariants(&b);
    assert_int_equal(a.prim_count, 2);
    assert_int_equal(b.prim_count, 2);
    assert_int_equal(b.prims[0].kind, STP_SCENE_CONE);
    EXPECT_VEC(b.prims[0].apex, 0, 0, 1);
    EXPECT_EQ_D(b.prims[0].apex_radius, 0.5);
    assert_int_equal(a.light_count, 1);
    assert_int_equal(b.light_count, 1);
    EXPECT_VEC(b.lights[0].position, 1, 2, 3);
    assert_int_equal(a.polygon_count, b.polygon_count);
    assert_int_equal(a.vertex_count, b.vertex_count);
    for (i = 0; i < a.vertex_count; i++)
        EXPECT_VEC(b.vertices[i], a.vertices[i].x, a.vertices[i].y, a.vertices[i].z);
    /* messages keep the line of the entity */
    assert_int_equal(b.polygons[16].source_line, 5);
    assert_int_equal(a.polygons[16].source_line, 14);
    stp_scene_free(&a);
    stp_scene_free(&b);
}

/* A UTF-8 byte-order mark before the first line: every reader skips it
 * (OBJ used to lose its first vertex, NFF and OFF refused the file). */
static void test_byte_order_mark(void **state)
{
    static const char *const formats[] = {"nff", "obj", "off"};
    static const char *const texts[] = {
        "\xEF\xBB\xBFp 3\n0 0 0\n1 0 0\n0 1 0\n",
        "\xEF\xBB\xBFv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
        "\xEF\xBB\xBFOFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"};
    char err[ERR_SIZE];
    stp_scene s;
    int k;
    (void)state;
    for (k = 0; k < 3; k++) {
        parse_ok(formats[k], texts[k], NULL, &s);
        assert_int_equal(s.polygon_count, 1);
        assert_int_equal(s.vertex_count, 3);
        EXPECT_VEC(s.vertices[0], 0, 0, 0);
        EXPECT_VEC(s.vertices[1], 1, 0, 0);
        stp_scene_free(&s);
    }
    /* only at the start: elsewhere it is still a bad token */
    assert_int_equal(parse_as("nff", "s 0 0 0 1\n\xEF\xBB\xBFs 0 0 0 1\n", 24, NULL, &s, err), -1);
    expect_prefix(err, "t:2: unknown entity", "BOM on line 2");
}

/* analytic_only: spheres and cones as prims without tessellation. */
static void test_analytic_only(void **state)
{
    stp_scene_options o;
    stp_scene s;
    (void)state;
    stp_scene_options_default(&o);
    o.analytic_only = 1;
    parse_ok("nff", "s 0 0 0 1\nc 0 0 0 1 0 0 1 0\n", &o, &s);
    assert_int_equal(s.prim_count, 2);
    assert_int_equal(s.polygon_count, 0);
    assert_int_equal(s.vertex_count, 0);
    stp_scene_free(&s);
    parse_ok("nff", "s 0 0 0 1\np 3\n0 0 0\n1 0 0\n0 1 0\n", &o, &s);
    assert_int_equal(s.prim_count, 1);
    assert_int_equal(s.polygon_count, 1);
    stp_scene_free(&s);
}

static void test_nff_keeps_vertex_order(void **state)
{
    stp_scene s;
    (void)state;
    /* clockwise as given: must not be "fixed" */
    parse_ok("nff",
             "p 4\n0 0 0\n0 1 0\n1 1 0\n1 0 0\n"
             "pp 3\n0 0 0 0 0 -1\n0 1 0 0 0 -1\n1 0 0 0 0 -2\n",
             NULL, &s);
    check_invariants(&s);
    assert_int_equal(s.polygon_count, 2);
    EXPECT_VEC(s.vertices[1], 0, 1, 0);
    EXPECT_VEC(s.vertices[3], 1, 0, 0);
    assert_true(newell(&s, &s.polygons[0]).z < 0.0);
    assert_int_equal(s.polygons[1].has_normals, 1);
    assert_int_equal(s.polygons[1].source_line, 6);
    /* normals are not renormalised */
    EXPECT_VEC(s.normals[6], 0, 0, -2);
    stp_scene_free(&s);
}

/* ---- OBJ --------------------------------------------------------------- */

static void test_obj_face_forms(void **state)
{
    stp_scene s;
    (void)state;
    parse_ok("obj",
             "# comment\n"
             "mtllib x.mtl\n"
             "o thing\n"
             "g group\n"
             "s 1\n"
             "usemtl red\n"
             "v 0 0 0\n"
             "v 1 0 0\n"
             "v 1 1 0 1.0\n"    /* w */
             "v 0 1 0 1 0 0\n"  /* colour extension */
             "vt 0 0\n"
             "vt 1 0\n"
             "vt 1 1\n"
             "vn 0 0 1\n"
             "vn 0 0 0.5\n"
             "f 1 2 3\n"
             "f 1/1 2/2 3/3\n"
             "f 1//1 2//2 3//1\n"
             "f 1/1/2 2/2/2 3/3/2 4/1/1\n"
             "f -4/-3/-2 -3/-2/-1 -2/-1/-2\n"
             "l 1 2\n"
             "curv 0 1 1 2\n"
             "f -4 -3 -1\n",
             NULL, &s);
    check_invariants(&s);
    assert_int_equal(s.polygon_count, 6);
    assert_int_equal(s.vertex_count, 3 + 3 + 3 + 4 + 3 + 3);
    assert_int_equal(s.material_count, 1);
    assert_int_equal(s.light_count, 0);
    assert_int_equal(s.prim_count, 0);
    assert_int_equal(s.has_view, 0);
    assert_int_equal(s.polygons[0].has_normals, 0);
    assert_int_equal(s.polygons[1].has_normals, 0);
    assert_int_equal(s.polygons[2].has_normals, 1);
    assert_int_equal(s.polygons[3].has_normals, 1);
    assert_int_equal(s.polygons[4].has_normals, 1);
    assert_int_equal(s.polygons[5].has_normals, 0);
    assert_int_equal(s.polygons[0].source_line, 16);
    assert_int_equal(s.polygons[5].source_line, 23);
    assert_int_equal(s.polygons[3].count, 4);
    EXPECT_VEC(s.vertices[2], 1, 1, 0);
    EXPECT_VEC(s.normals[6], 0, 0, 1);
    EXPECT_VEC(s.normals[7], 0, 0, 0.5);
    EXPECT_VEC(s.normals[8], 0, 0, 1);
    EXPECT_VEC(s.vertices[12], 0, 1, 0);
    EXPECT_VEC(s.normals[12], 0, 0, 1);
    /* -4 .. -2 of four vertices are 1 .. 3; -2 of two normals is the first */
    EXPECT_VEC(s.vertices[13], 0, 0, 0);
    EXPECT_VEC(s.vertices[14], 1, 0, 0);
    EXPECT_VEC(s.vertices[15], 1, 1, 0);
    EXPECT_VEC(s.normals[13], 0, 0, 1);
    EXPECT_VEC(s.normals[14], 0, 0, 0.5);
    EXPECT_VEC(s.vertices[17], 1, 0, 0);
    EXPECT_VEC(s.vertices[18], 0, 1, 0);
    EXPECT_EQ_D(s.materials[0].kd, 1.0);
    EXPECT_EQ_D(s.materials[0].ior, 1.0);
    stp_scene_free(&s);
}

static void test_obj_mixed_normals(void **state)
{
    stp_scene s;
    (void)state;
    parse_ok("obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2 3//1\n", NULL, &s);
    check_invariants(&s); /* zero normals where has_normals is 0 */
    assert_int_equal(s.polygons[0].has_normals, 0);
    stp_scene_free(&s);
}

/* ---- OFF --------------------------------------------------------------- */

static void test_off_variants(void **state)
{
    stp_scene s;
    (void)state;
    parse_ok("off",
             "# leading comment\n"
             "OFF 4 2 0\n"
             "0 0 0\n1 0 0\n1 1 0\n0 1 0\n"
             "3 0 1 2\n"
             "3 0 2 3 255\n",
             NULL, &s);
    check_invariants(&s);
    assert_int_equal(s.polygon_count, 2);
    assert_int_equal(s.vertex_count, 6);
    assert_int_equal(s.polygons[1].source_line, 8);
    EXPECT_VEC(s.vertices[4], 1, 1, 0);
    assert_int_equal(s.material_count, 1);
    stp_scene_free(&s);

    parse_ok("off",
             "NOFF\n3 1\n"
             "0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 0.5\n"
             "3 2 1 0 0.1 0.2 0.3 1\n",
             NULL, &s);
    check_invariants(&s);
    assert_int_equal(s.polygons[0].has_normals, 1);
    EXPECT_VEC(s.vertices[0], 0, 1, 0);
    EXPECT_VEC(s.normals[0], 0, 0, 0.5);
    stp_scene_free(&s);

    parse_ok("off",
             "COFF\n3 1 3\n"
             "0 0 0 1 0 0 1\n1 0 0 0 1 0\n0 1 0 0 0 1 1\n"
             "3 0 1 2\n",
             NULL, &s);
    check_invariants(&s);
    assert_int_equal(s.polygons[0].has_normals, 0);
    stp_scene_free(&s);

    parse_ok("off",
             "CNOFF\n3 1 3\n"
             "0 0 0 0 0 1 1 0 0 1\n1 0 0 0 0 1 0 1 0\n0 1 0 0 0 1 0 0 1 1\n"
             "3 0 1 2\n",
             NULL, &s);
    check_invariants(&s);
    assert_int_equal(s.polygons[0].has_normals, 1);
    stp_scene_free(&s);
}

/* ---- files on disk ----------------------------------------------------- */

static void check_cube(const stp_scene *s)
{
    stp_scene_vec3 mid = {0.5, 0.5, 0.5};
    size_t i;
    assert_int_equal(s->polygon_count, 6);
    assert_int_equal(s->vertex_count, 24);
    for (i = 0; i < 6; i++) {
        const stp_scene_polygon *p = &s->polygons[i];
        assert_int_equal(p->count, 4);
        assert_true(dot(newell(s, p), sub(centroid(s, p), mid)) > 0.0);
    }
}

static void test_load_fixtures(void **state)
{
    stp_scene s;
    stp_scene_options o;
    stp_scene_vec3 lo, hi;
    (void)state;

    load_ok("STP_SOURCE_DIR", "tests/data/scenes/cube.obj", NULL, &s);
    check_cube(&s);
    assert_int_equal(s.polygons[0].has_normals, 1);
    assert_int_equal(s.polygons[1].has_normals, 1);
    assert_int_equal(s.polygons[2].has_normals, 0);
    assert_int_equal(s.polygons[3].has_normals, 0);
    assert_int_equal(s.polygons[4].has_normals, 1);
    assert_int_equal(s.polygons[5].has_normals, 1);
    EXPECT_VEC(s.normals[16], 0, 1, 0);
    assert_int_equal(s.polygons[0].source_line, 26);
    assert_int_equal(stp_scene_bounds(&s, &lo, &hi), 0);
    EXPECT_VEC(lo, 0, 0, 0);
    EXPECT_VEC(hi, 1, 1, 1);
    stp_scene_free(&s);

    load_ok("STP_SOURCE_DIR", "tests/data/scenes/cube.off", NULL, &s);
    check_cube(&s);
    assert_int_equal(s.polygons[0].source_line, 12);
    stp_scene_free(&s);

    stp_scene_options_default(&o);
    load_ok("STP_SOURCE_DIR", "tests/data/scenes/entities.nff", &o, &s);
    assert_int_equal(s.prim_count, 3);
    assert_int_equal(s.polygon_count, 1 + sphere_polygons(&o) + 2 * (size_t)o.cone_slices + 1);
    assert_int_equal(s.material_count, 4);
    assert_int_equal(s.light_count, 2);
    EXPECT_EQ_D(s.lights[1].color[1], 0.5);
    assert_int_equal(s.prims[0].kind, STP_SCENE_SPHERE);
    assert_int_equal(s.prims[0].material, 1);
    assert_int_equal(s.prims[1].kind, STP_SCENE_CONE);
    assert_int_equal(s.prims[1].material, 2);
    EXPECT_VEC(s.prims[1].apex, 2, 0, 2);
    EXPECT_EQ_D(s.prims[2].apex_radius, 0.0);
    assert_int_equal(s.polygons[s.polygon_count - 1].material, 3);
    assert_int_equal(s.polygons[s.polygon_count - 1].has_normals, 1);
    assert_int_equal(s.resolution[0], 320);
    assert_int_equal(s.resolution[1], 240);
    EXPECT_EQ_D(s.background[2], 0.3);
    assert_int_equal(stp_scene_bounds(&s, &lo, &hi), 0);
    EXPECT_VEC(lo, -5, -5, 0);
    EXPECT_VEC(hi, 5, 5, 3);
    stp_scene_free(&s);
}

static void expect_prefix(const char *err, const char *prefix, const char *what)
{
    size_t n = strlen(prefix);
    if (strncmp(err, prefix, n) != 0) {
        print_error("%s: message \"%s\" does not start with \"%s\"\n", what, err, prefix);
        fail();
    }
}

static void test_load_errors(void **state)
{
    char err[ERR_SIZE];
    stp_scene s;
    char *path;
    FILE *f;
    (void)state;

    assert_int_equal(stp_scene_load("/nonexistent/dir/x.nff", NULL, &s, err, sizeof err), -1);
    expect_prefix(err, "/nonexistent/dir/x.nff: ", "missing file");
    assert_scene_empty(&s);
    /* upper-case extension is recognised: the failure is opening, not the format */
    assert_int_equal(stp_scene_load("/nonexistent/dir/X.OBJ", NULL, &s, err, sizeof err), -1);
    assert_null(strstr(err, "format"));
    assert_int_equal(stp_scene_load("/nonexistent/scene.stl", NULL, &s, err, sizeof err), -1);
    expect_prefix(err, "/nonexistent/scene.stl: unknown scene format", "extension");
    assert_int_equal(stp_scene_load("/nonexistent/nff", NULL, &s, err, sizeof err), -1);
    expect_prefix(err, "/nonexistent/nff: unknown scene format", "no extension");
    assert_scene_empty(&s);

    /* a malformed file reports its path and line */
    path = join_path("STP_BINARY_DIR", "test_scene_bad.off");
    f = fopen(path, "wb");
    assert_non_null(f);
    fputs("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 5\n", f);
    fclose(f);
    assert_int_equal(stp_scene_load(path, NULL, &s, err, sizeof err), -1);
    {
        char want[ERR_SIZE];
        snprintf(want, sizeof want, "%s:6: ", path);
        expect_prefix(err, want, "file error");
    }
    assert_scene_empty(&s);
    remove(path);
    free(path);
}

/* ---- malformed input --------------------------------------------------- */

typedef struct bad_case {
    const char *format;
    const char *text;
    const char *prefix; /* the exact start of the message */
} bad_case;

#define VIEW_HEAD "v\nfrom 0 0 0\nat 0 0 1\nup 0 1 0\n"
#define TRI "0 0 0\n1 0 0\n0 1 0\n"
#define OBJ_TRI "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
#define OFF_TRI "OFF\n3 1 0\n" TRI

static const bad_case bad_cases[] = {
    /* nothing there */
    {"nff", "", "t: empty file"},
    {"nff", "\n\n   \n", "t: empty file"},
    {"nff", "# only\n# comments\n", "t: empty file"},
    {"nff", "l 1 2 3\nb 0 0 0\n", "t: no geometry"},
    {"obj", "# comment\n", "t: empty file"},
    {"obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n", "t: no geometry"},
    {"off", "", "t: empty file"},
    {"off", "OFF\n3 0 0\n" TRI, "t: no geometry"},
    /* NFF: numbers */
    {"nff", "s 1.2.3 0 0 1\n", "t:1: bad number '1.2.3'"},
    {"nff", "s nan 0 0 1\n", "t:1: bad number 'nan'"},
    {"nff", "s 0 inf 0 1\n", "t:1: bad number 'inf'"},
    {"nff", "s 0 0 -infinity 1\n", "t:1: bad number"},
    {"nff", "s 0x10 0 0 1\n", "t:1: bad number '0x10'"},
    {"nff", "s 1,5 0 0 1\n", "t:1: bad number"},
    {"nff", "s 1e999 0 0 1\n", "t:1: number out of range"},
    {"nff", "s 0 0 0 1e\n", "t:1: bad number"},
    {"nff", "s 0 0 0 -\n", "t:1: bad number"},
    {"nff", "s 0 0 0 .\n", "t:1: bad number"},
    {"nff", "s 0 0 0 1\ns 0 0 0 "
            "1000000000000000000000000000000000000000000000000000000000000000000000000000000000"
            "000000000000000000000000000000000000000000000000000000000000000000000000000000\n",
     "t:2: number too long"},
    {"nff", "s -1e308 0 0 1e308\n", "t:1: coordinate out of range"},
    {"nff", "# c\n\n  \ns 0 0 0 1\ns 0 0 0 1e309\n", "t:5: number out of range"},
    /* NFF: entities */
    {"nff", "x 1 2 3\n", "t:1: unknown entity 'x'"},
    {"nff", "s 0 0 0 1\nP 3\n", "t:2: unknown entity 'P'"},
    {"nff", "s 0 0 0\n", "t:1: s: expected 4 numbers, found 3"},
    {"nff", "s 0 0 0 1 2\n", "t:1: s: expected 4 numbers, found more"},
    {"nff", "s 0 0 0 0\n", "t:1: s: radius is zero"},
    {"nff", "b 0 0\ns 0 0 0 1\n", "t:1: b: expected 3 numbers"},
    {"nff", "l 1 2\n", "t:1: l: expected 3 or 6 numbers, found 2"},
    {"nff", "l 1 2 3 4\n", "t:1: l: expected 3 or 6 numbers, found 4"},
    {"nff", "l 1 2 3 4 5 6 7\n", "t:1: l: expected 3 or 6 numbers, found more"},
    {"nff", "l 1 2 x\n", "t:1: bad number 'x'"},
    {"nff", "f 1 1 1 1 0 0 0\n", "t:1: f: expected 8 numbers, found 7"},
    {"nff", "f 1 1 1 1 0 0 0 1 9\n", "t:1: f: expected 8 numbers, found more"},
    /* NFF: polygons */
    {"nff", "p 2\n0 0 0\n1 0 0\n", "t:1: p: a polygon needs at least 3 vertices"},
    {"nff", "p 0\n", "t:1: p: a polygon needs at least 3 vertices"},
    {"nff", "p -3\n" TRI, "t:1: p: a polygon needs at least 3 vertices"},
    {"nff", "p\n" TRI, "t:1: p: a polygon needs at least 3 vertices, not 0"},
    {"nff", "p 3.0\n" TRI, "t:1: bad integer '3.0'"},
    {"nff", "p 3 4\n" TRI, "t:4: p vertex: expected 3 numbers, found more"},
    {"nff", "p 1000000000\n" TRI, "t:1: p: too many vertices"},
    {"nff", "p 99999999999999999999\n" TRI, "t:1: integer out of range"},
    {"nff", "p 1000000\n" TRI, "t:1: p: file ends after 3 of 1000000 vertices"},
    {"nff", "s 0 0 0 1\np 3\n0 0 0\n1 0 0\n", "t:2: p: file ends after 2 of 3 vertices"},
    {"nff", "p 3\n0 0 0\n1 0 0\n0 1\n", "t:4: p vertex: expected 3 numbers, found 2"},
    {"nff", "p 3\n0 0 0\n1 0 0\n0 1 0 5\n", "t:4: p vertex: expected 3 numbers, found more"},
    {"nff", "p 3\n0 0 0\np 3\n" TRI, "t:1: p: next entity after 1 of 3 vertices"},
    {"nff", "pp 3\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0\n", "t:4: pp vertex: expected 6 numbers"},
    {"nff", "pp 3\n" TRI, "t:4: pp vertex: expected 6 numbers, found 3"},
    /* NFF: cones */
    {"nff", "c\n0 0 0 1\n", "t:2: c: expected 8 numbers, found 4"},
    {"nff", "c\n", "t:1: c: expected 8 numbers, found 0"},
    {"nff", "c\n0 0 0 1\n0 0 1 1 5\n", "t:3: c: expected 8 numbers, found more"},
    {"nff", "c\n0 0 0 1\n0 0 1\n", "t:3: c: expected 8 numbers, found 7"},
    {"nff", "c\n0 0 0 1\n0 0 0 1\n", "t:1: c: base and apex coincide"},
    {"nff", "c\n0 0 0 0\n0 0 1 0\n", "t:1: c: both radii are zero"},
    {"nff", "c\n0 0 0 1\n0 0 1 -1\n", "t:1: c: radii have opposite signs"},
    {"nff", "c\n-1e308 0 0 1\n1e308 0 0 1\n", "t:1: coordinate out of range"},
    /* NFF: view */
    {"nff", "v\nfrom 0 0 0\n", "t:1: view: file ends before 'at'"},
    {"nff", "v x\n", "t:1: view: expected 'from', found 'x'"},
    {"nff", "v\nfrom 0 0\n", "t:2: from: expected 3 numbers, found 2"},
    {"nff", VIEW_HEAD "angle 45\nresolution 512 512\np 3\n" TRI,
     "t:7: view: expected 'hither', found 'p'"},
    {"nff", VIEW_HEAD "angle 45\nfrom 1 1 1\n", "t:6: view: 'from' given twice"},
    {"nff", VIEW_HEAD "angle 45\nhither 1\nresolution 0 512\n",
     "t:7: resolution must be 1..65536, not 0"},
    {"nff", VIEW_HEAD "angle 45\nhither 1\nresolution 512 -5\n",
     "t:7: resolution must be 1..65536, not -5"},
    {"nff", VIEW_HEAD "angle 45\nhither 1\nresolution 512.5 512\n", "t:7: bad integer '512.5'"},
    {"nff", VIEW_HEAD "angle 45\nhither 1\nresolution 512\n",
     "t:7: resolution: expected 2 integers, found 1"},
    {"nff", VIEW_HEAD "angle 45\nhither 1\nresolution 512 512 1\n", "t:7: resolution: expected 2 integers, found more"},
    {"nff", VIEW_HEAD "angle 0\n", "t:5: angle must be between 0 and 180 degrees"},
    {"nff", VIEW_HEAD "angle 180\n", "t:5: angle must be between 0 and 180 degrees"},
    {"nff", VIEW_HEAD "hither -1\n", "t:5: hither must not be negative"},
    {"nff", "v\nfrom 1 2 3\nat 1 2 3\nup 0 1 0\nangle 45\nhither 1\nresolution 8 8\ns 0 0 0 1\n",
     "t:3: view: 'at' equals 'from'"},
    {"nff", "v\nfrom 0 0 0\nat 0 0 1\nup 0 0 0\nangle 45\nhither 1\nresolution 8 8\ns 0 0 0 1\n",
     "t:4: view: 'up' is zero"},
    {"nff", "v\nfrom 0 0 0\nat 0 0 1\nup 0 0 -3\nangle 45\nhither 1\nresolution 8 8\ns 0 0 0 1\n",
     "t:4: view: 'up' is parallel to the view direction"},
    {"nff", VIEW_HEAD "angle 45\nhither 1\nresolution 8 8\nv\n", "t:8: v: second view"},
    {"nff", "b 0 0 0\nl 1 1 1\n" VIEW_HEAD, "t:3: v: the view must come before"},
    {"nff", "s 0 0 0 1\nv\n", "t:2: v: the view must come before"},
    /* OBJ */
    {"obj", "v 0 0 0\nv 1 0 0\nf 1 2\n", "t:3: f: a face needs at least 3 vertices, not 2"},
    {"obj", "v 0 0 0\nf\n", "t:2: f: a face needs at least 3 vertices, not 0"},
    {"obj", "f 1 2 3\n", "t:1: f: vertex index 1 out of range (0 defined)"},
    {"obj", "v 0 0 0\n" OBJ_TRI "f 0 1 2\n", "t:5: f: vertex index 0"},
    {"obj", "v 0 0 0\n" OBJ_TRI "f 1 2 5\n", "t:5: f: vertex index 5 out of range (4 defined)"},
    {"obj", OBJ_TRI "f -4 -1 -2\n", "t:4: f: vertex index -4 out of range (3 defined)"},
    {"obj", OBJ_TRI "f 1 2 3\nv 9 9 9\nf 1 2 5\n", "t:6: f: vertex index 5 out of range"},
    {"obj", "v 1.2.3 0 0\n", "t:1: bad number '1.2.3'"},
    {"obj", "v nan 0 0\n", "t:1: bad number 'nan'"},
    {"obj", "v 0 0\n", "t:1: v: expected 3, 4 or 6 numbers, found 2"},
    {"obj", "v 0 0 0 1 1\n", "t:1: v: expected 3, 4 or 6 numbers, found 5"},
    {"obj", "v 0 0 0 1 1 1 1\n", "t:1: v: expected 3, 4 or 6 numbers, found 7"},
    {"obj", "vn 0 0\n", "t:1: vn: expected 3 numbers, found 2"},
    {"obj", "vn 0 0 1e400\n", "t:1: number out of range"},
    {"obj", "v 0 0 0\n" OBJ_TRI "f 1/1 2/1 3/1\n",
     "t:5: f: texture index 1 out of range (0 defined)"},
    {"obj", OBJ_TRI "vn 0 0 1\nf 1//1 2//1 3//\n", "t:5: f: empty normal index"},
    {"obj", OBJ_TRI "vn 0 0 1\nf 1//1 2//1 3//2\n",
     "t:5: f: normal index 2 out of range (1 defined)"},
    {"obj", OBJ_TRI "vt 0 0\nf 1/ 2/1 3/1\n", "t:5: f: empty texture index"},
    {"obj", OBJ_TRI "f /1 2 3\n", "t:4: f: empty vertex index"},
    {"obj", OBJ_TRI "vt 0 0\nvn 0 0 1\nf 1/1/1/1 2 3\n", "t:6: f: bad vertex '1/1/1/1'"},
    {"obj", OBJ_TRI "f a b c\n", "t:4: bad integer 'a'"},
    {"obj", OBJ_TRI "f 1.0 2 3\n", "t:4: bad integer '1.0'"},
    {"obj", OBJ_TRI "f 1 2 99999999999999999999\n", "t:4: integer out of range"},
    {"obj", OBJ_TRI "f 1 2 3\n\x01\x02 junk\nf 1 2 3 x\n", "t:6: bad integer 'x'"},
    /* OFF */
    {"off", "OF\n3 1 0\n", "t:1: expected an OFF header, found 'OF'"},
    {"off", "# c\n3 1 0\n" TRI "3 0 1 2\n", "t:2: expected an OFF header, found '3'"},
    {"off", "OFF\n", "t:1: file ends before the counts line"},
    {"off", "OFF\n3\n", "t:2: counts: expected 'vertices faces [edges]'"},
    {"off", "OFF\n3 1 0 7\n", "t:2: counts: expected 'vertices faces [edges]', found more"},
    {"off", "OFF\n-3 1 0\n", "t:2: counts: negative count -3"},
    {"off", "OFF\n3 x 0\n", "t:2: bad integer 'x'"},
    {"off", "OFF\n1000000000000 1 0\n", "t:2: counts: too many vertices"},
    {"off", "OFF\n3 1000000000000 0\n", "t:2: counts: too many faces"},
    {"off", "OFF\n1000000 1 0\n" TRI, "t:2: file ends after 3 of 1000000 vertices"},
    {"off", "OFF\n3 1\n0 0 0\n1 0 0\n", "t:2: file ends after 2 of 3 vertices"},
    {"off", "OFF\n# c\n\n3 2 0\n" TRI "3 0 1 2\n", "t:4: file ends after 1 of 2 faces"},
    {"off", "OFF\n3 1 0\n0 0 0\n1 0\n", "t:4: vertex: expected 3 numbers, found 2"},
    {"off", "OFF\n3 1 0\n0 0 0\n1 0 0 1\n", "t:4: vertex: expected 3 numbers, found more"},
    {"off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1e999 0\n", "t:5: number out of range"},
    {"off", "NOFF\n3 1 0\n" TRI, "t:3: vertex: expected 6 numbers, found 3"},
    {"off", "COFF\n3 1 0\n0 0 0 1 1 1\n1 0 0 1 1\n",
     "t:4: vertex: expected 6 or 7 numbers, found 5"},
    {"off", OFF_TRI "3 0 1 3\n", "t:6: face: index 3 out of range (0..2)"},
    {"off", OFF_TRI "3 0 1 -1\n", "t:6: face: index -1 out of range (0..2)"},
    {"off", OFF_TRI "2 0 1\n", "t:6: face: needs at least 3 vertices, not 2"},
    {"off", OFF_TRI "4 0 1 2\n", "t:6: face: expected 4 indices, found 3"},
    {"off", OFF_TRI "1000000000 0 1 2\n", "t:6: face: too many vertices"},
    {"off", OFF_TRI "3 0 1 2 1 1 1 1 1\n", "t:6: face: too many values after the indices"},
    {"off", OFF_TRI "3 0 1 2 0.5 red\n", "t:6: bad number 'red'"},
    {"off", OFF_TRI "3 0 1 2.0\n", "t:6: bad integer '2.0'"},
    {"off", OFF_TRI "3 0 1 2\n3 0 1 2\n", "t:7: extra data after the last face"},
    {"off", OFF_TRI "3 0 1 2\n# fine\n\nx\n", "t:9: extra data after the last face"},
};

static void test_malformed_inputs(void **state)
{
    size_t i;
    (void)state;
    for (i = 0; i < sizeof bad_cases / sizeof bad_cases[0]; i++) {
        const bad_case *c = &bad_cases[i];
        char err[ERR_SIZE];
        stp_scene s;
        int rc;
        memset(err, 'x', sizeof err);
        err[sizeof err - 1] = '\0';
        /* garbage in the scene must not matter: it is output only */
        memset(&s, 0x5a, sizeof s);
        rc = parse_as(c->format, c->text, strlen(c->text), NULL, &s, err);
        if (rc != -1) {
            print_error("case %zu (%s): accepted \"%s\"\n", i, c->format, c->text);
            if (rc == 0)
                stp_scene_free(&s);
            fail();
        }
        {
            char what[64];
            snprintf(what, sizeof what, "case %zu (%s)", i, c->format);
            expect_prefix(err, c->prefix, what);
        }
        assert_scene_empty(&s);
    }
}

static void test_nul_bytes(void **state)
{
    static const char in_data[] = "s 0 0 0 1\ns 0 0\0 0 1\n";
    static const char in_comment[] = "# a\0b\ns 0 0 0 1\n";
    static const char at_end[] = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n\0";
    char err[ERR_SIZE];
    stp_scene s;
    (void)state;
    assert_int_equal(parse_as("nff", in_data, sizeof in_data - 1, NULL, &s, err), -1);
    expect_prefix(err, "t:2: NUL byte", "NUL in data");
    assert_scene_empty(&s);
    assert_int_equal(parse_as("nff", in_comment, sizeof in_comment - 1, NULL, &s, err), -1);
    expect_prefix(err, "t:1: NUL byte", "NUL in comment");
    assert_int_equal(parse_as("obj", at_end, sizeof at_end - 1, NULL, &s, err), -1);
    expect_prefix(err, "t:5: NUL byte", "NUL at end");
    assert_int_equal(parse_as("off", "\0", 1, NULL, &s, err), -1);
    expect_prefix(err, "t:1: NUL byte", "only NUL");
    /* the size is honoured: text after it is not read */
    assert_int_equal(parse_as("nff", "s 0 0 0 1\nbogus", 10, NULL, &s, err), 0);
    assert_int_equal(s.prim_count, 1);
    stp_scene_free(&s);
}

static void test_byte_limit(void **state)
{
    const size_t saved = stp_scene_byte_limit;
    stp_scene_options o;
    char err[ERR_SIZE];
    stp_scene s;
    int rc;
    (void)state;
    stp_scene_options_default(&o);
    o.sphere_slices = 64;
    o.sphere_stacks = 64;
    stp_scene_byte_limit = 64 * 1024;
    rc = parse_as("nff", "p 3\n" TRI "s 0 0 0 1\n", strlen("p 3\n" TRI "s 0 0 0 1\n"), &o, &s, err);
    stp_scene_byte_limit = saved;
    assert_int_equal(rc, -1);
    expect_prefix(err, "t:5: scene too large", "sphere over budget");
    /* the message says what would make the scene fit (issue 13) */
    if (!strstr(err, "fewer --slices/--stacks, or --raytrace"))
        fail_msg("no hint in: %s", err);
    assert_scene_empty(&s);
    /* within the default budget the same works */
    parse_ok("nff", "p 3\n" TRI "s 0 0 0 1\n", &o, &s);
    assert_int_equal(s.polygon_count, 1 + 64 * 64);
    stp_scene_free(&s);
}

static void test_bad_arguments(void **state)
{
    stp_scene_options o;
    char err[ERR_SIZE];
    char tiny[8];
    stp_scene s;
    (void)state;
    stp_scene_options_default(&o);
    o.sphere_slices = 2;
    assert_int_equal(parse_as("nff", "s 0 0 0 1\n", 10, &o, &s, err), -1);
    expect_prefix(err, "t: sphere_slices must be 3..1024, not 2", "slices");
    stp_scene_options_default(&o);
    o.sphere_stacks = 1;
    assert_int_equal(parse_as("nff", "s 0 0 0 1\n", 10, &o, &s, err), -1);
    expect_prefix(err, "t: sphere_stacks must be 2..1024", "stacks");
    stp_scene_options_default(&o);
    o.cone_slices = 1025;
    assert_int_equal(parse_as("nff", "s 0 0 0 1\n", 10, &o, &s, err), -1);
    expect_prefix(err, "t: cone_slices must be 3..1024", "cone slices");
    assert_scene_empty(&s);

    assert_int_equal(parse_as("stl", "s 0 0 0 1\n", 10, NULL, &s, err), -1);
    expect_prefix(err, "t: unknown format 'stl'", "format");
    assert_int_equal(parse_as("NFF", "s 0 0 0 1\n", 10, NULL, &s, err), -1);
    assert_int_equal(parse_as(NULL, "s 0 0 0 1\n", 10, NULL, &s, err), -1);
    assert_int_equal(parse_as("nff", NULL, 0, NULL, &s, err), -1);
    expect_prefix(err, "t: empty file", "NULL text");
    assert_int_equal(stp_scene_parse("x", 1, "nff", NULL, NULL, &s, err, sizeof err), -1);
    expect_prefix(err, "<input>:1: unknown entity 'x'", "no name");
    assert_int_equal(stp_scene_parse("x", 1, "nff", "t", NULL, NULL, err, sizeof err), -1);

    /* small or missing error buffers are fine */
    assert_int_equal(stp_scene_parse("x", 1, "nff", "name", NULL, &s, tiny, sizeof tiny), -1);
    assert_string_equal(tiny, "name:1:");
    assert_int_equal(stp_scene_parse("x", 1, "nff", "name", NULL, &s, NULL, 0), -1);
    assert_int_equal(stp_scene_parse("x", 1, "nff", "name", NULL, &s, tiny, 0), -1);
    assert_scene_empty(&s);

    /* unprintable bytes are not copied into messages */
    assert_int_equal(parse_as("nff", "\x01\x7f\xff 1\n", 6, NULL, &s, err), -1);
    assert_string_equal(err, "t:1: unknown entity '\?\?\?'");
    stp_scene_free(NULL);
}

static void test_bounds(void **state)
{
    stp_scene s;
    stp_scene_vec3 lo = {7, 7, 7}, hi = {7, 7, 7};
    (void)state;
    memset(&s, 0, sizeof s);
    assert_int_equal(stp_scene_bounds(&s, &lo, &hi), -1);
    assert_int_equal(stp_scene_bounds(NULL, &lo, &hi), -1);
    EXPECT_VEC(lo, 7, 7, 7);

    load_spd("tetra-s1.nff", NULL, &s);
    assert_int_equal(stp_scene_bounds(&s, &lo, &hi), 0);
    EXPECT_VEC(lo, -1, -1, -1);
    EXPECT_VEC(hi, 1, 1, 1);
    assert_int_equal(stp_scene_bounds(&s, NULL, NULL), 0);
    stp_scene_free(&s);

    /* analytic extents: the sphere's box, not its (smaller) tessellation */
    parse_ok("nff", "s 1 2 3 -2\n", NULL, &s);
    assert_int_equal(stp_scene_bounds(&s, &lo, &hi), 0);
    EXPECT_VEC(lo, -1, 0, 1);
    EXPECT_VEC(hi, 3, 4, 5);
    stp_scene_free(&s);

    /* With three slices and stacks the tessellation falls short of the
     * analytic extents on every side but the poles' z, and cones along +x
     * and -x cover both z sides: the bounds must still be exact. */
    {
        stp_scene_options o = {3, 3, 3, 0};
        parse_ok("nff", "s 1 2 3 2\nc\n0 0 0 1\n4 0 0 1\nc\n0 0 9 1\n-4 0 9 1\n", &o, &s);
        assert_int_equal(stp_scene_bounds(&s, &lo, &hi), 0);
        EXPECT_NEAR(lo.x, -4, 1e-12);
        EXPECT_NEAR(lo.y, -1, 1e-12);
        EXPECT_NEAR(lo.z, -1, 1e-12);
        EXPECT_NEAR(hi.x, 4, 1e-12);
        EXPECT_NEAR(hi.y, 4, 1e-12);
        EXPECT_NEAR(hi.z, 10, 1e-12);
        stp_scene_free(&s);
        parse_ok("nff", "s 1 2 3 2\n", &o, &s);
        assert_int_equal(stp_scene_bounds(&s, &lo, &hi), 0);
        EXPECT_NEAR(lo.x, -1, 1e-12);
        EXPECT_NEAR(lo.y, 0, 1e-12);
        EXPECT_NEAR(hi.x, 3, 1e-12);
        EXPECT_NEAR(hi.y, 4, 1e-12);
        stp_scene_free(&s);
        parse_ok("nff", "c\n0 0 0 1\n4 0 0 1\nc\n4 0 0 1\n0 0 0 1\n", &o, &s);
        assert_int_equal(stp_scene_bounds(&s, &lo, &hi), 0);
        EXPECT_NEAR(lo.z, -1, 1e-12);
        EXPECT_NEAR(hi.z, 1, 1e-12);
        EXPECT_NEAR(lo.y, -1, 1e-12);
        EXPECT_NEAR(hi.y, 1, 1e-12);
        stp_scene_free(&s);
    }

    /* a cone along z: discs of radius 2 at z=0 and 1 at z=4 */
    parse_ok("nff", "c\n0 0 0 2\n0 0 4 1\n", NULL, &s);
    assert_int_equal(stp_scene_bounds(&s, &lo, &hi), 0);
    EXPECT_NEAR(lo.x, -2, 1e-12);
    EXPECT_NEAR(lo.y, -2, 1e-12);
    EXPECT_NEAR(lo.z, 0, 1e-12);
    EXPECT_NEAR(hi.x, 2, 1e-12);
    EXPECT_NEAR(hi.z, 4, 1e-12);
    stp_scene_free(&s);

    /* along the x = y diagonal: each disc reaches r*sqrt(1/2) in x and y */
    parse_ok("nff", "c\n0 0 0 1\n3 3 0 1\n", NULL, &s);
    assert_int_equal(stp_scene_bounds(&s, &lo, &hi), 0);
    EXPECT_NEAR(lo.x, -sqrt(0.5), 1e-12);
    EXPECT_NEAR(hi.y, 3 + sqrt(0.5), 1e-12);
    EXPECT_NEAR(lo.z, -1, 1e-12);
    EXPECT_NEAR(hi.z, 1, 1e-12);
    stp_scene_free(&s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_options_default),
        cmocka_unit_test(test_spd_tetra_s1),
        cmocka_unit_test(test_spd_tetra_s2),
        cmocka_unit_test(test_spd_mount_s2),
        cmocka_unit_test(test_spd_teapot_s1),
        cmocka_unit_test(test_spd_teapot_s2),
        cmocka_unit_test(test_spd_gears_s1),
        cmocka_unit_test(test_spd_balls_s1),
        cmocka_unit_test(test_spd_balls_s2),
        cmocka_unit_test(test_sphere_tessellation),
        cmocka_unit_test(test_cone_tessellation),
        cmocka_unit_test(test_nff_default_material),
        cmocka_unit_test(test_nff_layout),
        cmocka_unit_test(test_nff_token_stream),
        cmocka_unit_test(test_byte_order_mark),
        cmocka_unit_test(test_analytic_only),
        cmocka_unit_test(test_nff_keeps_vertex_order),
        cmocka_unit_test(test_obj_face_forms),
        cmocka_unit_test(test_obj_mixed_normals),
        cmocka_unit_test(test_off_variants),
        cmocka_unit_test(test_load_fixtures),
        cmocka_unit_test(test_load_errors),
        cmocka_unit_test(test_malformed_inputs),
        cmocka_unit_test(test_nul_bytes),
        cmocka_unit_test(test_byte_limit),
        cmocka_unit_test(test_bad_arguments),
        cmocka_unit_test(test_bounds),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
