/* SPDX-License-Identifier: MIT */
/*
 * The renderer through its public API (include/stipple/render.h): the fill
 * rule, hidden surfaces, back faces, bands, the display file and segments,
 * hither clipping and the caller's buffers.
 *
 * Most scenes use a parallel view from (0,0,-10) at the origin with y up,
 * scaled so one world unit is one pixel: then the view's x axis is world -x
 * (looking along +z, right is -x in a right-handed world) and a world point
 * (x, y) lands on device (W/2 - x, H/2 - y).  Polygons are written in device
 * coordinates (multiples of 1/16 pixel, exact in Q27.4) through dev(), and
 * expected pixel sets are computed here from the documented rule: a pixel
 * belongs to a polygon when its centre is inside by even-odd, spans covering
 * x_left <= centre < x_right and edges y_top <= centre < y_bottom.
 * STP_PIXEL_STYLE8 with shading off makes each pixel the fill style index.
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

#define ONE STP_FIX_ONE
#define PI 3.14159265358979323846

static stp_fix fx(double v)
{
    return (stp_fix)floor(v * ONE + 0.5);
}

static stp_vec3 vec(double x, double y, double z)
{
    stp_vec3 v;
    v.x = fx(x);
    v.y = fx(y);
    v.z = fx(z);
    return v;
}

/* ---- a renderer with its buffers ---- */

typedef struct fixture {
    uint32_t w, h, capacity;
    void *mem;
    stp_instr *df;
    stp_renderer *r;
} fixture;

static void set_parallel_view(fixture *f)
{
    stp_view v;
    uint32_t short_side = f->w < f->h ? f->w : f->h;
    memset(&v, 0, sizeof v);
    v.from = vec(0, 0, -10);
    v.at = vec(0, 0, 0);
    v.up = vec(0, 1, 0);
    v.window_half = fx(short_side / 2.0); /* one unit per pixel */
    v.hither = fx(1);
    v.fov_degrees = fx(90);
    v.projection = STP_PARALLEL;
    assert_int_equal(stp_renderer_set_view(f->r, &v), STP_OK);
}

/* A renderer of w x h with a parallel view and segment 1 open. */
static void fixture_open(fixture *f, uint32_t w, uint32_t h, uint32_t capacity)
{
    f->w = w;
    f->h = h;
    f->capacity = capacity;
    f->mem = malloc(stp_renderer_size());
    f->df = calloc(capacity, sizeof *f->df);
    assert_non_null(f->mem);
    assert_non_null(f->df);
    f->r = stp_renderer_create(f->mem, stp_renderer_size(), f->df, capacity, w, h);
    assert_non_null(f->r);
    set_parallel_view(f);
    assert_int_equal(stp_segment_create(f->r, 1), STP_OK);
}

static void fixture_close(fixture *f)
{
    free(f->mem);
    free(f->df);
    f->mem = NULL;
    f->df = NULL;
}

/* World point of device (dx, dy) at world depth z (see the file comment). */
static stp_vec3 dev(const fixture *f, double dx, double dy, double z)
{
    return vec(f->w / 2.0 - dx, f->h / 2.0 - dy, z);
}

typedef struct dpt {
    double x, y;
} dpt;

/* Enter a polygon given in device coordinates at depth z with a style. */
static int poly(fixture *f, const dpt *p, int n, double z, int style)
{
    stp_vec3 v[64];
    int i;
    assert_true(n <= 64);
    for (i = 0; i < n; i++)
        v[i] = dev(f, p[i].x, p[i].y, z);
    stp_renderer_set_fill_style(f->r, style);
    return stp_renderer_polygon(f->r, v, n);
}

/* ---- rendering into a frame ---- */

typedef struct capture {
    stp_port port;
    uint8_t *frame;
    size_t stride;
    uint32_t next_y, flushes;
    int out_of_order;
    int fail_on_flush; /* flush number that returns an error, or -1 */
} capture;

static int flush_copy(stp_port *port, uint32_t y0, uint32_t rows, const uint8_t *pixels, size_t stride)
{
    capture *c = port->user;
    uint32_t y;
    if ((int)c->flushes == c->fail_on_flush) {
        c->flushes++;
        return -1;
    }
    c->flushes++;
    if (y0 != c->next_y || rows == 0 || y0 + rows > port->height || stride != c->stride)
        c->out_of_order = 1;
    for (y = 0; y < rows && y0 + y < port->height; y++)
        memcpy(c->frame + (size_t)(y0 + y) * c->stride, pixels + (size_t)y * stride, c->stride);
    c->next_y = y0 + rows;
    return 0;
}

typedef struct render_opts {
    stp_pixel_format format;
    stp_hidden hidden;
    uint32_t band_rows; /* 0: the whole height */
    int keep_setup;     /* lend the per-polygon setup array */
    const stp_cell *cell;
    const uint8_t *gamma;
    const stp_style_table *styles;
    stp_fix background;
} render_opts;

static render_opts opts(stp_pixel_format format, stp_hidden hidden)
{
    render_opts o;
    memset(&o, 0, sizeof o);
    o.format = format;
    o.hidden = hidden;
    return o;
}

/* Render into a new frame (free it); checks the bands arrive top to bottom
 * and cover the frame once. */
static uint8_t *render(const fixture *f, const render_opts *o, int *status)
{
    capture c;
    stp_output out;
    stp_frame_memory mem;
    uint32_t rows = o->band_rows ? o->band_rows : f->h;
    size_t polygons = stp_renderer_polygon_count(f->r);
    memset(&c, 0, sizeof c);
    c.port.width = f->w;
    c.port.height = f->h;
    c.port.format = o->format;
    c.port.flush = flush_copy;
    c.port.user = &c;
    c.stride = stp_row_bytes(o->format, f->w);
    c.fail_on_flush = -1;
    c.frame = calloc(f->h, c.stride);
    assert_non_null(c.frame);
    memset(&out, 0, sizeof out);
    out.hidden = o->hidden;
    out.cell = o->cell;
    out.gamma = o->gamma;
    out.styles = o->styles;
    out.background = o->background;
    memset(&mem, 0, sizeof mem);
    mem.band_rows = rows;
    mem.band_size = c.stride * rows;
    mem.band = malloc(mem.band_size);
    mem.zbuf_count = (size_t)f->w * rows;
    mem.zbuf = malloc(mem.zbuf_count * sizeof *mem.zbuf);
    mem.sort_count = polygons;
    mem.sort = malloc((polygons ? polygons : 1) * sizeof *mem.sort);
    assert_true(mem.band && mem.zbuf && mem.sort);
    /* the caller's memory holds garbage: nothing may depend on it */
    memset(mem.band, 0xA5, mem.band_size);
    memset(mem.zbuf, 0xA5, mem.zbuf_count * sizeof *mem.zbuf);
    memset(mem.sort, 0xA5, (polygons ? polygons : 1) * sizeof *mem.sort);
    if (o->keep_setup) {
        mem.setup_count = polygons;
        mem.setup = malloc((polygons ? polygons : 1) * sizeof *mem.setup);
        assert_non_null(mem.setup);
        memset(mem.setup, 0xA5, (polygons ? polygons : 1) * sizeof *mem.setup);
    }
    *status = stp_renderer_render(f->r, &c.port, &out, &mem);
    if (*status == STP_OK) {
        assert_false(c.out_of_order);
        assert_int_equal(c.next_y, f->h);
        assert_int_equal(c.flushes, (f->h + rows - 1) / rows);
    }
    free(mem.band);
    free(mem.zbuf);
    free(mem.sort);
    free(mem.setup);
    return c.frame;
}

/* STYLE8 frame, whole height, the given hidden-surface method. */
static uint8_t *render_styles(const fixture *f, stp_hidden hidden)
{
    render_opts o = opts(STP_PIXEL_STYLE8, hidden);
    int status;
    uint8_t *frame = render(f, &o, &status);
    assert_int_equal(status, STP_OK);
    return frame;
}

/* ---- expected pixel sets, computed independently ---- */

/* Whether pixel (i, j)'s centre is inside polygon p (device coordinates,
 * multiples of 1/16) by the documented rule, in exact integers. */
static int inside_exact(const dpt *p, int n, int i, int j)
{
    int64_t xc = 16 * (int64_t)i + 8, yc = 16 * (int64_t)j + 8;
    int k, count = 0;
    for (k = 0; k < n; k++) {
        int64_t xa = (int64_t)lround(p[k].x * 16), ya = (int64_t)lround(p[k].y * 16);
        int64_t xb = (int64_t)lround(p[(k + 1) % n].x * 16), yb = (int64_t)lround(p[(k + 1) % n].y * 16);
        if (ya == yb)
            continue;
        if (ya > yb) {
            int64_t t = xa;
            xa = xb;
            xb = t;
            t = ya;
            ya = yb;
            yb = t;
        }
        if (!(ya <= yc && yc < yb))
            continue;
        /* crossing x = xa + (yc - ya)(xb - xa)/(yb - ya) <= xc */
        if (xa * (yb - ya) + (yc - ya) * (xb - xa) <= xc * (yb - ya))
            count++;
    }
    return count & 1;
}

/* Distance in pixels from pixel (i, j)'s centre to the polygon's outline. */
static double edge_distance(const dpt *p, int n, int i, int j)
{
    double px = i + 0.5, py = j + 0.5, best = 1e30;
    int k;
    for (k = 0; k < n; k++) {
        double ax = p[k].x, ay = p[k].y, bx = p[(k + 1) % n].x, by = p[(k + 1) % n].y;
        double dx = bx - ax, dy = by - ay, t = 0.0, d;
        if (dx != 0.0 || dy != 0.0)
            t = ((px - ax) * dx + (py - ay) * dy) / (dx * dx + dy * dy);
        t = t < 0 ? 0 : (t > 1 ? 1 : t);
        d = hypot(px - (ax + t * dx), py - (ay + t * dy));
        if (d < best)
            best = d;
    }
    return best;
}

/* With STP_SQRT_FAST the view basis (from stp_vec3_unity) is unit only to
 * 2^-15 (unity(-1,0,0) gives -65535/65536), and projection floors to the
 * 1/16-pixel grid, so a vertex can land one subpixel step off in x and y:
 * centres within 0.1 pixel of an edge may go either way there. */
#if STP_SQRT_FAST
#define GEOMETRY_SLACK 0.1
#else
#define GEOMETRY_SLACK 0.0
#endif

