/* SPDX-License-Identifier: MIT */
/*
 * Direct drawing (issue 15 item 3): an immediate-mode path that draws a
 * triangle mesh straight into a 1-bit band, for a spinning model on a
 * small chip.  No display file, no segments: beyond back-face removal
 * the triangles are painted in mesh order, as the full renderer's
 * --hidden none paints them (convex models, or models whose triangles are
 * ordered so later ones may cover earlier ones), far to near after
 * stp_direct_frame_sort, as its painter's sort (--hidden painter) paints
 * them, or with a band of depths after stp_direct_frame_depth, as its Z
 * buffer (--hidden zbuffer) paints them.
 *
 * Per frame:
 *   1. stp_direct_frame_project: every vertex transformed (the model
 *      composed with the view, the renderer's geometry stage: the same
 *      view coordinates as stp_renderer_mesh under
 *      stp_direct_model_transform) and projected once into caller scratch
 *      (stp_direct_point),
 *      every front face shaded once (flat; one light; the seed's ambient +
 *      diffuse equation, docs/model.md section 2, shade_fast.c's prepare and 32-bit
 *      arithmetic) into a per-face byte pair;
 *   2. stp_direct_draw_band for each band of rows (u8g2-style page mode:
 *      one band of caller memory), painting the faces that touch it with
 *      the full renderer's fill rule (pixel centres, top-left rule, Q27.4
 *      device coordinates) and its ordered-dither halftone, MSB first; a
 *      face the picture's edge cuts clipped first, by the renderer's
 *      clipper and projection (not in the compact form, which walks it
 *      whole).
 *
 * 32-bit arithmetic per vertex, face and pixel on 32-bit targets (the
 * face shader's per-frame prepare, shade_fast.c's stp_shade_fast_prepare
 * shared with the mesh route, forms a few 64-bit products; the face shader
 * takes the path its prepare chooses for every route: on 64-bit hosts its
 * 64-bit form, as the mesh route there), no division in any loop over
 * pixels.  Formats and ranges:
 *   Q1.14      int16_t, one = 16384 (STP_MESH_NORMAL_ONE): rotations,
 *              normals.
 *   stp_fix    world and view coordinates (STP_FIX_FRAC_BITS fractional
 *              bits; the limits below are raw, so in units they shrink as
 *              the precision grows: 128 units at 16 bits).  Mesh vertices and the
 *              differences used (translation - eye, light - eye) must be
 *              below 2^23 raw (128 units) in magnitude, the ranges of the
 *              geometry stage's 32-bit form for points near the eye
 *              (view.c); view coordinates then stay below 2^26.
 *   device     Q27.4 (1/16 pixel), kept in int16_t: a vertex projected
 *              in [-8192, 8192) (pixels -512..511); so width, height <=
 *              512.  A vertex nearer than hither or projecting beyond
 *              that range is left unprojected and its faces clipped (in
 *              the compact form the frame is refused with
 *              STP_ERR_RANGE).
 */
#ifndef STIPPLE_DIRECT_H
#define STIPPLE_DIRECT_H

#include <stddef.h>
#include <stdint.h>

#include "stipple/dither.h"
#include "stipple/mesh.h"
#include "stipple/transform.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A camera, prepared once (stp_direct_view_look). */
typedef struct stp_direct_view {
    stp_vec3 from;        /* the eye, world units */
    stp_vec3 axis[3];     /* right, up, forward (left-handed): unit vectors,
                             the renderer's view axes for the same look-at */
    stp_fix focal;        /* pixels per unit of x/z, > 0 */
    stp_fix hither;       /* nearest view z allowed, > 0 */
    uint16_t width, height; /* device pixels, 1..512 */
} stp_direct_view;

/* The camera at from looking at at, with up's projection as the picture's
 * up, focal pixels per unit of x/z (for a field of view fov over the
 * shorter side s: focal = (s / 2) / tan(fov / 2)), points nearer than
 * hither refused.  Errors: STP_ERR_ARG (v NULL, width or height not in
 * 1..512, focal or hither <= 0), STP_ERR_VIEW (from = at,
 * up along the line of sight, or from - at not below 2^23 raw). */
int stp_direct_view_look(stp_direct_view *v, stp_vec3 from, stp_vec3 at, stp_vec3 up, stp_fix focal,
                         stp_fix hither, uint16_t width, uint16_t height);

