/* SPDX-License-Identifier: MIT */
/*
 * Host side: smooth shading over large polygons (issue 14, item 6).  A
 * smooth polygon takes its shade at its vertices only, so a floor whose
 * corners lie far from the light interpolates dark corner shades across
 * the bright middle (balls-s1's floor went dark).  Polygons whose longest
 * edge exceeds a quarter of the distance from their centroid to the
 * nearest light are split into triangles small enough (fan from vertex 0,
 * then each triangle into 4^k by a regular grid, k <= 6), with normals
 * interpolated and renormalised where the file gives them.
 */
#ifndef STIPPLE_TOOLS_SUBDIVIDE_H
#define STIPPLE_TOOLS_SUBDIVIDE_H

#include <stddef.h>
#include "render_scene.h"

/* out: a copy of scene whose large polygons are subdivided as above, for
 * the lights stp_tool_setup gives (materials, lights and primitives are
 * shared with scene, vertices, normals and polygons are new: free them
 * with stp_tool_subdivided_free).  Returns 1 when something was split, 0
 * when nothing needed it (out untouched), -1 with a message. */
int stp_tool_subdivide(const stp_scene *scene, const stp_tool_options *opt, stp_scene *out, char *err,
                       size_t err_size);
void stp_tool_subdivided_free(stp_scene *out);

#endif
