/* SPDX-License-Identifier: MIT */
/* Host side: shadow maps covering a scene.  See shadows_setup.h. */
#include "shadows_setup.h"

#include <math.h>
#include <stdio.h>

#include "render_scene.h"
#include "scene_util.h"

#define PI 3.14159265358979323846

int stp_tool_shadow_view(stp_scene_vec3 centre, double radius, stp_scene_vec3 light,
                         stp_shadow_view *out)
{
    double dx = centre.x - light.x, dy = centre.y - light.y, dz = centre.z - light.z;
    double d = sqrt(dx * dx + dy * dy + dz * dz), fov, near;
    if (!(d > 0))
        return -1;
    if (radius < 0)
        radius = 0;
    if (d > 1.05 * radius) {
        fov = 2 * asin(radius / d) * 180 / PI + 2;
        if (fov > 170)
            fov = 170;
        near = 0.9 * (d - radius);
        if (near < d / 1000)
            near = d / 1000;
    } else {
        fov = 150;
        near = (radius > 0 ? radius : d) / 1000;
    }
    out->target.x = stp_tool_fix(centre.x);
    out->target.y = stp_tool_fix(centre.y);
    out->target.z = stp_tool_fix(centre.z);
    out->fov_degrees = stp_tool_fix(fov);
    out->near = stp_tool_fix(near);
    if (out->near <= 0)
        out->near = 1;
    return 0;
}

static double to_double(stp_fix v)
{
    return (double)v / STP_FIX_ONE;
}

int stp_tool_shadows_setup(stp_renderer *r, const stp_scene *scene, const stp_view *view,
                           double aspect, const stp_lighting *lighting, uint32_t resolution,
                           uint16_t *maps, size_t map_count, char *err, size_t err_size)
{
    stp_scene_vec3 lo, hi, centre, at;
    size_t per_map = (size_t)resolution * resolution;
    double radius, seen, dx, dy, dz;
    int j;
    if (resolution < 1 || resolution > 32767) {
        snprintf(err, err_size, "shadow map resolution %u outside 1..32767", (unsigned)resolution);
        return -1;
    }
    if (lighting->count < 0 || map_count / per_map < (size_t)lighting->count) {
        snprintf(err, err_size, "shadow maps: %zu entries for %d maps of %zu", map_count,
                 lighting->count, per_map);
        return -1;
    }
    if (stp_scene_bounds(scene, &lo, &hi) != 0) {
        snprintf(err, err_size, "the scene has no polygons to render");
        return -1;
    }
    centre.x = (lo.x + hi.x) / 2;
    centre.y = (lo.y + hi.y) / 2;
    centre.z = (lo.z + hi.z) / 2;
    dx = (hi.x - lo.x) / 2;
    dy = (hi.y - lo.y) / 2;
    dz = (hi.z - lo.z) / 2;
    radius = sqrt(dx * dx + dy * dy + dz * dz);
    /* the part of the scene the view shows, roughly: the window at the
     * depth of the scene's centre (not at 'at', which NFF may place
     * anywhere along the line of sight, even next to the eye) */
    if (view->projection == STP_PERSPECTIVE) {
        stp_scene_vec3 from, dir;
        double len, depth;
        from.x = to_double(view->from.x);
        from.y = to_double(view->from.y);
        from.z = to_double(view->from.z);
        dir.x = to_double(view->at.x) - from.x;
        dir.y = to_double(view->at.y) - from.y;
        dir.z = to_double(view->at.z) - from.z;
        len = sqrt(dir.x * dir.x + dir.y * dir.y + dir.z * dir.z);
        depth = len > 0 ? ((centre.x - from.x) * dir.x + (centre.y - from.y) * dir.y +
                           (centre.z - from.z) * dir.z) / len
                        : 0;
        /* a centre behind the eye: what is seen starts at the near side */
        if (depth < radius / 4)
            depth = radius / 4;
        at.x = from.x + dir.x / len * depth;
        at.y = from.y + dir.y / len * depth;
        at.z = from.z + dir.z / len * depth;
        seen = depth * tan(to_double(view->fov_degrees) * PI / 360);
    } else {
        at.x = to_double(view->at.x);
        at.y = to_double(view->at.y);
        at.z = to_double(view->at.z);
        seen = to_double(view->window_half);
    }
    seen *= 2 * (aspect > 1 ? aspect : 1);
    if (seen > 0 && seen < radius) {
        centre = at;
        radius = seen;
    }
    for (j = 0; j < lighting->count; j++) {
        stp_shadow_view sv;
        stp_scene_vec3 l;
        int status;
        l.x = to_double(lighting->lights[j].position.x);
        l.y = to_double(lighting->lights[j].position.y);
        l.z = to_double(lighting->lights[j].position.z);
        if (stp_tool_shadow_view(centre, radius, l, &sv) != 0) {
            snprintf(err, err_size, "light %d stands where its map must look: no direction", j + 1);
            return -1;
        }
        status = stp_renderer_set_shadow_map(r, j, maps + (size_t)j * per_map, per_map, resolution, resolution, &sv);
        if (status != STP_OK) {
            snprintf(err, err_size, "shadow map of light %d: %s", j + 1, stp_status_text(status));
            return -1;
        }
    }
    return 0;
}