/* A model transform: p' = scale (rot p) + translate. */
typedef struct stp_direct_model {
    int16_t rot[3][3];   /* a rotation, row-major, Q1.14 */
    stp_fix scale;       /* uniform, (0, 2); 1 (STP_FIX_ONE) in the compact
                            form (config.h's STP_DIRECT_COMPACT) */
    stp_vec3 translate;  /* world units */
} stp_direct_model;

/* The renderer's model transform of m (stp_renderer_set_transform):
 * entries floor(rot scale / 2^14), the translation as it is.  Direct
 * drawing places its vertices by this transform composed with the view,
 * as the renderer's geometry stage composes them, so a mesh drawn by
 * direct drawing and by stp_renderer_mesh under it has the same view
 * coordinates and device positions.  m or out NULL is ignored. */
void stp_direct_model_transform(const stp_direct_model *m, stp_transform *out);

/* sin(2 pi angle / 65536) in Q1.14 (angle: 1/65536 of a turn), within
 * 2 raw units: a 65-entry quarter table and linear interpolation. */
int16_t stp_direct_sin(uint16_t angle);

/* The model turned by yaw about the y axis, then by pitch about the x
 * axis (angles in 1/65536 of a turn), scaled and translated: rot =
 * Rx(pitch) Ry(yaw).  m NULL is ignored. */
void stp_direct_model_turn(stp_direct_model *m, uint16_t yaw, uint16_t pitch, stp_fix scale,
                           stp_vec3 translate);

/* The one light and the material (docs/model.md section 2, one light):
 *   s = min(1, BRIGHT (B R + P R (N.L) / (C + U)))
 * position: world units; power P, brightness BRIGHT in [0, 256);
 * background B and reflectivity R in [0, 1]; attenuation_c C > 0 (values
 * <= 0 are taken as 1 raw unit, as shade.c does). */
typedef struct stp_direct_light {
    stp_vec3 position;
    stp_fix power;
    stp_fix brightness;
    stp_fix background;
    stp_fix attenuation_c;
    stp_fix reflectivity;
} stp_direct_light;

/* Deprecated: stp_mesh_prepare_normals(mesh, normals, NULL), the one
 * function for mesh normals (mesh.h), which it calls: the same normals,
 * the same errors. */
int stp_direct_mesh_normals(const stp_mesh *mesh, int16_t *normals);

/* Per-vertex scratch (caller memory, one per mesh vertex; 16 bytes). */
typedef struct stp_direct_point {
    int32_t x, y, z;     /* view coordinates, stp_fix */
    int16_t dx, dy;      /* device position, Q27.4 */
} stp_direct_point;

/* One frame, as stp_direct_frame_project leaves it for the bands. */
typedef struct stp_direct_frame {
    const stp_mesh *mesh;
    const stp_direct_point *points;
    const uint16_t *faces;    /* per triangle: 0 not drawn, else 256 + intensity
                                 (+ STP_DIRECT_FACE_CLIPPED) */
    const uint8_t *cell;      /* 4 x 4 thresholds, row-major */
    uint16_t width, height;
    uint16_t layout;          /* the bands' stp_band_layout: STP_BAND_ROWS after
                                 stp_direct_frame_project; set STP_BAND_PAGES
                                 before drawing for a page-layout panel */
    /* the painter's order (not set or read in the compact form, config.h's
     * STP_DIRECT_COMPACT, which has no sort) */
    uint16_t order_count;     /* the faces in order (stp_direct_frame_sort) */
    stp_fix hither;           /* the view's: the depth keys' */
    const stp_sort_entry *order; /* the bands' order of faces, far to near
                                    (stp_direct_frame_sort), or NULL (after
                                    stp_direct_frame_project): mesh order */
    /* the renderer's clipping (not set or read in the compact form) */
    stp_fix focal;            /* the view's: its pyramid's */
    uint16_t clipped;         /* front faces the pyramid's sides cut
                                 (faces[] holds STP_DIRECT_FACE_CLIPPED) */
    /* the renderer's Z buffer (stp_direct_frame_depth), or NULL: none */
    const struct stp_direct_depth *depth;
} stp_direct_frame;

/* The flag faces[t] carries beside 256 + intensity for a front face the
 * picture's edge cuts: the bands draw it clipped to the view's pyramid
 * (not in the compact form). */
