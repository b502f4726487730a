/* SPDX-License-Identifier: MIT */
/* Private: the renderer object and what render.c and raster.c share. */
#ifndef STIPPLE_RENDER_PRIVATE_H
#define STIPPLE_RENDER_PRIVATE_H

#include "stipple/render.h"
#include "fix_private.h"
#include "clip_private.h"
#include "view_private.h"
#include "shade_fast_private.h"
#include "shade_private.h"

#define STP_CLIP_VERTICES (STP_MAX_POLYGON_VERTICES + 5)

typedef struct stp_segment {
    int32_t id;
    uint32_t start, end; /* display-file entries [start, end) */
    uint8_t used, open, visible;
} stp_segment;

/* One edge of a polygon being scan-converted, oriented top to bottom
 * (stp_edge_setup).  Coordinates Q27.4: the edge covers row centres
 * ya <= yc < yb, starting at x = xa.  step: its change of x per row (16 Q4
 * y units) in Q4 x units with 16 fractional bits, 16 times the slope
 * trunc(2^16 (xb - xa) / (yb - ya)) (|step| < 2^40); acc: x at the row
 * centre being scanned with 16 fractional bits, xa 2^16 + (yc - ya) slope
 * (below 2^52 in magnitude: |yc - ya| < 2^20 and |slope| < 2^36), so
 * floor(acc / 2^16) is the crossing.  Smooth polygons: the shade sa at
 * the top, shade_step and shade_acc likewise with 16 more fractional bits. */
typedef struct stp_edge {
    int64_t step, acc; /* the 64-bit fields first: no padding */
#if STP_WITH_GOURAUD
    int64_t shade_step, shade_acc;
    int32_t sa;
#endif
    int32_t xa, ya, yb;
#if STP_WITH_EDGE_AA
    int32_t aa_slope, aa_lo, aa_hi; /* for the crossings (stp_crossing) */
#endif
} stp_edge;

/* A crossing of a row by an edge: x (Q27.4), for smooth polygons the shade
 * there, and with edge anti-aliasing compiled in its edge's slope and x
 * extent. */
typedef struct stp_crossing {
    int32_t x;
#if STP_WITH_GOURAUD
    int32_t shade;
#endif
#if STP_WITH_EDGE_AA
    /* the edge's slope (stp_edge_aa_slope) and x extent (Q4), for edge_aa.c */
    int32_t slope, x_lo, x_hi;
#endif
} stp_crossing;


#if STP_WITH_SHADOWS
/* A light's shadow map (render.h, stp_renderer_set_shadow_map).  The light's frame:
 * origin at the light, z along the map's axis, x right, y up (left-handed
 * like the view).  A view point p goes to the light's frame as
 * p_l = m p + t: m is the rotation (Q28: entries are cosines, |m| <= 1 + a
 * rounding), t the view's origin (the eye) in the light's frame (stp_fix). */
typedef struct stp_shadow_map {
    uint16_t *depth;     /* NULL: no map for this light */
    uint32_t width, height;
    uint32_t generation; /* 1..2^23-1, kept in the records (STP_OP_LIGHT_TERM) */
    int32_t m[3][3];
    stp_fix t[3];
    stp_vec3 light_view; /* the light in view coordinates when the map was set */
    stp_fix focal;       /* texels per unit of x_l / z_l, F fractional bits */
    stp_fix near;        /* > 0 */
    stp_clip_volume volume; /* the map's pyramid, for clip.c */
} stp_shadow_map;

/* What the raster needs to re-light the pixels of one polygon, gathered
 * from its STP_OP_LIGHT_TERM records (shadow.c). */
