/* SPDX-License-Identifier: MIT */
/*
 * Direct drawing (include/stipple/direct.h) against the full renderer:
 * a torus, a tetrahedron and a sphere (convex) at several angles, drawn
 * by stp_direct_* and by stp_renderer_mesh + stp_renderer_render (same
 * view, light, material, levels, Bayer 4x4 cell, back faces removed,
 * display-file order), compared pixel by pixel: the torus and the sphere
 * (inside the picture) equal, since direct drawing enters through the
 * renderer's geometry and face stages; the tetrahedron, which crosses the
 * picture's bottom edge, equal too, since direct drawing clips the faces
 * an edge cuts as the renderer does (the compact form, STP_DIRECT_COMPACT,
 * walks them whole: within its bounds a frame, every differing pixel
 * within one pixel of a drawn edge, or inside a face whose style the two
 * paths chose differently); the sphere also equal to the
 * renderer's frame with the Z buffer (convex: mesh order and depth
 * agree); each front face's shade within 1/30 of the
 * double reference; bands of any height give the whole frame exactly and
 * the panel's page layout holds the row-major frame transposed, with the
 * model at the centre, across the picture's edge and cut by the near
 * plane (faces drawn clipped); bad arguments.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "direct_private.h"
#include "reference/shade_ref.h"
#include "stipple/stipple.h"

#define W 128
#define H 64
#define STRIDE (W / 8)
#define LEVELS 16
#define MAX_V 400
#define MAX_T 800

typedef struct model {
    stp_vec3 v[MAX_V];
    uint16_t t[3 * MAX_T];
    int16_t n[3 * MAX_T];
    stp_mesh mesh;
} model;

static stp_fix fx(double v)
{
    return (stp_fix)lround(v * STP_FIX_ONE);
}

static stp_vec3 vec(double x, double y, double z)
{
    stp_vec3 p;
    p.x = fx(x);
    p.y = fx(y);
    p.z = fx(z);
    return p;
}

/* Triangle a, b, c wound counter-clockwise seen from outside, outside
 * being away from point (ox, oy, oz). */
static void add_tri(model *m, uint16_t a, uint16_t b, uint16_t c, double ox, double oy, double oz)
{
    const stp_vec3 *p = m->v;
    double ux = (double)(p[b].x - p[a].x), uy = (double)(p[b].y - p[a].y), uz = (double)(p[b].z - p[a].z);
    double vx = (double)(p[c].x - p[a].x), vy = (double)(p[c].y - p[a].y), vz = (double)(p[c].z - p[a].z);
    double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
    double out = nx * ((double)p[a].x / STP_FIX_ONE - ox) + ny * ((double)p[a].y / STP_FIX_ONE - oy) +
                 nz * ((double)p[a].z / STP_FIX_ONE - oz);
    uint16_t *t = &m->t[3 * m->mesh.triangle_count++];
    t[0] = a;
    t[1] = out >= 0 ? b : c;
    t[2] = out >= 0 ? c : b;
}

static void finish(model *m)
{
    m->mesh.vertices = m->v;
    m->mesh.triangles = m->t;
    m->mesh.normals = m->n;
    m->mesh.bounds = 0;
    assert_int_equal(stp_mesh_prepare_normals(&m->mesh, m->n, NULL), STP_OK);
}

/* major radius 1, minor 0.4, about the y axis: 20 x 12 quads */
static void make_torus(model *m)
{
    const double pi = 3.14159265358979323846;
    int i, j, na = 20, nt = 12;
    memset(m, 0, sizeof *m);
    for (i = 0; i < na; i++)
        for (j = 0; j < nt; j++) {
            double u = 2 * pi * i / na, v = 2 * pi * j / nt;
            m->v[i * nt + j] = vec((1 + 0.4 * cos(v)) * cos(u), 0.4 * sin(v), (1 + 0.4 * cos(v)) * sin(u));
        }
    m->mesh.vertex_count = (uint16_t)(na * nt);
    for (i = 0; i < na; i++)
        for (j = 0; j < nt; j++) {
            uint16_t a = (uint16_t)(i * nt + j), b = (uint16_t)(((i + 1) % na) * nt + j);
            uint16_t c = (uint16_t)(((i + 1) % na) * nt + (j + 1) % nt), d = (uint16_t)(i * nt + (j + 1) % nt);
            double u = 2 * pi * (i + 0.5) / na; /* the tube's centre near the quad */
            add_tri(m, a, b, c, cos(u), 0, sin(u));
            add_tri(m, a, c, d, cos(u), 0, sin(u));
        }
    finish(m);
}

static void make_tetra(model *m)
{
    memset(m, 0, sizeof *m);
    m->v[0] = vec(1, 1, 1);
    m->v[1] = vec(1, -1, -1);
    m->v[2] = vec(-1, 1, -1);
    m->v[3] = vec(-1, -1, 1);
    m->mesh.vertex_count = 4;
    add_tri(m, 0, 1, 2, 0, 0, 0);
    add_tri(m, 0, 1, 3, 0, 0, 0);
    add_tri(m, 0, 2, 3, 0, 0, 0);
    add_tri(m, 1, 2, 3, 0, 0, 0);
    finish(m);
}

