/* SPDX-License-Identifier: MIT */
/* Host side: a scene made fit for the core.  See scene_prepare.h. */
#include "scene_prepare.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene_util.h"

static stp_scene_vec3 v3(double x, double y, double z)
{
    stp_scene_vec3 v;
    v.x = x;
    v.y = y;
    v.z = z;
    return v;
}

static double dist(stp_scene_vec3 a, stp_scene_vec3 b)
{
    return hypot(hypot(a.x - b.x, a.y - b.y), a.z - b.z);
}

static double max_abs(stp_scene_vec3 v)
{
    return fmax(fabs(v.x), fmax(fabs(v.y), fabs(v.z)));
}

void stp_tool_prepared_free(stp_tool_prepared *p)
{
    if (!p)
        return;
    stp_scene_free(&p->scene);
    free(p->polygon_number);
    memset(p, 0, sizeof *p);
}

size_t stp_tool_prepared_polygon_number(const stp_tool_prepared *p, size_t i)
{
    return p->polygon_number != NULL && i < p->scene.polygon_count ? p->polygon_number[i] : i + 1;
}

/* Number the copy's polygons from first on as coming from the file's
 * polygon p (number file_no among the file's own, 0 for a prim's). */
static void number_pieces(stp_tool_prepared *out, size_t first, const stp_scene_polygon *p,
                          size_t file_no)
{
    for (; first < out->scene.polygon_count; first++)
        out->polygon_number[first] = p->prim < 0 ? file_no : 0;
}

/* ---- copying, with big polygons split ----------------------------------- */

static stp_scene_vec3 lerp(stp_scene_vec3 a, stp_scene_vec3 b, double t)
{
    return v3(a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, a.z + (b.z - a.z) * t);
}

/* A bow tie p (vertices pv, normals pn) appended to s as its two triangles
 * either side of the crossing X: edges v0-v1 and v2-v3 crossing give
 * (X, v1, v2) and (X, v3, v0); v1-v2 and v3-v0 give (X, v2, v3) and
 * (X, v0, v1).  Returns 0 (nothing appended) for a simple quad. */
static int split_bow_tie(const stp_scene_polygon *p, const stp_scene_vec3 *pv,
                         const stp_scene_vec3 *pn, stp_scene *s)
{
    int edge, half, k;
    double t;
    stp_scene_vec3 x, xn;
    if (!stp_tool_bow_tie(pv, &edge, &t))
        return 0;
    x = lerp(pv[edge], pv[edge + 1], t);
    xn = lerp(pn[edge], pn[edge + 1], t);
    for (half = 0; half < 2; half++) {
        stp_scene_polygon *q = &s->polygons[s->polygon_count++];
        int first = (edge + 1 + 2 * half) % 4;
        *q = *p;
        q->first = s->vertex_count;
        q->count = 3;
        s->vertices[s->vertex_count] = x;
        s->normals[s->vertex_count++] = xn;
        for (k = 0; k < 2; k++) {
            s->vertices[s->vertex_count] = pv[(first + k) % 4];
            s->normals[s->vertex_count++] = pn[(first + k) % 4];
        }
    }
    return 1;
}

