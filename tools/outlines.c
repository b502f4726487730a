/* SPDX-License-Identifier: MIT */
/* Host side: silhouette and crease edges, cut to their visible pieces
 * (outlines.h). */
#include "outlines.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

typedef stp_scene_vec3 vec;

static vec sub(vec a, vec b) { vec r = {a.x - b.x, a.y - b.y, a.z - b.z}; return r; }
static vec add_scaled(vec a, vec b, double s) { vec r = {a.x + b.x * s, a.y + b.y * s, a.z + b.z * s}; return r; }
static double dot(vec a, vec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static vec cross(vec a, vec b)
{
    vec r = {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
    return r;
}
static int unit(vec *v)
{
    double l = sqrt(dot(*v, *v));
    if (!(l > 0))
        return -1;
    v->x /= l;
    v->y /= l;
    v->z /= l;
    return 0;
}

/* The view's frame as src/view.c builds it (left-handed: right = dir x up). */
typedef struct eye_frame {
    vec from, forward, right, up;
    double focal; /* pixels */
    double w, h;
    int perspective;
} eye_frame;

static int eye_frame_make(const stp_outline_view *v, eye_frame *e)
{
    double short_side = v->width < v->height ? v->width : v->height;
    vec upn = v->up;
    e->from = v->from;
    e->forward = sub(v->at, v->from);
    if (unit(&e->forward) || unit(&upn))
        return -1;
    e->right = cross(e->forward, upn);
    if (unit(&e->right))
        return -1;
    e->up = cross(e->right, e->forward);
    (void)unit(&e->up);
    e->perspective = v->perspective;
    e->w = v->width;
    e->h = v->height;
    if (v->perspective) {
        double half = v->fov_degrees * 3.14159265358979323846 / 360.0;
        if (!(half > 0) || !(tan(half) > 0))
            return -1;
        e->focal = short_side / 2 / tan(half);
    } else {
        if (!(v->window_half > 0))
            return -1;
        e->focal = short_side / 2 / v->window_half;
    }
    return 0;
}

static int project(const eye_frame *e, vec p, double *x, double *y)
{
    vec d = sub(p, e->from);
    double vx = dot(d, e->right), vy = dot(d, e->up), vz = dot(d, e->forward);
    if (e->perspective) {
        if (!(vz > 0))
            return -1;
        vx /= vz;
        vy /= vz;
    }
    *x = e->w / 2 + e->focal * vx;
    *y = e->h / 2 - e->focal * vy;
    return 0;
}

int stp_outline_project(const stp_outline_view *view, stp_scene_vec3 p, double *x, double *y)
{
    eye_frame e;
    if (eye_frame_make(view, &e) != 0)
        return -1;
    return project(&e, p, x, y);
}

/* A polygon's plane: unit Newell normal n, n . X = d; 0 for no area. */
typedef struct plane {
    vec n;
    double d;
    int ok;
} plane;

static plane polygon_plane(const stp_scene *s, const stp_scene_polygon *p)
{
    plane pl;
    vec n = {0, 0, 0};
    int k;
    for (k = 0; k < p->count; k++) {
        vec a = s->vertices[p->first + (size_t)k], b = s->vertices[p->first + (size_t)((k + 1) % p->count)];
        n.x += (a.y - b.y) * (a.z + b.z);
        n.y += (a.z - b.z) * (a.x + b.x);
        n.z += (a.x - b.x) * (a.y + b.y);
    }
    pl.ok = unit(&n) == 0;
    pl.n = n;
    pl.d = p->count > 0 ? dot(n, s->vertices[p->first]) : 0;
    return pl;
}

/* One polygon's side of an edge: its end points as quantised keys (lower
 * key first), whether the polygon runs it from the lower key. */
typedef struct half_edge {
    int64_t key[2][3];
    vec a, b; /* the end points, lower key first */
    size_t polygon;
    int forward;
} half_edge;

static int key_compare(const int64_t *a, const int64_t *b)
{
    int i;
    for (i = 0; i < 3; i++)
        if (a[i] != b[i])
            return a[i] < b[i] ? -1 : 1;
    return 0;
}

static int half_edge_compare(const void *pa, const void *pb)
{
    const half_edge *a = pa, *b = pb;
    int c = key_compare(a->key[0], b->key[0]);
    if (c == 0)
        c = key_compare(a->key[1], b->key[1]);
    if (c == 0)
        c = a->polygon < b->polygon ? -1 : (a->polygon > b->polygon ? 1 : 0);
    return c;
}

static void quantise(vec p, double q, int64_t *key)
{
    key[0] = (int64_t)llround(p.x / q);
    key[1] = (int64_t)llround(p.y / q);
    key[2] = (int64_t)llround(p.z / q);
}

/* Every polygon edge as a half edge, sorted so shared edges are adjacent. */
static half_edge *half_edges(const stp_scene *s, size_t *count)
{
    double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0}, diag, q;
    size_t i, n = 0;
    half_edge *h;
    for (i = 0; i < s->vertex_count; i++) {
        double c[3] = {s->vertices[i].x, s->vertices[i].y, s->vertices[i].z};
        int k;
        for (k = 0; k < 3; k++) {
            if (i == 0 || c[k] < lo[k])
                lo[k] = c[k];
            if (i == 0 || c[k] > hi[k])
                hi[k] = c[k];
        }
    }
    diag = sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                (hi[2] - lo[2]) * (hi[2] - lo[2]));
    q = diag > 0 ? diag * 1e-5 : 1e-5; /* NFF files print about 6 digits */
    for (i = 0; i < s->polygon_count; i++)
        n += (size_t)(s->polygons[i].count > 0 ? s->polygons[i].count : 0);
    h = malloc((n ? n : 1) * sizeof *h);
    if (!h)
        return 0;
    n = 0;
    for (i = 0; i < s->polygon_count; i++) {
        const stp_scene_polygon *p = &s->polygons[i];
        int k;
        for (k = 0; k < p->count; k++) {
            vec a = s->vertices[p->first + (size_t)k], b = s->vertices[p->first + (size_t)((k + 1) % p->count)];
            int64_t ka[3], kb[3];
            half_edge *e = &h[n];
            quantise(a, q, ka);
            quantise(b, q, kb);
            if (key_compare(ka, kb) == 0)
                continue; /* a repeated vertex: no edge */
            e->forward = key_compare(ka, kb) < 0;
            memcpy(e->key[0], e->forward ? ka : kb, sizeof ka);
            memcpy(e->key[1], e->forward ? kb : ka, sizeof kb);
            e->a = e->forward ? a : b;
            e->b = e->forward ? b : a;
            e->polygon = i;
            n++;
        }
    }
    qsort(h, n, sizeof *h, half_edge_compare);
    *count = n;
    return h;
}