typedef struct stp_shadow_poly {
    int count;                    /* lights tested; 0: the polygon has no record */
    int light[STP_MAX_LIGHTS];    /* their indices */
    int32_t bias[STP_MAX_LIGHTS]; /* their b (map depth units) */
    uint32_t tested;              /* bit j: light j is tested */
    int grey;                     /* STP_LIGHT_TERM_GREY record */
    stp_fix ambient, brightness;
    stp_fix terms[STP_MAX_LIGHTS]; /* by light index; 0 for untested ones */
    stp_fix full;                 /* the shade with every light */
    /* depth key plane: key(xq, yq) = (k0 + gx (xq - x0) + gy (yq - y0))
     * 2^shift / 2^16 raw key units, xq, yq device Q27.4 */
    int64_t k0, gx, gy;
    int32_t x0, y0;
    int shift;
} stp_shadow_poly;
#endif

#if STP_VERTEX_CACHE
/* One vertex cache entry (config.h, STP_VERTEX_CACHE): an entered point
 * (before the model transform), its view coordinates, its outcode and,
 * once known, its device position.  Valid while stamp equals the renderer's
 * cache_stamp (set_view, set_transform and segment_create change that). */
typedef struct stp_vertex_entry {
    stp_vec3 point, view;
    uint32_t stamp;
    int16_t code;           /* outcode (0..31) or STP_CODE_RANGE */
    uint16_t used_by;       /* the last polygon that took it (cache_polygon) */
    int32_t dx, dy, dz;     /* device position (project), when projected */
} stp_vertex_entry;
#define STP_CACHE_NOT_PROJECTED INT32_MIN /* dx of an entry not projected yet */
#define STP_CODE_RANGE 32    /* code of a saturated view point (STP_ERR_RANGE) */
#define STP_CACHE_NONE 0xFFFFu /* cached[i] of a vertex kept outside the cache */
#endif


struct stp_renderer {
    stp_instr *df;
    uint32_t capacity, used;
    uint32_t width, height;

    stp_segment segments[STP_MAX_SEGMENTS];
    int open_segment; /* index into segments, -1 when none */
    int fill_style, levels;

#if !STP_PLAYBACK_ONLY /* the entry side's state: playback.c sets none of it */
    /* view: orthonormal basis (world units), centre of projection */
    stp_vec3 from, right, up, forward;
    /* world_facing_near: from - 2^20 per coordinate, mod 2^32, and whether
     * |from| < 2^30 in each (then v - from is within (-2^31 - 2^30, 2^31 +
     * 2^30), so its residue mod 2^32 within 2^20 of 0 is the difference) */
    uint32_t near_bias_x, near_bias_y, near_bias_z;
    int near_ok;
    stp_view_transform to_view; /* world to view (view.c) */
    stp_projection projection;
    stp_fix hither;
    stp_fix focal; /* perspective: pixels per (x/z); parallel: pixels per unit */
    stp_clip_volume clip_volume; /* the view's, for clip.c */

    stp_lighting user_lighting;    /* what SET-LIGHT last said (world) */
    stp_lighting segment_lighting; /* COPY-LIGHT of the open segment (view) */
    stp_material material;
    int shading, backface_removal;
    int current_style;      /* polygon style last entered in the open segment, -1 none */
    int current_line_style; /* line style likewise */
    int colour;             /* colour shading on */
    stp_fix t_min, t_max, t_attenuation; /* transparency (t_attenuation:
                                            e^(-a d), 1 when none) */
    int t_power;
    stp_fix current_transmission; /* t last entered in the open segment */
    int32_t current_colour; /* colour last entered with current_style */
    stp_fix last_shade;
    /* the face stage's shading constants (stp_render_face_shader:
     * stp_shade_fast_prepare of segment_lighting, material and the eye at
     * the view origin, or the direction towards the eye of a parallel
     * view), prepared on the first shaded face after they change:
     * open_segment clears fast_shade_valid when the copied lighting differs
     * from the last segment's, set_object_shade when the material differs,
     * set_view when the projection changes; fast_shade_parallel: the
     * projection they were prepared for */
    stp_shade_fast fast_shade;
    int fast_shade_valid;
    int fast_shade_parallel;
    /* the face stage's model frame (stp_render_model_frame), for the view
     * and model transform in force; frame_valid cleared with the vertex
     * cache (cache_forget) */
    stp_model_frame frame;
    int frame_valid;

