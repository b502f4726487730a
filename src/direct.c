/* SPDX-License-Identifier: MIT */
/* Direct drawing's per-frame step (include/stipple/direct.h): every vertex
 * transformed and projected once, every front face shaded once.
 *
 * Formats (ranges as direct.h states them):
 *   geometry   the geometry stage's (view.c, the renderer's): the model
 *              transform (stp_direct_model_transform) composed with the
 *              view once a frame (stp_view_compose_small: composite axes
 *              rounded to stp_fix, the eye's terms exact; 32-bit
 *              arithmetic on 32-bit targets at 16 fractional bits), each
 *              vertex's view coordinates floor(C p - V (from - t)) by
 *              stp_view_small_point, exact: the renderer's values
 *              (with more than 16 fractional bits its two steps, as the
 *              renderer's).  Below 2^26 for the ranges of direct.h.
 *   projection the one perspective projection (view.c's
 *              stp_view_perspective, the renderer's): floor(trunc(focal x
 *              / z) 2^-12) in Q4 exactly (a reciprocal of z, or on AVR
 *              and in STP_SMALL_DIVISION builds restoring division; z in
 *              [hither, 2^26): the 32-bit form,
 *              project_private.h's stp_project_exact, alone on targets
 *              without STP_WIDE_ARITH: its 64-bit fallback could only
 *              give points beyond the device range)
 *   shading    shade_fast.c (its file comment): its prepare and its face
 *              path, the ones the mesh route uses (the 64-bit host path
 *              where prepare chooses it, as for the mesh route); the
 *              prepared light (stp_direct_lit) made per frame by
 *              stp_direct_frame_project or given to
 *              stp_direct_frame_project_lit. */
#include "stipple/direct.h"

#include "direct_private.h"
#include "shade_fast_private.h"
#include "view_private.h" /* stp_view_perspective */
#include "div64_private.h" /* STP_UDIV32 */
#include "render_private.h" /* the face stage: stp_render_face_side, stp_render_view_normal */
#include "sort_private.h"   /* the painter's sort, the renderer's */
#include "direct_clip_private.h" /* faces the picture's edge cuts */

#define F STP_FIX_FRAC_BITS
#define ONE STP_FIX_ONE
#define Q14 14
#define COORD_LIMIT ((int32_t)1 << 23)
#define DEVICE_LIMIT 8192

/* 1 when |v| < 2^23 (COORD_LIMIT): one unsigned comparison */
static int in_coord_range(int32_t v)
{
    return (uint32_t)v + (uint32_t)(COORD_LIMIT - 1) <= 2u * (uint32_t)(COORD_LIMIT - 1);
}

/* d = a - b; 0 when a component's difference is not below 2^23 in
 * magnitude, or wraps (the operands' signs differ and the difference's
 * differs from a's) */
static int difference(const stp_vec3 *a, const stp_vec3 *b, int32_t d[3])
{
    int j;
#if defined(__OPTIMIZE_SIZE__) && !STP_LEAN_CODE
    /* builds for size on 32-bit cores: the components from copies
     * (load-multiple on ARMv6-M), not a call each; elsewhere by index
     * (on 8-bit cores the copies cost the Uno image 116 B; unrolled at
     * -O2, where the index folds) */
    const int32_t av[3] = {a->x, a->y, a->z}, bv[3] = {b->x, b->y, b->z};
#endif
    STP_UNROLL3
    for (j = 0; j < 3; j++) {
#if defined(__OPTIMIZE_SIZE__) && !STP_LEAN_CODE
        uint32_t x = (uint32_t)av[j], y = (uint32_t)bv[j], v = x - y;
#else
        uint32_t x = (uint32_t)stp_vec3_comp(a, j), y = (uint32_t)stp_vec3_comp(b, j), v = x - y;
#endif
        if (((x ^ y) & (x ^ v) & 0x80000000u) != 0 || !in_coord_range((int32_t)v))
            return 0;
        d[j] = (int32_t)v;
    }
    return 1;
}

