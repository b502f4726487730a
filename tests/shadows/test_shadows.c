/* SPDX-License-Identifier: MIT */
/*
 * Shadows by a shadow Z buffer per light (docs/model.md section 5; render.h,
 * stp_renderer_set_shadow_map) through the public API.
 *
 * Every scene here is a few quads (a floor, casters) whose picture is also
 * traced in double precision: for each pixel centre, the nearest quad along
 * the eye ray, and for each light whether the segment from that point to
 * the light crosses another quad (and whether the point lies in the light
 * map's pyramid: outside it the renderer documents "lit").  A pixel the
 * trace finds lit by every light must be exactly the pixel of the same
 * scene rendered without any shadow map; a pixel hidden from some lights
 * must be INTENSITY of the shade re-lit without them (docs/model.md section 2,
 * written out here in double).
 *
 * Tolerance: a pixel is only checked when the trace classifies its 8
 * neighbours' centres (one pixel away) like its own, i.e. no shadow, map
 * or polygon border passes within 1 pixel of its centre.  Why 1 pixel: the
 * map stores depth at texel centres (the device's fill rule), so a shadow
 * border moves by up to one texel, which these scenes keep below one pixel
 * on the floor (texel footprints of 0.3-0.6 pixel); device vertices are
 * rounded to 1/16 pixel.  The tests also bound how many pixels that
 * exempts, so a border cannot hide a wrong region.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "stipple/stipple.h"

#define W 48
#define H 48
#define LEVELS 16
#define MAP_MAX 256
#define MAX_QUADS 12
#define PI 3.14159265358979323846

/* ------------------------------------------------------------ scenes */

typedef struct quad {
    double v[4][3];
} quad;

typedef struct scene {
    int perspective;
    double from[3], at[3];
    double fov;         /* perspective */
    int nlights;
    double light[2][3];
    double power[2];
    double background;  /* B; R = 1, no specular, BRIGHT 1, C = 1 */
    int map_res;        /* 0: no map */
    double map_fov, map_near, target[3];
    stp_hidden hidden;
    uint32_t band_rows;
    stp_pixel_format format;
    int smooth;         /* floor (quad 0) entered with stp_renderer_polygon_smooth */
    int colour;         /* colour shading, RGB888 */
    int nquads;
    quad quads[MAX_QUADS];
    int order_reversed; /* enter the quads last to first */
} scene;

static quad rect_z(double x0, double y0, double x1, double y1, double z)
{
    quad q;
    double v[4][3] = {{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}};
    memcpy(q.v, v, sizeof v);
    return q;
}

/* A floor over the whole view at z = 0, a square caster of half side `half`
 * at height h, one light straight above at lz (or at lx, 0, lz), a parallel
 * view from above: world units are pixels (device x = W/2 + x, y = H/2 - y). */
static void base_scene(scene *s, double half, double h, double lx, double lz)
{
    memset(s, 0, sizeof *s);
    s->from[2] = 100;
    s->fov = 60;
    s->nlights = 1;
    s->light[0][0] = lx;
    s->light[0][2] = lz;
    s->power[0] = 10.5; /* floor under a light 20 above: 0.25 + 0.5 */
    s->background = 0.25;
    s->map_res = 128;
    s->map_fov = 120;
    s->map_near = 1;
    s->hidden = STP_HIDDEN_ZBUFFER;
    s->band_rows = H;
    s->format = STP_PIXEL_STYLE8;
    s->quads[s->nquads++] = rect_z(-40, -40, 40, 40, 0);
    if (half > 0)
        s->quads[s->nquads++] = rect_z(-half, -half, half, half, h);
}

/* ------------------------------------------------------------ rendering */

static uint8_t frame_px[W * H * 3];
static size_t frame_stride;

static int flush(stp_port *port, uint32_t y0, uint32_t rows, const uint8_t *px, size_t stride)
{
    uint32_t y;
    (void)port;
    for (y = 0; y < rows; y++)
        memcpy(&frame_px[(y0 + y) * frame_stride], px + y * stride, frame_stride);
    return 0;
}

static stp_fix fx(double v)
{
    return (stp_fix)lround(v * STP_FIX_ONE);
}

static stp_vec3 fx3(const double *v)
{
    stp_vec3 r;
    r.x = fx(v[0]);
    r.y = fx(v[1]);
    r.z = fx(v[2]);
    return r;
}

static stp_renderer_storage storage;
static stp_instr df[512];
static uint16_t maps[2][MAP_MAX * MAP_MAX];