/* radius 1.3: 14 around, 9 rings and two poles */
static void make_sphere(model *m)
{
    const double pi = 3.14159265358979323846;
    int i, j, na = 14, nr = 9;
    memset(m, 0, sizeof *m);
    m->v[0] = vec(0, 1.3, 0);
    m->v[1] = vec(0, -1.3, 0);
    for (j = 0; j < nr; j++)
        for (i = 0; i < na; i++) {
            double th = pi * (j + 1) / (nr + 1), ph = 2 * pi * i / na;
            m->v[2 + j * na + i] = vec(1.3 * sin(th) * cos(ph), 1.3 * cos(th), 1.3 * sin(th) * sin(ph));
        }
    m->mesh.vertex_count = (uint16_t)(2 + na * nr);
    for (i = 0; i < na; i++) {
        uint16_t a = (uint16_t)(2 + i), b = (uint16_t)(2 + (i + 1) % na);
        add_tri(m, 0, a, b, 0, 0, 0);
        a = (uint16_t)(2 + (nr - 1) * na + i);
        b = (uint16_t)(2 + (nr - 1) * na + (i + 1) % na);
        add_tri(m, 1, a, b, 0, 0, 0);
    }
    for (j = 0; j + 1 < nr; j++)
        for (i = 0; i < na; i++) {
            uint16_t a = (uint16_t)(2 + j * na + i), b = (uint16_t)(2 + j * na + (i + 1) % na);
            uint16_t c = (uint16_t)(2 + (j + 1) * na + (i + 1) % na), d = (uint16_t)(2 + (j + 1) * na + i);
            add_tri(m, a, b, c, 0, 0, 0);
            add_tri(m, a, c, d, 0, 0, 0);
        }
    finish(m);
}

/* The scene both paths draw. */
typedef struct scene {
    stp_view view;
    stp_direct_view dview;
    stp_direct_light light;
    stp_direct_model pose;
    uint8_t cell[16];
    stp_cell full_cell;
} scene;

static void scene_make(scene *s, uint16_t yaw, uint16_t pitch)
{
    stp_fix half, focal;
    memset(s, 0, sizeof *s);
    s->view.from = vec(0, 1.8, -3.8);
    s->view.at = vec(0, 0, 0);
    s->view.up = vec(0, 1, 0);
    s->view.fov_degrees = fx(40);
    s->view.hither = fx(0.1);
    s->view.projection = STP_PERSPECTIVE;
    /* the full renderer's focal length (view.c) */
    half = s->view.fov_degrees / 2;
    focal = (stp_fix)(((int64_t)H * stp_fix_cos_deg(half) * (STP_FIX_ONE / 2)) / stp_fix_sin_deg(half));
    assert_int_equal(stp_direct_view_look(&s->dview, s->view.from, s->view.at, s->view.up, focal, s->view.hither, W, H),
                     STP_OK);
    s->light.position = vec(-4, 6, -5);
    s->light.power = fx(9);
    s->light.brightness = fx(1);
    s->light.background = fx(0.2);
    s->light.attenuation_c = fx(1);
    s->light.reflectivity = fx(0.8);
    stp_direct_model_turn(&s->pose, yaw, pitch, fx(1), vec(0, 0, 0));
    assert_int_equal(stp_cell_bayer(&s->full_cell, 4), 0);
    memcpy(s->cell, s->full_cell.thresholds, 16);
}

/* The full renderer's transform of the pose: m = rot scale in stp_fix. */
static stp_transform pose_transform(const stp_direct_model *p)
{
    stp_transform t;
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++)
            t.m[i][j] = (stp_fix)(((int64_t)p->rot[i][j] * 4 * p->scale) >> 16);
    t.t = p->translate;
    return t;
}

typedef struct full {
    stp_renderer_storage storage;
    stp_instr df[8 * MAX_T];
    stp_mesh_vertex scratch[MAX_V];
    uint8_t frame[H * STRIDE];
    stp_renderer *r;
} full;

static int copy_flush(stp_port *port, uint32_t y0, uint32_t rows, const uint8_t *px, size_t stride)
{
    full *f = port->user;
    memcpy(f->frame + (size_t)y0 * STRIDE, px, rows * stride);
    return 0;
}

static void full_setup(full *f, const scene *s, const model *m)
{
    stp_lighting l;
    stp_material mat;
    stp_transform t = pose_transform(&s->pose);
    f->r = stp_renderer_create(&f->storage, sizeof f->storage, f->df, 8 * MAX_T, W, H);
    assert_non_null(f->r);
    assert_int_equal(stp_renderer_set_view(f->r, &s->view), STP_OK);
    stp_lighting_default(&l);
    l.brightness = s->light.brightness;
    l.background = s->light.background;
    l.attenuation_c = s->light.attenuation_c;
    l.count = 1;
    l.lights[0].position = s->light.position;
    l.lights[0].power = s->light.power;
    assert_int_equal(stp_renderer_set_lighting(f->r, &l), STP_OK);
    stp_material_default(&mat);
    mat.reflectivity = s->light.reflectivity;
    mat.specular = 0;
    assert_int_equal(stp_renderer_set_object_shade(f->r, &mat), STP_OK);
    assert_int_equal(stp_renderer_set_shading(f->r, 1), STP_OK);
    assert_int_equal(stp_renderer_set_levels(f->r, LEVELS), STP_OK);
    assert_int_equal(stp_renderer_set_backface_removal(f->r, 1), STP_OK);
    assert_int_equal(stp_segment_create(f->r, 1), STP_OK);
    assert_int_equal(stp_renderer_set_transform(f->r, &t), STP_OK);
    (void)m;
}

