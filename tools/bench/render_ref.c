/* SPDX-License-Identifier: MIT */
/* Double-precision reference renderer: see render_ref.h. */
#include "render_ref.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene_util.h"

#define REF_PI 3.14159265358979323846

int ref_ctx_init(ref_ctx *c, int width, int height)
{
    ref_view v;
    memset(c, 0, sizeof *c);
    if (width < 1 || height < 1 || width > 32767 || height > 32767)
        return -1;
    c->width = width;
    c->height = height;
    c->levels = 16;
    c->fill_style = 16;
    c->shading = 0;
    c->last_shade = -1;
    /* the seed's INITIALIZE-10 */
    c->lighting.brightness = 1;
    c->lighting.background = 0;
    c->lighting.c = 1;
    c->lighting.count = 1;
    c->lighting.lights[0].position = ref_v3(0, 0, 1);
    c->lighting.lights[0].power = 1;
    c->material.reflectivity = 1;
    c->material.refraction = 10;
    c->material.gloss = 10;
    c->material.specular = 1;
    memset(&v, 0, sizeof v);
    v.from = ref_v3(0, 0, -1);
    v.up = ref_v3(0, 1, 0);
    v.fov_degrees = 90;
    v.window_half = 1;
    v.hither = 1.0 / 256;
    v.perspective = 1;
    (void)ref_set_view(c, &v);
    return 0;
}

void ref_ctx_free(ref_ctx *c)
{
    free(c->polys);
    free(c->xy);
    memset(c, 0, sizeof *c);
}

int ref_view_frame_make(const ref_view *v, int width, int height, ref_view_frame *out)
{
    ref_vec3 dir, upn, right, up;
    double short_side = width < height ? width : height, focal;
    if (!v || ref_unit(ref_sub(v->at, v->from), &dir) == 0.0 || ref_unit(v->up, &upn) == 0.0)
        return REF_ERR_VIEW;
    /* up (nearly) along the line of sight: the core's threshold, 2^-10 */
    if (ref_unit(ref_cross(dir, upn), &right) < 1.0 / 1024)
        return REF_ERR_VIEW;
    (void)ref_unit(ref_cross(right, dir), &up);
    if (!(v->hither > 0))
        return REF_ERR_VIEW;
    if (v->perspective) {
        double half = v->fov_degrees / 2 * REF_PI / 180;
        if (!(v->fov_degrees > 0 && v->fov_degrees < 180))
            return REF_ERR_VIEW;
        focal = short_side / 2 * cos(half) / sin(half);
    } else {
        if (!(v->window_half > 0))
            return REF_ERR_VIEW;
        focal = short_side / 2 / v->window_half;
    }
    out->from = v->from;
    out->forward = dir;
    out->right = right;
    out->up = up;
    out->focal = focal;
    out->hither = v->hither;
    out->perspective = v->perspective != 0;
    return REF_OK;
}

int ref_set_view(ref_ctx *c, const ref_view *v)
{
    ref_view_frame f;
    if (ref_view_frame_make(v, c->width, c->height, &f) != REF_OK)
        return REF_ERR_VIEW;
    c->focal = f.focal;
    c->from = f.from;
    c->forward = f.forward;
    c->right = f.right;
    c->up = f.up;
    c->hither = f.hither;
    c->perspective = f.perspective;
    return REF_OK;
}

ref_vec3 ref_world_to_view(const ref_ctx *c, ref_vec3 p)
{
    ref_vec3 d = ref_sub(p, c->from);
    return ref_v3(ref_dot(d, c->right), ref_dot(d, c->up), ref_dot(d, c->forward));
}

void ref_set_lighting(ref_ctx *c, const ref_lighting *world)
{
    int j;
    c->lighting = *world;
    for (j = 0; j < world->count && j < REF_MAX_LIGHTS; j++)
        c->lighting.lights[j].position = ref_world_to_view(c, world->lights[j].position);
}

void ref_set_material(ref_ctx *c, const ref_material *m)
{
    c->material = *m;
}

static int intensity_of(double s, int levels)
{
    return ref_intensity_index(s, levels);
}

/* Grow an array to hold need elements. */
static int reserve(void **p, size_t *cap, size_t need, size_t elem)
{
    size_t n;
    void *q;
    if (need <= *cap)
        return 0;
    n = *cap ? *cap : 64;
    while (n < need)
        n *= 2;
    q = realloc(*p, n * elem);
    if (!q)
        return -1;
    *p = q;
    *cap = n;
    return 0;
}

