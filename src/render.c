/* SPDX-License-Identifier: MIT */
/* The display file: viewing, segments and DISPLAY-FILE-ENTER (transform,
 * SHADE-CHECK, clip, project, store).  See include/stipple/render.h. */
#include "align_private.h"
#include "render_private.h"
#include "shadow_private.h"
#include "view_private.h"
#include "shade_private.h"
#include "clip_private.h"
#include "recip_private.h"
#include "edge_walk_private.h" /* stp_tri_sort, stp_edge_acc_short, stp_floor16 */

#define F STP_FIX_FRAC_BITS
#define ONE STP_FIX_ONE

/* Whether a 64-bit division is one instruction (64-bit hosts); elsewhere
 * (a ~470-instruction library call on ARMv6-M) a quotient that fits 32
 * bits is taken in 32 bits, with the same result. */
#define WIDE_DIVISION STP_WIDE_ARITH /* recip_private.h: the same test */

/* STP_RENDERER_BYTES must bound the object: a negative array size here
 * stops the build when it does not. */
typedef char stp_renderer_bytes_bound[sizeof(stp_renderer) <= STP_RENDERER_BYTES ? 1 : -1];

size_t stp_renderer_size(void)
{
    return sizeof(stp_renderer);
}

static void world_to_view(const stp_renderer *r, stp_vec3 p, stp_vec3 *out);

/* The face stage's prepared shading (render_private.h) is out of date. */
static void forget_fast_shade(stp_renderer *r)
{
    r->fast_shade_valid = 0;
}
static void close_implicit_segment(stp_renderer *r);

/* C99 has no alignof: a type's alignment is its offset after a char. */
struct renderer_alignment {
    char c;
    stp_renderer r;
};
struct instr_alignment {
    char c;
    stp_instr i;
};
static void cache_forget(stp_renderer *r);

stp_renderer *stp_renderer_create(void *mem, size_t mem_size, stp_instr *display_file,
                                  uint32_t capacity, uint32_t width, uint32_t height)
{
    stp_renderer *r = (stp_renderer *)mem;
    stp_view view;
    int i;
    if (mem == 0 || mem_size < sizeof(stp_renderer) || display_file == 0 || capacity == 0 ||
        width < 1 || height < 1 || width > 32767 || height > 32767)
        return 0;
    /* a misaligned object would fault on the first 64-bit access on a
     * Cortex-M0 rather than fail here */
    if (!stp_is_aligned(mem, offsetof(struct renderer_alignment, r)) ||
        !stp_is_aligned(display_file, offsetof(struct instr_alignment, i)))
        return 0;
    r->df = display_file;
    r->capacity = capacity;
    r->used = 0;
    r->width = width;
    r->height = height;
    for (i = 0; i < STP_MAX_SEGMENTS; i++)
        r->segments[i].used = 0;
    r->open_segment = -1;
    stp_lighting_default(&r->user_lighting);
    r->segment_lighting = r->user_lighting;
    stp_material_default(&r->material);
    forget_fast_shade(r);
    r->fast_shade_parallel = 0;
    r->frame_valid = 0;
    r->model_route_ok = 0;
    r->shading = 0;
    r->levels = 16;
    stp_pattern_keep_forget(r);
    r->fill_style = 16;
    r->backface_removal = 0;
    r->pixel_cull = 0;
    r->current_style = -1;
    r->current_line_style = -1;
    r->colour = 0;
    r->current_colour = 0;
    r->t_min = r->t_max = 0;
    r->t_attenuation = ONE;
    r->t_power = 2;
    r->current_transmission = 0;
    r->last_shade = -1;
    r->pen_valid = 0;
    r->model_on = 0;
    stp_transform_identity(&r->model);
#if STP_VERTEX_CACHE
    for (i = 0; i < STP_VERTEX_CACHE; i++) {
        r->cache[i].stamp = 0;
        r->cache[i].used_by = 0;
    }
    r->cache_stamp = 1;
    r->cache_polygon = 0;
    r->cache_hash = STP_CACHE_HASH;
#endif
#if STP_WITH_SHADOWS
    for (i = 0; i < STP_MAX_LIGHTS; i++) {
        r->shadow[i].depth = 0;
        r->shadow_record[i] = UINT32_MAX;
    }
    r->shadow_set = 0;
    r->shadow_generation = 0;
#endif
    view.from.x = view.from.y = 0;
    view.from.z = -ONE;
    view.at.x = view.at.y = view.at.z = 0;
    view.up.x = view.up.z = 0;
    view.up.y = ONE;
    view.fov_degrees = 90 * ONE;
    view.window_half = ONE;
    view.hither = ONE >> 8;
    view.projection = STP_PERSPECTIVE;
    (void)stp_renderer_set_view(r, &view);
    return r;
}

int stp_renderer_set_view(stp_renderer *r, const stp_view *v)
{
    stp_view_frame vf;
    int status;
    if (r == 0 || v == 0)
        return STP_ERR_ARG;
    status = stp_view_frame_make(v, r->width, r->height, &vf);
    if (status != STP_OK)
        return status;
    close_implicit_segment(r);
    if ((vf.projection == STP_PARALLEL) != r->fast_shade_parallel)
        forget_fast_shade(r); /* the face shader's eye changes */
    r->focal = vf.focal;
    r->from = vf.from;
    r->near_ok = vf.from.x > -(1L << 30) && vf.from.x < (1L << 30) && vf.from.y > -(1L << 30) &&
                 vf.from.y < (1L << 30) && vf.from.z > -(1L << 30) && vf.from.z < (1L << 30);
    r->near_bias_x = (uint32_t)vf.from.x - ((uint32_t)1 << 20);
    r->near_bias_y = (uint32_t)vf.from.y - ((uint32_t)1 << 20);
    r->near_bias_z = (uint32_t)vf.from.z - ((uint32_t)1 << 20);
    r->forward = vf.forward;
    r->right = vf.right;
    r->up = vf.up;
    r->projection = vf.projection;
    r->hither = vf.hither;
    r->clip_volume.focal = vf.focal;
    r->clip_volume.near = vf.hither;
    /* the picture and the guard band around it (project_private.h: 0
     * without it), at most 32767 a side */
    r->clip_volume.width = r->width + 2u * stp_guard_pixels(r->width);
    r->clip_volume.height = r->height + 2u * stp_guard_pixels(r->height);
    r->clip_volume.parallel = vf.projection == STP_PARALLEL;
    stp_view_transform_make(&vf, &r->to_view);
    stp_render_geometry_update(r);
    r->pen_valid = 0;
    cache_forget(r);
#if STP_WITH_SHADOWS
    {
        /* the maps' transforms start from this view's coordinates */
        int j;
        r->at = v->at;
        for (j = 0; j < STP_MAX_LIGHTS; j++)
            r->shadow[j].depth = 0;
        r->shadow_set = 0;
    }
#endif
    return STP_OK;
}

int stp_renderer_set_light(stp_renderer *r, stp_vec3 position, stp_fix brightness, stp_fix background)
{
    stp_lighting *l;
    if (r == 0 || brightness < 0 || background < 0 || background > ONE)
        return STP_ERR_ARG;
    close_implicit_segment(r);
    l = &r->user_lighting;
    l->background = background;
    l->brightness = brightness;
    l->count = 1;
    l->lights[0].position = position;
    l->lights[0].power = ONE - l->background;
    r->shading = 1;
    return STP_OK;
}

int stp_renderer_set_lighting(stp_renderer *r, const stp_lighting *lighting)
{
    if (r == 0 || lighting == 0 || lighting->count < 0 || lighting->count > STP_MAX_LIGHTS)
        return STP_ERR_ARG;
    close_implicit_segment(r);
    r->shading = 1;
    r->user_lighting = *lighting;
    r->user_lighting.background = stp_fix_clamp(lighting->background, 0, ONE);
    if (r->user_lighting.brightness < 0)
        r->user_lighting.brightness = 0;
    return STP_OK;
}

static int material_equal(const stp_material *a, const stp_material *b)
{
    return a->reflectivity == b->reflectivity && a->refraction == b->refraction &&
           a->gloss == b->gloss && a->specular == b->specular && a->colour[0] == b->colour[0] &&
           a->colour[1] == b->colour[1] && a->colour[2] == b->colour[2];
}

int stp_renderer_set_object_shade(stp_renderer *r, const stp_material *material)
{
    int c;
    if (r == 0 || material == 0 || material->reflectivity < 0 || material->reflectivity > ONE ||
        material->refraction < 0 || material->gloss < 0 || material->specular < 0)
        return STP_ERR_ARG;
    for (c = 0; c < 3; c++)
        if (material->colour[c] < 0 || material->colour[c] > ONE)
            return STP_ERR_ARG;
    if (!material_equal(&r->material, material))
        forget_fast_shade(r); /* the face stage prepares its shading again */
    r->material = *material;
    return STP_OK;
}

int stp_renderer_set_shading(stp_renderer *r, int on)
{
    if (r == 0)
        return STP_ERR_ARG;
    r->shading = on != 0;
    return STP_OK;
}

int stp_renderer_set_fill_style(stp_renderer *r, int index)
{
    if (r == 0 || index < 1 || index > r->levels)
        return STP_ERR_ARG;
    r->fill_style = index;
    return STP_OK;
}

int stp_renderer_set_levels(stp_renderer *r, int levels)
{
    if (r == 0 || levels < 2 || levels > 256)
        return STP_ERR_ARG;
    r->levels = levels;
    if (r->fill_style > levels)
        r->fill_style = levels;
    r->current_style = -1;
    return STP_OK;
}

int stp_renderer_set_colour(stp_renderer *r, int on)
{
    if (r == 0)
        return STP_ERR_ARG;
#if STP_WITH_COLOUR
    r->colour = on != 0;
    r->model_route_ok = 0; /* model_route decides again */
    return STP_OK;
#else
    return on ? STP_ERR_UNSUPPORTED : STP_OK;
#endif
}

int stp_renderer_set_transparency(stp_renderer *r, stp_fix t_min, stp_fix t_max, int power,
                         stp_fix absorption, stp_fix thickness)
{
    if (r == 0 || t_min < 0 || t_max < 0 || t_min > ONE || t_max > ONE || power < 1 || power > 4 ||
        absorption < 0 || thickness < 0)
        return STP_ERR_ARG;
#if STP_WITH_TRANSPARENCY
    r->t_min = t_min;
    r->t_max = t_max;
    r->model_route_ok = 0; /* model_route decides again */
    r->t_power = power;
    /* e^(-a d) = 2^(-a d log2 e) */
    {
        stp_fix ad = stp_fix_mul(absorption, thickness);
        /* exactly 1 without absorption: exp2's rounding must not dim t */
        r->t_attenuation = ad == 0 ? ONE
                                   : stp_fix_clamp(stp_fix_exp2(-stp_fix_mul(ad, stp_fix_from_ratio(94548, 65536))),
                                                   0, ONE);
    }
    return STP_OK;
#else
    (void)thickness;
    (void)absorption;
    return t_min == 0 && t_max == 0 ? STP_OK : STP_ERR_UNSUPPORTED;
#endif
}

