/* SPDX-License-Identifier: MIT */
/* Double-precision reference ray tracer: see raytrace_ref.h. */
#include "raytrace_ref.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define RT_MAX_DEPTH 64

enum { RT_SPHERE = 0, RT_CONE = 1, RT_POLYGON = 2 };

typedef struct rt_object {
    int kind;
    int material;
    ref_vec3 a;    /* sphere: centre; cone: base; polygon: unit plane normal */
    ref_vec3 axis; /* cone: unit axis, base to apex */
    double radius; /* sphere: radius; cone: base radius */
    double slope;  /* cone: radius change per unit along the axis */
    double length; /* cone: base to apex */
    double offset; /* polygon: N.v0 */
    size_t first;  /* polygon: first vertex (and normal) */
    int count;     /* polygon: vertices */
    int has_normals;
    int drop;      /* polygon: the axis the 2D projection drops */
} rt_object;

struct ref_rt {
    int width, height;
    /* view */
    ref_vec3 from, right, up, forward;
    double focal, hither;
    int perspective;
    ref_lighting lighting;
    const ref_rt_material *materials;
    size_t material_count;
    int max_depth;
    double min_weight;
    /* objects */
    rt_object *objects;
    size_t object_count, object_cap;
    ref_vec3 *verts, *norms; /* per polygon vertex; norms valid for patches */
    size_t vert_count, vert_cap;
    double object_scale; /* largest absolute coordinate of the objects' boxes */
    double eps;          /* 1e-9 * scene scale */
    int smooth_shadows;  /* ref_rt_set_smooth_shadows */
};

typedef struct rt_ray {
    ref_vec3 o, d;   /* d unit */
    long start;      /* object the ray starts on, -1 none */
    long inside;     /* sphere the ray travels inside (absorption), -1 none */
    int primary;
} rt_ray;

/* ---- vectors */

static double vcomp(ref_vec3 a, int axis)
{
    return axis == 0 ? a.x : (axis == 1 ? a.y : a.z);
}

static double vmaxabs(ref_vec3 a)
{
    double m = fabs(a.x);
    if (fabs(a.y) > m)
        m = fabs(a.y);
    if (fabs(a.z) > m)
        m = fabs(a.z);
    return m;
}

static int vfinite(ref_vec3 a)
{
    return isfinite(a.x) && isfinite(a.y) && isfinite(a.z);
}

/* ---- creation and settings */

static void update_eps(ref_rt *rt)
{
    double s = rt->object_scale, e = vmaxabs(rt->from);
    if (e > s)
        s = e;
    rt->eps = 1e-9 * (s > 0 ? s : 1.0);
}

ref_rt *ref_rt_create(int width, int height)
{
    ref_rt *rt;
    ref_view v;
    if (width < 1 || height < 1 || width > 32767 || height > 32767)
        return NULL;
    rt = calloc(1, sizeof *rt);
    if (!rt)
        return NULL;
    rt->width = width;
    rt->height = height;
    rt->lighting.brightness = 1;
    rt->lighting.background = 0;
    rt->lighting.c = 1;
    rt->lighting.count = 1;
    rt->lighting.lights[0].position = ref_v3(0, 0, 1);
    rt->lighting.lights[0].power = 1;
    rt->max_depth = 4;
    rt->min_weight = 1.0 / 64;
    memset(&v, 0, sizeof v);
    v.from = ref_v3(0, 0, -1);
    v.up = ref_v3(0, 1, 0);
    v.fov_degrees = 90;
    v.window_half = 1;
    v.hither = 1.0 / 256;
    v.perspective = 1;
    (void)ref_rt_set_view(rt, &v);
    return rt;
}

void ref_rt_free(ref_rt *rt)
{
    if (!rt)
        return;
    free(rt->objects);
    free(rt->verts);
    free(rt->norms);
    free(rt);
}

