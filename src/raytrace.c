/* SPDX-License-Identifier: MIT */
/* The ray tracer (include/stipple/raytrace.h).
 *
 * Number formats (F = STP_FIX_FRAC_BITS):
 *   positions, radii, lengths, ray distances t   F fractional bits; every
 *       coordinate within +-2^28 raw (STP_RT_COORD_LIMIT), so a difference
 *       of two is below 2^29 and a squared length below 3 * 2^58.
 *   directions and normals                       Q30 unit vectors (int32),
 *       so |d|^2 = 1 to 2^-29 and the perpendicular forms below stay exact
 *       for distant objects.
 *   position . direction                         F + 30 fractional bits in
 *       int64: |p| < 2^29 and |d| <= 2^30 bound each product by 2^59.
 *   t of a hit                                   below RT_FAR (2^31 - 1 raw);
 *       farther hits are misses.
 *   cone slope k                                 Q24, |k| <= 16.
 * Where a product can exceed 64 bits (the cone's quadratic), lengths are
 * scaled down by a power of two first (the quadratic is homogeneous in
 * length) and mul_shift forms the 128-bit product's high part. */
#include "align_private.h"
#include "stipple/raytrace.h"

#include "fix_private.h"
#include "output_private.h"
#include "frame_memory_private.h"
#include "diffuse_private.h"
#include "dither_private.h" /* stp_cell_default */
#include "view_private.h"

#if STP_WITH_RAYTRACE

#define F STP_FIX_FRAC_BITS
#define ONE STP_FIX_ONE
#define Q30_ONE ((int64_t)1 << 30)
#define RT_FAR (((int64_t)1 << 31) - 1)
#define LEAF_MAX 4u
#define STACK_MAX 64

enum { KIND_SPHERE = 1, KIND_CONE = 2, KIND_POLYGON = 3 };
/* polygon flags: bits 0-1 the axis its inside test drops, bit 2 vertex
 * normals follow its vertices */
#define FLAG_AXIS_MASK 3u
#define FLAG_NORMALS 4u

struct stp_raytracer {
    stp_rt_memory mem;
    uint32_t objects, points, nodes_used;
    uint32_t width, height;
    stp_view_frame view;
    stp_lighting lighting;
    const stp_rt_material *materials;
    uint32_t material_count;
    uint32_t max_material; /* the largest material index of the objects */
    int max_depth;
    stp_fix min_weight;
    int levels, colour, has_hierarchy;
    stp_rt_stats stats;
};

typedef struct rt_ray {
    int32_t o[3]; /* origin, F fractional bits */
    int32_t d[3]; /* unit direction, Q30 */
} rt_ray;

/* One ray's box-test constants: per axis how t is formed from a plane
 * coordinate (see box_range). */
typedef struct rt_slab {
    int64_t inv[3];
    uint8_t mode[3];
} rt_slab;
enum { SLAB_PARALLEL = 0, SLAB_DIVIDE = 1, SLAB_INVERSE = 2 };

/* ---- integer helpers ------------------------------------------------- */

static int64_t abs64(int64_t v)
{
    return v < 0 ? -v : v;
}

/* v / 2^s rounded to nearest (s >= 1). */
static int64_t round_shift(int64_t v, int s)
{
    return stp_asr64(v + ((int64_t)1 << (s - 1)), s);
}

/* floor(a * b / 2^s) for 0 <= s < 64, from the 128-bit product formed of
 * 32-bit halves; the caller guarantees the result fits in 63 bits. */
static int64_t mul_shift(int64_t a, int64_t b, int s)
{
    int negative = (a < 0) != (b < 0);
    uint64_t ua = (uint64_t)abs64(a), ub = (uint64_t)abs64(b);
    uint64_t al = ua & 0xFFFFFFFFu, ah = ua >> 32, bl = ub & 0xFFFFFFFFu, bh = ub >> 32;
    uint64_t ll = al * bl, lh = al * bh, hl = ah * bl, hh = ah * bh;
    uint64_t mid = (ll >> 32) + (lh & 0xFFFFFFFFu) + (hl & 0xFFFFFFFFu);
    uint64_t lo = (ll & 0xFFFFFFFFu) | (mid << 32);
    uint64_t hi = hh + (lh >> 32) + (hl >> 32) + (mid >> 32);
    uint64_t q = s == 0 ? lo : ((lo >> s) | (hi << (64 - s)));
    /* negative: floor of -(x) = -ceil(x) */
    if (negative) {
        int inexact = s != 0 && (lo & (((uint64_t)1 << s) - 1)) != 0;
        return -(int64_t)q - inexact;
    }
    return (int64_t)q;
}

/* a . d with a (F fractional bits, each |a_i| < 2^29 + 2^28) and d (Q30):
 * F + 30 fractional bits. */
static int64_t dot_pd(const int64_t a[3], const int32_t d[3])
{
    return a[0] * d[0] + a[1] * d[1] + a[2] * d[2];
}

/* Two Q30 unit vectors' dot product, Q30. */
static int64_t dot_dd(const int32_t a[3], const int32_t b[3])
{
    return round_shift((int64_t)a[0] * b[0] + (int64_t)a[1] * b[1] + (int64_t)a[2] * b[2], 30);
}

/* v / |v| as a Q30 unit vector; 0 (and out unchanged) for the zero vector.
 * Any |v_i| < 2^62: v is scaled so its largest component lies in
 * [2^29, 2^30) before the root, which keeps 29 bits whatever its length. */
static int unit_q30(int64_t x, int64_t y, int64_t z, int32_t out[3])
{
    int64_t m = abs64(x), len;
    uint64_t len2;
    if (abs64(y) > m)
        m = abs64(y);
    if (abs64(z) > m)
        m = abs64(z);
    if (m == 0)
        return 0;
    while (m >= Q30_ONE) {
        x = stp_asr64(x, 1);
        y = stp_asr64(y, 1);
        z = stp_asr64(z, 1);
        m >>= 1;
    }
    while (m < Q30_ONE / 2) {
        x *= 2;
        y *= 2;
        z *= 2;
        m *= 2;
    }
    len2 = (uint64_t)(x * x) + (uint64_t)(y * y) + (uint64_t)(z * z);
    len = (int64_t)stp_isqrt64(len2);
    out[0] = (int32_t)((x * Q30_ONE + (x < 0 ? -len / 2 : len / 2)) / len);
    out[1] = (int32_t)((y * Q30_ONE + (y < 0 ? -len / 2 : len / 2)) / len);
    out[2] = (int32_t)((z * Q30_ONE + (z < 0 ? -len / 2 : len / 2)) / len);
    return 1;
}

static stp_vec3 q30_to_vec(const int32_t d[3])
{
    stp_vec3 v;
    v.x = (stp_fix)round_shift(d[0], 30 - F);
    v.y = (stp_fix)round_shift(d[1], 30 - F);
    v.z = (stp_fix)round_shift(d[2], 30 - F);
    return v;
}

static int coord_ok(stp_vec3 p)
{
    const int32_t lim = STP_RT_COORD_LIMIT;
    return p.x >= -lim && p.x <= lim && p.y >= -lim && p.y <= lim && p.z >= -lim && p.z <= lim;
}

/* The point o + t d (t < 2^31, so each product is below 2^61). */
static void point_along(const rt_ray *ray, int64_t t, int32_t out[3])
{
    int i;
    for (i = 0; i < 3; i++) {
        /* within the limit for every hit but a non-planar polygon's plane
         * far off its vertices, which hit_polygon then rejects */
        int64_t v = ray->o[i] + round_shift(t * ray->d[i], 30);
        out[i] = (int32_t)(v > Q30_ONE ? Q30_ONE : (v < -Q30_ONE ? -Q30_ONE : v));
    }
}

/* ---- creation and settings ------------------------------------------- */

size_t stp_rt_size(void)
{
    return sizeof(stp_raytracer);
}

/* keeps STP_RAYTRACER_BYTES honest: a negative array size if it is short */
typedef char stp_rt_bytes_bound_check[(sizeof(stp_raytracer) <= STP_RAYTRACER_BYTES) ? 1 : -1];

/* C99 has no alignof: a type's alignment is its offset after a char. */
struct raytracer_alignment {
    char c;
    stp_raytracer rt;
};

stp_raytracer *stp_rt_create(void *mem, size_t mem_size, const stp_rt_memory *m, uint32_t width,
                             uint32_t height)
{
    stp_raytracer *rt = (stp_raytracer *)mem;
    stp_view view;
    size_t i;
    if (mem == 0 || m == 0 || mem_size < sizeof(stp_raytracer) || width < 1 || height < 1 ||
        width > 32767 || height > 32767)
        return 0;
    if ((m->objects == 0 && m->object_capacity > 0) || (m->points == 0 && m->point_capacity > 0))
        return 0;
    /* misaligned, the object would fault later on a Cortex-M0 */
    if (!stp_is_aligned(mem, offsetof(struct raytracer_alignment, rt)))
        return 0;
    for (i = 0; i < sizeof(stp_raytracer); i++)
        ((uint8_t *)mem)[i] = 0;
    rt->mem = *m;
    rt->width = width;
    rt->height = height;
    stp_lighting_default(&rt->lighting);
    rt->max_depth = 4;
    rt->min_weight = ONE / 64;
    rt->levels = 16;
    view.from.x = view.from.y = 0;
    view.from.z = -ONE;
    view.at.x = view.at.y = view.at.z = 0;
    view.up.x = view.up.z = 0;
    view.up.y = ONE;
    view.fov_degrees = 90 * ONE;
    view.window_half = ONE;
    view.hither = ONE >> 8;
    view.projection = STP_PERSPECTIVE;
    (void)stp_view_frame_make(&view, width, height, &rt->view);
    return rt;
}

