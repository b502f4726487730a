/* SPDX-License-Identifier: MIT */
/* Private: the one polygon clipper, shared by the display file (render.c:
 * the view's pyramid or box) and the shadow maps (shadow.c: a light's
 * pyramid). */
#ifndef STIPPLE_CLIP_PRIVATE_H
#define STIPPLE_CLIP_PRIVATE_H

#include "stipple/render.h"
#include "fix_private.h" /* stp_asr64 */

/* A volume to clip against, in its own frame (x right, y up, z forward):
 * perspective, the pyramid of a width x height device seen with `focal`
 * pixels per unit of x/z, cut by the near plane z = near; parallel, the box
 * |focal x| <= width/2, |focal y| <= height/2 (focal in pixels per unit),
 * z >= near.  focal and near have F fractional bits. */
typedef struct stp_clip_volume {
    stp_fix focal, near;
    uint32_t width, height;
    int parallel;
} stp_clip_volume;

/* Signed distance of p from plane `plane` (0: near, 1..4: left, right,
 * top, bottom), >= 0 inside; scaled by a positive per-plane factor (only
 * signs and ratios matter).  Every term is below 2^47. */
int64_t stp_clip_distance(const stp_clip_volume *v, int plane, stp_vec3 p);

/* Outcode of p: bit `plane` set when stp_clip_distance(v, plane, p) < 0. */
unsigned stp_clip_outcode(const stp_clip_volume *v, stp_vec3 p);

/* stp_clip_outcode's five planes at once, in line (its value everywhere;
 * stp_clip_outcode takes a shorter test first on 32-bit targets) for
 * render.c's vertex cache, whose miss costs a call less so */
STP_HOT_INLINE unsigned stp_clip_outcode_planes(const stp_clip_volume *v, stp_vec3 p)
{
    int64_t fx = stp_asr64((int64_t)v->focal * p.x, STP_FIX_FRAC_BITS),
            fy = stp_asr64((int64_t)v->focal * p.y, STP_FIX_FRAC_BITS);
    int64_t hw, hh;
    unsigned code = (int64_t)p.z - v->near < 0 ? 1u : 0u;
    if (!v->parallel) {
        hw = ((int64_t)v->width * p.z) / 2;
        hh = ((int64_t)v->height * p.z) / 2;
    } else {
        hw = ((int64_t)v->width * STP_FIX_ONE) / 2;
        hh = ((int64_t)v->height * STP_FIX_ONE) / 2;
    }
    if (fx + hw < 0)
        code |= 2u;
    if (hw - fx < 0)
        code |= 4u;
    if (hh - fy < 0)
        code |= 8u;
    if (fy + hh < 0)
        code |= 16u;
    return code;
}

/* Sutherland-Hodgman against the five planes.  The n vertices are in a[];
 * b[] is as large (n + 5 entries each); when sa is not NULL, sa[] holds a
 * value per vertex (a smooth polygon's shades, with sb[] beside b[])
 * interpolated like the positions.  Returns the clipped vertex count; the
 * vertices are in *result (a or b), the other buffer in *spare, and the
 * values in *values (sa or sb; NULL when sa is). */
int stp_clip_polygon(const stp_clip_volume *v, stp_vec3 *a, stp_vec3 *b, stp_fix *sa,
                     stp_fix *sb, int n, stp_vec3 **result, stp_vec3 **spare, stp_fix **values);

#endif
