/* SPDX-License-Identifier: MIT */
/* Indexed triangle meshes entered in one call: see include/stipple/mesh.h.
 * Per call: the composite normal rotation, the eye in model coordinates
 * and a scale for the back-face test; per front face: its three vertices
 * transformed, outcoded and projected once each (scratch), the prepared
 * normal rotated into view coordinates, one shade. */
#include "stipple/mesh.h"

#include "render_private.h"
#include "shade_private.h"
#include "clip_private.h"
#include "view_private.h"
#include "recip_private.h"

#define F STP_FIX_FRAC_BITS
#define ONE STP_FIX_ONE

/* stp_mesh_vertex.state: STATE_NEW not transformed in this call (a
 * constant one Thumb instruction makes: every vertex is marked so); else
 * the outcode (bits 0..4, clip.c) or CODE_RANGE, plus UNPROJECTED until
 * dx, dy, dz hold the device position: 0 is a vertex inside the view
 * volume and projected, so one test (enter_face) finds a face whose three
 * vertices are ready, the common case. */
#define STATE_NEW 128
#define CODE_RANGE 32
#define UNPROJECTED 64

/* enter_faces removes a sure back face, and enters a sure front face,
 * from face_side's 32-bit estimate before the estimate's own test (M0+
 * torus: 3 120 instructions a frame fewer); not in size-first builds (its
 * code, 176 bytes at -Os) */
#if !STP_WIDE_ARITH && !defined(__OPTIMIZE_SIZE__)
#define SURE_BACK 1
#else
#define SURE_BACK 0
#endif

/* TIME_FIRST: a 32-bit core's build for speed (64-bit products library
 * calls, not -Os), where code off the face loop's common path is kept out
 * of stp_renderer_mesh (OUT_OF_LINE: the once-a-call steps check_mesh,
 * prepare_call and mesh_box; a face crossing the view volume's
 * planes, ready_clipped; wide_centre), so that the face loop's function
 * holds less and its branches reach (M0+ torus: 80 instructions, 167
 * cycles a frame fewer for the first two; ready_clipped 1 200 and 1 500);
 * elsewhere inline: the shorter code at -Os, the faster on a 64-bit host
 * (5 K instructions a frame fewer). */
#if !STP_WIDE_ARITH && !defined(__OPTIMIZE_SIZE__)
#define TIME_FIRST 1 /* also mesh_box's and enter_face's forms */
#define OUT_OF_LINE STP_NOINLINE
#else
#define TIME_FIRST 0
#define OUT_OF_LINE static
#endif

/* What one call finds once for all its triangles. */
typedef struct mesh_context {
    stp_renderer *r;
    const stp_mesh *mesh;
    const stp_vec3 *vertices; /* mesh->vertices */
    int cull; /* back faces are removed (r->backface_removal) */
    int32_t least_side; /* the least face side entered: 1 with cull, else INT32_MIN */
#if SURE_BACK
    /* a face side estimate (face_estimate) below this is surely a removed
     * back face: -2^15 with cull (the estimate's sign then exact and
     * negative), else INT32_MIN (none) */
    int32_t sure_back;
#endif
    stp_mesh_vertex *scratch;
    const stp_model_frame *frame; /* the face stage's (render_private.h) */
    stp_side_estimate side_estimate; /* the back-face test's first, 32-bit estimate */
    int inside; /* 1: every vertex is inside the view volume (no outcodes)
                   and its view coordinates are below 2^29 in magnitude */
    stp_view_lens lens; /* the projection's constants (view.c) */
    uint8_t focal_bits; /* stp_bit_length32(lens.focal), once a call (unsigned: the
                           projection's not-known case, -1, folds away) */
    const stp_shade_fast *shade; /* the face stage's shader (stp_render_face_shader), NULL: shading off */
    int32_t test_rows; /* rows of a triangle pixel culling (render.h) tests: STP_CENTRE_TEST_MAX, or 0 when off */
    /* the face stage's per-call values, kept here rather than in r (whose
     * fields lie beyond the ARMv6-M load's reach): the intensity steps
     * (stp_intensity_steps), the fill style and its shade (shading off),
     * the style in force (stp_render_current_style; entered: its value
     * at the call's start or the last fallback) and r->last_shade, both
     * written back by keep_state */
    int32_t steps;
    int fill_style, current, entered;
    stp_fix fill_shade, last_shade;
} mesh_context;

/* ---- normals, once ---- */

int stp_mesh_prepare_normals(const stp_mesh *mesh, int16_t *normals, uint16_t *bad_triangle)
{
    uint16_t t;
    if (mesh == 0 || normals == 0 ||
        (mesh->triangle_count > 0 && (mesh->vertices == 0 || mesh->triangles == 0)))
        return STP_ERR_ARG;
    for (t = 0; t < mesh->triangle_count; t++) {
        const uint16_t *k = &mesh->triangles[3 * (uint32_t)t];
        if (k[0] >= mesh->vertex_count || k[1] >= mesh->vertex_count ||
            k[2] >= mesh->vertex_count) {
            if (bad_triangle)
                *bad_triangle = t;
            return STP_ERR_ARG;
        }
        stp_vec3 v[3];
        v[0] = mesh->vertices[k[0]];
        v[1] = mesh->vertices[k[1]];
        v[2] = mesh->vertices[k[2]];
        if (!stp_render_triangle_normal(v, &normals[3 * (uint32_t)t])) {
            if (bad_triangle)
                *bad_triangle = t;
            return STP_ERR_DEGENERATE;
        }
    }
    return STP_OK;
}

/* ---- once per call ---- */

