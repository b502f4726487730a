/* SPDX-License-Identifier: MIT */
/* Private: the renderer object (struct stp_renderer) and the records it
 * holds: display-file segments, the scan converter's edges and crossings,
 * shadow maps, vertex cache entries.  Types and macros only, no .c file of
 * its own: render.c (entry), raster.c (output), shadow.c, edge_aa.c and
 * playback.c include it for the layout; the stages whose types it holds
 * (clip_private.h, view_private.h, shade_fast_private.h) are below every
 * file that includes it. */
#ifndef STIPPLE_RENDERER_STATE_H
#define STIPPLE_RENDERER_STATE_H

#include "stipple/render.h"
#include "clip_private.h"
#include "view_private.h"
#include "shade_fast_private.h"
#include "arith_private.h" /* STP_WIDE_ARITH */

#define STP_CLIP_VERTICES (STP_MAX_POLYGON_VERTICES + 5)

typedef struct stp_segment {
    int32_t id;
    uint32_t start, end; /* display-file entries [start, end) */
    uint8_t used, open, visible;
    uint8_t pixel_culled; /* pixel culling (stp_renderer_set_pixel_cull)
                             dropped a triangle of it: no edge AA */
} stp_segment;

/* One edge of a polygon being scan-converted, oriented top to bottom
 * (stp_edge_setup).  Coordinates Q27.4: the edge covers row centres
 * ya <= yc < yb, starting at x = xa.  step: its change of x per row (16 Q4
 * y units) in Q4 x units with 16 fractional bits, 16 times the slope
 * trunc(2^16 (xb - xa) / (yb - ya)) (|step| < 2^40); acc: x at the row
 * centre being scanned with 16 fractional bits, xa 2^16 + (yc - ya) slope
 * (below 2^52 in magnitude: |yc - ya| < 2^20 and |slope| < 2^36), so
 * floor(acc / 2^16) is the crossing.  Smooth polygons: the shade sa at
 * the top, shade_step and shade_acc likewise with 16 more fractional bits. */
typedef struct stp_edge {
    int64_t step, acc; /* the 64-bit fields first: no padding */
#if STP_WITH_GOURAUD
    int64_t shade_step, shade_acc;
    int32_t sa;
#endif
    int32_t xa, ya, yb;
#if STP_WITH_EDGE_AA
    int32_t aa_slope, aa_lo, aa_hi; /* for the crossings (stp_crossing) */
#endif
} stp_edge;

/* A crossing of a row by an edge: x (Q27.4), for smooth polygons the shade
 * there, and with edge anti-aliasing compiled in its edge's slope and x
 * extent. */
typedef struct stp_crossing {
    int32_t x;
#if STP_WITH_GOURAUD
    int32_t shade;
#endif
#if STP_WITH_EDGE_AA
    /* the edge's slope (stp_edge_aa_slope) and x extent (Q4), for edge_aa.c */
    int32_t slope, x_lo, x_hi;
#endif
} stp_crossing;


#if STP_WITH_SHADOWS
/* A light's shadow map (render.h, stp_renderer_set_shadow_map).  The light's frame:
 * origin at the light, z along the map's axis, x right, y up (left-handed
 * like the view).  A view point p goes to the light's frame as
 * p_l = m p + t: m is the rotation (Q28: entries are cosines, |m| <= 1 + a
 * rounding), t the view's origin (the eye) in the light's frame (stp_fix). */
typedef struct stp_shadow_map {
    uint16_t *depth;     /* NULL: no map for this light */
    uint32_t width, height;
    uint32_t generation; /* 1..2^23-1, kept in the records (STP_OP_LIGHT_TERM) */
    int32_t m[3][3];
    stp_fix t[3];
    stp_vec3 light_view; /* the light in view coordinates when the map was set */
    stp_fix focal;       /* texels per unit of x_l / z_l, F fractional bits */
    stp_fix near;        /* > 0 */
    stp_clip_volume volume; /* the map's pyramid, for clip.c */
} stp_shadow_map;
#endif

#if STP_VERTEX_CACHE
/* One vertex cache entry (config.h, STP_VERTEX_CACHE): an entered point
 * (before the model transform), its view coordinates, its outcode and,
 * once known, its device position.  Valid while stamp equals the renderer's
 * cache_stamp (set_view, set_transform and segment_create change that). */
