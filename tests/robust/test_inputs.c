/* SPDX-License-Identifier: MIT */
/*
 * Inputs real users give (mesh files without lights, scenes with many
 * lights, one huge object beside small ones, degenerate and self-crossing
 * polygons, very long polygons), through the path of `stipple render`:
 * stp_scene_parse, then stp_tool_render (polygon renderer) and
 * stp_tool_raytrace (ray tracer).
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "render_scene.h"
#include "scene.h"
#include "scene_prepare.h"
#include "stp_posix.h"

#define W 96
#define H 72

/* Grey render (raytrace: ray-traced) of a scene text; 0, or -1 with err. */
static int render_text(const char *format, const char *text, int raytrace, stp_posix_frame *f,
                       char *err, size_t err_size)
{
    stp_scene s;
    stp_tool_options opt;
    int rc;
    stp_tool_options_default(&opt);
    opt.width = W;
    opt.height = H;
    if (stp_scene_parse(text, strlen(text), format, "t", NULL, &s, err, err_size) != 0)
        return -1;
    if (stp_posix_frame_init(f, W, H, STP_PIXEL_GREY8) != 0) {
        stp_scene_free(&s);
        return -1;
    }
    rc = raytrace ? stp_tool_raytrace(&s, &opt, stp_posix_frame_port(f), NULL, err, err_size)
                  : stp_tool_render(&s, &opt, stp_posix_frame_port(f), NULL, err, err_size);
    stp_scene_free(&s);
    if (rc != 0)
        stp_posix_frame_free(f);
    return rc;
}

static void render_ok(const char *format, const char *text, int raytrace, stp_posix_frame *f)
{
    char err[512] = "";
    if (render_text(format, text, raytrace, f, err, sizeof err) != 0)
        fail_msg("%s render of a %s file failed: %s", raytrace ? "ray-traced" : "polygon",
                 format, err);
}

/* How many grey levels cover at least `share` of the object's pixels
 * (pixels other than the black background). */
static int greys_covering(const stp_posix_frame *f, double share, int *object_pixels)
{
    int count[256] = {0}, n = 0, levels = 0, i;
    uint32_t x, y;
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            uint8_t v = f->pixels[y * f->stride + x];
            if (v) {
                count[v]++;
                n++;
            }
        }
    for (i = 1; i < 256; i++)
        levels += n > 0 && count[i] >= share * n;
    if (object_pixels)
        *object_pixels = n;
    return levels;
}

/* ---- mesh files carry no lights ----------------------------------------- */

/* A unit cube in every format, without a light: the default light above
 * and left of the eye shades its three visible faces differently (they
 * used to come out one flat grey, the ambient share). */
static void test_meshes_without_lights_are_shaded(void **state)
{
    static const char *const cube[][2] = {
        {"obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n"},
        {"off", "OFF\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
                "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n"},
        {"ply", "ply\nformat ascii 1.0\nelement vertex 8\nproperty float x\nproperty float y\n"
                "property float z\nelement face 6\nproperty list uchar int vertex_indices\n"
                "end_header\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
                "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n"},
        {"nff", "f 1 1 1 1 0 0 0 1\n"
                "p 4\n0 0 0\n0 1 0\n1 1 0\n1 0 0\np 4\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
                "p 4\n0 0 0\n1 0 0\n1 0 1\n0 0 1\np 4\n1 0 0\n1 1 0\n1 1 1\n1 0 1\n"
                "p 4\n1 1 0\n0 1 0\n0 1 1\n1 1 1\np 4\n0 1 0\n0 0 0\n0 0 1\n0 1 1\n"},
    };
    size_t i;
    int rt;
    (void)state;
    for (i = 0; i < sizeof cube / sizeof cube[0]; i++)
        for (rt = 0; rt < 2; rt++) {
            stp_posix_frame f;
            int pixels, greys;
            render_ok(cube[i][0], cube[i][1], rt, &f);
            greys = greys_covering(&f, 0.05, &pixels);
            stp_posix_frame_free(&f);
            if (pixels < W * H / 20 || greys < 3)
                fail_msg("%s cube, %s: %d pixels drawn, %d greys over 5%% of them (want 3 faces)",
                         cube[i][0], rt ? "ray-traced" : "rasterised", pixels, greys);
        }
}

