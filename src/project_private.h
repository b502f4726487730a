/* SPDX-License-Identifier: MIT */
/* Private: the one perspective projection, used by polygon entry
 * (render.c), mesh entry (mesh.c), shadow maps (shadow.c) and direct
 * drawing (direct.c).  Inline: it runs once per vertex, and the 32-bit
 * form's common case is a few products; the 64-bit quotients are view.c's
 * stp_view_perspective_wide.  No .c file of its own: the inline part of
 * view_private.h, which declares stp_view_perspective_wide and includes it
 * at its end (include view_private.h). */
#ifndef STIPPLE_PROJECT_PRIVATE_H
#define STIPPLE_PROJECT_PRIVATE_H

#include <stdint.h>

#include "stipple/render.h" /* stp_vec3, STP_SUBPIXEL_BITS */
#include "fix_private.h"    /* stp_bit_length32 */
#include "recip_private.h"  /* STP_WIDE_ARITH, stp_umul32x32, stp_recip32 */

/* The guard band (builds with STP_DIRECT_COMPACT, config.h): the renderer
 * clips a polygon at the picture's sides only where it reaches beyond a
 * band of stp_guard_pixels(size) pixels around the picture (its clip
 * volume widened by that much, render.c); the raster walks the rest whole
 * and clamps rows and spans to the picture, as direct drawing's compact
 * form walks its faces, so both draw a face across the picture's edge
 * with the same crossings.  Device coordinates then lie within
 * [-STP_GUARD_Q4, 2^19) rather than [0, 2^19); elsewhere the guard is 0
 * and they are clamped to the picture. */
#define STP_GUARD_BAND STP_DIRECT_COMPACT
#if STP_GUARD_BAND
#define STP_GUARD_Q4 ((int32_t)512 << STP_SUBPIXEL_BITS) /* the widest guard, Q4 */
#else
#define STP_GUARD_Q4 0
#endif

/* The guard band's width in pixels beside a side of size pixels (<=
 * 32767): 512, less for sizes above 31743 so that size + 2 guard stays
 * within 32767 (the clip volume's and the raster's ranges); 0 without
 * the guard band. */
static inline uint32_t stp_guard_pixels(uint32_t size)
{
#if STP_GUARD_BAND
    return size <= 32767u - 1024u ? 512u : (32767u - size) / 2u;
#else
    (void)size;
    return 0;
#endif
}

/* stp_guard_pixels(size) in Q27.4 device units */
static inline int32_t stp_guard_subpixels(uint32_t size)
{
    return (int32_t)stp_guard_pixels(size) << STP_SUBPIXEL_BITS;
}

/* A perspective projection's constants: focal, hither (stp_fix, > 0), and
 * the picture's half width and height in Q27.4 (width 2^3, height 2^3),
 * with the guard band: its widths in Q4 (stp_guard_pixels). */
typedef struct stp_view_lens {
    stp_fix focal, hither;
    int32_t half_width, half_height;
#if STP_GUARD_BAND
    int32_t guard_x, guard_y;
#endif
} stp_view_lens;
#if STP_GUARD_BAND
#define STP_LENS_GUARD_X(lens) ((lens)->guard_x)
#define STP_LENS_GUARD_Y(lens) ((lens)->guard_y)
#else
#define STP_LENS_GUARD_X(lens) 0
#define STP_LENS_GUARD_Y(lens) 0
#endif

/* The lens of a width x height picture (each <= 32767, so the halves in
 * Q4 fit int32) seen with focal and hither */
static inline void stp_view_lens_make(stp_view_lens *lens, stp_fix focal, stp_fix hither, uint32_t width,
                                      uint32_t height)
{
    lens->focal = focal;
    lens->hither = hither;
    lens->half_width = (int32_t)width << (STP_SUBPIXEL_BITS - 1);
    lens->half_height = (int32_t)height << (STP_SUBPIXEL_BITS - 1);
#if STP_GUARD_BAND
    lens->guard_x = stp_guard_subpixels(width);
    lens->guard_y = stp_guard_subpixels(height);
#endif
}

#if !STP_WIDE_ARITH
/* The 32-bit form by restoring division (stp_project_divide) rather than
 * a reciprocal of z: on cores without a 32-bit multiply (AVR), and in
 * size-first builds (STP_SMALL_DIVISION: the lean direct core 7 008 ->
 * 6 592 B on a Cortex-M0+, its -Os frame 1 506 520 -> 1 727 640
 * instructions), the same values. */