int stp_rt_set_view(stp_raytracer *rt, const stp_view *view)
{
    stp_view_frame vf;
    int status;
    if (rt == 0 || view == 0 || !coord_ok(view->from))
        return STP_ERR_ARG;
    status = stp_view_frame_make(view, rt->width, rt->height, &vf);
    if (status == STP_OK)
        rt->view = vf;
    return status;
}

int stp_rt_set_lighting(stp_raytracer *rt, const stp_lighting *lighting)
{
    int j;
    if (rt == 0 || lighting == 0 || lighting->count < 0 || lighting->count > STP_MAX_LIGHTS)
        return STP_ERR_ARG;
    for (j = 0; j < lighting->count; j++)
        if (!coord_ok(lighting->lights[j].position))
            return STP_ERR_ARG;
    rt->lighting = *lighting;
    return STP_OK;
}

int stp_rt_set_materials(stp_raytracer *rt, const stp_rt_material *table, uint32_t count)
{
    if (rt == 0 || (table == 0 && count > 0))
        return STP_ERR_ARG;
    rt->materials = table;
    rt->material_count = count;
    return STP_OK;
}

int stp_rt_set_recursion(stp_raytracer *rt, int max_depth, stp_fix min_weight)
{
    if (rt == 0 || max_depth < 0 || max_depth > STP_RT_MAX_DEPTH || min_weight < 0 ||
        min_weight > ONE)
        return STP_ERR_ARG;
    rt->max_depth = max_depth;
    rt->min_weight = min_weight;
    return STP_OK;
}

int stp_rt_set_levels(stp_raytracer *rt, int levels)
{
    if (rt == 0 || levels < 2 || levels > 256)
        return STP_ERR_ARG;
    rt->levels = levels;
    return STP_OK;
}

int stp_rt_set_colour(stp_raytracer *rt, int on)
{
    if (rt == 0)
        return STP_ERR_ARG;
#if STP_WITH_COLOUR
    rt->colour = on != 0;
    return STP_OK;
#else
    (void)on;
    return STP_ERR_UNSUPPORTED;
#endif
}

uint32_t stp_rt_object_count(const stp_raytracer *rt)
{
    return rt ? rt->objects : 0;
}

void stp_rt_get_stats(const stp_raytracer *rt, stp_rt_stats *out)
{
    if (rt && out)
        *out = rt->stats;
}

void stp_rt_reset_stats(stp_raytracer *rt)
{
    if (rt) {
        rt->stats.rays = rt->stats.shadow_rays = 0;
        rt->stats.box_tests = rt->stats.object_tests = 0;
    }
}

/* ---- adding objects ----------------------------------------------------- */

static stp_rt_object *new_object(stp_raytracer *rt, int kind, uint32_t material)
{
    stp_rt_object *ob;
    int i;
    if (rt->objects >= rt->mem.object_capacity)
        return 0;
    ob = &rt->mem.objects[rt->objects];
    ob->kind = (uint8_t)kind;
    ob->flags = 0;
    ob->count = 0;
    ob->material = material;
    ob->first = 0;
    for (i = 0; i < 3; i++)
        ob->a[i] = ob->b[i] = ob->lo[i] = ob->hi[i] = 0;
    ob->r0 = ob->slope = ob->length = ob->bound = 0;
    ob->offset = 0;
    return ob;
}

static void commit_object(stp_raytracer *rt)
{
    uint32_t m = rt->mem.objects[rt->objects].material;
    if (rt->objects == 0 || m > rt->max_material)
        rt->max_material = m;
    rt->objects++;
    rt->has_hierarchy = 0;
}

int stp_rt_sphere(stp_raytracer *rt, stp_vec3 centre, stp_fix radius, uint32_t material)
{
    stp_rt_object *ob;
    int32_t c[3];
    int i;
    if (rt == 0 || radius < 0 || !coord_ok(centre) || radius > STP_RT_COORD_LIMIT)
        return STP_ERR_ARG;
    if (radius == 0)
        return STP_ERR_DEGENERATE;
    ob = new_object(rt, KIND_SPHERE, material);
    if (ob == 0)
        return STP_ERR_FULL;
    c[0] = centre.x;
    c[1] = centre.y;
    c[2] = centre.z;
    for (i = 0; i < 3; i++) {
        ob->a[i] = c[i];
        ob->lo[i] = c[i] - radius - 4;
        ob->hi[i] = c[i] + radius + 4;
    }
    ob->r0 = radius;
    commit_object(rt);
    return STP_OK;
}

int stp_rt_cone(stp_raytracer *rt, stp_vec3 base, stp_fix base_radius, stp_vec3 apex,
                stp_fix apex_radius, uint32_t material)
{
    stp_rt_object *ob;
    int64_t d[3], len2, len, rmax, half;
    int32_t axis[3];
    int32_t b[3], a[3];
    int i;
    if (rt == 0 || base_radius < 0 || apex_radius < 0 || !coord_ok(base) || !coord_ok(apex) ||
        (base_radius == 0 && apex_radius == 0) || base_radius > STP_RT_COORD_LIMIT ||
        apex_radius > STP_RT_COORD_LIMIT)
        return STP_ERR_ARG;
    b[0] = base.x;
    b[1] = base.y;
    b[2] = base.z;
    a[0] = apex.x;
    a[1] = apex.y;
    a[2] = apex.z;
    for (i = 0; i < 3; i++)
        d[i] = (int64_t)a[i] - b[i];
    len2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    len = (int64_t)stp_isqrt64((uint64_t)len2);
    if (len == 0 || !unit_q30(d[0], d[1], d[2], axis))
        return STP_ERR_DEGENERATE;
    /* |r1 - r0| / length <= 16, so the slope fits Q24 and hit_cone's
     * scaling keeps precision */
    if (abs64((int64_t)apex_radius - base_radius) > 16 * len)
        return STP_ERR_ARG;
    ob = new_object(rt, KIND_CONE, material);
    if (ob == 0)
        return STP_ERR_FULL;
    rmax = base_radius > apex_radius ? base_radius : apex_radius;
    half = len / 2;
    for (i = 0; i < 3; i++) {
        /* the end discs reach r sqrt(1 - u_i^2) off the axis along axis i */
        int64_t u = axis[i];
        int64_t across = (int64_t)stp_isqrt64((uint64_t)(Q30_ONE * Q30_ONE - u * u)); /* Q30 */
        int64_t e0 = ((int64_t)base_radius * across >> 30) + 4;
        int64_t e1 = ((int64_t)apex_radius * across >> 30) + 4;
        int64_t lo0 = b[i] - e0, lo1 = a[i] - e1, hi0 = b[i] + e0, hi1 = a[i] + e1;
        ob->a[i] = b[i];
        ob->b[i] = axis[i];
        ob->lo[i] = (int32_t)(lo0 < lo1 ? lo0 : lo1);
        ob->hi[i] = (int32_t)(hi0 > hi1 ? hi0 : hi1);
    }
    ob->r0 = base_radius;
    ob->length = (int32_t)len;
    ob->slope = (int32_t)((((int64_t)apex_radius - base_radius) * ((int64_t)1 << 24)) / len);
    ob->bound = (int32_t)stp_isqrt64((uint64_t)(half * half + rmax * rmax)) + 2;
    commit_object(rt);
    return STP_OK;
}

/* Newell's normal (Algorithm 10.4) of a polygon as a Q30 unit vector in
 * unit[]; 0 for a degenerate one.  In 64 bits: differences < 2^29 and sums
 * < 2^29, so each term < 2^58 and n <= 4096 of them fit. */
static int polygon_unit_normal(const stp_vec3 *vertices, int n, int32_t unit[3])
{
    int64_t nx = 0, ny = 0, nz = 0;
    int k;
    for (k = 0; k < n; k++) {
        stp_vec3 p = vertices[k == 0 ? n - 1 : k - 1], v = vertices[k];
        nx += ((int64_t)p.y - v.y) * ((int64_t)p.z + v.z);
        ny += ((int64_t)p.z - v.z) * ((int64_t)p.x + v.x);
        nz += ((int64_t)p.x - v.x) * ((int64_t)p.y + v.y);
    }
    return unit_q30(nx, ny, nz, unit);
}

/* The polygon's bounding box (one unit around its vertices) and dropped
 * axis (the normal's largest component, for the inside test).  A polygon
 * that is not quite planar is hit on its Newell plane inside its
 * projection, which can lie off its vertices along the dropped axis: the
 * box also holds each vertex moved onto the plane along that axis
 * (|n_d| >= 1/sqrt(3), so the quotient is tame), within the coordinate
 * limit that hit_polygon keeps to. */
