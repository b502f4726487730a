/* SPDX-License-Identifier: MIT */
/* Private: polygon entry's functions (render.c) for mesh entry (mesh.c),
 * and the face stage both share.  The renderer object: renderer_state.h. */
#ifndef STIPPLE_RENDER_PRIVATE_H
#define STIPPLE_RENDER_PRIVATE_H

#include "stipple/render.h"
#include "renderer_state.h"
#include "geometry_stage_private.h"
#include "fix_private.h"
#include "clip_private.h"
#include "view_private.h"
#include "shade_fast_private.h"
#include "shade_private.h"

#if !STP_PLAYBACK_ONLY
/* render.c, for mesh.c: an implicit segment opened when none is (as
 * stp_renderer_polygon does; STP_OK or its error), and the device position
 * (Q27.4) and depth key of a view point inside the view volume, exactly as
 * stp_renderer_polygon stores it. */
int stp_render_check_open(stp_renderer *r);
void stp_render_project(const stp_renderer *r, stp_vec3 p, stp_instr *out);

/* The face stage (render.c), shared by stp_renderer_polygon and
 * stp_renderer_mesh: a flat face's normal, side and shade are formed by
 * these functions on either route, so both enter a face alike.
 *
 * stp_render_model_normal: the unit normal of polygon v (n >= 3 points in
 * model coordinates, wound counter-clockwise seen from the side it points
 * to) as Q1.14 in out[]: a triangle's exact cross product, a longer
 * polygon's Newell sum, normalised once and rounded.  Returns 0 (out
 * unset) for a zero normal.  stp_mesh_prepare_normals is this for each
 * triangle. */
int stp_render_model_normal(const stp_vec3 *v, int n, int16_t out[3]);
/* Here, for render.c and mesh.c (direct drawing links mesh.c's
 * stp_mesh_prepare_normals without render.c): (a, b, c) (|.| < 2^62) as a
 * Q1.14 unit vector in out[] (STP_UNIT, Q30, rounded to nearest), 0 for a
 * zero vector; */
static inline int stp_render_unit_q14(int64_t a, int64_t b, int64_t c, int16_t out[3])
{
    return stp_unit_q14_from64(a, b, c, out);
}

/* a triangle's cross product (v1 - v0) x (v2 - v0) in c[] (model
 * coordinates): the edge vectors (below 2^33) cut to 30 bits together
 * (floor), so each term is below 2^61 and each component below 2^62; the
 * cut keeps the direction within 2^-28 of the exact one. */
#if defined(__OPTIMIZE_SIZE__)
/* in builds for size: the same values from loops over the components */
static inline void stp_render_triangle_cross(const stp_vec3 *v, int64_t c[3])
{
    int64_t e[6]; /* v1 - v0, v2 - v0 */
    uint64_t spread = 0;
    int i, j = 0, k, bits;
    const stp_vec3 *w = &v[1];
    for (i = 0; i < 6; i++) {
        e[i] = (int64_t)stp_vec3_comp(w, j) - stp_vec3_comp(&v[0], j);
        spread |= stp_abs64u(e[i]);
        if (++j == 3) {
            j = 0;
            w = &v[2];
        }
    }
    bits = stp_bit_length64(spread) - 30;
    for (i = 0; i < 6 && bits > 0; i++)
        e[i] = stp_asr64(e[i], bits);
    /* c_i = e_j e'_k - e_k e'_j, (i, j, k) turning cyclically from
     * (0, 1, 2) */
    for (i = 0, j = 1, k = 2; i < 3; i++) {
        c[i] = e[j] * e[3 + k] - e[k] * e[3 + j];
        j = k;
        k = i;
    }
}
#else
static inline void stp_render_triangle_cross(const stp_vec3 *v, int64_t c[3])
{
    int64_t x1 = (int64_t)v[1].x - v[0].x, y1 = (int64_t)v[1].y - v[0].y,
            z1 = (int64_t)v[1].z - v[0].z;
    int64_t x2 = (int64_t)v[2].x - v[0].x, y2 = (int64_t)v[2].y - v[0].y,
            z2 = (int64_t)v[2].z - v[0].z;
#if STP_HAVE_MUL64
    /* the usual triangle needs no cut: edges in [-2^29, 2^29) (a window
     * test by offsets, fewer steps than the magnitudes) */
    const uint64_t h = (uint64_t)1 << 29;
    if ((((uint64_t)x1 + h) | ((uint64_t)y1 + h) | ((uint64_t)z1 + h) | ((uint64_t)x2 + h) |
         ((uint64_t)y2 + h) | ((uint64_t)z2 + h)) >= 2 * h)
#endif
    {
        uint64_t spread = stp_abs64u(x1) | stp_abs64u(y1) | stp_abs64u(z1) | stp_abs64u(x2) |
                          stp_abs64u(y2) | stp_abs64u(z2);
#if STP_NARROW_FORMS
        if (spread < ((uint64_t)1 << 15)) {
            /* edges below 2^15 (half a unit: a mesh's triangle): products
             * below 2^30, their differences below 2^31, the same values in
             * int32 without the 64-bit multiply library call */
            c[0] = (int32_t)y1 * (int32_t)z2 - (int32_t)z1 * (int32_t)y2;
            c[1] = (int32_t)z1 * (int32_t)x2 - (int32_t)x1 * (int32_t)z2;
            c[2] = (int32_t)x1 * (int32_t)y2 - (int32_t)y1 * (int32_t)x2;
            return;
        }
#endif
        if (spread >> 30) {
            int bits = stp_bit_length64(spread) - 30;
            x1 = stp_asr64(x1, bits);
            y1 = stp_asr64(y1, bits);
            z1 = stp_asr64(z1, bits);
            x2 = stp_asr64(x2, bits);
            y2 = stp_asr64(y2, bits);
            z2 = stp_asr64(z2, bits);
        }
    }
    c[0] = y1 * z2 - z1 * y2;
    c[1] = z1 * x2 - x1 * z2;
    c[2] = x1 * y2 - y1 * x2;
}
#endif

