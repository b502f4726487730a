/* SPDX-License-Identifier: MIT */
/*
 * stipple build-time configuration: the one place where every switch of the
 * core is defined, with its default.  A firmware build overrides them with
 * -D on the compiler line or by defining STP_CONFIG_HEADER to the name of a
 * header of its own, included first.  Numeric switches must be plain
 * decimal literals (config_guard.h pastes them into a symbol name).
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

/* Fractional bits of stp_fix (the core's one scalar type, a signed Q format
 * in 32 bits).  16 (default): range [-32768, 32768), step 1.5e-5.
 * 20: range [-2048, 2048), step 9.5e-7, for small scenes wanting precision.
 * 12: range [-524288, 524288), step 2.4e-4, for large coordinates.
 * Allowed: 12..20 (angles in degrees, up to 360, must fit). */
#ifndef STP_FIX_FRAC_BITS
#define STP_FIX_FRAC_BITS 16
#endif

/* Square root of stp_fix_sqrt, stp_fix_sqrt_wide and stp_vec3_unity (the
 * view's and shadow maps' set-up, smooth vertex normals, the ray tracer;
 * polygon shading normalises through its own reciprocal square root,
 * fix_private.h, whatever this says):
 * 0 (default) exact: floor of the true root.
 * 1 fast: the same reciprocal-root estimate without the final correction,
 * rounded down within 2^-29 relative. */
#ifndef STP_SQRT_FAST
#define STP_SQRT_FAST 0
#endif

/* Largest polygon vertex count accepted by the display file (after clipping a
 * polygon may gain up to five vertices; the scratch space is sized for that).
 * The renderer object grows by 2 * (this + 5) * 12 bytes. */
#ifndef STP_MAX_POLYGON_VERTICES
#define STP_MAX_POLYGON_VERTICES 160
#endif

/* Entries of the renderer's vertex cache (0 or a power of two up to 4096).
 * A mesh enters each shared vertex several times (a closed triangle mesh
 * about six): the cache keeps the view coordinates, outcode and device
 * position of recently entered points, keyed by their exact coordinates,
 * so a repeated vertex is not transformed and projected again.  Each entry
 * costs 44 bytes of the renderer object, plus 2 bytes per
 * STP_MAX_POLYGON_VERTICES; 0 takes the cache out (`stipple compile`'s
 * headers do: a compiled scene is entered once), and with it the mesh
 * path's shading kept across calls (render_private.h). */
#ifndef STP_VERTEX_CACHE
#define STP_VERTEX_CACHE 64
#endif

/* Number of point lights a segment can hold (seed: 1; (10.16): several). */
#ifndef STP_MAX_LIGHTS
#define STP_MAX_LIGHTS 4
#endif

/* Number of display-file segments alive at once. */
#ifndef STP_MAX_SEGMENTS
#define STP_MAX_SEGMENTS 16
#endif

/* 1: the specular term (D, G, F of Torrance-Sparrow) is compiled in.
 * 0: shading is ambient + diffuse only; a scene without specular surfaces
 * saves the code and the work. */
#ifndef STP_WITH_SPECULAR
#define STP_WITH_SPECULAR 1
#endif

/* 1: the Z-buffer hidden-surface method is compiled in. */
#ifndef STP_WITH_ZBUFFER
#define STP_WITH_ZBUFFER 1
#endif

/* Styles whose 1-bit pattern rows a frame keeps (a power of two; 8 bytes
 * of the frame's stack each; 0: rebuilt at every change of style).  16:
 * every style of a 16-level frame keeps its own slot. */
#ifndef STP_PATTERN_CACHE
#define STP_PATTERN_CACHE 16
#endif
#if STP_PATTERN_CACHE & (STP_PATTERN_CACHE - 1)
#error "STP_PATTERN_CACHE must be 0 or a power of two"
#endif

/* 1: the painter's depth sort is compiled in. */
#ifndef STP_WITH_PAINTER
#define STP_WITH_PAINTER 1
#endif

/* 1: smooth (Gouraud) shading is compiled in: display-file entries carry a
 * per-vertex shade (4 more bytes each) and spans interpolate it.  0: flat
 * polygons only, the display file stays at 16 bytes an entry. */
#ifndef STP_WITH_GOURAUD
#define STP_WITH_GOURAUD 1
#endif

/* 1: colour shading (10.45) is compiled in: stp_renderer_set_colour shades each
 * polygon per channel for RGB888 output. */
#ifndef STP_WITH_COLOUR
#define STP_WITH_COLOUR 1
#endif

/* 1: transparency (docs/model.md section 5) is compiled in: a polygon blends with
 * what the band already holds, v = v_r + t v_t. */
#ifndef STP_WITH_TRANSPARENCY
#define STP_WITH_TRANSPARENCY 1
#endif