static void polygon_box(stp_rt_object *ob, const stp_vec3 *vertices, uint32_t n)
{
    const int32_t *unit = ob->a;
    int64_t ax = abs64(unit[0]), ay = abs64(unit[1]), az = abs64(unit[2]);
    uint32_t i;
    int k, d, u, v;
    for (k = 0; k < 3; k++) {
        ob->lo[k] = STP_RT_COORD_LIMIT;
        ob->hi[k] = -STP_RT_COORD_LIMIT;
    }
    for (i = 0; i < n; i++) {
        const int32_t c[3] = {vertices[i].x, vertices[i].y, vertices[i].z};
        for (k = 0; k < 3; k++) {
            if (c[k] - 1 < ob->lo[k])
                ob->lo[k] = c[k] - 1;
            if (c[k] + 1 > ob->hi[k])
                ob->hi[k] = c[k] + 1;
        }
    }
    ob->flags = (uint8_t)(ax >= ay && ax >= az ? 0 : (ay >= az ? 1 : 2));
    d = ob->flags & FLAG_AXIS_MASK;
    u = d == 0 ? 1 : 0;
    v = d == 2 ? 1 : 2;
    for (i = 0; i < n; i++) {
        const int32_t c[3] = {vertices[i].x, vertices[i].y, vertices[i].z};
        int64_t w = (ob->offset - (int64_t)unit[u] * c[u] - (int64_t)unit[v] * c[v]) / unit[d];
        if (w < -STP_RT_COORD_LIMIT)
            w = -STP_RT_COORD_LIMIT;
        if (w > STP_RT_COORD_LIMIT)
            w = STP_RT_COORD_LIMIT;
        if (w - 1 < ob->lo[d])
            ob->lo[d] = (int32_t)w - 1;
        if (w + 1 > ob->hi[d])
            ob->hi[d] = (int32_t)w + 1;
    }
}

/* The vertex normals, as unit vectors, into out[0..n-1]: a zero normal
 * takes the plane's, turned to the side the others point to. */
static void polygon_vertex_normals(const int32_t unit[3], const stp_vec3 *normals, uint32_t n,
                                   stp_vec3 *out)
{
    stp_vec3 plane = q30_to_vec(unit), u;
    int64_t side = 0;
    uint32_t i;
    for (i = 0; i < n; i++)
        if (stp_vec3_unity(normals[i], &u) != 0)
            side += (int64_t)u.x * plane.x + (int64_t)u.y * plane.y + (int64_t)u.z * plane.z;
    if (side < 0) {
        plane.x = -plane.x;
        plane.y = -plane.y;
        plane.z = -plane.z;
    }
    for (i = 0; i < n; i++) {
        if (stp_vec3_unity(normals[i], &u) == 0)
            u = plane;
        out[i] = u;
    }
}

int stp_rt_polygon(stp_raytracer *rt, const stp_vec3 *vertices, const stp_vec3 *normals, int n,
                   uint32_t material)
{
    stp_rt_object *ob;
    int32_t unit[3];
    uint32_t need, i;
    int k;
    if (rt == 0 || vertices == 0 || n < 3)
        return n < 3 && rt && vertices ? STP_ERR_DEGENERATE : STP_ERR_ARG;
    if (n > STP_MAX_POLYGON_VERTICES)
        return STP_ERR_TOO_MANY_VERTICES;
    for (k = 0; k < n; k++)
        if (!coord_ok(vertices[k]))
            return STP_ERR_ARG;
    if (!polygon_unit_normal(vertices, n, unit))
        return STP_ERR_DEGENERATE;
    need = (uint32_t)n * (normals ? 2u : 1u);
    if (rt->points > rt->mem.point_capacity || need > rt->mem.point_capacity - rt->points)
        return STP_ERR_FULL;
    ob = new_object(rt, KIND_POLYGON, material);
    if (ob == 0)
        return STP_ERR_FULL;
    ob->count = (uint16_t)n;
    ob->first = rt->points;
    for (k = 0; k < 3; k++)
        ob->a[k] = unit[k];
    for (i = 0; i < (uint32_t)n; i++)
        rt->mem.points[rt->points + i] = vertices[i];
    ob->offset = (int64_t)unit[0] * vertices[0].x + (int64_t)unit[1] * vertices[0].y +
                 (int64_t)unit[2] * vertices[0].z;
    polygon_box(ob, vertices, (uint32_t)n);
    if (normals) {
        ob->flags |= FLAG_NORMALS;
        polygon_vertex_normals(unit, normals, (uint32_t)n, rt->mem.points + rt->points + (uint32_t)n);
    }
    rt->points += need;
    commit_object(rt);
    return STP_OK;
}

/* ---- intersections ------------------------------------------------------ */

/* Nearest root t > tmin of a sphere, or 0 when none.  The perpendicular
 * form h^2 = r^2 - |oc - (oc.d) d|^2 keeps the hit exact for a distant
 * sphere, where b^2 - c would cancel two large numbers. */
static int hit_sphere(const stp_rt_object *ob, const rt_ray *ray, int64_t tmin, int64_t *t)
{
    int64_t oc[3], b, pp = 0, h2, h;
    int i;
    for (i = 0; i < 3; i++)
        oc[i] = (int64_t)ray->o[i] - ob->a[i];
    b = round_shift(dot_pd(oc, ray->d), 30);
    for (i = 0; i < 3; i++) {
        int64_t p = oc[i] - round_shift(b * ray->d[i], 30);
        pp += p * p;
    }
    h2 = (int64_t)ob->r0 * ob->r0 - pp;
    if (h2 < 0)
        return 0;
    h = (int64_t)stp_isqrt64((uint64_t)h2);
    if (-b - h > tmin)
        *t = -b - h;
    else if (-b + h > tmin)
        *t = -b + h;
    else
        return 0;
    return *t < RT_FAR;
}

/* Even-odd inside test of point p on the polygon's projection that drops
 * axis `drop`; a point exactly on an edge counts on one side only (edges
 * cover v_a <= p_v < v_b, crossings strictly right of p). */
static int inside_polygon(const stp_raytracer *rt, const stp_rt_object *ob, const int32_t p[3])
{
    int du = ob->flags & FLAG_AXIS_MASK, u = du == 0 ? 1 : 0, v = du == 2 ? 1 : 2;
    const stp_vec3 *pts = rt->mem.points + ob->first;
    int inside = 0, n = ob->count, k;
    const int32_t *prev = (const int32_t *)&pts[n - 1];
    for (k = 0; k < n; k++) {
        const int32_t *cur = (const int32_t *)&pts[k];
        int64_t ay = (int64_t)prev[v] - p[v], by = (int64_t)cur[v] - p[v];
        if ((ay > 0) != (by > 0)) {
            int64_t ax = (int64_t)prev[u] - p[u], bx = (int64_t)cur[u] - p[u];
            int64_t cross = ax * by - ay * bx;
            if ((cross > 0) == (by > ay) && cross != 0)
                inside ^= 1;
        }
        prev = cur;
    }
    return inside;
}

/* Polygon hit: the plane's t, then the inside test at the hit point.  A
 * ray within 2^-20 (cosine) of the plane misses: its t would be a quotient
 * of rounding noise. */
static int hit_polygon(const stp_raytracer *rt, const stp_rt_object *ob, const rt_ray *ray,
                       int64_t tmin, int64_t tmax, int64_t *t, int32_t hit[3])
{
    int64_t den = dot_dd(ob->a, ray->d), num, o[3], tt;
    o[0] = ray->o[0];
    o[1] = ray->o[1];
    o[2] = ray->o[2];
    if (abs64(den) < ((int64_t)1 << 10))
        return 0;
    num = ob->offset - dot_pd(o, ob->a);
    if (num == 0 || (num > 0) != (den > 0))
        return 0;
    /* t = num / den > tmax  <=>  |num| > tmax |den| (|den| < 2^31, tmax < 2^31) */
    if (abs64(num) >= RT_FAR * abs64(den))
        return 0;
    tt = num / den;
    if (tt <= tmin || tt > tmax)
        return 0;
    point_along(ray, tt, hit);
    /* off the vertices of a non-planar polygon, the plane may run beyond
     * the coordinate limit: no hit there (the box stops at the limit) */
    if (hit[0] < -STP_RT_COORD_LIMIT || hit[0] > STP_RT_COORD_LIMIT || hit[1] < -STP_RT_COORD_LIMIT ||
        hit[1] > STP_RT_COORD_LIMIT || hit[2] < -STP_RT_COORD_LIMIT || hit[2] > STP_RT_COORD_LIMIT)
        return 0;
    if (!inside_polygon(rt, ob, hit))
        return 0;
    *t = tt;
    return 1;
}

/* Cone (open, truncated) hit.  The ray is first moved up to the cone's
 * bounding sphere (t0) so every length below is within a few times the
 * cone's size E, and lengths are scaled down by 2^s until E (1 + |k|)^2
 * is below 2^20 raw: then R0 < 2^22 / (1 + |k|), |B| < 2^23, C < 2^45
 * and A C (A < 2^39) fits mul_shift.  A cylinder of size 16 units (F = 16)
 * keeps every bit; only steep or flat cones give up low bits.  The
 * quadratic A t^2 + 2 B t + C = 0 is
 *   A = |d_perp|^2 - (k d.u)^2,
 *   B = w_perp . d_perp - R0 k (d.u),
 *   C = |w_perp|^2 - R0^2,  R0 = r0 + k w.u,
 * its roots taken as q / A and C / q with q = -(B + sign(B) h), which
 * loses nothing when A is tiny (a ray along a cylinder's side). */
/* hit_cone's start: where the ray enters the cone's bounding sphere (*t0,
 * not before 0) and the scale 2^-s of its lengths; 0 when the ray misses
 * the sphere or leaves it before tmin. */