int stp_renderer_set_pixel_cull(stp_renderer *r, int on)
{
    if (r == 0)
        return STP_ERR_ARG;
    r->pixel_cull = on ? STP_CENTRE_TEST_MAX : 0;
    return STP_OK;
}

int stp_renderer_set_backface_removal(stp_renderer *r, int on)
{
    if (r == 0)
        return STP_ERR_ARG;
    r->backface_removal = on != 0;
    return STP_OK;
}

/* ---- segments ---- */

static int find_segment(const stp_renderer *r, int id)
{
    int i;
    for (i = 0; i < STP_MAX_SEGMENTS; i++)
        if (r->segments[i].used && r->segments[i].id == id)
            return i;
    return -1;
}

/* A free slot of the segment table, or -1. */
static int free_segment_slot(const stp_renderer *r)
{
    int i;
    for (i = 0; i < STP_MAX_SEGMENTS; i++)
        if (!r->segments[i].used)
            return i;
    return -1;
}

static int vec_equal(stp_vec3 a, stp_vec3 b)
{
    return a.x == b.x && a.y == b.y && a.z == b.z;
}

/* COPY-LIGHT: the user's lighting into the segment's with the lights in
 * view coordinates; the mesh path's prepared shading is kept when the
 * result equals the last segment's (the common case: a scene re-entered
 * every frame under a fixed view and lighting). */
static void copy_light(stp_renderer *r)
{
    const stp_lighting *u = &r->user_lighting;
    stp_lighting *s = &r->segment_lighting;
    int same = s->count == u->count && s->brightness == u->brightness &&
               s->background == u->background && s->attenuation_c == u->attenuation_c, j, c;
    for (j = 0; j < u->count; j++) {
        stp_vec3 p;
        world_to_view(r, u->lights[j].position, &p);
        same = same && vec_equal(p, s->lights[j].position) && u->lights[j].power == s->lights[j].power;
        for (c = 0; c < 3; c++)
            same = same && u->lights[j].colour[c] == s->lights[j].colour[c];
        s->lights[j] = u->lights[j];
        s->lights[j].position = p;
    }
    s->count = u->count;
    s->brightness = u->brightness;
    s->background = u->background;
    s->attenuation_c = u->attenuation_c;
    if (!same)
        forget_fast_shade(r);
}

/* Open segment id (checked by the caller: no segment open, id not in use). */
static int open_segment(stp_renderer *r, int id)
{
    int i = free_segment_slot(r);
    if (i < 0)
        return STP_ERR_FULL;
    r->segments[i].used = 1;
    r->segments[i].open = 1;
    r->segments[i].visible = 1;
    r->segments[i].pixel_culled = 0;
    r->segments[i].id = id;
    r->segments[i].start = r->segments[i].end = r->used;
    r->open_segment = i;
    r->current_style = -1;
    r->current_line_style = -1;
    r->current_transmission = 0;
    r->pen_valid = 0;
    if (r->model_on)
        cache_forget(r);
    r->model_on = 0;
    stp_render_geometry_update(r);
    /* COPY-LIGHT: the lighting belongs to the view; fix it for this segment
     * with the lights in view coordinates */
    copy_light(r);
    return STP_OK;
}

/* Implicit segments: drawing with no open segment opens one, with the first
 * free id of -1, -2, ...; it stays open until a segment is created or the
 * view or the lighting changes (so the next one copies the new lighting). */
static int open_implicit_segment(stp_renderer *r)
{
    int id = -1;
    while (find_segment(r, id) >= 0)
        id--; /* at most STP_MAX_SEGMENTS steps */
    return open_segment(r, id);
}

static void close_implicit_segment(stp_renderer *r)
{
    if (r->open_segment >= 0 && r->segments[r->open_segment].id < 0) {
        r->segments[r->open_segment].open = 0;
        r->open_segment = -1;
    }
}

int stp_segment_create(stp_renderer *r, int id)
{
    if (r == 0 || id < 0 || id > 32767)
        return STP_ERR_ARG;
    if ((r->open_segment >= 0 && r->segments[r->open_segment].id >= 0) || find_segment(r, id) >= 0)
        return STP_ERR_SEGMENT;
    if (free_segment_slot(r) < 0)
        return STP_ERR_FULL; /* before ending an implicit one: a failed call changes nothing */
    close_implicit_segment(r);
    return open_segment(r, id);
}

int stp_segment_close(stp_renderer *r)
{
    if (r == 0)
        return STP_ERR_ARG;
    if (r->open_segment < 0)
        return STP_ERR_SEGMENT;
    r->segments[r->open_segment].open = 0;
    r->open_segment = -1;
    return STP_OK;
}

int stp_segment_delete(stp_renderer *r, int id)
{
    int s, i;
    uint32_t start, len, k;
    if (r == 0)
        return STP_ERR_ARG;
    s = find_segment(r, id);
    if (s < 0 || r->segments[s].open)
        return STP_ERR_SEGMENT;
    start = r->segments[s].start;
    len = r->segments[s].end - start;
    for (k = start; k + len < r->used; k++)
        r->df[k] = r->df[k + len];
    r->used -= len;
    r->segments[s].used = 0;
    for (i = 0; i < STP_MAX_SEGMENTS; i++) {
        if (r->segments[i].used && r->segments[i].start >= start + len) {
            r->segments[i].start -= len;
            r->segments[i].end -= len;
        }
    }
    return STP_OK;
}

int stp_segment_visibility(stp_renderer *r, int id, int visible)
{
    int s;
    if (r == 0)
        return STP_ERR_ARG;
    s = find_segment(r, id);
    if (s < 0)
        return STP_ERR_SEGMENT;
    r->segments[s].visible = visible != 0;
    return STP_OK;
}

uint32_t stp_renderer_display_file_used(const stp_renderer *r)
{
    return r->used;
}

uint32_t stp_renderer_polygon_count(const stp_renderer *r)
{
    uint32_t count = 0, k;
    int i;
    for (i = 0; i < STP_MAX_SEGMENTS; i++) {
        const stp_segment *s = &r->segments[i];
        if (!s->used || !s->visible)
            continue;
        for (k = s->start; k < s->end; k++) {
            if (r->df[k].op >= 3) {
                count++;
                k += (uint32_t)r->df[k].op - 1;
            }
        }
    }
    return count;
}

stp_fix stp_renderer_last_shade(const stp_renderer *r)
{
    return r->last_shade;
}

/* ---- transform, clip, project ---- */

#if STP_WITH_SHADOWS
/* Whether a shadow map is set (stp_shadow_any, without the call). */
static int shadows_on(const stp_renderer *r)
{
    return r->shadow_set != 0;
}
#endif

static void world_to_view(const stp_renderer *r, stp_vec3 p, stp_vec3 *out)
{
    stp_view_transform_point(&r->to_view, p, out);
}

/* Forget every cached vertex (the view or the model transform changed). */
static void cache_forget(stp_renderer *r)
{
#if STP_VERTEX_CACHE
    int i;
#endif
    r->frame_valid = 0; /* the model frame too */
    r->model_route_ok = 0;
#if STP_VERTEX_CACHE
    if (++r->cache_stamp == 0) {
        /* wrapped: clear the entries so an old stamp cannot match */
        for (i = 0; i < STP_VERTEX_CACHE; i++)
            r->cache[i].stamp = 0;
        r->cache_stamp = 1;
    }
#endif
}

/* An entered point (model coordinates) to view coordinates by the
 * geometry stage; a point the model transform saturated comes out
 * saturated too (see stp_view_saturated).  In line where the caller has
 * the point's address (cache_fill: a call took the point apart). */
STP_HOT_INLINE void vertex_at_view(const stp_renderer *r, const stp_vec3 *p, stp_vec3 *out)
{
    if (stp_render_point_at_view(r, p, out))
        out->x = STP_FIX_MAX;
}

/* vertex_at_view of a point passed by value, a call */
static void vertex_to_view(const stp_renderer *r, stp_vec3 p, stp_vec3 *out)
{
    vertex_at_view(r, &p, out);
}

#if STP_COMPACT_COMPOSE
/* The view transform alone as the compact form's composition with the
 * identity (view.c's compose_compact: its eye terms rounded as direct
 * drawing's), where that applies; else the view transform itself */
static void view_only(stp_renderer *r)
{
    stp_transform identity;
    stp_transform_identity(&identity);
    if (!stp_view_transform_compose(&r->to_view, &identity, &r->point_view))
        r->point_view = r->to_view;
}
#else
/* The view transform alone */
static void view_only(stp_renderer *r)
{
    r->point_view = r->to_view;
}
#endif

void stp_render_geometry_update(stp_renderer *r)
{
    if (!r->model_on) {
        r->geometry = STP_GEOMETRY_VIEW;
        view_only(r);
    } else if (stp_view_transform_compose(&r->to_view, &r->model, &r->point_view)) {
        r->geometry = STP_GEOMETRY_COMPOSED;
    } else {
        r->geometry = STP_GEOMETRY_TWO_STEPS;
    }
}


int stp_renderer_set_transform(stp_renderer *r, const stp_transform *t)
{
    int i, j, identity = 1;
    if (r == 0)
        return STP_ERR_ARG;
    if (r->open_segment < 0)
        return STP_ERR_NO_SEGMENT;
    cache_forget(r);
    if (t == 0) {
        r->model_on = 0;
        stp_render_geometry_update(r);
        return STP_OK;
    }
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++)
            identity &= t->m[i][j] == (i == j ? ONE : 0);
    r->model = *t;
    r->model_on = !(identity && t->t.x == 0 && t->t.y == 0 && t->t.z == 0);
    stp_render_geometry_update(r);
    return STP_OK;
}

#if STP_WITH_LINES
/* The volume lines are clipped to: the picture's own, also with the guard
 * band (project_private.h), which only polygons take (the line raster
 * draws from clipped ends): r's clip volume, or with the guard band the
 * picture's in *picture. */
static const stp_clip_volume *line_volume(const stp_renderer *r, stp_clip_volume *picture)
{
#if STP_GUARD_BAND
    *picture = r->clip_volume;
    picture->width = r->width;
    picture->height = r->height;
    return picture;
#else
    (void)picture;
    return &r->clip_volume;
#endif
}

