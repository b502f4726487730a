/* SPDX-License-Identifier: MIT */
/*
 * stipple: fixed-point renderer of lit polygon scenes for bilevel, grey and
 * colour devices.  Include this for the whole public API.
 *
 * Naming rule: every public symbol starts with stp_ (types, functions) or
 * STP_ (macros, enumerators); functions are module first,
 * stp_<module>_<action>, the module being what they act on: stp_fix_mul,
 * stp_cell_bayer, stp_renderer_polygon and stp_renderer_render (the polygon
 * renderer, stp_renderer), stp_rt_polygon and stp_rt_render (the ray
 * tracer), stp_segment_create, stp_frame_memory_split.  The renderer's
 * names before 0.3 are macros in stipple/deprecated.h for one release.
 * Private code lives in src/ and its headers are not installed.
 */
#ifndef STIPPLE_STIPPLE_H
#define STIPPLE_STIPPLE_H

#include "stipple/config.h"
#include "stipple/config_guard.h"
#include "stipple/version.h"
#include "stipple/fix.h"
#include "stipple/shade.h"
#include "stipple/dither.h"
#include "stipple/port.h"
#include "stipple/render.h"
#include "stipple/colour.h"
#include "stipple/raytrace.h"

#endif
