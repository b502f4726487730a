/* SPDX-License-Identifier: MIT */
/*
 * The ray tracer (docs/model.md section 5, last item): one ray per pixel from the
 * eye, the nearest hit shaded with (10.16), a shadow ray to each light, and
 * reflected and refracted rays followed recursively until a ray hits
 * nothing, the depth limit is reached or its weight is too small to matter.
 *
 * It shares the polygon renderer's view (stp_view), lighting (stp_lighting),
 * shading (stp_shade_point), INTENSITY, gamma, halftone and band output
 * (stp_output, stp_port), but not its display file: objects are kept in
 * world coordinates in caller memory.  Compiled in with STP_WITH_RAYTRACE
 * (without it only stp_rt_size and stp_rt_create exist, returning 0 and
 * NULL); a program that does not call it does not link it (its own object
 * file).
 *
 * What a ray sees (this is what tools/bench/raytrace_ref.c recomputes in
 * double precision; numbers are the core's choices):
 *   primary ray   pixel (i, j): perspective: from the eye through the point
 *                 (i + 1/2 - W/2, H/2 - j - 1/2) pixels from the image
 *                 centre on a plane `focal` pixels ahead (focal = (short
 *                 side / 2) / tan(fov / 2), as stp_renderer_set_view); parallel: along
 *                 the line of sight from that point of the window.  Hits
 *                 nearer the eye than the hither plane are ignored.
 *   nearest hit   the object with the smallest t > t_min; N its unit
 *                 normal there (patches: the vertex normals interpolated,
 *                 renormalised), turned to face the ray (two-sided).
 *   local shade   v_l = stp_shade_point(lighting', R, n, k, Ks, N, P,
 *                 eye = the ray's origin) (perspective primary rays and all
 *                 secondary rays; parallel primary rays use E = -d), where
 *                 lighting' is the lighting with each light's power P_j
 *                 multiplied by its visibility: 1 when the segment from P
 *                 to the light crosses no object, else the product of the
 *                 transmissions t of the objects it crosses (0 for an opaque
 *                 one; no bending: shadow rays go straight).  So v_l is
 *                 min(1, BRIGHT (B R + sum_j vis_j P_j (...)/(C + U_j))).
 *   reflection    with Ks > 0: the mirror ray r = d - 2 (d.N) N, weight
 *                 w_r = Ks F(c = E.N, n), F the Fresnel factor (10.6) with
 *                 c = E.N as (10.22) says.
 *   refraction    with t > 0: spheres bend the ray by Snell's law (10.19),
 *                 index 1 outside and n inside (entering when the ray meets
 *                 the outward normal head on); total internal reflection
 *                 sends the whole transmitted share into the reflected ray.
 *                 Polygons and cones are thin sheets: the ray goes straight
 *                 through.  Weight w_t = t (1 - F); a ray travelling inside
 *                 a sphere is further weighted by e^(-a d) (10.18), d the
 *                 distance to where it leaves.
 *   result        v = min(1, v_l + w_r v(reflected) + w_t v(transmitted)),
 *                 a ray that hits nothing sees the output's background;
 *                 a secondary ray is cast only when depth < max_depth and
 *                 the product of the weights along the path >= min_weight.
 *   colour        with stp_rt_set_colour(rt, 1) each of r, g, b is traced
 *                 the same way with stp_shade_point_colour; grey output
 *                 shows its luminance.
 *
 * Precision (fixed point throughout; positions stp_fix, directions and
 * normals Q30, distances t stp_fix; see src/raytrace.c):
 *   large distances  every coordinate must lie within +-STP_RT_COORD_LIMIT
 *                    (raw), so differences stay below 2^29 and squared
 *                    lengths below 2^60 in 64 bits: the add functions refuse
 *                    larger with STP_ERR_ARG.  Sphere hits use the
 *                    perpendicular form h^2 = r^2 - |oc - (oc.d) d|^2, which
 *                    has no cancellation of large terms for distant spheres.
 *   grazing hits     a ray within 2^-20 (as a cosine) of a polygon's plane
 *                    misses it; a ray tangent to a sphere or cone hits at one
 *                    point (h = 0) or misses, never divides by zero.
 *   self-hits        a secondary ray never tests the plane it starts on (a
 *                    polygon cannot be hit twice by one straight ray), nor a
 *                    sphere it leaves outwards (convex); a ray inside a
 *                    sphere takes its far root only; every secondary ray
 *                    starts STP_RT_OFFSET (raw) off the surface on its own
 *                    side and ignores hits nearer than that (cones).
 *   shadow terminator a shadow ray leaving a patch (a polygon with vertex
 *                    normals) starts on the side its interpolated normal
 *                    faces and passes the patches sharing a corner with it
 *                    (same coordinates), so the flat facets do not shade the
 *                    smooth surface they stand for (no seams where the
 *                    normal faces a light the facet turns from).
 */
