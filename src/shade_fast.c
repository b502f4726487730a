/* SPDX-License-Identifier: MIT */
/*
 * MAKE-SHADE of flat faces in 32-bit arithmetic: see shade_fast_private.h.
 *
 * Formats (each with its range; nothing here overflows):
 *   N        the caller's unit normal, Q14 in int16 (|N| = 1 +- 2^-13)
 *   w        a direction scaled to 16 bits (stp_shade_fast_dir): |w_i| < 2^16
 *   N.w      int32: |N.w| <= |N||w| < 2^14 (1 + 2^-13) sqrt(3) 2^16 < 2^31
 *   cosines  Q30 in int32 (one = 2^30): N.E, N.L, E.L, N.H, E.H, within
 *            [-2^30, 2^30] after clamping (rounding can exceed 1 by a few
 *            units: each is clamped where it feeds a formula that needs <= 1)
 *   D, F, G/(N.E) where E.H >= 1/4 (specular_fixed): D in Q30 (<= 1),
 *            F in Q16 (<= 65535, the prepared table), G/(N.E) in Q26 (<=
 *            min(1/(N.E), 2 N.H/E.H) <= 8, capped at 2^29), D F G/(N.E)
 *            in Q27 (<= 2^30); below E.H = 1/4 (L nearly opposite E) the
 *            old stp_sf16 route with the exact Fresnel
 *   stp_sf16 16-bit mantissa floating numbers where the range is not
 *            bounded: BRIGHT P_j |R| and BRIGHT P_j Ks (prepared),
 *            1/(C + U), 1/(N.E), their products: any exponent, so a huge
 *            BRIGHT or a grazing view cannot overflow; each operation
 *            truncates (relative error below 2^-15)
 *   sums     Q26 in int32 (one = 2^26): each light's share is saturated at
 *            8 and the sum returns 1 as soon as it reaches 1 (every share
 *            is >= 0), so at most 2^29 + 2^30 + 1 < 2^31 is ever formed
 *            (the ambient term, at most 2^29, and a share or GRAZE_EXACT).
 * High words of 32 x 32 products (arith_private.h): stp_umulhi32_approx
 * (three 16 x 16 products on ARMv6-M, up to 2 units low; exact with a
 * 64-bit multiply) on the face path, where each product is used at 2^28
 * or more or only as an absolute error; stp_umulhi32x32 (four, exact) in
 * prepare and the exact Fresnel; mul_u16 where one factor has 16 bits
 * (two products, exact).
 */
#include "shade_fast_private.h"

#include "fix_private.h" /* STP_TABLE */
#include "shade_private.h" /* stp_shade_unit: the exact route */

#define F STP_FIX_FRAC_BITS
#define ONE STP_FIX_ONE
#define Q30 ((int32_t)1 << 30)
#define SUM_BITS 26
#define SUM_ONE ((int32_t)1 << SUM_BITS)
#define SHARE_CAP ((uint32_t)1 << 29)

/* A grazing eye (N.E below fast_min_cos, 1/20, exact_prepare): a light
 * nearly opposite the eye (|L + E| < 1/2, 1 + E.L < 1/8: specular_share's
 * stp_sf16 branch; E.L < NEAR_OPPOSITE on the host path) takes N.H =
 * N.(L + E)/|L + E| and E.H = |L + E|/2 from 1 + E.L, whose absolute
 * error (the scaled directions' 2^-15) is relative to E.H^2 ~ (N.E)^2 near
 * the mirror direction, so the face takes the exact route
 * (light_share returns GRAZE_EXACT, 2^30 + 1, never a share: each share
 * is within +-2^30, and added to a sum in [-2^29, 2^29] (the ambient
 * term, then below 2^26) it reaches SUM_ONE without overflow, so
 * face_body tests it only there); with the
 * other lights the cosines' errors stay absolute (G/(N.E) = 4 N.H
 * min(N.E, N.L)/(|L + E| N.E) <= 8 N.L/|L + E|^2: no 1/(N.E)), so the
 * fast route keeps them down to GRAZE_FLOOR, 1/1280, where N.E's own
 * error (below 2^-14, the direction's truncation) still leaves its sign. */
#define NEAR_OPPOSITE (-((int32_t)7 << 27)) /* E.L = -7/8 in Q30 */
#define GRAZE_EXACT (((int32_t)1 << 30) + 1)
#define GRAZE_FLOOR(s) ((s)->fast_min_cos >> 6)
#define FAST_MIN_COS (Q30 / 20) /* fast_min_cos with the highlight (exact_prepare) */

/* ---- integer helpers ---- */

/* A rare branch of the face laid out of its common path in builds for
 * speed; builds for size keep the compiler's layout (the hints cost AVR
 * and -Os images bytes) */
#if defined(__OPTIMIZE_SIZE__)
#define HOT_UNLIKELY(c) (c)
#else
#define HOT_UNLIKELY(c) STP_UNLIKELY(c)
#endif

/* The face's shade from the Q26 sum of the ambient part and the shares
 * of the lights that reach it (lit: at least one did), rounded once to
 * stp_fix; a face no light reaches gets the prepared ambient shade. */
STP_HOT_INLINE stp_fix shade_of_sum(const stp_shade_fast *s, int lit, int32_t sum)
{
    if (!lit)
        return s->ambient_shade;
    if (sum <= 0)
        return 0;
    return (stp_fix)((sum + ((int32_t)1 << (SUM_BITS - F - 1))) >> (SUM_BITS - F));
}

/* floor(a m / 2^16) for m < 2^16, exact: two 32-bit products */
STP_HOT_INLINE uint32_t mul_u16(uint32_t a, uint32_t m)
{
#if STP_WIDE_ARITH
    return (uint32_t)(((uint64_t)a * m) >> 16);
#else
    return (a >> 16) * m + ((stp_lo16(a) * m) >> 16);
#endif
}

/* floor(a m / 2^16) for |a| < 2^31 and m <= 2^16 with |a >> 16| m < 2^31:
 * two 32-bit products. */
static inline int32_t mul_q16(int32_t a, uint32_t m)
{
    return stp_asr32(a, 16) * (int32_t)m + (int32_t)((stp_lo16((uint32_t)a) * m) >> 16);
}

/* ---- reciprocal square root and reciprocal ---- */

/* The reciprocal's seed: 2^31 / x at the middle of [256 + i, 257 + i) 2^7,
 * rounded to nearest: (2^25 + k) / (2 k + 1) with k = 256 + i, the
 * quotient truncated.  A table where a multiply is an instruction; in
 * size-first builds (STP_SMALL_DIVISION) recip.c's stp_recip_seed, the
 * same values computed; on targets without a multiply (AVR) the quotient
 * itself (a 32 / 16-bit library division, which such an image links
 * anyway, instead of 512 bytes of flash), the same seeds. */
#if STP_HAVE_MUL32 && !STP_SMALL_DIVISION
static const uint16_t recip_seed[256] STP_TABLE = {
    65408, 65154, 64902, 64652, 64404, 64158, 63913, 63671, 63430, 63191, 62954, 62719,
    62485, 62253, 62023, 61795, 61568, 61343, 61119, 60897, 60677, 60458, 60241, 60026,
    59812, 59599, 59388, 59179, 58971, 58764, 58559, 58356, 58153, 57952, 57753, 57555,
    57358, 57163, 56968, 56776, 56584, 56394, 56205, 56017, 55831, 55646, 55462, 55279,
    55098, 54917, 54738, 54560, 54383, 54207, 54033, 53859, 53687, 53516, 53346, 53177,
    53009, 52842, 52676, 52511, 52347, 52184, 52022, 51862, 51702, 51543, 51385, 51228,
    51072, 50917, 50763, 50610, 50458, 50306, 50156, 50007, 49858, 49710, 49563, 49417,
    49272, 49128, 48985, 48842, 48700, 48559, 48419, 48280, 48141, 48003, 47867, 47730,
    47595, 47460, 47326, 47193, 47061, 46929, 46798, 46668, 46539, 46410, 46282, 46155,
    46028, 45902, 45777, 45652, 45528, 45405, 45283, 45161, 45040, 44919, 44799, 44680,
    44561, 44443, 44326, 44209, 44093, 43977, 43862, 43748, 43634, 43521, 43408, 43296,
    43185, 43074, 42963, 42854, 42744, 42636, 42528, 42420, 42313, 42207, 42101, 41996,
    41891, 41786, 41683, 41579, 41476, 41374, 41272, 41171, 41070, 40970, 40870, 40771,
    40672, 40574, 40476, 40378, 40281, 40185, 40089, 39993, 39898, 39804, 39709, 39616,
    39522, 39429, 39337, 39245, 39153, 39062, 38971, 38881, 38791, 38702, 38613, 38524,
    38436, 38348, 38260, 38173, 38087, 38000, 37915, 37829, 37744, 37659, 37575, 37491,
    37407, 37324, 37241, 37159, 37077, 36995, 36914, 36833, 36752, 36672, 36592, 36512,
    36433, 36354, 36275, 36197, 36119, 36041, 35964, 35887, 35810, 35734, 35658, 35583,
    35507, 35432, 35358, 35283, 35209, 35136, 35062, 34989, 34916, 34844, 34771, 34700,
    34628, 34557, 34486, 34415, 34344, 34274, 34204, 34135, 34065, 33996, 33928, 33859,
    33791, 33723, 33655, 33588, 33521, 33454, 33387, 33321, 33255, 33189, 33124, 33059,
    32994, 32929, 32864, 32800,
};
#define RECIP_SEED(k) STP_TABLE_U16(&recip_seed[(k) & 0xFFu]) /* k in [256, 512): k - 256 */
#elif STP_HAVE_MUL32
#define RECIP_SEED(k) stp_recip_seed(2u * (k) + 1u) /* round(2^25 / (2 k + 1)) */
#else
#define RECIP_SEED(k) ((((uint32_t)1 << 25) + (k)) / (2u * (k) + 1u))
#endif

/* 1/sqrt(q) for q in [2^30, 2^32) (fix_private.h): inlined where time
 * counts, fix.c's one copy in builds for size */
#if defined(__OPTIMIZE_SIZE__)
#define rsqrt_norm stp_rsqrt_norm
#else
#define rsqrt_norm stp_rsqrt_norm_inline
#endif

/* 2^31 / m for m in [2^15, 2^16): in (2^15, 2^16], error below 2^-15
 * relative: a seed (2^-9) and one Newton step y (2 - m y 2^-31).  Inlined
 * at the face's three reciprocals (recip16_hot, sf_recip_hot: 9
 * instructions a face fewer on ARMv6-M), a call elsewhere (recip16). */
STP_HOT_INLINE uint32_t recip16_hot(uint32_t m)
{
    uint32_t y = RECIP_SEED(m >> 7);
    uint32_t p = m * y; /* ~ 2^31, < 2^32 */
    /* e = 2^31 - p, |e| < 2^23: 2^31 - p + 2^30 modulo 2^32 is in
     * (2^30 - 2^23, 2^30 + 2^23), so the signed value needs no branch */
    int32_t e = (int32_t)(0xC0000000u - p) - 0x40000000;
    return (uint32_t)((int32_t)y + stp_asr32(mul_q16(e, y), 15)); /* |e| < 2^23 */
}

STP_NOINLINE uint32_t recip16(uint32_t m)
{
    return recip16_hot(m);
}

/* ---- stp_sf16: m 2^-e, m = 0 or in [2^15, 2^16) ---- */

STP_HOT_INLINE stp_sf16 sf_make(uint32_t v, int e)
{
    stp_sf16 r;
    int n;
    if (v == 0) {
        r.m = 0;
        r.e = 0;
        return r;
    }
    n = stp_bit_length32(v) - 16;
    r.m = n > 0 ? v >> n : v << -n;
    r.e = e - n;
    return r;
}

static stp_sf16 sf_mul(stp_sf16 a, stp_sf16 b)
{
    uint32_t p = a.m * b.m; /* < 2^32 */
    stp_sf16 r;
    if (p >= 0x80000000u) {
        r.m = p >> 16;
        r.e = a.e + b.e - 16;
    } else {
        r.m = p >> 15; /* 0 stays 0 */
        r.e = a.e + b.e - 15;
    }
    return r;
}