static stp_vec3 clip_point(stp_vec3 a, stp_vec3 b, int64_t da, int64_t db)
{
    int64_t t = stp_clip_fraction(da, db);
    stp_vec3 p;
    p.x = stp_lerp_fix(a.x, b.x, t);
    p.y = stp_lerp_fix(a.y, b.y, t);
    p.z = stp_lerp_fix(a.z, b.z, t);
    return p;
}
#endif

/* Sutherland-Hodgman against the five planes (clip.c) from clip_a; returns
 * the vertex count of the clipped polygon, its vertices in *result (and,
 * when smooth, its vertex shades in *shades, interpolated like the
 * positions). */
static int clip_polygon(stp_renderer *r, int n, int smooth, stp_vec3 **result, stp_fix **shades)
{
    stp_vec3 *spare;
    stp_fix *sa = 0, *sb = 0;
#if STP_WITH_GOURAUD
    if (smooth) {
        sa = r->shade_a;
        sb = r->shade_b;
    }
#else
    (void)smooth;
#endif
    return stp_clip_polygon(&r->clip_volume, r->clip_a, r->clip_b, sa, sb, n, result, &spare,
                            shades);
}

/* Device coordinates (Q27.4) and depth key of a clipped view point: the
 * one perspective projection (view.c), or the parallel one. */
static void project(const stp_renderer *r, stp_vec3 p, stp_instr *out)
{
    int64_t x, y, wq, hq, gx, gy;
    if (r->projection == STP_PERSPECTIVE) {
        stp_view_lens lens;
        int32_t d[3];
        /* width, height <= 32767 (stp_renderer_create) */
        stp_view_lens_make(&lens, r->focal, r->hither, r->width, r->height);
        stp_view_perspective_device(&lens, &p, d);
        out->x = d[0];
        out->y = d[1];
        out->z = d[2];
        return;
    }
    wq = (int64_t)r->width << STP_SUBPIXEL_BITS;
    hq = (int64_t)r->height << STP_SUBPIXEL_BITS;
    x = wq / 2 + stp_asr64((int64_t)r->focal * p.x, 2 * F - STP_SUBPIXEL_BITS);
    y = hq / 2 - stp_asr64((int64_t)r->focal * p.y, 2 * F - STP_SUBPIXEL_BITS);
    out->z = -p.z;
    /* the clipper keeps points inside up to rounding: clamp the last bit
     * (to the picture and its guard band, project_private.h) */
    gx = stp_guard_subpixels(r->width);
    gy = stp_guard_subpixels(r->height);
    out->x = (int32_t)(x < -gx ? -gx : (x > wq + gx ? wq + gx : x));
    out->y = (int32_t)(y < -gy ? -gy : (y > hq + gy ? hq + gy : y));
}

static inline int check_open(stp_renderer *r)
{
    if (r == 0)
        return STP_ERR_ARG;
    return r->open_segment < 0 ? open_implicit_segment(r) : STP_OK;
}

int stp_render_check_open(stp_renderer *r)
{
    return check_open(r);
}

void stp_render_project(const stp_renderer *r, stp_vec3 p, stp_instr *out)
{
    project(r, p, out);
}

/* The index of the first pixel centre at or right of the crossing the
 * rasters draw from an edge accumulator at a row centre (stp_tri_edge_x:
 * floor(acc / 2^16), the accumulator's value within (-2^14, 2^30 + 2^20):
 * 2^16 times a point between the edge's ends less below yc - ya < 2^14
 * for the slope's truncation): floor((floor(acc / 2^16) + 7) / 16) =
 * floor((acc + 7 2^16) / 2^20), the sum positive and below 2^31. */
static inline uint32_t centre_index(uint32_t acc)
{
    return (acc + ((uint32_t)(STP_HALF_PIXEL - 1) << 16)) >> 20;
}

/* Whether a row centre 16 r + 8, row <= r < end, has a pixel centre
 * between the crossings of the long edge (accumulator *acc at row, step
 * 16 slopes) and the short edge a - b (a->y <= the centres < b->y, x
 * below 2^14): the rasters' accumulators (stp_edge_acc_short), each
 * stepped by 16 slopes modulo 2^32 as the triangle walk steps them (the
 * value formed at that row).  *acc is left at end. */
static inline int half_reached(uint32_t *acc, uint32_t step, const stp_instr *a, const stp_instr *b, int32_t row,
                               int32_t end)
{
    int32_t slope;
    uint32_t left = *acc, right = stp_edge_acc_short(a, b, row * 16 + STP_HALF_PIXEL, &slope);
    for (; row < end; row++) {
        /* centres [x_left, x_right) drawn: pixels [index(left), index(right)) */
        if (centre_index(left) != centre_index(right))
            return 1;
        left += step;
        right += (uint32_t)slope * 16u;
    }
    *acc = left;
    return 0;
}

int stp_render_centre_reached(int32_t x0, int32_t y0, int32_t x1, int32_t y1, int32_t x2, int32_t y2)
{
    stp_instr v[3];
    const stp_instr *top, *mid, *bot;
    int32_t row, row_mid, end, slope;
    uint32_t acc;
    if ((uint32_t)(x0 | x1 | x2) >> 14)
        return 1; /* not narrow: kept untested */
    /* (the area's magnitude: any vertex order) */
    if (!STP_CENTRE_GATE_INLINE && !stp_render_thin(x0, y0, x1, y1, x2, y2))
        return 1; /* not tested (the caller's gate, here on 32-bit targets) */
    /* the raster's vertex order and edges (edge_walk_private.h) */
    v[0].x = x0;
    v[0].y = y0;
    v[1].x = x1;
    v[1].y = y1;
    v[2].x = x2;
    v[2].y = y2;
    stp_tri_sort(&v[0], &v[1], &v[2], &top, &mid, &bot);
    /* the rows whose centre lies in [top, mid), then [mid, bottom) */
    row = (top->y + STP_HALF_PIXEL - 1) >> STP_SUBPIXEL_BITS; /* a floor (stp_row_below) */
    row_mid = (mid->y + STP_HALF_PIXEL - 1) >> STP_SUBPIXEL_BITS;
    end = (bot->y + STP_HALF_PIXEL - 1) >> STP_SUBPIXEL_BITS;
    if (row == end)
        return 0;
    acc = stp_edge_acc_short(top, bot, row * 16 + STP_HALF_PIXEL, &slope);
    if (row < row_mid && half_reached(&acc, (uint32_t)slope * 16u, top, mid, row, row_mid))
        return 1;
    return row_mid < end && half_reached(&acc, (uint32_t)slope * 16u, mid, bot, row_mid, end);
}

/* ---- the face stage (render_private.h): shared with mesh.c ---- */

static void newell_sum(const stp_vec3 *v, int n, int64_t *na, int64_t *nb, int64_t *nc);

int stp_render_model_normal(const stp_vec3 *v, int n, int16_t out[3])
{
    int64_t a, b, c;
    if (n == 3)
        return stp_render_triangle_normal(v, out);
    newell_sum(v, n, &a, &b, &c);
    return stp_render_unit_q14(a, b, c, out);
}

/* r->frame for the transforms in force (once after either changes). */
STP_NOINLINE void model_frame_prepare(stp_renderer *r)
{
    if (r->projection != STP_PERSPECTIVE)
        r->frame.usable = 0;
    else
        (void)stp_model_frame_make(&r->to_view, r->from, r->model_on ? &r->model : 0, &r->frame);
    r->frame_valid = 1;
}

/* stp_render_model_frame, inline for a polygon's entry */
STP_HOT_INLINE const stp_model_frame *model_frame(stp_renderer *r)
{
    if (!r->frame_valid)
        model_frame_prepare(r);
    return r->frame.usable ? &r->frame : 0;
}

const stp_model_frame *stp_render_model_frame(stp_renderer *r)
{
    return model_frame(r);
}

void stp_render_face_shader_prepare(stp_renderer *r, int parallel)
{
    /* the eye at the view's origin; parallel: towards it along -z */
    stp_vec3 origin = {0, 0, 0}, towards_eye = {0, 0, -ONE};
    stp_shade_fast_prepare(&r->fast_shade, &r->segment_lighting, &r->material, origin, parallel,
                           towards_eye);
    r->fast_shade_valid = 1;
    r->fast_shade_parallel = parallel;
}

static void append(stp_renderer *r, int32_t op, int32_t x, int32_t y, int32_t z, int32_t shade)
{
    stp_instr *in = &r->df[r->used++];
    in->op = op;
    in->x = x;
    in->y = y;
    in->z = z;
#if STP_WITH_GOURAUD
    in->shade = shade;
#else
    (void)shade;
#endif
    r->segments[r->open_segment].end = r->used;
}

int stp_renderer_move(stp_renderer *r, stp_vec3 p)
{
    stp_vec3 q;
    int status = check_open(r);
    if (status != STP_OK)
        return status;
    vertex_to_view(r, p, &q);
    if (stp_view_saturated(q))
        return STP_ERR_RANGE;
    r->pen = q;
    r->pen_valid = 1;
    return STP_OK;
}

int stp_renderer_line(stp_renderer *r, stp_vec3 p)
{
#if STP_WITH_LINES
    stp_vec3 a, b, q;
    stp_instr pa, pb;
    stp_clip_volume picture;
    const stp_clip_volume *volume;
    int plane, status = check_open(r);
    if (status != STP_OK)
        return status;
    volume = line_volume(r, &picture);
    vertex_to_view(r, p, &q);
    if (stp_view_saturated(q))
        return STP_ERR_RANGE;
    if (!r->pen_valid) {
        r->pen = q;
        r->pen_valid = 1;
        return STP_OK;
    }
    a = r->pen;
    b = q;
    r->pen = q;
    for (plane = 0; plane < 5; plane++) {
        int64_t da = stp_clip_distance(volume, plane, a), db = stp_clip_distance(volume, plane, b);
        if (da < 0 && db < 0)
            return STP_OK; /* wholly outside */
        if (da < 0)
            a = clip_point(b, a, db, da);
        else if (db < 0)
            b = clip_point(a, b, da, db);
    }
    if (r->capacity - r->used < 2u + (r->current_line_style != r->fill_style ? 1u : 0u))
        return STP_ERR_FULL;
    if (r->current_line_style != r->fill_style) {
        append(r, STP_OP_LINE_STYLE, r->fill_style, 0, 0, -1);
        r->current_line_style = r->fill_style;
    }
    project(r, a, &pa);
    project(r, b, &pb);
    append(r, STP_OP_MOVE, pa.x, pa.y, pa.z, -1);
    append(r, STP_OP_LINE, pb.x, pb.y, pb.z, -1);
    return STP_OK;
#else
    (void)r;
    (void)p;
    return STP_ERR_UNSUPPORTED;
#endif
}

