/* SPDX-License-Identifier: MIT */
/* The stiff and extreme suite: see stiff_cases.h. */
#include "stiff_cases.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define MAX_CASES 96
#define PI 3.14159265358979323846

static stiff_case cases[MAX_CASES];
static size_t case_count;
static int cases_built;

stp_fix stiff_to_fix(double v)
{
    double s = v * (double)STP_FIX_ONE;
    if (!(s == s))
        return 0;
    if (s >= (double)STP_FIX_MAX)
        return STP_FIX_MAX;
    if (s <= (double)STP_FIX_MIN)
        return STP_FIX_MIN;
    return (stp_fix)lround(s);
}

static double from_fix(stp_fix v)
{
    return (double)v / (double)STP_FIX_ONE;
}

static ref_vec3 unit(ref_vec3 v)
{
    ref_vec3 u;
    (void)ref_unit(v, &u);
    return u;
}

static ref_vec3 add_scaled(ref_vec3 a, ref_vec3 d, double s)
{
    return ref_v3(a.x + d.x * s, a.y + d.y * s, a.z + d.z * s);
}

/* Rotation about x by 30 degrees, then about y by 20: puts a polygon off
 * every axis so that rounding of its coordinates matters. */
static ref_vec3 tilt(ref_vec3 p)
{
    double ax = 30 * PI / 180, ay = 20 * PI / 180;
    ref_vec3 q = ref_v3(p.x, p.y * cos(ax) - p.z * sin(ax), p.y * sin(ax) + p.z * cos(ax));
    return ref_v3(q.x * cos(ay) + q.z * sin(ay), q.y, -q.x * sin(ay) + q.z * cos(ay));
}

/* ---- building the table ---- */

static stiff_case *new_case(const char *name, const char *behaviour, stiff_kind kind)
{
    stiff_case *c;
    if (case_count >= MAX_CASES)
        abort(); /* the table is static: raise MAX_CASES */
    c = &cases[case_count++];
    memset(c, 0, sizeof *c);
    c->name = name;
    c->behaviour = behaviour;
    c->kind = kind;
    c->lighting.brightness = 1;
    c->lighting.background = 0.2;
    c->lighting.c = 1;
    c->lighting.count = 1;
    c->material.reflectivity = 0.8;
    c->material.refraction = 10;
    c->material.gloss = 0.2;
    c->material.specular = 0.3;
    c->expect = -1;
    c->tol = STIFF_HALF_STEP;
    c->expect_status = STP_OK;
    return c;
}

/* Light j of a SHADE case at dist from the point along dir, with the power
 * 0.5 (C + U) that cancels the attenuation (so the shade stays unsaturated
 * and every term shows). */
static void light_dir(stiff_case *c, int j, ref_vec3 dir, double dist)
{
    c->lighting.lights[j].position = add_scaled(c->point, unit(dir), dist);
    c->lighting.lights[j].power = 0.5 * (c->lighting.c + dist);
}

/* A SHADE case: point (0, 0, 4) seen from the origin (E = (0, 0, -1)),
 * facing the eye, light 3 units off above-left on the eye's side. */
static stiff_case *shade_case(const char *name, const char *behaviour)
{
    stiff_case *c = new_case(name, behaviour, STIFF_SHADE);
    c->point = ref_v3(0, 0, 4);
    c->eye = ref_v3(0, 0, 0);
    c->normal = ref_v3(0, 0, -1);
    c->pdir = ref_v3(0, 0, -1);
    light_dir(c, 0, ref_v3(-1, 1, -1), 3);
    return c;
}

/* A POLYGON case: 64 x 64, from (0, 0, -4) at the origin, 60 degrees,
 * hither 1/64; one light at (-2, 3, -6) with power 0.8 (1 + |light|). */
static stiff_case *polygon_case(const char *name, const char *behaviour)
{
    stiff_case *c = new_case(name, behaviour, STIFF_POLYGON);
    ref_vec3 l = ref_v3(-2, 3, -6);
    c->view.from = ref_v3(0, 0, -4);
    c->view.at = ref_v3(0, 0, 0);
    c->view.up = ref_v3(0, 1, 0);
    c->view.fov_degrees = 60;
    c->view.window_half = 2;
    c->view.hither = 1.0 / 64;
    c->view.perspective = 1;
    c->lighting.lights[0].position = l;
    c->lighting.lights[0].power = 0.8 * (1 + sqrt(ref_dot(l, l)));
    return c;
}