    int pen_valid;
    stp_vec3 pen; /* view coordinates */
    stp_transform model; /* of the open segment's points (stp_renderer_set_transform) */
    int model_on;        /* 0: the identity, skipped */
    /* the geometry stage (view_private.h) for the open segment's points:
     * STP_GEOMETRY_VIEW (no model transform: point_view is to_view),
     * STP_GEOMETRY_COMPOSED (point_view: model then view, composed) or
     * STP_GEOMETRY_TWO_STEPS (model, then to_view); set with the view and
     * the model transform (stp_render_geometry_update) */
    int geometry;
    stp_view_transform point_view;

    /* scratch: the clipper's two vertex lists and the scan converter's
     * edges; here rather than on the stack so a small MCU stack suffices */
    stp_vec3 clip_a[STP_CLIP_VERTICES];
    stp_vec3 clip_b[STP_CLIP_VERTICES];
#if STP_WITH_GOURAUD
    stp_fix shade_a[STP_CLIP_VERTICES]; /* per-vertex shades beside clip_a/b */
    stp_fix shade_b[STP_CLIP_VERTICES];
#endif
#if STP_VERTEX_CACHE
    stp_vertex_entry cache[STP_VERTEX_CACHE];
    uint32_t cache_stamp; /* >= 1 */
    uint16_t cache_polygon; /* serial of the polygon being entered (wraps) */
    uint16_t cached[STP_MAX_POLYGON_VERTICES]; /* clip_a[i]'s entry in cache[] */
#endif
#endif /* !STP_PLAYBACK_ONLY */
    stp_edge edges[STP_CLIP_VERTICES];
    stp_crossing crossings[STP_CLIP_VERTICES];

#if STP_WITH_SHADOWS
    stp_shadow_map shadow[STP_MAX_LIGHTS];
    uint32_t shadow_generation; /* of the last map set */
    uint32_t shadow_set;        /* bit j: shadow[j].depth != 0 */
    uint32_t shadow_record[STP_MAX_LIGHTS]; /* display-file entry of the
                                               polygon being entered's record
                                               for light j, or UINT32_MAX */
    stp_vec3 at; /* the view's look-at point (world) */
#endif
};

#if !STP_PLAYBACK_ONLY
/* render.c, for mesh.c: an implicit segment opened when none is (as
 * stp_renderer_polygon does; STP_OK or its error), and the device position
 * (Q27.4) and depth key of a view point inside the view volume, exactly as
 * stp_renderer_polygon stores it. */
int stp_render_check_open(stp_renderer *r);
void stp_render_project(const stp_renderer *r, stp_vec3 p, stp_instr *out);

/* The face stage (render.c), shared by stp_renderer_polygon and
 * stp_renderer_mesh: a flat face's normal, side and shade are formed by
 * these functions on either route, so both enter a face alike.
 *
 * stp_render_model_normal: the unit normal of polygon v (n >= 3 points in
 * model coordinates, wound counter-clockwise seen from the side it points
 * to) as Q1.14 in out[]: a triangle's exact cross product, a longer
 * polygon's Newell sum, normalised once and rounded.  Returns 0 (out
 * unset) for a zero normal.  stp_mesh_prepare_normals is this for each
 * triangle. */
int stp_render_model_normal(const stp_vec3 *v, int n, int16_t out[3]);
/* Here, for render.c and mesh.c (direct drawing links mesh.c's
 * stp_mesh_prepare_normals without render.c): (a, b, c) (|.| < 2^62) as a
 * Q1.14 unit vector in out[] (STP_UNIT, Q30, rounded to nearest), 0 for a
 * zero vector; */
static inline int stp_render_unit_q14(int64_t a, int64_t b, int64_t c, int16_t out[3])
{
    stp_unit3 u;
    if (stp_unit_from64(a, b, c, &u) == 0)
        return 0;
    out[0] = (int16_t)stp_asr64((int64_t)u.x + ((int64_t)1 << 15), 16);
    out[1] = (int16_t)stp_asr64((int64_t)u.y + ((int64_t)1 << 15), 16);
    out[2] = (int16_t)stp_asr64((int64_t)u.z + ((int64_t)1 << 15), 16);
    return 1;
}

