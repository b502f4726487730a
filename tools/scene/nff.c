/* SPDX-License-Identifier: MIT */
/*
 * NFF (Neutral File Format, Eric Haines' SPD) reader.  Line oriented: each
 * entity's fields sit on the lines the format gives them, extra whitespace
 * is tolerated.  Spheres and cones are kept as primitives and tessellated.
 */
#include <math.h>
#include <string.h>

#include "scene_private.h"

#define NFF_PI 3.14159265358979323846

static stp_scene_vec3 vec3(double x, double y, double z)
{
    stp_scene_vec3 v;
    v.x = x;
    v.y = y;
    v.z = z;
    return v;
}

static stp_scene_vec3 cross(stp_scene_vec3 a, stp_scene_vec3 b)
{
    return vec3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}

/* Robust length: coordinates may be tiny or huge. */
static double length(stp_scene_vec3 a)
{
    return hypot(hypot(a.x, a.y), a.z);
}

/* ---- tessellation ------------------------------------------------------ */

/* Emits one polygon of n (3 or 4) corners, reversed with flipped normals
 * when the inside is the visible side. */
static int emit(stp_parser *ps, long line, const stp_scene_vec3 *pos, const stp_scene_vec3 *nrm,
                int n, int inside, int material)
{
    size_t first = ps->scene->vertex_count;
    int i;
    for (i = 0; i < n; i++) {
        int k = inside ? n - 1 - i : i;
        stp_scene_vec3 nn = nrm[k];
        if (inside)
            nn = vec3(-nn.x, -nn.y, -nn.z);
        if (stp_add_vertex(ps, line, &pos[k], &nn) != 0)
            return -1;
    }
    if (stp_add_polygon(ps, line, first, n, material, 1) != 0)
        return -1;
    /* tessellation runs right after its primitive is added */
    ps->scene->polygons[ps->scene->polygon_count - 1].prim = (int)ps->scene->prim_count - 1;
    return 0;
}

/* Unit direction on the sphere for stack i (0 = +z pole, stacks = -z pole)
 * and slice j; poles exact so the fans close. */
static stp_scene_vec3 sphere_dir(int i, int stacks, int j, int slices)
{
    double th, ph;
    if (i == 0)
        return vec3(0.0, 0.0, 1.0);
    if (i == stacks)
        return vec3(0.0, 0.0, -1.0);
    th = NFF_PI * i / stacks;
    ph = 2.0 * NFF_PI * (j % slices) / slices; /* seam reuses slice 0 exactly */
    return vec3(sin(th) * cos(ph), sin(th) * sin(ph), cos(th));
}

/* slices x stacks polygons: triangle fans at the poles, quads between.
 * Corners go (lower, left), (lower, right), (upper, right), (upper, left)
 * seen from outside, i.e. counter-clockwise with the outward normal. */
static int tessellate_sphere(stp_parser *ps, long line, const stp_scene_prim *pr)
{
    const int slices = ps->opt->sphere_slices, stacks = ps->opt->sphere_stacks;
    const double r = fabs(pr->base_radius);
    const int inside = pr->base_radius < 0.0;
    int i, j;

    for (i = 0; i < stacks; i++) {
        for (j = 0; j < slices; j++) {
            stp_scene_vec3 d[4], pos[4], nrm[4];
            int c, n = 0;
            d[0] = sphere_dir(i + 1, stacks, j, slices);
            d[1] = sphere_dir(i + 1, stacks, j + 1, slices);
            d[2] = sphere_dir(i, stacks, j + 1, slices);
            d[3] = sphere_dir(i, stacks, j, slices);
            for (c = 0; c < 4; c++) {
                /* The two corners on a pole coincide: keep one. */
                if ((i == 0 && c == 3) || (i == stacks - 1 && c == 0))
                    continue;
                nrm[n] = d[c];
                pos[n] = vec3(pr->base.x + r * d[c].x, pr->base.y + r * d[c].y,
                              pr->base.z + r * d[c].z);
                n++;
            }
            if (emit(ps, line, pos, nrm, n, inside, pr->material) != 0)
                return -1;
        }
    }
    return 0;
}

