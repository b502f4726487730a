/* SPDX-License-Identifier: MIT */
/* Direct drawing's band fill (include/stipple/direct.h): the faces a frame
 * drew, painted into one band of a 1-bit picture with the full renderer's
 * rule (include/stipple/render.h, raster_private.h): a pixel belongs to a
 * face when its centre (16 p + 8 in Q4) lies in the face, left and top
 * edges included, right and bottom excluded.  An edge (xa, ya) - (xb, yb),
 * oriented downwards, crosses row centre yc (ya <= yc < yb) at
 * floor((xa 2^16 + (yc - ya) slope) / 2^16), slope = trunc(2^16 (xb - xa)
 * / (yb - ya)): the full renderer's value, which it accumulates row by row
 * in 64 bits; here in 32 (edge_x): device coordinates below 2^13 in
 * magnitude keep xa 2^16 below 2^29 and (yc - ya) slope below
 * 2^16 |xb - xa| < 2^30.  Runs go through the one 1-bit run filler
 * (dither.c), in rows or in the panel's pages (stp_band_layout). */
#include "stipple/direct.h"

#include "direct_private.h"
#include "run_fill_private.h" /* stp_halftone_fill_bits, the one run filler */

#define SUB 4
#define HALF (1 << (SUB - 1))

/* floor(v / 16) */
static int32_t floor16(int32_t v)
{
    return stp_direct_asr(v, SUB);
}

/* The crossing at row y (centre yc = 16 y + 8) is
 * floor((xa 2^16 + (yc - ya) slope) / 2^16).  With a multiply instruction
 * (arith_private.h, STP_HAVE_MUL32) it is formed each row; without one
 * (AVR: a 32-bit product is a library call) acc holds the sum at row
 * acc_row, formed once when the face's loop first meets the edge and then
 * stepped by 16 slope a row: the same integer, so the same crossings. */
typedef struct band_edge {
    int32_t xa, ya, yb, slope;
#if !STP_HAVE_MUL32
    int32_t acc_row;
    uint32_t acc, step; /* unsigned: the step past an edge's last row may wrap, unused */
#endif
} band_edge;

/* e's crossing of row y (its centre yc inside [ya, yb)); rows asked in
 * increasing order.  Below 2^30 in magnitude. */
static int32_t edge_x(band_edge *e, int32_t y, int32_t yc)
{
#if STP_HAVE_MUL32
    (void)y;
    return stp_direct_asr(e->xa * 65536 + (yc - e->ya) * e->slope, 16);
#else
    int32_t x;
    if (e->acc_row != y)
        e->acc = (uint32_t)(e->xa * 65536 + (yc - e->ya) * e->slope);
    x = stp_direct_asr((int32_t)e->acc, 16);
    e->acc += e->step;
    e->acc_row = y + 1;
    return x;
#endif
}

/* Edge a - b oriented downwards into *e; 0 when no row centre crosses it. */
static int edge_make(band_edge *e, const stp_direct_point *a, const stp_direct_point *b)
{
    int32_t xa = a->dx, ya = a->dy, xb = b->dx, yb = b->dy, dx;
    uint32_t q;
    if (ya > yb) {
        xa = b->dx;
        ya = b->dy;
        xb = a->dx;
        yb = a->dy;
    }
    if (floor16(ya + HALF - 1) == floor16(yb + HALF - 1))
        return 0; /* horizontal, or between two row centres */
    dx = xb - xa;
    q = stp_direct_udiv(stp_direct_abs(dx) << 16, (uint32_t)(yb - ya)); /* < 2^30 */
    e->xa = xa;
    e->ya = ya;
    e->yb = yb;
    e->slope = dx < 0 ? -(int32_t)q : (int32_t)q;
#if !STP_HAVE_MUL32
    e->step = (uint32_t)e->slope << SUB;
    e->acc_row = INT32_MIN; /* no row yet */
#endif
    return 1;
}

/* The byte of cell row (y mod 4) at intensity: bit 7 - x ON where
 * intensity > threshold (x mod 4), repeated. */
static uint8_t pattern_of(const uint8_t *cell, uint32_t y, uint32_t intensity)
{
    const uint8_t *t = &cell[(y & 3u) * 4u];
    uint32_t p = (uint32_t)(intensity > t[0]) << 7 | (uint32_t)(intensity > t[1]) << 6 |
                 (uint32_t)(intensity > t[2]) << 5 | (uint32_t)(intensity > t[3]) << 4;
    return (uint8_t)(p | p >> 4);
}

