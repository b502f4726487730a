/* SPDX-License-Identifier: MIT */
/* MAKE-SHADE, INTENSITY and gamma tables: see include/stipple/shade.h. */
#include "stipple/shade.h"
#include "fix_private.h"

#define F STP_FIX_FRAC_BITS
#define ONE STP_FIX_ONE

void stp_lighting_default(stp_lighting *lighting)
{
    int i;
    lighting->brightness = ONE;
    lighting->background = 0;
    lighting->attenuation_c = ONE;
    lighting->count = 1;
    for (i = 0; i < STP_MAX_LIGHTS; i++) {
        lighting->lights[i].position.x = 0;
        lighting->lights[i].position.y = 0;
        lighting->lights[i].position.z = ONE;
        lighting->lights[i].power = ONE;
        lighting->lights[i].colour[0] = lighting->lights[i].colour[1] =
            lighting->lights[i].colour[2] = ONE;
    }
}

void stp_material_default(stp_material *material)
{
    material->reflectivity = ONE;
    material->refraction = 10 * ONE;
    material->gloss = 10 * ONE;
    material->specular = ONE;
    material->colour[0] = material->colour[1] = material->colour[2] = ONE;
}

#if STP_WITH_SPECULAR || STP_WITH_RAYTRACE
/* Fresnel factor (10.6)-(10.8) in the listing's order of operations.
 * c = E.H in (0, 1], n > 0.  Result clamped to [0, 1]. */
static stp_fix fresnel(stp_fix c, stp_fix n)
{
    /* g^2 = n^2 + c^2 - 1 with 2F fractional bits: n < 2^(31-F) so
     * n^2 < 2^62 and the sum fits */
    int64_t g2 = (int64_t)n * n + (int64_t)c * c - ((int64_t)1 << (2 * F));
    int64_t g, gmc, gpc, r, r2, num, den, t, t2, fr;
    if (g2 <= 0)
        return ONE; /* n < 1 and beyond the critical angle: total reflection */
    g = stp_fix_sqrt_wide(g2);
    gmc = g - c;
    gpc = g + c; /* > 0: g >= 0 and c > 0 */
    r = (gmc * ONE) / gpc; /* |r| <= 1 */
    r2 = (r * r) >> F;
    num = ((c * gpc) >> F) - ONE;
    den = stp_asr64(c * gmc, F) + ONE;
    if (den <= 0)
        return ONE; /* t -> infinity: the bracket, and F, saturate */
    t = stp_fix_sat64((num * ONE) / den);
    t2 = (t * t) >> F; /* < 2^62 >> F */
    /* r2 <= 2^F and ONE + t2 < 2^47: the product fits */
    fr = (r2 * (ONE + t2)) >> (F + 1);
    return fr > ONE ? ONE : (stp_fix)fr;
}

stp_fix stp_fresnel(stp_fix c, stp_fix n)
{
    if (c <= 0)
        return ONE;
    return fresnel(c > ONE ? ONE : c, n <= 0 ? 1 : n);
}
#endif

stp_specular_terms stp_specular(stp_fix n_dot_h, stp_fix n_dot_e, stp_fix n_dot_l,
                                stp_fix e_dot_h, stp_fix refraction, stp_fix gloss)
{
    stp_specular_terms out = {0, 0, 0};
#if STP_WITH_SPECULAR
    stp_fix k = gloss < 1 ? 1 : gloss;
    stp_fix q;
    int64_t gnum, m;
    if (n_dot_h <= 0 || n_dot_e <= 0 || n_dot_l <= 0 || e_dot_h <= 0)
        return out;
    if (n_dot_h > ONE)
        n_dot_h = ONE;
    /* D = (k / (k + 1 - N.H))^2: the denominator is >= k > 0 */
    q = stp_fix_div(k, stp_fix_add(k, ONE - n_dot_h));
    out.d = stp_fix_mul(q, q);
    /* G = 2 min(N.E, N.L) (N.H) / (E.H), capped at 1 */
    m = n_dot_e < n_dot_l ? n_dot_e : n_dot_l;
    gnum = 2 * m * (int64_t)n_dot_h; /* 2F fractional bits, < 2^(2F+1) */
    out.g = gnum / e_dot_h >= ONE ? ONE : (stp_fix)(gnum / e_dot_h);
    out.f = fresnel(e_dot_h > ONE ? ONE : e_dot_h, refraction <= 0 ? 1 : refraction);
#else
    (void)n_dot_h;
    (void)n_dot_e;
    (void)n_dot_l;
    (void)e_dot_h;
    (void)refraction;
    (void)gloss;
#endif
    return out;
}

#if STP_WITH_SPECULAR
/* D F G/(N.E), with G/(N.E) formed directly: G = min(1, 2 (N.H) min(N.E,
 * N.L)/(E.H)), so G/(N.E) = min(1/(N.E), 2 (N.H) (min(N.E, N.L)/(N.E))/(E.H)).
 * Forming the tiny G of a grazing eye first and dividing it by the tiny N.E
 * afterwards would keep only the few bits G has left.  N.E, N.L > 0 here;
 * the quotient is capped at STP_FIX_MAX (the shade saturates long before). */
