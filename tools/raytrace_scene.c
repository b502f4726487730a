/* SPDX-License-Identifier: MIT */
/* Host side: a stp_scene through the core's ray tracer.  See render_scene.h
 * (stp_tool_raytrace).
 *
 * Scene to ray tracer: NFF spheres and cones go in as themselves (their
 * tessellations, which the polygon renderer draws, are left out); every
 * other polygon goes in as a polygon, with its vertex normals when the file
 * gives them (NFF pp, OBJ vn, OFF normals): a patch.  Materials as the
 * polygon renderer maps them (stp_tool_material), plus NFF's T as the
 * transmission; no absorption (NFF has none).  View, lighting, levels,
 * halftone, gamma and background as stp_tool_render. */
#define _POSIX_C_SOURCE 200809L
#include "render_scene.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "scene_prepare.h"

static double seconds_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

uint32_t stp_tool_rt_material(const stp_scene *scene, int material)
{
    return material >= 0 && (size_t)material < scene->material_count
               ? (uint32_t)material
               : (uint32_t)scene->material_count;
}

static int build_prepared(const stp_tool_prepared *prep, stp_tool_rt *t, stp_tool_stats *stats,
                          char *err, size_t err_size);

int stp_tool_rt_build(const stp_scene *scene, const stp_tool_options *opt, stp_tool_rt *t,
                      stp_tool_stats *stats, char *err, size_t err_size)
{
    stp_tool_prepared prep;
    int rc;
    memset(t, 0, sizeof *t);
    if (stp_tool_prepare(scene, opt, &prep, err, err_size) != 0)
        return -1;
    rc = build_prepared(&prep, t, stats, err, err_size);
    stp_tool_prepared_free(&prep);
    return rc;
}