/* Build the renderer for a scene: view, lighting, maps (with_maps), then
 * the quads.  Returns the renderer. */
static stp_renderer *build(const scene *s, int with_maps)
{
    stp_renderer *r = stp_renderer_create(&storage, sizeof storage, df, 512, W, H);
    stp_view v;
    stp_lighting l;
    stp_material m;
    int i, j;
    assert_non_null(r);
    memset(&v, 0, sizeof v);
    v.from = fx3(s->from);
    v.at = fx3(s->at);
    v.up.y = STP_FIX_ONE;
    v.fov_degrees = fx(s->fov);
    v.window_half = fx(H / 2.0);
    v.hither = fx(1);
    v.projection = s->perspective ? STP_PERSPECTIVE : STP_PARALLEL;
    assert_int_equal(stp_renderer_set_view(r, &v), STP_OK);
    assert_int_equal(stp_renderer_set_levels(r, LEVELS), STP_OK);
    stp_lighting_default(&l);
    l.brightness = STP_FIX_ONE;
    l.background = fx(s->background);
    l.attenuation_c = STP_FIX_ONE;
    l.count = s->nlights;
    for (j = 0; j < s->nlights; j++) {
        l.lights[j].position = fx3(s->light[j]);
        l.lights[j].power = fx(s->power[j]);
    }
    assert_int_equal(stp_renderer_set_lighting(r, &l), STP_OK);
    stp_material_default(&m);
    m.specular = 0;
    stp_renderer_set_object_shade(r, &m);
    stp_renderer_set_shading(r, 1);
    if (s->colour)
        assert_int_equal(stp_renderer_set_colour(r, 1), STP_OK);
    if (with_maps && s->map_res > 0) {
        for (j = 0; j < s->nlights; j++) {
            stp_shadow_view sv;
            sv.target = fx3(s->target);
            sv.fov_degrees = fx(s->map_fov);
            sv.near = fx(s->map_near);
            assert_int_equal(stp_renderer_set_shadow_map(r, j, maps[j], MAP_MAX * MAP_MAX, (uint32_t)s->map_res,
                                                (uint32_t)s->map_res, &sv),
                             STP_OK);
        }
    }
    assert_int_equal(stp_segment_create(r, 1), STP_OK);
    for (i = 0; i < s->nquads; i++) {
        const quad *q = &s->quads[s->order_reversed ? s->nquads - 1 - i : i];
        stp_vec3 p[4], n[4];
        int k;
        for (k = 0; k < 4; k++) {
            p[k] = fx3(q->v[k]);
            n[k].x = n[k].y = 0;
            n[k].z = STP_FIX_ONE;
        }
        if (s->smooth && q == &s->quads[0])
            assert_int_equal(stp_renderer_polygon_smooth(r, p, n, 4), STP_OK);
        else
            assert_int_equal(stp_renderer_polygon(r, p, 4), STP_OK);
    }
    assert_int_equal(stp_segment_close(r), STP_OK);
    return r;
}

/* Render the display file into frame_px; returns stp_renderer_render's status. */
static int output(stp_renderer *r, const scene *s)
{
    static uint8_t band[W * H * 3];
    static uint16_t zbuf[W * H];
    static stp_sort_entry sort[MAX_QUADS];
    stp_port port;
    stp_output out;
    stp_frame_memory fm;
    port.width = W;
    port.height = H;
    port.format = s->format;
    port.flush = flush;
    port.user = NULL;
    frame_stride = stp_row_bytes(s->format, W);
    memset(&out, 0, sizeof out);
    out.hidden = s->hidden;
    memset(&fm, 0, sizeof fm);
    fm.band = band;
    fm.setup = 0; /* no per-polygon setups kept between bands */
    fm.setup_count = 0;
    fm.band_size = sizeof band;
    fm.band_rows = s->band_rows;
    fm.zbuf = zbuf;
    fm.zbuf_count = W * H;
    fm.sort = sort;
    fm.sort_count = MAX_QUADS;
    return stp_renderer_render(r, &port, &out, &fm);
}

static void render(const scene *s, int with_maps, uint8_t *out)
{
    stp_renderer *r = build(s, with_maps);
    assert_int_equal(output(r, s), STP_OK);
    memcpy(out, frame_px, frame_stride * H);
}

/* ------------------------------------------------------------ the trace */

typedef struct vec {
    double x, y, z;
} vec;

