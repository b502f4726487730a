/* SPDX-License-Identifier: MIT */
/*
 * The three entries, picture for picture (issue 20): direct drawing
 * (stp_direct_*), the renderer's mesh entry (stp_renderer_mesh) and its
 * polygon entry (stp_renderer_polygon, triangle by triangle), then
 * stp_renderer_render: the same view, focal length, light, material
 * without highlight, 16 levels, Bayer 4 x 4 cell, back faces removed, the
 * renderer's model transform stp_direct_model_transform's.  Every
 * renderer picture (display-file order, painter's sort, Z buffer) is made
 * by both renderer entries and must be the same, byte for byte, with as
 * many polygons stored.  Direct drawing has no Z buffer: its mesh-order
 * picture is compared with the renderer's display-file order, its
 * painter's order (stp_direct_frame_sort) with the renderer's painter's
 * sort (the order also against one made here: keys in 64 bits, qsort),
 * both memcmp; the sorted picture's pixels differing from the Z buffer's
 * are counted against a bound.
 * Models: the benchmark torus (tools/bench/torus.c, 1000 triangles,
 * vertices merged as torus_bench_use_mesh merges them) still and in 8
 * poses, at 128 x 64 and 400 x 240 (sorted against the Z buffer: equal in
 * 17 of 18 frames, 1 pixel in one; bound 2); and the shared scenes direct
 * drawing can draw (one material, one light, triangles: tetra-s1 and
 * tetra-s2, the file's view and light position) still and in the same 8
 * poses at both sizes, where the sorted picture must equal the Z buffer's
 * too (bound 0).  Built with STP_DIRECT_COMPACT (the Uno's and the lean
 * image's form) the pictures are equal too: the renderer takes that
 * form's look-at, composite, normal rotation and shading point in those
 * builds, so every vertex lands at the same view coordinates and device
 * position; its side by the winding of the projected vertices
 * (render_private.h); and its guard band (project_private.h), so a face
 * across the picture's edge is walked whole by both.  (Before the winding
 * side 1 pixel of the 146 frames differed; before the guard band 15, in
 * 13 frames.)  In both forms every projected vertex must have the
 * renderer's view coordinates and device position.  The compact form
 * refuses the sort and any scale but 1.
 * The torus also moved across each edge of the picture and a corner (9
 * poses each, and one with hither 8 raw, both sizes: 92 frames), where
 * the renderer clips (in the compact form: walks whole within its guard
 * band): equal in mesh order and in the painter's order, the renderer's
 * sorted keys (the clipped polygons' among them) a subsequence of direct
 * drawing's order.  (Without direct drawing's clipping 16 of the 90
 * frames differ, in 1 or 2 pixels.)  And brought toward the eye until the near plane cuts it
 * (32 frames, vertices left unprojected), and at 1200 random poses and
 * places (and hither distances) across the edges, off the picture and through the near plane:
 * equal likewise (not in the compact form, which refuses such frames).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "stipple/direct.h"
#include "stipple/stipple.h"
#include "test_scenes.h"
#include "torus.h"

#if !STP_DIRECT_COMPACT
#define TEST_RANDOM_SEED 0x5eed20u
#include "test_random.h" /* next_random (run_random) */
#endif

#define MAX_W 400
#define MAX_H 240
#define LEVELS 16

typedef struct work {
    torus_bench bench;
    stp_renderer_storage storage;
    stp_instr df[5 * TORUS_TRIANGLES];
    stp_mesh_vertex scratch[3 * TORUS_TRIANGLES];
    stp_direct_point pts[3 * TORUS_TRIANGLES];
    uint16_t faces[TORUS_TRIANGLES];
    stp_sort_entry direct_order[TORUS_TRIANGLES]; /* stp_direct_frame_sort's */
    stp_sort_entry sort[TORUS_TRIANGLES];         /* the renderer's painter's sort */
    uint16_t zbuf[MAX_W * MAX_H];
    int32_t direct_depths[3 * TORUS_TRIANGLES]; /* stp_direct_frame_depth's */
    uint16_t direct_zband[MAX_W * MAX_H];
    uint8_t direct_depth[MAX_H * MAX_W / 8]; /* direct drawing's, depth-tested */
    uint8_t direct[MAX_H * MAX_W / 8];
    uint8_t direct_sorted[MAX_H * MAX_W / 8];
    uint8_t full[MAX_H * MAX_W / 8];
    uint8_t full_painter[MAX_H * MAX_W / 8];
    uint8_t full_zbuffer[MAX_H * MAX_W / 8];
    uint8_t band[MAX_H * MAX_W / 8];
    uint8_t polygon_full[MAX_H * MAX_W / 8]; /* the renderer's, by stp_renderer_polygon */
    uint8_t banded[MAX_H * MAX_W / 8];       /* direct drawing's in 8-row bands */
    uint8_t *picture;                        /* where copy_flush writes */
    const stp_mesh *mesh;                    /* the model: the torus's or a scene's */
    stp_view view;                           /* its view and direct drawing's light */
    stp_direct_light light;
    stp_scene scene;                         /* a shared scene's (scene_open), else empty */
    stp_mesh scene_mesh;                     /* and its merged mesh */
    stp_mesh_bounds scene_bounds;
    stp_vec3 *scene_vertices;
    uint16_t *scene_triangles;
    int16_t *scene_normals;
    const char *name; /* the model's, for the log */
    int zbuffer_bound; /* the sorted picture's pixels differing from the Z buffer's, at most */
    int width, height;
    uint32_t polygons; /* the renderer's last display file's */
    unsigned clipped;  /* the last direct frame's faces the edge cuts */
    stp_fix hither;    /* the view's hither when not 0 (else scene_view's) */
    int near;          /* frames near the eye: some may show little */
    long lit;          /* the ON pixels of the frames compared */
} work;