static int faces_eye(const eye_frame *e, vec n, vec at)
{
    if (e->perspective)
        return dot(n, sub(e->from, at)) > 0;
    return dot(n, e->forward) < 0;
}

/* The kinds (a mask) of the edge shared by the half edges g[0..m-1]. */
static int edge_kind(const eye_frame *e, const half_edge *g, size_t m, const plane *planes,
                     double crease_cos)
{
    vec n1, n2, mid;
    if (m != 2)
        return STP_OUTLINE_SILHOUETTE; /* boundary, or more than two polygons */
    if (!planes[g[0].polygon].ok || !planes[g[1].polygon].ok)
        return 0;
    n1 = planes[g[0].polygon].n;
    n2 = planes[g[1].polygon].n;
    if (g[0].forward == g[1].forward) { /* inconsistent winding */
        n2.x = -n2.x;
        n2.y = -n2.y;
        n2.z = -n2.z;
    }
    mid = add_scaled(g[0].a, sub(g[0].b, g[0].a), 0.5);
    return (faces_eye(e, n1, mid) != faces_eye(e, n2, mid) ? STP_OUTLINE_SILHOUETTE : 0) |
           (dot(n1, n2) < crease_cos ? STP_OUTLINE_CREASE : 0);
}

/* Polygons by the screen cells (2x2 pixels over the picture; points and
 * extents beyond it go to the border cells) their projected extent
 * covers; a polygon reaching behind the eye is in every cell. */
typedef struct grid {
    double x0, y0, cw, ch;
    int nx, ny;
    size_t *start; /* nx*ny + 1 offsets into items */
    size_t *items;
} grid;

static int clamp_cell(double v, int n)
{
    return v < 0 ? 0 : (v >= n ? n - 1 : (int)v);
}