/* ---- any number of lights ------------------------------------------------ */

/* An NFF floor under n lights in a ring above it (n = 0: none). */
static char *floor_with_lights(int n)
{
    size_t size = 512 + (size_t)n * 64, used;
    char *t = malloc(size);
    int j;
    used = (size_t)snprintf(t, size, "f 1 1 1 1 0 0 0 1\np 4\n-4 -4 0\n4 -4 0\n4 4 0\n-4 4 0\n"
                                     "p 3\n-3 -2 0\n3 -2 0\n0 1 3\n");
    for (j = 0; j < n; j++)
        used += (size_t)snprintf(t + used, size - used, "l %.6f %.6f 6\n",
                                 5 * cos(j * 2.399963), 5 * sin(j * 2.399963));
    return t;
}

/* 0, 1, 4, 5, 17 and 200 lights: prepared into at most STP_MAX_LIGHTS
 * whose weights add up to the file's count (none: the default light,
 * weight 1), and rendered (shaded up to 5) by both renderers (more lights than the
 * build holds used to overwrite the preparation's fields, or its stack). */
static void test_any_number_of_lights(void **state)
{
    static const int counts[] = {0, 1, 4, 5, 17, 200};
    size_t i;
    (void)state;
    for (i = 0; i < sizeof counts / sizeof counts[0]; i++) {
        char *t = floor_with_lights(counts[i]), err[512] = "";
        int expect = counts[i] < STP_MAX_LIGHTS ? counts[i] : STP_MAX_LIGHTS, rt, j;
        stp_tool_options opt;
        stp_tool_prepared prep;
        stp_scene s;
        double total = 0;
        stp_tool_options_default(&opt);
        assert_int_equal(stp_scene_parse(t, strlen(t), "nff", "t", NULL, &s, err, sizeof err), 0);
        assert_int_equal(stp_tool_prepare(&s, &opt, &prep, err, sizeof err), 0);
        assert_int_equal((int)prep.scene.light_count, expect);
        assert_int_equal((int)prep.lights_in, counts[i]);
        for (j = 0; j < STP_MAX_LIGHTS; j++) {
            if (j < expect)
                total += prep.light_weight[j];
            else
                assert_true(prep.light_weight[j] == 1.0);
            assert_true(prep.power_factor[j] == 1.0);
        }
        assert_true(fabs(total - counts[i]) < 1e-9);
        assert_true(prep.scale == 1.0);
        stp_tool_prepared_free(&prep);
        stp_scene_free(&s);
        for (rt = 0; rt < 2; rt++) {
            stp_posix_frame f;
            int pixels;
            render_ok("nff", t, rt, &f);
            /* many lights from all round saturate the floor (auto power
             * gives n lights sqrt(n) times one light's): drawn, not black */
            if ((greys_covering(&f, 0.02, &pixels) < 2 && counts[i] <= 5) || pixels < W * H / 10)
                fail_msg("%d lights, %s: %d pixels, not shaded", counts[i],
                         rt ? "ray-traced" : "rasterised", pixels);
            stp_posix_frame_free(&f);
        }
        free(t);
    }
}

/* ---- long polygons ------------------------------------------------------- */

/* An OBJ file of one polygon: a star of n vertices (every other one
 * reflex), or a comb (comb != 0: teeth along the top). */
