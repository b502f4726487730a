/* SPDX-License-Identifier: MIT */
/*
 * The peer side of the side-by-side torus bench (peer_bench.c, issue 21):
 * the same torus drawn by small3dlib (drummyfish's one-header C renderer,
 * https://codeberg.org/drummyfish/small3dlib), compiled from the peer's own
 * source at bench time (tools/bench/peer_bench.sh --peer-small3dlib DIR; it
 * is never part of this repository).  Only peer_s3l.c includes the header.
 *
 * What small3dlib is asked to do, through its documented API (S3L_Model3D,
 * S3L_Scene, S3L_newFrame, S3L_drawScene, the S3L_PIXEL_FUNCTION callback):
 * the same vertices and triangles as the stipple mesh (stp_fix converted to
 * its 1/512 units), the same view (eye, centre, up, 35 degrees across the
 * shorter side) and pose, folded into the model's custom transform matrix;
 * its Z buffer (S3L_Z_BUFFER 2, the reduced one of bytes, by default; 1,
 * the full 32-bit one, with PEER_S3L_Z_BUFFER=1), its back-face culling,
 * no near-plane clipping (the torus lies well inside the view).  Per frame:
 * the frame cleared (unlit, as stipple leaves what no polygon covers), the light turned
 * into model coordinates, S3L_newFrame, S3L_drawScene; at the first pixel
 * of each drawn triangle its flat Lambert level (16 levels: 0.2 ambient +
 * 0.8 N.L towards the light, a light at the direction of stipple's point
 * light from the torus's centre, so no per-face light vector, no
 * attenuation, no specular) and at every pixel the Bayer 4x4 threshold
 * into the finished MSB-first 1-bit frame (1 = lit, as STP_PIXEL_MONO1).
 */
#ifndef STIPPLE_TOOLS_BENCH_PEER_S3L_H
#define STIPPLE_TOOLS_BENCH_PEER_S3L_H

#include <stddef.h>
#include <stdint.h>

#include "stipple/stipple.h"

/* The view and light in world units (the stipple scene's). */
typedef struct peer_view {
    double eye[3], at[3], up[3];
    double fov_degrees; /* across the shorter side */
    double light[3];    /* the point light's position */
} peer_view;

/* 1 when the program was built with the peer's source, else 0 (and the
 * functions below return -1). */
extern const int peer_s3l_available;

/* Set up a width x height frame (at most 640 x 480) of the meshes
 * parts[0 .. part_count - 1] (each at most 65 535 vertices and triangles,
 * normals prepared).  Keeps pointers to nothing of the caller's.  Returns
 * 0, or -1 with a message in err. */
int peer_s3l_init(int width, int height, const stp_mesh *parts, int part_count,
                  const peer_view *view, char *err, size_t err_size);

/* Pose the model for the next frames as torus_bench_pose does (tilt about
 * x, then spin about y; no move). */
void peer_s3l_pose(double tilt_degrees, double spin_degrees);

/* One frame (the measured function): returns 0. */
int peer_s3l_frame(void);

/* The finished frame: height rows of *stride bytes. */
const uint8_t *peer_s3l_bits(size_t *stride);

void peer_s3l_free(void);

#endif
