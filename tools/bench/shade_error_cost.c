/* SPDX-License-Identifier: MIT */
/*
 * Error against run time of the shading configurations
 * (tools/bench/shade_error_cost.sh builds this once per compile-time
 * variant: STP_FIX_FRAC_BITS 12 / 16 / 20, STP_SQRT_FAST, STP_WITH_SPECULAR)
 * in these run-time modes:
 *   default    stp_shade_fast_face as the mesh path calls it: the fast route
 *              where it keeps the 2e-3 bound, the exact route elsewhere
 *   fast       the fast route for every face (16-bit scaled directions,
 *              table-seeded reciprocal square roots and reciprocals, the
 *              49-node Fresnel table, Q30 D, Q16 F)
 *   exact      the exact route for every face (30-bit directions, exact
 *              roots and quotients, Fresnel computed, 32-bit mantissas)
 *   point      stp_shade_point, the per-point shader of the polygon path
 *              (no prepared constants: everything from the lighting each call)
 *   levels16, levels256
 *              the default face shade put through INTENSITY
 *              (stp_intensity_index) to 16 or 256 levels; the error is that
 *              of the displayed intensity (index - 1)/(levels - 1)
 *   fresnel-table, fresnel-formula
 *              default on the cases with 1 <= n < 2 and a highlight: F
 *              from the 49-node table, or from its formula on each face
 *              (prepare_mode: the face shader has no switch for it)
 *   q14normal  default, judged against the reference for a 15-bit normal
 *              (make_fine) of which the face shader's Q1.14 normal is the
 *              rounding: what the Q1.14 format costs in error
 *   n15normal  stp_shade_point given that 15-bit normal (an stp_fix normal,
 *              as the polygon path has), judged against the same reference
 * over the cases of tests/shade_accuracy against their double reference
 * (tests/shade_accuracy/case_reference.c): "typical" are the non-extreme
 * cases (what a scene's faces meet), "stiff" the extreme ones (grazing,
 * near mirror, tiny gloss, huge BRIGHT, small C, near lights).
 *
 * Host build (SHADE_COST_HOST):
 *   shade_error_cost [--cases N]          per mode one line:
 *     mode typical_n max mean stiff_n stiff_max stiff_mean diff16 diff256
 *     (diffL: % of typical cases whose INTENSITY index at L levels differs
 *     from the reference's INT(ref (L - 1) + 1))
 *   shade_error_cost --cases N --only MODE
 *     shades the typical cases in MODE only (callgrind collects shade_one)
 * Target build (shade_cost_m0/): per mode "stipple: cost MODE INSTR N" with
 * INSTR the Cortex-M0+ instructions per shade_one call, averaged over the N
 * typical cases, under QEMU -icount (prepare and case making not counted),
 * and "stipple: tick T" (instructions per SysTick tick).
 */
#include "cases.h"
#include "shade_fast_private.h"

#ifndef SHADE_COST_CASES
#define SHADE_COST_CASES 3000u /* cases looked at; about 30 % are typical */
#endif

#ifdef __GNUC__
#define NOINLINE __attribute__((noinline))
#else
#define NOINLINE
#endif

enum { M_DEFAULT, M_FAST, M_EXACT, M_POINT, M_LEVELS16, M_LEVELS256, M_FTABLE, M_FFORMULA, M_Q14, M_N15, M_COUNT };
static const char *const mode_names[M_COUNT] = {"default",   "fast",     "exact",         "point", "levels16",
                                                "levels256", "fresnel-table", "fresnel-formula", "q14normal",
                                                "n15normal"};

#ifndef __AVR__ /* (the AVR build takes its cases from the host) */
static int typical(const acc_case *c)
{
    return !(c->flags & ACC_EXTREME);
}

/* Case i.  At F = 12 the cases' smallest C (2^-16) rounds to 0, which the
 * shaders take as one step 2^-F (shade.h); the case is given that C, so
 * that the reference judges the input the shaders use. */
static void make_case(acc_case *c, uint32_t i)
{
    acc_case_make(c, i);
    if (c->lighting.attenuation_c <= 0)
        c->lighting.attenuation_c = 1;
}