#define STP_PROJECT_DIVIDES (!STP_HAVE_MUL32 || STP_SMALL_DIVISION)

/* The reciprocal of z, scaled by f (f / z as w 2^-sh, 2^31 <= w < 2^32, 0
 * < f < 2^31): z = dn 2^-s with dn in [2^31, 2^32) and 2^32 + v within 2
 * below floor((2^64 - 1) / dn) (stp_recip32_estimate), so P = f (2^32 +
 * v) < 2^64 approximates f 2^64 / dn from below within 4 f (relative
 * 2^-30); w = P's top 32 bits (P >> t, w >= 2^31) and sh = 64 - t - s, at
 * least 1 (t <= 32, s <= 31).  P's high word is in [f, 2 f), so t is f's
 * bit length fb (stp_bit_length32, a caller's once for many points) or
 * one more; fb -1: not known (t found from P). */
static inline void stp_project_scale(uint32_t f, int fb, uint32_t v, int s, uint32_t *w, int *sh)
{
    uint32_t ph = f + stp_umulhi32x32(f, v), pl = f * v; /* ph in [f, 2 f) */
    int t = fb < 0 ? stp_bit_length32(ph) : fb + (int)((ph >> fb) != 0);
    *w = t == 32 ? ph : (ph << (32 - t)) | (pl >> t);
    *sh = 64 - t - s;
}

/* q = floor(n / z) from an estimate e in [q - 7, q] and n_low = n mod 2^32
 * (z < 2^29): the remainder n - e z is in [0, 8 z), below 2^32, so taken
 * mod 2^32 it corrects e.  0 when the quotient is 2^31 or more. */
static inline int stp_project_correct(uint32_t e, uint32_t n_low, uint32_t z, uint32_t *q)
{
    uint32_t rem;
    if (e >= 0x80000000u)
        return 0;
    rem = n_low - e * z;
    while (rem >= z) {
        e++;
        rem -= z;
    }
    *q = e;
    return e < 0x80000000u;
}

/* The offset from the quotient q = floor(f |c| / z): floor of the signed
 * quotient truncated toward zero, at STP_SUBPIXEL_BITS. */
static inline int32_t stp_project_subpixel(int negative, uint32_t q)
{
    const int shift = STP_FIX_FRAC_BITS - STP_SUBPIXEL_BITS;
    return negative ? -(int32_t)((q + ((1u << shift) - 1u)) >> shift) : (int32_t)(q >> shift);
}

/* floor(f mx / z) and floor(f my / z) exactly, for mx, my < 2^31 and z <
 * 2^29, from the estimates e = floor(m w / 2^sh): every step rounds down,
 * so e <= the quotient Q, and Q - e <= 8 Q 2^-32 + 2 (w 2^-sh is below f
 * / z by at most (4 f + 2^t) 2^(s - 64) <= 8 f 2^(s - 64), and m f 2^(s -
 * 64) <= Q 2^-32), at most 5 for Q < 2^31 (7 from STP_NARROW_FORMS's
 * three-product estimates below; stp_project_correct).  Each
 * estimate is the high word of one product: m w / 2^sh is below 2^31 only
 * when m < 2^sh (w >= 2^31), so for sh <= 32 m 2^(32 - sh) fits 32 bits
 * (one test for both: mx | my < 2^sh) and e = floor(m 2^(32 - sh) w /
 * 2^32); for sh > 32 e = floor(m w / 2^32) / 2^(sh - 32).  0 when a
 * quotient is 2^31 or more.  Both coordinates in one step with
 * STP_NARROW_FORMS (fewer values live on ARMv6-M), else one a call. */
#if !STP_NARROW_FORMS
/* A build for size (or without 32-bit forms beside 64-bit ones): one
 * quotient a call, which the compiler keeps out of line for x and y (less
 * code than the two-coordinate step below). */
static inline int stp_project_quotient(uint32_t m, uint32_t w, int sh, uint32_t n_low, uint32_t z, uint32_t *q)
{
    uint32_t e;
    if (sh <= 32) {
        if ((m >> (sh - 1)) > 1u) /* m >= 2^sh, m < 2^31 */
            return 0;
        e = stp_umulhi32x32(m << (32 - sh), w);
    } else {
        e = sh - 32 >= 32 ? 0u : stp_umulhi32x32(m, w) >> (sh - 32);
    }
    return stp_project_correct(e, n_low, z, q);
}
#endif

