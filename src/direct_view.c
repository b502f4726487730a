/* SPDX-License-Identifier: MIT */
/* Direct drawing's camera, model transform and sine (include/stipple/direct.h). */
#include "stipple/direct.h"

#include "direct_view_private.h"
#include "fix_private.h" /* STP_TABLE */
#include "view_private.h" /* stp_view_axes */

#define Q14 14
#define COORD_LIMIT ((int32_t)1 << 23) /* direct.h: coordinates below 2^23 raw */

#if STP_DIRECT_COMPACT
/* v scaled to unit length in Q1.14: the core's one unit vector in the
 * form mesh.c's normals take (fix.c's stp_unit_q14_from64: stp_unit_from64
 * rounded to Q14).  0 for a zero vector (out untouched). */
static int unit14(const int32_t v[3], int16_t out[3])
{
    return stp_unit_q14_from64(v[0], v[1], v[2], out);
}

/* a x b of Q1.14 vectors: Q2.28, each component below 2^29 */
STP_DIRECT_SMALL void cross14(const int16_t a[3], const int16_t b[3], int32_t c[3])
{
    int i, j, k;
    /* c_i = a_j b_k - a_k b_j, (i, j, k) turning cyclically from (0, 1, 2) */
    for (i = 0, j = 1, k = 2; i < 3; i++) {
        c[i] = (int32_t)a[j] * b[k] - (int32_t)a[k] * b[j];
        j = k;
        k = i;
    }
}

/* Q1.14 value v as stp_fix */
#if STP_FIX_FRAC_BITS >= 14
#define Q14_TO_FIX(v) ((int32_t)(v) * ((int32_t)1 << (STP_FIX_FRAC_BITS >= 14 ? STP_FIX_FRAC_BITS - 14 : 0)))
#else
#define Q14_TO_FIX(v) stp_asr32((v), 14 - STP_FIX_FRAC_BITS)
#endif

/* Q1.14 vector a as stp_fix; one call */
#if defined(__GNUC__)
__attribute__((noinline))
#endif
static void q14_axis(const int16_t a[3], stp_vec3 *out)
{
    out->x = Q14_TO_FIX(a[0]);
    out->y = Q14_TO_FIX(a[1]);
    out->z = Q14_TO_FIX(a[2]);
}

/* The compact form's axes (config.h: STP_DIRECT_COMPACT): in Q1.14 by the
 * unit vectors mesh normals take, kept as stp_fix (exact multiples of
 * 2^(F - 14)); 0 when from - at or up is zero or up lies along the line
 * of sight. */
static int look_axes(const int32_t d[3], stp_vec3 up, stp_vec3 axis[3])
{
    int32_t u[3], c[3];
    int16_t a[3][3], upn[3];
    int i;
    u[0] = up.x;
    u[1] = up.y;
    u[2] = up.z;
    if (unit14(d, a[2]) == 0 || unit14(u, upn) == 0)
        return 0;
    /* right = forward x up, as view.c; short: up along the line of sight */
    cross14(a[2], upn, c);
    if (stp_abs32(c[0]) + stp_abs32(c[1]) + stp_abs32(c[2]) < ((uint32_t)1 << 18))
        return 0;
    (void)unit14(c, a[0]);
    cross14(a[0], a[2], c);
    (void)unit14(c, a[1]);
    for (i = 0; i < 3; i++)
        q14_axis(a[i], &axis[i]);
    return 1;
}
#else
/* The renderer's axes (view.c's stp_view_axes: the one place they are
 * formed) */
static int look_axes(const int32_t d[3], stp_vec3 up, stp_vec3 axis[3])
{
    stp_vec3 from = {0, 0, 0}, at;
    at.x = d[0];
    at.y = d[1];
    at.z = d[2];
    return stp_view_axes(from, at, up, &axis[0], &axis[1], &axis[2]) == STP_OK;
}
#endif