/* The case with a finer normal for the normal modes: each Q1.14 component
 * n becomes the 15-bit 2 n + d, d in {-1, 0, 1} picked from the case
 * number (capped to int16): Q1.14 is its rounding (off by 0 or half a step),
 * and the reference (which normalises the normal) judges against it. */
static void make_fine(acc_case *fine, const acc_case *c, uint32_t i)
{
    int a;
    *fine = *c;
    for (a = 0; a < 3; a++) {
        uint32_t h = (i * 3u + (uint32_t)a) * 2654435761u;
        int32_t v = 2 * (int32_t)c->normal[a] + (int32_t)((h >> 16) % 3u) - 1;
        fine->normal[a] = (int16_t)(v > 32767 ? 32767 : (v < -32767 ? -32767 : v));
    }
}

/* the cases mode k looks at: the Fresnel pair those its formula can take
 * in the fast route's formats (1 <= n < 2, highlight on) */
static int applies(const acc_case *c, int k)
{
    if (k == M_FTABLE || k == M_FFORMULA)
        return STP_WITH_SPECULAR && c->material.specular > 0 && c->material.refraction >= STP_FIX_ONE &&
               c->material.refraction < 2 * STP_FIX_ONE;
    return 1;
}

#endif

/* the prepared face shading of case c for mode k */
static void prepare_mode(stp_shade_fast *f, const acc_case *c, int k)
{
    stp_shade_fast_prepare(f, &c->lighting, &c->material, c->eye, c->parallel, c->parallel_dir);
    (void)k;
#if STP_WITH_SPECULAR /* (a build without the highlight has no exact route) */
    if (k == M_FAST) {
        f->exact_always = 0;
        f->fast_min_cos = 0;
    } else if (k == M_EXACT && f->exact != 0) {
        f->exact_always = 1;
    }
    if (k == M_FFORMULA && f->refraction_ge_1) {
        /* Fresnel by its formula on the fast route: the face shader has no
         * switch for it, so the table's flag is cleared, which sends F
         * through fresnel_sf's other branch, g = sqrt(n^2 - u) with n^2 in
         * Q30 (32 bits: n < 2, what applies() admits) */
        uint64_t n = (uint64_t)c->material.refraction;
        f->n2 = (uint32_t)(STP_FIX_FRAC_BITS >= 15 ? (n * n) >> (2 * STP_FIX_FRAC_BITS - 30)
                                                   : (n * n) << (30 - 2 * STP_FIX_FRAC_BITS));
        f->refraction_ge_1 = 0;
    }
#if STP_WIDE_ARITH
    /* the host's route is the prepare's choice (wide_route): chosen again
     * for the flags the mode changed; the 64-bit route has no fast or
     * Fresnel-formula variant, so those modes take the 32-bit route there */
    if (k == M_EXACT && f->exact_always && f->wide_route == STP_SHADE_WIDE_FAST)
        f->wide_route = STP_SHADE_WIDE_EXACT;
    if ((k == M_FAST || k == M_FFORMULA) && f->wide_route != STP_SHADE_WIDE_AMBIENT)
        f->wide_route = STP_SHADE_WIDE_NARROW;
#endif
#endif
}

/* One shade of case c in mode k: a shade in [0, 1] (stp_fix), or for the
 * level modes the INTENSITY index.  What the cost figures count. */
NOINLINE static stp_fix shade_one(const stp_shade_fast *f, const acc_case *c, int k)
{
    if (k == M_POINT || k == M_N15) {
        /* the Q1.14 normal as it is (stp_shade_point normalises any length) */
        stp_vec3 n;
        n.x = c->normal[0];
        n.y = c->normal[1];
        n.z = c->normal[2];
        return stp_shade_point(&c->lighting, &c->material, n, c->point, c->eye, c->parallel, c->parallel_dir);
    }
    if (k == M_LEVELS16)
        return stp_intensity_index(stp_shade_fast_face(f, c->normal, c->point), 16);
    if (k == M_LEVELS256)
        return stp_intensity_index(stp_shade_fast_face(f, c->normal, c->point), 256);
    return stp_shade_fast_face(f, c->normal, c->point);
}

#ifdef SHADE_COST_HOST
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "case_reference.h"

typedef struct stats {
    double max, sum, stiff_max, stiff_sum;
    unsigned long n, stiff_n, diff16, diff256;
} stats;