#if STP_NARROW_FORMS
/* The offset (stp_project_subpixel) of Q = floor(f m / z), sign -1 for a
 * negative coordinate (else 0), from an estimate e with Q - e < 8 and
 * n_low = f m mod 2^32: the offset is floor((Q + b) / 2^k), k = F -
 * STP_SUBPIXEL_BITS and b = 2^k - 1 when negative (else 0), so when e +
 * b's low k bits are at most 2^k - 9 every Q in [e, e + 7] gives e + b's;
 * with e < 2^31 that test fails for e >= 2^31 - 7 (its low bits, or e -
 * 1's, are then at least 2^k - 8), so Q < 2^31.  No remainder: the common
 * case (all but 8 in 2^k), no branch on the sign; else
 * stp_project_correct.  0 when Q is 2^31 or more.  hot (a constant):
 * the shortcut laid out as the hot path, for callers that know f's bit
 * length (the mesh's vertices: M0+ torus 3 840 instructions, 5 697 cycles
 * fewer a frame; the direct frame's projection took 3 520 more with it) */
STP_HOT_INLINE int stp_project_offset_of(uint32_t e, int32_t sign, uint32_t n_low, uint32_t z, int32_t *out, int hot)
{
    const int k = STP_FIX_FRAC_BITS - STP_SUBPIXEL_BITS;
    const uint32_t mask = ((uint32_t)1 << k) - 1u;
    uint32_t b = e + ((uint32_t)sign & mask), q;
    int fast = mask >= 15u && e < 0x80000000u && ((~b & mask) >> 3) != 0;
    if (hot ? !STP_UNLIKELY(!fast) : fast) {
        *out = ((int32_t)(b >> k) ^ sign) - sign;
        return 1;
    }
    if (!stp_project_correct(e, n_low, z, &q))
        return 0;
    *out = stp_project_subpixel(sign != 0, q);
    return 1;
}
#endif

/* The offsets (stp_project_subpixel) of floor(f mx / z) and floor(f my /
 * z), px and py negative or not (nx, ny).  With STP_NARROW_FORMS each
 * estimate from stp_umulhi32_approx (three products; short of the high
 * word by at most 2, so Q - e < 8, and the remainder below 8 z < 2^32),
 * then stp_project_offset_of (hot: its layout). */
static inline int stp_project_quotients(uint32_t mx, uint32_t my, int nx, int ny, uint32_t f, uint32_t w, int sh,
                                        uint32_t z, int32_t *x, int32_t *y, int hot)
{
#if STP_NARROW_FORMS
    uint32_t ex, ey;
    if (sh <= 32) {
        if (((mx | my) >> (sh - 1)) > 1u) /* mx or my >= 2^sh */
            return 0;
        ex = stp_umulhi32_approx(mx << (32 - sh), w);
        ey = stp_umulhi32_approx(my << (32 - sh), w);
    } else {
        if (sh - 32 >= 32)
            w = 0u; /* the quotients 0 */
        ex = stp_umulhi32_approx(mx, w) >> (sh & 31); /* sh - 32 while sh < 64 */
        ey = stp_umulhi32_approx(my, w) >> (sh & 31);
    }
    return stp_project_offset_of(ex, -(int32_t)nx, f * mx, z, x, hot) &&
           stp_project_offset_of(ey, -(int32_t)ny, f * my, z, y, hot);
#else
    (void)hot;
    uint32_t qx, qy;
    if (!stp_project_quotient(mx, w, sh, f * mx, z, &qx) || !stp_project_quotient(my, w, sh, f * my, z, &qy))
        return 0;
    *x = stp_project_subpixel(nx, qx);
    *y = stp_project_subpixel(ny, qy);
    return 1;
#endif
}

/* floor(h 2^30 / z) exactly for 0 < h < 2^31 and 0 < z < 2^29 (z = dn
 * 2^-s, s >= 3, v as for stp_project_scale): P = h (2^32 + v) approximates
 * h 2^64 / dn from below within 3 h, so e = floor(P / 2^(34 - s)) is below
 * the quotient Q = h 2^(30 + s) / dn by at most 3 h 2^(s - 2) 2^-32 + 1 <=
 * 3 Q 2^-32 + 1 (h 2^(s - 2) < Q), under 3 for Q < 2^31
 * (stp_project_correct): P's high word and one product fewer than
 * stp_project_scale and stp_project_quotients take.  0 when the quotient is
 * 2^31 or more. */
