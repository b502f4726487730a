/* SPDX-License-Identifier: MIT */
/* Private: the edge walker, the edge setup and row crossings the polygon
 * raster (raster.c), direct drawing's bands (direct_band.c) and the shadow
 * maps (shadow.c) share, inline so none pays a call per edge and row; and
 * the 32 x 32 -> 64-bit products they use.  No .c file of its own.  The formats are stp_edge's
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

/* floor(n / d) for n = a 2^12, a < 2^19, and 2 <= d < 2^31 from r =
 * floor((2^32 - 1) / d) (< 2^31): n < 2^31 and r > (2^32 - d) / d, so n r
 * / 2^32 lies less than n / 2^32 < 1/2 below n / d and not above it; its
 * floor is the quotient or one short, and the remainder (below 2 d <
 * 2^32) corrects it.  One division (r) serves every n with the same d.
 * floor(n r / 2^32) = floor(a r / 2^20) from 32-bit products, n's twelve
 * zero bits spared: r = rh 2^20 + rl and a = ah 2^12 + al give a rh (<
 * 2^30) plus floor((ah rl 2^12 + al rl) / 2^20) = floor((ah rl + floor(al
 * rl / 2^12)) / 2^8), ah rl < 2^27 and al rl < 2^32: three products where
 * the high word of a full 32 x 32-bit one takes four (STP_NARROW_FORMS;
 * builds for size keep the product every caller shares). */
static inline uint32_t stp_quotient_q12_by_recip(uint32_t n, uint32_t d, uint32_t r)
{
#if STP_NARROW_FORMS
    uint32_t rl = r & 0xFFFFFu, a = n >> 12, q = a * (r >> 20) + (((a >> 12) * rl + (((a & 0xFFFu) * rl) >> 12)) >> 8);
#else
    uint32_t q = stp_umulhi32x32(n, r);
#endif
    return n - q * d >= d ? q + 1u : q;
}

/* The reciprocals for slopes of short edges (stp_slope_recip,
 * recip_private.h), used where a 32-bit division is a library call. */
#if !STP_WIDE_ARITH && UINTPTR_MAX > 0xFFFFu && !STP_SMALL_DIVISION
#define STP_SLOPE_RECIP STP_SLOPE_RECIP_SIZE
#else
#define STP_SLOPE_RECIP 0
#endif

/* |num| den < 2^16, the table's condition, tested as un < m / 2^16 with m
 * = stp_slope_recip[den] = floor(2^32 / den) + 1 (2 <= den < 2^16): the
 * shift the quotient takes anyway instead of a product and a constant.
 * floor(m / 2^16) den <= 2^16: were k = floor(m / 2^16) above 2^16 / den,
 * k 2^16 (<= m) would exceed 2^32 / den, so equal m, while k den >= 2^16
 * + 1 gives m den >= 2^32 + 2^16 > 2^32 + den >= m den; so un < k gives
 * un den < 2^16.  It refuses only un = k where den is no power of two (a
 * division gives those). */
#define STP_SLOPE_RECIP_FITS(un, m) ((un) < (m) >> 16)

/* floor(v / 16) for -2^27 <= v < 2^31 - 2^27 (Q4 coordinates and their
 * half-pixel offsets): a shift of the offset value, no division */
static inline int32_t stp_floor16(int32_t v)
{
    return (int32_t)(((uint32_t)v + 0x8000000u) >> 4) - 0x800000;
}


/* trunc(2^16 num / den) for den > 0 and |num| < 2^21: a 32-bit division
 * while 2^16 num fits 32 bits (ARMv6-M: a short library call instead of a
 * ~470-instruction 64-bit one); with wide arithmetic the one 64-bit
 * division, no test (host mesh torus 4 500 instructions a frame fewer). */
