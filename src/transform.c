/* SPDX-License-Identifier: MIT */
/* Model transforms: see include/stipple/transform.h. */
#include "stipple/transform.h"
#include "fix_private.h"

#define F STP_FIX_FRAC_BITS
#define ONE STP_FIX_ONE

void stp_transform_identity(stp_transform *t)
{
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++)
            t->m[i][j] = i == j ? ONE : 0;
    t->t.x = t->t.y = t->t.z = 0;
}

/* Row i of a 3x3 stp_fix matrix times a vector of stp_fix, rounded: each
 * product < 2^62 and their sum is formed halved so it cannot overflow. */
static stp_fix row_dot(const stp_fix row[3], stp_fix x, stp_fix y, stp_fix z)
{
    int64_t s = ((int64_t)row[0] * x) / 2 + ((int64_t)row[1] * y) / 2 + ((int64_t)row[2] * z) / 2;
    return stp_fix_sat64(stp_asr64(s + ((int64_t)1 << (F - 2)), F - 1));
}

/* t <- a t for a 3x3 matrix a: m <- a m, t <- a t. */
static void apply_matrix(stp_transform *t, stp_fix a[3][3])
{
    stp_transform out;
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++)
            out.m[i][j] = row_dot(a[i], t->m[0][j], t->m[1][j], t->m[2][j]);
    out.t.x = row_dot(a[0], t->t.x, t->t.y, t->t.z);
    out.t.y = row_dot(a[1], t->t.x, t->t.y, t->t.z);
    out.t.z = row_dot(a[2], t->t.x, t->t.y, t->t.z);
    *t = out;
}

void stp_transform_rotate(stp_transform *t, int axis, stp_fix degrees)
{
    stp_fix a[3][3], s = stp_fix_sin_deg(degrees), c = stp_fix_cos_deg(degrees);
    int i, j, u, v;
    if (axis < 0 || axis > 2)
        return;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++)
            a[i][j] = i == j ? ONE : 0;
    /* the plane (u, v) turned about `axis`: u towards v */
    u = (axis + 1) % 3;
    v = (axis + 2) % 3;
    a[u][u] = c;
    a[u][v] = -s;
    a[v][u] = s;
    a[v][v] = c;
    apply_matrix(t, a);
}

void stp_transform_scale(stp_transform *t, stp_fix sx, stp_fix sy, stp_fix sz)
{
    stp_fix a[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
    a[0][0] = sx;
    a[1][1] = sy;
    a[2][2] = sz;
    apply_matrix(t, a);
}

void stp_transform_translate(stp_transform *t, stp_vec3 d)
{
    t->t.x = stp_fix_add(t->t.x, d.x);
    t->t.y = stp_fix_add(t->t.y, d.y);
    t->t.z = stp_fix_add(t->t.z, d.z);
}

stp_vec3 stp_transform_direction(const stp_transform *t, stp_vec3 d)
{
    stp_vec3 out;
    out.x = row_dot(t->m[0], d.x, d.y, d.z);
    out.y = row_dot(t->m[1], d.x, d.y, d.z);
    out.z = row_dot(t->m[2], d.x, d.y, d.z);
    return out;
}

stp_vec3 stp_transform_point(const stp_transform *t, stp_vec3 p)
{
    stp_vec3 out = stp_transform_direction(t, p);
    out.x = stp_fix_add(out.x, t->t.x);
    out.y = stp_fix_add(out.y, t->t.y);
    out.z = stp_fix_add(out.z, t->t.z);
    return out;
}
