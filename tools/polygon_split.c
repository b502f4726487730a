/* SPDX-License-Identifier: MIT */
/* Host side: polygons above the build's vertex limit cut into pieces the
 * core takes.  See scene_prepare.h (stp_tool_split_polygon). */
#include <math.h>
#include <stdlib.h>

#include "scene_prepare.h"

#define TWO_PI 6.28318530717958647692

typedef struct point2 {
    double x, y;
} point2;

/* The polygon in the plane of its Newell normal: the coordinate along the
 * normal's largest component is dropped (the projection keeps convexity
 * and which points lie inside).  Returns the sign of the projected area
 * (+1 counter-clockwise, -1 clockwise, 0 none). */
static int project(const stp_scene_vec3 *v, int count, point2 *out)
{
    double nx = 0, ny = 0, nz = 0, area = 0;
    int i, axis;
    for (i = 0; i < count; i++) {
        const stp_scene_vec3 *a = &v[i], *b = &v[(i + 1) % count];
        nx += (a->y - b->y) * (a->z + b->z);
        ny += (a->z - b->z) * (a->x + b->x);
        nz += (a->x - b->x) * (a->y + b->y);
    }
    axis = fabs(nx) >= fabs(ny) && fabs(nx) >= fabs(nz) ? 0 : fabs(ny) >= fabs(nz) ? 1 : 2;
    for (i = 0; i < count; i++) {
        out[i].x = axis == 0 ? v[i].y : v[i].x;
        out[i].y = axis == 2 ? v[i].y : v[i].z;
    }
    for (i = 0; i < count; i++) {
        const point2 *a = &out[i], *b = &out[(i + 1) % count];
        area += a->x * b->y - a->y * b->x;
    }
    return area > 0 ? 1 : area < 0 ? -1 : 0;
}

static double turn(point2 a, point2 b, point2 c)
{
    return (b.x - a.x) * (c.y - b.y) - (b.y - a.y) * (c.x - b.x);
}

/* Convex: every turn one way (straight ones allowed) and one full turn in
 * all (a pentagram turns one way too, but twice round). */
static int is_convex(const point2 *p, int count)
{
    double total = 0;
    int i, sign = 0;
    for (i = 0; i < count; i++) {
        point2 a = p[(i + count - 1) % count], b = p[i], c = p[(i + 1) % count];
        double t = turn(a, b, c);
        int s = t > 0 ? 1 : t < 0 ? -1 : 0;
        if (s != 0 && sign != 0 && s != sign)
            return 0;
        if (s != 0)
            sign = s;
        total += atan2(t, (b.x - a.x) * (c.x - b.x) + (b.y - a.y) * (c.y - b.y));
    }
    return fabs(fabs(total) - TWO_PI) < 1e-6;
}

/* p inside or on triangle abc (orientation sign o). */
static int in_triangle(point2 p, point2 a, point2 b, point2 c, int o)
{
    return o * turn(a, b, p) >= 0 && o * turn(b, c, p) >= 0 && o * turn(c, a, p) >= 0;
}

/* Ear clipping over a ring of vertices (prev/next links), with the
 * reflex vertices (the only ones that can lie inside a candidate ear) in a
 * uniform grid of about count cells over the outline's bounds: an ear test
 * looks only at the reflex vertices of the cells its triangle's bounds
 * meet, so a polygon of n vertices takes about O(n) tests of O(1) points
 * when its reflex vertices are spread out (O(n^2) at worst, for reflex
 * vertices crowded into the cells of every ear).  A vertex that stops
 * being reflex or leaves the ring stays in its cell and is skipped. */
typedef struct ear_ring {
    const point2 *p;
    int orient;
    int *prev, *next, *reflex, *cell_head, *cell_next;
    int cols, rows;
    double x0, y0, cw, ch;
} ear_ring;

static int cell_coord(double v, double origin, double size, int cells)
{
    double c = size > 0 ? (v - origin) / size : 0;
    if (!(c >= 0))
        return 0;
    return c >= cells ? cells - 1 : (int)c;
}

static int is_reflex(const ear_ring *e, int b)
{
    return e->orient * turn(e->p[e->prev[b]], e->p[b], e->p[e->next[b]]) <= 0;
}

/* No reflex vertex of the ring other than a, b, c inside or on abc.
 * Vertices no longer reflex, or out of the ring, leave the cells here. */