/* Compare the pixels of `style` in a STYLE8 frame with the polygon's exact
 * set.  slack = 0: every pixel must match; slack > 0: pixels whose centre is
 * within slack pixels of an edge may go either way (the scan converter steps
 * along an edge in Q16 subpixel units, so a crossing within 1/16 pixel of a
 * centre can round to its other side). */
static void expect_exact_set(const fixture *f, const uint8_t *frame, int style, const dpt *p, int n,
                             double slack, const char *what)
{
    uint32_t i, j;
    long checked = 0;
    slack += GEOMETRY_SLACK;
    for (j = 0; j < f->h; j++)
        for (i = 0; i < f->w; i++) {
            int got = frame[j * f->w + i] == style, want = inside_exact(p, n, (int)i, (int)j);
            if (got != want && !(slack > 0 && edge_distance(p, n, (int)i, (int)j) <= slack))
                fail_msg("%s: pixel (%u,%u) is %s, the rule says %s", what, i, j, got ? "drawn" : "empty",
                         want ? "inside" : "outside");
            checked += want;
        }
    assert_true(checked > 0); /* the polygon covers something */
}

static int count_style(const fixture *f, const uint8_t *frame, int style)
{
    uint32_t k;
    int c = 0;
    for (k = 0; k < f->w * f->h; k++)
        c += frame[k] == style;
    return c;
}

/* ---- the fill rule ---- */

/* Render polygon(s) alone in a fresh fixture; returns the STYLE8 frame. */
static uint8_t *render_alone(uint32_t w, uint32_t h, const dpt *const *polys, const int *ns, int count, int style)
{
    fixture f;
    uint8_t *frame;
    int k;
    fixture_open(&f, w, h, 1024);
    for (k = 0; k < count; k++)
        assert_int_equal(poly(&f, polys[k], ns[k], 0, style), STP_OK);
    frame = render_styles(&f, STP_HIDDEN_NONE);
    fixture_close(&f);
    return frame;
}

static void check_split_square(const dpt *sq, int diag, double slack)
{
    /* triangles on either side of the diagonal from corner diag to corner
     * diag + 2 */
    const int S = 7;
    fixture f;
    dpt ta[3], tb[3];
    const dpt *one[1], *both[2], *square[1];
    int n3[2] = {3, 3}, n4[1] = {4};
    uint8_t *fa, *fb, *fab, *fsq;
    uint32_t k;
    ta[0] = sq[diag];
    ta[1] = sq[(diag + 1) % 4];
    ta[2] = sq[(diag + 2) % 4];
    tb[0] = sq[diag];
    tb[1] = sq[(diag + 2) % 4];
    tb[2] = sq[(diag + 3) % 4];
    f.w = f.h = 32;
    one[0] = ta;
    fa = render_alone(32, 32, one, n3, 1, S);
    one[0] = tb;
    fb = render_alone(32, 32, one, n3, 1, S);
    both[0] = ta;
    both[1] = tb;
    fab = render_alone(32, 32, both, n3, 2, S);
    square[0] = sq;
    fsq = render_alone(32, 32, square, n4, 1, S);
    for (k = 0; k < 32 * 32; k++) {
        int a = fa[k] == S, b = fb[k] == S;
        if (a && b)
            fail_msg("pixel (%u,%u) drawn by both triangles", k % 32, k / 32);
        if ((a || b) != (fab[k] == S))
            fail_msg("pixel (%u,%u): union of the triangles differs from both rendered together", k % 32, k / 32);
        if ((fab[k] == S) != (fsq[k] == S))
            fail_msg("pixel (%u,%u): the two triangles differ from the square", k % 32, k / 32);
    }
    expect_exact_set(&f, fsq, S, sq, 4, 0.0, "square");
    expect_exact_set(&f, fa, S, ta, 3, slack, "triangle a");
    expect_exact_set(&f, fb, S, tb, 3, slack, "triangle b");
    free(fa);
    free(fb);
    free(fab);
    free(fsq);
}

static void test_fill_rule_two_triangles_share_diagonal(void **state)
{
    /* pixel-aligned square: the diagonal runs through pixel centres, so the
     * tie rule decides every pixel on it */
    static const dpt aligned[4] = {{4, 4}, {12, 4}, {12, 12}, {4, 12}};
    /* unaligned corners, a square whose diagonal still has slope 1 */
    static const dpt offset[4] = {{3.25, 5.5}, {20.75, 5.5}, {20.75, 23.0}, {3.25, 23.0}};
    /* a rectangle whose diagonal has a slope that is not exact in Q16 */
    static const dpt rect[4] = {{2.0625, 3.5}, {29.5, 3.5}, {29.5, 10.8125}, {2.0625, 10.8125}};
    (void)state;
    check_split_square(aligned, 0, 0.0);
    check_split_square(aligned, 1, 0.0);
    check_split_square(offset, 0, 0.0);
    check_split_square(offset, 1, 0.0);
    check_split_square(rect, 0, 1.0 / 16);
    check_split_square(rect, 1, 1.0 / 16);
}

static void test_fill_rule_top_left_ties(void **state)
{
    /* edges through pixel centres: the left and top ones own them, the right
     * and bottom ones do not (x_left <= c < x_right, y_top <= c < y_bottom) */
    static const dpt sq[4] = {{4.5, 6.5}, {9.5, 6.5}, {9.5, 10.5}, {4.5, 10.5}};
    fixture f;
    uint8_t *frame;
    uint32_t i, j;
    (void)state;
    fixture_open(&f, 16, 16, 64);
    assert_int_equal(poly(&f, sq, 4, 0, 5), STP_OK);
    frame = render_styles(&f, STP_HIDDEN_NONE);
    for (j = 0; j < 16; j++)
        for (i = 0; i < 16; i++) {
            int want = i >= 4 && i < 9 && j >= 6 && j < 10;
            int on_edge = ((i == 4 || i == 9) && j >= 6 && j <= 10) || ((j == 6 || j == 10) && i >= 4 && i <= 9);
            if (GEOMETRY_SLACK > 0 && on_edge)
                continue; /* ties are not exact in this configuration */
            assert_int_equal(frame[j * 16 + i] == 5, want);
        }
    free(frame);
    fixture_close(&f);
}

static void test_fill_rule_fan_has_no_gaps_or_overlaps(void **state)
{
    /* 12 triangles around an off-grid centre; their outline is a 12-gon */
    enum { N = 12, S = 9 };
    dpt outer[N], tri[N][3];
    const dpt *one[1], *all[N], *ring[1];
    int n3[N], nn[1] = {N};
    uint8_t *single[N], *together, *outline;
    int count[32 * 32];
    fixture f;
    int k;
    uint32_t p;
    (void)state;
    f.w = f.h = 32;
    for (k = 0; k < N; k++) {
        double a = (k * 30.0 + 7.0) * PI / 180.0;
        outer[k].x = floor((16.3 + 13.0 * cos(a)) * 16 + 0.5) / 16; /* on the 1/16 grid */
        outer[k].y = floor((15.7 + 13.0 * sin(a)) * 16 + 0.5) / 16;
    }
    for (k = 0; k < N; k++) {
        tri[k][0].x = 16.3125;
        tri[k][0].y = 15.6875;
        tri[k][1] = outer[k];
        tri[k][2] = outer[(k + 1) % N];
        n3[k] = 3;
        all[k] = tri[k];
        one[0] = tri[k];
        single[k] = render_alone(32, 32, one, n3, 1, S);
    }
    together = render_alone(32, 32, all, n3, N, S);
    ring[0] = outer;
    outline = render_alone(32, 32, ring, nn, 1, S);
    memset(count, 0, sizeof count);
    for (k = 0; k < N; k++)
        for (p = 0; p < 32 * 32; p++)
            count[p] += single[k][p] == S;
    for (p = 0; p < 32 * 32; p++) {
        if (count[p] > 1)
            fail_msg("pixel (%u,%u) drawn by %d triangles of the fan", p % 32, p / 32, count[p]);
        if ((count[p] == 1) != (outline[p] == S))
            fail_msg("pixel (%u,%u): fan %d, outline %d (a gap or a stray pixel)", p % 32, p / 32, count[p],
                     outline[p] == S);
        if ((count[p] == 1) != (together[p] == S))
            fail_msg("pixel (%u,%u): triangles alone and together differ", p % 32, p / 32);
    }
    expect_exact_set(&f, outline, S, outer, N, 1.0 / 16, "12-gon");
    for (k = 0; k < N; k++)
        free(single[k]);
    free(together);
    free(outline);
}

static void test_fill_rule_concave_and_even_odd(void **state)
{
    /* a concave "E"-like comb with axis-aligned and 45-degree edges: exact */
    static const dpt comb[] = {{2, 2}, {28, 2}, {28, 8}, {10, 8}, {14, 12}, {28, 12}, {28, 18},
                               {10, 18}, {6, 22}, {28, 22}, {28, 29}, {2, 29}};
    /* a pentagram: self-intersecting, its inner pentagon is outside by
     * even-odd (winding number 2) */
    dpt star[5];
    fixture f;
    const dpt *one[1];
    int n[1];
    uint8_t *frame;
    int k;
    (void)state;
    f.w = f.h = 32;
    one[0] = comb;
    n[0] = (int)(sizeof comb / sizeof comb[0]);
    frame = render_alone(32, 32, one, n, 1, 4);
    expect_exact_set(&f, frame, 4, comb, n[0], 0.0, "concave comb");
    /* the notches are empty */
    assert_int_not_equal(frame[10 * 32 + 20], 4);
    assert_int_not_equal(frame[20 * 32 + 20], 4);
    free(frame);
    for (k = 0; k < 5; k++) {
        double a = (-90.0 + k * 144.0) * PI / 180.0;
        star[k].x = floor((16 + 14 * cos(a)) * 16 + 0.5) / 16;
        star[k].y = floor((16.5 + 14 * sin(a)) * 16 + 0.5) / 16;
    }
    one[0] = star;
    n[0] = 5;
    frame = render_alone(32, 32, one, n, 1, 4);
    expect_exact_set(&f, frame, 4, star, 5, 1.0 / 16, "pentagram");
    assert_int_not_equal(frame[17 * 32 + 16], 4); /* the centre */
    assert_int_equal(frame[6 * 32 + 16], 4);      /* the top point */
    free(frame);
}

/* ---- hidden surfaces ---- */

