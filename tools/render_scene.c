/* SPDX-License-Identifier: MIT */
/* Host side: a stp_scene through the core.  See render_scene.h. */
#include "render_scene.h"
#include "outlines.h"
#include "readable.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene_prepare.h"
#include "scene_util.h"
#include "shadows_setup.h"
#include "subdivide.h"
#include "tone.h"

void stp_tool_options_default(stp_tool_options *opt)
{
    memset(opt, 0, sizeof *opt);
    opt->width = 128;
    opt->height = 64;
    opt->levels = 16;
    opt->dither = STP_TOOL_DITHER_BAYER4;
    opt->spacing = STP_SPACING_LINEAR;
    opt->gamma = 1.0;
    opt->gamma_k = 1.0;
    opt->hidden = STP_HIDDEN_ZBUFFER;
    opt->shading = 1;
    opt->background = 0.2;
    opt->brightness = 1.0;
    opt->attenuation_c = 1.0;
    opt->auto_power = 1;
    opt->perspective = 1;
    opt->rt_depth = 4;
    opt->rt_min_weight = 1.0 / 64;
    opt->rt_hierarchy = 1;
    opt->crease_angle = 40.0;
}

stp_fix stp_tool_fix(double v)
{
    double s = v * (double)STP_FIX_ONE;
    if (!(s == s))
        return 0;
    if (s >= (double)STP_FIX_MAX)
        return STP_FIX_MAX;
    if (s <= (double)STP_FIX_MIN)
        return STP_FIX_MIN;
    return (stp_fix)lround(s);
}

stp_vec3 stp_tool_vec3(stp_scene_vec3 v)
{
    stp_vec3 r;
    r.x = stp_tool_fix(v.x);
    r.y = stp_tool_fix(v.y);
    r.z = stp_tool_fix(v.z);
    return r;
}

int stp_tool_cell(const stp_tool_options *opt, stp_cell *cell)
{
    switch (opt->dither) {
    case STP_TOOL_DITHER_BAYER2: return stp_cell_bayer_spaced(cell, 2, opt->spacing);
    case STP_TOOL_DITHER_BAYER4: return stp_cell_bayer_spaced(cell, 4, opt->spacing);
    case STP_TOOL_DITHER_BAYER8: return stp_cell_bayer_spaced(cell, 8, opt->spacing);
    case STP_TOOL_DITHER_SEED2X2: stp_cell_seed2x2(cell); return 0;
    case STP_TOOL_DITHER_PATTERN2X2: stp_cell_pattern2x2(cell); return 0;
    case STP_TOOL_DITHER_USER:
        return stp_cell_user(cell, opt->user_cell_w, opt->user_cell_h, opt->user_cell);
    case STP_TOOL_DITHER_DIFFUSE: return stp_cell_bayer(cell, 4);
    case STP_TOOL_DITHER_BAYER16: return stp_cell_bayer_spaced(cell, 16, opt->spacing);
    case STP_TOOL_DITHER_BLUE_NOISE: stp_cell_blue_noise(cell); return 0;
    case STP_TOOL_DITHER_CLUSTERED:
        return stp_cell_clustered(cell, opt->clustered_n, opt->clustered_angle);
    }
    return -1;
}

void stp_tool_still_defaults(stp_tool_options *opt)
{
    if (!opt->dither_given) {
        opt->dither = STP_TOOL_DITHER_DIFFUSE;
        opt->diffuse_kernel = STP_DIFFUSE_FLOYD_STEINBERG;
        opt->diffuse_raster = 1;
        opt->diffuse_noise = 1;
    }
    if (!opt->levels_given)
        opt->levels = 256;
    if (!opt->exposure_given)
        opt->exposure_auto = 1;
    /* with the default dither only: scripts that name a dither (the
     * goldens, the firmware comparisons) keep their pictures */
    if (!opt->dither_given && !opt->outlines_given && !opt->raytrace)
        opt->outlines_auto = 1;
}

size_t stp_tool_band_bytes(stp_pixel_format format, uint32_t width, int rows)
{
    size_t count = format == STP_PIXEL_MONO1_PAGES ? ((size_t)rows + 7u) / 8u : (size_t)rows;
    return stp_row_bytes(format, width) * count;
}

int stp_tool_band_rows(const stp_tool_options *opt, const stp_port *port)
{
    int rows = opt->band_rows > 0 && opt->band_rows < opt->height ? opt->band_rows : opt->height;
    if (port->format == STP_PIXEL_MONO1_PAGES && rows % 8 != 0)
        rows = rows + 8 - rows % 8 < opt->height ? rows + 8 - rows % 8 : opt->height;
    return rows;
}

