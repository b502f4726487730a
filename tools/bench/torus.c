/* SPDX-License-Identifier: MIT */
/* The torus workload of issue 11: see torus.h. */
#include "torus.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "render_scene.h"

int torus_scene_build(stp_scene *s)
{
    const double major = 1.0, minor = 0.4, pi = 3.14159265358979323846;
    const double dir_len = sqrt(3.0 * 3.0 + 5.2 * 5.2);
    int i, j, k = 0;
    size_t v = 0;
    memset(s, 0, sizeof *s);
    s->polygon_count = TORUS_TRIANGLES;
    s->vertex_count = 3 * s->polygon_count;
    s->vertices = calloc(s->vertex_count, sizeof *s->vertices);
    s->normals = calloc(s->vertex_count, sizeof *s->normals);
    s->polygons = calloc(s->polygon_count, sizeof *s->polygons);
    s->materials = calloc(1, sizeof *s->materials);
    s->lights = calloc(1, sizeof *s->lights);
    if (!s->vertices || !s->normals || !s->polygons || !s->materials || !s->lights) {
        stp_scene_free(s);
        return -1;
    }
    s->has_view = 1;
    s->from.y = 6 * 3.0 / dir_len;
    s->from.z = 6 * 5.2 / dir_len;
    s->up.y = 1;
    s->angle = 35;
    s->hither = 0.01;
    s->material_count = 1;
    s->materials[0].color[0] = s->materials[0].color[1] = s->materials[0].color[2] = 1;
    s->materials[0].kd = 0.7;
    s->materials[0].ks = 0.4;
    s->materials[0].shine = 20;
    s->light_count = 1;
    s->lights[0].position.x = -4;
    s->lights[0].position.y = 6;
    s->lights[0].position.z = 5;
    s->lights[0].color[0] = s->lights[0].color[1] = s->lights[0].color[2] = 1;
    for (i = 0; i < TORUS_AROUND; i++) {
        for (j = 0; j < TORUS_TUBE; j++) {
            /* the quad's corners q[c] at (theta, phi) steps (i, j), (i+1, j),
             * (i+1, j+1), (i, j+1): theta turns from +x towards +z, so
             * q0 -> q1 -> q2 runs clockwise seen from outside; the triangles
             * take the corners the other way round */
            stp_scene_vec3 q[4];
            int c, t;
            for (c = 0; c < 4; c++) {
                double th = 2 * pi * (i + (c == 1 || c == 2)) / TORUS_AROUND;
                double ph = 2 * pi * (j + (c >= 2)) / TORUS_TUBE;
                q[c].x = (major + minor * cos(ph)) * cos(th);
                q[c].y = minor * sin(ph);
                q[c].z = (major + minor * cos(ph)) * sin(th);
            }
            for (t = 0; t < 2; t++) {
                stp_scene_polygon *p = &s->polygons[k++];
                p->first = v;
                p->count = 3;
                p->material = 0;
                p->prim = -1;
                s->vertices[v++] = q[0];
                s->vertices[v++] = q[t == 0 ? 2 : 3];
                s->vertices[v++] = q[t == 0 ? 1 : 2];
            }
        }
    }
    return 0;
}

static int copy_flush(stp_port *port, uint32_t y0, uint32_t rows, const uint8_t *pixels,
                      size_t stride)
{
    torus_bench *b = (torus_bench *)port->user;
    uint32_t y;
    for (y = 0; y < rows; y++)
        memcpy(b->frame + (size_t)(y0 + y) * b->stride, pixels + (size_t)y * stride, b->stride);
    return 0;
}

void torus_bench_free(torus_bench *b)
{
    free(b->renderer_mem);
    free(b->df);
    free(b->vertices);
    free(b->band);
    free(b->zbuf);
    free(b->frame);
    free(b->mesh_vertices);
    free(b->mesh_triangles);
    free(b->mesh_normals);
    free(b->mesh_bounds);
    free(b->mesh_scratch);
    free(b->fine_parts);
    stp_scene_free(&b->scene);
    memset(b, 0, sizeof *b);
}

int torus_bench_init(torus_bench *b, int width, int height, char *err, size_t err_size)
{
    return torus_bench_init_for(b, width, height, TORUS_TRIANGLES, err, err_size);
}