/* How a polygon's shade is found (DISPLAY-FILE-ENTER's SHADE-CHECK). */
typedef enum stp_enter_shading {
    STP_ENTER_FLAT = 0,           /* one shade, at the vertex average */
    STP_ENTER_SMOOTH_NORMALS = 1, /* a shade per vertex from its own normal */
    STP_ENTER_SMOOTH_SHADES = 2   /* per-vertex shades given by the caller */
} stp_enter_shading;

/* Which side of a polygon the eye sees, when known before the transform. */
typedef enum stp_face {
    STP_FACE_UNKNOWN = 0,
    STP_FACE_FRONT = 1,
    STP_FACE_BACK = 2
} stp_face;

/* What entering one polygon finds out about it, step by step. */
typedef struct stp_entry {
    int n;                      /* vertices, in r->clip_a (view coordinates) */
    stp_face face;              /* from world_facing, or STP_FACE_UNKNOWN */
    stp_enter_shading shading;
    const stp_vec3 *normals;    /* STP_ENTER_SMOOTH_NORMALS: world normals */
    const stp_fix *shades;      /* STP_ENTER_SMOOTH_SHADES: the caller's */
    int range;                  /* a vertex's view coordinates saturated */
    unsigned outside_all;       /* clip planes every vertex is outside of */
    unsigned outside_any;       /* clip planes some vertex is outside of */
    int64_t nx, ny, nz;         /* Newell normal, not normalised */
    stp_vec3 centre;            /* vertex average */
    int facing;                 /* sign of N.E: > 0 front, < 0 back, 0 edge-on */
    stp_unit3 normal, eye_dir;  /* unit N (turned to the eye) and E */
    int32_t n_dot_e;            /* STP_UNIT, >= 0 */
    int style;
    int32_t colour;
    stp_fix transmission;
    const stp_instr *projected; /* an unclipped polygon's device vertices, or NULL */
#if STP_VERTEX_CACHE
    stp_vertex_entry *entry[3]; /* a triangle's cache entries (r->cached[] as
                                   pointers, NULL outside), when not STP_SIZE_BUILD */
#endif
} stp_entry;

/* A build for size: a triangle's steps are not unrolled apart. */
#if defined(__OPTIMIZE_SIZE__)
#define STP_SIZE_BUILD 1
#else
#define STP_SIZE_BUILD 0
#endif

#if STP_VERTEX_CACHE
/* log2 STP_VERTEX_CACHE (a power of two up to 4096: config.h) */
#define STP_CACHE_BITS                                                                                   \
    (STP_VERTEX_CACHE >= 4096 ? 12 : STP_VERTEX_CACHE >= 2048 ? 11 : STP_VERTEX_CACHE >= 1024 ? 10 :       \
     STP_VERTEX_CACHE >= 512 ? 9 : STP_VERTEX_CACHE >= 256 ? 8 : STP_VERTEX_CACHE >= 128 ? 7 :             \
     STP_VERTEX_CACHE >= 64 ? 6 : STP_VERTEX_CACHE >= 32 ? 5 : STP_VERTEX_CACHE >= 16 ? 4 :                 \
     STP_VERTEX_CACHE >= 8 ? 3 : STP_VERTEX_CACHE >= 4 ? 2 : 1)

/* A miss of cache_vertex: point p to view coordinates and its outcode,
 * into entry c (slot) unless this polygon's vertex i - 1 or earlier holds
 * it (then p stays outside the cache, its view point in r->clip_a[i]).
 * Returns the outcode, the entry taken (or NULL) in *entry.  Out of line:
 * a miss is the rarer case. */
STP_NOINLINE unsigned cache_fill(stp_renderer *r, stp_vertex_entry *c, uint32_t slot, const stp_vec3 *p,
                                 int i, uint16_t serial, stp_vertex_entry **entry)
{
    unsigned code;
    int held = c->used_by == serial; /* the slot holds an earlier vertex of this polygon */
    stp_vec3 *view = held ? &r->clip_a[i] : &c->view;
    vertex_at_view(r, p, view);
#if STP_NARROW_FORMS
    code = stp_view_saturated(*view) ? STP_CODE_RANGE : stp_clip_outcode(&r->clip_volume, *view);
#else
    /* stp_clip_outcode's planes in line (the 32-bit targets' shorter
     * test first stays a call) */
    code = stp_view_saturated(*view) ? STP_CODE_RANGE : stp_clip_outcode_planes(&r->clip_volume, *view);
#endif
    if (held) {
        r->cached[i] = (uint16_t)STP_CACHE_NONE;
        *entry = 0;
        return code;
    }
    c->stamp = r->cache_stamp;
    c->point = *p;
    c->code = (int16_t)code;
    c->dx = STP_CACHE_NOT_PROJECTED;
    c->used_by = serial;
    r->clip_a[i] = c->view;
    r->cached[i] = (uint16_t)slot;
    *entry = c;
    return code;
}

/* Vertex i of the polygon being entered (serial), point p, through the
 * vertex cache: its view point in r->clip_a[i], its entry in *entry
 * (NULL outside) and, unless cached is NULL, r->cached[i] (a miss sets it
 * either way); returns its outcode. */
STP_HOT_INLINE unsigned cache_vertex(stp_renderer *r, const stp_vec3 *p, int i, uint16_t serial, uint32_t hash,
                                     uint32_t stamp, stp_vertex_entry *cache, stp_vec3 *view_out,
                                     uint16_t *cached, stp_vertex_entry **entry)
{
    /* the coordinates as scalars: a copy of the point is taken only by a
     * miss */
    const stp_fix px = p->x, py = p->y, pz = p->z;
    /* a multiplicative hash of the exact coordinates, rotated apart and
     * mixed by one product; the slot is the product's top bits, one shift
     * (the bits 0..20 folded before took three: torus 128x64, host 0.812
     * -> 0.809 M instructions a frame, Cortex-M0+ 1 687 040 -> 1 687 000).
     * With up to 64 entries uz >> 10 stands for uz rotated left by 22, one
     * shift (ARMv6-M has no rotation by an immediate count): its low bits
     * are below a 64th of a unit */
    uint32_t ux = (uint32_t)px, uy = (uint32_t)py, uz = (uint32_t)pz;
    uint32_t rz = STP_VERTEX_CACHE <= 64 ? uz >> 10 : (uz << 22) | (uz >> 10);
    uint32_t h = (ux ^ ((uy << 11) | (uy >> 21)) ^ rz) * hash;
    uint32_t slot = STP_VERTEX_CACHE == 1 ? 0 : h >> (32 - STP_CACHE_BITS);
    stp_vertex_entry *c = &cache[slot];
    if (c->stamp != stamp || c->point.x != px || c->point.y != py || c->point.z != pz)
        return cache_fill(r, c, slot, p, i, serial, entry);
    c->used_by = serial;
    view_out[i] = c->view;
    if (cached)
        cached[i] = (uint16_t)slot;
    *entry = c;
    return (unsigned)c->code;
}
#endif

/* Step 1: the vertices to view coordinates (r->clip_a), through the
 * vertex cache when there is one, and whether one of them saturated.  A
 * cache entry this polygon already holds is never taken by a later vertex
 * of it (that vertex stays outside the cache), so r->cached[] stays valid
 * until the polygon is stored.  With the cache each entry's outcode is
 * found with its view coordinates (a later polygon sharing the vertex is
 * likely to face the eye and need it), so the polygon's outcodes are
 * known here.  A triangle's three vertices are taken in line, apart from
 * the loop, their entries in e->entry[]; slots 0 leaves r->cached[] unset
 * on a hit, for a caller reading e->entry[] alone. */
STP_HOT_INLINE void enter_transform_n(stp_renderer *r, const stp_vec3 *vertices, stp_entry *e, const int n,
                                      const int slots)
{
    int i;
    unsigned range = 0;
#if STP_VERTEX_CACHE
    const uint16_t serial = ++r->cache_polygon; /* wraps: a stale match only skips the cache */
    /* on ARMv6-M the multiplier STP_CACHE_HASH is read from the state,
     * where the compiler cannot see it: gcc expands a constant product
     * into 14 shifts and additions there, one MULS otherwise */
#if STP_NARROW_FORMS
    const uint32_t hash = r->cache_hash;
#else
    const uint32_t hash = STP_CACHE_HASH; /* a constant: one instruction fewer on the host */
#endif
    /* locals: the stores may alias r's fields for the compiler */
    const uint32_t stamp = r->cache_stamp;
    stp_vertex_entry *const cache = r->cache;
    stp_vec3 *const view_out = r->clip_a;
    uint16_t *const cached = slots ? r->cached : 0;
    unsigned all, any;
    if (n == 3 && !STP_SIZE_BUILD) {
        unsigned c0 = cache_vertex(r, &vertices[0], 0, serial, hash, stamp, cache, view_out, cached, &e->entry[0]);
        unsigned c1 = cache_vertex(r, &vertices[1], 1, serial, hash, stamp, cache, view_out, cached, &e->entry[1]);
        unsigned c2 = cache_vertex(r, &vertices[2], 2, serial, hash, stamp, cache, view_out, cached, &e->entry[2]);
        all = c0 & c1 & c2;
        any = c0 | c1 | c2;
    } else {
        all = 31u;
        any = 0;
        for (i = 0; i < n; i++) {
            stp_vertex_entry *entry;
            unsigned code = cache_vertex(r, &vertices[i], i, serial, hash, stamp, cache, view_out, cached, &entry);
            all &= code;
            any |= code;
        }
    }
    range = any & STP_CODE_RANGE;
    e->outside_all = all;
    e->outside_any = any;
#else
    (void)slots;
    for (i = 0; i < n; i++) {
        vertex_to_view(r, vertices[i], &r->clip_a[i]);
        range |= (unsigned)stp_view_saturated(r->clip_a[i]);
    }
#endif
    e->range = range != 0;
}

static void enter_transform(stp_renderer *r, const stp_vec3 *vertices, stp_entry *e)
{
    enter_transform_n(r, vertices, e, e->n, 1);
}

#if !STP_VERTEX_CACHE
/* The outcodes of the vertices, so the clipper runs only on polygons that
 * cross a plane (after the back-face test: a removed face needs none; with
 * the cache enter_transform finds them). */
static void enter_outcodes(stp_renderer *r, stp_entry *e)
{
    int i;
    e->outside_all = 31u;
    e->outside_any = 0;
    for (i = 0; i < e->n; i++) {
        unsigned code = stp_clip_outcode(&r->clip_volume, r->clip_a[i]);
        e->outside_all &= code;
        e->outside_any |= code;
    }
}
#endif