int stp_tool_diffusion(const stp_tool_options *opt, uint32_t width, stp_diffusion *d)
{
    memset(d, 0, sizeof *d);
    if (opt->dither != STP_TOOL_DITHER_DIFFUSE)
        return 0;
    d->kernel = (uint8_t)opt->diffuse_kernel;
    d->serpentine = (uint8_t)!opt->diffuse_raster;
    if (opt->diffuse_noise) {
        d->noise = stp_cell_blue_noise_64;
        d->noise_amplitude = (uint8_t)STP_DIFFUSE_NOISE_AMPLITUDE_OF(opt->diffuse_kernel);
        d->noise_band = STP_DIFFUSE_NOISE_BAND;
    }
    d->error_count = stp_diffusion_error_count(opt->diffuse_kernel, width);
    d->errors = malloc(sizeof *d->errors * (d->error_count ? d->error_count : 1));
    return d->errors ? 1 : -1;
}

/* Seed parameters from NFF's material (documented in README "Scenes"):
 * R = Kd x luminance of the colour (the seed's YIQ weights .30 .59 .11);
 * n = the index of refraction when > 1, else the seed's default 10 (NFF
 * writes 0 or 1 for opaque surfaces, which would leave no highlight);
 * k = 2/Shine (Phong cos^s and the facet distribution agree near the
 * highlight when k = 2/s), the seed's 10 when Shine <= 0;
 * specular weight = Ks. */
static double clamp01(double v)
{
    return v < 0 ? 0 : (v > 1 ? 1 : v);
}

void stp_tool_material(const stp_scene_material *m, int colour, stp_material *out)
{
    double lum = 0.30 * m->color[0] + 0.59 * m->color[1] + 0.11 * m->color[2];
    /* grey: the colour's luminance goes into R; colour: R = Kd and the
     * colour itself splits it over the channels */
    double refl = colour ? m->kd : m->kd * lum;
    int c;
    for (c = 0; c < 3; c++)
        out->colour[c] = stp_tool_fix(colour ? clamp01(m->color[c]) : 1.0);
    out->reflectivity = stp_tool_fix(refl < 0 ? 0 : (refl > 1 ? 1 : refl));
    out->refraction = stp_tool_fix(m->ior > 1.0 ? m->ior : 10.0);
    out->gloss = stp_tool_fix(m->shine > 0 ? 2.0 / m->shine : 10.0);
    out->specular = stp_tool_fix(m->ks < 0 ? 0 : m->ks);
}

/* Order of vertex indices by position, for averaging normals over the
 * polygons that share a vertex (the readers give each polygon its own
 * copies of its vertices). */
static const stp_scene_vec3 *sort_positions;
static int compare_positions(const void *pa, const void *pb)
{
    const stp_scene_vec3 *a = &sort_positions[*(const size_t *)pa], *b = &sort_positions[*(const size_t *)pb];
    if (a->x != b->x)
        return a->x < b->x ? -1 : 1;
    if (a->y != b->y)
        return a->y < b->y ? -1 : 1;
    if (a->z != b->z)
        return a->z < b->z ? -1 : 1;
    return 0;
}

/* A polygon's vertex normals that turn further than STP_TOOL_SMOOTH_LIMIT
 * from its own (Newell) normal, oriented as the vertex normals mostly are,
 * are replaced by it: a coarse mesh's analytic normals (the SPD teapot's
 * spout and rim) may point away from the face they sit on, and Gouraud
 * would then shade its interior darker than any side of the surface is.
 * Flat on those vertices, the face keeps the light flat shading gives it. */
#define STP_TOOL_SMOOTH_LIMIT_COS 0.5 /* 60 degrees */
static void keep_normals_near_faces(const stp_scene *scene, stp_scene_vec3 *normals)
{
    size_t p;
    for (p = 0; p < scene->polygon_count; p++) {
        const stp_scene_polygon *poly = &scene->polygons[p];
        stp_scene_vec3 n = {0, 0, 0}, *vn = normals + poly->first;
        double len, along = 0;
        int k;
        for (k = 0; k < poly->count; k++) {
            const stp_scene_vec3 *a = &scene->vertices[poly->first + (size_t)(k == 0 ? poly->count - 1 : k - 1)];
            const stp_scene_vec3 *b = &scene->vertices[poly->first + (size_t)k];
            n.x += (a->y - b->y) * (a->z + b->z);
            n.y += (a->z - b->z) * (a->x + b->x);
            n.z += (a->x - b->x) * (a->y + b->y);
        }
        len = sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
        if (!(len > 0))
            continue;
        for (k = 0; k < poly->count; k++) {
            double l = sqrt(vn[k].x * vn[k].x + vn[k].y * vn[k].y + vn[k].z * vn[k].z);
            if (l > 0)
                along += (vn[k].x * n.x + vn[k].y * n.y + vn[k].z * n.z) / l;
        }
        if (along < 0)
            len = -len; /* the face normal the way the vertex normals point */
        for (k = 0; k < poly->count; k++) {
            double l = sqrt(vn[k].x * vn[k].x + vn[k].y * vn[k].y + vn[k].z * vn[k].z);
            if (!(l > 0) || (vn[k].x * n.x + vn[k].y * n.y + vn[k].z * n.z) / (l * len) < STP_TOOL_SMOOTH_LIMIT_COS) {
                vn[k].x = n.x / len;
                vn[k].y = n.y / len;
                vn[k].z = n.z / len;
            }
        }
    }
}

