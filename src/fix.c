/* SPDX-License-Identifier: MIT */
/* Fixed-point arithmetic: see include/stipple/fix.h for formats and errors. */
#include "stipple/fix.h"
#include "fix_private.h"
#include "div64_private.h" /* STP_DIV64 */

#define F STP_FIX_FRAC_BITS

stp_fix stp_fix_from_int(int32_t n)
{
    return stp_fix_sat64((int64_t)n * STP_FIX_ONE);
}

stp_fix stp_fix_from_ratio(int32_t num, int32_t den)
{
    int64_t n, q;
    if (den == 0)
        return num > 0 ? STP_FIX_MAX : (num < 0 ? STP_FIX_MIN : 0);
    n = (int64_t)num * STP_FIX_ONE;
    if (den < 0) {
        n = -n;
        den = -den;
    }
    /* round half away from zero */
    q = (n >= 0 ? n + den / 2 : n - den / 2) / den;
    return stp_fix_sat64(q);
}

stp_fix stp_fix_add(stp_fix a, stp_fix b)
{
    return stp_fix_sat64((int64_t)a + b);
}

stp_fix stp_fix_sub(stp_fix a, stp_fix b)
{
    return stp_fix_sat64((int64_t)a - b);
}

stp_fix stp_fix_mul(stp_fix a, stp_fix b)
{
    int64_t p = (int64_t)a * b; /* |p| < 2^62: cannot overflow */
    int64_t half = (int64_t)1 << (F - 1);
    /* divide rather than shift so negative values round symmetrically */
    p = (p >= 0 ? p + half : p - half) / ((int64_t)1 << F);
    return stp_fix_sat64(p);
}

stp_fix stp_fix_div(stp_fix a, stp_fix b)
{
    if (b == 0)
        return a > 0 ? STP_FIX_MAX : (a < 0 ? STP_FIX_MIN : 0);
    /* |a| * 2^F < 2^55: the shifted numerator fits in 64 bits */
    return stp_fix_sat64(((int64_t)a * STP_FIX_ONE) / b);
}

uint16_t stp_isqrt32(uint32_t v)
{
    /* as stp_isqrt64 below, in 32-bit words: 16 steps */
    uint32_t root = 0, bit = (uint32_t)1 << 30;
    while (bit > v)
        bit >>= 2;
    while (bit != 0) {
        if (v >= root + bit) {
            v -= root + bit;
            root = (root >> 1) + bit;
        } else {
            root >>= 1;
        }
        bit >>= 2;
    }
    return (uint16_t)root;
}

uint32_t stp_isqrt64(uint64_t v)
{
    /* Digit-by-digit (restoring) square root: exact floor, 32 steps, only
     * shifts, adds and compares, so it costs the same on every core. */
    uint64_t root = 0, bit = (uint64_t)1 << 62;
    if (v <= 0xFFFFFFFFu)
        return stp_isqrt32((uint32_t)v);
    while (bit > v)
        bit >>= 2;
    while (bit != 0) {
        if (v >= root + bit) {
            v -= root + bit;
            root = (root >> 1) + bit;
        } else {
            root >>= 1;
        }
        bit >>= 2;
    }
    return (uint32_t)root;
}

#if STP_SQRT_FAST
/* the reciprocal square root's root (stp_sqrt64_fast, below): within
 * 2^-29 relative, a few multiplications instead of a 32-step loop */
#define ROOT64(v) stp_sqrt64_fast(v)
#else
#define ROOT64(v) stp_isqrt64(v)
#endif

stp_fix stp_fix_sqrt(stp_fix a)
{
    if (a <= 0)
        return 0;
    /* sqrt(a * 2^F) has F fractional bits: a*2^F < 2^55 */
    return (stp_fix)ROOT64((uint64_t)a << F);
}

stp_fix stp_fix_sqrt_wide(int64_t v)
{
    uint32_t root;
    if (v <= 0)
        return 0;
    root = ROOT64((uint64_t)v);
    return root > (uint32_t)STP_FIX_MAX ? STP_FIX_MAX : (stp_fix)root;
}

stp_fix stp_fix_log2(stp_fix a)
{
    /* Integer part from the position of the top bit; fraction by repeated
     * squaring of the mantissa in [1, 2) (one result bit per square). */
    int32_t ip = 0;
    uint64_t m;
    int i;
    int64_t result;
    if (a <= 0)
        return STP_FIX_MIN;
    /* a = m 2^(top - F) with m in [1, 2): normalise m straight to Q30 by a
     * left shift (a < 2^31, so top <= 30 and no bit of a is lost; shifting
     * right to F fractional bits first would cost up to 1.5 LSB) */
    m = (uint64_t)a;
    while ((m >> ip) > 1)
        ip++;
    m <<= (30 - ip);
    ip -= F;
    result = (int64_t)ip * STP_FIX_ONE;
    for (i = F - 1; i >= 0; i--) {
        m = (m * m) >> 30;
        if (m >= ((uint64_t)2 << 30)) {
            m >>= 1;
            result += (int64_t)1 << i;
        }
    }
    return stp_fix_sat64(result);
}

