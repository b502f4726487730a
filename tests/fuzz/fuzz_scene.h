/* SPDX-License-Identifier: MIT */
/*
 * The body of the scene-reader targets (fuzz_nff.c, fuzz_obj.c, fuzz_off.c):
 * the fuzz input is the file text, parsed from memory with
 * stp_scene_parse.  Beyond the sanitizers, the result is checked against
 * what tools/scene/scene.h promises:
 *  - failure: -1, a message "<name>:<line>: ..." or "<name>: ..." that fits
 *    the buffer, and an empty scene; the same failure with a tiny or no
 *    message buffer (a buffer of exactly that size, so an overrun is seen);
 *  - success: 0, at least one polygon, every polygon of >= 3 vertices inside
 *    the vertex array with a valid material, finite numbers everywhere,
 *    normals present where a polygon says so, and stp_scene_bounds agreeing.
 * The scene budget (stp_scene_byte_limit, a test hook of the readers) is
 * lowered to 32 KiB..4 MiB, chosen by the input's length, so inputs of a
 * few KB reach the "scene too large" path without the fuzzer spending
 * gigabytes; likewise the tessellation is the coarsest allowed (3 slices, 2
 * stacks) for one length in four, the default (16, 8) otherwise.
 */
#ifndef STP_FUZZ_SCENE_H
#define STP_FUZZ_SCENE_H

#include <math.h>
#include <string.h>

#include "fuzz_common.h"
#include "scene.h"
#include "scene_private.h"
#include "scene_util.h"

#define FZ_SCENE_NAME "fuzz-input"

static int fz_finite3(const stp_scene_vec3 *v)
{
    return isfinite(v->x) && isfinite(v->y) && isfinite(v->z);
}

static int fz_scene_is_empty(const stp_scene *s)
{
    return s->lights == NULL && s->materials == NULL && s->vertices == NULL &&
           s->normals == NULL && s->polygons == NULL && s->prims == NULL &&
           s->light_count == 0 && s->material_count == 0 && s->vertex_count == 0 &&
           s->polygon_count == 0 && s->prim_count == 0 && s->has_view == 0 &&
           s->has_background == 0;
}

static void fz_check_message(const char *err, size_t err_size)
{
    size_t len = strnlen(err, err_size);
    const size_t name_len = sizeof FZ_SCENE_NAME - 1;

    FZ_CHECK(len < err_size, "message not NUL-terminated within its buffer");
    FZ_CHECK(len > name_len + 2, "message too short: '%s'", err);
    FZ_CHECK(memcmp(err, FZ_SCENE_NAME ":", name_len + 1) == 0,
             "message does not start with the name: '%s'", err);
}

