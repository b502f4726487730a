/* SPDX-License-Identifier: MIT */
/*
 * Shading, INTENSITY, style tables and gamma (include/stipple/shade.h)
 * against the double-precision reference tests/reference/shade_ref.c, which
 * is written from SPEC.md section 2 and shares no code with src/shade.c.
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
#include "stipple/shade.h"

#define F STP_FIX_FRAC_BITS
#define ONE STP_FIX_ONE
#define LSB (1.0 / (double)ONE)
#define PI 3.14159265358979323846

/*
 * Tolerance on the shade s (absolute, s in [0, 1]).
 *
 * The target is an error well below one INTENSITY step: at 16 levels a step
 * is 1/15 = 0.0667, and 2e-3 is 1/33 of it, so the fixed-point shade selects
 * the reference's style except within 2e-3 of a step boundary.  What feeds
 * the error (F = 16, LSB = 1.5e-5): the unit vectors E, L, H are within
 * ~2 LSB per component, so each cosine is within ~4 LSB; D's slope
 * dD/d(N.H) = 2D/(k + 1 - N.H) <= 2/k reaches 40 at k = 0.05, turning
 * 4 LSB into 2.4e-3 of D at the highlight's flank; the share D.G.F/(N.E)
 * then divides by N.E.  Measured over the grid below (printed when the test
 * runs: 2.5 million cases) the worst error is 3.1e-4 for N.E >=
 * SHADE_GRAZING, and 1.8e-4 in the fine highlight sweep at k = 0.05; so
 * SHADE_TOL = 2e-3 holds with a margin of 6 while staying 1/33 of a
 * 16-level step (and 1/2 of a 256-level step).
 *
 * At grazing view (N.E < SHADE_GRAZING = 0.1) the specular share is divided
 * by a small N.E, and so is its error (1.4e-2 measured at N.E = 0.002), so
 * there the bound scales: SHADE_TOL * SHADE_GRAZING / N.E.  The worst
 * err/tolerance over the whole grid is printed too (0.15 measured).
 */
#if STP_FIX_FRAC_BITS >= 16
#define SHADE_TOL 2e-3
#else
/* a coarser stp_fix: the same error budget counted in LSB */
#define SHADE_TOL (2e-3 * (double)(1 << (16 - STP_FIX_FRAC_BITS)))
#endif
#define SHADE_GRAZING 0.1

/* Tolerances of the specular factors, each in [0, 1] and computed from
 * exact fixed-point cosines (the same inputs go to the reference):
 * D: two roundings (the quotient truncated, its square rounded) and the
 *    quotient's 1 LSB times 2q <= 2: 3 LSB.
 * G: one truncated quotient: < 1 LSB (1.5 allowed for the reference's
 *    own rounding).
 * F: g is a floor root, the ratios r and t are truncated and squared;
 *    t's error is amplified by 1/(c(g-c)+1) <= 1: 8 LSB is generous
 *    (measured worst: D 2.25, G 1.00, F 3.6 LSB). */
#define D_TOL (3.0 * LSB)
#define G_TOL (1.5 * LSB)
#define F_TOL (8.0 * LSB)

/* ---- conversions ---- */

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
    ref_vec3 r;
    r.x = dbl(v.x);
    r.y = dbl(v.y);
    r.z = dbl(v.z);
    return r;
}

/* A unit vector in both forms: the fixed one from stp_vec3_unity, the
 * reference one its exact double value (both see the same input). */
static stp_vec3 unit_fix(double x, double y, double z)
{
    stp_vec3 u;
    (void)stp_vec3_unity(fvec(x, y, z), &u);
    return u;
}

/* Build the two lightings from one description. */
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
    fm->reflectivity = fx(refl);
    fm->refraction = fx(n);
    fm->gloss = fx(k);
    fm->specular = fx(ks);
    rm->reflectivity = dbl(fm->reflectivity);
    rm->refraction = dbl(fm->refraction);
    rm->gloss = dbl(fm->gloss);
    rm->specular = dbl(fm->specular);
}

/* ---- defaults ---- */