static const dpt near_sq[4] = {{4, 4}, {20, 4}, {20, 20}, {4, 20}};
static const dpt far_sq[4] = {{12, 12}, {28, 12}, {28, 28}, {12, 28}};

static void check_overlap(const uint8_t *frame, int near_style, int far_style, int overlap_style)
{
    uint32_t i, j;
    for (j = 0; j < 32; j++)
        for (i = 0; i < 32; i++) {
            int in_near = i >= 4 && i < 20 && j >= 4 && j < 20;
            int in_far = i >= 12 && i < 28 && j >= 12 && j < 28;
            int v = frame[j * 32 + i];
            if (in_near && in_far) {
                if (v != overlap_style)
                    fail_msg("overlap pixel (%u,%u) has style %d, want %d", i, j, v, overlap_style);
            } else if (in_near) {
                assert_int_equal(v, near_style);
            } else if (in_far) {
                assert_int_equal(v, far_style);
            } else {
                assert_true(v != near_style && v != far_style);
            }
        }
}

static void test_hidden_surfaces_nearer_square_wins(void **state)
{
    static const stp_hidden methods[2] = {STP_HIDDEN_ZBUFFER, STP_HIDDEN_PAINTER};
    int m, order;
    (void)state;
    for (m = 0; m < 2; m++)
        for (order = 0; order < 2; order++) {
            fixture f;
            uint8_t *frame;
            fixture_open(&f, 32, 32, 256);
            /* near at world z = 0 (10 from the eye), far at z = 3 */
            if (order == 0) {
                assert_int_equal(poly(&f, near_sq, 4, 0, 3), STP_OK);
                assert_int_equal(poly(&f, far_sq, 4, 3, 11), STP_OK);
            } else {
                assert_int_equal(poly(&f, far_sq, 4, 3, 11), STP_OK);
                assert_int_equal(poly(&f, near_sq, 4, 0, 3), STP_OK);
            }
            frame = render_styles(&f, methods[m]);
            check_overlap(frame, 3, 11, 3);
            free(frame);
            /* without hidden-surface removal: display-file order */
            frame = render_styles(&f, STP_HIDDEN_NONE);
            check_overlap(frame, 3, 11, order == 0 ? 11 : 3);
            free(frame);
            fixture_close(&f);
        }
}

static void test_zbuffer_interpenetrating_polygons(void **state)
{
    /* A slopes from world z = -4 at device x = 4 to z = +4 at x = 28; B is
     * flat at z = 0: left of x = 16 A is nearer, right of it B.  A painter
     * cannot do this; the Z buffer must, pixel by pixel (one column either
     * side of the crossing is left to rounding). */
    fixture f;
    stp_vec3 a[4], b[4];
    uint8_t *frame;
    uint32_t i, j;
    int order;
    (void)state;
    for (order = 0; order < 2; order++) {
        fixture_open(&f, 32, 32, 256);
        a[0] = dev(&f, 4, 6, -4);
        a[1] = dev(&f, 28, 6, 4);
        a[2] = dev(&f, 28, 26, 4);
        a[3] = dev(&f, 4, 26, -4);
        b[0] = dev(&f, 6, 8, 0);
        b[1] = dev(&f, 26, 8, 0);
        b[2] = dev(&f, 26, 24, 0);
        b[3] = dev(&f, 6, 24, 0);
        stp_renderer_set_fill_style(f.r, order == 0 ? 2 : 12);
        assert_int_equal(stp_renderer_polygon(f.r, order == 0 ? a : b, 4), STP_OK);
        stp_renderer_set_fill_style(f.r, order == 0 ? 12 : 2);
        assert_int_equal(stp_renderer_polygon(f.r, order == 0 ? b : a, 4), STP_OK);
        frame = render_styles(&f, STP_HIDDEN_ZBUFFER);
        for (j = 8; j < 24; j++)
            for (i = 6; i < 26; i++) {
                int want_a = i < 15, want_b = i > 16; /* the crossing is at x = 16 */
                const int style_a = 2; /* A has style 2 in both orders */
                int v = frame[j * 32 + i];
                if ((want_a && v != style_a) || (want_b && v == style_a))
                    fail_msg("order %d pixel (%u,%u) = %d: wrong surface in front", order, i, j, v);
            }
        free(frame);
        fixture_close(&f);
    }
}

/* ---- back faces ---- */

/* Cube [-3,3]^3, faces counter-clockwise seen from outside (right-handed
 * world: the right-hand rule gives the outward normal). */
static const double cube_faces[6][4][3] = {
    {{3, -3, -3}, {3, 3, -3}, {3, 3, 3}, {3, -3, 3}},         /* +x */
    {{-3, -3, -3}, {-3, -3, 3}, {-3, 3, 3}, {-3, 3, -3}},     /* -x */
    {{-3, 3, -3}, {-3, 3, 3}, {3, 3, 3}, {3, 3, -3}},         /* +y */
    {{-3, -3, -3}, {3, -3, -3}, {3, -3, 3}, {-3, -3, 3}},     /* -y */
    {{-3, -3, 3}, {3, -3, 3}, {3, 3, 3}, {-3, 3, 3}},         /* +z */
    {{-3, -3, -3}, {-3, 3, -3}, {3, 3, -3}, {3, -3, -3}},     /* -z */
};

static void set_cube_view(fixture *f, const double *from)
{
    stp_view v;
    memset(&v, 0, sizeof v);
    v.from = vec(from[0], from[1], from[2]);
    v.at = vec(0, 0, 0);
    v.up = vec(0, 1, 0);
    v.window_half = fx(8);
    v.hither = fx(1);
    v.fov_degrees = fx(90);
    v.projection = STP_PARALLEL;
    assert_int_equal(stp_renderer_set_view(f->r, &v), STP_OK);
}

/* Outward normal of a cube face, by the right-hand rule. */
static void face_normal(int k, double *n)
{
    const double(*p)[3] = cube_faces[k];
    double u[3] = {p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]};
    double w[3] = {p[2][0] - p[1][0], p[2][1] - p[1][1], p[2][2] - p[1][2]};
    n[0] = u[1] * w[2] - u[2] * w[1];
    n[1] = u[2] * w[0] - u[0] * w[2];
    n[2] = u[0] * w[1] - u[1] * w[0];
}

static void enter_cube(fixture *f, int only_front, const double *from)
{
    int k, i;
    for (k = 0; k < 6; k++) {
        stp_vec3 v[4];
        double n[3];
        face_normal(k, n);
        if (only_front && n[0] * from[0] + n[1] * from[1] + n[2] * from[2] <= 0)
            continue;
        for (i = 0; i < 4; i++)
            v[i] = vec(cube_faces[k][i][0], cube_faces[k][i][1], cube_faces[k][i][2]);
        stp_renderer_set_fill_style(f->r, 2 + 2 * k);
        assert_int_equal(stp_renderer_polygon(f->r, v, 4), STP_OK);
    }
}

static void test_backface_removal_keeps_faces_towards_viewer(void **state)
{
    static const double froms[3][3] = {{-7, -5, -10}, {6, 8, 9}, {-9, 4, 3}};
    int s;
    (void)state;
    for (s = 0; s < 3; s++) {
        fixture with, front_only, all;
        uint8_t *a, *b, *c;
        int k, front = 0;
        for (k = 0; k < 6; k++) {
            double n[3];
            face_normal(k, n);
            front += n[0] * froms[s][0] + n[1] * froms[s][1] + n[2] * froms[s][2] > 0;
        }
        assert_int_equal(front, 3);
        /* removal on, all six faces entered: three enter nothing */
        fixture_open(&with, 32, 32, 256);
        set_cube_view(&with, froms[s]);
        stp_renderer_set_backface_removal(with.r, 1);
        enter_cube(&with, 0, froms[s]);
        assert_int_equal(stp_renderer_polygon_count(with.r), 3);
        /* the three faces the viewer sees, entered by hand */
        fixture_open(&front_only, 32, 32, 256);
        set_cube_view(&front_only, froms[s]);
        enter_cube(&front_only, 1, froms[s]);
        /* all six with a Z buffer: a closed convex solid looks the same */
        fixture_open(&all, 32, 32, 256);
        set_cube_view(&all, froms[s]);
        enter_cube(&all, 0, froms[s]);
        a = render_styles(&with, STP_HIDDEN_NONE);
        b = render_styles(&front_only, STP_HIDDEN_NONE);
        c = render_styles(&all, STP_HIDDEN_ZBUFFER);
        assert_memory_equal(a, b, 32 * 32);
        {
            /* the cube is visible: faces have styles 2..12 */
            uint32_t p;
            int drawn = 0;
            for (p = 0; p < 32 * 32; p++)
                drawn += a[p] >= 2;
            assert_true(drawn > 100);
        }
        {
            /* the Z buffer agrees except where two faces meet on an edge */
            uint32_t p;
            int diff = 0;
            for (p = 0; p < 32 * 32; p++)
                diff += a[p] != c[p];
            assert_true(diff <= 40);
        }
        free(a);
        free(b);
        free(c);
        fixture_close(&with);
        fixture_close(&front_only);
        fixture_close(&all);
    }
}

static void test_backface_removal_single_polygon(void **state)
{
    /* device (4,12) -> (12,12) -> (4,4) runs counter-clockwise on the
     * screen: its front faces the viewer; the reverse order is a back face */
    static const dpt ccw[3] = {{4, 12}, {12, 12}, {4, 4}};
    static const dpt cw[3] = {{4, 12}, {4, 4}, {12, 12}};
    fixture f;
    uint32_t used;
    (void)state;
    fixture_open(&f, 16, 16, 64);
    stp_renderer_set_backface_removal(f.r, 1);
    assert_int_equal(poly(&f, ccw, 3, 0, 5), STP_OK);
    used = stp_renderer_display_file_used(f.r);
    assert_true(used >= 3);
    assert_int_equal(poly(&f, cw, 3, 0, 6), STP_OK); /* enters nothing */
    assert_int_equal(stp_renderer_display_file_used(f.r), used);
    assert_int_equal(stp_renderer_polygon_count(f.r), 1);
    /* removal off: back faces are kept */
    stp_renderer_set_backface_removal(f.r, 0);
    assert_int_equal(poly(&f, cw, 3, 0, 6), STP_OK);
    assert_int_equal(stp_renderer_polygon_count(f.r), 2);
    fixture_close(&f);
}

