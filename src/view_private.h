/* SPDX-License-Identifier: MIT */
/* Private: the view frame shared by the polygon renderer and the ray
 * tracer, and the cross product the core's files share. */
#ifndef STIPPLE_VIEW_PRIVATE_H
#define STIPPLE_VIEW_PRIVATE_H

#include "stipple/render.h"
#include "stipple/transform.h"
#include "fix_private.h"   /* stp_fix_sat64 */
#include "arith_private.h" /* STP_WIDE_ARITH, STP_HOT_INLINE */

/* A view turned into what both renderers use: an orthonormal left-handed
 * basis (unit stp_vec3: x right, y up, z forward along the line of sight),
 * the centre of projection and the focal length: perspective, pixels per
 * unit of x/z; parallel, pixels per world unit (F fractional bits). */
typedef struct stp_view_frame {
    stp_vec3 from, right, up, forward;
    stp_fix focal, hither;
    stp_projection projection;
} stp_view_frame;

/* The frame of view v on a width x height device.  Returns STP_OK,
 * STP_ERR_VIEW (from == at, up along the line of sight, fov outside
 * (0, 180), hither or window_half <= 0) or STP_ERR_ARG (a bad projection);
 * *out is written only on success. */
int stp_view_frame_make(const stp_view *v, uint32_t width, uint32_t height, stp_view_frame *out);

/* One view axis in halves for 32-bit targets (view.c): each component
 * a[i] = high[i] 2^15 + low[i] (low in [-2^14, 2^14), high in [-4, 4]
 * for |a[i]| < 2^17), and from . axis (2F fractional bits, below 2^49) =
 * from_high 2^16 + from_low (low in [0, 2^16)), from_high32 the high part
 * where it is below 2^28 in magnitude, else 0.  16-bit halves where a
 * 32-bit product is a library call (AVR: RAM is short; the renderer holds
 * two transforms); 32-bit ones elsewhere (ARMv6-M loads a signed 16-bit
 * value only with a register offset). */
#if STP_HAVE_MUL32
typedef int32_t stp_view_half;
#else
typedef int16_t stp_view_half;
#endif
typedef struct stp_view_axis32 {
    stp_view_half high[3], low[3];
    int32_t from_high32, from_low;
} stp_view_axis32;

/* World to view coordinates: the view's axes and the eye's coordinate
 * along each (from . axis, 2F fractional bits, below 2^49), so a point's
 * view coordinates are p . axis - from . axis, exact in 64 bits. */
typedef struct stp_view_transform {
    stp_vec3 right, up, forward;
    int unit;   /* narrow, and every axis's squared length at most 5 2^30
                   (1.25 units squared): view.c's short form (with
                   STP_NARROW_FORMS, else 0) */
#if STP_NARROW_FORMS
    /* view.c's short form of axis k (right, up, forward): from_high32 +
     * 2^15, and from . axis mod 2^32; here, next to the axes, where every
     * field the short form reads is within ARMv6-M's load offsets */
    int32_t unit_high[3];
    uint32_t unit_low[3];
#endif
    int narrow; /* every from_high below 2^28 in magnitude */
    int64_t from_right, from_up, from_forward;
    /* the 32-bit targets' form (view.c) of each axis k (right, up, forward) */
    stp_view_axis32 axis32[3];
} stp_view_transform;

/* The view's axes (view_frame_make's and direct drawing's, the one place
 * they are formed) for line of sight *line (at - from): axes[2]
 * (forward) the unit vector along it, axes[0] (right) = forward x up and
 * axes[1] (up) = right x forward normalised (unit stp_vec3, F fractional
 * bits; with STP_DIRECT_COMPACT rounded to Q1.14, config.h).  Returns
 * STP_OK, or STP_ERR_VIEW (the line or up zero, or up along the line of
 * sight); the axes are written only on success. */
int stp_view_axes(const stp_vec3 *line, const stp_vec3 *up, stp_vec3 axes[3]);

void stp_view_transform_make(const stp_view_frame *vf, stp_view_transform *out);
/* The transform of axes right, up, forward (unit: |component| < 2^17) and
 * eye from, as stp_view_transform_make forms it from a frame. */
void stp_view_transform_of_axes(stp_vec3 right, stp_vec3 up, stp_vec3 forward, stp_vec3 from,
                                stp_view_transform *out);

/* p (world) in view coordinates, each floor((p - from) . axis), saturated;
 * _at: the same of *p (out not p), which leaves p in memory rather than
 * copying it (ARMv6-M: fewer values live in the 32-bit form). */