/* a triangle's normal (stp_render_model_normal for n = 3): its cross
 * product, normalised. */
static inline int stp_render_triangle_normal(const stp_vec3 *v, int16_t out[3])
{
    int64_t c[3];
    stp_render_triangle_cross(v, c);
    return stp_render_unit_q14(c[0], c[1], c[2], out);
}

/* render.c: r->geometry (and r->point_view) for the view and model
 * transform in force. */
void stp_render_geometry_update(stp_renderer *r);

/* The model frame of the view and model transform in force (prepared once
 * after either changes), or NULL when it is not usable (see above). */
const stp_model_frame *stp_render_model_frame(stp_renderer *r);
/* The face shader of the segment's lighting and the material
 * (stp_shade_fast_prepare), prepared when out of date (by
 * stp_render_face_shader_prepare, out of line: the check stays inline for
 * a polygon's entry). */
void stp_render_face_shader_prepare(stp_renderer *r, int parallel);
STP_HOT_INLINE const stp_shade_fast *stp_render_face_shader(stp_renderer *r)
{
    int parallel = r->projection == STP_PARALLEL;
    if (!r->fast_shade_valid || r->fast_shade_parallel != parallel)
        stp_render_face_shader_prepare(r, parallel);
    return &r->fast_shade;
}

/* ---- the winding side (STP_WINDING_SIDE: builds with STP_DIRECT_COMPACT,
 * config.h) ----
 * In those builds a triangle whose three vertices are projected (inside
 * the clip volume and its guard band, project_private.h) is a front face
 * when its device positions turn clockwise (y down: counter-clockwise
 * seen from the eye): the sign of twice its signed area.  Direct
 * drawing's compact form keeps its faces by this test (the model frame's
 * eye, which the exact side needs, is a 64-bit quotient its budget has
 * no room for); the renderer's mesh and model routes take it there too,
 * so all keep the same faces, where the exact side and the rounded
 * positions' winding disagree for a face within a fraction of a pixel of
 * edge-on.  A triangle the clipper cuts keeps the exact side.  Elsewhere
 * every route takes the exact side (stp_render_face_side). */
#define STP_WINDING_SIDE STP_DIRECT_COMPACT

/* Twice the signed area of a triangle whose second and third device
 * positions less its first are (ax, ay) and (bx, by), each within
 * (-2^15, 2^15) (an int on every target; products below 2^30): negative
 * when it turns clockwise on the device (y down). */
STP_HOT_INLINE int32_t stp_render_twice_area(int ax, int ay, int bx, int by)
{
    return (int32_t)ax * by - (int32_t)ay * bx;
}

#if STP_WINDING_SIDE
/* The winding side of the triangle at device positions (x_i, y_i) (Q27.4,
 * within [-2^19, 2^19]): 1 clockwise on the device (a front face), -1
 * counter-clockwise, 0 no area; stp_render_twice_area where the
 * differences are within (-2^15, 2^15), else 64-bit products (below
 * 2^40). */
