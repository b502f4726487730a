/* SPDX-License-Identifier: MIT */
/* Private: MAKE-SHADE on STP_UNIT directions, for the polygon entry path,
 * which has its unit normal and E in that format already. */
#ifndef STIPPLE_SHADE_PRIVATE_H
#define STIPPLE_SHADE_PRIVATE_H

#include "stipple/shade.h"
#include "fix_private.h"

/* stp_shade_point with the normal and the direction towards the eye as
 * STP_UNIT vectors (fix_private.h) and their cosine n_dot_e = N.E
 * (STP_UNIT; <= 0 gives the ambient share only). */
stp_fix stp_shade_unit(const stp_lighting *lighting, const stp_material *material,
                       stp_unit3 normal, stp_vec3 point, stp_unit3 eye_dir, int32_t n_dot_e);


/* stp_intensity_index (shade.h) inline, for the mesh path's per-face
 * step: INT(s (N - 1) + 1) with s clamped to [0, 1] and N to 2..256;
 * s (N - 1) <= 2^F 255 < 2^28 (F <= 20), so 32 bits hold it.  In two
 * parts, so that a caller entering many faces finds N - 1 once. */
STP_HOT_INLINE int32_t stp_intensity_steps(int levels)
{
    return levels < 2 ? 1 : (levels > 256 ? 255 : (int32_t)levels - 1);
}

/* the index of a shade already in [0, 1]: a face shader's
 * (stp_shade_fast_face and its ambient share are, shade_fast_private.h),
 * whose clamp would only cost (the mesh face loop's) */
STP_HOT_INLINE int stp_intensity_index_unit(stp_fix shade, int32_t steps)
{
    return (int)((shade * steps) >> STP_FIX_FRAC_BITS) + 1;
}

STP_HOT_INLINE int stp_intensity_index_steps(stp_fix shade, int32_t steps)
{
    return stp_intensity_index_unit(shade < 0 ? 0 : (shade > STP_FIX_ONE ? STP_FIX_ONE : shade), steps);
}

STP_HOT_INLINE int stp_intensity_index_inline(stp_fix shade, int levels)
{
    return stp_intensity_index_steps(shade, stp_intensity_steps(levels));
}

#endif