stp_fix stp_fix_exp2(stp_fix a)
{
    /* 2^a = 2^ip * 2^frac; 2^frac from the product of 2^(2^-i) for the set
     * bits of frac (table of 2^(2^-i) in Q2.30). */
    static const uint32_t pow2_inv[24] = {
        1518500250u, 1276901417u, 1170923762u, 1121280436u, 1097253708u, 1085434106u,
        1079572136u, 1076653033u, 1075196443u, 1074468888u, 1074105294u, 1073923544u,
        1073832680u, 1073787251u, 1073764537u, 1073753181u, 1073747502u, 1073744663u,
        1073743244u, 1073742534u, 1073742179u, 1073742001u, 1073741913u, 1073741868u};
    int32_t ip = (int32_t)stp_asr64(a, F); /* floor */
    uint32_t frac = (uint32_t)(a - (stp_fix)((uint32_t)ip << F));
    uint64_t r = (uint64_t)1 << 30; /* Q2.30 */
    int i;
    /* ip in [-2^(31-F), 2^(31-F)): shift results below fit the checks */
    if (ip < -(int32_t)(F + 31))
        return 0;
    for (i = 0; i < F; i++) {
        if (frac & ((uint32_t)1 << (F - 1 - i)))
            r = (r * pow2_inv[i] + ((uint64_t)1 << 29)) >> 30;
    }
    /* r in [1, 2) Q30; result = r * 2^ip with F fractional bits */
    {
        int32_t shift = ip + F - 30; /* r * 2^(ip) in Q(F) = r >> (30 - F - ip) */
        if (shift >= 0) {
            if (shift > 31 || (r << shift) > (uint64_t)STP_FIX_MAX)
                return STP_FIX_MAX;
            return (stp_fix)(r << shift);
        }
        if (-shift >= 63)
            return 0;
        return (stp_fix)((r + ((uint64_t)1 << (-shift - 1))) >> (-shift));
    }
}

stp_fix stp_fix_pow(stp_fix base, stp_fix e)
{
    stp_fix lg;
    if (base <= 0)
        return 0;
    lg = stp_fix_log2(base);
    return stp_fix_exp2(stp_fix_mul(lg, e));
}

/* sin(x) for x in [0, 90] degrees: odd polynomial in the angle in
 * quarter-turns, Q30 coefficients of a least-squares fit (error < 2e-6). */
static int64_t sin_quadrant_q30(int64_t t_q30)
{
    /* sin(pi/2 * t) = t*(c1 + t^2*(c3 + t^2*(c5 + t^2*c7))) for t in [0,1] */
    const int64_t c1 = 1686625467;  /* 1.5707924 */
    const int64_t c3 = -693536212;  /* -0.6459059 */
    const int64_t c5 = 85324513;    /* 0.0794647 */
    const int64_t c7 = -4673628;    /* -0.0043527 */
    int64_t t2 = (t_q30 * t_q30) >> 30;
    int64_t p = c7;
    p = c5 + stp_asr64(p * t2, 30);
    p = c3 + stp_asr64(p * t2, 30);
    p = c1 + stp_asr64(p * t2, 30);
    return stp_asr64(p * t_q30, 30);
}

/* sin of an angle in degrees given in 64 bits (so cos can add 90 degrees
 * to any stp_fix without saturating). */
static stp_fix sin_deg64(int64_t degrees)
{
    /* reduce to [0, 360) in Q(F) then to a quadrant */
    int64_t full = (int64_t)360 << F;
    int64_t d = degrees % full;
    int64_t quarter = (int64_t)90 << F;
    int64_t t_q30, s;
    int quadrant, neg = 0;
    if (d < 0)
        d += full;
    quadrant = (int)(d / quarter);
    d -= quadrant * quarter;
    if (quadrant & 1)
        d = quarter - d;
    if (quadrant >= 2)
        neg = 1;
    t_q30 = (d << 30) / quarter;
    s = stp_asr64(sin_quadrant_q30(t_q30), 30 - F);
    return (stp_fix)(neg ? -s : s);
}

stp_fix stp_fix_sin_deg(stp_fix degrees)
{
    return sin_deg64(degrees);
}

stp_fix stp_fix_cos_deg(stp_fix degrees)
{
    /* not stp_fix_add: within 90 degrees of STP_FIX_MAX it would saturate */
    return sin_deg64((int64_t)degrees + ((int64_t)90 << F));
}

stp_fix stp_vec3_dot(stp_vec3 a, stp_vec3 b)
{
    /* each product < 2^62 in magnitude; three of them < 2^63.6 could
     * overflow, so sum two at a time with a halved scale */
    int64_t s = ((int64_t)a.x * b.x) / 2 + ((int64_t)a.y * b.y) / 2 + ((int64_t)a.z * b.z) / 2;
    int64_t half = (int64_t)1 << (F - 2);
    s = (s >= 0 ? s + half : s - half) / ((int64_t)1 << (F - 1));
    return stp_fix_sat64(s);
}

static uint32_t abs32(int32_t v)
{
    return v < 0 ? (uint32_t)0 - (uint32_t)v : (uint32_t)v;
}