#if STP_DIRECT_COMPACT
/* ---- the compact form's geometry (config.h: STP_DIRECT_COMPACT) ----
 *   composite  C = V R in Q1.14 (view.c's stp_view_compose_q14: the
 *              view axes in Q1.14 times the model's rotation; the scale is
 *              1 in this form), |C| <= 1 + 2^-13
 *   vsum       floor(sum v_j m_j / 2^14) for |v_j| < 2^23 and int16_t
 *              m_j, exactly: sum floor(v_j / 2^14) m_j (16 x 16-bit
 *              products below 2^24) plus floor(sum (v_j mod 2^14) m_j /
 *              2^14) (products below 2^29, their sum below 1.5 2^30)
 *   view       floor(C v / 2^14) + floor(V (t - from) / 2^F): two vsum
 *              below 3 2^24 each: |.| < 2^26; the renderer's composed
 *              transform in these builds (view.c's compose_compact) */

/* floor(sum v_j m_j / 2^14) for |v_j| < 2^23 and int16_t m_j, exactly
 * (vsum above): below 3 2^24 */
STP_DIRECT_CALL int32_t dot3(const int32_t v[3], const int16_t m[3])
{
    int32_t high = 0, low = 0;
    int j;
    for (j = 0; j < 3; j++) {
        high += (int32_t)(int_fast16_t)stp_asr32(v[j], Q14) * m[j];
        low += (int32_t)(v[j] & 0x3FFF) * m[j];
    }
    return high + stp_asr32(low, Q14);
}

/* The view coordinates of world-space difference d (|d_i| < 2^23):
 * floor(V d / 2^F) by vsum, the renderer's exactly (the light's) */
static void to_view(const stp_direct_view *view, const int32_t d[3], int32_t out[3])
{
    int16_t a[3][3];
    int i;
    stp_view_axes_q14(view->axis, a);
    for (i = 0; i < 3; i++)
        out[i] = dot3(d, a[i]);
}
#else
/* The view coordinates of world-space difference d (|d_i| < 2^23) by
 * the geometry stage (view.c): floor(V . d / 2^F), V the view's axes: the
 * renderer's view coordinates of the point d + from, floor((V . (d +
 * from) - V . from) / 2^F). */
static void to_view(const stp_direct_view *view, const int32_t d[3], int32_t out[3])
{
    stp_view_small t;
    stp_vec3 p;
    stp_view_small_of_axes(view->axis, 0, 0, &t); /* the eye terms 0 */
    p.x = d[0];
    p.y = d[1];
    p.z = d[2];
    stp_view_small_point(&t, &p, &p);
    out[0] = p.x;
    out[1] = p.y;
    out[2] = p.z;
}

#endif

int stp_direct_light_prepare(stp_direct_lit *lit, const stp_direct_view *view, const stp_direct_light *l)
{
    stp_lighting lighting;
    stp_material material;
    stp_vec3 origin = {0, 0, 0};
    int32_t d[3], lv[3];
    if (!difference(&l->position, &view->from, d))
        return 0;
    to_view(view, d, lv);
    lighting.brightness = l->brightness;
    lighting.background = l->background;
    lighting.attenuation_c = l->attenuation_c;
    lighting.count = 1;
    lighting.lights[0].position.x = lv[0];
    lighting.lights[0].position.y = lv[1];
    lighting.lights[0].position.z = lv[2];
    lighting.lights[0].power = l->power;
    material.reflectivity = l->reflectivity;
    /* the fields the face shader's prepare reads (no colours: it shades
     * intensities); the highlight's only where it is compiled in */
#if STP_WITH_SPECULAR
    material.refraction = ONE / 2; /* below 1: no Fresnel table (no highlight) */
    material.gloss = ONE;
    material.specular = 0;
#endif
    stp_shade_fast_prepare_eye(&lit->fast, &lighting, &material, origin);
    return 1;
}

#if STP_DIRECT_COMPACT
int stp_direct_shading_prepare(stp_direct_shading *s, const stp_direct_lit *lit, const stp_direct_view *view,
                               const stp_direct_model *model)
{
    int16_t a[3][3];
    s->fast = &lit->fast;
    /* C = V R: the geometry stage's composite of the rotation alone */
    stp_view_axes_q14(view->axis, a);
    return stp_view_compose_q14(&a[0][0], &model->rot[0][0], s->rot); /* 0: rot no rotation */
}
#else
int stp_direct_shading_prepare(stp_direct_shading *s, const stp_direct_lit *lit, const stp_direct_view *view,
                               const stp_direct_model *model)
{
    stp_view_transform v; /* its axes: all of it the model frame reads */
    s->fast = &lit->fast;
    stp_direct_model_transform(model, &s->model); /* the geometry's too (geometry_prepare) */
    v.right = view->axis[0];
    v.up = view->axis[1];
    v.forward = view->axis[2];
    if (!stp_model_frame_make(&v, view->from, &s->model, &s->frame))
        return 0;
    /* every vertex a face is tested at is below 2^23 (place_vertex) */
    stp_render_side_estimate_make(&s->frame, (uint32_t)COORD_LIMIT - 1u, &s->side_estimate);
    return 1;
}
#endif

