/* SPDX-License-Identifier: MIT */
/*
 * The double-precision reference ray tracer (tools/bench/raytrace_ref.h)
 * against scenes whose answer is worked out here by hand: hit distances
 * from the geometry, shades from ref_shade_point and ref_fresnel_f (the
 * reference's building blocks) at the points, normals and eyes the
 * semantics of include/stipple/raytrace.h prescribe.
 *
 * Images are 33 x 33 so that the centre pixel (16, 16) looks exactly along
 * the line of sight; with a 90 degree field of view focal = 16.5 pixels.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include <cmocka.h>

#include "raytrace_ref.h"

#define W 33
#define H 33
#define C 16 /* the centre pixel */
#define PI 3.14159265358979323846

static ref_vec3 unit(ref_vec3 a)
{
    ref_vec3 u;
    (void)ref_unit(a, &u);
    return u;
}

static void close_to(double got, double want, double tol, const char *what)
{
    if (!(fabs(got - want) <= tol)) {
        print_error("%s: got %.17g, want %.17g (tolerance %g)\n", what, got, want, tol);
        fail();
    }
}

static void vec_close_to(ref_vec3 got, ref_vec3 want, double tol, const char *what)
{
    close_to(got.x, want.x, tol, what);
    close_to(got.y, want.y, tol, what);
    close_to(got.z, want.z, tol, what);
}

static ref_rt *make_view(ref_vec3 from, ref_vec3 at, double fov, double hither)
{
    ref_rt *rt = ref_rt_create(W, H);
    ref_view v;
    assert_non_null(rt);
    v.from = from;
    v.at = at;
    v.up = ref_v3(0, 1, 0);
    v.fov_degrees = fov;
    v.window_half = 1;
    v.hither = hither;
    v.perspective = 1;
    assert_int_equal(ref_rt_set_view(rt, &v), REF_OK);
    return rt;
}

static ref_lighting one_light(ref_vec3 at, double power, double background)
{
    ref_lighting l;
    l.brightness = 1;
    l.background = background;
    l.c = 1;
    l.count = 1;
    l.lights[0].position = at;
    l.lights[0].power = power;
    return l;
}

static ref_rt_material mat(double r, double n, double k, double ks, double t, double a)
{
    ref_rt_material m;
    m.surface.reflectivity = r;
    m.surface.refraction = n;
    m.surface.gloss = k;
    m.surface.specular = ks;
    m.transmission = t;
    m.absorption = a;
    return m;
}

/* A 40 x 40 wall in the plane z = z0. */
static int add_wall(ref_rt *rt, double z0, int material)
{
    ref_vec3 v[4];
    v[0] = ref_v3(-20, -20, z0);
    v[1] = ref_v3(20, -20, z0);
    v[2] = ref_v3(20, 20, z0);
    v[3] = ref_v3(-20, 20, z0);
    return ref_rt_polygon(rt, v, NULL, 4, material);
}

/* ------------------------------------------------------------ tests */

/* A sphere seen head-on: hit at d - r, shade = ref_shade_point there;
 * a pixel beside it sees the background; the hither plane. */
