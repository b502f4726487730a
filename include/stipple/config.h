/* SPDX-License-Identifier: MIT */
/*
 * stipple build-time configuration: the one place where every switch of the
 * core is defined, with its default.  A firmware build overrides them with
 * -D on the compiler line or by defining STP_CONFIG_HEADER to the name of a
 * header of its own, included first.  Numeric switches must be plain
 * decimal literals (config_guard.h pastes them into a symbol name).
 *
 * Twelve switches are for users (the first part below); each says what it
 * takes out and what that saves.  The sizes are measured on the defaults:
 * the code and constant data of the whole core (every C file of src/ built with
 * arm-none-eabi-gcc -mcpu=cortex-m0plus -mthumb -Os, text summed by
 * arm-none-eabi-size: 83 329 bytes), and the renderer object in RAM
 * (STP_RENDERER_BYTES, render.h).  A firmware links only what it calls, so
 * its own saving is at most the figure given.  The rest (the second part)
 * are internal: `stipple compile`, the tests and the benches set them;
 * they stay settable but are not a supported configuration.
 *
 * Switches marked [layout] change a struct layout or what a number means:
 * they are part of the compatibility tag (config_guard.h), and a library
 * and an application built with different values do not link.
 * tests/check_switches.sh builds the core with each switch flipped and
 * checks the object code changes, so a switch spelled differently here and
 * in the code cannot go unnoticed.
 */
#ifndef STIPPLE_CONFIG_H
#define STIPPLE_CONFIG_H

#ifdef STP_CONFIG_HEADER
#include STP_CONFIG_HEADER
#elif defined(ARDUINO)
/* The Arduino builder gives a library no -D of its own: the Arduino
 * library's configuration is stipple_config.h in its src/ folder. */
#include "stipple_config.h"
#endif
/* CMake's STP_CONFIG_HEADER option installs the header under this name and
 * passes -DSTP_USER_CONFIG=1 to the library and its consumers (stipple.pc,
 * stipple::core). */
#if defined(STP_USER_CONFIG) && STP_USER_CONFIG
#include "stipple/user_config.h"
#endif

/* ==== The user-facing switches (at most twelve) ==== */

/* [layout] Fractional bits of stp_fix (the core's one scalar type, a signed
 * Q format in 32 bits).  16 (default): range [-32768, 32768), step 1.5e-5.
 * 20: range [-2048, 2048), step 9.5e-7, for small scenes wanting precision.
 * 12: range [-524288, 524288), step 2.4e-4, for large coordinates.
 * Allowed: 12..20 (angles in degrees, up to 360, must fit).  Size: 12
 * saves 56 bytes of code. */
#ifndef STP_FIX_FRAC_BITS
#define STP_FIX_FRAC_BITS 16
#endif

/* [layout] Largest polygon vertex count accepted by the display file (after
 * clipping a polygon may gain up to five vertices; the scratch space is
 * sized for that).  Size: the renderer object holds 96 bytes (128 with
 * STP_WITH_EDGE_AA) per vertex slot: 160 -> 8 saves 19.5 KB of RAM and 24
 * bytes of code. */
#ifndef STP_MAX_POLYGON_VERTICES
#define STP_MAX_POLYGON_VERTICES 160
#endif

/* [layout] Number of point lights a segment can hold (seed: 1; (10.16):
 * several).  Size: 4 -> 1 saves 648 bytes of code and 3 x (48 + 112 with
 * STP_WITH_SHADOWS + 24 with the vertex cache) bytes of RAM. */
#ifndef STP_MAX_LIGHTS
#define STP_MAX_LIGHTS 4
#endif

/* [layout] Number of display-file segments alive at once.  Size: 16 -> 1
 * saves 424 bytes of code and 480 bytes of RAM. */
#ifndef STP_MAX_SEGMENTS
#define STP_MAX_SEGMENTS 16
#endif

/* [layout] 1: the specular term (D, G, F of Torrance-Sparrow) is compiled
 * in.  0 removes it: shading is ambient + diffuse only.  Saves 3 036 bytes
 * of code. */
#ifndef STP_WITH_SPECULAR
#define STP_WITH_SPECULAR 1
#endif

/* 1: the Z-buffer hidden-surface method is compiled in; 0 removes it (a
 * render asking for it returns STP_ERR_UNSUPPORTED).  Saves 4 560 bytes of
 * code. */
#ifndef STP_WITH_ZBUFFER
#define STP_WITH_ZBUFFER 1
#endif

/* 1: the painter's depth sort is compiled in; 0 removes it.  Saves 364
 * bytes of code.  With neither method, polygons are drawn in display-file
 * order (the caller's order), which is what a scene of non-overlapping
 * polygons needs. */