/* The light's values in their ranges (direct.h), each one unsigned
 * comparison: a negative value converts to 2^31 or more. */
static int light_ok(const stp_direct_light *l)
{
    return (uint32_t)l->power < 256u * (uint32_t)ONE && (uint32_t)l->brightness < 256u * (uint32_t)ONE &&
           (uint32_t)l->background <= (uint32_t)ONE && (uint32_t)l->reflectivity <= (uint32_t)ONE;
}

/* Device position (Q4) of view point p with p[2] >= hither > 0 by the one
 * perspective projection (view.c, the renderer's); 0 when it falls
 * outside the device range. */
static int project_point(const stp_direct_view *view, int focal_bits, stp_direct_point *pt)
{
    int32_t c[2];
    int i;
#if STP_WIDE_ARITH
    {
        int64_t w[2];
        stp_vec3 p;
        (void)focal_bits;
        p.x = pt->x;
        p.y = pt->y;
        p.z = pt->z;
        stp_view_perspective(view->focal, view->hither, p, &w[0], &w[1], 0);
        /* beyond 2^20 (Q4) an offset lands outside the device range */
        if (w[0] <= -((int64_t)1 << 20) || w[0] >= (int64_t)1 << 20 || w[1] <= -((int64_t)1 << 20) ||
            w[1] >= (int64_t)1 << 20)
            return 0;
        c[0] = (int32_t)w[0];
        c[1] = (int32_t)w[1];
    }
#else
    /* the projection's 32-bit form alone: it declines (z >= 2^29, a
     * quotient of 2^31 or more) only where the 64-bit one would land
     * beyond the device range (|offset| >= 2^(31 - F) pixels > 512) */
    if (!stp_project_exact_bits((uint32_t)view->focal, focal_bits, (uint32_t)view->hither, (uint32_t)pt->z, pt->x,
                                pt->y, &c[0], &c[1], 0))
        return 0;
#endif
    c[0] = (int32_t)view->width * 8 + c[0];
    c[1] = (int32_t)view->height * 8 - c[1];
    /* [-DEVICE_LIMIT, DEVICE_LIMIT): one unsigned comparison each */
    STP_UNROLL3
    for (i = 0; i < 2; i++)
        if ((uint32_t)c[i] + DEVICE_LIMIT >= 2u * DEVICE_LIMIT)
            return 0;
    pt->dx = (int16_t)c[0];
    pt->dy = (int16_t)c[1];
    return 1;
}

#if STP_DIRECT_COMPACT
/* A frame's geometry in the compact form: view = floor(C v / 2^14) + t
 * (C the shading's composite, t = floor(V (translate - from) / 2^F)) */
typedef struct stp_direct_geometry {
    const int16_t (*m)[3]; /* C's rows */
    int32_t t[3];
} stp_direct_geometry;

/* *g for model seen by view, d = translate - from (|d_i| < 2^23): its
 * composite the shading's C (view.c's stp_view_compose_q14 of the model's
 * rotation: the scale is 1 in this form, check_args; the renderer's
 * composite in these builds) and t = floor(V d / 2^F); 1 */
static int geometry_prepare(stp_direct_geometry *g, const stp_direct_view *view, const stp_direct_model *model,
                            const stp_direct_shading *shading, const int32_t d[3])
{
    int16_t a[3][3];
    int i;
    (void)model;
    stp_view_axes_q14(view->axis, a);
    for (i = 0; i < 3; i++)
        g->t[i] = dot3(d, a[i]); /* floor(V d / 2^F) */
    g->m = shading->rot; /* the scale is 1: Q = C (check_args) */
    return 1;
}

/* Vertex v of the mesh placed by g (view = M v + t) and projected into
 * *p; 0 when a coordinate is out of range (direct.h) or the point nearer
 * than hither or outside the device range. */
