/* SPDX-License-Identifier: MIT */
/*
 * Private: the target's arithmetic, the bottom layer of the core.  What a
 * target can do in one instruction decides which form of a product,
 * quotient or bit count the core compiles, not its pointer width:
 *
 *   STP_HAVE_MUL64  a 32 x 32 -> 64-bit multiply (x86-64, AArch64, ARMv7-M
 *                   and ARMv8-M Mainline: UMULL/SMULL, 32-bit ARM, RISC-V
 *                   with M: MUL + MULHU).  Not ARMv6-M (Cortex-M0/M0+/M1),
 *                   ARMv8-M Baseline (Cortex-M23), AVR: there a 64-bit
 *                   product is a library call, and the core forms it from
 *                   16-bit halves.
 *   STP_HAVE_CLZ    a count-leading-zeros instruction (x86-64, AArch64,
 *                   ARMv5T and later but ARMv6-M, RISC-V with Zbb); without
 *                   it GCC's __builtin_clz is a library call, and the core
 *                   counts with three halvings and a 16-entry table.
 *   STP_HAVE_DIV    a 32-bit hardware divide (x86-64, AArch64, ARMv7-M,
 *                   ARMv7-R, RISC-V with M).
 *   STP_HAVE_DIV64  a 64-bit divide in one instruction (64-bit hosts only):
 *                   elsewhere a 64-bit quotient is a library call of some
 *                   hundreds of instructions, and the core divides through
 *                   reciprocals (recip.c) or 32-bit quotients.
 *
 * Each is 0 or 1, found from the compiler's predefined macros and
 * overridable with -D.  STP_WIDE_ARITH, the name the rasterizer and the
 * shading test, is STP_HAVE_MUL64 && STP_HAVE_DIV64: "64-bit products and
 * quotients are single instructions".  -DSTP_WIDE_ARITH=0 forces the 32-bit
 * target arithmetic (all four capabilities 0 unless given too), so the
 * host's tests check the code a Cortex-M0+ runs.
 *
 * The primitives below give the same values in every form.
 */
#ifndef STIPPLE_ARITH_PRIVATE_H
#define STIPPLE_ARITH_PRIVATE_H

#include <stdint.h>

#include "stipple/config.h" /* STP_SMALL_DIVISION: a size-first build */

/* ---- capabilities ---- */

#if defined(STP_WIDE_ARITH) && !STP_WIDE_ARITH
/* forced 32-bit target arithmetic */
#define STP_ARITH_DETECTED_ 0
#endif

#ifndef STP_HAVE_MUL64
#if defined(STP_ARITH_DETECTED_)
#define STP_HAVE_MUL64 0
#elif defined(__x86_64__) || defined(_M_X64) || defined(__i386__) || defined(__aarch64__) ||       \
    (defined(__riscv) && defined(__riscv_mul)) || defined(__ARM_ARCH_ISA_ARM) ||                \
    (defined(__ARM_ARCH_ISA_THUMB) && __ARM_ARCH_ISA_THUMB >= 2)
#define STP_HAVE_MUL64 1
#elif defined(UINTPTR_MAX) && UINTPTR_MAX > 0xFFFFFFFFu
#define STP_HAVE_MUL64 1 /* another 64-bit host */
#else
#define STP_HAVE_MUL64 0
#endif
#endif

#ifndef STP_HAVE_CLZ
#if defined(STP_ARITH_DETECTED_) || !defined(__GNUC__)
#define STP_HAVE_CLZ 0
#elif defined(__x86_64__) || defined(__aarch64__) || defined(__ARM_FEATURE_CLZ) ||              \
    (defined(__riscv) && defined(__riscv_zbb))
#define STP_HAVE_CLZ 1
#else
#define STP_HAVE_CLZ 0
#endif
#endif

#ifndef STP_HAVE_DIV
#if defined(STP_ARITH_DETECTED_)
#define STP_HAVE_DIV 0
#elif defined(__x86_64__) || defined(_M_X64) || defined(__i386__) || defined(__aarch64__) ||       \
    defined(__ARM_FEATURE_IDIV) || (defined(__riscv) && defined(__riscv_div))
