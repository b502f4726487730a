/* SPDX-License-Identifier: MIT */
/*
 * Outlines (tools/outlines.h): the silhouette and crease edges of a cube
 * seen at an angle, worked out by hand; visibility (an edge behind a
 * square is cut where the square hides it); the pixels the renderer
 * draws for the cube's silhouette against an independent double-precision
 * projection and line; a golden picture of a shared scene with outlines.
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "outlines.h"
#include "render_scene.h"
#include "stp_posix.h"
#include "test_scenes.h"

#define W 48
#define H 32

/* A cube of side 2 about the origin, faces wound counter-clockwise seen
 * from outside (outward Newell normals), eye at (4, 3, 5): the +x, +y and
 * +z faces face it.  flip: the +z face wound the other way. */
static void cube_scene(stp_scene *scene, int flip)
{
    char text[2048], err[256];
    stp_scene_options sopt;
    const char *pz = flip ? "p 4\n-1 1 1\n1 1 1\n1 -1 1\n-1 -1 1\n" : "p 4\n-1 -1 1\n1 -1 1\n1 1 1\n-1 1 1\n";
    snprintf(text, sizeof text,
             "v\nfrom 4 3 5\nat 0 0 0\nup 0 1 0\nangle 40\nhither 0.1\nresolution %d %d\n"
             "b 0 0 0\nl 10 12 8\nf 0.8 0.8 0.8 1 0 0 0 0\n"
             "p 4\n1 -1 -1\n1 1 -1\n1 1 1\n1 -1 1\n"
             "p 4\n-1 -1 -1\n-1 -1 1\n-1 1 1\n-1 1 -1\n"
             "p 4\n-1 1 -1\n-1 1 1\n1 1 1\n1 1 -1\n"
             "p 4\n-1 -1 -1\n1 -1 -1\n1 -1 1\n-1 -1 1\n"
             "%s"
             "p 4\n-1 -1 -1\n-1 1 -1\n1 1 -1\n1 -1 -1\n",
             W, H, pz);
    stp_scene_options_default(&sopt);
    if (stp_scene_parse(text, strlen(text), "nff", "cube", &sopt, scene, err, sizeof err) != 0)
        fail_msg("%s", err);
}

static stp_outline_view cube_view(void)
{
    stp_outline_view v;
    memset(&v, 0, sizeof v);
    v.perspective = 1;
    v.from.x = 4;
    v.from.y = 3;
    v.from.z = 5;
    v.up.y = 1;
    v.fov_degrees = 40;
    v.width = W;
    v.height = H;
    return v;
}

static int is_vertex(stp_scene_vec3 p, double x, double y, double z)
{
    return fabs(p.x - x) < 1e-9 && fabs(p.y - y) < 1e-9 && fabs(p.z - z) < 1e-9;
}

static int is_corner(stp_scene_vec3 p)
{
    return fabs(fabs(p.x) - 1) < 1e-9 && fabs(fabs(p.y) - 1) < 1e-9 && fabs(fabs(p.z) - 1) < 1e-9;
}

/* Silhouette: the 6 edges touching neither (1,1,1) (where three faces
 * towards the eye meet) nor (-1,-1,-1) (three away), each whole.
 * Crease (90 degrees > 40): the 12 edges less the 3 at (-1,-1,-1), which
 * the cube hides: 9, each whole.  The same with a face wound the other
 * way. */
