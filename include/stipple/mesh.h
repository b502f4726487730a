/* SPDX-License-Identifier: MIT */
/*
 * Indexed triangle meshes entered in one call (issue 11): a model animated
 * by re-entering it every frame pays per frame only for what changes —
 * each vertex transformed and projected at most once, the back-face test
 * and the face's normal taken from normals prepared once (host or chip),
 * no per-face normal construction or normalisation.
 *
 * The mesh lives in the caller's memory (all of it may be const, in flash).
 * stp_renderer_mesh enters every triangle into the open segment exactly as
 * stp_renderer_polygon enters its three vertices: both go through one face
 * stage (src/render_private.h) - the back-face test on the Q1.14 model
 * normal (stp_mesh_prepare_normals' arithmetic, which stp_renderer_polygon
 * applies to the points it is given), the normal turned into view
 * coordinates, the face shader (the seed's equation in 32-bit arithmetic,
 * the same on every target; within 0.0025 of a double-precision reference
 * on the tests' torus: tests/mesh), the same display-file records
 * (STP_OP_SHADE when the style changes, device coordinates, depth keys),
 * the segment's model transform applied, back-face removal honoured.  With
 * normals from stp_mesh_prepare_normals the display file and the picture
 * are identical to triangle-by-triangle entry (tests/mesh/
 * test_entry_identical).  The shader is prepared once and kept in the
 * renderer until the segment's lighting (in view coordinates), the
 * material or the projection changes.
 *
 * What the fast path does not handle goes, triangle by triangle, through
 * stp_renderer_polygon (the fallback): a triangle that crosses or touches
 * the view volume's boundary (it needs clipping), and every triangle when
 * the mesh has no prepared normals, the model transform is not a rotation
 * with a uniform scale and a translation, the projection is parallel,
 * colour shading, transparency or a shadow map is on.  With
 * STP_WITH_MESH_FALLBACK 0 (config.h) the fallback is not linked and such
 * a triangle makes stp_renderer_mesh return STP_ERR_UNSUPPORTED instead.
 */
#ifndef STIPPLE_MESH_H
#define STIPPLE_MESH_H

#include <stddef.h>
#include <stdint.h>

#include "stipple/render.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Q1.14 unit normal components: 1.0 is STP_MESH_NORMAL_ONE. */
#define STP_MESH_NORMAL_ONE 16384

/* The bounds of a mesh's vertices, found once by stp_mesh_prepare_bounds
 * (host or chip) for as long as the vertices stay as they are - a model
 * moved or spun by its model transform keeps them - so that
 * stp_renderer_mesh does not pass over every vertex each call to find
 * them (the 500-vertex torus: about 10 000 instructions a frame on an
 * x86-64 host).  lo, hi: the box of every vertex, model units; reach2:
 * the largest squared distance of a vertex from the box's centre, in
 * stp_fix units squared (model units squared times 2^(2 STP_FIX_FRAC_BITS);
 * a bound of it, at most a few 2^-15 of the box's widest side larger,
 * where 64-bit products are library calls), for the proof that a spinning
 * model stays inside the view. */
typedef struct stp_mesh_bounds {
    stp_vec3 lo, hi;
    uint64_t reach2;
} stp_mesh_bounds;

/* An indexed triangle mesh.  vertices: vertex_count points, model units
 * (stp_fix); triangles: 3 * triangle_count indices below vertex_count,
 * each triangle wound counter-clockwise seen from outside (right-handed
 * world: (v1 - v0) x (v2 - v0) points out); normals: NULL, or
 * 3 * triangle_count Q1.14 components (x, y, z of each triangle's unit
 * outward normal in model coordinates, stp_mesh_prepare_normals); bounds:
 * NULL (found by each stp_renderer_mesh call), or stp_mesh_prepare_bounds'
 * for exactly these vertices.  Bounds that do not hold every vertex are a
 * caller error as a short scratch array is, with undefined results:
 * stp_renderer_mesh trusts them to skip clipping and saturation, so a
 * vertex outside the view may be projected unclipped (behind the eye: a
 * division by a depth of 0 or less).  Re-prepare after changing vertices,
 * or leave bounds NULL for vertices that change every frame. */
typedef struct stp_mesh {
    const stp_vec3 *vertices;
    const uint16_t *triangles;
    const int16_t *normals;
    uint16_t vertex_count;
    uint16_t triangle_count;
    const stp_mesh_bounds *bounds;
} stp_mesh;

/* Per-vertex scratch of stp_renderer_mesh (caller memory, one per mesh
 * vertex; its content is private and rewritten by every call):
 * sizeof(stp_mesh_vertex) bytes per vertex, 28 where int32_t has no
 * padding (every target stipple builds for). */
typedef struct stp_mesh_vertex {
    stp_vec3 view;            /* view coordinates, once transformed */
    int32_t dx, dy, dz;       /* device position and depth key, once projected */
    int32_t state;            /* private */
} stp_mesh_vertex;

/* The unit outward normal of every triangle of mesh (its normals field is
 * ignored), into normals[3 * i .. 3 * i + 2] as Q1.14 (|component| <= 2^14,
 * length 1 within 2^-13).  Exact cross products of the stp_fix vertices
 * (64-bit), normalised once.
 * Errors: STP_ERR_ARG (mesh, its arrays or normals NULL, an index not below
 * vertex_count: *bad_triangle is that triangle), STP_ERR_DEGENERATE (a
 * triangle with a zero normal — collinear or repeated vertices:
 * *bad_triangle is its index).  normals[] is then written up to the bad
 * triangle.  bad_triangle may be NULL; it is left alone on STP_OK. */
int stp_mesh_prepare_normals(const stp_mesh *mesh, int16_t *normals, uint16_t *bad_triangle);

/* The bounds of mesh's vertices into *bounds (mesh->bounds is ignored):
 * once, after the vertices are made or changed, then pointed at by
 * mesh->bounds.  The same arithmetic as stp_renderer_mesh's own pass, so
 * pictures are identical with and without.
 * Errors: STP_ERR_ARG (mesh, its vertices or bounds NULL, vertex_count
 * 0); *bounds is then left alone. */
int stp_mesh_prepare_bounds(const stp_mesh *mesh, stp_mesh_bounds *bounds);

/* Enter every triangle of mesh (see above) into the open segment (or an
 * implicit one, as stp_renderer_polygon opens).  scratch: scratch_count >=
 * mesh->vertex_count entries (sizeof(stp_mesh_vertex) bytes each), may be
 * reused between calls and meshes, never shared by two calls at once.
 * stp_renderer_last_shade afterwards: the last entered triangle's shade.
 * Errors: STP_ERR_ARG (r, mesh, scratch or a mesh array NULL, scratch_count
 * below vertex_count, an index not below vertex_count — all checked before
 * anything is entered, so nothing is), STP_ERR_FULL (the display file is
 * full: the triangles before it stay entered, as with
 * stp_renderer_polygon), STP_ERR_RANGE (a vertex's view coordinates
 * saturate; the triangles before it stay entered), STP_ERR_UNSUPPORTED
 * (STP_WITH_MESH_FALLBACK 0 and a triangle needs the fallback; earlier
 * triangles stay entered), or any error of stp_renderer_polygon from a
 * triangle that took the fallback. */
int stp_renderer_mesh(stp_renderer *r, const stp_mesh *mesh, stp_mesh_vertex *scratch,
                      size_t scratch_count);

#ifdef __cplusplus
}
#endif

#endif
