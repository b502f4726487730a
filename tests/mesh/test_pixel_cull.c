/* SPDX-License-Identifier: MIT */
/*
 * Pixel culling (stp_renderer_set_pixel_cull): a front triangle whose row
 * spans hold no pixel centre is left out before it is shaded.
 *   - each triangle the cull drops, entered alone without it into a
 *     renderer of its own and drawn (white on black, Z buffer), lights no
 *     pixel: the raster itself is the reference; a fine torus (tens of
 *     thousands of triangles of about a pixel), still and posed, through
 *     stp_renderer_mesh, and the benchmark torus through stp_renderer_polygon;
 *     the cull must drop thousands there (a test that drops nothing fails);
 *   - whole frames with and without it equal byte for byte (Z buffer,
 *     painter's sort, none; the benchmark torus both ways and the
 *     100 000-triangle torus), and both entries still give the same
 *     display file with it on;
 *   - a render with edge anti-aliasing of a display file from which it
 *     dropped a triangle is refused (STP_ERR_UNSUPPORTED), until that
 *     segment is gone; one from which it dropped nothing is drawn;
 *   - random small triangles and slivers in device coordinates, each
 *     drawn alone from a display file of its own: every one the cull's
 *     verdict (stp_render_triangle_shows) drops lights no pixel, and it
 *     drops most of those that light none.
 * Built against the host core (test_pixel_cull) and the 32-bit target
 * arithmetic (test_pixel_cull_narrow: stipple_core_m0plus_full).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "torus.h"
#include "stipple/playback.h"
#include "render_private.h" /* stp_render_triangle_shows: the cull's verdict */

/* Whether any pixel of b's last frame is lit. */
static int frame_lit(const torus_bench *b)
{
    size_t i, n = b->stride * (size_t)b->height;
    for (i = 0; i < n; i++)
        if (b->frame[i] != 0)
            return 1;
    return 0;
}

/* Polygons in b's display file. */
static uint32_t polygons(const torus_bench *b)
{
    return stp_renderer_polygon_count(b->r);
}

/* Enter triangle t of part p (or, part < 0, triangle t of the polygon
 * route's array) alone in segment 2 of b, with pixel culling on or off;
 * returns whether it was stored. */
static int enter_one(torus_bench *b, int part, size_t t, int cull)
{
    uint32_t before = polygons(b);
    assert_int_equal(stp_renderer_set_pixel_cull(b->r, cull), STP_OK);
    assert_int_equal(stp_segment_create(b->r, 2), STP_OK);
    if (b->posed)
        assert_int_equal(stp_renderer_set_transform(b->r, &b->pose), STP_OK);
    if (part >= 0) {
        stp_mesh one = b->parts[part];
        one.triangles = b->parts[part].triangles + 3 * t;
        one.normals = b->parts[part].normals + 3 * t;
        one.triangle_count = 1;
        assert_int_equal(stp_renderer_mesh(b->r, &one, b->mesh_scratch, b->scratch_count), STP_OK);
    } else {
        assert_int_equal(stp_renderer_polygon(b->r, b->vertices + 3 * t, 3), STP_OK);
    }
    assert_int_equal(stp_segment_close(b->r), STP_OK);
    return polygons(b) > before;
}

static void forget_one(torus_bench *b)
{
    assert_int_equal(stp_segment_delete(b->r, 2), STP_OK);
}

/* Every triangle of b (its mesh parts, or the polygon route's array of
 * `count` when part_count is 0) entered alone with and without the cull:
 * the cull keeps only what the control keeps, and each triangle it drops
 * draws no pixel in the control's frame.  Returns how many it dropped;
 * *drawn: kept triangles whose control frame lit a pixel. */