static void fz_check_scene(const stp_scene *s, const char *format)
{
    size_t i;

    FZ_CHECK(s->polygon_count > 0, "success without polygons");
    FZ_CHECK(s->vertices != NULL && s->normals != NULL && s->polygons != NULL,
             "missing arrays");
    FZ_CHECK(s->material_count > 0 && s->materials != NULL, "polygons but no material");
    for (i = 0; i < s->vertex_count; i++) {
        FZ_CHECK(fz_finite3(&s->vertices[i]), "vertex %zu not finite", i);
        FZ_CHECK(fz_finite3(&s->normals[i]), "normal %zu not finite", i);
    }
    for (i = 0; i < s->polygon_count; i++) {
        const stp_scene_polygon *p = &s->polygons[i];

        FZ_CHECK(p->count >= 3, "polygon %zu has %d vertices", i, p->count);
        FZ_CHECK(p->first <= s->vertex_count && (size_t)p->count <= s->vertex_count - p->first,
                 "polygon %zu (first %zu, count %d) outside %zu vertices", i, p->first,
                 p->count, s->vertex_count);
        FZ_CHECK(p->material >= 0 && (size_t)p->material < s->material_count,
                 "polygon %zu material %d of %zu", i, p->material, s->material_count);
        FZ_CHECK(p->has_normals == 0 || p->has_normals == 1, "polygon %zu has_normals %d", i,
                 p->has_normals);
        FZ_CHECK(p->source_line >= 1, "polygon %zu source line %d", i, p->source_line);
        if (!p->has_normals) {
            /* "zero where none" */
            int k;
            for (k = 0; k < p->count; k++) {
                const stp_scene_vec3 *n = &s->normals[p->first + (size_t)k];
                FZ_CHECK(n->x == 0.0 && n->y == 0.0 && n->z == 0.0,
                         "polygon %zu without normals has a non-zero normal", i);
            }
        }
    }
    for (i = 0; i < s->material_count; i++) {
        const stp_scene_material *m = &s->materials[i];
        FZ_CHECK(isfinite(m->color[0]) && isfinite(m->color[1]) && isfinite(m->color[2]) &&
                     isfinite(m->kd) && isfinite(m->ks) && isfinite(m->shine) &&
                     isfinite(m->t) && isfinite(m->ior),
                 "material %zu not finite", i);
    }
    for (i = 0; i < s->light_count; i++)
        FZ_CHECK(fz_finite3(&s->lights[i].position), "light %zu not finite", i);
    for (i = 0; i < s->prim_count; i++) {
        const stp_scene_prim *p = &s->prims[i];
        FZ_CHECK(p->kind == STP_SCENE_SPHERE || p->kind == STP_SCENE_CONE, "prim %zu kind", i);
        FZ_CHECK(p->material >= 0 && (size_t)p->material < s->material_count,
                 "prim %zu material %d", i, p->material);
        FZ_CHECK(fz_finite3(&p->base) && fz_finite3(&p->apex) && isfinite(p->base_radius) &&
                     isfinite(p->apex_radius),
                 "prim %zu not finite", i);
    }
    if (s->has_view) {
        FZ_CHECK(strcmp(format, "nff") == 0, "a view from a %s file", format);
        FZ_CHECK(fz_finite3(&s->from) && fz_finite3(&s->at) && fz_finite3(&s->up),
                 "view not finite");
        FZ_CHECK(s->angle > 0.0 && s->angle < 180.0, "view angle %g", s->angle);
        FZ_CHECK(s->hither >= 0.0 && isfinite(s->hither), "hither %g", s->hither);
        FZ_CHECK(s->resolution[0] >= 1 && s->resolution[1] >= 1, "resolution %d x %d",
                 s->resolution[0], s->resolution[1]);
    }
    if (s->has_background)
        FZ_CHECK(isfinite(s->background[0]) && isfinite(s->background[1]) &&
                     isfinite(s->background[2]),
                 "background not finite");
    {
        stp_scene_vec3 lo, hi;
        FZ_CHECK(stp_scene_bounds(s, &lo, &hi) == 0, "no bounds for a scene with geometry");
        FZ_CHECK(lo.x <= hi.x && lo.y <= hi.y && lo.z <= hi.z, "bounds inverted");
        for (i = 0; i < s->vertex_count; i++) {
            const stp_scene_vec3 *v = &s->vertices[i];
            FZ_CHECK(v->x >= lo.x && v->x <= hi.x && v->y >= lo.y && v->y <= hi.y &&
                         v->z >= lo.z && v->z <= hi.z,
                     "vertex %zu outside the bounds", i);
        }
    }
}

static int fz_scene_one(const uint8_t *data, size_t size, const char *format)
{
    stp_scene_options opt;
    stp_scene scene;
    char err[256];
    int rc;

    stp_scene_byte_limit = (size_t)32768 << (size % 8);
    stp_scene_options_default(&opt);
    if (size % 4 == 3) {
        opt.sphere_slices = 3;
        opt.sphere_stacks = 2;
        opt.cone_slices = 3;
    }
    memset(err, 'x', sizeof err);
    /* data is libFuzzer's own exact-sized copy: no terminating NUL to lean on */
    rc = stp_scene_parse((const char *)data, size, format, FZ_SCENE_NAME, &opt, &scene, err,
                         sizeof err);
    FZ_CHECK(rc == 0 || rc == -1, "stp_scene_parse returned %d", rc);
    if (rc == 0) {
        fz_check_scene(&scene, format);
        stp_scene_free(&scene);
        FZ_CHECK(fz_scene_is_empty(&scene), "stp_scene_free left something behind");
    } else {
        char *tiny;
        size_t tiny_size = 1 + size % 9;

        fz_check_message(err, sizeof err);
        FZ_CHECK(fz_scene_is_empty(&scene), "failed parse left a non-empty scene: %s", err);

        /* The same failure into a buffer of 1..9 bytes, and into none. */
        tiny = (char *)malloc(tiny_size);
        FZ_CHECK(tiny != NULL, "out of memory");
        rc = stp_scene_parse((const char *)data, size, format, FZ_SCENE_NAME, &opt, &scene,
                             tiny, tiny_size);
        FZ_CHECK(rc == -1, "second parse returned %d", rc);
        FZ_CHECK(strnlen(tiny, tiny_size) < tiny_size, "short message not terminated");
        FZ_CHECK(strncmp(tiny, err, tiny_size - 1) == 0,
                 "truncated message '%s' is not a prefix of '%s'", tiny, err);
        free(tiny);
        rc = stp_scene_parse((const char *)data, size, format, FZ_SCENE_NAME, &opt, &scene,
                             NULL, 0);
        FZ_CHECK(rc == -1, "parse without a message buffer returned %d", rc);
        FZ_CHECK(fz_scene_is_empty(&scene), "failed parse left a non-empty scene");
    }
    return 0;
}

#endif
