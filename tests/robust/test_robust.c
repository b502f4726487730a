/* SPDX-License-Identifier: MIT */
/*
 * Real inputs the tools used to draw wrong (issue 13), through the same
 * path the stipple command takes (stp_scene_parse, stp_tool_render):
 *   - units: one scene at scales 1e-4 ... 1e6 gives one picture; a sphere of
 *     radius 1e30 draws as a sphere; objects the range cannot hold together
 *     are refused with a message;
 *   - shadows when NFF's 'at' lies next to the eye (SPD rings);
 *   - lights beyond STP_MAX_LIGHTS merged, not dropped;
 *   - polygons beyond STP_MAX_POLYGON_VERTICES split, checked pixel by pixel
 *     against an even-odd coverage computed in double precision;
 *   - with the units kept (--no-rescale), the core's STP_ERR_RANGE reported
 *     as "file:line: coordinate ... beyond ...".
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

/* Grey render of an NFF or OBJ text; returns 0, or -1 with err set. */
static int render_text(const char *format, const char *text, const stp_tool_options *opt_in,
                       stp_posix_frame *f, char *err, size_t err_size)
{
    stp_scene s;
    stp_tool_options opt = *opt_in;
    int rc;
    if (stp_scene_parse(text, strlen(text), format, "t", NULL, &s, err, err_size) != 0)
        return -1;
    opt.width = W;
    opt.height = H;
    if (stp_posix_frame_init(f, W, H, STP_PIXEL_GREY8) != 0) {
        stp_scene_free(&s);
        return -1;
    }
    rc = stp_tool_render(&s, &opt, stp_posix_frame_port(f), NULL, err, err_size);
    stp_scene_free(&s);
    if (rc != 0)
        stp_posix_frame_free(f);
    return rc;
}

static void render_ok(const char *format, const char *text, const stp_tool_options *opt,
                      stp_posix_frame *f)
{
    char err[512] = "";
    if (render_text(format, text, opt, f, err, sizeof err) != 0)
        fail_msg("render failed: %s", err);
}

static int pixels_differing(const stp_posix_frame *a, const stp_posix_frame *b)
{
    int n = 0;
    uint32_t x, y;
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++)
            n += a->pixels[y * a->stride + x] != b->pixels[y * b->stride + x];
    return n;
}

/* ---- units ------------------------------------------------------------ */

/* A small SPD-like scene (floor, sphere, cylinder, two lights, the view)
 * with every length multiplied by k. */
static char *scene_at_scale(double k)
{
    static const double pts[][3] = {
        /* from, at, lights, floor corners, sphere centre, cone ends */
        {4, -3, 3}, {0, 0, 0.5}, {-4, 4, 8}, {5, 1, 6},
        {4, 4, 0}, {-4, 4, 0}, {-4, -4, 0}, {4, -4, 0},
        {0, 0, 1}, {1.5, -1, 0}, {1.5, -1, 1.5}};
    char *t = malloc(4096);
    double p[11][3];
    int i, j;
    for (i = 0; i < 11; i++)
        for (j = 0; j < 3; j++)
            p[i][j] = pts[i][j] * k;
    snprintf(t, 4096,
             "b 0.1 0.2 0.3\nv\nfrom %.17g %.17g %.17g\nat %.17g %.17g %.17g\nup 0 0 1\n"
             "angle 45\nhither %.17g\nresolution 64 64\n"
             "l %.17g %.17g %.17g\nl %.17g %.17g %.17g\n"
             "f 1 0.8 0.4 0.9 0 0 0 1\np 4\n%.17g %.17g %.17g\n%.17g %.17g %.17g\n"
             "%.17g %.17g %.17g\n%.17g %.17g %.17g\n"
             "f 0.6 0.7 1 0.7 0.3 20 0 1\ns %.17g %.17g %.17g %.17g\n"
             "c %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g\n",
             p[0][0], p[0][1], p[0][2], p[1][0], p[1][1], p[1][2], 0.01 * k, p[2][0], p[2][1],
             p[2][2], p[3][0], p[3][1], p[3][2], p[4][0], p[4][1], p[4][2], p[5][0], p[5][1],
             p[5][2], p[6][0], p[6][1], p[6][2], p[7][0], p[7][1], p[7][2], p[8][0], p[8][1],
             p[8][2], 0.8 * k, p[9][0], p[9][1], p[9][2], 0.3 * k, p[10][0], p[10][1], p[10][2],
             0.3 * k);
    return t;
}