static void vertex(stiff_case *c, ref_vec3 p)
{
    if (c->n >= STIFF_MAX_VERTS)
        abort();
    c->v[c->n++] = p;
}

static void triangle(stiff_case *c, ref_vec3 a, ref_vec3 b, ref_vec3 d)
{
    vertex(c, a);
    vertex(c, b);
    vertex(c, d);
}

/* Normal with N.E = ne for E = (0, 0, -1), tipped towards +x. */
static ref_vec3 normal_with_ne(double ne)
{
    return ref_v3(sqrt(1 - ne * ne), 0, -ne);
}

static void build_shade_cases(void)
{
    stiff_case *c;
    static const double grazing[] = {1e-2, 1e-4, 1e-6};
    static const char *const light_names[] = {"grazing_light_NL_1e-2", "grazing_light_NL_1e-4",
                                              "grazing_light_NL_1e-6"};
    static const char *const eye_names[] = {"grazing_eye_NE_1e-2", "grazing_eye_NE_1e-4",
                                            "grazing_eye_NE_1e-6"};
    static const char *const corner_names[] = {"grazing_both_EH_1e-2", "grazing_both_EH_1e-4",
                                               "grazing_both_EH_1e-6"};
    int i;

    c = shade_case("baseline", "finite: ambient + diffuse + highlight, none saturated");
    (void)c;

    for (i = 0; i < 3; i++) {
        double d = grazing[i];
        c = shade_case(light_names[i],
                       "finite: the diffuse term and G (~ N.L) vanish with N.L; a light whose "
                       "N.L rounds to <= 0 counts for nothing, which is within N.L of the truth");
        light_dir(c, 0, ref_v3(sqrt(1 - d * d), 0, -d), 3);
    }
    for (i = 0; i < 3; i++) {
        double e = grazing[i];
        c = shade_case(eye_names[i],
                       "finite: D G F / (N.E) stays bounded because G = 2 (N.H)(N.E)/(E.H) "
                       "carries N.E; at N.E <= 0 the shade is the ambient share (documented "
                       "for stp_shade_point), a jump the rounding of N.E can cross");
        c->normal = normal_with_ne(e);
        light_dir(c, 0, c->normal, 3);
        if (e < 1e-5) {
            c->tol = 0.5; /* the whole light's share: ambient only on one side */
            c->reason = "N.E = 1e-6 is below the step 2^-16: the rounded inputs have N.E <= 0 "
                        "(reference there: ambient only), the exact ones N.E > 0";
        }
    }
    c = shade_case("grazing_eye_NE_3e-5",
                   "finite: N.E two steps of Q16.16 above 0: the specular share is D F "
                   "2 (N.H)/(E.H), whatever the rounding does to N.E");
    c->normal = normal_with_ne(3e-5);
    light_dir(c, 0, c->normal, 3);
    for (i = 0; i < 3; i++) {
        /* N.E = N.L = sin e, L almost -E: E.H = sin e -> 0, H = N exactly,
         * D = G = 1, F -> 1: the specular share 1/(N.E) explodes */
        double e = grazing[i];
        c = shade_case(corner_names[i],
                       "saturated: L almost opposite E with both grazing makes D G F/(E.N) ~ "
                       "1/(N.E) explode; the quotient saturates and the shade is capped at 1");
        c->normal = ref_v3(cos(e), 0, -sin(e));
        light_dir(c, 0, ref_v3(sin(2 * e), 0, cos(2 * e)), 3);
        if (e < 1e-5) {
            c->tol = 1;
            c->reason = "N.E = N.L = 1e-6 are below the step 2^-16: after rounding the light is "
                        "behind the face or the eye in its plane (ambient only), where the exact "
                        "inputs give the capped 1";
        }
    }

    c = shade_case("opposite_L_plus_E_zero",
                   "documented: L = -E gives N.L = -N.E, so a face seen by the eye is not lit "
                   "by that light: ambient share B R only (H undefined is never needed)");
    c->lighting.lights[0].position = ref_v3(0, 0, 8);
    c->expect = 0.2 * 0.8;
    c = shade_case("opposite_L_plus_E_zero_edge_on",
                   "documented: L = -E with N perpendicular to both: N.E = N.L = 0, ambient only");
    c->lighting.lights[0].position = ref_v3(0, 0, 8);
    c->normal = ref_v3(1, 0, 0);
    c->expect = 0.2 * 0.8;

    c = shade_case("refraction_n_1", "finite: n = 1 gives g = c and F = 0: no highlight");
    c->material.refraction = 1;
    light_dir(c, 0, ref_v3(0.3, 0.2, -1), 3);
    c = shade_case("refraction_n_1_plus", "finite: n -> 1+ gives F -> 0 continuously");
    c->material.refraction = 1.0001;
    light_dir(c, 0, ref_v3(0.3, 0.2, -1), 3);
    c = shade_case("refraction_n_below_1_real",
                   "finite: n = 0.5 with n^2 + c^2 - 1 > 0: Fresnel as written");
    c->material.refraction = 0.5;
    light_dir(c, 0, ref_v3(0.3, 0.2, -1), 3);
    c = shade_case("refraction_n_below_1_total",
                   "documented: n = 0.5 with n^2 + c^2 < 1, g imaginary: total reflection, F = 1");
    c->material.refraction = 0.5;
    light_dir(c, 0, ref_v3(sin(80 * PI / 180), 0, -cos(80 * PI / 180)), 3);
    c = shade_case("refraction_n_0",
                   "documented: n <= 0 is taken as the smallest step: g imaginary, F = 1");
    c->material.refraction = 0;
    c = shade_case("refraction_n_1000", "finite: large n, F -> 1");
    c->material.refraction = 1000;
    c = shade_case("refraction_n_30000", "finite: n near the top of Q16.16, F -> 1 (g^2 < 2^62)");
    c->material.refraction = 30000;

    c = shade_case("gloss_k_1e-6_on_highlight",
                   "finite: k below the step is taken as 2^-F; on the highlight (H = N) D = 1");
    c->material.gloss = 1e-6;
    c->lighting.lights[0].position = ref_v3(0, 0, 1);
    c->lighting.lights[0].power = 0.5 * (1 + 3);
    c = shade_case("gloss_k_1e-6_off_highlight",
                   "finite: k -> 0 makes D a spike; off it D ~ (k/(1 - N.H))^2 -> 0");
    c->material.gloss = 1e-6;
    light_dir(c, 0, ref_v3(sin(PI / 180), 0, -cos(PI / 180)), 3);
    c = shade_case("gloss_k_1e-4_near_highlight", "finite: sharp highlight 1 degree off");
    c->material.gloss = 1e-4;
    light_dir(c, 0, ref_v3(sin(PI / 180), 0, -cos(PI / 180)), 3);
    c = shade_case("gloss_k_0", "finite: k = 0 is taken as 2^-F (D = 0 off the highlight)");
    c->material.gloss = 0;
    c = shade_case("gloss_k_1e4", "finite: k huge, D -> 1 everywhere");
    c->material.gloss = 1e4;
    c = shade_case("gloss_k_30000", "finite: k near the top of Q16.16, D -> 1");
    c->material.gloss = 30000;

    c = shade_case("light_on_point_U_0",
                   "documented: U = 0 has no direction: the light is taken as head-on, L = N, "
                   "weighted 1/(C + 0)");
    c->lighting.lights[0].position = c->point;
    c->lighting.lights[0].power = 0.5;
    c = shade_case("light_on_point_U_0_C_0",
                   "documented: C <= 0 is taken as 2^-F, so P/(C + 0) saturates and the shade "
                   "is capped at 1 (the real function is +infinity)");
    c->lighting.c = 0;
    c->lighting.lights[0].position = c->point;
    c->lighting.lights[0].power = 1;
    c->expect = 1;
    c = shade_case("light_far_U_30000",
                   "finite: 1/(C + U) ~ 3e-5 does not underflow (P term/(C + U) is one 64-bit "
                   "quotient): almost only the ambient share");
    c->lighting.lights[0].position = add_scaled(c->point, unit(ref_v3(-1, 1, -1)), 30000);
    c->lighting.lights[0].power = 1;
    c = shade_case("light_far_U_30000_powered", "finite: a far light with P = 0.5 (C + U)");
    light_dir(c, 0, ref_v3(-1, 1, -1), 30000);
    c = shade_case("light_difference_beyond_range",
                   "finite: light - point exceeds the stp_fix range (both near opposite ends): "
                   "the difference and U are formed in 64 bits, direction and distance kept");
    c->point = ref_v3(-30000, 0, 4);
    c->normal = unit(ref_v3(1, 0.5, -0.2));
    c->lighting.lights[0].position = ref_v3(30000, 10000, 0);
    c->lighting.lights[0].power = 30000; /* about 0.5 (C + U) */

    c = shade_case("brightness_1000", "clamped: BRIGHT >> 1 saturates the shade at 1");
    c->lighting.brightness = 1000;
    c->expect = 1;
    c = shade_case("brightness_30000_ambient_only",
                   "clamped: BRIGHT B R saturates in stp_fix and is capped at 1");
    c->lighting.brightness = 30000;
    c->lighting.lights[0].position = ref_v3(0, 0, 8);
    c->expect = 1;
    c = shade_case("brightness_0", "documented: BRIGHT = 0 gives 0");
    c->lighting.brightness = 0;
    c->expect = 0;
    c = shade_case("brightness_negative", "clamped: a negative BRIGHT gives 0");
    c->lighting.brightness = -1;
    c->expect = 0;

    c = shade_case("background_negative", "clamped: B < 0 is taken as 0");
    c->lighting.background = -0.5;
    c = shade_case("background_above_1", "clamped: B > 1 is taken as 1 (ambient = R)");
    c->lighting.background = 1.5;
    c->lighting.lights[0].power = 0.1;

    c = shade_case("reflectivity_0", "finite: R = 0 leaves the highlight only");
    c->material.reflectivity = 0;
    light_dir(c, 0, ref_v3(0.1, 0.1, -1), 3);
    c = shade_case("specular_off", "finite: Ks = 0 switches the highlight off");
    c->material.specular = 0;
    c = shade_case("parallel_projection", "finite: E is the given direction for every point");
    c->parallel = 1;
    c->pdir = unit(ref_v3(0.2, 0.1, -1));
    c->eye = ref_v3(100, 100, 100); /* ignored */
    c = shade_case("eye_at_point",
                   "documented: eye - point = 0 has no direction: N.E = 0, ambient only");
    c->eye = c->point;
    c->expect = 0.2 * 0.8;
    c = shade_case("four_lights_sum_above_1", "clamped: the lights' sum above 1 is capped");
    c->lighting.count = 4;
    for (i = 0; i < 4; i++)
        light_dir(c, i, ref_v3(i - 1.5, 1, -1), 3);
    c->expect = 1;
    c = shade_case("point_near_range",
                   "finite: point and light near the top of Q16.16, differences small");
    c->point = ref_v3(0, 0, 32000);
    c->eye = ref_v3(0, 0, 31990);
    light_dir(c, 0, ref_v3(-1, 1, -1), 500);
}