static vec mk(double x, double y, double z)
{
    vec v;
    v.x = x;
    v.y = y;
    v.z = z;
    return v;
}
static vec sub(vec a, vec b) { return mk(a.x - b.x, a.y - b.y, a.z - b.z); }
static vec add(vec a, vec b) { return mk(a.x + b.x, a.y + b.y, a.z + b.z); }
static vec scale(vec a, double k) { return mk(a.x * k, a.y * k, a.z * k); }
static double dot(vec a, vec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static vec cross(vec a, vec b)
{
    return mk(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static vec unit(vec a) { return scale(a, 1.0 / sqrt(dot(a, a))); }
static vec qv(const quad *q, int k) { return mk(q->v[k][0], q->v[k][1], q->v[k][2]); }

static vec quad_normal(const quad *q)
{
    return unit(cross(sub(qv(q, 1), qv(q, 0)), sub(qv(q, 2), qv(q, 0))));
}

/* Ray o + t d against a convex quad: t > 0 of the hit, or -1. */
static double hit(const quad *q, vec o, vec d)
{
    vec n = quad_normal(q);
    double den = dot(n, d), t;
    vec p;
    int k;
    if (fabs(den) < 1e-12)
        return -1;
    t = dot(n, sub(qv(q, 0), o)) / den;
    if (t <= 1e-9)
        return -1;
    p = add(o, scale(d, t));
    for (k = 0; k < 4; k++) {
        vec e = sub(qv(q, (k + 1) % 4), qv(q, k));
        if (dot(cross(e, sub(p, qv(q, k))), n) < 0)
            return -1;
    }
    return t;
}

/* The camera's basis, as stp_renderer_set_view builds it. */
typedef struct camera {
    vec from, right, up, fwd;
    double focal; /* pixels per unit (parallel) or per x/z (perspective) */
} camera;

static camera make_camera(const scene *s)
{
    camera c;
    c.from = mk(s->from[0], s->from[1], s->from[2]);
    c.fwd = unit(sub(mk(s->at[0], s->at[1], s->at[2]), c.from));
    c.right = unit(cross(c.fwd, mk(0, 1, 0)));
    c.up = cross(c.right, c.fwd);
    c.focal = s->perspective ? (H / 2.0) / tan(s->fov * PI / 360.0) : (H / 2.0) / (H / 2.0);
    return c;
}

/* The eye ray through device point (xs, ys). */
static void eye_ray(const scene *s, const camera *c, double xs, double ys, vec *o, vec *d)
{
    double xv = (xs - W / 2.0) / c->focal, yv = (H / 2.0 - ys) / c->focal;
    if (s->perspective) {
        *o = c->from;
        *d = add(add(scale(c->right, xv), scale(c->up, yv)), c->fwd);
    } else {
        *o = add(add(c->from, scale(c->right, xv)), scale(c->up, yv));
        *d = c->fwd;
    }
}

/* In light j's map pyramid (its frame as stp_renderer_set_shadow_map builds it)? */
static int in_pyramid(const scene *s, const camera *c, int j, vec p)
{
    vec l = mk(s->light[j][0], s->light[j][1], s->light[j][2]);
    vec f = unit(sub(mk(s->target[0], s->target[1], s->target[2]), l));
    vec rt = cross(f, c->up), up;
    vec d = sub(p, l);
    double tn = tan(s->map_fov * PI / 360.0), z;
    if (sqrt(dot(rt, rt)) < 1e-3)
        rt = cross(f, c->fwd);
    rt = unit(rt);
    up = cross(rt, f);
    z = dot(d, f);
    return z >= s->map_near && fabs(dot(d, rt)) < z * tn && fabs(dot(d, up)) < z * tn;
}

/* Classify device point (xs, ys): the quad seen (-1: none), and the lights
 * that do not reach the point (bit j), as the renderer defines them. */
static int classify(const scene *s, const camera *c, double xs, double ys, uint32_t *hidden, vec *point)
{
    vec o, d, p;
    double best = 1e300;
    int i, seen = -1, j;
    eye_ray(s, c, xs, ys, &o, &d);
    for (i = 0; i < s->nquads; i++) {
        double t = hit(&s->quads[i], o, d);
        if (t > 0 && t < best) {
            best = t;
            seen = i;
        }
    }
    *hidden = 0;
    if (seen < 0)
        return -1;
    p = add(o, scale(d, best));
    *point = p;
    for (j = 0; j < s->nlights; j++) {
        vec l = mk(s->light[j][0], s->light[j][1], s->light[j][2]);
        int blocked = 0;
        if (s->map_res <= 0 || !in_pyramid(s, c, j, p))
            continue;
        for (i = 0; i < s->nquads && !blocked; i++) {
            double t;
            if (i == seen)
                continue;
            t = hit(&s->quads[i], p, sub(l, p));
            if (t > 1e-9 && t < 1 - 1e-9)
                blocked = 1;
        }
        if (blocked)
            *hidden |= 1u << j;
    }
    return seen;
}

/* The style of quad `seen` re-lit without the lights in `hidden`: the flat
 * shade at its vertex average, docs/model.md section 2 without the specular term,
 * the normal turned to the eye. */
static int relit_style(const scene *s, const camera *c, int seen, uint32_t hidden)
{
    const quad *q = &s->quads[seen];
    vec centre = mk(0, 0, 0), n = quad_normal(q), e;
    double v = s->background;
    int k, j;
    for (k = 0; k < 4; k++)
        centre = add(centre, scale(qv(q, k), 0.25));
    e = s->perspective ? unit(sub(c->from, centre)) : scale(c->fwd, -1);
    if (dot(n, e) <= 0)
        n = scale(n, -1);
    for (j = 0; j < s->nlights; j++) {
        vec l = sub(mk(s->light[j][0], s->light[j][1], s->light[j][2]), centre);
        double u = sqrt(dot(l, l)), nl = dot(n, unit(l));
        if (nl > 0 && !(hidden & (1u << j)))
            v += s->power[j] * nl / (1 + u);
    }
    if (v > 1)
        v = 1;
    return (int)floor(v * (LEVELS - 1)) + 1;
}

typedef struct result {
    int checked, exempt, hidden_checked, lit_checked;
} result;

/* Check frame `got` (STYLE8) against the trace and the unshadowed render
 * `plain`.  style_check: 1 to compare hidden pixels with relit_style; 0
 * to require only that they are darker than `plain` (smooth).  A pixel
 * within 1 pixel of a border must still be what one of the points within
 * 1 pixel of its centre gets. */
static result check_frame(const scene *s, const uint8_t *got, const uint8_t *plain, int style_check)
{
    camera c = make_camera(s);
    result res = {0, 0, 0, 0};
    int x, y;
    for (y = 0; y < H; y++) {
        for (x = 0; x < W; x++) {
            uint32_t hid, nh;
            vec p, np;
            int seen = classify(s, &c, x + 0.5, y + 0.5, &hid, &p), dx, dy, mixed = 0, allowed = 0;
            for (dy = -1; dy <= 1; dy++)
                for (dx = -1; dx <= 1; dx++) {
                    int ns = classify(s, &c, x + 0.5 + dx, y + 0.5 + dy, &nh, &np);
                    if (ns != seen || nh != hid)
                        mixed = 1;
                    /* near a border the pixel may take what any point
                     * within one pixel of its centre gets */
                    if (got[y * W + x] == plain[y * W + x] ||
                        (nh != 0 && ns >= 0 && (style_check ? got[y * W + x] == relit_style(s, &c, ns, nh)
                                                            : got[y * W + x] < plain[y * W + x])))
                        allowed = 1;
                }
            if (mixed) {
                if (!allowed)
                    fail_msg("pixel (%d, %d) by a border: %d, not what a point within 1 pixel gets", x, y,
                             got[y * W + x]);
                res.exempt++;
                continue;
            }
            res.checked++;
            if (hid == 0) {
                res.lit_checked++;
                if (got[y * W + x] != plain[y * W + x])
                    fail_msg("pixel (%d, %d) lit: %d, without maps %d", x, y, got[y * W + x], plain[y * W + x]);
                /* the re-lighting formula agrees with the renderer's shade */
                if (style_check && seen >= 0)
                    assert_int_equal(relit_style(s, &c, seen, 0), plain[y * W + x]);
            } else {
                res.hidden_checked++;
                if (style_check) {
                    if (got[y * W + x] != relit_style(s, &c, seen, hid))
                        fail_msg("pixel (%d, %d) hidden from %x: %d, expected %d", x, y, (unsigned)hid,
                                 got[y * W + x], relit_style(s, &c, seen, hid));
                } else if (!(got[y * W + x] < plain[y * W + x])) {
                    fail_msg("pixel (%d, %d) hidden: %d, not darker than %d", x, y, got[y * W + x],
                             plain[y * W + x]);
                }
            }
        }
    }
    return res;
}

static void dump(const uint8_t *f)
{
    int x, y;
    for (y = 0; y < H; y++) {
        char line[W + 1];
        for (x = 0; x < W; x++)
            line[x] = f[y * W + x] == 0 ? '.' : "0123456789abcdefg"[f[y * W + x] % 17];
        line[W] = 0;
        print_message("%s\n", line);
    }
}

static uint8_t got[W * H * 3], plain[W * H * 3];

static result run_and_check(const scene *s, int style_check)
{
    result res;
    render(s, 0, plain);
    render(s, 1, got);
    res = check_frame(s, got, plain, style_check);
    if (getenv("STP_SHADOW_DUMP")) {
        dump(got);
        print_message("checked %d (lit %d, hidden %d), exempt %d\n", res.checked, res.lit_checked,
                      res.hidden_checked, res.exempt);
    }
    return res;
}

/* ------------------------------------------------------------ tests */

/* The square over the floor, light straight above, parallel camera: the
 * shadow is the square scaled by lz / (lz - h) = 2 about the light's foot,
 * [-12, 12]^2, its ring around the square's own [-6, 6]^2 at style 4
 * (B R = 0.25), the floor outside it lit (0.75: style 12). */
static void test_square_over_floor(void **state)
{
    scene s;
    result res;
    int x, y, ring = 0;
    (void)state;
    base_scene(&s, 6, 10, 0, 20);
    res = run_and_check(&s, 1);
    /* by hand too: the ring is 4, the square 16, the rest of the floor 12 */
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            double wx = x + 0.5 - W / 2.0, wy = H / 2.0 - y - 0.5;
            double m = fmax(fabs(wx), fabs(wy));
            int v = got[y * W + x];
            if (m < 5.5)
                assert_int_equal(v, 16);
            else if (m > 6.5 && m < 11.5) {
                assert_int_equal(v, 4);
                ring++;
            } else if (m > 12.5)
                assert_int_equal(v, 12);
        }
    assert_int_equal(ring, 22 * 22 - 14 * 14);
    assert_true(res.hidden_checked >= ring);
    /* the pixels left to the 1-pixel tolerance: the rings either side of
     * the square's border (centres at 5.5 and 6.5 from the axis) and of the
     * shadow's (11.5 and 12.5) */
    assert_int_equal(res.exempt, 4 * 11 + 4 * 13 + 4 * 23 + 4 * 25);
}

/* The light at a known angle: from (-10, 0, 20) the shadow is
 * x in [-2, 22], y in [-12, 12]; every hidden pixel has the ambient style. */
static void test_light_at_an_angle(void **state)
{
    scene s;
    result res;
    (void)state;
    base_scene(&s, 6, 10, -10, 20);
    s.power[0] = 12;
    res = run_and_check(&s, 1);
    assert_true(res.hidden_checked > 150);
    assert_true(res.lit_checked > 900);
    assert_int_equal(got[(H / 2) * W + W / 2 + 15], 4); /* (15.5, -0.5): shadow */
    assert_int_equal(got[(H / 2) * W + W / 2 - 8], plain[(H / 2) * W + W / 2 - 8]); /* (-7.5, -0.5) lit */
}

/* The same scene through a perspective camera looking down at an angle:
 * the pixel's view point is recovered from its depth key. */
static void test_perspective_camera(void **state)
{
    scene s;
    result res;
    (void)state;
    base_scene(&s, 6, 10, -10, 20);
    s.power[0] = 12;
    s.perspective = 1;
    s.from[0] = 5;
    s.from[1] = -45;
    s.from[2] = 60;
    s.fov = 50;
    res = run_and_check(&s, 1);
    assert_true(res.hidden_checked > 100);
    assert_true(res.lit_checked > 600);
}

/* Two lights with maps: pixels hidden from one keep the other's term. */
static void test_two_lights(void **state)
{
    scene s;
    result res;
    (void)state;
    if (STP_MAX_LIGHTS < 2)
        skip();
    base_scene(&s, 5, 10, -10, 20);
    s.nlights = 2;
    s.light[1][0] = 10;
    s.light[1][2] = 20;
    s.power[0] = s.power[1] = 8;
    res = run_and_check(&s, 1);
    assert_true(res.hidden_checked > 200);
    /* the square's shadows: x in [0, 20] from the left light, [-20, 0]
     * from the right one (y in [-10, 10]); each keeps the other light's
     * term, 0.25 + 0.306: style 9 (both lights: 0.86, style 13) */
    assert_int_equal(got[(H / 2 + 8) * W + W / 2 + 12], 9);
    assert_int_equal(got[(H / 2 + 8) * W + W / 2 - 13], 9);
    assert_int_equal(got[(H / 2 + 8) * W + W / 2 - 23], 13);
}

/* Stiff: the light inside a closed box.  Everything the light would reach
 * through its map is blocked: the floor inside the map's pyramid keeps the
 * ambient part only, the box's outside faces face away from the light; the
 * floor outside the pyramid is lit (render.h: the map must cover the
 * receivers).  Entry order does not matter. */
static void test_light_inside_caster(void **state)
{
    scene s;
    result res;
    int order, x, y;
    (void)state;
    for (order = 0; order < 2; order++) {
        double b = 3, c[3] = {0, 0, 20};
        base_scene(&s, 0, 0, 0, 20);
        s.map_fov = 60; /* covers |x|, |y| < 20 tan 30 = 11.5 on the floor */
        s.quads[s.nquads++] = rect_z(c[0] - b, c[1] - b, c[0] + b, c[1] + b, c[2] - b);
        s.quads[s.nquads++] = rect_z(c[0] - b, c[1] - b, c[0] + b, c[1] + b, c[2] + b);
        {
            quad q;
            double xs[2] = {-b, b};
            int k;
            for (k = 0; k < 2; k++) {
                double v1[4][3] = {{xs[k], -b, c[2] - b}, {xs[k], b, c[2] - b}, {xs[k], b, c[2] + b}, {xs[k], -b, c[2] + b}};
                double v2[4][3] = {{-b, xs[k], c[2] - b}, {b, xs[k], c[2] - b}, {b, xs[k], c[2] + b}, {-b, xs[k], c[2] + b}};
                memcpy(q.v, v1, sizeof v1);
                s.quads[s.nquads++] = q;
                memcpy(q.v, v2, sizeof v2);
                s.quads[s.nquads++] = q;
            }
        }
        s.order_reversed = order;
        res = run_and_check(&s, 1);
        assert_true(res.hidden_checked > 400);
        for (y = 0; y < H; y++)
            for (x = 0; x < W; x++) {
                double wx = x + 0.5 - W / 2.0, wy = H / 2.0 - y - 0.5;
                double m = fmax(fabs(wx), fabs(wy));
                if (m < 10.5)
                    assert_int_equal(got[y * W + x], 4); /* box top and blocked floor */
                else if (m > 12.5)
                    assert_int_equal(got[y * W + x], 12);
            }
    }
}

/* Polygons behind the light cast nothing: a square above a light that
 * looks down (seen through the light it would shadow [-12, 12]^2), and a
 * square in a plane through the light (edge-on to it: at most a line). */
static void test_polygons_behind_and_through_the_light(void **state)
{
    scene s;
    result res;
    int x, y;
    (void)state;
    base_scene(&s, 0, 0, 0, 20);
    s.quads[s.nquads++] = rect_z(-6, -6, 6, 6, 30);
    res = run_and_check(&s, 1);
    assert_int_equal(res.hidden_checked, 0);
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++)
            assert_int_equal(got[y * W + x], plain[y * W + x]);

    base_scene(&s, 0, 0, 0, 20);
    {
        quad q;
        double v[4][3] = {{-4, 0, 15}, {4, 0, 15}, {4, 0, 25}, {-4, 0, 25}};
        memcpy(q.v, v, sizeof v);
        s.quads[s.nquads++] = q;
    }
    render(&s, 0, plain);
    render(&s, 1, got);
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++)
            if (fabs(H / 2.0 - y - 0.5) > 1.0)
                assert_int_equal(got[y * W + x], plain[y * W + x]);
}

