/* SPDX-License-Identifier: MIT */
/* NFF output for the scene generators, and the vector arithmetic they share. */
#include <math.h>

#include "scenegen_private.h"

stp_sg_vec stp_sg_v(double x, double y, double z)
{
    stp_sg_vec v;
    v.x = x;
    v.y = y;
    v.z = z;
    return v;
}

stp_sg_vec stp_sg_add(stp_sg_vec a, stp_sg_vec b) { return stp_sg_v(a.x + b.x, a.y + b.y, a.z + b.z); }
stp_sg_vec stp_sg_sub(stp_sg_vec a, stp_sg_vec b) { return stp_sg_v(a.x - b.x, a.y - b.y, a.z - b.z); }
stp_sg_vec stp_sg_scale(stp_sg_vec a, double s) { return stp_sg_v(a.x * s, a.y * s, a.z * s); }
double stp_sg_dot(stp_sg_vec a, stp_sg_vec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
double stp_sg_length(stp_sg_vec a) { return sqrt(stp_sg_dot(a, a)); }

stp_sg_vec stp_sg_cross(stp_sg_vec a, stp_sg_vec b)
{
    return stp_sg_v(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}

stp_sg_vec stp_sg_unit(stp_sg_vec a)
{
    double len = stp_sg_length(a);
    return len > 0 ? stp_sg_scale(a, 1.0 / len) : a;
}

/* One number: 6 significant digits, and never "-0" (adding 0.0 turns a
 * negative zero positive). */
static void number(FILE *out, double v, char after)
{
    fprintf(out, "%.6g%c", v + 0.0, after);
}

static void point(FILE *out, stp_sg_vec v, char after)
{
    number(out, v.x, ' ');
    number(out, v.y, ' ');
    number(out, v.z, after);
}

void stp_sg_comment(FILE *out, const char *name, int size)
{
    fprintf(out, "# %s, size %d: written by 'stipple scene %s --size %d'\n", name, size, name, size);
}

void stp_sg_background(FILE *out, double r, double g, double b)
{
    fputs("b ", out);
    point(out, stp_sg_v(r, g, b), '\n');
}

void stp_sg_view(FILE *out, stp_sg_vec from, stp_sg_vec at, stp_sg_vec up, double angle_deg,
                 double hither, int resolution)
{
    fputs("v\nfrom ", out);
    point(out, from, '\n');
    fputs("at ", out);
    point(out, at, '\n');
    fputs("up ", out);
    point(out, up, '\n');
    fputs("angle ", out);
    number(out, angle_deg, '\n');
    fputs("hither ", out);
    number(out, hither, '\n');
    fprintf(out, "resolution %d %d\n", resolution, resolution);
}

void stp_sg_light(FILE *out, stp_sg_vec position)
{
    fputs("l ", out);
    point(out, position, '\n');
}

void stp_sg_material(FILE *out, double r, double g, double b, double kd, double ks, double shine,
                     double t, double ior)
{
    fputs("f ", out);
    point(out, stp_sg_v(r, g, b), ' ');
    number(out, kd, ' ');
    number(out, ks, ' ');
    number(out, shine, ' ');
    number(out, t, ' ');
    number(out, ior, '\n');
}

void stp_sg_polygon(FILE *out, int count, const stp_sg_vec *vertices)
{
    int i;
    fprintf(out, "p %d\n", count);
    for (i = 0; i < count; i++)
        point(out, vertices[i], '\n');
}

void stp_sg_patch(FILE *out, int count, const stp_sg_vec *vertices, const stp_sg_vec *normals)
{
    int i;
    fprintf(out, "pp %d\n", count);
    for (i = 0; i < count; i++) {
        point(out, vertices[i], ' ');
        point(out, normals[i], '\n');
    }
}

void stp_sg_sphere(FILE *out, stp_sg_vec centre, double radius)
{
    fputs("s ", out);
    point(out, centre, ' ');
    number(out, radius, '\n');
}

void stp_sg_cylinder(FILE *out, stp_sg_vec base, stp_sg_vec apex, double radius)
{
    fputs("c\n", out);
    point(out, base, ' ');
    number(out, radius, '\n');
    point(out, apex, ' ');
    number(out, radius, '\n');
}

int stp_sg_status(FILE *out)
{
    return ferror(out) ? -1 : 0;
}
