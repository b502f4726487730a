/* SPDX-License-Identifier: MIT */
/*
 * stipple benchmark: error against run time for one numeric configuration.
 *
 * The core's numeric switches (STP_FIX_FRAC_BITS, STP_SQRT_FAST) are
 * compile-time, so tools/bench/CMakeLists.txt builds this file once per
 * configuration against a core built with it (bench_<cfg>), and
 * run_bench.sh runs them all.  One run prints a human table and, with
 * --csv FILE, appends one CSV row (the header first when FILE is empty).
 *
 * Errors are against the double-precision reference (tests/reference/
 * shade_ref.c for the shading equation, tools/bench/render_ref.c for whole
 * pictures), which takes the exact double inputs:
 *   - shade error, max and mean absolute: on random geometry (fixed seed),
 *     on the stiff suite (tests/stiff/stiff_cases.c) and on every polygon of
 *     the shared scenes and the torus (flat shading, as stp_tool_render);
 *   - the share of those polygons whose INTENSITY style differs;
 *   - image error of whole MONO1 renders (stp_tool_render vs the reference
 *     renderer) at 128x64 and 400x240: differing pixels, and the mean
 *     absolute difference after a 3x3 box blur of the two 1-bit pictures.
 * Run time (CLOCK_MONOTONIC; each figure the best of several batches, so a
 * busy machine inflates it least):
 *   - ns per stp_shade_point on random inputs;
 *   - us per frame of the torus workload of issue 11 (torus.h: major radius
 *     1, minor 0.4, 25 x 20 segments = 1000 triangles wound counter-clockwise
 *     from outside, eye at distance 6 looking at the centre, 16 levels,
 *     Bayer 4x4, full shading, one light, Z buffer, back faces removed):
 *     entering the 1000 triangles into a fresh segment plus stp_renderer_render to
 *     MONO1, at 128x64, 400x240 and 640x480;
 *   - HALFTONE-FILLIN fill rate (stp_halftone_fillin over whole rows of a
 *     640x480 1-bit buffer) beside memset of the same rows, and their ratio.
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "render_ref.h"
#include "rt_compare.h"
#include "render_scene.h"
#include "scene_prepare.h"
#include "scene.h"
#include "scene_util.h"
#include "stiff_cases.h"
#include "torus.h"
#include "stipple/stipple.h"
#if STP_BENCH_MESH
#include "shade_fast_private.h"
#endif

#ifndef STP_BENCH_CONFIG
#define STP_BENCH_CONFIG "default"
#endif
#ifndef STP_BENCH_SCENES_DIR
#define STP_BENCH_SCENES_DIR "../shared/scenes"
#endif

static const char *const scene_names[] = {"tetra-s1", "tetra-s2", "mount-s2", "teapot-s1",
                                          "teapot-s2", "gears-s1", "balls-s1", "balls-s2"};
#define SCENE_COUNT (sizeof scene_names / sizeof scene_names[0])

static int quick, verbose;

/* ---- time ---- */

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

/* ---- random numbers: xorshift64*, fixed seed ---- */

static uint64_t rng_state = 0x5eed5eed5eedull;

static uint64_t rng_next(void)
{
    rng_state ^= rng_state >> 12;
    rng_state ^= rng_state << 25;
    rng_state ^= rng_state >> 27;
    return rng_state * 0x2545F4914F6CDD1Dull;
}

static double rng_uniform(double lo, double hi)
{
    return lo + (hi - lo) * (double)(rng_next() >> 11) / 9007199254740992.0;
}

static ref_vec3 rng_direction(void)
{
    for (;;) {
        ref_vec3 v = ref_v3(rng_uniform(-1, 1), rng_uniform(-1, 1), rng_uniform(-1, 1)), u;
        double len = ref_unit(v, &u);
        if (len > 0.1 && len <= 1)
            return u;
    }
}

static stp_vec3 fix3(ref_vec3 v)
{
    stp_vec3 r;
    r.x = stp_tool_fix(v.x);
    r.y = stp_tool_fix(v.y);
    r.z = stp_tool_fix(v.z);
    return r;
}

static double from_fix(stp_fix v)
{
    return (double)v / (double)STP_FIX_ONE;
}

/* ---- error statistics ---- */

typedef struct stat {
    double max, sum;
    long n;
} stat;

static void stat_add(stat *s, double e)
{
    if (e > s->max)
        s->max = e;
    s->sum += e;
    s->n++;
}

static double stat_mean(const stat *s)
{
    return s->n ? s->sum / (double)s->n : 0;
}

/* ---- random shading inputs (a scene's kind: point in front of the eye,
 * normal facing it, lights a few units off with power (1-B)(C+U)) ---- */

typedef struct shade_input {
    ref_lighting lighting;
    ref_material material;
    ref_vec3 normal, point, eye, pdir;
    int parallel;
    /* the same rounded for the core */
    stp_lighting fl;
    stp_material fm;
    stp_vec3 fn, fp, fe, fd;
#if STP_BENCH_MESH
    stp_shade_fast fast; /* prepared once per input (the mesh path caches it) */
    int16_t qn[3];       /* the normal in Q1.14, as a prepared mesh normal */
#endif
} shade_input;

#if STP_BENCH_MESH
/* A unit normal as the mesh path's Q1.14 prepared normal (rounded). */
static void q14_normal(ref_vec3 n, int16_t out[3])
{
    double len = sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
    out[0] = (int16_t)lround(n.x / len * STP_MESH_NORMAL_ONE);
    out[1] = (int16_t)lround(n.y / len * STP_MESH_NORMAL_ONE);
    out[2] = (int16_t)lround(n.z / len * STP_MESH_NORMAL_ONE);
}

static void fast_prepare_input(shade_input *in)
{
    q14_normal(in->normal, in->qn);
    stp_shade_fast_prepare(&in->fast, &in->fl, &in->fm, in->fe, in->parallel, in->fd);
}
#endif