STP_DIRECT_CALL int place_vertex(const stp_direct_view *view, const stp_direct_geometry *g, const stp_vec3 *v,
                                 stp_direct_point *p)
{
    int32_t w[3], r[3];
    int i;
#if defined(__OPTIMIZE_SIZE__) && !STP_LEAN_CODE
    /* builds for size on 32-bit cores: a copy (load-multiple on ARMv6-M),
     * not a call a component (the size-first Cortex-M0+ frame 31 000
     * instructions shorter); elsewhere by index (on 8-bit cores the copy
     * cost the Uno image 14 B; unrolled at -O2, where the index folds) */
    w[0] = v->x;
    w[1] = v->y;
    w[2] = v->z;
#endif
    STP_UNROLL3
    for (i = 0; i < 3; i++) {
#if !(defined(__OPTIMIZE_SIZE__) && !STP_LEAN_CODE)
        w[i] = stp_vec3_comp(v, i);
#endif
        if (!in_coord_range(w[i]))
            return 0;
    }
    STP_UNROLL3
    for (i = 0; i < 3; i++)
        r[i] = dot3(w, g->m[i]) + g->t[i];
    p->x = r[0];
    p->y = r[1];
    p->z = r[2];
    return p->z >= view->hither && project_point(view, -1, p);
}
#else
/* A frame's geometry: the model's transform and the view's after it
 * (composed; with more than 16 fractional bits the view's alone: the
 * renderer's two steps) */
typedef struct stp_direct_geometry {
#if F > 16
    stp_transform model;
    stp_view_transform view;
#else
    stp_view_small view;
#endif
    int focal_bits; /* stp_bit_length32(focal): the projection's, once a frame */
} stp_direct_geometry;

/* *g for model seen by view, d = translate - from (|d_i| < 2^23): its
 * transform (shading->model, made once a frame by the shading's prepare)
 * composed with the view's (the geometry stage, as the renderer composes
 * them); 0 when a composite axis is out of range (a scale within about
 * 2^-12 of 2) */
static int geometry_prepare(stp_direct_geometry *g, const stp_direct_view *view, const stp_direct_model *model,
                            const stp_direct_shading *shading, const int32_t d[3])
{
    (void)model;
    g->focal_bits = stp_bit_length32((uint32_t)view->focal);
#if F > 16
    /* unit axes reach 2^17: the renderer's two steps (the model, then the
     * view), as its geometry stage takes them */
    (void)d;
    g->model = shading->model;
    stp_view_transform_of_axes(view->axis[0], view->axis[1], view->axis[2], view->from, &g->view);
    return 1;
#else
    {
        int32_t e[3]; /* from - translate */
        e[0] = -d[0];
        e[1] = -d[1];
        e[2] = -d[2];
        return stp_view_compose_small(view->axis, e, &shading->model, &g->view);
    }
#endif
}

/* Vertex v of the mesh in view coordinates by the frame's geometry g (the
 * geometry stage's, the renderer's values; with more than 16 fractional
 * bits its two steps) and projected into *p; 0 when a coordinate is out
 * of range (direct.h).  A point nearer than hither or outside the device
 * range is not projected (STP_DIRECT_UNPROJECTED): the faces it is a
 * corner of are clipped (mark_clipped), and their clipped vertices
 * projected (direct_clip.c). */
STP_DIRECT_CALL int place_vertex(const stp_direct_view *view, const stp_direct_geometry *g, const stp_vec3 *v,
                                 stp_direct_point *p)
{
    stp_vec3 r;
    if (!in_coord_range(v->x) || !in_coord_range(v->y) || !in_coord_range(v->z))
        return 0;
#if F > 16
    if (stp_view_point_two_steps(&g->model, &g->view, *v, &r))
        return 0; /* the model point saturated */
#else
    stp_view_small_point(&g->view, v, &r);
#endif
    p->x = r.x;
    p->y = r.y;
    p->z = r.z;
    if (p->z < view->hither || !project_point(view, g->focal_bits, p))
        p->dx = p->dy = STP_DIRECT_UNPROJECTED;
    return 1;
}
#endif

#if STP_DIRECT_COMPACT
/* Component i (0: x, 1: y, 2: z) of p's view position: third's one
 * body serves the three components (with STP_LEAN_CODE one call, a third
 * of the code of three inlined copies; elsewhere folded per component) */