static size_t check_each(torus_bench *b, int part_count, size_t count, size_t *drawn)
{
    size_t dropped = 0, t;
    int p;
    *drawn = 0;
    /* white on black: a triangle's pixels are lit whatever its shade */
    assert_int_equal(stp_renderer_set_shading(b->r, 0), STP_OK);
    for (p = part_count > 0 ? 0 : -1; p < part_count; p++) {
        size_t n = p >= 0 ? b->parts[p].triangle_count : count;
        for (t = 0; t < n; t++) {
            int kept = enter_one(b, p, t, 1), control;
            forget_one(b);
            control = enter_one(b, p, t, 0);
            if (kept)
                assert_true(control); /* the cull only drops */
            if (control && (!kept || t % 16 == 0)) { /* every dropped one, a sample of the rest */
                memset(b->frame, 0x5A, b->stride * (size_t)b->height);
                assert_int_equal(stp_renderer_render(b->r, &b->port, &b->output, &b->memory), STP_OK);
                if (!kept && frame_lit(b)) {
                    fprintf(stderr, "part %d triangle %zu: dropped, but its control draws\n", p, t);
                    fail();
                }
                *drawn += kept && frame_lit(b);
            }
            dropped += control && !kept;
            forget_one(b);
        }
    }
    return dropped;
}

static void fine_torus(torus_bench *b, int w, int h, int around, int tube, const double *pose)
{
    char err[256];
    assert_int_equal(torus_bench_init_for(b, w, h, 2 * (size_t)around * (size_t)tube, err, sizeof err), 0);
    assert_int_equal(torus_bench_use_fine_mesh(b, around, tube, 0, err, sizeof err), 0);
    if (pose)
        torus_bench_pose(b, pose[0], pose[1], 0, 0, 0);
}

/* A fine torus through stp_renderer_mesh, triangles of about a pixel. */
static void test_mesh_dropped_draw_nothing(void **state)
{
    static const double pose[2] = {35, 50};
    static torus_bench b;
    size_t dropped, drawn;
    int posed;
    (void)state;
    for (posed = 0; posed < 2; posed++) {
        fine_torus(&b, 160, 96, 120, 90, posed ? pose : 0);
        dropped = check_each(&b, b.part_count, 0, &drawn);
        fprintf(stderr, "  mesh 160x96, %s: %zu of %d triangles dropped, draw nothing; %zu sampled kept ones draw\n",
                posed ? "posed" : "still", dropped, 2 * 120 * 90, drawn);
        assert_true(dropped >= 2000);
        assert_true(drawn >= 100);
        torus_bench_free(&b);
    }
}

/* The benchmark torus through stp_renderer_polygon, small on a small
 * frame. */
static void test_polygon_dropped_draw_nothing(void **state)
{
    static torus_bench b;
    char err[256];
    size_t dropped, drawn;
    (void)state;
    assert_int_equal(torus_bench_init(&b, 40, 24, err, sizeof err), 0);
    torus_bench_pose(&b, 25, 71, 0, 0, 0);
    dropped = check_each(&b, 0, TORUS_TRIANGLES, &drawn);
    fprintf(stderr, "  polygons 40x24: %zu of %d triangles dropped, draw nothing\n", dropped, TORUS_TRIANGLES);
    assert_true(dropped >= 20);
    torus_bench_free(&b);
}

/* The frame of b with pixel culling on and off: equal; returns the
 * polygons it dropped.  b->frame holds the culled frame after. */
static uint32_t frames_equal(torus_bench *b, uint8_t *kept_frame)
{
    uint32_t kept, culled;
    size_t bytes = b->stride * (size_t)b->height;
    assert_int_equal(stp_renderer_set_pixel_cull(b->r, 0), STP_OK);
    memset(b->frame, 0x55, bytes);
    assert_int_equal(torus_frame(b), 0);
    kept = polygons(b);
    memcpy(kept_frame, b->frame, bytes);
    assert_int_equal(stp_renderer_set_pixel_cull(b->r, 1), STP_OK);
    memset(b->frame, 0xAA, bytes);
    assert_int_equal(torus_frame(b), 0);
    culled = polygons(b);
    assert_memory_equal(kept_frame, b->frame, bytes);
    assert_true(culled <= kept);
    return kept - culled;
}