static void full_render_hidden(full *f, const scene *s, const model *m, stp_hidden hidden)
{
    stp_port port;
    stp_output out;
    stp_frame_memory mem;
    static uint8_t band[H * STRIDE];
    static uint16_t zbuf[W * H];
    full_setup(f, s, m);
    assert_int_equal(stp_renderer_mesh(f->r, &m->mesh, f->scratch, MAX_V), STP_OK);
    assert_int_equal(stp_segment_close(f->r), STP_OK);
    memset(&port, 0, sizeof port);
    port.width = W;
    port.height = H;
    port.format = STP_PIXEL_MONO1;
    port.flush = copy_flush;
    port.user = f;
    stp_output_default(&out);
    out.hidden = hidden;
    out.cell = &s->full_cell;
    memset(&mem, 0, sizeof mem);
    mem.band = band;
    mem.band_size = sizeof band;
    mem.band_rows = H;
    mem.zbuf = zbuf;
    mem.zbuf_count = W * H;
    assert_int_equal(stp_renderer_render(f->r, &port, &out, &mem), STP_OK);
}

/* The renderer's frame in mesh order (direct drawing's: no hidden-surface
 * removal but the back faces') */
static void full_render(full *f, const scene *s, const model *m)
{
    full_render_hidden(f, s, m, STP_HIDDEN_NONE);
}

/* The style index the full renderer gives triangle t alone (0: removed). */
static int full_style(full *f, const scene *s, const model *m, uint16_t t)
{
    stp_mesh one = m->mesh;
    stp_fix shade;
    full_setup(f, s, m);
    one.triangles = m->mesh.triangles + 3 * t;
    one.normals = m->mesh.normals + 3 * t;
    one.triangle_count = 1;
    assert_int_equal(stp_renderer_mesh(f->r, &one, f->scratch, MAX_V), STP_OK);
    shade = stp_renderer_last_shade(f->r);
    return shade < 0 ? 0 : stp_intensity_index(shade, LEVELS);
}

static int bit_at(const uint8_t *frame, int x, int y)
{
    return (frame[y * STRIDE + x / 8] >> (7 - x % 8)) & 1;
}

/* Distance in pixels from pixel (x, y)'s centre to segment a - b (Q4). */
static double seg_dist(int x, int y, const stp_direct_point *a, const stp_direct_point *b)
{
    double px = x + 0.5, py = y + 0.5, ax = a->dx / 16.0, ay = a->dy / 16.0, bx = b->dx / 16.0, by = b->dy / 16.0;
    double vx = bx - ax, vy = by - ay, l2 = vx * vx + vy * vy, u = l2 > 0 ? ((px - ax) * vx + (py - ay) * vy) / l2 : 0;
    u = u < 0 ? 0 : (u > 1 ? 1 : u);
    return hypot(px - ax - u * vx, py - ay - u * vy);
}

/* Whether pixel (x, y)'s centre lies in triangle p (device Q4 edge
 * functions, inclusive). */
static int inside(int x, int y, const stp_direct_point *const p[3])
{
    int64_t cx = 16 * x + 8, cy = 16 * y + 8, e[3];
    int i;
    for (i = 0; i < 3; i++) {
        const stp_direct_point *a = p[i], *b = p[(i + 1) % 3];
        e[i] = (int64_t)(b->dx - a->dx) * (cy - a->dy) - (int64_t)(b->dy - a->dy) * (cx - a->dx);
    }
    return (e[0] <= 0 && e[1] <= 0 && e[2] <= 0) || (e[0] >= 0 && e[1] >= 0 && e[2] >= 0);
}

typedef struct work {
    model m;
    full f;
    stp_direct_point pts[MAX_V];
    uint16_t faces[MAX_T];
    uint8_t frame[H * STRIDE];
    int style[MAX_T];
} work;

/* Compare the two paths for one model and pose; returns the differing
 * pixels. */
