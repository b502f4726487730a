/* SPDX-License-Identifier: MIT */
/* Direct drawing's band fill (include/stipple/direct.h): the faces a frame
 * drew, painted into one band of a 1-bit picture with the full renderer's
 * rule (include/stipple/render.h, edge_walk_private.h): a pixel belongs to a
 * face when its centre (16 p + 8 in Q4) lies in the face, left and top
 * edges included, right and bottom excluded.  The faces' rows come from the
 * triangle walk the renderer's triangle raster uses (edge_walk_private.h:
 * the same crossings, so the same pixels for the same device positions);
 * their runs go through the one 1-bit run filler (dither.c), in rows or in
 * the panel's pages (stp_band_layout); the faces in mesh order, or in the
 * frame's painter's order (stp_direct_frame_sort, direct.c).
 *
 * Device coordinates (Q4, [-8192, 8192)), pixel rows and columns and their
 * sums here stay below 2^14 in magnitude: plain int (16 bits at least),
 * in the walk too; only its crossings' accumulators are 32-bit. */
#include "stipple/direct.h"

#include "direct_band_private.h" /* the walk at the moved origin, the band's helpers */

/* One face's rows within the band's (rows: at the moved origin), through
 * the triangle walk (edge_walk_private.h), which also leaves out a face
 * outside the band before any edge's division; page_shift 0: band row r
 * is band + r stride (STP_BAND_ROWS); 3: its page starts at band + (r / 8)
 * stride, its bit 1 << (r mod 8) (STP_BAND_PAGES, the band's first row a
 * multiple of 8). */
