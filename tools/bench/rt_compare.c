/* SPDX-License-Identifier: MIT */
/* The ray tracer against its reference, and its speed: see rt_compare.h. */
#define _POSIX_C_SOURCE 200809L
#include "rt_compare.h"
#include "scene_prepare.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "raytrace_ref.h"

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

static double dfix(stp_fix v)
{
    return (double)v / (double)STP_FIX_ONE;
}

/* a scene point as the core got it, in double */
static ref_vec3 dvec_fix(stp_vec3 f)
{
    return ref_v3(dfix(f.x), dfix(f.y), dfix(f.z));
}

static ref_vec3 dvec(stp_scene_vec3 v)
{
    return dvec_fix(stp_tool_vec3(v));
}

/* The reference given the core's inputs (t from stp_tool_rt_build). */
static ref_rt *reference_of(const stp_scene *scene, const stp_tool_options *opt,
                            const stp_tool_rt *t, ref_rt_material **table_out)
{
    ref_rt *ref = ref_rt_create(opt->width, opt->height);
    ref_rt_material *table = calloc(t->material_count, sizeof *table);
    ref_view v;
    ref_lighting l;
    size_t i;
    int j, k;
    if (!ref || !table) {
        ref_rt_free(ref);
        free(table);
        return 0;
    }
    v.from = dvec_fix(t->view.from);
    v.at = dvec_fix(t->view.at);
    v.up = dvec_fix(t->view.up);
    v.fov_degrees = dfix(t->view.fov_degrees);
    v.window_half = dfix(t->view.window_half);
    v.hither = dfix(t->view.hither);
    v.perspective = t->view.projection == STP_PERSPECTIVE;
    (void)ref_rt_set_view(ref, &v);
    memset(&l, 0, sizeof l);
    l.brightness = dfix(t->lighting.brightness);
    l.background = dfix(t->lighting.background);
    l.c = dfix(t->lighting.attenuation_c);
    l.count = t->lighting.count;
    for (j = 0; j < l.count; j++) {
        l.lights[j].position = dvec_fix(t->lighting.lights[j].position);
        l.lights[j].power = dfix(t->lighting.lights[j].power);
    }
    ref_rt_set_lighting(ref, &l);
    for (i = 0; i < t->material_count; i++) {
        const stp_rt_material *m = &t->materials[i];
        table[i].surface.reflectivity = dfix(m->surface.reflectivity);
        table[i].surface.refraction = dfix(m->surface.refraction);
        table[i].surface.gloss = dfix(m->surface.gloss);
        table[i].surface.specular = dfix(m->surface.specular);
        table[i].transmission = dfix(m->transmission);
        table[i].absorption = dfix(m->absorption);
    }
    ref_rt_set_materials(ref, table, t->material_count);
    (void)ref_rt_set_recursion(ref, opt->rt_depth, dfix(stp_tool_fix(opt->rt_min_weight)));
    for (i = 0; i < scene->prim_count; i++) {
        const stp_scene_prim *pr = &scene->prims[i];
        int m = (int)stp_tool_rt_material(scene, pr->material);
        double rb = dfix(stp_tool_fix(fabs(pr->base_radius)));
        double ra = dfix(stp_tool_fix(fabs(pr->apex_radius)));
        if (pr->kind == STP_SCENE_SPHERE)
            (void)ref_rt_sphere(ref, dvec(pr->base), rb, m);
        else
            (void)ref_rt_cone(ref, dvec(pr->base), rb, dvec(pr->apex), ra, m);
    }
    for (i = 0; i < scene->polygon_count; i++) {
        const stp_scene_polygon *p = &scene->polygons[i];
        ref_vec3 vv[STP_MAX_POLYGON_VERTICES], vn[STP_MAX_POLYGON_VERTICES];
        int m = (int)stp_tool_rt_material(scene, p->material);
        if (p->prim >= 0 || p->count > STP_MAX_POLYGON_VERTICES)
            continue;
        for (k = 0; k < p->count; k++) {
            vv[k] = dvec(scene->vertices[p->first + (size_t)k]);
            vn[k] = dvec(scene->normals[p->first + (size_t)k]);
        }
        (void)ref_rt_polygon(ref, vv, p->has_normals ? vn : 0, p->count, m);
    }
    *table_out = table;
    return ref;
}

