/* SPDX-License-Identifier: MIT */
/* Private: what direct drawing's two band fills share (direct_band.c, in
 * mesh or painter's order; direct_depth.c, depth-tested): the triangle
 * walk at the moved origin, a face's pattern byte, the band's rows and
 * the set-up of a face the picture's edge cuts.  Device coordinates (Q4,
 * [-8192, 8192)), pixel rows and columns and their sums stay below 2^14
 * in magnitude: plain int (16 bits at least), in the walk too; only its
 * crossings' accumulators are 32-bit. */
#ifndef STIPPLE_DIRECT_BAND_PRIVATE_H
#define STIPPLE_DIRECT_BAND_PRIVATE_H

#include "stipple/direct.h"

#include "direct_private.h"
#include "run_fill_private.h" /* stp_halftone_fill_bits, the one run filler */
#include "direct_clip_private.h" /* faces the picture's edge cuts */

/* a helper one of the two files may not call (the compact form has no
 * depth test) */
#if defined(__GNUC__)
#define DIRECT_BAND_FN static __attribute__((unused))
#else
#define DIRECT_BAND_FN static
#endif

/* Direct drawing's device coordinates lie in [-DEVICE_ORIGIN,
 * DEVICE_ORIGIN) (Q4, direct.c); moved by DEVICE_ORIGIN (a whole number
 * of pixels, ORIGIN_PIXELS) they are the walk's x, y in [0, 2^14): >= 0,
 * an int, and narrow (STP_TRIANGLE_NARROW), with the same crossings and
 * pixels, moved by ORIGIN_PIXELS.  The walk reads the points themselves. */
#define DEVICE_ORIGIN 8192
#define STP_TRI_VERTEX stp_direct_point
#define STP_TRI_COORD int
#define STP_TRI_X(p) ((int)(p)->dx + DEVICE_ORIGIN)
#define STP_TRI_Y(p) ((int)(p)->dy + DEVICE_ORIGIN)
#include "edge_walk_private.h" /* the triangle walk, the one scan converter of triangles */

#define SUB STP_SUBPIXEL_BITS
#define ORIGIN_PIXELS (DEVICE_ORIGIN >> SUB)

/* The byte of cell row (y mod 4) at intensity: bit 7 - x ON where
 * intensity > threshold (x mod 4), repeated. */
DIRECT_BAND_FN uint8_t pattern_of(const uint8_t *cell, int y, uint8_t intensity)
{
    const uint8_t *t = &cell[(y & 3) * 4];
    unsigned p = 0, x;
    STP_UNROLL4
    for (x = 0; x < 4; x++)
        p = p << 1 | (unsigned)(intensity > t[x]);
    return (uint8_t)(p << 4 | p);
}

/* Rows y0 .. y0 + rows - 1 as the walk takes them (at the moved origin) */
DIRECT_BAND_FN void band_rows_at(stp_band_rows *band_rows, uint16_t y0, uint16_t rows)
{
    band_rows->y0 = (uint32_t)y0 + ORIGIN_PIXELS;
    band_rows->count = rows;
    band_rows->top = (int32_t)(band_rows->y0 << SUB);
    band_rows->end = (int32_t)((band_rows->y0 + rows) << SUB);
}

/* Whether face k's corners all lie above the band's top or all at or
 * below its end (rows: at the moved origin): then it reaches none of the
 * band's row centres, and is left out before the walk's set-up */
STP_HOT_INLINE int face_off_band(const stp_direct_frame *f, const uint16_t k[3], const stp_band_rows *rows)
{
    int a = STP_TRI_Y(&f->points[k[0]]), b = STP_TRI_Y(&f->points[k[1]]), c = STP_TRI_Y(&f->points[k[2]]);
    return (a < rows->top && b < rows->top && c < rows->top) || (a >= rows->end && b >= rows->end && c >= rows->end);
}

#if !STP_DIRECT_COMPACT
/* Whether a face the side planes alone cut (every corner projected, so in
 * front of the near plane) reaches none of the row centres of the band
 * [top, end) (Q4, device coordinates): clipped, it lies within its
 * corners' projection (a projection is continuous in front of the eye),
 * up to the roundings: below a subpixel for the corners' projection, below
 * one for the clipped vertices' and, for corners at least zmin raw from
 * the eye, at most one for the clipped points' last bits.  (Each of the
 * four side planes' clips moves a new point at most a raw unit off the
 * face, so at most 4 in y and z; a raw unit in y or z moves a device y by
 * at most (A + |y / z| A) / z subpixels, A = focal / 2^(F - 4), and |y / z|
 * A <= 8 height inside the picture: zmin = 4 (A + 8 height) keeps the
 * whole below one; nearer corners, where it grows without bound, are
 * clipped first.)  So all three corners at most top + 4 leave the clipped
 * polygon's y below top + 7, above top + 8, the band's first centre; all
 * at least end - 4 leave it above end - 7, below end - 8, its last (the
 * clamp into the picture keeps both).  0 for a face the near plane cuts (a
 * corner unprojected): clipped first. */
STP_HOT_INLINE int corners_off_band(const stp_direct_frame *f, const uint16_t k[3], int32_t top, int32_t end)
{
    const stp_direct_point *p = &f->points[k[0]], *q = &f->points[k[1]], *r = &f->points[k[2]];
    int32_t a = p->dy, b = q->dy, c = r->dy;
    int32_t zmin = ((f->focal >> (STP_FIX_FRAC_BITS - SUB)) + ((int32_t)f->height << (SUB - 1))) * 4;
    if (a == STP_DIRECT_UNPROJECTED || b == STP_DIRECT_UNPROJECTED || c == STP_DIRECT_UNPROJECTED ||
        p->z < zmin || q->z < zmin || r->z < zmin)
        return 0;
    return (a <= top + 4 && b <= top + 4 && c <= top + 4) || (a >= end - 4 && b >= end - 4 && c >= end - 4);
}

/* A face the picture's edge cuts (STP_DIRECT_FACE_CLIPPED) as the
 * renderer stores it, for the band rows: clipped and projected
 * (stp_direct_face_clip) into v, set up by the polygon raster's set-up
 * (edge_walk_private.h's stp_polygon_*, raster.c's draw_polygon's) into
 * edges, its rows in the band *first .. *last in device coordinates (not
 * moved); returns its edges, 0 when it leaves the band empty. */
STP_HOT_INLINE int clipped_face_rows(const stp_direct_frame *f, const uint16_t k[3], const stp_band_rows *rows,
                                     stp_instr v[STP_DIRECT_CLIP_MAX], int *n, stp_edge edges[STP_DIRECT_CLIP_MAX],
                                     int32_t *first, int32_t *last)
{
    int32_t ymin, ymax, top = rows->top - DEVICE_ORIGIN, end = rows->end - DEVICE_ORIGIN,
                        y0 = (int32_t)rows->y0 - ORIGIN_PIXELS;
    int ne;
    /* a face crossing a side of the picture: left out of the bands it
     * cannot reach before its clip (each clip a few thousand instructions
     * on a Cortex-M0+) */
    if (corners_off_band(f, k, top, end))
        return 0;
    *n = stp_direct_face_clip(f, k, v);
    if (*n < 3)
        return 0;
    stp_polygon_y_extent(v, *n, &ymin, &ymax);
    if (ymax <= top || ymin >= end)
        return 0;
    ne = stp_polygon_edges(edges, v, *n, 0);
    stp_polygon_rows(edges, ne, ymin, ymax, top, end, y0 + (int32_t)rows->count - 1, 0, first, last);
    return ne;
}
#endif

#endif
