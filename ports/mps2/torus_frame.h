/* SPDX-License-Identifier: MIT */
/* The torus frame of issue 11's benchmarks, integer only, so the host and
 * the Cortex-M firmware build the same vertices and render the same
 * picture: a torus (major radius 1, minor 0.4, 25 x 20 quads split into
 * 1000 triangles, wound counter-clockwise seen from outside), eye at
 * distance 6 along (0, 3, 5.2) looking at the centre, 35 degrees across the
 * shorter side, one point light at (-4, 6, 5), full seed shading, 16 levels,
 * Bayer 4x4, Z buffer, back faces removed, a 1-bit MSB-first frame. */
#ifndef STIPPLE_TORUS_FRAME_H
#define STIPPLE_TORUS_FRAME_H

#include "stipple/stipple.h"

#define TORUS_AROUND 25
#define TORUS_TUBE 20
#define TORUS_TRIANGLES (2 * TORUS_AROUND * TORUS_TUBE)
/* display-file entries: each triangle, a style change and a margin */
#define TORUS_DF_CAPACITY (TORUS_TRIANGLES * 5u + 16u)

/* The torus as an indexed mesh (stp_renderer_mesh): one vertex per ring
 * and tube step, the same points and triangles as torus_build's. */
#define TORUS_MESH_VERTICES (TORUS_AROUND * TORUS_TUBE)

/* vertices: TORUS_MESH_VERTICES points; triangles: 3 * TORUS_TRIANGLES
 * indices (in torus_build's order); normals: 3 * TORUS_TRIANGLES
 * (stp_mesh_prepare_normals); bounds: the vertices' (stp_mesh_prepare_bounds).  Returns STP_OK or its error. */
int torus_mesh_build(stp_mesh *mesh, stp_vec3 *vertices, uint16_t *triangles, int16_t *normals,
                     stp_mesh_bounds *bounds);

/* torus_enter through stp_renderer_mesh (scratch: TORUS_MESH_VERTICES
 * entries). */
int torus_enter_mesh(stp_renderer *r, const stp_mesh *mesh, stp_mesh_vertex *scratch);

/* The 3 * TORUS_TRIANGLES vertices (world units), from the core's own
 * fixed-point sine and cosine. */
void torus_build(stp_vec3 *vertices);

/* View, lighting, material and switches of the workload on a renderer
 * created at the frame's size.  Returns STP_OK or the core's error. */
int torus_setup(stp_renderer *r);

/* The two halves of a frame: entering the torus into a fresh segment 1
 * (the previous one deleted), and stp_renderer_render of the display file. */
int torus_enter(stp_renderer *r, const stp_vec3 *vertices);
int torus_render(stp_renderer *r, stp_port *port, const stp_frame_memory *mem);

/* One frame: the torus entered into a fresh segment 1 (the previous one
 * deleted), then rendered to port (MONO1) through mem (one band or more,
 * Z buffer).  Returns STP_OK or the core's error. */
int torus_frame(stp_renderer *r, const stp_vec3 *vertices, stp_port *port,
                const stp_frame_memory *mem);

#endif