/* Scales that need rescaling give exactly one picture; the scene at scale 1,
 * which the tools leave in its own units, differs from it in at most 1% of
 * the pixels (rounding of other coordinates, C in other units). */
static void test_units_do_not_change_the_picture(void **state)
{
    static const double scales[] = {1e-4, 1e-3, 1e4, 1e5, 1e6};
    stp_tool_options opt;
    stp_posix_frame ref, one, f;
    char *t;
    size_t i;
    (void)state;
    stp_tool_options_default(&opt);
    t = scene_at_scale(1e4);
    render_ok("nff", t, &opt, &ref);
    free(t);
    t = scene_at_scale(1);
    render_ok("nff", t, &opt, &one);
    free(t);
    assert_true(pixels_differing(&ref, &one) <= W * H / 100);
    for (i = 0; i < sizeof scales / sizeof scales[0]; i++) {
        t = scene_at_scale(scales[i]);
        render_ok("nff", t, &opt, &f);
        free(t);
        if (pixels_differing(&ref, &f) != 0)
            fail_msg("scale %g: %d pixels differ from scale 1e4", scales[i],
                     pixels_differing(&ref, &f));
        stp_posix_frame_free(&f);
    }
    /* the same for the ray tracer */
    opt.raytrace = 1;
    stp_posix_frame_free(&ref);
    t = scene_at_scale(1e-3);
    render_ok("nff", t, &opt, &ref);
    free(t);
    t = scene_at_scale(1e5);
    render_ok("nff", t, &opt, &f);
    free(t);
    assert_int_equal(pixels_differing(&ref, &f), 0);
    stp_posix_frame_free(&f);
    stp_posix_frame_free(&ref);
    stp_posix_frame_free(&one);
}

/* A lone sphere of radius 1e30 (a mesh view frames it) is drawn as the unit
 * sphere is; a triangle 1e5 units from the origin as one at the origin. */
static void test_huge_and_far_geometry(void **state)
{
    stp_tool_options opt;
    stp_posix_frame a, b;
    (void)state;
    stp_tool_options_default(&opt);
    render_ok("nff", "s 0 0 0 1e30\n", &opt, &a);
    render_ok("nff", "s 0 0 0 1\n", &opt, &b);
    assert_true(pixels_differing(&a, &b) <= W * H / 100);
    {
        /* and it is drawn, not a speck */
        int lit = 0;
        uint32_t x, y;
        for (y = 0; y < H; y++)
            for (x = 0; x < W; x++)
                lit += a.pixels[y * a.stride + x] != 0;
        assert_true(lit > W * H / 10);
    }
    stp_posix_frame_free(&a);
    stp_posix_frame_free(&b);
    render_ok("obj", "v 100000 100000 0\nv 100001 100000 0\nv 100000 100001 0\nf 1 2 3\n", &opt,
              &a);
    render_ok("obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", &opt, &b);
    assert_true(pixels_differing(&a, &b) <= W * H / 100);
    stp_posix_frame_free(&a);
    stp_posix_frame_free(&b);
}

/* What the range cannot hold together is refused with a message naming the
 * object and its line, never drawn wrong. */
static void test_unrepresentable_refused(void **state)
{
    stp_tool_options opt;
    stp_posix_frame f;
    char err[512] = "";
    (void)state;
    stp_tool_options_default(&opt);
    assert_int_equal(render_text("nff",
                                 "v\nfrom 0 0 -5\nat 0 0 0\nup 0 1 0\nangle 45\nhither 1\n"
                                 "resolution 8 8\ns 0 0 0 1e30\np 3\n0 0 0\n1 0 0\n0 1 0\n",
                                 &opt, &f, err, sizeof err),
                     -1);
    if (strncmp(err, "9: polygon ", 11) != 0 || !strstr(err, "beyond"))
        fail_msg("message: %s", err);
    /* tiny scenes render (they used to fail with "view: invalid view") */
    render_ok("nff",
              "v\nfrom 0 0 -5e-6\nat 0 0 0\nup 0 1 0\nangle 45\nhither 1e-8\nresolution 8 8\n"
              "s 0 0 0 1e-6\n",
              &opt, &f);
    stp_posix_frame_free(&f);
}