/* 1/a for a != 0 from y = 2^31 / a.m (recip16), in (2^15, 2^16] */
STP_HOT_INLINE stp_sf16 sf_recip_of(stp_sf16 a, uint32_t y)
{
    stp_sf16 r;
    r.m = y;
    r.e = 31 - a.e;
    if (HOT_UNLIKELY(STP_AT_LEAST_POW2(r.m, 16))) { /* a.m = 2^15 exactly */
        r.m >>= 1;
        r.e--;
    }
    return r;
}

/* 1/a for a != 0 */
STP_HOT_INLINE stp_sf16 sf_recip(stp_sf16 a)
{
    return sf_recip_of(a, recip16(a.m));
}

/* The same with recip16 inlined (the face's reciprocals); builds for size
 * keep the one copy */
#if defined(__OPTIMIZE_SIZE__)
#define sf_recip_hot sf_recip
#define recip16_hot recip16
#else
STP_HOT_INLINE stp_sf16 sf_recip_hot(stp_sf16 a)
{
    return sf_recip_of(a, recip16_hot(a.m));
}
#endif

#if !STP_BIT_LENGTH_CLZ
/* the significant bits of 0 .. 15 (where stp_bit_length32 is not the
 * count-leading-zeros form: builds for size on ARMv6-M take that one, the
 * same values, and no table) */
static const uint16_t len4[16] STP_TABLE = {0, 1, 2, 2, 3, 3, 3, 3, 4, 4, 4, 4, 4, 4, 4, 4};
#endif

/* Significant bits of v for v in [2^26, 2^30): 26 + those of v >> 26, in
 * [1, 16), one step of a 16-entry table where stp_bit_length32 takes
 * three halvings before its table (about 8 instructions fewer on ARMv6-M) */
STP_HOT_INLINE int bit_length_26(uint32_t v)
{
#if STP_BIT_LENGTH_CLZ
    return stp_bit_length32(v);
#else
    return 26 + (int)STP_TABLE_U16(&len4[v >> 26]);
#endif
}

/* Significant bits of any v, with one table step where v >> s is in
 * [1, 16), the common case where it is used: a direction's largest
 * component (s = 16: 2^16 to 2^20 raw units, a scene of a few units) and
 * gloss_q30's 1 + (1 - N.H)/k (s = 0, below 16).  Builds for size keep
 * the one form, and so do 8-bit cores (no 32-bit multiply: AVR), where the
 * 32-bit range test costs more than stp_bit_length32's byte steps save
 * (ATmega2560 at -O2: 36 343 against 36 134 cycles a face shade). */
STP_HOT_INLINE int bit_length_near(uint32_t v, int s)
{
#if STP_HAVE_CLZ || defined(__OPTIMIZE_SIZE__) || !STP_HAVE_MUL32
    (void)s;
    return stp_bit_length32(v);
#else
    uint32_t t = v >> s;
    if (HOT_UNLIKELY(t - 1u >= 15u))
        return stp_bit_length32(v);
    return s + (int)STP_TABLE_U16(&len4[t]);
#endif
}

/* 1/c for a Q30 cosine c in (0, 2^31) as stp_sf16, and in Q26 (*q26,
 * saturated at 2^31 - 1): sf_recip(sf_make(c, 30)) and sf_to_fixed(., 26,
 * 2^31 - 1) with the ranges known.  c is brought to [2^26, 2^31) by steps
 * of 4 bits (at most two from N.E >= 1/1280, GRAZE_FLOOR, below which
 * the face takes the exact route), which leave the mantissa as it was;
 * its reciprocal's exponent is then at most 26, so the Q26 value is a
 * left shift, and below 2^31 for a shift below 16. */
STP_HOT_INLINE stp_sf16 recip_cos(uint32_t c, uint32_t *q26)
{
    stp_sf16 a;
    int n, sh;
    a.e = 30;
    while (HOT_UNLIKELY(!STP_AT_LEAST_POW2(c, 26))) {
        c <<= 4;
        a.e += 4;
    }
    n = (HOT_UNLIKELY(STP_AT_LEAST_POW2(c, 30)) ? 31 : bit_length_26(c)) - 16; /* 11 .. 15 */
    a.m = c >> n;
    a.e -= n;
    a = sf_recip_hot(a);
    sh = 26 - a.e; /* >= 10 */
    *q26 = HOT_UNLIKELY(sh >= 16) ? 0x7FFFFFFFu : a.m << sh;
    return a;
}

/* a with b's exponent difference d >= 0 (a >= b) aligned: b.m >> d */
static uint32_t sf_aligned(stp_sf16 b, int d)
{
    return d > 16 ? 0 : b.m >> d;
}

/* a + b; nz: a.m, b.m != 0 known (the face's C + U: no tests; builds
 * for size keep the tests, one body) */
#if defined(__OPTIMIZE_SIZE__)
#define SF_ADD_TESTS 1
#else
#define SF_ADD_TESTS 0
#endif
STP_HOT_INLINE stp_sf16 sf_add_in(stp_sf16 a, stp_sf16 b, int nz)
{
    stp_sf16 r;
    uint32_t sum;
    if (!nz || SF_ADD_TESTS) {
        if (b.m == 0)
            return a;
        if (a.m == 0)
            return b;
    }
    /* the one with the larger scale (the smaller e) keeps its mantissa,
     * the other is aligned to it (no swap of the pair) */
    if (a.e > b.e) {
        sum = b.m + sf_aligned(a, a.e - b.e); /* < 2^17 */
        r.e = b.e;
    } else {
        sum = a.m + sf_aligned(b, b.e - a.e);
        r.e = a.e;
    }
    if (STP_AT_LEAST_POW2(sum, 16)) {
        r.m = sum >> 1;
        r.e--;
    } else {
        r.m = sum;
    }
    return r;
}

#define sf_add(a, b) sf_add_in(a, b, 0)

#if STP_WITH_SPECULAR
/* a 2^q truncated, saturated at cap (< 2^31) */
static uint32_t sf_to_fixed(stp_sf16 a, int q, uint32_t cap)
{
    int sh = q - a.e;
    uint32_t v;
    if (a.m == 0 || sh <= -32)
        return 0;
    if (sh >= 16)
        return cap; /* >= 2^31 */
    v = sh >= 0 ? a.m << sh : a.m >> -sh;
    return v > cap ? cap : v;
}
#endif

/* p 2^sh in Q26 for the sums, saturated at SHARE_CAP */
STP_HOT_INLINE int32_t share_of(uint32_t p, int sh)
{
    if (HOT_UNLIKELY(sh >= 0)) {
        if (p == 0)
            return 0; /* a zero product (a light of power 0) has any exponent */
        return sh >= 31 || p > (SHARE_CAP >> sh) ? (int32_t)SHARE_CAP : (int32_t)(p << sh);
    }
    return HOT_UNLIKELY(sh <= -32) ? 0 : (int32_t)(p >> -sh); /* 0 for p = 0 */
}

/* a b in Q26 for a in Q(q) (a < 2^31), b = m 2^-e: floor(2 a m 2^-16)
 * = a m 2^-15 scaled by 2^(26 - q + 15 - e) */
STP_HOT_INLINE int32_t share_times(uint32_t a, int q, stp_sf16 b)
{
    return share_of(mul_u16(a << 1, b.m), 41 - q - b.e);
}

/* ---- directions ---- */

/* |a| < 2^30 for each component: then the difference of two fits int32 */
static int is_big(stp_vec3 a)
{
    const uint32_t h = 0x40000000u;
    return (((uint32_t)a.x + h) | ((uint32_t)a.y + h) | ((uint32_t)a.z + h)) >= 0x80000000u;
}

/* Component i of a - b, halved first when big (|a_i| or |b_i| beyond
 * 2^30: the difference then fits int32) */
STP_INDEX_INLINE int32_t diff_comp(const stp_vec3 *a, const stp_vec3 *b, int i, int big)
{
    return big ? stp_asr32(stp_vec3_comp(a, i), 1) - stp_asr32(stp_vec3_comp(b, i), 1)
               : stp_vec3_comp(a, i) - stp_vec3_comp(b, i);
}

/* a - b scaled to 16 bits (stp_shade_fast_dir) and, when need_r, its
 * 1/length; halved first when either has a component beyond 2^30 (big).
 * Returns 0 for a zero difference (d->w = 0 then). */
/* need_r for the eye's direction (face_body): the highlight needs it; on
 * 32-bit cores every call asks for it, so that the flag, the same at each
 * call, is not passed (a fifth argument, on the stack: more instructions
 * a call than the rare diffuse eye's root); on 8-bit cores a root is of
 * library products */
#define EYE_NEEDS_R(s) (STP_HAVE_MUL32 || (s)->specular)

static int dir_make(stp_shade_fast_dir *d, const stp_vec3 *a, const stp_vec3 *b, int big, int need_r)
{
    uint32_t any = 0, q = 0;
    /* v = a - b: in registers where the core has them (32-bit), else in
     * d->w, scaled there in place (an 8-bit core's copy would be on the
     * stack) */
    int32_t held[3], *v = STP_HAVE_MUL32 ? held : d->w;
    int i, n;
    STP_UNROLL3
    for (i = 0; i < 3; i++) {
        v[i] = diff_comp(a, b, i, big);
        any |= stp_abs32(v[i]);
    }
    /* the bit length of the largest |v_i| is that of their OR */
    n = bit_length_near(any, 16) - 16; /* the largest 2^-n in [2^15, 2^16) */
    if (n == -16) {
        if (v != d->w) /* in place they are 0 already */
            d->w[0] = d->w[1] = d->w[2] = 0;
        return 0;
    }
    d->shift = n + big;
    /* |v_i| 2^-n truncated, below 2^16: the direction moves by at most
     * 2^-15 radian, which moves a cosine near 1 only to second order */
    if (n > 0) {
        STP_UNROLL3
        for (i = 0; i < 3; i++)
            d->w[i] = v[i] < 0 ? -(int32_t)(stp_abs32(v[i]) >> n) : v[i] >> n;
    } else {
        STP_UNROLL3
        for (i = 0; i < 3; i++)
            d->w[i] = v[i] * ((int32_t)1 << -n); /* |v_i| 2^-n < 2^16: no overflow */
    }
    STP_UNROLL3
    for (i = 0; i < 3; i++) {
        uint32_t u = stp_abs32(d->w[i]);
        q += (u * u) >> 2; /* each u^2 < 2^32 */
    }
    d->q = q; /* in [2^28, 3 2^30) */
    d->j = q < 0x40000000u;
    if (need_r)
        d->r = rsqrt_norm(q << (2 * d->j));
    return 1;
}

/* N.(a - b) > 0, exactly, for |a_i|, |b_i| < 2^30 (not big): with
 * v = a - b = h 2^16 + l (h = v >> 16, |h| <= 2^15; l in [0, 2^16)),
 * N.v = 2^16 A + 2 B + c, A = N.h, B = N.(l >> 1), c = N.(l & 1):
 * |A|, |B| <= 3 2^29 (|N_i| <= 2^14 + 2), |c| < 2^16.  N.v > 0 iff
 * 2^15 A + s > 0 with s = B + c/2 (exact in halves: the sign of
 * 2^15 A + B + c/2 is that of 2^15 A + floor(B + c/2) unless the sum is
 * 0 or -1/2, both "not > 0" as floor keeps them <= 0). */
static int faces_point(const int16_t n[3], const stp_vec3 *a, const stp_vec3 *b)
{
    int32_t h = 0, l = 0, c = 0, t;
    int i;
    STP_UNROLL3
    for (i = 0; i < 3; i++) {
        int32_t v = stp_vec3_comp(a, i) - stp_vec3_comp(b, i);
        h += (int32_t)n[i] * stp_asr32(v, 16);
        l += (int32_t)n[i] * (int32_t)(((uint32_t)v & 0xFFFFu) >> 1);
        if (v & 1)
            c += n[i];
    }
    t = l + stp_asr32(c, 1); /* floor(B + c/2): |t| < 2^31 */
    /* 2^15 h + t > 0  <=>  h > floor(-t / 2^15) */
    return h > stp_asr32(-t, 15);
}

