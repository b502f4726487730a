/* SPDX-License-Identifier: MIT */
/* Shadows by a shadow Z buffer per light (docs/model.md section 5): the maps,
 * their depth drawn as polygons are entered, and the per-pixel test of the
 * output.  See stp_renderer_set_shadow_map in include/stipple/render.h.
 *
 * Fixed-point formats here (F = STP_FIX_FRAC_BITS):
 *   light-frame points: stp_fix (F bits); the view -> light rotation m: Q28
 *     (|m| <= 1 plus a rounding, so m p + t with |p| < 2^31 stays below
 *     2^62 before the shift);
 *   map coordinates u, v: Q27.4 like the device's, in [0, size * 16];
 *   map depth q = 65535 near / z_l: at the vertices with 12 fractional bits
 *     (< 2^28), interpolated over the polygon's plane, stored as its floor
 *     in 1..65535; at a pixel with 8 fractional bits (< 2^24);
 *   the depth key plane of a receiver (stp_shadow_poly): keys shifted right
 *     until below 2^28 (so Newell's sums over up to 4101 vertices stay below
 *     2^62), gradients per Q4 unit with 16 fractional bits, clamped to
 *     +-2^40 (a polygon seen edge-on), so a key at a pixel stays below 2^62.
 * Every quotient that could overflow goes through shl_div, which saturates. */
#include "shadow_private.h"
#include "geometry_stage_private.h"
#include "edge_walk_private.h"
#include "view_private.h"

#define F STP_FIX_FRAC_BITS
#define ONE STP_FIX_ONE
#define SUB STP_SUBPIXEL_BITS
#define HALF_PIXEL (1 << (SUB - 1))

#if STP_WITH_SHADOWS

/* ---- small arithmetic ---- */

static int64_t clamp64(int64_t v, int64_t lo, int64_t hi)
{
    return v < lo ? lo : (v > hi ? hi : v);
}

/* a * 2^t / b for b > 0 and 0 <= t <= 62, truncated toward zero.  While
 * a * 2^t would not fit in 62 bits and b >= 2^32, b and t lose one bit (a
 * relative error below 2^-32); if it still does not fit, the result
 * saturates to +-2^62. */
static int64_t shl_div(int64_t a, int t, int64_t b)
{
    uint64_t ua = a < 0 ? (uint64_t)0 - (uint64_t)a : (uint64_t)a;
    int64_t q;
    if (t == 0)
        return a / b;
    while (t > 0 && (ua >> (62 - t)) != 0 && b >= ((int64_t)1 << 32)) {
        b >>= 1;
        t--;
    }
    if ((ua >> (62 - t)) != 0)
        return a < 0 ? -((int64_t)1 << 62) : ((int64_t)1 << 62);
    q = (int64_t)((ua << t) / (uint64_t)b);
    return a < 0 ? -q : q;
}

/* Sum of three products of F-bit values (2F fractional bits) in Q28. */
static int32_t to_q28(int64_t v)
{
#if 2 * STP_FIX_FRAC_BITS >= 28
    return (int32_t)stp_asr64(v, 2 * F - 28);
#else
    return (int32_t)(v * ((int64_t)1 << (28 - 2 * F)));
#endif
}

/* A view point in the map's light frame, each component F bits in 64 bits
 * (|p| < 2^31: below 2^62). */
static void to_light(const stp_shadow_map *sm, const int64_t p[3], int64_t out[3])
{
    int a;
    for (a = 0; a < 3; a++)
        out[a] = stp_asr64((int64_t)sm->m[a][0] * p[0] + (int64_t)sm->m[a][1] * p[1] +
                               (int64_t)sm->m[a][2] * p[2],
                           28) +
                 sm->t[a];
}

/* ---- the API ---- */

/* ---- setting a map (stp_renderer_set_shadow_map's steps) ---- */