static void build_polygon_cases(void)
{
    stiff_case *c;
    ref_vec3 a = tilt(ref_v3(-1, -1, 0)), b = tilt(ref_v3(1, -1, 0)), d = tilt(ref_v3(0, 1, 0));
    int i;

    c = polygon_case("polygon_baseline", "finite: a tilted triangle before the eye");
    triangle(c, a, b, d);

    c = polygon_case("polygon_repeated_vertex",
                     "finite: a repeated vertex adds nothing to Newell's sums: shaded as the "
                     "triangle");
    vertex(c, a);
    vertex(c, b);
    vertex(c, b);
    vertex(c, d);

    c = polygon_case("polygon_all_vertices_equal", "reported: STP_ERR_DEGENERATE, nothing entered");
    triangle(c, a, a, a);
    c->expect_status = STP_ERR_DEGENERATE;

    c = polygon_case("polygon_collinear",
                     "reported: collinear vertices have no normal: STP_ERR_DEGENERATE");
    triangle(c, ref_v3(-1, -1, 0), ref_v3(0, 0, 0), ref_v3(1, 1, 0));
    c->expect_status = STP_ERR_DEGENERATE;

    c = polygon_case("polygon_collinear_tilted",
                     "reported or finite: collinear vertices off the axes; the core's rounding "
                     "may leave a sliver of a few steps' area, which it then shades with the "
                     "normal the rounding gives it (it covers no pixel), else "
                     "STP_ERR_DEGENERATE; the reference calls it degenerate (no comparison)");
    triangle(c, a, ref_v3((a.x + b.x) / 2, (a.y + b.y) / 2, (a.z + b.z) / 2), b);
    c->or_degenerate = 1;

    c = polygon_case("polygon_zero_area_figure8",
                     "reported: a bow-tie whose two loops cancel has a zero Newell normal: "
                     "STP_ERR_DEGENERATE");
    vertex(c, ref_v3(-1, -1, 0));
    vertex(c, ref_v3(1, 1, 0));
    vertex(c, ref_v3(1, -1, 0));
    vertex(c, ref_v3(-1, 1, 0));
    c->expect_status = STP_ERR_DEGENERATE;

    c = polygon_case("polygon_0_vertices", "reported: STP_ERR_DEGENERATE");
    c->expect_status = STP_ERR_DEGENERATE;
    c = polygon_case("polygon_1_vertex", "reported: STP_ERR_DEGENERATE");
    vertex(c, a);
    c->expect_status = STP_ERR_DEGENERATE;
    c = polygon_case("polygon_2_vertices", "reported: STP_ERR_DEGENERATE");
    vertex(c, a);
    vertex(c, b);
    c->expect_status = STP_ERR_DEGENERATE;

    c = polygon_case("polygon_nonplanar_0.1",
                     "finite: Newell's normal is the best-fit plane's; shaded at the average");
    vertex(c, tilt(ref_v3(-1, -1, 0)));
    vertex(c, tilt(ref_v3(1, -1, 0)));
    vertex(c, tilt(ref_v3(1, 1, 0.1)));
    vertex(c, tilt(ref_v3(-1, 1, 0)));
    c = polygon_case("polygon_nonplanar_1", "finite: strongly twisted quad, best-fit normal");
    vertex(c, tilt(ref_v3(-1, -1, 0)));
    vertex(c, tilt(ref_v3(1, -1, 0)));
    vertex(c, tilt(ref_v3(1, 1, 1)));
    vertex(c, tilt(ref_v3(-1, 1, 0)));

    c = polygon_case("polygon_many_sided_max",
                     "finite: STP_MAX_POLYGON_VERTICES vertices on a circle");
    for (i = 0; i < STP_MAX_POLYGON_VERTICES && i < STIFF_MAX_VERTS; i++) {
        double t = 2 * PI * i / STP_MAX_POLYGON_VERTICES;
        vertex(c, tilt(ref_v3(cos(t), sin(t), 0)));
    }
    if (STP_MAX_POLYGON_VERTICES + 1 <= STIFF_MAX_VERTS) {
        c = polygon_case("polygon_too_many_sided",
                         "reported: one vertex above STP_MAX_POLYGON_VERTICES: "
                         "STP_ERR_TOO_MANY_VERTICES");
        for (i = 0; i <= STP_MAX_POLYGON_VERTICES; i++) {
            double t = 2 * PI * i / (STP_MAX_POLYGON_VERTICES + 1);
            vertex(c, tilt(ref_v3(cos(t), sin(t), 0)));
        }
        c->expect_status = STP_ERR_TOO_MANY_VERTICES;
    }

    c = polygon_case("polygon_sliver_1e-2", "finite: a thin triangle (width 1e-2 over length 2)");
    triangle(c, tilt(ref_v3(-1, 0, 0)), tilt(ref_v3(1, 0, 0)), tilt(ref_v3(0, 1e-2, 0)));
    c = polygon_case("polygon_sliver_1e-3", "finite: a thin triangle (width 1e-3 over length 2)");
    triangle(c, tilt(ref_v3(-1, 0, 0)), tilt(ref_v3(1, 0, 0)), tilt(ref_v3(0, 1e-3, 0)));
    c = polygon_case("polygon_sliver_1e-4",
                     "finite: width 1e-4 = 6.5 steps of Q16.16: the normal is defined by a few "
                     "bits of the rounded vertices");
    triangle(c, tilt(ref_v3(-1, 0, 0)), tilt(ref_v3(1, 0, 0)), tilt(ref_v3(0, 1e-4, 0)));

    c = polygon_case("polygon_tiny_1e-2", "finite: a triangle 1e-2 across");
    triangle(c, tilt(ref_v3(-1e-2, -1e-2, 0)), tilt(ref_v3(1e-2, -1e-2, 0)), tilt(ref_v3(0, 1e-2, 0)));
    c = polygon_case("polygon_tiny_1e-3", "finite: a triangle 1e-3 across (65 steps)");
    triangle(c, tilt(ref_v3(-1e-3, -1e-3, 0)), tilt(ref_v3(1e-3, -1e-3, 0)), tilt(ref_v3(0, 1e-3, 0)));
    c = polygon_case("polygon_tiny_1e-4",
                     "finite: a triangle 1e-4 across (6.5 steps): its normal is what the "
                     "rounded vertices say");
    triangle(c, tilt(ref_v3(-1e-4, -1e-4, 0)), tilt(ref_v3(1e-4, -1e-4, 0)), tilt(ref_v3(0, 1e-4, 0)));
    c = polygon_case("polygon_below_step",
                     "reported: all vertices round to one point: STP_ERR_DEGENERATE (the "
                     "reference, unrounded, still has a normal)");
    triangle(c, tilt(ref_v3(-1e-7, -1e-7, 0)), tilt(ref_v3(1e-7, -1e-7, 0)), tilt(ref_v3(0, 1e-7, 0)));
    c->expect_status = STP_ERR_DEGENERATE;

    c = polygon_case("polygon_far_corner_of_range",
                     "finite: world coordinates near 30000, seen from near by; view differences "
                     "are formed in 64 bits");
    c->view.from = ref_v3(29000, 29000, 25000);
    c->view.at = ref_v3(30000, 30000, 30000);
    c->lighting.lights[0].position = ref_v3(28000, 31000, 24000);
    c->lighting.lights[0].power = 0.8 * (1 + 6000);
    for (i = 0; i < 3; i++) {
        ref_vec3 p = i == 0 ? a : (i == 1 ? b : d);
        vertex(c, ref_v3(30000 + 400 * p.x, 30000 + 400 * p.y, 30000 + 400 * p.z));
    }
    c = polygon_case("polygon_span_of_range",
                     "finite: a triangle spanning -30000..30000, axis-aligned view");
    triangle(c, ref_v3(-30000, -30000, 100), ref_v3(30000, -30000, 100), ref_v3(0, 30000, 300));
    c = polygon_case("polygon_span_rotated_view",
                     "refused: seen obliquely its view coordinates exceed the range "
                     "(STP_ERR_RANGE, nothing entered)");
    c->view.at = ref_v3(1, 0.5, -3);
    triangle(c, ref_v3(-30000, -30000, 100), ref_v3(30000, -30000, 100), ref_v3(0, 30000, 300));
    c->expect_status = STP_ERR_RANGE;
    c = polygon_case("polygon_input_beyond_range",
                     "refused: world coordinates beyond the range saturate on input, so "
                     "their view coordinates do (STP_ERR_RANGE, nothing entered)");
    triangle(c, ref_v3(-1e5, -1e5, 50), ref_v3(1e5, -1e5, 50), ref_v3(0, 1e5, 60));
    c->expect_status = STP_ERR_RANGE;

    c = polygon_case("polygon_behind_eye",
                     "finite: shaded (centre behind the eye, E = unit(-centre)), wholly clipped: "
                     "nothing entered, STP_OK");
    triangle(c, ref_v3(-1, -1, -8), ref_v3(1, -1, -8), ref_v3(0, 1, -9));
    c = polygon_case("polygon_partly_behind_eye",
                     "finite: clipped at the hither plane, shaded at the unclipped average");
    triangle(c, ref_v3(-1, -1, -6), ref_v3(1, -1, 0), ref_v3(0, 1, 1));
    c = polygon_case("polygon_on_hither_plane",
                     "finite: a square exactly in the hither plane is kept (z >= hither)");
    vertex(c, ref_v3(-0.01, -0.01, -4 + 1.0 / 64));
    vertex(c, ref_v3(0.01, -0.01, -4 + 1.0 / 64));
    vertex(c, ref_v3(0.01, 0.01, -4 + 1.0 / 64));
    vertex(c, ref_v3(-0.01, 0.01, -4 + 1.0 / 64));
    c = polygon_case("polygon_vertex_at_eye",
                     "documented: a vertex at the eye puts the plane through the eye: edge-on, "
                     "N.E = 0, ambient share only (and no pixel)");
    triangle(c, ref_v3(0, 0, -4), ref_v3(1, -1, 0), ref_v3(-1, -1, 1));
    c->expect = 0.2 * 0.8;
    c = polygon_case("polygon_vertex_just_behind_eye",
                     "finite: a vertex just behind the eye is clipped away at the hither plane");
    triangle(c, ref_v3(0.1, 0.2, -4.5), ref_v3(1, -1, 0), ref_v3(-1, -1, 1));
    c = polygon_case("polygon_centre_at_eye",
                     "finite: vertex average at the eye: E is taken as the line of sight");
    vertex(c, ref_v3(-1, -1, -4));
    vertex(c, ref_v3(1, -1, -4));
    vertex(c, ref_v3(1, 1, -4));
    vertex(c, ref_v3(-1, 1, -4));
    c = polygon_case("polygon_edge_on",
                     "documented: a plane through the eye has N.E = 0: ambient share only");
    triangle(c, ref_v3(0, -1, 0), ref_v3(0, 1, 0), ref_v3(0, 0, 1));
}