/* cone_slices side polygons, quads or (with a zero radius) triangles, same
 * corner order as the sphere with the apex "up". */
static int tessellate_cone(stp_parser *ps, long line, const stp_scene_prim *pr)
{
    const int slices = ps->opt->cone_slices;
    const double rb = fabs(pr->base_radius), ra = fabs(pr->apex_radius);
    const int inside = pr->base_radius < 0.0 || pr->apex_radius < 0.0;
    stp_scene_vec3 w, e, u, v;
    double h, lu;
    int j;

    w = vec3(pr->apex.x - pr->base.x, pr->apex.y - pr->base.y, pr->apex.z - pr->base.z);
    h = length(w);
    if (!isfinite(h))
        return stp_fail(ps, line, "coordinate out of range");
    if (!(h > 0.0))
        return stp_fail(ps, line, "c: base and apex coincide");
    w = vec3(w.x / h, w.y / h, w.z / h);
    /* u, v, w right-handed, u built from the axis least aligned with w. */
    if (fabs(w.x) <= fabs(w.y) && fabs(w.x) <= fabs(w.z))
        e = vec3(1.0, 0.0, 0.0);
    else if (fabs(w.y) <= fabs(w.z))
        e = vec3(0.0, 1.0, 0.0);
    else
        e = vec3(0.0, 0.0, 1.0);
    u = cross(w, e);
    lu = length(u);
    u = vec3(u.x / lu, u.y / lu, u.z / lu);
    v = cross(w, u);

    for (j = 0; j < slices; j++) {
        /* Corner c: end (0 = base, 1 = apex) and slice index. */
        static const int end_of[4] = {0, 0, 1, 1};
        static const int step_of[4] = {0, 1, 1, 0};
        stp_scene_vec3 pos[4], nrm[4];
        int c, n = 0;
        for (c = 0; c < 4; c++) {
            const int at_apex = end_of[c];
            const double r = at_apex ? ra : rb;
            const stp_scene_vec3 *o = at_apex ? &pr->apex : &pr->base;
            double ph, cp, sp, nl;
            stp_scene_vec3 radial, nn;
            if (r == 0.0 && c == (at_apex ? 3 : 0))
                continue; /* the tip is shared: triangle */
            /* A tip vertex takes the slice's middle direction for its normal. */
            if (r == 0.0)
                ph = 2.0 * NFF_PI * (j + 0.5) / slices;
            else
                ph = 2.0 * NFF_PI * ((j + step_of[c]) % slices) / slices;
            cp = cos(ph);
            sp = sin(ph);
            radial = vec3(cp * u.x + sp * v.x, cp * u.y + sp * v.y, cp * u.z + sp * v.z);
            pos[n] = vec3(o->x + r * radial.x, o->y + r * radial.y, o->z + r * radial.z);
            /* The side's slope tilts the normal toward the narrower end. */
            nn = vec3(radial.x * h + w.x * (rb - ra), radial.y * h + w.y * (rb - ra),
                      radial.z * h + w.z * (rb - ra));
            nl = length(nn);
            nrm[n] = vec3(nn.x / nl, nn.y / nl, nn.z / nl);
            n++;
        }
        if (emit(ps, line, pos, nrm, n, inside, pr->material) != 0)
            return -1;
    }
    return 0;
}

/* ---- entities ---------------------------------------------------------- */

typedef struct nff_state {
    int seen_view;
    int seen_entity; /* l, f, p, pp, s or c read: too late for v */
    int material;    /* current material, -1 before the first f */
} nff_state;

static int current_material(stp_parser *ps, nff_state *st, long line)
{
    if (st->material < 0)
        st->material = stp_add_default_material(ps, line);
    return st->material;
}

enum { VIEW_FROM, VIEW_AT, VIEW_UP, VIEW_ANGLE, VIEW_HITHER, VIEW_RESOLUTION, VIEW_FIELDS };

