/* SPDX-License-Identifier: MIT */
/* The view frame (see view_private.h). */
#include "view_private.h"
#include "fix_private.h"
#include "recip_private.h" /* STP_WIDE_ARITH */
#include "project_private.h"
#include "div64_private.h" /* STP_DIV64 */

#define F STP_FIX_FRAC_BITS
#define ONE STP_FIX_ONE

stp_vec3 stp_vec3_cross(stp_vec3 a, stp_vec3 b)
{
    stp_vec3 c;
    c.x = stp_fix_sat64(stp_asr64((int64_t)a.y * b.z - (int64_t)a.z * b.y, F));
    c.y = stp_fix_sat64(stp_asr64((int64_t)a.z * b.x - (int64_t)a.x * b.z, F));
    c.z = stp_fix_sat64(stp_asr64((int64_t)a.x * b.y - (int64_t)a.y * b.x, F));
    return c;
}

/* out's axes (right, up, forward) the rows of c (9 entries, row-major) */
static void set_axes(stp_view_transform *out, const int32_t *c)
{
    out->right.x = c[0];
    out->right.y = c[1];
    out->right.z = c[2];
    out->up.x = c[3];
    out->up.y = c[4];
    out->up.z = c[5];
    out->forward.x = c[6];
    out->forward.y = c[7];
    out->forward.z = c[8];
}

#if STP_DIRECT_COMPACT
/* ---- the compact form's axes (config.h: STP_DIRECT_COMPACT) ----
 * Unit vectors in Q1.14 by the one unit-vector function mesh normals take
 * (fix.c's stp_unit_q14_from64), cross products of Q1.14 vectors in
 * Q2.28 (each component below 2^29), and the axes kept as stp_fix: exact
 * multiples of 2^(F - 14), so the geometry stage's Q1.14 form of them
 * (stp_view_axes_q14) is exact. */

/* v scaled to unit length in Q1.14; 0 for a zero vector (out untouched) */
static int unit14(int32_t x, int32_t y, int32_t z, int16_t out[3])
{
    return stp_unit_q14_from64(x, y, z, out);
}

/* a x b of Q1.14 vectors in Q2.28 */
static void cross14(const int16_t a[3], const int16_t b[3], int32_t c[3])
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
#if F >= 14
#define Q14_TO_FIX(v) ((int32_t)(v) * ((int32_t)1 << (F >= 14 ? F - 14 : 0)))
#else
#define Q14_TO_FIX(v) stp_asr32((v), 14 - F)
#endif

/* Q1.14 vector a as stp_fix */
static void q14_axis(const int16_t a[3], stp_vec3 *out)
{
    out->x = Q14_TO_FIX(a[0]);
    out->y = Q14_TO_FIX(a[1]);
    out->z = Q14_TO_FIX(a[2]);
}

int stp_view_axes(const stp_vec3 *line, const stp_vec3 *up, stp_vec3 axes[3])
{
    int32_t c[3];
    int16_t a[3][3], upn[3];
    int i;
    if (unit14(line->x, line->y, line->z, a[2]) == 0 || unit14(up->x, up->y, up->z, upn) == 0)
        return STP_ERR_VIEW;
    /* right = forward x up; short (below 2^-10 in Q2.28's 1-norm): up
     * along the line of sight */
    cross14(a[2], upn, c);
    if (stp_abs32(c[0]) + stp_abs32(c[1]) + stp_abs32(c[2]) < ((uint32_t)1 << 18))
        return STP_ERR_VIEW;
    (void)unit14(c[0], c[1], c[2], a[0]);
    cross14(a[0], a[2], c);
    (void)unit14(c[0], c[1], c[2], a[1]);
    for (i = 0; i < 3; i++)
        q14_axis(a[i], &axes[i]);
    return STP_OK;
}
#else
int stp_view_axes(const stp_vec3 *line, const stp_vec3 *up, stp_vec3 axes[3])
{
    stp_vec3 dir, right, upv, upn;
    if (stp_vec3_unity(*line, &dir) == 0)
        return STP_ERR_VIEW;
    if (stp_vec3_unity(*up, &upn) == 0)
        return STP_ERR_VIEW;
    /* right = dir x up; a short cross product means up is (nearly) along
     * the line of sight: no roll can be derived */
    right = stp_vec3_cross(dir, upn);
    if (stp_vec3_unity(right, &right) < (ONE >> 10))
        return STP_ERR_VIEW;
    upv = stp_vec3_cross(right, dir);
    (void)stp_vec3_unity(upv, &upv);
    axes[0] = right;
    axes[1] = upv;
    axes[2] = dir;
    return STP_OK;
}
#endif