static int cone_start(const stp_rt_object *ob, const rt_ray *ray, int64_t tmin, int64_t *t0,
                      int *s)
{
    int64_t oc[3], tc, pp = 0, bound = ob->bound, k1;
    int i;
    for (i = 0; i < 3; i++)
        oc[i] = ob->a[i] + round_shift((int64_t)ob->length * ob->b[i], 31) - ray->o[i];
    tc = round_shift(dot_pd(oc, ray->d), 30);
    for (i = 0; i < 3; i++) {
        int64_t p = oc[i] - round_shift(tc * ray->d[i], 30);
        pp += p * p;
    }
    if (pp > bound * bound || tc + bound <= tmin)
        return 0;
    *t0 = tc - bound > 0 ? tc - bound : 0;
    /* size (1 + |k|)^2 below 2^20 bounds R0 |k| and B by 2^22 */
    k1 = (abs64(ob->slope) >> 24) + 2;
    *s = 0;
    while ((bound >> *s) * k1 * k1 >= ((int64_t)1 << 20))
        (*s)++;
    return 1;
}

/* The nearer of the quadratic's roots (scaled by 2^-s, from t0) beyond
 * tmin whose point lies between the cone's ends (axial position wa + t da
 * in [0, len]): 1 and *t, or 0. */
static int cone_nearest_root(const int64_t roots[2], int64_t t0, int s, int64_t wa, int64_t da,
                             int64_t len, int64_t tmin, int64_t *t)
{
    int i, found = 0;
    for (i = 0; i < 2; i++) {
        int64_t ts = roots[i], tt, axial;
        if (ts < 0 || ts > (RT_FAR >> s))
            continue;
        tt = t0 + ts * ((int64_t)1 << s);
        if (tt <= tmin || tt >= RT_FAR || (found && tt >= *t))
            continue;
        axial = wa + round_shift(ts * da, 30);
        if (axial < 0 || axial > len)
            continue;
        *t = tt;
        found = 1;
    }
    return found;
}

static int hit_cone(const stp_rt_object *ob, const rt_ray *ray, int64_t tmin, int64_t *t)
{
    int64_t t0 = 0, w[3], wa, da, wp[3], dp[3];
    int64_t r0, len, R0, kd, A, B, C, disc, h, q, roots[2];
    int64_t dpp = 0, wpdp = 0, wpp = 0;
    int i, s = 0;
    if (!cone_start(ob, ray, tmin, &t0, &s))
        return 0;
    for (i = 0; i < 3; i++)
        w[i] = (int64_t)ray->o[i] + round_shift(t0 * ray->d[i], 30) - ob->a[i];
    wa = round_shift(dot_pd(w, ob->b), 30);
    da = dot_dd(ray->d, ob->b);
    for (i = 0; i < 3; i++) {
        wp[i] = stp_asr64(w[i] - round_shift(wa * ob->b[i], 30), s);
        dp[i] = ray->d[i] - round_shift(da * ob->b[i], 30);
        dpp += dp[i] * dp[i];
        wpdp += wp[i] * dp[i];
        wpp += wp[i] * wp[i];
    }
    r0 = stp_asr64(ob->r0, s);
    len = stp_asr64(ob->length, s);
    wa = stp_asr64(wa, s);
    R0 = r0 + round_shift((int64_t)ob->slope * wa, 24);
    kd = round_shift((int64_t)ob->slope * da, 24);
    A = round_shift(dpp, 30) - mul_shift(kd, kd, 30);
    B = round_shift(wpdp, 30) - mul_shift(R0, kd, 30);
    C = wpp - R0 * R0;
    disc = B * B - mul_shift(A, C, 30);
    if (disc < 0)
        return 0;
    h = (int64_t)stp_isqrt64((uint64_t)disc);
    q = B >= 0 ? -(B + h) : -(B - h);
    if (q == 0)
        return 0;
    roots[0] = A != 0 ? (q * Q30_ONE) / A : RT_FAR;
    roots[1] = C / q;
    return cone_nearest_root(roots, t0, s, wa, da, len, tmin, t);
}

/* The object's outward (spheres, cones) or plane (polygons) unit normal at
 * hit point p, Q30. */
static void geometric_normal(const stp_rt_object *ob, const int32_t p[3], int32_t n[3])
{
    int64_t v[3];
    int i;
    if (ob->kind == KIND_POLYGON) {
        n[0] = ob->a[0];
        n[1] = ob->a[1];
        n[2] = ob->a[2];
        return;
    }
    for (i = 0; i < 3; i++)
        v[i] = (int64_t)p[i] - ob->a[i];
    if (ob->kind == KIND_CONE) {
        /* gradient of |w_perp|^2 - r(w.u)^2: w_perp - r k u */
        int64_t wa = round_shift(dot_pd(v, ob->b), 30);
        int64_t r = ob->r0 + round_shift((int64_t)ob->slope * wa, 24);
        int64_t rk = round_shift(r * ob->slope, 24);
        for (i = 0; i < 3; i++)
            v[i] = v[i] - round_shift(wa * ob->b[i], 30) - round_shift(rk * ob->b[i], 30);
    }
    if (!unit_q30(v[0], v[1], v[2], n)) {
        /* the point is on a cone's axis (its apex): along the axis */
        n[0] = ob->b[0];
        n[1] = ob->b[1];
        n[2] = ob->b[2];
    }
}

/* The fan triangle (v0, v_best, v_best+1) of a patch holding p (the one
 * whose smallest barycentric coordinate is largest, should rounding leave
 * p outside them all) and p's weights in it, Q30.  Returns 0 when every
 * fan triangle is degenerate. */
static int patch_weights(const stp_raytracer *rt, const stp_rt_object *ob, const int32_t p[3],
                         int64_t w[3], int *best_out)
{
    int du = ob->flags & FLAG_AXIS_MASK, u = du == 0 ? 1 : 0, v = du == 2 ? 1 : 2;
    const stp_vec3 *pts = rt->mem.points + ob->first;
    const int32_t *a = (const int32_t *)&pts[0];
    int k, best = 1;
    int64_t best_min = INT64_MIN;
    w[0] = w[1] = w[2] = 0;
    for (k = 1; (uint32_t)k + 1u < ob->count; k++) {
        const int32_t *b = (const int32_t *)&pts[k], *c = (const int32_t *)&pts[k + 1];
        int64_t e[3], area, m;
        int q;
        /* twice the signed areas of (p, b, c), (a, p, c), (a, b, p) */
        e[0] = ((int64_t)b[u] - p[u]) * ((int64_t)c[v] - p[v]) -
               ((int64_t)c[u] - p[u]) * ((int64_t)b[v] - p[v]);
        e[1] = ((int64_t)p[u] - a[u]) * ((int64_t)c[v] - a[v]) -
               ((int64_t)c[u] - a[u]) * ((int64_t)p[v] - a[v]);
        e[2] = ((int64_t)b[u] - a[u]) * ((int64_t)p[v] - a[v]) -
               ((int64_t)p[u] - a[u]) * ((int64_t)b[v] - a[v]);
        area = e[0] + e[1] + e[2];
        if (area == 0)
            continue;
        if (area < 0) {
            area = -area;
            e[0] = -e[0];
            e[1] = -e[1];
            e[2] = -e[2];
        }
        /* weights in Q30: bring the area below 2^30 first, and clamp the
         * coordinates of a point far outside (they only rank triangles) */
        while (area >= ((int64_t)1 << 30)) {
            area = stp_asr64(area, 1);
            e[0] = stp_asr64(e[0], 1);
            e[1] = stp_asr64(e[1], 1);
            e[2] = stp_asr64(e[2], 1);
        }
        if (area == 0)
            continue;
        for (q = 0; q < 3; q++)
            e[q] = e[q] > 4 * area ? 4 * area : (e[q] < -4 * area ? -4 * area : e[q]);
        m = e[0] < e[1] ? e[0] : e[1];
        if (e[2] < m)
            m = e[2];
        if (m > best_min) {
            best_min = m;
            best = k;
            w[0] = (e[0] * Q30_ONE) / area;
            w[1] = (e[1] * Q30_ONE) / area;
            w[2] = (e[2] * Q30_ONE) / area;
        }
        if (m >= 0)
            break;
    }
    *best_out = best;
    return best_min != INT64_MIN;
}

/* A patch's shading normal at p: its vertex normals weighted by p's
 * barycentric coordinates (patch_weights), renormalised. */
static void patch_normal(const stp_raytracer *rt, const stp_rt_object *ob, const int32_t p[3],
                         int32_t out[3])
{
    const stp_vec3 *nrm = rt->mem.points + ob->first + ob->count;
    int64_t w[3], sum[3];
    int best;
    int found = patch_weights(rt, ob, p, w, &best);
    if (found) {
        const stp_vec3 *na = &nrm[0], *nb = &nrm[best], *nc = &nrm[best + 1];
        sum[0] = w[0] * na->x + w[1] * nb->x + w[2] * nc->x;
        sum[1] = w[0] * na->y + w[1] * nb->y + w[2] * nc->y;
        sum[2] = w[0] * na->z + w[1] * nb->z + w[2] * nc->z;
    }
    if (!found || !unit_q30(sum[0], sum[1], sum[2], out)) {
        out[0] = ob->a[0];
        out[1] = ob->a[1];
        out[2] = ob->a[2];
    }
}

/* ---- the hierarchy ------------------------------------------------------ */