/* Whether the fast path can enter this call's triangles: perspective,
 * prepared normals, none of the states it does not reproduce. */
static int fast_state(const stp_renderer *r, const stp_mesh *mesh)
{
    if (mesh->normals == 0 || r->projection != STP_PERSPECTIVE || r->colour ||
        r->current_transmission != 0)
        return 0;
#if STP_WITH_TRANSPARENCY
    if (r->t_max > 0 || r->t_min > 0)
        return 0;
#endif
#if STP_WITH_SHADOWS
    if (r->shadow_set != 0)
        return 0;
#endif
    return 1;
}

/* sqrt(v) rounded up: stp_sqrt64_fast is below the root by less than
 * 2^-29 of it plus its integer part's 1; 2^-20 and 2 are room to spare. */
STP_NOINLINE uint64_t root_up(uint64_t v)
{
    uint32_t root = stp_sqrt64_fast(v);
    return (uint64_t)root + (root >> 20) + 2;
}

/* An upper bound of the length of the largest vector M d / 2^F for |d| = 1
 * times 2^F, M the view transform t's matrix (rows the axes right, up,
 * forward, each component below 2^17 in magnitude: view.c): the root of
 * the largest row sum of |M^T M| (bounding its largest eigenvalue, a
 * Gershgorin disc's reach), each entry below 3 2^34, a row's sum below
 * 2^38.  About 2^F times the scale for a rotation and uniform scale. */
STP_NOINLINE uint64_t stretch_up(const stp_view_transform *t)
{
    const stp_vec3 *axis[3];
    uint64_t most = 0;
    int j, k;
    axis[0] = &t->right;
    axis[1] = &t->up;
    axis[2] = &t->forward;
    for (j = 0; j < 3; j++) {
        uint64_t sum = 0;
        for (k = 0; k < 3; k++) {
            int64_t g = 0;
            int i;
            for (i = 0; i < 3; i++)
                g += (int64_t)stp_vec3_comp(axis[i], j) * stp_vec3_comp(axis[i], k);
            sum += stp_abs64u(g);
        }
        if (sum > most)
            most = sum;
    }
    return root_up(most);
}

/* The largest squared distance of the points p to end from c, the centre
 * of their box (its widest side span), or (32-bit targets) a bound of it:
 * each difference below 2^31 in magnitude (c in the box), the sum below
 * 3 2^62. */
STP_NOINLINE uint64_t reach2(const stp_vec3 *p, const stp_vec3 *end, stp_vec3 c, uint32_t span)
{
#if STP_WIDE_ARITH
    uint64_t most = 0;
    (void)span;
    for (; p != end; p++) {
        int64_t dx = (int64_t)p->x - c.x, dy = (int64_t)p->y - c.y, dz = (int64_t)p->z - c.z;
        uint64_t d = (uint64_t)(dx * dx) + (uint64_t)(dy * dy) + (uint64_t)(dz * dz);
        if (d > most)
            most = d;
    }
    return most;
#else
    /* where 64-bit products are library calls: each difference d (|d| at
     * most span, below 2^31) as (|d| >> k) + 1 <= 2^15, at least |d| / 2^k,
     * squared in 32 bits (the sum below 3 2^30); the bound 2^2k times it,
     * below 3 (2^31 + 2^k)^2 < 2^64 (k <= 17) */
    int k = stp_bit_length32(span) - 15;
    uint32_t most = 0;
    if (k < 0)
        k = 0;
    for (; p != end; p++) {
        uint32_t dx = (stp_abs32((int32_t)((uint32_t)p->x - (uint32_t)c.x)) >> k) + 1;
        uint32_t dy = (stp_abs32((int32_t)((uint32_t)p->y - (uint32_t)c.y)) >> k) + 1;
        uint32_t dz = (stp_abs32((int32_t)((uint32_t)p->z - (uint32_t)c.z)) >> k) + 1;
        uint32_t d = dx * dx + dy * dy + dz * dz;
        if (d > most)
            most = d;
    }
    return (uint64_t)most << (2 * k);
#endif
}

/* The centre *c of the box [lo, hi] (rounded down) and its widest side's
 * span, each side below 2^32. */
static uint32_t box_centre(const stp_vec3 *lo, const stp_vec3 *hi, stp_vec3 *c)
{
    uint32_t span;
    c->x = (stp_fix)((uint32_t)lo->x + (((uint32_t)hi->x - (uint32_t)lo->x) >> 1));
    c->y = (stp_fix)((uint32_t)lo->y + (((uint32_t)hi->y - (uint32_t)lo->y) >> 1));
    c->z = (stp_fix)((uint32_t)lo->z + (((uint32_t)hi->z - (uint32_t)lo->z) >> 1));
    span = (uint32_t)hi->x - (uint32_t)lo->x;
    if ((uint32_t)hi->y - (uint32_t)lo->y > span)
        span = (uint32_t)hi->y - (uint32_t)lo->y;
    if ((uint32_t)hi->z - (uint32_t)lo->z > span)
        span = (uint32_t)hi->z - (uint32_t)lo->z;
    return span;
}

/* Whether every view point within rho (< 2^28) of q = (a or -a, z) (a
 * the magnitude of x or y, a and z below 2^28) is inside both side planes
 * of a pair, left and right (f focal, s = W 2^(F-1)) or top and bottom
 * (s = H 2^(F-1)): each plane's stp_clip_distance (perspective), fx + hw
 * and the like, is under 3/2 below its exact value 2^-F d(.) (floor(f x /
 * 2^F) and trunc(W z / 2) round down by under 1 and 1/2), d = g . (x, z)
 * with g = (+-f, s), so the nearer plane's d(q) = s z - f a less |g| rho
 * at least 2^(F+1) is enough.  |s z| < 2^58, |f a| < 2^59 (f < 2^31,
 * W < 2^15), |g| < 2^32, |g| rho < 2^60. */
