/* SPDX-License-Identifier: MIT */
/* The tone of a picture: see tone.h. */
#include "tone.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int stp_tool_tone_wanted(const stp_tool_options *opt)
{
    return opt->grey_contrast || opt->background_given || opt->exposure_auto;
}

static double luminance(const double *c)
{
    return 0.30 * c[0] + 0.59 * c[1] + 0.11 * c[2];
}

void stp_tool_contrast_greys(const stp_scene *scene, double *grey_of_material, double *grey_background)
{
    size_t n = scene->material_count + (scene->has_background ? 1u : 0u), i;
    double mean[3] = {0, 0, 0}, cov[3][3] = {{0}}, axis[3] = {0.30, 0.59, 0.11}, len, lo = 1e9, hi = -1e9;
    double shift = 0, *proj;
    int it, a, b;
    if (n == 0)
        return;
    proj = malloc(sizeof *proj * n);
    if (!proj)
        return;
#define COLOUR(k) ((k) < scene->material_count ? scene->materials[k].color : scene->background)
    for (i = 0; i < n; i++)
        for (a = 0; a < 3; a++)
            mean[a] += COLOUR(i)[a] / (double)n;
    for (i = 0; i < n; i++)
        for (a = 0; a < 3; a++)
            for (b = 0; b < 3; b++)
                cov[a][b] += (COLOUR(i)[a] - mean[a]) * (COLOUR(i)[b] - mean[b]);
    /* power iteration from the luminance direction */
    for (it = 0; it < 100; it++) {
        double next[3];
        for (a = 0; a < 3; a++)
            next[a] = cov[a][0] * axis[0] + cov[a][1] * axis[1] + cov[a][2] * axis[2];
        len = sqrt(next[0] * next[0] + next[1] * next[1] + next[2] * next[2]);
        if (len < 1e-12)
            break;
        for (a = 0; a < 3; a++)
            axis[a] = next[a] / len;
    }
    len = sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
    for (a = 0; a < 3; a++)
        axis[a] /= len;
    if (luminance(axis) < 0)
        for (a = 0; a < 3; a++)
            axis[a] = -axis[a];
    for (i = 0; i < n; i++) {
        const double *c = COLOUR(i);
        double d = (c[0] - mean[0]) * axis[0] + (c[1] - mean[1]) * axis[1] + (c[2] - mean[2]) * axis[2];
        proj[i] = luminance(mean) + d / sqrt(3.0);
        if (proj[i] < lo)
            lo = proj[i];
        if (proj[i] > hi)
            hi = proj[i];
    }
    if (lo < 0)
        shift = -lo;
    else if (hi > 1)
        shift = 1 - hi;
    for (i = 0; i < n; i++) {
        double g = proj[i] + shift;
        g = g < 0 ? 0 : (g > 1 ? 1 : g);
        if (i < scene->material_count)
            grey_of_material[i] = g;
        else
            *grey_background = g;
    }
#undef COLOUR
    free(proj);
}

/* A port that keeps the brightest byte it is sent. */
typedef struct probe {
    stp_port port;
    unsigned brightest;
} probe;

static int probe_flush(stp_port *port, uint32_t y0, uint32_t rows, const uint8_t *pixels, size_t stride)
{
    probe *p = (probe *)port->user;
    size_t n = stp_row_bytes(port->format, port->width), r, i;
    (void)y0;
    for (r = 0; r < rows; r++)
        for (i = 0; i < n; i++)
            if (pixels[r * stride + i] > p->brightest)
                p->brightest = pixels[r * stride + i];
    return 0;
}

/* The tone's scene: greys that keep contrast, the chosen background.
 * *materials: allocated when replaced (the caller frees it). */
static int toned_scene(const stp_scene *scene, const stp_tool_options *opt, stp_scene *toned,
                       stp_scene_material **materials, char *err, size_t err_size)
{
    *toned = *scene;
    *materials = 0;
    if (opt->grey_contrast && !opt->colour && scene->material_count > 0) {
        double *greys = malloc(sizeof *greys * scene->material_count), bg = 0;
        size_t i;
        *materials = malloc(sizeof **materials * scene->material_count);
        if (!greys || !*materials) {
            free(greys);
            free(*materials);
            *materials = 0;
            snprintf(err, err_size, "out of memory");
            return -1;
        }
        stp_tool_contrast_greys(scene, greys, &bg);
        for (i = 0; i < scene->material_count; i++) {
            (*materials)[i] = scene->materials[i];
            (*materials)[i].color[0] = (*materials)[i].color[1] = (*materials)[i].color[2] = greys[i];
        }
        if (scene->has_background)
            toned->background[0] = toned->background[1] = toned->background[2] = bg;
        toned->materials = *materials;
        free(greys);
    }
    if (opt->background_given) {
        toned->has_background = 1;
        memcpy(toned->background, opt->background_rgb, sizeof toned->background);
    }
    return 0;
}

/* The exposure gain of an already toned scene: 255 over the brightest
 * byte of a probe render with a black frame (1 when nothing is lit). */
static int probe_gain(const stp_scene *toned, const stp_tool_options *plain, double *gain, char *err,
                      size_t err_size)
{
    stp_scene dark = *toned;
    stp_tool_options p = *plain;
    probe pr;
    dark.has_background = 1;
    dark.background[0] = dark.background[1] = dark.background[2] = 0;
    p.levels = 256;
    p.dither = STP_TOOL_DITHER_BAYER4;
    p.band_rows = 0;
    p.outlines = 0; /* the scene's light sets the exposure, not lines over it */
    memset(&pr, 0, sizeof pr);
    pr.port.width = (uint32_t)plain->width;
    pr.port.height = (uint32_t)plain->height;
    pr.port.format = plain->colour ? STP_PIXEL_RGB888 : STP_PIXEL_GREY8;
    pr.port.flush = probe_flush;
    pr.port.user = &pr;
    if (stp_tool_render(&dark, &p, &pr.port, 0, err, err_size) != 0)
        return -1;
    *gain = pr.brightest > 0 ? 255.0 / (double)pr.brightest : 1.0;
    return 0;
}

int stp_tool_exposure_gain(const stp_scene *scene, const stp_tool_options *opt, double *gain, char *err,
                           size_t err_size)
{
    stp_scene toned;
    stp_scene_material *materials;
    stp_tool_options plain = *opt;
    int rc;
    plain.grey_contrast = plain.background_given = plain.exposure_auto = 0;
    if (toned_scene(scene, opt, &toned, &materials, err, err_size) != 0)
        return -1;
    rc = probe_gain(&toned, &plain, gain, err, err_size);
    free(materials);
    return rc;
}

int stp_tool_render_toned(const stp_scene *scene, const stp_tool_options *opt, stp_port *port,
                          stp_tool_stats *stats, char *err, size_t err_size)
{
    stp_scene toned;
    stp_tool_options plain = *opt;
    stp_scene_material *materials;
    int rc;
    plain.grey_contrast = plain.background_given = plain.exposure_auto = 0;
    if (toned_scene(scene, opt, &toned, &materials, err, err_size) != 0)
        return -1;
    if (opt->exposure_auto) {
        double gain;
        if (probe_gain(&toned, &plain, &gain, err, err_size) != 0) {
            free(materials);
            return -1;
        }
        plain.brightness *= gain;
    }
    rc = stp_tool_render(&toned, &plain, port, stats, err, err_size);
    free(materials);
    return rc;
}