static void polygon_cells(const stp_scene *s, const eye_frame *e, size_t i, const grid *g, int *c)
{
    const stp_scene_polygon *p = &s->polygons[i];
    double xl = 0, xh = 0, yl = 0, yh = 0;
    int k;
    for (k = 0; k < p->count; k++) {
        double x, y;
        if (project(e, s->vertices[p->first + (size_t)k], &x, &y) != 0) {
            c[0] = c[1] = 0;
            c[2] = g->nx - 1;
            c[3] = g->ny - 1;
            return;
        }
        if (k == 0 || x < xl) xl = x;
        if (k == 0 || x > xh) xh = x;
        if (k == 0 || y < yl) yl = y;
        if (k == 0 || y > yh) yh = y;
    }
    c[0] = clamp_cell(floor((xl - g->x0) / g->cw), g->nx);
    c[1] = clamp_cell(floor((yl - g->y0) / g->ch), g->ny);
    c[2] = clamp_cell(floor((xh - g->x0) / g->cw), g->nx);
    c[3] = clamp_cell(floor((yh - g->y0) / g->ch), g->ny);
}

static int grid_build(const stp_scene *s, const eye_frame *e, grid *g)
{
    size_t i, cells;
    int pass;
    g->nx = (int)(e->w / 2) + 2;
    g->ny = (int)(e->h / 2) + 2;
    g->nx = g->nx > 1024 ? 1024 : g->nx;
    g->ny = g->ny > 1024 ? 1024 : g->ny;
    /* one cell of margin each side of the picture */
    g->cw = (e->w + 2) / (g->nx - 2 > 0 ? g->nx - 2 : 1);
    g->ch = (e->h + 2) / (g->ny - 2 > 0 ? g->ny - 2 : 1);
    g->x0 = -1 - g->cw;
    g->y0 = -1 - g->ch;
    cells = (size_t)g->nx * (size_t)g->ny;
    g->start = calloc(cells + 1, sizeof *g->start);
    g->items = 0;
    if (!g->start)
        return -1;
    for (pass = 0; pass < 2; pass++) {
        for (i = 0; i < s->polygon_count; i++) {
            int c[4], x, y;
            polygon_cells(s, e, i, g, c);
            for (y = c[1]; y <= c[3]; y++)
                for (x = c[0]; x <= c[2]; x++) {
                    size_t cell = (size_t)y * (size_t)g->nx + (size_t)x;
                    if (pass == 0)
                        g->start[cell + 1]++;
                    else
                        g->items[g->start[cell]++] = i;
                }
        }
        if (pass == 0) {
            for (i = 1; i <= cells; i++)
                g->start[i] += g->start[i - 1];
            g->items = malloc((g->start[cells] ? g->start[cells] : 1) * sizeof *g->items);
            if (!g->items)
                return -1;
        } else {
            /* the fill moved each start to the next cell's: shift back */
            for (i = cells; i > 0; i--)
                g->start[i] = g->start[i - 1];
            g->start[0] = 0;
        }
    }
    return 0;
}

/* Whether the segment from p towards the eye meets polygon i. */
static int blocks(const stp_scene *s, const plane *pl, size_t i, const eye_frame *e, vec p)
{
    const stp_scene_polygon *poly = &s->polygons[i];
    vec dir = e->perspective ? sub(e->from, p) : add_scaled((vec){0, 0, 0}, e->forward, -1);
    double denom, t, hu, hv;
    vec hit;
    int k, inside = 0, drop;
    double an[3];
    if (!pl[i].ok)
        return 0;
    denom = dot(pl[i].n, dir);
    if (fabs(denom) < 1e-12)
        return 0;
    t = (pl[i].d - dot(pl[i].n, p)) / denom;
    if (!(t > 1e-9) || (e->perspective && !(t < 1)))
        return 0;
    hit = add_scaled(p, dir, t);
    if (!e->perspective && !(dot(sub(hit, e->from), e->forward) > 0))
        return 0; /* behind the viewer */
    an[0] = fabs(pl[i].n.x);
    an[1] = fabs(pl[i].n.y);
    an[2] = fabs(pl[i].n.z);
    drop = an[0] >= an[1] && an[0] >= an[2] ? 0 : (an[1] >= an[2] ? 1 : 2);
    hu = drop == 0 ? hit.y : hit.x;
    hv = drop == 2 ? hit.y : hit.z;
    for (k = 0; k < poly->count; k++) {
        vec a = s->vertices[poly->first + (size_t)k];
        vec b = s->vertices[poly->first + (size_t)((k + 1) % poly->count)];
        double au = drop == 0 ? a.y : a.x, av = drop == 2 ? a.y : a.z;
        double bu = drop == 0 ? b.y : b.x, bv = drop == 2 ? b.y : b.z;
        double eu = bu - au, ev = bv - av, len2 = eu * eu + ev * ev, f;
        if ((av > hv) != (bv > hv) && hu < au + (hv - av) * eu / ev)
            inside = !inside;
        /* on the boundary (to 1e-9 of the side): an occluder too, so a
         * ray through the seam of two polygons is not let through */
        f = len2 > 0 ? ((hu - au) * eu + (hv - av) * ev) / len2 : 0;
        f = f < 0 ? 0 : (f > 1 ? 1 : f);
        if ((hu - au - f * eu) * (hu - au - f * eu) + (hv - av - f * ev) * (hv - av - f * ev) <=
            1e-18 * len2)
            return 1;
    }
    return inside;
}