STP_INDEX_INLINE int32_t view_comp(const stp_direct_point *p, int i)
{
    return i == 0 ? p->x : (i == 1 ? p->y : p->z);
}

/* Component i of the centre of p's three points: their view coordinates'
 * sum s (each below 2^26) over 3 as floor(s / 2^16) 21846 + (s mod 2^16)
 * 21846 / 2^16: relative error below 2^-15 (21846 / 2^16 for 1/3), enough
 * for the point a face is shaded at. */
STP_DIRECT_CALL int32_t third(const stp_direct_point *const p[3], int i)
{
    /* each below 2^26: the sum below 2^28, the renderer's third
     * (render_private.h) */
    return stp_render_third(view_comp(p[0], i) + view_comp(p[1], i) + view_comp(p[2], i));
}

stp_fix stp_direct_face_shade(const stp_direct_shading *s, const int16_t *normal,
                              const stp_direct_point *const p[3])
{
    int16_t nv[3];
    stp_vec3 centre;
    int i;
    for (i = 0; i < 3; i++)
        nv[i] = (int16_t)stp_view_dot_q14(s->rot[i], normal); /* unit: within Q1.14 */
    centre.x = third(p, 0);
    centre.y = third(p, 1);
    centre.z = third(p, 2);
    /* view coordinates below 2^26 (direct.h), perspective, no highlight */
    return stp_shade_fast_face_near(s->fast, nv, centre); /* [0, 1] */
}

/* Whether the face of normal with triangle tri is a front face: by the
 * winding of its projected vertices p (render_private.h's winding side,
 * which the renderer takes in these builds): twice its signed area, y
 * down, differences below 2^14, negative for a front face (it turns
 * counter-clockwise seen from the eye) */
STP_HOT_INLINE int front_face(const stp_direct_shading *s, const int16_t *normal, const stp_vec3 *v0,
                              const stp_direct_point *const p[3])
{
    int ax = p[1]->dx - p[0]->dx, ay = p[1]->dy - p[0]->dy;
    int bx = p[2]->dx - p[0]->dx, by = p[2]->dy - p[0]->dy;
    (void)s;
    (void)normal;
    (void)v0;
    return stp_render_twice_area(ax, ay, bx, by) < 0;
}
#else
stp_fix stp_direct_face_shade(const stp_direct_shading *s, const int16_t *normal,
                              const stp_direct_point *const p[3])
{
    int16_t nv[3];
    stp_vec3 centre;
    /* the mesh route's face stage (mesh.c's enter_face): the normal turned
     * by the model frame, the vertices' average (view coordinates below
     * 2^26: the small form) */
    stp_render_view_normal(&s->frame, normal, 1, nv);
    centre.x = stp_render_average3(1, p[0]->x, p[1]->x, p[2]->x);
    centre.y = stp_render_average3(1, p[0]->y, p[1]->y, p[2]->y);
    centre.z = stp_render_average3(1, p[0]->z, p[1]->z, p[2]->z);
    /* view coordinates below 2^26 (direct.h), perspective, no highlight */
    return stp_shade_fast_face_near(s->fast, nv, centre); /* [0, 1] */
}

/* Whether the face of normal through model point v0 is a front face: the
 * face stage's side (stp_render_face_side: the exact sign of N.(eye - v0)
 * in model coordinates; in 32 bits for direct drawing's ranges), as the
 * mesh route removes back faces; where 64-bit products are library calls
 * from the mesh route's 32-bit estimate where its sign is sure (all but
 * faces near edge-on) */
#if !STP_WIDE_ARITH
/* the exact side for the estimate's unsure faces: rare, out of line */
STP_NOINLINE int exact_front(const stp_direct_shading *s, const int16_t *normal, const stp_vec3 *v0)
{
    return stp_render_face_side_near(&s->frame, normal, v0) > 0;
}
#endif

STP_HOT_INLINE int front_face(const stp_direct_shading *s, const int16_t *normal, const stp_vec3 *v0,
                              const stp_direct_point *const p[3])
{
    (void)p;
#if !STP_WIDE_ARITH
    {
        int32_t estimate = stp_render_side_estimate(&s->side_estimate, normal, v0);
        if (stp_render_side_sure(estimate))
            return estimate > 0;
        return exact_front(s, normal, v0);
    }
#else
    return stp_render_face_side_near(&s->frame, normal, v0) > 0;
#endif
}
#endif