int stp_direct_view_look(stp_direct_view *v, stp_vec3 from, stp_vec3 at, stp_vec3 up, stp_fix focal,
                         stp_fix hither, uint16_t width, uint16_t height)
{
    int32_t d[3];
    int i;
    if (v == 0 || width < 1 || width > 512 || height < 1 || height > 512 || focal <= 0 || hither <= 0)
        return STP_ERR_ARG;
    d[0] = at.x - from.x;
    d[1] = at.y - from.y;
    d[2] = at.z - from.z;
    for (i = 0; i < 3; i++)
        if (d[i] >= COORD_LIMIT || d[i] <= -COORD_LIMIT)
            return STP_ERR_VIEW;
    if (!look_axes(d, up, v->axis))
        return STP_ERR_VIEW;
    v->from = from;
    v->focal = focal;
    v->hither = hither;
    v->width = width;
    v->height = height;
    return STP_OK;
}

/* sin(pi i / 128) in Q1.14, i = 0..64 */
static const uint16_t quarter_sine[65] STP_TABLE = {
    0,     402,   804,   1205,  1606,  2006,  2404,  2801,  3196,  3590,  3981,  4370,  4756,
    5139,  5520,  5897,  6270,  6639,  7005,  7366,  7723,  8076,  8423,  8765,  9102,  9434,
    9760,  10080, 10394, 10702, 11003, 11297, 11585, 11866, 12140, 12406, 12665, 12916, 13160,
    13395, 13623, 13842, 14053, 14256, 14449, 14635, 14811, 14978, 15137, 15286, 15426, 15557,
    15679, 15791, 15893, 15986, 16069, 16143, 16207, 16261, 16305, 16340, 16364, 16379, 16384,
};

int16_t stp_direct_sin(uint16_t angle)
{
    unsigned r = angle & 0x3FFFu, i, f, a, b;
    if (angle & 0x4000u)
        r = 0x4000u - r; /* sin(pi - x) */
    i = r >> 8;
    f = r & 0xFFu;
    a = STP_TABLE_U16(&quarter_sine[i]);
    b = i < 64u ? STP_TABLE_U16(&quarter_sine[i + 1u]) : a;
    /* the table rises: b - a in [0, 402], times f below 2^17 */
    a += (unsigned)(((uint32_t)(b - a) * f + 128u) >> 8);
    return (int16_t)(angle & 0x8000u ? -(int)a : (int)a);
}

/* a b in Q1.14, rounded, for |a|, |b| <= 2^14: a 16 x 16-bit product */
STP_DIRECT_CALL int16_t mul14(int_fast16_t a, int_fast16_t b)
{
    return (int16_t)stp_asr32((int32_t)a * (int32_t)b + ((int32_t)1 << (Q14 - 1)), Q14);
}

void stp_direct_model_turn(stp_direct_model *m, uint16_t yaw, uint16_t pitch, stp_fix scale,
                           stp_vec3 translate)
{
    int_fast16_t sy = stp_direct_sin(yaw), cy = stp_direct_sin((uint16_t)(yaw + 0x4000u));
    int_fast16_t sx = stp_direct_sin(pitch), cx = stp_direct_sin((uint16_t)(pitch + 0x4000u));
    if (m == 0)
        return;
    /* Rx(pitch) Ry(yaw) */
    m->rot[0][0] = (int16_t)cy;
    m->rot[0][1] = 0;
    m->rot[0][2] = (int16_t)sy;
    m->rot[1][0] = mul14(sx, sy);
    m->rot[1][1] = (int16_t)cx;
    m->rot[1][2] = mul14(-sx, cy);
    m->rot[2][0] = mul14(-cx, sy);
    m->rot[2][1] = (int16_t)sx;
    m->rot[2][2] = mul14(cx, cy);
    m->scale = scale;
    m->translate = translate;
}

void stp_direct_model_transform(const stp_direct_model *m, stp_transform *out)
{
    int i, j;
    if (m == 0 || out == 0)
        return;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) {
            /* |rot| <= 2^14, 0 < scale < 2^(F + 1) */
#if STP_FIX_FRAC_BITS <= 16
            out->m[i][j] = stp_asr32((int32_t)m->rot[i][j] * m->scale, Q14); /* below 2^31 */
#else
            out->m[i][j] = (stp_fix)stp_asr64((int64_t)m->rot[i][j] * m->scale, Q14);
#endif
        }
    out->t = m->translate;
}

int stp_direct_mesh_normals(const stp_mesh *mesh, int16_t *normals)
{
    return stp_mesh_prepare_normals(mesh, normals, 0); /* the one normals function */
}