stp_fix stp_vec3_unity(stp_vec3 v, stp_vec3 *out)
{
    uint32_t m = abs32(v.x);
    int64_t x, y, z, len_scaled;
    uint64_t sum;
    int up = 0;
    if (abs32(v.y) > m)
        m = abs32(v.y);
    if (abs32(v.z) > m)
        m = abs32(v.z);
    out->x = out->y = out->z = 0;
    if (m == 0)
        return 0;
    /* scale so the largest component is in [2^29, 2^30): the squares' sum
     * < 3 * 2^60 fits, and the direction keeps ~30 bits whatever |v| is */
    while ((m << up) < ((uint32_t)1 << 29))
        up++;
    x = (int64_t)v.x * ((int64_t)1 << up);
    y = (int64_t)v.y * ((int64_t)1 << up);
    z = (int64_t)v.z * ((int64_t)1 << up);
    if (m >= ((uint32_t)1 << 30)) { /* up == 0 and m up to 2^31: scale down */
        x /= 2;
        y /= 2;
        z /= 2;
        up = -1;
    }
    sum = (uint64_t)(x * x) + (uint64_t)(y * y) + (uint64_t)(z * z);
    len_scaled = (int64_t)ROOT64(sum);
    if (len_scaled == 0)
        return 0;
    /* C's truncating quotients (with STP_SMALL_DIVISION div64.c's loop,
     * the same quotients, not the C library's 64-bit division) */
    out->x = (stp_fix)STP_DIV64(x * STP_FIX_ONE, len_scaled);
    out->y = (stp_fix)STP_DIV64(y * STP_FIX_ONE, len_scaled);
    out->z = (stp_fix)STP_DIV64(z * STP_FIX_ONE, len_scaled);
    /* |v| = len_scaled / 2^up */
    if (up >= 0)
        return (stp_fix)(len_scaled >> up);
    return stp_fix_sat64(len_scaled * 2);
}

/* ---- STP_UNIT vectors (fix_private.h) ---- */

/* fix_private.h's stp_rsqrt_norm_inline, out of line (never inlined into
 * RSQRT_SEED: builds for size would then keep a static copy beside this) */
#if defined(__GNUC__)
__attribute__((noinline))
#endif
uint32_t stp_rsqrt_norm(uint32_t q)
{
    return stp_rsqrt_norm_inline(q);
}

/* 1/sqrt(i/64 + 1 + 1/128) in Q16 for i = 0..191, rounded to nearest:
 * the root at the middle of each 64th of [1, 4) (relative error of a seed
 * below 2^-8).  In builds for size on cores with a 32-bit multiply the
 * same values from stp_rsqrt_norm at that middle, (2 (m >> 24) + 1) 2^23:
 * 2^31 / sqrt of it, within 2^-7 of a unit and never that near a half
 * (all 192 checked, test_fix), instead of 384 bytes of table. */
#if defined(__OPTIMIZE_SIZE__) && STP_HAVE_MUL32
#define RSQRT_SEED(m) ((stp_rsqrt_norm(((m) & 0xFF000000u) | 0x800000u) + 0x4000u) >> 15)
#else
#define RSQRT_SEED(m) STP_TABLE_U16(&rsqrt_seed[((m) >> 24) - 64])
static const uint16_t rsqrt_seed[192] STP_TABLE = {
    65281, 64781, 64292, 63814, 63347, 62889, 62442, 62004, 61575, 61154, 60742, 60339,
    59943, 59555, 59175, 58801, 58435, 58075, 57722, 57376, 57035, 56700, 56372, 56049,
    55731, 55419, 55112, 54810, 54513, 54221, 53933, 53650, 53371, 53097, 52826, 52560,
    52298, 52040, 51785, 51535, 51288, 51044, 50804, 50567, 50333, 50103, 49876, 49652,
    49430, 49212, 48997, 48784, 48574, 48367, 48163, 47961, 47761, 47564, 47370, 47178,
    46988, 46800, 46615, 46432, 46251, 46072, 45895, 45720, 45547, 45376, 45207, 45040,
    44875, 44711, 44550, 44390, 44232, 44075, 43920, 43767, 43615, 43465, 43316, 43169,
    43024, 42879, 42737, 42595, 42456, 42317, 42180, 42044, 41910, 41776, 41644, 41514,
    41384, 41256, 41129, 41003, 40878, 40754, 40631, 40510, 40390, 40270, 40152, 40035,
    39919, 39803, 39689, 39576, 39464, 39352, 39242, 39133, 39024, 38916, 38810, 38704,
    38599, 38494, 38391, 38289, 38187, 38086, 37986, 37887, 37788, 37690, 37593, 37497,
    37401, 37307, 37213, 37119, 37027, 36935, 36843, 36753, 36663, 36573, 36485, 36397,
    36309, 36222, 36136, 36051, 35966, 35882, 35798, 35715, 35632, 35550, 35469, 35388,
    35307, 35228, 35148, 35070, 34991, 34914, 34837, 34760, 34684, 34608, 34533, 34458,
    34384, 34310, 34237, 34164, 34092, 34020, 33949, 33878, 33807, 33737, 33668, 33599,
    33530, 33461, 33393, 33326, 33259, 33192, 33126, 33060, 32994, 32929, 32864, 32800};
