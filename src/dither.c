/* SPDX-License-Identifier: MIT */
/* Halftone cells and HALFTONE-FILLIN: see include/stipple/dither.h. */
#include "stipple/dither.h"
#include "dither_private.h"

#define F STP_FIX_FRAC_BITS

static void cell_clear(stp_cell *cell)
{
    int i;
    cell->kind = STP_CELL_THRESHOLD;
    cell->width = cell->height = 1;
    for (i = 0; i < STP_CELL_MAX * STP_CELL_MAX; i++)
        cell->thresholds[i] = 0;
    for (i = 0; i < 5; i++)
        cell->patterns[i] = 0;
    cell->mask = 0;
}

/* The entry y n + x of rank r (0..n*n-1) in the Bayer matrix of side n,
 * in the orientation of ImageMagick's maps: the recursive construction
 * B(2n)[y][x] = 4 B(n)[y mod n][x mod n] + B(2)[y div n][x div n], except that
 * the 8x8 map is that construction transposed.  Each 2x2 split
 * contributes its quadrant's B(2) value, weighted 1, 4, 16, ... from the
 * coarsest split to the finest, so r's base-4 digits, the most
 * significant (at top_shift, 2 log2(n) - 2) first, give the quadrants
 * from the finest split (bit 0 of x and y) up; B(2) = {{0, 2}, {3, 1}}
 * puts value v at x = bit 0 of v ^ (v >> 1), y = bit 0 of v.  (Sizes are
 * powers of two: no division, a library call on cores without a divide.) */
static uint32_t bayer_entry(uint32_t n, uint32_t top_shift, uint32_t r)
{
    uint32_t x = 0, y = 0, half, shift = top_shift, v;
    for (half = 1; half < n; half <<= 1, shift -= 2) {
        v = (r >> shift) & 3u;
        x |= ((v ^ (v >> 1)) & 1u) * half;
        y |= (v & 1u) * half;
    }
    return n == 8 ? x * n + y : y * n + x;
}

/* Threshold of rank r out of m for a spacing, 0..255. */
static uint8_t spaced_threshold(uint32_t r, uint32_t m, stp_spacing spacing)
{
    stp_fix frac;
    int64_t v;
    switch (spacing) {
    case STP_SPACING_EXPONENTIAL:
        /* 2^(-5 (m - r) / (m + 1)) */
        frac = stp_fix_exp2(stp_fix_from_ratio(-5 * (int32_t)(m - r), (int32_t)(m + 1)));
        v = ((int64_t)frac * 255 + STP_FIX_HALF) >> F;
        break;
    case STP_SPACING_CUBIC: {
        /* ((r+1)/(m+1))^3 exactly in integers */
        int64_t a = (int64_t)(r + 1), b = (int64_t)(m + 1);
        v = (255 * a * a * a + (b * b * b) / 2) / (b * b * b);
        break;
    }
    case STP_SPACING_LINEAR:
    default:
        /* ceil(255 (r+1) / (m+1)) - 1: ON iff v (m+1) >= 255 (r+1), the
         * comparison ImageMagick makes with its 8-bit input (r < m <= 256:
         * the numerator below 2^17, a 32-bit division) */
        v = (int64_t)((255u * (r + 1u) + m) / (m + 1u)) - 1;
        break;
    }
    return (uint8_t)(v < 0 ? 0 : (v > 255 ? 255 : v));
}

int stp_cell_bayer_spaced(stp_cell *cell, int n, stp_spacing spacing)
{
    uint32_t r, m, d, q, rem, q_step, rem_step, top_shift = 0, half;
    if (cell == 0 || (n != 2 && n != 4 && n != 8 && n != 16))
        return -1;
    cell_clear(cell);
    cell->width = cell->height = (uint8_t)n;
    m = (uint32_t)(n * n);
    for (half = 2; half < (uint32_t)n; half <<= 1)
        top_shift += 2;
    if (spacing != STP_SPACING_LINEAR) {
        for (r = 0; r < m; r++)
            cell->thresholds[bayer_entry((uint32_t)n, top_shift, r)] = spaced_threshold(r, m, spacing);
        return 0;
    }
    /* linear thresholds stepped rank by rank, not divided: the quotient
     * and remainder of (255 (r + 1) + m) / (m + 1) (spaced_threshold) grow
     * by those of 255 / (m + 1) a rank, the remainder carrying at most once */
    d = m + 1u;
    q = (255u + m) / d;
    rem = (255u + m) % d;
    q_step = 255u / d;
    rem_step = 255u % d;
    for (r = 0; r < m; r++) {
        cell->thresholds[bayer_entry((uint32_t)n, top_shift, r)] = (uint8_t)(q - 1u);
        q += q_step;
        rem += rem_step;
        if (rem >= d) {
            rem -= d;
            q++;
        }
    }
    return 0;
}