int stp_view_frame_make(const stp_view *v, uint32_t width, uint32_t height, stp_view_frame *out)
{
    stp_vec3 line, axes[3];
    stp_fix focal;
    uint32_t short_side;
    line.x = stp_fix_sub(v->at.x, v->from.x);
    line.y = stp_fix_sub(v->at.y, v->from.y);
    line.z = stp_fix_sub(v->at.z, v->from.z);
    if (stp_view_axes(&line, &v->up, axes) != STP_OK)
        return STP_ERR_VIEW;
    if (v->hither <= 0)
        return STP_ERR_VIEW;
    short_side = width < height ? width : height;
    if (v->projection == STP_PERSPECTIVE) {
        /* focal = (short/2) / tan(fov/2), in pixels, F fractional bits */
        stp_fix half = v->fov_degrees / 2, s, c;
        if (v->fov_degrees <= 0 || v->fov_degrees >= 180 * ONE)
            return STP_ERR_VIEW;
        s = stp_fix_sin_deg(half);
        c = stp_fix_cos_deg(half);
        if (s <= 0)
            return STP_ERR_VIEW;
        focal = stp_fix_sat64(((int64_t)short_side * c * (ONE / 2)) / s);
    } else if (v->projection == STP_PARALLEL) {
        if (v->window_half <= 0)
            return STP_ERR_VIEW;
        focal = stp_fix_sat64(((int64_t)short_side * ONE * (ONE / 2)) / v->window_half);
    } else {
        return STP_ERR_ARG;
    }
    out->from = v->from;
    out->right = axes[0];
    out->up = axes[1];
    out->forward = axes[2];
    out->focal = focal;
    out->hither = v->hither;
    out->projection = v->projection;
    return STP_OK;
}

#if STP_NARROW_FORMS && F == 16
/* Whether axis a (|a_i| < 2^17) is short enough for the short form
 * (view_private.h's unit): a^2 <= 5 2^30, tested in 32 bits on b_i =
 * floor(|a_i| / 4) + 1 > |a_i| / 4 (each at most 2^15, its square at most
 * 2^30, the sum below 2^32): sum b_i^2 <= 5 2^26 implies it. */
static int unit_axis(const int32_t a[3])
{
    uint32_t sum = 0;
    int i;
    for (i = 0; i < 3; i++) {
        uint32_t b = (stp_abs32(a[i]) >> 2) + 1u;
        if (b > ((uint32_t)1 << 15))
            return 0; /* |a_i| >= 2^17 */
        sum += b * b;
    }
    return sum <= ((uint32_t)5 << 26);
}
#endif

/* The 32-bit form's halves (view_private.h's stp_view_axis32), and
 * whether every |from_high| is below 2^28 (view.c's
 * stp_view_transform_point then sums in 32 bits). */
static void split_from(stp_view_transform *out)
{
    const int64_t *d[3];
    const stp_vec3 *axis[3];
    int k;
    d[0] = &out->from_right;
    d[1] = &out->from_up;
    d[2] = &out->from_forward;
    axis[0] = &out->right;
    axis[1] = &out->up;
    axis[2] = &out->forward;
    out->narrow = 1;
    out->unit = 1;
    for (k = 0; k < 3; k++) {
        stp_view_axis32 *h = &out->axis32[k];
        int64_t high = stp_asr64(*d[k], 16);
        int32_t a[3];
        int i;
        h->from_low = (int32_t)(*d[k] - high * 65536);
        h->from_high32 = 0;
        if (high >= ((int64_t)1 << 28) || high <= -((int64_t)1 << 28))
            out->narrow = 0;
        else
            h->from_high32 = (int32_t)high;
#if STP_NARROW_FORMS
        out->unit_high[k] = h->from_high32 + 0x8000;
        out->unit_low[k] = ((uint32_t)h->from_high32 << 16) + (uint32_t)h->from_low;
#endif
        a[0] = axis[k]->x;
        a[1] = axis[k]->y;
        a[2] = axis[k]->z;
#if STP_NARROW_FORMS && F == 16
        if (!unit_axis(a))
            out->unit = 0;
#else
        out->unit = 0; /* no short form (builds for size: less code) */
#endif
        for (i = 0; i < 3; i++) {
            int32_t low = (int32_t)(((uint32_t)a[i] & 0x7FFFu) ^ 0x4000u) - 0x4000;
            h->low[i] = (stp_view_half)low;
            h->high[i] = (stp_view_half)((a[i] - low) / 32768); /* exact */
        }
    }
    out->unit &= out->narrow;
}

static int64_t dot64(stp_vec3 a, stp_vec3 b)
{
    return (int64_t)a.x * b.x + (int64_t)a.y * b.y + (int64_t)a.z * b.z;
}

void stp_view_transform_of_axes(stp_vec3 right, stp_vec3 up, stp_vec3 forward, stp_vec3 from,
                                stp_view_transform *out)
{
    out->right = right;
    out->up = up;
    out->forward = forward;
    out->from_right = dot64(from, right);
    out->from_up = dot64(from, up);
    out->from_forward = dot64(from, forward);
    split_from(out);
}

void stp_view_transform_make(const stp_view_frame *vf, stp_view_transform *out)
{
    stp_view_transform_of_axes(vf->right, vf->up, vf->forward, vf->from, out);
}

/* ---- the geometry stage (view_private.h) ---- */

/* model's matrix m (the identity for NULL) and whether it is a similarity
 * (stp_view_similar).  Tested on m cut to 14 significant bits (mq = m /
 * 2^shift): products below 2^28, sums of three below 2^30, all in 32
 * bits. */
