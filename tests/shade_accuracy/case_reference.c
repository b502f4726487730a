/* SPDX-License-Identifier: MIT */
/* The reference shade of an accuracy case: see case_reference.h. */
#include "case_reference.h"

#include <stddef.h>

#include "reference/shade_ref.h"

static double fixd(stp_fix v)
{
    return (double)v / STP_FIX_ONE;
}

static ref_vec3 vecd(stp_vec3 v)
{
    return ref_v3(fixd(v.x), fixd(v.y), fixd(v.z));
}

double acc_reference(const acc_case *c, double *raw)
{
    ref_lighting lg;
    ref_material m;
    ref_vec3 n, dir;
    int j;
    double s;
    lg.brightness = fixd(c->lighting.brightness);
    lg.background = fixd(c->lighting.background);
    lg.c = fixd(c->lighting.attenuation_c);
    lg.count = c->lighting.count;
    for (j = 0; j < c->lighting.count; j++) {
        lg.lights[j].position = vecd(c->lighting.lights[j].position);
        lg.lights[j].power = fixd(c->lighting.lights[j].power);
    }
    m.reflectivity = fixd(c->material.reflectivity);
    m.refraction = fixd(c->material.refraction);
    m.gloss = fixd(c->material.gloss);
    m.specular = fixd(c->material.specular);
    (void)ref_unit(ref_v3(c->normal[0], c->normal[1], c->normal[2]), &n);
    (void)ref_unit(vecd(c->parallel_dir), &dir);
    s = ref_shade_point(&lg, &m, n, vecd(c->point), vecd(c->eye), c->parallel, dir);
    if (raw != NULL) {
        lg.brightness *= 0x1p-40; /* the same sum, far below the cap */
        *raw = ref_shade_point(&lg, &m, n, vecd(c->point), vecd(c->eye), c->parallel, dir) * 0x1p40;
    }
    return s;
}
