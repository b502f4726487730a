/* SPDX-License-Identifier: MIT */
/*
 * The Sierpinski tetrahedron: the regular tetrahedron with corners
 * (-1,-1,1), (-1,1,-1), (1,-1,-1), (1,1,1) replaced size-1 times by the four
 * half-size tetrahedra at its corners; 4^size triangles, each wound
 * counter-clockwise seen from outside.  View, light and material are the
 * SPD tetra's.
 */
#include "scenegen_private.h"

/* The face opposite corner `away`, wound so its normal points away from it. */
static void face(FILE *out, stp_sg_vec a, stp_sg_vec b, stp_sg_vec c, stp_sg_vec away)
{
    stp_sg_vec v[3];
    stp_sg_vec normal = stp_sg_cross(stp_sg_sub(b, a), stp_sg_sub(c, a));
    v[0] = a;
    if (stp_sg_dot(normal, stp_sg_sub(away, a)) > 0) {
        v[1] = c;
        v[2] = b;
    } else {
        v[1] = b;
        v[2] = c;
    }
    stp_sg_polygon(out, 3, v);
}

static void tetra(FILE *out, const stp_sg_vec corner[4], int depth)
{
    int k, m;
    if (depth == 0) {
        face(out, corner[0], corner[1], corner[2], corner[3]);
        face(out, corner[1], corner[2], corner[3], corner[0]);
        face(out, corner[2], corner[3], corner[0], corner[1]);
        face(out, corner[3], corner[0], corner[1], corner[2]);
        return;
    }
    for (k = 0; k < 4; k++) {
        stp_sg_vec half[4];
        for (m = 0; m < 4; m++)
            half[m] = stp_sg_scale(stp_sg_add(corner[k], corner[m]), 0.5);
        tetra(out, half, depth - 1);
    }
}

int stp_sg_write_tetra(FILE *out, int size)
{
    stp_sg_vec corner[4];
    corner[0] = stp_sg_v(-1, -1, 1);
    corner[1] = stp_sg_v(-1, 1, -1);
    corner[2] = stp_sg_v(1, -1, -1);
    corner[3] = stp_sg_v(1, 1, 1);
    stp_sg_comment(out, "tetra", size);
    stp_sg_background(out, 0.078, 0.361, 0.753);
    stp_sg_view(out, stp_sg_v(1.02285, -3.17715, -2.17451), stp_sg_v(-0.004103, -0.004103, 0.216539),
                stp_sg_v(-0.816497, -0.816497, 0.816497), 45, 1, 512);
    stp_sg_light(out, stp_sg_v(2, -18, -5));
    stp_sg_material(out, 1, 0.2, 0.2, 1, 0, 100000, 0, 0);
    tetra(out, corner, size - 1);
    return stp_sg_status(out);
}
