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

/* stp_mesh_vertex.state: -1 not transformed in this call; else the outcode
 * (bits 0..4, clip.c) or CODE_RANGE, plus PROJECTED once dx, dy, dz hold
 * the device position. */
#define STATE_NEW (-1)
#define CODE_RANGE 32
#define PROJECTED 64

/* What one call finds once for all its triangles. */
typedef struct mesh_context {
    stp_renderer *r;
    const stp_mesh *mesh;
    const stp_vec3 *vertices; /* mesh->vertices */
    int cull; /* back faces are removed (r->backface_removal) */
    stp_mesh_vertex *scratch;
    const stp_model_frame *frame; /* the face stage's (render_private.h) */
    /* the eye in model coordinates, floor-shifted right by `shift`, so
     * that it and every shifted vertex are within 2^14 in magnitude (the
     * back-face test's first, 32-bit estimate) */
    int32_t eye[3];
    int shift;
    int inside; /* 1: every vertex is inside the view volume (no outcodes)
                   and its view coordinates are below 2^29 in magnitude */
    stp_view_lens lens; /* the projection's constants (view.c) */
    const stp_shade_fast *shade; /* the face stage's shader (stp_render_face_shader) */
    int32_t test_rows; /* rows of a triangle pixel culling (render.h) tests: STP_CENTRE_TEST_MAX, or 0 when off */
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

/* Whether every point of the model box [lo, hi] lands strictly inside the
 * view volume under the model and view transforms, with room for their
 * rounding: the box grown by a margin worth 64 raw view units (64 / s
 * model units, s the model's scale: s2 = s^2 2^(2F)) has its eight
 * corners inside (outcode 0, nothing saturated) and their view
 * coordinates below 2^28.  The volume is convex and the transforms affine,
 * so then every vertex is inside too, its outcode (0) need not be formed,
 * and its view coordinates are below 2^28 (plus the rounding): a sum of
 * three fits int32. */
static int box_inside(const stp_renderer *r, stp_vec3 lo, stp_vec3 hi, int64_t s2)
{
    uint32_t s = stp_sqrt64_fast((uint64_t)s2); /* s 2^F, >= 2^10 (similarity) */
    int64_t margin = ((int64_t)64 << F) / (int64_t)(s > 0 ? s : 1) + 1;
    int corner;
    for (corner = 0; corner < 8; corner++) {
        int64_t x = (corner & 1) ? (int64_t)hi.x + margin : (int64_t)lo.x - margin;
        int64_t y = (corner & 2) ? (int64_t)hi.y + margin : (int64_t)lo.y - margin;
        int64_t z = (corner & 4) ? (int64_t)hi.z + margin : (int64_t)lo.z - margin;
        stp_vec3 p, view;
        if (x <= STP_FIX_MIN || x >= STP_FIX_MAX || y <= STP_FIX_MIN || y >= STP_FIX_MAX ||
            z <= STP_FIX_MIN || z >= STP_FIX_MAX)
            return 0;
        p.x = (stp_fix)x;
        p.y = (stp_fix)y;
        p.z = (stp_fix)z;
        if (stp_render_point_to_view(r, p, &view) || stp_view_saturated(view) || stp_clip_outcode(&r->clip_volume, view) != 0 ||
            (stp_abs32(view.x) | stp_abs32(view.y) | stp_abs32(view.z)) >= ((uint32_t)1 << 28))
            return 0;
    }
    return 1;
}

/* The per-call values of the fast path (mesh_context); 0 when the model
 * frame (render_private.h: the model transform, the eye's place) rules it
 * out. */
static int prepare_call(mesh_context *c)
{
    const stp_renderer *r = c->r;
    const stp_model_frame *f = stp_render_model_frame(c->r);
    uint32_t big = 0;
    stp_vec3 lo, hi;
    uint16_t v;
    int j, k;
    if (f == 0)
        return 0;
    c->frame = f;
    for (j = 0; j < 3; j++)
        big |= stp_abs32(f->eye[j]);
    /* the scale of the back-face test (every coordinate below 2^14) and
     * the model's bounding box */
    lo = hi = c->mesh->vertices[0];
    for (v = 0; v < c->mesh->vertex_count; v++) {
        const stp_vec3 *p = &c->mesh->vertices[v];
        lo.x = p->x < lo.x ? p->x : lo.x;
        lo.y = p->y < lo.y ? p->y : lo.y;
        lo.z = p->z < lo.z ? p->z : lo.z;
        hi.x = p->x > hi.x ? p->x : hi.x;
        hi.y = p->y > hi.y ? p->y : hi.y;
        hi.z = p->z > hi.z ? p->z : hi.z;
    }
    /* the box's corners bound every coordinate's magnitude */
    big |= stp_abs32(lo.x) | stp_abs32(lo.y) | stp_abs32(lo.z) | stp_abs32(hi.x) |
           stp_abs32(hi.y) | stp_abs32(hi.z);
    c->inside = box_inside(r, lo, hi, f->scale2);
    c->lens.focal = r->focal;
    c->lens.hither = r->hither;
    c->lens.half_width = (int32_t)r->width << (STP_SUBPIXEL_BITS - 1);
    c->lens.half_height = (int32_t)r->height << (STP_SUBPIXEL_BITS - 1);
    k = stp_bit_length32(big) - 14;
    c->shift = k > 0 ? k : 0;
    for (j = 0; j < 3; j++)
        c->eye[j] = stp_asr32(f->eye[j], c->shift);
    return 1;
}

/* ---- per vertex and per face ---- */

/* Vertex i (not transformed yet, scratch entry *s) in view coordinates
 * with its outcode (or CODE_RANGE): the geometry stage, as
 * stp_renderer_polygon's. */
static void vertex_transform(mesh_context *c, stp_mesh_vertex *s, uint16_t i)
{
    const stp_renderer *r = c->r;
    int range = stp_render_point_to_view(r, c->vertices[i], &s->view);
    if (c->inside)
        s->state = 0; /* box_inside: no vertex is outside or saturated */
    else
        s->state = range || stp_view_saturated(s->view) ? CODE_RANGE
                                               : (int32_t)stp_clip_outcode(&r->clip_volume, s->view);
}

/* Vertex i's outcode (or CODE_RANGE), transformed once per call; the
 * common case, a vertex an earlier face transformed, stays inline. */
STP_HOT_INLINE int32_t vertex_code(mesh_context *c, stp_mesh_vertex *s, uint16_t i)
{
    if (s->state == STATE_NEW)
        vertex_transform(c, s, i);
    return s->state & (CODE_RANGE | 31);
}

/* Vertex *s's device position, projected once per call (it is inside the
 * view volume: its outcode is 0). */
static void vertex_project(const mesh_context *c, stp_mesh_vertex *s)
{
    int32_t d[3];
    stp_view_perspective_device(&c->lens, &s->view, d); /* perspective (fast_state) */
    s->dx = d[0];
    s->dy = d[1];
    s->dz = d[2];
    s->state |= PROJECTED;
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

/* The display-file records of a front face inside the view (scratch
 * entries s[0..2], projected): SHADE when the style changed, then its
 * three vertices (the open segment's end: set once per call,
 * stp_renderer_mesh). */
static int store_face(mesh_context *c, stp_mesh_vertex *const s[3], int style)
{
    stp_instr *out = stp_render_triangle_records(c->r, style);
    if (out == 0)
        return STP_ERR_FULL;
    stp_render_put_vertex(&out[0], 3, s[0]->dx, s[0]->dy, s[0]->dz);
    stp_render_put_vertex(&out[1], STP_OP_LINE, s[1]->dx, s[1]->dy, s[1]->dz);
    stp_render_put_vertex(&out[2], STP_OP_LINE, s[2]->dx, s[2]->dy, s[2]->dz);
    return STP_OK;
}

/* The face stage's side of triangle t (stp_render_face_side: the exact
 * sign of N.(eye - v0)); where 64-bit products are library calls, first
 * estimated in 32 bits on the shifted eye and v0: products below 2^29, the
 * sum below 2^31 (|N| <= 1, |eye - v0| < 2^15 sqrt 3), off the exact sum
 * over 2^shift by less than |n0| + |n1| + |n2| < 2^15 (each floor less
 * than 1), so a larger estimate has the exact sign. */
static int face_side(const mesh_context *c, const int16_t *n, const stp_vec3 *a)
{
#if !STP_WIDE_ARITH
    int32_t side = (int32_t)n[0] * (c->eye[0] - stp_asr32(a->x, c->shift)) +
                   (int32_t)n[1] * (c->eye[1] - stp_asr32(a->y, c->shift)) +
                   (int32_t)n[2] * (c->eye[2] - stp_asr32(a->z, c->shift));
    if (side >= ((int32_t)1 << 15) || side <= -((int32_t)1 << 15))
        return side > 0 ? 1 : -1;
#endif
    return stp_render_face_side(c->frame, n, *a);
}

/* The triangle of indices k and normal n on the fast path, not removed as
 * a back face (face_side's side: enter_faces). */
static int enter_face(mesh_context *c, const uint16_t *k, const int16_t *n, int side)
{
    stp_renderer *r = c->r;
    stp_mesh_vertex *s[3];
    int16_t nv[3];
    int32_t code0, code1, code2, all, any;
    stp_vec3 centre;
    int style;
    r->last_shade = -1;
    s[0] = &c->scratch[k[0]];
    s[1] = &c->scratch[k[1]];
    s[2] = &c->scratch[k[2]];
    code0 = vertex_code(c, s[0], k[0]);
    code1 = vertex_code(c, s[1], k[1]);
    code2 = vertex_code(c, s[2], k[2]);
    all = code0 & code1 & code2;
    any = code0 | code1 | code2;
    if (any & CODE_RANGE)
        return STP_ERR_RANGE;
    if (all != 0)
        return STP_OK; /* wholly outside one plane */
    if (any != 0)
        return enter_fallback(c, k); /* crosses a plane: to be clipped */
    if ((s[0]->state & PROJECTED) == 0)
        vertex_project(c, s[0]);
    if ((s[1]->state & PROJECTED) == 0)
        vertex_project(c, s[1]);
    if ((s[2]->state & PROJECTED) == 0)
        vertex_project(c, s[2]);
    if (!stp_render_triangle_shows(r, c->test_rows, s[0]->dx, s[0]->dy, s[1]->dx, s[1]->dy, s[2]->dx,
                                   s[2]->dy))
        return STP_OK; /* between two row centres, or pixel culling: draws nothing */
    stp_render_view_normal(c->frame, n, side, nv);
    centre.x = stp_render_average3(c->inside, s[0]->view.x, s[1]->view.x, s[2]->view.x);
    centre.y = stp_render_average3(c->inside, s[0]->view.y, s[1]->view.y, s[2]->view.y);
    centre.z = stp_render_average3(c->inside, s[0]->view.z, s[1]->view.z, s[2]->view.z);
    style = stp_render_face_style(r, c->shade, nv, centre, side);
    return store_face(c, s, style);
}

/* The fast path's loop over count triangles, by pointers to their indices
 * and normals: a back face (or edge-on one) is removed before enter_face
 * (and its last_shade is -1 as there). */
static int enter_faces(mesh_context *c, uint16_t count)
{
    const uint16_t *k = c->mesh->triangles, *end = k + 3 * (uint32_t)count;
    const int16_t *n = c->mesh->normals;
    int status;
    for (; k != end; k += 3, n += 3) {
        int side = face_side(c, n, &c->vertices[k[0]]);
        if (side <= 0 && c->cull) {
            c->r->last_shade = -1; /* removed: stp_renderer_last_shade */
            continue;
        }
        if ((status = enter_face(c, k, n, side)) != STP_OK)
            return status;
    }
    return STP_OK;
}

/* The arguments and every index, before anything is entered. */
static int check_mesh(const stp_renderer *r, const stp_mesh *mesh, const stp_mesh_vertex *scratch,
                      size_t scratch_count)
{
    const uint16_t *k, *end;
    uint16_t count;
    if (r == 0 || mesh == 0 || scratch == 0 || scratch_count < mesh->vertex_count)
        return STP_ERR_ARG;
    if (mesh->triangle_count == 0)
        return STP_OK;
    if (mesh->vertices == 0 || mesh->triangles == 0)
        return STP_ERR_ARG;
    count = mesh->vertex_count;
    end = mesh->triangles + 3 * (uint32_t)mesh->triangle_count;
    for (k = mesh->triangles; k != end; k += 3)
        if (k[0] >= count || k[1] >= count || k[2] >= count)
            return STP_ERR_ARG;
    return STP_OK;
}

int stp_renderer_mesh(stp_renderer *r, const stp_mesh *mesh, stp_mesh_vertex *scratch,
                      size_t scratch_count)
{
    mesh_context c;
    stp_mesh_vertex *sv, *end;
    uint16_t t, count;
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
    c.scratch = scratch;
    fast = fast_state(r, mesh) && prepare_call(&c);
    c.shade = fast && r->shading ? stp_render_face_shader(r) : 0;
    c.test_rows = r->pixel_cull ? STP_CENTRE_TEST_MAX : 0;
#if !STP_WITH_MESH_FALLBACK
    if (!fast)
        return STP_ERR_UNSUPPORTED;
#endif
    for (sv = scratch, end = scratch + mesh->vertex_count; sv != end; sv++)
        sv->state = STATE_NEW;
    count = mesh->triangle_count; /* once: the stores below may alias the mesh */
    /* one loop per route: no choice per triangle */
    if (fast) {
        status = enter_faces(&c, count);
    } else {
        for (t = 0; t < count; t++)
            if ((status = enter_fallback(&c, &mesh->triangles[3 * (uint32_t)t])) != STP_OK)
                break;
    }
    /* the open segment ends where the display file does (store_face
     * leaves this to here) */
    r->segments[r->open_segment].end = r->used;
    return status;
}
