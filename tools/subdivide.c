/* SPDX-License-Identifier: MIT */
/* Subdivision of large smooth polygons: see subdivide.h. */
#include "subdivide.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_LEVEL 6

typedef struct growing {
    stp_scene_vec3 *vertices, *normals;
    size_t vertex_count, vertex_cap;
    stp_scene_polygon *polygons;
    size_t polygon_count, polygon_cap;
} growing;

static double distance(stp_scene_vec3 a, stp_scene_vec3 b)
{
    return sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) + (a.z - b.z) * (a.z - b.z));
}

static stp_scene_vec3 mix3(stp_scene_vec3 a, stp_scene_vec3 b, stp_scene_vec3 c, double u, double v)
{
    stp_scene_vec3 r;
    r.x = a.x + (b.x - a.x) * u + (c.x - a.x) * v;
    r.y = a.y + (b.y - a.y) * u + (c.y - a.y) * v;
    r.z = a.z + (b.z - a.z) * u + (c.z - a.z) * v;
    return r;
}

static stp_scene_vec3 unit(stp_scene_vec3 v)
{
    double len = sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    if (len > 0) {
        v.x /= len;
        v.y /= len;
        v.z /= len;
    }
    return v;
}

static int grow(growing *g, size_t vertices, size_t polygons)
{
    if (g->vertex_count + vertices > g->vertex_cap) {
        size_t cap = (g->vertex_count + vertices) * 2;
        stp_scene_vec3 *v = realloc(g->vertices, sizeof *v * cap), *n;
        if (!v)
            return -1;
        g->vertices = v;
        n = realloc(g->normals, sizeof *n * cap);
        if (!n)
            return -1;
        g->normals = n;
        g->vertex_cap = cap;
    }
    if (g->polygon_count + polygons > g->polygon_cap) {
        size_t cap = (g->polygon_count + polygons) * 2;
        stp_scene_polygon *p = realloc(g->polygons, sizeof *p * cap);
        if (!p)
            return -1;
        g->polygons = p;
        g->polygon_cap = cap;
    }
    return 0;
}

/* Append polygon p of scene unchanged. */
static int copy_polygon(growing *g, const stp_scene *scene, const stp_scene_polygon *p)
{
    int k;
    if (grow(g, (size_t)p->count, 1) != 0)
        return -1;
    g->polygons[g->polygon_count] = *p;
    g->polygons[g->polygon_count].first = g->vertex_count;
    g->polygon_count++;
    for (k = 0; k < p->count; k++) {
        g->vertices[g->vertex_count] = scene->vertices[p->first + (size_t)k];
        g->normals[g->vertex_count] = scene->normals ? scene->normals[p->first + (size_t)k]
                                                     : (stp_scene_vec3){0, 0, 0};
        g->vertex_count++;
    }
    return 0;
}

/* Append triangle (a, b, c) of polygon p (vertex indices into scene) cut
 * into n x n pieces on the grid a + (b - a) i/n + (c - a) j/n, winding
 * kept. */
static int split_triangle(growing *g, const stp_scene *scene, const stp_scene_polygon *p, size_t a,
                          size_t b, size_t c, int n)
{
    int i, j, t;
    const stp_scene_vec3 *V = scene->vertices, *N = scene->normals;
    if (grow(g, (size_t)(2 * n * n) * 3, (size_t)(2 * n * n)) != 0)
        return -1;
    for (j = 0; j < n; j++)
        for (i = 0; i + j < n; i++) {
            /* the upright piece, and the inverted one beside it */
            double corners[2][3][2] = {{{i, j}, {i + 1, j}, {i, j + 1}},
                                       {{i + 1, j}, {i + 1, j + 1}, {i, j + 1}}};
            for (t = 0; t < (i + j + 1 < n ? 2 : 1); t++) {
                int k;
                stp_scene_polygon q = *p;
                q.first = g->vertex_count;
                q.count = 3;
                for (k = 0; k < 3; k++) {
                    double u = corners[t][k][0] / n, v = corners[t][k][1] / n;
                    g->vertices[g->vertex_count] = mix3(V[a], V[b], V[c], u, v);
                    g->normals[g->vertex_count] =
                        (N && p->has_normals) ? unit(mix3(N[a], N[b], N[c], u, v)) : (stp_scene_vec3){0, 0, 0};
                    g->vertex_count++;
                }
                g->polygons[g->polygon_count++] = q;
            }
        }
    return 0;
}

/* The pieces per side a polygon needs: 2^k, the least with the longest
 * edge / 2^k <= a quarter of its centroid's distance to the nearest light
 * (k <= MAX_LEVEL); 1 when no split is needed. */
static int pieces(const stp_scene *scene, const stp_scene_polygon *p, const stp_lighting *lighting)
{
    stp_scene_vec3 centroid = {0, 0, 0};
    double longest = 0, nearest = 1e300, limit;
    int k, n = 1, level;
    for (k = 0; k < p->count; k++) {
        stp_scene_vec3 a = scene->vertices[p->first + (size_t)k],
                       b = scene->vertices[p->first + (size_t)((k + 1) % p->count)];
        double d = distance(a, b);
        centroid.x += a.x / p->count;
        centroid.y += a.y / p->count;
        centroid.z += a.z / p->count;
        if (d > longest)
            longest = d;
    }
    for (k = 0; k < lighting->count; k++) {
        stp_scene_vec3 l;
        double d;
        l.x = (double)lighting->lights[k].position.x / STP_FIX_ONE;
        l.y = (double)lighting->lights[k].position.y / STP_FIX_ONE;
        l.z = (double)lighting->lights[k].position.z / STP_FIX_ONE;
        d = distance(l, centroid);
        if (d < nearest)
            nearest = d;
    }
    limit = nearest / 4;
    for (level = 0; level < MAX_LEVEL && longest / n > limit; level++)
        n *= 2;
    return n;
}

int stp_tool_subdivide(const stp_scene *scene, const stp_tool_options *opt, stp_scene *out, char *err,
                       size_t err_size)
{
    stp_view view;
    stp_lighting lighting;
    growing g;
    size_t i;
    int any = 0;
    if (stp_tool_setup(scene, opt, &view, &lighting, err, err_size) != 0)
        return -1;
    if (lighting.count == 0)
        return 0;
    for (i = 0; i < scene->polygon_count && !any; i++)
        any = pieces(scene, &scene->polygons[i], &lighting) > 1;
    if (!any)
        return 0;
    memset(&g, 0, sizeof g);
    for (i = 0; i < scene->polygon_count; i++) {
        const stp_scene_polygon *p = &scene->polygons[i];
        int n = pieces(scene, p, &lighting), k, rc = 0;
        if (n == 1) {
            rc = copy_polygon(&g, scene, p);
        } else {
            for (k = 1; k + 1 < p->count && rc == 0; k++)
                rc = split_triangle(&g, scene, p, p->first, p->first + (size_t)k, p->first + (size_t)k + 1, n);
        }
        if (rc != 0) {
            free(g.vertices);
            free(g.normals);
            free(g.polygons);
            snprintf(err, err_size, "out of memory subdividing polygons");
            return -1;
        }
    }
    *out = *scene;
    out->vertices = g.vertices;
    out->normals = g.normals;
    out->vertex_count = g.vertex_count;
    out->polygons = g.polygons;
    out->polygon_count = g.polygon_count;
    return 1;
}

void stp_tool_subdivided_free(stp_scene *out)
{
    free(out->vertices);
    free(out->normals);
    free(out->polygons);
}
