/* SPDX-License-Identifier: MIT */
/* The torus frame (torus_frame.h). */
#include "torus_frame.h"

#define ONE STP_FIX_ONE

/* value / 1000 as stp_fix */
static stp_fix milli(int32_t value)
{
    return stp_fix_from_ratio(value, 1000);
}

/* Point of the torus at ring step i (of TORUS_AROUND) and tube step j. */
static stp_vec3 torus_point(int i, int j)
{
    stp_fix th = stp_fix_from_ratio(360 * (i % TORUS_AROUND), TORUS_AROUND);
    stp_fix ph = stp_fix_from_ratio(360 * (j % TORUS_TUBE), TORUS_TUBE);
    stp_fix minor = milli(400);
    stp_fix ring = stp_fix_add(ONE, stp_fix_mul(minor, stp_fix_cos_deg(ph)));
    stp_vec3 p;
    p.x = stp_fix_mul(ring, stp_fix_cos_deg(th));
    p.y = stp_fix_mul(minor, stp_fix_sin_deg(ph));
    p.z = stp_fix_mul(ring, stp_fix_sin_deg(th));
    return p;
}

void torus_build(stp_vec3 *vertices)
{
    int i, j;
    stp_vec3 *v = vertices;
    for (i = 0; i < TORUS_AROUND; i++) {
        for (j = 0; j < TORUS_TUBE; j++) {
            stp_vec3 q0 = torus_point(i, j), q1 = torus_point(i + 1, j),
                     q2 = torus_point(i + 1, j + 1), q3 = torus_point(i, j + 1);
            /* counter-clockwise seen from outside */
            *v++ = q0;
            *v++ = q2;
            *v++ = q1;
            *v++ = q0;
            *v++ = q3;
            *v++ = q2;
        }
    }
}

static uint16_t torus_index(int i, int j)
{
    return (uint16_t)((i % TORUS_AROUND) * TORUS_TUBE + j % TORUS_TUBE);
}

int torus_mesh_build(stp_mesh *mesh, stp_vec3 *vertices, uint16_t *triangles, int16_t *normals,
                     stp_mesh_bounds *bounds)
{
    int i, j;
    uint16_t *t = triangles;
    for (i = 0; i < TORUS_AROUND; i++)
        for (j = 0; j < TORUS_TUBE; j++) {
            vertices[torus_index(i, j)] = torus_point(i, j);
            /* torus_build's two triangles of the quad */
            *t++ = torus_index(i, j);
            *t++ = torus_index(i + 1, j + 1);
            *t++ = torus_index(i + 1, j);
            *t++ = torus_index(i, j);
            *t++ = torus_index(i, j + 1);
            *t++ = torus_index(i + 1, j + 1);
        }
    mesh->vertices = vertices;
    mesh->vertex_count = TORUS_MESH_VERTICES;
    mesh->triangles = triangles;
    mesh->triangle_count = TORUS_TRIANGLES;
    mesh->normals = 0;
    mesh->bounds = 0;
    if (stp_mesh_prepare_normals(mesh, normals, 0) != STP_OK || stp_mesh_prepare_bounds(mesh, bounds) != STP_OK)
        return STP_ERR_DEGENERATE;
    mesh->normals = normals;
    mesh->bounds = bounds;
    return STP_OK;
}

int torus_enter_mesh(stp_renderer *r, const stp_mesh *mesh, stp_mesh_vertex *scratch)
{
    int status;
    (void)stp_segment_delete(r, 1); /* absent on the first frame */
    status = stp_segment_create(r, 1);
    if (status == STP_OK)
        status = stp_renderer_mesh(r, mesh, scratch, TORUS_MESH_VERTICES);
    if (status == STP_OK)
        status = stp_segment_close(r);
    return status;
}

int torus_setup(stp_renderer *r)
{
    stp_view view;
    stp_lighting lighting;
    stp_material material;
    int status, c;
    view.from.x = 0;
    view.from.y = milli(3000);
    view.from.z = milli(5196); /* 6 cos 30 degrees */
    view.at.x = view.at.y = view.at.z = 0;
    view.up.x = view.up.z = 0;
    view.up.y = ONE;
    view.fov_degrees = 35 * ONE;
    view.window_half = ONE;
    view.hither = milli(10);
    view.projection = STP_PERSPECTIVE;
    status = stp_renderer_set_view(r, &view);
    if (status != STP_OK)
        return status;
    stp_lighting_default(&lighting);
    lighting.brightness = ONE;
    lighting.background = milli(200);
    lighting.attenuation_c = ONE;
    lighting.count = 1;
    lighting.lights[0].position.x = -4 * ONE;
    lighting.lights[0].position.y = 6 * ONE;
    lighting.lights[0].position.z = 5 * ONE;
    /* (1 - background)(C + |light - centre|) = 0.8 (1 + sqrt(77)) */
    lighting.lights[0].power = milli(7820);
    for (c = 0; c < 3; c++)
        lighting.lights[0].colour[c] = ONE;
    status = stp_renderer_set_lighting(r, &lighting);
    if (status != STP_OK)
        return status;
    stp_material_default(&material);
    material.reflectivity = milli(700);
    material.refraction = 10 * ONE;
    material.gloss = milli(100); /* 2 / shine 20 */
    material.specular = milli(400);
    stp_renderer_set_object_shade(r, &material);
    stp_renderer_set_shading(r, 1);
    stp_renderer_set_backface_removal(r, 1);
    return stp_renderer_set_levels(r, 16);
}

int torus_enter(stp_renderer *r, const stp_vec3 *vertices)
{
    int status, k;
    (void)stp_segment_delete(r, 1); /* absent on the first frame */
    status = stp_segment_create(r, 1);
    for (k = 0; k < TORUS_TRIANGLES && status == STP_OK; k++)
        status = stp_renderer_polygon(r, &vertices[3 * k], 3);
    if (status == STP_OK)
        status = stp_segment_close(r);
    return status;
}

int torus_render(stp_renderer *r, stp_port *port, const stp_frame_memory *mem)
{
    stp_output out;
    out.hidden = STP_HIDDEN_ZBUFFER;
    out.cell = 0; /* Bayer 4x4 */
    out.gamma = 0;
    out.styles = 0;
    out.background = 0;
    out.background_colour = 0;
    out.diffusion = 0; /* a halftone cell, no error diffusion */
    out.edge_aa = 0;
    return stp_renderer_render(r, port, &out, mem);
}

int torus_frame(stp_renderer *r, const stp_vec3 *vertices, stp_port *port,
                const stp_frame_memory *mem)
{
    int status = torus_enter(r, vertices);
    return status == STP_OK ? torus_render(r, port, mem) : status;
}