/* N.w (|.| < 2^31: see the file comment) */
static int32_t dot_n(const int16_t n[3], const stp_shade_fast_dir *d)
{
    int32_t dot = 0;
    int i;
    STP_UNROLL3
    for (i = 0; i < 3; i++)
        dot += (int32_t)n[i] * d->w[i];
    return dot;
}

/* The cosine N.w/|w| in Q30 from dot = N.w > 0 (N in Q14), corrected
 * for |N|^2 = 1 + nd 2^-28 (|nd| <= 2^17): cos (1 - nd 2^-29), >= 0.
 * (A dot <= 0 needs no cosine: every caller takes it as "not lit".) */
STP_HOT_INLINE int32_t cos_n(int32_t dot, const stp_shade_fast_dir *d, int32_t nd)
{
    int32_t c = (int32_t)(stp_umulhi32_approx((uint32_t)dot, d->r) << (1 + d->j)); /* <= 2^30 (1 + 2^-12) */
    return c - stp_asr32(stp_asr32(c, 15) * stp_asr32(nd, 2), 12); /* 2^15 2^15: fits */
}

/* The length of d's vector in raw stp_fix units: 2 sqrt(q) 2^shift */
STP_HOT_INLINE stp_sf16 dir_length(const stp_shade_fast_dir *d)
{
    /* sqrt(q) 2^(14 - j) in [2^27, 2^29.8) less the product's 2 units:
     * 27 to 30 bits */
    uint32_t v = stp_umulhi32_approx(d->q, d->r);
    int n = bit_length_26(v) - 16;
    stp_sf16 a;
    a.m = v >> n;
    a.e = 13 - d->j - d->shift - n;
    return a;
}

#if STP_WITH_SPECULAR
/* E.L in Q30 from two scaled directions: the products w_i w'_i can reach
 * 2^32, so each is formed as w (w' >> 1) 2^-2 + w (w' & 1) 2^-3 (~ w w'/8,
 * the sum below 1.5 2^30), then times both 1/lengths.  A call: inlined
 * into the face, its operands took registers the face then spilled (20
 * instructions a face more on ARMv6-M at -O2). */
STP_NOINLINE int32_t cos_dirs(const stp_shade_fast_dir *a, const stp_shade_fast_dir *b)
{
    int32_t s = 0, odd = 0;
    uint32_t m;
    int i;
    /* |a_i (b_i >> 1)| < 2^16 2^15; b_i & 1 is 0 or 1 (a_i or nothing) */
    STP_UNROLL3
    for (i = 0; i < 3; i++) {
        int32_t ai = a->w[i], bi = b->w[i];
        s += stp_asr32(ai * stp_asr32(bi, 1), 2);
        odd += ai & stp_asr32((int32_t)((uint32_t)bi << 31), 31); /* ai or 0 by b_i's low bit */
    }
    s += stp_asr32(odd, 3);
    m = s < 0 ? 0u - (uint32_t)s : (uint32_t)s;
    m = stp_umulhi32_approx(stp_umulhi32_approx(m, a->r), b->r) << (3 + a->j + b->j);
    if (m > (uint32_t)Q30)
        m = (uint32_t)Q30;
    return s < 0 ? -(int32_t)m : (int32_t)m;
}
#endif

#if STP_WITH_SPECULAR
/* a < b */
static int sf_less(stp_sf16 a, stp_sf16 b)
{
    if (a.m == 0 || b.m == 0)
        return b.m != 0;
    return a.e != b.e ? a.e > b.e : a.m < b.m;
}

/* r 2^-e for r in (2^30, 2^31] (a reciprocal square root): no search */
static stp_sf16 sf_from_r(uint32_t r, int e)
{
    stp_sf16 a;
    a.m = r >> 15;
    a.e = e - 15;
    if (a.m > 0xFFFFu) {
        a.m >>= 1;
        a.e--;
    }
    return a;
}

/* 1/sqrt(q) for any q in (0, 2^32): r 2^(j - 46) with r in (2^30, 2^31]
 * (q 4^j is brought into [2^30, 2^32)). */
STP_HOT_INLINE uint32_t rsqrt_any(uint32_t q, int *j)
{
    /* the common cases (|L + E|^2 >= 1/4) without a search */
    *j = STP_AT_LEAST_POW2(q, 30) ? 0 : (STP_AT_LEAST_POW2(q, 28) ? 1 : (32 - stp_bit_length32(q)) >> 1);
    return rsqrt_norm(q << (2 * *j));
}

/* |a - b| */
static stp_sf16 sf_diff(stp_sf16 a, stp_sf16 b)
{
    stp_sf16 t;
    if (b.m == 0)
        return a;
    if (a.m == 0)
        return b;
    if (a.e > b.e || (a.e == b.e && a.m < b.m)) { /* a the larger */
        t = a;
        a = b;
        b = t;
    }
    return sf_make(a.m - sf_aligned(b, b.e - a.e), a.e);
}

static const stp_sf16 sf_one = {0x8000u, 15};

/* sqrt(x) in Q30 for x in (0, 2^32) in Q30 */
static uint32_t sqrt_q30(uint32_t x)
{
    int j;
    uint32_t r = rsqrt_any(x, &j);
    /* sqrt(x 2^-30) 2^30 = x r 2^(j - 46) 2^15 */
    return stp_umulhi32x32(x, r) << (j + 1);
}

/* Fresnel (10.6)-(10.8) at c = E.H (Q30, in (0, 2^30]) for the prepared
 * index n, as stp_sf16 in [0, 1], given u = 1 - c^2 (Q30, in [0, 2^30]:
 * (1 - E.L)/2, since c^2 = |L + E|^2/4 = (1 + E.L)/2):
 *   g = sqrt(n^2 - u), u = 1 - c^2 (n >= 1: g = n sqrt(1 - u/n^2), so
 *   that n^2 needs no range), r = (g - c)/(g + c), t = (p - u)/(p + u)
 *   with p = c g (the listing's (c (g + c) - 1)/(c (g - c) + 1)),
 *   F = r^2 (1 + t^2)/2; 1 where g is imaginary (n < 1). */
static stp_sf16 fresnel_sf(const stp_shade_fast *s, uint32_t c, uint32_t u)
{
    stp_sf16 g, cs, us, r, p, den;
    if (s->refraction_ge_1) {
        uint32_t w = (uint32_t)Q30 - (stp_umulhi32x32(u, s->inv_n2) << 1); /* in [0, 2^30] */
        g = w == 0 ? sf_make(0, 0) : sf_mul(s->refraction, sf_make(sqrt_q30(w), 30));
    } else {
        if (s->n2 <= u)
            return sf_one; /* beyond the critical angle: total reflection */
        g = sf_make(sqrt_q30(s->n2 - u), 30);
    }
    cs = sf_make(c, 30);
    us = sf_make(u, 30);
    /* F = (g - c)^2 (p^2 + u^2) / ((g + c)(p + u))^2: one reciprocal;
     * g + c > 0 and p + u > 0 (c > 0) */
    p = sf_mul(cs, g);
    den = sf_mul(sf_add(g, cs), sf_add(p, us));
    if (den.m == 0)
        return sf_one;
    r = sf_diff(g, cs);
    r = sf_mul(sf_mul(r, r), sf_add(sf_mul(p, p), sf_mul(us, us)));
    den = sf_recip(den);
    r = sf_mul(r, sf_mul(den, den));
    return sf_less(sf_one, r) ? sf_one : r;
}

/* The table's first node (c = 1/4) in Q30; nodes every 1/64 (2^24) */
#define FRESNEL_C0 ((uint32_t)1 << 28)

/* F at c = E.H (Q30, in [2^28, 2^30]: c >= 1/4) in Q16, at most 65535:
 * the prepared table linearly interpolated (n >= 1), else fresnel_sf. */
static uint32_t fresnel_q16(const stp_shade_fast *s, uint32_t c, int32_t e_dot_l)
{
    if (s->refraction_ge_1) {
        /* c - FRESNEL_C0 (2^28) in steps of 2^24 and their fraction: c's own
         * bits (no subtraction) */
        uint32_t i = (c >> 24) - (FRESNEL_C0 >> 24), frac = (c >> 8) & 0xFFFFu;
        uint32_t a = s->fresnel[i];
        int32_t d;
        if (HOT_UNLIKELY(i >= STP_SHADE_FAST_FRESNEL_NODES - 1))
            return a;
        d = (int32_t)s->fresnel[i + 1] - (int32_t)a; /* |d| < 2^16 */
        return (uint32_t)((int32_t)a + stp_asr32(d * (int32_t)frac, 16));
    }
    return sf_to_fixed(fresnel_sf(s, c, e_dot_l >= Q30 ? 0u : ((uint32_t)Q30 - (uint32_t)e_dot_l) >> 1),
                       16, 0xFFFFu);
}

/* D = (1/(1 + (1 - N.H)/k))^2 in Q30 from omx = 1 - N.H (Q30, < 2^30):
 * x = omx/k in Q16 (below 2^32: 1/k in Q16 is below 2^32), t = 1 + x
 * = m 2^(n - 16) with m in [2^15, 2^16), 1/t = y 2^(-15 - n) with
 * y = 2^31/m (recip16), D = y^2 2^(-30 - 2n).  0 when x >= 2^31 (D < 2^-30). */
static uint32_t gloss_q30(const stp_shade_fast *s, uint32_t omx)
{
    uint32_t x = stp_umulhi32_approx(omx << 2, s->inv_gloss_q16), t, y;
    int n;
    if (x >= 0x80000000u)
        return 0;
    t = ((uint32_t)1 << 16) + x;
    n = bit_length_near(t >> 16, 0); /* 1 .. 16: one halving fewer */
    y = recip16_hot(t >> n);
    if (STP_AT_LEAST_POW2(y, 16)) /* m = 2^15: D = 2^(32 - 2n) 2^-30 */
        return n >= 16 ? 0u : (uint32_t)1 << (32 - 2 * n);
    return n >= 16 ? 0u : (y * y) >> (2 * n);
}

/* Ks D F G/(N.E) where E.H >= 1/4 (so G/(N.E) <= 2 (N.H)/(E.H) <= 8):
 * fixed formats, one conversion to stp_sf16 at the end.
 *   g1 = 2 N.H/E.H = 4 N.H/|L + E| in Q26 (<= 2^29),
 *   G/(N.E) = min(1/(N.E), g1 min(1, N.L/N.E)) in Q26 (<= 2^29),
 *   D in Q30, F in Q16, D F in Q31, D F G/(N.E) in Q27 (<= 2^30). */
static uint32_t specular_fixed(const stp_shade_fast *s, int32_t n_dot_l, int32_t n_dot_e,
                               uint32_t nh, uint32_t r, int j, uint32_t eh, int32_t e_dot_l,
                               stp_sf16 inv_ne, uint32_t inv_ne_q26)
{
    uint32_t g1 = stp_umulhi32_approx(nh, r) >> (1 - j), gne = g1, d, df;
    if (n_dot_l < n_dot_e) {
        /* N.L/N.E < 1 in Q30: N.L m 2^-e (inv_ne = m 2^-e) */
        uint32_t p = mul_u16((uint32_t)n_dot_l << 1, inv_ne.m); /* N.L m 2^-15 */
        int sh = 15 - inv_ne.e;
        uint32_t ratio = !HOT_UNLIKELY(sh < 0) ? (HOT_UNLIKELY(sh >= 16) ? (uint32_t)Q30 : p << sh) : (sh <= -32 ? 0u : p >> -sh);
        if (ratio > (uint32_t)Q30)
            ratio = (uint32_t)Q30;
        gne = stp_umulhi32_approx(g1 << 2, ratio); /* g1 ratio in Q26 */
    }
    if (gne > inv_ne_q26)
        gne = inv_ne_q26;
    if (gne > ((uint32_t)1 << 29))
        gne = (uint32_t)1 << 29;
    d = gloss_q30(s, (uint32_t)Q30 - nh);
    df = mul_u16(d << 1, fresnel_q16(s, eh, e_dot_l));
    return stp_umulhi32_approx(df, gne << 2);
}

