/* SPDX-License-Identifier: MIT */
/* Reciprocals and exact 64-bit division without a divide instruction: see
 * recip_private.h. */
#include "arith_private.h" /* STP_TABLE, products, bit counts */
#include "recip_private.h"

#if !STP_HAVE_MUL32
/* Without a 32-bit multiply (AVR, MSP430) the same floor by restoring
 * division of 2^64 - 1 by d, one quotient bit a step: about 60 bytes of
 * code and no 64-bit products, against the seed table and two Newton
 * steps' library multiplies.  The high word 2^32 - 1 >= d gives quotient
 * bit 32 (the implicit 2^32); r stays below d, and when 2 r + 1 reaches
 * 2^32 (r's top bit set) it exceeds d, so the subtraction is taken and
 * wraps back below d. */
uint32_t stp_recip32(uint32_t d)
{
    uint32_t r, v = 0;
    uint8_t i;
    if (d < 0x80000000u)
        return 0;
    r = 0xFFFFFFFFu - d;
    for (i = 0; i < 32u; i++) {
        uint32_t top = r & 0x80000000u;
        r = (r << 1) | 1u;
        v <<= 1;
        if (top != 0 || r >= d) {
            r -= d;
            v |= 1u;
        }
    }
    return v;
}
#else
#if STP_SMALL_DIVISION
/* round(2^25 / d) = floor((2^25 + floor(d / 2)) / d) for d in [513, 1024)
 * (recip_private.h): q = 2^25 / d by the chord of 1/x over [1/2, 1) (2^15
 * (48 - 32 x) / 17 at x = d / 1024, relative error below 1/17) and two
 * Newton steps q + q (n - d q) / 2^25 (to 2^-8.2, then within 2 units);
 * the remainder's corrections make it exact (for every d: at most one
 * step; |products| < 2^30).  88 bytes of code (ARMv6-M, -Os) in place of
 * the two tables' 768, in less time than a 32-bit division's loop. */
uint32_t stp_recip_seed(uint32_t d)
{
    int32_t n = ((int32_t)1 << 25) + (int32_t)(d >> 1), m = (int32_t)d;
    int32_t q = 92521 - (int32_t)((d * 15420u) >> 8), r;
    q += stp_asr32((q >> 4) * stp_asr32(n - m * q, 7), 14);
    q += stp_asr32((q >> 3) * (n - m * q), 22);
    r = n - m * q;
    while (r < 0) {
        q--;
        r += m;
    }
    while (r >= m) {
        q++;
        r -= m;
    }
    return (uint32_t)q;
}
/* the table's entries computed: 2^47 / m at interval i's middle is 2^25 /
 * (514 + 4 i) */
#define RECIP_SEED_AT(i) stp_recip_seed(514u + 4u * (i))
#else
/* RECIP_SEED[i] = round(2^24 / (257 + 2 i)): 2^47 / m at the middle of the
 * i-th of 128 equal intervals of m in [2^31, 2^32) (m's bits 30..24 are i).
 * Relative error against 2^47 / m anywhere in the interval: below
 * 1/(257 + 2 i) plus the rounding's 2^-17, under 1/257 everywhere (at an
 * interval's ends; half that in its middle).  Values in [32832, 65281]. */