/* The ray tracer loaded with a prepared scene. */
static int build_prepared(const stp_tool_prepared *prep, stp_tool_rt *t, stp_tool_stats *stats,
                          char *err, size_t err_size)
{
    const stp_scene *scene = &prep->scene;
    const stp_tool_options *opt = &prep->opt;
    stp_rt_memory mem;
    stp_rt_material *materials = 0;
    size_t objects = 0, points = 0, i, material_count;
    int status;
    double t0;

    memset(&mem, 0, sizeof mem);
    if (stp_tool_setup_prepared(prep, &t->view, &t->lighting, err, err_size) != 0)
        return -1;
    for (i = 0; i < scene->polygon_count; i++) {
        const stp_scene_polygon *p = &scene->polygons[i];
        if (p->prim >= 0)
            continue;
        objects++;
        points += (size_t)p->count * (p->has_normals ? 2u : 1u);
    }
    objects += scene->prim_count;
    if (objects == 0) {
        snprintf(err, err_size, "the scene has nothing to ray-trace");
        return -1;
    }
    if (objects > 0x7FFFFFFFu || points > 0xFFFFFFFFu) {
        snprintf(err, err_size, "scene too large for the ray tracer");
        return -1;
    }
    /* the scene's materials, then a default for polygons without one */
    material_count = scene->material_count + 1;
    materials = calloc(material_count, sizeof *materials);
    mem.objects = calloc(objects, sizeof *mem.objects);
    mem.object_capacity = (uint32_t)objects;
    mem.points = calloc(points ? points : 1, sizeof *mem.points);
    mem.point_capacity = (uint32_t)points;
    mem.nodes = calloc(2 * objects, sizeof *mem.nodes);
    mem.node_capacity = (uint32_t)(2 * objects);
    mem.order = calloc(objects, sizeof *mem.order);
    t->storage = malloc(stp_rt_size());
    t->mem = mem;
    t->materials = materials;
    t->material_count = material_count;
    if (!materials || !mem.objects || !mem.points || !t->storage || !mem.nodes || !mem.order) {
        snprintf(err, err_size, "out of memory");
        goto fail;
    }
    for (i = 0; i < material_count; i++) {
        stp_material_default(&materials[i].surface);
        if (i < scene->material_count) {
            double tr = scene->materials[i].t;
            stp_tool_material(&scene->materials[i], opt->colour, &materials[i].surface);
            materials[i].transmission = stp_tool_fix(tr < 0 ? 0 : (tr > 1 ? 1 : tr));
        }
    }
    t->rt = stp_rt_create(t->storage, stp_rt_size(), &mem, (uint32_t)opt->width,
                          (uint32_t)opt->height);
    if (!t->rt) {
        snprintf(err, err_size, "bad size %dx%d", opt->width, opt->height);
        goto fail;
    }
    if ((status = stp_rt_set_view(t->rt, &t->view)) != STP_OK ||
        (status = stp_rt_set_lighting(t->rt, &t->lighting)) != STP_OK ||
        (status = stp_rt_set_levels(t->rt, opt->levels)) != STP_OK ||
        (status = stp_rt_set_materials(t->rt, materials, (uint32_t)material_count)) != STP_OK ||
        (status = stp_rt_set_recursion(t->rt, opt->rt_depth, stp_tool_fix(opt->rt_min_weight))) !=
            STP_OK ||
        (opt->colour && (status = stp_rt_set_colour(t->rt, 1)) != STP_OK)) {
        snprintf(err, err_size, "ray tracer set-up: %s (coordinates must stay within +-%g units)",
                 stp_status_text(status), (double)STP_RT_COORD_LIMIT / STP_FIX_ONE);
        goto fail;
    }
    for (i = 0; i < scene->prim_count; i++) {
        const stp_scene_prim *pr = &scene->prims[i];
        uint32_t m = stp_tool_rt_material(scene, pr->material);
        /* NFF: a negative radius only turns the tessellation's normals
         * inwards; the ray tracer's lighting is two-sided anyway */
        double rb = pr->base_radius < 0 ? -pr->base_radius : pr->base_radius;
        double ra = pr->apex_radius < 0 ? -pr->apex_radius : pr->apex_radius;
        if (pr->kind == STP_SCENE_SPHERE)
            status = stp_rt_sphere(t->rt, stp_tool_vec3(pr->base), stp_tool_fix(rb), m);
        else
            status = stp_rt_cone(t->rt, stp_tool_vec3(pr->base), stp_tool_fix(rb),
                                 stp_tool_vec3(pr->apex), stp_tool_fix(ra), m);
        if (status == STP_ERR_DEGENERATE) {
            stats->polygons_skipped++;
            continue;
        }
        if (status != STP_OK) {
            snprintf(err, err_size, "%s %zu: %s", pr->kind == STP_SCENE_SPHERE ? "sphere" : "cone",
                     i + 1, stp_status_text(status));
            goto fail;
        }
    }
    for (i = 0; i < scene->polygon_count; i++) {
        const stp_scene_polygon *p = &scene->polygons[i];
        stp_vec3 v[STP_MAX_POLYGON_VERTICES], vn[STP_MAX_POLYGON_VERTICES];
        uint32_t m = stp_tool_rt_material(scene, p->material);
        int k;
        if (p->prim >= 0)
            continue;
        if (p->count > STP_MAX_POLYGON_VERTICES) {
            snprintf(err, err_size, "%d: polygon %zu has %d vertices; this build takes %d",
                     p->source_line, i + 1, p->count, STP_MAX_POLYGON_VERTICES);
            goto fail;
        }
        for (k = 0; k < p->count; k++) {
            v[k] = stp_tool_vec3(scene->vertices[p->first + (size_t)k]);
            if (p->has_normals)
                vn[k] = stp_tool_vec3(scene->normals[p->first + (size_t)k]);
        }
        stats->polygons_in++;
        status = stp_rt_polygon(t->rt, v, p->has_normals ? vn : 0, p->count, m);
        if (status == STP_ERR_DEGENERATE) {
            stats->polygons_skipped++;
            continue;
        }
        if (status != STP_OK) {
            snprintf(err, err_size, "%d: polygon %zu: %s", p->source_line, i + 1,
                     stp_status_text(status));
            goto fail;
        }
    }
    stats->rt_objects = stp_rt_object_count(t->rt);
    t->points_used = points;
    if (opt->rt_hierarchy) {
        t0 = seconds_now();
        status = stp_rt_build(t->rt);
        stats->rt_build_seconds = seconds_now() - t0;
        if (status != STP_OK) {
            snprintf(err, err_size, "hierarchy: %s", stp_status_text(status));
            goto fail;
        }
        stats->rt_nodes = 2 * stats->rt_objects - 1;
    }
    return 0;
fail:
    stp_tool_rt_free(t);
    return -1;
}

