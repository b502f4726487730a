/* SPDX-License-Identifier: MIT */
/* Private: the depth stage of hidden-surface removal by a Z buffer, one
 * implementation for every route that draws with one (raster.c's frame of
 * stp_renderer_render, direct drawing's bands, direct_band.c): a frame's
 * depth keys (the projection's floor(hither 2^30 / z), project_private.h)
 * mapped to Q12 depths over their range, a polygon's depth plane from its
 * projected vertices, its depths down the rows and the depth-tested 1-bit
 * spans.  Every route that gives a polygon the same vertices and the same
 * key range so gives it the same pixel depths and the same pixels.
 *
 * Formats: a depth key is an int32 in [1, 2^30], larger nearer; a Q12
 * depth (12 fractional bits) lies in [2^12, 65535 2^12] at the vertices,
 * and a pixel's depth, floor(Q12 / 2^12) clamped to 1..65535, is the Z
 * buffer's uint16 entry (0: nothing drawn; a pixel is drawn over when its
 * depth is larger).  Device coordinates are Q27.4, >= 0 and below 2^19
 * (with the guard band, project_private.h, >= -STP_GUARD_Q4 = -2^13: a
 * polygon's centre is then found from sums moved by STP_GUARD_Q4 a
 * vertex, DEPTH_CENTRE_BIAS, so they stay unsigned);
 * plane gradients are Q12 per subpixel, clamped to +-2^40 (edge-on
 * polygons); a depth at a pixel centre within a polygon's extent stays
 * below 2^62 in magnitude (int64), and the 32-bit short forms hold where
 * depth_terms_short says they do.
 *
 * Included after edge_walk_private.h (STP_HALF_PIXEL,
 * stp_quotient_q12_by_recip), within STP_WITH_ZBUFFER. */
#ifndef STIPPLE_DEPTH_PRIVATE_H
#define STIPPLE_DEPTH_PRIVATE_H

#include <stdint.h>

#include "stipple/config.h"
#include "stipple/render.h" /* stp_instr */
#include "arith_private.h"
#include "div64_private.h" /* STP_DIV64 */
#include "run_fill_private.h" /* stp_halftone_fill_bits, the one run filler */
#include "depth_keys_private.h" /* depth_keys, depth_q12_of */
#include "project_private.h" /* STP_GUARD_Q4: the guard band */

#ifndef STP_HALF_PIXEL
#error "depth_private.h needs edge_walk_private.h first"
#endif

/* num / den truncated toward zero (C's division), den != 0.  Without wide
 * arithmetic: one 32-bit division when both fit 32 bits; when |den| <
 * 2^16 and |num| < 2^48, three of 16-bit digits (long division); else
 * the library's. */
DEPTH_MAYBE_UNUSED static int64_t div_trunc(int64_t num, int64_t den)
{
#if !STP_WIDE_ARITH && !STP_SMALL_DIVISION /* with it: its loop alone, smaller */
    uint64_t un = num < 0 ? 0u - (uint64_t)num : (uint64_t)num, ud = den < 0 ? 0u - (uint64_t)den : (uint64_t)den;
    if ((un | ud) < ((uint64_t)1 << 32)) { /* one 32-bit division: a small triangle's gradients */
        uint32_t q = (uint32_t)un / (uint32_t)ud;
        return (num < 0) != (den < 0) ? -(int64_t)q : (int64_t)q;
    }
    if (ud < 65536u && un < ((uint64_t)1 << 48)) {
        uint32_t d = (uint32_t)ud, hi = (uint32_t)(un >> 32), q1, q2, q3, part;
        q1 = hi / d;
        part = ((hi - q1 * d) << 16) | (uint32_t)((un >> 16) & 0xFFFFu);
        q2 = part / d;
        part = ((part - q2 * d) << 16) | (uint32_t)(un & 0xFFFFu);
        q3 = part / d;
        un = ((uint64_t)q1 << 32) + ((uint64_t)q2 << 16) + q3;
        return (num < 0) != (den < 0) ? -(int64_t)un : (int64_t)un;
    }
#endif
    return STP_DIV64(num, den);
}

/* a b for |a b| < 2^63: a 32 x 32-bit product while a fits (ARMv6-M: no
 * 64 x 64-bit library call) */
DEPTH_MAYBE_UNUSED static int64_t mul_wide(int64_t a, int32_t b)
{
    if (!STP_WIDE_ARITH && a >= INT32_MIN && a <= INT32_MAX)
        return stp_smul32x32((int32_t)a, b);
    return a * b;
}