static int similarity(const stp_transform *model, int32_t m[3][3], int32_t mq[3][3])
{
    int32_t len[3], dot[3], cross[3], tol, det;
    uint32_t big = 0;
    int i, j, shift;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) {
            m[i][j] = model ? model->m[i][j] : (i == j ? ONE : 0);
            big |= stp_abs32(m[i][j]);
        }
    if (big < ((uint32_t)1 << (F - 6)) || big >= ((uint32_t)1 << 24))
        return 0; /* scale below 2^-6 or 256 and more */
    shift = stp_bit_length32(big) - 14;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++)
            mq[i][j] = shift > 0 ? stp_asr32(m[i][j], shift) : m[i][j] * ((int32_t)1 << -shift);
    for (j = 0; j < 3; j++)
        len[j] = mq[0][j] * mq[0][j] + mq[1][j] * mq[1][j] + mq[2][j] * mq[2][j];
    dot[0] = mq[0][0] * mq[0][1] + mq[1][0] * mq[1][1] + mq[2][0] * mq[2][1];
    dot[1] = mq[0][0] * mq[0][2] + mq[1][0] * mq[1][2] + mq[2][0] * mq[2][2];
    dot[2] = mq[0][1] * mq[0][2] + mq[1][1] * mq[1][2] + mq[2][1] * mq[2][2];
    tol = len[0] >> 10;
    for (j = 0; j < 3; j++) {
        int32_t d = len[j] - len[0];
        if (d > tol || -d > tol || dot[j] > tol || -dot[j] > tol)
            return 0;
    }
    /* c1 x c2 (below 2^29) cut to 15 bits, dotted with c0 (below 2^14) */
    cross[0] = stp_asr32(mq[1][1] * mq[2][2] - mq[2][1] * mq[1][2], 14);
    cross[1] = stp_asr32(mq[2][1] * mq[0][2] - mq[0][1] * mq[2][2], 14);
    cross[2] = stp_asr32(mq[0][1] * mq[1][2] - mq[1][1] * mq[0][2], 14);
    det = mq[0][0] * cross[0] + mq[1][0] * cross[1] + mq[2][0] * cross[2];
    return det > 0;
}

int stp_view_point_two_steps(const stp_transform *model, const stp_view_transform *to_view, stp_vec3 p,
                             stp_vec3 *out)
{
    p = stp_transform_point(model, p);
    stp_view_transform_point(to_view, p, out);
    return stp_view_saturated(p);
}

int stp_view_similar(const stp_transform *model)
{
    int32_t m[3][3], mq[3][3];
    return similarity(model, m, mq);
}

#if STP_DIRECT_COMPACT
/* a (|a| < 2^(F + 1)) in Q1.14, floor(a 2^(14 - F)) (exact for the
 * compact look-at's axes, multiples of 2^(F - 14): stp_view_axes) */
static int16_t to_q14(stp_fix a)
{
#if F >= 14
    return (int16_t)stp_asr32(a, F >= 14 ? F - 14 : 0);
#else
    return (int16_t)(a * ((int32_t)1 << (F >= 14 ? 0 : 14 - F)));
#endif
}

#if defined(__GNUC__)
__attribute__((noinline)) /* one copy for its callers (LTO inlined it in each) */
#endif
void stp_view_axes_q14(const stp_vec3 axes[3], int16_t out[3][3])
{
    int i;
    for (i = 0; i < 3; i++) {
        out[i][0] = to_q14(axes[i].x);
        out[i][1] = to_q14(axes[i].y);
        out[i][2] = to_q14(axes[i].z);
    }
}

#if defined(__GNUC__) && STP_LEAN_CODE
__attribute__((noinline)) /* one copy for its callers on AVR (LTO inlined it in each) */
#endif
int32_t stp_view_dot_q14(const int16_t a[3], const int16_t b[3])
{
    int32_t s = (int32_t)1 << 13;
    int k;
    for (k = 0; k < 3; k++)
        s += (int32_t)a[k] * b[k];
    return stp_asr32(s, 14);
}

int stp_view_compose_q14(const int16_t *a, const int16_t *m, int16_t q[3][3])
{
    uint32_t out = 0; /* some entry outside [-32767, 32767]: bit 16 set */
    int16_t column[3];
    int i, j;
    for (j = 0; j < 3; j++) {
        for (i = 0; i < 3; i++)
            column[i] = m[3 * i + j];
        for (i = 0; i < 3; i++) {
            /* below 2^14 (1 + 2^-14) |m_j| < 2^15 + 2 (|a_i| = 1) */
            int32_t v = stp_view_dot_q14(a + 3 * i, column);
            out |= (uint32_t)(v + 32767) + 1u; /* in range: 1 .. 65535 */
            q[i][j] = (int16_t)v;
        }
    }
    return (out >> 16) == 0;
}
#endif

#if STP_COMPACT_COMPOSE
/* Whether the compact composition applies to model seen along axes: every
 * axis component a multiple of 2^(F - 14) (the compact look-at's) and
 * every entry of m below 2 in magnitude (Q1.14). */
static int compact_fits(const stp_vec3 *const axis[3], const stp_transform *model)
{
    int i, j;
    for (i = 0; i < 3; i++) {
        if (((axis[i]->x | axis[i]->y | axis[i]->z) & (((int32_t)1 << (F - 14)) - 1)) != 0)
            return 0;
        for (j = 0; j < 3; j++)
            if (stp_abs32(model->m[i][j]) >= ((uint32_t)2 << F))
                return 0;
    }
    return 1;
}

/* The compact composition (config.h: STP_DIRECT_COMPACT) of model with the
 * view transform t's axes: C = Q 2^(F - 14), Q = stp_view_compose_q14's,
 * and each eye term rounded to a multiple of 2^F (*e: V_i . (from - t)
 * in units of 2^-2F, to 2^F ceil(e / 2^F)), so a point's view coordinate
 * floor((C p - e) / 2^F) is floor(Q p / 2^14) + floor(V_i . (t - from)
 * / 2^F): direct drawing's compact form, term for term.  0 (c and e
 * untouched) where it does not apply (compact_fits). */
