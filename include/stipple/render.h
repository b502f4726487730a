/* SPDX-License-Identifier: MIT */
/*
 * The renderer: display file (docs/model.md section 7), viewing, hidden surfaces,
 * scan conversion and band output.
 *
 * One stp_renderer holds all state; there are no globals, so two renderers
 * (two displays, two test threads) never interfere.  All memory is the
 * caller's: the renderer object itself, the display file, the band buffer,
 * the Z buffer and the painter's sort array.
 *
 * Coordinates: world and view positions are stp_fix.  The view-plane system
 * is left-handed: x right, y up, z away from the eye along the line of sight.
 * Device coordinates in the display file are Q27.4 (STP_SUBPIXEL_BITS
 * fractional bits), origin at the top-left corner of the top-left pixel, y
 * down; pixel (i, j) has its centre at (i + 0.5, j + 0.5).  Polygons are
 * clipped to the picture, so they lie within [0, 16 width] x [0, 16
 * height]; in builds with STP_DIRECT_COMPACT (config.h) to a guard band of
 * up to 512 pixels around it, the raster clamping their rows and spans.
 *
 * Fill rule (written down, tested in tests/core/test_raster.c): a pixel belongs to
 * a polygon when its centre is inside by the even-odd rule; a centre exactly
 * on an edge belongs to the polygon on the edge's right (x) side and below
 * (top-left rule: spans cover x_left <= centre < x_right, edges cover
 * y_top <= centre < y_bottom).  So two polygons sharing an edge never both
 * draw a pixel and leave no gap between them.
 */
#ifndef STIPPLE_RENDER_H
#define STIPPLE_RENDER_H

#include <stddef.h>
#include <stdint.h>
#include "stipple/config.h"
#include "stipple/config_guard.h"
#include "stipple/diffuse.h"
#include "stipple/dither.h"
#include "stipple/fix.h"
#include "stipple/port.h"
#include "stipple/shade.h"
#include "stipple/transform.h"