static void random_input(shade_input *in)
{
    int j;
    ref_vec3 e;
    memset(in, 0, sizeof *in);
    in->lighting.brightness = rng_uniform(0.5, 2);
    in->lighting.background = rng_uniform(0, 0.5);
    in->lighting.c = rng_uniform(0.5, 2);
    in->lighting.count = 1 + (int)(rng_next() % 2);
    in->material.reflectivity = rng_uniform(0, 1);
    in->material.refraction = rng_uniform(1.05, 20);
    in->material.gloss = exp(rng_uniform(log(0.02), log(20)));
    in->material.specular = rng_uniform(0, 1);
    in->point = ref_v3(rng_uniform(-5, 5), rng_uniform(-5, 5), rng_uniform(1, 20));
    in->parallel = (rng_next() % 8) == 0;
    in->pdir = ref_v3(0, 0, -1);
    if (in->parallel)
        e = in->pdir;
    else
        (void)ref_unit(ref_v3(-in->point.x, -in->point.y, -in->point.z), &e);
    in->normal = rng_direction();
    if (ref_dot(in->normal, e) < 0)
        in->normal = ref_v3(-in->normal.x, -in->normal.y, -in->normal.z);
    for (j = 0; j < in->lighting.count; j++) {
        ref_vec3 d = rng_direction();
        double u = rng_uniform(0.5, 30);
        in->lighting.lights[j].position =
            ref_v3(in->point.x + d.x * u, in->point.y + d.y * u, in->point.z + d.z * u);
        in->lighting.lights[j].power =
            (1 - in->lighting.background) * (in->lighting.c + u) / sqrt((double)in->lighting.count);
    }
    stp_lighting_default(&in->fl);
    in->fl.brightness = stp_tool_fix(in->lighting.brightness);
    in->fl.background = stp_tool_fix(in->lighting.background);
    in->fl.attenuation_c = stp_tool_fix(in->lighting.c);
    in->fl.count = in->lighting.count;
    for (j = 0; j < in->lighting.count; j++) {
        in->fl.lights[j].position = fix3(in->lighting.lights[j].position);
        in->fl.lights[j].power = stp_tool_fix(in->lighting.lights[j].power);
    }
    in->fm.reflectivity = stp_tool_fix(in->material.reflectivity);
    in->fm.refraction = stp_tool_fix(in->material.refraction);
    in->fm.gloss = stp_tool_fix(in->material.gloss);
    in->fm.specular = stp_tool_fix(in->material.specular);
    in->fn = fix3(in->normal);
    in->fp = fix3(in->point);
    in->fe = fix3(in->eye);
    in->fd = fix3(in->pdir);
#if STP_BENCH_MESH
    fast_prepare_input(in);
#endif
}

/* Smallest of N.E and |N.L_j|: near 0 the shade jumps (a light or the eye
 * crossing the surface's plane), so rounding there is ill-conditioned. */
static double min_cosine(const shade_input *in)
{
    ref_vec3 e, l;
    double m;
    int j;
    if (in->parallel)
        e = in->pdir;
    else
        (void)ref_unit(ref_v3(in->eye.x - in->point.x, in->eye.y - in->point.y, in->eye.z - in->point.z), &e);
    m = ref_dot(in->normal, e);
    for (j = 0; j < in->lighting.count; j++) {
        ref_vec3 p = in->lighting.lights[j].position;
        double nl;
        (void)ref_unit(ref_v3(p.x - in->point.x, p.y - in->point.y, p.z - in->point.z), &l);
        nl = fabs(ref_dot(in->normal, l));
        if (nl < m)
            m = nl;
    }
    return m;
}

static stp_fix core_shade(const shade_input *in)
{
#if STP_BENCH_MESH
    return stp_shade_fast_face(&in->fast, in->qn, in->fp);
#else
    return stp_shade_point(&in->fl, &in->fm, in->fn, in->fp, in->fe, in->parallel, in->fd);
#endif
}

#if STP_BENCH_MESH
/* A stiff shading case through the fast flat-face shading: the mesh
 * configuration measures what stp_renderer_mesh computes (its polygon
 * cases are the polygon path's, so they are left out of this row). */
static int fast_stiff_run(const stiff_case *c, stiff_outcome *o)
{
    shade_input in;
    int j;
    memset(o, 0, sizeof *o);
    if (c->kind != STIFF_SHADE)
        return 0;
    memset(&in, 0, sizeof in);
    stp_lighting_default(&in.fl);
    in.fl.brightness = stiff_to_fix(c->lighting.brightness);
    in.fl.background = stiff_to_fix(c->lighting.background);
    in.fl.attenuation_c = stiff_to_fix(c->lighting.c);
    in.fl.count = c->lighting.count;
    for (j = 0; j < c->lighting.count && j < STP_MAX_LIGHTS; j++) {
        in.fl.lights[j].position = fix3(c->lighting.lights[j].position);
        in.fl.lights[j].power = stiff_to_fix(c->lighting.lights[j].power);
    }
    stp_material_default(&in.fm);
    in.fm.reflectivity = stiff_to_fix(c->material.reflectivity);
    in.fm.refraction = stiff_to_fix(c->material.refraction);
    in.fm.gloss = stiff_to_fix(c->material.gloss);
    in.fm.specular = stiff_to_fix(c->material.specular);
    in.normal = c->normal;
    in.parallel = c->parallel;
    in.fp = fix3(c->point);
    in.fe = fix3(c->eye);
    in.fd = fix3(c->pdir);
    fast_prepare_input(&in);
    o->core = from_fix(core_shade(&in));
    o->ref = ref_shade_point(&c->lighting, &c->material, c->normal, c->point, c->eye, c->parallel,
                             c->pdir);
    o->answer = c->expect >= 0 ? c->expect : o->ref;
    o->has_err = o->core >= 0 && o->answer >= 0 && o->answer == o->answer;
    o->err = o->has_err ? fabs(o->core - o->answer) : 0;
    return 1;
}
#endif

/* ---- the core side of stp_tool_render, step by step ----
 *
 * stp_tool_render does not hand out per-polygon shades, so this mirrors its
 * set-up (view, lights, material mapping; flat shading only) and enters the
 * polygons itself, reading stp_renderer_last_shade after each.  check_mirror()
 * renders the result and compares it with stp_tool_render's picture, so a
 * change there that this mirror misses is reported, not silently measured. */