/* Row y's pixels whose centres lie in [x0, x1) (Q4), within the panel,
 * set to the face's pattern in the band; page_shift as for draw_face.
 * Apart from draw_face so that one finds the crossings and this one
 * fills them. */
static inline void fill_row(const stp_direct_frame *f, uint8_t *band, size_t stride, int page_shift,
                            int32_t y_top, int32_t y, int32_t x0, int32_t x1, uint32_t intensity)
{
    /* pixel p with x0 <= 16 p + 8 < x1 */
    int32_t a = floor16(x0 - HALF + 15), b = floor16(x1 - HALF + 15) - 1;
    a = a < 0 ? 0 : a;
    b = b > (int32_t)f->width - 1 ? (int32_t)f->width - 1 : b;
    if (a <= b)
        stp_halftone_fill_bits(band + (size_t)((uint32_t)(y - y_top) >> page_shift) * stride,
                               (uint8_t)(page_shift ? 1u << (y & 7) : 0u), (uint32_t)a, (uint32_t)b,
                               pattern_of(f->cell, (uint32_t)y, intensity));
}

/* One face's rows within [y_top, y_bottom) (pixel rows of the band);
 * page_shift 0: band row r is band + r stride (STP_BAND_ROWS); 3: its page
 * starts at band + (r / 8) stride, its bit 1 << (r mod 8) (STP_BAND_PAGES,
 * y_top a multiple of 8). */
static void draw_face(const stp_direct_frame *f, const stp_direct_point *p[3], uint32_t intensity,
                      uint8_t *band, size_t stride, int page_shift, int32_t y_top, int32_t y_bottom)
{
    band_edge e[3];
    int32_t ymin = p[0]->dy, ymax = p[0]->dy, y, y_first, y_last;
    int i, n = 0;
    for (i = 1; i < 3; i++) {
        ymin = p[i]->dy < ymin ? p[i]->dy : ymin;
        ymax = p[i]->dy > ymax ? p[i]->dy : ymax;
    }
    if (ymax <= y_top * 16 || ymin >= y_bottom * 16)
        return;
    for (i = 0; i < 3; i++)
        n += edge_make(&e[n], p[i], p[i == 2 ? 0 : i + 1]);
    y_first = floor16(ymin) < y_top ? y_top : floor16(ymin);
    y_last = floor16(ymax) >= y_bottom ? y_bottom - 1 : floor16(ymax);
    for (y = y_first; y <= y_last; y++) {
        int32_t yc = y * 16 + HALF, x[2], a;
        int c = 0;
        for (i = 0; i < n && c < 2; i++)
            if (e[i].ya <= yc && yc < e[i].yb)
                x[c++] = edge_x(&e[i], y, yc);
        if (c < 2)
            continue;
        if (x[0] > x[1]) {
            a = x[0];
            x[0] = x[1];
            x[1] = a;
        }
        fill_row(f, band, stride, page_shift, y_top, y, x[0], x[1], intensity);
    }
}

int stp_direct_draw_band(const stp_direct_frame *f, uint8_t *band, size_t stride, uint16_t y0,
                         uint16_t rows)
{
    uint32_t i, t, lines;
    int page_shift = 0;
    if (f == 0 || band == 0 || f->mesh == 0 || f->points == 0 || f->faces == 0 || f->cell == 0 || rows == 0 ||
        (uint32_t)y0 + rows > f->height)
        return STP_ERR_ARG;
    if (f->layout == STP_BAND_PAGES) {
        if (stride < f->width || (y0 & 7u) != 0)
            return STP_ERR_ARG;
        lines = ((uint32_t)rows + 7u) >> 3;
        page_shift = 3;
    } else {
        if (f->layout != STP_BAND_ROWS || stride < ((uint32_t)f->width + 7u) / 8u)
            return STP_ERR_ARG;
        lines = rows;
    }
    for (i = 0; i < lines * stride; i++)
        band[i] = 0;
    for (t = 0; t < f->mesh->triangle_count; t++) {
        const uint16_t *k = &f->mesh->triangles[3 * t];
        const stp_direct_point *p[3];
        if (f->faces[t] == 0)
            continue;
        p[0] = &f->points[k[0]];
        p[1] = &f->points[k[1]];
        p[2] = &f->points[k[2]];
        draw_face(f, p, f->faces[t] & 0xFFu, band, stride, page_shift, y0, (int32_t)y0 + rows);
    }
    return STP_OK;
}
