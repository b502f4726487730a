/* SPDX-License-Identifier: MIT */
/*
 * OFF reader (Geomview Object File Format, ASCII): header OFF, COFF, NOFF or
 * CNOFF (the counts may follow on the same line), "nv nf [ne]", nv vertex
 * lines "x y z [nx ny nz] [r g b [a]]", nf face lines "k i0 .. ik-1 [colour]"
 * with 0-based indices.  Counts are checked against what is really there.
 */
#include <string.h>

#include "scene_private.h"

typedef struct off_state {
    stp_scene_vec3 *pos, *nrm;
    size_t pos_cap, nrm_cap;
    int has_color, has_normals;
} off_state;

static int read_header(stp_parser *ps, off_state *st, stp_line *ln)
{
    stp_token tok;
    char show[40];
    int r = stp_next_line(ps, ln);
    if (r < 0)
        return -1;
    if (r == 0) /* unreachable: the caller refuses empty text */
        return stp_fail(ps, ps->line, "file ends before the OFF header");
    stp_next_token(ln, &tok);
    if (stp_token_is(&tok, "OFF")) {
        /* plain */
    } else if (stp_token_is(&tok, "COFF")) {
        st->has_color = 1;
    } else if (stp_token_is(&tok, "NOFF")) {
        st->has_normals = 1;
    } else if (stp_token_is(&tok, "CNOFF")) {
        st->has_color = 1;
        st->has_normals = 1;
    } else if (tok.n > 3 && memcmp(tok.s + tok.n - 3, "OFF", 3) == 0) {
        /* geomview's other variants: 4OFF, nOFF, STOFF, ... */
        return stp_fail(ps, ln->number, "'%s' is not read: only OFF, COFF, NOFF and CNOFF "
                                        "(3 dimensions, no texture coordinates)",
                        stp_token_show(&tok, show, sizeof show));
    } else {
        return stp_fail(ps, ln->number, "expected an OFF header, found '%s'",
                        stp_token_show(&tok, show, sizeof show));
    }
    {
        /* "OFF BINARY": the binary variant, whose counts and data are not text */
        stp_line rest = *ln;
        if (stp_next_token(&rest, &tok) && stp_token_is(&tok, "BINARY"))
            return stp_fail(ps, ln->number, "binary OFF is not read (only ASCII OFF): convert "
                                            "the file to ASCII");
    }
    return 0;
}

static int read_counts(stp_parser *ps, stp_line *ln, long long *nv, long long *nf)
{
    long long v[3];
    stp_token tok;
    int n = 0;
    while (stp_next_token(ln, &tok)) {
        if (n == 3)
            return stp_fail(ps, ln->number, "counts: expected 'vertices faces [edges]', "
                                            "found more");
        if (stp_parse_integer(ps, ln->number, &tok, &v[n]) != 0)
            return -1;
        if (v[n] < 0)
            return stp_fail(ps, ln->number, "counts: negative count %lld", v[n]);
        n++;
    }
    if (n < 2)
        return stp_fail(ps, ln->number, "counts: expected 'vertices faces [edges]'");
    /* Not used for allocation, but a count the budget could never hold is
     * refused before reading on. */
    if ((unsigned long long)v[0] > stp_scene_byte_limit / sizeof(stp_scene_vec3))
        return stp_fail(ps, ln->number, "counts: too many vertices (%lld)", v[0]);
    if ((unsigned long long)v[1] > stp_scene_byte_limit / sizeof(stp_scene_polygon))
        return stp_fail(ps, ln->number, "counts: too many faces (%lld)", v[1]);
    *nv = v[0];
    *nf = v[1];
    return 0;
}

static int read_vertex(stp_parser *ps, off_state *st, stp_line *ln, size_t index)
{
    const int base = st->has_normals ? 6 : 3;
    double num[10];
    int n;
    if (st->has_color) {
        /* the colour is RGB or RGBA */
        n = stp_count_tokens(ln);
        if (n != base + 3 && n != base + 4)
            return stp_fail(ps, ln->number, "vertex: expected %d or %d numbers, found %d",
                            base + 3, base + 4, n);
    } else {
        n = base;
    }
    if (stp_read_numbers(ps, ln, num, n, n, "vertex") < 0)
        return -1;
    if (stp_grow(ps, ln->number, (void **)&st->pos, &st->pos_cap, index + 1, sizeof *st->pos) != 0)
        return -1;
    st->pos[index].x = num[0];
    st->pos[index].y = num[1];
    st->pos[index].z = num[2];
    if (st->has_normals) {
        if (stp_grow(ps, ln->number, (void **)&st->nrm, &st->nrm_cap, index + 1,
                     sizeof *st->nrm) != 0)
            return -1;
        st->nrm[index].x = num[3];
        st->nrm[index].y = num[4];
        st->nrm[index].z = num[5];
    }
    return 0;
}