static void set_hidden(torus_bench *b, stp_hidden hidden, stp_sort_entry *sort, size_t sort_count)
{
    b->output.hidden = hidden;
    b->memory.sort = hidden == STP_HIDDEN_PAINTER ? sort : 0;
    b->memory.sort_count = hidden == STP_HIDDEN_PAINTER ? sort_count : 0;
}

/* The benchmark torus both ways at small sizes (where its triangles are
 * small), still and posed, under each hidden-surface method: frames equal
 * with and without the cull, and the two entries' display files equal with
 * it. */
static void test_frames_equal_benchmark_torus(void **state)
{
    static torus_bench poly, mesh;
    static stp_sort_entry sort_poly[TORUS_TRIANGLES], sort_mesh[TORUS_TRIANGLES];
    static uint8_t kept[640 * 480 / 8];
    static const int sizes[3][2] = {{40, 24}, {128, 64}, {400, 240}};
    static const stp_hidden methods[3] = {STP_HIDDEN_ZBUFFER, STP_HIDDEN_PAINTER, STP_HIDDEN_NONE};
    char err[256];
    uint32_t dropped_total = 0;
    int s, m, posed;
    (void)state;
    for (s = 0; s < 3; s++)
        for (m = 0; m < 3; m++)
            for (posed = 0; posed < 2; posed++) {
                int w = sizes[s][0], h = sizes[s][1];
                uint32_t used;
                assert_int_equal(torus_bench_init(&poly, w, h, err, sizeof err), 0);
                assert_int_equal(torus_bench_init(&mesh, w, h, err, sizeof err), 0);
                assert_int_equal(torus_bench_use_mesh(&mesh, err, sizeof err), 0);
                set_hidden(&poly, methods[m], sort_poly, TORUS_TRIANGLES);
                set_hidden(&mesh, methods[m], sort_mesh, TORUS_TRIANGLES);
                if (posed) {
                    torus_bench_pose(&poly, 50, 250, -0.1, 0.05, 0);
                    torus_bench_pose(&mesh, 50, 250, -0.1, 0.05, 0);
                }
                dropped_total += frames_equal(&poly, kept);
                dropped_total += frames_equal(&mesh, kept);
                used = stp_renderer_display_file_used(poly.r);
                assert_int_equal(stp_renderer_display_file_used(mesh.r), used);
                assert_memory_equal(poly.df, mesh.df, sizeof *poly.df * used);
                torus_bench_free(&poly);
                torus_bench_free(&mesh);
            }
    fprintf(stderr, "  benchmark torus: %u polygons dropped over the frames, frames equal\n",
            (unsigned)dropped_total);
    assert_true(dropped_total >= 100);
}

/* The side-by-side bench's 100 000-triangle torus at 400x240, still and
 * spinning: frames equal, tens of thousands dropped. */
static void test_frames_equal_fine_torus(void **state)
{
    static const double pose[2] = {20, 33};
    static torus_bench b;
    static uint8_t kept[400 * 240 / 8];
    uint32_t dropped;
    int posed;
    (void)state;
    for (posed = 0; posed < 2; posed++) {
        fine_torus(&b, 400, 240, 250, 200, posed ? pose : 0);
        dropped = frames_equal(&b, kept);
        fprintf(stderr, "  100 000 triangles, %s: %u dropped, frames equal\n", posed ? "posed" : "still",
                (unsigned)dropped);
        assert_true(dropped >= 10000);
        torus_bench_free(&b);
    }
}

/* Edge anti-aliasing draws partial pixels along slivers: refused for a
 * display file entered with the cull, until that segment is gone. */
