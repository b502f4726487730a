/* SPDX-License-Identifier: MIT */
/* Host side: dithering to a small palette of panel colours (palette.h). */
#include "palette.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct named_palette {
    const char *name, *alias;
    int count;
    uint8_t rgb[16][3];
} named_palette;

static const named_palette named[] = {
    {"bw", 0, 2, {{0, 0, 0}, {255, 255, 255}}},
    {"bwr", 0, 3, {{0, 0, 0}, {255, 255, 255}, {255, 0, 0}}},
    {"grey4", "gray4", 4, {{0, 0, 0}, {85, 85, 85}, {170, 170, 170}, {255, 255, 255}}},
    {"grey16", "gray16", 16, {{0, 0, 0}, {0}}}, /* filled in: 17 k */
    {"rgb8", 0, 8, {{0, 0, 0}, {0, 0, 255}, {0, 255, 0}, {0, 255, 255},
                    {255, 0, 0}, {255, 0, 255}, {255, 255, 0}, {255, 255, 255}}},
};

static const named_palette *find_named(const char *name)
{
    size_t i;
    for (i = 0; i < sizeof named / sizeof named[0]; i++)
        if (!strcmp(name, named[i].name) || (named[i].alias && !strcmp(name, named[i].alias)))
            return &named[i];
    return 0;
}

int stp_palette_is_name(const char *name)
{
    return find_named(name) != 0;
}

static void finish(stp_palette *p)
{
    int i;
    p->grey = 1;
    for (i = 0; i < p->count; i++)
        if (p->rgb[i][0] != p->rgb[i][1] || p->rgb[i][1] != p->rgb[i][2])
            p->grey = 0;
}

static int load_file(const char *path, stp_palette *p, char *err, size_t err_size)
{
    FILE *f = fopen(path, "r");
    char line[512];
    int line_no = 0;
    if (!f) {
        snprintf(err, err_size, "%s: cannot open palette: %s (built-in palettes: bw, bwr, grey4, "
                                "grey16, rgb8)", path, strerror(errno));
        return -1;
    }
    p->count = 0;
    while (fgets(line, sizeof line, f)) {
        const char *s = line;
        long v[3];
        int k;
        line_no++;
        while (*s == ' ' || *s == '\t')
            s++;
        if (*s == '#' || *s == '\n' || *s == '\r' || *s == '\0')
            continue;
        for (k = 0; k < 3; k++) {
            char *end;
            errno = 0;
            v[k] = strtol(s, &end, 10);
            if (end == s || errno || v[k] < 0 || v[k] > 255 ||
                (*end != ' ' && *end != '\t' && *end != '\n' && *end != '\r' && *end != '\0')) {
                snprintf(err, err_size, "%s:%d: expected three codes 0..255 (R G B)", path, line_no);
                fclose(f);
                return -1;
            }
            s = end;
        }
        if (p->count == STP_PALETTE_MAX) {
            snprintf(err, err_size, "%s:%d: more than %d colours", path, line_no, STP_PALETTE_MAX);
            fclose(f);
            return -1;
        }
        for (k = 0; k < 3; k++)
            p->rgb[p->count][k] = (uint8_t)v[k];
        p->count++;
    }
    fclose(f);
    if (p->count < 2) {
        snprintf(err, err_size, "%s: a palette needs at least 2 colours (it has %d)", path, p->count);
        return -1;
    }
    return 0;
}

int stp_palette_load(const char *spec, stp_palette *p, char *err, size_t err_size)
{
    const named_palette *n = find_named(spec);
    memset(p, 0, sizeof *p);
    if (n) {
        int i;
        p->count = n->count;
        for (i = 0; i < n->count; i++) {
            int k;
            for (k = 0; k < 3; k++)
                p->rgb[i][k] = n->count == 16 ? (uint8_t)(17 * i) : n->rgb[i][k];
        }
        p->bwr = !strcmp(n->name, "bwr");
    } else if (load_file(spec, p, err, err_size) != 0) {
        return -1;
    }
    finish(p);
    return 0;
}

double stp_palette_value(int code, int linear)
{
    double e = code / 255.0;
    if (!linear)
        return e;
    return e <= 0.04045 ? e / 12.92 : pow((e + 0.055) / 1.055, 2.4);
}

