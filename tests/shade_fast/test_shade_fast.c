/* SPDX-License-Identifier: MIT */
/*
 * The 32-bit flat-face shading (src/shade_fast.c) against the double
 * reference (tests/reference/shade_ref.c, written from docs/model.md
 * section 2, no code shared with src/) and against the accurate path
 * stp_shade_unit.  The reference sees the exact inputs the fast path
 * sees: the Q14 normal (normalised: the fast path takes |N| as 1), the
 * points and lights as rounded to stp_fix.
 *
 * Tolerances (absolute, shade in [0, 1]) are the worst errors measured
 * here with a margin, printed when the test runs; see docs/realtime.md.
 * At grazing view (N.E < GRAZING) the specular share is divided by N.E,
 * and so is its error: there the bound is TOL GRAZING / N.E, as in
 * tests/core/test_shade.c.
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

#include "reference/shade_ref.h"
#include "shade_fast_private.h"
#include "shade_private.h"

#define F STP_FIX_FRAC_BITS
#define ONE STP_FIX_ONE
#define LSB (1.0 / (double)ONE)
#define PI 3.14159265358979323846
#define GRAZING 0.1

/* Worst error allowed against the reference, and against stp_shade_unit
 * (measured at F = 16, printed: 1.8e-4 worst over the random faces,
 * 6.2e-5 over the grid, 9.3e-5 over the Fresnel range sweep, 2.4e-5 over
 * the highlight sweep, 1.9e-5 over the stiff cases; 1.4e-4 from
 * stp_shade_unit): a margin of 2.8, and 1/67 of a 16-level INTENSITY step.
 * With STP_WITH_SPECULAR 0 both paths are diffuse-only. */
#if STP_FIX_FRAC_BITS >= 16
#define TOL 5e-4
#else
#define TOL (5e-4 * (double)(1 << (16 - STP_FIX_FRAC_BITS)))
#endif

static stp_fix fx(double v)
{
    return (stp_fix)floor(v * ONE + 0.5);
}

static double dbl(stp_fix v)
{
    return (double)v * LSB;
}

static stp_vec3 fvec(double x, double y, double z)
{
    stp_vec3 v;
    v.x = fx(x);
    v.y = fx(y);
    v.z = fx(z);
    return v;
}

static ref_vec3 rvec(stp_vec3 v)
{
    return ref_v3(dbl(v.x), dbl(v.y), dbl(v.z));
}

/* A unit normal as the Q14 int16 triple the mesh path prepares, and the
 * reference's normal: that triple's exact direction. */
static ref_vec3 q14_normal(double x, double y, double z, int16_t n[3])
{
    double len = sqrt(x * x + y * y + z * z);
    ref_vec3 r;
    n[0] = (int16_t)lround(x / len * 16384.0);
    n[1] = (int16_t)lround(y / len * 16384.0);
    n[2] = (int16_t)lround(z / len * 16384.0);
    (void)ref_unit(ref_v3(n[0], n[1], n[2]), &r);
    return r;
}

typedef struct light_desc {
    double x, y, z, power;
} light_desc;

static void make_lighting(stp_lighting *fl, ref_lighting *rl, double bright, double background,
                          double c, const light_desc *lights, int count)
{
    int j;
    stp_lighting_default(fl);
    fl->brightness = fx(bright);
    fl->background = fx(background);
    fl->attenuation_c = fx(c);
    fl->count = count;
    rl->brightness = dbl(fl->brightness);
    rl->background = dbl(fl->background);
    rl->c = dbl(fl->attenuation_c);
    rl->count = count;
    for (j = 0; j < count; j++) {
        fl->lights[j].position = fvec(lights[j].x, lights[j].y, lights[j].z);
        fl->lights[j].power = fx(lights[j].power);
        rl->lights[j].position = rvec(fl->lights[j].position);
        rl->lights[j].power = dbl(fl->lights[j].power);
    }
}

static void make_material(stp_material *fm, ref_material *rm, double refl, double n, double k,
                          double ks)
{
    stp_material_default(fm);
    fm->reflectivity = fx(refl);
    fm->refraction = fx(n);
    fm->gloss = fx(k);
    fm->specular = fx(ks);
    rm->reflectivity = dbl(fm->reflectivity);
    rm->refraction = dbl(fm->refraction);
    rm->gloss = dbl(fm->gloss);
#if STP_WITH_SPECULAR
    rm->specular = dbl(fm->specular);
#else
    rm->specular = 0; /* the diffuse-only build */
#endif
}