static inline int stp_project_key(uint32_t h, uint32_t v, int s, uint32_t z, uint32_t *q)
{
    uint32_t ph = h + stp_umulhi32x32(h, v), pl = h * v; /* P = ph 2^32 + pl, ph < 2^32 */
    int k = 34 - s; /* in [3, 31] */
    if ((ph >> k) != 0)
        return 0; /* e >= 2^32 */
    return stp_project_correct((ph << (32 - k)) | (pl >> k), h << 30, z, q);
}

#if STP_PROJECT_DIVIDES
/* floor(f m / z) exactly for f, m < 2^31 and 0 < z < 2^29, without a
 * 32-bit product (AVR: each is a library call, and the reciprocal's 64-bit
 * products are four more): restoring division of f m, whose bits come
 * from a shift-and-add product over m's bits (where the core multiplies:
 * C's 64-bit product, libgcc's on ARMv6-M), one quotient bit a step.
 * The quotient is below 2^31 exactly when floor(f m / 2^31) is below z
 * (f m < 2^62); the remainder r then stays below z < 2^29, so 2 r + 1
 * fits.  0 when the quotient is 2^31 or more (stp_project_quotients'
 * cases: the same values). */
static inline int stp_project_divide(uint32_t f, uint32_t m, uint32_t z, uint32_t *q)
{
    uint32_t hi = 0, lo = 0;
    uint8_t i;
#if STP_HAVE_MUL32
    {
        uint64_t p = (uint64_t)f * m; /* size-first: libgcc's product on ARMv6-M */
        hi = (uint32_t)(p >> 32);
        lo = (uint32_t)p;
    }
#else
    /* hi 2^32 + lo = f m (bit tests and carries rather than shifts of
     * the top bit: the short code on an 8-bit core) */
    for (i = 0; i < 32u; i++) {
        hi <<= 1;
        if (lo & 0x80000000u)
            hi |= 1u;
        lo <<= 1;
        if (m & 0x80000000u) {
            lo += f;
            if (lo < f)
                hi++;
        }
        m <<= 1;
    }
#endif
    /* hi = floor(f m / 2^31), lo the other 31 bits at its top: each step
     * moves one into the remainder and the quotient bit into lo's bottom,
     * so after 31 steps lo is the quotient */
    hi <<= 1;
    if (lo & 0x80000000u)
        hi |= 1u;
    lo <<= 1;
    if (hi >= z)
        return 0;
    for (i = 0; i < 31u; i++) {
        hi <<= 1;
        if (lo & 0x80000000u)
            hi |= 1u;
        lo <<= 1;
        if (hi >= z) {
            hi -= z;
            lo |= 1u;
        }
    }
    *q = lo;
    return 1;
}
#endif

#if STP_PROJECT_DIVIDES
/* One offset of the 32-bit form by division (STP_PROJECT_DIVIDES):
 * stp_project_subpixel of floor(f |c| / z); 0 when |c| or the quotient is
 * 2^31 or more. */
static inline int stp_project_offset(uint32_t f, int32_t c, uint32_t z, int32_t *out)
{
    uint32_t m = c < 0 ? 0u - (uint32_t)c : (uint32_t)c, q;
    if (m >= 0x80000000u || !stp_project_divide(f, m, z, &q))
        return 0;
    *out = stp_project_subpixel(c < 0, q);
    return 1;
}
#endif

/* The depth key of view depth z (stp_fix, hither h <= z < 2^29):
 * floor(h 2^30 / z), in [1, 2^30], the key the projection gives every
 * point at depth z (stp_project_exact_bits, stp_project_wide: every form);
 * a larger key is nearer.  Direct drawing's painter's sort keys its faces
 * so.  Here by restoring division or the reciprocal of z, as
 * stp_project_exact_bits forms it (z >= h keeps the quotient below
 * 2^31). */
static inline int32_t stp_project_depth_key(uint32_t h, uint32_t z)
{
    uint32_t q = 0;
#if STP_PROJECT_DIVIDES
    (void)stp_project_divide(h, (uint32_t)1 << 30, z, &q);
#else
    int s = 32 - stp_bit_length32(z);
    (void)stp_project_key(h, stp_recip32_estimate(z << s), s, z, &q);
#endif
    return (int32_t)q;
}

/* The 32-bit form (z already raised to hither): 1 on success, 0 when z or
 * a quotient is out of its range (then the 64-bit quotients; *x, *y and
 * *key may have been written).  fb: stp_bit_length32(f), or -1 (not
 * known: stp_project_scale). */