#endif

/* floor(a b / 2^s) for 16 <= s < 32 and a result below 2^32 (the caller's
 * bound): exact.  Without STP_HAVE_MUL64 (the only builds that use it),
 * four 32-bit products of 16-bit halves put together in 32-bit words (no
 * 64-bit shifts or adds). */
#if !STP_HAVE_MUL64
/* a b as two 32-bit words: *high = floor(a b / 2^32), *low = a b mod 2^32 */
static inline void mul_words32(uint32_t a, uint32_t b, uint32_t *high, uint32_t *low)
{
    uint32_t al = a & 0xFFFFu, ah = a >> 16, bl = b & 0xFFFFu, bh = b >> 16;
    uint32_t ll = al * bl, lh = al * bh, hl = ah * bl;
    uint32_t mid = (ll >> 16) + (lh & 0xFFFFu) + (hl & 0xFFFFu); /* < 3 2^16 */
    *high = ah * bh + (lh >> 16) + (hl >> 16) + (mid >> 16);
    *low = (mid << 16) | (ll & 0xFFFFu);
}

static inline uint32_t mul_shr32(uint32_t a, uint32_t b, int s)
{
    uint32_t high, low;
    mul_words32(a, b, &high, &low);
    return (uint32_t)(high << (32 - s)) | (low >> s);
}

#if STP_NARROW_FORMS
/* floor((a b - 1) / 2^s) for a b >= 1, as mul_shr32 */
static inline uint32_t mul_shr32_less1(uint32_t a, uint32_t b, int s)
{
    uint32_t high, low;
    mul_words32(a, b, &high, &low);
    high -= low == 0 ? 1u : 0u; /* the borrow of low - 1 */
    low -= 1u;
    return (uint32_t)(high << (32 - s)) | (low >> s);
}
#endif
#endif

#if STP_NARROW_FORMS
/* rsqrt_q30's second Newton step, floor(y (3 2^30 - my2) / 2^31) with
 * y2 = floor(y^2 / 2^30) and my2 = floor(m y2 / 2^30), the same floors in
 * fewer 32-bit products: y (the first step's, in [2^29 - 768, 2^30)) =
 * a 2^16 + b gives y2 = 4 a^2 + floor((a b + floor(b^2 / 2^17)) / 2^13)
 * (three products).  The first step leaves m y^2 within 2^-14 of 2^60:
 * g = 2^30 - my2 is in [-1, 48707] for every m (all 3 2^30 checked against
 * the 64-bit definition; tests/core/test_fix.c's test_rsqrt_exact samples
 * them), so my2 is known from floor(m y2 / 2^30) mod 2^18, bits 14..31 of
 * floor(m y2 / 2^16) mod 2^32 (wrapping 32-bit sums of the four partial
 * products) read as a signed 18-bit value.  Then the step is y +
 * floor(y g / 2^31) with y = ya 2^15 + yb: ya g and yb g below 2^31. */
STP_HOT_INLINE uint32_t rsqrt_step_narrow(uint32_t m, uint32_t y)
{
    uint32_t a = y >> 16, b = y & 0xFFFFu;
    uint32_t y2 = ((a * a) << 2) + ((a * b + ((b * b) >> 17)) >> 13);
    uint32_t mh = m >> 16, ml = m & 0xFFFFu, yh = y2 >> 16, yl = y2 & 0xFFFFu;
    uint32_t w = ((mh * yh) << 16) + mh * yl + ml * yh + ((ml * yl) >> 16);
    int32_t g = 0 - stp_asr32((int32_t)w, 14);
    int32_t ya = (int32_t)(y >> 15), yb = (int32_t)(y & 0x7FFFu);
    return y + (uint32_t)stp_asr32(ya * g + stp_asr32(yb * g, 15), 16);
}
#endif

