/* SPDX-License-Identifier: MIT */
/*
 * Private: MAKE-SHADE of flat faces in 32-bit arithmetic, for entry paths
 * (triangle meshes) that shade many faces under one lighting and material.
 * The equation is shade.c's shade_unit (docs/model.md section 2):
 *   s = min(1, BRIGHT (B R + sum_j P_j (R (N.L_j) + Ks D G F/(N.E)) / (C + U_j)))
 * computed with 32 x 32 -> 32-bit products only (a 32 x 32 -> 64 product is
 * formed from four of them where 30 bits are needed) and no division: unit
 * vectors through a reciprocal square root (a table chord and a Newton step),
 * reciprocals through a table seed and Newton steps, Fresnel's F from a
 * per-material table (built by prepare from the exact F), D, F and G/(N.E)
 * in fixed formats where E.H >= 1/4 bounds them, and BRIGHT P_j/(C + U)
 * in a 16-bit-mantissa floating format (shade_fast.c).
 * Where those formats cannot keep the error within the bound (a gain
 * BRIGHT max P_j max(|R|, Ks)/C above 16; with the highlight, k < 0.05,
 * n < 1.25 or a face with N.E < 0.05) the face takes the exact route,
 * stp_shade_unit (shade.c), with the prepared lighting and material.
 * Measured error against the double reference: tests/shade_accuracy
 * (docs/error.md), tests/shade_fast.
 */
#ifndef STIPPLE_SHADE_FAST_PRIVATE_H
#define STIPPLE_SHADE_FAST_PRIVATE_H

#include <stdint.h>

#include "recip_private.h" /* STP_WIDE_ARITH */
#include "stipple/shade.h"

/* A positive number m 2^-e with m = 0 (the number 0) or m in [2^15, 2^16):
 * 16 significant bits, any exponent an int holds (|e| stays below 200). */
typedef struct stp_sf16 {
    uint32_t m;
    int e;
} stp_sf16;

/* A direction scaled to 16 bits: w = v 2^-shift rounded, the largest
 * |component| in [2^15, 2^16) (or all 0 for a zero vector), q = sum of
 * the w_i^2 / 4 in [2^28, 3 2^30), r = 1/sqrt(q) as r 2^(j - 46) with r in
 * (2^30, 2^31] and j in {0, 1}. */
typedef struct stp_shade_fast_dir {
    int32_t w[3];
    uint32_t q, r;
    int j, shift;
} stp_shade_fast_dir;

#define STP_SHADE_FAST_FRESNEL_NODES 49

/* Per-call constants of stp_shade_fast_face. */
/* stp_shade_fast_face's route on a host (wide_route, set by the prepare) */
#define STP_SHADE_WIDE_NARROW 0  /* the 32-bit path: a struct filled by hand, or F != 16 */
#define STP_SHADE_WIDE_AMBIENT 1 /* no light: every face the ambient shade */
#define STP_SHADE_WIDE_EXACT 2   /* exact_always with a light: every face exact */
#define STP_SHADE_WIDE_FAST 3    /* face_wide, with at least one light */

