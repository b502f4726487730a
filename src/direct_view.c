/* SPDX-License-Identifier: MIT */
/* Direct drawing's camera, model transform and sine (include/stipple/direct.h). */
#include "stipple/direct.h"

#include "direct_view_private.h"
#include "fix_private.h" /* STP_TABLE */
#include "view_private.h" /* stp_view_axes */

#define Q14 14
#define COORD_LIMIT ((int32_t)1 << 23) /* direct.h: coordinates below 2^23 raw */

/* Whether |v| < 2^23 (direct.h's range): one unsigned comparison */
static int in_coord_range(int32_t v)
{
    return (uint32_t)v + (uint32_t)(COORD_LIMIT - 1) < 2u * (uint32_t)COORD_LIMIT - 1u;
}

int stp_direct_view_look(stp_direct_view *v, stp_vec3 from, stp_vec3 at, stp_vec3 up, stp_fix focal,
                         stp_fix hither, uint16_t width, uint16_t height)
{
    stp_vec3 d; /* the line of sight */
    if (v == 0 || width < 1 || width > 512 || height < 1 || height > 512 || focal <= 0 || hither <= 0)
        return STP_ERR_ARG;
    d.x = at.x - from.x;
    d.y = at.y - from.y;
    d.z = at.z - from.z;
    if (!in_coord_range(d.x) || !in_coord_range(d.y) || !in_coord_range(d.z))
        return STP_ERR_VIEW;
    /* the renderer's axes (view.c: the one place they are formed) */
    if (stp_view_axes(&d, &up, v->axis) != STP_OK)
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