/* 1/sqrt(m / 2^30) in Q30 for m in [2^30, 2^32). */
static inline uint64_t rsqrt_q30(uint32_t m)
{
    uint64_t y = (uint64_t)RSQRT_SEED(m) << 14;
    int k;
    /* Newton for 1/sqrt: y <- y (3 - m y^2) / 2; each step squares the
     * relative error (2^-8 -> 2^-15 -> 2^-29 with the rounding).  m y^2 stays
     * within 2^30 (1 +- 2^-7), so 3 2^30 - m y^2 > 0 and y (...) < 2^62 */
#if STP_HAVE_MUL64
    for (k = 0; k < 2; k++) {
        /* y < 2^31, y2 and my2 near 2^30: 32 x 32 -> 64 products */
        uint64_t y2 = STP_UMUL_FIT32(y, y) >> 30;
        uint64_t my2 = STP_UMUL_FIT32(m, y2) >> 30;
        y = STP_UMUL_FIT32(y, ((uint64_t)3 << 30) - my2) >> 31;
    }
#else
    /* the same floors in 32-bit words: Newton approaches 1/sqrt from
     * below (the floors add a few units at most), so y and y2 stay within
     * a few units of 2^30, my2 within 2^30 (1 +- 2^-7), and each
     * floor(product / 2^s) fits 32 bits.  The first step's y is the
     * 16-bit seed times 2^14: y2 = seed^2 / 4, and y t / 2^31 =
     * (seed t_high + seed t_low / 2^16) / 2, floored at each step */
    {
        uint32_t seed = (uint32_t)(y >> 14), y2 = (seed * seed) >> 2;
        uint32_t t = ((uint32_t)3 << 30) - mul_shr32(m, y2, 30);
        y = (seed * (t >> 16) + ((seed * (t & 0xFFFFu)) >> 16)) >> 1;
    }
#if STP_NARROW_FORMS
    (void)k;
    y = rsqrt_step_narrow(m, (uint32_t)y);
#else
    for (k = 1; k < 2; k++) {
        uint32_t y2 = mul_shr32((uint32_t)y, (uint32_t)y, 30);
        uint32_t my2 = mul_shr32(m, y2, 30);
        y = mul_shr32((uint32_t)y, ((uint32_t)3 << 30) - my2, 31);
    }
#endif
#endif
    return y;
}

static inline uint32_t rsqrt64(uint64_t v, int *exponent)
{
    /* v = m 2^sh with m in [2^30, 2^32) and sh even, so 1/sqrt(v) =
     * rsqrt_q30(m) 2^-(30 + 15 + sh/2) */
    int sh = stp_bit_length64(v) - 31;
    if (sh & 1)
        sh--;
    *exponent = 45 + sh / 2;
    return (uint32_t)rsqrt_q30((uint32_t)(sh >= 0 ? v >> sh : v << -sh));
}

uint32_t stp_rsqrt64(uint64_t v, int *exponent)
{
    return rsqrt64(v, exponent);
}

#if STP_HAVE_MUL64
/* floor(v / 2^s) for |v| < 2^62, 0 <= s < 62, without a branch on the sign
 * (2^62 is a multiple of 2^s, so the offset changes nothing but the sign) */
static inline int64_t floor_shift(int64_t v, int s)
{
    return ((v + ((int64_t)1 << 62)) >> s) - ((int64_t)1 << (62 - s));
}
#else
#if !STP_NARROW_FORMS /* its one caller's form */
/* a^2 for a <= 2^30 from three 32-bit products (ah <= 2^14, so the cross
 * product al ah < 2^30 and twice it fits) */
static inline uint64_t square30(uint32_t a)
{
    uint32_t al = a & 0xFFFFu, ah = a >> 16;
    uint32_t ll = al * al, mid = al * ah, low = ll + (mid << 17);
    uint32_t high = ah * ah + (mid >> 15) + (low < ll ? 1u : 0u);
    return ((uint64_t)high << 32) | low;
}
#endif

/* floor((x inv + 2^(e-1)) / 2^e) for |x| <= 2^30, inv < 2^31, e = 29 or
 * 30 (stp_unit_from64's rounding) from the magnitude's product p: for
 * x < 0 it is -ceil((p - 2^(e-1)) / 2^e) = -floor((p + 2^(e-1) - 1) / 2^e) */
static inline int32_t round_unit(int32_t x, uint32_t inv, int e)
{
#if STP_NARROW_FORMS
    /* the same values in 32-bit words: with q = p or p - 1 (q >= 0: p >= 1
     * for x < 0, inv > 0), floor((q + 2^(e-1)) / 2^e) =
     * floor((floor(q / 2^(e-1)) + 1) / 2) (an integer added inside a floor
     * and a floor inside a floor by an integer change nothing), and
     * floor(q / 2^(e-1)) < 2^32 (p < 2^60, e - 1 >= 28): mul_shr32's exact
     * floor, p - 1 borrowing from its high word when its low word is 0 */
    if (x >= 0)
        return (int32_t)((mul_shr32((uint32_t)x, inv, e - 1) + 1u) >> 1);
    return 0 - (int32_t)((mul_shr32_less1(0u - (uint32_t)x, inv, e - 1) + 1u) >> 1);
#else
    uint64_t half = (uint64_t)1 << (e - 1);
    if (x >= 0)
        return (int32_t)((stp_umul32x32((uint32_t)x, inv) + half) >> e);
    return 0 - (int32_t)((stp_umul32x32(0u - (uint32_t)x, inv) + half - 1u) >> e);
#endif
}
#endif

/* stp_unit_q14_from64's rounding in 32-bit words (round_q14) where 32-bit
 * products are instructions and 64-bit ones library calls: in builds for
 * speed (STP_NARROW_FORMS) and in builds for size too, where its products
 * are less code than round_unit's 64-bit ones and shifts (the same
 * values; lean direct core 6 248 -> 6 168 B) */
#if STP_NARROW_FORMS || (defined(__OPTIMIZE_SIZE__) && STP_HAVE_MUL32 && !STP_HAVE_MUL64)
#define ROUND_Q14_WORDS 1
#else
#define ROUND_Q14_WORDS 0
#endif