static int compose_compact(const stp_vec3 *const axis[3], const stp_transform *model, int32_t c[3][3],
                           int64_t e[3])
{
    stp_vec3 axes[3];
    int16_t a[3][3], mq[3][3], q[3][3];
    int i, j;
    if (!compact_fits(axis, model))
        return 0;
    for (i = 0; i < 3; i++) {
        axes[i] = *axis[i];
        for (j = 0; j < 3; j++)
            mq[i][j] = to_q14(model->m[i][j]); /* below 2^15 (compact_fits) */
    }
    stp_view_axes_q14(axes, a); /* exact (compact_fits) */
    if (!stp_view_compose_q14(&a[0][0], &mq[0][0], q))
        return 0;
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++)
            c[i][j] = (int32_t)q[i][j] * ((int32_t)1 << (F - 14));
        e[i] = -stp_asr64(-e[i], F) * ((int64_t)1 << F);
    }
    return 1;
}
#endif

#if STP_COMPACT_COMPOSE
/* *out (the exact composition of model with the view of axes axis) as
 * the compact form composes it (compose_compact), where that applies */
static void compose_compact_view(const stp_vec3 *const axis[3], const stp_transform *model, stp_view_transform *out)
{
    int32_t c[3][3];
    int64_t e[3];
    e[0] = out->from_right;
    e[1] = out->from_up;
    e[2] = out->from_forward;
    if (!compose_compact(axis, model, c, e))
        return;
    set_axes(out, &c[0][0]);
    out->from_right = e[0];
    out->from_up = e[1];
    out->from_forward = e[2];
}

/* The model frame's rotation in the compact form (stp_model_frame_make):
 * for a model that is a rotation alone (its squared scale within 2^-10 of
 * 1; NULL: the identity) whose composition is the compact one
 * (compose_compact), rot = 2 Q in Q15, so stp_render_view_normal's
 * rounding, floor((2 S + 2^14) / 2^15) = floor((S + 2^13) / 2^14), is
 * direct drawing's turn of a normal by C = Q (stp_view_dot_q14); else rot
 * as it is (the exact frame's). */
static void compact_rotation(const stp_vec3 *const axis[3], const stp_transform *model, stp_model_frame *f)
{
    stp_transform identity;
    int32_t c[3][3];
    int64_t e[3] = {0, 0, 0};
    const int64_t one = (int64_t)1 << (2 * F), tolerance = one >> 10;
    int i, j;
    if (f->scale2 - one > tolerance || one - f->scale2 > tolerance)
        return; /* scaled: the exact frame */
    if (model == 0) {
        stp_transform_identity(&identity);
        model = &identity;
    }
    if (!compose_compact(axis, model, c, e))
        return;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++)
            f->rot[i][j] = 2 * stp_asr32(c[i][j], F - 14); /* exact: c = Q 2^(F - 14) */
}
#endif

int stp_view_transform_compose(const stp_view_transform *t, const stp_transform *model,
                               stp_view_transform *out)
{
    int32_t m[3][3], mq[3][3], c[3][3];
    const stp_vec3 *axis[3];
    int i, j;
    if (!similarity(model, m, mq))
        return 0;
    axis[0] = &t->right;
    axis[1] = &t->up;
    axis[2] = &t->forward;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) {
            /* |axis| < 2^17, |m| < 2^24 (similarity): below 3 2^41 */
            int64_t s = (int64_t)axis[i]->x * m[0][j] + (int64_t)axis[i]->y * m[1][j] +
                        (int64_t)axis[i]->z * m[2][j];
            s = stp_asr64(s + ((int64_t)1 << (F - 1)), F);
            if (s >= ((int64_t)1 << 17) || s <= -((int64_t)1 << 17))
                return 0;
            c[i][j] = (int32_t)s;
        }
    set_axes(out, &c[0][0]);
    /* V_i . (from - t) = from . V_i - t . V_i, exact */
    out->from_right = t->from_right - dot64(model->t, t->right);
    out->from_up = t->from_up - dot64(model->t, t->up);
    out->from_forward = t->from_forward - dot64(model->t, t->forward);
#if STP_COMPACT_COMPOSE
    compose_compact_view(axis, model, out);
#endif
    split_from(out);
    return 1;
}

/* ---- the geometry stage for points near the eye (view_private.h) ---- */

/* t's eye terms in the 32-bit form's shape (stp_view_small_point) */
static void small_eye_terms(stp_view_small *t)
{
    int i;
    for (i = 0; i < 3; i++) {
        t->high_biased[i] = t->high[i] + 0x8000;
        t->from_mod[i] = ((uint32_t)t->high[i] << 16) + t->low[i];
    }
}

void stp_view_small_of_axes(const stp_vec3 axes[3], int32_t high, uint32_t low, stp_view_small *out)
{
    int i;
    for (i = 0; i < 3; i++) {
        /* member by member: with one struct copy here, GCC 12 for
         * ARMv6-M at -Os took stp_view_small_point's loads of the axes as
         * not reading it and dropped this function's calls */
        out->axis[i].x = axes[i].x;
        out->axis[i].y = axes[i].y;
        out->axis[i].z = axes[i].z;
#if !(STP_WIDE_ARITH || F != 16) /* the 32-bit form's */
        out->axis_high[i][0] = (int16_t)stp_asr32(axes[i].x, 5);
        out->axis_high[i][1] = (int16_t)stp_asr32(axes[i].y, 5);
        out->axis_high[i][2] = (int16_t)stp_asr32(axes[i].z, 5);
#endif
        out->high[i] = high;
        out->low[i] = low;
    }
    small_eye_terms(out);
}