STP_HOT_INLINE int stp_render_winding_side(int32_t x0, int32_t y0, int32_t x1, int32_t y1, int32_t x2, int32_t y2)
{
    int32_t ax = x1 - x0, ay = y1 - y0, bx = x2 - x0, by = y2 - y0;
    int64_t area;
    /* each in (-2^15, 2^15): offset by 2^15 - 1, below 2^16 - 1 */
    if ((((uint32_t)ax + 32767u) | ((uint32_t)ay + 32767u) | ((uint32_t)bx + 32767u) | ((uint32_t)by + 32767u)) <
        65535u)
        area = stp_render_twice_area((int)ax, (int)ay, (int)bx, (int)by);
    else
        area = (int64_t)ax * by - (int64_t)ay * bx;
    return area < 0 ? 1 : (area > 0 ? -1 : 0);
}
#endif

/* The exact sign (-1, 0, 1) of N.(eye - v0) in model coordinates (the
 * product itself: stp_render_face_dot): which
 * side of a face with Q1.14 model normal n through model point v0 the eye
 * sees (1: the side n points to).  |eye - v0| < 2^30 + 2^31 per
 * coordinate: each product below 2^46, the sum below 2^48. */
STP_HOT_INLINE int64_t stp_render_face_dot(const stp_model_frame *f, const int16_t n[3], const stp_vec3 *v0)
{
    return (int64_t)n[0] * ((int64_t)f->eye[0] - v0->x) + (int64_t)n[1] * ((int64_t)f->eye[1] - v0->y) +
           (int64_t)n[2] * ((int64_t)f->eye[2] - v0->z);
}

STP_HOT_INLINE int stp_render_face_side(const stp_model_frame *f, const int16_t n[3], stp_vec3 v0)
{
    int64_t side = stp_render_face_dot(f, n, &v0);
    return side > 0 ? 1 : (side < 0 ? -1 : 0);
}

/* stp_render_face_side for |v0_i| < 2^23 (direct drawing's vertices;
 * the model frame's eye is below 2^30), the same sign; where 64-bit
 * products are library calls from 32-bit ones: with d_i = eye_i - v0_i =
 * 2^15 h_i + l_i (l_i in [0, 2^15), |h_i| <= 2^15 + 2^8), A = sum n_i h_i
 * and B = sum n_i l_i are below 3 (2^29 + 2^22) in magnitude (|n_i| <=
 * 2^14), and N.d = 2^15 A + B = 2^15 (A + floor(B / 2^15)) + (B mod
 * 2^15): the sign of A + floor(B / 2^15), or where that is 0 of B mod
 * 2^15 (>= 0). */
STP_HOT_INLINE int stp_render_face_side_near(const stp_model_frame *f, const int16_t n[3], const stp_vec3 *v0)
{
#if STP_WIDE_ARITH
    return stp_render_face_side(f, n, *v0);
#else
    int32_t d0 = f->eye[0] - v0->x, d1 = f->eye[1] - v0->y, d2 = f->eye[2] - v0->z;
    int32_t a = n[0] * stp_asr32(d0, 15) + n[1] * stp_asr32(d1, 15) + n[2] * stp_asr32(d2, 15);
    int32_t b = n[0] * (d0 & 0x7FFF) + n[1] * (d1 & 0x7FFF) + n[2] * (d2 & 0x7FFF);
    a += stp_asr32(b, 15);
    return a != 0 ? (a > 0 ? 1 : -1) : ((b & 0x7FFF) != 0);
#endif
}

/* The face side's 32-bit estimate, where 64-bit products are library
 * calls (the mesh route's and direct drawing's face loops): the eye in
 * model coordinates and every vertex floor-shifted right by shift, so each
 * is within 2^14 in magnitude; then est = sum n_i (eye_i >> shift - a_i >>
 * shift), each difference within 2^15 and |n_0| + |n_1| + |n_2| <= (2^14
 * + 1) sqrt 3 < 2^15 (n a unit normal rounded to Q1.14, as stp_mesh's
 * normals are: |n| <= 2^14 + 1), so the sum is below 2^31.  It is off the
 * exact N.(eye - a) / 2^shift by less than |n_0| + |n_1| + |n_2| < 2^15
 * (each pair of floors by less than 1): an estimate outside [-2^15, 2^15)
 * has the exact sign (stp_render_side_sure).  (stp_side_estimate:
 * view_private.h.) */

/* *e for frame f and vertices whose coordinates' magnitudes, ORed, are
 * at most coords */
STP_HOT_INLINE void stp_render_side_estimate_make(const stp_model_frame *f, uint32_t coords,
                                                  stp_side_estimate *e)
{
    int j, k;
    for (j = 0; j < 3; j++)
        coords |= stp_abs32(f->eye[j]);
    k = stp_bit_length32(coords) - 14;
    e->shift = k > 0 ? k : 0;
    for (j = 0; j < 3; j++)
        e->eye[j] = stp_asr32(f->eye[j], e->shift);
}

