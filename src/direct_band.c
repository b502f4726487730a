/* SPDX-License-Identifier: MIT */
/* Direct drawing's band fill (include/stipple/direct.h): the faces a frame
 * drew, painted into one band of a 1-bit picture with the full renderer's
 * rule (include/stipple/render.h, edge_walk_private.h): a pixel belongs to a
 * face when its centre (16 p + 8 in Q4) lies in the face, left and top
 * edges included, right and bottom excluded.  An edge (xa, ya) - (xb, yb),
 * oriented downwards, crosses row centre yc (ya <= yc < yb) at
 * floor((xa 2^16 + (yc - ya) slope) / 2^16), slope = trunc(2^16 (xb - xa)
 * / (yb - ya)): the full renderer's value, which it accumulates row by row
 * in 64 bits; here in 32 (band_edge): device coordinates below 2^13 in
 * magnitude keep xa 2^16 below 2^29 and (yc - ya) slope below
 * 2^16 |xb - xa| < 2^30.  Runs go through the one 1-bit run filler
 * (dither.c), in rows or in the panel's pages (stp_band_layout).
 *
 * Device coordinates (Q4, [-8192, 8192)), pixel rows and columns and their
 * sums here stay below 2^14 in magnitude: plain int (16 bits at least);
 * only the crossings' sums are 32-bit. */
#include "stipple/direct.h"

#include "direct_private.h"
#include "run_fill_private.h" /* stp_halftone_fill_bits, the one run filler */

#define SUB 4
#define HALF (1 << (SUB - 1))

/* floor(v / 16) for any int (as stp_asr32; on 32-bit cores the
 * complement form, which gcc folds and schedules better there) */
STP_DIRECT_CALL int floor16(int v)
{
#if !STP_HAVE_MUL32
    if (-1 >> 1 == -1)
        return v >> SUB;
#endif
    return v >= 0 ? v >> SUB : (int)~(~(unsigned)v >> SUB);
}

/* The first row whose centre 16 y + 8 is at or below Q4 ordinate v:
 * ceil((v - 8) / 16). */
static int row_at(int v)
{
    return floor16(v + HALF - 1);
}

/* An edge oriented downwards over the rows [y_lo, y_hi) whose centres it
 * crosses; acc = xa 2^16 + (yc - ya) slope at the next row to draw, then
 * stepped by 16 slope a row (unsigned: the step past an edge's last row,
 * never used, may wrap; an edge crossing two rows or more has
 * 16 |slope| <= 2^16 |xb - xa| < 2^30): the same integers as the product
 * formed at each row. */
typedef struct band_edge {
    int y_lo, y_hi;
    uint32_t acc, step;
} band_edge;

/* Edge a - b into *e, its crossings from row y_first on; 0 when no row
 * centre at or below y_first crosses it.  The slope's division is the
 * only one per edge (setup, not per pixel). */
STP_DIRECT_CALL int edge_make(band_edge *e, const stp_direct_point *a, const stp_direct_point *b, int y_first)
{
    int xa = a->dx, ya = a->dy, xb = b->dx, yb = b->dy, dx, y0;
    int32_t slope;
    uint32_t q;
    if (ya > yb) {
        xa = b->dx;
        ya = b->dy;
        xb = a->dx;
        yb = a->dy;
    }
    e->y_lo = row_at(ya);
    e->y_hi = row_at(yb);
    y0 = e->y_lo > y_first ? e->y_lo : y_first;
    if (y0 >= e->y_hi)
        return 0; /* horizontal, between two row centres, or above the band */
    dx = xb - xa;
    q = stp_direct_udiv((uint32_t)(dx < 0 ? -dx : dx) << 16, (uint32_t)(yb - ya)); /* < 2^30 */
    slope = dx < 0 ? -(int32_t)q : (int32_t)q;
    e->acc = (uint32_t)((int32_t)xa * 65536 + (int32_t)(y0 * 16 + HALF - ya) * slope);
    e->step = (uint32_t)slope << SUB;
    e->y_lo = y0;
    return 1;
}

/* The byte of cell row (y mod 4) at intensity: bit 7 - x ON where
 * intensity > threshold (x mod 4), repeated. */
static uint8_t pattern_of(const uint8_t *cell, int y, uint8_t intensity)
{
    const uint8_t *t = &cell[(y & 3) * 4];
    unsigned p = 0, x;
    STP_UNROLL4
    for (x = 0; x < 4; x++)
        p = p << 1 | (unsigned)(intensity > t[x]);
    return (uint8_t)(p << 4 | p);
}

/* One face's rows within [y_top, y_bottom) (pixel rows of the band);
 * page_shift 0: band row r is band + r stride (STP_BAND_ROWS); 3: its page
 * starts at band + (r / 8) stride, its bit 1 << (r mod 8) (STP_BAND_PAGES,
 * y_top a multiple of 8).  A row centre inside the face lies on exactly
 * two of its edges' half-open row ranges, one outside on none. */