int torus_bench_init_for(torus_bench *b, int width, int height, size_t triangles, char *err,
                         size_t err_size)
{
    stp_tool_options opt;
    stp_view view;
    stp_lighting lighting;
    size_t i, pixels = (size_t)width * (size_t)height;
    memset(b, 0, sizeof *b);
    b->width = width;
    b->height = height;
    if (torus_scene_build(&b->scene) != 0) {
        snprintf(err, err_size, "out of memory");
        return -1;
    }
    stp_tool_options_default(&opt);
    opt.width = width;
    opt.height = height;
    opt.backface_removal = 1;
    if (stp_tool_setup(&b->scene, &opt, &view, &lighting, err, err_size) != 0 ||
        stp_tool_cell(&opt, &b->cell) != 0) {
        torus_bench_free(b);
        return -1;
    }
    stp_material_default(&b->material);
    stp_tool_material(&b->scene.materials[0], 0, &b->material);
    /* a triangle clipped by the five planes has at most 8 vertices, and
     * one shade instruction may precede it */
    if (triangles < 1 || triangles > (0xFFFFFFFFu - 16) / 9) {
        snprintf(err, err_size, "bad triangle count %lu", (unsigned long)triangles);
        torus_bench_free(b);
        return -1;
    }
    b->capacity = (uint32_t)(triangles * 9 + 16);
    b->stride = stp_row_bytes(STP_PIXEL_MONO1, (uint32_t)width);
    b->renderer_mem = malloc(stp_renderer_size());
    b->df = malloc(sizeof *b->df * b->capacity);
    b->vertices = malloc(sizeof *b->vertices * b->scene.vertex_count);
    b->band = malloc(b->stride * (size_t)height);
    b->zbuf = malloc(sizeof *b->zbuf * pixels);
    b->frame = calloc(b->stride, (size_t)height);
    if (!b->renderer_mem || !b->df || !b->vertices || !b->band || !b->zbuf || !b->frame) {
        snprintf(err, err_size, "out of memory");
        torus_bench_free(b);
        return -1;
    }
    for (i = 0; i < b->scene.vertex_count; i++)
        b->vertices[i] = stp_tool_vec3(b->scene.vertices[i]);
    b->r = stp_renderer_create(b->renderer_mem, stp_renderer_size(), b->df, b->capacity,
                               (uint32_t)width, (uint32_t)height);
    if (!b->r || stp_renderer_set_view(b->r, &view) != STP_OK || stp_renderer_set_levels(b->r, 16) != STP_OK ||
        stp_renderer_set_lighting(b->r, &lighting) != STP_OK) {
        snprintf(err, err_size, "view or lighting refused by the core");
        torus_bench_free(b);
        return -1;
    }
    stp_renderer_set_shading(b->r, 1);
    stp_renderer_set_backface_removal(b->r, 1);
    b->output.hidden = STP_HIDDEN_ZBUFFER;
    b->output.cell = &b->cell;
    b->memory.band = b->band;
    b->memory.band_size = b->stride * (size_t)height;
    b->memory.band_rows = (uint32_t)height;
    b->memory.zbuf = b->zbuf;
    b->memory.zbuf_count = pixels;
    b->port.width = (uint32_t)width;
    b->port.height = (uint32_t)height;
    b->port.format = STP_PIXEL_MONO1;
    b->port.flush = copy_flush;
    b->port.user = b;
    return 0;
}

void torus_bench_pose(torus_bench *b, double tilt_degrees, double spin_degrees, double dx,
                      double dy, double dz)
{
    stp_vec3 d;
    stp_transform_identity(&b->pose);
    stp_transform_rotate(&b->pose, 0, stp_tool_fix(tilt_degrees));
    stp_transform_rotate(&b->pose, 1, stp_tool_fix(spin_degrees));
    d.x = stp_tool_fix(dx);
    d.y = stp_tool_fix(dy);
    d.z = stp_tool_fix(dz);
    stp_transform_translate(&b->pose, d);
    b->posed = 1;
}