#ifndef STIPPLE_RAYTRACE_H
#define STIPPLE_RAYTRACE_H

#include <stddef.h>
#include <stdint.h>
#include "stipple/config.h"
#include "stipple/config_guard.h"
#include "stipple/dither.h"
#include "stipple/fix.h"
#include "stipple/port.h"
#include "stipple/render.h"
#include "stipple/shade.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Coordinates (raw stp_fix) must lie within +-2^28: 4096 world units at
 * F = 16, 256 at F = 20. */
#define STP_RT_COORD_LIMIT ((int32_t)1 << 28)
/* How far (raw stp_fix, 2^-12 units at F = 16) a secondary ray starts off
 * the surface it leaves. */
#define STP_RT_OFFSET ((int32_t)1 << (STP_FIX_FRAC_BITS - 12))

/* A ray-tracing material: the shading parameters of the polygon renderer
 * and the transparency of (10.18).
 *   surface       R, n, k, Ks (Ks also weights the reflected ray), colour
 *   transmission  t in [0, 1]; 0 = opaque
 *   absorption    a >= 0 per world unit, inside spheres (0: none) */
typedef struct stp_rt_material {
    stp_material surface;
    stp_fix transmission;
    stp_fix absorption;
} stp_rt_material;

/* One object (sphere, cone or polygon) in caller memory.  The fields are
 * the ray tracer's own (set by stp_rt_sphere and friends); the type is
 * public only so that arrays of it can be declared. */
typedef struct stp_rt_object {
    uint8_t kind, flags;
    uint16_t count;       /* polygon: vertices */
    uint32_t material;
    uint32_t first;       /* polygon: first point (vertices, then normals) */
    int32_t a[3];         /* sphere: centre; cone: base; polygon: unit normal Q30 */
    int32_t b[3];         /* cone: axis Q30 */
    int32_t r0;           /* sphere: radius; cone: base radius */
    int32_t slope;        /* cone: radius change per unit along the axis, Q24 */
    int32_t length;       /* cone: base to apex */
    int32_t bound;        /* cone: radius of a sphere around it (centre at
                             half its length) */
    int64_t offset;       /* polygon: N.v0 with F + 30 fractional bits */
    int32_t lo[3], hi[3]; /* bounding box */
} stp_rt_object;

/* A node of the bounding-volume hierarchy (fields private). */
typedef struct stp_rt_node {
    int32_t lo[3], hi[3];
    uint32_t first; /* leaf: first entry of the order array; inner: left child */
    uint32_t count; /* leaf: objects (>= 1); inner: 0 (right child = left + 1) */
} stp_rt_node;

/* Memory the caller lends for the scene (it must outlive the ray tracer).
 *   objects, object_capacity   one per sphere, cone or polygon
 *   points, point_capacity     polygon vertices: n per polygon, 2n for one
 *                              with vertex normals
 *   nodes, node_capacity       the hierarchy: 2 * objects - 1 suffice;
 *                              NULL/0 when stp_rt_build is never called
 *   order                      object_capacity entries, with nodes */
typedef struct stp_rt_memory {
    stp_rt_object *objects;
    uint32_t object_capacity;
    stp_vec3 *points;
    uint32_t point_capacity;
    stp_rt_node *nodes;
    uint32_t node_capacity;
    uint32_t *order;
} stp_rt_memory;

typedef struct stp_raytracer stp_raytracer;

/* Bytes a ray tracer object needs, and a bound known at compile time for
 * static storage (alignment of int64_t). */
size_t stp_rt_size(void);
#define STP_RAYTRACER_BYTES (512u + 64u * STP_MAX_LIGHTS)
typedef union stp_raytracer_storage {
    int64_t align_integer;
    void *align_pointer;
    uint8_t bytes[STP_RAYTRACER_BYTES];
} stp_raytracer_storage;

/* Create a ray tracer in mem (stp_rt_size() bytes, aligned for int64_t and
 * pointers: an stp_raytracer_storage or malloc) for a width x height
 * device (1..32767 each) with the scene memory m (copied; the arrays are
 * used in place).  Starts with: the default view of stp_renderer_create,
 * the seed's default lighting, no materials, 16 levels, grey, max depth 4,
 * min weight 1/64, no hierarchy.  Returns NULL for a NULL or too small
 * argument, mem not aligned, or STP_WITH_RAYTRACE 0. */
stp_raytracer *stp_rt_create(void *mem, size_t mem_size, const stp_rt_memory *m, uint32_t width,
                             uint32_t height);

/* The view, as for stp_renderer_set_view (same errors: STP_ERR_VIEW, STP_ERR_ARG;
 * STP_ERR_ARG also for an eye beyond STP_RT_COORD_LIMIT). */
int stp_rt_set_view(stp_raytracer *rt, const stp_view *view);