static stp_fix specular_share(stp_specular_terms s, stp_fix n_dot_h, stp_fix n_dot_e,
                              stp_fix n_dot_l, stp_fix e_dot_h)
{
    int64_t m = n_dot_l < n_dot_e ? n_dot_l : n_dot_e, q, g_ne, cap, df;
    if (n_dot_h <= 0 || e_dot_h <= 0 || n_dot_e <= 0)
        return 0;
    if (n_dot_h > ONE)
        n_dot_h = ONE;
    q = (2 * m * n_dot_h) / n_dot_e;           /* 2 (N.H) min/(N.E) <= 2 ONE */
    g_ne = (q * ONE) / e_dot_h;                /* < 2^(2F+2) */
    cap = ((int64_t)ONE * ONE) / n_dot_e;      /* G capped at 1 */
    if (cap < g_ne)
        g_ne = cap;
    if (g_ne > STP_FIX_MAX)
        g_ne = STP_FIX_MAX;
    df = ((int64_t)s.d * s.f + STP_FIX_HALF) >> F; /* D, F in [0, 1] */
    return stp_fix_sat64((df * g_ne + STP_FIX_HALF) >> F);
}
#endif


/* MAKE-SHADE with its parts: when terms is not NULL, *ambient_out gets B*R
 * and terms[j] each light's saturated term (0 for a light that does not
 * reach the face), for stp_shade_point_terms; stp_shade_point passes NULL. */
static inline stp_fix shade_parts(const stp_lighting *lighting, const stp_material *material,
                                  stp_vec3 normal, stp_vec3 point, stp_vec3 eye, int parallel,
                                  stp_vec3 parallel_dir, stp_fix *ambient_out, stp_fix *terms)
{
    stp_vec3 e;
    stp_fix n_dot_e, background, refl, c, ambient;
    int64_t sum = 0; /* F fractional bits; each term is saturated to stp_fix
                        and there are at most STP_MAX_LIGHTS of them */
    int j, count;

    background = stp_fix_clamp(lighting->background, 0, ONE);
    refl = material->reflectivity;
    c = lighting->attenuation_c > 0 ? lighting->attenuation_c : 1;
    ambient = stp_fix_mul(background, refl);

    if (parallel)
        e = parallel_dir;
    else
        (void)stp_unity_diff(eye, point, &e);
    n_dot_e = stp_vec3_dot(normal, e);

    count = lighting->count < 0 ? 0 : (lighting->count > STP_MAX_LIGHTS ? STP_MAX_LIGHTS : lighting->count);
    if (n_dot_e <= 0)
        count = 0; /* a back face (or the eye on the point): ambient share only */
    if (terms) {
        *ambient_out = ambient;
        for (j = 0; j < STP_MAX_LIGHTS; j++)
            terms[j] = 0;
    }
    for (j = 0; j < count; j++) {
        const stp_light *light = &lighting->lights[j];
        stp_vec3 l;
        stp_fix n_dot_l, term;
        int64_t u = stp_unity_diff(light->position, point, &l);
        if (u == 0)
            l = normal; /* light on the surface: lit head-on, 1/(C + 0) */
        n_dot_l = stp_vec3_dot(normal, l);
        if (n_dot_l <= 0)
            continue;
        term = stp_fix_mul(refl, n_dot_l);
#if STP_WITH_SPECULAR
        if (material->specular != 0 && n_dot_e > 0) {
            stp_vec3 h, le;
            le.x = stp_fix_add(l.x, e.x);
            le.y = stp_fix_add(l.y, e.y);
            le.z = stp_fix_add(l.z, e.z);
            if (stp_vec3_unity(le, &h) != 0) { /* L + E = 0: H undefined, no highlight */
                stp_fix n_dot_h = stp_vec3_dot(normal, h), e_dot_h = stp_vec3_dot(e, h);
                stp_specular_terms s = stp_specular(n_dot_h, n_dot_e, n_dot_l, e_dot_h,
                                                    material->refraction, material->gloss);
                /* the share DGF/(E.N) explodes as E.N -> 0: it saturates,
                 * and the min(1, ...) below caps the shade */
                stp_fix share = stp_fix_mul(specular_share(s, n_dot_h, n_dot_e, n_dot_l, e_dot_h),
                                            material->specular);
                term = stp_fix_add(term, share);
            }
        }
#endif
        /* P_j * term / (C + U_j) in one 64-bit step */
        term = stp_fix_sat64(((int64_t)term * light->power) / (c + u));
        if (terms)
            terms[j] = term;
        sum += term;
    }
    sum += ambient;
    sum = stp_fix_sat64(sum);
    sum = stp_fix_mul(lighting->brightness, (stp_fix)sum);
    return stp_fix_clamp((stp_fix)sum, 0, ONE);
}

