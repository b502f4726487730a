/* SPDX-License-Identifier: MIT */
/* Private helpers of the fixed-point code shared by the core's files. */
#ifndef STIPPLE_FIX_PRIVATE_H
#define STIPPLE_FIX_PRIVATE_H

#include <stdint.h>

#include "stipple/fix.h"
#include "arith_private.h" /* STP_HOT_INLINE, STP_TABLE, products, bit counts */
#include "recip_private.h" /* reciprocals and exact division */
#include "div64_private.h" /* STP_DIV64 */

/* floor(sqrt(v)) for any 64-bit unsigned v (exact in both sqrt modes). */
uint32_t stp_isqrt64(uint64_t v);

/* floor(sqrt(v)) for a 32-bit v: the same digit-by-digit root in 32-bit
 * words (stp_isqrt64 takes it for v < 2^32), for cores where 64-bit
 * arithmetic is a library call. */
uint16_t stp_isqrt32(uint32_t v);

/* v's component i (0: x, 1: y, 2: z), for loops over the three
 * components: with STP_LEAN_CODE (AVR -Os) a loop is a third of the code
 * of three written out; elsewhere the loop is unrolled and the index
 * folds away.  No copy of the vector on the stack.  In size-first builds
 * (-Os with STP_SMALL_DIVISION, where such loops stay loops) one call
 * per file, not the choice inlined at each use: lean direct core 6 386 ->
 * 6 320 B. */
#if defined(__GNUC__) && defined(__OPTIMIZE_SIZE__) && STP_SMALL_DIVISION
static __attribute__((noinline, unused)) int32_t stp_vec3_comp(const stp_vec3 *v, int i)
#else
STP_INDEX_INLINE int32_t stp_vec3_comp(const stp_vec3 *v, int i)
#endif
{
    return i == 0 ? v->x : (i == 1 ? v->y : v->z);
}

/* Clamp a to [lo, hi]. */
static inline stp_fix stp_fix_clamp(stp_fix a, stp_fix lo, stp_fix hi)
{
    return a < lo ? lo : (a > hi ? hi : a);
}

/* Saturate a 64-bit value to stp_fix's range. */
static inline stp_fix stp_fix_sat64(int64_t v)
{
    return v > STP_FIX_MAX ? STP_FIX_MAX : (v < STP_FIX_MIN ? STP_FIX_MIN : (stp_fix)v);
}

/* Arithmetic shift right rounding toward minus infinity, for negative values
 * too (C99 leaves >> of a negative value to the implementation). */
static inline int64_t stp_asr64(int64_t v, int s)
{
    return v >= 0 ? v >> s : -((-(v + 1)) >> s) - 1;
}

/* floor(a / b) for b > 0. */
static inline int64_t stp_floordiv64(int64_t a, int64_t b)
{
    int64_t q = a / b;
    return (a % b != 0 && a < 0) ? q - 1 : q;
}


/* Where segment a-b crosses a plane, given the signed distances da >= 0 > db
 * or the reverse: the fraction t of the way from a, in Q30 ([0, 2^30]). */
static inline int64_t stp_clip_fraction(int64_t da, int64_t db)
{
    int64_t den = da - db;
    /* bring the distances below 2^32 so da << 30 cannot overflow */
    while (den >= ((int64_t)1 << 32) || den <= -((int64_t)1 << 32) ||
           da >= ((int64_t)1 << 32) || da <= -((int64_t)1 << 32)) {
        da /= 2;
        db /= 2;
        den = da - db;
    }
    return den == 0 ? 0 : STP_DIV64(da * ((int64_t)1 << 30), den); /* C's truncating quotient */
}

/* a + (b - a) t with t in Q30, saturated. */
static inline stp_fix stp_lerp_fix(stp_fix a, stp_fix b, int64_t t)
{
    return stp_fix_sat64(a + stp_asr64(((int64_t)b - a) * t, 30));
}

/* UNITY of a - b: *out = (a - b)/|a - b|, returning |a - b| with F
 * fractional bits in 64 bits.  The difference of two stp_fix can exceed the
 * range (points near opposite ends of it), and so can the length of a
 * difference within it: the difference is formed in 64 bits and halved
 * until its length fits (components below 2^30), which keeps its
 * direction, and the length is scaled back unsaturated (below 2^33). */