static inline int stp_project_exact_bits(uint32_t f, int fb, uint32_t h, uint32_t z, int32_t px, int32_t py,
                                         int32_t *x, int32_t *y, int32_t *key)
{
#if STP_PROJECT_DIVIDES
    (void)fb;
    if (z >= ((uint32_t)1 << 29) || f >= 0x80000000u || h >= 0x80000000u ||
        !stp_project_offset(f, px, z, x) || !stp_project_offset(f, py, z, y))
        return 0;
    if (key)
        *key = stp_project_depth_key(h, z); /* z >= h: below 2^31 */
    return 1;
#else
    uint32_t mx, my, qk, w, v;
    int sz, sh;
    /* f, h < 2^31 (> 0 as stp_fix): one test for both */
    if (z >= ((uint32_t)1 << 29) || ((f | h) & 0x80000000u) != 0)
        return 0;
    sz = 32 - stp_bit_length32(z);
    v = stp_recip32_estimate(z << sz);
    /* the key first: fewer values live (ARMv6-M) */
    if (key) {
        if (!stp_project_key(h, v, sz, z, &qk))
            return 0;
        *key = (int32_t)qk;
    }
    stp_project_scale(f, fb, v, sz, &w, &sh);
    mx = px < 0 ? 0u - (uint32_t)px : (uint32_t)px;
    my = py < 0 ? 0u - (uint32_t)py : (uint32_t)py;
    return ((mx | my) & 0x80000000u) == 0 && stp_project_quotients(mx, my, px < 0, py < 0, f, w, sh, z, x, y, fb >= 0);
#endif
}

static inline int stp_project_exact(uint32_t f, uint32_t h, uint32_t z, int32_t px, int32_t py, int32_t *x,
                                    int32_t *y, int32_t *key)
{
    return stp_project_exact_bits(f, -1, h, z, px, py, x, y, key);
}
#endif

#if STP_WIDE_ARITH
/* The depth key of view depth z (stp_fix, 0 < hither h <= z): floor(h
 * 2^30 / z) (the 32-bit form's comment above), by C's 64-bit quotient;
 * 64-bit operands, as the projection holds them. */
static inline int32_t stp_project_depth_key(int64_t h, int64_t z)
{
    return (int32_t)stp_div64_fast(h << 30, z);
}

/* stp_view_perspective_wide where 64-bit division is one instruction:
 * inline, C's quotients (stp_div64_fast). */
static inline void stp_project_wide(stp_fix focal, stp_fix hither, const stp_vec3 *p, int64_t *x, int64_t *y,
                                    int32_t *key)
{
    int64_t z = p->z < hither ? hither : p->z; /* > 0 */
    *x = stp_asr64(stp_div64_fast((int64_t)focal * p->x, z), STP_FIX_FRAC_BITS - STP_SUBPIXEL_BITS);
    *y = stp_asr64(stp_div64_fast((int64_t)focal * p->y, z), STP_FIX_FRAC_BITS - STP_SUBPIXEL_BITS);
    if (key)
        *key = stp_project_depth_key(hither, z);
}
#define STP_PROJECT_WIDE stp_project_wide /* inline here */
#else
#define STP_PROJECT_WIDE stp_view_perspective_wide
#endif

/* The projection of p (stp_view_perspective_wide's values, every form). */
static inline void stp_view_perspective(stp_fix focal, stp_fix hither, stp_vec3 p, int64_t *x, int64_t *y,
                                        int32_t *key)
{
#if !STP_WIDE_ARITH
    int32_t x32, y32;
    if (stp_project_exact((uint32_t)focal, (uint32_t)hither, (uint32_t)(p.z < hither ? hither : p.z), p.x, p.y,
                          &x32, &y32, key)) {
        *x = x32;
        *y = y32;
        return;
    }
#endif
    STP_PROJECT_WIDE(focal, hither, &p, x, y, key);
}

/* The device position of view point *p (perspective, clipped: inside up
 * to rounding), Q27.4, and its depth key: out[0] = half_width + the
 * offset, out[1] = half_height - the offset, clamped to [-gx, 2 half_width
 * + gx] and [-gy, 2 half_height + gy], g the guard band's (0 without it;
 * the clipper keeps points inside up to rounding: the clamp takes its last
 * bit), out[2] the key.  Each sum is formed moved by the guard, so the
 * clamp is the one to [0, limit]. */