int stp_palette_nearest(const stp_palette *p, int linear, const double rgb[3])
{
    int i, best = 0;
    double best_d = 0;
    for (i = 0; i < p->count; i++) {
        double d = 0;
        int k;
        for (k = 0; k < 3; k++) {
            double t = stp_palette_value(p->rgb[i][k], linear) - rgb[k];
            d += t * t;
        }
        if (i == 0 || d < best_d) {
            best = i;
            best_d = d;
        }
    }
    return best;
}

/* The distinct values a channel takes in the palette, ascending. */
static int channel_levels(const stp_palette *p, int linear, int channel, double *levels)
{
    int i, n = 0;
    for (i = 0; i < p->count; i++) {
        double v = stp_palette_value(p->rgb[i][channel], linear);
        int j, k;
        for (j = 0; j < n && levels[j] < v; j++)
            ;
        if (j < n && levels[j] == v)
            continue;
        for (k = n; k > j; k--)
            levels[k] = levels[k - 1];
        levels[j] = v;
        n++;
    }
    return n;
}

/* Ordered: one channel's value between its neighbouring palette levels. */
static double ordered_channel(const double *levels, int n, double v, const stp_cell *cell, uint32_t x,
                              uint32_t y)
{
    int j;
    double lo, hi, f;
    if (v <= levels[0])
        return levels[0];
    if (v >= levels[n - 1])
        return levels[n - 1];
    for (j = 1; j < n - 1 && levels[j] < v; j++)
        ;
    lo = levels[j - 1];
    hi = levels[j];
    f = (v - lo) / (hi - lo);
    return stp_cell_on(cell, x, y, (uint8_t)lround(255.0 * f)) ? hi : lo;
}

/* A kernel's shares: (dx, dy, weight); dx mirrored on right-to-left rows. */
typedef struct tap {
    int dx, dy, w;
} tap;

typedef struct kernel {
    int taps, divisor;
    tap t[12];
} kernel;

static const kernel kernels[STP_DIFFUSE_KERNELS] = {
    /* Floyd-Steinberg */
    {4, 16, {{1, 0, 7}, {-1, 1, 3}, {0, 1, 5}, {1, 1, 1}}},
    /* Atkinson: 6/8 of the error */
    {6, 8, {{1, 0, 1}, {2, 0, 1}, {-1, 1, 1}, {0, 1, 1}, {1, 1, 1}, {0, 2, 1}}},
    /* Sierra-Lite */
    {3, 4, {{1, 0, 2}, {-1, 1, 1}, {0, 1, 1}}},
    /* Jarvis-Judice-Ninke */
    {12, 48, {{1, 0, 7}, {2, 0, 5}, {-2, 1, 3}, {-1, 1, 5}, {0, 1, 7}, {1, 1, 5}, {2, 1, 3},
              {-2, 2, 1}, {-1, 2, 3}, {0, 2, 5}, {1, 2, 3}, {2, 2, 1}}},
    /* Stucki */
    {12, 42, {{1, 0, 8}, {2, 0, 4}, {-2, 1, 2}, {-1, 1, 4}, {0, 1, 8}, {1, 1, 4}, {2, 1, 2},
              {-2, 2, 1}, {-1, 2, 2}, {0, 2, 4}, {1, 2, 2}, {2, 2, 1}}},
    /* Burkes */
    {7, 32, {{1, 0, 8}, {2, 0, 4}, {-2, 1, 2}, {-1, 1, 4}, {0, 1, 8}, {1, 1, 4}, {2, 1, 2}}},
};

/* The working value of channel k of pixel i. */
static double pixel_value(const uint8_t *pixels, int channels, size_t i, int k, const double *decode)
{
    return decode[pixels[i * (size_t)channels + (channels == 3 ? (size_t)k : 0u)]];
}