/* Vertex normals for every vertex: the file's where a polygon has them,
 * else the area-weighted average of the Newell normals of the polygons
 * meeting at that position.  Returns a malloc'ed array or NULL. */
static stp_scene_vec3 *vertex_normals(const stp_scene *scene)
{
    size_t nv = scene->vertex_count, i, j, p;
    stp_scene_vec3 *face = calloc(nv ? nv : 1, sizeof *face), *out = calloc(nv ? nv : 1, sizeof *out);
    size_t *order = malloc(sizeof *order * (nv ? nv : 1));
    if (!face || !out || !order) {
        free(face);
        free(out);
        free(order);
        return NULL;
    }
    for (p = 0; p < scene->polygon_count; p++) {
        const stp_scene_polygon *poly = &scene->polygons[p];
        stp_scene_vec3 n = {0, 0, 0};
        int k;
        for (k = 0; k < poly->count; k++) {
            const stp_scene_vec3 *a = &scene->vertices[poly->first + (size_t)(k == 0 ? poly->count - 1 : k - 1)];
            const stp_scene_vec3 *b = &scene->vertices[poly->first + (size_t)k];
            n.x += (a->y - b->y) * (a->z + b->z);
            n.y += (a->z - b->z) * (a->x + b->x);
            n.z += (a->x - b->x) * (a->y + b->y);
        }
        for (k = 0; k < poly->count; k++)
            face[poly->first + (size_t)k] = n;
    }
    for (i = 0; i < nv; i++)
        order[i] = i;
    sort_positions = scene->vertices;
    qsort(order, nv, sizeof *order, compare_positions);
    for (i = 0; i < nv; i = j) {
        stp_scene_vec3 sum = {0, 0, 0};
        size_t k;
        for (j = i; j < nv && compare_positions(&order[i], &order[j]) == 0; j++) {
            sum.x += face[order[j]].x;
            sum.y += face[order[j]].y;
            sum.z += face[order[j]].z;
        }
        for (k = i; k < j; k++)
            out[order[k]] = sum;
    }
    for (p = 0; p < scene->polygon_count; p++) {
        const stp_scene_polygon *poly = &scene->polygons[p];
        int k;
        if (poly->has_normals && scene->normals)
            for (k = 0; k < poly->count; k++)
                out[poly->first + (size_t)k] = scene->normals[poly->first + (size_t)k];
    }
    free(face);
    free(order);
    keep_normals_near_faces(scene, out);
    return out;
}

static double dist3(stp_scene_vec3 a, stp_scene_vec3 b)
{
    double dx = a.x - b.x, dy = a.y - b.y, dz = a.z - b.z;
    return sqrt(dx * dx + dy * dy + dz * dz);
}

int stp_tool_view_of(const stp_scene *scene, const stp_tool_options *opt, stp_tool_view *v)
{
    stp_scene_vec3 lo, hi, centre;
    double radius;
    if (stp_scene_bounds(scene, &lo, &hi) != 0)
        return -1;
    centre.x = (lo.x + hi.x) / 2;
    centre.y = (lo.y + hi.y) / 2;
    centre.z = (lo.z + hi.z) / 2;
    radius = dist3(lo, hi) / 2;
    if (radius <= 0)
        radius = 1;
    if (scene->has_view) {
        v->from = scene->from;
        v->at = scene->at;
        v->up = scene->up;
        v->fov_degrees = opt->fov > 0 ? opt->fov : scene->angle;
        v->hither = scene->hither > 0 ? scene->hither : 1e-3;
    } else {
        /* a mesh with no view: look at its centre from the +x+y+z octant
         * (y up, as OBJ files usually are), far enough for 45 degrees */
        double fov = opt->fov > 0 ? opt->fov : 45.0;
        double d = radius / sin(fov * 0.5 * 3.14159265358979323846 / 180.0) * 1.05;
        v->from.x = centre.x + d * 0.48;
        v->from.y = centre.y + d * 0.40;
        v->from.z = centre.z + d * 0.78;
        v->at = centre;
        v->up.x = v->up.z = 0;
        v->up.y = 1;
        v->fov_degrees = fov;
        v->hither = d * 1e-3;
    }
    return 0;
}

/* weight[j]: how many lights light j stands for (NULL: 1 each); factor[j]:
 * a factor on its power (NULL: 1). */
