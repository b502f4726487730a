/* SPDX-License-Identifier: MIT */
/* Private helpers of the fixed-point code shared by the core's files. */
#ifndef STIPPLE_FIX_PRIVATE_H
#define STIPPLE_FIX_PRIVATE_H

/* A small function forced inline where a call would cost as much as its
 * body, except in builds for size (-Os), which keep it a call. */
#if defined(__GNUC__) && !defined(__OPTIMIZE_SIZE__)
#define STP_HOT_INLINE static inline __attribute__((always_inline))
#else
#define STP_HOT_INLINE static inline
#endif

#include <stdint.h>

#include "stipple/fix.h"
#include "recip_private.h" /* stp_umul32x32 */

/* Constant tables of the core.  On AVR, const data is copied into RAM at
 * start-up unless it is put in program memory and read with LPM; 384 bytes
 * of square-root seeds are a twentieth of an ATmega2560's RAM. */
#if defined(__AVR__)
#include <avr/pgmspace.h>
#define STP_TABLE PROGMEM
#define STP_TABLE_U16(p) pgm_read_word(p)
#else
#define STP_TABLE
#define STP_TABLE_U16(p) (*(p))
#endif

/* Arithmetic shift right rounding toward minus infinity, for negative values
 * too (C99 leaves >> of a negative value to the implementation). */
static inline int64_t stp_asr64(int64_t v, int s)
{
    return v >= 0 ? v >> s : -((-(v + 1)) >> s) - 1;
}

/* num / den truncated toward zero for den != 0 and a quotient that fits:
 * C's operator, or with STP_SMALL_DIVISION (config.h) the bit-serial loop
 * of div64.c, so the C library's 64-bit division is not linked. */
#if STP_SMALL_DIVISION
int64_t stp_div64_trunc(int64_t num, int64_t den);
#define STP_DIV64(num, den) stp_div64_trunc((int64_t)(num), (int64_t)(den))
#else
#define STP_DIV64(num, den) ((int64_t)(num) / (int64_t)(den))
#endif

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
    return den == 0 ? 0 : (da * ((int64_t)1 << 30)) / den;
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
 * 1/sqrt and refined by two Newton steps (relative error below 2^-29).
 * A zero vector returns 0 and leaves *out = 0. */
int64_t stp_unit_from64(int64_t x, int64_t y, int64_t z, stp_unit3 *out);

/* 1/sqrt(v) for v > 0: returns y in (2^29, 2^30] and *exponent with
 * 1/sqrt(v) = y 2^-exponent (relative error below 2^-29; table seed and
 * two Newton steps, no division). */
uint32_t stp_rsqrt64(uint64_t v, int *exponent);

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

/* Number of significant bits of v (0 for 0). */
static inline int stp_bit_length64(uint64_t v)
{
#if defined(__GNUC__)
    return v == 0 ? 0 : 64 - __builtin_clzll(v);
#else
    int n = 0;
    while (v >= ((uint64_t)1 << 16)) {
        v >>= 16;
        n += 16;
    }
    while (v != 0) {
        v >>= 1;
        n++;
    }
    return n;
#endif
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

/* v / 3 truncated toward zero, as C's operator, for any int32 v, without
 * a division (a library call on ARMv6-M, ~120 instructions): |v| < 2^32
 * times ceil(2^33 / 3) = 0xAAAAAAAB, shifted down 33, is floor(|v| / 3)
 * exactly (the multiplier's excess of 1/3 2^-33 times |v| < 2^32 stays
 * below the 1/3 gap to the next integer), then the sign. */
static inline int32_t stp_div3_toward_zero(int32_t v)
{
    uint32_t u = v < 0 ? 0u - (uint32_t)v : (uint32_t)v;
    uint32_t q = (uint32_t)(stp_umul32x32(u, 0xAAAAAAABu) >> 33);
    return v < 0 ? 0 - (int32_t)q : (int32_t)q;
}

/* Significant bits of v (0 for 0, else floor(log2 v) + 1): one
 * instruction where there is a count-leading-zeros instruction (64-bit
 * hosts, ARMv7-M), else three halvings of the range and a 16-entry table
 * (ARMv6-M and AVR have none; GCC's __builtin_clz would be a library call). */
STP_HOT_INLINE int stp_bit_length32(uint32_t v)
{
#if defined(__GNUC__) && (STP_WIDE_ARITH || defined(__ARM_FEATURE_CLZ))
    return v == 0 ? 0 : 32 - __builtin_clz(v);
#else
    static const uint16_t len4[16] STP_TABLE = {0, 1, 2, 2, 3, 3, 3, 3, 4, 4, 4, 4, 4, 4, 4, 4};
    int n = 0;
    if (v >= 0x10000u) {
        v >>= 16;
        n = 16;
    }
    if (v >= 0x100u) {
        v >>= 8;
        n += 8;
    }
    if (v >= 0x10u) {
        v >>= 4;
        n += 4;
    }
    return n + (int)STP_TABLE_U16(&len4[v]);
#endif
}

/* The high word of a b for 32-bit a and b, short of floor(a b / 2^32) by
 * at most 2 (the low halves' product and the carries out of the middle
 * products' low halves are dropped): three 32-bit products on 32-bit
 * targets; exact where a 64-bit product is one instruction.  For products
 * whose last two units do not matter. */
STP_HOT_INLINE uint32_t stp_umulhi32_approx(uint32_t a, uint32_t b)
{
#if STP_WIDE_ARITH
    return (uint32_t)(((uint64_t)a * b) >> 32);
#else
    uint32_t ah = a >> 16, bh = b >> 16;
    return ah * bh + ((ah * (b & 0xFFFFu)) >> 16) + (((a & 0xFFFFu) * bh) >> 16);
#endif
}

#endif
