/* SPDX-License-Identifier: MIT */
/* Colour models: see include/stipple/colour.h. */
#include "stipple/colour.h"
#include "fix_private.h"

#define F STP_FIX_FRAC_BITS
#define ONE STP_FIX_ONE

/* A constant given with 30 fractional bits, in stp_fix. */
#define Q30(v) ((stp_fix)stp_asr64((int64_t)(v) + ((int64_t)1 << (29 - F)), 30 - F))

static stp_fix min3(stp_fix a, stp_fix b, stp_fix c)
{
    stp_fix m = a < b ? a : b;
    return m < c ? m : c;
}

static stp_fix max3(stp_fix a, stp_fix b, stp_fix c)
{
    stp_fix m = a > b ? a : b;
    return m > c ? m : c;
}

static stp_vec3 v3(stp_fix x, stp_fix y, stp_fix z)
{
    stp_vec3 v;
    v.x = x;
    v.y = y;
    v.z = z;
    return v;
}

static stp_rgb rgb3(stp_fix r, stp_fix g, stp_fix b)
{
    stp_rgb c;
    c.r = r;
    c.g = g;
    c.b = b;
    return c;
}

stp_vec3 stp_mat3_apply(const stp_mat3 *m, stp_vec3 in)
{
    stp_vec3 out;
    int64_t s[3];
    int j;
    for (j = 0; j < 3; j++)
        s[j] = (int64_t)in.x * m->m[0][j] + (int64_t)in.y * m->m[1][j] + (int64_t)in.z * m->m[2][j];
    out.x = stp_fix_sat64(stp_asr64(s[0] + ((int64_t)1 << (F - 1)), F));
    out.y = stp_fix_sat64(stp_asr64(s[1] + ((int64_t)1 << (F - 1)), F));
    out.z = stp_fix_sat64(stp_asr64(s[2] + ((int64_t)1 << (F - 1)), F));
    return out;
}

int stp_mat3_inverse(const stp_mat3 *m, stp_mat3 *out)
{
    /* cofactors have 2F fractional bits; the determinant 3F, kept in 2F */
    int64_t cof[3][3], det;
    int i, j;
    const stp_fix(*a)[3] = m->m;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) {
            int r1 = (i + 1) % 3, r2 = (i + 2) % 3, c1 = (j + 1) % 3, c2 = (j + 2) % 3;
            cof[i][j] = (int64_t)a[r1][c1] * a[r2][c2] - (int64_t)a[r1][c2] * a[r2][c1];
        }
    det = stp_asr64(cof[0][0], F) * a[0][0] + stp_asr64(cof[0][1], F) * a[0][1] +
          stp_asr64(cof[0][2], F) * a[0][2]; /* 2F fractional bits */
    if (det == 0 || (det < 0 ? -det : det) < ((int64_t)1 << (F / 2)))
        return -1;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) {
            /* inverse[i][j] = cofactor[j][i] / det; scale the numerator by 2^F
             * after dropping F/2 bits of each so nothing overflows */
            int64_t num = stp_asr64(cof[j][i], F / 2) * ((int64_t)1 << F);
            out->m[i][j] = stp_fix_sat64(num / stp_asr64(det, F / 2));
        }
    return 0;
}

stp_vec3 stp_rgb_to_cmy(stp_rgb c)
{
    return v3(ONE - c.r, ONE - c.g, ONE - c.b);
}

stp_rgb stp_cmy_to_rgb(stp_vec3 cmy)
{
    return rgb3(ONE - cmy.x, ONE - cmy.y, ONE - cmy.z);
}

stp_vec3 stp_rgb_to_cmyk(stp_rgb c, stp_fix *k_out)
{
    stp_vec3 cmy = stp_rgb_to_cmy(c);
    stp_fix k = min3(cmy.x, cmy.y, cmy.z);
    *k_out = k;
    return v3(cmy.x - k, cmy.y - k, cmy.z - k);
}

stp_rgb stp_cmyk_to_rgb(stp_vec3 cmy, stp_fix k)
{
    return stp_cmy_to_rgb(v3(stp_fix_add(cmy.x, k), stp_fix_add(cmy.y, k), stp_fix_add(cmy.z, k)));
}

