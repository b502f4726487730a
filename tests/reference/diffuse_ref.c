/* SPDX-License-Identifier: MIT */
/* Double-precision dithering references: see diffuse_ref.h. */
#include "diffuse_ref.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The kernels as published (Floyd & Steinberg 1976; Atkinson's MacPaint
 * kernel; Frankie Sierra's "lite"; Jarvis, Judice & Ninke 1976; Stucki
 * 1981; Burkes 1988): weight of (dx, dy) over a divisor. */
typedef struct tap {
    int dx, dy, weight;
} tap;
typedef struct kernel_def {
    int divisor, count;
    tap taps[12];
} kernel_def;

/* Floyd-Steinberg's weights, over 16, for pixels whose band weight (below)
 * is above 0 when a mask is given: 5 right; 2 6 3 below. */
static const tap fs_band[4] = {{1, 0, 5}, {-1, 1, 2}, {0, 1, 6}, {1, 1, 3}};

static const kernel_def kernels[REF_KERNEL_COUNT] = {
    {16, 4, {{1, 0, 7}, {-1, 1, 3}, {0, 1, 5}, {1, 1, 1}}},
    {8, 6, {{1, 0, 1}, {2, 0, 1}, {-1, 1, 1}, {0, 1, 1}, {1, 1, 1}, {0, 2, 1}}},
    {4, 3, {{1, 0, 2}, {-1, 1, 1}, {0, 1, 1}}},
    {48, 12, {{1, 0, 7}, {2, 0, 5}, {-2, 1, 3}, {-1, 1, 5}, {0, 1, 7}, {1, 1, 5}, {2, 1, 3},
              {-2, 2, 1}, {-1, 2, 3}, {0, 2, 5}, {1, 2, 3}, {2, 2, 1}}},
    {42, 12, {{1, 0, 8}, {2, 0, 4}, {-2, 1, 2}, {-1, 1, 4}, {0, 1, 8}, {1, 1, 4}, {2, 1, 2},
              {-2, 2, 1}, {-1, 2, 2}, {0, 2, 4}, {1, 2, 2}, {2, 2, 1}}},
    {32, 7, {{1, 0, 8}, {2, 0, 4}, {-2, 1, 2}, {-1, 1, 4}, {0, 1, 8}, {1, 1, 4}, {2, 1, 2}}},
};

void ref_diffuse(const double *grey, int w, int h, ref_kernel kernel, int serpentine,
                 unsigned char *bits)
{
    ref_diffuse_noise(grey, w, h, kernel, serpentine, 0, 0, 0, bits);
}

/* The share 0..1 of the modulation at 8-bit level p: 1 within band levels
 * of 127.5, falling to 0 over the next 4. */
static double band_weight(double p, int band)
{
    double w = (2.0 * band + 8.0 - fabs(2.0 * p - 255.0)) / 8.0;
    return w < 0 ? 0 : (w > 1 ? 1 : w);
}

void ref_diffuse_noise(const double *grey, int w, int h, ref_kernel kernel, int serpentine,
                       const unsigned char *mask, double amplitude, int band, unsigned char *bits)
{
    const kernel_def *k = &kernels[kernel];
    double *v = malloc(sizeof *v * (size_t)w * (size_t)h);
    int x, y, i;
    if (!v)
        abort();
    memcpy(v, grey, sizeof *v * (size_t)w * (size_t)h);
    for (y = 0; y < h; y++) {
        int backwards = serpentine && (y & 1), dir = backwards ? -1 : 1;
        for (i = 0; i < w; i++) {
            double e, share = 0, threshold = 0.5;
            const tap *taps;
            int t;
            x = backwards ? w - 1 - i : i;
            if (mask) {
                share = band_weight(floor(grey[y * w + x] * 255.0 + 0.5), band);
                threshold += (mask[(y % 64) * 64 + x % 64] - 127.5) * amplitude / (256.0 * 255.0) * share;
            }
            taps = share > 0 && kernel == REF_FLOYD_STEINBERG ? fs_band : k->taps;
            bits[y * w + x] = (unsigned char)(v[y * w + x] >= threshold);
            e = v[y * w + x] - bits[y * w + x];
            for (t = 0; t < k->count; t++) {
                int tx = x + dir * taps[t].dx, ty = y + taps[t].dy;
                if (tx >= 0 && tx < w && ty < h)
                    v[ty * w + tx] += e * taps[t].weight / k->divisor;
            }
        }
    }
    free(v);
}

void ref_ordered(const double *grey, int w, int h, const unsigned char *t, int tw, int th,
                 unsigned char *bits)
{
    int x, y;
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++)
            bits[y * w + x] = (unsigned char)(255.0 * grey[y * w + x] > t[(y % th) * tw + x % tw]);
}