static void draw_face(const stp_direct_frame *f, const uint16_t k[3], uint8_t intensity, uint8_t *band,
                      size_t stride, int page_shift, const stp_band_rows *rows)
{
    stp_tri_walk w;
    uint32_t p1, p2;
    if (!stp_tri_walk_start(&f->points[k[0]], &f->points[k[1]], &f->points[k[2]], rows, &w))
        return;
    do {
        /* pixels ORIGIN_PIXELS .. ORIGIN_PIXELS + width - 1 are the panel's */
        if (stp_tri_walk_span(&w, ORIGIN_PIXELS + (uint32_t)f->width, &p1, &p2) && p2 >= ORIGIN_PIXELS) {
            unsigned r = (unsigned)(w.row - (int)rows->y0); /* the band's row */
            p1 = p1 < ORIGIN_PIXELS ? ORIGIN_PIXELS : p1;
            stp_halftone_fill_bits(band + (r >> page_shift) * stride,
                                   (uint8_t)(page_shift ? 1u << (r & 7) : 0u), (unsigned)(p1 - ORIGIN_PIXELS),
                                   (unsigned)(p2 - ORIGIN_PIXELS), pattern_of(f->cell, (int)(w.row & 3), intensity));
        }
    } while (stp_tri_walk_next(&w));
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


/* The checks of stp_direct_draw_band, the band cleared and its rows at
 * the moved origin (*band_rows) and layout shift: STP_OK or the error */
STP_HOT_INLINE int band_start(const stp_direct_frame *f, uint8_t *band, size_t stride, uint16_t y0, uint16_t rows,
                              int *page_shift, stp_band_rows *band_rows)
{
    size_t i, lines;
    int status;
    if (f == 0 || band == 0 || f->mesh == 0 || f->points == 0 || f->faces == 0 || f->cell == 0 || rows == 0 ||
        (uint32_t)y0 + rows > f->height)
        return STP_ERR_ARG;
    status = band_shape(f, stride, y0, rows, &lines, page_shift);
    if (status != STP_OK)
        return status;
    for (i = 0; i < lines * stride; i++)
        band[i] = 0;
    band_rows_at(band_rows, y0, rows);
    return STP_OK;
}

#if !STP_DIRECT_COMPACT
/* A face the picture's edge cuts, as the renderer draws it
 * (clipped_face_rows): each row's crossings into runs of the one run
 * filler; out of line */
STP_NOINLINE void draw_clipped_face(const stp_direct_frame *f, const uint16_t k[3], uint8_t intensity, uint8_t *band,
                                    size_t stride, int page_shift, const stp_band_rows *rows)
{
    stp_instr v[STP_DIRECT_CLIP_MAX];
    stp_edge edges[STP_DIRECT_CLIP_MAX];
    stp_crossing crossings[STP_DIRECT_CLIP_MAX];
    int32_t y, first, last, y0 = (int32_t)rows->y0 - ORIGIN_PIXELS;
    int n, ne = clipped_face_rows(f, k, rows, v, &n, edges, &first, &last);
    if (ne == 0)
        return;
    for (y = first; y <= last; y++) {
        int nc = stp_edges_row(edges, ne, y * (1 << SUB) + STP_HALF_PIXEL, 0, crossings), c;
        unsigned r = (unsigned)(y - y0); /* the band's row */
        uint32_t p1, p2;
        for (c = 0; c + 1 < nc; c += 2)
            if (stp_span_pixels(crossings[c].x, crossings[c + 1].x, f->width, &p1, &p2))
                stp_halftone_fill_bits(band + (r >> page_shift) * stride, (uint8_t)(page_shift ? 1u << (r & 7) : 0u),
                                       (unsigned)p1, (unsigned)p2, pattern_of(f->cell, (int)y, intensity));
    }
}

/* The drawn faces among count triangles k[0..2], k[3..5], ... with faces
 * (0: not drawn, else 256 + intensity) into the band; the one caller of
 * draw_face, which so stays in line (a second caller cost the M0+ frame
 * 24 000 instructions), a call of its own for both orders */
STP_NOINLINE void draw_faces(const stp_direct_frame *f, const uint16_t *k, const uint16_t *faces, uint16_t count,
                             uint8_t *band, size_t stride, int page_shift, const stp_band_rows *rows)
{
    uint16_t t;
    for (t = 0; t < count; t++, k += 3) {
        if (faces[t] != 0)
            draw_face(f, k, (uint8_t)faces[t], band, stride, page_shift, rows);
    }
}

/* The faces of f's painter's order (every entry a drawn face) into the
 * band, one at a time; clipping (a constant at each call) when some are
 * clipped (STP_DIRECT_FACE_CLIPPED) */
STP_HOT_INLINE void draw_in_order(const stp_direct_frame *f, uint8_t *band, size_t stride, int page_shift,
                                  const stp_band_rows *rows, const int clipping)
{
    uint16_t i, t;
    for (i = 0; i < f->order_count; i++) {
        const uint16_t *k;
        t = (uint16_t)f->order[i].index;
        k = f->mesh->triangles + 3 * (size_t)t;
        if (clipping && (f->faces[t] & STP_DIRECT_FACE_CLIPPED)) {
            /* (a corner may be unprojected: no y to pass it over by) */
            draw_clipped_face(f, k, (uint8_t)f->faces[t], band, stride, page_shift, rows);
            continue;
        }
        if (face_off_band(f, k, rows))
            continue; /* before the call */
        draw_faces(f, k, f->faces + t, 1, band, stride, page_shift, rows);
    }
}
#endif


#if !STP_DIRECT_COMPACT
/* Mesh order with faces the picture's edge cuts, one face at a time (a
 * face off the band passed over before its call); out of line, so the
 * painter's order's loops in stp_direct_draw_band keep their code (in
 * line, the sorted 8-row frame cost 2 200 instructions more) */
STP_NOINLINE void draw_mesh_order_clipped(const stp_direct_frame *f, uint8_t *band, size_t stride, int page_shift,
                                          const stp_band_rows *rows)
{
    const uint16_t *k = f->mesh->triangles;
    uint16_t t;
    for (t = 0; t < f->mesh->triangle_count; t++, k += 3) {
        if (f->faces[t] & STP_DIRECT_FACE_CLIPPED)
            draw_clipped_face(f, k, (uint8_t)f->faces[t], band, stride, page_shift, rows);
        else if (f->faces[t] != 0 && !face_off_band(f, k, rows))
            draw_faces(f, k, f->faces + t, 1, band, stride, page_shift, rows);
    }
}
#endif

#if !STP_DIRECT_COMPACT
/* stp_direct_draw_band depth-tested (stp_direct_frame_depth): the band's
 * depths checked for room, the band checked and cleared, then the depth
 * test's fill; out of line, so the other orders' code stays as it was
 * (in line, the sorted frame cost 3 900 instructions more on a
 * Cortex-M0+) */
STP_NOINLINE int draw_band_depth(const stp_direct_frame *f, uint8_t *band, size_t stride, uint16_t y0, uint16_t rows)
{
    int page_shift, status;
    stp_band_rows band_rows;
    if (f->depth->zband == 0 || (size_t)(f->width ? f->width : 1u) * rows > f->depth->zband_count)
        return STP_ERR_ARG; /* no room for the band's depths */
    status = band_start(f, band, stride, y0, rows, &page_shift, &band_rows);
    if (status == STP_OK)
        f->depth->draw(f, band, stride, y0, rows);
    return status;
}
#endif

int stp_direct_draw_band(const stp_direct_frame *f, uint8_t *band, size_t stride, uint16_t y0,
                         uint16_t rows)
{
    int page_shift = 0, status;
    stp_band_rows band_rows; /* at the moved origin */
#if !STP_DIRECT_COMPACT
    if (f != 0 && f->depth != 0)
        return draw_band_depth(f, band, stride, y0, rows);
#endif
    status = band_start(f, band, stride, y0, rows, &page_shift, &band_rows);
    if (status != STP_OK)
        return status;
#if STP_DIRECT_COMPACT
    {
        /* the compact form (no sort): the loop in line, as draw_faces's */
        const uint16_t *k = f->mesh->triangles;
        uint16_t t;
        for (t = 0; t < f->mesh->triangle_count; t++, k += 3) {
            if (f->faces[t] != 0)
                draw_face(f, k, (uint8_t)f->faces[t], band, stride, page_shift, &band_rows);
        }
    }
#else
    if (f->order != 0) {
        /* far to near (stp_direct_frame_sort); a frame without clipped
         * faces by the loop without their test */
        if (f->clipped != 0)
            draw_in_order(f, band, stride, page_shift, &band_rows, 1);
        else
            draw_in_order(f, band, stride, page_shift, &band_rows, 0);
        return STP_OK;
    }
    if (f->clipped != 0) {
        draw_mesh_order_clipped(f, band, stride, page_shift, &band_rows);
        return STP_OK;
    }
    draw_faces(f, f->mesh->triangles, f->faces, f->mesh->triangle_count, band, stride, page_shift, &band_rows);
#endif
    return STP_OK;
}
