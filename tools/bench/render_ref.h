/* SPDX-License-Identifier: MIT */
/*
 * Double-precision reference renderer (host only).
 *
 * Written from docs/model.md and the conventions documented in the public headers
 * (include/stipple/render.h: view system, fill rule; shade.h: shading
 * conventions), sharing no code with the fixed-point core: it renders the
 * same scenes through the same pipeline choices as stp_tool_render
 * (tools/render_scene.c), so that any difference between the two is numeric
 * error of the core.  The shading equation itself is tests/reference/
 * shade_ref.c (ref_shade_point).
 *
 * Pipeline, as the core's (each step in plain double, nothing quantised):
 *   - view: left-handed view system, x right, y up, z forward along the
 *     line of sight; right = unit(dir x up), up' = right x dir; the field of
 *     view spans the shorter side of the device; parallel projection maps
 *     window_half world units to half the shorter side;
 *   - lighting copied at ref_set_lighting (COPY-LIGHT): positions to view
 *     coordinates with the view then current;
 *   - polygon: Newell normal (Algorithm 10.4) of the view-space vertices,
 *     negated for the left-handed system; a zero normal (below 1e-10 of the
 *     polygon's extent squared: collinear vertices keep only rounding noise
 *     of area) = degenerate, nothing drawn; shaded at the vertex average; E = unit(-centre) (perspective)
 *     or (0, 0, -1) (parallel); N.E <= 0 flips N (two-sided lighting) or,
 *     with back-face removal, drops the polygon; INTENSITY index of the shade;
 *   - clipping to the hither plane z >= hither (the window is handled by
 *     sampling only pixel centres inside the device, which is equivalent);
 *   - projection x = W/2 + focal x/z, y = H/2 - focal y/z (perspective),
 *     x = W/2 + focal x, y = H/2 - focal y (parallel); device y down;
 *   - fill rule: a pixel belongs to a polygon when its centre is inside by
 *     the even-odd rule, edges covering y_top <= c < y_bottom and spans
 *     x_left <= c < x_right (render.h);
 *   - hidden surfaces: none (polygon order), painter (farthest vertex
 *     first, ties by order) or a Z buffer in double: the depth key 1/z
 *     (perspective; -z parallel) of the polygon's plane at the pixel centre,
 *     a pixel drawn when its key is strictly greater (nearer) than the
 *     buffer's;
 *   - pixels: GREY8 level of the style, round((index-1) 255 / (levels-1))
 *     (or the gamma (10.44) of (index-1)/(levels-1)), and MONO1 by the
 *     ordered-dither rule ON when level > threshold, Bayer 2x2 or 4x4 cell
 *     with linear spacing (thresholds ceil(255(r+1)/(m+1)) - 1, ranks of
 *     ImageMagick's o2x2 / o4x4 maps).
 */
#ifndef STIPPLE_TOOLS_BENCH_RENDER_REF_H
#define STIPPLE_TOOLS_BENCH_RENDER_REF_H

#include <stddef.h>

#include "reference/shade_ref.h"
#include "scene.h"

/* Results of ref_polygon (mirroring the core's status values in meaning). */
enum {
    REF_OK = 0,
    REF_ERR_ARG = -1,
    REF_ERR_DEGENERATE = -6, /* fewer than 3 vertices or zero Newell normal */
    REF_ERR_VIEW = -9
};

enum { REF_HIDDEN_NONE = 0, REF_HIDDEN_PAINTER = 1, REF_HIDDEN_ZBUFFER = 2 };

typedef struct ref_view {
    ref_vec3 from, at, up;
    double fov_degrees; /* perspective: full angle over the shorter side */
    double window_half; /* parallel: half the shorter side in world units */
    double hither;      /* > 0 */
    int perspective;    /* 1 perspective, 0 parallel */
} ref_view;

/* A view turned into its basis and focal length (both references use it):
 * forward = unit(at - from), right = unit(forward x up), up' = right x
 * forward; focal = (short side / 2) / tan(fov / 2) pixels (perspective) or
 * (short side / 2) / window_half pixels per unit (parallel). */
typedef struct ref_view_frame {
    ref_vec3 from, right, up, forward;
    double focal, hither;
    int perspective;
} ref_view_frame;

/* REF_OK, or REF_ERR_VIEW (from == at, zero up, |unit(forward x up)| below
 * the core's 2^-10, fov outside (0, 180), window_half or hither <= 0);
 * *out is written only on success. */
int ref_view_frame_make(const ref_view *v, int width, int height, ref_view_frame *out);

/* One polygon kept for scan conversion. */
typedef struct ref_poly2 {
    size_t first;     /* into the context's projected vertices */
    int count;
    int style;
    size_t tag;       /* caller's polygon number */
    double ka, kb, kc; /* depth key = ka x + kb y + kc at device (x, y) */
    int edge_on;      /* no area on screen: never drawn with the Z buffer */
    double far_key;   /* smallest key of its vertices (painter) */
} ref_poly2;

