/* SPDX-License-Identifier: MIT */
/*
 * stp_renderer_mesh against stp_renderer_polygon (issue 11): the torus of
 * the benchmark entered both ways, still and spinning — the same vertex
 * records for every front face both enter, picture differences only inside
 * faces whose style differs, shades within 1/30 of the double reference;
 * the fallback (clipping, a non-uniform scale, colour, transparency, no
 * prepared normals) giving the polygon path's display file; the normals;
 * bad arguments; the shared teapots (teapot-s1, teapot-s2) both ways.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "render_ref.h"
#include "render_scene.h"
#include "test_scenes.h"
#include "torus.h"

/* The worst |shade - double reference| of a face entered through the mesh
 * path (shade_fast.c's arithmetic): measured 0.00010 still and 0.00181
 * posed (the accurate stp_shade_unit on the same normals: 0.00014 and
 * 0.00192: the posed figure is the Q14 normals' and the pose's rounding,
 * not the shading's), bounded with some room. */
#define SHADE_BOUND 0.0025

/* A triangle as entered into a display file: its three vertex records'
 * x, y, z and the style in force. */
typedef struct face {
    int32_t v[9];
    int style;
    int matched;
} face;

static int face_cmp(const void *a, const void *b)
{
    return memcmp(((const face *)a)->v, ((const face *)b)->v, sizeof ((const face *)a)->v);
}

/* The unclipped triangles of b's display file, sorted by their vertices;
 * *clipped: how many polygons of another vertex count it holds. */
static size_t faces_of(const torus_bench *b, face *out, size_t *clipped)
{
    uint32_t used = stp_renderer_display_file_used(b->r), i = 0;
    size_t n = 0;
    int style = -1;
    *clipped = 0;
    while (i < used) {
        const stp_instr *in = &b->df[i];
        if (in->op == STP_OP_SHADE) {
            style = in->x;
            i++;
        } else if (in->op == 3) {
            int k;
            for (k = 0; k < 3; k++) {
                out[n].v[3 * k] = in[k].x;
                out[n].v[3 * k + 1] = in[k].y;
                out[n].v[3 * k + 2] = in[k].z;
            }
            out[n].style = style;
            out[n].matched = 0;
            n++;
            i += 3;
        } else if (in->op > 3) {
            (*clipped)++;
            i += (uint32_t)in->op;
        } else {
            i++;
        }
    }
    qsort(out, n, sizeof *out, face_cmp);
    return n;
}

static int mono_at(const torus_bench *b, int x, int y)
{
    return (b->frame[(size_t)y * b->stride + (size_t)x / 8] >> (7 - x % 8)) & 1;
}

/* Whether pixel (x, y) lies within a pixel of face f's device box. */
static int near_face(const face *f, int x, int y)
{
    int32_t x0 = f->v[0], x1 = f->v[0], y0 = f->v[1], y1 = f->v[1];
    int k;
    for (k = 1; k < 3; k++) {
        x0 = f->v[3 * k] < x0 ? f->v[3 * k] : x0;
        x1 = f->v[3 * k] > x1 ? f->v[3 * k] : x1;
        y0 = f->v[3 * k + 1] < y0 ? f->v[3 * k + 1] : y0;
        y1 = f->v[3 * k + 1] > y1 ? f->v[3 * k + 1] : y1;
    }
    /* Q27.4 device coordinates */
    return x >= x0 / 16 - 1 && x <= x1 / 16 + 1 && y >= y0 / 16 - 1 && y <= y1 / 16 + 1;
}

static void pose_both(torus_bench *a, torus_bench *b, double tilt, double spin, double dx, double dy,
                      double dz)
{
    torus_bench_pose(a, tilt, spin, dx, dy, dz);
    torus_bench_pose(b, tilt, spin, dx, dy, dz);
}

/* The torus's vertices turned as torus_bench_pose turns them, in double. */
static void pose_scene(stp_scene *s, double tilt, double spin, double dx, double dy, double dz)
{
    const double pi = 3.14159265358979323846;
    double ct = cos(tilt * pi / 180), st = sin(tilt * pi / 180);
    double cs = cos(spin * pi / 180), ss = sin(spin * pi / 180);
    size_t i;
    for (i = 0; i < s->vertex_count; i++) {
        stp_scene_vec3 p = s->vertices[i], q;
        q.x = p.x;
        q.y = ct * p.y - st * p.z;
        q.z = st * p.y + ct * p.z;
        p.x = cs * q.x + ss * q.z + dx;
        p.y = q.y + dy;
        p.z = -ss * q.x + cs * q.z + dz;
        s->vertices[i] = p;
    }
}

/* Whether device y coordinates a, b, c (Q27.4) span a row centre
 * 16 r + 8 in [min, max): the rows a triangle draws. */
static int spans_row_centre(int32_t a, int32_t b, int32_t c)
{
    double lo = fmin(a, fmin(b, c)), hi = fmax(a, fmax(b, c));
    double first = ceil((lo - 8) / 16); /* the first row centre at or below lo */
    return 16 * first + 8 < hi;
}