typedef struct core_scene {
    stp_renderer *r;
    void *rmem;
    stp_instr *df;
    uint32_t capacity;
    stp_vec3 *verts;        /* all polygon vertices, rounded */
    stp_material *materials; /* per scene material, [count] = the default */
    int levels;
    int opened;
    stp_lighting lighting; /* world positions, as given to the renderer */
    stp_vec3 eye;          /* the view's centre of projection, world units */
} core_scene;

static stp_vec3 sfix3(stp_scene_vec3 v)
{
    stp_vec3 r;
    r.x = stp_tool_fix(v.x);
    r.y = stp_tool_fix(v.y);
    r.z = stp_tool_fix(v.z);
    return r;
}

static void core_scene_free(core_scene *cs)
{
    free(cs->rmem);
    free(cs->df);
    free(cs->verts);
    free(cs->materials);
    memset(cs, 0, sizeof *cs);
}

/* As render_scene.c's stp_tool_render set-up.  Returns 0 or -1. */
static int core_scene_prepare(core_scene *cs, const stp_scene *scene, const stp_tool_options *opt,
                              char *err, size_t err_size)
{
    stp_view view;
    stp_lighting lighting;
    int status;
    size_t i, capacity = 16;

    memset(cs, 0, sizeof *cs);
    /* the view and lights stp_tool_render uses: of the prepared scene
     * (merged lights; the bench's scenes need no rescaling or splitting,
     * so their geometry is the file's) */
    {
        stp_tool_prepared prep;
        int rc;
        if (stp_tool_prepare(scene, opt, &prep, err, err_size) != 0)
            return -1;
        rc = stp_tool_setup_prepared(&prep, &view, &lighting, err, err_size);
        stp_tool_prepared_free(&prep);
        if (rc != 0)
            return -1;
    }
    for (i = 0; i < scene->polygon_count; i++)
        capacity += (size_t)scene->polygons[i].count + 6;
    cs->capacity = (uint32_t)capacity;
    cs->rmem = malloc(stp_renderer_size());
    cs->df = malloc(sizeof *cs->df * capacity);
    cs->verts = malloc(sizeof *cs->verts * (scene->vertex_count + 1));
    cs->materials = malloc(sizeof *cs->materials * (scene->material_count + 1));
    if (!cs->rmem || !cs->df || !cs->verts || !cs->materials) {
        snprintf(err, err_size, "out of memory");
        core_scene_free(cs);
        return -1;
    }
    for (i = 0; i < scene->vertex_count; i++)
        cs->verts[i] = sfix3(scene->vertices[i]);
    for (i = 0; i <= scene->material_count; i++) {
        stp_material *m = &cs->materials[i];
        stp_material_default(m);
        if (i < scene->material_count)
            stp_tool_material(&scene->materials[i], opt->colour, m);
    }
    cs->levels = opt->levels;
    cs->lighting = lighting;
    cs->eye = view.from;
    cs->r = stp_renderer_create(cs->rmem, stp_renderer_size(), cs->df, cs->capacity,
                                (uint32_t)opt->width, (uint32_t)opt->height);
    if (!cs->r || (status = stp_renderer_set_view(cs->r, &view)) != STP_OK ||
        (status = stp_renderer_set_levels(cs->r, opt->levels)) != STP_OK ||
        (status = stp_renderer_set_lighting(cs->r, &lighting)) != STP_OK ||
        (status = stp_renderer_set_shading(cs->r, opt->shading)) != STP_OK ||
        (status = stp_renderer_set_backface_removal(cs->r, opt->backface_removal)) != STP_OK) {
        snprintf(err, err_size, "view or lighting refused by the core");
        core_scene_free(cs);
        return -1;
    }
    return 0;
}

/* Enter every polygon into a fresh segment; shade[i] (if not NULL) gets the
 * core's shade of polygon i, -1 where it gave none. */
static int core_scene_enter(core_scene *cs, const stp_scene *scene, double *shade)
{
    size_t i;
    int last_material = -2;
    if (cs->opened)
        (void)stp_segment_delete(cs->r, 1);
    if (stp_segment_create(cs->r, 1) != STP_OK)
        return -1;
    cs->opened = 1;
    for (i = 0; i < scene->polygon_count; i++) {
        const stp_scene_polygon *p = &scene->polygons[i];
        int status;
        if (p->material != last_material) {
            size_t mi = p->material >= 0 && (size_t)p->material < scene->material_count
                            ? (size_t)p->material
                            : scene->material_count;
            if (stp_renderer_set_object_shade(cs->r, &cs->materials[mi]) != STP_OK ||
                stp_renderer_set_fill_style(cs->r, stp_intensity_index(cs->materials[mi].reflectivity, cs->levels)) != STP_OK)
                return -1;
            last_material = p->material;
        }
        if (p->count > STP_MAX_POLYGON_VERTICES)
            return -1;
        status = stp_renderer_polygon(cs->r, cs->verts + p->first, p->count);
        if (shade)
            shade[i] = status == STP_OK && stp_renderer_last_shade(cs->r) >= 0 ? from_fix(stp_renderer_last_shade(cs->r)) : -1;
        if (status != STP_OK && status != STP_ERR_DEGENERATE)
            return -1;
    }
    (void)stp_segment_close(cs->r);
    return 0;
}

/* ---- frames ---- */

typedef struct frame {
    stp_port port;
    uint8_t *px; /* MONO1 packed rows */
    size_t stride;
} frame;

static int frame_flush(stp_port *port, uint32_t y0, uint32_t rows, const uint8_t *pixels, size_t stride)
{
    frame *f = (frame *)port->user;
    uint32_t r;
    for (r = 0; r < rows; r++)
        memcpy(f->px + (size_t)(y0 + r) * f->stride, pixels + (size_t)r * stride, f->stride);
    return 0;
}

