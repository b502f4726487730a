/* SPDX-License-Identifier: MIT */
/*
 * Error diffusion of 8-bit grey rows to 1-bit rows, one row at a time, with
 * the error rows in caller memory, so a picture drawn in bands diffuses as
 * if drawn whole (the rows carry the error from one band to the next).
 *
 * A pixel's value v is its 8-bit drive level (0..255) plus the error it has
 * received; it is ON (lit) when v >= 127.5, and its error v - (ON ? 255 : 0)
 * goes to the kernel's neighbours to the right and below (shares that fall
 * outside the frame are lost).  Serpentine: odd rows (y odd) run right to
 * left with the kernel mirrored.
 *
 * Number format: an error is rounded to whole quarter levels (|e| <= 512:
 * in exact arithmetic an error never exceeds 127.5 levels when the
 * kernel's weights sum to at most 1, since an incoming error is a mean of
 * earlier ones and a value beyond the midpoint is quantised towards it;
 * it is saturated at 128 levels all the same).  An error-row entry holds
 * the exact sum of the shares e * weight it has received, in 1/(4 divisor)
 * levels: |entry| <= 512 divisor <= 24576, so int16_t storage; a pixel's
 * value 4 divisor level + entry is computed in int32_t.  So the shares of
 * a pixel add up exactly to its (rounded) error: rounding loses at most
 * 1/8 level per pixel, and no division is made per share.
 */
#ifndef STIPPLE_DIFFUSE_H
#define STIPPLE_DIFFUSE_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The kernels (weights of the right and lower neighbours):
 *   FLOYD_STEINBERG     7 right; 3 5 1 below; /16
 *   ATKINSON            1 1 right; 1 1 1 below; 1 two below; /8 (6/8 of
 *                       the error spreads: highlights and shadows clip)
 *   SIERRA_LITE         2 right; 1 1 below-left, below; /4
 *   JARVIS_JUDICE_NINKE 7 5; 3 5 7 5 3; 1 3 5 3 1; /48
 *   STUCKI              8 4; 2 4 8 4 2; 1 2 4 2 1; /42
 *   BURKES              8 4; 2 4 8 4 2; /32 */
typedef enum stp_diffusion_kernel {
    STP_DIFFUSE_FLOYD_STEINBERG = 0,
    STP_DIFFUSE_ATKINSON = 1,
    STP_DIFFUSE_SIERRA_LITE = 2,
    STP_DIFFUSE_JARVIS_JUDICE_NINKE = 3,
    STP_DIFFUSE_STUCKI = 4,
    STP_DIFFUSE_BURKES = 5
} stp_diffusion_kernel;

#define STP_DIFFUSE_KERNELS 6

/* An error diffusion: the kernel, the scan order and the caller's error
 * rows (stp_diffusion_error_count(kernel, width) entries, contents
 * undefined between frames: row 0 clears them). */
typedef struct stp_diffusion {
    uint8_t kernel;      /* stp_diffusion_kernel */
    uint8_t serpentine;  /* 1: odd rows right to left */
    int16_t *errors;
    size_t error_count;
} stp_diffusion;

/* Error entries (int16_t) a kernel needs for rows of width pixels: one row
 * per row the kernel reaches (2 or 3) of width + 4 entries.  0 for an
 * unknown kernel or a width outside 1..32767. */
size_t stp_diffusion_error_count(int kernel, uint32_t width);

/* Check a diffusion for rows of width pixels: STP_OK (0), -1 (STP_ERR_ARG)
 * for an unknown kernel or NULL rows, -7 (STP_ERR_MEMORY) when error_count
 * is below stp_diffusion_error_count. */
int stp_diffusion_check(const stp_diffusion *d, uint32_t width);

/* Diffuse row y (rows must come in order 0, 1, 2, ... of one picture; row 0
 * clears the error rows) in place: on entry pixels[0..width-1] hold the
 * row's 8-bit drive levels, on return pixels[0..(width+7)/8-1] hold the
 * 1-bit row, most significant bit first, bit 1 = ON, padding bits 0 (the
 * bytes after them are left undefined).  d must have passed
 * stp_diffusion_check for this width. */
void stp_diffuse_row(const stp_diffusion *d, uint8_t *pixels, uint32_t width, uint32_t y);

#ifdef __cplusplus
}
#endif

#endif
