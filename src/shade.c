/* SPDX-License-Identifier: MIT */
/* MAKE-SHADE, INTENSITY and gamma tables: see include/stipple/shade.h. */
#include "stipple/shade.h"
#include "fix_private.h"
#include "recip_private.h"
#include "shade_private.h"

#define F STP_FIX_FRAC_BITS
#define ONE STP_FIX_ONE

/* Products of operands known to fit 32 bits (MUL_U32: unsigned, MUL_S32:
 * signed), as int64_t: C's 64-bit product on 64-bit hosts, from 16-bit
 * halves on 32-bit targets (recip_private.h), where C's is a library call
 * for any 64-bit operands. */
#if STP_WIDE_ARITH
#define MUL_U32(a, b) ((int64_t)(a) * (int64_t)(b))
#define MUL_S32(a, b) ((int64_t)(a) * (int64_t)(b))
#else
#define MUL_U32(a, b) ((int64_t)stp_umul32x32((uint32_t)(a), (uint32_t)(b)))
#define MUL_S32(a, b) stp_smul32x32((int32_t)(a), (int32_t)(b))
#endif

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

/* stp_mul_shift_sat (fix_private.h) with its common case, a < 2^31 and
 * b < 2^32, through MUL_U32: the same value */
static inline int64_t mul_shift_sat(int64_t a, int64_t b, int s)
{
#if !STP_WIDE_ARITH
    if (((uint64_t)a >> 31) == 0 && ((uint64_t)b >> 32) == 0)
        return MUL_U32(a, b) >> s;
#endif
    return stp_mul_shift_sat(a, b, s);
}

#if STP_WITH_SPECULAR || STP_WITH_RAYTRACE
/* Fresnel factor (10.6)-(10.8) in the listing's order of operations.
 * c = E.H in (0, 1], n > 0.  Result clamped to [0, 1]. */
