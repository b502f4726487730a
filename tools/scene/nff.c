/* SPDX-License-Identifier: MIT */
/*
 * NFF (Neutral File Format, Eric Haines' SPD) reader.  Read as a stream of
 * whitespace-separated tokens across line breaks, as the SPD's own programs
 * write it (a cone's eight numbers on one line, a polygon's vertices on
 * its "p" line) and other NFF readers take it; each token keeps its line
 * for messages.  Spheres and cones are kept as primitives and tessellated.
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

/* ---- token stream ------------------------------------------------------ */

/* The file as tokens: lines are only where a token's line number comes
 * from ('#' still comments out the rest of a line). */
typedef struct nff_stream {
    stp_parser *ps;
    stp_line ln;      /* the rest of the current line */
    int in_line;      /* ln holds unread text */
    int peeked;       /* tok/line hold the next token, not yet taken */
    stp_token tok;
    long line;        /* line of tok */
    long last_line;   /* line of the last token taken */
    long prev_line;   /* line of the previous entity's last token */
} nff_stream;

/* The next token without taking it.  Returns 1, 0 at the end, -1 on error. */
static int peek(nff_stream *in, stp_token *tok, long *line)
{
    while (!in->peeked) {
        if (!in->in_line) {
            int r = stp_next_line(in->ps, &in->ln);
            if (r <= 0)
                return r;
            in->in_line = 1;
        }
        if (stp_next_token(&in->ln, &in->tok)) {
            in->line = in->ln.number;
            in->peeked = 1;
        } else {
            in->in_line = 0;
        }
    }
    *tok = in->tok;
    if (line)
        *line = in->line;
    return 1;
}

static void take(nff_stream *in)
{
    in->peeked = 0;
    in->last_line = in->line;
}

/* Next token, taken.  Returns 1, 0 at the end, -1 on error. */
static int next(nff_stream *in, stp_token *tok, long *line)
{
    int r = peek(in, tok, line);
    if (r > 0)
        take(in);
    return r;
}

static int looks_numeric(const stp_token *tok)
{
    char c = tok->s[0];
    return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.';
}

static int is_entity_keyword(const stp_token *tok)
{
    static const char *const words[] = {"v", "b", "l", "f", "p", "pp", "s", "c"};
    size_t i;
    for (i = 0; i < sizeof words / sizeof words[0]; i++)
        if (stp_token_is(tok, words[i]))
            return 1;
    return 0;
}

/* n numbers of entity `what` (head: the line of its keyword).  A missing
 * number (end of file or the next entity's keyword) is reported at the
 * line of the last one read: "what: expected <expect>, found k";
 * expect NULL means "n numbers". */
static int read_numbers_as(nff_stream *in, double *out, int n, const char *what,
                           const char *expect, long head)
{
    int k;
    for (k = 0; k < n; k++) {
        stp_token tok;
        long line;
        int r = peek(in, &tok, &line);
        if (r < 0)
            return -1;
        if (r == 0 || is_entity_keyword(&tok)) {
            if (expect)
                return stp_fail(in->ps, k ? in->last_line : head, "%s: expected %s, found %d",
                                what, expect, k);
            return stp_fail(in->ps, k ? in->last_line : head, "%s: expected %d numbers, found %d",
                            what, n, k);
        }
        take(in);
        if (stp_parse_double(in->ps, line, &tok, &out[k]) != 0)
            return -1;
    }
    return 0;
}

static int read_numbers(nff_stream *in, double *out, int n, const char *what, long head)
{
    return read_numbers_as(in, out, n, what, NULL, head);
}

/* A polygon's vertex count. */
static int read_integer(nff_stream *in, long long *out, const char *what, long head)
{
    stp_token tok;
    long line;
    int r = peek(in, &tok, &line);
    if (r < 0)
        return -1;
    if (r == 0 || !looks_numeric(&tok))
        return stp_fail(in->ps, head, "%s: missing vertex count", what);
    take(in);
    return stp_parse_integer(in->ps, line, &tok, out);
}

/* ---- entities ---------------------------------------------------------- */