/* the displayed value of shade_one's result in mode k */
static double shown(stp_fix v, int k)
{
    if (k == M_LEVELS16)
        return (v - 1) / 15.0;
    if (k == M_LEVELS256)
        return (v - 1) / 255.0;
    return (double)v / STP_FIX_ONE;
}

/* INTENSITY's index of the reference shade r at L levels */
static int ref_index(double r, int levels)
{
    return 1 + (int)floor(r * (levels - 1));
}

static void account(stats *s, const acc_case *c, stp_fix v, int k, double ref)
{
    double err = fabs(shown(v, k) - ref);
    stp_fix shade = k == M_LEVELS16 || k == M_LEVELS256 ? (stp_fix)0 : v;
    if (!typical(c)) {
        s->stiff_n++;
        s->stiff_sum += err;
        if (err > s->stiff_max)
            s->stiff_max = err;
        return;
    }
    s->n++;
    s->sum += err;
    if (err > s->max)
        s->max = err;
    if (k == M_LEVELS16 || k == M_LEVELS256)
        return;
    s->diff16 += stp_intensity_index(shade, 16) != ref_index(ref, 16);
    s->diff256 += stp_intensity_index(shade, 256) != ref_index(ref, 256);
}

static void emit_vec(const char *name, stp_vec3 v)
{
    printf(".%s = {%ld, %ld, %ld}, ", name, (long)v.x, (long)v.y, (long)v.z);
}

/* The first `count` typical cases (at most 140: an AVR object is below
 * 32 KB) as C source for the AVR build (avr-gcc's double is 32 bits:
 * cases.c cannot make them there). */
static int emit_avr(uint32_t count)
{
    uint32_t i, n = 0;
    int j;
    if (count > 140)
        count = 140;
    printf("/* generated by shade_error_cost --emit-avr %lu */\nstatic const acc_case avr_cases[] PROGMEM = {\n",
           (unsigned long)count);
    for (i = 0; n < count; i++) {
        acc_case c;
        make_case(&c, i);
        if (!typical(&c))
            continue;
        n++;
        printf("{.lighting = {.brightness = %ld, .background = %ld, .attenuation_c = %ld, .count = %d, .lights = {",
               (long)c.lighting.brightness, (long)c.lighting.background, (long)c.lighting.attenuation_c,
               c.lighting.count);
        for (j = 0; j < STP_MAX_LIGHTS; j++) {
            const stp_light *l = &c.lighting.lights[j];
            printf("{");
            emit_vec("position", l->position);
            printf(".power = %ld, .colour = {%ld, %ld, %ld}}, ", (long)l->power, (long)l->colour[0],
                   (long)l->colour[1], (long)l->colour[2]);
        }
        printf("}},\n .material = {.reflectivity = %ld, .refraction = %ld, .gloss = %ld, .specular = %ld, "
               ".colour = {%ld, %ld, %ld}},\n .normal = {%d, %d, %d}, ",
               (long)c.material.reflectivity, (long)c.material.refraction, (long)c.material.gloss,
               (long)c.material.specular, (long)c.material.colour[0], (long)c.material.colour[1],
               (long)c.material.colour[2], c.normal[0], c.normal[1], c.normal[2]);
        emit_vec("point", c.point);
        emit_vec("eye", c.eye);
        printf(".parallel = %d, ", c.parallel);
        emit_vec("parallel_dir", c.parallel_dir);
        printf(".flags = %uu},\n", c.flags);
    }
    printf("};\n#define AVR_CASES %lu\n", (unsigned long)n);
    return 0;
}

/* What the AVR build prints as its digests for the first `count` typical
 * cases: the shades of each mode it times, folded (the same arithmetic). */
static int avr_digest(uint32_t count)
{
    uint32_t digest[M_POINT + 1] = {0}, i, n = 0;
    int k;
    for (i = 0; n < count && n < 140; i++) {
        acc_case c;
        make_case(&c, i);
        if (!typical(&c))
            continue;
        n++;
        for (k = 0; k <= M_POINT; k++) {
            stp_shade_fast f;
            prepare_mode(&f, &c, k);
            digest[k] = digest[k] * 31u + (uint32_t)shade_one(&f, &c, k);
        }
    }
    for (k = 0; k <= M_POINT; k++)
        printf("stipple: digest %s %lu\n", mode_names[k], (unsigned long)digest[k]);
    return 0;
}