int ref_rt_set_view(ref_rt *rt, const ref_view *v)
{
    ref_view_frame f;
    if (ref_view_frame_make(v, rt->width, rt->height, &f) != REF_OK)
        return REF_ERR_VIEW;
    rt->from = f.from;
    rt->forward = f.forward;
    rt->right = f.right;
    rt->up = f.up;
    rt->focal = f.focal;
    rt->hither = f.hither;
    rt->perspective = f.perspective;
    update_eps(rt);
    return REF_OK;
}

void ref_rt_set_lighting(ref_rt *rt, const ref_lighting *world)
{
    rt->lighting = *world;
    if (rt->lighting.count > REF_MAX_LIGHTS)
        rt->lighting.count = REF_MAX_LIGHTS;
    if (rt->lighting.count < 0)
        rt->lighting.count = 0;
}

void ref_rt_set_materials(ref_rt *rt, const ref_rt_material *table, size_t count)
{
    rt->materials = table;
    rt->material_count = table ? count : 0;
}

int ref_rt_set_recursion(ref_rt *rt, int max_depth, double min_weight)
{
    if (max_depth < 0 || max_depth > RT_MAX_DEPTH || !(min_weight >= 0 && min_weight <= 1))
        return REF_ERR_ARG;
    rt->max_depth = max_depth;
    rt->min_weight = min_weight;
    return REF_OK;
}

size_t ref_rt_object_count(const ref_rt *rt)
{
    return rt->object_count;
}

/* ---- adding objects */

static rt_object *new_object(ref_rt *rt)
{
    rt_object *o;
    if (rt->object_count == rt->object_cap) {
        size_t n = rt->object_cap ? 2 * rt->object_cap : 16;
        rt_object *p = realloc(rt->objects, n * sizeof *p);
        if (!p)
            return NULL;
        rt->objects = p;
        rt->object_cap = n;
    }
    o = &rt->objects[rt->object_count];
    memset(o, 0, sizeof *o);
    return o;
}

static void grow_scale(ref_rt *rt, ref_vec3 p, double r)
{
    double s = vmaxabs(p) + r;
    if (s > rt->object_scale)
        rt->object_scale = s;
}

int ref_rt_sphere(ref_rt *rt, ref_vec3 centre, double radius, int material)
{
    rt_object *o;
    if (!rt || material < 0 || !vfinite(centre) || !isfinite(radius) || radius < 0)
        return REF_ERR_ARG;
    if (radius == 0)
        return REF_ERR_DEGENERATE;
    o = new_object(rt);
    if (!o)
        return REF_ERR_ARG;
    o->kind = RT_SPHERE;
    o->material = material;
    o->a = centre;
    o->radius = radius;
    grow_scale(rt, centre, radius);
    update_eps(rt);
    return (int)rt->object_count++;
}

int ref_rt_cone(ref_rt *rt, ref_vec3 base, double base_radius, ref_vec3 apex, double apex_radius,
                int material)
{
    rt_object *o;
    ref_vec3 axis;
    double length;
    if (!rt || material < 0 || !vfinite(base) || !vfinite(apex) || !isfinite(base_radius) ||
        !isfinite(apex_radius) || base_radius < 0 || apex_radius < 0 ||
        (base_radius == 0 && apex_radius == 0))
        return REF_ERR_ARG;
    length = ref_unit(ref_sub(apex, base), &axis);
    if (length == 0)
        return REF_ERR_DEGENERATE;
    o = new_object(rt);
    if (!o)
        return REF_ERR_ARG;
    o->kind = RT_CONE;
    o->material = material;
    o->a = base;
    o->axis = axis;
    o->radius = base_radius;
    o->length = length;
    o->slope = (apex_radius - base_radius) / length;
    grow_scale(rt, base, base_radius);
    grow_scale(rt, apex, apex_radius);
    update_eps(rt);
    return (int)rt->object_count++;
}