/* The estimate of normal n's side through model point a (above). */
STP_HOT_INLINE int32_t stp_render_side_estimate(const stp_side_estimate *e, const int16_t n[3], const stp_vec3 *a)
{
    int shift = e->shift;
    return (int32_t)n[0] * (e->eye[0] - stp_asr32(a->x, shift)) +
           (int32_t)n[1] * (e->eye[1] - stp_asr32(a->y, shift)) +
           (int32_t)n[2] * (e->eye[2] - stp_asr32(a->z, shift));
}

/* Whether estimate est has the exact side's sign (outside [-2^15, 2^15):
 * one shift and one comparison). */
STP_HOT_INLINE int stp_render_side_sure(int32_t est)
{
    return (uint32_t)(stp_asr32(est, 15) + 1) > 1u;
}

/* The side of a triangle with cross product c (stp_render_triangle_cross)
 * through v0 that stp_render_face_side gives for its normal n (c
 * normalised and rounded to Q1.14), found without normalising when the
 * sign is certain: 1 or -1, else 0 (near edge-on: the caller normalises).
 * With c and d = eye - v0 cut to 29 bits by floor shifts (c = 2^a cs + rc,
 * d = 2^b ds + rd, 0 <= r < 2^shift), |c.d - 2^(a+b) cs.ds| <= 2^(a+b)
 * (|cs|1 + |ds|1 + 3).  n = 2^14 c/|c| + delta with |delta_i| < 1 (the
 * rounding's half plus stp_unit_from64's error and the cut's 2^-28), so
 * n.d = 2^14 c.d/|c| + delta.d keeps the sign of c.d when 2^14 |c.d| >
 * 2 |c|1 |d|1 (a margin of 2), with |c|1 <= 2^a (|cs|1 + 3) and |d|1 <=
 * 2^b (|ds|1 + 3).  |cs|1 <= 3 C and |ds|1 <= 3 D for C and D the ORs of
 * the magnitudes: certain when |cs.ds| > 3 C + 3 D + 3 + (3 C + 3)(3 D + 3)
 * / 2^13.  Ranges: |cs|, |ds| <= 2^29, so C, D < 2^30, cs.ds below
 * 3 2^58 and (3 C + 3)(3 D + 3) below 2^64 (unsigned). */
#if STP_NARROW_FORMS
/* stp_render_certain_side's test in 32-bit arithmetic, where 64-bit
 * products are library calls, for c and d = eye - v0 already in int32
 * (|c_i|, |d_i| < 2^31): c and d cut by floor shifts to cs = c / 2^a,
 * |cs_i| <= 2^14, and ds = d / 2^b, |ds_i| <= 2^15, so cs.ds fits int32.
 * With the remainders below 2^a and 2^b, |c.d - 2^(a+b) cs.ds| < 2^(a+b)
 * (|cs|1 + |ds|1 + 3), |c|1 < 2^a (|cs|1 + 3) and |d|1 < 2^b (|ds|1 + 3);
 * cn and dn bound |cs|1 and |ds|1 (each |cs_i| <= (max |c_i| >> a) + 1).
 * |cs.ds| > cn + dn + 3 + (cn + 3)(dn + 3) / 2^13 (the quotient bounded
 * above by the shifted factors plus one, all below 2^10) gives the sign of
 * c.d and 2^13 |c.d| > |c|1 |d|1, the margin above.  1 or -1 when
 * certain, else 0 (the 64-bit test, with more bits, decides); 0 too when
 * some |d_i| >= d_limit (a power of two, at most 2^31): the callers' range
 * test of d, from the magnitudes formed here anyway. */
STP_HOT_INLINE int stp_render_certain_side_int32(int32_t cx, int32_t cy, int32_t cz, int32_t dx, int32_t dy,
                                               int32_t dz, uint32_t d_limit)
{
    uint32_t cm = stp_abs32(cx) | stp_abs32(cy) | stp_abs32(cz);
    uint32_t dm = stp_abs32(dx) | stp_abs32(dy) | stp_abs32(dz);
    /* the bound below at its largest, cn = 3 2^14 and dn = 3 2^15 (the
     * shifts make cm >> a < 2^14 and dm >> b < 2^15): a constant, fewer
     * steps than the bound of these c and d, and within about four times
     * it where both were cut (cm >> a >= 2^13, dm >> b >= 2^14): against
     * |cs.ds| up to 3 2^29, few more faces are left to the caller's 64-bit
     * test */
    const uint32_t cn = 3u << 14, dn = 3u << 15;
    if (dm >= d_limit)
        return 0;
    /* the shifts max(0, bit length - 14 or 15), from the bits above */
    int a = stp_bit_length32(cm >> 14), b = stp_bit_length32(dm >> 15);
    int32_t dot = stp_asr32(cx, a) * stp_asr32(dx, b) + stp_asr32(cy, a) * stp_asr32(dy, b) +
                  stp_asr32(cz, a) * stp_asr32(dz, b);
    if (stp_abs32(dot) <= cn + dn + 3u + (((cn + 3u) >> 6) + 1u) * (((dn + 3u) >> 7) + 1u))
        return 0;
    return dot > 0 ? 1 : -1;
}