/* Depth key at device (x, y) of the plane through centre with normal n
 * (view space): 1/z in perspective, -z in parallel. */
static void depth_plane(const ref_ctx *c, ref_vec3 n, ref_vec3 centre, ref_poly2 *p)
{
    double nc = ref_dot(n, centre);
    double w2 = c->width / 2.0, h2 = c->height / 2.0, f = c->focal;
    p->edge_on = 0;
    if (c->perspective) {
        /* ray t ((x - W/2)/f, (H/2 - y)/f, 1) meets n.p = n.c at z = t:
         * 1/z = (n.d)/(n.c) */
        if (nc == 0.0) {
            p->edge_on = 1;
            p->ka = p->kb = p->kc = 0;
            return;
        }
        p->ka = n.x / f / nc;
        p->kb = -n.y / f / nc;
        p->kc = (n.z - n.x * w2 / f + n.y * h2 / f) / nc;
    } else {
        /* z = (n.c - n.x x - n.y y) / n.z, key = -z */
        if (n.z == 0.0) {
            p->edge_on = 1;
            p->ka = p->kb = p->kc = 0;
            return;
        }
        p->ka = n.x / f / n.z;
        p->kb = -n.y / f / n.z;
        p->kc = (-nc + n.x * (-w2 / f) + n.y * (h2 / f)) / n.z;
    }
}

int ref_polygon(ref_ctx *c, const ref_vec3 *world, int n, size_t tag, double *shade_out)
{
    ref_vec3 *v, *clip;
    ref_vec3 normal, centre, eye_dir, rawn;
    double a = 0, b = 0, cc = 0, extent2 = 0, n_dot_e, s;
    int i, m, style, result = REF_OK;
    if (shade_out)
        *shade_out = -1;
    c->last_shade = -1;
    c->last_style = 0;
    c->last_n_dot_e = -1;
    c->last_size = 0;
    if (n < 3)
        return n >= 0 ? REF_ERR_DEGENERATE : REF_ERR_ARG;
    v = malloc(sizeof *v * (size_t)n * 3 + sizeof *v * 4);
    if (!v)
        return REF_ERR_ARG;
    clip = v + n;
    centre = ref_v3(0, 0, 0);
    for (i = 0; i < n; i++) {
        v[i] = ref_world_to_view(c, world[i]);
        centre.x += v[i].x;
        centre.y += v[i].y;
        centre.z += v[i].z;
    }
    centre.x /= n;
    centre.y /= n;
    centre.z /= n;
    /* Newell's sums (Algorithm 10.4) on coordinates relative to vertex 0
     * (the sums do not change under translation; this keeps their bits) */
    for (i = 0; i < n; i++) {
        ref_vec3 p = ref_sub(v[i == 0 ? n - 1 : i - 1], v[0]), q = ref_sub(v[i], v[0]);
        double d2 = ref_dot(q, q);
        if (d2 > extent2)
            extent2 = d2;
        a += (p.y - q.y) * (p.z + q.z);
        b += (p.z - q.z) * (p.x + q.x);
        cc += (p.x - q.x) * (p.y + q.y);
    }
    /* left-handed view system: Newell's right-handed sum points the other way */
    rawn = ref_v3(-a, -b, -cc);
    c->last_size = sqrt(extent2);
    /* |Newell| is twice the area: a polygon of exactly collinear vertices
     * keeps an area of rounding noise only (1e-16 of its extent squared)
     * after the view transform; below 1e-10 of it there is no normal */
    if (ref_unit(rawn, &normal) <= 1e-10 * extent2) {
        result = REF_ERR_DEGENERATE;
        goto done;
    }
    if (c->perspective) {
        if (ref_unit(ref_v3(-centre.x, -centre.y, -centre.z), &eye_dir) == 0.0)
            eye_dir = ref_v3(0, 0, -1);
    } else {
        eye_dir = ref_v3(0, 0, -1);
    }
    n_dot_e = ref_dot(normal, eye_dir);
    c->last_n_dot_e = fabs(n_dot_e);
    if (n_dot_e <= 0) {
        if (c->backface_removal)
            goto done;
        normal = ref_v3(-normal.x, -normal.y, -normal.z);
    }
    if (c->shading) {
        s = ref_shade_point(&c->lighting, &c->material, normal, centre, ref_v3(0, 0, 0),
                            !c->perspective, eye_dir);
        style = intensity_of(s, c->levels);
    } else {
        style = c->fill_style;
        s = (double)(style - 1) / (c->levels - 1);
    }
    c->last_shade = s;
    c->last_style = style;
    if (shade_out)
        *shade_out = s;

    /* clip to the hither plane z >= hither (Sutherland-Hodgman) */
    m = 0;
    for (i = 0; i < n; i++) {
        ref_vec3 p = v[i], q = v[(i + 1) % n];
        double dp = p.z - c->hither, dq = q.z - c->hither;
        if (dp >= 0)
            clip[m++] = p;
        if ((dp >= 0) != (dq >= 0)) {
            double t = dp / (dp - dq);
            clip[m++] = ref_v3(p.x + (q.x - p.x) * t, p.y + (q.y - p.y) * t, c->hither);
        }
    }
    if (m < 3)
        goto done;
    if (reserve((void **)&c->polys, &c->poly_cap, c->poly_count + 1, sizeof *c->polys) != 0 ||
        reserve((void **)&c->xy, &c->xy_cap, 2 * (c->xy_count + (size_t)m), sizeof *c->xy) != 0) {
        result = REF_ERR_ARG;
        goto done;
    }
    {
        ref_poly2 *p = &c->polys[c->poly_count++];
        double far_key = HUGE_VAL;
        p->first = c->xy_count;
        p->count = m;
        p->style = style;
        p->tag = tag;
        depth_plane(c, rawn, centre, p);
        for (i = 0; i < m; i++) {
            double x, y, key;
            if (c->perspective) {
                x = c->width / 2.0 + c->focal * clip[i].x / clip[i].z;
                y = c->height / 2.0 - c->focal * clip[i].y / clip[i].z;
                key = 1.0 / clip[i].z;
            } else {
                x = c->width / 2.0 + c->focal * clip[i].x;
                y = c->height / 2.0 - c->focal * clip[i].y;
                key = -clip[i].z;
            }
            if (key < far_key)
                far_key = key;
            c->xy[2 * c->xy_count] = x;
            c->xy[2 * c->xy_count + 1] = y;
            c->xy_count++;
        }
        p->far_key = far_key;
    }
done:
    free(v);
    return result;
}