static int setup_lights(const stp_scene *scene, const stp_tool_options *opt, const double *weight,
                        const double *factor, stp_view *view_out, stp_lighting *lighting_out,
                        char *err, size_t err_size)
{
    stp_scene_vec3 lo, hi, centre;
    double radius;
    stp_view view;
    stp_tool_view dv;
    stp_lighting lighting;
    stp_scene_vec3 light_pos[STP_MAX_LIGHTS];
    double light_total;
    int light_count, j, ch;

    if (stp_scene_bounds(scene, &lo, &hi) != 0) {
        snprintf(err, err_size, "the scene has no polygons to render");
        return -1;
    }
    centre.x = (lo.x + hi.x) / 2;
    centre.y = (lo.y + hi.y) / 2;
    centre.z = (lo.z + hi.z) / 2;
    radius = dist3(lo, hi) / 2;
    if (radius <= 0)
        radius = 1;

    stp_tool_view_of(scene, opt, &dv);
    memset(&view, 0, sizeof view);
    view.from = stp_tool_vec3(dv.from);
    view.at = stp_tool_vec3(dv.at);
    view.up = stp_tool_vec3(dv.up);
    view.fov_degrees = stp_tool_fix(dv.fov_degrees);
    view.hither = stp_tool_fix(dv.hither);
    if (view.hither <= 0)
        view.hither = 1;
    view.projection = opt->perspective ? STP_PERSPECTIVE : STP_PARALLEL;
    view.window_half = stp_tool_fix(radius);

    /* lights: the options', else the scene's, else one above-left of the eye */
    if (opt->light_count > 0) {
        light_count = opt->light_count > STP_MAX_LIGHTS ? STP_MAX_LIGHTS : opt->light_count;
        for (j = 0; j < light_count; j++)
            light_pos[j] = opt->lights[j];
    } else if (scene->light_count > 0) {
        light_count = (int)(scene->light_count > STP_MAX_LIGHTS ? STP_MAX_LIGHTS : scene->light_count);
        for (j = 0; j < light_count; j++)
            light_pos[j] = scene->lights[j].position;
    } else {
        stp_scene_vec3 eye = scene->has_view ? scene->from : centre;
        light_pos[0].x = eye.x - radius;
        light_pos[0].y = eye.y + radius * 2;
        light_pos[0].z = eye.z + radius * 3;
        light_count = 1;
    }
    memset(&lighting, 0, sizeof lighting);
    lighting.brightness = stp_tool_fix(opt->brightness);
    lighting.background = stp_tool_fix(opt->background);
    lighting.attenuation_c = stp_tool_fix(opt->attenuation_c);
    lighting.count = light_count;
    {
        double total = 0;
        for (j = 0; j < light_count; j++)
            total += weight ? weight[j] : 1.0;
        light_total = total;
    }
    for (j = 0; j < light_count; j++) {
        /* auto power: P_j = (1 - B)(C + U_j)/sqrt(lights), U_j the distance
         * to the scene's centre, so 1/(C+U) does not darken a scene whose
         * lights stand far off (the SPD files place them 10-150 units away)
         * and several lights together stay near full scale */
        double power = (1.0 - opt->background) * (weight ? weight[j] : 1.0) * (factor ? factor[j] : 1.0);
        if (opt->auto_power)
            power *= (opt->attenuation_c + dist3(light_pos[j], centre)) / sqrt(light_total);
        lighting.lights[j].position = stp_tool_vec3(light_pos[j]);
        lighting.lights[j].power = stp_tool_fix(power);
        for (ch = 0; ch < 3; ch++)
            lighting.lights[j].colour[ch] =
                stp_tool_fix(opt->colour && opt->light_count <= 0 && (size_t)j < scene->light_count
                                 ? clamp01(scene->lights[j].color[ch])
                                 : 1.0);
    }

    *view_out = view;
    *lighting_out = lighting;
    return 0;
}

int stp_tool_setup(const stp_scene *scene, const stp_tool_options *opt, stp_view *view,
                   stp_lighting *lighting, char *err, size_t err_size)
{
    return setup_lights(scene, opt, NULL, NULL, view, lighting, err, err_size);
}

int stp_tool_setup_prepared(const stp_tool_prepared *p, stp_view *view, stp_lighting *lighting,
                            char *err, size_t err_size)
{
    return setup_lights(&p->scene, &p->opt, p->light_weight, p->power_factor, view, lighting, err,
                        err_size);
}