int ref_rt_polygon(ref_rt *rt, const ref_vec3 *v, const ref_vec3 *normals, int n, int material)
{
    rt_object *o;
    ref_vec3 rawn, normal, sum;
    double a = 0, b = 0, c = 0, extent2 = 0, best;
    size_t need;
    int i;
    if (!rt || !v || material < 0 || n < 0)
        return REF_ERR_ARG;
    if (n < 3)
        return REF_ERR_DEGENERATE;
    for (i = 0; i < n; i++)
        if (!vfinite(v[i]) || (normals && !vfinite(normals[i])))
            return REF_ERR_ARG;
    /* Newell's sums (docs/model.md section 1) relative to v0 (they do not change
     * under translation) */
    for (i = 0; i < n; i++) {
        ref_vec3 p = ref_sub(v[i == 0 ? n - 1 : i - 1], v[0]), q = ref_sub(v[i], v[0]);
        double d2 = ref_dot(q, q);
        if (d2 > extent2)
            extent2 = d2;
        a += (p.y - q.y) * (p.z + q.z);
        b += (p.z - q.z) * (p.x + q.x);
        c += (p.x - q.x) * (p.y + q.y);
    }
    rawn = ref_v3(a, b, c);
    if (ref_unit(rawn, &normal) <= 1e-10 * extent2)
        return REF_ERR_DEGENERATE;
    need = rt->vert_count + (size_t)n;
    if (need > rt->vert_cap) {
        size_t cap = rt->vert_cap ? rt->vert_cap : 64;
        ref_vec3 *pv, *pn;
        while (cap < need)
            cap *= 2;
        pv = realloc(rt->verts, cap * sizeof *pv);
        if (!pv)
            return REF_ERR_ARG;
        rt->verts = pv;
        pn = realloc(rt->norms, cap * sizeof *pn);
        if (!pn)
            return REF_ERR_ARG;
        rt->norms = pn;
        rt->vert_cap = cap;
    }
    o = new_object(rt);
    if (!o)
        return REF_ERR_ARG;
    o->kind = RT_POLYGON;
    o->material = material;
    o->a = normal;
    o->offset = ref_dot(normal, v[0]);
    o->first = rt->vert_count;
    o->count = n;
    o->has_normals = normals != NULL;
    best = fabs(normal.x);
    o->drop = 0;
    if (fabs(normal.y) > best) {
        best = fabs(normal.y);
        o->drop = 1;
    }
    if (fabs(normal.z) > best)
        o->drop = 2;
    sum = ref_v3(0, 0, 0);
    for (i = 0; i < n; i++) {
        ref_vec3 u = ref_v3(0, 0, 0);
        rt->verts[o->first + (size_t)i] = v[i];
        if (normals)
            (void)ref_unit(normals[i], &u);
        rt->norms[o->first + (size_t)i] = u;
        sum = ref_add(sum, u);
        grow_scale(rt, v[i], 0);
    }
    if (normals) {
        /* a zero normal takes the plane's, on the side of the given ones */
        ref_vec3 plane = ref_dot(sum, normal) < 0 ? ref_scale(normal, -1) : normal;
        for (i = 0; i < n; i++) {
            ref_vec3 *u = &rt->norms[o->first + (size_t)i];
            if (u->x == 0 && u->y == 0 && u->z == 0)
                *u = plane;
        }
    }
    rt->vert_count = need;
    update_eps(rt);
    return (int)rt->object_count++;
}

/* ---- intersections */

/* Point (u, v) of p in the projection dropping axis drop. */
static void project(ref_vec3 p, int drop, double *u, double *v)
{
    *u = vcomp(p, drop == 0 ? 1 : 0);
    *v = vcomp(p, drop == 2 ? 1 : 2);
}

static int polygon_inside(const ref_rt *rt, const rt_object *o, ref_vec3 p)
{
    const ref_vec3 *v = rt->verts + o->first;
    double pu, pv;
    int i, j, inside = 0;
    project(p, o->drop, &pu, &pv);
    for (i = 0, j = o->count - 1; i < o->count; j = i++) {
        double ui, vi, uj, vj;
        project(v[i], o->drop, &ui, &vi);
        project(v[j], o->drop, &uj, &vj);
        if ((vi > pv) != (vj > pv)) {
            double cu = ui + (pv - vi) * (uj - ui) / (vj - vi);
            if (pu < cu)
                inside = !inside;
        }
    }
    return inside;
}