static void slab_setup(const rt_ray *ray, rt_slab *s)
{
    int i;
    for (i = 0; i < 3; i++) {
        int64_t d = ray->d[i];
        if (abs64(d) < ((int64_t)1 << 10)) {
            s->mode[i] = SLAB_PARALLEL;
            s->inv[i] = 0;
        } else if (abs64(d) < ((int64_t)1 << 22)) {
            s->mode[i] = SLAB_DIVIDE;
            s->inv[i] = 0;
        } else {
            /* 1/d in Q22, |1/d| <= 2^8: a difference (< 2^29) times it
             * stays below 2^60 */
            s->mode[i] = SLAB_INVERSE;
            s->inv[i] = ((int64_t)1 << 52) / d;
        }
    }
}

/* Where the ray is inside box [lo, hi]: 1 and [*enter, *leave] (t, a little
 * wider than exact: the test must never drop a box a hit is in), or 0. */
static int box_range(const rt_ray *ray, const rt_slab *s, const int32_t lo[3],
                     const int32_t hi[3], int64_t *enter, int64_t *leave)
{
    int64_t t_in = INT64_MIN, t_out = INT64_MAX;
    int i;
    for (i = 0; i < 3; i++) {
        int64_t a = (int64_t)lo[i] - ray->o[i], b = (int64_t)hi[i] - ray->o[i], ta, tb, tmp;
        if (s->mode[i] == SLAB_PARALLEL) {
            if (a > 0 || b < 0)
                return 0;
            continue;
        }
        if (s->mode[i] == SLAB_DIVIDE) {
            ta = (a * Q30_ONE) / ray->d[i];
            tb = (b * Q30_ONE) / ray->d[i];
        } else {
            ta = stp_asr64(a * s->inv[i], 22);
            tb = stp_asr64(b * s->inv[i], 22);
        }
        if (ta > tb) {
            tmp = ta;
            ta = tb;
            tb = tmp;
        }
        /* widen by the rounding of 1/d (2^-14 relative) and a few units */
        ta -= (abs64(ta) >> 12) + 4;
        tb += (abs64(tb) >> 12) + 4;
        if (ta > t_in)
            t_in = ta;
        if (tb < t_out)
            t_out = tb;
    }
    if (t_in > t_out)
        return 0;
    *enter = t_in;
    *leave = t_out;
    return 1;
}

static int64_t centre_key(const stp_rt_object *ob, int axis)
{
    return (int64_t)ob->lo[axis] + ob->hi[axis];
}

/* Reorder order[first, first + count) so that entry first + k has the k-th
 * smallest centre along axis (quickselect, median-of-three pivots). */
static void select_kth(const stp_rt_object *objs, uint32_t *order, uint32_t first, uint32_t count,
                       uint32_t k, int axis)
{
    uint32_t lo = first, hi = first + count - 1, target = first + k;
    while (lo < hi) {
        uint32_t mid = lo + (hi - lo) / 2, i = lo, j = hi, tmp;
        int64_t a = centre_key(&objs[order[lo]], axis), b = centre_key(&objs[order[mid]], axis),
                c = centre_key(&objs[order[hi]], axis), pivot;
        pivot = a < b ? (b < c ? b : (a < c ? c : a)) : (a < c ? a : (b < c ? c : b));
        while (i <= j) {
            while (centre_key(&objs[order[i]], axis) < pivot)
                i++;
            while (centre_key(&objs[order[j]], axis) > pivot)
                j--;
            if (i <= j) {
                tmp = order[i];
                order[i] = order[j];
                order[j] = tmp;
                i++;
                if (j == 0)
                    break;
                j--;
            }
        }
        if (target <= j)
            hi = j;
        else if (target >= i)
            lo = i;
        else
            break;
    }
}

int stp_rt_build(stp_raytracer *rt)
{
    uint32_t stack_node[STACK_MAX], n, top = 0, i;
    if (rt == 0)
        return STP_ERR_ARG;
    n = rt->objects;
    rt->has_hierarchy = 0;
    if (n == 0)
        return STP_OK;
    if (rt->mem.nodes == 0 || rt->mem.order == 0 || rt->mem.node_capacity < 2 * n - 1)
        return STP_ERR_MEMORY;
    for (i = 0; i < n; i++)
        rt->mem.order[i] = i;
    rt->mem.nodes[0].first = 0;
    rt->mem.nodes[0].count = n;
    rt->nodes_used = 1;
    stack_node[top++] = 0;
    while (top > 0) {
        stp_rt_node *node = &rt->mem.nodes[stack_node[--top]];
        uint32_t first = node->first, count = node->count, k, left;
        int64_t clo[3] = {INT64_MAX, INT64_MAX, INT64_MAX}, chi[3] = {INT64_MIN, INT64_MIN, INT64_MIN};
        int axis, a;
        for (a = 0; a < 3; a++) {
            node->lo[a] = INT32_MAX;
            node->hi[a] = INT32_MIN;
        }
        for (k = first; k < first + count; k++) {
            const stp_rt_object *ob = &rt->mem.objects[rt->mem.order[k]];
            for (a = 0; a < 3; a++) {
                int64_t c = centre_key(ob, a);
                if (ob->lo[a] < node->lo[a])
                    node->lo[a] = ob->lo[a];
                if (ob->hi[a] > node->hi[a])
                    node->hi[a] = ob->hi[a];
                if (c < clo[a])
                    clo[a] = c;
                if (c > chi[a])
                    chi[a] = c;
            }
        }
        axis = 0;
        for (a = 1; a < 3; a++)
            if (chi[a] - clo[a] > chi[axis] - clo[axis])
                axis = a;
        /* a leaf: few objects, centres all in one place, or the stack (and
         * the traversal's, which is as deep) is full */
        if (count <= LEAF_MAX || chi[axis] == clo[axis] || top + 2 > STACK_MAX)
            continue;
        select_kth(rt->mem.objects, rt->mem.order, first, count, count / 2, axis);
        left = rt->nodes_used;
        rt->nodes_used += 2;
        rt->mem.nodes[left].first = first;
        rt->mem.nodes[left].count = count / 2;
        rt->mem.nodes[left + 1].first = first + count / 2;
        rt->mem.nodes[left + 1].count = count - count / 2;
        node->first = left;
        node->count = 0;
        stack_node[top++] = left + 1;
        stack_node[top++] = left;
    }
    rt->has_hierarchy = 1;
    return STP_OK;
}

/* ---- casting ------------------------------------------------------------ */

/* What a ray must not test: the polygon it leaves (a straight ray meets a
 * plane once) or the sphere it leaves outwards (convex). */
#define NO_SKIP UINT32_MAX

typedef struct rt_hit {
    int64_t t;
    uint32_t object;
    int32_t p[3];
} rt_hit;

/* Test one object; keeps the nearer hit in *h (ties: the lower index, so
 * the hierarchy and the plain loop see the same object). */
static void test_object(stp_raytracer *rt, uint32_t index, const rt_ray *ray, int64_t tmin,
                        rt_hit *h)
{
    const stp_rt_object *ob = &rt->mem.objects[index];
    int64_t t = 0;
    int32_t p[3];
    int hit = 0;
    rt->stats.object_tests++;
    if (ob->kind == KIND_SPHERE)
        hit = hit_sphere(ob, ray, tmin, &t);
    else if (ob->kind == KIND_CONE)
        hit = hit_cone(ob, ray, tmin, &t);
    else
        hit = hit_polygon(rt, ob, ray, tmin, h->t, &t, p);
    if (!hit || t > h->t || (t == h->t && index > h->object))
        return;
    if (ob->kind != KIND_POLYGON) {
        int i;
        point_along(ray, t, p);
        /* a hit outside the object's box is rounding (a ray grazing a
         * hair-thin cone, whose quadratic was scaled): dropping it keeps
         * what the hierarchy sees equal to what every object sees */
        for (i = 0; i < 3; i++)
            if (p[i] < ob->lo[i] || p[i] > ob->hi[i])
                return;
    }
    h->t = t;
    h->object = index;
    h->p[0] = p[0];
    h->p[1] = p[1];
    h->p[2] = p[2];
}

/* The nearest hit with tmin < t < RT_FAR, skipping object `skip`.
 * Returns 0 for none. */
static int nearest_hit(stp_raytracer *rt, const rt_ray *ray, int64_t tmin, uint32_t skip,
                       rt_hit *h)
{
    h->t = RT_FAR;
    h->object = NO_SKIP;
    if (!rt->has_hierarchy) {
        uint32_t i;
        for (i = 0; i < rt->objects; i++)
            if (i != skip)
                test_object(rt, i, ray, tmin, h);
    } else {
        rt_slab slab;
        uint32_t stack[STACK_MAX], top = 0;
        int64_t stack_enter[STACK_MAX], enter, leave;
        slab_setup(ray, &slab);
        rt->stats.box_tests++;
        if (box_range(ray, &slab, rt->mem.nodes[0].lo, rt->mem.nodes[0].hi, &enter, &leave) &&
            leave > tmin) {
            stack_enter[top] = enter;
            stack[top++] = 0;
        }
        while (top > 0) {
            const stp_rt_node *node;
            top--;
            /* a hit found since this node was pushed may be nearer */
            if (stack_enter[top] > h->t)
                continue;
            node = &rt->mem.nodes[stack[top]];
            if (node->count > 0) {
                uint32_t k;
                for (k = node->first; k < node->first + node->count; k++)
                    if (rt->mem.order[k] != skip)
                        test_object(rt, rt->mem.order[k], ray, tmin, h);
            } else {
                /* both children tested now; the nearer popped first */
                int64_t e[2], l[2];
                int in[2], c;
                for (c = 0; c < 2; c++) {
                    const stp_rt_node *ch = &rt->mem.nodes[node->first + (uint32_t)c];
                    rt->stats.box_tests++;
                    in[c] = box_range(ray, &slab, ch->lo, ch->hi, &e[c], &l[c]) && l[c] > tmin &&
                            e[c] <= h->t;
                }
                if (in[0] && in[1]) {
                    int nearer = e[1] < e[0];
                    stack_enter[top] = e[1 - nearer];
                    stack[top++] = node->first + (uint32_t)(1 - nearer);
                    stack_enter[top] = e[nearer];
                    stack[top++] = node->first + (uint32_t)nearer;
                } else if (in[0] || in[1]) {
                    int c1 = in[1];
                    stack_enter[top] = e[c1];
                    stack[top++] = node->first + (uint32_t)c1;
                }
            }
        }
    }
    return h->object != NO_SKIP;
}