static int read_face(stp_parser *ps, off_state *st, stp_line *ln, long long nv, int material)
{
    stp_scene *s = ps->scene;
    size_t first = s->vertex_count;
    stp_token tok;
    long long k, i;
    double colour;
    int extra = 0;

    stp_next_token(ln, &tok);
    if (stp_parse_integer(ps, ln->number, &tok, &k) != 0)
        return -1;
    if (k < 3)
        return stp_fail(ps, ln->number, "face: needs at least 3 vertices, not %lld", k);
    if (k > STP_SCENE_MAX_POLYGON_VERTICES)
        return stp_fail(ps, ln->number, "face: too many vertices (%lld, limit %d)", k,
                        STP_SCENE_MAX_POLYGON_VERTICES);
    for (i = 0; i < k; i++) {
        long long vi;
        if (!stp_next_token(ln, &tok))
            return stp_fail(ps, ln->number, "face: expected %lld indices, found %lld", k, i);
        if (stp_parse_integer(ps, ln->number, &tok, &vi) != 0)
            return -1;
        if (vi < 0 || vi >= nv)
            return stp_fail(ps, ln->number, "face: index %lld out of range (0..%lld)", vi,
                            nv - 1);
        if (stp_add_vertex(ps, ln->number, &st->pos[vi], st->has_normals ? &st->nrm[vi] : NULL) !=
            0)
            return -1;
    }
    /* An optional face colour (colormap index, RGB or RGBA): checked as
     * numbers, otherwise ignored. */
    while (stp_next_token(ln, &tok)) {
        if (++extra > 4)
            return stp_fail(ps, ln->number, "face: too many values after the indices");
        if (stp_parse_double(ps, ln->number, &tok, &colour) != 0)
            return -1;
    }
    return stp_add_polygon(ps, ln->number, first, (int)k, material, st->has_normals);
}

static int read_body(stp_parser *ps, off_state *st)
{
    stp_line ln;
    long counts_line;
    long long nv = 0, nf = 0, i;
    int material, r;

    if (read_header(ps, st, &ln) != 0)
        return -1;
    {
        /* The counts may share the header line ("OFF 8 6 12"). */
        stp_line rest = ln;
        stp_token tok;
        if (!stp_next_token(&rest, &tok)) {
            r = stp_next_line(ps, &ln);
            if (r < 0)
                return -1;
            if (r == 0)
                return stp_fail(ps, ln.number, "file ends before the counts line");
        }
    }
    counts_line = ln.number;
    if (read_counts(ps, &ln, &nv, &nf) != 0)
        return -1;

    for (i = 0; i < nv; i++) {
        r = stp_next_line(ps, &ln);
        if (r < 0)
            return -1;
        if (r == 0)
            return stp_fail(ps, counts_line, "file ends after %lld of %lld vertices", i, nv);
        if (read_vertex(ps, st, &ln, (size_t)i) != 0)
            return -1;
    }
    material = stp_add_default_material(ps, counts_line);
    if (material < 0)
        return -1;
    for (i = 0; i < nf; i++) {
        r = stp_next_line(ps, &ln);
        if (r < 0)
            return -1;
        if (r == 0)
            return stp_fail(ps, counts_line, "file ends after %lld of %lld faces", i, nf);
        if (read_face(ps, st, &ln, nv, material) != 0)
            return -1;
    }
    r = stp_next_line(ps, &ln);
    if (r < 0)
        return -1;
    if (r > 0)
        return stp_fail(ps, ln.number, "extra data after the last face");
    return 0;
}

int stp_parse_off(stp_parser *ps)
{
    off_state st;
    int rc;
    memset(&st, 0, sizeof st);
    rc = read_body(ps, &st);
    stp_release(ps, st.pos, st.pos_cap, sizeof *st.pos);
    stp_release(ps, st.nrm, st.nrm_cap, sizeof *st.nrm);
    return rc;
}