#ifndef STP_WITH_PAINTER
#define STP_WITH_PAINTER 1
#endif

/* [layout] 1: smooth (Gouraud) shading is compiled in: display-file
 * entries carry a per-vertex shade (20 bytes an entry) and spans
 * interpolate it.  0 removes it: flat polygons only, 16 bytes an entry.
 * Saves 2 024 bytes of code and 5 944 bytes of the renderer object
 * (sizeof on x86-64: the clipped polygon's per-vertex shades). */
#ifndef STP_WITH_GOURAUD
#define STP_WITH_GOURAUD 1
#endif

/* 1: colour shading (10.45) is compiled in: stp_renderer_set_colour shades
 * each polygon per channel for RGB888 output.  0 removes it (the call
 * returns STP_ERR_UNSUPPORTED).  Saves 396 bytes of code. */
#ifndef STP_WITH_COLOUR
#define STP_WITH_COLOUR 1
#endif

/* [layout] 1: shadows (docs/model.md section 5) by a shadow Z buffer per
 * light are compiled in: stp_renderer_set_shadow_map, depth rasterised into
 * the maps as polygons are entered, a per-pixel test at output; a render
 * with no map set draws the same pixels as a build without.  0 removes
 * them.  Saves 8 954 bytes of code and 112 bytes of RAM per light. */
#ifndef STP_WITH_SHADOWS
#define STP_WITH_SHADOWS 1
#endif

/* [layout] 1: edge anti-aliasing (stp_output.edge_aa) is compiled in: the
 * pixels just outside a polygon's edges take its shade blended with what
 * is under them in proportion to the part of them it covers
 * (docs/edge-aa.md).  Each edge and row crossing carries the edge's slope
 * and x extent.  0 removes it (a render asking for it returns
 * STP_ERR_UNSUPPORTED).  Saves 2 204 bytes of code and 32 bytes of RAM per
 * clipped-polygon vertex slot (5.3 KB at the default polygon size). */
#ifndef STP_WITH_EDGE_AA
#define STP_WITH_EDGE_AA 1
#endif

/* 1: the ray tracer (include/stipple/raytrace.h) is compiled in.  It lives
 * in its own object file, so a program that never calls it does not link
 * it even when it is on; 0 takes its code out of the library (stp_rt_create
 * then returns NULL).  Saves 14 516 bytes of code (of the library). */
#ifndef STP_WITH_RAYTRACE
#define STP_WITH_RAYTRACE 1
#endif

/* ==== Internal switches ====
 * Set by `stipple compile` (its generated scene_config.h), the tests and
 * the benches; not a supported configuration.  Sizes as above. */

/* Square root of stp_fix_sqrt, stp_fix_sqrt_wide and stp_vec3_unity: 0
 * (default) the exact floor; 1 the same reciprocal-root estimate without
 * the final correction, rounded down within 2^-29 relative.  Same size. */
#ifndef STP_SQRT_FAST
#define STP_SQRT_FAST 0
#endif

/* 1: direct drawing in its compact form, for the smallest chips: the
 * view's axes rounded to Q1.14 (view.c's stp_view_axes in its compact
 * variant) and composed with the model's rotation in Q1.14 (models at
 * scale 1 only: view.c's stp_view_compose_q14), each vertex placed by
 * 16 x 16-bit products; a face drawn when its projected vertices turn
 * counter-clockwise, shaded with its normal turned by that composite at
 * its vertices' mean by a product-based third (render_private.h's
 * stp_render_third); no clipping (a face across the picture's edge is
 * walked whole, a vertex nearer than hither refused).  The renderer in
 * these builds takes the same look-at, composite, normal rotation (for a
 * model at scale 1) and shading point, so every vertex lands at the same
 * view coordinates and device position; the same side test for a
 * triangle it does not clip (render_private.h's winding side); and a
 * guard band (project_private.h): it clips at the picture's sides only
 * beyond 512 pixels around it and walks the rest whole, clamping rows and
 * spans.  So the pictures equal stp_renderer_mesh's pixel for pixel in
 * both forms (tests/direct/test_direct_equal_compact).  0 (default):
 * direct drawing enters through the renderer's geometry and face stages
 * (view.c's composed transform, exact; the model frame's side test,
 * normal rotation and the exact vertex mean; the renderer's clipper).
 * The Arduino library and the lean direct
 * image set it: 0 costs the Uno's SpinningCube 13 582 bytes of flash (the
 * model frame's similarity test, normalisation and 64-bit division;
 * 64-bit side tests) and the lean Cortex-M0+ direct core 8 184 (14 130
 * against 5 946 B: the renderer's look-at, model frame, composed geometry
 * and clipper; docs/direct.md). */
#ifndef STP_DIRECT_COMPACT
#define STP_DIRECT_COMPACT 0
#endif

