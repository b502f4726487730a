/* SPDX-License-Identifier: MIT */
/* A spinning torus drawn by direct drawing (include/stipple/direct.h),
 * integer only, so the host and the Cortex-M firmware build the same model
 * and draw the same pictures: the torus of issue 11's bench (major radius
 * 1, minor 0.4, 25 x 20 quads split into 1000 triangles) built from
 * stp_direct_sin, normals by stp_mesh_prepare_normals; eye at (0, 3, 5.2)
 * looking at the centre, 35 degrees across the 64 rows; one light at
 * (-4, 6, 5), power 9.775 (its attenuation at the centre cancelled),
 * background 0.2, R 0.7; 16 levels, Bayer 4x4; 128 x 64, 1 bit.  Frame n
 * turns the torus by n/64 of a turn about y and n 410/65536 about x. */
#ifndef STIPPLE_PORTS_DIRECT_SPIN_H
#define STIPPLE_PORTS_DIRECT_SPIN_H

#include "stipple/direct.h"

#define SPIN_WIDTH 128u
#define SPIN_HEIGHT 64u
#define SPIN_STRIDE (SPIN_WIDTH / 8u)
#define SPIN_AROUND 25u
#define SPIN_TUBE 20u
#define SPIN_VERTICES (SPIN_AROUND * SPIN_TUBE)
#define SPIN_TRIANGLES (2u * SPIN_VERTICES)

/* STP_SPIN_SORT 1: every frame's faces drawn far to near
 * (stp_direct_frame_sort, the renderer's painter's sort; 16 000 B more
 * RAM), else in mesh order: a torus is not convex, and in mesh order a
 * face behind may be drawn over one in front (some of the frames).  Not
 * in the compact form, which keeps mesh order. */
#if defined(STP_SPIN_SORT) && STP_SPIN_SORT && !STP_DIRECT_COMPACT
#define SPIN_SORTED 1
#else
#define SPIN_SORTED 0
#endif

/* STP_SPIN_DEPTH 1: every frame's faces drawn with the renderer's Z
 * buffer (stp_direct_frame_depth: a depth a vertex, 2 000 B, and a band
 * of depths, 2 bytes a pixel of the tallest band, SPIN_DEPTH_ROWS rows:
 * the whole picture's by default, 16 384 B), its picture pixel for pixel;
 * not with STP_SPIN_SORT (the later wins), nor in the compact form. */
#if defined(STP_SPIN_DEPTH) && STP_SPIN_DEPTH && !STP_DIRECT_COMPACT && STP_WITH_ZBUFFER
#define SPIN_DEPTH 1
#else
#define SPIN_DEPTH 0
#endif
#ifndef SPIN_DEPTH_ROWS
#define SPIN_DEPTH_ROWS SPIN_HEIGHT
#endif

/* STP_SPIN_PLACE 1: the torus's centre moved to (0.61, 2.41, 4.30), 0.9
 * units from the eye, so the near plane and the picture's edges cut it
 * (frame 10: 43 faces clipped, 26 vertices left unprojected): direct
 * drawing's clipping on the chip, test_firmware_mps2_direct_clipped;
 * 0 (default): about the origin. */
#ifndef STP_SPIN_PLACE
#define STP_SPIN_PLACE 0
#endif

typedef struct direct_spin {
    stp_mesh mesh;
    stp_direct_view view;
    stp_direct_light light;
    stp_vec3 vertices[SPIN_VERTICES];
    uint16_t triangles[3 * SPIN_TRIANGLES];
    int16_t normals[3 * SPIN_TRIANGLES];
    stp_direct_point points[SPIN_VERTICES];
    uint16_t faces[SPIN_TRIANGLES];
#if SPIN_SORTED
    stp_sort_entry order[SPIN_TRIANGLES]; /* the faces far to near */
#endif
#if SPIN_DEPTH
    int32_t depths[SPIN_VERTICES]; /* the vertices' depths (stp_direct_frame_depth) */
    uint16_t zband[SPIN_WIDTH * SPIN_DEPTH_ROWS];
    stp_direct_depth depth; /* over those two */
#endif
} direct_spin;

/* The model, its normals, the view and the light.  STP_OK or the error. */
int direct_spin_init(direct_spin *s);

/* Frame n projected and shaded into *f (its bands: stp_direct_draw_band),
 * its faces sorted with SPIN_SORTED, depth-tested with SPIN_DEPTH. */
int direct_spin_frame(direct_spin *s, uint16_t n, stp_direct_frame *f);

#endif