int torus_bench_use_mesh(torus_bench *b, char *err, size_t err_size)
{
    size_t n = 3 * (size_t)TORUS_TRIANGLES, i, j, count = 0;
    uint16_t bad = 0;
    int status;
    b->mesh_vertices = malloc(sizeof *b->mesh_vertices * n);
    b->mesh_triangles = malloc(sizeof *b->mesh_triangles * n);
    b->mesh_normals = malloc(sizeof *b->mesh_normals * n);
    if (!b->mesh_vertices || !b->mesh_triangles || !b->mesh_normals) {
        snprintf(err, err_size, "out of memory");
        return -1;
    }
    for (i = 0; i < n; i++) {
        stp_vec3 p = b->vertices[i];
        for (j = 0; j < count; j++)
            if (b->mesh_vertices[j].x == p.x && b->mesh_vertices[j].y == p.y &&
                b->mesh_vertices[j].z == p.z)
                break;
        if (j == count)
            b->mesh_vertices[count++] = p;
        b->mesh_triangles[i] = (uint16_t)j;
    }
    b->mesh.vertices = b->mesh_vertices;
    b->mesh.vertex_count = (uint16_t)count;
    b->mesh.triangles = b->mesh_triangles;
    b->mesh.triangle_count = TORUS_TRIANGLES;
    status = stp_mesh_prepare_normals(&b->mesh, b->mesh_normals, &bad);
    if (status != STP_OK) {
        snprintf(err, err_size, "triangle %u: %s", (unsigned)bad, stp_status_text(status));
        return -1;
    }
    b->mesh.normals = b->mesh_normals;
    b->mesh_bounds = malloc(sizeof *b->mesh_bounds);
    b->mesh_scratch = malloc(sizeof *b->mesh_scratch * count);
    if (!b->mesh_scratch || !b->mesh_bounds) {
        snprintf(err, err_size, "out of memory");
        return -1;
    }
    /* prepared once, as normals are: a spun model keeps its vertices */
    (void)stp_mesh_prepare_bounds(&b->mesh, b->mesh_bounds); /* vertices present: STP_OK */
    b->mesh.bounds = b->mesh_bounds;
    b->scratch_count = count;
    b->parts = &b->mesh;
    b->part_count = 1;
    b->use_mesh = 1;
    return 0;
}

/* Vertex (i, j) of the around x tube torus (theta step i, phi step j). */
static stp_vec3 fine_vertex(int i, int j, int around, int tube)
{
    const double major = 1.0, minor = 0.4, pi = 3.14159265358979323846;
    double th = 2 * pi * i / around, ph = 2 * pi * j / tube;
    stp_vec3 v;
    v.x = stp_tool_fix((major + minor * cos(ph)) * cos(th));
    v.y = stp_tool_fix(minor * sin(ph));
    v.z = stp_tool_fix((major + minor * cos(ph)) * sin(th));
    return v;
}

/* Part p's rings [i0, i0 + rings) into the arrays at v, t, n: rings + 1
 * rings of tube vertices, 2 x rings x tube triangles wound as
 * torus_scene_build winds them. */
static int fine_part(stp_mesh *m, int i0, int rings, int around, int tube, stp_vec3 *v,
                     uint16_t *t, int16_t *n, char *err, size_t err_size)
{
    int i, j, k = 0;
    uint16_t bad = 0;
    int status;
    for (i = 0; i <= rings; i++)
        for (j = 0; j < tube; j++)
            v[i * tube + j] = fine_vertex(i0 + i, j, around, tube);
    for (i = 0; i < rings; i++) {
        for (j = 0; j < tube; j++) {
            uint16_t q0 = (uint16_t)(i * tube + j), q1 = (uint16_t)((i + 1) * tube + j);
            uint16_t q2 = (uint16_t)((i + 1) * tube + (j + 1) % tube);
            uint16_t q3 = (uint16_t)(i * tube + (j + 1) % tube);
            t[k++] = q0, t[k++] = q2, t[k++] = q1;
            t[k++] = q0, t[k++] = q3, t[k++] = q2;
        }
    }
    m->vertices = v;
    m->vertex_count = (uint16_t)((rings + 1) * tube);
    m->triangles = t;
    m->triangle_count = (uint16_t)(2 * rings * tube);
    status = stp_mesh_prepare_normals(m, n, &bad);
    if (status != STP_OK) {
        snprintf(err, err_size, "fine torus, ring %d, triangle %u: %s", i0, (unsigned)bad,
                 stp_status_text(status));
        return -1;
    }
    m->normals = n;
    return 0;
}