int main(int argc, char **argv)
{
    static stats st[M_COUNT];
    uint32_t cases = SHADE_COST_CASES, i;
    int only = -1, a, k;
    for (a = 1; a + 1 < argc; a += 2) {
        if (strcmp(argv[a], "--cases") == 0) {
            cases = (uint32_t)strtoul(argv[a + 1], NULL, 10);
        } else if (strcmp(argv[a], "--emit-avr") == 0) {
            return emit_avr((uint32_t)strtoul(argv[a + 1], NULL, 10));
        } else if (strcmp(argv[a], "--avr-digest") == 0) {
            return avr_digest((uint32_t)strtoul(argv[a + 1], NULL, 10));
        } else if (strcmp(argv[a], "--only") == 0) {
            for (k = 0; k < M_COUNT; k++)
                if (strcmp(argv[a + 1], mode_names[k]) == 0)
                    only = k;
            if (only < 0)
                return fprintf(stderr, "%s: unknown mode %s\n", argv[0], argv[a + 1]), 2;
        } else {
            return fprintf(stderr, "usage: %s [--cases N] [--only MODE]\n", argv[0]), 2;
        }
    }
    for (i = 0; i < cases; i++) {
        acc_case c, fine;
        double ref, ref_fine;
        make_case(&c, i);
        if (only >= 0 && !typical(&c))
            continue;
        make_fine(&fine, &c, i);
        ref = only >= 0 ? 0.0 : acc_reference(&c, NULL);
        ref_fine = only >= 0 ? 0.0 : acc_reference(&fine, NULL);
        for (k = 0; k < M_COUNT; k++) {
            stp_shade_fast f;
            stp_fix v;
            const acc_case *in = k == M_N15 ? &fine : &c;
            if ((only >= 0 && k != only) || !applies(&c, k))
                continue;
            prepare_mode(&f, in, k);
            v = shade_one(&f, in, k);
            if (only < 0)
                account(&st[k], &c, v, k, k == M_Q14 || k == M_N15 ? ref_fine : ref);
        }
    }
    for (k = 0; only < 0 && k < M_COUNT; k++) {
        const stats *s = &st[k];
        double n = s->n != 0 ? (double)s->n : 1.0, sn = s->stiff_n != 0 ? (double)s->stiff_n : 1.0;
        printf("%s %lu %.3e %.3e %lu %.3e %.3e %.2f %.2f\n", mode_names[k], s->n, s->max, s->sum / n, s->stiff_n,
               s->stiff_max, s->stiff_sum / sn, 100.0 * (double)s->diff16 / n, 100.0 * (double)s->diff256 / n);
    }
    return 0;
}
#elif defined(__AVR__)
/* ATmega2560 under simavr: Timer1 counts every CPU cycle; the cases come
 * from the host (SHADE_COST_AVR_CASES: a file made by --emit-avr).  Prints
 * "stipple: cost MODE CYCLES N" for the modes default, fast, exact, point:
 * CPU cycles per shade_one call over the N cases, and "stipple: digest MODE
 * D" of the shades (--avr-digest prints the host's for the same cases). */
#include <avr/interrupt.h>
#include <avr/io.h>
#include <avr/pgmspace.h>
#include <avr/sleep.h>

#include SHADE_COST_AVR_CASES

static volatile uint16_t overflows;

ISR(TIMER1_OVF_vect)
{
    overflows++;
}

/* cycles since Timer1 started, 32 bits (wraps after 268 s at 16 MHz) */
static uint32_t cycles(void)
{
    uint8_t sreg = SREG;
    uint16_t lo, hi;
    cli();
    lo = TCNT1;
    hi = overflows;
    if ((TIFR1 & (1 << TOV1)) && lo < 0x8000u)
        hi++; /* the wrap happened before lo was read */
    SREG = sreg;
    return ((uint32_t)hi << 16) | lo;
}

static void put(const char *t)
{
    for (; *t; t++) {
        while (!(UCSR0A & (1 << UDRE0)))
            ;
        UDR0 = (uint8_t)*t;
    }
}