/* 1: the face shader's compact route: faces without the highlight (every
 * face with STP_WITH_SPECULAR 0) shaded from 16-bit directions, an exact
 * integer square root, the cosine by one division and each light's share
 * by one quotient, instead of the main route's reciprocal roots and
 * Newton steps.  Its error against the double reference is the cosine's,
 * about 1.1e-5, times the light's gain BRIGHT P |R| / (C + U): 2.2e-3 at
 * a gain of 200, where the main 32-bit route without the highlight (which
 * has no exact route to take over) has 3.1e-3 (tests/shade_fast:
 * test_shade_fast_compact; 1.4e-4 worst over its 200 000 random faces,
 * 7.8e-5 on the main 32-bit route).  The Arduino library sets it
 * (ports/arduino/src/stipple_config.h): about 1 500 bytes off the Uno's
 * SpinningCube. */
#ifndef STP_SHADE_COMPACT
#define STP_SHADE_COMPACT 0
#endif

/* [layout] Entries of the renderer's vertex cache (0 or a power of two up
 * to 4096): the view coordinates, outcode and device position of recently
 * entered points, keyed by their exact coordinates, so a vertex a mesh
 * enters several times is transformed and projected once.  44 bytes of RAM
 * an entry plus 2 per STP_MAX_POLYGON_VERTICES; 0 takes it out
 * (`stipple compile` does: a compiled scene is entered once; the face
 * stage's prepared shading stays in the renderer either way).  64 -> 0 saves 920 bytes of code.
 * The default is 64; 32 in builds of quadrilaterals and 16 in builds of
 * triangles (STP_MAX_POLYGON_VERTICES 4 and 3), the small targets'
 * builds, whose meshes go through mesh entry and its own scratch: the
 * cache is the largest part of their renderer object, then under 4 KiB
 * (tools/renderer_state.sh).  Measured in a triangle build: the
 * Cortex-M0+ renderer object 5 800 / 4 392 / 3 688 B with 64 / 32 / 16
 * entries, the bench torus entered polygon by polygon 0.802 / 0.817 /
 * 0.838 M instructions a frame (tools/bench/torus_bench.sh, 128x64). */
#ifndef STP_VERTEX_CACHE
#if STP_MAX_POLYGON_VERTICES <= 3
#define STP_VERTEX_CACHE 16
#elif STP_MAX_POLYGON_VERTICES <= 4
#define STP_VERTEX_CACHE 32
#else
#define STP_VERTEX_CACHE 64
#endif
#endif

/* Styles whose 1-bit pattern rows a frame keeps (a power of two; 8 bytes
 * of the frame's stack each; 0: rebuilt at every change of style).  16 ->
 * 0 saves 144 bytes of code. */
#ifndef STP_PATTERN_CACHE
#define STP_PATTERN_CACHE 16
#endif
#if STP_PATTERN_CACHE & (STP_PATTERN_CACHE - 1)
#error "STP_PATTERN_CACHE must be 0 or a power of two"
#endif

/* 1: transparency (docs/model.md section 5): a polygon blends with what the
 * band already holds, v = v_r + t v_t.  0 saves 876 bytes of code. */
#ifndef STP_WITH_TRANSPARENCY
#define STP_WITH_TRANSPARENCY 1
#endif

/* 1: line drawing (display-file opcodes move/line).  0 saves 1 028 bytes
 * of code. */
#ifndef STP_WITH_LINES
#define STP_WITH_LINES 1
#endif

/* 1: error diffusion (stp_output.diffusion) in the band renderer; 0: a
 * render asked for diffusion returns STP_ERR_UNSUPPORTED, and the diffusion
 * code is not linked.  0 saves 84 bytes of the core's own code. */
#ifndef STP_WITH_DIFFUSION
#define STP_WITH_DIFFUSION 1
#endif

/* 1: flat triangles take a scan converter of their own (raster.c
 * draw_triangle): about 40 % fewer render instructions on the 128x64
 * torus.  0: they take the general polygon path, which paints the same
 * pixels (stipple compile --static sets 0: size first); saves 1 804 bytes
 * of code. */
#ifndef STP_WITH_TRIANGLE_PATH
#define STP_WITH_TRIANGLE_PATH 1
#endif

/* 1: stp_renderer_mesh (mesh.h) enters a triangle its fast path does not
 * handle through stp_renderer_polygon; 0: such a triangle is
 * STP_ERR_UNSUPPORTED, and a firmware calling only stp_renderer_mesh does
 * not link the general entry path.  0 saves 68 bytes of the core's own
 * code (and the entry path in such a firmware). */
#ifndef STP_WITH_MESH_FALLBACK
#define STP_WITH_MESH_FALLBACK 1
#endif

