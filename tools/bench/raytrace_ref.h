/* SPDX-License-Identifier: MIT */
/*
 * Double-precision reference ray tracer (host only).
 *
 * Written from the header comment of include/stipple/raytrace.h and docs/model.md
 * sections 1, 2 and 5, sharing no code with the fixed-point core (src/): it
 * recomputes in plain double, nothing quantised, what a ray of the core's
 * stp_rt_trace_pixel sees, so that any difference between the two is
 * numeric error of the core.  The shading equation and the Fresnel factor
 * are tests/reference/shade_ref.c (ref_shade_point, ref_fresnel_f); the view
 * conventions are those of tools/bench/render_ref.h (re-implemented here,
 * same thresholds).  Everything is in world coordinates.
 *
 * What a ray sees (raytrace.h, in real arithmetic):
 *   view          left-handed: forward = unit(at - from), right =
 *                 unit(forward x up), up' = right x forward; focal = (short
 *                 side / 2) / tan(fov / 2) pixels (perspective) or (short
 *                 side / 2) / window_half pixels per world unit (parallel).
 *                 Primary ray of pixel (i, j): through the point
 *                 (i + 1/2 - W/2, H/2 - j - 1/2) pixels from the image centre
 *                 on the plane `focal` pixels ahead, from the eye
 *                 (perspective), or from that point of the window (pixels /
 *                 focal world units along right and up from `from`) along
 *                 forward (parallel).  Hits with view depth t (d.forward) <
 *                 hither are ignored.  Rejected views as ref_set_view:
 *                 from == at, zero up, |unit(forward x up)| < 2^-10, fov
 *                 outside (0, 180), window_half <= 0, hither <= 0.
 *   objects       sphere; open truncated cone (NFF `c`: no caps, radius
 *                 linear along the axis from base_radius at base to
 *                 apex_radius at apex); polygon: plane normal by Newell's
 *                 sums (docs/model.md section 1, on the world vertices, relative
 *                 to v0) normalised, the plane through v0 (N.x = N.v0, as the
 *                 core stores it), inside test even-odd on the projection
 *                 that drops the normal's largest axis (ties: the first of
 *                 x, y, z).
 *   patches       each given vertex normal is normalised first (any length;
 *                 a zero one takes the plane normal, oriented to the side of
 *                 the sum of the non-zero given normals); at a hit they are
 *                 interpolated barycentrically (in the same 2D projection)
 *                 within the fan triangle (v0, v_i, v_i+1) containing the
 *                 hit (the first such i; for a concave polygon whose hit
 *                 lies in none, the triangle it is least outside of) and
 *                 renormalised (a zero sum takes the plane normal).  So at
 *                 the centre of a convex quad (on the diagonal v0 v2) the
 *                 normal is unit(N0 + N2).
 *   nearest hit   smallest accepted t; N the unit normal there, turned to
 *                 face the ray (two-sided; for a patch, the interpolated
 *                 normal itself is turned).
 *   local shade   v_l = ref_shade_point(lighting', R, n, k, Ks, N, P,
 *                 eye = the ray's origin) (perspective primary and all
 *                 secondary rays; parallel primary rays: E = -d), lighting'
 *                 = the world lighting with each power P_j multiplied by its
 *                 visibility: the product of the transmissions t of the
 *                 objects the straight segment from P to light j crosses
 *                 (0 for an opaque one).  Each object counts at most once,
 *                 however often the segment meets it (a sphere crossed in and
 *                 out, or a cone crossed twice: t once); no absorption and no
 *                 Fresnel factor on shadow rays; a hit counts when
 *                 eps <= t < U - eps, U the distance to the light.
 *   Fresnel       F = ref_fresnel_f(c = E.N, n), E = -d, n the material's
 *                 index, the same from both sides of a sphere (the seed's
 *                 surface factor (10.22); the relative index 1/n appears only
 *                 in Snell's law); a NaN (c = 0 with n = 1) is taken as 1.
 *   reflection    with Ks > 0: r = d - 2 (d.N) N, weight w_r = Ks F.
 *   refraction    with t > 0: w_t = t (1 - F).  Spheres bend the ray by
 *                 Snell's law, eta = 1/n entering (d.N_outward < 0), n
 *                 leaving; total internal reflection (eta^2 (1 - c^2) > 1)
 *                 casts no transmitted ray and adds w_t to the reflected
 *                 one's weight (w_r + w_t; the reflected ray is then cast
 *                 even with Ks = 0).  Polygons and cones are thin sheets:
 *                 the transmitted ray goes straight on, d unchanged.
 *   absorption    a ray travelling inside a sphere -- one that starts on
 *                 the sphere heading into it (refracted in, or reflected
 *                 internally) -- is weighted by e^(-a d), a the sphere's
 *                 absorption and d the distance to its next hit (normally
 *                 where it leaves).  Media are not otherwise tracked: the eye
 *                 is in air (a primary ray from an eye inside a sphere is not
 *                 weighted), and a ray leaving an object that lies inside a
 *                 sphere is not weighted either.
 *   result        v = min(1, v_l + w_r v(reflected) + w_t v(transmitted));
 *                 a ray that hits nothing sees `background`; a secondary ray
 *                 is cast only when depth < max_depth (the primary ray has
 *                 depth 0, its children 1, ...) and the product of the
 *                 weights along its path including its own, w_r or w_t, is
 *                 >= min_weight.  The e^(-a d) of a ray inside a sphere is
 *                 part of the path weight of the rays spawned at its hit (it
 *                 is not known when that ray itself is cast).  A ray that is
 *                 not cast contributes 0.
 *   self-hits     exact rules instead of offsets: a secondary or shadow ray
 *                 never tests the polygon it starts on, nor a sphere it
 *                 starts on and leaves outwards (d.N_outward >= 0); on a
 *                 sphere it starts on heading inwards it takes the far root
 *                 only, t = -2 (o - c).d; on a cone it starts on, only the
 *                 other root of the quadratic whose constant term is then
 *                 exactly 0 (t = -2B/A).  Besides, a secondary or shadow ray
 *                 accepts hits with t >= eps only, eps = 1e-9 * the scene
 *                 scale (the largest absolute coordinate of the eye and of
 *                 the objects' bounding boxes; 1 if that is 0): this drops
 *                 the touching surfaces of other objects (a shared edge) and
 *                 tangent re-hits.  Primary rays accept t >= hither /
 *                 (d.forward) and no eps.
 *
 * Defaults at creation (the core's): the view of ref_ctx_init (from
 * (0,0,-1) at the origin, up (0,1,0), 90 degrees, hither 2^-8,
 * perspective), the seed's lighting (one light at (0,0,1), power 1,
 * brightness 1, background 0, C = 1), no materials, max depth 4, min
 * weight 1/64.
 */
