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
 * Threshold modulation (noise, noise_amplitude, noise_band): the midpoint
 * 127.5 of pixel (x, y), whose drive level is p, moves by
 *     (mask[(y mod 64) 64 + x mod 64] - 127.5) amplitude / 256 * w(p)
 * levels, mask a 64x64 threshold mask such as stp_cell_blue_noise_64
 * (dither.h), w(p) = clamp((2 band + 8 - |2p - 255|) / 8, 0, 1): 1 for
 * levels within band of mid-grey, 0 from band + 4 levels on (band >= 124:
 * every level).  The error is still v - output, so the mean grey is kept;
 * a blue-noise mask breaks up the regular "worms" plain diffusion draws
 * on flat greys (docs/dither.md).  The comparison is exact in int32_t:
 * 1024 v >= 1024 midpoint + (2 mask - 255) amplitude divisor 8 w(p), both
 * sides below 2^27 in magnitude.
 *
 * With a mask, Floyd-Steinberg also changes its weights for the pixels
 * where w(p) > 0 (levels within band + 4 of 127.5, exclusive): 5 right;
 * 2 below-left, 6 below, 3 below-right; /16.  Near mid-grey, where 7 3 5
 * 1 draws a checkerboard broken by diagonal lines (worms), those weights
 * draw almost none by themselves, so a weak modulation
 * (STP_DIFFUSE_NOISE_AMPLITUDE) is enough to break what is left, and the
 * error stays near plain diffusion's (docs/dither.md).  The shares are
 * still exact (e weight in the entries, over 16).  The other kernels keep
 * their weights.
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

/* An error diffusion: the kernel, the scan order, the caller's error
 * rows (stp_diffusion_error_count(kernel, width) entries, contents
 * undefined between frames: row 0 clears them) and the threshold
 * modulation (the last two members: an initialiser that leaves them out
 * gives plain diffusion). */
typedef struct stp_diffusion {
    uint8_t kernel;      /* stp_diffusion_kernel */
    uint8_t serpentine;  /* 1: odd rows right to left */
    int16_t *errors;
    size_t error_count;
    const uint8_t *noise;    /* NULL: threshold 127.5 everywhere; else a
                                64x64 row-major mask, 0..255, that moves it */
    uint8_t noise_amplitude; /* 0..255: the threshold moves by up to (mask -
                                127.5) amplitude / 256 levels (0: not at all) */
    uint8_t noise_band;      /* 0..255: for drive levels within band of 127.5
                                (tapering over 4 more levels; >= 124: all);
                                Floyd-Steinberg's band weights there too */
} stp_diffusion;

/* The still picture's diffusion (what `stipple render` uses for a 1-bit
 * picture file): Floyd-Steinberg, rows left to right, within this band of
 * mid-grey (levels 82..173) its band weights and thresholds modulated by
 * the blue-noise mask with this amplitude (+-10 levels; docs/dither.md
 * gives the measures that chose them).  The other kernels have no band
 * weights, so their modulation needs the larger amplitude (`-d NAME:blue`);
 * STP_DIFFUSE_NOISE_AMPLITUDE_OF(kernel) picks the one for a kernel. */
#define STP_DIFFUSE_NOISE_AMPLITUDE 20
#define STP_DIFFUSE_NOISE_AMPLITUDE_OTHERS 96
#define STP_DIFFUSE_NOISE_AMPLITUDE_OF(kernel)                                                   \
    ((kernel) == STP_DIFFUSE_FLOYD_STEINBERG ? STP_DIFFUSE_NOISE_AMPLITUDE                        \
                                             : STP_DIFFUSE_NOISE_AMPLITUDE_OTHERS)
#define STP_DIFFUSE_NOISE_BAND 42

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