#define STP_HAVE_DIV 1
#else
#define STP_HAVE_DIV 0
#endif
#endif

#ifndef STP_HAVE_DIV64
#if defined(STP_ARITH_DETECTED_)
#define STP_HAVE_DIV64 0
#elif defined(UINTPTR_MAX) && UINTPTR_MAX > 0xFFFFFFFFu
#define STP_HAVE_DIV64 1
#else
#define STP_HAVE_DIV64 0
#endif
#endif

/* A 32 x 32 -> 32-bit multiply instruction: every 32-bit CPU; not an 8- or
 * 16-bit one (AVR, MSP430), where a 32-bit product is a library call of
 * about 50 cycles, so loops step sums instead of forming products. */
#ifndef STP_HAVE_MUL32
#if defined(__AVR__) || defined(__MSP430__)
#define STP_HAVE_MUL32 0
#else
#define STP_HAVE_MUL32 1
#endif
#endif

#ifndef STP_WIDE_ARITH
#define STP_WIDE_ARITH (STP_HAVE_MUL64 && STP_HAVE_DIV64)
#endif

/* A 32-bit form beside a 64-bit one (the same values for operands in its
 * range) pays where 64-bit products are library calls and 32-bit ones
 * single instructions (ARMv6-M, ARMv8-M Baseline), in a build for speed;
 * on an 8-bit core every product is a library call, and there and in a
 * build for size (-Os) the 64-bit form alone is the smaller code. */
#if !STP_HAVE_MUL64 && STP_HAVE_MUL32 && !defined(__OPTIMIZE_SIZE__)
#define STP_NARROW_FORMS 1
#else
#define STP_NARROW_FORMS 0
#endif

/* ---- target helpers ---- */

/* A small function forced inline where a call would cost as much as its
 * body, except in builds for size (-Os), which keep it a call. */
#if defined(__GNUC__) && !defined(__OPTIMIZE_SIZE__)
#define STP_HOT_INLINE static inline __attribute__((always_inline))
#else
#define STP_HOT_INLINE static inline
#endif

/* A condition the hot path expects false: its branch laid out of the way
 * (the compiler's choice otherwise). */
#if defined(__GNUC__)
#define STP_UNLIKELY(c) __builtin_expect(!!(c), 0)
#else
#define STP_UNLIKELY(c) (c)
#endif

/* A function kept out of line (a cold route beside a hot one). */
#if defined(__GNUC__)
#define STP_NOINLINE static __attribute__((noinline))
#else
#define STP_NOINLINE static
#endif

/* STP_LEAN_CODE 1: a build for size (-Os) for a target without a multiply
 * instruction (AVR), where every 32-bit operation is several instructions:
 * loops over a vector's three components stay loops and small helpers are
 * calls, a third of the code.  Elsewhere both cost more time than bytes. */
#if defined(__OPTIMIZE_SIZE__) && !STP_HAVE_MUL32
#define STP_LEAN_CODE 1
#else
#define STP_LEAN_CODE 0
#endif

/* A small function called from several places: one out-of-line copy per
 * file with STP_LEAN_CODE (on AVR a 32-bit product of halves is about 100
 * bytes), else as STP_HOT_INLINE. */
#if defined(__GNUC__) && STP_LEAN_CODE
#define STP_SIZE_CALL static __attribute__((noinline, unused))
#else
#define STP_SIZE_CALL STP_HOT_INLINE
#endif

/* v mod 2^16: on Thumb-1 cores with UXTH (ARMv6-M, ARMv8-M Baseline) that
 * one instruction in builds for speed, where GCC (12) forms v & 0xFFFF
 * with two shifts; builds for size keep the plain form (with UXTH there
 * the Cortex-M0+ -Os face shade took 20 instructions more, for 4 to 24
 * bytes less). */
