/* SPDX-License-Identifier: MIT */
/*
 * The Utah teapot on a checkered floor: each of Newell's 32 bicubic Bezier
 * patches (teapot_data.c) evaluated on a (size+1) x (size+1) grid of its
 * parameters, each grid square split into two triangles with the surface
 * normals at their corners ("pp"), triangles with two coincident corners
 * (at the lid's knob and the bottom's centre, where a patch edge collapses
 * to a point) left out.  View, lights and materials are the SPD teapot's,
 * so size S gives the same geometry as the SPD's teapot at size factor S.
 */
#include <math.h>

#include "scenegen_private.h"

/* Cubic Bernstein weights at t, and their derivatives. */
static void bernstein(double t, double b[4], double db[4])
{
    double s = 1.0 - t;
    b[0] = s * s * s;
    b[1] = 3.0 * t * s * s;
    b[2] = 3.0 * t * t * s;
    b[3] = t * t * t;
    db[0] = -3.0 * s * s;
    db[1] = 3.0 * s * s - 6.0 * t * s;
    db[2] = 6.0 * t * s - 3.0 * t * t;
    db[3] = 3.0 * t * t;
}

/* Point and the derivatives along the rows (r) and the columns (c). */
static void patch_eval(int patch, double r, double c, stp_sg_vec *p, stp_sg_vec *dr, stp_sg_vec *dc)
{
    double br[4], dbr[4], bc[4], dbc[4];
    int i, j;
    bernstein(r, br, dbr);
    bernstein(c, bc, dbc);
    *p = *dr = *dc = stp_sg_v(0, 0, 0);
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++) {
            const double *q = stp_teapot_points[stp_teapot_patches[patch][4 * i + j] - 1];
            stp_sg_vec cp = stp_sg_v(q[0], q[1], q[2]);
            *p = stp_sg_add(*p, stp_sg_scale(cp, br[i] * bc[j]));
            *dr = stp_sg_add(*dr, stp_sg_scale(cp, dbr[i] * bc[j]));
            *dc = stp_sg_add(*dc, stp_sg_scale(cp, br[i] * dbc[j]));
        }
}

/* The unit normal dc x dr.  Where an edge collapses to a point one
 * derivative vanishes: the normal is then the limit, taken a step inside
 * the patch. */
static stp_sg_vec patch_normal(int patch, double r, double c)
{
    const double step = 1e-7;
    stp_sg_vec p, dr, dc, n;
    patch_eval(patch, r, c, &p, &dr, &dc);
    n = stp_sg_cross(dc, dr);
    if (stp_sg_length(n) < 1e-9) {
        patch_eval(patch, r < 0.5 ? r + step : r - step, c < 0.5 ? c + step : c - step, &p, &dr, &dc);
        n = stp_sg_cross(dc, dr);
    }
    return stp_sg_unit(n);
}

static int same_point(stp_sg_vec a, stp_sg_vec b)
{
    return stp_sg_length(stp_sg_sub(a, b)) < 1e-9;
}

/* One triangle of grid corners (row, column), unless degenerate. */
static void triangle(FILE *out, int patch, int size, const int corner[3][2])
{
    stp_sg_vec v[3], n[3], dr, dc;
    int k;
    for (k = 0; k < 3; k++) {
        double r = (double)corner[k][0] / size, c = (double)corner[k][1] / size;
        patch_eval(patch, r, c, &v[k], &dr, &dc);
        n[k] = patch_normal(patch, r, c);
    }
    if (same_point(v[0], v[1]) || same_point(v[1], v[2]) || same_point(v[2], v[0]))
        return;
    stp_sg_patch(out, 3, v, n);
}

/* size x size squares of 8/size units from -4 to 4, grey where the square's
 * row and column indices have an even sum, white elsewhere. */
static void floor_checker(FILE *out, int size)
{
    int parity, i, j;
    double w = 8.0 / size;
    for (parity = 0; parity < 2; parity++) {
        if (parity == 0)
            stp_sg_material(out, 1, 1, 1, 0.5, 0.5, 4.81884, 0, 0);
        else
            stp_sg_material(out, 0.5, 0.5, 0.5, 0.5, 0.5, 4.81884, 0, 0);
        for (i = 0; i < size; i++)
            for (j = 0; j < size; j++) {
                stp_sg_vec q[4];
                double x0 = -4 + i * w, y0 = -4 + j * w;
                if ((i + j + 1) % 2 != parity)
                    continue;
                q[0] = stp_sg_v(x0, y0, 0);
                q[1] = stp_sg_v(x0 + w, y0, 0);
                q[2] = stp_sg_v(x0 + w, y0 + w, 0);
                q[3] = stp_sg_v(x0, y0 + w, 0);
                stp_sg_polygon(out, 4, q);
            }
    }
}

int stp_sg_write_teapot(FILE *out, int size)
{
    int patch, i, j;
    stp_sg_comment(out, "teapot", size);
    stp_sg_background(out, 0.078, 0.361, 0.753);
    stp_sg_view(out, stp_sg_v(4.86, 7.2, 5.4), stp_sg_v(0, 0, 0), stp_sg_v(0, 0, 1), 45, 1, 512);
    stp_sg_light(out, stp_sg_v(-3.1, 9.8, 12.1));
    stp_sg_light(out, stp_sg_v(11.3, 5.1, 8.8));
    floor_checker(out, size);
    stp_sg_material(out, 1, 0.5, 0.1, 0.75, 0.25, 3.0827, 0, 0);
    for (patch = 0; patch < STP_TEAPOT_PATCHES; patch++)
        for (i = 0; i < size; i++)
            for (j = 0; j < size; j++) {
                const int lower[3][2] = {{i, j}, {i, j + 1}, {i + 1, j + 1}};
                const int upper[3][2] = {{i + 1, j + 1}, {i + 1, j}, {i, j}};
                triangle(out, patch, size, lower);
                triangle(out, patch, size, upper);
            }
    return stp_sg_status(out);
}