/* Each triangle's shade entered alone through stp_renderer_mesh (a mesh
 * of that one triangle), against the double reference; a triangle left
 * out because it spans no row centre must span none. */
static void shades_match_reference(torus_bench *b, const ref_render_result *res)
{
    stp_mesh one = b->mesh;
    size_t t;
    int removed = 0, between_rows = 0;
    double worst = 0;
    assert_int_equal(stp_segment_create(b->r, 2), STP_OK);
    if (b->posed)
        assert_int_equal(stp_renderer_set_transform(b->r, &b->pose), STP_OK);
    one.triangle_count = 1;
    for (t = 0; t < TORUS_TRIANGLES; t++) {
        double core;
        one.triangles = b->mesh.triangles + 3 * t;
        one.normals = b->mesh.normals + 3 * t;
        assert_int_equal(stp_renderer_mesh(b->r, &one, b->mesh_scratch, b->mesh.vertex_count),
                         STP_OK);
        core = stp_renderer_last_shade(b->r) < 0
                   ? -1
                   : (double)stp_renderer_last_shade(b->r) / STP_FIX_ONE;
        if (res->shade[t] < 0 || core < 0) {
            if (core < 0 && res->shade[t] >= 0 && res->n_dot_e[t] >= 2e-3) {
                /* left out unshaded only between two row centres: its
                 * projected vertices span none */
                const uint16_t *k = one.triangles;
                assert_false(spans_row_centre(b->mesh_scratch[k[0]].dy, b->mesh_scratch[k[1]].dy,
                                              b->mesh_scratch[k[2]].dy));
                between_rows++;
            } else if ((res->shade[t] < 0) != (core < 0)) {
                assert_true(res->n_dot_e[t] < 2e-3); /* decided otherwise only edge-on */
            }
            removed += core < 0;
            continue;
        }
        if (fabs(core - res->shade[t]) > worst)
            worst = fabs(core - res->shade[t]);
        if (fabs(core - res->shade[t]) > 1.0 / 30) {
            fprintf(stderr, "triangle %zu: mesh %.5f, reference %.5f\n", t, core, res->shade[t]);
            fail();
        }
    }
    fprintf(stderr, "  shades: worst |mesh - double reference| %.5f; %d faces between two row centres\n",
            worst, between_rows);
    assert_true(between_rows <= 30); /* a few slivers at the silhouette, not a wrong test */
    assert_true(worst <= SHADE_BOUND);
    assert_in_range(removed, 350, 650);
    assert_int_equal(stp_segment_close(b->r), STP_OK);
    assert_int_equal(stp_segment_delete(b->r, 2), STP_OK);
}

/* The torus at w x h, posed (tilt, spin) or not, entered both ways. */
static void mesh_matches_polygon(int w, int h, int posed, double tilt, double spin)
{
    static torus_bench poly, mesh;
    static face fp[TORUS_TRIANGLES], fm[TORUS_TRIANGLES];
    char err[256];
    size_t np, nm, cp, cm, i, only = 0, restyled = 0;
    long diff = 0, unexplained = 0;
    int x, y;
    assert_int_equal(torus_bench_init(&poly, w, h, err, sizeof err), 0);
    assert_int_equal(torus_bench_init(&mesh, w, h, err, sizeof err), 0);
    assert_int_equal(torus_bench_use_mesh(&mesh, err, sizeof err), 0);
    if (posed)
        pose_both(&poly, &mesh, tilt, spin, 0.05, -0.03, 0.04);
    /* twice, as the bench does: re-entering into a used display file */
    assert_int_equal(torus_frame(&poly), 0);
    assert_int_equal(torus_frame(&mesh), 0);
    assert_int_equal(torus_frame(&poly), 0);
    assert_int_equal(torus_frame(&mesh), 0);
    np = faces_of(&poly, fp, &cp);
    nm = faces_of(&mesh, fm, &cm);
    assert_int_equal(cp, 0);
    assert_int_equal(cm, 0);
    assert_in_range(nm, 350, 650);
    for (i = 0; i < nm; i++) {
        face *f = bsearch(&fm[i], fp, np, sizeof *fp, face_cmp);
        if (!f) {
            only++; /* a face decided front here and back there */
            continue;
        }
        f->matched = fm[i].matched = 1;
        if (f->style != fm[i].style)
            restyled++;
        else
            f->matched = fm[i].matched = 2; /* same records, same style */
    }
    for (i = 0; i < np; i++)
        only += fp[i].matched == 0;
    for (y = 0; y < h; y++) {
        for (x = 0; x < w; x++) {
            int explained = 0;
            if (mono_at(&poly, x, y) == mono_at(&mesh, x, y))
                continue;
            diff++;
            for (i = 0; i < nm && !explained; i++)
                explained = fm[i].matched != 2 && near_face(&fm[i], x, y);
            for (i = 0; i < np && !explained; i++)
                explained = fp[i].matched != 2 && near_face(&fp[i], x, y);
            unexplained += !explained;
        }
    }
    fprintf(stderr,
            "%dx%d pose %g/%g: %zu faces (polygon %zu), %zu entered by one path only, %zu "
            "restyled, %ld pixels differ\n",
            w, h, tilt, spin, nm, np, only, restyled, diff);
    assert_true(only <= 4);
    /* the mesh path's shades (shade_fast.c) are not the polygon path's
     * (shade.c): a face whose shade lies within their difference (< 0.002,
     * SHADE_BOUND) of a level boundary changes level; measured at most 1
     * face of ~450 on these poses and 0 pixels (the face was too small or
     * its halftone cell the same), bounded at 1 % of the faces and of the
     * pixels, every differing pixel inside or next to such a face */
    assert_true(restyled * 100 <= nm);
    assert_true(diff * 100 <= (long)w * h);
    assert_int_equal(unexplained, 0);
    if (w == 128) {
        /* the shades against the double reference */
        ref_render_options ropt;
        ref_render_result res;
        stp_scene s;
        assert_int_equal(torus_scene_build(&s), 0);
        if (posed)
            pose_scene(&s, tilt, spin, 0.05, -0.03, 0.04);
        ref_render_options_default(&ropt);
        ropt.width = w;
        ropt.height = h;
        ropt.backface_removal = 1;
        ropt.max_lights = STP_MAX_LIGHTS;
        ropt.max_vertices = STP_MAX_POLYGON_VERTICES;
        assert_int_equal(ref_render_scene(&s, &ropt, &res, err, sizeof err), 0);
        shades_match_reference(&mesh, &res);
        ref_render_result_free(&res);
        stp_scene_free(&s);
    }
    torus_bench_free(&poly);
    torus_bench_free(&mesh);
}