/* The transparent objects a shadow ray crosses, by object index, so their
 * transmissions are multiplied in index order: fixed-point products round,
 * and the order the hierarchy meets objects in must not change a pixel.
 * Beyond RT_CROSSED_MAX of them (only with that many transparent objects
 * between a point and a light) the rest fold into `extra` in the order met. */
#define RT_CROSSED_MAX 16
typedef struct rt_crossed {
    uint32_t count;
    uint32_t index[RT_CROSSED_MAX];
    stp_fix t[RT_CROSSED_MAX];
    stp_fix extra;
    uint32_t from; /* the patch the ray leaves, NO_SKIP for any other start */
} rt_crossed;

/* Whether polygon idx is a patch sharing a corner with patch `from` (the
 * same coordinates): a neighbouring facet of the smooth surface the ray
 * leaves, which does not shade that surface where its interpolated normal
 * faces the light (the shadow terminator), so shadow rays pass it. */
static int neighbour_facet(const stp_raytracer *rt, uint32_t from, uint32_t idx)
{
    const stp_rt_object *a, *b;
    const stp_vec3 *pa, *pb;
    uint32_t i, j;
    if (from == NO_SKIP)
        return 0;
    a = &rt->mem.objects[from];
    b = &rt->mem.objects[idx];
    if (b->kind != KIND_POLYGON || !(b->flags & FLAG_NORMALS))
        return 0;
    pa = rt->mem.points + a->first;
    pb = rt->mem.points + b->first;
    for (i = 0; i < a->count; i++)
        for (j = 0; j < b->count; j++)
            if (pa[i].x == pb[j].x && pa[i].y == pb[j].y && pa[i].z == pb[j].z)
                return 1;
    return 0;
}

/* Test object idx against a shadow ray ending at dist: 0 when an opaque
 * object blocks it, else 1 (a transparent one crossed is recorded). */
static int shadow_test(stp_raytracer *rt, uint32_t idx, const rt_ray *ray, int64_t dist,
                       rt_crossed *cr)
{
    rt_hit h;
    stp_fix t;
    uint32_t k;
    h.t = dist;
    h.object = NO_SKIP;
    test_object(rt, idx, ray, 0, &h);
    if (h.object == NO_SKIP || neighbour_facet(rt, cr->from, idx))
        return 1;
    t = rt->materials[rt->mem.objects[idx].material].transmission;
    if (t <= 0)
        return 0;
    if (cr->count == RT_CROSSED_MAX) {
        cr->extra = stp_fix_mul(cr->extra, t);
        return 1;
    }
    for (k = cr->count; k > 0 && cr->index[k - 1] > idx; k--) {
        cr->index[k] = cr->index[k - 1];
        cr->t[k] = cr->t[k - 1];
    }
    cr->index[k] = idx;
    cr->t[k] = t;
    cr->count++;
    return 1;
}

/* The light a shadow ray lets through from its origin to distance dist:
 * the product of the transmissions of the objects it crosses (once per
 * object, in index order), 0 at the first opaque one.  from: the patch the
 * ray leaves (its neighbouring facets are passed), else NO_SKIP. */
static stp_fix visibility(stp_raytracer *rt, const rt_ray *ray, int64_t dist, uint32_t skip,
                          uint32_t from)
{
    stp_fix vis = ONE;
    rt_crossed cr;
    rt_slab slab;
    uint32_t stack[STACK_MAX], top = 0, i;
    int64_t enter, leave;
    rt->stats.shadow_rays++;
    cr.count = 0;
    cr.extra = ONE;
    cr.from = from;
    if (!rt->has_hierarchy) {
        for (i = 0; i < rt->objects; i++)
            if (i != skip && !shadow_test(rt, i, ray, dist, &cr))
                return 0;
    } else {
        slab_setup(ray, &slab);
        rt->stats.box_tests++;
        if (box_range(ray, &slab, rt->mem.nodes[0].lo, rt->mem.nodes[0].hi, &enter, &leave) &&
            leave > 0)
            stack[top++] = 0;
        while (top > 0) {
            const stp_rt_node *node = &rt->mem.nodes[stack[--top]];
            if (node->count > 0) {
                uint32_t k;
                for (k = node->first; k < node->first + node->count; k++)
                    if (rt->mem.order[k] != skip &&
                        !shadow_test(rt, rt->mem.order[k], ray, dist, &cr))
                        return 0;
            } else {
                int c;
                for (c = 0; c < 2; c++) {
                    const stp_rt_node *ch = &rt->mem.nodes[node->first + (uint32_t)c];
                    rt->stats.box_tests++;
                    if (box_range(ray, &slab, ch->lo, ch->hi, &enter, &leave) && leave > 0 &&
                        enter <= dist)
                        stack[top++] = node->first + (uint32_t)c;
                }
            }
        }
    }
    for (i = 0; i < cr.count; i++)
        vis = stp_fix_mul(vis, cr.t[i]);
    vis = stp_fix_mul(vis, cr.extra);
    return vis > 0 ? vis : 0;
}

/* The object a secondary ray leaving object `index` in direction d must
 * skip: a polygon always; a sphere when d points outwards (n_out . d > 0). */
static uint32_t skip_for(const stp_raytracer *rt, uint32_t index, const int32_t n_out[3],
                         const int32_t d[3])
{
    const stp_rt_object *ob = &rt->mem.objects[index];
    if (ob->kind == KIND_POLYGON)
        return index;
    if (ob->kind == KIND_SPHERE && dot_dd(n_out, d) > 0)
        return index;
    return NO_SKIP;
}

/* A secondary ray from p, STP_RT_OFFSET off the surface on the side of n
 * (side +1) or the other (-1). */
static void offset_ray(rt_ray *ray, const int32_t p[3], const int32_t n[3], int side,
                       const int32_t d[3])
{
    int i;
    for (i = 0; i < 3; i++) {
        ray->o[i] = p[i] + side * (int32_t)round_shift((int64_t)STP_RT_OFFSET * n[i], 30);
        ray->d[i] = d[i];
    }
}

typedef struct rt_colour {
    stp_fix c[3];
} rt_colour;

static void trace(stp_raytracer *rt, const rt_ray *ray, int64_t tmin, uint32_t skip, int depth,
                  stp_fix weight, stp_fix absorption, int parallel_primary,
                  const rt_colour *background, rt_colour *out, int64_t *t_hit);

/* e^(-a d) for absorption a and distance d (both stp_fix). */
static stp_fix absorb(stp_fix a, int64_t d)
{
    /* log2(e) = 1.4426950 */
    int64_t x = round_shift((int64_t)a * d, F);
    int64_t e = round_shift(x * 24204406, 24); /* log2(e) in Q24 */
    if (e > 64 * (int64_t)ONE)
        return 0;
    return stp_fix_exp2((stp_fix)-e);
}

/* A reflected (side 1) or transmitted (side -1) ray from hit h in unit
 * direction dir, of weight w: what it sees, times w and, when it travels
 * inside the sphere it starts on, e^(-a d) over its length, is added to
 * out. */
static void secondary(stp_raytracer *rt, const rt_hit *h, const int32_t n_out[3],
                      const int32_t n_geo[3], int side, const int32_t dir[3], int depth,
                      stp_fix weight, stp_fix w, stp_fix absorption, const rt_colour *background,
                      rt_colour *out)
{
    const stp_rt_object *ob = &rt->mem.objects[h->object];
    stp_fix a = ob->kind == KIND_SPHERE && dot_dd(dir, n_out) < 0 ? absorption : 0;
    int64_t t_next = 0;
    rt_ray r;
    rt_colour v;
    int c, channels = rt->colour ? 3 : 1;
    offset_ray(&r, h->p, n_geo, side, dir);
    trace(rt, &r, 0, skip_for(rt, h->object, n_out, dir), depth + 1, stp_fix_mul(weight, w), a, 0,
          background, &v, &t_next);
    if (a > 0)
        w = stp_fix_mul(w, absorb(a, t_next));
    for (c = 0; c < channels; c++)
        out->c[c] = stp_fix_add(out->c[c], stp_fix_mul(w, v.c[c]));
}

/* The light the surface hit by `ray` at h sends back along it. */
/* The normals at a hit: n_out the surface's outward (geometric) normal,
 * n_geo the same turned to face the ray, n_shade the shading normal (a
 * patch's interpolated one, else n_out) turned to face the ray; Q30. */