static stp_fix fresnel(stp_fix c, stp_fix n)
{
    /* g^2 = n^2 + c^2 - 1 with 2F fractional bits: n < 2^(31-F) so
     * n^2 < 2^62 and the sum fits */
    int64_t g2 = MUL_S32(n, n) + MUL_S32(c, c) - ((int64_t)1 << (2 * F));
    int64_t g, gmc, gpc, r, r2, num, den, t, t2, fr;
    if (g2 <= 0)
        return ONE; /* n < 1 and beyond the critical angle: total reflection */
    g = (int64_t)stp_sqrt64_fast((uint64_t)g2); /* < 2^31: g2 < 2^62 */
    gmc = g - c;
    gpc = g + c; /* > 0: g >= 0 and c > 0 */
    r = stp_div64_fast(gmc * ONE, gpc); /* |r| <= 1 */
    r2 = MUL_S32(r, r) >> F; /* |r| <= 2^F */
    /* c in (0, 2^F], 0 < gpc < 2^31 + 2^F, |gmc| < 2^31 */
    num = (MUL_U32(c, gpc) >> F) - ONE;
    den = stp_asr64(MUL_S32(c, gmc), F) + ONE;
    if (den <= 0)
        return ONE; /* t -> infinity: the bracket, and F, saturate */
    t = stp_fix_sat64(stp_div64_fast(num * ONE, den));
    t2 = MUL_S32(t, t) >> F; /* t is stp_fix: < 2^62 >> F */
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
/* Ks D F G/(N.E) of one light in STP_UNIT (Q30) from the cosines (each in
 * (0, 2^30], STP_UNIT), saturated at 2^45 (32768, beyond any shade).
 *   D = (k/(k + 1 - N.H))^2 = (1 - (1 - N.H)/(k + 1 - N.H))^2: the quotient
 *     (1 - N.H) 2^30 / (k + 1 - N.H) has a numerator below 2^61 for any k;
 *   G/(N.E) = min(1/(N.E), 2 (N.H) (min(N.E, N.L)/(N.E))/(E.H)), formed
 *     directly so a grazing eye keeps its bits (the tiny G is never divided
 *     by the tiny N.E): 2 (N.H) min/(N.E) <= 2^31, shifted by 30 < 2^61;
 *   F from stp_fresnel's arithmetic at E.H rounded to stp_fix. */
static int64_t specular_share_unit(const stp_material *material, int64_t n_dot_h,
                                   int64_t n_dot_e, int64_t n_dot_l, int64_t e_dot_h)
{
    const int64_t one = STP_UNIT_ONE;
    int64_t k = (int64_t)(material->gloss < 1 ? 1 : material->gloss) << (STP_UNIT_BITS - F);
    int64_t m = n_dot_l < n_dot_e ? n_dot_l : n_dot_e, q, d, g_ne, cap, df, ec;
    stp_fix f;
    if (n_dot_h > one)
        n_dot_h = one;
    q = one - stp_div64_fast((one - n_dot_h) << STP_UNIT_BITS, k + one - n_dot_h);
    d = MUL_U32(q, q) >> STP_UNIT_BITS; /* q in [0, 2^30] */
#if STP_WIDE_ARITH
    /* one instruction a quotient: dividing is cheaper than the tests below */
    g_ne = stp_div64_fast(stp_div64_fast(2 * m * n_dot_h, n_dot_e) << STP_UNIT_BITS, e_dot_h);
    cap = stp_div64_fast(one << STP_UNIT_BITS, n_dot_e);
    if (cap < g_ne)
        g_ne = cap;
#else
    /* the same values with fewer quotients: (2 m N.H)/(N.E) is 2 N.H
     * exactly when m = N.E (the eye no higher than the light), and the cap
     * floor(2^60/(N.E)) is below g_ne exactly when g_ne N.E > 2^60 (g_ne
     * an integer; below 2^32 the product fits) */
    g_ne = m == n_dot_e ? 2 * n_dot_h
                        : stp_div64_fast(MUL_U32(2 * m, n_dot_h), n_dot_e);
    g_ne = stp_div64_fast(g_ne << STP_UNIT_BITS, e_dot_h);
    if (g_ne >= ((int64_t)1 << 32) ||
        MUL_U32(g_ne, n_dot_e) > (one << STP_UNIT_BITS)) {
        cap = stp_div64_fast(one << STP_UNIT_BITS, n_dot_e);
        if (cap < g_ne)
            g_ne = cap;
    }
#endif
    ec = (e_dot_h + ((int64_t)1 << (STP_UNIT_BITS - F - 1))) >> (STP_UNIT_BITS - F);
    f = fresnel(ec < 1 ? 1 : (ec > ONE ? ONE : (stp_fix)ec),
                material->refraction <= 0 ? 1 : material->refraction);
    df = MUL_U32(d, f) >> F; /* D, F in [0, 1]: STP_UNIT */
    df = mul_shift_sat(df, g_ne, STP_UNIT_BITS);
    df = mul_shift_sat(df, material->specular < 0 ? 0 : material->specular, F);
    return df > ((int64_t)1 << 45) ? (int64_t)1 << 45 : df;
}
#endif

/* stp_unit_dot (fix_private.h) with MUL_S32's products: the same value,
 * without the 64-bit multiply library call on 32-bit targets */
static inline int32_t unit_dot(stp_unit3 a, stp_unit3 b)
{
    int64_t s = MUL_S32(a.x, b.x) + MUL_S32(a.y, b.y) + MUL_S32(a.z, b.z);
    return (int32_t)stp_asr64(s + ((int64_t)1 << (STP_UNIT_BITS - 1)), STP_UNIT_BITS);
}

/* MAKE-SHADE on STP_UNIT directions: the shade of a point with unit normal
 * n seen along unit e (towards the eye; n_dot_e = N.E, STP_UNIT).  The
 * lights' terms are formed in STP_UNIT and 64 bits, summed with the ambient
 * part B R, multiplied by BRIGHT and only then rounded to stp_fix, so the
 * error does not grow with BRIGHT (each term keeps 2^-30, not 2^-16).
 * Per light, when terms is not NULL, terms[j] gets its term rounded to
 * stp_fix (saturated; 0 for a light that does not reach the face) and
 * *ambient_out B R, for stp_shade_point_terms. */
static stp_fix shade_unit(const stp_lighting *lighting, const stp_material *material,
                          stp_unit3 normal, stp_vec3 point, stp_unit3 e, int32_t n_dot_e,
                          stp_fix *ambient_out, stp_fix *terms)
{
    const int up = STP_UNIT_BITS - F; /* stp_fix to STP_UNIT */
    const int64_t term_cap = (int64_t)1 << 45;
    stp_fix background = stp_fix_clamp(lighting->background, 0, ONE);
    stp_fix refl = material->reflectivity;
    int64_t c = lighting->attenuation_c > 0 ? lighting->attenuation_c : 1;
    /* B R: both stp_fix, so the product has 2F fractional bits (24..40),
     * brought to STP_UNIT's 30; |B R| <= |R| < 2^(31-F), so < 2^61 either way */
    int64_t ambient = 2 * F >= STP_UNIT_BITS
                          ? stp_asr64((int64_t)background * refl, 2 * F - STP_UNIT_BITS)
                          : (int64_t)background * refl * ((int64_t)1 << (STP_UNIT_BITS - 2 * F));
    int64_t sum = 0; /* STP_UNIT; each term is capped at 2^45 */
    int j, count;

#if !STP_WITH_SPECULAR
    (void)e;
#endif
    count = lighting->count < 0 ? 0 : (lighting->count > STP_MAX_LIGHTS ? STP_MAX_LIGHTS : lighting->count);
    if (n_dot_e <= 0)
        count = 0; /* a back face (or the eye on the point): ambient share only */
    if (terms) {
        *ambient_out = stp_fix_mul(background, refl);
        for (j = 0; j < STP_MAX_LIGHTS; j++)
            terms[j] = 0;
    }
    for (j = 0; j < count; j++) {
        const stp_light *light = &lighting->lights[j];
        stp_unit3 l;
        int64_t u, term, power;
        int32_t n_dot_l;
        u = stp_unit_from64((int64_t)light->position.x - point.x,
                            (int64_t)light->position.y - point.y,
                            (int64_t)light->position.z - point.z, &l);
        if (u == 0)
            l = normal; /* light on the surface: lit head-on, 1/(C + 0) */
        n_dot_l = unit_dot(normal, l);
        if (n_dot_l <= 0)
            continue;
        /* R (N.L): stp_fix times STP_UNIT, back to STP_UNIT; |.| < 2^61 */
        term = stp_asr64(MUL_S32(refl, n_dot_l), F);
#if STP_WITH_SPECULAR
        if (material->specular != 0) {
            /* H = (L + E)/|L + E| is never formed: N.H = (N.L + N.E)/|L + E|
             * and E.H = (1 + E.L)/|L + E| with |L + E|^2 = 2 (1 + E.L), so
             * one reciprocal square root of a scalar serves both */
            int64_t one_el = (int64_t)STP_UNIT_ONE + unit_dot(e, l); /* in [0, 2^31] */
            if (one_el > 0) { /* L + E = 0: H undefined, no highlight */
                int ex;
                int64_t inv = (int64_t)stp_rsqrt64((uint64_t)one_el << 1, &ex);
                /* 1/|L + E| = inv 2^-ex 2^15 (the argument is STP_UNIT) */
                /* N.L, N.E > 0 here: the sums are in (0, 2^31 + 4], inv <= 2^30 */
                int64_t n_dot_h = MUL_U32((int64_t)n_dot_l + n_dot_e, inv),
                        e_dot_h = MUL_U32(one_el, inv);
                n_dot_h = stp_asr64(n_dot_h + ((int64_t)1 << (ex - 16)), ex - 15);
                e_dot_h = stp_asr64(e_dot_h + ((int64_t)1 << (ex - 16)), ex - 15);
                /* the share DGF/(E.N) explodes as E.N -> 0: it saturates,
                 * and the min(1, ...) below caps the shade */
                if (n_dot_h > 0 && e_dot_h > 0)
                    term += specular_share_unit(material, n_dot_h, n_dot_e, n_dot_l, e_dot_h);
            }
        }
#endif
        /* P_j term / (C + U_j): the product (STP_UNIT + F bits) saturates at
         * 2^62, far above any shade; C + U < 2^34 */
        power = light->power < 0 ? 0 : light->power;
        if (term < 0)
            term = 0;
        term = stp_div64_fast(mul_shift_sat(term, power, 0), c + u);
        if (term > term_cap)
            term = term_cap;
        if (terms)
            terms[j] = stp_fix_sat64((term + ((int64_t)1 << (up - 1))) >> up);
        sum += term;
    }
    sum += ambient;
    if (lighting->brightness <= 0 || sum <= 0)
        return 0;
    /* BRIGHT times the sum, still in STP_UNIT, then min(1, .) and one
     * rounding to stp_fix */
    sum = mul_shift_sat(sum, lighting->brightness, F);
    if (sum >= STP_UNIT_ONE)
        return ONE;
    return (stp_fix)((sum + ((int64_t)1 << (up - 1))) >> up);
}

/* stp_shade_point's inputs to STP_UNIT: the normal and E renormalised (the
 * caller's stp_fix unit vectors carry their own rounding), N.E. */
static stp_fix shade_parts(const stp_lighting *lighting, const stp_material *material,
                           stp_vec3 normal, stp_vec3 point, stp_vec3 eye, int parallel,
                           stp_vec3 parallel_dir, stp_fix *ambient_out, stp_fix *terms)
{
    stp_unit3 n, e;
    (void)stp_unit_from64(normal.x, normal.y, normal.z, &n);
    if (parallel)
        (void)stp_unit_from64(parallel_dir.x, parallel_dir.y, parallel_dir.z, &e);
    else
        (void)stp_unit_from64((int64_t)eye.x - point.x, (int64_t)eye.y - point.y,
                              (int64_t)eye.z - point.z, &e);
    return shade_unit(lighting, material, n, point, e, stp_unit_dot(n, e), ambient_out, terms);
}

stp_fix stp_shade_unit(const stp_lighting *lighting, const stp_material *material,
                       stp_unit3 normal, stp_vec3 point, stp_unit3 eye_dir, int32_t n_dot_e)
{
    return shade_unit(lighting, material, normal, point, eye_dir, n_dot_e, 0, 0);
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
    return stp_intensity_index_inline(shade, levels);
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