static void test_sphere_head_on(void **state)
{
    ref_rt_material m[1];
    ref_lighting l = one_light(ref_v3(3, 4, -12), 5, 0.2);
    ref_rt *rt = make_view(ref_v3(0, 0, -10), ref_v3(0, 0, 0), 90, 1e-3);
    double t, want, w_r;
    ref_vec3 p, n;
    ref_view v;
    (void)state;
    m[0] = mat(0.6, 1.5, 0.5, 0.4, 0, 0);
    ref_rt_set_materials(rt, m, 1);
    ref_rt_set_lighting(rt, &l);
    assert_int_equal(ref_rt_sphere(rt, ref_v3(0, 0, 0), 2, 0), 0);

    assert_int_equal(ref_rt_primary_hit(rt, C, C, &t), 0);
    assert_true(t == 8.0); /* 10 - 2, exactly */
    assert_int_equal(ref_rt_primary_surface(rt, C, C, &p, &n), 0);
    vec_close_to(p, ref_v3(0, 0, -2), 1e-15, "hit point");
    vec_close_to(n, ref_v3(0, 0, -1), 1e-15, "normal");

    /* no recursion: the local shade alone */
    assert_int_equal(ref_rt_set_recursion(rt, 0, 0), REF_OK);
    want = ref_shade_point(&l, &m[0].surface, ref_v3(0, 0, -1), ref_v3(0, 0, -2), ref_v3(0, 0, -10), 0,
                           ref_v3(0, 0, 0));
    assert_true(want > 0.6 * 0.2 + 0.05 && want < 0.95); /* lit, not saturated */
    close_to(ref_rt_trace_pixel(rt, C, C, 0.3), want, 1e-12, "local shade");

    /* with recursion the mirror ray (back along -z) misses: + w_r * background */
    assert_int_equal(ref_rt_set_recursion(rt, 4, 1.0 / 64), REF_OK);
    w_r = 0.4 * ref_fresnel_f(1.0, 1.5);
    assert_true(w_r >= 1.0 / 64);
    close_to(ref_rt_trace_pixel(rt, C, C, 0.3), want + w_r * 0.3, 1e-12, "local + reflected background");

    /* the corner ray misses */
    assert_int_equal(ref_rt_primary_hit(rt, 0, 0, &t), -1);
    assert_true(ref_rt_trace_pixel(rt, 0, 0, 0.3) == 0.3);

    /* hither beyond the front surface: the back of the sphere at 12 */
    v.from = ref_v3(0, 0, -10);
    v.at = ref_v3(0, 0, 0);
    v.up = ref_v3(0, 1, 0);
    v.fov_degrees = 90;
    v.window_half = 1;
    v.hither = 9;
    v.perspective = 1;
    assert_int_equal(ref_rt_set_view(rt, &v), REF_OK);
    assert_int_equal(ref_rt_primary_hit(rt, C, C, &t), 0);
    close_to(t, 12, 1e-14, "hit behind the hither plane");
    ref_rt_free(rt);
}

/* A wall behind a sphere that stands between it and the light: opaque,
 * the ambient share only; transmissive, the light's power times t (once
 * for the sphere, in and out). */
static void test_shadow_behind_sphere(void **state)
{
    ref_rt_material m[2];
    ref_lighting l = one_light(ref_v3(4, 0, -5), 3, 0.25), dim;
    ref_rt *rt = make_view(ref_v3(0, 0, -10), ref_v3(0, 0, 0), 90, 1e-3);
    double t, lit, want;
    int wall, ball;
    (void)state;
    m[0] = mat(0.7, 10, 10, 0, 0, 0);  /* the wall */
    m[1] = mat(0.5, 1.5, 10, 0, 0, 0); /* the sphere, opaque */
    ref_rt_set_materials(rt, m, 2);
    ref_rt_set_lighting(rt, &l);
    wall = add_wall(rt, 5, 0);
    ball = ref_rt_sphere(rt, ref_v3(2, 0, 0), 1, 1);
    assert_int_equal(wall, 0);
    assert_int_equal(ball, 1);

    /* the eye ray passes 2 from the sphere's centre and meets the wall at
     * (0, 0, 5); the segment from there to the light crosses the centre */
    assert_int_equal(ref_rt_primary_hit(rt, C, C, &t), wall);
    close_to(t, 15, 1e-13, "wall distance");
    close_to(ref_rt_trace_pixel(rt, C, C, 0), 0.25 * 0.7, 1e-15, "shadowed: ambient only");

    lit = ref_shade_point(&l, &m[0].surface, ref_v3(0, 0, -1), ref_v3(0, 0, 5), ref_v3(0, 0, -10), 0,
                          ref_v3(0, 0, 0));
    assert_true(lit > 0.25 * 0.7 + 0.05);

    /* a transmissive sphere (the table is kept by pointer): power x 0.4 */
    m[1].transmission = 0.4;
    dim = l;
    dim.lights[0].power *= 0.4;
    want = ref_shade_point(&dim, &m[0].surface, ref_v3(0, 0, -1), ref_v3(0, 0, 5), ref_v3(0, 0, -10), 0,
                           ref_v3(0, 0, 0));
    assert_true(want > 0.25 * 0.7 + 0.01 && want < lit - 0.01);
    close_to(ref_rt_trace_pixel(rt, C, C, 0), want, 1e-12, "shadow through t = 0.4");
    ref_rt_free(rt);
}

/* A mirror (Ks = 1, n huge) at 45 degrees reflecting a sphere: local shade
 * plus w_r times the sphere's shade seen from the mirror point; the depth
 * and weight cut-offs. */
