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

/* ---- xf: a 32-bit-mantissa floating number, m 2^e with m = 0 (the
 * number 0) or m in [2^31, 2^32), any exponent an int holds.  Every
 * operation truncates: relative error below 2^-31 each (sqrt 2^-29), so a
 * chain of twenty stays below 1e-8, and no range can overflow.  The
 * shading's factors are formed in it so that none is rounded to an
 * absolute step before BRIGHT, the powers and 1/(C + U) multiply it. */
typedef struct xf {
    uint32_t m;
    int e;
} xf;

static xf xf_u64(uint64_t v, int e)
{
    xf r;
    int n = stp_bit_length64(v) - 32;
    if (v == 0) {
        r.m = 0;
        r.e = 0;
        return r;
    }
    r.m = (uint32_t)(n >= 0 ? v >> n : v << -n);
    r.e = e + n;
    return r;
}

/* a b: the mantissas' product is in [2^62, 2^64), one test normalises it */
static xf xf_mul(xf a, xf b)
{
    uint64_t p;
    xf r;
    if (a.m == 0 || b.m == 0)
        return xf_u64(0, 0);
    p = stp_umul32x32(a.m, b.m); /* unsigned: may reach 2^64 - 1 */
    if (p >> 63) {
        r.m = (uint32_t)(p >> 32);
        r.e = a.e + b.e + 32;
    } else {
        r.m = (uint32_t)(p >> 31);
        r.e = a.e + b.e + 31;
    }
    return r;
}

/* a / b for b != 0: (a.m 2^32) / b.m in (2^31, 2^33), one test normalises it */
static xf xf_div(xf a, xf b)
{
    uint64_t q;
    xf r;
    if (a.m == 0)
        return a;
#if STP_WIDE_ARITH
    q = ((uint64_t)a.m << 32) / b.m;
#else
    q = stp_udiv64_recip((uint64_t)a.m << 32, b.m);
#endif
    if (q >> 32) {
        r.m = (uint32_t)(q >> 1);
        r.e = a.e - b.e - 31;
    } else {
        r.m = (uint32_t)q;
        r.e = a.e - b.e - 32;
    }
    return r;
}

/* a in units of 2^(e - 31) for e >= a.e: exact while e - a.e <= 31,
 * below 2^63 */
static uint64_t xf_bits(xf a, int e)
{
    int d = e - a.e;
    if (a.m == 0 || d >= 63)
        return 0;
    return d <= 31 ? (uint64_t)a.m << (31 - d) : (uint64_t)a.m >> (d - 31);
}

/* a + b for a, b >= 0 */
static xf xf_add(xf a, xf b)
{
    int e = a.e > b.e ? a.e : b.e;
    return xf_u64(xf_bits(a, e) + xf_bits(b, e), e - 31);
}

/* sqrt(a) for a >= 0: a = (m 2^sh) 2^(e - sh) with e - sh even */
static xf xf_sqrt(xf a)
{
    int sh = (a.e & 1) ? 31 : 32;
    if (a.m == 0)
        return a;
    return xf_u64(stp_sqrt64_fast((uint64_t)a.m << sh), (a.e - sh) / 2);
}

/* a in STP_UNIT (2^30) as int64, truncated, saturated at 2^45 */
static int64_t xf_unit(xf a)
{
    int sh = a.e + STP_UNIT_BITS;
    if (a.m == 0 || sh <= -32)
        return 0;
    if (sh >= 14)
        return (int64_t)1 << 45;
    return sh >= 0 ? (int64_t)a.m << sh : (int64_t)(a.m >> -sh);
}

#if STP_WITH_SPECULAR
/* |a - b| (and *negative = a < b) for a, b >= 0: exact before the one
 * truncation where the exponents differ by at most 31 */
static xf xf_sub(xf a, xf b, int *negative)
{
    int e = a.e > b.e ? a.e : b.e;
    uint64_t x = xf_bits(a, e), y = xf_bits(b, e);
    *negative = x < y;
    return xf_u64(x < y ? y - x : x - y, e - 31);
}

static int xf_less(xf a, xf b)
{
    if (a.m == 0 || b.m == 0)
        return b.m != 0;
    return a.e != b.e ? a.e < b.e : a.m < b.m;
}

