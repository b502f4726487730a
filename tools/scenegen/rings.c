/* SPDX-License-Identifier: MIT */
/*
 * A chain of size+1 interlocked rings, each 24 cylinders joined by 24
 * spheres (NFF's analytic primitives): centre line radius 1, tube radius
 * 0.15, centres 1.5 apart along x, rings alternately in the xy and the xz
 * plane and alternately gold and silver, so each passes through its
 * neighbours' holes with 0.2 units to spare.  Above a floor.
 */
#include <math.h>

#include "scenegen_private.h"

#define RING_RADIUS 1.0
#define RING_TUBE 0.15
#define RING_STEP 1.5
#define RING_SEGMENTS 24

/* Point at angle a on ring k of count. */
static stp_sg_vec ring_point(int k, int count, double a)
{
    double cx = RING_STEP * (k - 0.5 * (count - 1));
    if (k % 2 == 0)
        return stp_sg_v(cx + RING_RADIUS * cos(a), RING_RADIUS * sin(a), 0);
    return stp_sg_v(cx + RING_RADIUS * cos(a), 0, RING_RADIUS * sin(a));
}

int stp_sg_write_rings(FILE *out, int size)
{
    static const double two_pi = 6.28318530717958647692;
    const int count = size + 1;
    const double half = 0.5 * RING_STEP * (count - 1) + RING_RADIUS + 2;
    const double floor_z = -RING_RADIUS - RING_TUBE - 0.1;
    const double chain = 0.5 * RING_STEP * (count - 1) + RING_RADIUS + 0.3; /* half its length */
    stp_sg_vec floor[4];
    int k, s;
    floor[0] = stp_sg_v(half, half, floor_z);
    floor[1] = stp_sg_v(-half, half, floor_z);
    floor[2] = stp_sg_v(-half, -half, floor_z);
    floor[3] = stp_sg_v(half, -half, floor_z);
    stp_sg_comment(out, "rings", size);
    stp_sg_background(out, 0.078, 0.361, 0.753);
    stp_sg_view(out, stp_sg_v(0.5 * chain, -2.3 * chain, 1.4 * chain), stp_sg_v(0, 0, -0.2 * chain),
                stp_sg_v(0, 0, 1), 45, 0.1, 512);
    stp_sg_light(out, stp_sg_v(-3 * chain, -4 * chain, 5 * chain));
    stp_sg_light(out, stp_sg_v(4 * chain, -2 * chain, 3 * chain));
    stp_sg_material(out, 0.6, 0.6, 0.6, 0.8, 0, 100000, 0, 1);
    stp_sg_polygon(out, 4, floor);
    for (k = 0; k < count; k++) {
        if (k % 2 == 0)
            stp_sg_material(out, 1, 0.8, 0.3, 0.6, 0.4, 30, 0, 1);
        else
            stp_sg_material(out, 0.8, 0.8, 0.85, 0.5, 0.5, 30, 0, 1);
        for (s = 0; s < RING_SEGMENTS; s++) {
            stp_sg_vec a = ring_point(k, count, two_pi * s / RING_SEGMENTS);
            stp_sg_vec b = ring_point(k, count, two_pi * (s + 1) / RING_SEGMENTS);
            stp_sg_sphere(out, a, RING_TUBE);
            stp_sg_cylinder(out, a, b, RING_TUBE);
        }
    }
    return stp_sg_status(out);
}