/* A scene lit everywhere renders byte for byte as without maps; so does one
 * whose maps the view took away (stp_renderer_set_view removes them). */
static void test_lit_scene_unchanged(void **state)
{
    scene s;
    stp_renderer *r;
    stp_view v;
    (void)state;
    base_scene(&s, 0, 0, 0, 20);
    render(&s, 0, plain);
    render(&s, 1, got);
    assert_memory_equal(got, plain, W * H);

    base_scene(&s, 6, 10, 0, 20);
    render(&s, 0, plain);
    r = build(&s, 1);
    memset(&v, 0, sizeof v);
    v.from.z = fx(100);
    v.up.y = STP_FIX_ONE;
    v.window_half = fx(H / 2.0);
    v.hither = fx(1);
    v.projection = STP_PARALLEL;
    assert_int_equal(stp_renderer_set_view(r, &v), STP_OK);
    assert_int_equal(output(r, &s), STP_OK);
    assert_memory_equal(frame_px, plain, W * H);
}

/* Stiff: shadow acne.  A bare floor under a light ever nearer its plane
 * (elevations of 60 down to 2 degrees), through both cameras and map
 * resolutions from coarse to fine: every floor pixel is lit, so the frame
 * is the one without maps, byte for byte. */
static void test_no_acne_at_grazing_light(void **state)
{
    static const double elevation[] = {60, 30, 10, 5, 2};
    static const int res[] = {16, 64, 256};
    scene s;
    int e, k, persp;
    (void)state;
    for (persp = 0; persp < 2; persp++)
        for (e = 0; e < 5; e++)
            for (k = 0; k < 3; k++) {
                double a = elevation[e] * PI / 180;
                base_scene(&s, 0, 0, -30 * cos(a), 30 * sin(a));
                s.map_res = res[k];
                s.map_fov = 150;
                if (persp) {
                    s.perspective = 1;
                    s.from[1] = -40;
                    s.from[2] = 30;
                }
                render(&s, 0, plain);
                render(&s, 1, got);
                assert_memory_equal(got, plain, W * H);
            }
}