static stp_fix fx(double v)
{
    return (stp_fix)(v * STP_FIX_ONE + (v < 0 ? -0.5 : 0.5));
}

static stp_vec3 vec(double x, double y, double z)
{
    stp_vec3 p;
    p.x = fx(x);
    p.y = fx(y);
    p.z = fx(z);
    return p;
}

static int copy_flush(stp_port *port, uint32_t y0, uint32_t rows, const uint8_t *px, size_t stride)
{
    work *w = port->user;
    memcpy(w->picture + (size_t)y0 * stride, px, rows * stride);
    return 0;
}

/* The scene: torus.h's eye, light and field of view; direct drawing's one
 * light (power 9, background 0.2, C 1, reflectivity 0.7). */
static void scene_view(stp_view *v)
{
    memset(v, 0, sizeof *v);
    v->from = vec(0, 3, 5.2);
    v->at = vec(0, 0, 0);
    v->up = vec(0, 1, 0);
    v->fov_degrees = fx(35);
    v->hither = fx(0.1);
    v->projection = STP_PERSPECTIVE;
}

static stp_direct_light scene_light(void)
{
    stp_direct_light l;
    l.position = vec(-4, 6, 5);
    l.power = fx(9);
    l.brightness = fx(1);
    l.background = fx(0.2);
    l.attenuation_c = fx(1);
    l.reflectivity = fx(0.7);
    return l;
}

/* A renderer posed for the frame: view, direct drawing's light as the
 * renderer's lighting, the material without highlight, 16 levels, back
 * faces removed, segment 1 open with the pose's model transform */
static stp_renderer *renderer_posed(work *w, const stp_view *view, const stp_direct_light *dl,
                                    const stp_direct_model *pose)
{
    stp_renderer *r = stp_renderer_create(&w->storage, sizeof w->storage, w->df, 5 * TORUS_TRIANGLES,
                                          (uint32_t)w->width, (uint32_t)w->height);
    stp_lighting l;
    stp_material mat;
    stp_transform t, d;
    int i, j;
    assert_non_null(r);
    assert_int_equal(stp_renderer_set_view(r, view), STP_OK);
    stp_lighting_default(&l);
    l.brightness = dl->brightness;
    l.background = dl->background;
    l.attenuation_c = dl->attenuation_c;
    l.count = 1;
    l.lights[0].position = dl->position;
    l.lights[0].power = dl->power;
    assert_int_equal(stp_renderer_set_lighting(r, &l), STP_OK);
    stp_material_default(&mat);
    mat.reflectivity = dl->reflectivity;
    mat.specular = 0;
    assert_int_equal(stp_renderer_set_object_shade(r, &mat), STP_OK);
    assert_int_equal(stp_renderer_set_shading(r, 1), STP_OK);
    assert_int_equal(stp_renderer_set_levels(r, LEVELS), STP_OK);
    assert_int_equal(stp_renderer_set_backface_removal(r, 1), STP_OK);
    assert_int_equal(stp_segment_create(r, 1), STP_OK);
    /* the pose's rotation (Q1.14) times its scale, in stp_fix: floor(rot
     * scale / 2^14), as stp_direct_model_transform gives it */
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++)
            t.m[i][j] = (stp_fix)(((int64_t)pose->rot[i][j] * pose->scale) >> 14);
    t.t = pose->translate;
    stp_direct_model_transform(pose, &d);
    assert_memory_equal(&d, &t, sizeof t);
    assert_int_equal(stp_renderer_set_transform(r, &t), STP_OK);
    return r;
}

/* Renderer r's picture into picture, hidden surfaces by hidden */
static void renderer_picture(work *w, stp_renderer *r, const stp_cell *cell, stp_hidden hidden, uint8_t *picture)
{
    stp_port port;
    stp_output out;
    stp_frame_memory mem;
    memset(&port, 0, sizeof port);
    port.width = (uint32_t)w->width;
    port.height = (uint32_t)w->height;
    port.format = STP_PIXEL_MONO1;
    port.flush = copy_flush;
    port.user = w;
    w->picture = picture;
    stp_output_default(&out);
    out.hidden = hidden;
    out.cell = cell;
    memset(&mem, 0, sizeof mem);
    mem.band = w->band;
    mem.band_size = sizeof w->band;
    mem.band_rows = (uint32_t)w->height;
    mem.sort = w->sort;
    mem.sort_count = TORUS_TRIANGLES;
    mem.zbuf = w->zbuf;
    mem.zbuf_count = MAX_W * MAX_H;
    assert_int_equal(stp_renderer_render(r, &port, &out, &mem), STP_OK);
}

