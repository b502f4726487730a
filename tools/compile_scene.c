/* SPDX-License-Identifier: MIT */
/* Host side: a stp_scene compiled to C for firmware.  See compile_scene.h. */
#define _POSIX_C_SOURCE 200809L
#include "compile_scene.h"

#include <errno.h>
#include <getopt.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "options.h"
#include "scene_prepare.h"
#include "static_order.h"
#include "static_spans.h"
#include "compile_mesh.h"
#include "stp_scene_data.h"
#include "scene_util.h"

/* The scene is prepared as stp_tool_render prepares it (scene_prepare.h:
 * units, merged lights, split polygons); the view, lighting and materials
 * come from stp_tool_setup_prepared and stp_tool_material, the same calls
 * stp_tool_render makes, so the firmware's picture matches `stipple render`
 * (the QEMU test checks it pixel for pixel). */

static stp_vec3 fix3(stp_scene_vec3 v)
{
    stp_vec3 r;
    r.x = stp_tool_fix(v.x);
    r.y = stp_tool_fix(v.y);
    r.z = stp_tool_fix(v.z);
    return r;
}



/* ---- sizing: run the scene through the host core once ---- */

static int discard_rows(stp_port *port, uint32_t y0, uint32_t rows, const uint8_t *pixels,
                        size_t stride)
{
    (void)port;
    (void)y0;
    (void)rows;
    (void)pixels;
    (void)stride;
    return 0;
}

/* The display file's exact size comes from entering the scene for real:
 * clipping adds vertices and SHADE instructions depend on the shades, which
 * only the core knows.  The core's switches do not change what it enters, so
 * the host build's count holds for the firmware's configuration. */
static int measure(const stp_tool_prepared *prep, stp_tool_stats *stats, char *err, size_t errlen)
{
    stp_port port;
    stp_tool_prepared q = *prep; /* shares the scene's arrays: not freed */
    stp_tool_options *opt = &q.opt, o = q.opt;
    memset(&port, 0, sizeof port);
    port.width = (uint32_t)opt->width;
    port.height = (uint32_t)opt->height;
    port.format = STP_PIXEL_MONO1;
    port.flush = discard_rows;
    o.band_rows = 1; /* the smallest buffers: only the entry counts matter */
    o.styles = 0;
    *opt = o;
    return stp_tool_render_prepared(&q, &port, stats, err, errlen);
}

/* ---- writing ---- */

typedef struct writer {
    FILE *f;
    int failed;
} writer;

static void out(writer *w, const char *fmt, ...)
{
    va_list ap;
    if (!w->f || w->failed)
        return;
    va_start(ap, fmt);
    if (vfprintf(w->f, fmt, ap) < 0)
        w->failed = 1;
    va_end(ap);
}

static void out_vec(writer *w, stp_vec3 v)
{
    out(w, "{%ld, %ld, %ld}", (long)v.x, (long)v.y, (long)v.z);
}

static const char *hidden_name(stp_hidden h)
{
    switch (h) {
    case STP_HIDDEN_PAINTER: return "STP_HIDDEN_PAINTER";
    case STP_HIDDEN_ZBUFFER: return "STP_HIDDEN_ZBUFFER";
    default: return "STP_HIDDEN_NONE";
    }
}

/* What the scene uses, found once for both outputs. */
typedef struct plan {
    stp_view view;
    stp_lighting lighting;
    stp_material *materials;   /* compacted: only the used ones */
    int *material_map;         /* scene material index -> compacted, -1 unused */
    uint32_t material_count;
    int default_material;      /* compacted index of the default, -1 unused */
    int max_vertices;
    int specular;              /* 1 when some used material has Ks > 0 */
    unsigned long vertex_count;
    stp_tool_stats stats;
    stp_cell cell;
    uint8_t gamma[256];
    int has_gamma;
    stp_fix background;
} plan;

