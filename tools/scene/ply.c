/* SPDX-License-Identifier: MIT */
/*
 * PLY reader (Stanford polygon file format) in its three encodings: ascii,
 * binary_little_endian and binary_big_endian, version 1.0.
 *
 * The header ("ply", "format", "comment", "obj_info", "element NAME COUNT",
 * "property TYPE NAME", "property list COUNT_TYPE ITEM_TYPE NAME",
 * "end_header") declares elements; every element is read (so unknown ones
 * such as "edge" or "material" are skipped correctly, lists included), but
 * only two are used:
 *  - "vertex": scalar properties x, y, z (required) and nx, ny, nz (all
 *    three, else none: the polygons' vertex normals); colours and any other
 *    property are read and checked, then ignored;
 *  - "face": the list property "vertex_indices" (or "vertex_index") of
 *    0-based indices into the vertices, at least 3 per face.
 * The vertex element must come before the face element.  Types: char/int8,
 * uchar/uint8, short/int16, ushort/uint16, int/int32, uint/uint32,
 * float/float32, double/float64; list counts and indices must be integers.
 *
 * ASCII bodies hold one element instance per line (as every writer does),
 * so messages give "name:line:"; binary bodies give "name: byte N:" (the
 * offset of the value at fault from the start of the file).  Polygons of a
 * binary body carry the header line of the face element as source_line.
 * Counts are not trusted: arrays grow as data really arrives, and a binary
 * element of fixed-size instances is checked against the bytes left first.
 */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "scene_private.h"

#define PLY_MAX_ELEMENTS 32
#define PLY_MAX_PROPERTIES 64
#define PLY_NAME_MAX 32

typedef enum ply_type {
    PLY_NONE,
    PLY_INT8,
    PLY_UINT8,
    PLY_INT16,
    PLY_UINT16,
    PLY_INT32,
    PLY_UINT32,
    PLY_FLOAT32,
    PLY_FLOAT64
} ply_type;

typedef enum ply_encoding { PLY_ASCII, PLY_LITTLE, PLY_BIG } ply_encoding;

/* What a property means to the scene. */
enum { ROLE_NONE = -1, ROLE_X, ROLE_Y, ROLE_Z, ROLE_NX, ROLE_NY, ROLE_NZ, ROLE_COUNT };

typedef struct ply_property {
    ply_type type;       /* scalar type, or a list's item type */
    ply_type count_type; /* PLY_NONE for a scalar */
    int role;            /* ROLE_* of a vertex scalar, else ROLE_NONE */
    int is_indices;      /* the face element's vertex_indices list */
} ply_property;

typedef enum ply_kind { KIND_OTHER, KIND_VERTEX, KIND_FACE } ply_kind;

typedef struct ply_element {
    char name[PLY_NAME_MAX];
    long long count;
    long line; /* header line declaring it */
    ply_kind kind;
    ply_property props[PLY_MAX_PROPERTIES];
    int prop_count;
} ply_element;

typedef struct ply_state {
    ply_encoding encoding;
    ply_element elements[PLY_MAX_ELEMENTS];
    int element_count;
    size_t body; /* offset of the first byte after end_header */
    size_t at;   /* binary: offset of the next unread byte */
    stp_scene_vec3 *pos, *nrm;
    size_t pos_cap, nrm_cap, pos_count;
    int has_normals;
    long long *indices; /* one face's indices */
    size_t index_cap;
} ply_state;

/* Where the value being read is: the ASCII line, or the binary offset. */
typedef struct ply_cursor {
    stp_line line;  /* ASCII: the rest of the instance's line */
    size_t offset;  /* binary: offset of the value being read */
    size_t start;   /* binary: offset of the instance */
} ply_cursor;