/* (10.38) row by row as the seed prints it (R, G, B rows; columns I, Q,
 * Y): a grey gives I and Q within 0.025 of zero (docs/model.md section 6). */
static const int32_t yiq_q30[3][3] = {
    {644245094, 225485783, 322122547},   /* R:  0.60  0.21 0.30 */
    {-300647710, -558345748, 633507676}, /* G: -0.28 -0.52 0.59 */
    {-322122547, 343597384, 118111601}}; /* B: -0.30  0.32 0.11 */

static void yiq_matrix(stp_mat3 *m)
{
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++)
            m->m[i][j] = Q30(yiq_q30[i][j]);
}

stp_vec3 stp_rgb_to_iqy(stp_rgb c)
{
    stp_mat3 m;
    yiq_matrix(&m);
    return stp_mat3_apply(&m, v3(c.r, c.g, c.b));
}

stp_rgb stp_iqy_to_rgb(stp_vec3 iqy)
{
    stp_mat3 m, inv;
    stp_vec3 v;
    yiq_matrix(&m);
    (void)stp_mat3_inverse(&m, &inv); /* the seed's matrix is regular */
    v = stp_mat3_apply(&inv, iqy);
    return rgb3(v.x, v.y, v.z);
}

stp_fix stp_rgb_luminance(stp_rgb c)
{
    return stp_rgb_to_iqy(c).z;
}

/* Hue of the hexcone (Algorithm 10.13) from V = max and X = min, degrees. */
static stp_fix hexcone_hue(stp_rgb c, stp_fix v, stp_fix x)
{
    stp_fix d = v - x, r, g, b, h;
    if (d <= 0)
        return 0; /* grey: no hue */
    r = stp_fix_div(v - c.r, d);
    g = stp_fix_div(v - c.g, d);
    b = stp_fix_div(v - c.b, d);
    if (c.r == v)
        h = c.g == x ? 5 * ONE + b : ONE - g;
    else if (c.g == v)
        h = c.b == x ? ONE + r : 3 * ONE - b;
    else
        h = c.r == x ? 3 * ONE + g : 5 * ONE - r;
    h = stp_fix_sat64((int64_t)h * 60);
    return h >= 360 * ONE ? h - 360 * ONE : h;
}

stp_vec3 stp_rgb_to_hsv(stp_rgb c)
{
    stp_fix v = max3(c.r, c.g, c.b), x = min3(c.r, c.g, c.b);
    stp_fix s = v > 0 ? stp_fix_div(v - x, v) : 0;
    return v3(hexcone_hue(c, v, x), s, v);
}

stp_rgb stp_hsv_to_rgb(stp_vec3 hsv)
{
    stp_fix h = hsv.x, s = hsv.y, v = hsv.z, f, p, q, t;
    int sector;
    int64_t h6;
    if (s <= 0)
        return rgb3(v, v, v);
    h6 = ((int64_t)h % (360 * (int64_t)ONE) + 360 * (int64_t)ONE) % (360 * (int64_t)ONE) / 60;
    sector = (int)(h6 >> F);
    f = (stp_fix)(h6 - ((int64_t)sector << F));
    p = stp_fix_mul(v, ONE - s);
    q = stp_fix_mul(v, ONE - stp_fix_mul(s, f));
    t = stp_fix_mul(v, ONE - stp_fix_mul(s, ONE - f));
    switch (sector) {
    case 0: return rgb3(v, t, p);
    case 1: return rgb3(q, v, p);
    case 2: return rgb3(p, v, t);
    case 3: return rgb3(p, q, v);
    case 4: return rgb3(t, p, v);
    default: return rgb3(v, p, q);
    }
}

stp_vec3 stp_rgb_to_hls(stp_rgb c)
{
    stp_fix v = max3(c.r, c.g, c.b), x = min3(c.r, c.g, c.b);
    stp_fix l = (stp_fix)(((int64_t)v + x) / 2), s = 0;
    if (v > x) {
        if (l <= ONE / 2)
            s = stp_fix_div(v - x, v + x);
        else
            s = stp_fix_div(v - x, 2 * ONE - v - x);
    }
    return v3(hexcone_hue(c, v, x), l, s);
}