static inline uint32_t stp_lo16(uint32_t v)
{
#if defined(__GNUC__) && defined(__thumb__) && !defined(__thumb2__) && defined(__ARM_ARCH) && __ARM_ARCH >= 6 && \
    !defined(__OPTIMIZE_SIZE__)
    uint32_t h;
    __asm__("uxth %0, %1" : "=l"(h) : "l"(v));
    return h;
#else
    return v & 0xFFFFu;
#endif
}

/* v >= 2^k for a 32-bit unsigned v and constant k: a shift's test on
 * cores with a 32-bit multiply (ARMv6-M: one instruction fewer than
 * loading the constant), the comparison on 8-bit cores (a 32-bit shift
 * is a loop or four byte moves there). */
#define STP_AT_LEAST_POW2(v, k) (STP_HAVE_MUL32 ? ((uint32_t)(v) >> (k)) != 0 : (uint32_t)(v) >= ((uint32_t)1 << (k)))

/* A few loads chosen by an index, as in a loop over a vector's components:
 * inlined in every build (once the loop is unrolled the index is a
 * constant and the choice disappears) but STP_LEAN_CODE's calls. */
#if defined(__GNUC__) && !STP_LEAN_CODE
#define STP_INDEX_INLINE static inline __attribute__((always_inline))
#else
#define STP_INDEX_INLINE STP_SIZE_CALL
#endif

/* Before a loop over a vector's three components: unrolled (GCC at -O2
 * and -Os keeps such a loop a loop) but with STP_LEAN_CODE and in
 * size-first builds (-Os with STP_SMALL_DIVISION: the lean direct core
 * 6 564 -> 6 532 B). */
#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 8 && !STP_LEAN_CODE &&                        \
    !(defined(__OPTIMIZE_SIZE__) && STP_SMALL_DIVISION)
#define STP_UNROLL3 _Pragma("GCC unroll 3")
#define STP_UNROLL4 _Pragma("GCC unroll 4") /* the same, four times */
#else
#define STP_UNROLL3
#define STP_UNROLL4
#endif

/* floor(v / 2^s) for any int32 v, 0 <= s <= 31.  C leaves >> of a
 * negative value to the implementation: where it is the arithmetic shift
 * (every compiler the project builds with; the test folds away) that
 * shift, else the complement form, exact everywhere (gcc-avr does not
 * fold the complement form into a shift: twice the code). */
static inline int32_t stp_asr32(int32_t v, int s)
{
    if ((int32_t)-1 >> 1 == (int32_t)-1)
        return v >> s;
    return v >= 0 ? v >> s : (int32_t)~(~(uint32_t)v >> s);
}

/* |v| as unsigned, exact for every int32 v (2^31 for the most negative). */
static inline uint32_t stp_abs32(int32_t v)
{
    return v < 0 ? 0u - (uint32_t)v : (uint32_t)v;
}

/* |v| as unsigned, exact for every int64 v (2^63 for the most negative). */
static inline uint64_t stp_abs64u(int64_t v)
{
    return v < 0 ? 0u - (uint64_t)v : (uint64_t)v;
}

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

/* ---- products ---- */

/* a b exactly for 32-bit a and b: one instruction (or two: RISC-V's MUL
 * and MULHU) with STP_HAVE_MUL64, else four 32-bit products of 16-bit
 * halves (ARMv6-M has no 32 x 32 -> 64 multiply; libgcc's 64-bit one costs
 * ~40 instructions a call). */
static inline uint64_t stp_umul32x32(uint32_t a, uint32_t b)
{
#if STP_HAVE_MUL64 || !STP_HAVE_MUL32
    /* without even a 32-bit multiply (AVR) the halves below are four
     * library products; the C library's widening one (AVR: __umulsidi3,
     * on the 8 x 8 MUL) is smaller and faster, and exact the same */
    return (uint64_t)a * b;
#else
    uint32_t al = stp_lo16(a), ah = a >> 16, bl = stp_lo16(b), bh = b >> 16;
    uint32_t ll = al * bl, lh = al * bh, hl = ah * bl, hh = ah * bh;
    uint32_t mid = (ll >> 16) + stp_lo16(lh) + stp_lo16(hl); /* < 3 2^16 */
    return ((uint64_t)(hh + (lh >> 16) + (hl >> 16) + (mid >> 16)) << 32) |
           (uint64_t)((mid << 16) | stp_lo16(ll));
#endif
}

