/* SPDX-License-Identifier: MIT */
/* Private: the edge walker, the edge setup and row crossings the polygon
 * raster (raster.c) and the shadow maps (shadow.c) share, inline so
 * neither pays a call per edge and row; and the 32 x 32 -> 64-bit products
 * they use.  No .c file of its own.  The formats are stp_edge's
 * (renderer_state.h). */
#ifndef STIPPLE_EDGE_WALK_PRIVATE_H
#define STIPPLE_EDGE_WALK_PRIVATE_H

#include "renderer_state.h"
#include "edge_aa_private.h"

#define STP_HALF_PIXEL (1 << (STP_SUBPIXEL_BITS - 1))

/* Where 64-bit multiplication and division are single instructions
 * (64-bit hosts) the raster uses them; elsewhere (Cortex-M: a 64-bit
 * division is a ~470-instruction libgcc call on ARMv6-M, a 64-bit product
 * a ~50-instruction one) it takes 32 x 32 -> 64-bit products from 16-bit
 * halves and divides through 32-bit quotients, with the same results. */
#include "recip_private.h" /* STP_WIDE_ARITH; a test defines it 0 to check the narrow arithmetic on the host */
#include "div64_private.h" /* STP_DIV64 */

/* a b, exactly, for 32-bit a and b */
static inline uint64_t stp_umul32(uint32_t a, uint32_t b)
{
#if STP_WIDE_ARITH
    return (uint64_t)a * b;
#else
    uint32_t al = a & 0xFFFFu, ah = a >> 16, bl = b & 0xFFFFu, bh = b >> 16;
    uint32_t ll, lh, hl, hh, mid;
    if ((ah | bh) == 0)
        return a * b; /* below 2^32 */
    if (ah == 0 || bh == 0) {
        /* one factor below 2^16: two partial products, s 2^16 + l */
        uint32_t small = ah == 0 ? a : b, big = ah == 0 ? b : a, l = (big & 0xFFFFu) * small,
                 s = (big >> 16) * small, low = l + (s << 16);
        return ((uint64_t)((s >> 16) + (low < l ? 1u : 0u)) << 32) | low;
    }
    ll = al * bl;
    lh = al * bh;
    hl = ah * bl;
    hh = ah * bh;
    mid = (ll >> 16) + (lh & 0xFFFFu) + (hl & 0xFFFFu); /* < 3 2^16 */
    return ((uint64_t)(hh + (lh >> 16) + (hl >> 16) + (mid >> 16)) << 32) | ((mid << 16) | (ll & 0xFFFFu));
#endif
}

static inline int64_t stp_smul32(int32_t a, int32_t b)
{
#if STP_WIDE_ARITH
    return (int64_t)a * b;
#else
    uint64_t p = stp_umul32(a < 0 ? 0u - (uint32_t)a : (uint32_t)a, b < 0 ? 0u - (uint32_t)b : (uint32_t)b);
    return (a < 0) != (b < 0) ? -(int64_t)p : (int64_t)p;
#endif
}


/* floor(a b / 2^32), the high word of a 32 x 32-bit product */
static inline uint32_t stp_umulhi32(uint32_t a, uint32_t b)
{
#if STP_WIDE_ARITH
    return (uint32_t)(((uint64_t)a * b) >> 32);
#else
    uint32_t al = a & 0xFFFFu, ah = a >> 16, bl = b & 0xFFFFu, bh = b >> 16;
    uint32_t lh = al * bh, hl = ah * bl, mid = ((al * bl) >> 16) + (lh & 0xFFFFu) + (hl & 0xFFFFu); /* < 3 2^16 */
    return ah * bh + (lh >> 16) + (hl >> 16) + (mid >> 16);
#endif
}

/* floor(n / d) for n < 2^31 and 2 <= d < 2^31 from r = floor((2^32 - 1) /
 * d): r > (2^32 - d) / d, so n r / 2^32 lies less than n / 2^32 < 1/2
 * below n / d and not above it; its floor is the quotient or one short,
 * and the remainder (below 2 d < 2^32) corrects it.  One division (r)
 * serves every n with the same d. */
static inline uint32_t stp_quotient_by_recip(uint32_t n, uint32_t d, uint32_t r)
{
    uint32_t q = stp_umulhi32(n, r);
    return n - q * d >= d ? q + 1u : q;
}

/* floor(s / 3) for s < 2^30.  Without wide arithmetic from 32-bit
 * products: floor(t 0xAAAB / 2^17) is floor(t / 3) for t < 2^16 (3 0xAAAB
 * = 2^17 + 1: the excess t / (3 2^17) stays below 1/3), applied to s's top
 * 16 bits h = s >> 14 and then to t = (h mod 3) 2^14 + (s mod 2^14) < 3
 * 2^14. */