int torus_bench_use_fine_mesh(torus_bench *b, int around, int tube, unsigned part_max, char *err,
                              size_t err_size)
{
    int max_rings, parts, p, i0 = 0;
    size_t vertices, triangles, vi = 0, ti = 0;
    if (part_max == 0 || part_max > TORUS_PART_MAX)
        part_max = TORUS_PART_MAX;
    if (around < 3 || tube < 3 || (size_t)tube * 2 > part_max) {
        snprintf(err, err_size, "bad fine torus %d x %d in parts of %u", around, tube, part_max);
        return -1;
    }
    /* whole rings: 2 x rings x tube triangles and (rings + 1) x tube
     * vertices, both at most part_max */
    max_rings = (int)(part_max / (2u * (unsigned)tube));
    parts = (around + max_rings - 1) / max_rings;
    triangles = 2 * (size_t)around * (size_t)tube;
    vertices = ((size_t)around + (size_t)parts) * (size_t)tube;
    if (triangles * 9 + 16 > b->capacity) {
        snprintf(err, err_size, "the display file holds fewer than %lu triangles",
                 (unsigned long)triangles);
        return -1;
    }
    b->mesh_vertices = malloc(sizeof *b->mesh_vertices * vertices);
    b->mesh_triangles = malloc(sizeof *b->mesh_triangles * 3 * triangles);
    b->mesh_normals = malloc(sizeof *b->mesh_normals * 3 * triangles);
    b->fine_parts = calloc((size_t)parts, sizeof *b->fine_parts);
    b->mesh_bounds = malloc(sizeof *b->mesh_bounds * (size_t)parts);
    b->scratch_count = ((size_t)max_rings + 1) * (size_t)tube;
    b->mesh_scratch = malloc(sizeof *b->mesh_scratch * b->scratch_count);
    if (!b->mesh_vertices || !b->mesh_triangles || !b->mesh_normals || !b->fine_parts ||
        !b->mesh_scratch || !b->mesh_bounds) {
        snprintf(err, err_size, "out of memory");
        return -1;
    }
    for (p = 0; p < parts; p++) {
        /* rings shared out evenly, the first parts one more */
        int rings = around / parts + (p < around % parts);
        if (fine_part(&b->fine_parts[p], i0, rings, around, tube, b->mesh_vertices + vi,
                      b->mesh_triangles + ti, b->mesh_normals + ti, err, err_size) != 0)
            return -1;
        (void)stp_mesh_prepare_bounds(&b->fine_parts[p], &b->mesh_bounds[p]);
        b->fine_parts[p].bounds = &b->mesh_bounds[p];
        vi += (size_t)(rings + 1) * (size_t)tube;
        ti += 6 * (size_t)rings * (size_t)tube;
        i0 += rings;
    }
    b->parts = b->fine_parts;
    b->part_count = parts;
    b->use_mesh = 1;
    return 0;
}

int torus_frame(torus_bench *b)
{
    int t, p;
    (void)stp_segment_delete(b->r, 1);
    if (stp_segment_create(b->r, 1) != STP_OK)
        return -1;
    if (b->posed && stp_renderer_set_transform(b->r, &b->pose) != STP_OK)
        return -1;
    stp_renderer_set_object_shade(b->r, &b->material);
    for (p = 0; b->use_mesh && p < b->part_count; p++)
        if (stp_renderer_mesh(b->r, &b->parts[p], b->mesh_scratch, b->scratch_count) != STP_OK)
            return -1;
    for (t = 0; !b->use_mesh && t < TORUS_TRIANGLES; t++) {
        if (stp_renderer_polygon(b->r, b->vertices + 3 * t, 3) != STP_OK)
            return -1;
        if (b->keep_shades)
            b->shade[t] = stp_renderer_last_shade(b->r);
    }
    if (stp_segment_close(b->r) != STP_OK)
        return -1;
    return stp_renderer_render(b->r, &b->port, &b->output, &b->memory) == STP_OK ? 0 : -1;
}