typedef struct stp_shade_fast {
    /* The fields each face reads first, so that a Cortex-M0+ reaches each
     * with one load (its byte loads take offsets below 32, its word loads
     * below 128; a field beyond costs two instructions more a load). */
    uint8_t count;       /* lights that can reach a face (0 when BRIGHT <= 0) */
    uint8_t parallel;    /* E constant (parallel projection) */
    uint8_t specular;    /* the highlight is on (Ks > 0, STP_WITH_SPECULAR) */
    uint8_t refl_negative; /* R < 0: the diffuse term subtracts */
    uint8_t eye_big;     /* a component of eye outside [-2^30, 2^30) */
    uint8_t light_big[STP_MAX_LIGHTS];
#if STP_WITH_SPECULAR
    uint8_t refraction_ge_1; /* n >= 1: g = n sqrt(1 - (1 - c^2)/n^2) */
    uint8_t exact_always; /* the lighting or the material is outside the
                             fast route's range: every lit face exact
                             (the exact route: below) */
#endif
    stp_fix ambient_shade; /* the shade of a face no light reaches (exactly
                              as stp_shade_unit rounds it) */
    int32_t ambient;     /* BRIGHT B R in Q26 (one = 2^26), in [-2^29, 2^29] */
    stp_sf16 attenuation_c; /* C in raw stp_fix units (C >= 1: m != 0) */
    stp_sf16 power_refl[STP_MAX_LIGHTS]; /* BRIGHT P_j |R| 2^F (per raw unit of C + U) */
#if STP_WITH_SPECULAR
    stp_sf16 power_ks[STP_MAX_LIGHTS]; /* BRIGHT P_j Ks 2^F (per raw unit of C + U) */
    uint32_t inv_gloss_q16; /* 1/k in Q16, at most 2^32 - 1 */
    int32_t fast_min_cos; /* Q30: a face with N.E below it (highlight on)
                             takes the exact route when a light is nearly
                             opposite the eye or N.E is below 1/64 of it
                             (shade_fast.c GRAZE_EXACT); 0: never */
#endif
    stp_vec3 eye;        /* perspective: the centre of projection */
    stp_shade_fast_dir e; /* parallel: the direction towards the eye */
    stp_vec3 light[STP_MAX_LIGHTS];
#if STP_WITH_SPECULAR
    stp_sf16 inv_gloss;  /* 1/k */
    stp_sf16 refraction; /* n (>= 1 branch) */
    uint32_t inv_n2;     /* n >= 1: 1/n^2 in Q31 */
    uint32_t n2;         /* n < 1: n^2 in Q30 */
    /* n >= 1: F(c) in Q16 (capped at 65535) at c = 1/4 + i/64, i = 0..48
     * (E.H = c; below 1/4, and for n < 1, F is computed exactly) */
    uint16_t fresnel[STP_SHADE_FAST_FRESNEL_NODES];
#endif
#if STP_WITH_SPECULAR
    /* The exact route (stp_shade_unit, shade.c) for the faces where the
     * fast formats cannot promise the error bound (stp_shade_fast_face):
     * the lighting's and the material's values as given (with
     * exact_always and fast_min_cos above).  Builds without
     * the highlight (STP_WITH_SPECULAR 0, the lean microcontroller
     * configuration) have no exact route: neither these fields nor the
     * code that fills and reads them (shade_fast.c). */
    /* the exact route, set by stp_shade_fast_prepare (NULL in a struct
     * filled by hand: the fast route always, and no link to shade.c) */
    stp_fix (*exact)(const struct stp_shade_fast *s, const int16_t normal[3], stp_vec3 point);
    stp_fix x_bright, x_background, x_c, x_refl, x_refraction, x_gloss, x_ks;
    stp_fix x_power[STP_MAX_LIGHTS];
    stp_vec3 x_dir;       /* parallel: the direction towards the eye */
#endif
#if STP_WIDE_ARITH /* the 64-bit host path (shade_fast.c "wide"); parallel
                      projection there keeps the direction towards the eye
                      (not 0) in eye */
    uint8_t wide_route;  /* STP_SHADE_WIDE_*, set by stp_shade_fast_prepare:
                            the wide fields below hold unless NARROW; 0
                            (NARROW): a caller that filled the 32-bit
                            fields itself gets the 32-bit path */
    int8_t wide_refl_sign; /* -1 where R < 0 (refl_negative), else 1 (a
                              byte of the padding) */
    uint32_t wide_c;     /* C in raw stp_fix units, >= 1 */
    uint32_t wide_refl;  /* |R| in raw units */
    int32_t wide_acc_one; /* 1 - BRIGHT B R in Q26 (SUM_ONE - ambient, in
                             [-7 2^26, 9 2^26]): the lights' shares that
                             make a shade of 1 */
    /* BRIGHT P_j as m 2^-e = b p 2^-16 (b, p raw), m in [2^23, 2^24) or 0,
     * e in [-22, 39] (-64 with m = 0): m 2^36 (the dividend of its share)
     * and e + 26 (the shift of its diffuse share in Q26 adds -e - 26) */
    uint64_t wide_power[STP_MAX_LIGHTS];
    int8_t wide_power_e[STP_MAX_LIGHTS];
#if STP_WITH_SPECULAR
    uint8_t wide_gloss_r; /* k in Q30 as g 2^r, g < 2^24: r, ... */
    uint32_t wide_gloss;  /* ... and g */
    uint64_t wide_gloss30; /* g 2^30 */
    /* n >= 1: fresnel[i + 1] - fresnel[i], 0 at the last node */
    int32_t wide_fresnel_step[STP_SHADE_FAST_FRESNEL_NODES];
    uint32_t wide_ks;    /* Ks in raw units, 0 when Ks <= 0 */
#endif
#endif
} stp_shade_fast;