#if STP_WIDE_ARITH || F != 16
void stp_view_small_point(const stp_view_small *t, const stp_vec3 *p, stp_vec3 *out)
{
    int32_t v[3];
    int i;
    for (i = 0; i < 3; i++) {
        const stp_vec3 *a = &t->axis[i];
        /* each product below 2^40 (2^43 at F = 20), the eye term below 2^46 */
        int64_t s = (int64_t)a->x * p->x + (int64_t)a->y * p->y + (int64_t)a->z * p->z -
                    ((int64_t)t->high[i] * ((int64_t)1 << F) + (int64_t)t->low[i]);
        v[i] = (int32_t)stp_asr64(s, F);
    }
    out->x = v[0];
    out->y = v[1];
    out->z = v[2];
}
#else
/* With S = a . p - from, from = high 2^16 + low: a_i = 2^5 ah_i + al_i
 * and p_i = 2^11 ph_i + pl_i (floor splits, al_i in [0, 32), pl_i in
 * [0, 2048), |ah_i|, |ph_i| <= 2^12), so H = sum ah_i ph_i (16 x 16-bit
 * products, |H| <= 3 2^24) leaves a . p - 2^16 H = sum (2^5 ah_i pl_i +
 * 2^11 al_i ph_i + al_i pl_i), each term below 2^28 + 2^28 + 2^16 in
 * magnitude: below 1.51 2^30 in all, 1.51 2^14 in units of 2^16.  So
 * floor(S / 2^16) lies in [e, e + 2^16) for e = H - high - 2^15
 * (high_biased: high + 2^15, once a frame), and its low 16 bits are bits
 * 16..31 of S mod 2^32 (the wrapped sum of the products less from mod
 * 2^32, from_mod): e plus their difference from e's taken
 * mod 2^16, exactly (the form of the renderer's short form, unit_coordinate,
 * for these ranges: |a_i| < 2^17, |p_i| < 2^23). */
void stp_view_small_point(const stp_view_small *t, const stp_vec3 *p, stp_vec3 *out)
{
    int32_t v[3];
    int i;
    STP_UNROLL3
    for (i = 0; i < 3; i++) {
        const stp_vec3 *a = &t->axis[i];
        const int16_t *ah = t->axis_high[i];
        int32_t e = (int32_t)ah[0] * stp_asr32(p->x, 11) + (int32_t)ah[1] * stp_asr32(p->y, 11) +
                    (int32_t)ah[2] * stp_asr32(p->z, 11) - t->high_biased[i];
        uint32_t s = (uint32_t)a->x * (uint32_t)p->x + (uint32_t)a->y * (uint32_t)p->y +
                     (uint32_t)a->z * (uint32_t)p->z - t->from_mod[i];
        v[i] = e + (int32_t)(((s >> 16) - (uint32_t)e) & 0xFFFFu);
    }
    out->x = v[0];
    out->y = v[1];
    out->z = v[2];
}
#endif

/* Every value below is a view coordinate by stp_view_small_point (each
 * point below 2^23, each axis below 2^17):
 *   C_ij = floor((V_i . M_j + 2^(F-1)) / 2^F), the view of column M_j of
 *   m with the eye terms -2^(F-1) (high -1, low 2^(F-1)): compose_rows'
 *   rounding (stp_view_transform_compose);
 *   V_i . d = 2^F floor(V_i . d / 2^F) + (V_i . d mod 2^F): the view of d
 *   with the eye terms 0, and the low part from the products' sum mod
 *   2^32. */
int stp_view_compose_small(const stp_vec3 axes[3], const int32_t d[3], const stp_transform *model,
                           stp_view_small *out)
{
    stp_view_small v;
    stp_vec3 p, c[3], rows[3];
    int i;
    stp_view_small_of_axes(axes, -1, (uint32_t)1 << (F - 1), &v);
    for (i = 0; i < 3; i++) {
        p.x = model->m[0][i];
        p.y = model->m[1][i];
        p.z = model->m[2][i];
        stp_view_small_point(&v, &p, &c[i]); /* column i of C */
        if (stp_abs32(c[i].x) >= ((uint32_t)1 << 17) || stp_abs32(c[i].y) >= ((uint32_t)1 << 17) ||
            stp_abs32(c[i].z) >= ((uint32_t)1 << 17))
            return 0;
    }
    stp_view_small_of_axes(axes, 0, 0, &v);
    p.x = d[0];
    p.y = d[1];
    p.z = d[2];
    stp_view_small_point(&v, &p, &p); /* floor(V_i . d / 2^F) */
    /* C's rows (right, up, forward) from its columns */
    for (i = 0; i < 3; i++) {
        rows[i].x = stp_vec3_comp(&c[0], i);
        rows[i].y = stp_vec3_comp(&c[1], i);
        rows[i].z = stp_vec3_comp(&c[2], i);
    }
    stp_view_small_of_axes(rows, 0, 0, out);
    out->high[0] = p.x;
    out->high[1] = p.y;
    out->high[2] = p.z;
    for (i = 0; i < 3; i++)
        out->low[i] = ((uint32_t)d[0] * (uint32_t)axes[i].x + (uint32_t)d[1] * (uint32_t)axes[i].y +
                       (uint32_t)d[2] * (uint32_t)axes[i].z) &
                      (((uint32_t)1 << F) - 1u);
    small_eye_terms(out);
    return 1;
}