#define STP_DIRECT_FACE_CLIPPED 512u

/* The device position (dx and dy) of a point the projection leaves out:
 * nearer than hither, or outside the device range (not in the compact
 * form, which refuses such a frame).  Every face it is a corner of is
 * clipped or not drawn. */
#define STP_DIRECT_UNPROJECTED INT16_MIN

/* Transform, project and shade one frame of mesh (prepared normals
 * required: stp_mesh_prepare_normals) under model, view and light, into
 * points[0 .. vertex_count - 1] and faces[0 .. triangle_count - 1] (caller
 * memory, kept until the frame's bands are drawn) and *f: the vertices'
 * view coordinates and device positions stp_renderer_mesh gives under
 * stp_direct_model_transform(model).  A face is drawn when the eye sees
 * its front, as the mesh route decides it (the exact sign of N.(eye - v0)
 * in model coordinates; in the compact form, config.h's
 * STP_DIRECT_COMPACT, when its projected vertices turn counter-clockwise
 * on the screen), and shaded as the mesh route shades it; its shade goes through
 * INTENSITY with levels (2..255) styles and the linear 8-bit drive value
 * ((index - 1) 255 / (levels - 1), rounded), later compared with cell
 * (4 x 4 thresholds, row-major: a Bayer cell's, stp_cell_bayer) pixel by
 * pixel: ON where intensity > threshold.
 * Errors: STP_ERR_ARG (a pointer NULL, a mesh array NULL, an index not
 * below vertex_count, point_count or face_count too small, levels
 * outside 2..255, scale outside (0, 2) or in the compact form other than
 * 1, a light value outside its range, rot not a rotation or the scale
 * below 2^-6: the face stage's model frame, not with STP_DIRECT_COMPACT;
 * in the compact form rot so far from a rotation that its composite with
 * the view leaves Q1.14), STP_ERR_RANGE (a coordinate
 * beyond 2^23 raw, a scale within about 2^-12 of 2, where a composite
 * axis reaches 2^17, or in the compact form a vertex nearer than hither
 * or projecting outside the device range, which the default form clips
 * as the renderer does); *f is then not usable. */
int stp_direct_frame_project(stp_direct_frame *f, const stp_mesh *mesh, const stp_direct_model *model,
                             const stp_direct_view *view, const stp_direct_light *light, int levels,
                             const uint8_t cell[16], stp_direct_point *points, size_t point_count,
                             uint16_t *faces, size_t face_count);

/* A light prepared for a view: the face shader's constants, which depend
 * on the view and the light, not on the model (an opaque type: its layout
 * follows the build's configuration and the target's arithmetic).
 * stp_direct_frame_project prepares one for every frame; a program whose
 * view and light stay fixed may carry it as data made on the host for the
 * same configuration (guarded by the compatibility tag, config_guard.h)
 * and call stp_direct_frame_project_lit, so the prepare and its 64-bit
 * arithmetic are not linked: the Arduino examples' spin does
 * (ports/arduino/src/stipple_spin.c). */
typedef struct stp_direct_lit stp_direct_lit;

/* stp_direct_frame_project with the light already prepared for view
 * (lit): the same frame, the same errors but the light's (STP_ERR_ARG for
 * lit NULL). */
int stp_direct_frame_project_lit(stp_direct_frame *f, const stp_mesh *mesh, const stp_direct_model *model,
                                 const stp_direct_view *view, const stp_direct_lit *lit, int levels,
                                 const uint8_t cell[16], stp_direct_point *points, size_t point_count,
                                 uint16_t *faces, size_t face_count);

/* Draw rows y0 .. y0 + rows - 1 of frame f into band, 1 bit per pixel,
 * bit 1 = ON, in f->layout:
 *   STP_BAND_ROWS   rows x stride bytes, most significant bit first;
 *                   stride >= (width + 7) / 8;
 *   STP_BAND_PAGES  (rows + 7) / 8 pages of stride bytes, one byte a
 *                   column, least significant bit the top row (the
 *                   SSD1306 / SH1106 GDDRAM layout); stride >= width, y0 a
 *                   multiple of 8 (bits of a last page below rows are 0).
 * The band is cleared (OFF) first, then every drawn face is painted in
 * mesh order, far to near after stp_direct_frame_sort, or depth-tested
 * after stp_direct_frame_depth; both layouts hold the same pixels.  Errors: STP_ERR_ARG (f,
 * its arrays or band NULL, an unknown layout, stride too small, rows 0,
 * y0 + rows > height, a page band's y0 not a multiple of 8, a depth
 * buffer's zband_count below width x rows: stp_direct_frame_depth),
 * STP_ERR_UNSUPPORTED (STP_BAND_PAGES in a build without STP_WITH_PAGES). */