/* Roots of the cone's quadratic A t^2 + 2B t + C = 0 for the ray, in
 * increasing order; returns how many (0..2). */
static int cone_roots(const rt_object *o, const rt_ray *r, int starts_here, double t[2])
{
    ref_vec3 w = ref_sub(r->o, o->a);
    double wa = ref_dot(w, o->axis), da = ref_dot(r->d, o->axis);
    ref_vec3 qw = ref_sub(w, ref_scale(o->axis, wa)), qd = ref_sub(r->d, ref_scale(o->axis, da));
    double rw = o->radius + o->slope * wa, rd = o->slope * da;
    double qa = ref_dot(qd, qd) - rd * rd;
    double qb = ref_dot(qw, qd) - rw * rd;
    double qc = ref_dot(qw, qw) - rw * rw;
    double disc, q;
    if (starts_here) {
        /* the origin lies on the surface: qc is exactly 0, roots 0 and
         * -2B/A; only the other one */
        if (qa == 0)
            return 0;
        t[0] = -2 * qb / qa;
        return 1;
    }
    if (qa == 0) {
        if (qb == 0)
            return 0;
        t[0] = -qc / (2 * qb);
        return 1;
    }
    disc = qb * qb - qa * qc;
    if (disc < 0)
        return 0;
    q = -(qb + (qb >= 0 ? sqrt(disc) : -sqrt(disc)));
    if (q == 0) {
        t[0] = -qb / qa;
        return 1;
    }
    t[0] = q / qa;
    t[1] = qc / q;
    if (t[0] > t[1]) {
        double s = t[0];
        t[0] = t[1];
        t[1] = s;
    }
    return 2;
}

/* The nearest t >= t_lo at which the ray meets object id (HUGE_VAL: none). */
static double hit_object(const ref_rt *rt, size_t id, const rt_ray *r, double t_lo)
{
    const rt_object *o = &rt->objects[id];
    int starts_here = r->start >= 0 && (size_t)r->start == id;
    switch (o->kind) {
    case RT_SPHERE: {
        ref_vec3 oc = ref_sub(r->o, o->a);
        double b = ref_dot(oc, r->d), h2, h, t;
        if (starts_here) {
            /* leaving outwards: convex, no hit; heading in: the far root */
            if (b >= 0)
                return HUGE_VAL;
            t = -2 * b;
            return t >= t_lo ? t : HUGE_VAL;
        }
        /* perpendicular form: h^2 = r^2 - |oc - (oc.d) d|^2 */
        {
            ref_vec3 perp = ref_sub(oc, ref_scale(r->d, b));
            h2 = o->radius * o->radius - ref_dot(perp, perp);
        }
        if (h2 < 0)
            return HUGE_VAL;
        h = sqrt(h2);
        t = -b - h;
        if (t >= t_lo)
            return t;
        t = -b + h;
        return t >= t_lo ? t : HUGE_VAL;
    }
    case RT_CONE: {
        double t[2];
        int k, m = cone_roots(o, r, starts_here, t);
        for (k = 0; k < m; k++) {
            double s;
            if (t[k] < t_lo)
                continue;
            s = ref_dot(ref_sub(ref_add(r->o, ref_scale(r->d, t[k])), o->a), o->axis);
            if (s >= 0 && s <= o->length)
                return t[k];
        }
        return HUGE_VAL;
    }
    default: {
        double denom, t;
        if (starts_here)
            return HUGE_VAL;
        denom = ref_dot(o->a, r->d);
        if (denom == 0)
            return HUGE_VAL;
        t = (o->offset - ref_dot(o->a, r->o)) / denom;
        if (!(t >= t_lo) || !isfinite(t))
            return HUGE_VAL;
        return polygon_inside(rt, o, ref_add(r->o, ref_scale(r->d, t))) ? t : HUGE_VAL;
    }
    }
}