static const struct {
    const char *name;
    ply_type type;
} type_names[] = {{"char", PLY_INT8},     {"int8", PLY_INT8},       {"uchar", PLY_UINT8},
                  {"uint8", PLY_UINT8},   {"short", PLY_INT16},     {"int16", PLY_INT16},
                  {"ushort", PLY_UINT16}, {"uint16", PLY_UINT16},   {"int", PLY_INT32},
                  {"int32", PLY_INT32},   {"uint", PLY_UINT32},     {"uint32", PLY_UINT32},
                  {"float", PLY_FLOAT32}, {"float32", PLY_FLOAT32}, {"double", PLY_FLOAT64},
                  {"float64", PLY_FLOAT64}};

static size_t type_size(ply_type t)
{
    switch (t) {
    case PLY_INT8:
    case PLY_UINT8: return 1;
    case PLY_INT16:
    case PLY_UINT16: return 2;
    case PLY_INT32:
    case PLY_UINT32:
    case PLY_FLOAT32: return 4;
    case PLY_FLOAT64: return 8;
    default: return 0;
    }
}

static int type_is_integer(ply_type t)
{
    return t != PLY_FLOAT32 && t != PLY_FLOAT64 && t != PLY_NONE;
}

/* Range of an integer type. */
static void integer_range(ply_type t, long long *lo, long long *hi)
{
    switch (t) {
    case PLY_INT8: *lo = -128; *hi = 127; break;
    case PLY_UINT8: *lo = 0; *hi = 255; break;
    case PLY_INT16: *lo = -32768; *hi = 32767; break;
    case PLY_UINT16: *lo = 0; *hi = 65535; break;
    case PLY_INT32: *lo = -2147483647LL - 1; *hi = 2147483647LL; break;
    default: *lo = 0; *hi = 4294967295LL; break;
    }
}

/* ---- header ------------------------------------------------------------ */

static int parse_type(stp_parser *ps, const stp_line *ln, const stp_token *tok, ply_type *out)
{
    char show[40];
    size_t i;
    for (i = 0; i < sizeof type_names / sizeof type_names[0]; i++)
        if (stp_token_is(tok, type_names[i].name)) {
            *out = type_names[i].type;
            return 0;
        }
    return stp_fail(ps, ln->number, "property: unknown type '%s'",
                    stp_token_show(tok, show, sizeof show));
}

static int need_token(stp_parser *ps, stp_line *ln, stp_token *tok, const char *what)
{
    if (!stp_next_token(ln, tok))
        return stp_fail(ps, ln->number, "%s", what);
    return 0;
}

static int header_format(stp_parser *ps, ply_state *st, stp_line *ln)
{
    stp_token tok;
    char show[40];
    if (need_token(ps, ln, &tok, "format: expected 'ascii', 'binary_little_endian' or "
                                 "'binary_big_endian'") != 0)
        return -1;
    if (stp_token_is(&tok, "ascii"))
        st->encoding = PLY_ASCII;
    else if (stp_token_is(&tok, "binary_little_endian"))
        st->encoding = PLY_LITTLE;
    else if (stp_token_is(&tok, "binary_big_endian"))
        st->encoding = PLY_BIG;
    else
        return stp_fail(ps, ln->number, "format: unknown encoding '%s'",
                        stp_token_show(&tok, show, sizeof show));
    if (need_token(ps, ln, &tok, "format: expected the version 1.0") != 0)
        return -1;
    if (!stp_token_is(&tok, "1.0") && !stp_token_is(&tok, "1"))
        return stp_fail(ps, ln->number, "format: version '%s' (only 1.0 is known)",
                        stp_token_show(&tok, show, sizeof show));
    return stp_expect_end(ps, ln, "format");
}