int stp_tool_output(const stp_scene *scene, const stp_tool_options *opt, stp_output *out,
                    stp_cell *cell, uint8_t **gamma, stp_fix background_rgb[3], char *err,
                    size_t err_size)
{
    int ch;
    memset(out, 0, sizeof *out);
    *gamma = 0;
    out->hidden = opt->hidden;
    if (stp_tool_cell(opt, cell) != 0) {
        snprintf(err, err_size, "bad halftone cell");
        return -1;
    }
    out->cell = cell;
    if (opt->gamma != 1.0 || opt->gamma_k != 1.0) {
        *gamma = malloc((size_t)opt->levels);
        if (!*gamma || stp_gamma_table(*gamma, opt->levels, stp_tool_fix(opt->gamma),
                                       stp_tool_fix(opt->gamma_k)) != 0) {
            snprintf(err, err_size, "bad gamma table");
            free(*gamma);
            *gamma = 0;
            return -1;
        }
        out->gamma = *gamma;
    }
    out->styles = opt->styles;
    if (scene->has_background) {
        const double *b = scene->background;
        double lum = 0.30 * b[0] + 0.59 * b[1] + 0.11 * b[2];
        out->background = stp_tool_fix(lum < 0 ? 0 : (lum > 1 ? 1 : lum));
        if (opt->colour) {
            for (ch = 0; ch < 3; ch++)
                background_rgb[ch] = stp_tool_fix(clamp01(b[ch]));
            out->background_colour = background_rgb;
        }
    }
    return 0;
}

int stp_tool_render(const stp_scene *scene, const stp_tool_options *opt, stp_port *port,
                    stp_tool_stats *stats, char *err, size_t err_size)
{
    stp_tool_prepared prep;
    int rc;
    if (opt->outlines_auto && !opt->outlines && !opt->raytrace &&
        (port->format == STP_PIXEL_MONO1 || port->format == STP_PIXEL_MONO1_PAGES)) {
        /* silhouettes when the picture would not show its objects (readable.h) */
        stp_tool_options o = *opt;
        int silhouettes = 0;
        double level = 0;
        o.outlines_auto = 0;
        if (stp_tool_auto_outlines(scene, &o, &silhouettes, &level, err, err_size) != 0)
            return -1;
        if (silhouettes) {
            o.outlines = STP_OUTLINE_SILHOUETTE;
            o.outline_level = level;
        }
        return stp_tool_render(scene, &o, port, stats, err, err_size);
    }
    if (stp_tool_tone_wanted(opt))
        return stp_tool_render_toned(scene, opt, port, stats, err, err_size);
    if (opt->smooth && !opt->raytrace && !opt->subdivided) {
        /* large smooth polygons in pieces, so a floor under a light keeps
         * its light (subdivide.h) */
        stp_scene split;
        stp_tool_options whole = *opt;
        rc = stp_tool_subdivide(scene, opt, &split, err, err_size);
        if (rc < 0)
            return -1;
        whole.subdivided = 1;
        if (rc == 0)
            return stp_tool_render(scene, &whole, port, stats, err, err_size);
        rc = stp_tool_render(&split, &whole, port, stats, err, err_size);
        stp_tool_subdivided_free(&split);
        return rc;
    }
    if (opt->raytrace) {
#if STP_WITH_RAYTRACE
        return stp_tool_raytrace(scene, opt, port, stats, err, err_size);
#else
        snprintf(err, err_size, "this build has no ray tracer (STP_WITH_RAYTRACE 0)");
        return -1;
#endif
    }
    if (stp_tool_prepare(scene, opt, &prep, err, err_size) != 0)
        return -1;
    rc = stp_tool_render_prepared(&prep, port, stats, err, err_size);
    stp_tool_prepared_free(&prep);
    return rc;
}

static double fix_to_double(stp_fix v)
{
    return (double)v / STP_FIX_ONE;
}

/* The outline view of the core's view of a prepared scene. */
static void outline_view(const stp_tool_prepared *prep, const stp_view *view, stp_outline_view *out)
{
    stp_outline_view ov;
    ov.perspective = view->projection == STP_PERSPECTIVE;
    ov.from.x = fix_to_double(view->from.x);
    ov.from.y = fix_to_double(view->from.y);
    ov.from.z = fix_to_double(view->from.z);
    ov.at.x = fix_to_double(view->at.x);
    ov.at.y = fix_to_double(view->at.y);
    ov.at.z = fix_to_double(view->at.z);
    ov.up.x = fix_to_double(view->up.x);
    ov.up.y = fix_to_double(view->up.y);
    ov.up.z = fix_to_double(view->up.z);
    ov.fov_degrees = fix_to_double(view->fov_degrees);
    ov.window_half = fix_to_double(view->window_half);
    ov.width = prep->opt.width;
    ov.height = prep->opt.height;
    *out = ov;
}

/* The outline pieces of the prepared scene for the core's view. */
static int find_outlines(const stp_tool_prepared *prep, const stp_view *view, stp_outline_segment **seg,
                         size_t *count)
{
    stp_outline_view ov;
    outline_view(prep, view, &ov);
    return stp_outlines_find(&prep->scene, &ov, prep->opt.outlines, prep->opt.crease_angle, seg, count);
}

