/* SPDX-License-Identifier: MIT */
/* Double-precision reference of docs/model.md sections 2 and 3: see shade_ref.h. */
#include "shade_ref.h"

#include <math.h>

double ref_dot(ref_vec3 a, ref_vec3 b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

ref_vec3 ref_v3(double x, double y, double z)
{
    ref_vec3 r;
    r.x = x;
    r.y = y;
    r.z = z;
    return r;
}

ref_vec3 ref_add(ref_vec3 a, ref_vec3 b)
{
    return ref_v3(a.x + b.x, a.y + b.y, a.z + b.z);
}

ref_vec3 ref_sub(ref_vec3 a, ref_vec3 b)
{
    return ref_v3(a.x - b.x, a.y - b.y, a.z - b.z);
}

ref_vec3 ref_scale(ref_vec3 a, double s)
{
    return ref_v3(a.x * s, a.y * s, a.z * s);
}

ref_vec3 ref_cross(ref_vec3 a, ref_vec3 b)
{
    return ref_v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}

double ref_unit(ref_vec3 v, ref_vec3 *out)
{
    double len = sqrt(ref_dot(v, v));
    if (len == 0.0) {
        out->x = out->y = out->z = 0.0;
        return 0.0;
    }
    out->x = v.x / len;
    out->y = v.y / len;
    out->z = v.z / len;
    return len;
}

static ref_vec3 sub(ref_vec3 a, ref_vec3 b)
{
    ref_vec3 d;
    d.x = a.x - b.x;
    d.y = a.y - b.y;
    d.z = a.z - b.z;
    return d;
}

double ref_facet_d(double n_dot_h, double k)
{
    double q = k / (k + 1.0 - n_dot_h);
    return q * q;
}

double ref_blocking_g(double n_dot_h, double n_dot_e, double n_dot_l, double e_dot_h)
{
    double m = n_dot_e < n_dot_l ? n_dot_e : n_dot_l;
    double g = 2.0 * m * n_dot_h / e_dot_h;
    return g > 1.0 ? 1.0 : g;
}

double ref_fresnel_f(double e_dot_h, double n)
{
    double c = e_dot_h;
    double g2 = n * n + c * c - 1.0;
    double gf, t, r;
    if (g2 < 0.0)
        return 1.0;
    gf = sqrt(g2);
    t = ((gf + c) * c - 1.0) / ((gf - c) * c + 1.0);
    r = (gf - c) / (gf + c);
    return (t * t + 1.0) * r * r / 2.0;
}

double ref_shade_point(const ref_lighting *lighting, const ref_material *material,
                       ref_vec3 normal, ref_vec3 point, ref_vec3 eye, int parallel,
                       ref_vec3 parallel_dir)
{
    double b = lighting->background < 0.0 ? 0.0 : (lighting->background > 1.0 ? 1.0 : lighting->background);
    double r = material->reflectivity;
    double v = b * r, n_dot_e, s;
    ref_vec3 e;
    int j;

    if (parallel)
        e = parallel_dir;
    else
        (void)ref_unit(sub(eye, point), &e);
    n_dot_e = ref_dot(normal, e);

    if (n_dot_e > 0.0) {
        for (j = 0; j < lighting->count; j++) {
            ref_vec3 l, h, le;
            double u = ref_unit(sub(lighting->lights[j].position, point), &l);
            double n_dot_l, term;
            if (u == 0.0)
                l = normal;
            n_dot_l = ref_dot(normal, l);
            if (n_dot_l <= 0.0)
                continue;
            term = r * n_dot_l;
            le.x = l.x + e.x;
            le.y = l.y + e.y;
            le.z = l.z + e.z;
            if (material->specular != 0.0 && ref_unit(le, &h) > 0.0) {
                double n_dot_h = ref_dot(normal, h), e_dot_h = ref_dot(e, h);
                if (n_dot_h > 0.0 && e_dot_h > 0.0) {
                    double d = ref_facet_d(n_dot_h, material->gloss);
                    double g = ref_blocking_g(n_dot_h, n_dot_e, n_dot_l, e_dot_h);
                    double f = ref_fresnel_f(e_dot_h, material->refraction);
                    term += material->specular * d * g * f / n_dot_e;
                }
            }
            v += lighting->lights[j].power * term / (lighting->c + u);
        }
    }
    s = lighting->brightness * v;
    return s < 0.0 ? 0.0 : (s > 1.0 ? 1.0 : s);
}

int ref_intensity_index(double s, int levels)
{
    if (levels < 2)
        levels = 2;
    if (levels > 256)
        levels = 256;
    if (s < 0.0)
        s = 0.0;
    if (s > 1.0)
        s = 1.0;
    return (int)floor(s * (levels - 1) + 1.0);
}

double ref_gamma(double intensity, double gamma, double k)
{
    double v = pow(intensity / k, 1.0 / gamma);
    return v < 0.0 ? 0.0 : (v > 1.0 ? 1.0 : v);
}
