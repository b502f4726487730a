/* SPDX-License-Identifier: MIT */
/*
 * stp_renderer_mesh's proof that every vertex is inside the view volume
 * (src/mesh.c: box_inside, and ball_inside where a corner of the model's
 * rotated box is outside a plane), compiled once more here under other
 * names so that its static functions can be called.  Random point clouds
 * (balls, shells, boxes, slabs) under random rotations, scales and
 * offsets around the view volume's planes, at four frame sizes: whenever
 * either says inside, every point's outcode by the real transform is 0,
 * nothing saturates and its view coordinates are below 2^28.  The spinning
 * benchmark torus (tilt 20, spin 0..357 degrees, the bench's poses) is
 * proven inside in every pose at 128x64, though its box's corners stick
 * out in many, and its display files and frames there and in random
 * poses across the window's edges equal stp_renderer_polygon's, which
 * forms every vertex's outcode (no proof).  Again on the 32-bit target
 * arithmetic (test_mesh_ball_narrow).  Bounds prepared once
 * (stp_mesh_prepare_bounds) are the box and reach the per-call pass finds,
 * checked against an exact reference, and give the same proofs, display
 * files and frames.
 */
#define stp_renderer_mesh stp_renderer_mesh_ball
#define stp_mesh_prepare_normals stp_mesh_prepare_normals_ball
#define stp_mesh_prepare_bounds stp_mesh_prepare_bounds_ball
#include "mesh.c"
#undef stp_renderer_mesh
#undef stp_mesh_prepare_normals
#undef stp_mesh_prepare_bounds

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "torus.h"

#define CLOUD_MAX 96

static uint32_t seed = 20261206u;

static double uniform(double lo, double hi)
{
    seed = seed * 1664525u + 1013904223u;
    return lo + (hi - lo) * (double)(seed >> 8) / (double)(1u << 24);
}

static stp_fix fix_of(double v)
{
    return (stp_fix)lround(v * STP_FIX_ONE);
}

/* The model frame of transform t (NULL: none) set on b's renderer in a
 * fresh open segment, or NULL when the mesh path has none (not a
 * similarity). */
static const stp_model_frame *set_pose(torus_bench *b, const stp_transform *t)
{
    (void)stp_segment_close(b->r);
    (void)stp_segment_delete(b->r, 1);
    assert_int_equal(stp_segment_create(b->r, 1), STP_OK);
    assert_int_equal(stp_renderer_set_transform(b->r, t), STP_OK);
    return stp_render_model_frame(b->r);
}

/* Whether every point p[0..n) lands inside the view volume by the real
 * transform: outcode 0, nothing saturated, view coordinates below 2^28. */
static int all_inside(const stp_renderer *r, const stp_vec3 *p, int n)
{
    int i;
    for (i = 0; i < n; i++) {
        stp_vec3 v;
        if (stp_render_point_to_view(r, p[i], &v) || stp_view_saturated(v) ||
            stp_clip_outcode(&r->clip_volume, v) != 0 ||
            (stp_abs32(v.x) | stp_abs32(v.y) | stp_abs32(v.z)) >= ((uint32_t)1 << 28))
            return 0;
    }
    return 1;
}

/* Whether some corner of the box [lo, hi] is outside a plane (no margin):
 * where box_inside needs ball_inside. */
static int corner_out(const stp_renderer *r, stp_vec3 lo, stp_vec3 hi)
{
    int corner;
    for (corner = 0; corner < 8; corner++) {
        stp_vec3 p, v;
        p.x = (corner & 1) ? hi.x : lo.x;
        p.y = (corner & 2) ? hi.y : lo.y;
        p.z = (corner & 4) ? hi.z : lo.z;
        if (stp_render_point_to_view(r, p, &v) || stp_clip_outcode(&r->clip_volume, v) != 0)
            return 1;
    }
    return 0;
}

/* A random cloud of n points: a ball, a sphere's shell (the ball's worst
 * case), a box or a thin slab, of random size about a random centre. */
