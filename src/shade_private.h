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

#endif