#if ROUND_Q14_WORDS
/* stp_unit_q14_from64's rounding, floor((floor((x inv + 2^(e-1)) / 2^e) +
 * 2^15) / 2^16) = floor((x inv + 2^(e-1) + 2^(e+15)) / 2^(e+16)) (one
 * floor: integers added inside a floor, either sign of x), for |x| <=
 * 2^30, inv = ih 2^15 + il <= 2^30 (Newton's floors from below: ih <=
 * 2^15, il < 2^15), e = 29 or 30, in 32-bit words.  With x = xh 2^15 + xl
 * (floor: |xh| <= 2^15, 0 <= xl < 2^15), x inv = xh ih 2^30 + mid 2^15 +
 * xl il, mid = xh il + xl ih in (-2^30, 2^31 - 2^16]; the floor by 2^30 is
 * xh ih + 2^(e-15) + floor((mid + floor((xl il + 2^(e-1)) / 2^15)) /
 * 2^15), the inner sum below 2^31, then a floor by 2^(e-14). */
STP_HOT_INLINE int16_t round_q14(int32_t x, uint32_t ih, uint32_t il, int e)
{
    int32_t xh = stp_asr32(x, 15);
    uint32_t xl = (uint32_t)x & 0x7FFFu;
    int32_t mid = xh * (int32_t)il + (int32_t)(xl * ih);
    int32_t low = (int32_t)((xl * il + ((uint32_t)1 << (e - 1))) >> 15);
    int32_t q = xh * (int32_t)ih + ((int32_t)1 << (e - 15)) + stp_asr32(mid + low, 15);
    return (int16_t)stp_asr32(q, e - 14);
}
#endif

/* (x, y, z) (not all 0, |.| < 2^62) scaled by 2^up so the largest
 * component has 30 bits (its bit length is that of the three ORed; floor
 * shifts when up < 0) into v[]: |v[i]| <= 2^30.  Returns up.  Values
 * within int32, a mesh's cross products, are scaled in 32 bits (the same
 * values: exact products by 2^up, the same floors) where 64-bit words
 * cost more (STP_NARROW_FORMS). */
#if STP_NARROW_FORMS
/* unit_scale for int32 (x, y, z) (not all 0) with m = max |.| (ORed),
 * below 2^31: exact products by 2^up or one floor halving (up = -1) */
STP_HOT_INLINE int unit_scale32(int32_t x, int32_t y, int32_t z, uint32_t m, int32_t v[3])
{
    int up = 30 - stp_bit_length32(m);
    if (up >= 0) {
        v[0] = (int32_t)((uint32_t)x << up);
        v[1] = (int32_t)((uint32_t)y << up);
        v[2] = (int32_t)((uint32_t)z << up);
    } else {
        v[0] = stp_asr32(x, 1); /* up = -1 */
        v[1] = stp_asr32(y, 1);
        v[2] = stp_asr32(z, 1);
    }
    return up;
}
#endif

/* unit_scale's last step: (x, y, z) times 2^up (floor shifts when up < 0)
 * into v[] */
STP_HOT_INLINE int unit_scale_up(int64_t x, int64_t y, int64_t z, int up, int32_t v[3])
{
    if (up >= 0) {
        x *= (int64_t)1 << up;
        y *= (int64_t)1 << up;
        z *= (int64_t)1 << up;
    } else {
        x = stp_asr64(x, -up);
        y = stp_asr64(y, -up);
        z = stp_asr64(z, -up);
    }
    v[0] = (int32_t)x;
    v[1] = (int32_t)y;
    v[2] = (int32_t)z;
    return up;
}

STP_HOT_INLINE int unit_scale(int64_t x, int64_t y, int64_t z, int32_t v[3])
{
#if defined(__OPTIMIZE_SIZE__) && STP_HAVE_MUL32 && !STP_HAVE_MUL64
    /* builds for size where 64-bit operations are library calls: loops
     * over the components, the same values */
    const int64_t c[3] = {x, y, z};
    uint64_t m = 0;
    int i, up;
    for (i = 0; i < 3; i++)
        m |= stp_abs64u(c[i]);
    up = 30 - stp_bit_length64(m);
    for (i = 0; i < 3; i++)
        v[i] = up >= 0 ? (int32_t)((uint32_t)c[i] << up) : (int32_t)stp_asr64(c[i], -up);
    return up;
#else
    uint64_t m = stp_abs64u(x) | stp_abs64u(y) | stp_abs64u(z);
    int up;
#if STP_NARROW_FORMS
    if ((m >> 31) == 0)
        return unit_scale32((int32_t)x, (int32_t)y, (int32_t)z, (uint32_t)m, v);
#endif
    up = 30 - stp_bit_length64(m);
#if defined(__OPTIMIZE_SIZE__) && !STP_HAVE_MUL64
    if (up >= 0) {
        /* builds for size where 64-bit shifts are library calls: the
         * scaled values fit int32, so their low words alone, shifted in 32
         * bits (the same values) */
        v[0] = (int32_t)((uint32_t)x << up);
        v[1] = (int32_t)((uint32_t)y << up);
        v[2] = (int32_t)((uint32_t)z << up);
        return up;
    }
#endif
    return unit_scale_up(x, y, z, up, v);
#endif
}