STP_NOINLINE int sides_clear(int64_t f, int64_t s, uint32_t a, stp_fix z, uint64_t rho)
{
    int64_t d = s * z - f * (int64_t)a - (int64_t)2 * ONE;
    return d >= 0 && (uint64_t)d >= root_up((uint64_t)(f * f) + (uint64_t)(s * s)) * rho;
}

/* Whether every vertex of mesh (its bounding box [lo, hi]) is inside the
 * view volume with its view coordinates below 2^28 in magnitude, from a
 * ball about the box's centre c holding every vertex: radius R, R^2 the
 * largest squared distance (reach2).  In one composed transform (or the
 * view's alone: view.c), view(p) = floor((M p - t) / 2^F) (t the offsets
 * from . axis) is (M p - t) / 2^F - e(p) with e(p) in [0, 1)^3, so
 * view(v) - view(c) = M (v - c) / 2^F + e(c) - e(v) is shorter than
 * stretch_up R / 2^F + 2: rho.  Then each coordinate of view(c) (q) plus
 * rho below 2^28, and the planes' tests about q.  Not for the two steps
 * (rounded twice, saturating).  box_inside's rare case: the rotated box's corners
 * of a spinning model reach further than its vertices do (the spinning
 * torus: half its frames). */
STP_NOINLINE int ball_inside(const stp_renderer *r, const stp_mesh *mesh, const stp_vec3 *lo, const stp_vec3 *hi)
{
    const stp_clip_volume *v = &r->clip_volume;
    stp_vec3 c, q;
    uint64_t rho;
    uint32_t span;
    if (r->geometry == STP_GEOMETRY_TWO_STEPS)
        return 0;
    span = box_centre(lo, hi, &c);
    /* R < 2^33, stretch_up < 2^20: the product below 2^53 */
    rho = ((stretch_up(&r->point_view) *
                root_up(mesh->bounds != 0 ? mesh->bounds->reach2
                                          : reach2(mesh->vertices, mesh->vertices + mesh->vertex_count, c, span)) +
            (ONE - 1)) >> F) + 2;
    if (rho >= ((uint64_t)1 << 28))
        return 0;
    (void)stp_render_point_to_view(r, c, &q); /* saturated: fails below */
    /* every vertex's coordinates below 2^28 (each |q| below 2^31: the sum
     * does not wrap), z at least the near plane's (clip.c's distance
     * exact), inside the side planes */
    if ((stp_abs32(q.x) | stp_abs32(q.y) | stp_abs32(q.z)) + (uint32_t)rho >= ((uint32_t)1 << 28) ||
        (int64_t)q.z - v->near < (int64_t)rho)
        return 0;
    return sides_clear(v->focal, (int64_t)v->width << (F - 1), stp_abs32(q.x), q.z, rho) &&
           sides_clear(v->focal, (int64_t)v->height << (F - 1), stp_abs32(q.y), q.z, rho);
}

/* Whether every vertex of mesh (its bounding box [lo, hi]) lands strictly
 * inside the view volume under the model and view transforms, with room
 * for their rounding: the box grown by a margin worth 64 raw view units
 * (64 / s model units, s the model's scale: s2 = s^2 2^(2F)) has its eight
 * corners inside (outcode 0, nothing saturated) and their view coordinates
 * below 2^28.  The volume is convex and the transforms affine, so then
 * every vertex is inside too, its outcode (0) need not be formed, and its
 * view coordinates are below 2^28 (plus the rounding): a sum of three fits
 * int32.  A corner outside a plane leaves it to ball_inside (the same
 * promises). */
static int box_inside(const stp_renderer *r, const stp_mesh *mesh, const stp_vec3 *lo, const stp_vec3 *hi, int64_t s2)
{
    uint32_t s = stp_sqrt64_fast((uint64_t)s2); /* s 2^F, >= 2^10 (similarity) */
    /* 64 2^F / s in 32 bits (64 2^F = 2^22): a library call of a 32-bit
     * quotient rather than a 64-bit one (M0+ torus: 400 cycles fewer a call) */
    int64_t margin = (int64_t)(((uint32_t)64 << F) / (s > 0 ? s : 1u)) + 1;
    int corner;
    for (corner = 0; corner < 8; corner++) {
        int64_t x = (corner & 1) ? (int64_t)hi->x + margin : (int64_t)lo->x - margin;
        int64_t y = (corner & 2) ? (int64_t)hi->y + margin : (int64_t)lo->y - margin;
        int64_t z = (corner & 4) ? (int64_t)hi->z + margin : (int64_t)lo->z - margin;
        stp_vec3 p, view;
        if (x <= STP_FIX_MIN || x >= STP_FIX_MAX || y <= STP_FIX_MIN || y >= STP_FIX_MAX ||
            z <= STP_FIX_MIN || z >= STP_FIX_MAX)
            return 0;
        p.x = (stp_fix)x;
        p.y = (stp_fix)y;
        p.z = (stp_fix)z;
        if (stp_render_point_to_view(r, p, &view) || stp_view_saturated(view))
            return 0;
        if (stp_clip_outcode(&r->clip_volume, view) != 0)
            return ball_inside(r, mesh, lo, hi);
        if ((stp_abs32(view.x) | stp_abs32(view.y) | stp_abs32(view.z)) >= ((uint32_t)1 << 28))
            return 0;
    }
    return 1;
}