static int copy_scene(const stp_scene *in, stp_tool_prepared *out)
{
    stp_scene *s = &out->scene;
    size_t nv = 0, np = 0, i, file_no = 0;
    const int max = STP_MAX_POLYGON_VERTICES;

    /* sizes first: a split polygon of n vertices gives at most n pieces of
     * at most 3 (ears) or max (fan) vertices, at most 3n vertex copies */
    for (i = 0; i < in->polygon_count; i++) {
        size_t n = (size_t)in->polygons[i].count;
        nv += n > (size_t)max ? 3 * n : n == 4 ? 6 : n;
        np += n > (size_t)max ? n : n == 4 ? 2 : 1;
    }
    *s = *in;
    s->lights = 0;
    s->light_count = 0;
    s->materials = malloc(sizeof *s->materials * (in->material_count ? in->material_count : 1));
    s->vertices = malloc(sizeof *s->vertices * (nv ? nv : 1));
    s->normals = malloc(sizeof *s->normals * (nv ? nv : 1));
    s->polygons = malloc(sizeof *s->polygons * (np ? np : 1));
    out->polygon_number = malloc(sizeof *out->polygon_number * (np ? np : 1));
    s->prims = malloc(sizeof *s->prims * (in->prim_count ? in->prim_count : 1));
    s->lights = malloc(sizeof *s->lights * (in->light_count > STP_MAX_LIGHTS ? in->light_count
                                                                              : STP_MAX_LIGHTS));
    if (!s->materials || !s->vertices || !s->normals || !s->polygons || !s->prims || !s->lights ||
        !out->polygon_number)
        return -1;
    if (in->material_count)
        memcpy(s->materials, in->materials, sizeof *s->materials * in->material_count);
    if (in->prim_count)
        memcpy(s->prims, in->prims, sizeof *s->prims * in->prim_count);
    s->vertex_count = 0;
    s->polygon_count = 0;
    for (i = 0; i < in->polygon_count; i++) {
        const stp_scene_polygon *p = &in->polygons[i];
        const stp_scene_vec3 *pv = &in->vertices[p->first], *pn = &in->normals[p->first];
        int *idx = 0, *cnt = 0, pieces, k, used = 0;
        size_t first_piece = s->polygon_count;
        file_no += p->prim < 0;
        if (p->count == 4 && split_bow_tie(p, pv, pn, s)) {
            number_pieces(out, first_piece, p, file_no);
            out->polygons_split++;
            continue;
        }
        if (p->count <= max) {
            memcpy(&s->vertices[s->vertex_count], pv, sizeof *pv * (size_t)p->count);
            memcpy(&s->normals[s->vertex_count], pn, sizeof *pn * (size_t)p->count);
            s->polygons[s->polygon_count] = *p;
            s->polygons[s->polygon_count++].first = s->vertex_count;
            s->vertex_count += (size_t)p->count;
            number_pieces(out, first_piece, p, file_no);
            continue;
        }
        pieces = stp_tool_split_polygon(pv, p->count, max, &idx, &cnt);
        if (pieces < 0)
            return -1;
        for (k = 0; k < pieces; k++) {
            stp_scene_polygon *q = &s->polygons[s->polygon_count++];
            int j;
            *q = *p;
            q->first = s->vertex_count;
            q->count = cnt[k];
            for (j = 0; j < cnt[k]; j++) {
                s->vertices[s->vertex_count] = pv[idx[used + j]];
                s->normals[s->vertex_count++] = pn[idx[used + j]];
            }
            used += cnt[k];
        }
        free(idx);
        free(cnt);
        number_pieces(out, first_piece, p, file_no);
        out->polygons_split++;
    }
    return 0;
}

/* ---- lights ----------------------------------------------------------- */

/* The lights in use (--light's, else the file's) into the copy, merged
 * down to STP_MAX_LIGHTS: while there are too many, the two whose
 * directions from the scene's centre make the smallest angle become one,
 * in their mean direction (weighted by how many lights each stands for) at
 * their mean distance, with their mean colour and their summed weight.
 * Seen from the scene, a pair of lights in nearly one direction lights it
 * nearly as one light of their summed power does. */