static void test_seed_defaults(void **state)
{
    stp_lighting l;
    stp_material m;
    (void)state;
    memset(&l, 0x5A, sizeof l);
    memset(&m, 0x5A, sizeof m);
    stp_lighting_default(&l);
    stp_material_default(&m);
    /* INITIALIZE-10: light at (0,0,1), brightness 1, background 0 */
    assert_int_equal(l.count, 1);
    assert_int_equal(l.lights[0].position.x, 0);
    assert_int_equal(l.lights[0].position.y, 0);
    assert_int_equal(l.lights[0].position.z, ONE);
    assert_int_equal(l.lights[0].power, ONE); /* P = 1 - B */
    assert_int_equal(l.brightness, ONE);
    assert_int_equal(l.background, 0);
    assert_int_equal(l.attenuation_c, ONE);
    /* reflectivity 1, refraction 10, gloss 10; the seed's specular term */
    assert_int_equal(m.reflectivity, ONE);
    assert_int_equal(m.refraction, 10 * ONE);
    assert_int_equal(m.gloss, 10 * ONE);
    assert_int_equal(m.specular, ONE);
}

/* ---- D, G, F individually ---- */

static void test_specular_terms_against_reference(void **state)
{
    static const double ns[] = {1.5, 10.0, 100.0, 1.0, 0.8};
    static const double ks[] = {0.05, 0.5, 10.0};
    double worst_d = 0, worst_g = 0, worst_f = 0;
    int ih, ie, il, ic, in, ik, count = 0;
    (void)state;
    for (ih = 1; ih <= 12; ih++)
        for (ie = 1; ie <= 6; ie++)
            for (il = 1; il <= 6; il++)
                for (ic = 1; ic <= 8; ic++)
                    for (in = 0; in < 5; in++)
                        for (ik = 0; ik < 3; ik++) {
                            /* cosines over (0, 1], denser near 1 for N.H */
                            stp_fix nh = fx(1.0 - (ih - 1) * (ih - 1) / 130.0);
                            stp_fix ne = fx(ie / 6.0 - 0.03), nl = fx(il / 6.0 - 0.07);
                            stp_fix eh = fx(ic / 8.0);
                            stp_fix n = fx(ns[in]), k = fx(ks[ik]);
                            stp_specular_terms t = stp_specular(nh, ne, nl, eh, n, k);
                            double d = ref_facet_d(dbl(nh), dbl(k));
                            double g = ref_blocking_g(dbl(nh), dbl(ne), dbl(nl), dbl(eh));
                            double f = ref_fresnel_f(dbl(eh), dbl(n));
                            double ed = fabs(dbl(t.d) - d), eg = fabs(dbl(t.g) - g), ef = fabs(dbl(t.f) - f);
                            worst_d = ed > worst_d ? ed : worst_d;
                            worst_g = eg > worst_g ? eg : worst_g;
                            worst_f = ef > worst_f ? ef : worst_f;
                            if (ed > D_TOL || eg > G_TOL || ef > F_TOL)
                                fail_msg("specular(N.H=%.5f N.E=%.5f N.L=%.5f E.H=%.5f n=%g k=%g): "
                                         "D %.6f/%.6f G %.6f/%.6f F %.6f/%.6f (got/want)",
                                         dbl(nh), dbl(ne), dbl(nl), dbl(eh), ns[in], ks[ik], dbl(t.d), d,
                                         dbl(t.g), g, dbl(t.f), f);
                            count++;
                        }
    print_message("specular: %d cases, worst D %.2f LSB, G %.2f LSB, F %.2f LSB\n", count,
                  worst_d * ONE, worst_g * ONE, worst_f * ONE);
}

static void test_specular_terms_known_values(void **state)
{
    stp_specular_terms t;
    (void)state;
    /* at the highlight's centre N.H = 1: D = 1 for any k */
    t = stp_specular(ONE, ONE, ONE, ONE, 10 * ONE, ONE / 20);
    assert_int_equal(t.d, ONE);
    /* head-on: G = 2 min(1,1) 1 / 1 capped at 1 */
    assert_int_equal(t.g, ONE);
    /* head-on Fresnel, c = 1: g = n, F = ((n-1)/(n+1))^2 (t = 1):
     * n = 10 gives (9/11)^2 = 0.6694 */
    assert_true(fabs(dbl(t.f) - (9.0 / 11.0) * (9.0 / 11.0)) <= F_TOL);
    /* n = 1: no reflection */
    t = stp_specular(ONE, ONE, ONE, ONE, ONE, ONE);
    assert_true(dbl(t.f) <= F_TOL);
    /* D = (k/(k + 1 - N.H))^2 with k = 1, N.H = 0: 1/4 */
    t = stp_specular(1, ONE, ONE, ONE, 10 * ONE, ONE);
    assert_true(fabs(dbl(t.d) - 0.25) <= D_TOL);
    /* G below the cap: 2 * 0.25 * 0.5 / 1 = 0.25 */
    t = stp_specular(ONE / 2, ONE / 4, ONE, ONE, 10 * ONE, ONE);
    assert_true(fabs(dbl(t.g) - 0.25) <= G_TOL);
    /* total reflection: n < 1 and g imaginary gives F = 1 */
    t = stp_specular(ONE, ONE, ONE, ONE / 10, ONE / 2, ONE);
    assert_int_equal(t.f, ONE);
}