stp_fix stp_shade_point(const stp_lighting *lighting, const stp_material *material,
                        stp_vec3 normal, stp_vec3 point, stp_vec3 eye, int parallel,
                        stp_vec3 parallel_dir)
{
    return shade_parts(lighting, material, normal, point, eye, parallel, parallel_dir, 0, 0);
}

#if STP_WITH_SHADOWS
stp_fix stp_shade_point_terms(const stp_lighting *lighting, const stp_material *material,
                              stp_vec3 normal, stp_vec3 point, stp_vec3 eye, int parallel,
                              stp_vec3 parallel_dir, stp_fix *ambient, stp_fix terms[STP_MAX_LIGHTS])
{
    return shade_parts(lighting, material, normal, point, eye, parallel, parallel_dir, ambient,
                       terms);
}

stp_fix stp_shade_combine(stp_fix brightness, stp_fix ambient, const stp_fix *terms, int count,
                          uint32_t lit)
{
    /* the order of stp_shade_point: the terms' sum, the ambient part, one
     * saturation, BRIGHT, the cap */
    int64_t sum = 0;
    int j;
    for (j = 0; j < count && j < 32; j++)
        if (lit & ((uint32_t)1 << j))
            sum += terms[j];
    sum += ambient;
    sum = stp_fix_sat64(sum);
    sum = stp_fix_mul(brightness, (stp_fix)sum);
    return stp_fix_clamp((stp_fix)sum, 0, ONE);
}
#endif

void stp_shade_point_colour(const stp_lighting *lighting, const stp_material *material,
                            stp_vec3 normal, stp_vec3 point, stp_vec3 eye, int parallel,
                            stp_vec3 parallel_dir, stp_fix out[3])
{
    /* three passes of the grey equation with the channel's R and P_j: the
     * directions are recomputed each time, which keeps one code path (and
     * one set of tests) for grey and colour */
    stp_lighting lit = *lighting;
    stp_material mat = *material;
    int c, j, count = lighting->count < 0 ? 0 : (lighting->count > STP_MAX_LIGHTS ? STP_MAX_LIGHTS : lighting->count);
    for (c = 0; c < 3; c++) {
        mat.reflectivity = stp_fix_mul(material->reflectivity, material->colour[c]);
        for (j = 0; j < count; j++)
            lit.lights[j].power = stp_fix_mul(lighting->lights[j].power, lighting->lights[j].colour[c]);
        out[c] = stp_shade_point(&lit, &mat, normal, point, eye, parallel, parallel_dir);
    }
}

stp_fix stp_shade_luminance(const stp_fix rgb[3])
{
    /* weights in Q16 summing to exactly 65536 so white stays 1 */
    int64_t y = (int64_t)rgb[0] * 19661 + (int64_t)rgb[1] * 38666 + (int64_t)rgb[2] * 7209;
    return (stp_fix)((y + 32768) >> 16);
}

static int clamp_levels(int levels)
{
    return levels < 2 ? 2 : (levels > 256 ? 256 : levels);
}

int stp_intensity_index(stp_fix shade, int levels)
{
    levels = clamp_levels(levels);
    shade = stp_fix_clamp(shade, 0, ONE);
    /* INT(s*(N-1) + 1): exact, s*(N-1) < 2^(F+8) */
    return (int)(((int64_t)shade * (levels - 1)) >> F) + 1;
}

stp_fix stp_intensity_shade(int index, int levels)
{
    levels = clamp_levels(levels);
    if (index < 1)
        index = 1;
    if (index > levels)
        index = levels;
    /* ceil((index-1) 2^F / (levels-1)): rounding to nearest could land one
     * LSB below the style's lower boundary, and stp_intensity_index would
     * then give index - 1; rounded up it gives index back (levels-1 < 2^F) */
    return (stp_fix)(((int64_t)(index - 1) * ONE + (levels - 2)) / (levels - 1));
}

uint8_t stp_style_lookup(const stp_style_table *table, int index)
{
    if (index < 1)
        index = 1;
    if (index > table->levels)
        index = table->levels;
    return table->codes[index - 1];
}

int stp_style_inverse(const stp_style_table *table, uint8_t code)
{
    int i;
    for (i = 0; i < table->levels; i++)
        if (table->codes[i] == code)
            return i + 1;
    return 0;
}

int stp_gamma_table(uint8_t *out, int levels, stp_fix gamma, stp_fix k)
{
    int i;
    stp_fix inv_gamma;
    if (out == 0 || levels < 2 || levels > 256)
        return -1;
    if (gamma <= 0)
        gamma = ONE;
    if (k <= 0)
        k = ONE;
    inv_gamma = stp_fix_div(ONE, gamma);
    for (i = 0; i < levels; i++) {
        stp_fix x = stp_fix_div(stp_fix_from_ratio(i, levels - 1), k);
        stp_fix v;
        if (x <= 0)
            v = 0;
        else if (x >= ONE)
            v = ONE;
        else
            v = stp_fix_clamp(stp_fix_pow(x, inv_gamma), 0, ONE);
        out[i] = (uint8_t)(((int64_t)v * 255 + STP_FIX_HALF) >> F);
    }
    return 0;
}