static void build(void)
{
    if (cases_built)
        return;
    cases_built = 1;
    build_shade_cases();
    build_polygon_cases();
}

size_t stiff_case_count(void)
{
    build();
    return case_count;
}

const stiff_case *stiff_case_at(size_t i)
{
    build();
    return i < case_count ? &cases[i] : 0;
}

/* ---- running ---- */

static stp_vec3 fix3(ref_vec3 v)
{
    stp_vec3 r;
    r.x = stiff_to_fix(v.x);
    r.y = stiff_to_fix(v.y);
    r.z = stiff_to_fix(v.z);
    return r;
}

static ref_vec3 unfix3(stp_vec3 v)
{
    return ref_v3(from_fix(v.x), from_fix(v.y), from_fix(v.z));
}

static void core_lighting(const ref_lighting *in, stp_lighting *out)
{
    int j;
    stp_lighting_default(out);
    out->brightness = stiff_to_fix(in->brightness);
    out->background = stiff_to_fix(in->background);
    out->attenuation_c = stiff_to_fix(in->c);
    out->count = in->count > STP_MAX_LIGHTS ? STP_MAX_LIGHTS : in->count;
    for (j = 0; j < out->count; j++) {
        out->lights[j].position = fix3(in->lights[j].position);
        out->lights[j].power = stiff_to_fix(in->lights[j].power);
    }
}