static void test_specular_terms_zero_for_nonpositive_cosines(void **state)
{
    static const stp_fix bad[] = {0, -1, -ONE / 2, -ONE};
    int i, which;
    (void)state;
    for (which = 0; which < 4; which++)
        for (i = 0; i < 4; i++) {
            stp_fix c[4] = {ONE * 9 / 10, ONE * 8 / 10, ONE * 7 / 10, ONE * 6 / 10};
            stp_specular_terms t;
            c[which] = bad[i];
            t = stp_specular(c[0], c[1], c[2], c[3], 10 * ONE, ONE);
            assert_int_equal(t.d, 0);
            assert_int_equal(t.g, 0);
            assert_int_equal(t.f, 0);
        }
}

/* ---- the full shade over a grid ---- */

typedef struct shade_stats {
    long cases, graze_cases;
    double worst, worst_graze, worst_ratio; /* worst_ratio: err / tolerance */
    double sum_s;                           /* to check the grid is not all capped or dark */
} shade_stats;

/* Compare one configuration; n_dot_e is the reference's, for the grazing
 * rule. */
static void check_shade(const stp_lighting *fl, const ref_lighting *rl, const stp_material *fm,
                        const ref_material *rm, stp_vec3 normal, stp_vec3 point, stp_vec3 eye,
                        int parallel, stp_vec3 pdir, shade_stats *st)
{
    double want = ref_shade_point(rl, rm, rvec(normal), rvec(point), rvec(eye), parallel, rvec(pdir));
    stp_fix got_fix = stp_shade_point(fl, fm, normal, point, eye, parallel, pdir);
    double got = dbl(got_fix), err = fabs(got - want), tol = SHADE_TOL, n_dot_e;
    ref_vec3 e;
    if (parallel) {
        e = rvec(pdir);
    } else {
        ref_vec3 d;
        d.x = dbl(eye.x) - dbl(point.x);
        d.y = dbl(eye.y) - dbl(point.y);
        d.z = dbl(eye.z) - dbl(point.z);
        (void)ref_unit(d, &e);
    }
    n_dot_e = ref_dot(rvec(normal), e);
    assert_true(got_fix >= 0 && got_fix <= ONE);
    if (n_dot_e > 0 && n_dot_e < SHADE_GRAZING) {
        tol = SHADE_TOL * SHADE_GRAZING / n_dot_e;
        st->graze_cases++;
        if (err > st->worst_graze)
            st->worst_graze = err;
    } else {
        st->cases++;
        if (err > st->worst)
            st->worst = err;
    }
    if (err / tol > st->worst_ratio)
        st->worst_ratio = err / tol;
    st->sum_s += want;
    if (err > tol)
        fail_msg("shade: got %.6f want %.6f (err %.2e > %.2e)\n"
                 "  N=(%.5f %.5f %.5f) P=(%g %g %g) eye=(%g %g %g) parallel=%d dir=(%.4f %.4f %.4f) N.E=%.4f\n"
                 "  bright=%g B=%g C=%g lights=%d (first at %g %g %g P=%g)\n"
                 "  R=%g n=%g k=%g Ks=%g",
                 got, want, err, tol, dbl(normal.x), dbl(normal.y), dbl(normal.z), dbl(point.x),
                 dbl(point.y), dbl(point.z), dbl(eye.x), dbl(eye.y), dbl(eye.z), parallel, dbl(pdir.x),
                 dbl(pdir.y), dbl(pdir.z), n_dot_e, rl->brightness, rl->background, rl->c, rl->count,
                 rl->lights[0].position.x, rl->lights[0].position.y, rl->lights[0].position.z,
                 rl->lights[0].power, rm->reflectivity, rm->refraction, rm->gloss, rm->specular);
}

/* Light sets: positions in the frame of the points (the eye near the
 * origin, the surface ahead at z > 0). */
static const light_desc light_sets[][4] = {
    {{0, 0, 0, 1}},                                               /* at the eye */
    {{5, 5, 0, 1}},                                               /* above right */
    {{-4, 2, 3, 0.7}},                                            /* near, left */
    {{0, 10, 5, 1}},                                              /* overhead */
    {{0, 0, 1, 1}},                                               /* the seed's default */
    {{5, 5, 0, 0.5}, {-4, 2, 3, 0.5}},                            /* two */
    {{0, 0, 0, 0.4}, {0, 10, 5, 0.3}, {30, -20, 40, 1}},          /* three, one far */
    {{5, 5, 0, 0.25}, {-4, 2, 3, 0.25}, {0, -8, 6, 0.25}, {1, 1, 1, 0.25}}, /* four */
};
static const int light_counts[] = {1, 1, 1, 1, 1, 2, 3, 4};