typedef struct nff_state {
    int seen_view;
    int seen_entity; /* l, f, p, pp, s or c read: too late for v */
    int material;    /* current material, -1 before the first f */
    /* the last entity read, for a stray number after it */
    const char *last_what, *last_expect;
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

static int check_view(stp_parser *ps, const long *field_line)
{
    stp_scene *s = ps->scene;
    stp_scene_vec3 dir = vec3(s->at.x - s->from.x, s->at.y - s->from.y, s->at.z - s->from.z);
    double dl = length(dir), ul = length(s->up);
    if (!(dl > 0.0))
        return stp_fail(ps, field_line[VIEW_AT], "view: 'at' equals 'from'");
    if (!(ul > 0.0))
        return stp_fail(ps, field_line[VIEW_UP], "view: 'up' is zero");
    if (!(length(cross(vec3(dir.x / dl, dir.y / dl, dir.z / dl),
                       vec3(s->up.x / ul, s->up.y / ul, s->up.z / ul))) > 1e-9))
        return stp_fail(ps, field_line[VIEW_UP], "view: 'up' is parallel to the view direction");
    return 0;
}

/* "v" then its six fields, each a name and its numbers; any order, each
 * exactly once. */
static int read_view(nff_stream *in, nff_state *st, long vline)
{
    stp_parser *ps = in->ps;
    stp_scene *s = ps->scene;
    long field_line[VIEW_FIELDS];
    int seen = 0, k;
    char show[40];

    while (seen != (1 << VIEW_FIELDS) - 1) {
        stp_token tok;
        double num[3];
        long line;
        int missing = 0, r;
        while (seen & (1 << missing))
            missing++;
        r = next(in, &tok, &line);
        if (r < 0)
            return -1;
        if (r == 0)
            return stp_fail(ps, vline, "view: file ends before '%s'", view_field_names[missing]);
        for (k = 0; k < VIEW_FIELDS; k++)
            if (stp_token_is(&tok, view_field_names[k]))
                break;
        if (k == VIEW_FIELDS)
            return stp_fail(ps, line, "view: expected '%s', found '%s'",
                            view_field_names[missing], stp_token_show(&tok, show, sizeof show));
        if (seen & (1 << k))
            return stp_fail(ps, line, "view: '%s' given twice", view_field_names[k]);
        seen |= 1 << k;
        field_line[k] = line;
        st->last_what = view_field_names[k];
        st->last_expect = k <= VIEW_UP ? "3 numbers" : k == VIEW_RESOLUTION ? "2 integers"
                                                                             : "1 number";
        switch (k) {
        case VIEW_FROM:
        case VIEW_AT:
        case VIEW_UP:
            if (read_numbers(in, num, 3, view_field_names[k], line) != 0)
                return -1;
            *(k == VIEW_FROM ? &s->from : k == VIEW_AT ? &s->at : &s->up) =
                vec3(num[0], num[1], num[2]);
            break;
        case VIEW_ANGLE:
            if (read_numbers(in, num, 1, "angle", line) != 0)
                return -1;
            if (!(num[0] > 0.0 && num[0] < 180.0))
                return stp_fail(ps, line, "angle must be between 0 and 180 degrees");
            s->angle = num[0];
            break;
        case VIEW_HITHER:
            if (read_numbers(in, num, 1, "hither", line) != 0)
                return -1;
            if (num[0] < 0.0)
                return stp_fail(ps, line, "hither must not be negative");
            s->hither = num[0];
            break;
        default: { /* VIEW_RESOLUTION */
            int i;
            for (i = 0; i < 2; i++) {
                long long res;
                stp_token t2;
                long l2;
                int r2 = peek(in, &t2, &l2);
                if (r2 < 0)
                    return -1;
                if (r2 == 0 || !looks_numeric(&t2))
                    return stp_fail(ps, i ? in->last_line : line,
                                    "resolution: expected 2 integers, found %d", i);
                take(in);
                if (stp_parse_integer(ps, l2, &t2, &res) != 0)
                    return -1;
                if (res < 1 || res > STP_SCENE_MAX_RESOLUTION)
                    return stp_fail(ps, l2, "resolution must be 1..%d, not %lld",
                                    STP_SCENE_MAX_RESOLUTION, res);
                s->resolution[i] = (int)res;
            }
            break;
        }
        }
    }
    if (check_view(ps, field_line) != 0)
        return -1;
    s->has_view = 1;
    return 0;
}

/* "p n" / "pp n" then n vertices of 3 (pp: 6) numbers.  A file that ends
 * early is reported at the "p" line: its count is what cannot be met. */
static int read_polygon(nff_stream *in, nff_state *st, long head, int with_normals)
{
    stp_parser *ps = in->ps;
    const char *what = with_normals ? "pp" : "p";
    const int per = with_normals ? 6 : 3;
    long long n, i;
    size_t first = ps->scene->vertex_count;
    int material;

    if (read_integer(in, &n, what, head) != 0)
        return -1;
    if (n < 3)
        return stp_fail(ps, head, "%s: a polygon needs at least 3 vertices, not %lld", what, n);
    if (n > STP_SCENE_MAX_POLYGON_VERTICES)
        return stp_fail(ps, head, "%s: too many vertices (%lld, limit %d)", what, n,
                        STP_SCENE_MAX_POLYGON_VERTICES);
    material = current_material(ps, st, head);
    if (material < 0)
        return -1;
    st->last_what = with_normals ? "pp vertex" : "p vertex";
    st->last_expect = with_normals ? "6 numbers" : "3 numbers";
    /* Vertices are stored as they arrive; the count is only a promise, so
     * a short file fails here instead of over-allocating. */
    for (i = 0; i < n; i++) {
        double num[6];
        stp_scene_vec3 v, nv;
        stp_token tok;
        long line;
        int r = peek(in, &tok, &line);
        if (r < 0)
            return -1;
        if (r == 0 || is_entity_keyword(&tok))
            return stp_fail(ps, head, "%s: %s after %lld of %lld vertices", what,
                            r == 0 ? "file ends" : "next entity", i, n);
        if (read_numbers(in, num, per, st->last_what, line) != 0)
            return -1;
        v = vec3(num[0], num[1], num[2]);
        nv = with_normals ? vec3(num[3], num[4], num[5]) : vec3(0.0, 0.0, 0.0);
        if (stp_add_vertex(ps, line, &v, &nv) != 0)
            return -1;
    }
    return stp_add_polygon(ps, head, first, (int)n, material, with_normals);
}

static int read_sphere(nff_stream *in, nff_state *st, long head)
{
    stp_parser *ps = in->ps;
    double num[4];
    stp_scene_prim pr;
    if (read_numbers(in, num, 4, "s", head) != 0)
        return -1;
    if (num[3] == 0.0)
        return stp_fail(ps, head, "s: radius is zero");
    memset(&pr, 0, sizeof pr);
    pr.kind = STP_SCENE_SPHERE;
    pr.base = vec3(num[0], num[1], num[2]);
    pr.apex = pr.base;
    pr.base_radius = pr.apex_radius = num[3];
    pr.material = current_material(ps, st, head);
    if (pr.material < 0 || stp_add_prim(ps, head, &pr) != 0)
        return -1;
    if (!ps->opt->analytic_only)
        return tessellate_sphere(ps, head, &pr);
    return 0;
}

/* "c" then base "x y z r" and apex "x y z r" (the SPD writes all eight on
 * one line, others on two or three). */
static int read_cone(nff_stream *in, nff_state *st, long head)
{
    stp_parser *ps = in->ps;
    stp_scene_prim pr;
    double num[8];

    if (read_numbers(in, num, 8, "c", head) != 0)
        return -1;
    memset(&pr, 0, sizeof pr);
    pr.kind = STP_SCENE_CONE;
    pr.base = vec3(num[0], num[1], num[2]);
    pr.base_radius = num[3];
    pr.apex = vec3(num[4], num[5], num[6]);
    pr.apex_radius = num[7];
    if (pr.base.x == pr.apex.x && pr.base.y == pr.apex.y && pr.base.z == pr.apex.z)
        return stp_fail(ps, head, "c: base and apex coincide");
    if (pr.base_radius == 0.0 && pr.apex_radius == 0.0)
        return stp_fail(ps, head, "c: both radii are zero");
    /* Negative radii flip the visible side; mixing signs means nothing. */
    if ((pr.base_radius < 0.0 && pr.apex_radius > 0.0) ||
        (pr.base_radius > 0.0 && pr.apex_radius < 0.0))
        return stp_fail(ps, head, "c: radii have opposite signs");
    pr.material = current_material(ps, st, head);
    if (pr.material < 0 || stp_add_prim(ps, head, &pr) != 0)
        return -1;
    if (!ps->opt->analytic_only)
        return tessellate_cone(ps, head, &pr);
    {
        /* still refuse what the tessellation could not place */
        stp_scene_vec3 w = vec3(pr.apex.x - pr.base.x, pr.apex.y - pr.base.y,
                                pr.apex.z - pr.base.z);
        if (!isfinite(length(w)) || !isfinite(pr.base.x + pr.base_radius) ||
            !isfinite(pr.apex.x + pr.apex_radius))
            return stp_fail(ps, head, "coordinate out of range");
    }
    return 0;
}

/* "l x y z [r g b]": the colour is there when a number follows. */
static int read_light(nff_stream *in, nff_state *st, long head)
{
    double num[6];
    stp_scene_light light;
    stp_token tok;
    int r;
    st->last_what = "l";
    st->last_expect = "3 or 6 numbers";
    if (read_numbers_as(in, num, 3, "l", "3 or 6 numbers", head) != 0)
        return -1;
    r = peek(in, &tok, NULL);
    if (r < 0)
        return -1;
    light.color[0] = light.color[1] = light.color[2] = 1.0;
    if (r > 0 && looks_numeric(&tok)) {
        int k;
        for (k = 0; k < 3; k++) {
            long line;
            r = peek(in, &tok, &line);
            if (r < 0)
                return -1;
            if (r == 0 || is_entity_keyword(&tok))
                return stp_fail(in->ps, in->last_line, "l: expected 3 or 6 numbers, found %d",
                                3 + k);
            take(in);
            if (stp_parse_double(in->ps, line, &tok, &light.color[k]) != 0)
                return -1;
        }
    }
    light.position = vec3(num[0], num[1], num[2]);
    return stp_add_light(in->ps, head, &light);
}

static int read_entity(nff_stream *in, nff_state *st, const stp_token *kw, long line)
{
    stp_parser *ps = in->ps;
    char show[40];
    double num[8];

    /* "v must come first" is read as: before any light, material or
     * geometry.  The SPD writes "b" before "v", so "b" may precede it. */
    st->last_what = 0;
    if (stp_token_is(kw, "v")) {
        if (st->seen_view)
            return stp_fail(ps, line, "v: second view");
        if (st->seen_entity)
            return stp_fail(ps, line, "v: the view must come before lights, materials and geometry");
        st->seen_view = 1;
        return read_view(in, st, line);
    }
    if (stp_token_is(kw, "b")) {
        st->last_what = "b";
        st->last_expect = "3 numbers";
        if (read_numbers(in, num, 3, "b", line) != 0)
            return -1;
        ps->scene->has_background = 1;
        memcpy(ps->scene->background, num, 3 * sizeof num[0]);
        return 0;
    }
    st->seen_entity = 1;
    if (stp_token_is(kw, "l"))
        return read_light(in, st, line);
    if (stp_token_is(kw, "f")) {
        stp_scene_material m;
        st->last_what = "f";
        st->last_expect = "8 numbers";
        if (read_numbers(in, num, 8, "f", line) != 0)
            return -1;
        memcpy(m.color, num, sizeof m.color);
        m.kd = num[3];
        m.ks = num[4];
        m.shine = num[5];
        m.t = num[6];
        m.ior = num[7];
        st->material = stp_add_material(ps, line, &m);
        return st->material < 0 ? -1 : 0;
    }
    if (stp_token_is(kw, "p") || stp_token_is(kw, "pp"))
        return read_polygon(in, st, line, kw->n == 2);
    if (stp_token_is(kw, "s")) {
        st->last_what = "s";
        st->last_expect = "4 numbers";
        return read_sphere(in, st, line);
    }
    if (stp_token_is(kw, "c")) {
        st->last_what = "c";
        st->last_expect = "8 numbers";
        return read_cone(in, st, line);
    }
    return stp_fail(ps, line, "unknown entity '%s'", stp_token_show(kw, show, sizeof show));
}

int stp_parse_nff(stp_parser *ps)
{
    nff_stream in;
    nff_state st;
    stp_token kw;
    long line;
    int r;

    memset(&in, 0, sizeof in);
    in.ps = ps;
    memset(&st, 0, sizeof st);
    st.material = -1;
    while ((r = next(&in, &kw, &line)) > 0) {
        if (looks_numeric(&kw)) {
            char show[40];
            /* a number where an entity should start: one too many for the
             * entity before it when on its last line */
            if (st.last_what && line == in.prev_line)
                return stp_fail(ps, line, "%s: expected %s, found more", st.last_what,
                                st.last_expect);
            return stp_fail(ps, line, "unexpected number '%s' (expected an entity keyword)",
                            stp_token_show(&kw, show, sizeof show));
        }
        if (read_entity(&in, &st, &kw, line) != 0)
            return -1;
        in.prev_line = in.last_line;
    }
    return r;
}