/* ---- one comparison ---- */

typedef struct stats {
    long cases, graze_cases;
    double worst, worst_graze, worst_ratio, sum_err, sum_s;
    double worst_accurate, sum_accurate; /* |fast - stp_shade_unit| */
} stats;

typedef struct scene {
    stp_lighting fl;
    ref_lighting rl;
    stp_material fm;
    ref_material rm;
    stp_vec3 eye, pdir;
    int parallel;
} scene;

/* The accurate path on the same inputs, as render.c calls it. */
static stp_fix accurate(const scene *sc, const int16_t n[3], stp_vec3 point)
{
    stp_unit3 un, ue;
    int32_t ne;
    (void)stp_unit_from64(n[0], n[1], n[2], &un);
    if (sc->parallel)
        (void)stp_unit_from64(sc->pdir.x, sc->pdir.y, sc->pdir.z, &ue);
    else if (stp_unit_from64((int64_t)sc->eye.x - point.x, (int64_t)sc->eye.y - point.y,
                             (int64_t)sc->eye.z - point.z, &ue) == 0)
        return stp_shade_unit(&sc->fl, &sc->fm, un, point, ue, 0);
    ne = stp_unit_dot(un, ue);
    return stp_shade_unit(&sc->fl, &sc->fm, un, point, ue, ne < 0 ? 0 : ne);
}

#if !STP_WITH_SPECULAR
/* Without the highlight there is no exact route to take over where the
 * light's gain BRIGHT P_j |R| / (C + U_j) is large (with it, prepare sends
 * every face of a gain above 16 there), so the 32-bit routes' cosine
 * error, about 1.5e-5 on the main route and 1.1e-5 on the compact one,
 * is multiplied by the gain: TOL up to a gain of 20, 2.5e-5 times the
 * gain above (measured at gain 200: 3.1e-3 main, 2.2e-3 compact; the
 * host's 64-bit route 6.2e-6). */
#define NO_EXACT_TOL_PER_GAIN 2.5e-5
static double gain_tol(const scene *sc, stp_vec3 point)
{
    double gain = 0;
    int j;
    for (j = 0; j < sc->rl.count; j++) {
        ref_vec3 d = ref_sub(sc->rl.lights[j].position, rvec(point));
        double g = sc->rl.brightness * sc->rl.lights[j].power * fabs(sc->rm.reflectivity) /
                   (sc->rl.c + sqrt(ref_dot(d, d)));
        gain = fmax(gain, g);
    }
    return NO_EXACT_TOL_PER_GAIN * gain;
}
#endif

/* Compare one face; returns its error. */
static double check(const scene *sc, const int16_t n[3], ref_vec3 rn, stp_vec3 point, stats *st,
                    const char *what)
{
    stp_shade_fast s;
    ref_vec3 e;
    double want, got, err, tol = TOL, ne, acc;
    stp_fix got_fix;
    stp_shade_fast_prepare(&s, &sc->fl, &sc->fm, sc->eye, sc->parallel, sc->pdir);
    got_fix = stp_shade_fast_face(&s, n, point);
    want = ref_shade_point(&sc->rl, &sc->rm, rn, rvec(point), rvec(sc->eye), sc->parallel, rvec(sc->pdir));
    got = dbl(got_fix);
    err = fabs(got - want);
    if (sc->parallel)
        (void)ref_unit(rvec(sc->pdir), &e);
    else
        (void)ref_unit(ref_sub(rvec(sc->eye), rvec(point)), &e);
    ne = ref_dot(rn, e);
    assert_true(got_fix >= 0 && got_fix <= ONE);
    if (ne > 0 && ne < GRAZING) {
        tol = TOL * GRAZING / ne;
        st->graze_cases++;
        if (err > st->worst_graze)
            st->worst_graze = err;
    } else {
        st->cases++;
        if (err > st->worst)
            st->worst = err;
    }
#if !STP_WITH_SPECULAR
    tol = fmax(tol, gain_tol(sc, point));
#endif
    if (err / tol > st->worst_ratio)
        st->worst_ratio = err / tol;
    st->sum_err += err;
    st->sum_s += want;
    acc = fabs(got - dbl(accurate(sc, n, point)));
    if (acc > tol)
        fail_msg("%s: %.6f, stp_shade_unit %.6f", what, got, got - acc);
    st->sum_accurate += acc;
    if (acc > st->worst_accurate)
        st->worst_accurate = acc;
    if (err > tol)
        fail_msg("%s: got %.6f want %.6f (err %.2e > %.2e)\n"
                 "  N=(%d %d %d) P=(%g %g %g) eye=(%g %g %g) parallel=%d N.E=%.5f\n"
                 "  bright=%g B=%g C=%g lights=%d (first at %g %g %g P=%g) R=%g n=%g k=%g Ks=%g",
                 what, got, want, err, tol, n[0], n[1], n[2], dbl(point.x), dbl(point.y),
                 dbl(point.z), dbl(sc->eye.x), dbl(sc->eye.y), dbl(sc->eye.z), sc->parallel, ne,
                 sc->rl.brightness, sc->rl.background, sc->rl.c, sc->rl.count,
                 sc->rl.lights[0].position.x, sc->rl.lights[0].position.y,
                 sc->rl.lights[0].position.z, sc->rl.lights[0].power, sc->rm.reflectivity,
                 sc->rm.refraction, sc->rm.gloss, sc->rm.specular);
    return err;
}