/* faces[k] of triangle tri with normal: 0 for a back or edge-on face
 * (front_face), else 256 +
 * the intensity byte of the front face: the shade, INTENSITY, the linear
 * drive value floor((k 255 + d / 2) / d) of index k + 1, d = levels - 1
 * (output.c's stp_output_level), as (n m) >> 24 with m = ceil(2^24 / d)
 * (drive_m, once per frame): n = k 255 + d / 2 <= 255.5 d, so n m <
 * 255.5 2^24 + n < 2^32, and the excess n (m d - 2^24) / (d 2^24) stays
 * below 1 / d (n (m d - 2^24) < 255.5 d^2 <= 255.5 254^2 < 2^24): the
 * quotient exactly, without a division per face. */
STP_DIRECT_CALL uint16_t face_intensity(const stp_direct_shading *s, const int16_t *normal, const stp_mesh *mesh,
                                        const stp_direct_point *points, const uint16_t *tri, unsigned levels,
                                        uint32_t drive_m)
{
    const stp_direct_point *p[3];
    stp_fix shade;
    unsigned d = levels - 1u;
    uint32_t index;
    p[0] = &points[tri[0]];
    p[1] = &points[tri[1]];
    p[2] = &points[tri[2]];
    if (!front_face(s, normal, &mesh->vertices[tri[0]], p))
        return 0; /* a back face */
    shade = stp_direct_face_shade(s, normal, p);
    index = ((uint32_t)shade * d) >> F; /* index - 1, at most d */
    return (uint16_t)(256u + (((index * 255u + d / 2u) * drive_m) >> 24));
}

#if !STP_DIRECT_COMPACT
/* Whether device point p lies within a pixel of the picture's edge or
 * beyond it, or is not projected (STP_DIRECT_UNPROJECTED, below -16):
 * x outside [16, 16 width - 16] in Q4 or y outside [16, 16 height - 16],
 * one unsigned comparison a coordinate with xs = 16 width - 32 and ys =
 * 16 height - 32 (width, height >= 2).  A vertex a pixel inside is
 * inside every plane of the renderer's clipper: not nearer than hither
 * (it is projected), and inside each side plane, whose outcode's floors
 * (clip.c) take less than 1.5 raw units off a distance of z (1 - 1/16)
 * (the projection's floor is below 1/16 pixel), positive for z >= 2 raw,
 * and z >= hither; mark_clipped takes the exact test for every face
 * where hither is below 16 raw or the picture narrower than 2. */
STP_HOT_INLINE int near_edge(const stp_direct_point *p, uint32_t xs, uint32_t ys)
{
    return (uint32_t)((int32_t)p->dx - 16) > xs || (uint32_t)((int32_t)p->dy - 16) > ys;
}

/* Whether some point of f's points[0 .. count-1] is near_edge: once a
 * frame */
STP_NOINLINE int some_near_edge(const stp_direct_frame *f, const stp_direct_point *points, uint16_t count)
{
    const uint32_t xs = (uint32_t)f->width * 16u - 32u, ys = (uint32_t)f->height * 16u - 32u;
    uint16_t k;
    for (k = 0; k < count; k++)
        if (near_edge(&points[k], xs, ys))
            return 1;
    return 0;
}

/* The front faces among faces[] the renderer would clip, by the outcodes
 * (clip.c) of their vertices' view coordinates: STP_DIRECT_FACE_CLIPPED
 * added where some vertex is outside a plane (a side, or nearer than
 * hither), the face not drawn where all three are outside one (the
 * renderer drops it); their count.  The exact test only for faces with a
 * vertex near the picture's edge or unprojected (near_edge), none in a
 * frame that has no such vertex. */