int stp_model_frame_make(const stp_view_transform *t, stp_vec3 from, const stp_transform *model,
                         stp_model_frame *f)
{
    int32_t m[3][3], mq[3][3];
    int64_t d[3];
    const stp_vec3 *axis[3];
    int i, j;
    f->usable = 0;
    if (!similarity(model, m, mq))
        return 0;
    f->scale2 = (int64_t)m[0][0] * m[0][0] + (int64_t)m[1][0] * m[1][0] + (int64_t)m[2][0] * m[2][0];
    axis[0] = &t->right;
    axis[1] = &t->up;
    axis[2] = &t->forward;
    /* rows of V M (V: the view axes as rows, Q15 here), normalised: each
     * product below 2^15 2^14, the sums below 2^31 (|V_i| = 1,
     * |mq column| < 2^14 sqrt 3) */
    for (i = 0; i < 3; i++) {
        int32_t row[3];
        int32_t ax = stp_asr32(axis[i]->x, 1), ay = stp_asr32(axis[i]->y, 1), az = stp_asr32(axis[i]->z, 1);
        stp_unit3 u;
        for (j = 0; j < 3; j++)
            row[j] = ax * mq[0][j] + ay * mq[1][j] + az * mq[2][j];
        if (stp_unit_from64(row[0], row[1], row[2], &u) == 0)
            return 0;
        /* Q30 to Q15, rounded */
        f->rot[i][0] = (int32_t)stp_asr64((int64_t)u.x + ((int64_t)1 << 14), 15);
        f->rot[i][1] = (int32_t)stp_asr64((int64_t)u.y + ((int64_t)1 << 14), 15);
        f->rot[i][2] = (int32_t)stp_asr64((int64_t)u.z + ((int64_t)1 << 14), 15);
    }
#if STP_COMPACT_COMPOSE
    compact_rotation(axis, model, f);
#endif
    /* eye in model coordinates: M^-1 (from - t) = M^T (from - t) / s^2 */
    d[0] = (int64_t)from.x - (model ? model->t.x : 0);
    d[1] = (int64_t)from.y - (model ? model->t.y : 0);
    d[2] = (int64_t)from.z - (model ? model->t.z : 0);
    for (j = 0; j < 3; j++) {
        int64_t sum = m[0][j] * d[0] + m[1][j] * d[1] + m[2][j] * d[2], e;
        if (sum >= ((int64_t)1 << 46) || sum <= -((int64_t)1 << 46))
            return 0;
        e = STP_DIV64(sum * ONE, f->scale2); /* |sum| < 2^46: the product fits */
        if (e >= ((int64_t)1 << 30) || e <= -((int64_t)1 << 30))
            return 0;
        f->eye[j] = (int32_t)e;
    }
    f->usable = 1;
    return 1;
}

#if STP_WIDE_ARITH
void stp_view_transform_point(const stp_view_transform *t, stp_vec3 p, stp_vec3 *out)
{
    stp_view_transform_point_wide(t, p, out); /* view_private.h */
}

void stp_view_transform_point_at(const stp_view_transform *t, const stp_vec3 *p, stp_vec3 *out)
{
    stp_view_transform_point_wide(t, *p, out);
}
#else
/* floor(v / 2^16) (>> of a negative value is the implementation's: the
 * arithmetic shift on every compiler the project builds with, where the
 * test folds away) */
static int32_t high16(int32_t v)
{
    if ((int32_t)-1 >> 1 == (int32_t)-1)
        return v >> 16;
    return v >= 0 ? v >> 16 : (int32_t)~(~(uint32_t)v >> 16);
}

/* A point split in signed 16-bit halves: v = h 2^16 + l, l in [-2^15,
 * 2^15), h in [-2^15, 2^15]. */
typedef struct point_halves {
    int32_t h[3], l[3];
} point_halves;

/* The exact floor((p . a - from) / 2^F) saturated from floor(S / 2^16)
 * as axis_coordinate's sums give it, for any F and point (the narrow case
 * at F = 16 is axis_coordinate's): sum h a_i = 2^15 sum h high + sum h low,
 * below 1.5 2^18 and 1.5 2^30, from . a (*from) in 64 bits.  F > 16 shifts
 * further (a floor of a floor); F < 16 appends the top 16 - F bits of
 * S mod 2^16 = r mod 2^16.  (Till this was written for any F, the 32-bit
 * form divided by 2^16 at every precision: at F = 12 every view
 * coordinate came out 16 times too small, the light's included.) */
static stp_fix finish_coordinate(const point_halves *p, const stp_vec3 *a, const stp_view_axis32 *x,
                                 const int64_t *from, int narrow, int32_t small, int32_t r)
{
    int64_t v;
    (void)r; /* F < 16 only */
    if (narrow)
        v = p->h[0] * a->x + p->h[1] * a->y + p->h[2] * a->z - x->from_high32 + small;
    else
        v = (int64_t)(p->h[0] * x->high[0] + p->h[1] * x->high[1] + p->h[2] * x->high[2]) * 32768 +
            (int64_t)(p->h[0] * x->low[0] + p->h[1] * x->low[1] + p->h[2] * x->low[2]) +
            ((int64_t)small - stp_asr64(*from, 16));
#if F > 16
    v = stp_asr64(v, F > 16 ? F - 16 : 0);
#elif F < 16
    /* |v| < 2^35 (|S| < 2^51): times 2^(16 - F) well inside 64 bits */
    v = v * ((int64_t)1 << (F < 16 ? 16 - F : 0)) + (int64_t)(((uint32_t)r & 0xFFFFu) >> (F < 16 ? F : 0));
#endif
    return stp_fix_sat64(v);
}