static void test_still_128x64(void **state)
{
    (void)state;
    mesh_matches_polygon(128, 64, 0, 0, 0);
}

static void test_still_400x240(void **state)
{
    (void)state;
    mesh_matches_polygon(400, 240, 0, 0, 0);
}

/* Spinning: the model transform at several angles. */
static void test_spinning(void **state)
{
    static const double spins[] = {0, 37, 133, 250};
    size_t i;
    (void)state;
    for (i = 0; i < sizeof spins / sizeof spins[0]; i++)
        mesh_matches_polygon(128, 64, 1, 20 + 10 * (double)i, spins[i]);
    mesh_matches_polygon(400, 240, 1, 25, 71);
}

/* A state the fast path leaves to stp_renderer_polygon for the whole call:
 * the two display files are the same entry for entry. */
typedef void (*bench_state)(torus_bench *b);

static void same_display_file(bench_state set)
{
    static torus_bench poly, mesh;
    char err[256];
    uint32_t used;
    assert_int_equal(torus_bench_init(&poly, 128, 64, err, sizeof err), 0);
    assert_int_equal(torus_bench_init(&mesh, 128, 64, err, sizeof err), 0);
    assert_int_equal(torus_bench_use_mesh(&mesh, err, sizeof err), 0);
    set(&poly);
    set(&mesh);
    assert_int_equal(torus_frame(&poly), 0);
    assert_int_equal(torus_frame(&mesh), 0);
    used = stp_renderer_display_file_used(poly.r);
    assert_true(used > 1000);
    assert_int_equal(stp_renderer_display_file_used(mesh.r), used);
    assert_memory_equal(poly.df, mesh.df, sizeof *poly.df * used);
    assert_memory_equal(poly.frame, mesh.frame, poly.stride * 64);
    torus_bench_free(&poly);
    torus_bench_free(&mesh);
}

static void non_uniform_scale(torus_bench *b)
{
    stp_transform_identity(&b->pose);
    stp_transform_scale(&b->pose, STP_FIX_ONE, STP_FIX_ONE * 13 / 10, STP_FIX_ONE * 8 / 10);
    stp_transform_rotate(&b->pose, 1, 30 * STP_FIX_ONE);
    b->posed = 1;
}

static void colour_on(torus_bench *b)
{
    assert_int_equal(stp_renderer_set_colour(b->r, 1), STP_OK);
}

static void transparency_on(torus_bench *b)
{
    assert_int_equal(stp_renderer_set_transparency(b->r, STP_FIX_ONE / 4, STP_FIX_ONE / 2, 2, 0, 0),
                     STP_OK);
}

static void no_normals(torus_bench *b)
{
    b->mesh.normals = 0;
}

static void mirrored(torus_bench *b)
{
    stp_transform_identity(&b->pose);
    stp_transform_scale(&b->pose, -STP_FIX_ONE, STP_FIX_ONE, STP_FIX_ONE);
    b->posed = 1;
}