/* The renderer's picture of the pose into w->full, hidden surfaces by
 * hidden, the model entered by stp_renderer_mesh; entered triangle by
 * triangle through stp_renderer_polygon too, whose picture must be the
 * same, byte for byte, with as many polygons stored (the polygon entry
 * drawn first: w->sort and w->polygons are then the mesh entry's) */
static void draw_full(work *w, const stp_view *view, const stp_direct_light *dl, const stp_direct_model *pose,
                      const stp_cell *cell, stp_hidden hidden)
{
    stp_renderer *r = renderer_posed(w, view, dl, pose);
    uint32_t polygons;
    uint16_t t;
    for (t = 0; t < w->mesh->triangle_count; t++) {
        const uint16_t *k = &w->mesh->triangles[3 * (size_t)t];
        stp_vec3 v[3];
        v[0] = w->mesh->vertices[k[0]];
        v[1] = w->mesh->vertices[k[1]];
        v[2] = w->mesh->vertices[k[2]];
        assert_int_equal(stp_renderer_polygon(r, v, 3), STP_OK);
    }
    assert_int_equal(stp_segment_close(r), STP_OK);
    polygons = stp_renderer_polygon_count(r);
    renderer_picture(w, r, cell, hidden, w->polygon_full);
    r = renderer_posed(w, view, dl, pose);
    assert_int_equal(stp_renderer_mesh(r, w->mesh, w->scratch, 3 * TORUS_TRIANGLES), STP_OK);
    assert_int_equal(stp_segment_close(r), STP_OK);
    w->polygons = stp_renderer_polygon_count(r);
    renderer_picture(w, r, cell, hidden, w->full);
    assert_int_equal(w->polygons, polygons);
    assert_memory_equal(w->polygon_full, w->full, (size_t)w->width / 8 * (size_t)w->height);
}

/* The pixels that differ between pictures a and b (bytes bytes) */
static int pixels_differing(const uint8_t *a, const uint8_t *b, size_t bytes)
{
    size_t i;
    int b_, n = 0;
    for (i = 0; i < bytes; i++)
        for (b_ = 0; b_ < 8; b_++)
            n += ((a[i] ^ b[i]) >> b_) & 1;
    return n;
}

/* qsort's order for the reference: far to near, ties by index */
static int reference_less(const void *a, const void *b)
{
    const int64_t *x = a, *y = b;
    return x[0] != y[0] ? (x[0] < y[0] ? -1 : 1) : (x[1] < y[1] ? -1 : (x[1] > y[1]));
}

/* The key fr->order gives face t (a face the picture's edge cuts: its
 * clipped polygon's, checked against the renderer's in sorted_pictures),
 * or -1 when t is not in the order */
static int64_t key_in_order(const stp_direct_frame *fr, uint16_t t)
{
    uint16_t i;
    for (i = 0; i < fr->order_count; i++)
        if (fr->order[i].index == t)
            return fr->order[i].key;
    return -1;
}

/* fr->order against an order made here: each drawn face's key
 * floor(hither 2^30 / z) of its farthest vertex in 64 bits (a clipped
 * face's as fr->order has it), sorted by qsort on (key, index) */
static void check_order(work *w, const stp_direct_frame *fr)
{
    static int64_t ref[TORUS_TRIANGLES][2];
    size_t n = 0, i;
    uint16_t t;
    for (t = 0; t < w->mesh->triangle_count; t++) {
        const uint16_t *k = &w->mesh->triangles[3 * t];
        int64_t far = fr->points[k[0]].z;
        if (w->faces[t] == 0)
            continue;
        far = fr->points[k[1]].z > far ? fr->points[k[1]].z : far;
        far = fr->points[k[2]].z > far ? fr->points[k[2]].z : far;
        ref[n][0] = ((int64_t)fr->hither << 30) / far;
        if (w->faces[t] & STP_DIRECT_FACE_CLIPPED) {
            ref[n][0] = key_in_order(fr, t);
            if (ref[n][0] < 0)
                continue; /* nothing left of it */
        }
        ref[n][1] = t;
        n++;
    }
    qsort(ref, n, sizeof ref[0], reference_less);
    assert_int_equal(fr->order_count, n);
    for (i = 0; i < n; i++) {
        assert_int_equal(fr->order[i].index, ref[i][1]);
        assert_int_equal(fr->order[i].key, ref[i][0]);
    }
}

/* Frame fr drawn in 8-row bands (the firmware's; a clipped face left out
 * of the bands it cannot reach, direct_band.c) must give picture, the
 * frame drawn as one band, byte for byte */
static void bands_equal(work *w, const stp_direct_frame *fr, const uint8_t *picture)
{
    size_t stride = (size_t)w->width / 8;
    int y;
    for (y = 0; y < w->height; y += 8) {
        uint16_t rows = (uint16_t)(w->height - y < 8 ? w->height - y : 8);
        assert_int_equal(stp_direct_draw_band(fr, w->banded + (size_t)y * stride, stride, (uint16_t)y, rows), STP_OK);
    }
    assert_memory_equal(w->banded, picture, stride * (size_t)w->height);
}

