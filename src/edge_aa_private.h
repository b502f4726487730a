/* SPDX-License-Identifier: MIT */
/* Private: coverage-weighted shade on the pixels just outside a polygon's
 * edges (stp_output.edge_aa, STP_WITH_EDGE_AA; docs/edge-aa.md), called by
 * the polygon raster (raster.c) once per row of a polygon after its spans.
 *
 * Which pixels: those of the polygon's rows whose centres lie outside it
 * (the fill rule gives them to no span of the polygon) but near one of the
 * row's crossings.  The pixels the polygon owns keep its full shade, so an
 * edge two polygons of a mesh share never lets the background through (the
 * seam that blending owned pixels too would leave, ~c(1 - c) of background).
 *
 * Coverage: the crossing x_c (the edge's x at the row centre) and the edge
 * slope s (pixels of x per row) give the edge function at a pixel centre
 * x: its horizontal distance h = |x - x_c| pixels outside, divided by
 * 1 + |s| (the L1 length of the edge normal (1, -s)), so
 *     coverage = clamp(1/2 - h / (1 + |s|), 0, 1).
 * Exact for vertical and horizontal edges and wherever the coverage is 0,
 * 1/2 or 1; elsewhere it is the straight line through the exact curve's
 * ends (at 45 degrees the exact area is 2 c^2 for c = the formula below
 * 1/2: error at most 1/8).  Near a vertex the edge's line is taken beyond
 * the vertex; each pixel's coverage is capped by the other crossing of its
 * span, which narrows that over-reach for thin polygons.  tests/edge_aa
 * measures the error against exact areas (double precision). */
#ifndef STIPPLE_EDGE_AA_PRIVATE_H
#define STIPPLE_EDGE_AA_PRIVATE_H

#include "renderer_state.h"

#if STP_WITH_EDGE_AA

/* An edge's slope as the crossings carry it (stp_crossing.slope): |x
 * change per row| in pixels with 8 fractional bits, clamped to 2^23 (32768
 * pixels a row: wider than any device).  step: stp_edge.step (x change per
 * row in Q4 units with 16 fractional bits, |step| < 2^40). */
static inline int32_t stp_edge_aa_slope(int64_t step)
{
    int64_t s = (step < 0 ? -step : step) >> 12;
    return s > ((int64_t)1 << 23) ? (int32_t)1 << 23 : (int32_t)s;
}

/* What the coverage pass writes into, set once per stp_renderer_render:
 * the drawn format (GREY8 for a MONO1 port: the band is grey and is
 * thresholded or diffused as it is flushed), the output's gamma and style
 * table, the style levels, the device width. */
typedef struct stp_edge_aa {
    const stp_output *out;
    stp_pixel_format format;
    int levels;
    uint32_t width;
} stp_edge_aa;

/* Blend the pixels just outside the spans of one polygon row (crossings c,
 * nc of them, sorted by x, paired into spans as the raster pairs them)
 * with the polygon's shade, each in proportion to its coverage.
 *   row     the band row (the drawn format's bytes)
 *   zrow    its Z buffer row, or NULL (no Z buffer): with one, a pixel is
 *           blended only where the polygon's depth plane at its centre is
 *           nearer than the entry, and the entry is left as it was (the
 *           pixel is not the polygon's)
 *   d_row   with zrow: the plane's depth at x = 0 of the row centre, ddx its
 *           change per Q4 unit of x (Q12, as raster.c's depth planes)
 *   style   a style index 1..levels, or a colour (STP_COLOUR_FLAG) on RGB888
 *   smooth  1: each pixel takes the shade of its nearest crossing
 *           (c[k].shade, stp_fix in [0, 1]) instead of the style's
 * Opaque polygons only (the caller passes no transparent one). */
void stp_edge_aa_row(const stp_edge_aa *aa, uint8_t *row, uint16_t *zrow, const stp_crossing *c,
                     int nc, int32_t style, int smooth, int64_t d_row, int64_t ddx);

/* A finished grey band row (width levels) made a MONO1 row in place, each
 * pixel against the cell's threshold at (x, y) (the same test the 1-bit
 * spans make), the padding bits past width 0. */
void stp_edge_aa_threshold_row(uint8_t *row, uint32_t width, uint32_t y, const stp_cell *cell);

/* The same test, the bits going to row y's page line of a
 * STP_PIXEL_MONO1_PAGES band drawn as grey rows (stp_mono_page_from_bytes:
 * line on a grey row already made bits, or on row itself). */
void stp_edge_aa_threshold_page(uint8_t *row, uint32_t width, uint32_t y, const stp_cell *cell, uint8_t *line);

#endif

#endif
