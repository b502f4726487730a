/* SPDX-License-Identifier: MIT */
/* The display file: viewing, segments and DISPLAY-FILE-ENTER (transform,
 * SHADE-CHECK, clip, project, store).  See include/stipple/render.h. */
#include "align_private.h"
#include "render_private.h"
#include "view_private.h"

#define F STP_FIX_FRAC_BITS
#define ONE STP_FIX_ONE

/* STP_RENDERER_BYTES must bound the object: a negative array size here
 * stops the build when it does not. */
typedef char stp_renderer_bytes_bound[sizeof(stp_renderer) <= STP_RENDERER_BYTES ? 1 : -1];

size_t stp_renderer_size(void)
{
    return sizeof(stp_renderer);
}

static void world_to_view(const stp_renderer *r, stp_vec3 p, stp_vec3 *out);
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
    r->shading = 0;
    r->levels = 16;
    r->fill_style = 16;
    r->backface_removal = 0;
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
#if STP_WITH_SHADOWS
    for (i = 0; i < STP_MAX_LIGHTS; i++) {
        r->shadow[i].depth = 0;
        r->shadow_record[i] = UINT32_MAX;
    }
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
    r->focal = vf.focal;
    r->from = vf.from;
    r->forward = vf.forward;
    r->right = vf.right;
    r->up = vf.up;
    r->projection = vf.projection;
    r->hither = vf.hither;
    r->pen_valid = 0;