typedef struct stp_vertex_entry {
    stp_vec3 point, view;
    uint32_t stamp;
    int16_t code;           /* outcode (0..31) or STP_CODE_RANGE */
    uint16_t used_by;       /* the last polygon that took it (cache_polygon) */
    int32_t dx, dy, dz;     /* device position (project), when projected */
} stp_vertex_entry;
#define STP_CACHE_NOT_PROJECTED INT32_MIN /* dx of an entry not projected yet */
#define STP_CODE_RANGE 32    /* code of a saturated view point (STP_ERR_RANGE) */
#define STP_CACHE_NONE 0xFFFFu /* cached[i] of a vertex kept outside the cache */
#define STP_CACHE_HASH 0x9E3779B1u /* the cache hash's multiplier (cache_hash) */
#endif


/* The pattern rows raster.c's frames made (its use_style), kept across
 * frames on 64-bit hosts (STP_PATTERN_KEEP) for the cell they were made
 * for, copied here: a style's slot STP_PATTERN_CACHE as a frame's, with
 * the cell level (stp_output_level) it was made for; a later frame takes
 * those whose style still maps to that level under its cell alike (the
 * output, its cell and gamma table are each frame's arguments: compared,
 * not trusted).  width 0: nothing kept (stp_pattern_keep_forget).  Not on
 * 32-bit targets: RAM, and their frames' code stays as it is. */
#if STP_WIDE_ARITH && STP_PATTERN_CACHE > 0
#define STP_PATTERN_KEEP 1
#define STP_PATTERN_KEEP_TABLE 32 /* a cell's thresholds, up to 4 rows of 8 (8 % width == 0) */
typedef struct stp_pattern_keep {
    int32_t style[STP_PATTERN_CACHE]; /* -1: empty */
    uint8_t rows[STP_PATTERN_CACHE][4];
    uint8_t level[STP_PATTERN_CACHE];
    uint8_t kind, width, height;
    uint8_t table[STP_PATTERN_KEEP_TABLE]; /* the cell's first height rows of width thresholds */
} stp_pattern_keep;
#define stp_pattern_keep_forget(r) ((r)->kept_patterns.width = 0)
#else
#define STP_PATTERN_KEEP 0
#define stp_pattern_keep_forget(r) ((void)(r))
#endif

struct stp_renderer {
    stp_instr *df;
    uint32_t capacity, used;
    uint32_t width, height;

    int open_segment; /* index into segments, -1 when none */
    int fill_style, levels;
#if !STP_PLAYBACK_ONLY
    /* the fields a polygon's or a mesh's entry reads per face come first:
     * ARMv6-M loads and stores reach 124 bytes past the base with an
     * immediate offset (62 for halfwords), farther fields take one or two
     * instructions more each (the rest of the entry side's state below) */
#if STP_VERTEX_CACHE
    uint16_t cache_polygon; /* (the vertex cache, below) serial of the polygon being entered (wraps) */
    uint32_t cache_stamp;   /* >= 1 */
    uint32_t cache_hash;    /* STP_CACHE_HASH, set by stp_renderer_create */
#endif
    int shading, backface_removal;
    /* stp_renderer_set_pixel_cull: triangles reaching no pixel centre are
     * left out at entry (stp_render_centre_reached); the rows a triangle
     * it tests may span (STP_CENTRE_TEST_MAX), 0 when off */
    int pixel_cull;
    int current_style;      /* polygon style last entered in the open segment, -1 none */
    int current_line_style; /* line style likewise */
    int colour;             /* colour shading on */
    stp_fix current_transmission; /* t last entered in the open segment */
    int32_t current_colour; /* colour last entered with current_style */
    stp_fix last_shade;
    int fast_shade_valid;   /* (the face stage's shading constants, below) */
    int fast_shade_parallel;
    int frame_valid;        /* (the model frame, below) */
    /* a flat polygon's entry may take the model route (render.c's
     * model_route: frame valid and usable, no colour, no transparency,
     * no shadow map): set by model_route_decide, cleared with frame_valid,
     * by set_colour, set_transparency and a shadow map set (shadow.c) */
    int model_route_ok;
    int model_on;           /* 0: the model transform is the identity, skipped */
#endif
#if STP_WITH_SHADOWS
    uint32_t shadow_set;    /* bit j: shadow[j].depth != 0 */
#endif