typedef struct ref_ctx {
    int width, height, levels;
    int backface_removal, shading, fill_style;
    /* view */
    ref_vec3 from, right, up, forward;
    double focal, hither;
    int perspective;
    /* lighting in view coordinates (COPY-LIGHT) and the material */
    ref_lighting lighting;
    ref_material material;
    double last_shade; /* shade of the last ref_polygon call, -1 if none */
    int last_style;
    double last_n_dot_e; /* |N.E| of the last polygon (its conditioning), -1 if none */
    double last_size;    /* its largest distance from its first vertex */
    /* polygons waiting for ref_finish */
    ref_poly2 *polys;
    size_t poly_count, poly_cap;
    double *xy; /* projected vertices, x y pairs */
    size_t xy_count, xy_cap;
} ref_ctx;

/* Output options of ref_finish. */
typedef struct ref_output {
    int hidden;         /* REF_HIDDEN_* */
    int cell;           /* Bayer cell side for MONO1: 2 or 4 */
    double gamma, gamma_k; /* 1, 1: linear levels */
    double background;  /* shade of the empty frame, [0, 1] */
} ref_output;

/* A context for a width x height device with the core's defaults (levels
 * 16, shading off, fill style 16, no back-face removal, view from (0,0,-1)
 * at the origin, 90 degrees, hither 2^-8, seed lighting and material).
 * Returns 0, or -1 (bad size, out of memory). */
int ref_ctx_init(ref_ctx *c, int width, int height);
void ref_ctx_free(ref_ctx *c);

int ref_set_view(ref_ctx *c, const ref_view *v); /* REF_OK or REF_ERR_VIEW */
/* Lights' positions in world coordinates; converted with the current view. */
void ref_set_lighting(ref_ctx *c, const ref_lighting *world);
void ref_set_material(ref_ctx *c, const ref_material *m);

/* World point to view coordinates with the current view. */
ref_vec3 ref_world_to_view(const ref_ctx *c, ref_vec3 p);

/* DISPLAY-FILE-ENTER for one polygon of n world vertices: shade (when
 * shading is on; else the fill style), clip, project and keep it for
 * ref_finish under the given tag.  *shade (may be NULL) receives the shade
 * (-1 when the polygon is degenerate or removed as a back face).
 * Returns REF_OK or REF_ERR_DEGENERATE. */
int ref_polygon(ref_ctx *c, const ref_vec3 *v, int n, size_t tag, double *shade);

/* Scan-convert the kept polygons.  Any of grey (GREY8 levels), mono (0/1
 * per pixel, 1 = ON), style (INTENSITY index per pixel, background style
 * where nothing is drawn) and owner (tag of the polygon seen, or -1) may be
 * NULL; each holds width * height entries, row-major, top row first.
 * Returns 0, or -1 for a bad output description. */
int ref_finish(ref_ctx *c, const ref_output *out, unsigned char *grey, unsigned char *mono,
               int *style, long *owner);

/* INTENSITY style of shade s and the GREY8 level of a style. */
int ref_level(int style, int levels, double gamma, double gamma_k);

/* ---- whole scenes, mirroring stp_tool_render */

typedef struct ref_render_options {
    int width, height, levels;
    int cell;                  /* Bayer side: 2 or 4 */
    double gamma, gamma_k;
    int hidden;                /* REF_HIDDEN_* */
    int backface_removal, shading;
    double background, brightness, attenuation_c;
    int auto_power;
    int light_count;           /* > 0: these replace the scene's lights */
    ref_vec3 lights[REF_MAX_LIGHTS];
    double light_weight[REF_MAX_LIGHTS]; /* with light_count: how many of the file's
                                  lights each stands for (merged, as
                                  stp_tool_prepare does; 0 counts as 1) */
    int max_lights;            /* the core's STP_MAX_LIGHTS (lights beyond are dropped) */
    int max_vertices;          /* the core's STP_MAX_POLYGON_VERTICES (0: no limit) */
    int perspective;
    double fov;                /* 0: the scene's */
} ref_render_options;

/* The defaults of stp_tool_options_default (128 x 64, 16 levels, Bayer 4x4,
 * Z buffer, shading on, background 0.2, brightness 1, C 1, auto power,
 * perspective), max_lights 4, max_vertices 160. */
void ref_render_options_default(ref_render_options *o);

typedef struct ref_render_result {
    int width, height;
    size_t polygon_count;    /* the scene's polygons */
    double *shade;           /* per scene polygon, -1 where degenerate/removed */
    double *n_dot_e;         /* per scene polygon, |N.E| (-1 where degenerate) */
    double *size;            /* per scene polygon, its extent (world units) */
    int *poly_style;         /* per scene polygon, 0 where degenerate/removed */
    unsigned char *grey;     /* width * height */
    unsigned char *mono;     /* width * height, 0/1 */
    long *owner;             /* width * height, polygon index or -1 */
    size_t degenerate;       /* polygons skipped as degenerate */
} ref_render_result;

/* Render scene; returns 0, or -1 with a message in err.  Free the result
 * with ref_render_result_free. */
int ref_render_scene(const stp_scene *scene, const ref_render_options *opt,
                     ref_render_result *res, char *err, size_t err_size);
void ref_render_result_free(ref_render_result *res);

#endif