/* Lighting in world units (stp_renderer_set_lighting's meaning).  STP_ERR_ARG for a
 * count outside 0..STP_MAX_LIGHTS or a light beyond STP_RT_COORD_LIMIT. */
int stp_rt_set_lighting(stp_raytracer *rt, const stp_lighting *lighting);

/* The material table objects index (caller memory, kept by pointer; it may
 * change between renders).  STP_ERR_ARG for NULL with count > 0. */
int stp_rt_set_materials(stp_raytracer *rt, const stp_rt_material *table, uint32_t count);

/* Recursion limits: max_depth 0..STP_RT_MAX_DEPTH (0: primary rays and
 * shadows only), min_weight in [0, 1].  STP_ERR_ARG outside. */
int stp_rt_set_recursion(stp_raytracer *rt, int max_depth, stp_fix min_weight);

/* INTENSITY levels 2..256 (default 16).  STP_ERR_ARG outside. */
int stp_rt_set_levels(stp_raytracer *rt, int levels);

/* Colour tracing on (1) or off (0); STP_ERR_UNSUPPORTED without
 * STP_WITH_COLOUR. */
int stp_rt_set_colour(stp_raytracer *rt, int on);

/* Add objects (world units; material: an index into the table, checked at
 * render time).  Errors: STP_ERR_ARG (NULL, a radius < 0 or both cone radii
 * 0, a coordinate beyond STP_RT_COORD_LIMIT, a cone whose radius changes by
 * more than 16 per unit of length), STP_ERR_FULL (objects or points),
 * STP_ERR_DEGENERATE (a zero radius sphere, a cone of zero length, a
 * polygon with no area), STP_ERR_TOO_MANY_VERTICES (n above
 * STP_MAX_POLYGON_VERTICES).  A cone is open (no end caps), as NFF's.
 * normals: NULL for a flat polygon, else n vertex normals (any length; a
 * zero one takes the plane's) interpolated across it (an NFF patch).
 * Adding an object drops the hierarchy (build again). */
int stp_rt_sphere(stp_raytracer *rt, stp_vec3 centre, stp_fix radius, uint32_t material);
int stp_rt_cone(stp_raytracer *rt, stp_vec3 base, stp_fix base_radius, stp_vec3 apex,
                stp_fix apex_radius, uint32_t material);
int stp_rt_polygon(stp_raytracer *rt, const stp_vec3 *vertices, const stp_vec3 *normals, int n,
                   uint32_t material);

/* Objects added so far. */
uint32_t stp_rt_object_count(const stp_raytracer *rt);

/* Build the bounding-volume hierarchy over the objects (median split along
 * the longest axis, leaves of at most 4): O(n log n).  Without it every ray
 * tests every object.  STP_ERR_MEMORY when node_capacity < 2n - 1 or no
 * order array. */
int stp_rt_build(stp_raytracer *rt);

/* Counters since creation or the last reset (for benchmarks). */
typedef struct stp_rt_stats {
    uint32_t rays;         /* primary and secondary rays */
    uint32_t shadow_rays;
    uint32_t box_tests;    /* hierarchy nodes tested */
    uint32_t object_tests; /* ray-object intersection tests */
} stp_rt_stats;
void stp_rt_get_stats(const stp_raytracer *rt, stp_rt_stats *out);
void stp_rt_reset_stats(stp_raytracer *rt);

/* The shade pixel (x, y) sees, each channel in [0, 1] (grey: out[0], with
 * out[1] = out[2] = out[0]); background: the shade of rays that hit
 * nothing (3 channels, or NULL for 0).  Errors: STP_ERR_ARG (outside the
 * device, a material index outside the table). */
int stp_rt_trace_pixel(stp_raytracer *rt, uint32_t x, uint32_t y, const stp_fix *background,
                       stp_fix out[3]);

/* Trace every pixel and send the picture to the port band by band through
 * INTENSITY, the gamma table and the halftone (MONO1: each pixel's level
 * against its own threshold, as smooth polygons), as stp_renderer_render does.
 * output: hidden is ignored; background and background_colour give the
 * misses.  band: band_rows * stp_row_bytes(format, width) bytes (GREY8 rows
 * when output->diffusion diffuses a 1-bit picture; STP_PIXEL_MONO1_PAGES:
 * (band_rows + 7) / 8 pages of width bytes).  Errors: STP_ERR_ARG
 * (also a STP_PIXEL_MONO1_PAGES port with band_rows neither a multiple of 8
 * nor the height), STP_ERR_MEMORY (band too small), STP_ERR_UNSUPPORTED
 * (STP_PIXEL_MONO1_PAGES in a build without STP_WITH_PAGES), STP_ERR_PORT. */
int stp_rt_render(stp_raytracer *rt, stp_port *port, const stp_output *output, uint8_t *band,
                  size_t band_size, uint32_t band_rows);

#ifdef __cplusplus
}
#endif

#endif
