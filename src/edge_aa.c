/* SPDX-License-Identifier: MIT */
/* Coverage-weighted shade on polygon edge pixels: see edge_aa_private.h.
 *
 * Fixed-point formats here:
 *   coverage  Q0.8 in 0..256 (256: the whole pixel)
 *   x         crossings and pixel centres in Q27.4 device units (< 2^20)
 *   s, w      |slope| and 1 + |slope| in pixels of x per row, Q8:
 *             s in 0..2^23, w in 256..2^23 + 256
 *   shade     stp_fix in [0, 1]; a blend's difference times a coverage is
 *             below 2^(FRAC_BITS + 1 + 8) <= 2^29: 32 bits. */
#include "edge_aa_private.h"
#include "output_private.h"
#include "edge_walk_private.h"
#include "run_fill_private.h" /* stp_mono_page_from_bytes */

#if STP_WITH_EDGE_AA

#define COVER_ONE 256
#define COVER_HALF 128

/* The edge function at a pixel centre h >= 0 Q4 units from the crossing
 * (horizontally), over the L1 length w (Q8) of the edge normal (1, -s):
 * round(h 2^12 / w), the centre's distance from the edge in units of the
 * pixel's extent along the normal, Q8; 128 (half the extent) or more: the
 * pixel is clear of the edge.  The product h 2^12 is formed only for
 * h < w / 32 + 1 < 2^18 + 9, so below 2^31. */
static int32_t distance(int32_t h, int32_t w)
{
    int32_t q;
    if (h >= (w >> 5) + 1)
        return COVER_HALF;
    q = (int32_t)((h * 4096 + (w >> 1)) / w);
    return q > COVER_HALF ? COVER_HALF : q;
}

/* The area of the pixel on the near side of a line crossing it, t (Q8,
 * 0..128) of its extent along the normal from its corner: the pixel's
 * width across the normal rises over a (the shorter side's share of the
 * extent, Q8 0..128), stays 1/(1 - a) and falls again, so the area is
 * t^2 / (2 a (1 - a)) for t < a, (t - a/2) / (1 - a) after.  Numerators
 * below 2^22, denominators at most 2^16. */
static int32_t area_to(int32_t t, int32_t a)
{
    if (t < a) {
        int32_t den = 2 * a * (COVER_ONE - a);
        return (t * t * COVER_ONE + den / 2) / den;
    }
    return ((2 * t - a) * COVER_HALF + (COVER_ONE - a) / 2) / (COVER_ONE - a);
}

/* a of an edge of slope s (pixels of x per row, Q8) and w = 256 + s:
 * min(1, s) / (1 + s), Q8 */
static int32_t corner_share(int32_t s, int32_t w)
{
    return ((s < COVER_ONE ? s : COVER_ONE) * COVER_ONE + w / 2) / w;
}

/* One crossing as the coverage needs it: x (Q4), w = 1 + |slope| and
 * the corner share a (Q8), and where its edge ends on the side the
 * coverage reaches towards (its vertices' largest x for the right crossing
 * of a span, smallest for the left one). */
typedef struct side {
    int32_t x, w, a, end;
} side;

static void side_of(side *e, const stp_crossing *c, int32_t end)
{
    e->x = c->x;
    e->w = COVER_ONE + c->slope;
    e->a = corner_share(c->slope, e->w);
    e->end = end;
}

/* Coverage (Q8) of a pixel whose centre lies h >= 0 Q4 units outside the
 * edge: the area of the pixel on its inner side, exact for a straight edge
 * through the whole pixel. */
static int32_t outside(int32_t h, const side *e)
{
    int32_t d = distance(h, e->w);
    return d >= COVER_HALF ? 0 : area_to(COVER_HALF - d, e->a);
}

/* ... of a pixel whose centre lies h >= 0 inside it */
static int32_t inside(int32_t h, const side *e)
{
    int32_t d = distance(h, e->w);
    return d >= COVER_HALF ? COVER_ONE : COVER_ONE - area_to(COVER_HALF - d, e->a);
}