/* a b exactly for signed 32-bit a and b */
static inline int64_t stp_smul32x32(int32_t a, int32_t b)
{
#if STP_HAVE_MUL64 || !STP_HAVE_MUL32 /* as stp_umul32x32 */
    return (int64_t)a * b;
#else
    uint64_t p = stp_umul32x32(a < 0 ? 0u - (uint32_t)a : (uint32_t)a,
                               b < 0 ? 0u - (uint32_t)b : (uint32_t)b);
    return (a < 0) != (b < 0) ? -(int64_t)p : (int64_t)p;
#endif
}

/* floor(a b / 2^32) exactly: the high word of a 32 x 32-bit product,
 * without the low word's 32-bit assembly where the product is formed from
 * halves. */
static inline uint32_t stp_umulhi32x32(uint32_t a, uint32_t b)
{
#if STP_HAVE_MUL64 || !STP_HAVE_MUL32 /* as stp_umul32x32 */
    return (uint32_t)(((uint64_t)a * b) >> 32);
#else
    /* the middle products added one at a time, each sum below 2^32
     * (2^16 + (2^16 - 1)^2): fewer values live at once */
    uint32_t al = stp_lo16(a), ah = a >> 16, bl = stp_lo16(b), bh = b >> 16;
    uint32_t t = ((al * bl) >> 16) + al * bh;
    uint32_t u = stp_lo16(t) + ah * bl;
    return ah * bh + (t >> 16) + (u >> 16);
#endif
}

/* floor(u / 3) exactly, without a division (a library call of ~120
 * instructions on ARMv6-M).  With a 64-bit product: u ceil(2^33 / 3) /
 * 2^33 (0xAAAAAAAB exceeds 2^33 / 3 by 1/3, and that times u / 2^33 < 1/2
 * stays below the 1/3 gap to the next integer).  Without one, from 32-bit
 * products: stp_div3_u30 for u < 2^30 (a coordinate sum's size): u = a
 * 2^14 + b with 2^14 = 3 5461 + 1 gives floor(u / 3) = 5461 a +
 * floor(x / 3), x = a + b < 2^16 + 2^14; and for x < 2^17, (x 0xAAAB) >>
 * 17 = floor(x / 3 + x / (3 2^17)) is floor(x / 3) (the excess below 1/3),
 * the product below 1.25 2^16 0xAAAB < 2^32: two products, no branch.
 * stp_div3_u32 takes any u: below 2^16 one product ((u 0xAAAB) >> 17:
 * 3 0xAAAB = 2^17 + 1, the excess u / (3 2^17) below 1/3), up to 2^30
 * stp_div3_u30, beyond the 64-bit product from halves out of line
 * (stp_div3_large). */
static inline uint32_t stp_div3_u30(uint32_t u)
{
#if STP_HAVE_MUL64
    return (uint32_t)(stp_umul32x32(u, 0xAAAAAAABu) >> 33);
#else
    uint32_t a = u >> 14;
    return 5461u * a + (((a + (u & 0x3FFFu)) * 0xAAABu) >> 17);
#endif
}

#if !STP_HAVE_MUL64
#if defined(__GNUC__)
__attribute__((noinline, unused))
#endif
static uint32_t stp_div3_large(uint32_t u)
{
    return (uint32_t)(stp_umul32x32(u, 0xAAAAAAABu) >> 33);
}
#endif

static inline uint32_t stp_div3_u32(uint32_t u)
{
#if !STP_HAVE_MUL64
    if (u < 0x10000u) /* a small triangle's coordinate sums: one product */
        return (u * 0xAAABu) >> 17;
    if (u >= 0x40000000u)
        return stp_div3_large(u);
#endif
    return stp_div3_u30(u);
}