static inline uint32_t stp_div3_u30(uint32_t s)
{
#if STP_WIDE_ARITH
    return s / 3u;
#else
    uint32_t h, hq, t;
    if (s < 0x10000u) /* a small triangle's coordinate sums */
        return (s * 0xAAABu) >> 17;
    h = s >> 14;
    hq = (h * 0xAAABu) >> 17;
    t = ((h - 3u * hq) << 14) | (s & 0x3FFFu);
    return (hq << 14) + ((t * 0xAAABu) >> 17);
#endif
}

/* The reciprocals for slopes of short edges (stp_slope_recip,
 * recip_private.h), used where a 32-bit division is a library call. */
#if !STP_WIDE_ARITH && UINTPTR_MAX > 0xFFFFu && !STP_SMALL_DIVISION
#define STP_SLOPE_RECIP STP_SLOPE_RECIP_SIZE
#else
#define STP_SLOPE_RECIP 0
#endif

/* floor(v / 16) for -2^27 <= v < 2^31 - 2^27 (Q4 coordinates and their
 * half-pixel offsets): a shift of the offset value, no division */
static inline int32_t stp_floor16(int32_t v)
{
    return (int32_t)(((uint32_t)v + 0x8000000u) >> 4) - 0x800000;
}


/* trunc(2^16 num / den) for den > 0 and |num| < 2^21: a 32-bit division
 * while 2^16 num fits 32 bits (ARMv6-M: a short library call instead of a
 * ~470-instruction 64-bit one). */
static inline int64_t stp_slope_q16(int32_t num, int32_t den)
{
#if STP_SLOPE_RECIP > 0
    /* n = |num| 2^16 and m = stp_slope_recip[den]: n m / 2^32 (= |num| m
     * / 2^16) exceeds
     * n / den by less than n / 2^32, below 1 / den while |num| den < 2^16,
     * so its floor is the quotient */
    uint32_t un = num < 0 ? 0u - (uint32_t)num : (uint32_t)num;
    if (den >= 2 && den < STP_SLOPE_RECIP && un * (uint32_t)den < 65536u) {
        uint32_t q = (uint32_t)(stp_umul32(un, stp_slope_recip[den]) >> 16); /* un < 2^15 */
        return num < 0 ? -(int64_t)q : (int64_t)q;
    }
#endif
    if (num > -32768 && num < 32768)
        return (int32_t)(num * 65536) / den;
    return STP_DIV64((int64_t)num * 65536, den);
}

/* stp_slope_q16 for |num| < 2^15 (an edge of a triangle whose x are below
 * 2^14) in 32 bits: the quotient's magnitude is below 2^31.  The table's
 * floor(un m / 2^16) as un (m >> 16) + floor(un (m & 0xFFFF) / 2^16), two
 * products below 2^31 (un < 2^15). */
static inline int32_t stp_slope_q16_short(int32_t num, int32_t den)
{
#if STP_SLOPE_RECIP > 0
    uint32_t un = num < 0 ? 0u - (uint32_t)num : (uint32_t)num;
    if (den >= 2 && den < STP_SLOPE_RECIP && un * (uint32_t)den < 65536u) {
        uint32_t m = stp_slope_recip[den], q = un * (m >> 16) + ((un * (m & 0xFFFFu)) >> 16);
        return num < 0 ? -(int32_t)q : (int32_t)q;
    }
#endif
    return (num * (int32_t)65536) / den;
}

/* The vertices v[0..2] sorted by y, ties kept in their order: *top, *mid,
 * *bot, the order the triangle raster (raster.c) walks them in, and
 * pixel culling's test (render.c) with it. */
STP_HOT_INLINE void stp_tri_sort(const stp_instr *v, const stp_instr **top, const stp_instr **mid,
                                 const stp_instr **bot)
{
    const stp_instr *t = &v[0], *m = &v[1], *b = &v[2], *swap;
    if (m->y < t->y) {
        swap = t;
        t = m;
        m = swap;
    }
    if (b->y < m->y) {
        swap = m;
        m = b;
        b = swap;
        if (m->y < t->y) {
            swap = t;
            t = m;
            m = swap;
        }
    }
    *top = t;
    *mid = m;
    *bot = b;
}

/* Edge a - b (a the upper end, x below 2^14) at row centre yc (a->y <= yc
 * < b->y): the crossing's accumulator xa 2^16 + (yc - ya) slope modulo
 * 2^32, slope = stp_slope_q16_short(xb - xa, yb - ya) (|slope| <= 2^30)
 * into *slope.  The value lies within (-2^20, 2^30 + 2^20) (a point of
 * [xa, xb] less the slope's truncation, below one, times yc - ya), so the
 * unsigned sum is its two's complement; its floor(/ 2^16) is the crossing
 * both rasters draw from. */
static inline uint32_t stp_edge_acc_short(const stp_instr *a, const stp_instr *b, int32_t yc, int32_t *slope)
{
    *slope = stp_slope_q16_short(b->x - a->x, b->y - a->y);
    return (uint32_t)a->x * 65536u + (uint32_t)(yc - a->y) * (uint32_t)*slope;
}