/* Ks D F G/(N.E) of one light, from the cosines (Q30, N.L and N.E > 0)
 * and inv_ne = 1/(N.E); -1 (light_share's GRAZE_EXACT) for a light
 * nearly opposite a grazing eye, tested on the stp_sf16 branch only:
 *   |L + E|^2 = 2 (1 + E.L) = X, N.H = (N.L + N.E)/|L + E|,
 *   E.H = |L + E|/2, 1/(E.H) = 2/|L + E| (one reciprocal square root);
 *   D = (1/(1 + (1 - N.H)/k))^2;
 *   G/(N.E) = min(1/(N.E), 2 (N.H) min(N.E, N.L)/((N.E)(E.H))). */
static int32_t specular_share(const stp_shade_fast *s, int32_t n_dot_l, int32_t n_dot_e,
                              int32_t e_dot_l, stp_sf16 inv_ne, uint32_t inv_ne_q26, stp_sf16 wk)
{
    uint32_t one_el = (uint32_t)(Q30 + e_dot_l), x, r, nh, eh, omx;
    int j;
    stp_sf16 d, g;
    if ((int32_t)one_el <= 0)
        return 0; /* L = -E: H undefined */
    x = one_el >= 0x80000000u ? 0xFFFFFFFFu : one_el << 1;
    r = rsqrt_any(x, &j); /* 1/|L + E| = r 2^(j - 31) */
    nh = stp_umulhi32_approx((uint32_t)n_dot_l + (uint32_t)n_dot_e, r); /* the sum <= 2^31 + 8 */
    nh = HOT_UNLIKELY(nh >= (0x80000000u >> (1 + j))) ? (uint32_t)Q30 : nh << (1 + j);
    eh = stp_umulhi32_approx(x, r) << j; /* sqrt(x) 2^14 <= 2^30 */
    if (nh == 0 || eh == 0)
        return 0;
    if (nh > (uint32_t)Q30)
        nh = (uint32_t)Q30;
    if (STP_AT_LEAST_POW2(eh, 28) && j <= 1) /* eh >= FRESNEL_C0; j <= 1: |L + E| >= 1/2 */
        return share_times(specular_fixed(s, n_dot_l, n_dot_e, nh, r, j, eh, e_dot_l, inv_ne, inv_ne_q26), 27, wk);
    if (n_dot_e < s->fast_min_cos && s->exact)
        return -1; /* a light nearly opposite a grazing eye: GRAZE_EXACT */
    omx = (uint32_t)Q30 - nh;
    d = sf_one;
    if (omx != 0) {
        d = sf_recip(sf_add(sf_one, sf_mul(sf_make(omx, 30), s->inv_gloss)));
        d = sf_mul(d, d);
    }
    /* 2 N.H / E.H = N.H 2^-29 r 2^(j - 30) */
    g = sf_mul(sf_make(nh, 29), sf_from_r(r, 30 - j));
    if (n_dot_l < n_dot_e)
        g = sf_mul(g, sf_mul(sf_make((uint32_t)n_dot_l, 30), inv_ne));
    if (sf_less(inv_ne, g))
        g = inv_ne;
    return (int32_t)sf_to_fixed(sf_mul(sf_mul(sf_mul(d, fresnel_sf(s, eh, e_dot_l >= Q30 ? 0u : ((uint32_t)Q30 - (uint32_t)e_dot_l) >> 1)), g), wk), SUM_BITS, SHARE_CAP);
}
#endif

#if STP_WIDE_ARITH
/* ---- the host path: 64-bit fixed point, native products and quotients ----
 *
 * On a host (STP_WIDE_ARITH) a 64-bit product, a 64-bit quotient and a
 * count of leading zeros are one instruction each, so the face is shaded
 * without the scaled 16-bit directions, tables and soft mantissas above:
 *   v        a direction (light - point, eye - point): int64 differences of
 *            stp_fix, kept as they are when every |v_i| < 2^30, else
 *            divided by 4 (wide_make_big): |v|^2 < 3 2^60 and the dot product
 *            of two below 3 2^60 in magnitude
 *   |v|      len = |v| 2^j in [2^30, 2^31): |v|^2 4^j brought to [2^60,
 *            2^62) by one shift, its root by a seed line and two Newton
 *            steps (wide_sqrt60; relative error below 2^-23)
 *   |N|      the caller's Q14 normal: |N| 2^14 = (n.n + 2^28)/2 to first
 *            order (n.n = 2^28 (1 + d), |d| <= 2^-11: error below 2^-25)
 *   cosines  Q30 in int64 (<= 2^30 after clamping), each one quotient
 *   D        (k/(k + 1 - N.H))^2 in Q30, one quotient (k prepared in Q30,
 *            shifted below 2^32)
 *   F        Q16 (<= 65535): the prepared table, or the exact Fresnel
 *   G/(N.E)  Q26 in uint64: min(1/(N.E), 4 N.H/|L + E| min(1, N.L/N.E)),
 *            at most 2^56 (N.E >= 2^-30)
 *   shares   BRIGHT P_j |R| (N.L)/(C + U) and BRIGHT P_j Ks D F G/(N.E)/(C
 *            + U): C + U brought to [2^28, 2^29) by a right shift, the
 *            power's 24-bit mantissa times 2^36 (prepared) divided by it (one
 *            quotient in (2^30, 2^32)), times the Q30 cosine or the Q26 D F G/(N.E) brought to
 *            32 bits (products below 2^64), shifted to Q26 saturated at
 *            SHARE_CAP; the sum as in the narrow path. */

static inline int64_t asr64(int64_t v, int s)
{
    if ((int64_t)-1 >> 1 == (int64_t)-1)
        return v >> s;
    return v >= 0 ? v >> s : (int64_t)~(~(uint64_t)v >> s);
}

STP_HOT_INLINE int bit_length64(uint64_t v)
{
    return v == 0 ? 0 : 64 - __builtin_clzll(v);
}

#if STP_WITH_SPECULAR
/* sqrt(q) for q = x 2^30, x in [2, 2^33), relative error below 2^-23: q
 * 4^-h in [2^30, 2^32) (h = ceil(bits(q)/2) - 16 = floor(log2 x)/2, from
 * x's leading zeros), whose root 2^15 sqrt(u) (u in [1, 4)) is seeded by
 * the minimax line 2^15 (0.6863 + 0.3431 u) (relative error 2.94 %),
 * shifted back by h, then two Newton steps (4.3e-4, then 9.3e-8 and the
 * truncations; each step leaves r at or above the integer root, so q/r
 * never divides by 0). */
STP_HOT_INLINE uint64_t wide_sqrt30(uint64_t x)
{
    uint64_t q = x << 30, r;
    int h = (63 - __builtin_clzll(x)) >> 1;
    uint64_t y = q >> (2 * h); /* in [2^30, 2^32) */
    r = (22488u + ((y * 11243u) >> 30)) << h;
    r = (r + q / r) >> 1;
    return (r + q / r) >> 1;
}
#endif

/* sqrt(q) for q in [2^60, 2^62): wide_sqrt30's steps with h = 15 */
STP_HOT_INLINE uint64_t wide_sqrt60(uint64_t q)
{
    uint64_t y = q >> 30; /* in [2^30, 2^32) */
    uint64_t x = (22488u + ((y * 11243u) >> 30)) << 15;
    x = (x + q / x) >> 1;
    return (x + q / x) >> 1;
}

/* A direction: its stp_fix differences v (|v_i| < 2^32) kept as they are
 * when every |v_i| < 2^30, else v 2^-2 (s = 2), so that |v|^2 < 3 2^60
 * and the dot product of two is below 3 2^60 in magnitude; len = |v| 2^j
 * in [2^30, 2^31) with j in [0, 30] (from |v|^2 4^j in [2^60, 2^62): one
 * count of leading zeros, no scaling of the components); the raw length
 * is len 2^-(j - s) (s kept, not j - s, and stored only where read: a
 * light's, and a big eye's). */
typedef struct wide_dir {
    int64_t v[3];
    uint64_t len;
    int j, s;
} wide_dir;

/* A direction from v already scaled by 2^-s, but for s, which the caller
 * sets where it reads it (0 for v = 0); may_be_0 = 0 where the caller
 * knows v is not 0 (no test) */
STP_HOT_INLINE int wide_make_scaled(wide_dir *d, int64_t v0, int64_t v1, int64_t v2, int may_be_0)
{
    uint64_t q;
    d->v[0] = v0;
    d->v[1] = v1;
    d->v[2] = v2;
    q = (uint64_t)(v0 * v0 + v1 * v1 + v2 * v2); /* < 3 2^60 */
    if (may_be_0 && q == 0) {
        d->len = 0;
        d->j = 0;
        return 0;
    }
    d->j = (62 - (64 - __builtin_clzll(q))) >> 1; /* bits <= 62 */
    d->len = wide_sqrt60(q << (2 * d->j));
    return 1;
}

/* A direction with a component outside [-2^30, 2^30): out of the face's line */
STP_NOINLINE int wide_make_big(wide_dir *d, int64_t v0, int64_t v1, int64_t v2)
{
    d->s = 2;
    return wide_make_scaled(d, asr64(v0, 2), asr64(v1, 2), asr64(v2, 2), 1);
}

/* A component outside [-2^30, 2^30) */
STP_HOT_INLINE int wide_big(int64_t v0, int64_t v1, int64_t v2)
{
    const uint64_t h = (uint64_t)1 << 30;
    return ((((uint64_t)v0 + h) | ((uint64_t)v1 + h) | ((uint64_t)v2 + h)) >> 31) != 0;
}

/* The eye's direction (v not 0: no zero test); 1 where big (s = 2), else
 * 0 with s not set (read nowhere: the one reader, wide_eye_cos, takes
 * this result) */
STP_HOT_INLINE int wide_make_eye(wide_dir *d, int64_t v0, int64_t v1, int64_t v2)
{
    if (HOT_UNLIKELY(wide_big(v0, v1, v2))) {
        (void)wide_make_big(d, v0, v1, v2);
        return 1;
    }
    (void)wide_make_scaled(d, v0, v1, v2, 0);
    return 0;
}

/* A light's direction (0 for v = 0), d passing to no call: the big case
 * made in a copy, so that d can stay out of memory (2.7 instructions a
 * face fewer on the host torus than d passed to wide_make_big) */
STP_HOT_INLINE int wide_make_light(wide_dir *d, int64_t v0, int64_t v1, int64_t v2)
{
    if (HOT_UNLIKELY(wide_big(v0, v1, v2))) {
        wide_dir t;
        int made = wide_make_big(&t, v0, v1, v2);
        *d = t;
        return made;
    }
    d->s = 0;
    return wide_make_scaled(d, v0, v1, v2, 1);
}

/* N.v/(|N| |v|) in Q30 from dot = N.v, clamped to 2^30 above (not below:
 * each caller only tests a cosine <= 0): |N.v| 2^j <= |N| len < (2^14 +
 * 3) 2^31, so N.v 2^(j + 17) < 2^63; nlen28 len < 2^60, and >> 27 leaves
 * at least 2^31 */
STP_HOT_INLINE int64_t wide_cos_dot(int64_t dot, const wide_dir *d, uint64_t nlen28)
{
    /* dot 2^(j + 17) as an unsigned shift (it fits: the conversion back
     * gives it exactly, as in fix.c) */
    int64_t c = (int64_t)((uint64_t)dot << (d->j + 17)) / (int64_t)((nlen28 * d->len) >> 27);
    return HOT_UNLIKELY(c > Q30) ? Q30 : c;
}

/* p 2^t in Q26 (p < 2^63: a right shift by more than 62 leaves 0),
 * saturated at SHARE_CAP; the common right shift by 1 to 63 tested by one
 * unsigned comparison */