int stp_direct_draw_band(const stp_direct_frame *f, uint8_t *band, size_t stride, uint16_t y0,
                         uint16_t rows);

/* Order the front faces of frame f (after stp_direct_frame_project) far
 * to near for stp_direct_draw_band, as the renderer's painter's sort
 * (STP_HIDDEN_PAINTER) orders them: by the depth key of each face's
 * farthest vertex (the projection's floor(hither 2^30 / z), z its view
 * depth; a face the picture's edge or the near plane cuts by its clipped
 * polygon's, as the renderer keys what it stores, and one clipped to
 * nothing left out), ties in mesh order; a heap sort, O(n log n) in the n
 * front faces, no recursion.  A face nearer the eye then covers the faces
 * behind it, so a model that is not convex (a torus) is drawn as
 * stp_renderer_render draws it with STP_HIDDEN_PAINTER, pixel for pixel
 * (and for the test torus as with the Z buffer, all but a pixel in 3 of
 * 1 342 frames: test_direct_equal).  order: caller memory of order_count
 * entries, at least the front faces (at most the mesh's triangle_count),
 * kept with the frame until its bands are drawn; f->order points to it.
 * Errors: STP_ERR_ARG (f, order or the frame's arrays NULL),
 * STP_ERR_FULL (order_count below the faces to order), STP_ERR_UNSUPPORTED
 * (the compact form, config.h's STP_DIRECT_COMPACT: the smallest images
 * keep mesh order); f then keeps mesh order. */
int stp_direct_frame_sort(stp_direct_frame *f, stp_sort_entry *order, size_t order_count);

/* A depth buffer for direct drawing (stp_direct_frame_depth): the
 * caller's memory, set once; the rest set by each frame's call and read by
 * its bands. */
typedef struct stp_direct_depth {
    int32_t *depths;          /* depth_count entries, at least the mesh's
                                 vertex_count: the vertices' Q12 depths */
    size_t depth_count;
    uint16_t *zband;          /* zband_count entries, at least width x the
                                 most rows a band draws: a band's depths */
    size_t zband_count;
    /* set by stp_direct_frame_depth: */
    int32_t key_min, key_max; /* the stored faces' depth keys */
    /* the depth-tested band fill (so only a program that calls
     * stp_direct_frame_depth links it) */
    void (*draw)(const struct stp_direct_frame *f, uint8_t *band, size_t stride, uint16_t y0, uint16_t rows);
} stp_direct_depth;

/* Hidden surfaces by a depth buffer for frame f (after
 * stp_direct_frame_project), as stp_renderer_render's Z buffer
 * (STP_HIDDEN_ZBUFFER) removes them: stp_direct_draw_band then paints the
 * front faces in mesh order, each pixel where the face is nearer than
 * what the band holds there, with the renderer's depths (its depth keys
 * mapped over the range of the faces it would store, its depth planes and
 * pixel depths: depth_private.h), so the bands hold the renderer's
 * picture pixel for pixel, a model that is not convex included.  depth:
 * caller memory, its depths and zband set by the caller (4 bytes a vertex;
 * 2 bytes a pixel of the tallest band: 2 KiB for 8 rows of 128), kept
 * with the frame until its bands are drawn (f->depth points to it).  f
 * then draws in mesh order (a sort before is undone;
 * stp_direct_frame_sort after undoes this).  Errors: STP_ERR_ARG (f,
 * depth, its arrays or the frame's NULL, depth_count below vertex_count,
 * zband_count below width), STP_ERR_UNSUPPORTED (the compact form,
 * config.h's STP_DIRECT_COMPACT, or a build without STP_WITH_ZBUFFER); f
 * then keeps its order. */
int stp_direct_frame_depth(stp_direct_frame *f, stp_direct_depth *depth);

#ifdef __cplusplus
}
#endif

#endif