#if TIME_FIRST
/* The interval [*lo, *lo + *span] grown to hold v, a value outside it
 * (v - *lo, wrapped, above *span). */
STP_HOT_INLINE void box_grow(stp_fix v, stp_fix *lo, uint32_t *span)
{
    if (v < *lo) {
        *span += (uint32_t)*lo - (uint32_t)v;
        *lo = v;
    } else {
        *span = (uint32_t)v - (uint32_t)*lo;
    }
}
#endif

/* The bounding box [*lo_out, *hi_out] of the points p to end (at least
 * one): per call, or once (stp_mesh_prepare_bounds).  Where time counts
 * on a 32-bit core (TIME_FIRST) a function of its own, short, so that a
 * bound's rare update lies within the short conditional branch's reach
 * (ARMv6-M), and a coordinate inside the box one unsigned test of its
 * offset from the low corner (the span hi - lo): the common case falls
 * through (M0+ torus, 500 vertices: 2 700 cycles a frame fewer).
 * Elsewhere two tests a coordinate, the shorter code (-Os) and the faster
 * on a 64-bit host. */
OUT_OF_LINE void mesh_box(const stp_vec3 *p, const stp_vec3 *end, stp_vec3 *lo_out, stp_vec3 *hi_out)
{
#if TIME_FIRST
    stp_fix lx = p->x, ly = p->y, lz = p->z;
    uint32_t sx = 0, sy = 0, sz = 0; /* hi - lo */
    for (; p != end; p++) {
        if (STP_UNLIKELY((uint32_t)p->x - (uint32_t)lx > sx))
            box_grow(p->x, &lx, &sx);
        if (STP_UNLIKELY((uint32_t)p->y - (uint32_t)ly > sy))
            box_grow(p->y, &ly, &sy);
        if (STP_UNLIKELY((uint32_t)p->z - (uint32_t)lz > sz))
            box_grow(p->z, &lz, &sz);
    }
    lo_out->x = lx;
    lo_out->y = ly;
    lo_out->z = lz;
    hi_out->x = (stp_fix)((uint32_t)lx + sx);
    hi_out->y = (stp_fix)((uint32_t)ly + sy);
    hi_out->z = (stp_fix)((uint32_t)lz + sz);
#else
    stp_vec3 lo = *p, hi = *p;
    for (; p != end; p++) {
        stp_fix x = p->x, y = p->y, z = p->z;
        if (STP_UNLIKELY(x < lo.x))
            lo.x = x;
        if (STP_UNLIKELY(x > hi.x))
            hi.x = x;
        if (STP_UNLIKELY(y < lo.y))
            lo.y = y;
        if (STP_UNLIKELY(y > hi.y))
            hi.y = y;
        if (STP_UNLIKELY(z < lo.z))
            lo.z = z;
        if (STP_UNLIKELY(z > hi.z))
            hi.z = z;
    }
    *lo_out = lo;
    *hi_out = hi;
#endif
}

/* The n scratch entries from sv marked new (not transformed in this
 * call); four a step on 64-bit hosts (the loop's own three instructions
 * an entry otherwise: host torus, 500 vertices, 900 instructions a
 * frame fewer). */
static void mark_new(stp_mesh_vertex *sv, uint16_t n)
{
    stp_mesh_vertex *end = sv + n;
#if STP_WIDE_ARITH
    for (; end - sv >= 4; sv += 4) {
        sv[0].state = STATE_NEW;
        sv[1].state = STATE_NEW;
        sv[2].state = STATE_NEW;
        sv[3].state = STATE_NEW;
    }
#endif
    for (; sv != end; sv++)
        sv->state = STATE_NEW;
}

int stp_mesh_prepare_bounds(const stp_mesh *mesh, stp_mesh_bounds *bounds)
{
    stp_vec3 c;
    uint32_t span;
    if (mesh == 0 || bounds == 0 || mesh->vertices == 0 || mesh->vertex_count == 0)
        return STP_ERR_ARG;
    mesh_box(mesh->vertices, mesh->vertices + mesh->vertex_count, &bounds->lo, &bounds->hi);
    span = box_centre(&bounds->lo, &bounds->hi, &c);
    bounds->reach2 = reach2(mesh->vertices, mesh->vertices + mesh->vertex_count, c, span);
    return STP_OK;
}

/* The per-call values of the fast path (mesh_context); 0 when the model
 * frame (render_private.h: the model transform, the eye's place) rules it
 * out. */
OUT_OF_LINE int prepare_call(mesh_context *c)
{
    const stp_renderer *r = c->r;
    const stp_model_frame *f = stp_render_model_frame(c->r);
    uint32_t big;
    stp_vec3 lo, hi;
    const stp_vec3 *p;
    if (f == 0)
        return 0;
    c->frame = f;
    /* the scale of the back-face test (every coordinate below 2^14) and
     * the model's bounding box: prepared, or found here */
    if (c->mesh->bounds != 0) {
        lo = c->mesh->bounds->lo;
        hi = c->mesh->bounds->hi;
    } else {
        p = c->mesh->vertices;
        mesh_box(p, p + c->mesh->vertex_count, &lo, &hi);
    }
    mark_new(c->scratch, c->mesh->vertex_count);
    /* the box's corners bound every coordinate's magnitude */
    big = stp_abs32(lo.x) | stp_abs32(lo.y) | stp_abs32(lo.z) | stp_abs32(hi.x) |
           stp_abs32(hi.y) | stp_abs32(hi.z);
    c->inside = box_inside(r, c->mesh, &lo, &hi, f->scale2);
    stp_view_lens_make(&c->lens, r->focal, r->hither, r->width, r->height);
    c->focal_bits = (uint8_t)stp_bit_length32((uint32_t)r->focal);
    stp_render_side_estimate_make(f, big, &c->side_estimate);
    return 1;
}