static int random_cloud(stp_vec3 *p)
{
    int n = 1 + (int)uniform(0, CLOUD_MAX), kind = (int)uniform(0, 4), i;
    double size = exp(uniform(log(0.02), log(3.0)));
    double cx = uniform(-1, 1), cy = uniform(-1, 1), cz = uniform(-1, 1);
    for (i = 0; i < n; i++) {
        double x = uniform(-1, 1), y = uniform(-1, 1), z = uniform(-1, 1), len = sqrt(x * x + y * y + z * z);
        if (kind <= 1 && len < 1e-3) {
            x = 1;
            len = 1;
        }
        if (kind == 0 && len > 1) { /* a ball: folded inside */
            x /= len * len;
            y /= len * len;
            z /= len * len;
        } else if (kind == 1) { /* a shell */
            x /= len;
            y /= len;
            z /= len;
        } else if (kind == 3) {
            y *= 0.05; /* a slab */
        }
        p[i].x = fix_of(cx + size * x);
        p[i].y = fix_of(cy + size * y);
        p[i].z = fix_of(cz + size * z);
    }
    return n;
}

/* A random model transform: none (1 in 8), else rotations about the three
 * axes, a uniform scale of 1/8 to 4 (the larger ones the two steps) and
 * an offset of up to 4 units, so that the clouds lie inside, across and
 * outside the planes of the torus view (the eye 6 units from the origin). */
static int random_transform(stp_transform *t)
{
    stp_vec3 d;
    double s;
    if (uniform(0, 8) < 1)
        return 0;
    stp_transform_identity(t);
    s = exp(uniform(log(0.125), log(4.0)));
    if (uniform(0, 2) < 1)
        s = 1;
    stp_transform_scale(t, fix_of(s), fix_of(s), fix_of(s));
    stp_transform_rotate(t, 0, fix_of(uniform(0, 360)));
    stp_transform_rotate(t, 1, fix_of(uniform(0, 360)));
    stp_transform_rotate(t, 2, fix_of(uniform(0, 360)));
    d.x = fix_of(uniform(-4, 4));
    d.y = fix_of(uniform(-3, 3));
    d.z = fix_of(uniform(-4, 4));
    stp_transform_translate(t, d);
    return 1;
}

__extension__ typedef unsigned __int128 u128; /* GCC and Clang on 64-bit hosts */
__extension__ typedef __int128 s128;

/* The exact largest squared distance of m's vertices from the centre of
 * their box [lo, hi] (as box_centre rounds it), in 128 bits. */
static u128 exact_reach2(const stp_mesh *m, stp_vec3 lo, stp_vec3 hi)
{
    u128 most = 0;
    int64_t c[3];
    int i;
    c[0] = ((int64_t)lo.x + hi.x) >> 1;
    c[1] = ((int64_t)lo.y + hi.y) >> 1;
    c[2] = ((int64_t)lo.z + hi.z) >> 1;
    for (i = 0; i < m->vertex_count; i++) {
        const stp_vec3 *v = &m->vertices[i];
        s128 dx = v->x - c[0], dy = v->y - c[1], dz = v->z - c[2];
        u128 d = (u128)(dx * dx + dy * dy + dz * dz);
        if (d > most)
            most = d;
    }
    return most;
}

/* m's bounds prepared once: the box of its vertices (an independent
 * scan), reach2 the exact one where 64-bit products are instructions, else
 * a bound within each difference's rounding (2^k, k the widest side's bits
 * less 15, each square rounded up); with them, the same proofs as the
 * per-call pass's (by_ball, by_stage). */