int ref_level(int style, int levels, double gamma, double gamma_k)
{
    if (style < 1)
        style = 1;
    if (style > levels)
        style = levels;
    if (gamma != 1.0 || gamma_k != 1.0) {
        double g = gamma > 0 ? gamma : 1, k = gamma_k > 0 ? gamma_k : 1;
        return (int)floor(255.0 * ref_gamma((double)(style - 1) / (levels - 1), g, k) + 0.5);
    }
    /* the linear map: (index-1) * 255 / (levels-1), halves rounded up */
    return (int)floor((double)(style - 1) * 255.0 / (levels - 1) + 0.5);
}

/* Bayer threshold at (x, y) of a linear-spaced cell of side n (2 or 4):
 * ranks of ImageMagick's o2x2 and o4x4 maps. */
static int bayer_threshold(int n, int x, int y)
{
    static const int o2[2][2] = {{0, 2}, {3, 1}};
    static const int o4[4][4] = {{0, 8, 2, 10}, {12, 4, 14, 6}, {3, 11, 1, 9}, {15, 7, 13, 5}};
    int r = n == 2 ? o2[y % 2][x % 2] : o4[y % 4][x % 4];
    int m = n * n;
    /* ceil(255 (r+1) / (m+1)) - 1 */
    return (255 * (r + 1) + m) / (m + 1) - 1;
}

static const ref_ctx *sort_ctx;

static int painter_cmp(const void *pa, const void *pb)
{
    const size_t ia = *(const size_t *)pa, ib = *(const size_t *)pb;
    const ref_poly2 *a = &sort_ctx->polys[ia], *b = &sort_ctx->polys[ib];
    if (a->far_key != b->far_key)
        return a->far_key < b->far_key ? -1 : 1;
    return ia < ib ? -1 : (ia > ib ? 1 : 0);
}

static int cmp_double(const void *pa, const void *pb)
{
    double a = *(const double *)pa, b = *(const double *)pb;
    return a < b ? -1 : (a > b ? 1 : 0);
}