/* One component of the double hexcone's inverse. */
static stp_fix hls_value(stp_fix n1, stp_fix n2, stp_fix hue)
{
    int64_t h = ((int64_t)hue % (360 * (int64_t)ONE) + 360 * (int64_t)ONE) % (360 * (int64_t)ONE);
    if (h < 60 * (int64_t)ONE)
        return stp_fix_sat64(n1 + (((int64_t)n2 - n1) * h) / (60 * (int64_t)ONE));
    if (h < 180 * (int64_t)ONE)
        return n2;
    if (h < 240 * (int64_t)ONE)
        return stp_fix_sat64(n1 + (((int64_t)n2 - n1) * (240 * (int64_t)ONE - h)) / (60 * (int64_t)ONE));
    return n1;
}

stp_rgb stp_hls_to_rgb(stp_vec3 hls)
{
    stp_fix h = hls.x, l = hls.y, s = hls.z, m1, m2;
    if (s <= 0)
        return rgb3(l, l, l);
    m2 = l <= ONE / 2 ? stp_fix_mul(l, ONE + s) : stp_fix_sub(stp_fix_add(l, s), stp_fix_mul(l, s));
    m1 = stp_fix_sub(2 * l, m2);
    /* the hexcone's red is at 0 degrees: R takes hue + 120, B hue - 120 */
    return rgb3(hls_value(m1, m2, h + 120 * ONE), hls_value(m1, m2, h), hls_value(m1, m2, h - 120 * ONE));
}

stp_fix stp_fix_atan2_deg(stp_fix y, stp_fix x)
{
    /* odd polynomial for atan(t), t in [0, 1], degrees with 24 fractional
     * bits (least-squares fit, error 3e-4 degrees); octants by symmetry */
    static const int64_t c[6] = {961244490, -319806646, 186501456, -113128533, 51978937, -11819608};
    int64_t ax = x < 0 ? -(int64_t)x : x, ay = y < 0 ? -(int64_t)y : y, t, t2, p, a;
    int swap = ay > ax, k;
    if (ax == 0 && ay == 0)
        return 0;
    t = swap ? (ax << 30) / ay : (ay << 30) / ax; /* Q30 in [0, 1] */
    t2 = (t * t) >> 30;
    p = c[5];
    for (k = 4; k >= 0; k--)
        p = c[k] + stp_asr64(p * t2, 30);
    a = stp_asr64(p * t, 30); /* Q24 degrees in [0, 45] */
    if (swap)
        a = ((int64_t)90 << 24) - a;
    if (x < 0)
        a = ((int64_t)180 << 24) - a;
    if (y < 0)
        a = ((int64_t)360 << 24) - a;
    if (a >= ((int64_t)360 << 24))
        a -= (int64_t)360 << 24;
    return (stp_fix)stp_asr64(a + ((int64_t)1 << (23 - F)), 24 - F);
}

/* (10.39) with 1/sqrt(6), 1/sqrt(2), 1/sqrt(3) in Q30 */
#define INV_SQRT6 438353892
#define INV_SQRT2 759250125
#define INV_SQRT3 619925131

stp_vec3 stp_rgb_to_hsi(stp_rgb c)
{
    int64_t m1 = (2 * (int64_t)c.r - c.g - c.b) * INV_SQRT6;
    int64_t m2 = ((int64_t)c.g - c.b) * INV_SQRT2;
    stp_fix m1f = stp_fix_sat64(stp_asr64(m1, 30)), m2f = stp_fix_sat64(stp_asr64(m2, 30));
    stp_fix h = stp_fix_atan2_deg(m1f, m2f);
    stp_fix s = stp_fix_sqrt_wide((int64_t)m1f * m1f + (int64_t)m2f * m2f);
    /* I = I1 sqrt(3) = R + G + B */
    return v3(h, s, stp_fix_add(stp_fix_add(c.r, c.g), c.b));
}