/* Band rendering equals the full frame, with the Z buffer and the painter. */
static void test_bands_equal_full_frame(void **state)
{
    static const uint32_t bands[] = {1, 3, 5, 7, 16, 47};
    static uint8_t full[W * H];
    scene s;
    int m, b;
    (void)state;
    for (m = 0; m < 2; m++) {
        base_scene(&s, 6, 10, -10, 20);
        s.hidden = m ? STP_HIDDEN_PAINTER : STP_HIDDEN_ZBUFFER;
        render(&s, 1, full);
        for (b = 0; b < (int)(sizeof bands / sizeof bands[0]); b++) {
            s.band_rows = bands[b];
            render(&s, 1, got);
            assert_memory_equal(got, full, W * H);
        }
        /* the painter draws the same picture as the Z buffer here */
        if (m == 1) {
            s.hidden = STP_HIDDEN_ZBUFFER;
            s.band_rows = H;
            render(&s, 1, got);
            assert_memory_equal(got, full, W * H);
        }
    }
}

/* GREY8 output goes through the same styles. */
static void test_grey_output(void **state)
{
    scene s;
    (void)state;
    base_scene(&s, 6, 10, 0, 20);
    s.format = STP_PIXEL_GREY8;
    render(&s, 1, got);
    assert_int_equal(got[(H / 2) * W + W / 2 + 9], (3 * 255 + 7) / 15);   /* style 4 */
    assert_int_equal(got[(H / 2) * W + W / 2 + 20], (11 * 255 + 7) / 15); /* style 12 */
}