int stp_tool_outline_pixels(const stp_scene *scene, const stp_tool_options *opt, int kinds, double **xy,
                            size_t *count, char *err, size_t err_size)
{
    stp_tool_prepared prep;
    stp_view view;
    stp_lighting lighting;
    stp_outline_view ov;
    stp_outline_segment *seg = 0;
    size_t n = 0, i;
    int rc = -1;
    *xy = 0;
    *count = 0;
    if (stp_tool_prepare(scene, opt, &prep, err, err_size) != 0)
        return -1;
    if (stp_tool_setup_prepared(&prep, &view, &lighting, err, err_size) != 0)
        goto done;
    outline_view(&prep, &view, &ov);
    if (stp_outlines_find(&prep.scene, &ov, kinds, prep.opt.crease_angle, &seg, &n) != 0) {
        snprintf(err, err_size, "outlines: out of memory, or a view with from = at or up along the "
                                "line of sight");
        goto done;
    }
    *xy = malloc(sizeof **xy * 4 * (n ? n : 1));
    if (!*xy) {
        snprintf(err, err_size, "out of memory");
        goto done;
    }
    for (i = 0; i < n; i++) {
        double *q = *xy + 4 * *count;
        if (stp_outline_project(&ov, seg[i].a, &q[0], &q[1]) == 0 &&
            stp_outline_project(&ov, seg[i].b, &q[2], &q[3]) == 0)
            ++*count;
    }
    rc = 0;
done:
    free(seg);
    stp_tool_prepared_free(&prep);
    return rc;
}

/* The lines' shade: the option's, or for "auto" black unless the
 * background is dark (luminance below one half), then white. */
static double outline_level(const stp_scene *scene, const stp_tool_options *opt)
{
    const double *bg = opt->background_given ? opt->background_rgb
                                             : (scene->has_background ? scene->background : 0);
    if (opt->outline_level >= 0)
        return opt->outline_level;
    if (!bg)
        return 0; /* the core's default background is black: stay black */
    return 0.30 * bg[0] + 0.59 * bg[1] + 0.11 * bg[2] < 0.5 ? 1.0 : 0.0;
}

/* Enter the outline pieces as lines after the polygons. */
static int enter_outlines(stp_renderer *r, const stp_scene *scene, const stp_tool_options *opt,
                          const stp_outline_segment *seg, size_t count, char *err, size_t err_size)
{
    size_t i;
    int status = stp_renderer_set_fill_style(r, stp_intensity_index(stp_tool_fix(outline_level(scene, opt)),
                                                                     opt->levels));
    for (i = 0; status == STP_OK && i < count; i++) {
        status = stp_renderer_move(r, stp_tool_vec3(seg[i].a));
        if (status == STP_OK)
            status = stp_renderer_line(r, stp_tool_vec3(seg[i].b));
    }
    if (status != STP_OK) {
        snprintf(err, err_size, "outline %zu: %s", i, stp_status_text(status));
        return -1;
    }
    return 0;
}

/* "L: coordinate (x, y, z) of polygon N beyond ...": the core refused
 * polygon i (STP_ERR_RANGE); the vertex farthest from the eye is named in
 * the file's units. */
static void range_message(const stp_tool_prepared *prep, const stp_view *view, size_t i, char *err,
                          size_t err_size)
{
    const stp_scene *scene = &prep->scene;
    const stp_scene_polygon *p = &scene->polygons[i];
    const double one = STP_FIX_ONE;
    double ex = view->from.x / one, ey = view->from.y / one, ez = view->from.z / one, far = -1;
    stp_scene_vec3 v = scene->vertices[p->first];
    int k;
    for (k = 0; k < p->count; k++) {
        stp_scene_vec3 q = scene->vertices[p->first + (size_t)k];
        double d = hypot(hypot(q.x - ex, q.y - ey), q.z - ez);
        if (d > far) {
            far = d;
            v = q;
        }
    }
    snprintf(err, err_size,
             "%d: coordinate (%g, %g, %g) of polygon %zu beyond the core's range "
             "(+-32767 units from the eye along each view axis)%s",
             p->source_line, v.x / prep->scale + prep->offset.x, v.y / prep->scale + prep->offset.y,
             v.z / prep->scale + prep->offset.z, stp_tool_prepared_polygon_number(prep, i),
             prep->opt.keep_units ? "; without --no-rescale the scene is scaled into it" : "");
}

void stp_tool_scene_message(char *out, size_t size, const char *name, const char *err)
{
    size_t digits = strspn(err, "0123456789");
    if (digits > 0 && err[digits] == ':')
        snprintf(out, size, "%s:%s", name, err);
    else
        snprintf(out, size, "%s: %s", name, err);
}