static void test_cube_edges(void **state)
{
    int flip;
    (void)state;
    for (flip = 0; flip < 2; flip++) {
        stp_scene scene;
        stp_outline_view v = cube_view();
        stp_outline_segment *seg;
        size_t n, i;
        cube_scene(&scene, flip);
        assert_int_equal(stp_outlines_find(&scene, &v, STP_OUTLINE_SILHOUETTE, 40, &seg, &n), 0);
        assert_int_equal(n, 6);
        for (i = 0; i < n; i++) {
            assert_true(is_corner(seg[i].a) && is_corner(seg[i].b));
            assert_false(is_vertex(seg[i].a, 1, 1, 1) || is_vertex(seg[i].b, 1, 1, 1));
            assert_false(is_vertex(seg[i].a, -1, -1, -1) || is_vertex(seg[i].b, -1, -1, -1));
            assert_true(seg[i].kind & STP_OUTLINE_SILHOUETTE);
            assert_true(seg[i].kind & STP_OUTLINE_CREASE);
        }
        free(seg);
        assert_int_equal(stp_outlines_find(&scene, &v, STP_OUTLINE_CREASE, 40, &seg, &n), 0);
        assert_int_equal(n, 9);
        for (i = 0; i < n; i++) {
            assert_true(is_corner(seg[i].a) && is_corner(seg[i].b));
            assert_false(is_vertex(seg[i].a, -1, -1, -1) || is_vertex(seg[i].b, -1, -1, -1));
        }
        free(seg);
        /* no crease at 90 degrees or more apart... than 100 */
        assert_int_equal(stp_outlines_find(&scene, &v, STP_OUTLINE_CREASE, 100, &seg, &n), 0);
        assert_int_equal(n, 0);
        free(seg);
        stp_scene_free(&scene);
    }
}

/* A 2x2 square in z = 0 seen from (0, 0, 10), and a small square in
 * z = 1 (x -0.2..0.2, y 0.8..1.2) in front of its top edge: the ray from
 * (x, 1, 0) to the eye crosses z = 1 at (0.9 x, 0.9), inside the small
 * square for |x| <= 0.2/0.9 = 0.2222.  The top edge comes in two pieces
 * ending there (to one test step, 1/4 pixel); the other 3 edges and the
 * small square's 4 (all boundaries) are whole: 9 pieces. */
static void test_hidden_piece(void **state)
{
    static const char text[] = "v\nfrom 0 0 10\nat 0 0 0\nup 0 1 0\nangle 30\nhither 0.1\n"
                               "resolution 64 64\nb 0 0 0\nl 0 0 20\nf 1 1 1 1 0 0 0 0\n"
                               "p 4\n-1 -1 0\n1 -1 0\n1 1 0\n-1 1 0\n"
                               "p 4\n-0.2 0.8 1\n0.2 0.8 1\n0.2 1.2 1\n-0.2 1.2 1\n";
    stp_scene scene;
    stp_scene_options sopt;
    stp_outline_view v;
    stp_outline_segment *seg;
    char err[256];
    size_t n, i;
    int top = 0;
    double step;
    (void)state;
    stp_scene_options_default(&sopt);
    if (stp_scene_parse(text, strlen(text), "nff", "squares", &sopt, &scene, err, sizeof err) != 0)
        fail_msg("%s", err);
    memset(&v, 0, sizeof v);
    v.perspective = 1;
    v.from.z = 10;
    v.up.y = 1;
    v.fov_degrees = 30;
    v.width = v.height = 64;
    assert_int_equal(stp_outlines_find(&scene, &v, STP_OUTLINE_SILHOUETTE, 40, &seg, &n), 0);
    assert_int_equal(n, 9);
    /* the edge is 2 units, focal 32/tan 15 deg = 119.4 px at distance 10:
     * 23.9 px, 96 steps of 2/96 units */
    step = 2.0 / 96;
    for (i = 0; i < n; i++) {
        if (fabs(seg[i].a.y - 1) < 1e-9 && fabs(seg[i].b.y - 1) < 1e-9 && seg[i].a.z == 0) {
            double inner = fabs(seg[i].a.x) < fabs(seg[i].b.x) ? fabs(seg[i].a.x) : fabs(seg[i].b.x);
            double outer = fabs(seg[i].a.x) < fabs(seg[i].b.x) ? fabs(seg[i].b.x) : fabs(seg[i].a.x);
            top++;
            assert_true(fabs(inner - 0.2 / 0.9) <= step);
            assert_true(fabs(outer - 1) < 1e-9);
            assert_true((seg[i].a.x < 0) == (seg[i].b.x < 0)); /* one side each */
        }
    }
    assert_int_equal(top, 2);
    free(seg);
    stp_scene_free(&scene);
}

/* The reference: the core's view (src/view.c, src/render.c) in double:
 * left-handed frame right = dir x up, focal (short side / 2) / tan(fov/2),
 * x = W/2 + focal x/z, y = H/2 - focal y/z. */