/* Smooth floor: hidden pixels are darker, lit pixels unchanged. */
static void test_smooth_receiver(void **state)
{
    scene s;
    result res;
    (void)state;
    if (!STP_WITH_GOURAUD)
        skip();
    base_scene(&s, 6, 10, 0, 20);
    s.smooth = 1;
    s.power[0] = 30;
    res = run_and_check(&s, 0);
    assert_true(res.hidden_checked > 200);
}

/* Colour floor on RGB888: lit pixels unchanged, hidden ones darker in
 * every channel. */
static void test_colour_receiver(void **state)
{
    scene s;
    int x, y, c, darker = 0;
    (void)state;
    if (!STP_WITH_COLOUR)
        skip();
    base_scene(&s, 6, 10, 0, 20);
    s.colour = 1;
    s.format = STP_PIXEL_RGB888;
    render(&s, 0, plain);
    render(&s, 1, got);
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            double wx = x + 0.5 - W / 2.0, wy = H / 2.0 - y - 0.5;
            double m = fmax(fabs(wx), fabs(wy));
            for (c = 0; c < 3; c++) {
                int g = got[(y * W + x) * 3 + c], p = plain[(y * W + x) * 3 + c];
                if (m > 6.5 && m < 11.5) {
                    assert_true(g < p);
                    darker++;
                } else if (m < 5.5 || m > 12.5) {
                    assert_int_equal(g, p);
                }
            }
        }
    assert_true(darker > 0);
}