static void test_shade_grid_against_reference(void **state)
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
    shade_stats st = {0, 0, 0.0, 0.0, 0.0, 0.0};
    int it, ip, ipt, iv, ils, ir, in, ik, iks, ib, ibg, ic;
    (void)state;
    for (it = 0; it <= 6; it++)
        for (ip = 0; ip < (it == 0 || it == 6 ? 1 : 8); ip++) {
            /* normals over the sphere; many face away from the eye */
            double th = it * PI / 6.0, ph = ip * PI / 4.0 + 0.1;
            stp_vec3 normal = unit_fix(sin(th) * cos(ph), sin(th) * sin(ph), -cos(th));
            for (ipt = 0; ipt < 3; ipt++)
                for (iv = 0; iv < 4; iv++) {
                    stp_vec3 point = fvec(points[ipt][0], points[ipt][1], points[ipt][2]);
                    int parallel = iv >= 2;
                    stp_vec3 eye = parallel ? fvec(0, 0, 0) : fvec(eyes[iv][0], eyes[iv][1], eyes[iv][2]);
                    stp_vec3 pdir = parallel ? unit_fix(pdirs[iv - 2][0], pdirs[iv - 2][1], pdirs[iv - 2][2])
                                             : unit_fix(0, 0, -1);
                    for (ils = 0; ils < (int)(sizeof light_counts / sizeof light_counts[0]); ils++)
                        for (ib = 0; ib < 2; ib++)
                            for (ibg = 0; ibg < 3; ibg++)
                                for (ic = 0; ic < 2; ic++) {
                                    stp_lighting fl;
                                    ref_lighting rl;
                                    make_lighting(&fl, &rl, brights[ib], backgrounds[ibg], cs[ic],
                                                  light_sets[ils], light_counts[ils]);
                                    for (ir = 0; ir < 2; ir++)
                                        for (in = 0; in < 3; in++)
                                            for (ik = 0; ik < 3; ik++)
                                                for (iks = 0; iks < 3; iks++) {
                                                    stp_material fm;
                                                    ref_material rm;
                                                    make_material(&fm, &rm, refls[ir], ns[in], ks[ik], kss[iks]);
                                                    check_shade(&fl, &rl, &fm, &rm, normal, point, eye,
                                                                parallel, pdir, &st);
                                                }
                                }
                }
        }
    print_message("shade: %ld cases, worst |err| %.2e (tolerance %.1e); %ld grazing (N.E < %.2f), "
                  "worst %.2e; worst err/tolerance %.3f; mean shade %.3f\n",
                  st.cases, st.worst, SHADE_TOL, st.graze_cases, SHADE_GRAZING, st.worst_graze,
                  st.worst_ratio, st.sum_s / (double)(st.cases + st.graze_cases));
    assert_true(st.cases > 100000);
}

static void test_shade_highlight_sweep(void **state)
{
    /* A fine sweep of the light around the mirror direction, where D is
     * steepest (k = 0.05) and the specular share dominates: the grid above
     * samples it only coarsely. */
    shade_stats st = {0, 0, 0.0, 0.0, 0.0, 0.0};
    int i, j, in;
    static const double ns[] = {1.5, 10.0, 100.0};
    (void)state;
    for (i = 0; i < 60; i++)
        for (j = 0; j < 60; j++)
            for (in = 0; in < 3; in++) {
                stp_lighting fl;
                ref_lighting rl;
                stp_material fm;
                ref_material rm;
                light_desc l;
                double a = (i - 30) * 0.004, b = (j - 30) * 0.004;
                stp_vec3 normal = unit_fix(0.3, 0.1, -1.0);
                /* point at (0,0,5), eye at the origin: light near the
                 * mirror image of the eye */
                l.x = 3.0 + 10.0 * a;
                l.y = 1.0 + 10.0 * b;
                l.z = 0.2;
                l.power = 1.0;
                make_lighting(&fl, &rl, 1.0, 0.0, 1.0, &l, 1);
                make_material(&fm, &rm, 0.2, ns[in], 0.05, 1.0);
                check_shade(&fl, &rl, &fm, &rm, normal, fvec(0, 0, 5), fvec(0, 0, 0), 0,
                            unit_fix(0, 0, -1), &st);
            }
    print_message("highlight sweep: %ld cases, worst |err| %.2e, mean shade %.3f\n", st.cases + st.graze_cases,
                  st.worst > st.worst_graze ? st.worst : st.worst_graze,
                  st.sum_s / (double)(st.cases + st.graze_cases));
}

