/* SPDX-License-Identifier: MIT */
/*
 * libFuzzer target: the ray tracer on fuzzed scenes.  The input picks a
 * view, lights, materials and up to 24 spheres, cones and polygons (patches
 * too) anywhere inside the coordinate limit, at any size from one raw step
 * up: the extreme cases of raytrace.h (large distances, grazing and tangent
 * rays, secondary rays leaving surfaces).  Under ASan and UBSan any overflow
 * or out-of-bounds access is a finding; besides, every pixel traced through
 * the hierarchy must equal the one traced by testing every object, and
 * every shade must lie in [0, 1].
 */
#include <string.h>

#include "fuzz_common.h"
#include "stipple/stipple.h"

#define FZ_OBJECTS 24
#define FZ_W 12
#define FZ_H 9

/* A coordinate: mostly small (scene-like), sometimes anywhere within the
 * limit, sometimes one raw step from another value. */
static stp_fix coord(fz_reader *in)
{
    uint8_t kind = fz_u8(in);
    int32_t v = (int32_t)fz_u32(in);
    if (kind < 160)
        return (stp_fix)(v % (16 * STP_FIX_ONE));
    if (kind < 240)
        return (stp_fix)(v % STP_RT_COORD_LIMIT);
    return (stp_fix)(v % 4);
}

static stp_vec3 point(fz_reader *in)
{
    stp_vec3 p;
    p.x = coord(in);
    p.y = coord(in);
    p.z = coord(in);
    return p;
}

static stp_fix unit_fraction(fz_reader *in)
{
    return (stp_fix)((int64_t)fz_u16(in) * STP_FIX_ONE / 65535);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static stp_raytracer_storage storage;
    stp_rt_object objects[FZ_OBJECTS];
    stp_vec3 points[FZ_OBJECTS * 2 * 6];
    stp_rt_node nodes[2 * FZ_OBJECTS];
    uint32_t order[FZ_OBJECTS];
    stp_rt_material materials[4];
    stp_rt_memory mem;
    stp_raytracer *rt;
    stp_lighting lighting;
    stp_view view;
    fz_reader in;
    stp_fix bg[3];
    stp_fix plain[FZ_W * FZ_H];
    int i, k, count;
    uint32_t x, y;

    fz_init(&in, data, size);
    memset(&mem, 0, sizeof mem);
    mem.objects = objects;
    mem.object_capacity = FZ_OBJECTS;
    mem.points = points;
    mem.point_capacity = (uint32_t)(sizeof points / sizeof points[0]);
    mem.nodes = nodes;
    mem.node_capacity = 2 * FZ_OBJECTS;
    mem.order = order;
    rt = stp_rt_create(&storage, sizeof storage, &mem, FZ_W, FZ_H);
    FZ_CHECK(rt != 0, "create failed");

    view.from = point(&in);
    view.at = point(&in);
    view.up = point(&in);
    view.fov_degrees = (stp_fix)fz_range(&in, 1, 179) * STP_FIX_ONE;
    view.window_half = unit_fraction(&in) * 8 + 1;
    view.hither = unit_fraction(&in) + 1;
    view.projection = fz_u8(&in) & 1 ? STP_PARALLEL : STP_PERSPECTIVE;
    if (stp_rt_set_view(rt, &view) != STP_OK)
        return 0;
    stp_lighting_default(&lighting);
    lighting.count = fz_range(&in, 0, STP_MAX_LIGHTS);
    lighting.background = unit_fraction(&in);
    lighting.brightness = unit_fraction(&in) * 2;
    for (k = 0; k < lighting.count; k++) {
        lighting.lights[k].position = point(&in);
        lighting.lights[k].power = unit_fraction(&in) * 4;
        lighting.lights[k].colour[0] = lighting.lights[k].colour[1] = lighting.lights[k].colour[2] =
            STP_FIX_ONE;
    }
    FZ_CHECK(stp_rt_set_lighting(rt, &lighting) == STP_OK, "lighting refused");
    for (k = 0; k < 4; k++) {
        stp_material_default(&materials[k].surface);
        materials[k].surface.reflectivity = unit_fraction(&in);
        materials[k].surface.refraction = unit_fraction(&in) * 4 + 1;
        materials[k].surface.gloss = unit_fraction(&in);
        materials[k].surface.specular = unit_fraction(&in);
        materials[k].transmission = unit_fraction(&in);
        materials[k].absorption = unit_fraction(&in) * 2;
    }
    FZ_CHECK(stp_rt_set_materials(rt, materials, 4) == STP_OK, "materials refused");
    {
        int depth = fz_range(&in, 0, STP_RT_MAX_DEPTH);
        stp_fix min_weight = unit_fraction(&in) / 8;
        FZ_CHECK(stp_rt_set_recursion(rt, depth, min_weight) == STP_OK, "recursion refused");
    }

    count = fz_range(&in, 1, FZ_OBJECTS);
    for (i = 0; i < count && !fz_done(&in); i++) {
        uint8_t kind = fz_u8(&in) % 3;
        uint32_t m = fz_u8(&in) % 4;
        /* one read per statement: the order of a call's arguments is
         * unspecified, and the input must mean the same scene everywhere */
        if (kind == 0) {
            stp_vec3 centre = point(&in);
            stp_fix radius = coord(&in);
            (void)stp_rt_sphere(rt, centre, radius, m);
        } else if (kind == 1) {
            stp_vec3 base = point(&in), apex = point(&in);
            stp_fix base_radius = coord(&in), apex_radius = coord(&in);
            (void)stp_rt_cone(rt, base, base_radius, apex, apex_radius, m);
        } else {
            stp_vec3 v[6], n[6];
            int nv = fz_range(&in, 3, 6), smooth = fz_u8(&in) & 1;
            for (k = 0; k < nv; k++) {
                v[k] = point(&in);
                n[k] = point(&in);
            }
            (void)stp_rt_polygon(rt, v, smooth ? n : 0, nv, m);
        }
    }
    bg[0] = bg[1] = bg[2] = unit_fraction(&in);
    for (y = 0; y < FZ_H; y++)
        for (x = 0; x < FZ_W; x++) {
            stp_fix s[3];
            FZ_CHECK(stp_rt_trace_pixel(rt, x, y, bg, s) == STP_OK, "pixel refused");
            FZ_CHECK(s[0] >= 0 && s[0] <= STP_FIX_ONE, "shade %d outside [0, 1]", (int)s[0]);
            plain[y * FZ_W + x] = s[0];
        }
    FZ_CHECK(stp_rt_build(rt) == STP_OK, "build refused");
    for (y = 0; y < FZ_H; y++)
        for (x = 0; x < FZ_W; x++) {
            stp_fix s[3];
            FZ_CHECK(stp_rt_trace_pixel(rt, x, y, bg, s) == STP_OK, "pixel refused");
            FZ_CHECK(s[0] == plain[y * FZ_W + x],
                     "pixel (%u, %u): hierarchy %d, every object %d", x, y, (int)s[0],
                     (int)plain[y * FZ_W + x]);
        }
    return 0;
}