static int gather_lights(const stp_scene *in, const stp_tool_options *opt, stp_scene_vec3 centre,
                         stp_tool_prepared *out)
{
    stp_scene *s = &out->scene;
    size_t n, i, j;
    /* one weight per light in use: the file may have any number of them */
    size_t given = opt->light_count > 0 ? (size_t)opt->light_count : in->light_count;
    double *weight = malloc(sizeof *weight * (given > 0 ? given : 1));
    if (!weight)
        return -1;
    if (opt->light_count > 0) {
        for (i = 0; i < (size_t)opt->light_count; i++) {
            s->lights[i].position = opt->lights[i];
            s->lights[i].color[0] = s->lights[i].color[1] = s->lights[i].color[2] = 1.0;
            weight[i] = 1.0;
        }
        n = (size_t)opt->light_count;
        out->opt.light_count = 0; /* now the copy's own */
    } else {
        for (i = 0; i < in->light_count; i++) {
            s->lights[i] = in->lights[i];
            weight[i] = 1.0;
        }
        n = in->light_count;
    }
    out->lights_in = n;
    while (n > STP_MAX_LIGHTS) {
        size_t bi = 0, bj = 1;
        double best = -2;
        stp_scene_light merged;
        stp_scene_vec3 d[2], m;
        double w0, w1, len, r;
        int c;
        for (i = 0; i < n; i++)
            for (j = i + 1; j < n; j++) {
                stp_scene_vec3 a = s->lights[i].position, b = s->lights[j].position;
                double la = dist(a, centre), lb = dist(b, centre), cosang;
                if (!(la > 0) || !(lb > 0))
                    cosang = 1; /* a light at the centre goes first */
                else
                    cosang = ((a.x - centre.x) * (b.x - centre.x) + (a.y - centre.y) * (b.y - centre.y) +
                              (a.z - centre.z) * (b.z - centre.z)) / (la * lb);
                if (cosang > best) {
                    best = cosang;
                    bi = i;
                    bj = j;
                }
            }
        w0 = weight[bi];
        w1 = weight[bj];
        for (c = 0; c < 2; c++) {
            stp_scene_vec3 p = s->lights[c ? bj : bi].position;
            double l = dist(p, centre);
            d[c] = l > 0 ? v3((p.x - centre.x) / l, (p.y - centre.y) / l, (p.z - centre.z) / l)
                         : v3(0, 0, 0);
        }
        m = v3(w0 * d[0].x + w1 * d[1].x, w0 * d[0].y + w1 * d[1].y, w0 * d[0].z + w1 * d[1].z);
        len = hypot(hypot(m.x, m.y), m.z);
        r = (w0 * dist(s->lights[bi].position, centre) + w1 * dist(s->lights[bj].position, centre)) /
            (w0 + w1);
        if (len > 0)
            merged.position = v3(centre.x + m.x / len * r, centre.y + m.y / len * r,
                                 centre.z + m.z / len * r);
        else /* opposite lights: keep the first's place */
            merged.position = s->lights[bi].position;
        for (c = 0; c < 3; c++)
            merged.color[c] = (w0 * s->lights[bi].color[c] + w1 * s->lights[bj].color[c]) / (w0 + w1);
        s->lights[bi] = merged;
        weight[bi] = w0 + w1;
        s->lights[bj] = s->lights[n - 1];
        weight[bj] = weight[n - 1];
        n--;
    }
    s->light_count = n;
    /* no light at all: the fallback light (stp_tool_setup) stands for one */
    for (i = 0; i < STP_MAX_LIGHTS; i++)
        out->light_weight[i] = i < n ? weight[i] : 1.0;
    free(weight);
    return 0;
}

/* ---- units ------------------------------------------------------------ */

/* The scene's extent: the radius of its bounds, or the eye's distance
 * from their centre when larger. */
static double scene_extent(const stp_scene *s, stp_scene_vec3 lo, stp_scene_vec3 hi,
                           stp_scene_vec3 centre)
{
    double e = dist(lo, hi) / 2;
    if (s->has_view)
        e = fmax(e, dist(s->from, centre));
    return e;
}

static int needs_rescale(const stp_scene *s, stp_scene_vec3 lo, stp_scene_vec3 hi, double extent)
{
    const double lim = STP_TOOL_COORD_LIMIT;
    if (extent < STP_TOOL_EXTENT_MIN || max_abs(lo) > lim || max_abs(hi) > lim)
        return 1;
    return s->has_view && (max_abs(s->from) > lim || max_abs(s->at) > lim);
}

static stp_scene_vec3 to_units(stp_scene_vec3 v, stp_scene_vec3 off, double k)
{
    return v3((v.x - off.x) * k, (v.y - off.y) * k, (v.z - off.z) * k);
}

/* The number of polygon i among the file's own polygons (those of NFF's
 * spheres and cones are not counted: messages name those by the sphere or
 * cone), from 1. */
static size_t file_polygon_number(const stp_scene *s, size_t i)
{
    size_t j, n = 1;
    for (j = 0; j < i; j++)
        n += s->polygons[j].prim < 0;
    return n;
}

/* "L: ", the start of a message about line L (render_scene.h), or "" when
 * the line is not known (0). */
static const char *line_prefix(char buf[16], int line)
{
    buf[0] = 0;
    if (line > 0)
        snprintf(buf, 16, "%d: ", line);
    return buf;
}

/* The line of prim i: that of a polygon tessellating it (the reader gives
 * them its line), 0 when none is kept. */
static int prim_line(const stp_scene *s, size_t prim)
{
    size_t i;
    for (i = 0; i < s->polygon_count; i++)
        if (s->polygons[i].prim == (int)prim)
            return s->polygons[i].source_line;
    return 0;
}