static void test_mirror(void **state)
{
    ref_rt_material m[2];
    ref_lighting l = one_light(ref_v3(0, 2, -6), 10, 0.1);
    ref_rt *rt = make_view(ref_v3(0, 4, -4), ref_v3(0, 0, 0), 90, 1e-3);
    ref_vec3 quad[4], q, nq;
    double t, v_l, v_s, w_r, want;
    (void)state;
    m[0] = mat(0.1, 1e6, 0.02, 1, 0, 0); /* the mirror: a sharp highlight */
    m[1] = mat(0.8, 1.5, 10, 0, 0, 0);   /* the sphere: no secondary rays */
    ref_rt_set_materials(rt, m, 2);
    ref_rt_set_lighting(rt, &l);
    quad[0] = ref_v3(-3, -3, 0);
    quad[1] = ref_v3(3, -3, 0);
    quad[2] = ref_v3(3, 3, 0);
    quad[3] = ref_v3(-3, 3, 0);
    assert_int_equal(ref_rt_polygon(rt, quad, NULL, 4, 0), 0);
    assert_int_equal(ref_rt_sphere(rt, ref_v3(0, -4, -4), 1, 1), 1);
    assert_int_equal(ref_rt_set_recursion(rt, 4, 0), REF_OK);

    assert_int_equal(ref_rt_primary_hit(rt, C, C, &t), 0);
    close_to(t, 4 * sqrt(2.0), 1e-14, "mirror distance");

    /* at the origin: N = (0,0,-1) towards the eye, E.N = 1/sqrt 2; the
     * mirror ray (0,-1,-1)/sqrt 2 meets the sphere at 4 sqrt 2 - 1 */
    v_l = ref_shade_point(&l, &m[0].surface, ref_v3(0, 0, -1), ref_v3(0, 0, 0), ref_v3(0, 4, -4), 0,
                          ref_v3(0, 0, 0));
    q = ref_scale(unit(ref_v3(0, -1, -1)), 4 * sqrt(2.0) - 1);
    nq = unit(ref_v3(0, 1, 1));
    v_s = ref_shade_point(&l, &m[1].surface, nq, q, ref_v3(0, 0, 0), 0, ref_v3(0, 0, 0));
    w_r = ref_fresnel_f(1 / sqrt(2.0), 1e6);
    assert_true(w_r > 0.99 && w_r <= 1);
    assert_true(v_s > 0.3);
    want = v_l + w_r * v_s;
    assert_true(want < 1);
    close_to(ref_rt_trace_pixel(rt, C, C, 0), want, 1e-9, "mirror");
    close_to(ref_rt_trace_pixel(rt, C, C, 0.5), want, 1e-9, "mirror, background not seen");

    /* depth 0: primary ray and shadows only */
    assert_int_equal(ref_rt_set_recursion(rt, 0, 0), REF_OK);
    close_to(ref_rt_trace_pixel(rt, C, C, 0), v_l, 1e-12, "max depth 0");
    /* the weight cut-off: cast when w_r >= min_weight */
    assert_int_equal(ref_rt_set_recursion(rt, 1, w_r * (1 + 1e-9)), REF_OK);
    close_to(ref_rt_trace_pixel(rt, C, C, 0), v_l, 1e-12, "min weight above w_r");
    assert_int_equal(ref_rt_set_recursion(rt, 1, w_r * (1 - 1e-9)), REF_OK);
    close_to(ref_rt_trace_pixel(rt, C, C, 0), want, 1e-9, "min weight below w_r");
    ref_rt_free(rt);
}

/* A glass sphere of index 1 (R = 0: no light of its own) in front of a
 * wall: rays go straight through, F = 0, each of its two surfaces passes
 * t (1 - F) = t, and the inside path is weighted by e^(-a d). */