void stp_view_transform_point(const stp_view_transform *t, stp_vec3 p, stp_vec3 *out);
void stp_view_transform_point_at(const stp_view_transform *t, const stp_vec3 *p, stp_vec3 *out);

#if STP_WIDE_ARITH
/* stp_view_transform_point where 64-bit products are single instructions,
 * inline for the entry's per-vertex use (view.c's function is this).
 * stp_view_floor_shift_sat: floor(v / 2^F), saturated, for |v| < 2^62:
 * stp_asr64 (one arithmetic shift on these hosts; an offset to make v
 * non-negative first cost four instructions more a coordinate). */
STP_HOT_INLINE stp_fix stp_view_floor_shift_sat(int64_t v, int bounded)
{
    int64_t s = stp_asr64(v, STP_FIX_FRAC_BITS);
    /* stp_fix_sat64 with one unsigned test for the common case; none where
     * the caller knows s inside stp_fix's range (bounded) */
    if (!bounded &&
        STP_UNLIKELY((uint64_t)s - (uint64_t)STP_FIX_MIN > (uint64_t)STP_FIX_MAX - (uint64_t)STP_FIX_MIN))
        return s > 0 ? STP_FIX_MAX : STP_FIX_MIN;
    return (stp_fix)s;
}

/* bounded (a constant): the caller knows every view coordinate of p
 * strictly inside stp_fix's range (mesh.c's box_inside: below 2^29), so
 * saturation cannot occur and is not tested: the same values */
STP_HOT_INLINE void stp_view_transform_point_wide_in(const stp_view_transform *t, stp_vec3 p, stp_vec3 *out,
                                                    int bounded)
{
    /* (p - from) . axis = p . axis - from . axis, exactly in 64 bits: each
     * product < 2^47, so the sums stay below 2^50; p - from itself may
     * exceed stp_fix's range */
    out->x = stp_view_floor_shift_sat((int64_t)p.x * t->right.x + (int64_t)p.y * t->right.y +
                                      (int64_t)p.z * t->right.z - t->from_right, bounded);
    out->y = stp_view_floor_shift_sat((int64_t)p.x * t->up.x + (int64_t)p.y * t->up.y +
                                      (int64_t)p.z * t->up.z - t->from_up, bounded);
    out->z = stp_view_floor_shift_sat((int64_t)p.x * t->forward.x + (int64_t)p.y * t->forward.y +
                                      (int64_t)p.z * t->forward.z - t->from_forward, bounded);
}

STP_HOT_INLINE void stp_view_transform_point_wide(const stp_view_transform *t, stp_vec3 p, stp_vec3 *out)
{
    stp_view_transform_point_wide_in(t, p, out, 0);
}
#define STP_VIEW_TRANSFORM_POINT stp_view_transform_point_wide
#else
#define STP_VIEW_TRANSFORM_POINT stp_view_transform_point
#endif

/* ---- the geometry stage: model coordinates to view coordinates ----
 *
 * A model transform m (stp_transform: p -> M p + t) that is a rotation
 * times a uniform scale (stp_view_similar) is composed with the view
 * transform into one stp_view_transform (stp_view_transform_compose), so
 * a model point costs one stp_view_transform_point: the composite axes
 * C_i = V_i M (V_i the view axis, F bits; each sum of three products below
 * 3 2^41) rounded once to F fractional bits and required below 2^17 in
 * magnitude (the axis range stp_view_transform_point takes: a scale below
 * about 2), and the eye's terms V_i . (from - t) exact (2F fractional
 * bits: from . V_i below 2^49 less t . V_i below 3 2^48).  Each view
 * coordinate is then floor(C_i . p - V_i . (from - t)), within a few raw
 * units of the two steps' floor(V_i . (round(M p) + t - from)).  A model
 * point whose M p + t leaves stp_fix's range but whose view coordinates do
 * not is drawn, where the two steps saturated it (STP_ERR_RANGE).  Any
 * other model transform takes the two steps (stp_transform_point, then
 * stp_view_transform_point); the identity (no model transform) takes the
 * view transform alone. */

/* Whether a coordinate of view or world point p is saturated
 * (stp_view_transform_point and stp_transform_point clamp to
 * [STP_FIX_MIN, STP_FIX_MAX]): the point lies beyond what the coordinates
 * hold, and drawing it would move it. */