#if !STP_DIRECT_COMPACT
/* Direct drawing's frame fr depth-tested (stp_direct_frame_depth) must
 * give the renderer's Z-buffer picture (w->full_zbuffer) byte for byte,
 * in one band and in 8-row bands; then its refusals, and the sort after
 * it drawing far to near again. */
static void depth_picture(work *w, stp_direct_frame *fr, size_t stride)
{
    size_t bytes = stride * (size_t)w->height, vertices = w->mesh->vertex_count;
    stp_direct_depth depth;
    memset(&depth, 0, sizeof depth);
    depth.depths = w->direct_depths;
    depth.depth_count = vertices;
    depth.zband = w->direct_zband;
    depth.zband_count = (size_t)w->width * (size_t)w->height;
    assert_int_equal(stp_direct_frame_depth(fr, &depth), STP_OK);
    assert_ptr_equal(fr->depth, &depth);
    assert_null(fr->order);
    memset(w->direct_depth, 0xA5, bytes);
    assert_int_equal(stp_direct_draw_band(fr, w->direct_depth, stride, 0, (uint16_t)w->height), STP_OK);
    printf("  depth-tested: %d pixels differ from the renderer's Z buffer\n",
           pixels_differing(w->direct_depth, w->full_zbuffer, bytes));
    assert_memory_equal(w->direct_depth, w->full_zbuffer, bytes);
    bands_equal(w, fr, w->direct_depth);
    /* a band taller than its depths: refused, the band untouched */
    depth.zband_count = (size_t)w->width * 8u;
    assert_int_equal(stp_direct_frame_depth(fr, &depth), STP_OK);
    w->banded[0] = 0x5A;
    assert_int_equal(stp_direct_draw_band(fr, w->banded, stride, 0, 9), STP_ERR_ARG);
    assert_int_equal(w->banded[0], 0x5A);
    bands_equal(w, fr, w->direct_depth);
    /* refused: too few depths or entries, NULL arguments */
    depth.depth_count = vertices - 1u;
    assert_int_equal(stp_direct_frame_depth(fr, &depth), STP_ERR_ARG);
    depth.depth_count = vertices;
    depth.zband_count = (size_t)w->width - 1u;
    assert_int_equal(stp_direct_frame_depth(fr, &depth), STP_ERR_ARG);
    depth.zband_count = (size_t)w->width;
    depth.depths = NULL;
    assert_int_equal(stp_direct_frame_depth(fr, &depth), STP_ERR_ARG);
    depth.depths = w->direct_depths;
    depth.zband = NULL;
    assert_int_equal(stp_direct_frame_depth(fr, &depth), STP_ERR_ARG);
    depth.zband = w->direct_zband;
    assert_int_equal(stp_direct_frame_depth(fr, NULL), STP_ERR_ARG);
    assert_int_equal(stp_direct_frame_depth(NULL, &depth), STP_ERR_ARG);
    /* the sort after it: far to near, no depth test */
    assert_int_equal(stp_direct_frame_sort(fr, w->direct_order, TORUS_TRIANGLES), STP_OK);
    assert_null(fr->depth);
    assert_int_equal(stp_direct_draw_band(fr, w->banded, stride, 0, (uint16_t)w->height), STP_OK);
    assert_memory_equal(w->banded, w->direct_sorted, bytes);
}
#endif

/* Direct drawing's frame fr in its painter's order (stp_direct_frame_sort)
 * against the renderer's painter's sort, memcmp-equal, and its Z buffer,
 * counted (measured: 0 pixels in 17 of the 18 frames, 1 in one); the
 * compact form refuses the sort. */