STP_HOT_INLINE int32_t wide_share(uint64_t p, int t)
{
    if (HOT_UNLIKELY((unsigned)-1 - (unsigned)t >= 63u)) { /* t outside [-63, -1] */
        if (t < 0)
            return 0; /* t < -63 */
        return t >= 30 ? (p != 0 ? (int32_t)SHARE_CAP : 0)
                       : (p > ((uint64_t)SHARE_CAP >> t) ? (int32_t)SHARE_CAP : (int32_t)(p << t));
    }
    p >>= -t;
    return HOT_UNLIKELY(p > SHARE_CAP) ? (int32_t)SHARE_CAP : (int32_t)p;
}

#if STP_WITH_SPECULAR
/* Ks D F G/(N.E) in Q26 (uint64, <= 2^57) for one light: nl, ne, el Q30
 * cosines (nl, ne > 0), inv_ne = 1/(N.E) in Q26. */
STP_HOT_INLINE uint64_t wide_specular(const stp_shade_fast *s, int64_t nl, int64_t ne, int64_t el, uint64_t inv_ne)
{
    uint64_t x, sum, nh, eh, omx, d, f, g1, gne, df;
    if (el <= -Q30)
        return 0; /* L = -E: H undefined */
    x = (uint64_t)(2 * (Q30 + el));
    /* x >= 2: |L + E| in Q30 in [2^15, 2^31], N.H in (0, 2^30], E.H > 0 */
    sum = wide_sqrt30(x);
    eh = sum >> 1;
    /* F in Q16; n >= 1 here (n < FAST_MIN_REFRACTION takes the exact route,
     * exact_always, before face_wide) */
    if (eh >= FRESNEL_C0) {
        /* the prepared table, linearly interpolated (fresnel_q16 inline) */
        uint64_t i = (eh - FRESNEL_C0) >> 24, frac = ((eh - FRESNEL_C0) >> 8) & 0xFFFFu;
        f = (uint64_t)((int64_t)s->fresnel[i] + asr64((int64_t)s->wide_fresnel_step[i] * (int64_t)frac, 16));
    } else
        f = sf_to_fixed(fresnel_sf(s, (uint32_t)eh, el >= Q30 ? 0u : (uint32_t)((Q30 - el) >> 1)), 16, 0xFFFFu);
    nh = ((uint64_t)(nl + ne) << 30) / sum; /* (N.L + N.E) <= 2^31 */
    if (nh > (uint64_t)Q30)
        nh = (uint64_t)Q30;
    /* G/(N.E) in Q26: g1 = 2 N.H/E.H = 4 N.H/|L + E| (< 2^59) */
    g1 = (nh << 28) / sum;
    gne = g1 < inv_ne ? g1 : inv_ne;
    if (nl < ne) {
        /* g1 N.L/N.E is below 1/(N.E) iff g1 N.L < 2^56 (Q26 Q30) */
        if (g1 >> 33 == 0 || g1 < ((uint64_t)1 << 56) / (uint64_t)nl) {
            uint64_t t = (g1 * (uint64_t)nl) / (uint64_t)ne; /* g1 nl < 2^63 or < 2^56 */
            gne = t < gne ? t : gne;
        }
    }
    /* D: k in Q30 as gk 2^r (gk < 2^24), 1 - N.H in [0, 2^30] */
    omx = (uint64_t)Q30 - nh;
    d = s->wide_gloss30 / (s->wide_gloss + (omx >> s->wide_gloss_r)); /* g 2^30/(...): Q30, <= 2^30 */
    d = (d * d) >> 30;
    df = (d * f) >> 16; /* Q30, <= 2^30 */
    /* D F G/(N.E) in Q26, exactly floor(df gne 2^-30): one product below
     * 2^64 where gne < 2^34, else in two parts */
    if (!HOT_UNLIKELY(gne >> 34 != 0))
        return (df * gne) >> 30;
    return df * (gne >> 30) + ((df * (gne & ((uint64_t)Q30 - 1))) >> 30);
}
#endif


/* The direction towards the eye, ve, and N.E exactly (|N_i| <= 2^14 + 2,
 * |ve_i| < 2^32). */
STP_HOT_INLINE int64_t wide_eye_dot(const stp_shade_fast *s, const int16_t normal[3], const int64_t p[3], int64_t ve[3])
{
    if (s->parallel) {
        ve[0] = s->eye.x; /* the direction towards the eye (wide_prepare) */
        ve[1] = s->eye.y;
        ve[2] = s->eye.z;
    } else {
        ve[0] = s->eye.x - p[0];
        ve[1] = s->eye.y - p[1];
        ve[2] = s->eye.z - p[2];
    }
    return normal[0] * ve[0] + normal[1] * ve[1] + normal[2] * ve[2];
}

/* The eye's terms of the highlight on a face (face_wide): the direction
 * E and N.E in Q30 (unused without the highlight; 1/(N.E) is formed
 * where a light's highlight takes it, wide_light_specular: kept through
 * the light's terms, it cost a store and a load). */
typedef struct wide_eye {
    wide_dir e;
    int64_t ne;
} wide_eye;

#if STP_WITH_SPECULAR
/* N.E in Q30 for the highlight (dot_e = N.E > 0, ve not 0), e the
 * direction towards the eye. */
STP_HOT_INLINE int64_t wide_eye_cos(const int16_t normal[3], const int64_t ve[3], int64_t dot_e, uint64_t nlen28,
                                    wide_dir *e)
{
    int big = wide_make_eye(e, ve[0], ve[1], ve[2]); /* not 0: N.E > 0 */
    /* the exact N.E unless e was shifted */
    return wide_cos_dot(!big ? dot_e : normal[0] * e->v[0] + normal[1] * e->v[1] + normal[2] * e->v[2], e, nlen28);
}
#endif

#if STP_WITH_SPECULAR
/* E.L in Q30 (at most 2^30) for the eye's and the light's directions:
 * |e.l| 2^(je + jl) <= len_e len_l < 2^62, so twice it fits; len_e len_l
 * >> 29 >= 2^31 */
STP_HOT_INLINE int64_t wide_el(const wide_eye *we, const wide_dir *l)
{
    int64_t dot = we->e.v[0] * l->v[0] + we->e.v[1] * l->v[1] + we->e.v[2] * l->v[2];
    int64_t el = (int64_t)((uint64_t)dot << (we->e.j + l->j + 1)) / (int64_t)((we->e.len * l->len) >> 29);
    return el > Q30 ? Q30 : el; /* below -1: x <= 0 in wide_specular */
}

/* Light j's highlight share in Q26 (face_wide): nl N.L, el E.L, w and c
 * its BRIGHT P_j/(C + U) = w 2^(c - 10) (c as wide_light_w sets it). */
STP_HOT_INLINE int32_t wide_light_specular(const stp_shade_fast *s, const wide_eye *we, int64_t el, int64_t nl,
                                           uint64_t w, int c)
{
    uint64_t dfg = wide_specular(s, nl, we->ne, el, ((uint64_t)1 << 56) / (uint64_t)we->ne), n; /* N.E >= 2^-30 */
    int sh;
    /* D F G/(N.E) = dfg 2^-26 = n 2^(6 - sh), n = floor(dfg 2^(sh - 32))
     * in [2^31, 2^32) (sh = the leading zeros: dfg 2^sh has its top bit at
     * 63, and its low 32 bits 0 where sh > 32); the share n w Ks 2^(c + 6
     * - sh) = (n w 2^-32) Ks 2^(38 - sh + c), n w 2^-32 < 2^32, times Ks <
     * 2^31; dfg = 0 (no test): n = 0 and a share of 0 (dfg | 1 has
     * dfg's leading zeros where dfg > 0) */
    sh = __builtin_clzll(dfg | 1u);
    n = (dfg << sh) >> 32;
    return wide_share(((n * w) >> 32) * s->wide_ks, 38 - sh + c);
}
#endif

/* Light j's BRIGHT P_j/(C + U) = w 2^(c' - 10) (w returned, *c set to c'
 * = c - e - 26, the diffuse share's shift: wide_power_e holds e + 26) from
 * C + U = cu 2^-c in raw units (cu >= 2^29, c in *c) */
STP_HOT_INLINE uint64_t wide_light_w(const stp_shade_fast *s, int j, uint64_t cu, int *c)
{
    /* cu >= 2^29 brought to [2^28, 2^29) by a right shift (c -= t);
     * BRIGHT P_j/(C + U) = (m 2^-e)/(cu 2^-c) = w 2^(c - e - 36) with
     * w = m 2^36/cu in (2^30, 2^32) */
    int t = 35 - __builtin_clzll(cu); /* bit length - 29 (cu > 0) */
    *c -= t + s->wide_power_e[j]; /* c - e - 26 */
    return s->wide_power[j] / (cu >> t);
}

/* Light j's share in Q26 (face_wide) from nl = N.L > 0 (Q30), BRIGHT
 * P_j/(C + U) = w 2^(c - 10) (c wide_light_w's c - e - 26) and el = E.L
 * (with the highlight). */
STP_HOT_INLINE int32_t wide_light_share(const stp_shade_fast *s, const wide_eye *we, uint64_t w, int64_t nl, int c,
                                        int64_t el)
{
    /* BRIGHT P_j |R| (N.L)/(C + U) in Q26: nl 2^-30 |R| 2^-16 w 2^(c -
     * 10) 2^26 = (w nl 2^-30) |R| 2^c; w nl 2^-30 < 2^32, times |R| <
     * 2^31; signed as R by a product (no test) */
    int32_t share = wide_share(((w * (uint64_t)nl) >> 30) * s->wide_refl, c) * s->wide_refl_sign;
#if STP_WITH_SPECULAR
    if (s->specular)
        share += wide_light_specular(s, we, el, nl, w, c);
#else
    (void)we;
    (void)el;
#endif
    return share;
}

/* wide_light_share for light j on the face (at the point): lit head-on
 * (L = N, E.L = N.E), U = 0; out of the face's line */
STP_NOINLINE int32_t wide_light_at_point(const stp_shade_fast *s, const wide_eye *we, int j)
{
#if STP_WITH_SPECULAR
    int c = 29;
    uint64_t w = wide_light_w(s, j, (uint64_t)s->wide_c << 29, &c);
    return wide_light_share(s, we, w, Q30, c, we->ne);
#else
    int c = 29;
    uint64_t w = wide_light_w(s, j, (uint64_t)s->wide_c << 29, &c);
    return wide_light_share(s, we, w, Q30, c, 0);
#endif
}

static stp_fix face_wide(const stp_shade_fast *s, const int16_t normal[3], const stp_vec3 *point)
{
    int64_t ve[3], dot_e, p[3];
    uint64_t nn, nlen28;
    int32_t acc = 0; /* the shares added, each > 0: below SUM_ONE - ambient + 2^30 < 2^31 */
    int j;
    wide_eye we; /* e and ne set with the highlight, else ne 0 */
    p[0] = point->x;
    p[1] = point->y;
    p[2] = point->z;
    dot_e = wide_eye_dot(s, normal, p, ve);
    if (dot_e <= 0)
        return s->ambient_shade; /* a back face, edge-on, or the eye on it */
    nn = (uint64_t)((int32_t)normal[0] * normal[0]) + (uint64_t)((int32_t)normal[1] * normal[1]) +
         (uint64_t)((int32_t)normal[2] * normal[2]);
    nlen28 = (nn + ((uint64_t)1 << 28)) >> 1;
#if STP_WITH_SPECULAR
    if (s->specular) {
        /* fast_min_cos is FAST_MIN_COS with the highlight (exact_prepare) */
        we.ne = wide_eye_cos(normal, ve, dot_e, nlen28, &we.e);
        if (we.ne < (FAST_MIN_COS >> 6)) /* GRAZE_FLOOR */
            return we.ne <= 0 ? s->ambient_shade : s->exact(s, normal, *point);
    } else
#endif
        we.ne = 0;
    j = 0;
    do { /* s->count >= 1 (STP_SHADE_WIDE_FAST) */
        wide_dir l;
        int32_t share;
        if (wide_make_light(&l, s->light[j].x - p[0], s->light[j].y - p[1], s->light[j].z - p[2])) {
            int64_t nl = wide_cos_dot(normal[0] * l.v[0] + normal[1] * l.v[1] + normal[2] * l.v[2], &l, nlen28), el = 0;
            int c = l.j - l.s + 2;
            uint64_t w;
            if (HOT_UNLIKELY(nl <= 0))
                continue;
#if STP_WITH_SPECULAR
            if (s->specular) {
                el = wide_el(&we, &l);
                if (el < NEAR_OPPOSITE && we.ne < FAST_MIN_COS)
                    return s->exact(s, normal, *point); /* a light nearly opposite a grazing eye */
            }
#endif
            /* C + U = cu 2^-c in raw units with c = k + 2 >= 0 (k = j - s >=
             * -2), cu >= 4 len >= 2^32: C < 2^31 times 2^(k + 2) <= 2^32, plus
             * 4 len < 2^33 (wide_light_w's t takes the 2^2 back, exactly) */
            w = wide_light_w(s, j, ((uint64_t)s->wide_c << c) + (l.len << 2), &c);
            share = wide_light_share(s, &we, w, nl, c, el);
        } else
            share = wide_light_at_point(s, &we, j);
        if (share > 0) {
            acc += share;
            if (acc >= s->wide_acc_one) /* SUM_ONE - ambient */
                return ONE; /* every later share is >= 0 */
        }
    } while (++j < s->count);
    return shade_of_sum(s, acc != 0, s->ambient + acc);
}
#endif