/* 1/sqrt(s) = inv 2^-(e + 30) for s = v.v (v scaled by unit_scale): s is
 * in [2^58, 3 2^60), a bit length of 59..62, so rsqrt64's even shift is
 * 28 or 30 and e (to STP_UNIT) is 29 or 30; *squares = s (with
 * STP_NARROW_FORMS s less s mod 2^30: the callers use s >> 30 alone). */
STP_HOT_INLINE int64_t unit_inverse(const int32_t v[3], uint64_t *squares, int *e)
{
#if STP_NARROW_FORMS
    /* s in 32-bit words, no 64-bit sum: each |v_i| <= 2^30 as h 2^15 + l
     * (h <= 2^15, l < 2^15), v_i^2 = h^2 2^30 + h l 2^16 + l^2, so s =
     * hh 2^30 + hl 2^16 + ll with the three sums below 3 2^30; floor(s /
     * 2^k) for k = 30, 28 is hh 2^(30-k) + floor((hl + floor(ll / 2^16)) /
     * 2^(k-16)) (floors inside floors by integers), the sum inside below
     * 3 2^30 + 3 2^14.  s >= 2^60 when floor(s / 2^30) >= 2^30; else hh <
     * 2^30 and floor(s / 2^28) < 2^32. */
    uint32_t a0 = abs32(v[0]), a1 = abs32(v[1]), a2 = abs32(v[2]);
    uint32_t h0 = a0 >> 15, h1 = a1 >> 15, h2 = a2 >> 15;
    uint32_t l0 = a0 & 0x7FFFu, l1 = a1 & 0x7FFFu, l2 = a2 & 0x7FFFu;
    uint32_t hh = h0 * h0 + h1 * h1 + h2 * h2, hl = h0 * l0 + h1 * l1 + h2 * l2;
    uint32_t mid = hl + ((l0 * l0 + l1 * l1 + l2 * l2) >> 16), m;
    m = hh + (mid >> 14);
    *squares = (uint64_t)m << 30;
    if (m >= (uint32_t)1 << 30) {
        *e = 30;
    } else {
        *e = 29;
        m = (hh << 2) + (mid >> 12);
    }
    return (int64_t)rsqrt_q30(m);
#else
    uint64_t s;
    int sh;
    /* |v[i]| <= 2^30: exact 32 x 32 products */
#if STP_HAVE_MUL64
    s = (uint64_t)STP_SMUL_FIT32(v[0], v[0]) + (uint64_t)STP_SMUL_FIT32(v[1], v[1]) +
        (uint64_t)STP_SMUL_FIT32(v[2], v[2]);
#else
    /* a loop: one call of square30 (the lean direct core 12 B smaller) */
    int i;
    s = 0;
    for (i = 0; i < 3; i++)
        s += square30(abs32(v[i]));
#endif
    sh = s >= ((uint64_t)1 << 60) ? 30 : 28;
    *squares = s;
    *e = 45 + sh / 2 - 30;
#if STP_HAVE_MUL64
    return (int64_t)rsqrt_q30((uint32_t)(s >> sh));
#else
    /* floor(s / 2^sh) < 2^32 from s's two words: 32-bit shifts, not
     * libgcc's 64-bit one */
    return (int64_t)rsqrt_q30(((uint32_t)(s >> 32) << (32 - sh)) | ((uint32_t)s >> sh));
#endif
#endif
}

int64_t stp_unit_from64(int64_t x, int64_t y, int64_t z, stp_unit3 *out)
{
    int32_t v[3];
    uint64_t s, len;
    int up, e;
    int64_t inv;
    out->x = out->y = out->z = 0;
    if ((x | y | z) == 0)
        return 0;
    up = unit_scale(x, y, z, v);
    inv = unit_inverse(v, &s, &e);
    /* |v inv| < 2^60 */
#if STP_HAVE_MUL64
    {
        const int64_t half = (int64_t)1 << (e - 1);
        out->x = (int32_t)floor_shift(STP_SMUL_FIT32(v[0], inv) + half, e);
        out->y = (int32_t)floor_shift(STP_SMUL_FIT32(v[1], inv) + half, e);
        out->z = (int32_t)floor_shift(STP_SMUL_FIT32(v[2], inv) + half, e);
    }
    /* |v| scaled = s / sqrt(s): s >> 30 < 2^32 times inv < 2^31 */
    len = STP_UMUL_FIT32(s >> 30, inv) >> e;
#else
    out->x = round_unit(v[0], (uint32_t)inv, e);
    out->y = round_unit(v[1], (uint32_t)inv, e);
    out->z = round_unit(v[2], (uint32_t)inv, e);
    len = mul_shr32((uint32_t)(s >> 30), (uint32_t)inv, e); /* < 2^32: |v| scaled < 2^30 sqrt 3 */
#endif
    /* to the input's units, rounded to nearest (len may sit 2^-29 below an
     * exact integer length, which a floor would take a whole unit down) */
    if (up > 0)
        return (int64_t)((len + ((uint64_t)1 << (up - 1))) >> up);
    return up == 0 ? (int64_t)len : (int64_t)(len << -up);
}