/* ---- per vertex and per face ---- */

/* vertex_transform and vertex_ready inline in the face loop where 64-bit
 * products and quotients are instructions (host torus: 5 600 instructions
 * a frame fewer still, 8 200 spinning: the calls' saves and reloads);
 * calls elsewhere (ARMv6-M's registers, the code's size). */
#if STP_WIDE_ARITH
#define VERTEX_READY STP_HOT_INLINE
#else
#define VERTEX_READY static
#endif

/* Vertex i (not transformed yet, scratch entry *s) in view coordinates
 * with its outcode (or CODE_RANGE): the geometry stage, as
 * stp_renderer_polygon's. */
VERTEX_READY void vertex_transform(const mesh_context *c, stp_mesh_vertex *s, uint16_t i)
{
    const stp_renderer *r = c->r;
    int range = stp_render_point_to_view(r, c->vertices[i], &s->view);
    if (c->inside)
        s->state = UNPROJECTED; /* box_inside: no vertex is outside or saturated */
    else
        s->state = UNPROJECTED | (range || stp_view_saturated(s->view)
                                      ? CODE_RANGE
                                      : (int32_t)stp_clip_outcode(&r->clip_volume, s->view));
}

/* Vertex i's outcode (or CODE_RANGE), transformed once per call; the
 * common case, a vertex an earlier face transformed, stays inline. */
STP_HOT_INLINE int32_t vertex_code(mesh_context *c, stp_mesh_vertex *s, uint16_t i)
{
    if (s->state == STATE_NEW)
        vertex_transform(c, s, i);
    return s->state & (CODE_RANGE | 31);
}

#if !STP_WIDE_ARITH
/* vertex_project's 64-bit quotients, out of line: the hot path keeps
 * fewer values live (M0+ torus: 800 instructions, 1 410 cycles fewer a
 * frame than stp_view_perspective_device_bits inline) */
STP_NOINLINE void vertex_project_wide(const mesh_context *c, const stp_mesh_vertex *s, int32_t d[3])
{
    stp_view_perspective_device_wide(&c->lens, &s->view, d);
}
#endif

/* Vertex *s's device position, projected once per call (it is inside the
 * view volume: its outcode is 0). */
STP_HOT_INLINE void vertex_project(const mesh_context *c, stp_mesh_vertex *s)
{
    int32_t d[3];
#if STP_WIDE_ARITH
    stp_view_perspective_device_bits(&c->lens, c->focal_bits, &s->view, d);
#else
    if (STP_UNLIKELY(!stp_view_perspective_device_exact(&c->lens, c->focal_bits, &s->view, d)))
        vertex_project_wide(c, s, d); /* perspective (fast_state) */
#endif
    s->dx = d[0];
    s->dy = d[1];
    s->dz = d[2];
    s->state = 0; /* its outcode was 0 */
}

/* Vertex i (scratch entry *s, inside the view volume) transformed if not
 * yet, then projected: one call a vertex from the face loop.  A new one
 * comes only with c->inside (else vertex_code transformed it), so its
 * outcode is 0 and nothing saturates (box_inside). */
VERTEX_READY void vertex_ready(const mesh_context *c, stp_mesh_vertex *s, uint16_t i)
{
    if (!STP_UNLIKELY(s->state != STATE_NEW)) /* laid out as the hot path (c->inside: every vertex) */
        (void)stp_render_point_at_view_bounded(c->r, &c->vertices[i], &s->view); /* box_inside */
    vertex_project(c, s);
}

/* The triangle of indices k through stp_renderer_polygon (mesh.h: the
 * fallback). */
static int enter_fallback(const mesh_context *c, const uint16_t *k)
{
#if STP_WITH_MESH_FALLBACK
    stp_vec3 v[3];
    v[0] = c->mesh->vertices[k[0]];
    v[1] = c->mesh->vertices[k[1]];
    v[2] = c->mesh->vertices[k[2]];
    return stp_renderer_polygon(c->r, v, 3);
#else
    (void)c;
    (void)k;
    return STP_ERR_UNSUPPORTED;
#endif
}

/* The fast path's style in force and last shade (mesh_context) into the
 * renderer. */
static void keep_state(const mesh_context *c)
{
    stp_renderer *r = c->r;
    r->last_shade = c->last_shade;
    if (c->current != c->entered) {
        r->current_style = c->current; /* a SHADE was stored: colour 0 */
        r->current_colour = 0;
    }
}

/* The style in force and last shade of the renderer into the fast path's
 * (mesh_context). */
static void take_state(mesh_context *c)
{
    c->current = c->entered = stp_render_current_style(c->r);
    c->last_shade = c->r->last_shade;
}

/* enter_fallback on the fast path, which keeps the renderer's state in
 * its context. */
static int fast_fallback(mesh_context *c, const uint16_t *k)
{
    int status;
    keep_state(c);
    status = enter_fallback(c, k);
    take_state(c);
    return status;
}

/* The display-file records of a front face inside the view (scratch
 * entries s[0..2], projected) in the given style: SHADE when the style
 * changed, then its three vertices (the open segment's end: set once per
 * call, stp_renderer_mesh). */
