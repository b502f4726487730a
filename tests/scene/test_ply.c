/* SPDX-License-Identifier: MIT */
/*
 * Tests of the PLY reader (tools/scene/ply.c): one small mesh written by
 * hand in ASCII, binary little-endian and binary big-endian gives exactly
 * the same vertices, normals and polygons; every scalar type decodes;
 * unknown elements (with lists) are skipped; malformed files give the
 * expected "name:line:" (ASCII and header) or "name: byte N:" (binary)
 * message; files load from disk by their extension.
 */
#define _POSIX_C_SOURCE 200809L /* mkdtemp */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "scene.h"

#define ERR_SIZE 512

/* ---- building binary files byte by byte -------------------------------- */

typedef struct buf {
    unsigned char b[4096];
    size_t n;
    int big; /* 1: most significant byte first */
} buf;

static void put_text(buf *o, const char *s)
{
    size_t n = strlen(s);
    assert_true(o->n + n <= sizeof o->b);
    memcpy(o->b + o->n, s, n);
    o->n += n;
}

static void put_uint(buf *o, uint64_t v, int bytes)
{
    int i;
    assert_true(o->n + (size_t)bytes <= sizeof o->b);
    for (i = 0; i < bytes; i++) {
        int shift = 8 * (o->big ? bytes - 1 - i : i);
        o->b[o->n++] = (unsigned char)(v >> shift);
    }
}

static void put_f32(buf *o, float f)
{
    uint32_t u;
    memcpy(&u, &f, sizeof u);
    put_uint(o, u, 4);
}

static void put_f64(buf *o, double d)
{
    uint64_t u;
    memcpy(&u, &d, sizeof u);
    put_uint(o, u, 8);
}

/* ---- the mesh ---------------------------------------------------------- */

/* Four vertices (positions and normals exactly representable in float),
 * a quad and a triangle, and an "edge" element with a list to skip. */
static const double mesh_pos[4][3] = {{0, 0, 0}, {1.5, 0, 0}, {1.5, 2.25, -0.5}, {0, 2.25, -0.5}};
static const double mesh_nrm[4][3] = {{0, 0, 1}, {0, 0.5, 1}, {0.25, 0, 1}, {0, -0.75, 1}};
static const int mesh_quad[4] = {0, 1, 2, 3};
static const int mesh_tri[3] = {3, 2, 0};

static const char *mesh_ascii =
    "ply\n"                                      /* 1 */
    "format ascii 1.0\n"                         /* 2 */
    "comment hand-written test mesh\n"           /* 3 */
    "obj_info nothing\n"                         /* 4 */
    "element vertex 4\n"                         /* 5 */
    "property float x\n"                         /* 6 */
    "property float y\n"                         /* 7 */
    "property float z\n"                         /* 8 */
    "property float nx\n"                        /* 9 */
    "property float ny\n"                        /* 10 */
    "property float nz\n"                        /* 11 */
    "property uchar red\n"                       /* 12 */
    "property uchar green\n"                     /* 13 */
    "property uchar blue\n"                      /* 14 */
    "element face 2\n"                           /* 15 */
    "property list uchar int vertex_indices\n"   /* 16 */
    "element edge 1\n"                           /* 17 */
    "property list ushort short chain\n"         /* 18 */
    "property double weight\n"                   /* 19 */
    "end_header\n"                               /* 20 */
    "0 0 0 0 0 1 255 0 0\n"                      /* 21 */
    "1.5 0 0 0 0.5 1 0 255 0\n"                  /* 22 */
    "1.5 2.25 -0.5 0.25 0 1 0 0 255\n"           /* 23 */
    "0 2.25 -0.5 0 -0.75 1 9 9 9\n"              /* 24 */
    "4 0 1 2 3\n"                                /* 25 */
    "3 3 2 0\n"                                  /* 26 */
    "2 -7 300 0.125\n";                          /* 27 */