/* floor((p . a - from) / 2^F) saturated, the same value as the 64-bit
 * formula's, for axis a (|a_i| < 2^17) with halves *x and from . a
 * (*from), from 32-bit products (ARMv6-M has no 32 x 32 -> 64 multiply;
 * the library's costs ~40 instructions a call).  With p_i = h 2^16 + l
 * and a_i = high 2^15 + low (stp_view_axis32),
 *   p_i a_i = 2^16 h a_i + 2^15 l high + l low,
 * so with g = sum l high (|g| <= 1.5 2^17) and r = sum l low - from_low +
 * 2^15 (g mod 2), |r| < 1.5 2^30 + 2^16,
 *   S = p . a - from = 2^16 (sum h a_i - from_high + floor(g / 2)) + r,
 *   floor(S / 2^16) = sum h a_i - from_high + floor(g / 2) + floor(r / 2^16).
 * narrow (every |h| <= 2^12 and the transform's |from_high| < 2^28):
 * |sum h a_i| < 1.5 2^30, and every partial sum stays below 2^31 - 1 in
 * magnitude, so at F = 16 the value is exact in 32 bits and never
 * saturates; else finish_coordinate. */
STP_HOT_INLINE stp_fix axis_coordinate(const point_halves *p, const stp_vec3 *a, const stp_view_axis32 *x,
                                       const int64_t *from, int narrow)
{
    int32_t g = p->l[0] * x->high[0] + p->l[1] * x->high[1] + p->l[2] * x->high[2];
    int32_t r = p->l[0] * x->low[0] + p->l[1] * x->low[1] + p->l[2] * x->low[2] - x->from_low +
                (int32_t)(((uint32_t)g & 1u) << 15);
    int32_t small = stp_asr32(g, 1) + high16(r);
#if F == 16
    if (narrow)
        return p->h[0] * a->x + p->h[1] * a->y + p->h[2] * a->z - x->from_high32 + small;
#endif
    return finish_coordinate(p, a, x, from, narrow, small, r);
}

#if STP_NARROW_FORMS && F == 16
/* The short form of axis_coordinate for a unit transform (view_private.h:
 * |a| <= sqrt(5 / 4) 2^16) and every p_i in [-2^28, 2^28): with p_i = h_i
 * 2^14 + l_i (h_i in [-2^14, 2^14), l_i in [0, 2^14)), H = sum h_i a_i and
 * L = sum l_i a_i are each below sqrt(3) 2^14 sqrt(5 / 4) 2^16 < 0.97
 * 2^31 in magnitude (Cauchy-Schwarz), and with S = p . a - from,
 *   S / 2^16 - (floor(H / 4) - from_high)
 *     = (H mod 4) / 4 + (L - from_low) / 2^16,
 * in (-0.97 2^15 - 1, 0.97 2^15 + 1): floor(S / 2^16) is in [0, 2^16)
 * above the estimate e = floor(H / 4) - from_high - 2^15 (unit_estimate),
 * and its low 16 bits are those of (S mod 2^32) / 2^16, S mod 2^32 the
 * wrapped sum of p_i a_i less from's low word (unit_coordinate): e plus
 * their difference from e's taken mod 2^16.  Six products, the same
 * value, in two passes over the axes that each hold few values (ARMv6-M:
 * eight registers for products). */
STP_HOT_INLINE int32_t unit_estimate(const int32_t h[3], const stp_vec3 *a, int32_t unit_high)
{
    return stp_asr32(h[0] * a->x + h[1] * a->y + h[2] * a->z, 2) - unit_high;
}

STP_HOT_INLINE stp_fix unit_coordinate(const stp_vec3 *p, const stp_vec3 *a, uint32_t unit_low, int32_t e)
{
    uint32_t s = (uint32_t)p->x * (uint32_t)a->x + (uint32_t)p->y * (uint32_t)a->y +
                 (uint32_t)p->z * (uint32_t)a->z - unit_low;
    return e + (int32_t)(((s >> 16) - (uint32_t)e) & 0xFFFFu);
}
#endif

/* v's signed halves (point_halves) */
static void split_point(int32_t v, int32_t *h, int32_t *l)
{
    *l = (int32_t)(((uint32_t)v & 0xFFFFu) ^ 0x8000u) - 0x8000;
    *h = high16(v) + (int32_t)(((uint32_t)v >> 15) & 1u);
}

void stp_view_transform_point(const stp_view_transform *t, stp_vec3 p, stp_vec3 *out)
{
    stp_view_transform_point_at(t, &p, out);
}