/* stp_renderer_set_shadow_map's arguments: STP_OK, STP_ERR_ARG (a pointer,
 * the light or a size out of range) or STP_ERR_MEMORY (count below width
 * height texels). */
static int map_args(const stp_renderer *r, int light, const uint16_t *depth, size_t count, uint32_t width,
                    uint32_t height)
{
    if (r == 0 || depth == 0 || light < 0 || light >= STP_MAX_LIGHTS ||
        light >= r->user_lighting.count || width < 1 || height < 1 || width > 32767 ||
        height > 32767)
        return STP_ERR_ARG;
    if ((uint64_t)width * height > count) /* in 64 bits: size_t may be 16 */
        return STP_ERR_MEMORY;
    return STP_OK;
}

/* The map's roll, basis[0] (right) and basis[1] (up) about its axis
 * basis[2] (unit, forward): the view's up, or its forward when the axis
 * runs along the view's up (as stp_renderer_set_view derives its own).
 * Returns 0 when neither gives a direction. */
static int map_roll(const stp_renderer *r, stp_vec3 basis[3])
{
    stp_vec3 right = stp_vec3_cross(basis[2], r->up), up;
    if (stp_vec3_unity(right, &right) < (ONE >> 10)) {
        right = stp_vec3_cross(basis[2], r->forward);
        if (stp_vec3_unity(right, &right) == 0)
            return 0;
    }
    up = stp_vec3_cross(right, basis[2]);
    (void)stp_vec3_unity(up, &up);
    basis[0] = right;
    basis[1] = up;
    return 1;
}

/* The view -> light transform (m in Q28, t in F bits) of a map with axes
 * basis[] and the light at lpos, and the light in view coordinates. */
static void map_transform(stp_shadow_map *sm, const stp_renderer *r, stp_vec3 lpos, const stp_vec3 basis[3])
{
    stp_vec3 vbasis[3];
    int a, b;
    vbasis[0] = r->right;
    vbasis[1] = r->up;
    vbasis[2] = r->forward;
    /* p_world = from + sum_b p_b vbasis[b]: p_l[a] = basis[a].(p_world - L)
     * = sum_b p_b (basis[a].vbasis[b]) + basis[a].(from - L) */
    for (a = 0; a < 3; a++) {
        int64_t dx = (int64_t)r->from.x - lpos.x, dy = (int64_t)r->from.y - lpos.y,
                dz = (int64_t)r->from.z - lpos.z;
        for (b = 0; b < 3; b++)
            sm->m[a][b] = to_q28((int64_t)basis[a].x * vbasis[b].x + (int64_t)basis[a].y * vbasis[b].y +
                                 (int64_t)basis[a].z * vbasis[b].z);
        sm->t[a] = stp_fix_sat64(stp_asr64(dx * basis[a].x + dy * basis[a].y + dz * basis[a].z, F));
    }
    stp_view_transform_point(&r->to_view, lpos, &sm->light_view);
}

/* The map's focal length: texels per unit of x_l / z_l, (short / 2) /
 * tan(fov / 2) as the view's.  Returns 0 when it is not positive. */
static int map_focal(stp_shadow_map *sm, uint32_t width, uint32_t height, stp_fix fov)
{
    uint32_t short_side = width < height ? width : height;
    stp_fix half = fov / 2, s = stp_fix_sin_deg(half), c = stp_fix_cos_deg(half);
    if (s <= 0)
        return 0;
    sm->focal = stp_fix_sat64(((int64_t)short_side * c * (ONE / 2)) / s);
    return sm->focal > 0;
}

int stp_shadow_any(const stp_renderer *r)
{
    return r->shadow_set != 0;
}

#endif /* STP_WITH_SHADOWS */