static int header_element(stp_parser *ps, ply_state *st, stp_line *ln)
{
    ply_element *el;
    stp_token name, count;
    int i;
    if (st->element_count == PLY_MAX_ELEMENTS)
        return stp_fail(ps, ln->number, "element: too many elements (limit %d)",
                        PLY_MAX_ELEMENTS);
    if (need_token(ps, ln, &name, "element: expected a name and a count") != 0 ||
        need_token(ps, ln, &count, "element: expected a name and a count") != 0)
        return -1;
    el = &st->elements[st->element_count];
    memset(el, 0, sizeof *el);
    if (stp_parse_integer(ps, ln->number, &count, &el->count) != 0)
        return -1;
    if (el->count < 0)
        return stp_fail(ps, ln->number, "element: negative count %lld", el->count);
    if (name.n >= PLY_NAME_MAX)
        name.n = PLY_NAME_MAX - 1; /* only compared with short names */
    memcpy(el->name, name.s, name.n);
    el->line = ln->number;
    el->kind = stp_token_is(&name, "vertex") ? KIND_VERTEX
               : stp_token_is(&name, "face") ? KIND_FACE
                                             : KIND_OTHER;
    for (i = 0; i < st->element_count; i++)
        if (st->elements[i].kind == el->kind && el->kind != KIND_OTHER)
            return stp_fail(ps, ln->number, "element: a second '%s' element", el->name);
    if (el->kind == KIND_FACE) {
        for (i = 0; i < st->element_count && st->elements[i].kind != KIND_VERTEX; i++)
            ;
        if (i == st->element_count)
            return stp_fail(ps, ln->number, "element: 'face' before 'vertex' is not supported");
    }
    st->element_count++;
    return stp_expect_end(ps, ln, "element");
}

static int vertex_role(const stp_token *name)
{
    static const char *const names[ROLE_COUNT] = {"x", "y", "z", "nx", "ny", "nz"};
    int r;
    for (r = 0; r < ROLE_COUNT; r++)
        if (stp_token_is(name, names[r]))
            return r;
    return ROLE_NONE;
}

static int header_property(stp_parser *ps, ply_state *st, stp_line *ln)
{
    ply_element *el;
    ply_property *p;
    stp_token tok, name;
    if (st->element_count == 0)
        return stp_fail(ps, ln->number, "property: before any element");
    el = &st->elements[st->element_count - 1];
    if (el->prop_count == PLY_MAX_PROPERTIES)
        return stp_fail(ps, ln->number, "property: too many in element '%s' (limit %d)",
                        el->name, PLY_MAX_PROPERTIES);
    p = &el->props[el->prop_count];
    memset(p, 0, sizeof *p);
    p->role = ROLE_NONE;
    if (need_token(ps, ln, &tok, "property: expected a type and a name") != 0)
        return -1;
    if (stp_token_is(&tok, "list")) {
        if (need_token(ps, ln, &tok, "property list: expected a count type, an item type "
                                     "and a name") != 0 ||
            parse_type(ps, ln, &tok, &p->count_type) != 0)
            return -1;
        if (!type_is_integer(p->count_type))
            return stp_fail(ps, ln->number, "property list: the count type must be an integer");
        if (need_token(ps, ln, &tok, "property list: expected an item type and a name") != 0 ||
            parse_type(ps, ln, &tok, &p->type) != 0)
            return -1;
    } else if (parse_type(ps, ln, &tok, &p->type) != 0) {
        return -1;
    }
    if (need_token(ps, ln, &name, "property: expected a name") != 0)
        return -1;
    if (p->count_type == PLY_NONE && el->kind == KIND_VERTEX)
        p->role = vertex_role(&name);
    if (p->count_type != PLY_NONE && el->kind == KIND_FACE &&
        (stp_token_is(&name, "vertex_indices") || stp_token_is(&name, "vertex_index"))) {
        if (!type_is_integer(p->type))
            return stp_fail(ps, ln->number, "property list: vertex indices must be integers");
        p->is_indices = 1;
    }
    el->prop_count++;
    return stp_expect_end(ps, ln, "property");
}

