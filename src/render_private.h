/* Private: the renderer object and what render.c and raster.c share. */
#ifndef STIPPLE_RENDER_PRIVATE_H
#define STIPPLE_RENDER_PRIVATE_H

#include "stipple/render.h"
#include "fix_private.h"

#define STP_CLIP_VERTICES (STP_MAX_POLYGON_VERTICES + 5)

typedef struct stp_segment {
    int32_t id;
    uint32_t start, end; /* display-file entries [start, end) */
    uint8_t used, open, visible;
} stp_segment;

/* One edge of a polygon being scan-converted, oriented top to bottom.
 * Coordinates Q27.4; slope in Q4 x units per Q4 y unit, Q16.  Smooth
 * polygons: sa the shade at the top, shade_slope its change per Q4 y unit
 * with 16 more fractional bits. */
typedef struct stp_edge {
    int32_t xa, ya, yb;
    int64_t slope;
#if STP_WITH_GOURAUD
    int32_t sa;
    int64_t shade_slope;
#endif
} stp_edge;

/* A crossing of a row by an edge: x (Q27.4) and, for smooth polygons, the
 * shade there. */
typedef struct stp_crossing {
    int32_t x;
#if STP_WITH_GOURAUD
    int32_t shade;
#endif
} stp_crossing;

struct stp_renderer {
    stp_instr *df;
    uint32_t capacity, used;
    uint32_t width, height;

    stp_segment segments[STP_MAX_SEGMENTS];
    int open_segment; /* index into segments, -1 when none */

    /* view: orthonormal basis (world units), centre of projection */
    stp_vec3 from, right, up, forward;
    stp_projection projection;
    stp_fix hither;
    stp_fix focal; /* perspective: pixels per (x/z); parallel: pixels per unit */

    stp_lighting user_lighting;    /* what SET-LIGHT last said (world) */
    stp_lighting segment_lighting; /* COPY-LIGHT of the open segment (view) */
    stp_material material;
    int shading, fill_style, levels, backface_removal;
    int current_style;      /* polygon style last entered in the open segment, -1 none */
    int current_line_style; /* line style likewise */
    int colour;             /* colour shading on */
    stp_fix t_min, t_max, t_attenuation; /* transparency (t_attenuation:
                                            e^(-a d), 1 when none) */
    int t_power;
    stp_fix current_transmission; /* t last entered in the open segment */
    int32_t current_colour; /* colour last entered with current_style */
    stp_fix last_shade;

    int pen_valid;
    stp_vec3 pen; /* view coordinates */

    /* scratch: the clipper's two vertex lists and the scan converter's
     * edges; here rather than on the stack so a small MCU stack suffices */
    stp_vec3 clip_a[STP_CLIP_VERTICES];
    stp_vec3 clip_b[STP_CLIP_VERTICES];
#if STP_WITH_GOURAUD
    stp_fix shade_a[STP_CLIP_VERTICES]; /* per-vertex shades beside clip_a/b */
    stp_fix shade_b[STP_CLIP_VERTICES];
#endif
    stp_edge edges[STP_CLIP_VERTICES];
    stp_crossing crossings[STP_CLIP_VERTICES];
};

#endif