/* The edge setup the polygon raster and the shadow maps share.
 * stp_edge_setup: edge (xa, ya) - (xb, yb) (Q27.4, |coordinates| < 2^20)
 * oriented top to bottom into *e; returns 0 for a horizontal edge (no row
 * centre crosses it), 1 when a was the top, -1 when b was.
 * stp_edge_shades: a smooth polygon's shades (stp_fix in [0, 1]) at the
 * edge's top and bottom.
 * stp_edges_start: puts the edges on row centre yc (Q4).
 * stp_edges_row: the crossings of the current row centre yc, sorted by x,
 * into out (returns how many), then steps every edge one row down.
 * stp_span_pixels: the pixels [*p1, *p2] of 0..width-1 whose centres c
 * satisfy xl <= c < xr; returns 0 when there is none. */
static inline int stp_edge_setup(stp_edge *e, int32_t xa, int32_t ya, int32_t xb, int32_t yb)
{
    int dir = 1;
    if (ya == yb)
        return 0;
    if (ya > yb) {
        int32_t t = xa;
        xa = xb;
        xb = t;
        t = ya;
        ya = yb;
        yb = t;
        dir = -1;
    }
    /* no row centre 16 r + 8 in [ya, yb): the edge never crosses a row */
    if (stp_floor16(ya + STP_HALF_PIXEL - 1) == stp_floor16(yb + STP_HALF_PIXEL - 1))
        return 0;
    e->xa = xa;
    e->ya = ya;
    e->yb = yb;
    e->step = stp_slope_q16(xb - xa, yb - ya) * 16;
    e->acc = 0;
#if STP_WITH_EDGE_AA
    e->aa_slope = stp_edge_aa_slope(e->step);
    e->aa_lo = xa < xb ? xa : xb;
    e->aa_hi = xa < xb ? xb : xa;
#endif
#if STP_WITH_GOURAUD
    e->sa = 0;
    e->shade_step = e->shade_acc = 0;
#endif
    return dir;
}

#if STP_WITH_GOURAUD
static inline void stp_edge_shades(stp_edge *e, int32_t s_top, int32_t s_bottom)
{
    e->sa = s_top;
    e->shade_step = stp_slope_q16(s_bottom - s_top, e->yb - e->ya) * 16;
}
#endif

static inline void stp_edges_start(stp_edge *edges, int n, int32_t yc, int smooth)
{
    int i;
    (void)smooth;
    for (i = 0; i < n; i++) {
        stp_edge *e = &edges[i];
        /* step is 16 slopes exactly */
        int64_t slope = stp_asr64(e->step, 4);
        e->acc = (int64_t)e->xa * 65536 +
                 (slope >= INT32_MIN && slope <= INT32_MAX ? stp_smul32(yc - e->ya, (int32_t)slope)
                                                            : (int64_t)(yc - e->ya) * slope);
#if STP_WITH_GOURAUD
        if (smooth)
            e->shade_acc = (int64_t)e->sa * 65536 + (int64_t)(yc - e->ya) * stp_asr64(e->shade_step, 4);
#endif
    }
}

static inline int stp_edges_row(stp_edge *edges, int n, int32_t yc, int smooth, stp_crossing *out)
{
    int nc = 0, i, k;
    (void)smooth;
    for (i = 0; i < n; i++) {
        stp_edge *e = &edges[i];
        if (e->ya <= yc && yc < e->yb) {
            stp_crossing c;
            c.x = (int32_t)stp_asr64(e->acc, 16);
#if STP_WITH_GOURAUD
            c.shade = smooth ? (int32_t)stp_asr64(e->shade_acc, 16) : 0;
#endif
#if STP_WITH_EDGE_AA
            c.slope = e->aa_slope;
            c.x_lo = e->aa_lo;
            c.x_hi = e->aa_hi;
#endif
            /* insertion sort: crossings are few */
            for (k = nc; k > 0 && out[k - 1].x > c.x; k--)
                out[k] = out[k - 1];
            out[k] = c;
            nc++;
        }
        e->acc += e->step;
#if STP_WITH_GOURAUD
        if (smooth)
            e->shade_acc += e->shade_step;
#endif
    }
    return nc;
}

static inline int stp_span_pixels(int32_t xl, int32_t xr, uint32_t width, uint32_t *p1, uint32_t *p2)
{
    /* pixel p's centre 16 p + 8: xl <= 16 p + 8 < xr */
    int32_t a = stp_floor16(xl - STP_HALF_PIXEL + (1 << STP_SUBPIXEL_BITS) - 1), b = stp_floor16(xr - STP_HALF_PIXEL + (1 << STP_SUBPIXEL_BITS) - 1) - 1;
    if (a < 0)
        a = 0;
    if (b > (int32_t)width - 1)
        b = (int32_t)width - 1;
    if (a > b)
        return 0;
    *p1 = (uint32_t)a;
    *p2 = (uint32_t)b;
    return 1;
}

#endif
