/* SPDX-License-Identifier: MIT */
/* Direct drawing with the renderer's Z buffer (include/stipple/direct.h:
 * stp_direct_frame_depth): the depth keys of the faces the renderer would
 * store and the vertices' depths, once a frame; then each band's faces in
 * mesh order, each pixel painted where the face is nearer than what the
 * band's depths hold, by the renderer's depth stage (depth_private.h: the
 * same keys' mapping, depth planes and pixel depths as raster.c's), so
 * the renderer's picture pixel for pixel.  A file of its own, reached
 * through the frame (f->depth->draw), so a program that never asks for the
 * depth test links none of it. */
#include "direct_band_private.h"
#include "render_private.h" /* stp_render_row_count */
#include "project_private.h" /* stp_project_depth_key */
#if STP_DIRECT_DEPTH
#include "depth_private.h" /* the renderer's depth stage */
#endif

#if STP_DIRECT_DEPTH
/* Face k (not clipped) into the band with the depth test: its rows by the
 * triangle walk (as draw_face), its plane from its corners' device
 * positions and depths (f->depth->depths) and its spans' depths by the
 * renderer's depth stage (depth_private.h, as raster.c's tri_draw_z: the
 * plane made at the first row with pixels, stepped a row with the walk),
 * in device coordinates (pixels and rows less ORIGIN_PIXELS).  Out of
 * line, called only for a face that reaches the band (face_off_band): in
 * line, the face loop kept its counters in memory (the Cortex-M0+ frame
 * 112 000 instructions longer) */
STP_NOINLINE void draw_face_depth(const stp_direct_frame *f, const uint16_t k[3], uint8_t intensity, uint8_t *band,
                                  size_t stride, int page_shift, const stp_band_rows *rows, uint16_t *zband)
{
    stp_tri_walk w;
    stp_instr v[3]; /* device x, y alone: what the plane and its depths read */
    depth_plane pl;
    tri_depth td;
    uint32_t p1, p2;
    int made, i;
    if (!stp_tri_walk_start(&f->points[k[0]], &f->points[k[1]], &f->points[k[2]], rows, &w))
        return;
    while (!stp_tri_walk_span(&w, ORIGIN_PIXELS + (uint32_t)f->width, &p1, &p2) || p2 < ORIGIN_PIXELS)
        if (!stp_tri_walk_next(&w))
            return; /* no pixel centre */
    for (i = 0; i < 3; i++) {
        v[i].x = f->points[k[i]].dx;
        v[i].y = f->points[k[i]].dy;
    }
    made = depth_plane_triangle(v, f->depth->depths[k[0]], f->depth->depths[k[1]], f->depth->depths[k[2]], &pl);
    if (!made)
        return; /* edge-on: no area on screen */
    tri_depth_start(&td, &pl, v, STP_TRI_Y(w.bot) - STP_TRI_Y(w.top), stp_tri_walk_yc(&w) - DEVICE_ORIGIN, made);
    for (;;) {
        unsigned r = (unsigned)(w.row - (int)rows->y0); /* the band's row */
        uint8_t *line = band + (r >> page_shift) * stride, page_bit = (uint8_t)(page_shift ? 1u << (r & 7) : 0u),
                pattern = pattern_of(f->cell, (int)(w.row & 3), intensity);
        uint16_t *z = zband + (size_t)r * f->width;
        uint32_t u1 = (p1 < ORIGIN_PIXELS ? ORIGIN_PIXELS : p1) - ORIGIN_PIXELS, u2 = p2 - ORIGIN_PIXELS;
        int64_t d, ddx;
        if (!tri_span_straight(z, line, page_bit, pattern, u1, u2, &td, &pl, &d, &ddx))
            span_z_clamped_bits(z, line, page_bit, pattern, u1, u2, d, ddx);
        do {
            if (!stp_tri_walk_next(&w))
                return;
            tri_depth_step(&td, &pl);
        } while (!stp_tri_walk_span(&w, ORIGIN_PIXELS + (uint32_t)f->width, &p1, &p2) || p2 < ORIGIN_PIXELS);
    }
}

/* A face the picture's edge cuts (clipped_face_rows) with the depth
 * test: the plane the renderer gives the clipped polygon it stores (a
 * triangle's by its own form, raster.c's depth_plane_for), its new
 * vertices' depths by the frame's keys, each span's depths from the plane
 * (as raster.c's draw_polygon) */
static void draw_clipped_face_depth(const stp_direct_frame *f, const uint16_t k[3], uint8_t intensity, uint8_t *band,
                                    size_t stride, int page_shift, const stp_band_rows *rows, const depth_keys *keys)
{
    stp_instr v[STP_DIRECT_CLIP_MAX];
    stp_edge edges[STP_DIRECT_CLIP_MAX];
    stp_crossing crossings[STP_DIRECT_CLIP_MAX];
    depth_plane pl;
    int32_t y, first, last, y0 = (int32_t)rows->y0 - ORIGIN_PIXELS;
    int n, ne = clipped_face_rows(f, k, rows, v, &n, edges, &first, &last);
    if (ne == 0 || !(n == 3 ? depth_plane_triangle(v, depth_q12_of(keys, v[0].z), depth_q12_of(keys, v[1].z),
                                                   depth_q12_of(keys, v[2].z), &pl)
                            : depth_plane_polygon(keys, v, n, &pl)))
        return; /* nothing in the band, or edge-on: no area on screen */
    for (y = first; y <= last; y++) {
        int nc = stp_edges_row(edges, ne, y * (1 << SUB) + STP_HALF_PIXEL, 0, crossings), c;
        unsigned r = (unsigned)(y - y0); /* the band's row */
        int64_t d_row = depth_plane_row(&pl, (uint32_t)y);
        uint32_t p1, p2;
        for (c = 0; c + 1 < nc; c += 2)
            if (stp_span_pixels(crossings[c].x, crossings[c + 1].x, f->width, &p1, &p2))
                span_z_bits(f->depth->zband + (size_t)r * f->width, band + (r >> page_shift) * stride,
                            (uint8_t)(page_shift ? 1u << (r & 7) : 0u), pattern_of(f->cell, (int)y, intensity), p1, p2,
                            depth_plane_at(d_row, pl.ddx, p1), pl.ddx * (1 << SUB));
    }
}