static void hit_normals(const stp_raytracer *rt, const stp_rt_object *ob, const rt_ray *ray,
                        const rt_hit *h, int32_t n_out[3], int32_t n_geo[3], int32_t n_shade[3])
{
    int j;
    geometric_normal(ob, h->p, n_out);
    for (j = 0; j < 3; j++)
        n_geo[j] = n_shade[j] = n_out[j];
    if (ob->kind == KIND_POLYGON && (ob->flags & FLAG_NORMALS))
        patch_normal(rt, ob, h->p, n_shade);
    /* two-sided: both normals face the ray */
    if (dot_dd(n_geo, ray->d) > 0)
        for (j = 0; j < 3; j++)
            n_geo[j] = -n_geo[j];
    if (dot_dd(n_shade, ray->d) > 0)
        for (j = 0; j < 3; j++)
            n_shade[j] = -n_shade[j];
}

/* Shadows: each light of *lit reaching the hit is dimmed by what lies
 * between (its power times the visibility along a shadow ray). */
static void dim_by_shadows(stp_raytracer *rt, const rt_hit *h, const int32_t n_out[3],
                           const int32_t n_geo[3], const int32_t n_shade[3], int patch,
                           stp_lighting *lit)
{
    int j;
    for (j = 0; j < lit->count; j++) {
        stp_light *L = &lit->lights[j];
        int64_t lv[3], dist2, dist;
        rt_ray sray;
        int32_t ld[3];
        lv[0] = (int64_t)L->position.x - h->p[0];
        lv[1] = (int64_t)L->position.y - h->p[1];
        lv[2] = (int64_t)L->position.z - h->p[2];
        if (dot_pd(lv, n_shade) <= 0 || !unit_q30(lv[0], lv[1], lv[2], ld))
            continue; /* no term from this light: nothing to test */
        /* a patch's ray leaves on the side its shading normal (which faces
         * the light) says, not the facet's, and passes the neighbouring
         * facets (neighbour_facet): the shadow terminator */
        offset_ray(&sray, h->p, n_geo, patch || dot_dd(ld, n_geo) >= 0 ? 1 : -1, ld);
        lv[0] = (int64_t)L->position.x - sray.o[0];
        lv[1] = (int64_t)L->position.y - sray.o[1];
        lv[2] = (int64_t)L->position.z - sray.o[2];
        dist2 = lv[0] * lv[0] + lv[1] * lv[1] + lv[2] * lv[2];
        dist = (int64_t)stp_isqrt64((uint64_t)dist2);
        L->power = stp_fix_mul(L->power, visibility(rt, &sray, dist, skip_for(rt, h->object, n_out, ld),
                                             patch ? h->object : NO_SKIP));
    }
}

/* The refracted direction through a sphere's surface (Snell, 10.19) into
 * tdir (Q30): 1; 0 for total internal reflection; -1 when it has no
 * direction.  cos_i = -d.n_shade > 0; n the material's index. */
static int refracted(const rt_ray *ray, const int32_t n_out[3], const int32_t n_shade[3],
                     int64_t cos_i, stp_fix refraction, int32_t tdir[3])
{
    /* eta = n1 / n2; entering when the ray meets the outward normal head on */
    int entering = dot_dd(ray->d, n_out) < 0;
    int64_t n = refraction > 0 ? refraction : 1;
    int64_t eta = entering ? ((int64_t)ONE << 30) / n : (n << 30) / ONE; /* Q30 */
    int64_t sin2 = Q30_ONE - round_shift(cos_i * cos_i, 30);
    int64_t k = Q30_ONE - mul_shift(mul_shift(eta, eta, 30), sin2, 30);
    int64_t root, m, v[3];
    int j;
    if (k < 0)
        return 0;
    root = (int64_t)stp_isqrt64((uint64_t)k << 30); /* Q30 */
    m = mul_shift(eta, cos_i, 30) - root;
    for (j = 0; j < 3; j++)
        v[j] = mul_shift(eta, ray->d[j], 30) + mul_shift(m, n_shade[j], 30);
    return unit_q30(v[0], v[1], v[2], tdir) ? 1 : -1;
}

/* The reflected and transmitted rays of a hit, weighted by Fresnel's F
 * with c = E.N (10.22), added to *out. */
static void reflect_and_transmit(stp_raytracer *rt, const rt_ray *ray, const rt_hit *h,
                                 const int32_t n_out[3], const int32_t n_geo[3],
                                 const int32_t n_shade[3], int depth, stp_fix weight,
                                 const rt_colour *background, rt_colour *out)
{
    const stp_rt_object *ob = &rt->mem.objects[h->object];
    const stp_rt_material *mat = &rt->materials[ob->material];
    int64_t cos_i = -dot_dd(ray->d, n_shade); /* > 0: N faces the ray */
    stp_fix fres = stp_fresnel((stp_fix)round_shift(cos_i, 30 - F), mat->surface.refraction);
    stp_fix w_r = mat->surface.specular > 0 ? stp_fix_mul(mat->surface.specular, fres) : 0;
    stp_fix w_t = mat->transmission > 0 ? stp_fix_mul(mat->transmission, ONE - fres) : 0;
    int32_t tdir[3] = {ray->d[0], ray->d[1], ray->d[2]};
    int transmit = w_t > 0 && stp_fix_mul(weight, w_t) >= rt->min_weight;
    if (transmit && ob->kind == KIND_SPHERE) {
        int through = refracted(ray, n_out, n_shade, cos_i, mat->surface.refraction, tdir);
        if (through == 0) {
            /* total internal reflection: the share goes to the mirror */
            w_r = stp_fix_add(w_r, w_t);
            w_t = 0;
        }
        transmit = through > 0;
    }
    if (w_r > 0 && stp_fix_mul(weight, w_r) >= rt->min_weight) {
        int64_t dn = dot_dd(ray->d, n_shade), vv[3];
        int32_t rdir[3];
        int j;
        for (j = 0; j < 3; j++)
            vv[j] = ray->d[j] - round_shift(2 * dn * n_shade[j], 30);
        if (unit_q30(vv[0], vv[1], vv[2], rdir))
            secondary(rt, h, n_out, n_geo, 1, rdir, depth, weight, w_r, mat->absorption, background,
                      out);
    }
    if (transmit)
        secondary(rt, h, n_out, n_geo, -1, tdir, depth, weight, w_t, mat->absorption, background,
                  out);
}

static void shade_hit(stp_raytracer *rt, const rt_ray *ray, const rt_hit *h, int depth,
                      stp_fix weight, int parallel_primary, const rt_colour *background,
                      rt_colour *out)
{
    const stp_rt_object *ob = &rt->mem.objects[h->object];
    const stp_rt_material *mat = &rt->materials[ob->material];
    int32_t n_out[3], n_geo[3], n_shade[3];
    stp_lighting lit = rt->lighting;
    stp_vec3 point, normal, eye, back;
    int c, channels = rt->colour ? 3 : 1;
    hit_normals(rt, ob, ray, h, n_out, n_geo, n_shade);
    dim_by_shadows(rt, h, n_out, n_geo, n_shade, ob->kind == KIND_POLYGON && (ob->flags & FLAG_NORMALS),
                   &lit);
    point.x = h->p[0];
    point.y = h->p[1];
    point.z = h->p[2];
    normal = q30_to_vec(n_shade);
    if (parallel_primary) {
        eye = point;
        back.x = (stp_fix)-round_shift(ray->d[0], 30 - F);
        back.y = (stp_fix)-round_shift(ray->d[1], 30 - F);
        back.z = (stp_fix)-round_shift(ray->d[2], 30 - F);
    } else {
        eye.x = ray->o[0];
        eye.y = ray->o[1];
        eye.z = ray->o[2];
        back = eye;
    }
#if STP_WITH_COLOUR
    if (rt->colour)
        stp_shade_point_colour(&lit, &mat->surface, normal, point, eye, parallel_primary, back,
                               out->c);
    else
#endif
        out->c[0] = stp_shade_point(&lit, &mat->surface, normal, point, eye, parallel_primary, back);
    if (depth < rt->max_depth)
        reflect_and_transmit(rt, ray, h, n_out, n_geo, n_shade, depth, weight, background, out);
    for (c = 0; c < channels; c++)
        out->c[c] = stp_fix_clamp(out->c[c], 0, ONE);
}

/* Trace one ray.  absorption: a of the sphere the ray travels through
 * (0: none); the caller scales what it sees by e^(-a t_hit), and the rays
 * cast from its hit weigh that much less when deciding whether to cast. */
static void trace(stp_raytracer *rt, const rt_ray *ray, int64_t tmin, uint32_t skip, int depth,
                  stp_fix weight, stp_fix absorption, int parallel_primary,
                  const rt_colour *background, rt_colour *out, int64_t *t_hit)
{
    rt_hit h;
    rt->stats.rays++;
    if (!nearest_hit(rt, ray, tmin, skip, &h)) {
        *out = *background;
        *t_hit = RT_FAR;
        return;
    }
    *t_hit = h.t;
    if (absorption > 0)
        weight = stp_fix_mul(weight, absorb(absorption, h.t));
    shade_hit(rt, ray, &h, depth, weight, parallel_primary, background, out);
}

/* The primary ray of pixel (x, y) and the nearest t it may hit (the
 * hither plane). */
