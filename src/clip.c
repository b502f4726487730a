/* SPDX-License-Identifier: MIT */
/* The polygon clipper (clip_private.h). */
#include "clip_private.h"
#include "fix_private.h"

#define F STP_FIX_FRAC_BITS
#define ONE STP_FIX_ONE

int64_t stp_clip_distance(const stp_clip_volume *v, int plane, stp_vec3 p)
{
    /* both terms have F fractional bits and stay below 2^47 */
    int64_t fx = stp_asr64((int64_t)v->focal * p.x, F), fy = stp_asr64((int64_t)v->focal * p.y, F);
    int64_t hw, hh;
    if (plane == 0)
        return (int64_t)p.z - v->near;
    if (!v->parallel) {
        /* x_screen = W/2 + focal x / z lies in [0, W] <=> |focal x| <= (W/2) z */
        hw = ((int64_t)v->width * p.z) / 2;
        hh = ((int64_t)v->height * p.z) / 2;
    } else {
        hw = ((int64_t)v->width * ONE) / 2;
        hh = ((int64_t)v->height * ONE) / 2;
    }
    switch (plane) {
    case 1: return fx + hw;
    case 2: return hw - fx;
    case 3: return hh - fy;
    default: return fy + hh;
    }
}

unsigned stp_clip_outcode(const stp_clip_volume *v, stp_vec3 p)
{
    /* stp_clip_distance's five planes at once */
    int64_t fx = stp_asr64((int64_t)v->focal * p.x, F), fy = stp_asr64((int64_t)v->focal * p.y, F);
    int64_t hw, hh;
    unsigned code = (int64_t)p.z - v->near < 0 ? 1u : 0u;
    if (!v->parallel) {
        hw = ((int64_t)v->width * p.z) / 2;
        hh = ((int64_t)v->height * p.z) / 2;
    } else {
        hw = ((int64_t)v->width * ONE) / 2;
        hh = ((int64_t)v->height * ONE) / 2;
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

int stp_clip_polygon(const stp_clip_volume *v, stp_vec3 *a, stp_vec3 *b, stp_fix *sa,
                     stp_fix *sb, int n, stp_vec3 **result, stp_vec3 **spare, stp_fix **values)
{
    stp_vec3 *in = a, *out = b, *tmp;
    stp_fix *s_in = sa, *s_out = sb, *s_tmp;
    int plane, i, m;
    for (plane = 0; plane < 5 && n > 0; plane++) {
        m = 0;
        for (i = 0; i < n; i++) {
            int j = (i + 1) % n;
            stp_vec3 p = in[i], q = in[j];
            int64_t dp = stp_clip_distance(v, plane, p), dq = stp_clip_distance(v, plane, q);
            if (dp >= 0) {
                if (s_in)
                    s_out[m] = s_in[i];
                out[m++] = p;
            }
            if ((dp >= 0) != (dq >= 0)) {
                int64_t t = stp_clip_fraction(dp, dq);
                if (s_in)
                    s_out[m] = stp_lerp_fix(s_in[i], s_in[j], t);
                out[m].x = stp_lerp_fix(p.x, q.x, t);
                out[m].y = stp_lerp_fix(p.y, q.y, t);
                out[m].z = stp_lerp_fix(p.z, q.z, t);
                m++;
            }
        }
        n = m;
        tmp = in;
        in = out;
        out = tmp;
        s_tmp = s_in;
        s_in = s_out;
        s_out = s_tmp;
    }
    *result = in;
    *spare = out;
    *values = s_in;
    return n;
}