static void test_glass_index_one(void **state)
{
    ref_rt_material m[2];
    ref_lighting l = one_light(ref_v3(0, 6, -10), 8, 0.2);
    ref_rt *rt = make_view(ref_v3(0, 0, -10), ref_v3(0, 0, 0), 90, 1e-3);
    ref_vec3 o, d, pw;
    double t, v_wall, want, tw;
    (void)state;
    m[0] = mat(0, 1, 10, 0, 0.5, 0); /* the glass */
    m[1] = mat(0.7, 10, 10, 0, 0, 0); /* the wall */
    ref_rt_set_materials(rt, m, 2);
    ref_rt_set_lighting(rt, &l);
    assert_int_equal(ref_rt_sphere(rt, ref_v3(0, 0, 0), 1, 0), 0);
    assert_int_equal(add_wall(rt, 5, 1), 1);
    assert_int_equal(ref_rt_set_recursion(rt, 4, 0), REF_OK);

    assert_int_equal(ref_rt_primary_hit(rt, C, C, &t), 0);
    close_to(t, 9, 1e-14, "glass distance");
    /* (0, 0, 5): its segment to the light passes 1.86 from the sphere */
    v_wall = ref_shade_point(&l, &m[1].surface, ref_v3(0, 0, -1), ref_v3(0, 0, 5), ref_v3(0, 0, -10), 0,
                             ref_v3(0, 0, 0));
    assert_true(v_wall > 0.3);
    close_to(ref_rt_trace_pixel(rt, C, C, 0), 0.25 * v_wall, 1e-12, "through glass, n = 1");

    /* off the axis: still straight (the wall point on the eye ray) */
    assert_int_equal(ref_rt_primary_ray(rt, C + 1, C, &o, &d), REF_OK);
    assert_int_equal(ref_rt_primary_hit(rt, C + 1, C, &t), 0);
    tw = (5 - o.z) / d.z;
    pw = ref_add(o, ref_scale(d, tw));
    want = 0.25 * ref_shade_point(&l, &m[1].surface, ref_v3(0, 0, -1), pw, o, 0, ref_v3(0, 0, 0));
    close_to(ref_rt_trace_pixel(rt, C + 1, C, 0), want, 1e-12, "off axis, n = 1");

    /* absorption over the diameter */
    m[0].absorption = 0.3;
    close_to(ref_rt_trace_pixel(rt, C, C, 0), 0.25 * exp(-0.6) * v_wall, 1e-12, "absorption");

    /* depth: the wall is the third surface (depth 2) */
    assert_int_equal(ref_rt_set_recursion(rt, 1, 0), REF_OK);
    close_to(ref_rt_trace_pixel(rt, C, C, 0), 0, 1e-15, "max depth 1");
    /* path weights: 0.5 (into the glass) x e^-0.6 = 0.274, then x 0.5 =
     * 0.137 for the ray out */
    assert_int_equal(ref_rt_set_recursion(rt, 4, 0.13), REF_OK);
    close_to(ref_rt_trace_pixel(rt, C, C, 0), 0.25 * exp(-0.6) * v_wall, 1e-12, "min weight 0.13");
    assert_int_equal(ref_rt_set_recursion(rt, 4, 0.14), REF_OK);
    close_to(ref_rt_trace_pixel(rt, C, C, 0), 0, 1e-15, "min weight 0.14");
    m[0].absorption = 0;
    assert_int_equal(ref_rt_set_recursion(rt, 4, 0.24), REF_OK);
    close_to(ref_rt_trace_pixel(rt, C, C, 0), 0.25 * v_wall, 1e-12, "min weight 0.24");
    assert_int_equal(ref_rt_set_recursion(rt, 4, 0.26), REF_OK);
    close_to(ref_rt_trace_pixel(rt, C, C, 0), 0, 1e-15, "min weight 0.26");
    ref_rt_free(rt);
}

/* Total internal reflection: the eye inside a sphere of index 2 at 0.9
 * from its centre, looking along +z: the wall is met at sin i = 0.9 > 1/2,
 * so the whole transmitted share goes into the reflected ray, which runs
 * along a chord of length 2 sqrt(0.19) (absorbed) to the next wall point,
 * again at the same angle. */