/* Newell's sum (Algorithm 10.4) of polygon v (n points; right-handed: the
 * normal a counter-clockwise polygon shows), not normalised: relative
 * coordinates cut to 24 bits keep every product < 2^50 and the sum of up
 * to 4096 of them < 2^62; smaller polygons keep all their bits (the shift
 * is that of the largest magnitude, counted up to 2^32). */
static void newell_sum(const stp_vec3 *v, int n, int64_t *na, int64_t *nb, int64_t *nc)
{
    int64_t a = 0, b = 0, c = 0, div;
    uint64_t spread = 0;
    int i, bits, shift;
    for (i = 1; i < n; i++) {
        int64_t dx = (int64_t)v[i].x - v[0].x, dy = (int64_t)v[i].y - v[0].y,
                dz = (int64_t)v[i].z - v[0].z;
        spread |= (uint64_t)(dx < 0 ? -dx : dx) | (uint64_t)(dy < 0 ? -dy : dy) |
                  (uint64_t)(dz < 0 ? -dz : dz);
    }
    bits = stp_bit_length64(spread);
    shift = (bits > 32 ? 32 : bits) - 24;
    if (shift < 0)
        shift = 0;
    div = (int64_t)1 << shift;
    for (i = 0; i < n; i++) {
        int p = i == 0 ? n - 1 : i - 1;
        int64_t xp = ((int64_t)v[p].x - v[0].x) / div, yp = ((int64_t)v[p].y - v[0].y) / div,
                zp = ((int64_t)v[p].z - v[0].z) / div;
        int64_t x = ((int64_t)v[i].x - v[0].x) / div, y = ((int64_t)v[i].y - v[0].y) / div,
                z = ((int64_t)v[i].z - v[0].z) / div;
        a += (yp - y) * (zp + z);
        b += (zp - z) * (xp + x);
        c += (xp - x) * (yp + y);
    }
    *na = a;
    *nb = b;
    *nc = c;
}

/* The vertex average of polygon v (n points), each coordinate's sum
 * divided by n truncated toward zero (both routes' face centre). */
static stp_vec3 vertex_average(const stp_vec3 *v, int n)
{
    int64_t sx = 0, sy = 0, sz = 0;
    stp_vec3 out;
    int i;
    for (i = 0; i < n; i++) {
        sx += v[i].x;
        sy += v[i].y;
        sz += v[i].z;
    }
    if (!WIDE_DIVISION && n == 3 && sx >= INT32_MIN && sx <= INT32_MAX && sy >= INT32_MIN &&
        sy <= INT32_MAX && sz >= INT32_MIN && sz <= INT32_MAX) {
        /* the same truncated quotients without a division (a library
         * call per coordinate where 32-bit division is one) */
        out.x = (stp_fix)stp_div3_toward_zero((int32_t)sx);
        out.y = (stp_fix)stp_div3_toward_zero((int32_t)sy);
        out.z = (stp_fix)stp_div3_toward_zero((int32_t)sz);
    } else {
        out.x = (stp_fix)(sx / n);
        out.y = (stp_fix)(sy / n);
        out.z = (stp_fix)(sz / n);
    }
    return out;
}

/* Newell normal (Algorithm 10.4) of the view-space vertices in clip_a,
 * not normalised (components below 2^62), and their average.  Returns 0 for
 * a zero normal.  For a triangle Newell's sum is the cross product
 * (v1 - v0) x (v2 - v0) exactly, which is formed directly. */
static int newell(const stp_renderer *r, stp_entry *e)
{
    const stp_vec3 *v = r->clip_a;
    const int n = e->n;
    int64_t a = 0, b = 0, c = 0, div;
    uint64_t spread = 0; /* the relative coordinates' magnitudes ORed */
    int bits;
    if (n == 3) {
        int64_t x1 = (int64_t)v[1].x - v[0].x, y1 = (int64_t)v[1].y - v[0].y,
                z1 = (int64_t)v[1].z - v[0].z;
        int64_t x2 = (int64_t)v[2].x - v[0].x, y2 = (int64_t)v[2].y - v[0].y,
                z2 = (int64_t)v[2].z - v[0].z;
        spread = (uint64_t)(x1 < 0 ? -x1 : x1) | (uint64_t)(y1 < 0 ? -y1 : y1) |
                 (uint64_t)(z1 < 0 ? -z1 : z1) | (uint64_t)(x2 < 0 ? -x2 : x2) |
                 (uint64_t)(y2 < 0 ? -y2 : y2) | (uint64_t)(z2 < 0 ? -z2 : z2);
        /* below 2^24 every product is < 2^49 (see below) */
        if (spread >= ((uint64_t)1 << 24)) {
            bits = stp_bit_length64(spread);
            div = (int64_t)1 << ((bits > 32 ? 32 : bits) - 24);
            x1 /= div;
            y1 /= div;
            z1 /= div;
            x2 /= div;
            y2 /= div;
            z2 /= div;
        }
#if !STP_WIDE_ARITH
        if (spread < ((uint64_t)1 << 15)) {
            /* differences below 2^15 (half a unit, a mesh's triangle):
             * products below 2^30 and their differences below 2^31 in
             * int32, without the 64-bit multiply library call */
            a = (int32_t)y1 * (int32_t)z2 - (int32_t)z1 * (int32_t)y2;
            b = (int32_t)z1 * (int32_t)x2 - (int32_t)x1 * (int32_t)z2;
            c = (int32_t)x1 * (int32_t)y2 - (int32_t)y1 * (int32_t)x2;
        } else
#endif
        {
            a = y1 * z2 - z1 * y2;
            b = z1 * x2 - x1 * z2;
            c = x1 * y2 - y1 * x2;
        }
    } else {
        newell_sum(v, n, &a, &b, &c);
    }
    /* the view system is left-handed: Newell's sum, written for right-handed
     * coordinates, points the other way there */
    e->nx = -a;
    e->ny = -b;
    e->nz = -c;
    if (a == 0 && b == 0 && c == 0)
        return 0;
    e->centre = vertex_average(v, n);
    return 1;
}

/* Step 2: the normal, and which side of the polygon the eye sees, by the
 * sign of N.(eye - centre) in integers: nothing is normalised for a back
 * face that back-face removal drops.  Returns STP_OK, STP_ERR_DEGENERATE (a
 * zero normal) or 1 (a back face removed). */
static int enter_unit_vectors(stp_renderer *r, stp_entry *e);
static int enter_facing(stp_renderer *r, stp_entry *e)
{
    int64_t nx, ny, nz, side;
    int bits;
    if (!newell(r, e))
        return STP_ERR_DEGENERATE;
    if (e->face == STP_FACE_FRONT) {
        e->facing = 1; /* world_facing's exact sign */
        return enter_unit_vectors(r, e);
    }
    /* N cut to 30 bits, so each product with a coordinate is < 2^61 */
    {
        uint64_t ax = (uint64_t)(e->nx < 0 ? -e->nx : e->nx), ay = (uint64_t)(e->ny < 0 ? -e->ny : e->ny),
                 az = (uint64_t)(e->nz < 0 ? -e->nz : e->nz);
        uint64_t big = ax > ay ? ax : ay;
        bits = stp_bit_length64(big > az ? big : az) - 30;
    }
    nx = bits > 0 ? stp_asr64(e->nx, bits) : e->nx;
    ny = bits > 0 ? stp_asr64(e->ny, bits) : e->ny;
    nz = bits > 0 ? stp_asr64(e->nz, bits) : e->nz;
    if (r->projection == STP_PERSPECTIVE &&
        (e->centre.x != 0 || e->centre.y != 0 || e->centre.z != 0))
        side = -(nx * e->centre.x + ny * e->centre.y + nz * e->centre.z); /* E ~ -centre */
    else
        side = -nz; /* E = (0, 0, -1): parallel, or the centre at the eye */
    e->facing = side > 0 ? 1 : (side < 0 ? -1 : 0);
    if (e->facing <= 0 && r->backface_removal)
        return 1;
    return enter_unit_vectors(r, e);
}

/* The unit normal (turned to the eye) and eye direction of a polygon whose
 * side is known, and their cosine.  Returns STP_OK. */
static int enter_unit_vectors(stp_renderer *r, stp_entry *e)
{
    (void)stp_unit_from64(e->nx, e->ny, e->nz, &e->normal);
    if (r->projection == STP_PERSPECTIVE) {
        if (stp_unit_from64(-(int64_t)e->centre.x, -(int64_t)e->centre.y, -(int64_t)e->centre.z,
                            &e->eye_dir) == 0) {
            e->eye_dir.x = e->eye_dir.y = 0; /* centre at the eye: clipped anyway */
            e->eye_dir.z = -STP_UNIT_ONE;
        }
    } else {
        e->eye_dir.x = e->eye_dir.y = 0;
        e->eye_dir.z = -STP_UNIT_ONE;
    }
    if (e->facing < 0) {
        /* an open surface seen from behind: shade the side the eye sees */
        e->normal.x = -e->normal.x;
        e->normal.y = -e->normal.y;
        e->normal.z = -e->normal.z;
    }
    /* edge-on, or the centre at the eye: no light reaches the eye from it */
    e->n_dot_e = e->facing == 0 || (r->projection == STP_PERSPECTIVE && e->centre.x == 0 &&
                                    e->centre.y == 0 && e->centre.z == 0)
                     ? 0
                     : stp_unit_dot(e->normal, e->eye_dir);
    if (e->n_dot_e < 0)
        e->n_dot_e = 0;
    return STP_OK;
}

#if STP_WITH_GOURAUD
/* World direction to view coordinates (rotation only). */
static stp_vec3 direction_to_view(const stp_renderer *r, stp_vec3 d)
{
    stp_vec3 out;
    out.x = stp_fix_sat64(stp_asr64((int64_t)d.x * r->right.x + (int64_t)d.y * r->right.y + (int64_t)d.z * r->right.z, F));
    out.y = stp_fix_sat64(stp_asr64((int64_t)d.x * r->up.x + (int64_t)d.y * r->up.y + (int64_t)d.z * r->up.z, F));
    out.z = stp_fix_sat64(stp_asr64((int64_t)d.x * r->forward.x + (int64_t)d.y * r->forward.y + (int64_t)d.z * r->forward.z, F));
    return out;
}

