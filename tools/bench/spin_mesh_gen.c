/* SPDX-License-Identifier: MIT */
/*
 * Writes a scene as the C data of ports/spin/spin_scene.h (issue 11 item
 * 4): the firmware's spinning model.  The scene is loaded and prepared as
 * the stipple command does (units, lights merged, view and lighting by
 * stp_tool_setup_prepared, materials by stp_tool_material, the command's
 * default output: 16 levels, back faces kept), its polygons grouped by
 * material into indexed meshes (identical stp_fix points shared, each
 * polygon fanned into triangles, triangles with no area dropped), the
 * Q1.14 normals prepared by stp_mesh_prepare_normals.  A part whose points
 * all share one vertical coordinate (a floor) stays still; the others
 * spin about the vertical line through their bounds' centre.
 *
 * usage: spin_mesh_gen SCENE.nff OUT.c
 * Exit status: 0, 1 (an unreadable scene, a scene too large, a write
 * error: nothing is left at OUT.c), 2 (usage).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "render_scene.h"
#include "scene_prepare.h"

#define MAX_PART_VERTICES 65535u

typedef struct part {
    int material;
    stp_vec3 *vertices;
    uint16_t *triangles;
    int16_t *normals;
    size_t vertex_count, triangle_count, capacity;
} part;

static void *grow(void *p, size_t n, size_t size)
{
    void *q = realloc(p, n * size);
    if (!q) {
        fprintf(stderr, "spin_mesh_gen: out of memory\n");
        exit(1);
    }
    return q;
}

/* index of point v in the part, added when new */
static long part_vertex(part *pt, stp_vec3 v)
{
    size_t i;
    for (i = 0; i < pt->vertex_count; i++)
        if (pt->vertices[i].x == v.x && pt->vertices[i].y == v.y && pt->vertices[i].z == v.z)
            return (long)i;
    if (pt->vertex_count >= MAX_PART_VERTICES)
        return -1;
    pt->vertices = grow(pt->vertices, pt->vertex_count + 1, sizeof *pt->vertices);
    pt->vertices[pt->vertex_count] = v;
    return (long)pt->vertex_count++;
}

/* the triangle (a, b, c) unless it has no area (its prepared normal fails) */
static void part_triangle(part *pt, uint16_t a, uint16_t b, uint16_t c)
{
    stp_mesh one;
    uint16_t tri[3];
    int16_t n[3];
    tri[0] = a;
    tri[1] = b;
    tri[2] = c;
    one.vertices = pt->vertices;
    one.vertex_count = (uint16_t)pt->vertex_count;
    one.triangles = tri;
    one.triangle_count = 1;
    one.normals = 0;
    one.bounds = 0;
    if (stp_mesh_prepare_normals(&one, n, 0) != STP_OK)
        return;
    if (pt->triangle_count + 1 > pt->capacity) {
        pt->capacity = pt->capacity ? 2 * pt->capacity : 64;
        pt->triangles = grow(pt->triangles, 3 * pt->capacity, sizeof *pt->triangles);
        pt->normals = grow(pt->normals, 3 * pt->capacity, sizeof *pt->normals);
    }
    memcpy(pt->triangles + 3 * pt->triangle_count, tri, sizeof tri);
    memcpy(pt->normals + 3 * pt->triangle_count, n, sizeof n);
    pt->triangle_count++;
}

static stp_fix axis_of(stp_vec3 v, int axis)
{
    return axis == 0 ? v.x : (axis == 1 ? v.y : v.z);
}

static int part_is_flat(const part *pt, int axis)
{
    size_t i;
    for (i = 1; i < pt->vertex_count; i++)
        if (axis_of(pt->vertices[i], axis) != axis_of(pt->vertices[0], axis))
            return 0;
    return 1;
}

static void write_vec3(FILE *f, stp_vec3 v)
{
    fprintf(f, "{%ld, %ld, %ld}", (long)v.x, (long)v.y, (long)v.z);
}

static void write_part(FILE *f, const part *pt, size_t k)
{
    size_t i;
    fprintf(f, "static const stp_vec3 part%zu_vertices[%zu] = {\n", k, pt->vertex_count);
    for (i = 0; i < pt->vertex_count; i++) {
        fprintf(f, "    ");
        write_vec3(f, pt->vertices[i]);
        fprintf(f, ",\n");
    }
    fprintf(f, "};\nstatic const uint16_t part%zu_triangles[%zu] = {\n", k, 3 * pt->triangle_count);
    for (i = 0; i < pt->triangle_count; i++)
        fprintf(f, "    %u, %u, %u,\n", pt->triangles[3 * i], pt->triangles[3 * i + 1],
                pt->triangles[3 * i + 2]);
    fprintf(f, "};\nstatic const int16_t part%zu_normals[%zu] = {\n", k, 3 * pt->triangle_count);
    for (i = 0; i < pt->triangle_count; i++)
        fprintf(f, "    %d, %d, %d,\n", pt->normals[3 * i], pt->normals[3 * i + 1],
                pt->normals[3 * i + 2]);
    fprintf(f, "};\n");
}