/* a triangle's cross product (v1 - v0) x (v2 - v0) in c[] (model
 * coordinates): the edge vectors (below 2^33) cut to 30 bits together
 * (floor), so each term is below 2^61 and each component below 2^62; the
 * cut keeps the direction within 2^-28 of the exact one. */
static inline void stp_render_triangle_cross(const stp_vec3 *v, int64_t c[3])
{
    int64_t x1 = (int64_t)v[1].x - v[0].x, y1 = (int64_t)v[1].y - v[0].y,
            z1 = (int64_t)v[1].z - v[0].z;
    int64_t x2 = (int64_t)v[2].x - v[0].x, y2 = (int64_t)v[2].y - v[0].y,
            z2 = (int64_t)v[2].z - v[0].z;
    uint64_t spread = stp_abs64u(x1) | stp_abs64u(y1) | stp_abs64u(z1) | stp_abs64u(x2) |
                      stp_abs64u(y2) | stp_abs64u(z2);
    if (spread >> 30) {
        int bits = stp_bit_length64(spread) - 30;
        x1 = stp_asr64(x1, bits);
        y1 = stp_asr64(y1, bits);
        z1 = stp_asr64(z1, bits);
        x2 = stp_asr64(x2, bits);
        y2 = stp_asr64(y2, bits);
        z2 = stp_asr64(z2, bits);
    }
    c[0] = y1 * z2 - z1 * y2;
    c[1] = z1 * x2 - x1 * z2;
    c[2] = x1 * y2 - y1 * x2;
}

/* a triangle's normal (stp_render_model_normal for n = 3): its cross
 * product, normalised. */
static inline int stp_render_triangle_normal(const stp_vec3 *v, int16_t out[3])
{
    int64_t c[3];
    stp_render_triangle_cross(v, c);
    return stp_render_unit_q14(c[0], c[1], c[2], out);
}


#define STP_GEOMETRY_VIEW 0
#define STP_GEOMETRY_COMPOSED 1
#define STP_GEOMETRY_TWO_STEPS 2

/* render.c: r->geometry (and r->point_view) for the view and model
 * transform in force. */
void stp_render_geometry_update(stp_renderer *r);

/* The geometry stage for an entered point p (model coordinates): its view
 * coordinates in *out, each saturated; returns 1 when the model transform
 * (two steps: stp_view_point_two_steps, view.c) saturated it: the point
 * lies beyond what the coordinates hold (the caller reports
 * STP_ERR_RANGE), else 0. */
STP_HOT_INLINE int stp_render_point_to_view(const stp_renderer *r, stp_vec3 p, stp_vec3 *out)
{
    if (r->geometry == STP_GEOMETRY_TWO_STEPS)
        return stp_view_point_two_steps(&r->model, &r->to_view, p, out);
    STP_VIEW_TRANSFORM_POINT(&r->point_view, p, out); /* inline where 64-bit products are */
    return 0;
}

/* The model frame of the view and model transform in force (prepared once
 * after either changes), or NULL when it is not usable (see above). */
const stp_model_frame *stp_render_model_frame(stp_renderer *r);
/* The face shader of the segment's lighting and the material
 * (stp_shade_fast_prepare), prepared when out of date. */
const stp_shade_fast *stp_render_face_shader(stp_renderer *r);

/* The exact sign (-1, 0, 1) of N.(eye - v0) in model coordinates: which
 * side of a face with Q1.14 model normal n through model point v0 the eye
 * sees (1: the side n points to).  |eye - v0| < 2^30 + 2^31 per
 * coordinate: each product below 2^46, the sum below 2^48. */
