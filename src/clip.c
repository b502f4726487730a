/* SPDX-License-Identifier: MIT */
/* The polygon clipper (clip_private.h). */
#include "clip_private.h"
#include "fix_private.h"

#define F STP_FIX_FRAC_BITS
#define ONE STP_FIX_ONE

int64_t stp_clip_distance(const stp_clip_volume *v, int plane, stp_vec3 p)
{
    /* both terms have F fractional bits and stay below 2^47; each plane's
     * two products alone (64-bit products are library calls on 32-bit
     * cores) */
    int64_t f, half;
    int across = plane <= 2; /* planes 1 and 2 bound x, 3 and 4 y */
    int32_t size = across ? v->width : v->height;
    if (plane == 0)
        return (int64_t)p.z - v->near;
    f = stp_asr64((int64_t)v->focal * (across ? p.x : p.y), F);
    /* x_screen = W/2 + focal x / z lies in [0, W] <=> |focal x| <= (W/2) z */
    half = ((int64_t)size * (v->parallel ? ONE : p.z)) / 2;
    switch (plane) {
    case 1: return f + half;
    case 2: return half - f;
    case 3: return half - f;
    default: return f + half;
    }
}

#if STP_NARROW_FORMS
/* Whether perspective view point p is clearly inside the four
 * side planes, in 32-bit products (64-bit ones are library calls here):
 * with hw = floor(W z / 2) and fx = floor(f x / 2^16), |fx| <= hw when
 * f |x| / 2^16 + 2 <= W z / 2 (|fx| exceeds f |x| / 2^16 by less than 1,
 * hw falls short of W z / 2 by at most 1/2).  For f, |x| < 2^23 and z <
 * 2^25, u = ((f >> 8) + 1)((|x| >> 8) + 1) >= f |x| / 2^16 (below 2^31)
 * and l = W (z >> 8) <= W z / 2^8 (below 2^32: W < 2^15), so
 * ceil((u + 2) / 2^7) <= l is enough; likewise y with H.  0 means not
 * shown (the exact test decides): points within about 1% of a side
 * plane, or out of those ranges. */
static int inside_sides(const stp_clip_volume *v, stp_vec3 p)
{
    const uint32_t lim = (uint32_t)1 << 23;
    uint32_t f = (uint32_t)v->focal, ax = stp_abs32(p.x), ay = stp_abs32(p.y), fs, zs;
    if ((f | ax | ay) >= lim || (uint32_t)p.z >= ((uint32_t)1 << 25))
        return 0; /* a negative focal or z too (as unsigned, at least 2^31) */
    fs = (f >> 8) + 1u;
    zs = (uint32_t)p.z >> 8;
    return ((fs * ((ax >> 8) + 1u) + 129u) >> 7) <= v->width * zs &&
           ((fs * ((ay >> 8) + 1u) + 129u) >> 7) <= v->height * zs;
}
#endif

unsigned stp_clip_outcode(const stp_clip_volume *v, stp_vec3 p)
{
#if STP_NARROW_FORMS
    if (!v->parallel && inside_sides(v, p))
        return p.z < v->near ? 1u : 0u; /* only the near plane can cut */
#endif
    return stp_clip_outcode_planes(v, p);
}

int stp_clip_polygon(const stp_clip_volume *v, stp_vec3 *a, stp_vec3 *b, stp_fix *sa,
                     stp_fix *sb, int n, stp_vec3 **result, stp_vec3 **spare, stp_fix **values)
{
    stp_vec3 *in = a, *out = b, *tmp;
    stp_fix *s_in = sa, *s_out = sb, *s_tmp;
    int plane, i, m;
    for (plane = 0; plane < 5 && n > 0; plane++) {
        /* each vertex's distance once: the edge's end's is the next
         * edge's start's, the first vertex's the last edge's end's */
        int64_t d_first = stp_clip_distance(v, plane, in[0]), dp = d_first, dq;
        m = 0;
        for (i = 0; i < n; i++, dp = dq) {
            int j = i + 1 == n ? 0 : i + 1;
            stp_vec3 p = in[i], q = in[j];
            dq = j == 0 ? d_first : stp_clip_distance(v, plane, q);
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
