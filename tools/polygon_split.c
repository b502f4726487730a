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

/* Ear clipping: triangles written to idx (3 each).  Returns the number of
 * triangles, or -1 when no ear is left (a self-intersecting outline). */
static int ear_clip(const point2 *p, int count, int orient, int *idx)
{
    int *ring = malloc(sizeof *ring * (size_t)count);
    int n = count, made = 0, i, guard = 0;
    if (!ring)
        return -1;
    for (i = 0; i < count; i++)
        ring[i] = i;
    i = 0;
    while (n > 3) {
        int a = ring[(i + n - 1) % n], b = ring[i % n], c = ring[(i + 1) % n];
        int ear = orient * turn(p[a], p[b], p[c]) > 0, k;
        for (k = 0; ear && k < n; k++) {
            int q = ring[k];
            if (q == a || q == b || q == c)
                continue;
            /* a vertex on the ear's corner (a repeated point) does not block it */
            if ((p[q].x == p[a].x && p[q].y == p[a].y) || (p[q].x == p[c].x && p[q].y == p[c].y))
                continue;
            if (in_triangle(p[q], p[a], p[b], p[c], orient))
                ear = 0;
        }
        if (!ear && orient * turn(p[a], p[b], p[c]) == 0 && guard >= n) {
            /* a straight vertex no ear can take: drop it, the outline is
             * the same without it */
            ear = 2;
        }
        if (ear) {
            int j;
            if (ear == 1) {
                idx[3 * made] = a;
                idx[3 * made + 1] = b;
                idx[3 * made + 2] = c;
                made++;
            }
            for (j = i % n; j < n - 1; j++)
                ring[j] = ring[j + 1];
            n--;
            guard = 0;
            continue;
        }
        i = (i + 1) % n;
        if (++guard > 2 * n) {
            free(ring);
            return -1;
        }
    }
    if (orient * turn(p[ring[0]], p[ring[1]], p[ring[2]]) != 0) {
        idx[3 * made] = ring[0];
        idx[3 * made + 1] = ring[1];
        idx[3 * made + 2] = ring[2];
        made++;
    }
    free(ring);
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
