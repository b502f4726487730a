/* SPDX-License-Identifier: MIT */
/* Shared by the scene generators: NFF output and small vector helpers. */
#ifndef STIPPLE_TOOLS_SCENEGEN_PRIVATE_H
#define STIPPLE_TOOLS_SCENEGEN_PRIVATE_H

#include <stdio.h>

#include "scenegen.h"

typedef struct stp_sg_vec {
    double x, y, z;
} stp_sg_vec;

stp_sg_vec stp_sg_v(double x, double y, double z);
stp_sg_vec stp_sg_add(stp_sg_vec a, stp_sg_vec b);
stp_sg_vec stp_sg_sub(stp_sg_vec a, stp_sg_vec b);
stp_sg_vec stp_sg_scale(stp_sg_vec a, double s);
stp_sg_vec stp_sg_cross(stp_sg_vec a, stp_sg_vec b);
double stp_sg_dot(stp_sg_vec a, stp_sg_vec b);
double stp_sg_length(stp_sg_vec a);
/* a / |a|; a zero vector stays zero. */
stp_sg_vec stp_sg_unit(stp_sg_vec a);

/* NFF entities, numbers printed with 6 significant digits (as the SPD do).
 * The first line is a comment naming the generator and the size. */
void stp_sg_comment(FILE *out, const char *name, int size);
void stp_sg_background(FILE *out, double r, double g, double b);
void stp_sg_view(FILE *out, stp_sg_vec from, stp_sg_vec at, stp_sg_vec up, double angle_deg,
                 double hither, int resolution);
void stp_sg_light(FILE *out, stp_sg_vec position);
void stp_sg_material(FILE *out, double r, double g, double b, double kd, double ks, double shine,
                     double t, double ior);
void stp_sg_polygon(FILE *out, int count, const stp_sg_vec *vertices);
void stp_sg_patch(FILE *out, int count, const stp_sg_vec *vertices, const stp_sg_vec *normals);
void stp_sg_sphere(FILE *out, stp_sg_vec centre, double radius);
void stp_sg_cylinder(FILE *out, stp_sg_vec base, stp_sg_vec apex, double radius);
/* 0 when every write succeeded, else -1. */
int stp_sg_status(FILE *out);

/* Newell's teapot (teapot_data.c): control points numbered from 1 in the
 * patches, each patch 4 rows of 4. */
#define STP_TEAPOT_PATCHES 32
#define STP_TEAPOT_POINTS 306
extern const unsigned short stp_teapot_patches[STP_TEAPOT_PATCHES][16];
extern const double stp_teapot_points[STP_TEAPOT_POINTS][3];

/* The scenes' writers (one file each). */
int stp_sg_write_teapot(FILE *out, int size);
int stp_sg_write_tetra(FILE *out, int size);
int stp_sg_write_sphereflake(FILE *out, int size);
int stp_sg_write_torus(FILE *out, int size);
int stp_sg_write_rings(FILE *out, int size);
int stp_sg_write_mountain(FILE *out, int size);

#endif
