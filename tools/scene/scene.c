/* SPDX-License-Identifier: MIT */
/*
 * Scene model: options, loading by extension, freeing, and the scanner,
 * number parsing and growable arrays shared by the NFF, OBJ and OFF readers.
 */
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene.h"
#include "scene_private.h"
#include "scene_util.h"

size_t stp_scene_byte_limit = STP_SCENE_DEFAULT_BYTE_LIMIT;

void stp_scene_options_default(stp_scene_options *opt)
{
    if (!opt)
        return;
    opt->sphere_slices = 16;
    opt->sphere_stacks = 8;
    opt->cone_slices = 16;
    opt->analytic_only = 0;
}

void stp_scene_free(stp_scene *scene)
{
    if (!scene)
        return;
    free(scene->lights);
    free(scene->materials);
    free(scene->vertices);
    free(scene->normals);
    free(scene->polygons);
    free(scene->prims);
    memset(scene, 0, sizeof *scene);
}

/* ---- messages ---------------------------------------------------------- */

static void write_message(char *err, size_t err_size, const char *name, long line,
                          const char *fmt, va_list ap)
{
    int n;
    if (!err || err_size == 0)
        return;
    if (line > 0)
        n = snprintf(err, err_size, "%s:%ld: ", name, line);
    else
        n = snprintf(err, err_size, "%s: ", name);
    if (n < 0) {
        err[0] = '\0';
        return;
    }
    if ((size_t)n < err_size)
        vsnprintf(err + n, err_size - (size_t)n, fmt, ap);
}

int stp_fail(stp_parser *ps, long line, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    write_message(ps->err, ps->err_size, ps->name, line, fmt, ap);
    va_end(ap);
    return -1;
}

/* For failures before a parser exists (bad arguments, unreadable file). */
static int fail_plain(char *err, size_t err_size, const char *name, const char *fmt, ...)
    STP_SCENE_PRINTF(4, 5);
static int fail_plain(char *err, size_t err_size, const char *name, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    write_message(err, err_size, name, 0, fmt, ap);
    va_end(ap);
    return -1;
}

const char *stp_token_show(const stp_token *tok, char *buf, size_t size)
{
    /* Tokens can hold any byte; keep messages short and printable. */
    size_t i, n = tok->n, keep;
    if (size < 8) {
        if (size)
            buf[0] = '\0';
        return buf;
    }
    keep = n < size - 1 ? n : size - 4;
    for (i = 0; i < keep; i++) {
        unsigned char c = (unsigned char)tok->s[i];
        buf[i] = (c >= 0x20 && c < 0x7f) ? (char)c : '?';
    }
    if (keep < n) {
        memcpy(buf + keep, "...", 3);
        keep += 3;
    }
    buf[keep] = '\0';
    return buf;
}

/* ---- scanning ---------------------------------------------------------- */