/* depth_term_short (below) for g's magnitude m < 2^29 (extent >= 0) */
STP_HOT_INLINE int depth_magnitude_short(uint32_t m, int32_t extent)
{
    uint32_t hi;
    if (extent >= ((int32_t)1 << 14))
        return 0;
    /* m extent = hi 2^15 + (m mod 2^15) extent, hi = (m >> 15) extent < 2^28 */
    hi = (m >> 15) * (uint32_t)extent;
    return hi < (1u << 14) && (hi << 15) + (m & 0x7FFFu) * (uint32_t)extent < ((uint32_t)1 << 29);
}

/* |g| extent < 2^29 (extent >= 0): a depth gradient g (Q12 per subpixel)
 * over a triangle's extent in x or y, so each term of dc + ddx (x - xc) +
 * ddy (y - yc) at its pixel centres (x and xc within the vertices' x
 * extent, y and yc within their y extent) is below 2^29 and the sum, with
 * dc < 2^28 + 2^12, fits int32. */
STP_HOT_INLINE int depth_term_short(int64_t g, int32_t extent)
{
    uint32_t low = (uint32_t)g;
    /* g within int32 (its high word the low word's sign), then low + 2^29
     * in [1, 2^30): |g| < 2^29 */
    if ((uint32_t)((uint64_t)g >> 32) != (low >> 31 ? 0xFFFFFFFFu : 0u) ||
        low + ((uint32_t)1 << 29) - 1u >= ((uint32_t)1 << 30) - 1u)
        return 0;
    return depth_magnitude_short(low >> 31 ? 0u - low : low, extent);
}

/* floor(s / n) for n >= 1: n = 3 and 4 without a division */
DEPTH_MAYBE_UNUSED static uint32_t div_count(uint32_t s, uint32_t n)
{
    if (n == 3)
        return stp_div3_u32(s);
    if (n == 4)
        return s >> 2;
    return s / n;
}

/* One pixel's depth from the span's Q12 depth: floor, clamped to 1..65535. */
DEPTH_MAYBE_UNUSED static uint16_t depth_of(int64_t d)
{
    int64_t dv = stp_asr64(d, 12);
    return (uint16_t)(dv < 1 ? 1 : (dv > 65535 ? 65535 : dv));
}
/* Q12 depths whose pixel depth is 1..65535 lie in [MIN, END) */
#define DEPTH_Q12_MIN ((int64_t)1 << 12)
#define DEPTH_Q12_END ((int64_t)65536 << 12)

/* Pixels x1..x2 of a 1-bit band line from a pattern byte: the one run
 * filler (page_bit as stp_halftone_fill_bits). */
STP_HOT_INLINE void fill_run(uint8_t *row, uint8_t page_bit, uint32_t x1, uint32_t x2, uint8_t pattern)
{
    stp_halftone_fill_bits(row, page_bit, (unsigned)x1, (unsigned)x2, pattern);
}
/* An opaque span of a direct style (paint_setup) whose depths are all in
 * 1..65535: di the Q12 depth at x1's centre, dstep per pixel (both fit 32
 * bits, put_span_z).  Alternately skip the hidden pixels and take a run of
 * visible ones, writing their depth and the pattern byte of the row. */
STP_HOT_INLINE void span_z_direct(uint16_t *z, uint8_t *row, uint8_t page_bit, uint8_t pattern, uint32_t x1,
                                 uint32_t x2, int32_t di, int32_t dstep)
{
    /* every pixel's depth (uint32_t)di >> 12 is 1..65535 here: no clamp,
     * and compared with the entry as it is */
    uint16_t *zp = z + x1, *const zlast = z + x2;
#if STP_NARROW_FORMS
    /* a span of one pixel, or two in one byte, on a row of bytes (the
     * Cortex-M0+ torus's spans are a pixel or two) without a run: their
     * depths, and their bits from the pattern (the host's larger frames
     * pay more for the tests than they save; the two cases as one cost
     * the torus 10 000 instructions more) */
    if (x1 == x2 && !(STP_WITH_PAGES && page_bit)) {
        uint32_t depth = (uint32_t)di >> 12;
        if (depth > *zp) {
            uint8_t *b = row + (x1 >> 3), bit = (uint8_t)(0x80u >> (x1 & 7u));
            *zp = (uint16_t)depth;
            *b = (uint8_t)(*b ^ ((*b ^ pattern) & bit));
        }
        return;
    }
    if (x2 == x1 + 1u && (x1 & 7u) != 7u && !(STP_WITH_PAGES && page_bit)) {
        uint32_t depth = (uint32_t)di >> 12, depth2 = (uint32_t)(di + dstep) >> 12, bit = 0x80u >> (x1 & 7u),
                 mask = 0;
        if (depth > zp[0]) {
            zp[0] = (uint16_t)depth;
            mask = bit;
        }
        if (depth2 > zp[1]) {
            zp[1] = (uint16_t)depth2;
            mask |= bit >> 1;
        }
        if (mask != 0) {
            uint8_t *b = row + (x1 >> 3);
            *b = (uint8_t)(*b ^ ((*b ^ pattern) & mask));
        }
        return;
    }
#endif
    for (;;) {
        uint32_t run, depth;
        while ((depth = (uint32_t)di >> 12) <= *zp) {
            if (zp == zlast)
                return;
            zp++;
            di += dstep;
        }
        run = (uint32_t)(zp - z);
        /* (each pixel's depth formed once, for its test and its entry) */
        for (;;) {
            *zp = (uint16_t)depth;
            if (zp == zlast) {
                fill_run(row, page_bit, run, x2, pattern);
                return;
            }
            zp++;
            di += dstep;
            if ((depth = (uint32_t)di >> 12) <= *zp)
                break;
        }
        fill_run(row, page_bit, run, (uint32_t)(zp - z) - 1u, pattern);
    }
}