int stp_renderer_set_shadow_map(stp_renderer *r, int light, uint16_t *depth, size_t count, uint32_t width,
                       uint32_t height, const stp_shadow_view *view)
{
#if STP_WITH_SHADOWS
    stp_shadow_map built; /* built aside: a refused call changes nothing */
    stp_vec3 lpos, target, basis[3];
    stp_fix fov, near;
    int64_t dist;
    size_t i, texels;
    int status = map_args(r, light, depth, count, width, height);
    if (status != STP_OK)
        return status;
    texels = (size_t)width * (size_t)height;
    built = r->shadow[light];
    lpos = r->user_lighting.lights[light].position;
    target = view ? view->target : r->at;
    fov = view ? view->fov_degrees : 90 * ONE;
    if (fov <= 0 || fov >= 180 * ONE)
        return STP_ERR_VIEW;
    dist = stp_unity_diff(target, lpos, &basis[2]);
    if (dist == 0)
        return STP_ERR_VIEW;
    near = view ? view->near : stp_fix_sat64(dist / 16);
    if (view && near <= 0)
        return STP_ERR_VIEW;
    if (near <= 0)
        near = 1;
    if (!map_roll(r, basis))
        return STP_ERR_VIEW;
    map_transform(&built, r, lpos, basis);
    if (!map_focal(&built, width, height, fov))
        return STP_ERR_VIEW;
    built.near = near;
    built.volume.focal = built.focal;
    built.volume.near = near;
    built.volume.width = width;
    built.volume.height = height;
    built.volume.parallel = 0;
    for (i = 0; i < texels; i++)
        depth[i] = 0;
    built.depth = depth;
    r->shadow_set |= (uint32_t)1 << light;
    r->model_route_ok = 0; /* render.c's model route decides again: no map there */
    built.width = width;
    built.height = height;
    r->shadow_generation = r->shadow_generation % 0x7FFFFFu + 1u;
    built.generation = r->shadow_generation;
    r->shadow[light] = built;
    return STP_OK;
#else
    (void)light;
    (void)depth;
    (void)count;
    (void)width;
    (void)height;
    (void)view;
    return r == 0 ? STP_ERR_ARG : STP_ERR_UNSUPPORTED;
#endif
}

int stp_renderer_remove_shadow_map(stp_renderer *r, int light)
{
    if (r == 0 || light < 0 || light >= STP_MAX_LIGHTS)
        return STP_ERR_ARG;
#if STP_WITH_SHADOWS
    r->shadow[light].depth = 0;
    r->shadow_set &= ~((uint32_t)1 << light);
#endif
    return STP_OK;
}

#if STP_WITH_SHADOWS

/* ---- at entry: records ---- */

static int map_applies(const stp_renderer *r, int j)
{
    const stp_shadow_map *sm = &r->shadow[j];
    const stp_vec3 *lp = &r->segment_lighting.lights[j].position;
    return sm->depth != 0 && lp->x == sm->light_view.x && lp->y == sm->light_view.y &&
           lp->z == sm->light_view.z;
}

int stp_shadow_records(const stp_renderer *r, stp_vec3 normal, stp_vec3 centre, stp_vec3 eye_dir,
                       int colour, stp_instr *record)
{
    const stp_lighting *l = &r->segment_lighting;
    stp_fix ambient, terms[STP_MAX_LIGHTS];
    stp_vec3 origin = {0, 0, 0};
    int64_t fixed;
    int j, n = 0, lights = l->count < 0 ? 0 : (l->count > STP_MAX_LIGHTS ? STP_MAX_LIGHTS : l->count);
    uint32_t tested = 0;
    for (j = 0; j < lights; j++)
        if (map_applies(r, j))
            tested |= (uint32_t)1 << j;
    if (tested == 0)
        return 0;
    /* the same call as the flat shade's, so the terms add up to it */
    (void)stp_shade_point_terms(l, &r->material, normal, centre, origin,
                                r->projection == STP_PARALLEL, eye_dir, &ambient, terms);
    fixed = ambient;
    for (j = 0; j < STP_MAX_LIGHTS; j++) {
        if ((tested & ((uint32_t)1 << j)) && terms[j] > 0) {
            stp_instr *in = &record[1 + n++];
            in->x = (int32_t)((uint32_t)j | (r->shadow[j].generation << 8));
            in->y = terms[j];
            in->z = 1;
        } else {
            fixed += terms[j]; /* a light no map can take away */
        }
    }
    if (n == 0)
        return 0;
    record[0].x = colour ? STP_LIGHT_TERM_COLOUR : STP_LIGHT_TERM_GREY;
    record[0].y = stp_fix_sat64(fixed);
    record[0].z = l->brightness;
    for (j = 0; j <= n; j++) {
        record[j].op = STP_OP_LIGHT_TERM;
#if STP_WITH_GOURAUD
        record[j].shade = -1;
#endif
    }
    return 1 + n;
}

