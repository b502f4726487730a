/* SPDX-License-Identifier: MIT */
/*
 * Double-precision error diffusion and ordered dither of a grey picture, the
 * reference for the core's fixed-point diffusion (tests/core) and the
 * "applied to the ideal" methods of the quality bench.  Host code.
 */
#ifndef STIPPLE_TESTS_DIFFUSE_REF_H
#define STIPPLE_TESTS_DIFFUSE_REF_H

/* Kernels, in the order of stp_diffusion_kernel (include/stipple/diffuse.h). */
typedef enum ref_kernel {
    REF_FLOYD_STEINBERG = 0,
    REF_ATKINSON,
    REF_SIERRA_LITE,
    REF_JARVIS_JUDICE_NINKE,
    REF_STUCKI,
    REF_BURKES,
    REF_KERNEL_COUNT
} ref_kernel;

/* Diffuse grey[w*h] (0 = black .. 1 = white) to bits[w*h] (1 = ON): a pixel
 * is ON when its value plus the error it received is >= 0.5; the error
 * (value - output) goes to the kernel's neighbours that are inside the
 * frame (shares past an edge are lost).  serpentine: odd rows run right to
 * left with the kernel mirrored. */
void ref_diffuse(const double *grey, int w, int h, ref_kernel kernel, int serpentine,
                 unsigned char *bits);

/* As ref_diffuse with the threshold of pixel (x, y) moved by
 * (mask[(y mod 64) 64 + x mod 64] - 127.5) amplitude / 256 levels (of 255)
 * times clamp((2 band + 8 - |2p - 255|) / 8, 0, 1), p the pixel's grey in
 * levels rounded to an integer, mask a 64x64 threshold mask (NULL: not
 * moved): stp_diffusion's noise, noise_amplitude, noise_band; with a mask,
 * Floyd-Steinberg's pixels whose factor is above 0 spread their error
 * 5 right, 2 6 3 below (/16). */
void ref_diffuse_noise(const double *grey, int w, int h, ref_kernel kernel, int serpentine,
                       const unsigned char *mask, double amplitude, int band, unsigned char *bits);

/* Ordered dither with thresholds t[th*tw] (0..255, ON when 255 grey > t). */
void ref_ordered(const double *grey, int w, int h, const unsigned char *t, int tw, int th,
                 unsigned char *bits);

#endif