static void test_edge_aa_refused(void **state)
{
    static torus_bench b;
    static uint8_t grey_band[128 * 64]; /* edge AA draws a 1-bit port's band as GREY8 */
    char err[256];
    (void)state;
    assert_int_equal(stp_renderer_set_pixel_cull(0, 1), STP_ERR_ARG);
    assert_int_equal(torus_bench_init(&b, 128, 64, err, sizeof err), 0);
    assert_int_equal(torus_bench_use_mesh(&b, err, sizeof err), 0);
    b.memory.band = grey_band;
    b.memory.band_size = sizeof grey_band;
    b.output.edge_aa = 1;
    assert_int_equal(stp_renderer_set_pixel_cull(b.r, 1), STP_OK);
    assert_int_equal(torus_frame(&b), -1); /* the render refused */
    assert_int_equal(stp_renderer_render(b.r, &b.port, &b.output, &b.memory), STP_ERR_UNSUPPORTED);
    /* turning it off does not bring the slivers back */
    assert_int_equal(stp_renderer_set_pixel_cull(b.r, 0), STP_OK);
    assert_int_equal(stp_renderer_render(b.r, &b.port, &b.output, &b.memory), STP_ERR_UNSUPPORTED);
    /* without edge AA the same display file renders */
    b.output.edge_aa = 0;
    assert_int_equal(stp_renderer_render(b.r, &b.port, &b.output, &b.memory), STP_OK);
    /* entered again without it (torus_frame deletes segment 1 first) */
    b.output.edge_aa = 1;
#if STP_WITH_EDGE_AA
    assert_int_equal(torus_frame(&b), 0);
#else
    assert_int_equal(torus_frame(&b), -1); /* edge AA compiled out */
#endif
    /* with it on, a segment from which it dropped nothing (one triangle
     * across the picture) is not refused */
    {
        stp_vec3 big[3];
        big[0] = b.vertices[0];
        big[1].x = -STP_FIX_ONE;
        big[1].y = -STP_FIX_ONE;
        big[1].z = b.vertices[0].z;
        big[2].x = STP_FIX_ONE;
        big[2].y = -STP_FIX_ONE;
        big[2].z = b.vertices[0].z;
        assert_int_equal(stp_segment_delete(b.r, 1), STP_OK);
        assert_int_equal(stp_renderer_set_pixel_cull(b.r, 1), STP_OK);
        assert_int_equal(stp_segment_create(b.r, 2), STP_OK);
        assert_int_equal(stp_renderer_polygon(b.r, big, 3), STP_OK);
        assert_int_equal(stp_segment_close(b.r), STP_OK);
        assert_true(stp_renderer_polygon_count(b.r) >= 1);
#if STP_WITH_EDGE_AA
        assert_int_equal(stp_renderer_render(b.r, &b.port, &b.output, &b.memory), STP_OK);
#endif
    }
    torus_bench_free(&b);
}

/* xorshift32: the same triangles on every run */
static uint32_t next_random(uint32_t *s)
{
    *s ^= *s << 13;
    *s ^= *s >> 17;
    *s ^= *s << 5;
    return *s;
}

/* A value in [-span, span]. */
static int32_t around(uint32_t *s, int32_t span)
{
    return (int32_t)(next_random(s) % (uint32_t)(2 * span + 1)) - span;
}

/* Device vertices (Q27.4) of a random triangle inside a w x h frame: a
 * small one, a tiny one or a sliver (a third vertex near the segment
 * between two others), each vertex within 64 of one inside a four-pixel
 * margin. */
static void random_triangle(uint32_t *s, int w, int h, int32_t v[6])
{
    int32_t bx = 64 + (int32_t)(next_random(s) % (uint32_t)(16 * (w - 8))),
            by = 64 + (int32_t)(next_random(s) % (uint32_t)(16 * (h - 8)));
    int kind = (int)(next_random(s) % 3u), k;
    int32_t span = kind == 1 ? 16 : 40;
    v[0] = bx;
    v[1] = by;
    for (k = 2; k < 6; k += 2) {
        v[k] = bx + around(s, span);
        v[k + 1] = by + around(s, span);
    }
    if (kind == 2) { /* a sliver: the third vertex along the first edge, jittered */
        int32_t t = (int32_t)(next_random(s) % 17u);
        v[2] = bx + around(s, 58);
        v[3] = by + around(s, 58);
        v[4] = bx + (v[2] - bx) * t / 16 + around(s, 6);
        v[5] = by + (v[3] - by) * t / 16 + around(s, 6);
    }
}