static inline int64_t stp_unity_diff(stp_vec3 a, stp_vec3 b, stp_vec3 *out)
{
    const int64_t lim = ((int64_t)1 << 30) - 1;
    int64_t dx = (int64_t)a.x - b.x, dy = (int64_t)a.y - b.y, dz = (int64_t)a.z - b.z;
    int shift = 0;
    stp_vec3 d;
    while (dx > lim || dx < -lim || dy > lim || dy < -lim || dz > lim || dz < -lim) {
        dx /= 2;
        dy /= 2;
        dz /= 2;
        shift++;
    }
    d.x = (stp_fix)dx;
    d.y = (stp_fix)dy;
    d.z = (stp_fix)dz;
    return (int64_t)stp_vec3_unity(d, out) * ((int64_t)1 << shift);
}

/* ---- unit vectors and cosines for shading ----
 *
 * Format STP_UNIT (Q30 in int32): a unit vector's components and the
 * cosines between unit vectors, one = 2^30.  Range: [-1, 1] plus the
 * normaliser's rounding (|component| <= 2^30 + 2), so it fits int32 with a
 * factor 2 to spare.  Step 9.3e-10: far below stp_fix's 2^-16, so a cosine
 * near 0 (a grazing eye or light) or near 1 (a sharp highlight) keeps its
 * bits.  Products of two components are below 2^61 and a sum of three
 * below 2^62.6 (Cauchy-Schwarz: |a.b| <= |a||b|), so a dot product formed in
 * 64 bits cannot overflow. */
#define STP_UNIT_BITS 30
#define STP_UNIT_ONE ((int32_t)1 << STP_UNIT_BITS)

typedef struct stp_unit3 {
    int32_t x, y, z;
} stp_unit3;

/* The direction of (x, y, z) (any values with |component| < 2^62) as an
 * STP_UNIT vector in *out, and its length in the input's units (rounded
 * to nearest; error below 2^-28 relative plus half a unit).  No division: the squared length of
 * the vector scaled to 30 bits is seeded from a 192-entry table of
 * 1/sqrt (builds for size: the same seeds from stp_rsqrt_norm) and
 * refined by two Newton steps (relative error below 2^-29).
 * A zero vector returns 0 and leaves *out = 0. */
int64_t stp_unit_from64(int64_t x, int64_t y, int64_t z, stp_unit3 *out);
/* The same direction as Q1.14 in out[] (STP_UNIT rounded to nearest:
 * floor((u + 2^15) / 2^16) of stp_unit_from64's u, formed without u's
 * own rounding step where 64-bit products are native, and without the
 * length); 1, or 0 for a zero vector (out unset). */
int stp_unit_q14_from64(int64_t x, int64_t y, int64_t z, int16_t out[3]);
#if STP_HAVE_MUL64
/* stp_unit_q14_from64 for (x, y, z) not 0 whose magnitudes ORed, m, the
 * caller has formed (the polygon route's side test does): the same
 * values, without forming them again */
void stp_unit_q14_from64_or(int64_t x, int64_t y, int64_t z, uint64_t m, int16_t out[3]);
#endif
#if STP_NARROW_FORMS
/* stp_unit_q14_from64 for int32 components (the same values), where
 * 64-bit arguments and magnitudes cost more (ARMv6-M's -O2) */
int stp_unit_q14_from32(int32_t x, int32_t y, int32_t z, int16_t out[3]);
#endif

/* 1/sqrt(v) for v > 0: returns y in (2^29, 2^30] and *exponent with
 * 1/sqrt(v) = y 2^-exponent (relative error below 2^-29; table seed and
 * two Newton steps, no division). */
uint32_t stp_rsqrt64(uint64_t v, int *exponent);

/* The seed's chord nodes of stp_rsqrt_norm: 2^18 / sqrt(16 + i) (2^31 /
 * sqrt(q) at q = (16 + i) 2^26), each lowered by 3/(64 (16 + i)^2) of
 * itself, so that the chord between neighbours, which lies above the
 * convex 1/sqrt by up to 3/(32 x^2), is within 2^-12.3 of it on either
 * side; all below 2^16.  Static: a file that inlines the root has its
 * copy (addressed with the file's other tables: an external table cost
 * the ARMv6-M face shading's -O2 code its shared base address). */
static const uint16_t stp_rsqrt_node[49] STP_TABLE = {
    65524, 63569, 61779, 60132, 58610, 57198, 55884, 54656, 53506, 52425, 51407, 50446, 49538,
    48676, 47858, 47080, 46339, 45631, 44956, 44309, 43689, 43095, 42524, 41975, 41447, 40939,
    40449, 39976, 39519, 39077, 38650, 38237, 37836, 37448, 37072, 36707, 36352, 36008, 35673,
    35347, 35030, 34721, 34421, 34128, 33842, 33564, 33292, 33027, 32768,
};