static void ref_project(double px, double py, double pz, double *x, double *y)
{
    double f[3] = {-4, -3, -5}, u[3] = {0, 1, 0}, r[3], up[3], d[3] = {px - 4, py - 3, pz - 5};
    double lf = sqrt(50), lr, lu, vx, vy, vz, focal = (H / 2.0) / tan(20 * 3.14159265358979323846 / 180);
    int i;
    for (i = 0; i < 3; i++)
        f[i] /= lf;
    r[0] = f[1] * u[2] - f[2] * u[1];
    r[1] = f[2] * u[0] - f[0] * u[2];
    r[2] = f[0] * u[1] - f[1] * u[0];
    lr = sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
    for (i = 0; i < 3; i++)
        r[i] /= lr;
    up[0] = r[1] * f[2] - r[2] * f[1];
    up[1] = r[2] * f[0] - r[0] * f[2];
    up[2] = r[0] * f[1] - r[1] * f[0];
    lu = sqrt(up[0] * up[0] + up[1] * up[1] + up[2] * up[2]);
    vx = (d[0] * r[0] + d[1] * r[1] + d[2] * r[2]);
    vy = (d[0] * up[0] + d[1] * up[1] + d[2] * up[2]) / lu;
    vz = d[0] * f[0] + d[1] * f[1] + d[2] * f[2];
    *x = W / 2.0 + focal * vx / vz;
    *y = H / 2.0 - focal * vy / vz;
}

/* Mark the pixels of a line from pixel (x0, y0) to (x1, y1), Bresenham
 * stepping from the first end. */
static void ref_line(int x0, int y0, int x1, int y1, uint8_t *mark)
{
    int dx = abs(x1 - x0), dy = -abs(y1 - y0), sx = x0 < x1 ? 1 : -1, sy = y0 < y1 ? 1 : -1;
    int err = dx + dy;
    for (;;) {
        mark[y0 * W + x0] = 1;
        if (x0 == x1 && y0 == y1)
            break;
        int e2 = 2 * err;
        if (e2 >= dy) {
            err += dy;
            x0 += sx;
        }
        if (e2 <= dx) {
            err += dx;
            y0 += sy;
        }
    }
}

static void ref_pixel(const double *p, int *x, int *y)
{
    double fx, fy;
    ref_project(p[0], p[1], p[2], &fx, &fy);
    /* away from pixel boundaries, where fixed-point rounding could choose
     * the neighbour: the test would not be exact */
    assert_true(fx - floor(fx) > 0.02 && fx - floor(fx) < 0.98);
    assert_true(fy - floor(fy) > 0.02 && fy - floor(fy) < 0.98);
    *x = (int)floor(fx);
    *y = (int)floor(fy);
}

static void render_cube(int outlines, stp_posix_frame *f)
{
    stp_scene scene;
    stp_tool_options opt;
    char err[512];
    cube_scene(&scene, 0);
    stp_tool_options_default(&opt);
    opt.width = W;
    opt.height = H;
    opt.levels = 256;
    opt.brightness = 0.3; /* faces below white: white is the lines' */
    opt.outlines = outlines;
    opt.outline_level = 1;
    assert_int_equal(stp_posix_frame_init(f, W, H, STP_PIXEL_GREY8), 0);
    if (stp_tool_render(&scene, &opt, &f->port, 0, err, sizeof err) != 0)
        fail_msg("%s", err);
    stp_scene_free(&scene);
}

/* The silhouette's pixels: every white pixel lies on the reference line
 * of a silhouette edge drawn from one end or the other, and every pixel
 * both directions agree on is white.  Without outlines nothing is. */
