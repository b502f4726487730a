/* SPDX-License-Identifier: MIT */
/*
 * Shading (docs/model.md section 2), INTENSITY and gamma (section 3).
 *
 * All quantities are stp_fix.  Units: positions in view-plane units, angles
 * as cosines in [-1, 1], shades in [0, 1].  Nothing here can overflow: every
 * quotient that can explode (the specular share DGF/(E.N) as E.N -> 0, the
 * Fresnel ratio as its denominator -> 0) saturates and the final shade is
 * capped at 1, as MAKE-SHADE's min(1, ...) does.
 */
#ifndef STIPPLE_SHADE_H
#define STIPPLE_SHADE_H

#include <stdint.h>
#include "stipple/fix.h"

#ifdef __cplusplus
extern "C" {
#endif

/* One point light: position (view or world units, see where it is used),
 * power P_j of (10.16) (the seed's single light has P = 1 - background) and
 * colour, the share of the power in red, green, blue, each in [0, 1]
 * (default 1, 1, 1; used by colour shading only). */
typedef struct stp_light {
    stp_vec3 position;
    stp_fix power;
    stp_fix colour[3];
} stp_light;

/* The lighting of a view (SET-LIGHT, 10.8, extended to several lights).
 *   brightness      BRIGHT, overall factor, >= 0 (seed default 1)
 *   background      BKGRND = B, indirect light share, clamped to [0, 1]
 *   attenuation_c   C of 1/(C + U), > 0 (default 1; values <= 0 are taken
 *                   as 2^-F so the light on a surface stays finite)
 *   count           lights in use, 0..STP_MAX_LIGHTS */
typedef struct stp_lighting {
    stp_fix brightness;
    stp_fix background;
    stp_fix attenuation_c;
    int count;
    stp_light lights[STP_MAX_LIGHTS];
} stp_lighting;

/* An object's shading parameters (SET-OBJECT-SHADE, 10.7).
 *   reflectivity  R in [0, 1]          (seed default 1)
 *   refraction    n, index of refraction, > 0 (seed default 10)
 *   gloss         k > 0: small = sharp highlight (seed default 10);
 *                 values below 2^-F are taken as 2^-F
 *   specular      weight of the D.G.F/(E.N) term (1 = the seed's model;
 *                 NFF's Ks maps here; 0 switches the highlight off). */
typedef struct stp_material {
    stp_fix reflectivity;
    stp_fix refraction;
    stp_fix gloss;
    stp_fix specular;
    stp_fix colour[3]; /* reflectivity's share per channel, [0, 1] (1, 1, 1);
                          colour shading only */
} stp_material;

/* The seed's defaults (INITIALIZE-10): light at (0,0,1) with power 1,
 * brightness 1, background 0, C = 1; material R = 1, n = 10, k = 10. */
void stp_lighting_default(stp_lighting *lighting);
void stp_material_default(stp_material *material);

/* The specular factors for one light, each in [0, 1] (for diagnostics and
 * tests).  Inputs are cosines in [-1, 1]; n is the index of refraction, k the
 * gloss.  Where H is undefined or a cosine is <= 0 all three are 0. */
typedef struct stp_specular_terms {
    stp_fix d; /* facet distribution (10.4) */
    stp_fix g; /* roughness blocking, min(1, G_r, G_i) (10.9-10.11) */
    stp_fix f; /* Fresnel (10.6-10.8); 1 where g is imaginary (n < 1) */
} stp_specular_terms;
stp_specular_terms stp_specular(stp_fix n_dot_h, stp_fix n_dot_e, stp_fix n_dot_l,
                                stp_fix e_dot_h, stp_fix refraction, stp_fix gloss);

#if STP_WITH_SPECULAR || STP_WITH_RAYTRACE
/* The Fresnel factor F of (10.6)-(10.8), in [0, 1], for the cosine c of
 * the angle of incidence (E.H for a highlight, E.N for a mirror
 * reflection, (10.22)) and the index of refraction n (> 0; values <= 0 are
 * taken as 2^-F).  c <= 0 (grazing or behind) gives 1, as does an
 * imaginary g (n < 1 beyond the critical angle). */
stp_fix stp_fresnel(stp_fix c, stp_fix n);
#endif

/* MAKE-SHADE (Algorithm 10.5, extended to (10.16)) for one surface point.
 *   normal     unit surface normal N (from stp_vec3_unity)
 *   point      the point, in the same frame as the lights' positions
 *   eye        perspective: the centre of projection; parallel: ignored
 *   parallel   0: E = eye - point, normalised; 1: E = parallel_dir
 *   parallel_dir  unit direction towards the viewer (parallel only)
 * Returns the shade s in [0, 1]:
 *   s = min(1, BRIGHT * (B*R + sum_j P_j*(R*(N.L_j) + Ks*D*G*F/(N.E)) / (C + U_j)))
 * over the lights with N.L_j > 0 (none: s = min(1, BRIGHT*B*R)).  The
 * caller decides back faces (N.E <= 0) before calling: for them this returns
 * the ambient share only.
 * Precision: directions and cosines are carried with 30 fractional bits;
 * each light's factors (BRIGHT, P_j, 1/(C + U), R (N.L), D, F, G/(N.E))
 * with 32 significant bits whatever their size, the differences that
 * cancel (1 - N.H near the mirror direction, Fresnel's g - c for n near 1,
 * 1 + E.L for a light opposite the eye) formed from the vectors instead,
 * and U from the exact squared distance; one rounding to stp_fix at the
 * end.  So the error does not grow with BRIGHT, a small C, a small gloss
 * or a grazing light or eye: at most 2.8e-4 against the double reference
 * over 30 000 cases, 70 % of them extremes (docs/error.md,
 * tests/shade_accuracy), in the 64-bit and the 32-bit arithmetic. */
stp_fix stp_shade_point(const stp_lighting *lighting, const stp_material *material,
                        stp_vec3 normal, stp_vec3 point, stp_vec3 eye, int parallel,
                        stp_vec3 parallel_dir);

#if STP_WITH_SHADOWS
/* stp_shade_point with its parts kept apart, for shadows (render.h,
 * stp_renderer_set_shadow_map): *ambient = B*R and terms[j] (STP_MAX_LIGHTS entries)
 * = P_j*(R*(N.L_j) + Ks*D*G*F/(N.E))/(C + U_j), rounded and saturated to
 * stp_fix, for each light j that reaches the face, 0 for the others
 * (N.L_j <= 0, j beyond the count, every light of a back face).  Returns the
 * same shade as stp_shade_point; stp_shade_combine(BRIGHT, *ambient, terms,
 * STP_MAX_LIGHTS, all ones) gives it up to the terms' rounding, BRIGHT
 * (count + 1) 2^-(F+1). */
stp_fix stp_shade_point_terms(const stp_lighting *lighting, const stp_material *material,
                              stp_vec3 normal, stp_vec3 point, stp_vec3 eye, int parallel,
                              stp_vec3 parallel_dir, stp_fix *ambient, stp_fix terms[STP_MAX_LIGHTS]);

/* The shade of a point from its parts, with only the lights whose bit is set
 * in lit (bit j: terms[j], j < count, j < 32):
 * min(1, brightness * (ambient + sum of those terms)), clamped to [0, 1], in
 * stp_shade_point's order of operations (the sum formed in 64 bits and
 * saturated once, then BRIGHT). */
stp_fix stp_shade_combine(stp_fix brightness, stp_fix ambient, const stp_fix *terms, int count,
                          uint32_t lit);
#endif

/* Colour shading (10.45): the shade of each channel c = 0, 1, 2 (red, green,
 * blue) into out[c], as stp_shade_point with R_c = R * material colour[c] and
 * P_j,c = P_j * light j's colour[c].  The specular share is not tinted by the
 * material (the seed: it is colour-independent) but carries the light's
 * colour.  Each channel is capped at 1 on its own. */
void stp_shade_point_colour(const stp_lighting *lighting, const stp_material *material,
                            stp_vec3 normal, stp_vec3 point, stp_vec3 eye, int parallel,
                            stp_vec3 parallel_dir, stp_fix out[3]);

/* Luminance of a colour shade: 0.30 r + 0.59 g + 0.11 b, the Y of the seed's
 * YIQ (10.38), which is what a monochrome display shows of a colour. */
stp_fix stp_shade_luminance(const stp_fix rgb[3]);

/* INTENSITY (Algorithm 10.6): shade s in [0, 1] (clamped) to a style number
 * 1..levels, INT(s*(levels-1) + 1), darkest first.  levels in 2..256 (values
 * outside are clamped).  */
int stp_intensity_index(stp_fix shade, int levels);

/* The shade a style number stands for: (index-1)/(levels-1), the inverse of
 * stp_intensity_index up to its quantisation (index clamped to 1..levels). */
stp_fix stp_intensity_shade(int index, int levels);

/* A style table: levels device codes, darkest first (the seed's
 * SHADE-STYLES).  stp_style_lookup returns codes[index-1];
 * stp_style_inverse the index (1..levels) of the first entry equal to code,
 * or 0 if the code is not in the table. */
typedef struct stp_style_table {
    int levels;
    const uint8_t *codes;
} stp_style_table;
uint8_t stp_style_lookup(const stp_style_table *table, int index);
int stp_style_inverse(const stp_style_table *table, uint8_t code);

/* Gamma table (10.44): out[i] = round(255 * clamp((I/k)^(1/gamma), 0, 1))
 * with I = i/(levels-1), for i in 0..levels-1.  gamma > 0 (<= 0 is taken as
 * 1), k > 0 (<= 0 is taken as 1).  levels in 2..256; returns 0, or -1 when
 * levels is out of range (out untouched).  Error: at most 1 of 255 against
 * the real function (tests/core/test_shade.c). */
int stp_gamma_table(uint8_t *out, int levels, stp_fix gamma, stp_fix k);

#ifdef __cplusplus
}
#endif

#endif