static inline int stp_view_saturated(stp_vec3 p)
{
    return p.x >= STP_FIX_MAX || p.x <= STP_FIX_MIN || p.y >= STP_FIX_MAX || p.y <= STP_FIX_MIN ||
           p.z >= STP_FIX_MAX || p.z <= STP_FIX_MIN;
}

/* The two steps for model point p: model (stp_transform_point), then the
 * view transform to_view, into *out; returns 1 when the model transform
 * saturated p (stp_view_saturated), else 0. */
int stp_view_point_two_steps(const stp_transform *model, const stp_view_transform *to_view, stp_vec3 p,
                             stp_vec3 *out);

/* The face stage's model frame (render.c's stp_render_model_frame, direct
 * drawing's frame): what lets a face be tested and shaded from its Q1.14
 * model normal (a mesh's prepared one, or stp_render_model_normal of an
 * entered polygon) without forming a normal from its view coordinates.
 * usable: the model transform (identity when off) a rotation times a
 * uniform scale of at least 2^-6 and below 256 with a positive
 * determinant (stp_view_similar), and the eye in model coordinates below
 * 2^30 in each coordinate. */
typedef struct stp_model_frame {
    int32_t rot[3][3]; /* model normal to view normal: the view rotation
                          times the model's, normalised rows, Q15 */
    int32_t eye[3];    /* the eye in model coordinates (stp_fix, |.| < 2^30) */
    int64_t scale2;    /* the model's scale squared, 2F fractional bits */
    int usable;
} stp_model_frame;

/* The face side's 32-bit estimate's values (render_private.h's
 * stp_render_side_estimate): the model frame's eye floor-shifted right by
 * shift */
typedef struct stp_side_estimate {
    int32_t eye[3];
    int shift;
} stp_side_estimate;

/* STP_COMPACT_COMPOSE: the compact form's composition (config.h:
 * STP_DIRECT_COMPACT), where its Q1.14 matrix is one in the renderer's
 * units (at least 14 fractional bits) */
#define STP_COMPACT_COMPOSE (STP_DIRECT_COMPACT && STP_FIX_FRAC_BITS >= 14)

#if STP_DIRECT_COMPACT
/* The view's axes in Q1.14 rows, floor(a 2^(14 - F)): exact for the
 * compact look-at's axes (multiples of 2^(F - 14): stp_view_axes).  The
 * compact form's one conversion (direct drawing's, compose_compact's). */
void stp_view_axes_q14(const stp_vec3 axes[3], int16_t out[3][3]);

/* round(sum_k a_k b_k / 2^14) for Q1.14 a and b (products below 2^30 in
 * magnitude, their sum below 2^31): the compact form's one dot product
 * (its composite, its normals' turn). */
int32_t stp_view_dot_q14(const int16_t a[3], const int16_t b[3]);

/* The compact form's composite Q = A M (Q1.14, int16_t) of Q1.14
 * matrices a and m (9 entries each, row-major; a's rows at most 1 in
 * length, m's entries below 2 in magnitude): Q_ij = round(sum_k a_ik m_kj
 * / 2^14) (stp_view_dot_q14).  Returns 1, or 0 when an entry falls outside
 * [-32767, 32767] (q then holds it wrapped).  Direct drawing's compact
 * geometry and normal rotation (a the view's axes, the compact look-at's,
 * exact in Q1.14: stp_view_axes; m the model's rotation) and the
 * renderer's composition and model frame in those builds
 * (stp_view_transform_compose, stp_model_frame_make). */
int stp_view_compose_q14(const int16_t *a, const int16_t *m, int16_t q[3][3]);
#endif

/* Whether model (NULL: the identity) is a rotation times a uniform scale:
 * columns of equal squared length and pairwise orthogonal, each within
 * 1/1024 of the squared length (the rounding of composed stp_fix
 * rotations), a positive determinant (a reflection turns the winding), a
 * scale of at least 2^-6 (enough bits for the normals) and below 256. */
int stp_view_similar(const stp_transform *model);

/* *out = the view transform t after model (a similarity, stp_view_similar)
 * as one transform (see above).  Returns 1, or 0 (out unset) when model is
 * not a similarity or a composite axis component reaches 2^17 in
 * magnitude: then the two steps apply.  out must not be t.  With
 * STP_COMPACT_COMPOSE the composite is the compact form's where it applies
 * (view.c's compose_compact). */
int stp_view_transform_compose(const stp_view_transform *t, const stp_transform *model,
                               stp_view_transform *out);