/* stp_render_certain_side_int32 for c below 2^31 and d = eye - v0 below
 * 2^30, else 0.  d is formed mod 2^32: |eye| < 2^30 (stp_model_frame), so
 * an exact d is below 2^31 + 2^30 and one that wraps is at least 2^30 from
 * 0; below 2^30 after the wrap, it is exact. */
static inline int stp_render_certain_side32(const stp_model_frame *f, const int64_t c[3], stp_vec3 v0)
{
    if (((stp_abs64u(c[0]) | stp_abs64u(c[1]) | stp_abs64u(c[2])) >> 31) != 0)
        return 0;
    return stp_render_certain_side_int32((int32_t)c[0], (int32_t)c[1], (int32_t)c[2],
                                         (int32_t)((uint32_t)f->eye[0] - (uint32_t)v0.x),
                                         (int32_t)((uint32_t)f->eye[1] - (uint32_t)v0.y),
                                         (int32_t)((uint32_t)f->eye[2] - (uint32_t)v0.z), (uint32_t)1 << 30);
}
#endif

/* stp_render_certain_side for c whose magnitudes ORed are c_or (the
 * caller's, which stp_unit_q14_from64_or takes too) */
static inline int stp_render_certain_side_or(const stp_model_frame *f, const int64_t c[3], uint64_t c_or,
                                             stp_vec3 v0)
{
#if STP_NARROW_FORMS
    int sure = stp_render_certain_side32(f, c, v0);
    if (sure != 0)
        return sure;
#endif
    int64_t cx = c[0], cy = c[1], cz = c[2], dot;
    int64_t dx = (int64_t)f->eye[0] - v0.x, dy = (int64_t)f->eye[1] - v0.y,
            dz = (int64_t)f->eye[2] - v0.z;
    uint64_t d_or = stp_abs64u(dx) | stp_abs64u(dy) | stp_abs64u(dz), bound;
    if ((c_or | d_or) >> 29) {
        int a = stp_bit_length64(c_or) - 29, b = stp_bit_length64(d_or) - 29;
        if (a > 0) {
            cx = stp_asr64(cx, a);
            cy = stp_asr64(cy, a);
            cz = stp_asr64(cz, a);
            c_or = stp_abs64u(cx) | stp_abs64u(cy) | stp_abs64u(cz);
        }
        if (b > 0) {
            dx = stp_asr64(dx, b);
            dy = stp_asr64(dy, b);
            dz = stp_asr64(dz, b);
            d_or = stp_abs64u(dx) | stp_abs64u(dy) | stp_abs64u(dz);
        }
    }
    dot = cx * dx + cy * dy + cz * dz;
    bound = 3u * (c_or + d_or + 1u) + (((3u * c_or + 3u) * (3u * d_or + 3u)) >> 13) + 1u;
    if (stp_abs64u(dot) <= bound)
        return 0;
    return dot > 0 ? 1 : -1;
}

static inline int stp_render_certain_side(const stp_model_frame *f, const int64_t c[3], stp_vec3 v0)
{
    return stp_render_certain_side_or(f, c, stp_abs64u(c[0]) | stp_abs64u(c[1]) | stp_abs64u(c[2]), v0);
}

/* How many row centres 16 r + 8 a triangle with device y coordinates a,
 * b, c (Q27.4, >= 0: the projection clamps them into the picture) spans in
 * [min, max): the rasters (raster.c's row_below and the polygon edges)
 * draw exactly those rows, so a triangle spanning none draws no pixel in
 * any mode, edge AA included (it works on the rows drawn).  Both entries
 * leave such a triangle out before shading it. */
STP_HOT_INLINE int32_t stp_render_row_count(int32_t a, int32_t b, int32_t c)
{
    int32_t lo = a < b ? a : b, hi = a < b ? b : a;
    if (c < lo)
        lo = c;
    if (c > hi)
        hi = c;
    const int32_t below_centre = (1 << (STP_SUBPIXEL_BITS - 1)) - 1;
    return (int32_t)((uint32_t)(hi + below_centre) >> STP_SUBPIXEL_BITS) -
           (int32_t)((uint32_t)(lo + below_centre) >> STP_SUBPIXEL_BITS);
}