static void report(const char *what, const stats *st)
{
    long all = st->cases + st->graze_cases;
    print_message("%s: %ld cases: worst |err| %.2e (N.E >= %.2f), %ld grazing worst %.2e, "
                  "worst err/tol %.3f, mean |err| %.2e, mean shade %.3f; against stp_shade_unit: "
                  "worst %.2e mean %.2e\n",
                  what, all, st->worst, GRAZING, st->graze_cases, st->worst_graze, st->worst_ratio,
                  st->sum_err / (double)all, st->sum_s / (double)all, st->worst_accurate,
                  st->sum_accurate / (double)all);
}

/* ---- the grid ---- */

static const light_desc light_sets[][4] = {
    {{0, 0, 0, 1}},
    {{5, 5, 0, 1}},
    {{-4, 2, 3, 0.7}},
    {{0, 10, 5, 1}},
    {{0, 0, 1, 1}},
    {{5, 5, 0, 0.5}, {-4, 2, 3, 0.5}},
    {{0, 0, 0, 0.4}, {0, 10, 5, 0.3}, {30, -20, 40, 1}},
    {{5, 5, 0, 0.25}, {-4, 2, 3, 0.25}, {0, -8, 6, 0.25}, {1, 1, 1, 0.25}},
};
static const int light_counts[] = {1, 1, 1, 1, 1, 2, 3, 4};

static void test_grid_against_reference(void **state)
{
    static const double points[][3] = {{0, 0, 5}, {1, -2, 4}, {-3, 1, 8}};
    static const double eyes[][3] = {{0, 0, 0}, {2, 1, -1}};
    static const double pdirs[][3] = {{0, 0, -1}, {1, 1, -2}};
    static const double refls[] = {0.25, 1.0};
    static const double ns[] = {1.5, 10.0, 100.0};
    static const double ks[] = {0.05, 0.5, 10.0};
    static const double kss[] = {0.0, 0.5, 1.0};
    static const double brights[] = {1.0, 2.0};
    static const double backgrounds[] = {0.0, 0.3, 1.0};
    static const double cs[] = {1.0, 0.5};
    stats st;
    int it, ip, ipt, iv, ils, ir, in, ik, iks, ib, ibg, ic;
    (void)state;
    memset(&st, 0, sizeof st);
    for (it = 0; it <= 6; it++)
        for (ip = 0; ip < (it == 0 || it == 6 ? 1 : 8); ip++) {
            double th = it * PI / 6.0, ph = ip * PI / 4.0 + 0.1;
            int16_t n[3];
            ref_vec3 rn = q14_normal(sin(th) * cos(ph), sin(th) * sin(ph), -cos(th), n);
            for (ipt = 0; ipt < 3; ipt++)
                for (iv = 0; iv < 4; iv++) {
                    scene sc;
                    stp_vec3 point = fvec(points[ipt][0], points[ipt][1], points[ipt][2]);
                    sc.parallel = iv >= 2;
                    sc.eye = sc.parallel ? fvec(0, 0, 0) : fvec(eyes[iv][0], eyes[iv][1], eyes[iv][2]);
                    if (sc.parallel) {
                        double x = pdirs[iv - 2][0], y = pdirs[iv - 2][1], z = pdirs[iv - 2][2];
                        double l = sqrt(x * x + y * y + z * z);
                        sc.pdir = fvec(x / l, y / l, z / l);
                    } else {
                        sc.pdir = fvec(0, 0, -1);
                    }
                    for (ils = 0; ils < (int)(sizeof light_counts / sizeof light_counts[0]); ils++)
                        for (ib = 0; ib < 2; ib++)
                            for (ibg = 0; ibg < 3; ibg++)
                                for (ic = 0; ic < 2; ic++) {
                                    make_lighting(&sc.fl, &sc.rl, brights[ib], backgrounds[ibg], cs[ic],
                                                  light_sets[ils], light_counts[ils]);
                                    for (ir = 0; ir < 2; ir++)
                                        for (in = 0; in < 3; in++)
                                            for (ik = 0; ik < 3; ik++)
                                                for (iks = 0; iks < 3; iks++) {
                                                    make_material(&sc.fm, &sc.rm, refls[ir], ns[in], ks[ik],
                                                                  kss[iks]);
                                                    (void)check(&sc, n, rn, point, &st, "grid");
                                                }
                                }
                }
        }
    report("grid", &st);
    assert_true(st.cases > 100000);
    assert_true(st.sum_s / (double)(st.cases + st.graze_cases) > 0.1);
}