/* Back faces of triangles are removed before the transform (in world
 * coordinates, render.c world_facing): for random triangles in view, near
 * the eye (the int32 case), far from it (the 64-bit case) and beyond what
 * either decides (the view-space test), perspective and parallel, a
 * triangle (a tenth of the scene across) enters exactly when the double-precision sign of
 * ((v1 - v0) x (v2 - v0)).(eye - v0) (or -N.forward) says the eye sees its
 * front; faces within 1e-6 of edge-on are skipped, and so are the few that
 * enter nothing with back faces kept either (between two row centres). */
static void test_backface_removal_before_transform_matches_double(void **state)
{
    static const double scales[3] = {1, 20, 3000};
    uint32_t seed = 12345u;
    int s, proj, k, checked = 0, fronts = 0, between_rows = 0, winding_differs = 0;
    (void)state;
    for (s = 0; s < 3; s++) {
        for (proj = 0; proj < 2; proj++) {
            fixture f, kept;
            stp_view v;
            double from[3], forward[3], len;
            /* 1024 pixels across: triangles some pixels high, so few fall
             * between two row centres */
            fixture_open(&f, 1024, 1024, 4096);
            fixture_open(&kept, 1024, 1024, 4096);
            from[0] = 0.7 * scales[s];
            from[1] = 1.9 * scales[s];
            from[2] = -5.6 * scales[s];
            len = sqrt(from[0] * from[0] + from[1] * from[1] + from[2] * from[2]);
            for (k = 0; k < 3; k++)
                forward[k] = -from[k] / len;
            memset(&v, 0, sizeof v);
            v.from = vec(from[0], from[1], from[2]);
            v.at = vec(0, 0, 0);
            v.up = vec(0, 1, 0);
            v.window_half = fx(2 * scales[s]);
            v.hither = fx(0.01);
            v.fov_degrees = fx(60);
            v.projection = proj ? STP_PARALLEL : STP_PERSPECTIVE;
            assert_int_equal(stp_renderer_set_view(f.r, &v), STP_OK);
            assert_int_equal(stp_renderer_set_view(kept.r, &v), STP_OK);
            stp_renderer_set_backface_removal(f.r, 1);
            stp_renderer_set_backface_removal(kept.r, 0);
            for (k = 0; k < 200; k++) {
                stp_vec3 t[3];
                double p[3][3], a[3], b[3], n[3], c[3], side, scale_n;
                uint32_t before, kept_before;
                int i, j;
                for (j = 0; j < 3; j++) {
                    seed = seed * 1664525u + 1013904223u;
                    c[j] = ((double)(seed >> 8) / 16777216.0 - 0.5) * 1.2 * scales[s];
                }
                for (i = 0; i < 3; i++) {
                    for (j = 0; j < 3; j++) {
                        seed = seed * 1664525u + 1013904223u;
                        p[i][j] = c[j] + ((double)(seed >> 8) / 16777216.0 - 0.5) * 0.1 * scales[s];
                    }
                    t[i] = vec(p[i][0], p[i][1], p[i][2]);
                    for (j = 0; j < 3; j++) /* the coordinates the renderer gets */
                        p[i][j] = (double)(j == 0 ? t[i].x : j == 1 ? t[i].y : t[i].z) / ONE;
                }
                for (j = 0; j < 3; j++) {
                    a[j] = p[1][j] - p[0][j];
                    b[j] = p[2][j] - p[0][j];
                }
                n[0] = a[1] * b[2] - a[2] * b[1];
                n[1] = a[2] * b[0] - a[0] * b[2];
                n[2] = a[0] * b[1] - a[1] * b[0];
                if (proj) {
                    side = -(n[0] * forward[0] + n[1] * forward[1] + n[2] * forward[2]);
                    scale_n = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
                } else {
                    double e[3] = {from[0] - p[0][0], from[1] - p[0][1], from[2] - p[0][2]};
                    side = n[0] * e[0] + n[1] * e[1] + n[2] * e[2];
                    scale_n = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) *
                              sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
                }
                if (fabs(side) <= 1e-6 * scale_n)
                    continue;
                /* the control, back faces kept: a triangle between two row
                 * centres enters nothing either way (render.h) */
                kept_before = stp_renderer_polygon_count(kept.r);
                assert_int_equal(stp_renderer_polygon(kept.r, t, 3), STP_OK);
                before = stp_renderer_polygon_count(f.r);
                assert_int_equal(stp_renderer_polygon(f.r, t, 3), STP_OK);
                if (stp_renderer_polygon_count(kept.r) == kept_before) {
                    assert_int_equal(stp_renderer_polygon_count(f.r), before);
                    between_rows++;
                    continue;
                }
#if STP_DIRECT_COMPACT
                /* compact builds keep a triangle by the winding of its
                 * projected (rounded) vertices (render_private.h): it may
                 * differ from the exact side for a face within a fraction
                 * of a pixel of edge-on, here within 1% of it (measured: 2
                 * of the 1200, at 0.1% and 0.2%) */
                if (stp_renderer_polygon_count(f.r) - before != (side > 0 ? 1u : 0u)) {
                    assert_true(fabs(side) < 0.01 * scale_n);
                    winding_differs++;
                    checked++;
                    continue;
                }
#endif
                assert_int_equal(stp_renderer_polygon_count(f.r) - before, side > 0 ? 1u : 0u);
                checked++;
                fronts += side > 0;
            }
            fixture_close(&f);
            fixture_close(&kept);
        }
    }
    fprintf(stderr, "  %d triangles decided, %d between two row centres, %d by a winding the exact side differs from\n",
            checked, between_rows, winding_differs);
    assert_true(winding_differs <= checked / 100);
    assert_true(between_rows < checked / 10);
    assert_true(checked > 1000);
    assert_true(fronts > 400 && checked - fronts > 400);
}

/* A back face with a vertex beyond the view range is refused as a front
 * face is (STP_ERR_RANGE), not removed unseen. */
static void test_backface_removal_out_of_range_is_refused(void **state)
{
    fixture f;
    stp_view v;
    stp_vec3 front[3], back[3];
    (void)state;
    fixture_open(&f, 32, 32, 64);
    memset(&v, 0, sizeof v);
    v.from = vec(0, 0, -20000);
    v.at = vec(0, 0, 0);
    v.up = vec(0, 1, 0);
    v.hither = fx(1);
    v.fov_degrees = fx(60);
    v.projection = STP_PERSPECTIVE;
    assert_int_equal(stp_renderer_set_view(f.r, &v), STP_OK);
    stp_renderer_set_backface_removal(f.r, 1);
    /* 20000 + 20000 units from the eye: beyond view coordinates' range */
    front[0] = vec(-1, -1, 20000);
    front[1] = vec(1, -1, 20000);
    front[2] = vec(-1, 1, 20000);
    back[0] = front[0];
    back[1] = front[2];
    back[2] = front[1];
    assert_int_equal(stp_renderer_polygon(f.r, front, 3), STP_ERR_RANGE);
    assert_int_equal(stp_renderer_polygon(f.r, back, 3), STP_ERR_RANGE);
    assert_int_equal(stp_renderer_polygon_count(f.r), 0);
    fixture_close(&f);
}

/* ---- bands ---- */

static void enter_band_scene(fixture *f)
{
    static const dpt p1[4] = {{1, 1}, {30, 2.5}, {27, 20}, {3, 26}};
    static const dpt p2[3] = {{10, 4}, {36, 15}, {8, 28.75}};
    static const dpt p3[5] = {{20, 3}, {35, 9}, {33, 27}, {22, 28}, {15, 14}};
    stp_vec3 tilt[4];
    stp_lighting lighting;
    stp_material mat;
    assert_int_equal(poly(f, p1, 4, 2, 4), STP_OK);
    assert_int_equal(poly(f, p2, 3, 1, 9), STP_OK);
    assert_int_equal(poly(f, p3, 5, 3, 14), STP_OK);
    /* a tilted, shaded polygon crossing the others in depth */
    stp_lighting_default(&lighting);
    lighting.lights[0].position = vec(5, 10, -20);
    lighting.background = fx(0.2);
    assert_int_equal(stp_renderer_set_lighting(f->r, &lighting), STP_OK);
    stp_material_default(&mat);
    mat.gloss = fx(0.5);
    stp_renderer_set_object_shade(f->r, &mat);
    assert_int_equal(stp_segment_close(f->r), STP_OK);
    assert_int_equal(stp_segment_create(f->r, 2), STP_OK);
    stp_renderer_set_shading(f->r, 1);
    tilt[0] = dev(f, 5, 12, -2);
    tilt[1] = dev(f, 33, 10, 5);
    tilt[2] = dev(f, 30, 27, 6);
    tilt[3] = dev(f, 6, 24, -1);
    assert_int_equal(stp_renderer_polygon(f->r, tilt, 4), STP_OK);
    stp_renderer_set_shading(f->r, 0);
    /* and lines */
    stp_renderer_set_fill_style(f->r, 16);
    assert_int_equal(stp_renderer_move(f->r, dev(f, 0.5, 0.5, -3)), STP_OK);
    assert_int_equal(stp_renderer_line(f->r, dev(f, 36.5, 28.5, -3)), STP_OK);
    assert_int_equal(stp_renderer_line(f->r, dev(f, 2.5, 27.5, -3)), STP_OK);
    assert_int_equal(stp_segment_close(f->r), STP_OK);
}

/* Pixel-for-pixel equality of two frames (MONO1: the row padding bits are
 * not pixels and are checked separately). */
static int same_pixels(const fixture *f, stp_pixel_format format, const uint8_t *a, const uint8_t *b)
{
    size_t stride = stp_row_bytes(format, f->w);
    uint32_t x, y;
    if (format != STP_PIXEL_MONO1)
        return memcmp(a, b, stride * f->h) == 0;
    for (y = 0; y < f->h; y++)
        for (x = 0; x < f->w; x++) {
            size_t at = y * stride + x / 8;
            int bit = 7 - (int)(x % 8);
            if (((a[at] >> bit) & 1) != ((b[at] >> bit) & 1)) {
                print_error("first difference at pixel (%u,%u)\n", x, y);
                return 0;
            }
        }
    return 1;
}