static int compare(work *w, const char *name, uint16_t yaw, uint16_t pitch)
{
    scene s;
    stp_direct_frame fr;
    stp_direct_shading sh;
    stp_direct_lit lit;
    ref_lighting rl;
    ref_material rm;
    int x, y, diff = 0, edge = 0, style = 0, front = 0, level_diff = 0;
    uint16_t t;
    double worst = 0;
    scene_make(&s, yaw, pitch);
    assert_int_equal(stp_direct_frame_project(&fr, &w->m.mesh, &s.pose, &s.dview, &s.light, LEVELS, s.cell, w->pts,
                                              MAX_V, w->faces, MAX_T),
                     STP_OK);
    assert_int_equal(stp_direct_draw_band(&fr, w->frame, STRIDE, 0, H), STP_OK);
    full_render(&w->f, &s, &w->m);
    /* shades: the lean path's per face against the double reference */
    memset(&sh, 0, sizeof sh);
    assert_true(stp_direct_light_prepare(&lit, &s.dview, &s.light));
    stp_direct_shading_prepare(&sh, &lit, &s.dview, &s.pose);
    memset(&rl, 0, sizeof rl);
    rl.brightness = 1;
    rl.background = 0.2;
    rl.c = 1;
    rl.count = 1;
    rl.lights[0].position = ref_v3(-4, 6, -5);
    rl.lights[0].power = 9;
    memset(&rm, 0, sizeof rm);
    rm.reflectivity = 0.8;
    rm.refraction = 10;
    rm.gloss = 10;
    for (t = 0; t < w->m.mesh.triangle_count; t++) {
        const uint16_t *k = &w->m.mesh.triangles[3 * t];
        const stp_direct_point *p[3];
        int i, j, full_index = full_style(&w->f, &s, &w->m, t), lean_index;
        w->style[t] = full_index;
        if (w->faces[t] == 0)
            continue;
        front++;
        p[0] = &w->pts[k[0]];
        p[1] = &w->pts[k[1]];
        p[2] = &w->pts[k[2]];
        /* the shade: view-space double geometry of the same pose */
        {
            const int16_t *n = &w->m.mesh.normals[3 * t];
            double rot[3][3], nn[3], c[3] = {0, 0, 0}, shade_ref, shade;
            ref_vec3 nw, cw;
            for (i = 0; i < 3; i++)
                for (j = 0; j < 3; j++)
                    rot[i][j] = s.pose.rot[i][j] / 16384.0;
            for (i = 0; i < 3; i++) {
                nn[i] = 0;
                for (j = 0; j < 3; j++) {
                    const stp_vec3 *v = &w->m.v[k[j]];
                    nn[i] += rot[i][j] * n[j] / 16384.0;
                    c[i] += (rot[i][0] * v->x + rot[i][1] * v->y + rot[i][2] * v->z) / STP_FIX_ONE / 3;
                }
            }
            nw = ref_v3(nn[0], nn[1], nn[2]);
            cw = ref_v3(c[0], c[1], c[2]);
            shade_ref = ref_shade_point(&rl, &rm, nw, cw, ref_v3(0, 1.8, -3.8), 0, ref_v3(0, 0, 0));
            shade = (double)stp_direct_face_shade(&sh, n, p) / STP_FIX_ONE;
            if (fabs(shade - shade_ref) > worst)
                worst = fabs(shade - shade_ref);
            if (fabs(shade - shade_ref) > 1.0 / 30)
                printf("face %u: shade %f, reference %f\n", t, shade, shade_ref);
            assert_true(fabs(shade - shade_ref) <= 1.0 / 30);
            lean_index = ref_intensity_index(shade, LEVELS);
        }
        if (full_index != lean_index)
            level_diff++;
        assert_int_equal(w->faces[t] & 0xFF,
                         (uint16_t)(((lean_index - 1) * 255 + (LEVELS - 1) / 2) / (LEVELS - 1)));
    }
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            int owner = -1, near = 0;
            if (bit_at(w->frame, x, y) == bit_at(w->f.frame, x, y))
                continue;
            diff++;
            for (t = 0; t < w->m.mesh.triangle_count; t++) {
                const uint16_t *k = &w->m.mesh.triangles[3 * t];
                const stp_direct_point *p[3];
                int i;
                if (w->faces[t] == 0 && w->style[t] == 0)
                    continue;
                p[0] = &w->pts[k[0]];
                p[1] = &w->pts[k[1]];
                p[2] = &w->pts[k[2]];
                for (i = 0; i < 3; i++)
                    if (seg_dist(x, y, p[i], p[(i + 1) % 3]) < 1.0)
                        near = 1;
                if (inside(x, y, p))
                    owner = t;
            }
            if (near) {
                edge++;
            } else {
                /* inside one face both paths draw: its styles differ */
                assert_true(owner >= 0);
                assert_true(w->faces[owner] != 0);
                assert_int_not_equal(w->faces[owner] & 0xFF,
                                     (uint16_t)(((w->style[owner] - 1) * 255 + (LEVELS - 1) / 2) / (LEVELS - 1)));
                style++;
            }
        }
    printf("%-6s yaw %5u pitch %5u: %d front faces (%d styles differ), worst shade error %.5f, "
           "%d pixels differ (%d at edges, %d in faces whose style differs)\n",
           name, yaw, pitch, front, level_diff, worst, diff, edge, style);
    return diff;
}

static void run_model(void (*make)(model *), const char *name, int max_diff)
{
    work *w = calloc(1, sizeof *w);
    static const uint16_t angles[][2] = {{0, 0}, {3000, 2000}, {11000, 60000}, {25000, 9000}, {40000, 30000}, {52000, 47000}};
    size_t a;
    assert_non_null(w);
    make(&w->m);
    for (a = 0; a < sizeof angles / sizeof angles[0]; a++)
        assert_true(compare(w, name, angles[a][0], angles[a][1]) <= max_diff);
    free(w);
}