/* The light swept around the mirror direction at the sharpest gloss. */
static void test_highlight_sweep(void **state)
{
    static const double ns[] = {1.5, 10.0, 100.0};
    stats st;
    int i, k, in;
    int16_t n[3];
    ref_vec3 rn = q14_normal(0.3, 0.1, -1.0, n);
    (void)state;
    memset(&st, 0, sizeof st);
    for (i = 0; i < 60; i++)
        for (k = 0; k < 60; k++)
            for (in = 0; in < 3; in++) {
                scene sc;
                light_desc l;
                l.x = 3.0 + 10.0 * (i - 30) * 0.004;
                l.y = 1.0 + 10.0 * (k - 30) * 0.004;
                l.z = 0.2;
                l.power = 1.0;
                make_lighting(&sc.fl, &sc.rl, 1.0, 0.0, 1.0, &l, 1);
                make_material(&sc.fm, &sc.rm, 0.2, ns[in], 0.05, 1.0);
                sc.eye = fvec(0, 0, 0);
                sc.pdir = fvec(0, 0, -1);
                sc.parallel = 0;
                (void)check(&sc, n, rn, fvec(0, 0, 5), &st, "highlight sweep");
            }
    report("highlight sweep", &st);
}

/* E.H across its range, both sides of the Fresnel table's first node
 * (E.H = 1/4: below it, and for n < 1, F is computed exactly): the light
 * swept from beside the eye to behind the face's horizon, several indices
 * (n near 1 has the steepest F near grazing) and glosses. */
static void test_fresnel_range_sweep(void **state)
{
    static const double ns[] = {0.7, 1.0, 1.05, 1.5, 10.0, 100.0};
    static const double ks[] = {0.05, 1.0, 10.0};
    stats st;
    int i, in, ik;
    int16_t n[3];
    ref_vec3 rn = q14_normal(0.0, 0.0, -1.0, n);
    (void)state;
    memset(&st, 0, sizeof st);
    for (i = 0; i < 400; i++)
        for (in = 0; in < 6; in++)
            for (ik = 0; ik < 3; ik++) {
                scene sc;
                light_desc l;
                /* the angle between L and E from 0 to 179 degrees, L in the
                 * x-z plane, N.L > 0 while the angle stays below 180 - the
                 * eye's angle (E nearly along N here, so almost everywhere) */
                double a = (double)i * (179.0 / 400.0) * PI / 180.0;
                double ex = 0.3, ez = -1.0, el = sqrt(ex * ex + ez * ez);
                double b = atan2(ex / el, -ez / el) + a; /* E's angle from -z, plus a */
                l.x = 4.0 * sin(b);
                l.y = 0.1;
                l.z = 5.0 - 4.0 * cos(b);
                l.power = 4.0;
                make_lighting(&sc.fl, &sc.rl, 1.0, 0.1, 1.0, &l, 1);
                make_material(&sc.fm, &sc.rm, 0.5, ns[in], ks[ik], 1.0);
                sc.eye = fvec(1.5, 0, 0);
                sc.pdir = fvec(0, 0, -1);
                sc.parallel = 0;
                (void)check(&sc, n, rn, fvec(0, 0, 5), &st, "Fresnel range sweep");
            }
    report("Fresnel range sweep", &st);
    assert_true(st.cases + st.graze_cases > 5000);
}