/* Checks what the scene needs once the header is read. */
static int check_header(stp_parser *ps, ply_state *st, long end_line)
{
    int e, i, roles[ROLE_COUNT], indices;
    for (e = 0; e < st->element_count; e++) {
        ply_element *el = &st->elements[e];
        if (el->prop_count == 0)
            return stp_fail(ps, el->line, "element '%s' has no properties", el->name);
        for (i = 0; i < ROLE_COUNT; i++)
            roles[i] = 0;
        indices = 0;
        for (i = 0; i < el->prop_count; i++) {
            if (el->props[i].role != ROLE_NONE && roles[el->props[i].role]++)
                return stp_fail(ps, el->line, "element 'vertex': a property named twice");
            indices += el->props[i].is_indices;
        }
        if (el->kind == KIND_VERTEX) {
            if (!roles[ROLE_X] || !roles[ROLE_Y] || !roles[ROLE_Z])
                return stp_fail(ps, el->line, "element 'vertex' lacks x, y or z");
            st->has_normals = roles[ROLE_NX] && roles[ROLE_NY] && roles[ROLE_NZ];
            if ((unsigned long long)el->count > stp_scene_byte_limit / sizeof(stp_scene_vec3))
                return stp_fail(ps, el->line, "element: too many vertices (%lld)", el->count);
        }
        if (el->kind == KIND_FACE && indices != 1)
            return stp_fail(ps, el->line, "element 'face' needs one list property "
                                          "'vertex_indices'");
    }
    for (e = 0; e < st->element_count && st->elements[e].kind != KIND_FACE; e++)
        ;
    if (e == st->element_count)
        return stp_fail(ps, end_line, "no 'face' element: nothing to draw");
    return 0;
}

static int read_header(stp_parser *ps, ply_state *st)
{
    stp_line ln;
    stp_token tok;
    char show[40];
    int have_format = 0, r;

    r = stp_next_line(ps, &ln);
    if (r <= 0) /* the caller refuses empty text */
        return r < 0 ? -1 : stp_fail(ps, 0, "empty file");
    stp_next_token(&ln, &tok);
    /* the file's very first line: a blank or '#' line before it is no PLY */
    if (ln.number != 1 || !stp_token_is(&tok, "ply") || stp_next_token(&ln, &tok))
        return stp_fail(ps, 1, "not a PLY file (the first line must be 'ply')");
    for (;;) {
        r = stp_next_line(ps, &ln);
        if (r < 0)
            return -1;
        if (r == 0)
            return stp_fail(ps, ln.number, "file ends before 'end_header'");
        stp_next_token(&ln, &tok);
        if (stp_token_is(&tok, "comment") || stp_token_is(&tok, "obj_info"))
            continue;
        if (stp_token_is(&tok, "end_header")) {
            if (stp_expect_end(ps, &ln, "end_header") != 0)
                return -1;
            if (!have_format)
                return stp_fail(ps, ln.number, "no 'format' line in the header");
            st->body = ps->pos;
            return check_header(ps, st, ln.number);
        }
        if (stp_token_is(&tok, "format")) {
            if (have_format)
                return stp_fail(ps, ln.number, "format: given twice");
            if (st->element_count > 0)
                return stp_fail(ps, ln.number, "format: after an element");
            if (header_format(ps, st, &ln) != 0)
                return -1;
            have_format = 1;
        } else if (stp_token_is(&tok, "element")) {
            if (!have_format)
                return stp_fail(ps, ln.number, "element: before the 'format' line");
            if (header_element(ps, st, &ln) != 0)
                return -1;
        } else if (stp_token_is(&tok, "property")) {
            if (header_property(ps, st, &ln) != 0)
                return -1;
        } else if (tok.n > 0 && (strchr("+-.", tok.s[0]) || (tok.s[0] >= '0' && tok.s[0] <= '9'))) {
            /* numbers: the data, with no end_header line before it */
            return stp_fail(ps, ln.number, "data before 'end_header' (the header must end with "
                                           "a line 'end_header')");
        } else {
            return stp_fail(ps, ln.number, "unknown header keyword '%s'",
                            stp_token_show(&tok, show, sizeof show));
        }
    }
}

/* ---- values ------------------------------------------------------------ */