static void prepared_alike(const stp_renderer *r, stp_mesh *m, const stp_model_frame *f, int by_ball, int by_stage)
{
    stp_mesh_bounds pb;
    stp_vec3 lo = m->vertices[0], hi = m->vertices[0];
    u128 exact;
    int i, k;
    uint32_t span;
    assert_int_equal(stp_mesh_prepare_bounds_ball(m, &pb), STP_OK);
    for (i = 1; i < m->vertex_count; i++) {
        const stp_vec3 *v = &m->vertices[i];
        lo.x = v->x < lo.x ? v->x : lo.x;
        lo.y = v->y < lo.y ? v->y : lo.y;
        lo.z = v->z < lo.z ? v->z : lo.z;
        hi.x = v->x > hi.x ? v->x : hi.x;
        hi.y = v->y > hi.y ? v->y : hi.y;
        hi.z = v->z > hi.z ? v->z : hi.z;
    }
    assert_memory_equal(&pb.lo, &lo, sizeof lo);
    assert_memory_equal(&pb.hi, &hi, sizeof hi);
    exact = exact_reach2(m, lo, hi);
    if (STP_WIDE_ARITH) {
        assert_true(pb.reach2 == exact);
    } else {
        span = (uint32_t)hi.x - (uint32_t)lo.x;
        span = (uint32_t)hi.y - (uint32_t)lo.y > span ? (uint32_t)hi.y - (uint32_t)lo.y : span;
        span = (uint32_t)hi.z - (uint32_t)lo.z > span ? (uint32_t)hi.z - (uint32_t)lo.z : span;
        for (k = 0; k < 32 && (span >> k) != 0; k++)
            ;
        k = k > 15 ? k - 15 : 0;
        assert_true(pb.reach2 >= exact);
        assert_true(sqrt((double)pb.reach2) <= sqrt((double)exact) + 1.75 * ldexp(1, k) + 1);
    }
    m->bounds = &pb;
    assert_int_equal(ball_inside(r, m, &pb.lo, &pb.hi), by_ball);
    assert_int_equal(box_inside(r, m, &pb.lo, &pb.hi, f->scale2), by_stage);
    m->bounds = 0;
}

static void random_clouds(int w, int h)
{
    static torus_bench b;
    static stp_vec3 p[CLOUD_MAX];
    char err[256];
    long trial, ball = 0, ball_only = 0, truth = 0, stage = 0, missed = 0;
    assert_int_equal(torus_bench_init(&b, w, h, err, sizeof err), 0);
    for (trial = 0; trial < 40000; trial++) {
        stp_transform t;
        stp_mesh m;
        stp_vec3 lo, hi;
        const stp_model_frame *f;
        int n = random_cloud(p), posed = random_transform(&t), in, by_ball, by_stage;
        f = set_pose(&b, posed ? &t : 0);
        if (f == 0)
            continue;
        memset(&m, 0, sizeof m);
        m.vertices = p;
        m.vertex_count = (uint16_t)n;
        mesh_box(p, p + n, &lo, &hi);
        in = all_inside(b.r, p, n);
        by_ball = ball_inside(b.r, &m, &lo, &hi);
        by_stage = box_inside(b.r, &m, &lo, &hi, f->scale2);
        prepared_alike(b.r, &m, f, by_ball, by_stage);
        if ((by_ball && !in) || (by_stage && !in))
            fprintf(stderr, "  trial %ld: %d points, ball %d, stage %d, but a point is outside\n", trial, n,
                    by_ball, by_stage);
        assert_true(in || !by_ball);
        assert_true(in || !by_stage);
        truth += in;
        ball += by_ball;
        stage += by_stage;
        ball_only += by_stage && corner_out(b.r, lo, hi);
        missed += in && !by_stage;
    }
    fprintf(stderr, "  %dx%d: %ld clouds inside, %ld proven (%ld by the ball where a corner is out), "
                    "the ball alone %ld, %ld not proven\n",
            w, h, truth, stage, ball_only, ball, missed);
    /* both proofs decide many clouds, near the planes too */
    assert_true(ball > 2000 && ball_only > 200 && missed > 500);
    torus_bench_free(&b);
}

/* Prepared bounds at the ends of stp_fix's range: one vertex (reach 0),
 * two opposite corners of the whole range (each difference from the
 * centre just below 2^31), the eight corners, and a cloud at one end;
 * the box and reach as the exact reference has them, and neither proof
 * passes such a model in view (every step checked by UBSan in the
 * arith32 build). */
static void test_extreme_bounds(void **state)
{
    static torus_bench b;
    static const stp_fix ends[2] = {STP_FIX_MIN, STP_FIX_MAX};
    stp_vec3 p[8], lo, hi;
    stp_mesh m;
    const stp_model_frame *f;
    char err[256];
    int i, n, by_ball, by_stage;
    (void)state;
    assert_int_equal(torus_bench_init(&b, 128, 64, err, sizeof err), 0);
    f = set_pose(&b, 0);
    assert_non_null(f);
    for (n = 1; n <= 8; n++) {
        for (i = 0; i < n; i++) {
            p[i].x = n == 1 ? 5 : ends[i & 1];
            p[i].y = n == 1 ? -7 : ends[(i >> 1) & 1];
            p[i].z = n == 1 ? 11 : ends[(i >> 2) & 1];
            if (n == 3) /* a cloud at the top end */
                p[i].x = p[i].y = p[i].z = STP_FIX_MAX - i * 3;
        }
        memset(&m, 0, sizeof m);
        m.vertices = p;
        m.vertex_count = (uint16_t)n;
        mesh_box(p, p + n, &lo, &hi);
        by_ball = ball_inside(b.r, &m, &lo, &hi);
        by_stage = box_inside(b.r, &m, &lo, &hi, f->scale2);
        assert_true(all_inside(b.r, p, n) || (!by_ball && !by_stage));
        if (n > 1) /* the range's ends lie far outside the view */
            assert_true(!by_ball && !by_stage);
        else /* a point by the view's centre */
            assert_true(by_ball && by_stage);
        prepared_alike(b.r, &m, f, by_ball, by_stage);
    }
    torus_bench_free(&b);
}