/* ---- at entry: depth into the maps ---- */

/* Map coordinates (Q27.4) and depth (12 fractional bits) of a clipped
 * light-frame point (z >= near > 0): the one perspective projection
 * (view.c), the map's own depth. */
static stp_vec3 project_map(const stp_shadow_map *sm, stp_vec3 p)
{
    int64_t wq = (int64_t)sm->width << SUB, hq = (int64_t)sm->height << SUB, u, v;
    int64_t z = p.z < sm->near ? sm->near : p.z;
    stp_vec3 out;
    stp_view_perspective(sm->focal, sm->near, p, &u, &v, 0); /* the one projection */
    u = wq / 2 + u;
    v = hq / 2 - v;
    out.x = (int32_t)clamp64(u, 0, wq);
    out.y = (int32_t)clamp64(v, 0, hq);
    out.z = (int32_t)((((int64_t)sm->near * 65535) << 12) / z); /* <= 65535 << 12 */
    return out;
}

/* Scan-convert a projected polygon (x = u, y = v, z = depth Q12) into the
 * map, keeping the nearest (largest) depth per texel, with the device's fill
 * rule.  Returns the test's bias b = 1 + |dq/du| + |dq/dv| (one texel of
 * the polygon's depth slope, rounded up; at most 65535), or 0 when the
 * polygon has no area in the map. */
static int32_t fill_map(stp_renderer *r, const stp_shadow_map *sm, const stp_vec3 *v, int n)
{
    int64_t a = 0, b = 0, c = 0, sx = 0, sy = 0, sd = 0, ddx, ddy, xc, yc, dc, bias;
    int32_t ymin = INT32_MAX, ymax = INT32_MIN, first, last;
    int i, ne = 0;
    uint32_t y;
    for (i = 0; i < n; i++) {
        const stp_vec3 *p = &v[i == 0 ? n - 1 : i - 1], *q = &v[i];
        /* depths with 4 fractional bits here: every term < 2^40 */
        int64_t dp = p->z >> 8, dq = q->z >> 8;
        a += ((int64_t)p->y - q->y) * (dp + dq);
        b += (dp - dq) * ((int64_t)p->x + q->x);
        c += ((int64_t)p->x - q->x) * ((int64_t)p->y + q->y);
        sx += q->x;
        sy += q->y;
        sd += q->z;
        if (q->y < ymin)
            ymin = q->y;
        if (q->y > ymax)
            ymax = q->y;
    }
    if (c == 0)
        return 0; /* edge-on to the light */
    /* gradients of the Q12 depth per Q4 unit (Q4 depth * 2^8) */
    ddx = clamp64((-a * 256) / c, -((int64_t)1 << 40), (int64_t)1 << 40);
    ddy = clamp64((-b * 256) / c, -((int64_t)1 << 40), (int64_t)1 << 40);
    xc = sx / n;
    yc = sy / n;
    dc = sd / n;
    /* per texel (16 Q4 units), in whole depth units, rounded up */
    bias = 1 + (((ddx < 0 ? -ddx : ddx) + (ddy < 0 ? -ddy : ddy)) * 16 + 4095) / 4096;
    if (bias > 65535)
        bias = 65535;

    /* the polygon raster's edge setup and row crossings (raster.c) */
    for (i = 0; i < n; i++) {
        const stp_vec3 *pa = &v[i], *pb = &v[i + 1 == n ? 0 : i + 1];
        if (stp_edge_setup(&r->edges[ne], pa->x, pa->y, pb->x, pb->y) != 0)
            ne++;
    }
    /* texel rows whose centres lie in [ymin, ymax) (the map's rows: v is
     * clamped to [0, 16 height]) */
    stp_polygon_rows(r->edges, ne, ymin, ymax, 0, ymax, (int32_t)sm->height - 1, 0, &first, &last);
    for (y = (uint32_t)first; (int32_t)y <= last; y++) {
        int32_t yc_row = (int32_t)(y << SUB) + HALF_PIXEL;
        uint16_t *row = sm->depth + (size_t)y * sm->width;
        int nc = stp_edges_row(r->edges, ne, yc_row, 0, r->crossings), k;
        for (k = 0; k + 1 < nc; k += 2) {
            uint32_t p1, p2, p;
            int64_t d;
            if (!stp_span_pixels(r->crossings[k].x, r->crossings[k + 1].x, sm->width, &p1, &p2))
                continue;
            d = dc + ddx * (((int64_t)p1 << SUB) + HALF_PIXEL - xc) + ddy * ((int64_t)yc_row - yc);
            for (p = p1; p <= p2; p++, d += ddx * (1 << SUB)) {
                int64_t q = clamp64(stp_asr64(d, 12), 1, 65535);
                if (q > row[p])
                    row[p] = (uint16_t)q;
            }
        }
    }
    return (int32_t)bias;
}