/* Messages of the body: "name:line: what" (ASCII) or "name: byte N: what". */
static int body_fail(stp_parser *ps, const ply_state *st, const ply_cursor *cur,
                     const ply_element *el, long long index, const char *what)
{
    if (st->encoding == PLY_ASCII)
        return stp_fail(ps, cur->line.number, "%s %lld: %s", el->name, index, what);
    return stp_fail(ps, 0, "byte %zu: %s %lld: %s", cur->offset, el->name, index, what);
}

static int read_binary(stp_parser *ps, ply_state *st, ply_cursor *cur, const ply_element *el,
                       long long index, ply_type t, double *out)
{
    size_t n = type_size(t), i;
    unsigned char b[8];
    uint64_t u = 0;
    cur->offset = st->at;
    if (ps->size - st->at < n)
        return body_fail(ps, st, cur, el, index, "the file ends inside it");
    for (i = 0; i < n; i++)
        b[i] = (unsigned char)ps->text[st->at + (st->encoding == PLY_BIG ? i : n - 1 - i)];
    /* b now holds the value most significant byte first */
    for (i = 0; i < n; i++)
        u = (u << 8) | b[i];
    st->at += n;
    switch (t) {
    case PLY_INT8: *out = (double)(int8_t)(uint8_t)u; break;
    case PLY_UINT8: *out = (double)u; break;
    case PLY_INT16: *out = (double)(int16_t)(uint16_t)u; break;
    case PLY_UINT16: *out = (double)u; break;
    case PLY_INT32: *out = (double)(int32_t)(uint32_t)u; break;
    case PLY_UINT32: *out = (double)u; break;
    case PLY_FLOAT32: {
        uint32_t w = (uint32_t)u;
        float f;
        memcpy(&f, &w, sizeof f);
        *out = (double)f;
        break;
    }
    default: {
        double d;
        memcpy(&d, &u, sizeof d);
        *out = d;
        break;
    }
    }
    if (!isfinite(*out))
        return body_fail(ps, st, cur, el, index, "a value is not a finite number");
    return 0;
}

static int read_ascii(stp_parser *ps, ply_state *st, ply_cursor *cur, const ply_element *el,
                      long long index, ply_type t, double *out)
{
    stp_token tok;
    char show[40], what[96];
    if (!stp_next_token(&cur->line, &tok))
        return body_fail(ps, st, cur, el, index, "the line ends before its last property");
    if (type_is_integer(t)) {
        long long v, lo, hi;
        if (stp_parse_integer(ps, cur->line.number, &tok, &v) != 0)
            return -1;
        integer_range(t, &lo, &hi);
        if (v < lo || v > hi) {
            snprintf(what, sizeof what, "%s outside its type's range %lld..%lld",
                     stp_token_show(&tok, show, sizeof show), lo, hi);
            return body_fail(ps, st, cur, el, index, what);
        }
        *out = (double)v;
        return 0;
    }
    if (stp_parse_double(ps, cur->line.number, &tok, out) != 0)
        return -1;
    if (t == PLY_FLOAT32 && fabs(*out) > FLT_MAX) {
        snprintf(what, sizeof what, "%s outside float's range",
                 stp_token_show(&tok, show, sizeof show));
        return body_fail(ps, st, cur, el, index, what);
    }
    return 0;
}

static int read_value(stp_parser *ps, ply_state *st, ply_cursor *cur, const ply_element *el,
                      long long index, ply_type t, double *out)
{
    if (st->encoding == PLY_ASCII)
        return read_ascii(ps, st, cur, el, index, t, out);
    return read_binary(ps, st, cur, el, index, t, out);
}

/* ---- elements ---------------------------------------------------------- */

/* One list: its items go to st->indices when keep, else are checked and
 * dropped.  *count gets the number of items. */