static void test_bad_arguments(void **state)
{
    static uint16_t small[16];
    stp_renderer *r;
    stp_shadow_view sv;
    scene s;
    (void)state;
    base_scene(&s, 0, 0, 0, 20);
    r = build(&s, 0);
    memset(&sv, 0, sizeof sv);
    sv.fov_degrees = fx(90);
    sv.near = fx(1);
    assert_int_equal(stp_renderer_set_shadow_map(NULL, 0, small, 16, 4, 4, &sv), STP_ERR_ARG);
    assert_int_equal(stp_renderer_set_shadow_map(r, 0, NULL, 16, 4, 4, &sv), STP_ERR_ARG);
    assert_int_equal(stp_renderer_set_shadow_map(r, 0, small, 15, 4, 4, &sv), STP_ERR_MEMORY);
    assert_int_equal(stp_renderer_set_shadow_map(r, 0, small, 16, 8, 4, &sv), STP_ERR_MEMORY);
    assert_int_equal(stp_renderer_set_shadow_map(r, 0, small, 16, 0, 4, &sv), STP_ERR_ARG);
    assert_int_equal(stp_renderer_set_shadow_map(r, 0, small, 16, 4, 40000, &sv), STP_ERR_ARG);
    assert_int_equal(stp_renderer_set_shadow_map(r, -1, small, 16, 4, 4, &sv), STP_ERR_ARG);
    assert_int_equal(stp_renderer_set_shadow_map(r, 1, small, 16, 4, 4, &sv), STP_ERR_ARG); /* one light */
    assert_int_equal(stp_renderer_set_shadow_map(r, STP_MAX_LIGHTS, small, 16, 4, 4, &sv), STP_ERR_ARG);
    sv.fov_degrees = 0;
    assert_int_equal(stp_renderer_set_shadow_map(r, 0, small, 16, 4, 4, &sv), STP_ERR_VIEW);
    sv.fov_degrees = fx(180);
    assert_int_equal(stp_renderer_set_shadow_map(r, 0, small, 16, 4, 4, &sv), STP_ERR_VIEW);
    sv.fov_degrees = fx(90);
    sv.near = 0;
    assert_int_equal(stp_renderer_set_shadow_map(r, 0, small, 16, 4, 4, &sv), STP_ERR_VIEW);
    sv.near = fx(1);
    sv.target.z = fx(20); /* at the light */
    assert_int_equal(stp_renderer_set_shadow_map(r, 0, small, 16, 4, 4, &sv), STP_ERR_VIEW);
    sv.target.z = 0;
    small[3] = 77;
    assert_int_equal(stp_renderer_set_shadow_map(r, 0, small, 16, 4, 4, &sv), STP_OK);
    assert_int_equal(small[3], 0); /* cleared */
    assert_int_equal(stp_renderer_set_shadow_map(r, 0, small, 16, 4, 4, NULL), STP_OK); /* defaults */
    assert_int_equal(stp_renderer_remove_shadow_map(r, 0), STP_OK);
    assert_int_equal(stp_renderer_remove_shadow_map(r, STP_MAX_LIGHTS), STP_ERR_ARG);
    assert_int_equal(stp_renderer_remove_shadow_map(NULL, 0), STP_ERR_ARG);
}