/* The triangles pixel culling tests by their crossings: those spanning
 * at most STP_CENTRE_TEST_MAX row centres (the callers' test) whose twice
 * area, |(x1 - x0) (y2 - y0) - (x2 - x0) (y1 - y0)| in Q8 (512 for a
 * triangle of one square pixel), is below STP_CENTRE_TEST_AREA (0.5625 of
 * a pixel: stp_render_thin); others are kept untested.  Measured on the
 * 1000-triangle torus at 128x64 (host, callgrind, the cull on): of its
 * 459 front triangles a frame that span a row centre 62 reach no pixel
 * centre, 56 of them below a pixel of area and none of those above 5
 * rows, while one of 0.5 to 1 pixel is drawn twice as often as not, and
 * larger ones nearly always: testing those costs more than culling them
 * saves (about 600 instructions: shade, records, scan and walk).  The
 * area's two products cost less than the bounding box's column count
 * (the gate before) and select better; 4 or 3 rows save less at 128x64
 * (a frame 602.2 K, 5 rows; 605.3 K, 4; 606.0 K, 3) and cost less at
 * 400x240 (1 156.5 K; 1 155.9 K; 1 155.5 K; 1 155.3 K before). */
#define STP_CENTRE_TEST_MAX 5
#define STP_CENTRE_TEST_AREA 576
#if STP_CENTRE_TEST_MAX > 7
#error "stp_render_thin's products in int32 need STP_CENTRE_TEST_MAX <= 7"
#endif

/* Whether stp_render_triangle_shows tests the gate in line (the hosts
 * with 64-bit registers: a call a triangle costs more than the area) or
 * stp_render_centre_reached does (32-bit targets, whose mesh face loop,
 * where pixel culling is off, keeps its code: its registers are scarce).
 * The same triangles are tested either way. */
#define STP_CENTRE_GATE_INLINE STP_WIDE_ARITH

/* Whether a triangle spanning at most STP_CENTRE_TEST_MAX row centres
 * with device vertices (Q27.4, >= 0, x below 2^19: width <= 32767) is thin
 * enough for pixel culling to test (above).  Its y lie within 16 (7 + 1)
 * = 2^7 of each other, so each product lies below 2^26 in magnitude and
 * their difference below 2^27: int32 arithmetic. */
STP_HOT_INLINE int stp_render_thin(int32_t x0, int32_t y0, int32_t x1, int32_t y1, int32_t x2, int32_t y2)
{
    int32_t twice_area = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0);
    return (uint32_t)twice_area + (STP_CENTRE_TEST_AREA - 1u) < 2u * STP_CENTRE_TEST_AREA - 1u;
}

/* Whether a flat triangle with device vertices (x0, y0), (x1, y1), (x2,
 * y2) (Q27.4, >= 0; spanning 1 to STP_CENTRE_TEST_MAX row centres:
 * stp_render_row_count) may give a pixel to one of its rows' spans; 0 only
 * when neither raster (raster.c's draw_triangle and draw_polygon) draws a
 * pixel of it, in any mode but edge anti-aliasing (which also draws pixels
 * near the crossings of a row whose span is empty: so callers drop
 * triangles only under stp_renderer_set_pixel_cull, render.h, and such a
 * render refuses a display file entered so).  Both rasters draw on row r
 * (centre yc = 16 r + 8 in [ymin, ymax)) the pixel centres c with x_left
 * <= c < x_right, the two crossings of the edges covering yc
 * (stp_edge_setup: ya <= yc < yb, a the upper end), each floor((xa 2^16 +
 * (yc - ya) q) / 2^16) with q = 2^16 (xb - xa) / (yb - ya) truncated
 * toward zero (stp_edge_acc_short; a row stepped to holds the same
 * value).  For every x below 2^14 (others are kept, 1; the y extent is
 * below 16 (STP_CENTRE_TEST_MAX + 1)) it forms those crossings so, row
 * by row, in the triangle raster's vertex order (stp_tri_sort); where the
 * gate is not in line (STP_CENTRE_GATE_INLINE) it keeps a triangle that
 * is not thin first.  A call of its own (render.c), so that the callers'
 * path without the cull stays as it is. */
int stp_render_centre_reached(int32_t x0, int32_t y0, int32_t x1, int32_t y1, int32_t x2, int32_t y2);

