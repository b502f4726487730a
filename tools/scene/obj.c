/* SPDX-License-Identifier: MIT */
/*
 * Wavefront OBJ reader: v, vn and f (v, v/vt, v//vn, v/vt/vn, negative
 * indices relative to the data read so far).  Texture coordinates are only
 * counted, to check indices.  Other keywords (g, o, s, usemtl, mtllib, l,
 * curves...) are skipped: OBJ has many and none changes the polygons.
 * Numbers and indices are checked strictly.
 */
#include <string.h>

#include "scene_private.h"

typedef struct obj_state {
    stp_scene_vec3 *pos, *nrm;
    size_t pos_count, pos_cap, nrm_count, nrm_cap;
    long long vt_count;
    int material;
} obj_state;

/* One index field of a face corner, resolved to 0-based. */
static int resolve(stp_parser *ps, long line, const char *s, size_t n, long long defined,
                   const char *what, long long *out)
{
    stp_token tok;
    char show[40];
    long long v, abs;
    tok.s = s;
    tok.n = n;
    if (n == 0)
        return stp_fail(ps, line, "f: empty %s index", what);
    if (stp_parse_integer(ps, line, &tok, &v) != 0)
        return -1;
    if (v == 0)
        return stp_fail(ps, line, "f: %s index 0 (indices start at 1)", what);
    abs = v > 0 ? v : defined + v + 1;
    if (abs < 1 || abs > defined)
        return stp_fail(ps, line, "f: %s index %s out of range (%lld defined)", what,
                        stp_token_show(&tok, show, sizeof show), defined);
    *out = abs - 1;
    return 0;
}

static int read_face(stp_parser *ps, obj_state *st, stp_line *ln)
{
    stp_scene *s = ps->scene;
    size_t first = s->vertex_count, i;
    int count = 0, all_normals = 1;
    stp_token tok;

    while (stp_next_token(ln, &tok)) {
        const char *slash1 = memchr(tok.s, '/', tok.n);
        const char *end = tok.s + tok.n;
        long long vi, ni = -1, ti;
        if (count == STP_SCENE_MAX_POLYGON_VERTICES)
            return stp_fail(ps, ln->number, "f: too many vertices (limit %d)",
                            STP_SCENE_MAX_POLYGON_VERTICES);
        if (resolve(ps, ln->number, tok.s, slash1 ? (size_t)(slash1 - tok.s) : tok.n,
                    (long long)st->pos_count, "vertex", &vi) != 0)
            return -1;
        if (slash1) {
            const char *t = slash1 + 1;
            const char *slash2 = memchr(t, '/', (size_t)(end - t));
            const char *t_end = slash2 ? slash2 : end;
            /* v/vt needs vt; v//vn may leave it out. */
            if (t_end > t || !slash2) {
                if (resolve(ps, ln->number, t, (size_t)(t_end - t), st->vt_count, "texture",
                            &ti) != 0)
                    return -1;
            }
            if (slash2) {
                const char *nstart = slash2 + 1;
                if (memchr(nstart, '/', (size_t)(end - nstart))) {
                    char show[40];
                    return stp_fail(ps, ln->number, "f: bad vertex '%s'",
                                    stp_token_show(&tok, show, sizeof show));
                }
                if (resolve(ps, ln->number, nstart, (size_t)(end - nstart),
                            (long long)st->nrm_count, "normal", &ni) != 0)
                    return -1;
            }
        }
        if (ni < 0)
            all_normals = 0;
        if (stp_add_vertex(ps, ln->number, &st->pos[vi], ni >= 0 ? &st->nrm[ni] : NULL) != 0)
            return -1;
        count++;
    }
    if (count < 3)
        return stp_fail(ps, ln->number, "f: a face needs at least 3 vertices, not %d", count);
    /* Normals only count when every corner has one ("zero where none"). */
    if (!all_normals)
        for (i = first; i < s->vertex_count; i++)
            memset(&s->normals[i], 0, sizeof s->normals[i]);
    if (st->material < 0) {
        st->material = stp_add_default_material(ps, ln->number);
        if (st->material < 0)
            return -1;
    }
    return stp_add_polygon(ps, ln->number, first, count, st->material, all_normals);
}

static int read_lines(stp_parser *ps, obj_state *st)
{
    stp_line ln;
    int r;
    while ((r = stp_next_line(ps, &ln)) > 0) {
        stp_token kw;
        double num[6];
        stp_next_token(&ln, &kw);
        if (stp_token_is(&kw, "v")) {
            /* x y z, optionally w (ignored) or r g b (the common colour
             * extension, ignored). */
            int n = stp_count_tokens(&ln);
            if (n != 3 && n != 4 && n != 6)
                return stp_fail(ps, ln.number, "v: expected 3, 4 or 6 numbers, found %d", n);
            if (stp_read_numbers(ps, &ln, num, n, n, "v") < 0)
                return -1;
            if (stp_grow(ps, ln.number, (void **)&st->pos, &st->pos_cap, st->pos_count + 1,
                         sizeof *st->pos) != 0)
                return -1;
            st->pos[st->pos_count].x = num[0];
            st->pos[st->pos_count].y = num[1];
            st->pos[st->pos_count].z = num[2];
            st->pos_count++;
        } else if (stp_token_is(&kw, "vn")) {
            if (stp_read_numbers(ps, &ln, num, 3, 3, "vn") < 0)
                return -1;
            if (stp_grow(ps, ln.number, (void **)&st->nrm, &st->nrm_cap, st->nrm_count + 1,
                         sizeof *st->nrm) != 0)
                return -1;
            st->nrm[st->nrm_count].x = num[0];
            st->nrm[st->nrm_count].y = num[1];
            st->nrm[st->nrm_count].z = num[2];
            st->nrm_count++;
        } else if (stp_token_is(&kw, "vt")) {
            st->vt_count++;
        } else if (stp_token_is(&kw, "f")) {
            if (read_face(ps, st, &ln) != 0)
                return -1;
        }
        /* anything else: skipped on purpose (see the top of the file) */
    }
    return r;
}

int stp_parse_obj(stp_parser *ps)
{
    obj_state st;
    int rc;
    memset(&st, 0, sizeof st);
    st.material = -1;
    rc = read_lines(ps, &st);
    stp_release(ps, st.pos, st.pos_cap, sizeof *st.pos);
    stp_release(ps, st.nrm, st.nrm_cap, sizeof *st.nrm);
    return rc;
}