STP_NOINLINE uint16_t mark_clipped(const stp_direct_frame *f, uint16_t *faces)
{
    const stp_mesh *mesh = f->mesh;
    const uint16_t *tri = mesh->triangles;
    const uint32_t xs = (uint32_t)f->width * 16u - 32u, ys = (uint32_t)f->height * 16u - 32u;
    const int every = f->hither < 16 || f->width < 2 || f->height < 2; /* every face's outcodes */
    stp_clip_volume volume;
    uint16_t t, clipped = 0;
    if (!every && !some_near_edge(f, f->points, mesh->vertex_count))
        return 0;
    stp_direct_clip_volume(f, &volume);
    for (t = 0; t < mesh->triangle_count; t++, tri += 3) {
        unsigned all = 31u, any = 0, code;
        int i;
        if (faces[t] == 0 || (!every && !near_edge(&f->points[tri[0]], xs, ys) &&
                              !near_edge(&f->points[tri[1]], xs, ys) && !near_edge(&f->points[tri[2]], xs, ys)))
            continue;
        for (i = 0; i < 3; i++) {
            const stp_direct_point *p = &f->points[tri[i]];
            stp_vec3 v;
            v.x = p->x;
            v.y = p->y;
            v.z = p->z;
            code = stp_clip_outcode(&volume, v);
            all &= code;
            any |= code;
        }
        if (all != 0) {
            faces[t] = 0;
        } else if (any != 0) {
            faces[t] = (uint16_t)(faces[t] | STP_DIRECT_FACE_CLIPPED);
            clipped++;
        }
    }
    return clipped;
}
#endif

/* Every corner of the mesh's triangles indexes one of its vertices;
 * apart from check_args, whose other checks are of single values. */
static int corners_in_mesh(const stp_mesh *mesh)
{
    const uint16_t *c = mesh->triangles;
    uint16_t t, n = mesh->vertex_count;
    for (t = mesh->triangle_count; t != 0; t--, c += 3)
        if (c[0] >= n || c[1] >= n || c[2] >= n)
            return 0;
    return 1;
}

/* Whether scale is one direct drawing draws (direct.h): in (0, 2); in the
 * compact form 1 alone (its composite is the rotation's, its normal
 * rotation the renderer's: config.h's STP_DIRECT_COMPACT) */
static int scale_ok(stp_fix scale)
{
#if STP_DIRECT_COMPACT
    return scale == ONE;
#else
    return (uint32_t)scale - 1u < 2u * (uint32_t)ONE - 1u;
#endif
}

/* The arguments but the light (checked by stp_direct_frame_project) */
static int check_args(const stp_direct_frame *f, const stp_mesh *mesh, const stp_direct_model *model,
                      const stp_direct_view *view, const stp_direct_lit *lit, int levels, const uint8_t *cell,
                      const stp_direct_point *points, size_t point_count, const uint16_t *faces, size_t face_count)
{
    if (f == 0 || mesh == 0 || model == 0 || view == 0 || lit == 0 || cell == 0 || points == 0 ||
        faces == 0 || mesh->vertices == 0 || mesh->triangles == 0 || mesh->normals == 0 ||
        point_count < mesh->vertex_count || face_count < mesh->triangle_count || levels < 2 ||
        levels > 255 || !scale_ok(model->scale) || !corners_in_mesh(mesh))
        return STP_ERR_ARG;
    return STP_OK;
}

int stp_direct_frame_project(stp_direct_frame *f, const stp_mesh *mesh, const stp_direct_model *model,
                             const stp_direct_view *view, const stp_direct_light *light, int levels,
                             const uint8_t cell[16], stp_direct_point *points, size_t point_count,
                             uint16_t *faces, size_t face_count)
{
    stp_direct_lit lit;
    /* the light's own checks here, the others in stp_direct_frame_project_lit */
    if (view == 0 || light == 0 || !light_ok(light))
        return STP_ERR_ARG;
    if (!stp_direct_light_prepare(&lit, view, light))
        return STP_ERR_RANGE;
    return stp_direct_frame_project_lit(f, mesh, model, view, &lit, levels, cell, points, point_count, faces,
                                        face_count);
}