/* Prepare from the segment's lighting (light positions in VIEW coordinates,
 * as render.c keeps them per segment) and the material.  eye: the centre of
 * projection in view coordinates (perspective); parallel != 0: parallel
 * projection with parallel_dir the direction towards the eye (any length
 * but 0; 0 gives (0, 0, -1)).  Meant to be cached: call it only when the
 * lighting, the material or the view changes, and keep the struct (about
 * 320 bytes) across frames; with the highlight (Ks > 0, n >= 1) it builds
 * the 49-node Fresnel table from the exact F, about 26 000 Cortex-M0+
 * instructions (-O2; 39 300 at -Os), a few hundred otherwise. */
void stp_shade_fast_prepare(stp_shade_fast *s, const stp_lighting *lighting,
                            const stp_material *material, stp_vec3 eye, int parallel,
                            stp_vec3 parallel_dir);

/* stp_shade_fast_prepare(s, lighting, material, eye, 0, any): the
 * perspective prepare (the same fields).  A body of its own (the same
 * steps but the parallel view's direction) where that is all the prepare
 * there is: a size-first build (-Os with STP_SMALL_DIVISION) without the
 * highlight's and the host's routes, so a program that never projects in
 * parallel (direct drawing) links no parallel direction (lean direct core
 * 6 320 -> 6 248 B); elsewhere the general prepare's call. */
#if defined(__OPTIMIZE_SIZE__) && STP_SMALL_DIVISION && !STP_WITH_SPECULAR && !STP_WIDE_ARITH
#define STP_SHADE_PREPARE_EYE_BODY 1
void stp_shade_fast_prepare_eye(stp_shade_fast *s, const stp_lighting *lighting, const stp_material *material,
                                stp_vec3 eye);
#else
#define STP_SHADE_PREPARE_EYE_BODY 0
static inline void stp_shade_fast_prepare_eye(stp_shade_fast *s, const stp_lighting *lighting,
                                              const stp_material *material, stp_vec3 eye)
{
    stp_vec3 back = {0, 0, -STP_FIX_ONE}; /* unused (perspective): the prepared struct's x_dir */
    stp_shade_fast_prepare(s, lighting, material, eye, 0, back);
}
#endif

/* Shade of a flat face, in [0, 1] (stp_fix).  normal: unit normal in view
 * coordinates, Q1.14 (one = 16384; |n| = 1 +- 2^-13 is corrected to 1);
 * point: the face's vertex average in view coordinates.  N.E <= 0 gives
 * exactly the ambient share min(1, BRIGHT B R).  Error against the double
 * reference of the chapter's equations at most 6e-4 on the fast route and
 * 2.8e-4 on the exact one (tests/shade_accuracy, 30 000 cases; exactly 0
 * and 1 where the reference is).  Builds without the highlight have no
 * exact route, which with it takes every face of a light gain
 * BRIGHT P_j |R| / C above 16: there the 32-bit routes' cosine error
 * (about 1.5e-5) is multiplied by the gain (3.1e-3 at a gain of 200;
 * tests/shade_fast). */
stp_fix stp_shade_fast_face(const stp_shade_fast *s, const int16_t normal[3], stp_vec3 point);

/* stp_shade_fast_face for a struct prepared for perspective without the
 * highlight (Ks <= 0), with the eye, every light and point within
 * [-2^30, 2^30) in each coordinate (direct drawing's: below 2^26): the
 * same shade, without the tests for the cases those conditions exclude,
 * on the 32-bit targets (the host's is stp_shade_fast_face itself). */
#if STP_WIDE_ARITH
#define stp_shade_fast_face_near stp_shade_fast_face
#else
stp_fix stp_shade_fast_face_near(const stp_shade_fast *s, const int16_t normal[3], stp_vec3 point);
#endif

#endif