/* 1: a render with no halftone cell (stp_output.cell NULL) builds the Bayer
 * 4x4 cell on the stack; 0: it returns STP_ERR_UNSUPPORTED (compiled scenes
 * carry their cell).  0 saves 8 bytes of code. */
#ifndef STP_WITH_DEFAULT_CELL
#define STP_WITH_DEFAULT_CELL 1
#endif

/* 1: the core's 64-bit quotients (the band renderer's, the look-at's, the
 * model frame's, the clipper's, direct drawing's) and the 32-bit ones the
 * band renderer and direct drawing take on cores with a 32-bit multiply
 * and no divide instruction come from small bit-serial loops (src/div64.c:
 * up to 64 steps a 64-bit quotient, 32 a 32-bit one) instead of the C library's routines
 * (about 1 KB for 64 bits and 500 bytes for 32 on ARMv6-M, not counted
 * below), and short edges' slopes come from the division instead of a
 * 512-byte table: a size-first choice for playback-only firmware (stipple
 * compile --static sets it) and the lean direct-drawing image.  Same
 * results.  1 saves 686 bytes of the core's own code (Cortex-M0+, -Os,
 * every file of src/). */
#ifndef STP_SMALL_DIVISION
#define STP_SMALL_DIVISION 0
#endif

/* 1: the panels' page layout is compiled in: the STP_PIXEL_MONO1_PAGES
 * pixel format (stipple/port.h) and direct drawing's STP_BAND_PAGES bands,
 * written by the one 1-bit run filler's page path.  0: a render, ray
 * trace or band in that layout returns STP_ERR_UNSUPPORTED, and the page
 * paths are not linked: a firmware whose panel takes rows (the
 * lm3s6965evb images of firmware/ set it).  Same pixels in rows.  0 saves
 * 994 bytes of the whole core's code (Cortex-M0+, -Os), 552 bytes of a
 * static scene's lm3s6965evb image and 704 of an on-chip one. */
#ifndef STP_WITH_PAGES
#define STP_WITH_PAGES 1
#endif

/* [layout] 1: a playback-only core (stipple compile --static): the renderer
 * object keeps only what stp_playback_create and stp_renderer_render use,
 * and the entry side (render.c, view.c, clip.c, transform.c, ...) must not
 * be built; firmware/CMakeLists.txt builds src/playback.c, raster.c,
 * dither.c, output.c, shade.c, status.c, frame_memory.c, div64.c, recip.c,
 * fix.c and edge_aa.c.  Needs STP_WITH_SHADOWS 0.  The renderer object:
 * 14 160 instead of 23 536 bytes on x86-64 (defaults, shadows off). */
#ifndef STP_PLAYBACK_ONLY
#define STP_PLAYBACK_ONLY 0
#endif

/* Deepest recursion the ray tracer accepts (stp_rt_set_recursion); each
 * level holds about 1.25 KB of stack on Cortex-M0+ (arm-none-eabi-gcc -Os
 * -fstack-usage: shade_hit 1120 B, secondary 120 B), and the deepest level
 * about 1 KB more while it searches: depth 4 needs about 6 KB.  Same code
 * size. */
#ifndef STP_RT_MAX_DEPTH
#define STP_RT_MAX_DEPTH 8
#endif

#if STP_FIX_FRAC_BITS < 12 || STP_FIX_FRAC_BITS > 20
#error "STP_FIX_FRAC_BITS must be within 12..20"
#endif
#if STP_MAX_POLYGON_VERTICES < 3 || STP_MAX_POLYGON_VERTICES > 4096
#error "STP_MAX_POLYGON_VERTICES must be within 3..4096"
#endif
#if STP_VERTEX_CACHE < 0 || STP_VERTEX_CACHE > 4096 || (STP_VERTEX_CACHE & (STP_VERTEX_CACHE - 1)) != 0
#error "STP_VERTEX_CACHE must be 0 or a power of two up to 4096"
#endif
#if STP_MAX_LIGHTS < 1 || STP_MAX_SEGMENTS < 1
#error "STP_MAX_LIGHTS and STP_MAX_SEGMENTS must be at least 1"
#endif
#if STP_WITH_SHADOWS && STP_MAX_LIGHTS > 32
#error "STP_WITH_SHADOWS keeps one bit per light: STP_MAX_LIGHTS must be at most 32"
#endif
#if STP_PLAYBACK_ONLY && STP_WITH_SHADOWS
#error "STP_PLAYBACK_ONLY needs STP_WITH_SHADOWS 0 (shadow maps are entered on the chip)"
#endif
#if !STP_WITH_ZBUFFER && !STP_WITH_PAINTER
/* Neither method: polygons are drawn in display-file order (the caller's
 * order), which is what a scene of non-overlapping polygons needs. */
#endif

#endif