static char *one_polygon(int n, int comb)
{
    size_t size = (size_t)n * 48 + 64, used = 0;
    char *t = malloc(size);
    int i;
    for (i = 0; i < n; i++) {
        double x, y;
        if (comb) {
            int teeth = (n - 2) / 2, k = i / 2;
            if (i >= 2 * teeth) {
                x = i == 2 * teeth ? 1.0 : 0.0;
                y = 0;
            } else {
                x = (double)k / teeth + (i % 2) * 0.5 / teeth;
                y = k % 2 == 0 ? 1.0 : 0.2;
            }
        } else {
            double r = i % 2 == 0 ? 1.0 : 0.6, a = 6.283185307179586 * i / n;
            x = r * cos(a);
            y = r * sin(a);
        }
        used += (size_t)snprintf(t + used, size - used, "v %.9f %.9f 0\n", x, y);
    }
    used += (size_t)snprintf(t + used, size - used, "f");
    for (i = 0; i < n; i++)
        used += (size_t)snprintf(t + used, size - used, " %d", i + 1);
    snprintf(t + used, size - used, "\n");
    return t;
}

static double shoelace(const stp_scene_vec3 *v, const int *idx, int n)
{
    double a = 0;
    int i;
    for (i = 0; i < n; i++) {
        stp_scene_vec3 p = v[idx ? idx[i] : i], q = v[idx ? idx[(i + 1) % n] : (i + 1) % n];
        a += p.x * q.y - p.y * q.x;
    }
    return a / 2;
}

/* The split of long concave polygons: n - 2 triangles, each turning the
 * outline's way, whose areas add up to the outline's (shoelace formula). */
static void test_long_polygons_split(void **state)
{
    static const int sizes[][2] = {{20000, 0}, {4000, 1}, {STP_TOOL_MAX_POLYGON_VERTICES, 1}};
    size_t c;
    (void)state;
    for (c = 0; c < sizeof sizes / sizeof sizes[0]; c++) {
        char *t = one_polygon(sizes[c][0], sizes[c][1]), err[256];
        stp_scene s;
        int *idx, *cnt, pieces, k, n = sizes[c][0];
        double whole, sum = 0;
        assert_int_equal(stp_scene_parse(t, strlen(t), "obj", "t", NULL, &s, err, sizeof err), 0);
        pieces = stp_tool_split_polygon(s.vertices, n, STP_MAX_POLYGON_VERTICES, &idx, &cnt);
        assert_int_equal(pieces, n - 2);
        whole = shoelace(s.vertices, NULL, n);
        for (k = 0; k < pieces; k++) {
            double a = shoelace(s.vertices, idx + 3 * k, 3);
            assert_int_equal(cnt[k], 3);
            assert_true(a * whole > 0);
            sum += a;
        }
        assert_true(fabs(sum - whole) <= 1e-9 * fabs(whole));
        free(idx);
        free(cnt);
        stp_scene_free(&s);
        free(t);
    }
}

/* Beyond STP_TOOL_MAX_POLYGON_VERTICES a polygon is refused with its line
 * (splitting a 100 000-vertex polygon used to take minutes); at the limit
 * it renders. */
static void test_long_polygon_limit(void **state)
{
    char *t = one_polygon(STP_TOOL_MAX_POLYGON_VERTICES + 1, 0), err[512] = "", want[256];
    stp_posix_frame f;
    int rt, pixels;
    (void)state;
    snprintf(want, sizeof want, "%d: polygon 1 has %d vertices; at most %d are taken",
             STP_TOOL_MAX_POLYGON_VERTICES + 2, STP_TOOL_MAX_POLYGON_VERTICES + 1,
             STP_TOOL_MAX_POLYGON_VERTICES);
    for (rt = 0; rt < 2; rt++) {
        assert_int_equal(render_text("obj", t, rt, &f, err, sizeof err), -1);
        if (strncmp(err, want, strlen(want)) != 0)
            fail_msg("message '%s', want '%s...'", err, want);
    }
    free(t);
    t = one_polygon(STP_TOOL_MAX_POLYGON_VERTICES, 0);
    render_ok("obj", t, 0, &f);
    greys_covering(&f, 0.05, &pixels);
    assert_true(pixels > W * H / 10);
    stp_posix_frame_free(&f);
    free(t);
}