static void test_fallback_states(void **state)
{
    (void)state;
    same_display_file(non_uniform_scale);
    same_display_file(colour_on);
    same_display_file(transparency_on);
    same_display_file(no_normals);
    same_display_file(mirrored);
}

/* Triangles crossing the window or the hither plane go through
 * stp_renderer_polygon: every clipped polygon of the polygon path is in
 * the mesh path's display file, the same records in the same order. */
static void clipped_alike(double dx, double dy, double dz)
{
    static torus_bench poly, mesh;
    char err[256];
    uint32_t up, um, i = 0, j = 0;
    size_t clipped = 0;
    assert_int_equal(torus_bench_init(&poly, 128, 64, err, sizeof err), 0);
    assert_int_equal(torus_bench_init(&mesh, 128, 64, err, sizeof err), 0);
    assert_int_equal(torus_bench_use_mesh(&mesh, err, sizeof err), 0);
    pose_both(&poly, &mesh, 10, 20, dx, dy, dz);
    assert_int_equal(torus_frame(&poly), 0);
    assert_int_equal(torus_frame(&mesh), 0);
    up = stp_renderer_display_file_used(poly.r);
    um = stp_renderer_display_file_used(mesh.r);
    /* walk both: each clipped polygon of one is the next clipped one of the other */
    for (;;) {
        while (i < up && poly.df[i].op <= 3)
            i += poly.df[i].op == 3 ? 3u : 1u;
        while (j < um && mesh.df[j].op <= 3)
            j += mesh.df[j].op == 3 ? 3u : 1u;
        if (i >= up || j >= um)
            break;
        assert_int_equal(poly.df[i].op, mesh.df[j].op);
        assert_memory_equal(&poly.df[i], &mesh.df[j], sizeof *poly.df * (size_t)poly.df[i].op);
        i += (uint32_t)poly.df[i].op;
        j += (uint32_t)mesh.df[j].op;
        clipped++;
    }
    assert_true(i >= up && j >= um);
    fprintf(stderr, "offset (%g, %g, %g): %zu clipped polygons alike\n", dx, dy, dz, clipped);
    assert_true(clipped >= 5);
    torus_bench_free(&poly);
    torus_bench_free(&mesh);
}

static void test_fallback_clipping(void **state)
{
    (void)state;
    clipped_alike(3.5, 0, 0); /* across the window's right side */
    clipped_alike(0, 2.75, 4.75); /* around the eye: across the hither plane */
}

/* Back-face removal off: both sides entered, the back ones shaded as the
 * side the eye sees. */
static void test_backfaces_kept(void **state)
{
    static torus_bench poly, mesh;
    static face fp[TORUS_TRIANGLES], fm[TORUS_TRIANGLES];
    char err[256];
    size_t np, nm, cp, cm, i, restyled = 0;
    (void)state;
    assert_int_equal(torus_bench_init(&poly, 128, 64, err, sizeof err), 0);
    assert_int_equal(torus_bench_init(&mesh, 128, 64, err, sizeof err), 0);
    assert_int_equal(torus_bench_use_mesh(&mesh, err, sizeof err), 0);
    stp_renderer_set_backface_removal(poly.r, 0);
    stp_renderer_set_backface_removal(mesh.r, 0);
    assert_int_equal(torus_frame(&poly), 0);
    assert_int_equal(torus_frame(&mesh), 0);
    np = faces_of(&poly, fp, &cp);
    nm = faces_of(&mesh, fm, &cm);
    assert_int_equal(np, nm);
    assert_true(nm > 900);
    for (i = 0; i < nm; i++) {
        assert_memory_equal(fp[i].v, fm[i].v, sizeof fp[i].v);
        restyled += fp[i].style != fm[i].style;
    }
    assert_true(restyled * 20 <= nm);
    torus_bench_free(&poly);
    torus_bench_free(&mesh);
}

/* used (which shaded frames before) and fresh (a new renderer) enter a
 * frame under the same state: the same display file, which differs from
 * before's (the first `used` entries of an earlier frame of used). */
static void same_as_fresh(torus_bench *used, torus_bench *fresh, const stp_instr *before,
                          uint32_t before_used)
{
    uint32_t n;
    assert_int_equal(torus_frame(used), 0);
    assert_int_equal(torus_frame(fresh), 0);
    n = stp_renderer_display_file_used(used->r);
    assert_int_equal(stp_renderer_display_file_used(fresh->r), n);
    assert_memory_equal(used->df, fresh->df, sizeof *used->df * n);
    assert_true(n != before_used || memcmp(used->df, before, sizeof *before * n) != 0);
}

/* The mesh path prepares its shading once and keeps it across frames
 * (renderer_state.h: fast_shade): a new material or lighting must reach
 * it. */
