/* SPDX-License-Identifier: MIT */
/*
 * The quality bench's measure of a 1-bit picture (host code, double):
 * the ideal is stipple's own render at 4x the size with 256 levels to 8-bit
 * grey, box-filtered 4x4 down to the size (values in [0, 1]), in the tone
 * (exposure, grey from colour, background) of the method's options; the
 * error is the mean absolute difference between the 1-bit picture (ON = 1)
 * and the ideal, both blurred by a Gaussian of sigma 1.5 pixels (taps to 3
 * sigma, weights renormalised over the taps inside the frame).
 */
#ifndef STIPPLE_BENCH_QUALITY_MEASURE_H
#define STIPPLE_BENCH_QUALITY_MEASURE_H

#include "quality_methods.h"
#include "scene.h"

/* The ideal of scene at w x h in the tone of m's options (m NULL: the
 * library's defaults): ideal[w*h] in [0, 1].  0, or -1 (message on stderr). */
int qm_render_ideal(const stp_scene *scene, const qm_method *m, int w, int h, double *ideal);

/* Separable Gaussian blur of in[w*h] to out[w*h], sigma 1.5 pixels. */
void qm_gauss_blur(const double *in, double *out, int w, int h);

/* Mean |blur(bits) - ideal_blurred| over the w x h picture, bits 0/1. */
double qm_picture_error(const unsigned char *bits, const double *ideal_blurred, int w, int h);

/* Render scene with m's options (on top of the library's defaults) to a
 * w x h MONO1 picture, unpacked to bits[w*h] 0/1.  0, or -1. */
int qm_render_bits(const stp_scene *scene, const qm_method *m, int w, int h, unsigned char *bits);

#endif