static inline void stp_project_device_wide(const stp_view_lens *lens, const stp_vec3 *p, int32_t out[3])
{
    int64_t dx, dy;
    STP_PROJECT_WIDE(lens->focal, lens->hither, p, &dx, &dy, &out[2]);
    dx = lens->half_width + STP_LENS_GUARD_X(lens) + dx;
    dy = lens->half_height + STP_LENS_GUARD_Y(lens) - dy;
#if STP_WIDE_ARITH
    /* the hosts' per-vertex form: one unsigned test each for the common
     * case inside [0, 2 half] (3 instructions a coordinate fewer; where
     * this is the 32-bit form's rare fallback, the shorter code below) */
    if (STP_UNLIKELY((uint64_t)dx > (uint64_t)(2 * ((int64_t)lens->half_width + STP_LENS_GUARD_X(lens)))))
        dx = dx < 0 ? 0 : 2 * ((int64_t)lens->half_width + STP_LENS_GUARD_X(lens));
    if (STP_UNLIKELY((uint64_t)dy > (uint64_t)(2 * ((int64_t)lens->half_height + STP_LENS_GUARD_Y(lens)))))
        dy = dy < 0 ? 0 : 2 * ((int64_t)lens->half_height + STP_LENS_GUARD_Y(lens));
    out[0] = (int32_t)dx - STP_LENS_GUARD_X(lens);
    out[1] = (int32_t)dy - STP_LENS_GUARD_Y(lens);
#else
    out[0] = (int32_t)(dx < 0 ? 0
                              : (dx > 2 * (lens->half_width + STP_LENS_GUARD_X(lens))
                                     ? 2 * (lens->half_width + STP_LENS_GUARD_X(lens))
                                     : dx)) -
             STP_LENS_GUARD_X(lens);
    out[1] = (int32_t)(dy < 0 ? 0
                              : (dy > 2 * (lens->half_height + STP_LENS_GUARD_Y(lens))
                                     ? 2 * (lens->half_height + STP_LENS_GUARD_Y(lens))
                                     : dy)) -
             STP_LENS_GUARD_Y(lens);
#endif
}

#if STP_WIDE_ARITH
#define stp_view_perspective_device stp_project_device_wide
#define stp_view_perspective_device_bits(lens, fb, p, out) stp_project_device_wide(lens, p, out)
#else
/* Where 64-bit division is a library call: the 32-bit form inline, the
 * 64-bit quotients out of line (view_private.h's
 * stp_view_perspective_device_wide), so the common path keeps fewer values
 * live. */

/* c clamped to [0, limit] (limit >= 0): one unsigned test inside */
STP_HOT_INLINE int32_t stp_project_clamp(int32_t c, int32_t limit)
{
    if ((uint32_t)c > (uint32_t)limit)
        c = c < 0 ? 0 : limit;
    return c;
}

/* fb: stp_bit_length32(lens->focal), found once for many points (or -1:
 * stp_project_exact_bits) */
static inline int stp_view_perspective_device_exact(const stp_view_lens *lens, int fb, const stp_vec3 *p,
                                                    int32_t out[3])
{
    int32_t x32, y32;
    if (!stp_project_exact_bits((uint32_t)lens->focal, fb, (uint32_t)lens->hither,
                                (uint32_t)(p->z < lens->hither ? lens->hither : p->z), p->x, p->y, &x32, &y32,
                                &out[2]))
        return 0;
    /* |offset| < 2^(31 - 12): the sums fit int32 (moved by the guard
     * band's, 0 without it: stp_project_device_wide) */
    out[0] = stp_project_clamp(lens->half_width + STP_LENS_GUARD_X(lens) + x32,
                               2 * (lens->half_width + STP_LENS_GUARD_X(lens))) - STP_LENS_GUARD_X(lens);
    out[1] = stp_project_clamp(lens->half_height + STP_LENS_GUARD_Y(lens) - y32,
                               2 * (lens->half_height + STP_LENS_GUARD_Y(lens))) - STP_LENS_GUARD_Y(lens);
    return 1;
}

static inline void stp_view_perspective_device_bits(const stp_view_lens *lens, int fb, const stp_vec3 *p,
                                                    int32_t out[3])
{
    if (!stp_view_perspective_device_exact(lens, fb, p, out))
        stp_view_perspective_device_wide(lens, p, out);
}

static inline void stp_view_perspective_device(const stp_view_lens *lens, const stp_vec3 *p, int32_t out[3])
{
    stp_view_perspective_device_bits(lens, -1, p, out);
}
#endif

#endif