static const uint16_t RECIP_SEED[128] STP_TABLE = {
    65281u, 64777u, 64281u, 63792u, 63310u, 62836u, 62369u, 61909u,
    61455u, 61008u, 60568u, 60133u, 59705u, 59283u, 58867u, 58457u,
    58053u, 57654u, 57260u, 56872u, 56489u, 56111u, 55738u, 55370u,
    55007u, 54649u, 54295u, 53946u, 53601u, 53261u, 52925u, 52593u,
    52265u, 51942u, 51622u, 51306u, 50995u, 50686u, 50382u, 50081u,
    49784u, 49490u, 49200u, 48913u, 48630u, 48349u, 48072u, 47798u,
    47528u, 47260u, 46995u, 46733u, 46474u, 46218u, 45965u, 45714u,
    45467u, 45222u, 44979u, 44739u, 44502u, 44267u, 44035u, 43805u,
    43577u, 43352u, 43129u, 42908u, 42690u, 42474u, 42260u, 42048u,
    41838u, 41631u, 41425u, 41222u, 41020u, 40820u, 40623u, 40427u,
    40233u, 40041u, 39851u, 39662u, 39476u, 39291u, 39108u, 38926u,
    38746u, 38568u, 38392u, 38217u, 38044u, 37872u, 37702u, 37533u,
    37366u, 37200u, 37036u, 36873u, 36712u, 36552u, 36393u, 36236u,
    36080u, 35926u, 35772u, 35620u, 35470u, 35320u, 35172u, 35026u,
    34880u, 34735u, 34592u, 34450u, 34309u, 34169u, 34031u, 33893u,
    33757u, 33622u, 33487u, 33354u, 33222u, 33091u, 32961u, 32832u,
};
#define RECIP_SEED_AT(i) STP_TABLE_U16(&RECIP_SEED[i])
#endif

uint32_t stp_recip32_estimate(uint32_t d)
{
    uint32_t y0, y1, u, dh = d >> 16, dl = stp_lo16(d), at, corr, v;
    uint64_t p;
    if (d < 0x80000000u)
        return 0;
    y0 = RECIP_SEED_AT((d >> 24) & 127u); /* ~ 2^47 / d */
    /* Newton step 1 in 32 bits: y1 = y0 2^16 + y0 (2^47 - d y0) / 2^31.
     * u = (2^47 - d y0) / 2^16 (mod 2^32; |u| < 2^23 as a signed value:
     * the seed's error is below 1/257); at / 2^8 keeps 15 bits of it, so
     * y0 (at >> 8) < 2^31 */
    u = 0x80000000u - dh * y0 - ((dl * y0) >> 16);
    at = u >= 0x80000000u ? 0u - u : u;
    corr = (y0 * (at >> 8)) >> 7;
    y1 = y0 << 16;
    if (u >= 0x80000000u)
        y1 -= corr;
    else
        y1 = corr > 0xFFFFFFFFu - y1 ? 0xFFFFFFFFu : y1 + corr;
    /* y1 ~ 2^63 / d within 2^-16.  Step 2 straight into v's scale:
     * v ~ 2 y1 - 2^32 + y1 e / 2^62 with the exact error e = 2^63 - d y1
     * (|e| < 2^47, so e / 2^15 fits 32 bits), the product's high word from
     * three partial products (stp_umulhi32_approx, fix_private.h).
     * Newton's step lands below 2^64 / d by the square of y1's error
     * (under a unit here) and every rounding is downwards: over all 2^31 values of d, v is the floor or
     * up to 2 below it (0.14 corrections on average; stp_recip32 corrects
     * it) */
    if (d == 0x80000000u)
        return 0xFFFFFFFFu; /* 2^64 / d - 2^32 = 2^32 exactly: the floor is one less */
    if (y1 < 0x80000000u)
        y1 = 0x80000000u; /* 2^63 / d > 2^31: clamping moves towards it */
    /* d y1 as its high word and low word (cheaper on ARMv6-M than
     * stp_umul32x32's 64-bit assembly; the same product) */
    p = ((uint64_t)stp_umulhi32x32(d, y1) << 32) | (uint64_t)(d * y1);
    v = y1 << 1; /* 2 y1 - 2^32 */
    if (p <= ((uint64_t)1 << 63)) {
        uint32_t c = stp_umulhi32_approx(y1, (uint32_t)((((uint64_t)1 << 63) - p) >> 15)) >> 15;
        v = c > 0xFFFFFFFFu - v ? 0xFFFFFFFFu : v + c;
    } else {
        uint32_t c = (stp_umulhi32_approx(y1, (uint32_t)((p - ((uint64_t)1 << 63)) >> 15)) >> 15) + 2u;
        v = c > v ? 0u : v - c;
    }
    return v;
}