/* The shade of vertex i of a smooth polygon into r->shade_a[i]. */
static void shade_vertex(stp_renderer *r, const stp_entry *e, int i)
{
    stp_fix s = r->last_shade;
    if (e->shading == STP_ENTER_SMOOTH_SHADES) {
        s = stp_fix_clamp(e->shades[i], 0, ONE);
    } else if (r->shading) {
        stp_vec3 face = stp_unit_to_fix(e->normal), vn = face, to_eye, origin = {0, 0, 0};
        stp_vec3 eye = stp_unit_to_fix(e->eye_dir), ev = eye;
        stp_vec3 nw = r->model_on ? stp_transform_direction(&r->model, e->normals[i]) : e->normals[i];
        if (stp_vec3_unity(direction_to_view(r, nw), &vn) == 0) {
            vn = face;
        } else if (stp_vec3_dot(vn, face) < 0) {
            /* turn the vertex normal to the side the face shows: files
             * mix windings, and two-sided faces are seen from either */
            vn.x = -vn.x;
            vn.y = -vn.y;
            vn.z = -vn.z;
        }
        if (r->projection == STP_PERSPECTIVE) {
            to_eye.x = -r->clip_a[i].x;
            to_eye.y = -r->clip_a[i].y;
            to_eye.z = -r->clip_a[i].z;
            if (stp_vec3_unity(to_eye, &ev) == 0)
                ev = eye;
        }
        s = stp_shade_point(&r->segment_lighting, &r->material, vn, r->clip_a[i], origin,
                            r->projection == STP_PARALLEL, ev);
    }
    r->shade_a[i] = s;
}
#endif

/* Step 3: SHADE-CHECK: the polygon's shade (r->last_shade), INTENSITY
 * style and colour, and the vertex shades of a smooth polygon. */
static int enter_shade(stp_renderer *r, stp_entry *e)
{
    e->colour = 0;
    if (r->shading) {
#if STP_WITH_COLOUR
        if (r->colour) {
            stp_vec3 origin = {0, 0, 0};
            stp_fix rgb[3];
            int c;
            stp_shade_point_colour(&r->segment_lighting, &r->material, stp_unit_to_fix(e->normal),
                                   e->centre, origin, r->projection == STP_PARALLEL,
                                   stp_unit_to_fix(e->eye_dir), rgb);
            r->last_shade = stp_shade_luminance(rgb);
            e->colour = STP_COLOUR_FLAG;
            for (c = 0; c < 3; c++)
                e->colour |= (int32_t)(stp_intensity_index(rgb[c], r->levels) - 1) << (16 - 8 * c);
            e->style = stp_intensity_index(r->last_shade, r->levels);
        } else
#endif
        {
            /* the face stage's shader, on the unit normal (turned to the
             * eye) as Q1.14 */
            int16_t nv[3];
            (void)stp_render_unit_q14(e->normal.x, e->normal.y, e->normal.z, nv);
            e->style = stp_render_face_style(r, stp_render_face_shader(r), nv, e->centre, e->facing);
        }
    } else {
        e->style = stp_render_face_style(r, 0, 0, e->centre, 1);
    }
    if (e->shading != STP_ENTER_FLAT) {
#if STP_WITH_GOURAUD
        int i;
        for (i = 0; i < e->n; i++)
            shade_vertex(r, e, i);
#else
        return STP_ERR_UNSUPPORTED;
#endif
    }
    return STP_OK;
}

/* Step 4: the transmission t of (10.21) and (10.18); 0 when opaque. */
static void enter_transmission(const stp_renderer *r, stp_entry *e)
{
    e->transmission = 0;
#if STP_WITH_TRANSPARENCY
    if (r->t_max > 0 || r->t_min > 0) {
        /* (10.21): t = (t_max - t_min)(N.E)^power + t_min, then (10.18) */
        stp_fix ne = stp_fix_clamp(
            (stp_fix)((e->n_dot_e + ((int32_t)1 << (STP_UNIT_BITS - F - 1))) >> (STP_UNIT_BITS - F)),
            0, ONE);
        stp_fix p = ONE;
        int k;
        for (k = 0; k < r->t_power; k++)
            p = stp_fix_mul(p, ne);
        e->transmission = stp_fix_clamp(
            stp_fix_mul(stp_fix_add(stp_fix_mul(r->t_max - r->t_min, p), r->t_min), r->t_attenuation),
            0, ONE);
    }
#else
    (void)r;
#endif
}

/* Step 5, the attributes: the transparency and shade instructions that
 * changed since the last polygon, appended (capacity checked by
 * enter_store).  Apart from the clipping and the vertices: one job. */
static inline void store_attributes(stp_renderer *r, const stp_entry *e)
{
    if (e->transmission != r->current_transmission) {
        append(r, STP_OP_TRANSPARENCY, e->transmission, 0, 0, -1);
        r->current_transmission = e->transmission;
    }
    if (e->style != r->current_style || e->colour != r->current_colour) {
        append(r, STP_OP_SHADE, e->style, r->last_shade, e->colour, -1);
        r->current_style = e->style;
        r->current_colour = e->colour;
    }
}

#if STP_WITH_SHADOWS
/* Step 5, the shadow records: what the raster needs to re-light a pixel
 * hidden from a light (render.h, STP_OP_LIGHT_TERM), into record; their
 * count, 0 when the polygon needs none.  Apart from enter_store: one job. */
static inline int shadow_records_of(const stp_renderer *r, const stp_entry *e,
                                    stp_instr record[STP_MAX_LIGHTS + 1])
{
    if (r->shading && e->shading != STP_ENTER_SMOOTH_SHADES && shadows_on(r))
        return stp_shadow_records(r, stp_unit_to_fix(e->normal), e->centre, stp_unit_to_fix(e->eye_dir),
                                  e->colour != 0, record);
    return 0;
}

/* The records appended (capacity checked by enter_store), each after the
 * first indexed by its light in r->shadow_record. */
static inline void store_records(stp_renderer *r, const stp_instr *record, int records)
{
    int i;
    for (i = 0; i < records; i++) {
        if (i > 0)
            r->shadow_record[record[i].x & 0xFF] = r->used;
        append(r, STP_OP_LIGHT_TERM, record[i].x, record[i].y, record[i].z, -1);
    }
}
#endif

#if STP_VERTEX_CACHE
/* project_entered_vertex for vertex i's cache entry c (NULL: outside the
 * cache), as enter_transform_n found it for a triangle. */
STP_HOT_INLINE void project_cached_vertex(stp_renderer *r, stp_vertex_entry *c, int i, stp_instr *out)
{
    if (c && c->dx != STP_CACHE_NOT_PROJECTED) {
        out->x = c->dx;
        out->y = c->dy;
        out->z = c->dz;
        return;
    }
    project(r, r->clip_a[i], out);
    if (c) {
        c->dx = out->x;
        c->dy = out->y;
        c->dz = out->z;
    }
}
#endif

/* The device position of vertex i of r->clip_a (inside the view volume),
 * through the vertex cache: each cached vertex projected once. */
STP_HOT_INLINE void project_entered_vertex(stp_renderer *r, int i, stp_instr *out)
{
#if STP_VERTEX_CACHE
    project_cached_vertex(r, r->cached[i] != STP_CACHE_NONE ? &r->cache[r->cached[i]] : 0, i, out);
#else
    project(r, r->clip_a[i], out);
#endif
}

/* The device positions of the first n vertices of r->clip_a. */
static void project_entered(stp_renderer *r, int n, stp_instr *out)
{
    int i;
    for (i = 0; i < n; i++)
        project_entered_vertex(r, i, &out[i]);
}

/* Step 5: clip (only a polygon that crosses a plane), project and store:
 * the attribute instructions that changed, the shadow records, the
 * vertices. */
static int enter_store(stp_renderer *r, stp_entry *e)
{
    stp_vec3 *clipped = r->clip_a;
    stp_fix *clipped_shades = 0;
    stp_instr *out;
    int i, m = e->n, smooth = e->shading != STP_ENTER_FLAT;
    uint32_t attribute;
#if STP_WITH_SHADOWS
    stp_instr record[STP_MAX_LIGHTS + 1];
    int records;
#endif
#if STP_WITH_GOURAUD
    clipped_shades = r->shade_a;
#endif
    if (e->outside_all != 0)
        return STP_OK; /* wholly outside one plane: nothing of it is in view */
    if (e->outside_any != 0)
        m = clip_polygon(r, e->n, smooth, &clipped, &clipped_shades);
    if (m < 3)
        return STP_OK;
    attribute = e->style != r->current_style || e->colour != r->current_colour ? 1u : 0u;
    if (e->transmission != r->current_transmission)
        attribute++;
#if STP_WITH_SHADOWS
    records = shadow_records_of(r, e, record);
    attribute += (uint32_t)records;
#endif
    if (r->capacity - r->used < (uint32_t)m + attribute)
        return STP_ERR_FULL;
    store_attributes(r, e);
#if STP_WITH_SHADOWS
    store_records(r, record, records);
#endif
    /* the vertices straight into the display file (capacity checked) */
    out = &r->df[r->used];
    for (i = 0; i < m; i++) {
        out[i].op = i == 0 ? m : STP_OP_LINE;
#if STP_WITH_GOURAUD
        out[i].shade = smooth ? clipped_shades[i] : -1;
#endif
    }
    if (e->outside_any != 0) {
        for (i = 0; i < m; i++)
            project(r, clipped[i], &out[i]);
    } else if (e->projected) {
        for (i = 0; i < m; i++) { /* enter_model_face projected them */
            out[i].x = e->projected[i].x;
            out[i].y = e->projected[i].y;
            out[i].z = e->projected[i].z;
        }
    } else {
        project_entered(r, m, out); /* the cached ones */
    }
    r->used += (uint32_t)m;
    r->segments[r->open_segment].end = r->used;
    return STP_OK;
}

/* world_facing for a perspective view and a triangle within 2^20 (16
 * units) of the eye in each coordinate, the common case, in fewer steps:
 * with w = v - eye, ((v1 - v0) x (v2 - v0)).(eye - v0) = -w0.(w1 x w2)
 * (the terms with w0 twice vanish).  w + 2^20 is formed mod 2^32 (exact
 * when below 2^21: see near_bias), so w fits int32; |w| <= 2^20: w1 x w2
 * below 2^41, the triple product below 3 2^61, exact.  A zero triple
 * product (edge-on, or a zero normal) is left to the full path.  Returns
 * STP_FACE_UNKNOWN when a coordinate is out of that range. */