static void test_shading_cache(void **state)
{
    static torus_bench a, b;
    static stp_instr before[TORUS_TRIANGLES * 9 + 16];
    char err[256];
    stp_lighting lighting;
    uint32_t n;
    (void)state;
    assert_int_equal(torus_bench_init(&a, 128, 64, err, sizeof err), 0);
    assert_int_equal(torus_bench_use_mesh(&a, err, sizeof err), 0);
    assert_int_equal(torus_frame(&a), 0);
    n = stp_renderer_display_file_used(a.r);
    memcpy(before, a.df, sizeof *before * n);
    /* a duller, rougher material */
    assert_int_equal(torus_bench_init(&b, 128, 64, err, sizeof err), 0);
    assert_int_equal(torus_bench_use_mesh(&b, err, sizeof err), 0);
    a.material.reflectivity = STP_FIX_ONE / 3;
    a.material.gloss = STP_FIX_ONE / 2;
    b.material = a.material;
    same_as_fresh(&a, &b, before, n);
    torus_bench_free(&b);
    n = stp_renderer_display_file_used(a.r);
    memcpy(before, a.df, sizeof *before * n);
    /* another light, set before the next frame's segment */
    stp_lighting_default(&lighting);
    lighting.background = STP_FIX_ONE / 10;
    lighting.lights[0].position.x = 3 * STP_FIX_ONE;
    lighting.lights[0].position.y = -2 * STP_FIX_ONE;
    lighting.lights[0].position.z = -6 * STP_FIX_ONE;
    lighting.lights[0].power = 5 * STP_FIX_ONE;
    assert_int_equal(torus_bench_init(&b, 128, 64, err, sizeof err), 0);
    assert_int_equal(torus_bench_use_mesh(&b, err, sizeof err), 0);
    b.material = a.material;
    assert_int_equal(stp_renderer_set_lighting(a.r, &lighting), STP_OK);
    assert_int_equal(stp_renderer_set_lighting(b.r, &lighting), STP_OK);
    same_as_fresh(&a, &b, before, n);
    torus_bench_free(&a);
    torus_bench_free(&b);
}

/* The prepared normals against double cross products. */
static void test_normals(void **state)
{
    static torus_bench b;
    char err[256];
    size_t t;
    (void)state;
    assert_int_equal(torus_bench_init(&b, 128, 64, err, sizeof err), 0);
    assert_int_equal(torus_bench_use_mesh(&b, err, sizeof err), 0);
    assert_in_range(b.mesh.vertex_count, 500, 600); /* 500 and the seam */
    for (t = 0; t < TORUS_TRIANGLES; t++) {
        const stp_vec3 *p[3];
        double a[3], c[3], n[3], len;
        int k;
        for (k = 0; k < 3; k++)
            p[k] = &b.mesh.vertices[b.mesh.triangles[3 * t + (size_t)k]];
        a[0] = (double)p[1]->x - p[0]->x;
        a[1] = (double)p[1]->y - p[0]->y;
        a[2] = (double)p[1]->z - p[0]->z;
        c[0] = (double)p[2]->x - p[0]->x;
        c[1] = (double)p[2]->y - p[0]->y;
        c[2] = (double)p[2]->z - p[0]->z;
        n[0] = a[1] * c[2] - a[2] * c[1];
        n[1] = a[2] * c[0] - a[0] * c[2];
        n[2] = a[0] * c[1] - a[1] * c[0];
        len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (k = 0; k < 3; k++)
            assert_true(fabs(b.mesh.normals[3 * t + (size_t)k] / 16384.0 - n[k] / len) <=
                        1.0 / 8192);
    }
    torus_bench_free(&b);
}

static const stp_vec3 small_vertices[5] = {{0, 0, 0},
                                           {STP_FIX_ONE, 0, 0},
                                           {0, STP_FIX_ONE, 0},
                                           {2 * STP_FIX_ONE, 0, 0},
                                           {0, 0, STP_FIX_ONE}};

static void test_normals_errors(void **state)
{
    static const uint16_t tris[] = {0, 1, 2, 0, 2, 4, 0, 1, 3, 0, 1, 2};
    static const uint16_t bad_index[] = {0, 1, 2, 0, 5, 4};
    int16_t normals[12];
    uint16_t bad = 999;
    stp_mesh m;
    (void)state;
    memset(&m, 0, sizeof m);
    m.vertices = small_vertices;
    m.vertex_count = 5;
    m.triangles = tris;
    m.triangle_count = 2;
    assert_int_equal(stp_mesh_prepare_normals(&m, normals, &bad), STP_OK);
    assert_int_equal(bad, 999);
    assert_int_equal(normals[0], 0);
    assert_int_equal(normals[1], 0);
    assert_int_equal(normals[2], STP_MESH_NORMAL_ONE);
    assert_int_equal(normals[3], STP_MESH_NORMAL_ONE);
    assert_int_equal(normals[4], 0);
    assert_int_equal(normals[5], 0);
    /* triangle 2 (0, 1, 3) is collinear */
    m.triangle_count = 4;
    assert_int_equal(stp_mesh_prepare_normals(&m, normals, &bad), STP_ERR_DEGENERATE);
    assert_int_equal(bad, 2);
    m.triangles = bad_index;
    m.triangle_count = 2;
    assert_int_equal(stp_mesh_prepare_normals(&m, normals, &bad), STP_ERR_ARG);
    assert_int_equal(bad, 1);
    assert_int_equal(stp_mesh_prepare_normals(0, normals, &bad), STP_ERR_ARG);
    assert_int_equal(stp_mesh_prepare_normals(&m, 0, &bad), STP_ERR_ARG);
}

