/* SPDX-License-Identifier: MIT */
/* Private: a frame's depth keys mapped to Q12 depths for the Z buffer
 * (depth_private.h, the depth stage): the keys' range over the polygons a
 * frame stores, and each key's depth 2^12 + floor((key - key_min) 65534
 * 2^12 / range), in [2^12, 65535 2^12] (a larger key, nearer, deeper
 * into the buffer's 1..65535).  Keys are int32 in [1, 2^30]
 * (project_private.h's stp_project_depth_key); the range is below 2^32,
 * so every product and quotient here fits 64 bits, and 32 where the
 * reciprocal stands for the division (narrow arithmetic). */
#ifndef STIPPLE_DEPTH_KEYS_PRIVATE_H
#define STIPPLE_DEPTH_KEYS_PRIVATE_H

#include <stdint.h>

#include "stipple/config.h"
#include "arith_private.h"
#include "div64_private.h" /* STP_DIV64 */

/* a function some includers do not call (raster.c without its triangle
 * path) */
#if defined(__GNUC__)
#define DEPTH_MAYBE_UNUSED __attribute__((unused))
#else
#define DEPTH_MAYBE_UNUSED
#endif

/* A frame's depth keys: their range over the polygons it stores and the
 * mapping's scale (depth_keys_set). */
typedef struct depth_keys {
    int32_t key_min, key_max; /* depth-key range of the visible polygons */
    uint32_t key_range;       /* key_max - key_min, when positive */
    uint32_t depth_scale;     /* depth_q12_of's reciprocal and its shift (wide arithmetic: its factor) */
    int depth_shift;
} depth_keys;

/* *k for the keys key_min .. key_max (key_max < key_min: no polygon,
 * every key then maps to 65535 2^12, as does any key when they are
 * equal). */
DEPTH_MAYBE_UNUSED static void depth_keys_set(depth_keys *k, int32_t key_min, int32_t key_max)
{
    k->key_min = key_min;
    k->key_max = key_max;
    k->key_range = 0;
    k->depth_scale = 0;
    k->depth_shift = 0;
    if (key_max > key_min) {
        k->key_range = (uint32_t)key_max - (uint32_t)key_min;
#if STP_WIDE_ARITH
        k->depth_scale = (uint32_t)65534 << 12; /* key_quotient's factor */
#else
        while (((uint64_t)1 << k->depth_shift) <= k->key_range)
            k->depth_shift++;
        k->depth_scale = (uint32_t)STP_DIV64(((uint64_t)65534 << 12) << k->depth_shift, k->key_range);
#endif
    }
}

/* Depth key mapped to the Z buffer's 1..65535 with 12 fractional bits:
 * 2^12 + floor(u 65534 2^12 / range), u = key - key_min <= range < 2^32.
 * Without wide arithmetic the quotient comes from the frame's reciprocal:
 * depth_scale = floor(65534 2^12 2^s / range) < 2^29 with 2^s > range (s =
 * depth_shift), so u depth_scale / 2^s is less than one short of the
 * quotient and one correction makes it exact. */
#if !STP_WIDE_ARITH
/* key_quotient for key ranges of 2^31 or more (depth_shift 32): out of
 * line where speed comes first, so the common case's call saves no high
 * registers for it (inline in builds for size: one call less) */
#if defined(__OPTIMIZE_SIZE__)
DEPTH_MAYBE_UNUSED static uint32_t key_quotient_wide(const depth_keys *k, uint32_t u)
#else
DEPTH_MAYBE_UNUSED STP_NOINLINE uint32_t key_quotient_wide(const depth_keys *k, uint32_t u)
#endif
{
    uint64_t num = stp_umul32x32(u, (uint32_t)65534 << 12);
    uint32_t q = (uint32_t)(stp_umul32x32(u, k->depth_scale) >> k->depth_shift);
    if (stp_umul32x32(q + 1u, k->key_range) <= num)
        q++;
    return q;
}
#endif

DEPTH_MAYBE_UNUSED static uint32_t key_quotient(const depth_keys *k, uint32_t u)
{
#if STP_WIDE_ARITH
    /* the factor 65534 2^12 from the frame (depth_scale): a product by the
     * constant is made of shifts and a subtraction, four instructions to
     * one multiply */
    return (uint32_t)(stp_umul32x32(u, k->depth_scale) / k->key_range);
#else
    const uint32_t scale = (uint32_t)65534 << 12;
    uint32_t q;
    if (k->depth_shift >= 32)
        return key_quotient_wide(k, u);
    /* u < 2^s: u 2^(32 - s) < 2^32, and its high product word is the
     * estimate; the remainder u k - q range is in [0, 2 range), below
     * 2^32 (range < 2^31 here), so its 32-bit wrap is exact */
    q = stp_umulhi32x32(u << (32 - k->depth_shift), k->depth_scale);
    if (u * scale - q * k->key_range >= k->key_range)
        q++;
    return q;
#endif
}

DEPTH_MAYBE_UNUSED static int32_t depth_q12_of(const depth_keys *k, int32_t key)
{
    /* the quotient is at most 65534 2^12: below 2^28 */
#if STP_WIDE_ARITH
    /* (marked unlikely: GCC then lays a triangle's three quotients out
     * with fewer spills, host mesh torus 400 instructions a frame fewer;
     * unmarked elsewhere, whose code stays as it was) */
    if (STP_UNLIKELY(k->key_max <= k->key_min))
#else
    if (k->key_max <= k->key_min)
#endif
        return (int32_t)65535 << 12;
    return (int32_t)(1 << 12) + (int32_t)key_quotient(k, (uint32_t)key - (uint32_t)k->key_min);
}

#endif