#if STP_WIDE_ARITH
/* BRIGHT P_j for the host path (wide_prepare): b p (raw, each < 2^31:
 * below 2^62) = m 2^n, m in [2^23, 2^24) truncated: b p 2^-16 = m 2^-(16
 * - n), e = 16 - n in [-22, 39], kept as e + 26 (wide_light_w) */
static void wide_prepare_powers(stp_shade_fast *s, const stp_lighting *lighting)
{
    stp_fix bright = lighting->brightness;
    int j;
    for (j = 0; j < STP_MAX_LIGHTS; j++) {
        uint64_t bp = 0;
        int n;
        if (j < s->count && lighting->lights[j].power > 0 && bright > 0)
            bp = (uint64_t)(uint32_t)bright * (uint32_t)lighting->lights[j].power;
        n = bit_length64(bp) - 24;
        s->wide_power[j] = bp == 0 ? 0u : (n >= 0 ? bp >> n : bp << -n) << 36;
        s->wide_power_e[j] = (int8_t)(bp == 0 ? -38 : 42 - n);
    }
}

#if STP_WITH_SPECULAR
/* The highlight's terms for the host path (wide_prepare), after
 * prepare_specular */
static void wide_prepare_specular(stp_shade_fast *s, const stp_material *material)
{
    /* k in Q30 (< 2^45), shifted below 2^24 (truncated: relative error
     * below 2^-23) */
    uint64_t k = (uint64_t)(material->gloss < 1 ? 1u : (uint32_t)material->gloss) << 14;
    int r = bit_length64(k) - 24, j;
    r = r < 0 ? 0 : r;
    s->wide_ks = material->specular > 0 ? (uint32_t)material->specular : 0u;
    s->wide_gloss = (uint32_t)(k >> r);
    s->wide_gloss30 = (uint64_t)s->wide_gloss << 30;
    s->wide_gloss_r = (uint8_t)r;
    for (j = 0; j < STP_SHADE_FAST_FRESNEL_NODES; j++) /* the table, where prepare_specular made it */
        s->wide_fresnel_step[j] =
            s->refraction_ge_1 && j + 1 < STP_SHADE_FAST_FRESNEL_NODES ? (int32_t)s->fresnel[j + 1] - s->fresnel[j] : 0;
}
#endif

/* The host path's prepared fields (face_wide), after exact_prepare. */
static void wide_prepare(stp_shade_fast *s, const stp_lighting *lighting, const stp_material *material,
                         int parallel, stp_vec3 parallel_dir)
{
    stp_fix refl = material->reflectivity;
    if (parallel) {
        s->eye = parallel_dir;
        if (parallel_dir.x == 0 && parallel_dir.y == 0 && parallel_dir.z == 0)
            s->eye.z = -ONE;
    }
    /* the wide path's formats are written for F = 16 (its powers and
     * attenuation scale by 2^-16); other precisions take the 32-bit path,
     * tested at F = 12, 16 and 20 */
    s->wide_route = STP_FIX_FRAC_BITS != 16 ? STP_SHADE_WIDE_NARROW : (s->count == 0 ? STP_SHADE_WIDE_AMBIENT : STP_SHADE_WIDE_FAST);
#if STP_WITH_SPECULAR
    if (s->wide_route == STP_SHADE_WIDE_FAST && s->exact_always)
        s->wide_route = STP_SHADE_WIDE_EXACT;
    wide_prepare_specular(s, material);
#endif
    s->wide_c = lighting->attenuation_c > 0 ? (uint32_t)lighting->attenuation_c : 1u;
    s->wide_refl = refl < 0 ? 0u - (uint32_t)refl : (uint32_t)refl;
    s->wide_refl_sign = refl < 0 ? -1 : 1;
    s->wide_acc_one = SUM_ONE - s->ambient; /* prepare_ambient set ambient */
    wide_prepare_powers(s, lighting);
}
#endif

#if STP_WITH_SPECULAR
/* The exact route: stp_shade_unit (shade.c) with the prepared lighting and
 * material, the Q1.14 normal and E as STP_UNIT vectors.  Builds without the
 * highlight (STP_WITH_SPECULAR 0: the lean microcontroller configuration)
 * leave it out, and with it shade.c (about 1.7 KB on a Cortex-M0+, over
 * 5 KB on AVR): there it would serve only lights whose gain
 * BRIGHT P |R| / C exceeds FAST_MAX_GAIN, which keep the fast route's
 * error (not bounded by tests/shade_accuracy, which runs with the
 * highlight). */
static stp_fix face_exact(const stp_shade_fast *s, const int16_t normal[3], stp_vec3 point)
{
    stp_lighting lighting;
    stp_material material;
    stp_unit3 n, e;
    int j;
    (void)stp_unit_from64(normal[0], normal[1], normal[2], &n);
    if (s->parallel)
        (void)stp_unit_from64(s->x_dir.x, s->x_dir.y, s->x_dir.z, &e);
    else if (stp_unit_from64((int64_t)s->eye.x - point.x, (int64_t)s->eye.y - point.y,
                             (int64_t)s->eye.z - point.z, &e) == 0)
        return s->ambient_shade; /* the eye on the face */
    lighting.brightness = s->x_bright;
    lighting.background = s->x_background;
    lighting.attenuation_c = s->x_c;
    lighting.count = s->count;
    for (j = 0; j < s->count; j++) {
        lighting.lights[j].position = s->light[j];
        lighting.lights[j].power = s->x_power[j];
    }
    material.reflectivity = s->x_refl;
    material.refraction = s->x_refraction;
    material.gloss = s->x_gloss;
    material.specular = s->specular ? s->x_ks : 0;
    return stp_shade_unit(&lighting, &material, n, point, e, stp_unit_dot(n, e));
}

/* Where the fast route keeps its error within the bound (about 6e-4
 * measured, tests/shade_accuracy; the exact route everywhere else):
 *   the gain BRIGHT max_j P_j max(|R|, Ks)/C at most FAST_MAX_GAIN, so the
 *     directions' 2^-15 and the Q16/Q30 steps of F and D are not
 *     multiplied up by a bright light, a small C or a large power;
 *   with the highlight: k >= FAST_MIN_GLOSS (a sharp highlight moves by
 *     more than the scaled directions resolve), n >= FAST_MIN_REFRACTION
 *     (near 1 the Fresnel table's interpolation and Q16 steps lose F's
 *     relative precision) and, per face, N.E >= FAST_MIN_COS or, below
 *     it down to 1/64 of it (GRAZE_FLOOR), no light nearly opposite the
 *     eye (GRAZE_EXACT: there 1 + E.L's absolute error is relative to
 *     (N.E)^2). */
#define FAST_MAX_GAIN 16
#define FAST_MIN_GLOSS (ONE / 20)
#define FAST_MIN_REFRACTION (ONE + ONE / 4)
/* FAST_MIN_COS: at the top of the file (face_wide tests it) */

static int fast_keeps_bound(const stp_shade_fast *s, const stp_lighting *lighting, const stp_material *material)
{
    stp_fix r = material->reflectivity < 0 ? -material->reflectivity : material->reflectivity, p = 0;
    int64_t gain;
    int j;
    if (s->specular && (material->gloss < FAST_MIN_GLOSS || material->refraction < FAST_MIN_REFRACTION))
        return 0;
    if (s->specular && material->specular > r)
        r = material->specular;
    for (j = 0; j < s->count; j++)
        if (lighting->lights[j].power > p)
            p = lighting->lights[j].power;
    /* BRIGHT P (2F bits, < 2^62) to F bits, times max(|R|, Ks): F bits,
     * saturated at 2^62; C >= 1 raw unit */
    gain = stp_mul_shift_sat(stp_mul_shift_sat(lighting->brightness, p, F), r, F);
    return gain <= (int64_t)FAST_MAX_GAIN * (lighting->attenuation_c > 0 ? lighting->attenuation_c : 1);
}

/* The exact route's values, and where the fast route keeps the error bound */
static void exact_prepare(stp_shade_fast *s, const stp_lighting *lighting, const stp_material *material,
                          int parallel, stp_vec3 parallel_dir)
{
    int j;
    s->exact = face_exact;
    s->x_bright = lighting->brightness;
    s->x_background = lighting->background;
    s->x_c = lighting->attenuation_c;
    s->x_refl = material->reflectivity;
    s->x_refraction = material->refraction;
    s->x_gloss = material->gloss;
    s->x_ks = material->specular;
    for (j = 0; j < STP_MAX_LIGHTS; j++)
        s->x_power[j] = j < s->count ? lighting->lights[j].power : 0;
    s->x_dir = parallel_dir;
    if (parallel && parallel_dir.x == 0 && parallel_dir.y == 0 && parallel_dir.z == 0)
        s->x_dir.z = -ONE;
    s->exact_always = (uint8_t)!fast_keeps_bound(s, lighting, material);
    s->fast_min_cos = s->specular ? FAST_MIN_COS : 0;
}
#endif

/* The ambient-only shade (ambient_shade) and its Q26 term of the sums
 * (ambient) for background B in [0, 1], reflectivity R and BRIGHT (all F
 * bits), exactly as shade_unit forms them:
 *   ambient_shade = min(1, B R BRIGHT) rounded once to F bits (0 where
 *     B R <= 0 or BRIGHT <= 0);
 *   ambient = floor(floor(B R 2^(26 - 2F)) clamped to +-2^31, times BRIGHT
 *     2^-F) clamped to +-SHARE_CAP (0 where BRIGHT <= 0).
 * Only 32 x 32 -> 64-bit products of magnitudes (the C library's short
 * widening product where there is no such instruction), shifts and sums
 * below 2^63: B |R| < 2^(F + 31); a floor of a negative value is its
 * magnitude rounded up. */
/* v when the reflectivity is negative (neg 1), else 0: in builds for size
 * on 32-bit cores a mask of the flag, so the compiler keeps one path for
 * both signs (it copied the rest of prepare_ambient into each: lean direct
 * core 6 168 -> 6 134 B; on AVR the mask cost 96 bytes) */
#if defined(__OPTIMIZE_SIZE__) && STP_HAVE_MUL32
#define IF_NEG(neg, v) ((0u - (neg)) & (v))
#else
#define IF_NEG(neg, v) ((neg) ? (v) : 0u)
#endif

/* floor((x y + c) 2^-F) for 32-bit x and y and c < 2^32 (the sum below
 * 2^64): prepare_ambient's three products, one call in builds for size
 * (the lean direct core 34 B smaller), in line elsewhere */