/* Fresnel (10.6)-(10.8) without cancellation, from c = E.H and
 * u = 1 - c^2 = |L - E|^2/4 (each formed from the vectors, not from c) and
 * n2m1 = n^2 - 1 (exact, with its sign):
 *   g^2 = n^2 - 1 + c^2,  r = (g - c)/(g + c) = (n^2 - 1)/(g + c)^2,
 *   t = (c g - u)/(c g + u) (the listing's (c(g + c) - 1)/(c(g - c) + 1)),
 *   F = r^2 (1 + t^2)/2, at most 1; 1 where g is imaginary. */
static xf fresnel_xf(xf c, xf c2, xf u, xf n2m1, int n_below_1)
{
    xf g2, g, gc, r, p, num, den, t, one = xf_u64(1, 0), f;
    int neg;
    if (n_below_1) {
        g2 = xf_sub(c2, n2m1, &neg);
        if (neg || g2.m == 0)
            return one; /* beyond the critical angle */
    } else {
        g2 = xf_add(n2m1, c2);
    }
    g = xf_sqrt(g2);
    gc = xf_add(g, c);
    r = xf_div(n2m1, xf_mul(gc, gc));
    p = xf_mul(c, g);
    num = xf_sub(p, u, &neg);
    den = xf_add(p, u);
    if (den.m == 0)
        return one;
    t = xf_div(num, den);
    f = xf_mul(xf_mul(r, r), xf_add(one, xf_mul(t, t)));
    f.e--;
    return xf_less(one, f) ? one : f;
}

/* Ks D F G/(N.E) of one light from the STP_UNIT vectors n, l, e and the
 * cosines N.L, N.E (> 0), in xf; 0 where H is undefined (L = -E).  H is
 * never formed and no quantity is a difference of two nearly equal ones:
 *   S = (L + E)/2, c = E.H = |S|, 1 - c^2 = |(L - E)/2|^2,
 *   1 - N.H = |N x (L + E)|^2/(|L + E|(|L + E| + N.(L + E)))
 *           = 2 |N x S|^2/(c (2c + N.L + N.E)),
 *   N.H/E.H = (N.L + N.E)/(2 c^2),
 *   D = (k/(k + 1 - N.H))^2,
 *   G/(N.E) = min(1/(N.E), 2 (N.H/E.H) min(N.E, N.L)/(N.E)).
 * Components: S, (L - E)/2 and N x S each below 2^31 in magnitude (unit
 * vectors within 2^30 + 2), their squares' sums below 3 2^62, exact. */