int main(int argc, char **argv)
{
    stp_scene scene;
    stp_scene_options sopt;
    stp_tool_options opt;
    stp_tool_prepared prep;
    stp_view view;
    stp_lighting lighting;
    stp_output out;
    stp_cell cell;
    uint8_t *gamma = 0;
    stp_fix background_rgb[3];
    char err[512], tmp[4096];
    part *parts = 0;
    size_t part_count = 0, i, k, max_vertices = 0, capacity = 16;
    int axis, j, ok = 1;
    stp_fix lo[3] = {STP_FIX_MAX, STP_FIX_MAX, STP_FIX_MAX}, hi[3] = {STP_FIX_MIN, STP_FIX_MIN, STP_FIX_MIN};
    stp_vec3 centre;
    FILE *f;
    if (argc != 3) {
        fprintf(stderr, "usage: spin_mesh_gen SCENE.nff OUT.c\n");
        return 2;
    }
    stp_scene_options_default(&sopt);
    stp_tool_options_default(&opt);
    if (stp_scene_load(argv[1], &sopt, &scene, err, sizeof err) != 0) {
        fprintf(stderr, "spin_mesh_gen: %s\n", err);
        return 1;
    }
    if (stp_tool_prepare(&scene, &opt, &prep, err, sizeof err) != 0 ||
        stp_tool_setup_prepared(&prep, &view, &lighting, err, sizeof err) != 0 ||
        stp_tool_output(&prep.scene, &prep.opt, &out, &cell, &gamma, background_rgb, err, sizeof err) != 0) {
        fprintf(stderr, "spin_mesh_gen: %s: %s\n", argv[1], err);
        return 1;
    }
    free(gamma); /* the default options' gamma is linear: none */
    /* the vertical axis: the up vector's largest component */
    axis = abs(view.up.x) >= abs(view.up.y) ? 0 : 1;
    if (abs(view.up.z) > abs(axis_of(view.up, axis)))
        axis = 2;

    for (i = 0; i < prep.scene.polygon_count; i++) {
        const stp_scene_polygon *p = &prep.scene.polygons[i];
        part *pt = 0;
        long idx[64];
        for (k = 0; k < part_count; k++)
            if (parts[k].material == p->material)
                pt = &parts[k];
        if (!pt) {
            parts = grow(parts, part_count + 1, sizeof *parts);
            pt = &parts[part_count++];
            memset(pt, 0, sizeof *pt);
            pt->material = p->material;
        }
        if (p->count > 64) {
            fprintf(stderr, "%s:%d: polygon of %d vertices (at most 64)\n", argv[1], p->source_line, p->count);
            return 1;
        }
        for (j = 0; j < p->count; j++) {
            idx[j] = part_vertex(pt, stp_tool_vec3(prep.scene.vertices[p->first + (size_t)j]));
            if (idx[j] < 0) {
                fprintf(stderr, "%s:%d: more than %u distinct points in one material\n", argv[1],
                        p->source_line, MAX_PART_VERTICES);
                return 1;
            }
        }
        for (j = 2; j < p->count; j++)
            part_triangle(pt, (uint16_t)idx[0], (uint16_t)idx[j - 1], (uint16_t)idx[j]);
    }
    for (k = 0; k < part_count; k++) {
        if (parts[k].vertex_count > max_vertices)
            max_vertices = parts[k].vertex_count;
        /* a triangle and a style record each, as stipple counts them */
        capacity += 3 * parts[k].triangle_count + 6 * parts[k].triangle_count;
        if (part_is_flat(&parts[k], axis))
            continue;
        for (i = 0; i < parts[k].vertex_count; i++)
            for (j = 0; j < 3; j++) {
                stp_fix c = axis_of(parts[k].vertices[i], j);
                lo[j] = c < lo[j] ? c : lo[j];
                hi[j] = c > hi[j] ? c : hi[j];
            }
    }
    if (lo[0] > hi[0]) /* nothing spins: the origin */
        lo[0] = hi[0] = lo[1] = hi[1] = lo[2] = hi[2] = 0;
    centre.x = axis == 0 ? 0 : (stp_fix)(((int64_t)lo[0] + hi[0]) / 2);
    centre.y = axis == 1 ? 0 : (stp_fix)(((int64_t)lo[1] + hi[1]) / 2);
    centre.z = axis == 2 ? 0 : (stp_fix)(((int64_t)lo[2] + hi[2]) / 2);
    if (capacity > 0xFFFFFFFFu) {
        fprintf(stderr, "spin_mesh_gen: %s: scene too large\n", argv[1]);
        return 1;
    }

    snprintf(tmp, sizeof tmp, "%s.tmp", argv[2]);
    f = fopen(tmp, "w");
    if (!f) {
        perror(tmp);
        return 1;
    }
    fprintf(f, "/* SPDX-License-Identifier: MIT */\n/* Generated by spin_mesh_gen from %s: do not edit. */\n"
               "#include \"spin_scene.h\"\n\n", argv[1]);
    for (k = 0; k < part_count; k++)
        write_part(f, &parts[k], k);
    fprintf(f, "const spin_part spin_parts[%zu] = {\n", part_count);
    for (k = 0; k < part_count; k++) {
        stp_material m;
        stp_material_default(&m);
        if (parts[k].material >= 0 && (size_t)parts[k].material < prep.scene.material_count)
            stp_tool_material(&prep.scene.materials[parts[k].material], 0, &m);
        fprintf(f, "    {{part%zu_vertices, part%zu_triangles, part%zu_normals, %zu, %zu, 0},\n", k, k, k,
                parts[k].vertex_count, parts[k].triangle_count);
        fprintf(f, "     {%ld, %ld, %ld, %ld, {%ld, %ld, %ld}},\n     %d},\n", (long)m.reflectivity,
                (long)m.refraction, (long)m.gloss, (long)m.specular, (long)m.colour[0],
                (long)m.colour[1], (long)m.colour[2], !part_is_flat(&parts[k], axis));
    }
    fprintf(f, "};\nconst uint16_t spin_part_count = %zu;\n", part_count);
    fprintf(f, "const int spin_axis = %d;\nconst stp_vec3 spin_axis_point = ", axis);
    write_vec3(f, centre);
    fprintf(f, ";\nconst int spin_levels = %d;\nconst stp_fix spin_background = %ld;\n"
               "const int spin_backface_removal = %d;\n",
            opt.levels, (long)out.background, opt.backface_removal);
    fprintf(f, "stp_instr spin_display_file[%zu];\nconst uint32_t spin_display_file_capacity = %zu;\n",
            capacity, capacity);
    fprintf(f, "stp_mesh_vertex spin_scratch[%zu];\nconst uint16_t spin_scratch_count = %zu;\n\n",
            max_vertices ? max_vertices : 1, max_vertices ? max_vertices : 1);
    fprintf(f, "void spin_scene_view(stp_view *view)\n{\n");
    fprintf(f, "    view->from.x = %ld;\n    view->from.y = %ld;\n    view->from.z = %ld;\n",
            (long)view.from.x, (long)view.from.y, (long)view.from.z);
    fprintf(f, "    view->at.x = %ld;\n    view->at.y = %ld;\n    view->at.z = %ld;\n", (long)view.at.x,
            (long)view.at.y, (long)view.at.z);
    fprintf(f, "    view->up.x = %ld;\n    view->up.y = %ld;\n    view->up.z = %ld;\n", (long)view.up.x,
            (long)view.up.y, (long)view.up.z);
    fprintf(f, "    view->fov_degrees = %ld;\n    view->window_half = %ld;\n    view->hither = %ld;\n"
               "    view->projection = %s;\n}\n\n",
            (long)view.fov_degrees, (long)view.window_half, (long)view.hither,
            view.projection == STP_PERSPECTIVE ? "STP_PERSPECTIVE" : "STP_PARALLEL");
    fprintf(f, "void spin_scene_lighting(stp_lighting *lighting)\n{\n    stp_lighting_default(lighting);\n");
    fprintf(f, "    lighting->brightness = %ld;\n    lighting->background = %ld;\n"
               "    lighting->attenuation_c = %ld;\n    lighting->count = %d;\n",
            (long)lighting.brightness, (long)lighting.background, (long)lighting.attenuation_c,
            lighting.count);
    for (j = 0; j < lighting.count; j++) {
        const stp_light *l = &lighting.lights[j];
        fprintf(f, "    lighting->lights[%d].position.x = %ld;\n    lighting->lights[%d].position.y = %ld;\n"
                   "    lighting->lights[%d].position.z = %ld;\n    lighting->lights[%d].power = %ld;\n",
                j, (long)l->position.x, j, (long)l->position.y, j, (long)l->position.z, j, (long)l->power);
        for (k = 0; k < 3; k++)
            fprintf(f, "    lighting->lights[%d].colour[%zu] = %ld;\n", j, k, (long)l->colour[k]);
    }
    fprintf(f, "}\n");
    if (ferror(f))
        ok = 0;
    if (fclose(f) != 0)
        ok = 0;
    if (!ok || rename(tmp, argv[2]) != 0) {
        perror(argv[2]);
        remove(tmp);
        return 1;
    }
    fprintf(stderr, "spin_mesh_gen: %zu parts, %zu display-file entries, vertical axis %d\n", part_count,
            capacity, axis);
    for (k = 0; k < part_count; k++)
        free(parts[k].vertices), free(parts[k].triangles), free(parts[k].normals);
    free(parts);
    stp_tool_prepared_free(&prep);
    stp_scene_free(&scene);
    return 0;
}