/* --no-rescale: the coordinates go to the core as they are, so each must
 * be an stp_fix (the core then refuses, with STP_ERR_RANGE, a point too far
 * from the eye).  Within +-32767 (inclusive, as render.h states) each is
 * one; beyond, stp_tool_fix would saturate it into a point elsewhere. */
static int outside_fix(stp_scene_vec3 v)
{
    return !(max_abs(v) <= 32767.0);
}

static int check_units_kept(const stp_scene *s, char *err, size_t err_size)
{
    static const char range[] = "beyond the core's range (+-32767 units); without --no-rescale "
                                "the scene is scaled into it";
    size_t i;
    int k;
    for (i = 0; i < s->polygon_count; i++) {
        const stp_scene_polygon *p = &s->polygons[i];
        for (k = 0; k < p->count; k++) {
            stp_scene_vec3 v = s->vertices[p->first + (size_t)k];
            if (outside_fix(v)) {
                snprintf(err, err_size, "%d: coordinate (%g, %g, %g) of polygon %zu %s",
                         p->source_line, v.x, v.y, v.z, file_polygon_number(s, i), range);
                return -1;
            }
        }
    }
    for (i = 0; i < s->prim_count; i++) {
        const stp_scene_prim *p = &s->prims[i];
        if (outside_fix(p->base) || outside_fix(p->apex) || !(fabs(p->base_radius) <= 32767.0) ||
            !(fabs(p->apex_radius) <= 32767.0)) {
            char at[16];
            snprintf(err, err_size, "%s%s %zu %s", line_prefix(at, prim_line(s, i)),
                     p->kind == STP_SCENE_SPHERE ? "sphere" : "cone", i + 1, range);
            return -1;
        }
    }
    if (s->has_view && (outside_fix(s->from) || outside_fix(s->at))) {
        snprintf(err, err_size, "the view's from (%g, %g, %g) or at (%g, %g, %g) %s", s->from.x,
                 s->from.y, s->from.z, s->at.x, s->at.y, s->at.z, range);
        return -1;
    }
    return 0;
}

/* A polygon's size in the file's units: its farthest vertex from its
 * first along any axis. */
static double polygon_size(const stp_scene *s, const stp_scene_polygon *p)
{
    stp_scene_vec3 a = s->vertices[p->first];
    double size = 0;
    int k;
    for (k = 1; k < p->count; k++)
        size = fmax(size, max_abs(to_units(s->vertices[p->first + (size_t)k], a, 1.0)));
    return size;
}

/* The smallest object's size against the core's step: an object that the
 * rescaling leaves under a few steps would vanish or turn to a point.
 * Sizes are taken in the file's units (in) and scaled: the rescaled copy
 * of an object far smaller than the scene has already lost it (1 + 1e30
 * is 1e30 in double). */
static int check_resolution(const stp_tool_prepared *out, const stp_scene *in, char *err,
                            size_t err_size)
{
    const stp_scene *s = &out->scene;
    const double step = 1.0 / STP_FIX_ONE, extent_limit = 4 * step, k = out->scale;
    size_t i;
    for (i = 0; i < in->polygon_count; i++) {
        const stp_scene_polygon *p = &in->polygons[i];
        double size;
        if (p->prim >= 0)
            continue; /* checked with its prim */
        size = polygon_size(in, p);
        if (size > 0 && size * k < extent_limit) {
            snprintf(err, err_size,
                     "%d: polygon %zu: %g units across in a scene %g units across: "
                     "beyond the core's range of coordinates (2^15 units in steps of 2^-16, "
                     "after rescaling); remove the far-off or the tiny objects",
                     p->source_line, file_polygon_number(in, i), size, STP_TOOL_EXTENT_TARGET / k);
            return -1;
        }
    }
    for (i = 0; i < in->prim_count; i++) {
        const stp_scene_prim *p = &in->prims[i];
        double size = fmax(fabs(p->base_radius), fabs(p->apex_radius));
        if (p->kind == STP_SCENE_CONE)
            size = fmax(size, dist(p->base, p->apex));
        if (size * k < extent_limit) {
            char at[16];
            snprintf(err, err_size,
                     "%s%s %zu: %g units across in a scene %g units across: beyond the core's "
                     "range of coordinates (2^15 units in steps of 2^-16, after rescaling)",
                     line_prefix(at, prim_line(s, i)), p->kind == STP_SCENE_SPHERE ? "sphere" : "cone", i + 1,
                     size, STP_TOOL_EXTENT_TARGET / k);
            return -1;
        }
    }
    if (in->has_view && dist(in->from, in->at) * k < extent_limit) {
        snprintf(err, err_size,
                 "the view's from (%g, %g, %g) and at (%g, %g, %g) lie %g units apart in a scene "
                 "%g units across: beyond the core's range of coordinates (2^15 units in steps "
                 "of 2^-16, after rescaling); remove the far-off objects",
                 in->from.x, in->from.y, in->from.z, in->at.x, in->at.y, in->at.z,
                 dist(in->from, in->at), STP_TOOL_EXTENT_TARGET / k);
        return -1;
    }
    return 0;
}