static void test_random_clouds_128x64(void **state)
{
    (void)state;
    random_clouds(128, 64);
}

static void test_random_clouds_400x240(void **state)
{
    (void)state;
    random_clouds(400, 240);
}

static void test_random_clouds_640x480(void **state)
{
    (void)state;
    random_clouds(640, 480);
}

static void test_random_clouds_tall(void **state)
{
    (void)state;
    random_clouds(90, 300);
}

/* Plane k's inward gradient g in view coordinates (clip.c's distance
 * times 2^F: near (0, 0, 2^F), left and right (+-f, 0, W 2^(F-1)), top
 * and bottom (0, -+f, H 2^(F-1))) pulled back to model coordinates by
 * the composed transform's matrix (rows the axes of r->point_view, F
 * fractional bits): the direction in which the distance grows fastest. */
static void model_gradient(const stp_renderer *r, int k, double n[3])
{
    const stp_clip_volume *v = &r->clip_volume;
    const stp_vec3 *axis[3];
    double g[3] = {0, 0, 0}, len;
    int i;
    axis[0] = &r->point_view.right;
    axis[1] = &r->point_view.up;
    axis[2] = &r->point_view.forward;
    g[2] = k == 0 ? STP_FIX_ONE : (double)(k <= 2 ? v->width : v->height) * STP_FIX_ONE / 2;
    if (k == 1 || k == 2)
        g[0] = k == 1 ? v->focal : -v->focal;
    if (k == 3 || k == 4)
        g[1] = k == 4 ? v->focal : -v->focal;
    for (i = 0; i < 3; i++)
        n[i] = g[0] * stp_vec3_comp(axis[0], i) + g[1] * stp_vec3_comp(axis[1], i) + g[2] * stp_vec3_comp(axis[2], i);
    len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (i = 0; i < 3; i++)
        n[i] /= len;
}

/* Plane k's distance of view point q in view units (clip.c's distance
 * divided by its gradient's length). */
static double view_distance(const stp_clip_volume *v, int k, stp_vec3 q)
{
    double f = (double)v->focal / STP_FIX_ONE, across = (double)(k <= 2 ? v->width : v->height) / 2;
    if (k == 0)
        return (double)q.z - (double)v->near;
    return (double)stp_clip_distance(v, k, q) / sqrt(f * f + across * across);
}

/* The least distance of the ball of radius rho about view point q from
 * the five planes, in view units (negative: it crosses one). */
static double clearance(const stp_clip_volume *v, stp_vec3 q, double rho)
{
    double least = 1e300;
    int k;
    for (k = 0; k < 5; k++) {
        double d = view_distance(v, k, q) - rho;
        if (d < least)
            least = d;
    }
    return least;
}

/* The ball at its tightest: two points c +- o, o of length R along plane
 * k's model gradient (so that a point is where the ball comes nearest to
 * plane k; for the near plane a ball small enough to meet it before
 * the sides), c moved towards the plane in steps of one raw model unit
 * (binary search) to the last place the ball proves inside.  Wherever it
 * proves inside, both points' outcodes are 0 and the ball itself (radius
 * R times the model's scale about c's view point) clears every plane but
 * for c's rounding (under 2 view units); at the last place it comes within
 * a few view units of a plane: a proof too bold by more than that (a root
 * rounded down, a stretch or gradient too short) fails. */