static void test_bands_give_the_same_frame(void **state)
{
    static const stp_pixel_format formats[4] = {STP_PIXEL_MONO1, STP_PIXEL_GREY8, STP_PIXEL_STYLE8,
                                                STP_PIXEL_RGB888};
    static const stp_hidden methods[3] = {STP_HIDDEN_NONE, STP_HIDDEN_PAINTER, STP_HIDDEN_ZBUFFER};
    static const uint32_t bands[4] = {1, 3, 7, 29};
    fixture f;
    int fm, m, b;
    (void)state;
    fixture_open(&f, 37, 29, 256); /* odd sizes: MONO1 rows are padded */
    enter_band_scene(&f);
    for (fm = 0; fm < 4; fm++)
        for (m = 0; m < 3; m++) {
            render_opts o = opts(formats[fm], methods[m]);
            uint8_t *full;
            int status;
            size_t size = stp_row_bytes(formats[fm], f.w) * f.h;
            o.band_rows = f.h;
            full = render(&f, &o, &status);
            assert_int_equal(status, STP_OK);
            for (b = 0; b < 3; b++) {
                uint8_t *banded;
                o.band_rows = bands[b];
                banded = render(&f, &o, &status);
                assert_int_equal(status, STP_OK);
                if (!same_pixels(&f, formats[fm], full, banded))
                    fail_msg("format %d, hidden %d: band_rows %u differs from the full frame", formats[fm],
                             methods[m], bands[b]);
                free(banded);
                /* the depth setups kept from a polygon's first band */
                o.keep_setup = 1;
                banded = render(&f, &o, &status);
                o.keep_setup = 0;
                assert_int_equal(status, STP_OK);
                if (!same_pixels(&f, formats[fm], full, banded))
                    fail_msg("format %d, hidden %d: band_rows %u with kept setups differs from the full frame",
                             formats[fm], methods[m], bands[b]);
                free(banded);
            }
            /* the scene drew something beyond the background */
            {
                size_t k;
                int distinct = 0;
                for (k = 1; k < size; k++)
                    distinct |= full[k] != full[0];
                assert_true(distinct);
            }
            free(full);
        }
    fixture_close(&f);
}

/* Flat triangles take their own path through the raster (src/raster.c,
 * draw_triangle); the same triangle entered with a repeated vertex is a
 * quadrilateral, which takes the general path.  Both must paint the same
 * pixels: random triangles in 1/16-pixel steps (some on pixel centres and
 * edges, some beyond the frame, some needle-thin), with and without the Z
 * buffer, whole frame and 3-row bands. */
static int entered_vertices(const fixture *f)
{
    uint32_t k;
    for (k = 0; k < 16; k++)
        if (f->df[k].op >= 3)
            return f->df[k].op;
    return 0;
}

/* *entered: the vertices entered (the clipper may add some) */
static uint8_t *render_one(const dpt *p, int n, stp_hidden hidden, uint32_t band_rows, int *entered)
{
    fixture f;
    render_opts o = opts(STP_PIXEL_STYLE8, hidden);
    uint8_t *frame;
    int status;
    fixture_open(&f, 40, 30, 64);
    assert_int_equal(poly(&f, p, n, 0, 7), STP_OK);
    *entered = entered_vertices(&f);
    o.band_rows = band_rows;
    frame = render(&f, &o, &status);
    assert_int_equal(status, STP_OK);
    fixture_close(&f);
    return frame;
}

static void test_triangle_path_matches_general_path(void **state)
{
    uint32_t seed = 12345u;
    int k, drawn = 0, compared = 0;
    (void)state;
    for (k = 0; k < 400; k++) {
        dpt tri[3], quad[4];
        int i, h;
        for (i = 0; i < 3; i++) {
            seed = seed * 1103515245u + 12345u;
            /* k % 4: anywhere in 1/16 steps, on half pixels (centres and
             * edges; every other one with a horizontal edge), a needle (x
             * nearly equal), partly outside */
            if (k % 4 == 1) {
                tri[i].x = (double)((seed >> 8) % 80) / 2.0;
                tri[i].y = (double)((seed >> 20) % 60) / 2.0;
            } else {
                tri[i].x = (double)((seed >> 4) % 640) / 16.0;
                tri[i].y = (double)((seed >> 16) % 480) / 16.0;
            }
            if (k % 4 == 2)
                tri[i].x = 20.0 + (double)((seed >> 4) % 9) / 16.0;
            if (k % 4 == 3) {
                tri[i].x = tri[i].x * 1.5 - 10.0;
                tri[i].y = tri[i].y * 1.5 - 7.0;
            }
        }
        if (k % 8 == 1)
            tri[1].y = tri[0].y; /* a horizontal edge, top or bottom, often on row centres */
        for (i = 0; i < 3; i++)
            quad[i] = tri[i];
        quad[3] = tri[2];
        for (h = 0; h < 2; h++) {
            stp_hidden hidden = h ? STP_HIDDEN_ZBUFFER : STP_HIDDEN_NONE;
            int na, nb, nc;
            uint8_t *a = render_one(tri, 3, hidden, 30, &na), *b = render_one(quad, 4, hidden, 30, &nb),
                    *c = render_one(tri, 3, hidden, 3, &nc);
            size_t px;
            /* unclipped: the triangle path against the general one */
            compared += na == 3 && nb == 4;
            if (memcmp(a, b, 40 * 30) != 0 || memcmp(a, c, 40 * 30) != 0)
                fail_msg("triangle %d (%g,%g) (%g,%g) (%g,%g), hidden %d: the triangle path differs", k,
                         tri[0].x, tri[0].y, tri[1].x, tri[1].y, tri[2].x, tri[2].y, (int)hidden);
            for (px = 0; px < 40 * 30; px++)
                drawn += a[px] == 7;
            free(a);
            free(b);
            free(c);
        }
    }
    assert_true(compared >= 400); /* most triangles lie inside the view */
    assert_true(drawn > 10000);   /* and painted pixels */
}

/* The triangle path's depths (src/raster.c: depth_setup_triangle,
 * tri_depth_start, tri_span_z) decide which of many interpenetrating
 * random triangles shows at each pixel: small ones of a few pixels (the
 * mesh torus's), larger and needle-thin ones, steep depth slopes among
 * them, and diagonal slivers two subpixels wide (gradients' factors short
 * enough for 32 bits, their depth terms not).  Their frames (STYLE8, and
 * MONO1 through the direct pattern spans) hash to the value the scan
 * converter gave before its set-up was made cheaper, in the host's and
 * the 32-bit targets' arithmetic alike (test_raster_narrow), whole, in
 * 5-row bands and with kept setups (the latter found triangles whose top
 * lay in a band above their first row drawn from an unmade setup). */
static uint32_t frame_hash(uint32_t h, const uint8_t *p, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++)
        h = (h ^ p[i]) * 16777619u; /* FNV-1a */
    return h;
}

static void test_triangle_depths_unchanged(void **state)
{
    static const stp_pixel_format formats[] = {STP_PIXEL_STYLE8, STP_PIXEL_MONO1};
    static const uint32_t bands[] = {0, 5};
    fixture f;
    uint32_t seed = 2024u, h = 2166136261u;
    int k, fm, b, keep;
    (void)state;
    fixture_open(&f, 64, 48, 4096);
    for (k = 0; k < 600; k++) {
        stp_vec3 v[3];
        double cx, cy, size = k % 5 == 0 ? 40.0 : (k % 5 == 1 ? 12.0 : 4.0);
        int i;
        seed = seed * 1103515245u + 12345u;
        cx = (double)((seed >> 8) % 1024) / 16.0;
        seed = seed * 1103515245u + 12345u;
        cy = (double)((seed >> 8) % 768) / 16.0;
        if (k % 11 == 5) { /* a diagonal sliver's long edge through pixel centres */
            cx = floor(cx / 2.0) + 0.5;
            cy = floor(cy / 4.0) + 0.5;
        }
        for (i = 0; i < 3; i++) {
            double dx, dy, z;
            seed = seed * 1103515245u + 12345u;
            dx = ((double)((seed >> 4) % 1024) / 1023.0 - 0.5) * size;
            dy = ((double)((seed >> 16) % 1024) / 1023.0 - 0.5) * size;
            if (k % 7 == 3)
                dx *= 0.05; /* a needle */
            seed = seed * 1103515245u + 12345u;
            z = ((double)((seed >> 8) % 4096) / 4096.0 - 0.5) * (k % 3 == 0 ? 9.0 : 1.5);
            if (k % 11 == 5) { /* steep gradients across it: long depth terms */
                dx = i == 0 ? 0.0 : (i == 1 ? 15.0 + 2.0 / 16.0 : 30.0);
                dy = i == 0 ? 0.0 : (i == 1 ? 15.0 : 30.0);
                z *= 0.3 / (k % 3 == 0 ? 9.0 : 1.5);
            }
            v[i] = dev(&f, floor((cx + dx) * 16.0) / 16.0, floor((cy + dy) * 16.0) / 16.0, z);
        }
        stp_renderer_set_fill_style(f.r, 1 + k % 7);
        assert_int_equal(stp_renderer_polygon(f.r, v, 3), STP_OK);
    }
    for (fm = 0; fm < 2; fm++) {
        render_opts o = opts(formats[fm], STP_HIDDEN_ZBUFFER);
        size_t size = stp_row_bytes(formats[fm], f.w) * f.h;
        uint8_t *whole;
        int status;
        whole = render(&f, &o, &status);
        assert_int_equal(status, STP_OK);
        h = frame_hash(h, whole, size);
        for (b = 0; b < 2; b++)
            for (keep = 0; keep < 2; keep++) {
                uint8_t *banded;
                o.band_rows = bands[b];
                o.keep_setup = keep;
                banded = render(&f, &o, &status);
                assert_int_equal(status, STP_OK);
                if (memcmp(whole, banded, size) != 0)
                    fail_msg("format %d, band_rows %u, kept setups %d: differs from the whole frame", (int)formats[fm],
                             bands[b], keep);
                free(banded);
            }
        free(whole);
    }
    fixture_close(&f);
    print_message("triangle depths: frame hash %08x\n", h);
#if !STP_DIRECT_COMPACT
    assert_int_equal(h, 0x49a757a2u);
#else
    /* compact builds walk a triangle across the picture's edge whole
     * (project_private.h's guard band) where this frame's was clipped:
     * other pixels there, checked against the fill rule written out per
     * pixel by test_direct_walk (direct drawing's walk) and
     * test_direct_equal_compact (the renderer's equals it); the bands and
     * kept setups against the whole frame above */
    (void)h;
#endif
}