static int ear_empty(ear_ring *e, int a, int b, int c)
{
    const point2 *p = e->p;
    double lx = fmin(p[a].x, fmin(p[b].x, p[c].x)), hx = fmax(p[a].x, fmax(p[b].x, p[c].x));
    double ly = fmin(p[a].y, fmin(p[b].y, p[c].y)), hy = fmax(p[a].y, fmax(p[b].y, p[c].y));
    int cx0 = cell_coord(lx, e->x0, e->cw, e->cols), cx1 = cell_coord(hx, e->x0, e->cw, e->cols);
    int cy0 = cell_coord(ly, e->y0, e->ch, e->rows), cy1 = cell_coord(hy, e->y0, e->ch, e->rows);
    int cx, cy, q, *link;
    for (cy = cy0; cy <= cy1; cy++)
        for (cx = cx0; cx <= cx1; cx++)
            for (link = &e->cell_head[cy * e->cols + cx]; (q = *link) >= 0;) {
                if (!e->reflex[q] || e->next[q] < 0) {
                    *link = e->cell_next[q]; /* out of the cell */
                    continue;
                }
                link = &e->cell_next[q];
                if (q == a || q == b || q == c)
                    continue;
                if (p[q].x < lx || p[q].x > hx || p[q].y < ly || p[q].y > hy)
                    continue;
                /* a vertex on the ear's corner (a repeated point) does not block it */
                if ((p[q].x == p[a].x && p[q].y == p[a].y) || (p[q].x == p[c].x && p[q].y == p[c].y))
                    continue;
                if (in_triangle(p[q], p[a], p[b], p[c], e->orient))
                    return 0;
            }
    return 1;
}

static int ear_ring_init(ear_ring *e, const point2 *p, int count, int orient)
{
    double hx = p[0].x, hy = p[0].y;
    int i, side;
    e->p = p;
    e->orient = orient;
    e->x0 = p[0].x;
    e->y0 = p[0].y;
    for (i = 1; i < count; i++) {
        e->x0 = fmin(e->x0, p[i].x);
        e->y0 = fmin(e->y0, p[i].y);
        hx = fmax(hx, p[i].x);
        hy = fmax(hy, p[i].y);
    }
    side = (int)sqrt((double)count) + 1;
    e->cols = e->rows = side;
    e->cw = (hx - e->x0) / side;
    e->ch = (hy - e->y0) / side;
    e->prev = malloc(sizeof(int) * (size_t)count * 4);
    e->cell_head = malloc(sizeof(int) * (size_t)side * (size_t)side);
    if (!e->prev || !e->cell_head) {
        free(e->prev);
        free(e->cell_head);
        return -1;
    }
    e->next = e->prev + count;
    e->reflex = e->next + count;
    e->cell_next = e->reflex + count;
    for (i = 0; i < side * side; i++)
        e->cell_head[i] = -1;
    for (i = 0; i < count; i++) {
        e->prev[i] = (i + count - 1) % count;
        e->next[i] = (i + 1) % count;
    }
    for (i = 0; i < count; i++) {
        int cell = cell_coord(p[i].y, e->y0, e->ch, side) * side + cell_coord(p[i].x, e->x0, e->cw, side);
        e->reflex[i] = is_reflex(e, i);
        e->cell_next[i] = -1;
        if (e->reflex[i]) {
            e->cell_next[i] = e->cell_head[cell];
            e->cell_head[cell] = i;
        }
    }
    return 0;
}

/* Take b out of the ring; its neighbours may stop being reflex. */
static void ear_unlink(ear_ring *e, int b)
{
    int a = e->prev[b], c = e->next[b];
    e->next[a] = c;
    e->prev[c] = a;
    e->next[b] = e->prev[b] = -1;
    e->reflex[a] = e->reflex[a] && is_reflex(e, a);
    e->reflex[c] = e->reflex[c] && is_reflex(e, c);
}

/* Ear clipping: triangles written to idx (3 each).  Returns the number of
 * triangles, or -1 when no ear is left (a self-intersecting outline). */
static int ear_clip(const point2 *p, int count, int orient, int *idx)
{
    ear_ring e;
    int n = count, made = 0, b = 0, failed = 0;
    if (ear_ring_init(&e, p, count, orient) != 0)
        return -1;
    while (n > 3) {
        int a = e.prev[b], c = e.next[b];
        double t = orient * turn(p[a], p[b], p[c]);
        if (t > 0 && ear_empty(&e, a, b, c)) {
            idx[3 * made] = a;
            idx[3 * made + 1] = b;
            idx[3 * made + 2] = c;
            made++;
        } else if (!(t == 0 && failed >= n)) {
            /* not an ear; a straight vertex no ear takes (a full round
             * without one) is dropped below: the outline is the same */
            b = c;
            if (++failed > 2 * n) {
                made = -1;
                break;
            }
            continue;
        }
        ear_unlink(&e, b);
        n--;
        /* on past c: going back to a would fan every later ear round one
         * vertex, ever larger triangles meeting ever more cells */
        b = e.next[c];
        failed = 0;
    }
    if (made >= 0 && orient * turn(p[e.prev[b]], p[b], p[e.next[b]]) != 0) {
        idx[3 * made] = e.prev[b];
        idx[3 * made + 1] = b;
        idx[3 * made + 2] = e.next[b];
        made++;
    }
    free(e.prev);
    free(e.cell_head);
    return made;
}