#if defined(__GNUC__) && defined(__OPTIMIZE_SIZE__)
static __attribute__((noinline)) uint64_t mul_add_shr_f(uint32_t x, uint32_t y, uint64_t c)
#else
STP_HOT_INLINE uint64_t mul_add_shr_f(uint32_t x, uint32_t y, uint64_t c)
#endif
{
    return ((uint64_t)x * y + c) >> F;
}

static void prepare_ambient(stp_shade_fast *s, stp_fix background, stp_fix refl, stp_fix bright)
{
    uint32_t r = refl < 0 ? 0u - (uint32_t)refl : (uint32_t)refl, neg = refl < 0;
    uint64_t a, m;
    s->ambient_shade = 0;
    s->ambient = 0;
    if (bright <= 0)
        return;
    a = (uint64_t)(uint32_t)background * r;
    if (refl > 0) {
        /* B R = t 2^F + l (t < 2^31, l < 2^F): B R BRIGHT 2^-2F rounded is
         * floor((t BRIGHT + floor(l BRIGHT 2^-F) + 2^(F - 1)) 2^-F), the
         * sum below 2^62 + 2^32; floor(l BRIGHT 2^-F) + 2^(F - 1) below
         * 2^31 + 2^15 */
        uint64_t t = mul_add_shr_f((uint32_t)(a >> F), (uint32_t)bright,
                                   mul_add_shr_f((uint32_t)a & (uint32_t)(ONE - 1), (uint32_t)bright, 0) +
                                       ((uint32_t)1 << (F - 1)));
        s->ambient_shade = t >= (uint64_t)ONE ? ONE : (stp_fix)t;
    }
#if 2 * STP_FIX_FRAC_BITS >= SUM_BITS
    m = (a + IF_NEG(neg, ((uint32_t)1 << (2 * F - SUM_BITS)) - 1u)) >> (2 * F - SUM_BITS);
#else
    m = a << (SUM_BITS - 2 * F);
#endif
    if (m > 0x80000000u)
        m = 0x80000000u;
    /* m BRIGHT < 2^62 */
    m = mul_add_shr_f((uint32_t)m, (uint32_t)bright, IF_NEG(neg, (uint32_t)(ONE - 1)));
    if (m > SHARE_CAP)
        m = SHARE_CAP;
    s->ambient = neg ? -(int32_t)m : (int32_t)m;
}

/* Each of the s->count lights' position and its BRIGHT P_j |R| (and
 * BRIGHT P_j Ks) per raw unit of C + U; the other entries 0. */
static void prepare_lights(stp_shade_fast *s, const stp_lighting *lighting, const stp_material *material)
{
    stp_fix refl = material->reflectivity, bright = lighting->brightness;
    stp_sf16 bright_sf = sf_make(bright > 0 ? (uint32_t)bright : 0u, F);
    stp_sf16 refl_sf = sf_make(refl < 0 ? 0u - (uint32_t)refl : (uint32_t)refl, F);
#if STP_WITH_SPECULAR
    stp_sf16 ks_sf = sf_make(material->specular > 0 ? (uint32_t)material->specular : 0u, F);
#endif
    int j;
    for (j = 0; j < STP_MAX_LIGHTS; j++) {
        const stp_light *light = &lighting->lights[j];
        stp_sf16 p;
        if (j >= s->count) { /* unused: zero, so every field is set */
            s->light[j].x = s->light[j].y = s->light[j].z = 0;
            s->light_big[j] = 0;
            s->power_refl[j].m = 0;
            s->power_refl[j].e = 0;
#if STP_WITH_SPECULAR
            s->power_ks[j] = s->power_refl[j];
#endif
            continue;
        }
        p = sf_make(light->power > 0 ? (uint32_t)light->power : 0u, F);
        s->light[j] = light->position;
        s->light_big[j] = (uint8_t)is_big(light->position);
        p = sf_mul(bright_sf, p);
        p.e -= F; /* per raw unit of C + U */
        s->power_refl[j] = sf_mul(p, refl_sf);
#if STP_WITH_SPECULAR
        s->power_ks[j] = sf_mul(p, ks_sf);
#endif
    }
}

#if STP_WITH_SPECULAR
/* The highlight's material terms: 1/k, the refractive index n and 1/n^2
 * (or n^2 below 1), and the Fresnel table. */
static void prepare_specular(stp_shade_fast *s, const stp_material *material)
{
    stp_fix n = material->refraction <= 0 ? 1 : material->refraction;
    int j;
    s->specular = (uint8_t)(material->specular > 0);
    s->inv_gloss = sf_recip(sf_make(material->gloss < 1 ? 1u : (uint32_t)material->gloss, F));
    s->inv_gloss_q16 = sf_to_fixed(s->inv_gloss, 15, 0x7FFFFFFFu) << 1; /* below 2^32 */
    s->refraction = sf_make((uint32_t)n, F);
    s->refraction_ge_1 = (uint8_t)(n >= ONE);
    s->inv_n2 = 0;
    s->n2 = 0;
    if (s->refraction_ge_1)
        s->inv_n2 = sf_to_fixed(sf_recip(sf_mul(s->refraction, s->refraction)), 31, 0x80000000u - 1u);
    else
        s->n2 = (uint32_t)(2 * F >= 30 ? ((int64_t)n * n) >> (2 * F - 30)
                                       : ((int64_t)n * n) << (30 - 2 * F)); /* n < 1: < 2^30 */
    if (!s->refraction_ge_1)
        return;
    /* the Fresnel table: exact F at its nodes (about 570 instructions
     * each on ARMv6-M: the reason prepare is meant to be cached) */
    for (j = 0; j < STP_SHADE_FAST_FRESNEL_NODES; j++) {
        uint32_t c = FRESNEL_C0 + ((uint32_t)j << 24); /* <= 2^30 */
        uint32_t u = (uint32_t)Q30 - (stp_umulhi32x32(c << 1, c << 1)); /* 1 - c^2 in Q30 */
        s->fresnel[j] = (uint16_t)sf_to_fixed(fresnel_sf(s, c, u), 16, 0xFFFFu);
    }
}
#endif

/* prepare's fields before the view's direction: the counts and flags, the
 * ambient terms, the eye */
STP_HOT_INLINE void prepare_head(stp_shade_fast *s, const stp_lighting *lighting, const stp_material *material,
                                 const stp_vec3 *eye, int parallel)
{
    stp_fix bright = lighting->brightness;
    int count = lighting->count < 0 ? 0 : (lighting->count > STP_MAX_LIGHTS ? STP_MAX_LIGHTS : lighting->count);
    if (bright <= 0)
        count = 0;
    s->count = (uint8_t)count;
    s->parallel = (uint8_t)(parallel != 0);
    s->refl_negative = (uint8_t)(material->reflectivity < 0);
    s->attenuation_c = sf_make(lighting->attenuation_c > 0 ? (uint32_t)lighting->attenuation_c : 1u, 0);
    prepare_ambient(s, stp_fix_clamp(lighting->background, 0, ONE), material->reflectivity, bright);
    s->eye = *eye;
    s->eye_big = (uint8_t)is_big(*eye);
}

#if STP_SHADE_PREPARE_EYE_BODY
/* the perspective prepare alone (shade_fast_private.h) */
void stp_shade_fast_prepare_eye(stp_shade_fast *s, const stp_lighting *lighting, const stp_material *material,
                                stp_vec3 eye)
{
    prepare_head(s, lighting, material, &eye, 0);
    prepare_lights(s, lighting, material);
    s->specular = 0;
}
#endif

void stp_shade_fast_prepare(stp_shade_fast *s, const stp_lighting *lighting,
                            const stp_material *material, stp_vec3 eye, int parallel,
                            stp_vec3 parallel_dir)
{
    prepare_head(s, lighting, material, &eye, parallel);
    if (parallel) {
        stp_vec3 zero = {0, 0, 0};
        if (!dir_make(&s->e, &parallel_dir, &zero, is_big(parallel_dir), 1)) {
            stp_vec3 back = {0, 0, -ONE};
            (void)dir_make(&s->e, &back, &zero, 0, 1);
        }
    }
    prepare_lights(s, lighting, material);
#if STP_WITH_SPECULAR
    prepare_specular(s, material);
#else
    s->specular = 0;
#endif
#if STP_WITH_SPECULAR
    exact_prepare(s, lighting, material, parallel, parallel_dir);
#endif
#if STP_WIDE_ARITH
    wide_prepare(s, lighting, material, parallel, parallel_dir); /* after exact_always */
#endif
}


/* |N|^2 - 1 in Q28 (each n_i^2 <= 2^30, so the sum fits unsigned),
 * clamped to +-2^17. */
STP_HOT_INLINE int32_t normal_deviation(const int16_t normal[3])
{
    uint32_t nn = 0;
    int i;
    STP_UNROLL3
    for (i = 0; i < 3; i++)
        nn += (uint32_t)((int32_t)normal[i] * normal[i]);
#if !defined(__OPTIMIZE_SIZE__)
    /* one test (a shift's) for the common case, nn within 2^17 of 2^28
     * (2^28 + 2^17 itself on either branch) */
    if (HOT_UNLIKELY(STP_AT_LEAST_POW2(nn - 0x0FFE0000u, 18)))
        return nn >= 0x10020000u ? 0x20000 : -0x20000;
    return (int32_t)(nn - 0x10000000u);
#else
    return nn > 0x10020000u ? 0x20000 : (nn < 0x0FFE0000u ? -0x20000 : (int32_t)(nn - 0x10000000u));
#endif
}

#if STP_WITH_SPECULAR
/* N.E (Q30) below GRAZE_FLOOR, where the face takes the exact route (none
 * in a struct filled by hand, which has no exact route) */
STP_HOT_INLINE int below_floor(const stp_shade_fast *s, int32_t n_dot_e)
{
    return n_dot_e < GRAZE_FLOOR(s) && s->exact;
}
#endif

#if defined(__GNUC__)
#define STP_FACE_BODY static inline __attribute__((always_inline))
#else
#define STP_FACE_BODY static inline
#endif

/* Light j's share of the shade in Q26 (stp_shade_fast_face): BRIGHT P_j
 * |R| (N.L)/(C + U), signed as R, plus the highlight; 0 when the light is
 * behind the face.  nd: normal_deviation; e the eye's direction, n_dot_e
 * N.E (Q30), inv_ne 1/(N.E) and inv_ne_q26 the same in Q26; GRAZE_EXACT
 * (the face's exact route) for a light nearly opposite a grazing eye. */
STP_FACE_BODY int32_t light_share(const stp_shade_fast *s, int j, const int16_t normal[3], const stp_vec3 *point,
                                   int point_big, int near, int32_t nd, const stp_shade_fast_dir *e, int32_t n_dot_e,
                                   stp_sf16 inv_ne, uint32_t inv_ne_q26)
{
    stp_shade_fast_dir l;
    int32_t n_dot_l, share;
    stp_sf16 w;
    /* near: the near face (face_body), where no light is big */
    int at_point = !dir_make(&l, &s->light[j], point, near ? 0 : s->light_big[j] | point_big, 1);
    if (!at_point) {
        n_dot_l = dot_n(normal, &l);
        if (n_dot_l <= 0)
            return 0; /* the light behind the face, or in its plane */
        n_dot_l = cos_n(n_dot_l, &l, nd);
        if (n_dot_l <= 0)
            return 0;
        /* C >= 1 raw unit and |L| > 0: neither mantissa is 0 */
        w = sf_recip_hot(sf_add_in(s->attenuation_c, dir_length(&l), 1));
    } else {
        n_dot_l = Q30; /* the light on the face: lit head-on (L = N), U = 0 */
        w = sf_recip(s->attenuation_c);
    }
    share = share_times((uint32_t)n_dot_l, 30, sf_mul(w, s->power_refl[j]));
    if (s->refl_negative)
        share = -share;
#if STP_WITH_SPECULAR
    if (!near && s->specular) { /* near: no highlight (and no call left to it there) */
        int32_t e_dot_l = at_point ? n_dot_e : cos_dirs(e, &l);
        int32_t highlight = specular_share(s, n_dot_l, n_dot_e, e_dot_l, inv_ne, inv_ne_q26, sf_mul(w, s->power_ks[j]));
        if (highlight < 0)
            return GRAZE_EXACT;
        share += highlight;
    }
#else
    (void)e;
    (void)n_dot_e;
    (void)inv_ne;
    (void)inv_ne_q26;
#endif
    return share;
}

