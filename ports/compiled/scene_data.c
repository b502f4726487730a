/* SPDX-License-Identifier: MIT */
/* Feeding a compiled scene to the core: see stp_scene_data.h.  The order of
 * calls mirrors tools/render_scene.c's stp_tool_render, because the picture
 * depends on it (a style change enters a SHADE instruction). */
#include "stp_scene_data.h"

int stp_scene_data_enter(const stp_scene_data *s, void *mem, size_t mem_size,
                         stp_renderer **out)
{
    stp_renderer *r;
    const stp_vec3 *v;
    uint32_t i;
    uint32_t last_material = UINT32_MAX;
    int status;

    *out = 0;
    r = stp_renderer_create(mem, mem_size, s->display_file, s->display_capacity, s->width,
                            s->height);
    if (!r)
        return STP_ERR_ARG;
    if ((status = stp_renderer_set_view(r, &s->view)) != STP_OK ||
        (status = stp_renderer_set_levels(r, s->levels)) != STP_OK ||
        (status = stp_renderer_set_lighting(r, &s->lighting)) != STP_OK)
        return status;
    if ((status = stp_renderer_set_shading(r, s->shading)) != STP_OK ||
        (status = stp_renderer_set_backface_removal(r, s->backface_removal)) != STP_OK ||
        (status = stp_segment_create(r, 1)) != STP_OK)
        return status;
    v = s->vertices;
    for (i = 0; i < s->polygon_count; i++) {
#ifdef STP_SCENE_ROM_COPY
        /* the tables are in program memory: a record at a time into RAM */
        stp_scene_data_polygon poly;
        stp_material material;
        stp_vec3 corners[STP_MAX_POLYGON_VERTICES];
        const stp_scene_data_polygon *p = &poly;
        const stp_material *m = &material;
        const stp_vec3 *corner = corners;
        STP_SCENE_ROM_COPY(&poly, &s->polygons[i], sizeof poly);
        if (p->count > STP_MAX_POLYGON_VERTICES)
            return STP_ERR_TOO_MANY_VERTICES;
        STP_SCENE_ROM_COPY(corners, v, p->count * sizeof corners[0]);
        if (p->material != last_material)
            STP_SCENE_ROM_COPY(&material, &s->materials[p->material], sizeof material);
#else
        const stp_scene_data_polygon *p = &s->polygons[i];
        const stp_material *m = &s->materials[p->material];
        const stp_vec3 *corner = v;
#endif
        if (p->material != last_material) {
            /* with shading off the material's reflectivity picks the style */
            if ((status = stp_renderer_set_object_shade(r, m)) != STP_OK ||
                (status = stp_renderer_set_fill_style(r, stp_intensity_index(m->reflectivity, s->levels))) != STP_OK)
                return status;
            last_material = p->material;
        }
        status = stp_renderer_polygon(r, corner, p->count);
        v += p->count;
        if (status != STP_OK && status != STP_ERR_DEGENERATE)
            return status;
    }
    (void)stp_segment_close(r);
    *out = r;
    return STP_OK;
}

void stp_scene_data_output(const stp_scene_data *s, stp_output *out)
{
    out->hidden = s->hidden;
    out->cell = s->cell;
    out->gamma = s->gamma;
    out->styles = 0;
    out->background = s->background;
    out->background_colour = 0;
    out->diffusion = s->diffusion;
    out->edge_aa = 0; /* compiled scenes: STP_WITH_EDGE_AA 0 */
}