/* The first pixel whose centre 16 p + 8 is at or right of x (Q4). */
static int32_t first_centre_at(int32_t x)
{
    return stp_floor16(x - STP_HALF_PIXEL + 15);
}

/* Shade a style index stands for; the shade under a band pixel, read back
 * through the inverse of INTENSITY (the nearest level: gamma table or
 * linear ramp), channel ch of an RGB888 pixel. */
static stp_fix level_shade(const stp_edge_aa *aa, uint8_t level)
{
    int levels = aa->levels, best = 1, i, dbest = 256;
    if (!aa->out->gamma)
        return stp_intensity_shade((int)(((int32_t)level * (levels - 1) + 127) / 255) + 1, levels);
    for (i = 1; i <= levels; i++) {
        int d = aa->out->gamma[i - 1] - level;
        if (d < 0)
            d = -d;
        if (d < dbest) {
            dbest = d;
            best = i;
        }
    }
    return stp_intensity_shade(best, levels);
}

/* s_under + c (s_poly - s_under) / 256, rounded to nearest */
static stp_fix mix(stp_fix under, stp_fix poly, int32_t c)
{
    int32_t d = (int32_t)(poly - under) * c;
    return under + (stp_fix)(d >= 0 ? (d + 128) >> 8 : -((-d + 128) >> 8));
}

/* One pixel x of the row blended towards the polygon by coverage c: its
 * grey shade `shade`, or for a colour style its three channels. */
static void blend_pixel(const stp_edge_aa *aa, uint8_t *row, uint32_t x, int32_t style,
                        stp_fix shade, int32_t c)
{
    int levels = aa->levels;
    switch (aa->format) {
    case STP_PIXEL_GREY8:
        row[x] = stp_output_level(aa->out, levels,
                                  stp_intensity_index(mix(level_shade(aa, row[x]), shade, c), levels));
        break;
    case STP_PIXEL_RGB888: {
        int ch;
        for (ch = 0; ch < 3; ch++) {
            uint8_t *p = &row[3 * x + (uint32_t)ch];
            stp_fix s = shade;
            if (style & STP_COLOUR_FLAG)
                s = stp_intensity_shade((int)((style >> (16 - 8 * ch)) & 0xFF) + 1, levels);
            *p = stp_output_level(aa->out, levels, stp_intensity_index(mix(level_shade(aa, *p), s, c), levels));
        }
        break;
    }
    default: { /* STYLE8 (MONO1 is drawn as GREY8) */
        int under = aa->out->styles ? stp_style_inverse(aa->out->styles, row[x]) : row[x];
        stp_fix s_under = under > 0 ? stp_intensity_shade(under, levels) : 0;
        row[x] = stp_output_style_code(aa->out, levels, stp_intensity_index(mix(s_under, shade, c), levels));
        break;
    }
    }
}

/* Whether the polygon's plane is nearer than the Z entry at pixel x
 * (depths as raster.c: floor of the Q12 plane, clamped to 1..65535). */
static int nearer(const uint16_t *zrow, uint32_t x, int64_t d_row, int64_t ddx)
{
    int64_t d = stp_asr64(d_row + ddx * ((int64_t)x * 16 + STP_HALF_PIXEL), 12);
    uint16_t depth = (uint16_t)(d < 1 ? 1 : (d > 65535 ? 65535 : d));
    return depth > zrow[x];
}

/* What one row's gaps need to know of the polygon. */
typedef struct row_ctx {
    const stp_edge_aa *aa;
    uint8_t *row;
    uint16_t *zrow;
    int64_t d_row, ddx;
    int32_t style;
    int smooth;
    stp_fix flat; /* a flat grey style's shade */
} row_ctx;

/* A span beside a gap: near, the crossing facing the gap; far, its other
 * crossing. */
typedef struct span_side {
    side near, far;
} span_side;

