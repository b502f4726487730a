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
    stp_unit3 u;
    if (stp_unit_from64(a, b, c, &u) == 0)
        return 0;
    out[0] = (int16_t)stp_asr64((int64_t)u.x + ((int64_t)1 << 15), 16);
    out[1] = (int16_t)stp_asr64((int64_t)u.y + ((int64_t)1 << 15), 16);
    out[2] = (int16_t)stp_asr64((int64_t)u.z + ((int64_t)1 << 15), 16);
    return 1;
}

/* a triangle's normal (stp_render_model_normal for n = 3): the edge
 * vectors (below 2^33) cut to 30 bits together, so each cross-product term
 * is below 2^61 and their difference below 2^62. */
static inline int stp_render_triangle_normal(const stp_vec3 *v, int16_t out[3])
{
    int64_t e[6];
    uint64_t spread = 0;
    int i, bits;
    e[0] = (int64_t)v[1].x - v[0].x;
    e[1] = (int64_t)v[1].y - v[0].y;
    e[2] = (int64_t)v[1].z - v[0].z;
    e[3] = (int64_t)v[2].x - v[0].x;
    e[4] = (int64_t)v[2].y - v[0].y;
    e[5] = (int64_t)v[2].z - v[0].z;
    for (i = 0; i < 6; i++)
        spread |= (uint64_t)(e[i] < 0 ? -e[i] : e[i]);
    bits = stp_bit_length64(spread) - 30;
    if (bits > 0)
        for (i = 0; i < 6; i++)
            e[i] = stp_asr64(e[i], bits);
    return stp_render_unit_q14(e[1] * e[5] - e[2] * e[4], e[2] * e[3] - e[0] * e[5],
                               e[0] * e[4] - e[1] * e[3], out);
}

/* render.c: r->geometry (and r->point_view) for the view and model
 * transform in force. */
void stp_render_geometry_update(stp_renderer *r);

/* The model frame of the view and model transform in force (prepared once
 * after either changes), or NULL when it is not usable (see above). */
const stp_model_frame *stp_render_model_frame(stp_renderer *r);
/* The face shader of the segment's lighting and the material
 * (stp_shade_fast_prepare), prepared when out of date. */
const stp_shade_fast *stp_render_face_shader(stp_renderer *r);

/* The exact sign (-1, 0, 1) of N.(eye - v0) in model coordinates: which
 * side of a face with Q1.14 model normal n through model point v0 the eye
 * sees (1: the side n points to).  |eye - v0| < 2^30 + 2^31 per
 * coordinate: each product below 2^46, the sum below 2^48. */
STP_HOT_INLINE int stp_render_face_side(const stp_model_frame *f, const int16_t n[3], stp_vec3 v0)
{
    int64_t side = (int64_t)n[0] * ((int64_t)f->eye[0] - v0.x) +
                   (int64_t)n[1] * ((int64_t)f->eye[1] - v0.y) +
                   (int64_t)n[2] * ((int64_t)f->eye[2] - v0.z);
    return side > 0 ? 1 : (side < 0 ? -1 : 0);
}

/* The model normal n in view coordinates (Q1.14, rounded), turned to the
 * eye when side <= 0 (the other side of an open surface shows): each row
 * product Q15 x Q14, the sum below 2^29 (1 + rounding), to Q14 rounded
 * (floor of the sum plus a half: >> of a negative value is
 * implementation-defined, so the shift is taken on a value made positive). */
STP_HOT_INLINE int16_t stp_render_view_normal_row(const int32_t row[3], const int16_t n[3], int side)
{
    int32_t s = row[0] * n[0] + row[1] * n[1] + row[2] * n[2] + ((int32_t)1 << 14);
    s = (int32_t)(((uint32_t)s + ((uint32_t)1 << 30)) >> 15) - ((int32_t)1 << 15);
    return (int16_t)(side > 0 ? s : -s);
}

STP_HOT_INLINE void stp_render_view_normal(const stp_model_frame *f, const int16_t n[3], int side,
                                           int16_t nv[3])
{
    nv[0] = stp_render_view_normal_row(f->rot[0], n, side);
    nv[1] = stp_render_view_normal_row(f->rot[1], n, side);
    nv[2] = stp_render_view_normal_row(f->rot[2], n, side);
}

/* A flat face's INTENSITY style (1..levels) with shading on (its shade by
 * the face shader s from view normal nv and vertex average centre; the
 * ambient share only, as for N.E = 0, when side is 0: its plane passes
 * through the eye) or off (the fill style); r->last_shade set to its
 * shade. */
STP_HOT_INLINE int stp_render_face_style(stp_renderer *r, const stp_shade_fast *s, const int16_t nv[3],
                                         stp_vec3 centre, int side)
{
    int style;
    if (r->shading) {
        r->last_shade = side != 0 ? stp_shade_fast_face(s, nv, centre) : s->ambient_shade;
        return stp_intensity_index_inline(r->last_shade, r->levels);
    }
    style = r->fill_style;
    r->last_shade = stp_intensity_shade(style, r->levels);
    return style;
}
#endif

#endif
