/* SPDX-License-Identifier: MIT */
/* The camera of a render or an animation: see camera.h. */
#include "camera.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene_util.h"

static const double degree = 3.14159265358979323846 / 180.0;

static stp_scene_vec3 v3(double x, double y, double z)
{
    stp_scene_vec3 v;
    v.x = x;
    v.y = y;
    v.z = z;
    return v;
}
static stp_scene_vec3 sub(stp_scene_vec3 a, stp_scene_vec3 b)
{
    return v3(a.x - b.x, a.y - b.y, a.z - b.z);
}
static stp_scene_vec3 add_scaled(stp_scene_vec3 a, stp_scene_vec3 b, double k)
{
    return v3(a.x + b.x * k, a.y + b.y * k, a.z + b.z * k);
}
static double dot(stp_scene_vec3 a, stp_scene_vec3 b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
static stp_scene_vec3 cross(stp_scene_vec3 a, stp_scene_vec3 b)
{
    return v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static double length(stp_scene_vec3 a)
{
    return sqrt(dot(a, a));
}

int stp_tool_parse_point(const char *s, stp_scene_vec3 *v)
{
    double x, y, z;
    char extra;
    if (sscanf(s, "%lf,%lf,%lf%c", &x, &y, &z, &extra) != 3 || !isfinite(x) || !isfinite(y) ||
        !isfinite(z))
        return -1;
    *v = v3(x, y, z);
    return 0;
}

int stp_tool_camera_wanted(const stp_tool_options *opt)
{
    return opt->eye_count > 0 || opt->at_count > 0 || opt->up_given;
}

/* Key `count` points spread evenly over frames 0..frames-1: the point of
 * frame i, linearly between its two keys. */
static stp_scene_vec3 along_keys(const stp_scene_vec3 *keys, int count, int frame, int frames)
{
    double s;
    int k;
    if (count == 1 || frames <= 1)
        return keys[0];
    s = (double)frame * (count - 1) / (frames - 1);
    k = (int)floor(s);
    if (k >= count - 1)
        return keys[count - 1];
    s -= k;
    return add_scaled(keys[k], sub(keys[k + 1], keys[k]), s);
}

/* p turned by angle radians about the unit axis u through centre
 * (right-handed: counter-clockwise seen from the tip of u). */
static stp_scene_vec3 turn(stp_scene_vec3 p, stp_scene_vec3 centre, stp_scene_vec3 u, double angle)
{
    stp_scene_vec3 v = sub(p, centre), r;
    double c = cos(angle), s = sin(angle);
    r = v3(v.x * c, v.y * c, v.z * c);
    r = add_scaled(r, cross(u, v), s);
    r = add_scaled(r, u, dot(u, v) * (1 - c));
    return add_scaled(centre, r, 1.0);
}

/* The eye at the same distance from at, raised to elevation radians above
 * the plane square to the unit up u. */
static stp_scene_vec3 raise(stp_scene_vec3 eye, stp_scene_vec3 at, stp_scene_vec3 u, double elevation)
{
    stp_scene_vec3 d = sub(eye, at), flat;
    double dist = length(d), fl;
    flat = add_scaled(d, u, -dot(d, u));
    fl = length(flat);
    if (fl < 1e-9 * dist) {
        /* looking along up: any direction square to it will do */
        flat = fabs(u.x) < 0.9 ? cross(u, v3(1, 0, 0)) : cross(u, v3(0, 1, 0));
        fl = length(flat);
    }
    flat = v3(flat.x / fl, flat.y / fl, flat.z / fl);
    return add_scaled(add_scaled(at, flat, dist * cos(elevation)), u, dist * sin(elevation));
}

int stp_tool_camera_view(const stp_scene *scene, const stp_tool_options *opt,
                         const stp_tool_motion *motion, int frame, stp_tool_view *view,
                         double *turn_radians, char *err, size_t err_size)
{
    int frames = motion ? motion->frames : 1;
    stp_scene_vec3 u, d;
    double ul, dl;
    if (stp_tool_view_of(scene, opt, view) != 0) {
        snprintf(err, err_size, "the scene has no polygons to render");
        return -1;
    }
    if (opt->eye_count > 0)
        view->from = along_keys(opt->eye, opt->eye_count, frame, frames);
    if (opt->at_count > 0)
        view->at = along_keys(opt->at, opt->at_count, frame, frames);
    if (opt->up_given)
        view->up = opt->up;
    u = view->up;
    ul = length(u);
    if (!(ul > 0)) {
        snprintf(err, err_size, "--up: the up vector has no length");
        return -1;
    }
    u = v3(u.x / ul, u.y / ul, u.z / ul);
    *turn_radians = motion ? motion->orbit_degrees * degree * frame / frames : 0.0;
    view->from = turn(view->from, view->at, u, *turn_radians);
    if (motion && motion->elevation_given)
        view->from = raise(view->from, view->at, u, motion->elevation_degrees * degree);
    d = sub(view->at, view->from);
    dl = length(d);
    if (!(dl > 0)) {
        snprintf(err, err_size, "frame %d: the eye (--eye) is on the look-at point (--at)", frame + 1);
        return -1;
    }
    if (length(cross(d, u)) < 1e-6 * dl) {
        snprintf(err, err_size, "frame %d: up (--up) is along the line of sight", frame + 1);
        return -1;
    }
    if (!scene->has_view || opt->eye_count > 0 || opt->at_count > 0)
        view->hither = dl * 1e-3;
    return 0;
}

/* The light stp_tool_setup gives a scene with no view and no lights:
 * above and left of its centre (render_scene.c). */
static int default_light(const stp_scene *scene, stp_scene_vec3 *light)
{
    stp_scene_vec3 lo, hi;
    double radius;
    if (stp_scene_bounds(scene, &lo, &hi) != 0)
        return -1;
    radius = length(sub(hi, lo)) / 2;
    if (radius <= 0)
        radius = 1;
    *light = v3((lo.x + hi.x) / 2 - radius, (lo.y + hi.y) / 2 + radius * 2, (lo.z + hi.z) / 2 + radius * 3);
    return 0;
}

int stp_tool_camera_apply(const stp_scene *scene, const stp_tool_options *opt,
                          const stp_tool_motion *motion, int frame, stp_tool_camera_scene *out,
                          stp_tool_options *opt_out, char *err, size_t err_size)
{
    stp_tool_view view;
    stp_scene_vec3 u;
    double angle, ul;
    size_t j;
    int k;
    memset(out, 0, sizeof *out);
    if (stp_tool_camera_view(scene, opt, motion, frame, &view, &angle, err, err_size) != 0)
        return -1;
    out->scene = *scene;
    out->scene.has_view = 1;
    out->scene.from = view.from;
    out->scene.at = view.at;
    out->scene.up = view.up;
    out->scene.angle = view.fov_degrees;
    out->scene.hither = view.hither;
    *opt_out = *opt;
    opt_out->eye_count = opt_out->at_count = opt_out->up_given = 0;
    opt_out->fov = view.fov_degrees;
    if (!scene->has_view && scene->light_count == 0 && opt->light_count == 0 &&
        default_light(scene, &opt_out->lights[0]) == 0)
        opt_out->light_count = 1; /* where the scene's view would have put it */
    if (angle == 0.0)
        return 0;
    ul = length(view.up);
    u = v3(view.up.x / ul, view.up.y / ul, view.up.z / ul);
    if (scene->light_count > 0) {
        out->lights = malloc(sizeof *out->lights * scene->light_count);
        if (!out->lights) {
            snprintf(err, err_size, "out of memory");
            return -1;
        }
        for (j = 0; j < scene->light_count; j++) {
            out->lights[j] = scene->lights[j];
            out->lights[j].position = turn(scene->lights[j].position, view.at, u, angle);
        }
        out->scene.lights = out->lights;
    }
    for (k = 0; k < opt_out->light_count; k++)
        opt_out->lights[k] = turn(opt_out->lights[k], view.at, u, angle);
    return 0;
}

void stp_tool_camera_free(stp_tool_camera_scene *c)
{
    free(c->lights);
    c->lights = 0;
}