/* Polygons beyond STP_TOOL_MAX_POLYGON_VERTICES are refused: splitting
 * one can take minutes (ear clipping is quadratic at worst). */
static int check_polygon_sizes(const stp_scene *in, char *err, size_t err_size)
{
    size_t i;
    for (i = 0; i < in->polygon_count; i++) {
        const stp_scene_polygon *p = &in->polygons[i];
        if (p->count > STP_TOOL_MAX_POLYGON_VERTICES) {
            snprintf(err, err_size,
                     "%d: polygon %zu has %d vertices; at most %d are taken (splitting longer "
                     "ones into pieces the core takes can last minutes): cut it into smaller "
                     "polygons",
                     p->source_line, file_polygon_number(in, i), p->count, STP_TOOL_MAX_POLYGON_VERTICES);
            return -1;
        }
    }
    return 0;
}

/* The area of polygon p (half its Newell normal's length). */
static double polygon_area(const stp_scene *s, const stp_scene_polygon *p)
{
    double nx = 0, ny = 0, nz = 0;
    int k;
    for (k = 0; k < p->count; k++) {
        stp_scene_vec3 a = s->vertices[p->first + (size_t)k];
        stp_scene_vec3 b = s->vertices[p->first + (size_t)((k + 1) % p->count)];
        nx += (a.y - b.y) * (a.z + b.z);
        ny += (a.z - b.z) * (a.x + b.x);
        nz += (a.x - b.x) * (a.y + b.y);
    }
    return hypot(hypot(nx, ny), nz) / 2;
}

/* A scene with polygons but none with an area (every one a point, or its
 * vertices on a line) draws nothing: refused like a file without geometry.
 * Area in the file's units, against the square of the polygon's size
 * (rounding of collinear vertices leaves a trace of area).  A self-crossing
 * outline whose parts cancel (a symmetric bow tie) has area here too: its
 * parts are counted without their sign. */
static int check_some_area(const stp_scene *in, char *err, size_t err_size)
{
    size_t i;
    if (in->prim_count > 0)
        return 0;
    for (i = 0; i < in->polygon_count; i++) {
        const stp_scene_polygon *p = &in->polygons[i];
        double size = polygon_size(in, p), area = polygon_area(in, p);
        int k;
        if (size > 0 && area > 1e-12 * size * size)
            return 0;
        for (k = 1; size > 0 && k + 1 < p->count; k++) {
            /* the fan's triangles, each without its sign */
            stp_scene_polygon t = *p;
            stp_scene_vec3 tri[3];
            stp_scene tmp;
            tri[0] = in->vertices[p->first];
            tri[1] = in->vertices[p->first + (size_t)k];
            tri[2] = in->vertices[p->first + (size_t)k + 1];
            memset(&tmp, 0, sizeof tmp);
            tmp.vertices = tri;
            t.first = 0;
            t.count = 3;
            if (polygon_area(&tmp, &t) > 1e-12 * size * size)
                return 0;
        }
    }
    snprintf(err, err_size,
             "no geometry: none of the %zu polygons has an area (each a point or a line; the "
             "first on line %d)",
             in->polygon_count, in->polygon_count ? in->polygons[0].source_line : 0);
    return -1;
}

