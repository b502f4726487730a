/* SPDX-License-Identifier: MIT */
/* Error diffusion of grey rows: see include/stipple/diffuse.h. */
#include "stipple/diffuse.h"
#include "stipple/render.h"

#define ERR_BITS 6
#define LEVEL_ONE ((int32_t)255 << ERR_BITS) /* an ON pixel: 16320 */
#define MIDPOINT ((int32_t)255 << (ERR_BITS - 1)) /* 127.5 levels: 8160 */
#define ERR_LIMIT ((int32_t)128 << ERR_BITS) /* saturation of an error */
#define MARGIN 2 /* entries left and right of a row for shares past an edge */

typedef struct tap {
    int8_t dx, dy;
    uint8_t weight;
} tap;

typedef struct kernel_def {
    uint8_t divisor, rows, count;
    tap taps[12];
} kernel_def;

/* Taps in order of their cumulative share (any order works; this one is
 * the reading order). */
static const kernel_def kernels[STP_DIFFUSE_KERNELS] = {
    {16, 2, 4, {{1, 0, 7}, {-1, 1, 3}, {0, 1, 5}, {1, 1, 1}}},
    {8, 3, 6, {{1, 0, 1}, {2, 0, 1}, {-1, 1, 1}, {0, 1, 1}, {1, 1, 1}, {0, 2, 1}}},
    {4, 2, 3, {{1, 0, 2}, {-1, 1, 1}, {0, 1, 1}}},
    {48, 3, 12, {{1, 0, 7}, {2, 0, 5}, {-2, 1, 3}, {-1, 1, 5}, {0, 1, 7}, {1, 1, 5}, {2, 1, 3},
                 {-2, 2, 1}, {-1, 2, 3}, {0, 2, 5}, {1, 2, 3}, {2, 2, 1}}},
    {42, 3, 12, {{1, 0, 8}, {2, 0, 4}, {-2, 1, 2}, {-1, 1, 4}, {0, 1, 8}, {1, 1, 4}, {2, 1, 2},
                 {-2, 2, 1}, {-1, 2, 2}, {0, 2, 4}, {1, 2, 2}, {2, 2, 1}}},
    {32, 2, 7, {{1, 0, 8}, {2, 0, 4}, {-2, 1, 2}, {-1, 1, 4}, {0, 1, 8}, {1, 1, 4}, {2, 1, 2}}},
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

/* n / d rounded half away from zero (d > 0). */
static int32_t round_div(int32_t n, int32_t d)
{
    return n >= 0 ? (n + d / 2) / d : -((-n + d / 2) / d);
}

/* Spread error e of pixel x of row y over the kernel's taps: share i is
 * the rounded cumulative share up to tap i minus that up to tap i - 1, so
 * the shares add up to round(e total / divisor). */
static void spread(const kernel_def *k, int16_t *errors, uint32_t span, uint32_t y, uint32_t x,
                   int dir, int32_t e)
{
    int32_t cumulative = 0, given = 0;
    int i;
    for (i = 0; i < k->count; i++) {
        const tap *t = &k->taps[i];
        int16_t *row = errors + ((y + (uint32_t)t->dy) % k->rows) * span;
        int32_t share, sum;
        cumulative += t->weight;
        sum = round_div(e * cumulative, k->divisor);
        share = sum - given;
        given = sum;
        /* x + MARGIN + dir dx stays in 0..span-1 (|dx| <= MARGIN) */
        row[(uint32_t)((int32_t)x + MARGIN + dir * t->dx)] =
            (int16_t)(row[(uint32_t)((int32_t)x + MARGIN + dir * t->dx)] + share);
    }
}

void stp_diffuse_row(const stp_diffusion *d, uint8_t *pixels, uint32_t width, uint32_t y)
{
    const kernel_def *k = &kernels[d->kernel];
    uint32_t span = width + 2u * MARGIN, i;
    int16_t *current = d->errors + (y % k->rows) * span;
    int backwards = d->serpentine && (y & 1u);
    uint8_t byte = 0;
    if (y == 0)
        for (i = 0; i < k->rows * span; i++)
            d->errors[i] = 0;
    for (i = 0; i < width; i++) {
        uint32_t x = backwards ? width - 1u - i : i;
        int32_t v = ((int32_t)pixels[x] << ERR_BITS) + current[x + MARGIN];
        int on = v >= MIDPOINT;
        int32_t e = v - (on ? LEVEL_ONE : 0);
        if (e > ERR_LIMIT)
            e = ERR_LIMIT;
        if (e < -ERR_LIMIT)
            e = -ERR_LIMIT;
        pixels[x] = (uint8_t)on;
        spread(k, d->errors, span, y, x, backwards ? -1 : 1, e);
    }
    /* this row's entries become those of row y + rows */
    for (i = 0; i < span; i++)
        current[i] = 0;
    /* pack in place: byte x/8 is written after pixel x has been read, and
     * x/8 <= x */
    for (i = 0; i < width; i++) {
        if (pixels[i])
            byte = (uint8_t)(byte | (0x80u >> (i & 7u)));
        if ((i & 7u) == 7u || i == width - 1u) {
            pixels[i >> 3] = byte;
            byte = 0;
        }
    }
}
