/* SPDX-License-Identifier: MIT */
/*
 * The compatibility tag.  A library and an application built with different
 * switches of stipple/config.h can disagree on struct layouts (stp_lighting
 * holds STP_MAX_LIGHTS lights, a display-file entry stp_instr is 16 or 20
 * bytes by STP_WITH_GOURAUD, the renderer object's scratch grows with
 * STP_MAX_POLYGON_VERTICES) and on what a stp_fix means (STP_FIX_FRAC_BITS).
 * Every switch that does is part of one tag, STP_CONFIG_TAG, spelled from
 * the switches' values, in this order:
 *
 *   f STP_FIX_FRAC_BITS, v STP_MAX_POLYGON_VERTICES, l STP_MAX_LIGHTS,
 *   s STP_MAX_SEGMENTS, c STP_VERTEX_CACHE, then one digit each for
 *   STP_WITH_SPECULAR, STP_WITH_GOURAUD, STP_WITH_SHADOWS, STP_WITH_EDGE_AA
 *   and STP_PLAYBACK_ONLY,
 *
 * e.g. cfg_f16_v160_l4_s16_c64_11110 for the defaults.  The other switches
 * change code only: a call the library was built without returns
 * STP_ERR_UNSUPPORTED.
 *
 * Every constructor, the call that starts each use of the library, is
 * checked against the tag: it is linked under a name that carries it
 * (stp_renderer_create, stp_playback_create, stp_spans_start,
 * stp_rt_create, stp_direct_frame_project, stp_direct_frame_project_lit),
 * so an application compiled with other layout switches than its library
 * fails to link, naming the symbol it wanted, e.g.
 *   undefined reference to `stp_playback_create_cfg_f16_v160_l4_s16_c64_10110'
 * instead of reading 20-byte entries as 16-byte ones.  Source code calls the
 * plain names; the macros below rename them (config.h includes this
 * header, so every header of the library sees them).  Numeric switches must
 * be decimal literals, as config.h says.
 */
#ifndef STIPPLE_CONFIG_GUARD_H
#define STIPPLE_CONFIG_GUARD_H

#include "stipple/config.h"

/* Macros only; the guard keeps the rule every public header follows. */
#ifdef __cplusplus
extern "C" {
#endif

#define STP_CONFIG_PASTE_(name, f, v, l, s, c, w1, w2, w3, w4, w5)                                  \
    name##_cfg_f##f##_v##v##_l##l##_s##s##_c##c##_##w1##w2##w3##w4##w5
#define STP_CONFIG_PASTE(name, f, v, l, s, c, w1, w2, w3, w4, w5)                                   \
    STP_CONFIG_PASTE_(name, f, v, l, s, c, w1, w2, w3, w4, w5)
/* name carrying the tag of this configuration */
#define STP_CONFIG_SYMBOL(name)                                                                    \
    STP_CONFIG_PASTE(name, STP_FIX_FRAC_BITS, STP_MAX_POLYGON_VERTICES, STP_MAX_LIGHTS,            \
                     STP_MAX_SEGMENTS, STP_VERTEX_CACHE, STP_WITH_SPECULAR, STP_WITH_GOURAUD,      \
                     STP_WITH_SHADOWS, STP_WITH_EDGE_AA, STP_PLAYBACK_ONLY)

#define STP_CONFIG_STRING_(x) #x
#define STP_CONFIG_STRING(x) STP_CONFIG_STRING_(x)
/* The tag as a string constant, "stp_cfg_f16_v160_l4_s16_c64_11110" for
 * the defaults: for a firmware's banner or a tool's --version. */
#define STP_CONFIG_TAG STP_CONFIG_STRING(STP_CONFIG_SYMBOL(stp))

/* The constructors, checked against the tag at link time. */
#define stp_renderer_create STP_CONFIG_SYMBOL(stp_renderer_create)
#define stp_playback_create STP_CONFIG_SYMBOL(stp_playback_create)
#define stp_spans_start STP_CONFIG_SYMBOL(stp_spans_start)
#define stp_rt_create STP_CONFIG_SYMBOL(stp_rt_create)
#define stp_direct_frame_project STP_CONFIG_SYMBOL(stp_direct_frame_project)
#define stp_direct_frame_project_lit STP_CONFIG_SYMBOL(stp_direct_frame_project_lit)

#ifdef __cplusplus
}
#endif

#endif