stp_rgb stp_hsi_to_rgb(stp_vec3 hsi)
{
    stp_fix m1 = stp_fix_mul(hsi.y, stp_fix_sin_deg(hsi.x));
    stp_fix m2 = stp_fix_mul(hsi.y, stp_fix_cos_deg(hsi.x));
    int64_t i1 = stp_asr64((int64_t)hsi.z * INV_SQRT3, 30); /* I / sqrt(3), F bits */
    /* (10.42) */
    int64_t r = 2 * (int64_t)m1 * INV_SQRT6 + i1 * INV_SQRT3;
    int64_t g = -(int64_t)m1 * INV_SQRT6 + (int64_t)m2 * INV_SQRT2 + i1 * INV_SQRT3;
    int64_t b = -(int64_t)m1 * INV_SQRT6 - (int64_t)m2 * INV_SQRT2 + i1 * INV_SQRT3;
    return rgb3(stp_fix_sat64(stp_asr64(r + ((int64_t)1 << 29), 30)), stp_fix_sat64(stp_asr64(g + ((int64_t)1 << 29), 30)),
                stp_fix_sat64(stp_asr64(b + ((int64_t)1 << 29), 30)));
}

int stp_colour_rgb_to_xyz_matrix_xyz(const stp_xy primaries[3], stp_vec3 white_xyz,
                                     stp_mat3 *to_xyz, stp_vec3 *weights_out)
{
    stp_mat3 chroma, inv;
    stp_vec3 w;
    int i, j;
    for (i = 0; i < 3; i++) {
        if (primaries[i].y <= 0)
            return -1;
        chroma.m[i][0] = primaries[i].x;
        chroma.m[i][1] = primaries[i].y;
        chroma.m[i][2] = ONE - primaries[i].x - primaries[i].y;
    }
    if (stp_mat3_inverse(&chroma, &inv) != 0)
        return -1;
    /* weights: [w_r w_g w_b] * chroma = white */
    w = stp_mat3_apply(&inv, white_xyz);
    for (j = 0; j < 3; j++) {
        to_xyz->m[0][j] = stp_fix_mul(chroma.m[0][j], w.x);
        to_xyz->m[1][j] = stp_fix_mul(chroma.m[1][j], w.y);
        to_xyz->m[2][j] = stp_fix_mul(chroma.m[2][j], w.z);
    }
    if (weights_out)
        *weights_out = w;
    return 0;
}

int stp_colour_rgb_to_xyz_matrix(const stp_xy primaries[3], stp_xy white, stp_mat3 *to_xyz,
                                 stp_vec3 *weights_out)
{
    stp_vec3 white_xyz;
    if (white.y <= 0)
        return -1;
    /* Y = 1: X = x/y, Z = z/y (10.27) */
    white_xyz.x = stp_fix_div(white.x, white.y);
    white_xyz.y = ONE;
    white_xyz.z = stp_fix_div(ONE - white.x - white.y, white.y);
    return stp_colour_rgb_to_xyz_matrix_xyz(primaries, white_xyz, to_xyz, weights_out);
}

void stp_colour_table_grey(stp_colour_table *t)
{
    uint32_t i;
    for (i = 0; i < 256; i++)
        t->entry[i] = (i << 16) | (i << 8) | i;
}

static uint32_t byte_of(stp_fix v)
{
    int64_t b = ((int64_t)stp_fix_clamp(v, 0, ONE) * 255 + (ONE / 2)) >> F;
    return (uint32_t)b;
}

void stp_colour_table_pseudocolour(stp_colour_table *t)
{
    int i;
    for (i = 0; i < 256; i++) {
        stp_rgb c = stp_hsv_to_rgb(v3(stp_fix_from_ratio((int32_t)240 * (255 - i), 255), ONE, ONE));
        t->entry[i] = (byte_of(c.r) << 16) | (byte_of(c.g) << 8) | byte_of(c.b);
    }
}

void stp_colour_table_apply_gamma(stp_colour_table *t, const uint8_t *gamma_r,
                                  const uint8_t *gamma_g, const uint8_t *gamma_b)
{
    int i;
    for (i = 0; i < 256; i++) {
        uint32_t e = t->entry[i];
        t->entry[i] = ((uint32_t)gamma_r[(e >> 16) & 0xFF] << 16) |
                      ((uint32_t)gamma_g[(e >> 8) & 0xFF] << 8) | gamma_b[e & 0xFF];
    }
}