static int read_list(stp_parser *ps, ply_state *st, ply_cursor *cur, const ply_element *el,
                     long long index, const ply_property *p, int keep, size_t *count)
{
    double v;
    size_t k, n;
    char what[96];
    if (read_value(ps, st, cur, el, index, p->count_type, &v) != 0)
        return -1;
    if (v < 0)
        return body_fail(ps, st, cur, el, index, "a negative list length");
    n = (size_t)v;
    if (keep && n > STP_SCENE_MAX_POLYGON_VERTICES) {
        snprintf(what, sizeof what, "%zu vertices (limit %d)", n,
                 STP_SCENE_MAX_POLYGON_VERTICES);
        return body_fail(ps, st, cur, el, index, what);
    }
    /* a list longer than its line or than the rest of the file is refused
     * before anything is allocated for it */
    if (st->encoding == PLY_ASCII && n > (size_t)stp_count_tokens(&cur->line)) {
        snprintf(what, sizeof what, "a list of %zu values, the line has %d more", n,
                 stp_count_tokens(&cur->line));
        return body_fail(ps, st, cur, el, index, what);
    }
    if (st->encoding != PLY_ASCII && n > (ps->size - st->at) / type_size(p->type))
        return body_fail(ps, st, cur, el, index, "the file ends inside its list");
    if (keep && stp_grow(ps, cur->line.number, (void **)&st->indices, &st->index_cap, n,
                         sizeof *st->indices) != 0)
        return -1;
    for (k = 0; k < n; k++) {
        if (read_value(ps, st, cur, el, index, p->type, &v) != 0)
            return -1;
        if (keep)
            st->indices[k] = (long long)v;
    }
    *count = n;
    return 0;
}

/* Reads instance `index` of el; vertex roles go to vals, a face's indices to
 * st->indices (*index_count of them). */
static int read_instance(stp_parser *ps, ply_state *st, ply_cursor *cur, const ply_element *el,
                         long long index, double vals[ROLE_COUNT], size_t *index_count)
{
    int i;
    for (i = 0; i < el->prop_count; i++) {
        const ply_property *p = &el->props[i];
        double v;
        if (p->count_type != PLY_NONE) {
            size_t n = 0;
            if (read_list(ps, st, cur, el, index, p, p->is_indices, &n) != 0)
                return -1;
            if (p->is_indices)
                *index_count = n;
            continue;
        }
        if (read_value(ps, st, cur, el, index, p->type, &v) != 0)
            return -1;
        if (p->role != ROLE_NONE)
            vals[p->role] = v;
    }
    if (st->encoding == PLY_ASCII) {
        stp_token tok;
        char show[40], what[96];
        if (stp_next_token(&cur->line, &tok)) {
            snprintf(what, sizeof what, "unexpected '%s' after its properties",
                     stp_token_show(&tok, show, sizeof show));
            return body_fail(ps, st, cur, el, index, what);
        }
    }
    return 0;
}

static int store_vertex(stp_parser *ps, ply_state *st, long line, const double vals[ROLE_COUNT])
{
    size_t i = st->pos_count;
    if (stp_grow(ps, line, (void **)&st->pos, &st->pos_cap, i + 1, sizeof *st->pos) != 0)
        return -1;
    st->pos[i].x = vals[ROLE_X];
    st->pos[i].y = vals[ROLE_Y];
    st->pos[i].z = vals[ROLE_Z];
    if (st->has_normals) {
        if (stp_grow(ps, line, (void **)&st->nrm, &st->nrm_cap, i + 1, sizeof *st->nrm) != 0)
            return -1;
        st->nrm[i].x = vals[ROLE_NX];
        st->nrm[i].y = vals[ROLE_NY];
        st->nrm[i].z = vals[ROLE_NZ];
    }
    st->pos_count++;
    return 0;
}