static int sorted_pictures(work *w, stp_direct_frame *fr, const stp_view *view, const stp_direct_light *light,
                           const stp_direct_model *pose, const stp_cell *cell, size_t stride)
{
    size_t bytes = stride * (size_t)w->height;
    int status = stp_direct_frame_sort(fr, w->direct_order, TORUS_TRIANGLES);
    int painter, zbuffer;
#if STP_DIRECT_COMPACT
    assert_int_equal(status, STP_ERR_UNSUPPORTED);
    assert_int_equal(stp_direct_frame_sort(NULL, w->direct_order, TORUS_TRIANGLES), STP_ERR_ARG);
    {
        stp_direct_depth depth = {w->direct_depths, 3 * TORUS_TRIANGLES, w->direct_zband, MAX_W * MAX_H, 0, 0, 0};
        assert_int_equal(stp_direct_frame_depth(fr, &depth), STP_ERR_UNSUPPORTED);
    }
    (void)view;
    (void)light;
    (void)pose;
    (void)cell;
    (void)bytes;
    return 0;
#endif
    assert_int_equal(status, STP_OK);
    check_order(w, fr);
    assert_int_equal(stp_direct_draw_band(fr, w->direct_sorted, stride, 0, (uint16_t)w->height), STP_OK);
    bands_equal(w, fr, w->direct_sorted);
    draw_full(w, view, light, pose, cell, STP_HIDDEN_PAINTER);
    memcpy(w->full_painter, w->full, bytes);
    /* the renderer's sorted keys, the clipped polygons' among them, in
     * direct drawing's order: a subsequence of it (the renderer leaves
     * out a face that covers no pixel centre, direct drawing draws it and
     * paints nothing; both orders are by key, then mesh order) */
    {
        uint32_t i, j = 0;
        assert_true(w->polygons <= fr->order_count);
        for (i = 0; i < w->polygons; i++) {
            while (j < fr->order_count && fr->order[j].key != w->sort[i].key)
                j++;
            assert_true(j < fr->order_count);
            j++;
        }
    }
    draw_full(w, view, light, pose, cell, STP_HIDDEN_ZBUFFER);
    memcpy(w->full_zbuffer, w->full, bytes);
    painter = pixels_differing(w->direct_sorted, w->full_painter, bytes);
    zbuffer = pixels_differing(w->direct_sorted, w->full_zbuffer, bytes);
    printf("  sorted (%u faces): %d pixels differ from the renderer's painter's sort, %d from its Z buffer; "
           "mesh order %d from its Z buffer\n",
           (unsigned)fr->order_count, painter, zbuffer, pixels_differing(w->direct, w->full_zbuffer, bytes));
    assert_memory_equal(w->direct_sorted, w->full_painter, bytes);
    assert_true(zbuffer <= w->zbuffer_bound);
#if !STP_DIRECT_COMPACT
    depth_picture(w, fr, stride);
#endif
    /* refused: too few entries (mesh order kept), NULL arguments */
    {
        uint16_t front = fr->order_count;
        if (front > 0) { /* (a frame near the eye may have nothing left) */
            assert_int_equal(stp_direct_frame_sort(fr, w->direct_order, (size_t)front - 1u), STP_ERR_FULL);
            assert_null(fr->order);
            assert_int_equal(fr->order_count, 0);
        }
        assert_int_equal(stp_direct_frame_sort(fr, NULL, TORUS_TRIANGLES), STP_ERR_ARG);
        assert_int_equal(stp_direct_frame_sort(NULL, w->direct_order, TORUS_TRIANGLES), STP_ERR_ARG);
        assert_int_equal(stp_direct_frame_sort(fr, w->direct_order, front), STP_OK);
        assert_int_equal(fr->order_count, front);
    }
    return zbuffer;
}

/* Both pictures of one pose; returns the differing pixels. */
static int compare(work *w, uint16_t yaw, uint16_t pitch, stp_vec3 shift)
{
    stp_view view = w->view;
    stp_direct_view dv;
    stp_direct_light light = w->light;
    stp_direct_model pose;
    stp_direct_frame fr;
    stp_cell cell;
    stp_fix half, focal;
    size_t stride = (size_t)w->width / 8, i;
    int diff = 0, lit = 0, b;
    if (w->hither != 0)
        view.hither = w->hither;
    half = view.fov_degrees / 2;
    /* the renderer's focal length (view.c) */
    focal = (stp_fix)(((int64_t)(w->width < w->height ? w->width : w->height) * stp_fix_cos_deg(half) *
                       (STP_FIX_ONE / 2)) /
                      stp_fix_sin_deg(half));
    assert_int_equal(stp_direct_view_look(&dv, view.from, view.at, view.up, focal, view.hither, (uint16_t)w->width,
                                          (uint16_t)w->height),
                     STP_OK);
    stp_direct_model_turn(&pose, yaw, pitch, STP_FIX_ONE, shift);
    assert_int_equal(stp_cell_bayer(&cell, 4), 0);
    assert_int_equal(stp_direct_frame_project(&fr, w->mesh, &pose, &dv, &light, LEVELS, cell.thresholds,
                                              w->pts, 3 * TORUS_TRIANGLES, w->faces, TORUS_TRIANGLES),
                     STP_OK);
#if STP_DIRECT_COMPACT
    {
        /* the compact form draws at scale 1 alone (direct.h) */
        stp_direct_model scaled = pose;
        stp_direct_frame other;
        scaled.scale = STP_FIX_ONE - 1;
        assert_int_equal(stp_direct_frame_project(&other, w->mesh, &scaled, &dv, &light, LEVELS, cell.thresholds,
                                                  w->pts, 3 * TORUS_TRIANGLES, w->faces, TORUS_TRIANGLES),
                         STP_ERR_ARG);
        assert_int_equal(stp_direct_frame_project(&fr, w->mesh, &pose, &dv, &light, LEVELS, cell.thresholds, w->pts,
                                                  3 * TORUS_TRIANGLES, w->faces, TORUS_TRIANGLES),
                         STP_OK); /* the points again */
    }
#endif
    assert_int_equal(stp_direct_draw_band(&fr, w->direct, stride, 0, (uint16_t)w->height), STP_OK);
    bands_equal(w, &fr, w->direct);
    w->clipped = STP_DIRECT_COMPACT ? 0u : fr.clipped;
    sorted_pictures(w, &fr, &view, &light, &pose, &cell, stride);
    draw_full(w, &view, &light, &pose, &cell, STP_HIDDEN_NONE);
    for (i = 0; i < stride * (size_t)w->height; i++)
        for (b = 0; b < 8; b++) {
            diff += ((w->direct[i] ^ w->full[i]) >> b) & 1;
            lit += (w->full[i] >> b) & 1;
        }
    {
        /* where the two entries' view coordinates and device positions
         * differ (renderer: projected vertices only) */
        int moved = 0, view_moved = 0;
        for (i = 0; i < w->mesh->vertex_count; i++)
            if ((w->scratch[i].state & (64 | 128)) == 0) { /* projected (mesh.c: state 0) */
                moved += w->pts[i].dx != w->scratch[i].dx || w->pts[i].dy != w->scratch[i].dy;
                view_moved += w->pts[i].x != w->scratch[i].view.x || w->pts[i].y != w->scratch[i].view.y ||
                              w->pts[i].z != w->scratch[i].view.z;
            }
        printf("%s %dx%d yaw %5u pitch %5u shift (%.2f, %.2f): %d pixels ON, %d differ, %u faces "
               "clipped; %d vertices at other view coordinates, %d at other device positions\n",
               w->name, w->width, w->height, yaw, pitch, shift.x / (double)STP_FIX_ONE, shift.y / (double)STP_FIX_ONE, lit,
               diff, w->clipped, view_moved, moved);
        /* every projected vertex where the renderer has it, in both forms */
        assert_int_equal(view_moved, 0);
        assert_int_equal(moved, 0);
    }
    assert_true(lit > 100 || w->near);
    w->lit += lit;
    return diff;
}