/* stp_mesh_prepare_bounds: the box of small_vertices; bad arguments
 * STP_ERR_ARG with the bounds left alone. */
static void test_bounds_errors(void **state)
{
    stp_mesh_bounds b, before;
    stp_mesh m;
    int i;
    (void)state;
    memset(&m, 0, sizeof m);
    m.vertices = small_vertices;
    m.vertex_count = 5;
    assert_int_equal(stp_mesh_prepare_bounds(&m, &b), STP_OK);
    for (i = 0; i < 5; i++) {
        assert_true(b.lo.x <= small_vertices[i].x && small_vertices[i].x <= b.hi.x);
        assert_true(b.lo.y <= small_vertices[i].y && small_vertices[i].y <= b.hi.y);
        assert_true(b.lo.z <= small_vertices[i].z && small_vertices[i].z <= b.hi.z);
    }
    memset(&before, 0x5a, sizeof before);
    b = before;
    assert_int_equal(stp_mesh_prepare_bounds(0, &b), STP_ERR_ARG);
    assert_int_equal(stp_mesh_prepare_bounds(&m, 0), STP_ERR_ARG);
    m.vertex_count = 0;
    assert_int_equal(stp_mesh_prepare_bounds(&m, &b), STP_ERR_ARG);
    m.vertex_count = 5;
    m.vertices = 0;
    assert_int_equal(stp_mesh_prepare_bounds(&m, &b), STP_ERR_ARG);
    assert_memory_equal(&b, &before, sizeof b);
}