static stp_face world_facing_near(const stp_renderer *r, const stp_vec3 *v)
{
    const uint32_t half = (uint32_t)1 << 20;
    uint32_t x1 = (uint32_t)v[1].x - r->near_bias_x, y1 = (uint32_t)v[1].y - r->near_bias_y,
             z1 = (uint32_t)v[1].z - r->near_bias_z;
    uint32_t x2 = (uint32_t)v[2].x - r->near_bias_x, y2 = (uint32_t)v[2].y - r->near_bias_y,
             z2 = (uint32_t)v[2].z - r->near_bias_z;
    uint32_t x0, y0, z0;
    int64_t cx, cy, cz, side;
    if ((x1 | y1 | z1 | x2 | y2 | z2) >= 2 * half || !r->near_ok)
        return STP_FACE_UNKNOWN;
    x0 = (uint32_t)v[0].x - r->near_bias_x;
    y0 = (uint32_t)v[0].y - r->near_bias_y;
    z0 = (uint32_t)v[0].z - r->near_bias_z;
    if ((x0 | y0 | z0) >= 2 * half)
        return STP_FACE_UNKNOWN;
#if !STP_WIDE_ARITH
    {
        /* where 64-bit products are library calls, a small triangle (every
         * edge component within 2^15, half a unit: a mesh's): with d = w - w0, w0.(w1 x w2) = w0.(d1 x d2) (the
         * other terms are perpendicular to w0), d1 x d2 below 2^31 in
         * int32, three 64-bit products instead of nine */
        int32_t ax = (int32_t)(x1 - x0), ay = (int32_t)(y1 - y0), az = (int32_t)(z1 - z0);
        int32_t bx = (int32_t)(x2 - x0), by = (int32_t)(y2 - y0), bz = (int32_t)(z2 - z0);
        const uint32_t edge = (uint32_t)1 << 15;
        if (((uint32_t)ax + edge) < 2 * edge && ((uint32_t)ay + edge) < 2 * edge &&
            ((uint32_t)az + edge) < 2 * edge && ((uint32_t)bx + edge) < 2 * edge &&
            ((uint32_t)by + edge) < 2 * edge && ((uint32_t)bz + edge) < 2 * edge) {
            side = -((int64_t)(ay * bz - az * by) * ((int32_t)x0 - (int32_t)half) +
                     (int64_t)(az * bx - ax * bz) * ((int32_t)y0 - (int32_t)half) +
                     (int64_t)(ax * by - ay * bx) * ((int32_t)z0 - (int32_t)half));
            return side > 0 ? STP_FACE_FRONT : (side < 0 ? STP_FACE_BACK : STP_FACE_UNKNOWN);
        }
    }
#endif
    /* w = u - 2^20 in int32 */
    cx = (int64_t)((int32_t)y1 - (int32_t)half) * ((int32_t)z2 - (int32_t)half) -
         (int64_t)((int32_t)z1 - (int32_t)half) * ((int32_t)y2 - (int32_t)half);
    cy = (int64_t)((int32_t)z1 - (int32_t)half) * ((int32_t)x2 - (int32_t)half) -
         (int64_t)((int32_t)x1 - (int32_t)half) * ((int32_t)z2 - (int32_t)half);
    cz = (int64_t)((int32_t)x1 - (int32_t)half) * ((int32_t)y2 - (int32_t)half) -
         (int64_t)((int32_t)y1 - (int32_t)half) * ((int32_t)x2 - (int32_t)half);
    side = -(cx * ((int32_t)x0 - (int32_t)half) + cy * ((int32_t)y0 - (int32_t)half) +
             cz * ((int32_t)z0 - (int32_t)half));
    return side > 0 ? STP_FACE_FRONT : (side < 0 ? STP_FACE_BACK : STP_FACE_UNKNOWN);
}

/* Back-face removal before any transform, for a triangle entered with no
 * model transform: which side of triangle v (world coordinates) the eye
 * sees, from world_facing_near, else stp_view_triangle_side (view.c, out of
 * line: its 64-bit values would crowd the common case's registers).  The
 * sign is that of the view coordinates' test without their rounding (the
 * view transform is a rotation and a reflection into the left-handed view
 * system).  STP_FACE_BACK includes an edge-on face: the full path drops it
 * too, with STP_OK; STP_FACE_UNKNOWN leaves the decision to the full path. */
static stp_face world_facing(const stp_renderer *r, const stp_vec3 *v)
{
    int side;
    stp_face f = r->projection == STP_PERSPECTIVE ? world_facing_near(r, v) : STP_FACE_UNKNOWN;
    if (f != STP_FACE_UNKNOWN)
        return f;
    side = stp_view_triangle_side(r->from, r->forward, r->projection == STP_PARALLEL, v);
    return side > 0 ? STP_FACE_FRONT : (side < 0 ? STP_FACE_BACK : STP_FACE_UNKNOWN);
}

/* model_route's test, when model_route_ok is clear: sets model_route_ok
 * when it passes. */
STP_NOINLINE int model_route_decide(stp_renderer *r)
{
#if STP_WITH_SHADOWS
    if (shadows_on(r))
        return 0;
#endif
#if STP_WITH_TRANSPARENCY
    if (r->t_max > 0 || r->t_min > 0)
        return 0;
#endif
    if (r->colour || model_frame(r) == 0)
        return 0;
    r->model_route_ok = 1;
    return 1;
}

/* The model frame when a flat polygon takes the face stage's model route
 * (the route of every face stp_renderer_mesh enters without the fallback:
 * a usable model frame, monochrome, no transparency, no shadow map), or
 * NULL.  Known from model_route_ok, one test, while the state they depend
 * on stays (shadow.c clears it when a map is set). */
STP_HOT_INLINE const stp_model_frame *model_route(stp_renderer *r)
{
    if (STP_UNLIKELY(!r->model_route_ok) && !model_route_decide(r))
        return 0;
    return &r->frame;
}

#if STP_NARROW_FORMS
/* The side stp_render_certain_side finds for triangle v, in fewer steps
 * for a small triangle near the eye (the usual): edge components in
 * [1 - 2^15, 2^15] and d = eye - v0 below 2^29 (formed mod 2^32, tested by
 * stp_render_certain_side_int32 on the magnitudes it forms anyway: |eye| <
 * 2^30, so a d that wraps is at least 2^30 from 0; v0 then within 2^30 +
 * 2^29 keeps the edges unwrapped too).  The cross product c
 * (each product in [2^15 - 2^30, 2^30], each component within 2^31 -
 * 2^15) is then exact in int32: stp_render_triangle_cross's value, and
 * stp_render_certain_side's 32-bit test decides the side of the rounded
 * normal where it is certain.  Returns 1 or -1 then (c in c[]), else 0: the
 * caller takes the general path. */
STP_HOT_INLINE int small_triangle_side(const stp_model_frame *f, const stp_vec3 *v, int32_t c[3])
{
    const uint32_t edge = ((uint32_t)1 << 15) - 1u, near = (uint32_t)1 << 29;
    /* the edges plus 2^15 - 1: each below 2^16 when in range */
    uint32_t x1 = (uint32_t)v[1].x - (uint32_t)v[0].x + edge, y1 = (uint32_t)v[1].y - (uint32_t)v[0].y + edge,
             z1 = (uint32_t)v[1].z - (uint32_t)v[0].z + edge;
    uint32_t x2 = (uint32_t)v[2].x - (uint32_t)v[0].x + edge, y2 = (uint32_t)v[2].y - (uint32_t)v[0].y + edge,
             z2 = (uint32_t)v[2].z - (uint32_t)v[0].z + edge;
    int32_t ax, ay, az, bx, by, bz;
    if ((x1 | y1 | z1 | x2 | y2 | z2) > 0xFFFFu)
        return 0;
    ax = (int32_t)x1 - (int32_t)edge;
    ay = (int32_t)y1 - (int32_t)edge;
    az = (int32_t)z1 - (int32_t)edge;
    bx = (int32_t)x2 - (int32_t)edge;
    by = (int32_t)y2 - (int32_t)edge;
    bz = (int32_t)z2 - (int32_t)edge;
    c[0] = ay * bz - az * by;
    c[1] = az * bx - ax * bz;
    c[2] = ax * by - ay * bx;
    return stp_render_certain_side_int32(c[0], c[1], c[2], (int32_t)((uint32_t)f->eye[0] - (uint32_t)v[0].x),
                                         (int32_t)((uint32_t)f->eye[1] - (uint32_t)v[0].y),
                                         (int32_t)((uint32_t)f->eye[2] - (uint32_t)v[0].z), near);
}
#endif

/* The model normal n (Q1.14) of polygon v (e->n points) and the side of
 * it the eye sees (stp_render_face_side); for a triangle with back faces
 * removed the side is found first (stp_render_certain_side), so a certain back face
 * is not normalised: returns 0 for such a face (n unset), 1 otherwise,
 * STP_ERR_DEGENERATE for a zero normal. */
STP_HOT_INLINE int general_normal_and_side(const stp_renderer *r, const stp_vec3 *v, int count,
                                         const stp_model_frame *f, int16_t n[3], int *side)
{
    if (count == 3 && r->backface_removal) {
        int64_t c[3];
        int sure;
#if STP_HAVE_MUL64
        /* the magnitudes once, for the side test and the normal */
        uint64_t c_or;
        stp_render_triangle_cross(v, c);
        c_or = stp_abs64u(c[0]) | stp_abs64u(c[1]) | stp_abs64u(c[2]);
        if (c_or == 0)
            return STP_ERR_DEGENERATE;
        sure = stp_render_certain_side_or(f, c, c_or, v[0]);
        if (sure < 0)
            return 0;
        stp_unit_q14_from64_or(c[0], c[1], c[2], c_or, n);
#else
        stp_render_triangle_cross(v, c);
        if ((c[0] | c[1] | c[2]) == 0)
            return STP_ERR_DEGENERATE;
        sure = stp_render_certain_side(f, c, v[0]);
        if (sure < 0)
            return 0;
        (void)stp_render_unit_q14(c[0], c[1], c[2], n);
#endif
        *side = sure > 0 ? 1 : stp_render_face_side(f, n, v[0]);
        return 1;
    }
    if (!stp_render_model_normal(v, count, n))
        return STP_ERR_DEGENERATE;
    *side = stp_render_face_side(f, n, v[0]);
    return 1;
}

/* general_normal_and_side's result, for a small triangle with back faces
 * removed whose side is certain (small_triangle_side) found directly. */
STP_HOT_INLINE int model_normal_and_side(const stp_renderer *r, const stp_vec3 *v, int count,
                                         const stp_model_frame *f, int16_t n[3], int *side)
{
#if STP_NARROW_FORMS
    if (count == 3 && r->backface_removal) {
        int32_t c[3];
        int sure = small_triangle_side(f, v, c);
        if (sure < 0)
            return 0; /* a back face: not normalised */
        if (sure > 0) {
            /* stp_render_unit_q14's value from the int32 c */
            (void)stp_unit_q14_from32(c[0], c[1], c[2], n);
            *side = 1;
            return 1;
        }
    }
#endif
    return general_normal_and_side(r, v, count, f, n, side);
}