static inline int64_t stp_slope_q16(int32_t num, int32_t den)
{
#if STP_WIDE_ARITH
    return (int64_t)num * 65536 / den;
#else
#if STP_SLOPE_RECIP > 0
    /* n = |num| 2^16 and m = stp_slope_recip[den]: n m / 2^32 (= |num| m
     * / 2^16) exceeds
     * n / den by less than n / 2^32, below 1 / den while |num| den < 2^16
     * (STP_SLOPE_RECIP_FITS), so its floor is the quotient */
    uint32_t un = num < 0 ? 0u - (uint32_t)num : (uint32_t)num;
    if (den >= 2 && den < STP_SLOPE_RECIP) {
        uint32_t m = stp_slope_recip[den];
        if (STP_SLOPE_RECIP_FITS(un, m)) {
            uint32_t q = (uint32_t)(stp_umul32x32(un, m) >> 16); /* un < 2^15 */
            return num < 0 ? -(int64_t)q : (int64_t)q;
        }
    }
#endif
    if (num > -32768 && num < 32768)
        return (int32_t)(num * 65536) / den;
    return STP_DIV64((int64_t)num * 65536, den);
#endif
}

/* stp_slope_q16 for |num| < 2^15 (an edge of a triangle whose x are below
 * 2^14) in 32 bits: the quotient's magnitude is below 2^31.  The table's
 * floor(un m / 2^16) as un (m >> 16) + floor(un (m & 0xFFFF) / 2^16), two
 * products below 2^31 (un < 2^15). */
static inline int32_t stp_slope_q16_short(int32_t num, int32_t den)
{
#if STP_SLOPE_RECIP > 0
    /* (the table's case the likely one: the compiler lays it out straight,
     * the division apart) */
    uint32_t un = num < 0 ? 0u - (uint32_t)num : (uint32_t)num;
    if (!STP_UNLIKELY(den < 2 || den >= STP_SLOPE_RECIP)) {
        uint32_t m = stp_slope_recip[den];
        if (!STP_UNLIKELY(!STP_SLOPE_RECIP_FITS(un, m))) {
            uint32_t q = un * (m >> 16) + ((un * (uint16_t)m) >> 16);
            return num < 0 ? -(int32_t)q : (int32_t)q;
        }
    }
#endif
#if STP_UDIV32_LOOP || !STP_HAVE_MUL32
    {
        /* trunc(2^16 num / den) as C's division gives it (den > 0), from
         * the unsigned quotient: one division routine where it is a loop
         * (div64_private.h's, or AVR's library division) */
        uint32_t q = STP_UDIV32((num < 0 ? 0u - (uint32_t)num : (uint32_t)num) << 16, (uint32_t)den);
        return num < 0 ? -(int32_t)q : (int32_t)q;
    }
#else
    return (num * (int32_t)65536) / den;
#endif
}

/* The triangle walk's vertex: stp_instr (x, y: Q27.4 in int32_t) unless
 * the file defines STP_TRI_VERTEX, its coordinate type STP_TRI_COORD (at
 * least 16 bits, holding 2^SUB (32767 + 1)) and the coordinates
 * STP_TRI_X(p), STP_TRI_Y(p) before it includes this header (direct_band.c:
 * stp_direct_point at a moved origin, in int): one walk, compiled for the
 * vertices each caller has, so a 16-bit core does not widen them. */
#ifndef STP_TRI_VERTEX
#define STP_TRI_VERTEX stp_instr
#define STP_TRI_COORD int32_t
#define STP_TRI_X(p) ((p)->x)
#define STP_TRI_Y(p) ((p)->y)
#endif
/* Whether stp_tri_walk_start tests first for a triangle wholly above or
 * below the band, a shortcut (its rows find it too): left out where
 * 32-bit comparisons cost more code than they save time, and by a file
 * that defines it 0 before it includes this header, whose triangles are
 * seldom off the band (raster.c on 64-bit hosts). */
#ifndef STP_TRI_BAND_SHORTCUT
#define STP_TRI_BAND_SHORTCUT (!STP_LEAN_CODE)
#endif
typedef STP_TRI_VERTEX stp_tri_vertex;
typedef STP_TRI_COORD stp_tri_coord;

/* The vertices v0, v1, v2 sorted by y, ties kept in their order: *top,
 * *mid, *bot, the order the triangle walk takes them in, and pixel
 * culling's test (render.c) with it. */