static int frame_init(frame *f, int w, int h)
{
    memset(f, 0, sizeof *f);
    f->stride = stp_row_bytes(STP_PIXEL_MONO1, (uint32_t)w);
    f->px = calloc(f->stride, (size_t)h);
    f->port.width = (uint32_t)w;
    f->port.height = (uint32_t)h;
    f->port.format = STP_PIXEL_MONO1;
    f->port.flush = frame_flush;
    f->port.user = f;
    return f->px ? 0 : -1;
}

static int mono_at(const frame *f, int x, int y)
{
    return (f->px[(size_t)y * f->stride + (size_t)x / 8] >> (7 - x % 8)) & 1;
}

/* Render the display file of cs (after core_scene_enter) onto port. */
static int core_scene_render(core_scene *cs, const stp_scene *scene, const stp_tool_options *opt,
                             stp_port *port, uint8_t *band, uint16_t *zbuf)
{
    stp_output out;
    stp_frame_memory mem;
    stp_cell cell;
    memset(&out, 0, sizeof out);
    out.hidden = STP_HIDDEN_ZBUFFER;
    if (scene->has_background) {
        /* as stp_tool_render: the luminance of the scene's background */
        const double *b = scene->background;
        double lum = 0.30 * b[0] + 0.59 * b[1] + 0.11 * b[2];
        out.background = stp_tool_fix(lum < 0 ? 0 : (lum > 1 ? 1 : lum));
    }
    if (stp_tool_cell(opt, &cell) != 0)
        return -1;
    out.cell = &cell;
    memset(&mem, 0, sizeof mem);
    mem.band = band;
    mem.band_rows = (uint32_t)opt->height;
    mem.band_size = stp_row_bytes(STP_PIXEL_MONO1, (uint32_t)opt->width) * (size_t)opt->height;
    mem.zbuf = zbuf;
    mem.zbuf_count = (size_t)opt->width * (size_t)opt->height;
    return stp_renderer_render(cs->r, port, &out, &mem) == STP_OK ? 0 : -1;
}

/* ---- the torus workload ---- */

/* The torus of issue 11 (torus.c): wound counter-clockwise from outside. */
static int build_torus(stp_scene *s)
{
    return torus_scene_build(s);
}

/* ---- image comparison ---- */

/* 3x3 box blur of a 0/1 picture (mean over the in-frame neighbours). */
static void blur3(const unsigned char *in, double *out, int w, int h)
{
    int x, y, dx, dy;
    for (y = 0; y < h; y++) {
        for (x = 0; x < w; x++) {
            double s = 0;
            int n = 0;
            for (dy = -1; dy <= 1; dy++) {
                for (dx = -1; dx <= 1; dx++) {
                    int xx = x + dx, yy = y + dy;
                    if (xx < 0 || yy < 0 || xx >= w || yy >= h)
                        continue;
                    s += in[(size_t)yy * (size_t)w + (size_t)xx];
                    n++;
                }
            }
            out[(size_t)y * (size_t)w + (size_t)x] = s / n;
        }
    }
}

typedef struct image_error {
    long diff, pixels;
    double blur_sum; /* sum over pixels of |blur(core) - blur(ref)| */
    int renders, failures;
} image_error;

static void write_pbm(const char *path, const unsigned char *bits, int w, int h)
{
    FILE *f = fopen(path, "w");
    int x, y;
    if (!f)
        return;
    fprintf(f, "P1\n%d %d\n", w, h);
    for (y = 0; y < h; y++) {
        for (x = 0; x < w; x++)
            fputc(bits[(size_t)y * (size_t)w + (size_t)x] ? '0' : '1', f);
        fputc('\n', f);
    }
    fclose(f);
}

static const char *dump_dir;

/* The reference gets the lights the core gets: stp_tool_prepare merges
 * lights beyond STP_MAX_LIGHTS (gears-s1 has five), each merged light with
 * the power of the lights it stands for. */
static void ref_lights_as_core(const stp_scene *scene, const stp_tool_options *opt,
                               ref_render_options *ropt)
{
    stp_tool_prepared prep;
    char err[256];
    size_t j;
    if (stp_tool_prepare(scene, opt, &prep, err, sizeof err) != 0)
        return; /* the core's side reports it */
    if (prep.lights_in > STP_MAX_LIGHTS && prep.scene.light_count <= STP_MAX_LIGHTS) {
        ropt->light_count = (int)prep.scene.light_count;
        for (j = 0; j < prep.scene.light_count; j++) {
            ropt->lights[j] = ref_v3(prep.scene.lights[j].position.x, prep.scene.lights[j].position.y,
                                     prep.scene.lights[j].position.z);
            ropt->light_weight[j] = prep.light_weight[j];
        }
    }
    stp_tool_prepared_free(&prep);
}

/* Compare stp_tool_render with the reference renderer on one scene and
 * size; also checks the bench's mirror of stp_tool_render against it.
 * Returns the differing pixels of this render, or -1 on failure. */