#if STP_RECIP_U32
/* y ~ 2^63 / dn for dn = d 2^s in [2^31, 2^32): with the seed's relative
 * error e = 1 - dn y0 / 2^47 (|e| < 1/257), 2^63 / dn = y0 2^16 / (1 - e)
 * = y0 2^16 (1 + e + e^2 + ...), taken to e^2: c1 = y0 2^16 e from u ~ e
 * 2^30 (u's terms below 2^31, so int32 throughout) and c2 = c1 e, each
 * from factors below 2^16 (products below 2^31).  The dropped terms and
 * the floors are under 2^10 either way; u less 256 (y less 512 to 1024)
 * puts y below 2^63 / dn by 493 to 1791 (over all 2^31 dn), so y < 2^63 /
 * dn and q = floor(y / 2^t), t = 31 - s, is below 2^32 / d (q d < 2^32, r
 * = 2^32 - 1 - q d exact) and short of the floor Q by less than 2^11 /
 * 2^t + 1: by at most 1 for t >= 11.  For t <= 10 (d < 2^11) r < 2^11 d
 * 2^-t + 2 d < 2^13, and dq = floor(r floor(y / 2^16) / 2^(t + 16)) is
 * floor(r / d) or one short (r / d < 2^11, and floor(y / 2^16) is below
 * 2^47 / dn by less than 2^-14.9 of it): either way one correction ends
 * it. */
uint32_t stp_recip_u32(uint32_t d)
{
    uint32_t dn = d, y0, y, q, r;
    int32_t u, c1;
    int t = 31; /* 31 - s for dn = d 2^s in [2^31, 2^32) */
    /* normalised by five halving tests written out, which leave dn itself:
     * through stp_bit_length32 (its table) the Cortex-M0+ torus took 2 840
     * instructions more a frame, as a loop 13 840 more (not unrolled) */
    if ((dn >> 16) == 0) {
        dn <<= 16;
        t -= 16;
    }
    if ((dn >> 24) == 0) {
        dn <<= 8;
        t -= 8;
    }
    if ((dn >> 28) == 0) {
        dn <<= 4;
        t -= 4;
    }
    if ((dn >> 30) == 0) {
        dn <<= 2;
        t -= 2;
    }
    if ((dn >> 31) == 0) {
        dn <<= 1;
        t -= 1;
    }
    y0 = RECIP_SEED_AT((dn >> 24) & 127u);
    u = (int32_t)(0x40000000u - 256u) - (int32_t)(((dn >> 16) * y0) >> 1) - (int32_t)((stp_lo16(dn) * y0) >> 17);
    c1 = stp_asr32((int32_t)y0 * stp_asr32(u, 7), 7);
    y = (y0 << 16) + (uint32_t)(c1 + stp_asr32(stp_asr32(c1, 8) * stp_asr32(u, 7), 15));
    q = y >> t;
    r = ~(q * d);
    if (t < 11) {
        uint32_t dq = (r * (y >> 16)) >> (t + 16);
        q += dq;
        r -= dq * d;
    }
    return r >= d ? q + 1u : q;
}
#endif

uint32_t stp_recip32(uint32_t d)
{
    uint32_t v = stp_recip32_estimate(d);
    uint64_t p, r;
    if (d < 0x80000000u)
        return 0;
    /* (2^32 + v) d brought to at most 2^64 - 1 (a wrapped sum is below
     * d 2^32), then r = 2^64 - 1 - (2^32 + v) d below d */
    p = stp_umul32x32(d, v) + ((uint64_t)d << 32);
    while (p < ((uint64_t)d << 32)) { /* wrapped: v above the floor */
        v--;
        p -= d;
    }
    r = ~p;
    while (r >= d) {
        v++;
        r -= d;
    }
    return v;
}
#endif

/* (u1 2^32 + u0) / d for a normalised d (top bit set), its reciprocal v
 * (stp_recip32) and u1 < d: the quotient (below 2^32), *rem the
 * remainder.  One 32 x 32 -> 64 product, one 32-bit product and two
 * corrections (the division by an invariant integer of Moller and
 * Granlund, 2011). */
