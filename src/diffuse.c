/* SPDX-License-Identifier: MIT */
/* Error diffusion of grey rows: see include/stipple/diffuse.h. */
#include "stipple/diffuse.h"
#include "stipple/render.h"
#include "diffuse_private.h"
#include "run_fill_private.h" /* stp_mono_page_from_bytes */

#define QUARTERS 4 /* errors are whole quarter levels */
#define ERR_LIMIT (128 * QUARTERS) /* saturation of an error: 128 levels */
#define MARGIN 2 /* entries left and right of a row for shares past an edge */

typedef struct tap {
    int8_t dx, dy;
    uint8_t weight;
} tap;

typedef struct kernel_def {
    uint8_t divisor, rows, count;
    tap taps[12];
    const uint8_t *band; /* NULL, or the taps' weights (same order and
                            divisor) for pixels in the modulation's band */
} kernel_def;

/* Floyd-Steinberg's weights in the band (diffuse.h): 5 right; 2 6 3 below,
 * /16, found by a search over the 969 sets of four sixteenths on flat
 * mid-grey fields: the least error among the sets that drew no worms
 * there (docs/dither.md). */
static const uint8_t fs_band[4] = {5, 2, 6, 3};

static const kernel_def kernels[STP_DIFFUSE_KERNELS] = {
    {16, 2, 4, {{1, 0, 7}, {-1, 1, 3}, {0, 1, 5}, {1, 1, 1}}, fs_band},
    {8, 3, 6, {{1, 0, 1}, {2, 0, 1}, {-1, 1, 1}, {0, 1, 1}, {1, 1, 1}, {0, 2, 1}}, 0},
    {4, 2, 3, {{1, 0, 2}, {-1, 1, 1}, {0, 1, 1}}, 0},
    {48, 3, 12, {{1, 0, 7}, {2, 0, 5}, {-2, 1, 3}, {-1, 1, 5}, {0, 1, 7}, {1, 1, 5}, {2, 1, 3},
                 {-2, 2, 1}, {-1, 2, 3}, {0, 2, 5}, {1, 2, 3}, {2, 2, 1}},
     0},
    {42, 3, 12, {{1, 0, 8}, {2, 0, 4}, {-2, 1, 2}, {-1, 1, 4}, {0, 1, 8}, {1, 1, 4}, {2, 1, 2},
                 {-2, 2, 1}, {-1, 2, 2}, {0, 2, 4}, {1, 2, 2}, {2, 2, 1}},
     0},
    {32, 2, 7, {{1, 0, 8}, {2, 0, 4}, {-2, 1, 2}, {-1, 1, 4}, {0, 1, 8}, {1, 1, 4}, {2, 1, 2}}, 0},
};

size_t stp_diffusion_error_count(int kernel, uint32_t width)
{
    if (kernel < 0 || kernel >= STP_DIFFUSE_KERNELS || width < 1 || width > 32767u)
        return 0;
    return (size_t)kernels[kernel].rows * ((size_t)width + 2u * MARGIN);
}

int stp_diffusion_check(const stp_diffusion *d, uint32_t width)
{
    size_t need;
    if (d == 0 || d->errors == 0 || d->kernel >= STP_DIFFUSE_KERNELS)
        return STP_ERR_ARG;
    need = stp_diffusion_error_count(d->kernel, width);
    if (need == 0)
        return STP_ERR_ARG;
    return d->error_count < need ? STP_ERR_MEMORY : STP_OK;
}

/* The error of value v (in 1/(4 divisor) levels) after quantising it, in
 * quarter levels: (v - output) / divisor rounded half away from zero, the
 * division made as a multiplication by reciprocal = round(2^shift /
 * divisor) (no divider on small cores), shift the largest with reciprocal
 * < 29204: |v - output| <= 1020 divisor + 24576 <= 73536, so the product
 * stays below 2^31; exact for the power-of-two divisors, within 0.05
 * quarter level for 42 and 48.  Saturated at 128 levels. */
static int32_t quantised_error(int32_t v, int on, int32_t divisor, int32_t reciprocal, int shift)
{
    int32_t e = v - (on ? (int32_t)255 * QUARTERS * divisor : 0), half = (int32_t)1 << (shift - 1);
    e = e >= 0 ? (e * reciprocal + half) >> shift : -((-e * reciprocal + half) >> shift);
    if (e > ERR_LIMIT)
        e = ERR_LIMIT;
    if (e < -ERR_LIMIT)
        e = -ERR_LIMIT;
    return e;
}

/* The band's weight w(p) (diffuse.h) of drive level p (0..255) in eighths,
 * 0..8, band2 = 2 band (0..510). */
static int32_t band_share(uint32_t p, int32_t band2)
{
    int32_t distance = (int32_t)(2u * p) - 255, w;
    if (distance < 0)
        distance = -distance;
    w = band2 + 8 - distance;
    return w < 0 ? 0 : (w > 8 ? 8 : w);
}