/* The nine poses the torus is drawn in (still, and 8 turned) */
static const uint16_t poses[9][2] = {{0, 0},         {3000, 2000},   {11000, 60000}, {25000, 9000},
                                     {40000, 30000}, {52000, 47000}, {7000, 5000},   {33000, 61000},
                                     {60000, 16000}};

/* A work area for the benchmark torus, merged into a mesh, at width x
 * height; near: frames that may show little (compare's lit check off) */
static work *work_open(int width, int height, int near)
{
    work *w = calloc(1, sizeof *w);
    char err[200];
    assert_non_null(w);
    assert_int_equal(torus_bench_init(&w->bench, width, height, err, sizeof err), 0);
    assert_int_equal(torus_bench_use_mesh(&w->bench, err, sizeof err), 0);
    w->mesh = &w->bench.mesh;
    w->name = "torus";
    w->zbuffer_bound = 2;
    scene_view(&w->view);
    w->light = scene_light();
    w->width = width;
    w->height = height;
    w->near = near;
    return w;
}

/* Index of point p among the n merged vertices of w's scene mesh, added
 * when new */
static uint16_t scene_vertex(work *w, stp_vec3 p, uint16_t *n)
{
    uint16_t i;
    for (i = 0; i < *n; i++)
        if (w->scene_vertices[i].x == p.x && w->scene_vertices[i].y == p.y && w->scene_vertices[i].z == p.z)
            return i;
    w->scene_vertices[*n] = p;
    return (*n)++;
}

/* A work area for shared scene name (one material, one light, triangles
 * alone: a scene direct drawing can draw), its vertices merged into a
 * mesh, at width x height.  The file's view and light position; the
 * light's power 20 (the light 19 units from the model), background 0.2,
 * C 1, brightness 1, reflectivity 0.7 times the file's Kd. */
static work *scene_open(const char *name, int width, int height)
{
    work *w = calloc(1, sizeof *w);
    uint16_t count = 0, bad = 0;
    size_t t;
    int j;
    assert_non_null(w);
    stp_test_load_scene(name, &w->scene);
    assert_true(w->scene.has_view && w->scene.light_count == 1 && w->scene.material_count == 1 &&
                w->scene.prim_count == 0 && w->scene.polygon_count <= TORUS_TRIANGLES);
    w->scene_vertices = calloc(3 * w->scene.polygon_count, sizeof *w->scene_vertices);
    w->scene_triangles = calloc(3 * w->scene.polygon_count, sizeof *w->scene_triangles);
    w->scene_normals = calloc(3 * w->scene.polygon_count, sizeof *w->scene_normals);
    assert_true(w->scene_vertices && w->scene_triangles && w->scene_normals);
    for (t = 0; t < w->scene.polygon_count; t++) {
        const stp_scene_polygon *p = &w->scene.polygons[t];
        assert_int_equal(p->count, 3);
        for (j = 0; j < 3; j++) {
            const stp_scene_vec3 *v = &w->scene.vertices[p->first + (size_t)j];
            w->scene_triangles[3 * t + (size_t)j] = scene_vertex(w, vec(v->x, v->y, v->z), &count);
        }
    }
    w->scene_mesh.vertices = w->scene_vertices;
    w->scene_mesh.vertex_count = count;
    w->scene_mesh.triangles = w->scene_triangles;
    w->scene_mesh.triangle_count = (uint16_t)w->scene.polygon_count;
    assert_int_equal(stp_mesh_prepare_normals(&w->scene_mesh, w->scene_normals, &bad), STP_OK);
    w->scene_mesh.normals = w->scene_normals;
    assert_int_equal(stp_mesh_prepare_bounds(&w->scene_mesh, &w->scene_bounds), STP_OK);
    w->scene_mesh.bounds = &w->scene_bounds;
    w->mesh = &w->scene_mesh;
    w->name = name;
    /* (long edges: measured 0 of 128 x 64 and 15 of 400 x 240) */
    w->zbuffer_bound = 0; /* the painter's order is exact here */
    memset(&w->view, 0, sizeof w->view);
    w->view.from = vec(w->scene.from.x, w->scene.from.y, w->scene.from.z);
    w->view.at = vec(w->scene.at.x, w->scene.at.y, w->scene.at.z);
    w->view.up = vec(w->scene.up.x, w->scene.up.y, w->scene.up.z);
    w->view.fov_degrees = fx(w->scene.angle);
    w->view.hither = fx(w->scene.hither);
    w->view.projection = STP_PERSPECTIVE;
    w->light = scene_light();
    w->light.position =
        vec(w->scene.lights[0].position.x, w->scene.lights[0].position.y, w->scene.lights[0].position.z);
    w->light.power = fx(20);
    w->light.reflectivity = fx(0.7 * w->scene.materials[0].kd);
    w->width = width;
    w->height = height;
    return w;
}