static int store_face(mesh_context *c, stp_mesh_vertex *const s[3], int style)
{
    int change = style != c->current;
    stp_instr *out = stp_render_face_records(c->r, change, style, c->last_shade);
    if (out == 0)
        return STP_ERR_FULL;
    if (change)
        c->current = style;
    stp_render_put_vertex(&out[0], 3, s[0]->dx, s[0]->dy, s[0]->dz);
    stp_render_put_vertex(&out[1], STP_OP_LINE, s[1]->dx, s[1]->dy, s[1]->dz);
    stp_render_put_vertex(&out[2], STP_OP_LINE, s[2]->dx, s[2]->dy, s[2]->dz);
    return STP_OK;
}

#if !STP_WIDE_ARITH
/* stp_render_face_side for face_side's uncertain estimates. */
STP_NOINLINE int exact_side(const mesh_context *c, const int16_t *n, const stp_vec3 *a)
{
    return stp_render_face_side(c->frame, n, *a);
}
#endif

/* The face stage's side of triangle t (stp_render_face_side: the exact
 * sign of N.(eye - v0)); where 64-bit products are library calls, first
 * the face stage's 32-bit estimate (stp_render_side_estimate, exact in
 * sign outside [-2^15, 2^15)).  The result: a value of
 * that sign (the estimate itself, or -1, 0, 1), which is all its users
 * (the removal test, stp_render_view_normal, stp_render_face_shade) ask.
 * In two steps: face_estimate (exact where 64-bit products are cheap) and
 * face_checked, between which enter_faces removes a sure back face. */
STP_HOT_INLINE int32_t face_estimate(const mesh_context *c, const int16_t *n, const stp_vec3 *a)
{
#if !STP_WIDE_ARITH
    return stp_render_side_estimate(&c->side_estimate, n, a);
#else
    return stp_render_face_side(c->frame, n, *a);
#endif
}

/* face_side from its estimate side (face_estimate). */
STP_HOT_INLINE int32_t face_checked(const mesh_context *c, const int16_t *n, const stp_vec3 *a, int32_t side)
{
#if !STP_WIDE_ARITH
    if (stp_render_side_sure(side))
        return side;
    return exact_side(c, n, a); /* rare: out of line */
#else
    (void)c;
    (void)n;
    (void)a;
    return side;
#endif
}

/* The side in one step (face_estimate, face_checked). */
STP_HOT_INLINE int32_t face_side(const mesh_context *c, const int16_t *n, const stp_vec3 *a)
{
    return face_checked(c, n, a, face_estimate(c, n, a));
}

/* Vertex i (scratch entry *s) transformed and projected, when every
 * vertex is inside the view volume (c->inside). */
STP_HOT_INLINE void ready_inside(const mesh_context *c, stp_mesh_vertex *s, uint16_t i)
{
    if (s->state != 0)
        vertex_ready(c, s, i);
}

/* Whether the triangle of indices k (scratch entries s0, s1, s2; passed
 * one by one, not as enter_face's array, which a call would keep in
 * memory) is to be drawn, its vertices now
 * transformed and projected (1), or else the status to return for it
 * (STP_OK: wholly outside one plane; an error; the fallback's status for
 * one crossing a plane), the model's box not inside the view volume
 * (outcodes needed): ready_vertices' rare case. */
OUT_OF_LINE int ready_clipped(mesh_context *c, const uint16_t *k, stp_mesh_vertex *s0, stp_mesh_vertex *s1,
                              stp_mesh_vertex *s2)
{
    int32_t code0, code1, code2, any;
    stp_mesh_vertex *s[3];
    s[0] = s0;
    s[1] = s1;
    s[2] = s2;
    c->last_shade = -1; /* but for the fallback's */
    code0 = vertex_code(c, s[0], k[0]);
    code1 = vertex_code(c, s[1], k[1]);
    code2 = vertex_code(c, s[2], k[2]);
    any = code0 | code1 | code2;
    if (any & CODE_RANGE)
        return STP_ERR_RANGE;
    if ((code0 & code1 & code2) != 0)
        return STP_OK; /* wholly outside one plane */
    if (any != 0)
        return fast_fallback(c, k); /* crosses a plane: to be clipped */
    if (s[0]->state != 0)
        vertex_ready(c, s[0], k[0]); /* transformed: projected only */
    if (s[1]->state != 0)
        vertex_ready(c, s[1], k[1]);
    if (s[2]->state != 0)
        vertex_ready(c, s[2], k[2]);
    return 1;
}

/* ready_clipped's value for the triangle of indices k (scratch entries
 * s[0..2]): enter_face's path for a face with a vertex not ready, the
 * common case (every vertex inside the view volume: box_inside) here. */
static int ready_vertices(mesh_context *c, const uint16_t *k, stp_mesh_vertex *const s[3])
{
    if (c->inside) { /* box_inside: every outcode 0 */
        ready_inside(c, s[0], k[0]);
        ready_inside(c, s[1], k[1]);
        ready_inside(c, s[2], k[2]);
        return 1;
    }
    return ready_clipped(c, k, s[0], s[1], s[2]);
}

#if TIME_FIRST
/* The vertex average of scratch entries a, b, d without box_inside's
 * bound (stp_render_average3's 64-bit sums): out of the face loop's way
 * where time counts on a 32-bit core (M0+ torus: 840 instructions, 2 400
 * cycles a frame fewer); elsewhere enter_face's own code (the shorter at
 * -Os, the faster on a 64-bit host). */
STP_NOINLINE stp_vec3 wide_centre(const stp_mesh_vertex *a, const stp_mesh_vertex *b, const stp_mesh_vertex *d)
{
    stp_vec3 centre;
    centre.x = stp_render_average3(0, a->view.x, b->view.x, d->view.x);
    centre.y = stp_render_average3(0, a->view.y, b->view.y, d->view.y);
    centre.z = stp_render_average3(0, a->view.z, b->view.z, d->view.z);
    return centre;
}
#endif

