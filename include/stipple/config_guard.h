/* SPDX-License-Identifier: MIT */
/*
 * A library and an application built with different switches of
 * stipple/config.h disagree on struct layouts (stp_lighting holds
 * STP_MAX_LIGHTS lights, stp_instr has a shade with STP_WITH_GOURAUD) and on
 * what a stp_fix means (STP_FIX_FRAC_BITS).  So the functions that start
 * every use of the library, stp_renderer_create and stp_rt_create, are linked
 * under names that spell the configuration: an application compiled with
 * other switches than its library fails to link, naming the symbol it
 * wanted, e.g.
 *   undefined reference to `stp_renderer_create_cfg_f16_v160_l2_s16_d8_q0_111111111'
 * instead of drawing garbage.  Source code calls the plain names; the macros
 * below rename them.  The fields, in order: f STP_FIX_FRAC_BITS,
 * v STP_MAX_POLYGON_VERTICES, l STP_MAX_LIGHTS, s STP_MAX_SEGMENTS,
 * d STP_RT_MAX_DEPTH, q STP_SQRT_FAST, then STP_WITH_ SPECULAR, ZBUFFER,
 * PAINTER, GOURAUD, COLOUR, TRANSPARENCY, SHADOWS, LINES, RAYTRACE.
 * (Numeric switches must be decimal literals, as config.h says.)
 */
#ifndef STIPPLE_CONFIG_GUARD_H
#define STIPPLE_CONFIG_GUARD_H

#include "stipple/config.h"

#ifdef __cplusplus
extern "C" {
#endif

#define STP_CONFIG_PASTE_(name, f, v, l, s, d, q, w1, w2, w3, w4, w5, w6, w7, w8, w9)              \
    name##_cfg_f##f##_v##v##_l##l##_s##s##_d##d##_q##q##_##w1##w2##w3##w4##w5##w6##w7##w8##w9
#define STP_CONFIG_PASTE(name, f, v, l, s, d, q, w1, w2, w3, w4, w5, w6, w7, w8, w9)               \
    STP_CONFIG_PASTE_(name, f, v, l, s, d, q, w1, w2, w3, w4, w5, w6, w7, w8, w9)
/* name as linked in this configuration */
#define STP_CONFIG_SYMBOL(name)                                                                    \
    STP_CONFIG_PASTE(name, STP_FIX_FRAC_BITS, STP_MAX_POLYGON_VERTICES, STP_MAX_LIGHTS,            \
                     STP_MAX_SEGMENTS, STP_RT_MAX_DEPTH, STP_SQRT_FAST, STP_WITH_SPECULAR,         \
                     STP_WITH_ZBUFFER, STP_WITH_PAINTER, STP_WITH_GOURAUD, STP_WITH_COLOUR,        \
                     STP_WITH_TRANSPARENCY, STP_WITH_SHADOWS, STP_WITH_LINES, STP_WITH_RAYTRACE)

#define stp_renderer_create STP_CONFIG_SYMBOL(stp_renderer_create)
#define stp_rt_create STP_CONFIG_SYMBOL(stp_rt_create)

#ifdef __cplusplus
}
#endif

#endif