void stp_view_transform_point_at(const stp_view_transform *t, const stp_vec3 *pp, stp_vec3 *out)
{
    stp_vec3 p = *pp;
    point_halves ph;
    int narrow;
    /* every p_i in [-2^28, 2^28) */
    int small = (((uint32_t)p.x + 0x10000000u) | ((uint32_t)p.y + 0x10000000u) | ((uint32_t)p.z + 0x10000000u)) <
                0x20000000u;
#if STP_NARROW_FORMS && F == 16
    if (!STP_UNLIKELY(!t->unit || !small)) { /* laid out as the hot path */
        /* unit_coordinate's estimates (the high parts' products), then
         * its low words (the point's) */
        int32_t h[3];
        h[0] = stp_asr32(p.x, 14);
        h[1] = stp_asr32(p.y, 14);
        h[2] = stp_asr32(p.z, 14);
        out->x = unit_estimate(h, &t->right, t->unit_high[0]);
        out->y = unit_estimate(h, &t->up, t->unit_high[1]);
        out->z = unit_estimate(h, &t->forward, t->unit_high[2]);
        out->x = unit_coordinate(&p, &t->right, t->unit_low[0], out->x);
        out->y = unit_coordinate(&p, &t->up, t->unit_low[1], out->y);
        out->z = unit_coordinate(&p, &t->forward, t->unit_low[2], out->z);
        return;
    }
#endif
    split_point(p.x, &ph.h[0], &ph.l[0]);
    split_point(p.y, &ph.h[1], &ph.l[1]);
    split_point(p.z, &ph.h[2], &ph.l[2]);
    narrow = t->narrow && small; /* |h| <= 2^12 */
    out->x = axis_coordinate(&ph, &t->right, &t->axis32[0], &t->from_right, narrow);
    out->y = axis_coordinate(&ph, &t->up, &t->axis32[1], &t->from_up, narrow);
    out->z = axis_coordinate(&ph, &t->forward, &t->axis32[2], &t->from_forward, narrow);
}
#endif

/* Ranges: each difference of vertices below 2^ld (raw), the eye's below
 * 2^le: the cross product's components are below 2^(2 ld + 1) and the
 * triple product below 3 2^(2 ld + le + 1), so 2 ld + le <= 60 keeps it
 * below 2^63.  With ld, le <= 29 each view coordinate is below
 * sqrt(3) 2^30 < 2^31 - 1: none saturates. */
int stp_view_triangle_side(stp_vec3 from, stp_vec3 forward, int parallel, const stp_vec3 *v)
{
    int64_t x1 = (int64_t)v[1].x - v[0].x, y1 = (int64_t)v[1].y - v[0].y,
            z1 = (int64_t)v[1].z - v[0].z;
    int64_t x2 = (int64_t)v[2].x - v[0].x, y2 = (int64_t)v[2].y - v[0].y,
            z2 = (int64_t)v[2].z - v[0].z;
    int64_t ex = (int64_t)from.x - v[0].x, ey = (int64_t)from.y - v[0].y,
            ez = (int64_t)from.z - v[0].z;
    uint64_t spread = (uint64_t)(x1 < 0 ? -x1 : x1) | (uint64_t)(y1 < 0 ? -y1 : y1) |
                      (uint64_t)(z1 < 0 ? -z1 : z1) | (uint64_t)(x2 < 0 ? -x2 : x2) |
                      (uint64_t)(y2 < 0 ? -y2 : y2) | (uint64_t)(z2 < 0 ? -z2 : z2);
    uint64_t reach = (uint64_t)(ex < 0 ? -ex : ex) | (uint64_t)(ey < 0 ? -ey : ey) |
                     (uint64_t)(ez < 0 ? -ez : ez);
    int ld, le;
    int64_t cx, cy, cz, side;
    if ((spread | reach) >= ((uint64_t)1 << 29))
        return 0;
    ld = stp_bit_length64(spread);
    le = stp_bit_length64(reach);
    if (parallel) {
        ex = -(int64_t)forward.x; /* a unit stp_vec3: below 2^17 */
        ey = -(int64_t)forward.y;
        ez = -(int64_t)forward.z;
        le = F + 1;
    }
    if (2 * ld + le > 60)
        return 0;
    cx = y1 * z2 - z1 * y2;
    cy = z1 * x2 - x1 * z2;
    cz = x1 * y2 - y1 * x2;
    if (cx == 0 && cy == 0 && cz == 0)
        return 0; /* degenerate: the full path reports it */
    side = cx * ex + cy * ey + cz * ez;
    return side > 0 ? 1 : -1;
}

/* ---- the perspective projection (project_private.h) ---- */

/* project_private.h: the 64-bit quotients, by one reciprocal of z for the
 * three (z < 2^31) where 64-bit division is a library call, else C's
 * operator (the header's inline form, here for files built otherwise). */
void stp_view_perspective_wide(stp_fix focal, stp_fix hither, const stp_vec3 *pp, int64_t *x, int64_t *y,
                               int32_t *key)
{
#if STP_WIDE_ARITH
    stp_project_wide(focal, hither, pp, x, y, key);
#else
    stp_vec3 p = *pp;
    int64_t z = p.z < hither ? hither : p.z; /* > 0 */
    stp_recip_divisor dz;
    stp_recip_divisor_init(&dz, (uint32_t)z);
    *x = stp_asr64(stp_div64_by(&dz, (int64_t)focal * p.x), F - STP_SUBPIXEL_BITS);
    *y = stp_asr64(stp_div64_by(&dz, (int64_t)focal * p.y), F - STP_SUBPIXEL_BITS);
    if (key)
        *key = (int32_t)stp_div64_by(&dz, ((int64_t)hither) << 30);
#endif
}

#if !STP_WIDE_ARITH
void stp_view_perspective_device_wide(const stp_view_lens *lens, const stp_vec3 *p, int32_t out[3])
{
    stp_project_device_wide(lens, p, out);
}
#endif