/* Whether a pixel of value v (in 1/(4 divisor) levels) is ON under mask
 * value m (diffuse.h): its threshold midpoint moves by (2m - 255) scale w
 * / 1024, scale = amplitude divisor <= 12240, w = the band's weight 0..8,
 * exactly in int32_t: |1024 v| < 2^27 (|v| <= 1020 divisor + 24576),
 * |(2m - 255) scale w| <= 255 * 12240 * 8 < 2^25. */
static int modulated_on(int32_t v, int32_t midpoint, int32_t scale, int32_t w, uint32_t m)
{
    return v * 1024 >= midpoint * 1024 + ((int32_t)(2u * m) - 255) * scale * w;
}

/* Pack a row of 0/1 bytes in place, most significant bit first: byte x/8
 * is written after pixel x has been read, and x/8 <= x. */
static void pack_row(uint8_t *pixels, uint32_t width)
{
    uint32_t i;
    uint8_t byte = 0;
    for (i = 0; i < width; i++) {
        if (pixels[i])
            byte = (uint8_t)(byte | (0x80u >> (i & 7u)));
        if ((i & 7u) == 7u || i == width - 1u) {
            pixels[i >> 3] = byte;
            byte = 0;
        }
    }
}

/* Row y diffused in place: each grey pixel becomes 0 (OFF) or 1 (ON). */
static void diffuse_to_bytes(const stp_diffusion *d, uint8_t *pixels, uint32_t width, uint32_t y)
{
    const kernel_def *k = &kernels[d->kernel];
    uint32_t span = width + 2u * MARGIN, i;
    int16_t *rows[3]; /* rows y, y + 1, y + 2 (slots modulo k->rows) */
    int16_t *target[12];
    int32_t weight[12], band_weight[12];
    int32_t divisor = k->divisor, midpoint = (int32_t)255 * (QUARTERS / 2) * divisor;
    /* threshold modulation (diffuse.h): NULL row, or row y mod 64 of the mask */
    const uint8_t *noise_row = d->noise ? d->noise + (y & 63u) * 64u : 0;
    int32_t scale = (int32_t)d->noise_amplitude * divisor, band2 = 2 * (int32_t)d->noise_band;
    int32_t reciprocal;
    int shift = 16;
    int backwards = d->serpentine && (y & 1u), dir = backwards ? -1 : 1, t;
    while ((((int32_t)2 << shift) + divisor / 2) / divisor < 29204)
        shift++;
    reciprocal = (((int32_t)1 << shift) + divisor / 2) / divisor;
    if (y == 0)
        for (i = 0; i < k->rows * span; i++)
            d->errors[i] = 0;
    for (t = 0; t < 3; t++)
        rows[t] = d->errors + ((y + (uint32_t)t) % k->rows) * span + MARGIN;
    /* each tap's entry of pixel x is target[t][x] */
    for (t = 0; t < k->count; t++) {
        target[t] = rows[k->taps[t].dy] + dir * k->taps[t].dx;
        weight[t] = k->taps[t].weight;
        band_weight[t] = k->band ? k->band[t] : k->taps[t].weight;
    }
    /* two loops, so plain diffusion tests no mask per pixel; exact shares
     * e w: the entries hold sums of them, read over divisor above; |entry|
     * <= 512 times the weights reaching it: the divisor (<= 48: 24576), or
     * for Floyd-Steinberg mixing its two sets at most 7 + 3 + 6 + 3 = 19
     * sixteenths (9728) */
    for (i = 0; i < width && !noise_row; i++) {
        uint32_t x = backwards ? width - 1u - i : i;
        int32_t v = (int32_t)pixels[x] * QUARTERS * divisor + rows[0][x];
        int32_t e = quantised_error(v, v >= midpoint, divisor, reciprocal, shift);
        pixels[x] = (uint8_t)(v >= midpoint);
        for (t = 0; t < k->count; t++)
            target[t][x] = (int16_t)(target[t][x] + e * weight[t]);
    }
    for (i = 0; i < width && noise_row; i++) {
        uint32_t x = backwards ? width - 1u - i : i;
        int32_t v = (int32_t)pixels[x] * QUARTERS * divisor + rows[0][x];
        int32_t w = band_share(pixels[x], band2);
        int on = modulated_on(v, midpoint, scale, w, noise_row[x & 63u]);
        int32_t e = quantised_error(v, on, divisor, reciprocal, shift);
        const int32_t *share = w ? band_weight : weight;
        pixels[x] = (uint8_t)on;
        for (t = 0; t < k->count; t++)
            target[t][x] = (int16_t)(target[t][x] + e * share[t]);
    }
    /* this row's entries become those of row y + rows */
    for (i = 0; i < span; i++)
        rows[0][(int32_t)i - MARGIN] = 0;
}

void stp_diffuse_row(const stp_diffusion *d, uint8_t *pixels, uint32_t width, uint32_t y)
{
    diffuse_to_bytes(d, pixels, width, y);
    pack_row(pixels, width);
}

void stp_diffuse_row_page(const stp_diffusion *d, uint8_t *pixels, uint32_t width, uint32_t y, uint8_t *line)
{
    diffuse_to_bytes(d, pixels, width, y);
    stp_mono_page_from_bytes(line, (uint8_t)(1u << (y & 7u)), pixels, width);
}