static double background_of(const stp_scene *scene)
{
    if (scene->has_background) {
        const double *b = scene->background;
        double lum = 0.30 * b[0] + 0.59 * b[1] + 0.11 * b[2];
        return dfix(stp_tool_fix(lum < 0 ? 0 : (lum > 1 ? 1 : lum)));
    }
    return 0;
}

static int compare_prepared(const stp_scene *scene, const stp_tool_options *opt, stp_rt_error *e,
                            double *shades, char *err, size_t err_size);

/* Both tracers get the scene as the tools prepare it (units, lights,
 * split polygons: scene_prepare.h); preparing again inside
 * stp_tool_rt_build changes nothing. */
int stp_rt_compare(const stp_scene *scene, const stp_tool_options *opt, stp_rt_error *e,
                   double *shades, char *err, size_t err_size)
{
    stp_tool_prepared prep;
    int rc;
    memset(e, 0, sizeof *e);
    if (stp_tool_prepare(scene, opt, &prep, err, err_size) != 0)
        return -1;
    rc = compare_prepared(&prep.scene, &prep.opt, e, shades, err, err_size);
    stp_tool_prepared_free(&prep);
    return rc;
}

static int compare_prepared(const stp_scene *scene, const stp_tool_options *opt, stp_rt_error *e,
                            double *shades, char *err, size_t err_size)
{
    stp_tool_rt t;
    stp_tool_stats stats;
    ref_rt_material *table = 0;
    ref_rt *ref;
    stp_fix bg[3];
    double bgd = background_of(scene), sum = 0;
    int x, y;
    memset(e, 0, sizeof *e);
    memset(&stats, 0, sizeof stats);
    if (stp_tool_rt_build(scene, opt, &t, &stats, err, err_size) != 0)
        return -1;
    ref = reference_of(scene, opt, &t, &table);
    if (ref) /* the core's shadow rays pass a patch's neighbouring facets */
        ref_rt_set_smooth_shadows(ref, 1);
    if (!ref) {
        stp_tool_rt_free(&t);
        snprintf(err, err_size, "out of memory for the reference");
        return -1;
    }
    bg[0] = bg[1] = bg[2] = stp_tool_fix(bgd);
    for (y = 0; y < opt->height; y++) {
        for (x = 0; x < opt->width; x++) {
            stp_fix core[3];
            double r = ref_rt_trace_pixel(ref, x, y, bgd), c, d;
            if (stp_rt_trace_pixel(t.rt, (uint32_t)x, (uint32_t)y, bg, core) != STP_OK || r < 0) {
                snprintf(err, err_size, "pixel (%d, %d) could not be traced", x, y);
                ref_rt_free(ref);
                free(table);
                stp_tool_rt_free(&t);
                return -1;
            }
            c = dfix(core[0]);
            d = fabs(c - r);
            if (shades) {
                shades[(size_t)y * (size_t)opt->width + (size_t)x] = c;
                shades[(size_t)opt->width * (size_t)opt->height + (size_t)y * (size_t)opt->width +
                       (size_t)x] = r;
            }
            if (d > e->max) {
                e->max = d;
                e->max_x = x;
                e->max_y = y;
            }
            sum += d;
            if (d > 1.0 / 30)
                e->above_step++;
            {
                /* INTENSITY of each: INT(s (levels - 1) + 1), the core's from its
                 * own fixed-point shade */
                int ic = stp_intensity_index(core[0], opt->levels);
                int ir = (int)floor(r * (opt->levels - 1) + 1);
                if (ir > opt->levels)
                    ir = opt->levels;
                if (ic != ir)
                    e->style_differs++;
            }
            e->pixels++;
        }
    }
    e->mean = e->pixels ? sum / (double)e->pixels : 0;
    ref_rt_free(ref);
    free(table);
    stp_tool_rt_free(&t);
    return 0;
}

static int null_flush(stp_port *port, uint32_t y0, uint32_t rows, const uint8_t *pixels,
                      size_t stride)
{
    (void)port;
    (void)y0;
    (void)rows;
    (void)pixels;
    (void)stride;
    return 0;
}