/* The bound of differing pixels a frame: 0 (the faces an edge cuts
 * clipped as the renderer clips them: without that the tetrahedron's
 * frames differ in up to 2 pixels); the compact form's own bounds */
#if STP_DIRECT_COMPACT
#define INSIDE_BOUND(compact) (compact)
#define EDGE_BOUND(compact) (compact)
#else
#define INSIDE_BOUND(compact) 0
#define EDGE_BOUND(compact) 0
#endif

static void test_torus(void **state)
{
    (void)state;
    run_model(make_torus, "torus", INSIDE_BOUND(30));
}

static void test_tetra(void **state)
{
    (void)state;
    run_model(make_tetra, "tetra", EDGE_BOUND(15));
}

static void test_sphere(void **state)
{
    (void)state;
    run_model(make_sphere, "sphere", INSIDE_BOUND(25));
}

/* A convex model (the sphere) drawn by direct drawing equals the
 * renderer's frame with the Z buffer as well: back faces removed, its
 * front faces do not overlap, so mesh order and depth agree */
static void test_sphere_zbuffer(void **state)
{
    work *w = calloc(1, sizeof *w);
    static const uint16_t angles[][2] = {{0, 0}, {3000, 2000}, {11000, 60000}, {25000, 9000}, {40000, 30000}, {52000, 47000}};
    size_t a;
    (void)state;
    assert_non_null(w);
    make_sphere(&w->m);
    for (a = 0; a < sizeof angles / sizeof angles[0]; a++) {
        scene s;
        stp_direct_frame fr;
        int x, y, diff = 0;
        scene_make(&s, angles[a][0], angles[a][1]);
        assert_int_equal(stp_direct_frame_project(&fr, &w->m.mesh, &s.pose, &s.dview, &s.light, LEVELS, s.cell,
                                                  w->pts, MAX_V, w->faces, MAX_T),
                         STP_OK);
        assert_int_equal(stp_direct_draw_band(&fr, w->frame, STRIDE, 0, H), STP_OK);
        full_render_hidden(&w->f, &s, &w->m, STP_HIDDEN_ZBUFFER);
        for (y = 0; y < H; y++)
            for (x = 0; x < W; x++)
                diff += bit_at(w->frame, x, y) != bit_at(w->f.frame, x, y);
        printf("sphere yaw %5u pitch %5u against the Z buffer: %d pixels differ\n", angles[a][0], angles[a][1],
               diff);
        assert_true(diff <= INSIDE_BOUND(25));
    }
    free(w);
}

/* Bands of 1, 3, 8 and 64 rows give the whole frame exactly. */
/* Where the bands and pages tests place the model: at the centre, across
 * the picture's right edge, and (not in the compact form, which refuses
 * it) so near the eye that the near plane cuts it: faces clipped
 * (STP_DIRECT_FACE_CLIPPED) there, drawn by the clipped path */
#define PLACES (STP_DIRECT_COMPACT ? 2 : 3)
static void place_model(scene *s, int place)
{
    static const double at[3][3] = {{0, 0, 0}, {2.1, 0, 0}, {0, 1.44, -3.04}};
    s->pose.translate = vec(at[place][0], at[place][1], at[place][2]);
}

/* fr's clipped faces as expected of place */
static void clipped_as_placed(const stp_direct_frame *fr, int place)
{
#if STP_DIRECT_COMPACT
    (void)fr;
    (void)place;
#else
    if (place == 0)
        assert_int_equal(fr->clipped, 0);
    else
        assert_true(fr->clipped > 0);
#endif
}

static void bands_match(work *w, int place)
{
    static const uint16_t heights[] = {1, 3, 8, 64};
    uint8_t band[H * STRIDE];
    scene s;
    stp_direct_frame fr;
    size_t i;
    int lit = 0;
    scene_make(&s, 7000, 5000);
    place_model(&s, place);
    assert_int_equal(stp_direct_frame_project(&fr, &w->m.mesh, &s.pose, &s.dview, &s.light, LEVELS, s.cell, w->pts,
                                              MAX_V, w->faces, MAX_T),
                     STP_OK);
    clipped_as_placed(&fr, place);
    assert_int_equal(stp_direct_draw_band(&fr, w->frame, STRIDE, 0, H), STP_OK);
    for (i = 0; i < sizeof w->frame; i++)
        lit += w->frame[i] != 0;
    printf("bands: %d of %d frame bytes lit\n", lit, (int)sizeof w->frame);
    if (getenv("DIRECT_PBM")) { FILE *o = fopen(getenv("DIRECT_PBM"), "wb"); fprintf(o, "P4\n%d %d\n", W, H); fwrite(w->frame, 1, sizeof w->frame, o); fclose(o); }
    assert_true(lit > 100);
    for (i = 0; i < sizeof heights / sizeof heights[0]; i++) {
        uint16_t y0;
        for (y0 = 0; y0 < H; y0 = (uint16_t)(y0 + heights[i])) {
            uint16_t rows = (uint16_t)(y0 + heights[i] > H ? H - y0 : heights[i]);
            memset(band, 0xA5, sizeof band);
            assert_int_equal(stp_direct_draw_band(&fr, band, STRIDE, y0, rows), STP_OK);
            assert_memory_equal(band, w->frame + (size_t)y0 * STRIDE, (size_t)rows * STRIDE);
        }
    }
}