/* The triangle of indices k and normal n on the fast path, not removed as
 * a back face (face_side's side: enter_faces). */
STP_HOT_INLINE int enter_face(mesh_context *c, const uint16_t *k, const int16_t *n, int32_t side)
{
    stp_mesh_vertex *s[3];
    int16_t nv[3];
    stp_vec3 centre;
    int style, ready;
    s[0] = &c->scratch[k[0]];
    s[1] = &c->scratch[k[1]];
    s[2] = &c->scratch[k[2]];
    if ((s[0]->state | s[1]->state | s[2]->state) != 0 && (ready = ready_vertices(c, k, s)) != 1)
        return ready;
#if STP_WINDING_SIDE
    /* the side by the winding of the projected vertices (render_private.h) */
    side = stp_render_winding_side(s[0]->dx, s[0]->dy, s[1]->dx, s[1]->dy, s[2]->dx, s[2]->dy);
    if (side < c->least_side) {
        c->last_shade = -1;
        return STP_OK; /* a back face removed */
    }
#endif
    if (!stp_render_triangle_shows(c->r, c->test_rows, s[0]->dx, s[0]->dy, s[1]->dx, s[1]->dy, s[2]->dx,
                                   s[2]->dy)) {
        c->last_shade = -1;
        return STP_OK; /* between two row centres, or pixel culling: draws nothing */
    }
    stp_render_view_normal(c->frame, n, side, nv);
#if TIME_FIRST
    if (!c->inside)
        centre = wide_centre(s[0], s[1], s[2]);
    else
#endif
    {
        centre.x = stp_render_average3(c->inside, s[0]->view.x, s[1]->view.x, s[2]->view.x);
        centre.y = stp_render_average3(c->inside, s[0]->view.y, s[1]->view.y, s[2]->view.y);
        centre.z = stp_render_average3(c->inside, s[0]->view.z, s[1]->view.z, s[2]->view.z);
    }
    if (c->shade) {
        c->last_shade = stp_render_face_shade(c->shade, nv, centre, side);
        style = stp_intensity_index_unit(c->last_shade, c->steps); /* the shade in [0, 1] */
    } else {
        style = c->fill_style;
        c->last_shade = c->fill_shade;
    }
    return store_face(c, s, style);
}

/* The fast path's loop over count (> 0) triangles, by pointers to their
 * indices and normals: a back face (or edge-on one) is removed before
 * enter_face.  Its last_shade (-1, as enter_face's) counts only for the
 * last triangle, the one stp_renderer_last_shade reports (face_side is
 * pure: asked again after the loop). */
static int enter_faces(mesh_context *c, uint16_t count)
{
    const uint16_t *k = c->mesh->triangles, *end = k + 3 * (uint32_t)count;
    const int16_t *n = c->mesh->normals;
    const stp_vec3 *vertices = c->vertices;
    int status = STP_OK;
    take_state(c);
    for (; k != end; k += 3, n += 3) {
#if STP_WINDING_SIDE
        /* every face to enter_face, which takes its side by the winding
         * once its vertices are projected (render_private.h) */
        int32_t side = 0;
        (void)vertices;
#elif SURE_BACK
        const stp_vec3 *a = &vertices[k[0]];
        int32_t side = face_estimate(c, n, a);
        if (side < c->sure_back)
            continue; /* surely a back face: no test of the estimate */
        if (side < 32768) { /* else surely a front face, entered */
            side = face_checked(c, n, a, side);
            if (side < c->least_side)
                continue; /* a back face removed */
        }
#elif STP_WIDE_ARITH
        /* the exact product's sign tested first: a removed back face (with
         * cull) costs two tests, no side formed */
        int64_t dot = stp_render_face_dot(c->frame, n, &vertices[k[0]]);
        int32_t side;
        if (dot <= 0 && c->cull)
            continue; /* a back face removed */
        side = dot > 0 ? 1 : (dot < 0 ? -1 : 0);
#else
        int32_t side = face_side(c, n, &vertices[k[0]]);
        if (side < c->least_side)
            continue; /* a back face removed */
#endif
        if ((status = enter_face(c, k, n, side)) != STP_OK)
            break;
    }
    /* (with the winding side enter_face marks a face it removes) */
    if (!STP_WINDING_SIDE && status == STP_OK && c->cull && face_side(c, n - 3, &vertices[k[-3]]) <= 0)
        c->last_shade = -1; /* removed: stp_renderer_last_shade */
    keep_state(c);
    return status;
}

/* The fallback route for each of the count triangles (a call the fast
 * path cannot take: fast_state, prepare_call), the scratch entries marked
 * new first (prepare_call's pass on the fast path); a call of its own,
 * out of the fast path's way. */
STP_NOINLINE int enter_slow(const mesh_context *c, uint16_t count)
{
    const uint16_t *k = c->mesh->triangles, *end = k + 3 * (uint32_t)count;
    int status = STP_OK;
    mark_new(c->scratch, c->mesh->vertex_count);
    for (; k != end; k += 3)
        if ((status = enter_fallback(c, k)) != STP_OK)
            break;
    return status;
}

#if STP_WIDE_ARITH
/* Four indices k[0..3] (< 2^16) as the 16-bit lanes of a 64-bit word v,
 * tested at once against a count c in every lane: the lanes' top bits
 * set exactly where an index is not below c.  A lane's v | 2^15 minus
 * d (d <= 2^15 in each lane: lanes) lies in [0, 2^16), so no borrow
 * crosses lanes, and its top bit is set just when the lane's low 15 bits
 * are at least d.  c <= 2^15 (high 0, d = c): or'd with v (its own top
 * bit); c > 2^15 (high 1, d = c - 2^15): and'd with v (an index not below
 * c has its top bit set and its low bits at least d).  The four loads are
 * one on a little-endian host (the compiler merges them). */