static void test_total_internal_reflection(void **state)
{
    ref_rt_material m[1];
    ref_lighting l = one_light(ref_v3(0, 0, 0), 1, 0.1);
    ref_rt *rt = make_view(ref_v3(0.9, 0, 0), ref_v3(0.9, 0, 1), 90, 1e-3);
    ref_vec3 d = ref_v3(0, 0, 1), p1, n1, r1, p2, n2, r2, p3, n3;
    double z1 = sqrt(0.19), t, f, w, att, v1, v2, v3_, want;
    (void)state;
    m[0] = mat(0.5, 2, 10, 0.5, 0.6, 0.2);
    ref_rt_set_materials(rt, m, 1);
    ref_rt_set_lighting(rt, &l);
    assert_int_equal(ref_rt_sphere(rt, ref_v3(0, 0, 0), 1, 0), 0);

    assert_int_equal(ref_rt_primary_hit(rt, C, C, &t), 0);
    close_to(t, z1, 1e-15, "far root from inside");
    p1 = ref_v3(0.9, 0, z1);
    n1 = ref_scale(p1, -1); /* faced: inwards */
    f = ref_fresnel_f(z1, 2); /* c = E.N = z1 */
    w = 0.5 * f + 0.6 * (1 - f); /* Ks F + t (1 - F) */
    att = exp(-0.2 * 2 * z1);
    r1 = ref_sub(d, ref_scale(n1, 2 * ref_dot(d, n1)));
    p2 = ref_add(p1, ref_scale(r1, 2 * z1));
    close_to(ref_dot(p2, p2), 1, 1e-14, "second point on the sphere");
    n2 = ref_scale(p2, -1);
    r2 = ref_sub(r1, ref_scale(n2, 2 * ref_dot(r1, n2)));
    p3 = ref_add(p2, ref_scale(r2, 2 * z1));
    n3 = ref_scale(p3, -1);
    close_to(ref_dot(r1, n2), -z1, 1e-14, "same angle at the second point");

    v1 = ref_shade_point(&l, &m[0].surface, n1, p1, ref_v3(0.9, 0, 0), 0, ref_v3(0, 0, 0));
    v2 = ref_shade_point(&l, &m[0].surface, n2, p2, p1, 0, ref_v3(0, 0, 0));
    v3_ = ref_shade_point(&l, &m[0].surface, n3, p3, p2, 0, ref_v3(0, 0, 0));
    assert_true(v1 > 0.1 && v2 > 0.1 && v3_ > 0.1);

    /* a background of 1 would show any ray wrongly sent out */
    assert_int_equal(ref_rt_set_recursion(rt, 0, 0), REF_OK);
    close_to(ref_rt_trace_pixel(rt, C, C, 1), v1, 1e-12, "TIR, depth 0");
    assert_int_equal(ref_rt_set_recursion(rt, 1, 0), REF_OK);
    want = v1 + w * att * v2;
    if (want > 1)
        want = 1;
    assert_true(want < 1);
    close_to(ref_rt_trace_pixel(rt, C, C, 1), want, 1e-12, "TIR, depth 1");
    assert_int_equal(ref_rt_set_recursion(rt, 2, 0), REF_OK);
    want = v2 + w * att * v3_;
    want = v1 + w * att * (want > 1 ? 1 : want);
    assert_true(want < 1);
    close_to(ref_rt_trace_pixel(rt, C, C, 1), want, 1e-12, "TIR, depth 2");
    ref_rt_free(rt);
}

/* Cones: a hand calculation of the hit distance, the axial range (the
 * infinite double cone would be hit), no caps, the inside wall. */
