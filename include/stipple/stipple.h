/* SPDX-License-Identifier: MIT */
/*
 * stipple: fixed-point renderer of lit polygon scenes for bilevel, grey and
 * colour devices.  Include this for the whole public API.
 *
 * What do I want -> which calls (in order; the header to read first):
 *
 *   A scene file (NFF, OBJ, OFF, PLY) drawn on a Linux box
 *       -> the stipple command: `stipple render scene.nff -o out.png`
 *          (tools/, `stipple --help`); from C: stp_renderer_create,
 *          stp_renderer_set_view, stp_renderer_set_lighting, one
 *          stp_renderer_polygon per face, stp_renderer_render into an
 *          stp_posix_frame (ports/posix/stp_posix.h), stp_posix_write.
 *          render.h.
 *   An animated mesh on a microcontroller
 *       -> stp_renderer_create once (static stp_renderer_storage, no heap),
 *          then per frame stp_renderer_set_transform, stp_renderer_mesh
 *          (mesh.h; normals and bounds once with stp_mesh_prepare_normals
 *          and stp_mesh_prepare_bounds) and
 *          stp_renderer_render band by band into the display's page buffer
 *          (stp_port, port.h).  The smallest image: direct drawing,
 *          stp_direct_frame_project (then stp_direct_frame_sort, or
 *          stp_direct_frame_depth for the renderer's Z buffer, for a
 *          model that is not convex) and stp_direct_draw_band per band
 *          (direct.h).
 *   A fixed picture from flash
 *       -> `stipple compile --static` writes the display file as C:
 *          stp_playback_create, stp_renderer_render (playback.h); or
 *          `stipple compile --spans` writes the visible spans:
 *          stp_spans_start, stp_spans_draw (playback_spans.h), no renderer
 *          on the chip.
 *   Ray tracing (spheres, cones, polygons; shadows, reflection,
 *   refraction)
 *       -> stp_rt_create, stp_rt_set_view, stp_rt_set_lighting,
 *          stp_rt_set_materials, stp_rt_sphere / stp_rt_cone /
 *          stp_rt_polygon, stp_rt_build, stp_rt_render (raytrace.h).
 *
 * Everything else is a building block of these: fixed-point arithmetic
 * (fix.h), shading (shade.h), halftones and error diffusion (dither.h,
 * diffuse.h), colour models (colour.h), transforms (transform.h).  Build
 * switches: config.h; the compatibility tag of a build: config_guard.h.
 *
 * Naming rule: every public symbol starts with stp_ (types, functions) or
 * STP_ (macros, enumerators); stp_<module>_<verb> for functions of a module
 * (stp_fix_mul, stp_cell_bayer, stp_renderer_polygon, stp_rt_render).
 * Private code lives in src/ and its headers are not installed.
 * scripts/api_count.sh counts the public functions.
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