STP_HOT_INLINE uint64_t index_lanes_over(const uint16_t *k, uint64_t lanes, int high)
{
    const uint64_t top = 0x8000800080008000u;
    uint64_t v = (uint64_t)k[0] | (uint64_t)k[1] << 16 | (uint64_t)k[2] << 32 | (uint64_t)k[3] << 48;
    uint64_t t = (v | top) - lanes;
    return (high ? t & v : t | v) & top;
}

/* Six words (24 indices, eight triangles) from k: index_lanes_over's. */
STP_HOT_INLINE uint64_t index_block_over(const uint16_t *k, uint64_t lanes, int high)
{
    return index_lanes_over(k, lanes, high) | index_lanes_over(k + 4, lanes, high) |
           index_lanes_over(k + 8, lanes, high) | index_lanes_over(k + 12, lanes, high) |
           index_lanes_over(k + 16, lanes, high) | index_lanes_over(k + 20, lanes, high);
}

/* check_mesh's test of the indices k to the first multiple of eight
 * triangles where 64-bit words are registers: 24 indices (six words) a
 * step, 1.4 instructions an index against 2.7 (host torus: 3 000 indices,
 * about 3 100 instructions a frame fewer; the 100 000-triangle one, 50 000
 * vertices, the other form); 0 when one is not below count, else where
 * the rest begins.  One loop a form (high a constant in each). */
static const uint16_t *check_indices_wide(const uint16_t *k, uint16_t triangles, uint16_t count)
{
    const uint16_t *block_end = k + 24 * (uint32_t)(triangles >> 3);
    const uint64_t lane = 0x0001000100010001u;
    uint64_t over = 0;
    if (count <= 0x8000u)
        for (; k != block_end; k += 24)
            over |= index_block_over(k, count * lane, 0);
    else
        for (; k != block_end; k += 24)
            over |= index_block_over(k, (count - 0x8000u) * lane, 1);
    return over != 0 ? 0 : k;
}
#endif

/* The arguments and every index, before anything is entered. */
OUT_OF_LINE int check_mesh(const stp_renderer *r, const stp_mesh *mesh, const stp_mesh_vertex *scratch,
                      size_t scratch_count)
{
    const uint16_t *k, *end;
#if !STP_LEAN_CODE
    const uint16_t *pair_end;
#endif
    uint16_t count;
    if (r == 0 || mesh == 0 || scratch == 0 || scratch_count < mesh->vertex_count)
        return STP_ERR_ARG;
    if (mesh->triangle_count == 0)
        return STP_OK;
    if (mesh->vertices == 0 || mesh->triangles == 0)
        return STP_ERR_ARG;
    count = mesh->vertex_count;
    k = mesh->triangles;
    end = k + 3 * (uint32_t)mesh->triangle_count;
#if STP_WIDE_ARITH
    /* eight triangles a step; the loops below take the last few */
    if ((k = check_indices_wide(k, mesh->triangle_count, count)) == 0)
        return STP_ERR_ARG;
#endif
#if !STP_LEAN_CODE
    /* two triangles a step (half the loop's own cost) where time is
     * dearer than code; the loop below takes an odd count's last */
#if STP_WIDE_ARITH
    pair_end = k + 6 * ((uint32_t)(end - k) / 6u);
#else
    pair_end = k + 6 * (uint32_t)(mesh->triangle_count >> 1);
#endif
    for (; k != pair_end; k += 6)
        if (k[0] >= count || k[1] >= count || k[2] >= count || k[3] >= count || k[4] >= count ||
            k[5] >= count)
            return STP_ERR_ARG;
#endif
    for (; k != end; k += 3)
        if (k[0] >= count || k[1] >= count || k[2] >= count)
            return STP_ERR_ARG;
    return STP_OK;
}

int stp_renderer_mesh(stp_renderer *r, const stp_mesh *mesh, stp_mesh_vertex *scratch,
                      size_t scratch_count)
{
    mesh_context c;
    uint16_t count;
    int status = check_mesh(r, mesh, scratch, scratch_count), fast;
    if (status != STP_OK)
        return status;
    if (mesh->triangle_count == 0)
        return STP_OK;
    if ((status = stp_render_check_open(r)) != STP_OK)
        return status;
    c.r = r;
    c.mesh = mesh;
    c.vertices = mesh->vertices;
    c.cull = r->backface_removal;
    c.least_side = c.cull ? 1 : INT32_MIN;
#if SURE_BACK
    c.sure_back = c.cull ? -32768 : INT32_MIN;
#endif
    c.scratch = scratch;
    fast = fast_state(r, mesh) && prepare_call(&c);
    c.shade = fast && r->shading ? stp_render_face_shader(r) : 0;
    c.test_rows = r->pixel_cull;
    c.steps = stp_intensity_steps(r->levels);
    c.fill_style = r->fill_style;
    c.fill_shade = fast && !r->shading ? stp_intensity_shade(r->fill_style, r->levels) : 0;
#if !STP_WITH_MESH_FALLBACK
    if (!fast)
        return STP_ERR_UNSUPPORTED;
#endif
    count = mesh->triangle_count; /* once: the stores below may alias the mesh */
    /* one loop per route: no choice per triangle */
    status = fast ? enter_faces(&c, count) : enter_slow(&c, count);
    /* the open segment ends where the display file does (store_face
     * leaves this to here) */
    r->segments[r->open_segment].end = r->used;
    return status;
}