#ifdef __cplusplus
extern "C" {
#endif

#define STP_SUBPIXEL_BITS 4

/* Errors: every function that can fail returns 0 or one of these (< 0). */
typedef enum stp_status {
    STP_OK = 0,
    STP_ERR_ARG = -1,          /* a NULL pointer or a value out of its range */
    STP_ERR_FULL = -2,         /* the display file or segment table is full */
    STP_ERR_NO_SEGMENT = -3,   /* unused since 0.3 (drawing opens an implicit
                                  segment); kept so old code compiles */
    STP_ERR_SEGMENT = -4,      /* no such segment, or one already open */
    STP_ERR_TOO_MANY_VERTICES = -5, /* polygon above STP_MAX_POLYGON_VERTICES */
    STP_ERR_DEGENERATE = -6,   /* polygon with fewer than 3 distinct vertices
                                  or no area: nothing entered */
    STP_ERR_MEMORY = -7,       /* a caller buffer too small for the request */
    STP_ERR_PORT = -8,         /* the port's flush returned an error */
    STP_ERR_VIEW = -9,         /* from == at, up parallel to the line of sight,
                                  or a field of view outside (0, 180) */
    STP_ERR_UNSUPPORTED = -10, /* a feature compiled out of this build */
    STP_ERR_RANGE = -11        /* a point entered lies beyond the range of view
                                  coordinates (stp_fix: within +-32767 of the
                                  eye along each view axis, after the model
                                  transform, which must not saturate either):
                                  nothing entered */
} stp_status;

/* Short English text for a status, for messages. */
const char *stp_status_text(int status);

/* Display-file opcodes (the seed's scheme). */
enum {
    STP_OP_MOVE = 1,        /* move the pen to (x, y, z) */
    STP_OP_LINE = 2,        /* draw a line from the pen to (x, y, z) */
    /* op >= 3: an op-sided polygon; this entry holds vertex 0 and the next
     * op-1 entries (opcode STP_OP_LINE) hold vertices 1..op-1. */
    STP_OP_SHADE = 0,       /* fill style for following polygons: x = style
                               index 1..levels, y = the shade (stp_fix),
                               z = colour: 0 for grey, else STP_COLOUR_FLAG |
                               (r-1) << 16 | (g-1) << 8 | (b-1), the style
                               index of each channel */
    STP_OP_LINE_STYLE = -1, /* style for following lines: x = style index */
    STP_OP_TRANSPARENCY = -2, /* transmission t of following polygons: x = t
                               (stp_fix in [0, 1]; 0 = opaque) */
    STP_OP_LIGHT_TERM = -3  /* shadow record of the NEXT polygon only
                               (STP_WITH_SHADOWS; entered only for polygons
                               that a shadow map can darken, see
                               stp_renderer_set_shadow_map).  The records stand just
                               before the polygon's header, after its
                               STP_OP_SHADE / STP_OP_TRANSPARENCY.  First
                               one with x = STP_LIGHT_TERM_GREY or
                               STP_LIGHT_TERM_COLOUR: y = the part of the
                               shade no map can take away, B.R plus the terms
                               of the lights without a map (stp_fix, before
                               BRIGHT), z = BRIGHT; then one per light j
                               with a map that reaches the face: x = j |
                               (the map's generation << 8), y = the light's
                               term P_j (R (N.L_j) + DGF/(N.E)) / (C + U_j)
                               (stp_fix, before BRIGHT), z = the depth bias
                               of the test, in map depth units */
};

/* x of the first STP_OP_LIGHT_TERM record: how a shadowed pixel is re-lit.
 * GREY: the flat grey style came from these terms and is recomputed from
 * them; COLOUR: a colour polygon, whose channels are scaled (render.h,
 * stp_renderer_set_shadow_map). */
#define STP_LIGHT_TERM_GREY (-1)
#define STP_LIGHT_TERM_COLOUR (-2)

#define STP_COLOUR_FLAG ((int32_t)0x01000000)

/* One display-file instruction: an opcode and a point.  x, y: device Q27.4;
 * z: depth key, larger = nearer (perspective: 2^30 * hither / z_view, in
 * (0, 2^30]; parallel: -z_view as stp_fix).  With STP_WITH_GOURAUD, shade is
 * the vertex's shade (stp_fix in [0, 1]) for smooth polygons and -1 for flat
 * ones and for lines. */
typedef struct stp_instr {
    int32_t op;
    int32_t x, y, z;
#if STP_WITH_GOURAUD
    int32_t shade;
#endif
} stp_instr;

typedef enum stp_projection {
    STP_PERSPECTIVE = 0,
    STP_PARALLEL = 1
} stp_projection;

/* A view (NFF's "v" entity).  fov_degrees: perspective only, the full angle
 * spanned by the shorter side of the device, in (0, 180).  window_half:
 * parallel only, half the shorter side of the window in world units, > 0.
 * hither: distance of the near clipping plane from the eye, > 0. */
typedef struct stp_view {
    stp_vec3 from, at, up;
    stp_fix fov_degrees;
    stp_fix window_half;
    stp_fix hither;
    stp_projection projection;
} stp_view;

typedef enum stp_hidden {
    STP_HIDDEN_NONE = 0,    /* display-file order */
    STP_HIDDEN_PAINTER = 1, /* depth sort, farthest first */
    STP_HIDDEN_ZBUFFER = 2  /* 16-bit Z buffer per band */
} stp_hidden;

typedef struct stp_renderer stp_renderer;

/* Bytes a renderer object needs (its alignment is that of int64_t). */
size_t stp_renderer_size(void);

/* stp_renderer_size() known at compile time, for static allocation without
 * a heap (render.c checks the bound when it is built):
 *   static stp_renderer_storage storage;
 *   r = stp_renderer_create(&storage, sizeof storage, ...);
 * By default an upper bound from the configuration; a build that knows the
 * exact size for its target and configuration defines it first (the
 * firmware build measures it: firmware/renderer_bytes.cmake).  The terms:
 * fixed fields, segments, lights (the lighting twice, shadow maps), the
 * vertex cache, the per-vertex scratch, and the face stage's prepared
 * shading (128 + 24 per light: 216 + 4 bytes with 4 lights on 32- and
 * 64-bit targets) and model frame (80). */
#ifndef STP_RENDERER_BYTES
#define STP_RENDERER_BYTES                                                                      \
    (1024u + 32u * STP_MAX_SEGMENTS + (48u + 112u * STP_WITH_SHADOWS) * STP_MAX_LIGHTS + 64u + 44u * STP_VERTEX_CACHE +          \
     (96u + 32u * STP_WITH_EDGE_AA) * (STP_MAX_POLYGON_VERTICES + 5u) +                      \
     128u + 24u * STP_MAX_LIGHTS + 80u)
#endif
typedef union stp_renderer_storage {
    int64_t align_integer;
    void *align_pointer;
    uint8_t bytes[STP_RENDERER_BYTES];
} stp_renderer_storage;

/* Create a renderer in mem (stp_renderer_size() bytes, aligned for int64_t
 * and pointers: an stp_renderer_storage, or memory from malloc) with a
 * display file of capacity instructions in display_file.  The device size is
 * fixed at creation (1..32767 each way) because entering an instruction
 * projects it onto the device.  Everything else starts at the seed's
 * defaults (INITIALIZE-10): light at (0,0,1), brightness 1, background 0,
 * C = 1, R = 1, n = 10, k = 10, shading off (on from the first
 * stp_renderer_set_light / stp_renderer_set_lighting), 16 levels, Bayer 4x4 cell, identity
 * gamma, no hidden-surface removal, back faces kept, view from (0,0,-1) at
 * the origin, 90 degrees, hither 2^-8.
 * Returns the handle, or NULL for a NULL or too small argument, or mem or
 * display_file not aligned for their types (checked here: a misaligned
 * object would fault later on a Cortex-M0).  Linked under a name that spells
 * the configuration (stipple/config_guard.h). */
stp_renderer *stp_renderer_create(void *mem, size_t mem_size, stp_instr *display_file,
                                  uint32_t capacity, uint32_t width, uint32_t height);

/* --- viewing and attributes (take effect for instructions entered after) */

/* Set the view.  Returns STP_OK or STP_ERR_VIEW / STP_ERR_ARG.  Ends an
 * implicit segment (see segments below). */
int stp_renderer_set_view(stp_renderer *r, const stp_view *view);

/* SET-LIGHT (10.8): one light at (x, y, z) world units with the given
 * brightness (>= 0) and background in [0, 1]; its power is 1 - background.
 * Replaces all lights, turns shading on (stp_renderer_set_shading(r, 0) after it
 * turns it off again) and ends an implicit segment.  STP_ERR_ARG for NULL or
 * a value out of range (nothing changed). */
int stp_renderer_set_light(stp_renderer *r, stp_vec3 position, stp_fix brightness, stp_fix background);

/* Set the whole lighting (several lights, positions in world units); turns
 * shading on and ends an implicit segment, as stp_renderer_set_light.
 * Returns STP_ERR_ARG for count outside 0..STP_MAX_LIGHTS. */
int stp_renderer_set_lighting(stp_renderer *r, const stp_lighting *lighting);

/* SET-OBJECT-SHADE (10.7) with the specular weight; see stp_material.
 * STP_ERR_ARG for NULL, reflectivity or a colour share outside [0, 1],
 * refraction, gloss or specular < 0 (nothing changed; 0 is read as shade.h
 * says). */
int stp_renderer_set_object_shade(stp_renderer *r, const stp_material *material);

/* SET-SHADING: on (non-zero) or off (0).  Off: polygons take the fill
 * style.  Off at creation; stp_renderer_set_light turns it on.  STP_ERR_ARG for a
 * NULL r. */
int stp_renderer_set_shading(stp_renderer *r, int on);

/* Fill style used while shading is off, as an INTENSITY index 1..levels
 * (default: levels, the lightest).  STP_ERR_ARG outside (nothing changed). */
int stp_renderer_set_fill_style(stp_renderer *r, int index);

/* Colour shading (10.45) on (1) or off (0, default): polygons entered while
 * it is on are shaded per channel with the material's and the lights'
 * colours; RGB888 output shows the colour, the other formats its luminance
 * (stp_shade_luminance).  Smooth polygons stay grey.  Returns
 * STP_ERR_UNSUPPORTED without STP_WITH_COLOUR. */
int stp_renderer_set_colour(stp_renderer *r, int on);

/* Transparency of the polygons entered next (docs/model.md section 5): each one's
 * transmission is t = (t_max - t_min) (N.E)^power + t_min (10.21), times
 * e^(-absorption * thickness) (10.18) where a thickness is known (pass 0 for
 * none), clamped to [0, 1].  At output the polygon's shade v_r is blended with
 * the shade v_t already in the band under it, recovered by the inverse of
 * INTENSITY: v = min(1, v_r + t v_t) (10.20).  On a 1-bit device a pixel's
 * inverse is 0 or 1, so the blend happens per pixel before the halftone.
 * Order: with the painter's algorithm polygons blend back to front; with the
 * Z buffer all opaque polygons are drawn first, then the transparent ones in
 * display order, depth-tested but not writing depth.  t_min = t_max = 0
 * (the default) makes polygons opaque.  power: 1..4 (the seed: 2 or 3).
 * Returns STP_ERR_ARG for values out of range, STP_ERR_UNSUPPORTED without
 * STP_WITH_TRANSPARENCY. */
int stp_renderer_set_transparency(stp_renderer *r, stp_fix t_min, stp_fix t_max, int power,
                         stp_fix absorption, stp_fix thickness);

/* Number of INTENSITY levels, 2..256 (default 16). */
int stp_renderer_set_levels(stp_renderer *r, int levels);

/* Back-face removal on (non-zero) or off (0, default: back faces are shaded
 * as if seen from their front, which suits open meshes).  STP_ERR_ARG for a
 * NULL r. */
int stp_renderer_set_backface_removal(stp_renderer *r, int on);

/* Pixel culling on (non-zero) or off (0, default) for the polygons entered
 * from now on: a flat triangle (stp_renderer_polygon, stp_renderer_mesh)
 * inside the view whose row spans hold no pixel centre, so that it draws
 * no pixel, is left out of the display file before it is shaded (a
 * 100 000-triangle mesh at 400x240 has tens of thousands of them).  The
 * pictures stay the same in every output but edge anti-aliasing, which
 * also draws partial pixels along such slivers: stp_renderer_render
 * refuses (STP_ERR_UNSUPPORTED) an output with edge_aa set while a visible
 * segment has lost a triangle to pixel culling (a display file played
 * back elsewhere, playback.h, carries no such mark).  STP_ERR_ARG for a
 * NULL r. */
int stp_renderer_set_pixel_cull(stp_renderer *r, int on);

/* --- segments (the display file's grouping)
 *
 * Drawing (stp_renderer_polygon, stp_renderer_move, ...) with no open segment opens an
 * implicit one, id -1 (or -2, -3, ... while those exist), which collects the
 * polygons until stp_segment_create, stp_segment_close, stp_renderer_set_view,
 * stp_renderer_set_light or stp_renderer_set_lighting ends it; the next drawing call opens
 * another (with the lighting of that moment: COPY-LIGHT).  So a program that
 * needs no segments never names one.  Implicit segments take slots of
 * STP_MAX_SEGMENTS and can be deleted or hidden by their ids like others. */

/* Create and open segment id (0..32767), ending an open implicit segment.
 * The current lighting is copied into it (COPY-LIGHT) with light positions
 * in view coordinates.  Errors: STP_ERR_ARG, STP_ERR_SEGMENT if a segment
 * is open or id exists, STP_ERR_FULL. */
int stp_segment_create(stp_renderer *r, int id);
/* Close the open segment (STP_ERR_SEGMENT if none). */
int stp_segment_close(stp_renderer *r);
/* Delete a closed segment and its instructions (the display file is
 * compacted).  STP_ERR_SEGMENT if there is no such closed segment. */
int stp_segment_delete(stp_renderer *r, int id);
/* Make a segment visible (1) or invisible (0). */
int stp_segment_visibility(stp_renderer *r, int id, int visible);

/* The model transform (transform.h) of the points entered next in the open
 * segment: every vertex, pen position and shadow caster given to stp_renderer_move,
 * stp_line and the stp_renderer_polygon calls is taken through it (and smooth
 * normals through its matrix) before the view, so a spinning model is
 * re-entered each frame from the same vertex array with a new transform.
 * Lights are not transformed (they belong to the view).  NULL sets the
 * identity; stp_segment_create starts every segment with the identity.
 * Cost: nine more multiplications per vertex while a transform other than
 * the identity is set.  Errors: STP_ERR_ARG (r NULL), STP_ERR_NO_SEGMENT. */
int stp_renderer_set_transform(stp_renderer *r, const stp_transform *t);

/* --- drawing (DISPLAY-FILE-ENTER: transform, shade, project, clip, store) */

/* Move the pen / draw a line to a world point.  Lines are clipped to the
 * hither plane and the window.  Errors: STP_ERR_ARG, STP_ERR_FULL (the
 * display file, or no segment slot for an implicit segment), STP_ERR_RANGE
 * (the point beyond the range of view coordinates; the pen stays). */
int stp_renderer_move(stp_renderer *r, stp_vec3 p);
int stp_renderer_line(stp_renderer *r, stp_vec3 p);

/* An n-sided polygon (3 <= n <= STP_MAX_POLYGON_VERTICES) in world units.
 * With shading on, it is shaded at its vertex average with its Newell
 * normal (SHADE-CHECK) and a STP_OP_SHADE instruction is entered before
 * it when the style changes.  A monochrome polygon is shaded by the face
 * shader every flat face takes (a triangle of stp_renderer_mesh too, on
 * the same normal: perspective, a model transform that is a rotation times
 * a uniform scale, no transparency or shadow map: then the Newell normal
 * of its points in model coordinates as Q1.14, and its back-face test on
 * that normal, and a triangle enters exactly as in a mesh, mesh.h); colour
 * shading takes the per-point shader.  A polygon wholly clipped away, a
 * back face with back-face removal on, or (on that same route) a triangle
 * inside the view whose vertices span no row centre (it would draw no
 * pixel) enters nothing and returns STP_OK.
 * Errors: STP_ERR_ARG, STP_ERR_TOO_MANY_VERTICES, STP_ERR_DEGENERATE (zero
 * Newell normal: repeated/collinear vertices, no area), STP_ERR_FULL
 * (nothing of the polygon is left in the display file; or no segment slot
 * for an implicit segment), STP_ERR_RANGE (a vertex beyond the range of
 * view coordinates: within +-32767 of the eye along each view axis). */
int stp_renderer_polygon(stp_renderer *r, const stp_vec3 *vertices, int n);

/* Smooth (Gouraud) polygons (docs/model.md section 4): like stp_renderer_polygon, but each
 * vertex gets its own shade and pixels interpolate it along edges and spans
 * before the halftone compares it with the cell (the combined scheme).
 * stp_renderer_polygon_smooth computes each vertex's shade with the full shading
 * equation from its own normal (world units, any length; a zero normal takes
 * the polygon's) at the vertex; with shading off the fill style's shade is
 * used everywhere.  stp_renderer_polygon_vertex_shades takes the shades (stp_fix,
 * clamped to [0, 1]) from the caller.  Errors as stp_renderer_polygon, and
 * STP_ERR_UNSUPPORTED without STP_WITH_GOURAUD. */
int stp_renderer_polygon_smooth(stp_renderer *r, const stp_vec3 *vertices, const stp_vec3 *normals, int n);
int stp_renderer_polygon_vertex_shades(stp_renderer *r, const stp_vec3 *vertices, const stp_fix *shades,
                              int n);

/* --- shadows (docs/model.md section 5: a shadow Z buffer per light)
 *
 * A shadow map is a 16-bit depth buffer in caller memory, a perspective
 * view of the scene from one light: its axis runs from the light towards
 * `target`, fov_degrees is the full angle across its shorter side (texels
 * are square), and its up is the view's up (its forward when the axis runs
 * along the view's up).  Texel (u, v), v down like the device, holds
 * depth[v * width + u]: 0 where no polygon covers its centre, else
 * q = floor(65535 near / z_l), clamped to 1..65535, of the polygon nearest
 * the light there (z_l: distance along the axis; larger q = nearer the
 * light; q is affine over a polygon's texels, so it is interpolated like
 * the device's depth key).  Texel centres follow the device's fill rule.
 *
 * Order of calls.  The display file holds device coordinates only, so the
 * maps are drawn as polygons are ENTERED: set the view and the lighting,
 * then the maps (the call clears its map), then create the segments and
 * enter every polygon, casters included, then stp_renderer_render.  Every polygon
 * entered while a map is set is drawn into it (stp_renderer_polygon,
 * stp_renderer_polygon_smooth, stp_renderer_polygon_vertex_shades; any segment, visible or
 * not; back faces, polygons outside the view and transparent ones too: a
 * map holds depth only, so transparent polygons cast full shadows).  A
 * polygon entered before its light's map was set (or set again) casts no
 * shadow into it and receives none from that light.  stp_renderer_set_view removes
 * every map: the maps' transform starts from view coordinates.  Deleting a
 * segment does not take its polygons out of the maps.  The maps must stay
 * valid until stp_renderer_render returns.
 *
 * Receivers: polygons entered with shading on by stp_renderer_polygon or
 * stp_renderer_polygon_smooth, in a segment whose copy of the light (COPY-LIGHT)
 * stands where the light stood when its map was set, get STP_OP_LIGHT_TERM
 * records for the lights with a map whose term is > 0.  Caller-given shades
 * (stp_renderer_polygon_vertex_shades) and shading off receive no shadow.  Lines
 * neither cast nor receive.
 *
 * The test, per pixel of a receiver and per light with a record: the pixel
 * centre's view point is recovered from its device position and the depth
 * key interpolated over the polygon (perspective: z = 2^30 hither / key;
 * parallel: z = -key), turned into the light's frame and projected into the
 * map.  A point outside the map's pyramid or nearer the light than `near`
 * is lit (the map must cover the receivers).  Otherwise, with q_p its own
 * depth (8 more fractional bits) and m the texel it falls in, it is hidden
 * from the light when m != 0 and m > q_p + b, where the bias
 *   b = 1 + |dq/du| + |dq/dv|  (rounded up, at most 65535)
 * is computed at entry from the receiver's own projection into the map (its
 * depth slope over one texel) and kept in its record.  Why: a texel holds
 * the depth at its centre, up to half a texel away from the point in u and
 * in v, so a lit surface's own texel can exceed q_p by half that slope plus
 * the floors: b covers twice that, so a lit surface never shadows itself
 * (shadow acne), at any angle to the light and any map resolution (tested
 * down to 2 degrees on 16 x 16 maps).  The price: an occluder less than b
 * nearer the light than the receiver does not shadow it, so a shadow can
 * start up to about a texel's footprint away from where its caster touches
 * the receiver, more for a receiver almost edge-on to the light (which gets
 * little of its light anyway).
 *
 * A hidden pixel loses that light's term:
 *   flat grey polygons: s = min(1, BRIGHT (ambient part + sum of the terms
 *   of the lights that reach it)) -> INTENSITY -> the usual output
 *   (halftone, grey, style, transparency blend), exactly;
 *   colour polygons (each channel) and smooth polygons (the interpolated
 *   shade): scaled by that shade over the polygon's full flat grey shade,
 *   an approximation (exact for one white light without highlight).
 * A pixel that every light reaches is painted as without shadows. */

/* Where a shadow map looks: see above.  near > 0 also sets the depth
 * resolution: q = 65535 near / z_l, so one unit of q is z_l^2 / (65535 near)
 * deep; points farther than 65535 near all get q = 1 (never hidden). */
typedef struct stp_shadow_view {
    stp_vec3 target;     /* world point on the map's axis */
    stp_fix fov_degrees; /* full angle across the shorter side, (0, 180) */
    stp_fix near;        /* distance of the near plane from the light, > 0 */
} stp_shadow_view;

/* Set (and clear) light `light`'s shadow map: depth holds count >=
 * width * height entries; width, height 1..32767.  The light's position is
 * the current lighting's (stp_renderer_set_light / stp_renderer_set_lighting before this
 * call).  view NULL: target = the view's look-at point, fov 90 degrees,
 * near = |target - light| / 16.  To cover a scene of bounding sphere
 * (c, radius) from a light at distance d > radius of c: target c,
 * fov = 2 asin(radius / d) and a margin, near a little under d - radius
 * (tools/shadows_setup.c does this).  Errors: STP_ERR_ARG (r or depth NULL,
 * light outside 0..count-1 of the current lighting, a size out of range),
 * STP_ERR_MEMORY (count < width * height), STP_ERR_VIEW (target at the
 * light, fov outside (0, 180), near <= 0), STP_ERR_UNSUPPORTED without
 * STP_WITH_SHADOWS. */
int stp_renderer_set_shadow_map(stp_renderer *r, int light, uint16_t *depth, size_t count, uint32_t width,
                       uint32_t height, const stp_shadow_view *view);

/* Forget light `light`'s map (polygons entered next neither cast into it nor
 * receive its shadow; records already entered are ignored).  STP_ERR_ARG
 * for a light outside 0..STP_MAX_LIGHTS-1; STP_OK without STP_WITH_SHADOWS. */
int stp_renderer_remove_shadow_map(stp_renderer *r, int light);

/* Instructions in use and capacity of the display file. */
uint32_t stp_renderer_display_file_used(const stp_renderer *r);

/* Polygons in visible segments (the size of the painter's sort array). */
uint32_t stp_renderer_polygon_count(const stp_renderer *r);

/* The shade the last stp_renderer_polygon call computed (for tests), or -1
 * when it shaded nothing: a back face removed, a polygon outside the view,
 * or a triangle between two row centres (it would draw no pixel, so it is
 * left out of the display file unshaded). */
stp_fix stp_renderer_last_shade(const stp_renderer *r);

/* --- output */

/* Everything about how the display file meets the device. */
typedef struct stp_output {
    stp_hidden hidden;
    const stp_cell *cell;            /* MONO1, MONO1_PAGES: halftone cell
                                        (NULL: Bayer 4x4) */
    const uint8_t *gamma;            /* levels entries, style index-1 -> 0..255;
                                        NULL: linear (index-1)*255/(levels-1) */
    const stp_style_table *styles;   /* STYLE8: codes; NULL: the index itself */
    stp_fix background;              /* shade of the empty frame, [0, 1] */
    const stp_fix *background_colour; /* RGB888: its colour (3 shades), or NULL */
    const stp_diffusion *diffusion;  /* MONO1, MONO1_PAGES: error diffusion
                                        instead of the
                                        cell (NULL: the cell).  The band is
                                        drawn as GREY8 and diffused row by
                                        row as it is flushed, so it needs
                                        band_rows * width bytes; the error
                                        rows carry across bands, so bands
                                        equal the whole frame. */
    int edge_aa;                     /* 1: anti-aliased polygon edges: the
                                        pixels just outside an opaque,
                                        unshadowed polygon's edges blend its
                                        shade with what is under them by the
                                        part of them it covers (a 1-bit port's
                                        band is then drawn as GREY8, as for
                                        diffusion, and thresholded by the
                                        cell as it is flushed); 0: off.
                                        Needs STP_WITH_EDGE_AA, else
                                        STP_ERR_UNSUPPORTED; the ray tracer
                                        ignores it. */
} stp_output;

/* Memory the caller lends to one stp_renderer_render call.
 *   band, band_size     pixel rows: band_rows * stp_row_bytes(format,
 *                       width) (GREY8 rows for a 1-bit port the output
 *                       diffuses or anti-aliases); STP_PIXEL_MONO1_PAGES:
 *                       (band_rows + 7) / 8 pages of width bytes
 *   band_rows           rows per band, 1..height; STP_PIXEL_MONO1_PAGES:
 *                       a multiple of 8, or the height (port.h)
 *   zbuf, zbuf_count    STP_HIDDEN_ZBUFFER: width * band_rows entries
 *   sort, sort_count    STP_HIDDEN_PAINTER: stp_renderer_polygon_count() entries
 *   setup, setup_count  optional (NULL, 0: none), STP_HIDDEN_ZBUFFER:
 *                       stp_renderer_polygon_count() entries; each polygon's depth
 *                       setup is then made once per frame, in the first
 *                       band it reaches, and later bands take it from
 *                       there rather than redoing it (the same pixels) */
typedef struct stp_sort_entry {
    uint32_t index;  /* display-file entry of the polygon */
    int32_t key;     /* depth key of its farthest vertex */
    int32_t style;   /* its fill style (or colour, for RGB888 output) */
    int32_t transmission; /* its t (0: opaque) */
} stp_sort_entry;
/* One polygon's depth setup kept across the bands of a frame (contents
 * private to the raster). */
typedef struct stp_polygon_setup {
    int64_t plane[3];
    int32_t centre[2];
} stp_polygon_setup;
typedef struct stp_frame_memory {
    uint8_t *band;
    size_t band_size;
    uint32_t band_rows;
    uint16_t *zbuf;
    size_t zbuf_count;
    stp_sort_entry *sort;
    size_t sort_count;
    stp_polygon_setup *setup;
    size_t setup_count;
} stp_frame_memory;

/* The default output: the Z buffer (without STP_WITH_ZBUFFER the painter's
 * sort, without that display-file order), the Bayer 4x4 cell, the linear
 * gamma, no style table, background 0 (black, OFF), no error diffusion, no edge
 * anti-aliasing.  STP_ERR_ARG for NULL. */
int stp_output_default(stp_output *output);

/* Bytes of frame memory for band_rows rows of port (hidden: the method
 * stp_renderer_render will use; polygons: stp_renderer_polygon_count(), for the painter's
 * sort), plus up to 3 bytes for aligning the start of a buffer.  0 for a
 * NULL port or an unknown format. */
size_t stp_frame_memory_bytes(const stp_port *port, stp_hidden hidden, uint32_t band_rows,
                              uint32_t polygons);

/* Lay out one caller buffer (any alignment, size bytes) as the frame memory
 * of a stp_renderer_render call for port and output (NULL: stp_output_default): the
 * painter's sort array first (stp_renderer_polygon_count(r) entries, so call it after
 * the last polygon), then for the Z buffer one 16-bit entry per pixel of a
 * band, then the band (of GREY8 rows for a 1-bit port the output diffuses or
 * anti-aliases), with as many rows as fit, at most port->height (for a
 * STP_PIXEL_MONO1_PAGES port whole pages of 8 rows, or the whole height).
 * More rows: fewer passes over the display file (the picture is the same).
 * Errors: STP_ERR_ARG (a NULL argument; r may be NULL unless the method is
 * the painter's; an unknown pixel format), STP_ERR_MEMORY (not even one row
 * fits; *memory then zeroed). */
int stp_frame_memory_split(stp_frame_memory *memory, const stp_renderer *r, const stp_port *port,
                           const stp_output *output, void *buffer, size_t size);

/* Interpret the display file and send the picture to the port, band by band
 * (the display file is re-read for each band; the result is the same pixel
 * for pixel whatever the band height).  The port's size must be the
 * renderer's.  output NULL: stp_output_default's.  Errors: STP_ERR_ARG
 * (also a STP_PIXEL_MONO1_PAGES port with band_rows neither a multiple of 8
 * nor the height),
 * STP_ERR_MEMORY (a buffer too small, a setup array given with fewer than
 * stp_renderer_polygon_count() entries),
 * STP_ERR_UNSUPPORTED (a hidden-surface method compiled out, or the page
 * layout: STP_WITH_PAGES; edge_aa of a display file that lost triangles
 * to pixel culling, stp_renderer_set_pixel_cull),
 * STP_ERR_PORT. */
int stp_renderer_render(stp_renderer *r, stp_port *port, const stp_output *output,
               const stp_frame_memory *memory);

#ifdef __cplusplus
}
#endif

/* the names before 0.3, for one release */
#include "stipple/deprecated.h"

#endif