/* Lines across the picture's edges are clipped to the picture (in every
 * build: the guard band of compact builds, project_private.h, is the
 * polygons' alone): a row and a column across the whole picture, a line
 * wholly left of it, and one wholly beyond the guard band above it, drawn
 * exactly where written out here. */
static void test_lines_across_the_edges(void **state)
{
    fixture f;
    render_opts o = opts(STP_PIXEL_STYLE8, STP_HIDDEN_NONE);
    uint8_t *frame;
    uint32_t x, y;
    int status;
    (void)state;
    fixture_open(&f, 40, 30, 256);
    stp_renderer_set_fill_style(f.r, 16);
    assert_int_equal(stp_renderer_move(f.r, dev(&f, -40.5, 10.5, -3)), STP_OK);
    assert_int_equal(stp_renderer_line(f.r, dev(&f, 80.5, 10.5, -3)), STP_OK);
    assert_int_equal(stp_renderer_move(f.r, dev(&f, 5.5, -30.5, -3)), STP_OK);
    assert_int_equal(stp_renderer_line(f.r, dev(&f, 5.5, 70.5, -3)), STP_OK);
    assert_int_equal(stp_renderer_move(f.r, dev(&f, -100.5, 3.5, -3)), STP_OK);
    assert_int_equal(stp_renderer_line(f.r, dev(&f, -20.5, 20.5, -3)), STP_OK);
    assert_int_equal(stp_renderer_move(f.r, dev(&f, -900.5, -700.5, -3)), STP_OK);
    assert_int_equal(stp_renderer_line(f.r, dev(&f, 900.5, -600.5, -3)), STP_OK);
    assert_int_equal(stp_segment_close(f.r), STP_OK);
    frame = render(&f, &o, &status);
    assert_int_equal(status, STP_OK);
    for (y = 0; y < f.h; y++)
        for (x = 0; x < f.w; x++)
            if (frame[y * f.w + x] != (y == 10 || x == 5 ? 16 : 0))
                fail_msg("pixel (%u, %u) is %d", x, y, frame[y * f.w + x]);
    free(frame);
    fixture_close(&f);
}

/* A setup array shorter than the polygon count is refused, not overrun. */
static void test_short_setup_array_is_refused(void **state)
{
    fixture f;
    capture c;
    stp_output out;
    stp_frame_memory mem;
    stp_polygon_setup one;
    uint8_t band[37 * 29];
    uint16_t zbuf[37 * 29];
    (void)state;
    fixture_open(&f, 37, 29, 256);
    enter_band_scene(&f);
    assert_true(stp_renderer_polygon_count(f.r) > 1);
    memset(&c, 0, sizeof c);
    c.port.width = f.w;
    c.port.height = f.h;
    c.port.format = STP_PIXEL_GREY8;
    c.port.flush = flush_copy;
    c.port.user = &c;
    c.stride = f.w;
    c.fail_on_flush = -1;
    c.frame = calloc(f.h, c.stride);
    assert_non_null(c.frame);
    memset(&out, 0, sizeof out);
    out.hidden = STP_HIDDEN_ZBUFFER;
    memset(&mem, 0, sizeof mem);
    mem.band = band;
    mem.band_rows = f.h;
    mem.band_size = sizeof band;
    mem.zbuf = zbuf;
    mem.zbuf_count = sizeof zbuf / sizeof zbuf[0];
    mem.setup = &one;
    mem.setup_count = 1;
    assert_int_equal(stp_renderer_render(f.r, &c.port, &out, &mem), STP_ERR_MEMORY);
    assert_int_equal(c.flushes, 0);
    free(c.frame);
    fixture_close(&f);
}

static void test_mono1_row_padding_is_zero(void **state)
{
    /* MONO1 rows are padded to whole bytes; the bits past the width are not
     * pixels, but they reach the port (a PBM writer copies them): they must
     * be 0, not whatever the caller's band buffer held before (render()
     * fills it with 0xA5 first). */
    static const uint32_t bands[3] = {1, 3, 29};
    fixture f;
    int b, m;
    (void)state;
    fixture_open(&f, 37, 29, 256);
    enter_band_scene(&f);
    for (m = 0; m < 3; m++)
        for (b = 0; b < 3; b++) {
            render_opts o = opts(STP_PIXEL_MONO1, (stp_hidden)m);
            uint8_t *frame;
            int status;
            uint32_t y;
            o.band_rows = bands[b];
            o.background = ONE; /* white: every pixel bit is 1 where nothing is drawn */
            frame = render(&f, &o, &status);
            assert_int_equal(status, STP_OK);
            for (y = 0; y < f.h; y++)
                if ((frame[y * 5 + 4] & 0x07) != 0) /* pixels 37..39 */
                    fail_msg("hidden %d band_rows %u: row %u padding bits 0x%02x", m, bands[b], y,
                             frame[y * 5 + 4] & 0x07);
            free(frame);
        }
    fixture_close(&f);
}

/* ---- display file and segments ---- */

static void test_display_file_full_leaves_it_unchanged(void **state)
{
    static const dpt sq[4] = {{2, 2}, {6, 2}, {6, 6}, {2, 6}};
    static const dpt tri[3] = {{8, 8}, {14, 8}, {8, 14}};
    fixture f;
    uint32_t used;
    uint8_t *before, *after;
    stp_instr snapshot[14];
    int k, status;
    (void)state;
    fixture_open(&f, 16, 16, 14);
    /* 5 entries (style + 4), then 4 (same style) */
    assert_int_equal(poly(&f, sq, 4, 0, 3), STP_OK);
    assert_int_equal(stp_renderer_display_file_used(f.r), 5);
    assert_int_equal(poly(&f, sq, 4, 0, 3), STP_OK);
    assert_int_equal(stp_renderer_display_file_used(f.r), 9);
    /* a triangle with a new style needs 4: fits (13) */
    assert_int_equal(poly(&f, tri, 3, 0, 7), STP_OK);
    assert_int_equal(stp_renderer_display_file_used(f.r), 13);
    used = stp_renderer_display_file_used(f.r);
    memcpy(snapshot, f.df, sizeof snapshot);
    before = render_styles(&f, STP_HIDDEN_NONE);
    /* neither another square nor a triangle of a new style fits in 1 */
    for (k = 0; k < 3; k++) {
        status = k == 0 ? poly(&f, sq, 4, 0, 3) : poly(&f, tri, 3, 0, 7 + k);
        assert_int_equal(status, STP_ERR_FULL);
        assert_int_equal(stp_renderer_display_file_used(f.r), used);
        assert_memory_equal(snapshot, f.df, sizeof snapshot);
    }
    after = render_styles(&f, STP_HIDDEN_NONE);
    assert_memory_equal(before, after, 16 * 16);
    /* and the file still works: a segment can still be closed and drawn */
    assert_int_equal(stp_segment_close(f.r), STP_OK);
    free(before);
    free(after);
    fixture_close(&f);
}

static void test_segment_table_full(void **state)
{
    fixture f;
    int id;
    (void)state;
    fixture_open(&f, 8, 8, 64); /* segment 1 is open */
    assert_int_equal(stp_segment_close(f.r), STP_OK);
    for (id = 2; id <= STP_MAX_SEGMENTS; id++) {
        assert_int_equal(stp_segment_create(f.r, id), STP_OK);
        assert_int_equal(stp_segment_close(f.r), STP_OK);
    }
    assert_int_equal(stp_segment_create(f.r, 1000), STP_ERR_FULL);
    assert_int_equal(stp_segment_delete(f.r, 5), STP_OK);
    assert_int_equal(stp_segment_create(f.r, 1000), STP_OK);
    fixture_close(&f);
}

/* Points beyond the range of view coordinates (stp_fix, within +-32767 of
 * the eye along each view axis; the eye here is at z = -10) are refused
 * with STP_ERR_RANGE and enter nothing, instead of being drawn moved to
 * the edge of the range: world z 32760 is 32770 from the eye.  Ranges in
 * stp_fix end at 32767.99998. */
static void test_range_refused(void **state)
{
    fixture f;
    stp_vec3 v[3];
    stp_transform t;
    uint32_t used;
    (void)state;
    fixture_open(&f, 8, 8, 64);
    v[0] = vec(0, 0, 0);
    v[1] = vec(4, 0, 0);
    v[2] = vec(0, 4, 32760);
    used = stp_renderer_display_file_used(f.r);
    assert_int_equal(stp_renderer_polygon(f.r, v, 3), STP_ERR_RANGE);
    assert_int_equal(stp_renderer_display_file_used(f.r), used);
    /* 32757 from the eye: within range, entered */
    v[2] = vec(0, 4, 32747);
    assert_int_equal(stp_renderer_polygon(f.r, v, 3), STP_OK);
    assert_true(stp_renderer_display_file_used(f.r) > used);
    /* the edge: 32767.5 from the eye is held, 32768 is not */
    v[2] = vec(0, 4, 32757.5);
    assert_int_equal(stp_renderer_polygon(f.r, v, 3), STP_OK);
    v[2] = vec(0, 4, 32758);
    assert_int_equal(stp_renderer_polygon(f.r, v, 3), STP_ERR_RANGE);
    /* lines: the far point is refused and the pen stays where it was */
    assert_int_equal(stp_renderer_move(f.r, vec(0, 0, 32760)), STP_ERR_RANGE);
    assert_int_equal(stp_renderer_move(f.r, vec(0, 0, 0)), STP_OK);
    used = stp_renderer_display_file_used(f.r);
    assert_int_equal(stp_renderer_line(f.r, vec(1, 1, 40000.0 - 10000.0)), STP_OK);
    assert_int_equal(stp_renderer_line(f.r, vec(1, 1, 32760)), STP_ERR_RANGE);
    /* the model transform saturating (10000 x 4) is refused too */
    stp_transform_identity(&t);
    stp_transform_scale(&t, fx(4), fx(4), fx(4));
    assert_int_equal(stp_renderer_set_transform(f.r, &t), STP_OK);
    v[0] = vec(0, 0, 0);
    v[1] = vec(1, 0, 0);
    v[2] = vec(0, 1, 0);
    assert_int_equal(stp_renderer_polygon(f.r, v, 3), STP_OK);
    v[2] = vec(0, 10000, 0);
    assert_int_equal(stp_renderer_polygon(f.r, v, 3), STP_ERR_RANGE);
    assert_string_equal(stp_status_text(STP_ERR_RANGE),
                        "coordinate beyond the range of view coordinates");
    fixture_close(&f);
}