/* The drawn faces into the band in mesh order, depth-tested, the band's
 * depth entries cleared first (0: nothing drawn); stp_direct_draw_band
 * calls it through the frame (f->depth->draw, set below), its arguments
 * checked and the band cleared */
static void draw_depth(const stp_direct_frame *f, uint8_t *band, size_t stride, uint16_t y0, uint16_t rows)
{
    const uint16_t *k = f->mesh->triangles;
    stp_band_rows band_rows;
    depth_keys keys;
    int page_shift = f->layout == STP_BAND_PAGES ? 3 : 0;
    size_t i, count = (size_t)f->width * rows;
    uint16_t t, *z = f->depth->zband;
    band_rows_at(&band_rows, y0, rows);
    /* four entries a step (the loop's count and compare a quarter as
     * often), then the rest */
    for (i = 0; i + 4u <= count; i += 4u) {
        z[i] = 0;
        z[i + 1u] = 0;
        z[i + 2u] = 0;
        z[i + 3u] = 0;
    }
    for (; i < count; i++)
        z[i] = 0;
    if (f->clipped != 0)
        depth_keys_set(&keys, f->depth->key_min, f->depth->key_max);
    for (t = 0; t < f->mesh->triangle_count; t++, k += 3) {
        uint16_t face = f->faces[t];
        if (face == 0)
            continue; /* not drawn */
        if (face & STP_DIRECT_FACE_CLIPPED)
            draw_clipped_face_depth(f, k, (uint8_t)face, band, stride, page_shift, &band_rows, &keys);
        else if (!face_off_band(f, k, &band_rows))
            draw_face_depth(f, k, (uint8_t)face, band, stride, page_shift, &band_rows, f->depth->zband);
    }
}
#endif

#if STP_DIRECT_DEPTH
/* lo, hi widened to hold key */
static void key_widen(int32_t *lo, int32_t *hi, int32_t key)
{
    *lo = key < *lo ? key : *lo;
    *hi = key > *hi ? key : *hi;
}

/* The depth keys of the faces the renderer would store (what its Z
 * buffer maps over, raster.c's frame_extent): every front face but one
 * spanning no row centre (render.c and mesh.c keep those out, by
 * stp_render_row_count) and one clipped to nothing, a clipped face by its
 * clipped polygon's vertices; the key of each vertex of a stored face
 * that is not clipped into depths[] (0 for the others: keys are >= 1),
 * the range into *lo, *hi (*lo > *hi: none). */
static void stored_keys(const stp_direct_frame *f, int32_t *depths, int32_t *lo, int32_t *hi)
{
    const uint16_t *k = f->mesh->triangles;
    uint16_t t, v;
    int i;
    *lo = INT32_MAX;
    *hi = INT32_MIN;
    for (v = 0; v < f->mesh->vertex_count; v++)
        depths[v] = 0;
    for (t = 0; t < f->mesh->triangle_count; t++, k += 3) {
        if (f->faces[t] == 0)
            continue; /* not drawn */
        if (f->faces[t] & STP_DIRECT_FACE_CLIPPED) {
            stp_instr c[STP_DIRECT_CLIP_MAX];
            int n = stp_direct_face_clip(f, k, c);
            for (i = 0; i < n && n >= 3; i++)
                key_widen(lo, hi, c[i].z);
            continue;
        }
        if (stp_render_row_count(f->points[k[0]].dy, f->points[k[1]].dy, f->points[k[2]].dy) == 0)
            continue; /* between two row centres: not stored */
        for (i = 0; i < 3; i++) {
            if (depths[k[i]] == 0)
                depths[k[i]] = stp_project_depth_key((uint32_t)f->hither, (uint32_t)f->points[k[i]].z);
            key_widen(lo, hi, depths[k[i]]);
        }
    }
}
#endif

int stp_direct_frame_depth(stp_direct_frame *f, stp_direct_depth *depth)
{
#if !STP_DIRECT_DEPTH
    (void)depth;
    return f == 0 ? STP_ERR_ARG : STP_ERR_UNSUPPORTED; /* the compact form, or no Z buffer (direct.h) */
#else
    depth_keys keys;
    uint16_t v;
    if (f == 0 || depth == 0 || depth->depths == 0 || depth->zband == 0 || f->mesh == 0 || f->mesh->triangles == 0 ||
        f->points == 0 || f->faces == 0 || depth->depth_count < f->mesh->vertex_count || depth->zband_count < f->width)
        return STP_ERR_ARG;
    stored_keys(f, depth->depths, &depth->key_min, &depth->key_max);
    depth_keys_set(&keys, depth->key_min, depth->key_max);
    for (v = 0; v < f->mesh->vertex_count; v++)
        if (depth->depths[v] != 0)
            depth->depths[v] = depth_q12_of(&keys, depth->depths[v]);
    depth->draw = draw_depth;
    f->order = 0; /* mesh order, depth-tested */
    f->order_count = 0;
    f->depth = depth;
    return STP_OK;
#endif
}
