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