static void work_close(work *w)
{
    if (w->mesh == &w->bench.mesh)
        torus_bench_free(&w->bench);
    stp_scene_free(&w->scene);
    free(w->scene_vertices);
    free(w->scene_triangles);
    free(w->scene_normals);
    free(w);
}

/* 1 when the pose's two mesh-order pictures differ (compare, then the
 * whole pictures by memcmp), else 0 */
static int frame_differs(work *w, uint16_t yaw, uint16_t pitch, stp_vec3 shift)
{
    return compare(w, yaw, pitch, shift) != 0 ||
           memcmp(w->direct, w->full, (size_t)w->width / 8 * (size_t)w->height) != 0;
}

#if !STP_DIRECT_COMPACT
/* The last direct frame's vertices left unprojected */
static unsigned unprojected_points(const work *w)
{
    unsigned n = 0;
    size_t i;
    for (i = 0; i < w->mesh->vertex_count; i++)
        n += w->pts[i].dx == STP_DIRECT_UNPROJECTED;
    return n;
}
#endif

/* The compact form: 1 when some vertex of the last frame lies beyond the
 * picture's edge (its device position outside [0, 16 width] x [0, 16
 * height]), else 0 */
static unsigned beyond_edge(const work *w)
{
    size_t i;
    for (i = 0; i < w->mesh->vertex_count; i++)
        if (w->pts[i].dx < 0 || w->pts[i].dx > 16 * w->width || w->pts[i].dy < 0 || w->pts[i].dy > 16 * w->height)
            return 1;
    return 0;
}

/* Work area w's model still and in the 8 poses (every pose printed
 * before the verdict): every frame equal, in both forms */
static void run_poses(work *w)
{
    size_t p;
    int differ = 0;
    for (p = 0; p < 9; p++)
        differ += frame_differs(w, poses[p][0], poses[p][1], vec(0, 0, 0));
    assert_int_equal(differ, 0);
    work_close(w);
}

static void run_size(int width, int height)
{
    run_poses(work_open(width, height, 0));
}

static void test_torus_128x64(void **state)
{
    (void)state;
    run_size(128, 64);
}

static void test_torus_400x240(void **state)
{
    (void)state;
    run_size(400, 240);
}

/* The torus moved across each edge of the picture and a corner, where
 * the renderer clips: direct drawing clips those faces as it does (the
 * compact form walks them whole, counted against its bounds) */
static void run_edges(int width, int height)
{
    static const double shifts[5][2] = {{3.0, 0}, {-3.0, 0}, {0, 1.6}, {0, -1.6}, {2.4, 1.2}};
    work *w = work_open(width, height, 0);
    size_t s, p;
    int differ = 0;
    unsigned clipped = 0;
    for (s = 0; s < 5; s++)
        for (p = 0; p < 9; p++) {
            differ += frame_differs(w, poses[p][0], poses[p][1], vec(shifts[s][0], shifts[s][1], 0));
            clipped += STP_DIRECT_COMPACT ? beyond_edge(w) : w->clipped;
        }
    /* hither below 16 raw: every face's outcodes found (direct.c's
     * mark_clipped), the same pictures */
    w->hither = 8;
    differ += frame_differs(w, 3000, 2000, vec(2.4, 1.2, 0));
    clipped += STP_DIRECT_COMPACT ? beyond_edge(w) : w->clipped;
#if STP_DIRECT_COMPACT
    /* frames with vertices beyond the picture's edge (45 of the 46: the
     * renderer walks those faces whole in its guard band, as this form
     * does) */
    printf("compact form: %u of 46 frames cross the picture's edge, %d differ\n", clipped, differ);
    assert_true(clipped >= 45);
#else
    assert_true(clipped >= 46); /* faces clipped: frames cut by an edge */
#endif
    assert_int_equal(differ, 0);
    work_close(w);
}