/* Random faces: normals anywhere, points and lights at many distances,
 * materials and lightings drawn from wide ranges. */
static double uni(uint32_t *seed)
{
    *seed = *seed * 1664525u + 1013904223u;
    return (double)(*seed >> 8) / (double)(1u << 24);
}

/* 1 to 4 lights (drawn) at distances 0.1 .. 100 from point, towards the
 * eye; returns their count */
static int random_lights(uint32_t *seed, stp_vec3 point, light_desc lights[4])
{
    int j, count = 1 + (int)(uni(seed) * 4) % 4;
    for (j = 0; j < count; j++) {
        double ld = pow(10.0, 3 * uni(seed) - 1);
        lights[j].x = dbl(point.x) + (uni(seed) - 0.5) * 2 * ld;
        lights[j].y = dbl(point.y) + (uni(seed) - 0.5) * 2 * ld;
        lights[j].z = dbl(point.z) - uni(seed) * ld;
        lights[j].power = (0.2 + uni(seed)) * (1 + ld) / count;
    }
    return count;
}

static void test_random_against_reference(void **state)
{
    stats st;
    uint32_t seed = 2024u;
    int i;
    (void)state;
    memset(&st, 0, sizeof st);
    for (i = 0; i < 200000; i++) {
        scene sc;
        light_desc lights[4];
        int16_t n[3];
        ref_vec3 rn = q14_normal(uni(&seed) - 0.5, uni(&seed) - 0.5, -uni(&seed), n);
        double dist = pow(10.0, 3 * uni(&seed) - 1); /* 0.1 .. 100 */
        stp_vec3 point = fvec((uni(&seed) - 0.5) * dist, (uni(&seed) - 0.5) * dist, dist);
        int count = random_lights(&seed, point, lights);
        make_lighting(&sc.fl, &sc.rl, 0.5 + uni(&seed), uni(&seed) * 0.5, 0.5 + uni(&seed), lights, count);
        make_material(&sc.fm, &sc.rm, 0.1 + 0.9 * uni(&seed), 1.0 + pow(10.0, 2 * uni(&seed)) - 1,
                      pow(10.0, 2.5 * uni(&seed) - 1.3), uni(&seed));
        sc.parallel = uni(&seed) < 0.25;
        sc.eye = fvec(0, 0, 0);
        sc.pdir = fvec(0, 0, -1);
        (void)check(&sc, n, rn, point, &st, "random");
    }
    report("random", &st);
}

/* stp_shade_fast_face_near (perspective, no highlight, every coordinate
 * within 2^30: direct drawing's faces) gives stp_shade_fast_face's shade
 * exactly: random faces as above with Ks = 0, some lit from a light on
 * the face's point, some behind it. */
static void test_near_equals_face(void **state)
{
    uint32_t seed = 77u;
    int i, lit = 0;
    scene sc;
    stp_shade_fast fs;
    (void)state;
    for (i = 0; i < 100000; i++) {
        int16_t n[3];
        double dist = pow(10.0, 3 * uni(&seed) - 1); /* 0.1 .. 100 */
        stp_vec3 point = fvec((uni(&seed) - 0.5) * dist, (uni(&seed) - 0.5) * dist, dist);
        stp_fix want, got;
        (void)q14_normal(uni(&seed) - 0.5, uni(&seed) - 0.5, uni(&seed) - 0.8, n);
        if (i % 8 == 0 || i % 50 == 0) { /* a new lighting every 8 faces */
            light_desc lights[4];
            int count = random_lights(&seed, point, lights);
            if (i % 50 == 0) { /* the light on the face */
                lights[0].x = dbl(point.x);
                lights[0].y = dbl(point.y);
                lights[0].z = dbl(point.z);
            }
            make_lighting(&sc.fl, &sc.rl, 0.5 + uni(&seed) * (i % 7 == 0 ? 40 : 1), uni(&seed) * 0.5,
                          0.5 + uni(&seed), lights, count);
            make_material(&sc.fm, &sc.rm, (uni(&seed) - 0.2) * 1.2, 1.0 + pow(10.0, 2 * uni(&seed)) - 1,
                          pow(10.0, 2.5 * uni(&seed) - 1.3), 0);
            stp_shade_fast_prepare(&fs, &sc.fl, &sc.fm, fvec(0, 0, 0), 0, fvec(0, 0, -1));
        }
        want = stp_shade_fast_face(&fs, n, point);
        got = stp_shade_fast_face_near(&fs, n, point);
        if (got != want)
            fail_msg("face %d: near %ld, face %ld", i, (long)got, (long)want);
        lit += want != fs.ambient_shade;
    }
    assert_true(lit > 20000);
}