static int store_face(stp_parser *ps, ply_state *st, ply_cursor *cur, const ply_element *el,
                      long long index, size_t n, int material)
{
    stp_scene *s = ps->scene;
    size_t first = s->vertex_count, k;
    long line = st->encoding == PLY_ASCII ? cur->line.number : el->line;
    char what[96];
    cur->offset = cur->start; /* the message points at the face */
    if (n < 3) {
        snprintf(what, sizeof what, "needs at least 3 vertices, not %zu", n);
        return body_fail(ps, st, cur, el, index, what);
    }
    for (k = 0; k < n; k++) {
        long long vi = st->indices[k];
        if (vi < 0 || (size_t)vi >= st->pos_count) {
            snprintf(what, sizeof what, "index %lld out of range (0..%lld)", vi,
                     (long long)st->pos_count - 1);
            return body_fail(ps, st, cur, el, index, what);
        }
        if (stp_add_vertex(ps, line, &st->pos[vi], st->has_normals ? &st->nrm[vi] : NULL) != 0)
            return -1;
    }
    return stp_add_polygon(ps, line, first, (int)n, material, st->has_normals);
}

/* Bytes of one binary instance when it has no lists, else 0. */
static size_t fixed_size(const ply_element *el)
{
    size_t n = 0;
    int i;
    for (i = 0; i < el->prop_count; i++) {
        if (el->props[i].count_type != PLY_NONE)
            return 0;
        n += type_size(el->props[i].type);
    }
    return n;
}

static int read_element(stp_parser *ps, ply_state *st, const ply_element *el, int material)
{
    ply_cursor cur;
    long long i;
    size_t fixed = st->encoding == PLY_ASCII ? 0 : fixed_size(el);
    memset(&cur, 0, sizeof cur);
    cur.line.number = el->line;
    if (fixed && (unsigned long long)el->count > (ps->size - st->at) / fixed)
        return stp_fail(ps, 0, "byte %zu: element '%s': %lld of %zu bytes each need more "
                               "than the %zu bytes left",
                        st->at, el->name, el->count, fixed, ps->size - st->at);
    for (i = 0; i < el->count; i++) {
        double vals[ROLE_COUNT] = {0, 0, 0, 0, 0, 0};
        size_t n = 0;
        cur.start = st->at;
        if (st->encoding == PLY_ASCII) {
            int r = stp_next_line(ps, &cur.line);
            if (r < 0)
                return -1;
            if (r == 0)
                return stp_fail(ps, el->line, "file ends after %lld of %lld %s elements", i,
                                el->count, el->name);
        }
        if (read_instance(ps, st, &cur, el, i, vals, &n) != 0)
            return -1;
        if (el->kind == KIND_VERTEX && store_vertex(ps, st, cur.line.number, vals) != 0)
            return -1;
        if (el->kind == KIND_FACE && store_face(ps, st, &cur, el, i, n, material) != 0)
            return -1;
    }
    return 0;
}

static int read_body(stp_parser *ps, ply_state *st)
{
    int e, material;
    if (read_header(ps, st) != 0)
        return -1;
    st->at = st->body;
    material = stp_add_default_material(ps, st->elements[0].line);
    if (material < 0)
        return -1;
    for (e = 0; e < st->element_count; e++)
        if (read_element(ps, st, &st->elements[e], material) != 0)
            return -1;
    if (st->encoding == PLY_ASCII) {
        stp_line ln;
        int r = stp_next_line(ps, &ln);
        if (r < 0)
            return -1;
        if (r > 0)
            return stp_fail(ps, ln.number, "extra data after the last element");
    } else if (st->at != ps->size) {
        return stp_fail(ps, 0, "byte %zu: %zu bytes of extra data after the last element",
                        st->at, ps->size - st->at);
    }
    return 0;
}

int stp_parse_ply(stp_parser *ps)
{
    ply_state st;
    int rc;
    memset(&st, 0, sizeof st);
    rc = read_body(ps, &st);
    stp_release(ps, st.pos, st.pos_cap, sizeof *st.pos);
    stp_release(ps, st.nrm, st.nrm_cap, sizeof *st.nrm);
    stp_release(ps, st.indices, st.index_cap, sizeof *st.indices);
    return rc;
}