static void test_cone(void **state)
{
    ref_rt_material m[1];
    ref_rt *rt = make_view(ref_v3(0, 0, -10), ref_v3(0, 0, 0), 90, 1e-3);
    ref_vec3 p, n;
    ref_view v;
    double t, fov;
    (void)state;
    m[0] = mat(0.5, 10, 10, 0, 0, 0);
    ref_rt_set_materials(rt, m, 1);
    /* radius (1 - y)/2 for y in [-1, 1] */
    assert_int_equal(ref_rt_cone(rt, ref_v3(0, -1, 0), 1, ref_v3(0, 1, 0), 0, 0), 0);

    assert_int_equal(ref_rt_primary_hit(rt, C, C, &t), 0);
    close_to(t, 9.5, 1e-14, "cone, centre");
    assert_int_equal(ref_rt_primary_surface(rt, C, C, &p, &n), 0);
    /* gradient of x^2 + z^2 - ((1 - y)/2)^2 at (0, 0, -0.5): (0, 1/2, -1) */
    vec_close_to(n, unit(ref_v3(0, 0.5, -1)), 1e-14, "cone normal");

    /* pixel (16, 15): direction (0, 1, 16.5); -10 + 16.5 s = -(1 - s)/2
     * gives s = 9.5/16, y = s inside the range */
    assert_int_equal(ref_rt_primary_hit(rt, C, C - 1, &t), 0);
    close_to(t, 9.5 / 16 * sqrt(1 + 16.5 * 16.5), 1e-13, "cone, one pixel up");
    /* pixel (16, 13): the roots are at y = 1.9 and 1.75, beyond the apex */
    assert_int_equal(ref_rt_primary_hit(rt, C, C - 3, &t), -1);
    ref_rt_free(rt);

    /* an open cylinder along x, radius 1/2 */
    rt = make_view(ref_v3(0, 0, -10), ref_v3(0, 0, 0), 90, 1e-3);
    ref_rt_set_materials(rt, m, 1);
    assert_int_equal(ref_rt_cone(rt, ref_v3(-1, 0, 0), 0.5, ref_v3(1, 0, 0), 0.5, 0), 0);
    assert_int_equal(ref_rt_primary_hit(rt, C, C, &t), 0);
    close_to(t, 9.5, 1e-14, "cylinder, centre");
    /* along its axis: no caps */
    v.from = ref_v3(-10, 0, 0);
    v.at = ref_v3(0, 0, 0);
    v.up = ref_v3(0, 1, 0);
    v.window_half = 1;
    v.hither = 1e-3;
    v.perspective = 1;
    v.fov_degrees = 90;
    assert_int_equal(ref_rt_set_view(rt, &v), REF_OK);
    assert_int_equal(ref_rt_primary_hit(rt, C, C, &t), -1);
    /* focal 20: pixel (17, 16) looks along (20, 0, 1) (right = +z), into
     * the open end, and meets the inside wall at (0, 0, 1/2) */
    fov = 2 * atan(16.5 / 20) * 180 / PI;
    v.fov_degrees = fov;
    assert_int_equal(ref_rt_set_view(rt, &v), REF_OK);
    assert_int_equal(ref_rt_primary_surface(rt, C + 1, C, &p, &n), 0);
    vec_close_to(p, ref_v3(0, 0, 0.5), 1e-13, "inside wall point");
    vec_close_to(n, ref_v3(0, 0, -1), 1e-13, "inside wall normal, facing the ray");
    assert_int_equal(ref_rt_primary_hit(rt, C + 1, C, &t), 0);
    close_to(t, 0.5 * sqrt(401.0), 1e-13, "inside wall distance");
    ref_rt_free(rt);
}

/* Barycentric weights of p in the triangle (a, b, c) of the plane z = 0. */
static void bary(ref_vec3 p, ref_vec3 a, ref_vec3 b, ref_vec3 c, double w[3])
{
    double area = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
    w[1] = ((p.x - a.x) * (c.y - a.y) - (c.x - a.x) * (p.y - a.y)) / area;
    w[2] = ((b.x - a.x) * (p.y - a.y) - (p.x - a.x) * (b.y - a.y)) / area;
    w[0] = 1 - w[1] - w[2];
}

/* The normal a patch quad should have at p: fan triangles (v0, v1, v2),
 * (v0, v2, v3). */
static ref_vec3 quad_normal(const ref_vec3 *v, const ref_vec3 *nu, ref_vec3 p)
{
    double w[3];
    bary(p, v[0], v[1], v[2], w);
    if (w[0] >= 0 && w[1] >= 0 && w[2] >= 0)
        return unit(ref_add(ref_add(ref_scale(nu[0], w[0]), ref_scale(nu[1], w[1])), ref_scale(nu[2], w[2])));
    bary(p, v[0], v[2], v[3], w);
    assert_true(w[0] >= 0 && w[1] >= 0 && w[2] >= 0);
    return unit(ref_add(ref_add(ref_scale(nu[0], w[0]), ref_scale(nu[2], w[1])), ref_scale(nu[3], w[2])));
}

/* Patch normals: at the centre of a quad (the diagonal v0 v2), the average
 * of N0 and N2; elsewhere barycentric within the fan triangle; any length;
 * a zero normal takes the plane's. */