/* Pieces sharing v[0], each v[0] and a run of at most max - 1 vertices;
 * consecutive runs share their end vertex. */
static int fan(int count, int max, int *idx, int *cnt)
{
    int pieces = 0, start = 1, used = 0;
    while (start < count - 1) {
        int end = start + max - 2, k;
        if (end > count - 1)
            end = count - 1;
        idx[used++] = 0;
        for (k = start; k <= end; k++)
            idx[used++] = k;
        cnt[pieces++] = end - start + 2;
        start = end;
    }
    return pieces;
}

int stp_tool_split_polygon(const stp_scene_vec3 *v, int count, int max, int **piece_index,
                           int **piece_count)
{
    point2 *p;
    int *idx, *cnt, orient, pieces = -1;
    *piece_index = 0;
    *piece_count = 0;
    if (count < 3 || max < 3)
        return -1;
    p = malloc(sizeof *p * (size_t)count);
    /* room for either: a fan uses under 2 count indices, triangles 3 count */
    idx = malloc(sizeof *idx * 3 * (size_t)count);
    cnt = malloc(sizeof *cnt * (size_t)count);
    if (!p || !idx || !cnt) {
        free(p);
        free(idx);
        free(cnt);
        return -1;
    }
    orient = project(v, count, p);
    if (orient != 0 && !is_convex(p, count)) {
        pieces = ear_clip(p, count, orient, idx);
        if (pieces >= 0) {
            int k;
            for (k = 0; k < pieces; k++)
                cnt[k] = 3;
        }
    }
    if (pieces < 0)
        pieces = fan(count, max, idx, cnt);
    free(p);
    *piece_index = idx;
    *piece_count = cnt;
    return pieces;
}

/* The normal of the largest of the four corner triangles of a quad: a
 * plane to see it in even when its own (Newell) normal is zero, as a
 * symmetric bow tie's is. */
static stp_scene_vec3 quad_plane(const stp_scene_vec3 *v)
{
    stp_scene_vec3 best = {0, 0, 0};
    double best_len = -1;
    int i;
    for (i = 0; i < 4; i++) {
        const stp_scene_vec3 *a = &v[i], *b = &v[(i + 1) % 4], *c = &v[(i + 2) % 4];
        double ux = b->x - a->x, uy = b->y - a->y, uz = b->z - a->z;
        double wx = c->x - a->x, wy = c->y - a->y, wz = c->z - a->z;
        stp_scene_vec3 n;
        double len;
        n.x = uy * wz - uz * wy;
        n.y = uz * wx - ux * wz;
        n.z = ux * wy - uy * wx;
        len = fabs(n.x) + fabs(n.y) + fabs(n.z);
        if (len > best_len) {
            best_len = len;
            best = n;
        }
    }
    return best;
}

int stp_tool_bow_tie(const stp_scene_vec3 *v, int *edge, double *t)
{
    stp_scene_vec3 n = quad_plane(v);
    point2 p[4];
    int i, e;
    int axis = fabs(n.x) >= fabs(n.y) && fabs(n.x) >= fabs(n.z) ? 0 : fabs(n.y) >= fabs(n.z) ? 1 : 2;
    if (n.x == 0 && n.y == 0 && n.z == 0)
        return 0;
    for (i = 0; i < 4; i++) {
        p[i].x = axis == 0 ? v[i].y : v[i].x;
        p[i].y = axis == 2 ? v[i].y : v[i].z;
    }
    for (e = 0; e < 2; e++) {
        /* edges e..e+1 and e+2..e+3 cross strictly inside both */
        point2 a = p[e], b = p[e + 1], c = p[e + 2], d = p[(e + 3) % 4];
        double d1 = turn(a, b, c), d2 = turn(a, b, d), d3 = turn(c, d, a), d4 = turn(c, d, b);
        if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) {
            *edge = e;
            *t = d3 / (d3 - d4); /* along a..b */
            return 1;
        }
    }
    return 0;
}