int ref_finish(ref_ctx *c, const ref_output *out, unsigned char *grey, unsigned char *mono,
               int *style_px, long *owner)
{
    size_t npx = (size_t)c->width * (size_t)c->height, i, k;
    int *sty = malloc(sizeof *sty * npx);
    double *zbuf = out->hidden == REF_HIDDEN_ZBUFFER ? malloc(sizeof *zbuf * npx) : 0;
    long *own = malloc(sizeof *own * npx);
    size_t *order = malloc(sizeof *order * (c->poly_count + 1));
    double *xs = 0;
    size_t xs_cap = 0;
    int bg_style, result = -1, y, x;
    if (!sty || !own || !order || (out->hidden == REF_HIDDEN_ZBUFFER && !zbuf))
        goto done;
    if (out->cell != 2 && out->cell != 4)
        goto done;
    bg_style = intensity_of(out->background, c->levels);
    for (i = 0; i < npx; i++) {
        sty[i] = bg_style;
        own[i] = -1;
        if (zbuf)
            zbuf[i] = -HUGE_VAL;
    }
    for (i = 0; i < c->poly_count; i++)
        order[i] = i;
    if (out->hidden == REF_HIDDEN_PAINTER) {
        sort_ctx = c;
        qsort(order, c->poly_count, sizeof *order, painter_cmp);
    }
    for (k = 0; k < c->poly_count; k++) {
        const ref_poly2 *p = &c->polys[order[k]];
        const double *xy = c->xy + 2 * p->first;
        int n = p->count;
        if (zbuf && p->edge_on)
            continue;
        if (reserve((void **)&xs, &xs_cap, (size_t)n, sizeof *xs) != 0)
            goto done;
        for (y = 0; y < c->height; y++) {
            double yc = y + 0.5;
            int nc = 0, e;
            for (e = 0; e < n; e++) {
                double xa = xy[2 * e], ya = xy[2 * e + 1];
                double xb = xy[2 * ((e + 1) % n)], yb = xy[2 * ((e + 1) % n) + 1];
                if (ya == yb)
                    continue;
                if (ya > yb) {
                    double t = xa;
                    xa = xb;
                    xb = t;
                    t = ya;
                    ya = yb;
                    yb = t;
                }
                if (ya <= yc && yc < yb)
                    xs[nc++] = xa + (yc - ya) * (xb - xa) / (yb - ya);
            }
            if (nc < 2)
                continue;
            qsort(xs, (size_t)nc, sizeof *xs, cmp_double);
            for (e = 0; e + 1 < nc; e += 2) {
                /* pixels i with x_left <= i + 0.5 < x_right */
                double fl = ceil(xs[e] - 0.5), fr = ceil(xs[e + 1] - 0.5) - 1;
                int x1, x2;
                if (fl < 0)
                    fl = 0;
                if (fr > c->width - 1)
                    fr = c->width - 1;
                if (fl > fr)
                    continue;
                x1 = (int)fl;
                x2 = (int)fr;
                for (x = x1; x <= x2; x++) {
                    size_t at = (size_t)y * (size_t)c->width + (size_t)x;
                    if (zbuf) {
                        double key = p->ka * (x + 0.5) + p->kb * yc + p->kc;
                        if (!(key > zbuf[at]))
                            continue;
                        zbuf[at] = key;
                    }
                    sty[at] = p->style;
                    own[at] = (long)p->tag;
                }
            }
        }
    }
    for (y = 0; y < c->height; y++) {
        for (x = 0; x < c->width; x++) {
            size_t at = (size_t)y * (size_t)c->width + (size_t)x;
            int level = ref_level(sty[at], c->levels, out->gamma, out->gamma_k);
            if (grey)
                grey[at] = (unsigned char)level;
            if (mono)
                mono[at] = (unsigned char)(level > bayer_threshold(out->cell, x, y));
            if (style_px)
                style_px[at] = sty[at];
            if (owner)
                owner[at] = own[at];
        }
    }
    result = 0;
done:
    free(sty);
    free(zbuf);
    free(own);
    free(order);
    free(xs);
    return result;
}

/* ---- whole scenes ---- */

void ref_render_options_default(ref_render_options *o)
{
    memset(o, 0, sizeof *o);
    o->width = 128;
    o->height = 64;
    o->levels = 16;
    o->cell = 4;
    o->gamma = 1;
    o->gamma_k = 1;
    o->hidden = REF_HIDDEN_ZBUFFER;
    o->shading = 1;
    o->background = 0.2;
    o->brightness = 1;
    o->attenuation_c = 1;
    o->auto_power = 1;
    o->max_lights = 4;
    o->max_vertices = 160;
    o->perspective = 1;
}