static xf specular_xf(const stp_material *material, stp_unit3 n, stp_unit3 l, stp_unit3 e,
                      int32_t n_dot_l, int32_t n_dot_e)
{
    int32_t s0 = (int32_t)(((int64_t)l.x + e.x) >> 1), s1 = (int32_t)(((int64_t)l.y + e.y) >> 1),
            s2 = (int32_t)(((int64_t)l.z + e.z) >> 1);
    int32_t d0 = (int32_t)(((int64_t)l.x - e.x) >> 1), d1 = (int32_t)(((int64_t)l.y - e.y) >> 1),
            d2 = (int32_t)(((int64_t)l.z - e.z) >> 1);
    /* N x S in 2^60, to 2^30 (below 2^31 in magnitude) */
    int64_t x0 = stp_asr64(MUL_S32(n.y, s2) - MUL_S32(n.z, s1), 30);
    int64_t x1 = stp_asr64(MUL_S32(n.z, s0) - MUL_S32(n.x, s2), 30);
    int64_t x2 = stp_asr64(MUL_S32(n.x, s1) - MUL_S32(n.y, s0), 30);
    xf c2 = xf_u64((uint64_t)MUL_S32(s0, s0) + (uint64_t)MUL_S32(s1, s1) + (uint64_t)MUL_S32(s2, s2), -60);
    xf u = xf_u64((uint64_t)MUL_S32(d0, d0) + (uint64_t)MUL_S32(d1, d1) + (uint64_t)MUL_S32(d2, d2), -60);
    xf t = xf_u64((uint64_t)MUL_S32(x0, x0) + (uint64_t)MUL_S32(x1, x1) + (uint64_t)MUL_S32(x2, x2), -60);
    xf c, ns, nl, ne, omx, k, d, f, g, cap, n2m1;
    int64_t nv = material->refraction <= 0 ? 1 : material->refraction, n2;
    if (c2.m == 0)
        return c2; /* L = -E: H undefined */
    c = xf_sqrt(c2);
    nl = xf_u64((uint64_t)n_dot_l, -STP_UNIT_BITS);
    ne = xf_u64((uint64_t)n_dot_e, -STP_UNIT_BITS);
    ns = xf_add(nl, ne);
    /* 1 - N.H = 2 |N x S|^2/(c (2c + N.L + N.E)) */
    omx = xf_add(c, c);
    omx = xf_div(t, xf_mul(c, xf_add(omx, ns)));
    omx.e++;
    k = xf_u64((uint64_t)(material->gloss < 1 ? 1 : material->gloss), -F);
    d = xf_div(k, xf_add(k, omx));
    d = xf_mul(d, d);
    /* n^2 - 1 exactly (2F fractional bits) */
    n2 = MUL_U32(nv, nv) - ((int64_t)1 << (2 * F));
    n2m1 = xf_u64((uint64_t)(n2 < 0 ? -n2 : n2), -2 * F);
    f = fresnel_xf(c, c2, u, n2m1, n2 < 0);
    /* G/(N.E): 2 (N.H/E.H) min(N.E, N.L)/(N.E) = (N.L + N.E) min/(c^2 N.E) */
    cap = xf_div(xf_u64(1, 0), ne);
    g = xf_div(ns, c2);
    if (n_dot_l < n_dot_e)
        g = xf_mul(g, xf_div(nl, ne));
    if (xf_less(cap, g))
        g = cap;
    return xf_mul(xf_mul(xf_mul(d, f), g),
                  xf_u64((uint64_t)(material->specular < 0 ? 0 : material->specular), -F));
}
#endif

/* stp_unit_dot (fix_private.h) with MUL_S32's products: the same value,
 * without the 64-bit multiply library call on 32-bit targets */
static inline int32_t unit_dot(stp_unit3 a, stp_unit3 b)
{
    int64_t s = MUL_S32(a.x, b.x) + MUL_S32(a.y, b.y) + MUL_S32(a.z, b.z);
    return (int32_t)stp_asr64(s + ((int64_t)1 << (STP_UNIT_BITS - 1)), STP_UNIT_BITS);
}

/* The distance from the point to the light, v = light - point (|v_i| <
 * 2^32 raw units), in xf: the squares' sum formed exactly (v halved first
 * when a component reaches 2^31), then its root: no rounding to a raw
 * unit, so a light a few units away keeps its distance. */
static xf distance_xf(int64_t v0, int64_t v1, int64_t v2)
{
    uint64_t a0 = (uint64_t)(v0 < 0 ? -v0 : v0), a1 = (uint64_t)(v1 < 0 ? -v1 : v1),
             a2 = (uint64_t)(v2 < 0 ? -v2 : v2);
    int e = -2 * F;
    if (((a0 | a1 | a2) >> 31) != 0) {
        a0 >>= 1;
        a1 >>= 1;
        a2 >>= 1;
        e += 2;
    }
    return xf_sqrt(xf_u64((uint64_t)MUL_U32(a0, a0) + (uint64_t)MUL_U32(a1, a1) + (uint64_t)MUL_U32(a2, a2), e));
}

/* One light's share P_j (R (N.L) + Ks D G F/(N.E))/(C + U) times BRIGHT, in
 * STP_UNIT saturated at 2^45 (at least 0), or -1 when the light does not
 * reach the point (N.L <= 0).  Each factor is an xf, so nothing is rounded
 * to an absolute step before the products: the error does not grow with
 * BRIGHT, the powers, a small C or a small N.E. */