static void test_segment_errors(void **state)
{
    static const dpt tri[3] = {{1, 1}, {6, 1}, {1, 6}};
    fixture f;
    (void)state;
    fixture_open(&f, 8, 8, 64); /* segment 1 is open */
    assert_int_equal(stp_segment_create(f.r, 2), STP_ERR_SEGMENT); /* one is open */
    assert_int_equal(stp_segment_delete(f.r, 1), STP_ERR_SEGMENT); /* open: not deletable */
    assert_int_equal(stp_segment_close(f.r), STP_OK);
    assert_int_equal(stp_segment_close(f.r), STP_ERR_SEGMENT);     /* none open */
    assert_int_equal(stp_segment_create(f.r, 1), STP_ERR_SEGMENT); /* id exists */
    assert_int_equal(stp_segment_delete(f.r, 77), STP_ERR_SEGMENT);
    assert_int_equal(stp_segment_visibility(f.r, 77, 0), STP_ERR_SEGMENT);
    assert_int_equal(stp_segment_create(f.r, -1), STP_ERR_ARG);
    assert_int_equal(stp_segment_create(f.r, 32768), STP_ERR_ARG);
    /* drawing with no open segment opens an implicit one, id -1, which
     * stp_segment_create ends */
    assert_int_equal(poly(&f, tri, 3, 0, 3), STP_OK);
    assert_int_equal(stp_renderer_move(f.r, vec(0, 0, 0)), STP_OK);
    assert_int_equal(stp_renderer_line(f.r, vec(1, 1, 0)), STP_OK);
    assert_true(stp_renderer_display_file_used(f.r) > 0);
    assert_int_equal(stp_segment_delete(f.r, -1), STP_ERR_SEGMENT); /* open */
    assert_int_equal(stp_segment_create(f.r, 2), STP_OK);
    assert_int_equal(stp_segment_delete(f.r, -1), STP_OK);
    assert_int_equal(stp_renderer_display_file_used(f.r), 0);
    /* degenerate and oversized polygons */
    {
        stp_vec3 v[STP_MAX_POLYGON_VERTICES + 1];
        int i;
        for (i = 0; i < 3; i++)
            v[i] = vec(1, 1, 0);
        assert_int_equal(stp_renderer_polygon(f.r, v, 3), STP_ERR_DEGENERATE); /* repeated */
        v[0] = vec(0, 0, 0);
        v[1] = vec(1, 1, 0);
        v[2] = vec(2, 2, 0);
        assert_int_equal(stp_renderer_polygon(f.r, v, 3), STP_ERR_DEGENERATE); /* collinear */
        assert_int_equal(stp_renderer_polygon(f.r, v, 2), STP_ERR_DEGENERATE);
        for (i = 0; i <= STP_MAX_POLYGON_VERTICES; i++)
            v[i] = vec(cos(i * 0.01), sin(i * 0.01), 0);
        assert_int_equal(stp_renderer_polygon(f.r, v, STP_MAX_POLYGON_VERTICES + 1), STP_ERR_TOO_MANY_VERTICES);
        assert_int_equal(stp_renderer_polygon(f.r, NULL, 3), STP_ERR_ARG);
    }
    assert_int_equal(stp_renderer_display_file_used(f.r), 0);
    fixture_close(&f);
}

static void test_segment_delete_compacts_and_visibility(void **state)
{
    static const dpt a[4] = {{1, 1}, {10, 1}, {10, 10}, {1, 10}};
    static const dpt b1[3] = {{12, 2}, {30, 2}, {12, 20}};
    static const dpt b2[3] = {{20, 20}, {30, 20}, {30, 30}};
    static const dpt c[4] = {{2, 22}, {9, 22}, {9, 30}, {2, 30}};
    static const dpt d[3] = {{14, 24}, {18, 24}, {14, 28}};
    fixture f, ref;
    uint32_t used_all, used_b;
    uint8_t *got, *want;
    (void)state;
    fixture_open(&f, 32, 32, 256); /* segment 1 open */
    assert_int_equal(poly(&f, a, 4, 0, 3), STP_OK);
    assert_int_equal(stp_segment_close(f.r), STP_OK);
    used_b = stp_renderer_display_file_used(f.r);
    assert_int_equal(stp_segment_create(f.r, 2), STP_OK);
    assert_int_equal(poly(&f, b1, 3, 0, 5), STP_OK);
    assert_int_equal(poly(&f, b2, 3, 0, 6), STP_OK);
    assert_int_equal(stp_segment_close(f.r), STP_OK);
    used_b = stp_renderer_display_file_used(f.r) - used_b;
    assert_int_equal(stp_segment_create(f.r, 3), STP_OK);
    assert_int_equal(poly(&f, c, 4, 0, 8), STP_OK);
    assert_int_equal(stp_segment_close(f.r), STP_OK);
    used_all = stp_renderer_display_file_used(f.r);
    assert_int_equal(stp_renderer_polygon_count(f.r), 4);

    /* delete the middle segment: the file shrinks by its length and the
     * picture is that of segments 1 and 3 alone */
    assert_int_equal(stp_segment_delete(f.r, 2), STP_OK);
    assert_int_equal(stp_renderer_display_file_used(f.r), used_all - used_b);
    assert_int_equal(stp_renderer_polygon_count(f.r), 2);
    fixture_open(&ref, 32, 32, 256);
    assert_int_equal(poly(&ref, a, 4, 0, 3), STP_OK);
    assert_int_equal(stp_segment_close(ref.r), STP_OK);
    assert_int_equal(stp_segment_create(ref.r, 3), STP_OK);
    assert_int_equal(poly(&ref, c, 4, 0, 8), STP_OK);
    assert_int_equal(stp_segment_close(ref.r), STP_OK);
    got = render_styles(&f, STP_HIDDEN_NONE);
    want = render_styles(&ref, STP_HIDDEN_NONE);
    assert_memory_equal(got, want, 32 * 32);
    assert_int_equal(count_style(&f, got, 5) + count_style(&f, got, 6), 0);
    free(got);
    free(want);

    /* a new segment after the compaction, reusing the id */
    assert_int_equal(stp_segment_create(f.r, 2), STP_OK);
    assert_int_equal(poly(&f, d, 3, 0, 10), STP_OK);
    assert_int_equal(stp_segment_close(f.r), STP_OK);
    assert_int_equal(stp_segment_create(ref.r, 2), STP_OK);
    assert_int_equal(poly(&ref, d, 3, 0, 10), STP_OK);
    assert_int_equal(stp_segment_close(ref.r), STP_OK);
    got = render_styles(&f, STP_HIDDEN_ZBUFFER);
    want = render_styles(&ref, STP_HIDDEN_ZBUFFER);
    assert_memory_equal(got, want, 32 * 32);
    assert_true(count_style(&f, got, 3) > 0 && count_style(&f, got, 8) > 0 && count_style(&f, got, 10) > 0);
    free(got);
    free(want);

    /* an invisible segment is not drawn (nor counted for the painter) */
    assert_int_equal(stp_segment_visibility(f.r, 3, 0), STP_OK);
    assert_int_equal(stp_renderer_polygon_count(f.r), 2);
    got = render_styles(&f, STP_HIDDEN_PAINTER);
    assert_int_equal(count_style(&f, got, 8), 0);
    assert_true(count_style(&f, got, 3) > 0);
    free(got);
    assert_int_equal(stp_segment_visibility(f.r, 3, 1), STP_OK);
    got = render_styles(&f, STP_HIDDEN_PAINTER);
    assert_true(count_style(&f, got, 8) > 0);
    free(got);
    fixture_close(&f);
    fixture_close(&ref);
}

/* ---- hither clipping ---- */

static void set_perspective_view(fixture *f)
{
    stp_view v;
    memset(&v, 0, sizeof v);
    v.from = vec(0, 0, -10);
    v.at = vec(0, 0, 0);
    v.up = vec(0, 1, 0);
    v.fov_degrees = fx(90);
    v.window_half = fx(1);
    v.hither = fx(1);
    v.projection = STP_PERSPECTIVE;
    assert_int_equal(stp_renderer_set_view(f->r, &v), STP_OK);
}

static void test_hither_clipping(void **state)
{
    /* A floor at y = -1 from 3 behind the eye (view z = -3) to 5 ahead of it;
     * the hither plane is at view z = 1, halfway along each receding edge,
     * so the clipped polygon is exactly the floor from view z = 1 to 5.
     * Rendered, the two must be the same picture, and nothing may appear
     * above the horizon (the part behind the eye would project there,
     * upside down, if it were not clipped). */
    static const double xs[2] = {-2, 2};
    fixture crossing, clipped;
    stp_vec3 a[4], b[4];
    uint8_t *fa, *fb;
    uint32_t i, j;
    int drawn = 0;
    (void)state;
    fixture_open(&crossing, 32, 32, 256);
    fixture_open(&clipped, 32, 32, 256);
    set_perspective_view(&crossing);
    set_perspective_view(&clipped);
    /* world z = view z - 10 */
    a[0] = vec(xs[0], -1, -13);
    a[1] = vec(xs[0], -1, -5);
    a[2] = vec(xs[1], -1, -5);
    a[3] = vec(xs[1], -1, -13);
    b[0] = vec(xs[0], -1, -9);
    b[1] = vec(xs[0], -1, -5);
    b[2] = vec(xs[1], -1, -5);
    b[3] = vec(xs[1], -1, -9);
    stp_renderer_set_fill_style(crossing.r, 6);
    stp_renderer_set_fill_style(clipped.r, 6);
    assert_int_equal(stp_renderer_polygon(crossing.r, a, 4), STP_OK);
    assert_int_equal(stp_renderer_polygon(clipped.r, b, 4), STP_OK);
    fa = render_styles(&crossing, STP_HIDDEN_ZBUFFER);
    fb = render_styles(&clipped, STP_HIDDEN_ZBUFFER);
    assert_memory_equal(fa, fb, 32 * 32);
    for (j = 0; j < 32; j++)
        for (i = 0; i < 32; i++) {
            if (fa[j * 32 + i] == 6) {
                drawn++;
                if (j < 16)
                    fail_msg("pixel (%u,%u) above the horizon: the part behind the eye was drawn", i, j);
            }
        }
    /* the floor's far edge projects to y = 16 + 16/5 = 19.2, 2 units either
     * side to x = 16 -+ 6.4; it reaches the bottom of the frame */
    assert_true(drawn > 100);
    assert_int_equal(fa[31 * 32 + 16], 6);
    assert_int_not_equal(fa[18 * 32 + 16], 6);
    free(fa);
    free(fb);
    fixture_close(&crossing);
    fixture_close(&clipped);
}