void stp_shadow_enter(stp_renderer *r, const stp_vec3 *vertices, int n)
{
    int j, i, m;
    for (j = 0; j < STP_MAX_LIGHTS; j++) {
        stp_shadow_map *sm = &r->shadow[j];
        uint32_t rec = r->shadow_record[j];
        stp_vec3 *clipped, *spare;
        int32_t bias;
        r->shadow_record[j] = UINT32_MAX;
        if (sm->depth == 0)
            continue;
        /* through view coordinates, as the pixels' test will come */
        for (i = 0; i < n; i++) {
            stp_vec3 pv;
            int64_t p[3], l[3];
            /* the entered vertex through the geometry stage, the one the
             * display file's vertices come from (a composed model and view
             * transform included), so map and picture agree */
            (void)stp_render_point_to_view(r, vertices[i], &pv);
            p[0] = pv.x;
            p[1] = pv.y;
            p[2] = pv.z;
            to_light(sm, p, l);
            r->clip_a[i].x = stp_fix_sat64(l[0]);
            r->clip_a[i].y = stp_fix_sat64(l[1]);
            r->clip_a[i].z = stp_fix_sat64(l[2]);
        }
        {
            stp_fix *no_values;
            m = stp_clip_polygon(&sm->volume, r->clip_a, r->clip_b, 0, 0, n, &clipped, &spare,
                                 &no_values);
        }
        if (m < 3)
            continue;
        for (i = 0; i < m; i++)
            spare[i] = project_map(sm, clipped[i]);
        bias = fill_map(r, sm, spare, m);
        if (rec < r->used && bias > 0)
            r->df[rec].z = bias;
    }
}

/* ---- at output ---- */

/* The first shadow record of the polygon whose header is df[at]: just
 * before the header, the first with x < 0; UINT32_MAX when there is none. */
static uint32_t first_record(const stp_renderer *r, uint32_t at)
{
    uint32_t first = at;
    while (first > 0 && at - first <= STP_MAX_LIGHTS && r->df[first - 1].op == STP_OP_LIGHT_TERM) {
        first--;
        if (r->df[first].x < 0)
            return first;
    }
    return UINT32_MAX;
}

/* The records df[first..at): the shade's terms, the lights whose maps are
 * there to test (a light whose map is gone is lit, part of the ambient). */