static void mesh_binary(buf *o, int big)
{
    int i;
    memset(o, 0, sizeof *o);
    o->big = big;
    put_text(o, big ? "ply\nformat binary_big_endian 1.0\n" : "ply\nformat binary_little_endian 1.0\n");
    put_text(o, "comment hand-written test mesh\n"
                "element vertex 4\n"
                "property float x\nproperty float y\nproperty float z\n"
                "property float nx\nproperty float ny\nproperty float nz\n"
                "property uchar red\nproperty uchar green\nproperty uchar blue\n"
                "element face 2\n"
                "property list uchar int vertex_indices\n"
                "element edge 1\n"
                "property list ushort short chain\n"
                "property double weight\n"
                "end_header\n");
    for (i = 0; i < 4; i++) {
        int c;
        for (c = 0; c < 3; c++)
            put_f32(o, (float)mesh_pos[i][c]);
        for (c = 0; c < 3; c++)
            put_f32(o, (float)mesh_nrm[i][c]);
        put_uint(o, 200, 1);
        put_uint(o, 100, 1);
        put_uint(o, 50, 1);
    }
    put_uint(o, 4, 1);
    for (i = 0; i < 4; i++)
        put_uint(o, (uint64_t)mesh_quad[i], 4);
    put_uint(o, 3, 1);
    for (i = 0; i < 3; i++)
        put_uint(o, (uint64_t)mesh_tri[i], 4);
    put_uint(o, 2, 2);
    put_uint(o, (uint16_t)-7, 2);
    put_uint(o, 300, 2);
    put_f64(o, 0.125);
}

static void check_mesh(const stp_scene *s, int line_quad, int line_tri)
{
    int k;
    assert_int_equal(s->polygon_count, 2);
    assert_int_equal(s->vertex_count, 7);
    assert_int_equal(s->material_count, 1);
    assert_int_equal(s->prim_count, 0);
    assert_int_equal(s->light_count, 0);
    assert_int_equal(s->has_view, 0);
    assert_int_equal(s->polygons[0].first, 0);
    assert_int_equal(s->polygons[0].count, 4);
    assert_int_equal(s->polygons[1].first, 4);
    assert_int_equal(s->polygons[1].count, 3);
    assert_int_equal(s->polygons[0].has_normals, 1);
    assert_int_equal(s->polygons[1].has_normals, 1);
    assert_int_equal(s->polygons[0].material, 0);
    assert_int_equal(s->polygons[0].prim, -1);
    assert_int_equal(s->polygons[0].source_line, line_quad);
    assert_int_equal(s->polygons[1].source_line, line_tri);
    for (k = 0; k < 7; k++) {
        int v = k < 4 ? mesh_quad[k] : mesh_tri[k - 4];
        assert_true(s->vertices[k].x == mesh_pos[v][0]);
        assert_true(s->vertices[k].y == mesh_pos[v][1]);
        assert_true(s->vertices[k].z == mesh_pos[v][2]);
        assert_true(s->normals[k].x == mesh_nrm[v][0]);
        assert_true(s->normals[k].y == mesh_nrm[v][1]);
        assert_true(s->normals[k].z == mesh_nrm[v][2]);
    }
}

static void parse_ok(const void *text, size_t size, stp_scene *s)
{
    char err[ERR_SIZE];
    if (stp_scene_parse((const char *)text, size, "ply", "t.ply", NULL, s, err, sizeof err) != 0) {
        print_error("unexpected failure: %s\n", err);
        fail();
    }
}

static void test_ascii(void **state)
{
    stp_scene s;
    (void)state;
    parse_ok(mesh_ascii, strlen(mesh_ascii), &s);
    check_mesh(&s, 25, 26);
    stp_scene_free(&s);
}

static void test_binary_little(void **state)
{
    buf o;
    stp_scene s;
    (void)state;
    mesh_binary(&o, 0);
    parse_ok(o.b, o.n, &s);
    /* binary polygons carry the face element's header line */
    check_mesh(&s, 14, 14);
    stp_scene_free(&s);
}

static void test_binary_big(void **state)
{
    buf o;
    stp_scene s;
    (void)state;
    mesh_binary(&o, 1);
    parse_ok(o.b, o.n, &s);
    check_mesh(&s, 14, 14);
    stp_scene_free(&s);
}

/* Every scalar type, signed ones negative, as vertex coordinates. */
static void test_binary_types(void **state)
{
    static const char *types[8] = {"char", "uchar", "short", "ushort",
                                   "int", "uint", "float", "double"};
    static const int sizes[8] = {1, 1, 2, 2, 4, 4, 4, 8};
    static const double values[8] = {-100, 200, -30000, 60000, -2000000000.0, 4000000000.0,
                                     -0.375, 1e300};
    int big;
    (void)state;
    for (big = 0; big <= 1; big++) {
        int t;
        for (t = 0; t < 8; t++) {
            buf o;
            stp_scene s;
            char header[512];
            memset(&o, 0, sizeof o);
            o.big = big;
            snprintf(header, sizeof header,
                     "ply\nformat binary_%s_endian 1.0\nelement vertex 3\n"
                     "property %s x\nproperty uint8 y\nproperty int16 z\n"
                     "element face 1\nproperty list uint8 uint16 vertex_index\nend_header\n",
                     big ? "big" : "little", types[t]);
            put_text(&o, header);
            {
                int v;
                for (v = 0; v < 3; v++) {
                    double x = v == 2 ? values[t] : (double)v;
                    if (t == 6)
                        put_f32(&o, (float)x);
                    else if (t == 7)
                        put_f64(&o, x);
                    else
                        put_uint(&o, (uint64_t)(int64_t)x, sizes[t]);
                    put_uint(&o, (uint64_t)(v * 10), 1);
                    put_uint(&o, (uint16_t)(int16_t)-v, 2);
                }
            }
            put_uint(&o, 3, 1);
            put_uint(&o, 2, 2);
            put_uint(&o, 0, 2);
            put_uint(&o, 1, 2);
            parse_ok(o.b, o.n, &s);
            assert_int_equal(s.vertex_count, 3);
            assert_true(s.vertices[0].x == values[t]);
            assert_true(s.vertices[0].y == 20);
            assert_true(s.vertices[0].z == -2);
            assert_true(s.vertices[1].x == 0 && s.vertices[2].x == 1);
            assert_int_equal(s.polygons[0].has_normals, 0);
            stp_scene_free(&s);
        }
    }
}