void stp_tool_rt_free(stp_tool_rt *t)
{
    free(t->materials);
    free(t->mem.objects);
    free(t->mem.points);
    free(t->mem.nodes);
    free(t->mem.order);
    free(t->storage);
    memset(t, 0, sizeof *t);
}

int stp_tool_raytrace(const stp_scene *scene, const stp_tool_options *opt, stp_port *port,
                      stp_tool_stats *stats, char *err, size_t err_size)
{
    stp_tool_rt t;
    uint8_t *band = 0, *gamma = 0;
    stp_cell cell;
    stp_output out;
    stp_fix background_rgb[3];
    stp_tool_stats local;
    size_t band_size;
    int status, result = -1, band_rows;
    double t0;
    stp_diffusion diffusion;
    int diffusing = 0;

    memset(&diffusion, 0, sizeof diffusion);
    if (!stats)
        stats = &local;
    memset(stats, 0, sizeof *stats);
    if (stp_tool_rt_build(scene, opt, &t, stats, err, err_size) != 0)
        return -1;
    if (stp_tool_output(scene, opt, &out, &cell, &gamma, background_rgb, err, err_size) != 0)
        goto done;
    band_rows = stp_tool_band_rows(opt, port);
    diffusing = (port->format == STP_PIXEL_MONO1 || port->format == STP_PIXEL_MONO1_PAGES) &&
                stp_tool_diffusion(opt, (uint32_t)opt->width, &diffusion) != 0;
    if (diffusing)
        out.diffusion = &diffusion;
    /* error diffusion traces GREY8 rows (raytrace.h, stp_rt_render) */
    band_size = stp_tool_band_bytes(diffusing ? STP_PIXEL_GREY8 : port->format, (uint32_t)opt->width, band_rows);
    band = malloc(band_size ? band_size : 1);
    if (!band || (diffusing && !diffusion.errors)) {
        snprintf(err, err_size, "out of memory");
        goto done;
    }
    stats->frame_bytes = stp_rt_size() + sizeof *t.mem.objects * stats->rt_objects +
                         sizeof *t.mem.points * t.points_used +
                         (opt->rt_hierarchy ? (sizeof *t.mem.nodes * stats->rt_nodes +
                                               sizeof *t.mem.order * stats->rt_objects)
                                            : 0) +
                         band_size + sizeof(int16_t) * diffusion.error_count;
    t0 = seconds_now();
    status = stp_rt_render(t.rt, port, &out, band, band_size, (uint32_t)band_rows);
    stats->rt_trace_seconds = seconds_now() - t0;
    if (status != STP_OK) {
        snprintf(err, err_size, "ray trace: %s", stp_status_text(status));
        goto done;
    }
    {
        stp_rt_stats s;
        stp_rt_get_stats(t.rt, &s);
        stats->rt_rays = s.rays;
        stats->rt_shadow_rays = s.shadow_rays;
        stats->rt_box_tests = s.box_tests;
        stats->rt_object_tests = s.object_tests;
    }
    result = 0;
done:
    stp_tool_rt_free(&t);
    free(diffusion.errors);
    free(band);
    free(gamma);
    return result;
}
