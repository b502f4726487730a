/* SPDX-License-Identifier: MIT */
/*
 * Host side: a loaded scene made fit for the fixed-point core before it is
 * rendered or ray-traced (used by stp_tool_render and stp_tool_rt_build):
 *   - units: a scene whose extent or coordinates the core's stp_fix cannot
 *     hold well is moved and scaled uniformly into its comfortable range
 *     (eye, look-at, lights, hither and the attenuation constant alike), so
 *     the picture does not depend on the file's units;
 *   - lights beyond the build's STP_MAX_LIGHTS are merged, the closest in
 *     direction first;
 *   - polygons above STP_MAX_POLYGON_VERTICES are split: a fan of pieces
 *     when convex, ear clipping into triangles otherwise; a quad whose
 *     outline crosses itself (a bow tie) becomes its two triangles;
 *   - a scene none of whose polygons has an area is refused.
 * See docs/robust-inputs.md.
 */
#ifndef STIPPLE_TOOLS_SCENE_PREPARE_H
#define STIPPLE_TOOLS_SCENE_PREPARE_H

#include <stddef.h>
#include "render_scene.h"
#include "scene.h"

/* Coordinates the core is given stay within +-STP_TOOL_COORD_LIMIT units
 * (a 32x margin below stp_fix's 2^15 at 16 fractional bits, for the
 * products and sums of the view transform and shading).  A scene is
 * rescaled when a coordinate (geometry, eye, look-at) lies beyond it or
 * when it spans less than STP_TOOL_EXTENT_MIN units (where stp_fix's step,
 * 2^-16, is coarse): moved so that the centre of its bounds is the origin
 * and scaled so that its extent (the bounds' half diagonal, or the eye's
 * distance from their centre when larger) is STP_TOOL_EXTENT_TARGET.  The
 * eye, look-at point, lights and hither move with it; the attenuation
 * constant C is then taken in the rescaled units, so every rescaled file
 * gives the core the same scene whatever its units.  A scene already in
 * range, or any with opt->keep_units, is left as it is (its C is in its
 * own units).  Lights still beyond
 * the limit are brought in along their direction from the centre to half
 * the limit (auto power keeps their light at the centre; raw power is
 * scaled to do the same). */
#define STP_TOOL_COORD_LIMIT 1024.0
#define STP_TOOL_EXTENT_MIN 0.125
#define STP_TOOL_EXTENT_TARGET 8.0

/* The most vertices one polygon may have: longer ones are refused ("L:
 * polygon N has V vertices; at most ...").  Splitting a polygon of this
 * many vertices takes under a second at worst (docs/robust-inputs.md,
 * "Long polygons"); the readers take up to 2^20. */
#define STP_TOOL_MAX_POLYGON_VERTICES 16384

typedef struct stp_tool_prepared {
    stp_scene scene;           /* the prepared copy (owned) */
    stp_tool_options opt;      /* the options with --light positions and the
                                  attenuation constant in the copy's units */
    /* per light of scene: how many of the file's lights it stands for, and
     * the factor on its power (raw power: the scale and pulled-in lights) */
    double light_weight[STP_MAX_LIGHTS];
    double power_factor[STP_MAX_LIGHTS];
    double scale;              /* copy = (file - offset) * scale */
    stp_scene_vec3 offset;
    size_t lights_in;          /* lights before merging */
    size_t polygons_split;     /* polygons of the file split into pieces */
    size_t *polygon_number;    /* per polygon of scene: see
                                  stp_tool_prepared_polygon_number (owned) */
} stp_tool_prepared;

/* Prepare scene for opt into *out.  Returns 0, or -1 with a message:
 * out of memory, an object that the scene's range leaves below the core's
 * resolution ("L: polygon N: ... beyond ..."), or with opt->keep_units (no
 * rescaling) a coordinate beyond stp_fix's +-32767 ("L: coordinate (x, y,
 * z) of polygon N beyond ...").  A message about line L starts with "L: "
 * (render_scene.h).  On success free with stp_tool_prepared_free. */
int stp_tool_prepare(const stp_scene *scene, const stp_tool_options *opt, stp_tool_prepared *out,
                     char *err, size_t err_size);
void stp_tool_prepared_free(stp_tool_prepared *p);

/* The number, from 1, of the file's polygon that polygon i of the prepared
 * copy comes from (pieces of a split polygon and a bow tie's two triangles
 * give their polygon's number; the polygons tessellating NFF's spheres and
 * cones are not counted among the file's), so a message's "polygon N" is
 * the file's N; 0 for a sphere's or cone's polygon. */
size_t stp_tool_prepared_polygon_number(const stp_tool_prepared *p, size_t i);

/* Split the polygon v[0..count-1] (count > max >= 3) into pieces of at most
 * max vertices that cover it exactly: a fan of pieces sharing v[0] when it
 * is convex (collinear vertices allowed), else triangles by ear clipping in
 * the plane of its Newell normal.  Each piece is written as indices into v:
 * piece_index gets all of them in order, piece_count the size of each.
 * Both arrays are malloc'ed by the call (free them).  Returns the number of
 * pieces, or -1 (out of memory, or a polygon with no area whose ears cannot
 * be found: then the fan is used). */
int stp_tool_split_polygon(const stp_scene_vec3 *v, int count, int max, int **piece_index,
                           int **piece_count);

/* A bow tie: a quad v[0..3] whose outline crosses itself, seen in the
 * plane of its largest corner triangle.  Returns 1 with *edge the first of
 * the two crossing edges (0: v0-v1 with v2-v3; 1: v1-v2 with v3-v0) and *t
 * the crossing's place along it (0..1); 0 for a simple quad.  Preparation
 * draws a bow tie as its two triangles either side of the crossing (the
 * parts an even-odd fill of its outline covers). */
int stp_tool_bow_tie(const stp_scene_vec3 *v, int *edge, double *t);

/* stp_tool_setup for a prepared scene: the light powers take the weights
 * and factors of p into account. */
int stp_tool_setup_prepared(const stp_tool_prepared *p, stp_view *view, stp_lighting *lighting,
                            char *err, size_t err_size);

/* stp_tool_render's polygon path for a prepared scene (prep->opt.raytrace
 * is ignored), for callers that prepare once and render several times:
 * preparing a prepared scene again would forget its merged lights'
 * weights. */
int stp_tool_render_prepared(const stp_tool_prepared *prep, stp_port *port,
                             stp_tool_stats *stats, char *err, size_t err_size);

#endif