/* The torus brought toward the eye, along the line of sight, until the
 * near plane cuts it and some vertices project beyond the device's range
 * or lie behind the eye: those are left unprojected and their faces
 * clipped, as the renderer clips them (the compact form refuses such a
 * frame: not run there) */
#if !STP_DIRECT_COMPACT
static void run_near(int width, int height)
{
    static const double along[4] = {0.75, 0.8, 0.9, 1.0}; /* of the way from the origin to the eye */
    static const uint16_t near_poses[4][2] = {{0, 0}, {11000, 60000}, {40000, 30000}, {60000, 16000}};
    work *w = work_open(width, height, 1);
    size_t a, p;
    int differ = 0;
    unsigned clipped = 0, unprojected = 0;
    for (a = 0; a < 4; a++)
        for (p = 0; p < 4; p++) {
            differ += frame_differs(w, near_poses[p][0], near_poses[p][1], vec(0, 3 * along[a], 5.2 * along[a]));
            clipped += w->clipped;
            unprojected += unprojected_points(w);
        }
    printf("near the eye %dx%d: %u faces clipped, %u vertices unprojected, %ld pixels ON in 16 frames\n", width,
           height, clipped, unprojected, w->lit);
    assert_true(unprojected > 0);
    assert_true(w->lit > 16L * width * height / 10); /* most frames show much of the torus */
    assert_int_equal(differ, 0);
    work_close(w);
}

/* Random poses and places, across the picture's edges, off it and
 * through the near plane (x in [-4, 4], y in [-2.5, 2.5], z in [-3, 5.5]
 * around the origin the eye looks at from (0, 3, 5.2); hither 8 raw,
 * 0.1, 0.5 and 1.5 units in turn): every frame equal
 * to the renderer's, in mesh order and sorted; how many were cut, left
 * unprojected or empty is printed */
static void run_random(int width, int height, int frames)
{
    /* hither 8 raw (every face's outcodes found), scene_view's 0.1, 0.5
     * or 1.5 units in turn */
    static const stp_fix hithers[4] = {8, 0, STP_FIX_ONE / 2, 3 * STP_FIX_ONE / 2};
    work *w = work_open(width, height, 1);
    int f, differ = 0, cut = 0, unprojected = 0, empty = 0;
    for (f = 0; f < frames; f++) {
        uint16_t yaw = (uint16_t)next_random(), pitch = (uint16_t)next_random();
        double x = (next_random() / 4294967296.0) * 8 - 4, y = (next_random() / 4294967296.0) * 5 - 2.5,
               z = (next_random() / 4294967296.0) * 8.5 - 3;
        long lit = w->lit;
        w->hither = hithers[f & 3];
        differ += frame_differs(w, yaw, pitch, vec(x, y, z));
        cut += w->clipped > 0;
        unprojected += unprojected_points(w) > 0;
        empty += w->lit == lit;
    }
    printf("random %dx%d: %d frames, %d with clipped faces, %d with unprojected vertices, %d empty; %d differ\n",
           width, height, frames, cut, unprojected, empty, differ);
    assert_true(cut > frames / 4 && unprojected > 0 && empty < frames / 2);
    assert_int_equal(differ, 0);
    work_close(w);
}

static void test_random_128x64(void **state)
{
    (void)state;
    run_random(128, 64, 1000);
}

static void test_random_400x240(void **state)
{
    (void)state;
    run_random(400, 240, 200);
}

static void test_near_128x64(void **state)
{
    (void)state;
    run_near(128, 64);
}

static void test_near_400x240(void **state)
{
    (void)state;
    run_near(400, 240);
}
#endif

/* A shared scene direct drawing can draw, still and in 8 poses (turned
 * about its model origin): the three entries equal in every picture */
static void run_scene(const char *name, int width, int height)
{
    run_poses(scene_open(name, width, height));
}

static void test_tetra_s1_128x64(void **state)
{
    (void)state;
    run_scene("tetra-s1", 128, 64);
}

static void test_tetra_s1_400x240(void **state)
{
    (void)state;
    run_scene("tetra-s1", 400, 240);
}

static void test_tetra_s2_128x64(void **state)
{
    (void)state;
    run_scene("tetra-s2", 128, 64);
}

static void test_tetra_s2_400x240(void **state)
{
    (void)state;
    run_scene("tetra-s2", 400, 240);
}

static void test_edges_128x64(void **state)
{
    (void)state;
    run_edges(128, 64);
}

static void test_edges_400x240(void **state)
{
    (void)state;
    run_edges(400, 240);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_torus_128x64),
        cmocka_unit_test(test_torus_400x240),
        cmocka_unit_test(test_edges_128x64),
        cmocka_unit_test(test_edges_400x240),
        cmocka_unit_test(test_tetra_s1_128x64),
        cmocka_unit_test(test_tetra_s1_400x240),
        cmocka_unit_test(test_tetra_s2_128x64),
        cmocka_unit_test(test_tetra_s2_400x240),
#if !STP_DIRECT_COMPACT /* the compact form refuses frames near the eye */
        cmocka_unit_test(test_near_128x64),
        cmocka_unit_test(test_near_400x240),
        cmocka_unit_test(test_random_128x64),
        cmocka_unit_test(test_random_400x240),
#endif
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