STP_HOT_INLINE int stp_render_face_side(const stp_model_frame *f, const int16_t n[3], stp_vec3 v0)
{
    int64_t side = (int64_t)n[0] * ((int64_t)f->eye[0] - v0.x) +
                   (int64_t)n[1] * ((int64_t)f->eye[1] - v0.y) +
                   (int64_t)n[2] * ((int64_t)f->eye[2] - v0.z);
    return side > 0 ? 1 : (side < 0 ? -1 : 0);
}

/* The side of a triangle with cross product c (stp_render_triangle_cross)
 * through v0 that stp_render_face_side gives for its normal n (c
 * normalised and rounded to Q1.14), found without normalising when the
 * sign is certain: 1 or -1, else 0 (near edge-on: the caller normalises).
 * With c and d = eye - v0 cut to 29 bits by floor shifts (c = 2^a cs + rc,
 * d = 2^b ds + rd, 0 <= r < 2^shift), |c.d - 2^(a+b) cs.ds| <= 2^(a+b)
 * (|cs|1 + |ds|1 + 3).  n = 2^14 c/|c| + delta with |delta_i| < 1 (the
 * rounding's half plus stp_unit_from64's error and the cut's 2^-28), so
 * n.d = 2^14 c.d/|c| + delta.d keeps the sign of c.d when 2^14 |c.d| >
 * 2 |c|1 |d|1 (a margin of 2), with |c|1 <= 2^a (|cs|1 + 3) and |d|1 <=
 * 2^b (|ds|1 + 3).  |cs|1 <= 3 C and |ds|1 <= 3 D for C and D the ORs of
 * the magnitudes: certain when |cs.ds| > 3 C + 3 D + 3 + (3 C + 3)(3 D + 3)
 * / 2^13.  Ranges: |cs|, |ds| <= 2^29, so C, D < 2^30, cs.ds below
 * 3 2^58 and (3 C + 3)(3 D + 3) below 2^64 (unsigned). */
static inline int stp_render_certain_side(const stp_model_frame *f, const int64_t c[3], stp_vec3 v0)
{
    int64_t cx = c[0], cy = c[1], cz = c[2], dot;
    int64_t dx = (int64_t)f->eye[0] - v0.x, dy = (int64_t)f->eye[1] - v0.y,
            dz = (int64_t)f->eye[2] - v0.z;
    uint64_t c_or = stp_abs64u(cx) | stp_abs64u(cy) | stp_abs64u(cz);
    uint64_t d_or = stp_abs64u(dx) | stp_abs64u(dy) | stp_abs64u(dz), bound;
    if ((c_or | d_or) >> 29) {
        int a = stp_bit_length64(c_or) - 29, b = stp_bit_length64(d_or) - 29;
        if (a > 0) {
            cx = stp_asr64(cx, a);
            cy = stp_asr64(cy, a);
            cz = stp_asr64(cz, a);
            c_or = stp_abs64u(cx) | stp_abs64u(cy) | stp_abs64u(cz);
        }
        if (b > 0) {
            dx = stp_asr64(dx, b);
            dy = stp_asr64(dy, b);
            dz = stp_asr64(dz, b);
            d_or = stp_abs64u(dx) | stp_abs64u(dy) | stp_abs64u(dz);
        }
    }
    dot = cx * dx + cy * dy + cz * dz;
    bound = 3u * (c_or + d_or + 1u) + (((3u * c_or + 3u) * (3u * d_or + 3u)) >> 13) + 1u;
    if (stp_abs64u(dot) <= bound)
        return 0;
    return dot > 0 ? 1 : -1;
}

/* Whether a triangle with device y coordinates a, b, c (Q27.4, >= 0: the
 * projection clamps them into the picture) spans a row centre 16 r + 8 in
 * [min, max): the rasters (raster.c's row_below and the polygon edges)
 * draw exactly those rows, so a triangle spanning none draws no pixel in
 * any mode, edge AA included (it works on the rows drawn).  Both entries
 * leave such a triangle out before shading it. */