/* Whether triangle v, drawn alone (white on black, Z buffer) from a
 * display file of its own into b's frame, lights a pixel: the rasters'
 * own pixels. */
static int triangle_lit(torus_bench *b, const int32_t v[6], void *mem)
{
    stp_instr df[3];
    stp_renderer *pr;
    int k;
    memset(df, 0, sizeof df);
    for (k = 0; k < 3; k++) {
        df[k].op = k == 0 ? 3 : STP_OP_LINE;
        df[k].x = v[2 * k];
        df[k].y = v[2 * k + 1];
        df[k].z = 1 << 20;
#if STP_WITH_GOURAUD
        df[k].shade = -1;
#endif
    }
    pr = stp_playback_create(mem, stp_renderer_size(), df, 3, b->width, b->height, 16, 16);
    assert_non_null(pr);
    memset(b->frame, 0x5A, b->stride * (size_t)b->height);
    assert_int_equal(stp_renderer_render(pr, &b->port, &b->output, &b->memory), STP_OK);
    return frame_lit(b);
}

/* Random small triangles and slivers against the rasters: each the cull
 * drops lights no pixel, and it drops most of those that light none (the
 * area gate's kinds). */
static void test_random_small_triangles(void **state)
{
    static torus_bench b;
    static const int32_t big[6] = {16, 16, 16 * 38, 24, 40, 16 * 22};
    char err[256];
    uint32_t seed = 0x2545F491u;
    void *mem = malloc(stp_renderer_size());
    size_t i, spanning = 0, unlit = 0, dropped = 0, dropped_unlit = 0;
    (void)state;
    assert_non_null(mem);
    assert_int_equal(torus_bench_init(&b, 40, 24, err, sizeof err), 0);
    assert_int_equal(stp_renderer_set_pixel_cull(b.r, 1), STP_OK);
    assert_int_equal(stp_segment_create(b.r, 2), STP_OK); /* the verdict marks the open segment */
    assert_true(triangle_lit(&b, big, mem)); /* the reference draws */
    for (i = 0; i < 40000; i++) {
        int32_t v[6];
        int lit, shows;
        random_triangle(&seed, 40, 24, v);
        if (stp_render_row_count(v[1], v[3], v[5]) == 0)
            continue; /* between two row centres: left out untested */
        spanning++;
        shows = stp_render_triangle_shows(b.r, STP_CENTRE_TEST_MAX, v[0], v[1], v[2], v[3], v[4], v[5]);
        lit = triangle_lit(&b, v, mem);
        if (!shows && lit) {
            fprintf(stderr, "(%d,%d) (%d,%d) (%d,%d): dropped, but it draws\n", (int)v[0], (int)v[1],
                    (int)v[2], (int)v[3], (int)v[4], (int)v[5]);
            fail();
        }
        unlit += !lit;
        dropped += !shows;
        dropped_unlit += !shows && !lit;
    }
    assert_int_equal(stp_segment_close(b.r), STP_OK);
    fprintf(stderr, "  random triangles: %zu span a row centre, %zu of them light no pixel, %zu dropped\n",
            spanning, unlit, dropped);
    assert_int_equal(dropped, dropped_unlit);
    assert_true(unlit >= 2000);
    assert_true(dropped * 10 >= unlit * 6); /* most */
    free(mem);
    torus_bench_free(&b);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_mesh_dropped_draw_nothing),
        cmocka_unit_test(test_polygon_dropped_draw_nothing),
        cmocka_unit_test(test_frames_equal_benchmark_torus),
        cmocka_unit_test(test_frames_equal_fine_torus),
        cmocka_unit_test(test_edge_aa_refused),
        cmocka_unit_test(test_random_small_triangles),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