/* 1: shadows (docs/model.md section 5) by a shadow Z buffer per light are
 * compiled in: stp_renderer_set_shadow_map, depth rasterised into the maps as
 * polygons are entered, a per-pixel test at output.  The renderer object
 * grows by about 100 bytes per light; a render with no map set draws the
 * same pixels as a build without. */
#ifndef STP_WITH_SHADOWS
#define STP_WITH_SHADOWS 1
#endif

/* 1: line drawing (display-file opcodes move/line) is compiled in. */
#ifndef STP_WITH_LINES
#define STP_WITH_LINES 1
#endif

/* 1: error diffusion (stp_output.diffusion) is compiled into the band
 * renderer; 0: a render asked for diffusion returns STP_ERR_UNSUPPORTED, and
 * the diffusion code is not linked. */
#ifndef STP_WITH_DIFFUSION
#define STP_WITH_DIFFUSION 1
#endif

/* 1: edge anti-aliasing (stp_output.edge_aa) is compiled in: the pixels
 * just outside a polygon's edges take its shade blended with what is under
 * them in proportion to the part of them it covers (docs/edge-aa.md).  Each
 * edge and row crossing carries the edge's slope and x extent: 28 bytes of
 * the renderer object (x86-64) per clipped-polygon vertex slot, of which
 * there are STP_MAX_POLYGON_VERTICES + 5 (STP_RENDERER_BYTES counts 32).
 * 0: a render asked for it returns STP_ERR_UNSUPPORTED, and its code is
 * not linked. */
#ifndef STP_WITH_EDGE_AA
#define STP_WITH_EDGE_AA 1
#endif

/* 1: flat triangles take a scan converter of their own (two edges a row,
 * set up at the first row with pixels; raster.c draw_triangle): about 40 %
 * fewer render instructions on the 128x64 torus, about 1.5 KB more code on
 * ARMv6-M.  0: they take the general polygon path, which paints the same
 * pixels (stipple compile --static sets 0: size first). */
#ifndef STP_WITH_TRIANGLE_PATH
#define STP_WITH_TRIANGLE_PATH 1
#endif

/* 1: stp_renderer_mesh (mesh.h) enters a triangle its fast path does not
 * handle (one that needs clipping; every one under a non-similar model
 * transform, a parallel view, colour, transparency or shadow maps) through
 * stp_renderer_polygon; 0: such a triangle is STP_ERR_UNSUPPORTED, and a
 * firmware calling only stp_renderer_mesh does not link the general entry
 * path (a size-first choice for a spinning model kept inside the view). */
#ifndef STP_WITH_MESH_FALLBACK
#define STP_WITH_MESH_FALLBACK 1
#endif

/* 1: a render with no halftone cell (stp_output.cell NULL) builds the Bayer
 * 4x4 cell on the stack; 0: it returns STP_ERR_UNSUPPORTED, and the cell
 * construction code is not linked (compiled scenes carry their cell). */
#ifndef STP_WITH_DEFAULT_CELL
#define STP_WITH_DEFAULT_CELL 1
#endif

/* 1: the band renderer divides 64-bit numbers with a small bit-serial loop
 * (src/div64.c, tens of bytes, up to 64 steps a quotient) instead of the C
 * library's routines (about 1 KB on ARMv6-M): a size-first choice for
 * playback-only firmware (stipple compile --static sets it).  Same results. */
#ifndef STP_SMALL_DIVISION
#define STP_SMALL_DIVISION 0
#endif

/* 1: a playback-only core (stipple compile --static): the renderer object
 * keeps only what stp_playback_create and stp_renderer_render use, and the
 * entry side (render.c, view.c, clip.c, transform.c, ...) must not be
 * built; firmware/CMakeLists.txt builds src/playback.c, raster.c, dither.c,
 * output.c, shade.c, status.c, frame_memory.c, div64.c, recip.c, fix.c and
 * edge_aa.c.  Needs STP_WITH_SHADOWS 0. */
#ifndef STP_PLAYBACK_ONLY
#define STP_PLAYBACK_ONLY 0
#endif

/* 1: the ray tracer (include/stipple/raytrace.h) is compiled in.  It lives
 * in its own object file, so a program that never calls it does not link
 * it even when it is on; 0 takes its code out of the library
 * (stp_rt_create then returns NULL). */
#ifndef STP_WITH_RAYTRACE
#define STP_WITH_RAYTRACE 1
#endif

/* Deepest recursion the ray tracer accepts (stp_rt_set_recursion); each
 * level holds about 1.25 KB of stack on Cortex-M0+ (arm-none-eabi-gcc -Os
 * -fstack-usage: shade_hit 1120 B, secondary 120 B), and the deepest level
 * about 1 KB more while it searches: depth 4 needs about 6 KB. */
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