static int make_plan(const stp_tool_prepared *prep, plan *p, char *err, size_t errlen)
{
    const stp_scene *scene = &prep->scene;
    const stp_tool_options *opt = &prep->opt;
    size_t i;
    memset(p, 0, sizeof *p);
    p->default_material = -1;
    if (opt->width < 1 || opt->height < 1 || opt->width > 32767 || opt->height > 32767) {
        snprintf(err, errlen, "bad size %dx%d", opt->width, opt->height);
        return -1;
    }
    if (stp_tool_setup_prepared(prep, &p->view, &p->lighting, err, errlen) != 0)
        return -1;
    if (measure(prep, &p->stats, err, errlen) != 0)
        return -1;
    p->materials = calloc(scene->material_count + 1, sizeof *p->materials);
    p->material_map = malloc((scene->material_count + 1) * sizeof *p->material_map);
    if (!p->materials || !p->material_map) {
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    for (i = 0; i < scene->material_count; i++)
        p->material_map[i] = -1;
    p->max_vertices = 3;
    for (i = 0; i < scene->polygon_count; i++) {
        const stp_scene_polygon *poly = &scene->polygons[i];
        int *slot = poly->material >= 0 && (size_t)poly->material < scene->material_count
                        ? &p->material_map[poly->material]
                        : &p->default_material;
        if (*slot < 0) {
            stp_material *m = &p->materials[p->material_count];
            stp_material_default(m);
            if (slot != &p->default_material)
                stp_tool_material(&scene->materials[poly->material], opt->colour, m);
            if (m->specular != 0)
                p->specular = 1;
            *slot = (int)p->material_count++;
        }
        if (poly->count > p->max_vertices)
            p->max_vertices = poly->count;
        p->vertex_count += (unsigned long)poly->count;
    }
    if (p->material_count > 65535 || scene->polygon_count > 0xFFFFFFFFu ||
        p->vertex_count > 0xFFFFFFFFu) {
        snprintf(err, errlen, "scene too large to compile");
        return -1;
    }
    if (!opt->shading)
        p->specular = 0; /* no MAKE-SHADE at all */
    if (stp_tool_cell(opt, &p->cell) != 0) {
        snprintf(err, errlen, "bad halftone cell");
        return -1;
    }
    if (opt->gamma != 1.0 || opt->gamma_k != 1.0) {
        if (stp_gamma_table(p->gamma, opt->levels, stp_tool_fix(opt->gamma),
                            stp_tool_fix(opt->gamma_k)) != 0) {
            snprintf(err, errlen, "bad gamma table");
            return -1;
        }
        p->has_gamma = 1;
    }
    if (scene->has_background) {
        const double *b = scene->background;
        double lum = 0.30 * b[0] + 0.59 * b[1] + 0.11 * b[2];
        p->background = stp_tool_fix(lum < 0 ? 0 : (lum > 1 ? 1 : lum));
    }
    return 0;
}

static void write_config(writer *w, const plan *p, const stp_tool_options *opt, int is_static)
{
    out(w, "/* Generated by `stipple compile`: the least configuration of the core\n"
           " * this scene needs.  Use it as -DSTP_CONFIG_HEADER='\"<this file>\"' for the\n"
           " * core and the scene's C source alike. */\n"
           "#ifndef STP_COMPILED_SCENE_CONFIG_H\n"
           "#define STP_COMPILED_SCENE_CONFIG_H\n\n");
    out(w, "/* The scene's literals are stp_fix with this many fractional bits, and\n"
           " * the host's picture was made with this square root: fixed, not minimal. */\n"
           "#define STP_FIX_FRAC_BITS %d\n#define STP_SQRT_FAST %d\n\n",
        STP_FIX_FRAC_BITS, STP_SQRT_FAST);
    out(w, "/* Its largest polygon (the renderer's scratch space grows with this). */\n"
           "#define STP_MAX_POLYGON_VERTICES %d\n",
        p->max_vertices);
    out(w, "/* Lights in use (at least 1, the core's minimum). */\n"
           "#define STP_MAX_LIGHTS %d\n",
        p->lighting.count < 1 ? 1 : p->lighting.count);
    out(w, "/* The whole scene is entered into one segment. */\n"
           "#define STP_MAX_SEGMENTS 1\n");
    out(w, "/* 1 only when shading is on and some material has Ks > 0. */\n"
           "#define STP_WITH_SPECULAR %d\n",
        p->specular);
    out(w, "/* Only the hidden-surface method the output uses (%s). */\n"
           "#define STP_WITH_ZBUFFER %d\n#define STP_WITH_PAINTER %d\n",
        hidden_name(opt->hidden), opt->hidden == STP_HIDDEN_ZBUFFER,
        opt->hidden == STP_HIDDEN_PAINTER);
    out(w, "/* Scenes hold polygons only. */\n"
           "#define STP_WITH_LINES 0\n");
    out(w, "/* The scene is entered as flat grey polygons (stp_renderer_polygon), opaque and\n"
           " * without shadow maps. */\n"
           "#define STP_WITH_GOURAUD 0\n#define STP_WITH_COLOUR 0\n"
           "#define STP_WITH_TRANSPARENCY 0\n#define STP_WITH_SHADOWS 0\n");
    out(w, "/* The scene is entered once, at start-up: no vertex cache (it would cost\n"
           " * RAM a small board does not have, to speed up one pass). */\n"
           "#define STP_VERTEX_CACHE 0\n");
    out(w, "/* 1: the picture is error-diffused, so a firmware's band holds 8-bit rows\n"
           " * (stp_output.diffusion); 0: a halftone cell, 1-bit rows. */\n"
           "#define STP_COMPILED_DIFFUSION %d\n",
        opt->dither == STP_TOOL_DITHER_DIFFUSE ? 1 : 0);
    out(w, "#define STP_WITH_DIFFUSION STP_COMPILED_DIFFUSION\n"
           "/* No edge anti-aliasing on the chip (a host option): no slope per crossing. */\n"
           "#define STP_WITH_EDGE_AA 0\n"
           "/* The cell is compiled in as a value: none is built on the chip. */\n"
           "#define STP_WITH_DEFAULT_CELL 0\n");
    out(w, "/* A display file played back from flash (--static): 64-bit division by a\n"
           " * small loop, not the C library's routines, and triangles through the\n"
           " * general scan converter (size first). */\n"
           "#define STP_SMALL_DIVISION %d\n"
           "#define STP_WITH_TRIANGLE_PATH %d\n",
        is_static, !is_static);
    out(w, "/* --static: the chip only plays the display file back (a smaller renderer\n"
           " * object; the core is built from the playback sources alone). */\n"
           "#define STP_PLAYBACK_ONLY %d\n",
        is_static);
    out(w, "\n#endif\n");
}

/* The halftone cell as a value (no cell construction on the chip) and the
 * gamma table, when there is one. */
static void write_cell_gamma(writer *w, const plan *p, const stp_tool_options *opt)
{
    int k;
    out(w, "static const stp_cell cell = {%d, %d, %d, {", p->cell.kind, p->cell.width,
        p->cell.height);
    for (k = 0; k < (p->cell.mask ? 1 : p->cell.width * p->cell.height); k++)
        out(w, "%s%d", k ? ", " : "", p->cell.mask ? 0 : p->cell.thresholds[k]);
    out(w, "}, {");
    for (k = 0; k < 5; k++)
        out(w, "%s%d", k ? ", " : "", p->cell.patterns[k]);
    /* a mask cell names its const data: the core's blue noise is the one
     * the options can ask for */
    out(w, "}, %s};\n\n", p->cell.mask == stp_cell_blue_noise_64 ? "stp_cell_blue_noise_64" : "0");

    if (p->has_gamma) {
        out(w, "static const uint8_t gamma[%d] = {", opt->levels);
        for (k = 0; k < opt->levels; k++)
            out(w, "%s%d", k ? ", " : "", p->gamma[k]);
        out(w, "};\n\n");
    }
}

static void write_source(writer *w, const stp_scene *scene, const plan *p,
                         const stp_tool_options *opt)
{
    size_t i;
    uint32_t j;
    int k;
    uint32_t capacity = p->stats.display_entries > 0 ? (uint32_t)p->stats.display_entries : 1;
    uint32_t sort_count = (uint32_t)(p->stats.polygons_in - p->stats.polygons_skipped);

    out(w, "/* Generated by `stipple compile`: a %dx%d scene of %lu polygons, %lu vertices,\n"
           " * %lu materials, %d lights; display file %lu entries.  Do not edit. */\n",
        opt->width, opt->height, (unsigned long)scene->polygon_count, p->vertex_count,
        (unsigned long)p->material_count, p->lighting.count, (unsigned long)capacity);
    out(w, "#include \"stp_scene_data.h\"\n\n");
    out(w, "/* The literals below are in this format; another one would scale them. */\n"
           "#if STP_FIX_FRAC_BITS != %d\n#error \"compiled for STP_FIX_FRAC_BITS %d\"\n#endif\n"
           "#if STP_MAX_LIGHTS < %d || STP_MAX_POLYGON_VERTICES < %d\n"
           "#error \"the core's configuration is too small for this scene\"\n#endif\n\n",
        STP_FIX_FRAC_BITS, STP_FIX_FRAC_BITS, p->lighting.count < 1 ? 1 : p->lighting.count,
        p->max_vertices);

    out(w, "static const stp_vec3 vertices[%lu] STP_SCENE_ROM = {\n", p->vertex_count);
    for (i = 0; i < scene->polygon_count; i++) {
        const stp_scene_polygon *poly = &scene->polygons[i];
        for (k = 0; k < poly->count; k++) {
            out(w, "    ");
            out_vec(w, fix3(scene->vertices[poly->first + (size_t)k]));
            out(w, ",\n");
        }
    }
    out(w, "};\n\n");

    out(w, "static const stp_scene_data_polygon polygons[%lu] STP_SCENE_ROM = {\n",
        (unsigned long)scene->polygon_count);
    for (i = 0; i < scene->polygon_count; i++) {
        const stp_scene_polygon *poly = &scene->polygons[i];
        int m = poly->material >= 0 && (size_t)poly->material < scene->material_count
                    ? p->material_map[poly->material]
                    : p->default_material;
        out(w, "    {%d, %d},\n", poly->count, m);
    }
    out(w, "};\n\n");

    out(w, "/* reflectivity, refraction, gloss, specular weight, colour */\n"
           "static const stp_material materials[%lu] STP_SCENE_ROM = {\n",
        (unsigned long)p->material_count);
    for (j = 0; j < p->material_count; j++) {
        const stp_material *m = &p->materials[j];
        out(w, "    {%ld, %ld, %ld, %ld, {%ld, %ld, %ld}},\n", (long)m->reflectivity,
            (long)m->refraction, (long)m->gloss, (long)m->specular, (long)m->colour[0],
            (long)m->colour[1], (long)m->colour[2]);
    }
    out(w, "};\n\n");

    write_cell_gamma(w, p, opt);

    /* RAM: written by the core while the scene is entered and sorted */
    out(w, "static stp_instr display_file[%lu];\n", (unsigned long)capacity);
    if (opt->dither == STP_TOOL_DITHER_DIFFUSE) {
        /* error diffusion: its error rows (diffuse.h), the band is GREY8 */
        size_t n = stp_diffusion_error_count(opt->diffuse_kernel, (uint32_t)opt->width);
        out(w, "static int16_t diffusion_errors[%lu];\n", (unsigned long)n);
        if (opt->diffuse_noise)
            out(w, "static const stp_diffusion diffusion = {%d, %d, diffusion_errors, %lu, "
                   "stp_cell_blue_noise_64, %d, %d};\n",
                opt->diffuse_kernel, opt->diffuse_raster ? 0 : 1, (unsigned long)n,
                STP_DIFFUSE_NOISE_AMPLITUDE_OF(opt->diffuse_kernel), STP_DIFFUSE_NOISE_BAND);
        else
            out(w, "static const stp_diffusion diffusion = {%d, %d, diffusion_errors, %lu, 0, 0, 0};\n",
                opt->diffuse_kernel, opt->diffuse_raster ? 0 : 1, (unsigned long)n);
    }
    if (opt->hidden == STP_HIDDEN_PAINTER)
        out(w, "static stp_sort_entry sort[%lu];\n", (unsigned long)(sort_count ? sort_count : 1));
    out(w, "\n");

    out(w, "const stp_scene_data stp_compiled_scene = {\n");
    out(w, "    %d, %d, /* width, height */\n", opt->width, opt->height);
    out(w, "    %d, /* levels */\n    %d, /* shading */\n    %d, /* back-face removal */\n",
        opt->levels, opt->shading ? 1 : 0, opt->backface_removal ? 1 : 0);
    out(w, "    { /* view: from, at, up, fov, window half, hither, projection */\n        ");
    out_vec(w, p->view.from);
    out(w, ", ");
    out_vec(w, p->view.at);
    out(w, ", ");
    out_vec(w, p->view.up);
    out(w, ",\n        %ld, %ld, %ld, %s},\n", (long)p->view.fov_degrees,
        (long)p->view.window_half, (long)p->view.hither,
        p->view.projection == STP_PARALLEL ? "STP_PARALLEL" : "STP_PERSPECTIVE");
    out(w, "    { /* lighting: brightness, background, C, count, {position, power, colour} */\n"
           "        %ld, %ld, %ld, %d, {",
        (long)p->lighting.brightness, (long)p->lighting.background,
        (long)p->lighting.attenuation_c, p->lighting.count);
    for (k = 0; k < p->lighting.count; k++) {
        out(w, "%s{", k ? ", " : "");
        out_vec(w, p->lighting.lights[k].position);
        out(w, ", %ld, {%ld, %ld, %ld}}", (long)p->lighting.lights[k].power,
            (long)p->lighting.lights[k].colour[0], (long)p->lighting.lights[k].colour[1],
            (long)p->lighting.lights[k].colour[2]);
    }
    out(w, "}},\n");
    out(w, "    materials, %lu,\n    vertices, %lu,\n    polygons, %lu,\n",
        (unsigned long)p->material_count, p->vertex_count, (unsigned long)scene->polygon_count);
    out(w, "    display_file, %lu,\n", (unsigned long)capacity);
    if (opt->hidden == STP_HIDDEN_PAINTER)
        out(w, "    sort, %lu,\n", (unsigned long)(sort_count ? sort_count : 1));
    else
        out(w, "    0, 0,\n");
    out(w, "    %s,\n    &cell,\n    %s,\n    %ld, /* background */\n    %s\n};\n",
        hidden_name(opt->hidden), p->has_gamma ? "gamma" : "0", (long)p->background,
        opt->dither == STP_TOOL_DITHER_DIFFUSE ? "&diffusion" : "0 /* no error diffusion */");
}

/* ---- static scenes: the display file entered on the host ---- */

/* The scene entered through the host core exactly as the firmware's
 * stp_scene_data_enter would (the same data, the same calls): *df receives
 * the display file (malloc'ed, *used entries).  Returns 0, or -1 with err. */
static int enter_on_host(const stp_scene *scene, const plan *p, const stp_tool_options *opt,
                         stp_instr **df, uint32_t *used, char *err, size_t errlen)
{
    uint32_t capacity = p->stats.display_entries > 0 ? (uint32_t)p->stats.display_entries : 1;
    stp_vec3 *vertices = malloc((p->vertex_count + 1) * sizeof *vertices);
    stp_scene_data_polygon *polygons = malloc((scene->polygon_count + 1) * sizeof *polygons);
    void *mem = malloc(stp_renderer_size());
    stp_scene_data s;
    stp_renderer *r;
    size_t i, n = 0;
    int k, status, result = -1;

    *df = calloc(capacity, sizeof **df);
    if (!vertices || !polygons || !mem || !*df) {
        snprintf(err, errlen, "out of memory");
        goto done;
    }
    for (i = 0; i < scene->polygon_count; i++) {
        const stp_scene_polygon *poly = &scene->polygons[i];
        for (k = 0; k < poly->count; k++)
            vertices[n++] = fix3(scene->vertices[poly->first + (size_t)k]);
        polygons[i].count = (uint16_t)poly->count;
        polygons[i].material = (uint16_t)(poly->material >= 0 &&
                                                  (size_t)poly->material < scene->material_count
                                              ? p->material_map[poly->material]
                                              : p->default_material);
    }
    memset(&s, 0, sizeof s);
    s.width = (uint32_t)opt->width;
    s.height = (uint32_t)opt->height;
    s.levels = opt->levels;
    s.shading = opt->shading ? 1 : 0;
    s.backface_removal = opt->backface_removal ? 1 : 0;
    s.view = p->view;
    s.lighting = p->lighting;
    s.materials = p->materials;
    s.material_count = p->material_count;
    s.vertices = vertices;
    s.vertex_count = (uint32_t)p->vertex_count;
    s.polygons = polygons;
    s.polygon_count = (uint32_t)scene->polygon_count;
    s.display_file = *df;
    s.display_capacity = capacity;
    status = stp_scene_data_enter(&s, mem, stp_renderer_size(), &r);
    if (status != STP_OK) {
        snprintf(err, errlen, "entering the scene: %s", stp_status_text(status));
        goto done;
    }
    *used = stp_renderer_display_file_used(r);
    result = 0;
done:
    free(vertices);
    free(polygons);
    free(mem);
    if (result != 0) {
        free(*df);
        *df = 0;
    }
    return result;
}

/* The static scene's C source: the display file as const data (rodata:
 * flash on a microcontroller), the cell, and stp_compiled_static. */
static void write_static_source(writer *w, const plan *p, const stp_tool_options *opt,
                                const stp_instr *df, uint32_t used, int asked_zbuffer)
{
    uint32_t i;
    int fill_style = opt->levels < 16 ? opt->levels : 16; /* stp_renderer_create's */
    uint32_t sort_count = (uint32_t)(p->stats.polygons_in - p->stats.polygons_skipped);
    out(w, "/* Generated by `stipple compile --static`: a %dx%d scene entered on the host;\n"
           " * display file %lu entries, played back with stp_playback_create.  Do not\n"
           " * edit. */\n",
        opt->width, opt->height, (unsigned long)used);
    if (asked_zbuffer && opt->hidden == STP_HIDDEN_NONE)
        out(w, "/* Hidden surfaces: the polygons are in a painter's order the host found to\n"
               " * give the Z buffer's picture pixel for pixel; no Z buffer is needed. */\n");
    else if (asked_zbuffer)
        out(w, "/* Hidden surfaces: no painter's order gives the Z buffer's picture (cyclic\n"
               " * overlap, or polygons sharing pixels both ways): the Z buffer stays. */\n");
    out(w, "#include \"stp_scene_data.h\"\n\n");
    out(w, "/* Device coordinates Q27.4; the shade field exists with STP_WITH_GOURAUD. */\n"
           "#if STP_WITH_GOURAUD\n#define I(op, x, y, z, shade) {op, x, y, z, shade}\n"
           "#else\n#define I(op, x, y, z, shade) {op, x, y, z}\n#endif\n\n");
    out(w, "static const stp_instr display_file[%lu] = {\n", (unsigned long)used);
    for (i = 0; i < used; i++) {
#if STP_WITH_GOURAUD
        long shade = (long)df[i].shade;
#else
        long shade = -1;
#endif
        out(w, "    I(%ld, %ld, %ld, %ld, %ld),\n", (long)df[i].op, (long)df[i].x, (long)df[i].y,
            (long)df[i].z, shade);
    }
    out(w, "};\n\n");
    write_cell_gamma(w, p, opt);
    if (opt->hidden == STP_HIDDEN_PAINTER)
        out(w, "static stp_sort_entry sort[%lu];\n\n", (unsigned long)(sort_count ? sort_count : 1));
    out(w, "const stp_scene_static stp_compiled_static = {\n");
    out(w, "    %d, %d, /* width, height */\n    %d, /* levels */\n    %d, /* fill style */\n",
        opt->width, opt->height, opt->levels, fill_style);
    out(w, "    display_file, %lu,\n", (unsigned long)used);
    if (opt->hidden == STP_HIDDEN_PAINTER)
        out(w, "    sort, %lu,\n", (unsigned long)(sort_count ? sort_count : 1));
    else
        out(w, "    0, 0,\n");
    out(w, "    %s,\n    &cell,\n    %s,\n    %ld /* background */\n};\n",
        hidden_name(opt->hidden), p->has_gamma ? "gamma" : "0", (long)p->background);
}

/* The spans source: each row's runs {last x, shade} and each shade's
 * pattern rows, as const data (program memory on an AVR: STP_SPANS_ROM),
 * and stp_compiled_spans. */
static void write_spans_source(writer *w, const stp_tool_options *opt, const stp_tool_spans *s,
                               int asked_zbuffer)
{
    size_t i;
    int k, cy;
    uint32_t y = 0;
    out(w, "/* SPDX-License-Identifier: MIT */\n");
    out(w, "/* Generated by `stipple compile --spans`: a %dx%d scene entered, shaded,\n"
           " * projected and hidden on the host; its picture as %lu runs of %d shades,\n"
           " * played back with stp_spans_draw.  Do not edit. */\n",
        opt->width, opt->height, (unsigned long)(s->run_bytes / 2u), s->shade_count);
    if (asked_zbuffer)
        out(w, "/* Hidden surfaces: the host's Z buffer; the chip needs none. */\n");
    out(w, "#include \"stipple/playback_spans.h\"\n\nextern const stp_spans stp_compiled_spans;\n\n");
    out(w, "/* shade k, cell row cy: patterns[k * %d + cy] */\n"
           "static const uint8_t patterns[%d] STP_SPANS_ROM = {\n",
        s->cell_rows, s->shade_count * s->cell_rows);
    for (k = 0; k < s->shade_count; k++) {
        out(w, "    ");
        for (cy = 0; cy < s->cell_rows; cy++)
            out(w, "0x%02x, ", s->patterns[k * s->cell_rows + cy]);
        out(w, "/* level %d */\n", s->levels[k]);
    }
    out(w, "};\n\n/* per row: {last x, shade} ... up to x = %d */\n"
           "static const uint8_t runs[%lu] STP_SPANS_ROM = {\n",
        opt->width - 1, (unsigned long)s->run_bytes);
    for (i = 0; i < s->run_bytes; i += 2) {
        int row_start = i == 0 || s->runs[i - 2] == (uint8_t)(opt->width - 1);
        int row_end = s->runs[i] == (uint8_t)(opt->width - 1);
        out(w, "%s%d, %d,", row_start ? "    " : " ", s->runs[i], s->runs[i + 1]);
        if (row_end)
            out(w, " /* row %lu */\n", (unsigned long)y++);
    }
    out(w, "};\n\n");
    out(w, "const stp_spans stp_compiled_spans = {%d, %d, %d, %d, patterns, runs, %luu};\n",
        opt->width, opt->height, s->cell_rows, s->shade_count, (unsigned long)s->run_bytes);
}

/* What `stipple compile` writes: the scene's data, its host-entered display
 * file (--static), or its host picture as spans (--spans). */
enum { COMPILE_DATA, COMPILE_STATIC, COMPILE_SPANS };

/* stp_tool_compile, _static and _spans: the C source of the form asked
 * (is_static: COMPILE_*), and the header. */
static int compile(const stp_scene *scene, const stp_tool_options *opt, int is_static,
                   FILE *c_out, FILE *h_out, char *err, size_t errlen)
{
    plan p;
    writer wc, wh;
    stp_tool_prepared prep;
    stp_instr *df = 0;
    uint32_t used = 0;
    int result = -1;

    if (!scene || !opt) {
        snprintf(err, errlen, "no scene");
        return -1;
    }
    if (stp_tool_prepare(scene, opt, &prep, err, errlen) != 0)
        return -1;
    scene = &prep.scene;
    opt = &prep.opt;
    if (make_plan(&prep, &p, err, errlen) != 0)
        goto done;
    wc.f = c_out;
    wc.failed = 0;
    wh.f = h_out;
    wh.failed = 0;
    if (is_static == COMPILE_SPANS && opt->dither == STP_TOOL_DITHER_DIFFUSE) {
        snprintf(err, errlen, "--spans does not take error diffusion (-d): the firmware "
                              "plays spans through a halftone cell");
        goto done;
    }
    if (is_static != COMPILE_DATA) {
        stp_tool_options painter = *opt;
        stp_instr *ordered = 0;
        uint32_t ordered_used = 0;
        int exact = 0;
        if (enter_on_host(scene, &p, opt, &df, &used, err, errlen) != 0)
            goto done;
        /* a Z buffer only where no painter's order gives its picture */
        if (opt->hidden == STP_HIDDEN_ZBUFFER) {
            exact = stp_tool_static_order(df, used, (uint32_t)opt->width, (uint32_t)opt->height,
                                          &ordered, &ordered_used);
            if (exact < 0) {
                snprintf(err, errlen, "out of memory");
                goto done;
            }
        }
        if (exact) {
            free(df);
            df = ordered;
            used = ordered_used;
            painter.hidden = STP_HIDDEN_NONE;
        }
        if (is_static == COMPILE_SPANS) {
            stp_tool_spans spans;
            stp_output output;
            memset(&output, 0, sizeof output); /* fields the default leaves */
            stp_output_default(&output);
            output.hidden = painter.hidden;
            output.cell = &p.cell;
            output.gamma = p.has_gamma ? p.gamma : 0;
            output.background = p.background;
            if (stp_tool_static_spans(df, used, (uint32_t)opt->width, (uint32_t)opt->height,
                                      opt->levels, opt->levels < 16 ? opt->levels : 16, &output,
                                      &spans, err, errlen) != 0)
                goto done;
            write_spans_source(&wc, opt, &spans, opt->hidden == STP_HIDDEN_ZBUFFER);
            free(spans.runs);
        } else {
            write_static_source(&wc, &p, &painter, df, used, opt->hidden == STP_HIDDEN_ZBUFFER);
        }
        write_config(&wh, &p, &painter, 1); /* spans too: the probe builds on it */
    } else {
        write_source(&wc, scene, &p, opt);
        write_config(&wh, &p, opt, 0);
    }
    if (wc.failed || wh.failed || (c_out && fflush(c_out) != 0) || (h_out && fflush(h_out) != 0)) {
        snprintf(err, errlen, "write error: %s", strerror(errno));
        goto done;
    }
    result = 0;
done:
    free(df);
    free(p.materials);
    free(p.material_map);
    stp_tool_prepared_free(&prep);
    return result;
}

int stp_tool_compile(const stp_scene *scene, const stp_tool_options *opt, FILE *c_out,
                     FILE *h_out, char *err, size_t errlen)
{
    return compile(scene, opt, COMPILE_DATA, c_out, h_out, err, errlen);
}

int stp_tool_compile_static(const stp_scene *scene, const stp_tool_options *opt, FILE *c_out,
                            FILE *h_out, char *err, size_t errlen)
{
    return compile(scene, opt, COMPILE_STATIC, c_out, h_out, err, errlen);
}

int stp_tool_compile_spans(const stp_scene *scene, const stp_tool_options *opt, FILE *c_out,
                           FILE *h_out, char *err, size_t errlen)
{
    return compile(scene, opt, COMPILE_SPANS, c_out, h_out, err, errlen);
}

/* ---- the subcommand ---- */

void stp_tool_compile_usage(FILE *to)
{
    fprintf(to,
            "usage: stipple compile SCENE -o OUT.c [options]\n"
            "\n"
            "Compiles SCENE (.nff, .obj, .off, .ply; '-' for standard input) for a firmware\n"
            "build: OUT.c holds the scene as fixed-point data for\n"
            "ports/compiled/stp_scene_data.h, and a header (OUT_config.h unless --header\n"
            "says otherwise) sets the core's STP_* switches to what the scene needs.  The\n"
            "firmware's picture equals 'stipple render SCENE' with the same options,\n"
            "rendered to 1-bit (MONO1).\n"
            "\n"
            "  -o, --output FILE        the C source to write (required)\n"
            "      --static             enter, shade, clip and project on the host: OUT.c\n"
            "                           holds the display file as const data, for\n"
            "                           stp_playback_create (stp_compiled_static)\n"
            "      --spans              as --static, then hide surfaces on the host too: OUT.c\n"
            "                           holds the picture's rows as runs of one shade, for\n"
            "                           stp_spans_draw (stp_compiled_spans; no Z buffer)\n"
            "      --mesh               OUT is a C header: the polygons as one indexed\n"
            "                           triangle mesh (shared vertices, prepared normals;\n"
            "                           centred, radius 1) for direct drawing, in program\n"
            "                           memory on an AVR (NAME_mesh; no configuration header)\n"
            "      --name NAME          the mesh's C name (--mesh; default: model)\n"
            "      --header FILE        the configuration header (default: OUT without .c,\n"
            "                           plus _config.h)\n"
            "      --scene-format KIND  nff, obj, off or ply (needed for '-')\n"
            "  -h, --help               this help\n");
    stp_tool_options_help(to);
}

static int fail(const char *fmt, ...)
{
    va_list ap;
    fprintf(stderr, "stipple: compile: ");
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    return 1;
}

static FILE *open_tmp(const char *path, char *tmp, size_t tmplen)
{
    if ((size_t)snprintf(tmp, tmplen, "%s.tmp", path) >= tmplen)
        return 0;
    return fopen(tmp, "w");
}

/* --mesh: the scene at path as a mesh header at out_path (written whole
 * or not at all).  conflict: --static, --spans or --header given too. */
static int compile_mesh_main(const char *path, const char *format, const stp_scene_options *sopt,
                             const char *out_path, const char *name, int conflict)
{
    stp_scene scene;
    char tmp[4200], err[512];
    FILE *f;
    int status = 1;
    if (conflict)
        return stp_tool_usage_error("compile", "--mesh writes one header: no --static, --spans "
                                               "or --header with it");
    if (!strcmp(path, "-") && !format)
        return stp_tool_usage_error("compile", "a scene from standard input ('-') needs "
                                               "--scene-format nff|obj|off|ply");
    if (stp_scene_load_as(path, format, sopt, &scene, err, sizeof err) != 0)
        return fail("%s", err);
    if (!(f = open_tmp(out_path, tmp, sizeof tmp))) {
        fail("%s: %s", out_path, strerror(errno));
    } else if (stp_tool_compile_mesh(&scene, name, path, f, err, sizeof err) != 0) {
        fail("%s: %s", path, err);
        fclose(f);
    } else if (fclose(f) != 0 || rename(tmp, out_path) != 0) {
        fail("%s: %s", out_path, strerror(errno));
    } else {
        status = 0;
    }
    if (status != 0)
        remove(tmp);
    stp_scene_free(&scene);
    return status;
}

enum { OPT_HEADER = STP_TOOL_OPT_COMMAND, OPT_SCENE_FORMAT, OPT_STATIC, OPT_SPANS, OPT_MESH, OPT_NAME };

int stp_tool_compile_main(int argc, char **argv)
{
    static const struct option own[] = {{"output", required_argument, 0, 'o'},
                                        {"header", required_argument, 0, OPT_HEADER},
                                        {"scene-format", required_argument, 0, OPT_SCENE_FORMAT},
                                        {"static", no_argument, 0, OPT_STATIC},
                                        {"spans", no_argument, 0, OPT_SPANS},
                                        {"mesh", no_argument, 0, OPT_MESH},
                                        {"name", required_argument, 0, OPT_NAME},
                                        {"help", no_argument, 0, 'h'},
                                        {0, 0, 0, 0}};
    struct option longs[64];
    stp_tool_options opt;
    stp_scene_options sopt;
    stp_scene scene;
    stp_tool_given given;
    const char *c_path = 0, *h_path = 0, *scene_format = 0, *mesh_name = "model";
    char h_default[4096], c_tmp[4200], h_tmp[4200], err[512];
    FILE *cf = 0, *hf = 0;
    int c, status = 1, is_static = COMPILE_DATA, mesh = 0;

    stp_tool_options_default(&opt);
    stp_scene_options_default(&sopt);
    memset(&given, 0, sizeof given);
    opterr = 0;
    optind = 1;
    if (stp_tool_long_options(longs, sizeof longs / sizeof longs[0], own) != 0)
        return fail("internal: option table too small");
    while ((c = getopt_long(argc, argv, ":" STP_TOOL_SHORT_OPTIONS "o:h", longs, 0)) != -1) {
        int applied = stp_tool_apply_option(c, optarg, &opt, &sopt, err, sizeof err);
        if (c > 0 && c < STP_TOOL_OPT_COMMAND)
            given.code[c] = 1;
        if (applied < 0)
            return stp_tool_usage_error("compile", "%s", err);
        if (applied)
            continue;
        switch (c) {
        case 'o': c_path = optarg; break;
        case OPT_HEADER: h_path = optarg; break;
        case OPT_SCENE_FORMAT:
            if (!(scene_format = stp_tool_parse_scene_format(optarg)))
                return stp_tool_usage_error("compile", "bad --scene-format '%s' (nff, obj, off, "
                                                       "ply)", optarg);
            break;
        case OPT_STATIC: /* --spans is static too, and wins */
            if (is_static == COMPILE_DATA)
                is_static = COMPILE_STATIC;
            break;
        case OPT_SPANS: is_static = COMPILE_SPANS; break;
        case OPT_MESH: mesh = 1; break;
        case OPT_NAME: mesh_name = optarg; break;
        case 'h': stp_tool_compile_usage(stdout); return 0;
        default: return stp_tool_getopt_error("compile", c, argv);
        }
    }
    if (optind >= argc)
        return stp_tool_usage_error("compile", "no scene given");
    if (optind < argc - 1)
        return stp_tool_usage_error("compile", "one scene only ('%s' is extra)",
                                    argv[optind + 1]);
    /* the compiled-scene firmware path enters flat, grey, opaque polygons */
    if (opt.raytrace)
        return stp_tool_usage_error("compile", "--raytrace is not supported for compiled "
                                               "scenes (they carry a display file)");
    if (stp_tool_check_renderer(&given, 0, err, sizeof err) != 0)
        return stp_tool_usage_error("compile", "%s", err);
    if (opt.smooth || opt.colour || opt.transparency || opt.shadow_resolution)
        return stp_tool_usage_error("compile", "--smooth, --color, --transparent and --shadows "
                                               "are not supported for compiled scenes yet");
    if (opt.edge_aa)
        return stp_tool_usage_error("compile", "--edge-aa is not supported for compiled scenes "
                                               "(their core is built with STP_WITH_EDGE_AA 0)");
    if (!c_path)
        return stp_tool_usage_error("compile", "no output given (-o FILE.c)");
    if (mesh)
        return compile_mesh_main(argv[optind], scene_format, &sopt, c_path, mesh_name,
                                 is_static != COMPILE_DATA || h_path);
    if (!h_path) {
        size_t n = strlen(c_path);
        if (n >= 2 && !strcmp(c_path + n - 2, ".c"))
            n -= 2;
        if (n + sizeof "_config.h" > sizeof h_default)
            return fail("%s: name too long", c_path);
        memcpy(h_default, c_path, n);
        memcpy(h_default + n, "_config.h", sizeof "_config.h");
        h_path = h_default;
    }
    if (!strcmp(argv[optind], "-") && !scene_format)
        return stp_tool_usage_error("compile", "a scene from standard input ('-') needs "
                                               "--scene-format nff|obj|off|ply");
    if (stp_scene_load_as(argv[optind], scene_format, &sopt, &scene, err, sizeof err) != 0)
        return fail("%s", err);
    cf = open_tmp(c_path, c_tmp, sizeof c_tmp);
    hf = open_tmp(h_path, h_tmp, sizeof h_tmp);
    if (!cf || !hf) {
        fail("%s: %s", !cf ? c_path : h_path, strerror(errno));
        goto done;
    }
    if ((is_static == COMPILE_SPANS    ? stp_tool_compile_spans
         : is_static == COMPILE_STATIC ? stp_tool_compile_static
                                       : stp_tool_compile)(&scene, &opt, cf, hf, err, sizeof err) != 0) {
        fail("%s: %s", argv[optind], err);
        goto done;
    }
    {
        int c_bad = fclose(cf) != 0, h_bad = fclose(hf) != 0;
        cf = hf = 0;
        if (c_bad || h_bad) {
            fail("write error: %s", strerror(errno));
            goto done;
        }
    }
    if (rename(c_tmp, c_path) != 0 || rename(h_tmp, h_path) != 0) {
        fail("rename: %s", strerror(errno));
        goto done;
    }
    status = 0;
done:
    if (cf)
        fclose(cf);
    if (hf)
        fclose(hf);
    if (status != 0) {
        remove(c_tmp);
        remove(h_tmp);
    }
    stp_scene_free(&scene);
    return status;
}
