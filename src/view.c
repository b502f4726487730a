/* SPDX-License-Identifier: MIT */
/* The view frame (see view_private.h). */
#include "view_private.h"
#include "fix_private.h"

#define F STP_FIX_FRAC_BITS
#define ONE STP_FIX_ONE

stp_vec3 stp_vec3_cross(stp_vec3 a, stp_vec3 b)
{
    stp_vec3 c;
    c.x = stp_fix_sat64(stp_asr64((int64_t)a.y * b.z - (int64_t)a.z * b.y, F));
    c.y = stp_fix_sat64(stp_asr64((int64_t)a.z * b.x - (int64_t)a.x * b.z, F));
    c.z = stp_fix_sat64(stp_asr64((int64_t)a.x * b.y - (int64_t)a.y * b.x, F));
    return c;
}

int stp_view_frame_make(const stp_view *v, uint32_t width, uint32_t height, stp_view_frame *out)
{
    stp_vec3 dir, right, up, upn;
    stp_fix focal;
    uint32_t short_side;
    dir.x = stp_fix_sub(v->at.x, v->from.x);
    dir.y = stp_fix_sub(v->at.y, v->from.y);
    dir.z = stp_fix_sub(v->at.z, v->from.z);
    if (stp_vec3_unity(dir, &dir) == 0)
        return STP_ERR_VIEW;
    if (stp_vec3_unity(v->up, &upn) == 0)
        return STP_ERR_VIEW;
    /* right = dir x up; a short cross product means up is (nearly) along
     * the line of sight: no roll can be derived */
    right = stp_vec3_cross(dir, upn);
    if (stp_vec3_unity(right, &right) < (ONE >> 10))
        return STP_ERR_VIEW;
    up = stp_vec3_cross(right, dir);
    (void)stp_vec3_unity(up, &up);
    if (v->hither <= 0)
        return STP_ERR_VIEW;
    short_side = width < height ? width : height;
    if (v->projection == STP_PERSPECTIVE) {
        /* focal = (short/2) / tan(fov/2), in pixels, F fractional bits */
        stp_fix half = v->fov_degrees / 2, s, c;
        if (v->fov_degrees <= 0 || v->fov_degrees >= 180 * ONE)
            return STP_ERR_VIEW;
        s = stp_fix_sin_deg(half);
        c = stp_fix_cos_deg(half);
        if (s <= 0)
            return STP_ERR_VIEW;
        focal = stp_fix_sat64(((int64_t)short_side * c * (ONE / 2)) / s);
    } else if (v->projection == STP_PARALLEL) {
        if (v->window_half <= 0)
            return STP_ERR_VIEW;
        focal = stp_fix_sat64(((int64_t)short_side * ONE * (ONE / 2)) / v->window_half);
    } else {
        return STP_ERR_ARG;
    }
    out->from = v->from;
    out->right = right;
    out->up = up;
    out->forward = dir;
    out->focal = focal;
    out->hither = v->hither;
    out->projection = v->projection;
    return STP_OK;
}

void stp_view_transform_make(const stp_view_frame *vf, stp_view_transform *out)
{
    out->right = vf->right;
    out->up = vf->up;
    out->forward = vf->forward;
    out->from_right = (int64_t)vf->from.x * vf->right.x + (int64_t)vf->from.y * vf->right.y +
                      (int64_t)vf->from.z * vf->right.z;
    out->from_up = (int64_t)vf->from.x * vf->up.x + (int64_t)vf->from.y * vf->up.y +
                   (int64_t)vf->from.z * vf->up.z;
    out->from_forward = (int64_t)vf->from.x * vf->forward.x + (int64_t)vf->from.y * vf->forward.y +
                        (int64_t)vf->from.z * vf->forward.z;
}

/* floor(v / 2^F), saturated, for |v| < 2^62: the offset makes the shifted
 * value non-negative (a right shift of a negative value is the
 * implementation's), and 2^62 is a multiple of 2^F, so the floor is exact */
static stp_fix floor_shift_sat(int64_t v)
{
    return stp_fix_sat64(((v + ((int64_t)1 << 62)) >> F) - ((int64_t)1 << (62 - F)));
}

void stp_view_transform_point(const stp_view_transform *t, stp_vec3 p, stp_vec3 *out)
{
    /* (p - from) . axis = p . axis - from . axis, exactly in 64 bits: each
     * product < 2^47, so the sums stay below 2^50; p - from itself may
     * exceed stp_fix's range */
    out->x = floor_shift_sat((int64_t)p.x * t->right.x + (int64_t)p.y * t->right.y +
                             (int64_t)p.z * t->right.z - t->from_right);
    out->y = floor_shift_sat((int64_t)p.x * t->up.x + (int64_t)p.y * t->up.y +
                             (int64_t)p.z * t->up.z - t->from_up);
    out->z = floor_shift_sat((int64_t)p.x * t->forward.x + (int64_t)p.y * t->forward.y +
                             (int64_t)p.z * t->forward.z - t->from_forward);
}

/* Ranges: each difference of vertices below 2^ld (raw), the eye's below
 * 2^le: the cross product's components are below 2^(2 ld + 1) and the
 * triple product below 3 2^(2 ld + le + 1), so 2 ld + le <= 60 keeps it
 * below 2^63.  With ld, le <= 29 each view coordinate is below
 * sqrt(3) 2^30 < 2^31 - 1: none saturates. */
int stp_view_triangle_side(stp_vec3 from, stp_vec3 forward, int parallel, const stp_vec3 *v)
{
    int64_t x1 = (int64_t)v[1].x - v[0].x, y1 = (int64_t)v[1].y - v[0].y,
            z1 = (int64_t)v[1].z - v[0].z;
    int64_t x2 = (int64_t)v[2].x - v[0].x, y2 = (int64_t)v[2].y - v[0].y,
            z2 = (int64_t)v[2].z - v[0].z;
    int64_t ex = (int64_t)from.x - v[0].x, ey = (int64_t)from.y - v[0].y,
            ez = (int64_t)from.z - v[0].z;
    uint64_t spread = (uint64_t)(x1 < 0 ? -x1 : x1) | (uint64_t)(y1 < 0 ? -y1 : y1) |
                      (uint64_t)(z1 < 0 ? -z1 : z1) | (uint64_t)(x2 < 0 ? -x2 : x2) |
                      (uint64_t)(y2 < 0 ? -y2 : y2) | (uint64_t)(z2 < 0 ? -z2 : z2);
    uint64_t reach = (uint64_t)(ex < 0 ? -ex : ex) | (uint64_t)(ey < 0 ? -ey : ey) |
                     (uint64_t)(ez < 0 ? -ez : ez);
    int ld, le;
    int64_t cx, cy, cz, side;
    if ((spread | reach) >= ((uint64_t)1 << 29))
        return 0;
    ld = stp_bit_length64(spread);
    le = stp_bit_length64(reach);
    if (parallel) {
        ex = -(int64_t)forward.x; /* a unit stp_vec3: below 2^17 */
        ey = -(int64_t)forward.y;
        ez = -(int64_t)forward.z;
        le = F + 1;
    }
    if (2 * ld + le > 60)
        return 0;
    cx = y1 * z2 - z1 * y2;
    cy = z1 * x2 - x1 * z2;
    cz = x1 * y2 - y1 * x2;
    if (cx == 0 && cy == 0 && cz == 0)
        return 0; /* degenerate: the full path reports it */
    side = cx * ex + cy * ey + cz * ez;
    return side > 0 ? 1 : -1;
}
