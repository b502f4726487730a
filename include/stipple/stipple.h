/* SPDX-License-Identifier: MIT */
/*
 * stipple: fixed-point renderer of lit polygon scenes for bilevel, grey and
 * colour devices.  Include this for the whole public API.
 *
 * Naming rule: every public symbol starts with stp_ (types, functions) or
 * STP_ (macros, enumerators); stp_<module>_<verb> for functions of a module
 * (stp_fix_mul, stp_cell_bayer), stp_<verb> for the renderer's own calls
 * (stp_renderer_polygon, stp_renderer_render).  Private code lives in src/ and its headers are
 * not installed.
 */
#ifndef STIPPLE_STIPPLE_H
#define STIPPLE_STIPPLE_H

/* C linkage for everything below (each header also guards itself) */
#ifdef __cplusplus
extern "C" {
#endif

#include "stipple/config.h"
#include "stipple/config_guard.h"
#include "stipple/version.h"
#include "stipple/fix.h"
#include "stipple/shade.h"
#include "stipple/dither.h"
#include "stipple/diffuse.h"
#include "stipple/port.h"
#include "stipple/transform.h"
#include "stipple/render.h"
#include "stipple/mesh.h"
#include "stipple/direct.h"
#include "stipple/colour.h"
#include "stipple/raytrace.h"
#include "stipple/playback.h"
#include "stipple/playback_spans.h"

#ifdef __cplusplus
}
#endif

#endif