static void test_polygon_behind_the_eye_enters_nothing(void **state)
{
    fixture f;
    stp_vec3 v[3];
    uint8_t *frame;
    (void)state;
    fixture_open(&f, 32, 32, 256);
    set_perspective_view(&f);
    v[0] = vec(-1, -1, -12);
    v[1] = vec(1, -1, -12);
    v[2] = vec(0, 1, -15);
    assert_int_equal(stp_renderer_polygon(f.r, v, 3), STP_OK);
    assert_int_equal(stp_renderer_display_file_used(f.r), 0);
    /* a wall through the eye's own plane, steeply: clipped, drawn, no crash */
    v[0] = vec(-30, -30, -20);
    v[1] = vec(30, -30, 5);
    v[2] = vec(0, 30, -8);
    assert_int_equal(stp_renderer_polygon(f.r, v, 3), STP_OK);
    frame = render_styles(&f, STP_HIDDEN_ZBUFFER);
    assert_true(count_style(&f, frame, 16) > 0);
    free(frame);
    fixture_close(&f);
}

/* ---- the caller's buffers and the port ---- */

static void test_render_rejects_small_buffers(void **state)
{
    static const dpt tri[3] = {{1, 1}, {6, 1}, {1, 6}};
    fixture f;
    capture c;
    stp_output out;
    stp_frame_memory mem;
    uint8_t band[64 * 4];
    uint16_t zbuf[64 * 4];
    stp_sort_entry sort[4];
    (void)state;
    fixture_open(&f, 64, 8, 64);
    assert_int_equal(poly(&f, tri, 3, 0, 3), STP_OK);
    assert_int_equal(poly(&f, tri, 3, 1, 4), STP_OK);
    memset(&c, 0, sizeof c);
    c.port.width = 64;
    c.port.height = 8;
    c.port.format = STP_PIXEL_GREY8;
    c.port.flush = flush_copy;
    c.port.user = &c;
    c.stride = 64;
    c.fail_on_flush = -1;
    c.frame = calloc(8, 64);
    memset(&out, 0, sizeof out);
    memset(&mem, 0, sizeof mem);
    mem.band = band;
    mem.band_rows = 4;
    mem.band_size = 64 * 4 - 1; /* one byte short */
    out.hidden = STP_HIDDEN_NONE;
    assert_int_equal(stp_renderer_render(f.r, &c.port, &out, &mem), STP_ERR_MEMORY);
    assert_int_equal(c.flushes, 0);
    mem.band_size = 64 * 4;
    assert_int_equal(stp_renderer_render(f.r, &c.port, &out, &mem), STP_OK);
    /* Z buffer: width * band_rows entries */
    out.hidden = STP_HIDDEN_ZBUFFER;
    mem.zbuf = zbuf;
    mem.zbuf_count = 64 * 4 - 1;
    assert_int_equal(stp_renderer_render(f.r, &c.port, &out, &mem), STP_ERR_MEMORY);
    mem.zbuf = NULL;
    mem.zbuf_count = 64 * 4;
    assert_int_equal(stp_renderer_render(f.r, &c.port, &out, &mem), STP_ERR_MEMORY);
    mem.zbuf = zbuf;
    assert_int_equal(stp_renderer_render(f.r, &c.port, &out, &mem), STP_OK);
    /* painter: one entry per polygon */
    out.hidden = STP_HIDDEN_PAINTER;
    mem.sort = sort;
    mem.sort_count = 1;
    assert_int_equal(stp_renderer_render(f.r, &c.port, &out, &mem), STP_ERR_MEMORY);
    mem.sort_count = 2;
    assert_int_equal(stp_renderer_render(f.r, &c.port, &out, &mem), STP_OK);
    /* band rows out of range, wrong port size, no flush */
    mem.band_rows = 0;
    assert_int_equal(stp_renderer_render(f.r, &c.port, &out, &mem), STP_ERR_ARG);
    mem.band_rows = 9;
    assert_int_equal(stp_renderer_render(f.r, &c.port, &out, &mem), STP_ERR_ARG);
    mem.band_rows = 4;
    c.port.width = 63;
    assert_int_equal(stp_renderer_render(f.r, &c.port, &out, &mem), STP_ERR_ARG);
    c.port.width = 64;
    out.hidden = (stp_hidden)7;
    assert_int_equal(stp_renderer_render(f.r, &c.port, &out, &mem), STP_ERR_ARG);
    out.hidden = STP_HIDDEN_NONE;
    /* the port stops the frame */
    c.flushes = 0;
    c.next_y = 0;
    c.fail_on_flush = 1;
    assert_int_equal(stp_renderer_render(f.r, &c.port, &out, &mem), STP_ERR_PORT);
    assert_int_equal(c.flushes, 2);
    free(c.frame);
    fixture_close(&f);
}

static void test_renderer_create_rejects_bad_arguments(void **state)
{
    stp_instr df[4];
    void *mem = malloc(stp_renderer_size());
    (void)state;
    assert_non_null(mem);
    assert_null(stp_renderer_create(NULL, stp_renderer_size(), df, 4, 8, 8));
    assert_null(stp_renderer_create(mem, stp_renderer_size() - 1, df, 4, 8, 8));
    assert_null(stp_renderer_create(mem, stp_renderer_size(), NULL, 4, 8, 8));
    assert_null(stp_renderer_create(mem, stp_renderer_size(), df, 0, 8, 8));
    assert_null(stp_renderer_create(mem, stp_renderer_size(), df, 4, 0, 8));
    assert_null(stp_renderer_create(mem, stp_renderer_size(), df, 4, 8, 32768));
    assert_non_null(stp_renderer_create(mem, stp_renderer_size(), df, 4, 32767, 1));
    free(mem);
}

/* ---- style output ---- */

static void test_style8_background_and_style_table(void **state)
{
    static const dpt sq[4] = {{2, 2}, {6, 2}, {6, 6}, {2, 6}};
    static const uint8_t codes[16] = {'@', '#', '%', '*', '+', '=', '-', ':', '.', ',', '\'', '`',
                                      '^', '"', '~', ' '};
    stp_style_table table = {16, codes};
    fixture f;
    render_opts o;
    uint8_t *frame;
    int status;
    (void)state;
    fixture_open(&f, 8, 8, 64);
    assert_int_equal(poly(&f, sq, 4, 0, 5), STP_OK);
    /* port.h: without a table the pixel is the index itself, 0 where
     * nothing is drawn and the background is 0 */
    o = opts(STP_PIXEL_STYLE8, STP_HIDDEN_NONE);
    frame = render(&f, &o, &status);
    assert_int_equal(status, STP_OK);
    assert_int_equal(frame[3 * 8 + 3], 5);
    assert_int_equal(frame[0], 0);
    free(frame);
    /* a background shade picks its INTENSITY index */
    o.background = ONE;
    frame = render(&f, &o, &status);
    assert_int_equal(frame[0], 16);
    assert_int_equal(frame[3 * 8 + 3], 5);
    free(frame);
    /* with a table: the codes */
    o.background = 0;
    o.styles = &table;
    frame = render(&f, &o, &status);
    assert_int_equal(status, STP_OK);
    assert_int_equal(frame[3 * 8 + 3], '+');
    assert_int_equal(frame[0], '@');
    free(frame);
    fixture_close(&f);
}

static void test_grey8_levels_and_gamma(void **state)
{
    static const dpt sq[4] = {{2, 2}, {6, 2}, {6, 6}, {2, 6}};
    uint8_t gamma[16];
    fixture f;
    render_opts o;
    uint8_t *frame;
    int status, k;
    (void)state;
    for (k = 0; k < 16; k++)
        gamma[k] = (uint8_t)(200 - k);
    fixture_open(&f, 8, 8, 64);
    assert_int_equal(poly(&f, sq, 4, 0, 6), STP_OK);
    o = opts(STP_PIXEL_GREY8, STP_HIDDEN_NONE);
    frame = render(&f, &o, &status);
    /* linear: (index - 1) * 255 / 15 rounded: style 6 -> 85 */
    assert_int_equal(frame[3 * 8 + 3], 85);
    assert_int_equal(frame[0], 0);
    free(frame);
    o.gamma = gamma;
    frame = render(&f, &o, &status);
    assert_int_equal(frame[3 * 8 + 3], 195);
    assert_int_equal(frame[0], 200);
    free(frame);
    fixture_close(&f);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_fill_rule_two_triangles_share_diagonal),
        cmocka_unit_test(test_fill_rule_top_left_ties),
        cmocka_unit_test(test_fill_rule_fan_has_no_gaps_or_overlaps),
        cmocka_unit_test(test_fill_rule_concave_and_even_odd),
        cmocka_unit_test(test_hidden_surfaces_nearer_square_wins),
        cmocka_unit_test(test_zbuffer_interpenetrating_polygons),
        cmocka_unit_test(test_backface_removal_keeps_faces_towards_viewer),
        cmocka_unit_test(test_backface_removal_single_polygon),
        cmocka_unit_test(test_backface_removal_before_transform_matches_double),
        cmocka_unit_test(test_backface_removal_out_of_range_is_refused),
        cmocka_unit_test(test_bands_give_the_same_frame),
        cmocka_unit_test(test_triangle_path_matches_general_path),
        cmocka_unit_test(test_triangle_depths_unchanged),
        cmocka_unit_test(test_lines_across_the_edges),
        cmocka_unit_test(test_short_setup_array_is_refused),
        cmocka_unit_test(test_mono1_row_padding_is_zero),
        cmocka_unit_test(test_display_file_full_leaves_it_unchanged),
        cmocka_unit_test(test_segment_table_full),
        cmocka_unit_test(test_segment_errors),
        cmocka_unit_test(test_segment_delete_compacts_and_visibility),
        cmocka_unit_test(test_hither_clipping),
        cmocka_unit_test(test_polygon_behind_the_eye_enters_nothing),
        cmocka_unit_test(test_render_rejects_small_buffers),
        cmocka_unit_test(test_renderer_create_rejects_bad_arguments),
        cmocka_unit_test(test_range_refused),
        cmocka_unit_test(test_style8_background_and_style_table),
        cmocka_unit_test(test_grey8_levels_and_gamma),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