static long compare_images(const char *name, const stp_scene *scene, int w, int h, image_error *ie,
                           int *mirror_ok)
{
    stp_tool_options opt;
    ref_render_options ropt;
    ref_render_result res;
    frame f, g;
    char err[256];
    unsigned char *core_bits;
    double *bc, *br;
    size_t npx = (size_t)w * (size_t)h, i;
    long diff = 0;
    int x, y;
    core_scene cs;
    uint8_t *band;
    uint16_t *zbuf;

    stp_tool_options_default(&opt);
    opt.width = w;
    opt.height = h;
    ref_render_options_default(&ropt);
    ropt.width = w;
    ropt.height = h;
    ropt.max_lights = STP_MAX_LIGHTS;
    ropt.max_vertices = STP_MAX_POLYGON_VERTICES;
    ref_lights_as_core(scene, &opt, &ropt);
    if (frame_init(&f, w, h) != 0 || frame_init(&g, w, h) != 0)
        return -1;
    ie->renders++;
    if (stp_tool_render(scene, &opt, &f.port, 0, err, sizeof err) != 0) {
        fprintf(stderr, "bench: %s %dx%d: the core failed: %s\n", name, w, h, err);
        ie->failures++;
        free(f.px);
        free(g.px);
        return -1;
    }
    if (ref_render_scene(scene, &ropt, &res, err, sizeof err) != 0) {
        fprintf(stderr, "bench: %s %dx%d: the reference failed: %s\n", name, w, h, err);
        ie->failures++;
        free(f.px);
        free(g.px);
        return -1;
    }
    /* the mirror must draw what stp_tool_render draws */
    band = malloc(f.stride * (size_t)h);
    zbuf = malloc(sizeof *zbuf * npx);
    if (band && zbuf && core_scene_prepare(&cs, scene, &opt, err, sizeof err) == 0) {
        if (core_scene_enter(&cs, scene, 0) != 0 || core_scene_render(&cs, scene, &opt, &g.port, band, zbuf) != 0 ||
            memcmp(f.px, g.px, f.stride * (size_t)h) != 0) {
            long bytes = 0;
            for (i = 0; i < f.stride * (size_t)h; i++)
                bytes += f.px[i] != g.px[i];
            fprintf(stderr, "bench: %s %dx%d: the mirror of stp_tool_render differs in %ld bytes\n", name,
                    w, h, bytes);
            *mirror_ok = 0;
        }
        core_scene_free(&cs);
    } else {
        *mirror_ok = 0;
    }
    free(band);
    free(zbuf);

    core_bits = malloc(npx);
    bc = malloc(sizeof *bc * npx);
    br = malloc(sizeof *br * npx);
    if (!core_bits || !bc || !br) {
        free(core_bits);
        free(bc);
        free(br);
        ref_render_result_free(&res);
        free(f.px);
        free(g.px);
        return -1;
    }
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++)
            core_bits[(size_t)y * (size_t)w + (size_t)x] = (unsigned char)mono_at(&f, x, y);
    for (i = 0; i < npx; i++)
        diff += core_bits[i] != res.mono[i];
    blur3(core_bits, bc, w, h);
    blur3(res.mono, br, w, h);
    for (i = 0; i < npx; i++)
        ie->blur_sum += fabs(bc[i] - br[i]);
    ie->diff += diff;
    ie->pixels += (long)npx;
    if (dump_dir) {
        char path[1024];
        snprintf(path, sizeof path, "%s/%s-%dx%d-%s.pbm", dump_dir, name, w, h, STP_BENCH_CONFIG);
        write_pbm(path, core_bits, w, h);
        snprintf(path, sizeof path, "%s/%s-%dx%d-ref.pbm", dump_dir, name, w, h);
        write_pbm(path, res.mono, w, h);
    }
    free(core_bits);
    free(bc);
    free(br);
    ref_render_result_free(&res);
    free(f.px);
    free(g.px);
    return diff;
}

#if STP_BENCH_MESH
/* Replace every shade the polygon path gave (shade[i] >= 0) by the fast
 * flat-face shading of the mesh path: the polygon's Newell normal (double,
 * from its rounded vertices) as a Q1.14 prepared normal, its vertex average,
 * in world coordinates (the view is rigid, so the shade is the same). */
static void fast_scene_shades(const core_scene *cs, const stp_scene *scene, double *shade)
{
    stp_shade_fast fast;
    int last_material = -2;
    size_t i;
    for (i = 0; i < scene->polygon_count; i++) {
        const stp_scene_polygon *p = &scene->polygons[i];
        const stp_vec3 *v = cs->verts + p->first;
        ref_vec3 n = {0, 0, 0};
        int64_t sx = 0, sy = 0, sz = 0;
        int16_t qn[3];
        stp_vec3 centre;
        int k;
        if (shade[i] < 0)
            continue;
        if (p->material != last_material) {
            size_t mi = p->material >= 0 && (size_t)p->material < scene->material_count
                            ? (size_t)p->material
                            : scene->material_count;
            stp_vec3 zero = {0, 0, 0};
            stp_shade_fast_prepare(&fast, &cs->lighting, &cs->materials[mi], cs->eye, 0, zero);
            last_material = p->material;
        }
        for (k = 0; k < p->count; k++) {
            const stp_vec3 *a = &v[(k + p->count - 1) % p->count], *b = &v[k];
            double ax = from_fix(a->x), ay = from_fix(a->y), az = from_fix(a->z);
            double bx = from_fix(b->x), by = from_fix(b->y), bz = from_fix(b->z);
            n.x += (ay - by) * (az + bz);
            n.y += (az - bz) * (ax + bx);
            n.z += (ax - bx) * (ay + by);
            sx += b->x;
            sy += b->y;
            sz += b->z;
        }
        centre.x = (stp_fix)(sx / p->count);
        centre.y = (stp_fix)(sy / p->count);
        centre.z = (stp_fix)(sz / p->count);
        /* a back face is shaded as seen from its front (back-face removal
         * off, as stp_renderer_polygon and stp_renderer_mesh do) */
        if (n.x * (from_fix(cs->eye.x) - from_fix(centre.x)) + n.y * (from_fix(cs->eye.y) - from_fix(centre.y)) +
                n.z * (from_fix(cs->eye.z) - from_fix(centre.z)) < 0)
            n = ref_v3(-n.x, -n.y, -n.z);
        q14_normal(n, qn);
        shade[i] = from_fix(stp_shade_fast_face(&fast, qn, centre));
    }
}
#endif

/* Per-polygon shades of the core and the reference on one scene. */
typedef struct poly_error {
    stat shade;
    long compared, style_diff, degenerate_mismatch;
} poly_error;