#if STP_SHADE_COMPACT
/* ---- the compact route (STP_SHADE_COMPACT, include/stipple/config.h) ----
 * A face without the highlight, in 16-bit directions:
 *   w      a - b scaled by 2^-n (floor), the largest |w_i| in [2^14, 2^15]:
 *          int16; halved first when either point is big (as dir_make)
 *   q      sum of w_i^2 <= 3 2^30 (uint32); |w| = floor(sqrt(q)) in
 *          [2^14, 2^15 sqrt(3)) (stp_isqrt32)
 *   N.w    int32: |N.w| <= |N||w| < 2^14 (1 + 2^-13) 2^15.8 < 2^29.8
 *   cosine N.L in Q16 as floor(4 N.w / |w|) (4 N.w < 2^32), |N| taken as
 *          1, at most 2^16 (|N| may exceed 1 by 2^-13)
 *   U      |w| 2^n raw units, then S = C + U in stp_sf16 as the main route
 *   share  cos BRIGHT P_j |R| / S in Q26 from one quotient:
 *          floor(cos_q16 P.m / S.m) (cos_q16 P.m <= 2^16 (2^16 - 1) <
 *          2^32; the quotient below 2^17) times 2^(10 + S.e - P.e),
 *          saturated (share_of): no reciprocal, no product of two
 *          stp_sf16
 * Errors: w's truncation turns the direction by at most sqrt(3) 2^-14
 * radian, the root and the cosine's floor add 2^-14 and 2^-16, |N| = 1 +-
 * 2^-13 a relative 2^-13, the quotient's floor 2^-15 of the share at a
 * cosine of 1: the shade's error is about 2.5e-4 times the gain
 * BRIGHT P_j |R| / (C + U) where that exceeds 1, tested in
 * tests/shade_fast (test_shade_fast_compact). */
#define NO_DIR (-128)

/* w = (a - b) 2^-n as above; returns n (with the halving: the raw length
 * is |w| 2^n), NO_DIR when a = b.  Each difference is formed twice (no
 * copy of the vector kept across the bit count). */
static int compact_dir(int16_t w[3], const stp_vec3 *a, const stp_vec3 *b, int big)
{
    uint32_t any = 0;
    int i, n;
    for (i = 0; i < 3; i++)
        any |= stp_abs32(diff_comp(a, b, i, big));
    if (any == 0)
        return NO_DIR;
    n = stp_bit_length32(any) - 15; /* |v_i| < 2^(15 + n) */
    for (i = 0; i < 3; i++) {
        int32_t v = diff_comp(a, b, i, big);
        w[i] = (int16_t)(n > 0 ? stp_asr32(v, n) : (int32_t)((uint32_t)v << -n));
    }
    return n + big;
}

/* The sum of a_i b_i modulo 2^32 (each product below 2^30 in
 * magnitude): N.w as int32 (|N.w| < 2^29.8) and |w|^2 as uint32 (below
 * 3 2^30).  One copy for both (STP_SIZE_CALL). */
STP_SIZE_CALL uint32_t compact_dot(const int16_t a[3], const int16_t b[3])
{
    uint32_t sum = 0;
    int i;
    STP_UNROLL3
    for (i = 0; i < 3; i++)
        sum += (uint32_t)((int32_t)a[i] * b[i]);
    return sum;
}

/* Light j's diffuse share in Q26, as light_share's: 0 behind the face
 * (near: face_body's, no point big) */
static int32_t compact_share(const stp_shade_fast *s, int j, const int16_t normal[3], stp_vec3 point,
                             int point_big, int near)
{
    int16_t w[3];
    uint32_t cos_q16, len;
    int32_t share;
    stp_sf16 u, sum; /* U, C + U */
    int n = compact_dir(w, &s->light[j], &point, near ? 0 : s->light_big[j] | point_big);
    if (n != NO_DIR) {
        int32_t dot = (int32_t)compact_dot(normal, w);
        if (dot <= 0)
            return 0;
        len = stp_isqrt32(compact_dot(w, w));
        cos_q16 = ((uint32_t)dot << 2) / len;
        if (cos_q16 > (uint32_t)1 << 16)
            cos_q16 = (uint32_t)1 << 16;
        u.m = len < 0x8000u ? len << 1 : len; /* |w| in [2^14, 2^16): at most one shift */
        u.e = len < 0x8000u ? 1 - n : -n;
        sum = sf_add(s->attenuation_c, u);
    } else {
        cos_q16 = (uint32_t)1 << 16; /* the light on the face: lit head-on, U = 0 */
        sum = s->attenuation_c;
    }
    share = share_of(cos_q16 * s->power_refl[j].m / sum.m, 10 + sum.e - s->power_refl[j].e);
    return s->refl_negative ? -share : share;
}

/* The face on the compact route (face_body's, without the highlight) */
STP_FACE_BODY stp_fix face_compact(const stp_shade_fast *s, const int16_t normal[3], stp_vec3 point,
                                   int point_big, int near)
{
    int32_t sum = s->ambient;
    int j, lit = 0;
    if (s->count == 0)
        return s->ambient_shade;
    if (!near && s->parallel) { /* near: perspective (stp_shade_fast_face_near) */
        if (dot_n(normal, &s->e) <= 0)
            return s->ambient_shade;
    } else {
        int16_t w[3];
        if (compact_dir(w, &s->eye, &point, near ? 0 : s->eye_big | point_big) == NO_DIR ||
            (int32_t)compact_dot(normal, w) <= 0)
            return s->ambient_shade; /* a back face, edge-on, or the eye on it */
    }
    for (j = 0; j < s->count; j++) {
        int32_t share = compact_share(s, j, normal, point, point_big, near);
        if (share > 0) {
            lit = 1;
            sum += share;
            if (sum >= SUM_ONE)
                return ONE;
        }
    }
    return shade_of_sum(s, lit, sum);
}

/* The faces the compact route shades: every face without the highlight */
#define FACE_COMPACT(s) (!STP_WITH_SPECULAR || !(s)->specular)
#endif

/* The 32-bit targets' face, for both entries: near 1 (point_big 0) for
 * stp_shade_fast_face_near (perspective, no highlight, the eye, the
 * lights and the point within [-2^30, 2^30): the tests below that only
 * those exclude are left out, constant), near 0 and is_big(point) for
 * stp_shade_fast_face: the same integers where both apply.  Inlined into
 * each entry with its helpers (STP_FACE_BODY in every build: called from
 * both, they would otherwise stay calls), so each entry is the one
 * function it was, and a program that calls one links one (sections
 * collected). */
#if STP_WITH_SPECULAR
/* The lighting or the material outside the fast route's range: every
 * lit face takes the exact route (each entry's first test) */
#define FACE_EXACT_ALWAYS(s) ((s)->exact_always && (s)->exact && (s)->count != 0)
#endif
STP_FACE_BODY stp_fix face_body(const stp_shade_fast *s, const int16_t normal[3], const stp_vec3 *point, int point_big,
                                int near)
{
    stp_shade_fast_dir e_local;
    const stp_shade_fast_dir *e = &s->e;
    int32_t nd, dot_e = 0, sum = s->ambient;
    int j;
    int32_t n_dot_e = 0;
    stp_sf16 inv_ne = {0, 0};
    uint32_t inv_ne_q26 = 0;
#if STP_SHADE_COMPACT
    if (FACE_COMPACT(s))
        return face_compact(s, normal, *point, point_big, near);
#endif
    if (s->count == 0)
        return s->ambient_shade;
    /* does the face face the eye?  e: the direction towards it (e_local
     * made here, or the parallel view's); dot_e = N.E where the highlight
     * or a big or parallel eye needs it (kept in this function: as a
     * helper writing through pointers it cost an AVR image 510 B) */
    if (near || (!s->parallel && !s->specular && !(s->eye_big | point_big))) {
        if (!faces_point(normal, &s->eye, point)) /* diffuse only: E matters only through N.E's sign */
            return s->ambient_shade;
    } else {
        if (!s->parallel) {
            if (!dir_make(&e_local, &s->eye, point, s->eye_big | point_big, EYE_NEEDS_R(s)))
                return s->ambient_shade; /* the eye on the face */
            e = &e_local;
        }
        dot_e = dot_n(normal, e);
        if (HOT_UNLIKELY(dot_e <= 0))
            return s->ambient_shade; /* a back face, or edge-on */
    }
    nd = normal_deviation(normal);
#if STP_WITH_SPECULAR
    if (!near && s->specular) {
        n_dot_e = cos_n(dot_e, e, nd);
        if (n_dot_e <= 0)
            return s->ambient_shade;
        if (below_floor(s, n_dot_e))
            return s->exact(s, normal, *point);
        inv_ne = recip_cos((uint32_t)n_dot_e, &inv_ne_q26);
    }
#endif
    for (j = 0; j < s->count; j++) {
        int32_t share = light_share(s, j, normal, point, point_big, near, nd, e, n_dot_e, inv_ne, inv_ne_q26);
        if (!HOT_UNLIKELY(share <= 0)) {
            sum += share; /* GRAZE_EXACT too: at most 2^29 + 2^30 + 1 */
            if (HOT_UNLIKELY(sum >= SUM_ONE)) {
#if STP_WITH_SPECULAR
                if (!near && share == GRAZE_EXACT) /* near: no highlight */
                    return s->exact(s, normal, *point);
#endif
                return ONE; /* every later share is >= 0 */
            }
        }
    }
    /* a light reached the face iff its share moved the sum (each share
     * added is > 0, and the sum stays below 2^31) */
    return shade_of_sum(s, sum != s->ambient, sum);
}

/* The 32-bit targets' entries; on a host (kept compiled there: its
 * helpers serve prepare and the Fresnel) a function of its own for a
 * struct that prepare did not fill, so that the wide route's calls do not
 * set up its registers and stack. */
#if STP_WIDE_ARITH
STP_NOINLINE stp_fix face_narrow(const stp_shade_fast *s, const int16_t normal[3], stp_vec3 point)
#else
stp_fix stp_shade_fast_face(const stp_shade_fast *s, const int16_t normal[3], stp_vec3 point)
#endif
{
#if STP_WITH_SPECULAR
    if (FACE_EXACT_ALWAYS(s))
        return s->exact(s, normal, point);
#endif
#if defined(__OPTIMIZE_SIZE__)
    {
        /* builds for size: the face on a copy of the point (without it,
         * ARMv6-M -Os took 1 283 instructions a face, not 1 240) */
        stp_vec3 at = point;
        return face_body(s, normal, &at, is_big(point), 0);
    }
#else
    return face_body(s, normal, &point, is_big(point), 0);
#endif
}

#if !STP_WIDE_ARITH
stp_fix stp_shade_fast_face_near(const stp_shade_fast *s, const int16_t normal[3], stp_vec3 point)
{
#if STP_WITH_SPECULAR
    if (FACE_EXACT_ALWAYS(s))
        return s->exact(s, normal, point);
#endif
    return face_body(s, normal, &point, 0, 1);
}
#endif

#if STP_WIDE_ARITH
stp_fix stp_shade_fast_face(const stp_shade_fast *s, const int16_t normal[3], stp_vec3 point)
{
#if STP_SHADE_COMPACT
    if (FACE_COMPACT(s))
        return face_narrow(s, normal, point); /* the compact route, on the 32-bit path's fields */
#endif
    if (s->wide_route == STP_SHADE_WIDE_FAST)
        return face_wide(s, normal, &point); /* the host path */
    if (s->wide_route == STP_SHADE_WIDE_NARROW)
        return face_narrow(s, normal, point);
#if STP_WITH_SPECULAR
    if (s->wide_route == STP_SHADE_WIDE_EXACT)
        return s->exact(s, normal, point);
#endif
    return s->ambient_shade; /* STP_SHADE_WIDE_AMBIENT: no light */
}
#endif