static void test_shade_light_at_point_is_head_on(void **state)
{
    /* light exactly at the point: L = N, U = 0, so the diffuse term is
     * P R / C; with no specular, R = 0.5, C = 1, P = 1: s = 0.5 */
    stp_lighting fl;
    ref_lighting rl;
    stp_material fm;
    ref_material rm;
    light_desc l = {1, 2, 3, 1};
    stp_vec3 n = unit_fix(0, 0.6, -0.8);
    stp_fix s;
    (void)state;
    make_lighting(&fl, &rl, 1.0, 0.0, 1.0, &l, 1);
    make_material(&fm, &rm, 0.5, 10, 10, 0);
    s = stp_shade_point(&fl, &fm, n, fvec(1, 2, 3), fvec(0, 0, 0), 0, unit_fix(0, 0, -1));
    assert_true(fabs(dbl(s) - 0.5) <= SHADE_TOL);
    assert_true(fabs(dbl(s) - ref_shade_point(&rl, &rm, rvec(n), rvec(fvec(1, 2, 3)), rvec(fvec(0, 0, 0)), 0,
                                              rvec(unit_fix(0, 0, -1)))) <= SHADE_TOL);
    /* with the highlight on, still finite and within [0, 1] */
    make_material(&fm, &rm, 0.5, 10, 0.05, 1);
    s = stp_shade_point(&fl, &fm, n, fvec(1, 2, 3), fvec(0, 0, 0), 0, unit_fix(0, 0, -1));
    assert_true(s >= 0 && s <= ONE);
    assert_true(fabs(dbl(s) - ref_shade_point(&rl, &rm, rvec(n), rvec(fvec(1, 2, 3)), rvec(fvec(0, 0, 0)), 0,
                                              rvec(unit_fix(0, 0, -1)))) <= SHADE_TOL);
}

static void test_shade_back_face_is_ambient_only(void **state)
{
    /* shade.h: for N.E <= 0 the shade is the ambient share only, even with
     * a light in front of the surface */
    stp_lighting fl;
    ref_lighting rl;
    stp_material fm;
    ref_material rm;
    light_desc l = {0, 0, 10, 1}; /* behind the surface from the eye: lights its back */
    stp_vec3 n = unit_fix(0, 0, 1); /* facing away from the eye at the origin */
    stp_fix s;
    (void)state;
    make_lighting(&fl, &rl, 1.0, 0.4, 1.0, &l, 1);
    make_material(&fm, &rm, 0.5, 10, 10, 1);
    s = stp_shade_point(&fl, &fm, n, fvec(0, 0, 5), fvec(0, 0, 0), 0, unit_fix(0, 0, -1));
    assert_true(fabs(dbl(s) - 0.4 * 0.5) <= SHADE_TOL);
    /* parallel: the direction towards the viewer is (0,0,-1) */
    s = stp_shade_point(&fl, &fm, n, fvec(0, 0, 5), fvec(0, 0, 0), 1, unit_fix(0, 0, -1));
    assert_true(fabs(dbl(s) - 0.4 * 0.5) <= SHADE_TOL);
}

static void test_shade_no_lights_and_caps(void **state)
{
    stp_lighting fl;
    ref_lighting rl;
    stp_material fm;
    ref_material rm;
    light_desc l = {0, 0, 0, 1};
    stp_vec3 n = unit_fix(0, 0, -1);
    (void)state;
    /* no lights: BRIGHT B R */
    make_lighting(&fl, &rl, 1.5, 0.5, 1.0, &l, 0);
    make_material(&fm, &rm, 0.8, 10, 10, 1);
    assert_true(fabs(dbl(stp_shade_point(&fl, &fm, n, fvec(0, 0, 5), fvec(0, 0, 0), 0, n)) - 0.6) <= SHADE_TOL);
    /* large brightness caps at exactly 1 */
    make_lighting(&fl, &rl, 1000.0, 1.0, 1.0, &l, 1);
    assert_int_equal(stp_shade_point(&fl, &fm, n, fvec(0, 0, 5), fvec(0, 0, 0), 0, n), ONE);
    /* background above 1 is clamped to 1: B R = 0.8 */
    make_lighting(&fl, &rl, 1.0, 3.0, 1.0, &l, 0);
    assert_true(fabs(dbl(stp_shade_point(&fl, &fm, n, fvec(0, 0, 5), fvec(0, 0, 0), 0, n)) - 0.8) <= SHADE_TOL);
    /* brightness 0: black */
    make_lighting(&fl, &rl, 0.0, 1.0, 1.0, &l, 1);
    assert_int_equal(stp_shade_point(&fl, &fm, n, fvec(0, 0, 5), fvec(0, 0, 0), 0, n), 0);
    /* the specular share explodes at grazing view: saturates, caps at 1,
     * never wraps negative */
    {
        stp_vec3 graze = unit_fix(0, 1, -0.00002);
        stp_fix s;
        make_lighting(&fl, &rl, 1.0, 0.0, 1.0, &l, 1);
        fl.lights[0].position = fvec(0, 3, 4.9);
        make_material(&fm, &rm, 0.1, 100, 0.05, 1);
        s = stp_shade_point(&fl, &fm, graze, fvec(0, 0, 5), fvec(0, 0, 0), 0, n);
        assert_true(s >= 0 && s <= ONE);
    }
}