int stp_rt_time(const stp_scene *scene, const stp_tool_options *opt, double budget,
                stp_rt_speed *s, char *err, size_t err_size)
{
    stp_tool_rt t;
    stp_tool_stats stats;
    stp_output out;
    stp_port port;
    stp_rt_stats rs;
    uint8_t *band;
    double start, best = 1e30, build_best = 1e30;
    int runs = 0, k;
    memset(s, 0, sizeof *s);
    memset(&stats, 0, sizeof stats);
    if (stp_tool_rt_build(scene, opt, &t, &stats, err, err_size) != 0)
        return -1;
    s->objects = stats.rt_objects;
    if (opt->rt_hierarchy) {
        /* the build is fast: repeat it to see its time at all */
        for (k = 0; k < 200; k++) {
            double t0 = now(), dt;
            if (stp_rt_build(t.rt) != STP_OK) {
                snprintf(err, err_size, "hierarchy build failed");
                stp_tool_rt_free(&t);
                return -1;
            }
            dt = now() - t0;
            if (dt < build_best)
                build_best = dt;
        }
        s->build_us = build_best * 1e6;
    }
    band = malloc((size_t)opt->width * (size_t)opt->height);
    if (!band) {
        stp_tool_rt_free(&t);
        snprintf(err, err_size, "out of memory");
        return -1;
    }
    memset(&out, 0, sizeof out);
    out.background = stp_tool_fix(background_of(scene));
    port.width = (uint32_t)opt->width;
    port.height = (uint32_t)opt->height;
    port.format = STP_PIXEL_GREY8;
    port.flush = null_flush;
    port.user = 0;
    start = now();
    do {
        double t0 = now(), dt;
        stp_rt_reset_stats(t.rt);
        if (stp_rt_render(t.rt, &port, &out, band, (size_t)opt->width * (size_t)opt->height,
                          (uint32_t)opt->height) != STP_OK) {
            snprintf(err, err_size, "render failed");
            free(band);
            stp_tool_rt_free(&t);
            return -1;
        }
        dt = now() - t0;
        if (dt < best)
            best = dt;
        runs++;
    } while (runs < 3 || (now() - start < budget && runs < 1000));
    stp_rt_get_stats(t.rt, &rs);
    s->frame_us = best * 1e6;
    s->rays = rs.rays;
    s->shadow_rays = rs.shadow_rays;
    s->box_tests = rs.box_tests;
    s->object_tests = rs.object_tests;
    free(band);
    stp_tool_rt_free(&t);
    return 0;
}

int stp_rt_bench(FILE *out, const char *scenes_dir, const char *const *names, int count,
                 const stp_tool_options *opt, double budget)
{
    int i, h;
    fprintf(out,
            "ray tracer, %dx%d, depth %d, min weight %g, STP_FIX_FRAC_BITS %d; best of repeated "
            "frames\n",
            opt->width, opt->height, opt->rt_depth, opt->rt_min_weight, STP_FIX_FRAC_BITS);
    fprintf(out, "%-10s %7s %-9s %10s %12s %10s %9s %9s %10s %10s %8s\n", "scene", "objects",
            "hierarchy", "build us", "us/frame", "rays", "shadow", "Mrays/s", "obj tests",
            "err max", "err mean");
    for (i = 0; i < count; i++) {
        char path[4096], err[512];
        stp_scene scene;
        stp_scene_options sopt;
        stp_rt_error e;
        stp_scene_options_default(&sopt);
        snprintf(path, sizeof path, "%s/%s.nff", scenes_dir, names[i]);
        if (stp_scene_load(path, &sopt, &scene, err, sizeof err) != 0) {
            fprintf(stderr, "stipple bench: %s\n", err);
            return -1;
        }
        if (stp_rt_compare(&scene, opt, &e, 0, err, sizeof err) != 0) {
            fprintf(stderr, "stipple bench: %s: %s\n", path, err);
            stp_scene_free(&scene);
            return -1;
        }
        for (h = 1; h >= 0; h--) {
            stp_tool_options o = *opt;
            stp_rt_speed s;
            o.rt_hierarchy = h;
            if (stp_rt_time(&scene, &o, budget, &s, err, sizeof err) != 0) {
                fprintf(stderr, "stipple bench: %s: %s\n", path, err);
                stp_scene_free(&scene);
                return -1;
            }
            fprintf(out, "%-10s %7lu %-9s %10.1f %12.0f %10lu %9lu %9.3f %10lu %10.2e %8.2e\n",
                    names[i], s.objects, h ? "BVH" : "none", s.build_us, s.frame_us, s.rays,
                    s.shadow_rays, (double)(s.rays + s.shadow_rays) / s.frame_us,
                    s.object_tests, e.max, e.mean);
        }
        stp_scene_free(&scene);
    }
    fprintf(out, "Mrays/s counts primary, secondary and shadow rays; err: |core - double "
                 "reference| shade over every pixel\n");
    return 0;
}
