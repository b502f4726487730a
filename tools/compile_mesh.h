/* SPDX-License-Identifier: MIT */
/*
 * Host side: a scene's polygons as one indexed triangle mesh for direct
 * drawing (`stipple compile MODEL --mesh`): a C header holding the shared
 * vertices (stp_fix), the triangles (vertex indices, fan-split polygons,
 * the file's winding kept), the prepared Q1.14 normals
 * (stp_mesh_prepare_normals) and an stp_mesh record, all in STP_MESH_ROM
 * (program memory on an AVR, plain const elsewhere).  The model is moved
 * so its bounding box's centre is the origin and scaled so its farthest
 * vertex is 1 unit away.
 */
#ifndef STIPPLE_TOOLS_COMPILE_MESH_H
#define STIPPLE_TOOLS_COMPILE_MESH_H

#include <stddef.h>
#include <stdio.h>

#include "scene.h"

/* Write scene's polygons as mesh `name` (a C identifier) to out; source
 * names the model in the header's comment.  Triangles whose normal is 0
 * once the vertices are in stp_fix are left out (their count is in the
 * comment).  Returns 0, or -1 with a message in err (no polygons, more
 * than 65535 vertices or triangles, every triangle degenerate, a bad
 * name). */
int stp_tool_compile_mesh(const stp_scene *scene, const char *name, const char *source,
                          FILE *out, char *err, size_t errlen);

#endif