static void put_u32(uint32_t v)
{
    char b[11];
    int i = 10;
    b[i] = 0;
    do {
        b[--i] = (char)('0' + v % 10u);
        v /= 10u;
    } while (v != 0);
    put(b + i);
}

int main(void)
{
    static acc_case c;
    static stp_shade_fast f;
    static uint32_t total[M_COUNT], digest[M_COUNT], overhead;
    volatile stp_fix sink;
    uint32_t t0, t1;
    unsigned i;
    int k;
    UBRR0 = 0;
    UCSR0B = 1 << TXEN0;
    TCCR1A = 0;
    TCCR1B = 1 << CS10; /* no prescaler: one count a cycle */
    TIMSK1 = 1 << TOIE1;
    sei();
    t0 = cycles();
    t1 = cycles();
    overhead = t1 - t0;
    for (i = 0; i < AVR_CASES; i++) {
        memcpy_P(&c, &avr_cases[i], sizeof c);
        for (k = 0; k <= M_POINT; k++) { /* the modes the AVR row needs */
            prepare_mode(&f, &c, k);
            t0 = cycles();
            sink = shade_one(&f, &c, k);
            t1 = cycles();
            total[k] += t1 - t0 - overhead;
            digest[k] = digest[k] * 31u + (uint32_t)sink;
        }
    }
    for (k = 0; k <= M_POINT; k++) {
        put("stipple: cost ");
        put(mode_names[k]);
        put(" ");
        put_u32((total[k] + AVR_CASES / 2) / AVR_CASES);
        put(" ");
        put_u32(AVR_CASES);
        put("\nstipple: digest ");
        put(mode_names[k]);
        put(" ");
        put_u32(digest[k]);
        put("\n");
    }
    (void)sink;
    cli();
    sleep_cpu(); /* simavr ends the run */
    return 0;
}
#else
#include "stellaris.h"

/* Each shade is timed SHADE_COST_REPEAT times in a row: a SysTick tick is
 * several instructions, and the repetition makes its rounding negligible
 * (the loop's own few instructions a call are counted with the shade). */
#ifndef SHADE_COST_REPEAT
#define SHADE_COST_REPEAT 16u
#endif

static void report(const char *name, uint32_t v, uint32_t n)
{
    char num[12];
    stp_semihost_write("stipple: cost ");
    stp_semihost_write(name);
    stp_semihost_write(" ");
    stp_semihost_write(stp_utoa(v, num));
    stp_semihost_write(" ");
    stp_semihost_write(stp_utoa(n, num));
    stp_semihost_write("\n");
}

int main(void)
{
    static acc_case c, fine;
    static stp_shade_fast f;
    static uint64_t total[M_COUNT];
    static uint32_t n[M_COUNT];
    volatile stp_fix sink;
    uint32_t per_tick, i, overhead;
    uint64_t t0, t1;
    unsigned r;
    int k;
    stp_count_start();
    per_tick = stp_count_calibrate();
    t0 = stp_count_now();
    t1 = stp_count_now();
    overhead = (uint32_t)((t1 - t0) * per_tick);
    report("tick", per_tick, 0);
    for (i = 0; i < SHADE_COST_CASES; i++) {
        make_case(&c, i);
        if (!typical(&c))
            continue;
        make_fine(&fine, &c, i);
        for (k = 0; k < M_COUNT; k++) {
            const acc_case *in = k == M_N15 ? &fine : &c;
            if (!applies(&c, k))
                continue;
            n[k]++;
            prepare_mode(&f, in, k);
            t0 = stp_count_now();
            for (r = 0; r < SHADE_COST_REPEAT; r++)
                sink = shade_one(&f, in, k);
            t1 = stp_count_now();
            total[k] += (t1 - t0) * per_tick - overhead;
        }
    }
    for (k = 0; k < M_COUNT; k++) {
        uint64_t calls = (uint64_t)(n[k] != 0 ? n[k] : 1u) * SHADE_COST_REPEAT;
        report(mode_names[k], (uint32_t)((total[k] + calls / 2) / calls), n[k]);
    }
    (void)sink;
    stp_semihost_exit(0);
}
#endif