static void core_material(const ref_material *in, stp_material *out)
{
    out->reflectivity = stiff_to_fix(in->reflectivity);
    out->refraction = stiff_to_fix(in->refraction);
    out->gloss = stiff_to_fix(in->gloss);
    out->specular = stiff_to_fix(in->specular);
}

/* The rounded inputs back in double, for the reference at them. */
static void unfix_lighting(const stp_lighting *in, ref_lighting *out)
{
    int j;
    memset(out, 0, sizeof *out);
    out->brightness = from_fix(in->brightness);
    out->background = from_fix(in->background);
    /* the core's documented reading of C <= 0 */
    out->c = in->attenuation_c > 0 ? from_fix(in->attenuation_c) : 1.0 / STP_FIX_ONE;
    out->count = in->count;
    for (j = 0; j < in->count; j++) {
        out->lights[j].position = unfix3(in->lights[j].position);
        out->lights[j].power = from_fix(in->lights[j].power);
    }
}

static void run_shade(const stiff_case *c, stiff_outcome *o)
{
    stp_lighting l;
    stp_material m;
    ref_lighting lq;
    ref_material mq;
    stp_fix s;
    core_lighting(&c->lighting, &l);
    core_material(&c->material, &m);
    s = stp_shade_point(&l, &m, fix3(c->normal), fix3(c->point), fix3(c->eye), c->parallel,
                        fix3(c->pdir));
    o->status = 0;
    o->ref_status = REF_OK;
    o->core = from_fix(s);
    o->ref = ref_shade_point(&c->lighting, &c->material, c->normal, c->point, c->eye, c->parallel,
                             c->pdir);
    unfix_lighting(&l, &lq);
    mq.reflectivity = from_fix(m.reflectivity);
    mq.refraction = m.refraction > 0 ? from_fix(m.refraction) : 1.0 / STP_FIX_ONE;
    mq.gloss = m.gloss > 0 ? from_fix(m.gloss) : 1.0 / STP_FIX_ONE;
    mq.specular = from_fix(m.specular);
    o->ref_q = ref_shade_point(&lq, &mq, unfix3(fix3(c->normal)), unfix3(fix3(c->point)),
                               unfix3(fix3(c->eye)), c->parallel, unfix3(fix3(c->pdir)));
}