#if STP_WITH_SHADOWS
    {
        /* the maps' transforms start from this view's coordinates */
        int j;
        r->at = v->at;
        for (j = 0; j < STP_MAX_LIGHTS; j++)
            r->shadow[j].depth = 0;
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

int stp_renderer_set_object_shade(stp_renderer *r, const stp_material *material)
{
    int c;
    if (r == 0 || material == 0 || material->reflectivity < 0 || material->reflectivity > ONE ||
        material->refraction < 0 || material->gloss < 0 || material->specular < 0)
        return STP_ERR_ARG;
    for (c = 0; c < 3; c++)
        if (material->colour[c] < 0 || material->colour[c] > ONE)
            return STP_ERR_ARG;
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

/* Open segment id (checked by the caller: no segment open, id not in use). */
static int open_segment(stp_renderer *r, int id)
{
    int i = free_segment_slot(r), j;
    if (i < 0)
        return STP_ERR_FULL;
    r->segments[i].used = 1;
    r->segments[i].open = 1;
    r->segments[i].visible = 1;
    r->segments[i].id = id;
    r->segments[i].start = r->segments[i].end = r->used;
    r->open_segment = i;
    r->current_style = -1;
    r->current_line_style = -1;
    r->current_transmission = 0;
    r->pen_valid = 0;
    /* COPY-LIGHT: the lighting belongs to the view; fix it for this segment
     * with the lights in view coordinates */
    r->segment_lighting = r->user_lighting;
    for (j = 0; j < r->segment_lighting.count; j++)
        world_to_view(r, r->user_lighting.lights[j].position,
                      &r->segment_lighting.lights[j].position);
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

static void world_to_view(const stp_renderer *r, stp_vec3 p, stp_vec3 *out)
{
    /* differences in 64 bits: p - from may exceed stp_fix's range */
    int64_t dx = (int64_t)p.x - r->from.x, dy = (int64_t)p.y - r->from.y,
            dz = (int64_t)p.z - r->from.z;
    out->x = stp_fix_sat64(stp_asr64(dx * r->right.x + dy * r->right.y + dz * r->right.z, F));
    out->y = stp_fix_sat64(stp_asr64(dx * r->up.x + dy * r->up.y + dz * r->up.z, F));
    out->z = stp_fix_sat64(stp_asr64(dx * r->forward.x + dy * r->forward.y + dz * r->forward.z, F));
}

#if STP_WITH_SHADOWS
void stp_view_point(const stp_renderer *r, stp_vec3 p, stp_vec3 *out)
{
    world_to_view(r, p, out);
}
#endif

/* Signed distance of view point p from clip plane `plane` (0: hither,
 * 1..4: left, right, top, bottom of the window), >= 0 inside.  Scaled by a
 * positive per-plane factor (only signs and ratios matter). */
static int64_t plane_distance(const stp_renderer *r, int plane, stp_vec3 p)
{
    /* both terms have F fractional bits and stay below 2^47 */
    int64_t fx = stp_asr64((int64_t)r->focal * p.x, F), fy = stp_asr64((int64_t)r->focal * p.y, F);
    int64_t hw, hh;
    if (plane == 0)
        return (int64_t)p.z - r->hither;
    if (r->projection == STP_PERSPECTIVE) {
        /* x_screen = W/2 + focal x / z lies in [0, W] <=> |focal x| <= (W/2) z */
        hw = ((int64_t)r->width * p.z) / 2;
        hh = ((int64_t)r->height * p.z) / 2;
    } else {
        hw = ((int64_t)r->width * ONE) / 2;
        hh = ((int64_t)r->height * ONE) / 2;
    }
    switch (plane) {
    case 1: return fx + hw;
    case 2: return hw - fx;
    case 3: return hh - fy;
    default: return fy + hh;
    }
}



#if STP_WITH_LINES
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

/* Sutherland-Hodgman against the five planes; returns the vertex count of
 * the clipped polygon, its vertices in *result (and, when smooth, its
 * vertex shades in *shades, interpolated like the positions). */
static int clip_polygon(stp_renderer *r, int n, int smooth, stp_vec3 **result, stp_fix **shades)
{
    stp_vec3 *in = r->clip_a, *out = r->clip_b, *tmp;
#if STP_WITH_GOURAUD
    stp_fix *s_in = r->shade_a, *s_out = r->shade_b, *s_tmp;
#endif
    int plane, i, m;
    (void)smooth;
    for (plane = 0; plane < 5 && n > 0; plane++) {
        m = 0;
        for (i = 0; i < n; i++) {
            int j = (i + 1) % n;
            stp_vec3 a = in[i], b = in[j];
            int64_t da = plane_distance(r, plane, a), db = plane_distance(r, plane, b);
            if (da >= 0) {
#if STP_WITH_GOURAUD
                if (smooth)
                    s_out[m] = s_in[i];
#endif
                out[m++] = a;
            }
            if ((da >= 0) != (db >= 0)) {
                int64_t t = stp_clip_fraction(da, db);
#if STP_WITH_GOURAUD
                if (smooth)
                    s_out[m] = stp_lerp_fix(s_in[i], s_in[j], t);
#endif
                out[m].x = stp_lerp_fix(a.x, b.x, t);
                out[m].y = stp_lerp_fix(a.y, b.y, t);
                out[m].z = stp_lerp_fix(a.z, b.z, t);
                m++;
            }
        }
        n = m;
        tmp = in;
        in = out;
        out = tmp;
#if STP_WITH_GOURAUD
        s_tmp = s_in;
        s_in = s_out;
        s_out = s_tmp;
#endif
    }
    *result = in;
#if STP_WITH_GOURAUD
    *shades = s_in;
#else
    *shades = 0;
#endif
    return n;
}

/* Device coordinates (Q27.4) and depth key of a clipped view point. */
static void project(const stp_renderer *r, stp_vec3 p, stp_instr *out)
{
    int64_t x, y;
    int64_t wq = (int64_t)r->width << STP_SUBPIXEL_BITS, hq = (int64_t)r->height << STP_SUBPIXEL_BITS;
    if (r->projection == STP_PERSPECTIVE) {
        int64_t z = p.z < r->hither ? r->hither : p.z; /* > 0 */
        /* focal * x / z has F fractional bits; keep SUBPIXEL of them */
        x = stp_asr64(((int64_t)r->focal * p.x) / z, F - STP_SUBPIXEL_BITS);
        y = stp_asr64(((int64_t)r->focal * p.y) / z, F - STP_SUBPIXEL_BITS);
        out->z = (int32_t)((((int64_t)r->hither) << 30) / z);
    } else {
        x = stp_asr64((int64_t)r->focal * p.x, 2 * F - STP_SUBPIXEL_BITS);
        y = stp_asr64((int64_t)r->focal * p.y, 2 * F - STP_SUBPIXEL_BITS);
        out->z = -p.z;
    }
    x = wq / 2 + x;
    y = hq / 2 - y;
    /* the clipper keeps points inside up to rounding: clamp the last bit */
    out->x = (int32_t)(x < 0 ? 0 : (x > wq ? wq : x));
    out->y = (int32_t)(y < 0 ? 0 : (y > hq ? hq : y));
}

static int check_open(stp_renderer *r)
{
    if (r == 0)
        return STP_ERR_ARG;
    return r->open_segment < 0 ? open_implicit_segment(r) : STP_OK;
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
    int status = check_open(r);
    if (status != STP_OK)
        return status;
    world_to_view(r, p, &r->pen);
    r->pen_valid = 1;
    return STP_OK;
}

int stp_renderer_line(stp_renderer *r, stp_vec3 p)
{
#if STP_WITH_LINES
    stp_vec3 a, b, q;
    stp_instr pa, pb;
    int plane, status = check_open(r);
    if (status != STP_OK)
        return status;
    world_to_view(r, p, &q);
    if (!r->pen_valid) {
        r->pen = q;
        r->pen_valid = 1;
        return STP_OK;
    }
    a = r->pen;
    b = q;
    r->pen = q;
    for (plane = 0; plane < 5; plane++) {
        int64_t da = plane_distance(r, plane, a), db = plane_distance(r, plane, b);
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

/* SHADE-CHECK: Newell normal (Algorithm 10.4) and vertex average of the
 * view-space vertices in clip_a.  Returns 0 for a zero normal. */
static int newell(stp_renderer *r, int n, stp_vec3 *normal, stp_vec3 *centre)
{
    const stp_vec3 *v = r->clip_a;
    int64_t a = 0, b = 0, c = 0, sx = 0, sy = 0, sz = 0;
    uint32_t m = 0;
    int i, shift = 0;
    for (i = 0; i < n; i++) {
        int64_t d[3];
        int k;
        d[0] = (int64_t)v[i].x - v[0].x;
        d[1] = (int64_t)v[i].y - v[0].y;
        d[2] = (int64_t)v[i].z - v[0].z;
        for (k = 0; k < 3; k++) {
            uint64_t ad = (uint64_t)(d[k] < 0 ? -d[k] : d[k]);
            if (ad > m)
                m = (uint32_t)(ad > 0xFFFFFFFFu ? 0xFFFFFFFFu : ad);
        }
        sx += v[i].x;
        sy += v[i].y;
        sz += v[i].z;
    }
    /* relative coordinates below 2^24 keep every product < 2^50 and the sum
     * of up to 4096 of them < 2^62; smaller polygons keep all their bits */
    while ((m >> shift) >= ((uint32_t)1 << 24))
        shift++;
    for (i = 0; i < n; i++) {
        int p = i == 0 ? n - 1 : i - 1;
        int64_t xp = ((int64_t)v[p].x - v[0].x) / ((int64_t)1 << shift),
                yp = ((int64_t)v[p].y - v[0].y) / ((int64_t)1 << shift),
                zp = ((int64_t)v[p].z - v[0].z) / ((int64_t)1 << shift);
        int64_t x = ((int64_t)v[i].x - v[0].x) / ((int64_t)1 << shift),
                y = ((int64_t)v[i].y - v[0].y) / ((int64_t)1 << shift),
                z = ((int64_t)v[i].z - v[0].z) / ((int64_t)1 << shift);
        a += (yp - y) * (zp + z);
        b += (zp - z) * (xp + x);
        c += (xp - x) * (yp + y);
    }
    /* the view system is left-handed: Newell's sum, written for right-handed
     * coordinates, points the other way there */
    a = -a;
    b = -b;
    c = -c;
    while (a > INT32_MAX || a < -INT32_MAX || b > INT32_MAX || b < -INT32_MAX || c > INT32_MAX ||
           c < -INT32_MAX) {
        a /= 2;
        b /= 2;
        c /= 2;
    }
    {
        stp_vec3 nv;
        nv.x = (stp_fix)a;
        nv.y = (stp_fix)b;
        nv.z = (stp_fix)c;
        if (stp_vec3_unity(nv, normal) == 0)
            return 0;
    }
    centre->x = (stp_fix)(sx / n);
    centre->y = (stp_fix)(sy / n);
    centre->z = (stp_fix)(sz / n);
    return 1;
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
#endif

/* DISPLAY-FILE-ENTER of a polygon.  smooth: 0 flat; 1 shade each vertex from
 * normals[]; 2 take shades[] from the caller. */
static int enter_polygon_df(stp_renderer *r, const stp_vec3 *vertices, int n, int smooth,
                            const stp_vec3 *normals, const stp_fix *shades)
{
    stp_vec3 normal, centre, eye_dir, *clipped;
    stp_fix n_dot_e, *clipped_shades;
    int i, m, style, status;
    int32_t colour;
    stp_fix transmission;
    uint32_t attribute;
#if STP_WITH_SHADOWS
    stp_instr record[STP_MAX_LIGHTS + 1];
    int records;
#endif
    if (r == 0 || vertices == 0 || n < 3)
        return n < 3 && n >= 0 && r != 0 ? STP_ERR_DEGENERATE : STP_ERR_ARG;
    if (n > STP_MAX_POLYGON_VERTICES)
        return STP_ERR_TOO_MANY_VERTICES;
    /* an implicit segment is opened only for a call that can draw */
    if ((status = check_open(r)) != STP_OK)
        return status;
    for (i = 0; i < n; i++)
        world_to_view(r, vertices[i], &r->clip_a[i]);
    r->last_shade = -1;
    if (!newell(r, n, &normal, &centre))
        return STP_ERR_DEGENERATE;

    /* direction towards the eye, for the back-face test and shading */
    if (r->projection == STP_PERSPECTIVE) {
        stp_vec3 to_eye;
        to_eye.x = -centre.x;
        to_eye.y = -centre.y;
        to_eye.z = -centre.z;
        if (stp_vec3_unity(to_eye, &eye_dir) == 0)
            eye_dir.z = -ONE; /* centre at the eye: it will be clipped anyway */
    } else {
        eye_dir.x = eye_dir.y = 0;
        eye_dir.z = -ONE;
    }
    n_dot_e = stp_vec3_dot(normal, eye_dir);
    if (n_dot_e <= 0) {
        if (r->backface_removal)
            return STP_OK;
        /* an open surface seen from behind: shade the side the eye sees */
        normal.x = -normal.x;
        normal.y = -normal.y;
        normal.z = -normal.z;
    }
    colour = 0;
    if (r->shading) {
        stp_vec3 origin = {0, 0, 0};
#if STP_WITH_COLOUR
        if (r->colour) {
            stp_fix rgb[3];
            int c;
            stp_shade_point_colour(&r->segment_lighting, &r->material, normal, centre, origin,
                                   r->projection == STP_PARALLEL, eye_dir, rgb);
            r->last_shade = stp_shade_luminance(rgb);
            colour = STP_COLOUR_FLAG;
            for (c = 0; c < 3; c++)
                colour |= (int32_t)(stp_intensity_index(rgb[c], r->levels) - 1) << (16 - 8 * c);
        } else
#endif
            r->last_shade = stp_shade_point(&r->segment_lighting, &r->material, normal, centre,
                                            origin, r->projection == STP_PARALLEL, eye_dir);
        style = stp_intensity_index(r->last_shade, r->levels);
    } else {
        style = r->fill_style;
        r->last_shade = stp_intensity_shade(style, r->levels);
    }
#if STP_WITH_GOURAUD
    if (smooth) {
        for (i = 0; i < n; i++) {
            stp_fix s = r->last_shade;
            if (smooth == 2) {
                s = stp_fix_clamp(shades[i], 0, ONE);
            } else if (r->shading) {
                stp_vec3 vn = normal, to_eye, e = eye_dir, origin = {0, 0, 0};
                if (stp_vec3_unity(direction_to_view(r, normals[i]), &vn) == 0) {
                    vn = normal;
                } else if (stp_vec3_dot(vn, normal) < 0) {
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
                    if (stp_vec3_unity(to_eye, &e) == 0)
                        e = eye_dir;
                }
                s = stp_shade_point(&r->segment_lighting, &r->material, vn, r->clip_a[i], origin,
                                    r->projection == STP_PARALLEL, e);
            }
            r->shade_a[i] = s;
        }
    }
#else
    (void)normals;
    (void)shades;
    if (smooth)
        return STP_ERR_UNSUPPORTED;
#endif

    m = clip_polygon(r, n, smooth, &clipped, &clipped_shades);
    if (m < 3)
        return STP_OK; /* nothing of it is in view */
    attribute = style != r->current_style || colour != r->current_colour ? 1u : 0u;
    transmission = 0;
#if STP_WITH_TRANSPARENCY
    if (r->t_max > 0 || r->t_min > 0) {
        /* (10.21): t = (t_max - t_min)(N.E)^power + t_min, then (10.18) */
        stp_fix ne = stp_fix_clamp(n_dot_e < 0 ? -n_dot_e : n_dot_e, 0, ONE), p = ONE;
        int k;
        for (k = 0; k < r->t_power; k++)
            p = stp_fix_mul(p, ne);
        transmission = stp_fix_clamp(
            stp_fix_mul(stp_fix_add(stp_fix_mul(r->t_max - r->t_min, p), r->t_min), r->t_attenuation),
            0, ONE);
    }
#endif
    if (transmission != r->current_transmission)
        attribute++;
#if STP_WITH_SHADOWS
    /* shadow records: what the raster needs to re-light a pixel hidden
     * from a light (render.h, STP_OP_LIGHT_TERM) */
    records = 0;
    if (r->shading && smooth != 2)
        records = stp_shadow_records(r, normal, centre, eye_dir, colour != 0, record);
    attribute += (uint32_t)records;
#endif
    if (r->capacity - r->used < (uint32_t)m + attribute)
        return STP_ERR_FULL;
    if (transmission != r->current_transmission) {
        append(r, STP_OP_TRANSPARENCY, transmission, 0, 0, -1);
        r->current_transmission = transmission;
    }
    if (style != r->current_style || colour != r->current_colour) {
        append(r, STP_OP_SHADE, style, r->last_shade, colour, -1);
        r->current_style = style;
        r->current_colour = colour;
    }
#if STP_WITH_SHADOWS
    for (i = 0; i < records; i++) {
        if (i > 0)
            r->shadow_record[record[i].x & 0xFF] = r->used;
        append(r, STP_OP_LIGHT_TERM, record[i].x, record[i].y, record[i].z, -1);
    }
#endif
    for (i = 0; i < m; i++) {
        stp_instr p;
        project(r, clipped[i], &p);
        append(r, i == 0 ? m : STP_OP_LINE, p.x, p.y, p.z, smooth ? clipped_shades[i] : -1);
    }
    return STP_OK;
}

static int enter_polygon(stp_renderer *r, const stp_vec3 *vertices, int n, int smooth,
                         const stp_vec3 *normals, const stp_fix *shades)
{
    int status = enter_polygon_df(r, vertices, n, smooth, normals, shades);
#if STP_WITH_SHADOWS
    /* every polygon entered casts into the maps, in view or not, back face
     * or not (render.h) */
    if (status == STP_OK)
        stp_shadow_enter(r, vertices, n);
#endif
    return status;
}

int stp_renderer_polygon(stp_renderer *r, const stp_vec3 *vertices, int n)
{
    return enter_polygon(r, vertices, n, 0, 0, 0);
}

int stp_renderer_polygon_smooth(stp_renderer *r, const stp_vec3 *vertices, const stp_vec3 *normals, int n)
{
    if (normals == 0)
        return STP_ERR_ARG;
    return enter_polygon(r, vertices, n, 1, normals, 0);
}

int stp_renderer_polygon_vertex_shades(stp_renderer *r, const stp_vec3 *vertices, const stp_fix *shades,
                              int n)
{
    if (shades == 0)
        return STP_ERR_ARG;
    return enter_polygon(r, vertices, n, 2, 0, shades);
}
