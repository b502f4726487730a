/* SPDX-License-Identifier: MIT */
/*
 * Double-precision reference of the shading system, written from docs/model.md
 * section 2 (MAKE-SHADE, Algorithm 10.5, extended to several lights as in
 * (10.16)) and section 3 (INTENSITY, gamma).  It shares no code with
 * src/shade.c and uses the conventions documented for stp_shade_point in
 * include/stipple/shade.h:
 *   - E = unit(eye - point) in perspective, the given direction in parallel;
 *   - a light exactly at the point is taken as L = N, U = 0;
 *   - lights with N.L <= 0 contribute nothing;
 *   - N.E <= 0 (a back face, or the eye on the surface point) gives the
 *     ambient share only: min(1, BRIGHT * B * R);
 *   - where H is undefined (L + E = 0) there is no specular term;
 *   - F = 1 where Fresnel's g is imaginary (n^2 + c^2 - 1 < 0).
 * Plain doubles, no saturation: the reference is the real function.
 */
#ifndef STIPPLE_TESTS_SHADE_REF_H
#define STIPPLE_TESTS_SHADE_REF_H

#define REF_MAX_LIGHTS 8

typedef struct ref_vec3 {
    double x, y, z;
} ref_vec3;

typedef struct ref_light {
    ref_vec3 position;
    double power; /* P_j */
} ref_light;

typedef struct ref_lighting {
    double brightness; /* BRIGHT */
    double background; /* B, clamped to [0, 1] by ref_shade_point */
    double c;          /* C of 1/(C + U), > 0 */
    int count;
    ref_light lights[REF_MAX_LIGHTS];
} ref_lighting;

typedef struct ref_material {
    double reflectivity; /* R */
    double refraction;   /* n */
    double gloss;        /* k */
    double specular;     /* Ks, weight of D.G.F/(N.E) */
} ref_material;

double ref_dot(ref_vec3 a, ref_vec3 b);
ref_vec3 ref_v3(double x, double y, double z);
ref_vec3 ref_add(ref_vec3 a, ref_vec3 b);
ref_vec3 ref_sub(ref_vec3 a, ref_vec3 b);
ref_vec3 ref_scale(ref_vec3 a, double s);
ref_vec3 ref_cross(ref_vec3 a, ref_vec3 b);
/* v/|v| into *out; returns |v| (0 and *out = 0 for the zero vector). */
double ref_unit(ref_vec3 v, ref_vec3 *out);

/* Facet distribution (10.4): D = (k / (k + 1 - N.H))^2. */
double ref_facet_d(double n_dot_h, double k);
/* Roughness blocking in the listing's order: 2 min(N.E, N.L)(N.H)/(E.H),
 * capped at 1. */
double ref_blocking_g(double n_dot_h, double n_dot_e, double n_dot_l, double e_dot_h);
/* Fresnel (10.6-10.8) in the listing's order: gf = sqrt(n^2 + c^2 - 1),
 * t = ((gf + c)c - 1)/((gf - c)c + 1), F = (t^2 + 1)((gf - c)/(gf + c))^2 / 2;
 * 1 where gf is imaginary. */
double ref_fresnel_f(double e_dot_h, double n);

/* The full shade s in [0, 1]:
 * min(1, BRIGHT (B R + sum_j P_j (R (N.L_j) + Ks D G F/(N.E)) / (C + U_j)))
 * over the lights with N.L_j > 0. */
double ref_shade_point(const ref_lighting *lighting, const ref_material *material,
                       ref_vec3 normal, ref_vec3 point, ref_vec3 eye, int parallel,
                       ref_vec3 parallel_dir);

/* INTENSITY (Algorithm 10.6): INT(s (N - 1) + 1), s clamped to [0, 1],
 * levels clamped to 2..256. */
int ref_intensity_index(double s, int levels);

/* Gamma (10.44): V = (I/k)^(1/gamma), clamped to [0, 1]. */
double ref_gamma(double intensity, double gamma, double k);

#endif