/* Bad arguments: STP_ERR_ARG with nothing entered. */
static void test_bad_arguments(void **state)
{
    static torus_bench b;
    static uint16_t tris[3 * TORUS_TRIANGLES];
    char err[256];
    stp_mesh m;
    uint32_t used;
    (void)state;
    assert_int_equal(torus_bench_init(&b, 128, 64, err, sizeof err), 0);
    assert_int_equal(torus_bench_use_mesh(&b, err, sizeof err), 0);
    assert_int_equal(stp_segment_create(b.r, 1), STP_OK);
    used = stp_renderer_display_file_used(b.r);
    m = b.mesh;
    memcpy(tris, b.mesh.triangles, sizeof tris);
    tris[3 * TORUS_TRIANGLES - 1] = b.mesh.vertex_count; /* the last index out of range */
    m.triangles = tris;
    assert_int_equal(stp_renderer_mesh(b.r, &m, b.mesh_scratch, b.mesh.vertex_count), STP_ERR_ARG);
    assert_int_equal(stp_renderer_display_file_used(b.r), used);
    /* an index out of range at each place of a 64-bit word, in the first
     * and a later block of eight triangles (check_mesh's wide test), and
     * values whose 16-bit lanes test differently: count, 2^15, 2^16 - 1 */
    {
        static const uint16_t places[] = {0, 1, 2, 3, 4, 7, 11, 12, 19, 20, 23, 24 * 7 + 5, 24 * 7 + 22};
        const uint16_t values[] = {b.mesh.vertex_count, 0x8000u, 0xFFFFu};
        size_t p, v;
        for (p = 0; p < sizeof places / sizeof places[0]; p++)
            for (v = 0; v < sizeof values / sizeof values[0]; v++) {
                memcpy(tris, b.mesh.triangles, sizeof tris);
                tris[places[p]] = values[v];
                assert_int_equal(stp_renderer_mesh(b.r, &m, b.mesh_scratch, b.mesh.vertex_count), STP_ERR_ARG);
            }
        memcpy(tris, b.mesh.triangles, sizeof tris);
        tris[3 * TORUS_TRIANGLES - 1] = b.mesh.vertex_count;
        assert_int_equal(stp_renderer_display_file_used(b.r), used);
    }
    /* more than 2^15 vertices (check_mesh's other lane form): the torus's
     * vertices repeated (500 a copy), its triangles on copies from 32 500;
     * an index of count or above refused, those below entered */
    {
        const uint16_t big = 40000, base = 32768;
        stp_vec3 *verts = malloc(big * sizeof *verts);
        stp_mesh_vertex *scratch = malloc(big * sizeof *scratch);
        const uint16_t values[] = {40000, 40001, 0xFFFFu};
        const uint16_t places[] = {0, 1, 2, 3, 5, 12, 23, 24 * 9 + 17};
        size_t i, p, v;
        assert_non_null(verts);
        assert_non_null(scratch);
        for (i = 0; i < big; i++)
            verts[i] = b.mesh.vertices[i % b.mesh.vertex_count];
        m = b.mesh;
        m.vertices = verts;
        m.vertex_count = big;
        m.triangles = tris;
        for (p = 0; p < sizeof places / sizeof places[0]; p++)
            for (v = 0; v < sizeof values / sizeof values[0]; v++) {
                for (i = 0; i < 3 * TORUS_TRIANGLES; i++)
                    tris[i] = (uint16_t)(base - base % b.mesh.vertex_count + b.mesh.triangles[i]);
                tris[places[p]] = values[v];
                assert_int_equal(stp_renderer_mesh(b.r, &m, scratch, big), STP_ERR_ARG);
            }
        assert_int_equal(stp_renderer_display_file_used(b.r), used);
        for (i = 0; i < 3 * TORUS_TRIANGLES; i++) { /* copies at 0, 32 000 and 39 500 (39 999 the highest) */
            static const uint16_t copy[] = {0, 32000, 39500};
            tris[i] = (uint16_t)(copy[i % 3] + b.mesh.triangles[i]);
        }
        assert_int_equal(stp_renderer_mesh(b.r, &m, scratch, big), STP_OK);
        assert_true(stp_renderer_display_file_used(b.r) > used + 1000);
        used = stp_renderer_display_file_used(b.r);
        memcpy(tris, b.mesh.triangles, sizeof tris);
        tris[3 * TORUS_TRIANGLES - 1] = b.mesh.vertex_count;
        m = b.mesh;
        m.triangles = tris;
        free(scratch);
        free(verts);
    }
    assert_int_equal(stp_renderer_mesh(0, &b.mesh, b.mesh_scratch, b.mesh.vertex_count), STP_ERR_ARG);
    assert_int_equal(stp_renderer_mesh(b.r, 0, b.mesh_scratch, b.mesh.vertex_count), STP_ERR_ARG);
    assert_int_equal(stp_renderer_mesh(b.r, &b.mesh, 0, b.mesh.vertex_count), STP_ERR_ARG);
    assert_int_equal(stp_renderer_mesh(b.r, &b.mesh, b.mesh_scratch, b.mesh.vertex_count - 1u),
                     STP_ERR_ARG);
    m = b.mesh;
    m.vertices = 0;
    assert_int_equal(stp_renderer_mesh(b.r, &m, b.mesh_scratch, b.mesh.vertex_count), STP_ERR_ARG);
    assert_int_equal(stp_renderer_display_file_used(b.r), used);
    /* an empty mesh enters nothing and is fine */
    m.triangle_count = 0;
    m.vertex_count = 0;
    assert_int_equal(stp_renderer_mesh(b.r, &m, b.mesh_scratch, 0), STP_OK);
    /* and the whole torus enters after the refusals */
    assert_int_equal(stp_renderer_mesh(b.r, &b.mesh, b.mesh_scratch, b.mesh.vertex_count), STP_OK);
    assert_true(stp_renderer_display_file_used(b.r) > used + 1000);
    torus_bench_free(&b);
}

/* A shared scene's triangles of its first triangle's material (flat, back
 * faces removed, the scene's view and lights at 256 x 256), entered one by
 * one with stp_renderer_polygon and as one mesh: the same vertex records
 * for the front faces both enter, few faces decided or styled otherwise. */