/* With the units kept the core gets the file's coordinates: a polygon
 * 40 000 units from the eye is refused by the core (STP_ERR_RANGE), one
 * beyond stp_fix by the host, each with its line; the same polygons nearer
 * the eye render. */
static void test_units_kept_range_refused(void **state)
{
    static const char view[] = "v\nfrom 0 0 -20000\nat 0 0 0\nup 0 1 0\nangle 45\nhither 1\n"
                               "resolution 8 8\nl 0 5 -10\n";
    char text[512], err[512] = "", message[1024];
    stp_tool_options opt;
    stp_posix_frame f;
    (void)state;
    stp_tool_options_default(&opt);
    opt.keep_units = 1;
    snprintf(text, sizeof text, "%sp 3\n-10000 -10000 20000\n10000 -10000 20000\n0 10000 20000\n",
             view);
    assert_int_equal(render_text("nff", text, &opt, &f, err, sizeof err), -1);
    /* the vertex farthest from the eye: the first of the two at equal distance */
    assert_string_equal(err, "9: coordinate (-10000, -10000, 20000) of polygon 1 beyond the core's "
                             "range (+-32767 units from the eye along each view axis); without "
                             "--no-rescale the scene is scaled into it");
    stp_tool_scene_message(message, sizeof message, "far.nff", err);
    assert_string_equal(message, "far.nff:9: coordinate (-10000, -10000, 20000) of polygon 1 beyond "
                                 "the core's range (+-32767 units from the eye along each view "
                                 "axis); without --no-rescale the scene is scaled into it");
    /* rescaled (the default), the same file renders */
    opt.keep_units = 0;
    render_ok("nff", text, &opt, &f);
    stp_posix_frame_free(&f);
    /* within range the units kept give a picture */
    opt.keep_units = 1;
    snprintf(text, sizeof text, "%sp 3\n-10000 -10000 10000\n10000 -10000 10000\n0 10000 10000\n",
             view);
    render_ok("nff", text, &opt, &f);
    stp_posix_frame_free(&f);
    /* beyond stp_fix itself: refused before the core, which would get it
     * saturated (moved) */
    assert_int_equal(render_text("obj", "v 0 0 0\nv 1 0 0\nv 0 40000 0\nf 1 2 3\n", &opt, &f, err,
                                 sizeof err),
                     -1);
    assert_string_equal(err, "4: coordinate (0, 40000, 0) of polygon 1 beyond the core's range "
                             "(+-32767 units); without --no-rescale the scene is scaled into it");
    /* a message without a line keeps "name: " */
    stp_tool_scene_message(message, sizeof message, "s.nff", "out of memory");
    assert_string_equal(message, "s.nff: out of memory");
}

/* ---- shadows with 'at' next to the eye ---------------------------------- */

static void test_shadows_with_at_near_the_eye(void **state)
{
    /* SPD rings puts 'at' a hundredth of the way to the scene */
    static const char *const scenes[] = {
        "v\nfrom -4 -5 4.5\nat -3.96 -4.95 4.461\nup 0 0 1\nangle 45\nhither 0.01\n"
        "resolution 64 64\nl 1 1 9\nf 1 1 1 1 0 0 0 1\np 4\n5 5 0\n-5 5 0\n-5 -5 0\n5 -5 0\n"
        "s 0 0 1.2 0.8\n",
        "v\nfrom -4 -5 4.5\nat 0 0 0.6\nup 0 0 1\nangle 45\nhither 0.01\n"
        "resolution 64 64\nl 1 1 9\nf 1 1 1 1 0 0 0 1\np 4\n5 5 0\n-5 5 0\n-5 -5 0\n5 -5 0\n"
        "s 0 0 1.2 0.8\n"};
    stp_tool_options opt;
    stp_posix_frame lit, shadowed[2];
    int k;
    (void)state;
    stp_tool_options_default(&opt);
    for (k = 0; k < 2; k++) {
        opt.shadow_resolution = 0;
        render_ok("nff", scenes[k], &opt, &lit);
        opt.shadow_resolution = 256;
        render_ok("nff", scenes[k], &opt, &shadowed[k]);
        /* the sphere's shadow on the floor: a few hundred pixels darker */
        if (pixels_differing(&lit, &shadowed[k]) < 100)
            fail_msg("scene %d: only %d pixels shadowed", k, pixels_differing(&lit, &shadowed[k]));
        stp_posix_frame_free(&lit);
    }
    /* moving 'at' along the line of sight hardly changes the picture */
    assert_true(pixels_differing(&shadowed[0], &shadowed[1]) <= W * H / 100);
    stp_posix_frame_free(&shadowed[0]);
    stp_posix_frame_free(&shadowed[1]);
}