int stp_cell_bayer(stp_cell *cell, int n)
{
    return stp_cell_bayer_spaced(cell, n, STP_SPACING_LINEAR);
}

#if !defined(__AVR__)
/* stp_cell_bayer(cell, 4)'s thresholds (linear spacing: 15 r + 14 for
 * rank r), row-major; test_dither checks them equal. */
static const uint8_t bayer4_linear[16] = {14, 134, 44, 164, 194, 74, 224, 104, 59, 179, 29, 149, 239, 119, 209, 89};
#endif

void stp_cell_default(stp_cell *cell)
{
#if defined(__AVR__)
    /* there a const table is in program memory, which the cell's plain
     * reads do not see: the cell made as stp_cell_bayer makes it */
    (void)stp_cell_bayer(cell, 4);
#else
    /* a mask cell on the constant table: nothing made, the 256 threshold
     * bytes left unwritten (stp_cell_table reads the mask) */
    int i;
    cell->kind = STP_CELL_THRESHOLD;
    cell->width = cell->height = 4;
    for (i = 0; i < 5; i++)
        cell->patterns[i] = 0;
    cell->mask = bayer4_linear;
#endif
}

void stp_cell_seed2x2(stp_cell *cell)
{
    cell_clear(cell);
    cell->width = cell->height = 2;
    cell->thresholds[0] = 200; /* upper left: last to turn on */
    cell->thresholds[1] = 100;
    cell->thresholds[2] = 150;
    cell->thresholds[3] = 50; /* lower right: first */
}

int stp_cell_user(stp_cell *cell, int width, int height, const uint8_t *thresholds)
{
    int i;
    if (cell == 0 || thresholds == 0 || width < 1 || height < 1 || width > STP_CELL_MAX ||
        height > STP_CELL_MAX)
        return -1;
    cell_clear(cell);
    cell->width = (uint8_t)width;
    cell->height = (uint8_t)height;
    for (i = 0; i < width * height; i++)
        cell->thresholds[i] = thresholds[i];
    return 0;
}

void stp_cell_blue_noise(stp_cell *cell)
{
    (void)stp_cell_mask(cell, 64, 64, stp_cell_blue_noise_64);
}

int stp_cell_mask(stp_cell *cell, int width, int height, const uint8_t *thresholds)
{
    if (cell == 0 || thresholds == 0 || width < 1 || height < 1 || width > 255 || height > 255)
        return -1;
    cell_clear(cell);
    cell->width = (uint8_t)width;
    cell->height = (uint8_t)height;
    cell->mask = thresholds;
    return 0;
}

/* Squared distance, in half pixels, from pixel (x, y)'s centre to the
 * nearest of the points (cx + i n/2... ) given as centres in half pixels of
 * a lattice repeating every n pixels: the smallest over the wrapped
 * offsets.  centres: count (x, y) pairs in half pixels. */
static int32_t nearest_squared(int x, int y, int n, const int *centres, int count)
{
    int32_t best = -1;
    int i;
    for (i = 0; i < count; i++) {
        int32_t dx = (int32_t)(2 * x + 1 - centres[2 * i]), dy = (int32_t)(2 * y + 1 - centres[2 * i + 1]);
        int32_t d;
        /* wrap into [-n, n] half pixels */
        dx = (dx % (2 * n) + 2 * n) % (2 * n);
        dy = (dy % (2 * n) + 2 * n) % (2 * n);
        if (dx > n)
            dx = 2 * n - dx;
        if (dy > n)
            dy = 2 * n - dy;
        d = dx * dx + dy * dy;
        if (best < 0 || d < best)
            best = d;
    }
    return best;
}

/* Growth key of a pixel: dot side (nearer a dot centre than a hole centre)
 * by distance from the dot, then the hole side by distance from the hole
 * downwards.  Distances are below 4 n^2 <= 1024 half pixels squared. */
static int32_t clustered_key(int x, int y, int n, const int *dots, const int *holes, int count)
{
    int32_t d = nearest_squared(x, y, n, dots, count), h = nearest_squared(x, y, n, holes, count);
    return d <= h ? d : 4096 - h;
}