static void scene_mesh_matches_polygon(const char *name)
{
    static face fp[4096], fm[4096];
    stp_scene s;
    stp_tool_options opt;
    stp_view view;
    stp_lighting lighting;
    stp_material material;
    stp_renderer *r[2];
    void *mem[2];
    stp_instr *df[2];
    stp_vec3 *tri = 0, *verts = 0;
    uint16_t *index = 0;
    int16_t *normals = 0;
    stp_mesh_vertex *scratch = 0;
    stp_mesh mesh;
    torus_bench view_of[2];
    size_t t, n = 0, nv = 0, np, nm, cp, cm, i, only = 0, restyled = 0;
    uint32_t capacity;
    char err[256];
    int m = -1, k;
    stp_test_load_scene(name, &s);
    stp_tool_options_default(&opt);
    opt.width = 256;
    opt.height = 256;
    opt.backface_removal = 1;
    assert_int_equal(stp_tool_setup(&s, &opt, &view, &lighting, err, sizeof err), 0);
    tri = malloc(sizeof *tri * 3 * s.polygon_count);
    verts = malloc(sizeof *verts * 3 * s.polygon_count);
    index = malloc(sizeof *index * 3 * s.polygon_count);
    normals = malloc(sizeof *normals * 3 * s.polygon_count);
    scratch = malloc(sizeof *scratch * 3 * s.polygon_count);
    assert_non_null(tri && verts && index && normals && scratch);
    /* the non-degenerate triangles of one material, vertices merged */
    for (t = 0; t < s.polygon_count; t++) {
        const stp_scene_polygon *p = &s.polygons[t];
        stp_mesh one;
        uint16_t ix[3] = {0, 1, 2};
        int16_t nn[3];
        if (p->count != 3 || (m >= 0 && p->material != m))
            continue;
        m = p->material;
        for (k = 0; k < 3; k++)
            tri[3 * n + (size_t)k] = stp_tool_vec3(s.vertices[p->first + (size_t)k]);
        memset(&one, 0, sizeof one);
        one.vertices = &tri[3 * n];
        one.vertex_count = 3;
        one.triangles = ix;
        one.triangle_count = 1;
        if (stp_mesh_prepare_normals(&one, nn, 0) != STP_OK)
            continue; /* degenerate: stp_renderer_polygon refuses it too */
        for (k = 0; k < 3; k++) {
            stp_vec3 q = tri[3 * n + (size_t)k];
            for (i = 0; i < nv; i++)
                if (verts[i].x == q.x && verts[i].y == q.y && verts[i].z == q.z)
                    break;
            if (i == nv)
                verts[nv++] = q;
            index[3 * n + (size_t)k] = (uint16_t)i;
        }
        n++;
    }
    assert_true(n >= 50);
    memset(&mesh, 0, sizeof mesh);
    mesh.vertices = verts;
    mesh.vertex_count = (uint16_t)nv;
    mesh.triangles = index;
    mesh.triangle_count = (uint16_t)n;
    assert_int_equal(stp_mesh_prepare_normals(&mesh, normals, 0), STP_OK);
    mesh.normals = normals;
    stp_material_default(&material);
    stp_tool_material(&s.materials[m], 0, &material);
    capacity = (uint32_t)(9 * n + 16);
    for (k = 0; k < 2; k++) {
        mem[k] = malloc(stp_renderer_size());
        df[k] = malloc(sizeof *df[k] * capacity);
        r[k] = stp_renderer_create(mem[k], stp_renderer_size(), df[k], capacity, 256, 256);
        assert_non_null(r[k]);
        assert_int_equal(stp_renderer_set_view(r[k], &view), STP_OK);
        assert_int_equal(stp_renderer_set_levels(r[k], 16), STP_OK);
        assert_int_equal(stp_renderer_set_lighting(r[k], &lighting), STP_OK);
        assert_int_equal(stp_renderer_set_shading(r[k], 1), STP_OK);
        assert_int_equal(stp_renderer_set_backface_removal(r[k], 1), STP_OK);
        assert_int_equal(stp_segment_create(r[k], 1), STP_OK);
        assert_int_equal(stp_renderer_set_object_shade(r[k], &material), STP_OK);
        memset(&view_of[k], 0, sizeof view_of[k]);
        view_of[k].r = r[k];
        view_of[k].df = df[k];
    }
    for (t = 0; t < n; t++)
        assert_int_equal(stp_renderer_polygon(r[0], &tri[3 * t], 3), STP_OK);
    assert_int_equal(stp_renderer_mesh(r[1], &mesh, scratch, nv), STP_OK);
    np = faces_of(&view_of[0], fp, &cp);
    nm = faces_of(&view_of[1], fm, &cm);
    for (i = 0; i < nm; i++) {
        face *f = bsearch(&fm[i], fp, np, sizeof *fp, face_cmp);
        if (!f) {
            only++;
            continue;
        }
        f->matched = 1;
        restyled += f->style != fm[i].style;
    }
    for (i = 0; i < np; i++)
        only += !fp[i].matched;
    fprintf(stderr, "%s: %zu triangles, %zu vertices; %zu faces entered (polygon %zu), %zu by one "
            "path only, %zu restyled, clipped %zu / %zu\n",
            name, n, nv, nm, np, only, restyled, cm, cp);
    assert_true(nm >= n / 4);
    assert_int_equal(cm, cp); /* the clipped ones through the fallback */
    assert_true(only * 50 <= n);
    assert_true(restyled * 10 <= nm);
    for (k = 0; k < 2; k++) {
        free(mem[k]);
        free(df[k]);
    }
    free(tri);
    free(verts);
    free(index);
    free(normals);
    free(scratch);
    stp_scene_free(&s);
}

static void test_shared_scenes(void **state)
{
    (void)state;
    scene_mesh_matches_polygon("teapot-s2");
    scene_mesh_matches_polygon("teapot-s1");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_still_128x64),
        cmocka_unit_test(test_still_400x240),
        cmocka_unit_test(test_spinning),
        cmocka_unit_test(test_fallback_states),
        cmocka_unit_test(test_fallback_clipping),
        cmocka_unit_test(test_backfaces_kept),
        cmocka_unit_test(test_shading_cache),
        cmocka_unit_test(test_normals),
        cmocka_unit_test(test_normals_errors),
        cmocka_unit_test(test_bounds_errors),
        cmocka_unit_test(test_bad_arguments),
        cmocka_unit_test(test_shared_scenes),
    };
    return cmocka_run_group_tests(tests, 0, 0);
}