/* The edge ends at a vertex: a pixel whose centre lies h Q4 units short of
 * it (h < 0: past it) is covered by at most the part of it on the near
 * side, clamp(1/2 + h / 16, 0, 1) (the edge's line goes on past its end;
 * the polygon does not). */
static int32_t beyond_end(int32_t h)
{
    if (h <= -STP_HALF_PIXEL)
        return 0;
    if (h >= STP_HALF_PIXEL)
        return COVER_ONE;
    return COVER_HALF + h * 16;
}

/* Coverage of pixel p of a gap by the span on its left (NULL: none): the
 * area inside its near edge less the area outside its far one (a polygon
 * thinner than the pixel: a strip), capped where the near edge ends; 0 or
 * less: none. */
static int32_t from_left(const span_side *l, int32_t p)
{
    int32_t cx = p * 16 + STP_HALF_PIXEL, c, cap;
    if (!l)
        return 0;
    c = outside(cx - l->near.x, &l->near);
    if (c > 0) {
        c -= COVER_ONE - inside(cx - l->far.x, &l->far);
        cap = beyond_end(l->near.end - cx);
        if (cap < c)
            c = cap;
    }
    return c;
}

/* ... by the span on its right */
static int32_t from_right(const span_side *r, int32_t p)
{
    int32_t cx = p * 16 + STP_HALF_PIXEL, c, cap;
    if (!r)
        return 0;
    c = outside(r->near.x - cx, &r->near);
    if (c > 0) {
        c -= COVER_ONE - inside(r->far.x - cx, &r->far);
        cap = beyond_end(cx - r->near.end);
        if (cap < c)
            c = cap;
    }
    return c;
}

/* a crossing's shade (smooth polygons) */
static stp_fix crossing_shade(const stp_crossing *c)
{
#if STP_WITH_GOURAUD
    return c->shade;
#else
    (void)c;
    return 0;
#endif
}

static void cover(const row_ctx *rc, int32_t p, int32_t c, stp_fix shade)
{
    uint32_t x = (uint32_t)p;
    if (c <= 0)
        return;
    if (c > COVER_ONE)
        c = COVER_ONE;
    if (rc->zrow && !nearer(rc->zrow, x, rc->d_row, rc->ddx))
        return;
    blend_pixel(rc->aa, rc->row, x, rc->style, shade, c);
}

/* The gap of pixels lo..hi between the span of crossings lc[0], lc[1]
 * (NULL: the row's start) and that of rc[0], rc[1] (NULL: its end): from
 * each side, the pixels the neighbouring span's edge partly covers, each
 * pixel once (a pixel both spans reach takes the sum: they cover disjoint
 * parts of it, and the shade of the side covering more). */
static void fill_gap(const row_ctx *rc, const stp_crossing *lc, const stp_crossing *rc2, int32_t lo,
                     int32_t hi)
{
    span_side left, right;
    const span_side *l = 0, *r = 0;
    stp_fix shade_l, shade_r, flat = rc->flat;
    int32_t p, last = lo - 1;
    if (lo > hi)
        return;
    if (lc) {
        side_of(&left.near, &lc[1], lc[1].x_hi);
        side_of(&left.far, &lc[0], lc[0].x_lo);
        l = &left;
    }
    if (rc2) {
        side_of(&right.near, &rc2[0], rc2[0].x_lo);
        side_of(&right.far, &rc2[1], rc2[1].x_hi);
        r = &right;
    }
    shade_l = lc && rc->smooth ? crossing_shade(&lc[1]) : flat;
    shade_r = rc2 && rc->smooth ? crossing_shade(&rc2[0]) : flat;
    for (p = lo; l && p <= hi; p++) {
        int32_t cl = from_left(l, p), cr;
        if (cl <= 0)
            break;
        cr = from_right(r, p);
        cover(rc, p, cl + (cr > 0 ? cr : 0), cl >= cr ? shade_l : shade_r);
        last = p;
    }
    for (p = hi; r && p > last; p--) {
        int32_t cr = from_right(r, p), cl;
        if (cr <= 0)
            break;
        cl = from_left(l, p);
        cover(rc, p, cr + (cl > 0 ? cl : 0), shade_r);
    }
}