/* v / 3 truncated toward zero, as C's operator, for any int32 v */
static inline int32_t stp_div3_toward_zero(int32_t v)
{
    uint32_t q = stp_div3_u32(v < 0 ? 0u - (uint32_t)v : (uint32_t)v);
    return v < 0 ? 0 - (int32_t)q : (int32_t)q;
}

/* The high word of a b for 32-bit a and b, short of floor(a b / 2^32) by
 * at most 2 (the low halves' product and the carries out of the middle
 * products' low halves are dropped): three 32-bit products without
 * STP_HAVE_MUL64; exact with it.  For products whose last two units do not
 * matter. */
STP_SIZE_CALL uint32_t stp_umulhi32_approx(uint32_t a, uint32_t b)
{
#if STP_HAVE_MUL64
    return (uint32_t)(((uint64_t)a * b) >> 32);
#elif !STP_HAVE_MUL32
    /* 16 x 16 -> 32-bit products written as such (the operands' types say
     * so), which an 8-bit target forms by its short widening helper
     * rather than a 32 x 32 one */
    uint16_t ah = (uint16_t)(a >> 16), al = (uint16_t)a, bh = (uint16_t)(b >> 16), bl = (uint16_t)b;
    return (uint32_t)ah * bh + (((uint32_t)ah * bl) >> 16) + (((uint32_t)al * bh) >> 16);
#else
    uint32_t ah = a >> 16, bh = b >> 16;
    return ah * bh + ((ah * stp_lo16(b)) >> 16) + ((stp_lo16(a) * bh) >> 16);
#endif
}

/* a b for operands held in 64-bit (or narrower) variables whose values
 * are known to fit 32 bits: on 64-bit hosts C's product of the variables
 * as they are (no narrowing instruction), elsewhere stp_smul32x32 /
 * stp_umul32x32 of their low words (one UMULL on a Cortex-M3). */
#if STP_WIDE_ARITH
#define STP_SMUL_FIT32(a, b) ((int64_t)(a) * (int64_t)(b))
#define STP_UMUL_FIT32(a, b) ((uint64_t)(a) * (uint64_t)(b))
#else
#define STP_SMUL_FIT32(a, b) stp_smul32x32((int32_t)(a), (int32_t)(b))
#define STP_UMUL_FIT32(a, b) stp_umul32x32((uint32_t)(a), (uint32_t)(b))
#endif

/* ---- bit counts ---- */

/* Significant bits of v (0 for 0, else floor(log2 v) + 1): one
 * instruction with STP_HAVE_CLZ; in other builds for size on cores with a
 * 32-bit multiply (ARMv6-M) GCC's __builtin_clz, the C library's one copy
 * (its three halvings and table, which stp_bit_length64 links anyway),
 * not this function's copy in each file; else three halvings of the range
 * and a 16-entry table. */
#if STP_HAVE_CLZ || (defined(__GNUC__) && defined(__OPTIMIZE_SIZE__) && STP_HAVE_MUL32)
#define STP_BIT_LENGTH_CLZ 1 /* stp_bit_length32 is __builtin_clz's */
#else
#define STP_BIT_LENGTH_CLZ 0
#endif
STP_HOT_INLINE int stp_bit_length32(uint32_t v)
{
#if STP_BIT_LENGTH_CLZ
    return v == 0 ? 0 : 32 - __builtin_clz(v);
#elif STP_LEAN_CODE
    /* a byte at a time (a move on an 8-bit core), then bit by bit: a
     * quarter of the code of the table's form there */
    int n = 32;
    if (v == 0)
        return 0;
    while ((v & 0xFF000000u) == 0) {
        v <<= 8;
        n -= 8;
    }
    while ((v & 0x80000000u) == 0) {
        v <<= 1;
        n--;
    }
    return n;
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

/* Number of significant bits of v (0 for 0). */
static inline int stp_bit_length64(uint64_t v)
{
#if defined(__GNUC__)
    return v == 0 ? 0 : 64 - __builtin_clzll(v);
#else
    uint32_t high = (uint32_t)(v >> 32);
    return high != 0 ? 32 + stp_bit_length32(high) : stp_bit_length32((uint32_t)v);
#endif
}

#endif