static void rescale(stp_tool_prepared *out, const stp_tool_options *opt, stp_scene_vec3 off,
                    double k)
{
    stp_scene *s = &out->scene;
    size_t i;
    out->scale = k;
    out->offset = off;
    for (i = 0; i < s->vertex_count; i++)
        s->vertices[i] = to_units(s->vertices[i], off, k);
    for (i = 0; i < s->prim_count; i++) {
        s->prims[i].base = to_units(s->prims[i].base, off, k);
        s->prims[i].apex = to_units(s->prims[i].apex, off, k);
        s->prims[i].base_radius *= k;
        s->prims[i].apex_radius *= k;
    }
    for (i = 0; i < s->light_count; i++)
        s->lights[i].position = to_units(s->lights[i].position, off, k);
    if (s->has_view) {
        stp_scene_vec3 from = to_units(s->from, off, k), at = to_units(s->at, off, k);
        /* only at's direction matters: a far look-at point is brought to
         * the scene's distance (shadow maps use it as a hint) */
        if (max_abs(at) > STP_TOOL_COORD_LIMIT) {
            stp_scene_vec3 d = v3(s->at.x - s->from.x, s->at.y - s->from.y, s->at.z - s->from.z);
            double l = hypot(hypot(d.x, d.y), d.z);
            double r = dist(from, v3(0, 0, 0)) + STP_TOOL_EXTENT_TARGET;
            at = v3(from.x + d.x / l * r, from.y + d.y / l * r, from.z + d.z / l * r);
        }
        s->from = from;
        s->at = at;
        s->hither *= k;
    }
    /* C of 1/(C + U) is not scaled: it is taken in the units of the
     * rescaled scene, so it means the same whatever the file's units (a C
     * of 1 in millimetres would otherwise flatten every light's falloff,
     * in kilometres sharpen it) */
    (void)opt;
}

/* Lights beyond the limit come in along their direction from the centre;
 * with raw power the light keeps its attenuation at the centre. */
static void pull_in_lights(stp_tool_prepared *out, stp_scene_vec3 centre)
{
    stp_scene *s = &out->scene;
    size_t i;
    for (i = 0; i < s->light_count; i++) {
        stp_scene_vec3 p = s->lights[i].position;
        double d = dist(p, centre), r = STP_TOOL_COORD_LIMIT / 2;
        if (max_abs(p) <= STP_TOOL_COORD_LIMIT || !(d > r))
            continue;
        s->lights[i].position = v3(centre.x + (p.x - centre.x) / d * r,
                                   centre.y + (p.y - centre.y) / d * r,
                                   centre.z + (p.z - centre.z) / d * r);
        if (!out->opt.auto_power)
            out->power_factor[i] *= (out->opt.attenuation_c + r) / (out->opt.attenuation_c + d);
    }
}

int stp_tool_prepare(const stp_scene *scene, const stp_tool_options *opt, stp_tool_prepared *out,
                     char *err, size_t err_size)
{
    stp_scene_vec3 lo, hi, centre;
    double extent;
    size_t i;

    memset(out, 0, sizeof *out);
    out->opt = *opt;
    out->scale = 1;
    if (stp_scene_bounds(scene, &lo, &hi) != 0) {
        snprintf(err, err_size, "the scene has no polygons to render");
        return -1;
    }
    if (check_polygon_sizes(scene, err, err_size) != 0 || check_some_area(scene, err, err_size) != 0)
        return -1;
    if (copy_scene(scene, out) != 0) {
        stp_tool_prepared_free(out);
        snprintf(err, err_size, "out of memory");
        return -1;
    }
    centre = v3((lo.x + hi.x) / 2, (lo.y + hi.y) / 2, (lo.z + hi.z) / 2);
    if (gather_lights(scene, opt, centre, out) != 0) {
        stp_tool_prepared_free(out);
        snprintf(err, err_size, "out of memory");
        return -1;
    }
    for (i = 0; i < STP_MAX_LIGHTS; i++)
        out->power_factor[i] = 1;
    extent = scene_extent(scene, lo, hi, centre);
    if (!(extent > 0))
        extent = 1;
    if (opt->keep_units) {
        if (check_units_kept(scene, err, err_size) != 0) {
            stp_tool_prepared_free(out);
            return -1;
        }
    } else if (needs_rescale(scene, lo, hi, extent)) {
        /* to one extent whatever the units: files that differ only in
         * their units give the same scene to the core */
        double k = STP_TOOL_EXTENT_TARGET / extent;
        rescale(out, opt, centre, k);
        if (check_resolution(out, scene, err, err_size) != 0) {
            stp_tool_prepared_free(out);
            return -1;
        }
        centre = v3(0, 0, 0);
    }
    pull_in_lights(out, centre);
    return 0;
}