int stp_direct_frame_project_lit(stp_direct_frame *f, const stp_mesh *mesh, const stp_direct_model *model,
                                 const stp_direct_view *view, const stp_direct_lit *lit, int levels,
                                 const uint8_t cell[16], stp_direct_point *points, size_t point_count,
                                 uint16_t *faces, size_t face_count)
{
    int32_t d[3];
    uint32_t drive_m;
    stp_direct_shading shading;
    stp_direct_geometry g;
    const uint16_t *tri;
    const int16_t *normal;
    int status;
    uint16_t k;
    status = check_args(f, mesh, model, view, lit, levels, cell, points, point_count, faces, face_count);
    if (status != STP_OK)
        return status;
    f->layout = STP_BAND_ROWS;
    /* ceil(2^24 / (levels - 1)), face_intensity's reciprocal */
    drive_m = STP_UDIV32(((uint32_t)1 << 24) + (uint32_t)levels - 2u, (uint32_t)levels - 1u);
    if (!difference(&model->translate, &view->from, d))
        return STP_ERR_RANGE;
    if (!stp_direct_shading_prepare(&shading, lit, view, model))
        return STP_ERR_ARG; /* rot not a rotation, or the scale below 2^-6 (direct.h) */
    if (!geometry_prepare(&g, view, model, &shading, d))
        return STP_ERR_RANGE;
    for (k = 0; k < mesh->vertex_count; k++)
        if (!place_vertex(view, &g, &mesh->vertices[k], &points[k]))
            return STP_ERR_RANGE;
    tri = mesh->triangles;
    normal = mesh->normals;
    for (k = 0; k < mesh->triangle_count; k++, tri += 3, normal += 3)
        faces[k] = face_intensity(&shading, normal, mesh, points, tri, (unsigned)levels, drive_m);
    f->mesh = mesh;
    f->points = points;
    f->faces = faces;
    f->cell = cell;
    f->width = view->width;
    f->height = view->height;
#if !STP_DIRECT_COMPACT /* the compact form has no sort or clipping: its bands read none of these */
    f->hither = view->hither;
    f->focal = view->focal;
    f->order = 0; /* mesh order until stp_direct_frame_sort */
    f->order_count = 0;
    f->depth = 0; /* no depth test until stp_direct_frame_depth */
    f->clipped = mark_clipped(f, faces);
#endif
    return STP_OK;
}

#if !STP_DIRECT_COMPACT
/* The painter's key of face k the picture's edge or the near plane cuts
 * (STP_DIRECT_FACE_CLIPPED): the renderer keys what it stores, the
 * clipped polygon, by its farthest vertex; 0 when nothing is left of it
 * (stored by neither).  Rare: out of line. */
STP_NOINLINE int clipped_key(const stp_direct_frame *f, const uint16_t *k, int32_t *key)
{
    stp_instr v[STP_DIRECT_CLIP_MAX];
    int m = stp_direct_face_clip(f, k, v), i;
    if (m < 3)
        return 0;
    *key = v[0].z;
    for (i = 1; i < m; i++)
        *key = v[i].z < *key ? v[i].z : *key;
    return 1;
}
#endif

int stp_direct_frame_sort(stp_direct_frame *f, stp_sort_entry *order, size_t order_count)
{
#if STP_DIRECT_COMPACT
    (void)order;
    (void)order_count;
    if (f == 0)
        return STP_ERR_ARG;
    return STP_ERR_UNSUPPORTED; /* the smallest images keep mesh order (direct.h) */
#else
    const uint16_t *k;
    size_t n = 0;
    uint16_t t;
    if (f == 0 || order == 0 || f->mesh == 0 || f->mesh->triangles == 0 || f->points == 0 || f->faces == 0)
        return STP_ERR_ARG;
    f->order = 0;
    f->order_count = 0;
    f->depth = 0; /* far to near, not depth-tested */
    k = f->mesh->triangles;
    for (t = 0; t < f->mesh->triangle_count; t++, k += 3) {
        int32_t z0 = f->points[k[0]].z, z1 = f->points[k[1]].z, z2 = f->points[k[2]].z, far;
        if (f->faces[t] == 0)
            continue; /* not drawn */
        if (n == order_count) {
            /* full: refused unless nothing is left of the face */
            int32_t key;
            if ((f->faces[t] & STP_DIRECT_FACE_CLIPPED) && !clipped_key(f, k, &key))
                continue;
            return STP_ERR_FULL;
        }
        /* the farthest vertex's key: the key falls as z grows (a drawn
         * face has a vertex in [hither, 2^26)) */
        far = z0 > z1 ? z0 : z1;
        far = far > z2 ? far : z2;
        order[n].key = stp_project_depth_key((uint32_t)f->hither, (uint32_t)far);
        if ((f->faces[t] & STP_DIRECT_FACE_CLIPPED) && !clipped_key(f, k, &order[n].key))
            continue; /* nothing left to draw: no entry */
        order[n].index = t;
        order[n].style = f->faces[t];
        order[n].transmission = 0;
        n++;
    }
    stp_sort_far_to_near(order, n);
    f->order = order;
    f->order_count = (uint16_t)n;
    return STP_OK;
#endif
}