/* The smallest t a ray accepts. */
static double t_low(const ref_rt *rt, const rt_ray *r)
{
    if (r->primary)
        return rt->hither / ref_dot(r->d, rt->forward);
    return rt->eps;
}

/* Nearest hit: object id or -1, *t its distance. */
static long nearest(const ref_rt *rt, const rt_ray *r, double *t_out)
{
    double best = HUGE_VAL, lo = t_low(rt, r);
    long id = -1;
    size_t i;
    for (i = 0; i < rt->object_count; i++) {
        double t = hit_object(rt, i, r, lo);
        if (t < best) {
            best = t;
            id = (long)i;
        }
    }
    *t_out = id >= 0 ? best : -1;
    return id;
}

/* ---- normals */

/* Interpolated vertex normal of patch o at p (unit, not yet faced). */
static ref_vec3 patch_normal(const ref_rt *rt, const rt_object *o, ref_vec3 p)
{
    const ref_vec3 *v = rt->verts + o->first, *nv = rt->norms + o->first;
    double pu, pv, u0, v0, best_min = -HUGE_VAL, best_w[3] = {0, 0, 0};
    int i, best_i = -1;
    ref_vec3 sum, out;
    project(p, o->drop, &pu, &pv);
    project(v[0], o->drop, &u0, &v0);
    for (i = 1; i + 1 < o->count; i++) {
        double u1, v1, u2, v2, area, w1, w2, w0, mn;
        project(v[i], o->drop, &u1, &v1);
        project(v[i + 1], o->drop, &u2, &v2);
        area = (u1 - u0) * (v2 - v0) - (u2 - u0) * (v1 - v0);
        if (area == 0)
            continue;
        w1 = ((pu - u0) * (v2 - v0) - (u2 - u0) * (pv - v0)) / area;
        w2 = ((u1 - u0) * (pv - v0) - (pu - u0) * (v1 - v0)) / area;
        w0 = 1 - w1 - w2;
        mn = w0 < w1 ? w0 : w1;
        if (w2 < mn)
            mn = w2;
        if (mn > best_min) {
            best_min = mn;
            best_i = i;
            best_w[0] = w0;
            best_w[1] = w1;
            best_w[2] = w2;
        }
        if (mn >= 0)
            break; /* the first fan triangle containing p */
    }
    if (best_i < 0)
        return o->a;
    sum = ref_add(ref_add(ref_scale(nv[0], best_w[0]), ref_scale(nv[best_i], best_w[1])),
               ref_scale(nv[best_i + 1], best_w[2]));
    if (ref_unit(sum, &out) == 0)
        return o->a;
    return out;
}

/* Geometric outward (sphere, cone) or plane/patch normal at p, unit. */
static ref_vec3 object_normal(const ref_rt *rt, const rt_object *o, ref_vec3 p)
{
    ref_vec3 n;
    switch (o->kind) {
    case RT_SPHERE:
        if (ref_unit(ref_sub(p, o->a), &n) == 0)
            n = ref_v3(0, 0, -1);
        return n;
    case RT_CONE: {
        /* gradient of |q|^2 - r(s)^2: q - r(s) slope axis */
        ref_vec3 w = ref_sub(p, o->a), q, qn;
        double s = ref_dot(w, o->axis);
        q = ref_sub(w, ref_scale(o->axis, s));
        if (ref_unit(q, &qn) == 0)
            return o->axis; /* the apex point itself: no normal, take the axis */
        (void)ref_unit(ref_sub(qn, ref_scale(o->axis, o->slope)), &n);
        return n;
    }
    default:
        return o->has_normals ? patch_normal(rt, o, p) : o->a;
    }
}

/* ---- shading */

void ref_rt_set_smooth_shadows(ref_rt *rt, int on)
{
    rt->smooth_shadows = on;
}

/* Whether polygons a and b have a vertex in common (the same coordinates:
 * a patch's facets share their corners exactly). */