static void test_bands(void **state)
{
    work *w = calloc(1, sizeof *w);
    int place;
    (void)state;
    assert_non_null(w);
    make_torus(&w->m);
    for (place = 0; place < PLACES; place++)
        bands_match(w, place);
    free(w);
}

/* The drive value of every drawn face at levels 2..255 (a multiply by a
 * per-frame reciprocal in direct.c): output.c's division,
 * floor(((index - 1) 255 + (levels - 1) / 2) / (levels - 1)), with the
 * index from the face's shade (stp_direct_face_shade) as
 * stp_intensity_index forms it. */
static void test_levels(void **state)
{
    work *w = calloc(1, sizeof *w);
    stp_direct_shading sh;
    stp_direct_lit lit;
    scene s;
    stp_direct_frame fr;
    int levels, checked = 0;
    (void)state;
    assert_non_null(w);
    make_sphere(&w->m);
    scene_make(&s, 7000, 5000);
    assert_true(stp_direct_light_prepare(&lit, &s.dview, &s.light));
    stp_direct_shading_prepare(&sh, &lit, &s.dview, &s.pose);
    for (levels = 2; levels <= 255; levels++) {
        uint16_t t;
        assert_int_equal(stp_direct_frame_project(&fr, &w->m.mesh, &s.pose, &s.dview, &s.light, levels, s.cell,
                                                  w->pts, MAX_V, w->faces, MAX_T),
                         STP_OK);
        for (t = 0; t < w->m.mesh.triangle_count; t++) {
            const uint16_t *k = &w->m.mesh.triangles[3 * t];
            const stp_direct_point *p[3];
            int index;
            if (w->faces[t] == 0)
                continue;
            p[0] = &w->pts[k[0]];
            p[1] = &w->pts[k[1]];
            p[2] = &w->pts[k[2]];
            index = stp_intensity_index(stp_direct_face_shade(&sh, &w->m.mesh.normals[3 * t], p), levels);
            assert_int_equal(w->faces[t], 256 + ((index - 1) * 255 + (levels - 1) / 2) / (levels - 1));
            checked++;
        }
    }
    assert_true(checked > 254 * 50);
    free(w);
}

/* A cube of side 1.6 about the origin: 12 triangles. */
static void make_cube(model *m)
{
    static const uint8_t quads[6][4] = {{0, 1, 3, 2}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                        {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 3, 7, 5}};
    int i;
    memset(m, 0, sizeof *m);
    for (i = 0; i < 8; i++)
        m->v[i] = vec(i & 1 ? 0.8 : -0.8, i & 2 ? 0.8 : -0.8, i & 4 ? 0.8 : -0.8);
    m->mesh.vertex_count = 8;
    for (i = 0; i < 6; i++) {
        add_tri(m, quads[i][0], quads[i][1], quads[i][2], 0, 0, 0);
        add_tri(m, quads[i][0], quads[i][2], quads[i][3], 0, 0, 0);
    }
    finish(m);
}

/* Page layout (STP_BAND_PAGES): every band of 8, 16, 24 and 64 rows, at
 * strides W and W + 5, holds the row-major frame transposed into pages,
 * pixel for pixel (bit y mod 8 of byte (y / 8) stride + x), for the torus
 * and a cube in several poses; a last band shorter than its page leaves
 * the page's lower bits 0. */
static void pages_match(work *w, uint16_t yaw, uint16_t pitch, int place)
{
    static const uint16_t heights[] = {8, 16, 24, 64};
    static uint8_t pages[(H / 8) * (W + 5)];
    size_t strides[2] = {W, W + 5};
    scene s;
    stp_direct_frame fr;
    size_t i, k;
    int lit = 0;
    scene_make(&s, yaw, pitch);
    place_model(&s, place);
    assert_int_equal(stp_direct_frame_project(&fr, &w->m.mesh, &s.pose, &s.dview, &s.light, LEVELS, s.cell, w->pts,
                                              MAX_V, w->faces, MAX_T),
                     STP_OK);
    assert_int_equal(stp_direct_draw_band(&fr, w->frame, STRIDE, 0, H), STP_OK);
    fr.layout = STP_BAND_PAGES;
    for (k = 0; k < 2; k++)
        for (i = 0; i < sizeof heights / sizeof heights[0]; i++) {
            uint16_t y0;
            for (y0 = 0; y0 < H; y0 = (uint16_t)(y0 + heights[i])) {
                uint16_t rows = (uint16_t)(y0 + heights[i] > H ? H - y0 : heights[i]);
                int x, y;
                memset(pages, 0xA5, sizeof pages);
                assert_int_equal(stp_direct_draw_band(&fr, pages, strides[k], y0, rows), STP_OK);
                for (y = 0; y < rows; y++)
                    for (x = 0; x < W; x++) {
                        int got = (pages[(size_t)(y / 8) * strides[k] + (size_t)x] >> (y % 8)) & 1;
                        assert_int_equal(got, bit_at(w->frame, x, y0 + y));
                        lit += got;
                    }
            }
        }
    /* a 5-row band: the page's rows 5..7 stay 0 */
    memset(pages, 0xFF, sizeof pages);
    assert_int_equal(stp_direct_draw_band(&fr, pages, W, 0, 5), STP_OK);
    for (i = 0; i < W; i++)
        assert_int_equal(pages[i] & 0xE0, 0);
    assert_true(lit > 100);
}