/* Issue 13 item 11: at large BRIGHT (the seed's advice for distant lights)
 * the shade keeps its precision.  Each light's term is tiny there (far
 * lights, small powers) and BRIGHT multiplies it back to [0, 1]: a term
 * rounded to 2^-16 before BRIGHT would carry an error of BRIGHT 2^-16 per
 * light (0.15 at 10^4).  Random well-conditioned inputs (N.E >= 0.3), one
 * to four lights 20..200 units away, powers chosen so the unclamped shade
 * is about 0.1..0.9, at BRIGHT 1000, 3000 and 10000; the reference sees
 * the same rounded inputs. */
static void test_shade_large_brightness_against_reference(void **state)
{
    static const double brights[] = {1000, 3000, 10000};
    double worst = 0;
    int b, i, cases = 0;
    uint32_t seed = 12345u;
    (void)state;
    for (b = 0; b < 3; b++) {
        for (i = 0; i < 2000; i++) {
            light_desc lights[4];
            stp_lighting fl;
            ref_lighting rl;
            stp_material fm;
            ref_material rm;
            stp_vec3 n, point, eye = {0, 0, 0}, none = {0, 0, 0};
            ref_vec3 rn;
            double v[12], s1, target, ref, err;
            int j, k, count;
            for (k = 0; k < 12; k++) {
                seed = seed * 1664525u + 1013904223u;
                v[k] = (double)(seed >> 8) / (double)(1u << 24);
            }
            count = 1 + (int)(v[0] * 4) % 4;
            point = fvec(v[1] * 4 - 2, v[2] * 4 - 2, 6 + v[3] * 4);
            /* a normal facing the eye */
            n = unit_fix(v[4] - 0.5, v[5] - 0.5, -1 - v[6]);
            for (j = 0; j < count; j++) {
                double dist = 20 + 180 * v[7 + j], ang = v[11] * 6.28 + j;
                lights[j].x = dbl(point.x) + dist * 0.5 * cos(ang);
                lights[j].y = dbl(point.y) + dist * 0.5 * sin(ang);
                lights[j].z = dbl(point.z) - dist * 0.7;
                lights[j].power = 1;
            }
            make_material(&fm, &rm, 0.3 + 0.6 * v[8], 10, 0.05 + v[9], 0.5);
            /* the unclamped shade at BRIGHT 1 with unit powers */
            make_lighting(&fl, &rl, 1, 0, 1, lights, count);
            rn = rvec(n);
            if (ref_dot(rn, ref_scale(rvec(point), -1)) < 0.3 * sqrt(ref_dot(rvec(point), rvec(point))))
                continue;
            s1 = ref_shade_point(&rl, &rm, rn, rvec(point), rvec(eye), 0, rvec(none));
            if (s1 <= 0)
                continue;
            target = 0.1 + 0.8 * v[10];
            for (j = 0; j < count; j++)
                lights[j].power = target / (brights[b] * s1);
            make_lighting(&fl, &rl, brights[b], 0, 1, lights, count);
            ref = ref_shade_point(&rl, &rm, rn, rvec(point), rvec(eye), 0, rvec(none));
            err = fabs(dbl(stp_shade_point(&fl, &fm, n, point, eye, 0, none)) - ref);
            if (err > worst)
                worst = err;
            cases++;
        }
    }
    print_message("shade at BRIGHT 1000..10000, %d cases: worst error %.2e\n", cases, worst);
    assert_true(cases > 3000);
    assert_true(worst < SHADE_TOL);
}

/* ---- INTENSITY ---- */