static inline uint32_t div_2by1(uint32_t u1, uint32_t u0, uint32_t d, uint32_t v, uint32_t *rem)
{
    uint64_t qq = stp_umul32x32(v, u1) + ((((uint64_t)u1 + 1u) << 32) | u0); /* mod 2^64 */
    uint32_t q1 = (uint32_t)(qq >> 32), q0 = (uint32_t)qq, r = u0 - q1 * d;
    if (r > q0) {
        q1--;
        r += d;
    }
    if (r >= d) {
        q1++;
        r -= d;
    }
    *rem = r;
    return q1;
}

void stp_recip_divisor_init(stp_recip_divisor *p, uint32_t d)
{
    p->s = d == 0 ? 0 : 32 - stp_bit_length32(d);
    p->dn = d << p->s;
    p->v = stp_recip32(p->dn);
}

uint64_t stp_udiv64_by(const stp_recip_divisor *p, uint64_t n)
{
    /* n 2^s as three words w2 w1 w0 (w2 < 2^s <= dn), then two steps of
     * the 2-by-1 division, the first skipped when its quotient word is 0 */
    uint32_t nh = (uint32_t)(n >> 32), nl = (uint32_t)n, w2, w1, w0, qh = 0, ql, r;
    int s = p->s;
    if (p->dn == 0)
        return UINT64_MAX;
    w2 = s != 0 ? nh >> (32 - s) : 0u;
    w1 = s != 0 ? (nh << s) | (nl >> (32 - s)) : nh;
    w0 = nl << s;
    if (w2 != 0 || w1 >= p->dn)
        qh = div_2by1(w2, w1, p->dn, p->v, &w1);
    ql = div_2by1(w1, w0, p->dn, p->v, &r);
    return ((uint64_t)qh << 32) | ql;
}

int64_t stp_div64_by(const stp_recip_divisor *p, int64_t n)
{
    uint64_t q = stp_udiv64_by(p, n < 0 ? 0u - (uint64_t)n : (uint64_t)n);
    return (int64_t)(n < 0 ? 0u - q : q);
}

uint64_t stp_udiv64_recip(uint64_t n, uint64_t d)
{
    uint32_t dh = (uint32_t)(d >> 32), nh = (uint32_t)(n >> 32), nl = (uint32_t)n;
    uint32_t w2, w1, w0, v, r;
    int s;
    if (d == 0)
        return UINT64_MAX;
    if (n < d)
        return 0;
    /* n 2^s as three 32-bit words w2 w1 w0, s normalising d's top word */
    s = 32 - stp_bit_length32(dh != 0 ? dh : (uint32_t)d);
    w2 = s != 0 ? nh >> (32 - s) : 0u;
    w1 = s != 0 ? (nh << s) | (nl >> (32 - s)) : nh;
    w0 = nl << s;
    if (dh == 0) {
        stp_recip_divisor one;
        one.dn = (uint32_t)d << s;
        one.v = stp_recip32(one.dn);
        one.s = s;
        return stp_udiv64_by(&one, n);
    } else {
        /* a two-word divisor d1 d0 (normalised): the quotient is below
         * 2^32; the estimate from w2 w1 / d1 (w2 < 2^s <= d1) is at most 2
         * too large, and comparing q d0 with the remainder's next word
         * makes it exact (Knuth's algorithm D, step D3) */
        uint64_t dd = d << s;
        uint32_t d1 = (uint32_t)(dd >> 32), d0 = (uint32_t)dd, q;
        v = stp_recip32(d1);
        q = div_2by1(w2, w1, d1, v, &r);
        while (stp_umul32x32(q, d0) > (((uint64_t)r << 32) | w0)) {
            q--;
            if (r > 0xFFFFFFFFu - d1)
                break; /* r + d1 >= 2^32: the test can no longer fail */
            r += d1;
        }
        return q;
    }
}