/* 1/sqrt(q) for q in [2^30, 2^32): r in (2^30, 2^31] with 1/sqrt(q) =
 * r 2^-46, relative error below 2^-23 (2^-24.2 over 300 000 random q).
 * The seed y ~ 2^31/sqrt(q) is the chord of two nodes at q's 16-bit
 * fraction of its step (2^-12.3; the nodes differ by less than 2^11, so
 * the product stays below 2^27), refined by one Newton step with the
 * high word of q y^2, which keeps the 15 more bits of its correction in r
 * (e y 2^-16 as two 32-bit products).  A table step and a product where a
 * first Newton step on 16-bit operands (2^-6 to 2^-11) cost twice as many
 * instructions on ARMv6-M.  Inline for the face shading (shade_fast.c)
 * where time counts; stp_rsqrt_norm is its one out-of-line copy (builds
 * for size, and stp_rsqrt64's seeds there). */
STP_HOT_INLINE uint32_t stp_rsqrt_norm_inline(uint32_t q)
{
    const uint16_t *node = &stp_rsqrt_node[(q >> 26) - 16u]; /* both nodes from one address */
    uint32_t y0 = STP_TABLE_U16(node);
    uint32_t y = y0 - (((y0 - STP_TABLE_U16(node + 1)) * ((q >> 10) & 0xFFFFu)) >> 16);
    /* q y^2 2^-32 ~ 2^30 (y < 2^16: y^2 < 2^32); |e| < 2^19 */
    int32_t e = ((int32_t)1 << 30) - (int32_t)stp_umulhi32_approx(q, y * y);
    return (y << 15) + (uint32_t)(stp_asr32(e, 16) * (int32_t)y + (int32_t)((stp_lo16((uint32_t)e) * y) >> 16));
}
uint32_t stp_rsqrt_norm(uint32_t q);

/* sqrt(v), rounded down within 2^-29 relative (not the exact floor
 * stp_isqrt64 gives), from stp_rsqrt64: a few multiplications instead of a
 * 32-step loop. */
uint32_t stp_sqrt64_fast(uint64_t v);

/* Cosine of two STP_UNIT vectors, STP_UNIT, rounded to nearest. */
static inline int32_t stp_unit_dot(stp_unit3 a, stp_unit3 b)
{
    int64_t s = (int64_t)a.x * b.x + (int64_t)a.y * b.y + (int64_t)a.z * b.z;
    return (int32_t)stp_asr64(s + ((int64_t)1 << (STP_UNIT_BITS - 1)), STP_UNIT_BITS);
}

/* An STP_UNIT vector as stp_fix components, rounded to nearest. */
static inline stp_vec3 stp_unit_to_fix(stp_unit3 u)
{
    stp_vec3 v;
    const int s = STP_UNIT_BITS - STP_FIX_FRAC_BITS;
    v.x = (stp_fix)stp_asr64((int64_t)u.x + ((int64_t)1 << (s - 1)), s);
    v.y = (stp_fix)stp_asr64((int64_t)u.y + ((int64_t)1 << (s - 1)), s);
    v.z = (stp_fix)stp_asr64((int64_t)u.z + ((int64_t)1 << (s - 1)), s);
    return v;
}

/* (a b) >> s for a, b >= 0 and 0 <= s <= 62, exact when a b < 2^63;
 * otherwise both are cut to 63 significant bits together first (relative
 * error below 2^-30 when each keeps 31 bits), and a result of 2^62 or more
 * saturates to 2^62. */
static inline int64_t stp_mul_shift_sat(int64_t a, int64_t b, int s)
{
    int la, lb, cut;
    if (((uint64_t)a >> 31) == 0 && ((uint64_t)b >> 32) == 0)
        return (a * b) >> s; /* the common case: a b < 2^63 */
    la = stp_bit_length64((uint64_t)a);
    lb = stp_bit_length64((uint64_t)b);
    if (la + lb <= 63)
        return (a * b) >> s;
    cut = la + lb - 63;
    if (cut > s)
        return (int64_t)1 << 62;
    /* take the bits from the longer operand first, keeping 31 in each */
    while (cut > 0) {
        if (la >= lb) {
            a >>= 1;
            la--;
        } else {
            b >>= 1;
            lb--;
        }
        cut--;
        s--;
    }
    {
        int64_t p = (a * b) >> s;
        return p >= ((int64_t)1 << 62) ? (int64_t)1 << 62 : p;
    }
}

#endif