/* Whether a flat triangle inside the view with device vertices (x0, y0),
 * (x1, y1), (x2, y2) (Q27.4, >= 0) may draw: it spans a row centre
 * (stp_render_row_count) and, spanning at most test_rows (pixel culling's
 * STP_CENTRE_TEST_MAX, 0 when off) and thin, reaches a pixel centre.  A
 * culled one marks the open segment (it lost a sliver edge AA would draw:
 * render.h).  Both entries test their triangles so before shading them. */
STP_HOT_INLINE int stp_render_triangle_shows(stp_renderer *r, int32_t test_rows, int32_t x0, int32_t y0,
                                             int32_t x1, int32_t y1, int32_t x2, int32_t y2)
{
    int32_t rows = stp_render_row_count(y0, y1, y2);
    if (rows == 0)
        return 0;
    if (STP_UNLIKELY(rows <= test_rows) && (!STP_CENTRE_GATE_INLINE || stp_render_thin(x0, y0, x1, y1, x2, y2)) &&
        !stp_render_centre_reached(x0, y0, x1, y1, x2, y2)) {
        r->segments[r->open_segment].pixel_culled = 1;
        return 0;
    }
    return 1;
}

/* A triangle's vertex average (one coordinate of its three view points),
 * each sum divided by 3 truncated toward zero: both entries' face centre
 * (render.c's vertex_average, the same quotients).  small: each value
 * below 2^28 in magnitude (mesh.c's box_inside), so the sum fits int32.
 * With STP_DIRECT_COMPACT a sum below 2^28 takes the compact form's third
 * (stp_render_third, below). */
#if STP_DIRECT_COMPACT
/* The compact form's third of s (|s| < 2^28; config.h:
 * STP_DIRECT_COMPACT): floor(s / 2^16) 21846 + floor((s mod 2^16) 21846 /
 * 2^16), 16 x 16-bit products, relative error below 2^-15 (21846 / 2^16
 * for 1/3): the point a face is shaded at, direct drawing's and, in those
 * builds, the renderer's (stp_render_average3). */
STP_HOT_INLINE int32_t stp_render_third(int32_t s)
{
    int_fast16_t high = (int_fast16_t)stp_asr32(s, 16); /* below 2^12 */
    uint_fast16_t low = (uint_fast16_t)((uint32_t)s & 0xFFFFu);
    return (int32_t)high * 21846 + (int32_t)((uint32_t)low * 21846u >> 16);
}
#endif

STP_HOT_INLINE stp_fix stp_render_average3(int small, int32_t a, int32_t b, int32_t c)
{
    int64_t s;
#if STP_DIRECT_COMPACT
    s = (int64_t)a + b + c;
    if (s > -((int64_t)1 << 28) && s < ((int64_t)1 << 28))
        return stp_render_third((int32_t)s); /* the compact form's */
#endif
    if (small) {
        int32_t sum = a + b + c; /* below 3 2^28 < 2^30 in magnitude */
        return sum >= 0 ? (stp_fix)stp_div3_u30((uint32_t)sum) : -(stp_fix)stp_div3_u30(0u - (uint32_t)sum);
    }
    s = (int64_t)a + b + c;
#if !STP_WIDE_ARITH
    /* a 64-bit quotient is a library call: a 32-bit one while s fits */
    if (s >= INT32_MIN && s <= INT32_MAX)
        return (stp_fix)stp_div3_toward_zero((int32_t)s);
#endif
    return (stp_fix)(s / 3);
}

/* A flat opaque triangle's display-file records, as both entries store
 * them: SHADE (style, shade, colour 0) when change (the style or colour
 * in force differs), written here, then room for its three vertex
 * records, which the caller writes (stp_render_put_vertex: op 3, then
 * STP_OP_LINE twice); r->used counts them all.  NULL when the display file
 * has no room for them (nothing written).  The caller keeps the style in
 * force (r->current_style and r->current_colour, or a local for many
 * faces: mesh.c), the open segment's end and the transmission (0: the
 * caller's test). */
STP_HOT_INLINE stp_instr *stp_render_face_records(stp_renderer *r, int change, int style, stp_fix shade)
{
    uint32_t used = r->used;
    stp_instr *out;
    if (r->capacity - used < (change ? 4u : 3u))
        return 0;
    out = &r->df[used];
    if (change) {
        out->op = STP_OP_SHADE;
        out->x = style;
        out->y = shade;
        out->z = 0;
#if STP_WITH_GOURAUD
        out->shade = -1;
#endif
        out++;
        used++;
    }
    r->used = used + 3;
    return out;
}

/* The style in force for a caller keeping it in a local: r->current_style,
 * or -1 while a colour is (r->current_colour), which no style (>= 1)
 * matches. */