static void run_polygon(const stiff_case *c, stiff_outcome *o)
{
    static stp_instr df[4 * STIFF_MAX_VERTS];
    static int64_t rmem[8192];
    void *mem = rmem;
    stp_renderer *r;
    stp_view view;
    stp_lighting l;
    stp_material m;
    stp_vec3 v[STIFF_MAX_VERTS];
    ref_ctx ctx;
    double shade;
    int i;
    o->core = o->ref = o->ref_q = -1;
    o->status = STP_ERR_ARG;
    o->ref_status = REF_ERR_ARG;
    if (stp_renderer_size() > sizeof rmem)
        return;
    r = stp_renderer_create(mem, sizeof rmem, df, sizeof df / sizeof df[0], STIFF_WIDTH, STIFF_HEIGHT);
    if (!r)
        return;
    memset(&view, 0, sizeof view);
    view.from = fix3(c->view.from);
    view.at = fix3(c->view.at);
    view.up = fix3(c->view.up);
    view.fov_degrees = stiff_to_fix(c->view.fov_degrees);
    view.window_half = stiff_to_fix(c->view.window_half);
    view.hither = stiff_to_fix(c->view.hither);
    view.projection = c->view.perspective ? STP_PERSPECTIVE : STP_PARALLEL;
    if (stp_renderer_set_view(r, &view) != STP_OK)
        return;
    core_lighting(&c->lighting, &l);
    if (stp_renderer_set_lighting(r, &l) != STP_OK)
        return;
    stp_material_default(&m);
    core_material(&c->material, &m);
    if (stp_renderer_set_object_shade(r, &m) != STP_OK)
        return;
    if (stp_segment_create(r, 1) != STP_OK)
        return;
    for (i = 0; i < c->n; i++)
        v[i] = fix3(c->v[i]);
    o->status = stp_renderer_polygon(r, v, c->n);
    if (o->status == STP_OK && stp_renderer_last_shade(r) >= 0)
        o->core = from_fix(stp_renderer_last_shade(r));

    if (ref_ctx_init(&ctx, STIFF_WIDTH, STIFF_HEIGHT) != 0)
        return;
    if (ref_set_view(&ctx, &c->view) == REF_OK) {
        ref_set_lighting(&ctx, &c->lighting);
        ref_set_material(&ctx, &c->material);
        ctx.shading = 1;
        o->ref_status = ref_polygon(&ctx, c->v, c->n, 0, &shade);
        if (o->ref_status == REF_OK && shade >= 0)
            o->ref = shade;
    }
    ref_ctx_free(&ctx);
}

void stiff_run(const stiff_case *c, stiff_outcome *o)
{
    memset(o, 0, sizeof *o);
    if (c->kind == STIFF_SHADE)
        run_shade(c, o);
    else
        run_polygon(c, o);
    o->answer = c->expect >= 0 ? c->expect : o->ref;
    o->has_err = o->core >= 0 && o->answer >= 0 && o->answer == o->answer;
    o->err = o->has_err ? fabs(o->core - o->answer) : 0;
}