int64_t stp_div64_recip(int64_t n, int64_t d)
{
    uint64_t un = n < 0 ? 0u - (uint64_t)n : (uint64_t)n;
    uint64_t ud = d < 0 ? 0u - (uint64_t)d : (uint64_t)d;
    uint64_t q = stp_udiv64_recip(un, ud);
    return (int64_t)((n < 0) != (d < 0) ? 0u - q : q);
}

#if UINTPTR_MAX > 0xFFFFu && !STP_SMALL_DIVISION
/* floor(2^32 / d) + 1 for d = 2..127 (recip_private.h; the edge walker's
 * stp_slope_q16, edge_walk_private.h); entries 0 and 1 unused */
const uint32_t stp_slope_recip[STP_SLOPE_RECIP_SIZE] = {
    0x00000000u, 0x00000000u, 0x80000001u, 0x55555556u, 0x40000001u, 0x33333334u,
    0x2AAAAAABu, 0x24924925u, 0x20000001u, 0x1C71C71Du, 0x1999999Au, 0x1745D175u,
    0x15555556u, 0x13B13B14u, 0x12492493u, 0x11111112u, 0x10000001u, 0x0F0F0F10u,
    0x0E38E38Fu, 0x0D79435Fu, 0x0CCCCCCDu, 0x0C30C30Du, 0x0BA2E8BBu, 0x0B21642Du,
    0x0AAAAAABu, 0x0A3D70A4u, 0x09D89D8Au, 0x097B425Fu, 0x0924924Au, 0x08D3DCB1u,
    0x08888889u, 0x08421085u, 0x08000001u, 0x07C1F07Du, 0x07878788u, 0x07507508u,
    0x071C71C8u, 0x06EB3E46u, 0x06BCA1B0u, 0x06906907u, 0x06666667u, 0x063E7064u,
    0x06186187u, 0x05F417D1u, 0x05D1745Eu, 0x05B05B06u, 0x0590B217u, 0x0572620Bu,
    0x05555556u, 0x0539782Au, 0x051EB852u, 0x05050506u, 0x04EC4EC5u, 0x04D4873Fu,
    0x04BDA130u, 0x04A7904Bu, 0x04924925u, 0x047DC120u, 0x0469EE59u, 0x0456C798u,
    0x04444445u, 0x04325C54u, 0x04210843u, 0x04104105u, 0x04000001u, 0x03F03F04u,
    0x03E0F83Fu, 0x03D22636u, 0x03C3C3C4u, 0x03B5CC0Fu, 0x03A83A84u, 0x039B0AD2u,
    0x038E38E4u, 0x0381C0E1u, 0x03759F23u, 0x0369D037u, 0x035E50D8u, 0x03531DEDu,
    0x03483484u, 0x033D91D3u, 0x03333334u, 0x03291620u, 0x031F3832u, 0x03159722u,
    0x030C30C4u, 0x03030304u, 0x02FA0BE9u, 0x02F14991u, 0x02E8BA2Fu, 0x02E05C0Cu,
    0x02D82D83u, 0x02D02D03u, 0x02C8590Cu, 0x02C0B02Du, 0x02B93106u, 0x02B1DA47u,
    0x02AAAAABu, 0x02A3A0FEu, 0x029CBC15u, 0x0295FAD5u, 0x028F5C29u, 0x0288DF0Du,
    0x02828283u, 0x027C4598u, 0x02762763u, 0x02702703u, 0x026A43A0u, 0x02647C6Au,
    0x025ED098u, 0x02593F6Au, 0x0253C826u, 0x024E6A18u, 0x02492493u, 0x0243F6F1u,
    0x023EE090u, 0x0239E0D6u, 0x0234F72Du, 0x02302303u, 0x022B63CCu, 0x0226B903u,
    0x02222223u, 0x021D9EAEu, 0x02192E2Au, 0x0214D022u, 0x02108422u, 0x020C49BBu,
    0x02082083u, 0x02040811u
};
#endif