static const char *const view_field_names[VIEW_FIELDS] = {"from",  "at",     "up",
                                                           "angle", "hither", "resolution"};

/* "v" then one line per field; any order, each exactly once. */
static int read_view(stp_parser *ps, stp_line *vline)
{
    stp_scene *s = ps->scene;
    long field_line[VIEW_FIELDS];
    int seen = 0, k;
    char show[40];

    if (stp_expect_end(ps, vline, "v") != 0)
        return -1;
    while (seen != (1 << VIEW_FIELDS) - 1) {
        stp_line ln;
        stp_token tok;
        double num[3];
        int missing = 0, r;
        while (seen & (1 << missing))
            missing++;
        r = stp_next_line(ps, &ln);
        if (r < 0)
            return -1;
        if (r == 0)
            return stp_fail(ps, vline->number, "view: file ends before '%s'",
                            view_field_names[missing]);
        stp_next_token(&ln, &tok);
        for (k = 0; k < VIEW_FIELDS; k++)
            if (stp_token_is(&tok, view_field_names[k]))
                break;
        if (k == VIEW_FIELDS)
            return stp_fail(ps, ln.number, "view: expected '%s', found '%s'",
                            view_field_names[missing], stp_token_show(&tok, show, sizeof show));
        if (seen & (1 << k))
            return stp_fail(ps, ln.number, "view: '%s' given twice", view_field_names[k]);
        seen |= 1 << k;
        field_line[k] = ln.number;
        switch (k) {
        case VIEW_FROM:
        case VIEW_AT:
        case VIEW_UP:
            if (stp_read_numbers(ps, &ln, num, 3, 3, view_field_names[k]) < 0)
                return -1;
            *(k == VIEW_FROM ? &s->from : k == VIEW_AT ? &s->at : &s->up) =
                vec3(num[0], num[1], num[2]);
            break;
        case VIEW_ANGLE:
            if (stp_read_numbers(ps, &ln, num, 1, 1, "angle") < 0)
                return -1;
            if (!(num[0] > 0.0 && num[0] < 180.0))
                return stp_fail(ps, ln.number, "angle must be between 0 and 180 degrees");
            s->angle = num[0];
            break;
        case VIEW_HITHER:
            if (stp_read_numbers(ps, &ln, num, 1, 1, "hither") < 0)
                return -1;
            if (num[0] < 0.0)
                return stp_fail(ps, ln.number, "hither must not be negative");
            s->hither = num[0];
            break;
        default: { /* VIEW_RESOLUTION */
            int i;
            for (i = 0; i < 2; i++) {
                long long res;
                if (!stp_next_token(&ln, &tok))
                    return stp_fail(ps, ln.number, "resolution: expected 2 integers, found %d",
                                    i);
                if (stp_parse_integer(ps, ln.number, &tok, &res) != 0)
                    return -1;
                if (res < 1 || res > STP_SCENE_MAX_RESOLUTION)
                    return stp_fail(ps, ln.number, "resolution must be 1..%d, not %lld",
                                    STP_SCENE_MAX_RESOLUTION, res);
                s->resolution[i] = (int)res;
            }
            if (stp_expect_end(ps, &ln, "resolution") != 0)
                return -1;
            break;
        }
        }
    }
    {
        stp_scene_vec3 dir = vec3(s->at.x - s->from.x, s->at.y - s->from.y, s->at.z - s->from.z);
        double dl = length(dir), ul = length(s->up);
        if (!(dl > 0.0))
            return stp_fail(ps, field_line[VIEW_AT], "view: 'at' equals 'from'");
        if (!(ul > 0.0))
            return stp_fail(ps, field_line[VIEW_UP], "view: 'up' is zero");
        if (!(length(cross(vec3(dir.x / dl, dir.y / dl, dir.z / dl),
                           vec3(s->up.x / ul, s->up.y / ul, s->up.z / ul))) > 1e-9))
            return stp_fail(ps, field_line[VIEW_UP],
                            "view: 'up' is parallel to the view direction");
    }
    s->has_view = 1;
    return 0;
}