/* ---- what cannot be drawn is refused ------------------------------------ */

static void refused(const char *format, const char *text, const char *want)
{
    char err[512] = "";
    stp_posix_frame f;
    int rt;
    for (rt = 0; rt < 2; rt++) {
        if (render_text(format, text, rt, &f, err, sizeof err) == 0) {
            stp_posix_frame_free(&f);
            fail_msg("%s: rendered (%s), want a refusal '%s...'", format,
                     rt ? "ray tracer" : "polygons", want);
        }
        if (strncmp(err, want, strlen(want)) != 0)
            fail_msg("%s: message '%s', want '%s...'", format, err, want);
    }
}

#define CUBE_OBJ                                                                                  \
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"                    \
    "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n"

/* A unit cube beside a triangle 1e30 away (the cube used to vanish, exit
 * 0), a PLY with a vertex at 3e38 (a black frame), a view 5 units long
 * beside a triangle 1e30 across ("view: invalid view"): refused, naming
 * the line of the object lost. */
static void test_small_beside_huge_refused(void **state)
{
    (void)state;
    refused("obj", CUBE_OBJ "v 1e30 1e30 1e30\nv 1.5e30 1e30 1e30\nv 1e30 1.5e30 1e30\nf 9 10 11\n",
            "9: polygon 1: 1 units across in a scene ");
    refused("ply",
            "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
            "property float z\nelement face 2\nproperty list uchar int vertex_indices\n"
            "end_header\n0 0 0\n1 0 0\n0 1 0\n3e38 1 1\n3 0 1 2\n3 1 2 3\n",
            "14: polygon 1: 1 units across in a scene ");
    refused("nff",
            "v\nfrom 0 0 -5\nat 0 0 0\nup 0 1 0\nangle 45\nhither 1\nresolution 8 8\n"
            "p 3\n1e30 0 0\n0 1e30 0\n0 0 1e30\n",
            "the view's from (0, 0, -5) and at (0, 0, 0) lie 5 units apart in a scene ");
    /* the file's polygon 1, not the 129th of the scene (128 pieces of the sphere first) */
    refused("nff", "s 0 0 0 1e30\np 3\n0 0 0\n1 0 0\n0 1 0\n",
            "2: polygon 1: 1 units across in a scene ");
}

/* Polygons that all lack an area (points, or vertices on a line) are
 * refused like a file without geometry (they gave a black frame, exit 0). */
static void test_degenerate_scenes_refused(void **state)
{
    (void)state;
    refused("obj", "v 0 0 0\nv 1 1 1\nv 2 2 2\nv 3 3 3\nf 1 2 3\nf 1 2 4\nf 1 1 1\n",
            "no geometry: none of the 3 polygons has an area");
    refused("off", "OFF\n3 1 0\n0 0 0\n0 0 0\n0 0 0\n3 0 1 2\n",
            "no geometry: none of the 1 polygons has an area");
    refused("nff", "p 4\n0 0 0\n1 0 0\n2 0 0\n3 0 0\n", "no geometry");
}

/* A bow tie (a quad whose outline crosses itself; its signed area is 0, so
 * it was skipped) draws as its two triangles either side of the crossing,
 * pixel for pixel as the two triangles given alone, by both renderers. */