static void check_index_boundaries(int levels)
{
    int j;
    for (j = 0; j < levels; j++) {
        /* the smallest shade of style j+1: ceil(j 2^F / (levels-1)) */
        int64_t num = (int64_t)j * ONE;
        stp_fix edge = (stp_fix)((num + levels - 2) / (levels - 1));
        stp_fix probes[5];
        int p;
        probes[0] = edge - 1;
        probes[1] = edge;
        probes[2] = edge + 1;
        probes[3] = edge + (stp_fix)(ONE / (levels - 1) / 2);
        probes[4] = edge - (stp_fix)(ONE / (levels - 1) / 2);
        for (p = 0; p < 5; p++) {
            stp_fix s = probes[p];
            int want = ref_intensity_index(dbl(s), levels);
            if (stp_intensity_index(s, levels) != want)
                fail_msg("intensity_index(%d = %.7f, %d) = %d, want %d", s, dbl(s), levels,
                         stp_intensity_index(s, levels), want);
        }
        /* exactly at the boundary: the style itself, one LSB below: the one under */
        assert_int_equal(stp_intensity_index(edge, levels), j + 1);
        if (j > 0)
            assert_int_equal(stp_intensity_index(edge - 1, levels), j);
    }
}

static void test_intensity_index_at_step_boundaries(void **state)
{
    int levels;
    (void)state;
    check_index_boundaries(16); /* the seed's INT(15 s + 1) */
    check_index_boundaries(2);
    check_index_boundaries(256);
    for (levels = 3; levels < 256; levels += 7)
        check_index_boundaries(levels);
    /* the ends, and clamping of s and of levels */
    assert_int_equal(stp_intensity_index(0, 16), 1);
    assert_int_equal(stp_intensity_index(ONE, 16), 16);
    assert_int_equal(stp_intensity_index(ONE - 1, 16), 15);
    assert_int_equal(stp_intensity_index(-ONE, 16), 1);
    assert_int_equal(stp_intensity_index(5 * ONE, 16), 16);
    assert_int_equal(stp_intensity_index(STP_FIX_MAX, 256), 256);
    assert_int_equal(stp_intensity_index(ONE, 1), 2);   /* levels clamped to 2 */
    assert_int_equal(stp_intensity_index(ONE, 999), 256); /* and to 256 */
    /* seed example: 15 s + 1 */
    assert_int_equal(stp_intensity_index(fx(0.5), 16), 8);
    assert_int_equal(stp_intensity_index(fx(0.999), 16), 15);
}

static void test_intensity_index_random_shades(void **state)
{
    int i, levels;
    (void)state;
    for (levels = 2; levels <= 256; levels++)
        for (i = 0; i <= 1000; i++) {
            stp_fix s = (stp_fix)((int64_t)ONE * i / 1000 + (i * 7919) % 13 - 6);
            assert_int_equal(stp_intensity_index(s, levels), ref_intensity_index(dbl(s), levels));
        }
}

static void test_intensity_shade_is_inverse(void **state)
{
    int levels, i;
    (void)state;
    for (levels = 2; levels <= 256; levels++) {
        for (i = 1; i <= levels; i++) {
            stp_fix s = stp_intensity_shade(i, levels);
            /* the shade a style stands for: (i-1)/(levels-1) */
            assert_true(fabs(dbl(s) - (double)(i - 1) / (levels - 1)) <= 1.0 * LSB);
            /* and INTENSITY maps it back to the same style */
            if (stp_intensity_index(s, levels) != i)
                fail_msg("intensity_index(intensity_shade(%d, %d) = %d) = %d", i, levels, s,
                         stp_intensity_index(s, levels));
        }
        assert_int_equal(stp_intensity_shade(1, levels), 0);
        assert_int_equal(stp_intensity_shade(levels, levels), ONE);
        /* indices out of range are clamped */
        assert_int_equal(stp_intensity_shade(0, levels), 0);
        assert_int_equal(stp_intensity_shade(levels + 5, levels), ONE);
    }
}

/* ---- style tables ---- */