static void draw_face(const stp_direct_frame *f, const stp_direct_point *p[3], uint8_t intensity,
                      uint8_t *band, size_t stride, int page_shift, int y_top, int y_bottom)
{
    band_edge e[3];
    int y, y_start = y_bottom, y_end = y_top, i, n = 0;
    for (i = 0; i < 3; i++)
        if (edge_make(&e[n], p[i], p[i == 2 ? 0 : i + 1], y_top)) {
            y_start = e[n].y_lo < y_start ? e[n].y_lo : y_start;
            y_end = e[n].y_hi > y_end ? e[n].y_hi : y_end;
            n++;
        }
    y_end = y_end < y_bottom ? y_end : y_bottom;
    for (y = y_start; y < y_end; y++) {
        int x[2], c = 0, a, b;
        for (i = 0; i < n; i++)
            if (e[i].y_lo <= y && y < e[i].y_hi) {
                if (c < 2)
                    x[c++] = (int)stp_asr32((int32_t)e[i].acc, 16);
                e[i].acc += e[i].step;
            }
        if (c < 2)
            continue;
        /* pixels p with x0 <= 16 p + 8 < x1, within the panel */
        a = row_at(x[0] < x[1] ? x[0] : x[1]);
        b = row_at(x[0] < x[1] ? x[1] : x[0]) - 1;
        a = a < 0 ? 0 : a;
        b = b < (int)f->width ? b : (int)f->width - 1;
        if (a <= b)
            stp_halftone_fill_bits(band + ((unsigned)(y - y_top) >> page_shift) * stride,
                                   (uint8_t)(page_shift ? 1u << (y & 7) : 0u), (unsigned)a, (unsigned)b,
                                   pattern_of(f->cell, y, intensity));
    }
}

/* The shift of f's layout (*page_shift: 0 rows, 3 pages) and the band's
 * lines (*lines: rows or pages) for a band of rows rows at y0, stride
 * bytes a line: STP_OK, STP_ERR_ARG when the arguments do not fit, or
 * STP_ERR_UNSUPPORTED for pages without STP_WITH_PAGES (direct.h). */
static int band_shape(const stp_direct_frame *f, size_t stride, uint16_t y0, uint16_t rows, size_t *lines,
                      int *page_shift)
{
    if (f->layout == STP_BAND_PAGES) {
        if (!STP_WITH_PAGES)
            return STP_ERR_UNSUPPORTED; /* the page layout compiled out (config.h) */
        *lines = ((size_t)rows + 7u) >> 3;
        *page_shift = 3;
        return stride < f->width || (y0 & 7u) != 0 ? STP_ERR_ARG : STP_OK;
    }
    *lines = rows;
    *page_shift = 0;
    return f->layout != STP_BAND_ROWS || stride < ((size_t)f->width + 7u) / 8u ? STP_ERR_ARG : STP_OK;
}

int stp_direct_draw_band(const stp_direct_frame *f, uint8_t *band, size_t stride, uint16_t y0,
                         uint16_t rows)
{
    const uint16_t *k;
    size_t i, lines;
    uint16_t t;
    int page_shift = 0, status;
    if (f == 0 || band == 0 || f->mesh == 0 || f->points == 0 || f->faces == 0 || f->cell == 0 || rows == 0 ||
        (uint32_t)y0 + rows > f->height)
        return STP_ERR_ARG;
    status = band_shape(f, stride, y0, rows, &lines, &page_shift);
    if (status != STP_OK)
        return status;
    for (i = 0; i < lines * stride; i++)
        band[i] = 0;
    k = f->mesh->triangles;
    for (t = 0; t < f->mesh->triangle_count; t++, k += 3) {
        const stp_direct_point *p[3];
        int top, bottom;
        if (f->faces[t] == 0)
            continue;
        p[0] = &f->points[k[0]];
        p[1] = &f->points[k[1]];
        p[2] = &f->points[k[2]];
        /* the rows its vertices span, against the band's, before any
         * edge's division */
        top = p[0]->dy < p[1]->dy ? p[0]->dy : p[1]->dy;
        top = p[2]->dy < top ? p[2]->dy : top;
        bottom = p[0]->dy > p[1]->dy ? p[0]->dy : p[1]->dy;
        bottom = p[2]->dy > bottom ? p[2]->dy : bottom;
        if (row_at(bottom) <= (int)y0 || row_at(top) >= (int)y0 + (int)rows)
            continue;
        draw_face(f, p, (uint8_t)f->faces[t], band, stride, page_shift, y0, (int)y0 + (int)rows);
    }
    return STP_OK;
}