static int point_visible(const stp_scene *s, const plane *pl, const grid *g, const eye_frame *e, vec p,
                         const half_edge *own, size_t own_count)
{
    double x, y;
    int cx, cy;
    size_t k;
    if (project(e, p, &x, &y) != 0)
        return 0;
    cx = clamp_cell(floor((x - g->x0) / g->cw), g->nx);
    cy = clamp_cell(floor((y - g->y0) / g->ch), g->ny);
    for (k = g->start[(size_t)cy * (size_t)g->nx + (size_t)cx];
         k < g->start[(size_t)cy * (size_t)g->nx + (size_t)cx + 1]; k++) {
        size_t i = g->items[k], j;
        int mine = 0;
        for (j = 0; j < own_count; j++)
            mine |= own[j].polygon == i;
        if (!mine && blocks(s, pl, i, e, p))
            return 0;
    }
    return 1;
}

/* Append the visible pieces of one edge. */
static int add_pieces(const stp_scene *s, const plane *pl, const grid *g, const eye_frame *e,
                      const half_edge *own, size_t own_count, int kind, stp_outline_segment **out,
                      size_t *count, size_t *cap)
{
    vec a = own[0].a, b = own[0].b, d = sub(b, a);
    double xa, ya, xb, yb, len = 16;
    int n, k, run = -1;
    if (project(e, a, &xa, &ya) == 0 && project(e, b, &xb, &yb) == 0)
        len = sqrt((xb - xa) * (xb - xa) + (yb - ya) * (yb - ya));
    n = (int)ceil(4 * len);
    n = n < 1 ? 1 : (n > 4096 ? 4096 : n);
    for (k = 0; k <= n; k++) {
        int vis = k < n && point_visible(s, pl, g, e, add_scaled(a, d, (k + 0.5) / n), own, own_count);
        if (vis && run < 0)
            run = k;
        if (!vis && run >= 0) {
            if (*count == *cap) {
                size_t nc = *cap ? 2 * *cap : 64;
                stp_outline_segment *m = realloc(*out, nc * sizeof *m);
                if (!m)
                    return -1;
                *out = m;
                *cap = nc;
            }
            (*out)[*count].a = add_scaled(a, d, (double)run / n);
            (*out)[*count].b = add_scaled(a, d, (double)k / n);
            (*out)[*count].kind = kind;
            (*count)++;
            run = -1;
        }
    }
    return 0;
}

int stp_outlines_find(const stp_scene *scene, const stp_outline_view *view, int kinds,
                      double crease_degrees, stp_outline_segment **out, size_t *count)
{
    eye_frame e;
    plane *planes = 0;
    half_edge *h = 0;
    grid g = {0, 0, 0, 0, 0, 0, 0, 0};
    size_t n = 0, i, j, cap = 0;
    double crease_cos = cos(crease_degrees * 3.14159265358979323846 / 180.0);
    int rc = -1;
    *out = 0;
    *count = 0;
    if (eye_frame_make(view, &e) != 0)
        return -1;
    planes = malloc((scene->polygon_count ? scene->polygon_count : 1) * sizeof *planes);
    if (!planes)
        goto done;
    for (i = 0; i < scene->polygon_count; i++)
        planes[i] = polygon_plane(scene, &scene->polygons[i]);
    if (!(h = half_edges(scene, &n)) || grid_build(scene, &e, &g) != 0)
        goto done;
    for (i = 0; i < n; i = j) {
        int kind;
        for (j = i + 1; j < n && key_compare(h[i].key[0], h[j].key[0]) == 0 &&
                        key_compare(h[i].key[1], h[j].key[1]) == 0;
             j++)
            ;
        kind = edge_kind(&e, &h[i], j - i, planes, crease_cos);
        if ((kind & kinds) &&
            add_pieces(scene, planes, &g, &e, &h[i], j - i, kind, out, count, &cap) != 0)
            goto done;
    }
    rc = 0;
done:
    if (rc != 0) {
        free(*out);
        *out = 0;
        *count = 0;
    }
    free(planes);
    free(h);
    free(g.start);
    free(g.items);
    return rc;
}