static void test_style_table_lookup_and_inverse(void **state)
{
    /* a line printer's characters, darkest first, not ordered by code */
    static const uint8_t codes[16] = {'#', 'M', 'W', '8', 'B', '@', '%', '&',
                                      '*', '+', '=', '-', ':', '.', '\'', ' '};
    static const uint8_t dup[4] = {7, 9, 7, 3};
    stp_style_table t = {16, codes}, d = {4, dup};
    int i;
    (void)state;
    for (i = 1; i <= 16; i++) {
        assert_int_equal(stp_style_lookup(&t, i), codes[i - 1]);
        assert_int_equal(stp_style_inverse(&t, codes[i - 1]), i);
    }
    assert_int_equal(stp_style_lookup(&t, 0), '#');    /* clamped */
    assert_int_equal(stp_style_lookup(&t, -3), '#');
    assert_int_equal(stp_style_lookup(&t, 17), ' ');
    assert_int_equal(stp_style_inverse(&t, 'Z'), 0);   /* not in the table */
    assert_int_equal(stp_style_inverse(&d, 7), 1);     /* the first match */
    assert_int_equal(stp_style_inverse(&d, 3), 4);
    /* shade -> style -> code -> style round trip */
    for (i = 0; i <= 100; i++) {
        int idx = stp_intensity_index(fx(i / 100.0), 16);
        assert_int_equal(stp_style_inverse(&t, stp_style_lookup(&t, idx)), idx);
    }
}

/* ---- gamma ---- */

static void test_gamma_table_against_reference(void **state)
{
    static const double gammas[] = {1.0, 1.8, 2.2, 3.0};
    static const double kk[] = {1.0, 0.8};
    static const int levels_list[] = {256, 16, 2, 5};
    int ig, ik, il, i, worst = 0;
    (void)state;
    for (ig = 0; ig < 4; ig++)
        for (ik = 0; ik < 2; ik++)
            for (il = 0; il < 4; il++) {
                uint8_t out[256];
                int levels = levels_list[il];
                stp_fix g = fx(gammas[ig]), k = fx(kk[ik]);
                assert_int_equal(stp_gamma_table(out, levels, g, k), 0);
                for (i = 0; i < levels; i++) {
                    double want = 255.0 * ref_gamma((double)i / (levels - 1), dbl(g), dbl(k));
                    double err = fabs((double)out[i] - want);
                    /* within 1/255 of the real function (shade.h) */
                    if (err > 1.0)
                        fail_msg("gamma(%d/%d, gamma %g, k %g) = %d, want %.3f", i, levels - 1,
                                 gammas[ig], kk[ik], out[i], want);
                    if (abs((int)out[i] - (int)floor(want + 0.5)) > worst)
                        worst = abs((int)out[i] - (int)floor(want + 0.5));
                }
                assert_int_equal(out[0], 0);
                assert_int_equal(out[levels - 1], 255);
            }
    print_message("gamma: worst difference from round(255 V) = %d\n", worst);
}

static void test_gamma_table_identity_and_bad_arguments(void **state)
{
    uint8_t out[256];
    int i;
    (void)state;
    assert_int_equal(stp_gamma_table(out, 256, ONE, ONE), 0);
    for (i = 0; i < 256; i++)
        assert_int_equal(out[i], i);
    /* gamma <= 0 and k <= 0 are taken as 1 */
    assert_int_equal(stp_gamma_table(out, 256, 0, -ONE), 0);
    for (i = 0; i < 256; i++)
        assert_int_equal(out[i], i);
    /* levels out of range: -1, out untouched */
    memset(out, 0xAB, sizeof out);
    assert_int_equal(stp_gamma_table(out, 1, ONE, ONE), -1);
    assert_int_equal(stp_gamma_table(out, 257, ONE, ONE), -1);
    assert_int_equal(stp_gamma_table(NULL, 16, ONE, ONE), -1);
    for (i = 0; i < 256; i++)
        assert_int_equal(out[i], 0xAB);
    /* monotonic for gamma 2.2 */
    assert_int_equal(stp_gamma_table(out, 256, fx(2.2), ONE), 0);
    for (i = 1; i < 256; i++)
        assert_true(out[i] >= out[i - 1]);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_seed_defaults),
        cmocka_unit_test(test_specular_terms_against_reference),
        cmocka_unit_test(test_specular_terms_known_values),
        cmocka_unit_test(test_specular_terms_zero_for_nonpositive_cosines),
        cmocka_unit_test(test_shade_grid_against_reference),
        cmocka_unit_test(test_shade_highlight_sweep),
        cmocka_unit_test(test_shade_light_at_point_is_head_on),
        cmocka_unit_test(test_shade_back_face_is_ambient_only),
        cmocka_unit_test(test_shade_no_lights_and_caps),
        cmocka_unit_test(test_shade_large_brightness_against_reference),
        cmocka_unit_test(test_intensity_index_at_step_boundaries),
        cmocka_unit_test(test_intensity_index_random_shades),
        cmocka_unit_test(test_intensity_shade_is_inverse),
        cmocka_unit_test(test_style_table_lookup_and_inverse),
        cmocka_unit_test(test_gamma_table_against_reference),
        cmocka_unit_test(test_gamma_table_identity_and_bad_arguments),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