/* ---- the stiff cases ---- */

typedef struct stiff {
    const char *name;
    double nx, ny, nz;      /* normal */
    double px, py, pz;      /* point; eye at the origin */
    light_desc light[4];
    int count;
    double bright, background, c;
    double refl, n, k, ks;
    int parallel;
    double tol;             /* 0: TOL with the grazing rule */
} stiff;

static void test_stiff_cases(void **state)
{
    static const stiff cases[] = {
        {"baseline", 0, 0, -1, 0, 0, 4, {{-1.7, 1.7, 2.3, 2}}, 1, 1, 0.2, 1, 0.8, 10, 0.2, 0.3, 0, 0},
        {"grazing_eye_NE_1e-2", 0.99995, 0, -0.01, 0, 0, 4, {{2.1, 0, 3.97, 2}}, 1, 1, 0.2, 1, 0.8, 10, 0.2, 0.3, 0, 0},
        {"grazing_eye_NE_1e-3", 0.9999995, 0, -0.001, 0, 0, 4, {{2.1, 0, 3.99, 2}}, 1, 1, 0.2, 1, 0.8, 10, 0.2, 0.3, 0, 0},
        {"grazing_light", 0, 0, -1, 0, 0, 4, {{3, 0, 3.97, 2}}, 1, 1, 0.2, 1, 0.8, 10, 0.2, 0.3, 0, 0},
        {"light_on_surface", 0, 0.6, -0.8, 1, 2, 3, {{1, 2, 3, 1}}, 1, 1, 0, 1, 0.5, 10, 0.05, 1, 0, 0},
        {"light_near_surface", 0, 0, -1, 0, 0, 4, {{0.001, 0, 3.999, 0.01}}, 1, 1, 0, 1, 0.5, 10, 0.5, 1, 0, 0},
        {"L_is_minus_E", 0, 0, -1, 0, 0, 4, {{0, 0, 8, 1}}, 1, 1, 0.3, 1, 0.5, 10, 0.5, 1, 0, 0},
        {"light_behind_face", 0, 0, -1, 0, 0, 4, {{1, 1, 6, 1}}, 1, 1, 0.3, 1, 0.5, 10, 0.5, 1, 0, 0},
        {"far_light", 0.2, 0.1, -1, 0, 0, 4, {{-3000, 5000, -4000, 4000}}, 1, 1, 0.1, 1, 0.7, 10, 0.3, 0.5, 0, 0},
        {"very_far_light", 0.2, 0.1, -1, 0, 0, 4, {{-10000, 16000, -16000, 30000}}, 1, 1, 0.1, 1, 0.7, 10, 0.3, 0.5, 0, 0},
        {"near_light", 0.2, 0.1, -1, 0, 0, 4, {{-0.01, 0.02, 3.98, 0.02}}, 1, 1, 0.1, 1, 0.7, 10, 0.3, 0.5, 0, 0},
        {"gloss_tiny", 0.3, 0.1, -1, 0, 0, 5, {{3, 1, 0.2, 1}}, 1, 1, 0, 1, 0.2, 10, 0.001, 1, 0, 0},
        {"gloss_huge", 0.3, 0.1, -1, 0, 0, 5, {{3, 1, 0.2, 1}}, 1, 1, 0, 1, 0.2, 10, 20000, 0.2, 0, 0},
        {"refraction_1", 0.3, 0.1, -1, 0, 0, 5, {{3, 1, 0.2, 2}}, 1, 1, 0, 1, 0.2, 1, 0.3, 1, 0, 0},
        {"refraction_0.5", 0.3, 0.1, -1, 0, 0, 5, {{3, 1, 0.2, 2}}, 1, 1, 0, 1, 0.2, 0.5, 0.3, 1, 0, 0},
        {"refraction_large", 0.3, 0.1, -1, 0, 0, 5, {{3, 1, 0.2, 2}}, 1, 1, 0, 1, 0.2, 30000, 0.3, 1, 0, 0},
        {"brightness_large", 0.2, 0.1, -1, 0, 0, 5, {{-60, 80, -100, 0.0005}}, 1, 1000, 0, 1, 0.6, 10, 0.3, 0.5, 0, 0},
        {"brightness_huge_capped", 0.2, 0.1, -1, 0, 0, 5, {{-6, 8, -10, 1}}, 1, 20000, 0.5, 1, 0.6, 10, 0.3, 0.5, 0, 0},
        {"four_lights", 0.2, -0.3, -1, 1, 0, 6, {{5, 5, 0, 0.25}, {-4, 2, 3, 0.25}, {0, -8, 6, 0.25}, {1, 1, 1, 0.25}}, 4, 1, 0.1, 1, 0.9, 3, 0.2, 0.7, 0, 0},
        {"parallel_far_point", 0.3, 0.4, -1, 2000, -1000, 3000, {{1990, -990, 2990, 3}}, 1, 1, 0.1, 1, 0.8, 10, 0.2, 0.5, 1, 0},
        {"huge_coordinates", 0.1, 0.2, -1, 20000, 20000, 30000, {{-30000, -30000, -30000, 30000}}, 1, 1, 0.1, 1, 0.8, 10, 0.2, 0.5, 0, 0},
        {"reflectivity_0", 0.3, 0.1, -1, 0, 0, 5, {{3, 1, 0.2, 1}}, 1, 1, 0.2, 1, 0, 10, 0.3, 1, 0, 0},
        {"reflectivity_0_no_highlight", 0.3, 0.1, -1, 0, 0, 5, {{3, 1, 0.2, 1}}, 1, 1, 0.2, 1, 0, 10, 0.3, 0, 0, 0},
        {"C_tiny", 0, 0, -1, 0, 0, 4, {{0, 0, 3.9, 0.05}}, 1, 1, 0, 0.0001, 0.8, 10, 0.2, 0.3, 0, 0},
        /* gain BRIGHT P |R| / (C + U) of 20 and 200 on a light nearly in
         * the face's plane (cosine 0.033 and 0.0033): the cosine's error
         * times the gain */
        {"grazing_light_gain_20", 0, 0, -1, 0, 0, 4, {{3, 0, 3.9, 100}}, 1, 1, 0, 1, 0.8, 10, 0.2, 0, 0, 0},
        {"grazing_light_gain_200", 0, 0, -1, 0, 0, 4, {{3, 0, 3.99, 1000}}, 1, 1, 0, 1, 0.8, 10, 0.2, 0, 0, 0},
    };
    stats st;
    size_t i;
    const double range = (double)(1L << (31 - F)); /* stp_fix's range */
    (void)state;
    memset(&st, 0, sizeof st);
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const stiff *c = &cases[i];
        scene sc;
        int16_t n[3];
        ref_vec3 rn = q14_normal(c->nx, c->ny, c->nz, n);
        double err, big = fmax(fmax(fmax(fabs(c->px), fabs(c->py)), fmax(fabs(c->pz), c->bright)),
                               fmax(c->k, c->n));
        int j;
        for (j = 0; j < c->count; j++)
            big = fmax(big, fmax(fmax(fabs(c->light[j].x), fabs(c->light[j].y)),
                                 fmax(fabs(c->light[j].z), c->light[j].power)));
        if (big >= range) {
            print_message("  %-24s beyond this stp_fix's range: skipped\n", c->name);
            continue;
        }
        make_lighting(&sc.fl, &sc.rl, c->bright, c->background, c->c, c->light, c->count);
        make_material(&sc.fm, &sc.rm, c->refl, c->n, c->k, c->ks);
        sc.eye = fvec(0, 0, 0);
        sc.pdir = fvec(0, 0, -1);
        sc.parallel = c->parallel;
        err = check(&sc, n, rn, fvec(c->px, c->py, c->pz), &st, c->name);
        print_message("  %-24s err %.2e\n", c->name, err);
    }
    report("stiff", &st);
}

