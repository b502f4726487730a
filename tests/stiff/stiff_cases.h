/* SPDX-License-Identifier: MIT */
/*
 * The stiff and extreme suite (issue 3, item 3) as a table shared by the
 * cmocka tests (tests/stiff/test_stiff.c, default configuration) and the
 * benchmark (tools/bench/bench.c, one build per numeric configuration).
 *
 * Each case runs the fixed-point core (stp_shade_point, or one polygon
 * through stp_renderer_polygon) on its inputs rounded to stp_fix, and the
 * double-precision reference (tests/reference/shade_ref.c, and
 * tools/bench/render_ref.c for polygons) on the exact inputs.  The case
 * states the behaviour decided for it (finite, clamped, reported), the
 * answer (the reference where it is finite, or a documented value), and the
 * tolerance on |core - answer|: half an INTENSITY step at 16 levels (1/30)
 * unless a reason is given.
 */
#ifndef STIPPLE_TESTS_STIFF_CASES_H
#define STIPPLE_TESTS_STIFF_CASES_H

#include <stddef.h>

#include "reference/shade_ref.h"
#include "render_ref.h"
#include "stipple/stipple.h"

#define STIFF_HALF_STEP (1.0 / 30.0)
#define STIFF_MAX_VERTS 200
#define STIFF_WIDTH 64
#define STIFF_HEIGHT 64

typedef enum stiff_kind {
    STIFF_SHADE,  /* stp_shade_point on view-plane inputs */
    STIFF_POLYGON /* one polygon through a 64 x 64 renderer, shading on */
} stiff_kind;

typedef struct stiff_case {
    const char *name;
    const char *behaviour; /* what was decided, in a sentence */
    stiff_kind kind;
    ref_lighting lighting; /* SHADE: view-plane positions; POLYGON: world */
    ref_material material;
    /* SHADE */
    ref_vec3 normal, point, eye, pdir;
    int parallel;
    /* POLYGON */
    ref_view view;
    int n;
    ref_vec3 v[STIFF_MAX_VERTS];
    int expect_status; /* the core's status (POLYGON); STP_OK etc. */
    int or_degenerate; /* STP_ERR_DEGENERATE is accepted too (no shade then) */
    /* answer */
    double expect; /* >= 0: the documented answer; < 0: the reference */
    double tol;    /* allowed |core - answer| */
    const char *reason; /* why tol is above half a step (NULL: it is not) */
} stiff_case;

typedef struct stiff_outcome {
    int status;     /* the core's status (SHADE: 0) */
    int ref_status; /* the reference's (REF_OK, REF_ERR_DEGENERATE) */
    double core;    /* the core's shade, -1 when it gave none */
    double ref;     /* the reference at the exact inputs, -1 when none */
    double ref_q;   /* the reference at the core's rounded inputs (SHADE) */
    double answer;  /* expect, or ref */
    double err;     /* |core - answer|, 0 when neither has a shade */
    int has_err;    /* both the core and the answer have a shade */
} stiff_outcome;

size_t stiff_case_count(void);
const stiff_case *stiff_case_at(size_t i);

/* Run one case through the core (this build's configuration) and the
 * reference. */
void stiff_run(const stiff_case *c, stiff_outcome *out);

/* Double to stp_fix of this build, rounded to nearest, saturated. */
stp_fix stiff_to_fix(double v);

#endif