void ref_render_result_free(ref_render_result *res)
{
    free(res->shade);
    free(res->n_dot_e);
    free(res->size);
    free(res->poly_style);
    free(res->grey);
    free(res->mono);
    free(res->owner);
    memset(res, 0, sizeof *res);
}

static ref_vec3 from_scene(stp_scene_vec3 v)
{
    return ref_v3(v.x, v.y, v.z);
}

static double dist3(ref_vec3 a, ref_vec3 b)
{
    ref_vec3 d = ref_sub(a, b);
    return sqrt(ref_dot(d, d));
}

/* NFF material to the seed's parameters, as render_scene.c's
 * material_from_scene (R = Kd x luminance, n = ior if > 1 else 10,
 * k = 2/Shine if Shine > 0 else 10, specular weight Ks). */
static void material_of(const stp_scene_material *m, ref_material *out)
{
    double lum = 0.30 * m->color[0] + 0.59 * m->color[1] + 0.11 * m->color[2];
    double refl = m->kd * lum;
    out->reflectivity = refl < 0 ? 0 : (refl > 1 ? 1 : refl);
    out->refraction = m->ior > 1.0 ? m->ior : 10.0;
    out->gloss = m->shine > 0 ? 2.0 / m->shine : 10.0;
    out->specular = m->ks < 0 ? 0 : m->ks;
}