    stp_segment segments[STP_MAX_SEGMENTS];

#if !STP_PLAYBACK_ONLY /* the entry side's state: playback.c sets none of it */
    /* view: orthonormal basis (world units), centre of projection */
    stp_vec3 from, right, up, forward;
    /* world_facing_near: from - 2^20 per coordinate, mod 2^32, and whether
     * |from| < 2^30 in each (then v - from is within (-2^31 - 2^30, 2^31 +
     * 2^30), so its residue mod 2^32 within 2^20 of 0 is the difference) */
    uint32_t near_bias_x, near_bias_y, near_bias_z;
    int near_ok;
    stp_view_transform to_view; /* world to view (view.c) */
    stp_projection projection;
    stp_fix hither;
    stp_fix focal; /* perspective: pixels per (x/z); parallel: pixels per unit */
    stp_clip_volume clip_volume; /* the view's, for clip.c */

    stp_lighting user_lighting;    /* what SET-LIGHT last said (world) */
    stp_lighting segment_lighting; /* COPY-LIGHT of the open segment (view) */
    stp_material material;
    stp_fix t_min, t_max, t_attenuation; /* transparency (t_attenuation:
                                            e^(-a d), 1 when none) */
    int t_power;
    /* the face stage's shading constants (stp_render_face_shader:
     * stp_shade_fast_prepare of segment_lighting, material and the eye at
     * the view origin, or the direction towards the eye of a parallel
     * view), prepared on the first shaded face after they change:
     * open_segment clears fast_shade_valid when the copied lighting differs
     * from the last segment's, set_object_shade when the material differs,
     * set_view when the projection changes; fast_shade_parallel: the
     * projection they were prepared for */
    stp_shade_fast fast_shade;
    /* the face stage's model frame (stp_render_model_frame), for the view
     * and model transform in force; frame_valid cleared with the vertex
     * cache (cache_forget) */
    stp_model_frame frame;

    int pen_valid;
    stp_vec3 pen; /* view coordinates */
    stp_transform model; /* of the open segment's points (stp_renderer_set_transform) */
    /* the geometry stage (view_private.h, geometry_stage_private.h) for
     * the open segment's points: STP_GEOMETRY_VIEW (no model transform:
     * point_view is to_view), STP_GEOMETRY_COMPOSED (point_view: model
     * then view, composed) or STP_GEOMETRY_TWO_STEPS (model, then
     * to_view); set with the view and the model transform
     * (stp_render_geometry_update) */
    int geometry;
    stp_view_transform point_view;

    /* scratch: the clipper's two vertex lists and the scan converter's
     * edges; here rather than on the stack so a small MCU stack suffices */
    stp_vec3 clip_a[STP_CLIP_VERTICES];
    stp_vec3 clip_b[STP_CLIP_VERTICES];
#if STP_WITH_GOURAUD
    stp_fix shade_a[STP_CLIP_VERTICES]; /* per-vertex shades beside clip_a/b */
    stp_fix shade_b[STP_CLIP_VERTICES];
#endif
#if STP_VERTEX_CACHE
    stp_vertex_entry cache[STP_VERTEX_CACHE];
    uint16_t cached[STP_MAX_POLYGON_VERTICES]; /* clip_a[i]'s entry in cache[] */
#endif
#endif /* !STP_PLAYBACK_ONLY */
    stp_edge edges[STP_CLIP_VERTICES];
    stp_crossing crossings[STP_CLIP_VERTICES];

#if STP_WITH_SHADOWS
    stp_shadow_map shadow[STP_MAX_LIGHTS];
    uint32_t shadow_generation; /* of the last map set */
    uint32_t shadow_record[STP_MAX_LIGHTS]; /* display-file entry of the
                                               polygon being entered's record
                                               for light j, or UINT32_MAX */
    stp_vec3 at; /* the view's look-at point (world) */
#endif
#if STP_PATTERN_KEEP
    stp_pattern_keep kept_patterns;
#endif
};

#endif
