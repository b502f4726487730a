/* SPDX-License-Identifier: MIT */
/*
 * Colour models (docs/model.md section 6), in stp_fix.
 *
 * RGB components are in [0, 1]; angles (hue) in degrees [0, 360); other
 * ranges are given per function.  Matrices follow the seed's row-vector
 * convention: [out] = [in] * M, M.m[row][column].  Inputs outside the stated
 * ranges are not rejected: results then follow the formulas (saturating),
 * which is what out-of-gamut colours need to stay visible to the caller.
 */
#ifndef STIPPLE_COLOUR_H
#define STIPPLE_COLOUR_H

#include <stdint.h>
#include "stipple/fix.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct stp_rgb {
    stp_fix r, g, b;
} stp_rgb;

typedef struct stp_mat3 {
    stp_fix m[3][3];
} stp_mat3;

/* [out] = [in] * m, each product in 64 bits, saturated. */
stp_vec3 stp_mat3_apply(const stp_mat3 *m, stp_vec3 in);

/* Inverse of m by the adjugate; returns 0, or -1 (out untouched) when m is
 * singular at stp_fix precision.  Error: a few 2^-F for entries near 1. */
int stp_mat3_inverse(const stp_mat3 *m, stp_mat3 *out);

/* CMY (10.37): C = 1 - R, M = 1 - G, Y = 1 - B, and back. */
stp_vec3 stp_rgb_to_cmy(stp_rgb c);
stp_rgb stp_cmy_to_rgb(stp_vec3 cmy);

/* CMYK: K = min(C, M, Y), the other three less K (under-colour removal in
 * full); k_out receives K.  Back: C = C' + K, ... then CMY to RGB. */
stp_vec3 stp_rgb_to_cmyk(stp_rgb c, stp_fix *k_out);
stp_rgb stp_cmyk_to_rgb(stp_vec3 cmy, stp_fix k);

/* YIQ (10.38): [I Q Y] = [R G B] * the seed's matrix (columns I, Q, Y; Y the
 * luminance 0.30 R + 0.59 G + 0.11 B).  stp_yiq_to_rgb uses its inverse. */
stp_vec3 stp_rgb_to_iqy(stp_rgb c);
stp_rgb stp_iqy_to_rgb(stp_vec3 iqy);

/* Luminance Y of the seed's YIQ: 0.30 R + 0.59 G + 0.11 B. */
stp_fix stp_rgb_luminance(stp_rgb c);

/* HSV hexcone (Algorithms 10.13, 10.14): h degrees [0, 360) (0 for grey),
 * s, v in [0, 1]; out = {h, s, v}. */
stp_vec3 stp_rgb_to_hsv(stp_rgb c);
stp_rgb stp_hsv_to_rgb(stp_vec3 hsv);

/* HLS double hexcone: out = {h, l, s}, h as HSV's, l and s in [0, 1]. */
stp_vec3 stp_rgb_to_hls(stp_rgb c);
stp_rgb stp_hls_to_rgb(stp_vec3 hls);

/* HSI (10.39-10.42): rotate so the grey diagonal is the third axis
 * (M1, M2, I1), then H = atan(M1/M2) in degrees [0, 360), S = |(M1, M2)| in
 * [0, sqrt(2/3)], I = I1 * sqrt(3) = R + G + B in [0, 3] (the seed's
 * scaling).  out = {h, s, i}. */
stp_vec3 stp_rgb_to_hsi(stp_rgb c);
stp_rgb stp_hsi_to_rgb(stp_vec3 hsi);

/* atan2(y, x) in degrees [0, 360); 0 for (0, 0).  Error < 0.001 degrees. */
stp_fix stp_fix_atan2_deg(stp_fix y, stp_fix x);

/* The RGB -> CIE XYZ matrix of a device (10.28-10.36): primaries[i] = the
 * (x, y) chromaticity of red, green, blue; white = (x, y) of the white point
 * (Y = 1).  The rows are each primary's (x, y, z) times its weight, the
 * weights solving "R = G = B = 1 gives the white point".  weights_out may be
 * NULL.  Returns 0, or -1 when a y is 0 or the primaries are collinear. */
typedef struct stp_xy {
    stp_fix x, y;
} stp_xy;
int stp_colour_rgb_to_xyz_matrix(const stp_xy primaries[3], stp_xy white, stp_mat3 *to_xyz,
                                 stp_vec3 *weights_out);

/* The same with the white point given as XYZ (the seed's worked example
 * states X = 0.950, Y = 1, Z = 1.089, rounded from x = 0.313, y = 0.329). */
int stp_colour_rgb_to_xyz_matrix_xyz(const stp_xy primaries[3], stp_vec3 white_xyz,
                                     stp_mat3 *to_xyz, stp_vec3 *weights_out);

/* A colour table (SPEC 6): 256 entries of 24-bit colour, 0xRRGGBB. */
typedef struct stp_colour_table {
    uint32_t entry[256];
} stp_colour_table;

/* Grey ramp: entry i = (i, i, i). */
void stp_colour_table_grey(stp_colour_table *t);

/* Pseudocolour for grey images: entry i has hue 240 - 240 i/255 degrees
 * (blue through green to red), full saturation and value. */
void stp_colour_table_pseudocolour(stp_colour_table *t);

/* Gamma per primary: each entry's R, G, B byte is replaced by
 * gamma_r[R], gamma_g[G], gamma_b[B] (256-entry tables, e.g. from
 * stp_gamma_table with 256 levels). */
void stp_colour_table_apply_gamma(stp_colour_table *t, const uint8_t *gamma_r,
                                  const uint8_t *gamma_g, const uint8_t *gamma_b);

#ifdef __cplusplus
}
#endif

#endif