static void tight_balls(int w, int h)
{
    static torus_bench b;
    char err[256];
    double worst = 0, closest = 1e30;
    long trial, searched = 0;
    assert_int_equal(torus_bench_init(&b, w, h, err, sizeof err), 0);
    for (trial = 0; trial < 3000; trial++) {
        stp_transform t;
        stp_vec3 p[2], lo, hi, c, q;
        stp_mesh m;
        double n[3], radius = exp(uniform(log(0.01), log(1.5))), scale = 1, rho = 0;
        const stp_model_frame *f;
        int k = (int)uniform(0, 5), i, posed = uniform(0, 4) >= 1;
        int32_t o[3], step, lo_t = 0, hi_t, far;
        if (posed) { /* the composed transform: scales below 2 */
            scale = uniform(0.25, 1.9);
            stp_transform_identity(&t);
            stp_transform_scale(&t, fix_of(scale), fix_of(scale), fix_of(scale));
            stp_transform_rotate(&t, 0, fix_of(uniform(0, 360)));
            stp_transform_rotate(&t, 1, fix_of(uniform(0, 360)));
            stp_transform_rotate(&t, 2, fix_of(uniform(0, 360)));
        }
        f = set_pose(&b, posed ? &t : 0);
        if (f == 0 || b.r->geometry == STP_GEOMETRY_TWO_STEPS)
            continue;
        if (k == 0) /* small enough to meet the near plane before the sides */
            radius *= 0.0015;
        scale = sqrt((double)f->scale2) / STP_FIX_ONE;
        far = hi_t = (int32_t)(8 * STP_FIX_ONE / scale); /* 8 view units: beyond the planes */
        model_gradient(b.r, k, n);
        for (i = 0; i < 3; i++)
            o[i] = (int32_t)lround(radius * STP_FIX_ONE * n[i]);
        rho = sqrt((double)o[0] * o[0] + (double)o[1] * o[1] + (double)o[2] * o[2]) * scale;
        memset(&m, 0, sizeof m);
        m.vertices = p;
        m.vertex_count = 2;
        /* from the origin (the view's axis, 6 units ahead) towards plane k */
        for (step = 0; step < 40 && hi_t - lo_t > 1; step++) {
            int32_t mid = lo_t + (hi_t - lo_t) / 2;
            c.x = (stp_fix)lround(-mid * n[0]);
            c.y = (stp_fix)lround(-mid * n[1]);
            c.z = (stp_fix)lround(-mid * n[2]);
            p[0].x = c.x + o[0];
            p[0].y = c.y + o[1];
            p[0].z = c.z + o[2];
            p[1].x = c.x - o[0];
            p[1].y = c.y - o[1];
            p[1].z = c.z - o[2];
            mesh_box(p, p + 2, &lo, &hi);
            if (ball_inside(b.r, &m, &lo, &hi)) {
                double clear;
                assert_true(all_inside(b.r, p, 2));
                (void)stp_render_point_to_view(b.r, c, &q);
                clear = clearance(&b.r->clip_volume, q, rho);
                if (clear < closest)
                    closest = clear;
                lo_t = mid;
            } else {
                hi_t = mid;
            }
        }
        assert_true(hi_t < far); /* the last place found */
        if (lo_t == 0)
            continue; /* not proven inside at the start */
        searched++;
        c.x = (stp_fix)lround(-lo_t * n[0]);
        c.y = (stp_fix)lround(-lo_t * n[1]);
        c.z = (stp_fix)lround(-lo_t * n[2]);
        (void)stp_render_point_to_view(b.r, c, &q);
        if (clearance(&b.r->clip_volume, q, rho) > worst)
            worst = clearance(&b.r->clip_volume, q, rho);
    }
    fprintf(stderr, "  %dx%d: %ld balls searched; where proven inside they clear the planes by at least "
                    "%.2f view units, at the last place by at most %.2f\n",
            w, h, searched, closest, worst);
    assert_true(searched > 1500);
    /* sound, and close to the planes (32-bit targets bound the radius
     * more loosely: reach2) */
    assert_true(closest > -2 && worst < 32);
    torus_bench_free(&b);
}

static void test_tight_balls_128x64(void **state)
{
    (void)state;
    tight_balls(128, 64);
}

static void test_tight_balls_tall(void **state)
{
    (void)state;
    tight_balls(90, 300);
}