/* The polygon's depth plane, by Newell's sums on (x, y, depth) over its
 * projected vertices: exact for planar polygons, a best fit otherwise.
 * Gradients per subpixel unit with 12 fractional bits (clamped to +-2^40:
 * a polygon seen edge-on), through the vertex average (xc, yc, dc).
 * Returns 0 when the polygon is edge-on (no area on screen). */
typedef struct depth_plane {
    int64_t ddx, ddy, dc;
    int32_t xc, yc;
} depth_plane;

/* Each vertex's coordinates moved by DEPTH_CENTRE_BIAS in the sums a
 * centre is found from (0 without the guard band) */
#define DEPTH_CENTRE_BIAS ((uint32_t)STP_GUARD_Q4)

/* The plane through Newell's sums a, b, c (c != 0) of n vertices whose
 * coordinates, each moved by DEPTH_CENTRE_BIAS, and Q12 depths sum to sx,
 * sy, sd: gradients -a 4096 / c and -b 4096 / c clamped to +-2^40, the
 * centre their averages. */
static inline void depth_plane_from_sums(depth_plane *pl, int64_t a, int64_t b, int64_t c, uint32_t sx, uint32_t sy,
                                         int64_t sd, int n)
{
    pl->ddx = div_trunc(-a * 4096, c);
    pl->ddy = div_trunc(-b * 4096, c);
#if STP_WIDE_ARITH
    /* both in [-2^28, 2^28) by one test (|4096 a| <= 2^40: nothing to clamp) */
    if ((((uint64_t)a + ((uint64_t)1 << 28)) | ((uint64_t)b + ((uint64_t)1 << 28))) >= ((uint64_t)1 << 29)) {
#else
    if (!(a > -((int64_t)1 << 28) && a < ((int64_t)1 << 28) && b > -((int64_t)1 << 28) &&
          b < ((int64_t)1 << 28))) { /* else |4096 a|, |4096 b| < 2^40: nothing to clamp */
#endif
        if (pl->ddx > ((int64_t)1 << 40)) pl->ddx = (int64_t)1 << 40;
        if (pl->ddx < -((int64_t)1 << 40)) pl->ddx = -((int64_t)1 << 40);
        if (pl->ddy > ((int64_t)1 << 40)) pl->ddy = (int64_t)1 << 40;
        if (pl->ddy < -((int64_t)1 << 40)) pl->ddy = -((int64_t)1 << 40);
    }
    pl->xc = (int32_t)(div_count(sx, (uint32_t)n) - DEPTH_CENTRE_BIAS);
    pl->yc = (int32_t)(div_count(sy, (uint32_t)n) - DEPTH_CENTRE_BIAS);
    /* depths below 2^28: 32-bit division while the sum fits */
    pl->dc = sd < ((int64_t)1 << 32) ? (int64_t)div_count((uint32_t)sd, (uint32_t)n) : STP_DIV64(sd, n);
}

#if !STP_WIDE_ARITH
/* A small triangle's gradients (depth_plane_from_sums's quotients)
 * trunc(-a 4096 / c) and trunc(-b 4096 / c) for |a|, |b| < 2^19 and c !=
 * 0: quotients of 32-bit magnitudes (n = |a| 4096 < 2^31, so they fit
 * int32), both from one reciprocal r = floor((2^32 - 1) / |c|)
 * (stp_quotient_q12_by_recip; on ARMv6-M r without a division,
 * stp_recip_u32: the library's is ~150 instructions).  Returns 1 when the
 * triangle's depth terms are short (depth_terms_short) by the quotients'
 * magnitudes and extents at least its own (x_ext, y_ext < 2^14): |g| <
 * 2^29 and |g| extent < 2^29, as depth_term_short asks, by a test that
 * passes only where the true one does; 0: not known. */
DEPTH_MAYBE_UNUSED static int gradients_short(int32_t a, int32_t b, int32_t c, int64_t *ga, int64_t *gb, int32_t x_ext, int32_t y_ext)
{
    uint32_t ua = (a < 0 ? 0u - (uint32_t)a : (uint32_t)a) << 12, ub = (b < 0 ? 0u - (uint32_t)b : (uint32_t)b) << 12,
             uc = c < 0 ? 0u - (uint32_t)c : (uint32_t)c, qa = ua, qb = ub;
    if (uc > 1) {
#if STP_RECIP_U32
        uint32_t r = stp_recip_u32(uc);
#else
        uint32_t r = 0xFFFFFFFFu / uc;
#endif
        qa = stp_quotient_q12_by_recip(ua, uc, r);
        qb = stp_quotient_q12_by_recip(ub, uc, r);
    }
    /* -a and c of opposite signs: negative (a = 0: qa = 0 either way);
     * qa, qb <= ua, ub < 2^31, so the signed quotients are int32s */
    *ga = (a ^ c) >= 0 ? -(int32_t)qa : (int32_t)qa;
    *gb = (b ^ c) >= 0 ? -(int32_t)qb : (int32_t)qb;
#if defined(__OPTIMIZE_SIZE__) /* builds for size: depth_terms_short's one copy asks */
    (void)x_ext;
    (void)y_ext;
    return 0;
#else
    /* q extent < 2^29 from (floor(q / 2^14) + 1) extent < 2^15, which
     * exceeds q extent / 2^14 (q < 2^31 and extents below 2^14: the
     * product below 2^31), and with it q < 2^29 (extents >= 1, c != 0): a
     * product a term, short by at most 2^14 extent of the exact test
     * (depth_magnitude_short), which a torus's faces never need */
    return ((((qa >> 14) + 1u) * (uint32_t)x_ext) | (((qb >> 14) + 1u) * (uint32_t)y_ext)) < ((uint32_t)1 << 15);
#endif
}

/* |p| + |q| (|p|, |q| < 2^20): at least max(0, p, q) - min(0, p, q), the
 * extent of three coordinates relative to the first (equal to it when p
 * and q differ in sign, at most twice it), fewer instructions */
/* A small triangle's centre (depth_plane_from_sums's, n = 3): coordinate
 * sums below 2^22, its depths' below 2^30 (stp_div3_u30 without the
 * tests; builds for size share stp_div3_u32) */
#if defined(__OPTIMIZE_SIZE__)
#define STP_CENTRE_DIV3(s) stp_div3_u32(s)
#else
#define STP_CENTRE_DIV3(s) stp_div3_u30(s)
#endif
STP_HOT_INLINE void triangle_centre(depth_plane *pl, uint32_t sx, uint32_t sy, uint32_t sd)
{
    pl->xc = (int32_t)(stp_div3_u32(sx) - DEPTH_CENTRE_BIAS);
    pl->yc = (int32_t)(stp_div3_u32(sy) - DEPTH_CENTRE_BIAS);
    pl->dc = STP_CENTRE_DIV3(sd);
}

#if !defined(__OPTIMIZE_SIZE__)
DEPTH_MAYBE_UNUSED static int32_t extent_bound(int32_t p, int32_t q)
{
    return (p < 0 ? -p : p) + (q < 0 ? -q : q);
}
#endif
#endif

/* A triangle's plane: its Newell sums are its cross product, exactly
 * (relative coordinates below 2^20, depths below 2^16); its three Q12
 * depths (below 2^28) sum below 2^30.  Without wide arithmetic a small
 * triangle (offsets from the first vertex with |x1| + |x2| < 2^14, |y1| +
 * |y2| < 2^13: products below 2^30, so the sums fit int32, and |a|, |b| <
 * 2^19) in 32 bits: no clamp (|a|, |b| < 2^28), the same values.  With wide arithmetic the
 * body is short (no 32-bit route) and the draw path inlines it: its call
 * cost a fifth of it (the host's torus). */
#if STP_WIDE_ARITH
#define DEPTH_TRIANGLE_FN STP_HOT_INLINE
#else
#define DEPTH_TRIANGLE_FN DEPTH_MAYBE_UNUSED static
#endif
/* depth_setup_triangle's answers besides 0 (edge-on): the plane made, and
 * (PLANE_SHORT) its depth terms found short on the way (depth_terms_short,
 * not asked again) */
#define PLANE_MADE 1
#define PLANE_SHORT 2
DEPTH_TRIANGLE_FN int depth_plane_triangle(const stp_instr *v, int32_t d0, int32_t d1, int32_t d2, depth_plane *pl)
{
    int32_t x1 = v[1].x - v[0].x, y1 = v[1].y - v[0].y, x2 = v[2].x - v[0].x, y2 = v[2].y - v[0].y;
    int32_t e1 = (d1 >> 12) - (d0 >> 12), e2 = (d2 >> 12) - (d0 >> 12);
    uint32_t sx = (uint32_t)v[0].x + (uint32_t)v[1].x + (uint32_t)v[2].x + 3u * DEPTH_CENTRE_BIAS,
             sy = (uint32_t)v[0].y + (uint32_t)v[1].y + (uint32_t)v[2].y + 3u * DEPTH_CENTRE_BIAS,
             sd = (uint32_t)d0 + (uint32_t)d1 + (uint32_t)d2;
    int64_t a, b, c;
#if !STP_WIDE_ARITH /* 64-bit hosts: 64-bit products and quotients cost what 32-bit ones do */
    /* |x1| + |x2| < 2^14 and |y1| + |y2| < 2^13 (the extents
     * gradients_short takes, a test each): products below 2^30 still (|e|
     * < 2^16); |a|, |b| < 2^19 by one unsigned comparison each */
    const uint32_t gs = (uint32_t)1 << 19;
#if defined(__OPTIMIZE_SIZE__)
    /* builds for size (gradients_short takes no extents): -2^14 <= x1, x2
     * < 2^14 and -2^13 <= y1, y2 < 2^13 (products below 2^30 as well),
     * each offset by the bound below twice it, a power of two, so both by
     * their OR (lm3s6965: 24 bytes fewer) */
    const uint32_t xs = (uint32_t)1 << 14, ys = (uint32_t)1 << 13;
    const int32_t x_ext = 0, y_ext = 0;
    if (((((uint32_t)x1 + xs) | ((uint32_t)x2 + xs)) >> 15) == 0 &&
        ((((uint32_t)y1 + ys) | ((uint32_t)y2 + ys)) >> 14) == 0) {
#else
    int32_t x_ext, y_ext;
    /* the centre first, its sums not kept across the tests and the
     * quotients (a route that falls through makes it again; builds for
     * size make it after them, as an ATmega2560's large triangles fall
     * through) */
    triangle_centre(pl, sx, sy, sd);
    x_ext = extent_bound(x1, x2);
    y_ext = extent_bound(y1, y2);
    if (x_ext < ((int32_t)1 << 14) && y_ext < ((int32_t)1 << 13)) {
#endif
        int32_t c32 = x1 * y2 - y1 * x2, a32 = y1 * e2 - e1 * y2, b32 = e1 * x2 - x1 * e2;
        if (c32 != 0 && (uint32_t)a32 + (gs - 1u) < 2u * gs - 1u && (uint32_t)b32 + (gs - 1u) < 2u * gs - 1u) {
            int terms = gradients_short(a32, b32, c32, &pl->ddx, &pl->ddy, x_ext, y_ext);
#if defined(__OPTIMIZE_SIZE__)
            triangle_centre(pl, sx, sy, sd);
#endif
            return terms ? PLANE_SHORT : PLANE_MADE;
        }
        a = a32;
        b = b32;
        c = c32;
    } else
#endif
    {
        a = stp_smul32x32(y1, e2) - stp_smul32x32(e1, y2);
        b = stp_smul32x32(e1, x2) - stp_smul32x32(x1, e2);
        c = stp_smul32x32(x1, y2) - stp_smul32x32(y1, x2);
    }
    if (c == 0) {
        pl->ddx = pl->ddy = pl->dc = 0;
        pl->xc = pl->yc = 0;
        return 0;
    }
    depth_plane_from_sums(pl, a, b, c, sx, sy, (int64_t)sd, 3);
    return PLANE_MADE;
}

/* Plane pl's Q12 depth at device x = 0 on row y's centre (|ddx|, |ddy|
 * <= 2^40 and coordinates below 2^20: every term and the sum below
 * 2^62), the rows of a polygon's spans (depth_plane_at) */
STP_HOT_INLINE int64_t depth_plane_row(const depth_plane *pl, uint32_t y)
{
    return pl->dc - pl->ddx * pl->xc + pl->ddy * (((int64_t)y << STP_SUBPIXEL_BITS) + STP_HALF_PIXEL - pl->yc);
}

/* The Q12 depth at pixel p's centre of the row whose depth at x = 0 is
 * d_row (depth_plane_row), ddx the plane's gradient a subpixel: dc +
 * ddx (x - xc) + ddy (y - yc) */
STP_HOT_INLINE int64_t depth_plane_at(int64_t d_row, int64_t ddx, uint32_t p)
{
    int32_t xq = (int32_t)(p << STP_SUBPIXEL_BITS) + STP_HALF_PIXEL;
    return d_row + (ddx >= INT32_MIN && ddx <= INT32_MAX ? stp_smul32x32((int32_t)ddx, xq) : ddx * xq);
}

/* Any polygon's plane by Newell's loop (triangles: depth_setup_triangle). */
DEPTH_MAYBE_UNUSED static int depth_plane_polygon(const depth_keys *k, const stp_instr *v, int n, depth_plane *pl)
{
    int64_t a = 0, b = 0, c = 0, sd = 0, d_last = depth_q12_of(k, v[n - 1].z), d_prev = d_last;
    uint32_t sx = 0, sy = 0; /* n <= 4101 coordinates in [0, 2^19]: < 2^32 */
    int i;
    pl->ddx = pl->ddy = pl->dc = 0;
    pl->xc = pl->yc = 0;
    for (i = 0; i < n; i++) {
        const stp_instr *p = &v[i == 0 ? n - 1 : i - 1], *q = &v[i];
        int64_t d_q = i == n - 1 ? d_last : depth_q12_of(k, q->z), dp = d_prev >> 12, dq = d_q >> 12;
        /* coordinates in [0, 2^19], depths in [1, 65535]: 32-bit factors */
        a += stp_smul32x32(p->y - q->y, (int32_t)(dp + dq));
        b += stp_smul32x32((int32_t)(dp - dq), p->x + q->x);
        c += stp_smul32x32(p->x - q->x, p->y + q->y);
        sx += (uint32_t)q->x + DEPTH_CENTRE_BIAS;
        sy += (uint32_t)q->y + DEPTH_CENTRE_BIAS;
        sd += d_q;
        d_prev = d_q;
    }
    if (c == 0)
        return 0;
    depth_plane_from_sums(pl, a, b, c, sx, sy, sd, n);
    return 1;
}
/* The int32 whose two's complement is u (no implementation-defined
 * conversion of a value above INT32_MAX) */
DEPTH_MAYBE_UNUSED static int32_t from_twos(uint32_t u)
{
    return u < 0x80000000u ? (int32_t)u : -(int32_t)~u - 1;
}

/* The triangle v's depth terms are short (depth_term_short in x and y):
 * its depths at pixel centres, dc + ddx (x - xc) + ddy (y - yc), then lie
 * within +-(2^28 + 2^12 + 2^30), so they follow from their values modulo
 * 2^32 in 32-bit unsigned arithmetic. */
DEPTH_MAYBE_UNUSED static int depth_terms_short(const depth_plane *pl, const stp_instr *v, int32_t y_extent)
{
    int32_t x_lo = v[0].x, x_hi = v[0].x;
    x_lo = v[1].x < x_lo ? v[1].x : x_lo;
    x_hi = v[1].x > x_hi ? v[1].x : x_hi;
    x_lo = v[2].x < x_lo ? v[2].x : x_lo;
    x_hi = v[2].x > x_hi ? v[2].x : x_hi;
    return depth_term_short(pl->ddx, x_hi - x_lo) && depth_term_short(pl->ddy, y_extent);
}

/* A flat triangle's depths down its rows (draw_triangle): short ones
 * (depth_terms_short) modulo 2^32 at pixel 0's centre on the row centre
 * (d_row32), per pixel in x (gx_pixel) and per row (gy_row); else general
 * Q12 ones on the row centre at x = TRI_DEPTH_X0 (d_row): pixel 0's centre
 * where a span's ends are then a product each (32-bit cores and hosts:
 * M0+ mesh torus 2 160 instructions a frame fewer), device x = 0 on 8- and
 * 16-bit cores (ATmega2560: 56 bytes, 3 400 cycles fewer that way). */
#if STP_HAVE_MUL32
#define TRI_DEPTH_X0 STP_HALF_PIXEL
#else
#define TRI_DEPTH_X0 0
#endif
typedef struct tri_depth {
    int64_t d_row;
#if STP_NARROW_FORMS
    int64_t d_step; /* d_row's change a row (general ones) */
#endif
    uint32_t d_row32, gx_pixel, gy_row;
    int short_depth;
} tri_depth;

/* the general depths' step a row: kept where speed comes first, else the
 * compiler forms it ahead of the rows' loop, for every triangle, short
 * ones too; formed at each step elsewhere (a smaller frame on AVR) */
#if STP_NARROW_FORMS
#define TRI_DEPTH_STEP(td, pl) ((void)(pl), (td)->d_step)
#else
#define TRI_DEPTH_STEP(td, pl) ((pl)->ddy * (1 << STP_SUBPIXEL_BITS))
#endif

/* The depths of the triangle v (plane pl, y_extent high; made is
 * depth_setup_triangle's answer) from row centre yc down. */
STP_HOT_INLINE void tri_depth_start(tri_depth *td, const depth_plane *pl, const stp_instr *v, int32_t y_extent,
                                   int32_t yc, int made)
{
    /* (64-bit hosts: 64-bit depths cost what 32-bit ones do) */
    td->short_depth = !STP_WIDE_ARITH && (made == PLANE_SHORT || depth_terms_short(pl, v, y_extent));
    if (td->short_depth) {
        td->gx_pixel = (uint32_t)pl->ddx << STP_SUBPIXEL_BITS;
        td->gy_row = (uint32_t)pl->ddy << STP_SUBPIXEL_BITS;
        td->d_row32 = (uint32_t)pl->dc + (uint32_t)pl->ddx * (uint32_t)(STP_HALF_PIXEL - pl->xc) +
                      (uint32_t)pl->ddy * (uint32_t)(yc - pl->yc);
        td->d_row = 0; /* unused: set for the compiler's flow analysis */
    } else {
        td->d_row = pl->dc + mul_wide(pl->ddx, TRI_DEPTH_X0 - pl->xc) + mul_wide(pl->ddy, yc - pl->yc);
#if STP_NARROW_FORMS
        td->d_step = pl->ddy * (1 << STP_SUBPIXEL_BITS);
#endif
        td->d_row32 = td->gx_pixel = td->gy_row = 0; /* unused, likewise */
    }
}

/* The next row's depths. */
STP_HOT_INLINE void tri_depth_step(tri_depth *td, const depth_plane *pl)
{
    if (td->short_depth)
        td->d_row32 += td->gy_row;
    else
        td->d_row += TRI_DEPTH_STEP(td, pl);
}

/* An opaque span x1..x2 of a 1-bit band line (row, page_bit as
 * stp_halftone_fill_bits, pattern its row's byte) whose Q12 depths, d at
 * x1's centre and ddx a pixel, may leave 1..65535: each pixel's clamped
 * (depth_of), and the visible ones' written to z (the line's entries) and
 * painted in runs. */
DEPTH_MAYBE_UNUSED STP_NOINLINE void span_z_clamped_bits(uint16_t *z, uint8_t *row, uint8_t page_bit, uint8_t pattern,
                                                         uint32_t x1, uint32_t x2, int64_t d, int64_t ddx)
{
    uint32_t x = x1, run = 0;
    int in_run = 0;
    /* one run filler call (a run ends at a hidden pixel or past x2): the
     * smaller code, for the rare spans that come here */
    for (;;) {
        uint16_t depth = x <= x2 ? depth_of(d) : 0;
        if (depth > z[x <= x2 ? x : x2]) {
            z[x] = depth;
            if (!in_run) {
                run = x;
                in_run = 1;
            }
        } else {
            if (in_run)
                fill_run(row, page_bit, run, x - 1, pattern);
            in_run = 0;
            if (x > x2)
                return;
        }
        x++;
        d += ddx;
    }
}

/* An opaque depth-tested span of a 1-bit band line, any depths (as
 * span_z_clamped_bits): straight (span_z_direct) when both ends' depths
 * are 1..65535, so every pixel's between, and the depth and its step fit
 * 32 bits (|step| <= |d_end - d|); a polygon's span of a 1-bit style
 * (raster.c's put_span_z, direct_depth.c's clipped faces).  span_z_direct
 * inlined twice: a line of rows (page_bit 0) as a constant, so the rows'
 * run filler keeps no page test. */
DEPTH_MAYBE_UNUSED STP_NOINLINE void span_z_bits(uint16_t *z, uint8_t *row, uint8_t page_bit, uint8_t pattern,
                                                 uint32_t x1, uint32_t x2, int64_t d, int64_t ddx)
{
    int64_t d_end = d + ddx * (int64_t)(x2 - x1);
    int32_t dstep = x2 > x1 ? (int32_t)ddx : 0;
    if (!(d >= DEPTH_Q12_MIN && d < DEPTH_Q12_END && d_end >= DEPTH_Q12_MIN && d_end < DEPTH_Q12_END))
        span_z_clamped_bits(z, row, page_bit, pattern, x1, x2, d, ddx);
    else if (STP_WITH_PAGES && page_bit != 0)
        span_z_direct(z, row, page_bit, pattern, x1, x2, (int32_t)d, dstep);
    else
        span_z_direct(z, row, 0, pattern, x1, x2, (int32_t)d, dstep);
}

/* A triangle's short depth (tri_depth_start) at pixel p's centre on the
 * current row, modulo 2^32 */
#define TRI_DEPTH_SHORT_AT(td, p) ((td)->d_row32 + (td)->gx_pixel * (p))

/* The Q12 depth of triangle pl's (depths td) pixel p1 on the current
 * row, and (*ddx) its step a pixel */
DEPTH_MAYBE_UNUSED STP_HOT_INLINE int64_t tri_depth_at(const tri_depth *td, const depth_plane *pl, uint32_t p1,
                                                       int64_t *ddx)
{
    *ddx = pl->ddx * (1 << STP_SUBPIXEL_BITS);
    if (td->short_depth)
        return from_twos(TRI_DEPTH_SHORT_AT(td, p1));
#if STP_HAVE_MUL32
    return td->d_row + mul_wide(*ddx, (int32_t)p1);
#else
    return td->d_row + mul_wide(pl->ddx, (int32_t)(p1 << STP_SUBPIXEL_BITS) + STP_HALF_PIXEL);
#endif
}

/* The opaque depth-tested span p1..p2 of a triangle's row (plane pl,
 * depths td) into a 1-bit band line (z its entries, row, page_bit and
 * pattern as span_z_clamped_bits) when its depths are 1..65535 at both
 * ends (span_z_direct): 1; else 0, *d_out the depth at p1's centre and
 * *ddx_out its step a pixel, for
 * the caller's clamped span (span_z_bits; the pattern then not formed
 * here, a register fewer across the test on ARMv6-M: its mesh torus 8 000
 * instructions a frame). */
STP_HOT_INLINE int tri_span_straight(uint16_t *z, uint8_t *row, uint8_t page_bit, uint8_t pattern, uint32_t p1,
                                     uint32_t p2, const tri_depth *td, const depth_plane *pl, int64_t *d_out,
                                     int64_t *ddx_out)
{
    if (td->short_depth) {
        /* the depths at the span's first and last pixel centres, modulo 2^32 */
        /* (where speed comes first on a 32-bit core the last from the
         * first, the same value; elsewhere it cost an ATmega2560 cycles) */
        uint32_t d = TRI_DEPTH_SHORT_AT(td, p1),
                 d_end = STP_NARROW_FORMS ? d + td->gx_pixel * (p2 - p1) : TRI_DEPTH_SHORT_AT(td, p2);
        const uint32_t depths = (uint32_t)(DEPTH_Q12_END - DEPTH_Q12_MIN);
        if (d - (uint32_t)DEPTH_Q12_MIN < depths &&
            ((STP_NARROW_FORMS && p2 == p1) || d_end - (uint32_t)DEPTH_Q12_MIN < depths)) {
            /* 1..65535 at both ends; the step a pixel is added only
             * where the span has two (span_z_direct), whose centres 16
             * apart lie within the x extent: 16 |ddx| < 2^29 (from_twos
             * maps every other value too: no test for one pixel) */
            span_z_direct(z, row, page_bit, pattern, p1, p2, (int32_t)d, from_twos(td->gx_pixel));
            return 1;
        }
        *d_out = from_twos(d);
        *ddx_out = pl->ddx * (1 << STP_SUBPIXEL_BITS);
        return 0;
    } else {
#if STP_HAVE_MUL32
        int64_t ddx = pl->ddx * (1 << STP_SUBPIXEL_BITS), d = td->d_row + mul_wide(ddx, (int32_t)p1),
                d_end = td->d_row + mul_wide(ddx, (int32_t)p2);
#else
        int32_t xq = (int32_t)(p1 << STP_SUBPIXEL_BITS) + STP_HALF_PIXEL;
        int64_t d = td->d_row + mul_wide(pl->ddx, xq);
        int64_t ddx = pl->ddx * (1 << STP_SUBPIXEL_BITS), d_end = d + mul_wide(ddx, (int32_t)(p2 - p1));
#endif
        if (d >= DEPTH_Q12_MIN && d < DEPTH_Q12_END && d_end >= DEPTH_Q12_MIN && d_end < DEPTH_Q12_END) {
            /* (the step is added only where the span has two pixels,
             * d_end - d fitting 32 bits: 64-bit hosts pass its low 32
             * bits, as above, without a test; ARMv6-M keeps the test:
             * without it GCC's layout cost its mesh torus 400
             * instructions a frame) */
            span_z_direct(z, row, page_bit, pattern, p1, p2, (int32_t)d,
                          STP_WIDE_ARITH ? from_twos((uint32_t)ddx) : p2 > p1 ? (int32_t)ddx : 0);
            return 1;
        }
        *d_out = d;
        *ddx_out = ddx;
        return 0;
    }
}

#endif
