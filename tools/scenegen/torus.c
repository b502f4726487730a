/* SPDX-License-Identifier: MIT */
/*
 * A torus about the z axis: tube radius 0.35 around a circle of radius 1,
 * cut into 12*size steps around the axis and 8*size around the tube
 * (96*size^2 quadrilaterals), each with its exact surface normals ("pp"),
 * wound counter-clockwise seen from outside, above a floor.
 */
#include <math.h>

#include "scenegen_private.h"

#define TORUS_MAJOR 1.0
#define TORUS_MINOR 0.35

/* Point and outward normal at angle theta around the axis and phi around
 * the tube (phi = 0 on the outer equator). */
static void torus_point(double theta, double phi, stp_sg_vec *p, stp_sg_vec *n)
{
    *n = stp_sg_v(cos(phi) * cos(theta), cos(phi) * sin(theta), sin(phi));
    *p = stp_sg_add(stp_sg_v(TORUS_MAJOR * cos(theta), TORUS_MAJOR * sin(theta), 0),
                    stp_sg_scale(*n, TORUS_MINOR));
}

int stp_sg_write_torus(FILE *out, int size)
{
    static const double two_pi = 6.28318530717958647692;
    const int around = 12 * size, tube = 8 * size;
    stp_sg_vec floor[4];
    int i, j, k;
    floor[0] = stp_sg_v(3, 3, -TORUS_MINOR);
    floor[1] = stp_sg_v(-3, 3, -TORUS_MINOR);
    floor[2] = stp_sg_v(-3, -3, -TORUS_MINOR);
    floor[3] = stp_sg_v(3, -3, -TORUS_MINOR);
    stp_sg_comment(out, "torus", size);
    stp_sg_background(out, 0.078, 0.361, 0.753);
    stp_sg_view(out, stp_sg_v(2.2, -2.6, 2.4), stp_sg_v(0, 0, 0), stp_sg_v(0, 0, 1), 45, 0.1, 512);
    stp_sg_light(out, stp_sg_v(-4, -6, 8));
    stp_sg_light(out, stp_sg_v(5, 2, 6));
    stp_sg_material(out, 0.7, 0.7, 0.7, 0.8, 0, 100000, 0, 1);
    stp_sg_polygon(out, 4, floor);
    stp_sg_material(out, 0.2, 0.6, 1, 0.7, 0.3, 20, 0, 1);
    for (i = 0; i < around; i++)
        for (j = 0; j < tube; j++) {
            const int corner[4][2] = {{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}};
            stp_sg_vec v[4], n[4];
            for (k = 0; k < 4; k++)
                torus_point(two_pi * corner[k][0] / around, two_pi * corner[k][1] / tube, &v[k], &n[k]);
            stp_sg_patch(out, 4, v, n);
        }
    return stp_sg_status(out);
}