static int compare_polygons(const char *name, const stp_scene *scene, poly_error *pe, stat *local)
{
    stp_tool_options opt;
    ref_render_options ropt;
    ref_render_result res;
    core_scene cs;
    char err[256];
    double *shade;
    size_t i;
    stp_tool_options_default(&opt);
    ref_render_options_default(&ropt);
    ropt.max_lights = STP_MAX_LIGHTS;
    ropt.max_vertices = STP_MAX_POLYGON_VERTICES;
    ref_lights_as_core(scene, &opt, &ropt);
    if (core_scene_prepare(&cs, scene, &opt, err, sizeof err) != 0) {
        fprintf(stderr, "bench: %s: %s\n", name, err);
        return -1;
    }
    shade = malloc(sizeof *shade * (scene->polygon_count + 1));
    if (!shade || core_scene_enter(&cs, scene, shade) != 0 ||
        ref_render_scene(scene, &ropt, &res, err, sizeof err) != 0) {
        fprintf(stderr, "bench: %s: polygons not compared\n", name);
        free(shade);
        core_scene_free(&cs);
        return -1;
    }
#if STP_BENCH_MESH
    fast_scene_shades(&cs, scene, shade);
#endif
    for (i = 0; i < scene->polygon_count; i++) {
        double c = shade[i], r = res.shade[i];
        if ((c >= 0) != (r >= 0)) {
            pe->degenerate_mismatch++;
            continue;
        }
        if (c < 0)
            continue;
        if (verbose && fabs(c - r) > STIFF_HALF_STEP)
            printf("  %s polygon %zu (line %d, %d vertices, size %.2g, |N.E| %.2g): core %.5f "
                   "reference %.5f\n",
                   name, i + 1, scene->polygons[i].source_line, scene->polygons[i].count, res.size[i],
                   res.n_dot_e[i], c, r);
        stat_add(&pe->shade, fabs(c - r));
        stat_add(local, fabs(c - r));
        pe->compared++;
        if (stp_intensity_index(stp_tool_fix(c), opt.levels) != ref_intensity_index(r, opt.levels))
            pe->style_diff++;
    }
    free(shade);
    core_scene_free(&cs);
    ref_render_result_free(&res);
    return 0;
}

/* ---- run time ---- */

/* Best time per call of fn(arg) in seconds: batches of `per_batch` calls
 * until `budget` seconds have passed (at least 3 batches); the best batch. */
typedef void (*work_fn)(void *arg, long i);

static double best_time(work_fn fn, void *arg, double budget)
{
    long per_batch = 1, i;
    double best = 1e30, start, t0, t;
    int batches = 0;
    /* calibrate: batches of about 2 ms, short enough that on a busy machine
     * many of them run without being preempted (the best is kept) */
    for (;;) {
        t0 = now();
        for (i = 0; i < per_batch; i++)
            fn(arg, i);
        t = now() - t0;
        if (t > 2e-3 || per_batch > (1L << 26))
            break;
        per_batch *= 2;
    }
    start = now();
    while (batches < 3 || now() - start < budget) {
        t0 = now();
        for (i = 0; i < per_batch; i++)
            fn(arg, i);
        t = (now() - t0) / (double)per_batch;
        if (t < best)
            best = t;
        batches++;
    }
    return best;
}

typedef struct shade_work {
    shade_input *in;
    long count;
    volatile uint32_t sink;
} shade_work;

static void shade_once(void *arg, long i)
{
    shade_work *w = (shade_work *)arg;
    w->sink = w->sink + (uint32_t)core_shade(&w->in[i % w->count]);
}

static void torus_once(void *arg, long i)
{
    torus_bench *b = (torus_bench *)arg;
    (void)i;
    if (torus_frame(b) != 0)
        b->keep_shades = -1; /* a refused frame: reported as a failed timing */
}

/* us per frame of issue 11's torus workload (torus.h: every triangle
 * re-entered, back faces removed, a finished MONO1 frame). */
static double time_torus(const stp_scene *torus, int w, int h, double budget)
{
    static torus_bench b;
    char err[256];
    double t;
    (void)torus;
    if (torus_bench_init(&b, w, h, err, sizeof err) != 0)
        return -1;
#if STP_BENCH_MESH
    if (torus_bench_use_mesh(&b, err, sizeof err) != 0) {
        torus_bench_free(&b);
        return -1;
    }
#endif
    t = best_time(torus_once, &b, budget);
    if (b.keep_shades < 0)
        t = -1;
    torus_bench_free(&b);
    return t;
}

#define FILL_W 640
#define FILL_H 480

typedef struct fill_work {
    uint8_t buf[(FILL_W / 8) * FILL_H];
    stp_cell cell;
} fill_work;

static void fill_once(void *arg, long i)
{
    fill_work *w = (fill_work *)arg;
    uint32_t y;
    for (y = 0; y < FILL_H; y++)
        stp_halftone_fillin(w->buf + (size_t)y * (FILL_W / 8), 0, FILL_W - 1, y, &w->cell,
                            (uint8_t)((unsigned long)i * 37u + y));
}

static void memset_once(void *arg, long i)
{
    fill_work *w = (fill_work *)arg;
    uint32_t y;
    for (y = 0; y < FILL_H; y++)
        memset(w->buf + (size_t)y * (FILL_W / 8), (int)(((unsigned long)i * 37u + y) & 255u), FILL_W / 8);
}

/* ---- main ---- */

static void usage(FILE *to)
{
    fprintf(to,
            "usage: bench_<cfg> [--quick] [--verbose] [--csv FILE] [--scenes DIR] [--dump DIR]\n"
            "  Measures shade and image error against the double reference and the run\n"
            "  time of this build's numeric configuration (" STP_BENCH_CONFIG ").\n"
            "  --quick      fewer inputs and short timings (a smoke test)\n"
            "  --verbose    list the scene polygons whose shade is off by more than 1/30\n"
            "  --csv FILE   append one CSV row to FILE (header first if FILE is empty)\n"
            "  --scenes DIR the shared NFF scenes (default $STP_SCENES_DIR, else\n"
            "               " STP_BENCH_SCENES_DIR ")\n"
            "  --dump DIR   write the core's and the reference's PBM pictures there\n");
}