static void test_patch_normals(void **state)
{
    ref_rt_material m[1];
    ref_lighting l = one_light(ref_v3(3, 2, -5), 4, 0.1);
    ref_rt *rt = make_view(ref_v3(0, 0, -10), ref_v3(0, 0, 0), 90, 1e-3);
    ref_vec3 v[4], nn[4], nu[4], p, n, want;
    int pix[3][2] = {{C, C}, {C - 4, C + 2}, {C + 3, C - 2}};
    int i;
    (void)state;
    m[0] = mat(0.6, 1.5, 0.3, 0.5, 0, 0);
    ref_rt_set_materials(rt, m, 1);
    ref_rt_set_lighting(rt, &l);
    assert_int_equal(ref_rt_set_recursion(rt, 0, 0), REF_OK);
    v[0] = ref_v3(-3, -3, 0);
    v[1] = ref_v3(3, -3, 0);
    v[2] = ref_v3(3, 3, 0);
    v[3] = ref_v3(-3, 3, 0);
    nn[0] = ref_v3(0.3, 0.2, -1);
    nn[1] = ref_v3(1.5, 0, -3); /* length 3.35: only its direction counts */
    nn[2] = ref_v3(-0.1, 0.4, -1);
    nn[3] = ref_v3(0, -0.5, -1);
    for (i = 0; i < 4; i++)
        nu[i] = unit(nn[i]);
    assert_int_equal(ref_rt_polygon(rt, v, nn, 4, 0), 0);

    assert_int_equal(ref_rt_primary_surface(rt, C, C, &p, &n), 0);
    vec_close_to(p, ref_v3(0, 0, 0), 1e-14, "quad centre");
    vec_close_to(n, unit(ref_add(nu[0], nu[2])), 1e-14, "centre: unit(N0 + N2)");

    for (i = 0; i < 3; i++) {
        double s;
        assert_int_equal(ref_rt_primary_surface(rt, pix[i][0], pix[i][1], &p, &n), 0);
        close_to(p.z, 0, 1e-14, "on the plane");
        want = quad_normal(v, nu, p);
        vec_close_to(n, want, 1e-13, "interpolated normal");
        s = ref_shade_point(&l, &m[0].surface, want, p, ref_v3(0, 0, -10), 0, ref_v3(0, 0, 0));
        close_to(ref_rt_trace_pixel(rt, pix[i][0], pix[i][1], 0), s, 1e-12, "patch shade");
    }
    /* the normals matter: the flat plane's shade differs */
    {
        double flat = ref_shade_point(&l, &m[0].surface, ref_v3(0, 0, -1), ref_v3(0, 0, 0),
                                      ref_v3(0, 0, -10), 0, ref_v3(0, 0, 0));
        assert_true(fabs(ref_rt_trace_pixel(rt, C, C, 0) - flat) > 0.01);
    }
    ref_rt_free(rt);

    /* N3 = 0: the plane's normal, on the side of the others (-z), in the
     * triangle (v0, v2, v3) (y > x): pixel (19, 14) hits (-1.82, 1.21) */
    rt = make_view(ref_v3(0, 0, -10), ref_v3(0, 0, 0), 90, 1e-3);
    ref_rt_set_materials(rt, m, 1);
    nn[3] = ref_v3(0, 0, 0);
    nu[3] = ref_v3(0, 0, -1);
    assert_int_equal(ref_rt_polygon(rt, v, nn, 4, 0), 0);
    assert_int_equal(ref_rt_primary_surface(rt, C + 3, C - 2, &p, &n), 0);
    assert_true(p.x < -1.8 && p.y > 1.2);
    want = quad_normal(v, nu, p);
    vec_close_to(n, want, 1e-13, "zero vertex normal takes the plane's");
    ref_rt_free(rt);
}

/* A concave (L-shaped) polygon seen in parallel projection: the notch is
 * empty; parallel primary rays shade with E = -d. */
static void test_concave_parallel(void **state)
{
    ref_rt_material m[1];
    ref_lighting l = one_light(ref_v3(-3, -2, -4), 4, 0.1);
    ref_rt *rt = ref_rt_create(W, H);
    ref_vec3 v[6];
    ref_view view;
    double t, want;
    (void)state;
    assert_non_null(rt);
    m[0] = mat(0.6, 1.5, 0.3, 0.5, 0, 0);
    ref_rt_set_materials(rt, m, 1);
    ref_rt_set_lighting(rt, &l);
    assert_int_equal(ref_rt_set_recursion(rt, 0, 0), REF_OK);
    view.from = ref_v3(0, 0, -10);
    view.at = ref_v3(0, 0, 0);
    view.up = ref_v3(0, 1, 0);
    view.fov_degrees = 90;
    view.window_half = 3.3; /* focal = 16.5 / 3.3 = 5 pixels per unit */
    view.hither = 1e-3;
    view.perspective = 0;
    assert_int_equal(ref_rt_set_view(rt, &view), REF_OK);
    v[0] = ref_v3(-2, -2, 0);
    v[1] = ref_v3(2, -2, 0);
    v[2] = ref_v3(2, 0, 0);
    v[3] = ref_v3(0, 0, 0);
    v[4] = ref_v3(0, 2, 0);
    v[5] = ref_v3(-2, 2, 0);
    assert_int_equal(ref_rt_polygon(rt, v, NULL, 6, 0), 0);
    /* pixel (i, j) sees world x = -(i + 0.5 - 16.5)/5, y = (16.5 - j - 0.5)/5 */
    assert_int_equal(ref_rt_primary_hit(rt, 11, 11, &t), -1); /* (1, 1): the notch */
    assert_true(ref_rt_trace_pixel(rt, 11, 11, 0.4) == 0.4);
    assert_int_equal(ref_rt_primary_hit(rt, 21, 21, &t), 0); /* (-1, -1) */
    close_to(t, 10, 1e-14, "parallel distance");
    assert_int_equal(ref_rt_primary_hit(rt, 11, 21, &t), 0);  /* (1, -1) */
    assert_int_equal(ref_rt_primary_hit(rt, 21, 11, &t), 0);  /* (-1, 1) */
    want = ref_shade_point(&l, &m[0].surface, ref_v3(0, 0, -1), ref_v3(-1, -1, 0), ref_v3(0, 0, 0), 1,
                           ref_v3(0, 0, -1));
    assert_true(want > 0.1);
    close_to(ref_rt_trace_pixel(rt, 21, 21, 0), want, 1e-12, "parallel shade");
    ref_rt_free(rt);
}