static int shares_vertex(const ref_rt *rt, const rt_object *a, const rt_object *b)
{
    int i, j;
    for (i = 0; i < a->count; i++)
        for (j = 0; j < b->count; j++) {
            ref_vec3 u = rt->verts[a->first + (size_t)i], v = rt->verts[b->first + (size_t)j];
            if (u.x == v.x && u.y == v.y && u.z == v.z)
                return 1;
        }
    return 0;
}

/* Whether object i would not exist on the smooth surface a shadow ray
 * leaving patch `start` belongs to: one of its neighbouring facets. */
static int smooth_ignores(const ref_rt *rt, long start, size_t i)
{
    const rt_object *s, *o;
    if (!rt->smooth_shadows || start < 0)
        return 0;
    s = &rt->objects[start];
    o = &rt->objects[i];
    if (s->kind != RT_POLYGON || !s->has_normals || o->kind != RT_POLYGON || !o->has_normals)
        return 0;
    return shares_vertex(rt, s, o);
}

/* Visibility of light position l from p (product of transmissions of the
 * objects the segment crosses, each once). */
static double visibility(const ref_rt *rt, ref_vec3 p, long start, ref_vec3 l)
{
    rt_ray s;
    double u, vis = 1;
    size_t i;
    u = ref_unit(ref_sub(l, p), &s.d);
    if (u == 0)
        return 1;
    s.o = p;
    s.start = start;
    s.inside = -1;
    s.primary = 0;
    for (i = 0; i < rt->object_count && vis > 0; i++) {
        double t;
        if (smooth_ignores(rt, start, i))
            continue;
        t = hit_object(rt, i, &s, rt->eps);
        if (t < u - rt->eps)
            vis *= rt->materials[rt->objects[i].material].transmission;
    }
    return vis;
}

static double fresnel(double c, double n)
{
    double f = ref_fresnel_f(c, n);
    if (isnan(f))
        return 1;
    return f < 0 ? 0 : (f > 1 ? 1 : f);
}

static double trace(const ref_rt *rt, const rt_ray *r, int depth, double path, double background)
{
    const rt_object *o;
    const ref_rt_material *m;
    ref_lighting lit;
    ref_vec3 p, n, n_out, e;
    double t, att = 1, v, c, f, w_r = 0, w_t = 0, path_here;
    long id = nearest(rt, r, &t);
    int j;
    if (id < 0)
        return background;
    o = &rt->objects[id];
    m = &rt->materials[o->material];
    p = ref_add(r->o, ref_scale(r->d, t));
    n_out = object_normal(rt, o, p);
    n = ref_dot(n_out, r->d) > 0 ? ref_scale(n_out, -1) : n_out;
    if (r->inside >= 0)
        att = exp(-rt->materials[rt->objects[r->inside].material].absorption * t);
    path_here = path * att;

    /* local shade with each light's power times its visibility */
    lit = rt->lighting;
    for (j = 0; j < lit.count; j++)
        if (lit.lights[j].power != 0)
            lit.lights[j].power *= visibility(rt, p, id, lit.lights[j].position);
    e = ref_scale(r->d, -1);
    if (r->primary && !rt->perspective)
        v = ref_shade_point(&lit, &m->surface, n, p, r->o, 1, e);
    else
        v = ref_shade_point(&lit, &m->surface, n, p, r->o, 0, e);

    c = ref_dot(e, n);
    f = fresnel(c, m->surface.refraction);
    if (m->surface.specular > 0)
        w_r = m->surface.specular * f;
    if (m->transmission > 0)
        w_t = m->transmission * (1 - f);

    {
        rt_ray tr, rr;
        int cast_t = 0;
        tr.o = p;
        tr.start = id;
        tr.inside = -1;
        tr.primary = 0;
        tr.d = r->d;
        if (w_t > 0 && o->kind == RT_SPHERE) {
            int entering = ref_dot(r->d, n_out) < 0;
            double eta = entering ? 1 / m->surface.refraction : m->surface.refraction;
            double k = 1 - eta * eta * (1 - c * c);
            if (k < 0) {
                /* total internal reflection: the transmitted share is reflected */
                w_r += w_t;
                w_t = 0;
            } else {
                (void)ref_unit(ref_add(ref_scale(r->d, eta), ref_scale(n, eta * c - sqrt(k))), &tr.d);
                if (ref_dot(tr.d, n_out) < 0)
                    tr.inside = id;
            }
        }
        cast_t = w_t > 0;
        rr.o = p;
        rr.start = id;
        rr.primary = 0;
        rr.d = ref_sub(r->d, ref_scale(n, 2 * ref_dot(r->d, n)));
        rr.inside = o->kind == RT_SPHERE && ref_dot(rr.d, n_out) < 0 ? id : -1;
        if (w_r > 0 && depth < rt->max_depth && path_here * w_r >= rt->min_weight)
            v += w_r * trace(rt, &rr, depth + 1, path_here * w_r, background);
        if (cast_t && depth < rt->max_depth && path_here * w_t >= rt->min_weight)
            v += w_t * trace(rt, &tr, depth + 1, path_here * w_t, background);
    }
    if (v > 1)
        v = 1;
    return att * v;
}