int stp_cell_clustered(stp_cell *cell, int n, int angle)
{
    /* centres in half pixels: 0 degrees, the dot in the middle of the cell
     * and the hole at its corner; 45 degrees, dots at the corner and the
     * middle, holes at the middles of the edges */
    int dots[4], holes[4], count, x, y, qx, qy;
    if (cell == 0 || n < 2 || n > STP_CELL_MAX || (angle != 0 && angle != 45) ||
        (angle == 45 && (n < 4 || n % 2 != 0)))
        return -1;
    if (angle == 0) {
        count = 1;
        dots[0] = dots[1] = n;
        holes[0] = holes[1] = 0;
    } else {
        count = 2;
        dots[0] = dots[1] = 0;
        dots[2] = dots[3] = n;
        holes[0] = n;
        holes[1] = 0;
        holes[2] = 0;
        holes[3] = n;
    }
    cell_clear(cell);
    cell->width = cell->height = (uint8_t)n;
    /* rank = the number of pixels that grow before this one */
    for (y = 0; y < n; y++)
        for (x = 0; x < n; x++) {
            int32_t key = clustered_key(x, y, n, dots, holes, count);
            uint32_t rank = 0;
            for (qy = 0; qy < n; qy++)
                for (qx = 0; qx < n; qx++) {
                    int32_t k = clustered_key(qx, qy, n, dots, holes, count);
                    if (k < key || (k == key && qy * n + qx < y * n + x))
                        rank++;
                }
            cell->thresholds[y * n + x] =
                spaced_threshold(rank, (uint32_t)(n * n), STP_SPACING_LINEAR);
        }
    return 0;
}

void stp_cell_pattern2x2(stp_cell *cell)
{
    /* bits: (y*2 + x); order lower-right (3), upper-left (0), upper-right (1),
     * lower-left (2) */
    cell_clear(cell);
    cell->kind = STP_CELL_PATTERN;
    cell->width = cell->height = 2;
    cell->patterns[0] = 0x0;
    cell->patterns[1] = 0x8;
    cell->patterns[2] = 0x9;
    cell->patterns[3] = 0xB;
    cell->patterns[4] = 0xF;
}

uint8_t stp_halftone_pattern_byte(const stp_cell *cell, uint32_t y, uint8_t intensity)
{
    /* the cell's width divides 8: the row's w thresholds give the first w
     * bits, which repeat across the byte */
    uint32_t w = cell->width, h = cell->height, b, s;
    /* a mask rather than a division for the usual power-of-two heights */
    const uint8_t *cell_row = &stp_cell_table(cell)[((h & (h - 1u)) == 0 ? y & (h - 1u) : y % h) * w];
    uint32_t pattern = 0;
    if (w == 4) { /* Bayer 4x4 and the other 4-wide cells: no loop, no branch */
        pattern = (uint32_t)(intensity > cell_row[0]) << 7 | (uint32_t)(intensity > cell_row[1]) << 6 |
                  (uint32_t)(intensity > cell_row[2]) << 5 | (uint32_t)(intensity > cell_row[3]) << 4;
        return (uint8_t)(pattern | pattern >> 4);
    }
    for (b = 0; b < w; b++)
        if (intensity > cell_row[b])
            pattern |= 0x80u >> b;
    for (s = w; s < 8; s *= 2)
        pattern |= pattern >> s;
    return (uint8_t)pattern;
}

void stp_halftone_fillin_line(uint8_t *line, uint8_t page_bit, uint32_t x1, uint32_t x2, uint32_t y,
                              const stp_cell *cell, uint8_t intensity)
{
    uint32_t w = cell->width, hx, x;
    const uint8_t *cell_row;
    if (cell->kind != STP_CELL_PATTERN && (w & (w - 1u)) == 0 && w <= 8u) { /* w divides 8, no division */
        /* The cell's width divides 8, so every byte of the row sees the same
         * cell columns at the same bits: one pattern byte fills the span. */
        stp_halftone_fill_bits(line, page_bit, (unsigned)x1, (unsigned)x2,
                               stp_halftone_pattern_byte(cell, y, intensity));
        return;
    }
    if (cell->kind == STP_CELL_PATTERN) {
        for (x = x1; x <= x2; x++)
            stp_mono_put(line, page_bit, x, stp_cell_on(cell, x, y, intensity));
        return;
    }
    /* The cell row is resolved once per span; hx steps and wraps as in the
     * seed's listing, so the inner loop is a compare and a bit write. */
    hx = x1 % w;
    cell_row = &stp_cell_table(cell)[(y % cell->height) * w];
    for (x = x1; x <= x2; x++) {
        stp_mono_put(line, page_bit, x, intensity > cell_row[hx]);
        if (++hx == w)
            hx = 0;
    }
}

void stp_halftone_fillin(uint8_t *row, uint32_t x1, uint32_t x2, uint32_t y,
                         const stp_cell *cell, uint8_t intensity)
{
    stp_halftone_fillin_line(row, 0, x1, x2, y, cell, intensity);
}

void stp_halftone_row(uint8_t *out, const uint8_t *grey, uint32_t width, uint32_t y,
                      const stp_cell *cell)
{
    uint32_t x;
    for (x = 0; x < width; x++) {
        uint8_t bit = (uint8_t)(0x80u >> (x & 7u));
        if (stp_cell_on(cell, x, y, grey[x]))
            out[x >> 3] = (uint8_t)(out[x >> 3] | bit);
        else
            out[x >> 3] = (uint8_t)(out[x >> 3] & ~bit);
    }
}