/* ---- lights beyond the build's limit ------------------------------------ */

static void test_lights_merged(void **state)
{
    /* STP_MAX_LIGHTS + 2 lights: all but one under the floor, the last one
     * above it; dropping lights beyond the limit left the floor unlit */
    char text[2048];
    size_t n = 0;
    int j;
    stp_tool_options opt;
    stp_posix_frame below, all;
    stp_scene s;
    stp_tool_prepared prep;
    char err[512];
    double total = 0;
    (void)state;
    stp_tool_options_default(&opt);
    n += (size_t)snprintf(text + n, sizeof text - n,
                          "v\nfrom 0 -6 6\nat 0 0 0\nup 0 0 1\nangle 45\nhither 0.1\n"
                          "resolution 8 8\n");
    for (j = 0; j < STP_MAX_LIGHTS + 1; j++)
        n += (size_t)snprintf(text + n, sizeof text - n, "l %d %d -5\n", j - 2, j % 2);
    snprintf(text + n, sizeof text - n, "p 4\n3 3 0\n-3 3 0\n-3 -3 0\n3 -3 0\n");
    render_ok("nff", text, &opt, &below);
    /* the light above comes last: it was the one dropped */
    snprintf(text + n, sizeof text - n, "l 0 0 6\np 4\n3 3 0\n-3 3 0\n-3 -3 0\n3 -3 0\n");
    render_ok("nff", text, &opt, &all);
    {
        long sum_below = 0, sum_all = 0;
        uint32_t x, y;
        for (y = 0; y < H; y++)
            for (x = 0; x < W; x++) {
                sum_below += below.pixels[y * below.stride + x];
                sum_all += all.pixels[y * all.stride + x];
            }
        if (!(sum_all > sum_below + (long)W * H * 10))
            fail_msg("the light above the floor was lost: %ld vs %ld", sum_all, sum_below);
    }
    stp_posix_frame_free(&below);
    stp_posix_frame_free(&all);
    /* the merge: the count fits, nothing is lost, the closest pair went */
    assert_int_equal(stp_scene_parse(text, strlen(text), "nff", "t", NULL, &s, err, sizeof err),
                     0);
    assert_int_equal(s.light_count, STP_MAX_LIGHTS + 2);
    assert_int_equal(stp_tool_prepare(&s, &opt, &prep, err, sizeof err), 0);
    assert_int_equal(prep.scene.light_count, STP_MAX_LIGHTS);
    assert_int_equal(prep.lights_in, STP_MAX_LIGHTS + 2);
    for (j = 0; j < STP_MAX_LIGHTS; j++)
        total += prep.light_weight[j];
    assert_true(fabs(total - (STP_MAX_LIGHTS + 2)) < 1e-12);
    {
        int above = 0;
        for (j = 0; j < STP_MAX_LIGHTS; j++)
            if (prep.scene.lights[j].position.z > 0) {
                above++;
                assert_true(fabs(prep.light_weight[j] - 1) < 1e-12); /* kept alone */
            }
        assert_int_equal(above, 1);
    }
    stp_tool_prepared_free(&prep);
    stp_scene_free(&s);
}

/* ---- polygons beyond the build's vertex limit --------------------------- */

#define BIG 936

/* Even-odd inside test and the distance to the outline, in double. */
static int inside(double (*p)[2], int n, double x, double y, double *edge_dist)
{
    int i, j, in = 0;
    double best = 1e300;
    for (i = 0, j = n - 1; i < n; j = i++) {
        double ax = p[j][0], ay = p[j][1], bx = p[i][0], by = p[i][1];
        double dx = bx - ax, dy = by - ay, t, qx, qy, d;
        if ((ay > y) != (by > y) && x < ax + (y - ay) * dx / dy)
            in = !in;
        t = ((x - ax) * dx + (y - ay) * dy) / (dx * dx + dy * dy);
        t = t < 0 ? 0 : t > 1 ? 1 : t;
        qx = ax + t * dx - x;
        qy = ay + t * dy - y;
        d = sqrt(qx * qx + qy * qy);
        if (d < best)
            best = d;
    }
    *edge_dist = best;
    return in;
}