/* The geometry stage's transform for points near the eye (direct
 * drawing's, once a frame): view coordinate i of a point p is
 *   floor((axis[i] . p - from_i) / 2^F),  from_i = high[i] 2^F + low[i],
 * the value stp_view_transform_point gives for the same axes and eye
 * terms, exactly.  Ranges: |axis components| < 2^17 (at F = 16), |p_i| <
 * 2^23, |high| < 2^26, low in [0, 2^F): view coordinates below 2^26.
 * Where 64-bit products are library calls and F = 16, in 32 bits
 * (view.c: a 16 x 16-bit estimate and the products' sum mod 2^32), else
 * in 64. */
typedef struct stp_view_small {
    stp_vec3 axis[3];        /* rows: right, up, forward */
    int16_t axis_high[3][3]; /* floor(axis / 2^5): the 32-bit form's estimate */
    int32_t high[3];
    uint32_t low[3];
    /* the 32-bit form's eye terms: high + 2^15, and (high 2^16 + low) mod 2^32 */
    int32_t high_biased[3];
    uint32_t from_mod[3];
} stp_view_small;

/* *out = axes (each component below 2^17 in magnitude, F = 16) with
 * every eye term high 2^F + low */
void stp_view_small_of_axes(const stp_vec3 axes[3], int32_t high, uint32_t low, stp_view_small *out);

/* p's view coordinates by t (the ranges above); out may be p. */
void stp_view_small_point(const stp_view_small *t, const stp_vec3 *p, stp_vec3 *out);

/* *out = view axes axes[0..2] (unit vectors) after model's matrix m
 * (|m| < 2^17; its translation is not read) with d = from - t, the eye's
 * offset from the model's translation (|d_i| < 2^23): composite axes
 * C_i = V_i M rounded to F fractional bits, eye terms V_i . d exact, as
 * stp_view_transform_compose forms them, so every point's view
 * coordinates are the renderer's for the same view and model (a
 * similarity).  Returns 1, or 0 (out partly written) when a composite
 * component reaches 2^17 in magnitude (there the renderer takes its two
 * steps). */
int stp_view_compose_small(const stp_vec3 axes[3], const int32_t d[3], const stp_transform *model,
                           stp_view_small *out);

/* The model frame of view transform t (only its axes right, up and
 * forward are read), eye from (world) and model (NULL: the identity);
 * returns f->usable (1, or 0 when model is no similarity or the eye in
 * model coordinates is not below 2^30). */
int stp_model_frame_make(const stp_view_transform *t, stp_vec3 from, const stp_transform *model,
                         stp_model_frame *f);

/* Which side of triangle v (world coordinates) an eye at from (perspective)
 * or looking along forward (parallel: unit, F fractional bits) sees, by the
 * exact sign of ((v1 - v0) x (v2 - v0)).(from - v0), or of -N.forward:
 * 1 the front (counter-clockwise seen from the eye in the left-handed view
 * system), -1 the back or edge-on, 0 not decided: a zero normal, or
 * coordinates too far apart to decide in 64 bits or to be sure that none of
 * the vertices' view coordinates saturates (differences from one another
 * and from `from` of 2^29 raw units or more; see view.c). */
int stp_view_triangle_side(stp_vec3 from, stp_vec3 forward, int parallel, const stp_vec3 *v);

/* The projection of view point *p, its z raised to hither when nearer:
 *   *x = floor(trunc(focal p.x / z) / 2^(F - STP_SUBPIXEL_BITS)), *y the
 *   same of p.y: the device offsets from the picture's centre in Q27.4,
 *   y up; *key = trunc(hither 2^30 / z), the depth key (key NULL: not
 *   formed).
 * focal > 0, hither > 0 (stp_fix); |*x|, |*y| < 2^(63 - F).  By 64-bit
 * quotients (one reciprocal of z on targets without STP_WIDE_ARITH). */
void stp_view_perspective_wide(stp_fix focal, stp_fix hither, const stp_vec3 *p, int64_t *x, int64_t *y,
                               int32_t *key);

/* stp_project_device_wide (project_private.h) out of line, where 64-bit
 * division is a library call: the 32-bit form's fallback. */
struct stp_view_lens;
void stp_view_perspective_device_wide(const struct stp_view_lens *lens, const stp_vec3 *p, int32_t out[3]);

/* The one perspective projection: project_private.h. */
#include "project_private.h"

/* a x b with F fractional bits, each component saturated. */
stp_vec3 stp_vec3_cross(stp_vec3 a, stp_vec3 b);

#endif