STP_HOT_INLINE int stp_render_current_style(const stp_renderer *r)
{
    return r->current_colour != 0 ? -1 : r->current_style;
}

/* stp_render_face_records on the renderer's style in force, the shade
 * r->last_shade. */
STP_HOT_INLINE stp_instr *stp_render_triangle_records(stp_renderer *r, int style)
{
    int change = style != r->current_style || r->current_colour != 0;
    stp_instr *out = stp_render_face_records(r, change, style, r->last_shade);
    if (out != 0 && change) {
        r->current_style = style;
        r->current_colour = 0;
    }
    return out;
}

/* A flat polygon's vertex record: device position (x, y) and depth key z. */
STP_HOT_INLINE void stp_render_put_vertex(stp_instr *out, int32_t op, int32_t x, int32_t y, int32_t z)
{
    out->op = op;
    out->x = x;
    out->y = y;
    out->z = z;
#if STP_WITH_GOURAUD
    out->shade = -1;
#endif
}

/* The model normal n in view coordinates (Q1.14, rounded), turned to the
 * eye when side <= 0 (the other side of an open surface shows): each row
 * product Q15 x Q14, the sum S below 2^29 (1 + rounding), to Q14 rounded
 * (floor((S + 2^14) / 2^15): stp_asr32, one shift on ARMv6-M).  Where the
 * 32-bit forms are taken (STP_NARROW_FORMS: ARMv6-M's -O2) the turned
 * value -floor((S + 2^14) / 2^15) = floor((-S + 2^14 - 1) / 2^15) is the
 * same rounding of -n's sum with the half one less, no choice per row;
 * elsewhere (a 64-bit host, builds for size) each row is turned, the
 * shorter code there. */
#if STP_NARROW_FORMS
STP_HOT_INLINE void stp_render_view_normal(const stp_model_frame *f, const int16_t n[3], int32_t side,
                                           int16_t nv[3])
{
    int32_t n0 = n[0], n1 = n[1], n2 = n[2], half = (int32_t)1 << 14;
    if (side <= 0) {
        n0 = -n0;
        n1 = -n1;
        n2 = -n2;
        half--;
    }
    nv[0] = (int16_t)stp_asr32(f->rot[0][0] * n0 + f->rot[0][1] * n1 + f->rot[0][2] * n2 + half, 15);
    nv[1] = (int16_t)stp_asr32(f->rot[1][0] * n0 + f->rot[1][1] * n1 + f->rot[1][2] * n2 + half, 15);
    nv[2] = (int16_t)stp_asr32(f->rot[2][0] * n0 + f->rot[2][1] * n1 + f->rot[2][2] * n2 + half, 15);
}
#else
STP_HOT_INLINE int16_t stp_render_view_normal_row(const int32_t row[3], const int16_t n[3], int32_t side)
{
    int32_t s = stp_asr32(row[0] * n[0] + row[1] * n[1] + row[2] * n[2] + ((int32_t)1 << 14), 15);
    return (int16_t)(side > 0 ? s : -s);
}

STP_HOT_INLINE void stp_render_view_normal(const stp_model_frame *f, const int16_t n[3], int32_t side,
                                           int16_t nv[3])
{
    nv[0] = stp_render_view_normal_row(f->rot[0], n, side);
    nv[1] = stp_render_view_normal_row(f->rot[1], n, side);
    nv[2] = stp_render_view_normal_row(f->rot[2], n, side);
}
#endif

/* A flat face's shade by the face shader s from view normal nv and vertex
 * average centre: the ambient share only, as for N.E = 0, when side is 0
 * (its plane passes through the eye). */
STP_HOT_INLINE stp_fix stp_render_face_shade(const stp_shade_fast *s, const int16_t nv[3], stp_vec3 centre,
                                             int32_t side)
{
    return side != 0 ? stp_shade_fast_face(s, nv, centre) : s->ambient_shade;
}

/* A flat face's INTENSITY style (1..levels) with shading on (its shade:
 * stp_render_face_shade) or off (the fill style); r->last_shade set to its
 * shade. */
STP_HOT_INLINE int stp_render_face_style(stp_renderer *r, const stp_shade_fast *s, const int16_t nv[3],
                                         stp_vec3 centre, int side)
{
    int style;
    if (r->shading) {
        r->last_shade = stp_render_face_shade(s, nv, centre, side);
        return stp_intensity_index_inline(r->last_shade, r->levels);
    }
    style = r->fill_style;
    r->last_shade = stp_intensity_shade(style, r->levels);
    return style;
}
#endif

#endif