/* A 936-vertex outline (convex: a circle; non-convex: a star with 468
 * points) rendered face on with a 90-degree view from 10 units: device x =
 * W/2 + x f / 10, y = H/2 - y f / 10 with f = (H/2) / tan(45).  Every pixel
 * whose centre lies more than 0.2 pixel from the outline (device
 * coordinates are rounded to 1/16 pixel) is drawn exactly
 * when the centre is inside. */
static void check_big_polygon(int star)
{
    static double pts[BIG][2];
    char *text = malloc(BIG * 64 + 512);
    size_t n = 0;
    int i, wrong = 0, covered = 0;
    uint32_t x, y;
    stp_tool_options opt;
    stp_posix_frame f;
    const double focal = (H / 2.0) / tan(45.0 * 3.14159265358979323846 / 180);
    n += (size_t)sprintf(text, "v\nfrom 0 0 10\nat 0 0 0\nup 0 1 0\nangle 90\nhither 1\n"
                               "resolution 8 8\nl 0 0 10\np %d\n", BIG);
    for (i = 0; i < BIG; i++) {
        double a = 2 * 3.14159265358979323846 * i / BIG;
        double r = star ? (i % 2 ? 2.0 : 6.0) : 6.0;
        pts[i][0] = r * cos(a);
        pts[i][1] = r * sin(a);
        n += (size_t)sprintf(text + n, "%.17g %.17g 0\n", pts[i][0], pts[i][1]);
    }
    stp_tool_options_default(&opt);
    render_ok("nff", text, &opt, &f);
    free(text);
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            double wx = (x + 0.5 - W / 2.0) * 10 / focal, wy = (H / 2.0 - (y + 0.5)) * 10 / focal;
            double d;
            int want = inside(pts, BIG, wx, wy, &d), got = f.pixels[y * f.stride + x] != 0;
            covered += want;
            if (want != got && d * focal / 10 > 0.2)
                wrong++;
        }
    stp_posix_frame_free(&f);
    assert_true(covered > 100);
    if (wrong)
        fail_msg("%s: %d pixels away from the outline disagree with the reference",
                 star ? "star" : "circle", wrong);
}

static void test_big_polygons_split(void **state)
{
    (void)state;
    check_big_polygon(0);
    check_big_polygon(1);
}

/* The splitter's pieces: within the limit and covering the polygon's area. */
static void test_split_pieces(void **state)
{
    static stp_scene_vec3 v[BIG];
    int *idx, *cnt, pieces, k, used = 0, star;
    (void)state;
    for (star = 0; star < 2; star++) {
        double area = 0, want = 0;
        for (k = 0; k < BIG; k++) {
            double a = 2 * 3.14159265358979323846 * k / BIG, r = star ? (k % 2 ? 2 : 6) : 6;
            v[k].x = r * cos(a);
            v[k].y = r * sin(a);
            v[k].z = 0;
        }
        for (k = 0; k < BIG; k++)
            want += v[k].x * v[(k + 1) % BIG].y - v[(k + 1) % BIG].x * v[k].y;
        pieces = stp_tool_split_polygon(v, BIG, STP_MAX_POLYGON_VERTICES, &idx, &cnt);
        assert_true(pieces > 1);
        used = 0;
        for (k = 0; k < pieces; k++) {
            int j;
            assert_true(cnt[k] >= 3 && cnt[k] <= STP_MAX_POLYGON_VERTICES);
            for (j = 0; j < cnt[k]; j++) {
                const stp_scene_vec3 *a = &v[idx[used + j]], *b = &v[idx[used + (j + 1) % cnt[k]]];
                area += a->x * b->y - b->x * a->y;
            }
            used += cnt[k];
        }
        if (star)
            assert_int_equal(pieces, BIG - 2); /* ear clipping: triangles */
        assert_true(fabs(area - want) < 1e-9 * fabs(want));
        free(idx);
        free(cnt);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_units_do_not_change_the_picture),
        cmocka_unit_test(test_huge_and_far_geometry),
        cmocka_unit_test(test_unrepresentable_refused),
        cmocka_unit_test(test_units_kept_range_refused),
        cmocka_unit_test(test_shadows_with_at_near_the_eye),
        cmocka_unit_test(test_lights_merged),
        cmocka_unit_test(test_big_polygons_split),
        cmocka_unit_test(test_split_pieces),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