/* "p n" / "pp n": n lines of x y z (pp: x y z nx ny nz).  A file that ends
 * early is reported at the "p" line: its count is what cannot be met. */
static int read_polygon(stp_parser *ps, nff_state *st, stp_line *head, int with_normals)
{
    const char *what = with_normals ? "pp" : "p";
    const int per = with_normals ? 6 : 3;
    stp_token tok;
    long long n, i;
    size_t first = ps->scene->vertex_count;
    int material;

    if (!stp_next_token(head, &tok))
        return stp_fail(ps, head->number, "%s: missing vertex count", what);
    if (stp_parse_integer(ps, head->number, &tok, &n) != 0)
        return -1;
    if (stp_expect_end(ps, head, what) != 0)
        return -1;
    if (n < 3)
        return stp_fail(ps, head->number, "%s: a polygon needs at least 3 vertices, not %lld",
                        what, n);
    if (n > STP_SCENE_MAX_POLYGON_VERTICES)
        return stp_fail(ps, head->number, "%s: too many vertices (%lld, limit %d)", what, n,
                        STP_SCENE_MAX_POLYGON_VERTICES);
    material = current_material(ps, st, head->number);
    if (material < 0)
        return -1;
    /* Vertices are stored as their lines arrive; the count is only a
     * promise, so a short file fails here instead of over-allocating. */
    for (i = 0; i < n; i++) {
        stp_line ln;
        double num[6];
        stp_scene_vec3 v, nv;
        int r = stp_next_line(ps, &ln);
        if (r < 0)
            return -1;
        if (r == 0)
            return stp_fail(ps, head->number, "%s: file ends after %lld of %lld vertices", what,
                            i, n);
        if (stp_read_numbers(ps, &ln, num, per, per, with_normals ? "pp vertex" : "p vertex") < 0)
            return -1;
        v = vec3(num[0], num[1], num[2]);
        nv = with_normals ? vec3(num[3], num[4], num[5]) : vec3(0.0, 0.0, 0.0);
        if (stp_add_vertex(ps, ln.number, &v, &nv) != 0)
            return -1;
    }
    return stp_add_polygon(ps, head->number, first, (int)n, material, with_normals);
}

static int read_sphere(stp_parser *ps, nff_state *st, stp_line *ln)
{
    double num[4];
    stp_scene_prim pr;
    if (stp_read_numbers(ps, ln, num, 4, 4, "s") < 0)
        return -1;
    if (num[3] == 0.0)
        return stp_fail(ps, ln->number, "s: radius is zero");
    memset(&pr, 0, sizeof pr);
    pr.kind = STP_SCENE_SPHERE;
    pr.base = vec3(num[0], num[1], num[2]);
    pr.apex = pr.base;
    pr.base_radius = pr.apex_radius = num[3];
    pr.material = current_material(ps, st, ln->number);
    if (pr.material < 0 || stp_add_prim(ps, ln->number, &pr) != 0)
        return -1;
    return tessellate_sphere(ps, ln->number, &pr);
}

/* "c" then base and apex lines "x y z r". */
static int read_cone(stp_parser *ps, nff_state *st, stp_line *head)
{
    stp_scene_prim pr;
    double num[2][4];
    int k;

    if (stp_expect_end(ps, head, "c") != 0)
        return -1;
    for (k = 0; k < 2; k++) {
        stp_line ln;
        int r = stp_next_line(ps, &ln);
        if (r < 0)
            return -1;
        if (r == 0)
            return stp_fail(ps, head->number, "c: file ends before the %s line",
                            k ? "apex" : "base");
        if (stp_read_numbers(ps, &ln, num[k], 4, 4, k ? "c apex" : "c base") < 0)
            return -1;
    }
    memset(&pr, 0, sizeof pr);
    pr.kind = STP_SCENE_CONE;
    pr.base = vec3(num[0][0], num[0][1], num[0][2]);
    pr.base_radius = num[0][3];
    pr.apex = vec3(num[1][0], num[1][1], num[1][2]);
    pr.apex_radius = num[1][3];
    if (pr.base.x == pr.apex.x && pr.base.y == pr.apex.y && pr.base.z == pr.apex.z)
        return stp_fail(ps, head->number, "c: base and apex coincide");
    if (pr.base_radius == 0.0 && pr.apex_radius == 0.0)
        return stp_fail(ps, head->number, "c: both radii are zero");
    /* Negative radii flip the visible side; mixing signs means nothing. */
    if ((pr.base_radius < 0.0 && pr.apex_radius > 0.0) ||
        (pr.base_radius > 0.0 && pr.apex_radius < 0.0))
        return stp_fail(ps, head->number, "c: radii have opposite signs");
    pr.material = current_material(ps, st, head->number);
    if (pr.material < 0 || stp_add_prim(ps, head->number, &pr) != 0)
        return -1;
    return tessellate_cone(ps, head->number, &pr);
}