int stp_tool_render_prepared(const stp_tool_prepared *prep, stp_port *port,
                             stp_tool_stats *stats, char *err, size_t err_size)
{
    const stp_scene *scene = &prep->scene;
    const stp_tool_options *opt = &prep->opt;
    stp_view view;
    stp_lighting lighting;
    stp_renderer *r = 0;
    void *rmem = 0;
    stp_instr *df = 0;
    uint8_t *band = 0, *gamma = 0;
    uint16_t *zbuf = 0;
    stp_sort_entry *sort = 0;
    stp_cell cell;
    stp_output out;
    stp_frame_memory mem;
    size_t capacity = 16, i;
    int status, last_material = -1, band_rows, result = -1;
    stp_fix background_rgb[3];
    stp_tool_stats local;
    stp_scene_vec3 *normals = 0;
    uint16_t *shadow_maps = 0;
    stp_diffusion diffusion;
    int diffusing = 0, one_bit;
    stp_outline_segment *outline = 0;
    size_t outline_count = 0;

    memset(&diffusion, 0, sizeof diffusion);
    if (!stats)
        stats = &local;
    memset(stats, 0, sizeof *stats);
    if (stp_tool_setup_prepared(prep, &view, &lighting, err, err_size) != 0)
        return -1;

    if (opt->outlines && find_outlines(prep, &view, &outline, &outline_count) != 0) {
        snprintf(err, err_size,
                 "outlines: out of memory, or a view with from = at or up along the line of sight");
        return -1;
    }
    capacity += 3 * outline_count; /* a style, then move and line each */
    for (i = 0; i < scene->polygon_count; i++)
        /* the polygon, a style and a transparency attribute, and with
         * shadows its light records */
        capacity += (size_t)scene->polygons[i].count + 6 +
                    (opt->shadow_resolution ? 1u + STP_MAX_LIGHTS : 0u);
    if (capacity > 0xFFFFFFFFu) {
        snprintf(err, err_size, "scene too large for one display file");
        goto done;
    }
    rmem = malloc(stp_renderer_size());
    df = malloc(sizeof *df * capacity);
    if (!rmem || !df) {
        snprintf(err, err_size, "out of memory");
        goto done;
    }
    r = stp_renderer_create(rmem, stp_renderer_size(), df, (uint32_t)capacity,
                            (uint32_t)opt->width, (uint32_t)opt->height);
    if (!r) {
        snprintf(err, err_size, "bad size %dx%d", opt->width, opt->height);
        goto done;
    }
    if ((status = stp_renderer_set_view(r, &view)) != STP_OK || (status = stp_renderer_set_levels(r, opt->levels)) != STP_OK ||
        (status = stp_renderer_set_lighting(r, &lighting)) != STP_OK) {
        snprintf(err, err_size, "view: %s", stp_status_text(status));
        goto done;
    }
    if ((status = stp_renderer_set_shading(r, opt->shading)) != STP_OK ||
        (status = stp_renderer_set_backface_removal(r, opt->backface_removal)) != STP_OK) {
        snprintf(err, err_size, "shading: %s", stp_status_text(status));
        goto done;
    }
    if (opt->colour && (status = stp_renderer_set_colour(r, 1)) != STP_OK) {
        snprintf(err, err_size, "colour: %s", stp_status_text(status));
        goto done;
    }
    if (opt->shadow_resolution > 0 && lighting.count > 0) {
        size_t n = (size_t)opt->shadow_resolution * opt->shadow_resolution * (size_t)lighting.count;
        shadow_maps = malloc(sizeof *shadow_maps * n);
        if (!shadow_maps) {
            snprintf(err, err_size, "out of memory for the shadow maps");
            goto done;
        }
        if (stp_tool_shadows_setup(r, scene, &view, (double)opt->width / opt->height, &lighting,
                                   opt->shadow_resolution, shadow_maps, n, err, err_size) != 0)
            goto done;
    }
    if ((status = stp_segment_create(r, 1)) != STP_OK) {
        snprintf(err, err_size, "segment: %s", stp_status_text(status));
        goto done;
    }
    if (opt->smooth) {
        normals = vertex_normals(scene);
        if (!normals) {
            snprintf(err, err_size, "out of memory");
            goto done;
        }
    }
    for (i = 0; i < scene->polygon_count; i++) {
        const stp_scene_polygon *p = &scene->polygons[i];
        stp_vec3 v[STP_MAX_POLYGON_VERTICES], vn[STP_MAX_POLYGON_VERTICES];
        int k;
        if (p->material != last_material) {
            stp_material m;
            stp_material_default(&m);
            if (p->material >= 0 && (size_t)p->material < scene->material_count)
                stp_tool_material(&scene->materials[p->material], opt->colour, &m);
            if ((status = stp_renderer_set_object_shade(r, &m)) != STP_OK) {
                snprintf(err, err_size, "%d: material of polygon %zu: %s", p->source_line, i + 1,
                         stp_status_text(status));
                goto done;
            }
            /* NFF's T: the surface transmits up to T facing the eye and T/2
             * at grazing angles, (10.21) with power 2; no thickness known */
            if (opt->transparency) {
                double t = p->material >= 0 && (size_t)p->material < scene->material_count
                               ? scene->materials[p->material].t
                               : 0.0;
                t = t < 0 ? 0 : (t > 1 ? 1 : t);
                status = stp_renderer_set_transparency(r, stp_tool_fix(t / 2), stp_tool_fix(t), 2, 0, 0);
                if (status != STP_OK) {
                    snprintf(err, err_size, "transparency: %s", stp_status_text(status));
                    goto done;
                }
            }
            /* with shading off the material's reflectivity picks the style */
            (void)stp_renderer_set_fill_style(r, stp_intensity_index(m.reflectivity, opt->levels)); /* in range */
            last_material = p->material;
        }
        if (p->count > STP_MAX_POLYGON_VERTICES) {
            snprintf(err, err_size, "%d: polygon %zu has %d vertices; this build takes %d",
                     p->source_line, i + 1, p->count, STP_MAX_POLYGON_VERTICES);
            goto done;
        }
        for (k = 0; k < p->count; k++)
            v[k] = stp_tool_vec3(scene->vertices[p->first + (size_t)k]);
        stats->polygons_in++;
        if (normals) {
            for (k = 0; k < p->count; k++) {
                /* normals as unit vectors: their length is irrelevant and
                 * area-weighted sums may exceed stp_fix's range */
                stp_scene_vec3 nn = normals[p->first + (size_t)k];
                double len = sqrt(nn.x * nn.x + nn.y * nn.y + nn.z * nn.z);
                if (len > 0) {
                    nn.x /= len;
                    nn.y /= len;
                    nn.z /= len;
                }
                vn[k] = stp_tool_vec3(nn);
            }
            status = stp_renderer_polygon_smooth(r, v, vn, p->count);
        } else {
            status = stp_renderer_polygon(r, v, p->count);
        }
        if (status == STP_ERR_DEGENERATE) {
            stats->polygons_skipped++;
            continue;
        }
        if (status == STP_ERR_RANGE) {
            range_message(prep, &view, i, err, err_size);
            goto done;
        }
        if (status != STP_OK) {
            snprintf(err, err_size, "%d: polygon %zu: %s", p->source_line,
                     stp_tool_prepared_polygon_number(prep, i),
                     stp_status_text(status));
            goto done;
        }
    }
    if (outline_count && enter_outlines(r, scene, opt, outline, outline_count, err, err_size) != 0)
        goto done;
    (void)stp_segment_close(r);
    stats->display_entries = stp_renderer_display_file_used(r);

    band_rows = stp_tool_band_rows(opt, port);
    memset(&mem, 0, sizeof mem);
    mem.band_rows = (uint32_t)band_rows;
    one_bit = port->format == STP_PIXEL_MONO1 || port->format == STP_PIXEL_MONO1_PAGES;
    diffusing = one_bit && stp_tool_diffusion(opt, (uint32_t)opt->width, &diffusion) != 0;
    /* error diffusion and edge anti-aliasing draw a 1-bit band as GREY8 (render.h, stp_output) */
    mem.band_size = stp_tool_band_bytes(diffusing || (opt->edge_aa && one_bit) ? STP_PIXEL_GREY8 : port->format,
                                        (uint32_t)opt->width, band_rows);
    band = malloc(mem.band_size);
    mem.band = band;
    if (opt->hidden == STP_HIDDEN_ZBUFFER) {
        mem.zbuf_count = (size_t)opt->width * (size_t)band_rows;
        zbuf = malloc(sizeof *zbuf * mem.zbuf_count);
        mem.zbuf = zbuf;
    } else if (opt->hidden == STP_HIDDEN_PAINTER) {
        mem.sort_count = stp_renderer_polygon_count(r) + 1;
        sort = malloc(sizeof *sort * mem.sort_count);
        mem.sort = sort;
    }
    if (!band || (opt->hidden == STP_HIDDEN_ZBUFFER && !zbuf) ||
        (opt->hidden == STP_HIDDEN_PAINTER && !sort)) {
        snprintf(err, err_size, "out of memory");
        goto done;
    }
    if (diffusing && !diffusion.errors) {
        snprintf(err, err_size, "out of memory");
        goto done;
    }
    if (stp_tool_output(scene, opt, &out, &cell, &gamma, background_rgb, err, err_size) != 0)
        goto done;
    if (diffusing)
        out.diffusion = &diffusion;
    out.edge_aa = opt->edge_aa;
    stats->frame_bytes = stp_renderer_size() + sizeof *df * stats->display_entries + mem.band_size +
                         sizeof(uint16_t) * mem.zbuf_count + sizeof(stp_sort_entry) * mem.sort_count +
                         sizeof(int16_t) * diffusion.error_count;
    status = stp_renderer_render(r, port, &out, &mem);
    if (status != STP_OK) {
        snprintf(err, err_size, "render: %s", stp_status_text(status));
        goto done;
    }
    result = 0;
done:
    free(outline);
    free(diffusion.errors);
    free(shadow_maps);
    free(normals);
    free(rmem);
    free(df);
    free(band);
    free(zbuf);
    free(sort);
    free(gamma);
    return result;
}