/* ---- errors ------------------------------------------------------------ */

static void expect_error(const void *text, size_t size, const char *want)
{
    char err[ERR_SIZE];
    stp_scene s;
    int rc = stp_scene_parse((const char *)text, size, "ply", "t.ply", NULL, &s, err, sizeof err);
    if (rc != -1 || strcmp(err, want) != 0) {
        print_error("rc %d, message '%s', want '%s'\n", rc, rc ? err : "", want);
        fail();
    }
    assert_null(s.polygons);
    assert_null(s.vertices);
}

#define HEAD "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n" \
             "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
#define VERTS "0 0 0\n1 0 0\n0 1 0\n"

static void expect_text_error(const char *text, const char *want)
{
    expect_error(text, strlen(text), want);
}

static void test_ascii_errors(void **state)
{
    (void)state;
    expect_text_error("plx\nformat ascii 1.0\n", "t.ply:1: not a PLY file (the first line must be 'ply')");
    expect_text_error("ply\nformat ascii 2.0\n", "t.ply:2: format: version '2.0' (only 1.0 is known)");
    expect_text_error("ply\nformat utf8 1.0\n", "t.ply:2: format: unknown encoding 'utf8'");
    expect_text_error("ply\nelement vertex 3\n", "t.ply:2: element: before the 'format' line");
    expect_text_error("ply\nformat ascii 1.0\nproperty float x\n", "t.ply:3: property: before any element");
    expect_text_error("ply\nformat ascii 1.0\nelement vertex 1\nproperty real x\n",
                      "t.ply:4: property: unknown type 'real'");
    expect_text_error("ply\nformat ascii 1.0\nelement vertex -1\n", "t.ply:3: element: negative count -1");
    expect_text_error("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n",
                      "t.ply:4: file ends before 'end_header'");
    expect_text_error("ply\nformat ascii 1.0\nwhatever\n", "t.ply:3: unknown header keyword 'whatever'");
    expect_text_error("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n0 0\n",
                      "t.ply:3: element 'vertex' lacks x, y or z");
    expect_text_error("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                      "property float z\nend_header\n0 0 0\n",
                      "t.ply:7: no 'face' element: nothing to draw");
    expect_text_error("ply\nformat ascii 1.0\nelement face 1\nproperty list uchar int vertex_indices\n",
                      "t.ply:3: element: 'face' before 'vertex' is not supported");
    expect_text_error("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                      "property float z\nelement face 1\nproperty list float int vertex_indices\n",
                      "t.ply:8: property list: the count type must be an integer");
    expect_text_error("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                      "property float z\nelement face 1\nproperty list uchar float vertex_indices\n",
                      "t.ply:8: property list: vertex indices must be integers");
    expect_text_error("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                      "property float z\nelement face 1\nproperty int flags\nend_header\n",
                      "t.ply:7: element 'face' needs one list property 'vertex_indices'");
    /* body: line numbers of the instance */
    expect_text_error(HEAD "0 0 0\n1 0 0\n", "t.ply:3: file ends after 2 of 3 vertex elements");
    expect_text_error(HEAD "0 0 0\n1 0\n0 1 0\n3 0 1 2\n",
                      "t.ply:11: vertex 1: the line ends before its last property");
    expect_text_error(HEAD "0 0 0\n1 0 0 7\n0 1 0\n3 0 1 2\n",
                      "t.ply:11: vertex 1: unexpected '7' after its properties");
    expect_text_error(HEAD "0 0 0\n1 x 0\n0 1 0\n3 0 1 2\n", "t.ply:11: bad number 'x'");
    expect_text_error(HEAD VERTS "3 0 1 3\n", "t.ply:13: face 0: index 3 out of range (0..2)");
    expect_text_error(HEAD VERTS "3 0 -1 2\n", "t.ply:13: face 0: index -1 out of range (0..2)");
    expect_text_error(HEAD VERTS "2 0 1\n", "t.ply:13: face 0: needs at least 3 vertices, not 2");
    expect_text_error(HEAD VERTS "4 0 1 2\n", "t.ply:13: face 0: a list of 4 values, the line has 3 more");
    expect_text_error(HEAD VERTS "256 0 1 2\n", "t.ply:13: face 0: 256 outside its type's range 0..255");
    expect_text_error(HEAD VERTS "3 0 1 2\n3 0 1 2\n", "t.ply:14: extra data after the last element");
    expect_text_error(HEAD "0 0 0\n1e39 0 0\n0 1 0\n3 0 1 2\n", "t.ply:11: vertex 1: 1e39 outside float's range");
}