STP_HOT_INLINE int stp_render_rows_spanned(int32_t a, int32_t b, int32_t c)
{
    int32_t lo = a < b ? a : b, hi = a < b ? b : a;
    if (c < lo)
        lo = c;
    if (c > hi)
        hi = c;
    const int32_t below_centre = (1 << (STP_SUBPIXEL_BITS - 1)) - 1;
    return ((uint32_t)(lo + below_centre) >> STP_SUBPIXEL_BITS) !=
           ((uint32_t)(hi + below_centre) >> STP_SUBPIXEL_BITS);
}

/* The model normal n in view coordinates (Q1.14, rounded), turned to the
 * eye when side <= 0 (the other side of an open surface shows): each row
 * product Q15 x Q14, the sum below 2^29 (1 + rounding), to Q14 rounded
 * (floor of the sum plus a half: >> of a negative value is
 * implementation-defined, so the shift is taken on a value made positive). */
STP_HOT_INLINE int16_t stp_render_view_normal_row(const int32_t row[3], const int16_t n[3], int side)
{
    int32_t s = row[0] * n[0] + row[1] * n[1] + row[2] * n[2] + ((int32_t)1 << 14);
    s = (int32_t)(((uint32_t)s + ((uint32_t)1 << 30)) >> 15) - ((int32_t)1 << 15);
    return (int16_t)(side > 0 ? s : -s);
}

STP_HOT_INLINE void stp_render_view_normal(const stp_model_frame *f, const int16_t n[3], int side,
                                           int16_t nv[3])
{
    nv[0] = stp_render_view_normal_row(f->rot[0], n, side);
    nv[1] = stp_render_view_normal_row(f->rot[1], n, side);
    nv[2] = stp_render_view_normal_row(f->rot[2], n, side);
}

/* A flat face's INTENSITY style (1..levels) with shading on (its shade by
 * the face shader s from view normal nv and vertex average centre; the
 * ambient share only, as for N.E = 0, when side is 0: its plane passes
 * through the eye) or off (the fill style); r->last_shade set to its
 * shade. */
STP_HOT_INLINE int stp_render_face_style(stp_renderer *r, const stp_shade_fast *s, const int16_t nv[3],
                                         stp_vec3 centre, int side)
{
    int style;
    if (r->shading) {
        r->last_shade = side != 0 ? stp_shade_fast_face(s, nv, centre) : s->ambient_shade;
        return stp_intensity_index_inline(r->last_shade, r->levels);
    }
    style = r->fill_style;
    r->last_shade = stp_intensity_shade(style, r->levels);
    return style;
}
#endif

#if STP_WITH_SHADOWS

/* shadow.c, at entry: the STP_OP_LIGHT_TERM records of a polygon shaded
 * with this normal at this centre (view coordinates; colour: a colour
 * polygon), in record[] (1 + STP_MAX_LIGHTS entries, op unset): returns
 * how many, 0 when no map can darken it.  Biases are 1 until
 * stp_shadow_enter sets them through r->shadow_record. */
int stp_shadow_records(const stp_renderer *r, stp_vec3 normal, stp_vec3 centre, stp_vec3 eye_dir,
                       int colour, stp_instr *record);
/* shadow.c, at entry, once the polygon (world vertices, n validated) is in
 * the display file or was dropped from it with STP_OK: draw its depth into
 * every map and patch its records' biases. */
void stp_shadow_enter(stp_renderer *r, const stp_vec3 *vertices, int n);

/* shadow.c, at output: gather the records of the polygon whose header is
 * df[at] (sp->count = 0 when it has none); the lights that do not reach
 * device pixel (x, y) of it (bit j: light j); the polygon's shade with
 * only the lights in `lit`. */
void stp_shadow_polygon(const stp_renderer *r, uint32_t at, stp_shadow_poly *sp);
uint32_t stp_shadow_hidden(const stp_renderer *r, const stp_shadow_poly *sp, uint32_t x, uint32_t y);
stp_fix stp_shadow_shade(const stp_shadow_poly *sp, uint32_t lit);
/* 1 when some light has a map set */
int stp_shadow_any(const stp_renderer *r);
#endif

#endif