#ifndef STIPPLE_TOOLS_BENCH_RAYTRACE_REF_H
#define STIPPLE_TOOLS_BENCH_RAYTRACE_REF_H

#include <stddef.h>

#include "reference/shade_ref.h"
#include "render_ref.h"

/* A ray-tracing material (stp_rt_material's meaning).
 *   surface       R, n, k, Ks (Ks also weights the reflected ray)
 *   transmission  t in [0, 1]; 0 = opaque
 *   absorption    a >= 0 per world unit, inside spheres */
typedef struct ref_rt_material {
    ref_material surface;
    double transmission, absorption;
} ref_rt_material;

typedef struct ref_rt ref_rt;

/* A ray tracer for a width x height device (1..32767 each), with the
 * defaults above.  NULL for a bad size or out of memory. */
ref_rt *ref_rt_create(int width, int height);
void ref_rt_free(ref_rt *rt);

/* The view (ref_view of render_ref.h).  REF_OK, or REF_ERR_VIEW (the view is
 * then unchanged). */
int ref_rt_set_view(ref_rt *rt, const ref_view *v);

/* Lighting, light positions in world coordinates (copied; lights beyond
 * REF_MAX_LIGHTS are dropped). */
void ref_rt_set_lighting(ref_rt *rt, const ref_lighting *world);

/* The material table objects index: KEPT BY POINTER, like the core's (it
 * must outlive the tracing and may change between calls). */
void ref_rt_set_materials(ref_rt *rt, const ref_rt_material *table, size_t count);

/* Recursion limits: max_depth 0..64 (0: primary rays and shadows only),
 * min_weight in [0, 1].  REF_OK, or REF_ERR_ARG (nothing changed). */
int ref_rt_set_recursion(ref_rt *rt, int max_depth, double min_weight);

/* on: a shadow ray leaving a patch (a polygon with vertex normals) ignores
 * the patches sharing a vertex with it, as if the facets were the smooth
 * surface their normals describe (which does not shade itself where its
 * normal faces the light); the reference for the shadow-terminator test.
 * Off by default. */
void ref_rt_set_smooth_shadows(ref_rt *rt, int on);

/* Add objects.  Return the object's id (0, 1, 2, ... in order of adding),
 * or a negative error: REF_ERR_ARG (NULL, a negative radius, both cone
 * radii 0, a material < 0, a non-finite coordinate, out of memory),
 * REF_ERR_DEGENERATE (a zero radius sphere, a cone of zero length, a polygon
 * with fewer than 3 vertices or no area: |Newell| <= 1e-10 of its extent
 * squared, as ref_polygon).  The material index is checked against the
 * table at trace time.  normals: NULL for a flat polygon, else n vertex
 * normals.  Unlike the core there is no limit on coordinates, on the cone's
 * slope or on the number of vertices. */
int ref_rt_sphere(ref_rt *rt, ref_vec3 centre, double radius, int material);
int ref_rt_cone(ref_rt *rt, ref_vec3 base, double base_radius, ref_vec3 apex, double apex_radius,
                int material);
int ref_rt_polygon(ref_rt *rt, const ref_vec3 *v, const ref_vec3 *normals, int n, int material);

size_t ref_rt_object_count(const ref_rt *rt);

/* The shade pixel (x, y) sees, in [0, 1] (grey only); background: the
 * shade of rays that hit nothing.  -1 for a pixel outside the device or an
 * object whose material is outside the table. */
double ref_rt_trace_pixel(const ref_rt *rt, int x, int y, double background);

/* The primary ray of pixel (x, y): origin and unit direction.  REF_OK or
 * REF_ERR_ARG (outside the device). */
int ref_rt_primary_ray(const ref_rt *rt, int x, int y, ref_vec3 *origin, ref_vec3 *dir);

/* The id of the object the primary ray of (x, y) hits (-1: none, or outside
 * the device) and *t (may be NULL) its distance along the unit direction
 * (-1 when none). */
int ref_rt_primary_hit(const ref_rt *rt, int x, int y, double *t);

/* As ref_rt_primary_hit, with the hit point and the unit normal used for
 * shading there (interpolated for patches, turned to face the ray); either
 * pointer may be NULL. */
int ref_rt_primary_surface(const ref_rt *rt, int x, int y, ref_vec3 *point, ref_vec3 *normal);

#endif