static void test_binary_errors(void **state)
{
    static const char head[] = "ply\nformat binary_little_endian 1.0\nelement vertex 3\n"
                               "property float x\nproperty float y\nproperty float z\n"
                               "element face 1\nproperty list uchar int vertex_indices\n"
                               "end_header\n";
    const size_t h = sizeof head - 1, faces = h + 36;
    char want[128];
    buf o;
    int v;
    (void)state;

    /* too few bytes for the vertices: refused before reading them */
    memset(&o, 0, sizeof o);
    put_text(&o, head);
    put_f32(&o, 0);
    snprintf(want, sizeof want,
             "t.ply: byte %zu: element 'vertex': 3 of 12 bytes each need more than the 4 bytes left",
             h);
    expect_error(o.b, o.n, want);

    /* the face list: an index out of range, at the face's offset */
    memset(&o, 0, sizeof o);
    put_text(&o, head);
    for (v = 0; v < 9; v++)
        put_f32(&o, (float)(v == 3 || v == 7));
    put_uint(&o, 3, 1);
    put_uint(&o, 0, 4);
    put_uint(&o, 1, 4);
    put_uint(&o, 5, 4);
    snprintf(want, sizeof want, "t.ply: byte %zu: face 0: index 5 out of range (0..2)", faces);
    expect_error(o.b, o.n, want);

    /* the list runs past the end */
    o.n = faces;
    put_uint(&o, 3, 1);
    put_uint(&o, 0, 4);
    snprintf(want, sizeof want, "t.ply: byte %zu: face 0: the file ends inside its list", faces);
    expect_error(o.b, o.n, want);

    /* extra bytes after the last element */
    o.n = faces;
    put_uint(&o, 3, 1);
    put_uint(&o, 0, 4);
    put_uint(&o, 1, 4);
    put_uint(&o, 2, 4);
    put_uint(&o, 0xAB, 1);
    snprintf(want, sizeof want, "t.ply: byte %zu: 1 bytes of extra data after the last element",
             faces + 13);
    expect_error(o.b, o.n, want);

    /* a NaN coordinate, at its own offset (vertex 1's y) */
    o.n = h;
    for (v = 0; v < 9; v++)
        put_f32(&o, v == 4 ? NAN : 0.0f);
    snprintf(want, sizeof want, "t.ply: byte %zu: vertex 1: a value is not a finite number", h + 16);
    expect_error(o.b, o.n, want);
}

/* ---- from disk --------------------------------------------------------- */

static void test_load_file(void **state)
{
    char dir[] = "/tmp/stp_test_plyXXXXXX";
    char named[64], err[ERR_SIZE];
    buf o;
    stp_scene s;
    FILE *f;
    (void)state;
    assert_non_null(mkdtemp(dir));
    /* the loader picks the format by the extension, in either case */
    snprintf(named, sizeof named, "%s/mesh.PLY", dir);
    mesh_binary(&o, 1);
    f = fopen(named, "wb");
    assert_non_null(f);
    assert_int_equal(fwrite(o.b, 1, o.n, f), o.n);
    assert_int_equal(fclose(f), 0);
    assert_int_equal(stp_scene_load(named, NULL, &s, err, sizeof err), 0);
    check_mesh(&s, 14, 14);
    stp_scene_free(&s);
    remove(named);
    remove(dir);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_ascii),         cmocka_unit_test(test_binary_little),
        cmocka_unit_test(test_binary_big),    cmocka_unit_test(test_binary_types),
        cmocka_unit_test(test_ascii_errors),  cmocka_unit_test(test_binary_errors),
        cmocka_unit_test(test_load_file),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