/* Faces seen nearly edge-on, N.E from 0.021 to 0.079 in steps of 0.002:
 * across the face shader's hand-over to its exact route (N.E below 1/20
 * with a light nearly opposite the eye, here the mirror light; the other
 * two stay on the fast route: shade_fast.c GRAZE_EXACT), which the random
 * faces and the grid reach only by chance.
 * The eye at the origin, the face at (0, 0, 4), N = (sqrt(1 - c^2), 0, -c);
 * one light in the mirror direction of the eye (the strongest highlight),
 * one along the normal, one to the side; three glosses. */
static void test_eye_cosine_band(void **state)
{
    static const double glosses[] = {0.05, 0.2, 0.5};
    stats st;
    int step, which, g;
    (void)state;
    memset(&st, 0, sizeof st);
    for (step = 0; step < 30; step++) {
        double c = 0.021 + 0.002 * step, sn = sqrt(1 - c * c);
        for (which = 0; which < 3; which++) {
            /* E = (0, 0, -1); mirror direction 2 (N.E) N - E */
            double dx = which == 0 ? 2 * c * sn : which == 1 ? sn : 0.6;
            double dy = which == 2 ? 0.7 : 0;
            double dz = which == 0 ? -2 * c * c + 1 : which == 1 ? -c : -0.4;
            light_desc l;
            l.x = 3 * dx;
            l.y = 3 * dy;
            l.z = 4 + 3 * dz;
            l.power = 2;
            for (g = 0; g < 3; g++) {
                scene sc;
                int16_t n[3];
                ref_vec3 rn = q14_normal(sn, 0, -c, n);
                char what[64];
                make_lighting(&sc.fl, &sc.rl, 1, 0.2, 1, &l, 1);
                make_material(&sc.fm, &sc.rm, 0.8, 10, glosses[g], 0.5);
                sc.eye = fvec(0, 0, 0);
                sc.pdir = fvec(0, 0, -1);
                sc.parallel = 0;
                snprintf(what, sizeof what, "N.E %.3f light %d gloss %.2f", c, which, glosses[g]);
                (void)check(&sc, n, rn, fvec(0, 0, 4), &st, what);
            }
        }
    }
    report("eye cosine band", &st);
}

