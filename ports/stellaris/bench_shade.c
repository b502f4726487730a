/* SPDX-License-Identifier: MIT */
/*
 * The shading micro-benchmark of the bench images (bench_shade.h): the
 * instructions per stp_shade_point call over a fixed set of the scene's own
 * polygons, its lights and materials.  Not linked into the shipping image.
 */
#include "bench_shade.h"
#include "stellaris.h"

/* STP_FW_SHADE_INPUTS points taken from the scene's polygons, each shaded
 * STP_FW_SHADE_REPEAT times. */
#ifndef STP_FW_SHADE_INPUTS
#define STP_FW_SHADE_INPUTS 64u
#endif
#ifndef STP_FW_SHADE_REPEAT
#define STP_FW_SHADE_REPEAT 4u
#endif

/* One stp_shade_point call's inputs, in world space (where the compiled
 * scene's vertices and lights are). */
typedef struct shade_input {
    const stp_material *material;
    stp_vec3 normal, point;
} shade_input;

static int64_t abs64(int64_t v)
{
    return v < 0 ? -v : v;
}

/* The unit normal of a polygon from its first three vertices (the core takes
 * Newell's normal in view space; for the timing a plane's normal is as good),
 * turned towards the viewer, and the mean of its vertices.  Returns 0 for a
 * polygon with no direction (collinear or repeated vertices). */
static int polygon_input(const stp_scene_data *s, const stp_scene_data_polygon *p,
                         const stp_vec3 *v, stp_vec3 towards_viewer_parallel, shade_input *in)
{
    int64_t a[3], b[3], c[3], sum[3] = {0, 0, 0}, big;
    stp_vec3 cross, to_eye;
    uint32_t i;
    int k;

    if (p->count < 3)
        return 0;
    a[0] = (int64_t)v[1].x - v[0].x;
    a[1] = (int64_t)v[1].y - v[0].y;
    a[2] = (int64_t)v[1].z - v[0].z;
    b[0] = (int64_t)v[2].x - v[0].x;
    b[1] = (int64_t)v[2].y - v[0].y;
    b[2] = (int64_t)v[2].z - v[0].z;
    /* edges below 2^30 so that the products and their sums fit 64 bits */
    big = 0;
    for (k = 0; k < 3; k++) {
        big |= abs64(a[k]);
        big |= abs64(b[k]);
    }
    while (big >= ((int64_t)1 << 30)) {
        for (k = 0; k < 3; k++) {
            a[k] /= 2;
            b[k] /= 2;
        }
        big /= 2;
    }
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
    /* only the direction counts: bring it into stp_fix's range */
    big = abs64(c[0]) | abs64(c[1]) | abs64(c[2]);
    while (big >= ((int64_t)1 << 30)) {
        for (k = 0; k < 3; k++)
            c[k] /= 2;
        big /= 2;
    }
    cross.x = (stp_fix)c[0];
    cross.y = (stp_fix)c[1];
    cross.z = (stp_fix)c[2];
    if (stp_vec3_unity(cross, &in->normal) == 0)
        return 0;

    for (i = 0; i < p->count; i++) {
        sum[0] += v[i].x;
        sum[1] += v[i].y;
        sum[2] += v[i].z;
    }
    in->point.x = (stp_fix)(sum[0] / (int64_t)p->count);
    in->point.y = (stp_fix)(sum[1] / (int64_t)p->count);
    in->point.z = (stp_fix)(sum[2] / (int64_t)p->count);
    in->material = &s->materials[p->material];

    /* the side the viewer sees, as the core shades it */
    if (s->view.projection == STP_PARALLEL) {
        to_eye = towards_viewer_parallel;
    } else {
        to_eye.x = stp_fix_sub(s->view.from.x, in->point.x);
        to_eye.y = stp_fix_sub(s->view.from.y, in->point.y);
        to_eye.z = stp_fix_sub(s->view.from.z, in->point.z);
    }
    if (stp_vec3_dot(in->normal, to_eye) < 0) {
        in->normal.x = -in->normal.x;
        in->normal.y = -in->normal.y;
        in->normal.z = -in->normal.z;
    }
    return 1;
}

static volatile uint32_t shade_sink;

/* See bench_shade.h. */
uint32_t stp_bench_shade(const stp_scene_data *s, uint32_t per_tick, uint32_t *calls)
{
    shade_input in[STP_FW_SHADE_INPUTS];
    const stp_vec3 *v = s->vertices;
    stp_vec3 dir = {0, 0, 0}, back;
    uint32_t i = 0, k, rep, used = 0, acc = 0;
    int parallel = s->view.projection == STP_PARALLEL;
    uint64_t t0, t1, n;

    back.x = stp_fix_sub(s->view.from.x, s->view.at.x);
    back.y = stp_fix_sub(s->view.from.y, s->view.at.y);
    back.z = stp_fix_sub(s->view.from.z, s->view.at.z);
    if (stp_vec3_unity(back, &dir) == 0)
        dir.z = STP_FIX_ONE;
    *calls = 0;
    if (s->polygon_count == 0)
        return 0;
    for (k = 0; k < STP_FW_SHADE_INPUTS && i < s->polygon_count; k++) {
        uint32_t target = (uint32_t)(((uint64_t)k * s->polygon_count) / STP_FW_SHADE_INPUTS);
        while (i < target) {
            v += s->polygons[i].count;
            i++;
        }
        /* a polygon with no direction gives way to the next one */
        while (i < s->polygon_count && !polygon_input(s, &s->polygons[i], v, dir, &in[used])) {
            v += s->polygons[i].count;
            i++;
        }
        if (i < s->polygon_count)
            used++;
    }
    if (used == 0)
        return 0;

    t0 = stp_count_now();
    for (rep = 0; rep < STP_FW_SHADE_REPEAT; rep++)
        for (k = 0; k < used; k++)
            acc += (uint32_t)stp_shade_point(&s->lighting, in[k].material, in[k].normal,
                                             in[k].point, s->view.from, parallel, dir);
    t1 = stp_count_now();
    shade_sink = acc; /* the shades are used, whatever the compiler sees */

    n = (uint64_t)used * STP_FW_SHADE_REPEAT;
    *calls = (uint32_t)n;
    return (uint32_t)(((t1 - t0) * per_tick + n / 2u) / n);
}