/* A map of one texel and a huge map ratio: no crash, nothing outside the
 * usual styles. */
static void test_tiny_map(void **state)
{
    scene s;
    int i;
    (void)state;
    base_scene(&s, 6, 10, 0, 20);
    s.map_res = 1;
    render(&s, 1, got);
    for (i = 0; i < W * H; i++)
        assert_true(got[i] >= 1 && got[i] <= LEVELS);
}

/* Without STP_WITH_SHADOWS the API says so. */
static void test_compiled_out(void **state)
{
    static uint16_t map[16];
    scene s;
    stp_renderer *r;
    (void)state;
    base_scene(&s, 0, 0, 0, 20);
    r = build(&s, 0);
    assert_int_equal(stp_renderer_set_shadow_map(r, 0, map, 16, 4, 4, NULL), STP_ERR_UNSUPPORTED);
    assert_int_equal(stp_renderer_remove_shadow_map(r, 0), STP_OK);
}

int main(void)
{
    const struct CMUnitTest off[] = {cmocka_unit_test(test_compiled_out)};
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_square_over_floor),
        cmocka_unit_test(test_light_at_an_angle),
        cmocka_unit_test(test_perspective_camera),
        cmocka_unit_test(test_two_lights),
        cmocka_unit_test(test_light_inside_caster),
        cmocka_unit_test(test_polygons_behind_and_through_the_light),
        cmocka_unit_test(test_lit_scene_unchanged),
        cmocka_unit_test(test_no_acne_at_grazing_light),
        cmocka_unit_test(test_bands_equal_full_frame),
        cmocka_unit_test(test_grey_output),
        cmocka_unit_test(test_smooth_receiver),
        cmocka_unit_test(test_colour_receiver),
        cmocka_unit_test(test_bad_arguments),
        cmocka_unit_test(test_tiny_map),
    };
    if (!STP_WITH_SHADOWS)
        return cmocka_run_group_tests(off, NULL, NULL);
    return cmocka_run_group_tests(tests, NULL, NULL);
}
