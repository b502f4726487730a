/* SPDX-License-Identifier: MIT */
/*
 * The sphereflake: a sphere of radius 1/2 at the origin carrying nine
 * spheres of a third its radius, touching it, each carrying nine more, size
 * generations deep (1 + 9 + ... + 9^size spheres), on a floor.  A sphere's
 * children sit around its own axis w (the direction from its parent; +z for
 * the first): three at 35.26 degrees from w (cos = sqrt(2/3)) at azimuths
 * 45, 165 and 285 degrees, six on its equator at 15, 75, ..., 315 degrees,
 * azimuths measured in the frame that the shortest rotation taking +z to w
 * makes of x, y, z.  Written depth first.  View, lights and materials are
 * the SPD balls'; size S gives the SPD's spheres at size factor S (tested
 * for S = 1, 2).
 */
#include <math.h>

#include "scenegen_private.h"

typedef struct frame {
    stp_sg_vec u, v, w;
} frame;

/* The shortest rotation taking +z to w (unit), applied to x, y, z
 * (Rodrigues' formula about z x w). */
static frame frame_for_axis(stp_sg_vec w)
{
    frame f;
    stp_sg_vec axis = stp_sg_cross(stp_sg_v(0, 0, 1), w);
    double s = stp_sg_length(axis), c = w.z;
    if (s < 1e-12) {
        /* along +z: no rotation; along -z: half a turn about x */
        f.u = stp_sg_v(1, 0, 0);
        f.v = stp_sg_v(0, c > 0 ? 1 : -1, 0);
        f.w = stp_sg_v(0, 0, c > 0 ? 1 : -1);
        return f;
    }
    axis = stp_sg_scale(axis, 1.0 / s);
    {
        const stp_sg_vec basis[2] = {{1, 0, 0}, {0, 1, 0}};
        stp_sg_vec out[2];
        int i;
        for (i = 0; i < 2; i++) {
            stp_sg_vec b = basis[i];
            out[i] = stp_sg_add(stp_sg_add(stp_sg_scale(b, c), stp_sg_scale(stp_sg_cross(axis, b), s)),
                                stp_sg_scale(axis, stp_sg_dot(axis, b) * (1 - c)));
        }
        f.u = out[0];
        f.v = out[1];
    }
    f.w = w;
    return f;
}

/* Child k's direction in frame f (k = 0..8: every third one above). */
static stp_sg_vec child_direction(const frame *f, int k)
{
    static const double pi = 3.14159265358979323846;
    int group = k / 3, within = k % 3;
    double azimuth, cos_elev, sin_elev;
    if (within == 0) {
        azimuth = 45 + 120 * group;
        sin_elev = sqrt(2.0 / 3.0);
        cos_elev = sqrt(1.0 / 3.0);
    } else {
        azimuth = 15 + 120 * group + 60 * (within - 1);
        sin_elev = 0;
        cos_elev = 1;
    }
    azimuth *= pi / 180;
    return stp_sg_add(stp_sg_add(stp_sg_scale(f->u, cos(azimuth) * cos_elev),
                                 stp_sg_scale(f->v, sin(azimuth) * cos_elev)),
                      stp_sg_scale(f->w, sin_elev));
}

static void flake(FILE *out, stp_sg_vec centre, double radius, stp_sg_vec axis, int generations)
{
    frame f;
    int k;
    stp_sg_sphere(out, centre, radius);
    if (generations == 0)
        return;
    f = frame_for_axis(axis);
    for (k = 0; k < 9; k++) {
        stp_sg_vec d = child_direction(&f, k);
        double child = radius / 3;
        flake(out, stp_sg_add(centre, stp_sg_scale(d, radius + child)), child, d, generations - 1);
    }
}

int stp_sg_write_sphereflake(FILE *out, int size)
{
    stp_sg_vec floor[4];
    floor[0] = stp_sg_v(12, 12, -0.5);
    floor[1] = stp_sg_v(-12, 12, -0.5);
    floor[2] = stp_sg_v(-12, -12, -0.5);
    floor[3] = stp_sg_v(12, -12, -0.5);
    stp_sg_comment(out, "sphereflake", size);
    stp_sg_background(out, 0.078, 0.361, 0.753);
    stp_sg_view(out, stp_sg_v(2.1, 1.3, 1.7), stp_sg_v(0, 0, 0), stp_sg_v(0, 0, 1), 45, 0.01, 512);
    stp_sg_light(out, stp_sg_v(4, 3, 2));
    stp_sg_light(out, stp_sg_v(1, -4, 4));
    stp_sg_light(out, stp_sg_v(-3, 1, 5));
    stp_sg_material(out, 1, 0.75, 0.33, 0.8, 0, 100000, 0, 1);
    stp_sg_polygon(out, 4, floor);
    stp_sg_material(out, 1, 0.9, 0.7, 0.5, 0.5, 3.0827, 0, 1);
    flake(out, stp_sg_v(0, 0, 0), 0.5, stp_sg_v(0, 0, 1), size);
    return stp_sg_status(out);
}