/* N.E <= 0: exactly the ambient share, as stp_shade_unit gives it. */
static void test_back_face_is_exactly_ambient(void **state)
{
    static const double brights[] = {0, 0.5, 1, 3, 1000};
    static const double backgrounds[] = {0, 0.3, 1, 2};
    static const double refls[] = {0, 0.25, 0.8, 1};
    light_desc l = {0, 0, 10, 1};
    size_t ib, ig, ir;
    int16_t n[3];
    (void)state;
    (void)q14_normal(0.1, 0.2, 1, n); /* faces away from the eye at the origin */
    for (ib = 0; ib < 5; ib++)
        for (ig = 0; ig < 4; ig++)
            for (ir = 0; ir < 4; ir++) {
                scene sc;
                stp_shade_fast s;
                stp_unit3 un, ue = {0, 0, -STP_UNIT_ONE};
                stp_fix want;
                make_lighting(&sc.fl, &sc.rl, brights[ib], backgrounds[ig], 1, &l, 1);
                make_material(&sc.fm, &sc.rm, refls[ir], 10, 0.5, 1);
                (void)stp_unit_from64(n[0], n[1], n[2], &un);
                want = stp_shade_unit(&sc.fl, &sc.fm, un, fvec(0, 0, 5), ue, 0);
                stp_shade_fast_prepare(&s, &sc.fl, &sc.fm, fvec(0, 0, 0), 0, fvec(0, 0, -1));
                assert_int_equal(stp_shade_fast_face(&s, n, fvec(0, 0, 5)), want);
                stp_shade_fast_prepare(&s, &sc.fl, &sc.fm, fvec(0, 0, 0), 1, fvec(0, 0, -1));
                assert_int_equal(stp_shade_fast_face(&s, n, fvec(0, 0, 5)), want);
                /* no light at all, and a face edge-on */
                sc.fl.count = 0;
                stp_shade_fast_prepare(&s, &sc.fl, &sc.fm, fvec(0, 0, 0), 0, fvec(0, 0, -1));
                assert_int_equal(stp_shade_fast_face(&s, n, fvec(0, 0, 5)), want);
            }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_back_face_is_exactly_ambient),
        cmocka_unit_test(test_near_equals_face),
        cmocka_unit_test(test_stiff_cases),
        cmocka_unit_test(test_eye_cosine_band),
        cmocka_unit_test(test_highlight_sweep),
        cmocka_unit_test(test_fresnel_range_sweep),
        cmocka_unit_test(test_random_against_reference),
        cmocka_unit_test(test_grid_against_reference),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