STP_HOT_INLINE void stp_tri_sort(const stp_tri_vertex *v0, const stp_tri_vertex *v1, const stp_tri_vertex *v2,
                                 const stp_tri_vertex **top, const stp_tri_vertex **mid, const stp_tri_vertex **bot)
{
    const stp_tri_vertex *t = v0, *m = v1, *b = v2, *swap;
    if (STP_TRI_Y(m) < STP_TRI_Y(t)) {
        swap = t;
        t = m;
        m = swap;
    }
    if (STP_TRI_Y(b) < STP_TRI_Y(m)) {
        swap = m;
        m = b;
        b = swap;
        if (STP_TRI_Y(m) < STP_TRI_Y(t)) {
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
static inline uint32_t stp_edge_acc_short(const stp_tri_vertex *a, const stp_tri_vertex *b, stp_tri_coord yc,
                                          int32_t *slope)
{
    *slope = stp_slope_q16_short(STP_TRI_X(b) - STP_TRI_X(a), STP_TRI_Y(b) - STP_TRI_Y(a));
    return (uint32_t)STP_TRI_X(a) * 65536u + (uint32_t)(stp_tri_coord)(yc - STP_TRI_Y(a)) * (uint32_t)*slope;
}

/* ---- the triangle walk: the triangle raster's (raster.c) and direct
 * drawing's bands' (direct_band.c) one scan converter for triangles ----
 * A triangle's edge over the rows it crosses, as stp_edge_setup and
 * stp_edges_row make it: the crossing of row centre yc is
 * floor((xa 2^16 + (yc - ya) slope) / 2^16) with slope = trunc(2^16 (xb -
 * xa) / (yb - ya)), stepped by 16 slopes a row; so the triangle walk
 * gives exactly the crossings the general one does.  Coordinates are Q27.4
 * and >= 0 (the renderer's project() clamps them; direct drawing moves its
 * origin), but for the guard band of compact builds (project_private.h):
 * there x and y from -2^13, the narrow walk's x still >= 0 (a triangle
 * left of the picture is not narrow: the polygon raster's), the wide
 * walk's first centre clamped (STP_TRI_CLAMP_LEFT).  Without wide arithmetic in 32 bits (ARMv6-M: no 64-bit adds and
 * shifts a row): only triangles whose x are below 2^14 are walked
 * (STP_TRIANGLE_NARROW), and at a row centre ya <= yc < yb the accumulator
 * is 2^16 times a point of [xa, xb] less (yc - ya) times the slope's
 * truncation (below one), so within (-2^20, 2^30 + 2^20); a step taken (the
 * next row is the edge's too) is the difference of two such values, below
 * 2^31.  A slope of 2^27 or more is never stepped by (|xb - xa| < 2^14,
 * so yb - ya < 8: one row centre at most), so its step, 16 slopes modulo
 * 2^32, is stored without a test (unsigned: no overflow). */
#if STP_WIDE_ARITH /* 64-bit registers: no limit, no narrowing */
typedef int64_t stp_tri_acc;
typedef int32_t stp_tri_x; /* a crossing's x, Q27.4 */
#define STP_TRIANGLE_NARROW(v) 1
#else
typedef uint32_t stp_tri_acc; /* the accumulator modulo 2^32 (two's complement) */
typedef int stp_tri_x;        /* narrow: below 2^14, an int (16 bits on AVR) */
#define STP_TRIANGLE_NARROW(v)                                                                                   \
    ((((uint32_t)STP_TRI_X(&(v)[0]) | (uint32_t)STP_TRI_X(&(v)[1]) | (uint32_t)STP_TRI_X(&(v)[2])) >> 14) == 0)
#endif
typedef struct stp_tri_edge {
    stp_tri_acc acc, step;
} stp_tri_edge;

/* The walk's accumulators carry (STP_HALF_PIXEL - 1) 2^16 more than the
 * crossing's: the first pixel centre at or right of crossing x, (x +
 * STP_HALF_PIXEL - 1) >> SUB, is then acc >> (16 + SUB), one shift a
 * crossing (stp_tri_walk_span).  Narrow, the sum stays below 2^31 (2^30 +
 * 2^20 + 2^19).  Not on 8- and 16-bit cores (no 32-bit multiply): there
 * the high half's int takes the offset and its shift for less than a
 * 32-bit shift by 16 + SUB (ATmega2560 tetra 36 000 cycles a frame). */
#if STP_HAVE_MUL32
#define STP_TRI_ACC_BIAS ((int32_t)(STP_HALF_PIXEL - 1) * 65536)
#else
#define STP_TRI_ACC_BIAS 0
#endif

static inline void stp_tri_edge_start(stp_tri_edge *e, const stp_tri_vertex *a, const stp_tri_vertex *b,
                                      stp_tri_coord yc)
{
#if STP_WIDE_ARITH
    int64_t slope = stp_slope_q16(STP_TRI_X(b) - STP_TRI_X(a), STP_TRI_Y(b) - STP_TRI_Y(a));
    int32_t dy = yc - STP_TRI_Y(a);
    e->acc = (int64_t)STP_TRI_X(a) * 65536 + STP_TRI_ACC_BIAS +
             (slope >= INT32_MIN && slope <= INT32_MAX ? stp_smul32x32(dy, (int32_t)slope) : (int64_t)dy * slope);
    e->step = slope * 16;
#else
    /* |xb - xa| < 2^14: the slope fits 32 bits (|slope| <= 2^30), and the
     * accumulator's value lies within int32 (above), so its sum taken
     * modulo 2^32 in unsigned arithmetic is its value's two's complement;
     * its step is used only while |slope| < 2^27 (above), where it is
     * 16 slopes exactly */
    int32_t slope;
    e->acc = stp_edge_acc_short(a, b, yc, &slope) + (uint32_t)STP_TRI_ACC_BIAS;
    e->step = (uint32_t)slope * 16u;
#endif
}

/* The first pixel centre at or right of the crossing x = floor(acc' /
 * 2^16) of an edge accumulator at a row centre the edge crosses, acc' =
 * acc less STP_TRI_ACC_BIAS: 2^16 times a point between xa and the edge's
 * exact crossing (the slope is truncated toward zero), so 0 <= acc' <
 * 2^30 (x >= 0) and, narrow, its 32 bits are its value and the crossing
 * is below 2^14; (x + STP_HALF_PIXEL - 1) >> SUB = floor((acc' +
 * STP_TRI_ACC_BIAS) / 2^(16 + SUB)) */
static inline stp_tri_x stp_tri_edge_pixel(stp_tri_acc acc)
{
#if STP_HAVE_MUL32
    return (stp_tri_x)(acc >> (16 + STP_SUBPIXEL_BITS));
#else /* STP_TRI_ACC_BIAS 0 */
    return ((stp_tri_x)(acc >> 16) + STP_HALF_PIXEL - 1) >> STP_SUBPIXEL_BITS;
#endif
}

/* The pixels [*p1, *p2] of 0..width-1 (width <= 32767) whose centres c
 * satisfy xl <= c < xr (stp_span_pixels) for crossings 0 <= xl <= xr
 * (within the vertices' x extent), given as a and b, the first centres at
 * or right of xl and xr (stp_tri_edge_pixel).  A file whose crossings may
 * lie left of 0 (raster.c with the guard band, project_private.h) defines
 * STP_TRI_CLAMP_LEFT 1 before it includes this header: a clamped too. */
#ifndef STP_TRI_CLAMP_LEFT
#define STP_TRI_CLAMP_LEFT 0
#endif
static inline int stp_tri_span_pixels(stp_tri_x a, stp_tri_x b, uint32_t width, uint32_t *p1, uint32_t *p2)
{
    if (STP_TRI_CLAMP_LEFT && a < 0)
        a = 0;
    if (b > (stp_tri_x)width)
        b = (stp_tri_x)width;
    if (a >= b)
        return 0;
    *p1 = (uint32_t)a;
    *p2 = (uint32_t)(b - 1);
    return 1;
}

/* The first row whose centre 16 r + 8 lies at or below y (Q27.4, 0 <= y
 * <= 32767 2^SUB: the row fits an int; with the guard band of compact
 * builds, project_private.h, from -2^13: the floor by >>, arithmetic on a
 * negative value with GCC and Clang, which document it, as fix.c's
 * high16 assumes too). */
STP_HOT_INLINE int stp_row_below(stp_tri_coord y)
{
    return (int)((y + STP_HALF_PIXEL - 1) >> STP_SUBPIXEL_BITS);
}

/* A band's rows y0 .. y0 + count - 1, and their extent in subpixels
 * [top, end) = [y0 2^SUB, (y0 + count) 2^SUB) (SUB = STP_SUBPIXEL_BITS,
 * y0 + count <= 32767), both kept: a walk tests each. */
typedef struct stp_band_rows {
    uint32_t y0, count;
    int32_t top, end;
} stp_band_rows;

/* A triangle's walk down its rows in a band: the long edge top-bottom
 * (lng) and the short one (sht: top-mid above row r_mid, mid-bottom from
 * there) at row `row`, to r_last.  Its vertices' y lie in [0, 32767 2^SUB]
 * (the renderer's frames and direct drawing's moved origin; from -2^13
 * with the guard band: stp_row_below), so a row is an int (16 bits on AVR,
 * where each 32-bit step a row costs).
 * stp_tri_walk_start: walk w at the first row of triangle v0 v1 v2 (their
 *   x, y) within the band's rows; 0 when it has none.
 * stp_tri_walk_span: the pixels [*p1, *p2] of 0..width-1 of w's row
 *   between its two crossings; 0 when there is none.
 * stp_tri_walk_next: w a row down; 0 when its row was the last.
 * stp_tri_walk_yc: the centre of w's row, Q27.4. */
typedef struct stp_tri_walk {
    stp_tri_edge lng, sht;
    int row, r_mid, r_last;
    const stp_tri_vertex *top, *mid, *bot;
} stp_tri_walk;

/* The centre of row `row`, Q27.4 (formed where needed: cheaper than
 * stepping it a row, measured) */
STP_HOT_INLINE stp_tri_coord stp_tri_row_centre(int row)
{
    return (stp_tri_coord)row * (1 << STP_SUBPIXEL_BITS) + STP_HALF_PIXEL;
}

STP_HOT_INLINE stp_tri_coord stp_tri_walk_yc(const stp_tri_walk *w)
{
    return stp_tri_row_centre(w->row);
}

STP_HOT_INLINE int stp_tri_walk_start(const stp_tri_vertex *v0, const stp_tri_vertex *v1, const stp_tri_vertex *v2,
                                      const stp_band_rows *band, stp_tri_walk *w)
{
    int r_first, r_last;
    stp_tri_coord yc;
    stp_tri_sort(v0, v1, v2, &w->top, &w->mid, &w->bot);
    /* (a shortcut: the rows below find it too; STP_TRI_BAND_SHORTCUT) */
    if (STP_TRI_BAND_SHORTCUT && (STP_TRI_Y(w->bot) <= band->top || STP_TRI_Y(w->top) >= band->end))
        return 0; /* not in the band */
    /* rows whose centre lies in [top, bottom), in the band */
#if STP_WIDE_ARITH
    /* stp_row_below is monotone, so the y clamped to the band's [top, end)
     * give the rows clamped to its rows: the first row below top is y0,
     * below end y0 + count (the test above leaves each clamped y between
     * the triangle's, a coordinate).  64-bit hosts only: host mesh torus
     * 1 400 instructions a frame fewer, but ARMv6-M's direct frame 10 000
     * more */
    w->r_mid = stp_row_below(STP_TRI_Y(w->mid)); /* the first row below mid's y */
    r_first = stp_row_below(STP_TRI_Y(w->top) > band->top ? STP_TRI_Y(w->top) : (stp_tri_coord)band->top);
    r_last = stp_row_below(STP_TRI_Y(w->bot) < band->end ? STP_TRI_Y(w->bot) : (stp_tri_coord)band->end) - 1;
#else
    r_first = stp_row_below(STP_TRI_Y(w->top));
    r_last = stp_row_below(STP_TRI_Y(w->bot)) - 1;
    w->r_mid = stp_row_below(STP_TRI_Y(w->mid)); /* the first row below mid's y */
    if (r_first < (int)band->y0)
        r_first = (int)band->y0;
    if (r_last > (int)(band->y0 + band->count) - 1)
        r_last = (int)(band->y0 + band->count) - 1;
#endif
    if (r_first > r_last)
        return 0;
    w->row = r_first;
    w->r_last = r_last;
    yc = stp_tri_row_centre(r_first);
    stp_tri_edge_start(&w->lng, w->top, w->bot, yc);
    if (r_first < w->r_mid)
        stp_tri_edge_start(&w->sht, w->top, w->mid, yc);
    else
        stp_tri_edge_start(&w->sht, w->mid, w->bot, yc);
    return 1;
}

STP_HOT_INLINE int stp_tri_walk_span(const stp_tri_walk *w, uint32_t width, uint32_t *p1, uint32_t *p2)
{
    /* (the first centres ordered: the same order as the crossings') */
    stp_tri_x xl = stp_tri_edge_pixel(w->lng.acc), xr = stp_tri_edge_pixel(w->sht.acc);
    if (xl > xr) {
        stp_tri_x x = xl;
        xl = xr;
        xr = x;
    }
    return stp_tri_span_pixels(xl, xr, width, p1, p2);
}

STP_HOT_INLINE int stp_tri_walk_next(stp_tri_walk *w)
{
    if (w->row == w->r_last)
        return 0;
    w->row++;
    w->lng.acc += w->lng.step;
    if (w->row == w->r_mid)
        stp_tri_edge_start(&w->sht, w->mid, w->bot, stp_tri_walk_yc(w));
    else
        w->sht.acc += w->sht.step;
    return 1;
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
                 (slope >= INT32_MIN && slope <= INT32_MAX ? stp_smul32x32(yc - e->ya, (int32_t)slope)
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

/* ---- the polygon raster's set-up: raster.c's draw_polygon and direct
 * drawing's clipped faces (direct_band.c), then each its own spans ----
 * stp_polygon_y_extent: the lowest and highest device y (Q27.4) of
 * polygon v[0..n-1] (n >= 1).
 * stp_polygon_edges: its edges into edges[] (n of room), oriented top to
 * bottom, those no row centre crosses dropped, with their ends' shades
 * when smooth; returns their count.
 * stp_polygon_rows: for a polygon with y extent [ymin, ymax) that reaches
 * the band's [top, end) (Q27.4, >= 0), the rows whose centres lie in both,
 * at most last_row, in *first and *last (*first > *last: none), and its ne
 * edges put on the first one's centre. */
STP_HOT_INLINE void stp_polygon_y_extent(const stp_instr *v, int n, int32_t *ymin, int32_t *ymax)
{
    int32_t lo = v[0].y, hi = v[0].y;
    int i;
    for (i = 1; i < n; i++) {
        if (v[i].y < lo)
            lo = v[i].y;
        if (v[i].y > hi)
            hi = v[i].y;
    }
    *ymin = lo;
    *ymax = hi;
}

STP_HOT_INLINE int stp_polygon_edges(stp_edge *edges, const stp_instr *v, int n, int smooth)
{
    int i, ne = 0;
    for (i = 0; i < n; i++) {
        const stp_instr *a = &v[i], *b = &v[i + 1 == n ? 0 : i + 1];
        int dir = stp_edge_setup(&edges[ne], a->x, a->y, b->x, b->y);
        if (dir == 0)
            continue;
#if STP_WITH_GOURAUD
        if (smooth)
            stp_edge_shades(&edges[ne], dir > 0 ? a->shade : b->shade, dir > 0 ? b->shade : a->shade);
#else
        (void)smooth;
#endif
        ne++;
    }
    return ne;
}

STP_HOT_INLINE void stp_polygon_rows(stp_edge *edges, int ne, int32_t ymin, int32_t ymax, int32_t top, int32_t end,
                                     int32_t last_row, int smooth, int32_t *first, int32_t *last)
{
    *first = (ymin < top ? top : ymin) >> STP_SUBPIXEL_BITS;
    *last = (ymax > end ? end : ymax) >> STP_SUBPIXEL_BITS;
    if (*last > last_row)
        *last = last_row;
    stp_edges_start(edges, ne, *first * (1 << STP_SUBPIXEL_BITS) + STP_HALF_PIXEL, smooth);
}

#endif