/* Arguments and errors. */
static void test_errors(void **state)
{
    ref_rt_material m[1];
    ref_rt *rt;
    ref_vec3 line[3];
    ref_view v;
    (void)state;
    assert_null(ref_rt_create(0, 5));
    assert_null(ref_rt_create(5, 32768));
    rt = ref_rt_create(W, H);
    assert_non_null(rt);
    assert_int_equal(ref_rt_sphere(rt, ref_v3(0, 0, 0), 0, 0), REF_ERR_DEGENERATE);
    assert_int_equal(ref_rt_sphere(rt, ref_v3(0, 0, 0), -1, 0), REF_ERR_ARG);
    assert_int_equal(ref_rt_cone(rt, ref_v3(0, 0, 0), 1, ref_v3(0, 0, 0), 1, 0), REF_ERR_DEGENERATE);
    assert_int_equal(ref_rt_cone(rt, ref_v3(0, 0, 0), 0, ref_v3(0, 1, 0), 0, 0), REF_ERR_ARG);
    line[0] = ref_v3(0, 0, 0);
    line[1] = ref_v3(1, 1, 1);
    line[2] = ref_v3(2, 2, 2);
    assert_int_equal(ref_rt_polygon(rt, line, NULL, 3, 0), REF_ERR_DEGENERATE);
    assert_int_equal(ref_rt_polygon(rt, line, NULL, 2, 0), REF_ERR_DEGENERATE);
    assert_int_equal(ref_rt_set_recursion(rt, -1, 0), REF_ERR_ARG);
    assert_int_equal(ref_rt_set_recursion(rt, 2, 1.5), REF_ERR_ARG);
    v.from = ref_v3(0, 0, 0);
    v.at = ref_v3(0, 1, 0);
    v.up = ref_v3(0, 1, 0);
    v.fov_degrees = 90;
    v.window_half = 1;
    v.hither = 1;
    v.perspective = 1;
    assert_int_equal(ref_rt_set_view(rt, &v), REF_ERR_VIEW);
    assert_int_equal((int)ref_rt_object_count(rt), 0);
    /* the default view looks from (0,0,-1) along +z */
    assert_int_equal(ref_rt_sphere(rt, ref_v3(0, 0, 3), 1, 0), 0);
    assert_true(ref_rt_trace_pixel(rt, C, C, 0) == -1); /* no material table */
    m[0] = mat(1, 10, 10, 0, 0, 0);
    ref_rt_set_materials(rt, m, 1);
    assert_true(ref_rt_trace_pixel(rt, C, C, 0) >= 0);
    assert_true(ref_rt_trace_pixel(rt, W, 0, 0) == -1);
    assert_int_equal(ref_rt_primary_hit(rt, -1, 0, NULL), -1);
    ref_rt_free(rt);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sphere_head_on),
        cmocka_unit_test(test_shadow_behind_sphere),
        cmocka_unit_test(test_mirror),
        cmocka_unit_test(test_glass_index_one),
        cmocka_unit_test(test_total_internal_reflection),
        cmocka_unit_test(test_cone),
        cmocka_unit_test(test_patch_normals),
        cmocka_unit_test(test_concave_parallel),
        cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