static int dither_ordered(const stp_palette *p, const stp_palette_method *m, const uint8_t *pixels,
                          int channels, uint32_t width, uint32_t height, uint8_t *index,
                          const double *decode)
{
    double levels[3][STP_PALETTE_MAX];
    int n[3], k;
    uint32_t x, y;
    if (!m->cell || m->cell->width == 0 || m->cell->height == 0)
        return -1;
    for (k = 0; k < 3; k++)
        n[k] = channel_levels(p, m->linear, k, levels[k]);
    for (y = 0; y < height; y++)
        for (x = 0; x < width; x++) {
            size_t i = (size_t)y * width + x;
            double c[3];
            for (k = 0; k < 3; k++)
                c[k] = ordered_channel(levels[k], n[k], pixel_value(pixels, channels, i, k, decode),
                                       m->cell, x, y);
            index[i] = (uint8_t)stp_palette_nearest(p, m->linear, c);
        }
    return 0;
}

static int dither_diffused(const stp_palette *p, const stp_palette_method *m, const uint8_t *pixels,
                           int channels, uint32_t width, uint32_t height, uint8_t *index,
                           const double *decode)
{
    const kernel *kn;
    size_t row = (size_t)width + 4; /* 2 pixels of padding each side */
    double *err;                     /* 3 rows (y, y+1, y+2) x row x 3 channels */
    uint32_t y;
    if (m->kernel < 0 || m->kernel >= STP_DIFFUSE_KERNELS)
        return -1;
    kn = &kernels[m->kernel];
    err = calloc(3 * row * 3, sizeof *err);
    if (!err)
        return -1;
    for (y = 0; y < height; y++) {
        int backwards = m->serpentine && (y & 1u);
        uint32_t step;
        for (step = 0; step < width; step++) {
            uint32_t x = backwards ? width - 1 - step : step;
            size_t i = (size_t)y * width + x;
            double want[3];
            int k, e, t;
            for (k = 0; k < 3; k++) {
                double v = pixel_value(pixels, channels, i, k, decode) + err[((size_t)x + 2) * 3 + (size_t)k];
                want[k] = v < 0 ? 0 : (v > 1 ? 1 : v);
            }
            e = stp_palette_nearest(p, m->linear, want);
            index[i] = (uint8_t)e;
            for (k = 0; k < 3; k++) {
                double q = want[k] - stp_palette_value(p->rgb[e][k], m->linear);
                for (t = 0; t < kn->taps; t++) {
                    long tx = (long)x + (backwards ? -kn->t[t].dx : kn->t[t].dx);
                    if (tx < 0 || tx >= (long)width)
                        continue; /* shares past the edges are dropped */
                    err[((size_t)kn->t[t].dy * row + (size_t)tx + 2) * 3 + (size_t)k] +=
                        q * kn->t[t].w / kn->divisor;
                }
            }
        }
        /* the rows move up one: y+1 becomes y */
        memmove(err, err + row * 3, 2 * row * 3 * sizeof *err);
        memset(err + 2 * row * 3, 0, row * 3 * sizeof *err);
    }
    free(err);
    return 0;
}

int stp_palette_dither(const stp_palette *p, const stp_palette_method *m, const uint8_t *pixels,
                       int channels, uint32_t width, uint32_t height, uint8_t *index)
{
    double decode[256];
    int c;
    if (!p || !m || !pixels || !index || (channels != 1 && channels != 3) || p->count < 2)
        return -1;
    for (c = 0; c < 256; c++)
        decode[c] = stp_palette_value(c, m->linear);
    if (m->diffuse)
        return dither_diffused(p, m, pixels, channels, width, height, index, decode);
    return dither_ordered(p, m, pixels, channels, width, height, index, decode);
}

void stp_palette_bwr_planes(const uint8_t *index, uint32_t width, uint32_t height, uint8_t *bw,
                            uint8_t *red)
{
    size_t stride = ((size_t)width + 7) / 8;
    uint32_t x, y;
    memset(bw, 0xFF, stride * height);
    memset(red, 0, stride * height);
    for (y = 0; y < height; y++)
        for (x = 0; x < width; x++) {
            uint8_t bit = (uint8_t)(0x80u >> (x & 7u));
            size_t b = (size_t)y * stride + x / 8;
            uint8_t e = index[(size_t)y * width + x];
            if (e == 0)
                bw[b] = (uint8_t)(bw[b] & ~bit);
            else if (e == 2)
                red[b] = (uint8_t)(red[b] | bit);
        }
}