static void test_bow_tie_as_two_triangles(void **state)
{
    static const char view[] = "v\nfrom 0.5 0.5 3\nat 0.5 0.5 0\nup 0 1 0\nangle 40\nhither 0.1\n"
                               "resolution 96 72\nl 0 1 4\nf 1 1 1 1 0 0 0 1\n";
    char bow[512], wings[512];
    int rt;
    (void)state;
    snprintf(bow, sizeof bow, "%sp 4\n0 0 0\n1 1 0\n1 0 0\n0 1 0\n", view);
    snprintf(wings, sizeof wings, "%sp 3\n0.5 0.5 0\n1 1 0\n1 0 0\np 3\n0.5 0.5 0\n0 1 0\n0 0 0\n",
             view);
    for (rt = 0; rt < 2; rt++) {
        stp_posix_frame a, b;
        int pixels, diff = 0;
        uint32_t i;
        render_ok("nff", bow, rt, &a);
        render_ok("nff", wings, rt, &b);
        for (i = 0; i < W * H; i++)
            diff += a.pixels[i] != b.pixels[i];
        greys_covering(&a, 0.05, &pixels);
        stp_posix_frame_free(&a);
        stp_posix_frame_free(&b);
        if (diff != 0 || pixels < W * H / 20)
            fail_msg("%s: bow tie %d pixels drawn, %d differ from its two triangles",
                     rt ? "ray tracer" : "polygons", pixels, diff);
    }
}

/* ---- messages that name the real fault ----------------------------------- */

static void parse_fails(const char *format, const char *text, size_t size, const char *want)
{
    stp_scene s;
    if (size == 0)
        size = strlen(text);
    char err[512] = "";
    if (stp_scene_parse(text, size, format, "t", NULL, &s, err, sizeof err) == 0) {
        stp_scene_free(&s);
        fail_msg("%s parsed, want '%s'", format, want);
    }
    if (strncmp(err, want, strlen(want)) != 0)
        fail_msg("%s: message '%s', want '%s...'", format, err, want);
}

/* Line ends of CR alone (classic Mac OS) are line ends (the files were "an
 * empty file" or "not a PLY file"); a PLY header without end_header, a
 * binary OFF, an OBJ given as PLY are named as such, at the right line. */
static void test_reader_messages(void **state)
{
    static const char obj[] = "v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 3\r";
    static const char ply[] = "ply\rformat ascii 1.0\relement vertex 3\rproperty float x\r"
                              "property float y\rproperty float z\relement face 1\r"
                              "property list uchar int vertex_indices\rend_header\r"
                              "0 0 0\r1 0 0\r0 1 0\r3 0 1 2\r";
    static const char binary_off[] = "OFF BINARY\n\0\0\0\x08\0\0\0\x06";
    stp_scene s;
    char err[512] = "";
    (void)state;
    assert_int_equal(stp_scene_parse(obj, strlen(obj), "obj", "t", NULL, &s, err, sizeof err), 0);
    assert_int_equal((int)s.polygon_count, 1);
    assert_int_equal(s.polygons[0].source_line, 4);
    stp_scene_free(&s);
    assert_int_equal(stp_scene_parse(ply, strlen(ply), "ply", "t", NULL, &s, err, sizeof err), 0);
    assert_int_equal((int)s.polygon_count, 1);
    assert_int_equal((int)s.vertex_count, 3);
    stp_scene_free(&s);
    parse_fails("ply",
                "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                "-1 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
                0, "t:9: data before 'end_header'");
    parse_fails("off", binary_off, sizeof binary_off - 1, "t:1: binary OFF is not read");
    parse_fails("off", "4OFF\n1 0 0\n0 0 0 0\n", 0, "t:1: '4OFF' is not read: only OFF");
    parse_fails("ply", "# Blender OBJ\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", 0,
                "t:1: not a PLY file");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_meshes_without_lights_are_shaded),
        cmocka_unit_test(test_any_number_of_lights),
        cmocka_unit_test(test_long_polygons_split),
        cmocka_unit_test(test_long_polygon_limit),
        cmocka_unit_test(test_small_beside_huge_refused),
        cmocka_unit_test(test_degenerate_scenes_refused),
        cmocka_unit_test(test_bow_tie_as_two_triangles),
        cmocka_unit_test(test_reader_messages),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