int ref_render_scene(const stp_scene *scene, const ref_render_options *opt,
                     ref_render_result *res, char *err, size_t err_size)
{
    stp_scene_vec3 slo, shi;
    ref_vec3 lo, hi, centre, light_pos[REF_MAX_LIGHTS];
    double radius;
    ref_view view;
    ref_lighting lighting;
    ref_output out;
    ref_ctx ctx;
    ref_vec3 *verts = 0;
    size_t i, npx;
    int j, light_count, last_material = -2, max_lights;
    double weight[REF_MAX_LIGHTS], weight_total = 0;

    memset(res, 0, sizeof *res);
    if (stp_scene_bounds(scene, &slo, &shi) != 0) {
        snprintf(err, err_size, "the scene has no polygons to render");
        return -1;
    }
    lo = from_scene(slo);
    hi = from_scene(shi);
    centre = ref_v3((lo.x + hi.x) / 2, (lo.y + hi.y) / 2, (lo.z + hi.z) / 2);
    radius = dist3(lo, hi) / 2;
    if (radius <= 0)
        radius = 1;

    memset(&view, 0, sizeof view);
    if (scene->has_view) {
        view.from = from_scene(scene->from);
        view.at = from_scene(scene->at);
        view.up = from_scene(scene->up);
        view.fov_degrees = opt->fov > 0 ? opt->fov : scene->angle;
        view.hither = scene->hither > 0 ? scene->hither : 1e-3;
    } else {
        double fov = opt->fov > 0 ? opt->fov : 45.0;
        double d = radius / sin(fov * 0.5 * REF_PI / 180.0) * 1.05;
        view.from = ref_v3(centre.x + d * 0.48, centre.y + d * 0.40, centre.z + d * 0.78);
        view.at = centre;
        view.up = ref_v3(0, 1, 0);
        view.fov_degrees = fov;
        view.hither = d * 1e-3;
    }
    view.perspective = opt->perspective;
    view.window_half = radius;

    max_lights = opt->max_lights > 0 && opt->max_lights < REF_MAX_LIGHTS ? opt->max_lights : REF_MAX_LIGHTS;
    if (opt->light_count > 0) {
        light_count = opt->light_count > max_lights ? max_lights : opt->light_count;
        for (j = 0; j < light_count; j++)
            light_pos[j] = opt->lights[j];
    } else if (scene->light_count > 0) {
        light_count = (int)(scene->light_count > (size_t)max_lights ? (size_t)max_lights : scene->light_count);
        for (j = 0; j < light_count; j++)
            light_pos[j] = from_scene(scene->lights[j].position);
    } else {
        ref_vec3 eye = scene->has_view ? from_scene(scene->from) : centre;
        light_pos[0] = ref_v3(eye.x - radius, eye.y + radius * 2, eye.z + radius * 3);
        light_count = 1;
    }
    memset(&lighting, 0, sizeof lighting);
    lighting.brightness = opt->brightness < 0 ? 0 : opt->brightness;
    lighting.background = opt->background;
    lighting.c = opt->attenuation_c;
    lighting.count = light_count;
    for (j = 0; j < light_count; j++)
        weight[j] = opt->light_count > 0 && opt->light_weight[j] > 0 ? opt->light_weight[j] : 1.0;
    for (j = 0; j < light_count; j++)
        weight_total += weight[j];
    for (j = 0; j < light_count; j++) {
        /* a merged light has the power of the lights it stands for */
        double power = (1.0 - opt->background) * weight[j];
        if (opt->auto_power)
            power *= (opt->attenuation_c + dist3(light_pos[j], centre)) / sqrt(weight_total);
        lighting.lights[j].position = light_pos[j];
        lighting.lights[j].power = power;
    }

    if (ref_ctx_init(&ctx, opt->width, opt->height) != 0) {
        snprintf(err, err_size, "bad size %dx%d", opt->width, opt->height);
        return -1;
    }
    if (ref_set_view(&ctx, &view) != REF_OK || opt->levels < 2 || opt->levels > 256) {
        snprintf(err, err_size, "view: bad view or levels");
        ref_ctx_free(&ctx);
        return -1;
    }
    ctx.levels = opt->levels;
    ref_set_lighting(&ctx, &lighting);
    ctx.shading = opt->shading != 0;
    ctx.backface_removal = opt->backface_removal != 0;

    res->width = opt->width;
    res->height = opt->height;
    res->polygon_count = scene->polygon_count;
    npx = (size_t)opt->width * (size_t)opt->height;
    res->shade = malloc(sizeof *res->shade * (scene->polygon_count + 1));
    res->poly_style = malloc(sizeof *res->poly_style * (scene->polygon_count + 1));
    res->n_dot_e = malloc(sizeof *res->n_dot_e * (scene->polygon_count + 1));
    res->size = malloc(sizeof *res->size * (scene->polygon_count + 1));
    res->grey = malloc(npx);
    res->mono = malloc(npx);
    res->owner = malloc(sizeof *res->owner * npx);
    if (!res->shade || !res->poly_style || !res->n_dot_e || !res->size || !res->grey || !res->mono || !res->owner)
        goto fail_mem;

    for (i = 0; i < scene->polygon_count; i++) {
        const stp_scene_polygon *p = &scene->polygons[i];
        int k, status;
        ref_vec3 *nv;
        if (p->material != last_material) {
            ref_material m;
            m.reflectivity = 1;
            m.refraction = 10;
            m.gloss = 10;
            m.specular = 1;
            if (p->material >= 0 && (size_t)p->material < scene->material_count)
                material_of(&scene->materials[p->material], &m);
            ref_set_material(&ctx, &m);
            ctx.fill_style = intensity_of(m.reflectivity, ctx.levels);
            last_material = p->material;
        }
        if (opt->max_vertices > 0 && p->count > opt->max_vertices) {
            snprintf(err, err_size, "polygon %zu (line %d) has %d vertices; the core takes %d", i + 1,
                     p->source_line, p->count, opt->max_vertices);
            goto fail;
        }
        nv = realloc(verts, sizeof *verts * (size_t)(p->count > 0 ? p->count : 1));
        if (!nv)
            goto fail_mem;
        verts = nv;
        for (k = 0; k < p->count; k++)
            verts[k] = from_scene(scene->vertices[p->first + (size_t)k]);
        status = ref_polygon(&ctx, verts, p->count, i, &res->shade[i]);
        res->poly_style[i] = status == REF_OK ? ctx.last_style : 0;
        res->n_dot_e[i] = status == REF_OK ? ctx.last_n_dot_e : -1;
        res->size[i] = ctx.last_size;
        if (status == REF_ERR_DEGENERATE)
            res->degenerate++;
        else if (status != REF_OK)
            goto fail_mem;
    }
    memset(&out, 0, sizeof out);
    out.hidden = opt->hidden;
    out.cell = opt->cell;
    out.gamma = opt->gamma;
    out.gamma_k = opt->gamma_k;
    if (scene->has_background) {
        const double *b = scene->background;
        double lum = 0.30 * b[0] + 0.59 * b[1] + 0.11 * b[2];
        out.background = lum < 0 ? 0 : (lum > 1 ? 1 : lum);
    }
    if (ref_finish(&ctx, &out, res->grey, res->mono, 0, res->owner) != 0) {
        snprintf(err, err_size, "bad output options or out of memory");
        goto fail;
    }
    free(verts);
    ref_ctx_free(&ctx);
    return 0;
fail_mem:
    snprintf(err, err_size, "out of memory");
fail:
    free(verts);
    ref_ctx_free(&ctx);
    ref_render_result_free(res);
    return -1;
}