void stp_edge_aa_row(const stp_edge_aa *aa, uint8_t *row, uint16_t *zrow, const stp_crossing *c,
                     int nc, int32_t style, int smooth, int64_t d_row, int64_t ddx)
{
    row_ctx rc;
    int k;
    int32_t lo = 0, last_pixel = (int32_t)aa->width - 1;
    if (nc < 2)
        return;
    rc.aa = aa;
    rc.row = row;
    rc.zrow = zrow;
    rc.d_row = d_row;
    rc.ddx = ddx;
    rc.style = style;
    rc.smooth = smooth;
    rc.flat = smooth || (style & STP_COLOUR_FLAG) ? 0 : stp_intensity_shade((int)style, aa->levels);
    /* span k: crossings c[2k], c[2k+1], pixels with centres in [x_l, x_r);
     * the gap before it ends at the last centre left of x_l */
    for (k = 0; k + 1 < nc; k += 2) {
        int32_t hi = first_centre_at(c[k].x) - 1;
        fill_gap(&rc, k > 0 ? &c[k - 2] : 0, &c[k], lo, hi > last_pixel ? last_pixel : hi);
        lo = first_centre_at(c[k + 1].x);
        if (lo < 0)
            lo = 0;
    }
    fill_gap(&rc, &c[k - 2], 0, lo, last_pixel);
}

void stp_edge_aa_threshold_row(uint8_t *row, uint32_t width, uint32_t y, const stp_cell *cell)
{
    const uint8_t *t;
    uint32_t x, hx = 0, w = cell->width, bits = 0;
    if (cell->kind == STP_CELL_PATTERN) {
        /* in place: byte b is written from pixels 8b..8b+7, after grey[b]
         * is read */
        stp_halftone_row(row, row, width, y, cell);
        if (width % 8u)
            row[width / 8u] = (uint8_t)(row[width / 8u] & (0xFF00u >> (width % 8u)));
        return;
    }
    /* a threshold cell: its row resolved once, as stp_halftone_fillin does
     * (ON where the level exceeds the threshold: stp_cell_on's test); byte
     * b is stored after pixels 8b..8b+7, so after grey[b] was read */
    t = &stp_cell_table(cell)[(y % cell->height) * w];
    if (8u % w == 0) {
        /* every byte sees the same 8 thresholds: whole bytes unrolled */
        uint8_t t8[8];
        uint32_t b;
        for (x = 0; x < 8u; x++)
            t8[x] = t[x % w];
        for (b = 0; b < width / 8u; b++) {
            const uint8_t *g = row + 8u * b;
            row[b] = (uint8_t)((g[0] > t8[0]) << 7 | (g[1] > t8[1]) << 6 | (g[2] > t8[2]) << 5 |
                               (g[3] > t8[3]) << 4 | (g[4] > t8[4]) << 3 | (g[5] > t8[5]) << 2 |
                               (g[6] > t8[6]) << 1 | (g[7] > t8[7]));
        }
        x = 8u * b; /* the partial byte's pixels below */
        hx = x % w;
    } else {
        x = 0;
    }
    for (; x < width; x++) {
        bits = (bits << 1) | (row[x] > t[hx] ? 1u : 0u);
        if (++hx == w)
            hx = 0;
        if ((x & 7u) == 7u) {
            row[x >> 3] = (uint8_t)bits;
            bits = 0;
        }
    }
    if (width % 8u)
        row[width / 8u] = (uint8_t)(bits << (8u - width % 8u)); /* padding bits 0 */
}

void stp_edge_aa_threshold_page(uint8_t *row, uint32_t width, uint32_t y, const stp_cell *cell, uint8_t *line)
{
    uint32_t x;
    for (x = 0; x < width; x++)
        row[x] = (uint8_t)stp_cell_on(cell, x, y, row[x]);
    stp_mono_page_from_bytes(line, (uint8_t)(1u << (y & 7u)), row, width);
}

#endif