/* The torus at w x h, posed (tilt, spin, offset), entered polygon by
 * polygon and as one mesh: the same display file and frame.  Returns
 * whether the mesh path proves every vertex inside, and in *out whether a
 * corner of its box is outside a plane. */
/* mesh's display file and frame (h rows) equal poly's. */
static void same_output(const torus_bench *poly, const torus_bench *mesh, int h)
{
    uint32_t used = stp_renderer_display_file_used(poly->r);
    assert_int_equal(stp_renderer_display_file_used(mesh->r), used);
    assert_memory_equal(poly->df, mesh->df, sizeof *poly->df * used);
    assert_int_equal(memcmp(poly->frame, mesh->frame, poly->stride * (size_t)h), 0);
}

static int same_frames(int w, int h, double tilt, double spin, double dx, double dy, double dz, int *out)
{
    static torus_bench poly, mesh;
    char err[256];
    stp_vec3 lo, hi;
    const stp_model_frame *f;
    int inside;
    assert_int_equal(torus_bench_init(&poly, w, h, err, sizeof err), 0);
    assert_int_equal(torus_bench_init(&mesh, w, h, err, sizeof err), 0);
    assert_int_equal(torus_bench_use_mesh(&mesh, err, sizeof err), 0);
    torus_bench_pose(&poly, tilt, spin, dx, dy, dz);
    torus_bench_pose(&mesh, tilt, spin, dx, dy, dz);
    assert_int_equal(torus_frame(&poly), 0);
    assert_int_equal(torus_frame(&mesh), 0);
    same_output(&poly, &mesh, h);
    /* the bench's mesh has prepared bounds; without, the same again */
    assert_non_null(mesh.mesh.bounds);
    mesh.mesh.bounds = 0;
    assert_int_equal(torus_frame(&mesh), 0);
    same_output(&poly, &mesh, h);
    /* the proof for this pose, the torus's box as the mesh path finds it */
    f = set_pose(&mesh, &mesh.pose);
    assert_non_null(f);
    mesh_box(mesh.mesh.vertices, mesh.mesh.vertices + mesh.mesh.vertex_count, &lo, &hi);
    inside = box_inside(mesh.r, &mesh.mesh, &lo, &hi, f->scale2);
    assert_true(all_inside(mesh.r, mesh.mesh.vertices, mesh.mesh.vertex_count) || !inside);
    *out = corner_out(mesh.r, lo, hi);
    torus_bench_free(&poly);
    torus_bench_free(&mesh);
    return inside;
}

/* The bench's spinning poses: every one proven inside at 128x64. */
static void test_spinning_torus(void **state)
{
    int frame, corners = 0;
    (void)state;
    for (frame = 0; frame < 120; frame++) {
        int out;
        assert_true(same_frames(128, 64, 20, 3.0 * frame, 0, 0, 0, &out));
        corners += out;
    }
    fprintf(stderr, "  120 spinning poses proven inside, %d with a corner of the box outside\n", corners);
    assert_true(corners >= 25);
}

/* Random poses, some across the window's edges (clipped triangles): the
 * mesh path's frames equal the polygon path's whatever the proof says. */
static void test_random_torus(void **state)
{
    int i, proven = 0, by_ball = 0;
    (void)state;
    for (i = 0; i < 60; i++) {
        int out, in, w = i % 3 == 0 ? 400 : 128, h = i % 3 == 0 ? 240 : 64;
        double tilt = uniform(0, 360), spin = uniform(0, 360), dx = uniform(-1, 1);
        double dy = uniform(-0.8, 0.8), dz = uniform(-1.5, 1.5);
        in = same_frames(w, h, tilt, spin, dx, dy, dz, &out);
        proven += in;
        by_ball += in && out;
    }
    fprintf(stderr, "  60 random poses: %d proven inside, %d by the ball\n", proven, by_ball);
    assert_true(proven >= 10 && proven <= 55 && by_ball >= 3);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_random_clouds_128x64), cmocka_unit_test(test_random_clouds_400x240),
        cmocka_unit_test(test_random_clouds_640x480), cmocka_unit_test(test_random_clouds_tall),
        cmocka_unit_test(test_tight_balls_128x64),   cmocka_unit_test(test_tight_balls_tall),
        cmocka_unit_test(test_spinning_torus),        cmocka_unit_test(test_random_torus),
        cmocka_unit_test(test_extreme_bounds),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