/* ---- pixels */

int ref_rt_primary_ray(const ref_rt *rt, int x, int y, ref_vec3 *origin, ref_vec3 *dir)
{
    double px, py;
    if (!rt || x < 0 || y < 0 || x >= rt->width || y >= rt->height)
        return REF_ERR_ARG;
    px = x + 0.5 - rt->width / 2.0;
    py = rt->height / 2.0 - y - 0.5;
    if (rt->perspective) {
        *origin = rt->from;
        (void)ref_unit(ref_add(ref_add(ref_scale(rt->right, px), ref_scale(rt->up, py)),
                            ref_scale(rt->forward, rt->focal)),
                       dir);
    } else {
        *origin = ref_add(rt->from, ref_add(ref_scale(rt->right, px / rt->focal), ref_scale(rt->up, py / rt->focal)));
        *dir = rt->forward;
    }
    return REF_OK;
}

static int materials_ok(const ref_rt *rt)
{
    size_t i;
    for (i = 0; i < rt->object_count; i++)
        if ((size_t)rt->objects[i].material >= rt->material_count)
            return 0;
    return 1;
}

double ref_rt_trace_pixel(const ref_rt *rt, int x, int y, double background)
{
    rt_ray r;
    if (!rt || ref_rt_primary_ray(rt, x, y, &r.o, &r.d) != REF_OK || !materials_ok(rt))
        return -1;
    r.start = -1;
    r.inside = -1;
    r.primary = 1;
    return trace(rt, &r, 0, 1.0, background);
}

int ref_rt_primary_surface(const ref_rt *rt, int x, int y, ref_vec3 *point, ref_vec3 *normal)
{
    rt_ray r;
    double t;
    long id;
    if (!rt || ref_rt_primary_ray(rt, x, y, &r.o, &r.d) != REF_OK)
        return -1;
    r.start = -1;
    r.inside = -1;
    r.primary = 1;
    id = nearest(rt, &r, &t);
    if (id >= 0) {
        ref_vec3 p = ref_add(r.o, ref_scale(r.d, t)), n = object_normal(rt, &rt->objects[id], p);
        if (ref_dot(n, r.d) > 0)
            n = ref_scale(n, -1);
        if (point)
            *point = p;
        if (normal)
            *normal = n;
    }
    return (int)id;
}

int ref_rt_primary_hit(const ref_rt *rt, int x, int y, double *t)
{
    rt_ray r;
    double tt = -1;
    long id = -1;
    if (rt && ref_rt_primary_ray(rt, x, y, &r.o, &r.d) == REF_OK) {
        r.start = -1;
        r.inside = -1;
        r.primary = 1;
        id = nearest(rt, &r, &tt);
    }
    if (t)
        *t = tt;
    return (int)id;
}