static int64_t light_share(const stp_lighting *lighting, const stp_material *material, int j, stp_unit3 normal,
                           stp_vec3 point, stp_unit3 e, int32_t n_dot_e)
{
    const stp_light *light = &lighting->lights[j];
    int64_t v0 = (int64_t)light->position.x - point.x, v1 = (int64_t)light->position.y - point.y,
            v2 = (int64_t)light->position.z - point.z, diffuse, specular = 0;
    stp_unit3 l;
    int32_t n_dot_l;
    xf gain, u = xf_u64(0, 0);
    if (stp_unit_from64(v0, v1, v2, &l) == 0)
        l = normal; /* light on the surface: lit head-on, 1/(C + 0) */
    else
        u = distance_xf(v0, v1, v2);
    n_dot_l = unit_dot(normal, l);
    if (n_dot_l <= 0)
        return -1;
    /* BRIGHT P_j/(C + U) */
    gain = xf_mul(xf_u64((uint64_t)(light->power < 0 ? 0 : light->power), -F),
                  xf_u64((uint64_t)(lighting->brightness < 0 ? 0 : lighting->brightness), -F));
    gain = xf_div(gain, xf_add(xf_u64((uint64_t)(lighting->attenuation_c > 0 ? lighting->attenuation_c : 1), -F), u));
    diffuse = xf_unit(xf_mul(xf_mul(gain, xf_u64((uint64_t)n_dot_l, -STP_UNIT_BITS)),
                             xf_u64((uint64_t)(material->reflectivity < 0 ? -(int64_t)material->reflectivity
                                                                        : material->reflectivity), -F)));
    if (material->reflectivity < 0)
        diffuse = -diffuse;
#if STP_WITH_SPECULAR
    if (material->specular > 0)
        specular = xf_unit(xf_mul(gain, specular_xf(material, normal, l, e, n_dot_l, n_dot_e)));
#else
    (void)e;
    (void)n_dot_e;
#endif
    diffuse += specular;
    return diffuse < 0 ? 0 : (diffuse > ((int64_t)1 << 45) ? (int64_t)1 << 45 : diffuse);
}

/* MAKE-SHADE on STP_UNIT directions: the shade of a point with unit normal
 * n seen along unit e (towards the eye; n_dot_e = N.E, STP_UNIT).  Each
 * light's share is formed with BRIGHT in it (light_share), the ambient part
 * BRIGHT B R in 64 bits, summed in STP_UNIT and rounded once to stp_fix.
 * Per light, when terms is not NULL, terms[j] gets its term without BRIGHT
 * rounded to stp_fix (saturated; 0 for a light that does not reach the
 * face) and *ambient_out B R, for stp_shade_point_terms. */
static stp_fix shade_unit(const stp_lighting *lighting, const stp_material *material,
                          stp_unit3 normal, stp_vec3 point, stp_unit3 e, int32_t n_dot_e,
                          stp_fix *ambient_out, stp_fix *terms)
{
    const int up = STP_UNIT_BITS - F; /* stp_fix to STP_UNIT */
    stp_fix background = stp_fix_clamp(lighting->background, 0, ONE);
    stp_fix refl = material->reflectivity, bright = lighting->brightness;
    /* B R (2F fractional bits, |.| < 2^(31 + F)) times BRIGHT in STP_UNIT */
    int64_t br = (int64_t)background * refl, sum;
    int j, count;
    if (terms) {
        *ambient_out = stp_fix_mul(background, refl);
        for (j = 0; j < STP_MAX_LIGHTS; j++)
            terms[j] = 0;
    }
    if (bright <= 0)
        return 0;
    sum = mul_shift_sat(br < 0 ? -br : br, bright, 3 * F - STP_UNIT_BITS);
    if (br < 0)
        sum = -sum;
    count = lighting->count < 0 ? 0 : (lighting->count > STP_MAX_LIGHTS ? STP_MAX_LIGHTS : lighting->count);
    if (n_dot_e <= 0)
        count = 0; /* a back face (or the eye on the point): ambient share only */
    for (j = 0; j < count; j++) {
        int64_t share = light_share(lighting, material, j, normal, point, e, n_dot_e);
        if (share < 0)
            continue;
        if (terms) /* without BRIGHT: share 2^F/bright in STP_UNIT, to stp_fix */
            terms[j] = stp_fix_sat64(stp_div64_fast(share << 16, bright) >> (46 - 2 * F));
        sum += share;
    }
    if (sum <= 0)
        return 0;
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
