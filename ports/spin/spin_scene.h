/* SPDX-License-Identifier: MIT */
/*
 * A scene spun about its vertical axis (issue 11 item 4), as indexed meshes
 * for firmware.  The data is a build product: tools/bench/spin_mesh_gen
 * writes it from an NFF scene (the view, lights and materials as the
 * stipple command maps them; polygons fanned into triangles; the Q1.14
 * face normals prepared on the host, const data in flash).  spin_frame.c
 * renders it on the host and on the chip alike.
 */
#ifndef STIPPLE_SPIN_SCENE_H
#define STIPPLE_SPIN_SCENE_H

#include "stipple/stipple.h"

/* One material's triangles of the scene. */
typedef struct spin_part {
    stp_mesh mesh;         /* vertices, triangles and prepared normals */
    stp_material material; /* as stipple maps the NFF "f" line */
    int spins;             /* 1: turned every frame; 0: a flat horizontal part
                              (a floor), entered once */
} spin_part;

extern const spin_part spin_parts[];
extern const uint16_t spin_part_count;
/* the vertical axis (0: x, 1: y, 2: z; the view's up) and a point on the
 * vertical line the spinning parts turn about (their bounds' centre) */
extern const int spin_axis;
extern const stp_vec3 spin_axis_point;
/* the output as stipple maps the scene: levels, background (0..1), back
 * faces removed or not */
extern const int spin_levels;
extern const stp_fix spin_background;
extern const int spin_backface_removal;

/* Caller memory sized for the scene (RAM): the display file and the
 * per-vertex scratch of stp_renderer_mesh (the largest part's vertices). */
extern stp_instr spin_display_file[];
extern const uint32_t spin_display_file_capacity;
extern stp_mesh_vertex spin_scratch[];
extern const uint16_t spin_scratch_count;

/* The scene's view and lighting (stp_tool_setup_prepared's values). */
void spin_scene_view(stp_view *view);
void spin_scene_lighting(stp_lighting *lighting);

#endif