/* One coordinate of a triangle's vertex average (stp_render_average3):
 * where 32 x 32 -> 64 products are library calls and 32-bit ones are not,
 * values below 2^28 (the usual) take mesh entry's 32-bit quotient, tested
 * as each in [-2^27, 2^27), one addition each; a coordinate at a time,
 * fewer values held at once than one test of all nine. */
STP_HOT_INLINE stp_fix centre_coordinate(int32_t a, int32_t b, int32_t c)
{
    const uint32_t half = (uint32_t)1 << 27;
    int small = STP_NARROW_FORMS && (((uint32_t)a + half) | ((uint32_t)b + half) | ((uint32_t)c + half)) < 2 * half;
    return stp_render_average3(small, a, b, c);
}

/* A front triangle inside the view on the model route (enter_model_face,
 * its vertices in r->clip_a and the cache): the face stage's last steps as
 * stp_renderer_mesh takes them (mesh.c's enter_face): projected, left out
 * when it draws nothing, shaded from model normal n, its three records
 * stored (enter_store's, where a transmission instruction is due). */
static int enter_model_triangle(stp_renderer *r, stp_entry *e, const stp_model_frame *f,
                                const int16_t n[3], int side)
{
    stp_instr p[3];
    stp_instr *out;
    stp_vec3 centre;
    int16_t nv[3];
    int style;
#if STP_VERTEX_CACHE && !STP_SIZE_BUILD
    /* the entries enter_transform_n's triangle case found */
    project_cached_vertex(r, e->entry[0], 0, &p[0]);
    project_cached_vertex(r, e->entry[1], 1, &p[1]);
    project_cached_vertex(r, e->entry[2], 2, &p[2]);
#else
    project_entered_vertex(r, 0, &p[0]);
    project_entered_vertex(r, 1, &p[1]);
    project_entered_vertex(r, 2, &p[2]);
#endif
#if STP_WINDING_SIDE
    /* the side by the winding of the projected vertices (render_private.h) */
    side = stp_render_winding_side(p[0].x, p[0].y, p[1].x, p[1].y, p[2].x, p[2].y);
    if (side <= 0 && r->backface_removal)
        return STP_OK; /* a back face removed */
#endif
    if (!stp_render_triangle_shows(r, r->pixel_cull, p[0].x, p[0].y, p[1].x,
                                   p[1].y, p[2].x, p[2].y))
        return STP_OK; /* between two row centres, or pixel culling: draws nothing */
    stp_render_view_normal(f, n, side, nv);
    centre.x = centre_coordinate(r->clip_a[0].x, r->clip_a[1].x, r->clip_a[2].x);
    centre.y = centre_coordinate(r->clip_a[0].y, r->clip_a[1].y, r->clip_a[2].y);
    centre.z = centre_coordinate(r->clip_a[0].z, r->clip_a[1].z, r->clip_a[2].z);
    style = stp_render_face_style(r, r->shading ? stp_render_face_shader(r) : 0, nv, centre, side);
    if (STP_UNLIKELY(r->current_transmission != 0)) {
        e->style = style;
        e->colour = 0;
        e->transmission = 0;
        e->projected = p;
        return enter_store(r, e);
    }
    out = stp_render_triangle_records(r, style);
    if (out == 0)
        return STP_ERR_FULL;
    stp_render_put_vertex(&out[0], 3, p[0].x, p[0].y, p[0].z);
    stp_render_put_vertex(&out[1], STP_OP_LINE, p[1].x, p[1].y, p[1].z);
    stp_render_put_vertex(&out[2], STP_OP_LINE, p[2].x, p[2].y, p[2].z);
    r->segments[r->open_segment].end = r->used;
    return STP_OK;
}

/* The front (or two-sided) flat polygon of enter_model_face with model
 * normal n and side: transformed, clipped, shaded and stored.  In line:
 * the back-face test before it already saves every register it takes
 * (measured, torus 128x64: host 0.995 -> 0.978 M instructions, Cortex-M0+
 * 1 893 840 -> 1 880 160, against a call of its own); a call in a build
 * for size (the smaller code: 64 to 84 bytes on the Cortex-M0+ images). */
#if STP_SIZE_BUILD
#define STP_FRONT_INLINE STP_NOINLINE
#else
#define STP_FRONT_INLINE STP_HOT_INLINE
#endif
STP_FRONT_INLINE int enter_model_front(stp_renderer *r, const stp_vec3 *vertices, int count,
                                     const stp_model_frame *f, const int16_t n[3], int side)
{
    stp_entry e;
    int16_t nv[3];
    e.n = count;
    e.shading = STP_ENTER_FLAT;
    e.projected = 0;
    if (count == 3 && !STP_SIZE_BUILD)
        /* a triangle's: unrolled; its entries in e.entry[], r->cached[]
         * left as it is (enter_model_triangle and enter_store's clipped
         * and projected paths do not read it) */
        enter_transform_n(r, vertices, &e, 3, 0);
    else
        enter_transform(r, vertices, &e);
    if (e.range)
        return STP_ERR_RANGE;
#if !STP_VERTEX_CACHE
    enter_outcodes(r, &e);
#endif
    if (e.outside_all != 0)
        return STP_OK; /* wholly outside one plane: not shaded */
    if (count == 3 && e.outside_any == 0)
        return enter_model_triangle(r, &e, f, n, side);
#if STP_WINDING_SIDE
    if (count == 3 && r->backface_removal) {
        /* a triangle the clipper cuts (its side not yet found:
         * enter_model_face): the exact side */
        side = stp_render_face_side(f, n, vertices[0]);
        if (side <= 0)
            return STP_OK;
    }
#endif
    stp_render_view_normal(f, n, side, nv);
    e.style = stp_render_face_style(r, r->shading ? stp_render_face_shader(r) : 0, nv,
                                    vertex_average(r->clip_a, count), side);
    e.colour = 0;
    e.transmission = 0;
    return enter_store(r, &e);
}

/* DISPLAY-FILE-ENTER of a flat polygon on the model route: the face
 * stage's normal (of the entered points), side, view normal and shade, as
 * stp_renderer_mesh enters a triangle; then clip, project and store.  A
 * back face removed is not transformed. */
static int enter_model_face(stp_renderer *r, const stp_vec3 *vertices, int count,
                            const stp_model_frame *f)
{
    int16_t n[3];
    int side = 0, found;
#if STP_WINDING_SIDE
    if (count == 3 && r->backface_removal) {
        /* a triangle's side found later: by its winding once projected
         * (enter_model_triangle), or the exact one where the clipper cuts
         * it (enter_model_front) */
        if (!stp_render_model_normal(vertices, 3, n))
            return STP_ERR_DEGENERATE;
        return enter_model_front(r, vertices, 3, f, n, 0);
    }
#endif
    found = model_normal_and_side(r, vertices, count, f, n, &side);
    if (found != 1)
        return found == 0 ? STP_OK : found;
    if (side <= 0 && r->backface_removal)
        return STP_OK;
    return enter_model_front(r, vertices, count, f, n, side);
}

/* DISPLAY-FILE-ENTER of a polygon off the model route: the steps above
 * in order.  A call of its own, apart from the model route's. */
STP_NOINLINE int enter_view_polygon(stp_renderer *r, const stp_vec3 *vertices, int n,
                                    stp_enter_shading shading, const stp_vec3 *normals,
                                    const stp_fix *shades)
{
    stp_entry e;
    int status;
    e.n = n;
    e.shading = shading;
    e.normals = normals;
    e.projected = 0;
    e.shades = shades;
    /* off the model route, a triangle's side is known before the transform
     * when back faces are removed and there is no model transform */
    e.face = n == 3 && r->backface_removal && !r->model_on ? world_facing(r, vertices)
                                                           : STP_FACE_UNKNOWN;
    if (e.face == STP_FACE_BACK)
        return STP_OK;
    enter_transform(r, vertices, &e);
    if (e.range)
        return STP_ERR_RANGE;
    status = enter_facing(r, &e);
    if (status != STP_OK)
        return status == 1 ? STP_OK : status;
    status = enter_shade(r, &e);
    if (status != STP_OK)
        return status;
    enter_transmission(r, &e);
#if !STP_VERTEX_CACHE
    enter_outcodes(r, &e);
#endif
    return enter_store(r, &e);
}

/* DISPLAY-FILE-ENTER of a polygon: the checks, then the model route
 * (enter_model_face: no shadow map is set there) or the view route, after
 * which every polygon entered casts into the maps, in view or not, back
 * face or not (render.h). */
STP_HOT_INLINE int enter_polygon(stp_renderer *r, const stp_vec3 *vertices, int n,
                                 stp_enter_shading shading, const stp_vec3 *normals, const stp_fix *shades)
{
    const stp_model_frame *frame;
    int status;
    /* the good arguments' tests (n in [3, STP_MAX_POLYGON_VERTICES]) each
     * a branch of its own (fewer steps than one test of three), the
     * error's kind after */
    if (STP_UNLIKELY(r == 0))
        return STP_ERR_ARG;
    if (STP_UNLIKELY(vertices == 0) || STP_UNLIKELY((unsigned)n - 3u > STP_MAX_POLYGON_VERTICES - 3u)) {
        if (n < 0)
            return STP_ERR_ARG;
        if (n < 3)
            return STP_ERR_DEGENERATE; /* with vertices NULL too */
        return vertices == 0 ? STP_ERR_ARG : STP_ERR_TOO_MANY_VERTICES;
    }
    /* an implicit segment is opened only for a call that can draw */
    if ((status = check_open(r)) != STP_OK)
        return status;
    r->last_shade = -1;
    if (shading == STP_ENTER_FLAT && (frame = model_route(r)) != 0)
        return enter_model_face(r, vertices, n, frame);
    status = enter_view_polygon(r, vertices, n, shading, normals, shades);
#if STP_WITH_SHADOWS
    if (status == STP_OK && shadows_on(r))
        stp_shadow_enter(r, vertices, n);
#endif
    return status;
}

int stp_renderer_polygon(stp_renderer *r, const stp_vec3 *vertices, int n)
{
    return enter_polygon(r, vertices, n, STP_ENTER_FLAT, 0, 0);
}

int stp_renderer_polygon_smooth(stp_renderer *r, const stp_vec3 *vertices, const stp_vec3 *normals, int n)
{
    if (normals == 0)
        return STP_ERR_ARG;
    return enter_polygon(r, vertices, n, STP_ENTER_SMOOTH_NORMALS, normals, 0);
}

int stp_renderer_polygon_vertex_shades(stp_renderer *r, const stp_vec3 *vertices, const stp_fix *shades,
                              int n)
{
    if (shades == 0)
        return STP_ERR_ARG;
    return enter_polygon(r, vertices, n, STP_ENTER_SMOOTH_SHADES, 0, shades);
}