static void take_records(const stp_renderer *r, uint32_t first, uint32_t at, stp_shadow_poly *sp)
{
    int64_t fixed = r->df[first].y;
    uint32_t k;
    int i;
    sp->grey = r->df[first].x == STP_LIGHT_TERM_GREY;
    sp->brightness = r->df[first].z;
    for (i = 0; i < STP_MAX_LIGHTS; i++)
        sp->terms[i] = 0;
    for (k = first + 1; k < at; k++) {
        const stp_instr *in = &r->df[k];
        uint32_t j = (uint32_t)in->x & 0xFFu, gen = (uint32_t)in->x >> 8;
        if (in->y <= 0)
            continue;
        if (j < STP_MAX_LIGHTS && r->shadow[j].depth != 0 && r->shadow[j].generation == gen &&
            !(sp->tested & ((uint32_t)1 << j))) {
            sp->tested |= (uint32_t)1 << j;
            sp->light[sp->count] = (int)j;
            sp->bias[sp->count] = (int32_t)clamp64(in->z, 1, 65535);
            sp->terms[j] = in->y;
            sp->count++;
        } else {
            fixed += in->y; /* its map is gone: the light is not tested */
        }
    }
    sp->ambient = stp_fix_sat64(fixed);
    sp->full = stp_shadow_shade(sp, 0xFFFFFFFFu);
}

/* The right shift that brings the polygon's depth keys below 2^28 (so
 * Newell's sums over its vertices stay below 2^62). */
static int key_shift(const stp_instr *v, int n)
{
    int64_t kmax = 0;
    int i, shift = 0;
    for (i = 0; i < n; i++) {
        int64_t z = v[i].z < 0 ? -(int64_t)v[i].z : v[i].z;
        if (z > kmax)
            kmax = z;
    }
    while ((kmax >> shift) >= ((int64_t)1 << 28))
        shift++;
    return shift;
}

/* -a 2^16 / c (c != 0, |c| < 2^46) clamped to +-2^40, as quotient and
 * remainder: a 2^16 itself could overflow. */
static int64_t key_gradient(int64_t a, int64_t c)
{
    const int64_t lim = (int64_t)1 << 40;
    int64_t q = a / c;
    if (q > (lim >> 16) || q < -(lim >> 16))
        return q > 0 ? -lim : lim;
    return -clamp64(q * 65536 + ((a % c) * 65536) / c, -lim, lim);
}

/* The depth key's plane over the device, by Newell's sums on (x, y, key)
 * as the Z buffer's (exact for planar polygons, a best fit otherwise). */
static void key_plane(const stp_instr *v, int n, stp_shadow_poly *sp)
{
    int64_t a = 0, b = 0, c = 0, sx = 0, sy = 0, sk = 0;
    int i;
    sp->shift = key_shift(v, n);
    for (i = 0; i < n; i++) {
        const stp_instr *p = &v[i == 0 ? n - 1 : i - 1], *q = &v[i];
        int64_t kp = stp_asr64(p->z, sp->shift), kq = stp_asr64(q->z, sp->shift);
        a += ((int64_t)p->y - q->y) * (kp + kq);
        b += (kp - kq) * ((int64_t)p->x + q->x);
        c += ((int64_t)p->x - q->x) * ((int64_t)p->y + q->y);
        sx += q->x;
        sy += q->y;
        sk += kq;
    }
    /* keep c below 2^46 so key_gradient's remainder times 2^16 fits */
    while (c >= ((int64_t)1 << 46) || c <= -((int64_t)1 << 46)) {
        a /= 2;
        b /= 2;
        c /= 2;
    }
    sp->x0 = (int32_t)(sx / n);
    sp->y0 = (int32_t)(sy / n);
    sp->k0 = (sk / n) * 65536;
    sp->gx = c == 0 ? 0 : key_gradient(a, c);
    sp->gy = c == 0 ? 0 : key_gradient(b, c);
}