int main(int argc, char **argv)
{
    const char *csv_path = 0, *scenes_dir = getenv("STP_SCENES_DIR");
    stat rand_err = {0, 0, 0}, rand_well = {0, 0, 0}, stiff_err = {0, 0, 0};
    double worst_cosine = 1;
    poly_error pe;
    image_error ie;
    shade_work sw;
    fill_work *fw;
    stp_scene torus;
    double ns_shade, us_frame[3], fill_s, memset_s;
    double rt_max = 0, rt_sum = 0, rt_mean = 0, rt_above_pct = 0, rt_us_frame = 0, rt_mrays = 0;
    static const int sizes[3][2] = {{128, 64}, {400, 240}, {640, 480}};
    long stiff_over = 0, n_random;
    int i, mirror_ok = 1, scene_failures = 0;
    size_t k;
    double budget;

    for (i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--quick"))
            quick = 1;
        else if (!strcmp(argv[i], "--verbose"))
            verbose = 1;
        else if (!strcmp(argv[i], "--csv") && i + 1 < argc)
            csv_path = argv[++i];
        else if (!strcmp(argv[i], "--scenes") && i + 1 < argc)
            scenes_dir = argv[++i];
        else if (!strcmp(argv[i], "--dump") && i + 1 < argc)
            dump_dir = argv[++i];
        else if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            usage(stdout);
            return 0;
        } else {
            usage(stderr);
            return 2;
        }
    }
    if (!scenes_dir || !*scenes_dir)
        scenes_dir = STP_BENCH_SCENES_DIR;
    budget = quick ? 0.02 : 0.5;
    n_random = quick ? 2000 : 50000;
    memset(&pe, 0, sizeof pe);
    memset(&ie, 0, sizeof ie);

    printf("== %s: STP_FIX_FRAC_BITS %d, STP_SQRT_FAST %d\n", STP_BENCH_CONFIG, STP_FIX_FRAC_BITS,
           STP_SQRT_FAST);

    /* shade error on random geometry */
    sw.count = n_random;
    sw.in = malloc(sizeof *sw.in * (size_t)n_random);
    sw.sink = 0;
    if (!sw.in)
        return 1;
    for (i = 0; i < n_random; i++) {
        double c, r, before = rand_err.max;
        random_input(&sw.in[i]);
        c = from_fix(core_shade(&sw.in[i]));
        r = ref_shade_point(&sw.in[i].lighting, &sw.in[i].material, sw.in[i].normal, sw.in[i].point,
                            sw.in[i].eye, sw.in[i].parallel, sw.in[i].pdir);
        stat_add(&rand_err, fabs(c - r));
        if (rand_err.max > before)
            worst_cosine = min_cosine(&sw.in[i]);
        if (min_cosine(&sw.in[i]) >= 1.0 / 1024)
            stat_add(&rand_well, fabs(c - r));
    }
    printf("random geometry   %6ld inputs      shade error max %.2e mean %.2e (the worst where the "
           "smallest of N.E, |N.L| is %.1e); where that is >= 2^-10: max %.2e\n",
           rand_err.n, rand_err.max, stat_mean(&rand_err), worst_cosine, rand_well.max);

    /* the stiff suite */
    for (k = 0; k < stiff_case_count(); k++) {
        stiff_outcome o;
#if STP_BENCH_MESH
        if (!fast_stiff_run(stiff_case_at(k), &o))
            continue;
#else
        stiff_run(stiff_case_at(k), &o);
#endif
        if (!o.has_err)
            continue;
        stat_add(&stiff_err, o.err);
        if (o.err > STIFF_HALF_STEP) {
            stiff_over++;
            printf("  stiff case above half a step: %-34s err %.4f\n", stiff_case_at(k)->name, o.err);
        }
    }
    printf("stiff suite       %6ld cases       shade error max %.2e mean %.2e, %ld above 1/30\n",
           stiff_err.n, stiff_err.max, stat_mean(&stiff_err), stiff_over);

    /* scenes: polygons and pictures */
    if (build_torus(&torus) != 0)
        return 1;
    printf("%-10s %7s %10s %10s %8s %12s %12s\n", "scene", "polys", "shade max", "shade mean",
           "style%", "px 128x64", "px 400x240");
    for (k = 0; k <= SCENE_COUNT; k++) {
        stp_scene scene, *sp;
        stp_scene_options sopt;
        char path[1024], err[512];
        const char *name = k < SCENE_COUNT ? scene_names[k] : "torus";
        stat local = {0, 0, 0};
        long before_compared = pe.compared, before_style = pe.style_diff, d1, d2;
        if (k < SCENE_COUNT) {
            stp_scene_options_default(&sopt);
            snprintf(path, sizeof path, "%s/%s.nff", scenes_dir, name);
            if (stp_scene_load(path, &sopt, &scene, err, sizeof err) != 0) {
                fprintf(stderr, "bench: %s\n", err);
                scene_failures++;
                continue;
            }
            sp = &scene;
        } else {
            sp = &torus;
        }
        if (compare_polygons(name, sp, &pe, &local) != 0)
            scene_failures++;
        d1 = compare_images(name, sp, 128, 64, &ie, &mirror_ok);
        d2 = quick ? 0 : compare_images(name, sp, 400, 240, &ie, &mirror_ok);
        printf("%-10s %7ld %10.2e %10.2e %8.2f %12ld %12ld\n", name, pe.compared - before_compared,
               local.max, stat_mean(&local),
               pe.compared - before_compared
                   ? 100.0 * (double)(pe.style_diff - before_style) / (double)(pe.compared - before_compared)
                   : 0.0,
               d1, d2);
        if (k < SCENE_COUNT)
            stp_scene_free(&scene);
    }
    if (!mirror_ok)
        printf("WARNING: the bench's mirror of stp_tool_render draws differently from it: "
               "update core_scene_prepare/enter in tools/bench/bench.c\n");
    if (pe.degenerate_mismatch)
        printf("note: %ld polygons degenerate in one of the core and the reference only\n",
               pe.degenerate_mismatch);
    printf("scene polygons    %6ld polygons    shade error max %.2e mean %.2e, style differs %.2f%%\n",
           pe.compared, pe.shade.max, stat_mean(&pe.shade),
           pe.compared ? 100.0 * (double)pe.style_diff / (double)pe.compared : 0.0);
    printf("pictures          %6d renders     differing pixels %ld of %ld (%.3f%%), blurred mean abs "
           "difference %.2e%s\n",
           ie.renders, ie.diff, ie.pixels, ie.pixels ? 100.0 * (double)ie.diff / (double)ie.pixels : 0.0,
           ie.pixels ? ie.blur_sum / (double)ie.pixels : 0.0, ie.failures ? " (SOME FAILED)" : "");

    /* the ray tracer: every scene against the reference ray tracer at
     * 96 x 64, and the frame time of balls-s2 (91 spheres) at 128 x 128 */
    {
        stp_tool_options ro;
        stp_rt_speed speed;
        long above = 0, pixels = 0;
        char err[512];
        stp_tool_options_default(&ro);
        ro.raytrace = 1;
        ro.width = 96;
        ro.height = 64;
        for (k = 0; k < SCENE_COUNT; k++) {
            stp_scene scene;
            stp_scene_options sopt;
            stp_rt_error e;
            char path[1024];
            stp_scene_options_default(&sopt);
            snprintf(path, sizeof path, "%s/%s.nff", scenes_dir, scene_names[k]);
            if (stp_scene_load(path, &sopt, &scene, err, sizeof err) != 0 ||
                stp_rt_compare(&scene, &ro, &e, 0, err, sizeof err) != 0) {
                fprintf(stderr, "bench: ray tracer: %s\n", err);
                scene_failures++;
                continue;
            }
            if (e.max > rt_max)
                rt_max = e.max;
            rt_sum += e.mean * (double)e.pixels;
            pixels += e.pixels;
            above += e.above_step;
            stp_scene_free(&scene);
        }
        rt_mean = pixels ? rt_sum / (double)pixels : 0;
        rt_above_pct = pixels ? 100.0 * (double)above / (double)pixels : 0;
        {
            stp_scene scene;
            stp_scene_options sopt;
            char path[1024];
            stp_scene_options_default(&sopt);
            snprintf(path, sizeof path, "%s/balls-s2.nff", scenes_dir);
            ro.width = ro.height = 128;
            if (stp_scene_load(path, &sopt, &scene, err, sizeof err) == 0) {
                if (stp_rt_time(&scene, &ro, budget, &speed, err, sizeof err) == 0) {
                    rt_us_frame = speed.frame_us;
                    rt_mrays = (double)(speed.rays + speed.shadow_rays) / speed.frame_us;
                } else {
                    scene_failures++;
                }
                stp_scene_free(&scene);
            } else {
                fprintf(stderr, "bench: %s\n", err);
                scene_failures++;
            }
        }
        printf("ray tracer        %6d scenes      shade error max %.2e mean %.2e, %.3f%% of pixels "
               "above 1/30; balls-s2 128x128 %.0f us/frame, %.3f Mrays/s\n",
               (int)SCENE_COUNT, rt_max, rt_mean, rt_above_pct, rt_us_frame, rt_mrays);
    }

    /* run time */
    ns_shade = best_time(shade_once, &sw, budget) * 1e9;
    for (i = 0; i < 3; i++)
        us_frame[i] = time_torus(&torus, sizes[i][0], sizes[i][1], budget) * 1e6;
    fw = calloc(1, sizeof *fw);
    if (!fw)
        return 1;
    (void)stp_cell_bayer(&fw->cell, 4);
    fill_s = best_time(fill_once, fw, budget);
    memset_s = best_time(memset_once, fw, budget);
    printf("run time          %.1f ns/shade; torus %.0f us/frame at 128x64, %.0f at 400x240, %.0f at "
           "640x480\n",
           ns_shade, us_frame[0], us_frame[1], us_frame[2]);
    printf("HALFTONE-FILLIN   %.1f Mpixel/s, memset %.1f Mpixel/s on the same rows, ratio %.5f "
           "(memset %.0f times faster)\n",
           FILL_W * FILL_H / fill_s * 1e-6, FILL_W * FILL_H / memset_s * 1e-6, memset_s / fill_s,
           fill_s / memset_s);

    if (csv_path) {
        FILE *f = fopen(csv_path, "a+");
        long size;
        if (!f) {
            perror(csv_path);
            return 1;
        }
        fseek(f, 0, SEEK_END);
        size = ftell(f);
        if (size == 0)
            fprintf(f, "config,frac_bits,sqrt_fast,rand_max,rand_mean,rand_max_wellcond,stiff_max,stiff_mean,"
                       "stiff_over_half_step,scene_max,scene_mean,style_diff_pct,img_diff_px,"
                       "img_pixels,img_diff_pct,img_blur_mad,ns_per_shade,us_frame_128x64,"
                       "us_frame_400x240,us_frame_640x480,fill_mpx_s,memset_mpx_s,"
                       "fill_memset_ratio,rt_max,rt_mean,rt_above_pct,rt_us_frame_balls128,"
                       "rt_mrays_s,failures\n");
        fprintf(f, "%s,%d,%d,%.3e,%.3e,%.3e,%.3e,%.3e,%ld,%.3e,%.3e,%.3f,%ld,%ld,%.4f,%.3e,%.1f,%.1f,%.1f,%.1f,"
                   "%.1f,%.1f,%.4f,%.3e,%.3e,%.3f,%.0f,%.3f,%d\n",
                STP_BENCH_CONFIG, STP_FIX_FRAC_BITS, STP_SQRT_FAST, rand_err.max, stat_mean(&rand_err),
                rand_well.max,
                stiff_err.max, stat_mean(&stiff_err), stiff_over, pe.shade.max, stat_mean(&pe.shade),
                pe.compared ? 100.0 * (double)pe.style_diff / (double)pe.compared : 0.0, ie.diff,
                ie.pixels, ie.pixels ? 100.0 * (double)ie.diff / (double)ie.pixels : 0.0,
                ie.pixels ? ie.blur_sum / (double)ie.pixels : 0.0, ns_shade, us_frame[0], us_frame[1],
                us_frame[2], FILL_W * FILL_H / fill_s * 1e-6, FILL_W * FILL_H / memset_s * 1e-6,
                memset_s / fill_s, rt_max, rt_mean, rt_above_pct, rt_us_frame, rt_mrays,
                scene_failures + ie.failures + (mirror_ok ? 0 : 1));
        fclose(f);
    }
    stp_scene_free(&torus);
    free(sw.in);
    free(fw);
    return scene_failures || !mirror_ok ? 1 : 0;
}