static void test_pages(void **state)
{
    work *w = calloc(1, sizeof *w);
    static const uint16_t angles[][2] = {{0, 0}, {3000, 2000}, {11000, 60000}, {40000, 30000}};
    size_t a;
    (void)state;
    assert_non_null(w);
    int place;
    make_torus(&w->m);
    for (place = 0; place < PLACES; place++)
        for (a = 0; a < sizeof angles / sizeof angles[0]; a++)
            pages_match(w, angles[a][0], angles[a][1], place);
    make_cube(&w->m);
    for (a = 0; a < sizeof angles / sizeof angles[0]; a++)
        pages_match(w, angles[a][0], angles[a][1], 0);
    free(w);
}

static void test_sine(void **state)
{
    uint32_t a;
    (void)state;
    for (a = 0; a < 65536; a += 7) {
        double ref = 16384 * sin(2 * 3.14159265358979323846 * a / 65536);
        assert_true(fabs(stp_direct_sin((uint16_t)a) - ref) <= 2.0);
    }
}

/* stp_direct_mesh_normals, the deprecated name of stp_mesh_prepare_normals:
 * the same normals (byte for byte: the models' own, made by
 * stp_mesh_prepare_normals in finish()), the same errors; an edge of 2^24
 * raw, beyond the former 32-bit copy's range, is taken. */
static void test_normals(void **state)
{
    model *m = calloc(1, sizeof *m);
    int16_t lean[3 * MAX_T];
    void (*makers[])(model *) = {make_torus, make_sphere, make_tetra};
    size_t k;
    (void)state;
    assert_non_null(m);
    for (k = 0; k < 3; k++) {
        makers[k](m);
        assert_int_equal(stp_direct_mesh_normals(&m->mesh, lean), STP_OK);
        assert_memory_equal(lean, m->n, sizeof lean[0] * 3u * m->mesh.triangle_count);
    }
    m->v[3] = m->v[0]; /* the tetrahedron's triangles through 0 and 3 collapse */
    assert_int_equal(stp_direct_mesh_normals(&m->mesh, lean), STP_ERR_DEGENERATE);
    make_tetra(m);
    m->t[4] = 9;
    assert_int_equal(stp_direct_mesh_normals(&m->mesh, lean), STP_ERR_ARG);
    assert_int_equal(stp_direct_mesh_normals(NULL, lean), STP_ERR_ARG);
    assert_int_equal(stp_direct_mesh_normals(&m->mesh, NULL), STP_ERR_ARG);
    make_tetra(m);
    m->v[1].x = (stp_fix)1 << 23; /* an edge of 2^24 raw */
    m->v[0].x = -((stp_fix)1 << 23);
    assert_int_equal(stp_direct_mesh_normals(&m->mesh, lean), STP_OK);
    free(m);
}