int stp_parse_nff(stp_parser *ps)
{
    nff_state st;
    stp_line ln;
    int r;

    st.seen_view = 0;
    st.seen_entity = 0;
    st.material = -1;
    while ((r = stp_next_line(ps, &ln)) > 0) {
        stp_token kw;
        char show[40];
        stp_next_token(&ln, &kw);
        /* "v must come first" is read as: before any light, material or
         * geometry.  The SPD writes "b" before "v", so "b" may precede it. */
        if (stp_token_is(&kw, "v")) {
            if (st.seen_view)
                return stp_fail(ps, ln.number, "v: second view");
            if (st.seen_entity)
                return stp_fail(ps, ln.number,
                                "v: the view must come before lights, materials and geometry");
            st.seen_view = 1;
            if (read_view(ps, &ln) != 0)
                return -1;
            continue;
        }
        if (stp_token_is(&kw, "b")) {
            double num[3];
            if (stp_read_numbers(ps, &ln, num, 3, 3, "b") < 0)
                return -1;
            ps->scene->has_background = 1;
            memcpy(ps->scene->background, num, sizeof num);
            continue;
        }
        st.seen_entity = 1;
        if (stp_token_is(&kw, "l")) {
            double num[6];
            stp_scene_light light;
            int n = stp_count_tokens(&ln);
            if (n != 3 && n != 6)
                return stp_fail(ps, ln.number, "l: expected 3 or 6 numbers, found %d", n);
            if (stp_read_numbers(ps, &ln, num, n, n, "l") < 0)
                return -1;
            light.position = vec3(num[0], num[1], num[2]);
            light.color[0] = n == 6 ? num[3] : 1.0;
            light.color[1] = n == 6 ? num[4] : 1.0;
            light.color[2] = n == 6 ? num[5] : 1.0;
            if (stp_add_light(ps, ln.number, &light) != 0)
                return -1;
        } else if (stp_token_is(&kw, "f")) {
            double num[8];
            stp_scene_material m;
            if (stp_read_numbers(ps, &ln, num, 8, 8, "f") < 0)
                return -1;
            memcpy(m.color, num, sizeof m.color);
            m.kd = num[3];
            m.ks = num[4];
            m.shine = num[5];
            m.t = num[6];
            m.ior = num[7];
            st.material = stp_add_material(ps, ln.number, &m);
            if (st.material < 0)
                return -1;
        } else if (stp_token_is(&kw, "p")) {
            if (read_polygon(ps, &st, &ln, 0) != 0)
                return -1;
        } else if (stp_token_is(&kw, "pp")) {
            if (read_polygon(ps, &st, &ln, 1) != 0)
                return -1;
        } else if (stp_token_is(&kw, "s")) {
            if (read_sphere(ps, &st, &ln) != 0)
                return -1;
        } else if (stp_token_is(&kw, "c")) {
            if (read_cone(ps, &st, &ln) != 0)
                return -1;
        } else {
            return stp_fail(ps, ln.number, "unknown entity '%s'",
                            stp_token_show(&kw, show, sizeof show));
        }
    }
    return r;
}