static void primary_ray(const stp_raytracer *rt, uint32_t x, uint32_t y, rt_ray *ray, int64_t *tmin)
{
    const stp_view_frame *v = &rt->view;
    /* pixel centre offsets from the image centre in half pixels */
    int64_t hx = 2 * (int64_t)x + 1 - rt->width, hy = (int64_t)rt->height - 2 * (int64_t)y - 1;
    int32_t fwd[3], right[3], up[3];
    int i;
    fwd[0] = v->forward.x;
    fwd[1] = v->forward.y;
    fwd[2] = v->forward.z;
    right[0] = v->right.x;
    right[1] = v->right.y;
    right[2] = v->right.z;
    up[0] = v->up.x;
    up[1] = v->up.y;
    up[2] = v->up.z;
    if (v->projection == STP_PERSPECTIVE) {
        /* forward * 2 focal + right * hx + up * hy, in half pixels with 2F
         * fractional bits */
        int64_t d[3];
        for (i = 0; i < 3; i++)
            d[i] = (int64_t)fwd[i] * 2 * v->focal + (int64_t)right[i] * hx * ONE +
                   (int64_t)up[i] * hy * ONE;
        (void)unit_q30(d[0], d[1], d[2], ray->d);
        ray->o[0] = v->from.x;
        ray->o[1] = v->from.y;
        ray->o[2] = v->from.z;
        {
            /* view depth = t (d . forward) >= hither */
            int64_t df = round_shift((int64_t)ray->d[0] * fwd[0] + (int64_t)ray->d[1] * fwd[1] +
                                         (int64_t)ray->d[2] * fwd[2],
                                     F); /* Q30 */
            *tmin = df > 0 ? ((int64_t)v->hither * Q30_ONE) / df : 0;
        }
    } else {
        /* the window point: offsets hx/2 and hy/2 pixels over focal pixels
         * per unit */
        int64_t ox = (hx * (int64_t)ONE * ONE / 2) / v->focal, oy = (hy * (int64_t)ONE * ONE / 2) / v->focal;
        int32_t o[3];
        o[0] = v->from.x;
        o[1] = v->from.y;
        o[2] = v->from.z;
        for (i = 0; i < 3; i++)
            ray->o[i] = (int32_t)(o[i] + round_shift((int64_t)right[i] * ox + (int64_t)up[i] * oy, F));
        (void)unit_q30(fwd[0], fwd[1], fwd[2], ray->d);
        *tmin = v->hither;
    }
    *tmin -= 1; /* hits at t > tmin: the hither plane itself counts */
}

/* Every object's material is in the table (kept as a running maximum, so
 * a pixel's trace does not walk the objects). */
static int check_materials(const stp_raytracer *rt)
{
    return rt->objects == 0 || rt->max_material < rt->material_count ? STP_OK : STP_ERR_ARG;
}

static void trace_pixel(stp_raytracer *rt, uint32_t x, uint32_t y, const rt_colour *bg,
                        rt_colour *out)
{
    rt_ray ray;
    int64_t tmin, t_hit;
    primary_ray(rt, x, y, &ray, &tmin);
    trace(rt, &ray, tmin, NO_SKIP, 0, ONE, 0, rt->view.projection == STP_PARALLEL, bg, out, &t_hit);
    if (!rt->colour)
        out->c[1] = out->c[2] = out->c[0];
}

int stp_rt_trace_pixel(stp_raytracer *rt, uint32_t x, uint32_t y, const stp_fix *background,
                       stp_fix out[3])
{
    rt_colour bg, v;
    int c;
    if (rt == 0 || out == 0 || x >= rt->width || y >= rt->height)
        return STP_ERR_ARG;
    if (check_materials(rt) != STP_OK)
        return STP_ERR_ARG;
    for (c = 0; c < 3; c++)
        bg.c[c] = background ? stp_fix_clamp(background[c], 0, ONE) : 0;
    trace_pixel(rt, x, y, &bg, &v);
    for (c = 0; c < 3; c++)
        out[c] = v.c[c];
    return STP_OK;
}

/* The band for port in format drawn: STP_OK, STP_ERR_ARG (band_rows
 * outside 1..height, or a page port's neither whole pages nor the height)
 * or STP_ERR_MEMORY (band_size short). */
static int band_ok(const stp_port *port, stp_pixel_format drawn, size_t band_size, uint32_t band_rows)
{
    if (stp_row_bytes(drawn, port->width) == 0 || band_rows < 1 || band_rows > port->height)
        return STP_ERR_ARG;
    if (port->format == STP_PIXEL_MONO1_PAGES && band_rows % 8u != 0 && band_rows != port->height)
        return STP_ERR_ARG; /* whole pages (port.h) */
    return band_size < stp_band_bytes(drawn, port->width, band_rows) ? STP_ERR_MEMORY : STP_OK;
}

/* The checks of stp_rt_render's arguments; *drawn the format rows are
 * traced in (GREY8 under error diffusion) and *stride its row bytes. */
static int render_args(const stp_raytracer *rt, const stp_port *port, const stp_output *output,
                       const uint8_t *band, size_t band_size, uint32_t band_rows,
                       stp_pixel_format *drawn, size_t *stride)
{
    int status;
    if (rt == 0 || port == 0 || output == 0 || band == 0 || port->flush == 0)
        return STP_ERR_ARG;
    if (port->width != rt->width || port->height != rt->height)
        return STP_ERR_ARG;
    if (!STP_WITH_PAGES && port->format == STP_PIXEL_MONO1_PAGES)
        return STP_ERR_UNSUPPORTED; /* the page layout compiled out (config.h) */
    *drawn = port->format;
    if (output->diffusion && (port->format == STP_PIXEL_MONO1 || port->format == STP_PIXEL_MONO1_PAGES)) {
        status = stp_diffusion_check(output->diffusion, port->width);
        if (status != STP_OK)
            return status;
        *drawn = STP_PIXEL_GREY8;
    }
    *stride = stp_row_bytes(*drawn, port->width);
    status = band_ok(port, *drawn, band_size, band_rows);
    if (status != STP_OK)
        return status;
    if (port->format == STP_PIXEL_STYLE8 && output->styles == 0 && rt->levels > 255)
        return STP_ERR_ARG;
    return check_materials(rt) != STP_OK ? STP_ERR_ARG : STP_OK;
}

/* Trace row y into row (drawn format: MONO1_PAGES row y's page line, its
 * bits 0 before; the port's format says whether colour is kept) and
 * diffuse it when drawn differs from the port's (a page port's bits to
 * page, diffuse_private.h). */
static void render_row(stp_raytracer *rt, const stp_port *port, const stp_output *output,
                       const stp_cell *cell, const rt_colour *bg, stp_pixel_format drawn,
                       size_t stride, uint32_t y, uint8_t *row, uint8_t *page)
{
    uint32_t x;
    int c;
    if (drawn == STP_PIXEL_MONO1)
        row[stride - 1] = 0; /* padding bits past the width */
    for (x = 0; x < rt->width; x++) {
        rt_colour v;
        trace_pixel(rt, x, y, bg, &v);
        if (port->format == STP_PIXEL_RGB888 && rt->colour) {
            for (c = 0; c < 3; c++)
                row[3 * x + (uint32_t)c] =
                    stp_output_level(output, rt->levels, stp_intensity_index(v.c[c], rt->levels));
        } else {
            stp_fix grey = rt->colour ? stp_shade_luminance(v.c) : v.c[0];
            stp_output_put_shade(row, drawn, x, y, output, cell, rt->levels, grey);
        }
    }
    if (drawn != port->format && STP_PAGES_FORMAT(port->format))
        stp_diffuse_row_page(output->diffusion, row, rt->width, y, page);
    else if (drawn != port->format)
        stp_diffuse_row(output->diffusion, row, rt->width, y);
}

int stp_rt_render(stp_raytracer *rt, stp_port *port, const stp_output *output, uint8_t *band,
                  size_t band_size, uint32_t band_rows)
{
    stp_cell default_cell;
    const stp_cell *cell;
    rt_colour bg;
    size_t stride = 0;
    uint32_t y0;
    int c;
    stp_pixel_format drawn = STP_PIXEL_MONO1;
    int status = render_args(rt, port, output, band, band_size, band_rows, &drawn, &stride);
    if (status != STP_OK)
        return status;
    if (output->cell) {
        cell = output->cell;
    } else {
        stp_cell_default(&default_cell);
        cell = &default_cell;
    }
    for (c = 0; c < 3; c++)
        bg.c[c] = stp_fix_clamp(rt->colour && output->background_colour ? output->background_colour[c]
                                                                          : output->background,
                                0, ONE);
    for (y0 = 0; y0 < rt->height; y0 += band_rows) {
        uint32_t rows = rt->height - y0 < band_rows ? rt->height - y0 : band_rows, y;
        size_t i, page_bytes = stp_band_bytes(STP_PIXEL_MONO1_PAGES, rt->width, rows);
        for (i = 0; STP_PAGES_FORMAT(drawn) && i < page_bytes; i++)
            band[i] = 0; /* put_shade sets and clears its bit only */
        for (y = y0; y < y0 + rows; y++) {
            /* pages: row y's page line (grey rows diffused: on grey row
             * (y - y0) / 8, read already) */
            uint8_t *page = band + (size_t)((y - y0) >> 3) * stride;
            render_row(rt, port, output, cell, &bg, drawn, stride, y,
                       STP_PAGES_FORMAT(drawn) ? page : band + (size_t)(y - y0) * stride, page);
        }
        if (port->flush(port, y0, rows, band, stride) < 0)
            return STP_ERR_PORT;
    }
    return STP_OK;
}

#else /* !STP_WITH_RAYTRACE: no ray tracer (raytrace.h) */

size_t stp_rt_size(void)
{
    return 0;
}
stp_raytracer *stp_rt_create(void *mem, size_t mem_size, const stp_rt_memory *m, uint32_t width,
                             uint32_t height)
{
    (void)mem;
    (void)mem_size;
    (void)m;
    (void)width;
    (void)height;
    return 0;
}

#endif