void stp_shadow_polygon(const stp_renderer *r, uint32_t at, stp_shadow_poly *sp)
{
    uint32_t first = first_record(r, at);
    sp->count = 0;
    sp->tested = 0;
    if (first == UINT32_MAX)
        return;
    take_records(r, first, at, sp);
    if (sp->count > 0)
        key_plane(&r->df[at], (int)r->df[at].op, sp);
}

stp_fix stp_shadow_shade(const stp_shadow_poly *sp, uint32_t lit)
{
    return stp_shade_combine(sp->brightness, sp->ambient, sp->terms, STP_MAX_LIGHTS, lit);
}

uint32_t stp_shadow_hidden(const stp_renderer *r, const stp_shadow_poly *sp, uint32_t x, uint32_t y)
{
    const int64_t fix_lim = STP_FIX_MAX;
    int64_t xq = ((int64_t)x << SUB) + HALF_PIXEL, yq = ((int64_t)y << SUB) + HALF_PIXEL;
    int64_t key = sp->k0 + sp->gx * (xq - sp->x0) + sp->gy * (yq - sp->y0);
    int64_t dx = 2 * (int64_t)x + 1 - r->width, dy = (int64_t)r->height - 2 * (int64_t)y - 1;
    int64_t p[3];
    uint32_t hidden = 0;
    int k;
    /* the pixel centre's view point, from project()'s equations backwards */
    if (r->projection == STP_PERSPECTIVE) {
        /* key = 2^30 hither / z: z = hither 2^(30 + 16 - shift) / key */
        if (key <= 0)
            return 0;
        p[2] = clamp64(shl_div(r->hither, 46 - sp->shift, key), 1, fix_lim);
        /* x = (xs - W/2) z / focal, xs - W/2 = dx / 2 */
        p[0] = shl_div(dx * p[2], F - 1, r->focal);
        p[1] = shl_div(dy * p[2], F - 1, r->focal);
    } else {
        /* key = -z; x = (xs - W/2) / focal */
        p[2] = -stp_asr64(key, 16 - sp->shift);
        p[0] = shl_div(dx, 2 * F - 1, r->focal);
        p[1] = shl_div(dy, 2 * F - 1, r->focal);
    }
    p[0] = clamp64(p[0], -fix_lim, fix_lim);
    p[1] = clamp64(p[1], -fix_lim, fix_lim);
    p[2] = clamp64(p[2], -fix_lim, fix_lim);
    for (k = 0; k < sp->count; k++) {
        const stp_shadow_map *sm = &r->shadow[sp->light[k]];
        int64_t l[3], u, v, qp;
        uint16_t m;
        to_light(sm, p, l);
        if (l[2] < sm->near)
            continue; /* behind the map's near plane: not covered, lit */
        l[0] = clamp64(l[0], -fix_lim, fix_lim);
        l[1] = clamp64(l[1], -fix_lim, fix_lim);
        l[2] = clamp64(l[2], 1, fix_lim);
        u = ((int64_t)sm->width << (SUB - 1)) + stp_asr64(((int64_t)sm->focal * l[0]) / l[2], F - SUB);
        v = ((int64_t)sm->height << (SUB - 1)) - stp_asr64(((int64_t)sm->focal * l[1]) / l[2], F - SUB);
        if (u < 0 || v < 0 || u >= ((int64_t)sm->width << SUB) || v >= ((int64_t)sm->height << SUB))
            continue; /* outside the map's pyramid: lit */
        m = sm->depth[(size_t)(v >> SUB) * sm->width + (size_t)(u >> SUB)];
        if (m == 0)
            continue; /* nothing between the point and the light */
        qp = (((int64_t)sm->near * 65535) << 8) / l[2];
        if (((int64_t)m << 8) > qp + ((int64_t)sp->bias[k] << 8))
            hidden |= (uint32_t)1 << sp->light[k];
    }
    return hidden;
}

#endif /* STP_WITH_SHADOWS */