static void test_cube_pixels(void **state)
{
    static const double hexagon[6][3] = {{1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                         {-1, 1, 1},  {-1, -1, 1}, {1, -1, 1}};
    uint8_t forward[W * H], backward[W * H];
    stp_posix_frame f;
    int k, i, white = 0;
    (void)state;
    memset(forward, 0, sizeof forward);
    memset(backward, 0, sizeof backward);
    for (k = 0; k < 6; k++) {
        int x0, y0, x1, y1;
        ref_pixel(hexagon[k], &x0, &y0);
        ref_pixel(hexagon[(k + 1) % 6], &x1, &y1);
        ref_line(x0, y0, x1, y1, forward);
        ref_line(x1, y1, x0, y0, backward);
    }
    render_cube(STP_OUTLINE_SILHOUETTE, &f);
    for (i = 0; i < W * H; i++) {
        int on = f.pixels[i] == 255;
        white += on;
        if (on && !forward[i] && !backward[i])
            fail_msg("pixel (%d, %d) white off the silhouette", i % W, i / W);
        if (!on && forward[i] && backward[i])
            fail_msg("silhouette pixel (%d, %d) not drawn (%d)", i % W, i / W, f.pixels[i]);
    }
    assert_true(white > 40);
    stp_posix_frame_free(&f);
    render_cube(0, &f);
    for (i = 0; i < W * H; i++)
        assert_true(f.pixels[i] < 255);
    stp_posix_frame_free(&f);
}

/* Creases: the 3 edges at (-1,-1,-1) are hidden, so the pixels around
 * that corner's projection stay as the faces have them; the visible
 * corner (1,1,1), where 3 creases meet, is white. */
static void test_cube_hidden_creases(void **state)
{
    static const double hidden[3] = {-1, -1, -1}, front[3] = {1, 1, 1};
    stp_posix_frame with, without;
    int x, y, dx, dy;
    (void)state;
    render_cube(STP_OUTLINE_CREASE, &with);
    render_cube(0, &without);
    ref_pixel(hidden, &x, &y);
    for (dy = -1; dy <= 1; dy++)
        for (dx = -1; dx <= 1; dx++)
            assert_int_equal(with.pixels[(y + dy) * W + x + dx], without.pixels[(y + dy) * W + x + dx]);
    ref_pixel(front, &x, &y);
    assert_int_equal(with.pixels[y * W + x], 255);
    stp_posix_frame_free(&with);
    stp_posix_frame_free(&without);
}

/* teapot-s1 at 128x64 with both kinds of outlines, the library's
 * defaults otherwise (Bayer 4x4, 16 levels): tests/golden/
 * teapot-s1-outlines-128x64.pbm (tools/update_golden.sh). */
static void test_golden(void **state)
{
    stp_scene scene;
    stp_tool_options opt;
    stp_posix_frame f;
    char err[512], golden[1024], out[] = "/tmp/stp_outlines_XXXXXX";
    FILE *a, *b;
    int fd, ca, cb, same = 1;
    (void)state;
    stp_test_load_scene("teapot-s1", &scene);
    stp_tool_options_default(&opt);
    opt.outlines = STP_OUTLINE_SILHOUETTE | STP_OUTLINE_CREASE;
    assert_int_equal(stp_posix_frame_init(&f, 128, 64, STP_PIXEL_MONO1), 0);
    if (stp_tool_render(&scene, &opt, &f.port, 0, err, sizeof err) != 0)
        fail_msg("%s", err);
    stp_scene_free(&scene);
    fd = mkstemp(out);
    assert_true(fd >= 0);
    if (stp_posix_write(&f, out, STP_POSIX_FILE_P4, err, sizeof err) != 0)
        fail_msg("%s", err);
    stp_posix_frame_free(&f);
    snprintf(golden, sizeof golden, "%s/tests/golden/teapot-s1-outlines-128x64.pbm",
             stp_test_env_or("STP_SOURCE_DIR", "."));
    a = fopen(out, "rb");
    b = fopen(golden, "rb");
    assert_non_null(a);
    if (!b)
        fail_msg("cannot open %s", golden);
    do {
        ca = getc(a);
        cb = getc(b);
        same &= ca == cb;
    } while (ca != EOF && cb != EOF);
    fclose(a);
    fclose(b);
    if (!same)
        fail_msg("%s differs from %s", out, golden);
    remove(out);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_cube_edges),
        cmocka_unit_test(test_hidden_piece),
        cmocka_unit_test(test_cube_pixels),
        cmocka_unit_test(test_cube_hidden_creases),
        cmocka_unit_test(test_golden),
    };
    return cmocka_run_group_tests(tests, 0, 0);
}