static void test_bad_arguments(void **state)
{
    work *w = calloc(1, sizeof *w);
    scene s;
    stp_direct_frame fr;
    stp_direct_model far;
    uint8_t band[STRIDE];
    int i;
    (void)state;
    assert_non_null(w);
    make_tetra(&w->m);
    scene_make(&s, 0, 0);
    assert_int_equal(stp_direct_frame_project(NULL, &w->m.mesh, &s.pose, &s.dview, &s.light, LEVELS, s.cell, w->pts,
                                              MAX_V, w->faces, MAX_T),
                     STP_ERR_ARG);
    assert_int_equal(stp_direct_frame_project(&fr, &w->m.mesh, &s.pose, &s.dview, &s.light, 1, s.cell, w->pts, MAX_V,
                                              w->faces, MAX_T),
                     STP_ERR_ARG);
    assert_int_equal(stp_direct_frame_project(&fr, &w->m.mesh, &s.pose, &s.dview, &s.light, LEVELS, s.cell, w->pts, 3,
                                              w->faces, MAX_T),
                     STP_ERR_ARG);
    assert_int_equal(stp_direct_frame_project(&fr, &w->m.mesh, &s.pose, &s.dview, &s.light, LEVELS, s.cell, w->pts,
                                              MAX_V, w->faces, 3),
                     STP_ERR_ARG);
    /* an index beyond the vertices, at each corner of a triangle and in
     * the first and the last triangle */
    for (i = 0; i < 4; i++) {
        static const int at[4] = {0, 4, 5, 11};
        make_tetra(&w->m);
        w->m.t[at[i]] = 4;
        assert_int_equal(stp_direct_frame_project(&fr, &w->m.mesh, &s.pose, &s.dview, &s.light, LEVELS, s.cell,
                                                  w->pts, MAX_V, w->faces, MAX_T),
                         STP_ERR_ARG);
    }
    make_tetra(&w->m);
    far = s.pose;
    far.scale = 2 * STP_FIX_ONE;
    assert_int_equal(stp_direct_frame_project(&fr, &w->m.mesh, &far, &s.dview, &s.light, LEVELS, s.cell, w->pts,
                                              MAX_V, w->faces, MAX_T),
                     STP_ERR_ARG);
    /* behind the eye, then beside the device's range: refused by the
     * compact form, clipped away (nothing drawn) by the default form */
    far = s.pose;
    far.translate = vec(0, 5, -12);
    for (i = 0; i < 2; i++) {
        int status = stp_direct_frame_project(&fr, &w->m.mesh, &far, &s.dview, &s.light, LEVELS, s.cell, w->pts,
                                              MAX_V, w->faces, MAX_T);
#if STP_DIRECT_COMPACT
        assert_int_equal(status, STP_ERR_RANGE);
#else
        int y, b;
        assert_int_equal(status, STP_OK);
        assert_int_equal(fr.clipped, 0);
        for (y = 0; y < H; y++) {
            memset(band, 0xFF, sizeof band);
            assert_int_equal(stp_direct_draw_band(&fr, band, STRIDE, (uint16_t)y, 1), STP_OK);
            for (b = 0; b < STRIDE; b++)
                assert_int_equal(band[b], 0);
        }
#endif
        far.translate = vec(40, 0, 0);
    }
    /* the eye 5 units above -2^31 raw looking down z: a model 3 units in
     * front is drawn; one near +2^31, whose difference from the eye wraps
     * modulo 2^32 to 10 units in front, is refused (not drawn there) */
    {
        scene wrap = s;
        stp_vec3 from = {0, 0, INT32_MIN + 5 * STP_FIX_ONE}, at = {0, 0, INT32_MIN}, up = {0, STP_FIX_ONE, 0};
        assert_int_equal(stp_direct_view_look(&wrap.dview, from, at, up, fx(80), fx(0.1), W, H), STP_OK);
        wrap.light.position = from;
        wrap.light.position.x = -4 * STP_FIX_ONE;
        wrap.light.position.z += 2 * STP_FIX_ONE;
        far = s.pose;
        far.translate = from;
        far.translate.z -= 3 * STP_FIX_ONE;
        assert_int_equal(stp_direct_frame_project(&fr, &w->m.mesh, &far, &wrap.dview, &wrap.light, LEVELS, s.cell,
                                                  w->pts, MAX_V, w->faces, MAX_T),
                         STP_OK);
        far.translate.z = INT32_MAX - 5 * STP_FIX_ONE + 1; /* from.z - 10 units + 2^32 */
        assert_int_equal(stp_direct_frame_project(&fr, &w->m.mesh, &far, &wrap.dview, &wrap.light, LEVELS, s.cell,
                                                  w->pts, MAX_V, w->faces, MAX_T),
                         STP_ERR_RANGE);
    }
    assert_int_equal(stp_direct_view_look(&s.dview, s.view.from, s.view.from, s.view.up, fx(80), fx(0.1), W, H),
                     STP_ERR_VIEW);
    assert_int_equal(stp_direct_view_look(&s.dview, vec(0, 5, 0), vec(0, 0, 0), vec(0, 1, 0), fx(80), fx(0.1), W, H),
                     STP_ERR_VIEW);
    assert_int_equal(stp_direct_view_look(&s.dview, s.view.from, s.view.at, s.view.up, fx(80), fx(0.1), 513, H),
                     STP_ERR_ARG);
    scene_make(&s, 0, 0);
    assert_int_equal(stp_direct_frame_project(&fr, &w->m.mesh, &s.pose, &s.dview, &s.light, LEVELS, s.cell, w->pts,
                                              MAX_V, w->faces, MAX_T),
                     STP_OK);
    assert_int_equal(stp_direct_draw_band(&fr, band, STRIDE - 1, 0, 1), STP_ERR_ARG);
    assert_int_equal(stp_direct_draw_band(&fr, band, STRIDE, 0, 0), STP_ERR_ARG);
    assert_int_equal(stp_direct_draw_band(&fr, band, STRIDE, H - 1, 2), STP_ERR_ARG);
    assert_int_equal(stp_direct_draw_band(&fr, NULL, STRIDE, 0, 1), STP_ERR_ARG);
    fr.layout = STP_BAND_PAGES; /* stride below the width, y0 within a page */
    assert_int_equal(stp_direct_draw_band(&fr, w->frame, W - 1, 0, 8), STP_ERR_ARG);
    assert_int_equal(stp_direct_draw_band(&fr, w->frame, W, 4, 8), STP_ERR_ARG);
    fr.layout = 2;
    assert_int_equal(stp_direct_draw_band(&fr, w->frame, W, 0, 8), STP_ERR_ARG);
    free(w);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sine),         cmocka_unit_test(test_tetra), cmocka_unit_test(test_sphere),
        cmocka_unit_test(test_sphere_zbuffer),
        cmocka_unit_test(test_torus),        cmocka_unit_test(test_bands), cmocka_unit_test(test_normals),
        cmocka_unit_test(test_pages),        cmocka_unit_test(test_levels),
        cmocka_unit_test(test_bad_arguments),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