static int is_space(char c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

int stp_next_token(stp_line *ln, stp_token *tok)
{
    const char *p = ln->p;
    while (p < ln->end && is_space(*p))
        p++;
    if (p == ln->end || *p == '#') {
        ln->p = ln->end;
        return 0;
    }
    tok->s = p;
    while (p < ln->end && !is_space(*p))
        p++;
    tok->n = (size_t)(p - tok->s);
    ln->p = p;
    return 1;
}

int stp_next_line(stp_parser *ps, stp_line *ln)
{
    while (ps->pos < ps->size) {
        const char *start = ps->text + ps->pos;
        size_t rest = ps->size - ps->pos;
        const char *nl = memchr(start, '\n', rest);
        size_t len = nl ? (size_t)(nl - start) : rest, skip = nl ? 1 : 0;
        /* a CR not followed by LF ends a line too (classic Mac OS files);
         * one before LF stays in the line, as blank */
        const char *cr = memchr(start, '\r', len);
        long number = ps->line;
        stp_line probe;
        stp_token tok;

        if (cr && !(cr + 1 == nl)) {
            len = (size_t)(cr - start);
            skip = 1;
        }
        ps->pos += len + skip;
        if (ps->line < LONG_MAX)
            ps->line++;
        /* Text never legitimately holds NUL; refusing it keeps every later
         * step free to treat lines as ordinary strings. */
        if (memchr(start, '\0', len))
            return stp_fail(ps, number, "NUL byte in input");
        ln->p = start;
        ln->end = start + len;
        ln->number = number;
        probe = *ln;
        if (stp_next_token(&probe, &tok))
            return 1;
    }
    return 0;
}

int stp_count_tokens(const stp_line *ln)
{
    stp_line probe = *ln;
    stp_token tok;
    int n = 0;
    while (n < INT_MAX && stp_next_token(&probe, &tok))
        n++;
    return n;
}

int stp_token_is(const stp_token *tok, const char *word)
{
    size_t n = strlen(word);
    return tok->n == n && memcmp(tok->s, word, n) == 0;
}

/* ---- numbers ----------------------------------------------------------- */

int stp_parse_double(stp_parser *ps, long line, const stp_token *tok, double *out)
{
    char buf[128], show[40];
    char *end;
    size_t i;
    double v;

    if (tok->n >= sizeof buf)
        return stp_fail(ps, line, "number too long '%s'", stp_token_show(tok, show, sizeof show));
    /* Only plain decimal notation: this refuses nan, inf and hex floats,
     * which strtod would otherwise accept. */
    for (i = 0; i < tok->n; i++) {
        char c = tok->s[i];
        if (!((c >= '0' && c <= '9') || c == '.' || c == '+' || c == '-' || c == 'e' || c == 'E'))
            return stp_fail(ps, line, "bad number '%s'", stp_token_show(tok, show, sizeof show));
    }
    memcpy(buf, tok->s, tok->n);
    buf[tok->n] = '\0';
    errno = 0;
    v = strtod(buf, &end);
    if (end != buf + tok->n || tok->n == 0)
        return stp_fail(ps, line, "bad number '%s'", stp_token_show(tok, show, sizeof show));
    if (!isfinite(v))
        return stp_fail(ps, line, "number out of range '%s'",
                        stp_token_show(tok, show, sizeof show));
    *out = v;
    return 0;
}

int stp_parse_integer(stp_parser *ps, long line, const stp_token *tok, long long *out)
{
    const long long limit = 1000000000000000LL;
    char show[40];
    size_t i = 0;
    int neg = 0;
    long long v = 0;

    if (tok->n > 0 && (tok->s[0] == '+' || tok->s[0] == '-')) {
        neg = tok->s[0] == '-';
        i = 1;
    }
    if (i == tok->n)
        return stp_fail(ps, line, "bad integer '%s'", stp_token_show(tok, show, sizeof show));
    for (; i < tok->n; i++) {
        char c = tok->s[i];
        if (c < '0' || c > '9')
            return stp_fail(ps, line, "bad integer '%s'", stp_token_show(tok, show, sizeof show));
        v = v * 10 + (c - '0');
        if (v > limit)
            return stp_fail(ps, line, "integer out of range '%s'",
                            stp_token_show(tok, show, sizeof show));
    }
    *out = neg ? -v : v;
    return 0;
}

int stp_read_numbers(stp_parser *ps, stp_line *ln, double *out, int min, int max,
                     const char *what)
{
    stp_token tok;
    int n = 0;
    while (stp_next_token(ln, &tok)) {
        if (n == max) {
            if (min == max)
                return stp_fail(ps, ln->number, "%s: expected %d numbers, found more", what, max);
            return stp_fail(ps, ln->number, "%s: expected %d to %d numbers, found more", what,
                            min, max);
        }
        if (stp_parse_double(ps, ln->number, &tok, &out[n]) != 0)
            return -1;
        n++;
    }
    if (n < min) {
        if (min == max)
            return stp_fail(ps, ln->number, "%s: expected %d numbers, found %d", what, min, n);
        return stp_fail(ps, ln->number, "%s: expected %d to %d numbers, found %d", what, min,
                        max, n);
    }
    return n;
}

int stp_expect_end(stp_parser *ps, stp_line *ln, const char *what)
{
    stp_token tok;
    char show[40];
    if (stp_next_token(ln, &tok))
        return stp_fail(ps, ln->number, "%s: unexpected '%s'", what,
                        stp_token_show(&tok, show, sizeof show));
    return 0;
}

/* ---- arrays ------------------------------------------------------------ */

/* Capacity for need elements of elem bytes that keeps the budget: doubling
 * when it fits, the exact need near the limit. */
static int new_capacity(stp_parser *ps, long line, size_t cap, size_t need, size_t elem,
                        size_t *out)
{
    size_t held = ps->bytes - cap * elem; /* bytes held by everything else */
    size_t room = held < stp_scene_byte_limit ? stp_scene_byte_limit - held : 0;
    size_t max_elems = room / elem;
    size_t want;

    if (need > max_elems)
        return stp_fail(ps, line,
                        ps->opt->analytic_only
                            ? "scene too large (over %zu bytes)"
                            : "scene too large (over %zu bytes; fewer --slices/--stacks, or "
                              "--raytrace, which keeps spheres and cones unsplit, would help)",
                        stp_scene_byte_limit);
    want = cap < 16 ? 16 : cap;
    while (want < need && want <= SIZE_MAX / 2)
        want *= 2;
    if (want < need)
        want = need;
    if (want > max_elems)
        want = max_elems;
    *out = want;
    return 0;
}

int stp_grow(stp_parser *ps, long line, void **arr, size_t *cap, size_t need, size_t elem)
{
    size_t newcap = 0;
    void *p;
    if (need <= *cap)
        return 0;
    if (new_capacity(ps, line, *cap, need, elem, &newcap) != 0)
        return -1;
    p = realloc(*arr, newcap * elem);
    if (!p)
        return stp_fail(ps, line, "out of memory");
    *arr = p;
    ps->bytes = ps->bytes - *cap * elem + newcap * elem;
    *cap = newcap;
    return 0;
}

void stp_release(stp_parser *ps, void *arr, size_t cap, size_t elem)
{
    free(arr);
    ps->bytes -= cap * elem;
}

int stp_add_vertex(stp_parser *ps, long line, const stp_scene_vec3 *v, const stp_scene_vec3 *n)
{
    static const stp_scene_vec3 zero = {0.0, 0.0, 0.0};
    stp_scene *s = ps->scene;
    size_t need = s->vertex_count + 1;

    /* Finite input can still overflow in tessellation (huge centre plus
     * huge radius); refuse rather than hand infinities to the renderer. */
    if (!isfinite(v->x) || !isfinite(v->y) || !isfinite(v->z) ||
        (n && (!isfinite(n->x) || !isfinite(n->y) || !isfinite(n->z))))
        return stp_fail(ps, line, "coordinate out of range");
    if (need > ps->vertex_cap) {
        /* vertices and normals are parallel: grow both under one capacity. */
        const size_t elem = sizeof(stp_scene_vec3);
        size_t newcap = 0;
        void *p;
        if (new_capacity(ps, line, ps->vertex_cap, need, 2 * elem, &newcap) != 0)
            return -1;
        p = realloc(s->vertices, newcap * elem);
        if (!p)
            return stp_fail(ps, line, "out of memory");
        s->vertices = p;
        p = realloc(s->normals, newcap * elem);
        if (!p)
            return stp_fail(ps, line, "out of memory");
        s->normals = p;
        ps->bytes = ps->bytes - ps->vertex_cap * 2 * elem + newcap * 2 * elem;
        ps->vertex_cap = newcap;
    }
    s->vertices[s->vertex_count] = *v;
    s->normals[s->vertex_count] = n ? *n : zero;
    s->vertex_count++;
    return 0;
}

int stp_add_polygon(stp_parser *ps, long line, size_t first, int count, int material,
                    int has_normals)
{
    stp_scene *s = ps->scene;
    stp_scene_polygon *pg;
    if (stp_grow(ps, line, (void **)&s->polygons, &ps->polygon_cap, s->polygon_count + 1,
                 sizeof *s->polygons) != 0)
        return -1;
    pg = &s->polygons[s->polygon_count++];
    pg->first = first;
    pg->count = count;
    pg->material = material;
    pg->has_normals = has_normals;
    pg->prim = -1;
    pg->source_line = line > INT_MAX ? INT_MAX : (int)line;
    return 0;
}

int stp_add_prim(stp_parser *ps, long line, const stp_scene_prim *prim)
{
    stp_scene *s = ps->scene;
    if (stp_grow(ps, line, (void **)&s->prims, &ps->prim_cap, s->prim_count + 1,
                 sizeof *s->prims) != 0)
        return -1;
    s->prims[s->prim_count++] = *prim;
    return 0;
}

int stp_add_light(stp_parser *ps, long line, const stp_scene_light *light)
{
    stp_scene *s = ps->scene;
    if (stp_grow(ps, line, (void **)&s->lights, &ps->light_cap, s->light_count + 1,
                 sizeof *s->lights) != 0)
        return -1;
    s->lights[s->light_count++] = *light;
    return 0;
}

int stp_add_material(stp_parser *ps, long line, const stp_scene_material *m)
{
    stp_scene *s = ps->scene;
    if (s->material_count >= INT_MAX)
        return stp_fail(ps, line, "too many materials");
    if (stp_grow(ps, line, (void **)&s->materials, &ps->material_cap, s->material_count + 1,
                 sizeof *s->materials) != 0)
        return -1;
    s->materials[s->material_count] = *m;
    return (int)s->material_count++;
}

int stp_add_default_material(stp_parser *ps, long line)
{
    stp_scene_material m;
    m.color[0] = m.color[1] = m.color[2] = 1.0;
    m.kd = 1.0;
    m.ks = 0.0;
    m.shine = 0.0;
    m.t = 0.0;
    m.ior = 1.0;
    return stp_add_material(ps, line, &m);
}

/* ---- entry points ------------------------------------------------------ */

static int check_options(const stp_scene_options *opt, const char *name, char *err,
                         size_t err_size)
{
    const int max = STP_SCENE_MAX_TESSELLATION;
    if (opt->sphere_slices < 3 || opt->sphere_slices > max)
        return fail_plain(err, err_size, name, "sphere_slices must be 3..%d, not %d", max,
                          opt->sphere_slices);
    if (opt->sphere_stacks < 2 || opt->sphere_stacks > max)
        return fail_plain(err, err_size, name, "sphere_stacks must be 2..%d, not %d", max,
                          opt->sphere_stacks);
    if (opt->cone_slices < 3 || opt->cone_slices > max)
        return fail_plain(err, err_size, name, "cone_slices must be 3..%d, not %d", max,
                          opt->cone_slices);
    return 0;
}

/* held: bytes already spent by the caller (the file text) against the budget. */
static int parse_impl(const char *text, size_t size, const char *format, const char *name,
                      const stp_scene_options *opt, stp_scene *scene, char *err,
                      size_t err_size, size_t held)
{
    stp_scene_options defaults;
    stp_parser ps;
    int (*reader)(stp_parser *);
    int rc;

    if (err && err_size)
        err[0] = '\0';
    if (!name)
        name = "<input>";
    if (!scene)
        return fail_plain(err, err_size, name, "no scene to fill");
    memset(scene, 0, sizeof *scene);
    if (!opt) {
        stp_scene_options_default(&defaults);
        opt = &defaults;
    }
    if (check_options(opt, name, err, err_size) != 0)
        return -1;
    if (!text && size > 0)
        return fail_plain(err, err_size, name, "no text");
    if (!format)
        return fail_plain(err, err_size, name, "no format given");
    if (strcmp(format, "nff") == 0)
        reader = stp_parse_nff;
    else if (strcmp(format, "obj") == 0)
        reader = stp_parse_obj;
    else if (strcmp(format, "off") == 0)
        reader = stp_parse_off;
    else if (strcmp(format, "ply") == 0)
        reader = stp_parse_ply;
    else
        return fail_plain(err, err_size, name, "unknown format '%.16s'", format);

    memset(&ps, 0, sizeof ps);
    ps.text = text ? text : "";
    ps.size = text ? size : 0;
    ps.line = 1;
    ps.name = name;
    ps.err = err;
    ps.err_size = err_size;
    ps.scene = scene;
    ps.opt = opt;
    ps.bytes = held;
    /* A UTF-8 byte-order mark (editors on some systems write one) is not
     * part of any format's first line. */
    if (ps.size >= 3 && memcmp(ps.text, "\xEF\xBB\xBF", 3) == 0)
        ps.pos = 3;

    {
        /* An empty or comment-only file has no line to point at. */
        stp_parser probe = ps;
        stp_line ln;
        rc = stp_next_line(&probe, &ln);
        if (rc < 0)
            return -1;
        if (rc == 0)
            return fail_plain(err, err_size, name, "empty file");
    }

    rc = reader(&ps);
    if (rc == 0 && scene->polygon_count == 0 && scene->prim_count == 0)
        rc = stp_fail(&ps, 0, "no geometry");
    if (rc != 0) {
        stp_scene_free(scene);
        return -1;
    }
    return 0;
}

int stp_scene_parse(const char *text, size_t size, const char *format, const char *name,
                    const stp_scene_options *opt, stp_scene *scene, char *err, size_t err_size)
{
    return parse_impl(text, size, format, name, opt, scene, err, err_size, 0);
}

static int ascii_lower(int c)
{
    return (c >= 'A' && c <= 'Z') ? c - 'A' + 'a' : c;
}

static int ext_is(const char *ext, const char *want)
{
    for (; *ext && *want; ext++, want++)
        if (ascii_lower((unsigned char)*ext) != *want)
            return 0;
    return *ext == '\0' && *want == '\0';
}

int stp_scene_load(const char *path, const stp_scene_options *opt, stp_scene *scene,
                   char *err, size_t err_size)
{
    return stp_scene_load_as(path, NULL, opt, scene, err, err_size);
}

int stp_scene_load_as(const char *path, const char *format, const stp_scene_options *opt,
                      stp_scene *scene, char *err, size_t err_size)
{
    const char *slash, *dot;
    int from_stdin;
    char *text = NULL;
    size_t size = 0, cap = 0;
    FILE *f;
    int rc;

    if (err && err_size)
        err[0] = '\0';
    if (scene)
        memset(scene, 0, sizeof *scene);
    if (!path)
        return fail_plain(err, err_size, "<null>", "no path");
    if (!scene)
        return fail_plain(err, err_size, path, "no scene to fill");

    from_stdin = strcmp(path, "-") == 0;
    slash = strrchr(path, '/');
    dot = strrchr(slash ? slash + 1 : path, '.');
    if (format)
        ; /* given: parse_impl checks it */
    else if (from_stdin)
        return fail_plain(err, err_size, "stdin", "no scene format given for standard input");
    else if (dot && ext_is(dot + 1, "nff"))
        format = "nff";
    else if (dot && ext_is(dot + 1, "obj"))
        format = "obj";
    else if (dot && ext_is(dot + 1, "off"))
        format = "off";
    else if (dot && ext_is(dot + 1, "ply"))
        format = "ply";
    else
        return fail_plain(err, err_size, path,
                          "unknown scene format (expected .nff, .obj, .off or .ply)");

    if (from_stdin)
        path = "stdin"; /* the name in messages */
    f = from_stdin ? stdin : fopen(path, "rb");
    if (!f)
        return fail_plain(err, err_size, path, "%s", strerror(errno));
    /* Read in growing chunks: works for pipes too and never trusts a size
     * reported up front. */
    for (;;) {
        size_t got;
        if (size == cap) {
            size_t newcap = cap ? cap * 2 : 65536;
            char *p;
            if (newcap > stp_scene_byte_limit)
                newcap = stp_scene_byte_limit;
            if (newcap <= cap) {
                free(text);
                if (!from_stdin)
                    fclose(f);
                return fail_plain(err, err_size, path, "file too large (over %zu bytes)",
                                  stp_scene_byte_limit);
            }
            p = realloc(text, newcap);
            if (!p) {
                free(text);
                if (!from_stdin)
                    fclose(f);
                return fail_plain(err, err_size, path, "out of memory");
            }
            text = p;
            cap = newcap;
        }
        got = fread(text + size, 1, cap - size, f);
        size += got;
        if (got == 0) {
            if (ferror(f)) {
                int e = errno;
                free(text);
                if (!from_stdin)
                    fclose(f);
                return fail_plain(err, err_size, path, "read error: %s",
                                  e ? strerror(e) : "unknown");
            }
            break;
        }
    }
    if (!from_stdin)
        fclose(f);

    /* The text counts against the budget while the scene is built. */
    rc = parse_impl(text, size, format, path, opt, scene, err, err_size, cap);
    free(text);
    return rc;
}

/* ---- utilities --------------------------------------------------------- */

static void widen(stp_scene_vec3 *lo, stp_scene_vec3 *hi, double x, double y, double z,
                  double ex, double ey, double ez)
{
    if (x - ex < lo->x) lo->x = x - ex;
    if (y - ey < lo->y) lo->y = y - ey;
    if (z - ez < lo->z) lo->z = z - ez;
    if (x + ex > hi->x) hi->x = x + ex;
    if (y + ey > hi->y) hi->y = y + ey;
    if (z + ez > hi->z) hi->z = z + ez;
}

/* Extent along each axis of a disc of radius r with unit normal w:
 * r * sqrt(1 - w_i^2). */
static void widen_disc(stp_scene_vec3 *lo, stp_scene_vec3 *hi, const stp_scene_vec3 *c,
                       double r, const stp_scene_vec3 *w)
{
    double ex = r * sqrt(fmax(0.0, 1.0 - w->x * w->x));
    double ey = r * sqrt(fmax(0.0, 1.0 - w->y * w->y));
    double ez = r * sqrt(fmax(0.0, 1.0 - w->z * w->z));
    widen(lo, hi, c->x, c->y, c->z, ex, ey, ez);
}

int stp_scene_bounds(const stp_scene *scene, stp_scene_vec3 *lo, stp_scene_vec3 *hi)
{
    stp_scene_vec3 a, b;
    size_t i;

    if (!scene || (scene->vertex_count == 0 && scene->prim_count == 0))
        return -1;
    a.x = a.y = a.z = HUGE_VAL;
    b.x = b.y = b.z = -HUGE_VAL;
    for (i = 0; i < scene->vertex_count; i++) {
        const stp_scene_vec3 *v = &scene->vertices[i];
        widen(&a, &b, v->x, v->y, v->z, 0.0, 0.0, 0.0);
    }
    /* Analytic shapes bound their (inscribed) tessellations. */
    for (i = 0; i < scene->prim_count; i++) {
        const stp_scene_prim *p = &scene->prims[i];
        if (p->kind == STP_SCENE_SPHERE) {
            double r = fabs(p->base_radius);
            widen(&a, &b, p->base.x, p->base.y, p->base.z, r, r, r);
        } else {
            stp_scene_vec3 w;
            double h;
            w.x = p->apex.x - p->base.x;
            w.y = p->apex.y - p->base.y;
            w.z = p->apex.z - p->base.z;
            h = hypot(hypot(w.x, w.y), w.z);
            if (h > 0.0) {
                w.x /= h;
                w.y /= h;
                w.z /= h;
            }
            widen_disc(&a, &b, &p->base, fabs(p->base_radius), &w);
            widen_disc(&a, &b, &p->apex, fabs(p->apex_radius), &w);
        }
    }
    if (lo)
        *lo = a;
    if (hi)
        *hi = b;
    return 0;
}