/* stp_unit_q14_from64's steps after the scaling: v (unit_scale's) as
 * Q1.14 in out[].  In line in builds for size too, where it has one
 * caller (stp_unit_q14_from32 is ARMv6-M's -O2 alone): the code of
 * stp_unit_q14_from64 as one function (a call of its own measured 202
 * bytes more on the ATmega2560 teapot image, 82 fewer on the tetra). */
#if defined(__GNUC__)
static inline __attribute__((always_inline)) void unit_q14_scaled(const int32_t v[3], int16_t out[3])
#else
static inline void unit_q14_scaled(const int32_t v[3], int16_t out[3])
#endif
{
    uint64_t s;
    int e;
    int64_t inv = unit_inverse(v, &s, &e);
#if STP_HAVE_MUL64
    {
        /* floor((floor((v inv + 2^(e-1)) / 2^e) + 2^15) / 2^16) in one
         * floor: an integer added inside a floor may be added outside */
        const int64_t half = ((int64_t)1 << (e - 1)) + ((int64_t)1 << (e + 15));
        out[0] = (int16_t)floor_shift(STP_SMUL_FIT32(v[0], inv) + half, e + 16);
        out[1] = (int16_t)floor_shift(STP_SMUL_FIT32(v[1], inv) + half, e + 16);
        out[2] = (int16_t)floor_shift(STP_SMUL_FIT32(v[2], inv) + half, e + 16);
    }
#elif ROUND_Q14_WORDS
    {
        uint32_t ih = (uint32_t)inv >> 15, il = (uint32_t)inv & 0x7FFFu;
#if defined(__OPTIMIZE_SIZE__)
        /* builds for size: a loop, one copy of round_q14 in line (the
         * lean direct core 28 B smaller) */
        int i;
        for (i = 0; i < 3; i++)
            out[i] = round_q14(v[i], ih, il, e);
#else
        out[0] = round_q14(v[0], ih, il, e);
        out[1] = round_q14(v[1], ih, il, e);
        out[2] = round_q14(v[2], ih, il, e);
#endif
    }
#else
    out[0] = (int16_t)stp_asr32(round_unit(v[0], (uint32_t)inv, e) + ((int32_t)1 << 15), 16);
    out[1] = (int16_t)stp_asr32(round_unit(v[1], (uint32_t)inv, e) + ((int32_t)1 << 15), 16);
    out[2] = (int16_t)stp_asr32(round_unit(v[2], (uint32_t)inv, e) + ((int32_t)1 << 15), 16);
#endif
}

#if STP_HAVE_MUL64
void stp_unit_q14_from64_or(int64_t x, int64_t y, int64_t z, uint64_t m, int16_t out[3])
{
    int32_t v[3];
    (void)unit_scale_up(x, y, z, 30 - stp_bit_length64(m), v);
    unit_q14_scaled(v, out);
}

/* the steps above after the magnitudes (one copy of them) */
int stp_unit_q14_from64(int64_t x, int64_t y, int64_t z, int16_t out[3])
{
    uint64_t m = stp_abs64u(x) | stp_abs64u(y) | stp_abs64u(z);
    if (m == 0)
        return 0;
    stp_unit_q14_from64_or(x, y, z, m, out);
    return 1;
}
#else
int stp_unit_q14_from64(int64_t x, int64_t y, int64_t z, int16_t out[3])
{
    int32_t v[3];
    if ((x | y | z) == 0)
        return 0;
    (void)unit_scale(x, y, z, v);
    unit_q14_scaled(v, out);
    return 1;
}
#endif

#if STP_NARROW_FORMS
int stp_unit_q14_from32(int32_t x, int32_t y, int32_t z, int16_t out[3])
{
    int32_t v[3];
    uint32_t m = stp_abs32(x) | stp_abs32(y) | stp_abs32(z);
    if (m == 0)
        return 0;
    if (m >> 31)
        return stp_unit_q14_from64(x, y, z, out); /* a component -2^31 */
    (void)unit_scale32(x, y, z, m, v);
    unit_q14_scaled(v, out);
    return 1;
}
#endif

uint32_t stp_sqrt64_fast(uint64_t v)
{
    int sh, e;
    uint64_t m, r, inv;
    if (v == 0)
        return 0;
    sh = stp_bit_length64(v) - 31;
    if (sh & 1)
        sh--;
    m = sh >= 0 ? v >> sh : v << -sh;
    inv = rsqrt64(v, &e); /* sets e: a statement of its own */
    /* sqrt(v) = v / sqrt(v) = m 2^sh inv 2^-e: m < 2^32, inv <= 2^30;
     * e - sh = 45 - sh/2 > 0 */
    r = STP_UMUL_FIT32(m, inv) >> (e - sh);
    return r > 0xFFFFFFFFu ? 0xFFFFFFFFu : (uint32_t)r;
}
